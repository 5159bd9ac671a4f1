"""Near misses and hits off a head-on line, the contact distance tiny beside the separation:
every query against the exact answer of the float inputs (rational arithmetic), not the
library's own float64 arithmetic.

Ball A starts at the origin and moves at a constant velocity; B rests at a point nearly on
A's line. The exact closest approach of the centres is ``h = |P × v| / |v|`` (P the resting
centre), so A and B touch iff ``h < r`` with ``P·v > 0``. Contract §5: a closest approach
within the rounding of the separation (``h`` below ~2⁻⁵⁰ of ``|P|``) is beyond what float64
decides, and either answer may come back, the same from every query; an exactly head-on
motion is a hit.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

import ballcollide as bc


def exact(p: tuple[float, float], v: tuple[float, float], r: float) -> tuple[bool, Fraction]:
    """The exact hit or miss, and ``(h/|P|)²``."""
    (px, py), (vx, vy) = map(Fraction, p), map(Fraction, v)
    cross2 = (px * vy - py * vx) ** 2
    speed2 = vx * vx + vy * vy
    hit = px * vx + py * vy > 0 and cross2 < Fraction(r) ** 2 * speed2
    return hit, cross2 / speed2 / (px * px + py * py)


def queries(p, v, r) -> dict[str, float]:
    zero = [0.0, 0.0]
    path_a = ([0.0], [zero], [list(v)], [zero])
    path_b = ([0.0], [list(p)], [zero], [zero])
    return {
        "collision_time": bc.collision_time(zero, v, 0.0, p, zero, 0.0, r),
        "path_collision_time": bc.path_collision_time(path_a, path_b, r),
        "collision_times": float(
            bc.collision_times([zero], [v], [0.0], [p], [zero], [0.0], [r])[0]
        ),
    }


@pytest.mark.parametrize("seed", range(4))
def test_near_head_on_pairs_from_2_to_the_minus_60_to_minus_400(seed: int) -> None:
    rng = np.random.default_rng(seed)
    decided = 0
    for m in range(200):
        v = tuple(float(x) for x in rng.uniform(-3, 3, 2))
        # B on A's line: exactly (k a power of two), or rounded (a miss or hit below the grid).
        k = 2.0 ** int(rng.integers(-1, 2)) if m % 4 == 0 else float(rng.uniform(0.5, 3))
        p = (v[0] * k, v[1] * k)
        r = float(np.hypot(*p)) * 2.0 ** -float(rng.uniform(60, 400))
        hit, off2 = exact(p, v, r)
        times = queries(p, v, r)
        # One answer: hit or miss alike (the times within a few ulps).
        assert len({bool(np.isfinite(t)) for t in times.values()}) == 1, f"{p} {v} {r!r}: {times}"
        if off2 == 0:
            assert hit and np.isfinite(times["collision_time"]), f"{p} {v} {r!r}"
        if off2 > Fraction(1, 2**90) or off2 == 0:  # decided by float64 inputs
            decided += 1
            assert np.isfinite(times["collision_time"]) == hit, f"{p} {v} {r!r}: {times}"
    assert decided >= 40
