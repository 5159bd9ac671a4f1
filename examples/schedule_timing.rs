//! Times the event calendar on the benchmark's scene: frictionless disks in the unit box, `N`
//! on a grid, radius `¼/√N`, normal(0, 1) velocities; one thread.
//!
//! ```text
//! cargo run --release --example schedule_timing -- N EVENTS [FRICTION [RADIUS [open]]]
//! ```
//!
//! FRICTION (default 0) is every ball's friction deceleration, RADIUS (default 0.25) the
//! radius times `√N` (0.25: dense, the balls half a spacing apart; 0.025: dilute). With
//! `open`, the same balls without walls, driven through the calendar itself
//! (`next_collision`, equal masses exchanging their normal velocities, `update_balls`) rather
//! than `simulate`: µs per event after the build, until EVENTS or no event is left.
//!
//! Prints one line of `key=value` fields: `simulate`'s µs per event over EVENTS events (its
//! build of the calendar, timed on its own, left out; in wall-clock time, and in the
//! process's CPU time, which a loaded machine disturbs less), the calendar's build time and heap
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

/// The process's CPU time in seconds (Linux; elsewhere NaN): on a shared machine, where other
/// processes take the cores for part of the wall-clock time, what the run itself cost.
fn cpu_seconds() -> f64 {
    #[cfg(target_os = "linux")]
    {
        #[repr(C)]
        struct Timespec {
            seconds: i64,
            nanoseconds: i64,
        }
        const CLOCK_PROCESS_CPUTIME_ID: i32 = 2;
        unsafe extern "C" {
            fn clock_gettime(clock: i32, time: *mut Timespec) -> i32;
        }
        let mut time = Timespec {
            seconds: 0,
            nanoseconds: 0,
        };
        // SAFETY: `time` is a valid, writable `struct timespec` (two 64-bit fields on the
        // 64-bit Linux targets this builds for), and the clock id is Linux's.
        if unsafe { clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &mut time) } == 0 {
            return time.seconds as f64 + time.nanoseconds as f64 * 1e-9;
        }
    }
    f64::NAN
}

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

/// The open scene's run: the calendar without walls, collisions resolved elastically (equal
/// masses) until `events` or none is left: (seconds after the build, events, build seconds,
/// CPU seconds after the build).
fn open_run(
    balls: &[Ball],
    radii: &[f64],
    events: usize,
) -> Result<(f64, usize, f64, f64), String> {
    let begin = Instant::now();
    let mut s = CollisionSchedule::<2>::from_balls(balls, radii, 0.0, ScheduleOptions::default())
        .map_err(|e| e.to_string())?;
    let build = begin.elapsed().as_secs_f64();
    let begin = Instant::now();
    let cpu = cpu_seconds();
    let mut done = 0;
    while done < events {
        let Some(c) = s.next_collision() else { break };
        let t = c.time;
        let (pi, pj) = (s.path(c.i).position_at(t), s.path(c.j).position_at(t));
        let (vi, vj) = (s.path(c.i).velocity_at(t), s.path(c.j).velocity_at(t));
        let normal = (pi - pj).normalize();
        let dv = normal * (vi - vj).dot(&normal);
        let friction = balls[c.i].friction();
        let after = [
            Ball::new(pi, vi - dv, friction).map_err(|e| e.to_string())?,
            Ball::new(pj, vj + dv, balls[c.j].friction()).map_err(|e| e.to_string())?,
        ];
        s.update_balls(&[c.i, c.j], t, &after)
            .map_err(|e| e.to_string())?;
        done += 1;
    }
    Ok((
        begin.elapsed().as_secs_f64(),
        done,
        build,
        cpu_seconds() - cpu,
    ))
}

fn run(args: &[String]) -> Result<String, String> {
    let usage = "usage: schedule_timing N EVENTS [FRICTION [RADIUS [open]]]";
    let number = |i: usize, name: &str, default: Option<f64>| -> Result<f64, String> {
        match (args.get(i), default) {
            (Some(text), _) => text.parse::<f64>().map_err(|e| format!("{name}: {e}")),
            (None, Some(x)) => Ok(x),
            (None, None) => Err(format!("{usage} ({name})")),
        }
    };
    let n = number(1, "N", None)? as usize;
    let events = number(2, "EVENTS", None)? as usize;
    let friction = number(3, "FRICTION", Some(0.0))?;
    let radius = number(4, "RADIUS", Some(0.25))?;
    let open = match args.get(5).map(String::as_str) {
        None => false,
        Some("open") => true,
        Some(other) => return Err(format!("{usage}: expected open, got {other}")),
    };
    let side = (n as f64).sqrt().round().max(1.0) as usize;
    let (mut balls, r) = scene(side, 7)?;
    let r = r * radius / 0.25;
    if friction != 0.0 {
        balls = balls
            .iter()
            .map(|b| Ball::new(b.position(), b.velocity(), friction).map_err(|e| e.to_string()))
            .collect::<Result<_, _>>()?;
    }
    if open {
        let (seconds, done, build, cpu) = open_run(&balls, &vec![r; balls.len()], events)?;
        return Ok(format!(
            "n={} events={done} friction={friction} radius={radius} open=1 \
             us_per_event={:.3} cpu_us_per_event={:.3} seconds={seconds:.3} \
             build_seconds={build:.3}",
            balls.len(),
            seconds / done.max(1) as f64 * 1e6,
            cpu / done.max(1) as f64 * 1e6
        ));
    }
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
    let cpu = cpu_seconds();
    let calendar = CollisionSchedule::<2>::from_balls(&balls, &radii, 0.0, calendar_options)
        .map_err(|e| e.to_string())?;
    let build = begin.elapsed().as_secs_f64();
    let cpu_build = cpu_seconds() - cpu;
    let memory = calendar.heap_bytes();
    drop(calendar);
    let begin = Instant::now();
    let cpu = cpu_seconds();
    let result = simulate(&balls, &radii, walls, &options).map_err(|e| e.to_string())?;
    let elapsed = begin.elapsed().as_secs_f64();
    let cpu_elapsed = cpu_seconds() - cpu;
    // Per event, without the build that `simulate` does first.
    let per_event = (elapsed - build).max(0.0) / result.events.len().max(1) as f64 * 1e6;
    let cpu_per_event =
        (cpu_elapsed - cpu_build).max(0.0) / result.events.len().max(1) as f64 * 1e6;

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
        "n={} events={} friction={friction} radius={radius} open=0 \
         us_per_event={per_event:.3} cpu_us_per_event={cpu_per_event:.3} seconds={elapsed:.3} \
         build_seconds={build:.3} \
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
