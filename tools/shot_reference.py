"""pooltool 0.6.0's event sequences of simple seeded shots, for ``ballcollide.billiards``' engine.

This script plays seeded shots on pooltool's default table (``Table.default()``, the 7-foot
pocket table) with pooltool's own ``simulate`` and default physics, and writes each shot's
inputs and event sequence to ``tests/data/shot_cases.txt``, which ``tests/reference/shots.rs``
reads and replays with ``simulate_shot``.  It does not import ballcollide.  It needs pooltool
(run it in ``.venv-pooltool``, made by ``scripts/install-pooltool``).

Shots, by kind (each from its own seed):

* ``object``: the cue ball struck at one object ball, cut by up to 25 degrees, with some
  side, top or back spin;
* ``rail``: the cue ball alone, struck at a rail;
* ``pocket``: the cue ball alone, struck at a pocket's centre;
* ``two``: the cue ball struck at the first of two object balls;
* ``masse``: as ``object``, with the cue raised 5 to 35 degrees (a curved slide);
* ``break``: pooltool's 9-ball rack (``get_rack``, seeded), the cue ball struck at 5 to
  8 m/s at the head ball, up to a degree off;
* ``break8``: the same with pooltool's 8-ball rack (15 object balls; not in the committed
  file, whose size it would double: ``--kind break8``);
* ``straight``: the cue ball struck along an axis (``phi`` 0, 90, 180 or 270) straight at an
  object ball on the same line, so that both roll the same way after the collision: the two
  balls' accelerations are then equal, and pooltool's quartic, with a zero leading
  coefficient, makes them collide at once.

Every number is Python's ``repr`` of a float64 (it reads back to the same float).  Line
formats, one shot after the table:

* ``params m R u_s u_r u_sp_proportionality u_b e_b e_c f_c g`` (every ball's);
* ``linear ID p1x p1y p2x p2y height direction`` (``direction`` pooltool's
  ``CushionDirection``), ``circular ID cx cy radius height``, ``pocket ID cx cy radius depth``:
  the table, each kind's objects numbered in this order from 0;
* ``shot NAME`` then ``ball ID x y`` per ball (numbered from 0, the cue ball first),
  ``cue v0 phi theta a b M end_mass tip_radius`` (the strike of ball 0), ``event TYPE TIME
  AGENT...`` per event in pooltool's order (without the null events at both ends; agents
  ``b<k>`` a ball, ``l<k>``, ``c<k>``, ``p<k>`` a straight or rounded cushion or a pocket,
  ``cue`` the cue), ``final k s x y`` per ball (its motion state and position at the end),
  then ``end``.

Usage::

    .venv-pooltool/bin/python tools/shot_reference.py            # the whole file (16 of each)
    .venv-pooltool/bin/python tools/shot_reference.py --count 2  # the first 2 of each kind
    .venv-pooltool/bin/python tools/shot_reference.py --count 200 --kind break --out /tmp/b.txt

(``tests/reference/shots.rs`` reads another file named by ``BALLCOLLIDE_SHOT_CASES``.)
"""

from __future__ import annotations

import argparse
import math
import random
from pathlib import Path

import numpy as np
import pooltool as pt

OUT = Path(__file__).resolve().parent.parent / "tests" / "data" / "shot_cases.txt"
KINDS = ("object", "rail", "pocket", "two", "masse", "break", "straight", "break8")
COMMITTED = KINDS[:-1]  # the kinds of the committed file


def fmt(*xs: float) -> str:
    return " ".join(repr(float(x)) for x in xs)


def spin(rng: np.random.Generator) -> tuple[float, float]:
    """A contact point well inside the ball's face."""
    return float(rng.uniform(-0.4, 0.4)), float(rng.uniform(-0.5, 0.5))


