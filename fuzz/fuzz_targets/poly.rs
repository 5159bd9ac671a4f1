//! `real_roots` on 2 to 5 coefficients over the whole float range: roots sorted, finite, each a
//! root within a backward-error bound (exact evaluation), none lost (exact signs between
//! them), unchanged bits under ±0 flips and power-of-two scalings.
#![no_main]

use arbitrary::Unstructured;
use ballcollide_fuzz::{Raw, invariants, poly_case};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let input = match Raw::of(data) {
        Some(raw) => raw.poly_case(),
        None => poly_case(&mut Unstructured::new(data)).ok(),
    };
    if let Some((coeffs, k, m)) = input
        && let Err(e) = invariants::poly(&coeffs, k, m)
    {
        panic!("{e}");
    }
});
