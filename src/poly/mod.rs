//! Real roots of polynomials of degree ≤ 4, as accurate as float64 allows.
//!
//! Every solver takes the coefficients highest degree first, returns the real roots sorted
//! ascending and counted with multiplicity in a [`RealRoots`] (no heap), and never divides by
//! a leading coefficient that may be zero or tiny without care: a vanishing leading
//! coefficient drops the degree.

mod bracketed;
mod quadratic;
mod roots;
pub mod scaling;

pub use bracketed::bracketed_newton;
pub use quadratic::{solve_linear, solve_quadratic};
pub use roots::RealRoots;
