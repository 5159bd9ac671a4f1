//! Times the event calendar where balls never meet, or seldom do, and nothing bounds their
//! boxes (issue 38): with no horizon (`t_max = ∞`, `t_end = ∞`) against a finite one, in one
//! run, one thread.
//!
//! ```text
//! cargo run --release --example open_space_timing -- [REPEATS [CASE]]
//! ```
//!
//! Prints one line of `key=value` fields per case (only CASE's, if given), each time the
//! median of REPEATS runs (default 5):
//! - `parallel_open`: N = 400 frictionless balls in open space (no walls) on a row, 3 apart
//!   (radius ½), all moving across the row at 1: they never meet. The calendar's build and
//!   its first `next_collision()` (which is `None`), `t_max = ∞` against `1e3`.
//! - `gas_open`: a dilute gas without walls: N = 400 frictionless balls on a grid in the unit
//!   square, radius `0.1/√N`, normal(0, 1) velocities; events resolved elastically (equal
//!   masses) until none is left: µs per event, the build left out.
//! - `corner_open`: N = 1,000 balls in the unit square (radius 1e-7) moving side by side at
//!   (1, 1 + U(0, 1e-3)) for ever, and one at rest at (10, 10) that widens the grid: each
//!   moving ball's box runs to the far corner of the grid. The calendar's build and its first
//!   `next_collision()`, `t_max = ∞`.
//! - `parallel_box`: `simulate` in the unit box, N = 1, 4 or 200 balls on a grid, radius
//!   `¼/√N`, all at velocity (0.3, 0.7), 2,000 events: µs per event (the build included),
//!   `t_end = ∞` against `100` (the scene of `benchmarks/calendar_scaling.py`).

use std::process::ExitCode;
use std::time::Instant;

use ballcollide::path::{Path2, Segment2};
use ballcollide::schedule::{
    CollisionSchedule, ScheduleOptions, SimulationOptions, Walls, simulate,
};
use ballcollide::{Ball, simd};
use nalgebra::Vector2;

#[path = "../tests/support/rng.rs"]
mod rng;
use rng::Rng;

/// The median of `repeats` runs of `f` (each returning seconds, or what it measured).
fn median(repeats: usize, mut f: impl FnMut() -> Result<f64, String>) -> Result<f64, String> {
    let times = (0..repeats.max(1))
        .map(|_| f())
        .collect::<Result<Vec<_>, _>>()?;
    Ok(median_of(times))
}

