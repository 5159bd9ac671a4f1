"""Self-checks of the mpmath path reference (tools/path_reference.py).

Run with ``python -m pytest tools/test_path_reference.py -q``.
"""

from __future__ import annotations

import math
import os
import random
import sys

import pytest
from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import collision_reference as cr
import path_reference as pr

TIGHT = mpf(2) ** -200
SEED = 4242
INF = mp.inf


def seg(s, p, v, a=None):
    """A segment with float components (a defaults to zero)."""
    p = tuple(float(x) for x in p)
    return (float(s), p, tuple(float(x) for x in v), tuple(float(x) for x in (a or (0,) * len(p))))


def solve(a, b, radius, t_max=math.inf, dim=None):
    """Reference answer for two paths given as lists of segments."""
    dim = dim or len(a[0][1])
    return pr.collision(dim, tuple(a), tuple(b), float(radius), t_max)


def assert_time(res, expected, rel=TIGHT):
    """The reference time equals `expected` (mp or float) to `rel`."""
    expected = mpf(expected)
    assert abs(res.t - expected) <= rel * max(abs(expected), mpf(1)), (
        mp.nstr(res.t, 40),
        mp.nstr(expected, 40),
    )


# --- hand-computable cases ---------------------------------------------------


def test_head_on_constant_velocity():
    """t = (distance - R) / closing speed, from the exact binary inputs."""
    a = [seg(0, (0.1, 0.2), (0.7, 0.0))]
    b = [seg(0, (1.3, 0.2), (-0.4, 0.0))]
    res = solve(a, b, cr.R_TABLE)
    expected = (mpf(1.3) - mpf(0.1) - mpf(cr.R_TABLE)) / (mpf(0.7) + mpf(0.4))
    assert_time(res, expected)
    assert res.kind == "root" and not res.ambiguous
    assert 0 < res.floor < 1e-14


def test_late_start_keeps_absolute_time():
    """The same shot starting at 1e4 (B earlier, at rest): t = 1e4 + 1.5."""
    a = [seg(1e4, (0, 0), (1, 0))]
    b = [seg(9998.5, (2, 0), (0, 0))]
    res = solve(a, b, 0.5)
    assert_time(res, mpf(10001.5))
    # The floor is dominated by the start's rounding: eps * 1e4 (dt/ds = 1) + eps * t.
    assert 1.5 * pr.EPS * 1e4 < res.floor < 3 * pr.EPS * 1e4


def test_constant_deceleration_hit():
    """x_A = 2t - t^2/2 (a = -1), B at rest at 2.125, R = 0.25: t = 1.5."""
    a = [seg(0, (0, 0), (2, 0), (-1, 0)), seg(2, (2, 0), (0, 0))]
    b = [seg(0, (2.125, 0), (0, 0))]
    res = solve(a, b, 0.25)
    assert_time(res, 1.5)
    assert not res.ambiguous


def test_root_exactly_at_a_segment_start():
    """Splitting a = -1/2 at t = 1 (x = 0.75, v = 0.5): contact exactly at t = 1, both ways."""
    whole = [seg(0, (0, 0), (1, 0), (-0.5, 0))]
    split = [seg(0, (0, 0), (1, 0), (-0.5, 0)), seg(1, (0.75, 0), (0.5, 0), (-0.5, 0))]
    b = [seg(0, (1.25, 0), (0, 0))]
    r1, r2 = solve(whole, b, 0.5), solve(split, b, 0.5)
    assert_time(r1, 1)
    assert_time(r2, 1)
    assert r2.kind == "root" and not r2.ambiguous
    assert abs(r1.floor - r2.floor) <= 1e-3 * r1.floor


def test_split_segment_same_answer():
    """A generic shot with A's segment split at a dyadic time: the same time."""
    whole = [seg(0, (0, 0), (1, 0), (-0.5, 0))]
    split = [seg(0, (0, 0), (1, 0), (-0.5, 0)), seg(0.5, (0.4375, 0), (0.75, 0), (-0.5, 0))]
    b = [seg(0, (1.3, 0.1), (-0.2, 0))]
    r1, r2 = solve(whole, b, 0.5), solve(split, b, 0.5)
    assert r1.t < INF
    assert abs(r1.t - r2.t) <= TIGHT


