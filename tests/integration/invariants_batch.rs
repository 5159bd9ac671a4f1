//! The batch's invariants (`tests/support/invariants.rs`) on inputs drawn across the whole
//! float range: every pair's time is the scalar search's, bit for bit, on one thread and on
//! two, with shared or per-pair parameters, at every SIMD level this CPU has; valid input
//! never errors. The fuzz target `batch`
//! checks the same (docs/fuzzing.md).

use crate::support::cases;
use crate::support::invariants;
use crate::support::strategies;

use proptest::prelude::*;

proptest! {
    // A fixed seed: the same cases on every run, so that CI is repeatable; the fuzz target
    // draws new ones (docs/fuzzing.md).
    #![proptest_config(ProptestConfig {
        cases: cases::cases(150),
        rng_seed: proptest::test_runner::RngSeed::Fixed(23),
        ..ProptestConfig::default()
    })]

    #[test]
    fn batch_equals_the_scalar_search((cases, shared) in strategies::batch_case()) {
        // At every SIMD level this CPU has (`BALLCOLLIDE_REQUIRE_SIMD` makes a missing one fail).
        for level in ballcollide::simd::test_levels() {
            ballcollide::simd::with_level(level, || invariants::batch(&cases, shared))
                .map_err(|e| TestCaseError::fail(format!("at {level}: {e}")))?;
        }
    }
}
