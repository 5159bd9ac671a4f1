//! Property tests of the cubic and quartic solvers.
//!
//! # Why 1e-12 is an honest tolerance for products of well-separated roots
//!
//! The coefficients of `a·(x − r₁)…(x − r₄)` are formed in float64, so they are not exactly
//! those of the `rᵢ`: each coefficient `c_k` is off by at most `γ·Σ|terms of c_k|` with
//! `γ ≈ 5ε` (ε = 2⁻⁵³; four roundings deep plus the leading factor), and `Σ_k Σ|terms of c_k|·|x|ᵏ`
//! is exactly `|a|·Π(|x| + |r_j|)`. To first order the root `r₁` of the rounded polynomial is
//! therefore within
//!
//! ```text
//! γ·Π_j(|r₁| + |r_j|) / |p′(r₁)|  =  2γ·|r₁|·Π_{j≠1} (|r₁| + |r_j|)/|r₁ − r_j|
//! ```
//!
//! of `r₁`. Requiring `|rᵢ − r_j| ≥ σ·(|rᵢ| + |r_j|)` ("well separated", σ = 1/4) bounds the
//! relative shift by `2γ/σ³ ≈ 7e-14`; the solver's own error (a small multiple of the same
//! conditioning, measured in `poly_reference.rs`) adds about as much again. So 1e-12 holds
//! with a margin of about 6, yet any real loss of accuracy in the solver (a missed polishing
//! step, a wrong branch) shows up far above it.

use crate::support::cases;

use ballcollide::poly::{solve_cubic, solve_quartic};
use proptest::prelude::*;

const SIGMA: f64 = 0.25;

/// A root of magnitude 10^[-8, 8] with a random sign.
fn root() -> impl Strategy<Value = f64> {
    (-8.0f64..8.0, any::<bool>()).prop_map(|(e, neg)| {
        let m = 10f64.powf(e);
        if neg { -m } else { m }
    })
}

fn well_separated(r: &[f64]) -> bool {
    r.iter().enumerate().all(|(i, &x)| {
        r.iter()
            .skip(i + 1)
            .all(|&y| (x - y).abs() >= SIGMA * (x.abs() + y.abs()))
    })
}

/// Coefficients of `lead·Π(x − rᵢ)`, highest degree first, in float64.
fn expand(lead: f64, r: &[f64]) -> Vec<f64> {
    let mut c = vec![1.0];
    for &ri in r {
        let mut next = vec![0.0; c.len() + 1];
        for (k, &ck) in c.iter().enumerate() {
            next[k] += ck;
            next[k + 1] -= ri * ck;
        }
        c = next;
    }
    c.iter().map(|&ck| lead * ck).collect()
}

/// Real roots `r` well separated from each other and from the complex pair `u ± iv`, and the
/// pair from itself (`2|v| ≥ σ·2|z|`: a pair closer to the real axis is a near-double root,
/// which float coefficients may legitimately turn into a real pair).
fn separated_from_pair(r: &[f64], u: f64, v: f64) -> bool {
    let z = u.hypot(v);
    v.abs() >= SIGMA * z
        && well_separated(r)
        && r.iter().all(|&x| (x - u).hypot(v) >= SIGMA * (x.abs() + z))
}

fn assert_close(got: &[f64], want: &mut [f64], tol: f64) -> Result<(), TestCaseError> {
    want.sort_by(f64::total_cmp);
    prop_assert_eq!(got.len(), want.len(), "got {:?}, want {:?}", got, want);
    for (g, w) in got.iter().zip(want.iter()) {
        prop_assert!(
            ((g - w) / w).abs() <= tol,
            "root {} vs {} (rel {:e}); all {:?} vs {:?}",
            g,
            w,
            ((g - w) / w).abs(),
            got,
            want
        );
    }
    Ok(())
}

