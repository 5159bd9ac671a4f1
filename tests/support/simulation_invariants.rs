//! The invariants of `simulate`, checked by the fuzz target `simulate` (`fuzz/`) and by the
//! property tests (`tests/integration/simulation_progress.rs`): one implementation for both.
//!
//! - a valid start either runs or is refused as a start no motion comes from (a ball
//!   overlapping another or a wall, outside the box, as wide as the box), and then the named
//!   ball really is so; nothing else is an error (never "no progress");
//! - the run ends (within its `max_events`), its events in time order, within `[0, t_end]`;
//! - no two balls overlap, and no ball overlaps a wall, beyond `1e-9` of their contact
//!   distance (or radius), at the end nor at the end of the same run cut at earlier times
//!   (a horizon only cuts: those are states of one trajectory): fractions of `t_end`, some
//!   events' times and halfway to the next event (`cut_times`);
//! - a run cut at any of those times logs exactly the events of the whole run before it;
//! - the case with every length scaled by `2^±300` (toward the middle of the float range)
//!   runs to the same bits: the same events, each ball's final centre and velocity scaled
//!   (contract §1).
//!
//! On a table ([`TableCase`], [`table_simulation`]; the fuzz target `simulate_table`) also:
//! no ball in play overlaps a circle, a plane or a two-sided segment's flat part beyond
//! `1e-9` of its radius; a captured ball takes part in no later event and never moves again
//! (at rest where it entered, in every later cut); the kinetic energy never grows beyond what
//! [`simulate`]'s least parting speeds may add (restitutions are at most 1).
//!
//! The last three hold where `docs/contract.md` (§5) promises answers: every non-zero
//! magnitude of the case (the box's width, radii, velocities, frictions) within `2^±400` of
//! the box's width, and time able to resolve the motion ([`within_promise`]). Beyond, a run must still end or be refused, with its
//! events in order, and never panic.

#![allow(dead_code)]

use ballcollide::geometry::{ObjectKind, SegmentSide, Table};
use ballcollide::schedule::{LoggedEvent, Simulation, SimulationOptions, Walls, simulate};
use ballcollide::{Ball, InputError, InputErrorKind};
use nalgebra::Vector2;

/// A simulation's input: balls `(x, y, vx, vy, friction)`, radii, the box, masses (one, or
/// one per ball), restitution and end time.
#[derive(Clone, Debug)]
pub struct SimulationCase {
    pub balls: Vec<[f64; 5]>,
    pub radii: Vec<f64>,
    pub lo: [f64; 2],
    pub hi: [f64; 2],
    pub mass: Vec<f64>,
    pub restitution: f64,
    pub t_end: f64,
}

impl SimulationCase {
    /// Balls in the square `[0, side]²`, each `(at, radius, velocity, friction)` with `at` in
    /// `[0, 1]²` placing its centre where a ball of that radius fits (touching the walls at 0
    /// and 1).
    pub fn in_square(
        side: f64,
        balls: &[([f64; 2], f64, [f64; 2], f64)],
        mass: Vec<f64>,
        restitution: f64,
        t_end: f64,
    ) -> Self {
        let place = |u: f64, r: f64| r + (side - 2.0 * r) * u;
        Self {
            balls: balls
                .iter()
                .map(|&(at, r, v, f)| [place(at[0], r), place(at[1], r), v[0], v[1], f])
                .collect(),
            radii: balls.iter().map(|b| b.1).collect(),
            lo: [0.0; 2],
            hi: [side; 2],
            mass,
            restitution,
            t_end,
        }
    }
}

