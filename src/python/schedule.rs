//! The event calendar of the Python API: :class:`CollisionSchedule` (`crate::schedule`), in
//! 2-D or 3-D, the :class:`Event` it reports, and :func:`simulate` on it.
//!
//! Paths are read as one side of :func:`path_collision_times` ([`super::paths::side`]), friction
//! balls as a scene's ([`crate::scene::balls`]); each path is checked by
//! [`Path::from_rows`](crate::Path::from_rows), its errors located at the ball (or, in an
//! update, at its position in the update) and the segment, as the batch functions do.

use super::input_error::kind;
use numpy::{PyArray1, PyArray2};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{IntoPyDict, PyFloat, PyList, PyTuple};
use std::ops::ControlFlow;
use std::time::Instant;

use super::index_i64;
use super::input_error::{from_core, input_error};
use super::long_call::{INLINE_UP_TO, Kernel, Progress, SIGNAL_CHECKS, look, run, run_shown};
use super::paths::{Layout, Side, side};
use super::read::{self, Floats, Given, Param, param, rows};
use super::table::table_of;
use crate::Path;
use crate::batch::PerPair;
use crate::error::{InputError, InputErrorKind};
use crate::geometry::ObjectKind;
use crate::scene;
use crate::schedule::{
    Collision, CollisionSchedule as Core, Event as CoreEvent, ScheduleOptions, Side as WallSide,
    SimulationOptions, Walls,
};

/// The argument names of a calendar's path arrays.
const NAMES: [&str; 4] = ["start", "pos", "vel", "acc"];

/// A calendar in the dimension of its paths.
#[derive(Clone, Debug)]
enum Inner {
    Two(Core<2>),
    Three(Core<3>),
}

/// Runs `$body` with `$s` bound to the calendar, whatever its dimension.
macro_rules! each_dim {
    ($inner:expr, $s:ident => $body:expr) => {
        match $inner {
            Inner::Two($s) => $body,
            Inner::Three($s) => $body,
        }
    };
}

/// An event calendar: the next collision among N balls on paths, kept up to date as the
/// paths of a few balls change.
///
/// ``CollisionSchedule(start, pos, vel, acc, radius, *, box=None, t_max=inf)`` holds N balls
/// on paths of constant-acceleration segments (the arrays of one side of
/// :func:`path_collision_times`: ``start`` ``(N, K)``, ``pos``, ``vel``, ``acc``
/// ``(N, K, D)``, ``D`` = 2 or 3, padding with ``+inf`` starts) and a current time, at first
/// the earliest first start.
///
/// - :meth:`next_collision` is the earliest ``(t, i, j)``, ``i < j``, over all pairs whose
///   first contact (:func:`path_collision_times` on paths ``i`` and ``j`` at contact
///   distance ``radius[i] + radius[j]``, searched from the later of their first starts) is at
///   or after the current time, ties to the lowest ``i``, then ``j``: bit for bit what
///   recomputing every pair gives. A pair whose first contact came before the current time
///   (an event the caller went past) is not reported again.
/// - :meth:`update` gives some balls new paths, all from one time ``t ≥`` :attr:`time`, which
///   becomes the current time; only their pairs are recomputed.
/// - With ``box=(lo, hi)``, :meth:`next_event` also reports a ball's contact with the walls
///   of that axis-aligned box (its centre reaching ``lo + r`` or ``hi − r`` moving towards the
///   wall), as an :class:`Event`.
///
/// A refused call (a time before :attr:`time`, a bad path, an index out of range or repeated)
/// raises :class:`InputError` and leaves the calendar exactly as it was.
///
/// Parameters
/// ----------
/// start, pos, vel, acc
///     The paths, as one side of :func:`path_collision_times`.
/// radius
///     A number or shape ``(N,)``: each ball's radius (``> 0``).
/// box
///     ``None``, or ``(lo, hi)``: the box's low and high corners, each ``D`` numbers
///     (``lo < hi`` on every axis).
/// t_max
///     Horizon: a contact at ``t ≥ t_max`` is none.
/// progress
///     As in :func:`collision_times`, counting the balls whose first events are found (the
///     construction's cost; off by default).
///
/// Raises
/// ------
/// InputError
///     As :func:`path_collision_times` (``vel[3, 1]: must be finite, got NaN``), a radius of
///     another length or not ``> 0`` (``radius[2]: ...``), a bad ``box``
///     (``box[1]: the box's low bound must be below its high bound, got 1 and 1``).
/// TypeError
///     An argument that is not made of real numbers.
///
/// Examples
/// --------
/// >>> import numpy as np
/// >>> import ballcollide as bc
/// >>> # Three balls on a line: 0 moves at 1 m/s towards 1 (2 m away) and 2 (5 m away).
/// >>> start = np.zeros((3, 1))
/// >>> pos = [[[0.0, 0.0]], [[2.0, 0.0]], [[5.0, 0.0]]]
/// >>> vel = [[[1.0, 0.0]], [[0.0, 0.0]], [[0.0, 0.0]]]
/// >>> s = bc.CollisionSchedule(start, pos, vel, np.zeros((3, 1, 2)), 0.5)
/// >>> s.next_collision()
/// (1.0, 0, 1)
/// >>> # Ball 0 stops there, ball 1 goes on at 1 m/s.
/// >>> s.update([0, 1], [[1.0], [1.0]], [[[1.0, 0.0]], [[2.0, 0.0]]],
/// ...          [[[0.0, 0.0]], [[1.0, 0.0]]], np.zeros((2, 1, 2)))
/// >>> s.time, s.next_collision()
/// (1.0, (3.0, 1, 2))
#[pyclass(name = "CollisionSchedule", module = "ballcollide")]
pub(super) struct CollisionSchedule {
    inner: Inner,
}

