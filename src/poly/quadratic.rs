//! Real roots of linear and quadratic polynomials, computed stably.

use super::RealRoots;
use super::scaling::{exponent, scale};

/// The real root of `b·x + c = 0`.
///
/// A constant polynomial (`b = 0`) has no isolated root; it gives an empty result even when
/// `c = 0` (then every `x` is a root, as `numpy.roots` also reports nothing). A non-finite
/// coefficient gives no root, as for every solver.
///
/// ```
/// use ballcollide::poly::solve_linear;
/// assert_eq!(solve_linear(2.0, -3.0).as_slice(), &[1.5]);
/// assert!(solve_linear(0.0, 1.0).is_empty());
/// assert!(solve_linear(-1.0, f64::INFINITY).is_empty());
/// ```
pub fn solve_linear(b: f64, c: f64) -> RealRoots {
    let mut roots = RealRoots::empty();
    if b != 0.0 && b.is_finite() && c.is_finite() {
        roots.push(-c / b);
    }
    roots
}

/// The real roots of `a·x² + b·x + c = 0`, ascending, with multiplicity.
///
/// Accurate to a few ulp of what the exact coefficients determine:
/// - the roots are formed as `q = −(b + sign(b)·√Δ)/2`, `x₁ = q/a`, `x₂ = c/q`, so neither
///   root suffers cancellation;
/// - when the roots are close, `Δ = b² − 4ac` cancels; it is then recomputed with
///   fused multiply-adds that capture the rounding error of each product (Kahan's method),
///   so a double root stays double and a pair of close roots is not lost;
/// - the variable and the coefficients are rescaled by exact powers of two first, so
///   coefficients anywhere in the float range neither overflow nor underflow in `b²` or `4ac`.
///
/// `a = 0` falls back to [`solve_linear`]. A root too large for a float is reported as ±∞; a
/// non-finite coefficient gives no root.
///
/// ```
/// use ballcollide::poly::solve_quadratic;
/// // (x − 1)(x − 1e-10): the small root keeps full relative accuracy.
/// let r = solve_quadratic(1.0, -(1.0 + 1e-10), 1e-10);
/// assert_eq!(r.len(), 2);
/// assert!((r[0] - 1e-10).abs() <= 1e-26);
/// assert_eq!(r[1], 1.0);
/// // Coefficients far outside the range where b² is representable; the large root, 3e600,
/// // overflows to +∞ and is reported as such.
/// let r = solve_quadratic(1e-300, -3e300, 2e300);
/// assert_eq!(r.len(), 2);
/// assert!((r[0] - 2.0 / 3.0).abs() <= f64::EPSILON);
/// assert_eq!(r[1], f64::INFINITY);
/// ```
#[inline(always)]
pub fn solve_quadratic(a: f64, b: f64, c: f64) -> RealRoots {
    if !(a.is_finite() && b.is_finite() && c.is_finite()) {
        return RealRoots::empty();
    }
    if a == 0.0 {
        return solve_linear(b, c);
    }
    if c == 0.0 {
        return RealRoots::from_unsorted(&[0.0, -b / a]);
    }
    if plain(a) && plain(c) && (b == 0.0 || plain(b)) {
        // Every product and quotient below is a normal float: the rescaling would only
        // multiply each by a power of two, which changes no bit of a root (see `plain`).
        return roots_of(a, b, c, 0, |q| [q / a, c / q]);
    }
    solve_rescaled(a, b, c)
}

/// Whether `|x|` lies in `[2⁻²⁵⁰, 2²⁵¹)`. With `a`, `c` and a non-zero `b` there, `b²`, `4ac`,
/// the discriminant's rounding errors where they matter (cancellation: then `b² ≈ 4ac`, of
/// the same size), `√Δ`, `q`, `q/a` and `c/q` are all normal floats, so no rounding differs
/// from that of the rescaled coefficients, whose every value is the same times a power of
/// two: the roots are the same bits (a unit test compares the two on random coefficients).
#[inline(always)]
fn plain(x: f64) -> bool {
    let biased = (x.to_bits() >> 52) & 0x7ff;
    (1023 - 250..=1023 + 250).contains(&biased)
}

