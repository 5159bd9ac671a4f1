//! Ball–circular-cushion collisions (the rounded jaws of pockets): [`CircularCushion`], the
//! [`BallCircularCushionResolver`] trait, and [`StrongeCompliantCircular`], pooltool 0.6.0's
//! default model for them.
//!
//! The cushion is its own small struct, not the plane's [`Circle`](crate::geometry::Circle),
//! for the reason [`LinearCushion`](super::LinearCushion) is: pooltool's normal goes from the
//! circle's centre at the cushion's height to the ball's centre, in 3D.

use nalgebra::{Vector2, Vector3};

use super::ball_ball::smallest_kept_root;
use super::direction::{norm, unit, unit3};
use super::stronge::solve_with_normal;
use super::{BallParams, BallState, KISS_SPACER};

/// A rounded cushion as pooltool's `CircularCushionSegment`: a circle of `radius` about
/// `center` at `height` above the cloth.
///
/// ```
/// use ballcollide::billiards::CircularCushion;
/// use nalgebra::{Vector2, Vector3};
/// let jaw = CircularCushion::new(Vector2::new(0.0, 0.0), 0.01, 0.028575);
/// assert_eq!(jaw.normal_3d(Vector3::new(0.0, -0.05, 0.028575)), Vector3::new(0.0, -1.0, 0.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CircularCushion {
    /// The centre, in the plane of the table.
    pub center: Vector2<f64>,
    /// The radius.
    pub radius: f64,
    /// The height of the cushion above the cloth.
    pub height: f64,
}

impl CircularCushion {
    /// The cushion about `center` of `radius` at `height` (example: [`CircularCushion`]).
    pub const fn new(center: Vector2<f64>, radius: f64, height: f64) -> Self {
        Self {
            center,
            radius,
            height,
        }
    }

    /// The unit normal from the centre (at the cushion's height) to `xyz`, in 3D (pooltool's
    /// `get_normal_3d`; example: [`CircularCushion`]). NaN at the centre.
    pub fn normal_3d(&self, xyz: Vector3<f64>) -> Vector3<f64> {
        unit3(xyz - Vector3::new(self.center.x, self.center.y, self.height))
    }
}

/// A model of a ball meeting a rounded cushion: the ball's state just after, from its state at
/// contact; `None` where the model cannot resolve it (for pooltool's models: where pooltool
/// fails, as for a ball not moving into the cushion).
///
/// ```
/// use ballcollide::billiards::{BallCircularCushionResolver, BallParams, BallState, CircularCushion, MotionState, StrongeCompliantCircular};
/// use nalgebra::{Vector2, Vector3};
/// let params = BallParams::default();
/// let jaw = CircularCushion::new(Vector2::new(0.0, 0.0), 0.01, params.radius);
/// let ball = BallState::new(Vector2::new(0.01 + params.radius, 0.0), Vector2::new(-1.0, 0.0), Vector3::zeros(), MotionState::Rolling);
/// let after = StrongeCompliantCircular::default().solve(&ball, &params, &jaw).unwrap();
/// assert!((after.velocity.x - params.e_c).abs() < 1e-12);
/// ```
pub trait BallCircularCushionResolver {
    /// The ball's state just after meeting `cushion`, from its state at contact.
    fn solve(
        &self,
        ball: &BallState,
        params: &BallParams,
        cushion: &CircularCushion,
    ) -> Option<BallState>;

    /// The collision as pooltool resolves it: [`kiss_circular_cushion`], then
    /// [`solve`](Self::solve); `None` also where pooltool's `make_kiss` fails.
    fn resolve(
        &self,
        ball: &BallState,
        params: &BallParams,
        cushion: &CircularCushion,
    ) -> Option<BallState> {
        let kissed = kiss_circular_cushion(ball, params.radius, cushion)?;
        self.solve(&kissed, params, cushion)
    }
}

/// The ball moved so that its centre is `radius + cushion.radius + 1e-6` from the cushion's
/// centre, as pooltool places it (`CoreBallCCushionCollision.make_kiss`): along its velocity by
/// the root of smallest magnitude of pooltool's quadratic; if it does not move, or that would
/// move it more than `5e-6`, straight out from the centre. `None` where pooltool's quadratic
/// keeps no root (pooltool then fails). Only the position changes.
///
/// ```
/// use ballcollide::billiards::{BallState, CircularCushion, MotionState, kiss_circular_cushion};
/// use nalgebra::{Vector2, Vector3};
/// let jaw = CircularCushion::new(Vector2::new(0.0, 0.0), 0.01, 0.03);
/// let ball = BallState::new(Vector2::new(0.038, 0.0), Vector2::new(-1.0, 0.0), Vector3::zeros(), MotionState::Sliding);
/// let kissed = kiss_circular_cushion(&ball, 0.028, &jaw).unwrap();
/// assert!((kissed.position.x - (0.038 + 1e-6)).abs() < 1e-15);
/// ```
pub fn kiss_circular_cushion(
    ball: &BallState,
    radius: f64,
    cushion: &CircularCushion,
) -> Option<BallState> {
    let spacer = KISS_SPACER;
    let (r, v) = (ball.position, ball.velocity);
    let target = radius + cushion.radius + spacer;
    let fallback = || cushion.center + unit(r - cushion.center) * target;
    let mut kissed = *ball;
    if !ball.motion.translates() {
        kissed.position = fallback();
        return Some(kissed);
    }
    let diff = r - cushion.center;
    let alpha = v.x * v.x + v.y * v.y;
    let beta = 2.0 * (diff.x * v.x + diff.y * v.y);
    let gamma = diff.x * diff.x + diff.y * diff.y - target * target;
    let t = smallest_kept_root(alpha, beta, gamma)?;
    kissed.position = if norm(v * t) > 5.0 * spacer {
        fallback()
    } else {
        r + v * t
    };
    Some(kissed)
}

/// pooltool's `StrongeCompliantCircular` (its default for rounded cushions, `omega_ratio`
/// `1.8`): as [`StrongeCompliantLinear`](super::StrongeCompliantLinear), along the normal from
/// the circle's centre. Example: [`BallCircularCushionResolver`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StrongeCompliantCircular {
    /// `ω_t / ω_n`, the tangential to normal frequency ratio, in `(1, 2)`.
    pub omega_ratio: f64,
}

impl Default for StrongeCompliantCircular {
    /// `omega_ratio = 1.8`, as in pooltool's default resolver (VERSION 9).
    fn default() -> Self {
        Self { omega_ratio: 1.8 }
    }
}

impl BallCircularCushionResolver for StrongeCompliantCircular {
    fn solve(
        &self,
        ball: &BallState,
        params: &BallParams,
        cushion: &CircularCushion,
    ) -> Option<BallState> {
        let xyz = Vector3::new(ball.position.x, ball.position.y, params.radius);
        solve_with_normal(ball, params, cushion.normal_3d(xyz), self.omega_ratio)
    }
}
