"""``examples/pooltool_states.py``: billiard balls from pooltool-style states as paths."""

from __future__ import annotations

import importlib.util
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import ballcollide as bc

SCRIPT = Path(__file__).resolve().parents[2] / "examples" / "pooltool_states.py"


def example():
    spec = importlib.util.spec_from_file_location("pooltool_states", SCRIPT)
    assert spec and spec.loader
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up
    spec.loader.exec_module(module)
    return module


def test_paths_follow_the_sliding_and_rolling_model() -> None:
    ex = example()
    for state in ex.STATES:
        start, pos, vel, acc = ex.path_of(state)
        used = int(np.isfinite(start).sum())
        assert (np.diff(start[:used]) > 0).all()
        # Continuous: each segment starts where and as fast as the one before ends.
        for k in range(used - 1):
            tau = start[k + 1] - start[k]
            np.testing.assert_allclose(
                pos[k + 1], pos[k] + vel[k] * tau + 0.5 * acc[k] * tau**2, atol=1e-12
            )
            np.testing.assert_allclose(vel[k + 1], vel[k] + acc[k] * tau, atol=1e-12)
        # Ends at rest.
        assert (vel[used - 1] == 0).all() and (acc[used - 1] == 0).all()
        v, w = np.array(state.v), np.array(state.w)
        u = v + ex.R * np.array([-w[1], w[0]])
        if ex.motion(state) == "sliding":
            # Sliding ends when the slip is gone: the velocity has lost 2/7 of the slip.
            np.testing.assert_allclose(vel[1], v - 2 / 7 * u, atol=1e-12)
            assert np.linalg.norm(acc[0]) == pytest.approx(ex.U_SLIDE * ex.G)
            assert np.linalg.norm(acc[1]) == pytest.approx(ex.U_ROLL * ex.G)
        elif ex.motion(state) == "rolling":
            assert np.linalg.norm(u) < 1e-12
            assert np.linalg.norm(acc[0]) == pytest.approx(ex.U_ROLL * ex.G)
    # The cue ball's path bends: friction points far from its velocity.
    _, _, vel, acc = ex.path_of(ex.STATES[0])
    cos = vel[0] @ acc[0] / np.linalg.norm(vel[0]) / np.linalg.norm(acc[0])
    assert -0.98 < cos < -0.5


def test_contacts_are_two_radii_apart() -> None:
    ex = example()
    found = ex.contacts(ex.STATES)
    assert len(found) >= 3 and found == sorted(found)
    for t, i, j in found:
        xi, xj = (
            bc.path_positions_at(*(f[None] for f in ex.path_of(ex.STATES[b])), t)[0] for b in (i, j)
        )
        assert np.linalg.norm(xi - xj) == pytest.approx(2 * ex.R, rel=1e-9)
    # The earliest contact comes while the cue ball still slides: on its curve.
    t, i, j = found[0]
    assert i == 0 and t < ex.path_of(ex.STATES[0])[0][1]


def test_the_script_draws_the_picture(tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    out = tmp_path / "paths.png"
    result = subprocess.run(
        [sys.executable, str(SCRIPT), "--out", str(out)],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert result.returncode == 0, result.stderr
    assert result.stdout.count("contact ") >= 3
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert out.stat().st_size > 10_000
