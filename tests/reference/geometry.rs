//! Contacts with static geometry against the independent high-precision reference.
//!
//! `tests/data/geometry_cases.txt` is written by `tools/geometry_reference.py` (mpmath at 256
//! bits from the exact binary value of every input, never this library), with each time its
//! floor (the first-order change of the exact time under one rounding of every input: the
//! path's active segment, every number of the object and the radius) and an ambiguity flag.
//! The bar is the pair references' (`tests/support/reference_table.rs`): hit or miss right
//! outside the cases flagged ambiguous (within 1e-9 of a graze, of a segment's end, of
//! touching tangentially at the start, of the horizon), times within 64 floors.
//!
//! Run with `--nocapture` to see the error/floor distribution per category.

use crate::support::fields;
use crate::support::reference_table;

use ballcollide::CollisionOptions;
use ballcollide::geometry::{
    Circle, LineSegment, Plane, SegmentSide, Target, path_circle_contact, path_plane_contact,
    path_segment_contact, path_target_contact,
};
use ballcollide::path::Path;
use fields::Fields;
use reference_table::Table;

/// The library's answer for one line's case: its kind, path, radius, object and horizon.
fn answer<const D: usize>(kind: &str, fields: &mut Fields<'_>) -> Option<f64> {
    let k = fields.count();
    let path: Path<D> = fields.path(k);
    let radius = fields.number();
    let line = fields.line;
    let fail = |e: ballcollide::InputError| -> ! { panic!("line {line}: {e}") };
    let got = match kind {
        "segment" => {
            let (p, q) = (fields.vector::<2>(), fields.vector::<2>());
            let side = SegmentSide::from_sign(fields.number() as i64).unwrap_or_else(|e| fail(e));
            let segment = LineSegment::new(p, q, side).unwrap_or_else(|e| fail(e));
            let options = CollisionOptions {
                t_max: fields.number(),
            };
            let path = two_d(&path);
            path_segment_contact(&path, &segment, radius, &options)
        }
        "circle" | "target" => {
            let (centre, rho) = (fields.vector::<D>(), fields.number());
            let options = CollisionOptions {
                t_max: fields.number(),
            };
            if kind == "circle" {
                let circle = Circle::new(centre, rho).unwrap_or_else(|e| fail(e));
                path_circle_contact(&path, &circle, radius, &options)
            } else {
                let target = Target::new(centre, rho).unwrap_or_else(|e| fail(e));
                path_target_contact(&path, &target, &options)
            }
        }
        "plane" => {
            let (point, normal) = (fields.vector::<D>(), fields.vector::<D>());
            let plane = Plane::new(point, normal).unwrap_or_else(|e| fail(e));
            let options = CollisionOptions {
                t_max: fields.number(),
            };
            path_plane_contact(&path, &plane, radius, &options)
        }
        other => panic!("line {line}: kind {other}"),
    };
    got.unwrap_or_else(|e| fail(e))
}

/// A path known to be 2-D as a `Path<2>` (segments are 2-D only).
fn two_d<const D: usize>(path: &Path<D>) -> Path<2> {
    let segments = path
        .segments()
        .iter()
        .map(|s| {
            let v = |x: nalgebra::SVector<f64, D>| nalgebra::Vector2::new(x[0], x[1]);
            ballcollide::path::Segment::new(
                s.start,
                v(s.position),
                v(s.velocity),
                v(s.acceleration),
            )
        })
        .collect();
    Path::new(segments).expect("a valid path")
}

#[test]
fn matches_the_high_precision_reference() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/geometry_cases.txt");
    let path = std::env::var("GEOMETRY_CASES").unwrap_or_else(|_| path.to_string());
    let data = std::fs::read_to_string(&path).expect("tests/data/geometry_cases.txt");
    let mut table = Table::default();
    for (i, line) in data.lines().enumerate() {
        if line.trim().is_empty() || line.starts_with('#') {
            continue;
        }
        let words: Vec<&str> = line.split_whitespace().collect();
        let (category, kind, dimension) = (words[0], words[1], words[2]);
        let mut fields = Fields {
            line: i + 1,
            rest: words[3..].iter(),
        };
        let got = match dimension {
            "2" => answer::<2>(kind, &mut fields),
            "3" => answer::<3>(kind, &mut fields),
            d => panic!("line {}: dimension {d}", i + 1),
        };
        let (t_ref, floor) = (fields.number(), fields.number());
        let ambiguous = fields.number() == 1.0;
        table.record(category, i + 1, got, t_ref, floor, ambiguous);
    }
    table.check(if path.ends_with("geometry_cases.txt") {
        10_000
    } else {
        1
    });
}
