//! The eighth entry of [`LANES`] windows at once, over [`Simd`]: the lane twin of
//! [`window_eighth`](crate::collision::eighth_entry::window_eighth) and everything it calls
//! (the gap's accurate value and slopes, the Bernstein coefficients' first open eighth, the
//! fixed Newton steps), operation for operation, so that every lane gives the scalar
//! function's bits. Every step is taken in every lane: a lane whose steps have converged keeps
//! its state, as the scalar steps stop there.
//!
//! Where the scalar code writes a `nalgebra` operation, the lanes write it out in the order
//! `nalgebra` evaluates it: a dot product of 2 or 3 components left to right, a norm's square
//! as that dot product, a sum of magnitudes from 0.

use crate::collision::LONGEST_WINDOW;
use crate::collision::eighth_entry::RADIUS_FLOOR;
use crate::collision::exclusion::MARGIN_PER_SQUARE;
use crate::collision::length_unit::PRE;
use crate::collision::long_window::LONG;
use crate::collision::narrow_dip::NARROW;
use crate::simd::Simd;

/// A window's relative motion in lanes, as [`Gap`](crate::Gap) holds one.
#[derive(Clone, Copy)]
pub(super) struct GapLanes<S: Simd, const D: usize> {
    pub offset: [S::V; D],
    pub velocity: [S::V; D],
    pub acceleration: [S::V; D],
    pub radius: S::V,
}

/// What [`window_eighth`] settles in each lane, as
/// [`EighthEntry`](crate::collision::eighth_entry::EighthEntry).
pub(super) struct EighthLanes<S: Simd> {
    pub entry: S::V,
    pub found: S::M,
    pub screened_out: S::M,
}

/// `Σ aᵢ·bᵢ`, left to right.
#[inline(always)]
pub(super) fn dot<S: Simd, const D: usize>(s: S, a: &[S::V; D], b: &[S::V; D]) -> S::V {
    let mut sum = s.mul(a[0], b[0]);
    for i in 1..D {
        sum = s.add(sum, s.mul(a[i], b[i]));
    }
    sum
}

/// `Σ |aᵢ|`, from 0.
#[inline(always)]
fn abs_sum<S: Simd, const D: usize>(s: S, a: &[S::V; D]) -> S::V {
    let mut sum = s.zero();
    for &x in a {
        sum = s.add(sum, s.abs(x));
    }
    sum
}

/// `|x| > m ? |x| : m`: a step of [`largest`](crate::collision::length_unit::largest).
#[inline(always)]
pub(super) fn bigger<S: Simd>(s: S, m: S::V, x: S::V) -> S::V {
    s.max(s.abs(x), m)
}

/// The largest magnitude among `a`, from 0 (NaNs ignored).
#[inline(always)]
pub(super) fn largest<S: Simd, const D: usize>(s: S, a: &[S::V; D]) -> S::V {
    let mut m = s.zero();
    for &x in a {
        m = bigger(s, m, x);
    }
    m
}

/// [`LengthUnit`](crate::collision::length_unit::LengthUnit) in lanes: the pre-scaling and the
/// scale of each lane's unit, for a largest length `largest`.
#[derive(Clone, Copy)]
pub(super) struct UnitLanes<S: Simd> {
    pre: S::V,
    scale: S::V,
}

impl<S: Simd> UnitLanes<S> {
    /// `LengthUnit::of(largest)` in each lane.
    #[inline(always)]
    pub(super) fn of(s: S, largest: S::V) -> Self {
        let subnormal = s.lt(largest, s.splat(f64::MIN_POSITIVE));
        let pre = s.blend(subnormal, s.splat(1.0), s.splat(PRE));
        Self {
            pre,
            scale: s.unit_scale(s.mul(largest, pre)),
        }
    }

    /// `LengthUnit::apply`: `x·pre·scale`.
    #[inline(always)]
    pub(super) fn apply(self, s: S, x: S::V) -> S::V {
        s.mul(s.mul(x, self.pre), self.scale)
    }

