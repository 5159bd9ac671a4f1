//! The machine a benchmark ran on: every figure belongs to a CPU and a SIMD level. Shared by
//! the criterion benches (included by path).

/// Prints the CPU model and the SIMD level the batches run at (`BALLCOLLIDE_SIMD` forces it):
/// every figure belongs to both.
pub fn print_machine() {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|info| {
            info.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| std::env::consts::ARCH.to_string());
    eprintln!(
        "CPU: {cpu}; SIMD level: {} (available: {:?})",
        ballcollide::simd::current(),
        ballcollide::simd::Level::available()
    );
}
