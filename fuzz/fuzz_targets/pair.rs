//! `collision_time_with` on one pair over the whole float range: no error, NaN, negative or
//! infinite time for valid input; a horizon only cuts; A/B swap, ±0 flips, power-of-two
//! scalings of lengths and of time change no bit.
#![no_main]

use arbitrary::Unstructured;
use ballcollide_fuzz::{Raw, invariants, pair_case};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let input = match Raw::of(data) {
        Some(raw) => raw.pair_case(),
        None => pair_case(&mut Unstructured::new(data)).ok(),
    };
    if let Some((case, k, m)) = input
        && let Err(e) = invariants::pair(&case, k, m)
    {
        panic!("{e}");
    }
});
