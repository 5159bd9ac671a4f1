//! The whole-path screen: the box a ball's centre stays in along its whole path, and the
//! proof that two such boxes keep the balls apart ([`PathBounds::apart`]), whatever their
//! timing; and the same for the boxes of single segments, on the windows where both are active
//! ([`PathBounds::segments_apart`]).
//!
//! A path's bounds are a property of the path alone, so a batch computes them once per path
//! (once for a path broadcast against many) and every pair of paths compares two of them:
//! a few comparisons that settle about half the pairs of balls on a pool table before any
//! window is formed, and, of the pairs left, most windows (a slide against the other ball's
//! rest, say) before their motion is formed. The same pass notes the path's largest magnitude,
//! from which the pair's unit of length comes ([`length_unit`](super::length_unit)) for the
//! pairs that go on.

use super::length_unit::{LengthUnit, largest};
use super::window_box::{MARGIN, with_underflow};
use crate::path::Segment;

/// How many segments, from a path's first, keep a box of their own by default
/// ([`PathBounds::segments_apart`]): enough for a pool ball's slide, roll and rest, and for
/// the seed's friction ball; later segments share the box of the whole path, which is still a
/// bound, if a loose one. Bounds kept for long (the calendar's, one per ball) keep none, for
/// memory.
pub(crate) const SEGMENT_BOXES: usize = 4;

/// An axis-aligned box: the least and greatest value on each axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct AxisBox<const D: usize> {
    lo: [f64; D],
    hi: [f64; D],
}

impl<const D: usize> AxisBox<D> {
    /// The box that contains nothing (the start of a union).
    const EMPTY: Self = Self {
        lo: [f64::INFINITY; D],
        hi: [f64::NEG_INFINITY; D],
    };

    /// The box that contains everything (what a segment that is never active keeps: it proves
    /// nothing).
    const EVERYWHERE: Self = Self {
        lo: [f64::NEG_INFINITY; D],
        hi: [f64::INFINITY; D],
    };

    /// The smallest box holding both. `min` and `max` may drop a NaN: harmless here, because
    /// a box value is NaN only where a product overflowed, and then the path's `size` is
    /// infinite or NaN too, so that no box of it proves anything.
    #[inline(always)]
    fn union(self, other: Self) -> Self {
        let mut out = self;
        for i in 0..D {
            out.lo[i] = self.lo[i].min(other.lo[i]);
            out.hi[i] = self.hi[i].max(other.hi[i]);
        }
        out
    }

    /// Whether the boxes are more than `distance` apart on some axis.
    #[inline(always)]
    fn apart(&self, other: &Self, distance: f64) -> bool {
        (0..D)
            .any(|i| (self.lo[i] - other.hi[i] > distance) | (other.lo[i] - self.hi[i] > distance))
    }
}

/// What the screens need of one valid path: the box its centre stays in from its first start
/// on, and the box of each of its first `S` segments ([`SEGMENT_BOXES`] unless said); a bound
/// on the magnitudes that formed the boxes (for the margin), and the largest magnitude of any
/// of its segments' components (for the pair's unit of length).
#[derive(Clone, Copy, Debug)]
pub(crate) struct PathBounds<const D: usize, const S: usize = SEGMENT_BOXES> {
    whole: AxisBox<D>,
    segments: [AxisBox<D>; S],
    size: f64,
    /// What underflow can cost the boxes ([`with_underflow`]).
    spread: f64,
    largest: f64,
}

/// The screen distance: the distance beyond which two balls are proven apart, the contact
/// distance `radius` grown by the margin for the roundings made in forming boxes of the given
/// sizes and spreads.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ScreenDistance(f64);

impl ScreenDistance {
    /// The distance itself.
    #[inline(always)]
    pub(crate) fn value(self) -> f64 {
        self.0
    }
}

