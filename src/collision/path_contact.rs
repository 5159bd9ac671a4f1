//! When two balls on general paths first touch: [`path_collision_time`].
//!
//! Both paths are piecewise constant-acceleration ([`Path`]): between consecutive segment
//! starts of either path (a *window*), the relative motion `d(s)` is a quadratic in the time
//! `s` since the window's start and the gap `|d|² − r²` a quartic, which the same window
//! search as the friction balls' answers ([`search_window`](super::search_window): time
//! scaled to the window, Bernstein exclusion, critical points, bracketed Newton, long windows
//! in pieces). Each window's motion is formed from the two active segments' own inputs, in
//! time relative to each segment's start, so that late absolute times and long rolls keep
//! full accuracy; and every length is first divided by the pair's unit of length
//! ([`length_unit`](super::length_unit)), so that the answer does not depend on it.
//!
//! One search, the first contact of two paths, with entry points that differ only in what
//! the caller has done already:
//!
//! | function | inputs | for |
//! |---|---|---|
//! | [`path_collision_time`] | paths, radius and horizon unchecked | the public query |
//! | `first_contact_checked` | the same, with the screens on or off | it and [`path_collision_time_unscreened`] |
//! | [`first_contact_of_paths`] | valid segments; the bounds formed here | geometry's circles and targets, the calendar |
//! | [`first_contact_bounded_fma`] | valid segments with their bounds | the calendar (one pair at a time, FMA in hardware, without the window chord) |
//! | [`first_contact_bounded`] | the same, and what the lanes found ([`Prior`]) | the batches (inlined into each SIMD copy) |
//! | `first_contact_walk` | the same, the screens on or off | all of the above: the walk over windows |
//! | `first_contact_one_window` | two paths of one segment each | the walk's shortcut |

use super::chord_normals::apart_across_chords;
use super::length_unit::LengthUnit;
use super::path_bounds::{PathBounds, SEGMENT_BOXES};
use super::stage_counts::{Stage, count};
use super::straight::straight_window;
use super::window_box::apart_on_window;
use super::window_chord::apart_across_window_chord;
use super::{
    CollisionOptions, SettledBy, WindowSearch, apart_at_start, approaching, bounded_length,
    eighth_then_search,
};
use crate::error::{InputError, check_contact_distance, check_horizon};
use crate::gap::Gap;
use crate::path::{Path, Segment};

/// The first time (absolute, as the paths' starts are) at which balls on paths `a` and `b`
/// are `contact_distance` apart and starting to interpenetrate, searched from the later of the two
/// first starts; `None` if they never are before `options.t_max`.
///
/// Touching or overlapping at that first time is a contact only if the balls approach (the
/// first non-zero derivative of the gap is negative); a path that jumps into overlap at a
/// later segment start collides at that start; exact tangency is no contact.
///
/// # Errors
/// `contact_distance` must be finite and positive, `t_max ≥ 0` (`∞` allowed).
///
/// ```
/// use ballcollide::path::{Path2, Segment2};
/// use ballcollide::{CollisionOptions, path_collision_time};
/// use nalgebra::Vector2;
///
/// // A rolls at 1 m/s from the origin; from t = 1 s it is slowed at 0.5 m/s². B rests at x = 2.
/// let a = Path2::new(vec![
///     Segment2::new(0.0, Vector2::zeros(), Vector2::new(1.0, 0.0), Vector2::zeros()),
///     Segment2::new(1.0, Vector2::new(1.0, 0.0), Vector2::new(1.0, 0.0), Vector2::new(-0.5, 0.0)),
///     Segment2::at_rest(3.0, Vector2::new(2.0, 0.0)),
/// ])?;
/// let b = Path2::new(vec![Segment2::at_rest(0.0, Vector2::new(2.5, 0.0))])?;
/// let t = path_collision_time(&a, &b, 0.75, &CollisionOptions::default())?.expect("a contact");
/// // 1.75 m covered: 1 m by t = 1, then 0.75 = s − s²/4, s = 1.
/// assert!((t - 2.0).abs() < 1e-15);
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn path_collision_time<const D: usize>(
    a: &Path<D>,
    b: &Path<D>,
    contact_distance: f64,
    options: &CollisionOptions,
) -> Result<Option<f64>, InputError> {
    first_contact_checked::<D, true>(a, b, contact_distance, options)
}

