//! The event calendar's invariants (`schedule::CollisionSchedule`), checked by the property
//! tests (`tests/integration/schedule.rs`) and by the fuzz target `schedule` (`fuzz/`): one implementation
//! for both.
//!
//! A [`Draw`] makes a scene from a source of [`Choices`] (a seeded generator in the tests,
//! libFuzzer's bytes in the fuzz target): balls on paths of every kind (at rest, straight,
//! friction-like runs to rest, accelerating for ever, piecewise with jumps), radii, the walls
//! of a box, a table of segments, circles, targets and planes, transitions on or off, a
//! horizon ([`calendar`]). [`play`] then runs operations on its calendar — events resolved as
//! a simulation resolves them (new paths for the balls involved, from where they are), skips
//! past events with a few balls changed, refused updates, balls retired — and checks after
//! each:
//!
//! - `next_collision`, `next_wall_contact` and `next_event` are, bit for bit, what recomputing
//!   every pair (`path_collision_time`), every ball's walls (`Walls::first_contact`), every
//!   ball against every object on its own (`path_table_contact`) and every ball's next
//!   segment start gives, at or after the current time and before the horizon, for the balls
//!   in play, ties in the order of `Event` ([`check`], [`order`]);
//! - whatever the magnitudes, each reported event is one: at or after the current time and
//!   before the horizon, of balls in play and in range, `i < j`, an axis, object or segment
//!   that exists, `next_event` no later than `next_collision` and `next_wall_contact`
//!   ([`events_are_events`]);
//! - a refused update (a start before the current time, an index out of range or repeated,
//!   starts that differ, lengths that differ) and a refused retirement are refused for that
//!   reason and leave the calendar exactly as it was (its `Debug` output), and a valid update
//!   is accepted and moves the time to its start ([`refused_updates_change_nothing`]);
//! - a retired ball is out of play until an update gives it a path again.
//!
//! The comparison with brute force holds where the calendar's pruning is exact: its boxes
//! (`src/schedule/reach.rs`) are grown by a margin far above the pair search's rounding
//! error, which `docs/contract.md` §5 bounds while a pair's non-zero magnitudes are within
//! `2^±400` of each other and exact (no subnormal numbers). Beyond that range the pair search
//! may report a contact that the exact motion does not have, which the boxes rightly prune.
//! The fuzz target therefore compares with brute force when every non-zero magnitude of the
//! calendar's state (positions, velocities and accelerations of every segment, radii, walls,
//! the table's points and radii) is a normal float within `2^±400` of every other
//! ([`within_promise`], as `tests/support/invariants.rs` does for the scene's broad phase),
//! and checks only [`events_are_events`] otherwise; the tests compare always
//! ([`Compare::Always`]), their scenes being in range or chosen beyond it on purpose.

#![allow(dead_code)]

use ballcollide::geometry::{
    Circle, LineSegment, ObjectKind, Plane, SegmentSide, Table, Target, path_table_contact,
};
use ballcollide::path::{Path, Segment};
use ballcollide::schedule::{
    Collision, CollisionSchedule, Event, ObjectEvent, ScheduleOptions, Transition, WallContact,
    Walls,
};
use ballcollide::{CollisionOptions, InputErrorKind, path_collision_time};
use nalgebra::{SVector, Vector2};

/// Where a scene's random decisions come from.
pub trait Choices {
    /// Uniform in `0..n` (`n > 0`).
    fn below(&mut self, n: u64) -> u64;
    /// Uniform in `[lo, hi)`.
    fn uniform(&mut self, lo: f64, hi: f64) -> f64;
}

/// How a scene's numbers are drawn.
#[derive(Clone, Copy, Debug)]
pub enum Numbers {
    /// Multiples of 1/8: exact contacts, tangencies and ties are common.
    Dyadic,
    /// Full mantissas.
    Full,
}

/// Draws scenes and paths: numbers in the scene's own units (a square of side `size`, speeds
/// up to 1, accelerations up to 1), then scaled by powers of two.
pub struct Draw<C> {
    pub rng: C,
    pub numbers: Numbers,
    /// The side of the square the balls start in (before `length`).
    pub size: f64,
    /// Every length is multiplied by this power of two (1 in the tests' scenes).
    pub length: f64,
    /// Every time is multiplied by this power of two (1 in the tests' scenes): velocities by
    /// `length / time`, accelerations by `length / time²`.
    pub time: f64,
    /// Up to how many binary orders of magnitude a ball's speed, radius or first position,
    /// or an object's position, may differ from the scene's (0, the tests' scenes: none).
    /// Each path, radius and object is so spread now and then.
    pub spread: u32,
    /// How many times as many objects of each kind a table may have as the tests' tables
    /// (1: up to 5 segments, 3 circles, 2 targets, 1 plane).
    pub objects: u64,
}

