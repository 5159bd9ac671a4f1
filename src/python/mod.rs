//! The Python extension module `ballcollide._core` (feature `python`): the whole Python API.
//!
//! `python/ballcollide/__init__.py` re-exports these functions as they are. Each reads its
//! arguments once ([`read`]: lists, any real dtype, C or Fortran order, strided views,
//! read-only or big-endian arrays, any real number where a scalar goes), releases the GIL for
//! batches large enough to be worth it, and calls [`crate::batch`], [`crate::scene`] and
//! [`crate::poly`]. Validation of values is the core's, so Python and Rust give identical
//! answers and messages. The functions on paths of constant-acceleration segments are in
//! [`paths`].
//!
//! The `///` comments of the `#[pyfunction]`s below are the Python docstrings (numpydoc, with
//! doctests run by `tests/python/test_api.py`): the one place the Python API is documented.
//! `_core.pyi` holds only the types.
//!
//! Errors: bad values, shapes, lengths and layouts raise [`InputError`] (a `ValueError` with
//! `.argument`, `.index` and `.reason`); what is not made of real numbers raises `TypeError`.
//! Nothing here panics on any input.

mod geometry;
mod input_error;
mod long_call;
mod paths;
mod pooltool_inputs;
mod pooltool_system;
mod read;
mod schedule;
mod shots;
mod table;

use std::cell::Cell;
use std::num::NonZeroUsize;
use std::time::Instant;

use numpy::ndarray::{Dim, Dimension, IntoDimension, Ix1, Ix2};
use numpy::{PyArray, PyArray1, PyArray2, PyArrayMethods};
use pyo3::exceptions::PyMemoryError;
use pyo3::prelude::*;
use rayon::prelude::*;

use crate::batch::{self, Pairs, PerPair, Threads};
use crate::error::InputErrorKind;
use crate::poly;
use crate::scene::{self, SceneOptions};
use input_error::{InputError, from_core, input_error, kind};
use long_call::{INLINE_UP_TO, Kernel, Progress, run, run_shown};
use read::{Floats, Given, number, param, point, rows, threads};

// The `text_signature`s spell the default horizon `1e999`, a literal that reads as `inf`
// (`inspect.signature` shows `t_max=inf`), where pyo3 would show `...`.

/// Scenes of up to this many balls run on the calling thread holding the GIL: their work
/// grows with the pairs that can meet, and from a few dozen balls on it is worth releasing.
const SCENE_INLINE_UP_TO: usize = 16;

