//! `path_collision_time` and `path_collision_times` on two paths of 1 to 6 segments, 2-D or
//! 3-D, valid or not: invalid input is refused (never a panic), valid input never errors,
//! and the answer keeps its invariants (`tests/support/path_invariants.rs`).
#![no_main]

use arbitrary::Unstructured;
use ballcollide_fuzz::{Raw, path_case, path_invariants};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let input = match Raw::of(data) {
        Some(raw) => raw.path_case(),
        None => path_case(&mut Unstructured::new(data)).ok(),
    };
    if let Some((case, k)) = input
        && let Err(e) = path_invariants::path(&case, k)
    {
        panic!("{e}");
    }
});
