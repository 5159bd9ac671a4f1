"""Collision times of 10⁸ pairs of balls with Dask, out of core, on one machine.

The pairs are random shots on a pool table (2.54 m × 1.27 m, balls of 57.15 mm): both
balls anywhere on the table, ball A at up to 3 m/s with a per-pair rolling friction of
0.05–0.3 m/s², ball B at up to 1 m/s with 0.1 m/s² (cushions are ignored). The inputs are
generated chunk by chunk from a seed by Dask's random generator and never held in memory
whole (10⁸ pairs are 7.2 GB of float64 inputs); each chunk's times are reduced to a few
numbers as soon as they are computed.

Run it (needs ``pip install 'ballcollide[dask]'``; ``distributed`` for ``--scheduler
distributed``)::

    python examples/dask_at_scale.py                  # 10⁸ pairs, all cores
    python examples/dask_at_scale.py --pairs 1e6      # a quick run
    python examples/dask_at_scale.py --scheduler distributed --workers 2

It prints the number of collisions, the earliest one, the throughput in pairs per second
(generating the inputs included) and the peak memory (resident set size) of the process and
of its worker processes. ``--check`` also recomputes the first and last chunks in memory
with :func:`ballcollide.collision_times` and checks that the times are bitwise the same.
"""

from __future__ import annotations

import argparse
import os
import platform
import resource
import sys
import time
from datetime import datetime, timezone
from typing import Any

import dask
import dask.array as da
import numpy as np

import ballcollide
import ballcollide.dask as bcd

TABLE = (2.54, 1.27)  # m
RADIUS = 2 * 0.028575  # m: contact distance = two pool-ball radii


def scene(pairs: int, chunk: int, seed: int) -> dict[str, Any]:
    """The lazy inputs of ``pairs`` random shots, in chunks of ``chunk`` pairs."""
    rng = da.random.default_rng(seed)
    rows = ((pairs, 2), (chunk, 2))  # (N, 2) arrays: the two columns in one chunk

    def velocity(max_speed: float) -> da.Array:
        g = rng.standard_normal(*rows)  # a uniformly random direction …
        direction = g / da.sqrt((g**2).sum(axis=1, keepdims=True))
        return direction * rng.uniform(0.0, max_speed, size=(pairs, 1), chunks=(chunk, 1))

    return {
        "pos_a": rng.uniform(0.0, 1.0, *rows) * np.array(TABLE),
        "vel_a": velocity(3.0),
        "friction_a": rng.uniform(0.05, 0.3, size=pairs, chunks=chunk),
        "pos_b": rng.uniform(0.0, 1.0, *rows) * np.array(TABLE),
        "vel_b": velocity(1.0),
        "friction_b": 0.1,
        "contact_distance": RADIUS,
    }


def cpu_seconds() -> float:
    """User + system CPU time of this process and of its finished children so far."""
    own = resource.getrusage(resource.RUSAGE_SELF)
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def peak_rss_mib() -> tuple[float, float]:
    """Peak resident memory of this process and of its largest finished child, in MiB."""
    kib = 1024.0 if sys.platform != "darwin" else 1024.0 * 1024.0  # ru_maxrss units
    own = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / kib
    children = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / kib
    return own, children


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--pairs", type=float, default=1e8, help="number of pairs (1e8)")
    parser.add_argument("--chunk", type=float, default=1e6, help="pairs per chunk (1e6)")
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument(
        "--scheduler",
        choices=["threads", "processes", "distributed"],
        default="threads",
        help="Dask scheduler (threads: one per core)",
    )
    parser.add_argument(
        "--workers", type=int, default=os.cpu_count() or 1, help="threads or processes"
    )
    parser.add_argument("--check", action="store_true", help="recompute 2 chunks in memory")
    args = parser.parse_args(argv)
    pairs, chunk = int(args.pairs), int(args.chunk)
    if pairs < 1 or chunk < 1:
        parser.error("--pairs and --chunk must be ≥ 1")

    inputs = scene(pairs, chunk, args.seed)
    # One kernel thread per chunk (the default): Dask runs one chunk per worker thread.
    t = bcd.collision_times(**inputs)
    hit = da.isfinite(t)
    results = {
        "collisions": hit.sum(),
        "at t = 0 (touching and approaching)": (t == 0).sum(),
        "earliest later collision [s]": da.where(t > 0, t, np.inf).min(),
        "mean collision time [s]": da.where(hit, t, 0.0).sum() / hit.sum(),
        "latest collision [s]": da.where(hit, t, -np.inf).max(),
    }

    print(
        f"{pairs:,} pairs in {t.numblocks[0]} chunks of ≤ {chunk:,}, "
        f"scheduler {args.scheduler} × {args.workers}, ballcollide {ballcollide.__version__}, "
        f"dask {dask.__version__}, {platform.processor() or platform.machine()}, "
        f"{os.cpu_count()} cores",
        flush=True,
    )
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    client = None
    if args.scheduler == "distributed":
        from distributed import Client, LocalCluster

        cluster = LocalCluster(
            n_workers=args.workers, threads_per_worker=1, processes=True, dashboard_address=None
        )
        client = Client(cluster)
        compute_kwargs: dict[str, Any] = {}
    else:
        compute_kwargs = {"scheduler": args.scheduler, "num_workers": args.workers}

    cpu_start, start = cpu_seconds(), time.perf_counter()
    values = dask.compute(*results.values(), **compute_kwargs)
    wall = time.perf_counter() - start
    cpu = cpu_seconds() - cpu_start  # of worker processes: only counted once they exit
    own, children = peak_rss_mib()
    if client is not None:
        worker_peaks = client.run(lambda: peak_rss_mib()[0])
        children = max(worker_peaks.values())
        client.close()
        cluster.close()

    for name, value in zip(results, values):
        print(f"  {name}: {value:,}" if value.dtype.kind == "i" else f"  {name}: {value:.9g}")
    print(f"  collision rate: {values[0] / pairs:.4%}")
    report = [f"wall {wall:.1f} s, {pairs / wall:,.0f} pairs/s (generating the inputs included)"]
    if args.scheduler == "threads":  # worker processes' CPU time is not seen from here
        report.append(f"CPU {cpu:.1f} s, {pairs / cpu:,.0f} pairs per CPU-second")
    report.append(f"peak RSS {own:,.0f} MiB (this process)")
    if args.scheduler != "threads":
        report[-1] += f", {children:,.0f} MiB (largest worker)"
    report.append(f"the inputs would take {pairs * 72 / 2**30:,.1f} GiB in memory")
    report.append(f"load average before the run {load:.2f}")
    report.append(f"{datetime.now(timezone.utc):%Y-%m-%d %H:%M} UTC")
    print("; ".join(report))

    if args.check:
        for k in sorted({0, t.numblocks[0] - 1}):
            block = {
                name: x.blocks[k].compute() if isinstance(x, da.Array) else x
                for name, x in inputs.items()
            }
            expected = ballcollide.collision_times(**block)
            got = t.blocks[k].compute()
            same = np.array_equal(expected.view(np.int64), got.view(np.int64))
            print(f"check chunk {k}: {'bitwise identical' if same else 'DIFFERENT'}")
            if not same:
                return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
