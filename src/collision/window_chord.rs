//! A second cheap proof that two balls stay apart on a window, after the window box: the
//! separation `d(s) = d₀ + v·s + ½·a·s²`, seen across its own *chord* (from `d(0)` to
//! `d(L)`), keeps to one side of the origin, farther than the contact distance.
//!
//! The window box ([`window_box`](super::window_box)) looks along the coordinate axes; a
//! near miss on a diagonal (two balls passing each other at an angle, one behind the other)
//! sweeps a box around the origin and goes to the search. Its separation still keeps to one
//! side of the line through the origin parallel to its chord: on the normal `n` of the chord,
//! the projection `n·d(s)` is a quadratic whose ends are nearly equal, and whose range over the
//! window lies within the hull of its Bernstein control values, `n·d₀`, `n·d₀ + ½·n·v·L` and
//! `n·d(L)` (as for the boxes). If the whole hull lies beyond `radius·|n|` on one side, then
//! `|d(s)| ≥ |n·d(s)|/|n| > radius` on the whole window. On pool-table pairs this settles about
//! two in three of the windows the box leaves without a contact, for a few dozen operations
//! instead of the search (which costs ten times as much where there is no contact to find).
//!
//! The direction needs no precision: the hull bounds the projection on whatever direction was
//! computed, so only its length `|n|` and the projections' roundings count, and the margin
//! covers them as it covers the box's. The normal is `d₀·(c·c) − c·(d₀·c)` (the part of `d₀`
//! across the chord `c`, in any dimension), divided by its largest component, so that every
//! component is at most 1 in magnitude: each projected value and every intermediate of its
//! hull is then no larger than the sum of the box's per-axis magnitudes, and `|n| ≥ 1` (no
//! square underflows).

use super::window_box::{MARGIN, NORMAL_FLOOR, UNDERFLOW};
use crate::gap::Gap;

