//! Stopping a long call from outside, between chunks of its work.
//!
//! [`interruptible`] runs a call with a flag that its long loops look at between chunks: a
//! batch's chunks of 1,024 pairs, a scene's rows, a calendar's balls as it is built. Once the
//! flag is set, the call stops at the next look and returns an [`InputError`] of kind
//! [`InputErrorKind::Interrupted`]; what it would have returned is lost. The Python binding
//! runs its long calls so, setting the flag when Ctrl-C arrives (its calling thread waits for
//! the call and looks for Python's signals every 50 ms), so that `KeyboardInterrupt` comes
//! within a fraction of a second.
//!
//! The flag travels with the calling thread: the batch, scene and calendar entry points read
//! it where they start, on that thread, and hand it to their worker threads.
//!
//! [`counted`] gives a call a counter in the same way: the batch calls add the items (pairs,
//! paths) of each chunk they finish to it, at the same place they look at the flag, so that
//! another thread can show how far the call has come (the Python binding's progress bars).
//!
//! ```
//! use ballcollide::batch::{self, Pairs, PerPair, Threads};
//! use ballcollide::interrupt::interruptible;
//! use ballcollide::InputErrorKind;
//! use std::sync::Arc;
//! use std::sync::atomic::AtomicBool;
//!
//! let n = 5000;
//! let (pos_a, vel_a) = (vec![[0.0, 0.0]; n], vec![[1.0, 0.0]; n]);
//! let (pos_b, vel_b) = (vec![[3.0, 0.0]; n], vec![[-1.0, 0.0]; n]);
//! let pairs = Pairs {
//!     pos_a: &pos_a, vel_a: &vel_a, friction_a: PerPair::All(0.0),
//!     pos_b: &pos_b, vel_b: &vel_b, friction_b: PerPair::All(0.0),
//!     contact_distance: PerPair::All(1.0), t_max: PerPair::All(f64::INFINITY),
//! };
//! let mut out = vec![0.0; n];
//! // A flag set before the call stops it at its first look.
//! let stop = Arc::new(AtomicBool::new(true));
//! let result = interruptible(stop, || batch::collision_times(&pairs, &mut out, Threads::All));
//! assert_eq!(result.map_err(|e| e.kind()), Err(InputErrorKind::Interrupted));
//! // Without it, the same call runs to the end.
//! batch::collision_times(&pairs, &mut out, Threads::All)?;
//! assert_eq!(out[0], 1.0); // 3 apart, closing at 2, touching at 1 apart
//! # Ok::<(), ballcollide::InputError>(())
//! ```

use std::cell::RefCell;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use crate::error::{InputError, InputErrorKind};

thread_local! {
    /// The flag of the [`interruptible`] call running on this thread, if any.
    static FLAG: RefCell<Option<Arc<AtomicBool>>> = const { RefCell::new(None) };
    /// The counter of the [`counted`] call running on this thread, if any.
    static DONE: RefCell<Option<Arc<AtomicUsize>>> = const { RefCell::new(None) };
}

/// Runs `call` on this thread with `stop` as its flag: the long loops of the batch, scene and
/// calendar calls made inside it stop between chunks once `stop` is set (by another thread),
/// and return [`InputErrorKind::Interrupted`]. Calls nest: the innermost flag counts.
pub fn interruptible<T>(stop: Arc<AtomicBool>, call: impl FnOnce() -> T) -> T {
    /// Puts the outer flag back, also when `call` panics.
    struct Restore(Option<Arc<AtomicBool>>);
    impl Drop for Restore {
        fn drop(&mut self) {
            let outer = self.0.take();
            FLAG.with(|flag| *flag.borrow_mut() = outer);
        }
    }
    let _restore = Restore(FLAG.with(|flag| flag.replace(Some(stop))));
    call()
}

/// Runs `call` on this thread with `done` as its counter: the batch calls made inside it
/// ([`collision_times`](crate::batch::collision_times), the path and table batches) and the
/// calendar's construction
/// ([`CollisionSchedule::new`](crate::schedule::CollisionSchedule::new), counting balls) add
/// the items of each chunk they finish to `done` (relaxed: read it from another thread for a
/// progress bar; it reaches the number of items when the call succeeds). Calls nest: the
/// innermost counter counts.
///
/// ```
/// use ballcollide::batch::{self, Pairs, PerPair, Threads};
/// use ballcollide::interrupt::counted;
/// use std::sync::Arc;
/// use std::sync::atomic::{AtomicUsize, Ordering};
///
/// let n = 5000;
/// let (pos_a, vel_a) = (vec![[0.0, 0.0]; n], vec![[1.0, 0.0]; n]);
/// let (pos_b, vel_b) = (vec![[3.0, 0.0]; n], vec![[-1.0, 0.0]; n]);
/// let pairs = Pairs {
///     pos_a: &pos_a, vel_a: &vel_a, friction_a: PerPair::All(0.0),
///     pos_b: &pos_b, vel_b: &vel_b, friction_b: PerPair::All(0.0),
///     contact_distance: PerPair::All(1.0), t_max: PerPair::All(f64::INFINITY),
/// };
/// let mut out = vec![0.0; n];
/// let done = Arc::new(AtomicUsize::new(0));
/// counted(Arc::clone(&done), || batch::collision_times(&pairs, &mut out, Threads::All))?;
/// assert_eq!(done.load(Ordering::Relaxed), n);
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn counted<T>(done: Arc<AtomicUsize>, call: impl FnOnce() -> T) -> T {
    with_counter(Some(done), call)
}