fn lead() -> impl Strategy<Value = f64> {
    (-3.0f64..3.0, any::<bool>()).prop_map(|(e, neg)| {
        let m = 10f64.powf(e);
        if neg { -m } else { m }
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases::cases(1000), max_global_rejects: 100_000, ..ProptestConfig::default() })]

    #[test]
    fn quartic_recovers_well_separated_roots(
        r in prop::array::uniform4(root()).prop_filter("well separated", |r| well_separated(r)),
        a in lead(),
    ) {
        let c = expand(a, &r);
        let got = solve_quartic(c[0], c[1], c[2], c[3], c[4]);
        assert_close(&got, &mut r.clone(), 1e-12)?;
    }

    #[test]
    fn cubic_recovers_well_separated_roots(
        r in prop::array::uniform3(root()).prop_filter("well separated", |r| well_separated(r)),
        a in lead(),
    ) {
        let c = expand(a, &r);
        let got = solve_cubic(c[0], c[1], c[2], c[3]);
        assert_close(&got, &mut r.clone(), 1e-12)?;
    }

    /// Two real roots and a complex pair `u ± iv` (v not small): exactly the two real roots.
    #[test]
    fn quartic_with_a_complex_pair(
        r in prop::array::uniform2(root()),
        u in root(),
        v in root(),
    ) {
        prop_assume!(separated_from_pair(&r, u, v));
        // (x − r₁)(x − r₂)(x² − 2ux + u² + v²)
        let q = expand(1.0, &r);
        let (b, c) = (-2.0 * u, u * u + v * v);
        let p = [q[0], q[1] + b * q[0], q[2] + b * q[1] + c * q[0], b * q[2] + c * q[1], c * q[2]];
        let got = solve_quartic(p[0], p[1], p[2], p[3], p[4]);
        assert_close(&got, &mut r.clone(), 1e-12)?;
    }

    /// Cubic with one real root and a complex pair far from the axis.
    #[test]
    fn cubic_with_a_complex_pair(r in root(), u in root(), v in root()) {
        prop_assume!(separated_from_pair(&[r], u, v));
        let (b, c) = (-2.0 * u, u * u + v * v);
        let got = solve_cubic(1.0, b - r, c - r * b, -r * c);
        assert_close(&got, &mut [r], 1e-12)?;
    }

    /// Rescaling the coefficients by 2^k, or the variable by 2^m, changes nothing but the
    /// exact scale of the roots: the solvers work on an exactly rescaled problem.
    #[test]
    fn power_of_two_scalings_are_exact(
        c in prop::array::uniform5(-1e3f64..1e3),
        k in -200i32..200,
        m in -40i32..40,
    ) {
        prop_assume!(c[0] != 0.0 && c[4] != 0.0);
        let base = solve_quartic(c[0], c[1], c[2], c[3], c[4]);
        let s = 2f64.powi(k);
        let by_coeff = solve_quartic(c[0] * s, c[1] * s, c[2] * s, c[3] * s, c[4] * s);
        prop_assert_eq!(base.as_slice(), by_coeff.as_slice());
        // p(x) → p(2^m·x) has roots rᵢ/2^m.
        let t = 2f64.powi(m);
        let by_var = solve_quartic(c[0] * t.powi(4), c[1] * t.powi(3), c[2] * t * t, c[3] * t, c[4]);
        let want: Vec<f64> = base.iter().map(|x| x / t).collect();
        prop_assert_eq!(by_var.as_slice(), want.as_slice());
        let base3 = solve_cubic(c[0], c[1], c[2], c[3]);
        let by_var3 = solve_cubic(c[0] * t.powi(3), c[1] * t * t, c[2] * t, c[3]);
        let want3: Vec<f64> = base3.iter().map(|x| x / t).collect();
        prop_assert_eq!(by_var3.as_slice(), want3.as_slice());
    }

    /// Any input, including non-finite ones: no panic, sorted output, and nothing for a
    /// non-finite coefficient.
    #[test]
    fn any_input_is_safe(c in prop::array::uniform5(any::<f64>())) {
        let r = solve_quartic(c[0], c[1], c[2], c[3], c[4]);
        prop_assert!(r.len() <= 4);
        prop_assert!(r.windows(2).all(|w| w[0] <= w[1]));
        prop_assert!(r.iter().all(|x| !x.is_nan()));
        if c.iter().any(|x| !x.is_finite()) {
            prop_assert!(r.is_empty());
        }
        let r3 = solve_cubic(c[0], c[1], c[2], c[3]);
        prop_assert!(r3.len() <= 3 && r3.windows(2).all(|w| w[0] <= w[1]));
    }
}
