"""The Python API of ballcollide: answers, array handling, errors, threads and the GIL."""

from __future__ import annotations

import doctest
import re
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import ballcollide as bc
from ballcollide import _core

DATA = Path(__file__).resolve().parents[1] / "data" / "collision_cases.txt"
ARGS = ("pos_a", "vel_a", "friction_a", "pos_b", "vel_b", "friction_b", "contact_distance")


def random_batch(n: int, seed: int = 0) -> dict:
    """A batch of table-like pairs, about a third of which collide."""
    rng = np.random.default_rng(seed)
    pos_a = rng.uniform(0, 2.5, (n, 2))
    vel_a = rng.uniform(-3, 3, (n, 2))
    friction_a = rng.uniform(0, 0.5, n)
    # B near a point of A's path, give or take a few radii.
    s = rng.uniform(0, 1, n)[:, None]
    pos_b = pos_a + vel_a * s + rng.normal(0, 0.1, (n, 2))
    vel_b = rng.uniform(-1, 1, (n, 2)) * (rng.random(n) < 0.5)[:, None]
    friction_b = rng.uniform(0, 0.5, n)
    return {
        "pos_a": pos_a,
        "vel_a": vel_a,
        "friction_a": friction_a,
        "pos_b": pos_b,
        "vel_b": vel_b,
        "friction_b": friction_b,
        "contact_distance": 0.05715,
    }


def bits(x: np.ndarray) -> np.ndarray:
    return np.ascontiguousarray(x, dtype=np.float64).view(np.uint64)


# --- the reference cases (mpmath, tools/collision_reference.py) --------------------------


def _number(text: str) -> float:
    try:
        return float(text)
    except ValueError:
        return float.fromhex(text)


def load_reference() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    if not DATA.exists():
        pytest.skip(
            f"{DATA} is absent: generate the high-precision reference cases with "
            "tools/collision_reference.py"
        )
    lines, rows, categories = [], [], []
    for number, line in enumerate(DATA.read_text().splitlines(), start=1):
        fields = line.split()
        if not fields or fields[0].startswith("#"):
            continue
        assert len(fields) == 16, f"{DATA.name}:{number}: expected 16 columns"
        categories.append(fields[0])
        rows.append([_number(x) for x in fields[1:]])
        lines.append(number)
    return np.array(categories), np.array(rows), np.array(lines)


def reference_times(x: np.ndarray, **kwargs) -> np.ndarray:
    columns = (x[:, 0:2], x[:, 2:4], x[:, 4], x[:, 5:7], x[:, 7:9], x[:, 9], x[:, 10])
    return bc.collision_times(*columns, t_max=x[:, 11], **kwargs)


def test_reference_cases_agree_with_mpmath() -> None:
    categories, x, lines = load_reference()
    assert len(x) > 1000
    t = reference_times(x)
    t_ref, floor, ambiguous = x[:, 12], x[:, 13], x[:, 14] == 1
    assert not np.isnan(t).any()
    assert (t >= 0).all()
    disagree = (np.isinf(t) != np.isinf(t_ref)) & ~ambiguous
    assert not disagree.any(), [
        (int(n), c, float(a), float(b))
        for n, c, a, b in zip(lines[disagree], categories[disagree], t[disagree], t_ref[disagree])
    ][:10]
    both = np.isfinite(t) & np.isfinite(t_ref) & ~ambiguous
    tolerance = 64 * floor + 4 * np.spacing(np.abs(t_ref))
    error = np.where(both, np.abs(t - np.where(both, t_ref, 0.0)), 0.0)
    bad = both & (error > tolerance)
    assert not bad.any(), [
        (int(n), c, float(a), float(b), float(f))
        for n, c, a, b, f in zip(lines[bad], categories[bad], t[bad], t_ref[bad], floor[bad])
    ][:10]
    # Every category is exercised, with hits and (where the category has any) misses.
    for category in np.unique(categories):
        assert (categories == category).sum() >= 100, category


def test_scalar_call_equals_batch_on_reference_cases() -> None:
    _, x, _ = load_reference()
    t = reference_times(x)
    for i in range(0, len(x), 7):
        row = x[i]
        one = bc.collision_time(
            row[0:2], row[2:4], row[4], row[5:7], row[7:9], row[9], row[10], t_max=row[11]
        )
        assert bits(np.array([one])) == bits(t[i : i + 1]), i