/// The least and greatest Bernstein control values of `p + v·s + ½·a·s²` over `s ∈ [0, L]`:
/// `p`, `p + ½·v·L` and `p + v·L + ½·a·L²`, whose hull holds the quadratic's values there.
/// As selects, which may drop a NaN (see [`AxisBox::union`]): faster here than `min` and
/// `max` (which the union keeps, being faster there).
#[inline(always)]
pub(crate) fn bernstein_hull(p: f64, v: f64, a: f64, length: f64) -> [f64; 2] {
    let middle = p + 0.5 * v * length;
    let end = p + (v + 0.5 * a * length) * length;
    let lo = if middle < p { middle } else { p };
    let hi = if middle > p { middle } else { p };
    [
        if end < lo { end } else { lo },
        if end > hi { end } else { hi },
    ]
}

impl<const D: usize, const S: usize> PathBounds<D, S> {
    /// The bounds of a valid path (checked segments, [`Path::segments`](crate::Path::segments)).
    ///
    /// Per segment and axis, the coordinate `p + v·s + ½·a·s²` over the segment's span
    /// `[0, L]` lies within its Bernstein control values `p`, `p + ½·v·L`, `p + v·L + ½·a·L²`
    /// (the hull of a quadratic's control polygon: no division, no branch; for a roll that
    /// ends at rest the middle value is the stopping point itself, so the box is tight). The
    /// last segment lasts for ever: its side is unbounded wherever it drifts (towards its
    /// acceleration, or else its velocity).
    #[inline(always)]
    pub(crate) fn of(segments: &[Segment<D>]) -> Self {
        let mut bounds = Self {
            whole: AxisBox::EMPTY,
            segments: [AxisBox::EVERYWHERE; S],
            size: 0.0,
            spread: 0.0,
            largest: 0.0,
        };
        bounds.set_to(segments);
        bounds
    }

    /// Makes these the bounds of `segments` ([`PathBounds::of`]), in place: a batch keeps one
    /// per side and overwrites it field by field, pair after pair, rather than moving a whole
    /// new one into place (which the CPU would read back wider than it was written, stalling
    /// on it).
    #[inline(always)]
    pub(crate) fn set_to(&mut self, segments: &[Segment<D>]) {
        self.whole = AxisBox::EMPTY;
        let (mut size, mut spread, mut most) = (0.0, 0.0, [0.0; D]);
        let Some((last, finite)) = segments.split_last() else {
            self.size = 0.0;
            self.spread = 0.0;
            self.largest = 0.0;
            return;
        };
        for (k, (s, next)) in finite.iter().zip(&segments[1..]).enumerate() {
            let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
            let length = next.start - s.start;
            let slot = self.segments.get_mut(k);
            if length <= 0.0 {
                // Empty: never active, and no part of the unit either.
                if let Some(slot) = slot {
                    *slot = AxisBox::EVERYWHERE;
                }
                continue;
            }
            for i in 0..D {
                most[i] = largest([most[i], p[i], v[i], a[i]]);
            }
            // The margin covers relative roundings, and what underflowing products can cost
            // ([`with_underflow`]: at most `2⁻¹⁰⁷⁴·(1 + L)²` per axis, nothing divided here).
            let reach = 1.0 + length;
            spread += D as f64 * reach * reach;
            let mut hull = AxisBox::EMPTY;
            for i in 0..D {
                size += p[i].abs() + (v[i].abs() + a[i].abs() * length) * length;
                [hull.lo[i], hull.hi[i]] = bernstein_hull(p[i], v[i], a[i], length);
            }
            if let Some(slot) = slot {
                *slot = hull;
            }
            self.whole = self.whole.union(hull);
        }
        // The last segment lasts for ever.
        let mut drift = AxisBox::EMPTY;
        for (i, most) in most.iter_mut().enumerate() {
            let (p, v, a) = (last.position[i], last.velocity[i], last.acceleration[i]);
            *most = largest([*most, p, v, a]);
            size += p.abs();
            let towards = if a != 0.0 { a } else { v };
            let down = towards < 0.0 || (a > 0.0 && v < 0.0);
            let up = towards > 0.0 || (a < 0.0 && v > 0.0);
            drift.lo[i] = if down { f64::NEG_INFINITY } else { p };
            drift.hi[i] = if up { f64::INFINITY } else { p };
        }
        if let Some(slot) = self.segments.get_mut(finite.len()) {
            *slot = drift;
        }
        self.whole = self.whole.union(drift);
        // (Slots past the path's segments are never asked for; kept proving nothing all the
        // same.)
        for slot in self.segments.iter_mut().skip(segments.len()) {
            *slot = AxisBox::EVERYWHERE;
        }
        self.size = size;
        self.spread = spread;
        self.largest = largest(most);
    }

