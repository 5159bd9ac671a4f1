//! [`Ball`]: a ball sliding on a straight line, slowed by constant friction until it stops.

use nalgebra::Vector2;

use crate::collision::length_unit::norm_in_range;
use crate::error::{InputError, check_friction, finite};

/// A ball's state at time 0: its centre, its velocity, and the magnitude `μ ≥ 0` of the
/// friction deceleration, which points against the velocity.
///
/// Its centre moves as `x(t) = p + v·t − ½·μ·(v/|v|)·t²` until the stop time `τ = |v|/μ`, and
/// stays at `p + ½·v·τ` afterwards (the formula alone would turn the ball round). `μ = 0`
/// moves it for ever; `v = 0` keeps it at rest (τ = 0).
///
/// A `Ball` is always valid: [`Ball::new`] rejects non-finite numbers and negative friction,
/// so every query on it is total.
///
/// ```
/// use ballcollide::Ball;
/// use nalgebra::Vector2;
///
/// // 2 m/s along x, slowed at 0.5 m/s²: stops after 4 s, 4 m further on.
/// let ball = Ball::new(Vector2::new(1.0, 1.0), Vector2::new(2.0, 0.0), 0.5)?;
/// assert_eq!(ball.stop_time(), 4.0);
/// assert_eq!(ball.position_at(2.0), Vector2::new(4.0, 1.0));
/// assert_eq!(ball.position_at(10.0), Vector2::new(5.0, 1.0)); // stopped and stays
/// assert_eq!(ball.velocity_at(3.0), Vector2::new(0.5, 0.0));
/// # Ok::<(), ballcollide::InputError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ball {
    position: Vector2<f64>,
    velocity: Vector2<f64>,
    friction: f64,
    stop_time: f64,
}

/// Ball `i`'s error `e` (about a [`Ball`] input: `position`, `velocity`, `friction`), as the
/// calls that take balls as rows (`pos`, `vel`, `friction`: the scene, the calendar's
/// friction balls, `simulate`) name it: `vel[i]`.
pub(crate) fn row_error(e: InputError, i: usize) -> InputError {
    let name = match e.argument() {
        "position" => "pos",
        "velocity" => "vel",
        other => other,
    };
    e.renamed(name).at(i)
}

impl Ball {
    /// A ball at `position` with `velocity` and friction deceleration `friction` (≥ 0).
    ///
    /// # Errors
    /// An [`InputError`] naming `position`, `velocity` or `friction` when a component is NaN
    /// or infinite, or the friction is negative.
    ///
    /// ```
    /// use ballcollide::Ball;
    /// use nalgebra::Vector2;
    /// let err = Ball::new(Vector2::new(f64::NAN, 0.0), Vector2::zeros(), 0.1).unwrap_err();
    /// assert_eq!(err.argument(), "position");
    /// ```
    pub fn new(
        position: Vector2<f64>,
        velocity: Vector2<f64>,
        friction: f64,
    ) -> Result<Self, InputError> {
        finite("position", position.x)?;
        finite("position", position.y)?;
        finite("velocity", velocity.x)?;
        finite("velocity", velocity.y)?;
        let friction = check_friction("friction", friction)?;
        Ok(Self::from_checked(
            position.into(),
            velocity.into(),
            friction,
        ))
    }

    /// A ball from numbers known valid (finite, friction ≥ 0 and not `−0.0`), its stop time
    /// formed here: the one place where a stop time is made from a velocity and a friction.
    #[inline(always)]
    pub(crate) fn from_checked(position: [f64; 2], velocity: [f64; 2], friction: f64) -> Self {
        let velocity = Vector2::from(velocity);
        let speed = norm(velocity);
        // τ = |v|/μ: 0 for a ball at rest (even when μ = 0), ∞ for a frictionless mover, and
        // ∞ too when |v|/μ overflows (the ball then never stops within float time).
        let stop_time = if speed == 0.0 { 0.0 } else { speed / friction };
        Self {
            position: Vector2::from(position),
            velocity,
            friction,
            stop_time,
        }
    }

    /// A ball at rest at `position`.
    ///
    /// ```
    /// use ballcollide::Ball;
    /// use nalgebra::Vector2;
    /// let b = Ball::at_rest(Vector2::new(0.5, 0.25))?;
    /// assert_eq!(b.stop_time(), 0.0);
    /// assert_eq!(b.position_at(7.0), Vector2::new(0.5, 0.25));
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn at_rest(position: Vector2<f64>) -> Result<Self, InputError> {
        Self::new(position, Vector2::zeros(), 0.0)
    }

    /// The centre at time 0.
    ///
    /// ```
    /// use ballcollide::Ball;
    /// use nalgebra::Vector2;
    /// let b = Ball::new(Vector2::new(1.0, 2.0), Vector2::new(0.5, 0.0), 0.25)?;
    /// assert_eq!(b.position(), Vector2::new(1.0, 2.0));
    /// assert_eq!(b.velocity(), Vector2::new(0.5, 0.0));
    /// assert_eq!(b.friction(), 0.25);
    /// assert!(!b.is_at_rest());
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn position(&self) -> Vector2<f64> {
        self.position
    }

    /// The velocity at time 0 (example: [`Ball::position`]).
    pub fn velocity(&self) -> Vector2<f64> {
        self.velocity
    }

    /// The friction deceleration magnitude `μ` (example: [`Ball::position`]).
    pub fn friction(&self) -> f64 {
        self.friction
    }

