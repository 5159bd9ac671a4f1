//! Real roots of a quartic by Algorithm 1010 (Orellana & De Michele, ACM TOMS 46(2), 2020)
//! with the corrections of its two published Remarks (De Michele, ACM TOMS 2022 and 2024).
//!
//! # The method, in brief
//!
//! A monic quartic `x⁴ + a·x³ + b·x² + c·x + d` equals `vᵀ·M(φ)·v` with `v = (x², x, 1)` and
//!
//! ```text
//!        ⎡ 1      a/2        b/6 + φ/2 ⎤
//! M(φ) = ⎢ a/2    2b/3 − φ   c/2       ⎥      for every φ.
//!        ⎣ b/6+φ/2  c/2      d         ⎦
//! ```
//!
//! Its LDLᵀ factorisation, with `L = [[1,0,0],[l₁,1,0],[l₃,l₂,1]]` and `D = diag(1, d₂, d₃)`,
//! writes the quartic as `(x² + l₁x + l₃)² + d₂(x + l₂)² + d₃`. Choosing `φ` as a root of
//! `det M(φ) = 0` — the resolvent cubic `φ³ + gφ + h` — makes `d₃ = 0`, and then
//! - `d₂ < 0`: two real quadratic factors `x² + (l₁ ± γ)x + (l₃ ± γl₂)`, `γ = √−d₂`;
//! - `d₂ > 0`: two complex-conjugate factors (no simple real roots);
//! - `d₂ ≈ 0`: `l₂` is undetermined and the factors are taken from `d₃ = d − l₃²` instead,
//!   `x² + l₁x + l₃ ± √−d₃`.
//!
//! The paper takes the root of largest magnitude (the *dominant* root) of the resolvent, which
//! it computes from a shifted quartic (so that `g` and `h` are formed without cancellation)
//! and refines by Newton; it picks, among algebraically equivalent formulas for `d₂`, `l₂` and
//! the factor coefficients, the one with the smallest backward error; and it polishes the real
//! factors by Newton's method on the four equations that tie them to `a, b, c, d`.
//!
//! The Remarks correct the test that switches to the `d₂ ≈ 0` branch. The 2020 test
//! `|d₂| ≤ ε·max(|2b/3|, |φ|, l₁²)` missed cases where rounding leaves `d₂` slightly off zero:
//! the 2022 Remark compares with the sum `ε·(|2b/3| + |φ| + l₁²)`, and the 2024 Remark widens
//! the factor to `√ε`, keeping the `d₂ ≈ 0` factorisation only when its backward error is the
//! smaller one. Both published counter-examples are in this crate's tests.
//!
//! # What this implementation adds
//!
//! - Degenerate forms are dispatched first (`a = 0` → cubic, `e = 0` → root 0 and a cubic,
//!   `b = d = 0` → a quadratic in `x²`), and the coefficients and the variable are rescaled by
//!   exact powers of two so the roots are of order one (the paper divides by the leading
//!   coefficient and rescales by a constant only after an overflow). Roots that are more than
//!   2⁶⁴ apart in magnitude are split into separate lower-degree problems first (read off the
//!   Newton polygon of the coefficients), so a tiny leading coefficient never loses the
//!   ordinary roots.
//! - The complex-factor branches are turned into the real quadratic factors of the conjugate
//!   root pairs, which are polished the same way; a complex pair at whose real part the
//!   quartic vanishes within a few roundings is an exact double root pushed off the real axis
//!   by rounding, and is reported as real (so `(x − 1)⁴` has four real roots).
//! - Every real root is finally refined by guarded Newton steps on the (exactly scaled)
//!   original quartic with a compensated residual.

use super::bracketed::bracketed_newton;
use super::cubic::{merge, push_quadratic_roots, split_or_scale};
use super::horner::{RootBuf, abs_sum, eval_compensated, polish_roots};
use super::newton_polygon::monic_quartic_envelope;
use super::{RealRoots, solve_cubic};

/// √ε (ε = 2⁻⁵²): the 2024 Remark's threshold factor for the `d₂ ≈ 0` test.
const SQRT_EPS: f64 = 1.490_116_119_384_765_6e-8;

