//! The pair search's invariants (`tests/support/invariants.rs`) on inputs drawn across the
//! whole float range: valid input never errors, no NaN, negative or infinite time, a horizon
//! only cuts, and A/B swap, ±0 flips and power-of-two scalings of lengths and of time change
//! no bit. The fuzz target `pair` checks the same (docs/fuzzing.md).

use crate::support::cases;
use crate::support::invariants;
use crate::support::strategies;

use invariants::PairCase;
use proptest::prelude::*;

proptest! {
    // A fixed seed: the same cases on every run, so that CI is repeatable; the fuzz target
    // draws new ones (docs/fuzzing.md).
    #![proptest_config(ProptestConfig {
        cases: cases::cases(1000),
        rng_seed: proptest::test_runner::RngSeed::Fixed(21),
        ..ProptestConfig::default()
    })]

    #[test]
    fn the_pair_search_keeps_its_invariants(
        case in strategies::pair_case(),
        k in -1100i32..=1100,
        m in -600i32..=600,
    ) {
        invariants::pair(&case, k, m).map_err(TestCaseError::fail)?;
    }
}

/// The reproducers of issue 21, as invariants.
#[test]
fn issue21_reproducers() {
    let ball = |p: f64, v: f64, mu: f64| [p, 0.0, v, 0.0, mu];
    let cases = [
        // item 1: friction −0.0.
        PairCase {
            a: ball(0.0, 1.0, -0.0),
            b: ball(3.0, -1.0, 0.0),
            radius: 1.0,
            t_max: f64::INFINITY,
        },
        // item 2: a long window (t_max = 1e100) around a contact at t = 1.
        PairCase {
            a: ball(0.0, 1.0, 0.0),
            b: ball(3.0, -1.0, 0.0),
            radius: 1.0,
            t_max: 1e100,
        },
        // item 5: a horizon 1.5 times the contact time moves it by an ulp (table scale).
        PairCase {
            a: [
                1.1858866766421357,
                0.3923132905644326,
                1.2324764349422335,
                -2.570690455902241,
                0.05970603757958948,
            ],
            b: [
                1.2755192917180609,
                0.27996317735317033,
                -2.2163324064427465,
                0.1959911843730664,
                1.8587730657766453,
            ],
            radius: 0.05715,
            t_max: 0.03147376376666284,
        },
        // item 3: lengths at 1e-300 and 1e160.
        PairCase {
            a: ball(1e-300, -1e-300, 0.0),
            b: ball(-1e-300, 1e-300, 0.0),
            radius: 1e-300,
            t_max: f64::INFINITY,
        },
        PairCase {
            a: ball(1e160, -1e160, 0.0),
            b: ball(-1e160, 1e160, 0.0),
            radius: 1e160,
            t_max: f64::INFINITY,
        },
    ];
    let mut failures = Vec::new();
    for case in &cases {
        if let Err(e) = invariants::pair(case, 500, 3) {
            failures.push(e);
        }
    }
    // item 3: the contact at 0.5 must be found at every scale.
    for case in &cases[3..] {
        let ball = |x: &[f64; 5]| {
            ballcollide::Ball::new(
                nalgebra::Vector2::new(x[0], x[1]),
                nalgebra::Vector2::new(x[2], x[3]),
                x[4],
            )
        };
        let t = match (ball(&case.a), ball(&case.b)) {
            (Ok(a), Ok(b)) => ballcollide::collision_time(&a, &b, case.radius),
            (Err(e), _) | (_, Err(e)) => Err(e),
        };
        if !matches!(t, Ok(Some(x)) if x == 0.5) {
            failures.push(format!("{case:?}: {t:?}, expected Some(0.5)"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
