//! Reading the Python functions' arguments: numbers, rows, per-pair values, `num_threads`,
//! `out`. Each reader accepts what Python and numpy users hand over (lists and tuples,
//! any real dtype, C or Fortran order, strided views, read-only or big-endian arrays, and
//! any number `float()` accepts where a scalar goes) and gives the Rust core float64 data in
//! C order: in place when it already is so, else gathered and converted in one pass of our
//! own into a reused buffer (numpy's conversion for the rare dtypes that pass cannot read);
//! nested lists and tuples of Python numbers are read directly, not through numpy. Booleans
//! are not numbers here.
//!
//! Errors name the argument: `TypeError` for what is not made of real numbers,
//! [`InputError`](super::input_error::InputError) (a `ValueError`) for a wrong shape,
//! layout or value.

use super::input_error::kind;
use std::ffi::c_int;
use std::mem::MaybeUninit;
use std::num::NonZeroUsize;
use std::sync::OnceLock;

use numpy::ndarray::{Dimension, IxDyn};
use numpy::npyffi::{self, NPY_TYPES, NpyTypes, PY_ARRAY_API};
use numpy::{PyArray, PyArrayMethods};
use numpy::{PyArrayDescr, PyArrayDescrMethods};
use numpy::{PyReadonlyArray, PyReadwriteArray, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::exceptions::{PyDeprecationWarning, PyOverflowError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyFloat, PyInt, PyList, PyTuple};

use super::input_error::input_error;
use crate::batch::{PerPair, Threads};

/// float64 values in C order, read in place or converted, and the memory they were read
/// from.
///
/// An array read in place is not entered in rust-numpy's borrow registry (which costs two
/// locked hash-map updates and allocations per array, more than a call on a few pairs costs
/// in all) by a call that holds the GIL throughout: no Python code can write into it
/// meanwhile, and native code writing into a call's inputs from another thread without the
/// GIL breaks the documented contract (as it would for numpy's own functions). A call that
/// releases the GIL first borrows every array read in place through the registry ([`track`]),
/// so that a rust-numpy writer elsewhere (another call's `out=`) is refused meanwhile; and
/// every call checks that its `out` overlaps no input as the caller gave it ([`out`]), not
/// only the converted copy.
pub(super) struct Floats<'py> {
    data: Data<'py>,
    /// The array numpy read the values from (the caller's array, or one over the memory an
    /// object handed to numpy shares), and the addresses it spans: what an `out=` must not
    /// share memory with.
    source: (Bound<'py, PyUntypedArray>, std::ops::Range<usize>),
}

enum Data<'py> {
    /// A C-contiguous, aligned, native float64 array.
    InPlace(Bound<'py, PyArray<f64, IxDyn>>),
    /// The values gathered or converted into memory of our own.
    Copied(Buffer),
}

/// A buffer of gathered values, handed back to [`SPARE`] when dropped: the next call that
/// gathers reuses its memory instead of asking the system for fresh pages. A fresh page costs
/// a fault and the kernel's zeroing on first touch, which on virtual machines costs more than
/// gathering the values into it (~25 ns a pair for a float64 `(N, 2)` array here).
struct Buffer(Vec<f64>);

/// Buffers kept for reuse: at most [`SPARE_BUFFERS`] of them and [`SPARE_BYTES`] in all, the
/// largest kept first.
static SPARE: std::sync::Mutex<Vec<Vec<f64>>> = std::sync::Mutex::new(Vec::new());
const SPARE_BUFFERS: usize = 8;
const SPARE_BYTES: usize = 64 << 20;

impl Buffer {
    /// A buffer of `len` values, each written by `write` (which must write all of them): a
    /// spare one if one is large enough (the smallest such), else a new one.
    fn filled(len: usize, write: impl FnOnce(&mut [MaybeUninit<f64>])) -> Self {
        let spare = SPARE.lock().ok().and_then(|mut spare| {
            let fits = (0..spare.len())
                .filter(|&k| spare[k].capacity() >= len)
                .min_by_key(|&k| spare[k].capacity())?;
            Some(spare.swap_remove(fits))
        });
        let mut values = spare.unwrap_or_default();
        values.clear();
        values.reserve_exact(len);
        write(&mut values.spare_capacity_mut()[..len]);
        // SAFETY: `write` initialised the first `len` elements.
        unsafe { values.set_len(len) };
        Self(values)
    }
}

impl Drop for Buffer {
    fn drop(&mut self) {
        let values = std::mem::take(&mut self.0);
        let bytes = |v: &Vec<f64>| v.capacity() * size_of::<f64>();
        if bytes(&values) == 0 || bytes(&values) > SPARE_BYTES {
            return;
        }
        let Ok(mut spare) = SPARE.lock() else { return };
        spare.push(values);
        // Keep the largest buffers within the bounds.
        spare.sort_unstable_by_key(|v| std::cmp::Reverse(v.capacity()));
        let mut total = 0;
        spare.retain(|v| {
            total += bytes(v);
            total <= SPARE_BYTES
        });
        spare.truncate(SPARE_BUFFERS);
    }
}

impl<'py> Floats<'py> {
    /// The values, in C order.
    pub(super) fn values(&self) -> &[f64] {
        match &self.data {
            // SAFETY: nothing writes into the array while the values are read (see the type's
            // documentation: the GIL is held, or the array is borrowed through the registry,
            // and no other thread modifies a call's inputs). `as_slice` succeeds: `InPlace`
            // holds only C-contiguous, aligned arrays.
            Data::InPlace(a) => unsafe { a.as_slice() }.unwrap_or(&[]),
            Data::Copied(v) => &v.0,
        }
    }

    /// The array read in place, borrowed through rust-numpy's registry (see [`track`]).
    fn tracked(&self) -> PyResult<Option<PyReadonlyArray<'py, f64, IxDyn>>> {
        match &self.data {
            Data::InPlace(a) => a.try_readonly().map(Some).map_err(|_| being_written()),
            Data::Copied(_) => Ok(None),
        }
    }

    /// The values as rows of `D` numbers (`(x, y)` or `(x, y, z)`).
    pub(super) fn rows<const D: usize>(&self) -> &[[f64; D]] {
        self.values().as_chunks::<D>().0
    }
}

