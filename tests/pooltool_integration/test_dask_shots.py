"""``ballcollide.dask.simulate_many``: pooltool shots over a 2-process
``distributed.LocalCluster``, gathered bit for bit as one in-memory ``simulate_many`` call."""

from __future__ import annotations

import doctest
import logging
from typing import Any

import pytest

pt = pytest.importorskip("pooltool")
distributed = pytest.importorskip("distributed")

import numpy as np  # noqa: E402

import ballcollide  # noqa: E402
import ballcollide.dask as bcd  # noqa: E402
import ballcollide.pooltool as bcp  # noqa: E402

from .test_engine import named_shots  # noqa: E402


def assert_same(got: Any, expected: Any) -> None:
    assert len(got) == len(expected)
    assert got._arrays.keys() == expected._arrays.keys()
    for key, want in expected._arrays.items():
        have = got._arrays[key]
        if isinstance(want, np.ndarray):
            assert have.dtype == want.dtype, key
            assert np.array_equal(have, want, equal_nan=True), key
        else:
            assert have == want, key


def test_shots_over_a_local_cluster_are_the_in_memory_call() -> None:
    shots = [s for _, s in named_shots()[::6]]  # 35 shots: breaks, spin, massé, snooker
    expected = bcp.simulate_many(shots, num_threads=1, history=True)
    bad = pt.System.example()
    bad.balls["cue"].state.rvw[0, 0] = np.nan
    with (
        distributed.LocalCluster(
            n_workers=2,
            threads_per_worker=1,
            processes=True,
            dashboard_address=":0",
            silence_logs=logging.ERROR,
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        assert len(client.scheduler_info()["workers"]) == 2
        for chunk_size in (1, 8, len(shots)):
            with distributed.get_task_stream(client) as stream:
                got = bcd.simulate_many(shots, chunk_size=chunk_size, history=True)
            assert_same(got, expected)
            if chunk_size == 1:  # 35 chunks: both worker processes took part
                assert len({task["worker"] for task in stream.data}) == 2
        # The error names the bad shot by its place in the whole sequence.
        with pytest.raises(ballcollide.InputError) as error:
            bcd.simulate_many([*shots, bad], chunk_size=8)
        assert error.value.argument == f"shots[{len(shots)}].position"
        assert error.value.index == 0 and error.value.kind == "not_finite"
        assert str(error.value).startswith(f"shots[{len(shots)}].position[0]: must be finite")
        # As is a cue whose ball is not among its shot's (a ValueError, as in memory).
        stray = pt.System.example()
        stray.cue.cue_ball_id = "nope"
        with pytest.raises(ValueError, match=rf"^shots\[{len(shots)}\]: the cue's ball 'nope'"):
            bcd.simulate_many([*shots, stray], chunk_size=8)
    # to_system builds a shot's System from the gathered arrays.
    built = got.to_system(3)
    assert [e.time for e in built.events] == [e.time for e in bcp.simulate(shots[3]).events]


def test_no_shots_and_bad_chunk_sizes() -> None:
    assert len(bcd.simulate_many([], chunk_size=4)) == 0
    for bad in (0, -1, 1.5, True, "2"):
        with pytest.raises(ballcollide.InputError, match=r"^chunk_size: must be an int ≥ 1"):
            bcd.simulate_many([pt.System.example()], chunk_size=bad)  # type: ignore[arg-type]
    with pytest.raises(bcp.UnsupportedError):
        bcd.simulate_many([pt.System.example()], contact_rule="sticky")


def test_the_docstring_example() -> None:
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    for test in doctest.DocTestFinder().find(bcd.simulate_many, "simulate_many", globs={}):
        runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.attempted >= 2 and result.failed == 0
