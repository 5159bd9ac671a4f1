//! The window screens ([`PathBounds::segments_apart`], [`apart_on_window`],
//! [`apart_across_window_chord`]), eight pairs at a time (written once over the operations of
//! [`Simd`], compiled at each level), for the pairs of a block
//! that the whole-path screens ([`path_lanes`](super::path_lanes)) leave: a pair whose every
//! window they prove apart answers "none" at once, without being read again, checked, bounded
//! and walked one window at a time.
//!
//! A path of `K` rows with starts increasing has its windows where a segment of one path and a
//! segment of the other are both active: segment `i` of A and segment `j` of B share the
//! window from the later of their starts to the earlier of their ends, if it is not empty.
//! Every pair `(i, j)` is tried, each lane keeping only its own windows, so that the lanes need
//! no walk and no branch on the data. Each window is proven apart as the pair's own search
//! would prove it ([`first_contact_bounded`]): by its two segments' boxes, or else by the box
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
//! [`first_contact_bounded`]: crate::collision::path_contact

use super::path_lanes::{LaneBoxes, LaneRows};
use crate::collision::LONGEST_WINDOW;
use crate::collision::window_box::{MARGIN, NORMAL_FLOOR};
use crate::simd::Simd;

/// One side of a block for the window screens: its rows and its segment boxes.
pub(super) struct LaneSide<'a, S: Simd, const D: usize, const K: usize> {
    pub(super) rows: &'a LaneRows<S, D, K>,
    pub(super) boxes: &'a LaneBoxes<S, D, K>,
}

/// The relative motion of a block's windows, a lane each: as `window_gap` forms it.
struct LaneGap<S: Simd, const D: usize> {
    offset: [S::V; D],
    velocity: [S::V; D],
    acceleration: [S::V; D],
}

/// Which of the lanes `open` have every window proven apart, at contact distance `radius`,
/// with the pair's whole-path `reach` for the segment boxes (both as `settled` forms them).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
pub(super) fn windows_apart<S: Simd, const D: usize, const K: usize>(
    s: S,
    a: &LaneSide<'_, S, D, K>,
    b: &LaneSide<'_, S, D, K>,
    radius: S::V,
    reach: S::V,
    open: S::M,
) -> S::M {
    let infinity = s.splat(f64::INFINITY);
    let mut proven = open;
    for i in 0..K {
        for j in 0..K {
            let from = s.max(a.rows.s[i], b.rows.s[j]);
            let to = s.min(end(a, i, infinity), end(b, j, infinity));
            let left = proven & s.lt(from, to);
            if !s.any(left) {
                continue;
            }
            let left = left & !segments_apart(s, a.boxes, i, b.boxes, j, reach);
            if !s.any(left) {
                continue;
            }
            if i == K - 1 && j == K - 1 {
                // The window that lasts for ever: the segment boxes only.
                proven &= !left;
                continue;
            }
            let gap = window_gap(s, a.rows, i, b.rows, j, from);
            // `bounded_length`: the window's length up to the longest searched.
            let length = s.min(s.sub(to, from), s.splat(LONGEST_WINDOW));
            let mut left = left & !apart_on_window(s, &gap, radius, length);
            if s.any(left) {
                left &= !apart_across_window_chord(s, &gap, radius, length);
            }
            proven &= !left;
            if !s.any(proven) {
                return proven;
            }
        }
    }
    proven
}

/// Where segment `k` of `side` ends: where the next starts (the last, `infinity`: never).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn end<S: Simd, const D: usize, const K: usize>(
    side: &LaneSide<'_, S, D, K>,
    k: usize,
    infinity: S::V,
) -> S::V {
    if k + 1 < K {
        side.rows.s[k + 1]
    } else {
        infinity
    }
}

/// Segment `(p, v, a)` after `t`: `p + (v + a·(½·t))·t` and `v + a·t`, as
/// `Segment::position_at` and `velocity_at` form them.
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn moved<S: Simd>(s: S, p: S::V, v: S::V, a: S::V, t: S::V) -> (S::V, S::V) {
    let mid = s.add(v, s.mul(a, s.mul(s.splat(0.5), t)));
    (s.add(p, s.mul(mid, t)), s.add(v, s.mul(a, t)))
}

/// `p + (v + ½·a·t)·t` (as `axis_range` forms it).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn axis_at<S: Simd>(s: S, p: S::V, v: S::V, a: S::V, t: S::V) -> S::V {
    s.add(p, s.mul(s.add(v, s.mul(s.mul(s.splat(0.5), a), t)), t))
}

/// `PathBounds::segments_apart` lane-wise: segment `i`'s box of `a` and segment `j`'s of `b`
/// farther apart than `reach` on some axis.
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn segments_apart<S: Simd, const D: usize, const K: usize>(
    s: S,
    a: &LaneBoxes<S, D, K>,
    i: usize,
    b: &LaneBoxes<S, D, K>,
    j: usize,
    reach: S::V,
) -> S::M {
    let mut apart = s.none();
    for x in 0..D {
        apart |= s.gt(s.sub(a.lo[i][x], b.hi[j][x]), reach);
        apart |= s.gt(s.sub(b.lo[j][x], a.hi[i][x]), reach);
    }
    apart
}

