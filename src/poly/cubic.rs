//! Real roots of a cubic: one root by safeguarded Newton iteration (Kahan), deflation to a
//! stable quadratic, and a polishing step; plus the scaling helpers the quartic shares.

use super::horner::{RootBuf, eval_compensated, pair_within_rounding, polish_roots};
use super::newton_polygon::split_point;
use super::scaling::{exponent, scale};
use super::{RealRoots, real_roots, solve_quadratic};

/// A backward-error allowance, in units of ε/2, under which a complex pair `u ± iv` is taken as
/// the real double root `u` (see [`pair_within_rounding`]): a few roundings of the
/// coefficients, i.e. within about √8 conditioning floors of the real axis.
pub(super) const TOUCH_FACTOR: f64 = 4.0;

/// The real roots of `a·x³ + b·x² + c·x + d = 0`, ascending, with multiplicity.
///
/// Not Cardano's formula, which loses accuracy near multiple roots and for badly scaled
/// coefficients. Instead, following Kahan ("To solve a real cubic equation", 1986) and the
/// spirit of Flocke's Algorithm 954 (ACM TOMS 41(4), 2015):
/// 1. coefficients and variable are rescaled by exact powers of two so that the roots are of
///    order one and nothing overflows or underflows (coefficients from 1e-300 to 1e300 work;
///    when two groups of roots are more than 2⁶⁴ apart in magnitude the cubic is split into a
///    lower-degree polynomial for each group, which is exact to far below one rounding);
/// 2. one real root is found by Newton's method started beyond it on the side where the cubic
///    is convex, so the iterates approach it monotonically and cannot diverge;
/// 3. the cubic is deflated by that root (forward or backward, whichever is stable) and the
///    quadratic left is solved by [`solve_quadratic`];
/// 4. each root is refined by guarded Newton steps with a compensated residual. A pair of
///    complex roots `u ± iv` at which the cubic is zero within a few roundings of its
///    coefficients is reported as the real double root `u`: so exact multiple roots such as
///    `(x − 1)³` come back real.
///
/// `a = 0` falls back to [`solve_quadratic`]; `d = 0` gives the root 0 and the quadratic
/// `a·x² + b·x + c`. A root too large for a float is reported as ±∞. Any non-finite
/// coefficient gives no root (the polynomial is not defined).
///
/// ```
/// use ballcollide::poly::solve_cubic;
/// // (x − 1)(x − 2)(x − 3)
/// assert_eq!(solve_cubic(1.0, -6.0, 11.0, -6.0).as_slice(), &[1.0, 2.0, 3.0]);
/// // (x − 1)³: the triple root stays real.
/// assert_eq!(solve_cubic(1.0, -3.0, 3.0, -1.0).as_slice(), &[1.0, 1.0, 1.0]);
/// // x³ + 1: one real root, −1.
/// assert_eq!(solve_cubic(1.0, 0.0, 0.0, 1.0).as_slice(), &[-1.0]);
/// // A tiny leading coefficient: roots near 1e-300·(…) and a huge one at −1e300.
/// let r = solve_cubic(1e-300, 1.0, -3.0, 2.0);
/// assert_eq!(r.len(), 3);
/// assert!((r[0] + 1e300).abs() <= 1e285 && r[1] == 1.0 && r[2] == 2.0);
/// assert!(solve_cubic(f64::NAN, 1.0, 1.0, 1.0).is_empty());
/// ```
pub fn solve_cubic(a: f64, b: f64, c: f64, d: f64) -> RealRoots {
    if !(a.is_finite() && b.is_finite() && c.is_finite() && d.is_finite()) {
        return RealRoots::empty();
    }
    if a == 0.0 {
        return solve_quadratic(b, c, d);
    }
    if d == 0.0 {
        let mut roots = solve_quadratic(a, b, c);
        roots.push(0.0);
        roots.sort();
        return roots;
    }
    split_or_scale([a, b, c, d], cubic_scaled)
}

/// The last step shared by the cubic and quartic solvers, for finite coefficients with
/// non-zero first and last ones: a polynomial whose roots form two groups far apart in
/// magnitude is split and each part solved on its own; otherwise coefficients and variable are
/// scaled by powers of two for `solve_scaled`, whose roots are then scaled back.
pub(super) fn split_or_scale<const N: usize>(
    coeffs: [f64; N],
    solve_scaled: fn([f64; N]) -> RootBuf,
) -> RealRoots {
    let exps = exponents(&coeffs);
    if let Some(i) = split_point(&exps) {
        return merge(
            // Each part has degree below N − 1: no endless recursion.
            real_roots(&coeffs[..=i]),
            real_roots(&coeffs[i..]),
        );
    }
    let (Some(en), Some(s)) = (exps[0], root_exponent(&exps)) else {
        return RealRoots::empty(); // unreachable: the first and last coefficients are non-zero
    };
    solve_scaled(scaled(&coeffs, en, s)).unscaled(s)
}

