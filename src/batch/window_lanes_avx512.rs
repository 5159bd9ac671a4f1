//! The AVX-512 copy of [`window_lanes`](super::window_lanes), in intrinsics (see
//! [`path_lanes_avx512`](super::path_lanes_avx512)).
//!
//! The window screens ([`PathBounds::segments_apart`], [`apart_on_window`],
//! [`apart_across_window_chord`]), eight pairs at a time with AVX-512, for the pairs of a block
//! that the whole-path screens ([`path_lanes`](super::path_lanes)) leave: a pair whose every
//! window they prove apart answers "none" at once, without being read again, checked, bounded
//! and walked one window at a time.
//!
//! A path of `K` rows with starts increasing has its windows where a segment of one path and a
//! segment of the other are both active: segment `i` of A and segment `j` of B share the
//! window from the later of their starts to the earlier of their ends, if it is not empty.
//! Every pair `(i, j)` is tried, each lane keeping only its own windows, so that the lanes need
//! no walk and no branch on the data. Each window is proven apart as the pair's own search
//! would prove it ([`first_bounded_contact`]): by its two segments' boxes, or else by the box
//! or the chord of its separation, formed from the two segments' own inputs in time since
//! their own starts; the window that lasts for ever only by the segment boxes (the search
//! would bound its length first). Where the pair's search would find the same proof, the
//! operations and their order are the same; these run on the caller's numbers rather than in
//! the pair's unit of length, which changes no bit in the normal range, and they take a proof
//! only where no underflow can count (as the whole-path lanes do). So a pair settled here has
//! no contact, by the same margin, and for pairs of ordinary magnitudes exactly the pairs
//! whose windows the search would all prove apart are settled.
//!
//! On the seed model written as paths about half the pairs that the whole-path screens leave
//! are settled here: those that pass each other at different times, or at an angle.
//!
//! [`PathBounds::segments_apart`]: crate::collision::path_bounds::PathBounds
//! [`apart_on_window`]: crate::collision::window_box
//! [`apart_across_window_chord`]: crate::collision::window_chord
//! [`first_bounded_contact`]: crate::collision::path_contact

use core::arch::x86_64::{
    __m512d, __mmask8, _CMP_GE_OQ, _CMP_GT_OQ, _CMP_LT_OQ, _mm512_abs_pd, _mm512_add_pd,
    _mm512_cmp_pd_mask, _mm512_div_pd, _mm512_max_pd, _mm512_min_pd, _mm512_mul_pd, _mm512_set1_pd,
    _mm512_setzero_pd, _mm512_sub_pd,
};

use super::path_lanes_avx512::{LaneBoxes, LaneRows};
use crate::collision::LONGEST_WINDOW;
use crate::collision::window_box::{MARGIN, NORMAL_FLOOR};

/// One side of a block for the window screens: its rows and its segment boxes.
pub(super) struct LaneSide<'a, const D: usize, const K: usize> {
    pub(super) rows: &'a LaneRows<D, K>,
    pub(super) boxes: &'a LaneBoxes<D, K>,
}

/// The relative motion of a block's windows, a lane each: as `window_gap` forms it.
struct LaneGap<const D: usize> {
    offset: [__m512d; D],
    velocity: [__m512d; D],
    acceleration: [__m512d; D],
}

/// Which of the lanes `open` have every window proven apart, at contact distance `radius`,
/// with the pair's whole-path `reach` for the segment boxes (both as `settled` forms them).
#[inline]
#[target_feature(enable = "avx512f")]
pub(super) fn windows_apart<const D: usize, const K: usize>(
    a: &LaneSide<'_, D, K>,
    b: &LaneSide<'_, D, K>,
    radius: __m512d,
    reach: __m512d,
    open: __mmask8,
) -> __mmask8 {
    let infinity = _mm512_set1_pd(f64::INFINITY);
    let end = |side: &LaneSide<'_, D, K>, k: usize| {
        if k + 1 < K {
            side.rows.s[k + 1]
        } else {
            infinity
        }
    };
    let mut proven = open;
    for i in 0..K {
        for j in 0..K {
            let from = _mm512_max_pd(a.rows.s[i], b.rows.s[j]);
            let to = _mm512_min_pd(end(a, i), end(b, j));
            let left = proven & _mm512_cmp_pd_mask(from, to, _CMP_LT_OQ);
            if left == 0 {
                continue;
            }
            let left = left & !segments_apart(a.boxes, i, b.boxes, j, reach);
            if left == 0 {
                continue;
            }
            if i == K - 1 && j == K - 1 {
                // The window that lasts for ever: the segment boxes only.
                proven &= !left;
                continue;
            }
            let gap = window_gap(a.rows, i, b.rows, j, from);
            // `bounded_length`: the window's length up to the longest searched.
            let length = _mm512_min_pd(_mm512_sub_pd(to, from), _mm512_set1_pd(LONGEST_WINDOW));
            let mut left = left & !apart_on_window(&gap, radius, length);
            if left != 0 {
                left &= !apart_across_window_chord(&gap, radius, length);
            }
            proven &= !left;
            if proven == 0 {
                return 0;
            }
        }
    }
    proven
}