/// A scalar parameter: one value for all pairs (balls), or one per pair.
pub(super) enum Param<'py> {
    All(f64),
    Each(Floats<'py>),
}

impl<'py> Param<'py> {
    pub(super) fn per_pair(&self) -> PerPair<'_> {
        match self {
            Self::All(x) => PerPair::All(*x),
            Self::Each(values) => PerPair::Each(values.values()),
        }
    }

    /// The values, if one per pair.
    pub(super) fn each(&self) -> Option<&Floats<'py>> {
        match self {
            Self::All(_) => None,
            Self::Each(values) => Some(values),
        }
    }
}

/// Borrows every array of `inputs` read in place through rust-numpy's registry, for a call
/// that releases the GIL: the borrows last as long as the returned guards.
pub(super) fn track<'py>(
    inputs: &[Option<&Floats<'py>>],
) -> PyResult<Vec<PyReadonlyArray<'py, f64, IxDyn>>> {
    let mut guards = Vec::new();
    for input in inputs.iter().flatten() {
        guards.extend(input.tracked()?);
    }
    Ok(guards)
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

/// A numpy array of real numbers and its dtype.
struct Real<'py> {
    array: Bound<'py, PyUntypedArray>,
    dtype: Bound<'py, PyArrayDescr>,
}

/// `obj` as a numpy array of real numbers (itself if it is one, else `numpy.asarray(obj)`).
fn real_array<'py>(name: &str, obj: &Bound<'py, PyAny>) -> PyResult<Real<'py>> {
    match obj.cast::<PyUntypedArray>() {
        Ok(array) => real(name, obj, array.clone()),
        Err(_) => real(name, obj, asarray(name, obj)?),
    }
}

/// `numpy.asarray(obj)`, or an error naming the argument.
fn asarray<'py>(name: &str, obj: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyUntypedArray>> {
    let py = obj.py();
    if let Some(array) = nested_numbers(obj) {
        return Ok(array);
    }
    // numpy would read `[True, 0.5]` as the numbers `[1, 0.5]`; a bool is no real number
    // (as for a scalar argument).
    if holds_bool(obj, 0) {
        return Err(PyTypeError::new_err(format!(
            "{name}: expected real numbers, got bool"
        )));
    }
    // SAFETY: `obj` is a live object; `PyArray_FromAny` returns a new reference or NULL with
    // an exception set, and with no dtype asked for it returns an ndarray.
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
        input_error(py, name, None, kind::NOT_NUMBERS, &reason)
    })?;
    Ok(made.cast_into::<PyUntypedArray>()?)
}

/// Nested lists or tuples of Python floats and ints (not bools) of a regular shape, read
/// directly into a new C-ordered float64 array, about ten times as fast as numpy's reading of
/// them: the values and shape `numpy.asarray(obj)` would hold after `astype(float64)` (an
/// int converted as numpy converts an int64: to the nearest float64, ties to even). `None`
/// for anything else (another item type, an int beyond 64 bits, a ragged shape, a scalar),
/// which numpy then reads.
fn nested_numbers<'py>(obj: &Bound<'py, PyAny>) -> Option<Bound<'py, PyUntypedArray>> {
    let mut shape = Vec::new();
    let mut item = obj.clone();
    loop {
        let (len, first) = if let Ok(list) = item.cast::<PyList>() {
            (list.len(), list.get_item(0))
        } else if let Ok(tuple) = item.cast::<PyTuple>() {
            (tuple.len(), tuple.get_item(0))
        } else {
            break;
        };
        shape.push(len);
        if len == 0 || shape.len() > 32 {
            break;
        }
        item = first.ok()?;
    }
    if shape.is_empty() {
        return None;
    }
    let mut values = Vec::with_capacity(shape.iter().product());
    read_nested(obj, &shape, &mut values)?;
    let array = PyArray::from_vec(obj.py(), values).reshape(shape).ok()?;
    array.into_any().cast_into::<PyUntypedArray>().ok()
}

