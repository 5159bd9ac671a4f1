//! First contacts on paths against the independent high-precision reference.
//!
//! `tests/data/path_cases.txt` is written by `tools/path_reference.py` (mpmath at 256 bits from
//! the exact binary value of every input, never this library), with each time its floor (the
//! first-order change of the exact time under one rounding of every input) and an ambiguity
//! flag. The bar is the friction reference's (`tests/support/reference_table.rs`).
//!
//! Run with `--nocapture` to see the error/floor distribution per category.

use crate::support::fields;
use crate::support::reference_table;

use ballcollide::{CollisionOptions, path_collision_time};
use fields::Fields;
use reference_table::Table;

fn check<const D: usize>(table: &mut Table, category: &str, mut fields: Fields<'_>) {
    let (ka, kb) = (fields.count(), fields.count());
    let (a, b) = (fields.path::<D>(ka), fields.path::<D>(kb));
    let (radius, t_max) = (fields.number(), fields.number());
    let (t_ref, floor) = (fields.number(), fields.number());
    let ambiguous = fields.number() == 1.0;
    let line = fields.line;
    let got = path_collision_time(&a, &b, radius, &CollisionOptions { t_max })
        .unwrap_or_else(|e| panic!("line {line}: {e}"));
    table.record(category, line, got, t_ref, floor, ambiguous);
}

#[test]
fn matches_the_high_precision_reference() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/path_cases.txt");
    let data = std::fs::read_to_string(path).expect("tests/data/path_cases.txt");
    let mut table = Table::default();
    for (i, line) in data.lines().enumerate() {
        if line.trim().is_empty() || line.starts_with('#') {
            continue;
        }
        let words: Vec<&str> = line.split_whitespace().collect();
        let (category, dimension) = (words[0], words[1]);
        let fields = Fields {
            line: i + 1,
            rest: words[2..].iter(),
        };
        match dimension {
            "2" => check::<2>(&mut table, category, fields),
            "3" => check::<3>(&mut table, category, fields),
            d => panic!("line {}: dimension {d}", i + 1),
        }
    }
    table.check(20_000);
}
