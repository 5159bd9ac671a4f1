//! The level the vector code runs at: detected once, forced by `BALLCOLLIDE_SIMD` or
//! [`with_level`], and the levels a test must run ([`test_levels`]).
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

use std::sync::atomic::{AtomicU8, Ordering};
use std::sync::{Mutex, OnceLock};

/// An instruction-set level that the vector code has a copy for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Level {
    /// The target's baseline: the reference copy (x86-64: SSE2 without FMA, fused
    /// multiply-adds in software).
    Portable,
    /// aarch64 NEON (baseline there, with FMA): the portable copy.
    #[cfg(target_arch = "aarch64")]
    Neon,
    /// x86-64 AVX2 with FMA.
    #[cfg(target_arch = "x86_64")]
    Avx2Fma,
    /// x86-64 AVX-512 F, VL and DQ, with AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    Avx512,
}

impl Level {
    /// Every level of this target, narrowest first.
    pub const ALL: &'static [Level] = &[
        Level::Portable,
        #[cfg(target_arch = "aarch64")]
        Level::Neon,
        #[cfg(target_arch = "x86_64")]
        Level::Avx2Fma,
        #[cfg(target_arch = "x86_64")]
        Level::Avx512,
    ];

    /// The level's name, as `BALLCOLLIDE_SIMD` spells it.
    pub fn name(self) -> &'static str {
        match self {
            Level::Portable => "portable",
            #[cfg(target_arch = "aarch64")]
            Level::Neon => "neon",
            #[cfg(target_arch = "x86_64")]
            Level::Avx2Fma => "avx2",
            #[cfg(target_arch = "x86_64")]
            Level::Avx512 => "avx512",
        }
    }

    /// The level named `name` (as [`Level::name`] spells it), if this target has it.
    pub fn from_name(name: &str) -> Option<Level> {
        Level::ALL
            .iter()
            .copied()
            .find(|l| l.name().eq_ignore_ascii_case(name.trim()))
    }

    /// Whether this CPU runs the level's copy.
    pub fn supported(self) -> bool {
        match self {
            Level::Portable => true,
            #[cfg(target_arch = "aarch64")]
            Level::Neon => std::arch::is_aarch64_feature_detected!("neon"),
            #[cfg(target_arch = "x86_64")]
            Level::Avx2Fma => {
                std::arch::is_x86_feature_detected!("avx2")
                    && std::arch::is_x86_feature_detected!("fma")
            }
            #[cfg(target_arch = "x86_64")]
            Level::Avx512 => {
                Level::Avx2Fma.supported()
                    && std::arch::is_x86_feature_detected!("avx512f")
                    && std::arch::is_x86_feature_detected!("avx512vl")
                    && std::arch::is_x86_feature_detected!("avx512dq")
            }
        }
    }

    /// The levels this CPU runs, narrowest first (always [`Level::Portable`]).
    pub fn available() -> Vec<Level> {
        Level::ALL
            .iter()
            .copied()
            .filter(|l| l.supported())
            .collect()
    }

    /// The widest level this CPU runs.
    pub fn detected() -> Level {
        Level::ALL
            .iter()
            .copied()
            .rev()
            .find(|l| l.supported())
            .unwrap_or(Level::Portable)
    }

    fn code(self) -> u8 {
        1 + Level::ALL.iter().position(|&l| l == self).unwrap_or(0) as u8
    }

    fn of_code(code: u8) -> Option<Level> {
        Level::ALL.get(usize::from(code).checked_sub(1)?).copied()
    }
}

