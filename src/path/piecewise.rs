//! [`Path`]: a ball's motion as a checked sequence of constant-acceleration [`Segment`]s.

use nalgebra::SVector;

use super::Segment;
use crate::error::{InputError, InputErrorKind, finite};

/// A ball's motion: one or more [`Segment`]s, each active from its start until the next
/// segment's start; the last one lasts for ever.
///
/// A `Path` is always valid: [`Path::new`] (and [`Path::from_rows`]) check that there is at
/// least one segment, that the starts are finite and never decrease, and that every position,
/// velocity and acceleration is finite, so every query on it is total.
///
/// A segment whose start equals the next one's is *empty*: it is never active, and the path
/// jumps straight to the later segment (positions need not be continuous at a start; the caller
/// computes them). A path describes the motion from its [first start](Path::first_start) on;
/// queries at earlier times are answered at the first start.
///
/// ```
/// use ballcollide::path::{Path2, Segment2};
/// use nalgebra::Vector2;
///
/// // Rolls from the origin at 1 m/s, slowed at 0.5 m/s², and stops after 2 s, 1 m further on.
/// let path = Path2::new(vec![
///     Segment2::new(0.0, Vector2::zeros(), Vector2::new(1.0, 0.0), Vector2::new(-0.5, 0.0)),
///     Segment2::at_rest(2.0, Vector2::new(1.0, 0.0)),
/// ])?;
/// assert_eq!(path.position_at(1.0), Vector2::new(0.75, 0.0));
/// assert_eq!(path.velocity_at(1.0), Vector2::new(0.5, 0.0));
/// assert_eq!(path.position_at(50.0), Vector2::new(1.0, 0.0)); // the last segment lasts
/// # Ok::<(), ballcollide::InputError>(())
/// ```
// Aligned to a cache line: a path of one segment in the plane (the frictionless ball's) is
// one line, read in one go when the calendar meets the ball, in an array of paths as in one.
#[derive(Clone)]
#[repr(align(64))]
pub struct Path<const D: usize> {
    segments: Segments<D>,
}

/// A path's segments: up to two held in place (no allocation, and no second read to reach
/// them: a frictionless ball's path, one segment, and a friction ball's, sliding then at
/// rest; measured at 10⁶ frictionless balls in `simulate`, 78 cache misses per event against
/// 97 behind a pointer, callgrind with a 2 MiB last level), more on the heap.
#[derive(Clone)]
enum Segments<const D: usize> {
    One(Segment<D>),
    Two([Segment<D>; 2]),
    Many(Vec<Segment<D>>),
}

impl<const D: usize> Segments<D> {
    /// `segments` held in place, if they fit.
    fn inline(segments: &[Segment<D>]) -> Option<Self> {
        match *segments {
            [one] => Some(Self::One(one)),
            [a, b] => Some(Self::Two([a, b])),
            _ => None,
        }
    }

    /// The segments of `vec` (at least one).
    fn of(vec: Vec<Segment<D>>) -> Self {
        Self::inline(&vec).unwrap_or(Self::Many(vec))
    }
}

impl<const D: usize> std::fmt::Debug for Path<D> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Path")
            .field("segments", &self.segments())
            .finish()
    }
}

impl<const D: usize> PartialEq for Path<D> {
    fn eq(&self, other: &Self) -> bool {
        self.segments() == other.segments()
    }
}

/// A path in the plane.
pub type Path2 = Path<2>;

/// A path in space.
pub type Path3 = Path<3>;

/// The argument names that a path's errors report: one for a path without segments, one per
/// segment field.
pub(crate) struct Names {
    pub(crate) segments: &'static str,
    pub(crate) start: &'static str,
    pub(crate) position: &'static str,
    pub(crate) velocity: &'static str,
    pub(crate) acceleration: &'static str,
}

/// The argument names of [`Path::new`]'s errors.
const NAMES: Names = Names {
    segments: "segments",
    start: "start",
    position: "position",
    velocity: "velocity",
    acceleration: "acceleration",
};

