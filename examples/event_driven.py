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
``--plot docs/break.png`` draws the trajectories (needs matplotlib). ``--table`` plays it on a
pool table (:func:`ballcollide.pool_table`: rails, jaws with round tips, six pockets) instead
of in a plain box: balls rebound off the cushions and fall into the pockets, and the checks
cover the table's objects too (``--plot docs/table_break.png``).
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

    sim: bc.Simulation
    paths: list[list[np.ndarray]]
    stats: Stats
    table: dict[str, np.ndarray] | None = None


def energy(vel: np.ndarray) -> float:
    return 0.5 * float(np.sum(vel**2))  # unit masses


def table_overlap(pos: np.ndarray, table: dict[str, np.ndarray]) -> float:
    """The deepest overlap of balls at ``pos`` with the table's segments (where the centre's
    foot lies on one, from a side that counts) and circles, in m."""
    worst = -math.inf
    p, q = table["segments"][:, 0], table["segments"][:, 1]
    e = q - p
    for x in pos:
        w = x - p
        u = np.einsum("ij,ij->i", w, e) / np.einsum("ij,ij->i", e, e)
        d = (e[:, 0] * w[:, 1] - e[:, 1] * w[:, 0]) / np.hypot(*e.T)
        counts = (table["segment_sides"] == 0) | (np.sign(d) == table["segment_sides"])
        on = (u >= 0) & (u <= 1) & counts
        if on.any():
            worst = max(worst, float((BALL_RADIUS - np.abs(d[on])).max()))
        c = table["circles"]
        worst = max(worst, float((BALL_RADIUS + c[:, 2] - np.hypot(*(x - c[:, :2]).T)).max()))
    return worst


def check(
    pos: np.ndarray,
    stats: Stats,
    size: tuple[float, float] = TABLE,
    table: dict[str, np.ndarray] | None = None,
    in_play: np.ndarray | None = None,
) -> None:
    """No overlap beyond the tolerance (between balls in play, and with the table's
    objects), every ball in play inside the box."""
    if in_play is not None:
        pos = pos[in_play]
    n = len(pos)
    if n > 1:
        i, j = np.triu_indices(n, k=1)
        distance = np.hypot(*(pos[i] - pos[j]).T)
        overlap = float((2 * BALL_RADIUS - distance).max())
        stats.max_overlap = max(stats.max_overlap, overlap)
        assert overlap <= OVERLAP_TOLERANCE, f"balls overlap by {overlap:.3g} m"
    if table is not None:
        overlap = table_overlap(pos, table)
        stats.max_overlap = max(stats.max_overlap, overlap)
        assert overlap <= OVERLAP_TOLERANCE, f"a ball overlaps the table by {overlap:.3g} m"
        return
    lo = BALL_RADIUS - OVERLAP_TOLERANCE
    hi = np.array(size) - BALL_RADIUS + OVERLAP_TOLERANCE
    assert ((pos >= lo) & (pos <= hi)).all(), "a ball left the box"


