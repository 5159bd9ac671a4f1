//! The first windows of the pairs of paths that the lane-wise screens take and leave open,
//! settled eight at a time on their first open eighth, over [`Simd`].
//!
//! The pairs the screens ([`path_lanes`](super::path_lanes)) take whole and cannot prove
//! apart are held back (a [`BlockQueue`](super::block_queue::BlockQueue)) until a block of
//! them is full; each one's first window is then formed as the walk over windows would form
//! it ([`PathFirstWindow`]), and all eight are settled at once by the eighth entry on the
//! window's first open eighth ([`window_eighth`](super::eighth_lanes::window_eighth), the lane
//! twin of the walk's own). Most contacts of balls on a table come in the first window and are
//! plain there; the pairs answered so skip the walk; a pair whose first window is found free
//! of entries is walked from its second window on
//! ([`Prior::FirstWindowScreenedOut`](crate::collision::path_contact::Prior)); the others are
//! walked whole. The answers are the same bits as if the pairs had never been held.
//!
//! On the seed model written as paths (200,000 random table pairs), the lanes leave 9,720
//! pairs: 3,801 are answered here, 2,003 are walked from their second window, and 3,916 walked
//! whole.

use super::eighth_lanes::{
    GapLanes, UnitLanes, bounded_finite_length, largest as largest_of, window_eighth,
};
use super::paths::PathPairs;
use crate::collision::length_unit::largest;
use crate::path::Segment;
use crate::simd::{LANES, Mask, Simd};

/// A pair's first window as the walk of
/// [`first_contact_bounded`](crate::collision::path_contact::first_contact_bounded) forms it:
/// the segments of each path active at the pair's first time `start`, until the earlier of
/// their ends `end` (finite); `largest`, the largest magnitude among both paths' values, from
/// which with `radius` the pair's unit of length comes (as
/// [`PathBounds`](crate::collision::path_bounds::PathBounds) notes it for paths whose segments
/// are all non-empty); `t_max`, the horizon.
#[derive(Clone, Copy, Debug)]
struct PathFirstWindow<const D: usize> {
    a: Segment<D>,
    b: Segment<D>,
    start: f64,
    end: f64,
    largest: f64,
    radius: f64,
    t_max: f64,
}

/// What the first windows of pairs `offset + block[l]` settle: their answers where the eighth
/// entry finds an entry (its time, `∞` at or past the horizon), NaN for the others, and which
/// are free of entries (no entry, the gap positive at the window's end). The pairs must be
/// ones the lanes took whole: valid, rows of `K` all used, starts increasing strictly, radius
/// and horizon valid.
///
/// Only windows with a relative acceleration are settled here, so that no closed form comes
/// first in the walk; the screens the walk would run first are proofs that the balls are
/// apart, which an entry rules out, and which would screen the window out just the same; and
/// the balls are apart at the start: so these are the walk's findings, to the bit.
#[inline(always)]
pub(super) fn eighth_contacts<S: Simd, const D: usize, const K: usize>(
    s: S,
    pairs: &PathPairs<'_, D>,
    offset: usize,
    block: &[usize; LANES],
) -> ([f64; LANES], Mask) {
    let mut windows = [[0.0; LANES]; 5];
    let mut segments = [SegmentRows::<D>::default(); 2];
    for (l, &k) in block.iter().enumerate() {
        let w = first_window::<D, K>(pairs, offset + k);
        for (field, x) in windows
            .iter_mut()
            .zip([w.start, w.end, w.largest, w.radius, w.t_max])
        {
            field[l] = x;
        }
        for (rows, segment) in segments.iter_mut().zip([&w.a, &w.b]) {
            rows.start[l] = segment.start;
            for i in 0..D {
                rows.position[i][l] = segment.position[i];
                rows.velocity[i][l] = segment.velocity[i];
                rows.acceleration[i][l] = segment.acceleration[i];
            }
        }
    }
    let [start, end, most, radius, t_max] = [
        s.load(windows[0]),
        s.load(windows[1]),
        s.load(windows[2]),
        s.load(windows[3]),
        s.load(windows[4]),
    ];
    let unit = UnitLanes::of(s, largest_of(s, &[most, radius, s.zero()]));
    let radius = s.add(unit.apply(s, radius), unit.apply(s, s.zero()));
    let a = SegmentLanes::scaled(s, &segments[0], unit);
    let b = SegmentLanes::scaled(s, &segments[1], unit);
    let mut gap = GapLanes {
        offset: [s.zero(); D],
        velocity: [s.zero(); D],
        acceleration: [s.zero(); D],
        radius,
    };
    // `window_gap`: each segment evaluated in time since its own start.
    let (since_a, since_b) = (s.sub(start, a.start), s.sub(start, b.start));
    let mut accelerating = s.none();
    for i in 0..D {
        gap.offset[i] = s.sub(a.position_at(s, i, since_a), b.position_at(s, i, since_b));
        gap.velocity[i] = s.sub(a.velocity_at(s, i, since_a), b.velocity_at(s, i, since_b));
        gap.acceleration[i] = s.sub(a.acceleration[i], b.acceleration[i]);
        accelerating |= s.ne(gap.acceleration[i], s.zero());
    }
    let before = gap.apart_at_start(s);
    // (A first window of paths whose segments all end but the last ends.)
    let length = bounded_finite_length(s, s.sub(end, start));
    let eighth = window_eighth(s, &gap, length, before);
    let t = s.add(start, eighth.entry);
    let contact = s.blend(s.lt(t, t_max), s.splat(f64::INFINITY), t);
    let found = s.blend(eighth.found & accelerating, s.splat(f64::NAN), contact);
    (s.store(found), s.bits(eighth.screened_out & accelerating))
}

