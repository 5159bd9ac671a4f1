//! The tests against the independent high-precision references in `tests/data` (mpmath at
//! 50+ digits from the exact binary value of the inputs, written by `tools/*_reference.py`)
//! and against pooltool's own functions and shots: one binary, left out of the published
//! crate with the data it reads. Run one with `cargo test --test reference collision::`
//! (`-- --nocapture` prints each table's error distribution).

#[path = "../support/mod.rs"]
mod support;

mod billiards;
mod collision;
mod geometry;
mod narrow;
mod path;
mod poly;
mod shots;
