//! Relative motion along a straight line: closed forms. One friction ball at rest and the other
//! moving ([`first_contact`], [`contact`]); and a window of two paths with no relative
//! acceleration, the separation moving at constant velocity ([`straight_window`]).
//!
//! The mover runs along a straight line, so the separation is `d = Δ + v·σ`, with
//! `σ(t) = t − t²/(2τ)` the time it would take at its initial speed to cover what it has
//! covered (increasing until it stops at `τ`, where `σ = τ/2`). The gap is then a quadratic in
//! `σ`, `G(σ) = |v|²σ² + 2(Δ·v)σ + |Δ|² − r²`, whose smaller root is the contact if it comes
//! before the stop; `t` follows from `σ` in a form without cancellation. This replaces two
//! root searches (critical point and entry) by three square roots and one division.

use super::entry::WindowSearch;
use crate::gap::{Gap, gap_value_of};
use crate::motion::Ball;

/// How decisive the closed form of [`straight_window`] must be, relative to the magnitudes
/// involved, before it answers instead of the search: far above its few roundings.
const DECISIVE: f64 = 1.0 / ((1u64 << 30) as f64);

/// The first contact when exactly one ball is at rest and the balls are apart at the start
/// (`g0 = |Δ|² − r² > 0`, as computed by the general search); `None` when the closed form
/// does not apply (no ball or both at rest, magnitudes where squares could overflow or
/// underflow), leaving the general search to answer.
///
/// Depends on the A/B order only through which ball moves, and on the axes only through
/// sums of products in which swapping or negating axes changes nothing, bit for bit.
pub(crate) fn first_contact(
    a: &Ball,
    b: &Ball,
    radius: f64,
    t_max: f64,
    g0: f64,
) -> Option<Option<f64>> {
    let (mover, rest) = match (a.is_at_rest(), b.is_at_rest()) {
        (false, true) => (a, b),
        (true, false) => (b, a),
        _ => return None,
    };
    let delta = mover.position() - rest.position();
    let v = mover.velocity();
    let (applies, t) = contact([delta.x, delta.y], [v.x, v.y], mover.friction(), radius, g0);
    applies.then_some((t < t_max).then_some(t))
}

/// The closed form proper, for a mover at `Δ` from the resting ball with velocity `v` and
/// friction `μ`: whether it applies, and the contact time (`∞` for none).
///
/// Branch-free (choices are selects), so that the batch evaluates it lane-wise; the scalar
/// [`first_contact`] calls the same function. Three square roots and one division.
#[inline(always)]
pub(crate) fn contact(delta: [f64; 2], v: [f64; 2], mu: f64, radius: f64, g0: f64) -> (bool, f64) {
    let [dx, dy] = delta;
    let [vx, vy] = v;
    let speed2 = vx * vx + vy * vy;
    // Products of up to six lengths or speeds (E·(E − m) below: E is a length times |v|²)
    // stay in the normal range for these magnitudes; elsewhere the general search, which
    // scales, answers.
    let in_range = (1e-100..=1e100).contains(&speed2)
        & (1e-50..=1e50).contains(&radius)
        & (dx.abs().max(dy.abs()) <= 1e50)
        & (g0 > 0.0);
    // With σ = s/|v| (time, slowed by friction: σ = t − t²/(2τ)), d = Δ + v·σ and
    // G = |v|²σ² + 2(Δ·v)σ + g0: no unit vector (and its roundings) is needed.
    // G′(0)/2 = Δ·v: not approaching (G convex) means no contact ever.
    let approach = dx * vx + dy * vy;
    // G's discriminant/4 = |v|²·(r² − h²) = (r|v|)² − |Δ×v|², h the line's distance from
    // the resting centre: ≤ 0 when the line passes outside or exactly tangent. Formed without
    // |v| (the difference fused), so that its square root runs beside |v|'s.
    let cross = dx * vy - dy * vx;
    let disc = (radius * radius).mul_add(speed2, -cross * cross);
    let speed = speed2.sqrt();
    let meets = (approach < 0.0) & (disc > 0.0);
    // The smaller root, without cancellation (approach < 0): σ = g0/D.
    let d = disc.max(0.0).sqrt() - approach;
    // In E = D·|v| and m = 2·g0·μ the contact comes before the stop (σ < τ/2 = |v|/(2μ))
    // when E > m, and σ = t − t²/(2τ) gives t = 2σ/(1 + √(1 − m/E)), that is
    // t = 2·g0/(E + √(E·(E − m)))·|v|: one division, and no root waits for another division.
    let e = d * speed;
    let m = 2.0 * g0 * mu;
    let before_stop = e > m;
    let t = (2.0 * g0) / (e + (e * (e - m)).max(0.0).sqrt()) * speed;
    // A contact whose time overflowed, or whose E is so small that E·(E − m) could lose
    // digits to underflow, is left to the general search (E·(E − m) stays below the overflow
    // for the magnitudes `in_range` admits).
    let settled = !meets | !before_stop | (t.is_finite() & (e >= 1e-100));
    let hit = meets & before_stop;
    (in_range & settled, if hit { t } else { f64::INFINITY })
}

