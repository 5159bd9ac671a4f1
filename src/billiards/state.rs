//! [`BallState`]: where a billiard ball is, how it moves and spins, and its [`MotionState`].

use nalgebra::{Vector2, Vector3};

use crate::error::{InputError, finite};

/// What a billiard ball on the cloth is doing: pooltool's motion states, with its numbers
/// ([`code`](Self::code)).
///
/// ```
/// use ballcollide::billiards::MotionState;
/// assert_eq!(MotionState::Sliding.code(), 2);
/// assert_eq!(MotionState::from_code(3), Some(MotionState::Rolling));
/// assert_eq!(MotionState::from_code(5), None);
/// assert!(MotionState::Rolling.translates() && !MotionState::Spinning.translates());
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum MotionState {
    /// At rest, not spinning, on the table (`0`).
    #[default]
    Stationary,
    /// Spinning in place about the vertical: the centre does not move (`1`).
    Spinning,
    /// Sliding: the contact point slips on the cloth (`2`).
    Sliding,
    /// Rolling without slipping (`3`).
    Rolling,
    /// In a pocket, out of play (`4`).
    Pocketed,
}

impl MotionState {
    /// pooltool's number for the state (`pooltool.constants`): stationary 0, spinning 1,
    /// sliding 2, rolling 3, pocketed 4 (example: [`MotionState`]).
    pub const fn code(self) -> i64 {
        match self {
            Self::Stationary => 0,
            Self::Spinning => 1,
            Self::Sliding => 2,
            Self::Rolling => 3,
            Self::Pocketed => 4,
        }
    }

    /// The state of pooltool's number `code`, or `None` if it names none (example:
    /// [`MotionState`]).
    pub const fn from_code(code: i64) -> Option<Self> {
        match code {
            0 => Some(Self::Stationary),
            1 => Some(Self::Spinning),
            2 => Some(Self::Sliding),
            3 => Some(Self::Rolling),
            4 => Some(Self::Pocketed),
            _ => None,
        }
    }

    /// Whether the centre moves in this state: sliding or rolling (example:
    /// [`MotionState`]).
    pub const fn translates(self) -> bool {
        matches!(self, Self::Sliding | Self::Rolling)
    }
}

/// A billiard ball's state at one time: its centre and velocity in the plane of the table,
/// its angular velocity in space, and its [`MotionState`].
///
/// It is pooltool's `BallState` (`rvw` and `s`) on a table, where the centre stays at height
/// `R` and the velocity is horizontal: pooltool 0.6.0 never changes a ball's height nor gives
/// it a vertical velocity, so its `rvw[0, 2]` and `rvw[1, 2]` carry nothing here. The angular
/// velocity is `(ω_x, ω_y, ω_z)`, `ω_z` the spin about the vertical (side spin).
///
/// A `BallState` is plain data; [`check`](Self::check) says whether every number is finite.
/// The motion state is not checked against the velocities (a "stationary" ball with a
/// velocity stays where it is, as in pooltool).
///
/// ```
/// use ballcollide::billiards::{BallState, MotionState};
/// use nalgebra::{Vector2, Vector3};
/// let cue = BallState::new(
///     Vector2::new(0.5, 0.6),
///     Vector2::new(2.0, 0.0),
///     Vector3::new(0.0, -30.0, 5.0), // back spin and some side spin
///     MotionState::Sliding,
/// );
/// cue.check()?;
/// assert_eq!(BallState::at_rest(Vector2::new(1.0, 1.0)).motion, MotionState::Stationary);
/// # Ok::<(), ballcollide::InputError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BallState {
    /// The centre, in the plane of the table.
    pub position: Vector2<f64>,
    /// The velocity of the centre.
    pub velocity: Vector2<f64>,
    /// The angular velocity `(ω_x, ω_y, ω_z)`.
    pub angular_velocity: Vector3<f64>,
    /// What the ball is doing.
    pub motion: MotionState,
}

impl BallState {
    /// The state made of these values (example: [`BallState`]).
    pub const fn new(
        position: Vector2<f64>,
        velocity: Vector2<f64>,
        angular_velocity: Vector3<f64>,
        motion: MotionState,
    ) -> Self {
        Self {
            position,
            velocity,
            angular_velocity,
            motion,
        }
    }

    /// A ball at rest at `position`, not spinning (example: [`BallState`]).
    pub fn at_rest(position: Vector2<f64>) -> Self {
        Self::new(
            position,
            Vector2::zeros(),
            Vector3::zeros(),
            MotionState::Stationary,
        )
    }

    /// Checks that every number is finite.
    ///
    /// # Errors
    /// An [`InputError`] naming `position`, `velocity` or `angular_velocity`, at the index of
    /// the first component that is NaN or infinite.
    ///
    /// ```
    /// use ballcollide::billiards::BallState;
    /// use nalgebra::{Vector2, Vector3};
    /// let mut state = BallState::at_rest(Vector2::new(1.0, 1.0));
    /// state.angular_velocity = Vector3::new(0.0, 0.0, f64::NAN);
    /// let err = state.check().unwrap_err();
    /// assert_eq!(err.to_string(), "angular_velocity[2]: must be finite, got NaN");
    /// ```
    pub fn check(&self) -> Result<(), InputError> {
        let vectors: [(&'static str, &[f64]); 3] = [
            ("position", self.position.as_slice()),
            ("velocity", self.velocity.as_slice()),
            ("angular_velocity", self.angular_velocity.as_slice()),
        ];
        for (name, components) in vectors {
            for (k, &x) in components.iter().enumerate() {
                finite(name, x).map_err(|e| e.at(k))?;
            }
        }
        Ok(())
    }
}
