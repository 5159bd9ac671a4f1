"""``bc.simulate`` on a pool table against the same balls in the plain box of its playing
area: what the table's objects cost per event, from Python, one thread, in one run.

Breaks: a rack of 15 and the cue ball (``bc.pool_table()``: 18 segments, 12 jaw tips, 6
pockets, in a box 0.3 m beyond the playing area), the cue ball at 4–9 m/s, friction 0.4 m/s²,
restitution 0.95, cushions 0.8, each to rest; ``--shots`` of them per timing, the median of
``--repeats`` timings. Prints the CPU, µs per event on the table and in the box, and their
ratio.

``python benchmarks/table_simulate.py`` (the Rust figure: ``cargo run --release --example
table_timing``).
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from machine import cpu_model

import ballcollide as bc

R = 0.028575  # m
WIDTH, LENGTH = 1.27, 2.54


def rack(speed: float, aim: float) -> tuple[np.ndarray, np.ndarray]:
    gap = 1.0 + 1e-6
    pos = [(WIDTH / 2, LENGTH / 4)]
    for row in range(5):
        for k in range(row + 1):
            x = WIDTH / 2 + (2 * k - row) * R * gap
            y = 0.75 * LENGTH + row * np.sqrt(3) * R * gap
            pos.append((x, y))
    vel = np.zeros((16, 2))
    vel[0] = speed * np.sin(aim), speed * np.cos(aim)
    return np.array(pos), vel


def timing(shots: list, **options) -> tuple[float, int]:
    """Seconds for every shot once, and the events."""
    events = 0
    t0 = time.perf_counter()
    for pos, vel in shots:
        run = bc.simulate(pos, vel, 0.4, R, restitution=0.95, **options)
        events += len(run.times)
    return time.perf_counter() - t0, events


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--shots", type=int, default=100)
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    rng = np.random.default_rng(3)
    shots = [rack(rng.uniform(4, 9), rng.uniform(-0.02, 0.02)) for _ in range(args.shots)]
    table = bc.pool_table()
    on_table = {"box": ([-0.3, -0.3], [WIDTH + 0.3, LENGTH + 0.3]), "table_restitution": 0.8}
    on_table |= table
    in_box = {"box": ([0.0, 0.0], [WIDTH, LENGTH])}
    per_event = {"table": [], "box": []}
    events = {}
    for _ in range(args.repeats):
        for name, options in (("table", on_table), ("box", in_box)):
            seconds, count = timing(shots, **options)
            per_event[name].append(seconds * 1e6 / max(count, 1))
            events[name] = count
    t_table, t_box = (float(np.median(per_event[k])) for k in ("table", "box"))
    print(f"CPU: {cpu_model()} (bc.simulate runs scalar code: no SIMD level applies)")
    print(f"{args.shots} breaks to rest, median of {args.repeats}")
    print("| scene | µs/event | events |")
    print("|---|---:|---:|")
    print(f"| on the pool table | {t_table:.2f} | {events['table']:,} |")
    print(f"| in the plain box | {t_box:.2f} | {events['box']:,} |")
    print(f"ratio: {t_table / t_box:.2f}")


if __name__ == "__main__":
    main()
