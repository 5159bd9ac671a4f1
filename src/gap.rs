//! [`Gap`]: the relative motion of two balls on one time window, and its gap quartic.

use nalgebra::{SVector, Vector2};

use crate::motion::Ball;

/// The relative motion of two balls on a time window in which both move without stopping
/// (or rest): with `s` the time since the window's start,
/// `d(s) = offset + velocity·s + ½·acceleration·s²` is the vector from B's centre to A's,
/// and the **gap** `g(s) = |d(s)|² − contact_distance²` is negative exactly when the balls
/// overlap.
///
/// `g` is the quartic `a·s⁴ + b·s³ + c·s² + d·s + e` of [`Gap::quartic`]; the collision
/// search, however, evaluates `g` and its derivatives through `d(s)`, which stays accurate
/// where the expanded coefficients cancel (balls far apart compared with their radii).
///
/// ```
/// use ballcollide::{Ball, Gap};
/// use nalgebra::Vector2;
///
/// // A at rest at the origin, B coming from x = 1 at 1 m/s without friction.
/// let a = Ball::at_rest(Vector2::new(0.0, 0.0))?;
/// let b = Ball::new(Vector2::new(1.0, 0.0), Vector2::new(-1.0, 0.0), 0.0)?;
/// let gap = Gap::between(&a, &b, 0.5, 0.0);
/// assert_eq!(gap.quartic(), [0.0, 0.0, 1.0, -2.0, 0.75]); // (1 − s)² − 0.25
/// assert_eq!(gap.value(0.5), 0.0); // touching after 0.5 s
/// # Ok::<(), ballcollide::InputError>(())
/// ```
///
/// Generic over the dimension `D` (2 by default, 3 for balls in space): the search is the
/// same in both.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gap<const D: usize = 2> {
    /// `d(0)`: centre of A minus centre of B at the window's start.
    pub offset: SVector<f64, D>,
    /// `d′(0)`: relative velocity at the window's start.
    pub velocity: SVector<f64, D>,
    /// `d″`: relative acceleration, constant on the window.
    pub acceleration: SVector<f64, D>,
    /// The distance between centres at contact: the contact distance, the sum of the radii.
    pub contact_distance: f64,
}

impl Gap<2> {
    /// The relative motion of `a` and `b` from time `t0` on, valid until the first of them
    /// stops after `t0` (a ball already stopped at `t0` contributes its resting point and no
    /// motion).
    ///
    /// ```
    /// use ballcollide::{Ball, Gap};
    /// use nalgebra::Vector2;
    /// // A stops at x = 1 after 2 s; B rolls on along y without friction.
    /// let a = Ball::new(Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), 0.5)?;
    /// let b = Ball::new(Vector2::new(0.0, -3.0), Vector2::new(0.0, 1.0), 0.0)?;
    /// let after_stop = Gap::between(&a, &b, 0.1, 2.0);
    /// assert_eq!(after_stop.offset, Vector2::new(1.0, 1.0)); // (1, 0) − (0, −1)
    /// assert_eq!(after_stop.velocity, Vector2::new(0.0, -1.0));
    /// assert_eq!(after_stop.acceleration, Vector2::zeros());
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn between(a: &Ball, b: &Ball, contact_distance: f64, t0: f64) -> Self {
        Self {
            offset: a.position_at(t0) - b.position_at(t0),
            velocity: a.velocity_at(t0) - b.velocity_at(t0),
            acceleration: moving_friction(a, t0) - moving_friction(b, t0),
            contact_distance,
        }
    }
}

impl<const D: usize> Gap<D> {
    /// The same motion with time measured in units of `h` (`s = h·u`): velocity × h and
    /// acceleration × h². Exact when `h` is a power of two.
    ///
    /// ```
    /// use ballcollide::Gap;
    /// use nalgebra::Vector2;
    /// let gap = Gap {
    ///     offset: Vector2::new(1.0, 0.0),
    ///     velocity: Vector2::new(-1.0, 0.0),
    ///     acceleration: Vector2::new(0.5, 0.0),
    ///     contact_distance: 0.25,
    /// };
    /// assert_eq!(gap.time_scaled(4.0).value(0.25), gap.value(1.0));
    /// ```
    #[inline(always)]
    pub fn time_scaled(&self, h: f64) -> Self {
        Self {
            offset: self.offset,
            velocity: self.velocity * h,
            acceleration: self.acceleration * (h * h),
            contact_distance: self.contact_distance,
        }
    }

