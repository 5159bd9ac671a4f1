//! `scene`: the broad phase must give exactly the brute-force all-pairs answers (bit for bit,
//! same pairs, same tie rule), for any number of threads, on random scenes up to N = 2,000
//! with every kind of ball (stopping, frictionless, at rest, touching or overlapping at the
//! start) and with or without a horizon.

use std::num::NonZeroUsize;

use ballcollide::batch::{PerPair, Threads};
use ballcollide::scene::{
    self, PairSearch, SceneOptions, candidate_pairs, earliest_collision, first_contacts,
    pairwise_collision_times,
};
use ballcollide::{Ball, CollisionOptions, InputErrorKind, collision_time_with};
use nalgebra::Vector2;
use proptest::prelude::*;

use crate::support::rng;
use rng::Rng;

/// What a random scene is made of.
#[derive(Clone, Copy, Debug)]
enum Mix {
    /// Stopping balls, a quarter at rest, on a table sized for constant density.
    Table,
    /// Every kind: stopping, frictionless (rays), at rest, and balls placed touching or
    /// overlapping a neighbour, with varied radii.
    Everything,
    /// Frictionless balls only (every box infinite unless a horizon cuts it).
    Frictionless,
}

fn random_scene(n: usize, mix: Mix, seed: u64) -> (Vec<Ball>, Vec<f64>) {
    let mut rng = Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
    // 16 balls per 2.54 × 1.27 m table, scaled to keep the density.
    let scale = (n as f64 / 16.0).sqrt().max(1.0);
    let (w, h) = (2.54 * scale, 1.27 * scale);
    let mut balls: Vec<Ball> = Vec::with_capacity(n);
    let mut radii = Vec::with_capacity(n);
    for k in 0..n {
        let kind = match mix {
            Mix::Table => [0, 0, 0, 2][rng.below(4) as usize],
            Mix::Everything => rng.below(5),
            Mix::Frictionless => 1,
        };
        let r = match mix {
            Mix::Everything => rng.uniform(0.01, 0.08),
            _ => 0.028575,
        };
        let mut p = Vector2::new(rng.uniform(0.0, w), rng.uniform(0.0, h));
        if kind == 3 && k > 0 {
            // Touching or overlapping an earlier ball (exactly touching along an axis half
            // of the time).
            let other = rng.below(k as u64) as usize;
            let q = balls[other].position();
            let d = radii[other] + r;
            p = if rng.below(2) == 0 {
                q + Vector2::new(d, 0.0)
            } else {
                q + Vector2::new(rng.uniform(-d, d), rng.uniform(-d, d))
            };
        }
        let angle = rng.uniform(0.0, std::f64::consts::TAU);
        let speed = rng.uniform(0.0, 2.0);
        let v = Vector2::new(speed * angle.cos(), speed * angle.sin());
        let ball = match kind {
            1 => Ball::new(p, v, 0.0),
            2 => Ball::new(p, Vector2::zeros(), rng.uniform(0.0, 1.0)),
            _ => Ball::new(p, v, rng.uniform(0.05, 2.0)),
        };
        balls.push(ball.expect("valid ball"));
        radii.push(r);
    }
    (balls, radii)
}

/// The brute-force reference: every pair `i < j` through the public single-pair API.
fn brute_force(balls: &[Ball], radii: &[f64], t_max: f64) -> Vec<f64> {
    let n = balls.len();
    let mut times = vec![f64::INFINITY; n * n];
    let options = CollisionOptions { t_max };
    for i in 0..n {
        for j in i + 1..n {
            let t = collision_time_with(&balls[i], &balls[j], radii[i] + radii[j], &options)
                .expect("valid pair")
                .unwrap_or(f64::INFINITY);
            times[i * n + j] = t;
            times[j * n + i] = t;
        }
    }
    times
}

fn brute_earliest(times: &[f64], n: usize) -> Option<(f64, usize, usize)> {
    let mut best: Option<(f64, usize, usize)> = None;
    for i in 0..n {
        for j in i + 1..n {
            let t = times[i * n + j];
            if t.is_finite() && best.is_none_or(|(b, _, _)| t < b) {
                best = Some((t, i, j));
            }
        }
    }
    best
}

fn brute_first(times: &[f64], n: usize) -> (Vec<f64>, Vec<Option<usize>>) {
    (0..n)
        .map(|i| {
            let mut best = (f64::INFINITY, None);
            for j in 0..n {
                let t = times[i * n + j];
                if t.is_finite() && t < best.0 {
                    best = (t, Some(j));
                }
            }
            best
        })
        .unzip()
}

fn bits(x: &[f64]) -> Vec<u64> {
    x.iter().map(|t| t.to_bits()).collect()
}

