"""High-precision reference cases for contacts far narrower than the float grid (issue 39).

A family of exact, non-grazing contacts (and clear misses) whose contact distance ``r`` runs
from the separation itself down to ``2^-400`` of it, several cases per octave, for friction
balls and for paths in 2-D and 3-D; each answered by the repository's own independent
references (``tools/collision_reference.py`` for balls, ``tools/path_reference.py`` for paths:
mpmath from the exact binary inputs, here at 1200 bits rather than their 256 so that r² is
kept beside the separation's square), never by ballcollide.

The inputs are built so that the motion float64 numbers describe is the one intended, exactly:

* head on: offsets, velocities and accelerations on one line, either an axis or a diagonal
  (``(±1, ±1)``, ``(±1, ±1, ±1)``: a friction ball's friction vector ``−v/τ`` stays on it), or,
  for paths, a random direction with 26-bit components times 24-bit integers (every product
  exact, so the line is exactly a line);
  (a path with a later segment start only on an axis or a diagonal: the library forms the
  other ball's position at that start coordinate by coordinate, and the roundings put it off
  a line in a random direction by far more than ``r``; such a pair is beyond float64 there);
* off axis: the motion along one axis, the other ball displaced sideways along another axis by
  ``β·r`` (``β < 0.9``: a hit of depth ``≥ 1 − 0.9``; ``β > 1.1``: a clear miss);
* curved (paths): the motion along one axis, a sideways acceleration on another that brings the
  balls ``β·r`` apart sideways at the head-on time.

Usage::

    python tools/narrow_reference.py                 # writes tests/data/narrow_cases.txt
    python tools/narrow_reference.py --per-octave 1  # a quick, smaller run

Output: one case per line, ``ball <category> <the 16 columns of collision_cases.txt after the
category>`` or ``path <category> <the columns of path_cases.txt after the category>``.
"""

from __future__ import annotations

import argparse
import math
import os
import random
import sys
import time
from multiprocessing import Pool

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import collision_reference as cr
import path_reference as pr

DEFAULT_OUT = os.path.join(os.path.dirname(__file__), "..", "tests", "data", "narrow_cases.txt")
LOWEST_OCTAVE = 400


def integer(rng: random.Random, bits: int = 24) -> float:
    """A random integer of at most `bits` bits, at least 1."""
    return float(rng.randrange(1, 1 << bits))


def mantissa26(rng: random.Random) -> float:
    """A random number in [0.5, 1) with 26 significant bits."""
    return rng.randrange(1 << 25, 1 << 26) / float(1 << 26)


def scale(rng: random.Random, lo: int, hi: int) -> float:
    """A random power of two 2^k, lo <= k <= hi."""
    return math.ldexp(1.0, rng.randint(lo, hi))


def ratio(rng: random.Random, octave: int) -> float:
    """r / separation in the octave [2^-(octave+1), 2^-octave)."""
    return math.ldexp(1.0 + rng.random(), -octave - 1)


def lateral(rng: random.Random, hit: bool) -> float:
    """The sideways miss distance over r: < 0.9 for a hit, > 1.1 for a miss."""
    return rng.uniform(0.0, 0.9) if hit else rng.uniform(1.1, 3.0)


def head_on_line(rng: random.Random, dim: int, diagonal_only: bool) -> tuple[float, ...]:
    """A direction whose products with 24-bit integers are exact: an axis, a diagonal, or
    (paths) 26-bit components."""
    kind = rng.choice(["axis", "diagonal"] if diagonal_only else ["axis", "diagonal", "random"])
    if kind == "axis":
        w = [0.0] * dim
        w[rng.randrange(dim)] = rng.choice([-1.0, 1.0])
    elif kind == "diagonal":
        w = [rng.choice([-1.0, 1.0]) for _ in range(dim)]
    else:
        w = [rng.choice([-1.0, 1.0]) * mantissa26(rng) for _ in range(dim)]
    return tuple(w)


def on_line(w: tuple[float, ...], x: float) -> tuple[float, ...]:
    return tuple(x * c for c in w)


