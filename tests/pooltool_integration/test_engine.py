"""ballcollide's native engine (``ballcollide.pooltool.simulate`` and ``simulate_many``)
against stock pooltool 0.6.0 on the seeded shots of ``benchmarks/pooltool_engine.py``: 9-ball
and 8-ball breaks, cut shots with side, top and back spin, massé shots (raised cue), snooker
cut shots and breaks, three-cushion shots.

Each shot must give stock ``pt.simulate``'s events (type, agents, order) at times within
``1e-6 s``, and the balls' final states within ``1e-6 m``; the ``System`` must be built as
pooltool builds it (histories, agents' copies, null events, pockets, ``t``).
``simulate_many``'s arrays must be ``simulate``'s, bit for bit, on any number of threads.
"""

from __future__ import annotations

from functools import cache
from typing import Any

import pytest

pt = pytest.importorskip("pooltool")

import numpy as np  # noqa: E402
from pooltool.events import AgentType  # noqa: E402

import ballcollide  # noqa: E402
import ballcollide.pooltool as bcp  # noqa: E402

from .reference import script  # noqa: E402

TIME = 1e-6  # s: an event's time against stock pooltool's
POSITION = 1e-6  # m: a ball's final position against stock pooltool's
#: Why a straight shot differs: both balls move along the axis after the collision, with
#: velocity components across it of 1e-17 to 1e-14 m/s that are rounding; pooltool collides
#: two balls at once when their accelerations are the same to the bit, so those bits decide,
#: and pooltool's ball–ball resolution (rotations and BLAS) rounds them otherwise than the
#: engine (``tests/reference/shots.rs``, ``ACROSS_THE_AXIS``).
AT_ONCE = "a collision at once in one and not the other (the rounding across the axis)"
#: Shots known to differ from stock pooltool, with why (checked: a shot that comes to agree,
#: or another that differs, fails the test).
KNOWN: dict[str, str] = {"straight-5": AT_ONCE}


@cache
def named_shots() -> list[tuple[str, Any]]:
    return script("benchmarks/pooltool_engine.py").shots()


@cache
def stock(k: int) -> Any:
    return pt.simulate(named_shots()[k][1])


def signature(system: Any) -> list[tuple[str, tuple[str, ...]]]:
    return [(e.event_type.value, tuple(a.id for a in e.agents)) for e in system.events]


def difference(ours: Any, theirs: Any) -> tuple[str | None, float, float]:
    """Why ``ours`` is not ``theirs`` (None if it is), the worst time and final position."""
    a, b = signature(ours), signature(theirs)
    for k, (x, y) in enumerate(zip(a, b)):
        if x != y:
            at_once = [
                e.events[k].event_type == pt.EventType.BALL_BALL
                and e.events[k].time == e.events[k - 1].time
                for e in (ours, theirs)
            ]
            if at_once[0] != at_once[1]:
                return AT_ONCE, np.inf, np.inf
            return f"event {k}: {x} where pooltool has {y}", np.inf, np.inf
    if len(a) != len(b):
        return f"{len(a)} events where pooltool has {len(b)}", np.inf, np.inf
    dt = max(abs(x.time - y.time) for x, y in zip(ours.events, theirs.events))
    dx = 0.0
    for i, ball in theirs.balls.items():
        mine = ours.balls[i].state
        if mine.s != ball.state.s:
            return f"ball {i} ends in state {mine.s}, pooltool's {ball.state.s}", dt, np.inf
        dx = max(dx, float(np.abs(mine.rvw[0] - ball.state.rvw[0]).max()))
    if dt > TIME:
        return f"an event {dt:.1e} s from pooltool's", dt, dx
    if dx > POSITION:
        return f"a ball ends {dx:.1e} m from pooltool's", dt, dx
    return None, dt, dx


def test_the_engine_gives_stock_pooltools_events() -> None:
    shots = named_shots()
    assert len(shots) >= 200
    differ: dict[str, str] = {}
    worst = {"time": 0.0, "position": 0.0}
    events = 0
    for k, (name, system) in enumerate(shots):
        ours = bcp.simulate(system)
        why, dt, dx = difference(ours, stock(k))
        events += len(ours.events)
        if why is not None:
            differ[name] = why
        else:
            worst["time"] = max(worst["time"], dt)
            worst["position"] = max(worst["position"], dx)
    matched = len(shots) - len(differ)
    print(
        f"{matched} of {len(shots)} shots give stock pooltool's events ({events} events): "
        f"times within {worst['time']:.1e} s, final positions within {worst['position']:.1e} m"
    )
    for name, why in differ.items():
        print(f"  {name}: {why}")
    assert differ == KNOWN


