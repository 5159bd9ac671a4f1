"""The machine a benchmark ran on: every figure belongs to a CPU and a SIMD level (shared by
the scripts here, which run as ``python benchmarks/NAME.py`` and so find this module beside
them)."""

from __future__ import annotations

import platform


def cpu_model() -> str:
    """The CPU's model name (``/proc/cpuinfo``), else what ``platform`` knows."""
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def describe() -> str:
    """The CPU's model and the SIMD level ballcollide's batches run at (``BALLCOLLIDE_SIMD``
    forces one), as the benchmarks print them."""
    import ballcollide as bc

    return f"CPU: {cpu_model()}; SIMD level: {bc.simd_level()}"
