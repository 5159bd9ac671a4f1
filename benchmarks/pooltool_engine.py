"""ballcollide's native billiards engine against stock pooltool 0.6.0, shot by shot.

Plays one seeded set of shots (:func:`shots`: 9-ball and 8-ball breaks, cut shots with side,
top and back spin, massé shots with a raised cue, on pooltool's 9-ball table; cut shots and
a break on its snooker table; three-cushion shots on its carom table; straight shots along
an axis, where pooltool's rounding decides its collisions at once) four ways and prints
the median time per shot of each:

- ``stock``: ``pt.simulate(system)``;
- ``simulate``: ``ballcollide.pooltool.simulate(system)``, the same full ``System``;
- ``stock drop``, ``sim. drop``: the same two, each ``System`` dropped before the next shot
  (a search that keeps a score), where the two above keep the run's ``System`` s in a list
  (a user collecting results). A ``System`` is ~2,000 objects that Python's cyclic garbage
  collector tracks (as many as stock's); kept, they bring on collections of the whole heap
  (with pooltool and numba loaded, hundreds of thousands of objects), which cost both ways
  about a millisecond a shot here;
- ``many 1``, ``many 2``: ``ballcollide.pooltool.simulate_many(systems, num_threads=n)``,
  array results, on one and on two threads;
- its parts: ``reading`` the pooltool objects into arrays (Rust holding the GIL, on the
  calling thread) and ``engine 1``, ``engine 2``: the engine on those arrays
  (``_core.simulate_shots``);
- ``pairs 1``, ``pairs 2``: ``bc.collision_times`` on 10⁶ random pairs, a kernel whose
  halves cost the same, per call: what two threads gain on the machine at that moment (on a
  shared machine, whose other work may hold the second core).

And, on Linux, each thread's time on a CPU in ``engine 2``
(``/proc/self/task/*/schedstat``): how evenly the two threads share the shots, whatever the
machine's load; and its time waiting in the run queue for a CPU, which another process's
work adds to the call.

Each figure is a run's total time over its number of shots, the median over the runs; the
ways take turns within each run (stock's two in the first ``--stock-runs`` only), and each
is compared with stock run the same way (kept or dropped).

The same shots are the integration tests' (``tests/pooltool_integration/test_engine.py``).
Run it in pooltool's environment (``scripts/install-pooltool``)::

    .venv-pooltool/bin/python benchmarks/pooltool_engine.py            # 5 runs, stock 3
    .venv-pooltool/bin/python benchmarks/pooltool_engine.py --runs 3 --scale 0.5

On a shared machine the figures move with the load: compare medians of one run.
"""

from __future__ import annotations

import argparse
import math
import os
import random
import statistics
import sys
import threading
import time
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

#: Shots of each kind in the default set (210 in all).
COUNTS = {
    "break9": 30,
    "break8": 20,
    "cut": 60,
    "masse": 40,
    "snooker": 20,
    "snooker_break": 2,
    "threecushion": 30,
    "straight": 8,
}


def _free_spot(rng: np.random.Generator, table: Any, taken: list[Any], R: float) -> Any:
    """A spot 0.15 m inside the rails and 3 R from every ball in ``taken``."""
    while True:
        x = float(rng.uniform(0.15, table.w - 0.15))
        y = float(rng.uniform(0.15, table.l - 0.15))
        if all(math.hypot(x - a, y - b) > 3 * R for a, b in taken):
            return x, y


def _placed(game: Any, rng: np.random.Generator, count: int) -> Any:
    """A system of ``game``'s table with its cue ball and ``count`` other balls of its rack
    (their parameters) at free spots."""
    import pooltool as pt

    table = pt.Table.from_game_type(game)
    rack = pt.get_rack(game, table)
    cue_id = "white" if "white" in rack else "cue"
    others = sorted(i for i in rack if i != cue_id)[:count]
    spots: list[Any] = []
    balls = {}
    for i in [cue_id, *others]:
        ball = rack[i]
        spot = _free_spot(rng, table, spots, ball.params.R)
        spots.append(spot)
        ball.state.rvw[0, :2] = spot
        balls[i] = ball
    return pt.System(cue=pt.Cue(cue_ball_id=cue_id), table=table, balls=balls), cue_id, others


