//! The walls of an axis-aligned box, and when a ball on a path first reaches one.
//!
//! A ball of radius `r` touches the low wall of axis `k` when its centre's coordinate `x_k`
//! reaches `lo_k + r` moving towards it, the high wall when `x_k` reaches `hi_k − r` moving
//! towards it. On a segment, the signed distance to a wall's contact plane is a quadratic in
//! the time `s` since the segment's start, `u(s) = c + b·s + q·s²` (`c = (x − lo) − r`,
//! `b = v`, `q = ½·a` for the low wall; the signs flipped and `c = (hi − x) − r` for the high
//! one): the contact is its first entry root (`u` going from positive to negative). The walk
//! along the path is the plane and segment queries' own
//! (`geometry/signed_distance.rs`, [`first_entry`]), with the pair's semantics: at the path's
//! first start a ball on or beyond the plane collides at once only if it moves towards the
//! wall; a path that jumps beyond a plane at a later segment start collides at that start; a
//! tangency is no contact.

use crate::error::{InputError, InputErrorKind, check_ball_radius, check_horizon, finite};
use crate::geometry::signed_distance::{Quadratic, first_entry};
use crate::path::{Path, Segment};

/// Which of an axis's two walls.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Side {
    /// The wall at the low bound `lo`.
    Low,
    /// The wall at the high bound `hi`.
    High,
}

/// The walls of the box `[lo_k, hi_k]` on every axis `k`.
///
/// ```
/// use ballcollide::schedule::Walls;
/// let walls = Walls::new([0.0, 0.0], [2.0, 1.0])?;
/// assert_eq!(walls.hi(), [2.0, 1.0]);
/// let err = Walls::new([0.0, 1.0], [2.0, 1.0]).unwrap_err();
/// assert_eq!(err.to_string(), "box[1]: the box's low bound must be below its high bound, got 1 and 1");
/// # Ok::<(), ballcollide::InputError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Walls<const D: usize> {
    lo: [f64; D],
    hi: [f64; D],
}

impl<const D: usize> Walls<D> {
    /// The walls of the box from `lo` to `hi`.
    ///
    /// # Errors
    /// An [`InputError`] naming `box` at the axis: a bound that is NaN or infinite, or
    /// `lo ≥ hi`.
    pub fn new(lo: [f64; D], hi: [f64; D]) -> Result<Self, InputError> {
        for k in 0..D {
            finite("box", lo[k]).map_err(|e| e.at(k))?;
            finite("box", hi[k]).map_err(|e| e.at(k))?;
            if lo[k] >= hi[k] {
                let kind = InputErrorKind::EmptyBox {
                    lo: lo[k],
                    hi: hi[k],
                };
                return Err(InputError::new("box", kind).at(k));
            }
        }
        Ok(Self { lo, hi })
    }

    /// The low bounds.
    pub fn lo(&self) -> [f64; D] {
        self.lo
    }

    /// The high bounds.
    pub fn hi(&self) -> [f64; D] {
        self.hi
    }

    /// Whether a ball of radius `r` is as wide as the box or wider on some axis (`2r ≥
    /// keep·width`, `keep ≤ 1` a tolerance): it would touch two opposite walls at once
    /// wherever it is. The first such axis's error kind.
    pub(crate) fn wider_than(&self, r: f64, keep: f64) -> Option<InputErrorKind> {
        (0..D).find_map(|axis| {
            let width = self.hi[axis] - self.lo[axis];
            (2.0 * r >= width * keep).then_some(InputErrorKind::WiderThanBox { axis, width })
        })
    }

    /// The first contact of a ball of `radius` on `path` with these walls, searched from the
    /// path's first start: `(t, axis, side)`, ties to the lowest axis, then the low wall;
    /// `None` if there is none before `t_max`. This is the search the calendar runs.
    ///
    /// # Errors
    /// `radius` must be finite and positive, `t_max ≥ 0` (`∞` allowed).
    ///
    /// ```
    /// use ballcollide::path::{Path2, Segment2};
    /// use ballcollide::schedule::{Side, Walls};
    /// use nalgebra::Vector2;
    ///
    /// // Thrown up at 2 m/s under gravity 10 m/s², a ball of radius 0.1 under a ceiling at 0.25.
    /// let walls = Walls::new([-1.0, -1.0], [1.0, 0.25])?;
    /// let path = Path2::new(vec![Segment2::new(0.0, Vector2::zeros(), Vector2::new(0.0, 2.0), Vector2::new(0.0, -10.0))])?;
    /// let (t, axis, side) = walls.first_contact(&path, 0.1, f64::INFINITY)?.expect("a hit");
    /// assert_eq!((axis, side), (1, Side::High));
    /// assert!((t - 0.1).abs() < 1e-15); // 2t − 5t² = 0.15
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn first_contact(
        &self,
        path: &Path<D>,
        radius: f64,
        t_max: f64,
    ) -> Result<Option<(f64, usize, Side)>, InputError> {
        let radius = check_ball_radius("radius", radius)?;
        let t_max = check_horizon("t_max", t_max)?;
        Ok(first_wall_contact(path.segments(), radius, self, t_max))
    }
}

