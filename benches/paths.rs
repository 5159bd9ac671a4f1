//! Path benchmarks (issue 17): first contacts of balls on paths of constant-acceleration
//! segments, in batches.
//!
//! - `pool_table`: 200,000 random pool-table pairs of 3-segment paths (sliding → rolling →
//!   rest, built as pooltool builds them: [`PoolBall::path`]); on one thread, also its two
//!   parts apart: the pairs whose whole-path boxes are apart ([`boxes_apart`]) and the others;
//! - `seed_as_paths`: 200,000 random table pairs of friction balls (speeds 0–3 m/s, friction
//!   0.05–2 m/s²), as paths ([`Ball::path`]) through `path_collision_times` and as balls
//!   through `collision_times`;
//! - `ball_against_all`: in a 16-ball scene, every ball against the 15 others (what an event
//!   loop asks after each event), the ball broadcast (one A path) or repeated 15 times. Scenes:
//!   `break` (the rack at rest, the cue ball sliding into it with spin) and `spreading` (every
//!   ball of the rack moving away from it, sliding, the cue ball too). A query's 15 pairs are
//!   fewer than a batch task's chunk, so `Threads::All` runs them on the calling thread too:
//!   `ball_against_all_all_threads` is the same work as on one thread, in wall time.
//!
//! `cargo bench --bench paths` in `benches/` (under 2 minutes: few samples, short runs); `-- pool_table` etc.
//! selects a group. One-thread groups (`…_1_thread`) time the thread's CPU time
//! ([`ThreadCpuTime`]), the others wall time. First, for each set, the hits and how the pairs
//! divide are printed (see [`describe`]); with `--features stage-counts`, also how many pairs
//! and windows each stage of the library's search settles (`collision::stage_counts`).

use std::hint::black_box;
use std::num::NonZeroUsize;
use std::sync::OnceLock;
use std::time::Duration;

use ballcollide::Ball;
use ballcollide::batch::{PathPairs, PerPair, Threads, collision_times, path_collision_times};
use ballcollide::collision::stage_counts;
use ballcollide::path::Path2;
use criterion::measurement::Measurement;
use criterion::{
    BenchmarkGroup, Criterion, SamplingMode, Throughput, criterion_group, criterion_main,
};
use nalgebra::Vector2;

mod cpu_time;
#[path = "../tests/support/machine.rs"]
mod machine;
#[path = "../tests/support/path_table.rs"]
mod path_table;
#[path = "../tests/support/pool_balls.rs"]
mod pool_balls;
#[path = "../tests/support/rng.rs"]
mod rng;
#[path = "../tests/support/table_pairs.rs"]
mod table_pairs;
#[path = "../tests/support/thread_cpu_time.rs"]
mod thread_cpu_time;
use cpu_time::ThreadCpuTime;
use path_table::PathTable;
use pool_balls::{BALL_RADIUS, CUE_SPOT, PoolBall, rack};
use rng::Rng;
use table_pairs::{Kind, set};

/// The contact distance of two pool balls.
const CONTACT: f64 = 2.0 * BALL_RADIUS;
/// Pairs in the `pool_table` and `seed_as_paths` sets.
const PAIRS: usize = 200_000;

const ONE: Threads = Threads::AtMost(NonZeroUsize::MIN);

/// Two sides of a batch of path pairs, owned.
struct PathSet {
    a: PathTable<2>,
    b: PathTable<2>,
}

