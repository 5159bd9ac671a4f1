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
//! references is measured in `tests/poly_reference.rs` and recorded in `docs/poly-accuracy.md`.

mod bracketed;
mod cubic;
mod horner;
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
