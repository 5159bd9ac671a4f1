//! The path functions of the Python API: :func:`path_collision_times`,
//! :func:`path_collision_time` and :func:`path_positions_at`, over paths of
//! constant-acceleration segments in 2-D or 3-D (`crate::path`).
//!
//! A batch side is four arrays, `start` `(N, K)` and `pos`, `vel`, `acc` `(N, K, D)`; one path
//! is `(start (K,), pos (K, D), vel, acc)`. The arrays' shapes are checked here (the core sees
//! rows); their values, the padding with `+∞` starts and the lengths are checked by
//! [`crate::batch`], whose functions these call once per dimension: each is generic over
//! `D` and instantiated for 2 and 3.

use super::input_error::kind;
use std::num::NonZeroUsize;

use numpy::ndarray::{Ix1, Ix2};
use numpy::{PyArray1, PyArray2};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};

use super::input_error::{from_core, input_error, located_error};
use super::long_call::{INLINE_UP_TO, Kernel, Progress, run};
use super::read::{self, Floats, Given, Param, param, shape_text, threads};
use super::{output, timed};
use crate::batch::{self, PathPairs, PathRows, PerPair, Threads};

/// The argument names of one side's four arrays.
type Names = [&'static str; 4];

const NAMES_A: Names = ["start_a", "pos_a", "vel_a", "acc_a"];
const NAMES_B: Names = ["start_b", "pos_b", "vel_b", "acc_b"];
pub(super) const NAMES_ONE: Names = ["start", "pos", "vel", "acc"];

/// How a side's arrays are shaped: `(N, K)` and `(N, K, D)` in a batch, `(K,)` and `(K, D)`
/// for a single path.
#[derive(Clone, Copy, PartialEq)]
pub(super) enum Layout {
    Batch,
    Single,
}

impl Layout {
    /// `start`'s number of dimensions.
    fn start_dims(self) -> usize {
        match self {
            Self::Batch => 2,
            Self::Single => 1,
        }
    }

    /// `start`'s shape in words, and `pos`'s without its last dimension.
    fn lead_text(self) -> &'static str {
        match self {
            Self::Batch => "N, K",
            Self::Single => "K",
        }
    }
}

/// One side's arrays, read and shaped: `paths` paths of `segments` rows of `dim` numbers.
pub(super) struct Side<'py> {
    arrays: [Floats<'py>; 4],
    pub(super) paths: usize,
    pub(super) segments: usize,
    pub(super) dim: usize,
}

impl Side<'_> {
    /// The rows the core reads (`D` must be `self.dim`).
    pub(super) fn rows<const D: usize>(&self) -> PathRows<'_, D> {
        let [start, pos, vel, acc] = &self.arrays;
        PathRows {
            start: start.values(),
            pos: pos.rows(),
            vel: vel.rows(),
            acc: acc.rows(),
            segments: self.segments,
        }
    }

    pub(super) fn inputs(&self) -> [Option<&Floats<'_>>; 4] {
        self.arrays.each_ref().map(Some)
    }
}