    /// Every component in the unit.
    #[inline(always)]
    pub(super) fn apply_all<const D: usize>(self, s: S, mut a: [S::V; D]) -> [S::V; D] {
        for x in &mut a {
            *x = self.apply(s, *x);
        }
        a
    }
}

/// `|d|² − radius²` as [`gap_value_of`](crate::gap::gap_value_of) forms it: the components
/// from the smallest to the largest in magnitude (in 2-D the larger last), each square added
/// inside a fused multiply-add, the radius's square's rounding error taken out last.
#[inline(always)]
fn gap_value_of<S: Simd, const D: usize>(s: S, d: &[S::V; D], radius: S::V) -> S::V {
    let mut c = *d;
    // Insertion by magnitude, as compare-and-swaps in the order the insertion makes them (a
    // swap the insertion would not reach is one whose pair is already in order); a NaN is
    // never swapped.
    for i in 1..D {
        for j in (1..=i).rev() {
            let swap = s.gt(s.abs(c[j - 1]), s.abs(c[j]));
            let (low, high) = (s.blend(swap, c[j - 1], c[j]), s.blend(swap, c[j], c[j - 1]));
            (c[j - 1], c[j]) = (low, high);
        }
    }
    let r2 = s.mul(radius, radius);
    let minus_r2 = s.mul(s.splat(-1.0), r2);
    let r2_err = s.mul_add(radius, radius, minus_r2);
    let mut sum = minus_r2;
    for x in c {
        sum = s.mul_add(x, x, sum);
    }
    s.sub(sum, r2_err)
}

impl<S: Simd, const D: usize> GapLanes<S, D> {
    /// `d(u)` ([`Gap::separation`](crate::Gap::separation)).
    #[inline(always)]
    fn separation(&self, s: S, u: S::V) -> [S::V; D] {
        let half = s.mul(s.splat(0.5), u);
        let mut d = self.offset;
        for (i, d) in d.iter_mut().enumerate() {
            let rate = s.add(self.velocity[i], s.mul(self.acceleration[i], half));
            *d = s.add(*d, s.mul(rate, u));
        }
        d
    }

    /// `d′(u)`.
    #[inline(always)]
    fn relative_velocity(&self, s: S, u: S::V) -> [S::V; D] {
        let mut v = self.velocity;
        for (i, v) in v.iter_mut().enumerate() {
            *v = s.add(*v, s.mul(self.acceleration[i], u));
        }
        v
    }

    /// `g(u)` ([`Gap::value`](crate::Gap::value)).
    #[inline(always)]
    pub(super) fn value(&self, s: S, u: S::V) -> S::V {
        gap_value_of(s, &self.separation(s, u), self.radius)
    }

    /// `½·g′(u)`.
    #[inline(always)]
    pub(super) fn half_slope(&self, s: S, u: S::V) -> S::V {
        dot(s, &self.separation(s, u), &self.relative_velocity(s, u))
    }

    /// `½·g″(u)`.
    #[inline(always)]
    pub(super) fn half_curvature(&self, s: S, u: S::V) -> S::V {
        let v = self.relative_velocity(s, u);
        let d = self.separation(s, u);
        s.add(dot(s, &v, &v), dot(s, &d, &self.acceleration))
    }

    /// The bound on [`GapLanes::half_slope`]'s rounding (`Gap::half_slope_noise`).
    #[inline(always)]
    fn half_slope_noise(&self, s: S) -> S::V {
        let rate = s.add(abs_sum(s, &self.velocity), abs_sum(s, &self.acceleration));
        let size = s.add(abs_sum(s, &self.offset), rate);
        s.mul(s.mul(s.splat(4.0 * f64::EPSILON), size), rate)
    }

    /// The bound on [`GapLanes::value`]'s rounding near a contact (`Gap::value_noise`).
    #[inline(always)]
    fn value_noise(&self, s: S) -> S::V {
        let size = s.add(
            s.add(abs_sum(s, &self.offset), abs_sum(s, &self.velocity)),
            abs_sum(s, &self.acceleration),
        );
        let r = self.radius;
        s.mul(
            s.mul(s.splat(2.0 * f64::EPSILON), r),
            s.add(s.mul(s.splat(2.0), size), r),
        )
    }

