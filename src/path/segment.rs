//! [`Segment`]: one piece of a path, moving with constant acceleration from its start time.

use nalgebra::SVector;

/// One piece of a [`Path`](super::Path): from the absolute time `start` on, the centre moves
/// with constant acceleration,
///
/// `x(t) = position + velocity·(t − start) + ½·acceleration·(t − start)²`.
///
/// A segment is plain data and takes any values; a [`Path`](super::Path) checks them (finite,
/// starts in order) and decides until when each segment lasts.
///
/// ```
/// use ballcollide::path::Segment;
/// use nalgebra::Vector3;
///
/// // Thrown up at 10 m/s from the floor at t = 2 s, under a gravity of 10 m/s².
/// let up = Vector3::new(0.0, 0.0, 10.0);
/// let throw = Segment::new(2.0, Vector3::zeros(), up, -up);
/// assert_eq!(throw.position_at(3.0), Vector3::new(0.0, 0.0, 5.0)); // the top, 1 s later
/// assert_eq!(throw.velocity_at(3.0), Vector3::zeros());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment<const D: usize> {
    /// The absolute time at which the segment begins.
    pub start: f64,
    /// The centre at `start`.
    pub position: SVector<f64, D>,
    /// The velocity at `start`.
    pub velocity: SVector<f64, D>,
    /// The constant acceleration.
    pub acceleration: SVector<f64, D>,
}

/// A segment in the plane.
pub type Segment2 = Segment<2>;

/// A segment in space.
pub type Segment3 = Segment<3>;

impl<const D: usize> Segment<D> {
    /// The segment beginning at `start` at `position` with `velocity` and `acceleration`.
    ///
    /// ```
    /// use ballcollide::path::Segment2;
    /// use nalgebra::Vector2;
    /// let (p, v, a) = (Vector2::new(1.0, 0.5), Vector2::new(0.2, 0.0), Vector2::new(-0.1, 0.0));
    /// let roll = Segment2::new(1.5, p, v, a);
    /// assert_eq!(roll.start, 1.5);
    /// assert_eq!(roll.acceleration, Vector2::new(-0.1, 0.0));
    /// ```
    pub const fn new(
        start: f64,
        position: SVector<f64, D>,
        velocity: SVector<f64, D>,
        acceleration: SVector<f64, D>,
    ) -> Self {
        Self {
            start,
            position,
            velocity,
            acceleration,
        }
    }

    /// A segment at rest at `position` from `start` on (`velocity = acceleration = 0`).
    ///
    /// ```
    /// use ballcollide::path::Segment2;
    /// use nalgebra::Vector2;
    /// let rest = Segment2::at_rest(4.0, Vector2::new(1.0, 2.0));
    /// assert_eq!(rest.position_at(100.0), Vector2::new(1.0, 2.0));
    /// ```
    pub fn at_rest(start: f64, position: SVector<f64, D>) -> Self {
        Self::new(start, position, SVector::zeros(), SVector::zeros())
    }

    /// The centre at the absolute time `t`, by the segment's formula (whether or not the segment
    /// is still the active one of its path at `t`).
    ///
    /// The formula is evaluated in the time `s = t − start` since the segment began, as
    /// `position + (velocity + ½·acceleration·s)·s`. Expanding it in absolute time instead
    /// (`c₀ + c₁·t + c₂·t²`) would cancel catastrophically for late starts: at `start = 1e4` the
    /// coefficients are some 1e8 times the displacement, and as many ulps of it are lost. In
    /// relative time the result carries only the rounding of `s` itself, and is exactly
    /// `position` at `t = start`.
    ///
    /// ```
    /// use ballcollide::path::Segment2;
    /// use nalgebra::Vector2;
    /// // The same motion begun at 0 s and at 10,000 s: the same positions, to the bit.
    /// let (p, v, a) = (Vector2::new(1.0, 0.0), Vector2::new(0.3, 0.1), Vector2::new(-0.1, 0.05));
    /// let early = Segment2::new(0.0, p, v, a);
    /// let late = Segment2 { start: 1e4, ..early };
    /// assert_eq!(late.position_at(1e4 + 0.75), early.position_at(0.75));
    /// assert_eq!(late.position_at(1e4), late.position);
    /// ```
    pub fn position_at(&self, t: f64) -> SVector<f64, D> {
        let s = t - self.start;
        self.position + (self.velocity + self.acceleration * (0.5 * s)) * s
    }