/// An event of a :class:`CollisionSchedule`: ``(time, i, j, kind, index)`` (see
/// [`EVENT_DOC`]).
static EVENT: PyOnceLock<Py<PyAny>> = PyOnceLock::new();

/// The :class:`Event` type's documentation.
const EVENT_DOC: &str = "An event of a CollisionSchedule: (time, i, j, kind, index).\n\n\
    kind says what ball i meets, as one of the module's constants: BALL (j the other ball, \
    i < j; index -1), WALL (index the wall: 2*axis for the low wall of an axis, 2*axis + 1 \
    for the high one), SEGMENT, CIRCLE, TARGET, PLANE (index the object's, among those of \
    its kind), TRANSITION (ball i's path starts its segment index). j is -1 unless kind is \
    BALL. No event: (inf, -1, -1, -1, -1).";

/// The :class:`Event` named tuple type.
pub(super) fn event_type(py: Python<'_>) -> PyResult<&Bound<'_, PyAny>> {
    named_tuple(
        py,
        &EVENT,
        "Event",
        &["time", "i", "j", "kind", "index"],
        EVENT_DOC,
    )
}

/// The event kinds of :class:`Event` and of the geometry calls, as module constants: the
/// objects' by [`ObjectKind::code`], then `BALL`, `WALL` and `TRANSITION`.
pub(super) const BALL: i64 = 4;
pub(super) const WALL: i64 = 5;
pub(super) const TRANSITION: i64 = 6;

/// Adds the kinds' constants to the module.
pub(super) fn add_kinds(m: &Bound<'_, pyo3::types::PyModule>) -> PyResult<()> {
    for kind in ObjectKind::ALL {
        m.add(kind.name().to_uppercase(), i64::from(kind.code()))?;
    }
    m.add("BALL", BALL)?;
    m.add("WALL", WALL)?;
    m.add("TRANSITION", TRANSITION)?;
    Ok(())
}

/// The :class:`Simulation` named tuple type (what :func:`simulate` returns).
static SIMULATION: PyOnceLock<Py<PyAny>> = PyOnceLock::new();

/// The :class:`Simulation` named tuple type.
pub(super) fn simulation_type(py: Python<'_>) -> PyResult<&Bound<'_, PyAny>> {
    named_tuple(
        py,
        &SIMULATION,
        "Simulation",
        &["times", "i", "j", "pos", "vel", "kind", "index", "captured"],
        "What simulate returns: (times, i, j, pos, vel, kind, index, captured).\n\n\
         times (float64, shape (E,)): the events' times; i, j (int64): the balls of each, \
         j = -1 for a wall or an object; pos, vel (shape (N, 2)): the final state; kind, \
         index (int64, shape (E,)): what ball i met, as in Event (BALL, WALL, SEGMENT, \
         CIRCLE, TARGET, PLANE) and its index; captured (int64, shape (N,)): the target \
         that captured each ball, -1 for none.",
    )
}

/// A `collections.namedtuple` type of `ballcollide`, made once and kept in `cell`.
fn named_tuple<'py>(
    py: Python<'py>,
    cell: &'static PyOnceLock<Py<PyAny>>,
    name: &str,
    fields: &[&str],
    doc: &str,
) -> PyResult<&'py Bound<'py, PyAny>> {
    cell.get_or_try_init(py, || {
        let namedtuple = py.import("collections")?.getattr("namedtuple")?;
        let kwargs = [("module", "ballcollide")].into_py_dict(py)?;
        let class = namedtuple.call((name, fields.to_vec()), Some(&kwargs))?;
        class.setattr("__doc__", doc)?;
        Ok::<_, PyErr>(class.unbind())
    })
    .map(|class| class.bind(py))
}

/// A logged event's kind and index, as in :class:`Event`.
fn logged_kind(e: &crate::schedule::LoggedEvent) -> (i64, i64) {
    match (e.j, e.wall, e.object) {
        (Some(_), ..) => (BALL, -1),
        (None, Some((axis, side)), _) => (WALL, wall_face(axis, side)),
        (None, None, Some((kind, index))) => (i64::from(kind.code()), index_i64(index)),
        (None, None, None) => (-1, -1),
    }
}

/// A wall's index in :class:`Event`: `2·axis` for the low wall, `2·axis + 1` for the high.
fn wall_face(axis: usize, side: WallSide) -> i64 {
    index_i64(2 * axis + usize::from(side == WallSide::High))
}

/// The event as the named tuple.
fn event_tuple<'py>(py: Python<'py>, event: Option<CoreEvent>) -> PyResult<Bound<'py, PyAny>> {
    let fields: (f64, i64, i64, i64, i64) = match event {
        None => (f64::INFINITY, -1, -1, -1, -1),
        Some(CoreEvent::Collision(c)) => (c.time, index_i64(c.i), index_i64(c.j), BALL, -1),
        Some(CoreEvent::Wall(w)) => (
            w.time,
            index_i64(w.ball),
            -1,
            WALL,
            wall_face(w.axis, w.side),
        ),
        Some(CoreEvent::Object(o)) => (
            o.time,
            index_i64(o.ball),
            -1,
            i64::from(o.kind.code()),
            index_i64(o.index),
        ),
        Some(CoreEvent::Transition(t)) => (
            t.time,
            index_i64(t.ball),
            -1,
            TRANSITION,
            index_i64(t.segment),
        ),
    };
    event_type(py)?.call1(fields)
}

