//! The Python extension module `ballcollide._core` (feature `python`).
//!
//! A thin layer: it checks that arrays have the layout the Rust core reads without copying
//! (C-contiguous float64, the right shapes), releases the GIL, and calls [`crate::batch`],
//! [`crate::scene`] and [`crate::poly`]. Everything else — validation of values, the search itself — is the core's,
//! so Python and Rust give identical answers and identical error messages.
//!
//! The friendly entry points, which accept lists, any real dtype, Fortran order and strided
//! views, are in `python/ballcollide/__init__.py`; they normalise with
//! `np.ascontiguousarray(x, dtype=np.float64)` and call these functions.
//!
//! Errors: an [`InputError`] becomes `ValueError` with its message (argument name and index);
//! a wrong layout or shape is a `ValueError` naming the argument; a wrong type or dtype is a
//! `TypeError` naming it too. Nothing here panics on any input.

use std::cell::Cell;
use std::num::NonZeroUsize;
use std::sync::OnceLock;
use std::time::Instant;

use numpy::ndarray::{Dim, Dimension, Ix1, Ix2};
use numpy::{BorrowError, PyArray, PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray};
use numpy::{PyReadonlyArray1, PyReadonlyArray2, PyReadwriteArray};
use numpy::{PyUntypedArray, PyUntypedArrayMethods};
use pyo3::exceptions::{PyMemoryError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use rayon::prelude::*;

use crate::batch::{self, Pairs, PerPair, Threads};
use crate::error::{InputError, InputErrorKind};
use crate::poly;
use crate::scene::{self, SceneOptions};

/// A scalar parameter from Python: one float for all pairs, or a float64 array of one per pair.
enum Param<'py> {
    Each(PyReadonlyArray1<'py, f64>),
    All(f64),
}

impl<'py> Param<'py> {
    /// A float (or anything with `__float__`, such as a 0-d array), or a 1-D float64 array.
    fn extract(name: &str, obj: &Bound<'py, PyAny>) -> PyResult<Self> {
        match obj.cast::<PyUntypedArray>() {
            Ok(a) if a.ndim() > 0 => array(name, obj, PER_PAIR).map(Self::Each),
            _ => obj
                .extract::<f64>()
                .map(Self::All)
                .map_err(|_| type_error(name, PER_PAIR, obj)),
        }
    }

    fn per_pair(&self, name: &str) -> PyResult<PerPair<'_>> {
        match self {
            Self::All(x) => Ok(PerPair::All(*x)),
            Self::Each(a) => a
                .as_slice()
                .map(PerPair::Each)
                .map_err(|_| layout_error(name)),
        }
    }
}

const PER_PAIR: &str = "a float or a 1-D float64 array";
const ROWS: &str = "a 2-D float64 array of shape (N, 2)";

/// `obj` as a float64 numpy array of dimension `D`, borrowed read-only; a `TypeError` naming
/// the argument otherwise.
fn array<'py, D: Dimension>(
    name: &str,
    obj: &Bound<'py, PyAny>,
    expected: &str,
) -> PyResult<PyReadonlyArray<'py, f64, D>> {
    obj.extract::<PyReadonlyArray<'py, f64, D>>()
        .map_err(|_| type_error(name, expected, obj))
}

fn type_error(name: &str, expected: &str, obj: &Bound<'_, PyAny>) -> PyErr {
    let found = match obj.cast::<PyUntypedArray>() {
        Ok(a) => format!("a {}-D array of dtype {}", a.ndim(), a.dtype()),
        Err(_) => obj
            .get_type()
            .name()
            .map_or_else(|_| "another type".to_owned(), |n| n.to_string()),
    };
    PyTypeError::new_err(format!("{name}: expected {expected}, got {found}"))
}

fn layout_error(name: &str) -> PyErr {
    PyValueError::new_err(format!(
        "{name}: expected a C-contiguous, aligned float64 array \
         (the ballcollide functions convert any array-like)"
    ))
}