/// The real roots of `a·x⁴ + b·x³ + c·x² + d·x + e = 0`, ascending, with multiplicity.
///
/// Algorithm 1010 of ACM TOMS with both published Remarks: an LDLᵀ factorisation into two
/// quadratics from the dominant root of a resolvent cubic, a backward-error-driven choice
/// among equivalent formulas, the Remarks' corrected switch to the `d₂ ≈ 0` branch, and
/// Newton-polished factors (the method and what this implementation adds to it are described
/// at the top of `src/poly/quartic.rs`). Roots come out accurate to a
/// small multiple of what the float coefficients determine: a few ulp for well-separated
/// roots, about `√ε` relative for a double root, `ε^(1/m)` for an `m`-fold one.
///
/// - `a = 0` → [`solve_cubic`]`(b, c, d, e)`; `e = 0` → the root 0 and the cubic; `b = d = 0`
///   → the quadratic in `x²`. A tiny `a` is not a problem: it means a huge root, which is
///   found (or reported as ±∞ if it exceeds the float range) along with the others.
/// - Coefficients anywhere from 1e-300 to 1e300 work (exact power-of-two rescaling).
/// - Any non-finite coefficient gives no root: the polynomial is not defined.
///
/// ```
/// use ballcollide::poly::solve_quartic;
/// // (x − 1)(x − 2)(x − 3)(x − 4)
/// let r = solve_quartic(1.0, -10.0, 35.0, -50.0, 24.0);
/// assert_eq!(r.as_slice(), &[1.0, 2.0, 3.0, 4.0]);
/// // (x² + 1)²: no real root; (x − 1)⁴: a quadruple real root.
/// assert!(solve_quartic(1.0, 0.0, 2.0, 0.0, 1.0).is_empty());
/// let r = solve_quartic(1.0, -4.0, 6.0, -4.0, 1.0);
/// assert_eq!(r.len(), 4);
/// assert!(r.iter().all(|x| (x - 1.0).abs() < 1e-3));
/// // A tiny leading coefficient with a root near −1.017e15 (Flocke's example).
/// let r = solve_quartic(-5.898376305898030e-09, -6.000000000001007e+06,
///                       3.664603343001005e-27, 0.0, 9.000000000003021e+02);
/// assert_eq!(r.len(), 2);
/// assert!((r[0] / -1.0172290964212235e15 - 1.0).abs() < 1e-15);
/// assert!((r[1] / 0.05313292845913352 - 1.0).abs() < 1e-15);
/// assert!(solve_quartic(1.0, f64::NAN, 0.0, 0.0, 1.0).is_empty());
/// ```
pub fn solve_quartic(a: f64, b: f64, c: f64, d: f64, e: f64) -> RealRoots {
    if ![a, b, c, d, e].iter().all(|x| x.is_finite()) {
        return RealRoots::empty();
    }
    if a == 0.0 {
        return solve_cubic(b, c, d, e);
    }
    if e == 0.0 {
        return merge(solve_cubic(a, b, c, d), RealRoots::from_unsorted(&[0.0]));
    }
    if b == 0.0 && d == 0.0 {
        return split_or_scale([a, 0.0, c, 0.0, e], biquadratic_scaled);
    }
    split_or_scale([a, b, c, d, e], quartic_scaled)
}

/// `a·x⁴ + c·x² + e`, scaled as by [`quartic_scaled`], through the quadratic
/// `a·z² + c·z + e` in `z = x²`.
///
/// Scaled first, like every other quartic: in the original variable `z = x²` is the square
/// of a root, which overflows for roots beyond 1.3e154 and loses bits in the subnormal range
/// for roots below 1.5e-154, although the roots themselves are ordinary floats.
fn biquadratic_scaled(p: [f64; 5]) -> RootBuf {
    let [a, _, c, _, e] = p;
    let mut z = RootBuf::default();
    push_quadratic_roots(&[a, c, e], a, c, e, &mut z);
    let mut roots = RootBuf::default();
    for &zi in z.as_mut_slice().iter() {
        if zi >= 0.0 {
            let r = zi.sqrt();
            roots.push(-r);
            roots.push(r);
        }
    }
    roots
}

/// The roots, in the scaled variable, of a quartic `p` scaled as by [`scaled`]
/// (`p[0] ∈ [1, 2)`, all `|p[k]| < 2`, `p[4] ≠ 0`).
fn quartic_scaled(p: [f64; 5]) -> RootBuf {
    let lead = p[0];
    // A zero coefficient as +0 (`x + 0.0` leaves every other value as it is), whatever the
    // signs of it and of the leading coefficient: the factorisation's square and cube roots
    // take signs from intermediate values that a −0 can flip (found by the fuzzer:
    // −53·x⁴ ± 0·x³ + a·(x + 1)², a double root perturbed, gave roots an ulp apart), and the
    // roots must depend neither on the sign of a zero nor on that of the polynomial.
    let [b, c, d, e] = [p[1], p[2], p[3], p[4]].map(|x| x / lead + 0.0);
    let q = Monic::new(b, c, d, e);
    let f = polish_factors(q, factor(q));
    let mut roots = RootBuf::default();
    push_quadratic_roots(&p, 1.0, f[0], f[1], &mut roots);
    push_quadratic_roots(&p, 1.0, f[2], f[3], &mut roots);
    polish_roots(&p, roots.as_mut_slice());
    if all_vanish(&p, &roots) {
        roots
    } else {
        roots_by_pieces(&p)
    }
}

/// Whether `p` vanishes at each of `roots` as far as its coefficients can tell (a residual,
/// compensated, within [`RESIDUAL_ROUNDINGS`] roundings of the size of its terms), and they
/// are as many as a quartic's real roots can be (an even number). Where
/// the coefficients span nearly the 64 bits at which the Newton polygon splits the quartic
/// (`848.9375·x⁴ + c·x³ + c·x² + c·x − 13.625`, `c = 4.2e19`), the factorisation can get a
/// factor wrong: a complex pair near `x² + x + 1` came out as the real `x² + x + 0.0032`,
/// two roots at which `p` is as large as its terms, or a real pair with one root wrong.
fn all_vanish(p: &[f64; 5], roots: &RootBuf) -> bool {
    let roots = roots.as_slice();
    roots.len().is_multiple_of(2) && roots.iter().all(|&x| vanishes_at(p, x))
}

/// Whether `p` vanishes at `x` as far as its coefficients can tell: its compensated value
/// within [`RESIDUAL_ROUNDINGS`] roundings of the size of its terms.
fn vanishes_at(p: &[f64; 5], x: f64) -> bool {
    let (value, _) = eval_compensated(p, x);
    let allowed = RESIDUAL_ROUNDINGS * f64::EPSILON * abs_sum(p, x);
    value.abs().partial_cmp(&allowed) != Some(std::cmp::Ordering::Greater)
}