    /// The sum of the magnitudes of the offset, velocity and acceleration (`narrow_dip`'s).
    #[inline(always)]
    fn size(&self, s: S) -> S::V {
        s.add(
            s.add(abs_sum(s, &self.offset), abs_sum(s, &self.velocity)),
            abs_sum(s, &self.acceleration),
        )
    }

    /// The same motion with time scaled by `h` (`Gap::time_scaled`).
    #[inline(always)]
    pub(super) fn time_scaled(&self, s: S, h: S::V) -> Self {
        let h2 = s.mul(h, h);
        let mut scaled = *self;
        for i in 0..D {
            scaled.velocity[i] = s.mul(self.velocity[i], h);
            scaled.acceleration[i] = s.mul(self.acceleration[i], h2);
        }
        scaled
    }

    /// The motion in the unit of its own largest field (`in_own_unit`).
    #[inline(always)]
    fn in_own_unit(&self, s: S) -> Self {
        let mut most = bigger(s, s.zero(), largest(s, &self.offset));
        most = bigger(s, most, largest(s, &self.velocity));
        most = bigger(s, most, largest(s, &self.acceleration));
        most = bigger(s, most, self.radius);
        self.in_unit(s, UnitLanes::of(s, most))
    }

    /// The motion with every field in `unit` (`Gap::in_unit`).
    #[inline(always)]
    pub(super) fn in_unit(&self, s: S, unit: UnitLanes<S>) -> Self {
        Self {
            offset: unit.apply_all(s, self.offset),
            velocity: unit.apply_all(s, self.velocity),
            acceleration: unit.apply_all(s, self.acceleration),
            radius: unit.apply(s, self.radius),
        }
    }

    /// The lanes whose gap is positive at the start, in the unit of the offset and radius
    /// (`apart_at_start`).
    #[inline(always)]
    pub(super) fn apart_at_start(&self, s: S) -> S::M {
        let most = bigger(
            s,
            bigger(s, s.zero(), largest(s, &self.offset)),
            self.radius,
        );
        let unit = UnitLanes::of(s, most);
        let value = gap_value_of(
            s,
            &unit.apply_all(s, self.offset),
            unit.apply(s, self.radius),
        );
        s.gt(value, s.zero())
    }

    /// The Bernstein coefficients on `[0, end]` and their margin (`exclusion::bernstein`).
    #[inline(always)]
    fn bernstein(&self, s: S, end: S::V) -> ([S::V; 5], S::V) {
        let (p, v, f) = (&self.offset, &self.velocity, &self.acceleration);
        // `Gap::quartic`, highest degree first.
        let a4 = s.mul(s.splat(0.25), dot(s, f, f));
        let a3 = dot(s, v, f);
        let a2 = s.add(dot(s, v, v), dot(s, p, f));
        let a1 = s.mul(s.splat(2.0), dot(s, p, v));
        let a0 = s.sub(dot(s, p, p), s.mul(self.radius, self.radius));
        let end2 = s.mul(end, end);
        let a1 = s.mul(a1, end);
        let a2 = s.mul(a2, end2);
        let a3 = s.mul(a3, s.mul(end2, end));
        let a4 = s.mul(a4, s.mul(end2, end2));
        let (quarter, half) = (s.splat(0.25), s.splat(0.5));
        let (sixth, three_quarters) = (s.splat(1.0 / 6.0), s.splat(0.75));
        let b = [
            a0,
            s.add(a0, s.mul(quarter, a1)),
            s.add(s.add(a0, s.mul(half, a1)), s.mul(a2, sixth)),
            s.add(
                s.add(s.add(a0, s.mul(three_quarters, a1)), s.mul(half, a2)),
                s.mul(quarter, a3),
            ),
            s.add(s.add(s.add(s.add(a0, a1), a2), a3), a4),
        ];
        let m = s.add(self.size(s), self.radius);
        (b, s.mul(s.splat(MARGIN_PER_SQUARE), s.mul(m, m)))
    }
}