/// All three queries, with the broad phase and with all pairs, on 1 and all threads, equal
/// the brute force.
fn assert_matches_brute_force(balls: &[Ball], radii: &[f64], t_max: f64) {
    let n = balls.len();
    let reference = brute_force(balls, radii, t_max);
    let earliest = brute_earliest(&reference, n);
    let (first_t, first_p) = brute_first(&reference, n);
    let one = Threads::AtMost(NonZeroUsize::MIN);
    for search in [PairSearch::BroadPhase, PairSearch::AllPairs] {
        for threads in [Threads::All, one] {
            let options = SceneOptions {
                t_max,
                threads,
                search,
            };
            let times = pairwise_collision_times(balls, radii, &options).unwrap();
            let mismatch = (0..n * n).find(|&k| times[k].to_bits() != reference[k].to_bits());
            assert_eq!(
                mismatch.map(|k| (k / n, k % n, times[k], reference[k])),
                None,
                "{search:?} {threads:?}: (i, j, found, brute force)"
            );
            let found = earliest_collision(balls, radii, &options).unwrap();
            assert_eq!(
                found.map(|(t, i, j)| (t.to_bits(), i, j)),
                earliest.map(|(t, i, j)| (t.to_bits(), i, j)),
                "{search:?} {threads:?}"
            );
            let (t, p) = first_contacts(balls, radii, &options).unwrap();
            assert_eq!(bits(&t), bits(&first_t));
            assert_eq!(p, first_p);
        }
    }
}

#[test]
fn random_table_scenes_equal_brute_force() {
    for (n, seed) in [(2, 1), (16, 2), (100, 3), (500, 4), (2000, 5)] {
        let (balls, radii) = random_scene(n, Mix::Table, seed);
        assert_matches_brute_force(&balls, &radii, f64::INFINITY);
    }
}

#[test]
fn scenes_with_every_kind_of_ball_equal_brute_force() {
    for (n, seed) in [(3, 11), (40, 12), (300, 13), (2000, 14)] {
        let (balls, radii) = random_scene(n, Mix::Everything, seed);
        assert_matches_brute_force(&balls, &radii, f64::INFINITY);
        assert_matches_brute_force(&balls, &radii, 0.7);
        assert_matches_brute_force(&balls, &radii, 0.0);
    }
}

#[test]
fn frictionless_scenes_with_and_without_horizon() {
    for (n, seed) in [(50, 21), (1000, 22)] {
        let (balls, radii) = random_scene(n, Mix::Frictionless, seed);
        assert_matches_brute_force(&balls, &radii, f64::INFINITY);
        assert_matches_brute_force(&balls, &radii, 0.5);
    }
}

#[test]
fn the_broad_phase_prunes_most_pairs_of_a_table() {
    let n = 2000;
    let (balls, radii) = random_scene(n, Mix::Table, 31);
    let kept = candidate_pairs(&balls, &radii, f64::INFINITY).unwrap();
    assert!(kept < n * (n - 1) / 2 / 20, "kept {kept} pairs");
    // A horizon shortens the boxes.
    assert!(candidate_pairs(&balls, &radii, 0.1).unwrap() < kept);
}

#[test]
fn balls_at_rest_never_collide_with_each_other() {
    // A tight rack of resting balls, all touching: nothing moves, nothing collides.
    let r = 0.028575;
    let mut balls = Vec::new();
    for row in 0..5 {
        for k in 0..=row {
            let x = row as f64 * r * 3f64.sqrt();
            let y = (k as f64 - row as f64 / 2.0) * 2.0 * r;
            balls.push(Ball::at_rest(Vector2::new(x, y)).unwrap());
        }
    }
    let radii = vec![r; balls.len()];
    let options = SceneOptions::default();
    assert_eq!(earliest_collision(&balls, &radii, &options).unwrap(), None);
    assert_matches_brute_force(&balls, &radii, f64::INFINITY);

    // A cue ball shot at the apex hits it first.
    balls.push(Ball::new(Vector2::new(-1.0, 0.0), Vector2::new(3.0, 0.0), 0.2).unwrap());
    let mut radii = radii;
    radii.push(r);
    let (t, i, j) = earliest_collision(&balls, &radii, &options)
        .unwrap()
        .unwrap();
    assert_eq!((i, j), (0, 15));
    assert!(t > 0.3 && t < 0.4, "{t}");
    assert_matches_brute_force(&balls, &radii, f64::INFINITY);
}

