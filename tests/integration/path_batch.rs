//! The batch of path pairs: the single query's answers, bit for bit, whatever the threads,
//! with A broadcast or not; errors naming the argument, the pair and the segment. The batch
//! of positions: `Path::position_at`'s, likewise.

use std::num::NonZeroUsize;

use ballcollide::batch::{
    PathPairs, PathRows, PerPair, Threads, path_collision_times, path_positions_at,
};
use ballcollide::collision::path_collision_time_unscreened;
use ballcollide::path::Path;
use ballcollide::simd::{test_levels, with_level};
use ballcollide::{CollisionOptions, path_collision_time};

use crate::support::path_rows::RowSpec;
use crate::support::rng;
use rng::Rng;

/// `n` random paths of up to `k` segments in rows (padded with `+∞` starts), on a 2 m table.
struct Rows<const D: usize> {
    start: Vec<f64>,
    pos: Vec<[f64; D]>,
    vel: Vec<[f64; D]>,
    acc: Vec<[f64; D]>,
    k: usize,
}

impl<const D: usize> Rows<D> {
    fn random(rng: &mut Rng, n: usize, k: usize) -> Self {
        Self::drawn(
            RowSpec {
                segments: k,
                every_row_used: false,
                later_first_start: 1.0,
                first_start: [0.0, 1.0],
                length: [0.0, 2.0],
                empty: 0.0,
                pos: RowSpec::each_axis(-1.0, 1.0),
                continuous: false,
                vel: RowSpec::each_axis(-2.0, 2.0),
                acc: RowSpec::each_axis(-0.5, 0.5),
                last_at_rest: 0.0,
            },
            rng,
            n,
        )
    }

    /// `n` paths of exactly `k` segments (every row used, starts increasing), most ending at
    /// rest: the shapes the lanes take whole (a friction ball's, a pool ball's), in a box of
    /// `size` so that many pairs come close.
    fn rolling(rng: &mut Rng, n: usize, k: usize, size: f64) -> Self {
        Self::drawn(
            RowSpec {
                segments: k,
                every_row_used: true,
                later_first_start: 1.0,
                first_start: [0.0, 0.5],
                length: [0.05, 1.0],
                empty: 0.0,
                pos: RowSpec::each_axis(-0.5 * size, 0.5 * size),
                continuous: false,
                vel: RowSpec::each_axis(-2.0, 2.0),
                acc: RowSpec::each_axis(-1.0, 1.0),
                last_at_rest: 0.75,
            },
            rng,
            n,
        )
    }

    fn drawn(spec: RowSpec<D>, rng: &mut Rng, n: usize) -> Self {
        let (start, [pos, vel, acc]) = spec.draw(rng, n);
        Self {
            start,
            pos,
            vel,
            acc,
            k: spec.segments,
        }
    }

    fn side(&self) -> PathRows<'_, D> {
        PathRows {
            start: &self.start,
            pos: &self.pos,
            vel: &self.vel,
            acc: &self.acc,
            segments: self.k,
        }
    }

    fn path(&self, i: usize) -> Path<D> {
        let r = i * self.k..(i + 1) * self.k;
        Path::from_rows(
            &self.start[r.clone()],
            &self.pos[r.clone()],
            &self.vel[r.clone()],
            &self.acc[r],
        )
        .expect("valid rows")
    }
}

fn check_batch<const D: usize>(seed: u64) {
    let mut rng = Rng(seed);
    // In 3-D about 2 % of these pairs touch (about 76 of them; in 2-D about 13 %).
    let n = 4000;
    let (a, b) = (
        Rows::<D>::random(&mut rng, n, 4),
        Rows::<D>::random(&mut rng, n, 3),
    );
    let radii: Vec<f64> = (0..n).map(|_| 0.05 + 0.3 * rng.uniform(0.0, 1.0)).collect();
    let pairs = PathPairs {
        a: a.side(),
        b: b.side(),
        contact_distance: PerPair::Each(&radii),
        t_max: PerPair::All(f64::INFINITY),
    };
    let mut one = vec![0.0; n];
    let mut two = vec![0.0; n];
    path_collision_times(&pairs, &mut one, Threads::AtMost(NonZeroUsize::MIN)).unwrap();
    path_collision_times(&pairs, &mut two, Threads::All).unwrap();
    let mut hits = 0;
    for i in 0..n {
        let single = path_collision_time(&a.path(i), &b.path(i), radii[i], &Default::default())
            .unwrap()
            .unwrap_or(f64::INFINITY);
        assert_eq!(one[i].to_bits(), single.to_bits(), "pair {i}");
        assert_eq!(two[i].to_bits(), single.to_bits(), "pair {i}");
        hits += single.is_finite() as usize;
    }
    assert!(hits > n / 100, "{hits} hits: the test needs contacts");
    // A broadcast against every B.
    let first = PathRows {
        start: &a.start[..a.k],
        pos: &a.pos[..a.k],
        vel: &a.vel[..a.k],
        acc: &a.acc[..a.k],
        segments: a.k,
    };
    let broadcast = PathPairs { a: first, ..pairs };
    path_collision_times(&broadcast, &mut one, Threads::All).unwrap();
    let a0 = a.path(0);
    for (i, &t) in one.iter().enumerate().step_by(7) {
        let options = CollisionOptions::default();
        let single = path_collision_time(&a0, &b.path(i), radii[i], &options).unwrap();
        assert_eq!(
            t.to_bits(),
            single.unwrap_or(f64::INFINITY).to_bits(),
            "pair {i}"
        );
    }
}