fn collision_tuple(c: Option<Collision>) -> (f64, i64, i64) {
    c.map_or((f64::INFINITY, -1, -1), |c| {
        (c.time, index_i64(c.i), index_i64(c.j))
    })
}

/// The paths of a side's arrays, each checked (errors at `[ball, segment]`).
fn paths_of<const D: usize>(side: &Side<'_>) -> Result<Vec<Path<D>>, InputError> {
    let rows = side.rows::<D>();
    let k = side.segments;
    (0..side.paths)
        .map(|i| {
            let r = i * k..(i + 1) * k;
            Path::from_rows(
                &rows.start[r.clone()],
                &rows.pos[r.clone()],
                &rows.vel[r.clone()],
                &rows.acc[r],
            )
            .map_err(|e| e.in_pair(i))
        })
        .collect()
}

/// The walls of `box`: `None`, or a pair `(lo, hi)` of `dim` numbers each.
fn walls_of<const D: usize>(
    py: Python<'_>,
    obj: Option<&Bound<'_, PyAny>>,
) -> PyResult<Option<Walls<D>>> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(None);
    };
    walls_from(py, obj, "None or a tuple (lo, hi)").map(Some)
}

/// The walls of `obj`, a `(lo, hi)` pair of corners; `expected` says what a value of another
/// type should have been.
fn walls_from<const D: usize>(
    py: Python<'_>,
    obj: &Bound<'_, PyAny>,
    expected: &str,
) -> PyResult<Walls<D>> {
    let items: Option<Vec<Bound<'_, PyAny>>> = match (obj.cast::<PyTuple>(), obj.cast::<PyList>()) {
        (Ok(t), _) => Some(t.iter().collect()),
        (_, Ok(l)) => Some(l.iter().collect()),
        _ => None,
    };
    let corner = |item: &Bound<'_, PyAny>| -> PyResult<[f64; D]> {
        let (values, shape) = read::shaped("box", item)?;
        match <[f64; D]>::try_from(values.values()) {
            Ok(corner) if shape == [D] => Ok(corner),
            _ => {
                let reason = format!(
                    "expected (lo, hi), each of {D} numbers like pos's last dimension, got shape {}",
                    read::shape_text(&shape)
                );
                Err(input_error(py, "box", None, kind::SHAPE, &reason))
            }
        }
    };
    match items.as_deref() {
        Some([lo, hi]) => Walls::new(corner(lo)?, corner(hi)?).map_err(|e| from_core(py, e)),
        Some(other) => {
            let reason = format!("expected (lo, hi), got a sequence of {}", other.len());
            Err(input_error(py, "box", None, kind::SHAPE, &reason))
        }
        None => Err(PyTypeError::new_err(format!(
            "box: expected {expected}, got {}",
            obj.get_type().name()?
        ))),
    }
}

/// One radius per ball.
fn radii(py: Python<'_>, radius: &Bound<'_, PyAny>, n: usize) -> PyResult<Vec<f64>> {
    let radius = param("radius", radius)?;
    let values = match radius.per_pair() {
        PerPair::All(r) => vec![r; n],
        PerPair::Each(r) => r.to_vec(),
    };
    same_count(py, "radius", n, values.len())?;
    Ok(values)
}

/// An error naming `argument` unless it has `expected` rows.
fn same_count(
    py: Python<'_>,
    argument: &'static str,
    expected: usize,
    found: usize,
) -> PyResult<()> {
    if found == expected {
        return Ok(());
    }
    let kind = InputErrorKind::LengthMismatch { expected, found };
    Err(from_core(py, InputError::new(argument, kind)))
}

/// A scene's friction-ball arguments, read (in place where they can be).
struct BallArgs<'py> {
    pos: Floats<'py>,
    vel: Floats<'py>,
    friction: Param<'py>,
}

impl<'py> BallArgs<'py> {
    fn read(
        pos: &Bound<'py, PyAny>,
        vel: &Bound<'py, PyAny>,
        friction: &Bound<'py, PyAny>,
    ) -> PyResult<Self> {
        Ok(Self {
            pos: rows("pos", pos)?,
            vel: rows("vel", vel)?,
            friction: param("friction", friction)?,
        })
    }

    /// The number of balls (`pos`'s rows).
    fn len(&self) -> usize {
        self.pos.rows::<2>().len()
    }

    /// The rows `scene::balls` takes (slices: what a kernel on another thread may hold).
    fn rows(&self) -> (&[[f64; 2]], &[[f64; 2]], PerPair<'_>) {
        (self.pos.rows(), self.vel.rows(), self.friction.per_pair())
    }
}

/// Friction balls from a scene's arguments.
fn balls(
    py: Python<'_>,
    pos: &Bound<'_, PyAny>,
    vel: &Bound<'_, PyAny>,
    friction: &Bound<'_, PyAny>,
) -> PyResult<Vec<crate::Ball>> {
    let args = BallArgs::read(pos, vel, friction)?;
    let (pos, vel, friction) = args.rows();
    scene::balls(pos, vel, friction).map_err(|e| from_core(py, e))
}