/// [`solve_quadratic`] for finite `a ≠ 0` and `c ≠ 0`, rescaled by powers of two.
fn solve_rescaled(a: f64, b: f64, c: f64) -> RealRoots {
    let (Some(ea), Some(ec)) = (exponent(a), exponent(c)) else {
        return RealRoots::empty(); // unreachable: a and c are finite and non-zero here
    };
    // Substitute x = 2^s·y so that the leading and constant coefficients have similar size
    // (their ratio is the product of the roots), then scale the coefficients to max ≈ 1.
    // The exponents are combined before any multiplication so nothing overflows on the way;
    // a coefficient that underflows to 0 was negligible against the largest one.
    let s = (ec - ea) / 2;
    let ek = [Some(ea + 2 * s), exponent(b).map(|eb| eb + s), Some(ec)]
        .into_iter()
        .flatten()
        .max()
        .unwrap_or(0);
    let (a1, b1, c1) = (scale(a, 2 * s - ek), scale(b, s - ek), scale(c, -ek));
    // x₁ = q₁/a₁·2^s and x₂ = c₁/q₁·2^s. When the roots are far apart in magnitude, a₁ and c₁
    // are tiny next to b₁ and may be subnormal (so may a and c themselves): a quotient by or of
    // a subnormal loses bits or overflows although the root is an ordinary float (1.6e-320·x²
    // + 8.8e-14·x − 1e-323 has a root at −5.7e306). So a and c enter through their mantissas
    // in [1, 2) (exact), and the powers of two are applied once, to the quotients:
    // a₁ = ma·2^(ea+2s−ek) and c₁ = mc·2^(ec−ek).
    let (ma, mc) = (scale(a, -ea), scale(c, -ec));
    roots_of(a1, b1, c1, s, |q| {
        [scale(q / ma, ek - s - ea), scale(mc / q, ec + s - ek)]
    })
}

/// The roots of `a₁·y² + b₁·y + c₁` (`a₁`, `c₁` non-zero) as roots `x = 2^s·y`, ascending;
/// `quotients` forms the two roots `x₁ = q/a`, `x₂ = c/q` from `q = −(b₁ + sign(b₁)·√Δ)/2`.
#[inline(always)]
fn roots_of(
    a1: f64,
    b1: f64,
    c1: f64,
    s: i32,
    quotients: impl FnOnce(f64) -> [f64; 2],
) -> RealRoots {
    let disc = discriminant(a1, b1, c1);
    let mut roots = RealRoots::empty();
    if disc < 0.0 {
        return roots;
    }
    if disc == 0.0 {
        let x = scale(-0.5 * (b1 / a1), s);
        roots.push(x);
        roots.push(x);
        return roots;
    }
    if b1 == 0.0 {
        // ±√(−c/a): exactly opposite, whatever the sign of the zero. Both scaled coefficients
        // are within a factor 4 of 1 here, so the quotient is accurate.
        let x = scale((-c1 / a1).sqrt(), s);
        roots.push(-x);
        roots.push(x);
        return roots;
    }
    let q = -0.5 * (b1 + disc.sqrt().copysign(b1));
    for x in quotients(q) {
        roots.push(x);
    }
    roots.sort();
    roots
}