def free_spot(rng: np.random.Generator, table, taken: list[tuple[float, float]], R: float):
    """A spot at least 0.15 m from the rails and 3 R from every ball in ``taken``."""
    while True:
        x = float(rng.uniform(0.15, table.w - 0.15))
        y = float(rng.uniform(0.15, table.l - 0.15))
        if all(math.hypot(x - a, y - b) > 3 * R for a, b in taken):
            return x, y


def towards(a: tuple[float, float], b) -> float:
    return math.degrees(math.atan2(b[1] - a[1], b[0] - a[0]))


def rack(seed: int, table, game=pt.GameType.NINEBALL):
    """pooltool's rack of ``game`` (9-ball by default), seeded: the ids (the cue ball first)
    and spots.

    pooltool gives the rack's spots ids in an order that hash randomisation changes from run
    to run, so the object balls are named here by their spots, "1" the nearest the cue ball
    (the lowest y, then x).
    """
    random.seed(seed)
    np.random.seed(seed)  # noqa: NPY002 (get_rack draws from the legacy global generator)
    balls = pt.get_rack(game, table)
    spot = {i: tuple(float(x) for x in b.state.rvw[0, :2]) for i, b in balls.items()}
    rest = sorted((spot[i] for i in balls if i != "cue"), key=lambda p: (p[1], p[0]))
    spots = [spot["cue"], *rest]
    return ["cue"] + [str(k) for k in range(1, len(spots))], spots


def shot_of(kind: str, seed: int, table, R: float):
    """The balls' ids and spots and the strike (v0, phi, theta, a, b) of one shot."""
    rng = np.random.default_rng([KINDS.index(kind), seed])
    if kind in ("break", "break8"):
        game = pt.GameType.NINEBALL if kind == "break" else pt.GameType.EIGHTBALL
        ids, spots = rack(seed, table, game)
        phi = towards(spots[0], spots[1]) + float(rng.uniform(-1.0, 1.0))
        v0 = float(rng.uniform(5.0, 8.0))
        return ids, spots, (v0, phi % 360.0, 0.0, 0.0, float(rng.uniform(-0.3, 0.3)))
    if kind == "straight":
        phi = float(rng.choice([0.0, 90.0, 180.0, 270.0]))
        cue = free_spot(rng, table, [], R)
        step = float(rng.uniform(0.1, 0.5))
        direction = (round(math.cos(math.radians(phi))), round(math.sin(math.radians(phi))))
        target = (cue[0] + step * direction[0], cue[1] + step * direction[1])
        if not (0.1 < target[0] < table.w - 0.1 and 0.1 < target[1] < table.l - 0.1):
            target = (cue[0] - step * direction[0], cue[1] - step * direction[1])
            phi = (phi + 180.0) % 360.0
        v0 = float(rng.uniform(0.5, 3.0))
        return ["cue", "1"], [cue, target], (v0, phi, 0.0, 0.0, float(rng.uniform(-0.5, 0.5)))
    cue = free_spot(rng, table, [], R)
    spots = [cue]
    a, b = spin(rng)
    v0 = float(rng.uniform(1.0, 3.0))
    theta = float(rng.uniform(5.0, 35.0)) if kind == "masse" else 0.0
    if kind in ("object", "two", "masse"):
        for _ in range(2 if kind == "two" else 1):
            spots.append(free_spot(rng, table, spots, R))
        # A cut: aim at a point beside the object ball's centre (up to sin 25° of 2R).
        target = spots[1]
        phi = towards(cue, target)
        offset = 2 * R * math.sin(math.radians(float(rng.uniform(-25.0, 25.0))))
        distance = math.hypot(target[0] - cue[0], target[1] - cue[1])
        phi += math.degrees(math.asin(offset / distance))
    elif kind == "rail":
        phi = float(rng.choice([0.0, 90.0, 180.0, 270.0]) + rng.uniform(-30.0, 30.0))
    else:
        pocket = list(table.pockets.values())[int(rng.integers(len(table.pockets)))]
        phi = towards(cue, pocket.center)
        v0 = float(rng.uniform(0.8, 2.0))
        a, b = 0.0, float(rng.uniform(0.0, 0.4))
    ids = ["cue"] + [str(k) for k in range(1, len(spots))]
    return ids, spots, (v0, phi % 360.0, theta, a, b)