def test_thread_count_does_not_change_any_bit() -> None:
    batch = random_batch(50_000, seed=3)
    ref = bc.collision_times(**batch, num_threads=1)
    assert np.isfinite(ref).sum() > 1000  # the batch has many hits
    for threads in (2, 3, None):
        np.testing.assert_array_equal(
            bits(bc.collision_times(**batch, num_threads=threads)), bits(ref)
        )
    if DATA.exists():
        _, x, _ = load_reference()
        one = reference_times(x, num_threads=1)
        np.testing.assert_array_equal(bits(reference_times(x, num_threads=2)), bits(one))
        np.testing.assert_array_equal(bits(reference_times(x)), bits(one))


# --- simple answers ----------------------------------------------------------------------


def test_head_on_and_miss() -> None:
    t = bc.collision_times(
        [[0, 0], [0, 0]], [[1, 0], [1, 0]], 0.0, [[1, 0], [1, 5]], [[0, 0], [0, 0]], 0.0, 0.5
    )
    assert t.dtype == np.float64 and t.shape == (2,)
    assert t[0] == 0.5 and t[1] == np.inf


def test_friction_can_stop_a_ball_short() -> None:
    # 2 m/s at 8 m/s²: stops after 0.25 m, short of the 0.5 m gap.
    assert bc.collision_time([0, 0], [2, 0], 8.0, [1, 0], [0, 0], 0.0, 0.5) == np.inf
    # ... but a ball rolling into it after it stopped still hits it.
    t = bc.collision_time([0, 0], [2, 0], 8.0, [2, 0], [-1, 0], 0.0, 0.5)
    assert t == pytest.approx(1.25, rel=1e-15)


def test_horizon() -> None:
    args = ([0, 0], [1, 0], 0.0, [1, 0], [0, 0], 0.0, 0.5)
    assert bc.collision_time(*args, t_max=0.6) == 0.5
    assert bc.collision_time(*args, t_max=0.5) == np.inf  # at t ≥ t_max: none
    t = bc.collision_times(*[[a] if isinstance(a, list) else a for a in args], t_max=[0.4])
    assert t[0] == np.inf


def test_overlapping_at_start() -> None:
    # Overlapping and approaching: 0. Overlapping and separating: no collision.
    assert bc.collision_time([0, 0], [1, 0], 0.0, [0.3, 0], [0, 0], 0.0, 0.5) == 0.0
    assert bc.collision_time([0, 0], [-1, 0], 0.0, [0.3, 0], [0, 0], 0.0, 0.5) == np.inf


def test_empty_batch() -> None:
    empty = np.zeros((0, 2))
    t = bc.collision_times(empty, empty, 0.1, empty, empty, 0.1, 1.0)
    assert t.shape == (0,) and t.dtype == np.float64
    assert bc.positions_at(empty, empty, 0.1, 1.0).shape == (0, 2)
    assert bc.real_roots(np.zeros((0, 5))).shape == (0, 4)


# --- array handling ----------------------------------------------------------------------


def test_broadcasting_scalars_and_per_pair_values() -> None:
    batch = random_batch(3000, seed=5)
    n = len(batch["pos_a"])
    ref = bc.collision_times(**{**batch, "friction_b": 0.2}, t_max=1.5)
    variants = [
        {"friction_b": np.full(n, 0.2)},
        {"friction_b": np.float64(0.2)},
        {"friction_b": np.array(0.2)},  # 0-d
        {"friction_b": [0.2] * n},
        {"contact_distance": np.full(n, 0.05715)},
        {"t_max": np.full(n, 1.5)},
    ]
    for change in variants:
        kwargs = {**batch, "friction_b": 0.2, "t_max": 1.5, **change}
        np.testing.assert_array_equal(bits(bc.collision_times(**kwargs)), bits(ref))
    # Per-pair values are used per pair.
    radius = np.where(np.arange(n) % 2 == 0, 0.05715, 0.2)
    mixed = bc.collision_times(
        **{**batch, "friction_b": 0.2, "contact_distance": radius}, t_max=1.5
    )
    wide = bc.collision_times(**{**batch, "friction_b": 0.2, "contact_distance": 0.2}, t_max=1.5)
    np.testing.assert_array_equal(mixed[0::2], ref[0::2])
    np.testing.assert_array_equal(mixed[1::2], wide[1::2])


