//! General motion: paths of constant-acceleration segments, in 2-D and 3-D.
//!
//! A [`Path`] is a sequence of [`Segment`]s `(s_k, p_k, v_k, a_k)` with non-decreasing
//! absolute starts; on `[s_k, s_{k+1})` the centre is `p_k + v_k·(t − s_k) + ½·a_k·(t − s_k)²`,
//! and the last segment lasts for ever. It covers a billiard ball sliding (on a curve), rolling
//! and at rest, a ball in the air, a particle bouncing in a box; the friction [`Ball`] is the
//! two-segment case ([`Ball::path`]).
//!
//! - [`Segment`] (`segment.rs`): one piece, and its formula in time relative to its start;
//! - [`Path`] (`piecewise.rs`): checked construction ([`Path::new`]), the spans where each
//!   segment is active ([`Path::spans`]), the active segment at a time, positions and
//!   velocities;
//! - [`Path::from_rows`] (`rows.rs`): a path from rows of the batch arrays, with their `+∞`
//!   padding;
//! - [`Ball::path`] (`from_ball.rs`): the friction ball as a path;
//! - [`FrictionPath`] (`friction_path.rs`): the friction ball as a path from a given time, in
//!   a calendar's dimension.
//!
//! ```
//! use ballcollide::path::{Path3, Segment3};
//! use nalgebra::Vector3;
//!
//! // A ball leaves the cloth at 1 m/s up and 2 m/s along x, and lands 0.2 s later.
//! let g = Vector3::new(0.0, 0.0, -10.0);
//! let path = Path3::new(vec![
//!     Segment3::new(0.0, Vector3::zeros(), Vector3::new(2.0, 0.0, 1.0), g),
//!     Segment3::new(0.2, Vector3::new(0.4, 0.0, 0.0), Vector3::x() * 2.0, Vector3::zeros()),
//! ])?;
//! assert_eq!(path.position_at(0.1), Vector3::new(0.2, 0.0, 0.05)); // the top of the hop
//! assert_eq!(path.position_at(0.7), Vector3::new(1.4, 0.0, 0.0));
//! # Ok::<(), ballcollide::InputError>(())
//! ```
//!
//! [`Ball`]: crate::Ball
//! [`Ball::path`]: crate::Ball::path

mod friction_path;
mod from_ball;
mod piecewise;
mod rows;
mod segment;

pub use friction_path::FrictionPath;
pub(crate) use piecewise::{Names, locate, spans};
pub use piecewise::{Path, Path2, Path3};
pub(crate) use rows::segments_from_rows;
pub use segment::{Segment, Segment2, Segment3};
