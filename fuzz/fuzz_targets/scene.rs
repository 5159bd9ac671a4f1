//! The scene queries on 2 to 12 balls: broad phase = all pairs = the brute-force pair loop, bit
//! for bit, on one thread and on two; earliest collision and first contacts read off it; ±0
//! flips and power-of-two length scalings change no bit; valid input never errors.
#![no_main]

use arbitrary::Unstructured;
use ballcollide_fuzz::{Raw, invariants, scene_case};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let input = match Raw::of(data) {
        Some(raw) => raw.scene_case(),
        None => scene_case(&mut Unstructured::new(data)).ok(),
    };
    if let Some((case, k)) = input
        && let Err(e) = invariants::scene(&case, k)
    {
        panic!("{e}");
    }
});
