//! The invariants of `simulate`, checked by the fuzz target `simulate` (`fuzz/`) and by the
//! property tests (`tests/integration/simulation_progress.rs`): one implementation for both.
//!
//! - a valid start either runs or is refused as a start no motion comes from (a ball
//!   overlapping another or a wall, outside the box, as wide as the box), and then the named
//!   ball really is so; nothing else is an error (never "no progress");
//! - the run ends (within its `max_events`), its events in time order, within `[0, t_end]`;
//! - no two balls overlap, and no ball overlaps a wall, beyond `1e-9` of their contact
//!   distance (or radius), at the end nor at the end of the same run cut at earlier times
//!   (a horizon only cuts: those are states of one trajectory);
//! - a run cut at `t_end / 2` logs exactly the events of the whole run before `t_end / 2`.
//!
//! The last three hold where `docs/contract.md` (§5) promises answers: every non-zero
//! magnitude of the case (the box's width, radii, velocities, frictions) within `2^±400` of
//! the box's width, and time able to resolve the motion ([`within_promise`]). Beyond, a run must still end or be refused, with its
//! events in order, and never panic.

#![allow(dead_code)]

use ballcollide::schedule::{Simulation, SimulationOptions, Walls, simulate};
use ballcollide::{Ball, InputErrorKind};
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

/// The most events a checked run may take: each case runs four times, and a pair query may
/// take 250 µs where a window is 2²³⁴ times the motion's time scale (a ball at 5e118 with
/// friction 1409 in a box 2 wide, within the pair search's range), and 1.2 ms beyond that
/// range (its long-window stage halves pieces 4,096 times), so that a fuzz input stays
/// within libFuzzer's 10 s timeout under its instrumentation.
pub const MAX_EVENTS: usize = 1_000;

/// How deep an overlap may be at any state, relative to the contact distance.
pub const OVERLAP: f64 = 1e-9;

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
/// and time resolving the motion: twice the fastest ball (no collision makes a ball faster)
/// crosses the narrower width in at least `2⁻⁴⁰·t_end`, 2¹² ulps of `t_end`. (A ball at 1e82
/// in a box 2 wide meets a wall every 1e-82 time units, which no time near 1e-32 resolves:
/// such a run stops with "no progress".)
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

/// Checks every invariant of the module documentation on `case`; `Ok` also when the case is
/// not a valid input at all (a bad number, a bad box).
pub fn simulation(case: &SimulationCase) -> Result<(), String> {
    let strict = within_promise(case);
    let Ok(balls) = case
        .balls
        .iter()
        .map(|b| Ball::new(Vector2::new(b[0], b[1]), Vector2::new(b[2], b[3]), b[4]))
        .collect::<Result<Vec<_>, _>>()
    else {
        return Ok(());
    };
    let Ok(walls) = Walls::new(case.lo, case.hi) else {
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
        Err(e) => {
            return match e.kind() {
                // Refused starts: the named ball must be so (loosely: beyond half the
                // tolerance the start check uses).
                InputErrorKind::Overlap { other, .. } => {
                    let i = e.index().ok_or("an overlap without an index")?;
                    let contact = case.radii[i] + case.radii[other];
                    let d = (balls[i].position() - balls[other].position()).norm();
                    if d < contact {
                        Ok(())
                    } else {
                        Err(format!(
                            "{e}, but they are {d:e} apart ({contact:e}): {case:?}"
                        ))
                    }
                }
                InputErrorKind::OutsideBox { .. } | InputErrorKind::WiderThanBox { .. } => Ok(()),
                // Bad numbers the decoder may make (a radius ≤ 0, a mass ≤ 0, restitution
                // outside [0, 1], no end).
                InputErrorKind::NotFinite(_)
                | InputErrorKind::NonPositiveRadius(_)
                | InputErrorKind::NonPositiveMass(_)
                | InputErrorKind::NotInUnitInterval(_)
                | InputErrorKind::InvalidHorizon(_)
                | InputErrorKind::LengthMismatch { .. }
                | InputErrorKind::Endless => Ok(()),
                _ if !strict => Ok(()),
                _ => Err(format!("a valid start failed: {e}: {case:?}")),
            };
        }
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
        for cut in [0.5, 0.25, 0.75] {
            let t = case.t_end * cut;
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
    Ok(())
}
