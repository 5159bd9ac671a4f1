//! [`simulate`]: an event-driven simulation of smooth hard friction balls in a box, on the
//! calendar.
//!
//! Each ball is a friction [`Ball`] (slowed along its velocity until it stops; no friction,
//! and it moves straight on). At each event, in the calendar's order:
//! - two balls touch: momentum is exchanged along the line of centres `n` with the
//!   restitution `e` and the masses, so that they part at the normal speed
//!   `w = max(e·u, w_min)`, `u` the speed at which they approached (the tangential
//!   components are kept: smooth balls; see [`parting_speed`] for `w_min`); a ball's second
//!   and later events at one instant are elastic (see [`restitution_at`]), and a pair that
//!   a later event of the instant leaves parting too slowly collides again (`collide_pair`);
//! - a ball touches a wall: its velocity's component normal to the wall is reflected;
//! - a ball touches a segment, a circle or a plane of the table: its velocity's component
//!   normal to the object (from the contact point to its centre) is reflected with the
//!   table's restitution (and made at least `2⁻⁴⁰` of its speed, so that it parts);
//! - a ball's centre enters a target: the ball is captured, at rest where it entered, and
//!   takes no further part ([`CollisionSchedule::retire`]);
//!
//! and the balls involved get new friction paths from the event's time. It runs until
//! `t_end`, `max_events` or until no event is left (every ball at rest, or moving away for
//! ever).
//!
//! It always moves on. A start that no motion could come from (balls overlapping each other
//! or a wall, or a ball as wide as the box) is refused. Two balls pressed together (a resting
//! contact: restitution 0 and frictions that push one into the other) part at `w_min` at each
//! touch, so they bounce within a hair's breadth (`2⁻²¹` of their contact distance) instead
//! of colliding again at the same instant for ever, or sinking into each other unseen. What
//! is left, events piling up at one instant without end, is an error naming the balls.

use super::calendar::{CollisionSchedule, ScheduleOptions, friction_paths};
use super::event::Event;
use super::objects::ObjectCounts;
use super::walls::{Side, Walls};
use crate::collision::length_unit::{largest, norm_in_range, unit_of_largest};
use crate::error::{InputError, InputErrorKind, check_horizon, finite};
use crate::geometry::{ObjectKind, Table};
use crate::motion::Ball;
use nalgebra::Vector2;
use std::ops::ControlFlow;

/// Options of [`simulate`].
///
/// ```
/// use ballcollide::schedule::SimulationOptions;
/// let options = SimulationOptions { restitution: 0.9, ..Default::default() };
/// assert_eq!(options.max_events, None);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct SimulationOptions {
    /// Each ball's mass (one for all if a single value). Default `[1]`.
    pub mass: Vec<f64>,
    /// The coefficient of restitution of ball–ball collisions, in `[0, 1]`. Default 1.
    pub restitution: f64,
    /// The simulation ends at this time. Default `∞`.
    pub t_end: f64,
    /// The simulation ends after this many events. Default none.
    pub max_events: Option<usize>,
    /// The table's objects, besides the box. Default none.
    pub table: Table<2>,
    /// The coefficient of restitution of ball–object contacts, in `[0, 1]`. Default 1.
    pub table_restitution: f64,
}

impl Default for SimulationOptions {
    fn default() -> Self {
        Self {
            mass: vec![1.0],
            restitution: 1.0,
            t_end: f64::INFINITY,
            max_events: None,
            table: Table::default(),
            table_restitution: 1.0,
        }
    }
}

/// One event of a simulation's log: balls `i` and `j` collide at `time`, or ball `i` touches
/// a wall (`j = None`, `wall`: its axis and side) or an object of the table (`j = None`,
/// `object`: its kind and index; a target captures the ball).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LoggedEvent {
    /// When.
    pub time: f64,
    /// The (lower) ball.
    pub i: usize,
    /// The other ball, `None` for a wall or an object.
    pub j: Option<usize>,
    /// The wall, for a wall contact: its axis and side.
    pub wall: Option<(usize, Side)>,
    /// The object, for an object contact.
    pub object: Option<(ObjectKind, usize)>,
}

/// What [`simulate`] returns: the event log and the final state.
#[derive(Clone, Debug, PartialEq)]
pub struct Simulation {
    /// The events, in order.
    pub events: Vec<LoggedEvent>,
    /// The time of the final state: `t_end` if finite and reached; else the time of the last
    /// event (`max_events`), or the time every ball is at rest (no event left; `0`, the start,
    /// if some ball moves away for ever).
    pub end: f64,
    /// The balls at `end` (a captured ball at rest where it entered its target).
    pub balls: Vec<Ball>,
    /// Per ball, the target that captured it, if any.
    pub captured: Vec<Option<usize>>,
    /// How many ball–object pairs the calendar's object grid left out and asked
    /// ([`CollisionSchedule::object_counts`]).
    pub object_counts: ObjectCounts,
    /// Whether the run was stopped by its observer ([`simulate_observed`]) before its end.
    pub stopped: bool,
}

/// How far a simulation has come: what [`simulate_observed`]'s observer is shown after each
/// event.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Progress {
    /// The events so far.
    pub events: usize,
    /// The time of the last event.
    pub time: f64,
}

