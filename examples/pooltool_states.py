"""Billiard balls from pooltool-style states as paths, and their contacts.

Each ball is given as a state: centre ``r`` on the cloth, velocity ``v`` and angular velocity
``w``. With pooltool's model and defaults (ball radius R = 0.028575 m, sliding friction
u_s = 0.2, rolling friction u_r = 0.01, g = 9.81 m/s²), its centre then follows a path of
constant-acceleration segments:

- *sliding* while the contact point slips, at ``u = v + w × (−R ẑ)`` (its velocity over the
  cloth): friction ``−u_s·g·û`` against the slip, not against the velocity, so the path
  curves when ``u`` and ``v`` point different ways (side spin, draw, follow). The slip keeps
  its direction and shrinks to zero after ``2|u| / (7·u_s·g)``;
- then *rolling*: ``−u_r·g·v̂`` for ``|v| / (u_r·g)``, in a straight line;
- then *at rest* (a ball spinning in place about ``ẑ`` is at rest too, for its centre).

The script builds these paths for a few balls (padded to three segments with ``+inf``
starts, as ``ballcollide.path_collision_times`` takes them), asks for the first contact of
every pair at once (the contact each pair would have if nothing else happened; the earliest
of them is the event a simulator handles next), and draws the curved paths with the contact
points::

    python examples/pooltool_states.py                       # writes docs/pooltool_paths.png
    python examples/pooltool_states.py --out /tmp/paths.png
    python examples/pooltool_states.py --no-plot             # the table of contacts only

Cushions are left out: the paths run as if the table had none.
"""

from __future__ import annotations

import argparse
import itertools
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

import ballcollide as bc

R = 0.028575  # ball radius (m)
U_SLIDE = 0.2  # sliding friction coefficient
U_ROLL = 0.01  # rolling friction coefficient
G = 9.81  # gravity (m/s²)
TABLE = (2.54, 1.27)  # playing surface (m)
SEGMENTS = 3  # sliding, rolling, at rest
DEFAULT_OUT = Path(__file__).resolve().parents[1] / "docs" / "pooltool_paths.png"


@dataclass(frozen=True)
class State:
    """A ball's state on the cloth: centre ``r``, velocity ``v`` (both in the plane) and
    angular velocity ``w`` (3-D)."""

    name: str
    r: tuple[float, float]
    v: tuple[float, float]
    w: tuple[float, float, float]


def slip(v: np.ndarray, w: np.ndarray) -> np.ndarray:
    """The velocity of the contact point over the cloth, ``v + w × (−R ẑ)``, in the plane."""
    return v + R * np.array([-w[1], w[0]])


def motion(state: State) -> str:
    """pooltool's name of the state: sliding, rolling, spinning or stationary."""
    v, w = np.array(state.v, float), np.array(state.w, float)
    if np.linalg.norm(slip(v, w)) > 1e-12:
        return "sliding"
    if np.linalg.norm(v) > 0:
        return "rolling"
    return "spinning" if w[2] != 0 else "stationary"


def path_of(state: State) -> tuple[np.ndarray, ...]:
    """The ball's path from time 0: ``(start (K,), pos (K, 2), vel (K, 2), acc (K, 2))``
    with ``K = SEGMENTS``, unused segments padded with ``+inf`` starts and NaN."""
    r, v, w = (np.array(x, float) for x in (state.r, state.v, state.w))
    start = np.full(SEGMENTS, np.inf)
    pos, vel, acc = (np.full((SEGMENTS, 2), np.nan) for _ in range(3))
    t, k = 0.0, 0
    u = slip(v, w)
    if np.linalg.norm(u) > 1e-12:
        a = -U_SLIDE * G * u / np.linalg.norm(u)
        duration = 2 * np.linalg.norm(u) / (7 * U_SLIDE * G)
        start[k], pos[k], vel[k], acc[k] = t, r, v, a
        r, v = r + v * duration + 0.5 * a * duration**2, v + a * duration
        t, k = t + duration, k + 1
    speed = np.linalg.norm(v)
    if speed > 0:
        a = -U_ROLL * G * v / speed
        duration = speed / (U_ROLL * G)
        start[k], pos[k], vel[k], acc[k] = t, r, v, a
        r = r + v * duration + 0.5 * a * duration**2
        t, k = t + duration, k + 1
    start[k], pos[k], vel[k], acc[k] = t, r, 0.0, 0.0
    return start, pos, vel, acc


