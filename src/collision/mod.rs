//! When two balls first touch: [`collision_time`] (friction balls) and
//! [`path_collision_time`] (balls on paths of constant-acceleration segments).
//!
//! ## The map
//!
//! Every query goes through the same stages, in this order; each stage is one file and one
//! name, and the scalar queries, the batches (`crate::batch`) and the scene
//! (`crate::scene`) call the same function for it, so that all give the same bits.
//!
//! | stage | file | what it proves or does | who calls it |
//! |---|---|---|---|
//! | unit of length | `length_unit.rs` | divides every length of a pair by one power of two (exact), so that no answer depends on the unit | every friction-ball query, its batch lanes (`batch/prefilter_lanes.rs`); every path window (the path bounds work on the caller's numbers, with a margin for underflow) |
//! | **friction balls** | | | |
//! | prefilter | `prefilter.rs`; lane-wise, `batch/prefilter_lanes.rs` | the balls' straight runs to rest stay apart: never a contact | `collision_time`, scene, batch lanes (with the unit of length) |
//! | crossing | `crossing.rs` | moving balls whose runs cross are never there at the same time | `collision_time`, scene, batch lanes (a loop over the lanes: `apart_by_window`) |
//! | straight | `straight.rs` (`first_contact`, `contact`) | one ball at rest: the contact in closed form | `collision_time`, scene, batch lanes |
//! | moving entry | `moving_entry.rs`; lane-wise, `batch/moving_entry_lanes.rs` | both moving, an isolated crossing in the first window: the contact by the eighth entry below, cut by the horizon | `collision_time`, scene, batch lanes |
//! | after stop | `after_stop.rs` | after the first stop, the mover against a ball at rest: closed form | `collision_time`, scene, batch lanes |
//! | **paths** | | | |
//! | path bounds | `path_bounds.rs`; lane-wise, `batch/path_lanes.rs` | the boxes the two centres stay in along their whole paths are apart: never a contact | `path_collision_time`, `path_collision_times` (a broadcast path's bounds once per batch; rows of 2 and 3 segments eight pairs at a time, lane-wise, at the SIMD levels that run the lane stages, the same proof to the bit); not for two paths of one segment each, whose one window goes straight to the window's stages |
//! | chord normals | `chord_normals.rs` | on the normal of either path's chord (from where its ball starts to where it rests), the two paths' spans are apart: never a contact | `path_collision_time`, `path_collision_times`, after the path bounds (lane-wise with them in `batch/path_lanes.rs`) |
//! | segment boxes | `path_bounds.rs` (`segments_apart`) | the boxes of the two segments active on a window (kept with the path bounds) are apart: no contact on the window, and no motion formed | path windows |
//! | path contact | `path_contact.rs` | the window loop: windows between segment starts of either path, each formed from the two active segments in time since their own starts | `path_collision_time`, `path_collision_times` |
//! | (counts) | `stage_counts.rs` | how many pairs and windows each path stage settles (cargo feature `stage-counts`) | the benchmarks |
//! | window box | `window_box.rs` | the box the separation sweeps over one window keeps out of the contact distance | path windows; pieces of long windows |
//! | window chord | `window_chord.rs` | across the chord of the separation's run over one window, its span keeps out of the contact distance on one side | path windows, after the window box (not the calendar's pair searches, where it costs more than it saves) |
//! | (window lanes) | `batch/window_lanes.rs` | the three window screens above on every window of a pair at once, eight pairs at a time: no window of the pair can hold a contact | `path_collision_times` at the SIMD levels that run the lane stages, for the pairs of rows of 2 and 3 segments that the whole-path lanes leave |
//! | straight window | `straight.rs` (`straight_window`) | a window without relative acceleration: the separation runs along a line at constant speed, the entry in closed form where clear | path windows |
//! | **every window that is left** | | | |
//! | eighth entry | `eighth_entry.rs`; lane-wise, `batch/eighth_lanes.rs` (`window_eighth`) | a window whose first open eighth is isolated (one root, or one dip): its entry, or none, by fixed Newton steps, branch-free; a path window with every eighth proven positive: none | `moving_entry`; path windows, before the window search (`window_eighth`); the first-window lanes below |
//! | (first-window lanes) | `batch/first_window_lanes.rs` | the eighth entry (`batch/eighth_lanes.rs`) on the first windows of the pairs the lanes above take and leave, eight at a time: the pair's contact, or its first window screened out (the walk starts after it) | `path_collision_times` at the SIMD levels that run the lane stages, rows of 2 and 3 segments |
//! | parting | `parting.rs` | a window on which the distance grows throughout (a pair just after its collision, touching and parting): no entry, by one Bernstein bound of `d·d′` | `eighth_then_search`, for the windows the eighth leaves (before it, for windows that start touching), before the window search |
//! | window search | `mod.rs` (`search_window`) | time scaled to the window, the first entry found by the stages below | friction windows, path windows |
//! | long window | `long_window.rs` | windows far longer than the motion's time scale, in pieces, each proven apart or searched | `search_window`; `crossing` (which leaves long windows to the search) |
//! | exclusion | `exclusion.rs` | Bernstein bounds of the gap quartic: pieces of a window with no contact, and the shape of the rest | `entry` (for `search_window`), `crossing`, `moving_entry` |
//! | entry | `entry.rs` | the first + → − sign change on the pieces left: critical points, bracketed Newton | `search_window` |
//! | narrow dip | `narrow_dip.rs` | a dip whose float samples stay positive, the radius tiny beside the motion (`≤ 2⁻⁴⁰`): a contact if the closest approach, `|d × d′|/|d′|` from the cross product's own coefficients, is within the radius | `entry` (its dips and minima); `eighth_entry` only declines to call such a dip a miss |
//!
//! A stage's lane twin sits in `crate::batch`, beside the batch that runs it, written over the
//! SIMD layer's `Simd` ([`crate::simd`]) with the scalar stage's operations in the scalar
//! stage's order. The friction balls' batch lanes (`prefilter`, `crossing`, `moving_entry`,
//! `after_stop`, `straight`) run at every SIMD level (portable, AVX2 with FMA, AVX-512, NEON):
//! the prefilter's over `Simd`, the others as loops over the lanes that call the scalar stage,
//! vectorised by the compiler inside the level's shim. The path lanes
//! (`batch/path_lanes.rs`, `batch/window_lanes.rs`, `batch/first_window_lanes.rs` with
//! `batch/eighth_lanes.rs`) are compiled and tested at every level but run only where the
//! vectors hold four or more lanes (AVX2 with FMA, AVX-512: `Simd::RUNS_LANE_STAGES`); at the
//! portable and NEON levels those pairs go one by one, to the same bits.
//!
//! The gap `g(t) = |x_A(t) − x_B(t)|² − σ²` (`σ` the contact distance; see [`Gap`]) is a
//! quartic on each window; it is never divided by its leading coefficient, so equal or nearly
//! equal friction vectors (where it vanishes or nearly so) need no special case.
//!
//! ## Semantics (SPEC)
//! - touching or overlapping at `t = 0` is a collision at `0` only if the balls approach
//!   (`d·d′ < 0`, or `d·d′ = 0` with the gap shrinking at second order, `|d′|² + d·d″ < 0`);
//!   overlapping balls that separate (as right after a resolved collision) collide only on a
//!   later re-entry;
//! - exact tangency (the gap touches zero and grows again) is not a collision;
//! - a contact shallower than about 1e-13 of the radius is beyond what float64 inputs decide
//!   (the gap's minimum is then within rounding of zero): either answer may come back.

