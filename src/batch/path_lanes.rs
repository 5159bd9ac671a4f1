//! The whole-path screens ([`PathBounds::apart`], then [`apart_across_chords`]), eight pairs
//! at a time, written once over the operations of [`Simd`] and compiled at each level
//! ([`simd`](crate::simd): AVX-512, AVX2 + FMA, NEON, portable): a block of pairs of paths
//! read from their rows, every value checked and every path's box and chord spans formed in
//! the vector registers, one pair per lane, without a branch on the data ([`settled`]); then, for the pairs they leave, the window
//! screens on every window of the pair ([`window_lanes`](super::window_lanes)). The pairs they
//! settle (valid, proven apart) answer "none" at once; the others go on to the pair's own
//! search, which reads them again and reports any error.
//!
//! They are the two screens' proofs, computed the way [`PathBounds::set_to`],
//! [`PathBounds::screen_distance`] and [`apart_across_chords`] compute them: the same
//! operations in the same order on the same numbers, so that a lane is settled exactly when
//! the pair's own screens would settle it, and the batch's answers are the same bits with or
//! without them. They take the paths they can take whole: both sides with a path per pair and
//! `K` rows each, every row used with starts that increase strictly, every value finite, a
//! finite size, and no screen distance that underflow could touch; anything else is left to
//! the pair's own path (which settles it, or names its error).
//!
//! On a pool table three pairs in four are settled by the whole-path screens and one in five
//! by the windows, at about fifteen nanoseconds a pair instead of the sixty to eighty that
//! reading, checking and screening them one at a time costs (200 or more for the windows).
//!
//! [`PathBounds::apart`]: crate::collision::path_bounds::PathBounds
//! [`PathBounds::set_to`]: crate::collision::path_bounds::PathBounds
//! [`PathBounds::screen_distance`]: crate::collision::path_bounds::PathBounds
//! [`apart_across_chords`]: crate::collision::chord_normals

use super::PerPair;
use super::paths::{PathPairs, PathRows};
use super::window_lanes::{LaneSide, windows_apart};
use crate::collision::window_box::{MARGIN, NORMAL_FLOOR};
use crate::prefetch::prefetch;
use crate::simd::{LANES, MOST, Mask, Simd};

/// The pairs of a block that the lanes settle, by screen (bit `l` for the block's pair `l`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Settled {
    /// The path bounds are apart.
    pub(crate) bounds: Mask,
    /// The path bounds are not, the spans across a chord are.
    pub(crate) chords: Mask,
    /// Neither is, every window is proven apart ([`window_lanes`](super::window_lanes)).
    pub(crate) windows: Mask,
    /// Taken whole by the lanes (valid, every row used, a plain reach): where none of the
    /// above holds, the pair's own whole-path screens fail too.
    pub(crate) taken: Mask,
}

/// One side's rows of a block, a lane each: row `k`'s start and its position, velocity and
/// acceleration on each axis.
pub(super) struct LaneRows<S: Simd, const D: usize, const K: usize> {
    pub(super) s: [S::V; K],
    pub(super) p: [[S::V; D]; K],
    pub(super) v: [[S::V; D]; K],
    pub(super) a: [[S::V; D]; K],
}

/// One side's segment boxes of a block, a lane each: segment `k`'s least and greatest value
/// on each axis.
pub(super) struct LaneBoxes<S: Simd, const D: usize, const K: usize> {
    pub(super) lo: [[S::V; D]; K],
    pub(super) hi: [[S::V; D]; K],
}

/// One side's paths of a block, a lane each: which are taken (valid, every row used, starts
/// increasing strictly, finite size), and the box, size and spread [`PathBounds`] forms for
/// them.
///
/// [`PathBounds`]: crate::collision::path_bounds::PathBounds
struct LaneBounds<S: Simd, const D: usize, const K: usize> {
    taken: S::M,
    /// The lanes whose path ends at rest ([`rests_at_end`]).
    rests: S::M,
    lo: [S::V; D],
    hi: [S::V; D],
    size: S::V,
    spread: S::V,
    /// The box of each segment (`PathBounds`' segment boxes: a path of `K ≤ 3` rows keeps
    /// one for every segment).
    segments: LaneBoxes<S, D, K>,
}