def ball_case(rng: random.Random, octave: int, offset: bool) -> tuple[str, tuple, float]:
    """Friction balls head on (or off axis) at r / separation in `octave`."""
    length = scale(rng, -30, 30)  # the unit of the integers below
    time_unit = scale(rng, -20, 20)
    if offset:
        axis = rng.randrange(2)
        w = [0.0, 0.0]
        w[axis] = rng.choice([-1.0, 1.0])
        w = tuple(w)
    else:
        w = head_on_line(rng, 2, True)
    # B ahead of A along w by the separation; A runs at it, B runs at A, away or rests.
    sep = integer(rng)
    xa = integer(rng, 20)
    xb = xa + sep
    speed = integer(rng)
    sa = speed
    sb = rng.choice([0.0, -integer(rng), -integer(rng), integer(rng, 20) * 0.25])
    closing = sa - sb

    # Friction: none, or enough to cover the gap before the stop (mostly), in the unit
    # length / time².
    def friction(s: float) -> float:
        if s == 0.0 or rng.random() < 0.3:
            return 0.0
        stop_distance = sep * rng.uniform(0.8, 4.0)
        return s * s / (2.0 * stop_distance) if closing > 0 else rng.uniform(0.0, 1.0)

    fa, fb = friction(sa), friction(abs(sb))
    lu, vu, fu = length, length / time_unit, length / (time_unit * time_unit)
    pa = on_line(w, xa * lu)
    pb = on_line(w, xb * lu)
    va = on_line(w, sa * vu)
    vb = on_line(w, sb * vu)
    r = ratio(rng, octave) * sep * lu
    category = "ball_head_on"
    if offset:
        hit = rng.random() < 0.75
        side = [0.0, 0.0]
        side[1 - w.index(next(c for c in w if c != 0.0))] = rng.choice([-1.0, 1.0])
        h = lateral(rng, hit) * r
        pb = tuple(p + h * s for p, s in zip(pb, side))
        category = "ball_off_axis"
    inputs = (*pa, *va, fa * fu, *pb, *vb, fb * fu, r)
    return category, inputs, math.inf


def path_case(rng: random.Random, octave: int, dim: int, kind: str) -> tuple[str, tuple, float]:
    """Paths head on, off axis or curved, at r / separation in `octave`."""
    length = scale(rng, -30, 30)
    time_unit = scale(rng, -20, 20)
    lu, vu, au = length, length / time_unit, length / (time_unit * time_unit)
    # Speeds of at least 2^12 against separations below 2^12 and accelerations below 2^10:
    # A cannot turn back before the contact.
    sep = integer(rng, 12)
    xa = float(rng.randrange(0, 1 << 20))
    speed_a = float(rng.randrange(1 << 12, 1 << 24))
    speed_b = rng.choice([0.0, -integer(rng)])
    # A slowing or speeding along the line (the contact still before any turn back), or not.
    acc_a = rng.choice([0.0, -float(rng.randrange(0, 1 << 10))])
    acc_b = rng.choice([0.0, float(rng.randrange(0, 1 << 10))])
    r = ratio(rng, octave) * sep * lu
    if kind == "head_on":
        w = head_on_line(rng, dim, False)
    else:
        w = [0.0] * dim
        w[rng.randrange(dim)] = rng.choice([-1.0, 1.0])
        w = tuple(w)
    a_seg = (0.0, on_line(w, xa * lu), on_line(w, speed_a * vu), on_line(w, acc_a * au))
    b_seg = (0.0, on_line(w, (xa + sep) * lu), on_line(w, speed_b * vu), on_line(w, acc_b * au))
    if kind != "head_on":
        hit = rng.random() < 0.75
        beta = lateral(rng, hit)
        axis = w.index(next(c for c in w if c != 0.0))
        side_axis = rng.choice([k for k in range(dim) if k != axis])
        side = [0.0] * dim
        side[side_axis] = rng.choice([-1.0, 1.0])
        if kind == "off_axis":
            p = list(b_seg[1])
            p[side_axis] = side[side_axis] * beta * r
            b_seg = (0.0, tuple(p), b_seg[2], b_seg[3])
        else:
            # Sideways acceleration on B bringing it β·r aside at the head-on time t*
            # (float: the exact reference decides whatever comes out; β stays clear of 1).
            v = (speed_a - speed_b) * vu
            da = (acc_b - acc_a) * au
            d0 = sep * lu
            # d0 − v t + ½ da t² = 0, the smaller root, without cancellation.
            disc = v * v - 2.0 * da * d0
            t_star = 2.0 * d0 / (v + math.sqrt(disc))
            side_acc = 2.0 * beta * r / (t_star * t_star)
            acc = list(b_seg[3])
            acc[side_axis] = side[side_axis] * side_acc
            b_seg = (0.0, b_seg[1], b_seg[2], tuple(acc))
    category = f"path{dim}_{kind}"
    a_path = (a_seg,)
    on_grid_line = len({abs(c) for c in w if c != 0.0}) == 1
    if on_grid_line and rng.random() < 0.4:
        # A second segment for A before the contact: the same line, a new speed, from a time
        # exactly on the grid (the motion from there is A's new inputs, not the old ones).
        # Only on an axis or a diagonal: B's position at that time is formed component by
        # component, which keeps it on such a line, but off a line in a random direction by
        # a rounding of its coordinates, far more than r (see the module's docstring).
        start = time_unit * float(rng.randrange(1, 1 << 8)) / float(1 << 20)
        a_path = (
            (0.0, a_seg[1], on_line(w, speed_a * 0.5 * vu), on_line(w, 0.0 * au)),
            (start, a_seg[1], a_seg[2], a_seg[3]),
        )
    return category, (dim, a_path, (b_seg,), r), math.inf