#[test]
fn touching_and_overlapping_starts() {
    let ball = |p: [f64; 2], v: [f64; 2]| Ball::new(p.into(), v.into(), 0.1).unwrap();
    let balls = [
        // 0 and 1 touch and approach: a collision at 0.
        ball([0.0, 0.0], [1.0, 0.0]),
        ball([1.0, 0.0], [0.0, 0.0]),
        // 2 and 3 overlap and separate: no collision.
        ball([5.0, 10.0], [-1.0, 0.0]),
        ball([5.5, 10.0], [1.0, 0.0]),
    ];
    let radii = [0.5; 4];
    let options = SceneOptions::default();
    assert_eq!(
        earliest_collision(&balls, &radii, &options).unwrap(),
        Some((0.0, 0, 1))
    );
    let (times, partners) = first_contacts(&balls, &radii, &options).unwrap();
    assert_eq!(times, [0.0, 0.0, f64::INFINITY, f64::INFINITY]);
    assert_eq!(partners, [Some(1), Some(0), None, None]);
    assert_matches_brute_force(&balls, &radii, f64::INFINITY);
}

#[test]
fn ties_go_to_the_lowest_indices() {
    // Ball 2 sits between 1 and 3, which approach it symmetrically; 0 is far away. Pairs (1, 2)
    // and (2, 3) collide at the same time.
    let balls = [
        Ball::at_rest(Vector2::new(50.0, 50.0)).unwrap(),
        Ball::new(Vector2::new(-2.0, 0.0), Vector2::new(1.0, 0.0), 0.0).unwrap(),
        Ball::at_rest(Vector2::new(0.0, 0.0)).unwrap(),
        Ball::new(Vector2::new(2.0, 0.0), Vector2::new(-1.0, 0.0), 0.0).unwrap(),
    ];
    let radii = [0.5; 4];
    let options = SceneOptions::default();
    assert_eq!(
        earliest_collision(&balls, &radii, &options).unwrap(),
        Some((1.0, 1, 2))
    );
    let (times, partners) = first_contacts(&balls, &radii, &options).unwrap();
    assert_eq!(times, [f64::INFINITY, 1.0, 1.0, 1.0]);
    assert_eq!(partners, [None, Some(2), Some(1), Some(2)]);
}

#[test]
fn infinite_boxes_far_apart() {
    // Two frictionless rays running away from each other along x at the same height, far
    // apart: their boxes are half-planes that do not overlap.
    let balls = [
        Ball::new(Vector2::new(-1e3, 0.0), Vector2::new(-1.0, 0.0), 0.0).unwrap(),
        Ball::new(Vector2::new(1e3, 0.0), Vector2::new(1.0, 0.0), 0.0).unwrap(),
        // A ray along y through the path of neither.
        Ball::new(Vector2::new(0.0, -1e3), Vector2::new(0.0, 1.0), 0.0).unwrap(),
    ];
    let radii = [0.1; 3];
    assert_eq!(candidate_pairs(&balls, &radii, f64::INFINITY).unwrap(), 0);
    assert_matches_brute_force(&balls, &radii, f64::INFINITY);
    // Huge velocities and a horizon whose product overflows: boxes go to infinity, no NaN.
    let fast = [
        Ball::new(Vector2::new(0.0, 0.0), Vector2::new(1e300, 0.0), 0.0).unwrap(),
        Ball::at_rest(Vector2::new(1e10, 0.0)).unwrap(),
    ];
    assert_matches_brute_force(&fast, &[1.0, 1.0], 1e100);
}

#[test]
fn empty_and_single_ball_scenes() {
    let options = SceneOptions::default();
    assert!(
        pairwise_collision_times(&[], &[], &options)
            .unwrap()
            .is_empty()
    );
    assert_eq!(earliest_collision(&[], &[], &options).unwrap(), None);
    assert_eq!(
        first_contacts(&[], &[], &options).unwrap(),
        (vec![], vec![])
    );
    let one = [Ball::at_rest(Vector2::zeros()).unwrap()];
    assert_eq!(
        pairwise_collision_times(&one, &[1.0], &options).unwrap(),
        [f64::INFINITY]
    );
    assert_eq!(earliest_collision(&one, &[1.0], &options).unwrap(), None);
}

