//! Invariances of the contacts with static geometry, as property tests (issue 36, "Proof").
//!
//! Exact symmetries of float arithmetic must give the same bits: quarter turns and
//! reflections in the plane (a reflection flips a segment's side), sign flips of the axes and
//! quarter turns about the vertical in space (planes, spheres), every length scaled by a
//! power of two over the whole exponent range (and a plane's normal by another), a
//! translation by exact amounts (segments and planes, whose queries form every difference
//! from the caller's own numbers), a horizon after the contact, the box walls against the
//! planes they are, a circle or a target against the pair search with a ball at rest.
//! Inexact ones must agree within [`close`]'s tolerance, on configurations that are
//! [`robust`] (not within rounding of a graze or of a segment's end, where the hit/miss
//! answer is legitimately undecided): a segment reversed (`P` and `Q` swapped, its side
//! flipped), a circle or a target translated. Every answer must be valid (finite, from the
//! first start on, before the horizon; for numbers from the whole float range too) and a
//! contact (at the contact distance there, or within it at a start).
//!
//! Every property runs a fixed number of cases from a fixed seed.

use crate::support::property_paths;

use ballcollide::geometry::{
    Circle, LineSegment, Plane, SegmentSide, Target, path_circle_contact, path_plane_contact,
    path_segment_contact, path_target_contact,
};
use ballcollide::path::{Path, Segment};
use ballcollide::schedule::Walls;
use ballcollide::{CollisionOptions, InputErrorKind};
use nalgebra::{SVector, Vector2, Vector3};
use property_paths::{bits, config, wild, wild_path};
use proptest::prelude::*;

const INF: f64 = f64::INFINITY;

type Vector<const D: usize> = SVector<f64, D>;

/// A static object, as plain numbers (a segment only in 2-D).
#[derive(Clone, Debug)]
enum Object<const D: usize> {
    Segment(Vector<D>, Vector<D>, SegmentSide),
    Circle(Vector<D>, f64),
    Target(Vector<D>, f64),
    Plane(Vector<D>, Vector<D>),
}

/// A path, a ball's radius and an object.
#[derive(Clone, Debug)]
struct Case<const D: usize> {
    path: Vec<Segment<D>>,
    radius: f64,
    object: Object<D>,
}

fn flat<const D: usize>(v: Vector<D>) -> Vector2<f64> {
    Vector2::new(v[0], v[1])
}

impl<const D: usize> Case<D> {
    fn time(&self) -> Option<f64> {
        self.time_until(INF)
    }

    fn time_until(&self, t_max: f64) -> Option<f64> {
        let path = Path::new(self.path.clone()).expect("valid segments");
        let options = CollisionOptions { t_max };
        let r = self.radius;
        match &self.object {
            Object::Segment(p, q, side) => {
                assert_eq!(D, 2, "segments are 2-D");
                let segments = self.path.iter();
                let flat_path = segments
                    .map(|s| {
                        let (p, v, a) = (s.position, s.velocity, s.acceleration);
                        Segment::new(s.start, flat(p), flat(v), flat(a))
                    })
                    .collect();
                let path = Path::new(flat_path).expect("valid segments");
                let object = LineSegment::new(flat(*p), flat(*q), *side).expect("valid segment");
                path_segment_contact(&path, &object, r, &options)
            }
            Object::Circle(c, rho) => {
                let object = Circle::new(*c, *rho).expect("valid circle");
                path_circle_contact(&path, &object, r, &options)
            }
            Object::Target(c, rho) => {
                let object = Target::new(*c, *rho).expect("valid target");
                path_target_contact(&path, &object, &options)
            }
            Object::Plane(point, normal) => {
                let object = Plane::new(*point, *normal).expect("valid plane");
                path_plane_contact(&path, &object, r, &options)
            }
        }
        .expect("valid radius and horizon")
    }

    fn first_start(&self) -> f64 {
        self.path[0].start
    }