def test_layouts_and_dtypes_give_the_same_answers() -> None:
    # Values exactly representable in float32, so that every dtype holds the same numbers.
    batch = {
        k: (
            np.asarray(v, dtype=np.float32).astype(np.float64)
            if k != "contact_distance"
            else 0.0625
        )
        for k, v in random_batch(4000, seed=7).items()
    }
    ref = bc.collision_times(**batch)
    assert np.isfinite(ref).sum() > 100
    rows = ("pos_a", "vel_a", "pos_b", "vel_b")
    scalars = ("friction_a", "friction_b")

    def big_strided(a: np.ndarray) -> np.ndarray:
        holder = np.zeros((a.shape[0] * 2, 5) if a.ndim == 2 else (a.shape[0] * 3,))
        view = holder[::2, 1:5:2] if a.ndim == 2 else holder[::3]
        view[...] = a
        assert not view.flags.c_contiguous
        return view

    conversions = {
        "fortran": lambda a: np.asfortranarray(a),
        "strided": big_strided,
        "transposed view": lambda a: np.ascontiguousarray(a.T).T,
        "list": lambda a: a.tolist(),
        "float32": lambda a: a.astype(np.float32),
        "longdouble": lambda a: a.astype(np.longdouble),
        "big-endian": lambda a: a.astype(">f8"),
        "read-only": lambda a: np.lib.stride_tricks.as_strided(a, writeable=False),
    }
    for name, convert in conversions.items():
        kwargs = dict(batch)
        for k in rows + scalars:
            kwargs[k] = convert(batch[k])
        t = bc.collision_times(**kwargs)
        np.testing.assert_array_equal(bits(t), bits(ref), err_msg=name)
    # The Fortran-ordered array really is Fortran-ordered, and the core reads it by rows.
    fortran = np.asfortranarray(batch["pos_a"])
    assert fortran.flags.f_contiguous and not fortran.flags.c_contiguous
    t = _core.collision_times(fortran, *(batch[k] for k in ARGS[1:]))
    np.testing.assert_array_equal(bits(t), bits(ref))


def test_integer_inputs() -> None:
    t = bc.collision_times(
        np.array([[0, 0]], dtype=np.int64), [[2, 0]], 0, [[3, 0]], [[0, 0]], 0, 1
    )
    assert t[0] == 1.0


def test_scalar_call_matches_batch_on_random_pairs() -> None:
    batch = random_batch(500, seed=11)
    t = bc.collision_times(**batch)
    for i in range(len(t)):
        one = bc.collision_time(*(batch[k][i] for k in ARGS[:-1]), batch["contact_distance"])
        assert bits(np.array([one]))[0] == bits(t)[i]


def test_contact_distance_at_collision_time() -> None:
    batch = random_batch(5000, seed=13)
    t = bc.collision_times(**batch)
    hit = np.isfinite(t) & (t > 0)
    assert hit.sum() > 500
    a = bc.positions_at(batch["pos_a"][hit], batch["vel_a"][hit], batch["friction_a"][hit], t[hit])
    b = bc.positions_at(batch["pos_b"][hit], batch["vel_b"][hit], batch["friction_b"][hit], t[hit])
    distance = np.hypot(*(a - b).T)
    # The answer is the exact contact time to the floor of its conditioning: the distance
    # then equals the radius closely for all but near-grazing contacts.
    close = np.abs(distance - batch["contact_distance"]) <= 1e-9 * batch["contact_distance"]
    assert close.mean() > 0.99


# --- positions_at ------------------------------------------------------------------------


def test_positions_at() -> None:
    pos = [[1, 1], [1, 1], [1, 1], [0, 0], [5, -1]]
    vel = [[2, 0], [2, 0], [2, 0], [3, 4], [0, 0]]
    friction = [0.5, 0.5, 0.5, 0.0, 0.7]
    t = [2.0, 4.0, 100.0, 2.0, 3.0]
    expected = [[4, 1], [5, 1], [5, 1], [6, 8], [5, -1]]
    np.testing.assert_array_equal(bc.positions_at(pos, vel, friction, t), expected)
    # Negative times count as 0; one time for all balls broadcasts.
    np.testing.assert_array_equal(bc.positions_at(pos, vel, friction, -1.0), pos)
    stopped = bc.positions_at([[1, 1]] * 3, [[2, 0]] * 3, 0.5, [4.0, 4.5, 1e9])
    np.testing.assert_array_equal(stopped, [[5, 1]] * 3)  # a stopped ball stays put


# --- real_roots --------------------------------------------------------------------------