/// Simulates friction balls of `radii` in the box `walls` from time 0 (see the module
/// documentation).
///
/// # Errors
/// An [`InputError`]: a bad radius or mass (`mass[i]`, finite and `> 0`, one or one per
/// ball), a restitution outside `[0, 1]`, a NaN `t_end`; no `t_end`, no `max_events` and a
/// ball without friction (it would never end); a ball that overlaps another (`pos[i]`,
/// [`InputErrorKind::Overlap`]) or a wall, or lies outside the box (`pos[i]`,
/// [`InputErrorKind::OutsideBox`]), at the start, beyond `2⁻³⁰` of the radii (touching is
/// fine); a ball as wide as the box or wider, within the same `2⁻³⁰` (`radius[i]`:
/// it would touch both walls at once); more events at one instant than
/// [`MAX_EVENTS_AT_ONE_INSTANT`] allows for `N` balls (`pos[i]`,
/// [`InputErrorKind::NoProgress`], naming the two balls of the last one).
///
/// ```
/// use ballcollide::Ball;
/// use ballcollide::schedule::{SimulationOptions, Walls, simulate};
/// use nalgebra::Vector2;
///
/// // A ball at 1 m/s towards a resting one, in a 4 m × 1 m box: equal masses swap velocities.
/// let balls = [Ball::new(Vector2::new(0.5, 0.5), Vector2::new(1.0, 0.0), 0.0)?, Ball::at_rest(Vector2::new(2.0, 0.5))?];
/// let walls = Walls::new([0.0, 0.0], [4.0, 1.0])?;
/// let options = SimulationOptions { t_end: 3.0, ..Default::default() };
/// let run = simulate(&balls, &[0.25, 0.25], walls, &options)?;
/// assert_eq!((run.events[0].time, run.events[0].i, run.events[0].j), (1.0, 0, Some(1)));
/// assert_eq!((run.events[1].time, run.events[1].i, run.events[1].j), (2.75, 1, None));
/// assert_eq!(run.balls[0].velocity(), Vector2::zeros());
/// assert_eq!(run.balls[1].position(), Vector2::new(3.5, 0.5)); // back from the wall at 3.75
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn simulate(
    balls: &[Ball],
    radii: &[f64],
    walls: Walls<2>,
    options: &SimulationOptions,
) -> Result<Simulation, InputError> {
    simulate_observed(balls, radii, walls, options, |_| ControlFlow::Continue(()))
}

/// Events at one instant allowed for `n` balls: `1,000 + 64·n`. A touching chain or cluster
/// resolves in far fewer (each pair parts at once); more means the run is stuck.
pub const MAX_EVENTS_AT_ONE_INSTANT: (usize, usize) = (1000, 64);

/// [`simulate`], showing `observe` how far it has come after each event; `observe` returns
/// [`ControlFlow::Break`] to stop the run there (as if `max_events` were reached, with
/// [`Simulation::stopped`] set). For progress bars and for interrupting long runs (the
/// Python binding checks for Ctrl-C there).
///
/// # Errors
/// As [`simulate`].
///
/// ```
/// use ballcollide::Ball;
/// use ballcollide::schedule::{SimulationOptions, Walls, simulate_observed};
/// use nalgebra::Vector2;
/// use std::ops::ControlFlow;
///
/// let balls = [Ball::new(Vector2::new(0.5, 0.5), Vector2::new(1.0, 0.0), 0.0)?];
/// let walls = Walls::new([0.0, 0.0], [2.0, 1.0])?;
/// // Stop after three wall contacts, whatever the options say.
/// let run = simulate_observed(&balls, &[0.25], walls, &SimulationOptions { t_end: 100.0, ..Default::default() }, |p| {
///     if p.events == 3 { ControlFlow::Break(()) } else { ControlFlow::Continue(()) }
/// })?;
/// assert_eq!((run.events.len(), run.stopped, run.end), (3, true, 4.25));
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn simulate_observed(
    balls: &[Ball],
    radii: &[f64],
    walls: Walls<2>,
    options: &SimulationOptions,
    observe: impl FnMut(Progress) -> ControlFlow<()>,
) -> Result<Simulation, InputError> {
    simulate_in(balls, radii, walls, options, observe, true)
}