#[test]
fn bad_input_names_the_argument_and_index() {
    let balls = [Ball::at_rest(Vector2::zeros()).unwrap(); 3];
    let options = SceneOptions::default();
    let err = earliest_collision(&balls, &[1.0, 0.0, -1.0], &options).unwrap_err();
    assert_eq!((err.argument(), err.index()), ("radius", Some(1)));
    let err = first_contacts(&balls, &[1.0, f64::NAN, 1.0], &options).unwrap_err();
    assert_eq!(err.to_string(), "radius[1]: must be finite, got NaN");
    // A radius whose sums overflow is valid (the pair search forms them in its own unit).
    let times = pairwise_collision_times(&balls, &[1.0, 1.0, f64::MAX], &options).unwrap();
    assert_eq!(times, [f64::INFINITY; 9]); // overlapping at rest: no contact
    let err = earliest_collision(&balls, &[1.0; 2], &options).unwrap_err();
    assert_eq!(
        err.kind(),
        InputErrorKind::LengthMismatch {
            expected: 3,
            found: 2
        }
    );
    let bad_horizon = SceneOptions {
        t_max: -1.0,
        ..options
    };
    let err = earliest_collision(&balls, &[1.0; 3], &bad_horizon).unwrap_err();
    assert_eq!(err.argument(), "t_max");

    let err = scene::balls(
        &[[0.0, 0.0], [0.0, f64::INFINITY]],
        &[[0.0, 0.0]; 2],
        PerPair::All(0.1),
    )
    .unwrap_err();
    assert_eq!(err.to_string(), "pos[1]: must be finite, got inf");
    let err = scene::balls(&[[0.0, 0.0]; 2], &[[0.0, 0.0]; 3], PerPair::All(0.1)).unwrap_err();
    assert_eq!((err.argument(), err.index()), ("vel", None));
    let err = scene::balls(&[[0.0, 0.0]; 2], &[[0.0, 0.0]; 2], PerPair::Each(&[0.1])).unwrap_err();
    assert_eq!(err.argument(), "friction");
}

#[test]
fn translated_and_scaled_scenes() {
    // Far from the origin and at other scales, the rounding margin still keeps every pair the
    // kernel reports.
    let (balls, radii) = random_scene(400, Mix::Everything, 41);
    for (shift, scale) in [
        (1e6, 1.0),
        (-3e3, 1e-3),
        (0.0, 1e5),
        (1e8, 1e-2),
        (7.5, 1e-200),
    ] {
        let moved: Vec<Ball> = balls
            .iter()
            .map(|b| {
                let p = b.position() * scale + Vector2::new(shift, 0.5 * shift);
                Ball::new(p, b.velocity() * scale, b.friction() * scale).unwrap()
            })
            .collect();
        let r: Vec<f64> = radii.iter().map(|r| r * scale).collect();
        assert_matches_brute_force(&moved, &r, f64::INFINITY);
        assert_matches_brute_force(&moved, &r, 0.5);
    }
}

#[test]
fn grazing_pairs_at_the_edge_of_their_boxes() {
    // A ball sliding along an axis past another whose centre is the contact distance away
    // (give or take a few ulps to 1e-9): the boxes' edges sit exactly on the tangent line,
    // where only the rounding margin separates pruned from kept.
    let mut balls = Vec::new();
    let mut radii = Vec::new();
    let mut k = 0.0;
    for offset in [
        -1e-9, -1e-12, -1e-15, -4e-16, 0.0, 4e-16, 1e-15, 1e-12, 1e-9,
    ] {
        for (r1, r2) in [(0.028575, 0.028575), (0.01, 0.07), (1e-3, 1e-3)] {
            for (v, mu) in [(1.0, 0.0), (1.0, 0.3), (-2.0, 0.5)] {
                let gap = (r1 + r2) * (1.0 + offset);
                let y = 10.0 * k;
                k += 1.0;
                for axis in [0, 1] {
                    let at = |x: f64, y: f64| {
                        if axis == 0 {
                            Vector2::new(x, y)
                        } else {
                            Vector2::new(y, x)
                        }
                    };
                    let vel = if axis == 0 { [v, 0.0] } else { [0.0, v] };
                    balls.push(Ball::new(at(0.0, y), vel.into(), mu).unwrap());
                    balls.push(Ball::at_rest(at(v.signum() * 0.5, y + gap)).unwrap());
                    radii.extend([r1, r2]);
                }
            }
        }
    }
    assert_matches_brute_force(&balls, &radii, f64::INFINITY);
    assert_matches_brute_force(&balls, &radii, 1.0);
}

fn arb_ball() -> impl Strategy<Value = Ball> {
    (
        0u8..4,
        -3.0..3.0f64,
        -3.0..3.0f64,
        -2.0..2.0f64,
        -2.0..2.0f64,
        0.0..2.0f64,
    )
        .prop_map(|(kind, x, y, vx, vy, mu)| {
            let (v, mu) = match kind {
                0 => (Vector2::zeros(), mu),
                1 => (Vector2::new(vx, vy), 0.0),
                // Axis-aligned motion: boxes of zero width.
                2 => (Vector2::new(vx, 0.0), mu),
                _ => (Vector2::new(vx, vy), mu),
            };
            Ball::new(Vector2::new(x, y), v, mu).expect("valid")
        })
}

proptest! {
    #[test]
    fn any_small_scene_equals_brute_force(
        scene in prop::collection::vec((arb_ball(), 0.01..0.5f64), 0..24),
        t_max in prop_oneof![Just(f64::INFINITY), 0.0..3.0f64],
    ) {
        let (balls, radii): (Vec<Ball>, Vec<f64>) = scene.into_iter().unzip();
        assert_matches_brute_force(&balls, &radii, t_max);
    }
}
