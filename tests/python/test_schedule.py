"""The event calendar, bc.CollisionSchedule: bit for bit the brute force of
bc.path_collision_times over every pair after random sequences of updates (hypothesis), wall
contacts against mpmath references, friction balls, refused updates that change nothing,
and the errors' arguments and indices."""

from __future__ import annotations

import doctest
import math

import mpmath
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import ballcollide as bc

mpmath.mp.dps = 60


def bits(x: float) -> int:
    return int(np.float64(x).view(np.uint64))


def arrays(paths: list[list[tuple]], dim: int) -> tuple[np.ndarray, ...]:
    """Paths (lists of segments ``(s, p, v, a)``) as ``(N, K)`` and ``(N, K, D)`` arrays,
    padded with ``+inf`` starts."""
    n, k = len(paths), max((len(p) for p in paths), default=1)
    start = np.full((n, k), np.inf)
    pos, vel, acc = (np.zeros((n, k, dim)) for _ in range(3))
    for i, path in enumerate(paths):
        for j, (s, p, v, a) in enumerate(path):
            start[i, j], pos[i, j], vel[i, j], acc[i, j] = s, p, v, a
    return start, pos, vel, acc


def brute(paths: list[list[tuple]], radii: list[float], dim: int, now: float, t_max: float):
    """The earliest ``(t, i, j)`` over all pairs with ``t ≥ now``, from path_collision_times."""
    n = len(paths)
    pairs = [(i, j) for i in range(n) for j in range(i + 1, n)]
    if not pairs:
        return (math.inf, -1, -1)
    a = arrays([paths[i] for i, _ in pairs], dim)
    b = arrays([paths[j] for _, j in pairs], dim)
    r = np.array([radii[i] + radii[j] for i, j in pairs])
    times = bc.path_collision_times(*a, *b, r, t_max=t_max)
    best = (math.inf, -1, -1)
    for (i, j), t in zip(pairs, times):
        if now <= t < best[0]:
            best = (float(t), i, j)
    return best


small = st.integers(-16, 16).map(lambda k: k / 8)


@st.composite
def segment_values(draw, dim: int) -> tuple:
    p = [draw(st.integers(0, 16).map(lambda k: k / 8)) for _ in range(dim)]
    v = [draw(small) for _ in range(dim)]
    a = [draw(st.sampled_from([0.0, 0.0, -0.5, 0.25])) for _ in range(dim)]
    return p, v, a


@st.composite
def path_from(draw, t: float, dim: int) -> list[tuple]:
    p, v, a = draw(segment_values(dim))
    if draw(st.booleans()):
        return [(t, p, v, [0.0] * dim)]
    dt = draw(st.sampled_from([0.0, 0.5, 1.0, 2.0]))
    p2, v2, _ = draw(segment_values(dim))
    return [(t, p, v, a), (t + dt, p2, v2, [0.0] * dim)]


@st.composite
def scenarios(draw):
    dim = draw(st.sampled_from([2, 3]))
    n = draw(st.integers(0, 9))
    paths = [draw(path_from(0.0, dim)) for _ in range(n)]
    radii = [draw(st.sampled_from([0.25, 0.375, 0.5])) for _ in range(n)]
    t_max = draw(st.sampled_from([math.inf, 6.0]))
    steps = []
    for _ in range(draw(st.integers(1, 12))):
        resolve = draw(st.booleans())
        k = draw(st.integers(1, max(1, min(3, n))))
        chosen = draw(st.lists(st.integers(0, max(0, n - 1)), min_size=k, max_size=k, unique=True))
        dt = draw(st.sampled_from([0.0, 0.25, 1.0]))
        new = [draw(path_from(0.0, dim)) for _ in chosen]
        steps.append((resolve, chosen, dt, new))
    return dim, paths, radii, t_max, steps


def shifted(path: list[tuple], t: float) -> list[tuple]:
    return [(s + t, p, v, a) for s, p, v, a in path]


