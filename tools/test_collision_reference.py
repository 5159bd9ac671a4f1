"""Self-checks of the mpmath collision reference (tools/collision_reference.py).

Run with ``python -m pytest tools/test_collision_reference.py -q``.
"""

from __future__ import annotations

import math
import os
import random
import sys

import pytest
from mpmath import mp, mpf, polyroots

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import collision_reference as cr

R_TABLE = cr.R_TABLE
TIGHT = mpf(2) ** -200


def case(pa, va, fa, pb, vb, fb, radius):
    """Inputs tuple from vectors."""
    return (*pa, *va, fa, *pb, *vb, fb, radius)


def assert_time(result, expected, rel=TIGHT):
    """The reference time equals `expected` (mp or float) to `rel`."""
    expected = mpf(expected)
    assert abs(result.t - expected) <= rel * max(abs(expected), mpf(1)), (
        mp.nstr(result.t, 40),
        mp.nstr(expected, 40),
    )


# --- hand-computable cases ---------------------------------------------------


def test_head_on_frictionless_exact():
    """t = (distance - R) / closing speed, from the exact binary inputs."""
    inputs = case((0.1, 0.2), (0.7, 0.0), 0.0, (1.3, 0.2), (-0.4, 0.0), 0.0, R_TABLE)
    res = cr.collision(inputs)
    expected = (mpf(1.3) - mpf(0.1) - mpf(R_TABLE)) / (mpf(0.7) + mpf(0.4))
    assert_time(res, expected)
    assert not res.ambiguous
    assert 0 < res.floor < 1e-14


def test_head_on_simple_numbers():
    """A rolls into B at rest: t = 0.75; both moving: t = 0.375."""
    res = cr.collision(case((0, 0), (1, 0), 0, (1, 0), (0, 0), 0, 0.25))
    assert_time(res, 0.75)
    res = cr.collision(case((0, 0), (1, 0), 0, (1, 0), (-1, 0), 0, 0.25))
    assert_time(res, 0.375)


def test_ball_at_rest_hit_by_frictionless_ball():
    """Diagonal 3-4-5 shot: distance 10, R = 1, speed 5 -> t = 1.8."""
    res = cr.collision(case((0, 0), (3, 4), 0, (6, 8), (0, 0), 0.7, 1.0))
    assert_time(res, mpf(9) / 5)
    res = cr.collision(case((6, 8), (0, 0), 0.7, (0, 0), (3, 4), 0, 1.0))
    assert_time(res, mpf(9) / 5)


def test_hit_before_stop():
    """x_A = 2t - t^2/2 stops at 2 (t = 2); B at rest at 2.125: t = 1.5."""
    res = cr.collision(case((0, 0), (2, 0), 1, (2.125, 0), (0, 0), 0, 0.25))
    assert_time(res, 1.5)
    assert not res.ambiguous


def test_hit_just_before_stop_is_ambiguous():
    """Overlap of 2^-41 at the stop: t = 2 - 2^-20, but a tangency at a stop."""
    pb = 2.25 - 2.0**-41
    res = cr.collision(case((0, 0), (2, 0), 1, (pb, 0), (0, 0), 0, 0.25))
    assert_time(res, 2 - mpf(2) ** -20)
    assert res.ambiguous and "graze" in res.reasons


def test_stop_short_is_miss():
    """A stops 1e-3 short of touching B: a clear miss."""
    res = cr.collision(case((0, 0), (2, 0), 1, (2.251, 0), (0, 0), 0, 0.25))
    assert res.t == mp.inf and not res.ambiguous


def test_hit_after_a_stops():
    """A stops at x = 2 (t = 2); B comes from x = 10 at speed 1: t = 7."""
    res = cr.collision(case((0, 0), (2, 0), 1, (10, 0), (-1, 0), 0, 1.0))
    assert_time(res, 7)
    assert not res.ambiguous


def test_hit_exactly_at_stop_time():
    """B crosses A's stop point exactly when A stops (t = 2)."""
    res = cr.collision(case((0, 0), (2, 0), 1, (2, -1.5), (0, 0.5), 0, 0.5))
    assert_time(res, 2)
    assert not res.ambiguous