/// The collision time of each of N pairs of balls (``inf`` where they never touch).
///
/// Pair ``i`` is ball A (``pos_a[i]``, ``vel_a[i]``, ``friction_a``) against ball B
/// (``pos_b[i]``, ``vel_b[i]``, ``friction_b``) at contact distance ``contact_distance``;
/// each answer is exactly what :func:`collision_time` gives for that pair.
///
/// Parameters
/// ----------
/// pos_a, vel_a, pos_b, vel_b
///     Shape ``(N, 2)``: centres and velocities at time 0. Any real dtype, C or Fortran
///     order, strided views and nested lists are accepted (converted once to C-ordered
///     float64; arrays that already are so are read in place).
/// friction_a, friction_b, contact_distance, t_max
///     Numbers (the same for every pair) or shape ``(N,)``: friction decelerations
///     (``≥ 0``), contact distances (sums of the radii, ``> 0``), horizons (``≥ 0``,
///     ``inf`` for none). A number is anything ``float()`` accepts but a bool.
///     ``radius=`` is ``contact_distance``'s former name, deprecated (a
///     ``DeprecationWarning``): in the scene and calendar calls ``radius`` is one ball's.
/// num_threads
///     ``None`` (default): all cores. An int ``n ≥ 1``: at most ``n`` threads. The result
///     does not depend on it, bit for bit. Batches of up to 1024 pairs run on the calling
///     thread.
/// out
///     ``None`` (default): the times go into a new array. Else a writeable, C-contiguous
///     float64 array of shape ``(N,)`` that shares no memory with the inputs: the times are
///     written into it and it is returned, as numpy's ``out=``. A simulator that asks again
///     after every event saves the allocation, and the page faults of a fresh array, on
///     each call. If the call raises, its contents are unspecified.
/// progress
///     ``None`` or ``False`` (default): none. ``True``: a ``tqdm`` progress bar of the
///     pairs done (tqdm must be installed: the ``progress`` extra). A tqdm-like bar of
///     your own (``update(n)``, ``close()``), or a callable called with the number of new
///     pairs done. Moved on every 0.05 s, from chunk to chunk; what it is shown adds up to
///     N when the call succeeds. The answers do not depend on it.
///
/// Returns
/// -------
/// numpy.ndarray
///     Shape ``(N,)``, float64 (``out`` itself if given).
///
/// Raises
/// ------
/// InputError
///     A ``ValueError``: a NaN or infinite number, a negative friction, a
///     ``contact_distance ≤ 0``, a negative ``t_max``, a wrong shape or a length that
///     differs from ``pos_a``'s; the message names the argument and the first offending
///     index, e.g. ``friction_b[7]: friction must be ≥ 0, got -0.1`` (``.argument``,
///     ``.index``, ``.reason``). An ``out`` of the wrong shape, not C-contiguous, read-only
///     or sharing memory with an input; a ``num_threads`` below 1.
/// TypeError
///     An argument that is not made of real numbers, a non-integer ``num_threads``, or an
///     ``out`` that is not a float64 array of one dimension.
///
/// Notes
/// -----
/// The GIL is released while more than 1024 pairs are computed, so other Python threads
/// keep running. C-ordered float64 inputs are read in place, without a copy: do not modify
/// them from another thread during the call.
///
/// Examples
/// --------
/// >>> import numpy as np
/// >>> import ballcollide as bc
/// >>> pos_a = np.zeros((3, 2))
/// >>> vel_a = np.array([[1.0, 0.0], [1.0, 0.0], [2.0, 0.0]])
/// >>> pos_b = np.array([[1.0, 0.0], [1.0, 5.0], [1.0, 0.0]])
/// >>> bc.collision_times(pos_a, vel_a, 0.0, pos_b, np.zeros((3, 2)), 0.0, 0.5)
/// array([0.5 ,  inf, 0.25])
/// >>> bc.collision_times(pos_a, vel_a, [0.0, 0.0, 8.0], pos_b, np.zeros((3, 2)), 0.0, 0.5)
/// array([0.5, inf, inf])
/// >>> times = np.empty(3)
/// >>> bc.collision_times(pos_a, vel_a, 0.0, pos_b, np.zeros((3, 2)), 0.0, 0.5, out=times)
/// array([0.5 ,  inf, 0.25])
#[pyfunction]
#[pyo3(
    signature = (
        pos_a, vel_a, friction_a, pos_b, vel_b, friction_b, contact_distance=Given(None),
        *, t_max=Given(None), num_threads=None, out=None, progress=None, radius=Given(None)
    ),
    text_signature = "(pos_a, vel_a, friction_a, pos_b, vel_b, friction_b, contact_distance, \
                      *, t_max=1e999, num_threads=None, out=None, progress=None)"
)]
#[allow(clippy::too_many_arguments)]
fn collision_times<'py>(
    py: Python<'py>,
    pos_a: &Bound<'py, PyAny>,
    vel_a: &Bound<'py, PyAny>,
    friction_a: &Bound<'py, PyAny>,
    pos_b: &Bound<'py, PyAny>,
    vel_b: &Bound<'py, PyAny>,
    friction_b: &Bound<'py, PyAny>,
    contact_distance: Given<'py>,
    t_max: Given<'py>,
    num_threads: Option<&Bound<'py, PyAny>>,
    out: Option<&Bound<'py, PyAny>>,
    progress: Option<&Bound<'py, PyAny>>,
    radius: Given<'py>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let contact_distance = read::contact_distance(py, contact_distance, radius)?;
    let pos_a = rows("pos_a", pos_a)?;
    let vel_a = rows("vel_a", vel_a)?;
    let friction_a = param("friction_a", friction_a)?;
    let pos_b = rows("pos_b", pos_b)?;
    let vel_b = rows("vel_b", vel_b)?;
    let friction_b = param("friction_b", friction_b)?;
    let contact_distance = param("contact_distance", &contact_distance)?;
    let t_max = t_max.param_or("t_max", f64::INFINITY)?;
    let threads = threads(num_threads)?;
    let pairs = Pairs {
        pos_a: pos_a.rows(),
        vel_a: vel_a.rows(),
        friction_a: friction_a.per_pair(),
        pos_b: pos_b.rows(),
        vel_b: vel_b.rows(),
        friction_b: friction_b.per_pair(),
        contact_distance: contact_distance.per_pair(),
        t_max: t_max.per_pair(),
    };
    let n = pairs.pos_a.len();
    // The inputs' own errors first, then `out`'s.
    batch::check_lengths(&pairs, n).map_err(|e| from_core(py, e))?;
    let inputs = [
        Some(&pos_a),
        Some(&vel_a),
        Some(&pos_b),
        Some(&vel_b),
        friction_a.each(),
        friction_b.each(),
        contact_distance.each(),
        t_max.each(),
    ];
    let expected = "a 1-D float64 array of shape (N,)";
    output::<Ix1>(py, n, out, [n], expected, &inputs, |times| {
        // The bar once `out` is checked: made, it is closed whatever the call's end.
        let progress = Progress::of(py, progress, Some(n), "pair")?;
        timed(py, n, progress, || {
            batch::collision_times(&pairs, times, threads)
        })
    })
}

