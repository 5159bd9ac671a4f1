//! Balls parting throughout a window: the distance between their centres grows on all of it,
//! so the gap has no entry there.
//!
//! A pair that has just collided is searched again from the collision, touching and parting.
//! With friction its window runs until the first of the two stops, often hundreds of times
//! the motion's time scale: its first open eighth is not isolated (the window is long, and
//! it starts at a root), and the window search proves it apart piece by piece, the most
//! costly answer a pair gets (on 16 friction balls in a box, a quarter of the windows
//! searched, half the search's time). One bound settles it: with the window's time scaled
//! to `u ∈ [0, 1]`, `½·g′ = d·d′` is the cubic
//!
//! `d·v + (|v|² + d·a)·u + (3/2)(v·a)·u² + ½|a|²·u³`
//!
//! (`d`, `v`, `a` the separation, relative velocity and relative acceleration at the window's
//! start), and its four Bernstein coefficients bound it from below on `[0, 1]`. All four
//! positive by far more than their rounding prove the distance increasing on the whole
//! window.

use super::entry::WindowSearch;
use crate::gap::Gap;

/// How far above the scale of its rounding (the same sum over the terms' magnitudes) a
/// Bernstein coefficient must be: far beyond the few roundings that form it.
const MARGIN: f64 = 1.0 / (1u64 << 40) as f64;

/// The least scale of the first coefficient (`d·v` in the window's time): below it, terms
/// that underflow could lose more than the margin.
const LEAST_SCALE: f64 = 1.0 / (1u128 << 100) as f64 / (1u128 << 100) as f64;

/// No entry on a window of `length` (finite, > 0) whose balls part throughout it, if they
/// end it clearly apart and do not start it in an entry: `NoEntry`, ending positive, what
/// the window search would find. `None` leaves the window to the search: the distance not
/// proven increasing, an overlap just after being apart (an entry at the start, for the
/// search to report), or a gap at the end within a margin of its rounding.
#[inline(always)]
pub(crate) fn parting_window<const D: usize>(
    gap: &Gap<D>,
    length: f64,
    previous_positive: bool,
) -> Option<WindowSearch> {
    if !(length > 0.0 && length.is_finite()) {
        return None;
    }
    let scaled = gap.time_scaled(length);
    if !parting_throughout(&scaled) {
        return None;
    }
    let entry_at_start = previous_positive && scaled.value(0.0) < 0.0;
    // (Scaled, the window ends at 1.)
    let clearly_apart_at_end = scaled.value(1.0) > scaled.value_noise() / MARGIN;
    (!entry_at_start && clearly_apart_at_end).then_some(WindowSearch::NoEntry {
        ends_positive: true,
    })
}

