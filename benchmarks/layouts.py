"""What the layout of the inputs costs ``bc.collision_times``, in one run, on one thread.

The pairs are ``compare.py``'s random table pairs (both balls anywhere on a 9-ft table,
speeds 0–3 m/s, friction 0.05–2 m/s², contact distance two pool-ball radii), given as:

- ``C order``: C-ordered float64 ``(N, 2)`` rows and ``(N,)`` frictions (read in place);
- ``F order (N, 2): vel_a``: ``vel_a`` Fortran-ordered (``np.stack([vx, vy], 0).T``, as
  issue 35 found it), the rest C-ordered; ``F order (N, 2): all four``: the four ``(N, 2)``
  arrays Fortran-ordered;
- ``columns of (N, 10)``: every input a column view of one C-ordered ``(N, 10)`` table;
- ``every other row``: every input ``[::2]`` of an array twice as long;
- ``reversed``: every input ``[::-1]`` of a C-ordered array (negative strides);
- ``float32``: C-ordered float32 (the values rounded to float32);
- ``int64``: C-ordered int64 (millimetres, mm/s and mm/s², rounded);
- ``lists``: nested Python lists (``.tolist()``), on ``--list-pairs`` pairs.

Each layout is timed as the call itself and as the user's workaround on the same inputs
(``np.ascontiguousarray(x, dtype=np.float64)`` of each input, then the call). Every
measurement is the median over ``--repeats`` rounds of the process's CPU time (what the work
costs: on shared, loaded cores wall time adds the time spent waiting for a core) and, beside
it, of wall time; the rounds interleave the layouts, so that a change in the machine's load
touches them all alike. ``kernel`` is the Rust kernel's own (wall) time in the call
(``_core._last_kernel_seconds``): the rest is reading the inputs and the call's overhead.
Ratios are to the C-ordered call in the same run.

    python benchmarks/layouts.py [--pairs 1000000] [--list-pairs 100000] [--repeats 9]
"""

from __future__ import annotations

import argparse
import shlex
import sys
import time
from collections.abc import Callable
from typing import Any

import numpy as np
from compare import RADIUS, Pairs, random_table
from machine import describe

import ballcollide as bc
from ballcollide import _core

Inputs = dict[str, Any]
NAMES = ("pos_a", "vel_a", "friction_a", "pos_b", "vel_b", "friction_b")


def c_order(p: Pairs) -> Inputs:
    return dict(zip(NAMES, (p.pos_a, p.vel_a, p.mu_a, p.pos_b, p.vel_b, p.mu_b)))


def f_order(p: Pairs) -> Inputs:
    return {k: np.asfortranarray(v) if v.ndim == 2 else v for k, v in c_order(p).items()}


def f_vel_a(p: Pairs) -> Inputs:
    return {**c_order(p), "vel_a": np.stack([p.vel_a[:, 0], p.vel_a[:, 1]], 0).T}


def columns(p: Pairs) -> Inputs:
    table = np.empty((len(p), 10))
    spans = {"pos_a": 0, "vel_a": 2, "pos_b": 5, "vel_b": 7}
    table[:, 4], table[:, 9] = p.mu_a, p.mu_b
    for name, k in spans.items():
        table[:, k : k + 2] = getattr(p, name)
    views = {name: table[:, k : k + 2] for name, k in spans.items()}
    return {**views, "friction_a": table[:, 4], "friction_b": table[:, 9]}


def every_other_row(p: Pairs) -> Inputs:
    def spread(v: np.ndarray) -> np.ndarray:
        wide = np.zeros((2 * len(v), *v.shape[1:]))
        wide[::2] = v
        return wide[::2]

    return {k: spread(v) for k, v in c_order(p).items()}


def reversed_rows(p: Pairs) -> Inputs:
    return {k: np.ascontiguousarray(v[::-1])[::-1] for k, v in c_order(p).items()}


def float32(p: Pairs) -> Inputs:
    return {k: v.astype(np.float32) for k, v in c_order(p).items()}


def int64(p: Pairs) -> Inputs:
    return {k: np.rint(v * 1000).astype(np.int64) for k, v in c_order(p).items()}


def lists(p: Pairs) -> Inputs:
    return {k: v.tolist() for k, v in c_order(p).items()}


