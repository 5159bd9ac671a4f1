//! The first entry on a window whose first open eighth is isolated: found by a fixed number of
//! Newton steps, so that a batch runs it eight windows at a time without a branch (its lane
//! twin, `batch/eighth_lanes.rs`).
//!
//! Most contacts are transversal: the first eighth of the window that the Bernstein
//! coefficients do not prove positive ([`first_open_eighth`]) holds exactly one root, and
//! every eighth before it is proven clear, so that root is the first entry. It is found by
//! Newton steps kept inside the eighth (a step that would leave the bracket is replaced by
//! bisection), all on the accurate form of the gap ([`Gap::value`]), and kept only if the gap
//! there is within its rounding bound of zero, which is where the float arithmetic puts the
//! root: the answer the general search would give, to its accuracy. An eighth that holds a
//! single minimum (a graze, an entry and an exit close together, a near miss) is settled too:
//! its minimum is found first, by Newton on the slope; if the gap is negative there, the entry
//! lies between the eighth's start and it; if not, and every later eighth is proven positive,
//! the window holds no entry.
//!
//! Two stages stand on it: a friction pair's first window ([`moving_entry`](super::moving_entry),
//! lane-wise in the friction batch) and every window of balls on paths that would be searched
//! ([`window_eighth`], called by [`path_contact`](super::path_contact); its lane twin,
//! `batch/eighth_lanes.rs`, settles the first windows of the path batch's pairs eight at a
//! time over the SIMD layer, every step taken). Whatever it does not settle goes to the window
//! search.

use super::exclusion::{OpenEighth, first_open_eighth};
use super::long_window::long_window;
use super::narrow_dip::narrow;
use super::{in_own_unit, normal_time_unit};
use crate::gap::Gap;

/// What [`eighth_entry`] settles about a window.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct EighthEntry {
    /// The entry, as time in the window's units, where `found`.
    pub entry: f64,
    /// The first entry is `entry`.
    pub found: bool,
    /// The window is screened out: it holds no entry, and the gap ends it positive.
    pub screened_out: bool,
}

/// The first entry on the window `[0, end]` of `gap` (time scaled so that `end ≤ 1`), where
/// its first open `eighth` is isolated and the gap is positive at its start; `qualifies`: the
/// caller's own conditions (magnitudes in the range where its arithmetic is exact enough). The
/// Newton steps whose results would be masked out are skipped and the steps stop at
/// convergence; the lane twin (`batch/eighth_lanes.rs`) takes them all: the same results.
#[inline(always)]
pub(crate) fn eighth_entry<const D: usize>(
    gap: &Gap<D>,
    end: f64,
    eighth: &OpenEighth,
    qualifies: bool,
) -> EighthEntry {
    let (root, dip) = (eighth.one_root, eighth.one_dip);
    // The eighth `[lo, hi]` (time in the window's units); the coefficients promise its shape,
    // the accurate values at its ends must confirm it.
    let (lo, hi) = (
        end * (eighth.index * 0.125),
        end * ((eighth.index + 1.0) * 0.125),
    );
    let (g_lo, g_hi) = (gap.value(lo), gap.value(hi));
    let (slope_lo, slope_hi) = (gap.half_slope(lo), gap.half_slope(hi));
    let dip = dip & (slope_lo < 0.0) & (slope_hi > 0.0);
    // From the eighth's start, towards a single root, the root of g's second-order Taylor
    // model there (g is mostly convex near a contact): it starts Newton close enough for six
    // steps where the chord often does not (on random table contacts, the chord left a third
    // unsettled after six steps, this one in sixteen).
    let curvature_lo = gap.half_curvature(lo);
    let taylor =
        lo + g_lo / ((slope_lo * slope_lo - curvature_lo * g_lo).max(0.0).sqrt() - slope_lo);
    // A dip whose entry that model all but finds: g < 0 a sixteenth of the way further on.
    // With g > 0 at the start and a single minimum, that brackets the first root (before the
    // probe, g falls through 0 once, wherever the minimum lies), and its minimum is not
    // needed: most contacts, a Newton search saved.
    let probe = taylor + (taylor - lo) * (1.0 / 16.0);
    let probed = dip & !root & (taylor > lo) & (probe < hi);
    let g_probe = if probed { gap.value(probe) } else { f64::NAN };
    let bracketed = probed & (g_probe < 0.0);
    // The steps whose results would be masked out below are skipped.
    // The minimum is used for a dip, unless a single root with g < 0 at the eighth's end, or
    // the probe, already brackets the entry (and rules out a miss).
    let lowest_used = dip && !(root && g_hi < 0.0) && !bracketed;
    let (lowest, lowest_found) = if !lowest_used {
        (hi, false)
    } else {
        fixed_newton(
            &HalfSlope(gap),
            (lo, hi),
            slope_lo,
            secant((lo, hi), (slope_lo, slope_hi)),
            gap.half_slope_noise(),
        )
    };
    let g_lowest = gap.value(lowest);
    let starts_positive = qualifies & (gap.value(0.0) > 0.0) & (g_lo > 0.0);
    // The entry lies between the eighth's start and its end (a single root), the probe, or
    // its minimum.
    let (right, g_right) = if root {
        (hi, g_hi)
    } else if bracketed {
        (probe, g_probe)
    } else {
        (lowest, g_lowest)
    };
    let crossing = starts_positive & (root | dip) & (g_right < 0.0);
    let (entry, entry_found) = if !crossing {
        (lo, false)
    } else {
        let start = if root | bracketed {
            // The Taylor model's root, where it lies inside.
            if (taylor > lo) & (taylor < right) {
                taylor
            } else {
                secant((lo, right), (g_lo, g_right))
            }
        } else {
            // From a minimum, where the root may be near-double, the quadratic model there
            // is already close (where a secant would crawl in): g(m) + c·(u − m)² = 0.
            let model = right - (-g_right / gap.half_curvature(right)).sqrt();
            if (model > lo) & (model < right) {
                model
            } else {
                secant((lo, right), (g_lo, g_right))
            }
        };
        fixed_newton(&Value(gap), (lo, right), g_lo, start, gap.value_noise())
    };
    // A dip narrower than the float grid is not called a miss here: the window search decides
    // it on the closest approach (`narrow_dip`).
    let missed = starts_positive
        & dip
        & !bracketed
        & lowest_found
        & (g_lowest >= 0.0)
        & (g_hi > 0.0)
        & !narrow(gap);
    EighthEntry {
        entry,
        found: crossing & entry_found,
        screened_out: missed & eighth.rest_positive,
    }
}

