//! Real roots of polynomials of degree ≤ 4, as accurate as float64 allows.
//!
//! Every solver takes the coefficients highest degree first, returns the real roots sorted
//! ascending and counted with multiplicity in a [`RealRoots`] (no heap), and never divides by
//! a leading coefficient that may be zero or tiny without care: a vanishing leading
//! coefficient drops the degree.
//!
//! - [`solve_linear`], [`solve_quadratic`]: closed forms, the quadratic with a stable root
//!   formula and an FMA-compensated discriminant;
//! - [`solve_cubic`]: one root by Kahan's safeguarded Newton iteration, deflation, the stable
//!   quadratic, and a polishing step (not Cardano's formula);
//! - [`solve_quartic`]: Algorithm 1010 (Orellana & De Michele, ACM TOMS 2020) with both of its
//!   published Remarks (2022, 2024), Newton-polished factors and roots;
//! - [`eval`]: Horner evaluation.
//!
//! All of them rescale coefficients and variable by exact powers of two, so coefficients from
//! 1e-300 to 1e300 work, and treat a non-finite coefficient as "no polynomial": no root.
//! Exact multiple roots come back real and repeated. Accuracy against high-precision
//! references is measured in `tests/reference/poly.rs` and recorded in `docs/poly-accuracy.md`.

mod bracketed;
mod cubic;
mod horner;
mod newton_polygon;
mod quadratic;
mod quartic;
mod roots;
pub mod scaling;

pub use bracketed::bracketed_newton;
pub use cubic::solve_cubic;
pub use horner::eval;
pub use quadratic::{solve_linear, solve_quadratic};
pub use quartic::solve_quartic;
pub use roots::RealRoots;

/// The real roots of the polynomial with coefficients `coeffs`, highest degree first (like
/// `numpy.roots`), of degree 1 to 4 (2 to 5 coefficients): the solver for that degree.
/// Any other length gives no root.
///
/// ```
/// use ballcollide::poly::real_roots;
/// assert_eq!(real_roots(&[1.0, -3.0, 2.0]).as_slice(), &[1.0, 2.0]);
/// assert_eq!(real_roots(&[2.0, -1.0]).as_slice(), &[0.5]);
/// assert!(real_roots(&[1.0]).is_empty());
/// ```
pub fn real_roots(coeffs: &[f64]) -> RealRoots {
    match *coeffs {
        [a, b] => solve_linear(a, b),
        [a, b, c] => solve_quadratic(a, b, c),
        [a, b, c, d] => solve_cubic(a, b, c, d),
        [a, b, c, d, e] => solve_quartic(a, b, c, d, e),
        _ => RealRoots::empty(),
    }
}
