//! `batch::collision_times` on 1 to 40 pairs: the scalar search's bits for every pair, on one
//! thread and on two, with shared or per-pair parameters; valid input never errors.
#![no_main]

use arbitrary::Unstructured;
use ballcollide_fuzz::{Raw, batch_case, invariants};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let input = match Raw::of(data) {
        Some(raw) => raw.batch_case(),
        None => batch_case(&mut Unstructured::new(data)).ok(),
    };
    if let Some((cases, shared)) = input
        && let Err(e) = invariants::batch(&cases, shared)
    {
        panic!("{e}");
    }
});