/// Whether `obj` is a bool, Python's or numpy's.
fn is_bool(obj: &Bound<'_, PyAny>) -> bool {
    obj.is_instance_of::<PyBool>() || is_numpy_type(obj, NpyTypes::PyBoolArrType_Type)
}

/// Whether `obj`, nested lists or tuples (`depth` levels in), holds a bool (Python's or
/// numpy's, or an array of them) among its items.
fn holds_bool(obj: &Bound<'_, PyAny>, depth: usize) -> bool {
    let is_bool = |item: &Bound<'_, PyAny>| {
        is_bool(item)
            || item
                .cast::<PyUntypedArray>()
                .is_ok_and(|array| array.dtype().kind() == b'b')
    };
    if depth > 32 {
        return false;
    }
    let nested = |item: Bound<'_, PyAny>| is_bool(&item) || holds_bool(&item, depth + 1);
    if let Ok(list) = obj.cast::<PyList>() {
        list.iter().any(nested)
    } else if let Ok(tuple) = obj.cast::<PyTuple>() {
        tuple.iter().any(nested)
    } else {
        false
    }
}

/// Appends the numbers of `obj`, nested lists or tuples of `shape`, in C order.
fn read_nested(obj: &Bound<'_, PyAny>, shape: &[usize], values: &mut Vec<f64>) -> Option<()> {
    let Some((&len, inner)) = shape.split_first() else {
        let value = if obj.is_exact_instance_of::<PyFloat>() {
            obj.cast::<PyFloat>().ok()?.value()
        } else if obj.is_exact_instance_of::<PyInt>() {
            obj.extract::<i64>().ok()? as f64
        } else {
            return None;
        };
        values.push(value);
        return Some(());
    };
    let each = |item: Bound<'_, PyAny>| read_nested(&item, inner, values);
    if let Ok(list) = obj.cast::<PyList>() {
        if list.len() != len {
            return None;
        }
        return list.iter().try_for_each(each);
    }
    let tuple = obj.cast::<PyTuple>().ok()?;
    if tuple.len() != len {
        return None;
    }
    tuple.iter().try_for_each(each)
}

/// `array` (read from `obj`) if its dtype is a real one: a float or integer kind.
fn real<'py>(
    name: &str,
    obj: &Bound<'py, PyAny>,
    array: Bound<'py, PyUntypedArray>,
) -> PyResult<Real<'py>> {
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
    Ok(Real { array, dtype })
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

/// Whether `dtype` is float64 in this machine's byte order: what `PyArray<f64, _>`'s own
/// type check asks, without asking numpy for a float64 descriptor to compare with.
fn native_float64(dtype: &Bound<'_, PyArrayDescr>) -> bool {
    dtype.num() == NPY_TYPES::NPY_DOUBLE as c_int && dtype.is_native_byteorder() != Some(false)
}

/// The float64 values of a real array, in C order: the one reader of every array argument.
///
/// A C-contiguous, aligned, native float64 array is read in place. Any other layout of
/// float64, float32 or an integer type in this machine's byte order (Fortran order, a column
/// of a wider array, every other row, negative strides, unaligned) is gathered by [`gather`]
/// in one pass into memory of our own (a [`Buffer`], reused from call to call), converted as
/// numpy's casts convert. What remains
/// (float16, longdouble, byte-swapped) numpy converts: `numpy.ascontiguousarray(array,
/// dtype=float64)`, read in place.
fn floats<'py>(real: &Real<'py>) -> PyResult<Floats<'py>> {
    let Real { array, dtype } = real;
    let source = (array.clone(), extent(array, dtype));
    if native_float64(dtype) && array.is_c_contiguous() && array.is_aligned() {
        // SAFETY: an ndarray of native float64 (`native_float64`).
        let a = unsafe { array.cast_unchecked::<PyArray<f64, IxDyn>>() };
        let data = Data::InPlace(a.clone());
        return Ok(Floats { data, source });
    }
    if let Some(values) = gather(array, dtype) {
        let data = Data::Copied(values);
        return Ok(Floats { data, source });
    }
    let converted = ascontiguous_float64(array)?;
    // SAFETY: `numpy.ascontiguousarray(…, dtype=float64)` gives a C-contiguous, aligned array
    // of native float64; a new one (this call is its only reader) or `array` itself.
    let a = unsafe { converted.cast_into_unchecked::<PyArray<f64, IxDyn>>() };
    Ok(Floats {
        data: Data::InPlace(a),
        source,
    })
}