def test_the_system_is_built_as_pooltools() -> None:
    shots = named_shots()
    # A break with pockets, a massé shot, a three-cushion shot.
    picks = [
        k
        for k, (name, _) in enumerate(shots)
        if name in ("break9-0", "masse-0", "threecushion-0", "break8-1")
    ]
    for k in picks:
        system = shots[k][1]
        before = [b.state.rvw.copy() for b in system.balls.values()]
        ours, theirs = bcp.simulate(system), stock(k)
        # The shot given is not changed (inplace=False).
        assert all(np.array_equal(b.state.rvw, r) for b, r in zip(system.balls.values(), before))
        assert not system.events and ours is not system
        assert ours.t == ours.events[-1].time and abs(ours.t - theirs.t) < TIME
        assert ours.events[0].event_type == ours.events[-1].event_type == pt.EventType.NONE
        assert repr(ours.events[0].time) == repr(theirs.events[0].time)  # 0, an int
        for i, ball in ours.balls.items():
            history = ball.history.states
            assert len(history) == len(ours.events) == len(theirs.balls[i].history.states)
            assert [s.t for s in history] == [e.time for e in ours.events]
            assert history[-1] is ball.state
            for mine, stock_state in zip(history, theirs.balls[i].history.states):
                assert mine.s == stock_state.s
                assert np.abs(mine.rvw - stock_state.rvw).max() < 1e-5
            assert len(ball.history_cts) == 0
        for mine, stock_event in zip(ours.events, theirs.events):
            for a, b in zip(mine.agents, stock_event.agents):
                assert (a.agent_type, a.id) == (b.agent_type, b.id)
                assert type(a.initial) is type(b.initial) and type(a.final) is type(b.final)
                if a.agent_type == AgentType.BALL:
                    for x, y in ((a.initial, b.initial), (a.final, b.final)):
                        assert x.state.s == y.state.s and x.state.t == mine.time
                        assert np.abs(x.state.rvw - y.state.rvw).max() < 1e-5
                        assert len(x.history) == 0 and x.params == y.params
                if a.agent_type == AgentType.POCKET:
                    assert a.initial.contains == b.initial.contains
                    assert a.final.contains == b.final.contains
        for pid, pocket in ours.table.pockets.items():
            assert pocket.contains == theirs.table.pockets[pid].contains
        # pooltool's own tools read it.
        assert ours.simulated
        pt.continuize(ours, inplace=True)


def states_of(system: Any) -> list[Any]:
    """Every ``BallState`` of a simulated ``System``: the balls' histories, then the agents'
    copies."""
    states = [s for ball in system.balls.values() for s in ball.history.states]
    for event in system.events:
        for a in event.agents:
            if a.agent_type == AgentType.BALL:
                states += [a.initial.state, a.final.state]
    return states


def census(simulate: Any, system: Any) -> dict[str, int]:
    """How many objects of each type that the garbage collector tracks ``simulate(system)``'s
    result holds, of those it made (not the shot's own table segments, parameters, ...)."""
    import gc

    gc.collect()
    # Held, so that no id of theirs is reused meanwhile.
    existing = gc.get_objects()
    before = {id(o) for o in existing}
    made = simulate(system)
    seen: dict[int, str] = {}
    todo = [made]
    while todo:
        o = todo.pop()
        if id(o) in seen or id(o) in before or not gc.is_tracked(o):
            continue
        seen[id(o)] = type(o).__name__
        todo += gc.get_referents(o)
    names = list(seen.values())
    return {t: names.count(t) for t in set(names)}