    /// The same motion from `s` on (time since `s`): the separation and relative velocity at
    /// `s` as [`Gap::separation`] and [`Gap::relative_velocity`] give them.
    ///
    /// ```
    /// use ballcollide::Gap;
    /// use nalgebra::Vector2;
    /// let gap = Gap {
    ///     offset: Vector2::new(3.0, 1.0),
    ///     velocity: Vector2::new(-2.0, 0.0),
    ///     acceleration: Vector2::new(1.0, 0.0),
    ///     contact_distance: 1.0,
    /// };
    /// let later = gap.shifted(2.0);
    /// assert_eq!(later.offset, Vector2::new(1.0, 1.0));
    /// assert_eq!(later.value(1.0), gap.value(3.0));
    /// ```
    #[inline(always)]
    pub fn shifted(&self, s: f64) -> Self {
        Self {
            offset: self.separation(s),
            velocity: self.relative_velocity(s),
            acceleration: self.acceleration,
            contact_distance: self.contact_distance,
        }
    }

    /// The coefficients `[a, b, c, d, e]` of `g(s) = a·s⁴ + b·s³ + c·s² + d·s + e`, highest
    /// degree first (SPEC's formula with `Δp`, `Δv`, `Δf` the offset, velocity and
    /// acceleration), each formed in plain float arithmetic. [`Gap::value`] is the accurate
    /// way to evaluate `g`; the coefficients serve bounds and the full quartic solve.
    ///
    /// ```
    /// use ballcollide::Gap;
    /// use ballcollide::poly::solve_quartic;
    /// use nalgebra::Vector2;
    /// // Head-on on a line: the distance 3 − 2s + s²/2 reaches 1.5 at s = 1 (entry) and
    /// // s = 3 (exit).
    /// let gap = Gap {
    ///     offset: Vector2::new(3.0, 0.0),
    ///     velocity: Vector2::new(-2.0, 0.0),
    ///     acceleration: Vector2::new(1.0, 0.0),
    ///     contact_distance: 1.5,
    /// };
    /// let [a, b, c, d, e] = gap.quartic();
    /// let roots = solve_quartic(a, b, c, d, e);
    /// assert_eq!(roots.len(), 2);
    /// assert!((roots[0] - 1.0).abs() < 1e-12 && (roots[1] - 3.0).abs() < 1e-12);
    /// ```
    #[inline(always)]
    pub fn quartic(&self) -> [f64; 5] {
        let (p, v, f) = (self.offset, self.velocity, self.acceleration);
        [
            0.25 * f.norm_squared(),
            v.dot(&f),
            v.norm_squared() + p.dot(&f),
            2.0 * p.dot(&v),
            p.norm_squared() - self.contact_distance * self.contact_distance,
        ]
    }

    /// `d(s)`: the vector from B's centre to A's at time `s` of the window.
    ///
    /// ```
    /// use ballcollide::Gap;
    /// use nalgebra::Vector2;
    /// let gap = Gap {
    ///     offset: Vector2::new(3.0, 1.0),
    ///     velocity: Vector2::new(-2.0, 0.0),
    ///     acceleration: Vector2::new(1.0, 0.0),
    ///     contact_distance: 1.0,
    /// };
    /// assert_eq!(gap.separation(2.0), Vector2::new(1.0, 1.0)); // 3 − 4 + 2
    /// assert_eq!(gap.relative_velocity(2.0), Vector2::new(0.0, 0.0));
    /// assert_eq!(gap.value(2.0), 1.0); // |(1, 1)|² − 1
    /// assert_eq!(gap.half_slope(2.0), 0.0); // closest approach
    /// assert_eq!(gap.half_curvature(2.0), 1.0); // 0 + (1, 1)·(1, 0)
    /// ```
    #[inline(always)]
    pub fn separation(&self, s: f64) -> SVector<f64, D> {
        self.offset + (self.velocity + self.acceleration * (0.5 * s)) * s
    }

    /// `d′(s)`: the relative velocity at time `s` of the window (example: [`Gap::separation`]).
    #[inline(always)]
    pub fn relative_velocity(&self, s: f64) -> SVector<f64, D> {
        self.velocity + self.acceleration * s
    }

