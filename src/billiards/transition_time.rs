//! How long each motion state lasts: [`slide_time`], [`roll_time`], [`spin_time`]
//! (pooltool's `get_slide_time`, `get_roll_time`, `get_spin_time`, to the bit).

use super::direction::norm;
use super::{BallParams, BallState, slip_velocity};

/// How long a slide lasts: `2·|u| / (7·u_s·g)`, `u` the [`slip_velocity`], after which the
/// ball rolls; `+∞` for `u_s = 0`.
///
/// ```
/// use ballcollide::billiards::{BallParams, BallState, MotionState, slide_time};
/// use nalgebra::{Vector2, Vector3};
/// let params = BallParams::default();
/// // A stun shot at 2 m/s: slips at 2 m/s, slides for 2·2/(7·0.2·9.81) s.
/// let stun = BallState::new(Vector2::zeros(), Vector2::new(2.0, 0.0), Vector3::zeros(), MotionState::Sliding);
/// assert_eq!(slide_time(&stun, &params), 2.0 * 2.0 / (7.0 * 0.2 * 9.81));
/// ```
pub fn slide_time(state: &BallState, params: &BallParams) -> f64 {
    if params.u_s == 0.0 {
        return f64::INFINITY;
    }
    2.0 * norm(slip_velocity(state, params.radius)) / (7.0 * params.u_s * params.g)
}

/// How long a roll lasts: `|v| / (u_r·g)`, after which the ball spins in place or stops;
/// `+∞` for `u_r = 0`.
///
/// ```
/// use ballcollide::billiards::{BallParams, BallState, MotionState, roll_time};
/// use nalgebra::{Vector2, Vector3};
/// let params = BallParams::default();
/// let v = Vector2::new(0.6, 0.8);
/// let w = Vector3::new(-0.8, 0.6, 0.0) / params.radius;
/// let rolling = BallState::new(Vector2::zeros(), v, w, MotionState::Rolling);
/// assert_eq!(roll_time(&rolling, &params), 1.0 / (0.01 * 9.81));
/// ```
pub fn roll_time(state: &BallState, params: &BallParams) -> f64 {
    if params.u_r == 0.0 {
        return f64::INFINITY;
    }
    norm(state.velocity) / (params.u_r * params.g)
}

/// How long the spin about the vertical lasts: `2·R·|ω_z| / (5·u_sp·g)`, evaluated as
/// pooltool does (`|ω_z|·2/5·R/u_sp/g`, left to right); `+∞` for `u_sp = 0`.
///
/// ```
/// use ballcollide::billiards::{BallParams, BallState, MotionState, spin_time};
/// use nalgebra::{Vector2, Vector3};
/// let params = BallParams::default();
/// let spinning = BallState::new(Vector2::zeros(), Vector2::zeros(), Vector3::new(0.0, 0.0, -10.0), MotionState::Spinning);
/// let t = spin_time(&spinning, &params);
/// assert!((t - 2.0 * params.radius * 10.0 / (5.0 * params.u_sp() * params.g)).abs() < 1e-15);
/// ```
pub fn spin_time(state: &BallState, params: &BallParams) -> f64 {
    let u_sp = params.u_sp();
    if u_sp == 0.0 {
        return f64::INFINITY;
    }
    state.angular_velocity.z.abs() * 2.0 / 5.0 * params.radius / u_sp / params.g
}
