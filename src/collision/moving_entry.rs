//! Two moving balls that first touch while both still move, where the crossing is plain:
//! found lane-wise, without a branch.
//!
//! On a table most contacts come before either ball stops (on the first window), and most
//! are transversal: the first eighth of that window that the Bernstein coefficients do not
//! prove positive ([`first_open_eighth`]) holds exactly one root, and every eighth before
//! it is proven clear, so that root is the first contact. It is found by a fixed number of
//! Newton steps kept inside the eighth (a step that would leave the bracket is replaced by
//! bisection), all on the accurate form of the gap
//! ([`Gap::value`](crate::coefficients::Gap::value)), and kept only if the gap there is within
//! its rounding bound of zero, which is where the float arithmetic puts the root: the answer
//! the general search would give, to its accuracy.
//!
//! Balls that already touch or overlap and move into each other meet at 0 (SPEC): decided
//! here too, on the search's own values at time 0.
//!
//! Anything else (a ball at rest or without friction, a first open eighth of another shape,
//! Newton not settled in time) is left to the general search, which first calls this same
//! function: a batch that settles a pair lane-wise gives it the search's own bits.

use super::approaching;
use super::crossing::FirstWindow;
use super::exclusion::{OpenEighth, first_open_eighth, proves_positive_at_once};
use super::prefilter::PairInput;

/// What [`while_moving`] settles about a pair's first window.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct WhileMoving {
    /// The first contact, if it comes in the first window: its time, `∞` if that time is at
    /// or past the horizon; NaN where this does not settle it.
    pub entry: f64,
    /// The first window holds no contact, and the balls are apart at its end (the search goes
    /// on from the second window).
    pub no_entry: bool,
}

/// The first window of `pair` (both balls moving), where its first open eighth is plain.
///
/// The eighth is plain when it holds a single root, or a single minimum (a grazing contact,
/// an entry and an exit close together, or a near miss): the minimum is found first, by
/// Newton on the slope; if the gap is negative there, the entry lies between the eighth's
/// start and it; if not, and the minimum has converged and every later eighth is proven
/// positive, the window holds no contact.
#[inline(always)]
pub(crate) fn while_moving(pair: &PairInput) -> WhileMoving {
    let window = FirstWindow::of(pair);
    let eighth = first_open_eighth(&window.gap, window.end);
    settle(pair, &window, &eighth, false)
}

/// [`while_moving`] for one pair: the same answer, without the Newton steps where the window
/// holds no plain eighth (most pairs that reach the search), and with fused multiply-adds
/// in hardware where the CPU has them.
pub(crate) fn while_moving_one(pair: &PairInput) -> WhileMoving {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("fma") {
        // SAFETY: the CPU supports FMA, just detected.
        return unsafe { while_moving_one_fma(pair) };
    }
    while_moving_one_portable(pair)
}

/// [`while_moving_one_portable`] compiled with FMA enabled.
///
/// # Safety
/// The CPU must support FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
unsafe fn while_moving_one_fma(pair: &PairInput) -> WhileMoving {
    while_moving_one_portable(pair)
}

#[inline(always)]
fn while_moving_one_portable(pair: &PairInput) -> WhileMoving {
    let nothing = WhileMoving {
        entry: f64::NAN,
        no_entry: false,
    };
    let window = FirstWindow::of(pair);
    let start = at_start(&window, pair.t_max);
    if !start.is_nan() {
        return WhileMoving {
            entry: start,
            no_entry: false,
        };
    }
    // A window proven positive whole has no entry, which the search finds at once: `settle`
    // would find no entry there either (at most that there is none, which the search then
    // takes the same way).
    if !window.qualifies || proves_positive_at_once(&window.gap, window.end) {
        return nothing;
    }
    let eighth = first_open_eighth(&window.gap, window.end);
    if !(eighth.one_root | eighth.one_dip) {
        return nothing; // what `settle` finds for these
    }
    settle(pair, &window, &eighth, true)
}

