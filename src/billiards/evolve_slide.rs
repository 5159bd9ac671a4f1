//! [`evolve_slide`]: a sliding ball, `t` later.

use nalgebra::{Vector2, Vector3};

use super::direction::unit;
use super::{BallParams, BallState, evolve_spin, slip_velocity};

/// The state of a sliding ball `t` after `state` (for `0 ≤ t ≤` [`slide_time`]), pooltool's
/// `_evolve_slide_state`.
///
/// The cloth's friction `u_s·m·g` acts at the contact point against its slip `u`
/// ([`slip_velocity`]). The slip keeps its direction `û` while it shrinks to 0, so the centre
/// has the constant acceleration `−u_s·g·û` (a parabola, curved when `û` is not along `v`), and
/// the horizontal angular velocity changes at the constant rate `−(5/2)·(u_s·g/R)·(û_y, −û_x)`:
///
/// - `r = r₀ + v₀·t − ½·u_s·g·t²·û`,
/// - `v = v₀ − u_s·g·t·û`,
/// - `(ω_x, ω_y) = (ω₀ₓ, ω₀ᵧ) − (5/2)·(u_s·g/R)·t·(û_y, −û_x)`, and `ω_z` by [`evolve_spin`].
///
/// The motion state is left as it is. `t = 0` gives `state` unchanged (as pooltool). A ball
/// without slip (`u = 0`) keeps its velocity and horizontal spin, where pooltool's formula
/// divides by zero and gives NaN.
///
/// pooltool computes the same formulas in a frame turned to the initial velocity (with
/// `arctan2`, `cos`, `sin` and BLAS products there and back); this computes them in the table's
/// frame, so results differ from its by a few roundings (relative to the terms).
///
/// ```
/// use ballcollide::billiards::{BallParams, BallState, MotionState, evolve_slide, slide_time, slip_velocity};
/// use nalgebra::{Vector2, Vector3};
/// let params = BallParams::default();
/// let stun = BallState::new(Vector2::zeros(), Vector2::new(2.0, 0.0), Vector3::zeros(), MotionState::Sliding);
/// let end = evolve_slide(&stun, &params, slide_time(&stun, &params));
/// // At the end of the slide the ball rolls: 5/7 of its speed is left, and the slip is gone.
/// assert!((end.velocity - Vector2::new(10.0 / 7.0, 0.0)).norm() < 1e-15);
/// assert!(slip_velocity(&end, params.radius).norm() < 1e-14);
/// ```
///
/// [`slide_time`]: super::slide_time
pub fn evolve_slide(state: &BallState, params: &BallParams, t: f64) -> BallState {
    if t == 0.0 {
        return *state;
    }
    let (u_s, g, radius) = (params.u_s, params.g, params.radius);
    let slip = unit(slip_velocity(state, radius));
    // pooltool's scalar products, in its order: `0.5 * u_s * g * t**2`, `u_s * g * t`,
    // `5 / 2 / R * u_s * g * t`.
    let drift = 0.5 * u_s * g * (t * t);
    let slowing = u_s * g * t;
    let torque = 5.0 / 2.0 / radius * u_s * g * t;
    let w = state.angular_velocity;
    BallState {
        position: state.position + (state.velocity * t - slip * drift),
        velocity: state.velocity - slip * slowing,
        angular_velocity: Vector3::new(
            w.x - torque * slip.y,
            w.y + torque * slip.x,
            evolve_spin(w.z, params, t),
        ),
        motion: state.motion,
    }
}

/// The sliding ball's constant acceleration, `−u_s·g·û` (zero without slip).
pub(super) fn slide_acceleration(state: &BallState, params: &BallParams) -> Vector2<f64> {
    unit(slip_velocity(state, params.radius)) * -(params.u_s * params.g)
}