/// `numpy.ascontiguousarray(array, dtype=numpy.float64)`.
fn ascontiguous_float64<'py>(array: &Bound<'py, PyUntypedArray>) -> PyResult<Bound<'py, PyAny>> {
    let py = array.py();
    static ASCONTIGUOUS: pyo3::sync::PyOnceLock<Py<PyAny>> = pyo3::sync::PyOnceLock::new();
    static FLOAT64: pyo3::sync::PyOnceLock<Py<PyAny>> = pyo3::sync::PyOnceLock::new();
    let f = ASCONTIGUOUS.import(py, "numpy", "ascontiguousarray")?;
    let float64 = FLOAT64.import(py, "numpy", "float64")?;
    let converted = f.call1((array, float64))?;
    match converted.cast::<PyUntypedArray>() {
        Ok(a) if native_float64(&a.dtype()) && a.is_c_contiguous() && a.is_aligned() => {
            Ok(converted)
        }
        _ => Err(PyTypeError::new_err(
            "numpy.ascontiguousarray gave no C-contiguous float64 array",
        )),
    }
}

/// The values of `array` in C order as float64, in one pass over its memory (its strides,
/// any sign, any alignment), if its dtype is float64, float32 or an integer type of 1 to 8
/// bytes in this machine's byte order; `None` for any other dtype.
///
/// Each value is converted as numpy's cast (`astype(float64)`) converts it: exactly, or for an
/// integer beyond 2^53 rounded to the nearest float64 (ties to even).
fn gather(array: &Bound<'_, PyUntypedArray>, dtype: &Bound<'_, PyArrayDescr>) -> Option<Buffer> {
    let (kind, size) = (dtype.kind(), dtype.itemsize());
    let readable = matches!((kind, size), (b'f', 4 | 8) | (b'i' | b'u', 1 | 2 | 4 | 8));
    if !readable || dtype.is_native_byteorder() == Some(false) {
        return None;
    }
    let shape = array.shape();
    let strides = array.strides();
    // SAFETY: a live array's header; its data pointer.
    let src = unsafe { (*npyffi::_PyArray_GET_ITEM_DATA(array.as_array_ptr())).data }
        .cast_const()
        .cast::<u8>();
    Some(Buffer::filled(shape.iter().product(), |dst| {
        if dst.is_empty() {
            return;
        }
        // SAFETY (each `fill`): `src`, `shape` and `strides` are the array's own, so every
        // element read lies in its memory, and the element type is the dtype's (kind and
        // size); `dst` holds as many elements as the array; nothing writes into the array
        // meanwhile (the GIL is held: see `Floats`).
        unsafe {
            match (kind, size) {
                (b'f', 8) => fill::<f64>(dst, src, shape, strides, |x| x),
                (b'f', 4) => fill::<f32>(dst, src, shape, strides, f64::from),
                (b'i', 8) => fill::<i64>(dst, src, shape, strides, |x| x as f64),
                (b'i', 4) => fill::<i32>(dst, src, shape, strides, f64::from),
                (b'i', 2) => fill::<i16>(dst, src, shape, strides, f64::from),
                (b'i', 1) => fill::<i8>(dst, src, shape, strides, f64::from),
                (b'u', 8) => fill::<u64>(dst, src, shape, strides, |x| x as f64),
                (b'u', 4) => fill::<u32>(dst, src, shape, strides, f64::from),
                (b'u', 2) => fill::<u16>(dst, src, shape, strides, f64::from),
                (b'u', 1) => fill::<u8>(dst, src, shape, strides, f64::from),
                // Not reached (`readable`); every element written all the same.
                _ => dst.fill(MaybeUninit::new(f64::NAN)),
            }
        }
    }))
}

/// Writes the elements of the strided array at `src` (`shape`, byte `strides`, element type
/// `T`) into `dst` in C order, each through `to`. Rows of 2 or 3 numbers (the last dimension
/// of positions and velocities) are read whole: a Fortran-ordered `(N, 2)` array is then two
/// sequential streams, read at memory speed.
///
/// # Safety
///
/// `dst` holds the product of `shape` elements, at least one, and each is written; every element
/// `src + Σ index·stride` is a readable `T` (unaligned allowed).
unsafe fn fill<T: Copy>(
    dst: &mut [MaybeUninit<f64>],
    src: *const u8,
    shape: &[usize],
    strides: &[isize],
    to: impl Fn(T) -> f64 + Copy,
) {
    // SAFETY: within the array (the caller's promise); `offset`s stay in it.
    let at = |p: *const u8| MaybeUninit::new(to(unsafe { p.cast::<T>().read_unaligned() }));
    let step = |p: *const u8, k: usize, stride: isize| unsafe { p.offset(k as isize * stride) };
    match (shape, strides) {
        ([], _) => dst[0] = at(src),
        ([_], &[s]) => {
            for (k, d) in dst.iter_mut().enumerate() {
                *d = at(step(src, k, s));
            }
        }
        ([_, 2], &[s, t]) => {
            for (k, row) in dst.as_chunks_mut::<2>().0.iter_mut().enumerate() {
                let p = step(src, k, s);
                *row = [at(p), at(step(p, 1, t))];
            }
        }
        ([_, 3], &[s, t]) => {
            for (k, row) in dst.as_chunks_mut::<3>().0.iter_mut().enumerate() {
                let p = step(src, k, s);
                *row = [at(p), at(step(p, 1, t)), at(step(p, 2, t))];
            }
        }
        ([n, inner @ ..], [s, inner_strides @ ..]) => {
            let len = dst.len() / n;
            for (k, part) in dst.chunks_exact_mut(len).enumerate() {
                // SAFETY: the `k`th sub-array, within the array.
                unsafe { fill(part, step(src, k, *s), inner, inner_strides, to) };
            }
        }
        // As many strides as dimensions: not reached; every element written all the same.
        _ => dst.fill(MaybeUninit::new(f64::NAN)),
    }
}