@given(scenarios())
def test_the_calendar_is_brute_force_after_any_updates(scenario) -> None:
    dim, paths, radii, t_max, steps = scenario
    n = len(paths)
    s = bc.CollisionSchedule(*arrays(paths, dim), radii if n else 0.5, t_max=t_max)
    for resolve, chosen, dt, new in steps:
        expected = brute(paths, radii, dim, s.time, t_max)
        got = s.next_collision()
        assert (bits(got[0]), got[1:]) == (bits(expected[0]), expected[1:])
        if n == 0:
            return
        t = s.time + dt
        indices = chosen
        if resolve and got[1] >= 0:
            t, indices = got[0], [got[1], got[2]]
            new = new[:2] if len(new) >= 2 else new * 2
        new = [shifted(p, t) for p in new[: len(indices)]]
        s.update(indices, *arrays(new, dim))
        for i, p in zip(indices, new):
            paths[i] = p
        assert s.time == t
    expected = brute(paths, radii, dim, s.time, t_max)
    got = s.next_collision()
    assert (bits(got[0]), got[1:]) == (bits(expected[0]), expected[1:])


def line_schedule() -> bc.CollisionSchedule:
    start = np.zeros((3, 1))
    pos = [[[0.0, 0.0]], [[2.0, 0.0]], [[5.0, 0.0]]]
    vel = [[[1.0, 0.0]], [[0.0, 0.0]], [[0.0, 0.0]]]
    return bc.CollisionSchedule(start, pos, vel, np.zeros((3, 1, 2)), 0.5)


def one(t: float, p: list[float], v: list[float]) -> tuple[np.ndarray, ...]:
    return arrays([[(t, p, v, [0.0, 0.0])]], 2)


def test_refused_updates_raise_named_errors_and_change_nothing() -> None:
    s, twin = line_schedule(), line_schedule()
    s.update([0], *one(0.5, [0.5, 0], [0, 0]))
    twin.update([0], *one(0.5, [0.5, 0], [0, 0]))
    refused = [
        (([0], *one(0.25, [0, 0], [1, 0])), "start", 0, 0, "before the calendar's time 0.5"),
        (([3], *one(1.0, [0, 0], [1, 0])), "indices", 0, None, "must be in 0..3, got 3"),
        (([-1], *one(1.0, [0, 0], [1, 0])), "indices", 0, None, "got -1"),
        (([1, 1], *arrays([[(1.0, [0, 0], [0, 0], [0, 0])]] * 2, 2)), "indices", 1, None, "more"),
        (
            (
                [0, 1],
                *arrays([[(1.0, [0, 0], [0, 0], [0, 0])], [(2.0, [0, 0], [0, 0], [0, 0])]], 2),
            ),
            "start",
            1,
            0,
            "one time",
        ),
        (([0], *one(1.0, [math.nan, 0], [1, 0])), "pos", 0, 0, "finite"),
        (([0, 1], *one(1.0, [0, 0], [1, 0])), "start", None, None, "rows"),
    ]
    for args, argument, index, segment, text in refused:
        with pytest.raises(bc.InputError) as info:
            s.update(*args)
        err = info.value
        assert (err.argument, err.index, err.segment) == (argument, index, segment), str(err)
        assert text in str(err)
    # Nothing changed: the same answers as the twin's, now and after further updates.
    for step in range(4):
        assert s.time == twin.time
        assert s.next_event() == twin.next_event()
        t, i, j = s.next_collision()
        if i < 0:
            break
        for c in (s, twin):
            c.update([i, j], *arrays([[(t, [float(step), 0], [0, 0], [0, 0])]] * 2, 2))
    with pytest.raises(TypeError):
        s.update(["a"], *one(1.0, [0, 0], [1, 0]))
    with pytest.raises(bc.InputError, match="calendar's dimension 2"):
        s.update([0], *arrays([[(1.0, [0, 0, 0], [0, 0, 0], [0, 0, 0])]], 3))


def test_construction_errors_name_the_argument() -> None:
    start, pos, vel, acc = arrays(
        [[(0.0, [0, 0], [1, 0], [0, 0])], [(0.0, [2, 0], [0, 0], [0, 0])]], 2
    )
    with pytest.raises(bc.InputError) as info:
        bc.CollisionSchedule(start, pos, vel, acc, [0.5, -1.0])
    assert (info.value.argument, info.value.index) == ("radius", 1)
    with pytest.raises(bc.InputError) as info:
        bc.CollisionSchedule(start, pos, vel, acc, [0.5])
    assert info.value.argument == "radius"
    with pytest.raises(bc.InputError) as info:
        bc.CollisionSchedule(start, pos, vel, acc, 0.5, box=([0, 0], [1, 0]))
    assert (info.value.argument, info.value.index) == ("box", 1)
    with pytest.raises(bc.InputError, match="box"):
        bc.CollisionSchedule(start, pos, vel, acc, 0.5, box=([0, 0, 0], [1, 1, 1]))
    with pytest.raises(bc.InputError) as info:
        bc.CollisionSchedule.from_balls([[0, 0]], [[1, 0]], -0.5, 0.5)
    assert (info.value.argument, info.value.index) == ("friction", 0)
    with pytest.raises(bc.InputError, match="t_max"):
        bc.CollisionSchedule(start, pos, vel, acc, 0.5, t_max=-1.0)


