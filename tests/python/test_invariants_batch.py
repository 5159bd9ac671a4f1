"""collision_times over the whole float range (hypothesis): each pair's time is collision_time's,
bit for bit, on one thread and on two, with shared or per-pair parameters; valid input never
raises. The Rust fuzz target ``batch`` and tests/integration/invariants_batch.rs check the same."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from hypothesis import given, note
from hypothesis import strategies as st
from invariant_strategies import Pair, case_scale, pair_at, same, time

import ballcollide as bc

batches = case_scale.flatmap(
    lambda s: st.tuples(
        st.lists(pair_at(s), min_size=1, max_size=40),
        st.lists(st.booleans(), min_size=4, max_size=4),
    )
)


@given(batches)
def test_batch_equals_the_scalar_search(batch: tuple[list[Pair], list[bool]]) -> None:
    cases, shared = batch
    first = cases[0]
    cases = [
        replace(
            c,
            a=replace(c.a, mu=first.a.mu) if shared[0] else c.a,
            b=replace(c.b, mu=first.b.mu) if shared[1] else c.b,
            radius=first.radius if shared[2] else c.radius,
            t_max=first.t_max if shared[3] else c.t_max,
        )
        for c in cases
    ]
    if not all(c.valid() for c in cases):
        return
    note(f"{cases!r} shared {shared!r}")

    def param(i: int, xs: list[float]) -> float | np.ndarray:
        return xs[0] if shared[i] else np.array(xs)

    args = (
        np.array([[c.a.px, c.a.py] for c in cases]),
        np.array([[c.a.vx, c.a.vy] for c in cases]),
        param(0, [c.a.mu for c in cases]),
        np.array([[c.b.px, c.b.py] for c in cases]),
        np.array([[c.b.vx, c.b.vy] for c in cases]),
        param(1, [c.b.mu for c in cases]),
        param(2, [c.radius for c in cases]),
    )
    horizon = param(3, [c.t_max for c in cases])
    one = bc.collision_times(*args, t_max=horizon, num_threads=1)
    two = bc.collision_times(*args, t_max=horizon, num_threads=2)
    for i, c in enumerate(cases):
        want = time(c.a, c.b, c.radius, c.t_max)
        assert same(float(one[i]), want) and same(float(two[i]), want), (i, one[i], two[i], want)
