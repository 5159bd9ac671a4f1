//! The Newton polygon of a polynomial: the upper convex hull of the points `(k, log₂|c_k|)`
//! over its non-zero coefficients `c_k` (`k` the degree).
//!
//! It tells the solvers two things before any root is found:
//! - how large the roots are: each edge stands for a group of roots whose magnitude is about
//!   `2^slope`, so a vertex where the slope jumps by much separates two groups of roots far
//!   apart ([`split_point`]);
//! - which coefficients matter: at the polygon's height `h_k` over degree `k`,
//!   `2^h_k·|x|^k ≤ max_j |c_j|·|x|^j` for every `x` (`h_k` is a convex combination of two
//!   vertices' heights, and so is `h_k + k·log₂|x|`), so an error in `c_k` that is small next
//!   to `2^h_k` is small next to the polynomial's largest term wherever it is evaluated, and
//!   therefore next to the sum `Σ|c_j|·|x|^j` that the roots' conditioning is measured
//!   against ([`monic_quartic_envelope`]). A coefficient far below the polygon is negligible at every `x`,
//!   whatever its own relative error.
//!
//! Heights are taken from the coefficients' binary exponents (`2^e ≤ |c| < 2^(e+1)`), so the
//! bounds hold as stated, with a factor below 2 to spare.

use super::scaling::{exponent, pow2};

/// How far apart (in bits of magnitude) two groups of roots must be before the polynomial is
/// split into two lower-degree ones, one per group.
///
/// Dropping the coefficients of the other group changes each kept root's residual by at most
/// about `2^-SPLIT_BITS` relative, far below one rounding (2⁻⁵³), so the split costs no accuracy;
/// it is what keeps coefficients like `1e-300·x⁴ + x³ + …` from underflowing once rescaled.
const SPLIT_BITS: f64 = 64.0;

/// The vertices of a Newton polygon, degree ascending, as `(degree, exponent)`.
struct Hull {
    vertices: [(usize, f64); 5],
    len: usize,
}

impl Hull {
    /// The upper convex hull of `(degree, exponent)` over the non-zero coefficients of a
    /// polynomial of degree ≤ 4, given by their exponents (highest degree first, `None` for a
    /// zero).
    fn of(exps: &[Option<i32>]) -> Self {
        let mut hull = Self {
            vertices: [(0, 0.0); 5],
            len: 0,
        };
        let n = exps.len().saturating_sub(1);
        for k in 0..=n {
            let Some(e) = exps[n - k] else {
                continue;
            };
            let pt = (k, f64::from(e));
            // Keep the hull upper-convex: drop the last vertex while it lies on or below the
            // chord from the one before it to the new point.
            while hull.len >= 2 {
                let (k1, e1) = hull.vertices[hull.len - 2];
                let (k2, e2) = hull.vertices[hull.len - 1];
                let cross = (k2 - k1) as f64 * (pt.1 - e1) - (e2 - e1) * (pt.0 - k1) as f64;
                if cross >= 0.0 {
                    hull.len -= 1;
                } else {
                    break;
                }
            }
            if hull.len < hull.vertices.len() {
                hull.vertices[hull.len] = pt;
                hull.len += 1;
            }
        }
        hull
    }

    fn vertices(&self) -> &[(usize, f64)] {
        &self.vertices[..self.len]
    }
}

/// For the monic quartic `x⁴ + a·x³ + b·x² + c·x + d` (`d ≠ 0`), the powers of two
/// `2^⌊h_k⌋` under its Newton polygon at the degrees of `a, b, c, d`: an error in a
/// coefficient that is `δ` times its envelope is at most `δ` times the quartic's largest term,
/// at every `x` (see the module's documentation).
///
/// The quartic solver measures the backward error of a candidate factorisation against
/// `max(size of its terms, envelope)`: a coefficient far below the polygon (a tiny odd-degree
/// term next to an even quartic, say) is then not mistaken for one that must be reproduced to
/// full relative accuracy.
pub(super) fn monic_quartic_envelope(a: f64, b: f64, c: f64, d: f64) -> [f64; 4] {
    // Called once per quartic, so without the hull's bookkeeping: the polygon's height over a
    // degree is the highest chord between points on either side of it (or the point itself),
    // and with x⁴ at height 0 these are ten chords, written out. A zero coefficient is a point
    // at −∞, under every chord. No NaN can arise, so plain comparisons do for max.
    let (e3, e2, e1, e0) = (log2_floor(a), log2_floor(b), log2_floor(c), log2_floor(d));
    let max = |x: f64, y: f64| if x > y { x } else { y };
    let h3 = max(max(e3, e2 / 2.0), max(e1 / 3.0, e0 / 4.0));
    let h2 = max(
        max(e2, (e3 + e1) / 2.0),
        max(max((2.0 * e3 + e0) / 3.0, 2.0 * e1 / 3.0), e0 / 2.0),
    );
    let h1 = max(
        max(e1, (e2 + e0) / 2.0),
        max((e3 + 2.0 * e0) / 3.0, 3.0 * e0 / 4.0),
    );
    [
        pow2_floor(h3),
        pow2_floor(h2),
        pow2_floor(h1),
        pow2_floor(e0),
    ]
}

