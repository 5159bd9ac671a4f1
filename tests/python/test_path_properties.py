"""Property tests (hypothesis) of the collision time of balls on paths.

As in ``test_properties.py``: the invariances hold exactly for the exact time, and in float64
to within the answer's conditioning, which each case estimates by moving the radius by
±1e-7 (relative). A case whose hit/miss status changes there is near a graze and discarded;
otherwise the change ``spread`` of the time bounds what any perturbation of the distances by
less than ``1e-9·radius`` can do, to first order (the gap depends on the centres' distance
minus the radius). Rotating, translating, splitting a segment or writing a friction ball as
a path perturbs the inputs by a few roundings: distances by ``1e-15`` of the lengths at
most (lengths ≤ 10 here, radius ≥ 0.01), five orders below that bound, so ``1e-2·spread``
is a safe tolerance; a power-of-two change of units is exact.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
from hypothesis import assume, event, given, note
from hypothesis import strategies as st

import ballcollide as bc


def _clean(x: float) -> float:
    # No tiny-but-nonzero values: they would leave the exponent range when scaled.
    return x if abs(x) > 1e-6 else 0.0


coordinate = st.floats(-2.0, 2.0).map(_clean)
component = st.floats(-3.0, 3.0).map(_clean)
radius = st.floats(0.01, 0.5)

PathArrays = tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]


def at(path: PathArrays, t: float) -> np.ndarray:
    start, pos, vel, acc = path
    return bc.path_positions_at(start[None], pos[None], vel[None], acc[None], t)[0]


@dataclass(frozen=True)
class Pair:
    a: PathArrays
    b: PathArrays
    r: float

    def time(self) -> float:
        return bc.path_collision_time(self.a, self.b, self.r)

    def map_rows(self, f) -> Pair:
        """``f`` applied to every position, velocity and acceleration row."""

        def side(path: PathArrays) -> PathArrays:
            start, *rows = path
            return (start, *(np.array([f(x) for x in r]) for r in rows))  # type: ignore[return-value]

        return replace(self, a=side(self.a), b=side(self.b))

    def translated(self, c: np.ndarray) -> Pair:
        def side(path: PathArrays) -> PathArrays:
            start, pos, vel, acc = path
            return (start, pos + c, vel, acc)

        return replace(self, a=side(self.a), b=side(self.b))


@st.composite
def paths(draw, dim: int) -> PathArrays:
    k = draw(st.integers(1, 4))
    s0 = draw(st.floats(0.0, 2.0))
    starts = [s0]
    for _ in range(k - 1):
        starts.append(starts[-1] + draw(st.floats(0.0, 1.0)))
    vec = lambda s: np.array([draw(s) for _ in range(dim)])  # noqa: E731
    pos, vel, acc = [vec(coordinate)], [vec(component)], []
    continuous = draw(st.booleans())
    for j in range(k):
        acc.append(np.zeros(dim) if draw(st.booleans()) else vec(component))
        if j + 1 < k:
            tau = starts[j + 1] - starts[j]
            if continuous:  # the next segment goes on from where this one is
                pos.append(pos[j] + vel[j] * tau + 0.5 * acc[j] * tau * tau)
                vel.append(vel[j] + acc[j] * tau)
            else:
                pos.append(vec(coordinate))
                vel.append(vec(component))
    return np.array(starts), np.array(pos), np.array(vel), np.array(acc)


@st.composite
def pairs(draw, dim: int | None = None) -> Pair:
    dim = dim or draw(st.sampled_from([2, 3]))
    a, b, r = draw(paths(dim)), draw(paths(dim)), draw(radius)
    if draw(st.booleans()):
        # Aim: B moved so as to be near where A is at a time s, within 1.5 radii.
        s = max(a[0][0], b[0][0]) + draw(st.floats(0.05, 1.5))
        offset = np.array([draw(st.floats(-1.5, 1.5)) for _ in range(dim)]) * r
        shift = at(a, s) - at(b, s) + offset
        b = (b[0], b[1] + shift, b[2], b[3])
    return Pair(a, b, r)


def conditioned(p: Pair) -> tuple[float, float]:
    """The time of ``p`` and its change when the radius moves by 1e-7; discards the case if
    the balls touch or overlap where the search starts, or it is near a graze."""
    t_from = max(p.a[0][0], p.b[0][0])
    assume(np.linalg.norm(at(p.a, t_from) - at(p.b, t_from)) > p.r * (1 + 1e-6))
    t = p.time()
    others = [replace(p, r=p.r * (1 + d)).time() for d in (1e-7, -1e-7)]
    assume(all(math.isinf(x) == math.isinf(t) for x in others))
    spread = 0.0 if math.isinf(t) else max(abs(x - t) for x in others)
    note(f"t = {t!r}, spread = {spread!r}")
    event("hit" if math.isfinite(t) else "miss")
    return t, spread


def assert_close(got: float, t: float, spread: float) -> None:
    if math.isinf(t):
        assert math.isinf(got), (got, t)
        return
    tolerance = 1e-12 * t + 1e-2 * spread + 1e-300
    assert abs(got - t) <= tolerance, (got, t, spread)


@given(pairs())
def test_swapping_the_balls(p: Pair) -> None:
    t, spread = conditioned(p)
    assert_close(Pair(p.b, p.a, p.r).time(), t, spread)


@given(pairs(), st.lists(st.floats(-10, 10), min_size=3, max_size=3))
def test_translation(p: Pair, c: list[float]) -> None:
    t, spread = conditioned(p)
    assert_close(p.translated(np.array(c[: len(p.a[1][0])])).time(), t, spread)


@given(pairs(dim=2), st.floats(0.0, 2 * math.pi))
def test_rotation_2d(p: Pair, angle: float) -> None:
    t, spread = conditioned(p)
    c, s = math.cos(angle), math.sin(angle)
    rotation = np.array([[c, -s], [s, c]])
    assert_close(p.map_rows(lambda v: rotation @ v).time(), t, spread)


@given(pairs(dim=3), st.lists(st.floats(-1, 1), min_size=4, max_size=4))
def test_rotation_3d(p: Pair, q: list[float]) -> None:
    norm = math.sqrt(sum(x * x for x in q))
    assume(norm > 0.1)
    w, x, y, z = (v / norm for v in q)
    rotation = np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )
    t, spread = conditioned(p)
    assert_close(p.map_rows(lambda v: rotation @ v).time(), t, spread)


def _lengths(p: Pair) -> np.ndarray:
    values = np.concatenate([np.ravel(x) for x in (*p.a[1:], *p.b[1:], [p.r])])
    return np.abs(values[values != 0])


@given(pairs(), st.integers(-1074, 1023))
def test_power_of_two_units_of_length_are_exact(p: Pair, k: int) -> None:
    # Over the whole exponent range: every length stays a normal float64.
    lengths = _lengths(p)
    assume(math.log2(lengths.max()) + k < 1000 and math.log2(lengths.min()) + k > -1000)
    scaled = replace(p.map_rows(lambda v: np.ldexp(v, k)), r=math.ldexp(p.r, k))
    t, got = p.time(), scaled.time()
    event("hit" if math.isfinite(t) else "miss")
    assert got == t or (math.isinf(got) and math.isinf(t)), (got, t)


@given(pairs(), st.integers(-60, 60))
def test_power_of_two_units_of_time_are_exact(p: Pair, j: int) -> None:
    # Times (starts) times 2^j, velocities 2^-j, accelerations 2^-2j: the time times 2^j.
    s = 2.0**j
    lengths = _lengths(p)
    assume(math.log2(lengths.max()) + 2 * abs(j) < 1000)
    assume(math.log2(lengths.min()) - 2 * abs(j) > -1000)

    def side(path: PathArrays) -> PathArrays:
        start, pos, vel, acc = path
        return (start * s, pos, vel / s, acc / (s * s))

    scaled = Pair(side(p.a), side(p.b), p.r)
    t, got = p.time(), scaled.time()
    event("hit" if math.isfinite(t) else "miss")
    assert got == t * s or (math.isinf(got) and math.isinf(t)), (got, t * s)


@given(pairs(), st.integers(0, 3), st.floats(0.01, 0.99), st.booleans())
def test_splitting_a_segment(p: Pair, which: int, fraction: float, on_a: bool) -> None:
    t, spread = conditioned(p)
    path = p.a if on_a else p.b
    start, pos, vel, acc = path
    k = which % len(start)
    end = start[k + 1] if k + 1 < len(start) else start[k] + 1.0
    cut = start[k] + fraction * (end - start[k])
    assume(start[k] < cut < end)
    tau = cut - start[k]
    # The same motion from `cut` on, up to the roundings of its new position and velocity.
    p_cut = pos[k] + vel[k] * tau + 0.5 * acc[k] * tau * tau
    v_cut = vel[k] + acc[k] * tau
    split = (
        np.insert(start, k + 1, cut),
        np.insert(pos, k + 1, p_cut, axis=0),
        np.insert(vel, k + 1, v_cut, axis=0),
        np.insert(acc, k + 1, acc[k], axis=0),
    )
    other = replace(p, a=split) if on_a else replace(p, b=split)
    assert_close(other.time(), t, spread)


@given(pairs(dim=2), st.floats(-5, 5))
def test_a_2d_pair_embedded_in_3d(p: Pair, z: float) -> None:
    t, spread = conditioned(p)

    def side(path: PathArrays) -> PathArrays:
        start, pos, vel, acc = path
        pad = lambda rows, value: np.column_stack([rows, np.full(len(rows), value)])  # noqa: E731
        return (start, pad(pos, z), pad(vel, 0.0), pad(acc, 0.0))

    assert_close(bc.path_collision_time(side(p.a), side(p.b), p.r), t, spread)


# --- a friction ball and its path ----------------------------------------------------------


def ball_path(pos: np.ndarray, vel: np.ndarray, mu: float) -> PathArrays:
    """The path of a ball slowed by friction ``mu`` until it stops: two segments (one if it
    never stops or is at rest)."""
    speed = math.hypot(*vel)
    if mu == 0 or speed == 0:
        return np.array([0.0]), pos[None], vel[None], np.zeros((1, 2))
    tau = speed / mu
    return (
        np.array([0.0, tau]),
        np.array([pos, pos + vel * (tau / 2)]),
        np.array([vel, [0.0, 0.0]]),
        np.array([-mu * vel / speed, [0.0, 0.0]]),
    )


@given(
    st.lists(coordinate, min_size=4, max_size=4),
    st.lists(component, min_size=4, max_size=4),
    st.lists(st.one_of(st.just(0.0), st.floats(0.05, 2.0)), min_size=2, max_size=2),
    radius,
    st.booleans(),
    st.floats(0.05, 1.5),
)
def test_a_friction_ball_and_its_path_agree(
    x: list[float], v: list[float], mu: list[float], r: float, aim: bool, s: float
) -> None:
    pa, pb, va, vb = np.array(x[:2]), np.array(x[2:]), np.array(v[:2]), np.array(v[2:])
    if aim:  # B near where A is at time s
        pb = (
            bc.positions_at(pa[None], va[None], mu[0], s)[0]
            - bc.positions_at(np.zeros((1, 2)), vb[None], mu[1], s)[0]
            + (pb / 2) * r
        )
    pair = Pair(ball_path(pa, va, mu[0]), ball_path(pb, vb, mu[1]), r)
    t_path, spread = conditioned(pair)
    t_ball = bc.collision_time(pa, va, mu[0], pb, vb, mu[1], r)
    # The path's inputs are the ball's motion up to a few roundings (its acceleration vector,
    # stop time and resting point): the module docstring's bound applies.
    assert_close(t_ball, t_path, spread)


# --- robustness ----------------------------------------------------------------------------

wild = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0.0, -0.0, 5e-324, 1e300, np.nan, np.inf, -np.inf]),
)


@given(
    st.integers(1, 3),
    st.integers(1, 3),
    st.integers(0, 4),
    st.sampled_from([2, 3]),
    st.data(),
)
def test_any_values_give_times_or_a_clear_error(
    ka: int, kb: int, n: int, dim: int, data: st.DataObject
) -> None:
    def array(shape: tuple[int, ...]) -> np.ndarray:
        cells = int(np.prod(shape))
        return np.array(data.draw(st.lists(wild, min_size=cells, max_size=cells))).reshape(shape)

    args = []
    for k in (ka, kb):
        start = np.sort(array((n, k)), axis=1) if data.draw(st.booleans()) else array((n, k))
        args += [start, array((n, k, dim)), array((n, k, dim)), array((n, k, dim))]
    r = data.draw(st.one_of(wild, st.floats(0.01, 10)))
    try:
        t = bc.path_collision_times(*args, r)
    except bc.InputError as e:
        assert e.argument in {
            "start_a",
            "pos_a",
            "vel_a",
            "acc_a",
            "start_b",
            "pos_b",
            "vel_b",
            "acc_b",
            "contact_distance",
        }, str(e)
        return
    assert t.shape == (n,) and not np.isnan(t).any() and (t >= 0).all()
