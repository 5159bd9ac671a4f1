//! [`InputError`]: what is wrong with an input, naming the argument (and index, in batch).

use std::fmt;

/// What is wrong with one input value.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum InputErrorKind {
    /// NaN or ±∞.
    NotFinite(f64),
    /// A friction deceleration below zero.
    NegativeFriction(f64),
    /// A contact distance (the sum of the two balls' radii) that is zero or negative.
    NonPositiveRadius(f64),
    /// One ball's radius (in a scene or a calendar) that is zero or negative.
    NonPositiveBallRadius(f64),
    /// A horizon (`t_max`) or end time (`t_end`) that is negative or NaN.
    InvalidHorizon(f64),
    /// An array whose length differs from the others'.
    LengthMismatch {
        /// The length the other arguments have.
        expected: usize,
        /// The length this one has.
        found: usize,
    },
    /// A segment start earlier than the segment before it.
    DecreasingStart {
        /// The previous segment's start.
        previous: f64,
        /// This segment's start.
        start: f64,
    },
    /// A path with no segment.
    NoSegments,
    /// A time earlier than an event calendar's current time.
    BeforeCurrentTime {
        /// The time given.
        time: f64,
        /// The calendar's current time.
        current: f64,
    },
    /// Paths of one update that start at different times.
    StartsDiffer {
        /// The first path's start.
        first: f64,
        /// This path's start.
        start: f64,
    },
    /// A ball index beyond the number of balls.
    IndexOutOfRange {
        /// The index given.
        index: i64,
        /// The number of balls.
        len: usize,
    },
    /// A ball index given twice in one update.
    RepeatedIndex(usize),
    /// A number that must lie in `[0, 1]` (a coefficient of restitution).
    NotInUnitInterval(f64),
    /// A mass that is zero or negative.
    NonPositiveMass(f64),
    /// A simulation with no end: no end time, no event limit, and a ball that never stops.
    Endless,
    /// The call was stopped from outside before it ended ([`crate::interrupt`]).
    Interrupted,
    /// A box whose low bound is not below its high bound on an axis.
    EmptyBox {
        /// The low bound.
        lo: f64,
        /// The high bound.
        hi: f64,
    },
    /// A ball that overlaps another at the start of a simulation.
    Overlap {
        /// The other ball.
        other: usize,
        /// How far the centres are apart.
        distance: f64,
        /// The sum of the two radii.
        contact: f64,
    },
    /// A ball that overlaps an object of the table (or lies in a target) at the start of a
    /// simulation.
    OverlapsObject {
        /// The object's kind.
        kind: crate::geometry::ObjectKind,
        /// The object's index among its kind.
        index: usize,
        /// How far the centre is from the object (for a target, from its centre).
        distance: f64,
    },
    /// A ball that overlaps a wall of the box, or lies outside it, at the start of a
    /// simulation.
    OutsideBox {
        /// The axis of the wall.
        axis: usize,
    },
    /// A ball at least as wide as the box on an axis: it would touch both walls at once.
    WiderThanBox {
        /// The axis.
        axis: usize,
        /// The box's width on that axis.
        width: f64,
    },
    /// A simulation in which two balls (or a ball and a wall) keep colliding at one instant
    /// without time moving on.
    NoProgress {
        /// The other ball of the last such event (`None`: a wall).
        other: Option<usize>,
        /// The instant.
        time: f64,
        /// How many events came at that instant.
        events: usize,
    },
    /// A segment (of static geometry) whose two ends are the same point.
    DegenerateSegment,
    /// A circle's radius (of static geometry) below zero.
    NegativeCircleRadius(f64),
    /// A target's radius (of static geometry) that is zero or negative.
    NonPositiveTargetRadius(f64),
    /// A plane's normal that is the zero vector.
    ZeroNormal,
    /// A segment's side that is not −1, 0 or 1.
    InvalidSide(i64),
    /// A dimension of a [`PoolTable`](crate::geometry::PoolTable) that breaks `rule`.
    TableDimension {
        /// The dimension given.
        value: f64,
        /// What it must be, e.g. `"must be > 0"`.
        rule: &'static str,
    },
    /// An acceleration of gravity that is zero or negative.
    NonPositiveGravity(f64),
    /// A cue's contact point off the ball: `a² + b² > 1` (the value is `a² + b²`).
    ContactOffBall(f64),
    /// A contact that the event's resolver could not resolve (for pooltool's cushion models:
    /// where pooltool fails, as for a ball not moving into the cushion), at `time`.
    UnresolvedContact {
        /// When the contact came.
        time: f64,
    },
    /// A friction ball whose inputs are finite but whose path is not: `part` of it (its
    /// deceleration `−v/τ`, its resting point `p + ½·v·τ`, or its stop time) overflows to
    /// `value`.
    PathOverflow {
        /// Which part of the path.
        part: &'static str,
        /// What it came to.
        value: f64,
    },
}

