"""Scenes of N balls: pairwise_collision_times, earliest_collision, first_contacts.

Every answer must equal the brute force over all pairs through ``collision_times`` (pair
``i < j`` as A = ``i``, B = ``j``, at the sum of the two radii), bit for bit.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import ballcollide as bc

R = 0.028575


def random_scene(n: int, seed: int, *, mixed: bool = True) -> dict:
    """Balls on a table scaled to constant density: stopping, frictionless, at rest, and
    (with ``mixed``) varied radii and balls touching a neighbour."""
    rng = np.random.default_rng(seed)
    scale = max(1.0, np.sqrt(n / 16))
    pos = rng.uniform([0, 0], [2.54 * scale, 1.27 * scale], (n, 2))
    angle = rng.uniform(0, 2 * np.pi, n)
    speed = rng.uniform(0, 2, n)
    vel = np.column_stack([speed * np.cos(angle), speed * np.sin(angle)])
    friction = rng.uniform(0.05, 2.0, n)
    radius = np.full(n, R)
    if mixed and n > 1:
        kind = rng.integers(0, 4, n)
        friction[kind == 1] = 0.0  # frictionless
        vel[kind == 2] = 0.0  # at rest
        radius = rng.uniform(0.01, 0.08, n)
        for k in np.flatnonzero(kind == 3)[1:]:  # touching an earlier ball
            other = rng.integers(0, k)
            pos[k] = pos[other] + [radius[k] + radius[other], 0.0]
    return {"pos": pos, "vel": vel, "friction": friction, "radius": radius}


def brute_force(s: dict, t_max: float = np.inf) -> np.ndarray:
    n = len(s["pos"])
    i, j = np.triu_indices(n, k=1)
    times = bc.collision_times(
        s["pos"][i],
        s["vel"][i],
        np.broadcast_to(s["friction"], n)[i],
        s["pos"][j],
        s["vel"][j],
        np.broadcast_to(s["friction"], n)[j],
        np.broadcast_to(s["radius"], n)[i] + np.broadcast_to(s["radius"], n)[j],
        t_max=t_max,
    )
    out = np.full((n, n), np.inf)
    out[i, j] = times
    out[j, i] = times
    return out


def brute_earliest(m: np.ndarray) -> tuple[float, int, int]:
    n = len(m)
    i, j = np.triu_indices(n, k=1)
    t = m[i, j]
    if not np.isfinite(t).any():
        return (np.inf, -1, -1)
    k = np.argmin(t)  # first minimum in row-major (i, j) order: lowest i, then j
    return (float(t[k]), int(i[k]), int(j[k]))


def brute_first(m: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    times = m.min(axis=1) if len(m) else np.zeros(0)
    partner = np.where(np.isfinite(times), m.argmin(axis=1) if len(m) else 0, -1)
    return times, partner.astype(np.int64)


def bits(x: np.ndarray) -> np.ndarray:
    return np.ascontiguousarray(x, dtype=np.float64).view(np.uint64)


def assert_scene_matches(s: dict, t_max: float = np.inf) -> None:
    reference = brute_force(s, t_max)
    for threads in (None, 1):
        kw = {"t_max": t_max, "num_threads": threads}
        m = bc.pairwise_collision_times(s["pos"], s["vel"], s["friction"], s["radius"], **kw)
        assert m.shape == reference.shape and m.dtype == np.float64
        np.testing.assert_array_equal(bits(m), bits(reference))
        t, i, j = bc.earliest_collision(s["pos"], s["vel"], s["friction"], s["radius"], **kw)
        want = brute_earliest(reference)
        assert (i, j) == want[1:]
        assert bits(np.array(t)) == bits(np.array(want[0]))
        times, partner = bc.first_contacts(s["pos"], s["vel"], s["friction"], s["radius"], **kw)
        want_t, want_p = brute_first(reference)
        np.testing.assert_array_equal(bits(times), bits(want_t))
        np.testing.assert_array_equal(partner, want_p)
        assert partner.dtype == np.int64 and times.dtype == np.float64


@pytest.mark.parametrize(("n", "seed"), [(2, 0), (16, 1), (200, 2), (1500, 3)])
def test_random_scenes_equal_brute_force(n: int, seed: int) -> None:
    assert_scene_matches(random_scene(n, seed))
    assert_scene_matches(random_scene(n, seed, mixed=False))


@pytest.mark.parametrize("t_max", [0.0, 0.3, 2.0])
def test_horizon(t_max: float) -> None:
    assert_scene_matches(random_scene(300, 7), t_max)


@given(
    st.lists(
        st.tuples(
            st.floats(-2, 2),
            st.floats(-2, 2),
            st.floats(-2, 2),
            st.floats(-2, 2),
            st.sampled_from([0.0, 0.1, 1.0]),
            st.floats(0.01, 0.5),
        ),
        max_size=12,
    ),
    st.sampled_from([np.inf, 1.0]),
)
def test_any_small_scene_equals_brute_force(rows: list, t_max: float) -> None:
    a = np.array(rows, dtype=np.float64).reshape(-1, 6)
    s = {"pos": a[:, 0:2], "vel": a[:, 2:4], "friction": a[:, 4], "radius": a[:, 5]}
    assert_scene_matches(s, t_max)


def test_scalar_friction_and_radius_and_array_likes() -> None:
    pos = [[0, 0], [1, 0], [3, 0]]
    vel = [[1, 0], [0, 0], [0, 0]]
    m = bc.pairwise_collision_times(pos, vel, 0.0, 0.25)
    assert m.shape == (3, 3)
    assert m[0, 1] == m[1, 0] == 0.5 and m[0, 2] == 2.5 and np.isinf(np.diag(m)).all()
    assert bc.earliest_collision(pos, vel, 0, 0.25) == (0.5, 0, 1)
    times, partner = bc.first_contacts(np.asfortranarray(pos), vel, [0, 0, 0], [0.25] * 3)
    assert times.tolist() == [0.5, 0.5, 2.5] and partner.tolist() == [1, 0, 0]
    # Lists of ints, Fortran order and strided views give the same answer as float64 arrays.
    p = np.array(pos, dtype=np.float64)
    wide = np.zeros((3, 4))
    wide[:, ::2] = p
    np.testing.assert_array_equal(bc.pairwise_collision_times(wide[:, ::2], vel, 0.0, 0.25), m)


def test_empty_and_single_ball() -> None:
    empty = np.zeros((0, 2))
    m = bc.pairwise_collision_times(empty, empty, 0.1, 0.1)
    assert m.shape == (0, 0)
    assert bc.earliest_collision(empty, empty, 0.1, 0.1) == (np.inf, -1, -1)
    times, partner = bc.first_contacts(empty, empty, 0.1, 0.1)
    assert times.shape == (0,) and partner.shape == (0,) and partner.dtype == np.int64
    one = [[0.0, 0.0]]
    assert bc.pairwise_collision_times(one, [[1.0, 0.0]], 0.1, 0.1).tolist() == [[np.inf]]
    assert bc.earliest_collision(one, [[1.0, 0.0]], 0.1, 0.1) == (np.inf, -1, -1)
    times, partner = bc.first_contacts(one, [[1.0, 0.0]], 0.1, 0.1)
    assert times.tolist() == [np.inf] and partner.tolist() == [-1]


def test_ties_go_to_the_lowest_indices() -> None:
    pos = [[50, 50], [-2, 0], [0, 0], [2, 0]]
    vel = [[0, 0], [1, 0], [0, 0], [-1, 0]]
    assert bc.earliest_collision(pos, vel, 0.0, 0.5) == (1.0, 1, 2)
    times, partner = bc.first_contacts(pos, vel, 0.0, 0.5)
    assert times.tolist() == [np.inf, 1.0, 1.0, 1.0]
    assert partner.tolist() == [-1, 2, 1, 2]


FUNCTIONS = [bc.pairwise_collision_times, bc.earliest_collision, bc.first_contacts]


@pytest.mark.parametrize("f", FUNCTIONS)
@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"radius": [0.1, 0.0, 0.1]}, r"^radius\[1\]: .*must be > 0, got 0"),
        ({"radius": [0.1, 0.1, np.nan]}, r"^radius\[2\]: must be finite, got NaN"),
        ({"radius": -1.0}, r"^radius\[0\]: .*must be > 0, got -1"),
        ({"radius": [0.1, 0.1]}, r"^radius: has 2 rows, expected 3"),
        ({"friction": [0.1, -0.5, 0.1]}, r"^friction\[1\]: friction must be ≥ 0, got -0.5"),
        ({"friction": [0.1, 0.1]}, r"^friction: has 2 rows, expected 3"),
        ({"pos": [[0, 0], [1, np.inf], [2, 0]]}, r"^pos\[1\]: must be finite, got inf"),
        ({"vel": [[0, 0], [0, 0], [np.nan, 0]]}, r"^vel\[2\]: must be finite, got NaN"),
        ({"vel": [[0, 0], [0, 0]]}, r"^vel: has 2 rows, expected 3"),
        ({"pos": [0, 0, 0]}, r"^pos: expected shape \(N, 2\)"),
        ({"t_max": -1.0}, r"^t_max: .*got -1"),
        ({"t_max": np.nan}, r"^t_max: .*got NaN"),
        ({"num_threads": 0}, r"^num_threads: "),
    ],
)
def test_bad_input_names_the_argument_and_index(f, change: dict, message: str) -> None:
    args = {"pos": [[0, 0], [1, 0], [2, 0]], "vel": np.zeros((3, 2)), "friction": 0.1}
    args["radius"] = 0.1
    args.update(change)
    keywords = {k: args.pop(k) for k in ("t_max", "num_threads") if k in args}
    with pytest.raises(ValueError, match=message):
        f(args["pos"], args["vel"], args["friction"], args["radius"], **keywords)


@pytest.mark.parametrize("f", FUNCTIONS)
def test_wrong_types(f) -> None:
    with pytest.raises(TypeError, match=r"^radius: expected real numbers"):
        f([[0, 0]], [[0, 0]], 0.1, ["a"])
    with pytest.raises(ValueError, match=r"^radius: expected a scalar or shape"):
        f([[0, 0]], [[0, 0]], 0.1, [[0.1]])


def test_a_matrix_too_large_for_memory_is_a_memory_error() -> None:
    n = 1_000_000  # an 8 TB matrix
    with pytest.raises(MemoryError, match="first_contacts need only O"):
        bc.pairwise_collision_times(np.zeros((n, 2)), np.zeros((n, 2)), 0.1, 0.1)
