//! [`evolve_spin`]: the spin about the vertical, decaying under the cloth's spinning friction.

use super::BallParams;

/// Below this `|ω_z|` a spin is left as it is (pooltool's `EPS`, 100 float64 epsilons).
const STILL_SPIN: f64 = f64::EPSILON * 100.0;

/// The spin about the vertical `t` after it was `w_z`: it decays towards 0 at the constant
/// rate `α = 5·u_sp·g / (2·R)` and stays there (pooltool's
/// `_evolve_perpendicular_spin_component`, to the bit).
///
/// As pooltool: `t = 0` and `|w_z| < 100·ε` (`2.2e-14`) give `w_z` unchanged; the decay stops
/// at `t = |w_z|/α`, where the result is `0` up to one rounding (`w_z − α·(|w_z|/α)`, not
/// always exactly 0). The spin decays in every motion state: a sliding or rolling ball's side
/// spin too.
///
/// ```
/// use ballcollide::billiards::{BallParams, evolve_spin};
/// let params = BallParams::default();
/// let rate = 5.0 * params.u_sp() * params.g / (2.0 * params.radius);
/// assert_eq!(rate, 10.9); // 1/s²: 5·(4/9)·9.81/2
/// assert_eq!(evolve_spin(10.0, &params, 0.5), 10.0 - rate * 0.5);
/// assert_eq!(evolve_spin(-10.0, &params, 0.5), -10.0 + rate * 0.5);
/// assert!(evolve_spin(10.0, &params, 100.0).abs() < 1e-14); // spent: 0, up to a rounding
/// assert_eq!(evolve_spin(1e-15, &params, 1.0), 1e-15); // below pooltool's EPS: unchanged
/// ```
pub fn evolve_spin(w_z: f64, params: &BallParams, t: f64) -> f64 {
    if t == 0.0 || w_z.abs() < STILL_SPIN {
        return w_z;
    }
    let alpha = 5.0 * params.u_sp() * params.g / (2.0 * params.radius);
    let t = if t > w_z.abs() / alpha {
        w_z.abs() / alpha
    } else {
        t
    };
    let sign = if w_z > 0.0 { 1.0 } else { -1.0 };
    w_z - sign * alpha * t
}