def test_real_roots_well_conditioned_vs_numpy_roots() -> None:
    rng = np.random.default_rng(17)
    for k in (1, 2, 3, 4):
        roots = np.sort(
            rng.choice(np.arange(-20, 21), size=(500, k)) / 4 + rng.random((500, 1)), axis=1
        )
        # Keep the roots at least 0.2 apart: well conditioned.
        keep = np.all(np.diff(roots, axis=1) >= 0.2, axis=1)
        roots = roots[keep]
        lead = rng.uniform(0.5, 2, len(roots)) * rng.choice([-1, 1], len(roots))
        coeffs = np.array([a * np.poly(r) for a, r in zip(lead, roots)])
        got = bc.real_roots(coeffs)
        assert got.shape == (len(roots), k)
        np.testing.assert_allclose(got, roots, rtol=1e-10, atol=1e-12)
        via_numpy = np.array([np.sort(np.roots(c).real) for c in coeffs])
        np.testing.assert_allclose(got, via_numpy, rtol=1e-9, atol=1e-10)


def test_real_roots_complex_pairs_are_not_real_roots() -> None:
    # (x² + 1)(x − 2)(x + 3) and (x² + 2x + 5)(x² + 1): 2 and 0 real roots.
    c1 = np.poly([1j, -1j, 2, -3]).real
    c2 = np.poly([-1 + 2j, -1 - 2j, 1j, -1j]).real
    got = bc.real_roots([c1, c2])
    np.testing.assert_allclose(got[0, :2], [-3, 2], rtol=1e-14)
    assert np.isnan(got[0, 2:]).all() and np.isnan(got[1]).all()
    assert np.isnan(bc.real_roots([1, 0, 1])).all()


def test_real_roots_double_root() -> None:
    np.testing.assert_array_equal(bc.real_roots([1.0, -2.0, 1.0]), [1.0, 1.0])  # (x − 1)²
    np.testing.assert_array_equal(bc.real_roots([[4.0, -4.0, 1.0]]), [[0.5, 0.5]])  # (2x − 1)²
    # (x − 1)²(x − 3)² and (x − 1)²(x + 2): double roots kept with their multiplicity.
    quartic = bc.real_roots(np.poly([1, 1, 3, 3]))
    np.testing.assert_allclose(quartic, [1, 1, 3, 3], rtol=1e-7)
    cubic = bc.real_roots(np.poly([1, 1, -2]))
    np.testing.assert_allclose(cubic, [-2, 1, 1], rtol=1e-7)


def test_real_roots_leading_zeros_lower_the_degree() -> None:
    got = bc.real_roots([[0, 0, 1, -3, 2], [0, 0, 0, 2, -1], [0, 0, 0, 0, 5], [0, 0, 0, 0, 0]])
    np.testing.assert_array_equal(got[0], [1, 2, np.nan, np.nan])
    np.testing.assert_array_equal(got[1], [0.5, np.nan, np.nan, np.nan])
    assert np.isnan(got[2:]).all()  # constants have no isolated roots


def test_real_roots_accepts_lists_ints_and_layouts() -> None:
    coeffs = np.array([[1, -10, 35, -50, 24], [2, 0, -2, 0, 0]], dtype=np.int32)
    ref = bc.real_roots(coeffs.astype(np.float64))
    np.testing.assert_array_equal(ref, [[1, 2, 3, 4], [-1, 0, 0, 1]])
    for variant in (coeffs, coeffs.tolist(), np.asfortranarray(coeffs), coeffs[:, ::1].T.copy().T):
        np.testing.assert_array_equal(bc.real_roots(variant), ref)


# --- errors ------------------------------------------------------------------------------


def valid(n: int = 4) -> dict:
    return {
        "pos_a": np.zeros((n, 2)),
        "vel_a": np.ones((n, 2)),
        "friction_a": np.full(n, 0.1),
        "pos_b": np.full((n, 2), 3.0),
        "vel_b": np.zeros((n, 2)),
        "friction_b": np.full(n, 0.1),
        "contact_distance": np.full(n, 0.5),
        "t_max": np.full(n, np.inf),
    }


def raises(exc: type, message: str, **kwargs):
    with pytest.raises(exc, match="^" + re.escape(message)):
        bc.collision_times(**kwargs)


@pytest.mark.parametrize("name", ["pos_a", "vel_a", "pos_b", "vel_b"])
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_rows(name: str, bad: float) -> None:
    kwargs = valid()
    kwargs[name][2, 1] = bad
    raises(ValueError, f"{name}[2]: must be finite", **kwargs)


@pytest.mark.parametrize("name", ["friction_a", "friction_b", "contact_distance"])
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_values(name: str, bad: float) -> None:
    kwargs = valid()
    kwargs[name][1] = bad
    raises(ValueError, f"{name}[1]: must be finite", **kwargs)
    kwargs[name] = bad  # a scalar belongs to no pair in particular: no index
    raises(ValueError, f"{name}: must be finite", **kwargs)


