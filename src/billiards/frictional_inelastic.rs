//! [`FrictionalInelastic`]: pooltool's default ball–ball collision, with the friction of
//! [`AlciatoreFriction`].

use nalgebra::{Vector2, Vector3};

use super::direction::{cross, norm3, unit, unit3};
use super::{BallBallResolver, BallParams, BallState, MotionState};

/// Below this relative speed of the contact points, a collision has no slip to start with
/// (pooltool's `EPS`).
const NO_SLIP: f64 = f64::EPSILON * 100.0;

/// The coefficient of friction between two balls as a function of how fast their surfaces
/// slide over each other at the contact, `μ = a + b·e^(−c·|Δu|)` (Alciatore's fit, TP A-14;
/// pooltool's `AlciatoreBallBallFriction`). [`Default`] is pooltool's fit: `a = 9.951e-3`,
/// `b = 0.108`, `c = 1.088` (s/m).
///
/// ```
/// use ballcollide::billiards::AlciatoreFriction;
/// let fit = AlciatoreFriction::default();
/// assert_eq!(fit.at(0.0), 9.951e-3 + 0.108); // surfaces that do not slide: the most grip
/// assert!(fit.at(10.0) < 0.011);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AlciatoreFriction {
    /// The friction at high sliding speeds.
    pub a: f64,
    /// The friction added at a sliding speed of 0.
    pub b: f64,
    /// How fast the added friction fades with the sliding speed.
    pub c: f64,
}

impl Default for AlciatoreFriction {
    fn default() -> Self {
        Self {
            a: 9.951e-3,
            b: 0.108,
            c: 1.088,
        }
    }
}

impl AlciatoreFriction {
    /// The friction at the sliding speed `speed` (example: [`AlciatoreFriction`]).
    pub fn at(&self, speed: f64) -> f64 {
        self.a + self.b * (-self.c * speed).exp()
    }

    /// The friction between two balls in contact: at the speed of the contact points'
    /// velocities relative to each other, tangent to the balls (each ball's velocity without
    /// its part along the line of centres, plus its spin's at the contact), as pooltool's
    /// `calculate_friction` computes it.
    pub fn between(&self, balls: [&BallState; 2], params: [&BallParams; 2]) -> f64 {
        let normal = unit(balls[1].position - balls[0].position);
        let n = Vector3::new(normal.x, normal.y, 0.0);
        let a = tangent_surface_velocity(balls[0], n, params[0].radius);
        let b = tangent_surface_velocity(balls[1], -n, params[1].radius);
        self.at(norm3(a - b))
    }
}

/// pooltool's `tangent_surface_velocity`: the velocity of the point of the ball's surface in
/// the direction `d`, without the centre's velocity along `d`.
fn tangent_surface_velocity(ball: &BallState, d: Vector3<f64>, radius: f64) -> Vector3<f64> {
    let v = Vector3::new(ball.velocity.x, ball.velocity.y, 0.0);
    // np.sum(v * d): in order, from 0.
    let along = v.x * d.x + v.y * d.y + v.z * d.z;
    let tangent = v - d * along;
    tangent + cross(ball.angular_velocity, d * radius)
}

/// pooltool 0.6.0's default ball–ball model (`FrictionalInelastic`, after Alciatore's technical
/// proofs TP A-5, A-6 and A-14): an inelastic collision of two equal balls along the line of
/// centres, with the restitution the average of the two balls' `e_b`, and friction between
/// them at the contact (coefficient [`AlciatoreFriction`]) that throws them off that line and
/// changes their spins. The friction acts against the contact points' relative slip for as
/// long as they slide; if that would reverse the slip, the surfaces grip instead (the
/// no-slip solution). Both balls leave sliding.
///
/// Computed as pooltool computes it, in the frame of the line of centres, with that frame
/// built from the line's unit vector rather than turned by its angle (pooltool's `arctan2`,
/// `cos`, `sin` and BLAS products): results within a few roundings of pooltool's. The vertical
/// velocity the friction would give is dropped, as pooltool drops it. The balls are taken as
/// equal (the first ball's radius; the masses do not enter), at one height.
///
/// ```
/// use ballcollide::billiards::{BallBallResolver, BallParams, BallState, FrictionalInelastic, MotionState};
/// use nalgebra::{Vector2, Vector3};
/// let params = BallParams::default();
/// let r = params.radius;
/// // A half-ball hit: the object ball leaves along the line of centres, thrown a little.
/// let cue = BallState::new(Vector2::zeros(), Vector2::new(2.0, 0.0), Vector3::new(0.0, 2.0 / r, 0.0), MotionState::Rolling);
/// let object = BallState::at_rest(Vector2::new(2.0 * r * 0.75f64.sqrt(), r));
/// let [cue, object] = FrictionalInelastic::default().solve([&cue, &object], [&params, &params]);
/// let line = Vector2::new(0.75f64.sqrt(), 0.5);
/// let off_line = object.velocity.perp(&line) / object.velocity.norm();
/// assert!(off_line > 0.005 && off_line < 0.02); // thrown by about half a degree
/// assert!(cue.velocity.dot(&object.velocity).abs() < 0.2); // nearly at right angles
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FrictionalInelastic {
    /// The friction between the balls.
    pub friction: AlciatoreFriction,
}

