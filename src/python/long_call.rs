//! How a binding runs the core's kernel: on the calling thread with the GIL (small calls),
//! without it, or without it and watched for Ctrl-C (long calls).
//!
//! A watched kernel runs on a thread of its own inside [`interruptible`]: the calling thread
//! (the one Python's signal handlers run on) waits for it and, every [`SIGNAL_CHECKS`], takes
//! the GIL for a moment to run them; the first one that raises (`KeyboardInterrupt`) sets the
//! kernel's flag, the kernel stops at its next chunk, and the call raises that exception.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::time::Duration;

use pyo3::prelude::*;

use super::input_error::from_core;
use crate::interrupt::interruptible;

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
    let result = match how {
        Kernel::Inline => kernel(),
        Kernel::Released => py.detach(kernel),
        Kernel::Watched => {
            let (result, signal) = py.detach(|| watched(kernel));
            if let Some(signal) = signal {
                return Err(signal);
            }
            result
        }
    };
    result.map_err(|e| from_core(py, e))
}

/// `kernel` on a thread of its own, the calling thread (without the GIL) running Python's
/// signal handlers every [`SIGNAL_CHECKS`] until it ends; the first error they raise stops
/// it. Its result, and that error.
fn watched<T: Send>(
    kernel: impl Send + FnOnce() -> Result<T, crate::InputError>,
) -> (Result<T, crate::InputError>, Option<PyErr>) {
    let stop = Arc::new(AtomicBool::new(false));
    let mut signal = None;
    let result = std::thread::scope(|scope| {
        let (done, finished) = mpsc::channel::<()>();
        let worker = {
            let stop = Arc::clone(&stop);
            scope.spawn(move || {
                let result = interruptible(stop, kernel);
                // The receiver lives until the join below.
                let _ = done.send(());
                result
            })
        };
        while let Err(RecvTimeoutError::Timeout) = finished.recv_timeout(SIGNAL_CHECKS) {
            if signal.is_none()
                && let Err(e) = Python::attach(|py| py.check_signals())
            {
                signal = Some(e);
                stop.store(true, Ordering::Relaxed);
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
