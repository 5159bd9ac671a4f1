//! The friction batch's first-window stage over [`Simd`]: the lane twin of
//! [`while_moving`](crate::collision::moving_entry) (two moving balls' first window settled on
//! its first open eighth, or the contact at 0 of balls touching and approaching), with the
//! window formed as [`FirstWindow::of`](crate::collision::crossing::FirstWindow) forms it and
//! the eighth entry of [`eighth_lanes`](super::eighth_lanes): the same operations in the same
//! order, so every lane gives the scalar stage's bits (the batch's tests compare its answers
//! with the scalar search's at every level).

use super::eighth_lanes::{
    GapLanes, UnitLanes, bigger, dot, eighth_entry, first_open_eighth, largest, long_window,
    normal_time_unit,
};
use super::prefilter_lanes::PairLanes;
use crate::collision::LONGEST_WINDOW;
use crate::collision::prefilter::LIMIT;
use crate::simd::{LANES, Mask, Simd};

/// `FirstWindow` in lanes: the friction pair's first window, `[0, min(τ_A, τ_B)]`.
struct FirstWindowLanes<S: Simd> {
    /// The lanes that qualify for the lane-wise stage (`FirstWindow::qualifies`).
    qualifies: S::M,
    /// The relative motion from time 0, in seconds.
    initial: GapLanes<S, 2>,
    /// The same, time in units of `unit`.
    gap: GapLanes<S, 2>,
    /// The window's end in those units.
    end: S::V,
    /// The time unit, a power of two.
    unit: S::V,
}

/// `lo ≤ x ≤ hi`, as two ordered compares (NaN fails both).
#[inline(always)]
fn within<S: Simd>(s: S, x: S::V, lo: f64, hi: f64) -> S::M {
    s.ge(x, s.splat(lo)) & s.ge(s.splat(hi), x)
}

/// The lanes where `x` is finite (`|x| ≤ MAX`; NaN fails).
#[inline(always)]
fn finite<S: Simd>(s: S, x: S::V) -> S::M {
    s.ge(s.splat(f64::MAX), s.abs(x))
}

/// The lanes where both coordinates are at most [`LIMIT`] in magnitude (`FirstWindow::of`'s
/// `max(|x|, |y|) ≤ LIMIT`, which differs only where one is NaN, a pair `valid` refuses).
#[inline(always)]
fn near<S: Simd>(s: S, [x, y]: [S::V; 2]) -> S::M {
    s.ge(s.splat(LIMIT), s.abs(x)) & s.ge(s.splat(LIMIT), s.abs(y))
}

/// `−v / τ`: a component of a ball's friction acceleration.
#[inline(always)]
fn pull<S: Simd>(s: S, v: S::V, tau: S::V) -> S::V {
    s.div(s.mul(s.splat(-1.0), v), tau)
}

/// `prefilter::valid` in each lane.
#[inline(always)]
fn valid<S: Simd>(s: S, p: &PairLanes<S>) -> S::M {
    let zero = s.zero();
    let mut all = s.all();
    for x in [
        p.pos_a[0],
        p.pos_a[1],
        p.vel_a[0],
        p.vel_a[1],
        p.pos_b[0],
        p.pos_b[1],
        p.vel_b[0],
        p.vel_b[1],
        p.friction_a,
        p.friction_b,
        p.radius,
    ] {
        all &= finite(s, x);
    }
    all & s.ge(p.friction_a, zero)
        & s.ge(p.friction_b, zero)
        & s.gt(p.radius, zero)
        & s.ge(p.t_max, zero)
}

impl<S: Simd> FirstWindowLanes<S> {
    /// `FirstWindow::of` in each lane. (Where a lane does not qualify its window's numbers
    /// are never used: every answer below is masked by `qualifies`.)
    #[inline(always)]
    fn of(s: S, p: &PairLanes<S>) -> Self {
        let ([vax, vay], [vbx, vby]) = (p.vel_a, p.vel_b);
        let square_a = s.add(s.mul(vax, vax), s.mul(vay, vay));
        let square_b = s.add(s.mul(vbx, vbx), s.mul(vby, vby));
        let tau_a = s.div(s.sqrt(square_a), p.friction_a);
        let tau_b = s.div(s.sqrt(square_b), p.friction_b);
        let length = s.min(s.min(tau_a, tau_b), s.splat(LONGEST_WINDOW));
        let (lo, hi) = (1.0 / LIMIT, LIMIT);
        let qualifies = valid(s, p)
            & within(s, square_a, lo, hi)
            & within(s, square_b, lo, hi)
            & within(s, p.friction_a, lo, hi)
            & within(s, p.friction_b, lo, hi)
            & near(s, p.pos_a)
            & near(s, p.pos_b)
            & within(s, p.radius, lo, hi)
            & s.ge(length, s.splat(f64::MIN_POSITIVE));
        let unit = normal_time_unit(s, length);
        let initial = GapLanes {
            offset: [s.sub(p.pos_a[0], p.pos_b[0]), s.sub(p.pos_a[1], p.pos_b[1])],
            velocity: [s.sub(vax, vbx), s.sub(vay, vby)],
            acceleration: [
                s.sub(pull(s, vax, tau_a), pull(s, vbx, tau_b)),
                s.sub(pull(s, vay, tau_a), pull(s, vby, tau_b)),
            ],
            radius: p.radius,
        };
        Self {
            qualifies: qualifies & !long_window(s, &initial, length),
            gap: initial.time_scaled(s, unit),
            initial,
            end: s.div(length, unit),
            unit,
        }
    }
}