impl InputErrorKind {
    /// A stable name for the kind, for programs to branch on (Python's `InputError.kind`):
    /// its variant's name in snake case, e.g. `"negative_friction"`. The Python binding adds
    /// the kinds of what it checks itself (`"shape"`, `"not_numbers"`, `"out_of_range"`,
    /// `"out_layout"`, `"shared_memory"`); `docs/contract.md` §6 lists them all.
    ///
    /// ```
    /// use ballcollide::InputErrorKind;
    /// assert_eq!(InputErrorKind::NegativeFriction(-0.5).code(), "negative_friction");
    /// ```
    pub const fn code(&self) -> &'static str {
        match self {
            Self::NotFinite(_) => "not_finite",
            Self::NegativeFriction(_) => "negative_friction",
            Self::NonPositiveRadius(_) => "non_positive_radius",
            Self::NonPositiveBallRadius(_) => "non_positive_ball_radius",
            Self::InvalidHorizon(_) => "invalid_horizon",
            Self::LengthMismatch { .. } => "length_mismatch",
            Self::DecreasingStart { .. } => "decreasing_start",
            Self::NoSegments => "no_segments",
            Self::BeforeCurrentTime { .. } => "before_current_time",
            Self::StartsDiffer { .. } => "starts_differ",
            Self::IndexOutOfRange { .. } => "index_out_of_range",
            Self::RepeatedIndex(_) => "repeated_index",
            Self::NotInUnitInterval(_) => "not_in_unit_interval",
            Self::NonPositiveMass(_) => "non_positive_mass",
            Self::Endless => "endless",
            Self::Interrupted => "interrupted",
            Self::EmptyBox { .. } => "empty_box",
            Self::Overlap { .. } => "overlap",
            Self::OverlapsObject { .. } => "overlaps_object",
            Self::OutsideBox { .. } => "outside_box",
            Self::WiderThanBox { .. } => "wider_than_box",
            Self::NoProgress { .. } => "no_progress",
            Self::DegenerateSegment => "degenerate_segment",
            Self::NegativeCircleRadius(_) => "negative_circle_radius",
            Self::NonPositiveTargetRadius(_) => "non_positive_target_radius",
            Self::ZeroNormal => "zero_normal",
            Self::InvalidSide(_) => "invalid_side",
            Self::TableDimension { .. } => "table_dimension",
            Self::NonPositiveGravity(_) => "non_positive_gravity",
            Self::ContactOffBall(_) => "contact_off_ball",
            Self::UnresolvedContact { .. } => "unresolved_contact",
            Self::PathOverflow { .. } => "path_overflow",
        }
    }

    /// The offending number, where the kind has one (the value given; for a start earlier
    /// than the one before, that start; for a time before the calendar's, that time).
    ///
    /// ```
    /// use ballcollide::InputErrorKind;
    /// assert_eq!(InputErrorKind::NegativeFriction(-0.5).value(), Some(-0.5));
    /// assert_eq!(InputErrorKind::NoSegments.value(), None);
    /// ```
    pub const fn value(&self) -> Option<f64> {
        match *self {
            Self::NotFinite(x)
            | Self::NegativeFriction(x)
            | Self::NonPositiveRadius(x)
            | Self::NonPositiveBallRadius(x)
            | Self::InvalidHorizon(x)
            | Self::NotInUnitInterval(x)
            | Self::NonPositiveMass(x)
            | Self::NegativeCircleRadius(x)
            | Self::NonPositiveTargetRadius(x)
            | Self::NonPositiveGravity(x)
            | Self::ContactOffBall(x) => Some(x),
            Self::InvalidSide(side) => Some(side as f64),
            Self::TableDimension { value, .. } => Some(value),
            Self::DecreasingStart { start, .. } | Self::StartsDiffer { start, .. } => Some(start),
            Self::BeforeCurrentTime { time, .. } | Self::UnresolvedContact { time } => Some(time),
            Self::PathOverflow { value, .. } => Some(value),
            Self::IndexOutOfRange { index, .. } => Some(index as f64),
            Self::RepeatedIndex(i) => Some(i as f64),
            Self::EmptyBox { lo, .. } => Some(lo),
            Self::WiderThanBox { width, .. } => Some(width),
            Self::Overlap { distance, .. } | Self::OverlapsObject { distance, .. } => {
                Some(distance)
            }
            Self::LengthMismatch { found, .. } => Some(found as f64),
            Self::NoProgress { time, .. } => Some(time),
            Self::NoSegments
            | Self::Endless
            | Self::Interrupted
            | Self::OutsideBox { .. }
            | Self::DegenerateSegment
            | Self::ZeroNormal => None,
        }
    }
}

