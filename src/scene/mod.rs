//! Many balls at once: which pairs touch, and which touch first.
//!
//! A simulator asks, after every event, which of its N balls collide first. Each query here
//! takes the balls ([`Ball`]) and one radius per ball; a pair collides when its centres come
//! within the sum of its two radii, at the time [`collision_time`](crate::collision_time)
//! gives for it:
//!
//! - [`pairwise_collision_times`]: the full `N × N` matrix of collision times;
//! - [`earliest_collision`]: the first collision of the scene and its pair `(i, j)`;
//! - [`first_contacts`]: for each ball, its first collision and its partner.
//!
//! ## Broad phase
//!
//! Comparing all `N(N−1)/2` pairs is what a simple simulator does. Here each ball's centre
//! is known to stay on a straight segment (to its rest point under friction, to the horizon
//! `t_max` or for ever when frictionless, a point at rest), so its swept bounding box, grown by
//! its radius and a rigorous rounding margin, contains everything the ball can touch. The
//! narrow axis of the scene is cut into strips about as high as a typical box, and a
//! sort-and-sweep along the wide axis within each strip finds the pairs whose boxes overlap
//! (about `N log N` work on a table of constant density); only those go to the exact pair
//! kernel, in parallel (rayon).
//!
//! ## Guarantees
//!
//! - The answers are those of the brute-force all-pairs computation, bit for bit: pair
//!   `(i, j)` with `i < j` is always evaluated as `collision_time(balls[i], balls[j],
//!   radii[i] + radii[j])` (with the horizon), whether or not the broad phase is used and
//!   whatever the number of threads.
//! - Ties are broken by the lowest `i`, then the lowest `j` ([`earliest_collision`]), and by
//!   the lowest partner index ([`first_contacts`]).
//! - Bad input is an [`InputError`] naming the argument and the first offending index, e.g.
//!   ``radius[3]: a ball's radius must be > 0, got -1``.
//!
//! ```
//! use ballcollide::Ball;
//! use ballcollide::scene::{SceneOptions, earliest_collision, first_contacts};
//! use nalgebra::Vector2;
//!
//! // A cue ball rolling at 1 m/s (no friction) towards two balls at rest.
//! let balls = [
//!     Ball::new(Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), 0.0)?,
//!     Ball::at_rest(Vector2::new(1.0, 0.0))?,
//!     Ball::at_rest(Vector2::new(3.0, 0.0))?,
//! ];
//! let radii = [0.25; 3];
//! let options = SceneOptions::default();
//! assert_eq!(earliest_collision(&balls, &radii, &options)?, Some((0.5, 0, 1)));
//! let (times, partners) = first_contacts(&balls, &radii, &options)?;
//! assert_eq!(times, [0.5, 0.5, 2.5]); // ball 0 would reach ball 2 at 2.5 s if 1 weren't there
//! assert_eq!(partners, [Some(1), Some(0), Some(0)]);
//! # Ok::<(), ballcollide::InputError>(())
//! ```

mod broad_phase;

use std::num::NonZeroUsize;

use nalgebra::Vector2;
use rayon::prelude::*;

use crate::interrupt::Interrupt;

use crate::batch::{PerPair, Threads};
use crate::collision::first_contact_screened;
use crate::error::{InputError, InputErrorKind, check_ball_radius, check_horizon};
use crate::motion::{Ball, row_error};
use broad_phase::Sweep;

/// Options of a scene query.
///
/// ```
/// use ballcollide::scene::{PairSearch, SceneOptions};
/// let options = SceneOptions { t_max: 2.0, ..Default::default() };
/// assert_eq!(options.search, PairSearch::BroadPhase);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneOptions {
    /// The horizon: a collision at `t ≥ t_max` is reported as none. Default `∞`. A finite
    /// horizon also shortens the swept boxes of frictionless balls (and of slow stoppers).
    pub t_max: f64,
    /// How many threads may be used. The answers do not depend on it.
    pub threads: Threads,
    /// How candidate pairs are found. The answers do not depend on it.
    pub search: PairSearch,
}

impl Default for SceneOptions {
    fn default() -> Self {
        Self {
            t_max: f64::INFINITY,
            threads: Threads::All,
            search: PairSearch::BroadPhase,
        }
    }
}