/// The addresses `array`'s elements span, from its lowest byte to past its highest, whatever
/// its strides (numpy's own bounds for `may_share_memory`); empty for an empty array.
fn extent(
    array: &Bound<'_, PyUntypedArray>,
    dtype: &Bound<'_, PyArrayDescr>,
) -> std::ops::Range<usize> {
    // SAFETY: a live array's header; only its data pointer is read.
    let start = unsafe { (*npyffi::_PyArray_GET_ITEM_DATA(array.as_array_ptr())).data } as usize;
    let (mut lo, mut hi) = (start, start);
    for (&len, &stride) in array.shape().iter().zip(array.strides()) {
        let Some(last) = len.checked_sub(1) else {
            return start..start;
        };
        let span = stride.unsigned_abs().saturating_mul(last);
        if stride < 0 {
            lo = lo.saturating_sub(span);
        } else {
            hi = hi.saturating_add(span);
        }
    }
    lo..hi.saturating_add(dtype.itemsize())
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
        let real = real_array(name, obj)?;
        if real.array.ndim() != 0 {
            let shape = shape_text(real.array.shape());
            let reason = format!("expected a scalar, got shape {shape}");
            return Err(input_error(obj.py(), name, None, kind::SHAPE, &reason));
        }
        return Ok(floats(&real)?.values().first().copied().unwrap_or(f64::NAN));
    }
    obj.extract::<f64>().map_err(|e| {
        let py = obj.py();
        if e.is_instance_of::<PyOverflowError>(py) {
            let reason = format!(
                "must be finite, got {} (beyond float64's range)",
                e.value(py)
            );
            input_error(py, name, None, NOT_FINITE, &reason)
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
    // (A bool among the items, which numpy would read as a number: refused by the reading.)
    let real = real_array(name, obj)?;
    if real.array.shape() != [2] {
        let shape = shape_text(real.array.shape());
        let reason = format!("expected a 2-vector (x, y), got shape {shape}");
        return Err(input_error(obj.py(), name, None, kind::SHAPE, &reason));
    }
    match floats(&real)?.values() {
        &[x, y] => Ok([x, y]),
        _ => Err(input_error(
            obj.py(),
            name,
            None,
            kind::SHAPE,
            "expected a 2-vector (x, y)",
        )),
    }
}

/// An `(N, 2)` array of rows.
pub(super) fn rows<'py>(name: &str, obj: &Bound<'py, PyAny>) -> PyResult<Floats<'py>> {
    let real = real_array(name, obj)?;
    let shape = real.array.shape();
    if shape.len() != 2 || shape[1] != 2 {
        let reason = format!("expected shape (N, 2), got {}", shape_text(shape));
        return Err(input_error(obj.py(), name, None, kind::SHAPE, &reason));
    }
    floats(&real)
}

/// A per-pair parameter: a number, or an array-like of shape `(N,)`.
pub(super) fn param<'py>(name: &str, obj: &Bound<'py, PyAny>) -> PyResult<Param<'py>> {
    if let Ok(x) = obj.cast::<PyFloat>() {
        return Ok(Param::All(x.value()));
    }
    let real = match obj.cast::<PyUntypedArray>() {
        Ok(array) => real(name, obj, array.clone())?,
        Err(_) if obj.is_instance_of::<PyList>() || obj.is_instance_of::<PyTuple>() => {
            real(name, obj, asarray(name, obj)?)?
        }
        Err(_) => return number(name, obj).map(Param::All),
    };
    match real.array.ndim() {
        0 => number(name, &real.array).map(Param::All),
        1 => floats(&real).map(Param::Each),
        _ => {
            let shape = shape_text(real.array.shape());
            let reason = format!("expected a scalar or shape (N,), got shape {shape}");
            Err(input_error(obj.py(), name, None, kind::SHAPE, &reason))
        }
    }
}

