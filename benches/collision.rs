//! Collision-time kernel benchmarks on the sets of issue 5: random table pairs, all-grazing
//! pairs, a ball at rest, and batch throughput (10³ … 10⁷ pairs) with one and two threads;
//! and, for scale, the floor under any batch kernel on this machine: reading every input of a
//! batch once and writing one number per pair.
//!
//! `cargo bench --bench collision` in `benches/`; criterion prints the median time per iteration, and the
//! throughput in pairs per second (elements/s). `-- kernel`, `-- batch` or `-- floor` selects
//! a group.
//! The one-thread kernel groups time the thread's CPU time (see [`ThreadCpuTime`]), the batch
//! groups wall time (several threads).

use std::hint::black_box;
use std::num::NonZeroUsize;
use std::time::Duration;

use ballcollide::batch::{Threads, collision_times};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};

mod cpu_time;
#[path = "../tests/support/machine.rs"]
mod machine;
#[path = "../tests/support/rng.rs"]
mod rng;
#[path = "../tests/support/table_pairs.rs"]
mod table_pairs;
#[path = "../tests/support/thread_cpu_time.rs"]
mod thread_cpu_time;
use cpu_time::ThreadCpuTime;
use table_pairs::{Kind, Set, set};

fn kernel(c: &mut Criterion<ThreadCpuTime>) {
    machine::print_machine();
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
