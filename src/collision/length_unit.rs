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
//! The batch's lanes and the scalar search divide by the same unit, computed by the same
//! function, so they see the same numbers.

use nalgebra::SVector;

use super::prefilter::PairInput;
use crate::gap::Gap;
use crate::motion::Ball;

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

impl LengthUnit {
    /// The unit for a pair whose largest length is `largest` (≥ 0). Branch-free, so that a
    /// batch forms it lane-wise.
    #[inline(always)]
    pub(crate) fn of(largest: f64) -> Self {
        /// 2⁶⁰⁰: brings any subnormal into the normal range, exactly.
        const PRE: f64 = f64::from_bits((1023 + 600) << 52);
        let subnormal = largest < f64::MIN_POSITIVE;
        let pre = if subnormal { PRE } else { 1.0 };
        Self {
            pre,
            scale: normal_scale(largest * pre),
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

/// The power of two that brings a normal `largest` into `[2, 4)`: `2^(1024 − f)`, `f` its
/// exponent field (normal for every field from 1 to 2046). `∞` for a subnormal or zero
/// `largest` (field 0), 0 for an infinite one (field 2047): either turns the pair's numbers
/// into infinities or NaNs.
#[inline(always)]
fn normal_scale(largest: f64) -> f64 {
    const FIELD: u64 = 0x7ff;
    let field = (largest.to_bits() >> 52) & FIELD;
    // At most `FIELD`: a plain subtraction, which vectorises.
    f64::from_bits((FIELD - field) << 52)
}

/// The largest magnitude among `lengths`, NaNs ignored (as a select, which vectorises).
#[inline(always)]
pub(crate) fn largest<const N: usize>(lengths: [f64; N]) -> f64 {
    lengths.iter().fold(0.0, |m: f64, x| {
        let x = x.abs();
        if x > m { x } else { m }
    })
}

/// A block of pairs (the batch's lanes, as rows and per-pair values) put in place in their
/// own units of length, as [`normalised`] puts each pair (with one radius per pair).
///
/// One factor per lane, without [`LengthUnit`]'s pre-scaling of a subnormal largest length:
/// such a pair comes out with infinities or NaNs, which no lane-wise stage accepts (they
/// need every number finite), so it goes to the search, which normalises it in two steps.
/// For every other pair the pre-scaling is by 1, and both give the same numbers.
#[inline(always)]
pub(crate) fn normalise_lanes<const L: usize>(
    pos: [&mut [[f64; 2]; L]; 2],
    vel: [&mut [[f64; 2]; L]; 2],
    friction: [&mut [f64; L]; 2],
    radius: &mut [f64; L],
) {
    let [pos_a, pos_b] = pos;
    let [vel_a, vel_b] = vel;
    let [friction_a, friction_b] = friction;
    // The rows' coordinates first, element by element across the four row blocks (the
    // same lanes' x and y sit side by side), then each lane's x and y, frictions and radius:
    // the same maximum as [`largest`] over the pair's eleven numbers, in vertical operations.
    let bigger = |m: f64, x: f64| {
        let x = x.abs();
        if x > m { x } else { m }
    };
    let mut rows_largest = [[0.0; 2]; L];
    for k in 0..L {
        for axis in 0..2 {
            let m = bigger(0.0, pos_a[k][axis]);
            let m = bigger(m, vel_a[k][axis]);
            let m = bigger(m, pos_b[k][axis]);
            rows_largest[k][axis] = bigger(m, vel_b[k][axis]);
        }
    }
    let mut scales = [0.0; L];
    for (k, scale) in scales.iter_mut().enumerate() {
        let [x, y] = rows_largest[k];
        let m = bigger(bigger(x, y), friction_a[k]);
        *scale = normal_scale(bigger(bigger(m, friction_b[k]), radius[k]));
    }
    for rows in [pos_a, vel_a, pos_b, vel_b] {
        for (row, &scale) in rows.iter_mut().zip(&scales) {
            *row = row.map(|x| x * scale);
        }
    }
    for values in [friction_a, friction_b] {
        for (mu, &scale) in values.iter_mut().zip(&scales) {
            *mu = *mu * scale + 0.0;
        }
    }
    for (r, &scale) in radius.iter_mut().zip(&scales) {
        *r *= scale;
    }
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
