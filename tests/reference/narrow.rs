//! Contacts far narrower than the float grid (issue 39), against the independent reference.
//!
//! `tests/data/narrow_cases.txt` is written by `tools/narrow_reference.py`: exact head-on and
//! off-axis contacts (and clear misses) whose contact distance runs from the separation down
//! to `2⁻⁴⁰⁰` of it, four cases per octave, friction balls and paths in 2-D and 3-D, answered
//! by the repository's mpmath references (`tools/collision_reference.py`,
//! `tools/path_reference.py`) at 1200 bits from the exact binary inputs, never by this library.
//! The bar is the other reference tests' (`tests/support/reference_table.rs`): hit or miss as
//! the reference says, the time within a small multiple of its floor. A friction pair is asked
//! both ways, `collision_time` and `path_collision_time` on the balls' paths (`Ball::path`),
//! and the two must agree on hit or miss; a path pair's calendar (`CollisionSchedule` of the two
//! balls) must give `path_collision_time`'s bits.
//!
//! Run with `--nocapture` to see the error/floor distribution per category.

use crate::support::fields;
use crate::support::reference_table;

use ballcollide::path::Path;
use ballcollide::schedule::{CollisionSchedule, ScheduleOptions};
use ballcollide::{Ball, CollisionOptions, collision_time_with, path_collision_time};
use fields::Fields;
use nalgebra::Vector2;
use reference_table::Table;

fn check_path<const D: usize>(table: &mut Table, category: &str, mut fields: Fields<'_>) {
    let (ka, kb) = (fields.number() as usize, fields.number() as usize);
    let (a, b) = (fields.path::<D>(ka), fields.path::<D>(kb));
    let (radius, t_max) = (fields.number(), fields.number());
    let (t_ref, floor) = (fields.number(), fields.number());
    let ambiguous = fields.number() == 1.0;
    let line = fields.line;
    let got = path_collision_time(&a, &b, radius, &CollisionOptions { t_max })
        .unwrap_or_else(|e| panic!("line {line}: {e}"));
    table.record(category, line, got, t_ref, floor, ambiguous);
    assert_eq!(
        calendar_time(a, b, radius).map(f64::to_bits),
        got.map(f64::to_bits),
        "line {line}: the calendar and path_collision_time"
    );
}

/// The first collision of the calendar of two balls on `a` and `b` whose radii sum to `radius`
/// (halves: exact).
fn calendar_time<const D: usize>(a: Path<D>, b: Path<D>, radius: f64) -> Option<f64> {
    let radii = [0.5 * radius, 0.5 * radius];
    let mut calendar =
        CollisionSchedule::new(vec![a, b], &radii, ScheduleOptions::default()).expect("valid");
    calendar.next_collision().map(|c| c.time)
}

fn check_balls(table: &mut Table, category: &str, mut fields: Fields<'_>) {
    let (a, b) = (fields.ball(), fields.ball());
    let (radius, t_max) = (fields.number(), fields.number());
    let (t_ref, floor) = (fields.number(), fields.number());
    let ambiguous = fields.number() == 1.0;
    let line = fields.line;
    let options = CollisionOptions { t_max };
    let got = collision_time_with(&a, &b, radius, &options)
        .unwrap_or_else(|e| panic!("line {line}: {e}"));
    table.record(category, line, got, t_ref, floor, ambiguous);
    let (Ok(path_a), Ok(path_b)) = (a.path(), b.path()) else {
        panic!("line {line}: paths of valid balls")
    };
    let as_paths = path_collision_time(&path_a, &path_b, radius, &options)
        .unwrap_or_else(|e| panic!("line {line}: {e}"));
    table.record(
        &format!("{category}_as_path"),
        line,
        as_paths,
        t_ref,
        floor,
        ambiguous,
    );
    assert_eq!(
        got.is_some(),
        as_paths.is_some(),
        "line {line}: collision_time {got:?}, path_collision_time {as_paths:?}"
    );
}

#[test]
fn narrow_contacts_match_the_high_precision_reference() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/narrow_cases.txt");
    let data = std::fs::read_to_string(path).expect("tests/data/narrow_cases.txt");
    let mut table = Table::default();
    for (i, line) in data.lines().enumerate() {
        if line.trim().is_empty() || line.starts_with('#') {
            continue;
        }
        let words: Vec<&str> = line.split_whitespace().collect();
        let (query, category) = (words[0], words[1]);
        let fields = Fields {
            line: i + 1,
            rest: words[2..].iter(),
        };
        match query {
            "ball" => check_balls(&mut table, category, fields),
            "path" => {
                let mut fields = fields;
                match fields.number() as usize {
                    2 => check_path::<2>(&mut table, category, fields),
                    3 => check_path::<3>(&mut table, category, fields),
                    d => panic!("line {}: dimension {d}", i + 1),
                }
            }
            q => panic!("line {}: query {q}", i + 1),
        }
    }
    table.check(1_600);
}

/// The two reproducers: head on along x, 2 apart, each ball at `v` towards the other.
#[test]
fn the_reported_head_on_contacts_are_hits_for_every_query() {
    for (v, r) in [
        (5.109376374596892e-05, 1.2747625043112508e-60),
        (4.984466564316976e-05, 1.0109067911581229e-20),
    ] {
        let ball = |x: f64, v: f64| Ball::new(Vector2::new(x, 0.0), Vector2::new(v, 0.0), 0.0);
        let (Ok(a), Ok(b)) = (ball(0.0, v), ball(2.0, -v)) else {
            panic!("valid balls")
        };
        let (Ok(pa), Ok(pb)) = (a.path(), b.path()) else {
            panic!("valid paths")
        };
        let options = CollisionOptions::default();
        let expected = (2.0 - r) / (2.0 * v);
        let by_balls = collision_time_with(&a, &b, r, &options).expect("valid");
        let by_paths = path_collision_time(&pa, &pb, r, &options).expect("valid");
        let by_calendar = calendar_time(pa, pb, r);
        for t in [by_balls, by_paths, by_calendar] {
            let t = t.unwrap_or(f64::INFINITY);
            assert!(
                (t - expected).abs() <= 4.0 * f64::EPSILON * expected,
                "v = {v:e}, r = {r:e}: {t} vs {expected}"
            );
        }
    }
}
