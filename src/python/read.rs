//! Reading the Python functions' arguments: numbers, rows, per-pair values, `num_threads`,
//! `out`. Each reader accepts what Python and numpy users hand over (lists and tuples,
//! any real dtype, C or Fortran order, strided views, read-only or big-endian arrays, and
//! any number `float()` accepts where a scalar goes) and gives the Rust core float64 data in
//! C order: in place when it already is so, else converted once (rust-numpy's
//! [`PyArrayLike`] with [`AllowTypeChange`]). Booleans are not numbers here.
//!
//! Errors name the argument: `TypeError` for what is not made of real numbers,
//! [`InputError`](super::input_error::InputError) (a `ValueError`) for a wrong shape,
//! layout or value.

use std::num::NonZeroUsize;
use std::sync::OnceLock;

use numpy::PyArrayDescrMethods;
use numpy::ndarray::{Dimension, IxDyn};
use numpy::npyffi::{self, NpyTypes, PY_ARRAY_API};
use numpy::{AllowTypeChange, BorrowError, PyArray, PyArrayLike, PyArrayMethods};
use numpy::{PyReadonlyArray, PyReadwriteArray, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::exceptions::{PyOverflowError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyFloat, PyInt, PyList, PyTuple};

use super::input_error::input_error;
use crate::batch::{PerPair, Threads};

/// float64 values in C order, read in place or converted.
pub(super) enum Floats<'py> {
    /// A C-contiguous, aligned, native float64 array, borrowed (rust-numpy's borrow tracking:
    /// a call writing into it as `out=` meanwhile is refused).
    InPlace(PyReadonlyArray<'py, f64, IxDyn>),
    /// The values gathered or converted into memory of our own.
    Copied(Vec<f64>),
}

impl Floats<'_> {
    /// The values, in C order.
    pub(super) fn values(&self) -> &[f64] {
        match self {
            // Chosen only for a C-contiguous, aligned array, which `as_slice` reads in place.
            Self::InPlace(a) => a.as_slice().unwrap_or(&[]),
            Self::Copied(v) => v,
        }
    }

    /// The values as `(x, y)` rows.
    pub(super) fn rows(&self) -> &[[f64; 2]] {
        self.values().as_chunks::<2>().0
    }
}

/// A scalar parameter: one value for all pairs (balls), or one per pair.
pub(super) enum Param<'py> {
    All(f64),
    Each(Floats<'py>),
}

impl Param<'_> {
    pub(super) fn per_pair(&self) -> PerPair<'_> {
        match self {
            Self::All(x) => PerPair::All(*x),
            Self::Each(values) => PerPair::Each(values.values()),
        }
    }
}

/// An argument with a default, as distinct from one given as `None` (a `TypeError` where a
/// number goes): `Given(None)` when left out.
pub(super) struct Given<'py>(pub(super) Option<Bound<'py, PyAny>>);

impl<'a, 'py> FromPyObject<'a, 'py> for Given<'py> {
    type Error = PyErr;

    fn extract(obj: Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        Ok(Self(Some(obj.to_owned())))
    }
}

impl<'py> Given<'py> {
    /// The number given, or `default`.
    pub(super) fn number_or(&self, name: &str, default: f64) -> PyResult<f64> {
        self.0.as_ref().map_or(Ok(default), |obj| number(name, obj))
    }

    /// The per-pair parameter given, or `default` for all.
    pub(super) fn param_or(&self, name: &str, default: f64) -> PyResult<Param<'py>> {
        self.0
            .as_ref()
            .map_or(Ok(Param::All(default)), |obj| param(name, obj))
    }
}

