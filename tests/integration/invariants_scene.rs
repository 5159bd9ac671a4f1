//! The scene queries' invariants (`tests/support/invariants.rs`) on scenes drawn across the
//! whole float range: the broad phase, all pairs, one thread and two give the brute-force pair
//! loop's matrix bit for bit; the earliest collision and first contacts are read off it; ±0
//! flips and power-of-two scalings of lengths change no bit; valid input never errors. The
//! fuzz target `scene` checks the same (docs/fuzzing.md).

use crate::support::cases;
use crate::support::invariants;
use crate::support::strategies;

use proptest::prelude::*;

proptest! {
    // A fixed seed: the same cases on every run, so that CI is repeatable; the fuzz target
    // draws new ones (docs/fuzzing.md).
    #![proptest_config(ProptestConfig {
        cases: cases::cases(100),
        rng_seed: proptest::test_runner::RngSeed::Fixed(22),
        ..ProptestConfig::default()
    })]

    #[test]
    fn the_scene_equals_the_brute_force_pairs(
        case in strategies::scene_case(),
        k in -1100i32..=1100,
    ) {
        invariants::scene(&case, k).map_err(TestCaseError::fail)?;
    }
}
