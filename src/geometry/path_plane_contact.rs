//! When a ball on a path first comes down onto a [`Plane`]: [`path_plane_contact`].
//!
//! The centre's height above the plane times `|n|` is `n·(x − Q)`, and the ball touches it
//! where that is `r·|n|`: on each segment of the path `n·(x − Q) − r·|n|` is a quadratic in
//! time, and the walk of [`first_entry`](super::signed_distance::first_entry) (the calendar's
//! box walls take the same one, for planes whose normals are axes) finds its first entry.
//! The normal is first brought to its own power of two and every length to the query's
//! (exact), so no answer depends on the units.

use super::shapes::Plane;
use super::signed_distance::{Quadratic, dot, first_entry, largest_in_path};
use crate::CollisionOptions;
use crate::collision::length_unit::{LengthUnit, largest};
use crate::error::{InputError, check_ball_radius, check_horizon};
use crate::path::{Path, Segment};

/// The first time (absolute, as the path's starts are) at which a ball of `radius` on `path`
/// comes down onto `plane`, the signed distance `n·(x − Q)/|n|` of its centre falling to
/// `radius`, searched from the path's first start; `None` if it does not before
/// `options.t_max`.
///
/// As for two balls: on or beyond the plane at the first start (the distance `≤ radius`) is a
/// contact only if the ball moves towards it (the first non-zero derivative of the distance
/// is negative); a path that jumps from above to on or beyond it at a later segment start
/// touches at that start; grazing the plane (the distance coming down to `radius` and going
/// up again) is no contact. In 2-D the plane is a line touched from the side its normal
/// points to.
///
/// # Errors
/// `radius` must be finite and positive, `t_max ≥ 0` (`∞` allowed).
///
/// ```
/// use ballcollide::geometry::{Plane, path_plane_contact};
/// use ballcollide::path::{Path3, Segment3};
/// use ballcollide::CollisionOptions;
/// use nalgebra::Vector3;
///
/// // The table's bed (z = 0, its normal of any length); a ball of radius 0.1 leaves z = 1
/// // at 1 m/s along x and falls under 10 m/s²: it lands when 1 − 5t² = 0.1.
/// let bed = Plane::new(Vector3::zeros(), Vector3::new(0.0, 0.0, 2.0))?;
/// let gravity = Vector3::new(0.0, 0.0, -10.0);
/// let path = Path3::new(vec![Segment3::new(0.0, Vector3::new(0.0, 0.0, 1.0), Vector3::x(), gravity)])?;
/// let t = path_plane_contact(&path, &bed, 0.1, &CollisionOptions::default())?.expect("it lands");
/// assert!((t - 0.18f64.sqrt()).abs() < 1e-15);
/// // A ceiling at z = 2 (its normal pointing down): the ball falls away from it, never.
/// let ceiling = Plane::new(Vector3::new(0.0, 0.0, 2.0), Vector3::new(0.0, 0.0, -1.0))?;
/// assert_eq!(path_plane_contact(&path, &ceiling, 0.1, &CollisionOptions::default())?, None);
/// // Beyond a plane and moving deeper is a contact at once (as overlapping balls that
/// // approach): the bed seen from below.
/// let from_below = Plane::new(Vector3::new(0.0, 0.0, 2.0), Vector3::new(0.0, 0.0, 1.0))?;
/// assert_eq!(path_plane_contact(&path, &from_below, 0.1, &CollisionOptions::default())?, Some(0.0));
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn path_plane_contact<const D: usize>(
    path: &Path<D>,
    plane: &Plane<D>,
    radius: f64,
    options: &CollisionOptions,
) -> Result<Option<f64>, InputError> {
    let radius = check_ball_radius("radius", radius)?;
    let t_max = check_horizon("t_max", options.t_max)?;
    Ok(first_plane_contact(path.segments(), plane, radius, t_max))
}

