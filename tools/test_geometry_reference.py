"""Self-checks of the mpmath static-geometry reference (tools/geometry_reference.py).

Run with ``python -m pytest tools/test_geometry_reference.py -q``.
"""

from __future__ import annotations

import math
import os
import random
import sys

from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import geometry_reference as gr

TIGHT = mpf(2) ** -200
INF = mp.inf


def seg(s, p, v, a=None):
    """A path segment with float components (a defaults to zero)."""
    p = tuple(float(x) for x in p)
    a = a or (0.0,) * len(p)
    return (float(s), p, tuple(float(x) for x in v), tuple(float(x) for x in a))


def solve(kind, path, radius, obj, t_max=math.inf):
    """Reference answer for one object."""
    dim = len(path[0][1])
    case = gr.Case("test", kind, dim, tuple(path), float(radius), tuple(obj), t_max)
    return gr.contact(case)


def assert_time(res, expected):
    """The reference time equals `expected` to 2^-200 (relative, or absolute below 1)."""
    expected = mpf(expected)
    assert abs(res.t - expected) <= TIGHT * max(abs(expected), mpf(1)), (
        mp.nstr(res.t, 40),
        mp.nstr(expected, 40),
    )


# --- segments ------------------------------------------------------------------


def test_a_ball_rolling_onto_a_segment_touches_it_at_its_radius():
    down = [seg(0, (1.0, 0.7), (0.0, -0.3))]
    res = solve("segment", down, 0.1, (0.0, 0.0, 2.0, 0.0, 1))
    assert_time(res, (mpf(0.7) - mpf(0.1)) / mpf(0.3))
    assert res.kind == "root" and not res.ambiguous
    assert 0 < res.floor < 1e-14


def test_the_side_filter_and_the_ends():
    up = [seg(0, (1.0, -0.7), (0.0, 0.3))]
    assert solve("segment", up, 0.1, (0.0, 0.0, 2.0, 0.0, 1)).t == INF
    assert solve("segment", up, 0.1, (0.0, 0.0, 2.0, 0.0, -1)).t < INF
    # The same segment reversed: its left is below.
    assert solve("segment", up, 0.1, (2.0, 0.0, 0.0, 0.0, 1)).t < INF
    beyond = [seg(0, (2.5, 0.7), (0.0, -0.3))]
    assert solve("segment", beyond, 0.1, (0.0, 0.0, 2.0, 0.0, 0)).t == INF
    # Into the band beyond Q, then sliding along it onto the segment: no contact.
    slide = [seg(0, (2.5, 0.2), (0.0, -1.0)), seg(0.15, (2.5, 0.05), (-1.0, 0.0))]
    assert solve("segment", slide, 0.1, (0.0, 0.0, 2.0, 0.0, 0)).t == INF
    # Exactly over an end: a contact, flagged (either answer is fine there).
    over_q = [seg(0, (2.0, 0.7), (0.0, -0.3))]
    res = solve("segment", over_q, 0.1, (0.0, 0.0, 2.0, 0.0, 0))
    assert res.t < INF and "end" in res.reasons


def test_a_jump_across_the_band_is_no_contact_and_into_it_is():
    rest = lambda t, y: seg(t, (1.0, y), (0.0, 0.0))  # noqa: E731
    across = [rest(0, 1.0), rest(2, -1.0)]
    assert solve("segment", across, 0.25, (0.0, 0.0, 2.0, 0.0, 0)).t == INF
    into = [rest(0, 1.0), rest(2, -0.1)]
    res = solve("segment", into, 0.25, (0.0, 0.0, 2.0, 0.0, -1))
    assert res.t == 2 and res.kind == "jump"
    assert solve("segment", into, 0.25, (0.0, 0.0, 2.0, 0.0, 1)).t == INF


def test_touching_at_the_start_counts_only_when_approaching():
    obj = (0.0, 0.0, 2.0, 0.0, 0)
    towards = solve("segment", [seg(3, (1.0, 0.25), (0.0, -1.0))], 0.25, obj)
    assert towards.t == 3 and towards.kind == "t_from"
    away = solve("segment", [seg(3, (1.0, 0.25), (0.0, 1.0))], 0.25, obj)
    assert away.t == INF
    along = solve("segment", [seg(3, (1.0, 0.25), (1.0, 0.0))], 0.25, obj)
    assert along.t == INF and along.ambiguous


# --- circles, targets, planes ---------------------------------------------------


def test_circles_and_targets_are_met_at_rho_plus_r_and_rho():
    path = [seg(0, (0.0, 0.0), (0.5, 0.0))]
    res = solve("circle", path, 0.125, (3.0, 0.0, 0.25))
    assert_time(res, (3 - mpf(0.375)) / mpf(0.5))
    res = solve("target", path, 0.125, (3.0, 0.0, 0.25))
    assert_time(res, (3 - mpf(0.25)) / mpf(0.5))
    # A pass at 0.4 from the centre misses a circle at 0.375 and enters a target of 0.5.
    aside = [seg(0, (0.0, 0.4), (0.5, 0.0))]
    assert solve("circle", aside, 0.125, (3.0, 0.0, 0.25)).t == INF
    assert solve("target", aside, 0.125, (3.0, 0.0, 0.5)).t < INF


def test_a_ball_falls_onto_a_plane_at_its_radius_whatever_the_normal_s_length():
    path = [seg(0, (0.0, 0.0, 1.0), (1.0, 0.0, 0.0), (0.0, 0.0, -10.0))]
    for n in (1.0, 2.0, 0.1):
        res = solve("plane", path, 0.1, (5.0, -3.0, 0.0, 0.0, 0.0, n))
        assert_time(res, mp.sqrt((1 - mpf(0.1)) / 5))
    # A tangency (the apex at r) is no contact, and ambiguous.
    apex = [seg(0, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, 0.0, -2.0))]
    res = solve("plane", apex, 0.25, (0.0, 0.0, 0.5, 0.0, 0.0, -1.0))
    assert res.t == INF and "graze" in res.reasons


def test_powers_of_two_change_no_time():
    rng = random.Random(5)
    for gen in (gr.gen_seg_table, gr.gen_plane_bounce):
        for case in gen(rng, 10):
            base = gr.contact(case)
            scaled = gr.contact(gr.scaled_case(case, "x", 2.0**-37))
            assert base.t == scaled.t
            assert abs(base.floor - scaled.floor) <= mpf(2) ** -150 * (1 + base.floor)


def test_lines_round_trip():
    rng = random.Random(7)
    cases = gr.gen_seg_ends(rng, 3) + gr.gen_plane_touch(rng, 3)
    cases += gr.gen_disc_3d("circle", "c")(rng, 3)
    for case in cases:
        res = gr.contact(case)
        parsed = gr.parse_line(gr.format_line(case, res))
        assert parsed.case == case
        assert parsed.t_ref == gr.mp_to_float(res.t)
        assert parsed.ambiguous == res.ambiguous