/// `b² − 4ac`, with the rounding errors of both products restored when they cancel.
///
/// Kahan's test `3·|b² − 4ac| < b² + 4ac` tells when cancellation has eaten more than about
/// a bit; only then is the fused multiply-add correction (exact product errors) needed.
fn discriminant(a: f64, b: f64, c: f64) -> f64 {
    let p = b * b;
    let q = 4.0 * a * c;
    let d = p - q;
    if 3.0 * d.abs() >= p + q.abs() {
        return d;
    }
    let dp = b.mul_add(b, -p);
    let dq = (4.0 * a).mul_add(c, -q);
    d + (dp - dq)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coefficients_in_the_plain_range_get_the_rescaled_roots_to_the_bit() {
        let mut rng = crate::test_rng::Rng(5);
        let float = |rng: &mut crate::test_rng::Rng, lo: f64, hi: f64| {
            let x = rng.uniform(1.0, 2.0) * rng.uniform(lo, hi).round().exp2();
            if rng.uniform(0.0, 1.0) < 0.5 { -x } else { x }
        };
        let bits = |r: &RealRoots| r.as_slice().iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        let mut compared = 0;
        for n in 0..300_000 {
            let (a, c) = (
                float(&mut rng, -250.0, 250.0),
                float(&mut rng, -250.0, 250.0),
            );
            let b = match n % 4 {
                0 => 0.0,
                1 => float(&mut rng, -250.0, 250.0),
                // Close or double roots: b² ≈ 4ac, to the last bits.
                _ => {
                    let b = 2.0 * (a * c).abs().sqrt() * (1.0 + rng.uniform(-1.0, 1.0) * 1e-12);
                    if n % 8 < 4 {
                        b
                    } else {
                        b * (1.0 + f64::EPSILON)
                    }
                }
            };
            if !(plain(a) && plain(c) && (b == 0.0 || plain(b))) {
                continue;
            }
            compared += 1;
            let (plain_roots, rescaled) = (solve_quadratic(a, b, c), solve_rescaled(a, b, c));
            assert_eq!(bits(&plain_roots), bits(&rescaled), "{a:e} {b:e} {c:e}");
        }
        assert!(compared > 250_000, "only {compared} compared");
        // Exact double roots, 2^k·(x − 2^m)², and a missing middle term, at the range's edges.
        for k in [-250, -249, -125, 0, 125, 249, 250] {
            for m in [-1, 0, 1] {
                let (a, r) = (2f64.powi(k), 2f64.powi(m));
                let (b, c) = (-2.0 * a * r, a * r * r);
                if !(plain(a) && plain(b) && plain(c)) {
                    continue;
                }
                let roots = solve_quadratic(a, b, c);
                assert_eq!(roots.as_slice(), &[r, r], "2^{k}·(x − 2^{m})²");
                assert_eq!(bits(&roots), bits(&solve_rescaled(a, b, c)));
                let opposite = solve_quadratic(a, 0.0, -c);
                assert_eq!(opposite.as_slice(), &[-r, r]);
                assert_eq!(bits(&opposite), bits(&solve_rescaled(a, 0.0, -c)));
            }
        }
    }

    #[test]
    fn double_root_is_reported_twice() {
        // (3x − 1)² = 9x² − 6x + 1: 1/3 is not a float, but the coefficients are exact.
        let r = solve_quadratic(9.0, -6.0, 1.0);
        assert_eq!(r.len(), 2);
        assert_eq!(r[0], r[1]);
        assert!((r[0] - 1.0 / 3.0).abs() <= f64::EPSILON);
    }

    #[test]
    fn discriminant_cancellation_is_compensated() {
        // (x + 1)(x + 1 + 2^-29) = x² + (2 + 2^-29)·x + (1 + 2^-29), all exact. b² rounds to
        // exactly 4c, so the naive discriminant is 0 and reports a false double root at
        // −(1 + 2^-30); the exact one is 2^-58.
        let h = 2f64.powi(-29);
        let r = solve_quadratic(1.0, 2.0 + h, 1.0 + h);
        assert_eq!(r.as_slice(), &[-(1.0 + h), -1.0]);
    }

    #[test]
    fn subnormal_leading_or_constant_coefficients_keep_both_roots() {
        // Found by the fuzz target `poly`: the large root overflowed to ±∞ (a quotient by a
        // subnormal a) and the small one lost bits (c/q formed in the subnormal range).
        // Expected: the nearest floats to the exact roots (mpmath, 80 digits).
        let cases = [
            (
                [2.14964753e-315, -9.313069759778103e-10, 2.53e-321],
                [2.716200105827e-312, 4.33237059909601e305],
            ),
            (
                [1.553e-320, 8.837381374653466e-14, -1e-323],
                [-5.691078280515176e306, 1.11812679547425e-310],
            ),
            (
                [3.6455701910074625e-304, 0.0859375, 5e-324],
                [-2.357312998992099e302, -6e-323],
            ),
        ];
        for ([a, b, c], want) in cases {
            assert_eq!(
                solve_quadratic(a, b, c).as_slice(),
                &want,
                "{a:e} {b:e} {c:e}"
            );
        }
    }

    #[test]
    fn the_sign_of_a_zero_coefficient_does_not_matter() {
        let plus = solve_quadratic(0.3, 0.0, -0.7);
        let minus = solve_quadratic(0.3, -0.0, -0.7);
        assert_eq!(plus, minus);
        assert_eq!(plus[0], -plus[1]);
    }

    #[test]
    fn roots_far_apart_keep_their_bits() {
        // 5e-324·x² + x + 1e-302: the small root is −1e-302·(1 + 5e-626): exactly −1e-302
        // in float64. The scaled constant term would be subnormal.
        let r = solve_quadratic(5e-324, 1.0, 1e-302);
        assert_eq!(r.len(), 2);
        assert_eq!(r[0], f64::NEG_INFINITY);
        assert_eq!(r[1], -1e-302);
    }

    #[test]
    fn linear_and_degenerate() {
        assert_eq!(solve_quadratic(0.0, 2.0, -4.0).as_slice(), &[2.0]);
        assert!(solve_quadratic(0.0, 0.0, 1.0).is_empty());
        assert_eq!(solve_quadratic(2.0, -4.0, 0.0).as_slice(), &[0.0, 2.0]);
        assert!(solve_quadratic(f64::NAN, 1.0, 1.0).is_empty());
    }

    #[test]
    fn extreme_scales() {
        for k in [-300, -150, -20, 0, 20, 150, 300] {
            let s = 10f64.powi(k);
            // (x − s)(x − 2s) = x² − 3s·x + 2s²  → scaled by s^-1 to stay in range.
            let r = solve_quadratic(1.0 / s, -3.0, 2.0 * s);
            assert_eq!(r.len(), 2, "k = {k}");
            assert!(
                (r[0] / s - 1.0).abs() < 4.0 * f64::EPSILON,
                "k = {k}: {r:?}"
            );
            assert!(
                (r[1] / s - 2.0).abs() < 4.0 * f64::EPSILON,
                "k = {k}: {r:?}"
            );
        }
    }
}
