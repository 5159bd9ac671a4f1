//! Collision-time kernel benchmarks on the sets of issue 5: random table pairs, all-grazing
//! pairs, a ball at rest, and batch throughput (10³ … 10⁷ pairs) with one and two threads;
//! and, for scale, the floor under any batch kernel on this machine: reading every input of a
//! batch once and writing one number per pair.
//!
//! `cargo bench --bench collision`; criterion prints the median time per iteration, and the
//! throughput in pairs per second (elements/s). `-- kernel`, `-- batch` or `-- floor` selects
//! a group.
//! The one-thread kernel groups time the thread's CPU time (see [`ThreadCpuTime`]), the batch
//! groups wall time (several threads).

use std::hint::black_box;
use std::num::NonZeroUsize;
use std::time::Duration;

use ballcollide::batch::{Pairs, PerPair, Threads, collision_times};
use std::sync::OnceLock;
use std::time::Instant;

use criterion::measurement::{Measurement, ValueFormatter};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};

const RADIUS: f64 = 2.0 * 0.028575;

#[path = "../tests/support/rng.rs"]
mod rng;
use rng::Rng;

/// Structure of the pair sets, owned.
struct Set {
    pos_a: Vec<[f64; 2]>,
    vel_a: Vec<[f64; 2]>,
    mu_a: Vec<f64>,
    pos_b: Vec<[f64; 2]>,
    vel_b: Vec<[f64; 2]>,
    mu_b: Vec<f64>,
}

impl Set {
    fn pairs(&self) -> Pairs<'_> {
        Pairs {
            pos_a: &self.pos_a,
            vel_a: &self.vel_a,
            friction_a: PerPair::Each(&self.mu_a),
            pos_b: &self.pos_b,
            vel_b: &self.vel_b,
            friction_b: PerPair::Each(&self.mu_b),
            radius: PerPair::All(RADIUS),
            t_max: PerPair::All(f64::INFINITY),
        }
    }
}

#[derive(Clone, Copy)]
enum Kind {
    /// Both balls anywhere on a 2.54 × 1.27 m table, speeds 0–3 m/s, friction 0.05–2 m/s².
    RandomTable,
    /// B at rest, A aimed so that the closest approach is within 1e-2 … 1e-12 of the radius.
    Grazing,
    /// Cue ball (A) to an object ball at rest (B).
    AtRest,
    /// Both balls moving the same way with the same friction, A catching B up on a parallel
    /// track `radius·(1 ± 1e-2 … 1e-12)` aside, before B stops: grazing contacts that the
    /// general search (not the one-ball-at-rest closed form) has to settle.
    GrazingMoving,
}

