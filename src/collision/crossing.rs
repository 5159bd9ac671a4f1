//! Two moving balls whose paths cross: a lane-wise proof that they are never there at the
//! same time.
//!
//! The [`prefilter`](super::prefilter) settles pairs whose paths stay apart; of the rest, on a
//! table, only one in four or five ever touches: the others cross paths at different times.
//! This test settles most of those, still without a branch, so that a batch runs it on
//! blocks of the prefilter's survivors and leaves the search only a few pairs beyond the
//! contacts themselves:
//!
//! - on the first window (both balls moving), the search's own Bernstein test
//!   ([`window_screened_out`]) on the very window the search would build, bit for bit, so the
//!   search can only agree;
//! - on the second window one ball rests at its stopping point while the other runs on
//!   along a straight segment: the distance from that point to that segment, against the
//!   contact distance and a margin far above every rounding error made here and in the
//!   search. That settles the rest of time too (both at rest from the end of the segment).

use nalgebra::Vector2;

use super::exclusion::window_screened_out;
use super::long_window::long_window;
use super::prefilter::{LIMIT, MARGIN, PairInput, valid};
use super::{LONGEST_WINDOW, normal_time_unit};
use crate::gap::Gap;

/// The first window of two moving balls with friction, `[0, min(τ_A, τ_B)]`, exactly as
/// [`first_contact`](super::first_contact) builds and scales it.
pub(crate) struct FirstWindow {
    /// Whether the pair qualifies for the lane-wise tests: valid, both balls moving with
    /// friction, every magnitude in range ([`LIMIT`]), a window of normal length.
    pub qualifies: bool,
    /// The relative motion from time 0, in seconds: the search's own `Gap::between(a, b, r, 0)`.
    pub initial: Gap,
    /// The same, time in units of [`FirstWindow::unit`].
    pub gap: Gap,
    /// The window's end in those units (`≤ 1`).
    pub end: f64,
    /// The time unit, a power of two.
    pub unit: f64,
    /// The stop times.
    pub tau: [f64; 2],
}

impl FirstWindow {
    /// The first window of `pair`.
    #[inline(always)]
    pub(crate) fn of(pair: &PairInput) -> Self {
        let [vax, vay] = pair.vel_a;
        let [vbx, vby] = pair.vel_b;
        let (mu_a, mu_b, radius) = (pair.friction_a, pair.friction_b, pair.radius);
        // Speeds and stop times as `Ball::new` forms them (|v|² in this range takes its
        // square root), so that the window below is the search's own.
        let (square_a, square_b) = (vax * vax + vay * vay, vbx * vbx + vby * vby);
        let (speed_a, speed_b) = (square_a.sqrt(), square_b.sqrt());
        let (tau_a, tau_b) = (speed_a / mu_a, speed_b / mu_b);
        let in_range = |x: f64| (1.0 / LIMIT..=LIMIT).contains(&x);
        // The window the search searches: the horizon plays no part in it (it only cuts the
        // answer), so that a contact before the horizon comes back bit for bit as without one.
        let length = tau_a.min(tau_b).min(LONGEST_WINDOW);
        let qualifies = valid(pair)
            & in_range(square_a)
            & in_range(square_b)
            & in_range(mu_a)
            & in_range(mu_b)
            & (pair.pos_a[0].abs().max(pair.pos_a[1].abs()) <= LIMIT)
            & (pair.pos_b[0].abs().max(pair.pos_b[1].abs()) <= LIMIT)
            & in_range(radius)
            & (length >= f64::MIN_POSITIVE);
        let unit = normal_time_unit(length);
        let initial = Gap {
            offset: Vector2::new(pair.pos_a[0] - pair.pos_b[0], pair.pos_a[1] - pair.pos_b[1]),
            velocity: Vector2::new(vax - vbx, vay - vby),
            acceleration: Vector2::new(-vax / tau_a - -vbx / tau_b, -vay / tau_a - -vby / tau_b),
            contact_distance: radius,
        };
        // A long window is searched in pieces, which the lanes leave to the search.
        let qualifies = qualifies & !long_window(&initial, length);
        Self {
            qualifies,
            initial,
            gap: initial.time_scaled(unit),
            end: length / unit,
            unit,
            tau: [tau_a, tau_b],
        }
    }
}

/// Whether two valid moving balls with friction provably never touch. `false` means "not
/// proven" (and is the answer for inputs that do not qualify: a ball at rest or without
/// friction, magnitudes out of range, a horizon of 0). The batch takes the two
/// proofs apart ([`apart_by_window`]); the tests take them together.
#[cfg(test)]
pub(crate) fn screened_out_by_crossing(pair: &PairInput) -> bool {
    let (first, second) = apart_by_window(pair);
    first & second
}