/// An invalid input: which argument, at which index (for batch calls), and why.
///
/// Its `Display` is a sentence meant for the user, e.g.
/// ``friction_a[12]: friction must be ≥ 0, got -0.5``.
///
/// ```
/// use ballcollide::{Ball, InputErrorKind};
/// use nalgebra::Vector2;
///
/// let err = Ball::new(Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), -0.5).unwrap_err();
/// assert_eq!(err.argument(), "friction");
/// assert_eq!(err.kind(), InputErrorKind::NegativeFriction(-0.5));
/// assert_eq!(err.to_string(), "friction: friction must be ≥ 0, got -0.5");
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InputError {
    argument: &'static str,
    index: Option<usize>,
    segment: Option<usize>,
    kind: InputErrorKind,
}

impl InputError {
    /// An error about `argument`.
    ///
    /// ```
    /// use ballcollide::{InputError, InputErrorKind};
    /// let err = InputError::new("contact_distance", InputErrorKind::NonPositiveRadius(0.0));
    /// assert_eq!(err.index(), None);
    /// let reason = "the contact distance (sum of the two radii) must be > 0, got 0";
    /// assert_eq!(err.to_string(), format!("contact_distance: {reason}"));
    /// ```
    pub const fn new(argument: &'static str, kind: InputErrorKind) -> Self {
        Self {
            argument,
            index: None,
            segment: None,
            kind,
        }
    }

    /// The same error, located at `index` of a batch.
    ///
    /// ```
    /// use ballcollide::{InputError, InputErrorKind};
    /// let err = InputError::new("t_max", InputErrorKind::InvalidHorizon(-1.0)).at(7);
    /// assert_eq!(err.index(), Some(7));
    /// assert!(err.to_string().starts_with("t_max[7]: "));
    /// ```
    pub const fn at(self, index: usize) -> Self {
        Self {
            index: Some(index),
            ..self
        }
    }

    /// The same error, about the segment it was located at ([`InputError::at`]) of the path of
    /// pair `pair` of a batch: printed `start_b[7, 2]` for pair 7, segment 2.
    ///
    /// ```
    /// use ballcollide::{InputError, InputErrorKind};
    /// let err = InputError::new("vel_b", InputErrorKind::NotFinite(f64::NAN)).at(2).in_pair(7);
    /// assert_eq!((err.index(), err.segment()), (Some(7), Some(2)));
    /// assert_eq!(err.to_string(), "vel_b[7, 2]: must be finite, got NaN");
    /// ```
    pub const fn in_pair(self, pair: usize) -> Self {
        Self {
            index: Some(pair),
            segment: self.index,
            ..self
        }
    }

    /// The same error, about another argument name (e.g. `position` → `pos_a`).
    ///
    /// ```
    /// use ballcollide::{InputError, InputErrorKind};
    /// let err = InputError::new("position", InputErrorKind::NotFinite(f64::NAN)).renamed("pos_a");
    /// assert_eq!(err.argument(), "pos_a");
    /// ```
    pub const fn renamed(self, argument: &'static str) -> Self {
        Self { argument, ..self }
    }

    /// The name of the offending argument (see [`InputError::new`]).
    pub const fn argument(&self) -> &'static str {
        self.argument
    }

    /// The index of the first offending element, for batch calls (see [`InputError::at`]).
    pub const fn index(&self) -> Option<usize> {
        self.index
    }

    /// The segment of a path, for errors in a batch of paths (see [`InputError::in_pair`]).
    pub const fn segment(&self) -> Option<usize> {
        self.segment
    }

    /// What is wrong.
    ///
    /// ```
    /// use ballcollide::{Ball, InputErrorKind};
    /// use nalgebra::Vector2;
    /// let err = Ball::new(Vector2::zeros(), Vector2::zeros(), f64::INFINITY).unwrap_err();
    /// assert_eq!(err.kind(), InputErrorKind::NotFinite(f64::INFINITY));
    /// ```
    pub const fn kind(&self) -> InputErrorKind {
        self.kind
    }
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.argument)?;
        match (self.index, self.segment) {
            (Some(i), Some(k)) => write!(f, "[{i}, {k}]")?,
            (Some(i), None) => write!(f, "[{i}]")?,
            _ => {}
        }
        write!(f, ": {}", self.kind)
    }
}

