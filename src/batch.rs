//! Many pairs at once: [`collision_times`] over slices, in parallel, into a caller's buffer.
//!
//! The layout is what numpy hands over without copying: positions and velocities as `(N, 2)`
//! rows (`&[[f64; 2]]`), and each scalar parameter either shared by all pairs or given per
//! pair ([`PerPair`]). Every pair goes through the same validation and the same
//! [`collision_time`](crate::collision_time) search as a single query, so batch and scalar
//! answers are identical, and so are the answers for any number of threads.

use std::num::NonZeroUsize;

use nalgebra::Vector2;
use rayon::prelude::*;

use crate::collision::first_contact;
use crate::error::{InputError, InputErrorKind, check_horizon, check_radius, finite};
use crate::motion::Ball;

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

    fn check_len(&self, argument: &'static str, n: usize) -> Result<(), InputError> {
        match self {
            Self::Each(xs) if xs.len() != n => Err(length_mismatch(argument, n, xs.len())),
            _ => Ok(()),
        }
    }
}

/// The inputs of a batch of collision queries: pair `i` is ball A
/// (`pos_a[i]`, `vel_a[i]`, `friction_a`) against ball B, at contact distance `radius`,
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
    pub radius: PerPair<'a>,
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
/// negative friction, a non-positive radius, a negative horizon, or an array whose length
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
///     radius: PerPair::All(0.5), t_max: PerPair::All(f64::INFINITY),
/// };
/// let mut out = [0.0; 2];
/// collision_times(&pairs, &mut out, Threads::All)?;
/// assert_eq!(out, [0.5, f64::INFINITY]);
///
/// let bad = Pairs { radius: PerPair::Each(&[0.5, -1.0]), ..pairs };
/// let err = collision_times(&bad, &mut out, Threads::All).unwrap_err();
/// assert_eq!(err.to_string(), "radius[1]: radius (sum of the two radii) must be > 0, got -1");
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn collision_times(
    pairs: &Pairs<'_>,
    out: &mut [f64],
    threads: Threads,
) -> Result<(), InputError> {
    let n = out.len();
    check_lengths(pairs, n)?;
    run_chunks(out, threads, |offset, chunk| {
        for (k, slot) in chunk.iter_mut().enumerate() {
            let i = offset + k;
            *slot = pair_time(pairs, i)
                .map_err(|e| e.at(i))?
                .unwrap_or(f64::INFINITY);
        }
        Ok(())
    })
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
/// positions_at(&[[0.0, 0.0]], &[[2.0, 0.0]], PerPair::All(0.5), PerPair::All(10.0), &mut out, Threads::All)?;
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
    let n = out.len();
    check_len("pos", pos.len(), n)?;
    check_len("vel", vel.len(), n)?;
    friction.check_len("friction", n)?;
    t.check_len("t", n)?;
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
fn pair_time(pairs: &Pairs<'_>, i: usize) -> Result<Option<f64>, InputError> {
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
    let radius = check_radius("radius", pairs.radius.get(i))?;
    let t_max = check_horizon("t_max", pairs.t_max.get(i))?;
    Ok(first_contact(&a, &b, radius, t_max))
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

fn check_lengths(pairs: &Pairs<'_>, n: usize) -> Result<(), InputError> {
    check_len("pos_a", pairs.pos_a.len(), n)?;
    check_len("vel_a", pairs.vel_a.len(), n)?;
    pairs.friction_a.check_len("friction_a", n)?;
    check_len("pos_b", pairs.pos_b.len(), n)?;
    check_len("vel_b", pairs.vel_b.len(), n)?;
    pairs.friction_b.check_len("friction_b", n)?;
    pairs.radius.check_len("radius", n)?;
    pairs.t_max.check_len("t_max", n)
}

fn check_len(argument: &'static str, len: usize, n: usize) -> Result<(), InputError> {
    if len == n {
        Ok(())
    } else {
        Err(length_mismatch(argument, n, len))
    }
}

fn length_mismatch(argument: &'static str, expected: usize, found: usize) -> InputError {
    InputError::new(argument, InputErrorKind::LengthMismatch { expected, found })
}

/// Runs `work(offset, chunk)` over `out` in chunks, on the requested threads, and returns the
/// error of the lowest index if any chunk failed (each chunk stops at its first error).
fn run_chunks<T: Send>(
    out: &mut [T],
    threads: Threads,
    work: impl Fn(usize, &mut [T]) -> Result<(), InputError> + Sync,
) -> Result<(), InputError> {
    let parallel = |out: &mut [T]| {
        out.par_chunks_mut(CHUNK)
            .enumerate()
            .map(|(c, chunk)| work(c * CHUNK, chunk))
            .reduce(|| Ok(()), first_error)
    };
    match threads {
        Threads::AtMost(n) if n.get() == 1 => work(0, out),
        Threads::All => parallel(out),
        Threads::AtMost(n) => match rayon::ThreadPoolBuilder::new().num_threads(n.get()).build() {
            Ok(pool) => pool.install(|| parallel(out)),
            // No thread could be started: the calling thread does the work.
            Err(_) => work(0, out),
        },
    }
}

/// Of two chunk results, the error with the lower index (chunks may finish in any order).
fn first_error(x: Result<(), InputError>, y: Result<(), InputError>) -> Result<(), InputError> {
    match (x, y) {
        (Err(a), Err(b)) => Err(if b.index() < a.index() { b } else { a }),
        (Err(e), Ok(())) | (Ok(()), Err(e)) => Err(e),
        (Ok(()), Ok(())) => Ok(()),
    }
}
