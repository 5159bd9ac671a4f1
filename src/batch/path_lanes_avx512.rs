//! The AVX-512 copy of [`path_lanes`](super::path_lanes), in intrinsics: the batch's
//! [`Level::Avx512`](crate::simd::Level) runs it, because the compiler does not yet make
//! code as fast from the generic lanes (twice the time on a pool table; the row reads by
//! permutes and the masks in `k` registers are what it misses). The same operations as the
//! generic lanes, to the bit (the lane tests compare the two at every block).
//!
//! The whole-path screens ([`PathBounds::apart`], then [`apart_across_chords`]), eight pairs
//! at a time with AVX-512: a block of pairs of paths read from their rows, every value checked
//! and every path's box and chord spans formed in the vector registers, one pair per lane,
//! without a branch on the data ([`settled`]); then, for the pairs they leave, the window
//! screens on every window of the pair ([`window_lanes`](super::window_lanes)). The pairs they
//! settle (valid, proven apart) answer "none" at once; the others go on to the pair's own
//! search, which reads them again and reports any error.
//!
//! They are the two screens' proofs, computed the way [`PathBounds::set_to`],
//! [`PathBounds::reach`] and [`apart_across_chords`] compute them: the same operations in the
//! same order on the same numbers, so that a lane is settled exactly when the pair's own
//! screens would settle it, and the batch's answers are the same bits with or without them.
//! They take the paths they can take whole: both sides with a path per pair and `K` rows each,
//! every row used with starts that increase strictly, every value finite, a finite size, and
//! no reach that underflow could touch; anything else is left to the pair's own path (which
//! settles it, or names its error).
//!
//! On a pool table three pairs in four are settled by the whole-path screens and one in five
//! by the windows, at about fifteen nanoseconds a pair instead of the sixty to eighty that
//! reading, checking and screening them one at a time costs (200 or more for the windows).
//!
//! [`PathBounds::apart`]: crate::collision::path_bounds::PathBounds
//! [`PathBounds::set_to`]: crate::collision::path_bounds::PathBounds
//! [`PathBounds::reach`]: crate::collision::path_bounds::PathBounds
//! [`apart_across_chords`]: crate::collision::chord_normals

use core::arch::x86_64::{
    __m512d, __mmask8, _CMP_EQ_OQ, _CMP_GE_OQ, _CMP_GT_OQ, _CMP_LT_OQ, _CMP_NEQ_UQ, _mm512_abs_pd,
    _mm512_add_pd, _mm512_cmp_pd_mask, _mm512_div_pd, _mm512_loadu_epi64, _mm512_loadu_pd,
    _mm512_mask_blend_pd, _mm512_max_pd, _mm512_min_pd, _mm512_mul_pd, _mm512_permutex2var_pd,
    _mm512_set1_pd, _mm512_setzero_pd, _mm512_sqrt_pd, _mm512_sub_pd,
};

use super::PerPair;
use super::paths::{PathPairs, PathRows};
use super::window_lanes_avx512::{LaneSide, windows_apart};
use crate::collision::window_box::{MARGIN, NORMAL_FLOOR};

use super::lane_ops::LANES;

/// The pairs of a block that the lanes settle, by screen (bit `l` for the block's pair `l`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SettledAvx512 {
    /// The path bounds are apart.
    pub(crate) bounds: __mmask8,
    /// The path bounds are not, the spans across a chord are.
    pub(crate) chords: __mmask8,
    /// Neither is, every window is proven apart ([`window_lanes`](super::window_lanes)).
    pub(crate) windows: __mmask8,
    /// Taken whole by the lanes (valid, every row used, a plain reach): where none of the
    /// above holds, the pair's own whole-path screens fail too.
    pub(crate) taken: __mmask8,
}

/// One side's rows of a block, a lane each: row `k`'s start and its position, velocity and
/// acceleration on each axis.
pub(super) struct LaneRows<const D: usize, const K: usize> {
    pub(super) s: [__m512d; K],
    pub(super) p: [[__m512d; D]; K],
    pub(super) v: [[__m512d; D]; K],
    pub(super) a: [[__m512d; D]; K],
}