/// The result array: `out` (checked: see [`read::out`]) or a new one of `shape`, written by
/// `fill`. The inputs read in place are borrowed through rust-numpy's registry first if the
/// batch of `items` is large enough for the GIL to be released ([`read::track`]).
fn output<'py, D: Dimension>(
    py: Python<'py>,
    items: usize,
    out: Option<&Bound<'py, PyAny>>,
    shape: impl IntoDimension<Dim = D>,
    expected: &str,
    inputs: &[Option<&Floats<'_>>],
    fill: impl FnOnce(&mut [f64]) -> PyResult<()>,
) -> PyResult<Bound<'py, PyArray<f64, D>>> {
    let shape = shape.into_dimension();
    let _borrowed = match items > INLINE_UP_TO {
        true => read::track(inputs)?,
        false => Vec::new(),
    };
    let Some(out) = out else {
        let fresh = PyArray::<f64, D>::zeros(py, shape, false);
        // SAFETY: a new array, which nothing else holds yet.
        fill(unsafe { fresh.as_slice_mut() }.map_err(|_| layout(py))?)?;
        return Ok(fresh);
    };
    let mut written = read::out::<D>(out, shape.slice(), expected, inputs)?;
    let _borrowed = match items > INLINE_UP_TO {
        true => Some(written.tracked()?),
        false => None,
    };
    fill(written.values())?;
    Ok(written.into_array())
}

/// An output array that is not C-contiguous after all (checked before: never seen).
fn layout(py: Python<'_>) -> PyErr {
    input_error(
        py,
        "out",
        None,
        kind::OUT_LAYOUT,
        "expected a C-contiguous, aligned float64 array",
    )
}

thread_local! {
    /// How long the Rust kernel ran in this thread's last `collision_times` (or
    /// `path_collision_times`) call of more than [`INLINE_UP_TO`] pairs, in seconds.
    static LAST_KERNEL_SECONDS: Cell<f64> = const { Cell::new(f64::NAN) };
}

/// [`run_shown`], timing the kernel of batches of more than [`INLINE_UP_TO`] pairs
/// ([`_last_kernel_seconds`]); small batches are not timed, so as not to add the clock's cost
/// to calls that cost a microsecond.
fn timed(
    py: Python<'_>,
    n: usize,
    progress: Option<Progress>,
    kernel: impl Send + FnOnce() -> Result<(), crate::InputError>,
) -> PyResult<()> {
    let how = Kernel::for_items(n, INLINE_UP_TO);
    if how == Kernel::Inline {
        return run_shown(py, how, progress, kernel);
    }
    let seconds = run_shown(py, how, progress, || {
        let start = Instant::now();
        kernel()?;
        Ok(start.elapsed().as_secs_f64())
    })?;
    LAST_KERNEL_SECONDS.with(|last| last.set(seconds));
    Ok(())
}

/// How a scene query of `n` balls runs: its work grows with the pairs that can meet, some
/// dozens a ball.
fn scene_kernel(n: usize) -> Kernel {
    const PAIRS_A_BALL: usize = 64;
    Kernel::for_items(
        n.saturating_mul(PAIRS_A_BALL),
        SCENE_INLINE_UP_TO * PAIRS_A_BALL,
    )
}

/// Seconds the Rust kernel took inside this thread's last :func:`collision_times` (or
/// :func:`path_collision_times`) call on more than 1024 pairs (NaN before any).
///
/// What ``benchmarks/compare.py`` subtracts from the call's own time to measure what the
/// binding adds, in the same call (separate runs on shared cores differ by more than that).
/// Private: for benchmarks.
#[pyfunction]
fn _last_kernel_seconds() -> f64 {
    LAST_KERNEL_SECONDS.with(Cell::get)
}

/// The SIMD level the batches run at: ``"avx512"``, ``"avx2"``, ``"neon"`` or
/// ``"portable"``, the widest this CPU has unless the environment variable
/// ``BALLCOLLIDE_SIMD`` names another (read once, at the first batch). Every level gives the
/// same answers, bit for bit; only the speed differs. Benchmarks print it beside the CPU.
///
/// Examples
/// --------
/// >>> import ballcollide as bc
/// >>> bc.simd_level() in ("avx512", "avx2", "neon", "portable")
/// True
#[pyfunction]
fn simd_level() -> &'static str {
    crate::simd::current().name()
}