    /// Every vector of the case (positions, velocities, accelerations, the object's points
    /// and normal) mapped by `f`; a segment's side flipped if `flip` (a reflection).
    fn mapped(&self, f: impl Fn(Vector<D>) -> Vector<D>, flip: bool) -> Self {
        let path = self
            .path
            .iter()
            .map(|s| Segment::new(s.start, f(s.position), f(s.velocity), f(s.acceleration)))
            .collect();
        let object = match &self.object {
            Object::Segment(p, q, side) => {
                let side = if flip { side.flipped() } else { *side };
                Object::Segment(f(*p), f(*q), side)
            }
            Object::Circle(c, rho) => Object::Circle(f(*c), *rho),
            Object::Target(c, rho) => Object::Target(f(*c), *rho),
            Object::Plane(point, normal) => Object::Plane(f(*point), f(*normal)),
        };
        Case {
            path,
            radius: self.radius,
            object,
        }
    }

    /// Every length times `2^k` (positions, velocities, accelerations, the object's points
    /// and radius, the ball's radius); a plane's normal times `2^n`. (In two factors, so that
    /// a `2^k` beyond the float range may still scale small numbers exactly.)
    fn scaled(&self, k: i32, n: i32) -> Self {
        let (up, rest) = (2f64.powi(k / 2), 2f64.powi(k - k / 2));
        let s = |v: Vector<D>| v * up * rest;
        let path = self
            .path
            .iter()
            .map(|x| Segment::new(x.start, s(x.position), s(x.velocity), s(x.acceleration)))
            .collect();
        let object = match &self.object {
            Object::Segment(p, q, side) => Object::Segment(s(*p), s(*q), *side),
            Object::Circle(c, rho) => Object::Circle(s(*c), rho * up * rest),
            Object::Target(c, rho) => Object::Target(s(*c), rho * up * rest),
            Object::Plane(point, normal) => Object::Plane(s(*point), normal * 2f64.powi(n)),
        };
        Case {
            path,
            radius: self.radius * up * rest,
            object,
        }
    }

    /// The positions and the object's points moved by `shift` (velocities, accelerations and
    /// a normal unchanged).
    fn translated(&self, shift: Vector<D>) -> Self {
        let path = self
            .path
            .iter()
            .map(|s| Segment {
                position: s.position + shift,
                ..*s
            })
            .collect();
        let object = match &self.object {
            Object::Segment(p, q, side) => Object::Segment(p + shift, q + shift, *side),
            Object::Circle(c, rho) => Object::Circle(c + shift, *rho),
            Object::Target(c, rho) => Object::Target(c + shift, *rho),
            Object::Plane(point, normal) => Object::Plane(point + shift, *normal),
        };
        Case {
            path,
            radius: self.radius,
            object,
        }
    }

    /// Every number that is a length, for the exponent range of exact scalings.
    fn lengths(&self) -> Vec<f64> {
        let mut out: Vec<f64> = self
            .path
            .iter()
            .flat_map(|s| {
                let v = [s.position, s.velocity, s.acceleration];
                v.into_iter()
                    .flat_map(|x| x.iter().copied().collect::<Vec<_>>())
            })
            .collect();
        out.push(self.radius);
        match &self.object {
            Object::Segment(p, q, _) => out.extend(p.iter().chain(q.iter())),
            Object::Circle(c, rho) | Object::Target(c, rho) => {
                out.extend(c.iter());
                out.push(*rho);
            }
            Object::Plane(point, _) => out.extend(point.iter()),
        }
        out
    }
}

// ---------------------------------------------------------------------------------------------
// Configurations

/// A path of 1–4 segments (see [`property_paths::path`]).
fn path<const D: usize>() -> impl Strategy<Value = Vec<Segment<D>>> {
    property_paths::path(4)
}

fn side() -> impl Strategy<Value = SegmentSide> {
    prop_oneof![
        Just(SegmentSide::Both),
        Just(SegmentSide::Left),
        Just(SegmentSide::Right)
    ]
}

fn point<const D: usize>() -> impl Strategy<Value = Vector<D>> {
    prop::array::uniform::<_, D>(-1.5..1.5f64).prop_map(Vector::from)
}

/// A segment with ends in the paths' box, at least 0.05 apart (2-D only).
fn segment_object<const D: usize>() -> impl Strategy<Value = Object<D>> {
    (point::<D>(), point::<D>(), side())
        .prop_filter("distinct ends", |(p, q, _)| (p - q).norm() > 0.05)
        .prop_map(|(p, q, side)| Object::Segment(p, q, side))
}