pub(crate) mod after_stop;
pub(crate) mod chord_normals;
pub(crate) mod crossing;
pub(crate) mod eighth_entry;
mod entry;
pub(crate) mod exclusion;
pub(crate) mod length_unit;
pub(crate) mod long_window;
pub(crate) mod moving_entry;
pub(crate) mod narrow_dip;
pub(crate) mod parting;
pub(crate) mod path_bounds;
pub(crate) mod path_contact;
pub(crate) mod prefilter;
pub mod stage_counts;
pub(crate) mod straight;
pub(crate) mod window_box;
pub(crate) mod window_chord;

use crate::error::{InputError, check_contact_distance, check_horizon};
use crate::gap::{Gap, gap_value_of};
use crate::motion::Ball;
use crate::poly::scaling::{exponent, pow2};
use crate::simd::fraction_cleared;
use after_stop::after_first_stop;
use crossing::apart_by_window;
use eighth_entry::window_eighth;
use entry::{WindowSearch, first_entry, piecewise_entry};
use length_unit::{LengthUnit, largest, normalised_balls};
use long_window::{first_piece, long_window, next_piece, short_piece};
use moving_entry::{WhileMoving, while_moving_one};
use nalgebra::SVector;
use parting::parting_window;
pub use path_contact::path_collision_time;
#[doc(hidden)]
pub use path_contact::path_collision_time_unscreened;
use prefilter::{PairInput, screened_out_by_runs};
use window_box::apart_on_window;

