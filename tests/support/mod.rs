//! What the tests share: random numbers, exact arithmetic, the reference tables' readers, the
//! property tests' strategies and the invariants they check. Both test binaries
//! (`tests/integration`, `tests/reference`) include this module; each file says what it is
//! for. The fuzz targets, examples and benches include single files of this folder by path
//! (`machine.rs`, `pool_balls.rs`, `table_pairs.rs`, `thread_cpu_time.rs` and
//! `timing_example.rs` are theirs alone), so a file names its siblings as `super::…`.
// Each binary uses a part of it.
#![allow(dead_code)]

pub mod cases;
pub mod exact;
pub mod fields;
pub mod geometry_invariants;
pub mod geometry_strategies;
pub mod invariants;
pub mod narrow_pairs;
pub mod path_invariants;
pub mod path_rows;
pub mod path_strategies;
pub mod path_table;
pub mod property_paths;
pub mod reference_table;
pub mod rng;
pub mod schedule_invariants;
pub mod shot_cases;
pub mod simulation_invariants;
pub mod strategies;
