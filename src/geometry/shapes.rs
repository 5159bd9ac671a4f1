//! The static objects a ball can meet: [`LineSegment`] (with its [`SegmentSide`]),
//! [`Circle`], [`Target`] and [`Plane`], each checked when made, so that every query on
//! them is total.

use nalgebra::{SVector, Vector2};

use crate::error::{InputError, InputErrorKind, finite};

/// Which contacts with a [`LineSegment`] count: those from its left (`d > 0`, `d` the
/// signed distance of the centre from the line `P → Q`), from its right (`d < 0`), or both.
///
/// As numbers (the Python batch's `segment_sides`): `+1` left, `−1` right, `0` both.
///
/// ```
/// use ballcollide::geometry::SegmentSide;
/// assert_eq!(SegmentSide::from_sign(1)?, SegmentSide::Left);
/// assert_eq!(SegmentSide::Right.sign(), -1);
/// assert_eq!(SegmentSide::Left.flipped(), SegmentSide::Right);
/// let err = SegmentSide::from_sign(2).unwrap_err();
/// assert_eq!(err.to_string(), "side: a segment's side must be -1, 0 or 1, got 2");
/// # Ok::<(), ballcollide::InputError>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum SegmentSide {
    /// Contacts from either side count (`0`).
    #[default]
    Both,
    /// Only contacts from the left of `P → Q` count (`+1`): a cushion whose table lies there.
    Left,
    /// Only contacts from the right of `P → Q` count (`−1`).
    Right,
}

impl SegmentSide {
    /// The side of the number `sign`: `+1` left, `−1` right, `0` both (example:
    /// [`SegmentSide`]).
    ///
    /// # Errors
    /// An [`InputError`] naming `side` for any other number.
    pub fn from_sign(sign: i64) -> Result<Self, InputError> {
        match sign {
            0 => Ok(Self::Both),
            1 => Ok(Self::Left),
            -1 => Ok(Self::Right),
            _ => Err(InputError::new("side", InputErrorKind::InvalidSide(sign))),
        }
    }

    /// The side as a number: `+1` left, `−1` right, `0` both (example: [`SegmentSide`]).
    pub const fn sign(self) -> i64 {
        match self {
            Self::Both => 0,
            Self::Left => 1,
            Self::Right => -1,
        }
    }

    /// The side seen from the other end (`P` and `Q` swapped): left and right exchange
    /// (example: [`SegmentSide`]).
    pub const fn flipped(self) -> Self {
        match self {
            Self::Both => Self::Both,
            Self::Left => Self::Right,
            Self::Right => Self::Left,
        }
    }

    /// Whether a contact from the side of sign `sign` (of `d`: `+1`, `−1`, or 0 on the line
    /// itself) counts.
    pub(crate) fn counts(self, sign: i8) -> bool {
        match self {
            Self::Both => true,
            Self::Left => sign > 0,
            Self::Right => sign < 0,
        }
    }
}

/// A straight segment from `P` to `Q` in the plane (a cushion, a jaw's flat face, a wall at
/// any angle), whose flat part a ball of radius `r` touches when its centre comes within `r`
/// of the line `P → Q` at a point whose foot lies between `P` and `Q`
/// ([`path_segment_contact`](super::path_segment_contact)). Its ends are not part of it: a
/// rounded end is a [`Circle`] of radius 0 at `P` or `Q`, given as an object of its own.
///
/// ```
/// use ballcollide::geometry::{LineSegment, SegmentSide};
/// use nalgebra::Vector2;
///
/// let cushion = LineSegment::new(Vector2::new(0.0, 0.0), Vector2::new(2.0, 0.0), SegmentSide::Left)?;
/// assert_eq!(cushion.q(), Vector2::new(2.0, 0.0));
/// let reversed = cushion.reversed();
/// assert_eq!((reversed.p(), reversed.side()), (cushion.q(), SegmentSide::Right));
///
/// let err = LineSegment::new(Vector2::new(1.0, 1.0), Vector2::new(1.0, 1.0), SegmentSide::Both).unwrap_err();
/// assert_eq!(err.to_string(), "q: a segment's two ends must differ");
/// let err = LineSegment::new(Vector2::new(f64::NAN, 0.0), Vector2::zeros(), SegmentSide::Both).unwrap_err();
/// assert_eq!(err.to_string(), "p: must be finite, got NaN");
/// # Ok::<(), ballcollide::InputError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineSegment {
    p: Vector2<f64>,
    q: Vector2<f64>,
    side: SegmentSide,
}

impl LineSegment {
    /// The segment from `p` to `q`, touched from `side` (example: [`LineSegment`]).
    ///
    /// # Errors
    /// An [`InputError`] naming `p` or `q` for a NaN or infinite coordinate, and `q` when it
    /// equals `p`.
    pub fn new(p: Vector2<f64>, q: Vector2<f64>, side: SegmentSide) -> Result<Self, InputError> {
        finite_vector("p", &p)?;
        finite_vector("q", &q)?;
        if p == q {
            return Err(InputError::new("q", InputErrorKind::DegenerateSegment));
        }
        Ok(Self { p, q, side })
    }