def test_both_stop_before_reaching():
    """Stopping distances 0.5 each, gap 4 > R: miss."""
    res = cr.collision(case((0, 0), (1, 0), 1, (5, 0), (-1, 0), 1, 1.0))
    assert res.t == mp.inf and not res.ambiguous and res.floor == 0


def test_overlapping_separating_is_not_zero():
    """Overlap at t = 0 while separating, and never again: no collision."""
    res = cr.collision(case((0, 0), (-1, 0), 0, (0.5, 0), (1, 0), 0, 1.0))
    assert res.t == mp.inf and not res.ambiguous


def test_overlapping_separating_then_reentry():
    """B flees with high friction and stops; A follows: re-entry.

    Gap 0.5 + 2t - 2t^2 (B stops at 0.75); re-entry at 2t^2 - 2t + R - 0.5 = 0.
    """
    res = cr.collision(case((0, 0), (1, 0), 0, (0.5, 0), (3, 0), 4, 0.9))
    r = mpf(0.9)
    assert_time(res, (2 + mp.sqrt(4 - 8 * (r - mpf(0.5)))) / 4)
    assert not res.ambiguous


def test_touching_approaching_is_zero():
    """|d(0)| = R exactly and approaching: t = 0."""
    res = cr.collision(case((0, 0), (1, 0), 0, (1, 0), (0, 0), 0, 1.0))
    assert res.t == 0 and not res.ambiguous
    assert 0 < res.floor < 1e-15


def test_overlapping_approaching_is_zero_with_zero_floor():
    """Deep overlap, approaching: t = 0, floor 0."""
    res = cr.collision(case((0, 0), (1, 0), 1, (0.5, 0), (0, 0), 0, 1.0))
    assert res.t == 0 and res.floor == 0 and not res.ambiguous


def test_touching_separating_is_miss():
    """|d(0)| = R exactly and separating: no collision."""
    res = cr.collision(case((0, 0), (-1, 0), 0, (1, 0), (0, 0), 0, 1.0))
    assert res.t == mp.inf and not res.ambiguous


def test_touching_tangential_is_ambiguous_miss():
    """Touching and sliding tangentially: a miss on the grazing boundary."""
    res = cr.collision(case((0, 0), (0, 1), 0, (1, 0), (0, 0), 0, 1.0))
    assert res.t == mp.inf and res.ambiguous


def test_exact_tangency_is_miss():
    """d(t) = (t - 5, 1), R = 1: g = (t - 5)^2 touches 0 at t = 5."""
    res = cr.collision(case((0, 1), (1, 0), 0, (5, 0), (0, 0), 0, 1.0))
    assert res.t == mp.inf
    assert res.ambiguous and "graze" in res.reasons


def test_exact_tangency_with_friction_is_miss():
    """Same tangency reached while A decelerates (A stops at x = 8)."""
    res = cr.collision(case((0, 1), (4, 0), 1, (5, 0), (0, 0), 0, 1.0))
    assert res.t == mp.inf and res.ambiguous


def test_equal_friction_vectors_exact():
    """Same direction and mu: relative motion linear, t = 0.5."""
    res = cr.collision(case((0, 0), (2, 0), 1, (1, 0), (1, 0), 1, 0.5))
    assert_time(res, 0.5)
    assert not res.ambiguous


def test_static_overlap_is_miss():
    """Both at rest and overlapping: nothing ever happens."""
    res = cr.collision(case((0, 0), (0, 0), 1, (0.5, 0), (0, 0), 1, 1.0))
    assert res.t == mp.inf and not res.ambiguous


def test_t_max_cut():
    """Contact at 0.75: t_max 0.76 keeps it, 0.75 or 0.5 removes it."""
    inputs = case((0, 0), (1, 0), 0, (1, 0), (0, 0), 0, 0.25)
    res = cr.collision(inputs, 0.76)
    assert_time(res, 0.75)
    assert not res.ambiguous
    res = cr.collision(inputs, 0.75)
    assert res.t == mp.inf and res.ambiguous and "t_max" in res.reasons
    res = cr.collision(inputs, 0.5)
    assert res.t == mp.inf and not res.ambiguous


