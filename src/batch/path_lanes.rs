//! The path bounds' screen ([`PathBounds::apart`]), eight pairs at a time with AVX-512: a
//! block of pairs of paths read from their rows, every value checked and every path's box
//! formed in the vector registers, one pair per lane, without a branch on the data
//! ([`settled`]). The pairs it settles (valid, their boxes apart) answer "none" at once; the
//! others go on to the pair's own search, which reads them again and reports any error.
//!
//! It is the path bounds' proof, computed the way [`PathBounds::set_to`] and
//! [`PathBounds::reach`] compute it: the same operations in the same order on the same
//! numbers, so that a lane is settled exactly when the pair's own screen would settle it, and
//! the batch's answers are the same bits with or without it. It takes the paths it can take
//! whole: both sides with a path per pair and `K` rows each, every row used with starts that
//! increase strictly, every value finite, a finite size, and no reach that underflow could
//! touch; anything else is left to the pair's own path (which settles it, or names its error).
//!
//! On a pool table half the pairs are settled here, at a few nanoseconds a pair instead of the
//! fifty or so that reading, checking and bounding them one at a time costs.
//!
//! [`PathBounds::apart`]: crate::collision::path_bounds::PathBounds
//! [`PathBounds::set_to`]: crate::collision::path_bounds::PathBounds
//! [`PathBounds::reach`]: crate::collision::path_bounds::PathBounds

use core::arch::x86_64::{
    __m512d, __m512i, __mmask8, _CMP_GE_OQ, _CMP_GT_OQ, _CMP_LT_OQ, _CMP_NEQ_UQ, _mm512_abs_pd,
    _mm512_add_pd, _mm512_cmp_pd_mask, _mm512_i64gather_pd, _mm512_loadu_epi64,
    _mm512_mask_blend_pd, _mm512_max_pd, _mm512_min_pd, _mm512_mul_pd, _mm512_set1_pd,
    _mm512_setzero_pd, _mm512_sub_pd,
};

use super::PerPair;
use super::paths::{PathPairs, PathRows};
use crate::collision::window_box::{MARGIN, NORMAL_FLOOR};

/// Pairs per block: one vector of eight `f64`s.
pub(crate) const LANES: usize = 8;

/// One side's paths of a block, a lane each: which are taken (valid, every row used, starts
/// increasing strictly), and the box, size and spread [`PathBounds`] forms for them.
///
/// [`PathBounds`]: crate::collision::path_bounds::PathBounds
struct LaneBounds<const D: usize> {
    taken: __mmask8,
    lo: [__m512d; D],
    hi: [__m512d; D],
    size: __m512d,
    spread: __m512d,
}

/// Which of pairs `first..first + LANES` are settled (bit `l` for pair `first + l`): both
/// paths taken, radius and horizon valid, and the two paths' boxes farther apart on some axis
/// than the reach.
///
/// # Safety
/// Both sides must hold a path per pair in rows of `K ≥ 1` segments (`start` of `n·K` values,
/// `pos`, `vel`, `acc` of `n·K` rows, as [`path_collision_times`](super::path_collision_times)
/// checks them), per-pair `radius` and `t_max` of `n` values, and `first + LANES ≤ n`.
#[target_feature(enable = "avx512f")]
pub(crate) unsafe fn settled<const D: usize, const K: usize>(
    pairs: &PathPairs<'_, D>,
    first: usize,
) -> __mmask8 {
    // SAFETY: the caller's promise, passed on.
    let (a, b) = unsafe {
        (
            lane_bounds::<D, K>(&pairs.a, first),
            lane_bounds::<D, K>(&pairs.b, first),
        )
    };
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
    let finite = |x: __m512d| {
        _mm512_cmp_pd_mask(_mm512_abs_pd(x), _mm512_set1_pd(f64::INFINITY), _CMP_LT_OQ)
    };
    let valid = _mm512_cmp_pd_mask(radius, zero, _CMP_GT_OQ)
        & finite(radius)
        & _mm512_cmp_pd_mask(t_max, zero, _CMP_GE_OQ)
        & finite(sizes);
    a.taken & b.taken & valid & plain_reach & apart
}

/// The per-pair values of pairs `first..first + LANES`, a lane each.
#[target_feature(enable = "avx512f")]
fn lanes_of(values: PerPair<'_>, first: usize) -> __m512d {
    let lanes: [f64; LANES] = std::array::from_fn(|l| values.get(first + l));
    // SAFETY: `[f64; 8]` and `__m512d` have the same size, and every bit pattern is valid.
    unsafe { std::mem::transmute(lanes) }
}