/// The first wall contact of a ball of `radius` on a valid path (`segments`), searched from
/// the path's first start: `(t, axis, side)`, ties to the lowest axis, then the low wall;
/// `None` if there is none before `t_max`.
pub(crate) fn first_wall_contact<const D: usize>(
    segments: &[Segment<D>],
    radius: f64,
    walls: &Walls<D>,
    t_max: f64,
) -> Option<(f64, usize, Side)> {
    let mut best: Option<(f64, usize, Side)> = None;
    // Strictly earlier only: the loops visit axes and sides in tie order.
    let mut consider = |hit: Option<(f64, Side)>, axis: usize| {
        if let Some((t, side)) = hit
            && best.is_none_or(|(b, _, _)| t < b)
        {
            best = Some((t, axis, side));
        }
    };
    let straight = match segments {
        [segment] => Some(segment),
        _ => None,
    };
    for axis in 0..D {
        if let Some(segment) = straight.filter(|s| s.acceleration[axis] == 0.0) {
            // One segment, no acceleration on this axis: only the wall the velocity points
            // to can be reached (the other plane's distance never falls).
            if let Some(side) = facing(segment.velocity[axis]) {
                let hit = first_plane_contact(segments, radius, walls, axis, side, t_max);
                consider(hit.map(|t| (t, side)), axis);
            }
            continue;
        }
        for side in [Side::Low, Side::High] {
            let hit = first_plane_contact(segments, radius, walls, axis, side, t_max);
            consider(hit.map(|t| (t, side)), axis);
        }
    }
    best
}

/// The signed distance to one wall's contact plane on a segment, `c + b·s + q·s²`: positive
/// inside. (A wall is a [`Plane`](crate::geometry::Plane) whose normal is an axis; its
/// distance is formed here without the general plane's products.)
#[inline(always)]
fn plane_distance<const D: usize>(
    segment: &Segment<D>,
    radius: f64,
    walls: &Walls<D>,
    axis: usize,
    side: Side,
) -> Quadratic {
    let (x, v, a) = (
        segment.position[axis],
        segment.velocity[axis],
        segment.acceleration[axis],
    );
    let (c, b, q) = match side {
        Side::Low => ((x - walls.lo[axis]) - radius, v, 0.5 * a),
        Side::High => ((walls.hi[axis] - x) - radius, -v, -0.5 * a),
    };
    Quadratic { c, b, q }
}

/// The wall a velocity component `v` points to (none for 0).
fn facing(v: f64) -> Option<Side> {
    if v < 0.0 {
        Some(Side::Low)
    } else if v > 0.0 {
        Some(Side::High)
    } else {
        None
    }
}

