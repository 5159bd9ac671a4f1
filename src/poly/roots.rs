//! [`RealRoots`]: the real roots of a polynomial of degree ≤ 4, on the stack.

use std::fmt;
use std::ops::Deref;

/// The real roots of a polynomial of degree at most four, sorted ascending and counted with
/// multiplicity (a double root appears twice).
///
/// It lives on the stack (no heap allocation) and dereferences to a slice, so every slice
/// method works on it.
///
/// # Example
/// ```
/// use ballcollide::poly::{solve_quadratic, RealRoots};
///
/// // (x − 1)² = x² − 2x + 1 has the double root 1.
/// let roots: RealRoots = solve_quadratic(1.0, -2.0, 1.0);
/// assert_eq!(roots.as_slice(), &[1.0, 1.0]);
/// assert_eq!(roots.len(), 2);
/// assert!(solve_quadratic(1.0, 0.0, 1.0).is_empty()); // x² + 1 has no real root
/// ```
#[derive(Clone, Copy, PartialEq)]
pub struct RealRoots {
    len: u8,
    values: [f64; 4],
}

impl RealRoots {
    /// The capacity: a polynomial of degree ≤ 4 has at most four real roots.
    pub const CAPACITY: usize = 4;

    /// No real root.
    ///
    /// ```
    /// assert!(ballcollide::poly::RealRoots::empty().is_empty());
    /// ```
    pub const fn empty() -> Self {
        Self {
            len: 0,
            values: [0.0; 4],
        }
    }

    /// Roots from a slice of at most four values, sorted ascending (NaN values are dropped:
    /// they are never roots; `−0.0` becomes `+0.0`).
    ///
    /// Values beyond the fourth are ignored.
    ///
    /// ```
    /// use ballcollide::poly::RealRoots;
    /// let r = RealRoots::from_unsorted(&[3.0, -1.0, 2.0]);
    /// assert_eq!(r.as_slice(), &[-1.0, 2.0, 3.0]);
    /// let z = RealRoots::from_unsorted(&[-0.0]);
    /// assert!(z[0].is_sign_positive());
    /// ```
    pub fn from_unsorted(values: &[f64]) -> Self {
        let mut roots = Self::empty();
        for &x in values.iter().take(Self::CAPACITY) {
            roots.push(x);
        }
        roots.sort();
        roots
    }

    /// Appends one root (kept unsorted until [`RealRoots::sort`]); NaN is ignored and so is a
    /// fifth value. A zero root is stored as `+0.0`: its sign means nothing, and keeping it
    /// would make the roots' bits depend on the signs of zero coefficients (`−b/a` with
    /// `b = ±0`).
    pub(crate) fn push(&mut self, x: f64) {
        let n = self.len as usize;
        if n < Self::CAPACITY && !x.is_nan() {
            self.values[n] = if x == 0.0 { 0.0 } else { x };
            self.len += 1;
        }
    }

    /// Sorts the roots ascending (insertion sort: at most four values).
    pub(crate) fn sort(&mut self) {
        let n = self.len as usize;
        for i in 1..n {
            let mut j = i;
            while j > 0 && self.values[j - 1] > self.values[j] {
                self.values.swap(j - 1, j);
                j -= 1;
            }
        }
    }

    /// The roots as a slice, ascending.
    pub fn as_slice(&self) -> &[f64] {
        &self.values[..self.len as usize]
    }
}

impl Default for RealRoots {
    fn default() -> Self {
        Self::empty()
    }
}

impl Deref for RealRoots {
    type Target = [f64];
    fn deref(&self) -> &[f64] {
        self.as_slice()
    }
}

impl fmt::Debug for RealRoots {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_list().entries(self.as_slice()).finish()
    }
}

impl<'a> IntoIterator for &'a RealRoots {
    type Item = &'a f64;
    type IntoIter = std::slice::Iter<'a, f64>;
    fn into_iter(self) -> Self::IntoIter {
        self.as_slice().iter()
    }
}
