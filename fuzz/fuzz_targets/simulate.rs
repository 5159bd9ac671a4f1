//! `simulate` on 1 to 8 balls in a box, or a touching train of up to 16: valid starts run or
//! are refused as impossible (and are so), runs end, events in order, no overlap beyond 1e-9
//! at the end, at cut times, at up to eight events' times and halfway to the next; a cut run
//! logs the events before its cut (tests/support/simulation_invariants.rs).
#![no_main]

use arbitrary::Unstructured;
use ballcollide_fuzz::{simulation_case, simulation_invariants};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(case) = simulation_case(&mut Unstructured::new(data)) else {
        return;
    };
    // A slow input (libFuzzer's timeout) breaks no invariant to print: show its case.
    if std::env::var_os("BALLCOLLIDE_FUZZ_SHOW").is_some() {
        eprintln!("{case:?}");
    }
    if let Err(e) = simulation_invariants::simulation(&case) {
        panic!("{e}");
    }
});
