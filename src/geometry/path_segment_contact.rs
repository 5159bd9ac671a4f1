//! When a ball on a path first touches the flat part of a [`LineSegment`]:
//! [`path_segment_contact`].
//!
//! With `e = Q − P`, the centre's signed distance from the line times `|e|` is
//! `D(x) = e × (x − P)` (positive on the left), and the ball touches the line where
//! `|D| = r·|e|`: a band of half-width `r` about the line, whose two edges are the functions
//! `D − r·|e|` (entered from the left) and `−D − r·|e|` (from the right). On each segment of
//! the path both are quadratics in time, and the walk of
//! [`first_entry`](super::signed_distance::first_entry) finds their entries, each kept only if
//! the foot of the centre lies on the segment there, `0 ≤ (x − P)·e` and `(x − Q)·e ≤ 0`
//! (each from the centre's offset from its own end: exact to a few roundings of the centre's
//! distance from the end it tests, whatever the other end's magnitude), and the side counts.
//!
//! `D` at a segment's start is formed from the exact differences `Q − P` and `x − P`
//! (each as a sum of two floats) with the products' rounding errors restored: to within a
//! few roundings of its own value, whichever end is near. (A plain cross product would carry
//! an error of the segment's length times `2⁻⁵³` even where the ball touches it next to the
//! other end, far more than one rounding of the inputs moves the contact there.) Every
//! length is first divided by the query's own power of two (exact), so no answer depends on
//! the unit of length. First of all, the pair search's whole-path box screen, with the
//! segment's ends as the other path, proves most balls that never come near apart.

use nalgebra::Vector2;

use super::shapes::LineSegment;
use super::signed_distance::{Crossing, Quadratic, first_entry, largest_in_path};
use crate::CollisionOptions;
use crate::collision::length_unit::{LengthUnit, largest};
use crate::collision::path_bounds::PathBounds;
use crate::error::{InputError, check_ball_radius, check_horizon};
use crate::path::{Path, Segment};

/// The first time (absolute, as the path's starts are) at which a ball of `radius` on `path`
/// starts to touch the flat part of `segment` from a side that counts, searched from the
/// path's first start; `None` if it does not before `options.t_max`.
///
/// With `d(t)` the signed distance of the centre from the line `P → Q` (positive on its
/// left) and `u(t)` the parameter of its foot (0 at `P`, 1 at `Q`), the contact is the
/// earliest `t` at which `d² − r²` goes from positive to negative with `0 ≤ u ≤ 1` there;
/// [`SegmentSide::Left`](super::SegmentSide::Left) counts only contacts with `d > 0`,
/// [`SegmentSide::Right`](super::SegmentSide::Right) only those with `d < 0`. As for two
/// balls: touching or within `r` at the first start is a contact only if the centre moves
/// towards the line (the first non-zero derivative of `d² − r²` is negative); a path that
/// jumps from beyond `r` to within it at a later segment start touches at that start; exact
/// tangency is no contact.
///
/// The ends are not part of the flat part: a ball that comes within `r` of the line beyond
/// `P` or `Q` does not touch it, not even if it then slides along within `r` of the line
/// onto the stretch between them (it meets the rounded end on its way:
/// [`path_circle_contact`](super::path_circle_contact) with a [`Circle`](super::Circle) of
/// radius 0 at the end, an object of its own).
///
/// # Errors
/// `radius` must be finite and positive, `t_max ≥ 0` (`∞` allowed).
///
/// ```
/// use ballcollide::geometry::{LineSegment, SegmentSide, path_segment_contact};
/// use ballcollide::path::{Path2, Segment2};
/// use ballcollide::CollisionOptions;
/// use nalgebra::Vector2;
///
/// // A cushion along y = 0 from x = 0 to 2, played from above (its left, going P → Q).
/// let cushion = LineSegment::new(Vector2::new(0.0, 0.0), Vector2::new(2.0, 0.0), SegmentSide::Left)?;
/// let options = CollisionOptions::default();
/// // A ball of radius 0.1 at (1, 0.5) rolling straight down at 1 m/s: it touches at y = 0.1.
/// let down = Path2::new(vec![Segment2::new(0.0, Vector2::new(1.0, 0.5), Vector2::new(0.0, -1.0), Vector2::zeros())])?;
/// let t = path_segment_contact(&down, &cushion, 0.1, &options)?.expect("a contact");
/// assert!((t - 0.4).abs() < 1e-15);
/// // The same roll beyond the cushion's end (x = 3) does not touch its flat part.
/// let beyond = Path2::new(vec![Segment2::new(0.0, Vector2::new(3.0, 0.5), Vector2::new(0.0, -1.0), Vector2::zeros())])?;
/// assert_eq!(path_segment_contact(&beyond, &cushion, 0.1, &options)?, None);
/// // Coming from below, the left-side cushion is not there.
/// let up = Path2::new(vec![Segment2::new(0.0, Vector2::new(1.0, -0.5), Vector2::new(0.0, 1.0), Vector2::zeros())])?;
/// assert_eq!(path_segment_contact(&up, &cushion, 0.1, &options)?, None);
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn path_segment_contact(
    path: &Path<2>,
    segment: &LineSegment,
    radius: f64,
    options: &CollisionOptions,
) -> Result<Option<f64>, InputError> {
    let radius = check_ball_radius("radius", radius)?;
    let t_max = check_horizon("t_max", options.t_max)?;
    Ok(first_segment_contact(
        path.segments(),
        segment,
        radius,
        t_max,
    ))
}