    /// `g(s) = |d(s)|² − contact_distance²`, with the subtraction done inside fused
    /// multiply-adds so that its sign is right when the distance is within rounding of the
    /// contact distance.
    ///
    /// The larger component goes last whatever the axes, so that rotating or reflecting the
    /// whole configuration by quarter turns changes nothing, bit for bit. Example:
    /// [`Gap::separation`].
    #[inline(always)]
    pub fn value(&self, s: f64) -> f64 {
        gap_value_of(&self.separation(s), self.contact_distance)
    }

    /// `½·g′(s) = d(s)·d′(s)`: negative while the balls approach (example:
    /// [`Gap::separation`]).
    #[inline(always)]
    pub fn half_slope(&self, s: f64) -> f64 {
        self.separation(s).dot(&self.relative_velocity(s))
    }

    /// `½·g″(s) = |d′(s)|² + d(s)·d″`: the derivative of [`Gap::half_slope`] (example:
    /// [`Gap::separation`]).
    #[inline(always)]
    pub fn half_curvature(&self, s: f64) -> f64 {
        self.relative_velocity(s).norm_squared() + self.separation(s).dot(&self.acceleration)
    }

    /// A bound on the rounding error of [`Gap::half_slope`] for `0 ≤ s ≤ 1` (time scaled to
    /// the window): below it, the slope's sign is rounding noise, and locating a critical
    /// point more closely gains nothing (the gap is flat there to second order).
    ///
    /// `d(s)` is formed with an error below `2ε·S`, where `S` sums the magnitudes of all
    /// components of its three terms, and `d′(s)` with one below `2ε·S′`; `d·d′` inherits them.
    #[inline(always)]
    pub(crate) fn half_slope_noise(&self) -> f64 {
        let rate = self.velocity.abs().sum() + self.acceleration.abs().sum();
        let size = self.offset.abs().sum() + rate;
        4.0 * f64::EPSILON * size * rate
    }

    /// A bound on the rounding error of [`Gap::value`] for `0 ≤ s ≤ 1` where `|d(s)| ≈ r`
    /// (near a contact): `2r·2ε·S + 2ε·r²`, with `S` as in [`Gap::half_slope_noise`].
    #[inline(always)]
    pub(crate) fn value_noise(&self) -> f64 {
        let size =
            self.offset.abs().sum() + self.velocity.abs().sum() + self.acceleration.abs().sum();
        2.0 * f64::EPSILON * self.contact_distance * (2.0 * size + self.contact_distance)
    }
}

/// `x² + y² − radius²` as [`Gap::value`] computes it (the batch's lanes use it too, so that
/// both give the same bits): the subtraction inside fused multiply-adds, the larger component
/// last. Without branches, so that it vectorises.
#[inline(always)]
pub(crate) fn gap_value(x: f64, y: f64, radius: f64) -> f64 {
    let x_larger = x.abs() >= y.abs();
    let big = if x_larger { x } else { y };
    let small = if x_larger { y } else { x };
    let r2 = radius * radius;
    let r2_err = radius.mul_add(radius, -r2);
    big.mul_add(big, small.mul_add(small, -r2)) - r2_err
}

/// `|d|² − radius²` as [`Gap::value`] computes it in any dimension: in 2-D [`gap_value`]; in
/// 3-D the same, the components taken from the smallest to the largest in magnitude (so that
/// a 2-D motion embedded in 3-D with a zero third component gives the 2-D bits).
#[inline(always)]
pub(crate) fn gap_value_of<const D: usize>(d: &SVector<f64, D>, radius: f64) -> f64 {
    if D == 2 {
        return gap_value(d[0], d[1], radius);
    }
    let mut c: SVector<f64, D> = *d;
    // A few components: insertion by magnitude, ascending.
    for i in 1..D {
        let mut j = i;
        while j > 0 && c[j - 1].abs() > c[j].abs() {
            c.swap_rows(j - 1, j);
            j -= 1;
        }
    }
    let r2 = radius * radius;
    let r2_err = radius.mul_add(radius, -r2);
    c.iter().fold(-r2, |acc, &x| x.mul_add(x, acc)) - r2_err
}

/// A ball's friction acceleration on a window starting at `t0`: zero once it has stopped.
fn moving_friction(ball: &Ball, t0: f64) -> Vector2<f64> {
    if t0 < ball.stop_time() {
        ball.friction_vector()
    } else {
        Vector2::zeros()
    }
}