/// The first contact of one pair of paths, its radius and horizon checked first, with the
/// screens (`SCREENS`) or without them.
fn first_contact_checked<const D: usize, const SCREENS: bool>(
    a: &Path<D>,
    b: &Path<D>,
    radius: f64,
    options: &CollisionOptions,
) -> Result<Option<f64>, InputError> {
    let radius = check_contact_distance("contact_distance", radius)?;
    let t_max = check_horizon("t_max", options.t_max)?;
    let (a, b) = (a.segments(), b.segments());
    let bounds = (PathBounds::of(a), PathBounds::of(b));
    let (a, b) = ((a, &bounds.0), (b, &bounds.1));
    Ok(first_contact_walk::<D, SEGMENT_BOXES, SCREENS>(
        a,
        b,
        [radius, 0.0],
        t_max,
        Prior::Nothing,
        true,
    ))
}

/// The first contact on validated inputs, the paths' bounds formed here; the contact distance
/// is the sum of `radii`, formed in the pair's unit of length; the window chord tried only
/// with `window_chord` (see [`first_contact_bounded_fma`]).
/// `a` and `b` are the segments of valid paths ([`Path::segments`]).
pub(crate) fn first_contact_of_paths<const D: usize>(
    a: &[Segment<D>],
    b: &[Segment<D>],
    radii: [f64; 2],
    t_max: f64,
    window_chord: bool,
) -> Option<f64> {
    first_contact_bounded_fma::<D, SEGMENT_BOXES>(
        (a, &PathBounds::of(a)),
        (b, &PathBounds::of(b)),
        radii,
        t_max,
        window_chord,
    )
}

/// [`first_contact_bounded`] (without a prior) for one pair at a time, with fused
/// multiply-adds in hardware where the CPU has them: one instruction rather than a library
/// call, the same exact result, so the same bits. The window chord, a proof like the other
/// screens (so the same answer either way), is tried only with `window_chord`: the calendar's
/// pair searches leave it out, as on their pairs (friction balls, pool balls on shots) it
/// settles about one window in ten of those it is asked about and costs more than it saves
/// (`schedule_timing`, 16 to 6,400 friction balls: 3–5 % less CPU per event without it;
/// `shot_timing`: as fast or faster on every kind of shot).
pub(crate) fn first_contact_bounded_fma<const D: usize, const S: usize>(
    a: (&[Segment<D>], &PathBounds<D, S>),
    b: (&[Segment<D>], &PathBounds<D, S>),
    radii: [f64; 2],
    t_max: f64,
    window_chord: bool,
) -> Option<f64> {
    // The level of the batch (or the process): `simd`'s one dispatch point.
    let contact = FirstContactBoundedFma {
        a,
        b,
        radii,
        t_max,
        window_chord,
    };
    crate::simd::dispatch_scalar(crate::simd::current(), contact)
}

/// [`first_contact_bounded_fma`]'s arguments, run by [`crate::simd::dispatch_scalar`].
struct FirstContactBoundedFma<'a, const D: usize, const S: usize> {
    a: (&'a [Segment<D>], &'a PathBounds<D, S>),
    b: (&'a [Segment<D>], &'a PathBounds<D, S>),
    radii: [f64; 2],
    t_max: f64,
    window_chord: bool,
}

impl<const D: usize, const S: usize> crate::simd::Kernel for FirstContactBoundedFma<'_, D, S> {
    type Output = Option<f64>;

    #[inline(always)]
    fn run<L: crate::simd::Simd>(self, _: L) -> Option<f64> {
        first_contact_walk::<D, S, true>(
            self.a,
            self.b,
            self.radii,
            self.t_max,
            Prior::Nothing,
            self.window_chord,
        )
    }
}

/// [`path_collision_time`] without the stages that only prove balls apart (the path bounds
/// and the window box): every window goes to the window search. Those stages are proofs, so
/// the answers must be the same bits; the invariant tests and the fuzz target check it with
/// this. Not part of the supported API.
#[doc(hidden)]
pub fn path_collision_time_unscreened<const D: usize>(
    a: &Path<D>,
    b: &Path<D>,
    contact_distance: f64,
    options: &CollisionOptions,
) -> Result<Option<f64>, InputError> {
    first_contact_checked::<D, false>(a, b, contact_distance, options)
}

