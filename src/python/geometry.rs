//! Balls on paths against static geometry from Python: :func:`path_geometry_times`, on
//! [`batch::path_geometry_times`], and the kinds of object (`SEGMENT`, `CIRCLE`, `TARGET`,
//! `PLANE`: [`ObjectKind::code`]).
//!
//! The paths are read as one side of :func:`path_collision_times` ([`super::paths::side`]), the
//! objects by [`table_of`]; the answers go into three arrays (`time`, `kind`, `index`), new or
//! the caller's `out=(time, kind, index)`.

use numpy::PyArray1;
use numpy::ndarray::Ix1;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};

use super::input_error::{from_core, input_error, kind};
use super::long_call::{INLINE_UP_TO, Kernel, Progress, run_shown};
use super::paths::{Layout, NAMES_ONE, Side, broadcast, broadcast_len, param_len, side};
use super::read::{self, Floats, Given, Out, param, threads};
use super::table::table_of;
use crate::batch::{self, ContactColumns, PerPair, Threads};

/// The three answers: time (float64), kind (int8), index (int64).
type Answers<'py> = (
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<i8>>,
    Bound<'py, PyArray1<i64>>,
);

/// The first contact of each of N balls on paths with a table of static objects:
/// ``(time, kind, index)``, each of shape ``(N,)``.
///
/// Ball ``i`` (path ``i``, radius ``radius[i]``) first touches object ``index[i]`` of kind
/// ``kind[i]`` at ``time[i]`` (absolute, as the starts are); ``inf``, ``-1``, ``-1`` if it
/// touches none before ``t_max``. Of contacts at one time the lowest kind wins
/// (``SEGMENT < CIRCLE < TARGET < PLANE``), then the lowest index. The contact with each
/// object (docs/contract.md, section 4.7):
///
/// - a **segment** ``(P, Q)`` (a cushion, a jaw's face): the centre comes within ``radius`` of
///   the line ``P → Q`` with its foot between ``P`` and ``Q``, from a side that counts
///   (``segment_sides``); its ends are not part of it (give them as circles of radius 0). For
///   3-D paths, the vertical wall over that line;
/// - a **circle** ``(C, ρ)``, ``ρ ≥ 0`` (a jaw's rounded tip, a post): the centre comes within
///   ``ρ + radius`` of ``C``, from outside (in 3-D, a sphere);
/// - a **target** ``(C, ρ)``, ``ρ > 0`` (a pocket): the centre enters the disc of radius ``ρ``
///   about ``C``, whatever the ball's radius (in 3-D, a ball of space);
/// - a **plane** ``(Q, n)`` (a table's bed, a wall at any angle): the signed distance
///   ``n·(x − Q)/|n|`` of the centre comes down to ``radius``.
///
/// As for two balls (:func:`path_collision_times`), touching at the first start is a contact
/// only when approaching, a tangency is none, and a horizon only cuts. Each answer is what the
/// Rust ``geometry::path_table_contact`` gives for that path, whatever ``num_threads``.
///
/// Parameters
/// ----------
/// start, pos, vel, acc
///     The balls' paths, as one side of :func:`path_collision_times`: shape ``(N, K)`` and
///     ``(N, K, D)``, ``D`` = 2 or 3, padding with ``+inf`` starts. One path (``N = 1``)
///     stands for every ball.
/// radius
///     A number or shape ``(N,)``: each ball's radius (``> 0``).
/// segments
///     Shape ``(M, 2, 2)``: segment ``m`` runs from ``P = segments[m, 0]`` to
///     ``Q = segments[m, 1]`` (``P ≠ Q``).
/// segment_sides
///     ``None`` (contacts from both sides count), one int for every segment, or ``M`` ints:
///     ``1`` counts only contacts from the left of ``P → Q``, ``-1`` only from its right,
///     ``0`` both.
/// circles, targets
///     Shape ``(M, 3)``, rows ``(cx, cy, rho)``; for 3-D paths ``(M, 4)``,
///     ``(cx, cy, cz, rho)``.
/// planes
///     Shape ``(M, 2, D)``, rows ``(point, normal)``: the normal, of any non-zero length,
///     points to the side the plane is touched from.
/// t_max
///     A number or shape ``(N,)``: horizons (``≥ 0``; a contact at ``t ≥ t_max`` is none).
/// num_threads
///     As in :func:`collision_times`.
/// out
///     ``None``, or a tuple ``(time, kind, index)`` of three arrays of shape ``(N,)`` and
///     dtypes float64, int8 and int64, each writeable, C-contiguous and sharing no memory
///     with another or with the paths, ``radius`` or ``t_max``: the answers are written into
///     them, and they are returned. (The objects are copied before anything is written.)
/// progress
///     As in :func:`collision_times`, counting paths (balls).
///
/// An object argument left out (or ``None``, or ``[]``) is no object of its kind. Every array
/// is read as in :func:`collision_times` (lists, any real dtype, any layout).
///
/// Returns
/// -------
/// time : numpy.ndarray
///     Shape ``(N,)``, float64: when each ball first touches an object (``inf``: none).
/// kind : numpy.ndarray
///     Shape ``(N,)``, int8: that object's kind, :data:`SEGMENT` (0), :data:`CIRCLE` (1),
///     :data:`TARGET` (2) or :data:`PLANE` (3); ``-1`` for none.
/// index : numpy.ndarray
///     Shape ``(N,)``, int64: that object's index among those of its kind (``-1``: none).
///
/// Raises
/// ------
/// InputError
///     As :func:`path_collision_times` for the paths (``vel[3, 1]: must be finite, got
///     NaN``), ``radius`` and ``t_max``. A bad object names its argument and index, with its
///     kind: ``segments[2]: a segment's two ends must differ`` (``degenerate_segment``),
///     ``segment_sides[1]: a segment's side must be -1, 0 or 1, got 2`` (``invalid_side``),
///     ``circles[0]: a circle's radius must be ≥ 0, got -1`` (``negative_circle_radius``),
///     ``targets[3]: a target's radius must be > 0, got 0``
///     (``non_positive_target_radius``), ``planes[0]: a plane's normal must not be zero``
///     (``zero_normal``), a NaN or infinite number (``not_finite``); a wrong shape
///     (``shape``), ``M`` sides for another number of segments (``length_mismatch``). ``out``
///     as in :func:`collision_times`, its arrays named ``out[0]``, ``out[1]``, ``out[2]``.
/// TypeError
///     As :func:`collision_times`; ``segment_sides`` that are not ints (a bool, a float);
///     an ``out`` that is not a tuple of three arrays of those dtypes.
///
/// Notes
/// -----
/// The GIL is released while more than 1024 object queries (``N`` times the number of
/// objects) are computed, and Ctrl-C stops a long call.
///
/// Examples
/// --------
/// >>> import numpy as np
/// >>> import ballcollide as bc
/// >>> # A cushion along y = 0 from x = 0 to 1, played from above (its left), and a pocket
/// >>> # past its end; three balls of radius 0.1 roll down at 1 m/s from y = 1.
/// >>> segments, targets = [[[0, 0], [1, 0]]], [[1.2, 0, 0.05]]
/// >>> start, pos = np.zeros((3, 1)), [[[0.5, 1]], [[1.2, 1]], [[3, 1]]]
/// >>> vel, acc = np.tile([0.0, -1.0], (3, 1, 1)), np.zeros((3, 1, 2))
/// >>> time, kind, index = bc.path_geometry_times(
/// ...     start, pos, vel, acc, 0.1, segments=segments, segment_sides=1, targets=targets)
/// >>> time
/// array([0.9 , 0.95,  inf])
/// >>> kind, index
/// (array([ 0,  2, -1], dtype=int8), array([ 0,  0, -1]))
/// >>> bool(kind[1] == bc.TARGET)
/// True
#[pyfunction]
#[pyo3(
    signature = (
        start, pos, vel, acc, radius, *, segments=None, segment_sides=None, circles=None,
        targets=None, planes=None, t_max=Given(None), num_threads=None, out=None,
        progress=None
    ),
    text_signature = "(start, pos, vel, acc, radius, *, segments=None, segment_sides=None, \
                      circles=None, targets=None, planes=None, t_max=1e999, num_threads=None, \
                      out=None, progress=None)"
)]
#[allow(clippy::too_many_arguments)]
pub(super) fn path_geometry_times<'py>(
    py: Python<'py>,
    start: &Bound<'py, PyAny>,
    pos: &Bound<'py, PyAny>,
    vel: &Bound<'py, PyAny>,
    acc: &Bound<'py, PyAny>,
    radius: &Bound<'py, PyAny>,
    segments: Option<&Bound<'py, PyAny>>,
    segment_sides: Option<&Bound<'py, PyAny>>,
    circles: Option<&Bound<'py, PyAny>>,
    targets: Option<&Bound<'py, PyAny>>,
    planes: Option<&Bound<'py, PyAny>>,
    t_max: Given<'py>,
    num_threads: Option<&Bound<'py, PyAny>>,
    out: Option<&Bound<'py, PyAny>>,
    progress: Option<&Bound<'py, PyAny>>,
) -> PyResult<Answers<'py>> {
    let paths = side(py, NAMES_ONE, [start, pos, vel, acc], Layout::Batch, None)?;
    let radius = param("radius", radius)?;
    let t_max = t_max.param_or("t_max", f64::INFINITY)?;
    let threads = threads(num_threads)?;
    let lengths = [Some(paths.paths), param_len(&radius), param_len(&t_max)];
    let n = broadcast_len(lengths.into_iter().flatten());
    let per_ball = [radius.per_pair(), t_max.per_pair()].map(|p| broadcast(p, n));
    let mut inputs = Vec::from(paths.inputs());
    inputs.extend([radius.each(), t_max.each()]);
    let objects = [segments, segment_sides, circles, targets, planes];
    let call = Call {
        paths: &paths,
        per_ball,
        threads,
        n,
        inputs: &inputs,
        progress,
    };
    match paths.dim {
        2 => call.answers::<2>(py, objects, out),
        _ => call.answers::<3>(py, objects, out),
    }
}

