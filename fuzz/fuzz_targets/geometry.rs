//! `batch::path_geometry_times`, `geometry::path_table_contact` and the object constructors
//! on 1 to 3 paths (2-D or 3-D) against up to 3 objects of each kind, valid or not: invalid
//! input is refused (never a panic), valid input never errors, and the answers keep their
//! invariants (`tests/support/geometry_invariants.rs`).
#![no_main]

use arbitrary::Unstructured;
use ballcollide_fuzz::{Raw, geometry_case, geometry_invariants};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let input = match Raw::of(data) {
        Some(raw) => raw.geometry_case(),
        None => geometry_case(&mut Unstructured::new(data)).ok(),
    };
    if let Some((case, k, j)) = input
        && let Err(e) = geometry_invariants::geometry(&case, k, j)
    {
        panic!("{e}");
    }
});