/// The reason alone, without the argument: `friction must be ≥ 0, got -0.5`.
///
/// ```
/// use ballcollide::InputErrorKind;
/// assert_eq!(InputErrorKind::NotFinite(f64::NAN).to_string(), "must be finite, got NaN");
/// // Magnitudes far from 1 in exponent form, as Python prints them.
/// assert_eq!(
///     InputErrorKind::NegativeFriction(-1e300).to_string(),
///     "friction must be ≥ 0, got -1e+300"
/// );
/// ```
impl fmt::Display for InputErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::NotFinite(x) => write!(f, "must be finite, got {}", Brief(x)),
            Self::NegativeFriction(x) => write!(f, "friction must be ≥ 0, got {}", Brief(x)),
            Self::NonPositiveRadius(x) => {
                write!(
                    f,
                    "the contact distance (sum of the two radii) must be > 0, got {}",
                    Brief(x)
                )
            }
            Self::NonPositiveBallRadius(x) => {
                write!(f, "a ball's radius must be > 0, got {}", Brief(x))
            }
            // The argument (`t_max`, `t_end`) is named by the error, not here.
            Self::InvalidHorizon(x) => write!(f, "must be ≥ 0 (∞ for none), got {}", Brief(x)),
            Self::LengthMismatch { expected, found } => {
                write!(f, "has {found} rows, expected {expected}")
            }
            Self::DecreasingStart { previous, start } => write!(
                f,
                "starts must not decrease, got {} after {}",
                Brief(start),
                Brief(previous)
            ),
            Self::NoSegments => f.write_str("a path needs at least one segment"),
            Self::BeforeCurrentTime { time, current } => write!(
                f,
                "must not be before the calendar's time {}, got {}",
                Brief(current),
                Brief(time)
            ),
            Self::StartsDiffer { first, start } => write!(
                f,
                "an update's paths must all start at one time, got {} after {}",
                Brief(start),
                Brief(first)
            ),
            Self::IndexOutOfRange { index, len } => {
                write!(f, "ball index must be in 0..{len}, got {index}")
            }
            Self::RepeatedIndex(i) => write!(f, "ball {i} is given more than once"),
            Self::NotInUnitInterval(x) => write!(f, "must be in [0, 1], got {}", Brief(x)),
            Self::NonPositiveMass(x) => write!(f, "mass must be > 0, got {}", Brief(x)),
            Self::Interrupted => f.write_str("interrupted before it ended"),
            Self::Endless => {
                f.write_str("a ball without friction never stops: give t_end or max_events")
            }
            Self::EmptyBox { lo, hi } => write!(
                f,
                "the box's low bound must be below its high bound, got {} and {}",
                Brief(lo),
                Brief(hi)
            ),
            Self::Overlap {
                other,
                distance,
                contact,
            } => write!(
                f,
                "the ball overlaps ball {other} at the start: its centre is {} from theirs, \
                 less than the sum of their radii {}",
                Brief(distance),
                Brief(contact)
            ),
            Self::OverlapsObject {
                kind,
                index,
                distance,
            } => write!(
                f,
                "the ball overlaps {} {index} of the table at the start: its centre is {} from it",
                kind.name(),
                Brief(distance)
            ),
            Self::OutsideBox { axis } => write!(
                f,
                "the ball overlaps a wall of the box on axis {axis} (or lies outside the box) \
                 at the start"
            ),
            Self::WiderThanBox { axis, width } => write!(
                f,
                "the ball must be narrower than the box, which is {} wide on axis {axis}",
                Brief(width)
            ),
            Self::NoProgress {
                other,
                time,
                events,
            } => {
                match other {
                    Some(j) => write!(f, "the ball and ball {j}")?,
                    None => f.write_str("the ball and a wall")?,
                }
                write!(
                    f,
                    " keep colliding at t = {}: {events} events at that instant",
                    Brief(time)
                )
            }
            Self::DegenerateSegment => f.write_str("a segment's two ends must differ"),
            Self::NegativeCircleRadius(x) => {
                write!(f, "a circle's radius must be ≥ 0, got {}", Brief(x))
            }
            Self::NonPositiveTargetRadius(x) => {
                write!(f, "a target's radius must be > 0, got {}", Brief(x))
            }
            Self::ZeroNormal => f.write_str("a plane's normal must not be zero"),
            Self::TableDimension { value, rule } => write!(f, "{rule}, got {}", Brief(value)),
            Self::InvalidSide(side) => {
                write!(f, "a segment's side must be -1, 0 or 1, got {side}")
            }
            Self::NonPositiveGravity(x) => write!(f, "gravity must be > 0, got {}", Brief(x)),
            Self::ContactOffBall(x) => write!(
                f,
                "the contact point must lie on the ball (a² + b² ≤ 1), got a² + b² = {}",
                Brief(x)
            ),
            Self::UnresolvedContact { time } => write!(
                f,
                "the contact at t = {} could not be resolved by its model",
                Brief(time)
            ),
            Self::PathOverflow { part, value } => write!(
                f,
                "the ball's {part} is beyond the range of float64 ({}), so its path cannot be \
                 represented",
                Brief(value)
            ),
        }
    }
}