/// [`first_contact_of_paths`] with each path's bounds given (a batch computes a broadcast path's
/// once); inlined into each vector copy of the batch.
#[inline(always)]
pub(crate) fn first_contact_bounded<const D: usize, const S: usize>(
    a: (&[Segment<D>], &PathBounds<D, S>),
    b: (&[Segment<D>], &PathBounds<D, S>),
    radii: [f64; 2],
    t_max: f64,
    prior: Prior,
) -> Option<f64> {
    first_contact_walk::<D, S, true>(a, b, radii, t_max, prior, true)
}

/// What a caller already knows of a pair when its search starts.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) enum Prior {
    /// Nothing: every screen runs.
    #[default]
    Nothing,
    /// The batch's lanes took the pair whole and settled it by none of their screens
    /// (`batch/path_lanes.rs`, `batch/window_lanes.rs`): the whole-path screens, the same
    /// proofs to the bit, would fail again, and the window chord is left out (on the windows
    /// of such pairs it hardly ever proves one apart, and costs more than it saves there).
    /// The screens are proofs, so the answer is the same either way.
    LanesLeft,
    /// As `LanesLeft`, and the first-window lanes (`batch/first_window_lanes.rs`) found the
    /// pair's first window screened out (no entry, the gap positive at its end): what its
    /// search would find (the lane twin of [`window_eighth`]), so the walk starts after it.
    FirstWindowScreenedOut,
}

/// The first contact: the whole-path screens, then the walk over windows, with the screens
/// that prove balls apart (`SCREENS`) or without them, the window chord among them only with
/// `window_chord`.
#[inline(always)]
fn first_contact_walk<const D: usize, const S: usize, const SCREENS: bool>(
    (a, bounds_a): (&[Segment<D>], &PathBounds<D, S>),
    (b, bounds_b): (&[Segment<D>], &PathBounds<D, S>),
    radii: [f64; 2],
    t_max: f64,
    prior: Prior,
    window_chord: bool,
) -> Option<f64> {
    count(Stage::PathPair);
    if let ([sa], [sb]) = (a, b) {
        return first_contact_one_window::<D, S, SCREENS>(
            sa,
            sb,
            (bounds_a, bounds_b),
            radii,
            t_max,
            window_chord,
        );
    }
    // Paths whose boxes keep apart need no window: a proof (its margin far above the
    // search's rounding), so its answer is the search's, in any unit.
    let distance = bounds_a.screen_distance(bounds_b, radii[0] + radii[1]);
    let screens = SCREENS && prior == Prior::Nothing;
    if screens && bounds_a.apart(bounds_b, distance) {
        count(Stage::BoundsApart);
        return None;
    }
    if screens && apart_across_chords(a, b, distance) {
        count(Stage::ChordsApart);
        return None;
    }
    let (unit, radius) = pair_unit(bounds_a, bounds_b, radii);
    let mut start = first_time(a.first()?, b.first()?);
    let (mut i, mut j) = (active(a, 0, start), active(b, 0, start));
    let mut previous_positive = None;
    let mut first_screened_out = prior == Prior::FirstWindowScreenedOut;
    loop {
        if start >= t_max {
            return None;
        }
        let (end_a, end_b) = (end_of(a, i), end_of(b, j));
        let end = end_a.min(end_b);
        count(Stage::Window);
        if first_screened_out {
            // Searched and settled on its first open eighth, lane-wise.
            count(Stage::WindowSearched);
            count(Stage::WindowEighth);
            first_screened_out = false;
            previous_positive = Some(true);
        } else if SCREENS && bounds_a.segments_apart(i, bounds_b, j, distance) {
            // The boxes of the two segments, from the path bounds, settle most windows of
            // balls on general paths before any motion is formed (a proof like the path
            // bounds', so the same answer as the search's).
            count(Stage::WindowSegmentsApart);
            previous_positive = Some(true);
        } else {
            let window = Window {
                a: &a[i],
                b: &b[j],
                start,
                end,
            };
            let chord = screens && window_chord;
            match window.search::<SCREENS>(unit, radius, previous_positive, chord) {
                // (At the window's start, which is before `t_max`, or on it.)
                WindowStep::Contact(t) => return (t < t_max).then_some(t),
                WindowStep::NoEntry { ends_positive } => previous_positive = Some(ends_positive),
            }
        }
        if end == f64::INFINITY {
            return None;
        }
        start = end;
        // On to the next segment of the path (or both) whose segment ended, without a branch
        // on which it was (hard to predict); past it, any empty ones (rare).
        i = active(a, i + usize::from(end_a == end), end);
        j = active(b, j + usize::from(end_b == end), end);
    }
}

