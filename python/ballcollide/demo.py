"""``python -m ballcollide demo``: collision times for a realistic batch of pool-ball pairs.

The batch: pairs of balls on a 2.54 m × 1.27 m table (a 9-ft pool table's playing area), ball
radius 0.028575 m (so two balls touch at 0.05715 m between centres), rolling friction about
0.1 m/s² (each ball 0.09 to 0.11), ball A rolling at up to 3 m/s in any direction, ball B at
rest in half the pairs and rolling in the others. Each pair's horizon ``t_max`` is the time
at which the first of its two balls reaches a cushion (found with :func:`real_roots`), as an
event-driven simulator would ask it: a collision after that is not one the table would see.

It prints how many pairs collide and how fast :func:`collision_times` ran; with ``--plot``
it draws a few colliding pairs (needs matplotlib: ``pip install 'ballcollide[plot]'``).
"""

from __future__ import annotations

import argparse
import os
import time
from typing import Any

import numpy as np

from . import __version__, collision_times, positions_at, real_roots

TABLE = (2.54, 1.27)  # playing area, m
BALL_RADIUS = 0.028575  # m (2 1/4 in diameter)
CONTACT = 2 * BALL_RADIUS  # centre distance at contact, m
FRICTION = (0.09, 0.11)  # rolling friction deceleration, m/s²
MAX_SPEED = 3.0  # m/s

Batch = dict[str, Any]


def _speeds_and_directions(rng: np.random.Generator, n: int, max_speed: float) -> np.ndarray:
    speed = rng.uniform(0.0, max_speed, n)
    angle = rng.uniform(0.0, 2 * np.pi, n)
    return np.column_stack([speed * np.cos(angle), speed * np.sin(angle)])


def _place(rng: np.random.Generator, n: int) -> np.ndarray:
    """Ball centres uniform on the table, a ball radius inside the cushions."""
    low = np.array([BALL_RADIUS, BALL_RADIUS])
    high = np.array(TABLE) - BALL_RADIUS
    return rng.uniform(low, high, (n, 2))


def cushion_times(pos: np.ndarray, vel: np.ndarray, friction: np.ndarray) -> np.ndarray:
    """When each ball's centre first comes within a ball radius of a cushion (``inf``: never).

    Along each axis the ball follows ``x(t) = p + v·t − ½·μ·(v/|v|)·t²`` until it stops at
    ``τ = |v|/μ``; the crossing of the cushion line is the smaller root of that quadratic, if
    it comes before ``τ``. All 2N quadratics are solved in one :func:`real_roots` call.
    """
    speed = np.hypot(vel[:, 0], vel[:, 1])
    moving = speed > 0
    stop = np.where(moving, speed / np.where(friction > 0, friction, 1.0), 0.0)
    stop = np.where(moving & (friction == 0), np.inf, stop)
    times = np.full(len(pos), np.inf)
    for axis, length in enumerate(TABLE):
        v = vel[:, axis]
        bound = np.where(v > 0, length - BALL_RADIUS, BALL_RADIUS)
        unit = np.divide(v, speed, out=np.zeros_like(v), where=moving)
        coeffs = np.column_stack([-0.5 * friction * unit, v, pos[:, axis] - bound])
        first = real_roots(coeffs)[:, 0]  # ascending: the entry root; NaN if none
        hit = np.isfinite(first) & (first >= 0) & (first <= stop)
        times = np.minimum(times, np.where(hit, first, np.inf))
    return times


