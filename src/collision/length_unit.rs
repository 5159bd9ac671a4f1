//! Every pair is searched in its own unit of length: a power of two, chosen from the pair's
//! largest length, by which all its lengths (positions, velocities, frictions, radii) are
//! divided before any arithmetic.
//!
//! Scaling by a power of two is exact, and so is every correctly rounded operation on scaled
//! numbers (as long as nothing overflows or underflows), so the answers do not depend on the
//! caller's unit of length, bit for bit, over the whole float range: a pair given in metres,
//! in light years or in units of 2⁻⁹⁰⁰ is the same pair here. It also keeps the search's
//! squares and sums finite where the caller's numbers are near `f64::MAX` (positions of
//! `±1e308`, a sum of two radii that would overflow), and normal where they are near the
//! underflow. Times are not scaled: a time is a length divided by a speed.
//!
//! The batch's lanes (`batch/prefilter_lanes.rs`, `batch/eighth_lanes.rs`) and the scalar
//! search divide by the same unit, formed by the same operations (the scale by the SIMD
//! layer's `unit_scale`), so they see the same numbers.

use nalgebra::SVector;

use super::prefilter::PairInput;
use crate::gap::Gap;
use crate::motion::Ball;
use crate::simd::unit_scale;

/// The unit of a pair whose largest length (in magnitude) is `largest`: multiplying by
/// [`LengthUnit::apply`] brings `largest` into `[2, 4)`, exactly.
///
/// Two factors, so that the unit can be as small as the smallest subnormal: `pre` brings a
/// subnormal `largest` into the normal range first (`2⁶⁰⁰`, or 1), and `scale` is then a
/// normal power of two. A NaN `largest` is ignored by the `max` that forms it; an infinite one
/// (or 0, never valid: a radius is positive) gives a factor of 0 or ∞, which turns the pair's
/// numbers into NaN, so an invalid pair stays invalid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct LengthUnit {
    pre: f64,
    scale: f64,
}

/// 2⁶⁰⁰: [`LengthUnit`]'s pre-scaling, which brings any subnormal into the normal range,
/// exactly.
pub(crate) const PRE: f64 = f64::from_bits((1023 + 600) << 52);

impl LengthUnit {
    /// The unit for a pair whose largest length is `largest` (≥ 0). Branch-free, so that a
    /// batch forms it lane-wise.
    #[inline(always)]
    pub(crate) fn of(largest: f64) -> Self {
        let subnormal = largest < f64::MIN_POSITIVE;
        let pre = if subnormal { PRE } else { 1.0 };
        Self {
            pre,
            scale: unit_scale(largest * pre),
        }
    }

    /// `x` in this unit.
    #[inline(always)]
    pub(crate) fn apply(self, x: f64) -> f64 {
        x * self.pre * self.scale
    }

    /// A friction in this unit, with `−0.0` made `+0.0`: a friction of `−0` is no friction,
    /// and a stop time formed from it must be `+∞`, not `−∞`.
    #[inline(always)]
    pub(crate) fn friction(self, mu: f64) -> f64 {
        self.apply(mu) + 0.0
    }

    /// A length in this unit back in the caller's: exact where the result is normal (the
    /// two powers of two divided out one after the other, as their product may overflow).
    #[inline(always)]
    pub(crate) fn restore(self, x: f64) -> f64 {
        x / self.scale / self.pre
    }
}

/// The unit of length of the largest magnitude `big` ([`LengthUnit::of`]), or a unit of 1
/// where `big` is 0, infinite or NaN (nothing to scale, or nothing scaling can save).
#[inline]
pub(crate) fn unit_of_largest(big: f64) -> LengthUnit {
    LengthUnit::of(if big > 0.0 && big.is_finite() {
        big
    } else {
        1.0
    })
}

/// `|v|` without overflow or underflow of the squares, for any finite `v`: formed in the unit
/// of `v`'s largest component, so that `2^k·v` has `2^k·|v|` to the bit (a scene scaled by a
/// power of two keeps its bits, contract §1). A zero, infinite or NaN `v` gives what `v.norm()`
/// gives (in a unit of 1).
#[inline]
pub(crate) fn norm_in_range<const D: usize>(v: &SVector<f64, D>) -> f64 {
    let unit = unit_of_largest(v.amax());
    unit.restore(v.map(|x| unit.apply(x)).norm())
}

impl<const D: usize> Gap<D> {
    /// The same motion with every field (all lengths, in a window's time units; the offset
    /// and the radius at least) multiplied by `unit`: exact where nothing overflows or
    /// underflows.
    #[inline(always)]
    pub(crate) fn in_unit(&self, unit: LengthUnit) -> Self {
        let u = |x: SVector<f64, D>| x.map(|c| unit.apply(c));
        Self {
            offset: u(self.offset),
            velocity: u(self.velocity),
            acceleration: u(self.acceleration),
            contact_distance: unit.apply(self.contact_distance),
        }
    }
}