impl<const D: usize> Path<D> {
    /// The path made of `segments`, in order.
    ///
    /// # Errors
    /// An [`InputError`] at the index of the first offending segment, naming `start` when a
    /// start is NaN or infinite or earlier than the one before, `position`, `velocity` or
    /// `acceleration` when a component is NaN or infinite; naming `segments` when there is
    /// none.
    ///
    /// ```
    /// use ballcollide::path::{Path2, Segment2};
    /// use ballcollide::InputErrorKind;
    /// use nalgebra::Vector2;
    ///
    /// let rest = |t: f64| Segment2::at_rest(t, Vector2::zeros());
    /// let err = Path2::new(vec![rest(0.0), rest(2.0), rest(1.0)]).unwrap_err();
    /// assert_eq!(err.to_string(), "start[2]: starts must not decrease, got 1 after 2");
    ///
    /// let nan = Segment2 { velocity: Vector2::new(0.0, f64::NAN), ..rest(3.0) };
    /// let err = Path2::new(vec![rest(0.0), nan]).unwrap_err();
    /// assert_eq!((err.argument(), err.index()), ("velocity", Some(1)));
    ///
    /// let err = Path2::new(vec![]).unwrap_err();
    /// assert_eq!(err.kind(), InputErrorKind::NoSegments);
    /// ```
    pub fn new(segments: Vec<Segment<D>>) -> Result<Self, InputError> {
        Self::checked(segments, &NAMES)
    }

    /// Checks `segments` as [`Path::new`] does, without making a path of them.
    pub(crate) fn check(segments: &[Segment<D>]) -> Result<(), InputError> {
        check_segments(segments, &NAMES)
    }

    /// Makes this path the one of `segments`, which must have passed [`Path::check`], and
    /// leaves in `segments` a buffer to reuse (its contents unspecified): the caller's own,
    /// or the heap buffer the path held, whichever is larger; no allocation once the buffers
    /// have grown.
    pub(crate) fn swap_checked(&mut self, segments: &mut Vec<Segment<D>>) {
        debug_assert!(Self::check(segments).is_ok());
        match Segments::inline(segments) {
            // Copied in place; a heap buffer held goes back, if the larger.
            Some(inline) => {
                if let Segments::Many(held) = std::mem::replace(&mut self.segments, inline)
                    && held.capacity() > segments.capacity()
                {
                    *segments = held;
                }
            }
            None => match &mut self.segments {
                Segments::Many(held) => std::mem::swap(held, segments),
                _ => self.segments = Segments::Many(std::mem::take(segments)),
            },
        }
    }

    /// The path made of `segments`, which must have passed [`Path::check`].
    pub(super) fn from_checked(segments: Vec<Segment<D>>) -> Self {
        debug_assert!(Self::check(&segments).is_ok());
        Self {
            segments: Segments::of(segments),
        }
    }

    /// The path made of a copy of `segments`, which must have passed [`Path::check`] (no
    /// allocation for up to two).
    pub(crate) fn from_checked_slice(segments: &[Segment<D>]) -> Self {
        debug_assert!(Self::check(segments).is_ok());
        Self {
            segments: Segments::inline(segments)
                .unwrap_or_else(|| Segments::Many(segments.to_vec())),
        }
    }

    /// The path made of `segments` if they are valid, else an error using `names`.
    pub(super) fn checked(segments: Vec<Segment<D>>, names: &Names) -> Result<Self, InputError> {
        check_segments(&segments, names)?;
        Ok(Self::from_checked(segments))
    }

    /// The segments, in order (at least one).
    ///
    /// ```
    /// use ballcollide::path::{Path3, Segment3};
    /// use nalgebra::Vector3;
    /// let path = Path3::new(vec![Segment3::at_rest(0.5, Vector3::new(1.0, 2.0, 3.0))])?;
    /// assert_eq!(path.segments().len(), 1);
    /// assert_eq!(path.first_start(), 0.5);
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn segments(&self) -> &[Segment<D>] {
        match &self.segments {
            Segments::One(one) => std::slice::from_ref(one),
            Segments::Two(two) => two,
            Segments::Many(many) => many,
        }
    }

    /// The first segment's start: the time from which the path describes the motion (example:
    /// [`Path::segments`]).
    pub fn first_start(&self) -> f64 {
        self.segments()[0].start
    }

    /// The segments that are ever active, each with the time at which it ends: the next
    /// segment's start, or `+∞` for the last. Each is active on `[start, end)`; empty segments
    /// are skipped.
    ///
    /// ```
    /// use ballcollide::path::{Path2, Segment2};
    /// use nalgebra::Vector2;
    /// let rest = |t: f64| Segment2::at_rest(t, Vector2::zeros());
    /// let path = Path2::new(vec![rest(0.0), rest(1.0), rest(1.0), rest(3.0)])?;
    /// let spans: Vec<_> = path.spans().map(|(segment, end)| (segment.start, end)).collect();
    /// assert_eq!(spans, [(0.0, 1.0), (1.0, 3.0), (3.0, f64::INFINITY)]);
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn spans(&self) -> impl Iterator<Item = (&Segment<D>, f64)> {
        spans(self.segments())
    }