/// The pair calls' contact distance (the sum of the two radii): `contact_distance`, or the
/// same value under its former name `radius=`, with a `DeprecationWarning` (in the scene and
/// calendar calls `radius` is one ball's own radius: one name, one meaning).
pub(super) fn contact_distance<'py>(
    py: Python<'py>,
    contact_distance: Given<'py>,
    radius: Given<'py>,
) -> PyResult<Bound<'py, PyAny>> {
    match (contact_distance.0, radius.0) {
        (Some(given), None) => Ok(given),
        (None, Some(given)) => {
            PyErr::warn(
                py,
                &py.get_type::<PyDeprecationWarning>(),
                c"radius= is deprecated in the pair calls, where it is the contact distance \
                  (the sum of the two radii): pass contact_distance= instead",
                1,
            )?;
            Ok(given)
        }
        (Some(_), Some(_)) => Err(PyTypeError::new_err(
            "contact_distance: given twice (radius= is its deprecated name)",
        )),
        (None, None) => Err(PyTypeError::new_err(
            "contact_distance: missing (the distance between the centres at contact)",
        )),
    }
}

/// `num_threads`: `None` → every core; an int `n ≥ 1` → at most `n` (and at most the cores
/// there are, so that a huge `n` cannot start thousands of threads).
pub(super) fn threads(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Threads> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(Threads::All);
    };
    let index = int("num_threads", obj, "None or an int")?;
    let n = match index.extract::<i64>() {
        Ok(n) => n,
        // Beyond 64 bits: as many threads as there are cores if positive.
        Err(_) if index.gt(0)? => i64::MAX,
        Err(_) => i64::MIN,
    };
    if n < 1 {
        let reason = format!("must be None (all cores) or ≥ 1, got {index}");
        return Err(input_error(
            obj.py(),
            "num_threads",
            None,
            kind::OUT_OF_RANGE,
            &reason,
        ));
    }
    let n = usize::try_from(n).unwrap_or(usize::MAX).min(cores());
    Ok(NonZeroUsize::new(n).map_or(Threads::All, Threads::AtMost))
}

/// A count such as `max_events`: `None` → none; an int `n ≥ 0` → `n` (one beyond `usize`, more
/// than could ever be counted, as `usize::MAX`).
pub(super) fn count(name: &str, obj: Option<&Bound<'_, PyAny>>) -> PyResult<Option<usize>> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(None);
    };
    let index = int(name, obj, "None or an int")?;
    if index.lt(0)? {
        let reason = format!("must be None or ≥ 0, got {index}");
        return Err(input_error(
            obj.py(),
            name,
            None,
            kind::OUT_OF_RANGE,
            &reason,
        ));
    }
    Ok(Some(index.extract::<usize>().unwrap_or(usize::MAX)))
}

/// Ball indices, each in `0..n`: an int, or a sequence of ints (a list, a tuple, a 1-D integer
/// array). An index out of range (negative, or of any size) is an
/// [`InputError`](super::input_error::InputError) at its position, `indices[m]`; what is not an
/// int (a bool, a float, a string) a `TypeError` naming it.
pub(super) fn indices(name: &str, obj: &Bound<'_, PyAny>, n: usize) -> PyResult<Vec<usize>> {
    let one = |m: Option<usize>, item: &Bound<'_, PyAny>| -> PyResult<usize> {
        let expected = match m {
            Some(_) => "an int (a ball index)",
            None => "an int or a sequence of ints (ball indices)",
        };
        ball_index(name, m, item, n, expected)
    };
    let py = obj.py();
    let sequence = obj.is_instance_of::<PyList>()
        || obj.is_instance_of::<PyTuple>()
        || obj.cast::<PyUntypedArray>().is_ok_and(|a| a.ndim() != 0);
    if !sequence {
        return one(None, obj).map(|i| vec![i]);
    }
    if let Ok(array) = obj.cast::<PyUntypedArray>() {
        let dtype = array.dtype();
        if !matches!(dtype.kind(), b'i' | b'u') {
            return Err(PyTypeError::new_err(format!(
                "{name}: expected ints (ball indices), got an array of dtype {dtype}"
            )));
        }
        if array.ndim() != 1 {
            let shape = shape_text(array.shape());
            let reason = format!("expected an int or shape (M,), got shape {shape}");
            return Err(input_error(py, name, None, kind::SHAPE, &reason));
        }
    }
    obj.try_iter()?
        .enumerate()
        .map(|(m, item)| one(Some(m), &item?))
        .collect()
}

/// One ball index, an int in `0..n` (`name`, at `m` in a sequence): out of range an
/// [`InputError`](super::input_error::InputError), not an int a `TypeError` saying it
/// `expected` one.
pub(super) fn ball_index(
    name: &str,
    m: Option<usize>,
    obj: &Bound<'_, PyAny>,
    n: usize,
    expected: &str,
) -> PyResult<usize> {
    let index = match m {
        Some(m) => int(&format!("{name}[{m}]"), obj, expected)?,
        None => int(name, obj, expected)?,
    };
    match index.extract::<usize>() {
        Ok(i) if i < n => Ok(i),
        _ => {
            let reason = format!("ball index must be in 0..{n}, got {index}");
            Err(input_error(obj.py(), name, m, INDEX_OUT_OF_RANGE, &reason))
        }
    }
}