def test_jump_into_overlap_at_a_segment_start():
    """B jumps from (5, 0) to (0.5, 0) at s = 2 next to A at rest (R = 1): t = 2."""
    a = [seg(0, (0, 0), (0, 0))]
    b = [seg(0, (5, 0), (0, 0)), seg(2, (0.5, 0), (0, 0))]
    res = solve(a, b, 1.0)
    assert res.t == 2 and res.kind == "jump" and not res.ambiguous
    # dt/ds = 1 for the one jumping start, plus the output rounding.
    assert res.floor == 2 * pr.EPS * 2


def test_jump_out_of_reach_is_no_contact():
    """B jumps from far to just outside (R (1 + 1e-3)): no contact."""
    a = [seg(0, (0, 0), (0, 0))]
    b = [seg(0, (5, 0), (0, 0)), seg(2, (1.001, 0), (0, 0))]
    res = solve(a, b, 1.0)
    assert res.t == INF and not res.ambiguous


def test_tangency_is_not_a_collision():
    """A passes B at exactly the contact distance: a tangency, no collision (ambiguous)."""
    a = [seg(0, (0, 0), (1, 0))]
    b = [seg(0, (5, 1), (0, 0))]
    res = solve(a, b, 1.0)
    assert res.t == INF and res.ambiguous and "graze" in res.reasons


def test_tangency_at_a_bounce():
    """A bounces off a wall at x = 1 exactly touching B at (2, 0): a kink tangency."""
    a = [seg(0, (0, 0), (1, 0)), seg(1, (1, 0), (-1, 0))]
    b = [seg(0, (2, 0), (0, 0))]
    res = solve(a, b, 1.0)
    assert res.t == INF and res.ambiguous and "graze" in res.reasons


def test_separating_overlap_at_t_from_is_not_a_collision():
    """Overlapping at t_from while separating, never again: no collision."""
    a = [seg(0, (0, 0), (-1, 0))]
    b = [seg(0, (0.5, 0), (1, 0))]
    res = solve(a, b, 1.0)
    assert res.t == INF and not res.ambiguous


def test_separating_overlap_then_reentry():
    """B flees at speed 1, decelerating at 1: d = 0.5 + t - t^2/2 from A at rest, R = 0.9.

    Overlapping and separating at t = 0, out at 1 - sqrt(0.2), back in at
    t = 1 + sqrt(1 - 2 (R - 0.5)).
    """
    a = [seg(0, (0, 0), (0, 0))]
    b = [seg(0, (0.5, 0), (1, 0), (-1, 0))]
    res = solve(a, b, 0.9)
    assert_time(res, 1 + mp.sqrt(1 - 2 * (mpf(0.9) - mpf(0.5))))
    assert res.kind == "root" and not res.ambiguous


def test_approaching_touch_at_t_from_is_a_hit_at_t_from():
    """Touching (|d| = R exactly) and approaching at t_from = 3 (B started earlier)."""
    a = [seg(3, (0, 0), (1, 0))]
    b = [seg(1, (1, 0), (0, 0))]
    res = solve(a, b, 1.0)
    assert res.t == 3 and res.kind == "t_from" and not res.ambiguous
    assert res.floor > pr.EPS * 3


def test_overlap_approaching_at_t_from_floor_is_the_start():
    """A real overlap, approaching: t = t_from with floor eps |t_from|."""
    a = [seg(2, (0, 0), (1, 0))]
    b = [seg(2, (0.5, 0), (0, 0))]
    res = solve(a, b, 1.0)
    assert res.t == 2 and res.floor == pr.EPS * 2


def test_touch_at_rest_accelerating_together_is_a_hit():
    """Touching at rest, A accelerating towards B: g' = 0, g'' < 0: a hit at t_from."""
    a = [seg(0, (0, 0), (0, 0), (1, 0))]
    b = [seg(0, (1, 0), (0, 0))]
    res = solve(a, b, 1.0)
    assert res.t == 0 and res.kind == "t_from" and not res.ambiguous


def test_touch_at_rest_accelerating_apart_is_a_miss():
    """Touching at rest, A accelerating away: no collision, and no input could change that."""
    a = [seg(0, (0, 0), (0, 0), (-1, 0))]
    b = [seg(0, (1, 0), (0, 0))]
    res = solve(a, b, 1.0)
    assert res.t == INF and not res.ambiguous