def test_bad_input_rejected():
    """The reference refuses invalid inputs instead of guessing."""
    with pytest.raises(ValueError):
        cr.collision(case((0, 0), (1, 0), -1, (1, 0), (0, 0), 0, 0.25))
    with pytest.raises(ValueError):
        cr.collision(case((0, 0), (1, 0), 0, (1, 0), (0, 0), 0, 0.0))
    with pytest.raises(ValueError):
        cr.collision(case((math.nan, 0), (1, 0), 0, (1, 0), (0, 0), 0, 1.0))


# --- generated sample ----------------------------------------------------------


@pytest.fixture(scope="module")
def sample():
    """A small deterministic sample of every category, with results."""
    cases = cr.generate_cases(12345, 0.01)
    return [cr.solve_case(c) for c in cases]


def test_generation_is_deterministic():
    """Same seed, same cases."""
    assert cr.generate_cases(3, 0.005) == cr.generate_cases(3, 0.005)


def test_sample_has_every_category(sample):
    """Every category appears, with hits and misses overall."""
    names = {c.category for c, _ in sample}
    assert names == {name for name, _, _ in cr.CATEGORIES}
    assert any(r.t < mp.inf for _, r in sample)
    assert any(r.t == mp.inf for _, r in sample)


def test_contact_distance_is_radius(sample):
    """At t_ref (mp), |d| = R to 1e-40; g > 0 just before and < 0 just after."""
    checked = 0
    for c, res in sample:
        t = res.t
        if not 0 < t < mp.inf:
            continue
        pr = cr.make_problem(c.inputs)
        ax, ay = cr.ball_position(pr.a, t)
        bx, by = cr.ball_position(pr.b, t)
        dist = mp.sqrt((ax - bx) ** 2 + (ay - by) ** 2)
        assert abs(dist / pr.radius - 1) < mpf(10) ** -40, c
        h = t * mpf(10) ** -30
        assert pr.gap(t - h) > 0, c
        assert pr.gap(t + h) < 0, c
        checked += 1
    assert checked > 100


def test_t0_hits_are_touching_and_approaching(sample):
    """A collision at 0 has g(0) <= 0 and d.d' < 0."""
    for c, res in sample:
        if res.t == 0:
            pr = cr.make_problem(c.inputs)
            assert pr.gap(mpf(0)) <= 0
            assert pr.gap_slope(mpf(0)) < 0


def brute_first_entry(inputs):
    """Independent first entry: mpmath.polyroots per window, signs by probing."""
    pr = cr.make_problem(inputs)
    g0 = pr.gap(mpf(0))
    if g0 <= 0 and pr.gap_slope(mpf(0)) < 0:
        return mpf(0)
    pts = []
    for lo, hi in cr.time_windows(pr.a, pr.b):
        pts.append(lo)
        c = cr.gap_poly(pr.a, pr.b, pr.radius, lo)
        if len(c) < 2:
            continue
        with mp.workprec(500):
            roots = polyroots(list(reversed(c)), maxsteps=500, extraprec=1000)
        for r in roots:
            if abs(mp.im(r)) <= mpf(10) ** -35 * (1 + abs(r)):
                r = mp.re(r)
                if lo < r < hi:
                    pts.append(r)
    pts = sorted(set(pts))
    pts.append(2 * pts[-1] + 10)
    prev = 0
    for left, right in zip(pts, pts[1:]):
        probe = left + (right - left) * mpf(10) ** -25
        sign = 1 if pr.gap(probe) > 0 else -1
        if prev == 1 and sign == -1:
            return left
        end = right - (right - left) * mpf(10) ** -25
        prev = 1 if pr.gap(end) > 0 else -1
    return mp.inf