/// Which of pairs `first..first + LANES` are settled: both paths taken, radius and horizon
/// valid, and the two paths' boxes farther apart on some axis than the reach, or else both
/// paths ending at rest and apart across a chord.
///
/// Written once over `s`'s operations, inlined into the batch's copy for its level.
///
/// # Panics
/// Unless both sides hold a path per pair in rows of `K ≥ 1` segments (`start` of `n·K`
/// values, `pos`, `vel`, `acc` of `n·K` rows, as
/// [`path_collision_times`](super::path_collision_times) checks them), per-pair `radius` and
/// `t_max` of `n` values, and `first + LANES ≤ n`.
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
pub(crate) fn settled<S: Simd, const D: usize, const K: usize>(
    s: S,
    pairs: &PathPairs<'_, D>,
    first: usize,
) -> Settled {
    let (rows_a, rows_b) = (
        lane_rows::<S, D, K>(s, &pairs.a, first),
        lane_rows::<S, D, K>(s, &pairs.b, first),
    );
    let (a, b) = (lane_bounds(s, &rows_a), lane_bounds(s, &rows_b));
    let radius = lanes_of(s, pairs.contact_distance, first);
    let t_max = lanes_of(s, pairs.t_max, first);
    let zero = s.zero();
    // `radius + MARGIN·(size_a + size_b + radius)`, as `PathBounds::screen_distance` forms it.
    let sizes = s.add(s.add(a.size, b.size), radius);
    let reach = s.add(radius, s.mul(s.splat(MARGIN), sizes));
    // Where underflow could count (`with_underflow` would grow the reach): not taken.
    let spread = s.add(a.spread, b.spread);
    let floor = s.mul(s.splat(NORMAL_FLOOR), spread);
    let plain_reach = !s.lt(reach, floor);
    let mut apart = s.none();
    for i in 0..D {
        apart |= s.gt(s.sub(a.lo[i], b.hi[i]), reach);
        apart |= s.gt(s.sub(b.lo[i], a.hi[i]), reach);
    }
    // A radius that is positive and finite, a horizon ≥ 0 (NaN fails both); sizes finite.
    let valid = s.gt(radius, zero) & finite(s, radius) & s.ge(t_max, zero) & finite(s, sizes);
    let taken = a.taken & b.taken & valid & plain_reach;
    // The chords, only where some lane is left for them.
    let open = taken & !apart & a.rests & b.rests;
    let chords = if s.any(open) {
        // B's chord only where A's leaves a lane open (each costs a division and a root).
        let first = open & apart_across_chord(s, &rows_a, &rows_b, reach);
        let rest = open & !first;
        if s.any(rest) {
            first | (rest & apart_across_chord(s, &rows_b, &rows_a, reach))
        } else {
            first
        }
    } else {
        s.none()
    };
    // The windows, only where some lane is left for them.
    let left = taken & !apart & !chords;
    let windows = if s.any(left) {
        let (side_a, side_b) = (
            LaneSide {
                rows: &rows_a,
                boxes: &a.segments,
            },
            LaneSide {
                rows: &rows_b,
                boxes: &b.segments,
            },
        );
        windows_apart(s, &side_a, &side_b, radius, reach, left)
    } else {
        s.none()
    };
    Settled {
        bounds: s.bits(taken & apart),
        chords: s.bits(chords),
        windows: s.bits(windows),
        taken: s.bits(taken),
    }
}

/// Lanes whose value is finite.
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn finite<S: Simd>(s: S, x: S::V) -> S::M {
    s.lt(s.abs(x), s.splat(f64::INFINITY))
}

/// The per-pair values of pairs `first..first + LANES`, a lane each.
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn lanes_of<S: Simd>(s: S, values: PerPair<'_>, first: usize) -> S::V {
    let mut lanes = [0.0; LANES];
    for (l, lane) in lanes.iter_mut().enumerate() {
        *lane = values.get(first + l);
    }
    s.load(lanes)
}

/// How many pairs ahead of the block its rows are asked for in the cache: two blocks, 16
/// pairs. The lanes read eight streams at once, faster than the CPU's own prefetch keeps up
/// with. Asked for 16 blocks ahead, the seed model as paths took 9.10–9.18 ms against
/// 8.62–8.72 at AVX2, and 7.31–7.45 against 6.64–6.73 at AVX-512; pool-table paths the same
/// (criterion, alternated in one session, AMD EPYC; 1 and 3 blocks ahead as 2, no prefetch
/// as 16). Probably the lines asked for so early were often gone from the first-level cache
/// again by the time they were read.
const AHEAD: usize = 2 * LANES;