/// A segment of each lane's path, as rows of lanes.
#[derive(Clone, Copy)]
struct SegmentRows<const D: usize> {
    start: [f64; LANES],
    position: [[f64; LANES]; D],
    velocity: [[f64; LANES]; D],
    acceleration: [[f64; LANES]; D],
}

impl<const D: usize> Default for SegmentRows<D> {
    fn default() -> Self {
        Self {
            start: [0.0; LANES],
            position: [[0.0; LANES]; D],
            velocity: [[0.0; LANES]; D],
            acceleration: [[0.0; LANES]; D],
        }
    }
}

/// A segment of each lane's path, in the pair's unit of length.
struct SegmentLanes<S: Simd, const D: usize> {
    start: S::V,
    position: [S::V; D],
    velocity: [S::V; D],
    acceleration: [S::V; D],
}

impl<S: Simd, const D: usize> SegmentLanes<S, D> {
    /// The segment from its rows, in `unit`.
    #[inline(always)]
    fn scaled(s: S, rows: &SegmentRows<D>, unit: UnitLanes<S>) -> Self {
        let mut segment = Self {
            start: s.load(rows.start),
            position: [s.zero(); D],
            velocity: [s.zero(); D],
            acceleration: [s.zero(); D],
        };
        for i in 0..D {
            segment.position[i] = unit.apply(s, s.load(rows.position[i]));
            segment.velocity[i] = unit.apply(s, s.load(rows.velocity[i]));
            segment.acceleration[i] = unit.apply(s, s.load(rows.acceleration[i]));
        }
        segment
    }

    /// Component `i` of the position `since` its start (`Segment::position_at`).
    #[inline(always)]
    fn position_at(&self, s: S, i: usize, since: S::V) -> S::V {
        let half = s.mul(s.splat(0.5), since);
        let rate = s.add(self.velocity[i], s.mul(self.acceleration[i], half));
        s.add(self.position[i], s.mul(rate, since))
    }

    /// Component `i` of the velocity `since` its start (`Segment::velocity_at`).
    #[inline(always)]
    fn velocity_at(&self, s: S, i: usize, since: S::V) -> S::V {
        s.add(self.velocity[i], s.mul(self.acceleration[i], since))
    }
}

/// Pair `i`'s first window, as its walk forms it: at the later of the two first starts, the
/// segment of each path active then (the last whose start is not after it), until the earlier
/// of their ends.
#[inline(always)]
fn first_window<const D: usize, const K: usize>(
    pairs: &PathPairs<'_, D>,
    i: usize,
) -> PathFirstWindow<D> {
    let (start_a, rows_a) = pairs.a.rows::<K>(i);
    let (start_b, rows_b) = pairs.b.rows::<K>(i);
    // `+ 0.0`: as the walk's first time, +0 for a first start of −0.
    let start = start_a[0][0].max(start_b[0][0]) + 0.0;
    let (a, end_a) = active(start_a[0], rows_a, start);
    let (b, end_b) = active(start_b[0], rows_b, start);
    let mut most = 0.0;
    for rows in rows_a.iter().chain(&rows_b) {
        for row in rows.iter() {
            most = largest([most, largest(*row)]);
        }
    }
    PathFirstWindow {
        a,
        b,
        start,
        end: end_a.min(end_b),
        largest: most,
        radius: pairs.contact_distance.get(i),
        t_max: pairs.t_max.get(i),
    }
}