/// De Casteljau's subdivision at the midpoint (`exclusion::halves`).
#[inline(always)]
fn halves<S: Simd>(s: S, b: [S::V; 5]) -> ([S::V; 5], [S::V; 5]) {
    let c = [
        mid(s, b[0], b[1]),
        mid(s, b[1], b[2]),
        mid(s, b[2], b[3]),
        mid(s, b[3], b[4]),
    ];
    let d = [mid(s, c[0], c[1]), mid(s, c[1], c[2]), mid(s, c[2], c[3])];
    let e = [mid(s, d[0], d[1]), mid(s, d[1], d[2])];
    let f = mid(s, e[0], e[1]);
    ([b[0], c[0], d[0], e[0], f], [f, e[1], d[2], c[3], b[4]])
}

/// `½·(x + y)`.
#[inline(always)]
fn mid<S: Simd>(s: S, x: S::V, y: S::V) -> S::V {
    s.mul(s.splat(0.5), s.add(x, y))
}

/// The lanes where every coefficient is above `margin`.
#[inline(always)]
fn above<S: Simd>(s: S, b: &[S::V; 5], margin: S::V) -> S::M {
    let mut all = s.all();
    for &x in b {
        all &= s.gt(x, margin);
    }
    all
}

/// The lanes where exactly one of `masks` is set.
#[inline(always)]
fn exactly_one<S: Simd, const N: usize>(s: S, masks: [S::M; N]) -> S::M {
    let (mut one, mut two) = (s.none(), s.none());
    for m in masks {
        two |= one & m;
        one |= m;
    }
    one & !two
}

/// The lanes where the signs (`> 0` or not) of consecutive values change exactly once.
#[inline(always)]
fn one_sign_change<S: Simd, const N: usize, const M: usize>(s: S, x: &[S::V; N]) -> S::M {
    let mut changes = [s.none(); M];
    for (k, change) in changes.iter_mut().enumerate() {
        *change = s.gt(x[k], s.zero()) ^ s.gt(x[k + 1], s.zero());
    }
    exactly_one(s, changes)
}

/// `exclusion::one_root` in each lane.
#[inline(always)]
fn one_root<S: Simd>(s: S, b: &[S::V; 5], margin: S::V) -> S::M {
    let mut clear = s.all();
    for &x in b {
        clear &= s.gt(s.abs(x), margin);
    }
    clear & s.gt(b[0], s.zero()) & one_sign_change::<S, 5, 4>(s, b)
}

/// `exclusion::one_dip` in each lane.
#[inline(always)]
fn one_dip<S: Simd>(s: S, b: &[S::V; 5], margin: S::V) -> S::M {
    let slopes = [
        s.sub(b[1], b[0]),
        s.sub(b[2], b[1]),
        s.sub(b[3], b[2]),
        s.sub(b[4], b[3]),
    ];
    let twice = s.mul(s.splat(2.0), margin);
    let mut steep = s.all();
    for &x in &slopes {
        steep &= s.gt(s.abs(x), twice);
    }
    s.gt(b[0], margin) & steep & s.lt(slopes[0], s.zero()) & one_sign_change::<S, 4, 3>(s, &slopes)
}

/// `exclusion::OpenEighth` in lanes.
pub(super) struct OpenEighthLanes<S: Simd> {
    index: S::V,
    one_root: S::M,
    one_dip: S::M,
    rest_positive: S::M,
}

/// `exclusion::first_open_eighth` in each lane.
#[inline(always)]
pub(super) fn first_open_eighth<S: Simd, const D: usize>(
    s: S,
    gap: &GapLanes<S, D>,
    end: S::V,
) -> OpenEighthLanes<S> {
    let (b, margin) = gap.bernstein(s, end);
    let (l, r) = halves(s, b);
    let ((ll, lr), (rl, rr)) = (halves(s, l), halves(s, r));
    let ((e0, e1), (e2, e3)) = (halves(s, ll), halves(s, lr));
    let ((e4, e5), (e6, e7)) = (halves(s, rl), halves(s, rr));
    let eighths = [e0, e1, e2, e3, e4, e5, e6, e7];
    // From the last to the first, so that the first open eighth is the one kept.
    let (mut index, mut piece) = (s.splat(8.0), e7);
    let (mut open, mut two_open) = (s.none(), s.none());
    for k in (0..8).rev() {
        let closed = !above(s, &eighths[k], margin);
        index = s.blend(closed, index, s.splat(k as f64));
        for (c, &e) in piece.iter_mut().zip(&eighths[k]) {
            *c = s.blend(closed, *c, e);
        }
        two_open |= open & closed;
        open |= closed;
    }
    OpenEighthLanes {
        index,
        one_root: open & one_root(s, &piece, margin),
        one_dip: open & one_dip(s, &piece, margin),
        rest_positive: !two_open,
    }
}