/// The first entry on a window of `length` (time since its start, `∞` allowed) where the
/// relative acceleration is zero, so that the separation `d + v·s` runs along a straight line
/// at constant speed and the gap is the quadratic `|v|²s² + 2(d·v)s + g₀`: its smaller root,
/// `s = g₀ / (√D − d·v)` with `D = (r|v|)² − |d × v|²`, without cancellation. For balls apart
/// at the start (and the gap positive just `before` it), where every decision is clear by far
/// ([`DECISIVE`]); and for balls clearly receding on a window that lasts for ever, whatever the
/// gap (no entry, nor re-entry), unless it starts negative after being positive. `None` leaves
/// the window to the search (near grazing, a root near the window's end, touching at the
/// start, magnitudes where squares could overflow or underflow).
///
/// For frictionless balls (a particle in a box, a disk on an air table) every window is one;
/// rolling balls side by side with one acceleration too. Symmetric in A and B and in the axes,
/// bit for bit (products of two negated numbers; sums over the axes in their order), and a
/// 2-D motion embedded in 3-D with a zero third component gives the 2-D bits. Inlined into
/// each copy of the path search (its fused multiply-add one instruction in the FMA copy).
#[inline(always)]
pub(crate) fn straight_window<const D: usize>(
    gap: &Gap<D>,
    length: f64,
    before: bool,
) -> Option<WindowSearch> {
    // (A NaN length or value fails the comparisons: not straight, or not in range.)
    if gap.acceleration.iter().any(|&a| a != 0.0) || length.is_nan() || length <= 0.0 {
        return None;
    }
    let (d, v, radius) = (&gap.offset, &gap.velocity, gap.contact_distance);
    let speed2 = v.norm_squared();
    let size2 = d.norm_squared() + radius * radius;
    let in_range =
        (1e-100..=1e100).contains(&speed2) && (1e-50..=1e50).contains(&radius) && d.amax() <= 1e50;
    if !in_range {
        return None;
    }
    let g0 = gap_value_of(d, radius);
    let approach = d.dot(v);
    let apart = WindowSearch::NoEntry {
        ends_positive: true,
    };
    // Clearly receding on the last window (balls that have just collided, say): the gap only
    // grows, so there is no entry, nor re-entry; unless it was positive just before and starts
    // negative, an entry at the start, which the search reports.
    let receding = approach > 0.0 && approach * approach > DECISIVE * DECISIVE * speed2 * size2;
    if length == f64::INFINITY && receding && (!before || g0 > 0.0) {
        return Some(apart);
    }
    let clearly_apart = g0 > DECISIVE * size2;
    if !before || !clearly_apart {
        return None;
    }
    // Receding, or passing clearly outside: the gap stays above its least value, positive.
    let mut cross2 = 0.0;
    for i in 0..D {
        for j in i + 1..D {
            let c = d[i] * v[j] - d[j] * v[i];
            cross2 += c * c;
        }
    }
    let reach2 = radius * radius * speed2;
    let disc = (radius * radius).mul_add(speed2, -cross2);
    let apart = WindowSearch::NoEntry {
        ends_positive: true,
    };
    if approach >= 0.0 || disc < -DECISIVE * reach2 {
        return Some(apart);
    }
    if disc <= DECISIVE * reach2 {
        return None; // grazing: the search decides
    }
    let s = g0 / (disc.sqrt() - approach);
    if s < length * (1.0 - DECISIVE) {
        Some(WindowSearch::Entry(s))
    } else if s > length * (1.0 + DECISIVE) {
        Some(apart)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;

    fn shot(scale: f64) -> Option<Option<f64>> {
        let (Ok(a), Ok(b)) = (
            Ball::new(
                Vector2::new(0.0, 0.0),
                Vector2::new(2.0, 0.3) * scale,
                0.2 * scale,
            ),
            Ball::at_rest(Vector2::new(1.0, 0.1) * scale),
        ) else {
            panic!("valid balls")
        };
        let radius = 0.05715 * scale;
        let d = a.position() - b.position();
        let g0 = d.norm_squared() - radius * radius;
        first_contact(&a, &b, radius, f64::INFINITY, g0)
    }

    #[test]
    fn a_shot_at_a_resting_ball_is_solved_in_closed_form() {
        let t = shot(1.0).flatten().unwrap_or(f64::NAN);
        // A covers 2t − 0.1t² along its line, a distance the contact geometry fixes.
        assert!(t > 0.4 && t < 0.5, "{t}");
        assert_eq!(shot(0.5), shot(1.0)); // power-of-two units: the same bits
    }

    #[test]
    fn tiny_and_huge_units_are_left_to_the_general_search() {
        // Regression: at 1e-150 the discriminant (four lengths multiplied) underflowed to 0
        // and the closed form reported a miss.
        assert_eq!(shot(1e-150), None);
        assert_eq!(shot(1e150), None);
        assert!(shot(1e-30).flatten().is_some());
    }

    fn straight(d: [f64; 2], v: [f64; 2], radius: f64, length: f64) -> Option<WindowSearch> {
        let gap = Gap {
            offset: Vector2::from(d),
            velocity: Vector2::from(v),
            acceleration: Vector2::zeros(),
            contact_distance: radius,
        };
        straight_window(&gap, length, true)
    }

    #[test]
    fn a_straight_window_is_solved_in_closed_form_when_it_is_clear() {
        // Head on from 2 at 1 m/s, radius 0.5: contact at 1.5.
        assert_eq!(
            straight([2.0, 0.0], [-1.0, 0.0], 0.5, f64::INFINITY),
            Some(WindowSearch::Entry(1.5))
        );
        // The same, the window ending before it, or just after: no entry, or left to the search.
        let apart = Some(WindowSearch::NoEntry {
            ends_positive: true,
        });
        assert_eq!(straight([2.0, 0.0], [-1.0, 0.0], 0.5, 1.0), apart);
        assert_eq!(straight([2.0, 0.0], [-1.0, 0.0], 0.5, 1.5), None);
        // Receding, and passing 0.6 wide: apart.
        assert_eq!(straight([2.0, 0.0], [1.0, 0.0], 0.5, f64::INFINITY), apart);
        assert_eq!(straight([2.0, 0.6], [-1.0, 0.0], 0.5, f64::INFINITY), apart);
        // Grazing (passing 0.5 wide exactly), touching at the start, or accelerating: the search.
        assert_eq!(straight([2.0, 0.5], [-1.0, 0.0], 0.5, f64::INFINITY), None);
        assert_eq!(straight([0.5, 0.0], [-1.0, 0.0], 0.5, f64::INFINITY), None);
        let accelerating = Gap {
            offset: Vector2::new(2.0, 0.0),
            velocity: Vector2::new(-1.0, 0.0),
            acceleration: Vector2::new(0.1, 0.0),
            contact_distance: 0.5,
        };
        assert_eq!(straight_window(&accelerating, 1.0, true), None);
    }

    #[test]
    fn balls_receding_for_ever_never_meet_again_even_from_touching() {
        let gap = |d: [f64; 2], v: [f64; 2]| Gap {
            offset: Vector2::from(d),
            velocity: Vector2::from(v),
            acceleration: Vector2::zeros(),
            contact_distance: 0.5,
        };
        let apart = Some(WindowSearch::NoEntry {
            ends_positive: true,
        });
        // Just collided: touching (or overlapping by rounding) and moving apart.
        let touching = gap([0.5, 0.0], [1.0, 0.2]);
        assert_eq!(straight_window(&touching, f64::INFINITY, false), apart);
        let overlapping = gap([0.49, 0.0], [1.0, 0.2]);
        assert_eq!(straight_window(&overlapping, f64::INFINITY, false), apart);
        // Overlapping right after being apart: an entry at the start, for the search.
        assert_eq!(straight_window(&overlapping, f64::INFINITY, true), None);
        // A finite window, or an overlap that is not clearly opening: the search.
        assert_eq!(straight_window(&touching, 1.0, false), None);
        assert_eq!(
            straight_window(&gap([0.5, 0.0], [0.0, 1.0]), f64::INFINITY, false),
            None
        );
    }

    #[test]
    fn only_one_ball_at_rest_qualifies() {
        let (Ok(a), Ok(b)) = (
            Ball::new(Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), 0.1),
            Ball::new(Vector2::new(1.0, 0.0), Vector2::new(-1.0, 0.0), 0.1),
        ) else {
            panic!("valid balls")
        };
        assert_eq!(first_contact(&a, &b, 0.1, f64::INFINITY, 0.99), None);
        let (Ok(c), Ok(d)) = (
            Ball::at_rest(Vector2::new(0.0, 0.0)),
            Ball::at_rest(Vector2::new(1.0, 0.0)),
        ) else {
            panic!("valid balls")
        };
        assert_eq!(first_contact(&c, &d, 0.1, f64::INFINITY, 0.99), None);
    }
}
