//! Reading a table of static objects from Python arguments: [`table_of`], the one reader of
//! the keyword arguments `segments`, `segment_sides`, `circles`, `targets` and `planes`
//! (:func:`path_geometry_times`; the calendar and :func:`simulate` take the same).
//!
//! Each object is made by its own checked constructor ([`LineSegment::new`],
//! [`SegmentSide::from_sign`], [`Circle::new`], [`Target::new`], [`Plane::new`]), so that
//! what makes an object valid is decided in one place, the core; the reader checks the
//! shapes and locates the core's errors at the object: `segments[3]: a segment's two ends
//! must differ`.

use nalgebra::{SVector, Vector2};
use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};

use numpy::{PyArrayDescrMethods, PyUntypedArray, PyUntypedArrayMethods};

use super::input_error::{from_core, input_error, kind, located_error};
use super::read::{self, Floats, shape_text};
use crate::InputError;
use crate::error::InputErrorKind;
use crate::geometry::{Circle, LineSegment, Plane, SegmentSide, Table, Target};

/// The table of static objects given by the arguments of those names, for paths in `D`
/// dimensions (2 or 3); an argument that is `None` (or left out) gives no object of its kind.
///
/// - `segments`: shape `(M, 2, 2)`, segment `m` from `P = segments[m, 0]` to
///   `Q = segments[m, 1]` (in 3-D, the vertical wall over that line);
/// - `segment_sides`: `None` (every segment touched from both sides), an int for all
///   segments, or `M` ints; each `+1` (left of `P → Q`), `−1` (right) or `0` (both);
/// - `circles`, `targets`: shape `(M, D + 1)`, rows `(cx, cy, ρ)` (in 3-D `(cx, cy, cz, ρ)`);
/// - `planes`: shape `(M, 2, D)`, rows `(point, normal)`.
///
/// An empty list (shape `(0,)`) is no object. The arrays are read as every array argument is
/// ([`read`]: any real dtype and layout); the objects are copies, so the arrays may change
/// afterwards.
///
/// # Errors
/// The arguments are checked in the order above, each whole before the next (`segment_sides`
/// after `segments`' shape, before its values): a `TypeError` naming an argument that is not
/// made of real numbers, or (`segment_sides`) of ints; an `InputError` for a wrong shape
/// (kind `shape`), a number of sides other than the segments' (`length_mismatch`), and for an
/// object's values (the first bad object, named with its index, e.g. `circles[2]: a circle's
/// radius must be ≥ 0, got -0.5`), with the core's kinds: `not_finite`,
/// `degenerate_segment`, `invalid_side`, `negative_circle_radius`,
/// `non_positive_target_radius`, `zero_normal`.
pub(super) fn table_of<const D: usize>(
    py: Python<'_>,
    segments: Option<&Bound<'_, PyAny>>,
    segment_sides: Option<&Bound<'_, PyAny>>,
    circles: Option<&Bound<'_, PyAny>>,
    targets: Option<&Bound<'_, PyAny>>,
    planes: Option<&Bound<'_, PyAny>>,
) -> PyResult<Table<D>> {
    let ends = rows(py, "segments", segments, &[2, 2], "(P, Q)")?;
    let sides = sides(py, segment_sides, ends.count)?;
    let segments = ends.each(py, "segments", |m, v| {
        LineSegment::new(Vector2::new(v[0], v[1]), Vector2::new(v[2], v[3]), sides[m])
    })?;
    let disc = if D == 3 {
        "(cx, cy, cz, rho)"
    } else {
        "(cx, cy, rho)"
    };
    let centre = |v: &[f64]| SVector::<f64, D>::from_fn(|k, _| v[k]);
    let circles = rows(py, "circles", circles, &[D + 1], disc)?
        .each(py, "circles", |_, v| Circle::new(centre(v), v[D]))?;
    let targets = rows(py, "targets", targets, &[D + 1], disc)?
        .each(py, "targets", |_, v| Target::new(centre(v), v[D]))?;
    let planes =
        rows(py, "planes", planes, &[2, D], "(point, normal)")?
            .each(py, "planes", |_, v| Plane::new(centre(v), centre(&v[D..])))?;
    Ok(Table {
        segments,
        circles,
        targets,
        planes,
    })
}

/// One kind's array of objects: `count` rows of numbers, in C order.
struct Rows<'py> {
    values: Option<Floats<'py>>,
    count: usize,
}