impl SimulationCase {
    /// The case without the balls on an object of `table` (or touching one, within `1e-6` of
    /// the radius) or with their centre in a target: the starts `simulate` refuses.
    pub fn clear_of(mut self, table: &Table<2>) -> Self {
        let keep: Vec<bool> = self
            .balls
            .iter()
            .zip(&self.radii)
            .map(|(b, &r)| {
                let (depth, _, inside) = object_overlap(table, Vector2::new(b[0], b[1]), r, true);
                inside.is_none() && depth < -1e-6
            })
            .collect();
        fn kept<T: Copy>(v: &[T], keep: &[bool]) -> Vec<T> {
            v.iter()
                .zip(keep)
                .filter(|(_, k)| **k)
                .map(|(x, _)| *x)
                .collect()
        }
        self.radii = kept(&self.radii, &keep);
        if self.mass.len() > 1 {
            self.mass = kept(&self.mass, &keep);
        }
        self.balls = kept(&self.balls, &keep);
        self
    }
}

/// The most events a checked run may take: each case runs four times, and a pair query may
/// take 250 µs where a window is 2²³⁴ times the motion's time scale (a ball at 5e118 with
/// friction 1409 in a box 2 wide, within the pair search's range), and 1.2 ms beyond that
/// range (its long-window stage halves pieces 4,096 times), so that a fuzz input stays
/// within libFuzzer's 10 s timeout under its instrumentation.
pub const MAX_EVENTS: usize = 1_000;

/// How deep an overlap may be at any state, relative to the contact distance.
pub const OVERLAP: f64 = 1e-9;

/// Whether `simulate`'s refusal `e` of `case`'s start stands (`shown`: the case, in the
/// message): a ball it names as overlapping another must be so (loosely: beyond half the
/// tolerance the start check uses); the refusals of a bad box or bad numbers (the decoder
/// may make a radius ≤ 0, a mass ≤ 0, restitution outside [0, 1], no end) stand; any other
/// refusal of a case within the promise (`strict`) is a failure.
fn refused_start(
    e: &InputError,
    case: &SimulationCase,
    balls: &[Ball],
    strict: bool,
    shown: &dyn std::fmt::Debug,
) -> Result<(), String> {
    match e.kind() {
        InputErrorKind::Overlap { other, .. } => {
            let i = e.index().ok_or("an overlap without an index")?;
            let contact = case.radii[i] + case.radii[other];
            let d = (balls[i].position() - balls[other].position()).norm();
            if d < contact {
                Ok(())
            } else {
                Err(format!(
                    "{e}, but they are {d:e} apart ({contact:e}): {shown:?}"
                ))
            }
        }
        InputErrorKind::OutsideBox { .. }
        | InputErrorKind::WiderThanBox { .. }
        | InputErrorKind::NotFinite(_)
        | InputErrorKind::PathOverflow { .. }
        | InputErrorKind::NonPositiveRadius(_)
        | InputErrorKind::NonPositiveMass(_)
        | InputErrorKind::NotInUnitInterval(_)
        | InputErrorKind::InvalidHorizon(_)
        | InputErrorKind::LengthMismatch { .. }
        | InputErrorKind::Endless => Ok(()),
        _ if !strict => Ok(()),
        _ => Err(format!("a valid start failed: {e}: {shown:?}")),
    }
}

fn run(
    case: &SimulationCase,
    balls: &[Ball],
    walls: Walls<2>,
    t_end: f64,
) -> Result<Simulation, String> {
    let options = SimulationOptions {
        mass: case.mass.clone(),
        restitution: case.restitution,
        t_end,
        max_events: Some(MAX_EVENTS),
        ..Default::default()
    };
    simulate(balls, &case.radii, walls, &options).map_err(|e| format!("{e}"))
}