/// Runs `check` at every SIMD level this CPU has (`BALLCOLLIDE_REQUIRE_SIMD=avx512,avx2`
/// makes a missing level fail), naming them.
fn at_every_level(what: &str, check: impl Fn()) {
    let levels = test_levels();
    for &level in &levels {
        with_level(level, &check);
    }
    eprintln!("{what}: the single query's bits at every level of {levels:?}");
}

#[test]
fn the_batch_is_the_single_query_bit_for_bit_in_2d() {
    at_every_level("2-D paths", || check_batch::<2>(17));
}

#[test]
fn the_batch_is_the_single_query_bit_for_bit_in_3d() {
    at_every_level("3-D paths", || check_batch::<3>(18));
}

/// Rows of `k` segments on both sides, every row used: what the lanes screen (whole
/// paths, then every window at once) before the pairs left are searched without the screens
/// the lanes ran. The answers must be the single query's (with every screen), bit for bit.
fn check_lane_shaped<const D: usize>(seed: u64, k: usize) {
    let mut rng = Rng(seed);
    let n = 4000;
    let (a, b) = (
        Rows::<D>::rolling(&mut rng, n, k, 1.5),
        Rows::<D>::rolling(&mut rng, n, k, 1.5),
    );
    let radii: Vec<f64> = (0..n).map(|_| 0.05 + 0.3 * rng.uniform(0.0, 1.0)).collect();
    let pairs = PathPairs {
        a: a.side(),
        b: b.side(),
        contact_distance: PerPair::Each(&radii),
        t_max: PerPair::All(f64::INFINITY),
    };
    let mut out = vec![0.0; n];
    path_collision_times(&pairs, &mut out, Threads::AtMost(NonZeroUsize::MIN)).unwrap();
    let options = CollisionOptions::default();
    let mut hits = 0;
    for i in 0..n {
        let (pa, pb) = (a.path(i), b.path(i));
        let single = path_collision_time(&pa, &pb, radii[i], &options).unwrap();
        let bare = path_collision_time_unscreened(&pa, &pb, radii[i], &options).unwrap();
        let single = single.unwrap_or(f64::INFINITY);
        assert_eq!(out[i].to_bits(), single.to_bits(), "pair {i}");
        assert_eq!(
            bare.unwrap_or(f64::INFINITY).to_bits(),
            single.to_bits(),
            "pair {i}"
        );
        hits += single.is_finite() as usize;
    }
    // Both answers often (else the test could not fail either way).
    assert!(hits > n / 50 && hits < n * 19 / 20, "{hits} hits of {n}");
}

#[test]
fn rows_the_lanes_take_get_the_single_query_bit_for_bit() {
    at_every_level("rows the lanes take", || {
        for (k, seed) in [(2, 41), (3, 42)] {
            check_lane_shaped::<2>(seed, k);
            check_lane_shaped::<3>(seed + 10, k);
        }
    });
}