def test_bad_values_name_argument_and_index() -> None:
    kwargs = valid()
    kwargs["friction_b"][3] = -0.5
    raises(ValueError, "friction_b[3]: friction must be ≥ 0, got -0.5", **kwargs)
    kwargs = valid()
    kwargs["contact_distance"][2] = 0.0
    raises(
        ValueError,
        "contact_distance[2]: the contact distance (sum of the two radii) must be > 0, got 0",
        **kwargs,
    )
    kwargs["contact_distance"] = -1.0
    raises(
        ValueError,
        "contact_distance: the contact distance (sum of the two radii) must be > 0, got -1",
        **kwargs,
    )
    for t_max in (-1.0, np.nan):
        kwargs = valid()
        kwargs["t_max"][1] = t_max
        raises(ValueError, "t_max[1]: must be ≥ 0", **kwargs)


def test_first_bad_index_wins_across_arguments_and_threads() -> None:
    n = 10_000  # several chunks, computed in parallel
    kwargs = valid(n)
    kwargs["pos_a"][7000] = np.nan
    kwargs["friction_b"][5003] = -1.0
    kwargs["contact_distance"][9000] = 0.0
    for threads in (1, 2, None):
        raises(ValueError, "friction_b[5003]:", **kwargs, num_threads=threads)


@pytest.mark.parametrize(
    ("name", "value", "message"),
    [
        ("pos_a", np.zeros(4), "pos_a: expected shape (N, 2), got (4,)"),
        ("vel_a", np.zeros((4, 3)), "vel_a: expected shape (N, 2), got (4, 3)"),
        ("pos_b", np.zeros((4, 2, 1)), "pos_b: expected shape (N, 2), got (4, 2, 1)"),
        ("vel_b", 1.0, "vel_b: expected shape (N, 2), got ()"),
        ("pos_b", np.zeros((3, 2)), "pos_b: has 3 rows, expected 4"),
        ("vel_b", np.zeros((5, 2)), "vel_b: has 5 rows, expected 4"),
        ("friction_a", np.zeros(3), "friction_a: has 3 rows, expected 4"),
        ("contact_distance", np.ones(5), "contact_distance: has 5 rows, expected 4"),
        ("t_max", np.ones(1), "t_max: has 1 rows, expected 4"),
        ("friction_b", np.zeros((4, 1)), "friction_b: expected a scalar or shape (N,)"),
        ("pos_a", [[0, 0], [1]], "pos_a: cannot be read as an array of numbers"),
    ],
)
def test_wrong_shapes(name: str, value: object, message: str) -> None:
    raises(ValueError, message, **{**valid(), name: value})


@pytest.mark.parametrize("name", [*ARGS, "t_max"])
@pytest.mark.parametrize(
    "value",
    [
        "abc",
        None,
        np.array([["a", "b"]] * 4),
        np.array([[None, 1.0]] * 4, dtype=object),
        np.ones((4, 2), dtype=complex),
        np.ones((4, 2), dtype=bool),
        np.zeros(4, dtype="datetime64[s]"),
    ],
)
def test_wrong_types(name: str, value: object) -> None:
    with pytest.raises(TypeError, match=f"^{name}: expected real numbers"):
        bc.collision_times(**{**valid(), name: value})


def test_num_threads_errors() -> None:
    for bad in (0, -1, -(2**70)):
        with pytest.raises(ValueError, match=r"^num_threads: must be None"):
            bc.collision_times(**valid(), num_threads=bad)
    for bad in (1.5, "2", True):
        with pytest.raises(TypeError, match=r"^num_threads: expected None or an int"):
            bc.collision_times(**valid(), num_threads=bad)
    big = bc.collision_times(**valid(), num_threads=2**70)  # capped to the cores there are
    np.testing.assert_array_equal(big, bc.collision_times(**valid()))
    with pytest.raises(bc.InputError, match=r"^num_threads"):
        bc.collision_times(**valid(), num_threads=0)
    # Keyword-only, as declared in the core's signature.
    with pytest.raises(TypeError, match="positional"):
        _core.collision_times(*valid().values(), 0)  # type: ignore[misc]