fn value_error(e: InputError) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// The rows of an `(N, 2)` C-contiguous float64 array, without copying.
fn rows<'a>(name: &str, a: &'a PyReadonlyArray2<'_, f64>) -> PyResult<&'a [[f64; 2]]> {
    let shape = a.shape();
    if shape[1] != 2 {
        return Err(PyValueError::new_err(format!(
            "{name}: expected shape (N, 2), got ({}, {})",
            shape[0], shape[1]
        )));
    }
    // A Fortran-ordered array is contiguous too, and `as_slice` would read it column by
    // column: only C order gives rows.
    if !a.is_c_contiguous() {
        return Err(layout_error(name));
    }
    let flat = a.as_slice().map_err(|_| layout_error(name))?;
    Ok(flat.as_chunks::<2>().0)
}

/// A caller's output array (`out=`), borrowed for writing: a float64 array of dimension `D`
/// (else a `TypeError`), of shape `shape`, C-contiguous, writeable and sharing no memory with
/// the inputs, which are borrowed read-only while it is written (else a `ValueError`; numpy's
/// borrow tracking in rust-numpy detects the overlap).
///
/// Its shape is checked here, before the core sees it (and after the inputs' lengths): the
/// core measures every input against the output's length, and would blame the first input
/// for an output of the wrong length.
fn out_array<'py, D: Dimension>(
    obj: &Bound<'py, PyAny>,
    shape: &[usize],
    expected: &str,
) -> PyResult<PyReadwriteArray<'py, f64, D>> {
    let array = obj
        .cast::<PyArray<f64, D>>()
        .map_err(|_| type_error("out", expected, obj))?;
    if array.shape() != shape {
        return Err(PyValueError::new_err(format!(
            "out: expected shape {}, got {}",
            shape_text(shape),
            shape_text(array.shape())
        )));
    }
    if !array.is_c_contiguous() {
        return Err(layout_error("out"));
    }
    array.try_readwrite().map_err(|e| {
        PyValueError::new_err(match e {
            BorrowError::NotWriteable => "out: the array is read-only",
            _ => "out: the array shares memory with an input",
        })
    })
}

/// A shape as numpy prints it: `(3,)`, `(3, 2)`.
fn shape_text(shape: &[usize]) -> String {
    match shape {
        [n] => format!("({n},)"),
        _ => {
            let dims: Vec<String> = shape.iter().map(usize::to_string).collect();
            format!("({})", dims.join(", "))
        }
    }
}

/// `num_threads`: `None` → every core; `n ≥ 1` → at most `n` (and at most the cores there are,
/// so that a huge `n` cannot start thousands of threads).
fn threads(num_threads: Option<i64>) -> PyResult<Threads> {
    match num_threads {
        None => Ok(Threads::All),
        Some(n) if n >= 1 => {
            let n = usize::try_from(n).unwrap_or(usize::MAX).min(cores());
            Ok(NonZeroUsize::new(n).map_or(Threads::All, Threads::AtMost))
        }
        Some(n) => Err(PyValueError::new_err(format!(
            "num_threads: must be None (all cores) or ≥ 1, got {n}"
        ))),
    }
}

/// The cores this process may use, read once: `available_parallelism` reads the cgroup quota
/// and the affinity mask on every call (~25 µs on Linux), more than a call on a few hundred
/// pairs costs in all.
fn cores() -> usize {
    static CORES: OnceLock<usize> = OnceLock::new();
    *CORES.get_or_init(|| std::thread::available_parallelism().map_or(1, NonZeroUsize::get))
}

