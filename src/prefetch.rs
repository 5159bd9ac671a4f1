//! A hint to the CPU to bring a value's cache line in ahead of its use: where the addresses of
//! several reads are known before the first is needed (the rows of the next blocks of paths,
//! the calendar's candidates for a pair search), asking for all of them at once lets their
//! cache misses overlap instead of coming one after another.

/// Asks for the cache line holding `*value` in every level of the cache. A hint: it reads
/// nothing and cannot fault, whatever the pointer (x86-64's `prefetcht0`; elsewhere nothing).
#[inline(always)]
pub(crate) fn prefetch<T>(value: *const T) {
    #[cfg(target_arch = "x86_64")]
    {
        use core::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
        // SAFETY: a prefetch reads nothing and never faults, for any address (SSE, which
        // every x86-64 CPU has).
        unsafe { _mm_prefetch(value.cast::<i8>(), _MM_HINT_T0) };
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = value;
}
