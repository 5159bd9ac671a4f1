//! Input decoders for the fuzz targets, and the invariants they check (shared with the
//! property tests in `tests/invariants.rs`).
//!
//! libFuzzer's bytes are read as numbers over the whole float range: exponents from −1074 to
//! 1023, both zeros, small integers and dyadic fractions (which make contacts likely), numbers
//! of a table's size with full mantissas, all multiplied by one power of two per case (so that
//! a whole configuration sits at 2^±500, say).

use arbitrary::{Result, Unstructured};
use ballcollide::poly::scaling::scale;

#[path = "../../tests/support/exact.rs"]
mod exact;
#[path = "../../tests/support/geometry_invariants.rs"]
pub mod geometry_invariants;
#[path = "../../tests/support/invariants.rs"]
pub mod invariants;
#[path = "../../tests/support/narrow_pairs.rs"]
pub mod narrow_pairs;
#[path = "../../tests/support/path_invariants.rs"]
pub mod path_invariants;
#[path = "../../tests/support/path_table.rs"]
mod path_table;
#[path = "../../tests/support/rng.rs"]
mod rng;
#[path = "../../tests/support/schedule_invariants.rs"]
pub mod schedule_invariants;
#[path = "../../tests/support/simulation_invariants.rs"]
pub mod simulation_invariants;

use geometry_invariants::{DiscObject, GeometryCase, PlaneObject, SegmentObject};
use invariants::{BallInput, PairCase, SceneCase, Shared};
use narrow_pairs::NarrowDraw;
use path_invariants::{PathCase, SegmentInput};
use rng::Rng;
use schedule_invariants::{Choices, Compare, Draw, Numbers, Plan, Scene};

/// Inputs that start with this are read literally (see [`Raw`]) instead of decoded: the form of
/// the regression corpus, which stays the same input whatever the decoders become.
pub const RAW: &[u8] = b"raw:";

/// A literal input after [`RAW`]: little-endian `f64`, `i32` and `u32` values in the order the
/// case's fields are listed (`fuzz/raw_input.py` writes them).
pub struct Raw<'a>(&'a [u8]);

impl<'a> Raw<'a> {
    /// The literal reader, if `data` starts with [`RAW`].
    pub fn of(data: &'a [u8]) -> Option<Self> {
        data.strip_prefix(RAW).map(Self)
    }

    fn take<const N: usize>(&mut self) -> Option<[u8; N]> {
        let (head, rest) = self.0.split_first_chunk::<N>()?;
        self.0 = rest;
        Some(*head)
    }

    /// The next `f64`.
    pub fn f64(&mut self) -> Option<f64> {
        self.take().map(f64::from_le_bytes)
    }

    /// The next `i32`.
    pub fn i32(&mut self) -> Option<i32> {
        self.take().map(i32::from_le_bytes)
    }

    /// The next `u32`, as a count (at most `max`).
    pub fn count(&mut self, max: usize) -> Option<usize> {
        let n = usize::try_from(u32::from_le_bytes(self.take()?)).ok()?;
        (n <= max).then_some(n)
    }

    fn ball(&mut self) -> Option<BallInput> {
        Some([
            self.f64()?,
            self.f64()?,
            self.f64()?,
            self.f64()?,
            self.f64()?,
        ])
    }

    fn pair(&mut self) -> Option<PairCase> {
        Some(PairCase {
            a: self.ball()?,
            b: self.ball()?,
            radius: self.f64()?,
            t_max: self.f64()?,
        })
    }

    /// A pair: ball A (x, y, vx, vy, friction), ball B, radius, t_max; then k, m.
    pub fn pair_case(mut self) -> Option<(PairCase, i32, i32)> {
        Some((self.pair()?, self.i32()?, self.i32()?))
    }

    /// A batch: the number of pairs, each pair as in [`Raw::pair_case`] without k and m, then
    /// four bytes (non-zero: shared).
    pub fn batch_case(mut self) -> Option<(Vec<PairCase>, Shared)> {
        let n = self.count(1000)?;
        let cases = (0..n).map(|_| self.pair()).collect::<Option<Vec<_>>>()?;
        let s = self.take::<4>()?;
        Some((cases, s.map(|b| b != 0)))
    }

    /// A scene: the number of balls, each ball and its radius, t_max, k.
    pub fn scene_case(mut self) -> Option<(SceneCase, i32)> {
        let n = self.count(1000)?;
        let (mut balls, mut radii) = (Vec::new(), Vec::new());
        for _ in 0..n {
            balls.push(self.ball()?);
            radii.push(self.f64()?);
        }
        let t_max = self.f64()?;
        Some((
            SceneCase {
                balls,
                radii,
                t_max,
            },
            self.i32()?,
        ))
    }