/// `2^e` (for `|e| ≤ 1000`).
fn pow2(e: i32) -> f64 {
    2f64.powi(e)
}

impl<C: Choices> Draw<C> {
    /// A draw in the scene's own units (no scaling, no spread).
    pub fn new(rng: C, numbers: Numbers, size: f64) -> Self {
        Self {
            rng,
            numbers,
            size,
            length: 1.0,
            time: 1.0,
            spread: 0,
            objects: 1,
        }
    }

    pub fn number(&mut self, lo: f64, hi: f64) -> f64 {
        let x = self.rng.uniform(lo, hi);
        match self.numbers {
            Numbers::Dyadic => (x * 8.0).round() / 8.0,
            Numbers::Full => x,
        }
    }

    pub fn vector<const D: usize>(&mut self, lo: f64, hi: f64) -> SVector<f64, D> {
        SVector::from_fn(|_, _| self.number(lo, hi))
    }

    /// A power of two `2^e`, `e` in `-spread..=spread` (1 without spread).
    fn spread_factor(&mut self) -> f64 {
        let s = u64::from(self.spread);
        pow2((self.rng.below(2 * s + 1) as i64 - s as i64) as i32)
    }

    /// Now and then (with spread) a power of two `2^e`, `0 ≤ e ≤ spread`, that puts a
    /// position far out (the grids' regions and cells then change); else 1.
    fn far(&mut self) -> f64 {
        if self.spread > 0 && self.rng.below(8) == 0 {
            self.spread_factor().max(1.0)
        } else {
            1.0
        }
    }

    /// A duration of up to `most` (scene time units), scaled.
    pub fn duration(&mut self, most: f64) -> f64 {
        self.number(0.0, most) * self.time
    }

    /// A path from `t` at `position` (or a random one): one of every kind. `None` where the
    /// scaled numbers overflow (no valid path).
    pub fn path<const D: usize>(
        &mut self,
        t: f64,
        position: Option<SVector<f64, D>>,
    ) -> Option<Path<D>> {
        let size = self.size;
        let p = match position {
            Some(p) => p,
            None => {
                let p: SVector<f64, D> = self.vector(0.0, size);
                p * (self.length * self.far())
            }
        };
        let kind = self.rng.below(6);
        // Now and then faster or slower than the rest (the boxes' horizons change).
        let pace = if self.spread > 0 && self.rng.below(4) == 0 {
            self.spread_factor()
        } else {
            1.0
        };
        let (l, v, a) = (
            self.length,
            self.length / self.time * pace,
            self.length / self.time / self.time * pace,
        );
        let zero = SVector::<f64, D>::zeros();
        let segments = match kind {
            0 => vec![Segment::at_rest(t, p)],
            1 | 2 => vec![Segment::new(t, p, self.vector(-1.0, 1.0) * v, zero)],
            3 => {
                // A friction-like run to rest: decelerated along its velocity.
                let velocity: SVector<f64, D> = self.vector(-1.0, 1.0) * v;
                let speed: f64 = velocity.norm();
                if speed == 0.0 {
                    vec![Segment::at_rest(t, p)]
                } else {
                    let mu = self.number(0.25, 1.0).max(0.125) * a;
                    let tau = speed / mu;
                    let acceleration = velocity * (-mu / speed);
                    let seg = Segment::new(t, p, velocity, acceleration);
                    vec![seg, Segment::at_rest(t + tau, seg.position_at(t + tau))]
                }
            }
            4 => {
                // Accelerating for ever (a ball in the air, say).
                vec![Segment::new(
                    t,
                    p,
                    self.vector(-1.0, 1.0) * v,
                    self.vector(-0.5, 0.5) * a,
                )]
            }
            _ => {
                // Pieces, positions continuous or not, an empty segment sometimes.
                let mut segments = Vec::new();
                let mut s = t;
                let mut seg =
                    Segment::new(t, p, self.vector(-1.0, 1.0) * v, self.vector(-0.5, 0.5) * a);
                for _ in 0..1 + self.rng.below(3) {
                    segments.push(seg);
                    s += self.duration(2.0);
                    let position = if self.rng.below(3) == 0 {
                        seg.position_at(s) + self.vector(-0.25, 0.25) * l
                    } else {
                        seg.position_at(s)
                    };
                    seg = Segment::new(
                        s,
                        position,
                        self.vector(-1.0, 1.0) * v,
                        self.vector(-0.5, 0.5) * a,
                    );
                }
                segments.push(Segment::new(seg.start, seg.position, seg.velocity, zero));
                segments
            }
        };
        Path::new(segments).ok()
    }

