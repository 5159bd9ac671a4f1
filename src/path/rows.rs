//! [`Path::from_rows`]: a path from the rows of the batch arrays, with their padding convention.

use super::{Path, Segment, piecewise::Names, piecewise::check_order};
use crate::error::{InputError, InputErrorKind};

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
        let used = used_rows(start)?;
        let segments = (0..used)
            .map(|k| Segment::new(start[k], pos[k].into(), vel[k].into(), acc[k].into()))
            .collect();
        Self::checked(segments, &NAMES)
    }
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