/// The segment of a path (its rows, starts increasing strictly) active at `t`, at or after
/// its first start, and when it ends.
#[inline(always)]
fn active<const D: usize>(
    starts: &[f64],
    [pos, vel, acc]: [&[[f64; D]]; 3],
    t: f64,
) -> (Segment<D>, f64) {
    let k = starts[1..].iter().filter(|&&s| s <= t).count();
    let segment = Segment {
        start: starts[k],
        position: pos[k].into(),
        velocity: vel[k].into(),
        acceleration: acc[k].into(),
    };
    (segment, starts.get(k + 1).copied().unwrap_or(f64::INFINITY))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::batch::{PathRows, PerPair};
    use crate::collision::path_bounds::PathBounds;
    use crate::collision::path_contact::{Prior, first_contact_bounded};
    use crate::path::Path2;
    use crate::simd::{Kernel, Level, dispatch, test_levels};
    use crate::test_path_rows::RowSpec;
    use crate::test_rng::Rng;
    use nalgebra::Vector2;

    /// `n` 2-D paths of `K` segments with starts increasing strictly (what the lanes take),
    /// near each other on a table: random accelerations, the last segment often at rest, a
    /// first start of 0 or a little later.
    fn rows<const K: usize>(rng: &mut Rng, n: usize) -> (Vec<f64>, [Vec<[f64; 2]>; 3]) {
        RowSpec::<2> {
            segments: K,
            every_row_used: true,
            later_first_start: 0.25,
            first_start: [0.0, 0.3],
            length: [0.01, 0.8],
            empty: 0.0,
            pos: RowSpec::each_axis(0.0, 0.6),
            continuous: true,
            vel: RowSpec::each_axis(-2.0, 2.0),
            acc: RowSpec::each_axis(-3.0, 3.0),
            last_at_rest: 0.5,
        }
        .draw(rng, n)
    }

    /// The first windows of a block of pairs, settled at a level.
    struct FirstWindows<'a, const K: usize> {
        pairs: &'a PathPairs<'a, 2>,
        block: &'a [usize; LANES],
    }

    impl<const K: usize> Kernel for FirstWindows<'_, K> {
        type Output = ([f64; LANES], Mask);

        #[inline(always)]
        fn run<S: Simd>(self, s: S) -> Self::Output {
            eighth_contacts::<S, 2, K>(s, self.pairs, 0, self.block)
        }
    }

    fn first_window_lanes_give_the_walks_bits<const K: usize>() {
        let mut rng = Rng(40 + K as u64);
        let n = 8 * 2_000;
        let (start_a, [pos_a, vel_a, acc_a]) = rows::<K>(&mut rng, n);
        let (start_b, [pos_b, vel_b, acc_b]) = rows::<K>(&mut rng, n);
        let side = |start, pos, vel, acc| PathRows {
            start,
            pos,
            vel,
            acc,
            segments: K,
        };
        let radius: Vec<f64> = (0..n).map(|_| rng.uniform(0.05, 0.3)).collect();
        let t_max: Vec<f64> = (0..n)
            .map(|_| {
                if rng.below(5) == 0 {
                    rng.uniform(0.0, 1.0)
                } else {
                    f64::INFINITY
                }
            })
            .collect();
        let pairs = PathPairs {
            a: side(&start_a, &pos_a, &vel_a, &acc_a),
            b: side(&start_b, &pos_b, &vel_b, &acc_b),
            contact_distance: PerPair::Each(&radius),
            t_max: PerPair::Each(&t_max),
        };
        let path = |side: &PathRows<'_, 2>, i: usize| {
            let (start, [pos, vel, acc]) = side.rows::<K>(i);
            let segments = (0..K).map(|k| {
                Segment::new(
                    start[0][k],
                    Vector2::from(pos[k]),
                    Vector2::from(vel[k]),
                    Vector2::from(acc[k]),
                )
            });
            Path2::new(segments.collect()).expect("valid rows")
        };
        // Every level this CPU has.
        let levels = test_levels();
        let (mut found, mut free) = (0, 0);
        for first in (0..n).step_by(LANES) {
            let block: [usize; LANES] = std::array::from_fn(|l| first + l);
            let settled = |level| {
                dispatch(
                    level,
                    FirstWindows::<K> {
                        pairs: &pairs,
                        block: &block,
                    },
                )
            };
            let (contacts, frees) = settled(Level::Portable);
            for &level in &levels {
                let (ours, our_frees) = settled(level);
                assert_eq!(
                    ours.map(f64::to_bits),
                    contacts.map(f64::to_bits),
                    "{level}"
                );
                assert_eq!(our_frees, frees, "{level}");
            }
            for (l, &contact) in contacts.iter().enumerate() {
                let is_free = frees >> l & 1 != 0;
                let i = first + l;
                let (a, b) = (path(&pairs.a, i), path(&pairs.b, i));
                let (a, b) = (a.segments(), b.segments());
                let bounds = (PathBounds::<2>::of(a), PathBounds::<2>::of(b));
                let walk = |prior| {
                    first_contact_bounded(
                        (a, &bounds.0),
                        (b, &bounds.1),
                        [radius[i], 0.0],
                        t_max[i],
                        prior,
                    )
                    .unwrap_or(f64::INFINITY)
                };
                let answer = walk(Prior::Nothing);
                assert!(!is_free || contact.is_nan(), "pair {i}: both");
                if !contact.is_nan() {
                    assert_eq!(contact.to_bits(), answer.to_bits(), "pair {i}");
                    found += 1;
                }
                if is_free {
                    let after = walk(Prior::FirstWindowScreenedOut);
                    assert_eq!(after.to_bits(), answer.to_bits(), "pair {i} (free)");
                    free += 1;
                }
            }
        }
        // Both findings, often (else the test could not fail).
        assert!(found > 1_000 && free > 1_000, "{found} found, {free} free");
    }

    #[test]
    fn first_window_lanes_give_the_walks_bits_in_rows_of_two() {
        first_window_lanes_give_the_walks_bits::<2>();
    }

    #[test]
    fn first_window_lanes_give_the_walks_bits_in_rows_of_three() {
        first_window_lanes_give_the_walks_bits::<3>();
    }
}