def make_batch(n: int, seed: int) -> Batch:
    """``n`` pairs of balls (see the module docstring), reproducible from ``seed``."""
    rng = np.random.default_rng(seed)
    pos_a = _place(rng, n)
    pos_b = _place(rng, n)
    # Two balls cannot overlap on a table: draw B again where it would.
    while True:
        overlap = np.hypot(*(pos_a - pos_b).T) <= CONTACT
        if not overlap.any():
            break
        pos_b[overlap] = _place(rng, int(overlap.sum()))
    vel_a = _speeds_and_directions(rng, n, MAX_SPEED)
    vel_b = _speeds_and_directions(rng, n, MAX_SPEED)
    vel_b[rng.random(n) < 0.5] = 0.0
    friction_a = rng.uniform(*FRICTION, n)
    friction_b = rng.uniform(*FRICTION, n)
    t_max = np.minimum(
        cushion_times(pos_a, vel_a, friction_a), cushion_times(pos_b, vel_b, friction_b)
    )
    return {
        "pos_a": pos_a,
        "vel_a": vel_a,
        "friction_a": friction_a,
        "pos_b": pos_b,
        "vel_b": vel_b,
        "friction_b": friction_b,
        "contact_distance": CONTACT,
        "t_max": t_max,
    }


def run(pairs: int, seed: int, threads: int | None, repeat: int, plot: str | None) -> int:
    if plot is not None:
        try:
            import matplotlib  # noqa: F401
        except ImportError:
            print(
                "error: --plot needs matplotlib, which is not installed; install it with "
                "pip install matplotlib (or pip install 'ballcollide[plot]')"
            )
            return 2
    batch = make_batch(pairs, seed)
    best = np.inf
    times = np.empty(0)
    for _ in range(repeat):
        start = time.perf_counter()
        times = collision_times(**batch, num_threads=threads)
        best = min(best, time.perf_counter() - start)
    hits = np.isfinite(times)
    n_hits = int(hits.sum())
    where = "all cores" if threads is None else f"at most {threads} thread(s)"
    print(
        f"ballcollide {__version__} demo: {pairs:,} pairs of pool balls on a "
        f"{TABLE[0]} m × {TABLE[1]} m table (seed {seed})"
    )
    print(
        f"  contact distance {CONTACT:.5f} m, rolling friction {FRICTION[0]}–{FRICTION[1]} m/s², "
        f"speeds ≤ {MAX_SPEED} m/s, B at rest in half the pairs;"
    )
    print("  horizon of each pair: the first cushion either ball reaches")
    if n_hits:
        print(
            f"hits: {n_hits:,} of {pairs:,} pairs ({100 * n_hits / max(pairs, 1):.2f} %), "
            f"first at {times[hits].min():.3g} s, median {np.median(times[hits]):.3g} s"
        )
    else:
        print(f"hits: 0 of {pairs:,} pairs")
    rate = pairs / best if best > 0 else np.inf
    print(
        f"collision_times: {best * 1e3:.2f} ms on {where} (os.cpu_count() = {os.cpu_count()}), "
        f"best of {repeat} → {rate / 1e6:.2f} M pairs/s, "
        f"{1e9 * best / max(pairs, 1):.0f} ns/pair"
    )
    if plot is not None:
        drawn = draw(batch, times, seed, plot)
        print(f"plot: {drawn} colliding pair(s) drawn to {plot}")
    return 0


def _on_table(points: np.ndarray) -> np.ndarray:
    inside: np.ndarray = np.all((points >= 0) & (points <= np.array(TABLE)), axis=1)
    return inside


def _pick(batch: Batch, times: np.ndarray, rng: np.random.Generator, count: int) -> np.ndarray:
    """Up to ``count`` colliding pairs to draw: preferably contacts after 0.3 s of balls
    that would have come to rest on the table, so that the stop points show."""
    hits = np.isfinite(times) & (times > 0.3)
    stays = np.ones_like(hits)
    for ball in "ab":
        pos, vel, friction = (batch[f"{k}_{ball}"] for k in ("pos", "vel", "friction"))
        stop = np.hypot(vel[:, 0], vel[:, 1]) / friction
        stays &= _on_table(positions_at(pos, vel, friction, stop))
    preferred = np.flatnonzero(hits & stays)
    others = np.flatnonzero(hits & ~stays)
    chosen = rng.permutation(preferred)[:count]
    if len(chosen) < count:
        chosen = np.concatenate([chosen, rng.permutation(others)[: count - len(chosen)]])
    return np.sort(chosen)