impl std::fmt::Display for Level {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The level asked for by `value` (`BALLCOLLIDE_SIMD`'s), or the reason it is not taken as
/// it is, and the level used instead: the widest supported level not above it.
fn resolve(value: Option<&str>) -> (Level, Option<String>) {
    let detected = Level::detected();
    let Some(value) = value.filter(|v| !v.trim().is_empty()) else {
        return (detected, None);
    };
    let Some(asked) = Level::from_name(value) else {
        let names: Vec<_> = Level::ALL.iter().map(|l| l.name()).collect();
        return (
            detected,
            Some(format!(
                "BALLCOLLIDE_SIMD={value:?} is not one of {names:?} on this target: using {detected}"
            )),
        );
    };
    if asked.supported() {
        return (asked, None);
    }
    let used = Level::ALL
        .iter()
        .copied()
        .rev()
        .find(|l| *l <= asked && l.supported())
        .unwrap_or(Level::Portable);
    (
        used,
        Some(format!(
            "BALLCOLLIDE_SIMD={asked}: this CPU lacks it, using {used}"
        )),
    )
}

/// The process's level without an override: `BALLCOLLIDE_SIMD`, else the detected one.
fn default_level() -> Level {
    static DEFAULT: OnceLock<Level> = OnceLock::new();
    *DEFAULT.get_or_init(|| {
        let value = std::env::var("BALLCOLLIDE_SIMD").ok();
        let (level, warning) = resolve(value.as_deref());
        if let Some(warning) = warning {
            eprintln!("ballcollide: {warning}");
        }
        level
    })
}

/// The level forced by [`with_level`] (0: none).
static FORCED: AtomicU8 = AtomicU8::new(0);

/// The level the vector code runs at now: the one [`with_level`] forces, else
/// `BALLCOLLIDE_SIMD`'s, else the widest this CPU has.
pub fn current() -> Level {
    Level::of_code(FORCED.load(Ordering::Relaxed)).unwrap_or_else(default_level)
}

/// Runs `f` with every batch (and every FMA copy of the scalar search) at `level`, in every
/// thread, then restores the level before. Calls are serialised (one forced level at a time);
/// the answers are the same bits at every level, only the speed differs.
///
/// # Panics
/// If this CPU lacks `level` (see [`Level::available`]).
pub fn with_level<R>(level: Level, f: impl FnOnce() -> R) -> R {
    assert!(
        level.supported(),
        "the SIMD level {level} is not supported by this CPU (it has {:?})",
        Level::available()
    );
    static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());
    let _guard = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    struct Restore(u8);
    impl Drop for Restore {
        fn drop(&mut self) {
            FORCED.store(self.0, Ordering::Relaxed);
        }
    }
    let _restore = Restore(FORCED.swap(level.code(), Ordering::Relaxed));
    f()
}

/// The levels a test must run: those named in `BALLCOLLIDE_REQUIRE_SIMD` (comma-separated,
/// e.g. `avx512,avx2`) must be supported, else this panics (so that CI on a machine without
/// them fails rather than passing untested); the result is every level this CPU has.
pub fn test_levels() -> Vec<Level> {
    if let Ok(required) = std::env::var("BALLCOLLIDE_REQUIRE_SIMD") {
        for name in required.split(',').filter(|n| !n.trim().is_empty()) {
            let level = Level::from_name(name).unwrap_or_else(|| {
                panic!("BALLCOLLIDE_REQUIRE_SIMD names {name:?}, not a level of this target")
            });
            assert!(
                level.supported(),
                "BALLCOLLIDE_REQUIRE_SIMD asks for {level}, which this CPU lacks (it has {:?})",
                Level::available()
            );
        }
    }
    Level::available()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_unsupported_levels_fall_back() {
        for &level in Level::ALL {
            assert_eq!(Level::from_name(level.name()), Some(level));
        }
        assert_eq!(resolve(None), (Level::detected(), None));
        assert_eq!(resolve(Some("portable")), (Level::Portable, None));
        let (level, warning) = resolve(Some("sse9"));
        assert_eq!(level, Level::detected());
        assert!(warning.expect("a warning").contains("sse9"));
        for &level in Level::ALL {
            let (used, warning) = resolve(Some(level.name()));
            assert!(used.supported() && used <= level);
            assert_eq!(warning.is_none(), level.supported());
        }
    }

    #[test]
    fn with_level_forces_and_restores() {
        let before = current();
        for level in test_levels() {
            assert_eq!(with_level(level, current), level);
            assert_eq!(current(), before);
        }
    }
}
