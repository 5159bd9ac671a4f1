"""Shared settings and helpers of the Python tests."""

from __future__ import annotations

import os

from hypothesis import HealthCheck, settings

# Property tests: no deadline (the first call of a process may be slow), more examples in CI.
settings.register_profile(
    "default", deadline=None, suppress_health_check=[HealthCheck.too_slow], max_examples=150
)
settings.register_profile(
    "ci",
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
    max_examples=400,
    print_blob=True,
    # The same examples on every CI run, so that CI is repeatable; local runs and the fuzz
    # targets (docs/fuzzing.md) draw new ones.
    derandomize=True,
)
settings.load_profile("ci" if os.environ.get("CI") else "default")
