//! [`simulate_shots`]: many shots at once, over threads; [`shot_history`]: every ball's state
//! at every event of a shot, as pooltool records it.

use super::shot::simulate_struck;
use super::{BallParams, BallState, BilliardTable, Cue, Shot, ShotOptions, evolve};
use crate::InputError;
use crate::batch::{Threads, run_chunks_of};
use crate::interrupt::Interrupt;
use std::sync::atomic::{AtomicUsize, Ordering};

/// One shot of [`simulate_shots`]: its table, its balls (one [`BallParams`] each) and the
/// cue's strike at time 0, if any (the ball's index in `balls`, and the stroke).
#[derive(Clone, Copy, Debug)]
pub struct ShotSetup<'a> {
    /// The table it is played on.
    pub table: &'a BilliardTable,
    /// The balls' states at time 0, before the strike.
    pub balls: &'a [BallState],
    /// Each ball's parameters.
    pub params: &'a [BallParams],
    /// The strike: the ball struck and the stroke. `None`: the balls move as given.
    pub strike: Option<(usize, Cue)>,
}

/// Simulates each shot of `shots` as [`simulate_shot`](super::simulate_shot) does, with
/// `options`' models, `max_events` and contact rule (its `strike` is not read: each shot has
/// its own), on up to `threads` threads. Each shot's result is the one
/// [`simulate_shot`](super::simulate_shot) gives alone, bit for bit, whatever the number of
/// threads.
///
/// The threads take the shots one at a time, those with the most balls first (see
/// [`simulate_shots_then`]).
///
/// Inside [`interruptible`](crate::interrupt::interruptible), the flag is looked at before
/// each shot (and by each shot's calendar as it is built); inside
/// [`counted`](crate::interrupt::counted), each shot is counted as it ends.
///
/// Returns each shot's own result, in order: a shot that fails (with the error
/// [`simulate_shot`](super::simulate_shot) gives it) does not stop the others.
///
/// # Errors
/// [`InputErrorKind::Interrupted`](crate::InputErrorKind::Interrupted) once the flag is set.
///
/// ```
/// use ballcollide::batch::Threads;
/// use ballcollide::billiards::{BallParams, BallState, BilliardTable, Cue, ShotOptions, ShotSetup, simulate_shot, simulate_shots};
/// use nalgebra::Vector2;
///
/// let table = BilliardTable::default(); // no cushions, no pockets
/// let params = [BallParams::default(); 2];
/// let balls = [BallState::at_rest(Vector2::new(0.0, 0.0)), BallState::at_rest(Vector2::new(0.5, 0.0))];
/// let shots: Vec<ShotSetup> = (0..8)
///     .map(|k| ShotSetup { table: &table, balls: &balls, params: &params, strike: Some((0, Cue { v0: 1.0 + 0.1 * k as f64, ..Cue::default() })) })
///     .collect();
/// let options = ShotOptions::default();
/// let all = simulate_shots(&shots, &options, Threads::All)?;
/// let alone = simulate_shot(&table, &balls, &params, &ShotOptions { strike: shots[3].strike, ..Default::default() })?;
/// assert_eq!(all[3], Ok(alone));
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn simulate_shots(
    shots: &[ShotSetup<'_>],
    options: &ShotOptions,
    threads: Threads,
) -> Result<Vec<Result<Shot, InputError>>, InputError> {
    simulate_shots_then(shots, options, threads, |_, _, shot| shot)
}

/// [`simulate_shots`], each shot's [`Shot`] then handed to `then` (with its index in `shots`
/// and its setup) on the thread that simulated it: what a caller makes of each shot (its
/// [`shot_history`], its rows of a result array) is shared out over the threads with the
/// shots.
///
/// The threads take the shots one at a time from a shared counter until none is left, each
/// result kept at its shot's index (so that the output does not depend on which thread took
/// which shot). Shots differ in cost by tens of times (a break against a cut shot), and
/// costly ones often sit together in the list (a run of breaks): chunks fixed in advance, or
/// a splitting that hands a thread a quarter of the list at once, leave one thread with
/// them while the other idles, and a thread that starts late (on a busy machine) finds no
/// work left to share. They are taken in order of their balls, most first (a shot's events
/// grow with its balls), so that the last ones handed out are short and the threads end
/// together.
///
/// # Errors
/// As [`simulate_shots`].
pub fn simulate_shots_then<T: Send>(
    shots: &[ShotSetup<'_>],
    options: &ShotOptions,
    threads: Threads,
    then: impl Fn(usize, &ShotSetup<'_>, Shot) -> T + Sync,
) -> Result<Vec<Result<T, InputError>>, InputError> {
    let mut order: Vec<usize> = (0..shots.len()).collect();
    // Stable: shots of as many balls keep their order.
    order.sort_by_key(|&k| std::cmp::Reverse(shots[k].balls.len()));
    let next = AtomicUsize::new(0);
    // The caller's flag and counter, for the shots' threads: each shot is counted as it
    // ends (the chunks below are the threads, and count nothing themselves).
    let interrupt = Interrupt::current();
    let workers = match threads {
        Threads::All => rayon::current_num_threads(),
        Threads::AtMost(n) => n.get(),
    }
    .clamp(1, shots.len().max(1));
    let mut taken: Vec<Vec<(usize, Result<T, InputError>)>> =
        (0..workers).map(|_| Vec::new()).collect();
    run_chunks_of(
        1,
        &mut taken,
        threads,
        |_| 0,
        |_, mine| {
            for mine in mine {
                loop {
                    interrupt.check()?;
                    let Some(&k) = order.get(next.fetch_add(1, Ordering::Relaxed)) else {
                        break;
                    };
                    let s = &shots[k];
                    let result =
                        simulate_struck(s.table, s.balls, s.params, s.strike.as_ref(), options)
                            .map(|shot| then(k, s, shot));
                    mine.push((k, result));
                    interrupt.done(1);
                }
            }
            Ok(())
        },
    )?;
    let mut results: Vec<Option<Result<T, InputError>>> = shots.iter().map(|_| None).collect();
    for (k, result) in taken.into_iter().flatten() {
        results[k] = Some(result);
    }
    // Every shot was taken once no thread was interrupted.
    Ok(results
        .into_iter()
        .map(|r| r.unwrap_or_else(|| Err(crate::interrupt::interrupted())))
        .collect())
}

/// Every ball's state through a shot, as pooltool's `System` records it: `rows` has
/// `shot.events.len() + 2` rows of `balls.len()` states (row-major): row 0 the balls as given
/// (time 0, before the strike), row `k + 1` every ball just after event `k` (pooltool's ball
/// histories), the last row every ball at `shot.end` (pooltool's closing null event);
/// `before` holds, for each event in order, each of its balls' states just before it (the
/// agents' `initial` copies), in the order of the event's `balls`.
///
/// A ball an event involves has its state from the event; the others are evolved
/// ([`evolve`]) from their last event to each event's time, as pooltool evolves every ball,
/// and keep their motion state as pooltool's `_evolve` does (a ball's slide may end a
/// rounding before the collision that ends its event: its state there is still sliding).
#[derive(Clone, Debug, PartialEq)]
pub struct ShotHistory {
    /// The states, `(events + 2) × balls`, row-major.
    pub rows: Vec<BallState>,
    /// The states of each event's balls just before it, event after event.
    pub before: Vec<BallState>,
}

/// The [`ShotHistory`] of `shot`, played from `balls` with `params` (the inputs of
/// [`simulate_shot`](super::simulate_shot)); `params` as long as `balls`.
///
/// ```
/// use ballcollide::billiards::{BallParams, BallState, BilliardTable, Cue, ShotOptions, shot_history, simulate_shot};
/// use nalgebra::Vector2;
///
/// let balls = [BallState::at_rest(Vector2::new(0.0, 0.0)), BallState::at_rest(Vector2::new(0.5, 0.0))];
/// let params = [BallParams::default(); 2];
/// let options = ShotOptions { strike: Some((0, Cue::default())), ..Default::default() };
/// let shot = simulate_shot(&BilliardTable::default(), &balls, &params, &options)?;
/// let history = shot_history(&balls, &params, &shot);
/// assert_eq!(history.rows.len(), (shot.events.len() + 2) * 2);
/// assert_eq!(history.rows[..2], balls);
/// assert_eq!(history.rows[history.rows.len() - 2..], shot.states[..]);
/// assert_eq!(history.before[0], balls[0]); // the cue ball before the strike
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn shot_history(balls: &[BallState], params: &[BallParams], shot: &Shot) -> ShotHistory {
    let n = balls.len().min(params.len());
    let mut rows = Vec::with_capacity((shot.events.len() + 2) * n);
    let mut before = Vec::with_capacity(shot.events.len() * 2);
    // Each ball's last known state and its time.
    let mut last: Vec<(BallState, f64)> = balls[..n].iter().map(|b| (*b, 0.0)).collect();
    rows.extend_from_slice(&balls[..n]);
    // pooltool's `_evolve`: the state moved on, its motion state label kept (a transition
    // is an event of its own).
    let at = |(state, t0): &(BallState, f64), p: &BallParams, t: f64| {
        if t == *t0 {
            *state
        } else {
            BallState {
                motion: state.motion,
                ..evolve(state, p, t - t0)
            }
        }
    };
    for event in &shot.events {
        for (&b, after) in event.balls.iter().zip(&event.states) {
            if let (Some(l), Some(p)) = (last.get_mut(b), params.get(b)) {
                before.push(at(l, p, event.time));
                *l = (*after, event.time);
            }
        }
        for (l, p) in last.iter_mut().zip(params) {
            let now = at(l, p, event.time);
            rows.push(now);
        }
    }
    rows.extend(shot.states.iter().take(n));
    ShotHistory { rows, before }
}
