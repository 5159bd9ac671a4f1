//! A cheap, rigorous proof that two balls stay apart on a window: the box that the
//! separation `d(s) = d₀ + v·s + ½·a·s²` sweeps over the window keeps out of the contact
//! distance.
//!
//! On each axis `d` is a quadratic in `s`, so its range over `[0, L]` lies between its values
//! at the ends and at its vertex (if inside): a box. If even the box's nearest point to the
//! origin is farther than the radius (by a margin far above every rounding error made here),
//! the balls cannot touch on the window. It takes a handful of operations per axis and no
//! quartic, and settles most windows of balls on general paths: those far apart, and those
//! that cross each other's paths at other times (the box is of the relative motion, so time
//! is taken into account).

use crate::coefficients::Gap;
use crate::path::Segment;

/// Relative size of the margin, `2⁻⁴⁰ ≈ 9e-13` of the magnitudes involved: far above the few
/// roundings (`ε = 2⁻⁵³`) made in forming the box and in the search's own arithmetic.
const MARGIN: f64 = 1.0 / ((1u64 << 40) as f64);

/// The range `(lo, hi)` of `p + v·s + ½·a·s²` over `s ∈ [0, length]` (its values at the ends
/// and at its vertex, if inside), and a bound on the magnitudes that form it (for the margin).
#[inline(always)]
fn axis_range(p: f64, v: f64, a: f64, length: f64) -> (f64, f64, f64) {
    let end = p + (v + 0.5 * a * length) * length;
    let (mut lo, mut hi) = (p.min(end), p.max(end));
    // The vertex, where the motion along the axis turns, if it comes inside the span.
    let turn = -v / a;
    if turn > 0.0 && turn < length {
        let vertex = p - 0.5 * v * (v / a);
        lo = lo.min(vertex);
        hi = hi.max(vertex);
    }
    (lo, hi, p.abs() + (v.abs() + a.abs() * length) * length)
}

/// Whether `g > 0` is proven on `[0, length]` (time since the window's start) by the box the
/// separation sweeps. `false` means "not proven".
#[inline]
pub(crate) fn apart_on_window<const D: usize>(gap: &Gap<D>, length: f64) -> bool {
    let mut nearest2 = 0.0;
    let mut size = gap.radius;
    for i in 0..D {
        let (p, v, a) = (gap.offset[i], gap.velocity[i], gap.acceleration[i]);
        let (lo, hi, magnitude) = axis_range(p, v, a, length);
        let nearest = if lo > 0.0 {
            lo
        } else if hi < 0.0 {
            -hi
        } else {
            0.0
        };
        nearest2 += nearest * nearest;
        size += magnitude;
    }
    let reach = gap.radius + MARGIN * size;
    // NaN (an overflowing window) fails the comparison: not proven.
    nearest2 > reach * reach
}

/// The box a path's centre stays in from its first start on, as `(lo, hi, size)`: per
/// segment the range of each coordinate over the segment's span (its ends and its vertex), an
/// unbounded side for the last segment wherever it moves; `size` bounds the magnitudes
/// involved, for the margin.
fn path_box<const D: usize>(segments: &[Segment<D>]) -> ([f64; D], [f64; D], f64) {
    let (mut lo, mut hi, mut size) = ([f64::INFINITY; D], [f64::NEG_INFINITY; D], 0.0);
    for (k, s) in segments.iter().enumerate() {
        let length = segments
            .get(k + 1)
            .map_or(f64::INFINITY, |next| next.start - s.start);
        if length <= 0.0 {
            continue; // empty: never active
        }
        for i in 0..D {
            let (p, v, a) = (s.position[i], s.velocity[i], s.acceleration[i]);
            let (mut l, mut h) = (p, p);
            if length.is_finite() {
                let magnitude;
                (l, h, magnitude) = axis_range(p, v, a, length);
                size += magnitude;
            } else {
                // For ever: towards wherever the acceleration, or else the velocity, points.
                let drift = if a != 0.0 { a } else { v };
                if drift < 0.0 || (a > 0.0 && v < 0.0) {
                    l = f64::NEG_INFINITY;
                }
                if drift > 0.0 || (a < 0.0 && v > 0.0) {
                    h = f64::INFINITY;
                }
                size += p.abs();
            }
            lo[i] = lo[i].min(l);
            hi[i] = hi[i].max(h);
        }
    }
    (lo, hi, size)
}

