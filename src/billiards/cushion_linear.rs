//! Ball–linear-cushion collisions: [`LinearCushion`], the [`BallLinearCushionResolver`] trait,
//! and [`StrongeCompliantLinear`], pooltool 0.6.0's default model for them.
//!
//! The cushion is its own small struct, not the plane's
//! [`LineSegment`](crate::geometry::LineSegment): pooltool's cushion is a segment at a height
//! (`p1[2] == p2[2]`, the cushion's nose), and the normal its models use goes from the nose's
//! line to the ball's centre in 3D, so it leans by the height's difference from the radius;
//! a plane segment has no height to carry.

use nalgebra::{Vector2, Vector3};

use super::direction::{norm, norm3, unit, unit3};
use super::stronge::solve_with_normal;
use super::{BallParams, BallState, KISS_SPACER};

/// A straight cushion as pooltool's `LinearCushionSegment`: the segment from `p1` to `p2` on the
/// table, its nose at `height` above the cloth.
///
/// ```
/// use ballcollide::billiards::LinearCushion;
/// use nalgebra::{Vector2, Vector3};
/// let rail = LinearCushion::new(Vector2::new(0.0, 0.0), Vector2::new(2.0, 0.0), 0.028575);
/// // A ball of radius 0.028575 at the cushion's height: the normal is horizontal.
/// let n = rail.normal_3d(Vector3::new(1.0, 0.03, 0.028575));
/// assert_eq!(n, Vector3::new(0.0, 1.0, 0.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinearCushion {
    /// One end, in the plane of the table.
    pub p1: Vector2<f64>,
    /// The other end.
    pub p2: Vector2<f64>,
    /// The height of the cushion's nose above the cloth.
    pub height: f64,
}

impl LinearCushion {
    /// The cushion from `p1` to `p2` at `height` (example: [`LinearCushion`]).
    pub const fn new(p1: Vector2<f64>, p2: Vector2<f64>, height: f64) -> Self {
        Self { p1, p2, height }
    }

    /// The unit normal from the cushion's line to `xyz`, in 3D (pooltool's `get_normal_3d`;
    /// example: [`LinearCushion`]). NaN if `xyz` is on the line, or the ends coincide.
    pub fn normal_3d(&self, xyz: Vector3<f64>) -> Vector3<f64> {
        let p1 = Vector3::new(self.p1.x, self.p1.y, self.height);
        let p2 = Vector3::new(self.p2.x, self.p2.y, self.height);
        let axis = p2 - p1;
        let unit_axis = axis / norm3(axis);
        let r = xyz - p1;
        let along = r.x * unit_axis.x + r.y * unit_axis.y + r.z * unit_axis.z;
        unit3(r - unit_axis * along)
    }
}

/// A model of a ball meeting a straight cushion: the ball's state just after, from its state
/// at contact. `None` where the model cannot resolve it (for pooltool's models: where pooltool
/// fails, as for a ball not moving into the cushion).
///
/// ```
/// use ballcollide::billiards::{BallLinearCushionResolver, BallParams, BallState, LinearCushion, MotionState, StrongeCompliantLinear};
/// use nalgebra::{Vector2, Vector3};
/// let params = BallParams::default();
/// let rail = LinearCushion::new(Vector2::new(0.0, 0.0), Vector2::new(2.0, 0.0), params.radius);
/// let ball = BallState::new(Vector2::new(1.0, params.radius), Vector2::new(0.0, -1.0), Vector3::zeros(), MotionState::Sliding);
/// let after = StrongeCompliantLinear::default().solve(&ball, &params, &rail).unwrap();
/// assert!((after.velocity.y - params.e_c).abs() < 1e-12); // straight back, times e_c
/// assert!(StrongeCompliantLinear::default().solve(&after, &params, &rail).is_none()); // moving away
/// ```
pub trait BallLinearCushionResolver {
    /// The ball's state just after meeting `cushion`, from its state at contact.
    fn solve(
        &self,
        ball: &BallState,
        params: &BallParams,
        cushion: &LinearCushion,
    ) -> Option<BallState>;

