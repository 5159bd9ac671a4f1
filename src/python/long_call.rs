//! How a binding runs the core's kernel: on the calling thread with the GIL (small calls),
//! without it, or without it and watched for Ctrl-C (long calls).
//!
//! A watched kernel runs on a thread of its own inside [`interruptible`]: the calling thread
//! (the one Python's signal handlers run on) waits for it and, every [`SIGNAL_CHECKS`], takes
//! the GIL for a moment to run them; the first one that raises (`KeyboardInterrupt`) sets the
//! kernel's flag, the kernel stops at its next chunk, and the call raises that exception.
//!
//! Progress bars (`progress=`) are moved on from the same place, at the same moments: the
//! kernel adds the items of each chunk it finishes to a counter
//! ([`counted`](crate::interrupt::counted)), and the watching thread, holding the GIL for
//! its look for signals, moves the bar on to the count ([`Progress`]; `simulate`, which runs
//! on the calling thread, shows its own count at its own looks through the same type).

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::time::Duration;

use pyo3::exceptions::{PyImportError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{IntoPyDict, PyBool};

use super::input_error::from_core;
use crate::interrupt::{counted, interruptible};

/// How often a long call looks for Ctrl-C (Python's signal handlers).
pub(crate) const SIGNAL_CHECKS: Duration = Duration::from_millis(50);

/// Items (pairs, polynomials, balls) up to which a call runs on the calling thread holding
/// the GIL: releasing and retaking it, or waking a thread pool, would cost more than the work
/// (a few µs at most). The answers do not depend on it.
pub(crate) const INLINE_UP_TO: usize = 1024;

/// Items from which a call is watched for Ctrl-C: about a millisecond of work and more, where
/// the watcher's thread (some 20 µs to start) is lost in the work.
pub(crate) const WATCHED_FROM: usize = 1 << 15;

/// How a call's kernel runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Kernel {
    /// On the calling thread, holding the GIL.
    Inline,
    /// On the calling thread, the GIL released.
    Released,
    /// On a thread of its own, the GIL released, the calling thread watching for Ctrl-C.
    Watched,
}

impl Kernel {
    /// For a call over `items` whose work grows with them, run inline up to `inline_up_to`.
    pub(crate) fn for_items(items: usize, inline_up_to: usize) -> Self {
        if items <= inline_up_to {
            Self::Inline
        } else if items < WATCHED_FROM {
            Self::Released
        } else {
            Self::Watched
        }
    }
}

/// Runs `kernel` as `how` says, and maps its error (a Ctrl-C while it ran raises
/// `KeyboardInterrupt`, whatever the kernel returned).
pub(crate) fn run<T: Send>(
    py: Python<'_>,
    how: Kernel,
    kernel: impl Send + FnOnce() -> Result<T, crate::InputError>,
) -> PyResult<T> {
    run_shown(py, how, None, kernel)
}

/// [`run`], moving `progress` on (if any) as the kernel's chunks finish, and closing it at
/// the end (also on error). A call with a bar is watched, whatever its size.
pub(crate) fn run_shown<T: Send>(
    py: Python<'_>,
    how: Kernel,
    progress: Option<Progress>,
    kernel: impl Send + FnOnce() -> Result<T, crate::InputError>,
) -> PyResult<T> {
    let result = match (how, progress) {
        (Kernel::Inline, None) => kernel(),
        (Kernel::Released, None) => py.detach(kernel),
        (_, mut progress) => {
            let done = Arc::new(AtomicUsize::new(0));
            let (result, signal) = py.detach(|| watched(kernel, &done, progress.as_mut()));
            let closed = match progress {
                Some(p) => p.close(py, done.load(Ordering::Relaxed), None),
                None => Ok(()),
            };
            if let Some(signal) = signal {
                return Err(signal);
            }
            closed?;
            result
        }
    };
    result.map_err(|e| from_core(py, e))
}

/// `kernel` on a thread of its own, counting into `done`, the calling thread (without the
/// GIL) running Python's signal handlers, and moving `progress` on to `done`, every
/// [`SIGNAL_CHECKS`] until it ends; the first error they raise stops it. Its result, and that
/// error.
fn watched<T: Send>(
    kernel: impl Send + FnOnce() -> Result<T, crate::InputError>,
    done: &Arc<AtomicUsize>,
    mut progress: Option<&mut Progress>,
) -> (Result<T, crate::InputError>, Option<PyErr>) {
    let stop = Arc::new(AtomicBool::new(false));
    let mut signal = None;
    let result = std::thread::scope(|scope| {
        let (finished_tx, finished) = mpsc::channel::<()>();
        let worker = {
            let stop = Arc::clone(&stop);
            let done = Arc::clone(done);
            scope.spawn(move || {
                let result = interruptible(stop, || counted(done, kernel));
                // The receiver lives until the join below.
                let _ = finished_tx.send(());
                result
            })
        };
        while let Err(RecvTimeoutError::Timeout) = finished.recv_timeout(SIGNAL_CHECKS) {
            if signal.is_none() {
                let count = done.load(Ordering::Relaxed);
                let looked = Python::attach(|py| look(py, progress.as_deref_mut(), count, None));
                if let Err(e) = looked {
                    signal = Some(e);
                    stop.store(true, Ordering::Relaxed);
                }
            }
        }
        match worker.join() {
            Ok(result) => result,
            // The kernel's panic, on the calling thread (pyo3 turns it into PanicException).
            Err(panic) => std::panic::resume_unwind(panic),
        }
    });
    (result, signal)
}