/// A flag: `True` or `False` (Python's or numpy's bools); anything else is a `TypeError`
/// naming it.
pub(super) fn flag(name: &str, obj: &Bound<'_, PyAny>) -> PyResult<bool> {
    if !is_bool(obj) {
        let what = type_name(obj);
        return Err(PyTypeError::new_err(format!(
            "{name}: expected True or False, got {what}"
        )));
    }
    obj.is_truthy()
}

/// An int argument (a Python int, or anything with `__index__`: a numpy integer), as a Python
/// int; a bool (Python's or numpy's), a float or anything else is a `TypeError` naming it,
/// saying it `expected` that.
pub(super) fn int<'py>(
    name: &str,
    obj: &Bound<'py, PyAny>,
    expected: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let py = obj.py();
    let not_int =
        |what: &str| PyTypeError::new_err(format!("{name}: expected {expected}, got {what}"));
    if is_bool(obj) {
        return Err(not_int("bool"));
    }
    // SAFETY: a live object; `PyNumber_Index` returns a new reference or NULL with an
    // exception set.
    unsafe { Bound::from_owned_ptr_or_err(py, pyo3::ffi::PyNumber_Index(obj.as_ptr())) }
        .map_err(|_| not_int(&type_name(obj)))
}

/// The cores this process may use, read once: `available_parallelism` reads the cgroup quota
/// and the affinity mask on every call (~25 µs on Linux), more than a call on a few hundred
/// pairs costs in all.
fn cores() -> usize {
    static CORES: OnceLock<usize> = OnceLock::new();
    *CORES.get_or_init(|| std::thread::available_parallelism().map_or(1, NonZeroUsize::get))
}

/// A caller's output array (`out=`): a float64 numpy array of `shape` (else a `TypeError` if
/// not a native float64 array of that many dimensions, a `ValueError` otherwise),
/// C-contiguous, writeable and sharing no memory with the inputs. A call that releases the
/// GIL borrows it through rust-numpy's registry too ([`Out::tracked`]).
///
/// Its shape is checked here, after the inputs' own checks: the core measures every input
/// against the output's length, and would blame the first input for an output of the wrong
/// length.
pub(super) fn out<'py, D: Dimension>(
    obj: &Bound<'py, PyAny>,
    shape: &[usize],
    expected: &str,
    inputs: &[Option<&Floats<'_>>],
) -> PyResult<Out<'py, f64, D>> {
    out_of::<f64, D>(obj, None, shape, expected, inputs)
}

/// The element types of output arrays, and how their dtypes are told apart without asking
/// numpy for a descriptor to compare with.
pub(super) trait OutElement: numpy::Element {
    /// Whether `dtype` is this type in this machine's byte order.
    fn is(dtype: &Bound<'_, PyArrayDescr>) -> bool;
}

impl OutElement for f64 {
    fn is(dtype: &Bound<'_, PyArrayDescr>) -> bool {
        native_float64(dtype)
    }
}

impl OutElement for i8 {
    fn is(dtype: &Bound<'_, PyArrayDescr>) -> bool {
        dtype.kind() == b'i' && dtype.itemsize() == 1
    }
}

impl OutElement for i64 {
    fn is(dtype: &Bound<'_, PyArrayDescr>) -> bool {
        // (`long` and `long long` alike.)
        dtype.kind() == b'i' && dtype.itemsize() == 8 && dtype.is_native_byteorder() != Some(false)
    }
}

/// [`out`] for arrays of `T`, the output named `out[at]` where it is one of several (a tuple's
/// item `at`).
pub(super) fn out_of<'py, T: OutElement, D: Dimension>(
    obj: &Bound<'py, PyAny>,
    at: Option<usize>,
    shape: &[usize],
    expected: &str,
    inputs: &[Option<&Floats<'_>>],
) -> PyResult<Out<'py, T, D>> {
    let py = obj.py();
    let fail = |reason: &str| input_error(py, "out", at, kind::OUT_LAYOUT, reason);
    let array = match obj.cast::<PyUntypedArray>() {
        Ok(a) if a.ndim() == shape.len() && T::is(&a.dtype()) => {
            // SAFETY: an ndarray of native `T` (`OutElement::is`) with `D`'s dimensions.
            unsafe { a.cast_unchecked::<PyArray<T, D>>() }
        }
        found => {
            let found = match found {
                Ok(a) => format!("a {}-D array of dtype {}", a.ndim(), a.dtype()),
                Err(_) => type_name(obj),
            };
            let name = at.map_or_else(|| "out".to_owned(), |k| format!("out[{k}]"));
            let message = format!("{name}: expected {expected}, got {found}");
            return Err(PyTypeError::new_err(message));
        }
    };
    if array.shape() != shape {
        let (want, got) = (shape_text(shape), shape_text(array.shape()));
        return Err(fail(&format!("expected shape {want}, got {got}")));
    }
    if !array.is_c_contiguous() || !array.is_aligned() {
        let dtype = array.dtype();
        return Err(fail(&format!(
            "expected a C-contiguous, aligned {dtype} array"
        )));
    }
    // SAFETY: a live array's header.
    let flags = unsafe { (*npyffi::_PyArray_GET_ITEM_DATA(array.as_array_ptr())).flags };
    if flags & npyffi::NPY_ARRAY_WRITEABLE == 0 {
        return Err(fail("the array is read-only"));
    }
    // SAFETY: only the addresses are looked at.
    let range = unsafe { array.as_slice() }.map_or(0..0, address_range);
    // Against the arrays as the caller gave them: an input converted to a copy (Fortran
    // order, another dtype or byte order, a strided view) must not be overwritten either.
    // Spans that overlap share memory if the input is contiguous; else numpy decides
    // (`shares_memory`: a strided input may interleave with `out` without sharing an element).
    for input in inputs.iter().flatten() {
        let (source, r) = &input.source;
        if r.start < range.end && range.start < r.end {
            let shared = source.is_c_contiguous()
                || source.is_fortran_contiguous()
                || shares_memory(source, array)?;
            if shared {
                let reason = "the array shares memory with an input";
                return Err(input_error(py, "out", at, kind::SHARED_MEMORY, reason));
            }
        }
    }
    Ok(Out(array.clone()))
}