/// `window_gap` (`collision::path_contact`) lane-wise: A's segment `i` less B's segment `j`
/// at `start`, each by `Segment::position_at` and `velocity_at`.
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn window_gap<S: Simd, const D: usize, const K: usize>(
    s: S,
    a: &LaneRows<S, D, K>,
    i: usize,
    b: &LaneRows<S, D, K>,
    j: usize,
    start: S::V,
) -> LaneGap<S, D> {
    let (since_a, since_b) = (s.sub(start, a.s[i]), s.sub(start, b.s[j]));
    let zero = s.zero();
    let mut gap = LaneGap {
        offset: [zero; D],
        velocity: [zero; D],
        acceleration: [zero; D],
    };
    for x in 0..D {
        let (pa, va) = moved(s, a.p[i][x], a.v[i][x], a.a[i][x], since_a);
        let (pb, vb) = moved(s, b.p[j][x], b.v[j][x], b.a[j][x], since_b);
        gap.offset[x] = s.sub(pa, pb);
        gap.velocity[x] = s.sub(va, vb);
        gap.acceleration[x] = s.sub(a.a[i][x], b.a[j][x]);
    }
    gap
}

/// `apart_on_window` (`collision::window_box`) lane-wise, where no underflow can count (else
/// not proven).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn apart_on_window<S: Simd, const D: usize>(
    s: S,
    gap: &LaneGap<S, D>,
    radius: S::V,
    length: S::V,
) -> S::M {
    let (zero, one) = (s.zero(), s.splat(1.0));
    let (mut nearest2, mut size, mut spread) = (zero, radius, zero);
    for x in 0..D {
        let (p, v, a) = (gap.offset[x], gap.velocity[x], gap.acceleration[x]);
        // `axis_range`: `p + (v + ½·a·s)·s` at the end and at the turn held to the span.
        let end = axis_at(s, p, v, a, length);
        // (`f64::min` and `max` drop a NaN operand; `min_pd` and `max_pd` return the second
        // operand where either is NaN: the possibly NaN operand comes first.)
        let (lo, hi) = (s.min(end, p), s.max(end, p));
        let turn = s.sub(zero, s.div(v, a));
        let turn = s.min(s.max(turn, zero), length);
        let vertex = axis_at(s, p, v, a, turn);
        let (lo, hi) = (s.min(vertex, lo), s.max(vertex, hi));
        let far = s.add(s.abs(v), s.mul(s.abs(a), length));
        let magnitude = s.add(s.abs(p), s.mul(far, length));
        let reach = s.add(s.add(one, s.abs(v)), length);
        spread = s.add(spread, s.mul(reach, reach));
        let nearest = s.add(s.max(lo, zero), s.max(s.sub(zero, hi), zero));
        nearest2 = s.add(nearest2, s.mul(nearest, nearest));
        size = s.add(size, magnitude);
    }
    let reach = s.add(radius, s.mul(s.splat(MARGIN), size));
    let far = s.mul(reach, reach);
    plain(s, reach, spread) & square_normal(s, far) & s.gt(nearest2, far)
}

/// `apart_across_window_chord` (`collision::window_chord`) lane-wise, where no underflow can
/// count (else not proven).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn apart_across_window_chord<S: Simd, const D: usize>(
    s: S,
    gap: &LaneGap<S, D>,
    radius: S::V,
    length: S::V,
) -> S::M {
    let (d, v, a) = (&gap.offset, &gap.velocity, &gap.acceleration);
    let (zero, one) = (s.zero(), s.splat(1.0));
    let half_length = s.mul(s.splat(0.5), length);
    let mut chord = [s.zero(); D];
    for x in 0..D {
        chord[x] = s.mul(s.add(v[x], s.mul(a[x], half_length)), length);
    }
    let (mut cc, mut dc) = (zero, zero);
    for x in 0..D {
        cc = s.add(cc, s.mul(chord[x], chord[x]));
        dc = s.add(dc, s.mul(d[x], chord[x]));
    }
    let mut normal = [s.zero(); D];
    for x in 0..D {
        normal[x] = s.sub(s.mul(d[x], cc), s.mul(chord[x], dc));
    }
    let mut largest = zero;
    for n in &normal {
        largest = s.max(s.abs(*n), largest);
    }
    let scale = s.div(one, largest);
    let (mut at_start, mut slope, mut bend, mut nn) = (zero, zero, zero, zero);
    let (mut size, mut spread) = (radius, zero);
    for x in 0..D {
        let n = s.mul(normal[x], scale);
        nn = s.add(nn, s.mul(n, n));
        at_start = s.add(at_start, s.mul(n, d[x]));
        slope = s.add(slope, s.mul(n, v[x]));
        bend = s.add(bend, s.mul(n, a[x]));
        let far = s.add(s.abs(v[x]), s.mul(s.abs(a[x]), length));
        size = s.add(size, s.add(s.abs(d[x]), s.mul(far, length)));
        let reach = s.add(s.add(one, s.abs(v[x])), length);
        spread = s.add(spread, s.mul(reach, reach));
    }
    let middle = s.add(at_start, s.mul(slope, half_length));
    let end = s.add(
        at_start,
        s.mul(s.add(slope, s.mul(bend, half_length)), length),
    );
    let lo = s.min(end, s.min(middle, at_start));
    let hi = s.max(end, s.max(middle, at_start));
    let nearest = s.add(s.max(lo, zero), s.max(s.sub(zero, hi), zero));
    let reach = s.add(radius, s.mul(s.splat(MARGIN), size));
    let far = s.mul(s.mul(reach, reach), nn);
    plain(s, reach, spread)
        & s.ge(nn, one)
        & s.gt(nearest, zero)
        & s.gt(s.mul(nearest, nearest), far)
}

/// Lanes whose `reach` is beyond what underflow can cost boxes of `spread` (`with_underflow`
/// leaves it as it is).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn plain<S: Simd>(s: S, reach: S::V, spread: S::V) -> S::M {
    s.ge(reach, s.mul(s.splat(NORMAL_FLOOR), spread))
}

/// Lanes whose squared reach is above [`NORMAL_FLOOR`] (no slack for underflowing squares).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn square_normal<S: Simd>(s: S, far: S::V) -> S::M {
    s.gt(far, s.splat(NORMAL_FLOOR))
}
