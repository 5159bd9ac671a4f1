//! Polynomial evaluation (Horner's rule), and the residual tests and root polishing the
//! cubic and quartic solvers build on it.

/// The value of the polynomial with coefficients `coeffs` (highest degree first) at `x`, by
/// Horner's rule with fused multiply-adds.
///
/// An empty slice is the zero polynomial. The rounding error is at most about
/// `2·n·ε·Σ|cᵢ·xⁱ|` for degree `n` (ε = 2⁻⁵³); near a root that bound, not the value, is what
/// the float result can tell.
///
/// ```
/// use ballcollide::poly::eval;
/// // 2x³ − 3x + 1 at x = 2
/// assert_eq!(eval(&[2.0, 0.0, -3.0, 1.0], 2.0), 11.0);
/// assert_eq!(eval(&[], 5.0), 0.0);
/// ```
pub fn eval(coeffs: &[f64], x: f64) -> f64 {
    coeffs.iter().fold(0.0, |acc, &c| acc.mul_add(x, c))
}

/// `p(x)` by compensated Horner (Graillat, Langlois & Louvet 2005) and `p′(x)` by plain
/// Horner, with `coeffs` highest degree first.
///
/// The compensated value is as accurate as if computed in twice the working precision, then
/// rounded: near a simple root it still has correct leading digits where plain Horner returns
/// noise, which is what lets Newton's method converge to the last bit. The derivative only
/// sets the step length, so plain Horner is enough for it.
pub(crate) fn eval_compensated(coeffs: &[f64], x: f64) -> (f64, f64) {
    let Some((&first, rest)) = coeffs.split_first() else {
        return (0.0, 0.0);
    };
    let mut s = first;
    let mut err = 0.0_f64;
    let mut ds = 0.0_f64;
    for &c in rest {
        ds = ds * x + s;
        // s·x + c with both rounding errors captured exactly (TwoProduct by FMA, TwoSum).
        let p = s * x;
        let pe = s.mul_add(x, -p);
        let t = p + c;
        let z = t - p;
        let se = (p - (t - z)) + (c - z);
        err = err * x + (pe + se);
        s = t;
    }
    (s + err, ds)
}

/// `Σ|cᵢ|·|x|ⁱ`: the scale of the terms of `p(x)`. A relative change `δ` of every coefficient
/// changes `p(x)` by at most `δ` times this, so it is the yardstick for "`p(x)` is zero as far
/// as the coefficients can tell".
pub(crate) fn abs_sum(coeffs: &[f64], x: f64) -> f64 {
    // Plain arithmetic: a magnitude, needed to a few ulp only (and a fused multiply-add is a
    // library call on baseline x86-64).
    let ax = x.abs();
    coeffs.iter().fold(0.0, |acc, &c| acc * ax + c.abs())
}

/// Whether the complex pair `u ± iv` of roots of `p` is, as far as the coefficients can tell,
/// a real double root at `u`: whether a relative change of `factor·ε/2` in each coefficient
/// can move the root `z = u + iv` onto the real axis.
///
/// With the Taylor coefficients `t_k = p⁽ᵏ⁾(z)/k!`, the root moves by at least `Δ` only if
/// `Σ_{k≥1} |t_k|·Δᵏ` reaches the change `factor·ε/2·Σ|cᵢ||z|ⁱ` of `p`; so the pair can
/// collapse when that sum, taken at `Δ = v`, is below it. This is the conditioning band of a
/// double root (its width grows like √ε), and it looks at the pair itself: a pair whose real
/// part happens to be another, simple, root is not mistaken for a double root.
///
/// The solvers use it so that exact multiple roots such as `(x − 1)⁴`, which rounding pushes a
/// little off the real axis, come back real.
pub(crate) fn pair_within_rounding(coeffs: &[f64], u: f64, v: f64, factor: f64) -> bool {
    let n = coeffs.len();
    if n < 2 || !(u.is_finite() && v.is_finite()) {
        return false;
    }
    // Quick rejection, which settles almost every pair: the top Taylor term alone,
    // |c_n|·vⁿ, already exceeds the allowance (bounded above using |z| ≤ |u| + v).
    let allowance = |size: f64| factor * f64::EPSILON * 0.5 * size;
    let mut top = coeffs[0].abs();
    for _ in 1..n {
        top *= v;
    }
    if top > allowance(abs_sum(coeffs, u.abs() + v)) {
        return false;
    }

    // Taylor coefficients at z by repeated complex synthetic division (degree ≤ 4).
    let mut work = [(0.0_f64, 0.0_f64); 5];
    for (w, &c) in work.iter_mut().zip(coeffs) {
        *w = (c, 0.0);
    }
    let n = n.min(work.len());
    let mut moved = 0.0;
    let mut vk = 1.0;
    for k in 0..n {
        // After k divisions the first n − k entries are the quotient so far; the remainder of
        // the next division is t_k.
        let mut acc = (0.0, 0.0);
        for w in work.iter_mut().take(n - k) {
            acc = (acc.0 * u - acc.1 * v + w.0, acc.0 * v + acc.1 * u + w.1);
            *w = acc;
        }
        if k > 0 {
            moved += acc.0.hypot(acc.1) * vk;
        }
        vk *= v;
    }
    moved <= allowance(abs_sum(coeffs, u.hypot(v)))
}

