"""Balls on paths of constant-acceleration segments: answers against the mpmath reference,
batches, broadcasting, padding, threads, ``out=``, input types and errors."""

from __future__ import annotations

import re
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import ballcollide as bc

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data" / "path_cases.txt"


def bits(x: np.ndarray) -> np.ndarray:
    return np.ascontiguousarray(x, dtype=np.float64).view(np.uint64)


# --- the reference cases (mpmath, tools/path_reference.py) --------------------------------


def load_cases() -> list:
    if not DATA.exists():
        pytest.skip(f"{DATA} is absent: generate it with tools/path_reference.py")
    sys.path.insert(0, str(ROOT / "tools"))
    try:
        from path_reference import read_cases
    finally:
        sys.path.pop(0)
    return read_cases(str(DATA))


def as_arrays(paths: list, k: int, dim: int) -> tuple[np.ndarray, ...]:
    """Paths (tuples of segments ``(s, p, v, a)``) as ``(N, K)`` and ``(N, K, D)`` arrays,
    padded to ``k`` segments with ``+inf`` starts and NaN values (which must be ignored)."""
    n = len(paths)
    start = np.full((n, k), np.inf)
    pos, vel, acc = (np.full((n, k, dim), np.nan) for _ in range(3))
    for i, path in enumerate(paths):
        for j, (s, p, v, a) in enumerate(path):
            start[i, j], pos[i, j], vel[i, j], acc[i, j] = s, p, v, a
    return start, pos, vel, acc


def one_path(path: tuple) -> tuple[np.ndarray, ...]:
    """A path as the tuple ``(start (K,), pos (K, D), vel, acc)``, unpadded."""
    start, pos, vel, acc = as_arrays([path], len(path), len(path[0][1]))
    return start[0], pos[0], vel[0], acc[0]


class Batches:
    """The reference cases of each dimension as one padded batch."""

    def __init__(self) -> None:
        cases = load_cases()
        self.by_dim = {}
        for dim in (2, 3):
            chosen = [c for c in cases if c.dim == dim]
            ka = max(len(c.a) for c in chosen)
            kb = max(len(c.b) for c in chosen)
            self.by_dim[dim] = (
                chosen,
                as_arrays([c.a for c in chosen], ka, dim)
                + as_arrays([c.b for c in chosen], kb, dim),
                np.array([c.radius for c in chosen]),
                np.array([c.t_max for c in chosen]),
            )

    def times(self, dim: int, **kwargs) -> np.ndarray:
        _, arrays, radius, t_max = self.by_dim[dim]
        return bc.path_collision_times(*arrays, radius, t_max=t_max, **kwargs)


@pytest.fixture(scope="module")
def batches() -> Batches:
    return Batches()


def test_reference_cases_agree_with_mpmath(batches: Batches) -> None:
    # The Python-side accuracy test: every case of the file, through the padded batches.
    total = 0
    for dim in (2, 3):
        cases = batches.by_dim[dim][0]
        t = batches.times(dim)
        t_ref = np.array([c.t_ref for c in cases])
        floor = np.array([c.floor for c in cases])
        ambiguous = np.array([c.ambiguous for c in cases])
        assert not np.isnan(t).any()
        disagree = (np.isinf(t) != np.isinf(t_ref)) & ~ambiguous
        assert not disagree.any(), [
            (cases[i].category, float(t[i]), float(t_ref[i])) for i in np.flatnonzero(disagree)
        ][:10]
        both = np.isfinite(t) & np.isfinite(t_ref) & ~ambiguous
        tolerance = np.maximum(64 * floor, 4 * np.spacing(np.abs(t_ref)))
        error = np.where(both, np.abs(t - np.where(both, t_ref, 0.0)), 0.0)
        bad = both & (error > tolerance)
        assert not bad.any(), [
            (cases[i].category, float(t[i]), float(t_ref[i]), float(floor[i]))
            for i in np.flatnonzero(bad)
        ][:10]
        assert both.sum() > 1000
        total += len(cases)
    assert total >= 20_000


def test_single_pair_equals_batch_bit_for_bit(batches: Batches) -> None:
    for dim in (2, 3):
        cases = batches.by_dim[dim][0]
        t = batches.times(dim)
        for i in range(0, len(cases), 11):
            c = cases[i]
            one = bc.path_collision_time(one_path(c.a), one_path(c.b), c.radius, t_max=c.t_max)
            assert bits(np.array([one])) == bits(t[i : i + 1]), (dim, i, one, t[i])