# name, inputs, contact distance (int64 is in millimetres), pairs: "all" or "lists"
LAYOUTS: list[tuple[str, Callable[[Pairs], Inputs], float, str]] = [
    ("C order", c_order, RADIUS, "all"),
    ("F order (N, 2): vel_a", f_vel_a, RADIUS, "all"),
    ("F order (N, 2): all four", f_order, RADIUS, "all"),
    ("columns of (N, 10)", columns, RADIUS, "all"),
    ("every other row", every_other_row, RADIUS, "all"),
    ("reversed (negative strides)", reversed_rows, RADIUS, "all"),
    ("float32", float32, RADIUS, "all"),
    ("int64 (mm)", int64, RADIUS * 1000, "all"),
    ("C order", c_order, RADIUS, "lists"),
    ("lists", lists, RADIUS, "lists"),
]


def call(inputs: Inputs, radius: float) -> Callable[[], float]:
    """The call; returns its kernel's seconds."""

    def run() -> float:
        bc.collision_times(**inputs, contact_distance=radius, num_threads=1)
        return float(_core._last_kernel_seconds())

    return run


def workaround(inputs: Inputs, radius: float) -> Callable[[], float]:
    """``np.ascontiguousarray`` of each input, then the call; returns its kernel's seconds."""

    def run() -> float:
        given = {k: np.ascontiguousarray(v, dtype=np.float64) for k, v in inputs.items()}
        bc.collision_times(**given, contact_distance=radius, num_threads=1)
        return float(_core._last_kernel_seconds())

    return run


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pairs", type=int, default=1_000_000)
    parser.add_argument("--list-pairs", type=int, default=100_000)
    parser.add_argument("--repeats", type=int, default=9)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()

    data = random_table(np.random.default_rng(args.seed), args.pairs)
    sizes = {"all": args.pairs, "lists": min(args.list_pairs, args.pairs)}
    # (label, pairs, kind) → timed function
    cases: dict[tuple[str, int, str], Callable[[], float]] = {}
    for name, make, radius, size in LAYOUTS:
        inputs = make(data.head(sizes[size]))
        label = f"{name}, N = {sizes[size]:,}"
        cases[(label, sizes[size], "call")] = call(inputs, radius)
        cases[(label, sizes[size], "workaround")] = workaround(inputs, radius)

    Key = tuple[str, int, str]
    wall: dict[Key, list[float]] = {key: [] for key in cases}
    cpu: dict[Key, list[float]] = {key: [] for key in cases}
    kernel: dict[Key, list[float]] = {key: [] for key in cases}
    for f in cases.values():  # warm-up
        f()
    for _ in range(args.repeats):
        for key, f in cases.items():
            w, c = time.perf_counter(), time.process_time()
            k = f()
            wall[key].append(time.perf_counter() - w)
            cpu[key].append(time.process_time() - c)
            kernel[key].append(k)

    def ns(key: Key, of: dict[Key, list[float]]) -> float:
        return float(np.median(of[key])) / key[1] * 1e9

    print(f"{describe()}; numpy {np.__version__}; one thread (num_threads=1)")
    print(f"command: python {shlex.join(sys.argv)}")
    print(
        f"medians of {args.repeats} interleaved rounds; ns/pair is process CPU time (on shared "
        "cores the work, where wall time adds queueing), wall time beside it; ratios to "
        "C order of the same N\n"
    )
    print(
        "| layout | ns/pair | × C order | wall ns/pair | kernel ns/pair (wall) "
        "| workaround ns/pair | workaround × C order | call / workaround |"
    )
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    base: dict[int, float] = {}
    for label, n, kind in cases:
        if kind != "call":
            continue
        mine, theirs = ns((label, n, "call"), cpu), ns((label, n, "workaround"), cpu)
        base.setdefault(n, mine)
        print(
            f"| {label} | {mine:.1f} | {mine / base[n]:.2f} | {ns((label, n, 'call'), wall):.1f} "
            f"| {ns((label, n, 'call'), kernel):.1f} | {theirs:.1f} | {theirs / base[n]:.2f} "
            f"| {mine / theirs:.2f} |"
        )


if __name__ == "__main__":
    main()