/// Whether balls on two valid paths provably never come within `radius` of each other,
/// whatever their timing: the boxes their centres stay in ([`path_box`]), grown by the radius
/// and the margin, are disjoint on some axis. Most pairs of balls on a table that never touch
/// are settled by it before any window is formed.
pub(crate) fn paths_apart<const D: usize>(a: &[Segment<D>], b: &[Segment<D>], radius: f64) -> bool {
    let (lo_a, hi_a, size_a) = path_box(a);
    let (lo_b, hi_b, size_b) = path_box(b);
    let reach = radius + MARGIN * (size_a + size_b + radius);
    (0..D).any(|i| (lo_a[i] - hi_b[i] > reach) | (lo_b[i] - hi_a[i] > reach))
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;

    fn gap(offset: [f64; 2], velocity: [f64; 2], acceleration: [f64; 2]) -> Gap {
        Gap {
            offset: Vector2::from(offset),
            velocity: Vector2::from(velocity),
            acceleration: Vector2::from(acceleration),
            radius: 0.5,
        }
    }

    #[test]
    fn balls_crossing_at_different_times_are_apart() {
        // B passes through A's position after A has left... relative motion: d from (−2, 0) to
        // (2, 0) along y = 1: never within 0.5.
        let g = gap([-2.0, 1.0], [4.0, 0.0], [0.0, 0.0]);
        assert!(apart_on_window(&g, 1.0));
        let g = gap([-2.0, 0.2], [4.0, 0.0], [0.0, 0.0]);
        assert!(!apart_on_window(&g, 1.0)); // passes within 0.2: not proven (it is a contact)
    }

    #[test]
    fn the_vertex_counts() {
        // Decelerating towards the other and turning back at x = 0.25 (closest): not apart.
        let g = gap([2.0, 0.0], [-2.0, 0.0], [8.0 / 7.0, 0.0]);
        assert!(!apart_on_window(&g, 3.0));
        // The same cut before the turn, at x ≈ 1.38: apart.
        assert!(apart_on_window(&g, 0.35));
    }

    #[test]
    fn paths_far_apart_are_apart_and_a_drifting_one_is_not() {
        use nalgebra::Vector2 as V;
        let at = |x: f64, v: f64, a: f64| {
            Segment::new(0.0, V::new(x, 0.0), V::new(v, 0.0), V::new(a, 0.0))
        };
        // A rolls from 0 towards +x and stops at 1 (v = 1, a = −0.5 for 2 s); B rests at 3.
        let a = [at(0.0, 1.0, -0.5), Segment::at_rest(2.0, V::new(1.0, 0.0))];
        let b = [Segment::at_rest(0.0, V::new(3.0, 0.0))];
        assert!(paths_apart(&a, &b, 1.5));
        assert!(!paths_apart(&a, &b, 2.5));
        // A frictionless B drifting towards A is not.
        assert!(!paths_apart(&a, &[at(3.0, -0.1, 0.0)], 1.5));
        // Nor one accelerating towards A though moving away.
        assert!(!paths_apart(&a, &[at(3.0, 1.0, -0.01)], 1.5));
        assert!(paths_apart(&a, &[at(3.0, 1.0, 0.0)], 1.5));
    }

    #[test]
    fn an_overflowing_window_proves_nothing() {
        let g = gap([2.0, 0.0], [1.0, 0.0], [1.0, 0.0]);
        assert!(!apart_on_window(&g, 1e300));
    }
}
