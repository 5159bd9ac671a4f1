//! Many pairs at once: [`collision_times`] over slices, in parallel, into a caller's buffer.
//!
//! The layout is what numpy hands over without copying: positions and velocities as `(N, 2)`
//! rows (`&[[f64; 2]]`), and each scalar parameter either shared by all pairs or given per
//! pair ([`PerPair`]). Every pair goes through the same validation and the same
//! [`collision_time`](crate::collision_time) search as a single query, so batch and scalar
//! answers are identical, and so are the answers for any number of threads.
//!
//! Paths go in rows as well (`paths.rs`: [`path_collision_times`], [`path_positions_at`]), and
//! so do balls on paths against a table of static objects (`path_geometry.rs`:
//! [`path_geometry_times`], whose answers go into [`ContactColumns`]).
//!
//! The lane stages, each the twin of a scalar stage of `crate::collision` (its map), written
//! over the SIMD layer's `Simd`: `prefilter_lanes.rs` (the unit of length and the straight-run
//! screen), `moving_entry_lanes.rs` (a friction pair's first window), `path_lanes.rs` (the
//! whole-path screens), `window_lanes.rs` (the window screens), `first_window_lanes.rs` with
//! `eighth_lanes.rs` (the eighth entry on a path pair's first window); pairs wait for a full
//! block in a `block_queue.rs` queue. The map of the whole pipeline is in ARCHITECTURE.md.

mod block_queue;
mod eighth_lanes;
mod first_window_lanes;
mod moving_entry_lanes;
mod path_geometry;
mod path_lanes;
mod paths;
mod prefilter_lanes;
mod window_lanes;

#[cfg(feature = "python")]
pub(crate) use path_geometry::check_path_geometry;
pub use path_geometry::{ContactColumns, path_geometry_times};
pub use paths::{PathPairs, PathRows, path_collision_times, path_positions_at};
#[cfg(feature = "python")]
pub(crate) use paths::{check_path_pairs, check_path_positions};

use std::num::NonZeroUsize;
use std::sync::{Arc, Mutex};

use nalgebra::Vector2;
use rayon::prelude::*;
use rayon::{ThreadPool, ThreadPoolBuilder};

use crate::collision::after_stop::after_first_stop_of;
use crate::collision::crossing::{FirstWindow, apart_by_window};
use crate::collision::first_contact_given;
use crate::collision::length_unit::normalised;
use crate::collision::moving_entry::WhileMoving;
use crate::collision::prefilter::{PairInput, valid};
use crate::collision::straight;
use crate::error::{
    InputError, InputErrorKind, check_contact_distance, check_friction, check_horizon, finite,
};
use crate::gap::gap_value;
use crate::interrupt::{Interrupt, uncounted};
use crate::motion::Ball;
use crate::simd::{self, LANES, Mask, Simd};
use block_queue::BlockQueue;
use moving_entry_lanes::while_moving;
use prefilter_lanes::{PairLanes, screen_runs};

/// A scalar parameter of a batch: one value for every pair, or one per pair.
///
/// ```
/// use ballcollide::batch::PerPair;
/// let frictions = [0.1, 0.2, 0.3];
/// assert_eq!(PerPair::Each(&frictions).get(1), 0.2);
/// assert_eq!(PerPair::All(0.5).get(1), 0.5);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PerPair<'a> {
    /// The same value for every pair.
    All(f64),
    /// One value per pair.
    Each(&'a [f64]),
}

impl PerPair<'_> {
    /// The value for pair `i` (`i` must be in range for [`PerPair::Each`]).
    pub fn get(&self, i: usize) -> f64 {
        match self {
            Self::All(x) => *x,
            Self::Each(xs) => xs[i],
        }
    }

    /// Checks the shared value, if this is one.
    fn check_shared(
        &self,
        argument: &'static str,
        check: fn(&'static str, f64) -> Result<f64, InputError>,
    ) -> Result<(), InputError> {
        match self {
            Self::All(x) => check(argument, *x).map(|_| ()),
            Self::Each(_) => Ok(()),
        }
    }

    fn check_len(&self, argument: &'static str, n: usize) -> Result<(), InputError> {
        match self {
            Self::Each(xs) if xs.len() != n => Err(length_mismatch(argument, n, xs.len())),
            _ => Ok(()),
        }
    }
}

/// The inputs of a batch of collision queries: pair `i` is ball A
/// (`pos_a[i]`, `vel_a[i]`, `friction_a`) against ball B, at contact distance `contact_distance`,
/// with horizon `t_max` (`∞` for none).
#[derive(Clone, Copy, Debug)]
pub struct Pairs<'a> {
    /// Centres of the A balls, `(x, y)` per pair.
    pub pos_a: &'a [[f64; 2]],
    /// Velocities of the A balls.
    pub vel_a: &'a [[f64; 2]],
    /// Friction decelerations (≥ 0) of the A balls.
    pub friction_a: PerPair<'a>,
    /// Centres of the B balls.
    pub pos_b: &'a [[f64; 2]],
    /// Velocities of the B balls.
    pub vel_b: &'a [[f64; 2]],
    /// Friction decelerations (≥ 0) of the B balls.
    pub friction_b: PerPair<'a>,
    /// Contact distance (sum of the two radii, > 0).
    pub contact_distance: PerPair<'a>,
    /// Horizon: a collision at `t ≥ t_max` is reported as none.
    pub t_max: PerPair<'a>,
}