/// The root of the chord through `(lo, f_lo)` and `(hi, f_hi)`.
#[inline(always)]
fn secant<S: Simd>(s: S, (lo, hi): (S::V, S::V), (f_lo, f_hi): (S::V, S::V)) -> S::V {
    s.add(lo, s.mul(s.sub(hi, lo), s.div(f_lo, s.sub(f_lo, f_hi))))
}

/// A function of the window's time and its derivative, for [`fixed_newton`] (a trait rather
/// than a closure: see `simd`).
trait WithDerivative<S: Simd> {
    /// The value at `u` and the derivative there.
    fn at(&self, s: S, u: S::V) -> (S::V, S::V);
}

/// The gap's half slope, with its derivative.
struct HalfSlope<'a, S: Simd, const D: usize>(&'a GapLanes<S, D>);

impl<S: Simd, const D: usize> WithDerivative<S> for HalfSlope<'_, S, D> {
    #[inline(always)]
    fn at(&self, s: S, u: S::V) -> (S::V, S::V) {
        (self.0.half_slope(s, u), self.0.half_curvature(s, u))
    }
}

/// The gap's value, with its derivative.
struct Value<'a, S: Simd, const D: usize>(&'a GapLanes<S, D>);

impl<S: Simd, const D: usize> WithDerivative<S> for Value<'_, S, D> {
    #[inline(always)]
    fn at(&self, s: S, u: S::V) -> (S::V, S::V) {
        (
            self.0.value(s, u),
            s.mul(s.splat(2.0), self.0.half_slope(s, u)),
        )
    }
}

/// The state of [`fixed_newton`]'s steps in each lane (`eighth_entry::NewtonState`).
#[derive(Clone, Copy)]
struct NewtonLanes<S: Simd> {
    lo: S::V,
    hi: S::V,
    x: S::V,
    best: S::V,
    best_value: S::V,
    best_step: S::V,
    improved: S::M,
}

impl<S: Simd> NewtonLanes<S> {
    /// Converged: the correction at the best iterate is within `ulps` ulps.
    #[inline(always)]
    fn within(&self, s: S, ulps: f64) -> S::M {
        let bound = s.mul(s.splat(ulps * f64::EPSILON), self.best);
        s.eq(self.best_value, s.zero()) | s.ge(bound, self.best_step)
    }

    /// Stalled: within `noise` of zero, the last step did not lower `|f|`.
    #[inline(always)]
    fn stalled(&self, s: S, noise: S::V) -> S::M {
        !self.improved & s.ge(noise, self.best_value)
    }

    /// One step on `f` where not converged; the converged lanes keep their state.
    #[inline(always)]
    fn step(self, s: S, f: &impl WithDerivative<S>, lo_positive: S::M, noise: S::V) -> Self {
        let x = self.x;
        let (fx, dfx) = f.at(s, x);
        let zero = s.zero();
        let like_lo = !(s.gt(fx, zero) ^ lo_positive);
        let nonzero = s.ne(fx, zero);
        let lo = s.blend(like_lo & nonzero, self.lo, x);
        let hi = s.blend(!like_lo & nonzero, self.hi, x);
        let correction = s.div(fx, dfx);
        let size = s.abs(fx);
        let improved = s.lt(size, self.best_value);
        let newton = s.sub(x, correction);
        let inside = s.gt(newton, lo) & s.lt(newton, hi);
        let bisection = s.mul(s.splat(0.5), s.add(lo, hi));
        // Converged lanes stay: as if no lane moved, with the stepping lanes' values blended in.
        let stays = self.within(s, 0.5) | self.stalled(s, noise);
        let moves = !stays;
        Self {
            lo: s.blend(moves, self.lo, lo),
            hi: s.blend(moves, self.hi, hi),
            x: s.blend(moves, x, s.blend(inside, bisection, newton)),
            best: s.blend(moves & improved, self.best, x),
            best_value: s.blend(moves & improved, self.best_value, size),
            best_step: s.blend(moves & improved, self.best_step, s.abs(correction)),
            improved: (stays & self.improved) | (moves & improved),
        }
    }
}

