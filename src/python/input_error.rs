//! `ballcollide.InputError`: the Python exception of an invalid argument, with its parts.

use pyo3::create_exception;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

create_exception!(
    ballcollide,
    InputError,
    PyValueError,
    "An invalid argument: a bad value, shape, length or layout.\n\
     \n\
     A ``ValueError``, with the parts of its message as attributes:\n\
     \n\
     - ``argument``: the argument's name, e.g. ``\"friction_b\"``;\n\
     - ``index``: the first offending element (the pair, ball or row) as an int, or\n\
       ``None`` for a scalar argument, a whole array's shape or length, or the one path of\n\
       :func:`path_collision_time`;\n\
     - ``segment``: for a path's values (the ``start``, ``pos``, ``vel`` and ``acc``\n\
       arguments of the path functions), the offending segment as an int, else ``None``;\n\
     - ``reason``: what is wrong, e.g. ``\"friction must be ≥ 0, got -0.5\"``;\n\
     - ``kind``: what is wrong as a stable name to branch on, e.g.\n\
       ``\"negative_friction\"`` (the list: docs/contract.md, section 6);\n\
     - ``value``: the offending number as a float, where there is one, else ``None``.\n\
     \n\
     ``str(e)`` is ``f\"{argument}[{index}]: {reason}\"``, ``f\"{argument}[{index},\n\
     {segment}]: {reason}\"`` for pair (or path) ``index``'s segment ``segment``,\n\
     ``f\"{argument}[{segment}]: {reason}\"`` for a segment of a single path, or\n\
     ``f\"{argument}: {reason}\"`` without either.\n\
     \n\
     >>> import ballcollide as bc\n\
     >>> try:\n\
     ...     bc.collision_times([[0, 0]] * 3, [[1, 0]] * 3, 0.0, [[1, 0]] * 3, [[0, 0]] * 3,\n\
     ...                        [0.1, 0.1, -0.5], 0.5)\n\
     ... except bc.InputError as e:\n\
     ...     print(e.argument, e.index, e.reason, e.kind, e.value, sep=\" | \")\n\
     friction_b | 2 | friction must be ≥ 0, got -0.5 | negative_friction | -0.5\n\
     >>> try:\n\
     ...     bc.path_positions_at([[0, 2, 1]], [[[0, 0]] * 3], [[[1, 0]] * 3], [[[0, 0]] * 3], 0)\n\
     ... except bc.InputError as e:\n\
     ...     print(e, e.index, e.segment, sep=\" | \")\n\
     start[0, 2]: starts must not decrease, got 1 after 2 | 0 | 2\n"
);

/// The kinds of what the binding checks itself, beside the core's
/// ([`crate::InputErrorKind::code`]).
pub(super) mod kind {
    /// An array (or scalar) of the wrong shape, or an argument of the wrong structure.
    pub(in crate::python) const SHAPE: &str = "shape";
    /// An array-like numpy cannot read as numbers (ragged lists, objects).
    pub(in crate::python) const NOT_NUMBERS: &str = "not_numbers";
    /// An int outside its range (`num_threads < 1`, `max_events < 0`).
    pub(in crate::python) const OUT_OF_RANGE: &str = "out_of_range";
    /// An `out=` array of the wrong dtype, layout or shape, or read-only.
    pub(in crate::python) const OUT_LAYOUT: &str = "out_layout";
    /// An `out=` array sharing memory with an input.
    pub(in crate::python) const SHARED_MEMORY: &str = "shared_memory";
}

/// An [`InputError`] of `kind` about `argument` (at `index`, if any), with its attributes
/// set.
pub(super) fn input_error(
    py: Python<'_>,
    argument: &str,
    index: Option<usize>,
    kind: &str,
    reason: &str,
) -> PyErr {
    located_error(py, argument, [index, None], (kind, None), reason)
}

/// An [`InputError`] about `argument` at `[index, segment]` (either or both may be absent: a
/// segment of a single path has no index), of `kind` with the offending `value` if any, with
/// its attributes set.
pub(super) fn located_error(
    py: Python<'_>,
    argument: &str,
    [index, segment]: [Option<usize>; 2],
    (kind, offending): (&str, Option<f64>),
    reason: &str,
) -> PyErr {
    let message = match (index, segment) {
        (Some(i), Some(k)) => format!("{argument}[{i}, {k}]: {reason}"),
        (Some(i), None) | (None, Some(i)) => format!("{argument}[{i}]: {reason}"),
        (None, None) => format!("{argument}: {reason}"),
    };
    let err = InputError::new_err(message);
    let value = err.value(py);
    let set = value
        .setattr(pyo3::intern!(py, "argument"), argument)
        .and_then(|()| value.setattr(pyo3::intern!(py, "index"), index))
        .and_then(|()| value.setattr(pyo3::intern!(py, "segment"), segment))
        .and_then(|()| value.setattr(pyo3::intern!(py, "reason"), reason))
        .and_then(|()| value.setattr(pyo3::intern!(py, "kind"), kind))
        .and_then(|()| value.setattr(pyo3::intern!(py, "value"), offending));
    match set {
        Ok(()) => err,
        Err(e) => e,
    }
}

/// The core's [`crate::InputError`] as Python's: the same message, and its parts.
pub(super) fn from_core(py: Python<'_>, e: crate::InputError) -> PyErr {
    located_error(
        py,
        e.argument(),
        [e.index(), e.segment()],
        (e.kind().code(), e.kind().value()),
        &e.kind().to_string(),
    )
}
