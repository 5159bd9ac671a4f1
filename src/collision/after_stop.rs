//! After the first ball stops: the other runs on along a straight line, into or past a ball
//! at rest, which the closed form of [`straight`](super::straight) settles.
//!
//! On a table, a third of the contacts between two moving balls come after one of them has
//! stopped (the second window). The relative motion there is the mover's alone, so the
//! search's quartic is not needed: the gap from the first stop on (the search's own
//! `Gap::between(a, b, r, t₁)`) goes to the closed form, with the mover's friction. Single
//! queries and batches both call [`after_first_stop`], so both give the same bits.

use super::crossing::FirstWindow;
use super::prefilter::PairInput;
use super::straight;
use crate::gap::Gap;
use crate::motion::Ball;

/// The first contact from the first stop on, for balls `a` and `b` whose first window holds
/// none: its time (`∞` for none, or at or past the horizon), where the closed form settles it.
///
/// Returns whether it applies: both balls move and stop at different times, and the closed
/// form applies (apart at the first stop, magnitudes in its range). Its range is the closed
/// form's alone, so that scaling every input by a power of two changes nothing. Branch-free
/// apart from what the compiler turns into selects, so that a batch runs it lane-wise.
#[inline(always)]
pub(crate) fn after_first_stop(a: &Ball, b: &Ball, radius: f64, t_max: f64) -> (bool, f64) {
    let (tau_a, tau_b) = (a.stop_time(), b.stop_time());
    let t1 = tau_a.min(tau_b);
    let gap = Gap::between(a, b, radius, t1);
    // The mover is the ball that stops later. `straight::contact` wants it against the
    // resting ball; the offset and velocity here are A's against B's, which (both negated
    // when B moves) give the same products, bit for bit.
    let mu = if tau_a < tau_b {
        b.friction()
    } else {
        a.friction()
    };
    let (applies, t) = straight::contact(
        [gap.offset.x, gap.offset.y],
        [gap.velocity.x, gap.velocity.y],
        mu,
        radius,
        gap.value(0.0),
    );
    let t = t1 + t;
    let moving = (t1 > 0.0) & t1.is_finite() & (tau_a != tau_b);
    (moving & applies, if t < t_max { t } else { f64::INFINITY })
}

/// [`after_first_stop`] for a pair of the lane-wise tests (whose stop times its first window
/// holds); it does not apply where the pair does not qualify for them.
#[inline(always)]
pub(crate) fn after_first_stop_of(pair: &PairInput, window: &FirstWindow) -> (bool, f64) {
    let [tau_a, tau_b] = window.tau;
    let a = Ball::from_parts(pair.pos_a, pair.vel_a, pair.friction_a, tau_a);
    let b = Ball::from_parts(pair.pos_b, pair.vel_b, pair.friction_b, tau_b);
    let (applies, t) = after_first_stop(&a, &b, pair.radius, pair.t_max);
    (window.qualifies & applies, t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::prefilter::test_support::{moving_ball, pair, pair_of, search};
    use crate::test_rng::Rng;

    #[test]
    fn a_runner_hits_a_stopped_ball() {
        // B stops at 0.5 (at x = 1.25); A, slower to stop, reaches it later.
        let p = PairInput {
            friction_a: 0.5,
            friction_b: 2.0,
            ..pair([0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [1.0, 0.0])
        };
        let (applies, t) = after_first_stop_of(&p, &FirstWindow::of(&p));
        assert!(applies);
        // A covers 2t − t²/4 = 1.25 − 0.1.
        let exact = 4.0 - (16.0f64 - 4.0 * 1.15).sqrt();
        assert!(
            (t - exact).abs() <= 4.0 * f64::EPSILON * exact,
            "{t} {exact}"
        );
        assert_eq!(search(&p), Some(t));
    }

    #[test]
    fn where_it_applies_it_is_the_search_of_the_second_window() {
        // Random moving pairs at scales 1e-6 to 1e6 whose first window is screened out: where
        // the closed form applies, the search (which calls it) agrees with it, and the window
        // search it replaces agrees to within the floor of the problem.
        let mut rng = Rng(0xa5);
        let mut checked = 0;
        for _ in 0..20_000 {
            let scale = 10f64.powf(rng.uniform(-6.0, 6.0));
            let (a, b) = (moving_ball(&mut rng, scale), moving_ball(&mut rng, scale));
            let p = pair_of(a, b, rng.uniform(0.05, 0.5) * scale, f64::INFINITY);
            let window = FirstWindow::of(&p);
            let (applies, t) = after_first_stop_of(&p, &window);
            let first = crate::collision::crossing::apart_by_window(&p).0;
            if !(applies & first) {
                continue;
            }
            checked += 1;
            assert_eq!(search(&p).unwrap_or(f64::INFINITY), t, "{p:?}");
            let reference = second_window_search(&p);
            match reference {
                Some(r) => {
                    let tol = 1e-9 * r.abs().max(window.tau[0].max(window.tau[1]));
                    assert!((t - r).abs() <= tol, "{p:?}: {t} vs {r}");
                }
                None => assert!(t.is_infinite(), "{p:?}: {t} vs none"),
            }
        }
        assert!(checked > 500, "only {checked} checked");
    }

    /// The second window's contact by the general window search (which does not call the
    /// closed form).
    fn second_window_search(p: &PairInput) -> Option<f64> {
        use crate::collision::entry::{WindowSearch, first_entry};
        let window = FirstWindow::of(p);
        let [ta, tb] = window.tau;
        let (t1, t2) = (ta.min(tb), ta.max(tb));
        let a = Ball::from_parts(p.pos_a, p.vel_a, p.friction_a, ta);
        let b = Ball::from_parts(p.pos_b, p.vel_b, p.friction_b, tb);
        let gap = Gap::between(&a, &b, p.radius, t1);
        let unit = crate::collision::normal_time_unit(t2 - t1);
        match first_entry(&gap.time_scaled(unit), (t2 - t1) / unit, true) {
            WindowSearch::Entry(u) => Some(t1 + u * unit),
            WindowSearch::NoEntry { .. } => None,
        }
    }
}