/// The times to cut a run at (`events`: the whole run's log, to `t_end`), where no overlap
/// may be deeper than [`OVERLAP`] and the log before the cut must be the whole run's: a half,
/// a quarter and three quarters of `t_end`; then up to eight events' times (of the distinct
/// ones, evenly spread), where balls touch, each with the time halfway to the next event,
/// where a pair that passed into each other with no event would be found, as many as keep
/// the events the cut runs replay (counted from the log) within four times `most`, the
/// events a run may take.
fn cut_times(events: &[LoggedEvent], t_end: f64, most: usize) -> Vec<f64> {
    let mut times = vec![t_end * 0.5, t_end * 0.25, t_end * 0.75];
    let mut distinct: Vec<f64> = events.iter().map(|e| e.time).collect();
    distinct.dedup();
    let replayed = |t: f64| events.partition_point(|e| e.time <= t);
    let mut cost: usize = times.iter().map(|&t| replayed(t)).sum();
    let picks = distinct.len().min(8);
    for m in 0..picks {
        let at = m * distinct.len() / picks;
        let t = distinct[at];
        let next = distinct.get(at + 1).copied().unwrap_or(t_end);
        let pair = [t, t + (next - t) / 2.0];
        cost += pair.iter().map(|&t| replayed(t)).sum::<usize>();
        if cost > 4 * most {
            break;
        }
        times.extend(pair);
    }
    times
}

/// The deepest overlap in a state, relative (two balls: their contact distance; a ball and a
/// wall: its radius), and where.
fn deepest_overlap(state: &[Ball], radii: &[f64], walls: &Walls<2>) -> (f64, String) {
    let mut deepest = (0.0f64, String::new());
    for (i, a) in state.iter().enumerate() {
        for (j, b) in state.iter().enumerate().skip(i + 1) {
            let contact = radii[i] + radii[j];
            let depth = (contact - (a.position() - b.position()).norm()) / contact;
            if depth > deepest.0 {
                deepest = (depth, format!("balls {i} and {j}"));
            }
        }
        for axis in 0..2 {
            let p = a.position()[axis];
            let room = (p - walls.lo()[axis]).min(walls.hi()[axis] - p);
            let depth = (radii[i] - room) / radii[i];
            if depth > deepest.0 {
                deepest = (depth, format!("ball {i} and a wall on axis {axis}"));
            }
        }
    }
    deepest
}

/// Whether `case` is within the range the contract promises answers for: every non-zero
/// radius, velocity component and friction within `2^±400` of the box's width on each axis,
/// and time resolving the motion: twice the fastest ball (no collision makes a pair faster
/// than the sum of its speeds) crosses the narrower width, and friction stops it, in at least
/// `2⁻⁴⁰·t_end`, 2¹² ulps of `t_end`. (A ball at 1e82 in a box 2 wide meets a wall every
/// 1e-82 time units, which no time near 1e-32 resolves: such a run stops with "no
/// progress".)
pub fn within_promise(case: &SimulationCase) -> bool {
    let range = 2f64.powi(400);
    let widths = [case.hi[0] - case.lo[0], case.hi[1] - case.lo[1]];
    let fastest = case
        .balls
        .iter()
        .map(|b| b[2].hypot(b[3]))
        .fold(0.0, f64::max);
    let crossing = widths[0].min(widths[1]) / (2.0 * fastest);
    if crossing < case.t_end * 2f64.powi(-40) {
        return false;
    }
    // Friction acts over times that time resolves: the roughest friction stops a ball as fast
    // as the fastest (whose speed a collision may hand to it) in at least `2⁻³⁹·t_end`. Else
    // a ball stops within one ulp of time, and a pair that friction presses together meets
    // again at the same instant for ever (found by the fuzz target `simulate_table`: a
    // friction of 82 on speeds of 1e-23 in a box 2.6e-23 wide). A slower ball handed less
    // speed stops sooner still: this bound is the scale of the case, not a proof.
    let roughest = case.balls.iter().map(|b| b[4]).fold(0.0, f64::max);
    if fastest > 0.0 && fastest < 2.0 * roughest * case.t_end * 2f64.powi(-40) {
        return false;
    }
    let magnitudes = case
        .balls
        .iter()
        .flat_map(|b| [b[2], b[3], b[4]])
        .chain(case.radii.iter().copied())
        .map(f64::abs)
        .filter(|&m| m != 0.0);
    magnitudes
        .flat_map(|m| widths.map(|w| m / w))
        .all(|ratio| ratio <= range && ratio >= 1.0 / range)
}