#[pymethods]
impl CollisionSchedule {
    #[new]
    #[pyo3(
        signature = (start, pos, vel, acc, radius, *, r#box=None, t_max=Given(None),
                     segments=None, segment_sides=None, circles=None, targets=None,
                     planes=None, transitions=None, progress=None),
        text_signature = "(start, pos, vel, acc, radius, *, box=None, t_max=1e999, \
                          segments=None, segment_sides=None, circles=None, targets=None, \
                          planes=None, transitions=False, progress=None)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn new(
        py: Python<'_>,
        start: &Bound<'_, PyAny>,
        pos: &Bound<'_, PyAny>,
        vel: &Bound<'_, PyAny>,
        acc: &Bound<'_, PyAny>,
        radius: &Bound<'_, PyAny>,
        r#box: Option<&Bound<'_, PyAny>>,
        t_max: Given<'_>,
        segments: Option<&Bound<'_, PyAny>>,
        segment_sides: Option<&Bound<'_, PyAny>>,
        circles: Option<&Bound<'_, PyAny>>,
        targets: Option<&Bound<'_, PyAny>>,
        planes: Option<&Bound<'_, PyAny>>,
        transitions: Option<&Bound<'_, PyAny>>,
        progress: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let paths = side(py, NAMES, [start, pos, vel, acc], Layout::Batch, None)?;
        let radii = radii(py, radius, paths.paths)?;
        let t_max = t_max.number_or("t_max", f64::INFINITY)?;
        let objects = [segments, segment_sides, circles, targets, planes];
        let inner = match paths.dim {
            2 => {
                let options = options_of::<2>(py, r#box, t_max, objects, transitions)?;
                Inner::Two(build(py, &paths, &radii, options, progress)?)
            }
            _ => {
                let options = options_of::<3>(py, r#box, t_max, objects, transitions)?;
                Inner::Three(build(py, &paths, &radii, options, progress)?)
            }
        };
        Ok(Self { inner })
    }

    /// A calendar of friction balls (the model of :func:`collision_time`: each slowed by its
    /// friction along its velocity until it stops) given at time ``t``, in 2-D.
    ///
    /// Parameters
    /// ----------
    /// pos, vel
    ///     Shape ``(N, 2)``: the balls' centres and velocities at ``t``.
    /// friction, radius
    ///     Numbers or shape ``(N,)``: friction decelerations (``≥ 0``) and radii (``> 0``).
    /// t
    ///     The time at which the balls are given (finite); it is the calendar's time.
    /// box, t_max, progress
    ///     As for :class:`CollisionSchedule`.
    ///
    /// Raises
    /// ------
    /// InputError, TypeError
    ///     As :func:`first_contacts` (``friction[0]: friction must be ≥ 0, got -0.1``), and a
    ///     bad ``box`` or ``t``.
    ///
    /// Examples
    /// --------
    /// >>> import ballcollide as bc
    /// >>> s = bc.CollisionSchedule.from_balls([[0, 0], [1, 0]], [[1, 0], [0, 0]], 0.0, 0.25, t=2.0)
    /// >>> s.next_collision()
    /// (2.5, 0, 1)
    #[staticmethod]
    #[pyo3(
        signature = (pos, vel, friction, radius, t=Given(None), r#box=None, *, t_max=Given(None),
                     segments=None, segment_sides=None, circles=None, targets=None,
                     planes=None, transitions=None, progress=None),
        text_signature = "(pos, vel, friction, radius, t=0.0, box=None, *, t_max=1e999, \
                          segments=None, segment_sides=None, circles=None, targets=None, \
                          planes=None, transitions=False, progress=None)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn from_balls(
        py: Python<'_>,
        pos: &Bound<'_, PyAny>,
        vel: &Bound<'_, PyAny>,
        friction: &Bound<'_, PyAny>,
        radius: &Bound<'_, PyAny>,
        t: Given<'_>,
        r#box: Option<&Bound<'_, PyAny>>,
        t_max: Given<'_>,
        segments: Option<&Bound<'_, PyAny>>,
        segment_sides: Option<&Bound<'_, PyAny>>,
        circles: Option<&Bound<'_, PyAny>>,
        targets: Option<&Bound<'_, PyAny>>,
        planes: Option<&Bound<'_, PyAny>>,
        transitions: Option<&Bound<'_, PyAny>>,
        progress: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let args = BallArgs::read(pos, vel, friction)?;
        let n = args.len();
        let radii = radii(py, radius, n)?;
        let t = t.number_or("t", 0.0)?;
        let t_max = t_max.number_or("t_max", f64::INFINITY)?;
        let objects = [segments, segment_sides, circles, targets, planes];
        let options = options_of::<2>(py, r#box, t_max, objects, transitions)?;
        let progress = Progress::of(py, progress, Some(n), "ball")?;
        // The balls made inside the kernel, watched for Ctrl-C as the rest of the build is
        // (millions take a good part of a second).
        let (pos, vel, friction) = args.rows();
        let core = run_shown(py, calendar_kernel(n), progress, || {
            Core::from_balls(&scene::balls(pos, vel, friction)?, &radii, t, options)
        })?;
        Ok(Self {
            inner: Inner::Two(core),
        })
    }

    /// The current time: the start of the last update (at first, the earliest first start,
    /// or ``t`` of :meth:`from_balls`).
    #[getter]
    fn time(&self) -> f64 {
        each_dim!(&self.inner, s => s.time())
    }

    /// The number of balls.
    fn __len__(&self) -> usize {
        each_dim!(&self.inner, s => s.len())
    }

    /// The earliest ball–ball collision from :attr:`time` on: ``(t, i, j)`` with ``i < j``,
    /// or ``(inf, -1, -1)`` if there is none before ``t_max``.
    ///
    /// Examples
    /// --------
    /// >>> import ballcollide as bc
    /// >>> bc.CollisionSchedule.from_balls([[0, 0], [5, 0]], [[0, 0], [0, 0]], 0.0, 1.0).next_collision()
    /// (inf, -1, -1)
    fn next_collision(&mut self) -> (f64, i64, i64) {
        collision_tuple(each_dim!(&mut self.inner, s => s.next_collision()))
    }

    /// The earliest event from :attr:`time` on, as an :class:`Event` ``(time, i, j, kind,
    /// index)``: a collision (``kind`` :data:`BALL`), a ball reaching a wall of the ``box``
    /// (:data:`WALL`, ``index`` ``2·axis`` for the low wall, ``2·axis + 1`` for the high one)
    /// or an object of the table (:data:`SEGMENT`, :data:`CIRCLE`, :data:`TARGET`,
    /// :data:`PLANE`, ``index`` the object's), or with ``transitions=True`` a ball's next
    /// segment start (:data:`TRANSITION`, ``index`` the segment). Ordered by time, then the
    /// (lower) ball, then a ball's transition, wall, object (by kind, then index) and
    /// collisions. An event stays the next until the calendar moves past it: update the balls
    /// it involves.
    ///
    /// Examples
    /// --------
    /// >>> import ballcollide as bc
    /// >>> s = bc.CollisionSchedule.from_balls([[0.5, 0.5]], [[1, 0]], 0.0, 0.25, box=([0, 0], [1, 1]))
    /// >>> s.next_event()
    /// Event(time=0.25, i=0, j=-1, kind=5, index=1)
    /// >>> # A cushion from (0.6, 0) to (0.6, 1), played from its left (the ball's side).
    /// >>> s = bc.CollisionSchedule.from_balls([[0.5, 0.5]], [[1, 0]], 0.0, 0.05,
    /// ...                                     segments=[[[0.6, 0], [0.6, 1]]], segment_sides=1)
    /// >>> e = s.next_event()
    /// >>> e.kind == bc.SEGMENT, e.index, round(e.time, 12)
    /// (True, 0, 0.05)
    fn next_event<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let event = each_dim!(&mut self.inner, s => s.next_event());
        event_tuple(py, event)
    }

