//! A pool table as static geometry: [`PoolTable`] and its [`Table`].
//!
//! Six rails (cushion noses, one segment each, between the pockets), two jaws per pocket (a
//! segment each, turned towards the pocket's axis so that the throat is narrower than the
//! mouth), a round tip where each rail meets its jaw (a circle tangent to both, the rail and
//! the jaw ending at the points of tangency), and a capture circle (a target) in each pocket's
//! throat: 18 segments, 12 circles, 6 targets.

use nalgebra::Vector2;

use super::shapes::{Circle, LineSegment, SegmentSide, Target};
use super::table::Table;
use crate::error::{InputError, InputErrorKind};

/// The dimensions of a pool table, in metres (or any one unit). The playing area (between the
/// cushion noses) is `[0, width] × [0, length]`; the corner pockets are at its corners, the
/// side pockets halfway along the long rails (`x = 0` and `x = width`).
///
/// The defaults are a 9-foot table after the WPA's specification (playing area 2.54 m ×
/// 1.27 m, corner mouths 4.6 in, side mouths 5.1 in), with jaws and pockets of a simplified
/// shape: a table for tests, benchmarks and pictures, not a copy of any one table.
///
/// ```
/// use ballcollide::geometry::PoolTable;
/// let table = PoolTable::default().table()?;
/// assert_eq!((table.segments.len(), table.circles.len(), table.targets.len()), (18, 12, 6));
/// # Ok::<(), ballcollide::InputError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PoolTable {
    /// The playing area's extent along `x` (the short side).
    pub width: f64,
    /// Its extent along `y` (the long side).
    pub length: f64,
    /// The width of a corner pocket's mouth, between the two noses.
    pub corner_mouth: f64,
    /// The width of a side pocket's mouth.
    pub side_mouth: f64,
    /// How far each jaw runs from its nose into the pocket.
    pub jaw_length: f64,
    /// The radius of the round tips where rails meet jaws.
    pub jaw_radius: f64,
    /// How far a corner pocket's jaws turn towards its axis, in degrees (from parallel).
    pub corner_jaw_angle: f64,
    /// How far a side pocket's jaws turn towards its axis, in degrees (from straight out).
    pub side_jaw_angle: f64,
    /// The radius of the capture circles (targets); each lies on its pocket's axis, a jaw's
    /// length beyond the middle of the mouth.
    pub pocket_radius: f64,
}

impl Default for PoolTable {
    fn default() -> Self {
        Self {
            width: 1.27,
            length: 2.54,
            corner_mouth: 0.1168,
            side_mouth: 0.1295,
            jaw_length: 0.04,
            jaw_radius: 0.005,
            corner_jaw_angle: 7.0,
            side_jaw_angle: 14.0,
            pocket_radius: 0.045,
        }
    }
}

/// One nose: where a rail meets a jaw.
struct Nose {
    /// The corner where the rail's and the jaw's lines meet.
    at: Vector2<f64>,
    /// The rail's normal into the table.
    rail_normal: Vector2<f64>,
    /// The jaw's direction from the nose into the pocket.
    jaw: Vector2<f64>,
    /// The jaw's normal towards the pocket's axis (its playing side).
    jaw_normal: Vector2<f64>,
}