    /// A radius from 1/8 to 1/2 (scene units), scaled (and spread now and then).
    pub fn radius(&mut self) -> f64 {
        let r = self.number(0.125, 0.5).max(0.125) * self.length;
        if self.spread > 0 && self.rng.below(4) == 0 {
            r * self.spread_factor()
        } else {
            r
        }
    }

    /// A random table in the scene's square `[0, size]^D`: a few objects of every kind
    /// (those whose scaled numbers are no valid object left out).
    pub fn table<const D: usize>(&mut self) -> Table<D> {
        let (size, l, more) = (self.size, self.length, self.objects);
        let mut table = Table::default();
        for _ in 0..self.rng.below(5 * more + 1) {
            let p: SVector<f64, D> = self.vector::<D>(0.0, size) * (l * self.far());
            let q: SVector<f64, D> = self.vector::<D>(0.0, size) * (l * self.far());
            let side = SegmentSide::from_sign(self.rng.below(3) as i64 - 1).expect("a side");
            if let Ok(s) =
                LineSegment::new(Vector2::new(p[0], p[1]), Vector2::new(q[0], q[1]), side)
            {
                table.segments.push(s);
            }
        }
        for _ in 0..self.rng.below(3 * more + 1) {
            let rho = if self.rng.below(3) == 0 {
                0.0
            } else {
                self.number(0.0, 0.5)
            };
            let centre = self.vector::<D>(0.0, size) * (l * self.far());
            if let Ok(c) = Circle::new(centre, rho * l) {
                table.circles.push(c);
            }
        }
        for _ in 0..self.rng.below(2 * more + 1) {
            let rho = self.number(0.125, 0.5).max(0.125);
            let centre = self.vector::<D>(0.0, size) * (l * self.far());
            if let Ok(t) = Target::new(centre, rho * l) {
                table.targets.push(t);
            }
        }
        for _ in 0..self.rng.below(more + 1) {
            let n: SVector<f64, D> = self.vector(-1.0, 1.0);
            let point = self.vector::<D>(0.0, size) * (l * self.far());
            if let Ok(plane) = Plane::new(point, n) {
                table.planes.push(plane);
            }
        }
        table
    }
}

/// A scene's shape: how many balls, and what else the calendar holds.
#[derive(Clone, Copy, Debug)]
pub struct Scene {
    pub n: usize,
    /// The walls of the box `[-1/2, size + 1/2]^D` (scene units).
    pub walls: bool,
    pub table: bool,
    pub transitions: bool,
    /// The horizon (scene units of time; `∞` for none).
    pub t_max: f64,
    /// The paths' first start (scene units of time).
    pub start: f64,
    /// Whether each ball's first start is a random time after `start` (else all at `start`).
    pub stagger: bool,
}

