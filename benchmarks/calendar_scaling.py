"""The calendar's cost per event with and without friction, dense and dilute, boxed and
open, and where pairs never meet (no horizon): ``bc.simulate`` and ``bc.CollisionSchedule``,
one thread, in one run.

- ``friction``: ``N`` balls in the unit box on a grid (``√N × √N``), radius ``¼/√N``,
  velocities normal(0, 1) seeded by ``N``, ``max_events=5N``, friction ``μ`` from 0 to 5:
  µs per event (median of ``--repeats`` runs, and of as many more as fill 0.2 s), and each
  friction's ratio to the frictionless run at the same ``N``; once with the calendar's build
  (and the call) included, once after them (the same run less one with ``max_events=0``):
  a strong friction stops the balls within a few events, over which the build is shared;
  and once more with the build, against the frictionless run cut at the same number of
  events (where a friction run ends sooner), so that both share the fixed cost alike.
- ``horizons``: balls that never meet: one to 200 balls moving in parallel in a box (no
  ``t_end``, against ``t_end=100``), and 100 or 400 balls moving in parallel in open space,
  the first ``next_collision()`` with ``t_max=inf`` against ``t_max=1e3``.
- ``build``: ``CollisionSchedule.from_balls`` of 10⁵ balls in a 100 × 100 box (radius 0.01),
  frictionless and with friction 0.1.

``python benchmarks/calendar_scaling.py`` prints the CPU model and one table per part.
"""

from __future__ import annotations

import argparse
import time
from functools import partial

import numpy as np
from machine import cpu_model

import ballcollide as bc


def median_time(f, repeats: int, least: float = 0.2):
    """The median time of `repeats` calls of `f`, or of as many more as take `least` seconds
    (short runs on a shared machine), and the last result."""
    times, result = [], None
    while len(times) < repeats or sum(times) < least:
        t0 = time.perf_counter()
        result = f()
        times.append(time.perf_counter() - t0)
    return float(np.median(times)), result


def grid_scene(n: int):
    side = int(np.ceil(np.sqrt(n)))
    k = np.arange(n)
    pos = np.stack([(k % side + 0.5) / side, (k // side + 0.5) / side], 1)
    return pos, 0.25 / np.sqrt(n)


SAME_LENGTH = "the build included, against the frictionless run cut at as many events"


def friction(sizes, frictions, repeats: int) -> None:
    tables = {"the build included": [], "after the build": [], SAME_LENGTH: []}
    for n in sizes:
        pos, r = grid_scene(n)
        vel = np.random.default_rng(n).normal(size=(n, 2))
        rows = {name: [] for name in tables}
        base = {}
        frictionless = partial(bc.simulate, pos, vel, 0.0, r, box=([0, 0], [1, 1]))
        for mu in frictions:
            run = partial(bc.simulate, pos, vel, mu, r, box=([0, 0], [1, 1]))
            seconds, result = median_time(partial(run, max_events=5 * n), repeats)
            build, _ = median_time(partial(run, max_events=0), repeats)
            events = max(1, len(result[0]))
            per = {
                "the build included": seconds / events * 1e6,
                "after the build": max(0.0, seconds - build) / events * 1e6,
                SAME_LENGTH: seconds / events * 1e6,
            }
            if mu == 0:
                base = per
            # What each ratio is taken against: the frictionless run; for SAME_LENGTH, where
            # the balls are at rest before the last event (the call's fixed cost, the build
            # and the binding, shared by fewer events), that run cut at as many events.
            against = dict(base)
            if mu != 0 and events < 5 * n:
                same, _ = median_time(partial(frictionless, max_events=events), repeats)
                against[SAME_LENGTH] = same / events * 1e6
            for name, value in per.items():
                ratio = f" ({value / against[name]:.1f}×)" if mu != 0 and against.get(name) else ""
                rows[name].append(f"{value:.1f}{ratio}")
            rows["after the build"][-1] += f", {events} events"
        for name in tables:
            tables[name].append(f"| {n:,} | " + " | ".join(rows[name]) + " |")
    for name, lines in tables.items():
        print(f"\nµs per event, {name}:\n")
        print("| N | " + " | ".join(f"μ = {mu} (× μ=0)" for mu in frictions) + " |")
        print("|---:|" + "---:|" * len(frictions))
        print("\n".join(lines), flush=True)


def first_collision(pos, vel, t_max):
    return bc.CollisionSchedule.from_balls(pos, vel, 0.0, 0.5, t_max=t_max).next_collision()


def horizons(repeats: int) -> None:
    print("\n| scene | no horizon | with a horizon |")
    print("|---|---:|---:|")
    for n in [1, 4, 200]:
        pos, r = grid_scene(n)
        vel = np.tile([0.3, 0.7], (n, 1))
        cells = []
        for t_end in [np.inf, 100.0]:
            box = ([0, 0], [1, 1])
            run = partial(bc.simulate, pos, vel, 0.0, r, box=box, t_end=t_end, max_events=2000)
            seconds, result = median_time(run, repeats)
            cells.append(f"{seconds / max(1, len(result[0])) * 1e6:.1f} µs/event")
        print(f"| {n} parallel balls in a box | {cells[0]} | {cells[1]} (t_end=100) |")
    for n in [100, 400]:
        pos = np.stack([np.arange(n) * 3.0, np.zeros(n)], 1)
        vel = np.tile([0.0, 1.0], (n, 1))
        cells = []
        for t_max in [np.inf, 1e3]:
            seconds, _ = median_time(partial(first_collision, pos, vel, t_max), repeats)
            cells.append(f"{seconds * 1e3:.2f} ms")
        print(
            f"| {n} parallel balls in open space, first next_collision | {cells[0]} | "
            f"{cells[1]} (t_max=1e3) |",
            flush=True,
        )


def build(repeats: int) -> None:
    print("\n| from_balls, 10⁵ balls | seconds |")
    print("|---|---:|")
    n = 100_000
    rng = np.random.default_rng(2)
    pos = rng.uniform(0, 100, size=(n, 2))
    vel = rng.normal(size=(n, 2))
    for mu in [0.0, 0.1]:
        seconds, _ = median_time(
            lambda mu=mu: bc.CollisionSchedule.from_balls(
                pos, vel, mu, 0.01, box=([0, 0], [100, 100])
            ),
            repeats,
        )
        print(f"| friction {mu} | {seconds:.3f} |", flush=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--sizes", type=int, nargs="+", default=[16, 100, 400, 1600, 6400])
    parser.add_argument("--frictions", type=float, nargs="+", default=[0.0, 0.01, 0.5, 5.0])
    parser.add_argument("--parts", nargs="+", default=["friction", "horizons", "build"])
    args = parser.parse_args()
    print(f"CPU: {cpu_model()}; one thread (simulate and the calendar are sequential)")
    if "friction" in args.parts:
        friction(args.sizes, args.frictions, args.repeats)
    if "horizons" in args.parts:
        horizons(args.repeats)
    if "build" in args.parts:
        build(args.repeats)


if __name__ == "__main__":
    main()