impl PathSet {
    fn pairs(&self) -> PathPairs<'_, 2> {
        PathPairs {
            a: self.a.side(),
            b: self.b.side(),
            contact_distance: PerPair::All(CONTACT),
            t_max: PerPair::All(f64::INFINITY),
        }
    }

    /// The pairs `indices` of this set.
    fn pick(&self, indices: &[usize]) -> Self {
        Self {
            a: self.a.pick(indices),
            b: self.b.pick(indices),
        }
    }

    /// The pairs split by [`boxes_apart`]: those apart, the others.
    fn split_by_boxes(&self) -> [Self; 2] {
        let (apart, overlap): (Vec<usize>, Vec<usize>) =
            (0..self.a.len()).partition(|&i| boxes_apart(self, i));
        [self.pick(&apart), self.pick(&overlap)]
    }

    fn times(&self) -> Vec<f64> {
        let mut out = vec![0.0; self.b.len().max(self.a.len())];
        path_collision_times(&self.pairs(), &mut out, Threads::All).expect("valid paths");
        out
    }
}

/// `n` pairs of random pool balls ([`PoolBall::random`]).
fn pool_table(n: usize, seed: u64) -> PathSet {
    let mut rng = Rng(seed);
    let mut side = || {
        let paths: Vec<Path2> = (0..n).map(|_| PoolBall::random(&mut rng).path()).collect();
        PathTable::of(3, &paths)
    };
    let a = side();
    PathSet { a, b: side() }
}

/// The axis-aligned box a path covers from its first start on (the last segment at rest), as
/// `[min, max]` per axis: each segment's endpoints and, where its velocity turns within the
/// segment, the turning point.
fn path_box(table: &PathTable<2>, i: usize) -> [[f64; 2]; 2] {
    let rows: Vec<_> = table.rows(i).collect();
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for (k, &(start, p, v, a)) in rows.iter().enumerate() {
        let length = rows.get(k + 1).map_or(0.0, |next| next.0 - start);
        for axis in 0..2 {
            let at = |s: f64| p[axis] + v[axis] * s + 0.5 * a[axis] * s * s;
            let mut points = vec![at(0.0), at(length)];
            if a[axis] != 0.0 {
                let turn = -v[axis] / a[axis];
                if turn > 0.0 && turn < length {
                    points.push(at(turn));
                }
            }
            for x in points {
                lo[axis] = lo[axis].min(x);
                hi[axis] = hi[axis].max(x);
            }
        }
    }
    [lo, hi]
}

/// Whether the boxes of pair `i`'s two whole paths, one widened by the contact distance, miss
/// each other: the pair is apart for ever (a screen on whole paths could settle it).
fn boxes_apart(set: &PathSet, i: usize) -> bool {
    let ([lo_a, hi_a], [lo_b, hi_b]) = (path_box(&set.a, i), path_box(&set.b, i));
    (0..2).any(|axis| lo_a[axis] - CONTACT > hi_b[axis] || lo_b[axis] - CONTACT > hi_a[axis])
}

/// The starts of both paths of pair `i`, merged: the ends of the windows on which both
/// motions are polynomial.
fn window_starts(set: &PathSet, i: usize) -> Vec<f64> {
    let mut starts: Vec<f64> = (set.a.rows(i).chain(set.b.rows(i)))
        .map(|row| row.0)
        .collect();
    starts.sort_by(f64::total_cmp);
    starts.dedup();
    starts
}

