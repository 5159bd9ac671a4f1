//! Many pairs of paths at once: [`path_collision_times`] over rows, in parallel, into a
//! caller's buffer; and where many paths are at given times ([`path_positions_at`]).
//!
//! Each side of a batch is `N` paths of `K` segments in rows ([`PathRows`]: the layout of the
//! `(N, K)` and `(N, K, D)` arrays numpy hands over), or a single path broadcast against every
//! pair (`N = 1`: "ball `i` against all the others", what an event loop asks after each
//! event). Paths with fewer than `K` segments are padded with rows whose start is `+∞`.
//! Every pair goes through the same validation and the same search as
//! [`path_collision_time`](crate::path_collision_time), so batch and single answers are
//! identical, and so are the answers for any number of threads.
//!
//! At the SIMD levels whose vectors hold four or more lanes (AVX2, AVX-512:
//! [`Simd::RUNS_LANE_STAGES`], [`simd`](crate::simd)), rows of 2 and 3 segments (a friction
//! ball's, a pool ball's) first go through the path bounds and the chord normals eight pairs at a time
//! ([`path_lanes`](super::path_lanes)), then the window screens on every window of the pairs
//! left ([`window_lanes`](super::window_lanes)): the same proofs, to the bit, on the pairs they
//! can take whole, at a fraction of the cost. The pairs they take and do not settle are held
//! until eight are waiting, and their first windows settled at once on the first open eighth
//! ([`first_window_lanes`](super::first_window_lanes)); what is left goes on one by one.

use super::block_queue::BlockQueue;
use super::first_window_lanes::eighth_contacts;
use super::path_lanes::settled;
use super::{PerPair, Threads, check_len, run_chunks};
use crate::collision::path_bounds::PathBounds;
use crate::collision::path_contact::{Prior, first_contact_bounded};
use crate::collision::stage_counts::{Stage, count};
use crate::error::{InputError, InputErrorKind, check_contact_distance, check_horizon, finite};
use crate::path::{Names, Segment, locate, segments_from_rows};
use crate::simd::{Kernel, LANES, Simd, dispatch};

/// One side of a batch of path pairs: `N` paths of `segments` rows each, row `k` of path `i`
/// at `i·segments + k` of every slice.
///
/// ```
/// use ballcollide::batch::PathRows;
/// let start = [0.0, 1.0, 0.0, f64::INFINITY]; // two paths: 2 segments, then 1 (padded)
/// let rows = [[0.0, 0.0]; 4];
/// let paths = PathRows { start: &start, pos: &rows, vel: &rows, acc: &rows, segments: 2 };
/// assert_eq!(paths.len(), 2);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct PathRows<'a, const D: usize> {
    /// Segment starts, `N·K`.
    pub start: &'a [f64],
    /// Segment positions at their start, `N·K` rows.
    pub pos: &'a [[f64; D]],
    /// Segment velocities at their start, `N·K` rows.
    pub vel: &'a [[f64; D]],
    /// Segment accelerations, `N·K` rows.
    pub acc: &'a [[f64; D]],
    /// `K`: rows per path (≥ 1).
    pub segments: usize,
}

impl<const D: usize> PathRows<'_, D> {
    /// The number of paths `N` (0 when `segments` is 0).
    pub fn len(&self) -> usize {
        self.start.len().checked_div(self.segments).unwrap_or(0)
    }

    /// Whether there is no path.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Path `i`'s rows: start, position, velocity, acceleration; `K` of them if `K > 0` (it
    /// must then be `segments`: a count the compiler knows unrolls the loops over them).
    #[inline(always)]
    pub(super) fn rows<const K: usize>(&self, i: usize) -> ([&[f64]; 1], [&[[f64; D]]; 3]) {
        let k = if K > 0 { K } else { self.segments };
        let range = i * k..(i + 1) * k;
        (
            [&self.start[range.clone()]],
            [
                &self.pos[range.clone()],
                &self.vel[range.clone()],
                &self.acc[range],
            ],
        )
    }
}