def test_scalar_call_errors_name_the_argument_without_index() -> None:
    args = [[0, 0], [1, 0], 0.1, [3, 0], [0, 0], 0.1, 0.5]
    cases = [
        (0, [np.nan, 0], ValueError, "pos_a: must be finite, got NaN"),
        (4, [0, np.inf], ValueError, "vel_b: must be finite, got inf"),
        (2, -0.5, ValueError, "friction_a: friction must be ≥ 0, got -0.5"),
        (
            6,
            0.0,
            ValueError,
            "contact_distance: the contact distance (sum of the two radii) must be > 0, got 0",
        ),
        (3, [1, 2, 3], ValueError, "pos_b: expected a 2-vector (x, y), got shape (3,)"),
        (5, [0.1, 0.2], ValueError, "friction_b: expected a scalar, got shape (2,)"),
        (1, ["a", "b"], TypeError, "vel_a: expected real numbers"),
    ]
    for index, value, exc, message in cases:
        bad = list(args)
        bad[index] = value
        with pytest.raises(exc, match="^" + re.escape(message)):
            bc.collision_time(*bad)
    with pytest.raises(ValueError, match=r"^t_max: must be ≥ 0"):
        bc.collision_time(*args, t_max=-1.0)


def test_positions_at_errors() -> None:
    pos, vel = np.zeros((3, 2)), np.ones((3, 2))
    with pytest.raises(ValueError, match=r"^t\[1\]: must be finite"):
        bc.positions_at(pos, vel, 0.1, [0.0, np.inf, 1.0])
    with pytest.raises(ValueError, match=r"^friction\[2\]: friction must be ≥ 0"):
        bc.positions_at(pos, vel, [0.1, 0.1, -0.1], 1.0)
    with pytest.raises(ValueError, match=r"^vel\[0\]: must be finite"):
        bc.positions_at(pos, np.full((3, 2), np.nan), 0.1, 1.0)
    with pytest.raises(ValueError, match=r"^vel: has 2 rows, expected 3"):
        bc.positions_at(pos, vel[:2], 0.1, 1.0)
    with pytest.raises(TypeError, match=r"^t: expected real numbers"):
        bc.positions_at(pos, vel, 0.1, "now")


def test_real_roots_errors() -> None:
    with pytest.raises(ValueError, match=r"^coeffs\[1\]: must be finite, got NaN"):
        bc.real_roots([[1, 2, 3], [1, np.nan, 2], [np.inf, 0, 0]])
    with pytest.raises(ValueError, match=r"^coeffs\[0\]: must be finite, got -inf"):
        bc.real_roots([1, -np.inf])
    for shape in [(3, 1), (3, 6), (0, 0)]:
        with pytest.raises(ValueError, match=r"^coeffs: expected shape \(N, k\+1\)"):
            bc.real_roots(np.ones(shape))
    with pytest.raises(ValueError, match=r"^coeffs: expected shape"):
        bc.real_roots(np.ones((2, 2, 2)))
    with pytest.raises(TypeError, match=r"^coeffs: expected real numbers"):
        bc.real_roots([["a", "b"]])


def test_the_package_functions_are_the_cores() -> None:
    # One layer: the package re-exports the compiled functions, which read any array-like.
    for name in bc.__all__:
        assert getattr(bc, name) is getattr(_core, name), name
    strided = np.zeros((4, 2))[::2]
    t = _core.collision_times([[0, 0], [0, 0]], [[1, 0], [2, 0]], 0, [[3, 0]] * 2, strided, 0, 1)
    assert t.tolist() == [2.0, 1.0]


# --- out= ---------------------------------------------------------------------------------


def test_out_receives_the_same_bits_and_is_returned() -> None:
    batch = random_batch(5_000, seed=23)
    fresh = bc.collision_times(**batch, num_threads=1)
    assert np.isfinite(fresh).sum() > 100
    out = np.full(5_000, -1.0)
    for threads in (1, 2):
        got = bc.collision_times(**batch, num_threads=threads, out=out)
        assert got is out
        np.testing.assert_array_equal(bits(out), bits(fresh))
    # Written again in place, whatever it held: a second batch's answers replace the first's.
    other = random_batch(5_000, seed=24)
    np.testing.assert_array_equal(
        bits(bc.collision_times(**other, out=out)), bits(bc.collision_times(**other))
    )
    pos, vel = batch["pos_a"], batch["vel_a"]
    t = np.linspace(0.0, 3.0, 5_000)
    centres = np.full((5_000, 2), np.nan)
    got = bc.positions_at(pos, vel, batch["friction_a"], t, out=centres)
    assert got is centres
    np.testing.assert_array_equal(
        bits(centres), bits(bc.positions_at(pos, vel, batch["friction_a"], t))
    )