/// [`simulate_observed`], its calendar told that every wall contact is resolved
/// (`walls_resolved`, what this loop does: its pair searches stop at the walls), or not (the
/// same run, by the tests).
fn simulate_in(
    balls: &[Ball],
    radii: &[f64],
    walls: Walls<2>,
    options: &SimulationOptions,
    mut observe: impl FnMut(Progress) -> ControlFlow<()>,
    walls_resolved: bool,
) -> Result<Simulation, InputError> {
    let n = balls.len();
    let masses = masses(&options.mass, n)?;
    let e = options.restitution;
    if !(0.0..=1.0).contains(&e) {
        return Err(InputError::new(
            "restitution",
            InputErrorKind::NotInUnitInterval(e),
        ));
    }
    let t_end = check_horizon("t_end", options.t_end)?;
    let endless = t_end == f64::INFINITY
        && options.max_events.is_none()
        && balls.iter().any(|b| b.friction() == 0.0 && !b.is_at_rest());
    if endless {
        return Err(InputError::new("t_end", InputErrorKind::Endless));
    }
    let table_restitution = options.table_restitution;
    if !(0.0..=1.0).contains(&table_restitution) {
        let kind = InputErrorKind::NotInUnitInterval(table_restitution);
        return Err(InputError::new("table_restitution", kind));
    }
    let calendar_options = ScheduleOptions {
        walls: Some(walls),
        table: options.table.clone(),
        t_max: t_end,
        ..Default::default()
    };
    // `from_balls`, told that every wall contact is resolved below.
    let paths = friction_paths(balls, 0.0)?;
    let mut calendar = CollisionSchedule::build(paths, radii, calendar_options, walls_resolved)?;
    check_start(balls, radii, &walls)?;
    check_start_on_table(balls, radii, &options.table)?;
    let mut captured: Vec<Option<usize>> = vec![None; n];
    // Whether any ball is captured yet: until one is, the follow-ups do not look (a random
    // read per ball, a cache miss in a large scene).
    let mut any_captured = false;
    let mut events = Vec::new();
    let max_events = options.max_events.unwrap_or(usize::MAX);
    let most_at_one_instant = MAX_EVENTS_AT_ONE_INSTANT
        .1
        .saturating_mul(n)
        .saturating_add(MAX_EVENTS_AT_ONE_INSTANT.0);
    let mut at_this_instant = 0usize;
    let mut records: Vec<BallRecord> = balls
        .iter()
        .zip(radii)
        .enumerate()
        .map(|(i, (b, &radius))| BallRecord {
            friction: b.friction(),
            radius,
            mass: masses.get(i),
            last_event: f64::NEG_INFINITY,
        })
        .collect();
    // The pairs that collided at the current instant (see `collide_pair`).
    let mut instant_pairs: Vec<[usize; 2]> = Vec::new();
    // The balls whose velocity an event changed, whose pairs of the instant are followed up
    // (kept from event to event: no allocation per event).
    let mut moved: Vec<usize> = Vec::new();
    let mut end = 0.0;
    let mut stopped = false;
    'events: while events.len() < max_events {
        let Some(event) = calendar.next_event() else {
            break;
        };
        let t = event.time();
        if t != end || events.is_empty() {
            at_this_instant = 0;
            instant_pairs.clear();
        }
        end = t;
        let (i, j, wall, object) = match event {
            Event::Collision(c) => {
                collide_pair(e, &mut calendar, &mut records, [c.i, c.j], t, false)?;
                instant_pairs.push([c.i, c.j]);
                moved.extend([c.i, c.j]);
                (c.i, Some(c.j), None, None)
            }
            Event::Object(o) => {
                records[o.ball].last_event = t;
                let (p, v) = at(&calendar, o.ball, t);
                let friction = records[o.ball].friction;
                if o.kind == ObjectKind::Target {
                    calendar.update_balls(
                        &[o.ball],
                        t,
                        &[Ball::from_checked(p.into(), [0.0; 2], friction)],
                    )?;
                    calendar.retire(o.ball)?;
                    captured[o.ball] = Some(o.index);
                    any_captured = true;
                } else {
                    let normal = options.table.normal_at(o.kind, o.index, p);
                    let v = reflected(v, normal, table_restitution);
                    calendar.update_balls(
                        &[o.ball],
                        t,
                        &[Ball::from_checked(p.into(), v.into(), friction)],
                    )?;
                    moved.push(o.ball);
                }
                (o.ball, None, None, Some((o.kind, o.index)))
            }
            // (Not asked for.)
            Event::Transition(_) => continue,
            Event::Wall(w) => {
                records[w.ball].last_event = t;
                let (p, mut v) = at(&calendar, w.ball, t);
                v[w.axis] = match w.side {
                    Side::Low => v[w.axis].abs(),
                    Side::High => -v[w.axis].abs(),
                };
                let new = [Ball::from_checked(
                    p.into(),
                    v.into(),
                    records[w.ball].friction,
                )];
                calendar.update_balls(&[w.ball], t, &new)?;
                moved.push(w.ball);
                (w.ball, None, Some((w.axis, w.side)), None)
            }
        };
        let mut log = |events: &mut Vec<LoggedEvent>, i: usize, j: Option<usize>, wall, object| {
            events.push(LoggedEvent {
                time: t,
                i,
                j,
                wall,
                object,
            });
            at_this_instant += 1;
            check_progress(at_this_instant, most_at_one_instant, t, i, j)
        };
        log(&mut events, i, j, wall, object)?;
        // The follow-ups at this instant of every ball whose velocity changed.
        while let Some(x) = moved.pop() {
            for &[p, q] in &instant_pairs {
                let y = match x {
                    _ if p == x => q,
                    _ if q == x => p,
                    _ => continue,
                };
                if any_captured && (captured[x].is_some() || captured[y].is_some()) {
                    continue;
                }
                if events.len() >= max_events {
                    break 'events;
                }
                let pair = [x.min(y), x.max(y)];
                if collide_pair(e, &mut calendar, &mut records, pair, t, true)? {
                    log(&mut events, pair[0], Some(pair[1]), None, None)?;
                    moved.extend(pair);
                }
            }
        }
        let progress = Progress {
            events: events.len(),
            time: t,
        };
        if observe(progress).is_break() {
            stopped = true;
            break;
        }
    }
    let no_event_left = events.len() < max_events && !stopped;
    if no_event_left {
        end = if t_end.is_finite() {
            t_end
        } else {
            // At rest from the last stop on.
            (0..n)
                .map(|i| calendar.path(i).segments().last().map_or(0.0, |s| s.start))
                .fold(end, f64::max)
        };
    }
    let balls = (0..n)
        .map(|i| {
            let (p, v) = at(&calendar, i, end);
            Ball::from_checked(p.into(), v.into(), balls[i].friction())
        })
        .collect();
    Ok(Simulation {
        events,
        end,
        balls,
        captured,
        object_counts: calendar.object_counts(),
        stopped,
    })
}

/// What the event loop reads and writes of a ball besides its path, in one record aligned to
/// stay within one cache line: in a large scene each ball an event touches is a cache miss,
/// one here rather than one per array.
#[repr(C, align(32))]
struct BallRecord {
    friction: f64,
    radius: f64,
    mass: f64,
    /// The time of its last event (see `restitution_at`).
    last_event: f64,
}