/// A circle (radius 0 one time in four) or a target about the paths' box.
fn disc_object<const D: usize>() -> impl Strategy<Value = Object<D>> {
    let rho = prop_oneof![1 => Just(0.0), 3 => 0.0..0.5f64];
    let circle = (point::<D>(), rho).prop_map(|(c, rho)| Object::Circle(c, rho));
    let target = (point::<D>(), 0.01..0.5f64).prop_map(|(c, rho)| Object::Target(c, rho));
    prop_oneof![circle, target]
}

/// A plane through the paths' box, its normal of any length up to 1.7.
fn plane_object<const D: usize>() -> impl Strategy<Value = Object<D>> {
    (point::<D>(), prop::array::uniform::<_, D>(-1.0..1.0f64))
        .prop_filter("a normal", |(_, n)| n.iter().any(|x| x.abs() > 0.05))
        .prop_map(|(q, n)| Object::Plane(q, n.into()))
}

/// Any object (segments only in 2-D).
fn object<const D: usize>() -> BoxedStrategy<Object<D>> {
    if D == 2 {
        prop_oneof![3 => segment_object(), 2 => disc_object(), 1 => plane_object()].boxed()
    } else {
        prop_oneof![1 => disc_object(), 1 => plane_object()].boxed()
    }
}

/// A path (1–4 segments), a ball's radius, and an object of `objects`; in two cases out of
/// three the object is moved to within half a metre (in each coordinate) of where the ball
/// is at a random time in its first 3 s, so that many cases touch.
fn case_of<const D: usize>(
    objects: impl Strategy<Value = Object<D>>,
) -> impl Strategy<Value = Case<D>> {
    let aim = (
        prop::bool::weighted(2.0 / 3.0),
        0.0..3.0f64,
        prop::array::uniform::<_, D>(-0.5..0.5f64),
    );
    (path::<D>(), 0.05..0.5f64, objects, aim).prop_map(
        |(path, radius, object, (aimed, time, offset))| {
            let case = Case {
                path,
                radius,
                object,
            };
            if !aimed {
                return case;
            }
            let segments = Path::new(case.path.clone()).expect("valid segments");
            let at = segments.position_at(case.first_start() + time) + Vector::from(offset);
            let object = match case.object {
                Object::Segment(p, q, side) => {
                    let shift = at - (p + q) * 0.5;
                    Object::Segment(p + shift, q + shift, side)
                }
                Object::Circle(_, rho) => Object::Circle(at, rho),
                Object::Target(_, rho) => Object::Target(at, rho),
                Object::Plane(_, normal) => Object::Plane(at, normal),
            };
            Case { object, ..case }
        },
    )
}

fn case<const D: usize>() -> impl Strategy<Value = Case<D>> {
    case_of(object::<D>())
}

/// Whether the answer is decided well away from rounding: the same hit or miss, and times
/// within 1e-6·(1 + t), with the radius (a target's `ρ`) 1e-7 larger or smaller and a
/// segment 1e-7 (of its length) longer or shorter at both ends. A graze, a contact next to
/// a segment's end, or touching tangentially at the start fails it.
fn robust<const D: usize>(case: &Case<D>) -> bool {
    let t = case.time();
    let mut variants = Vec::new();
    for f in [1.0 + 1e-7, 1.0 - 1e-7] {
        let mut c = case.clone();
        c.radius *= f;
        c.object = match c.object {
            Object::Target(centre, rho) => Object::Target(centre, rho * f),
            Object::Segment(p, q, side) => {
                let grow = (q - p) * (f - 1.0);
                Object::Segment(p - grow, q + grow, side)
            }
            other => other,
        };
        variants.push(c.time());
    }
    variants.into_iter().all(|other| match (t, other) {
        (None, None) => true,
        (Some(t), Some(u)) => (t - u).abs() <= 1e-6 * (1.0 + t.abs()),
        _ => false,
    })
}