def test_the_system_is_made_of_what_pooltools_is(tmp_path: Any) -> None:
    shots = named_shots()
    picks = [k for k, (name, _) in enumerate(shots) if name in ("break9-1", "masse-2")]
    for k in picks:
        system = shots[k][1]
        ours, theirs = bcp.simulate(system), stock(k)
        # Each state's fields of pooltool's own types, as stock leaves them.
        for mine, its in zip(states_of(ours), states_of(theirs)):
            for x in (mine, its):
                assert type(x.rvw) is np.ndarray and x.rvw.dtype == np.float64
                assert x.rvw.shape == (3, 3) and x.rvw.flags.writeable
                assert type(x.s) is int and type(x.t) is float
        # No two states share an array, but a ball's last state is its history's last two
        # (pooltool adds it again at the closing null event).
        arrays = {id(s): s.rvw for s in states_of(ours)}
        assert len(arrays) == len(states_of(ours)) - len(ours.balls)
        rows = sorted((a.__array_interface__["data"][0], a.nbytes) for a in arrays.values())
        assert all(x + n <= y for (x, n), (y, _) in zip(rows, rows[1:]))
        for ball in ours.balls.values():
            assert ball.history.states[-2] is ball.history.states[-1] is ball.state

        # As many objects for the collector, type by type, as stock's System.
        assert census(bcp.simulate, system) == census(pt.simulate, system)
        # pooltool's own tools take it: a copy, the serializers, and back.
        copy = ours.copy()
        assert signature(copy) == signature(ours) and copy.t == ours.t
        path = tmp_path / f"{k}.msgpack"
        ours.save(path)
        loaded = pt.System.load(path)
        assert signature(loaded) == signature(ours)
        for a, b in zip(states_of(loaded), states_of(ours)):
            assert np.array_equal(a.rvw, b.rvw) and a.s == b.s and a.t == b.t
        # A state's rvw written into changes that state only.
        before = [s.rvw.copy() for s in states_of(ours)]
        ours.events[1].agents[1].final.state.rvw[0, 0] += 1.0
        changed = [not np.array_equal(s.rvw, b) for s, b in zip(states_of(ours), before)]
        assert sum(changed) == 1


def test_inplace_changes_the_shot_given() -> None:
    system = named_shots()[0][1].copy()
    assert bcp.simulate(system, inplace=True) is system
    assert system.events and system.t > 0


def test_simulate_many_is_simulate_on_any_threads() -> None:
    shots = named_shots()
    systems = [s for _, s in shots[::4]]
    one = bcp.simulate_many(systems, num_threads=1)
    assert len(one) == len(systems)
    for threads in (2, None):
        other = bcp.simulate_many(systems, num_threads=threads)
        for key in (
            "event_start",
            "time",
            "type",
            "ball",
            "object",
            "rvw",
            "s",
            "final_rvw",
            "final_s",
        ):
            assert np.array_equal(getattr(one, key), getattr(other, key), equal_nan=True), key
    with_history = bcp.simulate_many(systems, num_threads=2, history=True)
    names = one.type_names
    for k, system in enumerate(systems):
        alone = bcp.simulate(system)
        e0, e1 = one.event_start[k], one.event_start[k + 1]
        assert [e.time for e in alone.events[1:-1]] == one.time[e0:e1].tolist()
        assert [e.event_type.value for e in alone.events[1:-1]] == [
            names[t] for t in one.type[e0:e1]
        ]
        b0, b1 = one.ball_start[k], one.ball_start[k + 1]
        finals = np.array([b.state.rvw for b in alone.balls.values()])
        assert np.array_equal(finals, one.final_rvw[b0:b1])
        for built in (one.to_system(k), with_history.to_system(k)):
            assert signature(built) == signature(alone)
            assert [e.time for e in built.events] == [e.time for e in alone.events]


def test_simulate_many_names_a_bad_shot_on_two_threads() -> None:
    # A bad shot among many, on 2 threads, is named by its place among them.
    from ballcollide import _core

    systems = [s for _, s in named_shots()[::6]]
    k = len(systems) - 3
    bad = systems[k].copy()
    bad.balls[next(iter(bad.balls))].state.rvw[0, 0] = np.nan
    with pytest.raises(ballcollide.InputError) as raised:
        bcp.simulate_many([*systems[:k], bad, *systems[k + 1 :]], num_threads=2)
    assert raised.value.argument == f"shots[{k}].position" and raised.value.kind == "not_finite"
    stray = systems[k].copy()
    stray.cue.cue_ball_id = "nope"
    with pytest.raises(ValueError, match=rf"^shots\[{k}\]: the cue's ball 'nope'"):
        bcp.simulate_many([*systems[:k], stray, *systems[k + 1 :]], num_threads=2)
    # An array's index, as one call over all the shots' arrays gives it.
    odd = systems[k].copy()
    odd.balls[next(iter(odd.balls))].state.s = 9
    shots = [*systems[:k], odd, *systems[k + 1 :]]
    with pytest.raises(ballcollide.InputError) as alone:
        _core.simulate_shots(**bcp._inputs(shots), num_threads=2)
    with pytest.raises(ballcollide.InputError) as many:
        bcp.simulate_many(shots, num_threads=2)
    assert str(many.value) == str(alone.value) and many.value.argument == "s"