/// `PathBounds::segments_apart` lane-wise: segment `i`'s box of `a` and segment `j`'s of `b`
/// farther apart than `reach` on some axis.
#[inline]
#[target_feature(enable = "avx512f")]
fn segments_apart<const D: usize, const K: usize>(
    a: &LaneBoxes<D, K>,
    i: usize,
    b: &LaneBoxes<D, K>,
    j: usize,
    reach: __m512d,
) -> __mmask8 {
    let mut apart: __mmask8 = 0;
    for x in 0..D {
        apart |= _mm512_cmp_pd_mask(_mm512_sub_pd(a.lo[i][x], b.hi[j][x]), reach, _CMP_GT_OQ);
        apart |= _mm512_cmp_pd_mask(_mm512_sub_pd(b.lo[j][x], a.hi[i][x]), reach, _CMP_GT_OQ);
    }
    apart
}

/// `window_gap` (`collision::path_contact`) lane-wise: A's segment `i` less B's segment `j`
/// at `start`, each by `Segment::position_at` and `velocity_at`.
#[inline]
#[target_feature(enable = "avx512f")]
fn window_gap<const D: usize, const K: usize>(
    a: &LaneRows<D, K>,
    i: usize,
    b: &LaneRows<D, K>,
    j: usize,
    start: __m512d,
) -> LaneGap<D> {
    let half = _mm512_set1_pd(0.5);
    let (since_a, since_b) = (_mm512_sub_pd(start, a.s[i]), _mm512_sub_pd(start, b.s[j]));
    // `p + (v + a·(½·s))·s` and `v + a·s`.
    let at = |p: __m512d, v: __m512d, acc: __m512d, s: __m512d| {
        let mid = _mm512_add_pd(v, _mm512_mul_pd(acc, _mm512_mul_pd(half, s)));
        (
            _mm512_add_pd(p, _mm512_mul_pd(mid, s)),
            _mm512_add_pd(v, _mm512_mul_pd(acc, s)),
        )
    };
    let zero = _mm512_setzero_pd();
    let mut gap = LaneGap {
        offset: [zero; D],
        velocity: [zero; D],
        acceleration: [zero; D],
    };
    for x in 0..D {
        let (pa, va) = at(a.p[i][x], a.v[i][x], a.a[i][x], since_a);
        let (pb, vb) = at(b.p[j][x], b.v[j][x], b.a[j][x], since_b);
        gap.offset[x] = _mm512_sub_pd(pa, pb);
        gap.velocity[x] = _mm512_sub_pd(va, vb);
        gap.acceleration[x] = _mm512_sub_pd(a.a[i][x], b.a[j][x]);
    }
    gap
}

/// `apart_on_window` (`collision::window_box`) lane-wise, where no underflow can count (else
/// not proven).
#[inline]
#[target_feature(enable = "avx512f")]
fn apart_on_window<const D: usize>(gap: &LaneGap<D>, radius: __m512d, length: __m512d) -> __mmask8 {
    let (zero, half, one) = (
        _mm512_setzero_pd(),
        _mm512_set1_pd(0.5),
        _mm512_set1_pd(1.0),
    );
    let (mut nearest2, mut size, mut spread) = (zero, radius, zero);
    for x in 0..D {
        let (p, v, a) = (gap.offset[x], gap.velocity[x], gap.acceleration[x]);
        // `axis_range`: `p + (v + ½·a·s)·s` at the end and at the turn held to the span.
        let at = |s: __m512d| {
            _mm512_add_pd(
                p,
                _mm512_mul_pd(
                    _mm512_add_pd(v, _mm512_mul_pd(_mm512_mul_pd(half, a), s)),
                    s,
                ),
            )
        };
        let end = at(length);
        // (`f64::min` and `max` drop a NaN operand; `min_pd` and `max_pd` return the second
        // operand where either is NaN: the possibly NaN operand comes first.)
        let (lo, hi) = (_mm512_min_pd(end, p), _mm512_max_pd(end, p));
        let turn = _mm512_sub_pd(zero, _mm512_div_pd(v, a));
        let turn = _mm512_min_pd(_mm512_max_pd(turn, zero), length);
        let vertex = at(turn);
        let (lo, hi) = (_mm512_min_pd(vertex, lo), _mm512_max_pd(vertex, hi));
        let far = _mm512_add_pd(_mm512_abs_pd(v), _mm512_mul_pd(_mm512_abs_pd(a), length));
        let magnitude = _mm512_add_pd(_mm512_abs_pd(p), _mm512_mul_pd(far, length));
        let reach = _mm512_add_pd(_mm512_add_pd(one, _mm512_abs_pd(v)), length);
        spread = _mm512_add_pd(spread, _mm512_mul_pd(reach, reach));
        let nearest = _mm512_add_pd(
            _mm512_max_pd(lo, zero),
            _mm512_max_pd(_mm512_sub_pd(zero, hi), zero),
        );
        nearest2 = _mm512_add_pd(nearest2, _mm512_mul_pd(nearest, nearest));
        size = _mm512_add_pd(size, magnitude);
    }
    let reach = _mm512_add_pd(radius, _mm512_mul_pd(_mm512_set1_pd(MARGIN), size));
    let far = _mm512_mul_pd(reach, reach);
    plain(reach, spread) & square_normal(far) & _mm512_cmp_pd_mask(nearest2, far, _CMP_GT_OQ)
}