/// The time at which two balls first touch, or ``inf`` if they never do.
///
/// Parameters
/// ----------
/// pos_a, vel_a, pos_b, vel_b
///     Centre and velocity of each ball at time 0, as ``(x, y)``: two numbers (a list, a
///     tuple, an array).
/// friction_a, friction_b
///     Each ball's friction deceleration ``μ ≥ 0`` (length / time²); ``0`` for none.
/// contact_distance
///     The sum of the two balls' radii (``> 0``). ``radius=`` is its former name,
///     deprecated (a ``DeprecationWarning``).
/// t_max
///     Horizon: a collision at ``t ≥ t_max`` is reported as ``inf``.
///
/// A number is anything ``float()`` accepts (an int, a ``Fraction``, a numpy scalar …) but
/// a bool.
///
/// Returns
/// -------
/// float
///     The first time ``t ≥ 0`` at which the centres are ``contact_distance`` apart and
///     closing in (``0.0`` if they already touch or overlap and approach each other), else
///     ``inf``.
///     It is exactly the value :func:`collision_times` gives for the same pair.
///
/// Raises
/// ------
/// InputError
///     A ``ValueError``: a NaN or infinite number, a negative friction, a
///     ``contact_distance ≤ 0``, a negative or NaN ``t_max``, or a vector that is not two
///     numbers; the message names the argument (``.index`` is ``None``).
/// TypeError
///     An argument that is not made of real numbers.
///
/// Examples
/// --------
/// >>> import ballcollide as bc
/// >>> # A cue ball at 2 m/s, slowed at 0.2 m/s², towards a resting ball 1 m away.
/// >>> t = bc.collision_time([0, 0], [2, 0], 0.2, [1, 0], [0, 0], 0.2, 0.05715)
/// >>> round(t, 6)
/// 0.483094
/// >>> bc.collision_time([0, 0], [2, 0], 0.2, [1, 0.1], [0, 0], 0.2, 0.05715)  # misses
/// inf
#[pyfunction]
#[pyo3(
    signature = (
        pos_a, vel_a, friction_a, pos_b, vel_b, friction_b, contact_distance=Given(None),
        *, t_max=Given(None), radius=Given(None)
    ),
    text_signature = "(pos_a, vel_a, friction_a, pos_b, vel_b, friction_b, contact_distance, \
                      *, t_max=1e999)"
)]
#[allow(clippy::too_many_arguments)]
fn collision_time(
    py: Python<'_>,
    pos_a: &Bound<'_, PyAny>,
    vel_a: &Bound<'_, PyAny>,
    friction_a: &Bound<'_, PyAny>,
    pos_b: &Bound<'_, PyAny>,
    vel_b: &Bound<'_, PyAny>,
    friction_b: &Bound<'_, PyAny>,
    contact_distance: Given<'_>,
    t_max: Given<'_>,
    radius: Given<'_>,
) -> PyResult<f64> {
    let contact_distance = read::contact_distance(py, contact_distance, radius)?;
    let pairs = Pairs {
        pos_a: &[point("pos_a", pos_a)?],
        vel_a: &[point("vel_a", vel_a)?],
        friction_a: PerPair::All(number("friction_a", friction_a)?),
        pos_b: &[point("pos_b", pos_b)?],
        vel_b: &[point("vel_b", vel_b)?],
        friction_b: PerPair::All(number("friction_b", friction_b)?),
        contact_distance: PerPair::All(number("contact_distance", &contact_distance)?),
        t_max: PerPair::All(t_max.number_or("t_max", f64::INFINITY)?),
    };
    let mut out = [0.0];
    batch::collision_times(&pairs, &mut out, Threads::AtMost(NonZeroUsize::MIN))
        // A single query: the message names the argument, not an index.
        .map_err(|e| from_core(py, crate::InputError::new(e.argument(), e.kind())))?;
    Ok(out[0])
}

