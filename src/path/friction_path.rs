//! [`FrictionPath`]: a friction ball as a path from a given time, in the dimension of a
//! calendar (re-exported by [`schedule`](crate::schedule), which uses it).

use super::from_ball::check_ball_path;
use super::{Path, Segment};
use crate::error::InputError;
use crate::motion::Ball;

/// A friction ball's path from a time `t`, in the dimension `D` of a calendar
/// ([`CollisionSchedule`](crate::schedule::CollisionSchedule)'s friction-ball constructors).
pub trait FrictionPath<const D: usize> {
    /// [`Ball::path`] with every start moved on by `t`.
    ///
    /// # Errors
    /// As [`Ball::path`].
    ///
    /// ```
    /// use ballcollide::Ball;
    /// use ballcollide::path::FrictionPath;
    /// use nalgebra::Vector2;
    /// let ball = Ball::new(Vector2::zeros(), Vector2::new(1.0, 0.0), 0.5)?;
    /// let path = FrictionPath::<2>::path_from(&ball, 3.0)?;
    /// assert_eq!(path.segments()[1].start, 5.0);
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    fn path_from(&self, t: f64) -> Result<Path<D>, InputError> {
        let mut segments = Vec::new();
        self.write_path_from(t, &mut segments)?;
        Path::new(segments)
    }

    /// The segments of [`path_from`](Self::path_from)`(t)` written over `out`'s (its memory
    /// reused: what a calendar's update does), checked as `path_from` checks them.
    ///
    /// # Errors
    /// As [`path_from`](Self::path_from); `out` then holds no path.
    ///
    /// ```
    /// use ballcollide::Ball;
    /// use ballcollide::path::Path2;
    /// use ballcollide::path::FrictionPath;
    /// use nalgebra::Vector2;
    /// let ball = Ball::new(Vector2::zeros(), Vector2::new(1.0, 0.0), 0.5)?;
    /// let mut segments = Vec::new();
    /// FrictionPath::<2>::write_path_from(&ball, 3.0, &mut segments)?;
    /// assert_eq!(Path2::new(segments)?, FrictionPath::<2>::path_from(&ball, 3.0)?);
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    fn write_path_from(&self, t: f64, out: &mut Vec<Segment<D>>) -> Result<(), InputError>;
}

impl FrictionPath<2> for Ball {
    fn write_path_from(&self, t: f64, out: &mut Vec<Segment<2>>) -> Result<(), InputError> {
        let shift = |out: &mut Vec<Segment<2>>| {
            for segment in out.iter_mut() {
                segment.start += t;
            }
        };
        self.write_segments(out);
        shift(out);
        // Valid moved on, valid from 0 (the same values; starts 0 ≤ τ finite, as τ + t is):
        // one check. Else the error `Ball::path` reports first, if any, as `path_from` does.
        if Path::check(out).is_ok() {
            return Ok(());
        }
        self.write_segments(out);
        check_ball_path(out)?;
        shift(out);
        check_ball_path(out)
    }
}