/// How many threads a batch call may use.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Threads {
    /// rayon's global pool: every core, or `RAYON_NUM_THREADS`.
    #[default]
    All,
    /// At most this many threads (1 runs on the calling thread).
    AtMost(NonZeroUsize),
}

/// Pairs handled by one task: large enough that scheduling costs nothing, small enough to
/// balance two cores on a few thousand pairs.
const CHUNK: usize = 1024;

/// The collision time of every pair in `pairs`, written to `out` (`∞` where there is none).
///
/// # Errors
/// The first invalid pair's error (lowest index), naming the argument: non-finite numbers,
/// negative friction, a non-positive contact distance, a negative horizon, or an array whose length
/// differs from `out`'s. On error, `out` holds unspecified values.
///
/// ```
/// use ballcollide::batch::{collision_times, Pairs, PerPair, Threads};
///
/// let pos_a = [[0.0, 0.0], [0.0, 0.0]];
/// let vel_a = [[1.0, 0.0], [1.0, 0.0]];
/// let pos_b = [[1.0, 0.0], [1.0, 5.0]];
/// let vel_b = [[0.0, 0.0], [0.0, 0.0]];
/// let pairs = Pairs {
///     pos_a: &pos_a, vel_a: &vel_a, friction_a: PerPair::All(0.0),
///     pos_b: &pos_b, vel_b: &vel_b, friction_b: PerPair::All(0.0),
///     contact_distance: PerPair::All(0.5), t_max: PerPair::All(f64::INFINITY),
/// };
/// let mut out = [0.0; 2];
/// collision_times(&pairs, &mut out, Threads::All)?;
/// assert_eq!(out, [0.5, f64::INFINITY]);
///
/// let bad = Pairs { contact_distance: PerPair::Each(&[0.5, -1.0]), ..pairs };
/// let err = collision_times(&bad, &mut out, Threads::All).unwrap_err();
/// let reason = "the contact distance (sum of the two radii) must be > 0, got -1";
/// assert_eq!(err.to_string(), format!("contact_distance[1]: {reason}"));
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn collision_times(
    pairs: &Pairs<'_>,
    out: &mut [f64],
    threads: Threads,
) -> Result<(), InputError> {
    let n = out.len();
    check_lengths(pairs, n)?;
    let level = simd::current();
    run_chunks(out, threads, |offset, out| {
        simd::dispatch(level, SolveChunk { pairs, offset, out })
    })
}

/// The collision times of pairs `offset..offset + out.len()`: the batch's work on one chunk,
/// at a SIMD level ([`simd::dispatch`]).
///
/// Its first stage, the unit of length and the straight-run screen of a block of [`LANES`]
/// pairs, is written over the level's operations ([`PairLanes`], [`screen_runs`]); the later
/// stages (the timing test, the first window, the closed forms) are loops over the lanes that
/// call the scalar stages, which the compiler vectorises in each level's copy (8-wide with
/// AVX-512, 4-wide with AVX2). Both use only correctly rounded operations, and fused
/// multiply-adds only where written (`mul_add`, a library call without the FMA feature, one
/// instruction with it: the same exact result), so every level gives the same bits (a test
/// checks it).
struct SolveChunk<'p, 'c> {
    pairs: &'p Pairs<'p>,
    offset: usize,
    out: &'c mut [f64],
}

impl simd::Kernel for SolveChunk<'_, '_> {
    type Output = Result<(), InputError>;

    #[inline(always)]
    fn run<S: Simd>(self, s: S) -> Self::Output {
        solve_chunk(s, self.pairs, self.offset, self.out)
    }
}

/// Screens blocks of [`LANES`] pairs ([`screen`]); the moving pairs it leaves open are
/// gathered into blocks of their own for the timing test ([`apart_by_window`]), those it
/// leaves open into blocks of their own again for the first window's plain contacts
/// ([`while_moving`]), and whatever is still open goes to the full validated search. Pairs
/// with one ball at rest that it leaves open among moving pairs are gathered into blocks for
/// the closed form ([`straight::contact`]).
/// Invalid pairs reach the search as soon as they are met, so the first error found is the
/// lowest index's (the pairs held back are valid: they cannot fail).
#[inline(always)]
fn solve_chunk<S: Simd>(
    s: S,
    pairs: &Pairs<'_>,
    offset: usize,
    out: &mut [f64],
) -> Result<(), InputError> {
    let mut held = Held::default();
    for start in (0..out.len()).step_by(LANES) {
        let len = LANES.min(out.len() - start);
        let screened = screen(s, pairs, offset + start, len);
        match out.get_mut(start..start + LANES) {
            Some(block) if len == LANES => block.copy_from_slice(&screened.answers),
            _ => out[start..].copy_from_slice(&screened.answers[..len]),
        }
        // The pairs left open, one bit each: on random table pairs, about one a block.
        let mut open = (screened.answers.iter().take(len).enumerate())
            .fold(0u32, |bits, (k, x)| bits | (u32::from(x.is_nan()) << k));
        while open != 0 {
            let k = open.trailing_zeros() as usize;
            open &= open - 1;
            let i = offset + start + k;
            // Answered when its block is settled.
            if screened.crossing >> k & 1 != 0 {
                held.crossing.push((i, (false, false)));
            } else if screened.at_rest >> k & 1 != 0 {
                held.at_rest.push((i, (false, false)));
            } else {
                // Invalid, both at rest, one at rest beyond the closed form's range, no
                // friction, or magnitudes beyond the lane-wise tests' range.
                out[start + k] = search(pairs, i, None)?;
            }
        }
        // One call, the last block's draining everything: each stage is inlined once.
        held.advance(s, pairs, offset, out, start + len == out.len())?;
    }
    Ok(())
}

