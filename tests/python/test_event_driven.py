"""The event-driven demo (examples/event_driven.py): a short run keeps its invariants."""

from __future__ import annotations

import importlib.util
import math
import sys
from pathlib import Path

import numpy as np
import pytest

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "event_driven.py"


@pytest.fixture(scope="module")
def demo():
    spec = importlib.util.spec_from_file_location("event_driven", EXAMPLE)
    assert spec and spec.loader
    module = importlib.util.module_from_spec(spec)
    sys.modules["event_driven"] = module
    spec.loader.exec_module(module)
    return module


def test_a_few_events_of_the_break_keep_the_invariants(demo) -> None:
    sim = demo.break_simulation()
    stats = sim.run(max_events=12)
    assert stats.ball_events >= 1
    assert stats.ball_events + stats.wall_events == 12
    assert stats.max_overlap <= demo.OVERLAP_TOLERANCE
    energies = np.array(stats.energies)
    assert (np.diff(energies) <= energies[:-1] * demo.ENERGY_TOLERANCE).all()
    assert energies[-1] < energies[0]  # friction has taken some


def test_the_whole_break_runs_until_everything_stops(demo) -> None:
    sim = demo.break_simulation()
    stats = sim.run()
    assert stats.ball_events > 15 and stats.wall_events > 5
    assert stats.energies[-1] == 0.0
    assert (sim.vel == 0).all()
    assert stats.max_overlap <= demo.OVERLAP_TOLERANCE


def test_wall_times_solve_the_quadratic(demo) -> None:
    # One ball 1 m from the right wall's contact line, at 2 m/s, slowed at 0.5 m/s²:
    # 2s − s²/4 = 1 → s = 4 − √12.
    r = demo.BALL_RADIUS
    sim = demo.Simulation([[2.0 - r - 1.0, 0.5]], [[2.0, 0.0]], 0.5, size=(2.0, 1.0))
    dt, ball, axis = sim.next_wall()
    assert (ball, axis) == (0, 0)
    assert math.isclose(dt, 4 - math.sqrt(12), rel_tol=1e-14)
    # Too slow to get there: it stops first.
    slow = demo.Simulation([[0.5, 0.5]], [[0.1, 0.0]], 0.5, size=(2.0, 1.0))
    assert slow.next_wall() == (math.inf, -1, -1)
    # Just bounced off a wall (sitting on it, moving away): not an event again.
    bounced = demo.Simulation([[2.0 - r, 0.5]], [[-1.0, 0.0]], 0.0, size=(2.0, 1.0))
    dt, ball, axis = bounced.next_wall()
    assert math.isclose(dt, 2.0 - 2 * r)


def test_a_head_on_collision_exchanges_velocities(demo) -> None:
    r = demo.BALL_RADIUS
    sim = demo.Simulation([[0.5, 0.5], [1.0, 0.5]], [[1.0, 0.0], [0.0, 0.0]], 0.0, size=(10, 1))
    assert sim.step() == "ball"
    assert math.isclose(sim.time, 0.5 - 2 * r, rel_tol=1e-14)
    np.testing.assert_allclose(sim.vel, [[0.0, 0.0], [1.0, 0.0]], atol=1e-15)