/// `apart_across_window_chord` (`collision::window_chord`) lane-wise, where no underflow can
/// count (else not proven).
#[inline]
#[target_feature(enable = "avx512f")]
fn apart_across_window_chord<const D: usize>(
    gap: &LaneGap<D>,
    radius: __m512d,
    length: __m512d,
) -> __mmask8 {
    let (d, v, a) = (&gap.offset, &gap.velocity, &gap.acceleration);
    let (zero, one) = (_mm512_setzero_pd(), _mm512_set1_pd(1.0));
    let half_length = _mm512_mul_pd(_mm512_set1_pd(0.5), length);
    let chord: [__m512d; D] = std::array::from_fn(|x| {
        _mm512_mul_pd(
            _mm512_add_pd(v[x], _mm512_mul_pd(a[x], half_length)),
            length,
        )
    });
    let (mut cc, mut dc) = (zero, zero);
    for x in 0..D {
        cc = _mm512_add_pd(cc, _mm512_mul_pd(chord[x], chord[x]));
        dc = _mm512_add_pd(dc, _mm512_mul_pd(d[x], chord[x]));
    }
    let normal: [__m512d; D] = std::array::from_fn(|x| {
        _mm512_sub_pd(_mm512_mul_pd(d[x], cc), _mm512_mul_pd(chord[x], dc))
    });
    let mut largest = zero;
    for n in &normal {
        largest = _mm512_max_pd(_mm512_abs_pd(*n), largest);
    }
    let scale = _mm512_div_pd(one, largest);
    let (mut at_start, mut slope, mut bend, mut nn) = (zero, zero, zero, zero);
    let (mut size, mut spread) = (radius, zero);
    for x in 0..D {
        let n = _mm512_mul_pd(normal[x], scale);
        nn = _mm512_add_pd(nn, _mm512_mul_pd(n, n));
        at_start = _mm512_add_pd(at_start, _mm512_mul_pd(n, d[x]));
        slope = _mm512_add_pd(slope, _mm512_mul_pd(n, v[x]));
        bend = _mm512_add_pd(bend, _mm512_mul_pd(n, a[x]));
        let far = _mm512_add_pd(
            _mm512_abs_pd(v[x]),
            _mm512_mul_pd(_mm512_abs_pd(a[x]), length),
        );
        size = _mm512_add_pd(
            size,
            _mm512_add_pd(_mm512_abs_pd(d[x]), _mm512_mul_pd(far, length)),
        );
        let reach = _mm512_add_pd(_mm512_add_pd(one, _mm512_abs_pd(v[x])), length);
        spread = _mm512_add_pd(spread, _mm512_mul_pd(reach, reach));
    }
    let middle = _mm512_add_pd(at_start, _mm512_mul_pd(slope, half_length));
    let end = _mm512_add_pd(
        at_start,
        _mm512_mul_pd(
            _mm512_add_pd(slope, _mm512_mul_pd(bend, half_length)),
            length,
        ),
    );
    let lo = _mm512_min_pd(end, _mm512_min_pd(middle, at_start));
    let hi = _mm512_max_pd(end, _mm512_max_pd(middle, at_start));
    let nearest = _mm512_add_pd(
        _mm512_max_pd(lo, zero),
        _mm512_max_pd(_mm512_sub_pd(zero, hi), zero),
    );
    let reach = _mm512_add_pd(radius, _mm512_mul_pd(_mm512_set1_pd(MARGIN), size));
    let far = _mm512_mul_pd(_mm512_mul_pd(reach, reach), nn);
    plain(reach, spread)
        & _mm512_cmp_pd_mask(nn, one, _CMP_GE_OQ)
        & _mm512_cmp_pd_mask(nearest, zero, _CMP_GT_OQ)
        & _mm512_cmp_pd_mask(_mm512_mul_pd(nearest, nearest), far, _CMP_GT_OQ)
}

/// Lanes whose `reach` is beyond what underflow can cost boxes of `spread` (`with_underflow`
/// leaves it as it is).
#[inline]
#[target_feature(enable = "avx512f")]
fn plain(reach: __m512d, spread: __m512d) -> __mmask8 {
    _mm512_cmp_pd_mask(
        reach,
        _mm512_mul_pd(_mm512_set1_pd(NORMAL_FLOOR), spread),
        _CMP_GE_OQ,
    )
}

/// Lanes whose squared reach is above [`NORMAL_FLOOR`] (no slack for underflowing squares).
#[inline]
#[target_feature(enable = "avx512f")]
fn square_normal(far: __m512d) -> __mmask8 {
    _mm512_cmp_pd_mask(far, _mm512_set1_pd(NORMAL_FLOOR), _CMP_GT_OQ)
}
