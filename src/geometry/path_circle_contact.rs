//! When a ball on a path first touches a [`Circle`] from outside: [`path_circle_contact`].
//!
//! The circle is a ball at rest: a path of one segment at its centre, from the path's first
//! start on, at contact distance `ρ + r`; the pair search of two paths
//! ([`path_collision_time`](crate::path_collision_time)) answers, with its screens, its window
//! search and its accuracy, and no search of its own.

use super::shapes::Circle;
use crate::CollisionOptions;
use crate::collision::path_contact::first_contact_of_paths;
use crate::error::{InputError, check_ball_radius, check_horizon};
use crate::path::{Path, Segment};

/// The first time (absolute, as the path's starts are) at which a ball of `radius` on `path`
/// starts to touch `circle` from outside, its centre coming within `ρ + radius` of the
/// circle's centre, searched from the path's first start; `None` if it does not before
/// `options.t_max`.
///
/// The semantics are those of two balls ([`path_collision_time`](crate::path_collision_time)),
/// the circle being one at rest: touching or overlapping at the first start is a contact only
/// if the ball approaches; a jump into overlap at a later segment start is a contact there;
/// exact tangency is none. In 3-D the circle is a sphere.
///
/// # Errors
/// `radius` must be finite and positive, `t_max ≥ 0` (`∞` allowed).
///
/// ```
/// use ballcollide::geometry::{Circle, path_circle_contact};
/// use ballcollide::path::{Path2, Segment2};
/// use ballcollide::CollisionOptions;
/// use nalgebra::Vector2;
///
/// // A jaw's rounded tip of radius 0.25 at (2, 0); a ball of radius 0.5 rolls at it along y = 0.
/// let tip = Circle::new(Vector2::new(2.0, 0.0), 0.25)?;
/// let path = Path2::new(vec![Segment2::new(0.0, Vector2::zeros(), Vector2::new(1.0, 0.0), Vector2::zeros())])?;
/// let options = CollisionOptions::default();
/// assert_eq!(path_circle_contact(&path, &tip, 0.5, &options)?, Some(1.25)); // 2 − 0.75
/// // A point (ρ = 0), a segment's end: the ball's own radius.
/// let end = Circle::new(Vector2::new(2.0, 0.0), 0.0)?;
/// assert_eq!(path_circle_contact(&path, &end, 0.5, &options)?, Some(1.5));
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn path_circle_contact<const D: usize>(
    path: &Path<D>,
    circle: &Circle<D>,
    radius: f64,
    options: &CollisionOptions,
) -> Result<Option<f64>, InputError> {
    let radius = check_ball_radius("radius", radius)?;
    let t_max = check_horizon("t_max", options.t_max)?;
    Ok(first_circle_contact(path.segments(), circle, radius, t_max))
}

/// [`path_circle_contact`] on validated inputs.
pub(crate) fn first_circle_contact<const D: usize>(
    segments: &[Segment<D>],
    circle: &Circle<D>,
    radius: f64,
    t_max: f64,
) -> Option<f64> {
    let start = segments.first()?.start;
    let centre = [Segment::at_rest(start, circle.centre())];
    first_contact_of_paths(segments, &centre, [radius, circle.rho()], t_max, true)
}
