"""collision_time over the whole float range (hypothesis): valid input never raises, no NaN or
negative time, a horizon only cuts, and A/B swap, ±0 flips and power-of-two scalings of lengths
and of time change no bit. The Rust fuzz target ``pair`` and
tests/integration/invariants_pair.rs check the same."""

from __future__ import annotations

import math

from hypothesis import given, note
from hypothesis import strategies as st
from invariant_strategies import (
    INF,
    LATEST,
    Pair,
    flip_zero,
    pairs,
    same,
    scaled_exactly,
    time,
)


@given(pairs, st.integers(-1100, 1100), st.integers(-600, 600))
def test_the_pair_search_keeps_its_invariants(case: Pair, k: int, m: int) -> None:
    if not case.valid():
        return
    note(repr(case))
    a, b, r, horizon = case.a, case.b, case.radius, case.t_max
    free = time(a, b, r)
    cut = time(a, b, r, horizon)
    assert free == INF or free < INF
    assert same(cut, free if free < horizon else INF), f"horizon {horizon!r}: {free!r} → {cut!r}"
    if free < INF:
        for h in (math.nextafter(free, INF), free * 1.5, free + 1.0, 10.0, 1e10, 1e300):
            want = free if free < h else INF
            assert same(time(a, b, r, h), want), f"horizon {h!r} moved {free!r}"
    assert same(time(b, a, r, horizon), cut), "A/B swap"
    z = a.map(flip_zero, flip_zero, flip_zero), b.map(flip_zero, flip_zero, flip_zero)
    assert z[0] is not None and z[1] is not None
    assert same(time(z[0], z[1], r, flip_zero(horizon)), cut), "−0.0 = +0.0"

    def sl(x: float) -> float | None:
        return scaled_exactly(x, k)

    sa, sb, sr = a.map(sl, sl, sl), b.map(sl, sl, sl), sl(r)
    if sa is not None and sb is not None and sr is not None:
        assert same(time(sa, sb, sr), free), f"lengths scaled by 2^{k} (no horizon)"
        assert same(time(sa, sb, sr, horizon), cut), f"lengths scaled by 2^{k}"

    def same_pos(x: float) -> float:
        return x

    ta = a.map(same_pos, lambda v: scaled_exactly(v, m), lambda mu: scaled_exactly(mu, 2 * m))
    tb = b.map(same_pos, lambda v: scaled_exactly(v, m), lambda mu: scaled_exactly(mu, 2 * m))
    th = horizon if horizon == INF else scaled_exactly(horizon, -m)
    want = cut if cut == INF else scaled_exactly(cut, -m)
    want_free = free if free == INF else scaled_exactly(free, -m)
    # Units of time are promised within 2^±30, for pairs whose non-zero magnitudes are within
    # 2^±400 of each other (docs/contract.md §5; tests/support/invariants.rs does the same).
    sizes = [abs(x) for x in (a.px, a.py, a.vx, a.vy, a.mu, b.px, b.py, b.vx, b.vy, b.mu, r)]
    sizes = [x for x in sizes if x > 0.0]
    if (
        abs(m) <= 30
        and max(sizes) <= min(sizes) * 2.0**400
        and ta is not None
        and tb is not None
        and th is not None
        and want is not None
        and want_free is not None
        and (want == INF or want < LATEST)
        and (want_free == INF or want_free < LATEST)
    ):
        assert same(time(ta, tb, r, th), want), f"time scaled by 2^{m}"


def test_issue21_reproducers() -> None:
    # item 1: friction −0.0; item 2: a long window; item 3: extreme length scales.
    def pair(p: float, v: float, mu: float, q: float, w: float, r: float, h: float) -> Pair:
        from invariant_strategies import Ball

        return Pair(Ball(p, 0.0, v, 0.0, mu), Ball(q, 0.0, w, 0.0, 0.0), r, h)

    assert time(*_args(pair(0.0, 1.0, -0.0, 3.0, -1.0, 1.0, INF))) == 1.0
    assert time(*_args(pair(0.0, 1.0, 0.0, 3.0, -1.0, 1.0, 1e100))) == 1.0
    for s in (1e-300, 1e160):
        assert time(*_args(pair(s, -s, 0.0, -s, s, s, INF))) == 0.5


def _args(p: Pair) -> tuple:
    return (p.a, p.b, p.radius, p.t_max)
