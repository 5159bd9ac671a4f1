//! `simulate` on a table (issue 36): 1 to 8 balls in a box with segments (capped by circles),
//! circles, targets and a plane: runs end or are refused as impossible (and are so), events
//! in order, no overlap with a ball, a wall or an object beyond 1e-9 of the radius at the
//! end, at cut times, at up to eight events' times and halfway to the next; captured balls
//! never move again nor take part in a later event, the kinetic energy never grows
//! (restitutions ≤ 1), a cut run logs the events before its cut
//! (tests/support/simulation_invariants.rs).
#![no_main]

use arbitrary::Unstructured;
use ballcollide_fuzz::{simulation_invariants, simulation_table_case};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(case) = simulation_table_case(&mut Unstructured::new(data)) else {
        return;
    };
    if std::env::var_os("BALLCOLLIDE_FUZZ_SHOW").is_some() {
        eprintln!("{case:?}");
    }
    if let Err(e) = simulation_invariants::table_simulation(&case) {
        panic!("{e}");
    }
});