/// Two paths of one segment each (frictionless balls, say): their one window, from the later
/// start on, for ever. The whole-path screens and the walk over segments are left out: the
/// window's own stages (the straight window's closed form, the window box) settle it at least
/// as soon, and with them the search of one pair of disks ran about 40 % more instructions
/// (calendar, N = 16).
#[inline(always)]
fn first_contact_one_window<const D: usize, const S: usize, const SCREENS: bool>(
    a: &Segment<D>,
    b: &Segment<D>,
    (bounds_a, bounds_b): (&PathBounds<D, S>, &PathBounds<D, S>),
    radii: [f64; 2],
    t_max: f64,
    window_chord: bool,
) -> Option<f64> {
    let (unit, radius) = pair_unit(bounds_a, bounds_b, radii);
    let start = first_time(a, b);
    if start >= t_max {
        return None;
    }
    count(Stage::Window);
    let window = Window {
        a,
        b,
        start,
        end: f64::INFINITY,
    };
    match window.search::<SCREENS>(unit, radius, None, window_chord) {
        WindowStep::Contact(t) => (t < t_max).then_some(t),
        WindowStep::NoEntry { .. } => None,
    }
}

/// The pair's unit of length, and the contact distance (the sum of `radii`) in it.
#[inline(always)]
fn pair_unit<const D: usize, const S: usize>(
    bounds_a: &PathBounds<D, S>,
    bounds_b: &PathBounds<D, S>,
    radii: [f64; 2],
) -> (LengthUnit, f64) {
    let unit = bounds_a.pair_unit(bounds_b, radii);
    (unit, unit.apply(radii[0]) + unit.apply(radii[1]))
}

/// The pair's first time: the later of the two first starts. `+ 0.0` makes a first time of −0
/// a +0: `max` leaves the sign of equal zeros to the order of its operands, and the answer
/// must not depend on which path is A.
#[inline(always)]
fn first_time<const D: usize>(a: &Segment<D>, b: &Segment<D>) -> f64 {
    a.start.max(b.start) + 0.0
}

/// One window of a pair: the two active segments, from `start` to `end`.
struct Window<'a, const D: usize> {
    a: &'a Segment<D>,
    b: &'a Segment<D>,
    start: f64,
    end: f64,
}

/// What a window's search found.
enum WindowStep {
    /// The balls start to interpenetrate at this (absolute) time.
    Contact(f64),
    /// No entry; whether the gap ends the window positive (see [`WindowSearch::NoEntry`]).
    NoEntry { ends_positive: bool },
}