    fn path(&mut self) -> Option<Vec<SegmentInput>> {
        let n = self.count(64)?;
        (0..n)
            .map(|_| {
                let mut s = [0.0; 10];
                for x in &mut s {
                    *x = self.f64()?;
                }
                Some(s)
            })
            .collect()
    }

    /// A path query: four bytes (non-zero: 3-D), path A (the number of segments, each as
    /// start and three components of position, velocity, acceleration), path B, radius,
    /// t_max, k.
    pub fn path_case(mut self) -> Option<(PathCase, i32)> {
        let three_d = self.take::<4>()? != [0; 4];
        let (a, b) = (self.path()?, self.path()?);
        let case = PathCase {
            a,
            b,
            radius: self.f64()?,
            t_max: self.f64()?,
            three_d,
        };
        Some((case, self.i32()?))
    }

    fn floats<const N: usize>(&mut self) -> Option<[f64; N]> {
        let mut x = [0.0; N];
        for v in &mut x {
            *v = self.f64()?;
        }
        Some(x)
    }

    fn objects<T>(&mut self, mut one: impl FnMut(&mut Self) -> Option<T>) -> Option<Vec<T>> {
        let n = self.count(64)?;
        (0..n).map(|_| one(self)).collect()
    }

    /// Balls against static geometry: four bytes (non-zero: 3-D); the number of paths, each
    /// as in [`Raw::path_case`]; the number of segments, each as `P`, `Q` (`x, y` each) and
    /// its side (an `i32`); the number of circles, each as its centre (`x, y, z`) and `ρ`;
    /// the targets likewise; the number of planes, each as its point and normal (`x, y, z`
    /// each); the radius, t_max; k, j.
    pub fn geometry_case(mut self) -> Option<(GeometryCase, i32, i32)> {
        let three_d = self.take::<4>()? != [0; 4];
        let paths = self.objects(Self::path)?;
        let segments = self.objects(|r| Some((r.floats::<4>()?, i64::from(r.i32()?))))?;
        let circles = self.objects(Self::floats::<4>)?;
        let targets = self.objects(Self::floats::<4>)?;
        let planes = self.objects(Self::floats::<6>)?;
        let case = GeometryCase {
            paths,
            segments,
            circles,
            targets,
            planes,
            radius: self.f64()?,
            t_max: self.f64()?,
            three_d,
        };
        Some((case, self.i32()?, self.i32()?))
    }

    /// A polynomial: the number of coefficients, the coefficients, k, m.
    pub fn poly_case(mut self) -> Option<(Vec<f64>, i32, i32)> {
        let n = self.count(16)?;
        let c = (0..n).map(|_| self.f64()).collect::<Option<Vec<_>>>()?;
        Some((c, self.i32()?, self.i32()?))
    }
}

/// Any finite float, most often far from 1: a random exponent in −1074..=1023 and mantissa, or
/// ±0, or a small integer.
pub fn wide(u: &mut Unstructured) -> Result<f64> {
    let kind: u8 = u.arbitrary()?;
    Ok(match kind % 8 {
        0 => 0.0,
        1 => -0.0,
        2 => f64::from(u.arbitrary::<i8>()?),
        _ => {
            let e: i32 = u.int_in_range(-1074..=1023)?;
            let mantissa = u.arbitrary::<u64>()? >> 12;
            let unit = f64::from_bits((1023u64 << 52) | mantissa); // in [1, 2)
            let x = scale(unit, e);
            if u.arbitrary::<bool>()? { -x } else { x }
        }
    })
}

/// A small dyadic number `i/2^j` (`|i| < 2^15`, `0 ≤ j ≤ 8`), sometimes ±0.
pub fn small(u: &mut Unstructured) -> Result<f64> {
    let kind: u8 = u.arbitrary()?;
    Ok(match kind % 16 {
        0 => 0.0,
        1 => -0.0,
        _ => f64::from(u.arbitrary::<i16>()? / 2) / f64::from(1u16 << u.int_in_range(0..=8)?),
    })
}

/// A number like a table's: a full 52-bit mantissa, magnitude from 1/16 to 4, either sign.
pub fn table(u: &mut Unstructured) -> Result<f64> {
    let mantissa = u.arbitrary::<u64>()? >> 12;
    let x = scale(
        f64::from_bits((1023u64 << 52) | mantissa),
        u.int_in_range(-4..=1)?,
    );
    Ok(if u.arbitrary::<bool>()? { -x } else { x })
}

