//! The first entry of a quadratic signed distance along a path: the one walk behind the
//! plane and segment queries and the calendar's box walls.
//!
//! On each segment of a path the centre moves on a parabola, so its signed distance from a
//! line or a plane, less the ball's radius, is a quadratic in the time `s` since the
//! segment's start, `f(s) = c + b·s + q·s²` ([`Quadratic`]): positive on the free side,
//! negative beyond the contact surface. A contact is where `f` goes from positive to
//! negative, with the pair search's semantics (`docs/contract.md` §3):
//!
//! - at the path's first start, a ball on or beyond the surface (`c ≤ 0`) touches at once
//!   only if it approaches it (the first non-zero derivative of `f` is negative);
//! - at a later segment start, a path that was apart just before (`f > 0` at the end of the
//!   segment before) and is beyond just after (`c < 0`, or `c = 0` approaching) touches at
//!   that start: a jump;
//! - inside a segment, the root at which `f` falls through 0 ([`Quadratic::entry`]); a double
//!   root is a tangency, no contact;
//! - a horizon only cuts.
//!
//! Whether a segment ends apart is read off the same roots that decide its entries
//! ([`Quadratic::positive_before`]), never from a separate evaluation at its end: a root
//! that rounds to the segment's end (outside it) then leaves the segment apart, and the next
//! segment's start, on or beyond the surface, is the contact. (An evaluation could come out
//! `≤ 0` there and lose the contact altogether.)
//!
//! A query may follow several such functions at once (a segment's band has two edges, one
//! on each side of its line) and may refuse a candidate ([`first_entry`]'s `accept`: the
//! entry lies beyond the segment's ends, on the wrong side, or is no entry of the band); the
//! walk then goes on to the next candidate, in time order.

use crate::collision::length_unit::largest;
use crate::path::{Segment, spans};
use crate::poly::{RealRoots, solve_quadratic};
use nalgebra::SVector;

/// `c + b·s + q·s²`: a signed distance (less the radius) on one segment of a path, in the
/// time `s` since the segment's start.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Quadratic {
    /// The value at the segment's start.
    pub c: f64,
    /// The slope at the start.
    pub b: f64,
    /// Half the (constant) second derivative.
    pub q: f64,
}

impl Quadratic {
    /// Whether the first non-zero derivative at the start is negative (`f′ < 0`, or `f′ = 0`
    /// and `f″ < 0`): a ball on the surface is moving into it.
    #[inline(always)]
    pub(crate) fn approaching(self) -> bool {
        self.b < 0.0 || (self.b == 0.0 && self.q < 0.0)
    }

    /// Whether the function is proven positive on the whole segment `[0, length]`, by signs
    /// alone and without its roots: `c > 0` and rising at the start (`b ≥ 0`), and either not
    /// curving down (`q ≥ 0`: rising throughout) or curving down so little that it is still
    /// positive at the end (`q < 0` and `b ≥ 1.5·|q|·length`: then `f(length) > c`, and a
    /// concave function positive at both ends is positive between them). The `1.5` covers the
    /// rounding of the product, which must be normal (a product that underflowed bounds
    /// nothing). Then the segment holds no entry and ends positive, which is what its roots
    /// say too: they are then well apart and away from the segment (both below 0 when
    /// `q ≥ 0`; one below 0 and one beyond `b/|q| ≥ 1.5·length` when `q < 0`).
    ///
    /// What this saves: a ball decelerating to rest, against the plane behind it (a wall it
    /// moves away from), or at rest, needs no roots.
    #[inline(always)]
    fn positive_throughout(self, length: f64) -> bool {
        let (c, b, q) = (self.c, self.b, self.q);
        let rising = c > 0.0 && c < f64::INFINITY && (0.0..f64::INFINITY).contains(&b);
        if !rising {
            return false;
        }
        if q >= 0.0 {
            return true;
        }
        let fall = -q * length;
        fall >= f64::MIN_POSITIVE && b >= 1.5 * fall
    }

    /// The real roots, ascending (none for a constant; one for a line).
    #[inline(always)]
    fn roots(self) -> RealRoots {
        if self.q == 0.0 {
            // `solve_quadratic`'s linear case, without its general checks (finite values
            // only): the root of a line that is not flat.
            let mut roots = RealRoots::empty();
            if self.b != 0.0 && self.b.is_finite() && self.c.is_finite() {
                roots.push(-self.c / self.b);
            }
            return roots;
        }
        solve_quadratic(self.q, self.b, self.c)
    }

