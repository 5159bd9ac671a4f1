//! The path entry points' invariants (`tests/support/path_invariants.rs`) on two paths of 1
//! to 6 segments drawn across the whole float range, 2-D and 3-D, now and then with a value
//! no path may hold: validity as the contract defines it, never a panic; on valid input no
//! NaN, `−0` or time before the first start or at the horizon, a horizon only cuts, A/B swap,
//! zeros' signs and power-of-two lengths change no bit, the batch (per pair and broadcast, one
//! thread and two) gives the single query's bits. The fuzz target `path` checks the same
//! (docs/fuzzing.md).

use crate::support::cases;
use crate::support::path_invariants;
use crate::support::path_strategies;

use proptest::prelude::*;

proptest! {
    // A fixed seed: the same cases on every run, so that CI is repeatable; the fuzz target
    // draws new ones (docs/fuzzing.md).
    #![proptest_config(ProptestConfig {
        cases: cases::cases(500),
        rng_seed: proptest::test_runner::RngSeed::Fixed(25),
        ..ProptestConfig::default()
    })]

    #[test]
    fn paths_keep_their_invariants((case, k) in path_strategies::path_case()) {
        path_invariants::path(&case, k).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn paths_keep_their_invariants_at_the_chord_screens_edge(
        (case, k) in path_strategies::grazing_case()
    ) {
        path_invariants::path(&case, k).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn paths_keep_their_invariants_at_the_window_boxs_edge(
        (case, k) in path_strategies::window_box_edge_case()
    ) {
        path_invariants::path(&case, k).map_err(TestCaseError::fail)?;
    }
}