/// Whether `g > 0` is proven on `[0, length]` (time since the window's start, finite) by the
/// separation's span across its chord. `false` means "not proven".
///
/// For instance `d(s) = (−2, −1) + (3.25, 2.75)·s + ½·(−0.5, 0.5)·s²` on `[0, 1]` runs from
/// `(−2, −1)` to `(1, 2)`, and its box holds the origin; across its chord (along `(1, 1)`) its
/// span is `[0.53, 0.71]` (on the unit normal), so it is apart at a radius of 0.5.
#[inline(always)]
pub(crate) fn apart_across_window_chord<const D: usize>(gap: &Gap<D>, length: f64) -> bool {
    let (d, v, a) = (&gap.offset, &gap.velocity, &gap.acceleration);
    let half_length = 0.5 * length;
    let mut chord = [0.0; D];
    for (i, c) in chord.iter_mut().enumerate() {
        *c = (v[i] + a[i] * half_length) * length;
    }
    let (cc, dc) = (0..D).fold((0.0, 0.0), |(cc, dc), i| {
        (cc + chord[i] * chord[i], dc + d[i] * chord[i])
    });
    let mut normal = [0.0; D];
    let mut largest = 0.0f64;
    for (i, n) in normal.iter_mut().enumerate() {
        *n = d[i] * cc - chord[i] * dc;
        largest = largest.max(n.abs());
    }
    // (A NaN or infinite largest component, or none, proves nothing: caught by `nn ≥ 1`.)
    let scale = 1.0 / largest;
    let (mut at_start, mut slope, mut bend, mut nn) = (0.0, 0.0, 0.0, 0.0);
    let (mut size, mut spread) = (gap.contact_distance, 0.0);
    for i in 0..D {
        let n = normal[i] * scale;
        nn += n * n;
        at_start += n * d[i];
        slope += n * v[i];
        bend += n * a[i];
        size += d[i].abs() + (v[i].abs() + a[i].abs() * length) * length;
        let reach = 1.0 + v[i].abs() + length;
        spread += reach * reach;
    }
    // The hull of the projection's control values: `p`, `p + ½·v·L`, `p + v·L + ½·a·L²`.
    let middle = at_start + slope * half_length;
    let end = at_start + (slope + bend * half_length) * length;
    let lo = at_start.min(middle).min(end);
    let hi = at_start.max(middle).max(end);
    let nearest = lo.max(0.0) + (-hi).max(0.0);
    // The margin of the box, for its magnitudes (each projected term is at most the box's,
    // `|nᵢ| ≤ 1`), and `D` times its underflow (the projections add `D` products per value).
    let mut reach = gap.contact_distance + MARGIN * size;
    if reach < NORMAL_FLOOR * spread {
        reach += D as f64 * UNDERFLOW * spread;
    }
    // `nearest > reach·|n|`, in squares (no square root; `|n| ≥ 1`, so `reach²·nn` is normal
    // where `reach²` is, and the squares' roundings are far below the margin). `reach²` is
    // normal wherever a normal was formed at all: `normal` is a product of three of the
    // window's magnitudes, so its largest component is nonzero only if `size ≥ 2⁻³⁵⁸`, and
    // `reach ≥ MARGIN·size` then squares to above `2⁻⁸⁰⁰` (so no slack for underflowing
    // squares, as the box keeps, is needed). NaN anywhere fails a comparison: not proven.
    // (`n·fl(1/largest)` may round just below 1 on its largest axis, and `nn ≥ 1` then gives
    // up a proof: never a false one.)
    nn >= 1.0 && nearest > 0.0 && nearest * nearest > reach * reach * nn
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::window_box::apart_on_window;
    use crate::test_rng::Rng;
    use nalgebra::Vector2;
    use nalgebra::Vector3;

    fn gap2(offset: [f64; 2], velocity: [f64; 2], acceleration: [f64; 2], radius: f64) -> Gap {
        Gap {
            offset: Vector2::from(offset),
            velocity: Vector2::from(velocity),
            acceleration: Vector2::from(acceleration),
            contact_distance: radius,
        }
    }

    #[test]
    fn a_curved_near_miss_that_the_box_leaves_is_apart_across_its_chord() {
        // The example of the doc: from (−2, −1) to (1, 2), its span across the chord
        // [0.53, 0.71] on the unit normal.
        let g = gap2([-2.0, -1.0], [3.25, 2.75], [-0.5, 0.5], 0.5);
        assert!(!apart_on_window(&g, 1.0));
        assert!(apart_across_window_chord(&g, 1.0));
        // At a radius the span reaches, nothing is proven.
        let g = gap2([-2.0, -1.0], [3.25, 2.75], [-0.5, 0.5], 0.54);
        assert!(!apart_across_window_chord(&g, 1.0));
    }

    #[test]
    fn head_on_and_degenerate_windows_prove_nothing_they_should_not() {
        // Head-on (d₀ along the chord): the normal is noise or zero; never proven apart when
        // the motion runs through the origin.
        let g = gap2([-2.0, 0.0], [4.0, 0.0], [0.0, 0.0], 0.5);
        assert!(!apart_across_window_chord(&g, 1.0));
        // No motion at all: the chord is zero, so is the normal: not proven (the box settles
        // such windows when they are apart).
        let g = gap2([3.0, 4.0], [0.0, 0.0], [0.0, 0.0], 1.0);
        assert!(!apart_across_window_chord(&g, 1.0));
        // An overflowing window, NaN: not proven.
        let g = gap2([3.0, 4.0], [1e300, 0.0], [1e300, 0.0], 1.0);
        assert!(!apart_across_window_chord(&g, 1e300));
        let g = gap2([f64::NAN, 4.0], [1.0, 0.0], [0.0, 0.0], 1.0);
        assert!(!apart_across_window_chord(&g, 1.0));
    }

    /// The least distance of the separation from the origin over `[0, length]`, sampled
    /// densely: at least the true least distance, so that a sample within the radius is a
    /// contact on the window.
    fn least_distance<const D: usize>(g: &Gap<D>, length: f64) -> f64 {
        (0..=4096)
            .map(|k| {
                let s = length * f64::from(k) / 4096.0;
                (g.offset + g.velocity * s + g.acceleration * (0.5 * s * s)).norm()
            })
            .fold(f64::INFINITY, f64::min)
    }

    #[test]
    fn never_apart_where_the_separation_comes_within_the_radius_2d_and_3d() {
        // Random windows, many near misses: a window proven apart never comes within the
        // radius (dense samples), and the proof is often made (it is not vacuous).
        let mut rng = Rng(77);
        let (mut proven, mut beyond_the_box, mut touching, mut cases) = (0, 0, 0, 0);
        for k in 0..20_000 {
            let r = rng.uniform(0.05, 1.0);
            let length = rng.uniform(0.1, 2.0);
            let mut v = || rng.uniform(-2.0, 2.0);
            let (ok, boxed, close) = if k % 2 == 0 {
                let g = gap2([v(), v()], [v(), v()], [v(), v()], r);
                (
                    apart_across_window_chord(&g, length),
                    apart_on_window(&g, length),
                    least_distance(&g, length) <= r,
                )
            } else {
                let g = Gap {
                    offset: Vector3::new(v(), v(), v()),
                    velocity: Vector3::new(v(), v(), v()),
                    acceleration: Vector3::new(v(), v(), v()),
                    contact_distance: r,
                };
                (
                    apart_across_window_chord(&g, length),
                    apart_on_window(&g, length),
                    least_distance(&g, length) <= r,
                )
            };
            assert!(
                !(ok && close),
                "case {k}: proven apart, yet within the radius"
            );
            proven += usize::from(ok);
            beyond_the_box += usize::from(ok && !boxed);
            touching += usize::from(close);
            cases += 1;
        }
        assert!(proven > cases / 10, "{proven} of {cases} proven");
        // Many of them where the box proves nothing: the stage adds to it.
        assert!(
            beyond_the_box > cases / 20,
            "{beyond_the_box} of {cases} beyond the box"
        );
        assert!(
            touching > cases / 20,
            "{touching} of {cases} within the radius"
        );
    }

    #[test]
    fn the_margin_is_what_keeps_a_graze_unproven() {
        // A straight pass at exactly the radius, then 1e-15 and 1e-9 farther: on the edge
        // nothing is proven; far beyond the margin (2⁻⁴⁰ of the magnitudes) it is.
        for (y, proven) in [(1.0, false), (1.0 + 1e-15, false), (1.0 + 1e-9, true)] {
            let g = gap2([-2.0, y], [4.0, 0.0], [0.0, 0.0], 1.0);
            assert_eq!(apart_across_window_chord(&g, 1.0), proven, "y = {y}");
        }
    }
}