/// See [`all_vanish`]: far above the few roundings a rounded root leaves, far below the size
/// of the terms a wrong root leaves.
const RESIDUAL_ROUNDINGS: f64 = 4096.0;

/// The roots of the scaled quartic `p` (`|p[0]| ∈ [1, 2)`, all `|p[k]| < 2`, `p[4] ≠ 0`: every
/// root within `(−3, 3)`, none within `L = |p[4]|/(|p[4]| + 2)` of 0) piece by piece, where
/// its factorisation failed [`all_vanish`]: between consecutive critical points (the cubic
/// `p′`'s roots) and 0, `p` is monotone, and a sign change there holds one root: the bracket
/// narrowed geometrically to a factor of 4 (its ends may be 2⁻²⁰⁰ apart in magnitude), then
/// bracketed Newton on the compensated value. A critical point where `p` vanishes within its
/// rounding without a sign change is a double root. Slower than the factorisation, and as
/// sure as the cubic's roots.
fn roots_by_pieces(p: &[f64; 5]) -> RootBuf {
    const BOUND: f64 = 4.0;
    let value = |x: f64| eval_compensated(p, x);
    let least = p[4].abs() / (p[4].abs() + 2.0);
    let critical = solve_cubic(4.0 * p[0], 3.0 * p[1], 2.0 * p[2], p[3]);
    // The ends of the monotone pieces, ascending: −BOUND, the critical points, ±least
    // (around 0, where no root lies), BOUND.
    let mut marks = [0.0; 7];
    let mut count = 0;
    let mut add = |x: f64| {
        if x > -BOUND && x <= BOUND && (count == 0 || x > marks[count - 1]) {
            marks[count] = x;
            count += 1;
        }
    };
    let mut inner = critical.as_slice().iter().copied().peekable();
    for zero_side in [-least, least] {
        while let Some(&x) = inner.peek().filter(|&&x| x < zero_side) {
            add(x);
            inner.next();
        }
        add(zero_side);
    }
    inner.for_each(&mut add);
    add(BOUND);
    let mut roots = RootBuf::default();
    let (mut lo, mut f_lo) = (-BOUND, value(-BOUND).0);
    for (k, &hi) in marks[..count].iter().enumerate() {
        let f_hi = value(hi).0;
        if (f_lo < 0.0 && f_hi > 0.0) || (f_lo > 0.0 && f_hi < 0.0) {
            roots.push(root_in(&value, (lo, f_lo), (hi, f_hi)));
        } else if f_hi == 0.0 || (k + 1 < count && hi.abs() != least && vanishes_at(p, hi)) {
            // At a critical point, touching zero: a double root (or a root exactly there).
            let after = value(marks[..count].get(k + 1).copied().unwrap_or(BOUND)).0;
            let crosses = (f_hi == 0.0) && (f_lo < 0.0) != (after < 0.0);
            roots.push(hi);
            if !crosses {
                roots.push(hi);
            }
        }
        (lo, f_lo) = (hi, f_hi);
    }
    polish_roots(p, roots.as_mut_slice());
    roots
}

/// The root of `f` between `a` and `b` (of one sign, `f` of opposite signs there): the
/// bracket halved at the geometric mean of its ends' magnitudes until they are within a
/// factor of 4, then bracketed Newton.
fn root_in(
    f: &impl Fn(f64) -> (f64, f64),
    (mut a, mut fa): (f64, f64),
    (mut b, mut fb): (f64, f64),
) -> f64 {
    let sign = if a + b < 0.0 { -1.0 } else { 1.0 };
    for _ in 0..64 {
        let (small, large) = (a.abs().min(b.abs()), a.abs().max(b.abs()));
        if large <= 4.0 * small {
            break;
        }
        let mid = sign * (small.sqrt() * large.sqrt());
        let fm = f(mid).0;
        if fm == 0.0 {
            return mid;
        }
        if (fm < 0.0) == (fa < 0.0) {
            (a, fa) = (mid, fm);
        } else {
            (b, fb) = (mid, fm);
        }
    }
    bracketed_newton(f, a, b, fa, fb, 0.5 * (a + b), 0.0)
}

/// A monic quartic `x⁴ + a·x³ + b·x² + c·x + d`, with the yardsticks its backward errors are
/// measured against.
#[derive(Clone, Copy, Debug)]
struct Monic {
    a: f64,
    b: f64,
    c: f64,
    d: f64,
    /// For `a, b, c, d`: the height of the quartic's Newton polygon at that coefficient's
    /// degree ([`monic_quartic_envelope`]). An error in a coefficient that is small next to it is small
    /// next to the quartic's largest term at every `x`, so it never counts as large, however
    /// tiny the coefficient itself (see [`Monic::rel`]).
    envelope: [f64; 4],
}

impl Monic {
    fn new(a: f64, b: f64, c: f64, d: f64) -> Self {
        Self {
            a,
            b,
            c,
            d,
            envelope: monic_quartic_envelope(a, b, c, d),
        }
    }

