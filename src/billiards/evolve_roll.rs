//! [`evolve_roll`]: a rolling ball, `t` later.

use nalgebra::{Vector2, Vector3};

use super::direction::unit;
use super::{BallParams, BallState, evolve_spin};

/// `cos(π/2)` in float64 (`6.1e-17`, not 0): pooltool turns `v/R` a quarter turn by a
/// rotation matrix built from `np.pi / 2`, and its rolling spin carries this trace of the
/// other component.
const COS_QUARTER_TURN: f64 = 6.123233995736766e-17;

/// The state of a rolling ball `t` after `state` (for `0 ≤ t ≤` [`roll_time`]), pooltool's
/// `_evolve_roll_state`, with its arithmetic.
///
/// Rolling friction slows the centre at `u_r·g` against its velocity's direction `v̂`, and
/// the ball keeps rolling (`ω_xy` follows `v`):
///
/// - `r = r₀ + v₀·t − ½·u_r·g·t²·v̂`,
/// - `v = v₀ − u_r·g·t·v̂`,
/// - `(ω_x, ω_y) = (−v_y, v_x)/R` (to pooltool's bits: `v/R` turned by the rotation of
///   float64 `π/2`, whose cosine is `6.1e-17`), and `ω_z` by [`evolve_spin`].
///
/// The motion state is left as it is. `t = 0` gives `state` unchanged (its spin is not made
/// to roll), as pooltool. A ball without velocity stays where it is, where pooltool's formula
/// divides by zero and gives NaN.
///
/// ```
/// use ballcollide::billiards::{BallParams, BallState, MotionState, evolve_roll, roll_time};
/// use nalgebra::{Vector2, Vector3};
/// let params = BallParams::default();
/// let v = Vector2::new(0.0, 1.0);
/// let rolling = BallState::new(Vector2::zeros(), v, Vector3::new(-1.0 / params.radius, 0.0, 0.0), MotionState::Rolling);
/// let half = evolve_roll(&rolling, &params, roll_time(&rolling, &params) / 2.0);
/// assert!((half.velocity - v / 2.0).norm() < 1e-15);
/// assert!((half.angular_velocity.x + 0.5 / params.radius).abs() < 1e-12); // still rolling
/// ```
///
/// [`roll_time`]: super::roll_time
pub fn evolve_roll(state: &BallState, params: &BallParams, t: f64) -> BallState {
    if t == 0.0 {
        return *state;
    }
    let (u_r, g, radius) = (params.u_r, params.g, params.radius);
    let (r0, v0) = (state.position, state.velocity);
    let heading = unit(v0);
    let position = r0 + v0 * t - heading * (0.5 * u_r * g * (t * t));
    let velocity = v0 - heading * (u_r * g * t);
    let spin = velocity / radius;
    BallState {
        position,
        velocity,
        angular_velocity: Vector3::new(
            COS_QUARTER_TURN * spin.x - spin.y,
            spin.x + COS_QUARTER_TURN * spin.y,
            evolve_spin(state.angular_velocity.z, params, t),
        ),
        motion: state.motion,
    }
}

/// The rolling ball's constant acceleration, `−u_r·g·v̂` (zero at rest).
pub(super) fn roll_acceleration(state: &BallState, params: &BallParams) -> Vector2<f64> {
    unit(state.velocity) * -(params.u_r * params.g)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quarter_turn_cosine() {
        assert_eq!(COS_QUARTER_TURN, std::f64::consts::FRAC_PI_2.cos());
    }
}