/// The centres of N balls at time ``t``; a ball that has stopped stays where it stopped.
///
/// Ball ``i`` starts at ``pos[i]`` with velocity ``vel[i]`` and decelerates at
/// ``friction`` until it stops at ``τ = |v|/μ``; its centre at ``0 ≤ t ≤ τ`` is
/// ``p + v·t·(1 − t/(2τ))`` and ``p + v·τ/2`` afterwards. Negative times count as ``0``.
///
/// Parameters
/// ----------
/// pos, vel
///     Shape ``(N, 2)``, as in :func:`collision_times`.
/// friction, t
///     Numbers or shape ``(N,)``: friction decelerations (``≥ 0``) and times (finite).
/// num_threads
///     As in :func:`collision_times`.
/// out
///     As in :func:`collision_times`, of shape ``(N, 2)``.
///
/// Returns
/// -------
/// numpy.ndarray
///     Shape ``(N, 2)``, float64 (``out`` itself if given).
///
/// Raises
/// ------
/// InputError, TypeError
///     As :func:`collision_times`, e.g. ``t[1]: must be finite, got inf``.
///
/// Examples
/// --------
/// >>> import ballcollide as bc
/// >>> # 2 m/s slowed at 0.5 m/s²: it stops after 4 s, 4 m further on, and stays.
/// >>> bc.positions_at([[0, 0], [0, 0]], [[2, 0], [2, 0]], 0.5, [2.0, 10.0])
/// array([[3., 0.],
///        [4., 0.]])
#[pyfunction]
#[pyo3(signature = (pos, vel, friction, t, *, num_threads=None, out=None))]
fn positions_at<'py>(
    py: Python<'py>,
    pos: &Bound<'py, PyAny>,
    vel: &Bound<'py, PyAny>,
    friction: &Bound<'py, PyAny>,
    t: &Bound<'py, PyAny>,
    num_threads: Option<&Bound<'py, PyAny>>,
    out: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let pos = rows("pos", pos)?;
    let vel = rows("vel", vel)?;
    let friction = param("friction", friction)?;
    let t = param("t", t)?;
    let threads = threads(num_threads)?;
    let (pos_rows, vel_rows) = (pos.rows(), vel.rows());
    let (per_ball, times) = (friction.per_pair(), t.per_pair());
    let n = pos_rows.len();
    batch::check_ball_arrays(pos_rows, vel_rows, per_ball, times, n)
        .map_err(|e| from_core(py, e))?;
    let inputs = [Some(&pos), Some(&vel), friction.each(), t.each()];
    let expected = "a 2-D float64 array of shape (N, 2)";
    output::<Ix2>(py, n, out, [n, 2], expected, &inputs, |flat| {
        let centres = flat.as_chunks_mut::<2>().0;
        run(py, Kernel::for_items(n, INLINE_UP_TO), || {
            batch::positions_at(pos_rows, vel_rows, per_ball, times, centres, threads)
        })
    })
}

/// The real roots of N polynomials of degree ``k`` (1 to 4), sorted, NaN-padded.
///
/// Parameters
/// ----------
/// coeffs
///     Shape ``(N, k+1)``, highest degree first like ``numpy.roots``: row ``i`` is
///     ``c[i,0]·x^k + … + c[i,k]``. A 1-D array of ``k+1`` coefficients is one polynomial.
///     A zero leading coefficient lowers the degree (the row just has fewer roots).
///
/// Returns
/// -------
/// numpy.ndarray
///     Shape ``(N, k)`` (``(k,)`` for 1-D input), float64: each row's real roots in
///     ascending order, a multiple root repeated, then NaN for the missing ones. A constant
///     row (no isolated root) is all NaN.
///
/// Raises
/// ------
/// InputError
///     A ``ValueError``: a NaN or infinite coefficient (named as ``coeffs[i]``, ``i`` the
///     row), or a shape other than ``(N, 2..5)`` or ``(2..5,)``.
/// TypeError
///     Coefficients that are not real numbers.
///
/// Examples
/// --------
/// >>> import ballcollide as bc
/// >>> bc.real_roots([[1, -3, 2], [1, -2, 1], [1, 0, 1]])  # (x−1)(x−2), (x−1)², x²+1
/// array([[ 1.,  2.],
///        [ 1.,  1.],
///        [nan, nan]])
/// >>> bc.real_roots([1, -10, 35, -50, 24])  # (x−1)(x−2)(x−3)(x−4)
/// array([1., 2., 3., 4.])
#[pyfunction]
fn real_roots<'py>(py: Python<'py>, coeffs: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    let (data, shape) = read::coefficients("coeffs", coeffs)?;
    let flat = data.values();
    let (n, cols) = match *shape.as_slice() {
        [cols] => (1, cols),
        [n, cols] => (n, cols),
        _ => (0, 0),
    };
    if !(2..=5).contains(&cols) {
        let reason = format!(
            "expected shape (N, k+1) with degree k = 1..4, got {}",
            read::shape_text(&shape)
        );
        return Err(input_error(py, "coeffs", None, kind::SHAPE, &reason));
    }
    if let Some(i) = flat.iter().position(|x| !x.is_finite()) {
        let err = crate::InputError::new("coeffs", InputErrorKind::NotFinite(flat[i])).at(i / cols);
        return Err(from_core(py, err));
    }
    let k = cols - 1;
    let _borrowed = match n > INLINE_UP_TO {
        true => read::track(&[Some(&data)])?,
        false => Vec::new(),
    };
    let mut out = vec![f64::NAN; n * k];
    let solve = |roots_out: &mut [f64], c: &[f64]| {
        let roots = poly::real_roots(c);
        roots_out[..roots.len()].copy_from_slice(&roots);
    };
    let how = Kernel::for_items(n, INLINE_UP_TO);
    if how == Kernel::Inline {
        out.chunks_mut(k)
            .zip(flat.chunks(cols))
            .for_each(|(r, c)| solve(r, c));
    } else {
        run(py, how, || {
            // Chunks of INLINE_UP_TO polynomials, each looking at the caller's flag first.
            let interrupt = crate::interrupt::Interrupt::current();
            out.par_chunks_mut(k * INLINE_UP_TO)
                .zip(flat.par_chunks(cols * INLINE_UP_TO))
                .try_for_each(|(roots, coefficients)| {
                    interrupt.check()?;
                    roots
                        .chunks_mut(k)
                        .zip(coefficients.chunks(cols))
                        .for_each(|(r, c)| solve(r, c));
                    Ok(())
                })
        })?;
    }
    let roots = PyArray1::from_vec(py, out);
    Ok(match shape.len() {
        1 => roots.into_any(),
        _ => roots.reshape(Dim([n, k]))?.into_any(),
    })
}