impl BallBallResolver for FrictionalInelastic {
    fn solve(&self, balls: [&BallState; 2], params: [&BallParams; 2]) -> [BallState; 2] {
        let u_b = self.friction.between(balls, params);
        let e_b = (params[0].e_b + params[1].e_b) / 2.0;
        resolve_in_line_frame(balls, params[0].radius, u_b, e_b)
    }
}

/// One ball's velocity and angular velocity in the frame of the line of centres: `x` along it
/// (from the first ball to the second), `y` across it (a quarter turn anticlockwise), `z` up.
struct Frame {
    normal: Vector2<f64>,
}

impl Frame {
    fn to_line(&self, v: Vector2<f64>) -> Vector2<f64> {
        let n = self.normal;
        Vector2::new(v.x * n.x + v.y * n.y, v.y * n.x - v.x * n.y)
    }

    fn to_table(&self, v: Vector2<f64>) -> Vector2<f64> {
        let n = self.normal;
        Vector2::new(v.x * n.x - v.y * n.y, v.x * n.y + v.y * n.x)
    }

    fn spin_to_line(&self, w: Vector3<f64>) -> Vector3<f64> {
        let xy = self.to_line(w.xy());
        Vector3::new(xy.x, xy.y, w.z)
    }

    fn spin_to_table(&self, w: Vector3<f64>) -> Vector3<f64> {
        let xy = self.to_table(w.xy());
        Vector3::new(xy.x, xy.y, w.z)
    }
}

/// pooltool's `_resolve_ball_ball`, in the line of centres' frame.
fn resolve_in_line_frame(
    balls: [&BallState; 2],
    radius: f64,
    u_b: f64,
    e_b: f64,
) -> [BallState; 2] {
    let frame = Frame {
        normal: unit(balls[1].position - balls[0].position),
    };
    let (v1, v2) = (
        frame.to_line(balls[0].velocity),
        frame.to_line(balls[1].velocity),
    );
    let (w1, w2) = (
        frame.spin_to_line(balls[0].angular_velocity),
        frame.spin_to_line(balls[1].angular_velocity),
    );
    // Along the line: the inelastic collision, whatever the friction.
    let v1_n = 0.5 * ((1.0 - e_b) * v1.x + (1.0 + e_b) * v2.x);
    let v2_n = 0.5 * ((1.0 + e_b) * v1.x + (1.0 - e_b) * v2.x);
    let normal_change = (v2_n - v1_n).abs();
    // Across it, in 3-D (the friction has a vertical part, dropped at the end).
    let v1 = Vector3::new(0.0, v1.y, 0.0);
    let v2 = Vector3::new(0.0, v2.y, 0.0);
    let (w1_n, w2_n) = (w1.x, w2.x);
    let w1 = Vector3::new(0.0, w1.y, w1.z);
    let w2 = Vector3::new(0.0, w2.y, w2.z);
    let x = Vector3::x();
    let contact = |v: Vector3<f64>, w: Vector3<f64>, side: f64| v + cross(w, x * (side * radius));
    let slip = contact(v1, w1, 1.0) - contact(v2, w2, -1.0);
    let sliding = norm3(slip) > NO_SLIP;
    let mut after = None;
    if sliding {
        // Friction against the slip, proportional to the normal change.
        let dv = -unit3(slip) * (u_b * normal_change);
        let dw = cross(x, dv) * (2.5 / radius);
        let [v1f, w1f, v2f, w2f] = [v1 + dv, w1 + dw, v2 - dv, w2 + dw];
        let slip_after = contact(v1f, w1f, 1.0) - contact(v2f, w2f, -1.0);
        let reversed = slip.dot(&slip_after) <= 0.0;
        if !reversed {
            after = Some([v1f, w1f, v2f, w2f]);
        }
    }
    // No slip at the start, or friction that would reverse it: the surfaces grip.
    let [v1f, w1f, v2f, w2f] = after.unwrap_or_else(|| {
        let dv = (v1 - v2 + cross(w1 + w2, x) * radius) * -(1.0 / 7.0);
        let dw = (cross(x, v1 - v2) / radius + w1 + w2) * -(5.0 / 14.0);
        [v1 + dv, w1 + dw, v2 - dv, w2 + dw]
    });
    let state =
        |ball: &BallState, v: Vector3<f64>, v_n: f64, w: Vector3<f64>, w_n: f64| BallState {
            velocity: frame.to_table(Vector2::new(v_n, v.y)),
            angular_velocity: frame.spin_to_table(Vector3::new(w_n, w.y, w.z)),
            motion: MotionState::Sliding,
            ..*ball
        };
    [
        state(balls[0], v1f, v1_n, w1f, w1_n),
        state(balls[1], v2f, v2_n, w2f, w2_n),
    ]
}