/// `obj` as a numpy array of real numbers (itself if it is one, else `numpy.asarray(obj)`).
fn real_array<'py>(name: &str, obj: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyUntypedArray>> {
    let py = obj.py();
    let array = match obj.cast::<PyUntypedArray>() {
        Ok(array) => array.clone(),
        Err(_) => {
            // SAFETY: `obj` is a live object; `PyArray_FromAny` returns a new reference or
            // NULL with an exception set, and with no dtype asked for it returns an ndarray.
            let made = unsafe {
                let ptr = PY_ARRAY_API.PyArray_FromAny(
                    py,
                    obj.as_ptr(),
                    std::ptr::null_mut(),
                    0,
                    0,
                    0,
                    std::ptr::null_mut(),
                );
                Bound::from_owned_ptr_or_err(py, ptr)
            };
            // Ragged nested lists, objects numpy cannot read.
            let made = made.map_err(|e| {
                let reason = format!("cannot be read as an array of numbers ({})", e.value(py));
                input_error(py, name, None, &reason)
            })?;
            made.cast_into::<PyUntypedArray>()?
        }
    };
    let dtype = array.dtype();
    if !matches!(dtype.kind(), b'f' | b'i' | b'u') {
        let what = if is_numpy_scalar(obj) {
            "a scalar"
        } else {
            "an array"
        };
        return Err(PyTypeError::new_err(format!(
            "{name}: expected real numbers, got {what} of dtype {dtype}"
        )));
    }
    Ok(array)
}

/// Whether `obj` is a numpy scalar (`np.float32(1)`, `np.bool_(True)` …).
fn is_numpy_scalar(obj: &Bound<'_, PyAny>) -> bool {
    is_numpy_type(obj, NpyTypes::PyGenericArrType_Type)
}

/// Whether `obj` is an instance of one of numpy's types.
fn is_numpy_type(obj: &Bound<'_, PyAny>, ty: NpyTypes) -> bool {
    // SAFETY: a type object from numpy's C API table, and a live object.
    unsafe {
        let ty = npyffi::get_type_object(obj.py(), ty);
        pyo3::ffi::PyObject_TypeCheck(obj.as_ptr(), ty) != 0
    }
}

/// The float64 values of a real array, in C order.
fn floats<'py>(array: &Bound<'py, PyUntypedArray>) -> PyResult<Floats<'py>> {
    if let Ok(a) = array.cast::<PyArray<f64, IxDyn>>()
        && a.is_c_contiguous()
        && a.is_aligned()
    {
        return Ok(Floats::InPlace(
            a.try_readonly().map_err(|_| being_written())?,
        ));
    }
    let converted: PyArrayLike<'py, f64, IxDyn, AllowTypeChange> = array.extract()?;
    if converted.is_c_contiguous() && converted.is_aligned() {
        return Ok(Floats::InPlace((*converted).clone()));
    }
    Ok(Floats::Copied(
        converted.as_array().iter().copied().collect(),
    ))
}

fn being_written() -> PyErr {
    pyo3::exceptions::PyRuntimeError::new_err(
        "an input array is being written by another call (as its out=)",
    )
}

/// A shape as numpy prints it: `()`, `(3,)`, `(3, 2)`.
pub(super) fn shape_text(shape: &[usize]) -> String {
    match shape {
        [n] => format!("({n},)"),
        _ => {
            let dims: Vec<String> = shape.iter().map(usize::to_string).collect();
            format!("({})", dims.join(", "))
        }
    }
}

/// A number: a Python float (or `np.float64`) as is; anything else `float()` accepts (an int,
/// a `Fraction`, a `Decimal`, a numpy scalar or 0-d array of a real dtype); not a bool.
pub(super) fn number(name: &str, obj: &Bound<'_, PyAny>) -> PyResult<f64> {
    if let Ok(x) = obj.cast::<PyFloat>() {
        return Ok(x.value());
    }
    if obj.is_instance_of::<PyBool>() {
        return Err(PyTypeError::new_err(format!(
            "{name}: expected real numbers, got bool"
        )));
    }
    if obj.is_instance_of::<PyUntypedArray>()
        || obj.is_instance_of::<PyList>()
        || obj.is_instance_of::<PyTuple>()
        || is_numpy_scalar(obj)
    {
        let array = real_array(name, obj)?;
        if array.ndim() != 0 {
            let shape = shape_text(array.shape());
            let reason = format!("expected a scalar, got shape {shape}");
            return Err(input_error(obj.py(), name, None, &reason));
        }
        return Ok(floats(&array)?
            .values()
            .first()
            .copied()
            .unwrap_or(f64::NAN));
    }
    obj.extract::<f64>().map_err(|e| {
        let py = obj.py();
        if e.is_instance_of::<PyOverflowError>(py) {
            let reason = format!(
                "must be finite, got {} (beyond float64's range)",
                e.value(py)
            );
            input_error(py, name, None, &reason)
        } else if e.is_instance_of::<PyTypeError>(py) {
            PyTypeError::new_err(format!(
                "{name}: expected real numbers, got {}",
                type_name(obj)
            ))
        } else {
            e
        }
    })
}