/// The inputs of a batch of collision queries on paths: pair `i` is path `i` of `a` (or its
/// only path) against path `i` of `b` (or its only path), at contact distance `contact_distance`,
/// with horizon `t_max` (`∞` for none).
#[derive(Clone, Copy, Debug)]
pub struct PathPairs<'a, const D: usize> {
    /// The A paths (1 or `N`).
    pub a: PathRows<'a, D>,
    /// The B paths (1 or `N`).
    pub b: PathRows<'a, D>,
    /// Contact distance (sum of the two radii, > 0).
    pub contact_distance: PerPair<'a>,
    /// Horizon: a collision at `t ≥ t_max` is reported as none.
    pub t_max: PerPair<'a>,
}

/// The argument names of side A's and side B's rows in errors.
const NAMES: [Names; 2] = [
    Names {
        segments: "start_a",
        start: "start_a",
        position: "pos_a",
        velocity: "vel_a",
        acceleration: "acc_a",
    },
    Names {
        segments: "start_b",
        start: "start_b",
        position: "pos_b",
        velocity: "vel_b",
        acceleration: "acc_b",
    },
];

/// The first contact time of every pair of paths in `pairs` (absolute, as the starts are),
/// written to `out` (`∞` where there is none).
///
/// # Errors
/// The first invalid pair's error (lowest index), naming the argument and, for a path's
/// values, the pair and the segment (``start_b[7, 2]: starts must not decrease, got 1 after
/// 2``); a side's paths must number 1 or `out.len()`, and its rows `N·K` in every slice.
/// Shapes and shared values come first: a contact distance or horizon shared by all pairs, and a
/// broadcast path (reported at pair 0, even in an empty batch). On error, `out` holds
/// unspecified values.
///
/// ```
/// use ballcollide::batch::{PathPairs, PathRows, PerPair, Threads, path_collision_times};
///
/// // One ball rolling along x at 1 m/s against two at rest (broadcast A).
/// let a = PathRows { start: &[0.0], pos: &[[0.0, 0.0]], vel: &[[1.0, 0.0]], acc: &[[0.0, 0.0]], segments: 1 };
/// let rest = [[0.0, 0.0]; 2];
/// let b = PathRows { start: &[0.0, 0.0], pos: &[[2.0, 0.0], [2.0, 5.0]], vel: &rest, acc: &rest, segments: 1 };
/// let (contact_distance, t_max) = (PerPair::All(1.0), PerPair::All(f64::INFINITY));
/// let pairs = PathPairs { a, b, contact_distance, t_max };
/// let mut out = [0.0; 2];
/// path_collision_times(&pairs, &mut out, Threads::All)?;
/// assert_eq!(out, [1.0, f64::INFINITY]);
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn path_collision_times<const D: usize>(
    pairs: &PathPairs<'_, D>,
    out: &mut [f64],
    threads: Threads,
) -> Result<(), InputError> {
    let shared = check_path_pairs(pairs, out.len())?;
    let level = crate::simd::current();
    run_chunks(out, threads, |offset, chunk| {
        dispatch(
            level,
            PathChunk {
                pairs,
                offset,
                chunk,
                shared: &shared,
            },
        )
    })
}

/// The answers of pairs `offset..` into `chunk`: the batch's work on one chunk, at a SIMD
/// level ([`dispatch`]).
struct PathChunk<'p, 'c, const D: usize> {
    pairs: &'p PathPairs<'p, D>,
    offset: usize,
    chunk: &'c mut [f64],
    shared: &'p SharedPaths<D>,
}

impl<const D: usize> Kernel for PathChunk<'_, '_, D> {
    type Output = Result<(), InputError>;

    #[inline(always)]
    fn run<S: Simd>(self, s: S) -> Self::Output {
        path_chunk(s, self.pairs, self.offset, self.chunk, self.shared)
    }
}

/// Every pair of the chunk in turn, with one buffer per side reused for every pair, and the
/// lanes of `s` on blocks of pairs.
#[inline(always)]
fn path_chunk<S: Simd, const D: usize>(
    s: S,
    pairs: &PathPairs<'_, D>,
    offset: usize,
    chunk: &mut [f64],
    shared: &SharedPaths<D>,
) -> Result<(), InputError> {
    // The common row counts, a friction ball's (move, rest) and a pool ball's (slide, roll,
    // rest), with the loops over the rows unrolled: 6 % less time per pool-table pair.
    match (pairs.a.segments, pairs.b.segments) {
        (2, 2) => path_pairs_in_turn::<S, D, 2>(s, pairs, offset, chunk, shared),
        (3, 3) => path_pairs_in_turn::<S, D, 3>(s, pairs, offset, chunk, shared),
        _ => path_pairs_in_turn::<S, D, 0>(s, pairs, offset, chunk, shared),
    }
}