    /// The collision as pooltool resolves it: [`kiss_linear_cushion`], then
    /// [`solve`](Self::solve).
    fn resolve(
        &self,
        ball: &BallState,
        params: &BallParams,
        cushion: &LinearCushion,
    ) -> Option<BallState> {
        self.solve(
            &kiss_linear_cushion(ball, params.radius, cushion),
            params,
            cushion,
        )
    }
}

/// The ball moved so that its centre is `radius + 1e-6` from the cushion's line, as pooltool
/// places it before solving (`CoreBallLCushionCollision.make_kiss`): back or on along its
/// velocity by the time of smallest magnitude at which it is that far, in the plane; if it does
/// not move (spinning, stationary, pocketed), or that would move it more than `5e-6`, straight
/// out from the line instead. Only the position changes.
///
/// ```
/// use ballcollide::billiards::{BallState, LinearCushion, MotionState, kiss_linear_cushion};
/// use nalgebra::{Vector2, Vector3};
/// let rail = LinearCushion::new(Vector2::new(0.0, 0.0), Vector2::new(2.0, 0.0), 0.03);
/// let ball = BallState::new(Vector2::new(1.0, 0.028), Vector2::new(0.0, -1.0), Vector3::zeros(), MotionState::Sliding);
/// let kissed = kiss_linear_cushion(&ball, 0.028, &rail);
/// assert!((kissed.position.y - (0.028 + 1e-6)).abs() < 1e-15);
/// ```
pub fn kiss_linear_cushion(ball: &BallState, radius: f64, cushion: &LinearCushion) -> BallState {
    let spacer = KISS_SPACER;
    let r = ball.position;
    let v = ball.velocity;
    let fallback = || {
        let diff = cushion.p2 - cushion.p1;
        let t = -((cushion.p1 - r).dot(&diff)) / diff.dot(&diff);
        let c = cushion.p1 + diff * t;
        c + unit(r - c) * (radius + spacer)
    };
    let mut kissed = *ball;
    if !ball.motion.translates() {
        kissed.position = fallback();
        return kissed;
    }
    let (dx, dy) = (cushion.p2.x - cushion.p1.x, cushion.p2.y - cushion.p1.y);
    let (lx, ly) = if dx == 0.0 {
        (1.0, 0.0)
    } else {
        (-dy / dx, 1.0)
    };
    let n = unit(Vector2::new(lx, ly));
    let n = if n.dot(&v) > 0.0 { n } else { -n };
    let d0 = (r - cushion.p1).dot(&n);
    let vn = v.dot(&n);
    let t1 = (radius + spacer - d0) / vn;
    let t2 = (-(radius + spacer) - d0) / vn;
    let t = if t1.abs() < t2.abs() { t1 } else { t2 };
    kissed.position = if norm(v * t) > 5.0 * spacer {
        fallback()
    } else {
        r + v * t
    };
    kissed
}

/// pooltool's `StrongeCompliantLinear` (its default for straight cushions, with `omega_ratio`
/// `1.8`): Stronge's compliant frictional collision
/// ([`compliant_collinear_collision`](super::compliant_collinear_collision)) along the normal
/// from the cushion's nose to the ball's centre, with the ball's `f_c` and `e_c`, mass, and
/// `k_n = 1e3`. The ball ends sliding; its vertical velocity is dropped, as pooltool's.
/// Example: [`BallLinearCushionResolver`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StrongeCompliantLinear {
    /// `ω_t / ω_n`, the tangential to normal frequency ratio, in `(1, 2)`.
    pub omega_ratio: f64,
}

impl Default for StrongeCompliantLinear {
    /// `omega_ratio = 1.8`, as in pooltool's default resolver (VERSION 9).
    fn default() -> Self {
        Self { omega_ratio: 1.8 }
    }
}

impl BallLinearCushionResolver for StrongeCompliantLinear {
    fn solve(
        &self,
        ball: &BallState,
        params: &BallParams,
        cushion: &LinearCushion,
    ) -> Option<BallState> {
        let xyz = Vector3::new(ball.position.x, ball.position.y, params.radius);
        solve_with_normal(ball, params, cushion.normal_3d(xyz), self.omega_ratio)
    }
}