    /// The error `r` of coefficient `k` (0 for `a` … 3 for `d`) relative to the size of the
    /// terms it was formed from, `size`, or to the coefficient's envelope if that is larger
    /// (0 when both are zero).
    ///
    /// The paper measures each error relative to its coefficient (absolutely for a zero one);
    /// that breaks down when a coefficient is tiny next to its terms (a coefficient `1e-57`
    /// next to terms of order one makes every rounding look like a relative error of `1e40`).
    /// Relative to the terms, the measure is the componentwise backward error, which rounding
    /// can achieve; but it still breaks down when a coefficient and its terms are all tiny
    /// next to the rest of the quartic (`x⁴ − 1.07x² + 1e-207·x + 1e-12`): the factorisation
    /// that drops the `x` term has a relative error of 1 there, as large as one that gets the
    /// constant term wrong, and the wrong one may be kept. The envelope is the size below
    /// which a coefficient's error cannot matter at any `x`: measured against it, dropping
    /// `1e-207·x` costs nothing, and getting `1e-12` wrong costs all.
    fn rel(&self, k: usize, r: f64, size: f64) -> f64 {
        // A plain comparison: f64::max's NaN handling costs instructions in this hot loop, and
        // a NaN size gives the envelope here just as it would there.
        let size = if size > self.envelope[k] {
            size
        } else {
            self.envelope[k]
        };
        if size > 0.0 { r.abs() / size } else { 0.0 }
    }
}

/// Two real quadratic factors `(x² + α₁x + β₁)(x² + α₂x + β₂)` of the monic quartic, as
/// `[α₁, β₁, α₂, β₂]`: the heart of Algorithm 1010.
fn factor(q: Monic) -> [f64; 4] {
    let Monic { a, b, c, d, .. } = q;
    let phi = resolvent_dominant_root(a, b, c, d);
    let l1 = a / 2.0;
    let l3 = b / 6.0 + phi / 2.0;
    let del2 = c - a * l3;
    // d₂ from the (2,2) entry of the LDLᵀ factorisation, and d − l₃², which is d₂·l₂² when
    // d₃ = 0; with del2 = 2·d₂·l₂ they give three algebraically equal (d₂, l₂) pairs, of which
    // the one that best reproduces b, c, d is kept (rounding makes them differ).
    let d2_direct = 2.0 * b / 3.0 - phi - l1 * l1;
    let d_minus_l3sq = d - l3 * l3;
    let mut best: Option<(f64, f64, f64)> = None;
    let mut consider = |d2: f64, l2: f64| {
        let err = ldlt_error(q, d2, l1, l2, l3);
        if err.is_finite() && best.is_none_or(|(e, _, _)| err < e) {
            best = Some((err, d2, l2));
        }
    };
    if d2_direct != 0.0 {
        consider(d2_direct, del2 / (2.0 * d2_direct));
    }
    if del2 != 0.0 {
        let l2 = 2.0 * d_minus_l3sq / del2;
        if l2 != 0.0 {
            consider(del2 / (2.0 * l2), l2);
        }
        consider(d2_direct, l2);
    }
    let (d2, l2) = best.map_or((0.0, 0.0), |(_, d2, l2)| (d2, l2));

    // The main branch (d₂ ≠ 0): real factors for d₂ < 0, complex-conjugate ones for d₂ > 0.
    let main: Option<(Factors, f64)> = if d2 < 0.0 {
        let f = real_branch(q, l1, l2, l3, (-d2).sqrt());
        Some((Factors::Real(f), coefficient_error(q, f)))
    } else if d2 > 0.0 {
        let g = d2.sqrt();
        let f = Factors::Complex {
            alpha: (l1, g),
            beta: (l3, g * l2),
        };
        let err = f.error(q);
        Some((f, err))
    } else {
        None
    };

    // The d₂ ≈ 0 branch, with the Remarks' switching test; it is used when its backward error
    // is smaller than the main branch's. d₂ is a summand of b = d₂ + l₁² + 2l₃, so it is
    // measured against b's envelope too: where the terms it is formed from are all far below
    // the Newton polygon (a = b = c ≈ 0 next to d, say), d₂ is rounding noise — possibly a
    // subnormal one that no relative threshold on those terms can recognise — however it
    // compares with them.
    let d2_scale = ((2.0 * b / 3.0).abs() + phi.abs() + l1 * l1).max(q.envelope[1]);
    let near_zero = d2.abs() <= SQRT_EPS * d2_scale;
    let chosen = match main {
        Some((f, _)) if !near_zero => f,
        main => {
            let d3 = d - l3 * l3;
            let alt = if d3 <= 0.0 {
                let r = (-d3).sqrt();
                let (b1, b2) = balance_product(l3 + r, l3 - r, d);
                Factors::Real([l1, b1, l1, b2])
            } else {
                Factors::Complex {
                    alpha: (l1, 0.0),
                    beta: (l3, d3.sqrt()),
                }
            };
            match main {
                Some((f, err0)) if err0 <= alt.error(q) => f,
                _ => alt,
            }
        }
    };
    chosen.real()
}

/// The two quadratic factors in one of the two forms the branches produce.
#[derive(Clone, Copy)]
enum Factors {
    /// `[α₁, β₁, α₂, β₂]`, all real.
    Real([f64; 4]),
    /// `x² + αx + β` and its conjugate, with `α = (re, im)`, `β = (re, im)`.
    Complex { alpha: (f64, f64), beta: (f64, f64) },
}