def shot(kind: str, seed: int) -> Any:
    """Shot ``seed`` of ``kind`` (a key of :data:`COUNTS`), the same in every process."""
    import pooltool as pt
    from pooltool_dropin import break_shot

    if kind in ("break9", "break8"):
        return break_shot("nine" if kind == "break9" else "eight", seed)
    rng = np.random.default_rng([list(COUNTS).index(kind), seed])
    random.seed(seed)
    np.random.seed(seed)  # noqa: NPY002  (pooltool's racks draw from numpy's global state)
    if kind == "snooker_break":
        table = pt.Table.from_game_type(pt.GameType.SNOOKER)
        balls = pt.get_rack(pt.GameType.SNOOKER, table)
        system = pt.System(cue=pt.Cue(cue_ball_id="white"), table=table, balls=balls)
        reds = sorted(
            (i for i in balls if i.startswith("red")), key=lambda i: balls[i].state.rvw[0, 1]
        )
        system.strike(V0=rng.uniform(5.0, 7.0), phi=pt.aim.at_ball(system, reds[0]), b=0.1)
        return system
    if kind == "straight":
        # The cue ball struck along an axis at an object ball on that line.
        system, cue_id, others = _placed(pt.GameType.NINEBALL, rng, 1)
        phi = float(rng.choice([0.0, 90.0, 180.0, 270.0]))
        cue_ball, target = system.balls[cue_id], system.balls[others[0]]
        table = system.table
        x, y = cue_ball.state.rvw[0, :2]
        step = float(rng.uniform(0.1, 0.5))
        dx, dy = round(math.cos(math.radians(phi))), round(math.sin(math.radians(phi)))
        if not (0.1 < x + step * dx < table.w - 0.1 and 0.1 < y + step * dy < table.l - 0.1):
            dx, dy, phi = -dx, -dy, (phi + 180.0) % 360.0
        target.state.rvw[0, :2] = (x + step * dx, y + step * dy)
        system.strike(V0=float(rng.uniform(0.5, 3.0)), phi=phi, b=float(rng.uniform(-0.5, 0.5)))
        return system
    game = {
        "cut": pt.GameType.NINEBALL,
        "masse": pt.GameType.NINEBALL,
        "snooker": pt.GameType.SNOOKER,
        "threecushion": pt.GameType.THREECUSHION,
    }[kind]
    count = 2 if kind == "threecushion" else int(rng.integers(1, 4))
    system, cue_id, others = _placed(game, rng, count)
    target = others[0]
    # A cut: the object ball aimed at up to 25 degrees off full.
    cut = float(rng.uniform(-25.0, 25.0))
    R = system.balls[cue_id].params.R
    (cx, cy), (tx, ty) = (
        system.balls[cue_id].state.rvw[0, :2],
        system.balls[target].state.rvw[0, :2],
    )
    distance = math.hypot(tx - cx, ty - cy)
    offset = math.degrees(math.asin(min(1.0, 2 * R * math.sin(math.radians(cut)) / distance)))
    system.strike(
        V0=float(rng.uniform(1.5, 5.0 if kind == "threecushion" else 4.0)),
        phi=(pt.aim.at_ball(system, target) + offset) % 360.0,
        theta=float(rng.uniform(5.0, 35.0)) if kind == "masse" else 0.0,
        a=float(rng.uniform(-0.4, 0.4)),
        b=float(rng.uniform(-0.5, 0.5)),
    )
    return system


def shots(scale: float = 1.0) -> list[tuple[str, Any]]:
    """The set: ``(name, system)`` for each shot, :data:`COUNTS` times ``scale`` (at least
    one of each kind)."""
    return [
        (f"{kind}-{seed}", shot(kind, seed))
        for kind, count in COUNTS.items()
        for seed in range(max(1, round(count * scale)))
    ]


def _rounds(ways: dict[str, Any], systems: list[Any], runs: int, stock_runs: int) -> dict:
    """Each way's time per shot in each of ``runs`` rounds (stock's in the first
    ``stock_runs``), the ways taking turns within a round so that a change of the machine's
    load falls on all of them."""
    times: dict[str, list[float]] = {name: [] for name in ways}
    for r in range(runs):
        # Every other round the other way round: no way always runs right after another.
        order = list(ways.items())
        for name, way in order if r % 2 == 0 else reversed(order):
            if name.startswith("stock") and r >= stock_runs:
                continue
            start = time.perf_counter()
            way(systems)
            times[name].append((time.perf_counter() - start) / len(systems))
    return times


def _pairs(n: int) -> tuple[Any, ...]:
    """``collision_times``' arguments for ``n`` seeded random pairs on a pool table."""
    rng = np.random.default_rng(7)
    pos_a, pos_b = (rng.uniform(0.0, 2.0, (n, 2)) for _ in range(2))
    vel_a, vel_b = (rng.uniform(-2.0, 2.0, (n, 2)) for _ in range(2))
    return pos_a, vel_a, 0.2, pos_b, vel_b, 0.2, 0.05715