/// Moving pairs held back, in two queues: those waiting for the timing test, and those it
/// left open, waiting for the first window's lane-wise settling. Each stage runs on full
/// blocks, so lanes are not spent on pairs an earlier stage has answered (on random table
/// pairs, the timing test proves four in five apart).
#[derive(Default)]
struct Held {
    /// Pairs screened as crossing, for [`apart_by_window`].
    crossing: Queue,
    /// Pairs the timing test left open, with what it proved: the first window apart, the
    /// second.
    open: Queue,
    /// Valid pairs with one ball at rest that the screening left open in a block of moving
    /// pairs, for the closed form ([`straight::contact`]).
    at_rest: Queue,
}

/// Pair indices, each with two flags (what the timing test proved of the first and second
/// windows, for the open queue).
type Queue = BlockQueue<(usize, (bool, bool))>;

/// The inputs of pairs `index[..len]`, a lane each (defaults past `len`).
#[inline(always)]
fn lanes(pairs: &Pairs<'_>, index: &[usize; LANES], len: usize) -> [PairInput; LANES] {
    let mut lanes = [PairInput::default(); LANES];
    // Field by field, straight into the lane: a whole `PairInput` built aside and copied in
    // is stored in narrow pieces and reloaded wide, a stall on every lane.
    for (lane, &i) in lanes.iter_mut().zip(&index[..len]) {
        lane.pos_a = pairs.pos_a[i];
        lane.vel_a = pairs.vel_a[i];
        lane.friction_a = pairs.friction_a.get(i);
        lane.pos_b = pairs.pos_b[i];
        lane.vel_b = pairs.vel_b[i];
        lane.friction_b = pairs.friction_b.get(i);
        lane.radius = pairs.contact_distance.get(i);
        lane.t_max = pairs.t_max.get(i);
    }
    for lane in &mut lanes {
        *lane = normalised(lane, 0.0);
    }
    lanes
}

impl Held {
    /// Runs each stage on every full block, and on whatever is held if `finish` (`out` holds
    /// pairs `offset..`). Inlined into every copy of [`solve_chunk`], so that the
    /// tests run in the widest vectors; each stage has one call site, so it is inlined once.
    #[inline(always)]
    fn advance<S: Simd>(
        &mut self,
        s: S,
        pairs: &Pairs<'_>,
        offset: usize,
        out: &mut [f64],
        finish: bool,
    ) -> Result<(), InputError> {
        // Every queue is drained the same way: full blocks, and at the end whatever is held.
        let ready = |queue: &Queue| queue.len() >= LANES || (finish && queue.len() > 0);
        loop {
            let test = ready(&self.crossing);
            // Settling first keeps the open queue below one block before a test adds to it.
            if ready(&self.at_rest) {
                self.settle_at_rest(pairs, offset, out)?;
            } else if self.open.len() >= LANES || (finish && !test && self.open.len() > 0) {
                self.settle_first_window(s, pairs, offset, out)?;
            } else if test {
                self.time_test(pairs, offset, out);
            } else {
                return Ok(());
            }
        }
    }

    /// Answers a block of pairs with one ball at rest: the closed form where it applies, the
    /// search's answer elsewhere.
    #[inline(always)]
    fn settle_at_rest(
        &mut self,
        pairs: &Pairs<'_>,
        offset: usize,
        out: &mut [f64],
    ) -> Result<(), InputError> {
        let (held, len) = self.at_rest.take();
        let index = held.map(|(i, _)| i);
        let lanes = lanes(pairs, &index, len);
        let answers = at_rest_answers(|k| lanes[k], &first_lanes(len));
        for (&i, &answer) in index[..len].iter().zip(&answers) {
            out[i - offset] = if answer.is_nan() {
                search(pairs, i, None)?
            } else {
                answer
            };
        }
        Ok(())
    }

    /// Runs the timing test on a block of crossing pairs: `∞` where it proves both windows
    /// apart; the others move on to the open queue.
    #[inline(always)]
    fn time_test(&mut self, pairs: &Pairs<'_>, offset: usize, out: &mut [f64]) {
        let (held, len) = self.crossing.take();
        let index = held.map(|(i, _)| i);
        let lanes = lanes(pairs, &index, len);
        let mut apart = [(false, false); LANES];
        for (apart, lane) in apart.iter_mut().zip(&lanes) {
            *apart = apart_by_window(lane);
        }
        for (&i, &(first, second)) in index[..len].iter().zip(&apart) {
            if first & second {
                out[i - offset] = f64::INFINITY;
            } else {
                self.open.push((i, (first, second)));
            }
        }
    }