    /// The time `τ = |v|/μ` at which the ball stops: `0` for a ball at rest, `∞` for a
    /// frictionless moving ball.
    ///
    /// ```
    /// use ballcollide::Ball;
    /// use nalgebra::Vector2;
    /// let b = Ball::new(Vector2::zeros(), Vector2::new(3.0, 4.0), 0.0)?;
    /// assert_eq!(b.stop_time(), f64::INFINITY);
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn stop_time(&self) -> f64 {
        self.stop_time
    }

    /// A ball whose inputs are known valid and whose stop time is already formed as
    /// [`Ball::new`] forms it (the lane-wise tests build balls from checked inputs).
    #[inline(always)]
    pub(crate) fn from_parts(
        position: [f64; 2],
        velocity: [f64; 2],
        friction: f64,
        stop_time: f64,
    ) -> Self {
        Self {
            position: Vector2::from(position),
            velocity: Vector2::from(velocity),
            friction,
            stop_time,
        }
    }

    /// Whether the ball is at rest from the start (`v = 0`).
    ///
    /// ```
    /// use ballcollide::Ball;
    /// use nalgebra::Vector2;
    /// assert!(Ball::at_rest(Vector2::new(1.0, 1.0))?.is_at_rest());
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn is_at_rest(&self) -> bool {
        self.stop_time == 0.0
    }

    /// The friction acceleration vector `−μ·v/|v|` while the ball moves (zero at rest).
    ///
    /// It is formed as `−v/τ`, which is the same vector and keeps it consistent with
    /// [`Ball::stop_time`].
    ///
    /// ```
    /// use ballcollide::Ball;
    /// use nalgebra::Vector2;
    /// let b = Ball::new(Vector2::zeros(), Vector2::new(3.0, 4.0), 0.5)?;
    /// assert_eq!(b.friction_vector(), Vector2::new(-0.3, -0.4));
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn friction_vector(&self) -> Vector2<f64> {
        if self.stop_time == 0.0 || self.stop_time.is_infinite() {
            Vector2::zeros()
        } else {
            -self.velocity / self.stop_time
        }
    }

    /// Where the ball comes to rest (`p + ½·v·τ`); `None` if it never stops.
    ///
    /// ```
    /// use ballcollide::Ball;
    /// use nalgebra::Vector2;
    /// let b = Ball::new(Vector2::zeros(), Vector2::new(1.0, 0.0), 0.5)?;
    /// assert_eq!(b.rest_position(), Some(Vector2::new(1.0, 0.0)));
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn rest_position(&self) -> Option<Vector2<f64>> {
        self.stop_time
            .is_finite()
            .then(|| self.position + self.velocity * (0.5 * self.stop_time))
    }

    /// The centre at time `t ≥ 0` (times before 0 are taken as 0); a stopped ball stays.
    ///
    /// Written `p + v·t·(1 − t/(2τ))`: the factor lies in [½, 1] before the stop, so it
    /// carries no cancellation, and at `t = τ` it gives the resting point exactly.
    ///
    /// ```
    /// use ballcollide::Ball;
    /// use nalgebra::Vector2;
    /// let b = Ball::new(Vector2::zeros(), Vector2::new(2.0, 0.0), 1.0)?; // stops at t = 2
    /// assert_eq!(b.position_at(1.0), Vector2::new(1.5, 0.0));
    /// assert_eq!(b.position_at(2.0), Vector2::new(2.0, 0.0));
    /// assert_eq!(b.position_at(9.0), Vector2::new(2.0, 0.0));
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn position_at(&self, t: f64) -> Vector2<f64> {
        let t = t.max(0.0);
        let tau = self.stop_time;
        if t == 0.0 {
            self.position
        } else if tau.is_infinite() {
            self.position + self.velocity * t
        } else if t >= tau {
            self.position + self.velocity * (0.5 * tau)
        } else {
            self.position + self.velocity * (t * (1.0 - 0.5 * (t / tau)))
        }
    }

    /// The velocity at time `t ≥ 0`: `v·(1 − t/τ)` until the stop, zero after.
    ///
    /// ```
    /// use ballcollide::Ball;
    /// use nalgebra::Vector2;
    /// let b = Ball::new(Vector2::zeros(), Vector2::new(2.0, 0.0), 1.0)?; // stops at t = 2
    /// assert_eq!(b.velocity_at(1.5), Vector2::new(0.5, 0.0));
    /// assert_eq!(b.velocity_at(3.0), Vector2::zeros());
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn velocity_at(&self, t: f64) -> Vector2<f64> {
        let t = t.max(0.0);
        let tau = self.stop_time;
        if tau.is_infinite() || t == 0.0 {
            self.velocity
        } else if t >= tau {
            Vector2::zeros()
        } else {
            self.velocity * ((tau - t) / tau)
        }
    }
}

/// `|v|`: `√(x² + y²)` where the squares neither overflow nor lose bits to underflow, and
/// the same in a power-of-two unit elsewhere ([`norm_in_range`]): `2^k·v` has `2^k·|v|` to
/// the bit over the whole float range (contract §1), where `hypot` rounds differently.
fn norm(v: Vector2<f64>) -> f64 {
    let sum = v.x * v.x + v.y * v.y;
    if (1e-290..=1e290).contains(&sum) {
        sum.sqrt()
    } else {
        norm_in_range(&v)
    }
}