/// The power of two a case is scaled by: `2^0` half of the time, else any exponent.
pub fn case_scale(u: &mut Unstructured) -> Result<i32> {
    Ok(if u.arbitrary::<bool>()? {
        0
    } else {
        u.int_in_range(-1074..=1023)?
    })
}

/// A length-like number times `2^s`: [`small`] or [`table`], sometimes [`wide`] instead.
fn length(u: &mut Unstructured, s: i32) -> Result<f64> {
    Ok(match u.arbitrary::<u8>()? % 5 {
        0 => wide(u)?,
        1 | 2 => scale(table(u)?, s),
        _ => scale(small(u)?, s),
    })
}

/// A friction: 0, −0, a small one times `2^s` or times a further power of two (a ball that
/// barely decelerates: friction 1e-32 on a table), or any non-negative float.
fn friction(u: &mut Unstructured, s: i32) -> Result<f64> {
    let kind: u8 = u.arbitrary()?;
    Ok(match kind % 7 {
        0 => 0.0,
        1 => -0.0,
        2 => scale(small(u)?.abs(), s),
        3 => scale(small(u)?.abs(), s + u.int_in_range(-200..=40)?),
        4 => scale(table(u)?.abs(), s),
        _ => wide(u)?.abs(),
    })
}

/// A ball whose numbers are scaled by `2^s`.
pub fn ball(u: &mut Unstructured, s: i32) -> Result<BallInput> {
    Ok([
        length(u, s)?,
        length(u, s)?,
        length(u, s)?,
        length(u, s)?,
        friction(u, s)?,
    ])
}

/// A contact distance: a small positive one times `2^s`, or any positive float.
pub fn radius(u: &mut Unstructured, s: i32) -> Result<f64> {
    let r = if u.ratio(1, 4)? {
        wide(u)?.abs()
    } else {
        scale(small(u)?.abs(), s)
    };
    Ok(if r > 0.0 { r } else { scale(1.0, s) })
}

/// A horizon: none (∞), ±0, a small one, one of 1e10 … 1e300, or any non-negative float.
pub fn t_max(u: &mut Unstructured) -> Result<f64> {
    let kind: u8 = u.arbitrary()?;
    Ok(match kind % 8 {
        0..=2 => f64::INFINITY,
        3 => 0.0,
        4 => -0.0,
        5 => small(u)?.abs(),
        6 => 10f64.powi(u.int_in_range(10..=300)?),
        _ => wide(u)?.abs(),
    })
}

/// A pair query with the exponents of a length scaling and of a time scaling.
pub fn pair_case(u: &mut Unstructured) -> Result<(PairCase, i32, i32)> {
    let s = case_scale(u)?;
    let case = PairCase {
        a: ball(u, s)?,
        b: ball(u, s)?,
        radius: radius(u, s)?,
        t_max: t_max(u)?,
    };
    Ok((
        case,
        u.int_in_range(-1100..=1100)?,
        u.int_in_range(-600..=600)?,
    ))
}

/// A batch of 1 to 40 pair queries (sharing one scale) and which parameters are shared.
pub fn batch_case(u: &mut Unstructured) -> Result<(Vec<PairCase>, Shared)> {
    let s = case_scale(u)?;
    let n = u.int_in_range(1..=40)?;
    let mut cases = Vec::with_capacity(n);
    for _ in 0..n {
        cases.push(PairCase {
            a: ball(u, s)?,
            b: ball(u, s)?,
            radius: radius(u, s)?,
            t_max: t_max(u)?,
        });
    }
    let shared = [
        u.arbitrary()?,
        u.arbitrary()?,
        u.arbitrary()?,
        u.arbitrary()?,
    ];
    Ok((cases, shared))
}

/// A scene of 2 to 12 balls (sharing one scale) with the exponent of a length scaling.
pub fn scene_case(u: &mut Unstructured) -> Result<(SceneCase, i32)> {
    let s = case_scale(u)?;
    let n = u.int_in_range(2..=12)?;
    let mut balls = Vec::with_capacity(n);
    let mut radii = Vec::with_capacity(n);
    for _ in 0..n {
        balls.push(ball(u, s)?);
        radii.push(radius(u, s)?);
    }
    let case = SceneCase {
        balls,
        radii,
        t_max: t_max(u)?,
    };
    Ok((case, u.int_in_range(-1100..=1100)?))
}