impl Factors {
    /// Backward error with which the factors reproduce `a, b, c, d` (each coefficient's error
    /// relative to the size of its terms, see [`Monic::rel`]).
    fn error(self, q: Monic) -> f64 {
        let Monic { a, b, c, d, .. } = q;
        match self {
            Factors::Real(f) => coefficient_error(q, f),
            Factors::Complex {
                alpha: (ar, ai),
                beta: (br, bi),
            } => {
                // (x² + αx + β)(x² + ᾱx + β̄) = x⁴ + 2Re α·x³ + (|α|² + 2Re β)·x²
                //                                 + 2Re(α·β̄)·x + |β|².
                let (m2, n2) = (ar * ar + ai * ai, br * br + bi * bi);
                q.rel(0, 2.0 * ar - a, 2.0 * ar.abs() + a.abs())
                    + q.rel(1, m2 + 2.0 * br - b, m2 + 2.0 * br.abs() + b.abs())
                    + q.rel(
                        2,
                        2.0 * (ar * br + ai * bi) - c,
                        2.0 * ((ar * br).abs() + (ai * bi).abs()) + c.abs(),
                    )
                    + q.rel(3, n2 - d, n2 + d.abs())
            }
        }
    }

    /// The real quadratic factors. For the complex form they are `(x − z)(x − z̄)` for the two
    /// roots `z` of `x² + αx + β` (the quartic's roots are those and their conjugates).
    fn real(self) -> [f64; 4] {
        match self {
            Factors::Real(f) => f,
            Factors::Complex { alpha, beta } => {
                let half = (-alpha.0 / 2.0, -alpha.1 / 2.0);
                // z = −α/2 ± √(α²/4 − β); the larger one from the formula, the other from the
                // product z₁z₂ = β, so neither suffers cancellation.
                let disc = csub(cmul(half, half), beta);
                let sq = csqrt(disc);
                let z1 = cadd(half, sq);
                let z2 = csub(half, sq);
                let (zmax, zmin_direct) = if cabs2(z1) >= cabs2(z2) {
                    (z1, z2)
                } else {
                    (z2, z1)
                };
                let zmin = if cabs2(zmax) > 0.0 {
                    cdiv(beta, zmax)
                } else {
                    zmin_direct
                };
                [-2.0 * zmax.0, cabs2(zmax), -2.0 * zmin.0, cabs2(zmin)]
            }
        }
    }
}

/// Case `d₂ < 0` (the paper's Case I): the real factors, with the smaller `|β|` recomputed from
/// `β₁β₂ = d` and the smaller `|α|` from whichever of the three equations that involve it
/// reproduces `a, b, c` best.
fn real_branch(q: Monic, l1: f64, l2: f64, l3: f64, g: f64) -> [f64; 4] {
    let Monic { a, b, c, d, .. } = q;
    let mut a1 = l1 + g;
    let mut a2 = l1 - g;
    let (b1, b2) = balance_product(l3 + g * l2, l3 - g * l2, d);
    // Each candidate solves one of α₁ + α₂ = a, β₁ + α₁α₂ + β₂ = b, α₁β₂ + β₁α₂ = c for the
    // smaller α (the larger one is the accurate sum l₁ ± γ without cancellation).
    let pick =
        |cands: [Option<f64>; 3], set: fn(f64, [f64; 4]) -> [f64; 4], base: [f64; 4]| -> f64 {
            let mut best = (f64::INFINITY, f64::NAN);
            for x in cands.into_iter().flatten() {
                let f = set(x, base);
                let [x1, y1, x2, y2] = f;
                let err = q.rel(0, x1 + x2 - a, x1.abs() + x2.abs() + a.abs())
                    + q.rel(
                        1,
                        y1 + x1 * x2 + y2 - b,
                        y1.abs() + (x1 * x2).abs() + y2.abs() + b.abs(),
                    )
                    + q.rel(
                        2,
                        x1 * y2 + y1 * x2 - c,
                        (x1 * y2).abs() + (y1 * x2).abs() + c.abs(),
                    );
                if err < best.0 || best.1.is_nan() {
                    best = (err, x);
                }
            }
            best.1
        };
    if a1.abs() < a2.abs() {
        let cands = [
            (b2 != 0.0).then(|| (c - b1 * a2) / b2),
            (a2 != 0.0).then(|| (b - b1 - b2) / a2),
            Some(a - a2),
        ];
        a1 = pick(cands, |x, f| [x, f[1], f[2], f[3]], [a1, b1, a2, b2]);
    } else {
        let cands = [
            (b1 != 0.0).then(|| (c - a1 * b2) / b1),
            (a1 != 0.0).then(|| (b - b1 - b2) / a1),
            Some(a - a1),
        ];
        a2 = pick(cands, |x, f| [f[0], f[1], x, f[3]], [a1, b1, a2, b2]);
    }
    [a1, b1, a2, b2]
}

/// The pair `(β₁, β₂)` with the smaller one recomputed as `d / larger`: a product is accurate
/// where a difference `l₃ − γ·l₂` may have cancelled.
fn balance_product(b1: f64, b2: f64, d: f64) -> (f64, f64) {
    if b2.abs() < b1.abs() {
        (b1, d / b1)
    } else if b2.abs() > b1.abs() {
        (d / b2, b2)
    } else {
        (b1, b2)
    }
}

