//! [`InstantaneousPoint`]: pooltool 0.6.0's stick–ball model (its only one, and the default),
//! with its squirt ([`squirt_angle`]).

use std::f64::consts::PI;

use nalgebra::{Vector2, Vector3};

use super::{BallParams, BallState, Cue, MotionState, StickBallResolver};
use crate::error::{InputError, finite};

/// pooltool's `InstantaneousPoint`: the cue meets the ball at one point for an instant
/// (Alciatore's TP A-30), so the ball leaves sliding with the velocity and spin of the impulse
/// through that point; then its velocity turns by the squirt angle ([`squirt_angle`], TP
/// A-31). [`Default`] is pooltool's default resolver's: both throttles 1.
///
/// The stroke's contact point `(a, b)` is turned from the cue's frame into the ball's by the
/// elevation `θ`; the impulse gives the ball the speed `v = 2·V0 / (1 + m/M + |…|/(2R²/5))`
/// along the cue's horizontal direction (pooltool 0.6.0 drops the impulse's vertical part, a
/// massé's downward push: its "3D FIXME"), and the spin `v/(2R²/5) · (Q × the cue's
/// direction)`; both are turned onto the table by `φ + 90°`. Only the position of the ball
/// before is kept.
///
/// Checked against pooltool's own `resolve` on 2,000 random strokes, cues and balls
/// (`tests/reference/billiards.rs`): the same velocity and spin to the bit in 1,998; in the
/// other two, within 6.1e-17 of their scale (the ball's speed plus its spin's at the surface;
/// over the radius for spins), each differing component within 1.6e-16 of itself; the squirt
/// angle equal in 1,997, within 1.9e-16 of itself in the rest. Not always to the bit, because
/// pooltool's arithmetic is not all the C library's: it squares with NumPy's `**` and turns
/// the squirt with NumPy's `arctan2`, which on an AVX-512 machine are SIMD routines that
/// round otherwise now and then, and its rotations are BLAS's matrix products (see `rotate`
/// in the source for the order taken here).
///
/// Example: [`StickBallResolver`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InstantaneousPoint {
    /// Scales the spin the stroke gives (pooltool's `english_throttle`): below 1 less spin
    /// than the model's, above 1 more.
    pub english_throttle: f64,
    /// Scales the squirt angle (pooltool's `squirt_throttle`): 0 turns squirt off.
    pub squirt_throttle: f64,
}

impl Default for InstantaneousPoint {
    /// Both throttles 1, as in pooltool's default resolver (VERSION 9).
    fn default() -> Self {
        Self {
            english_throttle: 1.0,
            squirt_throttle: 1.0,
        }
    }
}

impl StickBallResolver for InstantaneousPoint {
    fn solve(&self, cue: &Cue, ball: &BallState, params: &BallParams) -> BallState {
        // The contact point in the ball's frame: the cue's (a, c, b) turned about the cue's
        // horizontal axis by θ, c the depth that puts it on the sphere. pooltool's order of
        // operations throughout (θ·π/180 here, θ·(π/180) in its cue_strike), so that its
        // rounding is ours.
        let theta = cue.theta * PI / 180.0;
        let (sin_t, cos_t) = (theta.sin(), theta.cos());
        let depth = (1.0 - cue.a * cue.a - cue.b * cue.b).sqrt();
        let contact = [
            cue.a,
            cos_t * depth - sin_t * cue.b,
            sin_t * depth + cos_t * cue.b,
        ];
        let (velocity, spin) = strike(cue, params, contact);
        let alpha = squirt_angle(
            params.mass,
            cue.specs.end_mass,
            contact[0],
            self.squirt_throttle,
        );
        BallState::new(
            ball.position,
            rotate(velocity, alpha),
            spin * self.english_throttle,
            MotionState::Sliding,
        )
    }

    /// Both throttles finite.
    fn check(&self) -> Result<(), InputError> {
        finite("english_throttle", self.english_throttle)?;
        finite("squirt_throttle", self.squirt_throttle)?;
        Ok(())
    }
}