/// Six Newton steps on `f` from `start` in every lane, inside `(lo, hi)` where `f` changes sign
/// (`f_lo` at `lo`) (`eighth_entry::fixed_newton`, lane-wise): the iterate where `|f|` was
/// smallest, and the lanes where it is the root to float accuracy.
#[inline(always)]
fn fixed_newton<S: Simd>(
    s: S,
    f: &impl WithDerivative<S>,
    (lo, hi): (S::V, S::V),
    f_lo: S::V,
    start: S::V,
    noise: S::V,
) -> (S::V, S::M) {
    let lo_positive = s.gt(f_lo, s.zero());
    let infinity = s.splat(f64::INFINITY);
    let mut state = NewtonLanes {
        lo,
        hi,
        x: start,
        best: start,
        best_value: infinity,
        best_step: infinity,
        improved: s.all(),
    };
    for _ in 0..6 {
        state = state.step(s, f, lo_positive, noise);
    }
    (state.best, state.within(s, 2.0) | state.stalled(s, noise))
}

/// `eighth_entry::eighth_entry` in each lane (every step taken).
#[inline(always)]
pub(super) fn eighth_entry<S: Simd, const D: usize>(
    s: S,
    gap: &GapLanes<S, D>,
    end: S::V,
    eighth: &OpenEighthLanes<S>,
    qualifies: S::M,
) -> EighthLanes<S> {
    let zero = s.zero();
    let (root, dip) = (eighth.one_root, eighth.one_dip);
    let lo = s.mul(end, s.mul(eighth.index, s.splat(0.125)));
    let hi = s.mul(
        end,
        s.mul(s.add(eighth.index, s.splat(1.0)), s.splat(0.125)),
    );
    let (g_lo, g_hi) = (gap.value(s, lo), gap.value(s, hi));
    let (slope_lo, slope_hi) = (gap.half_slope(s, lo), gap.half_slope(s, hi));
    let dip = dip & s.lt(slope_lo, zero) & s.gt(slope_hi, zero);
    let curvature_lo = gap.half_curvature(s, lo);
    // `.max(0.0)` of a difference that is never −0: `x > 0 ? x : 0` (NaN to 0, as `f64::max`).
    let discriminant = s.max(
        s.sub(s.mul(slope_lo, slope_lo), s.mul(curvature_lo, g_lo)),
        zero,
    );
    let taylor = s.add(lo, s.div(g_lo, s.sub(s.sqrt(discriminant), slope_lo)));
    let probe = s.add(taylor, s.mul(s.sub(taylor, lo), s.splat(1.0 / 16.0)));
    let probed = dip & !root & s.gt(taylor, lo) & s.lt(probe, hi);
    let g_probe = gap.value(s, probe);
    let bracketed = probed & s.lt(g_probe, zero);
    // The minimum's steps only where some lane uses it (the scalar steps skip it elsewhere;
    // the lanes that do not use it ignore it).
    let lowest_used = dip & !(root & s.lt(g_hi, zero)) & !bracketed;
    let (lowest, lowest_found) = if s.any(lowest_used) {
        fixed_newton(
            s,
            &HalfSlope(gap),
            (lo, hi),
            slope_lo,
            secant(s, (lo, hi), (slope_lo, slope_hi)),
            gap.half_slope_noise(s),
        )
    } else {
        (hi, s.none())
    };
    let g_lowest = gap.value(s, lowest);
    let starts_positive = qualifies & s.gt(gap.value(s, zero), zero) & s.gt(g_lo, zero);
    let right = s.blend(root, s.blend(bracketed, lowest, probe), hi);
    let g_right = s.blend(root, s.blend(bracketed, g_lowest, g_probe), g_hi);
    let crossing = starts_positive & (root | dip) & s.lt(g_right, zero);
    let minus_g_right = s.mul(s.splat(-1.0), g_right);
    let model = s.sub(
        right,
        s.sqrt(s.div(minus_g_right, gap.half_curvature(s, right))),
    );
    let from_model = s.gt(model, lo) & s.lt(model, right) & !root & !bracketed;
    let from_taylor = s.gt(taylor, lo) & s.lt(taylor, right) & (root | bracketed);
    let start = s.blend(
        from_model,
        s.blend(from_taylor, secant(s, (lo, right), (g_lo, g_right)), taylor),
        model,
    );
    let (entry, entry_found) =
        fixed_newton(s, &Value(gap), (lo, right), g_lo, start, gap.value_noise(s));
    let narrow = s.ge(s.mul(s.splat(NARROW), gap.size(s)), gap.radius);
    let missed = starts_positive
        & dip
        & !bracketed
        & lowest_found
        & s.ge(g_lowest, zero)
        & s.gt(g_hi, zero)
        & !narrow;
    EighthLanes {
        entry,
        found: crossing & entry_found,
        screened_out: missed & eighth.rest_positive,
    }
}