/// Prints, for a set of path pairs: the hits (at `t = 0`, in the first window, i.e. before
/// either path leaves its first segment, and later), the pairs whose whole-path boxes are
/// apart (and, of those, any hit — there must be none), and the windows a search from `t = 0`
/// meets up to the contact (or to the last start).
fn describe(name: &str, set: &PathSet) {
    stage_counts::take();
    let times = set.times();
    let stages = stage_counts::take();
    let n = times.len();
    let (mut at_zero, mut first, mut later, mut apart, mut apart_hits) = (0, 0, 0, 0, 0);
    let (mut windows, mut windows_no_contact) = (0, 0);
    for (i, &t) in times.iter().enumerate() {
        let starts = window_starts(set, i);
        let first_end = starts.get(1).copied().unwrap_or(f64::INFINITY);
        match t {
            _ if t == 0.0 => at_zero += 1,
            _ if t < first_end => first += 1,
            _ if t.is_finite() => later += 1,
            _ => windows_no_contact += starts.len(),
        }
        windows += starts.iter().filter(|&&s| s <= t).count();
        if boxes_apart(set, i) {
            apart += 1;
            apart_hits += usize::from(t.is_finite());
        }
    }
    let hits = at_zero + first + later;
    let pct = |k: usize| 100.0 * k as f64 / n as f64;
    eprintln!(
        "{name}: {n} pairs, {hits} hits ({:.2} %): {at_zero} at t = 0, {first} in the first \
         window, {later} later; no contact: {} ({:.2} %)",
        pct(hits),
        n - hits,
        pct(n - hits),
    );
    eprintln!(
        "{name}: whole-path boxes (one widened by the contact distance) apart: {apart} pairs \
         ({:.2} %; {apart_hits} of them hit); windows up to the contact (or all): {windows} \
         ({:.2} a pair), {windows_no_contact} of them in pairs without contact",
        pct(apart),
        windows as f64 / n as f64,
    );
    if stages.path_pairs > 0 {
        let of = |k: u64, n: u64| 100.0 * k as f64 / n as f64;
        let left =
            stages.path_pairs - stages.bounds_apart - stages.chords_apart - stages.windows_apart;
        eprintln!(
            "{name}: stages (feature stage-counts): {} pairs; path bounds apart: {} ({:.1} %); \
             apart across a chord: {} ({:.1} %); every window apart at once (lanes): {} \
             ({:.1} %); the {left} left: {} windows ({:.2} a pair), {} ({:.1} %) proven apart by their \
             segments' boxes, {} ({:.1} %) by the window box, {} ({:.1} %) across the window's \
             chord, {} ({:.1} %) in closed form \
             (straight), {} ({:.1} %) searched ({} of them settled on their first open eighth, {} \
             as parting throughout); {} contacts",
            stages.path_pairs,
            stages.bounds_apart,
            of(stages.bounds_apart, stages.path_pairs),
            stages.chords_apart,
            of(stages.chords_apart, stages.path_pairs),
            stages.windows_apart,
            of(stages.windows_apart, stages.path_pairs),
            stages.windows,
            stages.windows as f64 / left.max(1) as f64,
            stages.windows_segments_apart,
            of(stages.windows_segments_apart, stages.windows),
            stages.windows_box_apart,
            of(stages.windows_box_apart, stages.windows),
            stages.windows_chord_apart,
            of(stages.windows_chord_apart, stages.windows),
            stages.windows_straight,
            of(stages.windows_straight, stages.windows),
            stages.windows_searched,
            of(stages.windows_searched, stages.windows),
            stages.windows_eighth,
            stages.windows_parting,
            stages.contacts,
        );
    }
}

/// The group's short-run settings: few samples, so that the whole bench stays under 2 min; on
/// the large sets, every sample of the same few iterations (a call takes tens of ms).
fn short<M: Measurement>(group: &mut BenchmarkGroup<'_, M>, flat: bool) {
    group.sample_size(10);
    if flat {
        group.sampling_mode(SamplingMode::Flat);
    }
    group.warm_up_time(Duration::from_millis(500));
    group.measurement_time(Duration::from_secs(2));
}

fn bench_paths<M: Measurement>(
    group: &mut BenchmarkGroup<'_, M>,
    name: &str,
    set: &PathSet,
    threads: Threads,
) {
    let mut out = vec![0.0; set.b.len().max(set.a.len())];
    group.bench_function(name, |bench| {
        bench.iter(|| path_collision_times(black_box(&set.pairs()), &mut out, threads))
    });
}

/// The same friction balls as [`table_pairs::Set`] and as paths (2 rows each: moving, at rest).
struct SeedSet {
    balls: table_pairs::Set,
    paths: PathSet,
}

