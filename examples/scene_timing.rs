//! Times the scene queries ([`ballcollide::scene`]) from Rust on a scene read from a raw file,
//! so that `benchmarks/call_overhead.py` can set the Python calls' cost beside the Rust time
//! on the very same balls.
//!
//! ```text
//! cargo run --release --example scene_timing -- FILE [REPEATS]
//! ```
//!
//! FILE is little-endian: `n` as a `u64`, then `f64`s: `pos` (`2n`, rows `x, y`), `vel`
//! (`2n`), `friction` (`n`), `radius` (`n`). REPEATS (default 10,000) calls of each query are
//! timed one by one, with the default options (all cores; scenes this small run on the
//! calling thread). The output is one line of `key=value` fields: the median and minimum ns
//! per call of `earliest_collision`, `first_contacts` and `pairwise_collision_times`
//! (including the building of the balls from the rows, as a binding does).

use std::process::ExitCode;
use std::time::Instant;

use ballcollide::batch::PerPair;
use ballcollide::scene::{
    SceneOptions, balls, earliest_collision, first_contacts, pairwise_collision_times,
};

/// The next little-endian 8-byte word.
fn word(bytes: &mut &[u8]) -> Result<[u8; 8], String> {
    let (head, rest) = bytes.split_first_chunk::<8>().ok_or("file too short")?;
    *bytes = rest;
    Ok(*head)
}

/// The next `n` little-endian `f64`s.
fn f64s(bytes: &mut &[u8], n: usize) -> Result<Vec<f64>, String> {
    (0..n)
        .map(|_| word(bytes).map(f64::from_le_bytes))
        .collect()
}

/// The next `2n` `f64`s as `(x, y)` rows.
fn rows(bytes: &mut &[u8], n: usize) -> Result<Vec<[f64; 2]>, String> {
    Ok(f64s(bytes, 2 * n)?
        .chunks_exact(2)
        .map(|r| [r[0], r[1]])
        .collect())
}

/// The median and the minimum of `repeats` timings of `call`, in ns.
fn time(
    repeats: usize,
    mut call: impl FnMut() -> Result<(), String>,
) -> Result<(f64, f64), String> {
    call()?; // warm-up
    let mut ns = Vec::with_capacity(repeats);
    for _ in 0..repeats.max(1) {
        let start = Instant::now();
        call()?;
        ns.push(start.elapsed().as_secs_f64() * 1e9);
    }
    ns.sort_by(f64::total_cmp);
    Ok((ns[ns.len() / 2], ns[0]))
}

fn run() -> Result<String, String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let path = args.first().ok_or("usage: scene_timing FILE [REPEATS]")?;
    let repeats: usize = match args.get(1) {
        Some(s) => s.parse().map_err(|e| format!("REPEATS: {e}"))?,
        None => 10_000,
    };
    let bytes = std::fs::read(path).map_err(|e| format!("{path}: {e}"))?;
    let mut rest = bytes.as_slice();
    let n = u64::from_le_bytes(word(&mut rest)?);
    let n = usize::try_from(n).map_err(|e| e.to_string())?;
    let pos = rows(&mut rest, n)?;
    let vel = rows(&mut rest, n)?;
    let friction = f64s(&mut rest, n)?;
    let radius = f64s(&mut rest, n)?;
    if !rest.is_empty() {
        return Err(format!("{path}: {} bytes left over", rest.len()));
    }
    let options = SceneOptions::default();
    let build = || balls(&pos, &vel, PerPair::Each(&friction)).map_err(|e| e.to_string());
    let mut fields = vec![format!("n={n} repeats={repeats}")];
    let mut hits = 0;
    let (med, min) = time(repeats, || {
        let found = earliest_collision(&build()?, &radius, &options).map_err(|e| e.to_string())?;
        hits = usize::from(found.is_some());
        Ok(())
    })?;
    fields.push(format!(
        "earliest_collision_median_ns={med:.1} earliest_collision_min_ns={min:.1} found={hits}"
    ));
    let (med, min) = time(repeats, || {
        first_contacts(&build()?, &radius, &options)
            .map(|_| ())
            .map_err(|e| e.to_string())
    })?;
    fields.push(format!(
        "first_contacts_median_ns={med:.1} first_contacts_min_ns={min:.1}"
    ));
    let (med, min) = time(repeats, || {
        pairwise_collision_times(&build()?, &radius, &options)
            .map(|_| ())
            .map_err(|e| e.to_string())
    })?;
    fields.push(format!(
        "pairwise_collision_times_median_ns={med:.1} pairwise_collision_times_min_ns={min:.1}"
    ));
    Ok(fields.join(" "))
}

fn main() -> ExitCode {
    match run() {
        Ok(line) => {
            println!("{line}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("scene_timing: {e}");
            ExitCode::FAILURE
        }
    }
}