/// Reads a side's four arrays and checks their shapes: `start` of `layout`'s dimensions, and
/// `pos`, `vel`, `acc` of `start`'s shape and one more dimension `D`, 2 or 3 (`dim` if given:
/// side A's, which side B must share).
pub(super) fn side<'py>(
    py: Python<'py>,
    names: Names,
    objects: [&Bound<'py, PyAny>; 4],
    layout: Layout,
    dim: Option<usize>,
) -> PyResult<Side<'py>> {
    let lead = layout.lead_text();
    let (start, start_shape) = read::shaped(names[0], objects[0])?;
    if start_shape.len() != layout.start_dims() {
        let shape = shape_text(&start_shape);
        let reason = format!("expected shape ({lead}{}), got {shape}", comma(layout));
        return Err(input_error(py, names[0], None, kind::SHAPE, &reason));
    }
    let (pos, pos_shape) = read::shaped(names[1], objects[1])?;
    let d = match (pos_shape.split_last(), dim) {
        (Some((&d, rest)), None) if rest.len() == start_shape.len() && matches!(d, 2 | 3) => d,
        (Some((&d, rest)), Some(want)) if rest.len() == start_shape.len() && d == want => d,
        (_, None) => {
            let shape = shape_text(&pos_shape);
            let reason = format!("expected shape ({lead}, 2) or ({lead}, 3), got {shape}");
            return Err(input_error(py, names[1], None, kind::SHAPE, &reason));
        }
        (_, Some(want)) => {
            let shape = shape_text(&pos_shape);
            let reason = format!(
                "expected shape ({lead}, {want}) like pos_a (the same dimension), got {shape}"
            );
            return Err(input_error(py, names[1], None, kind::SHAPE, &reason));
        }
    };
    let mut expected = start_shape.clone();
    expected.push(d);
    if pos_shape != expected {
        let reason = format!(
            "expected shape {} like {} {}, got {}",
            shape_text(&expected),
            names[0],
            shape_text(&start_shape),
            shape_text(&pos_shape)
        );
        return Err(input_error(py, names[1], None, kind::SHAPE, &reason));
    }
    let same_as_pos = |name: &str, obj: &Bound<'py, PyAny>| -> PyResult<Floats<'py>> {
        let (values, shape) = read::shaped(name, obj)?;
        if shape != expected {
            let reason = format!(
                "expected shape {} like {}, got {}",
                shape_text(&expected),
                names[1],
                shape_text(&shape)
            );
            return Err(input_error(py, name, None, kind::SHAPE, &reason));
        }
        Ok(values)
    };
    let vel = same_as_pos(names[2], objects[2])?;
    let acc = same_as_pos(names[3], objects[3])?;
    let (paths, segments) = match *start_shape.as_slice() {
        [n, k] => (n, k),
        [k] => (1, k),
        _ => (0, 0),
    };
    Ok(Side {
        arrays: [start, pos, vel, acc],
        paths,
        segments,
        dim: d,
    })
}

/// The comma of a one-element shape: `(K,)`.
fn comma(layout: Layout) -> &'static str {
    match layout {
        Layout::Batch => "",
        Layout::Single => ",",
    }
}

/// The batch's length `N`: the first of `lengths` other than 1 (numpy's broadcasting of a
/// leading dimension of 1), else 1. The core checks that every other length is 1 or `N`.
pub(super) fn broadcast_len(lengths: impl IntoIterator<Item = usize>) -> usize {
    lengths.into_iter().find(|&n| n != 1).unwrap_or(1)
}

/// A per-pair parameter's length, if it has one.
pub(super) fn param_len(p: &Param<'_>) -> Option<usize> {
    p.each().map(|values| values.values().len())
}

/// A per-pair parameter of one value, broadcast: that value for all `n` pairs.
pub(super) fn broadcast<'a>(p: PerPair<'a>, n: usize) -> PerPair<'a> {
    match p {
        PerPair::Each(&[x]) if n != 1 => PerPair::All(x),
        p => p,
    }
}