/// `screened_out_by_crossing`'s proofs one window at a time: the balls never touch while both
/// move (the first window), and never after one has stopped (the second window and after).
/// Each is `false` for inputs that do not qualify.
#[inline(always)]
pub(crate) fn apart_by_window(pair: &PairInput) -> (bool, bool) {
    let [vax, vay] = pair.vel_a;
    let [vbx, vby] = pair.vel_b;
    let (radius, t_max) = (pair.radius, pair.t_max);
    let window = FirstWindow::of(pair);
    let [tau_a, tau_b] = window.tau;
    // A proof up to the horizon is enough: a contact after it is none.
    let first = window_screened_out(&window.gap, window.end.min(t_max / window.unit));

    // The second window: the ball that stops first rests at its stopping point; the other
    // runs on from where it is at that moment to where it stops.
    let a_first = tau_a <= tau_b;
    let pick = |x: f64, y: f64| if a_first { x } else { y };
    let (p_rest, v_rest, tau_rest) = (
        [
            pick(pair.pos_a[0], pair.pos_b[0]),
            pick(pair.pos_a[1], pair.pos_b[1]),
        ],
        [pick(vax, vbx), pick(vay, vby)],
        pick(tau_a, tau_b),
    );
    let (p_run, v_run, tau_run) = (
        [
            pick(pair.pos_b[0], pair.pos_a[0]),
            pick(pair.pos_b[1], pair.pos_a[1]),
        ],
        [pick(vbx, vax), pick(vby, vay)],
        pick(tau_b, tau_a),
    );
    let second = (t_max <= tau_rest)
        | point_clears_segment(p_rest, v_rest, tau_rest, p_run, v_run, tau_run, radius);
    (window.qualifies & first, window.qualifies & second)
}