/// One side's segment boxes of a block, a lane each: segment `k`'s least and greatest value
/// on each axis.
pub(super) struct LaneBoxes<const D: usize, const K: usize> {
    pub(super) lo: [[__m512d; D]; K],
    pub(super) hi: [[__m512d; D]; K],
}

/// One side's paths of a block, a lane each: which are taken (valid, every row used, starts
/// increasing strictly, finite size), and the box, size and spread [`PathBounds`] forms for
/// them.
///
/// [`PathBounds`]: crate::collision::path_bounds::PathBounds
struct LaneBounds<const D: usize, const K: usize> {
    taken: __mmask8,
    lo: [__m512d; D],
    hi: [__m512d; D],
    size: __m512d,
    spread: __m512d,
    /// The box of each segment (`PathBounds`' segment boxes: a path of `K ≤ 3` rows keeps
    /// one for every segment).
    segments: LaneBoxes<D, K>,
}

/// Which of pairs `first..first + LANES` are settled: both paths taken, radius and horizon
/// valid, and the two paths' boxes farther apart on some axis than the reach, or else both
/// paths ending at rest and apart across a chord.
///
/// # Safety
/// Both sides must hold a path per pair in rows of `K ≥ 1` segments (`start` of `n·K` values,
/// `pos`, `vel`, `acc` of `n·K` rows, as [`path_collision_times`](super::path_collision_times)
/// checks them), per-pair `radius` and `t_max` of `n` values, and `first + LANES ≤ n`.
#[target_feature(enable = "avx512f")]
pub(crate) unsafe fn settled<const D: usize, const K: usize>(
    pairs: &PathPairs<'_, D>,
    first: usize,
) -> SettledAvx512 {
    // SAFETY: the caller's promise, passed on.
    let (rows_a, rows_b) = unsafe {
        (
            lane_rows::<D, K>(&pairs.a, first),
            lane_rows::<D, K>(&pairs.b, first),
        )
    };
    let (a, b) = (lane_bounds(&rows_a), lane_bounds(&rows_b));
    let radius = lanes_of(pairs.radius, first);
    let t_max = lanes_of(pairs.t_max, first);
    let zero = _mm512_setzero_pd();
    // `radius + MARGIN·(size_a + size_b + radius)`, as `PathBounds::reach` forms it.
    let sizes = _mm512_add_pd(_mm512_add_pd(a.size, b.size), radius);
    let reach = _mm512_add_pd(radius, _mm512_mul_pd(_mm512_set1_pd(MARGIN), sizes));
    // Where underflow could count (`with_underflow` would grow the reach): not taken.
    let spread = _mm512_add_pd(a.spread, b.spread);
    let floor = _mm512_mul_pd(_mm512_set1_pd(NORMAL_FLOOR), spread);
    let plain_reach = !_mm512_cmp_pd_mask(reach, floor, _CMP_LT_OQ);
    let mut apart: __mmask8 = 0;
    for i in 0..D {
        apart |= _mm512_cmp_pd_mask(_mm512_sub_pd(a.lo[i], b.hi[i]), reach, _CMP_GT_OQ);
        apart |= _mm512_cmp_pd_mask(_mm512_sub_pd(b.lo[i], a.hi[i]), reach, _CMP_GT_OQ);
    }
    // A radius that is positive and finite, a horizon ≥ 0 (NaN fails both); sizes finite.
    let valid = _mm512_cmp_pd_mask(radius, zero, _CMP_GT_OQ)
        & finite(radius)
        & _mm512_cmp_pd_mask(t_max, zero, _CMP_GE_OQ)
        & finite(sizes);
    let taken = a.taken & b.taken & valid & plain_reach;
    // The chords, only where some lane is left for them.
    let open = taken & !apart & rests_at_end(&rows_a) & rests_at_end(&rows_b);
    let chords = if open != 0 {
        open & (apart_across_chord(&rows_a, &rows_b, reach)
            | apart_across_chord(&rows_b, &rows_a, reach))
    } else {
        0
    };
    // The windows, only where some lane is left for them.
    let left = taken & !apart & !chords;
    let windows = if left != 0 {
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
        windows_apart(&side_a, &side_b, radius, reach, left)
    } else {
        0
    };
    SettledAvx512 {
        bounds: taken & apart,
        chords,
        windows,
        taken,
    }
}

