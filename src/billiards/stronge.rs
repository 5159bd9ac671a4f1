//! Stronge's compliant frictional collision of a ball with a cushion, as pooltool 0.6.0 solves
//! it (`physics/resolve/stronge_compliant.py`, and `_solve` in its `ball_cushion`
//! `stronge_compliant` model): the normal and tangential compliances are springs of
//! frequencies `ω_n` and `ω_t = ω_n·omega_ratio`; the contact sticks or slips in closed-form
//! phases, and where a phase ends is a root found by TOMS748 (`root.rs`, scipy's steps) in two
//! of the three regimes (pooltool calls `scipy.optimize.toms748`).

use std::f64::consts::PI;

use nalgebra::Vector3;

use super::direction::{cross, norm3};
use super::root::toms748;
use super::{BallParams, BallState, MotionState};

/// The tangential and normal velocities of the contact point at the end of a collinear
/// compliant frictional collision (pooltool's
/// `resolve_collinear_compliant_frictional_inelastic_collision`), from those at its start:
/// `v_t_0 ≤ 0`, `v_n_0 < 0` (approaching). `beta_t`, `beta_n` are the inverse-inertia
/// coefficients (`3.5` and `1` for a ball on a half-space), `m` the effective mass, `mu` the
/// friction, `e_n` the normal restitution, `k_n` the normal stiffness (it sets the duration
/// only) and `eta_squared` the normal to tangential stiffness ratio, which must make
/// `ω_t/ω_n = √(beta_t/beta_n/eta_squared)` lie in `(1, 2)`.
///
/// `None` where pooltool fails: a tangential velocity above 0, a normal one not below 0, a
/// frequency ratio outside `(1, 2)`, a non-finite number, or no root where one is sought.
///
/// ```
/// use ballcollide::billiards::compliant_collinear_collision;
/// // Head on (no tangential velocity): the normal velocity comes back times e_n.
/// let (v_t, v_n) = compliant_collinear_collision(0.0, -2.0, 0.17, 3.5, 1.0, 0.2, 0.85, 1e3, 3.5 / 1.8f64.powi(2)).unwrap();
/// assert_eq!(v_t, 0.0);
/// assert!((v_n - 1.7).abs() < 1e-14);
/// // Glancing: friction acts through the whole contact (gross slip).
/// let (v_t, _) = compliant_collinear_collision(-5.0, -0.5, 0.17, 3.5, 1.0, 0.2, 0.85, 1e3, 3.5 / 1.8f64.powi(2)).unwrap();
/// assert!((v_t - (-5.0 + 0.2 * 0.5 * 3.5 * 1.85)).abs() < 1e-14);
/// ```
#[allow(clippy::too_many_arguments)]
pub fn compliant_collinear_collision(
    v_t_0: f64,
    v_n_0: f64,
    m: f64,
    beta_t: f64,
    beta_n: f64,
    mu: f64,
    e_n: f64,
    k_n: f64,
    eta_squared: f64,
) -> Option<(f64, f64)> {
    let inputs = [v_t_0, v_n_0, m, beta_t, beta_n, mu, e_n, k_n, eta_squared];
    if inputs.iter().any(|x| !x.is_finite()) || v_t_0 > 0.0 || v_n_0 >= 0.0 || e_n <= 0.0 {
        return None;
    }
    let beta_t_by_beta_n = beta_t / beta_n;
    let ratio = v_t_0 / v_n_0;
    let omega_n = (beta_n * k_n / m).sqrt();
    let omega_t = omega_n * (beta_t_by_beta_n / eta_squared).sqrt();
    let frequencies = omega_t / omega_n;
    if !(1.0 < frequencies && frequencies < 2.0) {
        return None;
    }
    let t_c = PI / (2.0 * omega_n);
    let t_f = (1.0 + e_n) * t_c;
    let restitution_phase = |t: f64| omega_n * t / e_n + (PI / 2.0) * (1.0 - 1.0 / e_n);
    let gross_slip_bound = mu * ((1.0 + e_n) * beta_t_by_beta_n - eta_squared / e_n);

    let v_t_f = if ratio > gross_slip_bound {
        v_t_0 - mu * v_n_0 * beta_t_by_beta_n * (1.0 + e_n)
    } else if ratio < mu * eta_squared {
        // Stick, then slip.
        let t_slip = if is_close(ratio, 0.0) {
            t_f
        } else if is_close(ratio, mu * eta_squared) {
            t_c
        } else {
            let f = |t: f64| {
                (-ratio * (omega_t * t).sin()).abs()
                    - (mu * eta_squared * omega_t / omega_n * restitution_phase(t).sin())
            };
            root(f, t_c, t_f)?
        };
        let v_t_stick_to_slip = v_t_stick(t_slip, omega_t, v_t_0, 0.0, 0.0);
        v_t_stick_to_slip
            + mu * v_n_0
                * beta_t_by_beta_n
                * e_n
                * (1.0 + (omega_n * t_slip / e_n + (PI / 2.0) * (1.0 - 1.0 / e_n)).cos())
    } else {
        // Slip, stick, slip.
        let t_stick =
            t_c * nondimensional_stick_time(ratio, beta_t_by_beta_n, mu, e_n, eta_squared, t_c)?;
        let (u_t, v_t) = if t_stick <= t_c {
            (
                -mu * v_n_0 * eta_squared / omega_n * (omega_n * t_stick).sin(),
                v_t_0 - mu * beta_t_by_beta_n * v_n_0 * (1.0 - (omega_n * t_stick).cos()),
            )
        } else {
            let phase = restitution_phase(t_stick);
            (
                -mu * v_n_0 * eta_squared / omega_n * phase.sin(),
                v_t_0 - mu * beta_t_by_beta_n * v_n_0 * (1.0 - e_n * phase.cos()),
            )
        };
        let t_slip = if is_close(ratio, mu * eta_squared) {
            t_c
        } else if is_close(ratio, gross_slip_bound) {
            t_f
        } else {
            let f = |t: f64| {
                (omega_n / (mu * v_n_0)
                    * (u_t * (omega_t * (t - t_stick)).cos()
                        - v_t / omega_t * (omega_t * (t - t_stick)).sin()))
                .abs()
                    - eta_squared * restitution_phase(t).sin()
            };
            root(f, t_c, t_f)?
        };
        let v_t_stick_to_slip = v_t_stick(t_slip, omega_t, v_t, u_t, t_stick);
        v_t_stick_to_slip
            + beta_t_by_beta_n * mu * v_n_0 * e_n * (1.0 + restitution_phase(t_slip).cos())
    };
    let v_n_f = e_n * v_n_0 * restitution_phase(t_f).cos();
    Some((v_t_f, v_n_f))
}