/// The calendar of a random scene of `scene`'s shape, and what it was made from (for a
/// failure's message); `Ok(None)` if the scaled numbers make no valid scene (a path or a
/// radius that overflows, a radius that underflows to 0).
///
/// # Errors
/// If the calendar refuses a valid scene.
pub fn calendar<const D: usize, C: Choices>(
    draw: &mut Draw<C>,
    scene: &Scene,
) -> Result<Option<(CollisionSchedule<D>, Made<D>)>, String> {
    let mut paths: Vec<Path<D>> = Vec::with_capacity(scene.n);
    let mut valid = true;
    for _ in 0..scene.n {
        let mut start = scene.start * draw.time;
        if scene.stagger {
            start += draw.duration(2.0);
        }
        match draw.path(start, None) {
            Some(p) => paths.push(p),
            None => valid = false,
        }
    }
    let radii: Vec<f64> = (0..scene.n).map(|_| draw.radius()).collect();
    let (lo, hi) = (-0.5 * draw.length, (draw.size + 0.5) * draw.length);
    let walls = if scene.walls {
        Some(Walls::new([lo; D], [hi; D]).ok())
    } else {
        None
    };
    let table = if scene.table {
        draw.table()
    } else {
        Table::default()
    };
    let t_max = scene.t_max * draw.time;
    // A ball as wide as the box is refused (`wider_than_box`).
    let radii_valid = radii
        .iter()
        .all(|&r| r > 0.0 && r.is_finite() && !(scene.walls && 2.0 * r >= hi - lo));
    let walls = match walls {
        None => None,
        Some(Some(w)) => Some(w),
        Some(None) => return Ok(None),
    };
    if !(valid && radii_valid && t_max >= 0.0) {
        return Ok(None);
    }
    let options = ScheduleOptions {
        walls,
        table,
        transitions: scene.transitions,
        t_max,
    };
    let made = Made {
        paths: paths.clone(),
        radii: radii.clone(),
        options: options.clone(),
    };
    match CollisionSchedule::new(paths, &radii, options) {
        Ok(s) => Ok(Some((s, made))),
        Err(e) => Err(format!("a valid scene refused: {e}: {made:?}")),
    }
}

/// What a calendar was made from.
#[derive(Clone, Debug)]
pub struct Made<const D: usize> {
    pub paths: Vec<Path<D>>,
    pub radii: Vec<f64>,
    pub options: ScheduleOptions<D>,
}

/// An operation of [`play`]'s that changed the calendar (for a failure's message).
#[derive(Clone, Debug)]
pub enum Operation<const D: usize> {
    Retire(usize),
    Update(Vec<usize>, Vec<Path<D>>),
}

/// Whether every non-zero magnitude of the calendar's state — every segment's position,
/// velocity and acceleration, the radii, the walls, the table's points and radii (not a
/// plane's normal, a direction) — is a normal float within `2^±400` of every other: the range
/// in which `docs/contract.md` §5 promises the pair search's accuracy, which the calendar's
/// pruning relies on (module documentation).
pub fn within_promise<const D: usize>(s: &CollisionSchedule<D>) -> bool {
    let mut values: Vec<f64> = Vec::new();
    for i in 0..s.len() {
        values.push(s.radius(i));
        for seg in s.path(i).segments() {
            values.extend(seg.position.iter());
            values.extend(seg.velocity.iter());
            values.extend(seg.acceleration.iter());
        }
    }
    if let Some(w) = s.walls() {
        values.extend(w.lo());
        values.extend(w.hi());
    }
    let table = s.table();
    for seg in &table.segments {
        values.extend(seg.p().iter().chain(seg.q().iter()));
    }
    for c in &table.circles {
        values.extend(c.centre().iter());
        values.push(c.rho());
    }
    for t in &table.targets {
        values.extend(t.centre().iter());
        values.push(t.rho());
    }
    for p in &table.planes {
        values.extend(p.point().iter());
    }
    let (lo, hi) = values
        .iter()
        .map(|x| x.abs())
        .filter(|&x| x > 0.0)
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), x| {
            (lo.min(x), hi.max(x))
        });
    hi == 0.0 || (lo >= f64::MIN_POSITIVE && hi <= lo * pow2(400))
}

/// The brute-force answer: every pair recomputed.
///
/// # Errors
/// If the pair search refuses a pair of the calendar's.
pub fn brute_collision<const D: usize>(
    s: &CollisionSchedule<D>,
) -> Result<Option<Collision>, String> {
    let options = CollisionOptions { t_max: s.t_max() };
    let mut best: Option<Collision> = None;
    for i in (0..s.len()).filter(|&i| s.in_play(i)) {
        for j in (i + 1..s.len()).filter(|&j| s.in_play(j)) {
            let r = s.radius(i) + s.radius(j);
            let t = path_collision_time(s.path(i), s.path(j), r, &options)
                .map_err(|e| format!("pair ({i}, {j}) refused by the pair search: {e}"))?;
            if let Some(t) = t.filter(|&t| t >= s.time()) {
                // Strictly earlier only: pairs come in (i, j) order.
                if best.is_none_or(|b| t < b.time) {
                    best = Some(Collision { time: t, i, j });
                }
            }
        }
    }
    Ok(best)
}

