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
/// segments now and then 2²⁰…2⁴⁵ long); one path in three ends at rest; one path in eight
/// has one value no path may hold (NaN, ±∞).
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
    let rests = prop_oneof![2 => Just(false), 1 => Just(true)];
    (
        first,
        prop::collection::vec((step, values), 1..=6),
        rests,
        bad,
    )
        .prop_map(|(first, rows, rests, bad)| {
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
            if rests && let Some(last) = path.last_mut() {
                last[4..].fill(0.0);
            }
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

/// A pair aimed at the edge of the chord screen (`collision/chord_normals.rs`), where its
/// proof and the search's answer meet: A rolls straight to rest along `v` (a friction ball),
/// now and then after a slide that curls it off that line; B rests beside A's chord, or rolls
/// alongside it, `h` from A's chord line; the contact distance is `h·(1 ± δ)`, `δ` from
/// 10⁻¹⁵ to 10⁻², so that the balls just touch or just miss (or overlap at the start) where
/// B is level with A's run. Lengths are scaled by `2^s` for `s` from −1000 to 1000,
/// times start from 0 or a late time; 2-D or 3-D (at one height).
pub fn grazing_case() -> impl Strategy<Value = (PathCase, i32)> {
    let run = (
        (-1.0f64..1.0, -1.0f64..1.0),
        0.0f64..std::f64::consts::TAU,
        0.1f64..3.0,
        0.05f64..5.0,
        prop_oneof![2 => Just(None), 1 => (0.01f64..0.3, -5.0f64..5.0, -5.0f64..5.0).prop_map(Some)],
    );
    let beside = (
        -0.3f64..1.3,
        1e-3f64..0.5,
        any::<bool>(),
        prop_oneof![Just(None), (-1.0f64..1.0).prop_map(Some)],
    );
    let closeness = (-15.0f64..-2.0, any::<bool>());
    (
        run,
        beside,
        closeness,
        -1000i32..=1000,
        prop_oneof![Just(0.0), Just(1e4), 0.0f64..100.0],
        any::<bool>(),
        -1100i32..=1100,
    )
        .prop_map(
            |((p, angle, speed, mu, slide), (f, h, left, rolls), (d, wider), s, t0, three_d, k)| {
                let scale = 2f64.powi(s);
                let row = |start, p, v, a| planar_row(t0 + start, scale, p, v, a);
                // A: the slide (if any), then the straight roll to rest.
                let mut a = Vec::new();
                let (mut at, mut pos) = (0.0, [p.0, p.1]);
                let mut vel = [speed * angle.cos(), speed * angle.sin()];
                if let Some((length, ax, ay)) = slide {
                    a.push(row(0.0, pos, vel, [ax, ay]));
                    pos = [
                        pos[0] + vel[0] * length + 0.5 * ax * length * length,
                        pos[1] + vel[1] * length + 0.5 * ay * length * length,
                    ];
                    vel = [vel[0] + ax * length, vel[1] + ay * length];
                    at = length;
                }
                let u = vel[0].hypot(vel[1]).max(1e-3);
                let stop = u / mu;
                let decel = [-mu * vel[0] / u, -mu * vel[1] / u];
                a.push(row(at, pos, vel, decel));
                let rest = [pos[0] + 0.5 * vel[0] * stop, pos[1] + 0.5 * vel[1] * stop];
                a.push(row(at + stop, rest, [0.0; 2], [0.0; 2]));
                // B: `h` off A's chord, level with the point a fraction `f` along it.
                let chord = [rest[0] - p.0, rest[1] - p.1];
                let length = chord[0].hypot(chord[1]).max(1e-300);
                let side = if left { 1.0 } else { -1.0 };
                let normal = [-chord[1] / length * side, chord[0] / length * side];
                let beside = [
                    p.0 + f * chord[0] + h * normal[0],
                    p.1 + f * chord[1] + h * normal[1],
                ];
                let b = match rolls {
                    None => vec![row(0.0, beside, [0.0; 2], [0.0; 2])],
                    // Rolling alongside, started `lag` s later (or earlier), to rest.
                    Some(lag) => {
                        let start = [
                            beside[0] - 0.5 * vel[0] * stop,
                            beside[1] - 0.5 * vel[1] * stop,
                        ];
                        vec![
                            row(lag.max(0.0), start, vel, decel),
                            row(lag.max(0.0) + stop, beside, [0.0; 2], [0.0; 2]),
                        ]
                    }
                };
                let delta = 10f64.powf(d);
                let radius = h * scale * if wider { 1.0 + delta } else { 1.0 - delta };
                let case = PathCase {
                    a,
                    b,
                    radius,
                    t_max: f64::INFINITY,
                    three_d,
                };
                (case, k)
            },
        )
}

/// A pair aimed at the edge of the window box (`collision/window_box.rs`), where its proof and
/// the search's answer meet: B rests at the origin; A's centre passes it on a parabola whose
/// closest point, `h` from B, is where the box is tight: A crosses the line through B along
/// the x axis (at speed `w`) at the time `s*` its y coordinate turns (`y = h + c·(s − s*)²`),
/// so that the box's nearest point to B is `h` itself, formed from numbers far larger than `h`
/// (`c·s*²` against `h` from 2⁻¹ to 2⁻⁴⁰). The contact distance is `h·(1 ± 2⁻ᵏ)`, `k` from 10
/// to 52: the balls just touch or just miss, by amounts from well above the box's margin (the
/// box then proves a miss) down to far below its roundings (where only the margin keeps it
/// from proving a touching pair apart). A runs for ever, or rests from a time
/// after `s*`; lengths scaled by `2^s` (`s` from −1000 to 1000), times from 0 or later;
/// 2-D or 3-D (at one height).
pub fn window_box_edge_case() -> impl Strategy<Value = (PathCase, i32)> {
    (
        (0.05f64..10.0, 0.1f64..5.0, 0.1f64..5.0),
        (1i32..=40, 10i32..=52, any::<bool>()),
        prop_oneof![Just(None), (1.2f64..4.0).prop_map(Some)],
        (
            -1000i32..=1000,
            prop_oneof![Just(0.0), Just(1e4), 0.0f64..100.0],
        ),
        (any::<bool>(), any::<bool>(), -1100i32..=1100),
    )
        .prop_map(
            |((turn, w, reach), (m, k, wider), rests, (s, t0), (flip, three_d, k2))| {
                let scale = 2f64.powi(s);
                let h = 2f64.powi(-m);
                // `c·s*²` of about `reach`: far above `h`.
                let c = reach / (turn * turn);
                let side = if flip { -1.0 } else { 1.0 };
                let (p, v, a) = (
                    [-w * turn, side * (h + c * turn * turn)],
                    [w, -side * 2.0 * c * turn],
                    [0.0, side * 2.0 * c],
                );
                let row = |start, p, v, a| planar_row(t0 + start, scale, p, v, a);
                let mut path_a = vec![row(0.0, p, v, a)];
                if let Some(f) = rests {
                    let s1 = turn * f;
                    let end = [
                        p[0] + v[0] * s1 + 0.5 * a[0] * s1 * s1,
                        p[1] + v[1] * s1 + 0.5 * a[1] * s1 * s1,
                    ];
                    path_a.push(row(s1, end, [0.0; 2], [0.0; 2]));
                }
                let delta = 2f64.powi(-k);
                let radius = h * scale * if wider { 1.0 + delta } else { 1.0 - delta };
                let case = PathCase {
                    a: path_a,
                    b: vec![row(0.0, [0.0; 2], [0.0; 2], [0.0; 2])],
                    radius,
                    t_max: f64::INFINITY,
                    three_d,
                };
                (case, k2)
            },
        )
}

/// A segment's inputs in the plane (z = 0): starting at `start`, position, velocity and
/// acceleration scaled by `scale`.
fn planar_row(start: f64, scale: f64, p: [f64; 2], v: [f64; 2], a: [f64; 2]) -> SegmentInput {
    let mut r = [0.0; 10];
    r[0] = start;
    for i in 0..2 {
        r[1 + i] = p[i] * scale;
        r[4 + i] = v[i] * scale;
        r[7 + i] = a[i] * scale;
    }
    r
}