/// pooltool's `cue_strike`: the velocity (in the plane) and the spin the stroke gives, before
/// squirt, from the contact point `(a, c, b)` in the ball's frame in units of its radius.
fn strike(cue: &Cue, params: &BallParams, contact: [f64; 3]) -> (Vector2<f64>, Vector3<f64>) {
    let (m, r) = (params.mass, params.radius);
    let phi = cue.phi * (PI / 180.0);
    let theta = cue.theta * (PI / 180.0);
    // The moment of inertia over the mass, 2R²/5.
    let i_m = 2.0 / 5.0 * (r * r);
    let [a, c, b] = contact.map(|x| r * x);
    let (sin_t, cos_t) = (theta.sin(), theta.cos());
    let (b_cos, c_sin) = (b * cos_t, c * sin_t);
    let lever = a * a + b_cos * b_cos + c_sin * c_sin - 2.0 * b * c * cos_t * sin_t;
    let speed = 2.0 * cue.v0 / (1.0 + m / cue.specs.mass + lever / i_m);
    // In the cue's frame the ball moves along −y (the cue's horizontal direction), the
    // vertical part dropped as pooltool drops it.
    let along = -speed * cos_t;
    let omega = speed / i_m;
    let spin = Vector3::new(
        omega * (-c * sin_t + b * cos_t),
        omega * (a * sin_t),
        omega * (-a * cos_t),
    );
    // Onto the table, turned by φ + 90°: the velocity (0, along) goes to (−sin·along,
    // cos·along), each one product, whatever order a matrix product would take.
    let turn = phi + PI / 2.0;
    let velocity = Vector2::new(-turn.sin() * along, turn.cos() * along);
    let spin = rotate(spin.xy(), turn).push(spin.z);
    (velocity, spin)
}

/// `v` turned by `angle` (radians, anticlockwise) in the plane, as pooltool's
/// `coordinate_rotation` turns it on the machine that wrote the reference table.
///
/// pooltool multiplies by the rotation matrix with `np.dot` in numba, that is BLAS's `dgemv`,
/// whose kernel picks the order of the sums and whether to fuse them; OpenBLAS's (on AVX-512)
/// computes each row as its second product fused onto its first:
/// `x' = fma(cos, x, −sin·y)`, `y' = fma(sin, x, cos·y)`. Written so, pooltool's bits come
/// out in all but 2 of the 2,000 reference strokes (against 1,333 with two roundings); another
/// BLAS may round otherwise, by an ulp of the terms.
fn rotate(v: Vector2<f64>, angle: f64) -> Vector2<f64> {
    let (sin, cos) = (angle.sin(), angle.cos());
    Vector2::new(cos.mul_add(v.x, -sin * v.y), sin.mul_add(v.x, cos * v.y))
}