    /// Takes ball ``i`` out of play (a ball captured by a pocket): it has no event from now
    /// on and no ball meets it, until an update gives it a path again.
    ///
    /// Raises
    /// ------
    /// InputError
    ///     An index out of range (``i: ball index must be in 0..3, got 5``); nothing changes.
    ///
    /// Examples
    /// --------
    /// >>> import ballcollide as bc
    /// >>> s = bc.CollisionSchedule.from_balls([[0, 0], [2, 0], [4, 0]], [[1, 0], [0, 0], [0, 0]], 0.0, 0.5)
    /// >>> s.retire(1)
    /// >>> s.in_play(1), s.next_collision()
    /// (False, (3.0, 0, 2))
    fn retire(&mut self, py: Python<'_>, i: &Bound<'_, PyAny>) -> PyResult<()> {
        let i = read::ball_index("i", None, i, self.__len__(), "an int (a ball index)")?;
        let result = each_dim!(&mut self.inner, s => s.retire(i));
        result.map_err(|e| from_core(py, e))
    }

    /// Whether ball ``i`` is in play (not taken out by :meth:`retire` since its last
    /// update).
    fn in_play(&self, i: &Bound<'_, PyAny>) -> PyResult<bool> {
        let i = read::ball_index("i", None, i, self.__len__(), "an int (a ball index)")?;
        Ok(each_dim!(&self.inner, s => s.in_play(i)))
    }

    /// Gives balls ``indices`` new paths, all starting at one time ``t ≥`` :attr:`time`,
    /// which becomes the current time.
    ///
    /// Parameters
    /// ----------
    /// indices
    ///     An int or a sequence of ``M`` ints: the balls, each once.
    /// start, pos, vel, acc
    ///     The ``M`` new paths, as for :class:`CollisionSchedule` (``(M, K)`` and
    ///     ``(M, K, D)``, the calendar's ``D``; ``K`` may differ from the calendar's); every
    ///     path's first start is ``t``.
    ///
    /// Raises
    /// ------
    /// InputError
    ///     And nothing changes: an index out of range or repeated (``indices[1]: ball 3 is
    ///     given more than once``), paths of another number or dimension, a bad path
    ///     (``vel[1, 0]: must be finite, got nan``), first starts that differ or are before
    ///     :attr:`time` (``start[0, 0]: must not be before the calendar's time 2, got 1``).
    ///     An index of any size out of range, negative included (``indices[0]: ball index
    ///     must be in 0..3, got -1``).
    /// TypeError
    ///     And nothing changes: an index that is not an int (a bool, a float: ``indices[1]:
    ///     expected an int (a ball index), got bool``), paths not made of real numbers.
    /// KeyboardInterrupt
    ///     Ctrl-C during an update of many balls (it looks every 4,096 balls): the calendar
    ///     is as if only the balls of the chunks done (the first of ``indices``) had been
    ///     updated, at their start; consistent.
    fn update(
        &mut self,
        py: Python<'_>,
        indices: &Bound<'_, PyAny>,
        start: &Bound<'_, PyAny>,
        pos: &Bound<'_, PyAny>,
        vel: &Bound<'_, PyAny>,
        acc: &Bound<'_, PyAny>,
    ) -> PyResult<()> {
        let n = self.__len__();
        let indices = read::indices("indices", indices, n)?;
        let dim = match self.inner {
            Inner::Two(_) => 2,
            Inner::Three(_) => 3,
        };
        let paths = side(py, NAMES, [start, pos, vel, acc], Layout::Batch, None)?;
        if paths.dim != dim {
            let reason = format!(
                "expected paths in the calendar's dimension {dim}, got {}",
                paths.dim
            );
            return Err(input_error(py, "pos", None, kind::SHAPE, &reason));
        }
        same_count(py, "start", indices.len(), paths.paths)?;
        let how = calendar_kernel(indices.len());
        match &mut self.inner {
            Inner::Two(s) => {
                let paths = paths_of(&paths).map_err(|e| from_core(py, e))?;
                run(py, how, || s.update(&indices, paths))
            }
            Inner::Three(s) => {
                let paths = paths_of(&paths).map_err(|e| from_core(py, e))?;
                run(py, how, || s.update(&indices, paths))
            }
        }
    }