impl<const D: usize> Window<'_, D> {
    /// The window's search, in the pair's `unit` of length, at contact distance `radius` (in
    /// that unit); `previous_positive`: whether the gap was positive just before the window
    /// (`None` at the pair's first time); the window chord only with `chord`.
    #[inline(always)]
    fn search<const SCREENS: bool>(
        &self,
        unit: LengthUnit,
        radius: f64,
        previous_positive: Option<bool>,
        chord: bool,
    ) -> WindowStep {
        let (start, end) = (self.start, self.end);
        let gap = window_gap(&scaled(self.a, unit), &scaled(self.b, unit), start, radius);
        let before = match previous_positive {
            Some(positive) => positive,
            None => {
                // At the first time: touching or overlapping balls collide only if they
                // approach; otherwise only a later re-entry counts.
                let apart = apart_at_start(&gap);
                if !apart && approaching(&gap) {
                    count(Stage::Contact);
                    return WindowStep::Contact(start);
                }
                apart
            }
        };
        let length = end - start;
        // No relative acceleration: a straight line, in closed form where it is clear (before
        // the box, which it makes unnecessary). Most other windows of balls on paths are
        // proven apart by the box the separation sweeps or by its span across its chord; the
        // rest are searched.
        let answer = if let Some(straight) = straight_window(&gap, length, before) {
            count(Stage::WindowStraight);
            straight
        } else if SCREENS && apart_on_window(&gap, bounded_length(&gap, length)) {
            count(Stage::WindowBoxApart);
            WindowSearch::NoEntry {
                ends_positive: true,
            }
        } else if SCREENS && chord && apart_across_window_chord(&gap, bounded_length(&gap, length))
        {
            // Near misses at an angle to the axes, which the box leaves (on a pool table,
            // most of the windows it leaves without a contact).
            count(Stage::WindowChordApart);
            WindowSearch::NoEntry {
                ends_positive: true,
            }
        } else {
            count(Stage::WindowSearched);
            // Most entries are isolated on the window's first open eighth, and most windows
            // without one too: settled there by a few Newton steps, the rest searched.
            let (answer, settled_by) = eighth_then_search(&gap, length, before);
            match settled_by {
                SettledBy::Eighth => count(Stage::WindowEighth),
                SettledBy::Parting => count(Stage::WindowParting),
                SettledBy::Search => {}
            }
            answer
        };
        match answer {
            WindowSearch::Entry(s) => {
                count(Stage::Contact);
                WindowStep::Contact(start + s)
            }
            WindowSearch::NoEntry { ends_positive } => WindowStep::NoEntry { ends_positive },
        }
    }
}

/// Whether every window of paths `a` and `b` (valid) is proven apart, at contact distance
/// `radius`, by the window screens of [`first_contact_bounded`], as its walk forms them: the
/// segment boxes, else (a window that ends) the box or the chord of its separation. The lane
/// tests' oracle (`batch/window_lanes.rs`), which must settle exactly such pairs.
#[cfg(test)]
pub(crate) fn every_window_screened<const D: usize>(
    a: &[Segment<D>],
    b: &[Segment<D>],
    radius: f64,
) -> bool {
    let (bounds_a, bounds_b) = (PathBounds::<D>::of(a), PathBounds::of(b));
    let distance = bounds_a.screen_distance(&bounds_b, radius);
    let (unit, radius) = pair_unit(&bounds_a, &bounds_b, [radius, 0.0]);
    let (Some(first_a), Some(first_b)) = (a.first(), b.first()) else {
        return false;
    };
    let mut start = first_time(first_a, first_b);
    let (mut i, mut j) = (active(a, 0, start), active(b, 0, start));
    loop {
        let (end_a, end_b) = (end_of(a, i), end_of(b, j));
        let end = end_a.min(end_b);
        if !bounds_a.segments_apart(i, &bounds_b, j, distance) {
            if end == f64::INFINITY {
                return false;
            }
            let gap = window_gap(&scaled(&a[i], unit), &scaled(&b[j], unit), start, radius);
            let length = bounded_length(&gap, end - start);
            if !(apart_on_window(&gap, length) || apart_across_window_chord(&gap, length)) {
                return false;
            }
        }
        if end == f64::INFINITY {
            return true;
        }
        start = end;
        i = active(a, i + usize::from(end_a == end), end);
        j = active(b, j + usize::from(end_b == end), end);
    }
}

/// The index of the segment active at `t` (the last one, from `from` on, whose start is
/// ≤ `t`: empty segments are never active), for `t` at or after segment `from`'s start.
fn active<const D: usize>(segments: &[Segment<D>], from: usize, t: f64) -> usize {
    let mut k = from;
    while segments.get(k + 1).is_some_and(|next| next.start <= t) {
        k += 1;
    }
    k
}

/// When segment `k` ends: the next one's start, `+∞` for the last.
fn end_of<const D: usize>(segments: &[Segment<D>], k: usize) -> f64 {
    segments.get(k + 1).map_or(f64::INFINITY, |next| next.start)
}