/// Options of a collision query ([`collision_time_with`]).
///
/// ```
/// use ballcollide::CollisionOptions;
/// let options = CollisionOptions { t_max: 2.0, ..Default::default() };
/// assert_eq!(CollisionOptions::default().t_max, f64::INFINITY);
/// # let _ = options;
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CollisionOptions {
    /// The horizon: a collision at `t ≥ t_max` is reported as none. Default `∞`.
    pub t_max: f64,
}

impl Default for CollisionOptions {
    fn default() -> Self {
        Self {
            t_max: f64::INFINITY,
        }
    }
}

/// The time at which `a` and `b` first touch (their centres `contact_distance` apart, the sum
/// of their radii), or `None` if they never do.
///
/// # Errors
/// `contact_distance` must be finite and positive.
///
/// ```
/// use ballcollide::{Ball, collision_time};
/// use nalgebra::Vector2;
///
/// // A cue ball shot at 2 m/s straight at a ball 1 m away, slowed at 0.2 m/s².
/// let cue = Ball::new(Vector2::new(0.0, 0.0), Vector2::new(2.0, 0.0), 0.2)?;
/// let target = Ball::at_rest(Vector2::new(1.0, 0.0))?;
/// let t = collision_time(&cue, &target, 0.05715)?.expect("they collide");
/// // It covers 1 − 0.05715 m: 2t − 0.1t² = 0.94285.
/// assert!((2.0 * t - 0.1 * t * t - 0.94285).abs() < 1e-15);
///
/// // The same shot aimed 0.1 m to the side misses.
/// let aside = Ball::at_rest(Vector2::new(1.0, 0.1))?;
/// assert_eq!(collision_time(&cue, &aside, 0.05715)?, None);
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn collision_time(
    a: &Ball,
    b: &Ball,
    contact_distance: f64,
) -> Result<Option<f64>, InputError> {
    collision_time_with(a, b, contact_distance, &CollisionOptions::default())
}

/// [`collision_time`] with options, such as a horizon `t_max`.
///
/// # Errors
/// `contact_distance` must be finite and positive, `t_max` must be ≥ 0 (`∞` allowed).
///
/// ```
/// use ballcollide::{Ball, CollisionOptions, collision_time_with};
/// use nalgebra::Vector2;
///
/// let a = Ball::new(Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), 0.0)?;
/// let b = Ball::at_rest(Vector2::new(2.0, 0.0))?;
/// let soon = CollisionOptions { t_max: 1.0 };
/// assert_eq!(collision_time_with(&a, &b, 0.5, &soon)?, None); // contact at 1.5 s
/// let later = CollisionOptions { t_max: 2.0 };
/// assert_eq!(collision_time_with(&a, &b, 0.5, &later)?, Some(1.5));
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn collision_time_with(
    a: &Ball,
    b: &Ball,
    contact_distance: f64,
    options: &CollisionOptions,
) -> Result<Option<f64>, InputError> {
    let radius = check_contact_distance("contact_distance", contact_distance)?;
    let t_max = check_horizon("t_max", options.t_max)?;
    Ok(first_contact_screened(a, b, [radius, 0.0], t_max))
}

/// [`first_contact`] after the batch's proofs that the balls never touch ([`screened_out_by_runs`],
/// [`apart_by_window`]): a pair they settle is one the search answers "none" for too (their
/// margins see to it), found for a fraction of the cost; and the same answer as a batch's,
/// bit for bit, either way. The contact distance is the sum of `radii` (formed in the pair's
/// unit of length, where it cannot overflow).
pub(crate) fn first_contact_screened(
    a: &Ball,
    b: &Ball,
    radii: [f64; 2],
    t_max: f64,
) -> Option<f64> {
    // The pair query's own contact distance, `r_a + r_b` rounded, wherever it is finite (so
    // that a scene's pair gives the bits of `collision_time` with that radius); the sum is
    // formed in the pair's unit only where it overflows.
    let sum = radii[0] + radii[1];
    let radii = if sum.is_finite() { [sum, 0.0] } else { radii };
    let (a, b, radius) = normalised_balls(a, b, radii);
    let (a, b) = (&a, &b);
    let pair = PairInput::of(a, b, radius, t_max);
    // One ball at rest: the closed form is cheaper than the proofs.
    let one_at_rest = a.is_at_rest() != b.is_at_rest();
    let both_moving = !a.is_at_rest() && !b.is_at_rest();
    if !one_at_rest && screened_out_by_runs(&pair) {
        return None;
    }
    if both_moving && apart_by_window(&pair) == (true, true) {
        return None;
    }
    first_contact_in_unit(a, b, radius, t_max, None)
}

