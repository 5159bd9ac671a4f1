//! The polynomial solvers' invariants (`tests/support/invariants.rs`) on coefficients drawn
//! across the whole float range: sorted, finite roots, each within a backward-error bound of
//! a true root by exact evaluation, none lost (exact signs between them), and bit-exact
//! invariance under ±0 flips and power-of-two scalings. The fuzz target `poly` checks the
//! same (docs/fuzzing.md).

use crate::support::cases;
use crate::support::exact;
use crate::support::invariants;
use crate::support::strategies;

use proptest::prelude::*;

proptest! {
    // A fixed seed: the same cases on every run, so that CI is repeatable; the fuzz target
    // draws new ones (docs/fuzzing.md).
    #![proptest_config(ProptestConfig {
        cases: cases::cases(1000),
        rng_seed: proptest::test_runner::RngSeed::Fixed(24),
        ..ProptestConfig::default()
    })]

    #[test]
    fn real_roots_keep_their_invariants(
        c in strategies::poly_case(),
        k in -1100i32..=1100,
        m in -300i32..=300,
    ) {
        invariants::poly(&c, k, m).map_err(TestCaseError::fail)?;
    }
}

#[test]
fn tiny_odd_degree_coefficients_keep_the_roots() {
    // issue 21 item 4: a coefficient-relative backward error made these lose their roots.
    for c in [
        [-5.18e-05, 0.0, 934.0, 1e-200, -0.01466],
        [0.5, 0.0, 2e-120, 1.3e-308, -4e-7],
        [-5.18e-05, 1e-200, 934.0, 0.0, -0.01466],
    ] {
        invariants::poly(&c, 7, -3).unwrap_or_else(|e| panic!("{e}"));
    }
}

#[test]
fn the_checker_catches_wrong_roots() {
    // A root moved by one part in 1e9 is no longer a root within the bound.
    let c = [1.0, -10.0, 35.0, -50.0, 24.0];
    assert!(exact::within_backward_error(
        &c,
        2.0,
        invariants::ROOT_ROUNDINGS
    ));
    assert!(!exact::within_backward_error(
        &c,
        2.0 + 2e-9,
        invariants::ROOT_ROUNDINGS
    ));
    assert_eq!(exact::sign_exact(&c, 2.5), 1);
    assert_eq!(exact::sign_exact(&c, 1.5), -1);
    assert_eq!(exact::sign_exact(&c, 3.0), 0);
}