/// [`while_moving`]'s work on the first open eighth.
#[inline(always)]
fn settle(
    pair: &PairInput,
    window: &FirstWindow,
    eighth: &OpenEighth,
    one_pair: bool,
) -> WhileMoving {
    let (gap, end) = (&window.gap, window.end);
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
    // One pair skips the steps whose results would be masked out below (lanes take them all:
    // the results are the same).
    // The minimum is used for a dip, unless a single root with g < 0 at the eighth's end
    // already brackets the entry (and rules out a miss).
    let lowest_used = dip && !(root && g_hi < 0.0);
    let (lowest, lowest_found) = if one_pair && !lowest_used {
        (hi, false)
    } else {
        fixed_newton(
            |u| (gap.half_slope(u), gap.half_curvature(u)),
            (lo, hi),
            slope_lo,
            secant((lo, hi), (slope_lo, slope_hi)),
            gap.half_slope_noise(),
            one_pair,
        )
    };
    let g_lowest = gap.value(lowest);
    let plain = window.qualifies & (gap.value(0.0) > 0.0) & (g_lo > 0.0);
    // The entry lies between the eighth's start and its end (a single root) or its minimum.
    let (right, g_right) = if root { (hi, g_hi) } else { (lowest, g_lowest) };
    let crossing = plain & (root | dip) & (g_right < 0.0);
    // From a minimum, where the root may be near-double, the quadratic model there is
    // already close (where a secant would crawl in): g(m) + c·(u − m)² = 0.
    let model = right - (-g_right / gap.half_curvature(right)).sqrt();
    // From the eighth's start, towards a single root, the root of g's second-order Taylor
    // model there (g is mostly convex near a contact): it starts Newton close enough for six
    // steps where the chord often does not (on random table contacts, the chord left a third
    // unsettled after six steps, this one in sixteen).
    let curvature_lo = gap.half_curvature(lo);
    let taylor =
        lo + g_lo / ((slope_lo * slope_lo - curvature_lo * g_lo).max(0.0).sqrt() - slope_lo);
    let start = if (model > lo) & (model < right) & !root {
        model
    } else if (taylor > lo) & (taylor < right) & root {
        taylor
    } else {
        secant((lo, right), (g_lo, g_right))
    };
    let (entry, entry_found) = if one_pair && !crossing {
        (lo, false)
    } else {
        fixed_newton(
            |u| (gap.value(u), 2.0 * gap.half_slope(u)),
            (lo, right),
            g_lo,
            start,
            gap.value_noise(),
            one_pair,
        )
    };
    let t = entry * window.unit;
    let entry = match (crossing & entry_found, t < pair.t_max) {
        (true, true) => t,
        (true, false) => f64::INFINITY,
        (false, _) => f64::NAN,
    };
    let missed = plain & dip & lowest_found & (g_lowest >= 0.0) & (g_hi > 0.0);
    let start = at_start(window, pair.t_max);
    WhileMoving {
        entry: if start.is_nan() { entry } else { start },
        no_entry: missed & eighth.rest_positive,
    }
}

/// The answer for balls touching or overlapping at the start and moving into each other: a
/// contact at 0 (SPEC), `∞` if the horizon is 0; NaN for every other pair. Decided on the
/// search's own values at time 0 (`window.initial`), so both decide alike.
#[inline(always)]
fn at_start(window: &FirstWindow, t_max: f64) -> f64 {
    let touching =
        window.qualifies & (window.initial.value(0.0) <= 0.0) & approaching(&window.initial);
    let now = if t_max > 0.0 { 0.0 } else { f64::INFINITY };
    if touching { now } else { f64::NAN }
}

/// The root of the chord through `(lo, f_lo)` and `(hi, f_hi)`.
#[inline(always)]
fn secant((lo, hi): (f64, f64), (f_lo, f_hi): (f64, f64)) -> f64 {
    lo + (hi - lo) * (f_lo / (f_lo - f_hi))
}