impl PoolTable {
    /// The table's objects: the rails (segments 0–5, played from the table's side, running
    /// anticlockwise from the bottom rail), the jaws (segments 6–17, two per pocket, played
    /// from either side), the jaw tips (circles) and the pockets (targets 0–5: corners
    /// `(0, 0)`, `(width, 0)`, side `(width, length/2)`, corners `(width, length)`,
    /// `(0, length)`, side `(0, length/2)`).
    ///
    /// # Errors
    /// An [`InputError`] if the dimensions make a degenerate object (a NaN, a negative
    /// radius, mouths wider than the rails).
    pub fn table(&self) -> Result<Table<2>, InputError> {
        self.check()?;
        let (w, l) = (self.width, self.length);
        let c = self.corner_mouth / std::f64::consts::SQRT_2;
        let s = self.side_mouth / 2.0;
        let v = Vector2::new;
        // The pockets anticlockwise from (0, 0), each with its centre point (on the playing
        // area's border), its outward axis, and its noses: the one reached first going
        // anticlockwise along the rails (the end of the rail before it), then the other.
        let half = std::f64::consts::FRAC_1_SQRT_2;
        let pockets = [
            (v(0.0, 0.0), v(-half, -half), v(0.0, c), v(c, 0.0)),
            (v(w, 0.0), v(half, -half), v(w - c, 0.0), v(w, c)),
            (
                v(w, l / 2.0),
                v(1.0, 0.0),
                v(w, l / 2.0 - s),
                v(w, l / 2.0 + s),
            ),
            (v(w, l), v(half, half), v(w, l - c), v(w - c, l)),
            (v(0.0, l), v(-half, half), v(c, l), v(0.0, l - c)),
            (
                v(0.0, l / 2.0),
                v(-1.0, 0.0),
                v(0.0, l / 2.0 + s),
                v(0.0, l / 2.0 - s),
            ),
        ];
        let mut table = Table::default();
        let mut jaws = Vec::new();
        // Per pocket, the tangent points on the rails of its two noses.
        let mut rail_ends = Vec::new();
        for (k, &(_, axis, first, second)) in pockets.iter().enumerate() {
            let side_pocket = k % 3 == 2;
            let angle = if side_pocket {
                self.side_jaw_angle
            } else {
                self.corner_jaw_angle
            }
            .to_radians();
            let mut ends = [Vector2::zeros(); 2];
            for (m, (at, other)) in [(first, second), (second, first)].into_iter().enumerate() {
                let nose = self.nose(at, other, axis, angle, side_pocket);
                let (tip, on_rail, on_jaw) = tangent_circle(&nose, self.jaw_radius);
                if !(tip.x.is_finite() && tip.y.is_finite()) {
                    // (A jaw nearly along its rail: the tip tangent to both lies far out.)
                    let rule =
                        "puts a jaw tip's centre beyond the float range, with the jaw angles";
                    return Err(dimension("jaw_radius", self.jaw_radius, rule));
                }
                table.circles.push(Circle::new(tip, self.jaw_radius)?);
                let far = on_jaw + nose.jaw * self.jaw_length;
                if far == on_jaw {
                    let rule = "is too short for a jaw's two ends to differ in float64";
                    return Err(dimension("jaw_length", self.jaw_length, rule));
                }
                if !(far.x.is_finite() && far.y.is_finite()) {
                    return Err(dimension("jaw_length", self.jaw_length, BEYOND));
                }
                jaws.push(LineSegment::new(on_jaw, far, SegmentSide::Both)?);
                ends[m] = on_rail;
            }
            rail_ends.push(ends);
            // Halved first: the same bits as `(first + second) / 2` (halving is exact), but
            // no overflow on a table wider than half the float range.
            let middle = first / 2.0 + second / 2.0;
            let centre = middle + axis * self.jaw_length;
            if !(centre.x.is_finite() && centre.y.is_finite()) {
                return Err(dimension("jaw_length", self.jaw_length, BEYOND));
            }
            table.targets.push(Target::new(centre, self.pocket_radius)?);
        }
        // Rail k runs from pocket k's second nose to pocket k + 1's first (anticlockwise:
        // the table on its left), along the border's direction there: else the mouths and
        // tips leave no rail between the pockets.
        let directions = [
            v(1.0, 0.0),
            v(0.0, 1.0),
            v(0.0, 1.0),
            v(-1.0, 0.0),
            v(0.0, -1.0),
            v(0.0, -1.0),
        ];
        for (k, direction) in directions.into_iter().enumerate() {
            let from = rail_ends[k][1];
            let to = rail_ends[(k + 1) % 6][0];
            if (to - from).dot(&direction) <= 0.0 {
                let (argument, value) = if k % 3 == 1 {
                    ("side_mouth", self.side_mouth)
                } else {
                    ("corner_mouth", self.corner_mouth)
                };
                let rule = "leaves no rail between the pockets (with the jaw tips)";
                return Err(dimension(argument, value, rule));
            }
            table
                .segments
                .push(LineSegment::new(from, to, SegmentSide::Left)?);
        }
        table.segments.extend(jaws);
        Ok(table)
    }

