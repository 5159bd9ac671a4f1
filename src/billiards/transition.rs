//! A ball's next change of motion state: [`TransitionKind`], [`NextTransition`] and
//! [`next_transition`] (pooltool's transition events and `CanonicalTransition`).

use nalgebra::{Vector2, Vector3};

use super::{BallParams, BallState, MotionState, roll_time, slide_time, spin_time};

/// A change of motion state that comes by itself, at a time known in advance (pooltool's
/// transition event types, `SLIDING_ROLLING` and so on).
///
/// ```
/// use ballcollide::billiards::{MotionState, TransitionKind};
/// let k = TransitionKind::RollingSpinning;
/// assert_eq!((k.before(), k.after()), (MotionState::Rolling, MotionState::Spinning));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TransitionKind {
    /// The slip is gone: the ball rolls.
    SlidingRolling,
    /// The ball stops rolling with spin about the vertical left: it spins in place.
    RollingSpinning,
    /// The ball stops rolling without spin left.
    RollingStationary,
    /// The spin in place is spent.
    SpinningStationary,
}

impl TransitionKind {
    /// The motion state the transition leaves (example: [`TransitionKind`]).
    pub const fn before(self) -> MotionState {
        match self {
            Self::SlidingRolling => MotionState::Sliding,
            Self::RollingSpinning | Self::RollingStationary => MotionState::Rolling,
            Self::SpinningStationary => MotionState::Spinning,
        }
    }

    /// The motion state the transition enters (example: [`TransitionKind`]).
    pub const fn after(self) -> MotionState {
        match self {
            Self::SlidingRolling => MotionState::Rolling,
            Self::RollingSpinning => MotionState::Spinning,
            Self::RollingStationary | Self::SpinningStationary => MotionState::Stationary,
        }
    }

    /// The ball's state just after the transition, from `state` just before it (pooltool's
    /// `CanonicalTransition`): the motion state becomes [`after`](Self::after); entering
    /// spinning sets the velocity and the horizontal angular velocity to exactly 0, entering
    /// stationary the velocity and the whole angular velocity. Position, and otherwise the
    /// velocities, are kept: a ball that starts rolling keeps whatever slip is left of its
    /// slide.
    ///
    /// pooltool also asserts that what it sets to 0 is below `1e-12`; this does not check.
    ///
    /// ```
    /// use ballcollide::billiards::{BallState, MotionState, TransitionKind};
    /// use nalgebra::{Vector2, Vector3};
    /// let end_of_roll = BallState::new(Vector2::new(1.0, 0.5), Vector2::new(1e-17, 0.0), Vector3::new(0.0, 3e-16, 4.0), MotionState::Rolling);
    /// let spinning = TransitionKind::RollingSpinning.apply(&end_of_roll);
    /// assert_eq!(spinning.velocity, Vector2::zeros());
    /// assert_eq!(spinning.angular_velocity, Vector3::new(0.0, 0.0, 4.0));
    /// assert_eq!((spinning.position, spinning.motion), (end_of_roll.position, MotionState::Spinning));
    /// ```
    pub fn apply(self, state: &BallState) -> BallState {
        let mut state = *state;
        state.motion = self.after();
        match state.motion {
            MotionState::Spinning => {
                state.velocity = Vector2::zeros();
                state.angular_velocity.x = 0.0;
                state.angular_velocity.y = 0.0;
            }
            MotionState::Stationary => {
                state.velocity = Vector2::zeros();
                state.angular_velocity = Vector3::zeros();
            }
            _ => {}
        }
        state
    }
}

/// A ball's next transition: which, and how long until it comes.
///
/// ```
/// use ballcollide::billiards::{NextTransition, TransitionKind};
/// let next = NextTransition { delay: 0.25, kind: TransitionKind::SlidingRolling };
/// assert_eq!(next.kind.after(), ballcollide::billiards::MotionState::Rolling);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NextTransition {
    /// The time until the transition, from the state's time (`+∞` for a state that never
    /// ends, under a friction of 0).
    pub delay: f64,
    /// The transition.
    pub kind: TransitionKind,
}

/// The transition that ends `state`'s motion state, if it has one (pooltool's
/// `_next_transition`): a sliding ball rolls after [`slide_time`]; a rolling ball stops rolling
/// after [`roll_time`], and then spins in place if its [`spin_time`] is longer than the roll,
/// else is stationary; a spinning ball is stationary after [`spin_time`]. A stationary or
/// pocketed ball has none.
///
/// ```
/// use ballcollide::billiards::{BallParams, BallState, MotionState, TransitionKind, next_transition, roll_time};
/// use nalgebra::{Vector2, Vector3};
/// let params = BallParams::default();
/// let v = Vector2::new(0.5, 0.0);
/// let mut rolling = BallState::new(Vector2::zeros(), v, Vector3::new(0.0, 0.5 / params.radius, 0.0), MotionState::Rolling);
/// let next = next_transition(&rolling, &params).expect("a roll ends");
/// assert_eq!((next.delay, next.kind), (roll_time(&rolling, &params), TransitionKind::RollingStationary));
/// rolling.angular_velocity.z = 100.0; // heavy side spin outlasts the roll (5.1 s)
/// assert_eq!(next_transition(&rolling, &params).map(|n| n.kind), Some(TransitionKind::RollingSpinning));
/// assert_eq!(next_transition(&BallState::at_rest(Vector2::zeros()), &params), None);
/// ```
pub fn next_transition(state: &BallState, params: &BallParams) -> Option<NextTransition> {
    let (delay, kind) = match state.motion {
        MotionState::Stationary | MotionState::Pocketed => return None,
        MotionState::Spinning => (spin_time(state, params), TransitionKind::SpinningStationary),
        MotionState::Rolling => {
            let roll = roll_time(state, params);
            if spin_time(state, params) > roll {
                (roll, TransitionKind::RollingSpinning)
            } else {
                (roll, TransitionKind::RollingStationary)
            }
        }
        MotionState::Sliding => (slide_time(state, params), TransitionKind::SlidingRolling),
    };
    Some(NextTransition { delay, kind })
}