/// The first contact time of each of N pairs of paths (absolute; ``inf`` where none).
///
/// Pair ``i`` is path ``i`` of A against path ``i`` of B at contact distance
/// ``contact_distance``.
/// A path is a list of segments ``(s_k, p_k, v_k, a_k)`` with non-decreasing absolute
/// starts; on ``[s_k, s_{k+1})`` the centre is ``p_k + v_k·(t − s_k) + ½·a_k·(t − s_k)²``,
/// and the last segment lasts for ever. The search starts at the later of the two first
/// starts; touching or overlapping there is a contact only if the balls approach; a path
/// that jumps into overlap at a later segment start collides at that start; a tangency is
/// no contact. Each answer is exactly what :func:`path_collision_time` gives for that pair.
///
/// Parameters
/// ----------
/// start_a, start_b
///     Shape ``(N, K)``: segment starts (absolute times). A path of fewer than ``K``
///     segments is padded at the end with starts of ``+inf``, whose other values are
///     ignored (NaN allowed). A and B may have different ``K``.
/// pos_a, vel_a, acc_a, pos_b, vel_b, acc_b
///     Shape ``(N, K, D)``, ``D`` = 2 or 3 (the same for both sides): each segment's
///     centre and velocity at its start, and its constant acceleration.
/// contact_distance, t_max
///     Numbers or shape ``(N,)``: contact distances (sums of the radii, ``> 0``) and
///     horizons (``≥ 0``, ``inf`` for none; a contact at ``t ≥ t_max`` is none).
///     ``radius=`` is ``contact_distance``'s former name, deprecated.
/// num_threads, out, progress
///     As in :func:`collision_times` (``progress`` counts pairs).
///
/// A leading dimension of 1 broadcasts against ``N`` (on either side, and for
/// ``contact_distance`` and ``t_max``): one path of A against N paths of B is "ball ``i``
/// against all others".
/// Inputs are read as in :func:`collision_times` (lists, any real dtype, any layout).
///
/// Returns
/// -------
/// numpy.ndarray
///     Shape ``(N,)``, float64 (``out`` itself if given).
///
/// Raises
/// ------
/// InputError
///     A ``ValueError``: a NaN or infinite value in a used segment, starts that decrease, a
///     first start of ``+inf``, ``K = 0``, ``contact_distance ≤ 0``, a negative ``t_max``,
///     a wrong shape or dimension, ``N`` other than 1 or the batch's; the message names the
///     argument, the pair and the segment, e.g. ``start_b[7, 2]: starts must not decrease,
///     got 1 after 2`` (``.argument``, ``.index`` (the pair), ``.segment``, ``.reason``).
///     ``out`` as in :func:`collision_times`.
/// TypeError
///     As :func:`collision_times`.
///
/// Notes
/// -----
/// The GIL is released while more than 1024 pairs are computed.
///
/// Examples
/// --------
/// >>> import numpy as np
/// >>> import ballcollide as bc
/// >>> # A (one path, broadcast) moves along x at 1 m/s and stops at x = 2 at t = 2; the two
/// >>> # B balls rest at x = 2.5 and x = 3.5. Contact distance 1.
/// >>> start_a, pos_a, vel_a = [[0.0, 2.0]], [[[0, 0], [2, 0]]], [[[1, 0], [0, 0]]]
/// >>> acc_a = np.zeros((1, 2, 2))
/// >>> start_b, pos_b = [[0.0], [0.0]], [[[2.5, 0]], [[3.5, 0]]]
/// >>> rest = np.zeros((2, 1, 2))
/// >>> bc.path_collision_times(start_a, pos_a, vel_a, acc_a, start_b, pos_b, rest, rest, 1.0)
/// array([1.5, inf])
#[pyfunction]
#[pyo3(
    signature = (
        start_a, pos_a, vel_a, acc_a, start_b, pos_b, vel_b, acc_b,
        contact_distance=Given(None), *, t_max=Given(None), num_threads=None, out=None,
        progress=None, radius=Given(None)
    ),
    text_signature = "(start_a, pos_a, vel_a, acc_a, start_b, pos_b, vel_b, acc_b, \
                      contact_distance, *, t_max=1e999, num_threads=None, out=None, \
                      progress=None)"
)]
#[allow(clippy::too_many_arguments)]
pub(super) fn path_collision_times<'py>(
    py: Python<'py>,
    start_a: &Bound<'py, PyAny>,
    pos_a: &Bound<'py, PyAny>,
    vel_a: &Bound<'py, PyAny>,
    acc_a: &Bound<'py, PyAny>,
    start_b: &Bound<'py, PyAny>,
    pos_b: &Bound<'py, PyAny>,
    vel_b: &Bound<'py, PyAny>,
    acc_b: &Bound<'py, PyAny>,
    contact_distance: Given<'py>,
    t_max: Given<'py>,
    num_threads: Option<&Bound<'py, PyAny>>,
    out: Option<&Bound<'py, PyAny>>,
    progress: Option<&Bound<'py, PyAny>>,
    radius: Given<'py>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let contact_distance = read::contact_distance(py, contact_distance, radius)?;
    let a = side(
        py,
        NAMES_A,
        [start_a, pos_a, vel_a, acc_a],
        Layout::Batch,
        None,
    )?;
    let b = side(
        py,
        NAMES_B,
        [start_b, pos_b, vel_b, acc_b],
        Layout::Batch,
        Some(a.dim),
    )?;
    let contact_distance = param("contact_distance", &contact_distance)?;
    let t_max = t_max.param_or("t_max", f64::INFINITY)?;
    let threads = threads(num_threads)?;
    let lengths = [
        Some(a.paths),
        Some(b.paths),
        param_len(&contact_distance),
        param_len(&t_max),
    ];
    let n = broadcast_len(lengths.into_iter().flatten());
    let per_pair = [contact_distance.per_pair(), t_max.per_pair()].map(|p| broadcast(p, n));
    let mut inputs = Vec::from(a.inputs());
    inputs.extend(b.inputs());
    inputs.extend([contact_distance.each(), t_max.each()]);
    let expected = "a 1-D float64 array of shape (N,)";
    let call = BatchCall {
        threads,
        n,
        out,
        progress,
        inputs: &inputs,
        expected,
    };
    match a.dim {
        2 => batch_times::<2>(py, [&a, &b], per_pair, call),
        _ => batch_times::<3>(py, [&a, &b], per_pair, call),
    }
}