/// The roots of a cubic whose coefficients `p` have been scaled so that `p[0] ∈ [1, 2)`,
/// `|p[k]| < 2` and `p[3] ≠ 0`, in the scaled variable.
fn cubic_scaled(p: [f64; 4]) -> RootBuf {
    let [a, b, c, d] = p;
    // Start at the inflection point; the sign of p there says on which side a root lies.
    let mut x = -(b / a) / 3.0;
    let (mut q, mut dq, mut b1, mut c2) = eval_newton(&p, x);
    if q != 0.0 {
        // Kahan's bound: x − s·r lies beyond the root on that side (r ≥ its distance from the
        // inflection point), where the cubic is convex towards the root, so Newton's iterates
        // move monotonically towards it. The step is shortened by one part in 1e15 so that
        // rounding cannot carry an iterate past the root.
        let t = q / a;
        let mut r = t.abs().cbrt();
        let s = t.signum();
        let t = -dq / a;
        if t > 0.0 {
            r = 1.324718 * r.max(t.sqrt());
        }
        let mut x0 = x - s * r;
        if x0 != x {
            // Monotone convergence ends when an iterate stops moving forward; for a triple root
            // convergence is linear (ratio 2/3), so 200 steps reach any float.
            let mut last = (q, dq, b1, c2);
            for _ in 0..200 {
                let cur = eval_newton(&p, x0);
                if cur.0 == 0.0 {
                    x = x0;
                    last = cur;
                    break;
                }
                let next = if cur.1 == 0.0 {
                    x0
                } else {
                    x0 - (cur.0 / cur.1) / 1.000_000_000_000_001
                };
                x = x0;
                last = cur;
                // The start is on the −s side of the root, so progress is in the +s direction.
                if s * next <= s * x0 || !next.is_finite() {
                    break;
                }
                x0 = next;
            }
            (q, dq, b1, c2) = last;
            let _ = (q, dq);
            // Backward deflation (from the constant term) is the stable one when the found
            // root is large compared with the others.
            if x != 0.0 && a.abs() * x * x > (d / x).abs() {
                c2 = -d / x;
                b1 = (c2 - c) / x;
            }
        }
    }
    let mut roots = RootBuf::default();
    roots.push(x);
    push_quadratic_roots(&p, a, b1, c2, &mut roots);
    polish_roots(&p, roots.as_mut_slice());
    roots
}

/// [`eval_deflate`] with `p(x)` from compensated Horner: near a cluster of roots plain
/// Horner's rounding noise would hide the sign of `p` (which picks the side the iteration
/// starts from) and stop the iteration far from the root; the compensated value stays
/// accurate down to about ε² of the size of the terms.
fn eval_newton(p: &[f64; 4], x: f64) -> (f64, f64, f64, f64) {
    let (_, dq, b1, c2) = eval_deflate(p, x);
    let (q, _) = eval_compensated(p, x);
    (q, dq, b1, c2)
}

/// `p(x)`, `p′(x)` and the quotient `a·y² + b1·y + c2` of `p` by `(y − x)`.
fn eval_deflate(p: &[f64; 4], x: f64) -> (f64, f64, f64, f64) {
    let [a, b, c, d] = *p;
    let q0 = a * x;
    let b1 = q0 + b;
    let c2 = b1.mul_add(x, c);
    let dq = (q0 + b1).mul_add(x, c2);
    let q = c2.mul_add(x, d);
    (q, dq, b1, c2)
}

/// Appends the roots of the quadratic factor `a·y² + b·y + c` of the polynomial `p`; a complex
/// pair `u ± iv` that a few roundings of `p`'s coefficients can turn into a real double root is
/// appended as the double root `u` (an exact double root that rounding pushed off the real
/// axis).
pub(super) fn push_quadratic_roots(p: &[f64], a: f64, b: f64, c: f64, roots: &mut RootBuf) {
    // A discriminant negative by far more than its rounding error (8ε of its terms, where the
    // stable solver's own is about 2ε) means a complex pair, which `solve_quadratic` would
    // report as no root: skip it (most ball–ball quartics have only complex roots).
    let (bb, ac4) = (b * b, 4.0 * a * c);
    let surely_complex = (bb - ac4) < -8.0 * f64::EPSILON * (bb + ac4.abs());
    let q = if surely_complex {
        RealRoots::empty()
    } else {
        solve_quadratic(a, b, c)
    };
    if q.is_empty() && a != 0.0 {
        let u = -b / (2.0 * a);
        // v² = c/a − u²; when it cancels (a near-double pair, where the decision is made) the
        // square's rounding error is recovered by a fused multiply-add.
        let ca = c / a;
        let mut v2 = ca - u * u;
        if v2.abs() < 1e-6 * ca.abs() {
            v2 = (-u).mul_add(u, ca);
        }
        let v = v2.max(0.0).sqrt();
        if u.is_finite() && pair_within_rounding(p, u, v, TOUCH_FACTOR) {
            roots.push(u);
            roots.push(u);
        }
    }
    for &r in &q {
        roots.push(r);
    }
}

