//! When the centre of a ball on a path first enters a [`Target`]:
//! [`path_target_contact`].
//!
//! As for a circle (`path_circle_contact.rs`), the target is a ball at rest and the pair
//! search of two paths answers, at contact distance `ρ` (the ball's own radius plays no part).

use super::shapes::Target;
use crate::CollisionOptions;
use crate::collision::path_contact::first_contact_of_paths;
use crate::error::{InputError, check_horizon};
use crate::path::{Path, Segment};

/// The first time (absolute, as the path's starts are) at which the centre of a ball on
/// `path` enters `target` (comes within `ρ` of its centre), searched from the path's first
/// start; `None` if it does not before `options.t_max`. The ball's radius plays no part: a
/// pocket captures a ball whose centre crosses its capture circle.
///
/// The semantics are those of two balls ([`path_collision_time`](crate::path_collision_time))
/// at contact distance `ρ`: a centre on or within the disc at the first start enters at once
/// only if it moves inwards; a jump into the disc at a later segment start enters there;
/// touching the circle and leaving it is no entry.
///
/// # Errors
/// `t_max ≥ 0` (`∞` allowed).
///
/// ```
/// use ballcollide::geometry::{Target, path_target_contact};
/// use ballcollide::path::{Path2, Segment2};
/// use ballcollide::CollisionOptions;
/// use nalgebra::Vector2;
///
/// // A pocket's capture circle of radius 0.5 at (3, 0); a ball rolls at it along y = 0,
/// // slowed at 0.5 m/s² from 2 m/s.
/// let pocket = Target::new(Vector2::new(3.0, 0.0), 0.5)?;
/// let path = Path2::new(vec![
///     Segment2::new(0.0, Vector2::zeros(), Vector2::new(2.0, 0.0), Vector2::new(-0.5, 0.0)),
///     Segment2::at_rest(4.0, Vector2::new(4.0, 0.0)),
/// ])?;
/// // 2t − t²/4 = 2.5: t = 4 − √6.
/// let t = path_target_contact(&path, &pocket, &CollisionOptions::default())?.expect("captured");
/// assert!((t - (4.0 - 6f64.sqrt())).abs() < 1e-15);
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn path_target_contact<const D: usize>(
    path: &Path<D>,
    target: &Target<D>,
    options: &CollisionOptions,
) -> Result<Option<f64>, InputError> {
    let t_max = check_horizon("t_max", options.t_max)?;
    Ok(first_target_contact(path.segments(), target, t_max))
}

/// [`path_target_contact`] on validated inputs.
pub(crate) fn first_target_contact<const D: usize>(
    segments: &[Segment<D>],
    target: &Target<D>,
    t_max: f64,
) -> Option<f64> {
    let start = segments.first()?.start;
    let centre = [Segment::at_rest(start, target.centre())];
    first_contact_of_paths(segments, &centre, [target.rho(), 0.0], t_max, true)
}
