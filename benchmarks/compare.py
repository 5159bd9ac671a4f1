"""ballcollide side by side with what users run today, on the same pairs, in the same run.

Methods (each skipped, with a message, when its package is missing):

- ``ballcollide``: ``collision_times`` on 1 thread and on all threads (full semantics: every
  time window, stop times, entry direction).
- ``numpy.roots loop``: per pair, the gap quartic (docs/contract.md) on each time window (both
  balls moving, then only the slower-stopping one), ``numpy.roots``, real roots (``|Im z| ≤ 1e-8
  max(1, |z|)``) inside the window, first root where ``g′ < 0`` (entry), and the ``t = 0``
  rule (touching and approaching). It covers every window, so it answers the same question as
  ballcollide; a double root (grazing contact) is decided by the sign of ``g′`` in rounding.
- ``numpy eigvals batched``: the companion matrices of all first-window quartics as one
  ``(N, 4, 4)`` stack through ``np.linalg.eigvals``, then the same filter, vectorised. It
  covers the **first window only** (until the first ball stops) and degree 4 (rows with
  ``a = 0`` go through the loop solver above).
- ``pooltool solve_many``: pooltool-billiards 0.6's batch quartic solver (a numba port of
  Algorithm 1010, ``pooltool.ptmath.roots.quartic.solve_many``) on the same coefficients, and
  its own root choice ``get_real_positive_smallest_roots`` (smallest real root ``≥ 0``; no
  stop time, no direction: its event loop re-solves after every motion change). Its answers
  are compared on the first window: a root after the first stop counts as "no contact".
- ``pooltool per-pair``: ``pooltool.evolution.event_based.solve.ball_ball_collision_time``
  (what its simulator calls, one pair at a time) in a Python loop, compared the same way.

Loop-based peers run on the first ``--loop-pairs`` pairs and batched peers on the first
``--batch-pairs`` pairs of the same set; ns/pair is each method's median over repeats divided
by the pairs it ran, and ratios are taken against ballcollide on 1 thread in the same run.
Hit/miss disagreements are counted against ballcollide on the pairs the peer ran; a
disagreement is "clear" when ballcollide's own hit/miss does not change with the radius scaled
by 1 ± 1e-6 (not a grazing contact). A few disagreements are settled by evaluating the motion
in mpmath (50 digits, from the exact binary inputs) at the disputed times.

``--paths`` adds the pool-path set (issue 17): ``--path-pairs`` pairs of pool balls on 3-segment
paths (sliding → rolling → rest, pooltool's motion model), ballcollide's path batch through the
Rust example ``examples/path_timing.rs`` (the Python bindings for paths come later) against
pooltool 0.6's own batch work on the first segment alone — its quartic coefficients
(``ball_ball_collision_coeffs`` in a numba loop, and the same quartics vectorised in numpy),
``solve_many`` and its root picker — alternating for ``--path-rounds`` rounds in one run.

``--overhead`` measures ``collision_times`` from Python on 10⁶ pairs against the Rust kernel
(``examples/kernel_timing.rs``) on the very same data, both on 1 thread.
"""

from __future__ import annotations

import argparse
import dataclasses
import functools
import importlib
import os
import shlex
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import machine
import numpy as np

import ballcollide as bc
from ballcollide import _core

RADIUS = 2 * 0.028575  # contact distance: two pool balls of radius 28.575 mm
TABLE = (2.54, 1.27)  # playing area of a 9-ft table, m
IMAG_TOL = 1e-8  # numpy peers: a root is real when |Im z| ≤ IMAG_TOL · max(1, |z|)
CONTACT_TOL = 1e-7  # mpmath check: |distance − radius| ≤ 0.1 µm counts as touching
ROOT = Path(__file__).resolve().parent.parent
SETS = ("random", "grazing", "at_rest", "parallel")


@dataclasses.dataclass
class Pairs:
    """A batch of ball pairs in ballcollide's layout (radius shared by all pairs)."""

    pos_a: np.ndarray
    vel_a: np.ndarray
    mu_a: np.ndarray
    pos_b: np.ndarray
    vel_b: np.ndarray
    mu_b: np.ndarray
    radius: float = RADIUS

    def __len__(self) -> int:
        return len(self.mu_a)

    def head(self, n: int) -> Pairs:
        """The first ``n`` pairs (views, no copy)."""
        return Pairs(
            self.pos_a[:n],
            self.vel_a[:n],
            self.mu_a[:n],
            self.pos_b[:n],
            self.vel_b[:n],
            self.mu_b[:n],
            self.radius,
        )

    def with_radius(self, radius: float) -> Pairs:
        """The same pairs with another contact distance."""
        return dataclasses.replace(self, radius=radius)


# ---------------------------------------------------------------------------------------------
# Data sets (the same recipes as benches/collision.rs, drawn with numpy)


def _polar(speed: np.ndarray, angle: np.ndarray) -> np.ndarray:
    return np.stack([speed * np.cos(angle), speed * np.sin(angle)], axis=1)


def _on_table(rng: np.random.Generator, n: int) -> np.ndarray:
    return np.stack([rng.uniform(0, TABLE[0], n), rng.uniform(0, TABLE[1], n)], axis=1)


def random_table(rng: np.random.Generator, n: int) -> Pairs:
    """Both balls anywhere on the table, speeds 0–3 m/s, friction 0.05–2 m/s²."""
    pa, pb = _on_table(rng, n), _on_table(rng, n)
    va = _polar(rng.uniform(0, 3, n), rng.uniform(0, 2 * np.pi, n))
    vb = _polar(rng.uniform(0, 3, n), rng.uniform(0, 2 * np.pi, n))
    return Pairs(pa, va, rng.uniform(0.05, 2, n), pb, vb, rng.uniform(0.05, 2, n))


def aimed(rng: np.random.Generator, n: int, grazing: bool) -> Pairs:
    """A (friction 0.05–2) shot at B at rest, fast enough to reach it before stopping.

    ``grazing``: the straight line passes B's centre at ``radius · (1 ± δ)``, δ log-uniform in
    1e-12 … 1e-2; otherwise at a uniform offset in ±1.5 radius (cue ball to object ball).
    """
    pa, pb = _on_table(rng, n), _on_table(rng, n)
    d = pb - pa
    dist = np.maximum(np.hypot(d[:, 0], d[:, 1]), 2 * RADIUS)
    if grazing:
        delta = 10.0 ** rng.uniform(-12, -2, n)
        offset = RADIUS * (1 + np.where(rng.uniform(0, 1, n) < 0.5, delta, -delta))
    else:
        offset = rng.uniform(-1.5, 1.5, n) * RADIUS
    angle = np.arctan2(d[:, 1], d[:, 0]) + np.arcsin(np.clip(offset / dist, -1, 1))
    mu = rng.uniform(0.05, 2, n)
    speed = np.sqrt(2 * mu * dist) * rng.uniform(1.05, 2, n)
    zeros = np.zeros((n, 2))
    return Pairs(pa, _polar(speed, angle), mu, pb, zeros, np.zeros(n))


