//! Criterion benchmark of `poly::solve_quartic` on random ball–ball gap quartics, against the
//! `roots` crate's `find_roots_quartic` on the very same quartics.
//!
//! Run: `cargo bench --bench poly` in `benches/`. Besides the timings it prints, once, how many real roots
//! `roots` misses (or reports that are not roots) compared with `solve_quartic`, whose roots
//! are checked against high-precision references in `tests/reference/poly.rs`.

use ballcollide::poly::solve_quartic;
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;

/// Ball radius sum (m), table size (m), as in SPEC and `tools/poly_reference.py`.
const R: f64 = 0.05715;
const TABLE: (f64, f64) = (2.54, 1.27);
/// Quartics per batch: each timing covers the whole batch.
const N: usize = 4096;

#[path = "../tests/support/rng.rs"]
mod rng;
use rng::Rng;

type V = (f64, f64);

fn friction(v: V, mu: f64) -> V {
    let s = v.0.hypot(v.1);
    if s == 0.0 {
        (0.0, 0.0)
    } else {
        (-mu * v.0 / s, -mu * v.1 / s)
    }
}

/// SPEC's gap quartic: a = ¼|Δf|², b = Δv·Δf, c = |Δv|² + Δp·Δf, d = 2Δp·Δv, e = |Δp|² − R².
fn gap(pa: V, va: V, fa: V, pb: V, vb: V, fb: V) -> [f64; 5] {
    let dp = (pa.0 - pb.0, pa.1 - pb.1);
    let dv = (va.0 - vb.0, va.1 - vb.1);
    let df = (fa.0 - fb.0, fa.1 - fb.1);
    let dot = |u: V, w: V| u.0 * w.0 + u.1 * w.1;
    [
        0.25 * dot(df, df),
        dot(dv, df),
        dot(dv, dv) + dot(dp, df),
        2.0 * dot(dp, dv),
        dot(dp, dp) - R * R,
    ]
}

fn on_table(rng: &mut Rng) -> V {
    (rng.uniform(R, TABLE.0 - R), rng.uniform(R, TABLE.1 - R))
}

fn velocity(speed: f64, angle: f64) -> V {
    (speed * angle.cos(), speed * angle.sin())
}

#[derive(Clone, Copy)]
enum Kind {
    /// Both balls moving, positions and velocities uniform.
    Random,
    /// Nearly parallel velocities, nearly equal friction: a ~ ε², b ~ ε (ε down to 1e-12).
    Parallel,
    /// One ball at rest, the other aimed at it half of the time.
    AtRest,
}

fn quartic(rng: &mut Rng, kind: Kind) -> [f64; 5] {
    let tau = std::f64::consts::TAU;
    let pa = on_table(rng);
    match kind {
        Kind::Random => {
            let pb = on_table(rng);
            let va = velocity(rng.uniform(0.0, 3.0), rng.uniform(0.0, tau));
            let vb = velocity(rng.uniform(0.0, 3.0), rng.uniform(0.0, tau));
            let (ma, mb) = (rng.uniform(0.05, 2.0), rng.uniform(0.05, 2.0));
            gap(pa, va, friction(va, ma), pb, vb, friction(vb, mb))
        }
        Kind::Parallel => {
            let eps = 10f64.powf(rng.uniform(-12.0, -2.0));
            let ang = rng.uniform(0.0, tau);
            let va = velocity(rng.uniform(0.0, 3.0), ang);
            let vb = velocity(rng.uniform(0.0, 3.0), ang + eps * rng.uniform(-1.0, 1.0));
            let ma = rng.uniform(0.05, 2.0);
            let mb = ma * (1.0 + eps * rng.uniform(-1.0, 1.0));
            let pb = if rng.uniform(0.0, 1.0) < 0.5 {
                on_table(rng)
            } else {
                let ell = rng.uniform(3.0 * R, 1.5);
                let off = rng.uniform(-2.5, 2.5) * R;
                (
                    pa.0 + ell * ang.cos() - off * ang.sin(),
                    pa.1 + ell * ang.sin() + off * ang.cos(),
                )
            };
            gap(pa, va, friction(va, ma), pb, vb, friction(vb, mb))
        }
        Kind::AtRest => {
            let pb = on_table(rng);
            let ang = if rng.uniform(0.0, 1.0) < 0.5 {
                rng.uniform(0.0, tau)
            } else {
                let dist = (pb.0 - pa.0).hypot(pb.1 - pa.1).max(1e-9);
                (pb.1 - pa.1).atan2(pb.0 - pa.0) + rng.uniform(-1.0, 1.0) * 2.5 * R / dist
            };
            let va = velocity(rng.uniform(0.0, 3.0), ang);
            let ma = rng.uniform(0.05, 2.0);
            gap(pa, va, friction(va, ma), pb, (0.0, 0.0), (0.0, 0.0))
        }
    }
}

