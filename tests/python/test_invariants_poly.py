"""real_roots over the whole float range (hypothesis): roots sorted and never NaN, each a root
within a backward-error bound by exact rational evaluation (or within an ulp of one), none
lost (exact signs between them), and the same bits under ±0 flips and power-of-two scalings of
the coefficients. The Rust fuzz target ``poly`` and tests/integration/invariants_poly.rs check
the same."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
from hypothesis import given, note
from hypothesis import strategies as st
from invariant_strategies import (
    INF,
    case_scale,
    flip_zero,
    ldexp,
    same,
    scaled_exactly,
    small,
    wide,
)

import ballcollide as bc

# A root's backward error may be up to 8^4 roundings (8 floors for a 4-fold root).
ROUNDINGS = 4096
EPS = Fraction(1, 2**53)


def coefficient(s: int) -> st.SearchStrategy[float]:
    return st.one_of(
        wide,
        st.builds(lambda x, k: ldexp(x, s + k), small, st.integers(-1100, 1100)),
        small.map(lambda x: ldexp(x, s)),
    )


polys = case_scale.flatmap(lambda s: st.lists(coefficient(s), min_size=2, max_size=5)).filter(
    lambda c: all(math.isfinite(x) for x in c)
)


def value_and_size(c: list[float], x: float) -> tuple[Fraction, Fraction]:
    fx = Fraction(x)
    n = len(c) - 1
    terms = [Fraction(ci) * fx ** (n - i) for i, ci in enumerate(c)]
    return sum(terms, Fraction(0)), sum((abs(t) for t in terms), Fraction(0))


def sign(c: list[float], x: float) -> int:
    v, _ = value_and_size(c, x)
    return (v > 0) - (v < 0)


def near_zero(c: list[float], x: float) -> bool:
    v, size = value_and_size(c, x)
    return abs(v) <= ROUNDINGS * EPS * size


def roots_of(c: list[float]) -> list[float]:
    row = bc.real_roots(np.array([c], dtype=np.float64))[0]
    return [float(x) for x in row if not math.isnan(x)]


def check(c: list[float]) -> list[float]:
    r = roots_of(c)
    assert r == sorted(r), f"roots {r!r} of {c!r}"
    p = c[next((i for i, x in enumerate(c) if x != 0.0), len(c)) :]
    if len(p) <= 1:
        assert r == []
        return r
    assert len(r) <= len(p) - 1
    for x in r:
        if math.isinf(x):
            continue
        ok = (
            near_zero(p, x)
            or sign(p, math.nextafter(x, -INF)) * sign(p, math.nextafter(x, INF)) <= 0
        )
        assert ok, f"{x!r} is not a root within {ROUNDINGS} roundings"
    # No root lost: sample points beyond every root (Fujiwara's bound) and inside every gap.
    e = [math.frexp(abs(x))[1] for x in p]
    n = len(p) - 1
    bound = max((math.ceil((e[d] - e[0] + 1) / d) for d in range(1, n + 1) if p[d]), default=0) + 2
    far = ldexp(1.0, bound) if bound <= 1023 else 1.7976931348623157e308
    marks = sorted({-far, far, *(x for x in r if math.isfinite(x) and abs(x) < far)})
    samples: list[tuple[float, bool]] = []
    for w, (lo, hi) in enumerate(zip(marks, marks[1:])):
        pts = [lo] if w == 0 else []
        for f in (0.125, 0.5, 0.875):
            x = lo * (1 - f) + hi * f
            if lo < x < hi and (not pts or pts[-1] < x):
                pts.append(x)
        if w == len(marks) - 2:
            pts.append(hi)
        samples += [(x, i == 0 and w > 0) for i, x in enumerate(pts)]
    for (x0, _), (x1, root_between) in zip(samples, samples[1:]):
        if not root_between and sign(p, x0) * sign(p, x1) < 0:
            assert near_zero(p, x0) or near_zero(p, x1), f"a root lost between {x0!r} and {x1!r}"
    return r


@given(polys, st.integers(-1100, 1100))
def test_real_roots_keep_their_invariants(c: list[float], k: int) -> None:
    note(f"coefficients {c!r}")
    r = check(c)
    flipped = roots_of([flip_zero(x) for x in c])
    assert all(same(x, y) for x, y in zip(r, flipped)) and len(r) == len(flipped)
    scaled = [scaled_exactly(x, k) for x in c]
    if all(x is not None for x in scaled):
        rs = roots_of(scaled)
        assert len(rs) == len(r) and all(same(x, y) for x, y in zip(r, rs)), f"2^{k}: {rs!r}"


def test_tiny_odd_degree_coefficients_keep_the_roots() -> None:
    # issue 21 item 4.
    r = roots_of([-5.18e-05, 0.0, 934.0, 1e-200, -0.01466])
    assert np.allclose(
        r,
        [-4246.279316162837, -0.003961809116745748, 0.003961809116745748, 4246.279316162837],
        rtol=1e-15,
        atol=0,
    )
    r = roots_of([0.5, 0.0, 2e-120, 1.3e-308, -4e-7])
    assert np.allclose(r, [-0.02990697562442441, 0.02990697562442441], rtol=1e-15, atol=0)
    for c in ([-5.18e-05, 0.0, 934.0, 1e-200, -0.01466], [0.5, 0.0, 2e-120, 1.3e-308, -4e-7]):
        check(c)