    /// The velocity at the absolute time `t`, `velocity + acceleration·(t − start)`, by the
    /// segment's formula (see [`Segment::position_at`] for why in time relative to `start`).
    ///
    /// ```
    /// use ballcollide::path::Segment2;
    /// use nalgebra::Vector2;
    /// let (v, a) = (Vector2::new(1.0, 0.0), Vector2::new(-0.5, 0.0));
    /// let roll = Segment2::new(2.0, Vector2::zeros(), v, a);
    /// assert_eq!(roll.velocity_at(3.0), Vector2::new(0.5, 0.0));
    /// ```
    pub fn velocity_at(&self, t: f64) -> SVector<f64, D> {
        self.velocity + self.acceleration * (t - self.start)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Vector2, Vector3};
    use proptest::prelude::*;

    /// `x + y` as an unevaluated sum `(hi, lo)`, exactly.
    fn two_sum(x: f64, y: f64) -> (f64, f64) {
        let hi = x + y;
        let z = hi - x;
        (hi, (x - (hi - z)) + (y - z))
    }

    /// `p + v·s + ½·a·s²` for one component, in double-double arithmetic (error ~2⁻¹⁰⁰ of the
    /// terms): a reference independent of the library's evaluation order.
    fn reference(p: f64, v: f64, a: f64, s: f64) -> f64 {
        let vs = v * s;
        let vs_lo = v.mul_add(s, -vs);
        let half_a_s = 0.5 * a * s; // 0.5·a is exact
        let half_a_s_lo = (0.5 * a).mul_add(s, -half_a_s);
        let a2 = half_a_s * s;
        let a2_lo = half_a_s.mul_add(s, -a2) + half_a_s_lo * s;
        let (hi, lo) = two_sum(p, vs);
        let (hi, lo2) = two_sum(hi, a2);
        hi + (lo + lo2 + vs_lo + a2_lo)
    }

    #[test]
    fn a_segment_is_exactly_at_its_position_at_its_start() {
        let p = Vector3::new(0.1, -0.3, 7e9);
        let seg = Segment::new(
            1e4 + 0.1,
            p,
            Vector3::new(3.0, 1e-7, -2.0),
            Vector3::repeat(9.5),
        );
        assert_eq!(seg.position_at(seg.start), p);
        assert_eq!(seg.velocity_at(seg.start), seg.velocity);
    }

    #[test]
    fn a_segment_follows_its_parabola_after_and_before_its_start() {
        let seg = Segment2::new(
            1.0,
            Vector2::new(1.0, 2.0),
            Vector2::new(2.0, 0.0),
            Vector2::new(0.0, -4.0),
        );
        assert_eq!(seg.position_at(2.0), Vector2::new(3.0, 0.0));
        assert_eq!(seg.velocity_at(2.0), Vector2::new(2.0, -4.0));
        // The formula alone, outside any path, extends backwards too.
        assert_eq!(seg.position_at(0.0), Vector2::new(-1.0, 0.0));
    }

    proptest! {
        #[test]
        fn positions_are_within_a_few_ulps_of_the_exact_formula(
            p in prop::array::uniform3(-10.0..10.0f64),
            v in prop::array::uniform3(-10.0..10.0f64),
            a in prop::array::uniform3(-10.0..10.0f64),
            start in 0.0..2e4f64,
            s in 0.0..60.0f64,
        ) {
            let seg = Segment3::new(start, p.into(), v.into(), a.into());
            let t = start + s;
            let s = t - start; // the time since the start that the segment sees
            let x = seg.position_at(t);
            for i in 0..3 {
                let exact = reference(p[i], v[i], a[i], s);
                let size = p[i].abs() + (v[i] * s).abs() + (0.5 * a[i] * s * s).abs();
                prop_assert!((x[i] - exact).abs() <= 4.0 * f64::EPSILON * size,
                    "{} vs {exact} (size {size})", x[i]);
            }
        }

        #[test]
        fn a_late_start_gives_the_positions_of_an_early_one(
            p in prop::array::uniform2(-10.0..10.0f64),
            v in prop::array::uniform2(-10.0..10.0f64),
            a in prop::array::uniform2(-10.0..10.0f64),
            start in 1e3..1e4f64,
            s in 0.0..1e3f64,
        ) {
            let early = Segment2::new(0.0, p.into(), v.into(), a.into());
            let late = Segment2 { start, ..early };
            let t = start + s;
            // t − start is exact here (Sterbenz), so the late segment sees the same time.
            prop_assert_eq!(late.position_at(t), early.position_at(t - start));
            prop_assert_eq!(late.velocity_at(t), early.velocity_at(t - start));
        }
    }
}