def test_the_corrected_contact_rule() -> None:
    # A straight stun shot: both balls end up rolling the same way, and pooltool's quartic
    # (leading coefficient 0) collides them again at once, over and over; the corrected rule
    # does not.
    table = pt.Table.default()
    balls = {
        "cue": pt.Ball.create("cue", xy=(0.5, 0.5)),
        "1": pt.Ball.create("1", xy=(0.5, 0.7)),
    }
    system = pt.System(cue=pt.Cue(cue_ball_id="cue"), table=table, balls=balls)
    system.strike(V0=2.0, phi=90.0, b=0.0)
    pooltool_rule = bcp.simulate(system)
    corrected = bcp.simulate(system, contact_rule="approaching")

    def collisions(s: Any) -> int:
        return sum(e.event_type == pt.EventType.BALL_BALL for e in s.events)

    assert collisions(corrected) == 3 < collisions(pooltool_rule)
    many = bcp.simulate_many([system], contact_rule="approaching")
    assert many.time.tolist() == [e.time for e in corrected.events[1:-1]]


def test_what_is_not_supported_is_named() -> None:
    from pooltool.physics.engine import PhysicsEngine
    from pooltool.physics.resolve.resolver import default_resolver
    from pooltool.physics.resolve.stick_ball.instantaneous_point import InstantaneousPoint

    system = named_shots()[0][1]
    for kwargs, words in [
        ({"continuous": True}, "continuous"),
        ({"t_final": 1.0}, "t_final"),
        ({"max_events": 10}, "max_events"),
        ({"include": {pt.EventType.BALL_BALL}}, "include"),
        ({"contact_rule": "nearest"}, "contact_rule"),
    ]:
        with pytest.raises(bcp.UnsupportedError, match=words):
            bcp.simulate(system, **kwargs)
    resolver = default_resolver()
    resolver.stick_ball = InstantaneousPoint(english_throttle=0.5, squirt_throttle=1.0)
    with pytest.raises(bcp.UnsupportedError, match="stick_ball"):
        bcp.simulate(system, engine=PhysicsEngine(resolver=resolver))
    # The engine's own checks, naming the shot.
    bad = system.copy()
    bad.balls["cue"].state.rvw[0, 0] = np.nan
    with pytest.raises(ballcollide.InputError, match=r"shots\[1\]") as raised:
        bcp.simulate_many([system, bad])
    assert raised.value.kind == "not_finite"
    lost = system.copy()
    lost.cue.cue_ball_id = "ghost"
    with pytest.raises(ValueError, match="ghost"):
        bcp.simulate(lost)


def test_reading_reads_each_distinct_table_once_with_pooltools_values() -> None:
    # Copies share their segments and pocket centres; a table made anew from the same spec
    # has equal rows to the bit: one table for all four. Its rows are pooltool's own values
    # (heights by pooltool's `height`, which the reader takes from the points).
    from types import SimpleNamespace

    from ballcollide import _core

    base = pt.System.example()
    shots = [base, base.copy(), pt.System.example(), base.copy()]
    inputs = _core._pooltool_inputs(shots)
    assert len(inputs["tables"]) == 1 and inputs["shot_table"].tolist() == [0, 0, 0, 0]
    linear, circular, pockets = inputs["tables"][0]
    table = base.table
    segments = table.cushion_segments
    assert np.array_equal(
        linear,
        [[*c.p1[:2], *c.p2[:2], c.height, c.direction] for c in segments.linear.values()],
    )
    assert np.array_equal(
        circular, [[*c.center[:2], c.radius, c.height] for c in segments.circular.values()]
    )
    assert np.array_equal(
        pockets, [[*p.center[:2], p.radius, p.depth] for p in table.pockets.values()]
    )
    # Another game's table: its own index.
    snooker = pt.Table.from_game_type(pt.GameType.SNOOKER)
    other = base.copy()
    other.table = snooker
    inputs = _core._pooltool_inputs([base, other, base.copy()])
    assert len(inputs["tables"]) == 2 and inputs["shot_table"].tolist() == [0, 1, 0]
    # A point that is not (x, y, z): the shot and the segment named.
    flat = SimpleNamespace(
        id="flat", p1=np.array([0.0, 0.0]), p2=np.array([1.0, 0.0, 0.0]), direction=2
    )
    odd = base.copy()
    odd.table = SimpleNamespace(
        cushion_segments=SimpleNamespace(linear={"flat": flat}, circular={}), pockets={}
    )
    with pytest.raises(
        ValueError, match=r"^shots\[1\]\.table: cushion segment 'flat': p1: expected a point"
    ):
        _core._pooltool_inputs([base, odd])
