//! The second whole-path screen: the two paths seen across each one's *chord*, the line
//! from where its ball starts to where it comes to rest ([`apart_across_chords`]).
//!
//! A ball that rolls to rest stays close to its chord (on it, for a friction ball's straight
//! run; within the curl of its slide, for a pool ball), so on the chord's normal the whole
//! path projects to a short span. If the other path's span on that normal keeps out of the
//! contact distance of it, the balls never touch, whatever their timing: a separating axis,
//! as the path bounds' boxes are on the coordinate axes. On random pool-table pairs that
//! settles about half the pairs the boxes leave (a pair of balls rolling side by side or
//! away from each other along a diagonal: their boxes overlap, their strips do not), for a
//! handful of products per segment, and a square root only for the pairs that pass a first
//! test on the paths' ends.
//!
//! A span is the hull of a segment's Bernstein control values (as for the boxes), here of
//! the projected coordinate `n·p + n·v·s + ½·n·a·s²`. Only paths that end at rest (last
//! segment with zero velocity and acceleration) have a bounded span on a direction that is
//! not an axis: a drift whose projected velocity rounds to zero could still leave it, so any
//! other path proves nothing here.
//!
//! The projections are formed on the caller's numbers with the path bounds' [`ScreenDistance`]: the
//! normal's components are at most ½ in magnitude, so that every projected value and every
//! intermediate of its hull is no larger than the largest per-axis term of the bounds' size,
//! and their roundings (and underflows) are covered by the same margin, as one more axis
//! would be. Where a projection overflows, so does the pair's size, and an infinite or NaN
//! screen distance proves nothing.

use super::path_bounds::{ScreenDistance, bernstein_hull};
use crate::path::Segment;

/// Whether balls on paths `a` and `b` (valid, [`Path::segments`](crate::Path::segments))
/// provably never come within `distance` of each other: on the normal of either path's chord,
/// their spans are farther apart than it (times the normal's length, for it is not
/// normalised to 1, see [`chord_normal`]).
///
/// Rigour: the normal `n` has components of magnitude at most ½ (+ a rounding), so that each
/// projection `n·x` is off by no more than a few roundings of the magnitudes the path
/// bounds' size sums, far below the margin in `distance`, and overflows only where that size
/// does; its length, `√(n·n)` to a few
/// roundings (far below that margin too), turns a proof on `n` into one on the unit normal.
#[inline(always)]
pub(crate) fn apart_across_chords<const D: usize>(
    a: &[Segment<D>],
    b: &[Segment<D>],
    distance: ScreenDistance,
) -> bool {
    if !(rests_at_end(a) && rests_at_end(b)) {
        return false;
    }
    apart_across_chord_of(a, b, distance) || apart_across_chord_of(b, a, distance)
}

/// Whether paths `own` and `other` (both ending at rest) are apart on the normal of `own`'s
/// chord.
#[inline(always)]
fn apart_across_chord_of<const D: usize>(
    own: &[Segment<D>],
    other: &[Segment<D>],
    distance: ScreenDistance,
) -> bool {
    let Some(normal) = chord_normal(own) else {
        return false;
    };
    let (Some(start), Some(other_start), Some(other_end)) =
        (own.first(), other.first(), other.last())
    else {
        return false;
    };
    // The spans hold the paths' ends: unless the other path starts and ends on the same side
    // of where this one starts, beyond the screen distance (on a normal at least ½ long), the spans
    // cannot be apart. Most pairs that the boxes leave stop here, before any span or square
    // root is formed. (An empty first segment's position is no part of its path: this test
    // may then give up on a pair the spans would prove, never the other way round.)
    let centre = along(&normal, &start.position);
    let ends = [
        along(&normal, &other_start.position),
        along(&normal, &other_end.position),
    ];
    // (Against less than half the distance: the normal is at least ½ long, less a rounding.)
    let least = 0.49 * distance.value();
    let above = ends[0].min(ends[1]) - centre > least;
    let below = centre - ends[0].max(ends[1]) > least;
    if !(above | below) {
        return false;
    }
    let distance = distance.value() * (normal[0] * normal[0] + normal[1] * normal[1]).sqrt();
    let (own, other) = (span(own, &normal), span(other, &normal));
    (own[0] - other[1] > distance) | (other[0] - own[1] > distance)
}

