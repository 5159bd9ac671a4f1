//! When a ball on a path first touches any object of a [`Table`]: [`path_table_contact`].
//!
//! Each object is asked on its own ([`object_contact`], the one place that maps a kind to its
//! query), and the earliest answer is kept in the order of [`ObjectContact::before`]. The
//! calendar asks the same function for the objects its grid leaves, so both give the same
//! bits.

use super::path_circle_contact::first_circle_contact;
use super::path_plane_contact::first_plane_contact;
use super::path_segment_contact::first_segment_contact;
use super::path_target_contact::first_target_contact;
use super::table::{ObjectContact, ObjectKind, Table, planar};
use crate::CollisionOptions;
use crate::error::{InputError, check_ball_radius, check_horizon};
use crate::path::{Path, Segment};

/// The first contact (absolute time, as the path's starts are) of a ball of `radius` on
/// `path` with any object of `table`, searched from the path's first start: its time, the
/// object's kind and index; at equal times the lowest kind, then index. `None` if there is
/// none before `options.t_max`.
///
/// Each object's contact is that of its own query ([`path_segment_contact`],
/// [`path_circle_contact`], [`path_target_contact`] — where the ball's centre enters the
/// target, whatever its radius — and [`path_plane_contact`]).
///
/// # Errors
/// `radius` must be finite and positive, `t_max ≥ 0` (`∞` allowed).
///
/// ```
/// use ballcollide::geometry::{LineSegment, ObjectKind, SegmentSide, Table, Target, path_table_contact};
/// use ballcollide::path::{Path2, Segment2};
/// use ballcollide::CollisionOptions;
/// use nalgebra::Vector2;
///
/// // A cushion along y = 0 and a pocket past its end.
/// let table = Table {
///     segments: vec![LineSegment::new(Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), SegmentSide::Left)?],
///     targets: vec![Target::new(Vector2::new(1.2, 0.0), 0.05)?],
///     ..Default::default()
/// };
/// let down = |x: f64| Path2::new(vec![Segment2::new(0.0, Vector2::new(x, 1.0), Vector2::new(0.0, -1.0), Vector2::zeros())]);
/// let options = CollisionOptions::default();
/// let hit = path_table_contact(&down(0.5)?, &table, 0.1, &options)?.expect("the cushion");
/// assert_eq!((hit.kind, hit.index), (ObjectKind::Segment, 0));
/// assert!((hit.time - 0.9).abs() < 1e-15);
/// let hit = path_table_contact(&down(1.2)?, &table, 0.1, &options)?.expect("the pocket");
/// assert_eq!((hit.kind, hit.index), (ObjectKind::Target, 0));
/// # Ok::<(), ballcollide::InputError>(())
/// ```
///
/// [`path_segment_contact`]: super::path_segment_contact
/// [`path_circle_contact`]: super::path_circle_contact
/// [`path_target_contact`]: super::path_target_contact
/// [`path_plane_contact`]: super::path_plane_contact
pub fn path_table_contact<const D: usize>(
    path: &Path<D>,
    table: &Table<D>,
    radius: f64,
    options: &CollisionOptions,
) -> Result<Option<ObjectContact>, InputError> {
    let radius = check_ball_radius("radius", radius)?;
    let t_max = check_horizon("t_max", options.t_max)?;
    let mut scratch = Vec::new();
    Ok(first_table_contact(
        path.segments(),
        table,
        radius,
        t_max,
        &mut scratch,
    ))
}

/// [`path_table_contact`] on validated inputs; `scratch` holds the path's planar copy (see
/// [`TablePath`]), reused from call to call.
pub(crate) fn first_table_contact<const D: usize>(
    segments: &[Segment<D>],
    table: &Table<D>,
    radius: f64,
    t_max: f64,
    scratch: &mut Vec<Segment<2>>,
) -> Option<ObjectContact> {
    let mut path = TablePath::new(segments, scratch);
    let mut best: Option<ObjectContact> = None;
    for kind in ObjectKind::ALL {
        for index in 0..table.count(kind) {
            let Some(time) = object_contact(&mut path, table, kind, index, radius, t_max) else {
                continue;
            };
            // Kinds and indices come in order: only an earlier time replaces the best.
            if best.is_none_or(|b| time < b.time) {
                best = Some(ObjectContact { time, kind, index });
            }
        }
    }
    best
}

/// A path as the object queries read it: its segments, and (made on first need) their
/// `(x, y)` copy for the segment queries.
pub(crate) struct TablePath<'a, const D: usize> {
    segments: &'a [Segment<D>],
    planar: &'a mut Vec<Segment<2>>,
    planar_made: bool,
}

impl<'a, const D: usize> TablePath<'a, D> {
    /// The path of `segments`, its planar copy to be written in `scratch`.
    pub(crate) fn new(segments: &'a [Segment<D>], scratch: &'a mut Vec<Segment<2>>) -> Self {
        Self {
            segments,
            planar: scratch,
            planar_made: false,
        }
    }

    fn planar(&mut self) -> &[Segment<2>] {
        if !self.planar_made {
            planar(self.segments, self.planar);
            self.planar_made = true;
        }
        self.planar
    }
}

/// The first contact of a ball of `radius` on `path` with object `index` of `kind`: the one
/// place that maps an object to its query.
pub(crate) fn object_contact<const D: usize>(
    path: &mut TablePath<'_, D>,
    table: &Table<D>,
    kind: ObjectKind,
    index: usize,
    radius: f64,
    t_max: f64,
) -> Option<f64> {
    match kind {
        ObjectKind::Segment => {
            first_segment_contact(path.planar(), &table.segments[index], radius, t_max)
        }
        ObjectKind::Circle => {
            first_circle_contact(path.segments, &table.circles[index], radius, t_max)
        }
        ObjectKind::Target => first_target_contact(path.segments, &table.targets[index], t_max),
        ObjectKind::Plane => {
            first_plane_contact(path.segments, &table.planes[index], radius, t_max)
        }
    }
}