/// What [`path_collision_times`] passes on to [`batch_times`] besides the pairs.
struct BatchCall<'a, 'py> {
    threads: Threads,
    n: usize,
    out: Option<&'a Bound<'py, PyAny>>,
    progress: Option<&'a Bound<'py, PyAny>>,
    inputs: &'a [Option<&'a Floats<'a>>],
    expected: &'a str,
}

/// [`path_collision_times`] in dimension `D`.
fn batch_times<'py, const D: usize>(
    py: Python<'py>,
    [a, b]: [&Side<'_>; 2],
    [contact_distance, t_max]: [PerPair<'_>; 2],
    call: BatchCall<'_, 'py>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let BatchCall {
        threads,
        n,
        out,
        progress,
        inputs,
        expected,
    } = call;
    let pairs = PathPairs::<D> {
        a: a.rows(),
        b: b.rows(),
        contact_distance,
        t_max,
    };
    // The inputs' own errors first, then `out`'s.
    batch::check_path_pairs(&pairs, n).map_err(|e| from_core(py, e))?;
    output::<Ix1>(py, n, out, [n], expected, inputs, |times| {
        // The bar once `out` is checked: made, it is closed whatever the call's end.
        let progress = Progress::of(py, progress, Some(n), "pair")?;
        timed(py, n, progress, || {
            batch::path_collision_times(&pairs, times, threads)
        })
    })
}

/// The four arrays of a path given as a tuple (or list) ``(start, pos, vel, acc)``.
fn path_tuple<'py>(name: &str, obj: &Bound<'py, PyAny>) -> PyResult<[Bound<'py, PyAny>; 4]> {
    let items: Option<Vec<Bound<'py, PyAny>>> = match (obj.cast::<PyTuple>(), obj.cast::<PyList>())
    {
        (Ok(t), _) => Some(t.iter().collect()),
        (_, Ok(l)) => Some(l.iter().collect()),
        _ => None,
    };
    match items.map(<[Bound<'py, PyAny>; 4]>::try_from) {
        Some(Ok(items)) => Ok(items),
        Some(Err(items)) => {
            let reason = format!(
                "expected a path (start, pos, vel, acc), got a sequence of {}",
                items.len()
            );
            Err(input_error(obj.py(), name, None, kind::SHAPE, &reason))
        }
        None => Err(PyTypeError::new_err(format!(
            "{name}: expected a path: a tuple (start, pos, vel, acc), got {}",
            obj.get_type()
                .name()
                .map_or_else(|_| "another type".to_owned(), |n| n.to_string())
        ))),
    }
}

/// The first contact time of two balls on paths (absolute), or ``inf`` if they never touch.
///
/// Parameters
/// ----------
/// path_a, path_b
///     Each a tuple ``(start, pos, vel, acc)``: ``start`` of shape ``(K,)`` (segment starts,
///     non-decreasing, padding with ``+inf`` allowed at the end), ``pos``, ``vel``, ``acc``
///     of shape ``(K, D)``, ``D`` = 2 or 3 (the same for both); the model and the padding
///     are those of :func:`path_collision_times`. A and B may have different ``K``.
/// contact_distance
///     The sum of the two balls' radii (``> 0``). ``radius=`` is its former name,
///     deprecated.
/// t_max
///     Horizon: a collision at ``t ≥ t_max`` is reported as ``inf``.
///
/// Returns
/// -------
/// float
///     Exactly the value :func:`path_collision_times` gives for the same pair.
///
/// Raises
/// ------
/// InputError
///     As :func:`path_collision_times`; the arrays are named ``start_a`` … ``acc_b``, and a
///     bad value by its segment, e.g. ``vel_b[1]: must be finite, got NaN`` (``.index`` is
///     ``None``, ``.segment`` is 1). A path that is not four arrays.
/// TypeError
///     As :func:`path_collision_times`, or a path that is not a tuple or list.
///
/// Examples
/// --------
/// >>> import ballcollide as bc
/// >>> # A ball falls from 1 m under gravity onto one resting on the floor (3-D).
/// >>> a = ([0.0], [[0, 0, 1.0]], [[0, 0, 0]], [[0, 0, -9.81]])
/// >>> b = ([0.0], [[0, 0, 0]], [[0, 0, 0]], [[0, 0, 0]])
/// >>> t = bc.path_collision_time(a, b, 0.5)  # falls 0.5 m: t = sqrt(2·0.5/9.81)
/// >>> round(t, 6)
/// 0.319275
#[pyfunction]
#[pyo3(
    signature = (
        path_a, path_b, contact_distance=Given(None), *, t_max=Given(None), radius=Given(None)
    ),
    text_signature = "(path_a, path_b, contact_distance, *, t_max=1e999)"
)]
pub(super) fn path_collision_time(
    py: Python<'_>,
    path_a: &Bound<'_, PyAny>,
    path_b: &Bound<'_, PyAny>,
    contact_distance: Given<'_>,
    t_max: Given<'_>,
    radius: Given<'_>,
) -> PyResult<f64> {
    let contact_distance = read::contact_distance(py, contact_distance, radius)?;
    let [sa, pa, va, aa] = path_tuple("path_a", path_a)?;
    let [sb, pb, vb, ab] = path_tuple("path_b", path_b)?;
    let a = side(py, NAMES_A, [&sa, &pa, &va, &aa], Layout::Single, None)?;
    let b = side(
        py,
        NAMES_B,
        [&sb, &pb, &vb, &ab],
        Layout::Single,
        Some(a.dim),
    )?;
    let contact_distance = PerPair::All(read::number("contact_distance", &contact_distance)?);
    let t_max = PerPair::All(t_max.number_or("t_max", f64::INFINITY)?);
    let mut out = [0.0];
    let one = Threads::AtMost(NonZeroUsize::MIN);
    let result = match a.dim {
        2 => single_time::<2>([&a, &b], [contact_distance, t_max], &mut out, one),
        _ => single_time::<3>([&a, &b], [contact_distance, t_max], &mut out, one),
    };
    // A single query: the message names the argument and the segment, not a pair.
    result.map_err(|e| {
        let reason = e.kind().to_string();
        let kind = (e.kind().code(), e.kind().value());
        located_error(py, e.argument(), [None, e.segment()], kind, &reason)
    })?;
    Ok(out[0])
}

