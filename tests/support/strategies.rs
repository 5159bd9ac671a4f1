//! proptest strategies over the whole float range, for the invariants of
//! `tests/support/invariants.rs`: the same kinds of numbers as the fuzz targets' decoders
//! (`fuzz/src/lib.rs`): exponents from −1074 to 1023, both zeros, small dyadic numbers that
//! make contacts likely, table-sized numbers with full mantissas, one power-of-two scale per
//! case.
#![allow(dead_code)]

use ballcollide::poly::scaling::scale;
use proptest::prelude::*;

use super::invariants::{BallInput, PairCase, SceneCase, Shared};

/// Any finite float, most often far from 1.
pub fn wide() -> impl Strategy<Value = f64> {
    prop_oneof![
        1 => Just(0.0),
        1 => Just(-0.0),
        1 => any::<i8>().prop_map(f64::from),
        5 => (any::<bool>(), -1074i32..=1023, 0u64..(1u64 << 52)).prop_map(|(neg, e, m)| {
            let x = scale(f64::from_bits((1023u64 << 52) | m), e);
            if neg { -x } else { x }
        }),
    ]
}

/// A small dyadic number `i/2^j`, sometimes ±0.
pub fn small() -> impl Strategy<Value = f64> {
    prop_oneof![
        1 => Just(0.0),
        1 => Just(-0.0),
        14 => (any::<i16>(), 0u32..=8).prop_map(|(i, j)| f64::from(i / 2) / f64::from(1u16 << j)),
    ]
}

/// A number like a table's: a full 52-bit mantissa, magnitude from 1/16 to 4, either sign.
pub fn table() -> impl Strategy<Value = f64> {
    (any::<bool>(), -4i32..=1, 0u64..(1u64 << 52)).prop_map(|(neg, e, m)| {
        let x = scale(f64::from_bits((1023u64 << 52) | m), e);
        if neg { -x } else { x }
    })
}

/// The power of two a case is scaled by: `2^0` half of the time, else any exponent.
pub fn case_scale() -> impl Strategy<Value = i32> {
    prop_oneof![Just(0), -1074i32..=1023]
}

/// A length-like number times `2^s` (or any float, now and then).
pub fn length(s: i32) -> impl Strategy<Value = f64> {
    prop_oneof![
        1 => wide(),
        2 => table().prop_map(move |x| scale(x, s)),
        2 => small().prop_map(move |x| scale(x, s)),
    ]
}

/// A friction: 0, −0, small ones times `2^s` (or a further power of two), any non-negative.
pub fn friction(s: i32) -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(0.0),
        Just(-0.0),
        small().prop_map(move |x| scale(x.abs(), s)),
        (small(), -200i32..=40).prop_map(move |(x, k)| scale(x.abs(), s + k)),
        table().prop_map(move |x| scale(x.abs(), s)),
        wide().prop_map(f64::abs),
        wide().prop_map(f64::abs),
    ]
}

/// A ball whose numbers are scaled by `2^s`.
pub fn ball(s: i32) -> impl Strategy<Value = BallInput> {
    (length(s), length(s), length(s), length(s), friction(s))
        .prop_map(|(px, py, vx, vy, mu)| [px, py, vx, vy, mu])
}

/// A positive contact distance.
pub fn radius(s: i32) -> impl Strategy<Value = f64> {
    prop_oneof![
        1 => wide().prop_map(f64::abs),
        3 => small().prop_map(move |x| scale(x.abs(), s)),
    ]
    .prop_map(move |r| if r > 0.0 { r } else { scale(1.0, s) })
}

/// A horizon: none, ±0, small, 1e10 … 1e300, or any non-negative float.
pub fn t_max() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => Just(f64::INFINITY),
        1 => Just(0.0),
        1 => Just(-0.0),
        1 => small().prop_map(f64::abs),
        1 => (10i32..=300).prop_map(|e| 10f64.powi(e)),
        1 => wide().prop_map(f64::abs),
    ]
}

fn pair_at(s: i32) -> impl Strategy<Value = PairCase> {
    (ball(s), ball(s), radius(s), t_max()).prop_map(|(a, b, radius, t_max)| PairCase {
        a,
        b,
        radius,
        t_max,
    })
}

/// A pair query.
pub fn pair_case() -> impl Strategy<Value = PairCase> {
    case_scale().prop_flat_map(pair_at)
}

/// 1 to 40 pair queries sharing one scale, and which parameters are shared.
pub fn batch_case() -> impl Strategy<Value = (Vec<PairCase>, Shared)> {
    case_scale().prop_flat_map(|s| {
        (
            prop::collection::vec(pair_at(s), 1..=40),
            any::<[bool; 4]>(),
        )
    })
}

/// A scene of 2 to 12 balls sharing one scale.
pub fn scene_case() -> impl Strategy<Value = SceneCase> {
    case_scale().prop_flat_map(|s| {
        (prop::collection::vec((ball(s), radius(s)), 2..=12), t_max()).prop_map(|(balls, t_max)| {
            let (balls, radii) = balls.into_iter().unzip();
            SceneCase {
                balls,
                radii,
                t_max,
            }
        })
    })
}

/// 2 to 5 polynomial coefficients, some tiny or huge next to the others.
pub fn poly_case() -> impl Strategy<Value = Vec<f64>> {
    case_scale().prop_flat_map(|s| {
        prop::collection::vec(
            prop_oneof![
                1 => wide(),
                1 => (small(), -1100i32..=1100).prop_map(move |(x, k)| scale(x, s + k)),
                2 => small().prop_map(move |x| scale(x, s)),
            ],
            2..=5,
        )
    })
}