def test_thread_count_does_not_change_any_bit(batches: Batches) -> None:
    for dim in (2, 3):
        ref = batches.times(dim, num_threads=1)
        for threads in (2, 3, None):
            np.testing.assert_array_equal(bits(batches.times(dim, num_threads=threads)), bits(ref))


def test_more_padding_of_any_values_changes_nothing(batches: Batches) -> None:
    _, arrays, radius, t_max = batches.by_dim[2]
    ref = batches.times(2)
    wider = []
    for side in (arrays[:4], arrays[4:]):
        start, *rows = side
        n = len(start)
        wider.append(np.concatenate([start, np.full((n, 2), np.inf)], axis=1))
        for r in rows:
            pad = np.full((n, 2, 2), np.nan)
            pad[:, 1] = [np.inf, -1e300]  # ignored too
            wider.append(np.concatenate([r, pad], axis=1))
    got = bc.path_collision_times(*wider, radius, t_max=t_max)
    np.testing.assert_array_equal(bits(got), bits(ref))


# --- a small batch of hand-made pairs ----------------------------------------------------


def rolling_pairs(n: int, seed: int = 0, dim: int = 2) -> dict:
    """Pool-table-like pairs of 3-segment paths (moving, slowing, at rest), many of them
    colliding, as keyword arguments of path_collision_times."""
    rng = np.random.default_rng(seed)
    out = {}
    for side in "ab":
        p0 = rng.uniform(0, 2, (n, dim))
        v0 = rng.uniform(-2, 2, (n, dim)) * (side == "a" or 0.3)
        a0 = rng.uniform(-1, 1, (n, dim))
        t1 = rng.uniform(0.1, 0.5, n)
        p1 = p0 + v0 * t1[:, None] + 0.5 * a0 * t1[:, None] ** 2
        v1 = v0 + a0 * t1[:, None]
        speed = np.linalg.norm(v1, axis=1)
        mu = 0.1
        a1 = -mu * v1 / np.where(speed > 0, speed, 1)[:, None]
        t2 = t1 + speed / mu
        p2 = p1 + v1 * (speed / mu / 2)[:, None]
        out[f"start_{side}"] = np.stack([np.zeros(n), t1, t2], axis=1)
        out[f"pos_{side}"] = np.stack([p0, p1, p2], axis=1)
        out[f"vel_{side}"] = np.stack([v0, v1, np.zeros((n, dim))], axis=1)
        out[f"acc_{side}"] = np.stack([a0, a1, np.zeros((n, dim))], axis=1)
    # B near a point of A's first segment.
    s = rng.uniform(0, 0.3, n)[:, None]
    out["pos_b"][:, 0] = out["pos_a"][:, 0] + out["vel_a"][:, 0] * s + rng.normal(0, 0.1, (n, dim))
    out["contact_distance"] = 0.05715
    return out


def side_args(batch: dict, side: str) -> list:
    return [batch[f"{k}_{side}"] for k in ("start", "pos", "vel", "acc")]


def call(batch: dict, **kwargs) -> np.ndarray:
    return bc.path_collision_times(
        *side_args(batch, "a"), *side_args(batch, "b"), batch["contact_distance"], **kwargs
    )


def test_hand_made_batches_hit_and_miss() -> None:
    for dim in (2, 3):
        t = call(rolling_pairs(4000, seed=dim, dim=dim))
        assert 200 < np.isfinite(t).sum() < 3900, np.isfinite(t).sum()
        assert (t[np.isfinite(t)] >= 0).all()


def test_contact_distance_at_the_collision_time() -> None:
    batch = rolling_pairs(2000, seed=5)
    t = call(batch)
    hit = np.isfinite(t)
    xa = bc.path_positions_at(*side_args(batch, "a"), np.where(hit, t, 0.0))
    xb = bc.path_positions_at(*side_args(batch, "b"), np.where(hit, t, 0.0))
    gap = np.linalg.norm(xa - xb, axis=1)[hit]
    starts_apart = np.linalg.norm(batch["pos_a"][:, 0] - batch["pos_b"][:, 0], axis=1) > 0.05715
    assert np.allclose(gap[starts_apart[hit]], 0.05715, rtol=1e-9)