/// Polynomial coefficients (2 to 5, highest degree first), with the exponents of a scaling of
/// the coefficients and of the variable.
pub fn poly_case(u: &mut Unstructured) -> Result<(Vec<f64>, i32, i32)> {
    let s = case_scale(u)?;
    let n = u.int_in_range(2..=5)?;
    let mut c = Vec::with_capacity(n);
    for _ in 0..n {
        // A coefficient may also be tiny or huge next to the others: 2^±k on top of the scale.
        let x = match u.arbitrary::<u8>()? % 4 {
            0 => wide(u)?,
            1 => scale(small(u)?, s + u.int_in_range(-1100..=1100)?),
            _ => scale(small(u)?, s),
        };
        c.push(x);
    }
    Ok((
        c,
        u.int_in_range(-1100..=1100)?,
        u.int_in_range(-300..=300)?,
    ))
}

/// A path of 1 to 6 segments whose numbers are scaled by `2^s`: starts from a first one
/// (0, small, or any) by durations that are small, table-like or any size (now and then
/// one that goes back in time; now and then 2²⁰…2⁴⁵ long), positions and velocities like
/// [`ball`]'s, accelerations like frictions of either sign (now and then subnormal); one path
/// in three ends at rest; one path in eight has one value no path may hold (NaN, ±∞), so
/// that the checks of invalid paths are fuzzed too.
fn path(u: &mut Unstructured, s: i32) -> Result<Vec<SegmentInput>> {
    let n = u.int_in_range(1..=6)?;
    let mut start = match u.arbitrary::<u8>()? % 4 {
        0 | 1 => 0.0,
        2 => small(u)?,
        _ => wide(u)?,
    };
    let mut segments = Vec::with_capacity(n);
    for k in 0..n {
        if k > 0 {
            start += match u.arbitrary::<u8>()? % 17 {
                0 => -small(u)?.abs(),
                1 | 2 => 0.0,
                3 | 4 => wide(u)?.abs(),
                5..=9 => table(u)?.abs(),
                // Long segments, where an underflowing product costs most.
                16 => scale(1.0, u.int_in_range(20..=45)?),
                _ => small(u)?.abs(),
            };
        }
        let mut row = [0.0; 10];
        row[0] = start;
        for x in &mut row[1..7] {
            *x = length(u, s)?;
        }
        for x in &mut row[7..] {
            // Now and then a subnormal acceleration, `i·2⁻¹⁰⁷⁴`.
            let a = if u.ratio(1, 8)? {
                f64::from_bits(u.int_in_range(1..=63)?)
            } else {
                friction(u, s)?
            };
            *x = if u.arbitrary()? { -a } else { a };
        }
        segments.push(row);
    }
    // One path in three ends at rest, as a ball that stops (the chord screen's case).
    if u.ratio(1, 3)? {
        segments[n - 1][4..].fill(0.0);
    }
    if u.ratio(1, 8)? {
        let bad = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY][u.int_in_range(0..=2)?];
        let (k, i) = (u.int_in_range(0..=n - 1)?, u.int_in_range(0..=9)?);
        segments[k][i] = bad;
    }
    Ok(segments)
}

/// A query on two paths (sharing one scale, 2-D or 3-D) with the exponent of a length
/// scaling.
pub fn path_case(u: &mut Unstructured) -> Result<(PathCase, i32)> {
    let s = case_scale(u)?;
    let three_d = u.arbitrary()?;
    let case = PathCase {
        a: path(u, s)?,
        b: path(u, s)?,
        radius: radius(u, s)?,
        t_max: t_max(u)?,
        three_d,
    };
    Ok((case, u.int_in_range(-1100..=1100)?))
}

/// Now and then (one in `n`) a value no object may hold in place of one of `x`'s: NaN or ±∞.
fn now_and_then_bad(u: &mut Unstructured, x: &mut [f64], n: u32) -> Result<()> {
    if u.ratio(1, n)? {
        let bad = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY][u.int_in_range(0..=2)?];
        x[u.int_in_range(0..=x.len() - 1)?] = bad;
    }
    Ok(())
}

/// A segment whose numbers are scaled by `2^s`: its ends like a ball's position (now and
/// then the same point), a side of −1, 0 or 1 (now and then any number).
fn segment_object(u: &mut Unstructured, s: i32) -> Result<SegmentObject> {
    let mut e = [length(u, s)?, length(u, s)?, length(u, s)?, length(u, s)?];
    if u.ratio(1, 16)? {
        e[2] = e[0];
        e[3] = e[1];
    }
    now_and_then_bad(u, &mut e, 16)?;
    let side = match u.arbitrary::<u8>()? % 16 {
        0 => i64::from(u.arbitrary::<i32>()?),
        k => i64::from(k % 3) - 1,
    };
    Ok((e, side))
}