/// [`path_chunk`] for rows of `K` segments on both sides (`K = 0`: any number); for
/// `K > 0`, blocks of pairs first go through the lane-wise screens
/// ([`path_lanes`](super::path_lanes)), where neither side is broadcast.
#[inline(always)]
fn path_pairs_in_turn<S: Simd, const D: usize, const K: usize>(
    s: S,
    pairs: &PathPairs<'_, D>,
    offset: usize,
    chunk: &mut [f64],
    shared: &SharedPaths<D>,
) -> Result<(), InputError> {
    let mut buffers = [PathBuffer::new(), PathBuffer::new()];
    let lanes = S::RUNS_LANE_STAGES && K > 0 && shared[0].is_none() && shared[1].is_none();
    // The pairs the lanes took and left, for the first-window lanes.
    let mut held = BlockQueue::<usize>::default();
    // Block by block: the pairs the lanes settle all at once (most pairs: they then cost no
    // work of their own here); those they take and leave held for the first-window lanes,
    // which run on full blocks of them; then the others, and those the first-window lanes
    // leave, walked one by one (so that an error is the lowest pair's: settled and held
    // pairs are valid). After the last block, the pairs still held. One call of the pair's
    // search in the loop (two would be inlined twice, and the compiler then does worse with
    // both).
    let blocks = chunk.len().div_ceil(LANES);
    for block in 0..=blocks {
        // The pairs of this step to walk one by one, with what the lanes found of them.
        let mut walk = BlockQueue::<(usize, Prior)>::default();
        if block == blocks {
            for &k in held.items() {
                walk.push((k, Prior::LanesLeft));
            }
        } else {
            let here = block * LANES;
            let len = LANES.min(chunk.len() - here);
            let (settled, taken) = if lanes && len == LANES {
                // The sides were checked to hold a path per pair in rows of `K`, the per-pair
                // values to have one per pair, and the block is in range.
                let lanes = settled::<S, D, K>(s, pairs, offset + here);
                count_settled(lanes.bounds, lanes.chords, lanes.windows);
                let settled = lanes.bounds | lanes.chords | lanes.windows;
                (u32::from(settled), u32::from(lanes.taken))
            } else {
                (0, 0)
            };
            for (l, slot) in chunk[here..here + len].iter_mut().enumerate() {
                if settled >> l & 1 != 0 {
                    *slot = f64::INFINITY;
                }
            }
            let mut left = !settled & ((1u32 << len) - 1);
            while left != 0 {
                let l = left.trailing_zeros() as usize;
                left &= left - 1;
                if taken >> l & 1 != 0 {
                    held.push(here + l);
                } else {
                    walk.push((here + l, Prior::Nothing));
                }
            }
            if let Some(block) = held.take_block() {
                // (Only pairs the lanes took are held.)
                let (contacts, free) = eighth_contacts::<S, D, K>(s, pairs, offset, &block);
                for (l, (&k, &contact)) in block.iter().zip(&contacts).enumerate() {
                    if contact.is_nan() {
                        let prior = if free >> l & 1 != 0 {
                            Prior::FirstWindowScreenedOut
                        } else {
                            Prior::LanesLeft
                        };
                        walk.push((k, prior));
                    } else {
                        count_first_window_contact();
                        chunk[k] = contact;
                    }
                }
            }
        }
        for &(k, prior) in walk.items() {
            chunk[k] = pair_time::<D, K>(pairs, offset + k, shared, &mut buffers, prior)?;
        }
    }
    Ok(())
}

/// Counts a pair answered by the first-window lanes as its walk would have counted it.
#[inline(always)]
fn count_first_window_contact() {
    for stage in [
        Stage::PathPair,
        Stage::Window,
        Stage::WindowSearched,
        Stage::WindowEighth,
        Stage::Contact,
    ] {
        count(stage);
    }
}