def test_broadcasting_one_path_against_many_and_scalars() -> None:
    batch = rolling_pairs(3000, seed=7)
    a_one = [x[:1] for x in side_args(batch, "a")]
    a_tiled = [np.repeat(x, 3000, axis=0) for x in a_one]
    b = side_args(batch, "b")
    radius = np.full(3000, 0.05715)
    ref = bc.path_collision_times(*a_tiled, *b, radius)
    assert np.isfinite(ref).sum() > 0
    for r in (0.05715, [0.05715], radius):
        got = bc.path_collision_times(*a_one, *b, r)
        np.testing.assert_array_equal(bits(got), bits(ref))
    # B broadcast, A per pair: the swap of roles.
    got = bc.path_collision_times(*b, *a_one, 0.05715)
    ref_b = bc.path_collision_times(*b, *a_tiled, 0.05715)
    np.testing.assert_array_equal(bits(got), bits(ref_b))
    # Both sides one path, radius and t_max per pair: N from them.
    t_max = np.array([np.inf, 0.0, 1e-3])
    got = bc.path_collision_times(*a_one, *[x[:1] for x in b], [1.0, 1.0, 1.0], t_max=t_max)
    one = bc.path_collision_times(*a_one, *[x[:1] for x in b], 1.0)
    assert got.shape == (3,) and got[0] == one[0]
    assert got[1] == np.inf  # t ≥ t_max = 0 is none
    # t_max of shape (1,) broadcasts like a number.
    np.testing.assert_array_equal(
        bc.path_collision_times(*a_one, *b, 0.05715, t_max=[0.5]),
        bc.path_collision_times(*a_one, *b, 0.05715, t_max=0.5),
    )


def test_different_segment_counts_and_empty_batches() -> None:
    batch = rolling_pairs(500, seed=8)
    a = side_args(batch, "a")
    b1 = [x[:, :1] for x in side_args(batch, "b")]  # B: one segment only
    t = bc.path_collision_times(*a, *b1, 0.05715)
    assert t.shape == (500,) and np.isfinite(t).any()
    empty = [x[:0] for x in a]
    assert bc.path_collision_times(*empty, *empty, 1.0).shape == (0,)
    assert bc.path_positions_at(*empty, 0.0).shape == (0, 2)


def test_out_receives_the_same_bits_and_is_returned() -> None:
    batch = rolling_pairs(5000, seed=9)
    fresh = call(batch)
    out = np.full(5000, -1.0)
    for threads in (1, 2):
        got = call(batch, num_threads=threads, out=out)
        assert got is out
        np.testing.assert_array_equal(bits(out), bits(fresh))
    with pytest.raises(ValueError, match=re.escape("out: expected shape (5000,), got (4,)")):
        call(batch, out=np.empty(4))
    with pytest.raises(ValueError, match=r"^out: the array shares memory with an input"):
        call(batch, out=batch["start_a"].reshape(-1)[:5000])
    a = side_args(batch, "a")
    centres = np.empty((5000, 2))
    t = np.linspace(0, 3, 5000)
    assert bc.path_positions_at(*a, t, out=centres) is centres
    np.testing.assert_array_equal(bits(centres), bits(bc.path_positions_at(*a, t)))
    with pytest.raises(ValueError, match=re.escape("out: expected shape (5000, 2), got")):
        bc.path_positions_at(*a, t, out=np.empty((5000, 3)))


def test_input_types_give_the_same_answers() -> None:
    batch = rolling_pairs(300, seed=10, dim=3)
    ref = call(batch)
    arrays = side_args(batch, "a") + side_args(batch, "b")
    variants = {
        "lists": [x.tolist() for x in arrays],
        "fortran": [np.asfortranarray(x) for x in arrays],
        "strided": [np.repeat(x, 2, axis=0)[::2] for x in arrays],
        "big-endian": [x.astype(">f8") for x in arrays],
        "read-only": [x.copy() for x in arrays],
    }
    for x in variants["read-only"]:
        x.flags.writeable = False
    for name, args in variants.items():
        got = bc.path_collision_times(*args, 0.05715)
        np.testing.assert_array_equal(bits(got), bits(ref), err_msg=name)
    # float32 inputs are their float64 values: the same answers as the float64 of them.
    f32 = [x.astype(np.float32) for x in arrays]
    np.testing.assert_array_equal(
        bits(bc.path_collision_times(*f32, np.float32(0.05715))),
        bits(
            bc.path_collision_times(
                *[x.astype(np.float64) for x in f32], float(np.float32(0.05715))
            )
        ),
    )
    # Integers where floats go.
    ints = bc.path_collision_times(
        [[0]], [[[0, 0]]], [[[1, 0]]], [[[0, 0]]], [[0]], [[[3, 0]]], [[[0, 0]]], [[[0, 0]]], 1
    )
    assert ints.tolist() == [2.0]


