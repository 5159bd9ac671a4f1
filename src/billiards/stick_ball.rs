//! The cue striking a ball: [`Cue`] and [`CueSpecs`] (pooltool 0.6.0's `Cue` and
//! `CueSpecs`), and the [`StickBallResolver`] trait of stick–ball models.
//!
//! pooltool's default model is [`InstantaneousPoint`](super::InstantaneousPoint).

use super::{BallParams, BallState};
use crate::error::{InputError, InputErrorKind, finite};

/// The physical cue: pooltool's `CueSpecs`, the fields its physics can use ([`Default`] is
/// its default, a Predator cue). pooltool's `brand`, `length` and shaft radii only draw the
/// cue, and are left out.
///
/// ```
/// use ballcollide::billiards::CueSpecs;
/// let predator = CueSpecs::default();
/// assert_eq!((predator.mass, predator.tip_radius), (0.567, 0.0106045));
/// assert_eq!(predator.end_mass, 0.170097 / 30.0); // a thirtieth of a pool ball
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CueSpecs {
    /// The cue's mass (pooltool's `M`).
    pub mass: f64,
    /// The mass of the cue's end, which sets the squirt: the lighter, the less the ball
    /// deflects with side spin (Alciatore's TP A-31).
    pub end_mass: f64,
    /// The tip's radius. pooltool 0.6.0's [`InstantaneousPoint`](super::InstantaneousPoint)
    /// does not use it: its `a`, `b` are the contact point itself (pooltool's docstring
    /// speaks of scaling by `1 + tip_radius/R`, which only its interface does, turning where
    /// the player aims the tip's centre into the contact point: [`contact_offset`](Self::contact_offset)).
    pub tip_radius: f64,
}

impl Default for CueSpecs {
    /// pooltool's `CueSpecs()`: `M = 0.567`, `end_mass = 0.170097 / 30`, `tip_radius =
    /// 0.0106045` (a nickel's).
    fn default() -> Self {
        Self {
            mass: 0.567,
            end_mass: 0.170097 / 30.0,
            tip_radius: 0.0106045,
        }
    }
}

impl CueSpecs {
    /// The contact point `(a, b)` on a ball of `ball_radius` when the tip's centre is aimed at
    /// `tip_center` (both in units of the ball's radius): `tip_center / (1 + tip_radius /
    /// ball_radius)`, pooltool's `tip_contact_offset`, the same arithmetic.
    ///
    /// ```
    /// use ballcollide::billiards::CueSpecs;
    /// let specs = CueSpecs { tip_radius: 0.01, ..CueSpecs::default() };
    /// assert_eq!(specs.contact_offset([0.0, 0.6], 0.03), [0.0, 0.6 / (1.0 + 0.01 / 0.03)]);
    /// ```
    pub fn contact_offset(&self, tip_center: [f64; 2], ball_radius: f64) -> [f64; 2] {
        let scale = 1.0 + self.tip_radius / ball_radius;
        tip_center.map(|x| x / scale)
    }
}

/// A stroke: how the cue meets the ball (pooltool's `Cue`, angles in degrees as there), with
/// the cue's [`CueSpecs`]. [`Default`] is pooltool's `Cue()`: 2 m/s, `φ = 0`, level, a little
/// follow (`b = 0.25`).
///
/// ```
/// use ballcollide::billiards::Cue;
/// let stroke = Cue { v0: 3.0, phi: 90.0, b: -0.4, ..Cue::default() }; // a draw shot up the table
/// stroke.check()?;
/// assert_eq!(Cue::default().b, 0.25);
/// # Ok::<(), ballcollide::InputError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cue {
    /// The cue's speed at impact (pooltool's `V0`; not the ball's speed after).
    pub v0: f64,
    /// The direction of the stroke on the table, in degrees: 0 along `+x`, 90 along `+y`.
    pub phi: f64,
    /// The cue's elevation above the cloth, in degrees: 0 level, 90 straight down (massé).
    pub theta: f64,
    /// The contact point's side offset, in units of the ball's radius: `−1` the ball's
    /// rightmost point, `+1` its leftmost (as seen along the cue).
    pub a: f64,
    /// The contact point's height offset, in units of the ball's radius: `−1` its bottom,
    /// `+1` its top.
    pub b: f64,
    /// The physical cue.
    pub specs: CueSpecs,
}

impl Default for Cue {
    fn default() -> Self {
        Self {
            v0: 2.0,
            phi: 0.0,
            theta: 0.0,
            a: 0.0,
            b: 0.25,
            specs: CueSpecs::default(),
        }
    }
}