def test_friction_balls_are_their_paths_from_t() -> None:
    rng = np.random.default_rng(3)
    n = 40
    pos = rng.uniform(0, 3, (n, 2))
    vel = rng.normal(0, 1, (n, 2))
    friction = rng.uniform(0, 0.5, n)
    s = bc.CollisionSchedule.from_balls(pos, vel, friction, 0.1, t=1.5)
    assert s.time == 1.5 and len(s) == n
    # The brute force: every pair with collision_times (the same model, from t = 0), moved on.
    i, j = np.triu_indices(n, 1)
    times = bc.collision_times(pos[i], vel[i], friction[i], pos[j], vel[j], friction[j], 0.2)
    k = int(np.argmin(times))
    t, a, b = s.next_collision()
    assert (a, b) == (int(i[k]), int(j[k]))
    assert t == pytest.approx(1.5 + times[k], abs=1e-12)
    s.update_balls([a, b], t, [[0, 0], [9, 9]], [[0, 0], [0, 0]], 0.0)
    assert s.time == t
    with pytest.raises(bc.InputError) as info:
        s.update_balls([0], t - 1, [[0, 0]], [[0, 0]], 0.0)
    assert info.value.argument == "t"
    with pytest.raises(bc.InputError) as info:
        s.update_balls([0, 1], t, [[0, 0]], [[0, 0]], 0.0)
    assert info.value.argument == "pos"


def test_an_event_is_a_named_tuple_and_walls_come_first_at_ties() -> None:
    # Ball 0 reaches the right wall at 0.25, when balls 1 and 2 collide too.
    s = bc.CollisionSchedule.from_balls(
        [[0.5, 0.625], [0.125, 0.125], [0.75, 0.125]],
        [[1, 0], [1, 0], [-1, 0]],
        0.0,
        [0.25, 0.0625, 0.0625],
        box=([0, 0], [1, 1]),
    )
    e = s.next_event()
    assert isinstance(e, bc.Event)
    # The high wall of axis 0: index 2·0 + 1.
    assert e == bc.Event(0.25, 0, -1, bc.WALL, 1)
    assert (e.time, e.i, e.j, e.kind, e.index) == (0.25, 0, -1, bc.WALL, 1)
    assert s.next_collision() == (0.25, 1, 2)
    empty = bc.CollisionSchedule.from_balls(np.zeros((0, 2)), np.zeros((0, 2)), 0.0, 1.0)
    assert empty.next_event() == (math.inf, -1, -1, -1, -1)
    assert empty.next_collision() == (math.inf, -1, -1)


# --- wall contacts against mpmath ---------------------------------------------------------


def reference_wall_time(segments: list[tuple], r: float, lo: list[float], hi: list[float]):
    """The first wall contact of one path, exactly (mpmath, from the exact doubles): the
    earliest entry root of each plane's quadratic on each segment's span; ``None`` if none.
    Also returns the smallest |u'| at a root seen (for the ambiguous band)."""
    mp = mpmath.mpf
    best = None
    for axis in range(len(lo)):
        for side in (-1, 1):
            for k, (s, p, v, a) in enumerate(segments):
                end = segments[k + 1][0] if k + 1 < len(segments) else math.inf
                if side < 0:
                    c, b, q = mp(p[axis]) - mp(lo[axis]) - mp(r), mp(v[axis]), mp(a[axis]) / 2
                else:
                    c, b, q = mp(hi[axis]) - mp(p[axis]) - mp(r), -mp(v[axis]), -mp(a[axis]) / 2
                if k == 0 and c <= 0 and (b < 0 or (b == 0 and q < 0)):
                    root = mp(0)
                else:
                    root = None
                    if q == 0:
                        if b < 0:
                            root = -c / b
                    else:
                        disc = b * b - 4 * q * c
                        if disc > 0:
                            r1 = (-b - mpmath.sqrt(disc)) / (2 * q)
                            r2 = (-b + mpmath.sqrt(disc)) / (2 * q)
                            root = min(r1, r2) if q > 0 else max(r1, r2)
                    if root is not None and not (0 < root < end - s):
                        root = None
                if root is not None:
                    t = mp(s) + root
                    if best is None or t < best[0]:
                        best = (
                            t,
                            axis,
                            side,
                            abs(b + 2 * q * root),
                            abs(c) + abs(b) * root + abs(q) * root * root,
                        )
                    break
    return best


