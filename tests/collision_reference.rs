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

use std::collections::BTreeMap;

use ballcollide::{Ball, CollisionOptions, collision_time_with};
use nalgebra::Vector2;

const DATA: &str = include_str!("data/collision_cases.txt");

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

fn ulp(x: f64) -> f64 {
    let x = x.abs();
    f64::from_bits(x.to_bits() + 1) - x
}

#[derive(Default)]
struct Stats {
    cases: usize,
    hits: usize,
    ambiguous: usize,
    ratios: Vec<f64>,
    worst: (f64, usize),
    failures: Vec<String>,
}

fn percentile(sorted: &[f64], p: f64) -> f64 {
    if sorted.is_empty() {
        return 0.0;
    }
    let k = ((sorted.len() as f64 - 1.0) * p).round() as usize;
    sorted[k]
}

#[test]
fn matches_the_high_precision_reference() {
    let mut by_category: BTreeMap<String, Stats> = BTreeMap::new();
    let cases = DATA
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty() && !l.starts_with('#'))
        .map(|(i, l)| parse(i + 1, l));
    let mut total = 0;
    for case in cases {
        total += 1;
        let options = CollisionOptions { t_max: case.t_max };
        let got = collision_time_with(&case.a, &case.b, case.radius, &options)
            .unwrap_or_else(|e| panic!("line {}: {e}", case.line));
        let stats = by_category.entry(case.category.clone()).or_default();
        stats.cases += 1;
        stats.ambiguous += case.ambiguous as usize;
        let want = case.t_ref.is_finite().then_some(case.t_ref);
        stats.hits += want.is_some() as usize;
        match (got, want) {
            (Some(t), Some(t_ref)) => {
                let err = (t - t_ref).abs();
                let tolerance = (64.0 * case.floor).max(4.0 * ulp(t_ref));
                let scale = case.floor.max(ulp(t_ref));
                stats.ratios.push(err / scale);
                if err / scale > stats.worst.0 {
                    stats.worst = (err / scale, case.line);
                }
                if err > tolerance && !case.ambiguous {
                    stats.failures.push(format!(
                        "line {}: t = {t:e}, t_ref = {t_ref:e}, error/floor = {:.1}",
                        case.line,
                        err / case.floor
                    ));
                }
            }
            (None, None) => {}
            _ if case.ambiguous => {}
            (got, _) => stats.failures.push(format!(
                "line {}: hit/miss differs: got {got:?}, reference {want:?}",
                case.line
            )),
        }
    }
    assert!(total >= 20_000, "only {total} reference cases");

    eprintln!(
        "{:<22} {:>6} {:>6} {:>6} {:>12} {:>12} {:>6} {:>7}",
        "category", "cases", "hits", "ambig", "p99.9 err/fl", "max err/fl", "fails", "at line"
    );
    let mut failures = Vec::new();
    for (name, stats) in &mut by_category {
        stats.ratios.sort_by(f64::total_cmp);
        eprintln!(
            "{:<22} {:>6} {:>6} {:>6} {:>12.2} {:>12.2} {:>6} {:>7}",
            name,
            stats.cases,
            stats.hits,
            stats.ambiguous,
            percentile(&stats.ratios, 0.999),
            stats.ratios.last().copied().unwrap_or(0.0),
            stats.failures.len(),
            stats.worst.1
        );
        failures.extend(stats.failures.iter().map(|f| format!("{name}: {f}")));
    }
    assert!(
        failures.is_empty(),
        "{} failures, first ones:\n{}",
        failures.len(),
        failures
            .iter()
            .take(30)
            .cloned()
            .collect::<Vec<_>>()
            .join("\n")
    );
}