/// [`path_plane_contact`] on validated inputs.
pub(crate) fn first_plane_contact<const D: usize>(
    segments: &[Segment<D>],
    plane: &Plane<D>,
    radius: f64,
    t_max: f64,
) -> Option<f64> {
    let normal = plane.normal();
    let normal_unit = LengthUnit::of(largest(normal.into()));
    let n = normal.map(|x| normal_unit.apply(x));
    let unit = LengthUnit::of(largest([
        largest_in_path(segments),
        largest(plane.point().into()),
        radius,
    ]));
    let point = plane.point().map(|x| unit.apply(x));
    let height = unit.apply(radius) * dot(&n, &n).sqrt();
    first_entry(
        segments,
        t_max,
        |segment| {
            let offset = segment.position.map(|x| unit.apply(x)) - point;
            let velocity = segment.velocity.map(|x| unit.apply(x));
            let acceleration = segment.acceleration.map(|x| unit.apply(x));
            let f = Quadratic {
                c: dot(&n, &offset) - height,
                b: dot(&n, &velocity),
                q: 0.5 * dot(&n, &acceleration),
            };
            ([f], ())
        },
        |_, _, _| true,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Vector2, Vector3};

    const INF: f64 = f64::INFINITY;

    fn plane3(point: [f64; 3], normal: [f64; 3]) -> Plane<3> {
        Plane::new(point.into(), normal.into()).expect("a valid plane")
    }

    #[test]
    fn a_landing_at_a_segment_start_counts_only_if_the_ball_then_moves_into_the_plane() {
        // Falls from z = 5.5 under 10 and reaches z = r = 0.5 at 1, where its next segment
        // starts: bouncing up (the contact resolved by the caller), the next landing is at 3;
        // going on down, the landing is at 1.
        let g = Vector3::new(0.0, 0.0, -10.0);
        let fall = Segment::new(0.0, Vector3::new(0.0, 0.0, 5.5), Vector3::zeros(), g);
        let at = Vector3::new(0.0, 0.0, 0.5);
        let bounce = vec![fall, Segment::new(1.0, at, Vector3::new(0.0, 0.0, 10.0), g)];
        let through = vec![
            fall,
            Segment::new(1.0, at, Vector3::new(0.0, 0.0, -10.0), g),
        ];
        let bed = plane3([0.0; 3], [0.0, 0.0, 1.0]);
        assert_eq!(first_plane_contact(&bounce, &bed, 0.5, INF), Some(3.0));
        assert_eq!(first_plane_contact(&through, &bed, 0.5, INF), Some(1.0));
        // From the bounce on: on the plane, moving away: the next landing, 2 s later.
        assert_eq!(first_plane_contact(&bounce[1..], &bed, 0.5, INF), Some(3.0));
        assert_eq!(first_plane_contact(&bounce[1..], &bed, 0.5, 3.0), None);
    }

    #[test]
    fn a_contact_at_a_first_start_of_minus_zero_is_at_plus_zero() {
        // Beyond the line x = 0 (touched from x > 0) and moving deeper, from t = −0: a
        // contact at once, at +0 (found by the invariants of tests/integration/invariants_geometry.rs).
        let path = vec![Segment::new(
            -0.0,
            Vector2::zeros(),
            Vector2::zeros(),
            Vector2::new(-1.0, 0.0),
        )];
        let line = Plane::new(Vector2::new(1.0, 0.0), Vector2::new(1.0, 0.0)).expect("valid");
        let t = first_plane_contact(&path, &line, 0.5, INF).expect("at once");
        assert_eq!(t.to_bits(), 0.0f64.to_bits());
    }

    #[test]
    fn the_normal_s_length_and_the_units_change_no_bit() {
        let path = vec![Segment::new(
            0.25,
            Vector2::new(0.3, 0.7),
            Vector2::new(-0.9, 0.4),
            Vector2::new(0.1, -0.35),
        )];
        let plane = |n: [f64; 2]| Plane::new(Vector2::new(-0.2, 0.1), n.into()).expect("valid");
        let t = first_plane_contact(&path, &plane([1.0, 0.5]), 0.125, INF).expect("a contact");
        for k in [-1000, -3, 7, 1000] {
            let f = 2f64.powi(k);
            let got = first_plane_contact(&path, &plane([f, 0.5 * f]), 0.125, INF);
            assert_eq!(got, Some(t), "2^{k}");
        }
        let scaled: Vec<_> = path
            .iter()
            .map(|s| {
                let f = 2f64.powi(-600);
                Segment::new(s.start, s.position * f, s.velocity * f, s.acceleration * f)
            })
            .collect();
        let f = 2f64.powi(-600);
        let small = Plane::new(Vector2::new(-0.2, 0.1) * f, Vector2::new(1.0, 0.5)).expect("valid");
        assert_eq!(
            first_plane_contact(&scaled, &small, 0.125 * f, INF),
            Some(t)
        );
    }
}
