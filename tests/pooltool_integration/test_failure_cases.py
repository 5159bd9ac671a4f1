"""Where stock pooltool's ball–ball detector goes wrong, ballcollide's answer, judged by
pooltool's own evolution of the balls (``reference``), and pooltool's own simulation of the
same balls with ballcollide installed."""

from __future__ import annotations

from typing import Any

import pytest

pt = pytest.importorskip("pooltool")

import numpy as np  # noqa: E402
from pooltool.evolution.event_based import solve  # noqa: E402

import ballcollide.pooltool as bcp  # noqa: E402

from .reference import TOUCH, first_contact, gap, is_first_contact  # noqa: E402

STATIONARY, SPINNING, SLIDING, ROLLING = 0, 1, 2, 3
R = 0.028575  # pooltool's default ball radius (m)


def ball(
    id: str, xy: tuple[float, float], v=(0.0, 0.0), w=(0.0, 0.0, 0.0), s=STATIONARY, **params
) -> Any:
    b = pt.Ball.create(id, xy=xy, **params)
    b.state.rvw[1, :2] = v
    b.state.rvw[2] = w
    b.state.s = s
    return b


def rolling(id: str, xy: tuple[float, float], v: tuple[float, float], **params) -> Any:
    """A ball rolling without slip: ω = ẑ × v / R."""
    radius = params.get("R", R)
    return ball(id, xy, v, (-v[1] / radius, v[0] / radius, 0.0), ROLLING, **params)


def stock_time(b1: Any, b2: Any) -> float:
    """Stock pooltool 0.6.0's detector on the pair (as its pair loop calls it)."""
    mu = [b.params.u_s if b.state.s == SLIDING else b.params.u_r for b in (b1, b2)]
    return float(
        solve.ball_ball_collision_time(
            rvw1=b1.state.rvw,
            rvw2=b2.state.rvw,
            s1=b1.state.s,
            s2=b2.state.s,
            mu1=mu[0],
            mu2=mu[1],
            m1=b1.params.m,
            m2=b2.params.m,
            g1=b1.params.g,
            g2=b2.params.g,
            R=b1.params.R,
        )
    )


def simulated(*balls: Any) -> Any:
    """pooltool's simulation of these balls (the first is the cue ball) on a large table with
    ballcollide installed."""
    table = pt.Table.default(pt.TableType.BILLIARD)
    system = pt.System(
        cue=pt.Cue(cue_ball_id=balls[0].id), table=table, balls={b.id: b for b in balls}
    )
    with bcp.install():
        return pt.simulate(system)


def ball_ball_events(system: Any) -> list[Any]:
    return [e for e in system.events if e.event_type == pt.EventType.BALL_BALL]


def test_balls_rolling_side_by_side_at_one_velocity_never_touch() -> None:
    a = rolling("a", (0.5, 0.5), (1.0, 0.3))
    b = rolling("b", (0.5, 0.5 + 3 * R), (1.0, 0.3))
    assert stock_time(a, b) == 0.0  # stock: a false contact now (its quartic is 0 = e)
    assert bcp.collision_time(a, b) == np.inf
    assert first_contact(a, b, horizon=12.0) == np.inf
    assert ball_ball_events(simulated(a, b)) == []


def test_exactly_touching_balls_that_separate_do_not_collide_now() -> None:
    # R = 2⁻⁵ so that the centres are exactly 2R apart in binary.
    a = ball("a", (0.5, 0.5), R=0.03125)
    b = rolling("b", (0.5625, 0.5), (1.0, 0.0), R=0.03125)
    assert gap(a, b, 0.0)[0] == 0.0
    assert stock_time(a, b) == 0.0  # stock: a contact at t = 0
    assert bcp.collision_time(a, b) == np.inf
    # In the simulation they meet again only after b comes back off a cushion.
    system = simulated(b, a)
    first = ball_ball_events(system)[0]
    cushion = next(e for e in system.events if e.event_type == pt.EventType.BALL_LINEAR_CUSHION)
    assert cushion.time < first.time
    b1, b2 = (agent.initial for agent in first.agents)
    assert abs(np.linalg.norm(b1.state.rvw[0] - b2.state.rvw[0]) - 0.0625) <= TOUCH


