//! Times `billiards::simulate_shot` on pooltool's shots of `tests/data/shot_cases.txt`
//! (written by `tools/shot_reference.py`: cuts, rails, pockets, two object balls, massé,
//! 9-ball breaks on pooltool's default table). One thread.
//!
//! ```text
//! cargo run --release --example shot_timing -- [ROUNDS]
//! ```
//!
//! Prints per kind of shot the shots, their events, and the median over ROUNDS (default 7)
//! of the µs per shot and per event; the CPU and SIMD level on stderr.

use std::process::ExitCode;
use std::time::Instant;

use ballcollide::billiards::{BallState, ShotOptions, simulate_shot};

#[path = "../tests/support/machine.rs"]
mod machine;
#[path = "../tests/support/shot_cases.rs"]
mod shot_cases;

fn main() -> ExitCode {
    let rounds: usize = match std::env::args().nth(1).map(|a| a.parse()) {
        None => 7,
        Some(Ok(n)) if n > 0 => n,
        Some(_) => {
            eprintln!("usage: shot_timing [ROUNDS > 0]");
            return ExitCode::FAILURE;
        }
    };
    machine::print_machine();
    let cases = shot_cases::read_cases();
    let mut kinds: Vec<&str> = Vec::new();
    for case in &cases.shots {
        let kind = case.name.split('-').next().unwrap_or_default();
        if !kinds.contains(&kind) {
            kinds.push(kind);
        }
    }
    println!(
        "{:>8} {:>6} {:>7} {:>12} {:>12}",
        "kind", "shots", "events", "us/shot", "us/event"
    );
    for kind in kinds {
        let shots: Vec<_> = cases
            .shots
            .iter()
            .filter(|c| c.name.starts_with(kind))
            .collect();
        let mut times = Vec::with_capacity(rounds);
        let mut events = 0;
        for _ in 0..rounds {
            events = 0;
            let start = Instant::now();
            for case in &shots {
                let balls: Vec<BallState> =
                    case.spots.iter().map(|&p| BallState::at_rest(p)).collect();
                let params = vec![cases.params; balls.len()];
                let options = ShotOptions {
                    strike: Some((0, case.cue)),
                    ..Default::default()
                };
                match simulate_shot(&cases.table, &balls, &params, &options) {
                    Ok(shot) => events += shot.events.len(),
                    Err(e) => {
                        eprintln!("{}: {e}", case.name);
                        return ExitCode::FAILURE;
                    }
                }
            }
            times.push(start.elapsed().as_secs_f64());
        }
        times.sort_by(f64::total_cmp);
        let median = times[rounds / 2];
        println!(
            "{kind:>8} {:>6} {events:>7} {:>12.1} {:>12.2}",
            shots.len(),
            median * 1e6 / shots.len() as f64,
            median * 1e6 / events as f64
        );
    }
    ExitCode::SUCCESS
}
