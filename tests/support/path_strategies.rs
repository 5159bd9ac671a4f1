//! proptest strategies for the path invariants (`tests/support/path_invariants.rs`): the same
//! kinds of paths as the fuzz target `path`'s decoder (`fuzz/src/lib.rs`), over the whole
//! float range, built from the numbers of `tests/support/strategies.rs`.
#![allow(dead_code)]

use proptest::prelude::*;

use super::path_invariants::{PathCase, SegmentInput};
use super::strategies::{case_scale, friction, length, radius, small, t_max, table, wide};

/// A path of 1 to 6 segments whose numbers are scaled by `2^s`, as the fuzz target's
/// decoder draws them: starts from a first one (0, small or any) by durations that are
/// small, table-like or any size (now and then one back in time), positions and velocities
/// like a ball's, accelerations like frictions of either sign (now and then subnormal, on
/// segments now and then 2²⁰…2⁴⁵ long); one path in eight has one
/// value no path may hold (NaN, ±∞).
pub fn path(s: i32) -> impl Strategy<Value = Vec<SegmentInput>> {
    let first = prop_oneof![2 => Just(0.0), 1 => small(), 1 => wide()];
    let step = prop_oneof![
        1 => small().prop_map(|x| -x.abs()),
        2 => Just(0.0),
        2 => wide().prop_map(f64::abs),
        5 => table().prop_map(f64::abs),
        6 => small().prop_map(f64::abs),
        // Long segments, where an underflowing product costs most.
        1 => (20i32..=45).prop_map(|e| 2f64.powi(e)),
    ];
    // Now and then a subnormal acceleration: `i·2⁻¹⁰⁷⁴`.
    let magnitude = prop_oneof![7 => friction(s), 1 => (1u64..64).prop_map(f64::from_bits)];
    let acceleration = (magnitude, any::<bool>()).prop_map(|(a, neg)| if neg { -a } else { a });
    let values = (
        prop::array::uniform6(length(s)),
        prop::array::uniform3(acceleration),
    );
    let bad = prop_oneof![
        7 => Just(None),
        1 => (0usize..60, prop_oneof![Just(f64::NAN), Just(f64::INFINITY), Just(f64::NEG_INFINITY)])
            .prop_map(Some),
    ];
    (first, prop::collection::vec((step, values), 1..=6), bad).prop_map(|(first, rows, bad)| {
        let mut start = first;
        let mut path: Vec<SegmentInput> = rows
            .into_iter()
            .enumerate()
            .map(|(k, (step, (lengths, accelerations)))| {
                if k > 0 {
                    start += step;
                }
                let mut row = [0.0; 10];
                row[0] = start;
                row[1..7].copy_from_slice(&lengths);
                row[7..].copy_from_slice(&accelerations);
                row
            })
            .collect();
        if let Some((at, x)) = bad {
            let n = path.len();
            path[(at / 10) % n][at % 10] = x;
        }
        path
    })
}
/// A query on two paths sharing one scale, 2-D or 3-D, and the exponent of a length scaling.
pub fn path_case() -> impl Strategy<Value = (PathCase, i32)> {
    case_scale().prop_flat_map(|s| {
        (
            path(s),
            path(s),
            radius(s),
            t_max(),
            any::<bool>(),
            -1100i32..=1100,
        )
            .prop_map(|(a, b, radius, t_max, three_d, k)| {
                (
                    PathCase {
                        a,
                        b,
                        radius,
                        t_max,
                        three_d,
                    },
                    k,
                )
            })
    })
}