/// A call's arguments, read: the paths, `radius` and `t_max` (per ball, broadcast), the
/// threads, the number of balls, and the arrays read in place or copied (for `out`'s checks).
struct Call<'a> {
    paths: &'a Side<'a>,
    per_ball: [PerPair<'a>; 2],
    threads: Threads,
    n: usize,
    inputs: &'a [Option<&'a Floats<'a>>],
    progress: Option<&'a Bound<'a, PyAny>>,
}

impl Call<'_> {
    /// The answers in dimension `D`, against the objects of `objects` (`segments`,
    /// `segment_sides`, `circles`, `targets`, `planes`).
    fn answers<'py, const D: usize>(
        &self,
        py: Python<'py>,
        [segments, sides, circles, targets, planes]: [Option<&Bound<'py, PyAny>>; 5],
        out: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Answers<'py>> {
        let table = table_of::<D>(py, segments, sides, circles, targets, planes)?;
        let (rows, n, [radius, t_max]) = (self.paths.rows::<D>(), self.n, self.per_ball);
        let threads = self.threads;
        // The inputs' own errors first, then `out`'s.
        batch::check_path_geometry(&rows, radius, t_max, n).map_err(|e| from_core(py, e))?;
        let how = Kernel::for_items(n.saturating_mul(table.len().max(1)), INLINE_UP_TO);
        let released = how != Kernel::Inline;
        let _borrowed = match released {
            true => read::track(self.inputs)?,
            false => Vec::new(),
        };
        let (mut time, mut kind, mut index) = outputs(py, n, out, self.inputs)?;
        let _written = match released {
            true => Some((time.tracked()?, kind.tracked()?, index.tracked()?)),
            false => None,
        };
        // The bar once `out` is checked: made, it is closed whatever the call's end.
        let progress = Progress::of(py, self.progress, Some(n), "path")?;
        let columns = ContactColumns {
            time: time.values(),
            kind: kind.values(),
            index: index.values(),
        };
        run_shown(py, how, progress, || {
            batch::path_geometry_times(&rows, &table, radius, t_max, columns, threads)
        })?;
        Ok((time.into_array(), kind.into_array(), index.into_array()))
    }
}