/// The binary exponents of the coefficients ([`exponent`]; `None` for a zero), computed once
/// for [`split_point`], [`root_exponent`] and [`scaled`].
fn exponents<const N: usize>(coeffs: &[f64; N]) -> [Option<i32>; N] {
    coeffs.map(exponent)
}

/// The exponent `s` such that the roots of the polynomial with coefficient exponents `exps`
/// (highest degree first, leading one non-zero) are at most about `2^s` in magnitude: the largest `⌈(e_k − e_n)/(n − k)⌉` over
/// the non-zero coefficients (Fujiwara's bound in powers of two).
fn root_exponent(exps: &[Option<i32>]) -> Option<i32> {
    let en = (*exps.first()?)?;
    let mut s = i32::MIN;
    for (i, &e) in exps.iter().enumerate().skip(1) {
        if let Some(ek) = e {
            // ⌈num / (n − k)⌉ with n − k = i ∈ 1..=4; constant divisors compile to shifts and
            // multiplications, where a variable one would be a slow integer division.
            let num = ek - en;
            let up = match i {
                1 => num,
                2 => (num + 1) >> 1,
                3 => -((-num).div_euclid(3)),
                4 => (num + 3) >> 2,
                _ => -((-num).div_euclid(i as i32)),
            };
            s = s.max(up);
        }
    }
    Some(if s == i32::MIN { 0 } else { s })
}

/// The coefficients of `p(2^s·y)`, divided by a power of two so that the leading one lies in
/// `[1, 2)` (`en` is the leading coefficient's exponent): all exact (barring underflow of
/// coefficients that are negligible).
fn scaled<const N: usize>(coeffs: &[f64; N], en: i32, s: i32) -> [f64; N] {
    let mut out = [0.0; N];
    for (i, (o, &c)) in out.iter_mut().zip(coeffs).enumerate() {
        // Degree k = N − 1 − i; the factor is 2^(s·k − s·(N − 1) − en) = 2^(−s·i − en).
        *o = scale(c, -s * i as i32 - en);
    }
    out
}

/// The union of two root sets, sorted.
pub(super) fn merge(x: RealRoots, y: RealRoots) -> RealRoots {
    let mut out = x;
    for &r in &y {
        out.push(r);
    }
    out.sort();
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn root_exponent_bounds_the_roots() {
        // Roots 1e3, 2e3, 3e3: 2^s ≥ 3e3 and not hugely more.
        let s = root_exponent(&exponents(&[1.0, -6e3, 11e6, -6e9])).unwrap_or(0);
        assert!((12..=14).contains(&s), "{s}");
    }

    #[test]
    fn multiple_roots_are_real() {
        assert_eq!(solve_cubic(1.0, -3.0, 3.0, -1.0).as_slice(), &[1.0; 3]);
        assert_eq!(
            solve_cubic(1.0, 0.0, -3.0, 2.0).as_slice(),
            &[-2.0, 1.0, 1.0]
        );
        // (x − 0.1)³ with rounded coefficients: still three real roots near 0.1.
        let r = solve_cubic(1.0, -0.3, 0.03, -0.001);
        assert!(!r.is_empty());
        for x in &r {
            assert!((x - 0.1).abs() < 1e-5, "{r:?}");
        }
    }

    #[test]
    fn degenerate_and_bad_input() {
        assert_eq!(solve_cubic(0.0, 1.0, -3.0, 2.0).as_slice(), &[1.0, 2.0]);
        assert_eq!(
            solve_cubic(1.0, -3.0, 2.0, 0.0).as_slice(),
            &[0.0, 1.0, 2.0]
        );
        assert!(solve_cubic(1.0, f64::INFINITY, 0.0, 1.0).is_empty());
        assert!(solve_cubic(0.0, 0.0, 0.0, 0.0).is_empty());
    }
}