/// Lanes whose value is finite.
#[inline]
#[target_feature(enable = "avx512f")]
fn finite(x: __m512d) -> __mmask8 {
    _mm512_cmp_pd_mask(_mm512_abs_pd(x), _mm512_set1_pd(f64::INFINITY), _CMP_LT_OQ)
}

/// The per-pair values of pairs `first..first + LANES`, a lane each.
#[inline]
#[target_feature(enable = "avx512f")]
fn lanes_of(values: PerPair<'_>, first: usize) -> __m512d {
    let lanes: [f64; LANES] = std::array::from_fn(|l| values.get(first + l));
    // SAFETY: `[f64; 8]` and `__m512d` have the same size, and every bit pattern is valid.
    unsafe { std::mem::transmute(lanes) }
}

/// The most values a path has in one array of its rows: `K·D` for 3 rows in 3-D.
const MOST: usize = 9;

/// `LANES·W` values from `values` on, a path's `W` in a row, as `W` vectors (the first `W` of
/// the array): vector `c`'s lane `l` holds `values[l·W + c]`. Read as whole vectors and put in
/// place by permutes and blends, which cost a fraction of gathers: the block's values are
/// contiguous. `W` is a constant so that the lane indices and masks are too.
///
/// # Safety
/// `values` must be valid for reading `LANES·W` values, and `1 ≤ W ≤ MOST`.
#[inline]
#[target_feature(enable = "avx512f")]
unsafe fn transposed<const W: usize>(values: *const f64) -> [__m512d; MOST] {
    let zero = _mm512_setzero_pd();
    let mut loaded = [zero; MOST];
    for (j, vector) in loaded.iter_mut().enumerate().take(W) {
        // SAFETY: vectors `0..W` are the caller's `LANES·W` values.
        *vector = unsafe { _mm512_loadu_pd(values.add(LANES * j)) };
    }
    let mut out = [zero; MOST];
    for (c, vector) in out.iter_mut().enumerate().take(W) {
        // Lane `l`'s value is value `l·W + c` of the block: in the pair of loaded vectors
        // `g = (l·W + c) / 16`, at `(l·W + c) % 16` of the two.
        let mut index = [0i64; LANES];
        for (l, at) in index.iter_mut().enumerate() {
            *at = ((l * W + c) % (2 * LANES)) as i64;
        }
        // SAFETY: reads the eight `i64`s of `index`.
        let index = unsafe { _mm512_loadu_epi64(index.as_ptr()) };
        for g in 0..W.div_ceil(2) {
            let mut mask: __mmask8 = 0;
            for l in 0..LANES {
                if (l * W + c) / (2 * LANES) == g {
                    mask |= 1 << l;
                }
            }
            if mask == 0 {
                continue;
            }
            // (With an odd `W` the last pair's second vector is never indexed.)
            let (low, high) = (loaded[2 * g], loaded[(2 * g + 1).min(W - 1)]);
            let part = _mm512_permutex2var_pd(low, index, high);
            *vector = _mm512_mask_blend_pd(mask, *vector, part);
        }
    }
    out
}

/// [`transposed`] for a width known only as `K` or `K·D` of a caller's constants (which
/// fold the match): the widths of rows of 1 to 3 segments in 2-D or 3-D.
///
/// # Safety
/// As [`transposed`], with `width` for `W`.
#[inline]
#[target_feature(enable = "avx512f")]
unsafe fn transposed_rows(values: *const f64, width: usize) -> [__m512d; MOST] {
    // SAFETY: the caller's promise, passed on.
    unsafe {
        match width {
            1 => transposed::<1>(values),
            2 => transposed::<2>(values),
            3 => transposed::<3>(values),
            4 => transposed::<4>(values),
            6 => transposed::<6>(values),
            9 => transposed::<9>(values),
            _ => unreachable!("no rows of {width} values (see `lane_rows`)"),
        }
    }
}