/// Counts the pairs of a block that the lanes settled, by their stage (nothing without the
/// `stage-counts` feature).
#[inline(always)]
fn count_settled(bounds: u8, chords: u8, windows: u8) {
    for l in 0..LANES {
        if (bounds | chords | windows) >> l & 1 != 0 {
            count(Stage::PathPair);
            count(if bounds >> l & 1 != 0 {
                Stage::BoundsApart
            } else if chords >> l & 1 != 0 {
                Stage::ChordsApart
            } else {
                Stage::WindowsApart
            });
        }
    }
}

/// The broadcast paths of a batch of path pairs (A's, B's), read and checked once, with their
/// bounds: `Some` for a side that holds one path.
pub(crate) type SharedPaths<const D: usize> = [Option<(Vec<Segment<D>>, PathBounds<D>)>; 2];

/// The checks of [`path_collision_times`] that need no pair: each side's rows, its number of
/// paths 1 or `n`, `contact_distance` and `t_max` of length `n` if per pair, shared values valid (a
/// broadcast path among them). The
/// Python binding runs them before it looks at a caller's `out` array.
pub(crate) fn check_path_pairs<const D: usize>(
    pairs: &PathPairs<'_, D>,
    n: usize,
) -> Result<SharedPaths<D>, InputError> {
    check_side(&pairs.a, &NAMES[0], n)?;
    check_side(&pairs.b, &NAMES[1], n)?;
    pairs.contact_distance.check_len("contact_distance", n)?;
    pairs.t_max.check_len("t_max", n)?;
    pairs
        .contact_distance
        .check_shared("contact_distance", check_contact_distance)?;
    pairs.t_max.check_shared("t_max", check_horizon)?;
    // A broadcast path is a shared value: checked here, even in an empty batch.
    let bounded = |path: Option<Vec<Segment<D>>>| {
        path.map(|segments| {
            let bounds = PathBounds::of(&segments);
            (segments, bounds)
        })
    };
    Ok([
        bounded(shared_path(&pairs.a, &NAMES[0])?),
        bounded(shared_path(&pairs.b, &NAMES[1])?),
    ])
}

/// A side's only path, read and checked (errors at pair 0), if it holds one path.
pub(super) fn shared_path<const D: usize>(
    side: &PathRows<'_, D>,
    names: &Names,
) -> Result<Option<Vec<Segment<D>>>, InputError> {
    if side.len() != 1 {
        return Ok(None);
    }
    let mut buffer = Vec::new();
    let segments = read_path::<D, 0>(side, 0, names, &mut buffer).map_err(|e| e.in_pair(0))?;
    Ok(Some(segments.to_vec()))
}

/// The argument names of [`path_positions_at`]'s rows in errors.
pub(super) const NAMES_ONE: Names = Names {
    segments: "start",
    start: "start",
    position: "pos",
    velocity: "vel",
    acceleration: "acc",
};

/// The centre of path `i` of `paths` (or of its only path) at time `t[i]`, written to `out[i]`:
/// what [`Path::position_at`](crate::Path::position_at) gives for that path; times before a
/// path's first start give its first position.
///
/// # Errors
/// The first invalid item's error (lowest index), naming the argument, and for a path's
/// values the item and the segment (``vel[3, 1]: must be finite, got NaN``): a NaN or
/// infinite time; the paths must number 1 or `out.len()`, `t` have `out.len()` values if per
/// item. On error, `out` holds unspecified values.
///
/// ```
/// use ballcollide::batch::{PathRows, PerPair, Threads, path_positions_at};
///
/// // One path at three times (broadcast): 1 m/s along x, then at rest from t = 2 s.
/// let path = PathRows {
///     start: &[0.0, 2.0],
///     pos: &[[0.0, 0.0], [2.0, 0.0]],
///     vel: &[[1.0, 0.0], [0.0, 0.0]],
///     acc: &[[0.0, 0.0], [0.0, 0.0]],
///     segments: 2,
/// };
/// let mut out = [[0.0; 2]; 3];
/// path_positions_at(&path, PerPair::Each(&[-1.0, 0.5, 9.0]), &mut out, Threads::All)?;
/// assert_eq!(out, [[0.0, 0.0], [0.5, 0.0], [2.0, 0.0]]);
///
/// let err = path_positions_at(&path, PerPair::All(f64::NAN), &mut out, Threads::All);
/// assert_eq!(err.unwrap_err().to_string(), "t: must be finite, got NaN");
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn path_positions_at<const D: usize>(
    paths: &PathRows<'_, D>,
    t: PerPair<'_>,
    out: &mut [[f64; D]],
    threads: Threads,
) -> Result<(), InputError> {
    let shared = check_path_positions(paths, t, out.len())?;
    run_chunks(out, threads, |offset, chunk| {
        let mut buffer = Vec::new();
        for (k, slot) in chunk.iter_mut().enumerate() {
            let i = offset + k;
            let segments = match &shared {
                Some(path) => path.as_slice(),
                None => read_path::<D, 0>(paths, i, &NAMES_ONE, &mut buffer)
                    .map_err(|e| e.in_pair(i))?,
            };
            let time = finite("t", t.get(i)).map_err(|e| e.at(i))?;
            let (segment, time) = locate(segments, time);
            *slot = segment.position_at(time).into();
        }
        Ok(())
    })
}