fn set(kind: Kind, n: usize, seed: u64) -> Set {
    let mut rng = Rng(seed);
    let mut s = Set {
        pos_a: Vec::with_capacity(n),
        vel_a: Vec::with_capacity(n),
        mu_a: Vec::with_capacity(n),
        pos_b: Vec::with_capacity(n),
        vel_b: Vec::with_capacity(n),
        mu_b: Vec::with_capacity(n),
    };
    for _ in 0..n {
        let pa = [rng.uniform(0.0, 2.54), rng.uniform(0.0, 1.27)];
        let pb = [rng.uniform(0.0, 2.54), rng.uniform(0.0, 1.27)];
        let speed = rng.uniform(0.0, 3.0);
        let mu = rng.uniform(0.05, 2.0);
        let (pb, va, vb, mu, mu_b) = match kind {
            Kind::RandomTable => {
                let (ta, tb) = (rng.uniform(0.0, 6.3), rng.uniform(0.0, 6.3));
                let sb = rng.uniform(0.0, 3.0);
                (
                    pb,
                    [speed * ta.cos(), speed * ta.sin()],
                    [sb * tb.cos(), sb * tb.sin()],
                    mu,
                    rng.uniform(0.05, 2.0),
                )
            }
            Kind::GrazingMoving => {
                let angle = rng.uniform(0.0, 6.3);
                let (ux, uy) = (angle.cos(), angle.sin());
                let delta = 10f64.powf(rng.uniform(-12.0, -2.0));
                let side = if rng.uniform(0.0, 1.0) < 0.5 {
                    1.0
                } else {
                    -1.0
                };
                let aside = RADIUS * (1.0 + side * delta);
                let ahead = rng.uniform(2.0 * RADIUS, 0.5);
                let pb = [
                    pa[0] + ahead * ux - aside * uy,
                    pa[1] + ahead * uy + aside * ux,
                ];
                let (speed_b, closing) = (rng.uniform(0.5, 2.0), rng.uniform(0.5, 1.5));
                // The same deceleration; A reaches B (after about ahead/closing) before B stops.
                let mu = rng.uniform(0.05, 2.0f64.min(0.9 * speed_b * closing / ahead));
                let speed_a = speed_b + closing;
                (
                    pb,
                    [speed_a * ux, speed_a * uy],
                    [speed_b * ux, speed_b * uy],
                    mu,
                    mu,
                )
            }
            Kind::Grazing | Kind::AtRest => {
                let (dx, dy) = (pb[0] - pa[0], pb[1] - pa[1]);
                let dist = dx.hypot(dy).max(2.0 * RADIUS);
                let offset = match kind {
                    Kind::Grazing => {
                        let delta = 10f64.powf(rng.uniform(-12.0, -2.0));
                        RADIUS
                            * (1.0
                                + if rng.uniform(0.0, 1.0) < 0.5 {
                                    delta
                                } else {
                                    -delta
                                })
                    }
                    _ => rng.uniform(-1.5, 1.5) * RADIUS,
                };
                let angle = dy.atan2(dx) + (offset / dist).clamp(-1.0, 1.0).asin();
                // Fast enough to reach the target before stopping.
                let speed = (2.0 * mu * dist).sqrt() * rng.uniform(1.05, 2.0);
                (
                    pb,
                    [speed * angle.cos(), speed * angle.sin()],
                    [0.0, 0.0],
                    mu,
                    0.0,
                )
            }
        };
        s.pos_a.push(pa);
        s.vel_a.push(va);
        s.mu_a.push(mu);
        s.pos_b.push(pb);
        s.vel_b.push(vb);
        s.mu_b.push(mu_b);
    }
    s
}

/// CPU time of the calling thread (`CLOCK_THREAD_CPUTIME_ID`, nanoseconds): unlike wall time
/// it does not count the time other processes take on a shared machine, so that single-thread
/// kernel timings are comparable between runs. Off Linux it falls back to wall time.
struct ThreadCpuTime;

#[cfg(target_os = "linux")]
fn thread_cpu_ns() -> u64 {
    #[repr(C)]
    struct Timespec {
        sec: i64,
        nsec: i64,
    }
    unsafe extern "C" {
        fn clock_gettime(clock: i32, time: *mut Timespec) -> i32;
    }
    const CLOCK_THREAD_CPUTIME_ID: i32 = 3;
    let mut t = Timespec { sec: 0, nsec: 0 };
    // SAFETY: `t` is a valid, writable timespec; the clock id is Linux's thread CPU clock.
    let ok = unsafe { clock_gettime(CLOCK_THREAD_CPUTIME_ID, &mut t) } == 0;
    if ok {
        t.sec as u64 * 1_000_000_000 + t.nsec as u64
    } else {
        wall_ns()
    }
}

#[cfg(not(target_os = "linux"))]
fn thread_cpu_ns() -> u64 {
    wall_ns()
}

/// Wall nanoseconds since the first call.
fn wall_ns() -> u64 {
    static START: OnceLock<Instant> = OnceLock::new();
    START.get_or_init(Instant::now).elapsed().as_nanos() as u64
}

impl Measurement for ThreadCpuTime {
    type Intermediate = u64;
    type Value = u64;
    fn start(&self) -> u64 {
        thread_cpu_ns()
    }
    fn end(&self, start: u64) -> u64 {
        thread_cpu_ns().saturating_sub(start)
    }
    fn add(&self, a: &u64, b: &u64) -> u64 {
        a + b
    }
    fn zero(&self) -> u64 {
        0
    }
    fn to_f64(&self, value: &u64) -> f64 {
        *value as f64
    }
    fn formatter(&self) -> &dyn ValueFormatter {
        &CpuFormatter
    }
}

/// Prints CPU nanoseconds as times (ns … s) and element throughputs in Melem/s.
struct CpuFormatter;