/// A circle or a target whose numbers are scaled by `2^s`: its centre like a ball's
/// position, its radius like a ball's (a circle's now and then 0), now and then ≤ 0.
fn disc_object(u: &mut Unstructured, s: i32) -> Result<DiscObject> {
    let mut c = [length(u, s)?, length(u, s)?, length(u, s)?, radius(u, s)?];
    match u.arbitrary::<u8>()? % 16 {
        0 => c[3] = 0.0,
        1 => c[3] = -c[3],
        2 => c[3] = -0.0,
        _ => {}
    }
    now_and_then_bad(u, &mut c, 16)?;
    Ok(c)
}

/// A plane whose point is scaled by `2^s`: its normal a small integer vector (now and then
/// 0), or any numbers.
fn plane_object(u: &mut Unstructured, s: i32) -> Result<PlaneObject> {
    let mut p = [length(u, s)?, length(u, s)?, length(u, s)?, 0.0, 0.0, 0.0];
    let any = u.ratio(1, 8)?;
    for n in &mut p[3..] {
        *n = if any {
            wide(u)?
        } else {
            f64::from(u.int_in_range(-2i8..=2)?)
        };
    }
    now_and_then_bad(u, &mut p, 16)?;
    Ok(p)
}

/// 0 to 3 objects made by `make` at scale `s`.
fn up_to_three<T>(
    u: &mut Unstructured,
    s: i32,
    make: fn(&mut Unstructured, i32) -> Result<T>,
) -> Result<Vec<T>> {
    let n = u.int_in_range(0..=3)?;
    (0..n).map(|_| make(u, s)).collect()
}

/// Balls against static geometry: 1 to 3 paths (as [`path_case`]'s) and 0 to 3 objects of
/// each kind (half the time no plane, else 1 or 2), sharing one scale, 2-D or 3-D, with the
/// exponents of a length scaling (any) and of a translation (about the case's scale).
pub fn geometry_case(u: &mut Unstructured) -> Result<(GeometryCase, i32, i32)> {
    let s = case_scale(u)?;
    let three_d = u.arbitrary()?;
    let n = u.int_in_range(1..=3)?;
    let paths = (0..n).map(|_| path(u, s)).collect::<Result<_>>()?;
    let segments = up_to_three(u, s, segment_object)?;
    let circles = up_to_three(u, s, disc_object)?;
    let targets = up_to_three(u, s, disc_object)?;
    // (Half the cases without a plane: a path that runs for ever meets most.)
    let planes = match u.arbitrary::<bool>()? {
        true => Vec::new(),
        false => (0..u.int_in_range(1..=2)?)
            .map(|_| plane_object(u, s))
            .collect::<Result<_>>()?,
    };
    let case = GeometryCase {
        paths,
        segments,
        circles,
        targets,
        planes,
        radius: radius(u, s)?,
        t_max: t_max(u)?,
        three_d,
    };
    let k = u.int_in_range(-1100..=1100)?;
    let j = s.saturating_add(u.int_in_range(-8..=8)?);
    Ok((case, k, j))
}

/// A simulation: 1 to 8 balls of radius `2^s·(1/64 … 1/4)` in a box `2^s·[0, 2]²`, each
/// anywhere in it (overlapping starts are common: refused, and checked to be so), at velocities
/// and frictions over the whole float range sometimes; one mass or one each (any positive
/// float); a restitution of 0, 1 or between; an end time from 1/256 to 64. One case in four
/// (decided by a byte after all the others, so that the inputs of the regression corpus,
/// which end before it, keep their cases) is a touching train instead ([`as_train`]).
pub fn simulation_case(u: &mut Unstructured) -> Result<simulation_invariants::SimulationCase> {
    let s = if u.arbitrary::<bool>()? {
        0
    } else {
        u.int_in_range(-500..=500)?
    };
    let n = u.int_in_range(1..=8)?;
    let side = scale(2.0, s);
    let mut balls = Vec::with_capacity(n);
    for _ in 0..n {
        let r = scale(f64::from(u.int_in_range(4..=64u8)?) / 256.0, s);
        let mut fraction = || -> Result<f64> { Ok(f64::from(u.arbitrary::<u16>()?) / 65535.0) };
        let at = [fraction()?, fraction()?];
        let v = [length(u, s)?, length(u, s)?];
        balls.push((at, r, v, friction(u, s)?));
    }
    let mass = if u.arbitrary::<bool>()? {
        vec![1.0]
    } else {
        (0..n)
            .map(|_| Ok(wide(u)?.abs().max(f64::from_bits(1))))
            .collect::<Result<_>>()?
    };
    let restitution = match u.arbitrary::<u8>()? % 4 {
        0 => 0.0,
        1 => 1.0,
        _ => f64::from(u.arbitrary::<u8>()?) / 255.0,
    };
    let t_end = f64::from(u.int_in_range(1..=16384u16)?) / 256.0;
    let case =
        simulation_invariants::SimulationCase::in_square(side, &balls, mass, restitution, t_end);
    // An input that ends here reads 0: no train.
    Ok(match u.arbitrary::<u8>()? % 4 {
        3 => as_train(case, u.arbitrary::<bool>()?),
        _ => case,
    })
}

