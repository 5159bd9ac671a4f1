//! Times the event calendar on the benchmark's scene: frictionless disks in the unit box, `N`
//! on a grid, radius `¼/√N`, normal(0, 1) velocities; one thread.
//!
//! ```text
//! cargo run --release --example schedule_timing -- N EVENTS
//! ```
//!
//! Prints one line of `key=value` fields: `simulate`'s µs per event over EVENTS events (its
//! build of the calendar, timed on its own, left out), the calendar's build time and heap
//! bytes per ball (its own state, the paths, the grid), and the ns per call of `path_collision_time` on the pairs the calendar asks about (each ball
//! against its grid neighbours, one constant-velocity segment each), the bulk of its work.

use std::hint::black_box;
use std::process::ExitCode;
use std::time::Instant;

use ballcollide::path::{Path2, Segment2};
use ballcollide::schedule::{
    CollisionSchedule, ScheduleOptions, SimulationOptions, Walls, simulate,
};
use ballcollide::{Ball, CollisionOptions, path_collision_time};
use nalgebra::Vector2;

#[path = "../tests/support/rng.rs"]
mod rng;
use rng::Rng;

/// The scene: `side²` balls.
fn scene(side: usize, seed: u64) -> Result<(Vec<Ball>, f64), String> {
    let mut rng = Rng(seed);
    let spacing = 1.0 / side as f64;
    let balls = (0..side * side)
        .map(|k| {
            let p = Vector2::new((k % side) as f64 + 0.5, (k / side) as f64 + 0.5) * spacing;
            let v = Vector2::new(rng.normal(), rng.normal());
            Ball::new(p, v, 0.0).map_err(|e| e.to_string())
        })
        .collect::<Result<_, _>>()?;
    Ok((balls, 0.25 * spacing))
}

fn run(args: &[String]) -> Result<String, String> {
    let number = |i: usize, name: &str| -> Result<usize, String> {
        let text = args
            .get(i)
            .ok_or(format!("usage: schedule_timing N EVENTS ({name})"))?;
        text.parse::<f64>()
            .map(|x| x as usize)
            .map_err(|e| format!("{name}: {e}"))
    };
    let n = number(1, "N")?;
    let events = number(2, "EVENTS")?;
    let side = (n as f64).sqrt().round().max(1.0) as usize;
    let (balls, r) = scene(side, 7)?;
    let walls = Walls::new([0.0, 0.0], [1.0, 1.0]).map_err(|e| e.to_string())?;
    let options = SimulationOptions {
        max_events: Some(events),
        ..Default::default()
    };
    let radii = vec![r; balls.len()];
    // The calendar alone: its build time and memory.
    let begin = Instant::now();
    let calendar_options = ScheduleOptions {
        walls: Some(walls),
        ..Default::default()
    };
    let calendar = CollisionSchedule::<2>::from_balls(&balls, &radii, 0.0, calendar_options)
        .map_err(|e| e.to_string())?;
    let build = begin.elapsed().as_secs_f64();
    let memory = calendar.heap_bytes();
    drop(calendar);
    let begin = Instant::now();
    let result = simulate(&balls, &radii, walls, &options).map_err(|e| e.to_string())?;
    let elapsed = begin.elapsed().as_secs_f64();
    // Per event, without the build that `simulate` does first.
    let per_event = (elapsed - build).max(0.0) / result.events.len().max(1) as f64 * 1e6;

    // The pair query on neighbours: ball k against k + 1 and k + side.
    let paths: Vec<Path2> = balls
        .iter()
        .map(|b| {
            Path2::new(vec![Segment2::new(
                0.0,
                b.position(),
                b.velocity(),
                Vector2::zeros(),
            )])
        })
        .collect::<Result<_, _>>()
        .map_err(|e| e.to_string())?;
    let pairs: Vec<(usize, usize)> = (0..paths.len())
        .flat_map(|k| [(k, k + 1), (k, k + side)])
        .filter(|&(_, j)| j < paths.len())
        .take(200_000)
        .collect();
    let options = CollisionOptions::default();
    let begin = Instant::now();
    let mut hits = 0usize;
    for &(i, j) in &pairs {
        let t = path_collision_time(&paths[i], &paths[j], 2.0 * r, &options);
        hits += usize::from(black_box(t).is_ok_and(|t| t.is_some()));
    }
    let pair_ns = begin.elapsed().as_secs_f64() / pairs.len().max(1) as f64 * 1e9;
    Ok(format!(
        "n={} events={} us_per_event={per_event:.3} seconds={elapsed:.3} build_seconds={build:.3} \
         bytes_per_ball={:.1} path_bytes_per_ball={:.1} grid_bytes_per_ball={:.1} \
         pair_query_ns={pair_ns:.1} pairs={} pair_hits={hits}",
        balls.len(),
        result.events.len(),
        memory.per_ball as f64 / balls.len() as f64,
        memory.paths as f64 / balls.len() as f64,
        memory.grid as f64 / balls.len() as f64,
        pairs.len()
    ))
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().collect();
    match run(&args) {
        Ok(line) => {
            println!("{line}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("schedule_timing: {e}");
            ExitCode::FAILURE
        }
    }
}
