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
        ds = ds.mul_add(x, s);
        // s·x + c with both rounding errors captured exactly (TwoProduct by FMA, TwoSum).
        let p = s * x;
        let pe = s.mul_add(x, -p);
        let t = p + c;
        let z = t - p;
        let se = (p - (t - z)) + (c - z);
        err = err.mul_add(x, pe + se);
        s = t;
    }
    (s + err, ds)
}

/// `Σ|cᵢ|·|x|ⁱ`: the scale of the terms of `p(x)`. A relative change `δ` of every coefficient
/// changes `p(x)` by at most `δ` times this, so it is the yardstick for "`p(x)` is zero as far
/// as the coefficients can tell".
pub(crate) fn abs_sum(coeffs: &[f64], x: f64) -> f64 {
    let ax = x.abs();
    coeffs.iter().fold(0.0, |acc, &c| acc.mul_add(ax, c.abs()))
}

/// Whether `x` is a root of `p` up to a relative change of `factor·ε` in each coefficient:
/// `|p(x)| ≤ factor·ε·Σ|cᵢ||x|ⁱ` (Oettli–Prager backward error for one point).
///
/// The solvers use it to decide that a pair of complex roots `u ± iv` with a tiny `v` is a real
/// double root at `u` that rounding pushed off the real axis: if `p(u)` is zero within what one
/// rounding of the coefficients can change, the data cannot tell the two apart, and exact
/// multiple roots such as `(x − 1)⁴` then come back real.
pub(crate) fn is_root_within(coeffs: &[f64], x: f64, factor: f64) -> bool {
    let (p, _) = eval_compensated(coeffs, x);
    p.abs() <= factor * f64::EPSILON * 0.5 * abs_sum(coeffs, x)
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
        for _ in 0..4 {
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
    fn root_within_rounding() {
        // x² − 2 at the float nearest √2: zero as far as the coefficients can tell.
        assert!(is_root_within(&[1.0, 0.0, -2.0], 2f64.sqrt(), 4.0));
        assert!(!is_root_within(&[1.0, 0.0, -2.0], 1.4143, 4.0));
    }
}