fn batch(seed: u64, kinds: &[Kind]) -> Vec<[f64; 5]> {
    let mut rng = Rng(seed);
    (0..N)
        .map(|i| quartic(&mut rng, kinds[i % kinds.len()]))
        .collect()
}

/// Distinct values of a sorted slice (the `roots` crate reports each root once).
fn distinct(x: &[f64]) -> Vec<f64> {
    let mut v: Vec<f64> = x.to_vec();
    v.dedup();
    v
}

/// (roots ours has that `roots` misses, roots `roots` reports that ours does not have),
/// matching within 1e-6 relative (generous: a miss is a root not found at all).
fn compare(qs: &[[f64; 5]]) -> (usize, usize, usize) {
    let near = |x: f64, y: f64| (x - y).abs() <= 1e-6 * x.abs().max(1.0);
    let (mut ours_total, mut missed, mut spurious) = (0, 0, 0);
    for q in qs {
        let ours = distinct(&solve_quartic(q[0], q[1], q[2], q[3], q[4]));
        let theirs = roots::find_roots_quartic(q[0], q[1], q[2], q[3], q[4]);
        let theirs = theirs.as_ref();
        ours_total += ours.len();
        missed += ours
            .iter()
            .filter(|&&x| !theirs.iter().any(|&y| near(x, y)))
            .count();
        spurious += theirs
            .iter()
            .filter(|&&y| !ours.iter().any(|&x| near(x, y)))
            .count();
    }
    (ours_total, missed, spurious)
}

fn bench_quartic(c: &mut Criterion) {
    let sets = [
        (
            "mixed",
            batch(0x5EED_0001, &[Kind::Random, Kind::Parallel, Kind::AtRest]),
        ),
        ("random", batch(0x5EED_0002, &[Kind::Random])),
        ("near-parallel", batch(0x5EED_0003, &[Kind::Parallel])),
        ("at-rest", batch(0x5EED_0004, &[Kind::AtRest])),
    ];
    println!(
        "\nreal roots on {N} quartics per set (distinct values; ballcollide is the reference):"
    );
    for (name, qs) in &sets {
        let (total, missed, spurious) = compare(qs);
        println!(
            "  {name:>13}: ballcollide {total}, roots 0.0.8 misses {missed} and reports {spurious} that are not roots"
        );
    }
    let mut group = c.benchmark_group("quartic_ball_ball");
    group.throughput(Throughput::Elements(N as u64));
    for (name, qs) in &sets {
        group.bench_with_input(BenchmarkId::new("ballcollide", name), qs, |b, qs| {
            b.iter(|| {
                let mut n = 0;
                for q in qs {
                    n += solve_quartic(q[0], q[1], q[2], q[3], q[4]).len();
                }
                black_box(n)
            })
        });
        group.bench_with_input(BenchmarkId::new("roots-0.0.8", name), qs, |b, qs| {
            b.iter(|| {
                let mut n = 0;
                for q in qs {
                    n += roots::find_roots_quartic(q[0], q[1], q[2], q[3], q[4])
                        .as_ref()
                        .len();
                }
                black_box(n)
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench_quartic);
criterion_main!(benches);