/// [`path_segment_contact`] on validated inputs: the segments of a valid path, `radius > 0`
/// finite, `t_max ≥ 0`.
pub(crate) fn first_segment_contact(
    segments: &[Segment<2>],
    object: &LineSegment,
    radius: f64,
    t_max: f64,
) -> Option<f64> {
    if apart(segments, object.p(), object.q(), radius) {
        return None;
    }
    walk(segments, object, radius, t_max)
}

/// [`first_segment_contact`] without the screen: the walk along the path.
fn walk(segments: &[Segment<2>], object: &LineSegment, radius: f64, t_max: f64) -> Option<f64> {
    let (p, q) = (object.p(), object.q());
    let unit = LengthUnit::of(largest([
        largest_in_path(segments),
        largest(p.into()),
        largest(q.into()),
        radius,
    ]));
    let scale = |x: Vector2<f64>| x.map(|c| unit.apply(c));
    let (p, q, radius) = (scale(p), scale(q), unit.apply(radius));
    // The direction, exactly, as `high + low`.
    let direction = Exact::difference(&q, &p);
    let e = direction.high;
    let length2 = e.x * e.x + e.y * e.y;
    let half_width = radius * length2.sqrt();
    let side = object.side();
    first_entry(
        segments,
        t_max,
        |segment| {
            let position = scale(segment.position);
            let offset = Exact::difference(&position, &p);
            // From Q too: the foot test at each end from the centre's offset from that end.
            let from_q = Exact::difference(&position, &q).high;
            let velocity = scale(segment.velocity);
            let acceleration = scale(segment.acceleration);
            let d = direction.cross(&offset);
            let slope = cross(&e, &velocity);
            let curvature = 0.5 * cross(&e, &acceleration);
            let left = Quadratic {
                c: d - half_width,
                b: slope,
                q: curvature,
            };
            let right = Quadratic {
                c: -d - half_width,
                b: -slope,
                q: -curvature,
            };
            let found = Found {
                d,
                edges: [left, right],
                offset: offset.high,
                from_q,
                velocity,
                acceleration,
            };
            ([left, right], found)
        },
        |_, found, candidate| {
            let Some(sign) = found.side_of(candidate.function, candidate.crossing) else {
                return false;
            };
            if !side.counts(sign) {
                return false;
            }
            // The foot on the segment: 0 ≤ (x − P)·e and (x − Q)·e ≤ 0, each from the
            // centre's offset from its own end, so that each is exact to a few roundings of
            // the centre's distance from that end, not of the segment's length (as
            // (x − P)·e ≤ |e|² would be next to Q).
            let s = candidate.s;
            let moved = (found.velocity + found.acceleration * (0.5 * s)) * s;
            let (x, y) = (found.offset + moved, found.from_q + moved);
            x.x * e.x + x.y * e.y >= 0.0 && y.x * e.x + y.y * e.y <= 0.0
        },
    )
}