/// `numpy.shares_memory(a, b)`: whether the two arrays have an element in common, exactly.
fn shares_memory(a: &Bound<'_, PyUntypedArray>, b: &Bound<'_, PyAny>) -> PyResult<bool> {
    let py = a.py();
    static SHARES_MEMORY: pyo3::sync::PyOnceLock<Py<PyAny>> = pyo3::sync::PyOnceLock::new();
    let f = SHARES_MEMORY.import(py, "numpy", "shares_memory")?;
    f.call1((a, b))?.is_truthy()
}

/// A caller's `out=` array, checked by [`out`] (or [`out_of`]).
pub(super) struct Out<'py, T, D>(Bound<'py, PyArray<T, D>>);

impl<'py, T: OutElement, D: Dimension> Out<'py, T, D> {
    /// A new array of `shape`, all zeros: an output of the call's own.
    pub(super) fn zeros(py: Python<'py>, shape: D) -> Self {
        Self(PyArray::zeros(py, shape, false))
    }

    /// Its elements, to be written.
    pub(super) fn values(&mut self) -> &mut [T] {
        // SAFETY: writeable, C-contiguous and aligned (checked by `out`), overlapping no
        // input; nothing else writes into it or reads it during the call: the GIL is held,
        // or the array is borrowed through the registry ([`Out::tracked`]).
        unsafe { self.0.as_slice_mut() }.unwrap_or(&mut [])
    }

    /// The addresses its elements occupy.
    pub(super) fn span(&self) -> std::ops::Range<usize> {
        // SAFETY: only the addresses are looked at.
        unsafe { self.0.as_slice() }.map_or(0..0, address_range)
    }

    /// The array borrowed for writing through rust-numpy's registry, for a call that releases
    /// the GIL (see [`track`]): refused if some rust-numpy code borrows it meanwhile.
    pub(super) fn tracked(&self) -> PyResult<PyReadwriteArray<'py, T, D>> {
        let py = self.0.py();
        self.0.try_readwrite().map_err(|_| {
            input_error(
                py,
                "out",
                None,
                kind::SHARED_MEMORY,
                "the array shares memory with an input",
            )
        })
    }

    pub(super) fn into_array(self) -> Bound<'py, PyArray<T, D>> {
        self.0
    }
}

/// The addresses a slice's elements occupy.
fn address_range<T>(values: &[T]) -> std::ops::Range<usize> {
    let r = values.as_ptr_range();
    r.start as usize..r.end as usize
}

/// An array of real numbers of any shape, and its shape (the caller checks it).
pub(super) fn shaped<'py>(
    name: &str,
    obj: &Bound<'py, PyAny>,
) -> PyResult<(Floats<'py>, Vec<usize>)> {
    let real = real_array(name, obj)?;
    let shape = real.array.shape().to_vec();
    Ok((floats(&real)?, shape))
}

/// Polynomial coefficients: a 1-D or 2-D array of real numbers, and its shape.
pub(super) fn coefficients<'py>(
    name: &str,
    obj: &Bound<'py, PyAny>,
) -> PyResult<(Floats<'py>, Vec<usize>)> {
    let real = real_array(name, obj)?;
    let shape = real.array.shape().to_vec();
    if !matches!(shape.len(), 1 | 2) {
        let reason = format!(
            "expected shape (N, k+1) with degree k = 1..4, got {}",
            shape_text(&shape)
        );
        return Err(input_error(obj.py(), name, None, kind::SHAPE, &reason));
    }
    Ok((floats(&real)?, shape))
}

/// The core's kinds of a number beyond float64's range and of a ball index out of range,
/// which the binding meets before the core does.
const NOT_FINITE: &str = crate::InputErrorKind::NotFinite(f64::INFINITY).code();
const INDEX_OUT_OF_RANGE: &str = crate::InputErrorKind::IndexOutOfRange { index: 0, len: 0 }.code();
