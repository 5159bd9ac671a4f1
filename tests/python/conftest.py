"""Shared settings and helpers of the Python tests."""

from __future__ import annotations

import os

from hypothesis import HealthCheck, settings

# Property tests, in two tiers: "fast" (the default; ./scripts/test) and "thorough" (.ci/run
# sets BALLCOLLIDE_HYPOTHESIS_PROFILE=thorough). No deadline (the first call of a process may be
# slow). Under CI the examples are the same on every run, so that CI is repeatable; local runs
# and the fuzz targets (docs/fuzzing.md) draw new ones.
_COMMON = dict(
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
    derandomize=bool(os.environ.get("CI")),
    print_blob=True,
)
settings.register_profile("fast", max_examples=50, **_COMMON)
settings.register_profile("thorough", max_examples=400, **_COMMON)
settings.load_profile(os.environ.get("BALLCOLLIDE_HYPOTHESIS_PROFILE", "fast"))
