//! [`Ball::path`]: the seed's friction ball as a path.

use super::{Path, Path2, Segment};
use crate::error::{InputError, InputErrorKind};
use crate::motion::Ball;

impl Ball {
    /// This ball's motion as a path: `[(0, p, v, −μ·v/|v|), (τ, p + ½·v·τ, 0, 0)]`, slowing to
    /// its [stop](Ball::stop_time) and then at rest; a single segment `(0, p, 0, 0)` for a ball
    /// at rest and `(0, p, v, 0)` for one that never stops. The segments are formed from the
    /// ball's own [`Ball::friction_vector`], [`Ball::stop_time`] and [`Ball::rest_position`], so
    /// the path's positions are the ball's to within a few ulps, and exactly the same at time 0
    /// and from the stop on.
    ///
    /// # Errors
    /// An [`InputError`] of kind [`PathOverflow`](crate::InputErrorKind::PathOverflow) when
    /// the path's values overflow although the ball's inputs are finite: a resting point
    /// beyond the range of `f64` (`|v|²/2μ` overflows; named `velocity`), or a deceleration
    /// `−v/τ` that does (`τ = |v|/μ` rounded into the subnormals; named `friction`).
    ///
    /// ```
    /// use ballcollide::Ball;
    /// use nalgebra::Vector2;
    ///
    /// let ball = Ball::new(Vector2::new(1.0, 1.0), Vector2::new(2.0, 0.0), 0.5)?; // stops at 4 s
    /// let path = ball.path()?;
    /// assert_eq!(path.segments().len(), 2);
    /// assert_eq!(path.segments()[1].start, 4.0);
    /// assert_eq!(path.position_at(2.0), ball.position_at(2.0));
    /// assert_eq!(path.position_at(9.0), Vector2::new(5.0, 1.0));
    /// assert_eq!(Ball::at_rest(Vector2::new(1.0, 1.0))?.path()?.segments().len(), 1);
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn path(&self) -> Result<Path2, InputError> {
        let mut segments = Vec::new();
        self.write_segments(&mut segments);
        check_ball_path(&segments)?;
        Path::new(segments)
    }

    /// The segments of [`Ball::path`] (one or two), unchecked, written over `out`'s (its
    /// memory reused; grown, if need be, to exactly what they take).
    pub(crate) fn write_segments(&self, out: &mut Vec<Segment<2>>) {
        out.clear();
        // At rest means τ = 0, which includes a velocity so small that |v|/μ underflows.
        if self.is_at_rest() {
            out.reserve_exact(1);
            out.push(Segment::at_rest(0.0, self.position()));
            return;
        }
        let moving = Segment::new(
            0.0,
            self.position(),
            self.velocity(),
            self.friction_vector(),
        );
        match self.rest_position() {
            Some(rest) => {
                out.reserve_exact(2);
                out.push(moving);
                out.push(Segment::at_rest(self.stop_time(), rest));
            }
            None => {
                // It never stops (a = 0).
                out.reserve_exact(1);
                out.push(moving);
            }
        }
    }
}