/// Collision times of N pairs (see `ballcollide.collision_times`); arrays must be
/// C-contiguous float64.
#[pyfunction]
#[pyo3(signature = (pos_a, vel_a, friction_a, pos_b, vel_b, friction_b, radius, t_max=None, num_threads=None, out=None))]
#[allow(clippy::too_many_arguments)]
fn collision_times<'py>(
    py: Python<'py>,
    pos_a: &Bound<'py, PyAny>,
    vel_a: &Bound<'py, PyAny>,
    friction_a: &Bound<'py, PyAny>,
    pos_b: &Bound<'py, PyAny>,
    vel_b: &Bound<'py, PyAny>,
    friction_b: &Bound<'py, PyAny>,
    radius: &Bound<'py, PyAny>,
    t_max: Option<&Bound<'py, PyAny>>,
    num_threads: Option<i64>,
    out: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let pos_a = array::<Ix2>("pos_a", pos_a, ROWS)?;
    let vel_a = array::<Ix2>("vel_a", vel_a, ROWS)?;
    let friction_a = Param::extract("friction_a", friction_a)?;
    let pos_b = array::<Ix2>("pos_b", pos_b, ROWS)?;
    let vel_b = array::<Ix2>("vel_b", vel_b, ROWS)?;
    let friction_b = Param::extract("friction_b", friction_b)?;
    let radius = Param::extract("radius", radius)?;
    let t_max = match t_max {
        Some(t) => Param::extract("t_max", t)?,
        None => Param::All(f64::INFINITY),
    };
    let pairs = Pairs {
        pos_a: rows("pos_a", &pos_a)?,
        vel_a: rows("vel_a", &vel_a)?,
        friction_a: friction_a.per_pair("friction_a")?,
        pos_b: rows("pos_b", &pos_b)?,
        vel_b: rows("vel_b", &vel_b)?,
        friction_b: friction_b.per_pair("friction_b")?,
        radius: radius.per_pair("radius")?,
        t_max: t_max.per_pair("t_max")?,
    };
    let threads = threads(num_threads)?;
    let n = pairs.pos_a.len();
    let Some(out) = out else {
        let mut out = vec![0.0; n];
        timed_kernel(py, || batch::collision_times(&pairs, &mut out, threads))?;
        return Ok(PyArray1::from_vec(py, out));
    };
    // The inputs' own errors first, as without `out`.
    batch::check_lengths(&pairs, n).map_err(value_error)?;
    let mut written = out_array::<Ix1>(out, &[n], OUT_TIMES)?;
    let out = written.as_slice_mut().map_err(|_| layout_error("out"))?;
    timed_kernel(py, || batch::collision_times(&pairs, out, threads))?;
    Ok((**written).clone())
}

thread_local! {
    /// How long the Rust kernel ran in this thread's last `collision_times` call, in seconds.
    static LAST_KERNEL_SECONDS: Cell<f64> = const { Cell::new(f64::NAN) };
}

/// Runs `kernel` without the GIL, and records how long it ran ([`_last_kernel_seconds`]).
fn timed_kernel(
    py: Python<'_>,
    kernel: impl Send + FnOnce() -> Result<(), InputError>,
) -> PyResult<()> {
    let (result, seconds) = py.detach(|| {
        let start = Instant::now();
        let result = kernel();
        (result, start.elapsed().as_secs_f64())
    });
    LAST_KERNEL_SECONDS.with(|last| last.set(seconds));
    result.map_err(value_error)
}

/// Seconds the Rust kernel took inside this thread's last `collision_times` call (NaN before
/// any): what `benchmarks/compare.py` subtracts from the call's own time to measure what the
/// binding adds, in the same call (separate runs on these shared cores differ by more than
/// that). Private: for benchmarks.
#[pyfunction]
fn _last_kernel_seconds() -> f64 {
    LAST_KERNEL_SECONDS.with(Cell::get)
}

const OUT_TIMES: &str = "a 1-D float64 array of shape (N,)";

/// The collision time of one pair (`inf` if none); the same search as one row of
/// `collision_times`, without an index in error messages.
#[pyfunction]
#[pyo3(signature = (pos_a, vel_a, friction_a, pos_b, vel_b, friction_b, radius, t_max=f64::INFINITY))]
#[allow(clippy::too_many_arguments)]
fn collision_time(
    pos_a: [f64; 2],
    vel_a: [f64; 2],
    friction_a: f64,
    pos_b: [f64; 2],
    vel_b: [f64; 2],
    friction_b: f64,
    radius: f64,
    t_max: f64,
) -> PyResult<f64> {
    let pairs = Pairs {
        pos_a: &[pos_a],
        vel_a: &[vel_a],
        friction_a: PerPair::All(friction_a),
        pos_b: &[pos_b],
        vel_b: &[vel_b],
        friction_b: PerPair::All(friction_b),
        radius: PerPair::All(radius),
        t_max: PerPair::All(t_max),
    };
    let mut out = [0.0];
    batch::collision_times(&pairs, &mut out, Threads::AtMost(NonZeroUsize::MIN))
        // A single query: the message names the argument, not an index.
        .map_err(|e| value_error(InputError::new(e.argument(), e.kind())))?;
    Ok(out[0])
}