/// The dominant (largest-magnitude) root `φ₀` of the resolvent cubic `det M(φ) = 0`, i.e.
/// `φ³ + g·φ + h = 0`, refined by Newton's method (up to 16 steps, stopped as soon as the
/// residual no longer decreases).
///
/// `g` and `h` are invariant under a shift `x → y + σ` of the quartic, so they are computed
/// from the shifted quartic whose `y²` coefficient vanishes (σ a root of `6σ² + 3aσ + b`, the
/// smaller one, when real) or else whose `y³` coefficient does (σ = −a/4): that is what keeps
/// `g` and `h` free of cancellation.
fn resolvent_dominant_root(a: f64, b: f64, c: f64, d: f64) -> f64 {
    let disc = 9.0 * a * a - 24.0 * b;
    let s = if disc > 0.0 {
        -2.0 * b / (3.0 * a + disc.sqrt().copysign(a))
    } else {
        -a / 4.0
    };
    let aq = a + 4.0 * s;
    let bq = b + 3.0 * s * (a + 2.0 * s);
    let cq = c + s * (2.0 * b + s * (3.0 * a + 4.0 * s));
    let dq = d + s * (c + s * (b + s * (a + s)));
    let gg = bq * bq / 9.0;
    let hh = aq * cq;
    let g = hh - 4.0 * dq - 3.0 * gg;
    let h = (8.0 * dq + hh - 2.0 * gg) * bq / 3.0 - cq * cq - dq * aq * aq;

    let mut x = depressed_cubic_dominant_root(g, h);
    // Newton refinement, stopped as soon as the residual no longer decreases.
    let f = |x: f64| x * (x * x + g) + h;
    let mut fx = f(x);
    let scale = (x * x * x).abs().max((g * x).abs()).max(h.abs());
    if fx.abs() > f64::EPSILON * scale {
        for _ in 0..16 {
            let df = 3.0 * x * x + g;
            if df == 0.0 {
                break;
            }
            let next = x - fx / df;
            let fnext = f(next);
            if fnext.abs() >= fx.abs() || fnext.is_nan() {
                break;
            }
            x = next;
            fx = fnext;
            if fx == 0.0 {
                break;
            }
        }
    }
    x
}

/// The root of largest magnitude of `x³ + g·x + h`, or a start for Newton's method that
/// converges to it: Cardano's formula with the cancellation-free sign choice when there is
/// one real root, the bound `2√Q` on the right side when there are three.
fn depressed_cubic_dominant_root(g: f64, h: f64) -> f64 {
    let q = -g / 3.0;
    let r = h / 2.0;
    if r == 0.0 {
        // x(x² + g): roots 0 and ±√−g.
        return if g <= 0.0 { (-g).sqrt() } else { 0.0 };
    }
    let q3 = q * q * q;
    let r2 = r * r;
    if r2 < q3 {
        // Three real roots −2√Q·cos((θ + 2πk)/3), cos θ = R/Q^(3/2): the dominant one has the
        // sign of −R and a magnitude in [√3·√Q, 2√Q]. Instead of the closed form (acos and
        // cos, the costliest part of the solver), start at the bound −sign(R)·2√Q: beyond the
        // root, on its convex side, so the Newton refinement that follows converges to it
        // monotonically and quadratically from within 15 %.
        -(2.0 * q.sqrt()).copysign(r)
    } else {
        let big = -(r.abs() + (r2 - q3).sqrt()).cbrt().copysign(r);
        let small = if big == 0.0 { 0.0 } else { q / big };
        big + small
    }
}

/// Backward error of an LDLᵀ candidate: how well `d₂ + l₁² + 2l₃`, `2d₂l₂ + 2l₁l₃` and
/// `d₂l₂² + l₃²` reproduce `b`, `c`, `d` (eqs. 29–30 of the paper), each error relative to
/// the size of its terms (see [`Monic::rel`]).
fn ldlt_error(q: Monic, d2: f64, l1: f64, l2: f64, l3: f64) -> f64 {
    let Monic { b, c, d, .. } = q;
    let (t1, t2, t3) = (l1 * l1, 2.0 * d2 * l2, d2 * l2 * l2);
    q.rel(
        1,
        d2 + t1 + 2.0 * l3 - b,
        d2.abs() + t1 + 2.0 * l3.abs() + b.abs(),
    ) + q.rel(
        2,
        t2 + 2.0 * l1 * l3 - c,
        t2.abs() + 2.0 * (l1 * l3).abs() + c.abs(),
    ) + q.rel(3, t3 + l3 * l3 - d, t3.abs() + l3 * l3 + d.abs())
}

/// Backward error with which real factors `[α₁, β₁, α₂, β₂]` reproduce the monic quartic's
/// `a, b, c, d`: the sum of the residuals, each relative to the size of its terms.
fn coefficient_error(q: Monic, f: [f64; 4]) -> f64 {
    let Monic { a, b, c, d, .. } = q;
    let [a1, b1, a2, b2] = f;
    let r = residual(q, f);
    q.rel(0, r[0], a1.abs() + a2.abs() + a.abs())
        + q.rel(1, r[1], b1.abs() + (a1 * a2).abs() + b2.abs() + b.abs())
        + q.rel(2, r[2], (a1 * b2).abs() + (b1 * a2).abs() + c.abs())
        + q.rel(3, r[3], (b1 * b2).abs() + d.abs())
}

/// The residuals of `α₁ + α₂ = a`, `β₁ + α₁α₂ + β₂ = b`, `α₁β₂ + β₁α₂ = c`, `β₁β₂ = d`.
///
/// Plain arithmetic: its rounding (ε times the size of the terms) is the backward error that
/// one rounding of the coefficients makes anyway, and the real roots are refined afterwards
/// against the original quartic with a compensated residual. (Fused multiply-adds would be
/// library calls on baseline x86-64, and this is the hot loop.)
fn residual(q: Monic, f: [f64; 4]) -> [f64; 4] {
    let Monic { a, b, c, d, .. } = q;
    let [a1, b1, a2, b2] = f;
    [
        (a1 - a) + a2,
        a1 * a2 + ((b1 - b) + b2),
        a1 * b2 + (b1 * a2 - c),
        b1 * b2 - d,
    ]
}