def table_lines(table) -> tuple[list[str], dict[tuple[str, str], str]]:
    """The table's lines, and each object's agent name by its agent type and pooltool id
    (ids repeat across kinds and balls: the linear cushion "1", the ball "1")."""
    lines, names = [], {}
    for k, (key, c) in enumerate(table.cushion_segments.linear.items()):
        lines.append(
            f"linear {key} {fmt(c.p1[0], c.p1[1], c.p2[0], c.p2[1], c.height)} {int(c.direction)}"
        )
        names[("linear_cushion_segment", key)] = f"l{k}"
    for k, (key, c) in enumerate(table.cushion_segments.circular.items()):
        lines.append(f"circular {key} {fmt(c.center[0], c.center[1], c.radius, c.height)}")
        names[("circular_cushion_segment", key)] = f"c{k}"
    for k, (key, p) in enumerate(table.pockets.items()):
        lines.append(f"pocket {key} {fmt(p.center[0], p.center[1], p.radius, p.depth)}")
        names[("pocket", key)] = f"p{k}"
    return lines, names


def play(name: str, ids, spots, strike, table, names: dict) -> list[str]:
    balls = {i: pt.Ball.create(i, xy=xy) for i, xy in zip(ids, spots)}
    system = pt.System(cue=pt.Cue(cue_ball_id="cue"), table=table, balls=balls)
    v0, phi, theta, a, b = strike
    system.strike(V0=v0, phi=phi, theta=theta, a=a, b=b)
    specs = system.cue.specs
    pt.simulate(system, inplace=True)
    agents = {**names, **{("ball", i): f"b{k}" for k, i in enumerate(ids)}}
    lines = [f"shot {name}"]
    lines += [f"ball {i} {fmt(*xy)}" for i, xy in zip(ids, spots)]
    lines.append(f"cue {fmt(v0, phi, theta, a, b, specs.M, specs.end_mass, specs.tip_radius)}")
    for event in system.events:
        kind = event.event_type.value
        if kind == "none":
            continue
        who = " ".join(
            "cue" if a.agent_type.value == "cue" else agents[(a.agent_type.value, a.id)]
            for a in event.agents
        )
        lines.append(f"event {kind} {event.time!r} {who}")
    for k, i in enumerate(ids):
        state = system.balls[i].state
        lines.append(f"final {k} {state.s} {fmt(state.rvw[0, 0], state.rvw[0, 1])}")
    lines.append("end")
    return lines


def cases(count: int, kinds: tuple[str, ...] = COMMITTED) -> list[str]:
    """The file's lines: the table, then ``count`` shots of each of ``kinds``."""
    table = pt.Table.default()
    p = pt.BallParams.default()
    params = (p.m, p.R, p.u_s, p.u_r, p.u_sp_proportionality, p.u_b, p.e_b, p.e_c, p.f_c, p.g)
    lines = [
        "# pooltool 0.6.0's events of seeded shots: written by tools/shot_reference.py",
        f"params {fmt(*params)}",
    ]
    object_lines, names = table_lines(table)
    lines += object_lines
    for kind in kinds:
        for seed in range(count):
            ids, spots, strike = shot_of(kind, seed, table, p.R)
            lines += play(f"{kind}-{seed}", ids, spots, strike, table, names)
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=16, help="shots of each kind")
    parser.add_argument("--out", type=Path, default=OUT)
    parser.add_argument("--kind", choices=KINDS, action="append", help="only these kinds")
    args = parser.parse_args()
    lines = cases(args.count, tuple(args.kind or COMMITTED))
    args.out.write_text("\n".join(lines) + "\n")
    print(f"wrote {args.out} ({len(lines)} lines)")


if __name__ == "__main__":
    main()
