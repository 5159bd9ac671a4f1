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

use crate::gap::Gap;

/// Relative size of the margin (the pair screen's, [`prefilter::MARGIN`]), `2⁻⁴⁰ ≈ 9e-13`
/// of the magnitudes involved: far above the few roundings (`ε = 2⁻⁵³`) made in forming a
/// box and in the search's own arithmetic.
///
/// [`prefilter::MARGIN`]: super::prefilter::MARGIN
pub(crate) use super::prefilter::MARGIN;

/// What underflow can cost a box: a quadratic's values over a span of length `L` computed in
/// floats are off by more than relative roundings only where a product underflows, by at most
/// `2⁻¹⁰⁷⁵` each, which the later products by `L` (and by the velocity, at the vertex) scale
/// up: in all below `2⁻¹⁰⁷⁴·(1 + |v| + L)²`. The boxes sum `(1 + |v| + L)²` (the *spread*) and
/// add `UNDERFLOW` times it to the margin, far above that cost; they do so only where it can
/// count against the relative margin ([`with_underflow`]), since arithmetic on subnormal
/// numbers is slow.
pub(crate) const UNDERFLOW: f64 = f64::from_bits(1 << 4); // 2⁻¹⁰⁷⁰, subnormal

/// `reach` grown by what underflow can cost boxes of the given spread (see [`UNDERFLOW`]):
/// unchanged unless that cost could exceed a rounding of `reach` ([`NORMAL_FLOOR`]` · spread`
/// is normal, so the test itself costs no subnormal arithmetic).
#[inline(always)]
pub(crate) fn with_underflow(reach: f64, spread: f64) -> f64 {
    if reach < NORMAL_FLOOR * spread {
        grown_by_underflow(reach, spread)
    } else {
        reach
    }
}

/// `reach + UNDERFLOW · spread`, out of line, so that the compiler never computes it (on a
/// subnormal constant, slow) where it is not needed.
#[cold]
#[inline(never)]
fn grown_by_underflow(reach: f64, spread: f64) -> f64 {
    reach + UNDERFLOW * spread
}

/// `near > far + SQUARE_SLACK`, out of line like [`grown_by_underflow`].
#[cold]
#[inline(never)]
fn beyond_slack(near: f64, far: f64) -> bool {
    near > far + SQUARE_SLACK
}

/// A computed square may have lost a few `2⁻¹⁰⁷⁵` to underflow: comparisons of squares below
/// [`NORMAL_FLOOR`] keep this much apart.
const SQUARE_SLACK: f64 = f64::from_bits(1 << 4); // 16·2⁻¹⁰⁷⁴

/// `2⁻¹⁰⁰⁰`: numbers above it (a reach, a square) are far above what underflow can cost
/// them, and products of it with the spreads stay normal.
pub(crate) const NORMAL_FLOOR: f64 = f64::from_bits((1023 - 1000) << 52);

/// The range `(lo, hi)` of `p + v·s + ½·a·s²` over `s ∈ [0, length]` (its values at the ends
/// and at its vertex, if inside), a bound on the magnitudes that form it (for the margin),
/// and its spread (what underflow can cost it, [`UNDERFLOW`]).
#[inline(always)]
fn axis_range(p: f64, v: f64, a: f64, length: f64) -> (f64, f64, f64, f64) {
    let at = |s: f64| p + (v + 0.5 * a * s) * s;
    let end = at(length);
    let (mut lo, mut hi) = (p.min(end), p.max(end));
    // The vertex, where the motion along the axis turns, if it comes inside the span: the
    // value at the turn `−v/a` held to the span (`max` and `min`, no branch: whether the turn
    // is inside is hard to predict, and a branch on it cost more than the division, measured
    // −7 % on pool pairs). Where the motion does not slow down (`v` and `a` of one sign, or
    // either 0) the turn is ≤ 0 or NaN, held to 0: the value there is `p`; where it turns after
    // the span, held to `length`: `end`. Either is in the range already. At an inside turn the
    // value is the vertex's up to a few roundings of the magnitudes (the turn's own rounding
    // counts only at second order, the motion being flat there), which the margin covers,
    // and its underflow the spread, as for `end`.
    let turn = (-(v / a)).max(0.0).min(length);
    let vertex = at(turn);
    lo = lo.min(vertex);
    hi = hi.max(vertex);
    let magnitude = p.abs() + (v.abs() + a.abs() * length) * length;
    let spread = 1.0 + v.abs() + length;
    (lo, hi, magnitude, spread * spread)
}

/// Whether `g > 0` is proven on `[0, length]` (time since the window's start) by the box the
/// separation sweeps. `false` means "not proven".
#[inline(always)]
pub(crate) fn apart_on_window<const D: usize>(gap: &Gap<D>, length: f64) -> bool {
    let mut nearest2 = 0.0;
    let (mut size, mut spread) = (gap.contact_distance, 0.0);
    for i in 0..D {
        let (p, v, a) = (gap.offset[i], gap.velocity[i], gap.acceleration[i]);
        let (lo, hi, magnitude, axis_spread) = axis_range(p, v, a, length);
        spread += axis_spread;
        // The distance of `[lo, hi]` from 0: `lo` if above it, `−hi` if below, else 0 (at
        // most one term is not 0, `lo ≤ hi`; `max` drops a NaN, as the tests it replaces do).
        // Without branches: which holds is hard to predict.
        let nearest = lo.max(0.0) + (-hi).max(0.0);
        nearest2 += nearest * nearest;
        size += magnitude;
    }
    let reach = with_underflow(gap.contact_distance + MARGIN * size, spread);
    // The squares too may have lost a few `2⁻¹⁰⁷⁵` to underflow: kept that far apart where they
    // are that small. NaN (an overflowing window) fails the comparisons: not proven.
    let (near, far) = (nearest2, reach * reach);
    if far > NORMAL_FLOOR {
        near > far
    } else {
        near > far && beyond_slack(near, far)
    }
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
            contact_distance: 0.5,
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

    /// `2^e`, exactly, from its bits (`powi` is exact only where the compiler folds it: an
    /// unoptimised build computes `2^-1070` as `1 / 2^1070`, which overflows).
    fn two_to(e: i32) -> f64 {
        if e >= -1022 {
            f64::from_bits(((e + 1023) as u64) << 52)
        } else {
            f64::from_bits(1 << (e + 1074))
        }
    }

    #[test]
    fn the_underflow_margins_are_the_powers_of_two_they_say() {
        assert_eq!(two_to(-1000) * two_to(-74), two_to(-1074));
        assert_eq!(UNDERFLOW, two_to(-1070));
        assert_eq!(SQUARE_SLACK, two_to(-1070));
        assert_eq!(NORMAL_FLOOR, two_to(-1000));
        // The absolute part counts only where it can matter.
        assert_eq!(with_underflow(1e-3, 4.0), 1e-3);
        let tiny = two_to(-1060);
        assert_eq!(with_underflow(tiny, 4.0), tiny + 4.0 * two_to(-1070));
    }

    #[test]
    fn an_overflowing_window_proves_nothing() {
        let g = gap([2.0, 0.0], [1.0, 0.0], [1.0, 0.0]);
        assert!(!apart_on_window(&g, 1e300));
    }
}
