"""An event-driven simulation of balls in a rectangular box, driven by ballcollide.

Balls slide in a box, slowed by a constant friction deceleration until they stop; they
bounce off each other (equal masses, elastic: the normal components of the velocities are
exchanged) and off the walls (the normal component is reversed). Between two events every
ball moves on a straight line, so the simulation jumps from event to event:

- the next ball–ball contact is :func:`ballcollide.earliest_collision` on the current state;
- the next wall contact of each ball is a quadratic in time per axis (``x(t) = p + v·t −
  ½·a·t²`` meets ``x = wall``, before the ball stops), all solved in one
  :func:`ballcollide.real_roots` call;
- every ball is advanced to the earlier of the two (:func:`ballcollide.positions_at`), the
  event is resolved, and the next one is asked for.

After every event it checks that no two balls overlap by more than 1e-9 m (also at a few
times between events), that no ball leaves the box, and that the kinetic energy never grows.

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


class Simulation:
    """Balls of equal mass and radius in the box ``[0, width] × [0, height]``."""

    def __init__(
        self,
        pos: np.ndarray,
        vel: np.ndarray,
        friction: float,
        radius: float = BALL_RADIUS,
        size: tuple[float, float] = TABLE,
    ) -> None:
        self.pos = np.array(pos, dtype=np.float64)
        self.vel = np.array(vel, dtype=np.float64)
        self.friction = float(friction)
        self.radius = float(radius)
        self.size = size
        self.time = 0.0
        self.stats = Stats()
        self.paths: list[list[np.ndarray]] = [[p.copy()] for p in self.pos]
        self._check(self.pos)
        self.stats.energies.append(self.energy())

    # --- motion -----------------------------------------------------------------------------

    def stop_times(self) -> np.ndarray:
        speed = np.hypot(self.vel[:, 0], self.vel[:, 1])
        if self.friction == 0:
            return np.where(speed > 0, np.inf, 0.0)
        return speed / self.friction

    def advance(self, dt: float) -> None:
        """Moves every ball on by ``dt`` (straight lines, slowing, stopping)."""
        self.pos = bc.positions_at(self.pos, self.vel, self.friction, dt)
        speed = np.hypot(self.vel[:, 0], self.vel[:, 1])
        slower = np.maximum(speed - self.friction * dt, 0.0)
        factor = np.divide(slower, speed, out=np.zeros_like(speed), where=speed > 0)
        self.vel = self.vel * factor[:, None]
        self.time += dt

    def energy(self) -> float:
        return 0.5 * float(np.sum(self.vel**2))  # unit masses

    # --- events -----------------------------------------------------------------------------

    def next_wall(self) -> tuple[float, int, int]:
        """The first wall contact ``(dt, ball, axis)``, ``(inf, -1, -1)`` if none.

        Along each axis, ``x(s) = p + v·s − ½·a·s²`` with ``a = μ·v/|v|`` (the friction's
        component) until the stop time; the ball reaches the wall at ``lo = r`` or
        ``hi = size − r`` at a root of ``−½·a·s² + v·s + (p − wall)``. A root counts if it
        lies in ``[0, τ]`` and the ball is moving towards that wall (a ball that has just
        bounced off it sits at a root ``s = 0`` but moves away).
        """
        n = len(self.pos)
        speed = np.hypot(self.vel[:, 0], self.vel[:, 1])
        unit = np.divide(
            self.vel, speed[:, None], out=np.zeros_like(self.vel), where=speed[:, None] > 0
        )
        accel = self.friction * unit
        tau = self.stop_times()
        best = (math.inf, -1, -1)
        rows, meta = [], []
        for axis in (0, 1):
            for wall, direction in ((self.radius, -1.0), (self.size[axis] - self.radius, 1.0)):
                v = self.vel[:, axis]
                rows.append(np.column_stack([-0.5 * accel[:, axis], v, self.pos[:, axis] - wall]))
                meta.append((axis, direction))
        roots = bc.real_roots(np.concatenate(rows))  # (4N, 2), NaN-padded
        for k, (axis, direction) in enumerate(meta):
            towards = self.vel[:, axis] * direction > 0
            r = roots[k * n : (k + 1) * n]
            ok = towards[:, None] & (r >= 0) & (r <= tau[:, None])
            s = np.where(ok, r, np.inf).min(axis=1)
            i = int(np.argmin(s))
            if s[i] < best[0]:
                best = (float(s[i]), i, axis)
        return best

    def step(self, t_end: float = math.inf) -> str | None:
        """Advances to the next event and resolves it; ``None`` when nothing moves any more
        (or at ``t_end``)."""
        horizon = t_end - self.time
        dt_ball, i, j = bc.earliest_collision(
            self.pos, self.vel, self.friction, self.radius, t_max=horizon
        )
        dt_wall, k, axis = self.next_wall()
        dt = min(dt_ball, dt_wall)
        if not math.isfinite(dt) or dt >= horizon:
            # No more events: run on until everything stops (or to t_end) and finish.
            rest = min(float(self.stop_times().max(initial=0.0)), horizon)
            self._advance_checked(rest)
            self._record()
            return None
        self._advance_checked(dt)
        if dt_ball <= dt_wall:
            self._collide(i, j)
            self.stats.ball_events += 1
            kind = "ball"
        else:
            self.vel[k, axis] = -self.vel[k, axis]
            # The ball is at the wall up to rounding: put it exactly there.
            lo, hi = self.radius, self.size[axis] - self.radius
            self.pos[k, axis] = min(max(self.pos[k, axis], lo), hi)
            self.stats.wall_events += 1
            kind = "wall"
        self._record()
        return kind

    def _collide(self, i: int, j: int) -> None:
        """Equal masses, elastic: exchange the velocity components along the line of centres."""
        d = self.pos[j] - self.pos[i]
        n = d / np.hypot(d[0], d[1])
        closing = float(np.dot(self.vel[i] - self.vel[j], n))
        if closing > 0:
            self.vel[i] -= closing * n
            self.vel[j] += closing * n

    def run(self, max_events: int = 100_000, t_end: float = math.inf) -> Stats:
        for _ in range(max_events):
            if self.step(t_end) is None:
                break
        self.stats.time = self.time
        return self.stats

    # --- invariants -------------------------------------------------------------------------

    def _advance_checked(self, dt: float) -> None:
        """Advances by ``dt``, checking for overlaps at a few times on the way."""
        if math.isfinite(dt) and dt > 0:
            for s in (0.25, 0.5, 0.75):
                self._check(bc.positions_at(self.pos, self.vel, self.friction, s * dt))
        self.advance(dt if math.isfinite(dt) else 0.0)
        self._check(self.pos)

    def _check(self, pos: np.ndarray) -> None:
        n = len(pos)
        if n > 1:
            i, j = np.triu_indices(n, k=1)
            distance = np.hypot(*(pos[i] - pos[j]).T)
            overlap = float((2 * self.radius - distance).max())
            self.stats.max_overlap = max(self.stats.max_overlap, overlap)
            assert overlap <= OVERLAP_TOLERANCE, f"balls overlap by {overlap:.3g} m"
        lo = self.radius - OVERLAP_TOLERANCE
        hi = np.array(self.size) - self.radius + OVERLAP_TOLERANCE
        assert ((pos >= lo) & (pos <= hi)).all(), "a ball left the box"

    def _record(self) -> None:
        energy = self.energy()
        previous = self.stats.energies[-1]
        assert energy <= previous * (1 + ENERGY_TOLERANCE), "kinetic energy grew"
        self.stats.energies.append(energy)
        for path, p in zip(self.paths, self.pos):
            if np.any(path[-1] != p):
                path.append(p.copy())


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


def break_simulation(friction: float = 0.6, **kwargs: float) -> Simulation:
    pos, vel = rack_and_cue(**kwargs)
    return Simulation(pos, vel, friction)


def plot(sim: Simulation, path: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle, Rectangle

    width, height = sim.size
    fig, ax = plt.subplots(figsize=(8, 4.4), dpi=100)
    ax.add_patch(Rectangle((0, 0), width, height, facecolor="#1f6f3f", edgecolor="#5a3a1a", lw=6))
    colors = plt.get_cmap("tab20")(np.linspace(0, 1, 16))
    for b, (points, color) in enumerate(zip(sim.paths, colors)):
        xy = np.array(points)
        cue = b == len(sim.paths) - 1
        c = "white" if cue else color
        ax.plot(xy[:, 0], xy[:, 1], color=c, lw=1.6 if cue else 1.0, alpha=0.9)
        ax.add_patch(Circle(tuple(xy[0]), sim.radius, fill=False, ec=c, lw=0.8, ls=":"))
        ax.add_patch(Circle(tuple(xy[-1]), sim.radius, color=c, ec="black", lw=0.5))
    s = sim.stats
    ax.set_title(
        f"16-ball break, event-driven with ballcollide: {s.ball_events} ball and "
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


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--events", type=int, default=100_000, help="stop after this many")
    parser.add_argument("--speed", type=float, default=6.0, help="cue ball speed, m/s")
    parser.add_argument("--friction", type=float, default=0.6, help="deceleration, m/s²")
    parser.add_argument("--plot", metavar="PNG", help="draw the trajectories to this file")
    args = parser.parse_args(argv)
    sim = break_simulation(friction=args.friction, speed=args.speed)
    stats = sim.run(max_events=args.events)
    print(
        f"{stats.ball_events} ball-ball and {stats.wall_events} wall collisions in "
        f"{stats.time:.3f} s of play; kinetic energy {stats.energies[0]:.3f} → "
        f"{stats.energies[-1]:.3g} J/kg, never increasing; deepest overlap "
        f"{max(stats.max_overlap, 0.0):.2g} m (≤ {OVERLAP_TOLERANCE:g})"
    )
    if args.plot:
        plot(sim, args.plot)
        print(f"trajectories: {args.plot}")


if __name__ == "__main__":
    main()