/// The offsets of row `row` of paths `0..LANES` of a block, in `f64`s from the block's first,
/// for rows of `width` values, `K` rows a path.
#[target_feature(enable = "avx512f")]
fn offsets<const K: usize>(row: usize, width: usize, component: usize) -> __m512i {
    let at: [i64; LANES] = std::array::from_fn(|l| ((l * K + row) * width + component) as i64);
    // SAFETY: reads the eight `i64`s of `at`.
    unsafe { _mm512_loadu_epi64(at.as_ptr()) }
}

/// How many pairs ahead of the block the rows are fetched to the cache: the gathers do not
/// set off the CPU's own prefetching as plain loads in order do.
const AHEAD: usize = 4 * LANES;

/// Asks for `values[from..from + len]` in the cache (nothing past the end).
#[inline(always)]
fn prefetch(values: &[f64], from: usize, len: usize) {
    use core::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
    let Some(values) = values.get(from..(from + len).min(values.len())) else {
        return;
    };
    for line in values.chunks(8) {
        // SAFETY: a hint on an address in the slice; it reads nothing.
        unsafe { _mm_prefetch(line.as_ptr().cast::<i8>(), _MM_HINT_T0) };
    }
}

/// The bounds of paths `first..first + LANES` of `side`, as `PathBounds::set_to` forms them
/// for paths whose rows are all used and whose segments are all non-empty, and the checks of
/// `Path::from_rows` in that case (every value finite, starts increasing).
///
/// # Safety
/// As [`settled`]: the side's rows hold paths `first..first + LANES`, `K` rows each.
#[target_feature(enable = "avx512f")]
unsafe fn lane_bounds<const D: usize, const K: usize>(
    side: &PathRows<'_, D>,
    first: usize,
) -> LaneBounds<D> {
    let zero = _mm512_setzero_pd();
    // Row `k` of every lane: its start, and its position, velocity and acceleration on
    // each axis.
    let gather = |values: *const f64, k: usize, width: usize, i: usize| {
        // SAFETY: the caller's promise: the block's rows are in range of `values`.
        unsafe { _mm512_i64gather_pd(offsets::<K>(k, width, i), values, 8) }
    };
    prefetch(side.start, (first + AHEAD) * K, LANES * K);
    for array in [side.pos, side.vel, side.acc] {
        prefetch(array.as_flattened(), (first + AHEAD) * K * D, LANES * K * D);
    }
    let start = side.start[first * K..].as_ptr();
    let rows = |array: &[[f64; D]]| array[first * K..].as_ptr().cast::<f64>();
    let (pos, vel, acc) = (rows(side.pos), rows(side.vel), rows(side.acc));
    let s: [__m512d; K] = std::array::from_fn(|k| gather(start, k, 1, 0));
    let row = |values: *const f64, k: usize| -> [__m512d; D] {
        std::array::from_fn(|i| gather(values, k, D, i))
    };
    let p: [[__m512d; D]; K] = std::array::from_fn(|k| row(pos, k));
    let v: [[__m512d; D]; K] = std::array::from_fn(|k| row(vel, k));
    let a: [[__m512d; D]; K] = std::array::from_fn(|k| row(acc, k));

    // Starts increasing strictly (NaN fails), from a first above −∞ to a last below +∞: all
    // finite. The other values of every segment but the last are in the size, whose
    // finiteness [`settled`] checks; the last segment's velocity and acceleration here.
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

    let half = _mm512_set1_pd(0.5);
    let one = _mm512_set1_pd(1.0);
    let axes = _mm512_set1_pd(D as f64);
    let mut bounds = LaneBounds {
        taken,
        lo: [_mm512_set1_pd(f64::INFINITY); D],
        hi: [_mm512_set1_pd(f64::NEG_INFINITY); D],
        size: zero,
        spread: zero,
    };
    for k in 0..K - 1 {
        let length = _mm512_sub_pd(s[k + 1], s[k]);
        let reach = _mm512_add_pd(one, length);
        bounds.spread = _mm512_add_pd(
            bounds.spread,
            _mm512_mul_pd(_mm512_mul_pd(axes, reach), reach),
        );
        for i in 0..D {
            let (p, v, a) = (p[k][i], v[k][i], a[k][i]);
            // |p| + (|v| + |a|·L)·L
            let far = _mm512_mul_pd(
                _mm512_add_pd(_mm512_abs_pd(v), _mm512_mul_pd(_mm512_abs_pd(a), length)),
                length,
            );
            bounds.size = _mm512_add_pd(bounds.size, _mm512_add_pd(_mm512_abs_pd(p), far));
            // The Bernstein hull: p, p + ½·v·L, p + (v + ½·a·L)·L.
            let middle = _mm512_add_pd(p, _mm512_mul_pd(_mm512_mul_pd(half, v), length));
            let slope = _mm512_add_pd(v, _mm512_mul_pd(_mm512_mul_pd(half, a), length));
            let end = _mm512_add_pd(p, _mm512_mul_pd(slope, length));
            let lo = _mm512_min_pd(end, _mm512_min_pd(middle, p));
            let hi = _mm512_max_pd(end, _mm512_max_pd(middle, p));
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
        let hi = _mm512_mask_blend_pd(up, p, _mm512_set1_pd(f64::INFINITY));
        bounds.lo[i] = _mm512_min_pd(bounds.lo[i], lo);
        bounds.hi[i] = _mm512_max_pd(bounds.hi[i], hi);
    }
    bounds
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::path_bounds::PathBounds;
    use crate::path::Path2;
    use crate::test_rng::Rng;

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
            let draw_side = |rng: &mut Rng| {
                let (mut start, mut rows) = (vec![], [vec![], vec![], vec![]]);
                for _ in 0..LANES {
                    let mut t = rng.uniform(-1.0, 1.0) * scale;
                    for k in 0..K {
                        start.push(t);
                        t += rng.uniform(0.0, 2.0) * scale;
                        let at_rest = k + 1 == K && rng.below(3) > 0;
                        for (r, rows) in rows.iter_mut().enumerate() {
                            let size = if r == 0 { 3.0 } else { 2.0 };
                            let mut x = || rng.uniform(-size, size) * scale;
                            let row = if r > 0 && at_rest {
                                [0.0; 2]
                            } else {
                                [x(), x()]
                            };
                            rows.push(row);
                        }
                    }
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

        /// Moves pair `l`'s B along x so that its box and A's are the reach apart, to within
        /// a few ulps either way: where the lanes' margin and sizes must be the path bounds'
        /// to the last bit.
        fn on_the_edge(&mut self, l: usize, rng: &mut Rng) -> bool {
            for _ in 0..4 {
                let bounds = |s: usize| {
                    let r = l * K..(l + 1) * K;
                    let [pos, vel, acc] = &self.rows[s];
                    let path = Path2::from_rows(
                        &self.start[s][r.clone()],
                        &pos[r.clone()],
                        &vel[r.clone()],
                        &acc[r],
                    );
                    path.ok().map(|path| PathBounds::<2>::of(path.segments()))
                };
                let (Some(a), Some(b)) = (bounds(0), bounds(1)) else {
                    return false;
                };
                let radius = self.radius[l];
                let gap = b.whole().0[0] - a.whole().1[0];
                let miss = a.reach(&b, radius).distance() - gap;
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
                radius: PerPair::Each(&self.radius),
                t_max: PerPair::Each(&self.t_max),
            }
        }

        /// Pair `l` as the scalar code sees it: `None` if invalid, else whether it is plain
        /// (every row used, starts increasing, finite sizes, a reach underflow cannot touch),
        /// and whether its path bounds are apart.
        fn scalar(&self, l: usize) -> Option<(bool, bool)> {
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
            let (a, b) = (
                PathBounds::<2>::of(a.segments()),
                PathBounds::of(b.segments()),
            );
            let reach = a.reach(&b, radius);
            let plain = plain_a && plain_b && a.plain_reach(&b, radius);
            Some((plain, a.apart(&b, reach)))
        }
    }

    fn lanes_settle_what_the_path_bounds_settle<const K: usize>() {
        if !std::arch::is_x86_feature_detected!("avx512f") {
            eprintln!("no AVX-512 here: the lanes are not run");
            return;
        }
        let mut rng = Rng(K as u64);
        let (mut settled_lanes, mut apart_left, mut plain_kept, mut edge) = (0, 0, 0, 0);
        for _ in 0..4_000 {
            let mut block = Block::<K>::draw(&mut rng);
            for l in 0..LANES {
                if rng.below(2) == 0 {
                    edge += usize::from(block.on_the_edge(l, &mut rng));
                }
            }
            // SAFETY: AVX-512 F is supported; the block's rows hold LANES paths of K rows.
            let settled = unsafe { settled::<2, K>(&block.pairs(), 0) };
            for l in 0..LANES {
                let lane = settled & (1 << l) != 0;
                match block.scalar(l) {
                    // Settled: valid, and the path bounds' own proof.
                    Some((plain, apart)) => {
                        assert!(!lane || (plain && apart), "lane {l} of {:?}", block.pairs());
                        // Plain and apart: the lanes settle it.
                        assert!(!(plain && apart) || lane, "lane {l} of {:?}", block.pairs());
                        settled_lanes += usize::from(lane);
                        apart_left += usize::from(apart && !plain);
                        plain_kept += usize::from(plain && !apart);
                    }
                    None => assert!(!lane, "invalid lane {l} of {:?}", block.pairs()),
                }
            }
        }
        // Each outcome is met many times (else the test could not fail).
        assert!(settled_lanes > 2_000, "{settled_lanes} settled");
        assert!(
            apart_left > 150,
            "{apart_left} apart, left to the pair's screen"
        );
        assert!(plain_kept > 3_000, "{plain_kept} plain, not apart");
        assert!(edge > 2_000, "{edge} on the edge");
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
