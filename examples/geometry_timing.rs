//! Times the static-geometry queries against the ball–ball pair query on the same paths: one
//! thread, single queries, in ns per query (a measurement to read, not a benchmark with a
//! bar).
//!
//! ```text
//! cargo run --release --example geometry_timing [-- N]
//! ```
//!
//! N (default 100,000) random billiard balls on a 9-ft table ([`PoolBall::random`]: sliding,
//! rolling, at rest; paths of 3 segments), each queried against: another random ball
//! (`path_collision_time`, contact distance 2R); one of the table's four cushions as a
//! segment, touched from the table's side (`path_segment_contact`); the same cushion as a
//! line (`path_plane_contact` in 2-D); a corner pocket's jaw tip, a circle of radius 1 cm
//! (`path_circle_contact`); and a corner pocket (`path_target_contact`, radius 6 cm). Each
//! query runs over all N balls, five times; the median of the five is printed, with the
//! number of hits.
//!
//! Then the batches on the same balls, one thread: `batch::path_collision_times` (each ball
//! against its random other) and `batch::path_geometry_times` against a whole pool table of
//! 36 objects (6 cushions, a jaw at each end of each, 12 rounded jaw tips, 6 pockets), with
//! `path_table_contact` one ball at a time; their time per object query (per ball over 36)
//! beside the batch's per pair.

use std::hint::black_box;
use std::time::Instant;

use std::num::NonZeroUsize;

use ballcollide::CollisionOptions;
use ballcollide::batch::{
    ContactColumns, PathPairs, PerPair, Threads, path_collision_times, path_geometry_times,
};
use ballcollide::geometry::{
    Circle, LineSegment, Plane, SegmentSide, Table, Target, path_circle_contact,
    path_plane_contact, path_segment_contact, path_table_contact, path_target_contact,
};
use ballcollide::path::Path2;
use ballcollide::path_collision_time;
use nalgebra::Vector2;

#[path = "../tests/support/path_table.rs"]
mod path_table;
#[path = "../tests/support/pool_balls.rs"]
mod pool_balls;
#[path = "../tests/support/rng.rs"]
mod rng;
use path_table::PathTable;
use pool_balls::{BALL_RADIUS, PoolBall, TABLE};
use rng::Rng;

/// Median ns per query of `query` over `paths` (five runs), and its hits.
fn time(paths: &[Path2], mut query: impl FnMut(usize, &Path2) -> Option<f64>) -> (f64, usize) {
    let mut runs = Vec::new();
    let mut hits = 0;
    for _ in 0..5 {
        hits = 0;
        let start = Instant::now();
        for (i, path) in paths.iter().enumerate() {
            hits += usize::from(black_box(query(i, black_box(path))).is_some());
        }
        runs.push(start.elapsed().as_secs_f64() * 1e9 / paths.len() as f64);
    }
    runs.sort_by(f64::total_cmp);
    (runs[2], hits)
}

/// Median ns per ball of `call` (five runs) over `n` balls, and what the last run returned.
fn time_call<T>(n: usize, mut call: impl FnMut() -> T) -> (f64, T) {
    let mut runs = Vec::new();
    let mut last = None;
    for _ in 0..5 {
        let start = Instant::now();
        last = Some(black_box(call()));
        runs.push(start.elapsed().as_secs_f64() * 1e9 / n as f64);
    }
    runs.sort_by(f64::total_cmp);
    (runs[2], last.expect("five runs"))
}

