//! What the timing examples (`examples/kernel_timing.rs`, `examples/path_timing.rs`) share:
//! reading the raw little-endian files that `benchmarks/compare.py` writes ([`Reader`]), the
//! arguments FILE [THREADS] [REPEATS] ([`Args`], [`threads`]), timing repeated batch calls
//! ([`time_calls`]), and printing the result or the error ([`report`]).
//!
//! Included by path next to `thread_cpu_time.rs`, which it uses as `super::thread_cpu_time`:
//! `#[path = "../tests/support/timing_example.rs"] mod timing_example;`.

use std::num::NonZeroUsize;
use std::process::ExitCode;
use std::time::Instant;

use ballcollide::InputError;
use ballcollide::batch::Threads;

use super::thread_cpu_time::thread_cpu_ns;

/// Reads little-endian words from a byte buffer, front to back.
pub struct Reader<'a> {
    bytes: &'a [u8],
}

impl<'a> Reader<'a> {
    /// A reader of `bytes` from their start.
    pub fn new(bytes: &'a [u8]) -> Self {
        Self { bytes }
    }

    fn word(&mut self) -> Result<[u8; 8], String> {
        let (head, rest) = self
            .bytes
            .split_first_chunk::<8>()
            .ok_or("file too short")?;
        self.bytes = rest;
        Ok(*head)
    }

    /// The next word as a count (`u64`).
    pub fn count(&mut self) -> Result<usize, String> {
        usize::try_from(u64::from_le_bytes(self.word()?)).map_err(|e| e.to_string())
    }

    /// The next word as an `f64`.
    pub fn f64(&mut self) -> Result<f64, String> {
        self.word().map(f64::from_le_bytes)
    }

    /// The next `n` words as `f64`s.
    pub fn f64s(&mut self, n: usize) -> Result<Vec<f64>, String> {
        (0..n).map(|_| self.f64()).collect()
    }

    /// The next `n` rows of `D` `f64`s.
    pub fn rows<const D: usize>(&mut self, n: usize) -> Result<Vec<[f64; D]>, String> {
        let flat = self.f64s(D * n)?;
        Ok(flat
            .chunks_exact(D)
            .map(|r| std::array::from_fn(|k| r[k]))
            .collect())
    }

    /// Checks that the whole file was read (`path` names it in the error).
    pub fn finish(self, path: &str) -> Result<(), String> {
        match self.bytes.len() {
            0 => Ok(()),
            left => Err(format!("{path}: {left} bytes left over")),
        }
    }
}

/// The arguments every timing example starts with: FILE, [THREADS], [REPEATS] (default 15),
/// and whatever follows them.
pub struct Args {
    pub path: String,
    pub threads: Threads,
    pub repeats: usize,
    pub rest: Vec<String>,
}

impl Args {
    /// The command line's arguments; `usage` is the error when FILE is missing.
    pub fn read(usage: &str) -> Result<Self, String> {
        let mut args = std::env::args().skip(1);
        let path = args.next().ok_or_else(|| usage.to_string())?;
        let threads = threads(args.next().as_deref())?;
        let repeats = match args.next() {
            Some(s) => s.parse().map_err(|e| format!("REPEATS: {e}"))?,
            None => 15,
        };
        Ok(Self {
            path,
            threads,
            repeats,
            rest: args.collect(),
        })
    }
}

/// A timing example's exit: its line printed, or `name: error` on standard error.
pub fn report(name: &str, result: Result<String, String>) -> ExitCode {
    match result {
        Ok(line) => {
            println!("{line}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{name}: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The THREADS argument: a number (default 1) or `all`.
pub fn threads(arg: Option<&str>) -> Result<Threads, String> {
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

/// Times `call` on an output of `n` pairs, once to warm up and then `repeats` times (at
/// least once); with `fresh`, every call writes into a newly allocated buffer instead of
/// reusing one. Returns the last output and one line of `key=value` fields: the median and
/// minimum ns per pair over the repeats (wall time), the median of the calling thread's CPU
/// time per pair (all the work on one thread; on a shared machine, the work without the
/// waits), and a checksum of the times (hit count and sum of the finite times, in order).
pub fn time_calls(
    n: usize,
    repeats: usize,
    fresh: bool,
    mut call: impl FnMut(&mut [f64]) -> Result<(), InputError>,
) -> Result<(Vec<f64>, String), String> {
    let mut out = vec![0.0; n];
    call(&mut out).map_err(|e| e.to_string())?; // warm-up
    let (mut ns, mut cpu) = (Vec::with_capacity(repeats), Vec::with_capacity(repeats));
    for _ in 0..repeats.max(1) {
        let (start, start_cpu) = (Instant::now(), thread_cpu_ns());
        if fresh {
            out = vec![0.0; n];
        }
        call(&mut out).map_err(|e| e.to_string())?;
        ns.push(start.elapsed().as_secs_f64() * 1e9 / n.max(1) as f64);
        cpu.push(thread_cpu_ns().saturating_sub(start_cpu) as f64 / n.max(1) as f64);
    }
    let hits = out.iter().filter(|t| t.is_finite()).count();
    let sum: f64 = out.iter().filter(|t| t.is_finite()).sum();
    let min = ns.iter().copied().fold(f64::INFINITY, f64::min);
    let line = format!(
        "n={n} repeats={} fresh={fresh} median_ns_per_pair={:.4} min_ns_per_pair={min:.4} median_thread_cpu_ns_per_pair={:.4} hits={hits} sum={sum:.17e}",
        ns.len(),
        median(ns.clone()),
        median(cpu),
    );
    Ok((out, line))
}