/// [`path_collision_time`] in dimension `D`: the batch of one pair.
fn single_time<const D: usize>(
    [a, b]: [&Side<'_>; 2],
    [contact_distance, t_max]: [PerPair<'_>; 2],
    out: &mut [f64; 1],
    threads: Threads,
) -> Result<(), crate::InputError> {
    let pairs = PathPairs::<D> {
        a: a.rows(),
        b: b.rows(),
        contact_distance,
        t_max,
    };
    batch::path_collision_times(&pairs, out, threads)
}

/// The centres of N balls on paths at times ``t`` (shape ``(N, D)``).
///
/// Row ``i`` is the centre of path ``i`` at ``t[i]``, by its active segment's formula
/// ``p_k + v_k·(t − s_k) + ½·a_k·(t − s_k)²`` (see :func:`path_collision_times`); a time
/// before a path's first start gives its first position.
///
/// Parameters
/// ----------
/// start, pos, vel, acc
///     One side of :func:`path_collision_times`: shape ``(N, K)`` and ``(N, K, D)``.
/// t
///     A number or shape ``(N,)``: the times (finite).
/// num_threads, out
///     As in :func:`collision_times`; ``out`` of shape ``(N, D)``.
///
/// A leading dimension of 1 broadcasts: one path (``N = 1``) at many times draws it.
///
/// Returns
/// -------
/// numpy.ndarray
///     Shape ``(N, D)``, float64 (``out`` itself if given).
///
/// Raises
/// ------
/// InputError, TypeError
///     As :func:`path_collision_times`, e.g. ``vel[3, 1]: must be finite, got NaN`` or
///     ``t[2]: must be finite, got inf``.
///
/// Examples
/// --------
/// >>> import ballcollide as bc
/// >>> # One path at three times: 1 m/s along x, then at rest at x = 2 from t = 2.
/// >>> path = ([[0.0, 2.0]], [[[0, 0], [2, 0]]], [[[1, 0], [0, 0]]], [[[0, 0], [0, 0]]])
/// >>> bc.path_positions_at(*path, [-1.0, 0.5, 9.0])
/// array([[0. , 0. ],
///        [0.5, 0. ],
///        [2. , 0. ]])
#[pyfunction]
#[pyo3(signature = (start, pos, vel, acc, t, *, num_threads=None, out=None))]
#[allow(clippy::too_many_arguments)]
pub(super) fn path_positions_at<'py>(
    py: Python<'py>,
    start: &Bound<'py, PyAny>,
    pos: &Bound<'py, PyAny>,
    vel: &Bound<'py, PyAny>,
    acc: &Bound<'py, PyAny>,
    t: &Bound<'py, PyAny>,
    num_threads: Option<&Bound<'py, PyAny>>,
    out: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let paths = side(py, NAMES_ONE, [start, pos, vel, acc], Layout::Batch, None)?;
    let t = param("t", t)?;
    let threads = threads(num_threads)?;
    let n = broadcast_len([Some(paths.paths), param_len(&t)].into_iter().flatten());
    let times = broadcast(t.per_pair(), n);
    let mut inputs = Vec::from(paths.inputs());
    inputs.push(t.each());
    match paths.dim {
        2 => positions::<2>(py, &paths, times, threads, n, out, &inputs),
        _ => positions::<3>(py, &paths, times, threads, n, out, &inputs),
    }
}

/// [`path_positions_at`] in dimension `D`.
fn positions<'py, const D: usize>(
    py: Python<'py>,
    paths: &Side<'_>,
    t: PerPair<'_>,
    threads: Threads,
    n: usize,
    out: Option<&Bound<'py, PyAny>>,
    inputs: &[Option<&Floats<'_>>],
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let rows = paths.rows::<D>();
    batch::check_path_positions(&rows, t, n).map_err(|e| from_core(py, e))?;
    let expected = format!("a 2-D float64 array of shape (N, {D})");
    output::<Ix2>(py, n, out, [n, D], &expected, inputs, |flat| {
        let centres = flat.as_chunks_mut::<D>().0;
        run(py, Kernel::for_items(n, INLINE_UP_TO), || {
            batch::path_positions_at(&rows, t, centres, threads)
        })
    })
}