/// [`Path::check`] on a friction ball's segments, its errors named after the ball's inputs:
/// a ball's finite inputs give a path that fails the check only where a value overflows (its
/// deceleration, its resting point, or its stop time moved on by the calendar's time).
pub(crate) fn check_ball_path<const D: usize>(segments: &[Segment<D>]) -> Result<(), InputError> {
    Path::check(segments).map_err(|e| {
        let value = e.kind().value().unwrap_or(f64::NAN);
        let (argument, part) = match e.argument() {
            "acceleration" => ("friction", "deceleration −v/τ"),
            "position" => ("velocity", "resting point p + ½·v·τ"),
            // τ = |v|/μ moved on by the calendar's time: a friction too small for it.
            "start" => ("friction", "stop time t + τ"),
            _ => return e,
        };
        InputError::new(argument, InputErrorKind::PathOverflow { part, value })
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::InputErrorKind;
    use crate::test_rng::Rng;
    use nalgebra::Vector2;
    use proptest::prelude::*;

    fn ball(p: [f64; 2], v: [f64; 2], friction: f64) -> Ball {
        Ball::new(p.into(), v.into(), friction).expect("valid ball")
    }

    fn path(ball: &Ball) -> Path2 {
        ball.path().expect("representable path")
    }

    /// The largest per-component difference between the path's and the ball's positions at
    /// `t`, in units of ε·(|p| + |v|·t): the size of the terms of the ball's formula.
    fn position_error(ball: &Ball, t: f64) -> f64 {
        let (x, y) = (path(ball).position_at(t), ball.position_at(t));
        (0..2)
            .map(|i| {
                let size = ball.position()[i].abs() + ball.velocity()[i].abs() * t;
                (x[i] - y[i]).abs() / (f64::EPSILON * size)
            })
            .fold(0.0, f64::max)
    }

    #[test]
    fn a_ball_at_rest_is_one_segment_at_rest() {
        let b = ball([0.5, -2.0], [0.0, 0.0], 0.3);
        assert_eq!(path(&b).segments(), &[Segment::at_rest(0.0, b.position())]);
    }

    #[test]
    fn a_frictionless_ball_is_one_segment_without_acceleration() {
        let b = ball([0.5, -2.0], [1.0, 3.0], 0.0);
        let expected = Segment::new(0.0, b.position(), b.velocity(), Vector2::zeros());
        assert_eq!(path(&b).segments(), &[expected]);
        assert_eq!(path(&b).position_at(1e6), b.position_at(1e6));
    }

    #[test]
    fn a_slowing_ball_is_a_slide_then_a_rest() {
        let b = ball([1.0, 2.0], [0.3, -0.4], 0.2);
        let rest = b.rest_position().expect("it stops");
        assert_eq!(
            path(&b).segments(),
            &[
                Segment::new(0.0, b.position(), b.velocity(), b.friction_vector()),
                Segment::at_rest(b.stop_time(), rest),
            ]
        );
    }

    #[test]
    fn positions_agree_exactly_at_the_start_and_from_the_stop_on() {
        let mut rng = Rng(0x5eed_ba11);
        for _ in 0..10_000 {
            let scale = 2f64.powi(rng.below(81) as i32 - 40);
            let b = ball(
                [
                    rng.uniform(-3.0, 3.0) * scale,
                    rng.uniform(-3.0, 3.0) * scale,
                ],
                [
                    rng.uniform(-3.0, 3.0) * scale,
                    rng.uniform(-3.0, 3.0) * scale,
                ],
                rng.uniform(0.0, 5.0) * scale,
            );
            let (path, tau) = (path(&b), b.stop_time());
            for t in [0.0, tau, tau.next_up(), 2.0 * tau, 1e300, f64::INFINITY] {
                assert_eq!(path.position_at(t), b.position_at(t), "{b:?} at {t}");
            }
            for t in [tau, 2.0 * tau, f64::INFINITY] {
                assert_eq!(path.velocity_at(t), b.velocity_at(t), "{b:?} at {t}");
            }
            assert_eq!(path.velocity_at(0.0), b.velocity_at(0.0));
        }
    }

    #[test]
    fn a_ball_whose_stop_time_underflows_is_at_rest() {
        let b = ball([0.5, -2.0], [1e-310, 0.0], 1e300);
        assert!(b.is_at_rest());
        assert_eq!(path(&b).segments(), &[Segment::at_rest(0.0, b.position())]);
        assert_eq!(path(&b).position_at(1.0), b.position_at(1.0));
    }

    #[test]
    fn a_deceleration_beyond_the_float_range_is_an_error() {
        // τ = 1e-15/1.5e308 rounds down to the smallest subnormal, and −v/τ overflows.
        let b = ball([0.0, 0.0], [1e-15, 0.0], 1.5e308);
        let err = b.path().expect_err("the path has an infinite acceleration");
        assert_eq!((err.argument(), err.index()), ("friction", None));
        assert_eq!(err.kind().code(), "path_overflow");
        assert_eq!(err.kind().value(), Some(f64::NEG_INFINITY));
    }

    #[test]
    fn a_resting_point_beyond_the_float_range_is_an_error() {
        // |v|²/2μ = 1e10/2e-300 overflows, though τ = 5e304 does not.
        let b = ball([0.0, 0.0], [1e5, 0.0], 2e-300);
        let err = b.path().expect_err("the path has an infinite position");
        assert_eq!((err.argument(), err.index()), ("velocity", None));
        let part = "resting point p + ½·v·τ";
        let kind = InputErrorKind::PathOverflow {
            part,
            value: f64::INFINITY,
        };
        assert_eq!(err.kind(), kind);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(crate::test_cases::cases(1000)))]
        #[test]
        fn positions_and_velocities_agree_to_a_couple_of_ulps(
            p in prop::array::uniform2(-3.0..3.0f64),
            v in prop::array::uniform2(-3.0..3.0f64),
            friction in 1e-3..5.0f64,
            scale in -40..=40i32,
            when in 0.0..1.5f64,
        ) {
            // Lengths scaled by a power of two, at times up to half again the stop time.
            let scale = 2f64.powi(scale);
            let b = ball(p.map(|x| x * scale), v.map(|x| x * scale), friction * scale);
            let t = b.stop_time() * when;
            prop_assert!(position_error(&b, t) <= 2.0, "{b:?} at {t}");
            let (x, y) = (path(&b).velocity_at(t), b.velocity_at(t));
            for i in 0..2 {
                prop_assert!((x[i] - y[i]).abs() <= 2.0 * f64::EPSILON * b.velocity()[i].abs(),
                    "{b:?} at {t}");
            }
        }
    }
}