def test_touching_tangential_is_ambiguous():
    """Touching while moving tangentially: approach undecidable, ambiguous."""
    a = [seg(0, (0, 0), (0, 1))]
    b = [seg(0, (1, 0), (0, 0))]
    res = solve(a, b, 1.0)
    assert res.ambiguous and "touch_t0" in res.reasons


def test_equal_gravity_falling_together_3d():
    """Same velocity and gravity, apart or exactly touching: no contact, not ambiguous."""
    g = (0, 0, -9.81)
    for dx in (0.5, 0.25):
        a = [seg(0, (0, 0, 10), (1, 0, 2), g)]
        b = [seg(0, (dx, 0, 10), (1, 0, 2), g)]
        res = solve(a, b, 0.25)
        assert res.t == INF and not res.ambiguous


def test_equal_gravity_3d_hit():
    """Under the same gravity the relative motion is linear: t = (1 - 0.25) / 1.5 = 0.5."""
    g = (0, 0, -9.81)
    a = [seg(0, (0, 0, 10), (1.5, 0, 2), g)]
    b = [seg(0, (1, 0, 10), (0, 0, 2), g)]
    res = solve(a, b, 0.25)
    assert_time(res, 0.5)


def test_t_max_cut():
    """Head-on at t = 1.5: t_max = 1.5 cuts it (t >= t_max is none), 1.6 keeps it."""
    a = [seg(0, (0, 0), (1, 0))]
    b = [seg(0, (2, 0), (0, 0))]
    assert solve(a, b, 0.5, 1.5).t == INF
    assert solve(a, b, 0.5, 1.4).t == INF
    res = solve(a, b, 0.5, 1.6)
    assert_time(res, 1.5)
    assert solve(a, b, 0.5, 1.5).ambiguous


def test_empty_segment_is_skipped():
    """A zero-length segment (start = next start) is never active."""
    a = [seg(0, (0, 0), (1, 0)), seg(1, (50, 50), (9, 9)), seg(1, (1, 0), (1, 0))]
    b = [seg(0, (2, 0), (0, 0))]
    assert_time(solve(a, b, 0.5), 1.5)


def test_bad_input_rejected():
    """Malformed paths raise ValueError."""
    good = [seg(0, (0, 0), (1, 0))]
    with pytest.raises(ValueError):
        solve([seg(1, (0, 0), (1, 0)), seg(0, (0, 0), (1, 0))], good, 1.0)
    with pytest.raises(ValueError):
        solve(good, [seg(0, (math.nan, 0), (1, 0))], 1.0)
    with pytest.raises(ValueError):
        solve(good, good, 0.0)
    with pytest.raises(ValueError):
        pr.collision(2, tuple(good), (seg(0, (0, 0, 0), (0, 0, 0)),), 1.0)


# --- the seed model as paths against collision_reference -----------------------


def test_seed_friction_agrees_with_collision_reference():
    """Two codes: seed balls as paths here, as balls in collision_reference."""
    rng = random.Random(SEED)
    cases = pr.gen_seed_friction(rng, 80)
    compared = hits = 0
    for case in cases:
        (pa, va, fa), (pb, vb, fb) = case.meta
        ref = cr.collision((*pa, *va, fa, *pb, *vb, fb, case.radius))
        res = pr.collision(2, case.a, case.b, case.radius)
        if res.ambiguous or ref.ambiguous:
            continue
        compared += 1
        assert (res.t < INF) == (ref.t < INF), case
        if res.t < INF:
            hits += 1
            tol = 4 * (res.floor + ref.floor)
            assert abs(res.t - ref.t) <= tol, (mp.nstr(res.t, 20), mp.nstr(ref.t, 20))
    assert compared >= 70 and hits >= 20


# --- a generated sample ----------------------------------------------------------


@pytest.fixture(scope="module")
def sample():
    """A small generated sample with its reference answers."""
    return [pr.solve_case(c) for c in pr.generate_cases(SEED, 0.004)]


def test_sample_has_every_category(sample):
    """Every category is generated (and generation is deterministic)."""
    assert {c.category for c, _ in sample} == {name for name, _, _ in pr.CATEGORIES}
    assert pr.generate_cases(3, 0.002) == pr.generate_cases(3, 0.002)


def test_floors_positive_for_hits(sample):
    """Hits have a positive finite floor (unless flagged), misses a zero floor.

    The one exception: an overlap hit at t_from = 0, which is exact (floor 0).
    """
    for case, res in sample:
        if res.t < INF:
            assert res.floor > 0 or (res.kind == "t_from" and res.t == 0), case
            assert res.floor < INF or res.ambiguous
            t_from = max(case.a[0][0], case.b[0][0])
            assert res.t >= t_from
        else:
            assert res.floor == 0


