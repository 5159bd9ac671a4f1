//! [`Path::from_rows`]: a path from the rows of the batch arrays, with their padding convention.

use super::piecewise::{Names, check_order, check_segments};
use super::{Path, Segment};
use crate::error::{InputError, InputErrorKind};
use nalgebra::SVector;

impl<const D: usize> Path<D> {
    /// The path whose segment `k` is row `k` of `start`, `pos`, `vel` and `acc`: the layout of
    /// one path in the batch functions' `(N, K)` and `(N, K, D)` arrays.
    ///
    /// Paths with fewer than `K` segments are padded at the end with unused rows whose start is
    /// `+∞`; those rows are dropped, and their other values are ignored (NaN allowed). A `+∞`
    /// start followed by a finite one is not padding, but starts that decrease.
    ///
    /// # Errors
    /// An [`InputError`] naming the argument (`start`, `pos`, `vel` or `acc`) and the row of
    /// the first offending value: `pos`, `vel` or `acc` with a row count other than
    /// `start.len()`; a NaN start or one earlier than the row before; a first start of `+∞`
    /// (no used row) or `−∞`; a NaN or infinite component in a used row; no rows at all.
    ///
    /// ```
    /// use ballcollide::path::Path2;
    /// use nalgebra::Vector2;
    ///
    /// // Two used segments and one padding row.
    /// let path = Path2::from_rows(
    ///     &[0.0, 2.0, f64::INFINITY],
    ///     &[[0.0, 0.0], [1.0, 0.0], [f64::NAN; 2]],
    ///     &[[1.0, 0.0], [0.0, 0.0], [f64::NAN; 2]],
    ///     &[[-0.5, 0.0], [0.0, 0.0], [f64::NAN; 2]],
    /// )?;
    /// assert_eq!(path.segments().len(), 2);
    /// assert_eq!(path.position_at(1.0), Vector2::new(0.75, 0.0));
    ///
    /// let rest = [[0.0; 2]; 3];
    /// let err = Path2::from_rows(&[0.0, f64::INFINITY, 1.0], &rest, &rest, &rest).unwrap_err();
    /// assert_eq!(err.to_string(), "start[2]: starts must not decrease, got 1 after inf");
    /// let err = Path2::from_rows(&[f64::INFINITY; 3], &rest, &rest, &rest).unwrap_err();
    /// assert_eq!(err.to_string(), "start[0]: must be finite, got inf");
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn from_rows(
        start: &[f64],
        pos: &[[f64; D]],
        vel: &[[f64; D]],
        acc: &[[f64; D]],
    ) -> Result<Self, InputError> {
        const NAMES: Names = Names {
            segments: "start",
            start: "start",
            position: "pos",
            velocity: "vel",
            acceleration: "acc",
        };
        for (argument, rows) in [("pos", pos.len()), ("vel", vel.len()), ("acc", acc.len())] {
            if rows != start.len() {
                let kind = InputErrorKind::LengthMismatch {
                    expected: start.len(),
                    found: rows,
                };
                return Err(InputError::new(argument, kind));
            }
        }
        let mut segments = Vec::new();
        let used = segments_from_rows([start], [pos, vel, acc], &NAMES, &mut segments)?;
        segments.truncate(used);
        Ok(Self::from_checked(segments))
    }
}