/// The three outputs being written: time, kind, index.
type Outputs<'py> = (Out<'py, f64, Ix1>, Out<'py, i8, Ix1>, Out<'py, i64, Ix1>);

/// The three output arrays of `n` answers: new ones, or the caller's `out=(time, kind,
/// index)`, each checked as [`read::out_of`] checks one (named `out[0]` … `out[2]`) and
/// sharing no memory with another.
fn outputs<'py>(
    py: Python<'py>,
    n: usize,
    out: Option<&Bound<'py, PyAny>>,
    inputs: &[Option<&Floats<'_>>],
) -> PyResult<Outputs<'py>> {
    let Some(out) = out.filter(|o| !o.is_none()) else {
        return Ok((
            Out::zeros(py, Ix1(n)),
            Out::zeros(py, Ix1(n)),
            Out::zeros(py, Ix1(n)),
        ));
    };
    let items: Vec<Bound<'py, PyAny>> = match (out.cast::<PyTuple>(), out.cast::<PyList>()) {
        (Ok(t), _) => t.iter().collect(),
        (_, Ok(l)) => l.iter().collect(),
        _ => {
            return Err(PyTypeError::new_err(
                "out: expected None or a tuple (time, kind, index) of three arrays",
            ));
        }
    };
    let [time, kind, index] = <[Bound<'py, PyAny>; 3]>::try_from(items).map_err(|items| {
        let reason = format!(
            "expected a tuple (time, kind, index) of three arrays, got a sequence of {}",
            items.len()
        );
        input_error(py, "out", None, kind::OUT_LAYOUT, &reason)
    })?;
    let one = |dtype: &str| format!("a 1-D {dtype} array of shape (N,)");
    let time = read::out_of::<f64, Ix1>(&time, Some(0), &[n], &one("float64"), inputs)?;
    let kind = read::out_of::<i8, Ix1>(&kind, Some(1), &[n], &one("int8"), inputs)?;
    let index = read::out_of::<i64, Ix1>(&index, Some(2), &[n], &one("int64"), inputs)?;
    let spans = [time.span(), kind.span(), index.span()];
    for (k, a) in spans.iter().enumerate() {
        if let Some(j) = spans[..k]
            .iter()
            .position(|b| a.start < b.end && b.start < a.end)
        {
            let reason = format!("the array shares memory with out[{j}]");
            return Err(input_error(
                py,
                "out",
                Some(k),
                kind::SHARED_MEMORY,
                &reason,
            ));
        }
    }
    Ok((time, kind, index))
}