def read_only(n: int) -> np.ndarray:
    a = np.empty(n)
    a.flags.writeable = False
    return a


def test_out_errors_name_out() -> None:
    batch = random_batch(4, seed=25)
    call = lambda out: bc.collision_times(**batch, out=out)  # noqa: E731
    for bad, exc, message in [
        (np.empty(3), ValueError, "out: expected shape (4,), got (3,)"),
        (
            np.empty((4, 1)),
            TypeError,
            "out: expected a 1-D float64 array of shape (N,), got a 2-D array of dtype float64",
        ),
        (
            np.empty(4, dtype=np.float32),
            TypeError,
            "out: expected a 1-D float64 array of shape (N,), got a 1-D array of dtype float32",
        ),
        ([0.0] * 4, TypeError, "out: expected a 1-D float64 array of shape (N,), got list"),
        (np.empty(8)[::2], ValueError, "out: expected a C-contiguous"),
        (read_only(4), ValueError, "out: the array is read-only"),
        (batch["friction_a"], ValueError, "out: the array shares memory with an input"),
    ]:
        with pytest.raises(exc, match="^" + re.escape(message)):
            call(bad)
    call(batch["pos_b"][:, 0].copy())  # a copy of an input's column is memory of its own
    # Memory shared with a row input: the first two rows of pos_a, flattened (a view).
    flat = batch["pos_a"].reshape(-1)[:4]
    with pytest.raises(ValueError, match=r"^out: the array shares memory with an input"):
        call(flat)
    pos = np.zeros((3, 2))
    with pytest.raises(ValueError, match=re.escape("out: expected shape (3, 2), got (3, 3)")):
        bc.positions_at(pos, pos, 0.1, 1.0, out=np.empty((3, 3)))
    with pytest.raises(ValueError, match=r"^out: expected a C-contiguous"):
        bc.positions_at(pos, pos, 0.1, 1.0, out=np.asfortranarray(np.empty((3, 2))))
    with pytest.raises(ValueError, match=r"^out: the array shares memory with an input"):
        bc.positions_at(pos, pos, 0.1, 1.0, out=pos)
    # An input error still names its argument and index; nothing else is promised of `out`.
    with pytest.raises(ValueError, match=r"^contact_distance\[2\]: the contact distance"):
        bc.collision_times(**{**batch, "contact_distance": [0.1, 0.1, -1.0, 0.1]}, out=np.empty(4))


def test_last_kernel_seconds_is_the_kernel_inside_the_call() -> None:
    batch = random_batch(200_000, seed=26)
    out = np.empty(200_000)
    start = time.perf_counter()
    bc.collision_times(**batch, num_threads=1, out=out)
    whole = time.perf_counter() - start
    kernel = _core._last_kernel_seconds()
    assert 0 < kernel <= whole
    bc.collision_times(**random_batch(2000, seed=27), num_threads=1)
    assert _core._last_kernel_seconds() < kernel  # the newest call's
    # Calls of up to 1024 pairs are not timed (the clock would add to a µs call).
    newest = _core._last_kernel_seconds()
    bc.collision_times(**random_batch(10, seed=28), num_threads=1)
    assert _core._last_kernel_seconds() == newest


# --- the GIL -----------------------------------------------------------------------------


def test_gil_is_released_during_a_batch() -> None:
    batch = {
        k: (np.ascontiguousarray(v) if isinstance(v, np.ndarray) else v)
        for k, v in random_batch(300_000, seed=19).items()
    }
    count = [0]
    stop = threading.Event()

    def counter() -> None:
        while not stop.is_set():
            count[0] += 1

    worker = threading.Thread(target=counter)
    worker.start()
    try:
        # The counter's pace when this thread does not hold the GIL (sleep releases it).
        start, begin = count[0], time.perf_counter()
        time.sleep(0.2)
        rate = (count[0] - start) / (time.perf_counter() - begin)
        start, begin = count[0], time.perf_counter()
        _core.collision_times(*(batch[k] for k in ARGS), num_threads=1)
        elapsed = time.perf_counter() - begin
        during = count[0] - start
    finally:
        stop.set()
        worker.join()
    assert elapsed > 0.02, "the batch was too quick to tell"
    # Holding the GIL, the call would let the counter advance for at most a switch
    # interval (5 ms); released, it keeps its pace.
    assert during > 0.3 * rate * elapsed, (during, rate, elapsed)


# --- the package -------------------------------------------------------------------------