/// Centres of N balls at time `t` (see `ballcollide.positions_at`).
#[pyfunction]
#[pyo3(signature = (pos, vel, friction, t, num_threads=None, out=None))]
fn positions_at<'py>(
    py: Python<'py>,
    pos: &Bound<'py, PyAny>,
    vel: &Bound<'py, PyAny>,
    friction: &Bound<'py, PyAny>,
    t: &Bound<'py, PyAny>,
    num_threads: Option<i64>,
    out: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let pos = array::<Ix2>("pos", pos, ROWS)?;
    let vel = array::<Ix2>("vel", vel, ROWS)?;
    let friction = Param::extract("friction", friction)?;
    let t = Param::extract("t", t)?;
    let pos = rows("pos", &pos)?;
    let vel = rows("vel", &vel)?;
    let friction = friction.per_pair("friction")?;
    let t = t.per_pair("t")?;
    let threads = threads(num_threads)?;
    let n = pos.len();
    let Some(out) = out else {
        let mut out = vec![[0.0; 2]; n];
        py.detach(|| batch::positions_at(pos, vel, friction, t, &mut out, threads))
            .map_err(value_error)?;
        return PyArray1::from_vec(py, out.into_flattened()).reshape(Dim([n, 2]));
    };
    batch::check_ball_arrays(pos, vel, friction, t, n).map_err(value_error)?;
    let mut written = out_array::<Ix2>(out, &[n, 2], ROWS)?;
    let flat = written.as_slice_mut().map_err(|_| layout_error("out"))?;
    let out = flat.as_chunks_mut::<2>().0;
    py.detach(|| batch::positions_at(pos, vel, friction, t, out, threads))
        .map_err(value_error)?;
    Ok((**written).clone())
}

/// Real roots of N polynomials of degree k = 1..4, coefficients `(N, k+1)` highest degree
/// first; `(N, k)` roots ascending with multiplicity, NaN-padded.
#[pyfunction]
fn real_roots<'py>(
    py: Python<'py>,
    coeffs: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let coeffs = array::<Ix2>("coeffs", coeffs, "a 2-D float64 array of shape (N, k+1)")?;
    let [n, cols] = [coeffs.shape()[0], coeffs.shape()[1]];
    if !(2..=5).contains(&cols) {
        return Err(PyValueError::new_err(format!(
            "coeffs: expected shape (N, k+1) with degree k = 1..4, got ({n}, {cols})"
        )));
    }
    if !coeffs.is_c_contiguous() {
        return Err(layout_error("coeffs"));
    }
    let flat = coeffs.as_slice().map_err(|_| layout_error("coeffs"))?;
    if let Some(i) = flat.iter().position(|x| !x.is_finite()) {
        let err = InputError::new("coeffs", InputErrorKind::NotFinite(flat[i])).at(i / cols);
        return Err(value_error(err));
    }
    let k = cols - 1;
    let mut out = vec![f64::NAN; n * k];
    py.detach(|| {
        out.par_chunks_mut(k)
            .zip(flat.par_chunks(cols))
            .with_min_len(1024)
            .for_each(|(roots_out, c)| {
                let roots = poly::real_roots(c);
                roots_out[..roots.len()].copy_from_slice(&roots);
            });
    });
    PyArray1::from_vec(py, out).reshape(Dim([n, k]))
}

/// The balls, per-ball radii and options of a scene query, validated by the core.
struct Scene {
    balls: Vec<crate::motion::Ball>,
    radii: Vec<f64>,
    options: SceneOptions,
}

/// Reads a scene's arrays (C-contiguous float64) and builds its balls; `radius` may be one
/// float for all balls.
fn scene_input(
    pos: &Bound<'_, PyAny>,
    vel: &Bound<'_, PyAny>,
    friction: &Bound<'_, PyAny>,
    radius: &Bound<'_, PyAny>,
    t_max: f64,
    num_threads: Option<i64>,
) -> PyResult<Scene> {
    let pos = array::<Ix2>("pos", pos, ROWS)?;
    let vel = array::<Ix2>("vel", vel, ROWS)?;
    let friction = Param::extract("friction", friction)?;
    let radius = Param::extract("radius", radius)?;
    let pos = rows("pos", &pos)?;
    let vel = rows("vel", &vel)?;
    let balls = scene::balls(pos, vel, friction.per_pair("friction")?).map_err(value_error)?;
    let radii = match radius.per_pair("radius")? {
        PerPair::All(r) => vec![r; balls.len()],
        PerPair::Each(r) => r.to_vec(),
    };
    Ok(Scene {
        balls,
        radii,
        options: SceneOptions {
            t_max,
            threads: threads(num_threads)?,
            ..SceneOptions::default()
        },
    })
}

