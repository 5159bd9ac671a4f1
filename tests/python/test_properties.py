"""Property tests (hypothesis): invariances of the collision time, and robustness on any input.

The invariances hold exactly for the exact collision time; in float64 they hold to within the
answer's conditioning. Each case estimates it by moving the radius by ±1e-7 (relative): a
case whose hit/miss status changes there is near a grazing contact, where either answer is
acceptable, and is discarded; otherwise the change of the time bounds how much rounding the
transformed inputs can move it.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import assume, event, given, note
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

import ballcollide as bc

EPS = 2.0**-52


def _clean(x: float) -> float:
    # No subnormal or tiny-but-nonzero coordinates: they would underflow when scaled.
    return x if abs(x) > 1e-150 else 0.0


coordinate = st.floats(-2.0, 2.0).map(_clean)
component = st.floats(-3.0, 3.0).map(_clean)
friction = st.one_of(st.just(0.0), st.floats(1e-3, 2.0))
radius = st.floats(0.01, 0.5)


@dataclass(frozen=True)
class Pair:
    pa: np.ndarray
    va: np.ndarray
    fa: float
    pb: np.ndarray
    vb: np.ndarray
    fb: float
    r: float

    def time(self) -> float:
        return bc.collision_time(self.pa, self.va, self.fa, self.pb, self.vb, self.fb, self.r)

    def map_vectors(self, f) -> Pair:
        return replace(self, pa=f(self.pa), va=f(self.va), pb=f(self.pb), vb=f(self.vb))


@st.composite
def pairs(draw) -> Pair:
    pa = np.array([draw(coordinate), draw(coordinate)])
    va = np.array([draw(component), draw(component)])
    fa = draw(friction)
    vb = np.zeros(2) if draw(st.booleans()) else np.array([draw(component), draw(component)])
    fb = draw(friction)
    r = draw(radius)
    if draw(st.booleans()):
        # Aim: B near where A is at time s (allowing for B's own motion), within 1.5 radii.
        s = draw(st.floats(0.05, 1.5))
        a_then = bc.positions_at(pa[None], va[None], fa, s)[0]
        b_moves = bc.positions_at(np.zeros((1, 2)), vb[None], fb, s)[0]
        offset = np.array([draw(st.floats(-1.5, 1.5)), draw(st.floats(-1.5, 1.5))]) * r
        pb = a_then - b_moves + offset
    else:
        pb = np.array([draw(coordinate), draw(coordinate)])
    return Pair(pa, va, fa, pb, vb, fb, r)


def conditioned(p: Pair) -> tuple[float, float]:
    """The time of ``p`` and its change when the radius moves by 1e-7; discards the case
    if the balls overlap at the start or it is near a grazing contact."""
    assume(math.hypot(*(p.pa - p.pb)) > p.r * (1 + 1e-6))
    t = p.time()
    others = [replace(p, r=p.r * (1 + d)).time() for d in (1e-7, -1e-7)]
    assume(all(math.isinf(x) == math.isinf(t) for x in others))
    spread = 0.0 if math.isinf(t) else max(abs(x - t) for x in others)
    note(f"t = {t!r}, spread = {spread!r}")
    event("hit" if math.isfinite(t) else "miss")
    return t, spread


def assert_close(got: float, t: float, spread: float, slack: float = 0.0) -> None:
    if math.isinf(t):
        assert math.isinf(got), (got, t)
        return
    tolerance = 1e-12 * t + 1e-2 * spread + slack + 1e-300
    assert abs(got - t) <= tolerance, (got, t, spread)


@given(pairs(), st.floats(-10, 10), st.floats(-10, 10))
def test_translation(p: Pair, cx: float, cy: float) -> None:
    t, spread = conditioned(p)
    c = np.array([cx, cy])
    moved = replace(p, pa=p.pa + c, pb=p.pb + c)
    assert_close(moved.time(), t, spread)


@given(pairs(), st.integers(1, 3))
def test_rotation_by_right_angles(p: Pair, quarter_turns: int) -> None:
    t, spread = conditioned(p)

    def rotate(v: np.ndarray) -> np.ndarray:  # exact
        for _ in range(quarter_turns):
            v = np.array([-v[1], v[0]])
        return v

    assert_close(p.map_vectors(rotate).time(), t, spread)


@given(pairs(), st.floats(0.0, 2 * math.pi))
def test_rotation_by_any_angle(p: Pair, angle: float) -> None:
    t, spread = conditioned(p)
    c, s = math.cos(angle), math.sin(angle)
    rotated = p.map_vectors(lambda v: np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]]))
    assert_close(rotated.time(), t, spread)


@given(pairs(), st.integers(-40, 40))
def test_scaling_by_powers_of_two_is_exact(p: Pair, k: int) -> None:
    s = 2.0**k
    scaled = replace(p.map_vectors(lambda v: v * s), fa=p.fa * s, fb=p.fb * s, r=p.r * s)
    t = p.time()
    got = scaled.time()
    assert got == t or (math.isinf(got) and math.isinf(t)), (got, t)


@given(pairs(), st.floats(-6, 6))
def test_scaling_by_any_factor(p: Pair, log10_s: float) -> None:
    t, spread = conditioned(p)
    s = 10.0**log10_s
    scaled = replace(p.map_vectors(lambda v: v * s), fa=p.fa * s, fb=p.fb * s, r=p.r * s)
    assert_close(scaled.time(), t, spread)


@given(pairs())
def test_swapping_the_balls(p: Pair) -> None:
    t, spread = conditioned(p)
    swapped = Pair(p.pb, p.vb, p.fb, p.pa, p.va, p.fa, p.r)
    assert_close(swapped.time(), t, spread)


def _advanced(pos: np.ndarray, vel: np.ndarray, mu: float, t0: float) -> tuple:
    """Position and velocity at ``t0`` (the state from which the same motion goes on)."""
    speed = math.hypot(*vel)
    stop = math.inf if mu == 0 or speed == 0 else speed / mu
    factor = 1.0 if math.isinf(stop) else max(0.0, (stop - t0) / stop)
    return bc.positions_at(pos[None], vel[None], mu, t0)[0], vel * factor


@given(pairs(), st.floats(0.0, 0.95))
def test_time_shift_along_the_trajectories(p: Pair, fraction: float) -> None:
    t, spread = conditioned(p)
    assume(math.isfinite(t))
    t0 = fraction * t
    pa, va = _advanced(p.pa, p.va, p.fa, t0)
    pb, vb = _advanced(p.pb, p.vb, p.fb, t0)
    later = replace(p, pa=pa, va=va, pb=pb, vb=vb)
    assume(math.hypot(*(pa - pb)) > p.r * (1 + 1e-9))
    assert_close(later.time(), t - t0, spread, slack=4 * EPS * t)


# --- robustness: any input gives an answer or a ValueError/TypeError, never a crash --------

any_float = st.floats(allow_nan=True, allow_infinity=True)
wide_float = st.one_of(
    any_float,
    st.floats(-1e6, 1e6),
    st.sampled_from([0.0, -0.0, 1e-300, 5e-324, 1e300, 1.7976931348623157e308, np.nan, np.inf]),
)


@st.composite
def fuzz_batches(draw) -> tuple[dict, int]:
    n = draw(st.integers(0, 6))

    def rows() -> object:
        shape = draw(st.sampled_from([(n, 2)] * 6 + [(n,), (n + 1, 2), (n, 3), (n, 2, 1)]))
        return draw(hnp.arrays(np.float64, shape, elements=wide_float))

    def per_pair(nonneg: bool) -> object:
        kind = draw(st.sampled_from(["scalar", "array", "array", "wrong"]))
        if kind == "scalar":
            x = draw(wide_float)
            return abs(x) if nonneg and draw(st.booleans()) else x
        shape = (n,) if kind == "array" else draw(st.sampled_from([(n + 1,), (n, 1)]))
        a = draw(hnp.arrays(np.float64, shape, elements=wide_float))
        return np.abs(a) if nonneg and draw(st.booleans()) else a

    batch = {
        "pos_a": rows(),
        "vel_a": rows(),
        "friction_a": per_pair(True),
        "pos_b": rows(),
        "vel_b": rows(),
        "friction_b": per_pair(True),
        "contact_distance": per_pair(True),
        "t_max": per_pair(True),
    }
    return batch, n


def _valid(batch: dict, n: int) -> bool:
    for k in ("pos_a", "vel_a", "pos_b", "vel_b"):
        a = batch[k]
        if a.shape != (n, 2) or not np.isfinite(a).all():
            return False
    for k in ("friction_a", "friction_b", "contact_distance", "t_max"):
        a = np.asarray(batch[k])
        if a.shape not in ((), (n,)):
            return False
    f = np.concatenate([np.ravel(batch["friction_a"]), np.ravel(batch["friction_b"])])
    r, t_max = np.ravel(batch["contact_distance"]), np.ravel(batch["t_max"])
    return bool(
        np.isfinite(f).all()
        and (f >= 0).all()
        and np.isfinite(r).all()
        and (r > 0).all()
        and (t_max >= 0).all()
    )


@given(fuzz_batches())
def test_any_batch_gives_times_or_a_clear_error(case: tuple[dict, int]) -> None:
    batch, n = case
    out = np.full(n, np.nan)
    try:
        t = bc.collision_times(**batch)
    except (ValueError, TypeError) as e:
        assert not _valid(batch, n), f"a valid input raised {e!r}"
        assert str(e).split(":")[0].split("[")[0] in {*batch, "num_threads"}, str(e)
        # The same error when writing into a caller's array.
        with pytest.raises(type(e), match="^" + re.escape(str(e)) + "$"):
            bc.collision_times(**batch, out=out)
        return
    # Into a caller's array: the same bits.
    assert bc.collision_times(**batch, out=out) is out
    assert (out.view(np.uint64) == t.view(np.uint64)).all()
    # Values are checked pair by pair: with no pair, a bad scalar goes unnoticed.
    assert _valid(batch, n) or n == 0
    assert t.shape == (n,) and t.dtype == np.float64
    assert not np.isnan(t).any(), t
    assert (t >= 0).all()
    assert (np.isinf(t) | (t < np.ravel(batch["t_max"]))).all()


finite_float = st.one_of(
    st.floats(allow_nan=False, allow_infinity=False),
    st.floats(-10, 10),
    st.sampled_from([0.0, -0.0, 5e-324, -1e-300, 1e300, -1.7976931348623157e308]),
)
nonnegative = finite_float.map(abs)
positive = nonnegative.filter(lambda x: x > 0)


@st.composite
def valid_extreme_batches(draw) -> dict:
    n = draw(st.integers(1, 6))

    def rows() -> np.ndarray:
        return draw(hnp.arrays(np.float64, (n, 2), elements=finite_float))

    def per_pair(elements: st.SearchStrategy) -> object:
        if draw(st.booleans()):
            return draw(elements)
        return draw(hnp.arrays(np.float64, (n,), elements=elements))

    return {
        "pos_a": rows(),
        "vel_a": rows(),
        "friction_a": per_pair(nonnegative),
        "pos_b": rows(),
        "vel_b": rows(),
        "friction_b": per_pair(nonnegative),
        "contact_distance": per_pair(positive),
        "t_max": per_pair(st.one_of(nonnegative, st.just(math.inf))),
    }


@given(valid_extreme_batches())
def test_valid_extreme_inputs_never_error_nor_give_nan(batch: dict) -> None:
    """Finite inputs anywhere in the float range are valid: an answer, never NaN."""
    t = bc.collision_times(**batch)
    assert not np.isnan(t).any(), t
    assert (t >= 0).all()
    assert (np.isinf(t) | (t < np.broadcast_to(batch["t_max"], t.shape))).all()


@given(
    hnp.arrays(
        np.float64,
        st.tuples(st.integers(0, 5), st.integers(0, 7)),
        elements=wide_float,
    )
)
def test_any_coefficients_give_roots_or_a_clear_error(coeffs: np.ndarray) -> None:
    try:
        roots = bc.real_roots(coeffs)
    except ValueError as e:
        assert str(e).startswith("coeffs")
        assert not (2 <= coeffs.shape[1] <= 5 and np.isfinite(coeffs).all()), e
        return
    n, k = coeffs.shape[0], coeffs.shape[1] - 1
    assert roots.shape == (n, k)
    for row in roots:
        real = row[~np.isnan(row)]
        assert np.isnan(row[len(real) :]).all()  # NaN padding at the end only
        assert (np.diff(real) >= 0).all()  # ascending


@given(
    st.integers(1, 4).flatmap(
        lambda k: hnp.arrays(np.float64, (k + 1,), elements=st.floats(-100, 100).map(_clean))
    )
)
def test_real_roots_are_roots(coeffs: np.ndarray) -> None:
    """Each reported root makes the polynomial small relative to its terms' sizes
    (evaluated exactly, with fractions)."""
    roots = bc.real_roots(coeffs)
    k = len(coeffs) - 1
    for x in roots[~np.isnan(roots)]:
        if not math.isfinite(x):
            continue
        terms = [Fraction(c) * Fraction(x) ** (k - i) for i, c in enumerate(coeffs)]
        size = sum(abs(term) for term in terms)
        # A root below the smallest subnormal rounds to 0: allow for that as well.
        slope = sum(
            abs(Fraction(c)) * (k - i) * abs(Fraction(x)) ** max(k - i - 1, 0)
            for i, c in enumerate(coeffs)
        )
        tolerance = Fraction(1000) * Fraction(EPS) * size + slope * Fraction(2.0**-1074)
        assert abs(sum(terms)) <= tolerance, (x, coeffs)


@pytest.mark.parametrize("k", [1, 2, 3, 4])
@given(data=st.data())
def test_real_roots_well_separated_match_numpy(k: int, data: st.DataObject) -> None:
    roots = sorted(data.draw(st.lists(st.floats(-10, 10), min_size=k, max_size=k)))
    assume(all(b - a > 0.1 for a, b in zip(roots, roots[1:])))
    lead = data.draw(st.sampled_from([1.0, -1.0, 0.5, 3.0]))
    coeffs = lead * np.poly(roots)
    got = bc.real_roots(coeffs)
    expected = np.sort(np.roots(coeffs).real)
    np.testing.assert_allclose(got, expected, rtol=1e-7, atol=1e-9)
    np.testing.assert_allclose(got, roots, rtol=1e-7, atol=1e-9)


def test_small_quadratic_root_with_subnormal_leading_coefficient() -> None:
    for c in (1e-302, 3e-302, 1.234e-300):
        # 5e-324·x² + x + c: the small root is −c·(1 + O(1e-625)), i.e. exactly −c in float64
        # (the other is −2e323, reported as −inf).
        roots = bc.real_roots([5e-324, 1.0, c])
        assert roots[1] == -c, (c, roots)
