//! Times the batch kernel [`ballcollide::batch::collision_times`] on pairs read from a raw
//! file, to measure what the Python binding adds on top of it (`benchmarks/compare.py`
//! writes the file and runs this example on the very same data).
//!
//! ```text
//! cargo run --release --example kernel_timing -- FILE [THREADS] [REPEATS] [fresh]
//! ```
//!
//! FILE is little-endian: `n` as a `u64`, then `f64`s: `pos_a` (`2n`, rows `x, y`), `vel_a`
//! (`2n`), `friction_a` (`n`), `pos_b` (`2n`), `vel_b` (`2n`), `friction_b` (`n`), `radius`
//! (one value for all pairs). THREADS is a number (default 1) or `all`; REPEATS defaults
//! to 15. With `fresh`, every call writes into a newly allocated output buffer (as the Python
//! binding does) instead of reusing one. The output is one line of `key=value` fields: the
//! median and minimum ns per pair over the repeats, the median CPU time of the calling thread
//! per pair (the whole work on one thread), and a checksum of the times (hit count and sum of
//! the finite times).

use std::process::ExitCode;

use ballcollide::batch::{Pairs, PerPair, collision_times};

#[path = "../tests/support/machine.rs"]
mod machine;
#[path = "../tests/support/thread_cpu_time.rs"]
mod thread_cpu_time;
#[path = "../tests/support/timing_example.rs"]
mod timing_example;
use timing_example::{Args, Reader, report, time_calls};

/// The pairs of one file, in the batch layout.
struct Data {
    pos_a: Vec<[f64; 2]>,
    vel_a: Vec<[f64; 2]>,
    friction_a: Vec<f64>,
    pos_b: Vec<[f64; 2]>,
    vel_b: Vec<[f64; 2]>,
    friction_b: Vec<f64>,
    radius: f64,
}

fn read(path: &str) -> Result<Data, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{path}: {e}"))?;
    let mut r = Reader::new(&bytes);
    let n = r.count()?;
    let data = Data {
        pos_a: r.rows(n)?,
        vel_a: r.rows(n)?,
        friction_a: r.f64s(n)?,
        pos_b: r.rows(n)?,
        vel_b: r.rows(n)?,
        friction_b: r.f64s(n)?,
        radius: r.f64()?,
    };
    r.finish(path)?;
    Ok(data)
}

fn run() -> Result<String, String> {
    let args = Args::read("usage: kernel_timing FILE [THREADS] [REPEATS] [fresh]")?;
    let fresh = match args.rest.first().map(String::as_str) {
        None => false,
        Some("fresh") => true,
        Some(other) => return Err(format!("expected `fresh`, got {other:?}")),
    };
    let d = read(&args.path)?;
    let pairs = Pairs {
        pos_a: &d.pos_a,
        vel_a: &d.vel_a,
        friction_a: PerPair::Each(&d.friction_a),
        pos_b: &d.pos_b,
        vel_b: &d.vel_b,
        friction_b: PerPair::Each(&d.friction_b),
        contact_distance: PerPair::All(d.radius),
        t_max: PerPair::All(f64::INFINITY),
    };
    let (_, line) = time_calls(d.pos_a.len(), args.repeats, fresh, |out| {
        collision_times(&pairs, out, args.threads)
    })?;
    Ok(line)
}

fn main() -> ExitCode {
    machine::print_machine();
    report("kernel_timing", run())
}