fn seed_set(n: usize, seed: u64) -> SeedSet {
    let balls = set(Kind::RandomTable, n, seed);
    let paths = |pos: &[[f64; 2]], vel: &[[f64; 2]], mu: &[f64]| -> PathTable<2> {
        let paths: Vec<Path2> = (pos.iter().zip(vel).zip(mu))
            .map(|((&p, &v), &mu)| {
                let ball = Ball::new(p.into(), v.into(), mu).expect("valid ball");
                ball.path().expect("representable path")
            })
            .collect();
        PathTable::of(2, &paths)
    };
    let paths = PathSet {
        a: paths(&balls.pos_a, &balls.vel_a, &balls.mu_a),
        b: paths(&balls.pos_b, &balls.vel_b, &balls.mu_b),
    };
    SeedSet { balls, paths }
}

/// Every ball of a scene against the 15 others: per ball, its path (broadcast), its path
/// repeated 15 times, and the others' paths.
struct Queries {
    queries: Vec<(PathTable<2>, PathTable<2>, PathTable<2>)>,
}

impl Queries {
    fn of(balls: &[PoolBall]) -> Self {
        let paths: Vec<Path2> = balls.iter().map(PoolBall::path).collect();
        let others = paths.len() - 1;
        let queries = (0..paths.len())
            .map(|i| {
                let b = (paths.iter().enumerate())
                    .filter(|&(j, _)| j != i)
                    .map(|(_, p)| p);
                (
                    PathTable::of(3, [&paths[i]]),
                    PathTable::of(3, std::iter::repeat_n(&paths[i], others)),
                    PathTable::of(3, b),
                )
            })
            .collect();
        Self { queries }
    }

    fn pairs(&self) -> u64 {
        self.queries.iter().map(|q| q.2.len() as u64).sum()
    }

    /// Runs every query, A broadcast or repeated; the earliest contact of the scene.
    fn run(&self, broadcast: bool, out: &mut [f64], threads: Threads) -> f64 {
        let mut first = f64::INFINITY;
        for (one, repeated, b) in &self.queries {
            let a = if broadcast { one } else { repeated };
            let p = PathPairs {
                a: a.side(),
                b: b.side(),
                contact_distance: PerPair::All(CONTACT),
                t_max: PerPair::All(f64::INFINITY),
            };
            let out = &mut out[..b.len()];
            path_collision_times(black_box(&p), out, threads).expect("valid paths");
            first = out.iter().copied().fold(first, f64::min);
        }
        first
    }
}

/// The break: the rack at rest, the cue ball sliding into it at 6 m/s with backspin and a
/// little side slip, so that its first segment curves.
fn break_scene() -> Vec<PoolBall> {
    let mut balls: Vec<PoolBall> = rack().into_iter().map(PoolBall::at_rest).collect();
    let apex = balls[0].position;
    let aim = Vector2::new(apex[0] - CUE_SPOT[0], apex[1] - CUE_SPOT[1]).normalize() * 6.0;
    balls.push(PoolBall {
        position: CUE_SPOT,
        velocity: aim.into(),
        spin: [10.0, -40.0],
    });
    balls
}

/// Just after a break: the rack spread out by a fifth about its centre (a gap of 11 mm
/// between neighbours), every ball of it sliding away from the centre (within ±0.5 rad) at
/// 0.5–3 m/s with random spin, the cue ball at 1 m/s in a random direction.
fn spreading_scene(seed: u64) -> Vec<PoolBall> {
    let mut rng = Rng(seed);
    let spots = rack();
    let n = spots.len() as f64;
    let centre = spots
        .iter()
        .fold([0.0, 0.0], |c, p| [c[0] + p[0] / n, c[1] + p[1] / n]);
    let w = 3.0 / BALL_RADIUS;
    let mut balls: Vec<PoolBall> = spots
        .into_iter()
        .map(|p| {
            let out = (p[1] - centre[1]).atan2(p[0] - centre[0]) + rng.uniform(-0.5, 0.5);
            let speed = rng.uniform(0.5, 3.0);
            let spread = |axis: usize| centre[axis] + 1.2 * (p[axis] - centre[axis]);
            PoolBall {
                position: [spread(0), spread(1)],
                velocity: [speed * out.cos(), speed * out.sin()],
                spin: [rng.uniform(-w, w), rng.uniform(-w, w)],
            }
        })
        .collect();
    let angle = rng.uniform(0.0, std::f64::consts::TAU);
    balls.push(PoolBall {
        position: CUE_SPOT,
        velocity: [angle.cos(), angle.sin()],
        spin: [rng.uniform(-w, w), rng.uniform(-w, w)],
    });
    balls
}