/// The checks of [`path_positions_at`] that need no item: the rows, 1 or `n` paths, `t` of
/// length `n` if per item and finite if shared. The Python binding runs them before it looks
/// at a caller's `out` array.
pub(crate) fn check_path_positions<const D: usize>(
    paths: &PathRows<'_, D>,
    t: PerPair<'_>,
    n: usize,
) -> Result<Option<Vec<Segment<D>>>, InputError> {
    check_side(paths, &NAMES_ONE, n)?;
    t.check_len("t", n)?;
    t.check_shared("t", finite)?;
    // A broadcast path is a shared value: checked here, even with no time to answer.
    shared_path(paths, &NAMES_ONE)
}

/// One side's path of the pair at hand and its bounds, read from the rows: one per side and
/// thread, overwritten in place from pair to pair.
struct PathBuffer<const D: usize> {
    segments: Vec<Segment<D>>,
    bounds: PathBounds<D>,
}

impl<const D: usize> PathBuffer<D> {
    fn new() -> Self {
        Self {
            segments: Vec::new(),
            bounds: PathBounds::of(&[]),
        }
    }

    /// Path `i` of `side`, checked, and its bounds (errors at pair `i`).
    #[inline(always)]
    fn read<const K: usize>(
        &mut self,
        side: &PathRows<'_, D>,
        i: usize,
        names: &Names,
    ) -> Result<(&[Segment<D>], &PathBounds<D>), InputError> {
        let path =
            read_path::<D, K>(side, i, names, &mut self.segments).map_err(|e| e.in_pair(i))?;
        self.bounds.set_to(path);
        Ok((path, &self.bounds))
    }
}

/// Pair `i`'s answer: its paths are the shared ones where a side is broadcast, else read
/// into that side's buffer; `prior`, what the lanes found of it.
#[inline(always)]
fn pair_time<const D: usize, const K: usize>(
    pairs: &PathPairs<'_, D>,
    i: usize,
    shared: &SharedPaths<D>,
    [buffer_a, buffer_b]: &mut [PathBuffer<D>; 2],
    prior: Prior,
) -> Result<f64, InputError> {
    let a = match &shared[0] {
        Some((path, bounds)) => (path.as_slice(), bounds),
        None => buffer_a.read::<K>(&pairs.a, i, &NAMES[0])?,
    };
    let b = match &shared[1] {
        Some((path, bounds)) => (path.as_slice(), bounds),
        None => buffer_b.read::<K>(&pairs.b, i, &NAMES[1])?,
    };
    let radius = check_contact_distance("contact_distance", pairs.contact_distance.get(i))
        .map_err(|e| e.at(i))?;
    let t_max = check_horizon("t_max", pairs.t_max.get(i)).map_err(|e| e.at(i))?;
    let contact = first_contact_bounded(a, b, [radius, 0.0], t_max, prior);
    Ok(contact.unwrap_or(f64::INFINITY))
}

/// Path `i` of `side`, checked, read into `buffer` (reused from path to path); its segments
/// (its errors at the segment's index).
#[inline(always)]
pub(super) fn read_path<'b, const D: usize, const K: usize>(
    side: &PathRows<'_, D>,
    i: usize,
    names: &Names,
    buffer: &'b mut Vec<Segment<D>>,
) -> Result<&'b [Segment<D>], InputError> {
    let (start, values) = side.rows::<K>(i);
    let used = segments_from_rows(start, values, names, buffer)?;
    Ok(&buffer[..used])
}

