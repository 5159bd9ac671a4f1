//! Ball–pocket collisions: [`Pocket`], the [`BallPocketResolver`] trait, and
//! [`CanonicalBallPocket`], pooltool 0.6.0's model for them (its only one).
//!
//! The pocket is its own small struct, not the plane's [`Target`](crate::geometry::Target):
//! pooltool's pocket has a depth, and the ball it takes is put at the bottom of it, `depth`
//! below the cloth, which a target on the plane has no number for.

use nalgebra::{Vector2, Vector3};

use super::{BallParams, BallState, MotionState};
use crate::error::{InputError, InputErrorKind, finite};

/// A pocket as pooltool's `Pocket`: a circle of `radius` about `center` on the table (a ball
/// whose centre enters it drops in), `depth` deep.
///
/// Which balls a pocket holds (pooltool's `Pocket.contains`) is the simulation's record, not
/// the pocket's: a `Pocket` is plain geometry, and [`check`](Self::check) says whether it is
/// valid.
///
/// ```
/// use ballcollide::billiards::Pocket;
/// use nalgebra::Vector2;
/// let corner = Pocket::new(Vector2::new(0.0, 0.0), 0.062, 0.08);
/// corner.check()?;
/// assert_eq!(corner.bottom(), -0.08); // where a pocketed ball's centre sits
/// # Ok::<(), ballcollide::InputError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pocket {
    /// The centre, in the plane of the table (pooltool's `a`, `b`).
    pub center: Vector2<f64>,
    /// The radius.
    pub radius: f64,
    /// How deep the pocket is (pooltool's default is `0.08` m).
    pub depth: f64,
}

impl Pocket {
    /// The pocket about `center` of `radius`, `depth` deep (example: [`Pocket`]).
    pub const fn new(center: Vector2<f64>, radius: f64, depth: f64) -> Self {
        Self {
            center,
            radius,
            depth,
        }
    }

    /// The height at which a pocketed ball's centre rests, `−depth` (pooltool's `rvw[0, 2]`
    /// after [`CanonicalBallPocket`]; a [`BallState`] is in the table's plane, and its height
    /// is this once it is [`Pocketed`](MotionState::Pocketed)). Example: [`Pocket`].
    pub fn bottom(&self) -> f64 {
        -self.depth
    }

    /// Checks the pocket: every number finite, `radius > 0` (pooltool checks nothing; a
    /// pocket of radius 0 or less takes no ball, which is a mistake rather than a choice).
    /// Any finite depth is valid (pooltool takes any).
    ///
    /// # Errors
    /// An [`InputError`] naming `center` (at the index of the first component that is not
    /// finite), `radius` or `depth`.
    ///
    /// ```
    /// use ballcollide::billiards::Pocket;
    /// use nalgebra::Vector2;
    /// let err = Pocket::new(Vector2::new(0.0, 0.0), 0.0, 0.08).check().unwrap_err();
    /// assert_eq!(err.to_string(), "radius: a target's radius must be > 0, got 0");
    /// let err = Pocket::new(Vector2::new(0.0, f64::NAN), 0.06, 0.08).check().unwrap_err();
    /// assert_eq!((err.argument(), err.index()), ("center", Some(1)));
    /// ```
    pub fn check(&self) -> Result<(), InputError> {
        for (k, &x) in self.center.iter().enumerate() {
            finite("center", x).map_err(|e| e.at(k))?;
        }
        if finite("radius", self.radius)? <= 0.0 {
            return Err(InputError::new(
                "radius",
                InputErrorKind::NonPositiveTargetRadius(self.radius),
            ));
        }
        finite("depth", self.depth)?;
        Ok(())
    }
}

/// A model of a ball dropping into a pocket: the ball's state once it is in, from its state
/// when its centre entered the pocket.
///
/// A model only moves the ball; the simulation records that the pocket holds it (pooltool's
/// `pocket.add`), and gives the state its time (pooltool's loop sets `t` after resolving).
///
/// ```
/// use ballcollide::billiards::{BallParams, BallPocketResolver, BallState, CanonicalBallPocket, MotionState, Pocket};
/// use nalgebra::{Vector2, Vector3};
/// let pocket = Pocket::new(Vector2::new(0.0, 0.0), 0.062, 0.08);
/// let ball = BallState::new(Vector2::new(0.03, 0.04), Vector2::new(-1.0, -1.0), Vector3::new(35.0, -35.0, 2.0), MotionState::Rolling);
/// let after = CanonicalBallPocket.resolve(&ball, &BallParams::default(), &pocket);
/// assert_eq!(after, BallState::new(Vector2::zeros(), Vector2::zeros(), Vector3::zeros(), MotionState::Pocketed));
/// ```
pub trait BallPocketResolver {
    /// The ball's state in `pocket`, from its state as it drops in.
    fn resolve(&self, ball: &BallState, params: &BallParams, pocket: &Pocket) -> BallState;
}

/// pooltool's `CanonicalBallPocket`: the ball is put at the pocket's centre, at its bottom
/// ([`Pocket::bottom`]), still (no velocity, no spin), and pocketed, whatever it was doing.
/// Example: [`BallPocketResolver`].
///
/// Checked against pooltool's own `resolve` on 2,000 random balls and pockets
/// (`tests/reference/billiards.rs`): the same state to the bit (the arithmetic is the same:
/// none, but for the sign of the depth), and pooltool's pocket holds the ball after each.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CanonicalBallPocket;

impl BallPocketResolver for CanonicalBallPocket {
    fn resolve(&self, _ball: &BallState, _params: &BallParams, pocket: &Pocket) -> BallState {
        // Nothing of the ball survives: pooltool builds a new state from the pocket alone.
        BallState::new(
            pocket.center,
            Vector2::zeros(),
            Vector3::zeros(),
            MotionState::Pocketed,
        )
    }
}