/// Newton's method on the four equations tying the factors to the coefficients (sec. 2.3 of
/// the paper), stopped when the backward error no longer decreases; the best iterate is kept.
/// (The paper stops on the coefficient-relative error and keeps the smallest absolute one;
/// both are measured here relative to the terms, see [`Monic::rel`].)
fn polish_factors(q: Monic, f: [f64; 4]) -> [f64; 4] {
    let mut x = f;
    let mut err = coefficient_error(q, x);
    let mut best = (err, x);
    // Already at rounding level (each residual about an ulp of its terms): a Newton step
    // could not do better, only confirm it.
    if !err.is_finite() || err <= 4.0 * f64::EPSILON {
        return x;
    }
    for _ in 0..20 {
        let r = residual(q, x);
        let Some(step) = factor_newton_step(x, r) else {
            break;
        };
        let next = [
            x[0] - step[0],
            x[1] - step[1],
            x[2] - step[2],
            x[3] - step[3],
        ];
        if !next.iter().all(|v| v.is_finite()) {
            break;
        }
        let e = coefficient_error(q, next);
        if e < best.0 {
            best = (e, next);
        }
        if e == 0.0 || e >= err || e.is_nan() {
            break;
        }
        x = next;
        err = e;
    }
    best.1
}

/// Solves `J·Δ = r` for the Jacobian `J` of the factor equations at `[α₁, β₁, α₂, β₂]`.
///
/// Eliminating `Δα₂ = r_a − Δα₁` leaves a 3×3 system whose determinant is the resultant of
/// the two quadratic factors, `(α₂ − α₁)(α₂β₁ − α₁β₂) + (β₂ − β₁)²`; it vanishes when the
/// factors share a root, and then no step is taken.
fn factor_newton_step(f: [f64; 4], r: [f64; 4]) -> Option<[f64; 4]> {
    let [a1, b1, a2, b2] = f;
    let [ra, rb, rc, rd] = r;
    let da = a2 - a1;
    let db = b2 - b1;
    let s1 = rb - a1 * ra;
    let s2 = rc - b1 * ra;
    let s3 = rd;
    let det = da * (a2 * b1 - a1 * b2) + db * db;
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let inv = 1.0 / det;
    let u1 = (s1 * (a2 * b1 - a1 * b2) + s2 * db + s3 * (a1 - a2)) * inv;
    let v1 = (da * (s2 * b1 - a1 * s3) - s1 * db * b1 + db * s3) * inv;
    let v2 = (da * (a2 * s3 - s2 * b2) - db * s3 + s1 * db * b2) * inv;
    let u2 = ra - u1;
    Some([u1, v1, u2, v2])
}

type C = (f64, f64);