impl Cue {
    /// Checks the stroke: every number finite, the contact point on the ball's face
    /// (`1 − a² − b² ≥ 0` in float64, as pooltool takes its square root), the masses `> 0`.
    /// A negative `v0` is taken as pooltool takes it (the ball goes the other way), and any
    /// angle (they are periodic).
    ///
    /// # Errors
    /// An [`InputError`] naming the field (`v0`, `phi`, `theta`, `a`, `b`, `specs.mass`,
    /// `specs.end_mass`, `specs.tip_radius`), or `a, b` for a contact point off the ball.
    ///
    /// ```
    /// use ballcollide::billiards::Cue;
    /// use ballcollide::InputErrorKind;
    /// let err = Cue { a: 0.8, b: 0.8, ..Cue::default() }.check().unwrap_err();
    /// assert_eq!((err.argument(), err.kind().code()), ("a, b", "contact_off_ball"));
    /// let mut cue = Cue::default();
    /// cue.specs.end_mass = 0.0;
    /// assert_eq!(cue.check().unwrap_err().argument(), "specs.end_mass");
    /// ```
    pub fn check(&self) -> Result<(), InputError> {
        finite("v0", self.v0)?;
        finite("phi", self.phi)?;
        finite("theta", self.theta)?;
        let (a, b) = (finite("a", self.a)?, finite("b", self.b)?);
        // pooltool's own expression: what it can take the square root of.
        if 1.0 - a * a - b * b < 0.0 {
            return Err(InputError::new(
                "a, b",
                InputErrorKind::ContactOffBall(a * a + b * b),
            ));
        }
        positive_mass("specs.mass", self.specs.mass)?;
        positive_mass("specs.end_mass", self.specs.end_mass)?;
        finite("specs.tip_radius", self.specs.tip_radius)?;
        Ok(())
    }
}

/// `Ok` if `x` is finite and `> 0`, else an error naming `argument`.
fn positive_mass(argument: &'static str, x: f64) -> Result<(), InputError> {
    if finite(argument, x)? > 0.0 {
        Ok(())
    } else {
        Err(InputError::new(
            argument,
            InputErrorKind::NonPositiveMass(x),
        ))
    }
}

/// A model of the cue striking a ball: the ball's state just after, from the stroke and its
/// state before (pooltool's stick–ball models; its loop gives the state its time).
///
/// A model implements [`solve`](Self::solve), which trusts its inputs, and
/// [`check`](Self::check) for its own parameters; [`resolve`](Self::resolve) checks the
/// model, the stroke, the ball and its parameters first.
///
/// ```
/// use ballcollide::billiards::{BallParams, BallState, Cue, InstantaneousPoint, MotionState, StickBallResolver};
/// use nalgebra::Vector2;
/// let params = BallParams::default();
/// let ball = BallState::at_rest(Vector2::new(0.5, 0.6));
/// let stroke = Cue { v0: 2.0, phi: 0.0, a: 0.0, b: 0.0, ..Cue::default() }; // a centre-ball hit
/// let after = InstantaneousPoint::default().resolve(&stroke, &ball, &params)?;
/// assert_eq!(after.motion, MotionState::Sliding);
/// assert_eq!(after.position, ball.position);
/// // 2·V0 / (1 + m/M): the cue's momentum shared with a ball 0.3 of its mass.
/// let speed = 2.0 * 2.0 / (1.0 + params.mass / 0.567);
/// assert!((after.velocity - Vector2::new(speed, 0.0)).norm() < 1e-15);
/// assert!(after.angular_velocity.norm() < 1e-12); // no spin from a centre-ball hit
/// let off = Cue { a: 0.9, b: 0.9, ..stroke };
/// assert!(InstantaneousPoint::default().resolve(&off, &ball, &params).is_err());
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub trait StickBallResolver {
    /// The ball's state just after `cue` strikes it, for inputs that pass their checks.
    fn solve(&self, cue: &Cue, ball: &BallState, params: &BallParams) -> BallState;

    /// Checks the model's own parameters (none by default).
    ///
    /// # Errors
    /// An [`InputError`] naming the offending parameter.
    fn check(&self) -> Result<(), InputError> {
        Ok(())
    }

    /// [`solve`](Self::solve), after checking the model ([`check`](Self::check)), the
    /// stroke ([`Cue::check`]), the ball ([`BallState::check`]) and its parameters
    /// ([`BallParams::check`]).
    ///
    /// # Errors
    /// The first check's [`InputError`].
    fn resolve(
        &self,
        cue: &Cue,
        ball: &BallState,
        params: &BallParams,
    ) -> Result<BallState, InputError> {
        self.check()?;
        cue.check()?;
        ball.check()?;
        params.check()?;
        Ok(self.solve(cue, ball, params))
    }
}
