"""pooltool's own break shots, simulated with its stock ball–ball detector and with ballcollide's
(``ballcollide.pooltool.install()``), timed in the same run.

Needs the environment of ``scripts/install-pooltool`` (pooltool-billiards 0.6.0 and
ballcollide in one virtual environment)::

    scripts/install-pooltool                     # once: ./.venv-pooltool
    .venv-pooltool/bin/python benchmarks/pooltool_dropin.py
    .venv-pooltool/bin/python benchmarks/pooltool_dropin.py --seeds 10 --repeats 9

For each game (9-ball, 8-ball) and seed, a break (:func:`break_shot`) is simulated
``--repeats`` times each way, alternating stock and ballcollide; the script prints the
medians of ``pooltool.simulate()`` per break and per event over all of them, the ratios
(the two ways' runs of one break may part after a while, and then their events differ, so
the time per event is the fairer measure), and the ball–ball
detector's own time per call of pooltool's pair loop (``get_next_ball_ball_collision``, timed
by wrapping it) and per pair it computes. The tests in ``tests/pooltool`` use the same
breaks.
"""

from __future__ import annotations

import argparse
import random
import statistics
import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import numpy as np

GAMES = ("nine", "eight")


def break_shot(game: str, seed: int) -> Any:
    """A random break of pooltool's 9-ball (``"nine"``) or 8-ball (``"eight"``) rack, the
    same for a given seed in every process: the rack's jitter from ``seed``, its balls
    renamed ``1``, ``2``, … in order of position (pooltool draws which ball goes where
    from a set, whose order changes from process to process), and a strike at the apex
    ball with a speed, angle offset and tip offsets drawn from ``seed``."""
    import pooltool as pt

    game_type = {"nine": pt.GameType.NINEBALL, "eight": pt.GameType.EIGHTBALL}[game]
    random.seed(seed)
    np.random.seed(seed)  # noqa: NPY002  (pooltool's rack draws from numpy's global state)
    table = pt.Table.from_game_type(game_type)
    rack = pt.get_rack(game_type, table)
    spots = sorted(
        (float(b.state.rvw[0, 1]), float(b.state.rvw[0, 0])) for b in rack.values() if b.id != "cue"
    )
    balls = {"cue": pt.Ball.create("cue", xy=rack["cue"].state.rvw[0, :2])}
    for k, (y, x) in enumerate(spots):
        balls[str(k + 1)] = pt.Ball.create(str(k + 1), xy=(x, y))
    system = pt.System(cue=pt.Cue(cue_ball_id="cue"), table=table, balls=balls)
    rng = np.random.default_rng(seed)
    system.strike(
        V0=rng.uniform(4.0, 9.0),
        phi=pt.aim.at_ball(system, "1") + rng.uniform(-0.8, 0.8),
        a=rng.uniform(-0.3, 0.3),
        b=rng.uniform(-0.3, 0.3),
    )
    return system


@contextmanager
def timed_pair_loop(record: list[tuple[float, int]]) -> Iterator[None]:
    """While active, each call of pooltool's current pair loop appends (seconds, pairs
    computed) to ``record``."""
    from pooltool.events import EventType
    from pooltool.evolution.event_based import simulate

    inner = simulate.get_next_ball_ball_collision

    def wrapper(shot: Any, collision_cache: Any) -> Any:
        before = len(collision_cache.times.get(EventType.BALL_BALL, {}))
        start = time.perf_counter()
        event = inner(shot, collision_cache)
        seconds = time.perf_counter() - start
        record.append((seconds, len(collision_cache.times[EventType.BALL_BALL]) - before))
        return event

    simulate.get_next_ball_ball_collision = wrapper
    try:
        yield
    finally:
        simulate.get_next_ball_ball_collision = inner


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=5, help="breaks per game")
    parser.add_argument("--repeats", type=int, default=7, help="runs of each break each way")
    args = parser.parse_args(argv)
    import pooltool as pt

    import ballcollide.pooltool as bcp

    print(f"pooltool {pt.__version__}, {args.seeds} breaks per game, {args.repeats} repeats")
    ways = ("stock", "ballcollide")
    for game in GAMES:
        systems = [break_shot(game, seed) for seed in range(args.seeds)]
        pt.simulate(systems[0])  # numba's compile (or cache load) out of the timings
        with bcp.install():
            pt.simulate(systems[0])
        # Per break: the seconds of each run and its number of events, each way.
        runs: dict[str, list[list[float]]] = {way: [[] for _ in systems] for way in ways}
        events: dict[str, list[int]] = {way: [0] * len(systems) for way in ways}
        for _ in range(args.repeats):
            for b, system in enumerate(systems):
                for way in ways:
                    handle = bcp.install() if way == "ballcollide" else None
                    try:
                        start = time.perf_counter()
                        result = pt.simulate(system)
                        runs[way][b].append(time.perf_counter() - start)
                    finally:
                        if handle is not None:
                            bcp.uninstall()
                    events[way][b] = len(result.events)
        calls: dict[str, list[tuple[float, int]]] = {way: [] for way in ways}
        for system in systems:  # the detector alone, in separate runs (the wrapper costs)
            for way in ways:
                handle = bcp.install() if way == "ballcollide" else None
                try:
                    with timed_pair_loop(calls[way]):
                        pt.simulate(system)
                finally:
                    if handle is not None:
                        bcp.uninstall()
        median = {way: [statistics.median(r) for r in runs[way]] for way in ways}
        print(f"\n{game}-ball breaks (events per break, stock / ballcollide:", end="")
        print(" ".join(f" {e}/{f}" for e, f in zip(events["stock"], events["ballcollide"])) + ")")
        for way in ways:
            per_call = [s for s, _ in calls[way]]
            computing = [s / n for s, n in calls[way] if n > 0]
            pairs = sum(n for _, n in calls[way])
            total = sum(median[way]) / sum(events[way])
            print(
                f"  {way:<11} simulate() {statistics.median(median[way]) * 1e3:7.2f} ms per"
                f" break (median), {total * 1e6:4.0f} µs per event (all breaks);"
                f" pair loop {statistics.median(per_call) * 1e6:6.1f} µs per call"
                f" ({len(per_call) / len(systems):.0f} calls, {pairs / len(systems):.0f} pairs"
                f" computed per break), {statistics.median(computing) * 1e6:5.2f} µs per pair"
                " when computing"
            )
        same = [b for b in range(len(systems)) if events["stock"][b] == events["ballcollide"][b]]
        ratios = [median["ballcollide"][b] / median["stock"][b] for b in same]
        per_event = [
            (median["ballcollide"][b] / events["ballcollide"][b])
            / (median["stock"][b] / events["stock"][b])
            for b in range(len(systems))
        ]
        if ratios:
            print(
                f"  ballcollide / stock, breaks with as many events both ways ({len(same)}):"
                f" {statistics.median(ratios):.2f} per break (median)"
            )
        print(f"  ballcollide / stock per event, all breaks: {statistics.median(per_event):.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