/// The case's balls and box, or `None` when either is not a valid input.
pub fn balls_and_walls(case: &SimulationCase) -> Option<(Vec<Ball>, Walls<2>)> {
    let balls = case
        .balls
        .iter()
        .map(|b| Ball::new(Vector2::new(b[0], b[1]), Vector2::new(b[2], b[3]), b[4]))
        .collect::<Result<Vec<_>, _>>()
        .ok()?;
    Some((balls, Walls::new(case.lo, case.hi).ok()?))
}

/// Checks every invariant of the module documentation on `case`; `Ok` also when the case is
/// not a valid input at all (a bad number, a bad box).
pub fn simulation(case: &SimulationCase) -> Result<(), String> {
    let strict = within_promise(case);
    let Some((balls, walls)) = balls_and_walls(case) else {
        return Ok(());
    };
    let options = SimulationOptions {
        mass: case.mass.clone(),
        restitution: case.restitution,
        t_end: case.t_end,
        max_events: Some(MAX_EVENTS),
        ..Default::default()
    };
    let full = match simulate(&balls, &case.radii, walls, &options) {
        Ok(run) => run,
        Err(e) => return refused_start(&e, case, &balls, strict, case),
    };
    if full.events.len() > MAX_EVENTS {
        return Err(format!("{} events: {case:?}", full.events.len()));
    }
    let mut previous = 0.0;
    for e in &full.events {
        if !(e.time >= previous && e.time <= case.t_end) {
            return Err(format!("event at {} after {previous}: {case:?}", e.time));
        }
        previous = e.time;
    }
    if !strict {
        return Ok(());
    }
    let (depth, where_) = deepest_overlap(&full.balls, &case.radii, &walls);
    if depth > OVERLAP {
        return Err(format!(
            "{where_} overlap by {depth:e} at the end {}: {case:?}",
            full.end
        ));
    }
    if full.events.len() < MAX_EVENTS && case.t_end.is_finite() {
        for t in cut_times(&full.events, case.t_end, MAX_EVENTS) {
            let part = run(case, &balls, walls, t)?;
            let (depth, where_) = deepest_overlap(&part.balls, &case.radii, &walls);
            if depth > OVERLAP {
                return Err(format!("{where_} overlap by {depth:e} at {t}: {case:?}"));
            }
            let before: Vec<_> = full.events.iter().filter(|e| e.time < t).copied().collect();
            let logged: Vec<_> = part.events.iter().filter(|e| e.time < t).copied().collect();
            if before != logged {
                return Err(format!("the run cut at {t} logs other events: {case:?}"));
            }
        }
    }
    same_run_scaled(case, &full, &options)
}

/// The case with every length scaled by `2^k`, `k = ±300` toward the middle of the float
/// range (none if the scaled lengths would leave `2^±900`, where a run's small velocities
/// could turn subnormal): the run of `full` to the bit, each length scaled.
fn same_run_scaled(
    case: &SimulationCase,
    full: &Simulation,
    options: &SimulationOptions,
) -> Result<(), String> {
    let lengths = case
        .balls
        .iter()
        .flatten()
        .chain(&case.radii)
        .chain(&case.lo)
        .chain(&case.hi)
        .map(|x| x.abs())
        .filter(|&x| x > 0.0);
    let (least, most) = lengths.fold((f64::INFINITY, 0.0f64), |(l, m), x| (l.min(x), m.max(x)));
    let k = if most < 2f64.powi(600) { 300 } else { -300 };
    let s = 2f64.powi(k);
    if !(least * s >= 2f64.powi(-900) && most * s <= 2f64.powi(900)) {
        return Ok(());
    }
    let scaled = SimulationCase {
        balls: case.balls.iter().map(|b| b.map(|x| x * s)).collect(),
        radii: case.radii.iter().map(|r| r * s).collect(),
        lo: case.lo.map(|x| x * s),
        hi: case.hi.map(|x| x * s),
        ..case.clone()
    };
    let Some((balls, walls)) = balls_and_walls(&scaled) else {
        return Err(format!("scaled by 2^{k}, not a valid input: {case:?}"));
    };
    let run = simulate(&balls, &scaled.radii, walls, options)
        .map_err(|e| format!("scaled by 2^{k}: {e}: {case:?}"))?;
    let scaled_balls = full
        .balls
        .iter()
        .map(|b| (b.position() * s, b.velocity() * s));
    let same_balls = run
        .balls
        .iter()
        .map(|b| (b.position(), b.velocity()))
        .eq(scaled_balls);
    if run.events != full.events || !same_balls {
        return Err(format!("scaled by 2^{k}, another run: {case:?}"));
    }
    Ok(())
}