def parallel(rng: np.random.Generator, n: int) -> Pairs:
    """Equal friction vectors: both balls roll along +x with the same μ (so ``a = b = 0``).

    B is on A's line (within ±1.5 radius sideways) half of the time, so the faster ball behind
    sometimes catches the other up.
    """
    pa = _on_table(rng, n)
    pb = _on_table(rng, n)
    near = rng.uniform(0, 1, n) < 0.5
    pb[near, 1] = pa[near, 1] + rng.uniform(-1.5, 1.5, near.sum()) * RADIUS
    zeros = np.zeros(n)
    va = np.stack([rng.uniform(0, 3, n), zeros], axis=1)
    vb = np.stack([rng.uniform(0, 3, n), zeros], axis=1)
    mu = rng.uniform(0.05, 2, n)
    return Pairs(pa, va, mu, pb, vb, mu.copy())


def make_set(name: str, n: int, seed: int) -> Pairs:
    """The named data set of ``n`` pairs."""
    rng = np.random.default_rng(seed)
    if name == "random":
        return random_table(rng, n)
    if name == "parallel":
        return parallel(rng, n)
    return aimed(rng, n, grazing=name == "grazing")


# ---------------------------------------------------------------------------------------------
# ballcollide


def bc_times(p: Pairs, threads: int | None, out: np.ndarray | None = None) -> np.ndarray:
    """ballcollide's collision times (``inf`` for none), into ``out`` if given."""
    return bc.collision_times(
        p.pos_a, p.vel_a, p.mu_a, p.pos_b, p.vel_b, p.mu_b, p.radius, num_threads=threads, out=out
    )


# ---------------------------------------------------------------------------------------------
# The gap quartic, per docs/contract.md


def accelerations(vel: np.ndarray, mu: np.ndarray) -> np.ndarray:
    """Friction acceleration vectors ``−μ v/|v|`` (zero for a ball at rest)."""
    speed = np.hypot(vel[..., 0], vel[..., 1])[..., None]
    unit = np.divide(vel, speed, out=np.zeros_like(vel), where=speed > 0)
    return np.asarray(-np.asarray(mu)[..., None] * unit)


def stop_times(vel: np.ndarray, mu: np.ndarray) -> np.ndarray:
    """``τ = |v|/μ`` (0 at rest, ``inf`` without friction)."""
    speed = np.hypot(vel[..., 0], vel[..., 1])
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(speed == 0, 0.0, speed / mu)


def gap_coefficients(dp: np.ndarray, dv: np.ndarray, df: np.ndarray, radius: float) -> np.ndarray:
    """Coefficients (highest first, shape ``(…, 5)``) of ``g(t) = |Δp + Δv t + ½Δf t²|² − R²``."""

    def dot(x: np.ndarray, y: np.ndarray) -> np.ndarray:
        return np.asarray(x[..., 0] * y[..., 0] + x[..., 1] * y[..., 1])

    return np.stack(
        [
            0.25 * dot(df, df),
            dot(dv, df),
            dot(dv, dv) + dot(dp, df),
            2 * dot(dp, dv),
            dot(dp, dp) - radius * radius,
        ],
        axis=-1,
    )


def window_end(vel: np.ndarray, mu: np.ndarray) -> np.ndarray:
    """When a ball's motion changes: its stop time, ``inf`` if it never moves."""
    tau = stop_times(vel, mu)
    return np.where(tau == 0, np.inf, tau)


def first_window(p: Pairs) -> tuple[np.ndarray, np.ndarray]:
    """The first-window quartics of all pairs and the window ends.

    The first window lasts until the first *moving* ball stops (a ball at rest from the
    start changes nothing), so with one ball at rest it covers the whole motion.
    """
    fa, fb = accelerations(p.vel_a, p.mu_a), accelerations(p.vel_b, p.mu_b)
    coeffs = gap_coefficients(p.pos_a - p.pos_b, p.vel_a - p.vel_b, fa - fb, p.radius)
    tau = np.minimum(window_end(p.vel_a, p.mu_a), window_end(p.vel_b, p.mu_b))
    return coeffs, tau


def first_window_only(times: np.ndarray, p: Pairs) -> np.ndarray:
    """``times`` with contacts at or after the first stop replaced by ``inf``."""
    _, tau = first_window(p)
    return np.where(times < tau, times, np.inf)


# ---------------------------------------------------------------------------------------------
# numpy.roots in a loop (all windows)


def entry_root(c: np.ndarray, length: float, at_start: bool) -> float:
    """First + → − crossing of the polynomial ``c`` in ``[0, length)``, or ``inf``."""
    if at_start and c[4] <= 0 and c[3] < 0:  # touching or overlapping, and approaching
        return 0.0
    if not np.any(c):
        return np.inf
    z = np.roots(c)
    real = np.sort(z[np.abs(z.imag) <= IMAG_TOL * np.maximum(1, np.abs(z))].real)
    slope = np.polyder(c)
    for t in real[(real >= 0) & (real < length)]:
        if np.polyval(slope, t) < 0:
            return float(t)
    return np.inf


def state_at(p: np.ndarray, v: np.ndarray, mu: float, t: float) -> tuple[np.ndarray, np.ndarray]:
    """Position and velocity at ``t`` of a ball (stopped balls stay put, velocity 0)."""
    tau = float(stop_times(v, np.asarray(mu)))
    acc = accelerations(v, np.asarray(mu))
    s = min(t, tau)
    pos = p + v * s + 0.5 * acc * s * s
    return pos, (v + acc * s if t < tau else np.zeros(2))


def loop_pair(
    pa: np.ndarray,
    va: np.ndarray,
    mua: float,
    pb: np.ndarray,
    vb: np.ndarray,
    mub: float,
    radius: float,
) -> float:
    """One pair's collision time with numpy.roots, window by window."""
    ta, tb = float(stop_times(va, np.asarray(mua))), float(stop_times(vb, np.asarray(mub)))
    edges = sorted({0.0, min(ta, tb), max(ta, tb)})
    for start, end in zip(edges, [*edges[1:], np.inf]):
        if start == end or (start >= ta and start >= tb):
            continue
        xa, ua = state_at(pa, va, mua, start)
        xb, ub = state_at(pb, vb, mub, start)
        fa = accelerations(ua, np.asarray(mua))
        fb = accelerations(ub, np.asarray(mub))
        c = gap_coefficients(xa - xb, ua - ub, fa - fb, radius)
        t = entry_root(c, end - start, at_start=start == 0.0)
        if t < np.inf:
            return start + t
    return np.inf


def numpy_roots_loop(p: Pairs) -> np.ndarray:
    """numpy.roots in a Python loop, every window (full semantics)."""
    return np.array(
        [
            loop_pair(
                p.pos_a[i], p.vel_a[i], p.mu_a[i], p.pos_b[i], p.vel_b[i], p.mu_b[i], p.radius
            )
            for i in range(len(p))
        ]
    )


# ---------------------------------------------------------------------------------------------
# numpy batched companion eigenvalues (first window)