def exact_gap(case, t):
    """g(t) in mp straight from the segment formulas (written here, not pr's)."""
    d2 = mpf(0)
    xs = []
    for path in (case.a, case.b):
        k = max(i for i, s in enumerate(path) if mpf(s[0]) <= t or i == 0)
        s, p, v, a = path[k]
        tau = t - mpf(s)
        xs.append(
            [mpf(pj) + mpf(vj) * tau + mpf(aj) * tau * tau / 2 for pj, vj, aj in zip(p, v, a)]
        )
    for x, y in zip(*xs):
        d2 += (x - y) ** 2
    return d2 - mpf(case.radius) ** 2


def test_brute_force_grid_finds_no_earlier_entry(sample):
    """A fine grid of g (plus every segment start) shows no + to - before t_ref.

    For hits, g is negative just after t_ref; for misses the grid runs to 2 s
    past the last segment start.
    """
    checked = 0
    for case, res in sample:
        if res.ambiguous or case.t_max < math.inf:
            continue
        t_from = mpf(max(case.a[0][0], case.b[0][0]))
        if res.t < INF:
            end = res.t
        else:
            end = max(mpf(s[0]) for s in (*case.a, *case.b)) + 2
        if end <= t_from or checked >= 45:
            continue
        starts = [mpf(s[0]) for s in (*case.a, *case.b) if t_from < s[0] < end]
        grid = sorted({t_from + (end - t_from) * i / 400 for i in range(400)} | set(starts))
        signs = [1 if exact_gap(case, t) > 0 else -1 for t in grid if t < end]
        for s0, s1 in zip(signs, signs[1:]):
            assert not (s0 > 0 and s1 < 0), case
        if res.t < INF:
            after = res.t + mp.ldexp(max(abs(res.t), mpf(1)), -120)
            assert exact_gap(case, after) < 0, case
        checked += 1
    assert checked >= 40


def test_floor_matches_finite_differences(sample):
    """floor ~ eps sum |t(x_i (1 + eps)) - t| + eps |t| for interior roots."""
    checked = 0
    for case, res in sample:
        if res.kind != "root" or res.t == INF or res.ambiguous or checked >= 6:
            continue
        paths = [list(case.a), list(case.b)]
        total = mpf(0)
        for which in (0, 1):
            path = paths[which]
            k = max(i for i, s in enumerate(path) if mpf(s[0]) <= res.t)
            for j in range(1 + 3 * case.dim):
                flat = [path[k][0], *path[k][1], *path[k][2], *path[k][3]]
                if flat[j] == 0.0:
                    continue
                bumped = list(flat)
                bumped[j] = flat[j] * (1 + 2.0**-40)
                d = case.dim
                new = (bumped[0], tuple(bumped[1 : 1 + d]), tuple(bumped[1 + d : 1 + 2 * d]))
                new = (*new, tuple(bumped[1 + 2 * d :]))
                trial = [list(p) for p in paths]
                trial[which][k] = new
                r2 = pr.collision(d, tuple(trial[0]), tuple(trial[1]), case.radius)
                total += abs(r2.t - res.t) / 2**-40 * pr.EPS
        r3 = pr.collision(case.dim, case.a, case.b, case.radius * (1 + 2.0**-40))
        total += abs(r3.t - res.t) / 2**-40 * pr.EPS + pr.EPS * abs(res.t)
        assert abs(total - res.floor) <= 0.05 * res.floor, (total, res.floor, case)
        checked += 1
    assert checked >= 3


def test_swap_symmetry(sample):
    """Swapping A and B gives the same time, floor and flag."""
    for case, res in sample[::5]:
        r2 = pr.collision(case.dim, case.b, case.a, case.radius, case.t_max)
        assert abs(r2.t - res.t) <= TIGHT * max(abs(res.t), 1) or r2.t == res.t
        assert r2.ambiguous == res.ambiguous


def test_power_of_two_scaling_is_exact(sample):
    """Lengths times 2^-7: the same time to the root accuracy, the floor scales not."""
    for case, res in sample[::7]:
        a, b = pr.scale_path(case.a, 2.0**-7), pr.scale_path(case.b, 2.0**-7)
        r2 = pr.collision(case.dim, a, b, case.radius * 2.0**-7, case.t_max)
        assert r2.t == res.t or abs(r2.t - res.t) <= mpf(2) ** -240 * max(abs(res.t), 1)
        assert r2.ambiguous == res.ambiguous