@pytest.mark.parametrize("seed", range(4))
def test_wall_contacts_match_mpmath(seed: int) -> None:
    rng = np.random.default_rng(seed)
    lo, hi = [-1.0, -0.5], [1.5, 2.0]
    checked = 0
    for _ in range(300):
        r = float(rng.uniform(0.05, 0.3))
        p = rng.uniform(-0.6, 1.2, 2)
        v = rng.normal(0, 1, 2)
        a = rng.normal(0, 1, 2) * rng.integers(0, 2)
        s0 = float(rng.choice([0.0, 3.7, 1e4 + 0.3]))
        segments = [(s0, p.tolist(), v.tolist(), a.tolist())]
        ref = reference_wall_time(segments, r, lo, hi)
        start, pos, vel, acc = arrays([segments], 2)
        sched = bc.CollisionSchedule(start, pos, vel, acc, r, box=(lo, hi))
        e = sched.next_event()
        if ref is None:
            assert e.time == math.inf
            continue
        t_ref, axis, side, slope, size = ref
        # The floor: one rounding of every input moves the plane by ~ε·size, the root by
        # that over the approach speed, and the absolute time by ε·|t|.
        eps = 2.0**-52
        floor = eps * (float(size) / max(float(slope), 1e-300) + abs(float(t_ref)))
        if float(slope) < 1e-6:
            continue  # grazing: either answer is acceptable
        assert (e.i, e.j, e.kind, e.index) == (0, -1, bc.WALL, 2 * axis + (side > 0))
        assert abs(mpmath.mpf(e.time) - t_ref) <= 8 * floor, (segments, r, e, t_ref)
        checked += 1
    assert checked > 150


def test_the_from_balls_docstring_example_runs() -> None:
    # doctest's finder does not see a compiled class's static methods.
    doc = bc.CollisionSchedule.from_balls.__doc__ or ""
    test = doctest.DocTestParser().get_doctest(doc, {}, "from_balls", None, 0)
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    runner.run(test)
    assert runner.failures == 0 and runner.tries >= 2


def test_the_first_events_are_python_billiards_ones() -> None:
    # python-billiards 0.5.0 lives in the benchmark's own environment (benchmarks/
    # event_calendar.py): BILLIARDS_PYTHON, or ./.venv-bench.
    import os
    import sys
    from pathlib import Path

    root = Path(__file__).resolve().parents[2]
    python = os.environ.get("BILLIARDS_PYTHON", str(root / ".venv-bench" / "bin" / "python"))
    if not Path(python).exists():
        # scripts/test installs it and sets BALLCOLLIDE_REQUIRE_BILLIARDS=1: never a skip there.
        if os.environ.get("BALLCOLLIDE_REQUIRE_BILLIARDS") == "1":
            pytest.fail(f"python-billiards required but {python} is missing")
        pytest.skip("python-billiards is not installed (see benchmarks/event_calendar.py)")
    sys.path.insert(0, str(root / "benchmarks"))
    try:
        import event_calendar
    finally:
        sys.path.pop(0)
    for n in (16, 100):
        _, ours = event_calendar.time_simulate(n, 200, 1)
        _, theirs = event_calendar.time_billiards(python, n, 50, 1)
        assert event_calendar.same_first_events(ours, theirs) == 50


def test_the_benchmarks_break_driven_from_python_runs() -> None:
    # benchmarks/event_calendar.py --break: a simulator's loop over next_event and
    # update_balls, with walls and balls resolved in Python (it reads the events' fields).
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "benchmarks"))
    try:
        import event_calendar
    finally:
        sys.path.pop(0)
    run = event_calendar.time_break(1)
    assert run["events"] > 16  # the rack scatters: more events than balls