def first_entries(roots: np.ndarray, coeffs: np.ndarray, tau: np.ndarray) -> np.ndarray:
    """Per row: the smallest real root in ``[0, tau)`` where ``g′ < 0``, else ``inf``."""
    real = np.abs(roots.imag) <= IMAG_TOL * np.maximum(1, np.abs(roots))
    t = roots.real
    a, b, c, d = (coeffs[:, k, None] for k in range(4))
    slope = ((4 * a * t + 3 * b) * t + 2 * c) * t + d
    ok = real & (t >= 0) & (t < tau[:, None]) & (slope < 0)
    return np.asarray(np.where(ok, t, np.inf).min(axis=1))


def eigvals_batched(p: Pairs) -> np.ndarray:
    """Companion-matrix eigenvalues of all first-window quartics at once."""
    coeffs, tau = first_window(p)
    out = np.full(len(p), np.inf)
    quartic = coeffs[:, 0] > 0
    c = coeffs[quartic]
    companion = np.zeros((len(c), 4, 4))
    companion[:, 0, :] = -c[:, 1:] / c[:, :1]
    companion[:, [1, 2, 3], [0, 1, 2]] = 1.0
    out[quartic] = first_entries(np.linalg.eigvals(companion), c, tau[quartic])
    for i in np.flatnonzero(~quartic):  # a = 0: equal friction vectors, degree ≤ 2
        out[i] = entry_root(coeffs[i], tau[i], at_start=False)
    touching = (coeffs[:, 4] <= 0) & (coeffs[:, 3] < 0)
    return np.where(touching, 0.0, out)


# ---------------------------------------------------------------------------------------------
# pooltool


def load_pooltool() -> dict[str, Any] | None:
    """pooltool-billiards' solver functions, or ``None`` (with a message) when absent."""
    try:
        quartic = importlib.import_module("pooltool.ptmath.roots.quartic")
        core = importlib.import_module("pooltool.ptmath.roots.core")
        solve = importlib.import_module("pooltool.evolution.event_based.solve")
        const = importlib.import_module("pooltool.constants")
        version = importlib.import_module("importlib.metadata").version("pooltool-billiards")
    except Exception as e:  # not installed, or installed without its runtime deps
        print(f"# skipped pooltool: cannot import it ({type(e).__name__}: {e})")
        return None
    return {
        "version": version,
        "solve_many": quartic.solve_many,
        "smallest": core.get_real_positive_smallest_roots,
        "pair_time": solve.ball_ball_collision_time,
        "coeffs": solve.ball_ball_collision_coeffs,
        "sliding": const.sliding,
        "rolling": const.rolling,
        "stationary": const.stationary,
    }


def pooltool_batch(pt: dict[str, Any], p: Pairs) -> np.ndarray:
    """pooltool's batch solver and root choice on the first-window quartics."""
    coeffs, _ = first_window(p)
    return np.asarray(pt["smallest"](pt["solve_many"](coeffs)))


def rvw(pos: np.ndarray, vel: np.ndarray, radius: float) -> np.ndarray:
    """pooltool's ball state: rows position (z = radius), velocity, angular velocity."""
    out = np.zeros((len(pos), 3, 3))
    out[:, 0, :2], out[:, 0, 2], out[:, 1, :2] = pos, radius, vel
    return out


def pooltool_pairs(pt: dict[str, Any], p: Pairs) -> Callable[[], np.ndarray]:
    """A loop over pooltool's per-pair ``ball_ball_collision_time`` (rolling balls, g = 1)."""
    r = 0.5 * p.radius
    ra, rb = rvw(p.pos_a, p.vel_a, r), rvw(p.pos_b, p.vel_b, r)

    def state(v: np.ndarray) -> int:
        return int(pt["rolling"] if np.any(v != 0) else pt["stationary"])

    sa = [state(v) for v in p.vel_a]
    sb = [state(v) for v in p.vel_b]
    mua, mub = p.mu_a.tolist(), p.mu_b.tolist()
    f = pt["pair_time"]

    def run() -> np.ndarray:
        return np.array(
            [
                f(ra[i], rb[i], sa[i], sb[i], mua[i], mub[i], 1.0, 1.0, 1.0, 1.0, r)
                for i in range(len(sa))
            ]
        )

    return run


def compile_seconds(fn: Callable[[], object]) -> float:
    """Wall time of one call (numba's first call compiles or loads its cache)."""
    start = time.perf_counter()
    fn()
    return time.perf_counter() - start


# ---------------------------------------------------------------------------------------------
# Timing and comparison


def median_times(fn: Callable[[], np.ndarray], repeats: int) -> tuple[float, float, np.ndarray]:
    """Median wall and process-CPU times over ``repeats`` calls (after one warm-up call), and
    the last result. On shared cores, CPU time shows the work when wall time shows queueing:
    CPU ≈ wall on 1 thread means the process had a core to itself."""
    result = fn()
    wall, cpu = [], []
    for _ in range(max(1, repeats)):
        w, c = time.perf_counter(), time.process_time()
        result = fn()
        wall.append(time.perf_counter() - w)
        cpu.append(time.process_time() - c)
    return float(np.median(wall)), float(np.median(cpu)), result


def median_time(fn: Callable[[], np.ndarray], repeats: int) -> tuple[float, np.ndarray]:
    """Median wall time over ``repeats`` calls (after one warm-up call) and the last result."""
    wall, _, result = median_times(fn, repeats)
    return wall, result


@dataclasses.dataclass
class Row:
    """One method's measurement and its agreement with ballcollide."""

    method: str
    pairs: int
    seconds: float
    cpu_seconds: float
    hits: int
    disagree: int = 0
    clear: int = 0
    worst_dt: float = 0.0
    worst_rel: float = 0.0

    @property
    def ns(self) -> float:
        return self.seconds / self.pairs * 1e9

    @property
    def cpu_ns(self) -> float:
        return self.cpu_seconds / self.pairs * 1e9


def disagreements(
    peer: np.ndarray, ref: np.ndarray, stable: np.ndarray, apart: np.ndarray
) -> tuple[np.ndarray, np.ndarray, float, float, int]:
    """Hit/miss disagreements, those on stable pairs, the worst time differences (absolute,
    relative to the larger time) where both hit and the balls are ``apart`` at ``t = 0``,
    and the pair with the worst absolute one."""
    differ = np.isfinite(peer) != np.isfinite(ref)
    both = np.flatnonzero(np.isfinite(peer) & np.isfinite(ref) & apart)
    if both.size == 0:
        return np.flatnonzero(differ), np.flatnonzero(differ & stable), 0.0, 0.0, -1
    dt = np.abs(peer[both] - ref[both])
    rel = dt / np.maximum(np.maximum(ref[both], peer[both]), 1e-300)
    worst = int(both[np.argmax(dt)])
    return (
        np.flatnonzero(differ),
        np.flatnonzero(differ & stable),
        float(dt.max()),
        float(rel.max()),
        worst,
    )


def stable_pairs(p: Pairs, threads: int | None) -> np.ndarray:
    """Pairs whose ballcollide hit/miss survives scaling the radius by 1 ± 1e-6."""
    lo = np.isfinite(bc_times(p.with_radius(p.radius * (1 - 1e-6)), threads))
    hi = np.isfinite(bc_times(p.with_radius(p.radius * (1 + 1e-6)), threads))
    return np.asarray(lo == hi)


