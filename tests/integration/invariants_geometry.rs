//! The static-geometry entry points' invariants (`tests/support/geometry_invariants.rs`) on 1
//! to 3 paths of 1 to 6 segments against up to 3 objects of each kind, drawn across the whole
//! float range, 2-D and 3-D, now and then with a value no path or object may hold: the
//! constructors and the batch accept exactly what the contract calls valid, never a panic;
//! on valid input the batch is `path_table_contact` and the earliest single-object query,
//! bit for bit, on one thread and two; no NaN, `−0` or time before the first start or at the
//! horizon, a horizon only cuts; power-of-two lengths change no bit, an exact translation no
//! bit of a segment's or a plane's query. The fuzz target `geometry` checks the same
//! (docs/fuzzing.md).

use crate::support::cases;
use crate::support::geometry_invariants;
use crate::support::geometry_strategies;

use proptest::prelude::*;

proptest! {
    // A fixed seed: the same cases on every run, so that CI is repeatable; the fuzz target
    // draws new ones (docs/fuzzing.md).
    #![proptest_config(ProptestConfig {
        cases: cases::cases(300),
        rng_seed: proptest::test_runner::RngSeed::Fixed(36),
        ..ProptestConfig::default()
    })]

    #[test]
    fn balls_against_static_geometry_keep_their_invariants(
        (case, k, j) in geometry_strategies::geometry_case()
    ) {
        geometry_invariants::geometry(&case, k, j).map_err(TestCaseError::fail)?;
    }
}
