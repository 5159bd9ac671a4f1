//! Ball–ball collisions: the [`BallBallResolver`] trait that every model implements, and the
//! steps pooltool runs around every model ([`make_kiss`] before, [`separate_touching`]
//! after).

use nalgebra::Vector2;

use super::direction::{norm, unit};
use super::{BallParams, BallState};

/// A model of a collision of two balls: their states just after it, from their states at the
/// moment the calendar found them touching.
///
/// pooltool's ball–ball models run the same three steps (its `CoreBallBallCollision.resolve`):
/// [`make_kiss`] puts the balls a hair (`1e-6`) more than two radii apart, the model solves the
/// collision, and [`separate_touching`] keeps balls that move on together from touching again
/// at once. A model implements [`solve`](Self::solve); [`resolve`](Self::resolve) runs the
/// three. The models: [`FrictionalInelastic`](super::FrictionalInelastic) (pooltool's
/// default).
///
/// ```
/// use ballcollide::billiards::{BallBallResolver, BallParams, BallState, FrictionalInelastic, MotionState};
/// use nalgebra::{Vector2, Vector3};
/// let params = BallParams::default();
/// let cue = BallState::new(Vector2::new(0.5, 0.5), Vector2::new(1.0, 0.0), Vector3::zeros(), MotionState::Sliding);
/// let object = BallState::at_rest(Vector2::new(0.5 + 2.0 * params.radius, 0.5));
/// let [cue, object] = FrictionalInelastic::default().resolve([&cue, &object], [&params, &params]);
/// // A straight stun shot: the cue ball nearly stops, the object ball takes nearly all its speed.
/// assert!(cue.velocity.norm() < 0.03 && (object.velocity.x - 0.975).abs() < 1e-12);
/// assert_eq!((cue.motion, object.motion), (MotionState::Sliding, MotionState::Sliding));
/// ```
pub trait BallBallResolver {
    /// The two balls' states just after the collision, from their states at contact (moved
    /// apart by [`make_kiss`]); `params` are the balls' parameters, in the same order.
    fn solve(&self, balls: [&BallState; 2], params: [&BallParams; 2]) -> [BallState; 2];

    /// The whole collision as pooltool resolves it: [`make_kiss`], [`solve`](Self::solve),
    /// [`separate_touching`].
    fn resolve(&self, balls: [&BallState; 2], params: [&BallParams; 2]) -> [BallState; 2] {
        let [a, b] = make_kiss(balls, params[0].radius);
        let solved = self.solve([&a, &b], params);
        separate_touching(&solved)
    }
}

/// The gap pooltool leaves between two balls it has just put in contact (`MIN_DIST`).
pub const KISS_SPACER: f64 = 1e-6;

/// The balls moved so that their centres are `2·radius + 1e-6` apart, as pooltool places them
/// before solving a collision (`make_kiss`; `radius` is the first ball's, as in pooltool).
///
/// If one ball moves, both go back or on along their velocities by the time `t` of smallest
/// magnitude at which they would be that far apart, in straight lines (a root of a quadratic,
/// by pooltool's `solve_complex`, keeping roots whose imaginary part is below `1e-3` of their
/// real part). If neither moves (stationary, spinning or pocketed), or that would move their
/// midpoint by more than `5e-6`, or no root is kept (pooltool then fails), they are pushed
/// apart along the line of centres instead, each by half the difference. Only positions change.
///
/// ```
/// use ballcollide::billiards::{BallState, KISS_SPACER, MotionState, make_kiss};
/// use nalgebra::{Vector2, Vector3};
/// let r = 0.028575;
/// let a = BallState::new(Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), Vector3::zeros(), MotionState::Sliding);
/// let b = BallState::at_rest(Vector2::new(2.0 * r - 2e-6, 0.0)); // 2 µm too close
/// let [a, b] = make_kiss([&a, &b], r);
/// assert!(((b.position - a.position).norm() - (2.0 * r + KISS_SPACER)).abs() < 1e-15);
/// assert_eq!(b.position, Vector2::new(2.0 * r - 2e-6, 0.0)); // the ball at rest stays
/// assert!((a.position.x + 3e-6).abs() < 1e-15); // the other went back 3 µm
/// ```
pub fn make_kiss(balls: [&BallState; 2], radius: f64) -> [BallState; 2] {
    let [mut a, mut b] = [*balls[0], *balls[1]];
    let (r1, r2) = (a.position, b.position);
    let spacer = KISS_SPACER;
    let moving = a.motion.translates() || b.motion.translates();
    let along = moving.then(|| kiss_time(&a, &b, radius)).flatten();
    let (mut p1, mut p2) = match along {
        Some(t) => (r1 + a.velocity * t, r2 + b.velocity * t),
        None => push_apart(r1, r2, radius, spacer),
    };
    if along.is_some() {
        let midpoint = (r1 + r2) / 2.0;
        let moved = (p1 + p2) / 2.0;
        if norm(midpoint - moved) > 5.0 * spacer {
            (p1, p2) = push_apart(r1, r2, radius, spacer);
        }
    }
    a.position = p1;
    b.position = p2;
    [a, b]
}