/// The balls, per-ball radii and options of a scene query, validated by the core.
struct Scene {
    balls: Vec<crate::motion::Ball>,
    radii: Vec<f64>,
    options: SceneOptions,
}

/// Reads a scene's arguments and builds its balls; `radius` may be one number for all balls.
fn scene_input(
    py: Python<'_>,
    pos: &Bound<'_, PyAny>,
    vel: &Bound<'_, PyAny>,
    friction: &Bound<'_, PyAny>,
    radius: &Bound<'_, PyAny>,
    t_max: Given<'_>,
    num_threads: Option<&Bound<'_, PyAny>>,
) -> PyResult<Scene> {
    let pos = rows("pos", pos)?;
    let vel = rows("vel", vel)?;
    let friction = param("friction", friction)?;
    let radius = param("radius", radius)?;
    let t_max = t_max.number_or("t_max", f64::INFINITY)?;
    let threads = threads(num_threads)?;
    let balls =
        scene::balls(pos.rows(), vel.rows(), friction.per_pair()).map_err(|e| from_core(py, e))?;
    let radii = match radius.per_pair() {
        PerPair::All(r) => vec![r; balls.len()],
        PerPair::Each(r) => r.to_vec(),
    };
    Ok(Scene {
        balls,
        radii,
        options: SceneOptions {
            t_max,
            threads,
            ..SceneOptions::default()
        },
    })
}

/// The collision time of every pair of N balls, as an ``(N, N)`` matrix.
///
/// Entry ``[i, j]`` is the time at which balls ``i`` and ``j`` first touch (what
/// :func:`collision_time` gives for ball ``i`` as A, ball ``j`` as B and the sum of their
/// radii, for ``i < j``; the matrix is symmetric), ``inf`` if they never do (or not before
/// ``t_max``), and ``inf`` on the diagonal. Only pairs whose swept bounding boxes overlap
/// are computed (the others cannot touch); the answer is the all-pairs answer, bit for bit.
///
/// Parameters
/// ----------
/// pos, vel
///     Shape ``(N, 2)``: each ball's centre and velocity at time 0 (any array-like, as in
///     :func:`collision_times`).
/// friction
///     A number or shape ``(N,)``: each ball's friction deceleration ``μ ≥ 0``.
/// radius
///     A number or shape ``(N,)``: each ball's radius (``> 0``). A pair touches when its
///     centres are the *sum* of its two radii apart.
/// t_max
///     Horizon: a collision at ``t ≥ t_max`` is reported as ``inf``.
/// num_threads
///     ``None``: all cores; an int ``≥ 1``: at most that many. The result does not depend
///     on it. Scenes of fewer than 64 balls run on the calling thread; the GIL is released
///     for more than 16.
///
/// Returns
/// -------
/// numpy.ndarray
///     Shape ``(N, N)``, float64 (``N²`` numbers: for large N prefer
///     :func:`earliest_collision` or :func:`first_contacts`).
///
/// Raises
/// ------
/// InputError
///     A ``ValueError``: a NaN or infinite number, a negative friction, a radius ``≤ 0``, a
///     negative ``t_max``, a wrong shape or length; the message names the argument and the
///     first bad index, e.g. ``radius[3]: ...``.
/// TypeError
///     An argument that is not made of real numbers.
/// MemoryError
///     An ``(N, N)`` matrix too large to allocate (checked before any work is done).
///
/// Examples
/// --------
/// >>> import ballcollide as bc
/// >>> # A ball at 1 m/s (no friction) towards a resting ball 1 m away; radii 0.2 and 0.3.
/// >>> bc.pairwise_collision_times([[0, 0], [1, 0]], [[1, 0], [0, 0]], 0.0, [0.2, 0.3])
/// array([[inf, 0.5],
///        [0.5, inf]])
#[pyfunction]
#[pyo3(
    signature = (pos, vel, friction, radius, *, t_max=Given(None), num_threads=None),
    text_signature = "(pos, vel, friction, radius, *, t_max=1e999, num_threads=None)"
)]
fn pairwise_collision_times<'py>(
    py: Python<'py>,
    pos: &Bound<'py, PyAny>,
    vel: &Bound<'py, PyAny>,
    friction: &Bound<'py, PyAny>,
    radius: &Bound<'py, PyAny>,
    t_max: Given<'py>,
    num_threads: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let s = scene_input(py, pos, vel, friction, radius, t_max, num_threads)?;
    let n = s.balls.len();
    // N² numbers: a matrix that cannot be allocated is a MemoryError, not an abort.
    let fits = n
        .checked_mul(n)
        .is_some_and(|cells| Vec::<f64>::new().try_reserve_exact(cells).is_ok());
    if !fits {
        return Err(PyMemoryError::new_err(format!(
            "pairwise_collision_times: an ({n}, {n}) matrix does not fit in memory; \
             earliest_collision and first_contacts need only O(N)"
        )));
    }
    let times = run(py, scene_kernel(n), || {
        scene::pairwise_collision_times(&s.balls, &s.radii, &s.options)
    })?;
    PyArray1::from_vec(py, times).reshape(Dim([n, n]))
}

