//! A dip of the gap narrower than the float grid: a contact that no float time can show.
//!
//! Where the contact distance is tiny beside the rest of the motion (`r ≲ 2⁻⁴⁰` of the
//! window's offset, velocity and acceleration), the band of time where `|d(u)| < r` can be
//! narrower than one ulp of `u`, and the float values of `d(u)` carry rounding far larger than
//! `r`: no float time need have a negative gap even for a head-on contact, whose depth is the
//! whole radius. Sampling the gap's sign there (as the window search does, and the eighth
//! entry) reports a miss; and a discriminant formed as `b² − 4ac` loses `r²` beside `|d|²`.
//!
//! The decision is taken instead on a quantity that keeps `r`: at the closest approach, the
//! distance `|d|` equals `|d × d′| / |d′|` (since `|d|²|d′|² = (d·d′)² + |d × d′|²` and
//! `d·d′ = 0` there), and the cross product is the polynomial
//! `C(u) = d₀×v + (d₀×a)·u + ½(v×a)·u²` of the window's own inputs, formed from its
//! coefficients, not from the rounded `d(u)`: a head-on motion (offset, velocity and
//! acceleration on one line, exactly) gives `C ≡ 0` bit for bit, a motion on an axis with a
//! sideways offset or acceleration on another keeps its exact sideways terms. `C` is nearly
//! stationary at the closest approach (`C′ = d × a`, with `|d| ≤ r` there), so its value at the
//! float time next to the minimum is the one at the minimum to far better than the radius.
//!
//! One place decides: the window search's dips ([`piecewise_entry`](super::entry) and
//! [`first_entry`](super::entry)) call [`narrow_entry`]; the eighth entry (scalar, the friction
//! lanes, the path windows and the first-window lanes) only refuses to call such a dip a miss
//! ([`narrow`]) and leaves it to the search, so that every query and every lane gives the same
//! answer, bit for bit.

use super::length_unit::LengthUnit;
use crate::gap::Gap;

/// How small the contact distance must be beside the window's motion (the sum of the
/// magnitudes of its offset, velocity and acceleration, time scaled to the window) before the
/// gap's sign at float times is no longer trusted at a dip: there, the gap's rounding is
/// above `2⁻¹²` of `r²`.
pub(crate) const NARROW: f64 = 1.0 / ((1u64 << 40) as f64);

/// How close to 0 the separation must come, relative to the window's magnitudes, at a narrow
/// dip that is a crossing: `2²⁰·ε` (see [`narrow_entry`]).
const CROSSING: f64 = (1u64 << 20) as f64 * f64::EPSILON;

/// Whether `gap` (time scaled to its window, `u ∈ [0, ≤ 1]`) is in the regime where a dip
/// that float samples find positive may still hold a contact ([`narrow_entry`] decides it).
/// Branch-free, for the lanes.
#[inline(always)]
pub(crate) fn narrow<const D: usize>(gap: &Gap<D>) -> bool {
    narrow_beside(gap, size(gap))
}

/// The sum of the magnitudes of the window's offset, velocity and acceleration.
#[inline(always)]
fn size<const D: usize>(gap: &Gap<D>) -> f64 {
    gap.offset.abs().sum() + gap.velocity.abs().sum() + gap.acceleration.abs().sum()
}

/// [`narrow`] for a window of that [`size`].
#[inline(always)]
fn narrow_beside<const D: usize>(gap: &Gap<D>, size: f64) -> bool {
    gap.contact_distance <= NARROW * size
}