/// Whether the box the centre stays in along the whole path, grown by `radius` and the pair
/// search's margin for rounding ([`PathBounds`]), keeps clear of the box of `P` and `Q`: a
/// proof that the ball never comes within `radius` of the segment, so never touches its flat
/// part (whose contacts all lie within `radius` of it). The pair search's own screen, with
/// the segment's ends as a path.
#[inline(always)]
fn apart(segments: &[Segment<2>], p: Vector2<f64>, q: Vector2<f64>, radius: f64) -> bool {
    let ends = [Segment::at_rest(0.0, p), Segment::at_rest(1.0, q)];
    let (path, ends) = (
        PathBounds::<2, 0>::of(segments),
        PathBounds::<2, 0>::of(&ends),
    );
    path.apart(&ends, path.screen_distance(&ends, radius))
}

/// What a segment of the path gives the acceptance of its candidates: the (scaled) signed
/// distance times `|e|` at its start, the two edges, and its motion relative to `P` (and its
/// offset from `Q`).
struct Found {
    d: f64,
    edges: [Quadratic; 2],
    offset: Vector2<f64>,
    from_q: Vector2<f64>,
    velocity: Vector2<f64>,
    acceleration: Vector2<f64>,
}

impl Found {
    /// The side (`+1` left, `−1` right, 0 on the line) of a candidate entry of edge `edge`
    /// (0 the left one, 1 the right one) that is an entry of the band, `None` for one that
    /// is not.
    ///
    /// An edge's root is an entry from its own side. At the first start, the edge's own test
    /// (on or beyond it, approaching) is the band's only for a centre on the edge's side of
    /// the line (`D` of the edge's sign; then `d² − r²` and the edge's distance have the same
    /// sign and the same first non-zero derivative); the other edge tests the other side. A
    /// jump from beyond the edge lands within the band if it lands on its side of the line,
    /// or else within the other edge (touching it, approaching).
    fn side_of(&self, edge: usize, crossing: Crossing) -> Option<i8> {
        let own: i8 = if edge == 0 { 1 } else { -1 };
        let on_own_side = f64::from(own) * self.d > 0.0;
        match crossing {
            Crossing::Root => Some(own),
            Crossing::First => on_own_side.then_some(own),
            Crossing::Jump if on_own_side => Some(own),
            Crossing::Jump => {
                let other = self.edges[1 - edge];
                let within = other.c < 0.0 || (other.c == 0.0 && other.approaching());
                within.then_some(if self.d == 0.0 { 0 } else { -own })
            }
        }
    }
}

/// `x × y`, the plain product (the two products in a fixed order, so that quarter turns and
/// reflections give the same bits).
#[inline(always)]
fn cross(x: &Vector2<f64>, y: &Vector2<f64>) -> f64 {
    x.x * y.y - x.y * y.x
}

/// A vector as the unevaluated sum `high + low` of two floats: an exact difference.
#[derive(Clone, Copy, Debug)]
struct Exact {
    high: Vector2<f64>,
    low: Vector2<f64>,
}

impl Exact {
    /// `x − y`, exactly (Knuth's two-sum on each component; the caller's numbers are in the
    /// query's unit, where nothing overflows).
    #[inline(always)]
    fn difference(x: &Vector2<f64>, y: &Vector2<f64>) -> Self {
        let mut high = Vector2::zeros();
        let mut low = Vector2::zeros();
        for k in 0..2 {
            let (a, b) = (x[k], -y[k]);
            let s = a + b;
            let b_virtual = s - a;
            let a_virtual = s - b_virtual;
            high[k] = s;
            low[k] = (a - a_virtual) + (b - b_virtual);
        }
        Self { high, low }
    }