/// Refines each root in `roots` by guarded Newton steps on `p` (compensated residual).
///
/// A step is taken only if it strictly lowers `|p|` and moves the root by less than half its
/// distance to every other root, so a cluster (where Newton is slow and may jump to a
/// neighbour) is left as the solver made it, and a multiple root reported several times is not
/// torn apart. A well-conditioned root ends within an ulp or so of the exact root of `p`.
pub(crate) fn polish_roots(coeffs: &[f64], roots: &mut [f64]) {
    for i in 0..roots.len() {
        let mut gap = f64::INFINITY;
        for (j, &r) in roots.iter().enumerate() {
            if j != i {
                gap = gap.min((r - roots[i]).abs());
            }
        }
        let mut x = roots[i];
        let (mut px, mut dpx) = eval_compensated(coeffs, x);
        for _ in 0..8 {
            if px == 0.0 || dpx == 0.0 || !px.is_finite() || !dpx.is_finite() {
                break;
            }
            let step = px / dpx;
            let next = x - step;
            if !next.is_finite() || next == x || 2.0 * ((next - roots[i]).abs()) >= gap {
                break;
            }
            let (pn, dpn) = eval_compensated(coeffs, next);
            if pn.abs() >= px.abs() {
                break;
            }
            x = next;
            px = pn;
            dpx = dpn;
        }
        roots[i] = x;
    }
}

/// Up to four roots under construction, in a scaled variable, before they are polished,
/// unscaled and sorted into a [`RealRoots`](super::RealRoots).
#[derive(Clone, Copy, Default)]
pub(crate) struct RootBuf {
    values: [f64; 4],
    len: usize,
}

impl RootBuf {
    /// Appends a root (ignored past four, or if NaN).
    pub(crate) fn push(&mut self, x: f64) {
        if self.len < self.values.len() && !x.is_nan() {
            self.values[self.len] = x;
            self.len += 1;
        }
    }

    /// The roots so far.
    pub(crate) fn as_slice(&self) -> &[f64] {
        &self.values[..self.len]
    }

    /// The roots so far, to be changed in place.
    pub(crate) fn as_mut_slice(&mut self) -> &mut [f64] {
        &mut self.values[..self.len]
    }

    /// The roots multiplied by `2^s` (exactly), sorted.
    pub(crate) fn unscaled(&self, s: i32) -> super::RealRoots {
        let mut out = [0.0; 4];
        for (o, &v) in out.iter_mut().zip(&self.values[..self.len]) {
            *o = super::scaling::scale(v, s);
        }
        super::RealRoots::from_unsorted(&out[..self.len])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compensated_horner_sees_through_cancellation() {
        // (x − 1)⁵ expanded, near x = 1: plain Horner returns rounding noise, the compensated
        // value keeps the sign and size of (x − 1)⁵.
        let c = [1.0, -5.0, 10.0, -10.0, 5.0, -1.0];
        let x = 1.0 + 2f64.powi(-10);
        let (p, _) = eval_compensated(&c, x);
        let exact = 2f64.powi(-50);
        assert!((p - exact).abs() <= 1e-3 * exact, "{p} vs {exact}");
    }

    #[test]
    fn polishing_reaches_the_last_bit_and_spares_clusters() {
        // (x − 1)(x − 2)(x − 3): start each root off by 1e-9.
        let c = [1.0, -6.0, 11.0, -6.0];
        let mut r = [1.0 + 1e-9, 2.0 - 1e-9, 3.0 + 1e-9];
        polish_roots(&c, &mut r);
        assert_eq!(r, [1.0, 2.0, 3.0]);
        // A double root reported twice is not pulled apart.
        let c = [1.0, -2.0, 1.0];
        let mut r = [1.0 + 1e-9, 1.0 + 1e-9];
        polish_roots(&c, &mut r);
        assert_eq!(r[0], r[1]);
    }

    #[test]
    fn pair_within_rounding_is_the_double_root_band() {
        // (x − 1)² + v²: with v = 1e-9 the pair is a double root as far as rounding goes
        // (the band is about √ε ≈ 1e-8), with v = 1e-6 it is not.
        for (v, inside) in [(1e-9, true), (1e-6, false)] {
            let c = [1.0, -2.0, 1.0 + v * v];
            assert_eq!(pair_within_rounding(&c, 1.0, v, 8.0), inside, "v = {v}");
        }
        // (x − 1)(x² − 2x + 1 + 1e14): the pair 1 ± 1e7·i has real part 1, a simple root;
        // p(1) = 0 but the pair is far from double.
        let c = [1.0, -3.0, 1e14 + 3.0, -(1e14 + 1.0)];
        assert!(!pair_within_rounding(&c, 1.0, 1e7, 8.0));
    }
}