    /// Answers a block of open pairs: the entry where [`while_moving`] settles the first
    /// window; where the first window is free (proven apart, or no entry found), `∞` if the
    /// second was proven apart, else the closed form from the first stop on
    /// ([`after_first_stop_of`]) where it applies; the search's answer elsewhere.
    #[inline(always)]
    fn settle_first_window<S: Simd>(
        &mut self,
        s: S,
        pairs: &Pairs<'_>,
        offset: usize,
        out: &mut [f64],
    ) -> Result<(), InputError> {
        let (held, len) = self.open.take();
        let (index, apart) = (held.map(|(i, _)| i), held.map(|(_, apart)| apart));
        let lanes = lanes(pairs, &index, len);
        let (entry, screened_out) = while_moving(s, &PairLanes::of_inputs(s, &lanes));
        let (mut no_entry, mut free) = ([false; LANES], [false; LANES]);
        for (l, (no_entry, free)) in no_entry.iter_mut().zip(&mut free).enumerate() {
            *no_entry = screened_out >> l & 1 != 0;
            *free = apart[l].0 | *no_entry;
        }
        // In a loop of its own, run only where some lane needs it (contacts after a stop are
        // rarer than contacts while both move). It builds the first windows again rather
        // than keep the ones `while_moving` built: holding eight windows across that loop
        // spilled registers, and the stage ran 1.2–1.3× slower on grazing pairs with both
        // balls moving (and on random table pairs) when tried.
        let mut after = [(false, f64::NAN); LANES];
        let needed = free
            .iter()
            .zip(&apart)
            .take(len)
            .any(|(&free, &(_, second))| free & !second);
        if needed {
            for (after, lane) in after.iter_mut().zip(&lanes) {
                *after = after_first_stop_of(lane, &FirstWindow::of(lane));
            }
        }
        let lane_answers = entry
            .iter()
            .zip(&no_entry)
            .zip(free.iter().zip(&apart).zip(&after));
        for (&i, ((&entry, &no_entry), ((&free, &(_, second)), &(applies, t)))) in
            index[..len].iter().zip(lane_answers)
        {
            out[i - offset] = if !entry.is_nan() {
                entry
            } else if free & second {
                f64::INFINITY
            } else if free & applies {
                t
            } else {
                search(
                    pairs,
                    i,
                    Some(WhileMoving {
                        entry,
                        screened_out: no_entry,
                    }),
                )?
            };
        }
        Ok(())
    }
}

/// Pair `i`'s collision time by the full search (`∞` for none), or its input error; `moving`
/// is what [`while_moving`] found for it, if the lanes ran it.
fn search(pairs: &Pairs<'_>, i: usize, moving: Option<WhileMoving>) -> Result<f64, InputError> {
    Ok(pair_time(pairs, i, moving)
        .map_err(|e| e.at(i))?
        .unwrap_or(f64::INFINITY))
}

/// What the screening of a block settles, and where the pairs it leaves open go.
struct Screened {
    /// `∞` for pairs proven apart ([`screen_runs`]), in a block where every pair has one ball
    /// at rest the closed form's time (or `∞`) where it applies; NaN for the rest (and for
    /// lanes past the block's length).
    answers: [f64; LANES],
    /// Open pairs for the timing test ([`apart_by_window`]): valid, both balls moving.
    crossing: Mask,
    /// Open pairs for the closed form: valid, one ball at rest (in a block of moving pairs).
    at_rest: Mask,
}

/// Screens pairs `start..start + len` (`len ≤ LANES`), lane-wise ([`PairLanes`],
/// [`screen_runs`]); whatever it leaves open and neither `crossing` nor `at_rest` goes to the
/// scalar search.
#[inline(always)]
fn screen<S: Simd>(s: S, pairs: &Pairs<'_>, start: usize, len: usize) -> Screened {
    // Each pair in its own unit of length, as the scalar search takes it.
    let lanes = PairLanes::normalised(s, pairs, start, len);
    let (rests_a, rests_b) = lanes.at_rest(s);
    let one_at_rest = rests_a ^ rests_b;
    // A block where every pair has one ball at rest (a cue ball against the others, say)
    // goes to the closed form alone, which settles misses as well as the screening does.
    if s.every(one_at_rest) {
        let inputs = lanes.inputs(s);
        return Screened {
            answers: at_rest_answers(|k| inputs[k], &first_lanes(len)),
            crossing: 0,
            at_rest: 0,
        };
    }
    let (in_range, apart) = screen_runs(s, &lanes);
    let plain = in_range & s.mask(first_lanes_mask(len));
    let open = plain & !apart;
    Screened {
        answers: s.store(s.blend(plain & apart, s.splat(f64::NAN), s.splat(f64::INFINITY))),
        crossing: s.bits(open & !rests_a & !rests_b),
        at_rest: s.bits(open & one_at_rest),
    }
}

/// The lanes `0..len` of a block, as bits.
#[inline(always)]
fn first_lanes_mask(len: usize) -> Mask {
    (((1u32 << len) - 1) & u32::from(Mask::MAX)) as Mask
}

/// The lanes `0..len` of a block.
#[inline(always)]
fn first_lanes(len: usize) -> [bool; LANES] {
    let mut first = [false; LANES];
    for (k, lane) in first.iter_mut().enumerate() {
        *lane = k < len;
    }
    first
}

/// Whether a ball with this velocity is at rest.
#[inline(always)]
fn rests([vx, vy]: [f64; 2]) -> bool {
    (vx == 0.0) & (vy == 0.0)
}