    /// Every dimension finite; the lengths `> 0` (the jaw tips' radius `≥ 0` and below half the
    /// narrower mouth), the jaw angles in `[0°, 45°)`, the mouths apart in float64.
    fn check(&self) -> Result<(), InputError> {
        let bad = |argument, value, rule| Err(dimension(argument, value, rule));
        for (argument, value) in [
            ("width", self.width),
            ("length", self.length),
            ("corner_mouth", self.corner_mouth),
            ("side_mouth", self.side_mouth),
            ("jaw_length", self.jaw_length),
            ("pocket_radius", self.pocket_radius),
        ] {
            if !(value > 0.0 && value.is_finite()) {
                return bad(argument, value, "must be finite and > 0");
            }
        }
        // Each mouth's noses apart in float64 (a table far larger than its mouths rounds
        // them together).
        let c = self.corner_mouth / std::f64::consts::SQRT_2;
        let half = self.length / 2.0;
        let s = self.side_mouth / 2.0;
        let too_large = "is too large for the pockets' mouths to be told apart in float64";
        if self.width - c >= self.width {
            return bad("width", self.width, too_large);
        }
        if self.length - c >= self.length || half - s >= half + s {
            return bad("length", self.length, too_large);
        }
        if !(self.jaw_radius >= 0.0 && self.jaw_radius.is_finite()) {
            return bad("jaw_radius", self.jaw_radius, "must be finite and ≥ 0");
        }
        if self.jaw_radius >= self.corner_mouth.min(self.side_mouth) / 2.0 {
            let rule = "must be below half the narrower mouth";
            return bad("jaw_radius", self.jaw_radius, rule);
        }
        for (argument, value) in [
            ("corner_jaw_angle", self.corner_jaw_angle),
            ("side_jaw_angle", self.side_jaw_angle),
        ] {
            if !(0.0..45.0).contains(&value) {
                return bad(argument, value, "must be in [0, 45) degrees");
            }
        }
        Ok(())
    }

    /// The nose at `at` of a pocket (a side pocket's, or a corner's) whose other nose is
    /// `other` and outward axis `axis`, its jaw turned by `angle` towards the axis.
    fn nose(
        &self,
        at: Vector2<f64>,
        other: Vector2<f64>,
        axis: Vector2<f64>,
        angle: f64,
        side_pocket: bool,
    ) -> Nose {
        // The rail runs along the playing area's border through `at`, away from the pocket:
        // its normal into the table is the border's.
        let inside = Vector2::new(self.width / 2.0, self.length / 2.0);
        let towards_other = other - at;
        let along = if side_pocket {
            // Both noses on one rail line, along y (exact, where normalising a mouth beyond
            // 1e154 would overflow).
            Vector2::new(0.0, towards_other.y.signum())
        } else {
            // A corner pocket: the rail through `at` is the axis-parallel line through it
            // that stays on the border (x or y fixed at 0 or the full size).
            let on_x_border = at.x == 0.0 || at.x == self.width;
            if on_x_border {
                Vector2::new(0.0, 1.0)
            } else {
                Vector2::new(1.0, 0.0)
            }
        };
        let mut rail_normal = Vector2::new(-along.y, along.x);
        if rail_normal.dot(&(inside - at)) < 0.0 {
            rail_normal = -rail_normal;
        }
        // The jaw: from parallel to the axis (a corner pocket's) or straight out (a side
        // pocket's, the same here), turned towards the axis.
        let mut towards_axis = Vector2::new(-axis.y, axis.x);
        if towards_axis.dot(&towards_other) < 0.0 {
            towards_axis = -towards_axis;
        }
        let jaw = (axis * angle.cos() + towards_axis * angle.sin()).normalize();
        let mut jaw_normal = Vector2::new(-jaw.y, jaw.x);
        if jaw_normal.dot(&towards_other) < 0.0 {
            jaw_normal = -jaw_normal;
        }
        Nose {
            at,
            rail_normal,
            jaw,
            jaw_normal,
        }
    }
}

/// The rule a jaw length breaks that reaches past the float range from the table's edge.
const BEYOND: &str = "puts a jaw's end or a pocket's centre beyond the float range";

/// The error of a dimension, `argument` = `value`, against `rule`.
fn dimension(argument: &'static str, value: f64, rule: &'static str) -> InputError {
    InputError::new(argument, InputErrorKind::TableDimension { value, rule })
}