/// The squirt angle, in radians: how far the ball's direction turns from the cue's when it
/// is struck off centre by `a` (the side offset in units of its radius, in the ball's frame),
/// `−throttle · atan2(5/2 · a·√(1 − a²), 1 + m_ball/m_end + 5/2 · (1 − a²))` (Alciatore's TP
/// A-31; pooltool's `get_squirt_angle`, the same arithmetic but for NumPy's `arctan2`).
/// Right side spin (`a < 0`) squirts the ball to the left (a positive angle).
///
/// ```
/// use ballcollide::billiards::{CueSpecs, squirt_angle};
/// let (ball, end) = (0.170097, CueSpecs::default().end_mass);
/// assert_eq!(squirt_angle(ball, end, 0.0, 1.0), 0.0); // no side, no squirt
/// let left = squirt_angle(ball, end, -0.5, 1.0);
/// assert!(left > 0.0 && (left.to_degrees() - 1.886).abs() < 1e-3); // about 1.9° with this cue
/// assert_eq!(squirt_angle(ball, end, -0.5, 0.0), 0.0); // the throttle turns it off
/// ```
pub fn squirt_angle(ball_mass: f64, end_mass: f64, a: f64, throttle: f64) -> f64 {
    let mass_ratio = ball_mass / end_mass;
    let across = 1.0 - a * a;
    let numerator = 5.0 / 2.0 * a * across.sqrt();
    let denominator = 1.0 + mass_ratio + 5.0 / 2.0 * across;
    -throttle * numerator.atan2(denominator)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::billiards::CueSpecs;

    fn strike(cue: &Cue) -> Result<BallState, InputError> {
        let ball = BallState::at_rest(Vector2::new(1.0, 0.5));
        InstantaneousPoint::default().resolve(cue, &ball, &BallParams::default())
    }

    #[test]
    fn every_field_is_checked() {
        let base = Cue::default();
        let specs = base.specs;
        let cases: [(&str, Cue); 9] = [
            (
                "v0",
                Cue {
                    v0: f64::NAN,
                    ..base
                },
            ),
            (
                "phi",
                Cue {
                    phi: f64::INFINITY,
                    ..base
                },
            ),
            (
                "theta",
                Cue {
                    theta: f64::NAN,
                    ..base
                },
            ),
            (
                "a",
                Cue {
                    a: f64::NAN,
                    ..base
                },
            ),
            (
                "b",
                Cue {
                    b: -f64::INFINITY,
                    ..base
                },
            ),
            // On the rim by the decimals, off it by float64's: 1 − 0.36 − 0.8² < 0, where
            // pooltool's square root is NaN.
            (
                "a, b",
                Cue {
                    a: 0.6,
                    b: 0.8,
                    ..base
                },
            ),
            (
                "specs.mass",
                Cue {
                    specs: CueSpecs { mass: 0.0, ..specs },
                    ..base
                },
            ),
            (
                "specs.end_mass",
                Cue {
                    specs: CueSpecs {
                        end_mass: -1.0,
                        ..specs
                    },
                    ..base
                },
            ),
            (
                "specs.tip_radius",
                Cue {
                    specs: CueSpecs {
                        tip_radius: f64::NAN,
                        ..specs
                    },
                    ..base
                },
            ),
        ];
        for (name, cue) in cases {
            assert_eq!(strike(&cue).unwrap_err().argument(), name);
        }
        let model = InstantaneousPoint {
            squirt_throttle: f64::NAN,
            ..InstantaneousPoint::default()
        };
        let ball = BallState::at_rest(Vector2::zeros());
        let err = model
            .resolve(&base, &ball, &BallParams::default())
            .unwrap_err();
        assert_eq!(err.argument(), "squirt_throttle");
        let bad_ball = BallState {
            velocity: Vector2::new(f64::NAN, 0.0),
            ..ball
        };
        let err = InstantaneousPoint::default().resolve(&base, &bad_ball, &BallParams::default());
        assert_eq!(err.unwrap_err().argument(), "velocity");
        let bad_params = BallParams {
            mass: 0.0,
            ..BallParams::default()
        };
        let err = InstantaneousPoint::default().resolve(&base, &ball, &bad_params);
        assert_eq!(err.unwrap_err().argument(), "mass");
    }

    #[test]
    fn edges_of_the_stroke() {
        // On the rim where float64 allows it, a side hit at the ball's equator: no squirt (the
        // impulse passes through the centre's line), the spin all about the vertical.
        let rim = strike(&Cue {
            a: 1.0,
            b: 0.0,
            ..Cue::default()
        })
        .unwrap();
        assert_eq!(
            squirt_angle(0.170097, CueSpecs::default().end_mass, 1.0, 1.0),
            -0.0
        );
        assert!(rim.angular_velocity.z < 0.0 && rim.angular_velocity.xy().norm() < 1e-12);
        // No speed, no motion; the ball still leaves sliding, as in pooltool.
        let still = strike(&Cue {
            v0: 0.0,
            ..Cue::default()
        })
        .unwrap();
        assert_eq!(
            (still.velocity, still.angular_velocity),
            (Vector2::zeros(), Vector3::zeros())
        );
        assert_eq!(still.motion, MotionState::Sliding);
        // Straight down (θ = 90°) through the top: no speed on the table but a trace.
        let down = strike(&Cue {
            theta: 90.0,
            a: 0.0,
            b: 0.0,
            ..Cue::default()
        })
        .unwrap();
        assert!(down.velocity.norm() < 1e-15);
    }
}