/// Checks a side's shape: `segments ≥ 1`, every slice of `N·K` rows, `N` either 1 or `n`.
pub(super) fn check_side<const D: usize>(
    side: &PathRows<'_, D>,
    names: &Names,
    n: usize,
) -> Result<(), InputError> {
    if side.segments == 0 {
        return Err(InputError::new(names.segments, InputErrorKind::NoSegments));
    }
    let rows = side.start.len();
    check_len(names.position, side.pos.len(), rows)?;
    check_len(names.velocity, side.vel.len(), rows)?;
    check_len(names.acceleration, side.acc.len(), rows)?;
    if !rows.is_multiple_of(side.segments) {
        return Err(InputError::new(
            names.start,
            InputErrorKind::LengthMismatch {
                expected: rows.div_ceil(side.segments) * side.segments,
                found: rows,
            },
        ));
    }
    match side.len() {
        1 => Ok(()),
        paths => check_len(names.start, paths, n),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simd::Level;
    use crate::test_path_rows::RowSpec;
    use crate::test_rng::Rng;

    /// `n` random 2-D paths of up to `k` segments in rows of `k` (padded with `+∞` starts):
    /// positions on a table, speeds and accelerations of a rolling or sliding ball, in random
    /// directions, segments of random lengths (sometimes empty), the last often at rest.
    fn random_rows(n: usize, seed: u64, k: usize) -> (Vec<f64>, [Vec<[f64; 2]>; 3]) {
        RowSpec::<2> {
            segments: k,
            every_row_used: false,
            later_first_start: 0.0,
            first_start: [0.0, 0.0],
            length: [0.0, 2.0],
            empty: 0.125,
            pos: [[0.0, 2.5], [0.0, 1.3]],
            continuous: false,
            vel: RowSpec::each_axis(-3.0, 3.0),
            acc: RowSpec::each_axis(-2.0, 2.0),
            last_at_rest: 0.5,
        }
        .draw(&mut Rng(seed), n)
    }

    /// The chunk at every level the CPU has gives the portable copy's bits, which are the
    /// single query's, in rows of 2 and 3 (the lanes' shapes) and of 4 (no lanes).
    fn every_level_agrees_with_the_portable_code_bit_for_bit(k: usize) {
        let n = 4_000;
        let (start_a, [pos_a, vel_a, acc_a]) = random_rows(n, 1, k);
        let (start_b, [pos_b, vel_b, acc_b]) = random_rows(n, 2, k);
        let pairs = PathPairs {
            a: PathRows {
                start: &start_a,
                pos: &pos_a,
                vel: &vel_a,
                acc: &acc_a,
                segments: k,
            },
            b: PathRows {
                start: &start_b,
                pos: &pos_b,
                vel: &vel_b,
                acc: &acc_b,
                segments: k,
            },
            contact_distance: PerPair::All(0.3),
            t_max: PerPair::All(f64::INFINITY),
        };
        let shared = check_path_pairs(&pairs, n).expect("valid");
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        let mut portable = vec![0.0; n];
        let chunk = PathChunk {
            pairs: &pairs,
            offset: 0,
            chunk: &mut portable,
            shared: &shared,
        };
        assert_eq!(dispatch(Level::Portable, chunk), Ok(()));
        let hits = portable.iter().filter(|t| t.is_finite()).count();
        assert!(hits > 400, "{hits} hits: the set should exercise contacts");
        // The single query's bits, pair by pair.
        for i in (0..n).step_by(7) {
            let path = |s: &PathRows<'_, 2>| {
                let mut buffer = Vec::new();
                read_path::<2, 0>(s, i, &NAMES[0], &mut buffer)
                    .expect("valid")
                    .to_vec()
            };
            let single = first_path_contact_of(&path(&pairs.a), &path(&pairs.b), 0.3);
            assert_eq!(single.to_bits(), portable[i].to_bits(), "pair {i}");
        }
        for level in crate::simd::test_levels() {
            let mut copy = vec![0.0; n];
            let chunk = PathChunk {
                pairs: &pairs,
                offset: 0,
                chunk: &mut copy,
                shared: &shared,
            };
            assert_eq!(dispatch(level, chunk), Ok(()));
            assert_eq!(bits(&portable), bits(&copy), "{level}");
            eprintln!("path chunk in rows of {k} at {level}: the portable copy's bits");
        }
    }

    #[test]
    fn every_level_agrees_with_the_portable_code_bit_for_bit_in_rows_of_two() {
        every_level_agrees_with_the_portable_code_bit_for_bit(2);
    }

    #[test]
    fn every_level_agrees_with_the_portable_code_bit_for_bit_in_rows_of_three() {
        every_level_agrees_with_the_portable_code_bit_for_bit(3);
    }

    #[test]
    fn every_level_agrees_with_the_portable_code_bit_for_bit_in_rows_of_four() {
        every_level_agrees_with_the_portable_code_bit_for_bit(4);
    }

    /// The same paths in rows of `k` and padded to rows of `k + 3` (an extra `+∞` row or more).
    fn padded(rows: &(Vec<f64>, [Vec<[f64; 2]>; 3]), k: usize) -> (Vec<f64>, [Vec<[f64; 2]>; 3]) {
        let (start, values) = rows;
        let pad = |row: usize| row % (k + 3) >= k;
        let from = |row: usize| (row / (k + 3)) * k + row % (k + 3);
        let n = start.len() / k * (k + 3);
        let start = (0..n)
            .map(|r| {
                if pad(r) {
                    f64::INFINITY
                } else {
                    start[from(r)]
                }
            })
            .collect();
        let values = values.clone().map(|v| {
            (0..n)
                .map(|r| if pad(r) { [f64::NAN; 2] } else { v[from(r)] })
                .collect()
        });
        (start, values)
    }

    /// Rows of `k` segments.
    fn side_rows(rows: &(Vec<f64>, [Vec<[f64; 2]>; 3]), k: usize) -> PathRows<'_, 2> {
        let (start, [pos, vel, acc]) = rows;
        PathRows {
            start,
            pos,
            vel,
            acc,
            segments: k,
        }
    }

    #[test]
    fn rows_of_two_and_three_answer_and_fail_as_rows_of_any_count() {
        // Rows of 2 and 3 take copies of the search with their loops unrolled.
        let n = 2_000;
        for k in [2, 3] {
            let (a, b) = (random_rows(n, 3, k), random_rows(n, 4, k));
            let (wide_a, wide_b) = (padded(&a, k), padded(&b, k));
            let rows = side_rows;
            let pairs = |a, b| PathPairs {
                a,
                b,
                contact_distance: PerPair::All(0.3),
                t_max: PerPair::All(f64::INFINITY),
            };
            let run = |pairs: &PathPairs<'_, 2>| {
                let mut out = vec![0.0; n];
                path_collision_times(pairs, &mut out, Threads::All).map(|()| out)
            };
            let tight = run(&pairs(rows(&a, k), rows(&b, k))).expect("valid");
            let wide = run(&pairs(rows(&wide_a, k + 3), rows(&wide_b, k + 3))).expect("valid");
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&tight), bits(&wide), "rows of {k}");
            assert!(tight.iter().filter(|t| t.is_finite()).count() > 100);
            // A NaN in pair 7's last row of B: the same error, naming the same segment.
            let mut bad = b.clone();
            bad.1[1][7 * k + k - 1][0] = f64::NAN;
            // Every row of pair 7 used, whatever the draw.
            for (j, start) in bad.0[7 * k..8 * k].iter_mut().enumerate() {
                *start = j as f64;
            }
            let err = run(&pairs(rows(&a, k), rows(&bad, k))).unwrap_err();
            assert_eq!(
                err.to_string(),
                format!("vel_b[7, {}]: must be finite, got NaN", k - 1)
            );
        }
    }

    /// The scalar search on two checked paths, `∞` for none.
    fn first_path_contact_of(a: &[Segment<2>], b: &[Segment<2>], radius: f64) -> f64 {
        crate::collision::path_contact::first_contact_of_paths(
            a,
            b,
            [radius, 0.0],
            f64::INFINITY,
            true,
        )
        .unwrap_or(f64::INFINITY)
    }
}