/// Whether two answers agree: both none, or both hits within 1e-9·(|t| + 1).
fn close(x: Option<f64>, y: Option<f64>) -> Result<(), TestCaseError> {
    match (x, y) {
        (None, None) => Ok(()),
        (Some(x), Some(y)) => {
            prop_assert!((x - y).abs() <= 1e-9 * (x.abs() + 1.0), "{x} vs {y}");
            Ok(())
        }
        _ => Err(TestCaseError::fail(format!(
            "hit/miss differ: {x:?} vs {y:?}"
        ))),
    }
}

// ---------------------------------------------------------------------------------------------
// Checks

/// A map of vectors.
type Map<const D: usize> = fn(Vector<D>) -> Vector<D>;

/// The 2-D vector maps that are exact, and whether each is a reflection.
fn exact_maps_2d() -> [(Map<2>, bool); 4] {
    [
        (|v| Vector2::new(-v.y, v.x), false),
        (|v| Vector2::new(-v.x, -v.y), false),
        (|v| Vector2::new(-v.x, v.y), true),
        (|v| Vector2::new(v.y, v.x), true),
    ]
}

/// The 3-D maps that are exact for every query here: quarter turns about z, sign flips.
fn exact_maps_3d() -> [Map<3>; 4] {
    [
        |v| Vector3::new(-v.y, v.x, v.z),
        |v| Vector3::new(-v.x, v.y, v.z),
        |v| Vector3::new(v.x, -v.y, v.z),
        |v| Vector3::new(v.x, v.y, -v.z),
    ]
}

fn check_units<const D: usize>(case: &Case<D>, where_: f64, n: i32) -> Result<(), TestCaseError> {
    let t = bits(case.time());
    let (lo, hi) = property_paths::exponent_range(case.lengths());
    let middle = lo + ((hi - lo) as f64 * where_) as i32;
    let mut checked = 0;
    for k in [lo, middle, hi, -400, 400, -1, 1] {
        if k < lo || k > hi {
            continue;
        }
        let scaled = case.scaled(k, n);
        prop_assert_eq!(t, bits(scaled.time()), "2^{}", k);
        checked += 1;
    }
    prop_assert!(
        checked >= 3,
        "only {checked} exact scalings in [{lo}, {hi}]"
    );
    Ok(())
}

fn check_horizon<const D: usize>(case: &Case<D>, f: f64) -> Result<(), TestCaseError> {
    property_paths::check_horizon(|t_max| case.time_until(t_max), case.first_start(), f)
}

/// An answer is a valid time, and a contact: at the contact distance there (to 1e-9 and the
/// rounding of the position and the object's numbers), or
/// within it at a segment start (a first start or a jump); a segment's foot on it and on a
/// side that counts.
fn check_contact<const D: usize>(case: &Case<D>) -> Result<(), TestCaseError> {
    let Some(t) = case.time() else {
        return Ok(());
    };
    prop_assert!(t.is_finite() && t >= case.first_start(), "{t}");
    let path = Path::new(case.path.clone()).expect("valid");
    let x = path.position_at(t);
    // The position's own rounding at t (its terms' size), and the object's numbers'.
    let segment = path.segment_at(t);
    let s = t - segment.start;
    let size = (segment.position.abs()
        + segment.velocity.abs() * s
        + segment.acceleration.abs() * (0.5 * s * s))
        .norm()
        + case.lengths().iter().map(|x| x.abs()).fold(0.0, f64::max);
    let tolerance = 1e-9 + 64.0 * f64::EPSILON * size;
    let at_start = case.path.iter().any(|s| s.start == t);
    let r = case.radius;
    let (distance, contact) = match &case.object {
        Object::Segment(p, q, side) => {
            let (p, q, x) = (flat(*p), flat(*q), flat(x));
            let e = q - p;
            let d = (e.x * (x - p).y - e.y * (x - p).x) / e.norm();
            let u = (x - p).dot(&e) / e.norm_squared();
            let slack = tolerance / e.norm();
            prop_assert!((-slack..=1.0 + slack).contains(&u), "u = {u} at {t}");
            let sign = if d > 0.0 {
                1
            } else if d < 0.0 {
                -1
            } else {
                0
            };
            prop_assert!(
                side.sign() == 0 || side.sign() == sign || d.abs() < 1e-9,
                "side {d}"
            );
            (d.abs(), r)
        }
        Object::Circle(c, rho) => ((x - c).norm(), rho + r),
        Object::Target(c, rho) => ((x - c).norm(), *rho),
        Object::Plane(point, normal) => ((x - point).dot(normal) / normal.norm(), r),
    };
    prop_assert!(
        distance <= contact + tolerance,
        "{distance} vs {contact} at {t}"
    );
    if !at_start {
        prop_assert!(
            distance >= contact - tolerance,
            "{distance} vs {contact} at {t}"
        );
    }
    Ok(())
}