/// The collision of balls `pair` at `t`: their new velocities (see [`collide`]) go into
/// the calendar. A `follow_up` collision is one of a pair that collided earlier at this
/// instant, after one of them has changed its velocity again (at a wall, or against a
/// third ball): it still touches, and it collides again only if it no longer parts as a
/// collision would make it (elastically, as every later event at one instant). Without
/// this, a pair left parting slower than its [`parting_speed`] while friction presses it
/// together (a ball against a cushion with a slower one behind it) sinks in unseen:
/// rounding may put its centres a hair within the contact distance, where the gap never
/// enters from outside. Whether the velocities changed.
fn collide_pair(
    restitution: f64,
    calendar: &mut CollisionSchedule<2>,
    records: &mut [BallRecord],
    [i, j]: [usize; 2],
    t: f64,
    follow_up: bool,
) -> Result<bool, InputError> {
    let (a, b) = (at(calendar, i, t), at(calendar, j, t));
    let frictions = [records[i].friction, records[j].friction];
    let masses = [records[i].mass, records[j].mass];
    // A pair moving as one body (the same friction, and velocities the same to within
    // rounding, `AS_ONE`) neither parts nor presses together but at rounding level. Its
    // follow-up leaves it so; reported (it approached at rounding level), it takes one
    // velocity, their momentum's, exactly the same for both, so that every derivative of
    // its gap is 0 and the calendar never reports it again until a later update makes it
    // approach (touching or overlapping balls that approach collide at once). Nudging it
    // apart at the least parting speed instead changed both velocities by far more than
    // their difference, and each change followed up the balls' other pairs of the instant:
    // along a touching train of k balls (a Newton's cradle) that ran to O(k³) events at
    // one instant.
    let as_one = frictions[0] == frictions[1] && {
        // In the velocities' power-of-two unit (no square overflowing or underflowing, the
        // same bits at every scale): one unit for the three norms.
        let unit = unit_of_largest(a.1.amax().max(b.1.amax()));
        let (va, vb) = (a.1.map(|x| unit.apply(x)), b.1.map(|x| unit.apply(x)));
        (va - vb).norm() <= AS_ONE * (va.norm() + vb.norm())
    };
    let (va, vb) = match (as_one, follow_up) {
        (true, true) => return Ok(false),
        (true, false) => {
            let v = one_velocity(a.1, b.1, masses);
            (v, v)
        }
        (false, _) => {
            let contact = records[i].radius + records[j].radius;
            let last = [records[i].last_event, records[j].last_event];
            let e = restitution_at(restitution, t, last);
            collide(a, b, masses, frictions, contact, e)
        }
    };
    let changed = (va, vb) != (a.1, b.1);
    if follow_up && !changed {
        return Ok(false);
    }
    (records[i].last_event, records[j].last_event) = (t, t);
    let new = [
        Ball::from_checked(a.0.into(), va.into(), frictions[0]),
        Ball::from_checked(b.0.into(), vb.into(), frictions[1]),
    ];
    calendar.update_balls(&[i, j], t, &new)?;
    Ok(changed)
}

/// The error for a run stuck at one instant: more than `most` events at `t`, the last
/// between ball `i` and ball `j` (`None`: a wall).
fn check_progress(
    events: usize,
    most: usize,
    t: f64,
    i: usize,
    j: Option<usize>,
) -> Result<(), InputError> {
    if events <= most {
        return Ok(());
    }
    let kind = InputErrorKind::NoProgress {
        other: j,
        time: t,
        events,
    };
    Err(InputError::new("pos", kind).at(i))
}

/// A velocity `v` after a contact with an object whose unit normal at the contact is `n`
/// (towards the ball): an approaching normal component reflected with restitution `e`, and
/// the normal speed made at least [`ROUNDING`] of the speed, so that the ball parts whatever
/// the rounding of its position (at `e = 0` it would slide along the object, touching it).
fn reflected(v: Vector2<f64>, n: Vector2<f64>, e: f64) -> Vector2<f64> {
    let normal = v.dot(&n);
    let target = (-e * normal).max(ROUNDING * norm_in_range(&v));
    if normal >= target {
        v
    } else {
        v + n * (target - normal)
    }
}

/// The one velocity of two balls moving as one body (see [`collide_pair`]): their momentum's,
/// `(m_a·v_a + m_b·v_b)/(m_a + m_b)`, from the mass ratio as in [`collide`] (no overflow for
/// any masses).
fn one_velocity(va: Vector2<f64>, vb: Vector2<f64>, masses: [f64; 2]) -> Vector2<f64> {
    // a's weight is b's share of a change, and b's a's.
    let [share_a, share_b] = shares(masses);
    va * share_b + vb * share_a
}

/// Each ball's share of a change of their relative velocity, `m_b/(m_a + m_b)` and
/// `m_a/(m_a + m_b)` (the impulse over each mass), from the mass ratio: in `[0, 1]` for any
/// masses from 5e-324 to `f64::MAX`, where `1/m` and `m_a + m_b` overflow; `½` exactly for
/// equal masses.
fn shares([ma, mb]: [f64; 2]) -> [f64; 2] {
    [1.0 / (1.0 + ma / mb), 1.0 / (1.0 + mb / ma)]
}

/// The restitution of a collision at `t` of two balls whose last events came at `last`:
/// `e`, or `1` if either ball has had an event at this very instant. Touching balls in a
/// chain or a cluster (a rack, a row against a wall) then settle at one instant in a few
/// events, as in Newton's cradle, instead of an inelastic collapse without end (restitution
/// 0 leaves three touching balls colliding at `t` over a thousand times before rounding ends
/// it): the TC model of Luding and McNamara (1998) with a contact duration of 0. A pair that
/// meets again later takes `e` again.
fn restitution_at(e: f64, t: f64, last: [f64; 2]) -> f64 {
    if last.contains(&t) { 1.0 } else { e }
}

/// Ball `i`'s centre and velocity at `t`, from its path.
fn at(calendar: &CollisionSchedule<2>, i: usize, t: f64) -> (Vector2<f64>, Vector2<f64>) {
    let path = calendar.path(i);
    (path.position_at(t), path.velocity_at(t))
}