/// A pool table's 36 objects: six cushions between the pockets (touched from the table, on
/// their left going round it counter-clockwise), a jaw of 5 cm at 45° into the pocket at each
/// end of each (touched from both sides), a rounded tip of 7 mm at each cushion end, six
/// pockets of 6 cm.
fn pool_table() -> Table<2> {
    let [w, h] = TABLE;
    let (corner, middle, jaw) = (0.1, 0.065, 0.05);
    let stretches = [
        ([corner, 0.0], [w / 2.0 - middle, 0.0]),
        ([w / 2.0 + middle, 0.0], [w - corner, 0.0]),
        ([w, corner], [w, h - corner]),
        ([w - corner, h], [w / 2.0 + middle, h]),
        ([w / 2.0 - middle, h], [corner, h]),
        ([0.0, h - corner], [0.0, corner]),
    ];
    let mut table = Table::default();
    let segment = |p, q, side| LineSegment::new(p, q, side).expect("a cushion or a jaw");
    for (p, q) in stretches {
        let (p, q) = (Vector2::from(p), Vector2::from(q));
        let e = (q - p).normalize();
        let outward = Vector2::new(e.y, -e.x);
        let slant = std::f64::consts::FRAC_1_SQRT_2 * jaw;
        table.segments.push(segment(p, q, SegmentSide::Left));
        table
            .segments
            .push(segment(p + (outward - e) * slant, p, SegmentSide::Both));
        table
            .segments
            .push(segment(q, q + (outward + e) * slant, SegmentSide::Both));
        for tip in [p, q] {
            table.circles.push(Circle::new(tip, 0.007).expect("a tip"));
        }
    }
    let pockets = [
        [0.0, 0.0],
        [w / 2.0, -0.03],
        [w, 0.0],
        [w, h],
        [w / 2.0, h + 0.03],
        [0.0, h],
    ];
    for c in pockets {
        table
            .targets
            .push(Target::new(c.into(), 0.06).expect("a pocket"));
    }
    table
}

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .map_or(100_000, |x| x.parse().expect("N: a number of balls"));
    let mut rng = Rng(0x36);
    let paths: Vec<Path2> = (0..n).map(|_| PoolBall::random(&mut rng).path()).collect();
    let others: Vec<Path2> = (0..n).map(|_| PoolBall::random(&mut rng).path()).collect();
    let pick: Vec<usize> = (0..n).map(|_| rng.below(4) as usize).collect();
    let [w, h] = TABLE;
    let corners = [[0.0, 0.0], [w, 0.0], [w, h], [0.0, h]];
    // Counter-clockwise along the table's edge: the table lies on each cushion's left.
    let cushions: Vec<LineSegment> = (0..4)
        .map(|k| {
            let (p, q) = (corners[k], corners[(k + 1) % 4]);
            LineSegment::new(p.into(), q.into(), SegmentSide::Left).expect("a cushion")
        })
        .collect();
    let lines: Vec<Plane<2>> = (0..4)
        .map(|k| {
            let (p, q) = (
                Vector2::from(corners[k]),
                Vector2::from(corners[(k + 1) % 4]),
            );
            let e = q - p;
            Plane::new(p, Vector2::new(-e.y, e.x)).expect("a line")
        })
        .collect();
    let tips: Vec<Circle<2>> = corners
        .iter()
        .map(|&c| Circle::new(c.into(), 0.01).expect("a tip"))
        .collect();
    let pockets: Vec<Target<2>> = corners
        .iter()
        .map(|&c| Target::new(c.into(), 0.06).expect("a pocket"))
        .collect();
    let options = CollisionOptions::default();
    let r = BALL_RADIUS;
    let rows = [
        (
            "path_collision_time (ball-ball)",
            time(&paths, |i, p| {
                path_collision_time(p, &others[i], 2.0 * r, &options).expect("valid")
            }),
        ),
        (
            "path_segment_contact (cushion)",
            time(&paths, |i, p| {
                path_segment_contact(p, &cushions[pick[i]], r, &options).expect("valid")
            }),
        ),
        (
            "path_plane_contact (cushion line)",
            time(&paths, |i, p| {
                path_plane_contact(p, &lines[pick[i]], r, &options).expect("valid")
            }),
        ),
        (
            "path_circle_contact (jaw tip)",
            time(&paths, |i, p| {
                path_circle_contact(p, &tips[pick[i]], r, &options).expect("valid")
            }),
        ),
        (
            "path_target_contact (pocket)",
            time(&paths, |i, p| {
                path_target_contact(p, &pockets[pick[i]], &options).expect("valid")
            }),
        ),
    ];
    println!("{n} billiard-ball paths, one thread, median of 5 runs:");
    for (name, (ns, hits)) in rows {
        println!("  {name:<36} {ns:7.1} ns/query  {hits:6} hits");
    }

    // The batches, one thread.
    let one = Threads::AtMost(NonZeroUsize::MIN);
    let (rows_a, rows_b) = (PathTable::of(3, &paths), PathTable::of(3, &others));
    let pairs = PathPairs {
        a: rows_a.side(),
        b: rows_b.side(),
        contact_distance: PerPair::All(2.0 * r),
        t_max: PerPair::All(f64::INFINITY),
    };
    let mut times = vec![0.0; n];
    let (pair_ns, hits) = time_call(n, || {
        path_collision_times(&pairs, &mut times, one).expect("valid");
        times.iter().filter(|t| t.is_finite()).count()
    });
    let table = pool_table();
    let objects = table.len() as f64;
    let (mut time, mut kind, mut index) = (vec![0.0; n], vec![0i8; n], vec![0i64; n]);
    let (batch_ns, table_hits) = time_call(n, || {
        let out = ContactColumns {
            time: &mut time,
            kind: &mut kind,
            index: &mut index,
        };
        let radius = PerPair::All(r);
        path_geometry_times(
            &rows_a.side(),
            &table,
            radius,
            PerPair::All(f64::INFINITY),
            out,
            one,
        )
        .expect("valid");
        kind.iter().filter(|&&k| k >= 0).count()
    });
    let (single_ns, single_hits) = time_call(n, || {
        let hit = |p: &Path2| path_table_contact(p, &table, r, &options).expect("valid");
        paths.iter().filter(|p| hit(p).is_some()).count()
    });
    assert_eq!(single_hits, table_hits, "the batch is the single query");
    println!("the same balls in batches, one thread, median of 5 calls:");
    println!(
        "  {:<44} {pair_ns:7.1} ns/pair  {hits:6} hits",
        "batch::path_collision_times"
    );
    println!("  against a pool table of {objects} objects:");
    for (name, ns, hits) in [
        ("batch::path_geometry_times", batch_ns, table_hits),
        ("path_table_contact, ball by ball", single_ns, single_hits),
    ] {
        let per_object = ns / objects;
        println!(
            "  {name:<44} {ns:7.1} ns/ball  {hits:6} hits  {per_object:6.1} ns/object query \
             = {:.2}x a pair",
            per_object / pair_ns
        );
    }
}