/// `approaching` in each lane: balls touching or overlapping at the start move into each
/// other (the first non-zero derivative of the gap is negative), in the unit of the motion's
/// own largest length.
#[inline(always)]
fn approaching<S: Simd>(s: S, gap: &GapLanes<S, 2>) -> S::M {
    let mut size = bigger(s, s.zero(), largest(s, &gap.offset));
    size = bigger(s, size, largest(s, &gap.velocity));
    size = bigger(s, size, largest(s, &gap.acceleration));
    let gap = gap.in_unit(s, UnitLanes::of(s, size));
    let zero = s.zero();
    let slope = gap.half_slope(s, zero);
    let curvature = gap.half_curvature(s, zero);
    let third = dot(s, &gap.velocity, &gap.acceleration);
    let flat = s.eq(slope, zero);
    s.lt(slope, zero)
        | (flat & s.lt(curvature, zero))
        | (flat & s.eq(curvature, zero) & s.lt(third, zero))
}

/// `while_moving` in each lane of `p` (pairs in their own units of length): the first
/// contact where the first window settles it (its time, `∞` at or past the horizon; NaN
/// elsewhere), and the lanes whose first window is screened out.
#[inline(always)]
pub(super) fn while_moving<S: Simd>(s: S, p: &PairLanes<S>) -> ([f64; LANES], Mask) {
    let window = FirstWindowLanes::of(s, p);
    let eighth = first_open_eighth(s, &window.gap, window.end);
    let found = eighth_entry(s, &window.gap, window.end, &eighth, window.qualifies);
    let t = s.mul(found.entry, window.unit);
    let infinity = s.splat(f64::INFINITY);
    let cut = s.blend(s.lt(t, p.t_max), infinity, t);
    let entry = s.blend(found.found, s.splat(f64::NAN), cut);
    // Balls touching and approaching at the start: a contact at 0, `∞` if the horizon is 0.
    let zero = s.zero();
    let touching = window.qualifies
        & s.ge(zero, window.initial.value(s, zero))
        & approaching(s, &window.initial);
    let now = s.blend(s.gt(p.t_max, zero), infinity, zero);
    (
        s.store(s.blend(touching, entry, now)),
        s.bits(found.screened_out),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::length_unit::normalised;
    use crate::collision::moving_entry::while_moving_one;
    use crate::collision::prefilter::PairInput;
    use crate::simd::{Kernel, dispatch, test_levels};
    use crate::test_rng::Rng;

    /// The lanes' answers for a block of pairs.
    struct Block<'a>(&'a [PairInput; LANES]);

    impl Kernel for Block<'_> {
        type Output = ([f64; LANES], Mask);

        #[inline(always)]
        fn run<S: Simd>(self, s: S) -> Self::Output {
            while_moving(s, &PairLanes::of_inputs(s, self.0))
        }
    }

    #[test]
    fn the_lanes_give_the_scalar_stages_bits_at_every_level() {
        // Close moving pairs on a table (contacts, grazes, near misses), some touching at the
        // start, some with a horizon.
        let mut rng = Rng(36);
        let (mut found, mut free) = (0, 0);
        for _ in 0..4_000 {
            let pairs: [PairInput; LANES] = std::array::from_fn(|_| {
                let pos_a = [rng.uniform(0.0, 2.54), rng.uniform(0.0, 1.27)];
                let near = rng.uniform(-0.25, 0.25);
                let pos_b = [pos_a[0] + near, pos_a[1] + rng.uniform(-0.25, 0.25)];
                let mut velocity = || {
                    let (speed, angle) = (rng.uniform(0.01, 3.0), rng.uniform(0.0, 6.3));
                    [speed * angle.cos(), speed * angle.sin()]
                };
                let (vel_a, vel_b) = (velocity(), velocity());
                let t_max = if rng.below(6) == 0 {
                    rng.uniform(0.0, 1.0)
                } else {
                    f64::INFINITY
                };
                let pair = PairInput {
                    pos_a,
                    vel_a,
                    friction_a: rng.uniform(0.05, 2.0),
                    pos_b,
                    vel_b,
                    friction_b: rng.uniform(0.05, 2.0),
                    radius: 0.05715,
                    t_max,
                };
                normalised(&pair, 0.0)
            });
            for level in test_levels() {
                let (entries, screened_out) = dispatch(level, Block(&pairs));
                for (l, pair) in pairs.iter().enumerate() {
                    let one = while_moving_one(pair);
                    assert_eq!(
                        entries[l].to_bits(),
                        one.entry.to_bits(),
                        "{level}: {pair:?}"
                    );
                    let lane_free = screened_out >> l & 1 != 0;
                    assert_eq!(lane_free, one.screened_out, "{level}: {pair:?}");
                    found += usize::from(!one.entry.is_nan());
                    free += usize::from(one.screened_out);
                }
            }
        }
        // Both findings, often (else the test could not fail).
        assert!(found > 1_000 && free > 1_000, "{found} found, {free} free");
    }
}