/// `eighth_entry::window_eighth` in each lane: `gap` a window's motion in the pair's unit of
/// length, `length` its bounded length, `before` the lanes where the gap was positive just
/// before it.
#[inline(always)]
pub(super) fn window_eighth<S: Simd, const D: usize>(
    s: S,
    gap: &GapLanes<S, D>,
    length: S::V,
    before: S::M,
) -> EighthLanes<S> {
    let short = s.ge(length, s.splat(f64::MIN_POSITIVE)) & !long_window(s, gap, length);
    // `normal_time_unit`: the power of two below the length, doubled unless it is that power.
    let below = s.fraction_cleared(length);
    let h = s.blend(s.eq(below, length), s.mul(s.splat(2.0), below), length);
    let scaled = gap.time_scaled(s, h).in_own_unit(s);
    let end = s.div(length, h);
    let eighth = first_open_eighth(s, &scaled, end);
    let qualifies = short & before & s.ge(scaled.radius, s.splat(RADIUS_FLOOR));
    let proven = qualifies & s.eq(eighth.index, s.splat(8.0));
    let found = eighth_entry(s, &scaled, end, &eighth, qualifies);
    EighthLanes {
        entry: s.mul(found.entry, h),
        found: found.found,
        screened_out: found.screened_out | proven,
    }
}

/// `normal_time_unit` in each lane: the power of two below the length, doubled unless it is
/// that power.
#[inline(always)]
pub(super) fn normal_time_unit<S: Simd>(s: S, length: S::V) -> S::V {
    let below = s.fraction_cleared(length);
    s.blend(s.eq(below, length), s.mul(s.splat(2.0), below), length)
}

/// `long_window::long_window` in each lane.
#[inline(always)]
pub(super) fn long_window<S: Simd, const D: usize>(
    s: S,
    gap: &GapLanes<S, D>,
    length: S::V,
) -> S::M {
    const LONG2: f64 = LONG * LONG;
    let (p, v, a) = (&gap.offset, &gap.velocity, &gap.acceleration);
    let size2 = s.add(dot(s, p, p), s.mul(gap.radius, gap.radius));
    let length2 = s.mul(length, length);
    let run2 = s.mul(length2, dot(s, v, v));
    let bend2 = s.mul(length2, s.mul(length2, dot(s, a, a)));
    s.gt(run2, s.mul(s.splat(LONG2), size2))
        | s.gt(bend2, s.mul(s.splat(LONG2), s.mul(s.splat(LONG2), size2)))
}

/// `bounded_finite_length` in each lane: at most [`LONGEST_WINDOW`] (NaN to it, as `f64::min`).
#[inline(always)]
pub(super) fn bounded_finite_length<S: Simd>(s: S, length: S::V) -> S::V {
    s.min(length, s.splat(LONGEST_WINDOW))
}
