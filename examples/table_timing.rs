//! Times `simulate` on a pool table against the same balls in a plain box: what the table's
//! 36 objects cost per event. One thread.
//!
//! ```text
//! cargo run --release --example table_timing -- SHOTS
//! ```
//!
//! Two scenes, each run on the table ([`PoolTable`]: 18 segments, 12 jaw tips, 6 pockets,
//! inside a box 0.25 beyond it) and in the plain box of the playing area:
//!
//! - `break`: SHOTS breaks of a racked 15 and the cue ball (friction 0.4 m/s², restitution
//!   0.95, cushions 0.8), each to rest; the events of all shots together;
//! - `long`: one frictionless elastic run of the same balls for 30 s (no pockets on the
//!   table, so that no ball leaves), thousands of events.
//!
//! Prints per scene the µs per event on the table and in the box (the median of 5 runs) and
//! their ratio, the events, and how many ball–object pairs the object grid left out and
//! asked per object search; the CPU and SIMD level on stderr.

use std::process::ExitCode;
use std::time::Instant;

use ballcollide::Ball;
use ballcollide::geometry::{PoolTable, Table};
use ballcollide::schedule::{Simulation, SimulationOptions, Walls, simulate};
use nalgebra::Vector2;

#[path = "../tests/support/machine.rs"]
mod machine;
#[path = "../tests/support/rng.rs"]
mod rng;
use rng::Rng;

/// A pool ball's radius.
const R: f64 = 0.028575;

/// The rack and the cue ball shot at `speed`, `aim` radians off the rack's axis.
fn rack(spec: &PoolTable, speed: f64, aim: f64, friction: f64) -> Result<Vec<Ball>, String> {
    let gap = 1.0 + 1e-6;
    let apex = Vector2::new(spec.width / 2.0, 0.75 * spec.length);
    let cue = Vector2::new(spec.width / 2.0, spec.length / 4.0);
    let mut balls = vec![Ball::new(
        cue,
        Vector2::new(aim.sin(), aim.cos()) * speed,
        friction,
    )];
    for row in 0..5 {
        for k in 0..=row {
            let x = apex.x + (2.0 * k as f64 - row as f64) * R * gap;
            let y = apex.y + row as f64 * 3f64.sqrt() * R * gap;
            balls.push(Ball::new(Vector2::new(x, y), Vector2::zeros(), friction));
        }
    }
    balls
        .into_iter()
        .collect::<Result<_, _>>()
        .map_err(|e| e.to_string())
}

/// One scene's runs: the balls of each run, its options and box.
struct Scene {
    runs: Vec<Vec<Ball>>,
    options: SimulationOptions,
    walls: Walls<2>,
}

impl Scene {
    /// Runs every shot once: the seconds taken, the events, and the object counts.
    fn time(&self) -> Result<(f64, usize, [u64; 3]), String> {
        let mut events = 0;
        let mut counts = [0u64; 3];
        let begin = Instant::now();
        for balls in &self.runs {
            let run: Simulation = simulate(balls, &vec![R; balls.len()], self.walls, &self.options)
                .map_err(|e| e.to_string())?;
            events += run.events.len();
            let c = run.object_counts;
            counts[0] += c.searches;
            counts[1] += c.pruned;
            counts[2] += c.asked;
        }
        Ok((begin.elapsed().as_secs_f64(), events, counts))
    }
}

/// The median of 5 timings of a scene: µs per event, events, object counts.
fn median_per_event(scene: &Scene) -> Result<(f64, usize, [u64; 3]), String> {
    let mut per_event = Vec::new();
    let mut last = (0, [0; 3]);
    for _ in 0..5 {
        let (seconds, events, counts) = scene.time()?;
        per_event.push(seconds * 1e6 / events.max(1) as f64);
        last = (events, counts);
    }
    per_event.sort_by(f64::total_cmp);
    Ok((per_event[2], last.0, last.1))
}

fn run(args: &[String]) -> Result<String, String> {
    let shots: usize = args
        .get(1)
        .map_or(Ok(100), |s| s.parse())
        .map_err(|e| format!("SHOTS: {e}"))?;
    let spec = PoolTable::default();
    let table = spec.table().map_err(|e| e.to_string())?;
    let margin = 0.25;
    let around = Walls::new(
        [-margin, -margin],
        [spec.width + margin, spec.length + margin],
    )
    .map_err(|e| e.to_string())?;
    let plain = Walls::new([0.0, 0.0], [spec.width, spec.length]).map_err(|e| e.to_string())?;
    let mut rng = Rng(3);
    let breaks: Vec<Vec<Ball>> = (0..shots)
        .map(|_| rack(&spec, rng.uniform(4.0, 9.0), rng.uniform(-0.02, 0.02), 0.4))
        .collect::<Result<_, _>>()?;
    let shot = SimulationOptions {
        restitution: 0.95,
        table_restitution: 0.8,
        ..Default::default()
    };
    let mut pocketless = table.clone();
    pocketless.targets.clear();
    let long = SimulationOptions {
        t_end: 30.0,
        ..Default::default()
    };
    let long_balls = vec![rack(&spec, 6.0, 0.013, 0.0)?];
    let scenes = [
        ("break", breaks, shot, table),
        ("long", long_balls, long, pocketless),
    ];
    let mut out = String::new();
    for (name, runs, options, table) in scenes {
        let on_table = Scene {
            runs: runs.clone(),
            options: SimulationOptions {
                table,
                ..options.clone()
            },
            walls: around,
        };
        let in_box = Scene {
            runs,
            options: SimulationOptions {
                table: Table::default(),
                ..options
            },
            walls: plain,
        };
        let (t_table, events_table, counts) = median_per_event(&on_table)?;
        let (t_box, events_box, _) = median_per_event(&in_box)?;
        let searches = counts[0].max(1) as f64;
        out += &format!(
            "{name}: table_us_per_event={t_table:.3} box_us_per_event={t_box:.3} ratio={:.2} \
             events_table={events_table} events_box={events_box} object_searches={} \
             pruned_per_search={:.1} asked_per_search={:.2}\n",
            t_table / t_box,
            counts[0],
            counts[1] as f64 / searches,
            counts[2] as f64 / searches,
        );
    }
    // (The calendar and simulate run scalar code: the SIMD level is the batches'.)
    machine::print_machine();
    Ok(out.trim_end().to_string())
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().collect();
    match run(&args) {
        Ok(line) => {
            println!("{line}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("table_timing: {e}");
            ExitCode::FAILURE
        }
    }
}