/// An object with numbers from the whole float range (valid: a segment's ends apart, radii
/// not negative, a normal not zero).
fn wild_object<const D: usize>() -> BoxedStrategy<Object<D>> {
    let point = || prop::array::uniform::<_, D>(wild()).prop_map(Vector::from);
    let segment = (point(), point(), side())
        .prop_filter("distinct ends", |(p, q, _)| p != q)
        .prop_map(|(p, q, side)| Object::Segment(p, q, side));
    let circle = (point(), wild()).prop_map(|(c, rho)| Object::Circle(c, rho.abs()));
    let target = (point(), wild())
        .prop_filter("a radius", |(_, rho)| *rho != 0.0)
        .prop_map(|(c, rho)| Object::Target(c, rho.abs()));
    let plane = (point(), point())
        .prop_filter("a normal", |(_, n)| n.iter().any(|x| *x != 0.0))
        .prop_map(|(q, n)| Object::Plane(q, n));
    if D == 2 {
        prop_oneof![segment, circle, target, plane].boxed()
    } else {
        prop_oneof![circle, target, plane].boxed()
    }
}

/// A wild case and horizon: paths, objects and radii from the whole float range.
fn wild_case<const D: usize>() -> impl Strategy<Value = (Case<D>, f64)> {
    let radius = wild().prop_map(|r| if r == 0.0 { 1.0 } else { r.abs() });
    let t_max = prop_oneof![Just(INF), Just(0.0), wild().prop_map(f64::abs)];
    (wild_path::<D>(), radius, wild_object::<D>(), t_max).prop_map(
        |(path, radius, object, t_max)| {
            (
                Case {
                    path,
                    radius,
                    object,
                },
                t_max,
            )
        },
    )
}

/// An answer from anywhere in the float range is a finite time from the first start on,
/// before the horizon (never a panic, never NaN).
fn check_valid<const D: usize>((case, t_max): (Case<D>, f64)) -> Result<(), TestCaseError> {
    if let Some(t) = case.time_until(t_max) {
        prop_assert!(t.is_finite() && t >= case.first_start() && t < t_max, "{t}");
    }
    Ok(())
}