/// At a dip of a [`narrow`] gap whose float samples are all `≥ 0`: `lowest` the float time
/// found next to its minimum (a root of the slope, in `(left, …]`), `left` the start of the
/// piece that holds it, where the gap is positive. The entry, as time in the window's units,
/// if the closest approach is within `r` (`|C| < r·|d′|`, in a unit where neither side
/// underflows): `lowest` moved by the closest approach's offset from it (`−(d·d′)/|d′|²`) and
/// back by the half-chord `√(r² − h²)/|d′|`, kept in `[left, lowest]`. `None` for a miss, or a
/// gap that is not narrow.
pub(crate) fn narrow_entry<const D: usize>(gap: &Gap<D>, left: f64, lowest: f64) -> Option<f64> {
    // (A NaN `lowest` fails the comparison: nothing to decide.)
    let inside = lowest > left;
    let size = size(gap);
    if !narrow_beside(gap, size) || !inside {
        return None;
    }
    let (p, v, a) = (&gap.offset, &gap.velocity, &gap.acceleration);
    let u = lowest;
    let w = gap.relative_velocity(u);
    let speed2 = w.norm_squared();
    // A crossing, not a turn: at a dip where the balls pass each other, the separation at
    // the float time next to the minimum is at rounding level (the slope's root is found to
    // its noise, `4ε·S·S′/|d′|²`, so `|d| ≤ 4ε·S·S′/|d′|`, below `2²⁰·ε·S` for any crossing
    // outside the grazing band, where `|d′| ≥ ~3e-5·S′`); a dip whose floor is a real
    // distance (the balls turn back short of each other, `d′ ≈ 0` there, and the cross
    // product vanishes with it on a line) is a miss, whatever `|C|/|d′|` says.
    let floor = gap.separation(u).abs().sum();
    let crossing = floor <= CROSSING * size; // (false for a NaN)
    if !crossing {
        return None;
    }
    // C(u) component by component (the pairs of axes), in the unit that brings `r` into
    // [2, 4): the comparison |C|² < r²|d′|² then neither underflows nor overflows for any
    // motion the contract covers (a speed so small that |d′|² underflows has a band of time
    // far wider than the grid: no narrow dip there, and the comparison says no).
    let unit = LengthUnit::of(gap.contact_distance);
    let mut cross2 = 0.0;
    for i in 0..D {
        for j in i + 1..D {
            let c0 = p[i] * v[j] - p[j] * v[i];
            let c1 = p[i] * a[j] - p[j] * a[i];
            let c2 = 0.5 * (v[i] * a[j] - v[j] * a[i]);
            let c = unit.apply(c0 + u * (c1 + u * c2));
            cross2 += c * c;
        }
    }
    let r = unit.apply(gap.contact_distance);
    let reach2 = r * r * speed2;
    let within = cross2 < reach2;
    if !within {
        return None;
    }
    // The closest approach is at `u − (d·d′)/|d′|²`; the entry a half-chord before it.
    let half_chord = ((reach2 - cross2).sqrt() / unit.apply(1.0)) / speed2;
    let approach = gap.half_slope(u) / speed2;
    let entry = u - approach - half_chord;
    Some(entry.max(left).min(lowest))
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Vector2, Vector3};

    #[test]
    fn a_head_on_contact_far_below_the_grid_is_found() {
        // 1 apart, closing at 3 (window units), r = 2⁻²⁰⁰: the band where |d| < r, around
        // u = 1/3, is far narrower than an ulp of u: no float time has a negative exact gap.
        let r = f64::from_bits((1023 - 200) << 52);
        let gap = Gap {
            offset: Vector2::new(1.0, 0.0),
            velocity: Vector2::new(-3.0, 0.0),
            acceleration: Vector2::zeros(),
            contact_distance: r,
        };
        let third = 1.0f64 / 3.0;
        assert!(narrow(&gap));
        let u = narrow_entry(&gap, 0.0, third).expect("a contact");
        assert!((u - third).abs() <= f64::EPSILON * third, "{u}");
        // Passing sideways at 2r: none; at r/2: a contact.
        for (y, hit) in [(2.0 * r, false), (0.5 * r, true)] {
            let g = Gap {
                offset: Vector2::new(1.0, y),
                ..gap
            };
            assert_eq!(narrow_entry(&g, 0.0, third).is_some(), hit, "{y}");
        }
    }

    #[test]
    fn a_curved_miss_and_hit_in_space() {
        // Along x at unit speed, bending sideways (z) by ½·a·u²: at u = 1/2, 0.125·a.
        let r = 1e-100;
        for (a, hit) in [(16.0 * r, false), (4.0 * r, true)] {
            let gap = Gap {
                offset: Vector3::new(0.5, 0.0, 0.0),
                velocity: Vector3::new(-1.0, 0.0, 0.0),
                acceleration: Vector3::new(0.0, 0.0, a),
                contact_distance: r,
            };
            assert_eq!(narrow_entry(&gap, 0.0, 0.5).is_some(), hit, "{a}");
        }
    }

    #[test]
    fn a_turn_short_of_the_other_ball_is_no_contact() {
        // On one line (the cross product is 0 for every u), closing at 1 and decelerating at
        // 2: the separation turns at u = 1/2 at 1 − 1/4 = 3/4 (in the window's units), far
        // from a tiny radius: no contact, though |d′| = 0 there makes |C|/|d′| = 0/0.
        let gap = Gap {
            offset: Vector2::new(1.0, 0.0),
            velocity: Vector2::new(-1.0, 0.0),
            acceleration: Vector2::new(2.0, 0.0),
            contact_distance: 1e-100,
        };
        assert!(narrow(&gap));
        assert_eq!(narrow_entry(&gap, 0.0, 0.5), None);
        // Turning 1e-6 short: still none; a crossing at the same rate: a contact.
        let close = Gap {
            offset: Vector2::new(0.25 + 1e-6, 0.0),
            ..gap
        };
        assert_eq!(narrow_entry(&close, 0.0, 0.5), None);
        let crossing = Gap {
            offset: Vector2::new(0.5, 0.0),
            acceleration: Vector2::zeros(),
            ..gap
        };
        assert!(narrow_entry(&crossing, 0.0, 0.5).is_some());
    }

    #[test]
    fn a_wide_radius_is_not_narrow() {
        let gap = Gap {
            offset: Vector2::new(1.0, 0.0),
            velocity: Vector2::new(-2.0, 0.0),
            acceleration: Vector2::zeros(),
            contact_distance: 1e-6,
        };
        assert!(!narrow(&gap));
        assert_eq!(narrow_entry(&gap, 0.0, 0.5), None);
    }
}
