//! The one dispatch point: a [`Kernel`] run at a [`Level`], inside a function compiled for
//! that level's features.

use super::Level;
#[cfg(target_arch = "x86_64")]
use super::{Avx2, Avx512};
use super::{Portable, Simd};

/// A batch's work on one chunk, generic over the level's operations.
///
/// Implementations mark [`Kernel::run`] `#[inline(always)]`: it is then compiled inside the
/// level's shim, with the level's features, and so is everything it inlines.
pub(crate) trait Kernel {
    /// What the work returns.
    type Output;

    /// The work, with the level's operations `s`.
    fn run<S: Simd>(self, s: S) -> Self::Output;
}

/// Runs `kernel` at `level` (a level this CPU lacks runs the portable copy: the same bits).
#[inline]
pub(crate) fn dispatch<K: Kernel>(level: Level, kernel: K) -> K::Output {
    match level {
        #[cfg(target_arch = "x86_64")]
        Level::Avx512 => {
            if let Some(s) = Avx512::new() {
                // SAFETY: the token proves the CPU has the shim's features.
                return unsafe { on_avx512(s, kernel) };
            }
        }
        #[cfg(target_arch = "x86_64")]
        Level::Avx2Fma => {
            if let Some(s) = Avx2::new() {
                // SAFETY: the token proves the CPU has the shim's features.
                return unsafe { on_avx2(s, kernel) };
            }
        }
        #[cfg(target_arch = "aarch64")]
        Level::Neon => {
            // (NEON is the aarch64 baseline: no shim.)
            if let Some(s) = super::Neon::new() {
                return on_neon(s, kernel);
            }
        }
        Level::Portable => {}
    }
    on_portable(kernel)
}

/// `kernel` on the portable operations, as a function of its own: `dispatch` is inlined into
/// each caller, and with the portable copy inside it every caller (each test included) would
/// compile the whole kernel again, at a build cost that doubled the test build.
#[inline(never)]
fn on_portable<K: Kernel>(kernel: K) -> K::Output {
    kernel.run(Portable)
}

/// Runs scalar `kernel` (its `run` given the portable operations) compiled with FMA at every
/// x86-64 level above the portable one: scalar stages whose `mul_add` would otherwise be a
/// library call each (the same exact result, so the same bits, at several times the cost).
/// The one place the scalar stages choose their copy, as [`dispatch`] is for the lanes.
#[inline]
pub(crate) fn dispatch_scalar<K: Kernel>(level: Level, kernel: K) -> K::Output {
    #[cfg(target_arch = "x86_64")]
    if level != Level::Portable {
        // SAFETY: every x86-64 level above the portable one has FMA, and `simd` hands out
        // only levels this CPU supports.
        return unsafe { on_fma(kernel) };
    }
    let _ = level;
    on_portable(kernel)
}

/// `kernel` on NEON, a function of its own for the reason `on_portable` is.
#[cfg(target_arch = "aarch64")]
#[inline(never)]
fn on_neon<K: Kernel>(s: super::Neon, kernel: K) -> K::Output {
    kernel.run(s)
}

/// `kernel` compiled with FMA, on the portable operations.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
unsafe fn on_fma<K: Kernel>(kernel: K) -> K::Output {
    kernel.run(Portable)
}

/// `kernel` compiled with AVX-512 (F, VL, DQ), AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma,avx512f,avx512vl,avx512dq")]
fn on_avx512<K: Kernel>(s: Avx512, kernel: K) -> K::Output {
    kernel.run(s)
}

/// `kernel` compiled with AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn on_avx2<K: Kernel>(s: Avx2, kernel: K) -> K::Output {
    kernel.run(s)
}
