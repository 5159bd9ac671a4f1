//! The collision time against the independent high-precision reference.
//!
//! `tests/data/collision_cases.txt` is written by `tools/collision_reference.py`, which
//! computes each case with mpmath at 60+ digits from the exact binary value of the float
//! inputs (never with this library), and records with each time its *floor*: the first-order
//! change of the exact time under one rounding of every input. SPEC's bar:
//! - no hit/miss disagreement, except on cases flagged ambiguous (within ~1e-9 of grazing);
//! - `|t − t_ref| ≤ 64·floor`, or ≤ 4 ulp of `t_ref` where that is larger.
//!
//! Run with `--nocapture` to see the error/floor distribution per category.

use crate::support::reference_table;

use ballcollide::{Ball, CollisionOptions, collision_time_with};
use nalgebra::Vector2;
use reference_table::Table;

const DATA: &str = include_str!("../data/collision_cases.txt");

struct Case {
    line: usize,
    category: String,
    a: Ball,
    b: Ball,
    radius: f64,
    t_max: f64,
    t_ref: f64,
    floor: f64,
    ambiguous: bool,
}

fn parse(line_no: usize, line: &str) -> Case {
    let f: Vec<&str> = line.split_whitespace().collect();
    assert_eq!(f.len(), 16, "line {line_no}: expected 16 columns");
    let x = |i: usize| -> f64 {
        f[i].parse()
            .unwrap_or_else(|_| panic!("line {line_no}: bad number {}", f[i]))
    };
    let ball = |i: usize| {
        Ball::new(
            Vector2::new(x(i), x(i + 1)),
            Vector2::new(x(i + 2), x(i + 3)),
            x(i + 4),
        )
        .unwrap_or_else(|e| panic!("line {line_no}: {e}"))
    };
    Case {
        line: line_no,
        category: f[0].to_string(),
        a: ball(1),
        b: ball(6),
        radius: x(11),
        t_max: x(12),
        t_ref: x(13),
        floor: x(14),
        ambiguous: f[15] == "1",
    }
}

#[test]
fn matches_the_high_precision_reference() {
    let mut table = Table::default();
    let cases = DATA
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty() && !l.starts_with('#'))
        .map(|(i, l)| parse(i + 1, l));
    for case in cases {
        let options = CollisionOptions { t_max: case.t_max };
        let got = collision_time_with(&case.a, &case.b, case.radius, &options)
            .unwrap_or_else(|e| panic!("line {}: {e}", case.line));
        table.record(
            &case.category,
            case.line,
            got,
            case.t_ref,
            case.floor,
            case.ambiguous,
        );
    }
    table.check(20_000);
}
