"""The event calendar's speed: ``bc.simulate`` against python-billiards 0.5.0 on the same
frictionless disks, and the calendar driven from Python on a 16-ball break.

Scene (issue 18): ``N`` frictionless disks of equal mass in the unit box, on a grid
(``√N × √N``), radius ``½·L/√N·½``, velocities normal(0, 1), seeded.

- ``simulate``: ``bc.simulate(..., max_events=E)`` in this process, one thread; µs per event
  is the median wall time over ``--repeats`` runs divided by ``E``, the calendar's build
  included (it is part of a run).
- ``billiards``: python-billiards 0.5.0 (PyPI ``billiards``) in its own environment
  (``--billiards-python``, e.g. a venv made with ``python -m venv .venv-bench &&
  .venv-bench/bin/pip install billiards==0.5.0``), in a subprocess on the very same scene
  (handed over in an ``.npz`` file): its own event loop (``bounce_ballball`` /
  ``bounce_ballobstacle``, what ``Billiard.evolve`` runs) for ``E`` events. Its first events
  are compared with ``simulate``'s (same pairs and walls, times to 1e-9).
- ``--large``: ``simulate`` alone at N = 1e3 … 1e6.
- ``--break``: the 16-ball break of ``examples/event_driven.py`` (friction 0.6 m/s², walls of
  the table), driven from Python: per event the calendar's calls (``next_event`` and
  ``update_balls``, timed apart from the resolution in Python), against one
  ``bc.earliest_collision`` call on the state after each event (what a simulator without the
  calendar asks after every event; it knows no walls).
- ``--pooltool`` (with ``--break``, run with ``.venv-pooltool/bin/python`` after
  ``scripts/install-pooltool``): pooltool 0.6.0's own event loop, ``pooltool.simulate()`` on
  three of its 8-ball breaks (16 balls; its own physics, so only the order of magnitude
  compares), per event, in the same run.

``python benchmarks/event_calendar.py --billiards-python .venv-bench/bin/python --large
--break`` prints one table; numbers are medians of the repeats, ratios in the same run.
"""

from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import ballcollide as bc

# Run by the billiards interpreter: the scene from an .npz, E events, a JSON line out.
BILLIARDS_RUNNER = r"""
import json, sys, time
import numpy as np
import billiards
from billiards.obstacles import InfiniteWall

data = np.load(sys.argv[1])
events = int(sys.argv[2])
repeats = int(sys.argv[3])
walls = [
    InfiniteWall((0, 0), (1, 0)), InfiniteWall((1, 0), (1, 1)),
    InfiniteWall((1, 1), (0, 1)), InfiniteWall((0, 1), (0, 0)),
]
times = []
first = []
for _ in range(repeats):
    table = billiards.Billiard(obstacles=walls)
    for p, v in zip(data["pos"], data["vel"]):
        table.add_ball(p, v, radius=float(data["radius"]), mass=1.0)
    log = []
    begin = time.perf_counter()
    for _ in range(events):
        if table.toi_next[0] <= table.obstacles_next[0]:
            t, i, j = table.bounce_ballball()
        else:
            t, i, obstacle = table.bounce_ballobstacle()
            j = -1
        log.append((float(t), int(i), int(j)))
    times.append(time.perf_counter() - begin)
    first = log[:50]
print(json.dumps({"seconds": sorted(times)[len(times) // 2], "first": first}))
"""


