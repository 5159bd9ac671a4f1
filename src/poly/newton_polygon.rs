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
//!   against ([`envelope`]). A coefficient far below the polygon is negligible at every `x`,
//!   whatever its own relative error.
//!
//! Heights are taken from the coefficients' binary exponents (`2^e ≤ |c| < 2^(e+1)`), so the
//! bounds hold as stated, with a factor below 2 to spare.

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

    /// The polygon's height over degree `k`, or `None` outside its span.
    fn height(&self, k: usize) -> Option<f64> {
        let v = self.vertices();
        let right = v.iter().position(|&(kv, _)| kv >= k)?;
        let (k2, e2) = v[right];
        if k2 == k {
            return Some(e2);
        }
        let (k1, e1) = v[right.checked_sub(1)?];
        Some(e1 + (e2 - e1) * (k - k1) as f64 / (k2 - k1) as f64)
    }
}

/// For each coefficient of `coeffs` (highest degree first, degree ≤ 4), the power of two
/// `2^⌊h_k⌋` under its Newton polygon at that degree: an error in `c_k` that is `δ` times this
/// is at most `δ` times the polynomial's largest term, at every `x` (see the module's
/// documentation). `0` outside the polygon's span (degrees above the leading non-zero
/// coefficient or below the last one).
///
/// The polynomial solvers measure the backward error of a candidate factorisation against
/// `max(size of its terms, envelope)`: a coefficient far below the polygon (a tiny odd-degree
/// term next to an even quartic, say) is then not mistaken for one that must be reproduced to
/// full relative accuracy.
pub(super) fn envelope<const N: usize>(coeffs: &[f64; N]) -> [f64; N] {
    let hull = Hull::of(&coeffs.map(super::scaling::exponent));
    let mut out = [0.0; N];
    for (i, o) in out.iter_mut().enumerate() {
        if let Some(h) = hull.height(N - 1 - i) {
            // Heights are within the exponent range of floats: the conversion is exact.
            *o = super::scaling::pow2(h.floor() as i32);
        }
    }
    out
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
        let c = [1.0, 0.0, 0.0, 2f64.powi(-100), 2f64.powi(-40)];
        assert_eq!(
            envelope(&c),
            [
                1.0,
                2f64.powi(-10),
                2f64.powi(-20),
                2f64.powi(-30),
                2f64.powi(-40)
            ]
        );
        // On the polygon, a coefficient is its own envelope (to a power of two).
        assert_eq!(envelope(&[1.0, -3.0, 2.0]), [1.0, 2.0, 2.0]);
        // Degrees outside the span of the non-zero coefficients get 0.
        assert_eq!(envelope(&[0.0, 1.0, 0.0, 4.0]), [0.0, 1.0, 2.0, 4.0]);
    }

    #[test]
    fn envelope_bounds_the_largest_term() {
        // 2^h_k·|x|^k ≤ max_j |c_j|·|x|^j at every x, for a polygon with interior vertices.
        let c = [3e-5, 0.0, 7e2, -1e-200, -1.5e-2];
        let env = envelope(&c);
        for x in [1e-8_f64, 1e-4, 3e-3, 0.1, 1.0, 42.0, 4e3, 1e7] {
            let largest = (0..5)
                .map(|i| c[i].abs() * x.powi(4 - i as i32))
                .fold(0.0, f64::max);
            for (i, e) in env.iter().enumerate() {
                assert!(
                    e * x.powi(4 - i as i32) <= largest * (1.0 + 1e-12),
                    "x = {x}, i = {i}"
                );
            }
        }
    }
}