/// The search itself, on inputs already validated (`radius > 0` finite, `t_max ≥ 0`).
#[cfg(test)]
pub(crate) fn first_contact(a: &Ball, b: &Ball, radius: f64, t_max: f64) -> Option<f64> {
    first_contact_given(a, b, radius, t_max, None)
}

/// [`first_contact`], given what [`while_moving_one`](moving_entry::while_moving_one) found for the
/// pair if the caller (a batch, lane-wise) has run it already: the search takes the same
/// steps either way.
pub(crate) fn first_contact_given(
    a: &Ball,
    b: &Ball,
    radius: f64,
    t_max: f64,
    moving: Option<WhileMoving>,
) -> Option<f64> {
    let (a, b, radius) = normalised_balls(a, b, [radius, 0.0]);
    first_contact_in_unit(&a, &b, radius, t_max, moving)
}

/// The search on a pair already in its own unit of length ([`length_unit`]).
fn first_contact_in_unit(
    a: &Ball,
    b: &Ball,
    radius: f64,
    t_max: f64,
    moving: Option<WhileMoving>,
) -> Option<f64> {
    let initial = Gap::between(a, b, radius, 0.0);
    let g0 = initial.value(0.0);
    // Apart or not at the start, on numbers that cannot underflow (the pair's unit of length
    // is chosen from speeds and frictions too, and beside a far larger one the squares of the
    // distance and the radius may): the same sign as `g0` wherever `g0` is exact.
    let apart = apart_at_start(&initial);
    if !apart && approaching(&initial) {
        return (t_max > 0.0).then_some(0.0);
    }
    if let Some(answer) = straight::first_contact(a, b, radius, t_max, g0) {
        return answer;
    }
    // The first window settled where its first open eighth is isolated (as a batch does it
    // lane-wise).
    let moving = moving.unwrap_or_else(|| while_moving_one(&PairInput::of(a, b, radius, t_max)));
    if !moving.entry.is_nan() {
        return moving.entry.is_finite().then_some(moving.entry);
    }
    let (t1, t2) = {
        let (ta, tb) = (a.stop_time(), b.stop_time());
        (ta.min(tb), ta.max(tb))
    };
    // With no contact in the first window, the balls are apart at its end.
    let mut previous_positive = apart || moving.screened_out;
    let windows = [(0.0, t1), (t1, t2), (t2, f64::INFINITY)];
    for (start, end) in windows.into_iter().skip(usize::from(moving.screened_out)) {
        // Windows are searched whole, whatever the horizon, which only cuts the answer: a
        // contact before it comes back bit for bit as without it.
        if start >= t_max {
            break;
        }
        if end <= start {
            continue;
        }
        // From the first stop on, one ball rests: the closed form, where it applies.
        if start == t1 && start > 0.0 {
            let (applies, t) = after_first_stop(a, b, radius, t_max);
            if applies {
                return t.is_finite().then_some(t);
            }
        }
        let gap = if start == 0.0 {
            initial
        } else {
            Gap::between(a, b, radius, start)
        };
        let (found, _) = eighth_then_search(&gap, end - start, previous_positive);
        match found {
            WindowSearch::Entry(s) => {
                let t = start + s;
                return (t < t_max).then_some(t);
            }
            WindowSearch::NoEntry { ends_positive } => previous_positive = ends_positive,
        }
    }
    None
}