/// The closed form's answers for pairs with one ball at rest ([`straight::contact`]),
/// lane-wise: for each lane `k` that is `open` and valid, where the closed form applies, its
/// time (`∞` for none, or at or past the horizon); NaN elsewhere.
///
/// The closed form gets exactly the inputs that the scalar search would give it, so it returns
/// the same bits.
#[inline(always)]
fn at_rest_answers(lane: impl Fn(usize) -> PairInput, open: &[bool; LANES]) -> [f64; LANES] {
    let mut answers = [f64::NAN; LANES];
    for (k, answer) in answers.iter_mut().enumerate() {
        let pair = lane(k);
        // The mover (A unless A rests) against the resting ball.
        let ((p, v, mu), q) = if rests(pair.vel_a) {
            ((pair.pos_b, pair.vel_b, pair.friction_b), pair.pos_a)
        } else {
            ((pair.pos_a, pair.vel_a, pair.friction_a), pair.pos_b)
        };
        let g0 = gap_value(
            pair.pos_a[0] - pair.pos_b[0],
            pair.pos_a[1] - pair.pos_b[1],
            pair.radius,
        );
        let (applies, t) = straight::contact([p[0] - q[0], p[1] - q[1]], v, mu, pair.radius, g0);
        let t = if t < pair.t_max { t } else { f64::INFINITY };
        if open[k] & valid(&pair) & applies {
            *answer = t;
        }
    }
    answers
}

/// The centre of every ball at its time `t` (`pos`, `vel`, `friction` as in [`Pairs`]),
/// written to `out`; a stopped ball stays where it stopped.
///
/// # Errors
/// As [`collision_times`]; `t` must be finite (negative times are taken as 0).
///
/// ```
/// use ballcollide::batch::{positions_at, PerPair, Threads};
/// let mut out = [[0.0; 2]; 1];
/// let (pos, vel) = ([[0.0, 0.0]], [[2.0, 0.0]]);
/// positions_at(&pos, &vel, PerPair::All(0.5), PerPair::All(10.0), &mut out, Threads::All)?;
/// assert_eq!(out, [[4.0, 0.0]]);
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn positions_at(
    pos: &[[f64; 2]],
    vel: &[[f64; 2]],
    friction: PerPair<'_>,
    t: PerPair<'_>,
    out: &mut [[f64; 2]],
    threads: Threads,
) -> Result<(), InputError> {
    check_ball_arrays(pos, vel, friction, t, out.len())?;
    run_chunks(out, threads, |offset, chunk| {
        for (k, slot) in chunk.iter_mut().enumerate() {
            let i = offset + k;
            let ball = ball(pos[i], vel[i], friction.get(i), ["pos", "vel", "friction"])
                .map_err(|e| e.at(i))?;
            let time = finite("t", t.get(i)).map_err(|e| e.at(i))?;
            *slot = ball.position_at(time).into();
        }
        Ok(())
    })
}

/// One pair's collision time, validating its inputs.
fn pair_time(
    pairs: &Pairs<'_>,
    i: usize,
    moving: Option<WhileMoving>,
) -> Result<Option<f64>, InputError> {
    let a = ball(
        pairs.pos_a[i],
        pairs.vel_a[i],
        pairs.friction_a.get(i),
        ["pos_a", "vel_a", "friction_a"],
    )?;
    let b = ball(
        pairs.pos_b[i],
        pairs.vel_b[i],
        pairs.friction_b.get(i),
        ["pos_b", "vel_b", "friction_b"],
    )?;
    let radius = check_contact_distance("contact_distance", pairs.contact_distance.get(i))?;
    let t_max = check_horizon("t_max", pairs.t_max.get(i))?;
    Ok(first_contact_given(&a, &b, radius, t_max, moving))
}