fn cadd(x: C, y: C) -> C {
    (x.0 + y.0, x.1 + y.1)
}
fn csub(x: C, y: C) -> C {
    (x.0 - y.0, x.1 - y.1)
}
fn cmul(x: C, y: C) -> C {
    (x.0 * y.0 - x.1 * y.1, x.0 * y.1 + x.1 * y.0)
}
fn cabs2(x: C) -> f64 {
    x.0 * x.0 + x.1 * x.1
}
fn cdiv(x: C, y: C) -> C {
    let n = cabs2(y);
    ((x.0 * y.0 + x.1 * y.1) / n, (x.1 * y.0 - x.0 * y.1) / n)
}
/// Principal square root, computed without cancellation.
fn csqrt(z: C) -> C {
    let (x, y) = z;
    if x == 0.0 && y == 0.0 {
        return (0.0, 0.0);
    }
    // Inputs are of order one here (scaled quartic), so the plain modulus cannot overflow.
    let m = (x * x + y * y).sqrt();
    let t = ((x.abs() + m) / 2.0).sqrt();
    if x >= 0.0 {
        (t, y / (2.0 * t))
    } else {
        ((y / (2.0 * t)).abs(), t.copysign(y))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `|p(x)|` within a few roundings of the size of its terms.
    fn is_root(p: &[f64; 5], x: f64) -> bool {
        let size: f64 = p.iter().fold(0.0, |acc, &c| acc * x.abs() + c.abs());
        eval_compensated(p, x).0.abs() <= 4.0 * f64::EPSILON * size
    }

    #[test]
    fn factor_newton_converges_quadratically() {
        // (x² − 3x + 2)(x² + x + 5) = x⁴ − 2x³ + 4x² − 13x + 10, from a perturbed start.
        let f = polish_factors(
            Monic::new(-2.0, 4.0, -13.0, 10.0),
            [-3.0 + 1e-3, 2.0 - 1e-3, 1.0 + 2e-3, 5.0 + 1e-3],
        );
        for (x, y) in f.iter().zip([-3.0, 2.0, 1.0, 5.0]) {
            assert!((x - y).abs() <= 4.0 * f64::EPSILON * y.abs(), "{f:?}");
        }
    }

    #[test]
    fn a_quartic_whose_factorisation_fails_is_solved_piece_by_piece() {
        // Found by the fuzz target `poly`: coefficients spanning 62 bits (the Newton polygon
        // splits at 64), c·x·(x² + x + 1) between a huge and a tiny root; the factorisation
        // made the complex pair the real factor x² + x + 0.0032 (two roots that are none).
        let c = 4.224376450473525e19;
        let close = |r: &RealRoots, exact: &[f64]| {
            r.as_slice().len() == exact.len()
                && (r.as_slice().iter().zip(exact))
                    .all(|(x, y)| (x - y).abs() <= 2.0 * f64::EPSILON * y.abs())
        };
        let r = solve_quartic(848.9375, c, c, c, -13.625);
        // (mpmath, 80 digits: −4.9760747410422144e16, 3.2253280832660465e-19.)
        assert!(
            close(
                &r,
                &[-4.976_074_741_042_214e16, 3.225_328_083_266_046_5e-19]
            ),
            "{r:?}"
        );
        // A real pair with one root wrong: −0.528 for −1.839 (mpmath's four roots below).
        let r = solve_quartic(
            212.234375,
            1.0560941126183813e19,
            4.239238329243848e19,
            c,
            4690.0,
        );
        let exact = [
            -4.976_074_741_042_214e16,
            -2.174_948_421_150_638,
            -1.839_124_073_518_871_5,
            -1.110_223_024_625_156_7e-16,
        ];
        assert!(close(&r, &exact), "{r:?}");
    }

    #[test]
    fn resolvent_root_is_a_root() {
        let (a, b, c, d) = (-10.0, 35.0, -50.0, 24.0);
        let phi = resolvent_dominant_root(a, b, c, d);
        // det M(φ) = 0
        let m = [
            [1.0, a / 2.0, b / 6.0 + phi / 2.0],
            [a / 2.0, 2.0 * b / 3.0 - phi, c / 2.0],
            [b / 6.0 + phi / 2.0, c / 2.0, d],
        ];
        let det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        assert!(det.abs() < 1e-9, "{det}");
    }

    /// The roots do not depend on the sign of a zero coefficient (the fuzzer's case: a double
    /// root at −1 perturbed, whose roots came out an ulp apart with −0·x³), nor on the
    /// polynomial's sign.
    #[test]
    fn a_zero_coefficient_of_either_sign_gives_the_same_roots() {
        let a = 4.224376450473525e19;
        let p = [-53.05859375, 0.0, a, 2.0 * a, a];
        let bits = |p: [f64; 5]| -> Vec<u64> {
            solve_quartic(p[0], p[1], p[2], p[3], p[4])
                .iter()
                .map(|r| r.to_bits())
                .collect()
        };
        let plus = bits(p);
        assert_eq!(plus.len(), 4);
        for k in 0..5 {
            let mut q = p;
            if q[k] == 0.0 {
                q[k] = -0.0;
                assert_eq!(bits(q), plus, "−0 at {k}");
            }
        }
        for q in [
            [0.0, 1.0, -3.0, 0.0, 2.0],
            [1.0, 0.0, -5.0, 0.0, 4.0],
            [1.0, -2.0, 0.0, 0.0, 0.0],
        ] {
            let flipped = q.map(|x| if x == 0.0 { -0.0 } else { x });
            assert_eq!(bits(flipped), bits(q), "{q:?}");
        }
        // Nor on the sign of the polynomial (a zero over a negative leading coefficient).
        for q in [
            p,
            [-p[0], 0.0, -a, -2.0 * a, -a],
            [2.0, 0.0, -3.0, 0.5, -0.25],
        ] {
            assert_eq!(bits(q.map(|x| -x)), bits(q), "{q:?}");
        }
    }

    #[test]
    fn remark_cases() {
        // Remark 2022: x⁴ + 2.2459773428819827x³ − 14.480985471938862x² − 17.678187643398402x + 1
        let r = solve_quartic(
            1.0,
            2.2459773428819827,
            -14.480985471938862,
            -17.678187643398402,
            1.0,
        );
        assert_eq!(r.len(), 4, "{r:?}");
        for &x in &r {
            assert!(is_root(
                &[
                    1.0,
                    2.2459773428819827,
                    -14.480985471938862,
                    -17.678187643398402,
                    1.0
                ],
                x
            ));
        }
        // Remark 2024: x⁴ − 11x² − 46 (through the general path too, not only as biquadratic).
        let q = Monic::new(0.0, -11.0, 0.0, -46.0);
        let f = polish_factors(q, factor(q));
        let mut roots = RootBuf::default();
        let p = [1.0, 0.0, -11.0, 0.0, -46.0];
        push_quadratic_roots(&p, 1.0, f[0], f[1], &mut roots);
        push_quadratic_roots(&p, 1.0, f[2], f[3], &mut roots);
        let x = (0.5 * (11.0 + 305f64.sqrt())).sqrt();
        let mut got = roots.as_mut_slice().to_vec();
        got.sort_by(f64::total_cmp);
        assert_eq!(got.len(), 2, "{got:?}");
        assert!((got[0] + x).abs() <= 4.0 * f64::EPSILON * x);
        assert!((got[1] - x).abs() <= 4.0 * f64::EPSILON * x);
    }

    #[test]
    fn degenerate_dispatch() {
        assert_eq!(
            solve_quartic(0.0, 1.0, -6.0, 11.0, -6.0).as_slice(),
            &[1.0, 2.0, 3.0]
        );
        assert_eq!(
            solve_quartic(1.0, -6.0, 11.0, -6.0, 0.0).as_slice(),
            &[0.0, 1.0, 2.0, 3.0]
        );
        // (x² − 1)(x² − 4)
        assert_eq!(
            solve_quartic(1.0, 0.0, -5.0, 0.0, 4.0).as_slice(),
            &[-2.0, -1.0, 1.0, 2.0]
        );
        assert!(solve_quartic(0.0, 0.0, 0.0, 0.0, 0.0).is_empty());
        assert!(solve_quartic(f64::INFINITY, 0.0, 0.0, 0.0, 1.0).is_empty());
    }
}