/// A window's first entry: its first open eighth first, then (balls parting throughout the
/// window, [`parting_window`]) none, then the window search; a window that starts with the
/// balls touching tries the parting bound before the eighth. An entry isolated on the eighth
/// is settled by Newton steps to the floor of its own time, where the search's steps are
/// sized by the window (a contact at 2⁻²² of the window's length, at a radius of 2⁻⁵² of the
/// distance, came 85 floors late). Both pair queries search their windows here, so they take
/// the same steps on one pair. Also which of the three settled it.
#[inline(always)]
pub(crate) fn eighth_then_search<const D: usize>(
    gap: &Gap<D>,
    length: f64,
    previous_positive: bool,
) -> (WindowSearch, SettledBy) {
    let bounded = bounded_length(gap, length);
    // A window that starts with the balls touching (within 2⁻¹⁰ of the contact distance's
    // square: a pair searched again from its collision) has a root at its first eighth's
    // start, which the eighth cannot isolate: the parting bound goes first. (Both prove what
    // they settle, so their order changes no answer.)
    let r2 = gap.contact_distance * gap.contact_distance;
    let touching = (gap.offset.norm_squared() - r2).abs() <= r2 * (1.0 / 1024.0);
    if touching && let Some(none) = parting_window(gap, bounded, previous_positive) {
        return (none, SettledBy::Parting);
    }
    let eighth = window_eighth(gap, bounded, previous_positive);
    if eighth.found {
        (WindowSearch::Entry(eighth.entry), SettledBy::Eighth)
    } else if eighth.screened_out {
        let none = WindowSearch::NoEntry {
            ends_positive: true,
        };
        (none, SettledBy::Eighth)
    } else if !touching && let Some(none) = parting_window(gap, bounded, previous_positive) {
        (none, SettledBy::Parting)
    } else {
        (
            search_window(gap, length, previous_positive),
            SettledBy::Search,
        )
    }
}

/// Which stage of [`eighth_then_search`] settled a window (for the stage counts).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum SettledBy {
    /// The first open eighth ([`window_eighth`]).
    Eighth,
    /// The distance growing throughout ([`parting_window`]).
    Parting,
    /// The window search.
    Search,
}

/// Whether the balls are apart at the window's start (`g(0) > 0`), decided in the unit of
/// the larger of the distance and the radius. Inlined, so that the vector and FMA copies of
/// the searches that call it form its fused products in hardware, not by a library call.
#[inline(always)]
pub(crate) fn apart_at_start<const D: usize>(gap: &Gap<D>) -> bool {
    let unit = LengthUnit::of(largest([largest(gap.offset.into()), gap.contact_distance]));
    gap_value_of(
        &gap.offset.map(|x| unit.apply(x)),
        unit.apply(gap.contact_distance),
    ) > 0.0
}

/// A window's motion in time units of the window (every field a length: the offset, the
/// velocity times the unit, the acceleration times its square, the radius) in the unit of its
/// own largest field: the same numbers up to an exact power of two, so that the window
/// search, whose every decision is homogeneous in lengths, takes the same steps.
fn in_own_unit<const D: usize>(gap: &Gap<D>) -> Gap<D> {
    gap.in_unit(LengthUnit::of(largest([
        largest(gap.offset.into()),
        largest(gap.velocity.into()),
        largest(gap.acceleration.into()),
        gap.contact_distance,
    ])))
}

/// Whether balls touching or overlapping at the start are moving into each other: the first
/// non-zero derivative of the gap is negative.
#[inline(always)]
pub(crate) fn approaching<const D: usize>(gap: &Gap<D>) -> bool {
    // The signs are those of products of lengths alone (the radius plays no part), so they
    // are taken in the unit of the motion's own largest length: balls whose centres are far
    // closer than their radii are long (overlapping deeply) do not lose the signs to underflow.
    let size = largest([
        largest(gap.offset.into()),
        largest(gap.velocity.into()),
        largest(gap.acceleration.into()),
    ]);
    let gap = gap.in_unit(LengthUnit::of(size));
    let slope = gap.half_slope(0.0);
    let curvature = gap.half_curvature(0.0);
    // g‴/6 = d′·d″ (g⁗ = 6|d″|² is never negative). `|` and `&` rather than `||` and `&&`:
    // no branch, so that lanes can run it.
    let third = gap.velocity.dot(&gap.acceleration);
    (slope < 0.0)
        | ((slope == 0.0) & (curvature < 0.0))
        | ((slope == 0.0) & (curvature == 0.0) & (third < 0.0))
}

/// Longest window searched: contacts later than about 1e301 (in the input's time unit) are not
/// reported, so that scaling time to the window never overflows.
pub(crate) const LONGEST_WINDOW: f64 = 1e301;

