"""An event-driven simulation of balls in a rectangular box: ``bc.simulate``.

Balls slide in a box, slowed by a constant friction deceleration until they stop; they
bounce off each other (equal masses, elastic: momentum exchanged along the line of centres)
and off the walls (the normal component is reversed). :func:`ballcollide.simulate` runs the
whole event loop in Rust on the event calendar (:class:`ballcollide.CollisionSchedule`): the
next collision or wall contact, the balls involved resolved and given new paths, and so on
until every ball has stopped.

This script draws and checks the run: it replays the log event by event (the state after
``k`` events is ``simulate`` with ``max_events=k``) and checks that no two balls overlap by
more than 1e-9 m, that no ball leaves the box, and that the kinetic energy never grows.

``python examples/event_driven.py`` simulates a 16-ball break (a rack of 15 and the cue ball)
on a 2.54 m × 1.27 m table until every ball has stopped and prints a summary;
``--plot docs/break.png`` draws the trajectories (needs matplotlib).
"""

from __future__ import annotations

import argparse
import math
from dataclasses import dataclass, field

import numpy as np

import ballcollide as bc

TABLE = (2.54, 1.27)  # m: a 9-ft pool table's playing area
BALL_RADIUS = 0.028575  # m
OVERLAP_TOLERANCE = 1e-9  # m
ENERGY_TOLERANCE = 1e-12  # relative: rounding of an exchange of velocity components


@dataclass
class Stats:
    """What happened, and the invariants' worst values."""

    ball_events: int = 0
    wall_events: int = 0
    time: float = 0.0
    max_overlap: float = 0.0  # m, the deepest interpenetration seen (≤ 0: none)
    energies: list[float] = field(default_factory=list)  # kinetic energy after each event


@dataclass
class Run:
    """A simulation's log, its final state, each ball's path (its centre at every event)."""

    times: np.ndarray
    i: np.ndarray
    j: np.ndarray
    pos: np.ndarray
    vel: np.ndarray
    paths: list[list[np.ndarray]]
    stats: Stats


def energy(vel: np.ndarray) -> float:
    return 0.5 * float(np.sum(vel**2))  # unit masses


def check(pos: np.ndarray, stats: Stats, size: tuple[float, float] = TABLE) -> None:
    """No overlap beyond the tolerance, every ball inside the box."""
    n = len(pos)
    if n > 1:
        i, j = np.triu_indices(n, k=1)
        distance = np.hypot(*(pos[i] - pos[j]).T)
        overlap = float((2 * BALL_RADIUS - distance).max())
        stats.max_overlap = max(stats.max_overlap, overlap)
        assert overlap <= OVERLAP_TOLERANCE, f"balls overlap by {overlap:.3g} m"
    lo = BALL_RADIUS - OVERLAP_TOLERANCE
    hi = np.array(size) - BALL_RADIUS + OVERLAP_TOLERANCE
    assert ((pos >= lo) & (pos <= hi)).all(), "a ball left the box"


def simulate(
    pos: np.ndarray,
    vel: np.ndarray,
    friction: float,
    max_events: int | None = None,
    size: tuple[float, float] = TABLE,
) -> Run:
    """``bc.simulate`` on the balls, and its replay event by event (paths and invariants)."""
    box = ((0.0, 0.0), size)
    times, i, j, end_pos, end_vel = bc.simulate(
        pos, vel, friction, BALL_RADIUS, box=box, max_events=max_events
    )
    stats = Stats(energies=[energy(np.asarray(vel, dtype=np.float64))])
    paths = [[np.array(p, dtype=np.float64)] for p in pos]
    check(np.asarray(pos, dtype=np.float64), stats, size)
    for k in range(1, len(times) + 1):
        *_, p, v = bc.simulate(pos, vel, friction, BALL_RADIUS, box=box, max_events=k)
        check(p, stats, size)
        e = energy(v)
        assert e <= stats.energies[-1] * (1 + ENERGY_TOLERANCE), "kinetic energy grew"
        stats.energies.append(e)
        for path, point in zip(paths, p):
            if np.any(path[-1] != point):
                path.append(point.copy())
    for path, point in zip(paths, end_pos):
        if np.any(path[-1] != point):
            path.append(point.copy())
    check(end_pos, stats, size)
    stats.energies.append(energy(end_vel))
    stats.ball_events = int((j >= 0).sum())
    stats.wall_events = int((j < 0).sum())
    stats.time = float(times[-1]) if len(times) else 0.0  # the last event
    return Run(times, i, j, end_pos, end_vel, paths, stats)