/// The largest magnitude among `lengths`, NaNs ignored (as a select, which vectorises).
#[inline(always)]
pub(crate) fn largest<const N: usize>(lengths: [f64; N]) -> f64 {
    lengths.iter().fold(0.0, |m: f64, x| {
        let x = x.abs();
        if x > m { x } else { m }
    })
}

/// `pair` in its own unit of length, its radius the sum of `pair.radius` and `radius_b` (two
/// radii: their sum may overflow where the scaled sum does not). The horizon is a time and
/// stays.
#[inline(always)]
pub(crate) fn normalised(pair: &PairInput, radius_b: f64) -> PairInput {
    let [pax, pay] = pair.pos_a;
    let [vax, vay] = pair.vel_a;
    let [pbx, pby] = pair.pos_b;
    let [vbx, vby] = pair.vel_b;
    let unit = LengthUnit::of(largest::<12>([
        pax,
        pay,
        vax,
        vay,
        pair.friction_a,
        pbx,
        pby,
        vbx,
        vby,
        pair.friction_b,
        pair.radius,
        radius_b,
    ]));
    let u = |x: f64| unit.apply(x);
    PairInput {
        pos_a: [u(pax), u(pay)],
        vel_a: [u(vax), u(vay)],
        friction_a: unit.friction(pair.friction_a),
        pos_b: [u(pbx), u(pby)],
        vel_b: [u(vbx), u(vby)],
        friction_b: unit.friction(pair.friction_b),
        radius: u(pair.radius) + u(radius_b),
        t_max: pair.t_max,
    }
}

/// Two valid balls and their radii in the pair's own unit of length ([`normalised`]): the
/// balls (their stop times formed anew, from the scaled numbers, as the lanes form them) and
/// the contact distance.
pub(crate) fn normalised_balls(a: &Ball, b: &Ball, radii: [f64; 2]) -> (Ball, Ball, f64) {
    let p = normalised(&PairInput::of(a, b, radii[0], f64::INFINITY), radii[1]);
    (
        Ball::from_checked(p.pos_a, p.vel_a, p.friction_a),
        Ball::from_checked(p.pos_b, p.vel_b, p.friction_b),
        p.radius,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_unit_brings_the_largest_length_into_two_to_four() {
        for k in -1074..=1023 {
            for m in [1.0, 1.5, 1.999_999_999] {
                let largest = m * 2f64.powi(k);
                if largest == 0.0 {
                    continue;
                }
                let unit = LengthUnit::of(largest);
                let x = unit.apply(largest);
                assert!((2.0..4.0).contains(&x), "2^{k}·{m}: {x}");
            }
        }
        assert_eq!(
            LengthUnit::of(f64::MAX).apply(f64::MAX),
            f64::MAX / 2f64.powi(1022)
        );
    }

    #[test]
    fn an_infinite_length_leaves_a_nan() {
        let unit = LengthUnit::of(f64::INFINITY);
        assert!(unit.apply(f64::INFINITY).is_nan() || unit.apply(1.0) == 0.0);
        assert!(unit.apply(f64::INFINITY).is_nan());
    }

    #[test]
    fn minus_zero_friction_becomes_plus_zero() {
        let unit = LengthUnit::of(1.0);
        assert!(unit.friction(-0.0).is_sign_positive());
        assert_eq!(unit.friction(-1.0), -2.0); // still invalid
    }

    #[test]
    fn a_pair_scaled_by_a_power_of_two_normalises_to_the_same_numbers() {
        let pair = PairInput {
            pos_a: [0.3, -1.25],
            vel_a: [2.0, 0.1],
            friction_a: 0.2,
            pos_b: [1.0, 0.0],
            vel_b: [0.0, -0.0],
            friction_b: 0.0,
            radius: 0.05715,
            t_max: 3.0,
        };
        let base = normalised(&pair, 0.0);
        for k in [-1000, -600, -100, -1, 1, 100, 600, 1000] {
            let s = 2f64.powi(k);
            let scaled = PairInput {
                pos_a: pair.pos_a.map(|x| x * s),
                vel_a: pair.vel_a.map(|x| x * s),
                friction_a: pair.friction_a * s,
                pos_b: pair.pos_b.map(|x| x * s),
                vel_b: pair.vel_b.map(|x| x * s),
                friction_b: pair.friction_b * s,
                radius: pair.radius * s,
                t_max: pair.t_max,
            };
            assert_eq!(normalised(&scaled, 0.0), base, "2^{k}");
        }
    }
}