    /// The distance beyond which boxes of these two paths prove balls `radius` apart:
    /// `radius` grown by the margin. On the caller's numbers (the comparisons need no unit);
    /// a radius sum that overflows proves nothing.
    #[inline(always)]
    pub(crate) fn screen_distance(&self, other: &Self, radius: f64) -> ScreenDistance {
        ScreenDistance(with_underflow(
            radius + MARGIN * (self.size + other.size + radius),
            self.spread + other.spread,
        ))
    }

    /// The whole path's box: its least and greatest values on each axis (for tests).
    #[cfg(test)]
    pub(crate) fn whole(&self) -> ([f64; D], [f64; D]) {
        (self.whole.lo, self.whole.hi)
    }

    /// Whether the screen distance of these two paths is in range: `radius + MARGIN·(sizes +
    /// radius)` itself, of finite sizes, untouched by underflow: what the lane-wise bounds take
    /// (their tests' oracle).
    #[cfg(test)]
    pub(crate) fn screen_distance_in_range(&self, other: &Self, radius: f64) -> bool {
        let sizes = self.size + other.size + radius;
        let distance = radius + MARGIN * sizes;
        sizes.is_finite()
            && distance >= super::window_box::NORMAL_FLOOR * (self.spread + other.spread)
    }

    /// Whether balls on the two paths provably never come within the screen distance of each
    /// other: the boxes of the whole paths, grown by it, are disjoint on some axis.
    #[inline(always)]
    pub(crate) fn apart(&self, other: &Self, distance: ScreenDistance) -> bool {
        self.whole.apart(&other.whole, distance.0)
    }

    /// Whether balls on segment `i` of this path and segment `j` of the other's provably keep
    /// out of the screen distance of each other while both are on them (a window of the pair): their
    /// boxes (the whole path's, for a segment past the first `S`), grown by it,
    /// are disjoint on some axis.
    #[inline(always)]
    pub(crate) fn segments_apart(
        &self,
        i: usize,
        other: &Self,
        j: usize,
        distance: ScreenDistance,
    ) -> bool {
        let a = self.segments.get(i).unwrap_or(&self.whole);
        let b = other.segments.get(j).unwrap_or(&other.whole);
        a.apart(b, distance.0)
    }