@st.composite
def tables(draw, dim: int) -> dict[str, object]:
    """A few objects of every kind in the scenes' square ``[0, 2]^dim`` (dyadic numbers:
    exact contacts and ties are common)."""
    eighth = st.integers(0, 16).map(lambda k: k / 8)
    m = draw(st.integers(0, 3))
    segments = [[[draw(eighth), draw(eighth)], [draw(eighth), draw(eighth)]] for _ in range(m)]
    segments = [s for s in segments if s[0] != s[1]]
    sides = [draw(st.sampled_from([-1, 0, 1])) for _ in segments]
    circles = [
        [draw(eighth) for _ in range(dim)] + [draw(st.sampled_from([0.0, 0.125, 0.25]))]
        for _ in range(draw(st.integers(0, 2)))
    ]
    targets = [
        [draw(eighth) for _ in range(dim)] + [draw(st.sampled_from([0.125, 0.25]))]
        for _ in range(draw(st.integers(0, 2)))
    ]
    planes = [
        [[draw(eighth) for _ in range(dim)], [draw(small) for _ in range(dim)]]
        for _ in range(draw(st.integers(0, 1)))
    ]
    planes = [p for p in planes if any(p[1])]
    table: dict[str, object] = {}
    if segments:
        table |= {"segments": segments, "segment_sides": sides}
    for name, rows in (("circles", circles), ("targets", targets), ("planes", planes)):
        if rows:
            table[name] = rows
    return table


def brute_object(paths, radii, dim: int, now: float, t_max: float, table: dict) -> tuple:
    """The earliest object event ``(t, ball, kind, index)`` with ``t ≥ now``: each object
    alone through path_geometry_times (its first contact from each path's start), in the
    calendar's order (time, ball, kind, index)."""
    best = (math.inf, -1, -1, -1)
    if not paths:
        return best
    start, pos, vel, acc = arrays(paths, dim)
    objects = [("segments", bc.SEGMENT), ("circles", bc.CIRCLE)]
    objects += [("targets", bc.TARGET), ("planes", bc.PLANE)]
    for name, kind in objects:
        for index, row in enumerate(table.get(name, [])):
            one: dict[str, object] = {name: [row]}
            if name == "segments":
                one["segment_sides"] = [table["segment_sides"][index]]
            times, _, _ = bc.path_geometry_times(start, pos, vel, acc, radii, t_max=t_max, **one)
            for ball, t in enumerate(times):
                if now <= t and (t, ball, kind, index) < best:
                    best = (float(t), ball, kind, index)
    return best


@given(scenarios(), st.data())
def test_the_calendar_with_a_table_is_brute_force_after_any_updates(scenario, data) -> None:
    # The next event over balls and objects, after updates that resolve events (of either
    # kind) or skip ahead: bit for bit the earliest of path_collision_times over the pairs
    # and of path_geometry_times over each object alone.
    dim, paths, radii, t_max, steps = scenario
    table = data.draw(tables(dim))
    n = len(paths)
    s = bc.CollisionSchedule(*arrays(paths, dim), radii if n else 0.5, t_max=t_max, **table)
    for step in [*steps, None]:
        collision = brute(paths, radii, dim, s.time, t_max)
        hit = brute_object(paths, radii, dim, s.time, t_max, table)
        ball = (collision[0], collision[1], 1, collision[2], -1)
        obj = (hit[0], hit[1], 0, hit[2], hit[3])
        first = min(ball, obj) if math.isfinite(min(ball, obj)[0]) else None
        e = s.next_event()
        if first is None:
            assert e.time == math.inf and e.kind == -1
        elif first[2] == 1:
            assert (bits(e.time), e.i, e.j, e.kind) == (bits(first[0]), first[1], first[3], bc.BALL)
        else:
            assert (bits(e.time), e.i, e.j, e.kind, e.index) == (
                bits(first[0]),
                first[1],
                -1,
                first[3],
                first[4],
            )
        if n == 0 or step is None:
            return
        resolve, chosen, dt, new = step
        t = s.time + dt
        indices = chosen
        if resolve and e.i >= 0:
            t, indices = e.time, [e.i] if e.j < 0 else [e.i, e.j]
        new = [shifted(p, t) for p in (new * 2)[: len(indices)]]
        s.update(indices, *arrays(new, dim))
        for i, p in zip(indices, new):
            paths[i] = p


@pytest.mark.parametrize("radius", [0.5, 0.6])
def test_a_ball_as_wide_as_the_box_is_refused_naming_it(radius):
    # It would touch two walls at once at every instant (a wall event at t = 0 for ever).
    with pytest.raises(bc.InputError) as error:
        bc.CollisionSchedule.from_balls([[0.5, 0.5]], [[1, 0.3]], 0.0, radius, box=([0, 0], [1, 2]))
    assert (error.value.argument, error.value.index) == ("radius", 0)
    assert error.value.kind == "wider_than_box"