/// Runs `call` on this thread with no counter: what a chunk of a counted call runs (a shot's
/// calendar, say) adds nothing to the caller's count, which is of the chunk's own items.
pub(crate) fn uncounted<T>(call: impl FnOnce() -> T) -> T {
    with_counter(None, call)
}

/// Runs `call` with `done` as this thread's counter, the outer one put back after it.
fn with_counter<T>(done: Option<Arc<AtomicUsize>>, call: impl FnOnce() -> T) -> T {
    /// Puts the outer counter back, also when `call` panics.
    struct Restore(Option<Arc<AtomicUsize>>);
    impl Drop for Restore {
        fn drop(&mut self) {
            let outer = self.0.take();
            DONE.with(|done| *done.borrow_mut() = outer);
        }
    }
    let _restore = Restore(DONE.with(|outer| outer.replace(done)));
    call()
}

/// The flag of the calling thread's [`interruptible`] call and the counter of its [`counted`]
/// call, to use from any thread.
#[derive(Clone, Debug, Default)]
pub(crate) struct Interrupt {
    stop: Option<Arc<AtomicBool>>,
    done: Option<Arc<AtomicUsize>>,
}

impl Interrupt {
    /// The calling thread's flag and counter (none outside [`interruptible`] and
    /// [`counted`]).
    pub(crate) fn current() -> Self {
        Self {
            stop: FLAG.with(|flag| flag.borrow().clone()),
            done: DONE.with(|done| done.borrow().clone()),
        }
    }

    /// `Err(Interrupted)` once the flag is set.
    pub(crate) fn check(&self) -> Result<(), InputError> {
        match &self.stop {
            Some(stop) if stop.load(Ordering::Relaxed) => Err(interrupted()),
            _ => Ok(()),
        }
    }

    /// Adds `items` finished to the counter, if any.
    pub(crate) fn done(&self, items: usize) {
        if let Some(done) = &self.done {
            done.fetch_add(items, Ordering::Relaxed);
        }
    }
}

/// The error of an interrupted call.
pub(crate) fn interrupted() -> InputError {
    InputError::new("call", InputErrorKind::Interrupted)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_flag_holds_inside_the_call_only_and_nests() {
        let outer = Arc::new(AtomicBool::new(false));
        let inner = Arc::new(AtomicBool::new(true));
        assert!(Interrupt::current().check().is_ok());
        interruptible(outer, || {
            assert!(Interrupt::current().check().is_ok());
            interruptible(inner, || assert!(Interrupt::current().check().is_err()));
            assert!(Interrupt::current().check().is_ok());
        });
        assert!(Interrupt::current().check().is_ok());
    }

    #[test]
    fn the_counter_holds_inside_the_call_only_and_nests() {
        let (outer, inner) = (Arc::new(AtomicUsize::new(0)), Arc::new(AtomicUsize::new(0)));
        Interrupt::current().done(1);
        counted(Arc::clone(&outer), || {
            Interrupt::current().done(2);
            counted(Arc::clone(&inner), || Interrupt::current().done(3));
            Interrupt::current().done(4);
        });
        Interrupt::current().done(5);
        assert_eq!(outer.load(Ordering::Relaxed), 6);
        assert_eq!(inner.load(Ordering::Relaxed), 3);
    }

    #[test]
    fn nothing_is_counted_inside_uncounted_and_the_counter_comes_back() {
        let done = Arc::new(AtomicUsize::new(0));
        counted(Arc::clone(&done), || {
            uncounted(|| Interrupt::current().done(7));
            Interrupt::current().done(2);
        });
        assert_eq!(done.load(Ordering::Relaxed), 2);
    }

    #[test]
    fn a_batch_of_shots_counts_its_shots_not_their_calendars_balls() {
        // Each shot builds a calendar, which counts its balls when built under a counter.
        use crate::batch::Threads;
        use crate::billiards::{
            BallParams, BallState, BilliardTable, Cue, ShotOptions, ShotSetup, simulate_shots,
        };
        use nalgebra::Vector2;
        let table = BilliardTable::default();
        let params = [BallParams::default(); 2];
        let balls = [
            BallState::at_rest(Vector2::new(0.0, 0.0)),
            BallState::at_rest(Vector2::new(0.5, 0.0)),
        ];
        let shots: Vec<ShotSetup> = (0..8)
            .map(|k| ShotSetup {
                table: &table,
                balls: &balls,
                params: &params,
                strike: Some((
                    0,
                    Cue {
                        v0: 1.0 + 0.1 * f64::from(k),
                        ..Cue::default()
                    },
                )),
            })
            .collect();
        let one = Threads::AtMost(std::num::NonZeroUsize::MIN);
        for threads in [one, Threads::All] {
            let done = Arc::new(AtomicUsize::new(0));
            let options = ShotOptions::default();
            let all = counted(Arc::clone(&done), || {
                simulate_shots(&shots, &options, threads)
            });
            assert!(all.is_ok_and(|all| all.iter().all(Result::is_ok)));
            assert_eq!(done.load(Ordering::Relaxed), shots.len(), "{threads:?}");
        }
    }

    #[test]
    fn a_flag_set_from_another_thread_is_seen() {
        let stop = Arc::new(AtomicBool::new(false));
        let seen = interruptible(Arc::clone(&stop), || {
            let interrupt = Interrupt::current();
            std::thread::scope(|s| {
                s.spawn(|| stop.store(true, Ordering::Relaxed));
            });
            interrupt.check()
        });
        assert_eq!(seen.map_err(|e| e.kind()), Err(InputErrorKind::Interrupted));
    }
}
