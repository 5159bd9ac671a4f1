//! [`ball_path`]: a billiard ball's motion until it stops, as a [`Path2`] for the calendar.

use crate::error::{InputError, finite};
use crate::path::{Path2, Segment2};

use super::evolve_roll::roll_acceleration;
use super::evolve_slide::slide_acceleration;
use super::{BallParams, BallState, MotionState, evolve, next_transition};

/// A billiard ball's motion from a state until it stops: a [`Path2`] of constant-acceleration
/// segments, one per motion state, and the ball's state at each segment's start.
///
/// Segment `k ≥ 1` begins with a transition, from `states()[k − 1].motion` to
/// `states()[k].motion`; a calendar asked for transitions
/// ([`ScheduleOptions::transitions`](crate::schedule::ScheduleOptions::transitions)) reports
/// each start as an [`Event::Transition`](crate::schedule::Event::Transition) with the
/// segment's index. Made by [`ball_path`].
#[derive(Clone, Debug, PartialEq)]
pub struct BallPath {
    path: Path2,
    states: Vec<BallState>,
    params: BallParams,
}

impl BallPath {
    /// The centre's motion (example: [`ball_path`]).
    pub fn path(&self) -> &Path2 {
        &self.path
    }

    /// The centre's motion, taken out.
    pub fn into_path(self) -> Path2 {
        self.path
    }

    /// The ball's state at the start of each segment, after the transition that begins it
    /// ([`TransitionKind::apply`](super::TransitionKind::apply)); as many as segments
    /// (example: [`ball_path`]).
    pub fn states(&self) -> &[BallState] {
        &self.states
    }

    /// The parameters the motion was made with.
    pub fn params(&self) -> &BallParams {
        &self.params
    }

    /// The ball's full state at the absolute time `t`: the state at the start of the segment
    /// active at `t`, [`evolve`](super::evolve)d for the time since that start, as pooltool's
    /// loop evolves a ball to an event. Times before the first start give the first state.
    ///
    /// ```
    /// use ballcollide::billiards::{BallParams, BallState, MotionState, ball_path};
    /// use nalgebra::{Vector2, Vector3};
    /// let params = BallParams::default();
    /// let shot = BallState::new(Vector2::new(0.5, 0.5), Vector2::new(1.5, 0.3), Vector3::new(10.0, 0.0, -20.0), MotionState::Sliding);
    /// let motion = ball_path(&shot, &params, 2.0)?;
    /// let later = motion.state_at(2.7);
    /// assert_eq!(later.motion, MotionState::Rolling);
    /// assert!((later.position - motion.path().position_at(2.7)).norm() < 1e-15);
    /// assert!((later.velocity - motion.path().velocity_at(2.7)).norm() < 1e-15);
    /// assert_eq!(motion.state_at(0.0), shot);
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn state_at(&self, t: f64) -> BallState {
        let segments = self.path.segments();
        // The last segment started by `t` (an empty one is followed by one of the same start).
        let k = segments.iter().rposition(|s| s.start <= t).unwrap_or(0);
        let since = (t - segments[k].start).max(0.0);
        evolve(&self.states[k], &self.params, since)
    }
}

/// The motion of a ball in `state` at the absolute time `start`, until it stops, as a
/// [`BallPath`]: one segment per motion state, each starting where the one before ended.
///
/// - sliding: the acceleration `−u_s·g·û` ([`evolve_slide`](super::evolve_slide): `û` is the
///   unit slip, constant during a slide), for [`slide_time`](super::slide_time); then
/// - rolling: `−u_r·g·v̂`, for [`roll_time`](super::roll_time); then
/// - spinning in place, at rest, for [`spin_time`](super::spin_time) (if the spin outlasts
///   the roll: [`next_transition`]); then
/// - stationary, at rest, for ever.
///
/// A ball that is rolling, spinning or stationary starts at that stage. Each segment starts at
/// the time the one before started plus its state's time, with the ball's state there as
/// pooltool's event loop makes it for a ball that nothing else happens to: the state before
/// [`evolve`](super::evolve)d over the difference of the two starts (in float64, which may
/// pass the state's time by a rounding, and [`evolve`](super::evolve) then goes on into the
/// next state for that rounding), then the transition
/// ([`TransitionKind::apply`](super::TransitionKind::apply)). A stage of time 0 (a slide without slip) is an empty
/// segment, kept with its state. A state that lasts for ever (a friction of 0) ends the path.
/// A pocketed ball is one segment at rest (a calendar should
/// [`retire`](crate::schedule::CollisionSchedule::retire) it). A stationary ball with a
/// velocity, which pooltool never makes, does not move.
///
/// The centre's positions and velocities on the path agree with [`evolve`](super::evolve) to a
/// few roundings (the path's segment formula against pooltool's, see `tests/integration/billiards.rs`).
///
/// # Errors
/// An [`InputError`] naming the first offending field of `params` ([`BallParams::check`]) or
/// of `state` ([`BallState::check`]), or `start` if it is not finite; a path whose numbers
/// overflow (speeds near `1e150`) is refused as [`Path2::new`] refuses it.
///
/// ```
/// use ballcollide::billiards::{BallParams, BallState, MotionState, ball_path};
/// use nalgebra::{Vector2, Vector3};
/// let params = BallParams::default();
/// // Struck with side spin: slides, rolls, then spins in place until the spin is spent.
/// let shot = BallState::new(Vector2::new(0.5, 0.5), Vector2::new(1.0, 0.0), Vector3::new(0.0, 0.0, 150.0), MotionState::Sliding);
/// let motion = ball_path(&shot, &params, 0.0)?;
/// let stages: Vec<_> = motion.states().iter().map(|s| s.motion).collect();
/// use MotionState::*;
/// assert_eq!(stages, [Sliding, Rolling, Spinning, Stationary]);
/// let rest = motion.path().segments()[2].position;
/// assert_eq!(motion.path().position_at(1e3), rest); // spinning in place did not move it
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn ball_path(
    state: &BallState,
    params: &BallParams,
    start: f64,
) -> Result<BallPath, InputError> {
    params.check()?;
    state.check()?;
    finite("start", start)?;
    let mut segments = Vec::with_capacity(4);
    let mut states = Vec::with_capacity(4);
    let (mut state, mut start) = (*state, start);
    // Each transition leads to a later stage (sliding, rolling, spinning, stationary): at
    // most four segments.
    loop {
        let acceleration = match state.motion {
            MotionState::Sliding => slide_acceleration(&state, params),
            MotionState::Rolling => roll_acceleration(&state, params),
            _ => Default::default(),
        };
        let velocity = if state.motion.translates() {
            state.velocity
        } else {
            Default::default()
        };
        segments.push(Segment2::new(start, state.position, velocity, acceleration));
        states.push(state);
        let Some(next) = next_transition(&state, params) else {
            break;
        };
        if next.delay == f64::INFINITY {
            break;
        }
        // As pooltool's loop reaches a transition: `evolve_ball_motion` over the event's time
        // less the current one (which may pass the state's end by a rounding, and then goes
        // on into the next state), then the transition.
        let end = start + next.delay;
        state = next.kind.apply(&evolve(&state, params, end - start));
        start = end;
    }
    Ok(BallPath {
        path: Path2::new(segments)?,
        states,
        params: *params,
    })
}
