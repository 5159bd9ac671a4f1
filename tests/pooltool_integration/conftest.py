"""The pooltool integration tests need pooltool-billiards 0.6.0 (``scripts/install-pooltool``).

Without it each module is skipped (``pytest.importorskip``, with the reason shown);
``scripts/test-pooltool``, which CI runs, sets ``BALLCOLLIDE_REQUIRE_POOLTOOL=1``, and then a
missing pooltool is an error, never a skip.
"""

from __future__ import annotations

import importlib.util
import os

if os.environ.get("BALLCOLLIDE_REQUIRE_POOLTOOL") == "1" and not importlib.util.find_spec(
    "pooltool"
):
    raise RuntimeError(
        "BALLCOLLIDE_REQUIRE_POOLTOOL=1 but pooltool is not importable: run "
        "scripts/install-pooltool and use its environment"
    )