/// The brute-force wall contact: every ball recomputed.
///
/// # Errors
/// If the wall query refuses a ball of the calendar's.
pub fn brute_wall<const D: usize>(s: &CollisionSchedule<D>) -> Result<Option<WallContact>, String> {
    let Some(walls) = s.walls() else {
        return Ok(None);
    };
    let mut best: Option<WallContact> = None;
    for ball in (0..s.len()).filter(|&i| s.in_play(i)) {
        let hit = walls
            .first_contact(s.path(ball), s.radius(ball), s.t_max())
            .map_err(|e| format!("ball {ball} refused by the wall query: {e}"))?;
        // Strictly earlier only: balls come in order.
        let earlier = |h: &(f64, usize, _)| h.0 >= s.time() && best.is_none_or(|b| h.0 < b.time);
        if let Some((time, axis, side)) = hit.filter(earlier) {
            best = Some(WallContact {
                time,
                ball,
                axis,
                side,
            });
        }
    }
    Ok(best)
}

/// The brute-force object contact: every ball against every object, each object on its own
/// (a table of one), contacts at or after the current time, in the order of `Event`.
///
/// # Errors
/// If the table query refuses a ball of the calendar's.
pub fn brute_object<const D: usize>(
    s: &CollisionSchedule<D>,
) -> Result<Option<ObjectEvent>, String> {
    let table = s.table();
    let options = CollisionOptions { t_max: s.t_max() };
    let mut best: Option<ObjectEvent> = None;
    for ball in (0..s.len()).filter(|&i| s.in_play(i)) {
        for kind in ObjectKind::ALL {
            for index in 0..table.count(kind) {
                let mut one = Table::default();
                match kind {
                    ObjectKind::Segment => one.segments.push(table.segments[index]),
                    ObjectKind::Circle => one.circles.push(table.circles[index]),
                    ObjectKind::Target => one.targets.push(table.targets[index]),
                    ObjectKind::Plane => one.planes.push(table.planes[index]),
                }
                let hit = path_table_contact(s.path(ball), &one, s.radius(ball), &options)
                    .map_err(|e| format!("ball {ball} refused by the table query: {e}"))?;
                // Strictly earlier only: balls, kinds and indices come in order.
                if let Some(c) = hit.filter(|c| c.time >= s.time())
                    && best.is_none_or(|b| c.time < b.time)
                {
                    best = Some(ObjectEvent {
                        time: c.time,
                        ball,
                        kind,
                        index,
                    });
                }
            }
        }
    }
    Ok(best)
}

/// The brute-force transition: every ball's next segment start at or after the current time.
pub fn brute_transition<const D: usize>(s: &CollisionSchedule<D>) -> Option<Transition> {
    let mut best: Option<Transition> = None;
    for ball in (0..s.len()).filter(|&i| s.in_play(i)) {
        let next = s
            .path(ball)
            .segments()
            .iter()
            .enumerate()
            .skip(1)
            .find(|(_, x)| x.start >= s.time());
        if let Some((segment, x)) = next.filter(|(_, x)| x.start < s.t_max())
            && best.is_none_or(|b| x.start < b.time)
        {
            best = Some(Transition {
                time: x.start,
                ball,
                segment,
            });
        }
    }
    best
}

/// An event's place in `Event`'s order, written out here on its own (for times ≥ 0, whose
/// bits order as they do; [`check`] orders any time).
pub fn order(e: &Event) -> (u64, usize, u8, usize, usize) {
    let bits = |t: f64| t.to_bits();
    match *e {
        Event::Transition(t) => (bits(t.time), t.ball, 0, t.segment, 0),
        Event::Wall(w) => (bits(w.time), w.ball, 1, w.axis, w.side as usize),
        Event::Object(o) => (bits(o.time), o.ball, 2, o.kind as usize, o.index),
        Event::Collision(c) => (bits(c.time), c.i, 3, c.j, 0),
    }
}

/// `order` for any time: the bits of a negative time made to order as the time does.
fn total_order(e: &Event) -> (u64, usize, u8, usize, usize) {
    let (bits, ball, kind, a, b) = order(e);
    let key = if bits >> 63 == 1 {
        !bits
    } else {
        bits | 1 << 63
    };
    (key, ball, kind, a, b)
}

fn bits_c(c: Option<Collision>) -> Option<(u64, usize, usize)> {
    c.map(|c| (c.time.to_bits(), c.i, c.j))
}