/// A simulation on a table: [`SimulationCase`]'s balls and box, the table's objects and their
/// restitution. (A segment's ends are touched only through circles: a ball entering a
/// segment's band beyond an end touches nothing, docs/contract.md §4.7; the decoder caps each
/// segment with circles of radius 0 at its ends, as a table's jaws are.)
#[derive(Clone, Debug)]
pub struct TableCase {
    pub case: SimulationCase,
    pub table: Table<2>,
    pub table_restitution: f64,
}

/// How deep a ball of radius `r` at `x` overlaps the table's circles, planes and two-sided
/// segments (the flat part: the foot on it), relative to `r` (negative: clear), and which;
/// and whether its centre lies in a target. A one-sided segment counts only `at_start`, on
/// its side (as `simulate` checks a start): a run may pass one from behind, by design, and
/// end within its band.
pub fn object_overlap(
    table: &Table<2>,
    x: Vector2<f64>,
    r: f64,
    at_start: bool,
) -> (f64, String, Option<usize>) {
    let mut worst = (f64::NEG_INFINITY, String::new());
    let mut see = |depth: f64, what: String| {
        if depth > worst.0 {
            worst = (depth, what);
        }
    };
    for (k, s) in table.segments.iter().enumerate() {
        if s.side() != SegmentSide::Both && !at_start {
            continue;
        }
        let (e, w) = (s.q() - s.p(), x - s.p());
        let u = w.dot(&e) / e.norm_squared();
        let d = (e.x * w.y - e.y * w.x) / e.norm();
        let counts = match s.side() {
            SegmentSide::Both => true,
            SegmentSide::Left => d >= 0.0,
            SegmentSide::Right => d <= 0.0,
        };
        if (0.0..=1.0).contains(&u) && counts {
            see((r - d.abs()) / r, format!("segment {k}"));
        }
    }
    for (k, c) in table.circles.iter().enumerate() {
        see(
            (r + c.rho() - (x - c.centre()).norm()) / r,
            format!("circle {k}"),
        );
    }
    for (k, p) in table.planes.iter().enumerate() {
        let h = p.normal().dot(&(x - p.point())) / p.normal().norm();
        see((r - h) / r, format!("plane {k}"));
    }
    let inside = table
        .targets
        .iter()
        .position(|t| (x - t.centre()).norm() < t.rho());
    (worst.0, worst.1, inside)
}

fn table_run(
    tc: &TableCase,
    balls: &[Ball],
    walls: Walls<2>,
    t_end: f64,
) -> Result<Simulation, String> {
    let case = &tc.case;
    let options = SimulationOptions {
        mass: case.mass.clone(),
        restitution: case.restitution,
        t_end,
        max_events: Some(table_events(case)),
        table: tc.table.clone(),
        table_restitution: tc.table_restitution,
    };
    simulate(balls, &case.radii, walls, &options).map_err(|e| format!("{e}"))
}