    /// The unit of length of a pair of paths with these bounds and contact `radii`: from the
    /// largest component of any segment of either, and the radii.
    #[inline]
    pub(crate) fn pair_unit(&self, other: &Self, radii: [f64; 2]) -> LengthUnit {
        LengthUnit::of(largest([self.largest, other.largest, radii[0], radii[1]]))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2 as V;

    /// Bounds with the default segment boxes.
    type Bounds = PathBounds<2>;

    fn apart(a: &[Segment<2>], b: &[Segment<2>], radius: f64) -> bool {
        let (a, b) = (Bounds::of(a), Bounds::of(b));
        a.apart(&b, a.screen_distance(&b, radius))
    }

    #[test]
    fn paths_far_apart_are_apart_and_a_drifting_one_is_not() {
        let at = |x: f64, v: f64, a: f64| {
            Segment::new(0.0, V::new(x, 0.0), V::new(v, 0.0), V::new(a, 0.0))
        };
        // A rolls from 0 towards +x and stops at 1 (v = 1, a = −0.5 for 2 s); B rests at 3.
        let a = [at(0.0, 1.0, -0.5), Segment::at_rest(2.0, V::new(1.0, 0.0))];
        let b = [Segment::at_rest(0.0, V::new(3.0, 0.0))];
        assert!(apart(&a, &b, 1.5));
        assert!(apart(&b, &a, 1.5));
        // The roll's box ends exactly at its stopping point: 1.9 from B is not 2.1 apart.
        assert!(!apart(&a, &b, 2.1));
        // A frictionless B drifting towards A is not.
        assert!(!apart(&a, &[at(3.0, -0.1, 0.0)], 1.5));
        // Nor one accelerating towards A though moving away.
        assert!(!apart(&a, &[at(3.0, 1.0, -0.01)], 1.5));
        assert!(apart(&a, &[at(3.0, 1.0, 0.0)], 1.5));
    }

    #[test]
    fn a_segment_that_turns_back_covers_its_turning_point() {
        // A moves towards B, turns at x = 1 (v = 2, a = −2, for 2 s: back at 0) and rests.
        let a = [
            Segment::new(0.0, V::zeros(), V::new(2.0, 0.0), V::new(-2.0, 0.0)),
            Segment::at_rest(2.0, V::zeros()),
        ];
        let b = [Segment::at_rest(0.0, V::new(1.6, 0.0))];
        assert!(!apart(&a, &b, 0.5)); // it comes within 0.6: the box must reach x = 1
        assert!(apart(&a, &[Segment::at_rest(0.0, V::new(-0.6, 0.0))], 0.5));
    }

    #[test]
    fn segment_boxes_see_which_segments_meet_in_time() {
        // A rests at x = 0 and then at x = 10, B the other way round: the whole boxes overlap,
        // the boxes of the segments active together do not.
        let rest = |start: f64, x: f64| Segment::at_rest(start, V::new(x, 0.0));
        let a = Bounds::of(&[rest(0.0, 0.0), rest(1.0, 10.0)]);
        let b = Bounds::of(&[rest(0.0, 10.0), rest(1.0, 0.0)]);
        let distance = a.screen_distance(&b, 1.0);
        assert!(!a.apart(&b, distance));
        assert!(a.segments_apart(0, &b, 0, distance) && a.segments_apart(1, &b, 1, distance));
        assert!(!a.segments_apart(0, &b, 1, distance) && !a.segments_apart(1, &b, 0, distance));
        // Past the first SEGMENT_BOXES segments, the whole path's box stands in.
        let many: Vec<_> = (0..6)
            .map(|k| rest(k as f64, 10.0 * (k % 2) as f64))
            .collect();
        let many = Bounds::of(&many);
        assert!(many.segments_apart(0, &b, 0, distance)); // x = 0 against x = 10
        assert!(!many.segments_apart(SEGMENT_BOXES, &b, 0, distance)); // [0, 10] against 10
    }

    #[test]
    fn empty_segments_are_skipped_even_for_the_unit() {
        let a = [
            Segment::new(0.0, V::new(0.0, 0.0), V::zeros(), V::zeros()),
            Segment::new(1.0, V::new(1e9, 0.0), V::zeros(), V::zeros()), // empty
            Segment::at_rest(1.0, V::new(0.0, 0.0)),
        ];
        let bounds = Bounds::of(&a);
        assert_eq!(
            bounds.whole,
            AxisBox {
                lo: [0.0; 2],
                hi: [0.0; 2]
            }
        );
        assert_eq!(bounds.largest, 0.0); // never active: no part of the unit
    }

    #[test]
    fn an_overflowing_box_proves_nothing() {
        let a = [
            Segment::new(0.0, V::zeros(), V::new(1e300, 0.0), V::new(1e300, 0.0)),
            Segment::at_rest(1e10, V::zeros()),
        ];
        let b = [Segment::at_rest(0.0, V::new(-5.0, 0.0))];
        assert!(!apart(&a, &b, 1.0));
    }
}