/// A pool table's objects, as the keyword arguments of :func:`simulate`,
/// :class:`CollisionSchedule` and :func:`path_geometry_times` take them: a dict with
/// ``segments`` (shape ``(18, 2, 2)``: the six rails, then two jaws per pocket),
/// ``segment_sides`` (``(18,)``: ``+1`` for the rails, played from the table's side, ``0`` for
/// the jaws), ``circles`` (``(12, 3)``: the round tips where rails meet jaws) and ``targets``
/// (``(6, 3)``: the pockets' capture circles).
///
/// The playing area is ``[0, width] × [0, length]``; the corner pockets are at its corners,
/// the side pockets halfway along the long rails. The defaults are a 9-foot table (2.54 m ×
/// 1.27 m, corner mouths 4.6 in, side mouths 5.1 in) with jaws and pockets of a simplified
/// shape (Rust: ``geometry::PoolTable``).
///
/// Parameters
/// ----------
/// width, length
///     The playing area's sides, along x and y.
/// corner_mouth, side_mouth
///     The pockets' mouths, between the noses.
/// jaw_length, jaw_radius
///     How far each jaw runs into its pocket; the radius of the jaw tips.
/// corner_jaw_angle, side_jaw_angle
///     How far the jaws turn towards their pocket's axis, in degrees.
/// pocket_radius
///     The capture circles' radius.
///
/// Raises
/// ------
/// InputError
///     Dimensions that make a degenerate object.
///
/// Examples
/// --------
/// >>> import ballcollide as bc
/// >>> table = bc.pool_table()
/// >>> {k: v.shape for k, v in table.items()}
/// {'segments': (18, 2, 2), 'segment_sides': (18,), 'circles': (12, 3), 'targets': (6, 3)}
/// >>> run = bc.simulate([[0.635, 0.5]], [[0, 2]], 0.3, 0.028575, box=([-0.3, -0.3], [1.6, 2.9]),
/// ...                   **table)
/// >>> run.captured  # straight up the middle, off the top rail and back: no pocket
/// array([-1])
#[pyfunction]
#[pyo3(signature = (*, width=Given(None), length=Given(None), corner_mouth=Given(None),
                    side_mouth=Given(None), jaw_length=Given(None), jaw_radius=Given(None),
                    corner_jaw_angle=Given(None), side_jaw_angle=Given(None),
                    pocket_radius=Given(None)),
       text_signature = "(*, width=1.27, length=2.54, corner_mouth=0.1168, side_mouth=0.1295, \
                         jaw_length=0.04, jaw_radius=0.005, corner_jaw_angle=7.0, \
                         side_jaw_angle=14.0, pocket_radius=0.045)")]