    /// Gives balls ``indices`` of a 2-D calendar new friction-ball paths from time ``t``
    /// (``≥`` :attr:`time`, which it becomes), as :meth:`from_balls` builds them.
    ///
    /// Parameters
    /// ----------
    /// indices
    ///     As in :meth:`update`.
    /// t
    ///     The time of the new states.
    /// pos, vel, friction
    ///     As in :meth:`from_balls`, for the ``M`` balls.
    ///
    /// Raises
    /// ------
    /// InputError
    ///     As :meth:`update` and :meth:`from_balls` (``t: must not be before the
    ///     calendar's time 2, got 1``); a 3-D calendar.
    /// KeyboardInterrupt
    ///     As :meth:`update`.
    ///
    /// Examples
    /// --------
    /// >>> import ballcollide as bc
    /// >>> s = bc.CollisionSchedule.from_balls([[0, 0], [1, 0]], [[1, 0], [0, 0]], 0.0, 0.25)
    /// >>> t, i, j = s.next_collision()
    /// >>> s.update_balls([i, j], t, [[0.5, 0], [1, 0]], [[0, 0], [1, 0]], 0.0)
    /// >>> s.time, s.next_collision()
    /// (0.5, (inf, -1, -1))
    fn update_balls(
        &mut self,
        py: Python<'_>,
        indices: &Bound<'_, PyAny>,
        t: &Bound<'_, PyAny>,
        pos: &Bound<'_, PyAny>,
        vel: &Bound<'_, PyAny>,
        friction: &Bound<'_, PyAny>,
    ) -> PyResult<()> {
        let n = self.__len__();
        let indices = read::indices("indices", indices, n)?;
        let t = read::number("t", t)?;
        let balls = balls(py, pos, vel, friction)?;
        same_count(py, "pos", indices.len(), balls.len())?;
        match &mut self.inner {
            Inner::Two(s) => run(py, calendar_kernel(indices.len()), || {
                s.update_balls(&indices, t, &balls)
            }),
            Inner::Three(_) => Err(input_error(
                py,
                "pos",
                None,
                kind::SHAPE,
                "friction balls are 2-D; this calendar is 3-D",
            )),
        }
    }

    /// ``CollisionSchedule(N balls in D-D, time=t)``, ``t`` as Python prints a float
    /// (``time=-1e+300``, not its 301 digits).
    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        let (n, time, dim) = match &self.inner {
            Inner::Two(s) => (s.len(), s.time(), 2),
            Inner::Three(s) => (s.len(), s.time(), 3),
        };
        let time = PyFloat::new(py, time).repr()?;
        Ok(format!(
            "CollisionSchedule({n} balls in {dim}-D, time={time})"
        ))
    }
}

