"""The scene queries over the whole float range (hypothesis): pairwise_collision_times equals
the brute-force collision_time loop bit for bit, on one thread and on two; earliest_collision
and first_contacts are read off it with the documented tie-breaking; valid input never raises.
The Rust fuzz target ``scene`` and tests/integration/invariants_scene.rs check the same."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, note
from hypothesis import strategies as st
from invariant_strategies import INF, Ball, ball, case_scale, radius, same, t_max, time

import ballcollide as bc

scenes = case_scale.flatmap(
    lambda s: st.tuples(st.lists(st.tuples(ball(s), radius(s)), min_size=2, max_size=12), t_max)
)


def brute(balls: list[Ball], radii: list[float], horizon: float) -> np.ndarray:
    n = len(balls)
    m = np.full((n, n), INF)
    for i in range(n):
        for j in range(i + 1, n):
            s = radii[i] + radii[j]
            if math.isfinite(s):
                t = time(balls[i], balls[j], s, horizon)
            else:  # halve every length of the pair: exact, and times do not depend on units

                def h(x: float) -> float:
                    return x / 2

                t = time(
                    balls[i].map(h, h, h),
                    balls[j].map(h, h, h),
                    radii[i] / 2 + radii[j] / 2,
                    horizon,
                )
            m[i, j] = m[j, i] = t
    return m


@given(scenes)
def test_the_scene_equals_the_brute_force_pairs(
    scene: tuple[list[tuple[Ball, float]], float],
) -> None:
    entries, horizon = scene
    balls = [b for b, _ in entries]
    radii = [r for _, r in entries]
    if not (all(b.valid() for b in balls) and horizon >= 0.0):
        return
    # The broad phase proves pairs apart everywhere; the pair kernel is exact only within the
    # contract's range (non-zero magnitudes within 2^±400 of each other: docs/contract.md §5),
    # and outside it the two may differ (tests/support/invariants.rs checks all pairs there).
    sizes = [abs(x) for b in balls for x in (b.px, b.py, b.vx, b.vy, b.mu)] + radii
    sizes = [x for x in sizes if x > 0.0]
    if max(sizes) > min(sizes) * 2.0**400:
        return
    note(f"{balls!r} {radii!r} {horizon!r}")
    pos = np.array([[b.px, b.py] for b in balls])
    vel = np.array([[b.vx, b.vy] for b in balls])
    mu = np.array([b.mu for b in balls])
    rad = np.array(radii)
    want = brute(balls, radii, horizon)
    for threads in (1, 2):
        got = bc.pairwise_collision_times(pos, vel, mu, rad, t_max=horizon, num_threads=threads)
        assert all(same(float(x), float(y)) for x, y in zip(got.ravel(), want.ravel()))
    t, i, j = bc.earliest_collision(pos, vel, mu, rad, t_max=horizon)
    n = len(balls)
    best = min(
        ((want[a, b], a, b) for a in range(n) for b in range(a + 1, n)), default=(INF, -1, -1)
    )
    if best[0] == INF:
        best = (INF, -1, -1)
    assert (t, i, j) == best
    times, partners = bc.first_contacts(pos, vel, mu, rad, t_max=horizon)
    for a in range(n):
        row = [(want[a, b], b) for b in range(n) if b != a]
        tb, pb = min(row)
        assert same(float(times[a]), tb) and int(partners[a]) == (pb if tb < INF else -1)
