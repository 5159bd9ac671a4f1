"""``python -m ballcollide demo``: the README's "run the main job" command."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from ballcollide import collision_times, demo


def run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "ballcollide", *args],
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )


def test_demo_runs_and_prints_a_summary() -> None:
    result = run("demo", "--pairs", "2000", "--seed", "3", "--threads", "1")
    assert result.returncode == 0, result.stderr
    out = result.stdout
    assert "2,000 pairs" in out
    hits = re.search(r"hits: ([\d,]+) of 2,000 pairs", out)
    assert hits and int(hits.group(1).replace(",", "")) > 0, out
    assert re.search(r"[\d.]+ M pairs/s, \d+ ns/pair", out), out


def test_demo_batch_is_realistic_and_reproducible() -> None:
    batch = demo.make_batch(5000, seed=9)
    again = demo.make_batch(5000, seed=9)
    for key, value in batch.items():
        np.testing.assert_array_equal(value, again[key])
    for ball in "ab":
        pos = batch[f"pos_{ball}"]
        assert (pos >= demo.BALL_RADIUS).all() and (
            pos <= np.array(demo.TABLE) - demo.BALL_RADIUS
        ).all()
        assert (np.hypot(*batch[f"vel_{ball}"].T) <= demo.MAX_SPEED).all()
        assert ((batch[f"friction_{ball}"] >= 0.09) & (batch[f"friction_{ball}"] <= 0.11)).all()
    assert (np.hypot(*(batch["pos_a"] - batch["pos_b"]).T) > demo.CONTACT).all()
    assert batch["contact_distance"] == pytest.approx(0.05715)
    # The horizon is a cushion time: before it, both balls are on the table.
    t = collision_times(**batch)
    assert np.isfinite(t).sum() > 0 and (t[np.isfinite(t)] < batch["t_max"][np.isfinite(t)]).all()


def test_cushion_times() -> None:
    r = demo.BALL_RADIUS
    pos = np.array([[1.0, 0.5], [1.0, 0.5], [1.0, 0.5], [1.0, 0.5]])
    vel = np.array([[1.0, 0.0], [0.0, -0.2], [0.0, 0.0], [0.1, 0.0]])
    friction = np.array([0.0, 0.0, 0.1, 0.1])
    times = demo.cushion_times(pos, vel, friction)
    assert times[0] == pytest.approx(demo.TABLE[0] - r - 1.0, rel=1e-14)
    assert times[1] == pytest.approx((0.5 - r) / 0.2, rel=1e-14)
    assert times[2] == np.inf  # at rest
    assert times[3] == np.inf  # stops after 5 cm


def test_demo_plot(tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    path = tmp_path / "demo.png"
    result = run("demo", "--pairs", "20000", "--repeat", "1", "--plot", str(path))
    assert result.returncode == 0, result.stderr
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert path.stat().st_size > 10_000
    assert "colliding pair(s) drawn" in result.stdout


def test_demo_plot_without_matplotlib_says_so(tmp_path: Path) -> None:
    code = (
        "import sys; sys.modules['matplotlib'] = None\n"
        "from ballcollide.__main__ import main\n"
        f"sys.exit(main(['demo', '--pairs', '100', '--plot', {str(tmp_path / 'x.png')!r}]))"
    )
    result = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=120, check=False
    )
    assert result.returncode == 2
    assert "needs matplotlib" in result.stdout and "pip install" in result.stdout


def test_cli_errors() -> None:
    assert run().returncode == 2  # a subcommand is required
    bad = run("demo", "--pairs", "0")
    assert bad.returncode == 2 and "--pairs" in bad.stderr
    assert run("demo", "--threads", "-1").returncode == 2
    version = run("--version")
    assert version.returncode == 0 and version.stdout.startswith("ballcollide ")
