"""A segment's flat part is decided as accurately next to either end, whatever the other
end's magnitude (issue 36; docs/contract.md §4.7), against the mpmath reference of
tools/geometry_reference.py (exact from the float inputs, 256 bits).

A ball on a straight path crosses the band of a segment one of whose ends is next to the
table and the other 1e20 to 1e32 away, its foot ``β·r`` on the flat part or beyond the near
end (``β`` from 2 down to 2⁻³⁰). The foot test ``(x − P)·e ≤ |e|²`` next to Q was exact only
to 2⁻⁵³ of the far end's distance (1e4 to 1e16 here), so these were decided at random there.
"""

from __future__ import annotations

import math
import os
import random
import sys

import numpy as np
import pytest

import ballcollide as bc

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tools"))
import geometry_reference as gr

sys.path.pop(0)

R = 0.028575


def far_end_case(rng: random.Random) -> tuple[gr.Case, bool]:
    """A case and whether its foot lies on the flat part by construction."""
    near = (rng.uniform(0.0, 1.27), rng.uniform(0.0, 2.54))
    theta = rng.uniform(0.0, 2.0 * math.pi)
    along = (math.cos(theta), math.sin(theta))
    far_distance = 10.0 ** rng.uniform(20.0, 32.0)
    far = (near[0] + far_distance * along[0], near[1] + far_distance * along[1])
    left = (-along[1], along[0])
    beta = 2.0 ** rng.uniform(-30.0, 1.0)
    on_flat = rng.random() < 0.5
    delta = beta * R if on_flat else -beta * R
    side = rng.choice((1, -1))
    # Where the centre enters the band: δ along from the near end, r off the line.
    x = tuple(near[k] + delta * along[k] + side * R * left[k] for k in range(2))
    phi = rng.uniform(-1.2, 1.2)
    speed = 10.0 ** rng.uniform(-1.0, 1.0)
    vel = tuple(
        speed * (-side * left[k] * math.cos(phi) + along[k] * math.sin(phi)) for k in range(2)
    )
    t_c = rng.uniform(0.1, 2.0)
    start = tuple(x[k] - vel[k] * t_c for k in range(2))
    path = ((0.0, start, vel, (0.0, 0.0)),)
    ends = (near, far) if rng.random() < 0.5 else (far, near)
    sided = rng.choice((0, 1, -1))
    sided = 0 if sided == 0 else side if ends[0] == near else -side
    obj = (*ends[0], *ends[1], float(rng.choice((0, sided))))
    return gr.Case("seg_far_end", "segment", 2, path, R, obj), on_flat


@pytest.mark.parametrize("seed", range(4))
def test_the_flat_part_next_to_the_near_end_whatever_the_far_ends_distance(seed: int) -> None:
    rng = random.Random(f"far-end:{seed}")
    checked = hits = 0
    for _ in range(50):
        case, on_flat = far_end_case(rng)
        ref = gr.contact(case)
        if set(ref.reasons) - {"end"}:
            continue  # a graze or a touch at the start: not this test's subject
        # The reference's own end band is relative to the length (1e-9 of 1e20 and more);
        # these feet are at least 2⁻³⁰·r from the end, far beyond the rounding of the inputs.
        assert (ref.t != gr.INF) == on_flat, case
        ((s, p, v, a),) = case.path
        px, py, qx, qy, side = case.obj
        time, kind, index = bc.path_geometry_times(
            [[s]], [[p]], [[v]], [[a]], case.radius,
            segments=[[[px, py], [qx, qy]]], segment_sides=[int(side)],
        )  # fmt: skip
        if ref.t == gr.INF:
            assert time[0] == math.inf and kind[0] == -1 and index[0] == -1, case
        else:
            hits += 1
            assert (kind[0], index[0]) == (bc.SEGMENT, 0), case
            error = abs(gr.mpf(float(time[0])) - ref.t)
            assert error <= 8 * ref.floor + 4 * np.spacing(float(ref.t)), (case, error, ref.floor)
        checked += 1
    assert checked >= 40 and 10 <= hits <= checked - 10
