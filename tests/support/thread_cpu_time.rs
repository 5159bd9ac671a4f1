//! [`thread_cpu_ns`]: the calling thread's CPU time, for the timing examples and the
//! benchmarks' one-thread groups (benches/cpu_time.rs makes it a criterion measurement).
//!
//! Included by path (`#[path = "../tests/support/thread_cpu_time.rs"] mod thread_cpu_time;`).
#![allow(dead_code)]

use std::sync::OnceLock;
use std::time::Instant;

/// The calling thread's CPU time in nanoseconds (`CLOCK_THREAD_CPUTIME_ID`; wall time off
/// Linux): unlike wall time it does not count the time other processes take on a shared
/// machine, so that single-thread kernel timings are comparable between runs.
#[cfg(target_os = "linux")]
pub fn thread_cpu_ns() -> u64 {
    #[repr(C)]
    struct Timespec {
        sec: i64,
        nsec: i64,
    }
    unsafe extern "C" {
        fn clock_gettime(clock: i32, time: *mut Timespec) -> i32;
    }
    const CLOCK_THREAD_CPUTIME_ID: i32 = 3;
    let mut t = Timespec { sec: 0, nsec: 0 };
    // SAFETY: `t` is a valid, writable timespec; the clock id is Linux's thread CPU clock.
    let ok = unsafe { clock_gettime(CLOCK_THREAD_CPUTIME_ID, &mut t) } == 0;
    if ok {
        t.sec as u64 * 1_000_000_000 + t.nsec as u64
    } else {
        wall_ns()
    }
}

/// The calling thread's CPU time in nanoseconds (wall time off Linux).
#[cfg(not(target_os = "linux"))]
pub fn thread_cpu_ns() -> u64 {
    wall_ns()
}

/// Wall nanoseconds since the first call.
fn wall_ns() -> u64 {
    static START: OnceLock<Instant> = OnceLock::new();
    START.get_or_init(Instant::now).elapsed().as_nanos() as u64
}