/// A window of balls on paths, settled on its first open eighth where the window search would
/// search it whole (not a long window, a length in the normal range): `gap` is its motion in
/// the pair's unit of length, `length` its length bounded as the search bounds it
/// ([`bounded_length`](super::bounded_length), which the caller's screens have formed), `before`
/// whether the gap was positive just before it. The entry is in time since the window's start,
/// as the search gives it. Nothing is settled where the window is not short, or the radius is
/// so small beside the motion that the gap's squares could underflow. A window without an
/// isolated eighth returns at once, and the Newton steps stop at convergence; the lane twin
/// (`batch/eighth_lanes.rs`) takes every step, without a branch: the same answer.
#[inline(always)]
pub(crate) fn window_eighth<const D: usize>(
    gap: &Gap<D>,
    length: f64,
    before: bool,
) -> EighthEntry {
    let nothing = EighthEntry {
        entry: f64::NAN,
        found: false,
        screened_out: false,
    };
    let short = (length >= f64::MIN_POSITIVE) & !long_window(gap, length);
    // (Where the window is not short, these are never used.)
    let h = normal_time_unit(length);
    let scaled = in_own_unit(&gap.time_scaled(h));
    let end = length / h;
    let eighth = first_open_eighth(&scaled, end);
    let qualifies = short & before & (scaled.contact_distance >= RADIUS_FLOOR);
    // Every eighth proven positive: no entry, the gap positive at the end (the search would
    // prove it piece by piece).
    let proven = qualifies & (eighth.index == 8.0);
    if proven {
        return EighthEntry {
            screened_out: true,
            ..nothing
        };
    }
    if !(qualifies & (eighth.one_root | eighth.one_dip)) {
        return nothing; // what `eighth_entry` finds for these
    }
    let found = eighth_entry(&scaled, end, &eighth, qualifies);
    EighthEntry {
        entry: found.entry * h,
        found: found.found,
        screened_out: found.screened_out | proven,
    }
}

/// The least radius of a window settled by [`window_eighth`], in the window's own unit (its
/// largest field in `[2, 4)`): its square and those of separations near it stay far above the
/// underflow.
pub(crate) const RADIUS_FLOOR: f64 = f64::from_bits((1023 - 300) << 52);

/// The root of the chord through `(lo, f_lo)` and `(hi, f_hi)`.
#[inline(always)]
fn secant((lo, hi): (f64, f64), (f_lo, f_hi): (f64, f64)) -> f64 {
    lo + (hi - lo) * (f_lo / (f_lo - f_hi))
}