/// The balls of an event, for a failure's message.
fn balls_of(e: &Event) -> Vec<usize> {
    match *e {
        Event::Transition(t) => vec![t.ball],
        Event::Wall(w) => vec![w.ball],
        Event::Object(o) => vec![o.ball],
        Event::Collision(c) => vec![c.i, c.j],
    }
}

/// The paths and radii of `balls`, for a failure's message.
fn describe<const D: usize>(s: &CollisionSchedule<D>, balls: &[usize]) -> String {
    balls
        .iter()
        .map(|&i| format!("ball {i}: radius {:?}, {:?}", s.radius(i), s.path(i)))
        .collect::<Vec<_>>()
        .join("; ")
}

/// Checks the calendar against brute force, and returns its next event.
///
/// # Errors
/// A message naming the answer that differs, the two answers and the balls involved.
pub fn check<const D: usize>(s: &mut CollisionSchedule<D>) -> Result<Option<Event>, String> {
    let now = s.time();
    let expected = brute_collision(s)?;
    let got = s.next_collision();
    if bits_c(got) != bits_c(expected) {
        let balls: Vec<usize> = [got, expected]
            .iter()
            .flatten()
            .flat_map(|c| [c.i, c.j])
            .collect();
        return Err(format!(
            "next_collision at {now:?}: the calendar says {got:?}, brute force {expected:?} ({})",
            describe(s, &balls)
        ));
    }
    let wall = brute_wall(s)?;
    let got = s.next_wall_contact();
    if got != wall || got.map(|w| w.time.to_bits()) != wall.map(|w| w.time.to_bits()) {
        let balls: Vec<usize> = [got, wall].iter().flatten().map(|w| w.ball).collect();
        return Err(format!(
            "next_wall_contact at {now:?}: the calendar says {got:?}, brute force {wall:?} ({})",
            describe(s, &balls)
        ));
    }
    let transitions = s.transitions();
    let candidates = [
        expected.map(Event::Collision),
        wall.map(Event::Wall),
        brute_object(s)?.map(Event::Object),
        brute_transition(s)
            .filter(|_| transitions)
            .map(Event::Transition),
    ];
    let expected = candidates.into_iter().flatten().min_by_key(total_order);
    let event = s.next_event();
    if event.as_ref().map(order) != expected.as_ref().map(order) {
        let balls: Vec<usize> = [event, expected]
            .iter()
            .flatten()
            .flat_map(balls_of)
            .collect();
        return Err(format!(
            "next_event at {now:?}: the calendar says {event:?}, brute force {expected:?} ({})",
            describe(s, &balls)
        ));
    }
    Ok(event)
}

/// Checks that the calendar's answers are events at all, whatever the magnitudes (module
/// documentation), and returns its next event.
///
/// # Errors
/// A message naming what is wrong.
pub fn events_are_events<const D: usize>(
    s: &mut CollisionSchedule<D>,
) -> Result<Option<Event>, String> {
    let (now, t_max, n) = (s.time(), s.t_max(), s.len());
    let when = |t: f64| t >= now && t < t_max;
    let collision = s.next_collision();
    if let Some(c) = collision
        && !(when(c.time) && c.i < c.j && c.j < n && s.in_play(c.i) && s.in_play(c.j))
    {
        return Err(format!(
            "next_collision at {now:?} (t_max {t_max:?}, {n} balls): {c:?}"
        ));
    }
    let wall = s.next_wall_contact();
    if let Some(w) = wall
        && !(when(w.time) && w.ball < n && s.in_play(w.ball) && w.axis < D && s.walls().is_some())
    {
        return Err(format!(
            "next_wall_contact at {now:?} (t_max {t_max:?}, {n} balls): {w:?}"
        ));
    }
    let event = s.next_event();
    let Some(e) = event else {
        return if collision.is_some() || wall.is_some() {
            Err(format!(
                "next_event at {now:?} is none, but {collision:?}, {wall:?}"
            ))
        } else {
            Ok(None)
        };
    };
    let valid = when(e.time())
        && balls_of(&e).iter().all(|&i| i < n && s.in_play(i))
        && match e {
            Event::Collision(c) => c.i < c.j,
            Event::Wall(w) => w.axis < D && s.walls().is_some(),
            Event::Object(o) => o.index < s.table().count(o.kind),
            Event::Transition(t) => {
                s.transitions()
                    && t.segment >= 1
                    && s.path(t.ball)
                        .segments()
                        .get(t.segment)
                        .is_some_and(|x| x.start.to_bits() == t.time.to_bits())
            }
        };
    let not_later = [collision.map(Event::Collision), wall.map(Event::Wall)]
        .iter()
        .flatten()
        .all(|x| total_order(&e) <= total_order(x));
    if !(valid && not_later) {
        return Err(format!(
            "next_event at {now:?} (t_max {t_max:?}, {n} balls): {e:?}; next_collision \
             {collision:?}, next_wall_contact {wall:?}"
        ));
    }
    Ok(event)
}