/// The normal of `own`'s chord and both paths' spans on it, as the screen forms them (for
/// tests that place paths at the screen's edge).
#[cfg(test)]
pub(crate) fn spans_across_chord<const D: usize>(
    own: &[Segment<D>],
    other: &[Segment<D>],
) -> Option<([f64; D], [f64; 2], [f64; 2])> {
    let normal = chord_normal(own)?;
    Some((normal, span(own, &normal), span(other, &normal)))
}

/// Whether the path's last segment is at rest: its span on any direction is then bounded.
#[inline(always)]
fn rests_at_end<const D: usize>(segments: &[Segment<D>]) -> bool {
    segments.last().is_some_and(|last| {
        (0..D).all(|i| (last.velocity[i] == 0.0) & (last.acceleration[i] == 0.0))
    })
}

/// The normal of the path's chord in the first two coordinates (in 3-D, the horizontal one:
/// the cloth's plane), scaled so that its larger component is ±½ (a division, where a unit
/// normal would need a square root too); `None` for a chord with no extent there (a ball that
/// ends where it started, or moves only vertically), or a subnormal, NaN or infinite one.
#[inline(always)]
fn chord_normal<const D: usize>(segments: &[Segment<D>]) -> Option<[f64; D]> {
    if D < 2 {
        return None;
    }
    let d = segments.last()?.position - segments.first()?.position;
    let (dx, dy) = (d[0], d[1]);
    let most = dx.abs().max(dy.abs());
    // A normal extent, so that the scale is finite and the components at most 1: a
    // subnormal chord (or a NaN or infinite one) has no normal.
    if !(f64::MIN_POSITIVE..f64::INFINITY).contains(&most) {
        return None;
    }
    // Components of at most ½ (halving is exact): a projected value then sums two halves of
    // per-axis terms that the path bounds' size bounds, so that none overflows while that
    // size is finite (with components of 1, `n·a` could overflow where no `aᵢ` does, and
    // an infinite intermediate of the wrong sign narrow a span).
    let scale = 0.5 / most;
    let mut normal = [0.0; D];
    normal[0] = -dy * scale;
    normal[1] = dx * scale;
    Some(normal)
}

/// `normal·x`.
#[inline(always)]
fn along<const D: usize>(normal: &[f64; D], x: &nalgebra::SVector<f64, D>) -> f64 {
    (0..D).map(|i| normal[i] * x[i]).sum()
}

