//! A scene's static objects together: [`Table`], the kinds of object ([`ObjectKind`]) and a
//! ball's contact with one of them ([`ObjectContact`]).

use crate::collision::length_unit::{norm_in_range, unit_of_largest};
use nalgebra::Vector2;

use super::shapes::{Circle, LineSegment, Plane, Target};
use crate::path::Segment;

/// How far beyond its ends a segment's box reaches, relative to the largest magnitude of its
/// ends: `2⁻³⁶`, some `2¹⁶` times the largest error its contact's foot test ever had there
/// (see [`Table::object_box`]; the same factor as the calendar's boxes of the balls).
const SEGMENT_MARGIN: f64 = 1.0 / ((1u64 << 36) as f64);

/// The kind of a static object, with its number (the Python layer's `SEGMENT`, `CIRCLE`,
/// `TARGET`, `PLANE`): the order in which contacts at one time are reported.
///
/// ```
/// use ballcollide::geometry::ObjectKind;
/// assert_eq!(ObjectKind::Target.code(), 2);
/// assert!(ObjectKind::Segment < ObjectKind::Plane);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum ObjectKind {
    /// A [`LineSegment`] (`0`).
    Segment,
    /// A [`Circle`] (`1`).
    Circle,
    /// A [`Target`] (`2`).
    Target,
    /// A [`Plane`] (`3`).
    Plane,
}

impl ObjectKind {
    /// Every kind, in order.
    pub const ALL: [Self; 4] = [Self::Segment, Self::Circle, Self::Target, Self::Plane];

    /// The kind's number (example: [`ObjectKind`]).
    pub const fn code(self) -> u8 {
        self as u8
    }

    /// The kind's name, as the Python layer's constant is named but in lower case:
    /// `"segment"`, `"circle"`, `"target"`, `"plane"`.
    pub const fn name(self) -> &'static str {
        match self {
            Self::Segment => "segment",
            Self::Circle => "circle",
            Self::Target => "target",
            Self::Plane => "plane",
        }
    }
}

/// A ball's first contact with one object of a [`Table`]: when, the object's kind and its
/// index among the objects of that kind.
///
/// Contacts are ordered by time, then kind ([`ObjectKind`]'s order), then index.
///
/// ```
/// use ballcollide::geometry::{ObjectContact, ObjectKind};
/// let a = ObjectContact { time: 1.0, kind: ObjectKind::Segment, index: 3 };
/// let b = ObjectContact { time: 1.0, kind: ObjectKind::Circle, index: 0 };
/// assert!(a.before(&b));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ObjectContact {
    /// When the ball starts to touch the object (absolute).
    pub time: f64,
    /// The object's kind.
    pub kind: ObjectKind,
    /// The object's index among the table's objects of its kind.
    pub index: usize,
}

impl ObjectContact {
    /// Whether `self` comes before `other`: by time, then kind, then index (example:
    /// [`ObjectContact`]).
    pub fn before(&self, other: &Self) -> bool {
        (self.time, self.kind, self.index) < (other.time, other.kind, other.index)
    }
}

/// The static objects of a scene: a pool table's cushions and jaws (segments), the jaws'
/// rounded tips (circles), its pockets (targets) and its bed (a plane); a curling sheet's or a
/// silo's walls. Objects are numbered within their kind, in the order given.
///
/// In 3-D a segment is the vertical wall over its line: its contact is that of the centre's
/// `(x, y)`; circles and targets are spheres, planes planes.
///
/// ```
/// use ballcollide::geometry::{Circle, LineSegment, SegmentSide, Table, Target};
/// use nalgebra::Vector2;
///
/// let cushion = LineSegment::new(Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), SegmentSide::Left)?;
/// let pocket = Target::new(Vector2::new(-0.05, -0.05), 0.06)?;
/// let table = Table { segments: vec![cushion], targets: vec![pocket], ..Default::default() };
/// assert_eq!(table.len(), 2);
/// # Ok::<(), ballcollide::InputError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Table<const D: usize> {
    /// Straight segments, each touched from its side.
    pub segments: Vec<LineSegment>,
    /// Circles (a jaw's tip, a segment's rounded end), touched from outside.
    pub circles: Vec<Circle<D>>,
    /// Targets (pockets): a ball whose centre enters one is captured.
    pub targets: Vec<Target<D>>,
    /// Planes, touched from the side their normal points to.
    pub planes: Vec<Plane<D>>,
}

impl<const D: usize> Default for Table<D> {
    fn default() -> Self {
        Self {
            segments: Vec::new(),
            circles: Vec::new(),
            targets: Vec::new(),
            planes: Vec::new(),
        }
    }
}

impl<const D: usize> Table<D> {
    /// How many objects the table has, of every kind (example: [`Table`]).
    pub fn len(&self) -> usize {
        self.segments.len() + self.circles.len() + self.targets.len() + self.planes.len()
    }

    /// Whether the table has no object.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// How many objects of `kind` there are.
    pub fn count(&self, kind: ObjectKind) -> usize {
        match kind {
            ObjectKind::Segment => self.segments.len(),
            ObjectKind::Circle => self.circles.len(),
            ObjectKind::Target => self.targets.len(),
            ObjectKind::Plane => self.planes.len(),
        }
    }