proptest! {
    #![proptest_config(config(1000, 0x36_0001))]

    #[test]
    fn answers_over_the_whole_float_range_are_valid_in_2d(case in wild_case::<2>()) {
        check_valid(case)?;
    }

    #[test]
    fn answers_over_the_whole_float_range_are_valid_in_3d(case in wild_case::<3>()) {
        check_valid(case)?;
    }

    #[test]
    fn exact_maps_in_the_plane_change_no_bit(case in case::<2>()) {
        let t = bits(case.time());
        for (f, reflection) in exact_maps_2d() {
            prop_assert_eq!(t, bits(case.mapped(f, reflection).time()));
        }
    }

    #[test]
    fn exact_maps_in_space_change_no_bit(case in case::<3>()) {
        let t = bits(case.time());
        for f in exact_maps_3d() {
            prop_assert_eq!(t, bits(case.mapped(f, false).time()));
        }
    }

    #[test]
    fn powers_of_two_change_no_bit_in_2d(
        case in case::<2>(), where_ in 0.0..1.0f64, n in -300i32..300,
    ) {
        check_units(&case, where_, n)?;
    }

    #[test]
    fn powers_of_two_change_no_bit_in_3d(
        case in case::<3>(), where_ in 0.0..1.0f64, n in -300i32..300,
    ) {
        check_units(&case, where_, n)?;
    }

    #[test]
    fn a_horizon_only_cuts_in_2d(case in case::<2>(), f in 0.0..1.0f64) {
        check_horizon(&case, f)?;
    }

    #[test]
    fn a_horizon_only_cuts_in_3d(case in case::<3>(), f in 0.0..1.0f64) {
        check_horizon(&case, f)?;
    }

    #[test]
    fn answers_are_contacts_in_2d(case in case::<2>()) {
        check_contact(&case)?;
    }

    #[test]
    fn answers_are_contacts_in_3d(case in case::<3>()) {
        check_contact(&case)?;
    }

    #[test]
    fn an_exact_translation_moves_no_bit_of_a_segment_or_a_plane(
        case in case_of(prop_oneof![segment_object::<2>(), plane_object::<2>()]),
        shift in prop::array::uniform2(-1000i32..1000),
    ) {
        // On the grid of 2⁻³⁰, an integer shift below 2¹¹ is exact.
        let grid = |x: f64| (x * 2f64.powi(30)).round() / 2f64.powi(30);
        let case = Case {
            path: case.path.iter().map(|s| Segment { position: s.position.map(grid), ..*s }).collect(),
            object: match case.object {
                Object::Segment(p, q, side) => Object::Segment(p.map(grid), q.map(grid), side),
                Object::Plane(point, normal) => Object::Plane(point.map(grid), normal),
                other => other,
            },
            ..case
        };
        let shift = Vector2::new(f64::from(shift[0]), f64::from(shift[1]));
        prop_assert_eq!(bits(case.time()), bits(case.translated(shift).time()));
    }

    #[test]
    fn a_translated_circle_or_target_moves_nothing(
        case in case_of(disc_object::<2>()),
        shift in prop::array::uniform2(-1000.0..1000.0f64),
    ) {
        prop_assume!(robust(&case));
        close(case.time(), case.translated(Vector2::from(shift)).time())?;
    }

    #[test]
    fn reversing_a_segment_flips_its_side_and_moves_nothing(case in case_of(segment_object::<2>())) {
        let Object::Segment(p, q, side) = case.object else {
            return Err(TestCaseError::reject("not a segment"));
        };
        prop_assume!(robust(&case));
        let reversed = Case { object: Object::Segment(q, p, side.flipped()), ..case.clone() };
        close(case.time(), reversed.time())?;
        // And with the side not flipped, the other side's contacts count.
        if side != SegmentSide::Both {
            let other = Case { object: Object::Segment(q, p, side), ..case.clone() };
            let flipped = Case { object: Object::Segment(p, q, side.flipped()), ..case.clone() };
            prop_assume!(robust(&flipped));
            close(other.time(), flipped.time())?;
        }
    }

    #[test]
    fn a_circle_or_a_target_is_a_ball_at_rest(case in case_of(disc_object::<2>())) {
        let (centre, contact) = match case.object {
            Object::Circle(c, rho) => (c, rho + case.radius),
            Object::Target(c, rho) => (c, rho),
            _ => return Err(TestCaseError::reject("not a disc")),
        };
        let path = Path::new(case.path.clone()).expect("valid");
        let rest = Path::new(vec![Segment::at_rest(case.first_start(), centre)]).expect("valid");
        let options = CollisionOptions::default();
        let pair = ballcollide::path_collision_time(&path, &rest, contact, &options);
        prop_assert_eq!(bits(case.time()), bits(pair.expect("valid")));
    }

    #[test]
    fn the_box_walls_are_the_planes_they_are(
        path in path::<2>(), radius in 0.05..0.5f64,
        lo in prop::array::uniform2(-2.0..-0.5f64), hi in prop::array::uniform2(0.5..2.0f64),
    ) {
        let walls = Walls::new(lo, hi).expect("a box");
        let path = Path::new(path).expect("valid");
        let options = CollisionOptions::default();
        let wall = walls.first_contact(&path, radius, INF).expect("valid").map(|w| w.0);
        let mut best: Option<f64> = None;
        for axis in 0..2 {
            for (bound, sign) in [(lo[axis], 1.0), (hi[axis], -1.0)] {
                let mut point = Vector2::zeros();
                point[axis] = bound;
                let mut normal = Vector2::zeros();
                normal[axis] = sign;
                let plane = Plane::new(point, normal).expect("a plane");
                if let Some(t) = path_plane_contact(&path, &plane, radius, &options).expect("valid") {
                    best = Some(best.map_or(t, |b: f64| b.min(t)));
                }
            }
        }
        prop_assert_eq!(bits(wall), bits(best));
    }
}