/// A time before `t` (`t - step`, or the float just below where that rounds back to `t`).
fn before(t: f64, step: f64) -> f64 {
    if t - step < t {
        t - step
    } else {
        t.next_down()
    }
}

/// A time after `t` (`t + step`, or the float just above).
fn after(t: f64, step: f64) -> f64 {
    if t + step > t { t + step } else { t.next_up() }
}

/// Every kind of refused update (and a refused retirement) leaves the calendar exactly as it
/// was, refused for its reason.
///
/// # Errors
/// An update accepted or refused for another reason, or a calendar changed by a refusal.
pub fn refused_updates_change_nothing<const D: usize, C: Choices>(
    s: &mut CollisionSchedule<D>,
    draw: &mut Draw<C>,
) -> Result<(), String> {
    let n = s.len();
    let before_text = format!("{s:?}");
    let t = s.time();
    let attempt = |s: &mut CollisionSchedule<D>,
                   what: &str,
                   indices: &[usize],
                   paths: Vec<Option<Path<D>>>,
                   kind: fn(InputErrorKind) -> bool|
     -> Result<(), String> {
        // (A path whose scaled numbers overflow: no update to try.)
        let Some(paths) = paths.into_iter().collect::<Option<Vec<_>>>() else {
            return Ok(());
        };
        match s.update(indices, paths) {
            Ok(()) => return Err(format!("{what}: accepted at {t:?}")),
            Err(e) if !kind(e.kind()) => return Err(format!("{what}: refused as {e}")),
            Err(_) => {}
        }
        if format!("{s:?}") != before_text {
            return Err(format!("{what}: refused, but the calendar changed"));
        }
        Ok(())
    };
    if t.is_finite() && t > f64::MIN {
        let past = before(t, draw.time);
        attempt(
            s,
            "a path before the current time",
            &[0],
            vec![draw.path(past, None)],
            |k| matches!(k, InputErrorKind::BeforeCurrentTime { .. }),
        )?;
    }
    attempt(
        s,
        "an index out of range",
        &[n],
        vec![draw.path(t, None)],
        |k| matches!(k, InputErrorKind::IndexOutOfRange { .. }),
    )?;
    if n >= 2 {
        let paths = vec![draw.path(t, None), draw.path(t, None), draw.path(t, None)];
        attempt(s, "a repeated index", &[1, 0, 1], paths, |k| {
            matches!(k, InputErrorKind::RepeatedIndex(1))
        })?;
        let paths = vec![draw.path(t, None), draw.path(after(t, draw.time), None)];
        attempt(s, "starts that differ", &[0, 1], paths, |k| {
            matches!(k, InputErrorKind::StartsDiffer { .. })
        })?;
    }
    attempt(s, "no path for an index", &[0], Vec::new(), |k| {
        matches!(k, InputErrorKind::LengthMismatch { .. })
    })?;
    if s.retire(n).is_ok() {
        return Err(format!("retire({n}) of {n} balls accepted"));
    }
    if format!("{s:?}") != before_text {
        return Err("a refused retire changed the calendar".into());
    }
    Ok(())
}

/// Whether [`play`] compares with brute force at every step, or only within the range of
/// [`within_promise`] (else only [`events_are_events`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Compare {
    Always,
    WithinPromise,
}

/// How often [`play`] does what besides resolving and skipping: refused updates at the steps
/// `k` with `k % refuse.0 == refuse.1`, a ball retired at those with `k % retire.0 ==
/// retire.1`.
#[derive(Clone, Copy, Debug)]
pub struct Plan {
    pub refuse: (usize, usize),
    pub retire: (usize, usize),
    pub compare: Compare,
}

impl Plan {
    /// The tests' plan: refusals every 7 steps, retirements every 11, brute force always.
    pub const TESTS: Plan = Plan {
        refuse: (7, 3),
        retire: (11, 5),
        compare: Compare::Always,
    };
}