def test_version_and_public_api() -> None:
    assert re.fullmatch(r"\d+\.\d+\.\d+.*", bc.__version__)
    assert bc.__version__ == _core.__version__
    # One list, the compiled module's; the package re-exports exactly it, all public and
    # documented, the benchmarks' hook left out.
    assert bc.__all__ == list(_core.__all__)
    assert len(set(bc.__all__)) == len(bc.__all__)
    for name in bc.__all__:
        assert name == "__version__" or not name.startswith("_"), name
        assert getattr(bc, name) is getattr(_core, name), name
        assert name == "__version__" or getattr(bc, name).__doc__, name
    assert "_last_kernel_seconds" not in bc.__all__
    assert callable(_core._last_kernel_seconds)
    # The stub lists the same names (stubtest checks its types against the module).
    stub = (Path(bc.__file__).parent / "_core.pyi").read_text()
    listed = re.search(r"__all__ = \[(.*?)\]", stub, re.S)
    assert listed is not None
    assert set(re.findall(r'"(\w+)"', listed.group(1))) == set(bc.__all__)


def test_simulate_returns_a_named_result() -> None:
    run = bc.simulate([[0.5, 0.5]], [[1, 0]], 0.0, 0.25, box=([0, 0], [2, 1]), t_end=2.0)
    assert isinstance(run, bc.Simulation)
    assert run._fields == ("times", "i", "j", "pos", "vel", "kind", "index", "captured")
    times, i, j, pos, vel, kind, index, captured = run  # still a tuple
    assert (kind.tolist(), index.tolist(), captured.tolist()) == ([bc.WALL], [1], [-1])
    assert pos is run.pos
    assert times is run.times and vel is run.vel
    assert (times.tolist(), i.tolist(), j.tolist()) == ([1.25], [0], [-1])


def test_docstring_examples() -> None:
    result = doctest.testmod(bc, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.attempted >= 10 and result.failed == 0


def test_typed_package() -> None:
    package = Path(bc.__file__).parent
    assert (package / "py.typed").exists()
    assert (package / "_core.pyi").exists()


# --- contact_distance and its deprecated name radius= ---------------------------------------

# Each pair call from its keyword arguments but the contact distance: (name, call).
PAIR_CALLS = {
    "collision_time": lambda **d: bc.collision_time(
        [0, 0], [1, 0], 0.0, [1, 0], [0, 0], 0.0, **d, t_max=5.0
    ),
    "collision_times": lambda **d: bc.collision_times(
        [[0, 0]], [[1, 0]], 0.0, [[1, 0]], [[0, 0]], 0.0, **d
    ),
    "path_collision_time": lambda **d: bc.path_collision_time(
        ([0.0], [[0, 0]], [[1, 0]], [[0, 0]]), ([0.0], [[1, 0]], [[0, 0]], [[0, 0]]), **d
    ),
    "path_collision_times": lambda **d: bc.path_collision_times(
        [[0.0]],
        [[[0, 0]]],
        [[[1, 0]]],
        [[[0, 0]]],
        [[0.0]],
        [[[1, 0]]],
        [[[0, 0]]],
        [[[0, 0]]],
        **d,
    ),
}


@pytest.mark.parametrize("name", list(PAIR_CALLS))
def test_the_old_name_radius_still_works_with_a_deprecation_warning(name: str) -> None:
    call = PAIR_CALLS[name]
    now = np.asarray(call(contact_distance=0.5))
    assert np.array_equal(now, [0.5]) or now.tolist() == 0.5
    with pytest.warns(DeprecationWarning, match=r"^radius= is deprecated .*contact_distance=") as w:
        old = np.asarray(call(radius=0.5))
    assert np.array_equal(old, now)
    # Reported at the caller's line (this file), where Python's filters show it.
    assert [Path(r.filename).name for r in w] == [Path(__file__).name]
    with pytest.raises(TypeError, match=r"^contact_distance: given twice"):
        call(contact_distance=0.5, radius=0.5)
    with pytest.raises(TypeError, match=r"^contact_distance: missing"):
        call()
    # A value the old name gives is read, and named, as the new one.
    with pytest.warns(DeprecationWarning), pytest.raises(bc.InputError) as e:
        call(radius=-1.0)
    assert (e.value.argument, e.value.kind) == ("contact_distance", "non_positive_radius")


def test_the_scene_calls_keep_radius_as_each_balls_own() -> None:
    t, i, j = bc.earliest_collision([[0, 0], [2, 0]], [[1, 0], [0, 0]], 0.0, radius=0.5)
    assert (t, i, j) == (1.0, 0, 1)  # centres 1 apart, the sum of the two radii