    /// The segments, if they are on the heap (three or more).
    pub(crate) fn heap_segments(&self) -> Option<&[Segment<D>]> {
        match &self.segments {
            Segments::Many(many) => Some(many),
            _ => None,
        }
    }

    /// The heap memory the path holds, in bytes (none for up to two segments, held in place).
    pub(crate) fn heap_bytes(&self) -> usize {
        match &self.segments {
            Segments::One(_) | Segments::Two(_) => 0,
            Segments::Many(many) => many.capacity() * std::mem::size_of::<Segment<D>>(),
        }
    }

    /// The segment active at `t`: the last one whose start is ≤ `t`. An empty segment (one
    /// whose start equals the next one's) is therefore never active; times before the first
    /// start (and NaN) are taken as the first start.
    ///
    /// ```
    /// use ballcollide::path::{Path2, Segment2};
    /// use nalgebra::Vector2;
    /// let rest = |t: f64, x: f64| Segment2::at_rest(t, Vector2::new(x, 0.0));
    /// // Segment 1 is empty: the path jumps from x = 0 to x = 2 at t = 1.
    /// let path = Path2::new(vec![rest(0.0, 0.0), rest(1.0, 1.0), rest(1.0, 2.0)])?;
    /// assert_eq!(path.segment_at(-5.0), &path.segments()[0]);
    /// assert_eq!(path.segment_at(0.999), &path.segments()[0]);
    /// assert_eq!(path.segment_at(1.0), &path.segments()[2]);
    /// assert_eq!(path.segment_at(1e300), &path.segments()[2]);
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn segment_at(&self, t: f64) -> &Segment<D> {
        self.locate(t).0
    }

    /// The centre at `t`, by the [active segment](Path::segment_at)'s formula
    /// ([`Segment::position_at`]); times before the first start give the first start's, and
    /// `t = +∞` the largest finite time's (a resting point, if the path ends at rest).
    ///
    /// ```
    /// use ballcollide::path::{Path3, Segment3};
    /// use nalgebra::Vector3;
    /// // Dropped from 5 m at t = 1 s under 10 m/s²: it falls for 1 s, then lies on the floor.
    /// let gravity = Vector3::new(0.0, 0.0, -10.0);
    /// let path = Path3::new(vec![
    ///     Segment3::new(1.0, Vector3::new(0.0, 0.0, 5.0), Vector3::zeros(), gravity),
    ///     Segment3::at_rest(2.0, Vector3::zeros()),
    /// ])?;
    /// assert_eq!(path.position_at(1.5), Vector3::new(0.0, 0.0, 3.75));
    /// assert_eq!(path.position_at(0.0), Vector3::new(0.0, 0.0, 5.0));
    /// assert_eq!(path.velocity_at(1.5), Vector3::new(0.0, 0.0, -5.0));
    /// assert_eq!(path.acceleration_at(1.5), gravity);
    /// assert_eq!(path.acceleration_at(7.0), Vector3::zeros());
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn position_at(&self, t: f64) -> SVector<f64, D> {
        let (segment, t) = self.locate(t);
        segment.position_at(t)
    }

    /// The velocity at `t`, by the active segment's formula (example: [`Path::position_at`]).
    pub fn velocity_at(&self, t: f64) -> SVector<f64, D> {
        let (segment, t) = self.locate(t);
        segment.velocity_at(t)
    }

    /// The acceleration at `t`: the active segment's (example: [`Path::position_at`]).
    pub fn acceleration_at(&self, t: f64) -> SVector<f64, D> {
        self.segment_at(t).acceleration
    }

    /// The segment active at `t`, and `t` itself, taken as the first start if earlier (or NaN),
    /// and as the largest finite time if `+∞` (so that a path ending at rest reports its resting
    /// point there rather than `0·∞`).
    fn locate(&self, t: f64) -> (&Segment<D>, f64) {
        locate(self.segments(), t)
    }
}