    /// The box `(lo, hi)` of object `index` of `kind` (`None`: unbounded, a plane), each
    /// bound rounded outwards; for a segment in 3-D the vertical extent is unbounded.
    ///
    /// A segment's box is its ends' grown by [`SEGMENT_MARGIN`] of their largest magnitude, a
    /// margin to spare: its contact's foot test (`0 ≤ (x − P)·e`, `(x − Q)·e ≤ 0`,
    /// `path_segment_contact`) is exact to a few roundings of the centre's distance from the
    /// end it tests, so that it takes a ball beyond an end for on the segment by at most a few
    /// roundings of that distance (it once took one up to `2⁻⁵³` of the other end's distance
    /// beyond it), and the calendar, which leaves out the objects whose boxes a ball's box
    /// misses, must find every contact that asking every object finds.
    pub(crate) fn object_box(
        &self,
        kind: ObjectKind,
        index: usize,
    ) -> Option<([f64; D], [f64; D])> {
        let (lo, hi): ([f64; D], [f64; D]) = match kind {
            ObjectKind::Segment => {
                let s = &self.segments[index];
                let (p, q) = (s.p(), s.q());
                let grow = SEGMENT_MARGIN * p.amax().max(q.amax());
                // The plane's two axes; in 3-D the vertical wall is unbounded upwards.
                (
                    std::array::from_fn(|k| match k {
                        0 | 1 => (p[k].min(q[k]) - grow).next_down(),
                        _ => f64::NEG_INFINITY,
                    }),
                    std::array::from_fn(|k| match k {
                        0 | 1 => (p[k].max(q[k]) + grow).next_up(),
                        _ => f64::INFINITY,
                    }),
                )
            }
            ObjectKind::Circle | ObjectKind::Target => {
                let (c, rho) = match kind {
                    ObjectKind::Circle => (self.circles[index].centre(), self.circles[index].rho()),
                    _ => (self.targets[index].centre(), self.targets[index].rho()),
                };
                (
                    std::array::from_fn(|k| (c[k] - rho).next_down()),
                    std::array::from_fn(|k| (c[k] + rho).next_up()),
                )
            }
            ObjectKind::Plane => return None,
        };
        Some((lo, hi))
    }
}

/// A path's segments in the plane of a [`LineSegment`]: their `(x, y)` components (in 2-D a
/// copy), written over `out`.
pub(crate) fn planar<const D: usize>(segments: &[Segment<D>], out: &mut Vec<Segment<2>>) {
    // (`D < 2` has no plane: its one axis and 0.)
    let xy = |v: &nalgebra::SVector<f64, D>| Vector2::new(v[0], v.get(1).copied().unwrap_or(0.0));
    out.clear();
    out.extend(segments.iter().map(|s| {
        Segment::new(
            s.start,
            xy(&s.position),
            xy(&s.velocity),
            xy(&s.acceleration),
        )
    }));
}

impl Table<2> {
    /// The distance of a centre at `x` from object `index` of `kind` where a ball there would
    /// touch it: for a segment, from its line, if the foot lies on it and the side counts
    /// (else `None`); for a circle, from its rim; for a target, from its centre; for a plane,
    /// the signed distance (negative behind it).
    pub(crate) fn distance_to(
        &self,
        kind: ObjectKind,
        index: usize,
        x: Vector2<f64>,
    ) -> Option<f64> {
        match kind {
            ObjectKind::Segment => {
                let s = &self.segments[index];
                let (e, w) = (s.q() - s.p(), x - s.p());
                // In the unit of the larger (a power of two: the same bits at every scale,
                // no square overflowing or underflowing).
                let unit = unit_of_largest(e.amax().max(w.amax()));
                let (e, w) = (e.map(|c| unit.apply(c)), w.map(|c| unit.apply(c)));
                let along = w.dot(&e) / e.norm_squared();
                let d = unit.restore((e.x * w.y - e.y * w.x) / e.norm());
                let sign = if d > 0.0 {
                    1
                } else if d < 0.0 {
                    -1
                } else {
                    0
                };
                ((0.0..=1.0).contains(&along) && s.side().counts(sign)).then_some(d.abs())
            }
            ObjectKind::Circle => {
                let c = &self.circles[index];
                Some(norm_in_range(&(x - c.centre())) - c.rho())
            }
            ObjectKind::Target => Some(norm_in_range(&(x - self.targets[index].centre()))),
            ObjectKind::Plane => {
                let p = &self.planes[index];
                let n = p.normal();
                Some((n / norm_in_range(&n)).dot(&(x - p.point())))
            }
        }
    }

    /// The unit normal of object `index` of `kind` (not a target) at a ball's centre `x` in
    /// contact: from the contact point towards the centre.
    pub(crate) fn normal_at(
        &self,
        kind: ObjectKind,
        index: usize,
        x: Vector2<f64>,
    ) -> Vector2<f64> {
        let unit = |v: Vector2<f64>| {
            let length = norm_in_range(&v);
            if length > 0.0 && length.is_finite() {
                v / length
            } else {
                Vector2::zeros()
            }
        };
        match kind {
            ObjectKind::Segment => {
                let s = &self.segments[index];
                let e = s.q() - s.p();
                let left = Vector2::new(-e.y, e.x);
                let n = unit(left);
                if n.dot(&(x - s.p())) >= 0.0 { n } else { -n }
            }
            ObjectKind::Circle => unit(x - self.circles[index].centre()),
            ObjectKind::Target => Vector2::zeros(),
            ObjectKind::Plane => unit(self.planes[index].normal()),
        }
    }
}