fn type_name(obj: &Bound<'_, PyAny>) -> String {
    obj.get_type()
        .name()
        .map_or_else(|_| "another type".to_owned(), |n| n.to_string())
}

/// An `(x, y)` vector: two numbers (a list or tuple of Python numbers is read directly).
pub(super) fn point(name: &str, obj: &Bound<'_, PyAny>) -> PyResult<[f64; 2]> {
    let plain = |item: &Bound<'_, PyAny>| {
        item.is_instance_of::<PyFloat>()
            || (item.is_instance_of::<PyInt>() && !item.is_instance_of::<PyBool>())
    };
    let pair = match (obj.cast::<PyTuple>(), obj.cast::<PyList>()) {
        (Ok(t), _) if t.len() == 2 => Some((t.get_item(0)?, t.get_item(1)?)),
        (_, Ok(l)) if l.len() == 2 => Some((l.get_item(0)?, l.get_item(1)?)),
        _ => None,
    };
    if let Some((x, y)) = pair
        && plain(&x)
        && plain(&y)
    {
        return Ok([number(name, &x)?, number(name, &y)?]);
    }
    let array = real_array(name, obj)?;
    if array.shape() != [2] {
        let shape = shape_text(array.shape());
        let reason = format!("expected a 2-vector (x, y), got shape {shape}");
        return Err(input_error(obj.py(), name, None, &reason));
    }
    match floats(&array)?.values() {
        &[x, y] => Ok([x, y]),
        _ => Err(input_error(
            obj.py(),
            name,
            None,
            "expected a 2-vector (x, y)",
        )),
    }
}

/// An `(N, 2)` array of rows.
pub(super) fn rows<'py>(name: &str, obj: &Bound<'py, PyAny>) -> PyResult<Floats<'py>> {
    let array = real_array(name, obj)?;
    if array.ndim() != 2 || array.shape()[1] != 2 {
        let shape = shape_text(array.shape());
        let reason = format!("expected shape (N, 2), got {shape}");
        return Err(input_error(obj.py(), name, None, &reason));
    }
    floats(&array)
}

/// A per-pair parameter: a number, or an array-like of shape `(N,)`.
pub(super) fn param<'py>(name: &str, obj: &Bound<'py, PyAny>) -> PyResult<Param<'py>> {
    if let Ok(x) = obj.cast::<PyFloat>() {
        return Ok(Param::All(x.value()));
    }
    let array_like = obj.is_instance_of::<PyUntypedArray>()
        || obj.is_instance_of::<PyList>()
        || obj.is_instance_of::<PyTuple>();
    if !array_like {
        return number(name, obj).map(Param::All);
    }
    let array = real_array(name, obj)?;
    match array.ndim() {
        0 => number(name, &array).map(Param::All),
        1 => floats(&array).map(Param::Each),
        _ => {
            let shape = shape_text(array.shape());
            let reason = format!("expected a scalar or shape (N,), got shape {shape}");
            Err(input_error(obj.py(), name, None, &reason))
        }
    }
}