/// `case`'s balls made a touching train: the first ball's radius, velocity and friction for
/// all, each centre two radii on from the last along the first ball's velocity (or along x if
/// it rests), as many as fit in the box; with `obstacle`, the last ball at rest (the train runs
/// into it: a Newton's cradle), else the train runs into a wall. Trains of touching balls
/// moving as one body are where a collision sets off the most events at one instant.
fn as_train(
    mut case: simulation_invariants::SimulationCase,
    obstacle: bool,
) -> simulation_invariants::SimulationCase {
    let Some(&[x, y, vx, vy, f]) = case.balls.first() else {
        return case;
    };
    let r = case.radii[0];
    let speed = vx.hypot(vy);
    let d = if speed > 0.0 && speed.is_finite() {
        [vx / speed, vy / speed]
    } else {
        [1.0, 0.0]
    };
    let fits = |p: [f64; 2]| (0..2).all(|k| p[k] >= case.lo[k] + r && p[k] <= case.hi[k] - r);
    let mut balls = Vec::new();
    for i in 0..16u32 {
        let step = 2.0 * r * f64::from(i);
        let p = [x + d[0] * step, y + d[1] * step];
        if !fits(p) {
            break;
        }
        balls.push([p[0], p[1], vx, vy, f]);
    }
    if obstacle
        && balls.len() > 1
        && let Some(last) = balls.last_mut()
    {
        last[2..4].copy_from_slice(&[0.0, 0.0]);
    }
    case.radii = vec![r; balls.len()];
    case.mass = vec![1.0];
    case.balls = balls;
    case
}

/// A simulation on a table: [`simulation_case`]'s balls and box, with 0 to 3 segments (each
/// capped by circles of radius 0 at its ends; sides both, left or right), 0 to 2 circles
/// (radius 0 now and then), 0 to 2 targets and 0 or 1 plane, anywhere in the box, and a
/// table restitution of 0, 1 or between. Balls that would start on an object or in a target
/// are left out (their refusal is `tests/integration/simulation_table.rs`' subject), so that most cases
/// run.
pub fn simulation_table_case(u: &mut Unstructured) -> Result<simulation_invariants::TableCase> {
    use ballcollide::geometry::{Circle, LineSegment, Plane, SegmentSide, Table, Target};
    use nalgebra::Vector2;
    // The table's choices first (short inputs still get objects), in units of the box.
    let mut fractions = [[0.0; 2]; 8];
    for point in &mut fractions {
        for c in point.iter_mut() {
            *c = f64::from(u.arbitrary::<u16>()?) / 65535.0;
        }
    }
    let segments = u.int_in_range(0..=3usize)?;
    let mut sides = [0u8; 3];
    for side in &mut sides {
        *side = u.arbitrary::<u8>()? % 4;
    }
    let circles = u.int_in_range(0..=2usize)?;
    let mut circle_sizes = [(0u8, 0u8); 2];
    for size in &mut circle_sizes {
        *size = (u.arbitrary::<u8>()?, u.arbitrary::<u8>()?);
    }
    let targets = u.int_in_range(0..=2usize)?;
    let target_sizes = [u.arbitrary::<u8>()?, u.arbitrary::<u8>()?];
    let plane = (u.arbitrary::<u8>()? % 3 == 0).then_some((
        f64::from(u.arbitrary::<i8>()?),
        f64::from(u.arbitrary::<i8>()?),
    ));
    let table_restitution = match u.arbitrary::<u8>()? % 4 {
        0 => 0.0,
        1 => 1.0,
        _ => f64::from(u.arbitrary::<u8>()?) / 255.0,
    };
    let case = simulation_case(u)?;
    let side = case.hi[0];
    let points: Vec<Vector2<f64>> = fractions
        .iter()
        .map(|f| Vector2::new(f[0] * side, f[1] * side))
        .collect();
    let mut table = Table::<2>::default();
    let kinds = [
        SegmentSide::Both,
        SegmentSide::Both,
        SegmentSide::Left,
        SegmentSide::Right,
    ];
    for k in 0..segments {
        let (p, q) = (points[2 * k], points[2 * k + 1]);
        if let Ok(segment) = LineSegment::new(p, q, kinds[usize::from(sides[k])]) {
            table.segments.push(segment);
            for end in [p, q] {
                if let Ok(cap) = Circle::new(end, 0.0) {
                    table.circles.push(cap);
                }
            }
        }
    }
    for (k, &(zero, size)) in circle_sizes.iter().enumerate().take(circles) {
        let rho = if zero % 4 == 0 {
            0.0
        } else {
            side * f64::from(size) / 1024.0
        };
        if let Ok(c) = Circle::new(points[6 + k], rho) {
            table.circles.push(c);
        }
    }
    for (k, &size) in target_sizes.iter().enumerate().take(targets) {
        let rho = side * (f64::from(size) + 1.0) / 1024.0;
        if let Ok(t) = Target::new(points[4 + k], rho) {
            table.targets.push(t);
        }
    }
    if let Some((x, y)) = plane
        && let Ok(plane) = Plane::new(points[0] * 0.25, Vector2::new(x, y))
    {
        table.planes.push(plane);
    }
    // Leave out the balls on an object (or touching one) or in a target.
    let case = case.clear_of(&table);
    Ok(simulation_invariants::TableCase {
        case,
        table,
        table_restitution,
    })
}