#[allow(clippy::too_many_arguments)]
pub(super) fn pool_table<'py>(
    py: Python<'py>,
    width: Given<'py>,
    length: Given<'py>,
    corner_mouth: Given<'py>,
    side_mouth: Given<'py>,
    jaw_length: Given<'py>,
    jaw_radius: Given<'py>,
    corner_jaw_angle: Given<'py>,
    side_jaw_angle: Given<'py>,
    pocket_radius: Given<'py>,
) -> PyResult<Bound<'py, pyo3::types::PyDict>> {
    let d = crate::geometry::PoolTable::default();
    let spec = crate::geometry::PoolTable {
        width: width.number_or("width", d.width)?,
        length: length.number_or("length", d.length)?,
        corner_mouth: corner_mouth.number_or("corner_mouth", d.corner_mouth)?,
        side_mouth: side_mouth.number_or("side_mouth", d.side_mouth)?,
        jaw_length: jaw_length.number_or("jaw_length", d.jaw_length)?,
        jaw_radius: jaw_radius.number_or("jaw_radius", d.jaw_radius)?,
        corner_jaw_angle: corner_jaw_angle.number_or("corner_jaw_angle", d.corner_jaw_angle)?,
        side_jaw_angle: side_jaw_angle.number_or("side_jaw_angle", d.side_jaw_angle)?,
        pocket_radius: pocket_radius.number_or("pocket_radius", d.pocket_radius)?,
    };
    let table = spec.table().map_err(|e| from_core(py, e))?;
    // Each kind as one flat run of numbers, reshaped to `(M, width)`.
    let rows = |flat: Vec<f64>, width: usize| -> PyResult<Bound<'py, PyAny>> {
        let n = flat.len() / width;
        PyArray1::from_vec(py, flat).call_method1("reshape", ((n, width),))
    };
    let dict = pyo3::types::PyDict::new(py);
    let ends = |s: &crate::geometry::LineSegment| [s.p().x, s.p().y, s.q().x, s.q().y];
    let segments = table.segments.iter().flat_map(ends).collect();
    let segments = rows(segments, 4)?.call_method1("reshape", ((table.segments.len(), 2, 2),))?;
    dict.set_item("segments", segments)?;
    let sides: Vec<i64> = table.segments.iter().map(|s| s.side().sign()).collect();
    dict.set_item("segment_sides", PyArray1::from_vec(py, sides))?;
    let disc = |c: nalgebra::Vector2<f64>, rho: f64| [c.x, c.y, rho];
    let circles = table
        .circles
        .iter()
        .flat_map(|c| disc(c.centre(), c.rho()))
        .collect();
    dict.set_item("circles", rows(circles, 3)?)?;
    let targets = table
        .targets
        .iter()
        .flat_map(|t| disc(t.centre(), t.rho()))
        .collect();
    dict.set_item("targets", rows(targets, 3)?)?;
    Ok(dict)
}