/// The kinetic energy `Σ (mᵢ/M)·|vᵢ/V|²` of a state, in units of the largest mass `M` and a
/// speed `V` (so that it neither overflows nor underflows for the cases' magnitudes).
fn energy(balls: &[Ball], mass: &[f64], speed: f64) -> f64 {
    let largest = mass.iter().copied().fold(0.0, f64::max);
    balls
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let m = if mass.len() == 1 {
                1.0
            } else {
                mass[i] / largest
            };
            m * (b.velocity() / speed).norm_squared()
        })
        .sum()
}

/// The deepest overlap of the balls in play of a state: with each other, the walls and the
/// table's objects, relative (the contact distance, the radius), and where.
fn deepest_on_table(
    state: &[Ball],
    captured: &[Option<usize>],
    radii: &[f64],
    walls: &Walls<2>,
    table: &Table<2>,
) -> (f64, String) {
    let mut deepest = (0.0f64, String::new());
    let in_play = |i: &usize| captured[*i].is_none();
    for i in (0..state.len()).filter(in_play) {
        let a = state[i].position();
        for j in (i + 1..state.len()).filter(in_play) {
            let contact = radii[i] + radii[j];
            let depth = (contact - (a - state[j].position()).norm()) / contact;
            if depth > deepest.0 {
                deepest = (depth, format!("balls {i} and {j}"));
            }
        }
        for axis in 0..2 {
            let room = (a[axis] - walls.lo()[axis]).min(walls.hi()[axis] - a[axis]);
            let depth = (radii[i] - room) / radii[i];
            if depth > deepest.0 {
                deepest = (depth, format!("ball {i} and a wall on axis {axis}"));
            }
        }
    }
    for (i, b) in state.iter().enumerate() {
        if captured[i].is_some() {
            continue;
        }
        let (depth, what, _) = object_overlap(table, b.position(), radii[i], false);
        if depth > deepest.0 {
            deepest = (depth, format!("ball {i} and {what}"));
        }
    }
    deepest
}

/// The most events a checked run on a table may take: [`MAX_EVENTS`] within the contract's
/// range, a tenth beyond it, where only an end is asked for (a ball with a friction of 1e191
/// pushed by another at 1.5e4 in a box 2 wide took 8 ms an event, 47 s for 1,000 under the
/// fuzzer's instrumentation).
fn table_events(case: &SimulationCase) -> usize {
    if within_promise(case) {
        MAX_EVENTS
    } else {
        MAX_EVENTS / 10
    }
}