/// A validated ball whose errors carry the batch's argument names.
fn ball(
    position: [f64; 2],
    velocity: [f64; 2],
    friction: f64,
    names: [&'static str; 3],
) -> Result<Ball, InputError> {
    Ball::new(Vector2::from(position), Vector2::from(velocity), friction).map_err(|e| {
        let name = match e.argument() {
            "position" => names[0],
            "velocity" => names[1],
            _ => names[2],
        };
        e.renamed(name)
    })
}

/// Checks the array lengths and the values shared by all pairs. A bad shared value is an error
/// (without an index: it belongs to no pair in particular) even in an empty batch. The Python
/// binding runs them before it looks at a caller's `out` array.
pub(crate) fn check_lengths(pairs: &Pairs<'_>, n: usize) -> Result<(), InputError> {
    check_len("pos_a", pairs.pos_a.len(), n)?;
    check_len("vel_a", pairs.vel_a.len(), n)?;
    pairs.friction_a.check_len("friction_a", n)?;
    check_len("pos_b", pairs.pos_b.len(), n)?;
    check_len("vel_b", pairs.vel_b.len(), n)?;
    pairs.friction_b.check_len("friction_b", n)?;
    pairs.contact_distance.check_len("contact_distance", n)?;
    pairs.t_max.check_len("t_max", n)?;
    pairs
        .friction_a
        .check_shared("friction_a", check_friction)?;
    pairs
        .friction_b
        .check_shared("friction_b", check_friction)?;
    pairs
        .contact_distance
        .check_shared("contact_distance", check_contact_distance)?;
    pairs.t_max.check_shared("t_max", check_horizon)
}

/// The checks of [`positions_at`] that need no pair: every array of length `n`, shared values
/// valid. The Python binding runs them before it looks at a caller's `out` array.
pub(crate) fn check_ball_arrays(
    pos: &[[f64; 2]],
    vel: &[[f64; 2]],
    friction: PerPair<'_>,
    t: PerPair<'_>,
    n: usize,
) -> Result<(), InputError> {
    check_len("pos", pos.len(), n)?;
    check_len("vel", vel.len(), n)?;
    friction.check_len("friction", n)?;
    t.check_len("t", n)?;
    friction.check_shared("friction", check_friction)?;
    t.check_shared("t", finite)
}

/// `len == n`, else a length mismatch naming `argument`.
pub(crate) fn check_len(argument: &'static str, len: usize, n: usize) -> Result<(), InputError> {
    if len == n {
        Ok(())
    } else {
        Err(length_mismatch(argument, n, len))
    }
}

fn length_mismatch(argument: &'static str, expected: usize, found: usize) -> InputError {
    InputError::new(argument, InputErrorKind::LengthMismatch { expected, found })
}

/// Runs `work(offset, chunk)` over `out` in chunks of [`CHUNK`] ([`run_chunks_of`]), each
/// item one query.
fn run_chunks<T: Send>(
    out: &mut [T],
    threads: Threads,
    work: impl Fn(usize, &mut [T]) -> Result<(), InputError> + Sync,
) -> Result<(), InputError> {
    run_chunks_of(CHUNK, out, threads, <[T]>::len, work)
}

/// Runs `work(offset, chunk)` over `out` in chunks of `size` (≥ 1) items, on the requested
/// threads, and returns the error of the lowest index if any chunk failed (each chunk stops at
/// its first error). Each chunk first looks at the caller's [`Interrupt`] flag: once it is
/// set, the chunks left fail with [`InputErrorKind::Interrupted`]; and once done, adds its
/// `queries(chunk)` to the caller's counter ([`counted`](crate::interrupt::counted)).
pub(crate) fn run_chunks_of<T: Send>(
    size: usize,
    out: &mut [T],
    threads: Threads,
    queries: fn(&[T]) -> usize,
    work: impl Fn(usize, &mut [T]) -> Result<(), InputError> + Sync,
) -> Result<(), InputError> {
    let size = size.max(1);
    let interrupt = Interrupt::current();
    let work = |offset: usize, out: &mut [T]| {
        interrupt.check()?;
        // The chunk's items are counted here, once: not what the work itself counts (the
        // calendar a shot builds counts its balls), on this thread or a pool's.
        uncounted(|| work(offset, out))?;
        interrupt.done(queries(out));
        Ok(())
    };
    let parallel = |out: &mut [T]| {
        out.par_chunks_mut(size)
            .enumerate()
            .map(|(c, chunk)| work(c * size, chunk))
            .reduce(|| Ok(()), first_error)
    };
    // On the calling thread: chunk after chunk, each looking at the flag.
    let serial = |out: &mut [T]| {
        out.chunks_mut(size)
            .enumerate()
            .try_for_each(|(c, chunk)| work(c * size, chunk))
    };
    match threads {
        // One chunk's worth (or one thread): handing it to a pool would only add a wake-up.
        _ if out.len() <= size => work(0, out),
        Threads::AtMost(n) if n.get() == 1 => serial(out),
        Threads::All => parallel(out),
        Threads::AtMost(n) => match pool(n.get()) {
            Some(pool) => pool.install(|| parallel(out)),
            // No thread could be started: the calling thread does the work.
            None => serial(out),
        },
    }
}

/// A rayon pool of `n` threads, built on first use and kept: building one costs tens of
/// microseconds and `n` threads, which a call on a thousand pairs should not pay each time.
/// Only a few sizes are kept (callers use one or two); others get a pool of their own.
fn pool(n: usize) -> Option<Arc<ThreadPool>> {
    const KEPT: usize = 8;
    static POOLS: Mutex<Vec<(usize, Arc<ThreadPool>)>> = Mutex::new(Vec::new());
    let build = || {
        ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .ok()
            .map(Arc::new)
    };
    // A poisoned lock (a panic elsewhere while holding it) only loses the cache.
    let Ok(mut pools) = POOLS.lock() else {
        return build();
    };
    if let Some((_, pool)) = pools.iter().find(|(size, _)| *size == n) {
        return Some(Arc::clone(pool));
    }
    let pool = build()?;
    if pools.len() < KEPT {
        pools.push((n, Arc::clone(&pool)));
    }
    Some(pool)
}

/// Of two chunk results, the error with the lower index (chunks may finish in any order).
fn first_error(x: Result<(), InputError>, y: Result<(), InputError>) -> Result<(), InputError> {
    match (x, y) {
        (Err(a), Err(b)) => Err(if b.index() < a.index() { b } else { a }),
        (Err(e), Ok(())) | (Ok(()), Err(e)) => Err(e),
        (Ok(()), Ok(())) => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::prefilter::screened_out_by_runs;
    use crate::simd::Portable;
    use crate::{CollisionOptions, collision_time_with};

    #[test]
    fn a_bad_shared_value_is_an_error_even_in_an_empty_batch() {
        let empty: [[f64; 2]; 0] = [];
        let pairs = |radius, t_max, friction| Pairs {
            pos_a: &empty,
            vel_a: &empty,
            friction_a: PerPair::All(friction),
            pos_b: &empty,
            vel_b: &empty,
            friction_b: PerPair::All(0.0),
            contact_distance: PerPair::All(radius),
            t_max: PerPair::All(t_max),
        };
        let run = |p: Pairs<'_>| collision_times(&p, &mut [], Threads::All);
        assert_eq!(run(pairs(1.0, f64::INFINITY, 0.0)), Ok(()));
        let err = run(pairs(0.0, f64::INFINITY, 0.0)).unwrap_err();
        assert_eq!((err.argument(), err.index()), ("contact_distance", None));
        let err = run(pairs(1.0, -1.0, 0.0)).unwrap_err();
        assert_eq!((err.argument(), err.index()), ("t_max", None));
        let err = run(pairs(1.0, 1.0, f64::NAN)).unwrap_err();
        assert_eq!((err.argument(), err.index()), ("friction_a", None));
        let mut out: [[f64; 2]; 0] = [];
        let err = positions_at(
            &empty,
            &empty,
            PerPair::All(-1.0),
            PerPair::All(0.0),
            &mut out,
            Threads::All,
        )
        .unwrap_err();
        assert_eq!((err.argument(), err.index()), ("friction", None));
    }

    use crate::test_rng::Rng;

    struct Rows {
        pos_a: Vec<[f64; 2]>,
        vel_a: Vec<[f64; 2]>,
        mu_a: Vec<f64>,
        pos_b: Vec<[f64; 2]>,
        vel_b: Vec<[f64; 2]>,
        mu_b: Vec<f64>,
        t_max: Vec<f64>,
    }

    /// Table-sized pairs at every scale of speed and friction, many of them near each other
    /// (a close pass or a contact), some at rest, frictionless, or with a horizon.
    fn rows(n: usize, seed: u64) -> Rows {
        let mut rng = Rng(seed);
        let mut r = Rows {
            pos_a: vec![],
            vel_a: vec![],
            mu_a: vec![],
            pos_b: vec![],
            vel_b: vec![],
            mu_b: vec![],
            t_max: vec![],
        };
        for k in 0..n {
            let pa = [rng.uniform(0.0, 2.54), rng.uniform(0.0, 1.27)];
            let near = k % 3 == 0;
            let pb = if near {
                [
                    pa[0] + rng.uniform(-0.2, 0.2),
                    pa[1] + rng.uniform(-0.2, 0.2),
                ]
            } else {
                [rng.uniform(0.0, 2.54), rng.uniform(0.0, 1.27)]
            };
            let velocity = |rng: &mut Rng| {
                let (s, a) = (rng.uniform(0.0, 3.0), rng.uniform(0.0, 6.3));
                match k % 7 {
                    0 => [0.0, 0.0],
                    _ => [s * a.cos(), s * a.sin()],
                }
            };
            r.vel_a.push(velocity(&mut rng));
            r.vel_b.push(if k % 5 == 0 {
                [0.0, 0.0]
            } else {
                velocity(&mut rng)
            });
            r.mu_a.push(if k % 11 == 0 {
                0.0
            } else {
                rng.uniform(0.05, 2.0)
            });
            r.mu_b.push(rng.uniform(0.0, 2.0));
            r.t_max.push(if k % 13 == 0 {
                rng.uniform(0.0, 2.0)
            } else {
                f64::INFINITY
            });
            r.pos_a.push(pa);
            r.pos_b.push(pb);
        }
        r
    }

    fn pairs(r: &Rows) -> Pairs<'_> {
        Pairs {
            pos_a: &r.pos_a,
            vel_a: &r.vel_a,
            friction_a: PerPair::Each(&r.mu_a),
            pos_b: &r.pos_b,
            vel_b: &r.vel_b,
            friction_b: PerPair::Each(&r.mu_b),
            contact_distance: PerPair::All(0.05715),
            t_max: PerPair::Each(&r.t_max),
        }
    }

    #[test]
    fn batch_equals_the_scalar_search_bit_for_bit() {
        // Not a multiple of the block or the chunk: the last chunk ends in a partial block
        // with pairs still queued for the timing test and the first window.
        let r = rows(20_003, 3);
        let p = pairs(&r);
        let mut out = vec![0.0; r.pos_a.len()];
        assert_eq!(collision_times(&p, &mut out, Threads::All), Ok(()));
        let mut hits = 0;
        for (i, &t) in out.iter().enumerate() {
            let a = Ball::new(r.pos_a[i].into(), r.vel_a[i].into(), r.mu_a[i]);
            let b = Ball::new(r.pos_b[i].into(), r.vel_b[i].into(), r.mu_b[i]);
            let (Ok(a), Ok(b)) = (a, b) else {
                panic!("valid balls at {i}")
            };
            let options = CollisionOptions { t_max: r.t_max[i] };
            let scalar = collision_time_with(&a, &b, 0.05715, &options);
            assert_eq!(
                scalar.map(|x| x.unwrap_or(f64::INFINITY).to_bits()),
                Ok(t.to_bits()),
                "pair {i}"
            );
            hits += usize::from(t.is_finite());
        }
        assert!(hits > 1000, "{hits} hits: the set should exercise contacts");
    }

    /// The screen's answers for every pair, block by block.
    struct ScreenAll<'a>(&'a Pairs<'a>);

    impl simd::Kernel for ScreenAll<'_> {
        type Output = Vec<f64>;

        #[inline(always)]
        fn run<S: Simd>(self, s: S) -> Vec<f64> {
            let n = self.0.pos_a.len();
            let mut out = Vec::with_capacity(n);
            for start in (0..n).step_by(LANES) {
                let len = LANES.min(n - start);
                out.extend_from_slice(&screen(s, self.0, start, len).answers[..len]);
            }
            out
        }
    }

    #[test]
    fn every_vector_copy_agrees_with_the_portable_code_bit_for_bit() {
        let r = rows(5_000, 5);
        let p = pairs(&r);
        let mut portable = vec![0.0; r.pos_a.len()];
        assert_eq!(solve_chunk(Portable, &p, 0, &mut portable), Ok(()));
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        // Every copy this CPU can run, through the dispatch.
        for level in crate::simd::test_levels() {
            let mut copy = vec![0.0; r.pos_a.len()];
            let chunk = SolveChunk {
                pairs: &p,
                offset: 0,
                out: &mut copy,
            };
            assert_eq!(simd::dispatch(level, chunk), Ok(()));
            assert_eq!(bits(&portable), bits(&copy), "{level}");
            eprintln!("friction lanes at {level}: same bits as the portable copy");
        }
        let (mut apart, mut closed) = (0, 0);
        let one = |i: usize| PairInput {
            pos_a: r.pos_a[i],
            vel_a: r.vel_a[i],
            friction_a: r.mu_a[i],
            pos_b: r.pos_b[i],
            vel_b: r.vel_b[i],
            friction_b: r.mu_b[i],
            radius: 0.05715,
            t_max: r.t_max[i],
        };
        // The screen's lanes, at every level: `∞` for every pair the scalar screen proves
        // apart.
        for level in crate::simd::test_levels() {
            let answers = simd::dispatch(level, ScreenAll(&p));
            for (i, &answer) in answers.iter().enumerate() {
                if screened_out_by_runs(&one(i)) {
                    assert_eq!(answer, f64::INFINITY, "{level}: pair {i}");
                    apart += 1;
                }
            }
        }
        // The closed form, lane-wise, on blocks of the pairs with one ball at rest.
        let at_rest: Vec<usize> = (0..r.pos_a.len())
            .filter(|&i| rests(r.vel_a[i]) != rests(r.vel_b[i]))
            .collect();
        for block in at_rest.chunks(LANES) {
            let mut open = [false; LANES];
            open[..block.len()].fill(true);
            let answers = at_rest_answers(|k| one(block[k.min(block.len() - 1)]), &open);
            for (&i, &answer) in block.iter().zip(&answers) {
                if !answer.is_nan() {
                    assert_eq!(answer.to_bits(), portable[i].to_bits(), "pair {i}");
                    closed += 1;
                }
            }
        }
        // Both shortcuts are exercised (and the scalar path: see the test above).
        assert!(
            apart > 1000 && closed > 100,
            "{apart} apart, {closed} closed form"
        );
    }

    #[test]
    fn pairs_held_back_are_answered_at_the_end_of_every_chunk() {
        // Close pairs (none proven apart), B at rest in four in five, so that most blocks mix
        // the timing test's pairs with the closed form's and the queues end chunks holding
        // more than a block; every pair must get the scalar search's answer, whichever
        // thread count splits the batch into chunks.
        let mut rng = Rng(0xc0de);
        let n = 5 * CHUNK + 3;
        let (mut pos_b, mut vel_b) = (vec![], vec![]);
        for _ in 0..n {
            // On A's path (y = x/20), give or take a third of the contact distance.
            let x = rng.uniform(0.2, 0.6);
            pos_b.push([x, x / 20.0 + rng.uniform(-0.02, 0.02)]);
            let speed = if rng.uniform(0.0, 1.0) < 0.8 {
                0.0
            } else {
                -0.3
            };
            vel_b.push([speed, rng.uniform(-0.1, 0.1) * speed]);
        }
        let (pos_a, vel_a) = (vec![[0.0, 0.0]; n], vec![[1.0, 0.05]; n]);
        let pairs = Pairs {
            pos_a: &pos_a,
            vel_a: &vel_a,
            friction_a: PerPair::All(0.5),
            pos_b: &pos_b,
            vel_b: &vel_b,
            friction_b: PerPair::All(0.5),
            contact_distance: PerPair::All(0.05715),
            t_max: PerPair::All(f64::INFINITY),
        };
        let scalar: Vec<u64> = (0..n)
            .map(|i| search(&pairs, i, None).map(f64::to_bits))
            .collect::<Result<_, _>>()
            .unwrap_or_default();
        assert_eq!(scalar.len(), n);
        for threads in [1, 2] {
            let mut out = vec![0.0; n];
            let threads = Threads::AtMost(NonZeroUsize::new(threads).unwrap_or(NonZeroUsize::MIN));
            assert_eq!(collision_times(&pairs, &mut out, threads), Ok(()));
            let bits: Vec<u64> = out.iter().map(|x| x.to_bits()).collect();
            assert_eq!(bits, scalar, "{threads:?}");
        }
    }

    #[test]
    fn the_first_error_is_reported_after_screened_pairs() {
        let r = rows(100, 9);
        let mut mu = r.mu_b.clone();
        mu[37] = -1.0;
        mu[80] = f64::NAN;
        let p = Pairs {
            friction_b: PerPair::Each(&mu),
            ..pairs(&r)
        };
        let mut out = vec![0.0; 100];
        let err = collision_times(&p, &mut out, Threads::All).err();
        assert_eq!(
            err.map(|e| (e.argument(), e.index())),
            Some(("friction_b", Some(37)))
        );
    }

    #[test]
    fn pools_are_kept_per_thread_count() {
        let (Some(a), Some(b)) = (pool(2), pool(2)) else {
            panic!("a two-thread pool")
        };
        assert!(Arc::ptr_eq(&a, &b));
        assert_eq!(a.current_num_threads(), 2);
        let r = rows(3_000, 1);
        let p = pairs(&r);
        let (mut x, mut y) = (vec![0.0; 3_000], vec![0.0; 3_000]);
        let two = Threads::AtMost(NonZeroUsize::MIN.saturating_add(1));
        assert_eq!(collision_times(&p, &mut x, two), Ok(()));
        assert_eq!(
            collision_times(&p, &mut y, Threads::AtMost(NonZeroUsize::MIN)),
            Ok(())
        );
        assert_eq!(x, y);
    }
}
