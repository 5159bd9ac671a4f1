//! The event calendar (`schedule::CollisionSchedule`) on 0 to 24 balls of every kind of path,
//! 2-D and 3-D, with or without walls, a table and transitions: after every operation
//! (an event resolved, a skip with a few balls changed, refused updates, a ball retired) its
//! next collision, wall contact and event are brute force's, bit for bit, within the
//! contract's range of magnitudes, and events at all beyond it; refused updates change
//! nothing; nothing panics (tests/support/schedule_invariants.rs).
#![no_main]

use ballcollide_fuzz::{Bytes, schedule_case, schedule_run};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut choices = Bytes::new(data);
    let case = schedule_case(&mut choices);
    // A slow input (libFuzzer's timeout) breaks no invariant to print: show its case.
    if std::env::var_os("BALLCOLLIDE_FUZZ_SHOW").is_some() {
        eprintln!("{case:?}");
    }
    let result = if case.three_d {
        schedule_run::<3>(&case, choices)
    } else {
        schedule_run::<2>(&case, choices)
    };
    if let Err(e) = result {
        panic!("{e}");
    }
});