    /// `self × other`, to within a few roundings of its value (plus `2⁻¹⁰⁶` of the
    /// products): the two products of the high parts exactly (their rounding errors by fused
    /// multiply-adds), and the first-order terms of the low parts.
    #[inline(always)]
    fn cross(&self, other: &Self) -> f64 {
        let (x, y) = (&self.high, &other.high);
        let first = x.x * y.y;
        let second = x.y * y.x;
        let first_error = x.x.mul_add(y.y, -first);
        let second_error = x.y.mul_add(y.x, -second);
        let lows = cross(x, &other.low) + cross(&self.low, y);
        (first - second) + ((first_error - second_error) + lows)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::SegmentSide;

    const INF: f64 = f64::INFINITY;

    fn one(p: [f64; 2], v: [f64; 2], a: [f64; 2]) -> Vec<Segment<2>> {
        vec![Segment::new(0.0, p.into(), v.into(), a.into())]
    }

    fn segment(p: [f64; 2], q: [f64; 2], side: SegmentSide) -> LineSegment {
        LineSegment::new(p.into(), q.into(), side).expect("a valid segment")
    }

    fn along_x(side: SegmentSide) -> LineSegment {
        segment([0.0, 0.0], [2.0, 0.0], side)
    }

    #[test]
    fn the_side_filter_keeps_the_contacts_from_its_side() {
        let down = one([1.0, 0.5], [0.0, -1.0], [0.0; 2]);
        let up = one([1.0, -0.5], [0.0, 1.0], [0.0; 2]);
        for (side, from_above, from_below) in [
            (SegmentSide::Both, true, true),
            (SegmentSide::Left, true, false),
            (SegmentSide::Right, false, true),
        ] {
            let object = along_x(side);
            let hit = |p: &[Segment<2>]| first_segment_contact(p, &object, 0.25, INF);
            assert_eq!(hit(&down).is_some(), from_above, "{side:?}");
            assert_eq!(hit(&up).is_some(), from_below, "{side:?}");
        }
        // One-sided: a ball from below passes through, and is not touched on its way back
        // down from above either unless it re-enters from above.
        let through = one([1.0, -0.5], [0.0, 2.0], [0.0, -1.0]); // turns at y = 1.5
        let t = first_segment_contact(&through, &along_x(SegmentSide::Left), 0.25, INF);
        // y = −0.5 + 2t − t²/2 = 0.25 on the way down: t = 2 + √2.5.
        let t = t.expect("a contact from above");
        assert!((t - (2.0 + 2.5f64.sqrt())).abs() < 1e-14, "{t}");
    }

    #[test]
    fn the_band_beyond_an_end_is_not_the_flat_part() {
        let object = along_x(SegmentSide::Both);
        // Down onto the line at x = 2.5: within r of the line, but beyond Q.
        let beyond = one([2.5, 1.0], [0.0, -1.0], [0.0; 2]);
        assert_eq!(first_segment_contact(&beyond, &object, 0.25, INF), None);
        // Entering the band beyond Q, then sliding back along it onto the segment: no
        // entry of the flat part (the round end is a circle of its own).
        let slide = one([2.5, 1.0], [-1.0, -1.0], [0.0, 2.0]); // y = 1 − t + t², lowest 0.75
        let slide_low = one([2.5, 0.5], [-1.0, -1.0], [0.0, 2.0]); // lowest 0.25: tangent
        assert_eq!(first_segment_contact(&slide, &object, 0.25, INF), None);
        assert_eq!(first_segment_contact(&slide_low, &object, 0.25, INF), None);
        let glide = one([2.5, 0.1], [-1.0, 0.0], [0.0; 2]);
        assert_eq!(first_segment_contact(&glide, &object, 0.25, INF), None);
        // Exactly over an end counts (0 ≤ u ≤ 1); just beyond does not.
        let on_p = one([0.0, 1.0], [0.0, -1.0], [0.0; 2]);
        assert_eq!(first_segment_contact(&on_p, &object, 0.25, INF), Some(0.75));
        let off_p = one([-1e-12, 1.0], [0.0, -1.0], [0.0; 2]);
        assert_eq!(first_segment_contact(&off_p, &object, 0.25, INF), None);
    }

    #[test]
    fn touching_at_the_start_counts_only_when_approaching() {
        let object = along_x(SegmentSide::Both);
        let touching = |v: [f64; 2], a: [f64; 2]| {
            first_segment_contact(&one([1.0, 0.25], v, a), &object, 0.25, INF)
        };
        assert_eq!(touching([0.0, -1.0], [0.0; 2]), Some(0.0));
        assert_eq!(touching([0.0, 1.0], [0.0; 2]), None);
        assert_eq!(touching([1.0, 0.0], [0.0; 2]), None); // along the edge
        assert_eq!(touching([1.0, 0.0], [0.0, -1.0]), Some(0.0)); // curving in
        // Overlapping, moving deeper: at once; moving out: only a later entry.
        let inside =
            |v: [f64; 2]| first_segment_contact(&one([1.0, 0.1], v, [0.0; 2]), &object, 0.25, INF);
        assert_eq!(inside([0.0, -1.0]), Some(0.0));
        assert_eq!(inside([0.0, 1.0]), None);
        // On the line itself, moving across: not approaching (d·d′ = 0, |d′|² > 0).
        let across = one([1.0, 0.0], [0.0, 1.0], [0.0; 2]);
        assert_eq!(first_segment_contact(&across, &object, 0.25, INF), None);
    }

    #[test]
    fn a_jump_into_the_band_is_a_contact_at_its_start_with_the_side_it_lands_on() {
        let rest = |t: f64, y: f64| Segment::at_rest(t, Vector2::new(1.0, y));
        let cases = [
            // From above to within r above the line: from the left.
            (
                vec![rest(0.0, 1.0), rest(2.0, 0.1)],
                SegmentSide::Left,
                Some(2.0),
            ),
            (
                vec![rest(0.0, 1.0), rest(2.0, 0.1)],
                SegmentSide::Right,
                None,
            ),
            // From above to within r below the line: a contact on the right.
            (
                vec![rest(0.0, 1.0), rest(2.0, -0.1)],
                SegmentSide::Right,
                Some(2.0),
            ),
            (
                vec![rest(0.0, 1.0), rest(2.0, -0.1)],
                SegmentSide::Left,
                None,
            ),
            (
                vec![rest(0.0, 1.0), rest(2.0, 0.0)],
                SegmentSide::Both,
                Some(2.0),
            ),
            (
                vec![rest(0.0, 1.0), rest(2.0, 0.0)],
                SegmentSide::Left,
                None,
            ),
            // Across the whole band: no contact.
            (
                vec![rest(0.0, 1.0), rest(2.0, -1.0)],
                SegmentSide::Both,
                None,
            ),
        ];
        for (k, (path, side, expected)) in cases.into_iter().enumerate() {
            let got = first_segment_contact(&path, &along_x(side), 0.25, INF);
            assert_eq!(got, expected, "case {k}");
        }
    }

    #[test]
    fn a_tangency_is_no_contact_and_a_horizon_only_cuts() {
        let object = along_x(SegmentSide::Both);
        // y = 1 − t + t²/4: lowest 0 at t = 2, the band's edge at 0.25 is entered before.
        let dip = one([1.0, 1.0], [0.0, -1.0], [0.0, 0.5]);
        let t = first_segment_contact(&dip, &object, 0.25, INF).expect("a contact");
        // 1 − t + t²/4 = 1/4: t = 2 − √1 = 1.
        assert_eq!(t, 1.0);
        assert_eq!(first_segment_contact(&dip, &object, 0.25, 1.0), None);
        assert_eq!(first_segment_contact(&dip, &object, 0.25, 1.5), Some(1.0));
        // y = 1 − t + t²/3 is lowest at t = 1.5, 0.25 exactly: a tangency.
        let tangent = one([1.0, 1.0], [0.0, -1.0], [0.0, 2.0 / 3.0]);
        let grazed = first_segment_contact(&tangent, &object, 0.25, INF);
        // 2/3 is not exact: the graze is within a rounding, either answer is fine; a quarter
        // in y is not.
        let _ = grazed;
        let tangent = one([1.0, 0.75], [0.0, -1.0], [0.0, 2.0]); // lowest 0.5
        assert_eq!(first_segment_contact(&tangent, &object, 0.25, INF), None);
    }

    #[test]
    fn the_screen_is_a_proof() {
        // Paths of 1–3 segments (continuous, some ending at rest) against segments anywhere
        // in and about their box: wherever the screen settles a case, the walk finds none.
        let mut rng = crate::test_rng::Rng(36);
        let mut draw = |lo: f64, hi: f64| rng.uniform(lo, hi);
        let mut screened = 0;
        for n in 0..20_000 {
            let mut path = Vec::new();
            let (mut t, mut p) = (draw(0.0, 2.0), [draw(0.0, 2.0), draw(0.0, 1.0)]);
            for k in 0..1 + n % 3 {
                let v = [draw(-2.0, 2.0), draw(-2.0, 2.0)];
                let a = if k == 2 {
                    [0.0; 2]
                } else {
                    [draw(-1.0, 1.0), draw(-1.0, 1.0)]
                };
                let v = if k == 2 { [0.0; 2] } else { v };
                let segment = Segment::new(t, p.into(), v.into(), a.into());
                let dt = draw(0.0, 1.5);
                let next = segment.position_at(t + dt);
                path.push(segment);
                (t, p) = (t + dt, [next.x, next.y]);
            }
            let ends = [
                [draw(-1.0, 3.0), draw(-1.0, 2.0)],
                [draw(-1.0, 3.0), draw(-1.0, 2.0)],
            ];
            let object = segment(ends[0], ends[1], SegmentSide::Both);
            let radius = draw(0.01, 0.3);
            if apart(&path, object.p(), object.q(), radius) {
                screened += 1;
                assert_eq!(
                    walk(&path, &object, radius, INF),
                    None,
                    "{path:?} {object:?}"
                );
            }
        }
        assert!(screened > 2000, "{screened}");
    }

    #[test]
    fn the_foot_test_is_as_accurate_next_to_either_end_whatever_the_other_ends_magnitude() {
        // The diagonal y = x from a far end at (a, a) to the origin, either way round; a ball
        // of radius 1/4 comes at it square on (velocity (−1, 1)) from (m + 1, m − 1): its
        // foot stays at m·√2 along the line from the origin, on the flat part for m > 0 and
        // beyond the near end for m < 0, by `β·r` down to 2⁻⁴⁰ of it. Contact at
        // t = 1 − r/√2. With (x − P)·e ≤ |e|² as the test next to Q, the foot was exact only
        // to 2⁻⁵³·a: 7e15 for a = 4e31, which decided every one of these at random.
        let r = 0.25;
        let exact = 1.0 - r / 2f64.sqrt();
        for a in [1.0, 712_345.678_901, 3.3e15, 4e31, 2f64.powi(300)] {
            for beta in [1.0, 0.5, 2f64.powi(-10), 2f64.powi(-40)] {
                for (m, hit) in [(beta * r, true), (-beta * r, false)] {
                    let path = one([m + 1.0, m - 1.0], [-1.0, 1.0], [0.0; 2]);
                    for (p, q) in [([a, a], [0.0, 0.0]), ([0.0, 0.0], [a, a])] {
                        let object = segment(p, q, SegmentSide::Both);
                        let t = first_segment_contact(&path, &object, r, INF);
                        assert_eq!(t.is_some(), hit, "a {a}, m {m}, P {p:?}");
                        if let Some(t) = t {
                            assert!((t - exact).abs() <= 4.0 * f64::EPSILON, "{a} {m}: {t}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn near_the_far_end_the_time_is_as_accurate_as_near_the_near_one() {
        // The diagonal y = x from far away (P = (a, a)) to the origin; the ball comes at it
        // square on and touches it next to Q, at (0.75, 0.75) ± r/√2: at t = (1 − √2/4)/2.
        // With x − P formed plainly, its rounding (1e-10 across the line) would move the
        // contact by 1e-10; it is a few ulp off.
        let exact = (1.0 - 2f64.sqrt() / 4.0) / 2.0;
        let down = one([0.25, 1.25], [1.0, -1.0], [0.0; 2]);
        for a in [1.0, 712_345.678_901, 3.3e15] {
            let object = segment([a, a], [0.0, 0.0], SegmentSide::Both);
            let t = first_segment_contact(&down, &object, 0.25, INF).expect("a contact");
            assert!(
                (t - exact).abs() <= 4.0 * f64::EPSILON * exact,
                "{a}: {t} vs {exact}"
            );
        }
    }
}
