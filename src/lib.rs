//! # ballcollide
//!
//! When do two balls slowing under friction first touch? Each ball moves on a straight line,
//! decelerated by a constant friction until it stops; the gap between two such balls is a
//! quartic in time on each window between stop times, and the collision is its first
//! entry root. This crate computes it exactly (to the float64 floor), fast, and for
//! millions of pairs.
//!
//! - [`Ball`] ([`motion`]): one ball's state and trajectory;
//! - [`Gap`] ([`gap`]): the relative motion of two balls and its gap quartic;
//! - [`collision_time`] ([`collision`]): the first contact of two balls;
//! - [`Path`] ([`path`]): general motion, paths of constant-acceleration segments in 2-D and 3-D;
//! - [`geometry`]: static objects (segments, circles, targets, planes) and when a ball on a
//!   path first touches one;
//! - [`poly`]: real-root solvers for polynomials of degree ≤ 4;
//! - [`billiards`]: billiard balls with pooltool's physics: sliding, rolling and spinning, as
//!   paths;
//! - [`scene`]: many balls at once: earliest collisions, with a broad phase;
//! - [`schedule`]: an event calendar: the next collision among N balls, kept up to date.
//!
//! ```
//! use ballcollide::{Ball, collision_time};
//! use nalgebra::Vector2;
//!
//! let a = Ball::new(Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), 0.0)?;
//! let b = Ball::at_rest(Vector2::new(1.0, 0.0))?;
//! assert_eq!(collision_time(&a, &b, 0.5)?, Some(0.5));
//! # Ok::<(), ballcollide::InputError>(())
//! ```
#![warn(missing_docs)]

pub mod batch;
pub mod billiards;
pub mod collision;
pub mod error;
pub mod gap;
pub mod geometry;
pub mod interrupt;
pub mod motion;
pub mod path;
pub mod poly;
mod prefetch;
#[cfg(feature = "python")]
mod python;
pub mod scene;
pub mod schedule;
pub mod simd;

/// The old name of [`gap`], kept so that code written against it still builds.
///
/// ```
/// #![allow(deprecated)]
/// use ballcollide::Ball;
/// use nalgebra::Vector2;
///
/// let a = Ball::at_rest(Vector2::new(0.0, 0.0))?;
/// let b = Ball::at_rest(Vector2::new(2.0, 0.0))?;
/// let gap: ballcollide::coefficients::Gap = ballcollide::gap::Gap::between(&a, &b, 1.0, 0.0);
/// assert_eq!(gap.value(0.0), 3.0);
/// # Ok::<(), ballcollide::InputError>(())
/// ```
#[deprecated(note = "renamed to `gap` (it holds `Gap`)")]
pub mod coefficients {
    pub use crate::gap::Gap;
}

pub use collision::{CollisionOptions, collision_time, collision_time_with, path_collision_time};
pub use error::{InputError, InputErrorKind};
pub use gap::Gap;
pub use motion::Ball;
pub use path::{Path, Path2, Path3, Segment, Segment2, Segment3};

/// The property tests' case counts (the fast tier's, raised to `PROPTEST_CASES` if set).
#[cfg(test)]
#[path = "../tests/support/cases.rs"]
mod test_cases;
/// The tests' random path rows (`super::rng` there: the generator above).
#[cfg(test)]
#[path = "../tests/support/path_rows.rs"]
mod test_path_rows;
/// The tests' and benchmarks' shared deterministic generator.
#[cfg(test)]
#[path = "../tests/support/rng.rs"]
mod test_rng;
#[cfg(test)]
use test_rng as rng;