/// The velocities after a collision of balls `a` and `b` (centre, velocity) of `masses`,
/// `frictions` and contact distance `contact`, with restitution `e`: they part along their
/// line of centres `n` at the normal speed `max(e·u, w)` (`u` the speed at which they
/// approached, `w` the [`parting_speed`]), or keep their velocities if they already part
/// faster than both. Each ball takes its share of the change by the other's mass fraction,
/// `m_j/(m_i + m_j) = 1/(1 + m_i/m_j)`, which neither overflows nor vanishes for masses
/// anywhere in the float range (`1/m` would overflow for `m` below `1/f64::MAX`).
///
/// Resolved in the pair's unit of length (a power of two, from the largest of the separation,
/// the velocities and the contact distance; the line of centres in the separation's own):
/// no square overflows or underflows, and a scene
/// scaled by a power of two collides to the same bits (contract §1); velocities kept are
/// returned as given.
fn collide(
    a: (Vector2<f64>, Vector2<f64>),
    b: (Vector2<f64>, Vector2<f64>),
    masses: [f64; 2],
    frictions: [f64; 2],
    contact: f64,
    e: f64,
) -> (Vector2<f64>, Vector2<f64>) {
    let d = a.0 - b.0;
    let unit = unit_of_largest(largest([d.amax(), a.1.amax(), b.1.amax(), contact]));
    let scaled = |v: Vector2<f64>| v.map(|x| unit.apply(x));
    let (va, vb) = (scaled(a.1), scaled(b.1));
    let frictions = frictions.map(|f| unit.friction(f));
    let (na, nb) = collide_in_unit(
        scaled(d),
        [va, vb],
        masses,
        frictions,
        unit.apply(contact),
        e,
    );
    let back = |new: Vector2<f64>, given: Vector2<f64>, original: Vector2<f64>| {
        if new == given {
            original
        } else {
            new.map(|x| unit.restore(x))
        }
    };
    (back(na, va, a.1), back(nb, vb, b.1))
}

/// [`collide`] in the pair's unit of length: `d` the separation, `[va, vb]` the velocities.
fn collide_in_unit(
    d: Vector2<f64>,
    [va, vb]: [Vector2<f64>; 2],
    masses: [f64; 2],
    frictions: [f64; 2],
    contact: f64,
    e: f64,
) -> (Vector2<f64>, Vector2<f64>) {
    // (In `d`'s own unit: the pair's unit may come from speeds far above the separation,
    // whose square would then underflow.)
    let distance = norm_in_range(&d);
    if !(distance > 0.0 && distance.is_finite()) {
        return (va, vb);
    }
    let n = d / distance;
    // The normal speed at which they part (negative: approach).
    let parting = (va - vb).dot(&n);
    let [share_a, share_b] = shares(masses);
    let part_at = |target: f64| {
        let change = target - parting;
        (va + n * (change * share_a), vb - n * (change * share_b))
    };
    // The frictions that press them together are those of their velocities after the
    // collision: from the restitution's first, then the least parting speed of those.
    let speeds = va.norm() + vb.norm();
    let rounding = ROUNDING * speeds;
    // Balls that already part faster keep their velocities, unless friction presses them
    // together and they part slower than its least speed. Within `SLACK` of the target is
    // enough, as for `least` below: a pair parted at `rounding` by an earlier event of the
    // instant forms its parting speed again from the new velocities up to a few ulps below
    // it, and moving it up to `rounding` once more changes a velocity by an ulp, so that its
    // follow-up (`collide_pair`) collides it again, without end (a frictionless gas at
    // restitution 0 stopped with "no progress" after 1,000 + 64·N such events at one
    // instant).
    let target = (e * -parting).max(rounding);
    let (after_a, after_b) = if parting >= target * (1.0 - SLACK) {
        (va, vb)
    } else {
        part_at(target)
    };
    // `w` no faster than the pair's own speeds: a friction far beyond the motion's scale
    // would make it any multiple of them (1e10 with a friction of 121 beside a box 5e-32 wide
    // and speeds of 1e-29), and the balls would outrun time's resolution. Balls that slow
    // stop within `|v|/μ` anyway, which ends the pressing too.
    // Within `SLACK` of it is enough: rounding puts the parting speed formed from the new
    // velocities up to `2⁻¹²` below `least` where `least` is just above `rounding`, and a
    // pair followed up again for that would never be done.
    let least = parting_speed(after_a, after_b, n, frictions, contact).min(speeds);
    if least * (1.0 - SLACK) > target.max(parting) {
        part_at(least)
    } else {
        (after_a, after_b)
    }
}

/// The least normal speed `w_min` at which two touching balls with velocities `va`, `vb`
/// (after the collision) part along `n`, so that the calendar sees them part rather than
/// touch again at the same instant or sink into each other unseen. [`collide`] makes it at
/// least `2⁻⁴⁰` of their speeds, far above the rounding of `Δv·n` (`2⁻⁵³`), so that the
/// gap's first derivative is positive whatever the rounding of the positions; here, for
/// balls pressed together (their frictions push them towards each other along `n` at the
/// relative deceleration `a`), it is `√(2⁻²⁰·R·a)`, `R` the contact distance. They then rise
/// apart by `w²/(2a) = 2⁻²¹·R` and touch again `2w/a` later at the speed `w`: a resting
/// contact becomes a bounce within a hair's breadth, and time moves on by `2w/a` each time
/// (restitution 0 would make the gap's first derivative vanish and leave the decision to
/// rounding).
///
/// When they approached slower than `w_min`, parting at `w_min` gives their normal motion a
/// little energy, at most `½·m·2⁻²⁰·R·a` for the reduced mass `m`: the work of the push over
/// `2⁻²¹·R`. [`collide`] caps it at the sum of the two balls' speeds before the collision.
fn parting_speed(
    va: Vector2<f64>,
    vb: Vector2<f64>,
    n: Vector2<f64>,
    frictions: [f64; 2],
    contact: f64,
) -> f64 {
    // Each ball's friction deceleration, against its velocity (none at rest).
    let deceleration = |v: Vector2<f64>, friction: f64| {
        let speed = v.norm();
        if speed > 0.0 && friction > 0.0 {
            v * (-friction / speed)
        } else {
            Vector2::zeros()
        }
    };
    let towards = -(deceleration(va, frictions[0]) - deceleration(vb, frictions[1])).dot(&n);
    if towards > 0.0 {
        (RESTING_RISE * contact * towards).sqrt()
    } else {
        0.0
    }
}

