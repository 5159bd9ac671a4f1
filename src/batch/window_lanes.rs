//! The window screens ([`PathBounds::segments_apart`], [`apart_on_window`],
//! [`apart_across_window_chord`]), eight pairs at a time (written once over `[f64; 8]` lanes,
//! [`lane_ops`](super::lane_ops), compiled in each copy of the batch), for the pairs of a block
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

#[allow(unused_imports)]
use super::lane_ops::{
    V, abs, add, blend, div, eq, ge, gt, lt, max, min, mul, ne, splat, sqrt, sub, zero,
};

use super::path_lanes::{LaneBoxes, LaneRows};
use crate::collision::LONGEST_WINDOW;
use crate::collision::window_box::{MARGIN, NORMAL_FLOOR};

/// One side of a block for the window screens: its rows and its segment boxes.
pub(super) struct LaneSide<'a, const D: usize, const K: usize> {
    pub(super) rows: &'a LaneRows<D, K>,
    pub(super) boxes: &'a LaneBoxes<D, K>,
}

/// The relative motion of a block's windows, a lane each: as `window_gap` forms it.
struct LaneGap<const D: usize> {
    offset: [V; D],
    velocity: [V; D],
    acceleration: [V; D],
}

/// Which of the lanes `open` have every window proven apart, at contact distance `radius`,
/// with the pair's whole-path `reach` for the segment boxes (both as `settled` forms them).
#[inline(always)]
pub(super) fn windows_apart<const D: usize, const K: usize>(
    a: &LaneSide<'_, D, K>,
    b: &LaneSide<'_, D, K>,
    radius: V,
    reach: V,
    open: u8,
) -> u8 {
    let infinity = splat(f64::INFINITY);
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
            let from = max(a.rows.s[i], b.rows.s[j]);
            let to = min(end(a, i), end(b, j));
            let left = proven & lt(from, to);
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
            let length = min(sub(to, from), splat(LONGEST_WINDOW));
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
#[inline(always)]
fn segments_apart<const D: usize, const K: usize>(
    a: &LaneBoxes<D, K>,
    i: usize,
    b: &LaneBoxes<D, K>,
    j: usize,
    reach: V,
) -> u8 {
    let mut apart: u8 = 0;
    for x in 0..D {
        apart |= gt(sub(a.lo[i][x], b.hi[j][x]), reach);
        apart |= gt(sub(b.lo[j][x], a.hi[i][x]), reach);
    }
    apart
}

/// `window_gap` (`collision::path_contact`) lane-wise: A's segment `i` less B's segment `j`
/// at `start`, each by `Segment::position_at` and `velocity_at`.
#[inline(always)]
fn window_gap<const D: usize, const K: usize>(
    a: &LaneRows<D, K>,
    i: usize,
    b: &LaneRows<D, K>,
    j: usize,
    start: V,
) -> LaneGap<D> {
    let half = splat(0.5);
    let (since_a, since_b) = (sub(start, a.s[i]), sub(start, b.s[j]));
    // `p + (v + a·(½·s))·s` and `v + a·s`.
    let at = |p: V, v: V, acc: V, s: V| {
        let mid = add(v, mul(acc, mul(half, s)));
        (add(p, mul(mid, s)), add(v, mul(acc, s)))
    };
    let zero = zero();
    let mut gap = LaneGap {
        offset: [zero; D],
        velocity: [zero; D],
        acceleration: [zero; D],
    };
    for x in 0..D {
        let (pa, va) = at(a.p[i][x], a.v[i][x], a.a[i][x], since_a);
        let (pb, vb) = at(b.p[j][x], b.v[j][x], b.a[j][x], since_b);
        gap.offset[x] = sub(pa, pb);
        gap.velocity[x] = sub(va, vb);
        gap.acceleration[x] = sub(a.a[i][x], b.a[j][x]);
    }
    gap
}

/// `apart_on_window` (`collision::window_box`) lane-wise, where no underflow can count (else
/// not proven).
#[inline(always)]
fn apart_on_window<const D: usize>(gap: &LaneGap<D>, radius: V, length: V) -> u8 {
    let (zero, half, one) = (zero(), splat(0.5), splat(1.0));
    let (mut nearest2, mut size, mut spread) = (zero, radius, zero);
    for x in 0..D {
        let (p, v, a) = (gap.offset[x], gap.velocity[x], gap.acceleration[x]);
        // `axis_range`: `p + (v + ½·a·s)·s` at the end and at the turn held to the span.
        let at = |s: V| add(p, mul(add(v, mul(mul(half, a), s)), s));
        let end = at(length);
        // (`f64::min` and `max` drop a NaN operand; `min_pd` and `max_pd` return the second
        // operand where either is NaN: the possibly NaN operand comes first.)
        let (lo, hi) = (min(end, p), max(end, p));
        let turn = sub(zero, div(v, a));
        let turn = min(max(turn, zero), length);
        let vertex = at(turn);
        let (lo, hi) = (min(vertex, lo), max(vertex, hi));
        let far = add(abs(v), mul(abs(a), length));
        let magnitude = add(abs(p), mul(far, length));
        let reach = add(add(one, abs(v)), length);
        spread = add(spread, mul(reach, reach));
        let nearest = add(max(lo, zero), max(sub(zero, hi), zero));
        nearest2 = add(nearest2, mul(nearest, nearest));
        size = add(size, magnitude);
    }
    let reach = add(radius, mul(splat(MARGIN), size));
    let far = mul(reach, reach);
    plain(reach, spread) & square_normal(far) & gt(nearest2, far)
}

/// `apart_across_window_chord` (`collision::window_chord`) lane-wise, where no underflow can
/// count (else not proven).
#[inline(always)]
fn apart_across_window_chord<const D: usize>(gap: &LaneGap<D>, radius: V, length: V) -> u8 {
    let (d, v, a) = (&gap.offset, &gap.velocity, &gap.acceleration);
    let (zero, one) = (zero(), splat(1.0));
    let half_length = mul(splat(0.5), length);
    let chord: [V; D] = std::array::from_fn(|x| mul(add(v[x], mul(a[x], half_length)), length));
    let (mut cc, mut dc) = (zero, zero);
    for x in 0..D {
        cc = add(cc, mul(chord[x], chord[x]));
        dc = add(dc, mul(d[x], chord[x]));
    }
    let normal: [V; D] = std::array::from_fn(|x| sub(mul(d[x], cc), mul(chord[x], dc)));
    let mut largest = zero;
    for n in &normal {
        largest = max(abs(*n), largest);
    }
    let scale = div(one, largest);
    let (mut at_start, mut slope, mut bend, mut nn) = (zero, zero, zero, zero);
    let (mut size, mut spread) = (radius, zero);
    for x in 0..D {
        let n = mul(normal[x], scale);
        nn = add(nn, mul(n, n));
        at_start = add(at_start, mul(n, d[x]));
        slope = add(slope, mul(n, v[x]));
        bend = add(bend, mul(n, a[x]));
        let far = add(abs(v[x]), mul(abs(a[x]), length));
        size = add(size, add(abs(d[x]), mul(far, length)));
        let reach = add(add(one, abs(v[x])), length);
        spread = add(spread, mul(reach, reach));
    }
    let middle = add(at_start, mul(slope, half_length));
    let end = add(at_start, mul(add(slope, mul(bend, half_length)), length));
    let lo = min(end, min(middle, at_start));
    let hi = max(end, max(middle, at_start));
    let nearest = add(max(lo, zero), max(sub(zero, hi), zero));
    let reach = add(radius, mul(splat(MARGIN), size));
    let far = mul(mul(reach, reach), nn);
    plain(reach, spread) & ge(nn, one) & gt(nearest, zero) & gt(mul(nearest, nearest), far)
}

/// Lanes whose `reach` is beyond what underflow can cost boxes of `spread` (`with_underflow`
/// leaves it as it is).
#[inline(always)]
fn plain(reach: V, spread: V) -> u8 {
    ge(reach, mul(splat(NORMAL_FLOOR), spread))
}

/// Lanes whose squared reach is above [`NORMAL_FLOOR`] (no slack for underflowing squares).
#[inline(always)]
fn square_normal(far: V) -> u8 {
    gt(far, splat(NORMAL_FLOOR))
}