/// Checks [`simulation`]'s invariants and the table's (module documentation) on `tc`; `Ok`
/// also when it is not a valid input at all.
pub fn table_simulation(tc: &TableCase) -> Result<(), String> {
    let case = &tc.case;
    let strict = within_promise(case);
    let Some((balls, walls)) = balls_and_walls(case) else {
        return Ok(());
    };
    let full = match table_run(tc, &balls, walls, case.t_end) {
        Ok(run) => run,
        Err(_) => {
            // Refusals as `simulation` checks them (the same options but the table), and a
            // ball on an object: the named ball must overlap one (loosely) or lie in a target.
            let options = SimulationOptions {
                mass: case.mass.clone(),
                restitution: case.restitution,
                t_end: case.t_end,
                max_events: Some(table_events(case)),
                table: tc.table.clone(),
                table_restitution: tc.table_restitution,
            };
            let e = simulate(&balls, &case.radii, walls, &options)
                .err()
                .ok_or("a run that failed once and not again")?;
            return match e.kind() {
                InputErrorKind::OverlapsObject { .. } => {
                    let i = e.index().ok_or("an object overlap without an index")?;
                    let (depth, _, inside) =
                        object_overlap(&tc.table, balls[i].position(), case.radii[i], true);
                    if depth > -1e-6 || inside.is_some() || depth.is_nan() {
                        Ok(())
                    } else {
                        Err(format!(
                            "{e}, but ball {i} is clear of every object: {tc:?}"
                        ))
                    }
                }
                _ => refused_start(&e, case, &balls, strict, tc),
            };
        }
    };
    if full.events.len() > table_events(case) {
        return Err(format!("{} events: {tc:?}", full.events.len()));
    }
    let mut previous = 0.0;
    // Per ball, when a target captured it.
    let mut captured_at: Vec<Option<f64>> = vec![None; balls.len()];
    for e in &full.events {
        if !(e.time >= previous && e.time <= case.t_end) {
            return Err(format!("event at {} after {previous}: {tc:?}", e.time));
        }
        previous = e.time;
        for b in [Some(e.i), e.j].into_iter().flatten() {
            if let Some(t) = captured_at[b] {
                return Err(format!(
                    "ball {b}, captured at {t}, in an event at {}: {tc:?}",
                    e.time
                ));
            }
        }
        if let Some((ObjectKind::Target, index)) = e.object {
            captured_at[e.i] = Some(e.time);
            if full.captured[e.i] != Some(index) {
                return Err(format!(
                    "ball {} captured by target {index}, reported {:?}: {tc:?}",
                    e.i, full.captured[e.i]
                ));
            }
        }
    }
    for (i, c) in full.captured.iter().enumerate() {
        if c.is_some() != captured_at[i].is_some() {
            return Err(format!(
                "ball {i}: captured {c:?} without its event: {tc:?}"
            ));
        }
        if c.is_some() && full.balls[i].velocity() != Vector2::zeros() {
            return Err(format!("captured ball {i} moves: {tc:?}"));
        }
    }
    if !strict {
        return Ok(());
    }
    let (depth, where_) =
        deepest_on_table(&full.balls, &full.captured, &case.radii, &walls, &tc.table);
    if depth > OVERLAP {
        return Err(format!(
            "{where_} overlap by {depth:e} at the end {}: {tc:?}",
            full.end
        ));
    }
    // Energy: at most what the least parting speeds add, `½·m·2⁻²⁰·R·a` per collision of
    // balls pressed together by their frictions (`a` at most the sum of their frictions), and
    // rounding.
    let speed = balls
        .iter()
        .map(|b| b.velocity().norm())
        .fold(0.0, f64::max);
    if speed > 0.0 && speed.is_finite() {
        let before = energy(&balls, &case.mass, speed);
        let friction = |i: usize| balls[i].friction();
        let added: f64 = full
            .events
            .iter()
            .filter_map(|e| e.j.map(|j| (e.i, j)))
            .map(|(i, j)| {
                let reach = (case.radii[i] + case.radii[j]) * (friction(i) + friction(j));
                2f64.powi(-20) * reach / (speed * speed)
            })
            .sum();
        let after = energy(&full.balls, &case.mass, speed);
        let most =
            before * (1.0 + 1e-9) + added + full.events.len() as f64 * 2f64.powi(-60) * before;
        if after > most && after.is_finite() {
            return Err(format!(
                "energy grew from {before:e} to {after:e} (at most {most:e}): {tc:?}"
            ));
        }
    }
    if full.events.len() < table_events(case) && case.t_end.is_finite() {
        for t in cut_times(&full.events, case.t_end, table_events(case)) {
            let part = table_run(tc, &balls, walls, t)?;
            let (depth, where_) =
                deepest_on_table(&part.balls, &part.captured, &case.radii, &walls, &tc.table);
            if depth > OVERLAP {
                return Err(format!("{where_} overlap by {depth:e} at {t}: {tc:?}"));
            }
            let before: Vec<_> = full.events.iter().filter(|e| e.time < t).copied().collect();
            let logged: Vec<_> = part.events.iter().filter(|e| e.time < t).copied().collect();
            if before != logged {
                return Err(format!("the run cut at {t} logs other events: {tc:?}"));
            }
            // A ball captured before the cut is where the whole run leaves it.
            for (i, at) in captured_at.iter().enumerate() {
                if at.is_some_and(|c| c < t) && part.balls[i].position() != full.balls[i].position()
                {
                    return Err(format!("captured ball {i} moved after its capture: {tc:?}"));
                }
            }
        }
    }
    Ok(())
}