/// See [`collide`].
const SLACK: f64 = 1.0 / 256.0;
/// See [`parting_speed`].
const ROUNDING: f64 = 1.0 / (1u64 << 40) as f64;
/// A pair whose velocities differ by at most this part of their speeds moves as one body
/// ([`collide_pair`]): the rounding of an exchange along a line of centres off the axes (a
/// few ulps), far below the least parting speed ([`ROUNDING`]) a collision gives.
const AS_ONE: f64 = 1.0 / (1u64 << 46) as f64;
/// See [`parting_speed`]: twice the rise of a resting contact's bounces, relative to the
/// contact distance.
const RESTING_RISE: f64 = 1.0 / (1u64 << 20) as f64;

/// The start of a simulation: no ball overlaps another or a wall, or lies outside the box,
/// beyond [`START_TOLERANCE`] of the radii (touching is fine), and none is as wide as the box.
fn check_start(balls: &[Ball], radii: &[f64], walls: &Walls<2>) -> Result<(), InputError> {
    let (lo, hi) = (walls.lo(), walls.hi());
    let keep = 1.0 - START_TOLERANCE;
    for (i, (ball, &r)) in balls.iter().zip(radii).enumerate() {
        let p = ball.position();
        if let Some(kind) = walls.wider_than(r, keep) {
            return Err(InputError::new("radius", kind).at(i));
        }
        for axis in 0..2 {
            let room = (p[axis] - lo[axis]).min(hi[axis] - p[axis]);
            if room < r * keep {
                return Err(InputError::new("pos", InputErrorKind::OutsideBox { axis }).at(i));
            }
        }
    }
    let worst = first_overlap(balls, radii, [lo, hi], keep);
    match worst {
        Some((a, b, distance, contact)) => {
            let kind = InputErrorKind::Overlap {
                other: a,
                distance,
                contact,
            };
            Err(InputError::new("pos", kind).at(b))
        }
        None => Ok(()),
    }
}

/// The overlapping pair `(a, b, distance, contact)` of balls inside the box `[lo, hi]`
/// (centres at least `keep·r` from its walls) with the lowest `a`, then `b` (`a < b`):
/// `distance < keep·contact`. Up to [`FEW_BALLS`] balls, by every pair; beyond, through a
/// grid of cells of about two median diameters, each listing the balls whose bounding squares
/// meet it (two balls that overlap have bounding squares that meet, so share a cell): O(N)
/// for balls that do not overlap, where a sweep along one axis meets a whole column of a
/// ball grid per ball (O(N^1.5): 28 % of a 10⁶-ball `simulate` of 200,000 events).
fn first_overlap(
    balls: &[Ball],
    radii: &[f64],
    walls: [[f64; 2]; 2],
    keep: f64,
) -> Option<(usize, usize, f64, f64)> {
    if balls.len() <= FEW_BALLS {
        first_overlap_of_few(balls, radii, keep)
    } else {
        first_overlap_in_grid(balls, radii, walls, keep)
    }
}

/// Up to this many balls, [`first_overlap`] tries every pair in order: cheaper than a grid's
/// allocations (16 balls: a fifth of a short run's fixed cost).
const FEW_BALLS: usize = 32;

/// [`first_overlap`] by every pair in order, the first found the lowest.
fn first_overlap_of_few(
    balls: &[Ball],
    radii: &[f64],
    keep: f64,
) -> Option<(usize, usize, f64, f64)> {
    (0..balls.len())
        .flat_map(|a| (a + 1..balls.len()).map(move |b| (a, b)))
        .find_map(|(a, b)| overlap(balls, radii, keep, a, b))
}

/// `(a, b, distance, contact)` if balls `a` and `b` overlap (`distance < keep·contact`). A
/// pair apart by a contact distance on an axis is settled without its distance, which is at
/// least that (`keep < 1` covers the distance's rounding).
fn overlap(
    balls: &[Ball],
    radii: &[f64],
    keep: f64,
    a: usize,
    b: usize,
) -> Option<(usize, usize, f64, f64)> {
    let contact = radii[a] + radii[b];
    let d = balls[a].position() - balls[b].position();
    if d.amax() >= contact {
        return None;
    }
    let distance = norm_in_range(&d);
    (distance < contact * keep).then_some((a, b, distance, contact))
}