#[test]
fn errors_name_the_argument_the_pair_and_the_segment() {
    let mut rng = Rng(5);
    let (a, mut b) = (
        Rows::<2>::random(&mut rng, 10, 3),
        Rows::<2>::random(&mut rng, 10, 3),
    );
    let mut out = [0.0; 10];
    let run = |b: &Rows<2>, out: &mut [f64]| {
        let pairs = PathPairs {
            a: a.side(),
            b: b.side(),
            contact_distance: PerPair::All(0.1),
            t_max: PerPair::All(f64::INFINITY),
        };
        path_collision_times(&pairs, out, Threads::All)
            .unwrap_err()
            .to_string()
    };
    b.start[7 * 3] = 5.0;
    b.start[7 * 3 + 1] = 4.0;
    b.start[7 * 3 + 2] = 6.0;
    assert_eq!(
        run(&b, &mut out),
        "start_b[7, 1]: starts must not decrease, got 4 after 5"
    );
    b.start[7 * 3 + 1] = 5.5;
    b.vel[4 * 3][1] = f64::NAN;
    b.start[4 * 3] = 0.0;
    assert_eq!(run(&b, &mut out), "vel_b[4, 0]: must be finite, got NaN");
    // A padding row's values are not read; a first start of +inf is no path.
    b.vel[4 * 3] = [0.0; 2];
    b.start[2 * 3..2 * 3 + 3].fill(f64::INFINITY);
    assert_eq!(run(&b, &mut out), "start_b[2, 0]: must be finite, got inf");
    let short = PathPairs {
        a: a.side(),
        b: PathRows {
            start: &b.start[..27],
            ..b.side()
        },
        contact_distance: PerPair::All(0.1),
        t_max: PerPair::All(f64::INFINITY),
    };
    let err = path_collision_times(&short, &mut out, Threads::All).unwrap_err();
    assert_eq!(err.argument(), "pos_b");
}

fn check_positions<const D: usize>(seed: u64) {
    let mut rng = Rng(seed);
    // In 3-D about 2 % of these pairs touch (about 76 of them; in 2-D about 13 %).
    let n = 4000;
    let paths = Rows::<D>::random(&mut rng, n, 4);
    let times: Vec<f64> = (0..n).map(|_| rng.uniform(-1.0, 8.0)).collect();
    let mut one = vec![[0.0; D]; n];
    let mut all = vec![[0.0; D]; n];
    let side = paths.side();
    let t = PerPair::Each(&times);
    path_positions_at(&side, t, &mut one, Threads::AtMost(NonZeroUsize::MIN)).unwrap();
    path_positions_at(&side, t, &mut all, Threads::All).unwrap();
    for i in 0..n {
        let want: [f64; D] = paths.path(i).position_at(times[i]).into();
        assert_eq!(one[i].map(f64::to_bits), want.map(f64::to_bits), "path {i}");
        assert_eq!(all[i].map(f64::to_bits), want.map(f64::to_bits), "path {i}");
    }
    // One path at every time.
    let first = PathRows {
        start: &paths.start[..paths.k],
        pos: &paths.pos[..paths.k],
        vel: &paths.vel[..paths.k],
        acc: &paths.acc[..paths.k],
        segments: paths.k,
    };
    path_positions_at(&first, t, &mut all, Threads::All).unwrap();
    let path = paths.path(0);
    for (i, x) in all.iter().enumerate() {
        let want: [f64; D] = path.position_at(times[i]).into();
        assert_eq!(x.map(f64::to_bits), want.map(f64::to_bits), "time {i}");
    }
}

#[test]
fn the_batch_of_positions_is_the_paths_bit_for_bit() {
    check_positions::<2>(19);
    check_positions::<3>(20);
}

#[test]
fn position_errors_name_the_argument_the_path_and_the_segment() {
    let mut rng = Rng(6);
    let mut paths = Rows::<3>::random(&mut rng, 10, 3);
    let mut out = [[0.0; 3]; 10];
    paths.start[5 * 3] = 0.0;
    paths.acc[5 * 3][2] = f64::INFINITY;
    let err = path_positions_at(&paths.side(), PerPair::All(1.0), &mut out, Threads::All);
    assert_eq!(
        err.unwrap_err().to_string(),
        "acc[5, 0]: must be finite, got inf"
    );
    paths.acc[5 * 3][2] = 0.0;
    let mut times = [1.0; 10];
    times[8] = f64::NAN;
    let err = path_positions_at(&paths.side(), PerPair::Each(&times), &mut out, Threads::All);
    assert_eq!(
        err.unwrap_err().to_string(),
        "t[8]: must be finite, got NaN"
    );
    let err = path_positions_at(
        &paths.side(),
        PerPair::All(1.0),
        &mut out[..4],
        Threads::All,
    );
    assert_eq!(
        err.unwrap_err().to_string(),
        "start: has 10 rows, expected 4"
    );
}