/// How many pairs ahead of the block its rows are asked for in the cache: 128 pairs, 1 to
/// 4 KiB further on in each of a side's four arrays. The lanes read eight streams at once,
/// faster than the CPU's own prefetch keeps up with, and a block's work is short: the rows
/// must be asked for many blocks before they are read to arrive in time.
const AHEAD: usize = 16 * LANES;

/// Asks for the `width·LANES` values from `at + width·AHEAD` in the cache (nothing past the
/// end).
#[inline(always)]
fn ahead(values: &[f64], at: usize, width: usize) {
    use core::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
    let from = at + width * AHEAD;
    if from + width * LANES <= values.len() {
        for line in 0..width {
            // SAFETY: in range (checked above); a hint, it reads nothing.
            unsafe {
                _mm_prefetch(
                    values.as_ptr().add(from + 8 * line).cast::<i8>(),
                    _MM_HINT_T0,
                )
            };
        }
    }
}

/// The rows of paths `first..first + LANES` of `side`, a lane each, read in order, whole
/// vectors at a time (and those [`AHEAD`] asked for in the cache).
///
/// # Safety
/// As [`settled`]: the side's rows hold paths `first..first + LANES`, `K` rows each.
#[inline]
#[target_feature(enable = "avx512f")]
unsafe fn lane_rows<const D: usize, const K: usize>(
    side: &PathRows<'_, D>,
    first: usize,
) -> LaneRows<D, K> {
    const { assert!(K <= 3 && D <= 3, "rows of up to 3 segments, in 2-D or 3-D") };
    ahead(side.start, first * K, K);
    for values in [side.pos, side.vel, side.acc] {
        ahead(values.as_flattened(), first * K * D, K * D);
    }
    // SAFETY: the caller's promise: the block's `LANES·K` starts and rows are in range.
    let (start, pos, vel, acc) = unsafe {
        (
            transposed_rows(side.start[first * K..].as_ptr(), K),
            transposed_rows(side.pos[first * K..].as_ptr().cast::<f64>(), K * D),
            transposed_rows(side.vel[first * K..].as_ptr().cast::<f64>(), K * D),
            transposed_rows(side.acc[first * K..].as_ptr().cast::<f64>(), K * D),
        )
    };
    let rows = |flat: [__m512d; MOST]| -> [[__m512d; D]; K] {
        std::array::from_fn(|k| std::array::from_fn(|i| flat[k * D + i]))
    };
    LaneRows {
        s: std::array::from_fn(|k| start[k]),
        p: rows(pos),
        v: rows(vel),
        a: rows(acc),
    }
}