/// A calendar's options from its keyword arguments: the box, the horizon, the table's
/// objects (`segments`, `segment_sides`, `circles`, `targets`, `planes`, read by
/// [`table_of`]) and whether transitions are reported.
fn options_of<const D: usize>(
    py: Python<'_>,
    r#box: Option<&Bound<'_, PyAny>>,
    t_max: f64,
    [segments, segment_sides, circles, targets, planes]: [Option<&Bound<'_, PyAny>>; 5],
    transitions: Option<&Bound<'_, PyAny>>,
) -> PyResult<ScheduleOptions<D>> {
    let transitions = match transitions {
        Some(flag) => read::flag("transitions", flag)?,
        None => false,
    };
    Ok(ScheduleOptions {
        walls: walls_of::<D>(py, r#box)?,
        table: table_of::<D>(py, segments, segment_sides, circles, targets, planes)?,
        transitions,
        t_max,
    })
}

/// The calendar of `paths` in dimension `D`.
fn build<const D: usize>(
    py: Python<'_>,
    paths: &Side<'_>,
    radii: &[f64],
    options: ScheduleOptions<D>,
    progress: Option<&Bound<'_, PyAny>>,
) -> PyResult<Core<D>> {
    let paths = paths_of::<D>(paths).map_err(|e| from_core(py, e))?;
    let progress = Progress::of(py, progress, Some(paths.len()), "ball")?;
    run_shown(py, calendar_kernel(paths.len()), progress, || {
        Core::new(paths, radii, options)
    })
}

/// How a calendar of `n` balls is built: each ball's first searches cost about as much as a
/// dozen pair queries.
fn calendar_kernel(n: usize) -> Kernel {
    const PAIRS_A_BALL: usize = 16;
    Kernel::for_items(n.saturating_mul(PAIRS_A_BALL), INLINE_UP_TO)
}

/// An event-driven simulation of smooth hard friction balls in a box, and on a table if
/// given, run in Rust on the calendar: a :class:`Simulation` ``(times, i, j, pos, vel, kind,
/// index, captured)``.
///
/// Each ball moves as in :func:`collision_time` (slowed by its friction along its velocity
/// until it stops; ``0`` for none). At each event, in :class:`CollisionSchedule`'s order,
/// two touching balls exchange momentum along their line of centres with the given
/// restitution and masses (the tangential components are kept), and a ball touching a wall
/// has its velocity's normal component reflected, a ball touching a segment, a circle or a
/// plane of the table has its velocity's component along the object's normal reflected with
/// ``table_restitution``, and a ball whose centre enters a target is captured (at rest there,
/// out of play); the balls involved go on from there. It
/// runs until ``t_end``, ``max_events``, or until no event is left (every ball at rest).
/// Balls pressed together part at a least speed (bounces ``2⁻²¹`` of their contact
/// distance high) and a ball's later events at one instant are elastic, so that every run
/// moves on (docs/contract.md §4.5).
///
/// Parameters
/// ----------
/// pos, vel
///     Shape ``(N, 2)``: centres and velocities at time 0.
/// friction, radius
///     Numbers or shape ``(N,)``: friction decelerations (``≥ 0``) and radii (``> 0``).
/// box
///     ``(lo, hi)``: the box's low and high corners (two numbers each).
/// mass
///     A number or shape ``(N,)``: the masses (``> 0``, finite: any from ``5e-324`` to
///     ``1.7e308``; only their ratios matter).
/// restitution
///     The coefficient of restitution of ball–ball collisions, a number in ``[0, 1]``.
/// t_end
///     The end time (``inf``: until no event is left).
/// max_events
///     ``None``, or an int ``≥ 0``: the number of events after which to stop.
/// progress
///     ``True`` for a progress bar of events (``tqdm``, which must be installed: the
///     ``progress`` extra), a tqdm-like bar of your own (``update``, ``close``, and
///     ``set_postfix`` if it has one, shown the time ``t``), or a callable called with the
///     number of new events; ``False`` or ``None`` (the default) for none. Moved on every
///     0.05 s; the events it is shown add up to ``len(times)``.
/// segments, segment_sides, circles, targets, planes
///     The table's objects, as for :func:`path_geometry_times` (2-D); :func:`pool_table`
///     gives a pool table's.
/// table_restitution
///     The coefficient of restitution of ball–object contacts, a number in ``[0, 1]``.
///
/// Returns
/// -------
/// Simulation
///     A named tuple: ``times`` (float64, shape ``(E,)``), ``i`` and ``j`` (int64: the
///     balls, ``j = -1`` for a wall or an object), ``pos``, ``vel`` (shape ``(N, 2)``): the
///     state at ``t_end`` if finite and reached, else at the last event (``max_events``) or
///     when every ball is at rest (a captured ball at rest where it entered its target);
///     ``kind`` and ``index`` (int64, shape ``(E,)``): what ball ``i`` met, as in
///     :class:`Event`; ``captured`` (int64, shape ``(N,)``): each ball's target, ``-1`` for
///     none.
///
/// Raises
/// ------
/// InputError
///     As :meth:`CollisionSchedule.from_balls`; a mass ``≤ 0``, a restitution outside
///     ``[0, 1]``, a negative ``max_events``; no ``t_end``, no ``max_events`` and a ball
///     without friction (it would never end); a ball overlapping another or a wall, or
///     outside the box, at the start (``pos[i]``), or as wide as the box (``radius[i]``);
///     a ball overlapping an object of the table or inside a target (``pos[i]``, kind
///     ``overlaps_object``); a bad object (as :func:`path_geometry_times`);
///     more than ``1000 + 64·N`` events at one instant (``pos[i]``, naming the balls that
///     keep colliding).
/// TypeError
///     An argument that is not made of real numbers (a bool included), or a
///     ``max_events`` that is not ``None`` or an int.
/// KeyboardInterrupt
///     On Ctrl-C, within about 0.05 s.
///
/// Notes
/// -----
/// The GIL is released while it runs.
///
/// Examples
/// --------
/// >>> import ballcollide as bc
/// >>> # A ball at 1 m/s towards a resting one in a 4 m × 1 m box: they swap velocities.
/// >>> times, i, j, pos, vel, *_ = bc.simulate([[0.5, 0.5], [2, 0.5]], [[1, 0], [0, 0]], 0.0,
/// ...                                         0.25, box=([0, 0], [4, 1]), t_end=3.0)
/// >>> times, i, j
/// (array([1.  , 2.75]), array([0, 1]), array([ 1, -1]))
/// >>> pos
/// array([[1.5, 0.5],
///        [3.5, 0.5]])
/// >>> run = bc.simulate([[0.5, 0.5]], [[1, 0]], 0.0, 0.25, box=([0, 0], [2, 1]), t_end=2.0)
/// >>> run.times, run.j  # one wall contact
/// (array([1.25]), array([-1]))
/// >>> # On a table: a pocket (a target of radius 0.05 at (1.5, 0.5)) captures the ball.
/// >>> run = bc.simulate([[0.5, 0.5]], [[1, 0]], 0.0, 0.25, box=([0, 0], [2, 1]), t_end=2.0,
/// ...                   targets=[[1.5, 0.5, 0.05]])
/// >>> run.kind.tolist() == [bc.TARGET], round(float(run.times[0]), 12), run.captured
/// (True, 0.95, array([0]))
#[pyfunction]
#[pyo3(
    signature = (pos, vel, friction, radius, *, r#box, mass=Given(None),
                 restitution=Given(None), t_end=Given(None), max_events=None, progress=None,
                 segments=None, segment_sides=None, circles=None, targets=None, planes=None,
                 table_restitution=Given(None)),
    text_signature = "(pos, vel, friction, radius, *, box, mass=1.0, restitution=1.0, \
                      t_end=1e999, max_events=None, progress=False, segments=None, \
                      segment_sides=None, circles=None, targets=None, planes=None, \
                      table_restitution=1.0)"
)]
#[allow(clippy::too_many_arguments, clippy::type_complexity)]
pub(super) fn simulate<'py>(
    py: Python<'py>,
    pos: &Bound<'py, PyAny>,
    vel: &Bound<'py, PyAny>,
    friction: &Bound<'py, PyAny>,
    radius: &Bound<'py, PyAny>,
    r#box: &Bound<'py, PyAny>,
    mass: Given<'py>,
    restitution: Given<'py>,
    t_end: Given<'py>,
    max_events: Option<&Bound<'py, PyAny>>,
    progress: Option<&Bound<'py, PyAny>>,
    segments: Option<&Bound<'py, PyAny>>,
    segment_sides: Option<&Bound<'py, PyAny>>,
    circles: Option<&Bound<'py, PyAny>>,
    targets: Option<&Bound<'py, PyAny>>,
    planes: Option<&Bound<'py, PyAny>>,
    table_restitution: Given<'py>,
) -> PyResult<Bound<'py, PyAny>> {
    let balls = balls(py, pos, vel, friction)?;
    let n = balls.len();
    let radii = radii(py, radius, n)?;
    let walls = walls_from::<2>(py, r#box, "a tuple (lo, hi)")?;
    let mass = match mass.param_or("mass", 1.0)?.per_pair() {
        PerPair::All(m) => vec![m],
        PerPair::Each(m) => m.to_vec(),
    };
    let options = SimulationOptions {
        mass,
        restitution: restitution.number_or("restitution", 1.0)?,
        t_end: t_end.number_or("t_end", f64::INFINITY)?,
        max_events: read::count("max_events", max_events)?,
        table: table_of::<2>(py, segments, segment_sides, circles, targets, planes)?,
        table_restitution: table_restitution.number_or("table_restitution", 1.0)?,
    };
    let mut bar = Progress::of(py, progress, options.max_events, "event")?;
    // Ctrl-C and the progress bar: the run looks for Python's signals, and moves the bar on,
    // every few hundredths of a second (with the GIL for that moment), and stops on the first
    // signal (or error of the bar) that raises.
    let mut interrupted: Option<PyErr> = None;
    let mut checked = Instant::now();
    let run = py
        .detach(|| {
            crate::schedule::simulate_observed(&balls, &radii, walls, &options, |p| {
                if checked.elapsed() < SIGNAL_CHECKS {
                    return ControlFlow::Continue(());
                }
                checked = Instant::now();
                let looked = Python::attach(|py| look(py, bar.as_mut(), p.events, Some(p.time)));
                match looked {
                    Ok(()) => ControlFlow::Continue(()),
                    Err(e) => {
                        interrupted = Some(e);
                        ControlFlow::Break(())
                    }
                }
            })
        })
        .map_err(|e| from_core(py, e));
    if let Some(bar) = bar {
        let (events, end) = run
            .as_ref()
            .map_or((0, f64::NAN), |r| (r.events.len(), r.end));
        let closed = bar.close(py, events, Some(end));
        if interrupted.is_none() {
            closed?;
        }
    }
    let run = run?;
    if let Some(e) = interrupted {
        return Err(e);
    }
    let times: Vec<f64> = run.events.iter().map(|e| e.time).collect();
    let i: Vec<i64> = run.events.iter().map(|e| index_i64(e.i)).collect();
    let j: Vec<i64> = run
        .events
        .iter()
        .map(|e| e.j.map_or(-1, index_i64))
        .collect();
    let (kinds, indices): (Vec<i64>, Vec<i64>) = run.events.iter().map(logged_kind).unzip();
    let captured: Vec<i64> = run
        .captured
        .iter()
        .map(|c| c.map_or(-1, index_i64))
        .collect();
    let state = |f: fn(&crate::Ball) -> [f64; 2]| -> PyResult<Bound<'py, PyArray2<f64>>> {
        let rows: Vec<Vec<f64>> = run.balls.iter().map(|b| f(b).to_vec()).collect();
        if rows.is_empty() {
            return Ok(PyArray2::zeros(py, [0, 2], false));
        }
        PyArray2::from_vec2(py, &rows).map_err(|e| PyTypeError::new_err(e.to_string()))
    };
    simulation_type(py)?.call1((
        PyArray1::from_vec(py, times),
        PyArray1::from_vec(py, i),
        PyArray1::from_vec(py, j),
        state(|b| b.position().into())?,
        state(|b| b.velocity().into())?,
        PyArray1::from_vec(py, kinds),
        PyArray1::from_vec(py, indices),
        PyArray1::from_vec(py, captured),
    ))
}