/// [`first_overlap`] through a grid (see there).
fn first_overlap_in_grid(
    balls: &[Ball],
    radii: &[f64],
    [lo, hi]: [[f64; 2]; 2],
    keep: f64,
) -> Option<(usize, usize, f64, f64)> {
    let n = balls.len();
    if n < 2 {
        return None;
    }
    // Cells of two median diameters, coarser if there would be more than about one per
    // ball: a typical ball's square meets one to four of them, and each cell holds a few
    // balls (finer cells, four per ball, made the grid's arrays some 80 bytes per ball of
    // fresh memory, whose pages cost more to map than the pairs they saved: measured by
    // samples at 10⁶ balls, the check 0.113 s against 0.135).
    let mut sorted = radii.to_vec();
    let median = *sorted.select_nth_unstable_by(n / 2, f64::total_cmp).1;
    let mut size = 4.0 * median;
    let most = n + 16;
    let counts = loop {
        let along = |k: usize| -> usize {
            let cells = ((hi[k] - lo[k]) / size).ceil();
            // (A box under a cell, or a quotient past the range: one cell, or the most.)
            if cells.is_finite() && cells >= 1.0 {
                (cells as usize).min(most)
            } else if cells >= 1.0 {
                most
            } else {
                1
            }
        };
        let counts = [along(0), along(1)];
        if counts[0].saturating_mul(counts[1]) <= most {
            break counts;
        }
        size *= 2.0;
    };
    let inverse = 1.0 / size;
    let cell = |k: usize, x: f64| -> usize {
        // Clamped below, then truncated (the floor, without a call to `floor` in a build
        // without SSE4.1), then above (`as` saturates, NaN to 0): order kept, so squares
        // that meet share a cell.
        (((x - lo[k]) * inverse).max(0.0) as usize).min(counts[k] - 1)
    };
    // The cells ball `i`'s bounding square meets.
    let cells_of = |i: usize| {
        let (p, r) = (balls[i].position(), radii[i]);
        let [[x0, x1], [y0, y1]] = [0, 1].map(|k| [cell(k, p[k] - r), cell(k, p[k] + r)]);
        (y0..=y1).flat_map(move |y| (x0..=x1).map(move |x| y * counts[0] + x))
    };
    // The cells' lists in one array, cell `c`'s at `starts[c]..starts[c + 1]`, each in ball
    // order: counted, then filled.
    let mut starts = vec![0usize; counts[0] * counts[1] + 1];
    for i in 0..n {
        for c in cells_of(i) {
            starts[c + 1] += 1;
        }
    }
    for c in 1..starts.len() {
        starts[c] += starts[c - 1];
    }
    let mut listed = vec![0u32; starts[starts.len() - 1]];
    let mut next = starts.clone();
    for i in 0..n {
        for c in cells_of(i) {
            listed[next[c]] = i as u32;
            next[c] += 1;
        }
    }
    drop(next);
    let mut worst: Option<(usize, usize, f64, f64)> = None;
    for cell in starts.windows(2) {
        let balls_here = &listed[cell[0]..cell[1]];
        for (m, &a) in balls_here.iter().enumerate() {
            let a = a as usize;
            for &b in &balls_here[m + 1..] {
                // In ball order within a cell: a < b.
                let b = b as usize;
                if worst.is_some_and(|w| (a, b) >= (w.0, w.1)) {
                    continue;
                }
                if let Some(found) = overlap(balls, radii, keep, a, b) {
                    worst = Some(found);
                }
            }
        }
    }
    worst
}

/// The start of a simulation on a table: no ball overlaps a segment, a circle or a plane, or
/// lies in a target, beyond [`START_TOLERANCE`] of its radius (touching is fine).
fn check_start_on_table(balls: &[Ball], radii: &[f64], table: &Table<2>) -> Result<(), InputError> {
    for (i, (ball, &r)) in balls.iter().zip(radii).enumerate() {
        let p = ball.position();
        for kind in ObjectKind::ALL {
            for index in 0..table.count(kind) {
                let (distance, least) = match table.distance_to(kind, index, p) {
                    Some(d) if kind == ObjectKind::Target => (d, table.targets[index].rho()),
                    Some(d) => (d, r * (1.0 - START_TOLERANCE)),
                    None => continue,
                };
                if distance < least {
                    let kind = InputErrorKind::OverlapsObject {
                        kind,
                        index,
                        distance,
                    };
                    return Err(InputError::new("pos", kind).at(i));
                }
            }
        }
    }
    Ok(())
}

/// How deep an overlap at the start may be, relative to the radii: rounding in the caller's
/// placement (a rack of touching balls), not a real overlap.
const START_TOLERANCE: f64 = 1.0 / (1u64 << 30) as f64;

/// The masses: one for all, or one per ball; each finite and `> 0`.
fn masses(mass: &[f64], n: usize) -> Result<PerBall<'_>, InputError> {
    if mass.len() != 1 && mass.len() != n {
        let kind = InputErrorKind::LengthMismatch {
            expected: n,
            found: mass.len(),
        };
        return Err(InputError::new("mass", kind));
    }
    for (i, &m) in mass.iter().enumerate() {
        finite("mass", m).map_err(|e| e.at(i))?;
        if m <= 0.0 {
            return Err(InputError::new("mass", InputErrorKind::NonPositiveMass(m)).at(i));
        }
    }
    Ok(PerBall(mass))
}

/// One value for all balls, or one per ball.
struct PerBall<'a>(&'a [f64]);