/// The used segments of one path's rows (of equal lengths), checked, into the first slots of
/// `buffer`; returns how many there are. A batch reuses one buffer for all its paths: it only
/// grows, and is written in place, field by field (a `Segment` built whole and pushed is
/// staged on the stack and read back wider than it was written, which stalls the store
/// forwarding of every row). Errors use `names` and the row.
#[inline(always)]
pub(crate) fn segments_from_rows<const D: usize>(
    [start]: [&[f64]; 1],
    [pos, vel, acc]: [&[[f64; D]]; 3],
    names: &Names,
    buffer: &mut Vec<Segment<D>>,
) -> Result<usize, InputError> {
    // The common case in one pass: starts in order, then padding (+∞) only, every used value
    // finite (`0·x` is ±0 for finite `x`, NaN otherwise). Anything else is checked
    // again below, slowly, to name the first offending value.
    let mut previous = f64::NEG_INFINITY;
    let mut common = true;
    let n = start.len().min(pos.len()).min(vel.len()).min(acc.len());
    let (starts, pos, vel, acc) = (&start[..n], &pos[..n], &vel[..n], &acc[..n]);
    if buffer.len() < n {
        buffer.resize(n, Segment::at_rest(0.0, SVector::zeros()));
    }
    let mut used = n;
    for (k, segment) in buffer[..n].iter_mut().enumerate() {
        let s = starts[k];
        if s == f64::INFINITY {
            common &= starts[k..].iter().all(|&x| x == f64::INFINITY);
            used = k;
            break;
        }
        let mut zero = 0.0 * s;
        for i in 0..D {
            zero += 0.0 * pos[k][i] + 0.0 * vel[k][i] + 0.0 * acc[k][i];
        }
        common &= (s >= previous) & (zero == 0.0);
        previous = s;
        segment.start = s;
        segment.position = pos[k].into();
        segment.velocity = vel[k].into();
        segment.acceleration = acc[k].into();
    }
    if common && used > 0 {
        return Ok(used);
    }
    let used = used_rows(start).map_err(|e| e.renamed(names.start))?;
    buffer.clear();
    buffer.extend(
        (0..used).map(|k| Segment::new(start[k], pos[k].into(), vel[k].into(), acc[k].into())),
    );
    check_segments(buffer, names)?;
    Ok(used)
}