/// Whether the stopping point of the ball at `p_rest` (velocity `v_rest`, stop time
/// `tau_rest`) is farther than `radius` from the rest of the other ball's path after
/// `tau_rest` (`≤ tau_run`): the points `p_run + v_run·σ`, `σ` from `t(1 − t/(2τ))` at
/// `t = tau_rest` to `τ/2`.
#[inline(always)]
fn point_clears_segment(
    p_rest: [f64; 2],
    v_rest: [f64; 2],
    tau_rest: f64,
    p_run: [f64; 2],
    v_run: [f64; 2],
    tau_run: f64,
    radius: f64,
) -> bool {
    let half = 0.5 * tau_rest;
    let stop = [p_rest[0] + v_rest[0] * half, p_rest[1] + v_rest[1] * half];
    let from = tau_rest * (1.0 - 0.5 * (tau_rest / tau_run));
    let to = 0.5 * tau_run;
    // The point's parameter along the runner's line, clamped to the segment.
    let (wx, wy) = (stop[0] - p_run[0], stop[1] - p_run[1]);
    let along = (wx * v_run[0] + wy * v_run[1]) / (v_run[0] * v_run[0] + v_run[1] * v_run[1]);
    let sigma = along.max(from).min(to);
    let (dx, dy) = (wx - v_run[0] * sigma, wy - v_run[1] * sigma);
    // Every coordinate involved is below `size`; each computed one errs by a few ε of it.
    let end = [p_run[0] + v_run[0] * to, p_run[1] + v_run[1] * to];
    let size = (p_run[0].abs().max(p_run[1].abs()))
        .max(stop[0].abs().max(stop[1].abs()))
        .max(end[0].abs().max(end[1].abs()));
    let clearance = radius + MARGIN * (size + radius);
    dx * dx + dy * dy > clearance * clearance
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::prefilter::test_support::{moving_ball, pair, pair_of, search};
    use crate::test_rng::Rng;

    #[test]
    fn crossing_at_different_times_is_proven() {
        // A crosses x = 2 along y = 0 at about 0.54 s; B, coming up x = 2 from y = −4.5,
        // stops right on A's path, at (2, 0), but only at 3 s, when A is at x = 7.5.
        assert!(screened_out_by_crossing(&pair(
            [0.0, 0.0],
            [4.0, 0.0],
            [2.0, -4.5],
            [0.0, 3.0]
        )));
    }

    #[test]
    fn a_contact_is_never_proven_away() {
        // Head-on along x: they meet.
        assert!(!screened_out_by_crossing(&pair(
            [0.0, 0.0],
            [2.0, 0.0],
            [1.0, 0.0],
            [-2.0, 0.0]
        )));
    }

    #[test]
    fn a_ball_running_into_the_stopped_one_is_caught_on_the_second_window() {
        // A stops at x = 0.5 (after 1 s); B, slower off the mark from x = 3, reaches it later.
        assert!(!screened_out_by_crossing(&PairInput {
            friction_b: 0.25,
            ..pair([0.0, 0.0], [1.0, 0.0], [3.0, 0.0], [-1.5, 0.0])
        }));
    }

    #[test]
    fn pairs_that_do_not_qualify_are_left_to_the_search() {
        let ok = pair([0.0, 0.0], [4.0, 0.0], [2.0, -4.5], [0.0, 3.0]);
        for bad in [
            PairInput {
                vel_b: [0.0, 0.0],
                ..ok
            },
            PairInput {
                friction_a: 0.0,
                ..ok
            },
            PairInput {
                radius: f64::NAN,
                ..ok
            },
            PairInput {
                pos_a: [1e200, 0.0],
                ..ok
            },
        ] {
            assert!(!screened_out_by_crossing(&bad), "{bad:?}");
        }
        // The window is the search's whatever the horizon; the proof needs only reach it.
        assert!(screened_out_by_crossing(&PairInput { t_max: 0.0, ..ok }));
    }

    #[test]
    fn a_proof_is_never_contradicted_by_the_search() {
        // Pairs crossing paths, many of them just missing each other in time or space, at
        // scales from 1e-6 to 1e6: every proof must agree with the search, and most misses
        // must be proven.
        let mut rng = Rng(0xc0ffee);
        let (mut proven, mut misses) = (0, 0);
        for k in 0..20_000 {
            let scale = 10f64.powf(rng.uniform(-6.0, 6.0));
            let ball = |rng: &mut Rng| moving_ball(rng, scale);
            let (a, b) = (ball(&mut rng), ball(&mut rng));
            let input = pair_of(
                a,
                b,
                0.2 * scale * 10f64.powf(-rng.uniform(0.0, 2.0)),
                if k % 7 == 0 {
                    rng.uniform(0.0, 2.0)
                } else {
                    f64::INFINITY
                },
            );
            let found = search(&input).is_some();
            if screened_out_by_crossing(&input) {
                proven += 1;
                assert!(!found, "{input:?}");
            }
            misses += usize::from(!found);
        }
        assert!(
            proven > misses * 3 / 4,
            "{proven} of {misses} misses proven"
        );
    }

    #[test]
    fn a_proof_after_a_stop_holds_where_the_search_looks_hardest() {
        // One ball stops at S early; the other passes S later, its line R·(1 ± δ) from S,
        // δ from 1e-2 down to 1e-15, at scales from 1e-6 to 1e6. Every proof must agree
        // with the search, and most passes clearing S by 1e-10 or more must be proven.
        let mut rng = Rng(0xfade);
        let (mut proven, mut clear) = (0, 0);
        for k in 0..20_000 {
            let scale = 10f64.powf(rng.uniform(-6.0, 6.0));
            let radius = 0.05715 * scale;
            let stop = [
                rng.uniform(-1.0, 1.0) * scale,
                rng.uniform(-1.0, 1.0) * scale,
            ];
            let unit = |angle: f64| [angle.cos(), angle.sin()];
            // The resting ball: 1 m/s, 2 m/s², so 0.25 m in 0.5 s, ending at `stop`.
            let r = unit(rng.uniform(0.0, 6.3));
            let rest_start = [stop[0] - 0.25 * scale * r[0], stop[1] - 0.25 * scale * r[1]];
            // The runner: 3 m before its closest point to S, at 2 m/s slowed at 0.5 m/s²,
            // so it gets there after 2 s and stops 1 m beyond.
            let u = unit(rng.uniform(0.0, 6.3));
            let delta = 10f64.powf(rng.uniform(-15.0, -2.0));
            let aside = radius * (1.0 + if k % 2 == 0 { delta } else { -delta });
            let side = if k % 4 < 2 { aside } else { -aside };
            let closest = [stop[0] - side * u[1], stop[1] + side * u[0]];
            let run_start = [
                closest[0] - 3.0 * scale * u[0],
                closest[1] - 3.0 * scale * u[1],
            ];
            let (a_rests, runner_friction) = (k % 3 == 0, 0.5 * scale);
            let rest = (rest_start, [r[0] * scale, r[1] * scale], 2.0 * scale);
            let run = (
                run_start,
                [2.0 * scale * u[0], 2.0 * scale * u[1]],
                runner_friction,
            );
            let (a, b) = if a_rests { (rest, run) } else { (run, rest) };
            let input = pair_of(a, b, radius, f64::INFINITY);
            if screened_out_by_crossing(&input) {
                proven += 1;
                assert_eq!(search(&input), None, "{input:?}");
            }
            clear += usize::from(aside > radius * (1.0 + 1e-10));
        }
        assert!(
            proven > clear * 3 / 4,
            "{proven} of {clear} clear passes proven"
        );
    }
}