/// How a scene query chooses the pairs that go to the exact pair kernel.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum PairSearch {
    /// Swept bounding boxes and a sort-and-sweep (default): about `N log N` plus the pairs
    /// whose boxes overlap.
    #[default]
    BroadPhase,
    /// Every one of the `N(N−1)/2` pairs: the reference the broad phase must equal, and the
    /// baseline of the benchmarks.
    AllPairs,
}

/// The balls of a scene from rows of numbers (the layout numpy hands over): ball `i` at
/// `pos[i]` with velocity `vel[i]` and friction deceleration `friction` (one for all, or one
/// per ball).
///
/// # Errors
/// An [`InputError`] naming `pos`, `vel` or `friction` and the first bad index: non-finite
/// numbers, a negative friction, or a length that differs from `pos`'s.
///
/// ```
/// use ballcollide::batch::PerPair;
/// use ballcollide::scene::balls;
///
/// let b = balls(&[[0.0, 0.0], [1.0, 0.0]], &[[1.0, 0.0], [0.0, 0.0]], PerPair::All(0.2))?;
/// assert_eq!(b[0].stop_time(), 5.0);
/// let err = balls(&[[0.0, 0.0]], &[[1.0, 0.0]], PerPair::Each(&[-0.1])).unwrap_err();
/// assert_eq!(err.to_string(), "friction[0]: friction must be ≥ 0, got -0.1");
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn balls(
    pos: &[[f64; 2]],
    vel: &[[f64; 2]],
    friction: PerPair<'_>,
) -> Result<Vec<Ball>, InputError> {
    let n = pos.len();
    check_len("vel", vel.len(), n)?;
    if let PerPair::Each(f) = friction {
        check_len("friction", f.len(), n)?;
    }
    (0..n)
        .map(|i| {
            Ball::new(
                Vector2::from(pos[i]),
                Vector2::from(vel[i]),
                friction.get(i),
            )
            .map_err(|e| row_error(e, i))
        })
        .collect()
}

/// The collision time of every pair, as a row-major `N × N` matrix: entry `i·N + j` is the
/// time at which balls `i` and `j` first touch, `∞` if they do not before `t_max`, and `∞` on
/// the diagonal. The matrix is symmetric (each pair is evaluated once, as `i < j`).
///
/// It holds `N²` numbers: for large scenes, prefer [`earliest_collision`] or
/// [`first_contacts`], which only keep what they return. (Like any `Vec`, a matrix that does
/// not fit in memory aborts the allocation; the Python binding checks first and raises
/// `MemoryError`.)
///
/// # Errors
/// `radii` must have one radius per ball, each finite and `> 0` (a sum of two radii may
/// exceed `f64::MAX`: the pair search forms it in the pair's own unit of length); `t_max ≥ 0`.
/// The error names `radius` and the first bad index, or `t_max`.
///
/// ```
/// use ballcollide::Ball;
/// use ballcollide::scene::{SceneOptions, pairwise_collision_times};
/// use nalgebra::Vector2;
///
/// let balls = [
///     Ball::new(Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), 0.0)?,
///     Ball::at_rest(Vector2::new(1.0, 0.0))?,
/// ];
/// let times = pairwise_collision_times(&balls, &[0.2, 0.3], &SceneOptions::default())?;
/// assert_eq!(times, [f64::INFINITY, 0.5, 0.5, f64::INFINITY]);
///
/// let err = pairwise_collision_times(&balls, &[0.2, -0.3], &SceneOptions::default());
/// assert_eq!(err.unwrap_err().to_string(), "radius[1]: a ball's radius must be > 0, got -0.3");
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn pairwise_collision_times(
    balls: &[Ball],
    radii: &[f64],
    options: &SceneOptions,
) -> Result<Vec<f64>, InputError> {
    let n = balls.len();
    let hits = hits(balls, radii, options)?;
    // N² saturates where it would overflow (more than 2³² balls): the allocation then fails.
    let mut times = vec![f64::INFINITY; n.saturating_mul(n)];
    for Hit { time, i, j } in hits {
        times[i * n + j] = time;
        times[j * n + i] = time;
    }
    Ok(times)
}