/// A long call's look at Python while it runs: the signal handlers (Ctrl-C), then the bar
/// moved on to `done` items (and the simulation's `time`, if given). The first error raised.
pub(crate) fn look(
    py: Python<'_>,
    progress: Option<&mut Progress>,
    done: usize,
    time: Option<f64>,
) -> PyResult<()> {
    py.check_signals()?;
    match progress {
        Some(p) => p.show(py, done, time),
        None => Ok(()),
    }
}

/// What `progress=` shows a long call's progress on.
enum Bar {
    /// A ``tqdm`` bar or one like it: ``update(n)``, ``close()``, and ``set_postfix(**values)``
    /// if it has it (`true`).
    Object(Py<PyAny>, bool),
    /// A callable, called with the number of items finished since its last call.
    Callable(Py<PyAny>),
}

/// A long call's progress bar, and the items it has shown.
pub(crate) struct Progress {
    bar: Bar,
    shown: usize,
}

impl Progress {
    /// The bar `progress` asks for, for a call of `total` items (unknown if `None`) named
    /// `unit` (for tqdm): none for `None` or `False`; for `True`, a `tqdm` bar (an
    /// `ImportError` naming `progress` if tqdm is not installed); an object with `update`
    /// and `close` (a tqdm bar of the caller's); else a callable. Any other value is a
    /// `TypeError` naming `progress`.
    pub(crate) fn of(
        py: Python<'_>,
        progress: Option<&Bound<'_, PyAny>>,
        total: Option<usize>,
        unit: &str,
    ) -> PyResult<Option<Self>> {
        let Some(progress) = progress.filter(|p| !p.is_none()) else {
            return Ok(None);
        };
        let bar = if let Ok(flag) = progress.cast::<PyBool>() {
            if !flag.is_true() {
                return Ok(None);
            }
            let tqdm = py.import("tqdm").map_err(|_| {
                PyImportError::new_err("progress: progress=True needs tqdm (pip install tqdm)")
            })?;
            let kwargs = [
                ("total", total.into_pyobject(py)?.into_any()),
                ("unit", unit.into_pyobject(py)?.into_any()),
            ];
            let bar = tqdm
                .getattr("tqdm")?
                .call((), Some(&kwargs.into_py_dict(py)?))?;
            Bar::Object(bar.unbind(), true)
        } else if progress.hasattr("update")? {
            if !progress.hasattr("close")? {
                return Err(PyTypeError::new_err(
                    "progress: expected a tqdm-like bar with update and close, got an object \
                     without close",
                ));
            }
            Bar::Object(progress.clone().unbind(), progress.hasattr("set_postfix")?)
        } else if progress.is_callable() {
            Bar::Callable(progress.clone().unbind())
        } else {
            return Err(PyTypeError::new_err(format!(
                "progress: expected True, False, None, a tqdm-like bar (with update and close) \
                 or a callable, got {}",
                progress
                    .get_type()
                    .name()
                    .map_or_else(|_| "another type".to_owned(), |n| n.to_string())
            )));
        };
        Ok(Some(Self { bar, shown: 0 }))
    }

    /// Moves the bar on to `done` items (and shows `time` beside it, if given and the bar
    /// takes a postfix). Nothing is called when there is nothing to show.
    pub(crate) fn show(&mut self, py: Python<'_>, done: usize, time: Option<f64>) -> PyResult<()> {
        let new = done.saturating_sub(self.shown);
        if new == 0 && time.is_none() {
            return Ok(());
        }
        match &self.bar {
            Bar::Object(bar, postfix) => {
                let bar = bar.bind(py);
                if let (Some(time), true) = (time, postfix) {
                    let values = [
                        ("t", time.into_pyobject(py)?.into_any()),
                        ("refresh", false.into_pyobject(py)?.to_owned().into_any()),
                    ];
                    bar.call_method("set_postfix", (), Some(&values.into_py_dict(py)?))?;
                }
                bar.call_method1("update", (new,))?;
            }
            Bar::Callable(f) if new > 0 => {
                f.bind(py).call1((new,))?;
            }
            Bar::Callable(_) => {}
        }
        self.shown = done;
        Ok(())
    }

    /// Shows the last items (`done` in all) and the end `time` (if given and finite), then
    /// closes the bar (a bar object's `close`).
    pub(crate) fn close(mut self, py: Python<'_>, done: usize, time: Option<f64>) -> PyResult<()> {
        self.show(py, done, time.filter(|t| t.is_finite()))?;
        if let Bar::Object(bar, _) = &self.bar {
            bar.bind(py).call_method0("close")?;
        }
        Ok(())
    }
}