/// The median of some values (at least one).
fn median_of(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// A path of one segment without acceleration from time `t`.
fn line(t: f64, p: Vector2<f64>, v: Vector2<f64>) -> Result<Path2, String> {
    Path2::new(vec![Segment2::new(t, p, v, Vector2::zeros())]).map_err(|e| e.to_string())
}

/// `parallel_open`: (build seconds, first `next_collision` seconds).
fn parallel_open(n: usize, t_max: f64) -> Result<(f64, f64), String> {
    let paths = (0..n)
        .map(|k| {
            line(
                0.0,
                Vector2::new(3.0 * k as f64, 0.0),
                Vector2::new(0.0, 1.0),
            )
        })
        .collect::<Result<Vec<_>, _>>()?;
    let options = ScheduleOptions {
        t_max,
        ..Default::default()
    };
    let begin = Instant::now();
    let mut s = CollisionSchedule::new(paths, &vec![0.5; n], options).map_err(|e| e.to_string())?;
    let build = begin.elapsed().as_secs_f64();
    let begin = Instant::now();
    let first = s.next_collision();
    let elapsed = begin.elapsed().as_secs_f64();
    if first.is_some() {
        return Err(format!("parallel balls met: {first:?}"));
    }
    Ok((build, elapsed))
}

/// `gas_open`: (seconds per event after the build, events).
fn gas_open(n: usize, t_max: f64) -> Result<(f64, usize), String> {
    let side = (n as f64).sqrt().round().max(1.0) as usize;
    let mut rng = Rng(11);
    let spacing = 1.0 / side as f64;
    let paths = (0..side * side)
        .map(|k| {
            let p = Vector2::new((k % side) as f64 + 0.5, (k / side) as f64 + 0.5) * spacing;
            line(0.0, p, Vector2::new(rng.normal(), rng.normal()))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let radius = 0.1 / side as f64;
    let options = ScheduleOptions {
        t_max,
        ..Default::default()
    };
    let radii = vec![radius; paths.len()];
    let mut s = CollisionSchedule::new(paths, &radii, options).map_err(|e| e.to_string())?;
    let begin = Instant::now();
    let mut events = 0;
    while let Some(c) = s.next_collision() {
        let t = c.time;
        let (pi, pj) = (s.path(c.i).position_at(t), s.path(c.j).position_at(t));
        let (vi, vj) = (s.path(c.i).velocity_at(t), s.path(c.j).velocity_at(t));
        // Equal masses: the normal components swap.
        let normal = (pi - pj).normalize();
        let dv = normal * (vi - vj).dot(&normal);
        let paths = vec![line(t, pi, vi - dv)?, line(t, pj, vj + dv)?];
        s.update(&[c.i, c.j], paths).map_err(|e| e.to_string())?;
        events += 1;
        if events > 100 * n {
            return Err("the gas does not settle".into());
        }
    }
    Ok((begin.elapsed().as_secs_f64() / events.max(1) as f64, events))
}

/// `corner_open`: (build seconds, first `next_collision` seconds).
fn corner_open(n: usize) -> Result<(f64, f64), String> {
    let mut rng = Rng(3);
    let mut paths = (0..n)
        .map(|_| {
            let p = Vector2::new(rng.uniform(0.0, 1.0), rng.uniform(0.0, 1.0));
            line(0.0, p, Vector2::new(1.0, 1.0 + rng.uniform(0.0, 1e-3)))
        })
        .collect::<Result<Vec<_>, _>>()?;
    paths.push(
        Path2::new(vec![Segment2::at_rest(0.0, Vector2::new(10.0, 10.0))])
            .map_err(|e| e.to_string())?,
    );
    let radii = vec![1e-7; paths.len()];
    let begin = Instant::now();
    let mut s = CollisionSchedule::new(paths, &radii, ScheduleOptions::default())
        .map_err(|e| e.to_string())?;
    let build = begin.elapsed().as_secs_f64();
    let begin = Instant::now();
    std::hint::black_box(s.next_collision());
    Ok((build, begin.elapsed().as_secs_f64()))
}

/// `parallel_box`: (seconds per event, events).
fn parallel_box(n: usize, t_end: f64) -> Result<(f64, usize), String> {
    let side = (n as f64).sqrt().ceil() as usize;
    let balls = (0..n)
        .map(|k| {
            let p = Vector2::new((k % side) as f64 + 0.5, (k / side) as f64 + 0.5) / side as f64;
            Ball::new(p, Vector2::new(0.3, 0.7), 0.0).map_err(|e| e.to_string())
        })
        .collect::<Result<Vec<_>, _>>()?;
    let radii = vec![0.25 / (n as f64).sqrt(); n];
    let walls = Walls::new([0.0, 0.0], [1.0, 1.0]).map_err(|e| e.to_string())?;
    let options = SimulationOptions {
        t_end,
        max_events: Some(2000),
        ..Default::default()
    };
    let begin = Instant::now();
    let result = simulate(&balls, &radii, walls, &options).map_err(|e| e.to_string())?;
    let events = result.events.len();
    Ok((begin.elapsed().as_secs_f64() / events.max(1) as f64, events))
}

fn run(args: &[String]) -> Result<Vec<String>, String> {
    let repeats = match args.get(1) {
        Some(text) => text.parse::<usize>().map_err(|e| format!("REPEATS: {e}"))?,
        None => 5,
    };
    let only = args.get(2).map(String::as_str);
    let wanted = |case: &str| only.is_none_or(|c| c == case);
    let mut lines = vec![format!(
        "simd={} repeats={repeats} one_thread=true",
        simd::current().name()
    )];
    for t_max in [f64::INFINITY, 1e3]
        .into_iter()
        .filter(|_| wanted("parallel_open"))
    {
        let n = 400;
        let build = median(repeats, || parallel_open(n, t_max).map(|r| r.0))?;
        let first = median(repeats, || parallel_open(n, t_max).map(|r| r.1))?;
        let total = median(repeats, || parallel_open(n, t_max).map(|r| r.0 + r.1))?;
        lines.push(format!(
            "case=parallel_open n={n} t_max={t_max} build_ms={:.3} first_ms={:.3} total_ms={:.3}",
            build * 1e3,
            first * 1e3,
            total * 1e3
        ));
    }
    for t_max in [f64::INFINITY, 1e3]
        .into_iter()
        .filter(|_| wanted("gas_open"))
    {
        let n = 400;
        let events = gas_open(n, t_max)?.1;
        let per = median(repeats, || gas_open(n, t_max).map(|r| r.0))?;
        lines.push(format!(
            "case=gas_open n={n} t_max={t_max} events={events} us_per_event={:.2}",
            per * 1e6
        ));
    }
    if wanted("corner_open") {
        let n = 1000;
        // Both times from the same runs (each takes a while).
        let runs = (0..repeats.max(1))
            .map(|_| corner_open(n))
            .collect::<Result<Vec<_>, _>>()?;
        let build = median_of(runs.iter().map(|r| r.0).collect());
        let first = median_of(runs.iter().map(|r| r.1).collect());
        lines.push(format!(
            "case=corner_open n={n} t_max=inf build_ms={:.3} first_ms={:.3}",
            build * 1e3,
            first * 1e3
        ));
    }
    for n in [1, 4, 200].into_iter().filter(|_| wanted("parallel_box")) {
        for t_end in [f64::INFINITY, 100.0] {
            let events = parallel_box(n, t_end)?.1;
            let per = median(repeats, || parallel_box(n, t_end).map(|r| r.0))?;
            lines.push(format!(
                "case=parallel_box n={n} t_end={t_end} events={events} us_per_event={:.2}",
                per * 1e6
            ));
        }
    }
    Ok(lines)
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().collect();
    match run(&args) {
        Ok(lines) => {
            for line in lines {
                println!("{line}");
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("open_space_timing: {e}");
            ExitCode::FAILURE
        }
    }
}