def generate(seed: int, per_octave: int) -> list[tuple[str, str, tuple, float]]:
    rng = random.Random(seed)
    cases = []
    for octave in range(LOWEST_OCTAVE):
        for _ in range(per_octave):
            kind = rng.random()
            if kind < 0.25:
                cases.append(("ball", *ball_case(rng, octave, False)))
            elif kind < 0.40:
                cases.append(("ball", *ball_case(rng, octave, True)))
            else:
                dim = rng.choice([2, 3])
                which = rng.choice(["head_on", "head_on", "off_axis", "curved"])
                cases.append(("path", *path_case(rng, octave, dim, which)))
    return cases


def solve(case: tuple[str, str, tuple, float]) -> str:
    query, category, inputs, t_max = case
    if query == "ball":
        res = cr.collision(inputs, t_max)
        fields = [query, category, *(cr.fmt(x) for x in inputs), cr.fmt(t_max)]
    else:
        dim, a, b, r = inputs
        res = pr.collision(dim, a, b, r, t_max)
        fields = [query, category, str(dim), str(len(a)), str(len(b))]
        for seg in (*a, *b):
            s, p, v, acc = seg
            fields += [pr.fmt(s), *(pr.fmt(x) for x in (*p, *v, *acc))]
        fields += [pr.fmt(r), pr.fmt(t_max)]
    fields += [cr.fmt(cr.mp_to_float(res.t)), cr.fmt_floor(res.floor)]
    fields.append("1" if res.ambiguous else "0")
    return " ".join(fields)


# r² is 2^-800 of the separation's square at the lowest octave: the references' 256 bits would
# lose it, so they run at PREC_BITS bits here, their thresholds scaled with it.
PREC_BITS = 1200


def init() -> None:
    for module in (cr, pr):
        module.PREC_BITS = PREC_BITS
        module.ZERO_BITS = PREC_BITS - 24
        module.ROOT_BITS = PREC_BITS - 8
        if hasattr(module, "SNAP_BITS"):
            module.SNAP_BITS = PREC_BITS - 16
        module.set_precision()


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.normpath(DEFAULT_OUT))
    parser.add_argument("--seed", type=int, default=20261203)
    parser.add_argument("--per-octave", type=int, default=4)
    parser.add_argument("--processes", type=int, default=2)
    args = parser.parse_args(argv)
    start = time.time()
    cases = generate(args.seed, args.per_octave)
    with Pool(args.processes, initializer=init) as pool:
        lines = list(pool.imap(solve, cases, chunksize=8))
    with open(args.out, "w", encoding="ascii") as fh:
        fh.write("# ballcollide narrow-contact reference cases (tools/narrow_reference.py)\n")
        fh.write(
            f"# {len(lines)} cases, seed {args.seed}, {args.per_octave} per octave of "
            f"r/separation from 1 to 2^-{LOWEST_OCTAVE}; mpmath at {PREC_BITS} bits from "
            "the exact float64 inputs\n"
        )
        fh.write("# line: ball <category and columns of collision_cases.txt after it>\n")
        fh.write("#    or path <category and columns of path_cases.txt after it>\n")
        for line in lines:
            fh.write(line + "\n")
    hits = sum(1 for line in lines if line.split()[-3] != "inf")
    ambiguous = sum(1 for line in lines if line.split()[-1] == "1")
    print(
        f"wrote {len(lines)} cases ({hits} hits, {ambiguous} ambiguous) to {args.out} "
        f"in {time.time() - start:.1f} s"
    )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