/// Asks for the `width·LANES` values from `at + width·AHEAD` in the cache (nothing past the
/// end; a hint).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn ahead(values: &[f64], at: usize, width: usize) {
    let from = at + width * AHEAD;
    if from + width * LANES <= values.len() {
        for line in 0..width {
            // (In range, checked above; a pointer, not an index: no bounds check per line.)
            prefetch(values.as_ptr().wrapping_add(from + 8 * line));
        }
    }
}

/// The rows of paths `first..first + LANES` of `side`, a lane each (and those [`AHEAD`] asked
/// for in the cache): lane `l` of row `k`'s value is the block's row `l·K + k`, read from
/// one slice of the block's rows by [`Simd::transposed`].
///
/// # Panics
/// If the side's rows do not hold paths `first..first + LANES` of `K` rows each (as
/// [`settled`] promises).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn lane_rows<S: Simd, const D: usize, const K: usize>(
    s: S,
    side: &PathRows<'_, D>,
    first: usize,
) -> LaneRows<S, D, K> {
    const { assert!(K <= 3 && D <= 3, "rows of up to 3 segments, in 2-D or 3-D") };
    ahead(side.start, first * K, K);
    for values in [side.pos, side.vel, side.acc] {
        ahead(values.as_flattened(), first * K * D, K * D);
    }
    let block = first * K..(first + LANES) * K;
    let start = transposed(s, &side.start[block.clone()], K);
    let mut starts = [s.zero(); K];
    starts.copy_from_slice(&start[..K]);
    LaneRows {
        s: starts,
        p: by_row(
            s,
            transposed(s, side.pos[block.clone()].as_flattened(), K * D),
        ),
        v: by_row(
            s,
            transposed(s, side.vel[block.clone()].as_flattened(), K * D),
        ),
        a: by_row(s, transposed(s, side.acc[block].as_flattened(), K * D)),
    }
}

/// A block's `K` rows of `D` values, from their values in the order of the rows. (Loops,
/// not `from_fn`: no closure in lane code.)
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn by_row<S: Simd, const D: usize, const K: usize>(s: S, flat: [S::V; MOST]) -> [[S::V; D]; K] {
    let mut rows = [[s.zero(); D]; K];
    for (k, row) in rows.iter_mut().enumerate() {
        row.copy_from_slice(&flat[k * D..(k + 1) * D]);
    }
    rows
}

/// [`Simd::transposed`] for a width known only as `K` or `K·D` of a caller's constants (which
/// fold the match): the widths of rows of 1 to 3 segments in 2-D or 3-D.
///
/// # Panics
/// If `values` holds fewer than `LANES·width` values.
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn transposed<S: Simd>(s: S, values: &[f64], width: usize) -> [S::V; MOST] {
    match width {
        1 => s.transposed::<1>(values),
        2 => s.transposed::<2>(values),
        3 => s.transposed::<3>(values),
        4 => s.transposed::<4>(values),
        6 => s.transposed::<6>(values),
        9 => s.transposed::<9>(values),
        _ => unreachable!("no rows of {width} values (see `lane_rows`)"),
    }
}

