"""Python timing of the scene queries (issue 6): ``earliest_collision`` with its broad phase
against the all-pairs answer a simulator gets from ``collision_times`` on every pair.

Scenes as in ``benches/scene.rs``: N = 16 is a pool break (rack of 15 at rest, cue ball
at 3 m/s); larger N are balls on a table scaled to keep 16 balls per 2.54 m × 1.27 m, half
rolling at up to 1 m/s, friction 0.1–0.3 m/s². All pairs up to N = 4,000 (memory).

    .venv/bin/python benches/scene.py
"""

from __future__ import annotations

import math
import time

import numpy as np

import ballcollide as bc

R = 0.028575


def rack() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    d = 2 * R
    pos = [
        (1.9 + row * d * math.sqrt(3) / 2, 0.635 + (k - row / 2) * d)
        for row in range(5)
        for k in range(row + 1)
    ]
    pos.append((0.635, 0.64))
    vel = np.zeros((16, 2))
    vel[15] = (3.0, 0.0)
    friction = np.where(np.arange(16) == 15, 0.2, 0.0)
    return np.array(pos), vel, friction


def table(n: int, seed: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    scale = math.sqrt(n / 16)
    pos = rng.uniform([0, 0], [2.54 * scale, 1.27 * scale], (n, 2))
    angle = rng.uniform(0, 2 * np.pi, n)
    speed = rng.uniform(0, 1, n) * (np.arange(n) % 2 == 0)
    vel = np.column_stack([speed * np.cos(angle), speed * np.sin(angle)])
    return pos, vel, rng.uniform(0.1, 0.3, n)


def best_of(f, args: tuple, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        f(*args)
        times.append(time.perf_counter() - start)
    return min(times)


def all_pairs(pos: np.ndarray, vel: np.ndarray, friction: np.ndarray) -> tuple[float, int, int]:
    i, j = np.triu_indices(len(pos), k=1)
    t = bc.collision_times(pos[i], vel[i], friction[i], pos[j], vel[j], friction[j], 2 * R)
    k = int(np.argmin(t))
    return (float(t[k]), int(i[k]), int(j[k])) if np.isfinite(t[k]) else (math.inf, -1, -1)


def main() -> None:
    print(f"{'N':>8} {'broad phase':>14} {'all pairs':>14} {'speed-up':>9}")
    for n in (16, 1_000, 4_000, 10_000, 100_000):
        pos, vel, friction = rack() if n == 16 else table(n, n)
        repeat = 200 if n <= 1000 else 5
        scene = (pos, vel, friction, R)
        fast = best_of(bc.earliest_collision, scene, repeat)
        if n <= 4_000:
            assert all_pairs(pos, vel, friction) == bc.earliest_collision(pos, vel, friction, R)
            slow = best_of(all_pairs, scene[:3], max(1, repeat // 10))
            print(f"{n:>8} {fast * 1e3:>11.3f} ms {slow * 1e3:>11.3f} ms {slow / fast:>8.0f}×")
        else:
            print(f"{n:>8} {fast * 1e3:>11.3f} ms {'—':>14} {'':>9}")


if __name__ == "__main__":
    main()