/// pooltool's fallback: each ball moved by half of `2·radius − |r₂ − r₁| + spacer` along the
/// line of centres.
fn push_apart(
    r1: Vector2<f64>,
    r2: Vector2<f64>,
    radius: f64,
    spacer: f64,
) -> (Vector2<f64>, Vector2<f64>) {
    let correction = 2.0 * radius - norm(r2 - r1) + spacer;
    let half = correction / 2.0;
    (r1 - unit(r2 - r1) * half, r2 + unit(r2 - r1) * half)
}

/// The time of smallest magnitude at which the two balls, moving in straight lines, are
/// `2·radius + spacer` apart, as pooltool's `make_kiss` finds it; `None` where it keeps no
/// root.
fn kiss_time(a: &BallState, b: &BallState, radius: f64) -> Option<f64> {
    let (dv, dr) = (b.velocity - a.velocity, b.position - a.position);
    let contact = 2.0 * radius + KISS_SPACER;
    let alpha = dv.x * dv.x + dv.y * dv.y;
    let beta = 2.0 * dv.x * dr.x + 2.0 * dv.y * dr.y;
    let gamma = dr.x * dr.x + dr.y * dr.y - contact * contact;
    smallest_kept_root(alpha, beta, gamma)
}

/// pooltool's choice among `solve_complex`'s roots of `alpha·t² + beta·t + gamma`: those
/// whose imaginary part is below `1e-3` of their real part, then the first of smallest
/// magnitude; `None` if none is kept (pooltool then fails).
pub(super) fn smallest_kept_root(alpha: f64, beta: f64, gamma: f64) -> Option<f64> {
    let roots = quadratic_roots(alpha, beta, gamma);
    // Kept: |imaginary| / |real| < 1e-3 (a root of 0, 0/0, is not kept); then the first of
    // smallest magnitude.
    let kept = roots
        .into_iter()
        .filter(|z| (z.im.abs() / z.re.abs()) < 1e-3)
        .map(|z| z.re);
    kept.fold(None, |best: Option<f64>, t| match best {
        Some(b) if b.abs() <= t.abs() => Some(b),
        _ => Some(t),
    })
}

/// A complex number, for the quadratic's roots.
#[derive(Clone, Copy, Debug)]
struct Complex {
    re: f64,
    im: f64,
}

impl Complex {
    const NAN: Self = Self {
        re: f64::NAN,
        im: f64::NAN,
    };

    fn real(re: f64) -> Self {
        Self { re, im: 0.0 }
    }

    fn abs(self) -> f64 {
        self.re.hypot(self.im)
    }