/// The first entry of one wall's plane, from the path's first start: the walk every plane
/// and segment query takes ([`first_entry`]), on this wall's distance.
fn first_plane_contact<const D: usize>(
    segments: &[Segment<D>],
    radius: f64,
    walls: &Walls<D>,
    axis: usize,
    side: Side,
    t_max: f64,
) -> Option<f64> {
    first_entry(
        segments,
        t_max,
        |segment| ([plane_distance(segment, radius, walls, axis, side)], ()),
        |_, _, _| true,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;

    /// A segment as `(start, position, velocity, acceleration)`.
    type Row = (f64, [f64; 2], [f64; 2], [f64; 2]);

    fn path(segments: &[Row]) -> Vec<Segment<2>> {
        segments
            .iter()
            .map(|&(s, p, v, a)| Segment::new(s, p.into(), v.into(), a.into()))
            .collect()
    }

    fn unit_box() -> Walls<2> {
        Walls::new([0.0, 0.0], [1.0, 1.0]).expect("valid box")
    }

    #[test]
    fn a_ball_moving_right_reaches_the_high_wall_at_hi_minus_r() {
        let p = path(&[(1.0, [0.5, 0.5], [0.25, 0.0], [0.0, 0.0])]);
        let hit = first_wall_contact(&p, 0.25, &unit_box(), f64::INFINITY);
        assert_eq!(hit, Some((2.0, 0, Side::High)));
    }

    #[test]
    fn a_ball_beyond_a_plane_moving_away_from_the_wall_is_no_contact_until_it_comes_back() {
        // Beyond the low plane (x < r) moving inwards, then decelerated back out.
        let p = path(&[(0.0, [0.1, 0.5], [1.0, 0.0], [-2.0, 0.0])]);
        let (t, axis, side) =
            first_wall_contact(&p, 0.25, &unit_box(), f64::INFINITY).expect("a hit");
        assert_eq!((axis, side), (0, Side::Low));
        // x(t) = 0.1 + t − t² = 0.25 on the way back: t = (1 + √0.4)/2.
        assert!((t - (1.0 + 0.4f64.sqrt()) / 2.0).abs() < 1e-15);
    }

    #[test]
    fn an_entry_too_soon_for_float_time_is_a_contact_at_the_start() {
        // 2.5e-152 of room at 1.4e303: the entry is at 1.8e-455, which rounds to the start
        // (a fuzzed simulation whose ball left its box through the wall).
        let walls = Walls::new([0.0; 2], [6.1e-151; 2]).expect("valid box");
        for start in [0.0, 0.25] {
            let p = path(&[(start, [5.75e-151, 3e-151], [1.4e303, 0.0], [0.0; 2])]);
            let hit = first_wall_contact(&p, 1.0e-152, &walls, f64::INFINITY);
            assert_eq!(hit, Some((start, 0, Side::High)));
        }
    }

    #[test]
    fn reaching_the_plane_exactly_at_a_segment_start_is_a_contact_there() {
        // The first segment's root is its end (0.25 = 0.75 − 0.5, at speed 1): not inside
        // it; the next segment starts on the plane, moving on. The contact is at 0.25, found
        // by the next segment's start (the first one ends apart, by the same roots).
        let p = path(&[
            (0.0, [0.5, 0.5], [1.0, 0.0], [0.0, 0.0]),
            (0.25, [0.75, 0.5], [1.0, 0.0], [0.0, 0.0]),
        ]);
        let hit = first_wall_contact(&p, 0.25, &unit_box(), f64::INFINITY);
        assert_eq!(hit, Some((0.25, 0, Side::High)));
    }

    #[test]
    fn a_tangency_and_a_ball_at_rest_are_no_contact() {
        // Turns exactly at x = 0.75 = hi − r: x = 0.5 + t − t², vertex at t = ½, x = 0.75.
        let p = path(&[(0.0, [0.5, 0.5], [1.0, 0.0], [-2.0, 0.0])]);
        let walls = Walls::new([-10.0, 0.0], [1.0, 1.0]).expect("valid");
        // It grazes the high plane, comes back and reaches the low one (−9.75) at (1 + √42)/2.
        let (t, axis, side) = first_wall_contact(&p, 0.25, &walls, f64::INFINITY).expect("a hit");
        assert_eq!((axis, side), (0, Side::Low));
        assert!((t - (1.0 + 42f64.sqrt()) / 2.0).abs() < 1e-14);
        let rest = path(&[(0.0, [0.5, 0.5], [0.0, 0.0], [0.0, 0.0])]);
        assert_eq!(
            first_wall_contact(&rest, 0.25, &unit_box(), f64::INFINITY),
            None
        );
    }

    #[test]
    fn a_jump_beyond_a_plane_at_a_segment_start_is_a_contact_there() {
        let p = path(&[
            (0.0, [0.5, 0.5], [0.0, 0.0], [0.0, 0.0]),
            (3.0, [0.9, 0.5], [0.0, 0.0], [0.0, 0.0]),
        ]);
        let hit = first_wall_contact(&p, 0.25, &unit_box(), f64::INFINITY);
        assert_eq!(hit, Some((3.0, 0, Side::High)));
        // Not before the horizon.
        assert_eq!(first_wall_contact(&p, 0.25, &unit_box(), 3.0), None);
    }

    #[test]
    fn one_straight_segment_gets_the_answer_of_every_plane_searched() {
        // The general search over all four planes, in tie order.
        let general = |p: &[Segment<2>], r: f64, w: &Walls<2>, t_max: f64| {
            let mut best: Option<(f64, usize, Side)> = None;
            for axis in 0..2 {
                for side in [Side::Low, Side::High] {
                    if let Some(t) = first_plane_contact(p, r, w, axis, side, t_max)
                        && best.is_none_or(|(b, _, _)| t < b)
                    {
                        best = Some((t, axis, side));
                    }
                }
            }
            best
        };
        let mut rng = crate::test_rng::Rng(13);
        let mut draw = |lo: f64, hi: f64| rng.uniform(lo, hi);
        let walls = unit_box();
        let mut hits = 0;
        for n in 0..2000 {
            // Some axes at rest, some balls beyond a plane, some with an acceleration.
            let pick = |x: f64, k: usize| if n % (3 + k) == 0 { 0.0 } else { x };
            let v = [pick(draw(-2.0, 2.0), 0), pick(draw(-2.0, 2.0), 1)];
            let a = [if n % 2 == 0 { 0.0 } else { draw(-1.0, 1.0) }, 0.0];
            let p = path(&[(draw(0.0, 2.0), [draw(-0.1, 1.1), draw(-0.1, 1.1)], v, a)]);
            let t_max = if n % 4 == 0 {
                draw(0.0, 3.0)
            } else {
                f64::INFINITY
            };
            let expected = general(&p, 0.125, &walls, t_max);
            hits += usize::from(expected.is_some());
            assert_eq!(
                first_wall_contact(&p, 0.125, &walls, t_max),
                expected,
                "{p:?}"
            );
        }
        assert!(hits > 1000);
    }

    #[test]
    fn a_corner_hit_goes_to_the_lowest_axis_then_the_low_wall() {
        let p = path(&[(0.0, [0.5, 0.5], [-1.0, -1.0], [0.0, 0.0])]);
        let hit = first_wall_contact(&p, 0.25, &unit_box(), f64::INFINITY);
        assert_eq!(hit, Some((0.25, 0, Side::Low)));
        let _ = Vector2::<f64>::zeros();
    }
}