    /// The first end, `P` (`u = 0`; example: [`LineSegment`]).
    pub fn p(&self) -> Vector2<f64> {
        self.p
    }

    /// The second end, `Q` (`u = 1`; example: [`LineSegment`]).
    pub fn q(&self) -> Vector2<f64> {
        self.q
    }

    /// Which contacts count (example: [`LineSegment`]).
    pub fn side(&self) -> SegmentSide {
        self.side
    }

    /// The same segment from `Q` to `P`: its side flipped, so that the same contacts count
    /// (example: [`LineSegment`]).
    pub fn reversed(&self) -> Self {
        Self {
            p: self.q,
            q: self.p,
            side: self.side.flipped(),
        }
    }
}

/// A disc of radius `ρ ≥ 0` about `C` that a ball touches from outside, its centre reaching
/// `ρ + r` from `C` ([`path_circle_contact`](super::path_circle_contact)): a jaw's rounded
/// tip, a post; with `ρ = 0`, the rounded end of a [`LineSegment`]. In 3-D (`D = 3`), a
/// sphere.
///
/// ```
/// use ballcollide::geometry::Circle;
/// use nalgebra::Vector2;
///
/// let tip = Circle::new(Vector2::new(1.0, 0.5), 0.01)?;
/// assert_eq!((tip.centre(), tip.rho()), (Vector2::new(1.0, 0.5), 0.01));
/// assert!(Circle::new(Vector2::new(1.0, 0.5), 0.0).is_ok()); // a point
/// let err = Circle::new(Vector2::new(1.0, 0.5), -0.5).unwrap_err();
/// assert_eq!(err.to_string(), "rho: a circle's radius must be ≥ 0, got -0.5");
/// # Ok::<(), ballcollide::InputError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Circle<const D: usize> {
    centre: SVector<f64, D>,
    rho: f64,
}

impl<const D: usize> Circle<D> {
    /// The circle about `centre` of radius `rho` (example: [`Circle`]).
    ///
    /// # Errors
    /// An [`InputError`] naming `centre` for a NaN or infinite coordinate, `rho` for a NaN or
    /// infinite radius or one below 0.
    pub fn new(centre: SVector<f64, D>, rho: f64) -> Result<Self, InputError> {
        let (centre, rho) = disc(
            centre,
            rho,
            rho >= 0.0,
            InputErrorKind::NegativeCircleRadius,
        )?;
        Ok(Self { centre, rho })
    }

    /// The centre `C` (example: [`Circle`]).
    pub fn centre(&self) -> SVector<f64, D> {
        self.centre
    }

    /// The radius `ρ` (example: [`Circle`]).
    pub fn rho(&self) -> f64 {
        self.rho
    }
}

/// A disc of radius `ρ > 0` about `C` that captures a ball when the ball's centre enters it,
/// whatever the ball's radius ([`path_target_contact`](super::path_target_contact)): a
/// pocket's capture circle, a goal mouth. In 3-D (`D = 3`), a ball of space.
///
/// ```
/// use ballcollide::geometry::Target;
/// use nalgebra::Vector2;
///
/// let pocket = Target::new(Vector2::new(0.0, 0.0), 0.06)?;
/// assert_eq!((pocket.centre(), pocket.rho()), (Vector2::zeros(), 0.06));
/// let err = Target::new(Vector2::new(0.0, 0.0), 0.0).unwrap_err();
/// assert_eq!(err.to_string(), "rho: a target's radius must be > 0, got 0");
/// # Ok::<(), ballcollide::InputError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Target<const D: usize> {
    centre: SVector<f64, D>,
    rho: f64,
}

impl<const D: usize> Target<D> {
    /// The target about `centre` of radius `rho` (example: [`Target`]).
    ///
    /// # Errors
    /// An [`InputError`] naming `centre` for a NaN or infinite coordinate, `rho` for a NaN or
    /// infinite radius or one that is not above 0.
    pub fn new(centre: SVector<f64, D>, rho: f64) -> Result<Self, InputError> {
        let valid = rho > 0.0;
        let (centre, rho) = disc(centre, rho, valid, InputErrorKind::NonPositiveTargetRadius)?;
        Ok(Self { centre, rho })
    }

    /// The centre `C` (example: [`Target`]).
    pub fn centre(&self) -> SVector<f64, D> {
        self.centre
    }

    /// The radius `ρ` (example: [`Target`]).
    pub fn rho(&self) -> f64 {
        self.rho
    }
}