/// `Path::locate` on the segments of a valid path (at least one, starts in order): what the
/// batch of positions uses on the rows it has read, without building a `Path`.
pub(crate) fn locate<const D: usize>(segments: &[Segment<D>], t: f64) -> (&Segment<D>, f64) {
    let first = segments.first().map_or(f64::NEG_INFINITY, |s| s.start);
    let t = t.max(first).min(f64::MAX);
    // The starts never decrease, so the segments begun by `t` are a prefix, and it holds
    // at least the first segment, which begins at the first start ≤ `t`.
    let begun = segments.partition_point(|segment| segment.start <= t);
    (&segments[begun.saturating_sub(1)], t)
}

/// Checks that `segments` make a path: at least one, starts finite and never decreasing,
/// every value finite; the error uses `names` and the offending segment's index.
pub(crate) fn check_segments<const D: usize>(
    segments: &[Segment<D>],
    names: &Names,
) -> Result<(), InputError> {
    if segments.is_empty() {
        return Err(InputError::new(names.segments, InputErrorKind::NoSegments));
    }
    let mut previous = f64::NEG_INFINITY;
    for (k, segment) in segments.iter().enumerate() {
        check_order(names.start, previous, segment.start).map_err(|e| e.at(k))?;
        finite(names.start, segment.start).map_err(|e| e.at(k))?;
        for (name, vector) in [
            (names.position, &segment.position),
            (names.velocity, &segment.velocity),
            (names.acceleration, &segment.acceleration),
        ] {
            for &x in vector.iter() {
                finite(name, x).map_err(|e| e.at(k))?;
            }
        }
        previous = segment.start;
    }
    Ok(())
}

/// The segments of a valid path that are ever active, each with the time it ends (the next
/// start; `+∞` for the last): empty segments are skipped.
pub(crate) fn spans<const D: usize>(
    segments: &[Segment<D>],
) -> impl Iterator<Item = (&Segment<D>, f64)> {
    let ends = segments
        .iter()
        .skip(1)
        .map(|segment| segment.start)
        .chain(std::iter::once(f64::INFINITY));
    segments
        .iter()
        .zip(ends)
        .filter(|(segment, end)| segment.start < *end)
}