/// The two large sets, drawn once for both timers, and the pool-table set's parts
/// ([`PathSet::split_by_boxes`]).
fn sets() -> &'static (PathSet, SeedSet, [PathSet; 2]) {
    static SETS: OnceLock<(PathSet, SeedSet, [PathSet; 2])> = OnceLock::new();
    SETS.get_or_init(|| {
        let pool = pool_table(PAIRS, 17);
        let parts = pool.split_by_boxes();
        (pool, seed_set(PAIRS, 11), parts)
    })
}

/// The groups on one thread or on all, for one kind of timer.
fn groups<M: Measurement>(c: &mut Criterion<M>, threads: Threads, label: &str) {
    let (pool, seed, pool_parts) = sets();
    let mut group = c.benchmark_group(format!("pool_table_{label}"));
    short(&mut group, true);
    group.throughput(Throughput::Elements(PAIRS as u64));
    bench_paths(&mut group, "paths_3_segments", pool, threads);
    group.finish();
    if label == "1_thread" {
        // What each part of the set costs: the pairs a whole-path box screen would settle, and
        // the rest (ns per pair of each part: the throughput is per pair of the part).
        let mut group = c.benchmark_group("pool_table_parts_1_thread");
        short(&mut group, true);
        for (name, part) in ["boxes_apart", "boxes_overlap"].iter().zip(pool_parts) {
            group.throughput(Throughput::Elements(part.a.len() as u64));
            bench_paths(&mut group, name, part, threads);
        }
        group.finish();
    }

    let mut group = c.benchmark_group(format!("seed_as_paths_{label}"));
    short(&mut group, true);
    group.throughput(Throughput::Elements(PAIRS as u64));
    let mut out = vec![0.0; PAIRS];
    group.bench_function("collision_times", |bench| {
        bench.iter(|| collision_times(black_box(&seed.balls.pairs()), &mut out, threads))
    });
    bench_paths(&mut group, "path_collision_times", &seed.paths, threads);
    group.finish();

    let mut group = c.benchmark_group(format!("ball_against_all_{label}"));
    short(&mut group, false);
    for (name, balls) in [("break", break_scene()), ("spreading", spreading_scene(5))] {
        let queries = Queries::of(&balls);
        let mut out = vec![0.0; balls.len()];
        if label == "1_thread" {
            let first = queries.run(true, &mut out, threads);
            eprintln!(
                "{name}: {} queries, the earliest contact at {first} s",
                balls.len()
            );
        }
        group.throughput(Throughput::Elements(queries.pairs()));
        for (how, broadcast) in [("broadcast", true), ("repeated", false)] {
            group.bench_function(format!("{name}_{how}"), |bench| {
                bench.iter(|| queries.run(broadcast, &mut out, threads))
            });
        }
    }
    group.finish();
}

fn one_thread(c: &mut Criterion<ThreadCpuTime>) {
    machine::print_machine();
    let (pool, seed, _) = sets();
    describe("pool_table", pool);
    describe("seed_as_paths", &seed.paths);
    groups(c, ONE, "1_thread");
}

fn all_threads(c: &mut Criterion) {
    groups(c, Threads::All, "all_threads");
}

criterion_group! {
    name = cpu;
    config = Criterion::default().with_measurement(ThreadCpuTime).without_plots();
    targets = one_thread
}
criterion_group! {
    name = wall;
    config = Criterion::default().without_plots();
    targets = all_threads
}
criterion_main!(cpu, wall);