/// The first collision of the scene: `Some((t, i, j))` with `i < j`, or `None` if no two balls
/// touch before `t_max`. Of several pairs colliding at the same time, the lowest `i` wins, then
/// the lowest `j`.
///
/// # Errors
/// As [`pairwise_collision_times`].
///
/// ```
/// use ballcollide::Ball;
/// use ballcollide::scene::{SceneOptions, earliest_collision};
/// use nalgebra::Vector2;
///
/// // Two balls rolling at each other (slowed at 0.5 m/s²), a third one far away.
/// let balls = [
///     Ball::new(Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), 0.5)?,
///     Ball::at_rest(Vector2::new(5.0, 5.0))?,
///     Ball::new(Vector2::new(1.0, 0.0), Vector2::new(-1.0, 0.0), 0.5)?,
/// ];
/// let (t, i, j) = earliest_collision(&balls, &[0.1; 3], &SceneOptions::default())?.unwrap();
/// assert_eq!((i, j), (0, 2));
/// assert!((t - (2.0 - 2.4_f64.sqrt())).abs() < 1e-15); // 1 − 2(t − t²/4) = 0.2
///
/// let soon = SceneOptions { t_max: 0.1, ..Default::default() };
/// assert_eq!(earliest_collision(&balls, &[0.1; 3], &soon)?, None);
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn earliest_collision(
    balls: &[Ball],
    radii: &[f64],
    options: &SceneOptions,
) -> Result<Option<(f64, usize, usize)>, InputError> {
    let hits = hits(balls, radii, options)?;
    Ok(hits
        .into_iter()
        .min_by(Hit::order)
        .map(|h| (h.time, h.i, h.j)))
}

/// For each ball, its first collision: `(times, partners)`, where ball `i` first touches ball
/// `partners[i]` at `times[i]` (`∞` and `None` if it touches none before `t_max`). Of several
/// partners at the same time, the lowest index wins.
///
/// Each ball's answer ignores the other balls' collisions: it is the first of its pair
/// times, as if nothing else happened (a simulator re-asks after each event).
///
/// # Errors
/// As [`pairwise_collision_times`].
///
/// ```
/// use ballcollide::Ball;
/// use ballcollide::scene::{SceneOptions, first_contacts};
/// use nalgebra::Vector2;
///
/// let balls = [
///     Ball::new(Vector2::new(0.0, 0.0), Vector2::new(0.0, 1.0), 0.0)?,
///     Ball::at_rest(Vector2::new(0.0, 2.0))?,
///     Ball::at_rest(Vector2::new(9.0, 9.0))?,
/// ];
/// let (times, partners) = first_contacts(&balls, &[0.5; 3], &SceneOptions::default())?;
/// assert_eq!(times, [1.0, 1.0, f64::INFINITY]);
/// assert_eq!(partners, [Some(1), Some(0), None]);
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn first_contacts(
    balls: &[Ball],
    radii: &[f64],
    options: &SceneOptions,
) -> Result<(Vec<f64>, Vec<Option<usize>>), InputError> {
    let n = balls.len();
    let hits = hits(balls, radii, options)?;
    let mut best: Vec<Option<(f64, usize)>> = vec![None; n];
    for Hit { time, i, j } in hits {
        for (me, partner) in [(i, j), (j, i)] {
            let better = match best[me] {
                None => true,
                Some((t, p)) => time < t || (time == t && partner < p),
            };
            if better {
                best[me] = Some((time, partner));
            }
        }
    }
    Ok(best
        .into_iter()
        .map(|b| b.map_or((f64::INFINITY, None), |(t, p)| (t, Some(p))))
        .unzip())
}

/// The number of pairs the broad phase keeps for the exact kernel (those whose swept boxes
/// overlap), out of `N(N−1)/2`: a measure of how much it prunes.
///
/// # Errors
/// As [`pairwise_collision_times`].
///
/// ```
/// use ballcollide::Ball;
/// use ballcollide::scene::candidate_pairs;
/// use nalgebra::Vector2;
///
/// let balls: Vec<Ball> = (0..10)
///     .map(|k| Ball::at_rest(Vector2::new(k as f64, 0.0)))
///     .collect::<Result<_, _>>()?;
/// // Balls at rest 1 m apart with radius 0.25: no box overlaps another.
/// assert_eq!(candidate_pairs(&balls, &[0.25; 10], f64::INFINITY)?, 0);
/// // Radius 0.6: neighbours' boxes overlap.
/// assert_eq!(candidate_pairs(&balls, &[0.6; 10], f64::INFINITY)?, 9);
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn candidate_pairs(balls: &[Ball], radii: &[f64], t_max: f64) -> Result<usize, InputError> {
    check(balls, radii, t_max)?;
    let sweep = Sweep::new(balls, radii, t_max, true);
    let mut count = 0;
    for rank in 0..sweep.len() {
        sweep.for_each_after(rank, |_, _| count += 1);
    }
    Ok(count)
}

