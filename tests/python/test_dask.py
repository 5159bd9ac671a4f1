"""ballcollide.dask: lazy, chunked collision times, bitwise equal to one in-memory call."""

from __future__ import annotations

import doctest
import logging
import multiprocessing
import subprocess
import sys
import textwrap
from concurrent.futures import ProcessPoolExecutor
from typing import Any

import numpy as np
import pytest

import ballcollide as bc

da = pytest.importorskip("dask.array", reason="dask is not installed (ballcollide[dask])")
dask = pytest.importorskip("dask")
import ballcollide.dask as bcd  # noqa: E402  (only once dask is known to be there)

NAMES = ("pos_a", "vel_a", "friction_a", "pos_b", "vel_b", "friction_b", "contact_distance")
ROWS = ("pos_a", "vel_a", "pos_b", "vel_b")
N = 501  # pairs; prime, so that no chunk size divides it


def scene(n: int = N, seed: int = 7) -> dict[str, Any]:
    """Shots on a table with some balls touching, at rest or without friction, as numpy."""
    rng = np.random.default_rng(seed)
    pos_a = rng.uniform(0.0, 2.0, (n, 2))
    pos_b = rng.uniform(0.0, 2.0, (n, 2))
    pos_b[::17] = pos_a[::17] + [0.05, 0.0]  # touching or overlapping at t = 0
    vel_a = rng.normal(0.0, 2.0, (n, 2))
    vel_b = rng.normal(0.0, 0.5, (n, 2))
    vel_b[::5] = 0.0  # at rest
    friction_a = rng.uniform(0.0, 0.5, n)
    friction_a[::7] = 0.0  # no friction
    return {
        "pos_a": pos_a,
        "vel_a": vel_a,
        "friction_a": friction_a,
        "pos_b": pos_b,
        "vel_b": vel_b,
        "friction_b": 0.2,
        "contact_distance": rng.uniform(0.05, 0.6, n),
    }


@pytest.fixture(scope="module")
def pairs() -> dict[str, Any]:
    return scene()


@pytest.fixture(scope="module")
def expected(pairs: dict[str, Any]) -> np.ndarray:
    t = bc.collision_times(**pairs)
    assert 0.1 < np.isfinite(t).mean() < 0.9 and (t == 0).any()  # a varied scene
    return t


def as_dask(pairs: dict[str, Any], chunks: Any) -> dict[str, Any]:
    """Every array of ``pairs`` as a Dask array with ``chunks`` along the pairs."""
    out = dict(pairs)
    for name, x in pairs.items():
        if isinstance(x, np.ndarray):
            out[name] = da.from_array(x, chunks=(chunks, 2) if x.ndim == 2 else (chunks,))
    return out


def assert_bitwise(got: Any, expected: np.ndarray) -> None:
    got = np.asarray(got)
    assert got.dtype == np.float64 and got.shape == expected.shape
    np.testing.assert_array_equal(got.view(np.int64), expected.view(np.int64))


# --- results -------------------------------------------------------------------------------


@pytest.mark.parametrize("scheduler", ["threads", "sync"])
def test_schedulers_in_process(pairs: dict, expected: np.ndarray, scheduler: str) -> None:
    t = bcd.collision_times(**as_dask(pairs, 64))
    assert_bitwise(t.compute(scheduler=scheduler), expected)


def test_processes_scheduler(pairs: dict, expected: np.ndarray) -> None:
    t = bcd.collision_times(**as_dask(pairs, 100))
    bad = dict(pairs, friction_a=pairs["friction_a"].copy())
    bad["friction_a"][345] = -0.5
    bad_t = bcd.collision_times(**as_dask(bad, 100))
    # One pool of 2 spawned processes (Dask's default start method) for both computations.
    context = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(2, mp_context=context) as pool:
        assert_bitwise(t.compute(scheduler="processes", pool=pool), expected)
        with pytest.raises(ValueError, match=r"^friction_a\[345\]: friction must be ≥ 0"):
            bad_t.compute(scheduler="processes", pool=pool)