/// The power of two `h ≥ length` (`length` itself if it is one) in whose units a window of
/// `length` runs over `[0, length/h] ⊂ [0, 1]`, exactly; `None` for a zero length.
fn time_unit(length: f64) -> Option<f64> {
    if length >= f64::MIN_POSITIVE {
        return Some(normal_time_unit(length));
    }
    match exponent(length) {
        Some(e) if length == pow2(e) => Some(length),
        Some(e) => Some(pow2(e + 1)),
        None => None,
    }
}

/// [`time_unit`] of a normal, finite, positive `length` (up to [`LONGEST_WINDOW`]), by its
/// bits: the power of two below it, doubled unless it is that power (as the batch's lanes
/// form it, with the same operation: `simd::fraction_cleared`).
#[inline(always)]
pub(crate) fn normal_time_unit(length: f64) -> f64 {
    let below = fraction_cleared(length);
    if below == length { length } else { 2.0 * below }
}

/// The first entry on a window of `length` (possibly infinite), as time since its start;
/// a long window ([`long_window`]) piece by piece.
///
/// With fused multiply-adds in hardware where the CPU has them: the search's evaluations of
/// the gap are made of them, and a copy compiled without them calls a library function for
/// each (the same exact result, so the same bits, at several times the cost).
fn search_window<const D: usize>(
    gap: &Gap<D>,
    length: f64,
    previous_positive: bool,
) -> WindowSearch {
    // The level of the batch (or the process): `simd`'s one dispatch point.
    let search = SearchWindow {
        gap,
        length,
        previous_positive,
    };
    crate::simd::dispatch_scalar(crate::simd::current(), search)
}

/// [`search_window`]'s arguments, run by [`crate::simd::dispatch_scalar`].
struct SearchWindow<'a, const D: usize> {
    gap: &'a Gap<D>,
    length: f64,
    previous_positive: bool,
}

impl<const D: usize> crate::simd::Kernel for SearchWindow<'_, D> {
    type Output = WindowSearch;

    #[inline(always)]
    fn run<S: crate::simd::Simd>(self, _: S) -> WindowSearch {
        search_window_in(self.gap, self.length, self.previous_positive)
    }
}

/// The body of [`search_window`].
#[inline(always)]
fn search_window_in<const D: usize>(
    gap: &Gap<D>,
    length: f64,
    previous_positive: bool,
) -> WindowSearch {
    let length = bounded_length(gap, length);
    if !long_window(gap, length) {
        return search_short_window(gap, length, previous_positive);
    }
    let (mut start, mut end) = (0.0, first_piece(gap, length));
    let mut previous_positive = previous_positive;
    let mut budget = SPLITS;
    loop {
        let piece = if start == 0.0 {
            *gap
        } else {
            gap.shifted(start)
        };
        match search_piece(&piece, end - start, previous_positive, &mut budget) {
            WindowSearch::Entry(s) => return WindowSearch::Entry(start + s),
            WindowSearch::NoEntry { ends_positive } => previous_positive = ends_positive,
        }
        if end >= length {
            return WindowSearch::NoEntry {
                ends_positive: previous_positive,
            };
        }
        start = end;
        end = next_piece(&gap.shifted(start), start, length);
    }
}

/// How many times the pieces of one long window may be halved in all: far more than a window
/// whose boxes prove its far parts apart needs (about two per halving towards each feature),
/// and a bound on the work where nothing can be proven (lengths whose squares underflow).
const SPLITS: u32 = 4096;