def test_path_positions_at_follows_the_segments() -> None:
    batch = rolling_pairs(1000, seed=11, dim=3)
    start, pos, vel, acc = side_args(batch, "a")
    rng = np.random.default_rng(12)
    t = rng.uniform(-0.5, 30, 1000)
    got = bc.path_positions_at(start, pos, vel, acc, t)
    k = np.maximum((start <= t[:, None]).sum(axis=1) - 1, 0)
    i = np.arange(1000)
    s = np.maximum(t, start[:, 0]) - start[i, k]
    expected = pos[i, k] + (vel[i, k] + acc[i, k] * (0.5 * s)[:, None]) * s[:, None]
    np.testing.assert_array_equal(bits(got), bits(expected))
    # One path at many times (broadcast), e.g. to draw it.
    line = bc.path_positions_at(start[:1], pos[:1], vel[:1], acc[:1], t)
    np.testing.assert_array_equal(
        bits(line),
        bits(bc.path_positions_at(*[np.repeat(x[:1], 1000, 0) for x in (start, pos, vel, acc)], t)),
    )
    assert line.shape == (1000, 3)


def test_a_friction_ball_as_a_path_has_its_positions() -> None:
    p, v, mu = np.array([0.5, 1.0]), np.array([1.5, -0.5]), 0.25
    speed = np.hypot(*v)
    tau = speed / mu
    path = (
        [[0.0, tau]],
        [[p, p + v * (tau / 2)]],
        [[v, [0.0, 0.0]]],
        [[-mu * v / speed, [0.0, 0.0]]],
    )
    t = np.array([0.0, 1.0, 3.0, tau, 100.0])
    np.testing.assert_allclose(
        bc.path_positions_at(*path, t),
        bc.positions_at([p] * 5, [v] * 5, mu, t),
        rtol=1e-15,
        atol=1e-15,
    )


# --- errors -------------------------------------------------------------------------------


def error_of(f, *args, **kwargs) -> bc.InputError:
    with pytest.raises(bc.InputError) as e:
        f(*args, **kwargs)
    return e.value


def test_bad_values_name_argument_pair_and_segment() -> None:
    batch = rolling_pairs(10, seed=13)
    for name, (i, k), value, reason in [
        ("vel_b", (7, 2), np.nan, "must be finite, got NaN"),
        ("pos_a", (3, 1), np.inf, "must be finite, got inf"),
        ("acc_a", (9, 0), -np.inf, "must be finite, got -inf"),
        ("start_b", (7, 2), 1.0, None),
        ("start_a", (2, 0), np.inf, None),
    ]:
        bad = {key: (v.copy() if isinstance(v, np.ndarray) else v) for key, v in batch.items()}
        if name.startswith("start"):
            if value == np.inf:
                bad[name][i] = np.inf  # no used segment: the first start is +inf
                reason = "must be finite, got inf"
            else:
                bad[name][i, 1] = 2.0
                bad[name][i, 2] = value
                reason = "starts must not decrease, got 1 after 2"
        else:
            bad[name][i, k, 1] = value
        err = error_of(call, bad)
        assert (err.argument, err.index, err.segment, err.reason) == (name, i, k, reason)
        assert str(err) == f"{name}[{i}, {k}]: {reason}"
    # Threads do not change which error is reported: the lowest pair.
    big = rolling_pairs(5000, seed=14)
    big["vel_a"][4321, 1, 0] = np.nan
    big["start_b"][1234, 2] = -1.0
    for threads in (1, 2, None):
        err = error_of(call, big, num_threads=threads)
        assert str(err) == "start_b[1234, 2]: starts must not decrease, got -1 after " + repr(
            float(big["start_b"][1234, 1])
        ).rstrip("0").rstrip(".")


def test_the_single_pair_names_the_segment_without_a_pair() -> None:
    a = ([0.0, 1.0], [[0, 0], [1, 0]], [[1, 0], [np.nan, 0]], [[0, 0], [0, 0]])
    b = ([0.0], [[3, 0]], [[0, 0]], [[0, 0]])
    err = error_of(bc.path_collision_time, a, b, 1.0)
    assert (err.argument, err.index, err.segment) == ("vel_a", None, 1)
    assert str(err) == "vel_a[1]: must be finite, got NaN"
    err = error_of(bc.path_collision_time, b, ([1.0, 0.5], *a[1:]), 1.0)
    assert str(err) == "start_b[1]: starts must not decrease, got 0.5 after 1"
    err = error_of(bc.path_collision_time, b, b, 0.0)
    assert str(err).startswith("contact_distance: the contact distance")
    err = error_of(bc.path_collision_time, b, b, 1.0, t_max=-1)
    assert str(err).startswith("t_max: must be ≥ 0")
    err = error_of(bc.path_collision_time, b, b[:3], 1.0)
    assert str(err) == "path_b: expected a path (start, pos, vel, acc), got a sequence of 3"
    with pytest.raises(TypeError, match=r"^path_a: expected a path"):
        bc.path_collision_time(np.zeros(4), b, 1.0)  # type: ignore[arg-type]
    # Padding is allowed for a single path too.
    padded = ([0.0, np.inf], [[3, 0], [np.nan] * 2], [[0, 0], [np.nan] * 2], [[0, 0]] * 2)
    assert bc.path_collision_time(a[:2] + ([[1, 0], [1, 0]], a[3]), padded, 1.0) == 2.0