def test_separating_balls_a_micrometre_apart_do_not_collide() -> None:
    a = ball("a", (0.5, 0.5))
    b = rolling("b", (0.5 + 2 * R + 1e-6, 0.5), (0.2, 0.0))
    stop = 0.2 / (b.params.u_r * b.params.g)
    stock = stock_time(a, b)
    assert stock > stop  # stock: a root of the extrapolated parabola, after b has stopped
    assert bcp.collision_time(a, b) == np.inf
    assert first_contact(a, b, horizon=2 * stock) == np.inf
    assert ball_ball_events(simulated(b, a)) == []


def test_separating_balls_a_micrometre_apart_that_come_back_collide_at_the_true_time() -> None:
    # b moves away at 0.2 m/s with heavy draw: friction against its slip turns it round
    # while it slides, and it rolls back into a.
    a = ball("a", (0.5, 0.5))
    b = ball("b", (0.5 + 2 * R + 1e-6, 0.5), (0.2, 0.0), (0.0, -60.0, 0.0), SLIDING)
    t = bcp.collision_time(a, b)
    reference = first_contact(a, b, horizon=3.0)
    assert np.isfinite(reference)
    assert abs(t - reference) <= 1e-9
    assert is_first_contact(a, b, t)
    (event,) = ball_ball_events(simulated(b, a))[:1]
    assert abs(event.time - reference) <= 1e-9


def test_overlapping_balls_that_separate_do_not_collide_now() -> None:
    # Overlapping by 1 µm (as pooltool's resolution can leave a ball in a cluster), moving
    # apart: stock collides them at once; ballcollide lets them part.
    a = ball("a", (0.5, 0.5))
    b = rolling("b", (0.5 + 2 * R - 1e-6, 0.5), (0.5, 0.0))
    assert gap(a, b, 0.0)[0] < -TOUCH
    assert bcp.collision_time(a, b) == np.inf
    assert ball_ball_events(simulated(b, a)) == []


def test_overlapping_balls_that_close_in_collide_now() -> None:
    a = ball("a", (0.5, 0.5))
    b = rolling("b", (0.5 + 2 * R - 1e-6, 0.5), (-0.5, 0.0))
    assert bcp.collision_time(a, b) == 0.0


def test_a_ball_rolling_past_another_within_its_reach_grazes_it_at_the_true_time() -> None:
    # Passes 1.9 R beside a resting ball's centre: a shallow contact.
    a = ball("a", (1.0, 0.5))
    b = rolling("b", (0.5, 0.5 + 1.9 * R), (1.0, 0.0))
    t = bcp.collision_time(a, b)
    assert is_first_contact(a, b, t)
    assert abs(t - first_contact(a, b, horizon=1.0)) <= 1e-9
    assert abs(t - stock_time(a, b)) <= 1e-9  # stock is right here


def test_balls_of_different_sizes_touch_at_the_sum_of_their_radii() -> None:
    # pooltool's own detector assumes one radius for both balls.
    a = ball("a", (1.0, 0.5), R=0.05)
    b = rolling("b", (0.5, 0.5), (1.0, 0.0), R=0.02)
    t = bcp.collision_time(a, b)
    assert is_first_contact(a, b, t)
    assert abs(gap(a, b, t)[0]) <= TOUCH
    assert bcp.collision_time(b, a) == t


def test_a_ball_labelled_sliding_without_slip_rolls_as_pooltool_evolves_it() -> None:
    # pooltool issue #78's state: "sliding" with zero slip (its slide lasts 0 s).
    a = ball("a", (1.0, 0.5))
    b = rolling("b", (0.5, 0.5 + 0.5 * R), (1.0, 0.0))
    b.state.s = SLIDING
    t = bcp.collision_time(a, b)
    assert is_first_contact(a, b, t)
    assert abs(t - first_contact(a, b, horizon=1.0)) <= 1e-9
