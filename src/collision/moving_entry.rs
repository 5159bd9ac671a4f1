//! Two moving balls that first touch while both still move, where the crossing is isolated:
//! found on the first window's first open eighth (lane-wise in the friction batch:
//! `batch/moving_entry_lanes.rs`).
//!
//! On a table most contacts come before either ball stops (on the first window), and most
//! are transversal: the first window's entry on its first open eighth
//! ([`eighth_entry`](super::eighth_entry)) settles them, from the window the search itself
//! would build ([`FirstWindow`]), and the time is then cut by the horizon as the search cuts
//! it.
//!
//! Balls that already touch or overlap and move into each other meet at 0 (SPEC): decided
//! here too, on the search's own values at time 0.
//!
//! Anything else (a ball at rest or without friction, a first open eighth of another shape,
//! Newton not settled in time) is left to the general search, which first calls this same
//! function: a batch that settles a pair lane-wise gives it the search's own bits.

use super::approaching;
use super::crossing::FirstWindow;
use super::eighth_entry::eighth_entry;
use super::exclusion::{OpenEighth, first_open_eighth, window_screened_out_at_once};
use super::prefilter::PairInput;

/// What [`while_moving_one`] settles about a pair's first window.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct WhileMoving {
    /// The first contact, if it comes in the first window: its time, `∞` if that time is at
    /// or past the horizon; NaN where this does not settle it.
    pub entry: f64,
    /// The first window is screened out: no contact, the balls apart at its end (the search goes
    /// on from the second window).
    pub screened_out: bool,
}

/// The first window of `pair` (both balls moving), where its first open eighth is isolated,
/// with fused multiply-adds in hardware where the CPU has them.
///
/// The eighth is isolated when it holds a single root, or a single minimum (a grazing contact,
/// an entry and an exit close together, or a near miss): the minimum is found first, by
/// Newton on the slope; if the gap is negative there, the entry lies between the eighth's
/// start and it; if not, and the minimum has converged and every later eighth is proven
/// positive, the window holds no contact. Without the Newton steps where the window holds no
/// isolated eighth (most pairs that reach the search); the batch's lane twin
/// (`batch/moving_entry_lanes.rs`) takes every step in every lane: the same answer.
pub(crate) fn while_moving_one(pair: &PairInput) -> WhileMoving {
    // The level of the batch (or the process): `simd`'s one dispatch point.
    crate::simd::dispatch_scalar(crate::simd::current(), WhileMovingOne(pair))
}

/// [`while_moving_one`]'s argument, run by [`crate::simd::dispatch_scalar`].
struct WhileMovingOne<'a>(&'a PairInput);

impl crate::simd::Kernel for WhileMovingOne<'_> {
    type Output = WhileMoving;

    #[inline(always)]
    fn run<S: crate::simd::Simd>(self, _: S) -> WhileMoving {
        while_moving_one_portable(self.0)
    }
}

#[inline(always)]
fn while_moving_one_portable(pair: &PairInput) -> WhileMoving {
    let nothing = WhileMoving {
        entry: f64::NAN,
        screened_out: false,
    };
    let window = FirstWindow::of(pair);
    let start = at_start(&window, pair.t_max);
    if !start.is_nan() {
        return WhileMoving {
            entry: start,
            screened_out: false,
        };
    }
    // A window proven positive whole has no entry, which the search finds at once: `settle`
    // would find no entry there either (at most that there is none, which the search then
    // takes the same way).
    if !window.qualifies || window_screened_out_at_once(&window.gap, window.end) {
        return nothing;
    }
    let eighth = first_open_eighth(&window.gap, window.end);
    if !(eighth.one_root | eighth.one_dip) {
        return nothing; // what `settle` finds for these
    }
    settle(pair, &window, &eighth)
}

/// [`while_moving_one`]'s work on the first open eighth.
#[inline(always)]
fn settle(pair: &PairInput, window: &FirstWindow, eighth: &OpenEighth) -> WhileMoving {
    let found = eighth_entry(&window.gap, window.end, eighth, window.qualifies);
    let t = found.entry * window.unit;
    let entry = match (found.found, t < pair.t_max) {
        (true, true) => t,
        (true, false) => f64::INFINITY,
        (false, _) => f64::NAN,
    };
    let start = at_start(window, pair.t_max);
    WhileMoving {
        entry: if start.is_nan() { entry } else { start },
        screened_out: found.screened_out,
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::prefilter::test_support::{moving_ball, pair, pair_of, search};
    use crate::test_rng::Rng;

    #[test]
    fn a_head_on_contact_is_settled() {
        // 1 apart, closing at 4 m/s and both braking at 1 m/s²: |d| = 1 − 4t + t² = 0.1.
        let t = while_moving_one(&pair([0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [-2.0, 0.0])).entry;
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
        assert_eq!(while_moving_one(&closing).entry, 0.0);
        assert_eq!(while_moving_one(&closing).entry, 0.0);
        assert_eq!(search(&closing), Some(0.0));
        let no_time = PairInput {
            t_max: 0.0,
            ..closing
        };
        // No time at all: the contact at 0 is cut by the horizon, as the search cuts it.
        assert_eq!(while_moving_one(&no_time).entry, f64::INFINITY);
        assert_eq!(while_moving_one(&no_time).entry, f64::INFINITY);
        assert_eq!(search(&no_time), None);
        let parting = pair([0.0, 0.0], [-1.0, 0.0], [0.05, 0.0], [1.0, 0.0]);
        assert!(while_moving_one(&parting).entry.is_nan());
        assert!(while_moving_one(&parting).entry.is_nan());
    }

    #[test]
    fn what_is_not_isolated_is_left_to_the_search() {
        // Apart for ever, a ball at rest, a grazing pass: not settled here.
        for p in [
            pair([0.0, 0.0], [1.0, 0.0], [0.0, 5.0], [1.0, 0.0]),
            pair([0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [0.0, 0.0]),
            pair([0.0, 0.0], [2.0, 0.0], [1.0, 0.1 - 1e-12], [0.0, 0.0]),
        ] {
            assert!(while_moving_one(&p).entry.is_nan(), "{p:?}");
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
            let t = while_moving_one(&p).entry;
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