/// numpy's `isclose(a, b)` (`|a − b| ≤ 1e-8 + 1e-5·|b|`).
fn is_close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-8 + 1e-5 * b.abs()
}

/// A root in `[t_c, t_f]` as pooltool finds it: `toms748` with scipy's defaults (`k = 1`,
/// `xtol = 2e-12`, `rtol = 4ε`, 100 iterations), the same steps to the same bits.
fn root(f: impl FnMut(f64) -> f64, t_c: f64, t_f: f64) -> Option<f64> {
    toms748(f, t_c, t_f, 1, 2e-12, 4.0 * f64::EPSILON, 100).filter(|t| (t_c..=t_f).contains(t))
}

fn v_t_stick(time: f64, omega_t: f64, v_t_stick_0: f64, u_t_stick_0: f64, time_stick: f64) -> f64 {
    omega_t * u_t_stick_0 * (omega_t * (time - time_stick)).sin()
        + v_t_stick_0 * (omega_t * (time - time_stick)).cos()
}

/// pooltool's `nondimensional_stick_time_for_initial_slip`; `None` where its asserts fail.
pub(super) fn nondimensional_stick_time(
    ratio: f64,
    beta_t_by_beta_n: f64,
    mu: f64,
    e_n: f64,
    eta_squared: f64,
    _t_c: f64,
) -> Option<f64> {
    let in_range = |x: f64| (-1.0..=1.0).contains(&x);
    if ratio <= mu * beta_t_by_beta_n {
        let x = ((ratio / mu) - beta_t_by_beta_n) / (eta_squared - beta_t_by_beta_n);
        let result = (2.0 / PI) * x.acos();
        (in_range(x) && (0.0..=1.0).contains(&result)).then_some(result)
    } else {
        let x = ((ratio / mu) - beta_t_by_beta_n) / (eta_squared / e_n - e_n * beta_t_by_beta_n);
        let result = (2.0 / PI) * (x.acos() - (PI / 2.0) * (1.0 - 1.0 / e_n)) * e_n;
        (in_range(x) && (1.0..=(1.0 + e_n)).contains(&result)).then_some(result)
    }
}

/// pooltool's `_solve` for both cushion kinds: the ball after it meets a cushion whose outward
/// unit normal at the contact (from the cushion to the ball's centre, in 3D) is `normal`.
/// `None` where [`compliant_collinear_collision`] is.
pub(super) fn solve_with_normal(
    ball: &BallState,
    params: &BallParams,
    normal: Vector3<f64>,
    omega_ratio: f64,
) -> Option<BallState> {
    let radius = params.radius;
    let mut v = Vector3::new(ball.velocity.x, ball.velocity.y, 0.0);
    let mut w = ball.angular_velocity;
    let surface = |v: Vector3<f64>, w: Vector3<f64>| v + cross(w, -normal * radius);
    let contact = surface(v, w);
    // decompose_normal_tangent(contact, normal, flip_tangent_direction=True)
    let v_n_0 = normal.x * contact.x + normal.y * contact.y + normal.z * contact.z;
    let n_cross_v = cross(normal, contact);
    let v_t_0 = -norm3(n_cross_v);
    let tangent = if v_t_0 != 0.0 {
        cross(n_cross_v, normal) / v_t_0
    } else {
        Vector3::zeros()
    };
    let (beta_t, beta_n) = (3.5, 1.0);
    let beta_t_by_beta_n: f64 = beta_t / beta_n;
    let (v_t_f, v_n_f) = compliant_collinear_collision(
        v_t_0,
        v_n_0,
        params.mass,
        beta_t,
        beta_n,
        params.f_c,
        params.e_c,
        1e3,
        beta_t_by_beta_n / omega_ratio.powi(2),
    )?;
    let dv_n = (v_n_f - v_n_0) / beta_n;
    v += normal * dv_n;
    let dv_t = (v_t_f - v_t_0) / beta_t;
    v += tangent * dv_t;
    w += cross(-normal, tangent * dv_t) * (2.5 / radius);
    Some(BallState::new(
        ball.position,
        v.xy(),
        w,
        MotionState::Sliding,
    ))
}