/// A pair of the narrow family (`tests/support/narrow_pairs.rs`): head on or off axis, the
/// contact distance down to 2⁻⁴⁰⁰ of the separation, for the invariant that every query gives
/// the same hit or miss for it.
pub fn narrow_draw(u: &mut Unstructured) -> Result<NarrowDraw> {
    let mut fractions = [0.0; 6];
    for f in &mut fractions {
        *f = f64::from(u.arbitrary::<u32>()?) / 4_294_967_296.0;
    }
    Ok(NarrowDraw {
        line: u.arbitrary()?,
        sideways: u.arbitrary()?,
        length: u.arbitrary()?,
        time: u.arbitrary()?,
        sep: u.arbitrary()?,
        xa: u.arbitrary()?,
        sa: u.arbitrary()?,
        sb: u.arbitrary()?,
        b_kind: u.arbitrary()?,
        fractions,
    })
}

/// libFuzzer's bytes as the choices of a calendar's case, scene and operations
/// (`tests/support/schedule_invariants.rs`), and once they run out, a generator seeded by a
/// hash of the whole input: a short input still makes a whole scene and run (libFuzzer's
/// inputs start at a few bytes and grow slowly), and any change of a byte changes the rest.
pub struct Bytes<'a> {
    bytes: Unstructured<'a>,
    rest: Rng,
}

impl<'a> Bytes<'a> {
    /// The choices in `data`, then those of a generator seeded by a hash of `data`.
    pub fn new(data: &'a [u8]) -> Self {
        // FNV-1a, made odd (the generator's state must not be 0).
        let hash = data.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &b| {
            (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
        });
        Self {
            bytes: Unstructured::new(data),
            rest: Rng(hash | 1),
        }
    }
}

impl Choices for Bytes<'_> {
    fn below(&mut self, n: u64) -> u64 {
        if self.bytes.is_empty() {
            self.rest.below(n)
        } else {
            self.bytes.int_in_range(0..=n - 1).unwrap_or(0)
        }
    }

    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        if self.bytes.is_empty() {
            return self.rest.uniform(lo, hi);
        }
        let bits = self.bytes.arbitrary::<u64>().unwrap_or(0) >> 11;
        lo + (hi - lo) * (bits as f64 / (1u64 << 53) as f64)
    }
}

/// A calendar's case: the scene's shape and scales, and the plan of its operations; the
/// scene's numbers and the operations are drawn from the choices after it ([`Bytes`]).
#[derive(Clone, Copy, Debug)]
pub struct ScheduleCase {
    pub three_d: bool,
    pub numbers: Numbers,
    pub scene: Scene,
    /// Exponents of the length and time scalings (`Draw::length`, `Draw::time`).
    pub length: i32,
    pub time: i32,
    pub spread: u32,
    /// How many times as many objects as the tests' tables (`Draw::objects`).
    pub objects: u64,
    pub steps: usize,
    pub plan: Plan,
}