def draw(batch: Batch, times: np.ndarray, seed: int, path: str, count: int = 4) -> int:
    """Draws up to ``count`` colliding pairs: paths to the contact, the contact, and where
    each ball would have stopped had they not collided. Returns how many were drawn."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle, Rectangle

    chosen = _pick(batch, times, np.random.default_rng(seed), count)
    fig, axes = plt.subplots(2, 2, figsize=(11, 7), squeeze=False)
    for ax in axes.flat:
        ax.set_axis_off()
    for ax, i in zip(axes.flat, chosen):
        t_hit = times[i]
        ax.set_axis_on()
        felt = Rectangle((0, 0), *TABLE, facecolor="#2e7d4f", alpha=0.25, edgecolor="k")
        ax.add_patch(felt)
        contact = []
        for ball, color in (("a", "tab:blue"), ("b", "tab:red")):
            pos = batch[f"pos_{ball}"][i]
            vel = batch[f"vel_{ball}"][i]
            friction = float(batch[f"friction_{ball}"][i])
            speed = float(np.hypot(*vel))
            stop = speed / friction if speed > 0 else 0.0
            before = np.linspace(0.0, t_hit, 200)
            after = np.linspace(t_hit, max(stop, t_hit), 200)
            rows = np.repeat(pos[None], 200, axis=0), np.repeat(vel[None], 200, axis=0)
            path_before = positions_at(*rows, friction, before)
            path_after = positions_at(*rows, friction, after)
            at_contact = path_before[-1]
            contact.append(at_contact)
            rest = path_after[-1]  # at its stop time: where it comes to rest
            label = f"ball {ball.upper()}"
            ax.plot(*path_before.T, color=color, lw=1.8, label=f"{label} to contact")
            (ghost,) = ax.plot(*path_after.T, color=color, lw=1, ls="--", alpha=0.6)
            ghost.set_clip_path(felt)
            ax.plot(*pos, "o", color=color, ms=4)
            ax.add_patch(Circle(tuple(at_contact), BALL_RADIUS, color=color, alpha=0.5))
            ax.plot(*rest, "x", color=color, ms=7, mew=2, label=f"{label} stop (no collision)")
        ax.plot(*((contact[0] + contact[1]) / 2), "*", color="k", ms=10, label="contact point")
        ax.set_xlim(-0.05, TABLE[0] + 0.05)
        ax.set_ylim(-0.05, TABLE[1] + 0.05)
        ax.set_aspect("equal")
        ax.set_title(f"pair {i}: contact at t = {t_hit:.3f} s", fontsize=10)
    handles, labels = axes.flat[0].get_legend_handles_labels()
    if handles:
        fig.legend(handles, labels, loc="lower center", ncol=5, fontsize=8, frameon=False)
    fig.suptitle(
        "ballcollide demo: colliding pairs (solid: path to contact; dashed: the path had they "
        "not collided; ×: where each would stop)",
        fontsize=10,
    )
    fig.tight_layout(rect=(0, 0.05, 1, 0.96), h_pad=2.5)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return len(chosen)


def _positive(text: str) -> int:
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be ≥ 1, got {value}")
    return value


def add_parser(subparsers: Any) -> None:
    """The ``demo`` subcommand of ``python -m ballcollide``."""
    parser = subparsers.add_parser(
        "demo",
        help="time collision_times on a realistic batch of pool-ball pairs",
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--pairs", type=_positive, default=1_000_000, help="pairs (default 1e6)")
    parser.add_argument("--seed", type=int, default=1, help="random seed (default 1)")
    parser.add_argument(
        "--threads", type=_positive, default=None, help="at most this many threads (default: all)"
    )
    parser.add_argument("--repeat", type=_positive, default=3, help="timed runs, best kept (3)")
    parser.add_argument("--plot", metavar="FILE.png", help="draw a few colliding pairs")
    parser.set_defaults(
        func=lambda args: run(args.pairs, args.seed, args.threads, args.repeat, args.plot)
    )