/// What a [`play`] went through.
#[derive(Clone, Copy, Debug, Default)]
pub struct Seen {
    /// The events met by class (transition, wall, object, collision: [`order`]'s numbering).
    pub events: [usize; 4],
    /// The checks made, and how many of them compared with brute force.
    pub checks: usize,
    pub compared: usize,
}

/// `steps` random events and updates on the calendar `s`, checked throughout (module
/// documentation): events resolved as a simulation would, skips past events, refused updates,
/// retirements.
///
/// # Errors
/// The first invariant broken, with the step and the operations that led there.
pub fn play<const D: usize, C: Choices>(
    s: &mut CollisionSchedule<D>,
    draw: &mut Draw<C>,
    steps: usize,
    plan: Plan,
) -> Result<Seen, String> {
    let mut log: Vec<Operation<D>> = Vec::new();
    let mut seen = Seen::default();
    let result = steps_of(s, draw, steps, plan, &mut log, &mut seen);
    result
        .map(|()| seen)
        .map_err(|e| format!("{e}\nafter {} operations: {log:#?}", log.len()))
}

fn steps_of<const D: usize, C: Choices>(
    s: &mut CollisionSchedule<D>,
    draw: &mut Draw<C>,
    steps: usize,
    plan: Plan,
    log: &mut Vec<Operation<D>>,
    seen: &mut Seen,
) -> Result<(), String> {
    let n = s.len();
    let check_now = |s: &mut CollisionSchedule<D>, seen: &mut Seen| {
        seen.checks += 1;
        if plan.compare == Compare::Always || within_promise(s) {
            seen.compared += 1;
            check(s)
        } else {
            events_are_events(s)
        }
    };
    for step in 0..steps {
        let event = check_now(s, seen)?;
        if let Some(e) = event {
            seen.events[order(&e).2 as usize] += 1;
        }
        if n > 0 && step % plan.refuse.0 == plan.refuse.1 {
            refused_updates_change_nothing(s, draw)?;
        }
        if n > 0 && step % plan.retire.0 == plan.retire.1 {
            // Out of play (a capture), until an update brings it back.
            let i = draw.rng.below(n as u64) as usize;
            log.push(Operation::Retire(i));
            s.retire(i)
                .map_err(|e| format!("retire({i}) refused: {e}"))?;
            if s.in_play(i) {
                return Err(format!("ball {i} in play after retire({i})"));
            }
            check_now(s, seen)?;
        }
        let roll = draw.rng.below(10);
        let now = s.time();
        let (indices, t): (Vec<usize>, f64) = match event {
            // Resolve the event, as a simulation does: new paths from where the balls are.
            Some(e) if roll < 7 => {
                let t = e.time();
                match e {
                    Event::Collision(c) => (vec![c.i, c.j], t),
                    Event::Wall(w) => (vec![w.ball], t),
                    Event::Object(o) => (vec![o.ball], t),
                    Event::Transition(x) => (vec![x.ball], t),
                }
            }
            // Skip ahead, past events perhaps, and change a few balls.
            _ if n > 0 => {
                let k = 1 + draw.rng.below(3.min(n as u64)) as usize;
                let mut indices: Vec<usize> = Vec::new();
                while indices.len() < k {
                    let i = draw.rng.below(n as u64) as usize;
                    if !indices.contains(&i) {
                        indices.push(i);
                    }
                }
                let dt = if roll == 9 { 0.0 } else { draw.duration(3.0) };
                (indices, if now.is_finite() { now + dt } else { now })
            }
            _ => return Ok(()),
        };
        if !t.is_finite() {
            return Ok(());
        }
        let paths = indices
            .iter()
            .map(|&i| {
                let here = if draw.rng.below(4) == 0 {
                    None
                } else {
                    Some(s.path(i).position_at(t))
                };
                draw.path(t, here)
            })
            .collect::<Vec<_>>();
        // (A new path whose scaled numbers overflow: this step changes nothing.)
        let Some(paths) = paths.into_iter().collect::<Option<Vec<_>>>() else {
            continue;
        };
        log.push(Operation::Update(indices.clone(), paths.clone()));
        s.update(&indices, paths)
            .map_err(|e| format!("a valid update refused: {e}"))?;
        if s.time().to_bits() != (t + 0.0).to_bits() {
            return Err(format!(
                "the time is {:?} after an update at {t:?}",
                s.time()
            ));
        }
    }
    // After the last operation too.
    check_now(s, seen).map(|_| ())
}