/// `num_threads`: `None` → every core; an int `n ≥ 1` → at most `n` (and at most the cores
/// there are, so that a huge `n` cannot start thousands of threads).
pub(super) fn threads(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Threads> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(Threads::All);
    };
    let py = obj.py();
    let not_int = |what: &str| {
        PyTypeError::new_err(format!("num_threads: expected None or an int, got {what}"))
    };
    if obj.is_instance_of::<PyBool>() || is_numpy_type(obj, NpyTypes::PyBoolArrType_Type) {
        return Err(not_int("bool"));
    }
    // SAFETY: a live object; `PyNumber_Index` returns a new reference or NULL with an
    // exception set.
    let index =
        unsafe { Bound::from_owned_ptr_or_err(py, pyo3::ffi::PyNumber_Index(obj.as_ptr())) }
            .map_err(|_| not_int(&type_name(obj)))?;
    let n = match index.extract::<i64>() {
        Ok(n) => n,
        // Beyond 64 bits: as many threads as there are cores if positive.
        Err(_) if index.gt(0)? => i64::MAX,
        Err(_) => i64::MIN,
    };
    if n < 1 {
        let reason = format!("must be None (all cores) or ≥ 1, got {index}");
        return Err(input_error(py, "num_threads", None, &reason));
    }
    let n = usize::try_from(n).unwrap_or(usize::MAX).min(cores());
    Ok(NonZeroUsize::new(n).map_or(Threads::All, Threads::AtMost))
}

/// The cores this process may use, read once: `available_parallelism` reads the cgroup quota
/// and the affinity mask on every call (~25 µs on Linux), more than a call on a few hundred
/// pairs costs in all.
fn cores() -> usize {
    static CORES: OnceLock<usize> = OnceLock::new();
    *CORES.get_or_init(|| std::thread::available_parallelism().map_or(1, NonZeroUsize::get))
}

/// A caller's output array (`out=`), borrowed for writing: a float64 numpy array of `shape`
/// (else a `TypeError` if not a native float64 array of that many dimensions, a
/// `ValueError` otherwise), C-contiguous, writeable and sharing no memory with the inputs.
///
/// Its shape is checked here, after the inputs' own checks: the core measures every input
/// against the output's length, and would blame the first input for an output of the wrong
/// length.
pub(super) fn out<'py, D: Dimension>(
    obj: &Bound<'py, PyAny>,
    shape: &[usize],
    expected: &str,
) -> PyResult<PyReadwriteArray<'py, f64, D>> {
    let py = obj.py();
    let fail = |reason: &str| input_error(py, "out", None, reason);
    let array = obj.cast::<PyArray<f64, D>>().map_err(|_| {
        let found = match obj.cast::<PyUntypedArray>() {
            Ok(a) => format!("a {}-D array of dtype {}", a.ndim(), a.dtype()),
            Err(_) => type_name(obj),
        };
        PyTypeError::new_err(format!("out: expected {expected}, got {found}"))
    })?;
    if array.shape() != shape {
        let (want, got) = (shape_text(shape), shape_text(array.shape()));
        return Err(fail(&format!("expected shape {want}, got {got}")));
    }
    if !array.is_c_contiguous() || !array.is_aligned() {
        return Err(fail("expected a C-contiguous, aligned float64 array"));
    }
    // rust-numpy's borrow tracking: the inputs read in place are borrowed (see [`Floats`]).
    array.try_readwrite().map_err(|e| match e {
        BorrowError::NotWriteable => fail("the array is read-only"),
        _ => fail("the array shares memory with an input"),
    })
}

/// Polynomial coefficients: a 1-D or 2-D array of real numbers, and its shape.
pub(super) fn coefficients<'py>(
    name: &str,
    obj: &Bound<'py, PyAny>,
) -> PyResult<(Floats<'py>, Vec<usize>)> {
    let array = real_array(name, obj)?;
    let shape = array.shape().to_vec();
    if !matches!(shape.len(), 1 | 2) {
        let reason = format!(
            "expected shape (N, k+1) with degree k = 1..4, got {}",
            shape_text(&shape)
        );
        return Err(input_error(obj.py(), name, None, &reason));
    }
    Ok((floats(&array)?, shape))
}