/// A segment in the pair's unit of length.
#[inline(always)]
fn scaled<const D: usize>(s: &Segment<D>, unit: LengthUnit) -> Segment<D> {
    Segment {
        start: s.start,
        position: s.position.map(|x| unit.apply(x)),
        velocity: s.velocity.map(|x| unit.apply(x)),
        acceleration: s.acceleration.map(|x| unit.apply(x)),
    }
}

/// The relative motion on the window starting at `start`, from the two active segments (in
/// the pair's unit of length), each evaluated in time since its own start.
#[inline(always)]
fn window_gap<const D: usize>(a: &Segment<D>, b: &Segment<D>, start: f64, radius: f64) -> Gap<D> {
    Gap {
        offset: a.position_at(start) - b.position_at(start),
        velocity: a.velocity_at(start) - b.velocity_at(start),
        acceleration: a.acceleration - b.acceleration,
        contact_distance: radius,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::path::{Path2, Segment2};
    use nalgebra::Vector2;

    #[test]
    fn a_contact_at_a_first_time_of_zero_is_plus_zero_whichever_path_starts_at_minus_zero() {
        // Overlapping and approaching at t_from = max(0, −0): a contact at once, +0 both ways
        // round.
        let a = Path2::new(vec![Segment2::new(
            0.0,
            Vector2::zeros(),
            Vector2::new(1.0, 0.0),
            Vector2::zeros(),
        )]);
        let b = Path2::new(vec![Segment2::at_rest(-0.0, Vector2::new(0.5, 0.0))]);
        let (a, b) = (a.expect("valid"), b.expect("valid"));
        let options = CollisionOptions::default();
        for (x, y) in [(&a, &b), (&b, &a)] {
            let t = path_collision_time(x, y, 1.0, &options).expect("valid");
            assert_eq!(t.map(f64::to_bits), Some(0f64.to_bits()));
        }
    }

    #[test]
    fn one_segment_each_gives_the_bits_of_the_walk_over_segments() {
        // The same paths behind an empty first segment (never active, no part of the bounds
        // or the unit) go through the walk over segments, one window: the same answer.
        let mut rng = crate::test_rng::Rng(31);
        let mut draw =
            |scale: f64| Vector2::new(rng.uniform(-scale, scale), rng.uniform(-scale, scale));
        let (mut contacts, mut cases) = (0, 0);
        for k in 0..4000 {
            let start = |x: f64| if k % 3 == 0 { 0.0 } else { x.abs() };
            let accelerated = k % 4 == 0;
            let mut segment = |t: f64| {
                let a = if accelerated {
                    draw(0.5)
                } else {
                    Vector2::zeros()
                };
                Segment2::new(start(t), draw(1.0), draw(2.0), a)
            };
            let (sa, sb) = (segment(0.3), segment(0.2));
            let hidden = |s: Segment2| {
                Path2::new(vec![Segment2::at_rest(s.start, Vector2::new(5.0, -7.0)), s])
            };
            let (Ok(a), Ok(b), Ok(a2), Ok(b2)) = (
                Path2::new(vec![sa]),
                Path2::new(vec![sb]),
                hidden(sa),
                hidden(sb),
            ) else {
                panic!("valid paths")
            };
            let t_max = if k % 5 == 0 { 0.4 } else { f64::INFINITY };
            let options = CollisionOptions { t_max };
            let radius = 0.05 + 0.2 * (k % 7) as f64;
            let bits = |x: Result<Option<f64>, InputError>| x.map(|t| t.map(f64::to_bits));
            for (x, y, x2, y2) in [(&a, &b, &a2, &b2), (&b, &a, &b2, &a2)] {
                let one = path_collision_time(x, y, radius, &options);
                assert_eq!(
                    bits(one),
                    bits(path_collision_time(x2, y2, radius, &options))
                );
                assert_eq!(
                    bits(path_collision_time_unscreened(x, y, radius, &options)),
                    bits(path_collision_time_unscreened(x2, y2, radius, &options))
                );
                contacts += usize::from(one.is_ok_and(|t| t.is_some()));
                cases += 1;
            }
        }
        // Both kinds of answer, often.
        assert!(
            contacts > cases / 10 && contacts < cases * 9 / 10,
            "{contacts} of {cases}"
        );
    }
}