def _thread_shares(call: Any, runs: int) -> list[tuple[float, float]]:
    """For the two busiest threads other than this one in ``call``, busier first: the time
    (ms) each ran on a CPU and the time it waited in the run queue for one (another
    process's work on a shared machine), each the median over ``runs`` calls; empty where
    ``/proc`` has no per-thread scheduler statistics."""

    def times() -> dict[str, tuple[int, int]]:
        out = {}
        for task in os.listdir("/proc/self/task"):
            try:
                with open(f"/proc/self/task/{task}/schedstat") as f:
                    ran, waited = f.read().split()[:2]
                out[task] = (int(ran), int(waited))
            except OSError:
                pass  # a thread that ended meanwhile
        return out

    me = str(threading.get_native_id())
    if not os.path.exists(f"/proc/self/task/{me}/schedstat"):
        return []
    per_call = []
    for _ in range(runs):
        before = times()
        call()
        after = times()
        used = sorted(
            (
                (ran - before.get(t, (0, 0))[0], waited - before.get(t, (0, 0))[1])
                for t, (ran, waited) in after.items()
                if t != me
            ),
            reverse=True,
        )[:2]
        per_call.append(used + [(0, 0)] * (2 - len(used)))
    return [
        (
            statistics.median(c[i][0] for c in per_call) / 1e6,
            statistics.median(c[i][1] for c in per_call) / 1e6,
        )
        for i in (0, 1)
    ]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5, help="runs of each way (median)")
    parser.add_argument("--scale", type=float, default=1.0, help="times COUNTS shots")
    parser.add_argument("--stock-runs", type=int, default=3, help="runs of stock pooltool")
    args = parser.parse_args(argv)

    import pooltool as pt
    from machine import describe

    import ballcollide as bc
    import ballcollide.pooltool as bcp

    named = shots(args.scale)
    systems = [s for _, s in named]
    print(describe())
    print(
        f"{len(systems)} shots ({', '.join(f'{k} {v}' for k, v in COUNTS.items())} x {args.scale})"
    )
    # Warm-ups: numba's compilation, imports, the thread pools.
    pt.simulate(systems[0])
    bcp.simulate(systems[0])
    bcp.simulate_many(systems[:4], num_threads=2)

    # simulate_many's two parts: reading the pooltool objects into arrays (Rust, holding the
    # GIL, on the calling thread) and the engine on them (Rust, on the threads).
    from ballcollide import _core

    inputs = bcp._inputs(systems)

    def dropped(simulate: Any) -> Any:
        def way(ss: list[Any]) -> None:
            for s in ss:
                simulate(s)

        return way

    ways = {
        "stock": lambda ss: [pt.simulate(s) for s in ss],
        "stock drop": dropped(pt.simulate),
        "simulate": lambda ss: [bcp.simulate(s) for s in ss],
        "sim. drop": dropped(bcp.simulate),
        "many 1": lambda ss: bcp.simulate_many(ss, num_threads=1),
        "many 2": lambda ss: bcp.simulate_many(ss, num_threads=2),
        "reading": lambda ss: bcp._inputs(ss),
        "engine 1": lambda ss: _core.simulate_shots(**inputs, num_threads=1),
        "engine 2": lambda ss: _core.simulate_shots(**inputs, num_threads=2),
    }
    pairs = _pairs(1_000_000)
    ways["pairs 1"] = lambda ss: bc.collision_times(*pairs, num_threads=1)
    ways["pairs 2"] = lambda ss: bc.collision_times(*pairs, num_threads=2)
    rounds = _rounds(ways, systems, args.runs, args.stock_runs)
    median = {name: statistics.median(t) for name, t in rounds.items()}

    def over(one: str, two: str) -> float:
        """The median of the rounds' ratios of way ``one`` to way ``two`` (each round's
        two ran a moment apart, under the same load)."""
        return statistics.median(a / b for a, b in zip(rounds[one], rounds[two]))

    pairs_1, pairs_2 = (median.pop(k) * len(systems) for k in ("pairs 1", "pairs 2"))
    stock, stock_drop = median.pop("stock"), median.pop("stock drop")
    events = sum(len(s.events) for s in (bcp.simulate(x) for x in systems))
    print(f"{events} events ({events / len(systems):.0f} a shot)")
    print(f"{'way':<10} {'per shot':>12} {'vs stock':>10}")
    print(f"{'stock':<10} {stock * 1e3:>9.3f} ms {1.0:>9.1f}x")
    print(f"{'stock drop':<10} {stock_drop * 1e3:>9.3f} ms {1.0:>9.1f}x")
    for name, t in median.items():
        against = stock_drop if name.endswith("drop") else stock
        print(f"{name:<10} {t * 1e6:>9.1f} us {against / t:>9.1f}x")
    print("2 threads over 1 (the median of the rounds' ratios): ", end="")
    print(f"{over('many 1', 'many 2'):.2f}x (simulate_many), ", end="")
    print(f"{over('engine 1', 'engine 2'):.2f}x (the engine alone), ", end="")
    print(f"{over('pairs 1', 'pairs 2'):.2f}x (collision_times: ", end="")
    print(f"{pairs_1 * 1e3:.1f} / {pairs_2 * 1e3:.1f} ms)")
    shares = _thread_shares(lambda: _core.simulate_shots(**inputs, num_threads=2), args.runs)
    if shares:
        (ran_1, waited_1), (ran_2, waited_2) = shares
        print(f"engine 2, its threads per call (median): on a CPU {ran_1:.1f} / {ran_2:.1f} ms;")
        print(f"  waiting for one {waited_1:.1f} / {waited_2:.1f} ms")
    # A shared machine's other work moves every figure (and takes the second core).
    print(f"load average (1, 5, 15 min) at the end: {os.getloadavg()}, {os.cpu_count()} CPUs")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
