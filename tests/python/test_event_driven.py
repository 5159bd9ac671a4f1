"""The event-driven demo (examples/event_driven.py, on bc.simulate): its runs keep their
invariants, and bc.simulate's physics on small cases worked by hand."""

from __future__ import annotations

import importlib.util
import math
import sys
from pathlib import Path

import numpy as np
import pytest

import ballcollide as bc

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
    run = demo.break_run(max_events=12)
    stats = run.stats
    assert stats.ball_events >= 1
    assert stats.ball_events + stats.wall_events == 12
    assert stats.max_overlap <= demo.OVERLAP_TOLERANCE
    energies = np.array(stats.energies)
    assert (np.diff(energies) <= energies[:-1] * demo.ENERGY_TOLERANCE).all()
    assert energies[-1] < energies[0]  # friction has taken some


def test_the_whole_break_runs_until_everything_stops(demo) -> None:
    run = demo.break_run()
    stats = run.stats
    assert stats.ball_events > 15 and stats.wall_events > 5
    assert stats.energies[-1] == 0.0
    assert (run.sim.vel == 0).all()
    assert stats.max_overlap <= demo.OVERLAP_TOLERANCE
    assert (np.diff(run.sim.times) >= 0).all()


def test_the_break_on_a_pool_table_pockets_balls_and_keeps_the_invariants(demo) -> None:
    # Replayed event by event: no overlap between balls in play or with the rails, jaws and
    # tips beyond 1e-9 m (the demo's checks), energy never rising; pocketed balls at rest.
    run = demo.break_run(table=True)
    sim, stats = run.sim, run.stats
    assert stats.max_overlap <= demo.OVERLAP_TOLERANCE
    energies = np.array(stats.energies)
    assert (np.diff(energies) <= energies[:-1] * demo.ENERGY_TOLERANCE).all()
    pocketed = sim.captured >= 0
    assert pocketed.any() and (sim.vel == 0).all()
    # Each capture is logged once, as a TARGET event of that ball and pocket, after which the
    # ball takes part in nothing.
    for ball in np.flatnonzero(pocketed):
        hits = np.flatnonzero((sim.kind == bc.TARGET) & (sim.i == ball))
        assert len(hits) == 1 and sim.index[hits[0]] == sim.captured[ball]
        later = (sim.times > sim.times[hits[0]]) & ((sim.i == ball) | (sim.j == ball))
        assert not later.any()
    assert ((sim.kind == bc.SEGMENT) | (sim.kind == bc.CIRCLE)).sum() >= 3


def test_a_wall_contact_solves_the_quadratic() -> None:
    # One ball 1 m from the right wall's contact line, at 2 m/s, slowed at 0.5 m/s²:
    # 2s − s²/4 = 1 → s = 4 − √12; it comes back at the same speed.
    r = 0.25
    times, i, j, pos, vel, *_ = bc.simulate(
        [[2.0 - r - 1.0, 0.5]], [[2.0, 0.0]], 0.5, r, box=([0, 0], [2, 1]), max_events=1
    )
    assert (i.tolist(), j.tolist()) == ([0], [-1])
    assert math.isclose(times[0], 4 - math.sqrt(12), rel_tol=1e-14)
    assert math.isclose(pos[0, 0], 2.0 - r, rel_tol=1e-14)
    assert vel[0, 0] < 0 and math.isclose(-vel[0, 0], 2 - 0.5 * times[0], rel_tol=1e-14)
    # Too slow to get there: it stops first, and the run ends with it at rest.
    times, _i, _j, pos, vel, *_ = bc.simulate(
        [[0.5, 0.5]], [[0.1, 0.0]], 0.5, r, box=([0, 0], [2, 1])
    )
    assert len(times) == 0 and (vel == 0).all() and math.isclose(pos[0, 0], 0.51)


def test_collisions_exchange_momentum_with_masses_and_restitution() -> None:
    # Head on: m = 1 at 1 m/s onto m = 3 at rest, e = ½: v' = (1 − 3·½)/4, (1 + ½)/4.
    times, i, j, pos, vel, *_ = bc.simulate(
        [[1.0, 0.5], [2.0, 0.5]],
        [[1.0, 0.0], [0.0, 0.0]],
        0.0,
        0.25,
        box=([0, 0], [10, 1]),
        mass=[1.0, 3.0],
        restitution=0.5,
        max_events=1,
    )
    assert (times[0], i[0], j[0]) == (0.5, 0, 1)
    np.testing.assert_allclose(vel, [[-0.125, 0.0], [0.375, 0.0]], rtol=1e-15, atol=1e-16)
    np.testing.assert_allclose(1.0 * vel[0] + 3.0 * vel[1], [1.0, 0.0], rtol=1e-15)
    # Oblique, equal masses, elastic: the normal components swap, the tangential stay.
    s = math.sqrt(0.5)
    times, i, j, pos, vel, *_ = bc.simulate(
        [[1.0, 1.0], [1.0 + 0.5 * s + 0.5, 1.0 + 0.5 * s]],
        [[1.0, 0.0], [0.0, 0.0]],
        0.0,
        0.25,
        box=([0, 0], [10, 10]),
        max_events=1,
    )
    n = (pos[1] - pos[0]) / np.linalg.norm(pos[1] - pos[0])
    np.testing.assert_allclose(vel[1], np.dot([1.0, 0.0], n) * n, atol=1e-15)
    np.testing.assert_allclose(vel[0] + vel[1], [1.0, 0.0], atol=1e-15)


def test_simulate_refuses_bad_input() -> None:
    args = ([[0.5, 0.5]], [[1.0, 0.0]], 0.0, 0.25)
    box = ([0, 0], [1, 1])
    with pytest.raises(bc.InputError, match="t_end or max_events") as info:
        bc.simulate(*args, box=box)
    assert info.value.argument == "t_end"
    with pytest.raises(bc.InputError) as info:
        bc.simulate(*args, box=box, t_end=1.0, restitution=1.5)
    assert info.value.argument == "restitution"
    with pytest.raises(bc.InputError) as info:
        bc.simulate(*args, box=box, t_end=1.0, mass=[-1.0])
    assert (info.value.argument, info.value.index) == ("mass", 0)
    with pytest.raises(bc.InputError) as info:
        bc.simulate(*args, box=([0, 0], [0, 1]), t_end=1.0)
    assert (info.value.argument, info.value.index) == ("box", 0)