def simulate(
    pos: np.ndarray,
    vel: np.ndarray,
    friction: float,
    max_events: int | None = None,
    size: tuple[float, float] = TABLE,
    table: dict[str, np.ndarray] | None = None,
) -> Run:
    """``bc.simulate`` on the balls (on ``table``'s objects if given, in a box 0.3 m beyond
    the playing area ``size``; else in that box), and its replay event by event (paths and
    invariants)."""
    margin = 0.3 if table is not None else 0.0
    box = ((-margin, -margin), (size[0] + margin, size[1] + margin))
    options: dict[str, object] = {"box": box}
    if table is not None:
        # Balls a little lively, cushions less so.
        options.update(restitution=0.95, table_restitution=0.8, **table)

    def run(max_events: int | None) -> bc.Simulation:
        return bc.simulate(pos, vel, friction, BALL_RADIUS, max_events=max_events, **options)

    sim = run(max_events)
    stats = Stats(energies=[energy(np.asarray(vel, dtype=np.float64))])
    paths = [[np.array(p, dtype=np.float64)] for p in pos]
    check(np.asarray(pos, dtype=np.float64), stats, size, table)
    for k in range(1, len(sim.times) + 1):
        state = run(k)
        in_play = state.captured < 0
        check(state.pos, stats, size, table, in_play)
        e = energy(state.vel)
        assert e <= stats.energies[-1] * (1 + ENERGY_TOLERANCE), "kinetic energy grew"
        stats.energies.append(e)
        for path, point in zip(paths, state.pos):
            if np.any(path[-1] != point):
                path.append(point.copy())
    for path, point in zip(paths, sim.pos):
        if np.any(path[-1] != point):
            path.append(point.copy())
    check(sim.pos, stats, size, table, sim.captured < 0)
    stats.energies.append(energy(sim.vel))
    stats.ball_events = int((sim.kind == bc.BALL).sum())
    stats.wall_events = int((sim.kind != bc.BALL).sum())
    stats.time = float(sim.times[-1]) if len(sim.times) else 0.0  # the last event
    return Run(sim, paths, stats, table)


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
    # On a table the run's x is the short side: drawn turned, the long side across.
    turn = (lambda xy: np.asarray(xy)[..., ::-1]) if run.table else (lambda xy: np.asarray(xy))
    if run.table:
        ax.add_patch(Rectangle((-0.12, -0.12), width + 0.24, height + 0.24, color="#5a3a1a"))
        ax.add_patch(Rectangle((0, 0), width, height, facecolor="#1f6f3f"))
        for cx, cy, rho in run.table["targets"]:
            ax.add_patch(Circle(tuple(turn((cx, cy))), rho, color="black"))
        for p, q in run.table["segments"]:
            ax.plot(*turn(np.array([p, q])).T, color="#c8a060", lw=1.2)
        for cx, cy, rho in run.table["circles"]:
            ax.add_patch(Circle(tuple(turn((cx, cy))), rho, fill=False, ec="#c8a060", lw=0.8))
    else:
        ax.add_patch(
            Rectangle((0, 0), width, height, facecolor="#1f6f3f", edgecolor="#5a3a1a", lw=6)
        )
    colors = plt.get_cmap("tab20")(np.linspace(0, 1, 16))
    for b, (points, color) in enumerate(zip(run.paths, colors)):
        xy = turn(np.array(points))
        cue = b == len(run.paths) - 1
        c = "white" if cue else color
        ax.plot(xy[:, 0], xy[:, 1], color=c, lw=1.6 if cue else 1.0, alpha=0.9)
        ax.add_patch(Circle(tuple(xy[0]), BALL_RADIUS, fill=False, ec=c, lw=0.8, ls=":"))
        captured = run.sim.captured[b] >= 0
        alpha = 0.45 if captured else 1.0
        ax.add_patch(Circle(tuple(xy[-1]), BALL_RADIUS, color=c, ec="black", lw=0.5, alpha=alpha))
    s = run.stats
    if run.table:
        pocketed = int((run.sim.captured >= 0).sum())
        cushions = int(((run.sim.kind != bc.BALL) & (run.sim.kind != bc.TARGET)).sum())
        title = (
            f"16-ball break on a pool table, bc.simulate: {s.ball_events} ball collisions, "
            f"{cushions} cushion and jaw contacts, {pocketed} pocketed in {s.time:.2f} s"
        )
    else:
        title = (
            f"16-ball break, bc.simulate: {s.ball_events} ball and "
            f"{s.wall_events} wall collisions in {s.time:.2f} s"
        )
    ax.set_title(title, fontsize=9)
    pad = 0.15 if run.table else 0.05
    ax.set_xlim(-pad, width + pad)
    ax.set_ylim(-pad, height + pad)
    ax.set_aspect("equal")
    legend = "dotted: start, filled: rest (faded: in a pocket), white: cue ball"
    ax.set_xlabel(("y (m)   " if run.table else "x (m)   ") + legend, fontsize=8)
    ax.tick_params(labelsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def break_run(
    friction: float = 0.6,
    speed: float = 6.0,
    max_events: int | None = None,
    table: bool = False,
) -> Run:
    pos, vel = rack_and_cue(speed=speed)
    if not table:
        return simulate(pos, vel, friction, max_events=max_events)
    # bc.pool_table's playing area is [0, 1.27] × [0, 2.54]: the rack turned onto it.
    width, height = TABLE
    objects = bc.pool_table(width=height, length=width)
    return simulate(
        pos[:, ::-1].copy(), vel[:, ::-1].copy(), friction, max_events, (height, width), objects
    )


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--events", type=int, default=None, help="stop after this many")
    parser.add_argument("--speed", type=float, default=6.0, help="cue ball speed, m/s")
    parser.add_argument("--friction", type=float, default=0.6, help="deceleration, m/s²")
    parser.add_argument("--plot", metavar="PNG", help="draw the trajectories to this file")
    parser.add_argument("--table", action="store_true", help="on a pool table with pockets")
    args = parser.parse_args(argv)
    run = break_run(
        friction=args.friction, speed=args.speed, max_events=args.events, table=args.table
    )
    stats = run.stats
    pocketed = int((run.sim.captured >= 0).sum())
    print(
        f"{stats.ball_events} ball-ball and {stats.wall_events} wall or table contacts "
        f"({pocketed} pocketed) in "
        f"{stats.time:.3f} s of play (to the last event); kinetic energy {stats.energies[0]:.3f} → "
        f"{stats.energies[-1]:.3g} J/kg, never increasing; deepest overlap "
        f"{max(stats.max_overlap, 0.0):.2g} m (≤ {OVERLAP_TOLERANCE:g})"
    )
    if args.plot:
        plot(run, args.plot)
        print(f"trajectories: {args.plot}")


if __name__ == "__main__":
    main()