# The cue ball struck with heavy draw and side spin (a massé-like shot: its slip points far
# from its velocity, so it hooks through a right angle while sliding), a second ball sliding
# with side spin (a gentler bend), one rolling, one spinning in place and two at rest.
STATES = [
    State("cue", (0.55, 1.00), (1.20, 0.0), (42.87, -104.99, 0.0)),
    State("1", (2.20, 0.35), (-0.80, 0.50), (0.87, 57.74, -10.0)),
    State("2", (0.786, 1.161), (0.20, -0.38), (0.38 / R, 0.20 / R, 0.0)),
    State("3", (1.97, 0.78), (0.0, 0.0), (0.0, 0.0, 25.0)),
    State("4", (0.95, 0.52), (0.0, 0.0), (0.0, 0.0, 0.0)),
    State("5", (1.45, 0.62), (0.0, 0.0), (0.0, 0.0, 0.0)),
]


def contacts(states: list[State]) -> list[tuple[float, int, int]]:
    """The first contact ``(t, i, j)`` of every pair ``i < j`` that touches, earliest first:
    one call on all the pairs."""
    paths = [path_of(s) for s in states]
    pairs = list(itertools.combinations(range(len(states)), 2))
    a = [np.stack([paths[i][f] for i, _ in pairs]) for f in range(4)]
    b = [np.stack([paths[j][f] for _, j in pairs]) for f in range(4)]
    t = bc.path_collision_times(*a, *b, 2 * R)
    return sorted((float(t[p]), i, j) for p, (i, j) in enumerate(pairs) if np.isfinite(t[p]))


def plot(states: list[State], found: list[tuple[float, int, int]], out: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle, Rectangle

    paths = [path_of(s) for s in states]
    fig, ax = plt.subplots(figsize=(11, 6))
    ax.add_patch(Rectangle((0, 0), *TABLE, facecolor="#2e7d4f", edgecolor="#5b3a1a", lw=6))
    colours = plt.get_cmap("tab10").colors
    for i, (state, path) in enumerate(zip(states, paths)):
        colour = colours[i % 10]
        start = path[0]
        used = start[np.isfinite(start)]
        for k in range(len(used) - 1):  # the moving segments, sampled finely
            t = np.linspace(used[k], used[k + 1], 200)
            x = bc.path_positions_at(*(f[None] for f in path), t)
            style = "-" if np.linalg.norm(path[3][k]) > U_ROLL * G * 1.5 else "--"
            ax.plot(*x.T, style, color=colour, lw=1.8)
        ax.add_patch(Circle(path[1][0], R, facecolor=colour, edgecolor="white", lw=1))
        rest = bc.path_positions_at(*(f[None] for f in path), used[-1])[0]
        if len(used) > 1:
            ax.add_patch(Circle(rest, R, facecolor="none", edgecolor=colour, lw=1, ls=":"))
        ax.annotate(
            f"{state.name} ({motion(state)})",
            path[1][0],
            xytext=(6, 8),
            textcoords="offset points",
            color="white",
            fontsize=8,
        )
    for n, (t, i, j) in enumerate(found):
        for ball in (i, j):
            centre = bc.path_positions_at(*(f[None] for f in paths[ball]), t)[0]
            ax.add_patch(
                Circle(
                    centre,
                    R,
                    facecolor="none",
                    edgecolor="yellow" if n == 0 else "white",
                    lw=2 if n == 0 else 1,
                )
            )
        xi = bc.path_positions_at(*(f[None] for f in paths[i]), t)[0]
        xj = bc.path_positions_at(*(f[None] for f in paths[j]), t)[0]
        point = (xi + xj) / 2
        ax.plot(*point, "x", color="yellow" if n == 0 else "white", ms=8, mew=2)
        label = f"{states[i].name}–{states[j].name} at {t:.3f} s"
        ax.annotate(
            label,
            point,
            xytext=(8, -12),
            textcoords="offset points",
            color="yellow" if n == 0 else "white",
            fontsize=8,
        )
    ax.set_xlim(-0.05, TABLE[0] + 0.05)
    ax.set_ylim(-0.05, TABLE[1] + 0.05)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(
        "Paths from pooltool-style states (solid: sliding, dashed: rolling, dotted circle: at "
        "rest),\ndrawn as if nothing collided, and each pair's first contact (yellow: the "
        "earliest, the next event), by path_collision_times",
        fontsize=10,
    )
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=110, bbox_inches="tight")
    plt.close(fig)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT, help="the picture (PNG)")
    parser.add_argument("--no-plot", action="store_true", help="print the contacts only")
    args = parser.parse_args(argv)
    found = contacts(STATES)
    for state in STATES:
        start = path_of(state)[0]
        ends = ", ".join(f"{s:.3f}" for s in start[np.isfinite(start)][1:])
        print(f"ball {state.name:>3}: {motion(state):<10} segment starts after 0: {ends or '-'}")
    for t, i, j in found:
        print(f"contact {STATES[i].name}–{STATES[j].name} at t = {t:.6f} s")
    if not args.no_plot:
        plot(STATES, found, args.out)
        print(f"picture: {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