    /// The root (of `roots`, this function's) at which it goes from positive to negative as
    /// `s` grows, if any: the smaller of two distinct roots when `q > 0`, the larger when
    /// `q < 0`, the root of a falling line when `q = 0`. A double root is a tangency: none.
    #[inline(always)]
    fn entry(self, roots: &RealRoots) -> Option<f64> {
        match *roots.as_slice() {
            [r] if self.b < 0.0 => Some(r),
            [r1, r2] if r1 < r2 => Some(if self.q > 0.0 { r1 } else { r2 }),
            _ => None,
        }
    }

    /// Whether the function is positive just before `end` (> 0, finite), by its `roots`:
    /// the sign pattern of the computed roots, so that it agrees with [`Quadratic::entry`].
    #[inline(always)]
    fn positive_before(self, roots: &RealRoots, end: f64) -> bool {
        match *roots.as_slice() {
            [] => {
                if self.q == 0.0 {
                    self.b == 0.0 && self.c > 0.0
                } else {
                    self.q > 0.0
                }
            }
            // A line: positive before its root if it falls, after it if it rises.
            [r] => {
                if self.b < 0.0 {
                    end <= r
                } else {
                    end > r
                }
            }
            // Positive outside the roots when `q > 0`, between them when `q < 0` (a double
            // root: positive on both sides, or nowhere).
            [r1, r2, ..] => {
                if self.q > 0.0 {
                    end <= r1 || end > r2
                } else {
                    end > r1 && end <= r2
                }
            }
        }
    }
}

/// How a candidate contact came about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Crossing {
    /// At the path's first start: on or beyond the surface, approaching it.
    First,
    /// At a later segment start: apart just before, on or beyond just after.
    Jump,
    /// Inside a segment, where the function falls through 0 (at `s > 0`, or at `s = 0` from
    /// a positive value: an entry too soon for a float time).
    Root,
}

/// A candidate contact, offered to [`first_entry`]'s `accept`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Candidate {
    /// Time since the segment's start.
    pub s: f64,
    /// Which of the functions enters.
    pub function: usize,
    /// How.
    pub crossing: Crossing,
}

/// The first accepted entry of any of `N` signed distances along a valid path (`segments`,
/// from its first start), as an absolute time before `t_max`; `None` if there is none.
///
/// `distance` forms each segment's `N` functions, with whatever else `accept` needs of the
/// segment (`X`, formed once); `accept` decides each candidate, in time order (at one time,
/// the lower function first). A refused candidate does not stop the walk.
#[inline(always)]
pub(crate) fn first_entry<const D: usize, const N: usize, X>(
    segments: &[Segment<D>],
    t_max: f64,
    mut distance: impl FnMut(&Segment<D>) -> ([Quadratic; N], X),
    mut accept: impl FnMut(&Segment<D>, &X, Candidate) -> bool,
) -> Option<f64> {
    // Whether each function was positive at the end of the segment before (`None` at the
    // path's first start).
    let mut positive_before: Option<[bool; N]> = None;
    for (segment, end) in spans(segments) {
        if segment.start >= t_max {
            return None;
        }
        let (functions, extra) = distance(segment);
        for (function, f) in functions.iter().enumerate() {
            let (on_or_beyond, crossing) = match positive_before {
                None => (f.c <= 0.0 && f.approaching(), Crossing::First),
                Some(positive) => (
                    positive[function] && (f.c < 0.0 || (f.c == 0.0 && f.approaching())),
                    Crossing::Jump,
                ),
            };
            let candidate = Candidate {
                s: 0.0,
                function,
                crossing,
            };
            if on_or_beyond && accept(segment, &extra, candidate) {
                // (A first start of −0 is the time +0, as the pair search answers.)
                return Some(segment.start + 0.0);
            }
        }
        let length = end - segment.start;
        // The functions proven positive throughout need no roots (`None`): no entry, and
        // positive at the segment's end.
        let roots = functions.map(|f| (!f.positive_throughout(length)).then(|| f.roots()));
        // Each function's entry inside the segment. A root of 0 from a positive value is an
        // entry that underflowed (a ball crossing its room faster than 2⁻¹⁰⁷⁴ time units): a
        // contact at the start, rounded.
        let mut entries = [None; N];
        for (function, f) in functions.iter().enumerate() {
            entries[function] = roots[function]
                .as_ref()
                .and_then(|roots| f.entry(roots))
                .filter(|&s| (s > 0.0 || (s == 0.0 && f.c > 0.0)) && s < length)
                .map(|s| (s, function));
        }
        // In time order, the lower function first at one time (N is 1 or 2).
        entries.sort_by(|x, y| match (x, y) {
            (Some(x), Some(y)) => x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)),
            (Some(_), None) => std::cmp::Ordering::Less,
            (None, Some(_)) => std::cmp::Ordering::Greater,
            (None, None) => std::cmp::Ordering::Equal,
        });
        for (s, function) in entries.into_iter().flatten() {
            let t = segment.start + s;
            if t >= t_max {
                return None;
            }
            let candidate = Candidate {
                s,
                function,
                crossing: Crossing::Root,
            };
            if accept(segment, &extra, candidate) {
                return Some(t);
            }
        }
        if length == f64::INFINITY {
            return None;
        }
        let mut positive = [false; N];
        for (function, f) in functions.iter().enumerate() {
            positive[function] = roots[function]
                .as_ref()
                .is_none_or(|roots| f.positive_before(roots, length));
        }
        positive_before = Some(positive);
    }
    None
}