def test_2d_embedded_in_3d_gives_the_2d_answer(sample):
    """A 2-D case on the plane z = 0.75 in 3-D: the same time, floor and flag."""
    for case, res in sample:
        if case.dim != 2:
            continue
        a, b = pr.embed3(case.a, 0.75), pr.embed3(case.b, 0.75)
        r3 = pr.collision(3, a, b, case.radius, case.t_max)
        assert r3.t == res.t or abs(r3.t - res.t) <= mpf(2) ** -240 * max(abs(res.t), 1)
        assert r3.ambiguous == res.ambiguous
        assert r3.floor == res.floor or abs(r3.floor - res.floor) <= 1e-6 * res.floor


def test_main_writes_a_readable_file(tmp_path):
    """The command line writes a file that read_cases parses back."""
    out = tmp_path / "cases.txt"
    assert (
        pr.main(["--fraction", "0.0005", "--seed", "9", "--processes", "1", "--out", str(out)]) == 0
    )
    cases = pr.read_cases(str(out))
    assert len(cases) == len(pr.CATEGORIES)
    for c in cases:
        res = pr.collision(c.dim, c.a, c.b, c.radius, c.t_max)
        assert pr.mp_to_float(res.t) == c.t_ref and res.ambiguous == c.ambiguous


def test_line_format_round_trips(sample):
    """format_line then parse_line gives back the exact inputs."""
    for case, res in sample:
        parsed = pr.parse_line(pr.format_line(case, res))
        assert (parsed.category, parsed.dim, parsed.a, parsed.b) == (
            case.category,
            case.dim,
            case.a,
            case.b,
        )
        assert parsed.radius == case.radius and parsed.t_max == case.t_max
        assert parsed.t_ref == pr.mp_to_float(res.t) and parsed.ambiguous == res.ambiguous


DATA = os.path.normpath(pr.DEFAULT_OUT)


@pytest.mark.skipif(not os.path.exists(DATA), reason="data file not generated")
def test_data_file_parses_and_header_matches():
    """The committed file: header as written by the script, every line parses."""
    with open(DATA, encoding="ascii") as fh:
        head = [line.rstrip("\n") for line in fh if line.startswith("#")]
    n = int(head[1].split()[1])
    seed = int(head[1].split()[4].rstrip(";"))
    assert head == pr.header(seed, n)
    cases = pr.read_cases(DATA)
    assert len(cases) == n >= 20000
    counts = {}
    for c in cases:
        counts[c.category] = counts.get(c.category, 0) + 1
        t_from = max(c.a[0][0], c.b[0][0])
        assert c.t_ref == math.inf or t_from <= c.t_ref <= c.t_max
        # The exact time is < t_max; only its rounding can reach t_max, in the band.
        assert c.t_ref == math.inf or c.t_ref < c.t_max or c.ambiguous
        assert c.floor >= 0
    assert set(counts) == {name for name, _, _ in pr.CATEGORIES}
    assert min(counts.values()) >= 1000


@pytest.mark.skipif(not os.path.exists(DATA), reason="data file not generated")
def test_data_file_is_what_the_generator_writes():
    """The committed inputs are those of generate_cases for the header's seed."""
    with open(DATA, encoding="ascii") as fh:
        seed = int(fh.readlines()[1].split()[4].rstrip(";"))
    cases = pr.read_cases(DATA)
    generated = pr.generate_cases(seed)
    assert len(cases) == len(generated)
    for c, g in zip(cases, generated):
        assert (c.category, c.dim, c.a, c.b, c.radius) == (g.category, g.dim, g.a, g.b, g.radius)
        assert g.t_max_rule is not None or c.t_max == g.t_max


@pytest.mark.skipif(not os.path.exists(DATA), reason="data file not generated")
def test_data_file_lines_recompute():
    """A few lines of the file, recomputed from their parsed inputs, match."""
    cases = pr.read_cases(DATA)
    for c in cases[:: len(cases) // 25]:
        res = pr.collision(c.dim, c.a, c.b, c.radius, c.t_max)
        assert pr.mp_to_float(res.t) == c.t_ref
        assert res.ambiguous == c.ambiguous