/// The bounds of a block's paths, as `PathBounds::set_to` forms them for paths whose rows are
/// all used and whose segments are all non-empty, and the checks of `Path::from_rows` in that
/// case (every value finite, starts increasing).
#[inline]
#[target_feature(enable = "avx512f")]
fn lane_bounds<const D: usize, const K: usize>(rows: &LaneRows<D, K>) -> LaneBounds<D, K> {
    let LaneRows { s, p, v, a } = rows;
    let zero = _mm512_setzero_pd();
    // Starts increasing strictly (NaN fails), from a first above −∞ to a last below +∞: all
    // finite. The other values of every segment but the last are in the size, whose
    // finiteness is checked below; the last segment's velocity and acceleration here.
    let infinity = _mm512_set1_pd(f64::INFINITY);
    let mut taken = _mm512_cmp_pd_mask(s[0], _mm512_set1_pd(f64::NEG_INFINITY), _CMP_GT_OQ)
        & _mm512_cmp_pd_mask(s[K - 1], infinity, _CMP_LT_OQ);
    for k in 1..K {
        taken &= _mm512_cmp_pd_mask(s[k], s[k - 1], _CMP_GT_OQ);
    }
    for i in 0..D {
        let last = _mm512_add_pd(_mm512_abs_pd(v[K - 1][i]), _mm512_abs_pd(a[K - 1][i]));
        taken &= _mm512_cmp_pd_mask(last, infinity, _CMP_LT_OQ);
    }

    let one = _mm512_set1_pd(1.0);
    let axes = _mm512_set1_pd(D as f64);
    let mut bounds = LaneBounds {
        taken,
        lo: [infinity; D],
        hi: [_mm512_set1_pd(f64::NEG_INFINITY); D],
        size: zero,
        spread: zero,
        segments: LaneBoxes {
            lo: [[zero; D]; K],
            hi: [[zero; D]; K],
        },
    };
    for k in 0..K - 1 {
        let length = _mm512_sub_pd(s[k + 1], s[k]);
        let reach = _mm512_add_pd(one, length);
        let spread = _mm512_mul_pd(_mm512_mul_pd(axes, reach), reach);
        bounds.spread = _mm512_add_pd(bounds.spread, spread);
        for i in 0..D {
            let (p, v, a) = (p[k][i], v[k][i], a[k][i]);
            // |p| + (|v| + |a|·L)·L
            let far = _mm512_add_pd(_mm512_abs_pd(v), _mm512_mul_pd(_mm512_abs_pd(a), length));
            let part = _mm512_add_pd(_mm512_abs_pd(p), _mm512_mul_pd(far, length));
            bounds.size = _mm512_add_pd(bounds.size, part);
            let [lo, hi] = bernstein_hull(p, v, a, length);
            (bounds.segments.lo[k][i], bounds.segments.hi[k][i]) = (lo, hi);
            bounds.lo[i] = _mm512_min_pd(bounds.lo[i], lo);
            bounds.hi[i] = _mm512_max_pd(bounds.hi[i], hi);
        }
    }
    // The last segment lasts for ever: unbounded on each side it drifts to.
    for i in 0..D {
        let (p, v, a) = (p[K - 1][i], v[K - 1][i], a[K - 1][i]);
        bounds.size = _mm512_add_pd(bounds.size, _mm512_abs_pd(p));
        let lt = |x: __m512d| _mm512_cmp_pd_mask(x, zero, _CMP_LT_OQ);
        let gt = |x: __m512d| _mm512_cmp_pd_mask(x, zero, _CMP_GT_OQ);
        let accelerates = _mm512_cmp_pd_mask(a, zero, _CMP_NEQ_UQ);
        let towards = _mm512_mask_blend_pd(accelerates, v, a);
        let down = lt(towards) | (gt(a) & lt(v));
        let up = gt(towards) | (lt(a) & gt(v));
        let lo = _mm512_mask_blend_pd(down, p, _mm512_set1_pd(f64::NEG_INFINITY));
        let hi = _mm512_mask_blend_pd(up, p, infinity);
        (bounds.segments.lo[K - 1][i], bounds.segments.hi[K - 1][i]) = (lo, hi);
        bounds.lo[i] = _mm512_min_pd(bounds.lo[i], lo);
        bounds.hi[i] = _mm512_max_pd(bounds.hi[i], hi);
    }
    bounds.taken &= finite(bounds.size);
    bounds
}

/// `bernstein_hull` (`collision::path_bounds`) lane-wise: the least and greatest of `p`,
/// `p + ½·v·L` and `p + (v + ½·a·L)·L`, with its selects (`x < y ? x : y` is `min_pd(x, y)`).
#[inline]
#[target_feature(enable = "avx512f")]
fn bernstein_hull(p: __m512d, v: __m512d, a: __m512d, length: __m512d) -> [__m512d; 2] {
    let half = _mm512_set1_pd(0.5);
    let middle = _mm512_add_pd(p, _mm512_mul_pd(_mm512_mul_pd(half, v), length));
    let slope = _mm512_add_pd(v, _mm512_mul_pd(_mm512_mul_pd(half, a), length));
    let end = _mm512_add_pd(p, _mm512_mul_pd(slope, length));
    [
        _mm512_min_pd(end, _mm512_min_pd(middle, p)),
        _mm512_max_pd(end, _mm512_max_pd(middle, p)),
    ]
}

/// Lanes whose path ends at rest (`rests_at_end` in `collision::chord_normals`).
#[inline]
#[target_feature(enable = "avx512f")]
fn rests_at_end<const D: usize, const K: usize>(rows: &LaneRows<D, K>) -> __mmask8 {
    let zero = _mm512_setzero_pd();
    let mut rests: __mmask8 = !0;
    for i in 0..D {
        rests &= _mm512_cmp_pd_mask(rows.v[K - 1][i], zero, _CMP_EQ_OQ);
        rests &= _mm512_cmp_pd_mask(rows.a[K - 1][i], zero, _CMP_EQ_OQ);
    }
    rests
}