/// The first collision among N balls: ``(t, i, j)`` with ``i < j``.
///
/// ``(inf, -1, -1)`` if no two balls touch before ``t_max``. Of pairs colliding at the same
/// time, the lowest ``i`` wins, then the lowest ``j``. This is the question an event-driven
/// simulator asks after every event; only the pairs whose swept bounding boxes overlap are
/// computed, and the answer equals the all-pairs answer exactly.
///
/// Parameters
/// ----------
/// pos, vel, friction, radius, t_max, num_threads
///     As in :func:`pairwise_collision_times`.
///
/// Raises
/// ------
/// InputError, TypeError
///     As :func:`pairwise_collision_times`.
///
/// Examples
/// --------
/// >>> import ballcollide as bc
/// >>> pos = [[0, 0], [5, 5], [1, 0]]
/// >>> vel = [[1, 0], [0, 0], [-1, 0]]
/// >>> t, i, j = bc.earliest_collision(pos, vel, 0.5, 0.05)
/// >>> (round(t, 6), i, j)
/// (0.51676, 0, 2)
/// >>> bc.earliest_collision(pos, vel, 0.5, 0.05, t_max=0.1)
/// (inf, -1, -1)
#[pyfunction]
#[pyo3(
    signature = (pos, vel, friction, radius, *, t_max=Given(None), num_threads=None),
    text_signature = "(pos, vel, friction, radius, *, t_max=1e999, num_threads=None)"
)]
fn earliest_collision(
    py: Python<'_>,
    pos: &Bound<'_, PyAny>,
    vel: &Bound<'_, PyAny>,
    friction: &Bound<'_, PyAny>,
    radius: &Bound<'_, PyAny>,
    t_max: Given<'_>,
    num_threads: Option<&Bound<'_, PyAny>>,
) -> PyResult<(f64, i64, i64)> {
    let s = scene_input(py, pos, vel, friction, radius, t_max, num_threads)?;
    let found = run(py, scene_kernel(s.balls.len()), || {
        scene::earliest_collision(&s.balls, &s.radii, &s.options)
    })?;
    Ok(found.map_or((f64::INFINITY, -1, -1), |(t, i, j)| {
        (t, index_i64(i), index_i64(j))
    }))
}

