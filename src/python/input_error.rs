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
       ``None`` for a scalar argument or a whole array's shape or length;\n\
     - ``reason``: what is wrong, e.g. ``\"friction must be ≥ 0, got -0.5\"``.\n\
     \n\
     ``str(e)`` is ``f\"{argument}[{index}]: {reason}\"``, or ``f\"{argument}: {reason}\"``\n\
     without an index.\n\
     \n\
     >>> import ballcollide as bc\n\
     >>> try:\n\
     ...     bc.collision_times([[0, 0]] * 3, [[1, 0]] * 3, 0.0, [[1, 0]] * 3, [[0, 0]] * 3,\n\
     ...                        [0.1, 0.1, -0.5], 0.5)\n\
     ... except bc.InputError as e:\n\
     ...     print(e.argument, e.index, e.reason, sep=\" | \")\n\
     friction_b | 2 | friction must be ≥ 0, got -0.5\n"
);

/// An [`InputError`] about `argument` (at `index`, if any), with its attributes set.
pub(super) fn input_error(
    py: Python<'_>,
    argument: &str,
    index: Option<usize>,
    reason: &str,
) -> PyErr {
    let message = match index {
        Some(i) => format!("{argument}[{i}]: {reason}"),
        None => format!("{argument}: {reason}"),
    };
    let err = InputError::new_err(message);
    let value = err.value(py);
    let set = value
        .setattr(pyo3::intern!(py, "argument"), argument)
        .and_then(|()| value.setattr(pyo3::intern!(py, "index"), index))
        .and_then(|()| value.setattr(pyo3::intern!(py, "reason"), reason));
    match set {
        Ok(()) => err,
        Err(e) => e,
    }
}

/// The core's [`crate::InputError`] as Python's: the same message, and its parts.
pub(super) fn from_core(py: Python<'_>, e: crate::InputError) -> PyErr {
    input_error(py, e.argument(), e.index(), &e.kind().to_string())
}
