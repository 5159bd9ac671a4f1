//! The vector code's one layer: which instruction-set level it runs at, and the operations
//! its lane stages are written in, once, for every level.
//!
//! - [`Level`] (`level.rs`): `Portable`, `Avx2Fma`, `Avx512` (x86-64), `Neon`
//!   (aarch64); detected once, forced by `BALLCOLLIDE_SIMD=portable|avx2|avx512|neon` or
//!   [`with_level`].
//! - `Simd` (`lanes.rs`): the operations on a block of eight pairs, one `f64` per pair in a
//!   vector and a truth value per pair in a mask (the level's own form, packed into bits
//!   where a stage hands its lanes on), with the semantics the stages' proofs rely on
//!   (`min`/`max` as `x < y ? x : y`, ordered compares, `ne` unordered, `mul_add` fused, two
//!   exact operations on the bits for the power-of-two units). One implementation
//!   per level, each a token type that only a CPU check makes: `Portable` (`[f64; 8]`
//!   arrays, the reference), `Avx2` (two `__m256d`), `Avx512` (one `__m512d`, masks in `k`
//!   registers), `Neon` (four `float64x2_t`).
//! - `dispatch` (`dispatch.rs`): the one place a batch picks its level, once per call, and
//!   runs its chunk kernel (generic over `Simd`) inside a function compiled for the level's
//!   features, so that every operation inlines to its instructions (and the scalar code the
//!   kernel calls is compiled with FMA where the level has it).
//!
//! Every level gives the same bits: the operations are correctly rounded IEEE-754 ones or
//! exact selections, and fused multiply-adds appear only where the code writes
//! `f64::mul_add` (exact in software without the FMA feature: the same result, slower). The
//! portable level is the reference; the tests run every level the CPU has against it
//! ([`test_levels`]).
//!
//! The stages are `#[inline(always)]` in optimised builds (a stage left out of line is
//! compiled without the level's features, and its operations become calls) and
//! `#[inline(never)]` in builds with debug assertions: unoptimised code gives every inlined
//! temporary its own stack slot, and the whole batch inlined into one shim took a 2 MiB frame,
//! more than a test thread's or a rayon worker's stack.
//!
//! Why a small trait of our own rather than `pulp` or `fearless_simd`: the stages' proofs
//! depend on the exact operations, their order and their NaN and signed-zero semantics
//! (`minpd`'s, not IEEE `minNum`'s, which is what generic SIMD crates give on NEON); the
//! trait states those in one place, with the score of operations the stages need and no
//! dependency;
//! and a stage written over it is read as the scalar proof it mirrors. Plain arrays left to
//! the compiler's vectoriser were tried first and cost twice the intrinsics' time (masks
//! packed from vectors of bools, rows gathered element by element).
//!
//! # Choosing the level
//! - By default: the widest level this CPU has ([`Level::detected`]).
//! - The environment variable `BALLCOLLIDE_SIMD=portable|avx2|avx512|neon`, read once: a
//!   level this CPU lacks (or an unknown name) falls back to the widest level it has that is
//!   not above the one asked for, with a warning on standard error, never an illegal
//!   instruction.
//! - [`with_level`] for tests and benchmarks: runs a closure with a level forced for the
//!   whole process (callers of `with_level` are serialised); it panics on a level this CPU
//!   lacks.

#[cfg(target_arch = "x86_64")]
mod avx2;
#[cfg(target_arch = "x86_64")]
mod avx512;
mod dispatch;
mod lanes;
mod level;
#[cfg(target_arch = "aarch64")]
mod neon;
mod portable;

#[cfg(target_arch = "x86_64")]
pub(crate) use avx2::Avx2;
#[cfg(target_arch = "x86_64")]
pub(crate) use avx512::Avx512;
pub(crate) use dispatch::{Kernel, dispatch, dispatch_scalar};
pub(crate) use lanes::{LANES, MOST, Mask, Simd, fraction_cleared, unit_scale};
pub use level::{Level, current, test_levels, with_level};
#[cfg(target_arch = "aarch64")]
pub(crate) use neon::Neon;
pub(crate) use portable::Portable;
