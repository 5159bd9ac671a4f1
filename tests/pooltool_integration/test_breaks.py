"""pooltool's own breaks (9-ball and 8-ball racks, fixed seeds) with ballcollide installed as
its ball–ball detector, against stock pooltool and against pooltool's own evolution."""

from __future__ import annotations

from functools import cache
from typing import Any

import pytest

pt = pytest.importorskip("pooltool")

import numpy as np  # noqa: E402
from pooltool.evolution.event_based import simulate as pt_simulate  # noqa: E402

import ballcollide.pooltool as bcp  # noqa: E402

from .reference import (  # noqa: E402
    SAME_TIME,
    TOUCH,
    allowances,
    benchmark,
    depths,
    is_first_contact,
    state_before,
    worst_overlap,
)

BREAKS = [(game, seed) for game in ("nine", "eight") for seed in range(4)]
BALL_BALL = pt.EventType.BALL_BALL


@cache
def simulated(game: str, seed: int) -> Any:
    """The break simulated by pooltool with ballcollide's detector."""
    system = benchmark().break_shot(game, seed)
    with bcp.install():
        return pt.simulate(system)


def next_event(shot: Any, ours: bool) -> Any:
    """pooltool's next event from ``shot`` (fresh caches), with either detector."""
    if ours:
        with bcp.install():
            return pt_simulate.get_next_event(shot)
    return pt_simulate.get_next_event(shot)


def same(e1: Any, e2: Any) -> bool:
    return (
        e1.event_type == e2.event_type
        and e1.ids == e2.ids
        and (e1.time == e2.time or abs(e1.time - e2.time) <= SAME_TIME)
    )


def verified(shot: Any, event: Any) -> bool:
    """Whether a ball–ball ``event`` from ``shot`` is a true first contact of its balls."""
    b1, b2 = (shot.balls[i] for i in event.ids)
    return is_first_contact(b1, b2, event.time - shot.t)


@pytest.mark.parametrize(("game", "seed"), BREAKS)
def test_each_event_is_stock_pooltools_from_the_same_state_wherever_stock_is_right(
    game: str, seed: int
) -> None:
    # Whole runs part ways once any time differs in its last digits (a break is chaotic:
    # each ball–ball collision multiplies a difference), so each event of the run is
    # compared with stock pooltool's next event from the same state. Where they differ, the
    # earlier of the two is judged by pooltool's own evolution: a true first contact that
    # ballcollide missed fails the test; a stock contact that is none is stock's error.
    system = simulated(game, seed)
    events = system.events
    first = next(k for k, e in enumerate(events) if e.event_type == pt.EventType.STICK_BALL)
    agreed, stock_wrong = 0, []
    for k in range(first + 1, len(events) - 1):
        shot = state_before(system, k)
        ours, stock = next_event(shot, ours=True), next_event(shot, ours=False)
        if depths(shot, 0.0).max() <= 0:
            # The run's event: asked afresh, the detector answers as it did from its cache
            # (a pair left overlapping is answered at the depth it had when last asked).
            assert same(ours, events[k]), (k, ours, events[k])
        if same(ours, stock):
            agreed += 1
            continue
        early = ours if ours.time <= stock.time else stock
        assert early.event_type == BALL_BALL, (k, ours, stock)
        if early is stock and not verified(shot, stock):
            stock_wrong.append((k, stock.ids, stock.time - shot.t))
            continue
        # ballcollide's contact comes first (stock missed it), or both are contacts at the
        # same time (a tie between pairs): ours must be a true first contact.
        assert verified(shot, ours), (k, ours, stock)
        if early is ours and abs(ours.time - stock.time) > SAME_TIME:
            stock_wrong.append((k, stock.ids, stock.time - shot.t))
    # The comparison did compare: nearly every event is stock's own.
    assert agreed >= 0.95 * (len(events) - first - 2), (agreed, stock_wrong)


@pytest.mark.parametrize(("game", "seed"), BREAKS)
def test_balls_touch_at_every_ball_ball_event(game: str, seed: int) -> None:
    # At their contact distance, R₁ + R₂ — or, for a pair that pooltool's resolution of an
    # earlier event left overlapping, at the depth it left them (see `allowances`).
    system = simulated(game, seed)
    ids = list(system.balls)
    allowed = np.zeros((len(ids), len(ids)))
    contacts = inside = 0
    for k, _, after in allowances(system):
        event = system.events[k]
        if event.event_type == BALL_BALL:
            b1, b2 = (agent.initial for agent in event.agents)
            dist = np.linalg.norm(b1.state.rvw[0, :2] - b2.state.rvw[0, :2])
            g = dist - b1.params.R - b2.params.R
            left = allowed[ids.index(b1.id), ids.index(b2.id)]
            assert abs(g + left) <= TOUCH, (k, event.ids, g, left)
            contacts += 1
            inside += left > TOUCH
        allowed = after.copy()
    assert contacts >= 5 and inside <= contacts // 2, (contacts, inside)


@pytest.mark.parametrize(("game", "seed"), BREAKS)
def test_no_ball_overlaps_another_between_events(game: str, seed: int) -> None:
    system = simulated(game, seed)
    depth, k, t = worst_overlap(system, (1e-6, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 1 - 1e-6))
    assert depth <= TOUCH, (depth, k, t)


def test_a_break_runs_the_same_events_as_stock_until_the_last_digits_part_them() -> None:
    # The first events of a break, before any difference can grow: the same events in the
    # same order at the same times as stock pooltool's own run.
    system = benchmark().break_shot("nine", 0)
    stock = pt.simulate(system)
    with bcp.install():
        ours = pt.simulate(system)
    k = 0
    while k < min(len(ours.events), len(stock.events)) and same(ours.events[k], stock.events[k]):
        k += 1
    contacts = sum(e.event_type == BALL_BALL for e in ours.events[:k])
    assert k >= 30 and contacts >= 10, (k, contacts)
