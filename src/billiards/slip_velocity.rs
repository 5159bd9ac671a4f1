//! [`slip_velocity`]: how fast the ball's contact point slides over the cloth.

use nalgebra::Vector2;

use super::BallState;

/// The velocity of the ball's contact point relative to the cloth, `u = v + ω × (−R·ẑ)`:
/// `(v_x − ω_y·R, v_y + ω_x·R)` (pooltool's `rel_velocity`, to the bit; its vertical
/// component is 0 on the table).
///
/// A sliding ball's cloth friction acts against `u`; a rolling ball has `u = 0`.
///
/// ```
/// use ballcollide::billiards::{BallState, MotionState, slip_velocity};
/// use nalgebra::{Vector2, Vector3};
/// let radius = 0.028575;
/// // Rolling along x at 1 m/s: ω_y = v/R, the contact point at rest on the cloth.
/// let v = Vector2::new(1.0, 0.0);
/// let rolling = BallState::new(Vector2::zeros(), v, Vector3::new(0.0, 1.0 / radius, 0.0), MotionState::Rolling);
/// assert!(slip_velocity(&rolling, radius).norm() < 1e-15);
/// // Without spin, the contact point moves with the centre.
/// let stun = BallState { angular_velocity: Vector3::zeros(), ..rolling };
/// assert_eq!(slip_velocity(&stun, radius), v);
/// ```
pub fn slip_velocity(state: &BallState, radius: f64) -> Vector2<f64> {
    let (v, w) = (state.velocity, state.angular_velocity);
    Vector2::new(v.x - w.y * radius, v.y + w.x * radius)
}