impl Rows<'_> {
    /// Each row made into an object by `make(m, row)`, its error located at `name[m]`.
    fn each<T>(
        &self,
        py: Python<'_>,
        name: &'static str,
        make: impl Fn(usize, &[f64]) -> Result<T, InputError>,
    ) -> PyResult<Vec<T>> {
        let values = self.values.as_ref().map_or(&[][..], Floats::values);
        let Some(width) = values.len().checked_div(self.count) else {
            return Ok(Vec::new());
        };
        values
            .chunks_exact(width)
            .enumerate()
            .map(|(m, row)| make(m, row).map_err(|e| from_core(py, e.renamed(name).at(m))))
            .collect()
    }
}

/// The array `obj` of rows of shape `row` (`None`: no row), its shape checked: `(M, *row)`,
/// or `(0,)` for none; `what` says what a row is.
fn rows<'py>(
    py: Python<'_>,
    name: &str,
    obj: Option<&Bound<'py, PyAny>>,
    row: &[usize],
    what: &str,
) -> PyResult<Rows<'py>> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(Rows {
            values: None,
            count: 0,
        });
    };
    let (values, shape) = read::shaped(name, obj)?;
    match shape.split_first() {
        Some((&count, rest)) if rest == row => Ok(Rows {
            values: Some(values),
            count,
        }),
        _ if shape == [0] => Ok(Rows {
            values: None,
            count: 0,
        }),
        _ => {
            let row: Vec<String> = row.iter().map(usize::to_string).collect();
            let (row, got) = (row.join(", "), shape_text(&shape));
            let reason = format!("expected shape (M, {row}) of rows {what}, got {got}");
            Err(input_error(py, name, None, kind::SHAPE, &reason))
        }
    }
}

/// The sides of `count` segments: all [`SegmentSide::Both`] for `None`; one int for all; or
/// a sequence of `count` ints (a list, a tuple, a 1-D integer array). Each is an int as
/// [`read::int`] reads one (a bool or a float is a `TypeError`), made a side by
/// [`SegmentSide::from_sign`].
fn sides(
    py: Python<'_>,
    obj: Option<&Bound<'_, PyAny>>,
    count: usize,
) -> PyResult<Vec<SegmentSide>> {
    const NAME: &str = "segment_sides";
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(vec![SegmentSide::Both; count]);
    };
    let array = obj.cast::<PyUntypedArray>().ok();
    let sequence = obj.is_instance_of::<PyList>()
        || obj.is_instance_of::<PyTuple>()
        || array.is_some_and(|a| a.ndim() != 0);
    if !sequence {
        return Ok(vec![side(py, None, obj)?; count]);
    }
    if let Some(array) = array {
        let dtype = array.dtype();
        // (An empty array holds no side: numpy makes `[]` float64.)
        if !matches!(dtype.kind(), b'i' | b'u') && !array.is_empty() {
            return Err(pyo3::exceptions::PyTypeError::new_err(format!(
                "{NAME}: expected ints (-1, 0 or 1), got an array of dtype {dtype}"
            )));
        }
        if array.ndim() != 1 {
            let shape = shape_text(array.shape());
            let reason = format!("expected an int or shape (M,), got shape {shape}");
            return Err(input_error(py, NAME, None, kind::SHAPE, &reason));
        }
    }
    let found = obj.len()?;
    if found != count {
        let kind = InputErrorKind::LengthMismatch {
            expected: count,
            found,
        };
        return Err(from_core(py, InputError::new(NAME, kind)));
    }
    obj.try_iter()?
        .enumerate()
        .map(|(m, item)| side(py, Some(m), &item?))
        .collect()
}

/// One segment's side (`segment_sides[m]`, or the one for all when `m` is `None`).
fn side(py: Python<'_>, m: Option<usize>, item: &Bound<'_, PyAny>) -> PyResult<SegmentSide> {
    const NAME: &str = "segment_sides";
    let label = m.map_or_else(|| NAME.to_owned(), |m| format!("{NAME}[{m}]"));
    let int = read::int(&label, item, "an int (-1, 0 or 1)")?;
    let located = |e: InputError| from_core(py, m.map_or(e, |m| e.at(m)));
    match int.extract::<i64>() {
        Ok(sign) => SegmentSide::from_sign(sign).map_err(|e| located(e.renamed(NAME))),
        // Beyond 64 bits: the core's kind, the number as Python writes it.
        Err(_) => {
            let kind = InputErrorKind::InvalidSide(0).code();
            let reason = format!("a segment's side must be -1, 0 or 1, got {int}");
            let value = int.extract::<f64>().ok();
            Err(located_error(py, NAME, [m, None], (kind, value), &reason))
        }
    }
}