/// `apart_across_chord_of` (`collision::chord_normals`) lane-wise, for taken paths that end
/// at rest: the normal of `own`'s chord, and the spans on it.
#[inline]
#[target_feature(enable = "avx512f")]
fn apart_across_chord<const D: usize, const K: usize>(
    own: &LaneRows<D, K>,
    other: &LaneRows<D, K>,
    reach: __m512d,
) -> __mmask8 {
    let (dx, dy) = (
        _mm512_sub_pd(own.p[K - 1][0], own.p[0][0]),
        _mm512_sub_pd(own.p[K - 1][1], own.p[0][1]),
    );
    let most = _mm512_max_pd(_mm512_abs_pd(dx), _mm512_abs_pd(dy));
    let normal_chord = _mm512_cmp_pd_mask(most, _mm512_set1_pd(f64::MIN_POSITIVE), _CMP_GE_OQ)
        & _mm512_cmp_pd_mask(most, _mm512_set1_pd(f64::INFINITY), _CMP_LT_OQ);
    let scale = _mm512_div_pd(_mm512_set1_pd(0.5), most);
    let zero = _mm512_setzero_pd();
    let normal: [__m512d; D] = std::array::from_fn(|i| match i {
        0 => _mm512_mul_pd(_mm512_mul_pd(dy, _mm512_set1_pd(-1.0)), scale),
        1 => _mm512_mul_pd(dx, scale),
        _ => zero,
    });
    // (The scalar screen first compares the other path's ends with where this one starts,
    // against 0.49 of the reach, to give up early; the spans hold those ends and that start,
    // and are compared against at least 0.4999 of the reach, so that the spans' test implies
    // it: the lanes need only the spans.)
    let length2 = _mm512_add_pd(
        _mm512_mul_pd(normal[0], normal[0]),
        _mm512_mul_pd(normal[1], normal[1]),
    );
    let reach = _mm512_mul_pd(reach, _mm512_sqrt_pd(length2));
    let (own, other) = (span(own, &normal), span(other, &normal));
    let spans_apart = _mm512_cmp_pd_mask(_mm512_sub_pd(own[0], other[1]), reach, _CMP_GT_OQ)
        | _mm512_cmp_pd_mask(_mm512_sub_pd(other[0], own[1]), reach, _CMP_GT_OQ);
    normal_chord & spans_apart
}

/// `normal·x` lane-wise, summed in the order of the axes (as `along` does).
#[inline]
#[target_feature(enable = "avx512f")]
fn along<const D: usize>(normal: &[__m512d; D], x: &[__m512d; D]) -> __m512d {
    let mut sum = _mm512_mul_pd(normal[0], x[0]);
    for i in 1..D {
        sum = _mm512_add_pd(sum, _mm512_mul_pd(normal[i], x[i]));
    }
    sum
}

/// `span` (`collision::chord_normals`) lane-wise: the least and greatest of `normal·x` along
/// the path (every segment non-empty, the last at rest).
#[inline]
#[target_feature(enable = "avx512f")]
fn span<const D: usize, const K: usize>(
    rows: &LaneRows<D, K>,
    normal: &[__m512d; D],
) -> [__m512d; 2] {
    let mut hull = [
        _mm512_set1_pd(f64::INFINITY),
        _mm512_set1_pd(f64::NEG_INFINITY),
    ];
    for k in 0..K - 1 {
        let length = _mm512_sub_pd(rows.s[k + 1], rows.s[k]);
        let [lo, hi] = bernstein_hull(
            along(normal, &rows.p[k]),
            along(normal, &rows.v[k]),
            along(normal, &rows.a[k]),
            length,
        );
        hull = [_mm512_min_pd(lo, hull[0]), _mm512_max_pd(hi, hull[1])];
    }
    let p = along(normal, &rows.p[K - 1]);
    [_mm512_min_pd(p, hull[0]), _mm512_max_pd(p, hull[1])]
}