/// The circle of radius `rho` behind both faces of a nose and tangent to both: its centre,
/// and its points of tangency on the rail's line and on the jaw's.
fn tangent_circle(nose: &Nose, rho: f64) -> (Vector2<f64>, Vector2<f64>, Vector2<f64>) {
    // n_r·x = −ρ and n_j·x = −ρ for x = centre − nose, by Cramer's rule.
    let (a, b) = (nose.rail_normal, nose.jaw_normal);
    let det = a.x * b.y - a.y * b.x;
    let x = Vector2::new(
        (-rho * b.y + rho * a.y) / det,
        (-rho * a.x + rho * b.x) / det,
    );
    let centre = nose.at + x;
    (centre, centre + a * rho, centre + b * rho)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tips_touch_their_rail_and_jaw_and_rails_meet_tips() {
        let spec = PoolTable::default();
        let table = spec.table().expect("a table");
        for circle in &table.circles {
            // Each tip is tangent to one rail and one jaw: at distance ρ from both lines, with
            // the foot on the segment (at its end).
            let touching = table
                .segments
                .iter()
                .filter(|s| {
                    let (e, w) = (s.q() - s.p(), circle.centre() - s.p());
                    let d = (e.x * w.y - e.y * w.x).abs() / e.norm();
                    let u = w.dot(&e) / e.norm_squared();
                    (d - circle.rho()).abs() < 1e-12 && (-1e-9..=1.0 + 1e-9).contains(&u)
                })
                .count();
            assert_eq!(touching, 2, "{circle:?}");
        }
        // Rails lie on the playing area's border.
        for s in &table.segments[..6] {
            for p in [s.p(), s.q()] {
                let on = p.x.abs() < 1e-12
                    || (p.x - spec.width).abs() < 1e-12
                    || p.y.abs() < 1e-12
                    || (p.y - spec.length).abs() < 1e-12;
                assert!(on, "{s:?}");
            }
        }
        // The throats let a ball through: the jaws' far ends are more than a ball apart.
        for k in 0..6 {
            let (a, b) = (table.segments[6 + 2 * k], table.segments[7 + 2 * k]);
            assert!((a.q() - b.q()).norm() > 2.0 * 0.028575, "pocket {k}");
        }
    }

    #[test]
    fn a_jaw_tip_beyond_the_float_range_is_refused_naming_its_radius() {
        // Found by the property test below: a side jaw at 2.2e-308° to its rail puts the tip
        // tangent to both at infinity, which was refused as a `centre`, no dimension.
        let spec = PoolTable {
            width: f64::MAX,
            length: f64::MAX,
            corner_mouth: f64::MAX,
            side_mouth: f64::MAX,
            jaw_length: f64::MAX / 2.0,
            jaw_radius: 9.9792015476736e291,
            corner_jaw_angle: 7.0,
            side_jaw_angle: f64::MIN_POSITIVE,
            pocket_radius: 0.045,
        };
        let error = spec.table().expect_err("no table");
        assert_eq!(error.argument(), "jaw_radius", "{error}");
    }

    /// A dimension: the default, or any float of either sign and any exponent (the table's
    /// checks, and the geometry built from what passes them, meet the whole float range).
    fn dimension(default: f64) -> impl proptest::strategy::Strategy<Value = f64> {
        use proptest::prelude::*;
        prop_oneof![
            Just(default),
            (1.0f64..2.0, -1074i32..1024, any::<bool>()).prop_map(|(m, e, negative)| {
                let x =
                    m * 2f64.powi(e.max(-1022)) * if e < -1022 { 2f64.powi(e + 1022) } else { 1.0 };
                if negative { -x } else { x }
            }),
            Just(0.0),
            Just(f64::INFINITY),
            // The ends of the range, where sums of two dimensions overflow.
            Just(f64::MAX),
            Just(f64::MAX / 2.0),
            Just(f64::MIN_POSITIVE),
        ]
    }

    proptest::proptest! {
        /// Any dimensions give a table or an error naming one of them, never an error about
        /// a piece derived from them (a tip's `centre` beyond the float range).
        #[test]
        fn any_dimensions_give_a_table_or_name_one(
            width in dimension(1.27), length in dimension(2.54),
            corner_mouth in dimension(0.1168), side_mouth in dimension(0.1295),
            jaw_length in dimension(0.04), jaw_radius in dimension(0.005),
            corner_jaw_angle in dimension(7.0), side_jaw_angle in dimension(14.0),
            pocket_radius in dimension(0.045),
        ) {
            let spec = PoolTable {
                width, length, corner_mouth, side_mouth, jaw_length, jaw_radius,
                corner_jaw_angle, side_jaw_angle, pocket_radius,
            };
            if let Err(error) = spec.table() {
                let named = [
                    "width", "length", "corner_mouth", "side_mouth", "jaw_length", "jaw_radius",
                    "corner_jaw_angle", "side_jaw_angle", "pocket_radius",
                ];
                proptest::prop_assert!(named.contains(&error.argument()), "{spec:?}: {error}");
            }
        }
    }
}