def rack_and_cue(
    speed: float = 6.0, angle: float = 0.004, gap: float = 1e-3
) -> tuple[np.ndarray, np.ndarray]:
    """A triangle of 15 balls at rest (apex on the foot spot, ``gap`` m between neighbours)
    and the cue ball on the head spot, shot at ``speed`` m/s slightly off the axis."""
    width, height = TABLE
    d = 2 * BALL_RADIUS + gap
    pos = [
        (0.75 * width + row * d * math.sqrt(3) / 2, height / 2 + (k - row / 2) * d)
        for row in range(5)
        for k in range(row + 1)
    ]
    pos.append((0.25 * width, height / 2))
    vel = np.zeros((16, 2))
    vel[15] = (speed * math.cos(angle), speed * math.sin(angle))
    return np.array(pos), vel


def plot(run: Run, path: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle, Rectangle

    width, height = TABLE
    fig, ax = plt.subplots(figsize=(8, 4.4), dpi=100)
    ax.add_patch(Rectangle((0, 0), width, height, facecolor="#1f6f3f", edgecolor="#5a3a1a", lw=6))
    colors = plt.get_cmap("tab20")(np.linspace(0, 1, 16))
    for b, (points, color) in enumerate(zip(run.paths, colors)):
        xy = np.array(points)
        cue = b == len(run.paths) - 1
        c = "white" if cue else color
        ax.plot(xy[:, 0], xy[:, 1], color=c, lw=1.6 if cue else 1.0, alpha=0.9)
        ax.add_patch(Circle(tuple(xy[0]), BALL_RADIUS, fill=False, ec=c, lw=0.8, ls=":"))
        ax.add_patch(Circle(tuple(xy[-1]), BALL_RADIUS, color=c, ec="black", lw=0.5))
    s = run.stats
    ax.set_title(
        f"16-ball break, bc.simulate: {s.ball_events} ball and "
        f"{s.wall_events} wall collisions in {s.time:.2f} s",
        fontsize=9,
    )
    ax.set_xlim(-0.05, width + 0.05)
    ax.set_ylim(-0.05, height + 0.05)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)   dotted: start, filled: rest, white: cue ball", fontsize=8)
    ax.tick_params(labelsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def break_run(friction: float = 0.6, speed: float = 6.0, max_events: int | None = None) -> Run:
    pos, vel = rack_and_cue(speed=speed)
    return simulate(pos, vel, friction, max_events=max_events)


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--events", type=int, default=None, help="stop after this many")
    parser.add_argument("--speed", type=float, default=6.0, help="cue ball speed, m/s")
    parser.add_argument("--friction", type=float, default=0.6, help="deceleration, m/s²")
    parser.add_argument("--plot", metavar="PNG", help="draw the trajectories to this file")
    args = parser.parse_args(argv)
    run = break_run(friction=args.friction, speed=args.speed, max_events=args.events)
    stats = run.stats
    print(
        f"{stats.ball_events} ball-ball and {stats.wall_events} wall collisions in "
        f"{stats.time:.3f} s of play (to the last event); kinetic energy {stats.energies[0]:.3f} → "
        f"{stats.energies[-1]:.3g} J/kg, never increasing; deepest overlap "
        f"{max(stats.max_overlap, 0.0):.2g} m (≤ {OVERLAP_TOLERANCE:g})"
    )
    if args.plot:
        plot(run, args.plot)
        print(f"trajectories: {args.plot}")


if __name__ == "__main__":
    main()
