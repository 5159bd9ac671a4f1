//! `tests/data/shot_cases.txt` (pooltool's shots, written by `tools/shot_reference.py`) read
//! into a table, ball parameters and shots: shared by `tests/reference/shots.rs` and
//! `examples/shot_timing.rs`.
#![allow(dead_code)]

use ballcollide::billiards::{
    BallParams, BilliardTable, CircularCushion, Cue, CueSpecs, LinearCushion, Pocket,
    side_of_direction,
};
use nalgebra::Vector2;

/// The data file's table, ball parameters and shots.
pub struct Cases {
    pub params: BallParams,
    pub table: BilliardTable,
    pub shots: Vec<Case>,
}

/// One of pooltool's shots: the balls' spots, the strike of ball 0, and what pooltool made
/// of it.
pub struct Case {
    pub name: String,
    pub spots: Vec<Vector2<f64>>,
    pub cue: Cue,
    /// Per event: type, time, agents (`b0`, `l3`, `cue`, …).
    pub events: Vec<(String, f64, Vec<String>)>,
    /// Per ball: motion state code and position at the end.
    pub finals: Vec<(i64, Vector2<f64>)>,
}

fn numbers(fields: &[&str]) -> Vec<f64> {
    fields
        .iter()
        .map(|x| x.parse().expect("a number"))
        .collect()
}

pub fn read_cases() -> Cases {
    // Another file of the same format (more shots of `tools/shot_reference.py`) if named.
    let path = std::env::var("BALLCOLLIDE_SHOT_CASES").unwrap_or_else(|_| {
        concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/shot_cases.txt").to_string()
    });
    let text = std::fs::read_to_string(&path).expect("the shots' file");
    let mut params = BallParams::default();
    let mut table = BilliardTable::default();
    let mut shots: Vec<Case> = Vec::new();
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let fields: Vec<&str> = line.split_whitespace().collect();
        match fields[0] {
            "params" => {
                let x = numbers(&fields[1..]);
                params = BallParams {
                    mass: x[0],
                    radius: x[1],
                    u_s: x[2],
                    u_r: x[3],
                    u_sp_proportionality: x[4],
                    u_b: x[5],
                    e_b: x[6],
                    e_c: x[7],
                    f_c: x[8],
                    g: x[9],
                };
            }
            "linear" => {
                let x = numbers(&fields[2..7]);
                let cushion =
                    LinearCushion::new(Vector2::new(x[0], x[1]), Vector2::new(x[2], x[3]), x[4]);
                let direction = fields[7].parse().expect("a direction");
                let side = side_of_direction(&cushion, direction).expect("a direction");
                table.linear.push((cushion, side));
            }
            "circular" => {
                let x = numbers(&fields[2..]);
                let cushion = CircularCushion::new(Vector2::new(x[0], x[1]), x[2], x[3]);
                table.circular.push(cushion);
            }
            "pocket" => {
                let x = numbers(&fields[2..]);
                table
                    .pockets
                    .push(Pocket::new(Vector2::new(x[0], x[1]), x[2], x[3]));
            }
            "shot" => shots.push(Case {
                name: fields[1].to_string(),
                spots: Vec::new(),
                cue: Cue::default(),
                events: Vec::new(),
                finals: Vec::new(),
            }),
            "ball" => {
                let x = numbers(&fields[2..]);
                let shot = shots.last_mut().expect("a shot");
                shot.spots.push(Vector2::new(x[0], x[1]));
            }
            "cue" => {
                let x = numbers(&fields[1..]);
                shots.last_mut().expect("a shot").cue = Cue {
                    v0: x[0],
                    phi: x[1],
                    theta: x[2],
                    a: x[3],
                    b: x[4],
                    specs: CueSpecs {
                        mass: x[5],
                        end_mass: x[6],
                        tip_radius: x[7],
                    },
                };
            }
            "event" => {
                let time = fields[2].parse().expect("a time");
                let agents = fields[3..].iter().map(|s| s.to_string()).collect();
                let shot = shots.last_mut().expect("a shot");
                shot.events.push((fields[1].to_string(), time, agents));
            }
            "final" => {
                let x = numbers(&fields[3..]);
                let s = fields[2].parse().expect("a motion state");
                let shot = shots.last_mut().expect("a shot");
                shot.finals.push((s, Vector2::new(x[0], x[1])));
            }
            "end" => {}
            other => panic!("unknown line {other}"),
        }
    }
    Cases {
        params,
        table,
        shots,
    }
}