# ---------------------------------------------------------------------------------------------
# mpmath verdicts


def mp_gap(p: Pairs, i: int, t: float) -> tuple[float, float]:
    """Exact (50-digit) ``|d(t)| − radius`` and ``d·d′`` of pair ``i`` at time ``t``."""
    import mpmath as mp

    mp.mp.dps = 50

    def ball(pos: np.ndarray, vel: np.ndarray, mu: float) -> tuple[Any, Any]:
        px, py, vx, vy = (mp.mpf(float(x)) for x in (*pos, *vel))
        speed = mp.sqrt(vx * vx + vy * vy)
        if speed == 0:
            return (px, py), (mp.mpf(0), mp.mpf(0))
        m = mp.mpf(float(mu))
        s = min(mp.mpf(t), speed / m) if m > 0 else mp.mpf(t)
        k = 1 - m * s / speed
        x = (px + vx * s - m * vx / speed * s * s / 2, py + vy * s - m * vy / speed * s * s / 2)
        moving = m == 0 or mp.mpf(t) < speed / m
        return x, ((vx * k, vy * k) if moving else (mp.mpf(0), mp.mpf(0)))

    (xa, ya), (ua, wa) = ball(p.pos_a[i], p.vel_a[i], p.mu_a[i])
    (xb, yb), (ub, wb) = ball(p.pos_b[i], p.vel_b[i], p.mu_b[i])
    dx, dy, du, dw = xa - xb, ya - yb, ua - ub, wa - wb
    return float(mp.sqrt(dx * dx + dy * dy) - mp.mpf(p.radius)), float(dx * du + dy * dw)


def valid_contact(p: Pairs, i: int, t: float) -> bool:
    """Whether ``t`` is a real contact: touching (or overlapping at 0) and approaching."""
    gap, approach = mp_gap(p, i, t)
    touching = gap <= CONTACT_TOL if t == 0 else abs(gap) <= CONTACT_TOL
    return touching and approach < 0


def verdict(p: Pairs, i: int, t_bc: float, t_peer: float) -> str:
    """Who is right on a hit/miss disagreement, from the high-precision motion."""
    claims = {name: t for name, t in (("ballcollide", t_bc), ("peer", t_peer)) if t < np.inf}
    ok = {name: valid_contact(p, i, t) for name, t in claims.items()}
    parts, gaps = [], {}
    for name, t in claims.items():
        gap, approach = mp_gap(p, i, t)
        gaps[name] = abs(gap)
        parts.append(f"{name} t={t:.17g}: |d|-R={gap:.3e} m, d·d'={approach:.3e}")
    right = sorted((t, name) for name, t in claims.items() if ok[name])
    if len(right) == 2:  # both touch within CONTACT_TOL: the closer to |d| = R is better
        who = "both touch; closer to |d| = R: " + min(gaps, key=gaps.__getitem__)
    elif right:
        who = right[0][1]  # the only real contact: the other's miss or claim is wrong
    else:
        who = "ballcollide" if "ballcollide" not in claims else "peer"
    return f"pair {i}: " + "; ".join(parts) + f" => right: {who}"


# ---------------------------------------------------------------------------------------------
# Report


def fmt_row(r: Row, base: float, compared: bool) -> str:
    """One markdown table line: times, ratio to ballcollide on 1 thread, agreement."""
    head = f"| {r.method:<40s} | {r.pairs:>9d} | {r.ns:>10.1f} | {r.cpu_ns:>10.1f} | "
    head += f"{r.ns / base:>8.2f} | {r.hits:>7d} |"
    if not compared:
        return head + f" {'—':>8s} | {'—':>5s} | {'—':>9s} | {'—':>9s} |"
    return head + (
        f" {r.disagree:>8d} | {r.clear:>5d} | {r.worst_dt:>9.2e} | {r.worst_rel:>9.2e} |"
    )


HEADER = (
    "| method                                   |     pairs |    ns/pair | cpu ns/pair |"
    " ÷ bc-1t  |    hits | disagree | clear | worst Δt  | worst rel |\n"
    "|------------------------------------------|----------:|-----------:|-----------:|"
    "---------:|--------:|---------:|------:|----------:|----------:|"
)


@dataclasses.dataclass
class Peer:
    """A peer: a name, a subsample size, a function, and how its answers are compared."""

    name: str
    pairs: int
    run: Callable[[Pairs], Callable[[], np.ndarray]]
    first_window: bool
    repeats: int


def measure_peer(
    peer: Peer, data: Pairs, ref: np.ndarray, stable: np.ndarray, checks: int
) -> tuple[Row, list[str]]:
    """Time a peer on its subsample and compare its answers with ballcollide's."""
    sub = data.head(peer.pairs)
    seconds, cpu, out = median_times(peer.run(sub), peer.repeats)
    want = ref[: peer.pairs]
    if peer.first_window:
        want, out = first_window_only(want, sub), first_window_only(out, sub)
    apart = first_window(sub)[0][:, 4] > 0
    idx, clear, worst, worst_rel, at = disagreements(out, want, stable[: peer.pairs], apart)
    row = Row(
        peer.name,
        len(sub),
        seconds,
        cpu,
        int(np.isfinite(out).sum()),
        len(idx),
        len(clear),
        worst,
        worst_rel,
    )
    tag = {True: "", False: " [near-grazing: either answer is acceptable (SPEC)]"}
    notes = [verdict(sub, int(i), want[i], out[i]) + tag[bool(stable[i])] for i in idx[:checks]]
    if len(idx):
        overlap = int((~apart[idx]).sum())
        notes.insert(0, f"{len(idx)} hit/miss disagreements, {overlap} of them overlapping at t=0")
    if worst > 0:
        notes.append("worst time difference: " + verdict(sub, at, want[at], out[at]))
    return row, notes


def run_set(name: str, args: argparse.Namespace, pt: dict[str, Any] | None) -> None:
    """Measure every method on one data set and print the table."""
    data = make_set(name, args.pairs, args.seed)
    one, one_cpu, t1 = median_times(lambda: bc_times(data, 1), args.repeats)
    allt, all_cpu, _ = median_times(lambda: bc_times(data, None), args.repeats)
    stable = stable_pairs(data, None)
    rows = [
        Row("ballcollide, 1 thread", len(data), one, one_cpu, int(np.isfinite(t1).sum())),
        Row(
            f"ballcollide, {os.cpu_count()} threads",
            len(data),
            allt,
            all_cpu,
            int(np.isfinite(t1).sum()),
        ),
    ]
    loops = min(args.loop_pairs, len(data))
    batch = min(args.batch_pairs, len(data))
    loop_reps = max(1, min(args.repeats, 3))
    peers = [
        Peer(
            "numpy.roots loop (all windows)",
            loops,
            lambda s: lambda: numpy_roots_loop(s),
            False,
            loop_reps,
        ),
        Peer(
            "numpy eigvals batched",
            batch,
            lambda s: lambda: eigvals_batched(s),
            True,
            args.repeats,
        ),
    ]
    if pt is not None:
        peers += [
            Peer(
                f"pooltool {pt['version']} solve_many",
                batch,
                lambda s: lambda: pooltool_batch(pt, s),
                True,
                args.repeats,
            ),
            Peer(
                "pooltool ball_ball_collision_time loop",
                loops,
                lambda s: pooltool_pairs(pt, s),
                True,
                loop_reps,
            ),
        ]
    notes: list[str] = []
    for peer in peers:
        row, why = measure_peer(peer, data, t1, stable, args.checks)
        rows.append(row)
        notes += [f"  {peer.name}: {w}" for w in why]
    print(
        f"\n## set: {name} — {len(data)} pairs, seed {args.seed}, "
        f"{int(np.isfinite(t1).sum())} hits, {int((~stable).sum())} near-grazing (unstable)"
    )
    print(HEADER)
    for k, r in enumerate(rows):
        print(fmt_row(r, rows[0].ns, compared=k >= 2))
    if notes:
        print("mpmath checks of disagreements (first few per method):")
        print("\n".join(notes))


