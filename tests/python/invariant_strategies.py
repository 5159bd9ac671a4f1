"""Hypothesis strategies over the whole float range, and the checks shared by the invariant tests.

The same kinds of numbers as the Rust fuzz targets and property tests (docs/fuzzing.md):
exponents from -1074 to 1023, both zeros, small dyadic numbers i/2^j (which make contacts
likely) and table-sized numbers with full mantissas, multiplied by one power of two per
case, so that a whole configuration can sit at 2^±500.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from hypothesis import strategies as st

import ballcollide as bc

INF = math.inf

# Contacts later than this are not reported (docs/contract.md): time scalings are checked
# only below it.
LATEST = 1e301


def ldexp(x: float, k: int) -> float:
    """x·2^k, or ±inf where that overflows (math.ldexp raises instead)."""
    try:
        return math.ldexp(x, k)
    except OverflowError:
        return math.copysign(INF, x)


def scaled_exactly(x: float, k: int) -> float | None:
    """x·2^k if that is exact (finite, and back to x when scaled back), else None."""
    y = ldexp(x, k)
    if not math.isfinite(y) or ldexp(y, -k) != x or math.copysign(1, y) != math.copysign(1, x):
        return None
    return y


def flip_zero(x: float) -> float:
    return -x if x == 0.0 else x


def same(x: float, y: float) -> bool:
    """The same float, bit for bit (±0 told apart)."""
    return (x == y and math.copysign(1, x) == math.copysign(1, y)) or (x != x and y != y)


wide = st.floats(allow_nan=False, allow_infinity=False)
small = st.one_of(
    st.sampled_from([0.0, -0.0]),
    st.builds(lambda i, j: i / 2**j, st.integers(-(2**14), 2**14), st.integers(0, 8)),
)
# Numbers of a table's size with full mantissas.
table = st.builds(lambda x, neg: -x if neg else x, st.floats(0.0625, 4.0), st.booleans())
case_scale = st.one_of(st.just(0), st.integers(-1074, 1023))


def length(s: int) -> st.SearchStrategy[float]:
    return st.one_of(wide, table.map(lambda x: ldexp(x, s)), small.map(lambda x: ldexp(x, s)))


def friction(s: int) -> st.SearchStrategy[float]:
    return st.one_of(
        st.sampled_from([0.0, -0.0]),
        small.map(lambda x: ldexp(abs(x), s)),
        st.builds(lambda x, k: ldexp(abs(x), s + k), small, st.integers(-200, 40)),
        wide.map(abs),
    )


def radius(s: int) -> st.SearchStrategy[float]:
    def positive(r: float) -> float:
        return r if r > 0.0 and math.isfinite(r) else ldexp(1.0, s)

    return st.one_of(wide.map(abs), small.map(lambda x: ldexp(abs(x), s))).map(positive)


t_max = st.one_of(
    st.just(INF),
    st.sampled_from([0.0, -0.0]),
    small.map(abs),
    st.integers(10, 300).map(lambda e: 10.0**e),
    wide.map(abs),
)


@dataclass(frozen=True)
class Ball:
    px: float
    py: float
    vx: float
    vy: float
    mu: float

    def valid(self) -> bool:
        nums = (self.px, self.py, self.vx, self.vy, self.mu)
        return all(math.isfinite(v) for v in nums) and self.mu >= 0.0

    def map(self, pos, vel, mu) -> Ball | None:
        p = [pos(self.px), pos(self.py)]
        v = [vel(self.vx), vel(self.vy)]
        m = mu(self.mu)
        if any(x is None for x in (*p, *v, m)):
            return None
        return Ball(p[0], p[1], v[0], v[1], m)


def ball(s: int) -> st.SearchStrategy[Ball]:
    return st.builds(Ball, length(s), length(s), length(s), length(s), friction(s))


@dataclass(frozen=True)
class Pair:
    a: Ball
    b: Ball
    radius: float
    t_max: float

    def valid(self) -> bool:
        return (
            self.a.valid()
            and self.b.valid()
            and math.isfinite(self.radius)
            and self.radius > 0.0
            and self.t_max >= 0.0
        )


def pair_at(s: int) -> st.SearchStrategy[Pair]:
    return st.builds(Pair, ball(s), ball(s), radius(s), t_max)


pairs = case_scale.flatmap(pair_at)


def time(a: Ball, b: Ball, r: float, horizon: float = INF) -> float:
    """collision_time for valid input (an error is a failure of the invariant)."""
    t = bc.collision_time(
        (a.px, a.py), (a.vx, a.vy), a.mu, (b.px, b.py), (b.vx, b.vy), b.mu, r, t_max=horizon
    )
    assert not math.isnan(t) and t >= 0.0, f"time {t} for {a} {b} {r} {horizon}"
    return t