impl Bytes<'_> {
    fn flag(&mut self) -> bool {
        self.below(2) == 1
    }

    /// Uniform in `lo..=hi`.
    fn int(&mut self, lo: i32, hi: i32) -> i32 {
        lo + self.below((hi - lo) as u64 + 1) as i32
    }
}

/// A calendar's case, from the first choices: 0 to 24 balls in 2-D or 3-D; walls, a table
/// and transitions each on or off; a horizon (none half of the time, else 0 or up to 16 time
/// units); the first start at 0, a small dyadic time either side, or late (up to 2⁸⁰); the
/// balls' first starts all at it or staggered; lengths scaled by `2^k` (`k = 0` half of the
/// time, else up to `2^±64` or over the whole float range), times by `2^m` (`m = 0` half of
/// the time, else up to `2^±100`), and half of the scenes with balls spread over up to
/// `2^±200` in speed, radius and distance (objects too); half of the tables with 2 to 8 times
/// as many objects at most as the tests' (up to 5 segments, 3 circles, 2 targets and a plane;
/// past 16 objects their grid has more than one cell); 1 to 64 steps; refusals every 1 to 16
/// steps and retirements every 1 to 24 (at a drawn phase).
pub fn schedule_case(c: &mut Bytes) -> ScheduleCase {
    let three_d = c.flag();
    let n = c.below(25) as usize;
    let numbers = if c.flag() {
        Numbers::Dyadic
    } else {
        Numbers::Full
    };
    let length = match c.below(4) {
        0 | 1 => 0,
        2 => c.int(-64, 64),
        _ => c.int(-1074, 1023),
    };
    let time = if c.flag() { 0 } else { c.int(-100, 100) };
    let spread = if c.flag() { 0 } else { c.int(1, 200) as u32 };
    let objects = if c.flag() { 1 } else { c.int(2, 8) as u64 };
    let t_max = match c.below(4) {
        0 | 1 => f64::INFINITY,
        2 => c.below(1 << 16) as f64 / 4096.0,
        _ => 0.0,
    };
    let start = match c.below(4) {
        0 | 1 => 0.0,
        2 => f64::from(c.int(-32768, 32767)) / 16.0,
        _ => scale(1.0, c.int(0, 80)),
    };
    let scene = Scene {
        n,
        walls: c.flag(),
        table: c.flag(),
        transitions: c.flag(),
        t_max,
        start,
        stagger: c.flag(),
    };
    let steps = c.int(1, 64) as usize;
    let refuse = c.int(1, 16) as usize;
    let retire = c.int(1, 24) as usize;
    let plan = Plan {
        refuse: (refuse, c.below(refuse as u64) as usize),
        retire: (retire, c.below(retire as u64) as usize),
        compare: Compare::WithinPromise,
    };
    ScheduleCase {
        three_d,
        numbers,
        scene,
        length,
        time,
        spread,
        objects,
        steps,
        plan,
    }
}

/// Runs a calendar's case on the choices that follow it (`tests/support/schedule_invariants.rs`);
/// with `BALLCOLLIDE_FUZZ_SHOW` set, prints what the run met (events by class, checks).
///
/// # Errors
/// The first invariant broken, with the case, the scene and the operations.
pub fn schedule_run<const D: usize>(case: &ScheduleCase, choices: Bytes) -> Result<(), String> {
    let size = 1.0 + (case.scene.n as f64).sqrt();
    let mut draw = Draw::new(choices, case.numbers, size);
    draw.length = scale(1.0, case.length);
    draw.time = scale(1.0, case.time);
    draw.spread = case.spread;
    draw.objects = case.objects;
    let (mut s, made) = match schedule_invariants::calendar::<D, _>(&mut draw, &case.scene) {
        Ok(Some(made)) => made,
        // Numbers scaled out of the float range: no valid scene.
        Ok(None) => return Ok(()),
        Err(e) => return Err(format!("{e}\ncase: {case:?}")),
    };
    let seen = schedule_invariants::play(&mut s, &mut draw, case.steps, case.plan)
        .map_err(|e| format!("{e}\ncase: {case:?}\nscene: {made:?}"))?;
    if std::env::var_os("BALLCOLLIDE_FUZZ_SHOW").is_some() {
        eprintln!("{seen:?}");
    }
    Ok(())
}
