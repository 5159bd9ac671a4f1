//! What the property suites on paths share (`tests/integration/path_properties.rs`,
//! `tests/integration/geometry_properties.rs`; included by path, beside `support/cases.rs` as `cases`):
//! the fixed-seed configuration, a simulator's kind of path, paths with values from the whole
//! float range, the check that a horizon only cuts, and the range of exact power-of-two
//! scalings.

#![allow(dead_code)]

use ballcollide::path::Segment;
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

/// `fast` cases in the fast tier (`PROPTEST_CASES` in the thorough one) from a fixed seed.
pub fn config(fast: u32, seed: u64) -> ProptestConfig {
    ProptestConfig {
        cases: super::cases::cases(fast),
        rng_seed: RngSeed::Fixed(seed),
        max_global_rejects: 4096,
        ..ProptestConfig::default()
    }
}

/// A time's bits (`None` stays `None`), to compare answers exactly.
pub fn bits(t: Option<f64>) -> Option<u64> {
    t.map(f64::to_bits)
}

/// A path of 1 to `most` segments, the first starting in `[0, 2)`: each later segment starts
/// 0 (the one before is then empty) to 2 s after the one before; most continue the previous
/// motion, as a simulator's paths do, the others jump. Lengths in metres (positions in a 2 m
/// box), speeds up to 2 m/s, accelerations up to 1 m/s².
pub fn path<const D: usize>(most: usize) -> impl Strategy<Value = Vec<Segment<D>>> {
    let piece = (
        prop_oneof![1 => Just(0.0), 4 => 0.0..2.0f64],
        prop::bool::weighted(0.7),
        prop::array::uniform::<_, D>(-1.0..1.0f64),
        prop::array::uniform::<_, D>(-2.0..2.0f64),
        prop::array::uniform::<_, D>(-1.0..1.0f64),
    );
    (0.0..2.0f64, prop::collection::vec(piece, 1..=most)).prop_map(|(t0, pieces)| {
        let mut segments: Vec<Segment<D>> = Vec::new();
        let mut t = t0;
        for (k, (dt, continuous, p, v, a)) in pieces.into_iter().enumerate() {
            if k > 0 {
                t += dt;
            }
            let (p, v) = match segments.last() {
                Some(previous) if continuous => (previous.position_at(t), previous.velocity_at(t)),
                _ => (p.into(), v.into()),
            };
            segments.push(Segment::new(t, p, v, a.into()));
        }
        segments
    })
}

/// That a horizon only cuts: with `time_until(t_max)` the answer under a horizon and `t_from`
/// where the search starts, a horizon after the answer gives it bit for bit, one at or before
/// it (or any, for none) gives none; `f` in `[0, 1)` picks a horizon in between.
pub fn check_horizon(
    time_until: impl Fn(f64) -> Option<f64>,
    t_from: f64,
    f: f64,
) -> Result<(), TestCaseError> {
    match time_until(f64::INFINITY) {
        Some(t) => {
            let later = [t.next_up(), t + 1.0 + f, 2.0 * t.abs() + 1.0, 1e300];
            for t_max in later {
                prop_assert_eq!(bits(time_until(t_max)), Some(t.to_bits()), "{}", t_max);
            }
            let earlier = [t, t.next_down(), t_from + f * (t - t_from), t_from, 0.0];
            for t_max in earlier.into_iter().filter(|&x| x >= 0.0) {
                prop_assert_eq!(time_until(t_max), None, "t_max = {}", t_max);
            }
        }
        None => {
            for t_max in [0.0, t_from + f, 1e300] {
                prop_assert_eq!(time_until(t_max), None);
            }
        }
    }
    Ok(())
}

/// The exponents `k` for which every one of `lengths` times `2^k` is a normal float: the
/// range the power-of-two scaling may cover exactly whatever the mantissas.
pub fn exponent_range(lengths: impl IntoIterator<Item = f64>) -> (i32, i32) {
    let (mut lo, mut hi) = (i32::MAX, i32::MIN);
    for x in lengths.into_iter().filter(|&x| x != 0.0) {
        let e = x.abs().log2().floor() as i32;
        lo = lo.min(e);
        hi = hi.max(e);
    }
    // Within one of the bounds on either side: the rounding of log2 is then harmless.
    (-1021 - lo, 1022 - hi)
}

/// A finite float from anywhere in the range: zeros of both signs, subnormals, tiny, ordinary
/// and huge magnitudes, up to `f64::MAX`.
pub fn wild() -> impl Strategy<Value = f64> {
    prop_oneof![
        2 => Just(0.0),
        1 => Just(-0.0),
        4 => -2.0..2.0f64,
        4 => (1.0..2.0f64, -1074..=1023i32, prop::bool::ANY).prop_map(|(m, e, negative)| {
            let x = (m * 2f64.powi(e.max(-1022))) * 2f64.powi((e + 1022).min(0));
            let x = if x.is_finite() { x } else { f64::MAX };
            if negative { -x } else { x }
        }),
        1 => Just(f64::MAX),
        1 => Just(f64::MIN_POSITIVE),
        1 => Just(f64::from_bits(1)),
    ]
}

/// A path of 1–6 segments with values from anywhere in the float range: starts from `wild`
/// (any sign) then non-decreasing by `wild` steps (0 included: empty segments; a sum that
/// overflows is held at `f64::MAX`).
pub fn wild_path<const D: usize>() -> impl Strategy<Value = Vec<Segment<D>>> {
    let piece = (
        wild(),
        prop::array::uniform::<_, D>(wild()),
        prop::array::uniform::<_, D>(wild()),
        prop::array::uniform::<_, D>(wild()),
    );
    (wild(), prop::collection::vec(piece, 1..=6)).prop_map(|(t0, pieces)| {
        let mut t = t0;
        pieces
            .into_iter()
            .enumerate()
            .map(|(k, (dt, p, v, a))| {
                if k > 0 {
                    t = (t + dt.abs()).min(f64::MAX);
                }
                Segment::new(t, p.into(), v.into(), a.into())
            })
            .collect()
    })
}