/// The `(N, N)` matrix of collision times of N balls (see
/// `ballcollide.pairwise_collision_times`).
#[pyfunction]
#[pyo3(signature = (pos, vel, friction, radius, t_max=f64::INFINITY, num_threads=None))]
fn pairwise_collision_times<'py>(
    py: Python<'py>,
    pos: &Bound<'py, PyAny>,
    vel: &Bound<'py, PyAny>,
    friction: &Bound<'py, PyAny>,
    radius: &Bound<'py, PyAny>,
    t_max: f64,
    num_threads: Option<i64>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let s = scene_input(pos, vel, friction, radius, t_max, num_threads)?;
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
    let times = py
        .detach(|| scene::pairwise_collision_times(&s.balls, &s.radii, &s.options))
        .map_err(value_error)?;
    PyArray1::from_vec(py, times).reshape(Dim([n, n]))
}

/// The first collision of N balls, `(t, i, j)` or `(inf, -1, -1)` (see
/// `ballcollide.earliest_collision`).
#[pyfunction]
#[pyo3(signature = (pos, vel, friction, radius, t_max=f64::INFINITY, num_threads=None))]
fn earliest_collision(
    py: Python<'_>,
    pos: &Bound<'_, PyAny>,
    vel: &Bound<'_, PyAny>,
    friction: &Bound<'_, PyAny>,
    radius: &Bound<'_, PyAny>,
    t_max: f64,
    num_threads: Option<i64>,
) -> PyResult<(f64, i64, i64)> {
    let s = scene_input(pos, vel, friction, radius, t_max, num_threads)?;
    let found = py
        .detach(|| scene::earliest_collision(&s.balls, &s.radii, &s.options))
        .map_err(value_error)?;
    Ok(found.map_or((f64::INFINITY, -1, -1), |(t, i, j)| {
        (t, index_i64(i), index_i64(j))
    }))
}

/// Each ball's first collision and partner (see `ballcollide.first_contacts`).
#[pyfunction]
#[pyo3(signature = (pos, vel, friction, radius, t_max=f64::INFINITY, num_threads=None))]
#[allow(clippy::type_complexity)]
fn first_contacts<'py>(
    py: Python<'py>,
    pos: &Bound<'py, PyAny>,
    vel: &Bound<'py, PyAny>,
    friction: &Bound<'py, PyAny>,
    radius: &Bound<'py, PyAny>,
    t_max: f64,
    num_threads: Option<i64>,
) -> PyResult<(Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<i64>>)> {
    let s = scene_input(pos, vel, friction, radius, t_max, num_threads)?;
    let (times, partners) = py
        .detach(|| scene::first_contacts(&s.balls, &s.radii, &s.options))
        .map_err(value_error)?;
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

/// ballcollide's compiled core: collision times of balls slowing under friction, and real
/// roots of polynomials of degree ≤ 4. Use the `ballcollide` package, which converts its
/// inputs and calls these functions.
#[pymodule(name = "_core")]
fn core_module(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_function(wrap_pyfunction!(collision_times, m)?)?;
    m.add_function(wrap_pyfunction!(_last_kernel_seconds, m)?)?;
    m.add_function(wrap_pyfunction!(collision_time, m)?)?;
    m.add_function(wrap_pyfunction!(positions_at, m)?)?;
    m.add_function(wrap_pyfunction!(real_roots, m)?)?;
    m.add_function(wrap_pyfunction!(pairwise_collision_times, m)?)?;
    m.add_function(wrap_pyfunction!(earliest_collision, m)?)?;
    m.add_function(wrap_pyfunction!(first_contacts, m)?)?;
    Ok(())
}