impl PerBall<'_> {
    fn get(&self, i: usize) -> f64 {
        if self.0.len() == 1 {
            self.0[0]
        } else {
            self.0[i]
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_rng::Rng;
    use nalgebra::Vector2;

    /// Every pair, in order: the lowest overlapping `(a, b)`.
    fn all_pairs(balls: &[Ball], radii: &[f64], keep: f64) -> Option<(usize, usize, f64, f64)> {
        for a in 0..balls.len() {
            for b in a + 1..balls.len() {
                let contact = radii[a] + radii[b];
                let distance = (balls[a].position() - balls[b].position()).norm();
                if distance < contact * keep {
                    return Some((a, b, distance, contact));
                }
            }
        }
        None
    }

    #[test]
    fn pair_searches_stopped_at_the_walls_give_the_same_run_to_the_bit() {
        // Friction balls roll far beyond the walls; the searches that stop at each ball's
        // next wall contact must change no event. Dense and dilute, weak and strong friction,
        // unequal radii and masses, a grid of one cell and of many.
        let mut rng = Rng(23);
        let mut events = 0;
        for round in 0..60 {
            let n = 2 + (rng.uniform(0.0, 120.0) as usize);
            let side = (n as f64).sqrt().ceil();
            let friction = [0.0, 0.01, 0.5, 5.0][round % 4];
            let balls: Vec<Ball> = (0..n)
                .map(|k| {
                    let p = Vector2::new(
                        (k as f64 % side + 0.5) / side,
                        ((k as f64 / side).floor() + 0.5) / side,
                    );
                    let v = Vector2::new(rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0));
                    Ball::new(p, v, friction * rng.uniform(0.5, 1.5)).expect("valid")
                })
                .collect();
            let radii: Vec<f64> = (0..n).map(|_| rng.uniform(0.05, 0.4) / side).collect();
            let mass: Vec<f64> = (0..n).map(|_| rng.uniform(0.5, 2.0)).collect();
            let walls = Walls::new([0.0, 0.0], [1.0, 1.0]).expect("valid");
            let options = SimulationOptions {
                max_events: Some(40 * n),
                t_end: 50.0,
                mass,
                restitution: [1.0, 0.9][round % 2],
                ..Default::default()
            };
            let run = |resolved| {
                simulate_in(
                    &balls,
                    &radii,
                    walls,
                    &options,
                    |_| ControlFlow::Continue(()),
                    resolved,
                )
                .expect("a valid scene")
            };
            let (stopped, whole) = (run(true), run(false));
            assert_eq!(stopped.events.len(), whole.events.len(), "round {round}");
            for (x, y) in stopped.events.iter().zip(&whole.events) {
                assert_eq!(
                    (x.time.to_bits(), x.i, x.j, x.wall),
                    (y.time.to_bits(), y.i, y.j, y.wall),
                    "round {round}"
                );
            }
            for (x, y) in stopped.balls.iter().zip(&whole.balls) {
                assert_eq!(x.position(), y.position(), "round {round}");
                assert_eq!(x.velocity(), y.velocity(), "round {round}");
            }
            events += whole.events.len();
        }
        assert!(events > 20_000, "only {events} events");
    }

    #[test]
    fn a_collision_at_a_wall_contact_s_time_is_found_with_the_searches_stopped_there() {
        // Ball A reaches the wall x = 2 at t = 1.4 as ball B, coming up from below, meets it
        // there: offsets of a few ulps put the collision just before, at or just after the
        // wall contact, with A as ball 0 or 1, with and without friction.
        let walls = Walls::new([0.0, 0.0], [2.0, 2.0]).expect("valid");
        let mut runs = 0;
        for k in -8..=8 {
            for mu in [0.0, 1e-3] {
                for a_first in [true, false] {
                    let y = 0.16 + f64::from(k) * f64::EPSILON * 0.16;
                    let a = Ball::new(Vector2::new(0.5, 0.5), Vector2::new(1.0, 0.0), mu);
                    let b = Ball::new(Vector2::new(1.9, y), Vector2::new(0.0, 0.1), mu);
                    let (a, b) = (a.expect("valid"), b.expect("valid"));
                    let balls = if a_first { [a, b] } else { [b, a] };
                    let options = SimulationOptions {
                        max_events: Some(20),
                        t_end: 5.0,
                        ..Default::default()
                    };
                    let run = |resolved| {
                        let observe = |_| ControlFlow::Continue(());
                        simulate_in(&balls, &[0.1, 0.1], walls, &options, observe, resolved)
                            .expect("a valid scene")
                    };
                    let (stopped, whole) = (run(true), run(false));
                    let log = |s: &Simulation| {
                        s.events
                            .iter()
                            .map(|e| (e.time.to_bits(), e.i, e.j, e.wall))
                            .collect::<Vec<_>>()
                    };
                    assert_eq!(log(&stopped), log(&whole), "k = {k}, mu = {mu}");
                    assert!(whole.events.iter().any(|e| e.j.is_some()), "k = {k}");
                    runs += 1;
                }
            }
        }
        assert_eq!(runs, 68);
    }

    #[test]
    fn the_grid_finds_the_pair_every_pair_finds() {
        let mut rng = Rng(5);
        let keep = 1.0 - START_TOLERANCE;
        let (lo, hi) = ([0.0, 0.0], [10.0, 4.0]);
        for round in 0..300 {
            let n = 1 + (rng.uniform(0.0, 60.0) as usize);
            // Some scenes on a grid (columns and rows of equal x and y), touching or not;
            // radii equal, spread, or one huge ball among small ones.
            let on_grid = round % 3 == 0;
            let radii: Vec<f64> = (0..n)
                .map(|i| match round % 4 {
                    0 => 0.1,
                    1 => rng.uniform(0.01, 0.5),
                    2 if i == n / 2 => 1.5,
                    _ => rng.uniform(0.01, 0.05),
                })
                .collect();
            let balls: Vec<Ball> = (0..n)
                .map(|i| {
                    let r = radii[i];
                    let p = if on_grid {
                        let spacing = rng.uniform(0.15, 0.3);
                        Vector2::new(
                            (0.5 + (i % 8) as f64 * spacing).clamp(r, hi[0] - r),
                            (0.5 + (i / 8) as f64 * spacing).clamp(r, hi[1] - r),
                        )
                    } else {
                        Vector2::new(rng.uniform(r, hi[0] - r), rng.uniform(r, hi[1] - r))
                    };
                    Ball::at_rest(p).expect("finite")
                })
                .collect();
            let every = all_pairs(&balls, &radii, keep);
            assert_eq!(
                first_overlap_in_grid(&balls, &radii, [lo, hi], keep),
                every,
                "round {round}"
            );
            assert_eq!(
                first_overlap_of_few(&balls, &radii, keep),
                every,
                "round {round}"
            );
        }
    }
}