/// The bounds of a block's paths, as `PathBounds::set_to` forms them for paths whose rows are
/// all used and whose segments are all non-empty, and the checks of `Path::from_rows` in that
/// case (every value finite, starts increasing).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn lane_bounds<S: Simd, const D: usize, const K: usize>(
    s: S,
    rows: &LaneRows<S, D, K>,
) -> LaneBounds<S, D, K> {
    let LaneRows { s: starts, p, v, a } = rows;
    let zero = s.zero();
    // Starts increasing strictly (NaN fails), from a first above −∞ to a last below +∞: all
    // finite. The other values of every segment but the last are in the size, whose
    // finiteness is checked below; the last segment's velocity and acceleration here.
    let infinity = s.splat(f64::INFINITY);
    let mut taken = s.gt(starts[0], s.splat(f64::NEG_INFINITY)) & s.lt(starts[K - 1], infinity);
    for k in 1..K {
        taken &= s.gt(starts[k], starts[k - 1]);
    }
    for i in 0..D {
        let last = s.add(s.abs(v[K - 1][i]), s.abs(a[K - 1][i]));
        taken &= s.lt(last, infinity);
    }

    let one = s.splat(1.0);
    let axes = s.splat(D as f64);
    let rests = rests_at_end(s, rows);
    let mut bounds = LaneBounds {
        taken,
        rests,
        lo: [infinity; D],
        hi: [s.splat(f64::NEG_INFINITY); D],
        size: zero,
        spread: zero,
        segments: LaneBoxes {
            lo: [[zero; D]; K],
            hi: [[zero; D]; K],
        },
    };
    for k in 0..K - 1 {
        let length = s.sub(starts[k + 1], starts[k]);
        let reach = s.add(one, length);
        let spread = s.mul(s.mul(axes, reach), reach);
        bounds.spread = s.add(bounds.spread, spread);
        for i in 0..D {
            let (p, v, a) = (p[k][i], v[k][i], a[k][i]);
            // |p| + (|v| + |a|·L)·L
            let far = s.add(s.abs(v), s.mul(s.abs(a), length));
            let part = s.add(s.abs(p), s.mul(far, length));
            bounds.size = s.add(bounds.size, part);
            let [lo, hi] = bernstein_hull(s, p, v, a, length);
            (bounds.segments.lo[k][i], bounds.segments.hi[k][i]) = (lo, hi);
            bounds.lo[i] = s.min(bounds.lo[i], lo);
            bounds.hi[i] = s.max(bounds.hi[i], hi);
        }
    }
    // The last segment lasts for ever: unbounded on each side it drifts to. Where every lane
    // rests (most blocks: balls that stop), its box is its point: what the compares and
    // selects below give at a velocity and acceleration of exactly 0, without them.
    let all_rest = s.every(rests);
    for i in 0..D {
        let (p, v, a) = (p[K - 1][i], v[K - 1][i], a[K - 1][i]);
        bounds.size = s.add(bounds.size, s.abs(p));
        let (lo, hi) = if all_rest {
            (p, p)
        } else {
            let accelerates = s.ne(a, zero);
            let towards = s.blend(accelerates, v, a);
            let down = s.lt(towards, zero) | (s.gt(a, zero) & s.lt(v, zero));
            let up = s.gt(towards, zero) | (s.lt(a, zero) & s.gt(v, zero));
            (
                s.blend(down, p, s.splat(f64::NEG_INFINITY)),
                s.blend(up, p, infinity),
            )
        };
        (bounds.segments.lo[K - 1][i], bounds.segments.hi[K - 1][i]) = (lo, hi);
        bounds.lo[i] = s.min(bounds.lo[i], lo);
        bounds.hi[i] = s.max(bounds.hi[i], hi);
    }
    bounds.taken &= finite(s, bounds.size);
    bounds
}

/// `bernstein_hull` (`collision::path_bounds`) lane-wise: the least and greatest of `p`,
/// `p + ½·v·L` and `p + (v + ½·a·L)·L`, with its selects (`x < y ? x : y` is `min_pd(x, y)`).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn bernstein_hull<S: Simd>(s: S, p: S::V, v: S::V, a: S::V, length: S::V) -> [S::V; 2] {
    let half = s.splat(0.5);
    let middle = s.add(p, s.mul(s.mul(half, v), length));
    let slope = s.add(v, s.mul(s.mul(half, a), length));
    let end = s.add(p, s.mul(slope, length));
    [s.min(end, s.min(middle, p)), s.max(end, s.max(middle, p))]
}

/// Lanes whose path ends at rest (`rests_at_end` in `collision::chord_normals`).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn rests_at_end<S: Simd, const D: usize, const K: usize>(s: S, rows: &LaneRows<S, D, K>) -> S::M {
    let zero = s.zero();
    let mut rests = s.all();
    for i in 0..D {
        rests &= s.eq(rows.v[K - 1][i], zero);
        rests &= s.eq(rows.a[K - 1][i], zero);
    }
    rests
}

/// `apart_across_chord_of` (`collision::chord_normals`) lane-wise, for taken paths that end
/// at rest: the normal of `own`'s chord, and the spans on it.
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn apart_across_chord<S: Simd, const D: usize, const K: usize>(
    s: S,
    own: &LaneRows<S, D, K>,
    other: &LaneRows<S, D, K>,
    reach: S::V,
) -> S::M {
    let (dx, dy) = (
        s.sub(own.p[K - 1][0], own.p[0][0]),
        s.sub(own.p[K - 1][1], own.p[0][1]),
    );
    let most = s.max(s.abs(dx), s.abs(dy));
    let normal_chord = s.ge(most, s.splat(f64::MIN_POSITIVE)) & s.lt(most, s.splat(f64::INFINITY));
    let scale = s.div(s.splat(0.5), most);
    let mut normal = [s.zero(); D];
    normal[0] = s.mul(s.mul(dy, s.splat(-1.0)), scale);
    normal[1] = s.mul(dx, scale);
    // (The scalar screen first compares the other path's ends with where this one starts,
    // against 0.49 of the reach, to give up early; the spans hold those ends and that start,
    // and are compared against at least 0.4999 of the reach, so that the spans' test implies
    // it: the lanes need only the spans.)
    let length2 = s.add(s.mul(normal[0], normal[0]), s.mul(normal[1], normal[1]));
    let reach = s.mul(reach, s.sqrt(length2));
    let (own, other) = (span(s, own, &normal), span(s, other, &normal));
    let spans_apart = s.gt(s.sub(own[0], other[1]), reach) | s.gt(s.sub(other[0], own[1]), reach);
    normal_chord & spans_apart
}