/// The first entry on a piece of a long window (its motion `piece`, re-expanded at its start),
/// as time since its start: nothing if its box proves it apart ([`apart_on_window`]); the
/// window search if it is short even measured by the radius alone ([`short_piece`]: then it
/// is short wherever the balls may touch in it); otherwise its two halves in turn, while the
/// `budget` of halvings lasts.
///
/// The halving is depth first, first halves before second halves, each second half
/// re-expanded at its own start from the motion of the piece it halves. It runs on an
/// explicit stack rather than by recursion: the budget allows thousands of nested halvings,
/// which frames on the call stack would pay for in stack space (a thread of 1 MiB could not
/// hold them). An entry found in a second half is `half + s` at each level, innermost first,
/// as the nesting gives it.
fn search_piece<const D: usize>(
    piece: &Gap<D>,
    length: f64,
    previous_positive: bool,
    budget: &mut u32,
) -> WindowSearch {
    /// No second half above: the entry time needs nothing added.
    const TOP: usize = usize::MAX;
    // Pieces still to search (last first): the motion, its length and the innermost second
    // half it lies in (an index into `halves`).
    let mut pending: Vec<(Gap<D>, f64, usize)> = Vec::new();
    // Second halves: the half to add to an entry found in them, and the one they lie in.
    let mut halves: Vec<(f64, usize)> = Vec::new();
    let mut previous_positive = previous_positive;
    let (mut piece, mut length, mut within) = (*piece, length, TOP);
    loop {
        let leaf = if apart_on_window(&piece, length) {
            Some(WindowSearch::NoEntry {
                ends_positive: true,
            })
        } else if *budget == 0 || short_piece(&piece, length) || length.is_nan() || length <= 0.0 {
            Some(search_short_window(&piece, length, previous_positive))
        } else {
            None
        };
        match leaf {
            Some(WindowSearch::Entry(mut s)) => {
                while within != TOP {
                    let (half, outer) = halves[within];
                    s += half;
                    within = outer;
                }
                return WindowSearch::Entry(s);
            }
            Some(WindowSearch::NoEntry { ends_positive }) => {
                previous_positive = ends_positive;
                match pending.pop() {
                    Some(next) => (piece, length, within) = next,
                    None => {
                        return WindowSearch::NoEntry {
                            ends_positive: previous_positive,
                        };
                    }
                }
            }
            None => {
                *budget -= 1;
                let half = 0.5 * length;
                halves.push((half, within));
                pending.push((piece.shifted(half), length - half, halves.len() - 1));
                length = half;
            }
        }
    }
}

/// The length of a window to search: `length` itself if finite (up to [`LONGEST_WINDOW`]);
/// for an unbounded one, up to twice the closest approach.
#[inline(always)]
fn bounded_length<const D: usize>(gap: &Gap<D>, length: f64) -> f64 {
    if length.is_finite() {
        bounded_finite_length(length)
    } else {
        unbounded_length(gap)
    }
}

/// [`bounded_length`] of a window that ends (`length` finite).
#[inline(always)]
fn bounded_finite_length(length: f64) -> f64 {
    length.min(LONGEST_WINDOW)
}

/// [`bounded_length`] of a window that lasts for ever.
fn unbounded_length<const D: usize>(gap: &Gap<D>) -> f64 {
    let length = if gap.acceleration != SVector::<f64, D>::zeros() {
        // Accelerating for ever (balls on general paths): |d(s)| ≥ ½|a|s² − |v|s − |d(0)|,
        // above the radius beyond the larger root of that quadratic; a margin of 2⁻²⁰ covers
        // the rounding of the bound (the window's end needs no precision).
        let (a, v) = (gap.acceleration.norm(), gap.velocity.norm());
        let reach = gap.offset.norm() + gap.contact_distance;
        let bound = (v + (v * v + 2.0 * a * reach).sqrt()) / a;
        bound * (1.0 + 1.0 / f64::from(1u32 << 20))
    } else {
        // A frictionless (or resting) relative motion: its gap is then a quadratic symmetric
        // about the closest approach s*, so any entry lies in [0, s*]: search [0, 2s*] to
        // keep s* inside.
        let approach = -gap.offset.dot(&gap.velocity);
        let speed2 = gap.velocity.norm_squared();
        if approach > 0.0 && speed2 > 0.0 {
            2.0 * (approach / speed2)
        } else {
            // Receding or at rest: only the start can be an entry.
            0.0
        }
    };
    length.min(LONGEST_WINDOW)
}

/// The first entry on a window of `length` that is not long, as time since its start.
#[inline(always)]
fn search_short_window<const D: usize>(
    gap: &Gap<D>,
    length: f64,
    previous_positive: bool,
) -> WindowSearch {
    let h = match time_unit(length) {
        Some(h) => h,
        None => {
            let g_start = gap.value(0.0);
            return if previous_positive && g_start < 0.0 {
                WindowSearch::Entry(0.0)
            } else {
                WindowSearch::NoEntry {
                    ends_positive: (g_start > 0.0) | (previous_positive & (g_start == 0.0)),
                }
            };
        }
    };
    // In the window's units every field is a length: in their own unit (exact), no square
    // underflows or overflows whatever the pair's unit was chosen from.
    let scaled = in_own_unit(&gap.time_scaled(h));
    let end = length / h;
    let found = piecewise_entry(&scaled, end)
        .unwrap_or_else(|| first_entry(&scaled, end, previous_positive));
    match found {
        WindowSearch::Entry(u) => WindowSearch::Entry(u * h),
        no_entry => no_entry,
    }
}
