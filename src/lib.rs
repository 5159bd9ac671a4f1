//! # ballcollide
//!
//! When do two balls slowing under friction first touch? Each ball moves on a straight line,
//! decelerated by a constant friction until it stops; the gap between two such balls is a
//! quartic in time on each window between stop times, and the collision is its first
//! entry root. This crate computes it exactly (to the float64 floor), fast, and for
//! millions of pairs.
//!
//! - [`poly`]: real-root solvers for polynomials of degree ≤ 4.
#![warn(missing_docs)]

pub mod poly;