/// `normal·x` lane-wise, summed in the order of the axes (as `along` does).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn along<S: Simd, const D: usize>(s: S, normal: &[S::V; D], x: &[S::V; D]) -> S::V {
    let mut sum = s.mul(normal[0], x[0]);
    for i in 1..D {
        sum = s.add(sum, s.mul(normal[i], x[i]));
    }
    sum
}

/// `span` (`collision::chord_normals`) lane-wise: the least and greatest of `normal·x` along
/// the path (every segment non-empty, the last at rest).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn span<S: Simd, const D: usize, const K: usize>(
    s: S,
    rows: &LaneRows<S, D, K>,
    normal: &[S::V; D],
) -> [S::V; 2] {
    let mut hull = [s.splat(f64::INFINITY), s.splat(f64::NEG_INFINITY)];
    for k in 0..K - 1 {
        let length = s.sub(rows.s[k + 1], rows.s[k]);
        let [lo, hi] = bernstein_hull(
            s,
            along(s, normal, &rows.p[k]),
            along(s, normal, &rows.v[k]),
            along(s, normal, &rows.a[k]),
            length,
        );
        hull = [s.min(lo, hull[0]), s.max(hi, hull[1])];
    }
    let p = along(s, normal, &rows.p[K - 1]);
    [s.min(p, hull[0]), s.max(p, hull[1])]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::CollisionOptions;
    use crate::collision::chord_normals::{apart_across_chords, spans_across_chord};
    use crate::collision::path_bounds::PathBounds;
    use crate::collision::path_collision_time_unscreened;
    use crate::collision::path_contact::every_window_screened;
    use crate::path::Path2;
    use crate::simd::{Kernel, Level, dispatch, test_levels};
    use crate::test_path_rows::RowSpec;
    use crate::test_rng::Rng;

    /// [`settled`] on a block, as a kernel to dispatch at a level.
    struct Block0<'a, const K: usize>(&'a PathPairs<'a, 2>);

    impl<const K: usize> Kernel for Block0<'_, K> {
        type Output = Settled;

        #[inline(always)]
        fn run<S: Simd>(self, s: S) -> Settled {
            settled::<S, 2, K>(s, self.0, 0)
        }
    }

    /// [`settled`] at `level` (which this CPU must have).
    fn settled_at<const K: usize>(level: Level, pairs: &PathPairs<'_, 2>) -> Settled {
        assert!(level.supported(), "{level}");
        dispatch(level, Block0::<K>(pairs))
    }

    /// [`settled`] at every level of `levels`: the same at each (the portable copy's).
    fn settled_at_every_level<const K: usize>(
        pairs: &PathPairs<'_, 2>,
        levels: &[Level],
    ) -> Settled {
        let portable = settled_at::<K>(Level::Portable, pairs);
        for &level in levels {
            assert_eq!(
                settled_at::<K>(level, pairs),
                portable,
                "{level}: {pairs:?}"
            );
        }
        portable
    }

    /// `LANES` pairs of 2-D paths of `K` rows: mostly plain (every row used, starts
    /// increasing), at scales from `2⁻¹⁰⁶⁰` to `2⁹⁶⁰` so that underflow, overflowing sizes and
    /// margins near the gap all occur; some with a row that the lanes must leave (an empty or
    /// padding row, a NaN), some radii and horizons invalid.
    struct Block<const K: usize> {
        start: [Vec<f64>; 2],
        rows: [[Vec<[f64; 2]>; 3]; 2],
        radius: Vec<f64>,
        t_max: Vec<f64>,
    }

    impl<const K: usize> Block<K> {
        fn draw(rng: &mut Rng) -> Self {
            let scale = 2f64.powi(rng.below(2020) as i32 - 1060);
            let spec = RowSpec::<2> {
                segments: K,
                every_row_used: true,
                later_first_start: 1.0,
                first_start: [-1.0, 1.0],
                length: [0.0, 2.0],
                empty: 0.0,
                pos: RowSpec::each_axis(-3.0, 3.0),
                continuous: false,
                vel: RowSpec::each_axis(-2.0, 2.0),
                acc: RowSpec::each_axis(-2.0, 2.0),
                // Half the blocks with every path ending at rest (the boxes' shortcut then).
                last_at_rest: if rng.below(2) == 0 { 1.0 } else { 2.0 / 3.0 },
            };
            let draw_side = |rng: &mut Rng| {
                // Drawn in units of `scale` (a power of two), then scaled: at the smallest
                // scales the values underflow into subnormals and neighbouring starts may round
                // to one (an empty row), as rows drawn at that scale do.
                let (mut start, mut rows) = spec.draw(rng, LANES);
                for t in &mut start {
                    *t *= scale;
                }
                for x in rows.iter_mut().flatten().flatten() {
                    *x *= scale;
                }
                // A few rows the lanes cannot take.
                for _ in 0..rng.below(3) {
                    let at = rng.below((LANES * K) as u64) as usize;
                    match rng.below(5) {
                        0 => start[at] = f64::INFINITY,
                        4 => start[at] = f64::NEG_INFINITY,
                        1 if !at.is_multiple_of(K) => start[at] = start[at - 1],
                        2 => rows[rng.below(3) as usize][at][1] = f64::NAN,
                        _ => rows[0][at][0] = f64::INFINITY,
                    }
                }
                (start, rows)
            };
            let (sa, ra) = draw_side(rng);
            let (sb, mut rb) = draw_side(rng);
            // B's paths shifted off A's on x, more or less.
            let shift = rng.uniform(-8.0, 8.0) * scale;
            for p in &mut rb[0] {
                p[0] += shift;
            }
            let value = |rng: &mut Rng, good: f64| match rng.below(16) {
                0 => f64::NAN,
                1 => -good,
                2 => 0.0,
                3 => f64::INFINITY,
                _ => good,
            };
            let radius = (0..LANES)
                .map(|_| {
                    let good = rng.uniform(0.0, 1.5) * scale;
                    value(rng, good)
                })
                .collect();
            let t_max = (0..LANES).map(|_| value(rng, 1.0)).collect();
            Self {
                start: [sa, sb],
                rows: [ra, rb],
                radius,
                t_max,
            }
        }

        /// Side `s`'s path of pair `l`, if valid.
        fn path(&self, s: usize, l: usize) -> Option<Path2> {
            let r = l * K..(l + 1) * K;
            let [pos, vel, acc] = &self.rows[s];
            Path2::from_rows(
                &self.start[s][r.clone()],
                &pos[r.clone()],
                &vel[r.clone()],
                &acc[r],
            )
            .ok()
        }

        /// Moves pair `l`'s B along x so that its box and A's are the reach apart, to within
        /// a few ulps either way: where the lanes' margin and sizes must be the path bounds'
        /// to the last bit.
        fn on_the_edge(&mut self, l: usize, rng: &mut Rng) -> bool {
            for _ in 0..4 {
                let bounds = |s: usize| self.path(s, l).map(|p| PathBounds::<2>::of(p.segments()));
                let (Some(a), Some(b)) = (bounds(0), bounds(1)) else {
                    return false;
                };
                let radius = self.radius[l];
                let gap = b.whole().0[0] - a.whole().1[0];
                let miss = a.screen_distance(&b, radius).value() - gap;
                if !miss.is_finite() {
                    return false;
                }
                let ulps = rng.uniform(-4.0, 4.0) * f64::EPSILON * gap.abs();
                for p in &mut self.rows[1][0][l * K..(l + 1) * K] {
                    p[0] += miss + ulps;
                }
            }
            true
        }

        /// Moves pair `l`'s B along the normal of A's chord so that, on it, B's span and A's
        /// are the reach apart (to within a few ulps either way), if both paths end at rest.
        fn on_the_chords_edge(&mut self, l: usize, rng: &mut Rng) -> bool {
            for _ in 0..4 {
                let (Some(a), Some(b)) = (self.path(0, l), self.path(1, l)) else {
                    return false;
                };
                let (a, b) = (a.segments(), b.segments());
                let Some((n, own, other)) = spans_across_chord(a, b) else {
                    return false;
                };
                let (bounds_a, bounds_b) = (PathBounds::<2>::of(a), PathBounds::of(b));
                let length2 = n[0] * n[0] + n[1] * n[1];
                let reach =
                    bounds_a.screen_distance(&bounds_b, self.radius[l]).value() * length2.sqrt();
                let gap = other[0] - own[1];
                let ulps = rng.uniform(-4.0, 4.0) * f64::EPSILON * gap.abs();
                let by = (reach - gap + ulps) / length2;
                if !by.is_finite() {
                    return false;
                }
                for p in &mut self.rows[1][0][l * K..(l + 1) * K] {
                    p[0] += by * n[0];
                    p[1] += by * n[1];
                }
            }
            true
        }

        fn side(&self, s: usize) -> PathRows<'_, 2> {
            let [pos, vel, acc] = &self.rows[s];
            PathRows {
                start: &self.start[s],
                pos,
                vel,
                acc,
                segments: K,
            }
        }

        fn pairs(&self) -> PathPairs<'_, 2> {
            PathPairs {
                a: self.side(0),
                b: self.side(1),
                contact_distance: PerPair::Each(&self.radius),
                t_max: PerPair::Each(&self.t_max),
            }
        }

        /// Pair `l` as the scalar code sees it: `None` if invalid, else whether it is plain
        /// (every row used, starts increasing, finite sizes, a reach underflow cannot touch),
        /// whether its path bounds are apart, and whether it is apart across the chords.
        fn scalar(&self, l: usize) -> Option<(bool, bool, bool)> {
            let rows = |s: usize| {
                let r = l * K..(l + 1) * K;
                let [pos, vel, acc] = &self.rows[s];
                let start = &self.start[s][r.clone()];
                let path = Path2::from_rows(start, &pos[r.clone()], &vel[r.clone()], &acc[r]);
                let increasing =
                    start.iter().all(|s| s.is_finite()) && start.windows(2).all(|w| w[0] < w[1]);
                path.ok().map(|path| (path, increasing))
            };
            let ((a, plain_a), (b, plain_b)) = (rows(0)?, rows(1)?);
            let (radius, t_max) = (self.radius[l], self.t_max[l]);
            if !(radius > 0.0 && radius.is_finite() && t_max >= 0.0) {
                return None;
            }
            let (bounds_a, bounds_b) = (
                PathBounds::<2>::of(a.segments()),
                PathBounds::of(b.segments()),
            );
            let reach = bounds_a.screen_distance(&bounds_b, radius);
            let plain = plain_a && plain_b && bounds_a.screen_distance_in_range(&bounds_b, radius);
            let apart = bounds_a.apart(&bounds_b, reach);
            let chords = apart_across_chords(a.segments(), b.segments(), reach);
            Some((plain, apart, chords))
        }

        /// Pair `l`'s paths, if both are valid.
        fn paths(&self, l: usize) -> Option<(Path2, Path2)> {
            Some((self.path(0, l)?, self.path(1, l)?))
        }
    }

    fn lanes_settle_what_the_path_bounds_settle<const K: usize>() {
        let levels = test_levels();
        eprintln!("path lanes in rows of {K} at {levels:?}");
        let mut rng = Rng(K as u64);
        let (mut settled_lanes, mut chord_lanes, mut apart_left) = (0, 0, 0);
        let (mut plain_kept, mut edge) = (0, 0);
        for _ in 0..4_000 {
            let mut block = Block::<K>::draw(&mut rng);
            for l in 0..LANES {
                edge += usize::from(match rng.below(3) {
                    0 => block.on_the_edge(l, &mut rng),
                    1 => block.on_the_chords_edge(l, &mut rng),
                    _ => false,
                });
            }
            let settled = settled_at_every_level::<K>(&block.pairs(), &levels);
            for l in 0..LANES {
                let bit = |mask: u8| mask & (1 << l) != 0;
                let (by_bounds, by_chords) = (bit(settled.bounds), bit(settled.chords));
                let what = || format!("lane {l} of {:?}", block.pairs());
                match block.scalar(l) {
                    // Settled exactly where the pair is plain and a screen proves it apart, by
                    // the screen that comes first.
                    Some((plain, apart, chords)) => {
                        assert_eq!(by_bounds, plain && apart, "bounds: {}", what());
                        assert_eq!(by_chords, plain && !apart && chords, "chords: {}", what());
                        settled_lanes += usize::from(by_bounds | by_chords);
                        chord_lanes += usize::from(by_chords);
                        apart_left += usize::from((apart || chords) && !plain);
                        plain_kept += usize::from(plain && !apart && !chords);
                    }
                    None => assert!(!(by_bounds | by_chords), "invalid: {}", what()),
                }
            }
        }
        // Each outcome is met many times (else the test could not fail).
        eprintln!("{settled_lanes} {chord_lanes} {apart_left} {plain_kept} {edge}");
        assert!(settled_lanes > 2_000, "{settled_lanes} settled");
        assert!(chord_lanes > 200, "{chord_lanes} settled across a chord");
        assert!(
            apart_left > 150,
            "{apart_left} apart, left to the pair's screen"
        );
        assert!(plain_kept > 3_000, "{plain_kept} plain, not apart");
        assert!(edge > 2_000, "{edge} on the edge");
    }

    /// The window lanes, on the pairs the whole-path screens leave: a pair they settle has no
    /// contact (the search without screens finds none, at any horizon), and where the pair's
    /// magnitudes are ordinary (no underflow or overflow in sight), they settle exactly the
    /// pairs whose every window the pair's own window screens prove apart.
    fn lanes_settle_what_the_window_screens_settle<const K: usize>() {
        let levels = test_levels();
        eprintln!("window lanes in rows of {K} at {levels:?}");
        let mut rng = Rng(100 + K as u64);
        let (mut settled_lanes, mut ordinary_left, mut checked) = (0, 0, 0);
        let options = CollisionOptions::default();
        for _ in 0..4_000 {
            let block = Block::<K>::draw(&mut rng);
            let settled = settled_at_every_level::<K>(&block.pairs(), &levels);
            for l in 0..LANES {
                let by_windows = settled.windows & (1 << l) != 0;
                let what = || format!("lane {l} of {:?}", block.pairs());
                let Some((plain, apart, chords)) = block.scalar(l) else {
                    assert!(!by_windows, "invalid: {}", what());
                    continue;
                };
                let Some((a, b)) = block.paths(l) else {
                    unreachable!("valid pairs have valid paths")
                };
                let radius = block.radius[l];
                assert!(!(by_windows && (apart || chords)), "twice: {}", what());
                if by_windows {
                    let unscreened = path_collision_time_unscreened(&a, &b, radius, &options);
                    assert_eq!(unscreened, Ok(None), "a contact: {}", what());
                    settled_lanes += 1;
                }
                // Ordinary magnitudes: every value of the pair between 2⁻⁴⁰⁰ and 2⁴⁰⁰ (or 0).
                let ordinary = [&a, &b].iter().all(|path| {
                    path.segments().iter().all(|s| {
                        [s.start]
                            .into_iter()
                            .chain(s.position.iter().copied())
                            .chain(s.velocity.iter().copied())
                            .chain(s.acceleration.iter().copied())
                            .all(|x| {
                                x == 0.0 || (x.abs() > 2f64.powi(-400) && x.abs() < 2f64.powi(400))
                            })
                    })
                }) && radius > 2f64.powi(-400);
                if plain && !apart && !chords && ordinary {
                    let screened = every_window_screened(a.segments(), b.segments(), radius);
                    assert_eq!(by_windows, screened, "windows: {}", what());
                    checked += 1;
                    ordinary_left += usize::from(!screened);
                }
            }
        }
        // Each outcome is met many times (else the test could not fail).
        assert!(settled_lanes > 500, "{settled_lanes} settled");
        assert!(checked > 2_000, "{checked} ordinary pairs compared");
        assert!(
            ordinary_left > 500,
            "{ordinary_left} ordinary pairs left to the search"
        );
    }

    #[test]
    fn window_lanes_settle_what_the_window_screens_settle_in_rows_of_two() {
        lanes_settle_what_the_window_screens_settle::<2>();
    }

    #[test]
    fn window_lanes_settle_what_the_window_screens_settle_in_rows_of_three() {
        lanes_settle_what_the_window_screens_settle::<3>();
    }

    #[test]
    fn lanes_settle_what_the_path_bounds_settle_in_rows_of_two() {
        lanes_settle_what_the_path_bounds_settle::<2>();
    }

    #[test]
    fn lanes_settle_what_the_path_bounds_settle_in_rows_of_three() {
        lanes_settle_what_the_path_bounds_settle::<3>();
    }
}
