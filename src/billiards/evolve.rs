//! [`evolve`]: a ball's state any time later, through its transitions.

use super::{
    BallParams, BallState, MotionState, evolve_roll, evolve_slide, evolve_spin, roll_time,
    slide_time, spin_time,
};

/// The state of the ball `t ≥ 0` after `state`, through as many transitions as come in that
/// time (pooltool's `evolve_ball_motion`, with its chaining).
///
/// A sliding ball slides for [`slide_time`], then rolls for [`roll_time`], then spins in place
/// for [`spin_time`], then is stationary; each stage starts from the state where the one
/// before ended, with the time left (`t` minus the stage's time, in float64). As in pooltool,
/// a stage is passed when `t ≥` its time; the states are chained as computed, with none of the
/// clean-up of [`TransitionKind::apply`] (the tiny velocities left at a roll's end stay), and
/// a rolling ball always passes through spinning (for a time of 0 if its spin is spent). A
/// stationary or pocketed ball stays as it is.
///
/// ```
/// use ballcollide::billiards::{BallParams, BallState, MotionState, evolve, slide_time};
/// use nalgebra::{Vector2, Vector3};
/// let params = BallParams::default();
/// let shot = BallState::new(Vector2::new(0.5, 0.5), Vector2::new(1.0, 0.0), Vector3::new(0.0, 0.0, 20.0), MotionState::Sliding);
/// let sliding = evolve(&shot, &params, slide_time(&shot, &params) / 2.0);
/// assert_eq!(sliding.motion, MotionState::Sliding);
/// let later = evolve(&shot, &params, 3.0);
/// assert_eq!(later.motion, MotionState::Rolling);
/// let done = evolve(&shot, &params, 60.0);
/// assert_eq!(done.motion, MotionState::Stationary);
/// assert_eq!(evolve(&done, &params, 1.0), done);
/// ```
///
/// [`TransitionKind::apply`]: super::TransitionKind::apply
// `!(t >= x)` rather than `t < x`: pooltool's test, `t >= x`, with a NaN in it (a NaN `t`
// stays in the first stage).
#[allow(clippy::neg_cmp_op_on_partial_ord)]
pub fn evolve(state: &BallState, params: &BallParams, t: f64) -> BallState {
    let mut state = *state;
    let mut t = t;
    if state.motion == MotionState::Sliding {
        let slide = slide_time(&state, params);
        if !(t >= slide) {
            return evolve_slide(&state, params, t);
        }
        state = evolve_slide(&state, params, slide);
        state.motion = MotionState::Rolling;
        t -= slide;
    }
    if state.motion == MotionState::Rolling {
        let roll = roll_time(&state, params);
        if !(t >= roll) {
            return evolve_roll(&state, params, t);
        }
        state = evolve_roll(&state, params, roll);
        state.motion = MotionState::Spinning;
        t -= roll;
    }
    if state.motion == MotionState::Spinning {
        let spin = spin_time(&state, params);
        let (t, motion) = if t >= spin {
            (spin, MotionState::Stationary)
        } else {
            (t, MotionState::Spinning)
        };
        state.angular_velocity.z = evolve_spin(state.angular_velocity.z, params, t);
        state.motion = motion;
    }
    state
}