def test_cascade_matches_polyroots(sample):
    """The derivative cascade agrees with polyroots on a subsample."""
    rng = random.Random(5)
    subset = rng.sample(sample, 60)
    for c, res in subset:
        expected = brute_first_entry(c.inputs)
        got = res.t_unbounded
        if expected == mp.inf or got == mp.inf:
            assert expected == got, c
        else:
            assert abs(got - expected) <= mpf(10) ** -30 * (1 + expected), c


def test_floor_matches_finite_differences(sample):
    """Analytic floor vs central differences (relative step 1e-30) in mp."""
    h = mpf(10) ** -30
    hits = [(c, r) for c, r in sample if 0 < r.t < mp.inf and not r.ambiguous]
    for c, res in hits[::10][:15]:
        total = mpf(0)
        for i, x in enumerate(c.inputs):
            if x == 0:
                continue
            xs = [mpf(v) for v in c.inputs]
            xs[i] = mpf(x) * (1 + h)
            tp = cr.collision(tuple(xs)).t_unbounded
            xs[i] = mpf(x) * (1 - h)
            tm = cr.collision(tuple(xs)).t_unbounded
            total += abs((tp - tm) / (2 * h))
        fd_floor = cr.EPS * total + cr.EPS * res.t_unbounded
        assert abs(fd_floor / res.floor - 1) < 1e-20, c


def test_power_of_two_scaling_is_exact(sample):
    """Scaling every length by 2^k leaves t, floor and the flag unchanged."""
    for c, res in sample[::7]:
        for k in (-37, 5):
            scaled = cr.scaled(c, c.category, 2.0**k)
            other = cr.collision(scaled.inputs, c.t_max)
            assert other.t == res.t
            assert other.ambiguous == res.ambiguous
            assert abs(other.floor - res.floor) <= mpf(10) ** -60 * res.floor


def test_swap_symmetry(sample):
    """Swapping A and B leaves the answer unchanged."""
    for c, res in sample[::5]:
        x = c.inputs
        other = cr.collision((*x[5:10], *x[0:5], x[10]), c.t_max)
        if res.t == mp.inf:
            assert other.t == mp.inf
        else:
            assert abs(other.t - res.t) <= mpf(10) ** -60 * (1 + res.t)
        assert other.ambiguous == res.ambiguous


def test_line_format_round_trips(sample):
    """16 columns; every float column parses back to the exact value."""
    for c, res in sample[:50]:
        fields = cr.format_line(c, res).split()
        assert len(fields) == len(cr.COLUMNS)
        assert fields[0] == c.category
        assert tuple(float(f) for f in fields[1:12]) == c.inputs
        assert float(fields[12]) == c.t_max
        assert float(fields[13]) == cr.mp_to_float(res.t)
        assert fields[15] in ("0", "1")


def test_mp_to_float_rounds_to_nearest():
    """Nearest rounding, not truncation."""
    x = mpf(1) + mpf(2) ** -53 + mpf(2) ** -80
    assert cr.mp_to_float(x) == 1.0 + 2.0**-52
    assert cr.mp_to_float(mpf(1) + mpf(2) ** -54) == 1.0


DATA = os.path.join(os.path.dirname(__file__), "..", "tests", "data")


@pytest.mark.skipif(
    not os.path.exists(os.path.join(DATA, "collision_cases.txt")),
    reason="data file not generated",
)
def test_data_file_agrees_with_reference():
    """The committed data file is well formed and matches the code on a sample."""
    path = os.path.join(DATA, "collision_cases.txt")
    with open(path, encoding="ascii") as fh:
        rows = [ln.split() for ln in fh if ln.strip() and not ln.startswith("#")]
    assert len(rows) >= 20000
    assert {r[0] for r in rows} == {name for name, _, _ in cr.CATEGORIES}
    for row in random.Random(1).sample(rows, 40):
        assert len(row) == len(cr.COLUMNS)
        inputs = tuple(float(f) for f in row[1:12])
        res = cr.collision(inputs, float(row[12]))
        assert float(row[13]) == cr.mp_to_float(res.t)
        assert row[14] == cr.fmt_floor(res.floor)
        assert row[15] == ("1" if res.ambiguous else "0")