/// Each ball's first collision: ``(times, partner)``, both of shape ``(N,)``.
///
/// Ball ``i`` first touches ball ``partner[i]`` at ``times[i]``, ignoring every other
/// collision (each is the earliest entry of row ``i`` of :func:`pairwise_collision_times`);
/// ``inf`` and ``-1`` if it touches none before ``t_max``. Of partners at the same time, the
/// lowest index wins.
///
/// Parameters
/// ----------
/// pos, vel, friction, radius, t_max, num_threads
///     As in :func:`pairwise_collision_times`.
///
/// Returns
/// -------
/// tuple of numpy.ndarray
///     ``times`` (float64) and ``partner`` (int64, ``-1`` for none).
///
/// Raises
/// ------
/// InputError, TypeError
///     As :func:`pairwise_collision_times`.
///
/// Examples
/// --------
/// >>> import ballcollide as bc
/// >>> times, partner = bc.first_contacts([[0, 0], [0, 2], [9, 9]], [[0, 1], [0, 0], [0, 0]],
/// ...                                    0.0, 0.5)
/// >>> times, partner
/// (array([ 1.,  1., inf]), array([ 1,  0, -1]))
#[pyfunction]
#[pyo3(
    signature = (pos, vel, friction, radius, *, t_max=Given(None), num_threads=None),
    text_signature = "(pos, vel, friction, radius, *, t_max=1e999, num_threads=None)"
)]
#[allow(clippy::type_complexity)]
fn first_contacts<'py>(
    py: Python<'py>,
    pos: &Bound<'py, PyAny>,
    vel: &Bound<'py, PyAny>,
    friction: &Bound<'py, PyAny>,
    radius: &Bound<'py, PyAny>,
    t_max: Given<'py>,
    num_threads: Option<&Bound<'py, PyAny>>,
) -> PyResult<(Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<i64>>)> {
    let s = scene_input(py, pos, vel, friction, radius, t_max, num_threads)?;
    let (times, partners) = run(py, scene_kernel(s.balls.len()), || {
        scene::first_contacts(&s.balls, &s.radii, &s.options)
    })?;
    let partners: Vec<i64> = partners
        .into_iter()
        .map(|p| p.map_or(-1, index_i64))
        .collect();
    Ok((
        PyArray1::from_vec(py, times),
        PyArray1::from_vec(py, partners),
    ))
}

/// An array index as Python's int64 (indices of in-memory arrays always fit).
fn index_i64(i: usize) -> i64 {
    i64::try_from(i).unwrap_or(i64::MAX)
}

/// ballcollide's compiled core: collision times of balls slowing under friction and of balls
/// on paths of constant-acceleration segments, their contacts with static geometry, and real
/// roots of polynomials of degree ≤ 4. The ``ballcollide`` package re-exports it.
#[pymodule(name = "_core")]
fn core_module(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    // numpy's C API loaded now, at import, rather than at a call's first array (rust-numpy
    // loads it lazily, running Python code, and panics if that raises): a Ctrl-C during a
    // long call's checks, before its first array, came out as a PanicException from there.
    numpy::PyArray1::<f64>::zeros(py, 0, false);
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("InputError", py.get_type::<InputError>())?;
    // An attribute, not an export: a hook for the benchmarks, out of `__all__`.
    m.setattr(
        "_last_kernel_seconds",
        wrap_pyfunction!(_last_kernel_seconds, m)?,
    )?;
    // ballcollide.pooltool's reader and builder of pooltool objects: attributes, not
    // exports.
    m.setattr(
        "_pooltool_inputs",
        wrap_pyfunction!(pooltool_inputs::pooltool_inputs, m)?,
    )?;
    m.setattr(
        "_PooltoolBuilder",
        py.get_type::<pooltool_system::PooltoolBuilder>(),
    )?;
    let public = [
        wrap_pyfunction!(collision_time, m)?,
        wrap_pyfunction!(collision_times, m)?,
        wrap_pyfunction!(positions_at, m)?,
        wrap_pyfunction!(paths::path_collision_times, m)?,
        wrap_pyfunction!(paths::path_collision_time, m)?,
        wrap_pyfunction!(paths::path_positions_at, m)?,
        wrap_pyfunction!(geometry::path_geometry_times, m)?,
        wrap_pyfunction!(geometry::pool_table, m)?,
        wrap_pyfunction!(real_roots, m)?,
        wrap_pyfunction!(pairwise_collision_times, m)?,
        wrap_pyfunction!(earliest_collision, m)?,
        wrap_pyfunction!(first_contacts, m)?,
        wrap_pyfunction!(schedule::simulate, m)?,
        wrap_pyfunction!(shots::simulate_shots, m)?,
        wrap_pyfunction!(simd_level, m)?,
    ];
    m.add_class::<schedule::CollisionSchedule>()?;
    m.add("Event", schedule::event_type(py)?)?;
    m.add("Simulation", schedule::simulation_type(py)?)?;
    schedule::add_kinds(m)?;
    for f in public {
        // Their public home, as numpy's functions are `numpy`'s: reprs, pickles and doctest
        // find them there.
        f.setattr("__module__", "ballcollide")?;
        m.add_function(f)?;
    }
    Ok(())
}