def scene(n: int, seed: int = 7) -> tuple[np.ndarray, np.ndarray, float]:
    side = max(1, round(math.sqrt(n)))
    spacing = 1.0 / side
    k = np.arange(side * side)
    pos = np.stack([(k % side + 0.5) * spacing, (k // side + 0.5) * spacing], axis=1)
    vel = np.random.default_rng(seed).normal(0.0, 1.0, (side * side, 2))
    return pos, vel, 0.25 * spacing


def time_simulate(n: int, events: int, repeats: int) -> tuple[float, tuple]:
    pos, vel, r = scene(n)
    seconds = []
    result: tuple = ()
    for _ in range(repeats):
        begin = time.perf_counter()
        result = bc.simulate(pos, vel, 0.0, r, box=([0, 0], [1, 1]), max_events=events)
        seconds.append(time.perf_counter() - begin)
    return float(np.median(seconds)) / events * 1e6, result


def time_billiards(python: str, n: int, events: int, repeats: int) -> tuple[float, list]:
    pos, vel, r = scene(n)
    with tempfile.TemporaryDirectory() as tmp:
        data = Path(tmp) / "scene.npz"
        np.savez(data, pos=pos, vel=vel, radius=r)
        out = subprocess.run(
            [python, "-c", BILLIARDS_RUNNER, str(data), str(events), str(repeats)],
            check=True,
            capture_output=True,
            text=True,
        )
    report = json.loads(out.stdout.strip().splitlines()[-1])
    return report["seconds"] / events * 1e6, report["first"]


def same_first_events(ours: tuple, theirs: list) -> int:
    """How many of the first events agree (pair or wall, time to 1e-9)."""
    times, i, j = ours[0], ours[1], ours[2]
    agree = 0
    for k, (t, a, b) in enumerate(theirs):
        if k >= len(times):
            break
        pair = (int(i[k]), int(j[k]))
        if pair != (a, b) or abs(times[k] - t) > 1e-9 * max(1.0, abs(t)):
            break
        agree += 1
    return agree


def break_scene() -> tuple[np.ndarray, np.ndarray, float, tuple]:
    """The break of examples/event_driven.py: a rack of 15 and the cue ball at 6 m/s."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "examples"))
    try:
        from event_driven import BALL_RADIUS, TABLE, rack_and_cue
    finally:
        sys.path.pop(0)
    pos, vel = rack_and_cue()
    return pos, vel, BALL_RADIUS, ((0.0, 0.0), TABLE)


def friction_state(p: np.ndarray, v: np.ndarray, mu: float, dt: float) -> tuple:
    """A friction ball's centre and velocity ``dt`` after ``(p, v)``."""
    speed = math.hypot(v[0], v[1])
    if speed == 0:
        return p.copy(), v.copy()
    u = min(dt, speed / mu)
    direction = v / speed
    return p + v * u - 0.5 * mu * direction * u * u, v - mu * direction * u


def time_break(repeats: int, mu: float = 0.6) -> dict:
    """The break driven from Python: the calendar's calls (``next_event`` and
    ``update_balls``) timed apart from the resolution in Python, and one
    ``earliest_collision`` (after ``positions_at``) on the state after each event."""
    pos0, vel0, r, box = break_scene()
    calls, resolution, scratch, counts = [], [], [], []
    for _ in range(repeats):
        s = bc.CollisionSchedule.from_balls(pos0, vel0, mu, r, box=box)
        pos, vel, since = pos0.copy(), vel0.copy(), np.zeros(len(pos0))
        states = []
        in_calls = in_python = 0.0
        while True:
            begin = time.perf_counter()
            e = s.next_event()
            middle = time.perf_counter()
            in_calls += middle - begin
            if e.time == math.inf:
                break
            idx = [e.i] if e.j < 0 else [e.i, e.j]
            moved = [friction_state(pos[b], vel[b], mu, e.time - since[b]) for b in idx]
            p = [m[0] for m in moved]
            v = [m[1] for m in moved]
            if e.j < 0:  # a wall: index 2·axis (low) or 2·axis + 1 (high)
                axis = e.index // 2
                v[0][axis] = -v[0][axis]
            else:
                n = (p[0] - p[1]) / np.linalg.norm(p[0] - p[1])
                dv = np.dot(v[0] - v[1], n) * n
                v = [v[0] - dv, v[1] + dv]
            for b, pb, vb in zip(idx, p, v):
                pos[b], vel[b], since[b] = pb, vb, e.time
            states.append((pos.copy(), vel.copy(), since.copy(), e.time))
            middle2 = time.perf_counter()
            in_python += middle2 - middle
            s.update_balls(idx, e.time, p, v, mu)
            in_calls += time.perf_counter() - middle2
        events = len(states)
        calls.append(in_calls / max(events, 1))
        resolution.append(in_python / max(events, 1))
        counts.append(events)
        # The same states, asked from scratch.
        moved_states = []
        for sp, sv, st, now in states:
            moved_states.append([friction_state(sp[b], sv[b], mu, now - st[b]) for b in range(16)])
        begin = time.perf_counter()
        for state in moved_states:
            here = np.array([m[0] for m in state])
            v_now = np.array([m[1] for m in state])
            bc.earliest_collision(here, v_now, mu, r)
        scratch.append((time.perf_counter() - begin) / max(events, 1))
    return {
        "events": int(np.median(counts)),
        "calls_us": float(np.median(calls)) * 1e6,
        "python_us": float(np.median(resolution)) * 1e6,
        "earliest_us": float(np.median(scratch)) * 1e6,
    }


def time_pooltool_breaks(seeds: int, repeats: int) -> float:
    """pooltool's own event loop per event (µs): ``pooltool.simulate()`` on its 8-ball breaks
    (16 balls, the breaks of ``benchmarks/pooltool_dropin.py``), stock detector, the median
    over ``repeats`` runs of each break, summed over the breaks and divided by their events.
    Needs pooltool (the environment of ``scripts/install-pooltool``)."""
    import pooltool as pt
    from pooltool_dropin import break_shot

    systems = [break_shot("eight", seed) for seed in range(seeds)]
    pt.simulate(systems[0])  # numba's compile (or cache load) out of the timings
    seconds, events = 0.0, 0
    for system in systems:
        runs = []
        for _ in range(repeats):
            start = time.perf_counter()
            result = pt.simulate(system)
            runs.append(time.perf_counter() - start)
        seconds += float(np.median(runs))
        events += len(result.events)
    return seconds / events * 1e6


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--billiards-python", help="an interpreter that has billiards 0.5.0")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--large", action="store_true", help="bc.simulate at N = 1e3 … 1e6")
    parser.add_argument("--break", dest="pool", action="store_true", help="the 16-ball break")
    parser.add_argument(
        "--pooltool",
        action="store_true",
        help="with --break: pooltool's own event loop on its 8-ball breaks, per event",
    )
    args = parser.parse_args()

    print("| N | events | bc.simulate µs/event | billiards µs/event | ratio | same first events |")
    print("|---|---|---|---|---|---|")
    for n, events, billiards_events in [(16, 20000, 2000), (1000, 20000, 200)]:
        ours, result = time_simulate(n, events, args.repeats)
        if args.billiards_python:
            theirs, first = time_billiards(args.billiards_python, n, billiards_events, args.repeats)
            agree = same_first_events(result, first)
            ratio = theirs / ours
            print(f"| {n} | {events} | {ours:.2f} | {theirs:.0f} | {ratio:.0f}× | {agree} of 50 |")
        else:
            print(f"| {n} | {events} | {ours:.2f} | (not run) | | |")
    if args.large:
        print()
        print("| N | events | bc.simulate µs/event (build included) |")
        print("|---|---|---|")
        for n in [1000, 10_000, 100_000, 1_000_000]:
            events = max(100_000, 2 * n)
            ours, _ = time_simulate(n, events, 1 if n >= 100_000 else args.repeats)
            print(f"| {n} | {events} | {ours:.2f} |")
    if args.pool:
        report = time_break(args.repeats)
        print()
        print(
            f"16-ball break from Python: {report['events']} events; per event "
            f"next_event + update_balls {report['calls_us']:.1f} µs (the resolution in "
            f"Python {report['python_us']:.1f} µs more), earliest_collision "
            f"{report['earliest_us']:.1f} µs"
        )
        if args.pooltool:
            pooltool_us = time_pooltool_breaks(seeds=3, repeats=args.repeats)
            ours_us = report["calls_us"] + report["python_us"]
            print(
                f"pooltool 0.6.0's own event loop on its 8-ball breaks (16 balls, its own "
                f"physics): {pooltool_us:.0f} µs per event; the calendar driven from Python "
                f"above, resolution included: {ours_us:.1f} µs ({pooltool_us / ours_us:.0f}×)"
            )
    sys.stdout.flush()


if __name__ == "__main__":
    main()