/// A function of the window's time and its derivative, for [`fixed_newton`]. A trait with
/// `#[inline(always)]` implementations rather than a closure: a closure the compiler leaves
/// out of line is compiled without the batch level's features (`simd::dispatch`), and each
/// `mul_add` in it becomes a call.
trait WithDerivative {
    /// The value at `u` and the derivative there.
    fn at(&self, u: f64) -> (f64, f64);
}

/// The gap's half slope (its minimum is where it is 0), with its derivative.
struct HalfSlope<'a, const D: usize>(&'a Gap<D>);

impl<const D: usize> WithDerivative for HalfSlope<'_, D> {
    #[inline(always)]
    fn at(&self, u: f64) -> (f64, f64) {
        (self.0.half_slope(u), self.0.half_curvature(u))
    }
}

/// The gap's value, with its derivative.
struct Value<'a, const D: usize>(&'a Gap<D>);

impl<const D: usize> WithDerivative for Value<'_, D> {
    #[inline(always)]
    fn at(&self, u: f64) -> (f64, f64) {
        (self.0.value(u), 2.0 * self.0.half_slope(u))
    }
}

/// The state of [`fixed_newton`]'s steps.
#[derive(Clone, Copy)]
struct NewtonState {
    /// The bracket.
    lo: f64,
    hi: f64,
    /// The iterate.
    x: f64,
    /// The best iterate, `|f|` and Newton's correction there.
    best: f64,
    best_value: f64,
    best_step: f64,
    /// Whether the last step improved on the best.
    improved: bool,
}

impl NewtonState {
    /// Converged: the correction at the best iterate is within `ulps` ulps.
    #[inline(always)]
    fn within(&self, ulps: f64) -> bool {
        (self.best_value == 0.0) | (self.best_step <= ulps * f64::EPSILON * self.best)
    }

    /// Stalled: within rounding noise of zero, a step failed to lower |f| (as the search's
    /// polishing stops); from there on, steps only jitter in the noise.
    #[inline(always)]
    fn stalled(&self, noise: f64) -> bool {
        !self.improved & (self.best_value <= noise)
    }

    /// Steps stop where the next could not move the iterate, or where they stall.
    #[inline(always)]
    fn converged(&self, noise: f64) -> bool {
        self.within(0.5) | self.stalled(noise)
    }

    /// One step on `f` (`lo_positive`: the sign of `f` at the bracket's low end); once
    /// converged, the state stays (the steps stop there; the lane twin steps on unchanged).
    #[inline(always)]
    fn step(self, f: &impl WithDerivative, lo_positive: bool, noise: f64) -> Self {
        let x = self.x;
        let (fx, dfx) = f.at(x);
        // Which end `x` replaces: the one where `f` has its sign.
        let like_lo = (fx > 0.0) == lo_positive;
        let lo = if like_lo & (fx != 0.0) { x } else { self.lo };
        let hi = if !like_lo & (fx != 0.0) { x } else { self.hi };
        let correction = fx / dfx;
        let improved = fx.abs() < self.best_value;
        let newton = x - correction;
        let inside = (newton > lo) & (newton < hi);
        let next = Self {
            lo,
            hi,
            x: if inside { newton } else { 0.5 * (lo + hi) },
            best: if improved { x } else { self.best },
            best_value: if improved { fx.abs() } else { self.best_value },
            best_step: if improved {
                correction.abs()
            } else {
                self.best_step
            },
            improved,
        };
        if self.converged(noise) { self } else { next }
    }
}

/// Up to six Newton steps on `f` from `start`, inside `(lo, hi)` where `f` changes sign
/// (`f_lo` at `lo`), until converged; a step that would leave the shrinking bracket is
/// replaced by bisection. (The lane twin takes the remaining steps unchanged once converged:
/// the same result.)
///
/// Returns the iterate where `|f|` was smallest, and whether it is the root to float
/// accuracy: Newton's correction there is within two ulps, or the steps stopped lowering
/// `|f|` (the last did not improve on it) once within `noise`, the bound on `f`'s rounding,
/// as the scalar search's polishing does.
#[inline(always)]
fn fixed_newton(
    f: &impl WithDerivative,
    (lo, hi): (f64, f64),
    f_lo: f64,
    start: f64,
    noise: f64,
) -> (f64, bool) {
    let lo_positive = f_lo > 0.0;
    let mut state = NewtonState {
        lo,
        hi,
        x: start,
        best: start,
        best_value: f64::INFINITY,
        best_step: f64::INFINITY,
        improved: true,
    };
    for _ in 0..6 {
        if state.converged(noise) {
            break;
        }
        state = state.step(f, lo_positive, noise);
    }
    (state.best, state.within(2.0) | state.stalled(noise))
}
