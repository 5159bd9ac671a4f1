"""Independent checks for the pooltool tests: where pooltool's own evolution puts the balls.

Nothing here calls ballcollide: distances come from ``pooltool.physics.evolve.
evolve_ball_motion`` (pooltool's closed-form motion of a ball over time, with its own
transitions), so a contact time from either detector is judged by the motion pooltool itself
simulates.
"""

from __future__ import annotations

import importlib.util
import math
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pooltool as pt
from pooltool.physics.evolve import evolve_ball_motion

ROOT = Path(__file__).resolve().parents[2]

TOUCH = 1e-9  # m: |distance − (R₁ + R₂)| at a contact, and the overlap allowed between events
SAME_TIME = 1e-9  # s: two detectors' times of one event

POCKETED = 4


def same_words(now: list[str], then: list[str], tolerance: float) -> bool:
    """Two reference lines' words: each the same, or numbers within ``tolerance`` (relative
    above 1): what the committed tables allow another CPU's BLAS or numba to round otherwise."""

    def same(a: str, b: str) -> bool:
        if a == b:
            return True
        try:
            x, y = float(a), float(b)
        except ValueError:
            return False
        return math.isclose(x, y, rel_tol=tolerance, abs_tol=tolerance)

    return all(map(same, now, then))


def script(relative: str) -> Any:
    """The repository's script at ``relative`` (a path from its root) as a module."""
    path = ROOT / relative
    spec = importlib.util.spec_from_file_location(path.stem, path)
    assert spec and spec.loader
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def benchmark() -> Any:
    """``benchmarks/pooltool_dropin.py`` as a module (its :func:`break_shot`)."""
    return script("benchmarks/pooltool_dropin.py")


def rvw_after(ball: Any, dt: float) -> np.ndarray:
    """The ball's ``rvw`` ``dt`` after its state, by pooltool's evolution."""
    p = ball.params
    rvw, _ = evolve_ball_motion(
        state=ball.state.s,
        rvw=ball.state.rvw,
        R=p.R,
        m=p.m,
        u_s=p.u_s,
        u_sp=p.u_sp,
        u_r=p.u_r,
        g=p.g,
        t=dt,
    )
    return rvw


def gap(ball1: Any, ball2: Any, dt: float) -> tuple[float, float]:
    """``(distance − (R₁ + R₂), rate of change of the distance)`` ``dt`` after their states."""
    a, b = rvw_after(ball1, dt), rvw_after(ball2, dt)
    d = b[0, :2] - a[0, :2]
    dist = float(np.hypot(*d))
    rate = float(d @ (b[1, :2] - a[1, :2])) / dist
    return dist - ball1.params.R - ball2.params.R, rate


def is_first_contact(ball1: Any, ball2: Any, dt: float, samples: int = 400) -> bool:
    """Whether the balls touch ``dt`` after their states while closing in, and do not overlap
    (by more than :data:`TOUCH`) at any of ``samples`` times before. A pair that overlaps at
    the start touches when its overlap comes back to that depth (see :func:`allowances`)."""
    left = max(-gap(ball1, ball2, 0.0)[0], 0.0)
    g, rate = gap(ball1, ball2, dt)
    if abs(g + left) > TOUCH or rate >= 0:
        return False
    earlier = np.linspace(0.0, dt, samples, endpoint=False)
    return all(gap(ball1, ball2, float(t))[0] + left > -TOUCH for t in earlier)


def first_contact(ball1: Any, ball2: Any, horizon: float, samples: int = 20_000) -> float:
    """The first time (after their states, before ``horizon``) the balls come within
    ``R₁ + R₂``: the first sample at which they overlap, then bisection on pooltool's
    evolution to 1e-13 s; ``inf`` if no sample overlaps. Contacts are counted only after a
    sample where the balls are apart, so balls touching and separating at the start do not
    count."""
    times = np.linspace(0.0, horizon, samples)
    was_apart = gap(ball1, ball2, 0.0)[0] > 0
    for lo, hi in zip(times[:-1], times[1:]):
        if gap(ball1, ball2, float(hi))[0] <= 0:
            if not was_apart:
                continue
            lo, hi = float(lo), float(hi)
            while hi - lo > 1e-13:
                mid = 0.5 * (lo + hi)
                lo, hi = (lo, mid) if gap(ball1, ball2, mid)[0] <= 0 else (mid, hi)
            return hi
        was_apart = True
    return float("inf")


def state_before(system: Any, k: int) -> Any:
    """A fresh system in the state the simulated ``system`` had just before its event ``k``
    (``k ≥ 1``): each ball in its state after event ``k − 1``, at that event's time."""
    balls = {
        ball.id: pt.Ball(id=ball.id, state=ball.history.states[k - 1].copy(), params=ball.params)
        for ball in system.balls.values()
    }
    shot = pt.System(cue=system.cue.copy(), table=system.table, balls=balls)
    shot.t = system.events[k - 1].time
    return shot


def depths(shot: Any, dt: float) -> np.ndarray:
    """How deep each two balls of ``shot`` overlap ``dt`` after their states:
    ``R_i + R_j − distance`` (m, negative when apart; ``-inf`` on the diagonal and for
    pocketed balls), in the order of ``shot.balls``."""
    balls = list(shot.balls.values())
    xy = np.array([rvw_after(b, dt)[0, :2] for b in balls])
    radius = np.array([b.params.R for b in balls])
    dist = np.hypot(*(xy[:, None, :] - xy[None, :, :]).transpose(2, 0, 1))
    depth = radius[:, None] + radius[None, :] - dist
    off = np.array([b.state.s == POCKETED for b in balls])
    depth[off, :] = depth[:, off] = -np.inf
    np.fill_diagonal(depth, -np.inf)
    return depth


def allowances(system: Any) -> Iterator[tuple[int, Any, np.ndarray]]:
    """For each event ``k`` of a simulated ``system``: ``(k, the system just after it, the
    overlap each pair may have until its next event)``.

    pooltool's resolution of a contact moves its two balls apart to a small spacer
    (``make_kiss``), which in a cluster can push one of them into a third ball: such a pair
    overlaps (by up to micrometres) from the event on. A detector is then right to let the
    overlap shrink and come back to that depth, never deeper; it is asked again after each
    event of either ball. So a pair's allowance is its overlap (or 0) just after the last
    event that involved either of its balls.
    """
    ids = list(system.balls)
    allowed = np.zeros((len(ids), len(ids)))
    for k in range(len(system.events) - 1):
        shot = state_before(system, k + 1)
        depth = np.maximum(depths(shot, 0.0), 0.0)
        involved = set(system.events[k].ids) & set(ids) if k > 0 else set(ids)
        for i in (ids.index(b) for b in involved):
            allowed[i, :] = depth[i, :]
            allowed[:, i] = depth[:, i]
        yield k, shot, allowed


def worst_overlap(system: Any, fractions: tuple[float, ...]) -> tuple[float, int, float]:
    """The deepest overlap of two balls beyond their allowance (:func:`allowances`) between
    the events of a simulated ``system``, at the given fractions of each interval:
    ``(excess depth (m), event index, time)``."""
    worst = (-np.inf, -1, 0.0)
    events = system.events
    for k, shot, allowed in allowances(system):
        t0, t1 = events[k].time, events[k + 1].time
        if k == 0 or t1 <= t0:
            continue
        for f in fractions:
            excess = float((depths(shot, f * (t1 - t0)) - allowed).max())
            if excess > worst[0]:
                worst = (excess, k, t0 + f * (t1 - t0))
    return worst
