//! [`Ball::path`]: the seed's friction ball as a path.

use super::{Path, Path2, Segment};
use crate::error::InputError;
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
    /// An [`InputError`] when the path's values overflow although the ball's inputs are finite:
    /// a resting point beyond the range of `f64` (`|v|²/2μ` overflows; `position` at segment
    /// 1), or a deceleration `−v/τ` that does (`acceleration` at segment 0).
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
        let moving = Segment::new(
            0.0,
            self.position(),
            self.velocity(),
            self.friction_vector(),
        );
        let segments = match self.rest_position() {
            Some(rest) if !self.is_at_rest() => {
                vec![moving, Segment::at_rest(self.stop_time(), rest)]
            }
            // At rest (v = a = 0), or never stopping (a = 0).
            _ => vec![moving],
        };
        Path::new(segments)
    }
}