impl ValueFormatter for CpuFormatter {
    fn scale_values(&self, typical: f64, values: &mut [f64]) -> &'static str {
        let (factor, unit) = match typical {
            t if t < 1e3 => (1.0, "ns"),
            t if t < 1e6 => (1e-3, "µs (cpu)"),
            t if t < 1e9 => (1e-6, "ms (cpu)"),
            _ => (1e-9, "s (cpu)"),
        };
        values.iter_mut().for_each(|v| *v *= factor);
        unit
    }
    fn scale_throughputs(
        &self,
        _typical: f64,
        throughput: &Throughput,
        values: &mut [f64],
    ) -> &'static str {
        let per = match *throughput {
            Throughput::Elements(n) | Throughput::ElementsAndBytes { elements: n, .. } => n,
            Throughput::Bytes(n) | Throughput::BytesDecimal(n) | Throughput::Bits(n) => n,
        } as f64;
        values.iter_mut().for_each(|v| *v = per * 1e3 / *v);
        "Melem/s (cpu)"
    }
    fn scale_for_machines(&self, _values: &mut [f64]) -> &'static str {
        "ns"
    }
}

fn kernel(c: &mut Criterion<ThreadCpuTime>) {
    let one = Threads::AtMost(NonZeroUsize::MIN);
    let mut group = c.benchmark_group("kernel_1_thread");
    let n = 4096;
    group.throughput(Throughput::Elements(n as u64));
    for (name, kind) in [
        ("random_table", Kind::RandomTable),
        ("grazing", Kind::Grazing),
        ("at_rest", Kind::AtRest),
        ("grazing_both_moving", Kind::GrazingMoving),
    ] {
        let s = set(kind, n, 7);
        let mut out = vec![0.0; n];
        group.bench_function(name, |bench| {
            bench.iter(|| collision_times(black_box(&s.pairs()), &mut out, one))
        });
    }
    group.finish();
}

fn throughput(c: &mut Criterion) {
    let mut group = c.benchmark_group("batch_random_table");
    group.sample_size(10);
    let two = NonZeroUsize::MIN.saturating_add(1);
    for n in [1_000, 100_000, 1_000_000, 10_000_000] {
        let s = set(Kind::RandomTable, n, 11);
        let mut out = vec![0.0; n];
        group.throughput(Throughput::Elements(n as u64));
        if n >= 10_000_000 {
            // About a second per iteration: ten samples, no more.
            group.warm_up_time(Duration::from_secs(1));
            group.measurement_time(Duration::from_secs(10));
        }
        for (label, threads) in [
            ("1_thread", Threads::AtMost(NonZeroUsize::MIN)),
            ("2_threads", Threads::AtMost(two)),
        ] {
            group.bench_with_input(BenchmarkId::new(label, n), &n, |bench, _| {
                bench.iter(|| collision_times(black_box(&s.pairs()), &mut out, threads))
            });
        }
    }
    group.finish();
}

/// Every input of pair `i` summed: what a kernel that reads each input once and does no
/// arithmetic would cost. The sum keeps the reads from being optimised away.
fn read_every_input(s: &Set, out: &mut [f64]) {
    let rows =
        (s.pos_a.iter().zip(&s.vel_a).zip(&s.mu_a)).zip(s.pos_b.iter().zip(&s.vel_b).zip(&s.mu_b));
    for (x, (((pa, va), ma), ((pb, vb), mb))) in out.iter_mut().zip(rows) {
        *x = (pa[0] + pa[1]) + (va[0] + va[1]) + ma + (pb[0] + pb[1]) + (vb[0] + vb[1]) + mb;
    }
}

/// The floor: one thread reading a set of 10⁶ random table pairs from memory (88 bytes a
/// pair with the output; the batch group's 10⁶ pairs pay it too). In cache the floor is far
/// lower, and this loop, compiled for the baseline CPU, would not show it.
fn floor(c: &mut Criterion<ThreadCpuTime>) {
    let mut group = c.benchmark_group("floor_read_inputs");
    let n = 1_000_000;
    let s = set(Kind::RandomTable, n, 11);
    let mut out = vec![0.0; n];
    group.throughput(Throughput::Elements(n as u64));
    group.bench_function(BenchmarkId::from_parameter(n), |bench| {
        bench.iter(|| read_every_input(black_box(&s), &mut out))
    });
    group.finish();
}

criterion_group! {
    name = kernels;
    config = Criterion::default().with_measurement(ThreadCpuTime);
    targets = kernel, floor
}
criterion_group!(batches, throughput);
criterion_main!(kernels, batches);