# ---------------------------------------------------------------------------------------------
# Python overhead over the Rust kernel


def write_raw(p: Pairs, path: Path) -> None:
    """The pairs in ``examples/kernel_timing.rs``'s raw little-endian format."""
    parts = [p.pos_a, p.vel_a, p.mu_a, p.pos_b, p.vel_b, p.mu_b, np.array([p.radius])]
    with path.open("wb") as f:
        f.write(np.uint64(len(p)).astype("<u8").tobytes())
        for x in parts:
            f.write(np.ascontiguousarray(x, dtype="<f8").tobytes())


def example_command(name: str, binary: str | None, tail: list[str]) -> list[str]:
    """How to run the Rust example ``name`` (its prebuilt ``binary``, else through cargo)."""
    if binary:
        return [binary, *tail]
    return ["cargo", "run", "-q", "--release", "--example", name, "--", *tail]


def run_example(cmd: list[str]) -> dict[str, str] | None:
    """Run a Rust timing example; its ``key=value`` fields, or ``None`` (with a message)."""
    print(f"$ {shlex.join(cmd)}")
    try:
        done = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, check=True)
    except (OSError, subprocess.CalledProcessError) as e:
        print(f"# skipped the Rust timing: {e}")
        return None
    print(done.stdout.strip())
    return dict(field.split("=", 1) for field in done.stdout.split())


def rust_kernel(
    args: argparse.Namespace, path: Path, threads: str, fresh: bool = False
) -> dict[str, str] | None:
    """``examples/kernel_timing.rs`` on the pairs in ``path``."""
    tail = [str(path), threads, str(args.repeats), *(["fresh"] if fresh else [])]
    return run_example(example_command("kernel_timing", args.kernel_bin, tail))


def overhead(args: argparse.Namespace) -> None:
    """``collision_times`` from Python vs the Rust kernel on the same 10⁶ pairs, 1 thread.

    First in the same call: the whole call's time against the kernel's inside it
    (``_core._last_kernel_seconds()``), writing into ``out=``. Then in separate runs, where
    like is timed against like: Python writing into one array passed as ``out=`` against the
    kernel reusing one buffer, and Python returning a new array each call against the kernel
    writing into a fresh buffer each call (a fresh array costs its page faults, whoever
    allocates it). The four alternate for ``--overhead-rounds`` rounds (each the median of
    ``--repeats`` calls), so that a change of load on shared cores hits all alike.
    """
    data = make_set("random", args.overhead_pairs, args.seed)
    print(f"\n## Python overhead: {len(data)} random pairs, 1 thread, median of {args.repeats}")
    times = bc_times(data, 1)
    finite = times[np.isfinite(times)]
    total = float(np.cumsum(finite)[-1]) if finite.size else 0.0  # in order, like the Rust sum
    print(f"python: hits={finite.size} sum={total:.17e}")
    one = data.head(1)
    fixed, _ = median_time(lambda: bc_times(one, 1), 1000)
    print(f"python: one call on 1 pair (fixed cost per call) {fixed * 1e6:.2f} µs")
    buffer = np.empty(len(data))
    # In the same call: the call's own time against the kernel's inside it, which no change
    # of load between runs can tilt.
    added, inside = [], []
    for _ in range(args.repeats):
        start = time.perf_counter()
        bc_times(data, 1, out=buffer)
        whole = time.perf_counter() - start
        kernel = _core._last_kernel_seconds()
        added.append(whole - kernel)
        inside.append(kernel)
    print(
        f"python, in the same call (out=, median of {args.repeats}): the kernel "
        f"{np.median(inside) / len(data) * 1e9:.3f} ns/pair, the binding adds "
        f"{np.median(added) * 1e6:.1f} µs a call, "
        f"{np.median(np.array(added) / np.array(inside)) * 100:+.3f} % of the kernel's time"
    )
    rounds: dict[str, list[float]] = {"py_out": [], "rust": [], "py_new": [], "rust_fresh": []}
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "pairs.bin"
        write_raw(data, path)
        for k in range(args.overhead_rounds):
            py_out, _ = median_time(lambda: bc_times(data, 1, out=buffer), args.repeats)
            rust = rust_kernel(args, path, "1")
            py_new, _ = median_time(lambda: bc_times(data, 1), args.repeats)
            fresh = rust_kernel(args, path, "1", fresh=True)
            if rust is None or fresh is None:
                return
            for key, value in [
                ("py_out", py_out / len(data) * 1e9),
                ("rust", float(rust["median_ns_per_pair"])),
                ("py_new", py_new / len(data) * 1e9),
                ("rust_fresh", float(fresh["median_ns_per_pair"])),
            ]:
                rounds[key].append(value)
            same = (
                int(rust["hits"]) == finite.size
                and float(rust["sum"]) == total
                and np.array_equal(buffer, times)
            )
            r = {key: values[-1] for key, values in rounds.items()}
            print(
                f"round {k + 1}: python out= {r['py_out']:.3f}, rust {r['rust']:.3f} ns/pair "
                f"({(r['py_out'] - r['rust']) / r['rust'] * 100:+.2f} %); python new array "
                f"{r['py_new']:.3f}, rust fresh buffer {r['rust_fresh']:.3f} ns/pair "
                f"({(r['py_new'] - r['rust_fresh']) / r['rust_fresh'] * 100:+.2f} %); "
                f"same answers: {same}"
            )
    a = {key: np.array(values) for key, values in rounds.items()}
    med = {key: float(np.median(values)) for key, values in a.items()}
    print(
        f"medians over rounds: python out= {med['py_out']:.3f}, rust {med['rust']:.3f}, python "
        f"new array {med['py_new']:.3f}, rust fresh buffer {med['rust_fresh']:.3f} ns/pair"
    )
    for label, py, rust in [
        ("out= vs reused buffer", "py_out", "rust"),
        ("new array vs fresh buffer", "py_new", "rust_fresh"),
    ]:
        print(
            f"overhead = (python − rust)/rust, {label}: "
            f"{(med[py] - med[rust]) / med[rust] * 100:+.2f} % from the medians, "
            f"{np.median((a[py] - a[rust]) / a[rust]) * 100:+.2f} % median of rounds"
        )