/// Up to six Newton steps on `f` (which returns its value and derivative) from `start`, inside
/// `(lo, hi)` where `f` changes sign (`f_lo` at `lo`), until converged; a step that would
/// leave the shrinking bracket is replaced by bisection. Without a branch unless `one_pair`
/// (which stops at convergence, where lanes take the remaining steps unchanged: the same
/// result).
///
/// Returns the iterate where `|f|` was smallest, and whether it is the root to float
/// accuracy: Newton's correction there is within two ulps, or the steps stopped lowering
/// `|f|` (the last did not improve on it) once within `noise`, the bound on `f`'s rounding,
/// as the scalar search's polishing does.
#[inline(always)]
fn fixed_newton(
    f: impl Fn(f64) -> (f64, f64),
    (lo, hi): (f64, f64),
    f_lo: f64,
    start: f64,
    noise: f64,
    one_pair: bool,
) -> (f64, bool) {
    let lo_positive = f_lo > 0.0;
    // (bracket, iterate, best iterate, |f| and Newton correction there, whether the last
    // step improved on it)
    type State = ((f64, f64), f64, f64, f64, f64, bool);
    // Converged: the correction at the best iterate is within `ulps` ulps.
    let within = |&(_, _, best, best_value, best_step, _): &State, ulps: f64| {
        (best_value == 0.0) | (best_step <= ulps * f64::EPSILON * best)
    };
    // Stalled: within rounding noise of zero, a step failed to lower |f| (as the search's
    // polishing stops); from there on, steps only jitter in the noise.
    let stalled = |&(_, _, _, best_value, _, improved): &State| !improved & (best_value <= noise);
    // Steps stop where the next could not move the iterate, or where they stall.
    let converged = |state: &State| within(state, 0.5) | stalled(state);
    let step = |state: State| -> State {
        let ((lo, hi), x, best, best_value, best_step, _) = state;
        let (fx, dfx) = f(x);
        // Which end `x` replaces: the one where `f` has its sign.
        let like_lo = (fx > 0.0) == lo_positive;
        let lo = if like_lo & (fx != 0.0) { x } else { lo };
        let hi = if !like_lo & (fx != 0.0) { x } else { hi };
        let correction = fx / dfx;
        let improved = fx.abs() < best_value;
        let newton = x - correction;
        let inside = (newton > lo) & (newton < hi);
        let next = (
            (lo, hi),
            if inside { newton } else { 0.5 * (lo + hi) },
            if improved { x } else { best },
            if improved { fx.abs() } else { best_value },
            if improved {
                correction.abs()
            } else {
                best_step
            },
            improved,
        );
        // Once converged, the state stays: one pair stops there, lanes step on unchanged.
        if converged(&state) { state } else { next }
    };
    let mut state = ((lo, hi), start, start, f64::INFINITY, f64::INFINITY, true);
    if one_pair {
        for _ in 0..6 {
            if converged(&state) {
                break;
            }
            state = step(state);
        }
    } else {
        // Written out rather than looped, so that a batch's lane loop around it vectorises.
        state = step(step(step(step(step(step(state))))));
    }
    (state.2, within(&state, 2.0) | stalled(&state))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::prefilter::test_support::{moving_ball, pair, pair_of, search};
    use crate::test_rng::Rng;

    #[test]
    fn a_head_on_contact_is_settled() {
        // 1 apart, closing at 4 m/s and both braking at 1 m/s²: |d| = 1 − 4t + t² = 0.1.
        let t = while_moving(&pair([0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [-2.0, 0.0])).entry;
        let exact = 2.0 - (4.0f64 - 0.9).sqrt();
        assert!(
            (t - exact).abs() <= 2.0 * f64::EPSILON * exact,
            "{t} {exact}"
        );
    }

    #[test]
    fn overlapping_balls_moving_into_each_other_touch_at_0() {
        // 0.05 apart at contact distance 0.1, closing; then the same pair separating, which
        // is not a contact at 0 (SPEC) and is left to the search.
        let closing = pair([0.0, 0.0], [1.0, 0.0], [0.05, 0.0], [-1.0, 0.0]);
        assert_eq!(while_moving(&closing).entry, 0.0);
        assert_eq!(while_moving_one(&closing).entry, 0.0);
        assert_eq!(search(&closing), Some(0.0));
        let no_time = PairInput {
            t_max: 0.0,
            ..closing
        };
        // No time at all: the contact at 0 is cut by the horizon, as the search cuts it.
        assert_eq!(while_moving(&no_time).entry, f64::INFINITY);
        assert_eq!(while_moving_one(&no_time).entry, f64::INFINITY);
        assert_eq!(search(&no_time), None);
        let parting = pair([0.0, 0.0], [-1.0, 0.0], [0.05, 0.0], [1.0, 0.0]);
        assert!(while_moving(&parting).entry.is_nan());
        assert!(while_moving_one(&parting).entry.is_nan());
    }

    #[test]
    fn what_is_not_plain_is_left_to_the_search() {
        // Apart for ever, a ball at rest, a grazing pass: not settled here.
        for p in [
            pair([0.0, 0.0], [1.0, 0.0], [0.0, 5.0], [1.0, 0.0]),
            pair([0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [0.0, 0.0]),
            pair([0.0, 0.0], [2.0, 0.0], [1.0, 0.1 - 1e-12], [0.0, 0.0]),
        ] {
            assert!(while_moving(&p).entry.is_nan(), "{p:?}");
        }
    }

    #[test]
    fn settled_contacts_are_the_searches_first_contacts() {
        // Moving pairs, near each other, at scales from 1e-6 to 1e6 and with horizons: where
        // this settles a pair, its answer is the first contact: the whole-window search's
        // (`first_entry`, which does not call it), to within rounding.
        let mut rng = Rng(0x5eed);
        let mut settled = 0;
        for _ in 0..20_000 {
            let scale = 10f64.powf(rng.uniform(-6.0, 6.0));
            let ball = |rng: &mut Rng| moving_ball(rng, scale);
            let (a, b) = (ball(&mut rng), ball(&mut rng));
            let t_max = if rng.uniform(0.0, 1.0) < 0.2 {
                rng.uniform(0.0, 2.0)
            } else {
                f64::INFINITY
            };
            let p = pair_of(a, b, rng.uniform(0.05, 1.0) * scale, t_max);
            let t = while_moving(&p).entry;
            if t.is_nan() {
                continue;
            }
            settled += 1;
            match whole_window_entry(&p) {
                Some(r) => {
                    // Both within the band where the gap is rounding: the gap's rounding
                    // bound over its slope, twice (one on each side), and a few ulps.
                    let window = FirstWindow::of(&p);
                    let u = r / window.unit;
                    let slope = 2.0 * window.gap.half_slope(u).abs() / window.unit;
                    let band = 2.0 * window.gap.value_noise() / slope + 4.0 * f64::EPSILON * r;
                    assert!((t - r).abs() <= band, "{p:?}: {t} vs {r}, band {band}");
                }
                None => assert_eq!(t, f64::INFINITY, "{p:?}"),
            }
            assert_eq!(search(&p).unwrap_or(f64::INFINITY), t, "{p:?}");
        }
        assert!(settled > 1_000, "only {settled} settled");
    }

    /// The first contact by the critical-point search on the whole first window (which this
    /// module does not use), `None` past the horizon or beyond the window.
    fn whole_window_entry(p: &PairInput) -> Option<f64> {
        use crate::collision::entry::{WindowSearch, first_entry};
        let window = FirstWindow::of(p);
        match first_entry(&window.gap, window.end, true) {
            WindowSearch::Entry(u) => Some(u * window.unit).filter(|&t| t < p.t_max),
            WindowSearch::NoEntry { .. } => None,
        }
    }
}