/// Checks that `start` is not NaN and not earlier than the `previous` start (infinities are
/// left to the caller: +∞ marks padding rows in [`Path::from_rows`]).
pub(super) fn check_order(
    argument: &'static str,
    previous: f64,
    start: f64,
) -> Result<(), InputError> {
    if start.is_nan() {
        Err(InputError::new(argument, InputErrorKind::NotFinite(start)))
    } else if start < previous {
        Err(InputError::new(
            argument,
            InputErrorKind::DecreasingStart { previous, start },
        ))
    } else {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::path::{Path2, Path3, Segment2, Segment3};
    use nalgebra::{Vector2, Vector3};
    use proptest::prelude::*;

    fn rest(t: f64, x: f64) -> Segment2 {
        Segment2::at_rest(t, Vector2::new(x, 0.0))
    }

    /// A path rebuilt in place holds the new segments whatever it held before (one or two in
    /// place, more on the heap), is equal to the path made of them, and hands back a buffer
    /// at least as large as the one it was given.
    #[test]
    fn a_path_rebuilt_in_place_holds_the_new_segments() {
        let lengths = [1usize, 2, 3, 5, 1, 3, 2, 1, 4, 4, 2, 2, 1, 1];
        let segments = |n: usize, x: f64| -> Vec<Segment2> {
            (0..n).map(|k| rest(k as f64, x + k as f64)).collect()
        };
        let mut path = Path2::new(segments(1, -1.0)).expect("valid");
        for (m, &n) in lengths.iter().enumerate() {
            let expected = segments(n, m as f64);
            let mut buffer = expected.clone();
            let given = buffer.capacity();
            path.swap_checked(&mut buffer);
            assert_eq!(path.segments(), expected.as_slice());
            assert_eq!(path, Path2::new(expected.clone()).expect("valid"));
            assert_eq!(path, Path2::from_checked_slice(&expected));
            if n <= 2 {
                // Copied in place: the caller keeps its buffer, or gets a larger one.
                assert!(buffer.capacity() >= given);
            }
            assert_eq!(path.heap_bytes() == 0, n <= 2);
            assert_eq!(
                format!("{path:?}"),
                format!("Path {{ segments: {expected:?} }}")
            );
        }
        // One segment in the plane is one cache line.
        assert_eq!(std::mem::align_of::<Path2>(), 64);
        for n in [1, 2] {
            let path = Path2::new(segments(n, 0.0)).expect("valid");
            let offset = path.segments().as_ptr() as usize - std::ptr::from_ref(&path) as usize;
            assert!(offset + std::mem::size_of::<Segment2>() <= 64);
        }
    }

    fn error(segments: Vec<Segment2>) -> InputError {
        match Path2::new(segments) {
            Ok(path) => panic!("accepted {path:?}"),
            Err(err) => err,
        }
    }

    #[test]
    fn a_path_needs_a_segment() {
        let err = error(vec![]);
        assert_eq!(err.argument(), "segments");
        assert_eq!(err.kind(), InputErrorKind::NoSegments);
        assert_eq!(
            err.to_string(),
            "segments: a path needs at least one segment"
        );
    }

    #[test]
    fn a_non_finite_value_is_named_with_its_segment() {
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let mut v = Vector2::zeros();
            v.y = bad;
            for (argument, segment) in [
                (
                    "start",
                    Segment2 {
                        start: bad,
                        ..rest(2.0, 0.0)
                    },
                ),
                (
                    "position",
                    Segment2 {
                        position: v,
                        ..rest(2.0, 0.0)
                    },
                ),
                (
                    "velocity",
                    Segment2 {
                        velocity: v,
                        ..rest(2.0, 0.0)
                    },
                ),
                (
                    "acceleration",
                    Segment2 {
                        acceleration: v,
                        ..rest(2.0, 0.0)
                    },
                ),
            ] {
                let err = error(vec![rest(0.0, 0.0), rest(1.0, 0.0), segment]);
                assert_eq!(err.argument(), argument);
                assert_eq!(err.index(), Some(2));
                if argument == "start" && bad == f64::NEG_INFINITY {
                    continue; // a decrease (see starts_must_not_decrease)
                }
                let InputErrorKind::NotFinite(x) = err.kind() else {
                    panic!("{err}");
                };
                assert_eq!(x.to_bits(), bad.to_bits());
            }
        }
    }

    #[test]
    fn the_first_offending_segment_is_reported() {
        let nan = Segment2 {
            position: Vector2::new(f64::NAN, 0.0),
            ..rest(1.0, 0.0)
        };
        let err = error(vec![rest(0.0, 0.0), nan, rest(0.5, 0.0)]);
        assert_eq!((err.argument(), err.index()), ("position", Some(1)));
    }

    #[test]
    fn starts_must_not_decrease() {
        let err = error(vec![rest(0.0, 0.0), rest(2.0, 0.0), rest(1.0, 0.0)]);
        assert_eq!((err.argument(), err.index()), ("start", Some(2)));
        assert_eq!(
            err.kind(),
            InputErrorKind::DecreasingStart {
                previous: 2.0,
                start: 1.0
            }
        );
        // −∞ after a finite start is a decrease; as a first start it is not finite.
        let err = error(vec![rest(0.0, 0.0), rest(f64::NEG_INFINITY, 0.0)]);
        assert!(matches!(err.kind(), InputErrorKind::DecreasingStart { .. }));
        let err = error(vec![rest(f64::NEG_INFINITY, 0.0)]);
        assert_eq!(err.kind(), InputErrorKind::NotFinite(f64::NEG_INFINITY));
        assert_eq!(err.index(), Some(0));
    }

    #[test]
    fn equal_starts_and_negative_starts_are_accepted() {
        let path = Path2::new(vec![
            rest(-3.0, 0.0),
            rest(-3.0, 1.0),
            rest(-0.0, 2.0),
            rest(0.0, 3.0),
        ]);
        assert_eq!(path.map(|p| p.segments().len()), Ok(4));
    }

    #[test]
    fn empty_segments_are_never_active() {
        // Segments 1 and 2 begin at t = 1 with segment 3: only segment 3 is active from 1 on.
        let path = Path2::new(vec![
            rest(0.0, 0.0),
            rest(1.0, 1.0),
            rest(1.0, 2.0),
            rest(1.0, 3.0),
        ])
        .expect("valid path");
        assert_eq!(path.segment_at(1.0_f64.next_down()), &path.segments()[0]);
        for t in [1.0, 1.5, 1e300, f64::INFINITY] {
            assert_eq!(path.segment_at(t), &path.segments()[3]);
            assert_eq!(path.position_at(t), Vector2::new(3.0, 0.0));
        }
    }

    #[test]
    fn times_before_the_first_start_are_taken_as_the_first_start() {
        // The leading empty segment is never active, not even before the path begins.
        let path = Path2::new(vec![
            rest(1.0, 5.0),
            Segment2::new(
                1.0,
                Vector2::zeros(),
                Vector2::new(1.0, 0.0),
                Vector2::new(-1.0, 0.0),
            ),
            rest(2.0, 0.5),
        ])
        .expect("valid path");
        for t in [0.5, -1e300, f64::NEG_INFINITY, f64::NAN] {
            assert_eq!(path.segment_at(t), &path.segments()[1]);
            assert_eq!(path.position_at(t), Vector2::zeros());
            assert_eq!(path.velocity_at(t), Vector2::new(1.0, 0.0));
            assert_eq!(path.acceleration_at(t), Vector2::new(-1.0, 0.0));
        }
    }

    #[test]
    fn the_last_segment_lasts_for_ever() {
        // A ball under gravity that never lands keeps falling, however late.
        let g = Vector3::new(0.0, 0.0, -10.0);
        let path = Path3::new(vec![
            Segment3::at_rest(0.0, Vector3::zeros()),
            Segment3::new(1.0, Vector3::zeros(), Vector3::zeros(), g),
        ])
        .expect("valid path");
        assert_eq!(path.position_at(1001.0), Vector3::new(0.0, 0.0, -5e6));
        assert_eq!(path.velocity_at(1001.0), Vector3::new(0.0, 0.0, -1e4));
    }

    #[test]
    fn a_jump_at_a_start_takes_the_new_segment_exactly_there() {
        let path = Path2::new(vec![
            Segment2::new(
                0.0,
                Vector2::zeros(),
                Vector2::new(1.0, 0.0),
                Vector2::zeros(),
            ),
            rest(1.0, 7.0),
        ])
        .expect("valid path");
        assert_eq!(
            path.position_at(1.0_f64.next_down()),
            Vector2::new(1.0_f64.next_down(), 0.0)
        );
        assert_eq!(path.position_at(1.0), Vector2::new(7.0, 0.0));
    }

    /// Up to 6 segments whose starts are drawn from a few values, so that many are empty.
    fn starts() -> impl Strategy<Value = Vec<f64>> {
        prop::collection::vec(
            prop::sample::select(vec![-1.0, 0.0, 0.5, 1.0, 2.5, 1e4]),
            1..=6,
        )
        .prop_map(|mut starts| {
            starts.sort_by(f64::total_cmp);
            starts
        })
    }

    proptest! {
        #[test]
        fn the_active_segment_is_the_last_one_begun(
            starts in starts(),
            t in prop::sample::select(vec![-2.0f64, -1.0, 0.0, 0.25, 0.5, 1.0, 2.0, 2.5, 1e4, 2e4]),
        ) {
            let segments: Vec<Segment2> =
                starts.iter().enumerate().map(|(k, &s)| rest(s, k as f64)).collect();
            let path = Path2::new(segments.clone()).expect("valid path");
            let clamped = t.max(starts[0]);
            let expected = (0..segments.len()).rev().find(|&k| starts[k] <= clamped);
            prop_assert_eq!(Some(path.segment_at(t)), expected.map(|k| &segments[k]));
            // Empty segments are never active.
            let k = expected.unwrap_or(0);
            prop_assert!(k + 1 == segments.len() || starts[k + 1] > starts[k]);
        }

        #[test]
        fn the_spans_are_where_each_segment_is_active(starts in starts()) {
            let segments: Vec<Segment2> =
                starts.iter().enumerate().map(|(k, &s)| rest(s, k as f64)).collect();
            let path = Path2::new(segments).expect("valid path");
            let spans: Vec<_> = path.spans().collect();
            // They tile [first start, ∞) ...
            prop_assert_eq!(spans[0].0.start, path.first_start());
            prop_assert_eq!(spans[spans.len() - 1].1, f64::INFINITY);
            for pair in spans.windows(2) {
                prop_assert_eq!(pair[0].1, pair[1].0.start);
            }
            // ... and each segment is the active one on its own.
            for (segment, end) in spans {
                prop_assert!(segment.start < end);
                prop_assert_eq!(path.segment_at(segment.start), segment);
                prop_assert_eq!(path.segment_at(end.next_down()), segment);
            }
        }
    }
}