/// A colliding pair, `i < j`.
#[derive(Clone, Copy, Debug)]
struct Hit {
    time: f64,
    i: usize,
    j: usize,
}

impl Hit {
    /// Earliest first, then lowest `i`, then lowest `j` (times are never NaN).
    fn order(a: &Self, b: &Self) -> std::cmp::Ordering {
        a.time
            .total_cmp(&b.time)
            .then(a.i.cmp(&b.i))
            .then(a.j.cmp(&b.j))
    }
}

/// Below this many balls (or with one thread), the work stays on the calling thread.
const PARALLEL_FROM: usize = 64;

/// Every colliding pair (in no particular order).
fn hits(balls: &[Ball], radii: &[f64], options: &SceneOptions) -> Result<Vec<Hit>, InputError> {
    let t_max = options.t_max;
    check(balls, radii, t_max)?;
    let n = balls.len();
    let kernel =
        |i: usize, j: usize| {
            first_contact_screened(&balls[i], &balls[j], [radii[i], radii[j]], t_max)
                .map(|time| Hit { time, i, j })
        };
    // The broad phase numbers balls in 32 bits; beyond that (never in memory today), all pairs.
    let search = if u32::try_from(n).is_ok() {
        options.search
    } else {
        PairSearch::AllPairs
    };
    let serial = n < PARALLEL_FROM || options.threads == Threads::AtMost(NonZeroUsize::MIN);
    // Each row first looks at the caller's flag: once it is set, the rows left find nothing
    // and the call fails below.
    let interrupt = Interrupt::current();
    let running = || interrupt.check().is_ok();
    let run = || -> Vec<Hit> {
        match search {
            PairSearch::AllPairs => {
                let row = |i: usize| -> Vec<Hit> {
                    if !running() {
                        return Vec::new();
                    }
                    (i + 1..n).filter_map(|j| kernel(i, j)).collect()
                };
                if serial {
                    (0..n).flat_map(row).collect()
                } else {
                    (0..n).into_par_iter().flat_map_iter(row).collect()
                }
            }
            PairSearch::BroadPhase => {
                let sweep = Sweep::new(balls, radii, t_max, !serial);
                let row = |rank: usize| -> Vec<Hit> {
                    let mut out = Vec::new();
                    if running() {
                        sweep.for_each_after(rank, |i, j| out.extend(kernel(i, j)));
                    }
                    out
                };
                // A box crossing several strips has several ranks.
                let ranks = sweep.len();
                if serial {
                    (0..ranks).flat_map(row).collect()
                } else {
                    (0..ranks).into_par_iter().flat_map_iter(row).collect()
                }
            }
        }
    };
    let hits = match options.threads {
        Threads::AtMost(k) if !serial => {
            match rayon::ThreadPoolBuilder::new().num_threads(k.get()).build() {
                Ok(pool) => pool.install(run),
                // No thread could be started: the global pool gives the same answers.
                Err(_) => run(),
            }
        }
        _ => run(),
    };
    interrupt.check()?;
    Ok(hits)
}

/// Validates the radii (one per ball, finite, `> 0`) and the horizon.
fn check(balls: &[Ball], radii: &[f64], t_max: f64) -> Result<(), InputError> {
    check_len("radius", radii.len(), balls.len())?;
    for (i, &r) in radii.iter().enumerate() {
        check_ball_radius("radius", r).map_err(|e| e.at(i))?;
    }
    check_horizon("t_max", t_max)?;
    Ok(())
}

fn check_len(argument: &'static str, len: usize, n: usize) -> Result<(), InputError> {
    if len == n {
        Ok(())
    } else {
        Err(InputError::new(
            argument,
            InputErrorKind::LengthMismatch {
                expected: n,
                found: len,
            },
        ))
    }
}
