//! The closed form for pairs with one ball at rest, lane-wise over [`Simd`]: the lane twin of
//! [`straight::contact`](crate::collision::straight) as the friction batch calls it, the
//! same operations in the same order, so every lane gives the scalar closed form's bits.

use super::eighth_lanes::gap_value_of;
use super::prefilter_lanes::{PairLanes, valid, within};
use crate::simd::{LANES, Mask, Simd};

/// For each lane that is `open`, valid and has one ball at rest, where the closed form
/// applies: its time (`∞` for none, or at or past the horizon); NaN elsewhere. The mover is A
/// unless A rests.
#[inline(always)]
pub(super) fn at_rest_answers<S: Simd>(s: S, p: &PairLanes<S>, open: Mask) -> [f64; LANES] {
    let (rests_a, _) = p.at_rest(s);
    let position = pick(s, rests_a, p.pos_a, p.pos_b);
    let velocity = pick(s, rests_a, p.vel_a, p.vel_b);
    let resting = pick(s, rests_a, p.pos_b, p.pos_a);
    let mu = s.blend(rests_a, p.friction_a, p.friction_b);
    let separation = [s.sub(p.pos_a[0], p.pos_b[0]), s.sub(p.pos_a[1], p.pos_b[1])];
    let g0 = gap_value_of(s, &separation, p.radius);
    let delta = [
        s.sub(position[0], resting[0]),
        s.sub(position[1], resting[1]),
    ];
    let (applies, t) = contact(s, delta, velocity, mu, p.radius, g0);
    let t = s.blend(s.lt(t, p.t_max), s.splat(f64::INFINITY), t);
    s.store(s.blend(open & valid(s, p) & applies, s.splat(f64::NAN), t))
}

/// `b` where the mask's bit is set, else `a`, both coordinates.
#[inline(always)]
fn pick<S: Simd>(s: S, bits: Mask, a: [S::V; 2], b: [S::V; 2]) -> [S::V; 2] {
    [s.blend(bits, a[0], b[0]), s.blend(bits, a[1], b[1])]
}

/// `straight::contact` in each lane: where the closed form settles the pair (in range, and
/// its time sound), and the time (`∞` for no contact).
#[inline(always)]
fn contact<S: Simd>(
    s: S,
    [dx, dy]: [S::V; 2],
    [vx, vy]: [S::V; 2],
    mu: S::V,
    radius: S::V,
    g0: S::V,
) -> (Mask, S::V) {
    let zero = s.zero();
    let speed2 = s.add(s.mul(vx, vx), s.mul(vy, vy));
    // (`|dx|, |dy| ≤ 1e50` for `max(|dx|, |dy|) ≤ 1e50`: they differ only where one is NaN,
    // which the caller's `valid` refuses.)
    let in_range = within(s, speed2, 1e-100, 1e100)
        & within(s, radius, 1e-50, 1e50)
        & s.ge(s.splat(1e50), s.abs(dx))
        & s.ge(s.splat(1e50), s.abs(dy))
        & s.gt(g0, zero);
    let approach = s.add(s.mul(dx, vx), s.mul(dy, vy));
    let cross = s.sub(s.mul(dx, vy), s.mul(dy, vx));
    let minus_cross = s.mul(s.splat(-1.0), cross);
    let disc = s.mul_add(s.mul(radius, radius), speed2, s.mul(minus_cross, cross));
    let speed = s.sqrt(speed2);
    let meets = s.lt(approach, zero) & s.gt(disc, zero);
    // `.max(0.0)` as `x > 0 ? x : 0` (NaN to 0 as `f64::max`; a −0 gives the same sums).
    let d = s.sub(s.sqrt(s.max(disc, zero)), approach);
    let e = s.mul(d, speed);
    let two_g0 = s.mul(s.splat(2.0), g0);
    let m = s.mul(two_g0, mu);
    let before_stop = s.gt(e, m);
    let root = s.sqrt(s.max(s.mul(e, s.sub(e, m)), zero));
    let t = s.mul(s.div(two_g0, s.add(e, root)), speed);
    let finite = s.lt(s.abs(t), s.splat(f64::INFINITY));
    let settled = !meets | !before_stop | (finite & s.ge(e, s.splat(1e-100)));
    let hit = meets & before_stop;
    (in_range & settled, s.blend(hit, s.splat(f64::INFINITY), t))
}
