//! The integration tests, one binary (one build of the batch and the calendar for all of them):
//! properties (symmetries, units, advancing along the paths), invariants against exact
//! arithmetic, the calendar and `simulate` against brute force, semantics and known hard
//! cases. The tests against the reference data in `tests/data` are the other binary,
//! `tests/reference`. Run one module with `cargo test --test integration schedule::`;
//! ARCHITECTURE.md lists which module tests what.

#[path = "../support/mod.rs"]
mod support;

mod billiards;
mod collision_properties;
mod collision_semantics;
mod collision_vs_quartic;
mod geometry_properties;
mod invariants_batch;
mod invariants_geometry;
mod invariants_pair;
mod invariants_path;
mod invariants_poly;
mod invariants_scene;
mod narrow_properties;
mod path_batch;
mod path_properties;
mod poly_properties;
mod scene;
mod schedule;
mod silent_wrong_answers;
mod simulation_progress;
mod simulation_table;