# ---------------------------------------------------------------------------------------------
# Pool-table paths (issue 17): ballcollide's path batch against pooltool's first-segment work

BALL_R = RADIUS / 2  # ball radius, m
U_SLIDE, U_ROLL, GRAVITY = 0.2, 0.01, 9.81  # pooltool's default cloth and gravity


@dataclasses.dataclass
class PathSide:
    """One side of a batch of paths: ``start`` ``(N, K)``; ``pos``, ``vel``, ``acc``
    ``(N, K, 2)``; unused trailing rows have ``start = inf`` (and zeros)."""

    start: np.ndarray
    pos: np.ndarray
    vel: np.ndarray
    acc: np.ndarray


@dataclasses.dataclass
class PoolPairs:
    """Pairs of pool balls: their paths, and their pooltool states at ``t = 0`` (``rvw``)."""

    a: PathSide
    b: PathSide
    rvw_a: np.ndarray
    rvw_b: np.ndarray

    def __len__(self) -> int:
        return len(self.rvw_a)

    def head(self, n: int) -> PoolPairs:
        """The first ``n`` pairs (views, no copy)."""

        def cut(s: PathSide) -> PathSide:
            return PathSide(s.start[:n], s.pos[:n], s.vel[:n], s.acc[:n])

        return PoolPairs(cut(self.a), cut(self.b), self.rvw_a[:n], self.rvw_b[:n])

    def first_window_end(self) -> np.ndarray:
        """When the first of the two balls leaves its first segment (``inf`` if neither)."""
        second = [s.start[:, 1] if s.start.shape[1] > 1 else np.inf for s in (self.a, self.b)]
        return np.asarray(np.minimum(*second))


def _norm(x: np.ndarray) -> np.ndarray:
    return np.asarray(np.hypot(x[..., 0], x[..., 1]))


def _unit(x: np.ndarray, size: np.ndarray) -> np.ndarray:
    return np.divide(x, size[:, None], out=np.zeros_like(x), where=size[:, None] > 0)


def pool_side(pos: np.ndarray, vel: np.ndarray, spin: np.ndarray) -> PathSide:
    """The paths of balls in pooltool's motion model, each segment's start in float64 from the
    one before: sliding while the contact point slips, ``u = v + ω × (−R ẑ) = (vx − R ωy,
    vy + R ωx)``, at ``−u_s g û`` for ``2|u|/(7 u_s g)``; rolling at ``−u_r g v̂`` for
    ``|v|/(u_r g)``; at rest. A ball without slip (or without speed after it) skips the
    slide (the roll); the used segments come first, then padding."""
    n = len(pos)
    slip = np.stack([vel[:, 0] - BALL_R * spin[:, 1], vel[:, 1] + BALL_R * spin[:, 0]], axis=1)
    u = _norm(slip)
    acc0 = -U_SLIDE * GRAVITY * _unit(slip, u)
    tau0 = 2 * u / (7 * U_SLIDE * GRAVITY)
    p1 = pos + vel * tau0[:, None] + 0.5 * acc0 * (tau0 * tau0)[:, None]
    v1 = vel + acc0 * tau0[:, None]
    speed = _norm(v1)
    acc1 = -U_ROLL * GRAVITY * _unit(v1, speed)
    tau1 = speed / (U_ROLL * GRAVITY)
    p2 = p1 + v1 * tau1[:, None] + 0.5 * acc1 * (tau1 * tau1)[:, None]
    zeros = np.zeros((n, 2))
    start = np.stack([np.zeros(n), tau0, tau0 + tau1], axis=1)
    rows = [np.stack(x, axis=1) for x in ((pos, p1, p2), (vel, v1, zeros), (acc0, acc1, zeros))]
    used = np.stack([u > 0, speed > 0, np.ones(n, bool)], axis=1)
    order = np.argsort(~used, axis=1, kind="stable")  # used rows first, in their order
    start = np.where(
        np.take_along_axis(used, order, 1), np.take_along_axis(start, order, 1), np.inf
    )
    pos_, vel_, acc_ = (np.take_along_axis(r, order[:, :, None], 1) for r in rows)
    return PathSide(start, pos_, vel_, acc_)