    /// `self / other` by CPython's (and numba's) algorithm (Smith's, `_Py_c_quot`).
    fn div(self, other: Self) -> Self {
        let (a, b) = (self, other);
        if b.re.abs() >= b.im.abs() {
            if b.re == 0.0 {
                return Self::NAN;
            }
            let ratio = b.im / b.re;
            let denom = b.re + b.im * ratio;
            Self {
                re: (a.re + a.im * ratio) / denom,
                im: (a.im - a.re * ratio) / denom,
            }
        } else {
            let ratio = b.re / b.im;
            let denom = b.re * ratio + b.im;
            Self {
                re: (a.re * ratio + a.im) / denom,
                im: (a.im * ratio - a.re) / denom,
            }
        }
    }
}

/// The roots of `a·t² + b·t + c` as pooltool's `roots.quadratic.solve_complex` computes them
/// for real coefficients (NaN for a root that is not there).
fn quadratic_roots(a: f64, b: f64, c: f64) -> [Complex; 2] {
    if a != 0.0 {
        let d = b * b - 4.0 * a * c;
        // cmath.sqrt of a real: on the imaginary axis below 0 (the sign of d's zero imaginary
        // part changes only the sign of the imaginary part, which no caller uses).
        let sqrt_d = if d >= 0.0 {
            Complex::real(d.sqrt())
        } else {
            Complex {
                re: 0.0,
                im: (-d).sqrt(),
            }
        };
        let sign_b = if b >= 0.0 { 1.0 } else { -1.0 };
        let den = Complex::real(2.0 * a);
        let mut num = Complex {
            re: -b - sign_b * sqrt_d.re,
            im: -(sign_b * sqrt_d.im),
        };
        if num.abs() < 1e-14 * den.abs() {
            num = Complex {
                re: -b + sign_b * sqrt_d.re,
                im: sign_b * sqrt_d.im,
            };
        }
        let r1 = num.div(den);
        let r2 = if r1.abs() < 1e-14 {
            Complex {
                re: -b + sqrt_d.re,
                im: sqrt_d.im,
            }
            .div(den)
        } else {
            Complex::real(c / a).div(r1)
        };
        return [r1, r2];
    }
    if b != 0.0 {
        return [Complex::real(-c / b), Complex::NAN];
    }
    [Complex::NAN; 2]
}

/// Balls that move on nearly together after a collision (line-of-centres speeds within
/// 1 cm/s, velocities within about 25° of each other, both moving), changed as pooltool's
/// `resolve_continually_touching` changes them: the slower of the two along the line of
/// centres takes a tenth of the faster's speed along it, so that they part instead of colliding
/// again at once (on a tie, the second ball counts as the faster, as in pooltool). Other pairs
/// are returned as they are.
///
/// ```
/// use ballcollide::billiards::{BallState, MotionState, separate_touching};
/// use nalgebra::{Vector2, Vector3};
/// let r = 0.028575;
/// let chaser = BallState::new(Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), Vector3::zeros(), MotionState::Sliding);
/// let chased = BallState { position: Vector2::new(2.0 * r, 0.0), velocity: Vector2::new(0.995, 0.0), ..chaser };
/// let [a, b] = separate_touching(&[chaser, chased]);
/// assert!((a.velocity.x - 0.9).abs() < 1e-15 && (b.velocity.x - 1.095).abs() < 1e-15);
/// ```
pub fn separate_touching(balls: &[BallState; 2]) -> [BallState; 2] {
    let [mut a, mut b] = *balls;
    let (v1, v2) = (a.velocity, b.velocity);
    let (speed1, speed2) = (norm(v1), norm(v2));
    if !(speed1 > 0.0 && speed2 > 0.0) {
        return [a, b];
    }
    let line = unit(b.position - a.position);
    let (loc1, loc2) = (v1.dot(&line), v2.dot(&line));
    let aligned = v1.dot(&v2) / (speed1 * speed2) > 0.9;
    if (loc2 - loc1).abs() < 0.01 && aligned {
        let stolen = loc1.max(loc2) * 0.1;
        let (new1, new2) = if loc1 > loc2 {
            (loc1 - stolen, loc2 + stolen)
        } else {
            (loc1 + stolen, loc2 - stolen)
        };
        a.velocity = v1 - line * loc1 + line * new1;
        b.velocity = v2 - line * loc2 + line * new2;
    }
    [a, b]
}