/// The number of used rows: all but the trailing ones whose start is `+∞`.
///
/// The order of the starts is checked on every row first, padding included, so that a `+∞`
/// start followed by a finite one is reported as the decrease it is, at the finite one.
fn used_rows(start: &[f64]) -> Result<usize, InputError> {
    let mut previous = f64::NEG_INFINITY;
    for (k, &s) in start.iter().enumerate() {
        check_order("start", previous, s).map_err(|e| e.at(k))?;
        previous = s;
    }
    match start.iter().rposition(|&s| s != f64::INFINITY) {
        Some(last) => Ok(last + 1),
        None if start.is_empty() => Err(InputError::new("start", InputErrorKind::NoSegments)),
        None => Err(InputError::new("start", InputErrorKind::NotFinite(f64::INFINITY)).at(0)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::path::{Path2, Path3, Segment3};
    use nalgebra::Vector3;
    use proptest::prelude::*;

    const INF: f64 = f64::INFINITY;

    fn error(start: &[f64], pos: &[[f64; 2]], vel: &[[f64; 2]], acc: &[[f64; 2]]) -> InputError {
        match Path2::from_rows(start, pos, vel, acc) {
            Ok(path) => panic!("accepted {path:?}"),
            Err(err) => err,
        }
    }

    #[test]
    fn padding_rows_are_dropped_whatever_their_values() {
        let nan = [f64::NAN; 2];
        let path = Path2::from_rows(
            &[0.0, 1.0, INF, INF],
            &[[0.0, 0.0], [1.0, 1.0], nan, [INF, 0.0]],
            &[[1.0, 1.0], [0.0, 0.0], nan, nan],
            &[[0.0, 0.0], [0.0, 0.0], nan, nan],
        )
        .expect("valid rows");
        assert_eq!(path.segments().len(), 2);
        assert_eq!(path.position_at(INF), nalgebra::Vector2::new(1.0, 1.0));
    }

    #[test]
    fn a_path_of_padding_only_has_no_finite_first_start() {
        let rows = [[0.0; 2]; 2];
        let err = error(&[INF, INF], &rows, &rows, &rows);
        assert_eq!((err.argument(), err.index()), ("start", Some(0)));
        assert_eq!(err.kind(), InputErrorKind::NotFinite(INF));
        assert_eq!(err.to_string(), "start[0]: must be finite, got inf");
    }

    #[test]
    fn no_rows_is_no_segment() {
        let err = error(&[], &[], &[], &[]);
        assert_eq!(err.to_string(), "start: a path needs at least one segment");
    }

    #[test]
    fn padding_followed_by_a_used_row_is_a_decrease() {
        let rows = [[0.0; 2]; 4];
        let err = error(&[0.0, INF, INF, 3.0], &rows, &rows, &rows);
        assert_eq!((err.argument(), err.index()), ("start", Some(3)));
        assert_eq!(
            err.kind(),
            InputErrorKind::DecreasingStart {
                previous: INF,
                start: 3.0
            }
        );
        // An earlier decrease is reported first.
        let err = error(&[2.0, 1.0, INF, 3.0], &rows, &rows, &rows);
        assert_eq!(err.index(), Some(1));
    }

    #[test]
    fn a_nan_start_is_an_error_even_among_padding() {
        let rows = [[0.0; 2]; 3];
        let err = error(&[0.0, INF, f64::NAN], &rows, &rows, &rows);
        assert_eq!((err.argument(), err.index()), ("start", Some(2)));
        assert!(matches!(err.kind(), InputErrorKind::NotFinite(x) if x.is_nan()));
    }

    #[test]
    fn a_negative_infinite_first_start_is_not_finite() {
        let rows = [[0.0; 2]; 2];
        let err = error(&[f64::NEG_INFINITY, 0.0], &rows, &rows, &rows);
        assert_eq!(err.to_string(), "start[0]: must be finite, got -inf");
    }

    #[test]
    fn a_non_finite_value_in_a_used_row_names_its_array_and_row() {
        let ok = [[0.0; 2]; 3];
        let mut bad = ok;
        bad[1][1] = f64::NAN;
        let start = [0.0, 1.0, INF];
        for (argument, err) in [
            ("pos", error(&start, &bad, &ok, &ok)),
            ("vel", error(&start, &ok, &bad, &ok)),
            ("acc", error(&start, &ok, &ok, &bad)),
        ] {
            assert_eq!((err.argument(), err.index()), (argument, Some(1)));
            assert_eq!(
                err.to_string(),
                format!("{argument}[1]: must be finite, got NaN")
            );
        }
    }

    #[test]
    fn arrays_of_another_length_are_named() {
        let (three, two) = ([[0.0; 2]; 3], [[0.0; 2]; 2]);
        let start = [0.0, 1.0, 2.0];
        for (argument, err) in [
            ("pos", error(&start, &two, &three, &three)),
            ("vel", error(&start, &three, &two, &three)),
            ("acc", error(&start, &three, &three, &two)),
        ] {
            assert_eq!(
                err.to_string(),
                format!("{argument}: has 2 rows, expected 3")
            );
        }
    }

    proptest! {
        #[test]
        fn rows_give_the_path_of_their_used_segments(
            rows in prop::collection::vec(
                (0.0..1.0f64, prop::array::uniform9(-5.0..5.0f64)), 1..=5),
            padding in 0..3usize,
        ) {
            let mut start = 0.0;
            let segments: Vec<Segment3> = rows
                .iter()
                .map(|(dt, x)| {
                    start += dt;
                    let v = |i: usize| Vector3::new(x[i], x[i + 1], x[i + 2]);
                    Segment3::new(start, v(0), v(3), v(6))
                })
                .collect();
            // Each array padded with rows that must be ignored.
            let pad = std::iter::repeat_n([f64::NAN; 3], padding);
            let array = |f: fn(&Segment3) -> Vector3<f64>| -> Vec<[f64; 3]> {
                segments.iter().map(|s| f(s).into()).chain(pad.clone()).collect()
            };
            let starts: Vec<f64> = segments
                .iter()
                .map(|s| s.start)
                .chain(std::iter::repeat_n(INF, padding))
                .collect();
            let path = Path3::from_rows(
                &starts,
                &array(|s| s.position),
                &array(|s| s.velocity),
                &array(|s| s.acceleration),
            );
            prop_assert_eq!(path, Path3::new(segments));
        }
    }
}