/// A float as messages print it: the shortest digits that read back to it (`-0.5`, `0`,
/// `NaN`, `inf`), and magnitudes below 1e-4 or from 1e16 on in exponent form like Python's
/// `repr` (`-1e+300`, `1.5e-07`), so that a message never spells out hundreds of digits.
struct Brief(f64);

impl fmt::Display for Brief {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        if !x.is_finite() || x == 0.0 || (1e-4..1e16).contains(&x.abs()) {
            return write!(f, "{x}");
        }
        let scientific = format!("{x:e}"); // `-1e300`, `1.5e-7`
        match scientific.split_once('e') {
            Some((mantissa, exponent)) => {
                let (sign, digits) = match exponent.strip_prefix('-') {
                    Some(digits) => ('-', digits),
                    None => ('+', exponent),
                };
                write!(f, "{mantissa}e{sign}{digits:0>2}")
            }
            None => f.write_str(&scientific),
        }
    }
}

impl std::error::Error for InputError {}

/// `Ok(x)` if `x` is finite, else an error naming `argument`.
pub(crate) fn finite(argument: &'static str, x: f64) -> Result<f64, InputError> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(InputError::new(argument, InputErrorKind::NotFinite(x)))
    }
}

/// Checks a friction deceleration: finite and ≥ 0. Returns it with `−0.0` made `+0.0`: a
/// friction of `−0` is no friction, and the stop time `|v|/μ` formed from it must be `+∞`.
pub(crate) fn check_friction(argument: &'static str, friction: f64) -> Result<f64, InputError> {
    finite(argument, friction)?;
    if friction >= 0.0 {
        Ok(friction + 0.0)
    } else {
        Err(InputError::new(
            argument,
            InputErrorKind::NegativeFriction(friction),
        ))
    }
}

/// Checks a contact distance (the sum of two radii): finite and > 0.
pub(crate) fn check_contact_distance(
    argument: &'static str,
    distance: f64,
) -> Result<f64, InputError> {
    positive(argument, distance, InputErrorKind::NonPositiveRadius)
}

/// Checks one ball's radius (a scene's, a calendar's): finite and > 0.
pub(crate) fn check_ball_radius(argument: &'static str, radius: f64) -> Result<f64, InputError> {
    positive(argument, radius, InputErrorKind::NonPositiveBallRadius)
}

/// `Ok(x)` if `x` is finite and > 0, else an error naming `argument` (`kind` for `x ≤ 0`).
fn positive(
    argument: &'static str,
    x: f64,
    kind: fn(f64) -> InputErrorKind,
) -> Result<f64, InputError> {
    finite(argument, x)?;
    if x > 0.0 {
        Ok(x)
    } else {
        Err(InputError::new(argument, kind(x)))
    }
}

/// Checks a horizon (or an end time): ≥ 0, +∞ allowed.
pub(crate) fn check_horizon(argument: &'static str, t_max: f64) -> Result<f64, InputError> {
    if t_max >= 0.0 {
        Ok(t_max)
    } else {
        Err(InputError::new(
            argument,
            InputErrorKind::InvalidHorizon(t_max),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::Brief;

    #[test]
    fn floats_print_as_python_prints_them_but_whole_numbers_without_a_point() {
        let cases = [
            (-0.5, "-0.5"),
            (0.0, "0"),
            (-1.0, "-1"),
            (1e15, "1000000000000000"),
            (1e16, "1e+16"),
            (-1e300, "-1e+300"),
            (1.5e-7, "1.5e-07"),
            (1e-4, "0.0001"),
            (9.99e-5, "9.99e-05"),
            (f64::MAX, "1.7976931348623157e+308"),
            (f64::MIN_POSITIVE / 4.0, "5.562684646268003e-309"),
            (f64::NAN, "NaN"),
            (f64::NEG_INFINITY, "-inf"),
        ];
        for (x, text) in cases {
            assert_eq!(Brief(x).to_string(), text, "{x:e}");
        }
    }
}
