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

use std::hint::black_box;
use std::time::Instant;

use ballcollide::CollisionOptions;
use ballcollide::geometry::{
    Circle, LineSegment, Plane, SegmentSide, Target, path_circle_contact, path_plane_contact,
    path_segment_contact, path_target_contact,
};
use ballcollide::path::Path2;
use ballcollide::path_collision_time;
use nalgebra::Vector2;

#[path = "../tests/support/pool_balls.rs"]
mod pool_balls;
#[path = "../tests/support/rng.rs"]
mod rng;
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
}
