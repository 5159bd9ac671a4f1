//! One pair, every query (issue 39): `collision_time` and `path_collision_time` on the same
//! friction balls as paths give the same hit or miss, and times within the floor, on pairs
//! whose depth is known by construction (head on or off axis, the contact distance down to
//! 2⁻⁴⁰⁰ of the separation: `tests/support/narrow_pairs.rs`).
#![no_main]

use arbitrary::Unstructured;
use ballcollide_fuzz::narrow_draw;
use ballcollide_fuzz::narrow_pairs::{narrow_pair, queries_agree};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(draw) = narrow_draw(&mut Unstructured::new(data)) {
        let (a, b, radius) = narrow_pair(&draw);
        if let Err(e) = queries_agree(&a, &b, radius) {
            panic!("{e}");
        }
    }
});
