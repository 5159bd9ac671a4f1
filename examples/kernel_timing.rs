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
//! binding does) instead of reusing one. The output is one line of `key=value` fields: the median and minimum ns per pair
//! over the repeats, and a checksum of the times (hit count and sum of the finite times).

use std::num::NonZeroUsize;
use std::process::ExitCode;
use std::time::Instant;

use ballcollide::batch::{Pairs, PerPair, Threads, collision_times};

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

/// Reads little-endian words from a byte buffer, front to back.
struct Reader<'a> {
    bytes: &'a [u8],
}

impl Reader<'_> {
    fn word(&mut self) -> Result<[u8; 8], String> {
        let (head, rest) = self
            .bytes
            .split_first_chunk::<8>()
            .ok_or("file too short")?;
        self.bytes = rest;
        Ok(*head)
    }

    fn f64s(&mut self, n: usize) -> Result<Vec<f64>, String> {
        (0..n)
            .map(|_| self.word().map(f64::from_le_bytes))
            .collect()
    }

    fn rows(&mut self, n: usize) -> Result<Vec<[f64; 2]>, String> {
        let flat = self.f64s(2 * n)?;
        Ok(flat.chunks_exact(2).map(|r| [r[0], r[1]]).collect())
    }
}

fn read(path: &str) -> Result<Data, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{path}: {e}"))?;
    let mut r = Reader { bytes: &bytes };
    let n = usize::try_from(u64::from_le_bytes(r.word()?)).map_err(|e| e.to_string())?;
    let data = Data {
        pos_a: r.rows(n)?,
        vel_a: r.rows(n)?,
        friction_a: r.f64s(n)?,
        pos_b: r.rows(n)?,
        vel_b: r.rows(n)?,
        friction_b: r.f64s(n)?,
        radius: f64::from_le_bytes(r.word()?),
    };
    if r.bytes.is_empty() {
        Ok(data)
    } else {
        Err(format!("{path}: {} bytes left over", r.bytes.len()))
    }
}

fn threads(arg: Option<&str>) -> Result<Threads, String> {
    match arg {
        None => Ok(Threads::AtMost(NonZeroUsize::MIN)),
        Some("all") => Ok(Threads::All),
        Some(s) => s
            .parse::<NonZeroUsize>()
            .map(Threads::AtMost)
            .map_err(|e| format!("THREADS: {e}")),
    }
}

fn median(mut xs: Vec<f64>) -> f64 {
    xs.sort_by(f64::total_cmp);
    xs[xs.len() / 2]
}

fn run() -> Result<String, String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let path = args
        .first()
        .ok_or("usage: kernel_timing FILE [THREADS] [REPEATS] [fresh]")?;
    let threads = threads(args.get(1).map(String::as_str))?;
    let repeats: usize = match args.get(2) {
        Some(s) => s.parse().map_err(|e| format!("REPEATS: {e}"))?,
        None => 15,
    };
    let fresh = match args.get(3).map(String::as_str) {
        None => false,
        Some("fresh") => true,
        Some(other) => return Err(format!("expected `fresh`, got {other:?}")),
    };
    let d = read(path)?;
    let pairs = Pairs {
        pos_a: &d.pos_a,
        vel_a: &d.vel_a,
        friction_a: PerPair::Each(&d.friction_a),
        pos_b: &d.pos_b,
        vel_b: &d.vel_b,
        friction_b: PerPair::Each(&d.friction_b),
        radius: PerPair::All(d.radius),
        t_max: PerPair::All(f64::INFINITY),
    };
    let n = d.pos_a.len();
    let mut out = vec![0.0; n];
    collision_times(&pairs, &mut out, threads).map_err(|e| e.to_string())?; // warm-up
    let mut ns = Vec::with_capacity(repeats);
    for _ in 0..repeats.max(1) {
        let start = Instant::now();
        if fresh {
            out = vec![0.0; n];
        }
        collision_times(&pairs, &mut out, threads).map_err(|e| e.to_string())?;
        ns.push(start.elapsed().as_secs_f64() * 1e9 / n.max(1) as f64);
    }
    let hits = out.iter().filter(|t| t.is_finite()).count();
    let sum: f64 = out.iter().filter(|t| t.is_finite()).sum();
    let min = ns.iter().copied().fold(f64::INFINITY, f64::min);
    Ok(format!(
        "n={n} repeats={} fresh={fresh} median_ns_per_pair={:.4} min_ns_per_pair={min:.4} hits={hits} sum={sum:.17e}",
        ns.len(),
        median(ns.clone()),
    ))
}

fn main() -> ExitCode {
    match run() {
        Ok(line) => {
            println!("{line}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("kernel_timing: {e}");
            ExitCode::FAILURE
        }
    }
}