#[test]
fn the_robustness_filter_rejects_grazes_and_ends_and_keeps_clear_answers() {
    let down = |x: f64, y: f64| {
        vec![Segment::new(
            0.0,
            Vector2::new(x, y),
            Vector2::new(0.0, -1.0),
            Vector2::zeros(),
        )]
    };
    let segment = |side| Object::Segment(Vector2::new(0.0, 0.0), Vector2::new(2.0, 0.0), side);
    let case = |x: f64| Case {
        path: down(x, 1.0),
        radius: 0.25,
        object: segment(SegmentSide::Both),
    };
    assert!(robust(&case(1.0))); // a clear hit
    assert!(robust(&case(3.0))); // a clear miss
    assert!(!robust(&case(2.0))); // over the end
    assert!(!robust(&case(2.0 + 1e-9))); // just beyond it
    let pass = Case {
        path: vec![Segment::new(
            0.0,
            Vector2::new(-1.0, 0.5),
            Vector2::new(1.0, 0.0),
            Vector2::zeros(),
        )],
        radius: 0.5,
        object: Object::Circle(Vector2::new(0.0, 0.0), 0.0),
    };
    assert!(!robust(&pass)); // tangent
}

#[test]
fn bad_radii_and_horizons_are_named() {
    let path = Path::new(vec![Segment::at_rest(0.0, Vector2::zeros())]).expect("valid");
    let segment = LineSegment::new(
        Vector2::new(0.0, 1.0),
        Vector2::new(1.0, 1.0),
        SegmentSide::Both,
    )
    .expect("valid");
    let circle = Circle::new(Vector2::new(0.0, 1.0), 0.5).expect("valid");
    let plane = Plane::new(Vector2::new(0.0, 1.0), Vector2::new(0.0, -1.0)).expect("valid");
    let target = Target::new(Vector2::new(0.0, 1.0), 0.5).expect("valid");
    let ok = CollisionOptions::default();
    let negative = CollisionOptions { t_max: -1.0 };
    for radius in [0.0, -1.0, f64::NAN, INF] {
        let errors = [
            path_segment_contact(&path, &segment, radius, &ok).unwrap_err(),
            path_circle_contact(&path, &circle, radius, &ok).unwrap_err(),
            path_plane_contact(&path, &plane, radius, &ok).unwrap_err(),
        ];
        for e in errors {
            assert_eq!(e.argument(), "radius", "{e}");
        }
    }
    let errors = [
        path_segment_contact(&path, &segment, 0.1, &negative).unwrap_err(),
        path_circle_contact(&path, &circle, 0.1, &negative).unwrap_err(),
        path_plane_contact(&path, &plane, 0.1, &negative).unwrap_err(),
        path_target_contact(&path, &target, &negative).unwrap_err(),
    ];
    for e in errors {
        assert_eq!(
            (e.argument(), e.kind()),
            ("t_max", InputErrorKind::InvalidHorizon(-1.0))
        );
    }
}

#[test]
fn the_configurations_hit_often_enough_to_test_contacts() {
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;
    let mut runner = TestRunner::deterministic();
    let mut counts = [[0usize; 2]; 4];
    for _ in 0..4000 {
        let case = case::<2>().new_tree(&mut runner).expect("a case").current();
        let kind = match case.object {
            Object::Segment(..) => 0,
            Object::Circle(..) => 1,
            Object::Target(..) => 2,
            Object::Plane(..) => 3,
        };
        counts[kind][usize::from(case.time().is_some())] += 1;
    }
    for (kind, [misses, hits]) in counts.iter().enumerate() {
        eprintln!("object {kind}: {hits} hits, {misses} misses");
        assert!(
            *hits * 5 >= *hits + *misses,
            "object {kind}: {hits} hits of {}",
            hits + misses
        );
    }
}