def test_shapes_and_dimensions() -> None:
    batch = rolling_pairs(4, seed=15)
    cases = [
        ({"start_a": np.zeros(4)}, "start_a: expected shape (N, K), got (4,)"),
        (
            {"pos_a": np.zeros((4, 3, 4))},
            "pos_a: expected shape (N, K, 2) or (N, K, 3), got (4, 3, 4)",
        ),
        (
            {"pos_a": np.zeros((4, 2, 2))},
            "pos_a: expected shape (4, 3, 2) like start_a (4, 3), got (4, 2, 2)",
        ),
        (
            {"vel_a": np.zeros((4, 3, 3))},
            "vel_a: expected shape (4, 3, 2) like pos_a, got (4, 3, 3)",
        ),
        ({"acc_b": np.zeros((4, 3))}, "acc_b: expected shape (4, 3, 2) like pos_b, got (4, 3)"),
        (
            {"pos_b": np.zeros((4, 3, 3))},
            "pos_b: expected shape (N, K, 2) like pos_a (the same dimension), got (4, 3, 3)",
        ),
        (
            {f"{k}_b": batch[f"{k}_b"][:3] for k in ("start", "pos", "vel", "acc")},
            "start_b: has 3 rows, expected 4",
        ),
        (
            {
                "start_a": np.zeros((4, 0)),
                **{f"{k}_a": np.zeros((4, 0, 2)) for k in ("pos", "vel", "acc")},
            },
            "start_a: a path needs at least one segment",
        ),
        ({"contact_distance": [1.0, 1.0]}, "contact_distance: has 2 rows, expected 4"),
        (
            {"contact_distance": -1.0},
            "contact_distance: the contact distance (sum of the two radii) must be > 0, got -1",
        ),
        (
            {"contact_distance": [1.0, 1.0, 0.0, 1.0]},
            "contact_distance[2]: the contact distance (sum of the two radii) must be > 0, got 0",
        ),
    ]
    for change, message in cases:
        err = error_of(call, {**batch, **change})
        assert str(err) == message, (str(err), message)
    with pytest.raises(bc.InputError, match=re.escape("t_max[1]: must be ≥ 0")):
        call(batch, t_max=[1.0, -1.0, 1.0, 1.0])
    with pytest.raises(TypeError, match=r"^vel_b: expected real numbers"):
        call({**batch, "vel_b": [[["a", "b"]] * 3] * 4})
    with pytest.raises(TypeError, match="positional"):
        bc.path_collision_times(*side_args(batch, "a"), *side_args(batch, "b"), 1.0, 5.0)  # type: ignore[misc]


def test_path_positions_at_errors() -> None:
    start, pos, vel, acc = side_args(rolling_pairs(5, seed=16), "a")
    err = error_of(bc.path_positions_at, start, pos, vel, acc, [0, 1, np.inf, 0, 0])
    assert str(err) == "t[2]: must be finite, got inf"
    vel = vel.copy()
    vel[3, 1, 0] = np.nan
    err = error_of(bc.path_positions_at, start, pos, vel, acc, 0.0)
    assert (str(err), err.index, err.segment) == ("vel[3, 1]: must be finite, got NaN", 3, 1)
    err = error_of(bc.path_positions_at, start, pos, vel, acc, [0.0, 1.0])
    assert str(err) == "t: has 2 rows, expected 5"


def test_gil_is_released_during_a_large_batch() -> None:
    batch = rolling_pairs(200_000, seed=17)
    count = [0]
    stop = threading.Event()

    def counter() -> None:
        while not stop.is_set():
            count[0] += 1

    worker = threading.Thread(target=counter)
    worker.start()
    try:
        start, begin = count[0], time.perf_counter()
        time.sleep(0.2)
        rate = (count[0] - start) / (time.perf_counter() - begin)
        start, begin = count[0], time.perf_counter()
        call(batch, num_threads=1)
        elapsed = time.perf_counter() - begin
        during = count[0] - start
    finally:
        stop.set()
        worker.join()
    assert elapsed > 0.01, "the batch was too quick to tell"
    assert during > 0.3 * rate * elapsed, (during, rate, elapsed)