/// The plane through `Q` with normal `n` (of any non-zero length), touched from the side `n`
/// points to: a ball of radius `r` touches it when the signed distance `n·(x − Q)/|n|` of its
/// centre comes down to `r` ([`path_plane_contact`](super::path_plane_contact)). A table's
/// bed under a ball in the air, a wall at any angle; in 2-D (`D = 2`), a line touched from
/// one side.
///
/// ```
/// use ballcollide::geometry::Plane;
/// use nalgebra::Vector3;
///
/// let bed = Plane::new(Vector3::zeros(), Vector3::new(0.0, 0.0, 2.0))?;
/// assert_eq!((bed.point(), bed.normal()), (Vector3::zeros(), Vector3::new(0.0, 0.0, 2.0)));
/// let err = Plane::new(Vector3::zeros(), Vector3::zeros()).unwrap_err();
/// assert_eq!(err.to_string(), "normal: a plane's normal must not be zero");
/// # Ok::<(), ballcollide::InputError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane<const D: usize> {
    point: SVector<f64, D>,
    normal: SVector<f64, D>,
}

impl<const D: usize> Plane<D> {
    /// The plane through `point` with `normal` (example: [`Plane`]).
    ///
    /// # Errors
    /// An [`InputError`] naming `point` or `normal` for a NaN or infinite coordinate, and
    /// `normal` for the zero vector.
    pub fn new(point: SVector<f64, D>, normal: SVector<f64, D>) -> Result<Self, InputError> {
        finite_vector("point", &point)?;
        finite_vector("normal", &normal)?;
        if normal.iter().all(|&x| x == 0.0) {
            return Err(InputError::new("normal", InputErrorKind::ZeroNormal));
        }
        Ok(Self { point, normal })
    }

    /// The point `Q` on the plane (example: [`Plane`]).
    pub fn point(&self) -> SVector<f64, D> {
        self.point
    }

    /// The normal `n`, as given: it points to the side the plane is touched from (example:
    /// [`Plane`]).
    pub fn normal(&self) -> SVector<f64, D> {
        self.normal
    }
}

/// The centre and radius of a disc (a circle's, a target's), checked: `centre` finite, `rho`
/// finite and `valid` (else an error of `kind`); a radius of −0 made 0.
fn disc<const D: usize>(
    centre: SVector<f64, D>,
    rho: f64,
    valid: bool,
    kind: fn(f64) -> InputErrorKind,
) -> Result<(SVector<f64, D>, f64), InputError> {
    finite_vector("centre", &centre)?;
    finite("rho", rho)?;
    if !valid {
        return Err(InputError::new("rho", kind(rho)));
    }
    Ok((centre, rho + 0.0))
}

/// `Ok` if every coordinate of `v` is finite, else an error naming `argument`.
fn finite_vector<const D: usize>(
    argument: &'static str,
    v: &SVector<f64, D>,
) -> Result<(), InputError> {
    for &x in v.iter() {
        finite(argument, x)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    #[test]
    fn every_bad_value_is_named() {
        let nan = f64::NAN;
        let inf = f64::INFINITY;
        let zero = Vector2::zeros();
        let one = Vector2::new(1.0, 0.0);
        let cases = [
            (
                LineSegment::new(Vector2::new(0.0, inf), one, SegmentSide::Both).err(),
                "p",
            ),
            (
                LineSegment::new(zero, Vector2::new(nan, 0.0), SegmentSide::Both).err(),
                "q",
            ),
            (LineSegment::new(one, one, SegmentSide::Left).err(), "q"),
            (Circle::new(Vector2::new(nan, 0.0), 1.0).err(), "centre"),
            (Circle::new(zero, inf).err(), "rho"),
            (Circle::new(zero, -1e-300).err(), "rho"),
            (Target::new(zero, -0.0).err(), "rho"),
            (Target::new(zero, nan).err(), "rho"),
            (Target::new(Vector2::new(0.0, -inf), 1.0).err(), "centre"),
            (Plane::new(Vector2::new(nan, 0.0), one).err(), "point"),
            (Plane::new(zero, Vector2::new(0.0, inf)).err(), "normal"),
            (Plane::new(zero, Vector2::new(-0.0, 0.0)).err(), "normal"),
        ];
        for (k, (err, argument)) in cases.into_iter().enumerate() {
            let err = err.unwrap_or_else(|| panic!("case {k} accepted"));
            assert_eq!(err.argument(), argument, "case {k}: {err}");
            assert_eq!(err.index(), None);
        }
        assert_eq!(
            SegmentSide::from_sign(i64::MIN).unwrap_err().kind(),
            InputErrorKind::InvalidSide(i64::MIN)
        );
    }

    #[test]
    fn good_values_are_kept_and_a_negative_zero_radius_is_zero() {
        let c = Circle::new(Vector3::new(1.0, 2.0, 3.0), -0.0).expect("valid");
        assert_eq!(c.rho().to_bits(), 0.0f64.to_bits());
        let t = Target::new(Vector2::new(1e300, -1e-300), 5e-324).expect("valid");
        assert_eq!(t.rho(), 5e-324);
        let p = Plane::new(Vector2::new(1.0, 1.0), Vector2::new(5e-324, 0.0)).expect("valid");
        assert_eq!(p.normal().x, 5e-324);
        for side in [SegmentSide::Both, SegmentSide::Left, SegmentSide::Right] {
            assert_eq!(SegmentSide::from_sign(side.sign()), Ok(side));
            assert_eq!(side.flipped().flipped(), side);
        }
    }
}
