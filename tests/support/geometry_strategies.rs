//! proptest strategies for the static-geometry invariants (`tests/support/geometry_invariants.rs`):
//! the same kinds of cases as the fuzz target `geometry`'s decoder (`fuzz/src/lib.rs`), paths
//! from `path_strategies.rs` and numbers from `strategies.rs`.
#![allow(dead_code)]

use proptest::prelude::*;

use super::geometry_invariants::{DiscObject, GeometryCase, PlaneObject, SegmentObject};
use super::path_strategies::path;
use super::strategies::{case_scale, length, radius, t_max, wide};

/// Now and then (one in 16) a value no object may hold in place of one of `N` numbers:
/// `Some((which, NaN or ±∞))`.
fn bad<const N: usize>() -> impl Strategy<Value = Option<(usize, f64)>> {
    prop_oneof![
        15 => Just(None),
        1 => (0..N, prop_oneof![Just(f64::NAN), Just(f64::INFINITY), Just(f64::NEG_INFINITY)])
            .prop_map(Some),
    ]
}

fn spoiled<const N: usize>(mut x: [f64; N], bad: Option<(usize, f64)>) -> [f64; N] {
    if let Some((at, v)) = bad {
        x[at] = v;
    }
    x
}

/// A segment scaled by `2^s`: ends like a ball's position (now and then the same point), a
/// side of −1, 0 or 1 (now and then any number).
fn segment_object(s: i32) -> impl Strategy<Value = SegmentObject> {
    let side = prop_oneof![15 => -1i64..=1, 1 => any::<i32>().prop_map(i64::from)];
    (
        prop::array::uniform4(length(s)),
        prop_oneof![15 => Just(false), 1 => Just(true)],
        bad::<4>(),
        side,
    )
        .prop_map(|(mut e, same, bad, side)| {
            if same {
                e[2] = e[0];
                e[3] = e[1];
            }
            (spoiled(e, bad), side)
        })
}

/// A circle or a target scaled by `2^s`: a centre like a ball's position, a radius like a
/// ball's, now and then 0, −0 or negative.
fn disc_object(s: i32) -> impl Strategy<Value = DiscObject> {
    (
        prop::array::uniform3(length(s)),
        radius(s),
        prop_oneof![13 => Just(1.0), 1 => Just(0.0), 1 => Just(-0.0), 1 => Just(-1.0)],
        bad::<4>(),
    )
        .prop_map(|(c, rho, sign, bad)| spoiled([c[0], c[1], c[2], rho * sign], bad))
}

/// A plane with its point scaled by `2^s`: a small integer normal (now and then 0), or any.
fn plane_object(s: i32) -> impl Strategy<Value = PlaneObject> {
    let normal = prop_oneof![
        7 => prop::array::uniform3((-2i8..=2).prop_map(f64::from)),
        1 => prop::array::uniform3(wide()),
    ];
    (prop::array::uniform3(length(s)), normal, bad::<6>())
        .prop_map(|(p, n, bad)| spoiled([p[0], p[1], p[2], n[0], n[1], n[2]], bad))
}

/// Balls against static geometry, as the fuzz target draws them: 1 to 3 paths and 0 to 3
/// objects of each kind (half the time no plane, else 1 or 2) sharing one scale, 2-D or 3-D;
/// the exponents of a length scaling and of a translation (about the case's scale).
pub fn geometry_case() -> impl Strategy<Value = (GeometryCase, i32, i32)> {
    case_scale().prop_flat_map(|s| {
        (
            prop::collection::vec(path(s), 1..=3),
            (
                prop::collection::vec(segment_object(s), 0..=3),
                prop::collection::vec(disc_object(s), 0..=3),
                prop::collection::vec(disc_object(s), 0..=3),
                // (Half the cases without a plane: a path that runs for ever meets most.)
                prop_oneof![Just(0usize..1), Just(1usize..3)]
                    .prop_flat_map(move |n| prop::collection::vec(plane_object(s), n)),
            ),
            (radius(s), t_max(), any::<bool>()),
            (-1100i32..=1100, -8i32..=8),
        )
            .prop_map(
                move |(
                    paths,
                    (segments, circles, targets, planes),
                    (radius, t_max, three_d),
                    (k, j),
                )| {
                    let case = GeometryCase {
                        paths,
                        segments,
                        circles,
                        targets,
                        planes,
                        radius,
                        t_max,
                        three_d,
                    };
                    (case, k, s.saturating_add(j))
                },
            )
    })
}
