//! Scene benchmarks (issue 6): the earliest collision among N balls with the broad phase
//! (swept boxes + sort-and-sweep, then the exact kernel) against all N(N−1)/2 pairs.
//!
//! Scenes: N = 16 is a pool break (a rack of 15 at rest, the cue ball shot at it); N = 1,000,
//! 10,000 and 100,000 are balls on a table scaled to keep the density of 16 balls per
//! 2.54 × 1.27 m table, half of them rolling at up to 1 m/s, friction 0.1–0.3 m/s².
//!
//! `cargo bench --bench scene` in `benches/`; the broad phase on all cores and on one thread, all pairs
//! (all cores) up to N = 10,000 (at 100,000 it would take minutes per iteration). The number of
//! pairs the broad phase keeps is printed first.

use std::hint::black_box;
use std::num::NonZeroUsize;

use ballcollide::Ball;
use ballcollide::batch::Threads;
use ballcollide::scene::{PairSearch, SceneOptions, candidate_pairs, earliest_collision};
use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use nalgebra::Vector2;

#[path = "../tests/support/pool_balls.rs"]
mod pool_balls;
#[path = "../tests/support/rng.rs"]
mod rng;
use pool_balls::BALL_RADIUS as R;
use rng::Rng;

/// A rack of 15 balls at rest and the cue ball at 3 m/s towards it.
fn rack() -> Vec<Ball> {
    let mut balls: Vec<Ball> = (pool_balls::rack().into_iter())
        .map(|p| Ball::at_rest(p.into()).expect("valid"))
        .collect();
    let cue = Vector2::from(pool_balls::CUE_SPOT);
    balls.push(Ball::new(cue, Vector2::new(3.0, 0.0), 0.2).expect("valid"));
    balls
}

/// N balls on a table scaled to keep the density of 16 balls per 2.54 × 1.27 m.
fn table(n: usize, seed: u64) -> Vec<Ball> {
    let mut rng = Rng(seed);
    let scale = (n as f64 / 16.0).sqrt();
    (0..n)
        .map(|k| {
            let p = Vector2::new(
                rng.uniform(0.0, 2.54 * scale),
                rng.uniform(0.0, 1.27 * scale),
            );
            let angle = rng.uniform(0.0, std::f64::consts::TAU);
            let speed = if k % 2 == 0 {
                rng.uniform(0.0, 1.0)
            } else {
                0.0
            };
            let v = Vector2::new(speed * angle.cos(), speed * angle.sin());
            Ball::new(p, v, rng.uniform(0.1, 0.3)).expect("valid")
        })
        .collect()
}

fn scenes() -> Vec<(usize, Vec<Ball>)> {
    let mut s = vec![(16, rack())];
    for n in [1_000, 10_000, 100_000] {
        s.push((n, table(n, n as u64)));
    }
    s
}

fn bench(c: &mut Criterion) {
    let scenes = scenes();
    for (n, balls) in &scenes {
        let radii = vec![R; *n];
        let kept = candidate_pairs(balls, &radii, f64::INFINITY).expect("valid");
        let all = n * (n - 1) / 2;
        eprintln!(
            "N = {n}: the broad phase keeps {kept} of {all} pairs ({:.3} %)",
            100.0 * kept as f64 / all as f64
        );
    }
    let mut group = c.benchmark_group("earliest_collision");
    for (n, balls) in &scenes {
        let radii = vec![R; *n];
        if *n >= 10_000 {
            group.sample_size(10);
        }
        let one = Threads::AtMost(NonZeroUsize::MIN);
        for (name, search, threads) in [
            ("broad_phase", PairSearch::BroadPhase, Threads::All),
            ("broad_phase_1thread", PairSearch::BroadPhase, one),
            ("all_pairs", PairSearch::AllPairs, Threads::All),
        ] {
            if search == PairSearch::AllPairs && *n > 10_000 {
                continue;
            }
            let options = SceneOptions {
                search,
                threads,
                ..SceneOptions::default()
            };
            group.bench_with_input(BenchmarkId::new(name, n), balls, |b, balls| {
                b.iter(|| earliest_collision(black_box(balls), &radii, &options).expect("valid"))
            });
        }
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