def pool_balls(rng: np.random.Generator, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Random balls as in ``tests/support/pool_balls.rs``: anywhere on the table, speed 0–3 m/s
    in a random direction, each spin component ``(ωx, ωy)`` uniform in ±(3 m/s)/R."""
    pos = _on_table(rng, n)
    vel = _polar(rng.uniform(0, 3, n), rng.uniform(0, 2 * np.pi, n))
    w = 3 / BALL_R
    return pos, vel, rng.uniform(-w, w, (n, 2))


def pool_rvw(pos: np.ndarray, vel: np.ndarray, spin: np.ndarray) -> np.ndarray:
    """pooltool's ball states: rows position (z = R), velocity, angular velocity (ωz = 0)."""
    out = rvw(pos, vel, BALL_R)
    out[:, 2, :2] = spin
    return out


def pool_pairs(n: int, seed: int) -> PoolPairs:
    """``n`` pairs of random pool balls (all sliding at ``t = 0``), as paths and states."""
    rng = np.random.default_rng(seed)
    a, b = pool_balls(rng, n), pool_balls(rng, n)
    return PoolPairs(pool_side(*a), pool_side(*b), pool_rvw(*a), pool_rvw(*b))


def write_paths(p: PoolPairs, path: Path) -> None:
    """The pairs in ``examples/path_timing.rs``'s raw little-endian format."""

    def u64(k: int) -> bytes:
        return np.uint64(k).astype("<u8").tobytes()

    with path.open("wb") as f:
        f.write(u64(len(p)))
        for side in (p.a, p.b):
            f.write(u64(side.start.shape[0]) + u64(side.start.shape[1]))
            for x in (side.start, side.pos, side.vel, side.acc):
                f.write(np.ascontiguousarray(x, dtype="<f8").tobytes())
        f.write(np.array([RADIUS], dtype="<f8").tobytes())


def rust_paths(
    args: argparse.Namespace, path: Path, threads: str, out: Path | None = None
) -> dict[str, str] | None:
    """``examples/path_timing.rs`` on the pairs in ``path`` (times written to ``out``)."""
    tail = [str(path), threads, str(args.repeats), *([str(out)] if out else [])]
    return run_example(example_command("path_timing", args.path_bin, tail))


def pooltool_coefficients(pt: dict[str, Any]) -> Callable[..., np.ndarray]:
    """pooltool's own per-pair quartic coefficients (``ball_ball_collision_coeffs``, numba) for
    a whole batch, called from a numba loop so that no Python call is paid per pair."""
    numba = importlib.import_module("numba")
    coeffs = pt["coeffs"]

    @numba.njit
    def batch(rvw_a, rvw_b, state, mu, g, radius):  # type: ignore[no-untyped-def]
        out = np.empty((rvw_a.shape[0], 5))
        for i in range(rvw_a.shape[0]):
            c = coeffs(rvw_a[i], rvw_b[i], state, state, mu, mu, 1.0, 1.0, g, g, radius)
            for k in range(5):
                out[i, k] = c[k]
        return out

    return lambda p: batch(p.rvw_a, p.rvw_b, pt["sliding"], U_SLIDE, GRAVITY, BALL_R)


def numpy_coefficients(p: PoolPairs) -> np.ndarray:
    """The same first-segment quartics as pooltool's, vectorised in numpy from the paths'
    first rows (``gap_coefficients``): the cheapest way to feed ``solve_many``."""
    a, b = p.a, p.b
    return gap_coefficients(
        a.pos[:, 0] - b.pos[:, 0], a.vel[:, 0] - b.vel[:, 0], a.acc[:, 0] - b.acc[:, 0], RADIUS
    )


def pooltool_first_segment(
    pt: dict[str, Any], coefficients: Callable[[PoolPairs], np.ndarray], p: PoolPairs
) -> tuple[np.ndarray, list[float]]:
    """pooltool's batch work on the pairs' first segments (both balls sliding): the
    coefficients, ``solve_many``, its root picker (smallest real root ≥ 0); the times, and
    the wall seconds of each of the three steps and the thread's CPU seconds of all three."""
    cpu, t0 = time.thread_time(), time.perf_counter()
    c = coefficients(p)
    t1 = time.perf_counter()
    roots = pt["solve_many"](c)
    t2 = time.perf_counter()
    times = np.asarray(pt["smallest"](roots))
    t3, cpu = time.perf_counter(), time.thread_time() - cpu
    return times, [t1 - t0, t2 - t1, t3 - t2, cpu]


def first_window_agreement(data: PoolPairs, t_bc: np.ndarray, t_pt: np.ndarray) -> str:
    """Hit/miss agreement on the first window (a root at or after it counts as none), and the
    worst time difference where both hit and the balls are apart at ``t = 0``."""
    end = data.first_window_end()
    bc_first = np.where(t_bc < end, t_bc, np.inf)
    pt_first = np.where(t_pt < end, t_pt, np.inf)
    apart = numpy_coefficients(data)[:, 4] > 0
    differ = np.isfinite(bc_first) != np.isfinite(pt_first)
    both = np.isfinite(bc_first) & np.isfinite(pt_first) & apart
    worst = float(np.abs(bc_first[both] - pt_first[both]).max()) if both.any() else 0.0
    return (
        f"first window: ballcollide {int(np.isfinite(bc_first).sum())} hits, pooltool "
        f"{int(np.isfinite(pt_first).sum())}; hit/miss disagreements {int(differ.sum())} "
        f"({int((differ & np.isfinite(pt_first)).sum())} a pooltool hit, "
        f"{int((differ & ~apart).sum())} overlapping at t = 0); worst |Δt| where both hit, "
        f"apart at t = 0: {worst:.2e} s"
    )


def path_set(args: argparse.Namespace, pt: dict[str, Any] | None) -> None:
    """ballcollide's path batch (through ``examples/path_timing.rs``) against pooltool's
    first-segment batch work, on the same pool-table pairs, alternating for
    ``--path-rounds`` rounds (each method the median of ``--repeats`` calls per round).

    pooltool's coefficients are taken two ways: its own ``ball_ball_collision_coeffs`` (from
    the balls' states) in a numba loop, and the same quartics vectorised in numpy."""
    data = pool_pairs(args.path_pairs, args.seed)
    n = len(data)
    print(
        f"\n## set: pool paths — {n} pairs of 3-segment pool-ball paths (sliding → rolling → "
        f"rest), seed {args.seed}; ns/pair = median of {args.repeats} calls per round"
    )
    peers: dict[str, Callable[[PoolPairs], np.ndarray]] = {}
    if pt is not None:
        peers["own"] = pooltool_coefficients(pt)
        peers["numpy"] = numpy_coefficients
        first = compile_seconds(lambda: pooltool_first_segment(pt, peers["own"], data.head(4)))
        print(f"# pooltool coefficient loop: first call (numba compile) {first:.1f} s, not timed")
    # Per round: wall and thread-CPU ns/pair, and for pooltool the wall ns/pair of its steps.
    rounds: dict[str, list[list[float]]] = {"bc": [], "own": [], "numpy": []}
    answers: dict[str, np.ndarray] = {}
    with tempfile.TemporaryDirectory() as tmp:
        path, out = Path(tmp) / "paths.bin", Path(tmp) / "times.bin"
        write_paths(data, path)
        every = rust_paths(args, path, "all", out)
        if every is None:
            return
        answers["bc"] = np.fromfile(out, dtype="<f8")
        for k in range(args.path_rounds):
            one = rust_paths(args, path, "1")
            if one is None:
                return
            fields = ("median_ns_per_pair", "median_thread_cpu_ns_per_pair")
            rounds["bc"].append([float(one[f]) for f in fields])
            line = f"round {k + 1}, ns/pair (cpu): ballcollide 1 thread "
            line += "{:.1f} ({:.1f})".format(*rounds["bc"][-1])
            for name, coefficients in peers.items():
                steps = []
                for _ in range(max(1, args.repeats)):
                    answers[name], seconds = pooltool_first_segment(pt, coefficients, data)
                    steps.append(seconds)
                s = np.array(steps) / n * 1e9
                wall, cpu = np.median(s[:, :3].sum(axis=1)), np.median(s[:, 3])
                rounds[name].append([float(wall), float(cpu), *np.median(s[:, :3], axis=0)])
                line += f"; pooltool ({name} coefficients) {wall:.1f} ({cpu:.1f})"
            print(line)
    bc = np.array(rounds["bc"])
    t_bc = answers["bc"]
    print(
        f"ballcollide: {int(np.isfinite(t_bc).sum())} hits ({100 * np.isfinite(t_bc).mean():.2f}"
        f" %), {int((t_bc < data.first_window_end()).sum())} in the first window (both balls "
        f"sliding), {int((t_bc == 0).sum())} at t = 0; 1 thread {np.median(bc[:, 0]):.1f} "
        f"ns/pair, thread cpu {np.median(bc[:, 1]):.1f} (medians of rounds); all threads "
        f"{float(every['median_ns_per_pair']):.1f} ns/pair"
    )
    version = pt["version"] if pt is not None else "?"
    for name in peers:
        r = np.array(rounds[name])
        med = np.median(r, axis=0)
        print(
            f"pooltool {version} first segment, {name} coefficients: {med[0]:.1f} ns/pair, "
            f"thread cpu {med[1]:.1f} (medians of rounds; wall: coefficients {med[2]:.1f}, "
            f"solve_many {med[3]:.1f}, root picker {med[4]:.1f}); pooltool ÷ ballcollide "
            f"1 thread: wall {med[0] / np.median(bc[:, 0]):.2f}, cpu "
            f"{med[1] / np.median(bc[:, 1]):.2f} from the medians; median of the rounds' "
            f"ratios: wall {np.median(r[:, 0] / bc[:, 0]):.2f}, cpu "
            f"{np.median(r[:, 1] / bc[:, 1]):.2f}"
        )
        print(f"  {first_window_agreement(data, t_bc, answers[name])}")


# ---------------------------------------------------------------------------------------------
# Plot: ns/pair against N


def scaling(
    args: argparse.Namespace, pt: dict[str, Any] | None
) -> dict[str, list[tuple[int, float]]]:
    """ns/pair against N for ballcollide and the batched peers (random set)."""
    curves: dict[str, list[tuple[int, float]]] = {}
    big = make_set("random", args.plot_max, args.seed + 1)
    methods: list[tuple[str, int, Callable[[Pairs], np.ndarray]]] = [
        ("ballcollide, 1 thread", args.plot_max, lambda s: bc_times(s, 1)),
        (f"ballcollide, {os.cpu_count()} threads", args.plot_max, lambda s: bc_times(s, None)),
        ("numpy eigvals batched", args.plot_peer_max, eigvals_batched),
    ]
    if pt is not None:
        methods.append(("pooltool solve_many", args.plot_peer_max, lambda s: pooltool_batch(pt, s)))
    for label, top, fn in methods:
        for n in (10**k for k in range(2, 9)):
            if n > top:
                break
            sub = big.head(n)
            reps = max(3, min(args.repeats, int(2e6 // n)))
            seconds, _ = median_time(functools.partial(fn, sub), reps)
            curves.setdefault(label, []).append((n, seconds / n * 1e9))
            print(f"plot: {label:<28s} N={n:>9d} {seconds / n * 1e9:>10.1f} ns/pair ({reps} reps)")
    return curves


def plot(curves: dict[str, list[tuple[int, float]]], path: str) -> None:
    """Log-log plot of the curves, saved as a small PNG."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.2), dpi=90)
    for label, pts in curves.items():
        ns, ys = zip(*pts)
        ax.loglog(ns, ys, marker="o", label=label)
    ax.set_xlabel("pairs per call (N)")
    ax.set_ylabel("ns per pair (median)")
    ax.set_title("Random table pairs: collision times, ns/pair against N", fontsize=10)
    stamp = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    ax.text(
        0.01,
        0.01,
        f"{os.cpu_count()} CPUs, load {os.getloadavg()[0]:.1f}, {stamp}",
        transform=ax.transAxes,
        fontsize=7,
        alpha=0.7,
    )
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    print(f"plot written to {path}")


# ---------------------------------------------------------------------------------------------
# Command line


def parse(argv: Sequence[str] | None) -> argparse.Namespace:
    """Command-line options."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pairs", type=int, default=1_000_000, help="pairs per set (ballcollide)")
    ap.add_argument("--loop-pairs", type=int, default=2_000, help="subsample for loop peers")
    ap.add_argument("--batch-pairs", type=int, default=200_000, help="subsample, batched peers")
    ap.add_argument("--repeats", type=int, default=7, help="timed repeats (median)")
    ap.add_argument("--seed", type=int, default=2024)
    ap.add_argument("--sets", default="random", help=f"comma list of {SETS}, 'all' or 'none'")
    ap.add_argument("--checks", type=int, default=3, help="mpmath checks per method")
    ap.add_argument("--quick", action="store_true", help="small sizes, no pooltool (smoke test)")
    ap.add_argument("--no-pooltool", action="store_true", help="skip pooltool")
    ap.add_argument("--plot", metavar="FILE.png", help="also plot ns/pair against N")
    ap.add_argument("--plot-max", type=int, default=1_000_000, help="largest N, ballcollide")
    ap.add_argument("--plot-peer-max", type=int, default=1_000_000, help="largest N, peers")
    ap.add_argument("--overhead", action="store_true", help="Python vs Rust kernel, 1 thread")
    ap.add_argument("--overhead-pairs", type=int, default=1_000_000)
    ap.add_argument("--overhead-rounds", type=int, default=5, help="Python/Rust alternations")
    ap.add_argument("--kernel-bin", help="prebuilt examples/kernel_timing binary (else cargo)")
    ap.add_argument("--paths", action="store_true", help="pool-table paths vs pooltool")
    ap.add_argument("--path-pairs", type=int, default=200_000, help="pairs of pool-ball paths")
    ap.add_argument("--path-rounds", type=int, default=3, help="ballcollide/pooltool rounds")
    ap.add_argument("--path-bin", help="prebuilt examples/path_timing binary (else cargo)")
    args = ap.parse_args(argv)
    if args.quick:
        args.pairs, args.loop_pairs, args.batch_pairs = 5_000, 300, 5_000
        args.repeats, args.no_pooltool = 3, True
    if args.sets in ("all", "none"):
        args.sets = SETS if args.sets == "all" else ()
    else:
        args.sets = tuple(args.sets.split(","))
    unknown = set(args.sets) - set(SETS)
    if unknown:
        ap.error(f"unknown sets {sorted(unknown)}; choose from {SETS}")
    return args


def setup_pooltool(args: argparse.Namespace) -> dict[str, Any] | None:
    """Import pooltool and warm its numba functions up, reporting the first-call time."""
    if args.no_pooltool:
        print("# skipped pooltool (--no-pooltool / --quick)")
        return None
    start = time.perf_counter()
    pt = load_pooltool()
    if pt is None:
        return None
    print(f"# pooltool-billiards {pt['version']}: import {time.perf_counter() - start:.1f} s")
    tiny = make_set("random", 4, 0)
    first = compile_seconds(lambda: pooltool_batch(pt, tiny))
    first += compile_seconds(lambda: pooltool_pairs(pt, tiny)())
    print(f"# pooltool first calls (numba compile or cache load, not timed below): {first:.1f} s")
    return pt


def main(argv: Sequence[str] | None = None) -> int:
    """Run the comparison."""
    args = parse(argv)
    print(
        f"# ballcollide {bc.__version__}, numpy {np.__version__}, python "
        f"{sys.version.split()[0]}, {os.cpu_count()} CPUs; ns/pair = median of "
        f"{args.repeats} repeats / pairs; '÷ bc-1t' = ns/pair ÷ ballcollide's 1-thread ns/pair"
    )
    print(f"# {machine.describe()}")
    print(
        f"# load average {os.getloadavg()[0]:.1f} at start; cpu ns/pair = process CPU time"
        " (all threads) / pairs: far below ns/pair on 1 thread = the cores were shared"
    )
    print(
        f"# loop peers on the first {args.loop_pairs} pairs, batched peers on the first "
        f"{args.batch_pairs}; numpy eigvals and pooltool are compared on the first window"
    )
    print(
        "# disagree: hit/miss differences with ballcollide (on the first window for numpy"
        " eigvals and pooltool); clear: of those, pairs whose ballcollide hit/miss is the same with"
        " the radius × (1 ± 1e-6); worst |Δt| (s) and worst relative Δt: pairs both call hits,"
        " balls apart at t = 0"
    )
    pt = setup_pooltool(args)
    for name in args.sets:
        run_set(name, args, pt)
    if args.paths:
        path_set(args, pt)
    if args.overhead:
        overhead(args)
    if args.plot:
        plot(scaling(args, pt), args.plot)
    return 0


if __name__ == "__main__":
    sys.exit(main())
