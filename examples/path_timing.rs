//! Times the batch search on paths, [`ballcollide::batch::path_collision_times`], on pairs
//! of 2-D paths read from a raw file (`benchmarks/compare.py` writes the file, runs this
//! example and times pooltool on the very same pairs in the same run).
//!
//! ```text
//! cargo run --release --example path_timing -- FILE [THREADS] [REPEATS] [OUT]
//! ```
//!
//! FILE is little-endian: `n` (the pairs) as a `u64`; then for side A and then side B: the
//! number of paths (1, broadcast, or `n`) and `K` (rows per path) as `u64`s, then `f64`s:
//! `start` (paths·K), `pos`, `vel`, `acc` (paths·K rows `x, y` each), in the row layout of
//! [`ballcollide::batch::PathRows`] (unused rows with `start = +∞`); last, `radius` (one
//! `f64` for all pairs). THREADS is a number (default 1) or `all`; REPEATS defaults to 15.
//! With OUT, the times of the last call are written there (`n` little-endian `f64`s, `+∞`
//! where there is no contact). The output is one line of `key=value` fields: the median and
//! minimum ns per pair over the repeats, the median CPU time of the calling thread per pair
//! (the whole work on one thread), and a checksum of the times (hit count and sum of
//! the finite times).

use std::process::ExitCode;

use ballcollide::batch::{PathPairs, PathRows, PerPair, path_collision_times};

#[path = "../tests/support/machine.rs"]
mod machine;
#[path = "../tests/support/thread_cpu_time.rs"]
mod thread_cpu_time;
#[path = "../tests/support/timing_example.rs"]
mod timing_example;
use timing_example::{Args, Reader, report, time_calls};

/// One side's rows, owned.
struct Side {
    start: Vec<f64>,
    pos: Vec<[f64; 2]>,
    vel: Vec<[f64; 2]>,
    acc: Vec<[f64; 2]>,
    segments: usize,
}

impl Side {
    fn read(r: &mut Reader<'_>) -> Result<Self, String> {
        let (paths, segments) = (r.count()?, r.count()?);
        let rows = paths
            .checked_mul(segments)
            .ok_or("paths × segments overflows")?;
        Ok(Self {
            start: r.f64s(rows)?,
            pos: r.rows(rows)?,
            vel: r.rows(rows)?,
            acc: r.rows(rows)?,
            segments,
        })
    }

    fn rows(&self) -> PathRows<'_, 2> {
        PathRows {
            start: &self.start,
            pos: &self.pos,
            vel: &self.vel,
            acc: &self.acc,
            segments: self.segments,
        }
    }
}

/// The pairs of one file.
struct Data {
    n: usize,
    a: Side,
    b: Side,
    radius: f64,
}

fn read(path: &str) -> Result<Data, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{path}: {e}"))?;
    let mut r = Reader::new(&bytes);
    let data = Data {
        n: r.count()?,
        a: Side::read(&mut r)?,
        b: Side::read(&mut r)?,
        radius: r.f64()?,
    };
    r.finish(path)?;
    Ok(data)
}

fn run() -> Result<String, String> {
    let args = Args::read("usage: path_timing FILE [THREADS] [REPEATS] [OUT]")?;
    let d = read(&args.path)?;
    let pairs = PathPairs {
        a: d.a.rows(),
        b: d.b.rows(),
        contact_distance: PerPair::All(d.radius),
        t_max: PerPair::All(f64::INFINITY),
    };
    let (out, line) = time_calls(d.n, args.repeats, false, |out| {
        path_collision_times(&pairs, out, args.threads)
    })?;
    if let Some(file) = args.rest.first() {
        let bytes: Vec<u8> = out.iter().flat_map(|t| t.to_le_bytes()).collect();
        std::fs::write(file, bytes).map_err(|e| format!("{file}: {e}"))?;
    }
    Ok(line)
}

fn main() -> ExitCode {
    machine::print_machine();
    report("path_timing", run())
}