/// The largest magnitude among the positions, velocities and accelerations of `segments`:
/// with the object's lengths and the radius, what a query's unit of length comes from.
#[inline(always)]
pub(crate) fn largest_in_path<const D: usize>(segments: &[Segment<D>]) -> f64 {
    segments.iter().fold(0.0, |most, s| {
        let most = largest([most, largest(s.position.into())]);
        largest([
            most,
            largest(s.velocity.into()),
            largest(s.acceleration.into()),
        ])
    })
}

/// `x·y` in a fixed order (component 0 first), so that quarter turns and reflections, which
/// permute and negate the products, give the same bits.
#[inline(always)]
pub(crate) fn dot<const D: usize>(x: &SVector<f64, D>, y: &SVector<f64, D>) -> f64 {
    let mut products = x.iter().zip(y.iter()).map(|(a, b)| a * b);
    let first = products.next().unwrap_or(0.0);
    products.fold(first, |sum, p| sum + p)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector1;

    fn quadratic(c: f64, b: f64, q: f64) -> Quadratic {
        Quadratic { c, b, q }
    }

    /// The first entry of the height above 0 of a 1-D path, every candidate accepted.
    fn first(segments: &[(f64, f64, f64, f64)], t_max: f64) -> Option<f64> {
        let segments: Vec<Segment<1>> = segments
            .iter()
            .map(|&(s, p, v, a)| Segment::new(s, Vector1::new(p), Vector1::new(v), Vector1::new(a)))
            .collect();
        first_entry(
            &segments,
            t_max,
            |s| {
                let f = quadratic(s.position.x, s.velocity.x, 0.5 * s.acceleration.x);
                ([f], ())
            },
            |_, _, _| true,
        )
    }

    #[test]
    fn the_entry_root_is_where_the_function_falls_through_zero() {
        // 1 − s² falls through 0 at 1; s² − 1 falls through 0 at −1 (and rises at 1).
        assert_eq!(
            quadratic(1.0, 0.0, -1.0).entry(&quadratic(1.0, 0.0, -1.0).roots()),
            Some(1.0)
        );
        let rising = quadratic(-1.0, 0.0, 1.0);
        assert_eq!(rising.entry(&rising.roots()), Some(-1.0));
        let tangent = quadratic(1.0, -2.0, 1.0);
        assert_eq!(tangent.entry(&tangent.roots()), None);
        let line = quadratic(2.0, -4.0, 0.0);
        assert_eq!(line.entry(&line.roots()), Some(0.5));
        let flat = quadratic(2.0, 0.0, 0.0);
        assert_eq!(flat.entry(&flat.roots()), None);
    }

    #[test]
    fn the_sign_at_an_end_follows_the_roots() {
        let f = quadratic(1.0, 0.0, -1.0); // positive on (−1, 1)
        let roots = f.roots();
        assert!(f.positive_before(&roots, 0.5));
        assert!(f.positive_before(&roots, 1.0)); // just before the root
        assert!(!f.positive_before(&roots, 1.5));
        let g = quadratic(-1.0, 0.0, 1.0); // positive outside [−1, 1]
        let roots = g.roots();
        assert!(!g.positive_before(&roots, 1.0));
        assert!(g.positive_before(&roots, 1.5));
        let tangent = quadratic(1.0, -2.0, 1.0);
        assert!(tangent.positive_before(&tangent.roots(), 1.0));
        let line = quadratic(1.0, -1.0, 0.0);
        assert!(line.positive_before(&line.roots(), 1.0));
        assert!(!line.positive_before(&line.roots(), 1.5));
        let none = quadratic(-1.0, 0.0, -1.0);
        assert!(!none.positive_before(&none.roots(), 1.0));
    }

    #[test]
    fn a_function_proven_positive_throughout_has_roots_that_say_so() {
        // Over the whole float range of each coefficient, and at the boundary of the proof:
        // a ball decelerating to rest against the plane behind it (b = 2·|q|·length).
        let mut rng = crate::test_rng::Rng(11);
        let mut proven = 0;
        for n in 0..200_000 {
            let magnitude = |rng: &mut crate::test_rng::Rng| {
                rng.uniform(0.5, 1.0) * 2f64.powi(rng.uniform(-1070.0, 1020.0) as i32)
            };
            let c = magnitude(&mut rng);
            let b = if n % 7 == 0 { 0.0 } else { magnitude(&mut rng) };
            let q = -magnitude(&mut rng) * if n % 5 == 0 { -1.0 } else { 1.0 };
            let length = match n % 3 {
                0 => magnitude(&mut rng),
                // At, or near, the stop of a deceleration from speed b: b = 2·|q|·length.
                1 => b / (2.0 * q.abs()) * rng.uniform(0.9, 1.0),
                _ => b / (1.5 * q.abs()) * rng.uniform(0.999, 1.001),
            };
            if !(length > 0.0 && length.is_finite()) {
                continue;
            }
            let f = quadratic(c, b, q);
            if f.positive_throughout(length) {
                proven += 1;
                let roots = f.roots();
                let entry = f.entry(&roots).filter(|&s| s >= 0.0 && s < length);
                assert_eq!(entry, None, "{f:?} on [0, {length}]");
                assert!(f.positive_before(&roots, length), "{f:?} on [0, {length}]");
            }
        }
        assert!(proven > 50_000, "only {proven} proven");
        // Not proven: starting on the surface, falling, curving down too much, for ever.
        assert!(!quadratic(0.0, 1.0, 0.0).positive_throughout(1.0));
        assert!(!quadratic(1.0, -1e-300, 0.0).positive_throughout(1.0));
        assert!(!quadratic(1.0, 1.0, -1.0).positive_throughout(1.0));
        assert!(!quadratic(1.0, 1.0, -1e-300).positive_throughout(f64::INFINITY));
        assert!(quadratic(1.0, 0.0, 0.0).positive_throughout(f64::INFINITY));
        // A product that underflows bounds nothing.
        assert!(!quadratic(1e-300, 0.0, -1e-300).positive_throughout(1e-20));
    }

    #[test]
    fn a_walk_takes_the_first_start_jumps_and_roots_with_the_pair_s_semantics() {
        let inf = f64::INFINITY;
        // Falls from 1 at speed 1: at 1.
        assert_eq!(first(&[(0.0, 1.0, -1.0, 0.0)], inf), Some(1.0));
        assert_eq!(first(&[(0.0, 1.0, -1.0, 0.0)], 1.0), None);
        // Beyond at the start: only when approaching; moving away, it never comes back.
        assert_eq!(first(&[(2.0, -1.0, -1.0, 0.0)], inf), Some(2.0));
        assert_eq!(first(&[(2.0, -1.0, 1.0, 0.0)], inf), None);
        // On the surface, at rest, accelerating into it: approaching.
        assert_eq!(first(&[(0.0, 0.0, 0.0, -1.0)], inf), Some(0.0));
        // A jump beyond at a later start, and onto the surface moving in.
        assert_eq!(
            first(&[(0.0, 1.0, 0.0, 0.0), (3.0, -1.0, 1.0, 0.0)], inf),
            Some(3.0)
        );
        assert_eq!(
            first(&[(0.0, 1.0, 0.0, 0.0), (3.0, 0.0, -1.0, 0.0)], inf),
            Some(3.0)
        );
        assert_eq!(
            first(&[(0.0, 1.0, 0.0, 0.0), (3.0, 0.0, 1.0, 0.0)], inf),
            None
        );
        // The root at the first segment's end: the next start, on the surface, moving in.
        assert_eq!(
            first(&[(0.0, 1.0, -1.0, 0.0), (1.0, 0.0, -1.0, 0.0)], inf),
            Some(1.0)
        );
        // A tangency is none: 1 − 2s + s² touches 0 at 1.
        assert_eq!(first(&[(0.0, 1.0, -2.0, 2.0)], inf), None);
    }

    #[test]
    fn a_refused_candidate_does_not_stop_the_walk() {
        let segments = [
            Segment::new(
                0.0,
                Vector1::new(1.0),
                Vector1::new(-1.0),
                Vector1::new(0.0),
            ),
            Segment::new(
                2.0,
                Vector1::new(1.0),
                Vector1::new(-1.0),
                Vector1::new(0.0),
            ),
        ];
        let mut offered = Vec::new();
        let hit = first_entry(
            &segments,
            f64::INFINITY,
            |s| ([quadratic(s.position.x, s.velocity.x, 0.0)], s.start),
            |_, &start, c| {
                offered.push((start, c.s, c.crossing));
                start > 1.0
            },
        );
        // The root at 1 is refused; the next segment starts apart again (a jump back), and
        // its root, at 3, is accepted.
        assert_eq!(hit, Some(3.0));
        assert_eq!(
            offered,
            [(0.0, 1.0, Crossing::Root), (2.0, 1.0, Crossing::Root)]
        );
    }
}