/// The least and greatest value of `normal·x` along the path (which ends at rest).
#[inline(always)]
fn span<const D: usize>(segments: &[Segment<D>], normal: &[f64; D]) -> [f64; 2] {
    let mut hull = [f64::INFINITY, f64::NEG_INFINITY];
    for (s, next) in segments.iter().zip(&segments[1..]) {
        let length = next.start - s.start;
        if length > 0.0 {
            let [lo, hi] = bernstein_hull(
                along(normal, &s.position),
                along(normal, &s.velocity),
                along(normal, &s.acceleration),
                length,
            );
            hull = [
                if lo < hull[0] { lo } else { hull[0] },
                if hi > hull[1] { hi } else { hull[1] },
            ];
        }
    }
    // The resting point (the last segment's position, where the ball stays for ever).
    if let Some(last) = segments.last() {
        let p = along(normal, &last.position);
        hull = [
            if p < hull[0] { p } else { hull[0] },
            if p > hull[1] { p } else { hull[1] },
        ];
    }
    hull
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::path_bounds::PathBounds;
    use crate::collision::path_collision_time_unscreened;
    use crate::path::Path2;
    use crate::{CollisionOptions, path_collision_time};
    use nalgebra::{Vector2 as V, Vector3};

    /// A ball rolling from `from` to rest at `to` in 2 s (deceleration to rest).
    fn roll(from: [f64; 2], to: [f64; 2]) -> Vec<Segment<2>> {
        let (p, q) = (V::from(from), V::from(to));
        let v = q - p; // covers `v·τ/2` in τ = 2 s
        vec![Segment::new(0.0, p, v, -v / 2.0), Segment::at_rest(2.0, q)]
    }

    fn apart(a: &[Segment<2>], b: &[Segment<2>], radius: f64) -> bool {
        let (ba, bb) = (PathBounds::<2>::of(a), PathBounds::<2>::of(b));
        apart_across_chords(a, b, ba.screen_distance(&bb, radius))
    }

    /// The screened and unscreened answers of the pair.
    fn answers(a: &[Segment<2>], b: &[Segment<2>], radius: f64) -> [Option<f64>; 2] {
        let (a, b) = (Path2::new(a.to_vec()), Path2::new(b.to_vec()));
        let (a, b) = (a.expect("valid"), b.expect("valid"));
        let options = CollisionOptions::default();
        [
            path_collision_time(&a, &b, radius, &options).expect("valid"),
            path_collision_time_unscreened(&a, &b, radius, &options).expect("valid"),
        ]
    }

    #[test]
    fn balls_rolling_side_by_side_on_a_diagonal_are_apart_across_their_chords() {
        // Two diagonal runs 1/√2 ≈ 0.707 apart: their boxes overlap, their strips do not.
        let a = roll([0.0, 0.0], [4.0, 4.0]);
        let b = roll([1.0, 0.0], [5.0, 4.0]);
        let (ba, bb) = (PathBounds::<2>::of(&a), PathBounds::<2>::of(&b));
        assert!(!ba.apart(&bb, ba.screen_distance(&bb, 0.7)));
        assert!(apart(&a, &b, 0.7) && apart(&b, &a, 0.7));
        assert!(!apart(&a, &b, 0.71) && !apart(&b, &a, 0.71));
        assert_eq!(answers(&a, &b, 0.7), [None, None]);
        // Beyond the strip's half-gap the balls overlap throughout, at a constant distance: no
        // contact (they never approach), which the search says too.
        assert_eq!(answers(&a, &b, 0.71), [None, None]);
    }

    #[test]
    fn a_ball_at_rest_off_a_runs_line_is_apart_across_the_runs_chord() {
        // The ball at rest has no chord; the run's chord still proves it.
        let a = roll([0.0, 0.0], [4.0, 4.0]);
        let b = [Segment::at_rest(0.0, V::new(3.0, 1.0))]; // √2 from the run's line
        assert!(apart(&a, &b, 1.4) && apart(&b, &a, 1.4));
        assert!(!apart(&a, &b, 1.42));
    }

    #[test]
    fn a_curling_slide_is_covered_by_its_control_values() {
        // A's chord runs along x from 0 to 4, but its slide curls out to y = 0.5 at t = 1 and
        // back (v = (2, 1), a = (0, −1) for 2 s), then it rests at (4, 0). B rests at
        // (2, 1.5): 1 from the top of the curl.
        let a = vec![
            Segment::new(0.0, V::zeros(), V::new(2.0, 1.0), V::new(0.0, -1.0)),
            Segment::at_rest(2.0, V::new(4.0, 0.0)),
        ];
        let b = [Segment::at_rest(0.0, V::new(2.0, 1.5))];
        // The span of A on its chord's normal is its control values' hull in y, [0, 1]:
        // a proof up to 0.5, none beyond, though the balls come no closer than 1.
        assert!(apart(&a, &b, 0.45) && apart(&b, &a, 0.45));
        assert!(!apart(&a, &b, 0.55));
        assert_eq!(answers(&a, &b, 0.55), [None, None]);
        let [screened, unscreened] = answers(&a, &b, 1.05);
        assert!(screened.is_some_and(|t| t < 1.0) && screened == unscreened);
    }

    #[test]
    fn the_margin_is_kept() {
        // A rolls along x from 0 to 4; B rests 1 from its line: apart by 1 exactly. A radius
        // within the margin of 1 is no proof (a screen without the margin would give one).
        let a = roll([0.0, 0.0], [4.0, 0.0]);
        let b = [Segment::at_rest(0.0, V::new(2.0, 1.0))];
        assert!(apart(&a, &b, 1.0 - 1e-6));
        assert!(!apart(&a, &b, 1.0 - 2f64.powi(-45)) && !apart(&b, &a, 1.0 - 2f64.powi(-45)));
    }

    #[test]
    fn a_projected_acceleration_near_the_float_range_does_not_narrow_the_span() {
        // Each acceleration component is finite, but on a normal of components ±1 their sum
        // overflowed to −∞ and cut the span short of B, which A passes through (found in
        // review). The size, which multiplies by the length before summing, stays finite.
        let m = f64::MAX;
        let a = vec![
            Segment::new(
                0.0,
                V::zeros(),
                V::new(0.35 * m, 0.35 * m),
                V::new(-0.6 * m, -0.6 * m),
            ),
            Segment::at_rest(0.5, V::new(1.0, -1.0)),
        ];
        let b = [Segment::at_rest(0.0, V::new(0.095 * m, 0.095 * m))];
        for radius in [1e306, 1e300] {
            assert!(!apart(&a, &b, radius) && !apart(&b, &a, radius));
            let [screened, unscreened] = answers(&a, &b, radius);
            assert!(unscreened.is_some() && screened == unscreened, "{radius}");
        }
    }

    #[test]
    fn a_path_that_does_not_end_at_rest_proves_nothing_here() {
        let a = roll([0.0, 0.0], [4.0, 4.0]);
        let drift = [Segment::new(
            0.0,
            V::new(3.0, 1.0),
            V::new(1e-300, 0.0),
            V::zeros(),
        )];
        assert!(!apart(&a, &drift, 0.5) && !apart(&drift, &a, 0.5));
    }

    #[test]
    fn in_three_dimensions_the_normal_is_horizontal_and_a_vertical_chord_has_none() {
        let up = [
            Segment::new(
                0.0,
                Vector3::zeros(),
                Vector3::new(0.0, 0.0, 2.0),
                -Vector3::z(),
            ),
            Segment::at_rest(2.0, Vector3::new(0.0, 0.0, 2.0)),
        ];
        assert_eq!(chord_normal(&up), None);
        let run = [
            Segment::new(
                0.0,
                Vector3::zeros(),
                Vector3::new(4.0, 4.0, 0.0),
                Vector3::new(-2.0, -2.0, 0.0),
            ),
            Segment::at_rest(2.0, Vector3::new(4.0, 4.0, 0.0)),
        ];
        assert_eq!(chord_normal(&run), Some([-0.5, 0.5, 0.0]));
        // A subnormal chord has none: its scale would overflow.
        let tiny: Vec<_> = run
            .iter()
            .map(|s| Segment {
                position: s.position * 1e-310,
                ..*s
            })
            .collect();
        assert_eq!(chord_normal(&tiny), None);
        // A ball rising in place 2 from the run's line, horizontally.
        let rising: Vec<_> = up
            .iter()
            .map(|s| Segment {
                position: s.position + Vector3::new(0.0, 2.0 * 2f64.sqrt(), 0.0),
                ..*s
            })
            .collect();
        let (br, bu) = (PathBounds::<3>::of(&run), PathBounds::<3>::of(&rising));
        assert!(apart_across_chords(
            &run,
            &rising,
            br.screen_distance(&bu, 1.9)
        ));
        assert!(!apart_across_chords(
            &run,
            &rising,
            br.screen_distance(&bu, 2.1)
        ));
    }
}