/// Whether the distance of `gap` (time scaled to the window, `u ∈ [0, 1]`) grows on the whole
/// window: the four Bernstein coefficients of `½·g′` each above [`MARGIN`] times its terms'
/// magnitudes (a NaN or an overflow fails).
#[inline(always)]
fn parting_throughout<const D: usize>(gap: &Gap<D>) -> bool {
    let (d, v, a) = (&gap.offset, &gap.velocity, &gap.acceleration);
    // The cubic's power coefficients `k`, and their terms' magnitudes `m`.
    let (mut k, mut m) = ([0.0f64; 4], [0.0f64; 4]);
    for i in 0..D {
        let (dv, da, vv, va, aa) = (
            d[i] * v[i],
            d[i] * a[i],
            v[i] * v[i],
            v[i] * a[i],
            a[i] * a[i],
        );
        k[0] += dv;
        m[0] += dv.abs();
        k[1] += vv + da;
        m[1] += vv + da.abs();
        k[2] += va;
        m[2] += va.abs();
        k[3] += aa;
        m[3] += aa;
    }
    let (k2, m2) = (1.5 * k[2], 1.5 * m[2]);
    let (k3, m3) = (0.5 * k[3], 0.5 * m[3]);
    let third = 1.0 / 3.0;
    let bernstein = [
        k[0],
        k[0] + k[1] * third,
        k[0] + (2.0 * k[1] + k2) * third,
        k[0] + k[1] + k2 + k3,
    ];
    let scale = [
        m[0],
        m[0] + m[1] * third,
        m[0] + (2.0 * m[1] + m2) * third,
        m[0] + m[1] + m2 + m3,
    ];
    m[0] >= LEAST_SCALE
        && bernstein
            .iter()
            .zip(&scale)
            .all(|(&b, &s)| b > MARGIN * s && s.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::entry::first_entry;
    use nalgebra::Vector2;

    fn gap(d: [f64; 2], v: [f64; 2], a: [f64; 2], r: f64) -> Gap<2> {
        Gap {
            offset: Vector2::from(d),
            velocity: Vector2::from(v),
            acceleration: Vector2::from(a),
            contact_distance: r,
        }
    }

    /// The distance sampled densely over the window: whether it grows.
    fn grows(g: &Gap<2>, length: f64) -> bool {
        (1..=4096).all(|k| {
            let (s0, s1) = (
                length * f64::from(k - 1) / 4096.0,
                length * f64::from(k) / 4096.0,
            );
            g.separation(s1).norm() > g.separation(s0).norm()
        })
    }

    #[test]
    fn a_pair_parting_after_a_collision_is_settled_as_the_search_settles_it() {
        // Touching (within rounding) and parting, both decelerating in different directions,
        // over a window of 54 time units (from the calendar on 16 friction balls).
        let g = gap(
            [0.00013219971581733114, -0.0009675730212981692],
            [0.007175780272769007, -0.01674681639752193],
            [-8.866357172286834e-5, 5.639958822242368e-5],
            0.0009765625,
        );
        let length = 54.26632710093588;
        assert!(grows(&g, length));
        for before in [false, true] {
            let settled = parting_window(&g, length, before);
            assert_eq!(
                settled,
                Some(WindowSearch::NoEntry {
                    ends_positive: true
                })
            );
            let scaled = g.time_scaled(length);
            assert_eq!(settled, Some(first_entry(&scaled, 1.0, before)));
        }
    }

    #[test]
    fn approaching_or_turning_back_is_left_to_the_search() {
        let length = 10.0;
        // Approaching at the start.
        let g = gap([1.0, 0.0], [-0.1, 0.0], [0.0, 0.0], 0.5);
        assert_eq!(parting_window(&g, length, true), None);
        // Parting, then pulled back: the relative acceleration turns the velocity round.
        let g = gap([1.0, 0.0], [0.1, 0.0], [-0.05, 0.0], 0.5);
        assert!(!grows(&g, length));
        assert_eq!(parting_window(&g, length, true), None);
        // Parting throughout, but an overlap right after being apart: an entry at the start.
        let g = gap([0.4, 0.0], [0.1, 0.0], [0.0, 0.0], 0.5);
        assert_eq!(parting_window(&g, length, true), None);
        assert_eq!(
            parting_window(&g, length, false),
            Some(WindowSearch::NoEntry {
                ends_positive: true
            })
        );
        // Parting, but still within the contact distance at the end.
        let g = gap([0.4, 0.0], [1e-3, 0.0], [0.0, 0.0], 0.5);
        assert_eq!(parting_window(&g, length, false), None);
    }

    #[test]
    fn windows_that_start_touching_get_the_answer_of_the_eighth_first() {
        // `eighth_then_search` tries the parting bound before the eighth on such windows:
        // the answer must be what the eighth, then the parting bound, then the search give.
        use crate::collision::eighth_entry::window_eighth;
        use crate::collision::{SettledBy, eighth_then_search};
        let mut rng = crate::test_rng::Rng(41);
        let (mut parted, mut entered) = (0, 0);
        for n in 0..20_000 {
            let r = rng.uniform(0.01, 1.0);
            let angle = rng.uniform(0.0, std::f64::consts::TAU);
            // Touching, within 2⁻¹² of the contact distance either way.
            let scale = r * (1.0 + rng.uniform(-1.0, 1.0) / 4096.0);
            let d = [scale * angle.cos(), scale * angle.sin()];
            let v = [rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)];
            let a = [rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1)];
            let length = rng.uniform(0.01, 100.0);
            let g = gap(d, v, a, r);
            let before = n % 2 == 0;
            let (answer, by) = eighth_then_search(&g, length, before);
            let eighth = window_eighth(&g, length, before);
            let old = if eighth.found {
                WindowSearch::Entry(eighth.entry)
            } else if eighth.screened_out {
                WindowSearch::NoEntry {
                    ends_positive: true,
                }
            } else if let Some(none) = parting_window(&g, length, before) {
                none
            } else {
                crate::collision::search_window(&g, length, before)
            };
            assert_eq!(answer, old, "{g:?} over {length}, before {before}");
            parted += usize::from(by == SettledBy::Parting);
            entered += usize::from(matches!(answer, WindowSearch::Entry(_)));
        }
        assert!(
            parted > 2_000 && entered > 2_000,
            "{parted} parted, {entered} entered"
        );
    }

    #[test]
    fn random_windows_it_settles_grow_and_agree_with_the_search() {
        let mut rng = crate::test_rng::Rng(7);
        let mut settled = 0;
        for _ in 0..20_000 {
            let r = rng.uniform(0.01, 1.0);
            let angle = rng.uniform(0.0, std::f64::consts::TAU);
            let d = [r * angle.cos(), r * angle.sin()];
            let v = [rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)];
            let a = [rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1)];
            let length = rng.uniform(0.01, 100.0);
            let g = gap(d, v, a, r * (1.0 - 1e-15));
            let before = rng.uniform(0.0, 1.0) < 0.5;
            if let Some(answer) = parting_window(&g, length, before) {
                settled += 1;
                assert!(grows(&g, length), "{g:?} over {length}");
                let scaled = g.time_scaled(length);
                assert_eq!(
                    answer,
                    first_entry(&scaled, 1.0, before),
                    "{g:?} over {length}"
                );
            }
        }
        assert!(settled > 2_000, "only {settled} settled");
    }
}