/// `2^⌊h⌋` (0 for `h = −∞`), with `⌊h⌋` taken without a library call: the truncation, one
/// less for a negative fraction.
#[inline(always)]
fn pow2_floor(h: f64) -> f64 {
    if h.is_finite() {
        let t = h as i32;
        pow2(if f64::from(t) > h { t - 1 } else { t })
    } else {
        0.0
    }
}

/// `⌊log₂|x|⌋` as a float (`−∞` for zero): the exponent field for a normal `x`.
#[inline(always)]
fn log2_floor(x: f64) -> f64 {
    if x.is_normal() {
        f64::from(((x.to_bits() >> 52) & 0x7ff) as i32 - 1023)
    } else {
        exponent(x).map_or(f64::NEG_INFINITY, f64::from)
    }
}

/// Where to split a polynomial (given by its coefficient exponents, highest degree first) whose roots form two groups more than
/// [`SPLIT_BITS`] apart in magnitude, as read off its Newton polygon: the index `i` such that
/// `coeffs[..=i]` has the large roots and `coeffs[i..]` the small ones.
///
/// The upper convex hull of the points `(degree k, log₂|c_k|)` has one edge per group of roots
/// of similar magnitude; the slope of an edge is the log of that magnitude. A vertex where the
/// slope jumps by more than `SPLIT_BITS` separates two groups, and at it each group's
/// polynomial is the part of the coefficients on its side, up to terms smaller than
/// `2^-SPLIT_BITS` relative.
pub(super) fn split_point(exps: &[Option<i32>]) -> Option<usize> {
    let n = exps.len().checked_sub(1)?;
    // Fast path: an edge slope is at most the exponent range, so slopes can differ by more
    // than SPLIT_BITS only if the exponents span more than SPLIT_BITS / 2.
    let (mut lo, mut hi) = (i32::MAX, i32::MIN);
    for &e in exps.iter().flatten() {
        lo = lo.min(e);
        hi = hi.max(e);
    }
    if f64::from(hi.saturating_sub(lo)) <= SPLIT_BITS / 2.0 {
        return None;
    }
    let hull = Hull::of(exps);
    for w in hull.vertices().windows(3) {
        let [(k0, e0), (k1, e1), (k2, e2)] = [w[0], w[1], w[2]];
        let small = (e0 - e1) / (k1 - k0) as f64;
        let large = (e1 - e2) / (k2 - k1) as f64;
        if large - small > SPLIT_BITS {
            return Some(n - k1);
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::super::scaling::exponent;
    use super::*;

    fn exponents<const N: usize>(c: [f64; N]) -> [Option<i32>; N] {
        c.map(exponent)
    }

    #[test]
    fn split_point_finds_separated_groups() {
        // 1e-300·x⁴ + x³ + x² + x + 1: one root near −1e300, three of order one.
        assert_eq!(
            split_point(&exponents([1e-300, 1.0, 1.0, 1.0, 1.0])),
            Some(1)
        );
        assert_eq!(split_point(&exponents([1.0, -6.0, 11.0, -6.0])), None);
        // Roots 1e-200 and 1e200.
        assert_eq!(split_point(&exponents([1.0, -1e200, 1.0])), Some(1));
    }

    #[test]
    fn envelope_is_the_polygon_height() {
        // x⁴ + 2⁻¹⁰⁰·x + 2⁻⁴⁰: the linear term lies far below the chord from x⁴ to the
        // constant, whose height over degree 1 is −30.
        let env = monic_quartic_envelope(0.0, 0.0, 2f64.powi(-100), 2f64.powi(-40));
        assert_eq!(
            env,
            [
                2f64.powi(-10),
                2f64.powi(-20),
                2f64.powi(-30),
                2f64.powi(-40)
            ]
        );
        // (x − 1)(x − 2)(x − 3)(x − 4): every coefficient is on the polygon, its own envelope
        // (to a power of two).
        let env = monic_quartic_envelope(-10.0, 35.0, -50.0, 24.0);
        assert_eq!(env, [8.0, 32.0, 32.0, 16.0]);
        // A negative fractional height rounds down: x⁴ + 2⁻³ has height −1.5 over degree 2.
        assert_eq!(monic_quartic_envelope(0.0, 0.0, 0.0, 0.125)[1], 0.25);
    }

    #[test]
    fn envelope_bounds_the_largest_term() {
        // 2^h_k·|x|^k ≤ max_j |c_j|·|x|^j at every x, for a polygon with interior vertices
        // (x⁴ − 1.8e7·x² − 1.9e-196·x + 283, the monic form of issue 21's reproducer).
        let c = [1.0, 0.0, -1.8e7, -1.9e-196, 283.0];
        let env = monic_quartic_envelope(c[1], c[2], c[3], c[4]);
        for x in [1e-8_f64, 1e-4, 3e-3, 0.1, 1.0, 42.0, 4e3, 1e7] {
            let largest = (0..5)
                .map(|i| c[i].abs() * x.powi(4 - i as i32))
                .fold(0.0, f64::max);
            for (i, e) in env.iter().enumerate() {
                let term = e * x.powi(3 - i as i32);
                assert!(term <= largest * (1.0 + 1e-12), "x = {x}, degree {}", 3 - i);
            }
        }
    }
}