def test_distributed_local_cluster(pairs: dict, expected: np.ndarray) -> None:
    distributed = pytest.importorskip(
        "distributed", reason="distributed is not installed: no LocalCluster to test on"
    )
    bad = dict(pairs, vel_b=pairs["vel_b"].copy())
    bad["vel_b"][400, 1] = np.nan
    with (
        distributed.LocalCluster(
            n_workers=2,
            threads_per_worker=1,
            processes=True,
            dashboard_address=":0",  # any free port: never clashes with another cluster
            silence_logs=logging.ERROR,
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        t = bcd.collision_times(**as_dask(pairs, 77))
        assert_bitwise(client.compute(t).result(), expected)
        # Both worker processes took part.
        assert len(client.scheduler_info()["workers"]) == 2
        with pytest.raises(ValueError, match=r"^vel_b\[400\]: must be finite, got NaN"):
            client.compute(bcd.collision_times(**as_dask(bad, 77))).result()


@pytest.mark.parametrize(
    "chunks",
    [
        (1, 1, 1, 1, 497),  # chunks of one pair
        7,
        64,
        250,  # last chunk of 1
        N,  # a single chunk
        (0, 100, 0, 0, 300, 101, 0),  # chunks with zero rows, first and last too
    ],
)
def test_odd_chunks(pairs: dict, expected: np.ndarray, chunks: Any) -> None:
    t = bcd.collision_times(**as_dask(pairs, chunks))
    want = da.core.normalize_chunks(chunks, (N,))
    assert t.chunks == want
    assert_bitwise(t.compute(scheduler="sync"), expected)


def test_zero_pairs() -> None:
    empty = np.zeros((0, 2))
    t = bcd.collision_times(da.from_array(empty), empty, 0.0, empty, empty, 0.0, 1.0)
    assert t.shape == (0,) and t.dtype == np.float64
    assert t.compute().shape == (0,)
    t = bcd.collision_times(empty, empty, np.zeros(0), empty, empty, 0.0, 1.0)
    assert t.compute().shape == (0,)


def test_arguments_chunked_differently(pairs: dict, expected: np.ndarray) -> None:
    d = as_dask(pairs, 100)
    d["vel_a"] = da.from_array(pairs["vel_a"], chunks=(37, 1))  # columns split too
    d["friction_a"] = da.from_array(pairs["friction_a"], chunks=250)
    d["contact_distance"] = da.from_array(pairs["contact_distance"], chunks=((0, 501),))
    d["pos_b"] = da.from_array(pairs["pos_b"], chunks=(501, 1))
    t = bcd.collision_times(**d)
    assert t.chunks == ((100, 100, 100, 100, 100, 1),)  # pos_a's, the first Dask argument
    assert_bitwise(t.compute(), expected)
    # With numpy pos_a, the first Dask argument sets the chunks.
    d["pos_a"] = pairs["pos_a"]
    t = bcd.collision_times(**d)
    assert t.chunks == ((37,) * 13 + (20,),)
    assert_bitwise(t.compute(), expected)


@pytest.mark.parametrize("mask", range(0, 64, 5))
def test_mixed_numpy_dask_and_lists(pairs: dict, expected: np.ndarray, mask: int) -> None:
    """Each array argument is, by the bits of ``mask``, a Dask array or numpy/a list."""
    args = dict(pairs)
    arrays = [name for name in NAMES if isinstance(pairs[name], np.ndarray)]
    for bit, name in enumerate(arrays):
        if mask >> bit & 1:
            args[name] = da.from_array(pairs[name], chunks=60 if name in ROWS else 90)
        elif bit % 2:
            args[name] = pairs[name].tolist()
    t = bcd.collision_times(**args)
    assert isinstance(t, da.Array)
    assert_bitwise(t.compute(), expected)


def test_numpy_only_gives_auto_chunks(pairs: dict, expected: np.ndarray) -> None:
    t = bcd.collision_times(**pairs)
    assert isinstance(t, da.Array) and t.numblocks == (1,)
    assert_bitwise(t.compute(), expected)


def test_scalar_and_per_pair_parameters(pairs: dict) -> None:
    n = N
    rng = np.random.default_rng(3)
    per_pair = {
        "friction_a": rng.uniform(0.0, 0.5, n),
        "friction_b": rng.uniform(0.0, 0.5, n),
        "contact_distance": rng.uniform(0.05, 0.6, n),
        "t_max": rng.choice([0.0, 0.3, 1.0, np.inf], n),
    }
    scalar = {"friction_a": 0.3, "friction_b": 0.0, "contact_distance": 0.25, "t_max": 0.8}
    for name in per_pair:
        for value in (scalar[name], per_pair[name]):
            args = {**pairs, name: value}
            want = bc.collision_times(**args)
            kinds: list[Any] = [value]
            if np.ndim(value) == 1:
                kinds += [da.from_array(value, chunks=33), value.tolist()]
            else:
                kinds += [np.float64(value), np.array(value), da.from_array(np.array(value))]
            for v in kinds:
                t = bcd.collision_times(**as_dask(pairs, 50) | {name: v})
                assert_bitwise(t.compute(), want)


def test_integer_inputs(pairs: dict) -> None:
    ints = {name: np.round(x * 10).astype(np.int32) for name, x in pairs.items()}
    ints["contact_distance"] = 3
    want = bc.collision_times(**ints)
    assert_bitwise(bcd.collision_times(**as_dask(ints, 40)).compute(), want)


def test_lazy_with_explicit_meta(pairs: dict) -> None:
    t = bcd.collision_times(**as_dask(pairs, 64), t_max=2.0)
    assert t.dtype == np.float64 and t.shape == (N,)
    assert type(t._meta) is np.ndarray and t._meta.shape == (0,)
    assert t.name.startswith("collision_times-")
    # One task per chunk on top of the inputs', nothing computed yet.
    assert len(t.dask.layers[t.name]) == t.numblocks[0]


def test_one_kernel_call_per_chunk_on_one_thread(
    pairs: dict, expected: np.ndarray, monkeypatch: pytest.MonkeyPatch
) -> None:
    calls: list[tuple[int, Any]] = []

    def spy(*args: Any, **kwargs: Any) -> np.ndarray:
        calls.append((len(args[0]), kwargs["num_threads"]))
        return bc.collision_times(*args, **kwargs)

    monkeypatch.setattr(bcd, "_collision_times", spy)
    assert_bitwise(bcd.collision_times(**as_dask(pairs, 100)).compute(scheduler="sync"), expected)
    assert sorted(calls) == [(1, 1)] + [(100, 1)] * 5
    calls.clear()
    t = bcd.collision_times(**as_dask(pairs, 300), num_threads=None)
    assert_bitwise(t.compute(scheduler="sync"), expected)
    assert sorted(calls, key=str) == [(201, None), (300, None)]


@pytest.mark.parametrize("num_threads", [None, 1, 2, 10**9])
def test_num_threads_does_not_change_results(
    pairs: dict, expected: np.ndarray, num_threads: int | None
) -> None:
    t = bcd.collision_times(**as_dask(pairs, 128), num_threads=num_threads)
    assert_bitwise(t.compute(), expected)


# --- errors --------------------------------------------------------------------------------

BAD_VALUES = [
    ("pos_a", (1,), np.inf, r"must be finite, got inf"),
    ("vel_a", (0,), np.nan, r"must be finite, got NaN"),
    ("friction_a", (), -0.1, r"friction must be ≥ 0, got -0.1"),
    ("pos_b", (1,), -np.inf, r"must be finite, got -inf"),
    ("vel_b", (1,), np.nan, r"must be finite, got NaN"),
    (
        "contact_distance",
        (),
        0.0,
        r"the contact distance \(sum of the two radii\) must be > 0, got 0",
    ),
    ("t_max", (), -1.0, r"must be ≥ 0 \(∞ for none\)"),
]


@pytest.mark.parametrize(("name", "col", "value", "message"), BAD_VALUES)
@pytest.mark.parametrize("index", [0, 99, 100, 377, N - 1])
def test_bad_value_names_its_global_index(
    pairs: dict, name: str, col: tuple, value: float, message: str, index: int
) -> None:
    args = {**pairs, "t_max": np.full(N, np.inf)}
    args[name] = args[name].copy()
    args[name][(index, *col)] = value
    # The same error as the in-memory call …
    with pytest.raises(ValueError, match=rf"^{name}\[{index}\]: {message}"):
        bc.collision_times(**args)
    for chunks in (100, (0, 50, 0, 300, 151)):
        t = bcd.collision_times(**as_dask(args, chunks))  # … lazily: no error yet
        with pytest.raises(ValueError, match=rf"^{name}\[{index}\]: {message}"):
            t.compute()
    # From a numpy argument mixed with Dask ones too.
    t = bcd.collision_times(**{**as_dask(args, 100), name: args[name]})
    with pytest.raises(ValueError, match=rf"^{name}\[{index}\]: {message}"):
        t.compute(scheduler="sync")


def test_bad_scalars_fail_at_once(pairs: dict) -> None:
    d = as_dask(pairs, 100)
    with pytest.raises(
        ValueError,
        match=r"^contact_distance: the contact distance \(sum of the two radii\) must be > 0",
    ):
        bcd.collision_times(**{**d, "contact_distance": -1.0})
    with pytest.raises(ValueError, match=r"^friction_b: friction must be ≥ 0, got -2"):
        bcd.collision_times(**{**d, "friction_b": np.float32(-2.0)})
    with pytest.raises(ValueError, match=r"^t_max: must be ≥ 0"):
        bcd.collision_times(**d, t_max=np.nan)
    with pytest.raises(ValueError, match=r"^friction_a: must be finite"):
        bcd.collision_times(**{**d, "friction_a": np.inf})
    # A 0-d Dask scalar is only known when computed: named without an index.
    t = bcd.collision_times(**{**d, "contact_distance": da.from_array(np.array(-1.0))})
    with pytest.raises(
        ValueError,
        match=r"^contact_distance: the contact distance \(sum of the two radii\) must be > 0",
    ):
        t.compute()


def test_shape_errors_are_eager(pairs: dict) -> None:
    d = as_dask(pairs, 100)
    cases: list[tuple[str, Any, str]] = [
        ("pos_a", d["pos_a"][:, 0], r"^pos_a: expected shape \(N, 2\), got \(501,\)"),
        ("vel_a", da.zeros((N, 3)), r"^vel_a: expected shape \(N, 2\), got \(501, 3\)"),
        ("pos_b", np.zeros((N, 2, 1)), r"^pos_b: expected shape \(N, 2\)"),
        ("vel_b", 1.0, r"^vel_b: expected shape \(N, 2\), got \(\)"),
        ("friction_a", da.zeros((N, 1)), r"^friction_a: expected a scalar or shape \(N,\)"),
        (
            "contact_distance",
            np.ones((N, 2)),
            r"^contact_distance: expected a scalar or shape \(N,\)",
        ),
        ("vel_a", da.zeros((N - 1, 2)), r"^vel_a: has 500 rows, expected 501"),
        ("friction_b", np.zeros(N + 1), r"^friction_b: has 502 rows, expected 501"),
        ("contact_distance", da.ones(3), r"^contact_distance: has 3 rows, expected 501"),
        ("pos_a", [[0.0, 0.0], [1.0]], r"^pos_a: cannot be read as an array of numbers"),
    ]
    for name, value, message in cases:
        with pytest.raises(ValueError, match=message):
            bcd.collision_times(**{**d, name: value})
    with pytest.raises(ValueError, match=r"^t_max: has 2 rows, expected 501"):
        bcd.collision_times(**d, t_max=da.ones(2))
    # The first argument's length is the one the others must have.
    with pytest.raises(ValueError, match=r"^vel_a: has 501 rows, expected 3"):
        bcd.collision_times(**{**d, "pos_a": np.zeros((3, 2))})


def test_type_errors_are_eager(pairs: dict) -> None:
    d = as_dask(pairs, 100)
    with pytest.raises(
        TypeError, match=r"^contact_distance: expected real numbers, got .*complex128"
    ):
        bcd.collision_times(**{**d, "contact_distance": d["contact_distance"] + 0j})
    with pytest.raises(TypeError, match=r"^pos_b: expected real numbers, got .*bool"):
        bcd.collision_times(**{**d, "pos_b": d["pos_b"] > 0})
    with pytest.raises(TypeError, match=r"^friction_a: expected real numbers"):
        bcd.collision_times(**{**d, "friction_a": "0.1"})
    with pytest.raises(TypeError, match="num_threads"):
        bcd.collision_times(**d, num_threads=1.5)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="num_threads"):
        bcd.collision_times(**d, num_threads=0)


def test_unknown_chunk_sizes(pairs: dict) -> None:
    d = as_dask(pairs, 100)
    pos_a = d["pos_a"][d["pos_a"][:, 0] > 1.0]  # a boolean mask: lengths unknown
    with pytest.raises(ValueError, match=r"^pos_a: its chunk sizes are unknown.*compute_chunk"):
        bcd.collision_times(**{**d, "pos_a": pos_a})


# --- packaging -----------------------------------------------------------------------------


def run_python(code: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-c", textwrap.dedent(code)],
        capture_output=True,
        text=True,
        timeout=60,
    )


def test_importing_ballcollide_does_not_import_dask() -> None:
    result = run_python(
        """
        import sys
        import ballcollide, ballcollide.demo
        ballcollide.collision_times([[0, 0]], [[1, 0]], 0.0, [[1, 0]], [[0, 0]], 0.0, 0.5)
        loaded = sorted(m for m in sys.modules if m.split(".")[0] in ("dask", "distributed"))
        assert not loaded, loaded
        import ballcollide.dask
        assert "dask.array" in sys.modules
        """
    )
    assert result.returncode == 0, result.stderr


def test_missing_dask_says_how_to_install() -> None:
    result = run_python(
        """
        import sys
        sys.modules["dask"] = None  # as if dask were not installed
        import ballcollide
        try:
            import ballcollide.dask
        except ImportError as e:
            print(e)
        else:
            raise AssertionError("no ImportError")
        """
    )
    assert result.returncode == 0, result.stderr
    assert "pip install 'ballcollide[dask]'" in result.stdout


def test_docstring_examples() -> None:
    # simulate_many's example needs pooltool: tests/pooltool_integration/test_dask_shots.py
    # runs it where pooltool is installed.
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    for test in doctest.DocTestFinder().find(bcd):
        if not test.name.endswith(".simulate_many"):
            runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.attempted > 10 and result.failed == 0


def test_the_old_name_radius_still_works_with_a_deprecation_warning() -> None:
    args = (da.zeros((3, 2), chunks=2), np.ones((3, 2)), 0.0, np.ones((3, 2)), np.ones((3, 2)))
    now = bcd.collision_times(*args, 0.0, contact_distance=0.5).compute()
    with pytest.warns(DeprecationWarning, match=r"^radius= is deprecated") as w:
        old = bcd.collision_times(*args, 0.0, radius=0.5)
    assert [r.filename for r in w] == [__file__]  # the caller's line
    assert np.array_equal(old.compute(), now)
    with pytest.raises(TypeError, match=r"^contact_distance: given twice"):
        bcd.collision_times(*args, 0.0, 0.5, radius=0.5)
    with pytest.raises(TypeError, match=r"^contact_distance: missing"):
        bcd.collision_times(*args, 0.0)
    # None is a value, as for ballcollide.collision_times: given, and a bad one.
    with pytest.raises(TypeError, match=r"^contact_distance: given twice"):
        bcd.collision_times(*args, 0.0, None, radius=0.5)
    with pytest.raises(TypeError, match=r"^contact_distance: expected real numbers"):
        bcd.collision_times(*args, 0.0, None)
