"""pooltool 0.6.0's own answers for ``ballcollide.billiards`` (the motion of a billiard ball).

This script draws seeded random balls and asks pooltool's own functions what they do: the
transition times (``ptmath.get_slide_time``, ``get_roll_time``, ``get_spin_time``), the slip
(``ptmath.rel_velocity``), the next transition (``_next_transition`` of its event loop), the
spin decay (``_evolve_perpendicular_spin_component``), the slide and the roll
(``_evolve_slide_state``, ``_evolve_roll_state``), the chained evolution
(``evolve_ball_motion``), and a lone ball's transitions until it stops, chained as its
``simulate`` loop chains them (``_next_transition``, ``evolve_ball_motion`` over the time to
the event, ``CanonicalTransition.resolve``).  It writes inputs and outputs to
``tests/data/billiards_cases.txt``, which ``tests/reference/billiards.rs`` reads.  It does not
import ballcollide.  It needs pooltool (run it in ``.venv-pooltool``, made by
``scripts/install-pooltool``).

Every number is written as Python's ``repr`` of a float64, which reads back to the same
float: the inputs are exact, and outputs can be compared to the bit.

Usage::

    .venv-pooltool/bin/python tools/billiards_reference.py            # the whole table
    .venv-pooltool/bin/python tools/billiards_reference.py --count 50  # the first 50 of each

Each kind of case has its own random stream, so a smaller ``--count`` gives the first lines
of each kind of the whole table (``tests/pooltool_integration/test_billiards_reference.py``
regenerates a few hundred and compares them with the committed file).

Line formats (``P`` = ``m R u_s u_r u_sp_proportionality g``; ``S`` = ``motion rx ry vx vy
wx wy wz``, ``motion`` pooltool's state number; a state's ``rvw`` on the table has
``r_z = R`` and ``v_z = 0``, which pooltool's functions keep exactly, and this script checks):

* ``times CAT P S : ux uy slide roll spin next delay`` (``next`` the transition's event type
  or ``none``; ``delay`` its time from the state's, 0);
* ``spin CAT P wz t : wz'``;
* ``slide CAT P S t : rx ry vx vy wx wy wz`` (and ``roll``, ``evolve`` likewise; ``evolve``
  writes the returned motion before the vectors);
* ``path CAT P S start : n`` then ``n`` transitions ``time type motion rx ry vx vy wx wy wz``;
* ``ball_ball CAT P e_b P e_b S S : kx1 ky1 kx2 ky2 u_b S' S'``: two balls at contact
  resolved by pooltool's default ball–ball model (``FrictionalInelastic`` with
  ``AlciatoreBallBallFriction``): the positions ``make_kiss`` gives them, the friction at
  those positions, and both states after ``resolve``;
* ``pocket CAT S ax ay radius depth t : motion rvw t' contains``: a ball dropped into a
  pocket by ``CanonicalBallPocket.resolve`` (its whole ``rvw``, its time, and whether the
  pocket holds it after);
* ``stick CAT m R V0 phi theta a b M end_mass tip_radius english squirt rx ry : motion vx
  vy wx wy wz t' alpha``: a cue striking a ball, ``InstantaneousPoint.resolve`` with squirt,
  and the squirt angle (``get_squirt_angle``).

The inputs of the last two are drawn to a few significant digits (random still, but short:
the table's size is mostly the outputs' 17 digits).
"""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Callable, Iterator
from pathlib import Path

import attrs
import numpy as np
import pooltool.constants as const
import pooltool.ptmath as ptmath
from pooltool.events.datatypes import EventType
from pooltool.evolution.event_based.cache import _next_transition
from pooltool.objects.ball.datatypes import Ball, BallState
from pooltool.objects.ball.params import BallParams
from pooltool.objects.cue.datatypes import Cue, CueSpecs
from pooltool.objects.table.components import (
    CircularCushionSegment,
    LinearCushionSegment,
    Pocket,
)
from pooltool.physics.evolve import (
    _evolve_perpendicular_spin_component,
    _evolve_roll_state,
    _evolve_slide_state,
    evolve_ball_motion,
)
from pooltool.physics.resolve.ball_ball.frictional_inelastic import FrictionalInelastic
from pooltool.physics.resolve.ball_cushion.stronge_compliant import (
    StrongeCompliantCircular,
    StrongeCompliantLinear,
)
from pooltool.physics.resolve.ball_pocket import CanonicalBallPocket
from pooltool.physics.resolve.stick_ball.instantaneous_point import InstantaneousPoint
from pooltool.physics.resolve.stick_ball.squirt import get_squirt_angle
from pooltool.physics.resolve.stronge_compliant import is_gross_slip, is_initial_stick
from pooltool.physics.resolve.transition import CanonicalTransition

SEED = 20261240
COUNT = 2000  # cases of each kind
OUT = Path(__file__).resolve().parents[1] / "tests" / "data" / "billiards_cases.txt"

PARAMS_PREBUILT = [
    BallParams(),
    BallParams(m=0.140, R=0.02619375, u_s=0.5, f_c=0.5),  # pooltool's SNOOKER_GENERIC
    BallParams(m=0.210, R=0.0615 / 2, f_c=0.15),  # pooltool's BILLIARD_GENERIC
]


def log_uniform(rng: np.random.Generator, lo: float, hi: float) -> float:
    return float(math.exp(rng.uniform(math.log(lo), math.log(hi))))


def random_params(rng: np.random.Generator) -> BallParams:
    """pooltool's default half of the time, its other prebuilt sets, or random values."""
    x = rng.random()
    if x < 0.5:
        return PARAMS_PREBUILT[0]
    if x < 0.7:
        return PARAMS_PREBUILT[1 + int(rng.integers(2))]
    return BallParams(
        m=float(rng.uniform(0.1, 0.3)),
        R=float(rng.uniform(0.02, 0.035)),
        u_s=log_uniform(rng, 0.05, 0.8),
        u_r=log_uniform(rng, 0.002, 0.05),
        u_sp_proportionality=float(rng.uniform(0.05, 2.0)),
        g=float(rng.uniform(1.0, 20.0)),
    )


def random_velocity(rng: np.random.Generator) -> tuple[float, float]:
    """A speed from 0.1 mm/s to 12 m/s, in any direction (a tenth along an axis)."""
    speed = log_uniform(rng, 1e-4, 12.0)
    if rng.random() < 0.1:
        vx, vy = [(speed, 0.0), (-speed, 0.0), (0.0, speed), (0.0, -speed)][int(rng.integers(4))]
        return vx, vy
    angle = rng.uniform(0.0, 2.0 * math.pi)
    return float(speed * math.cos(angle)), float(speed * math.sin(angle))


def random_spin(rng: np.random.Generator) -> float:
    """A spin about the vertical: none, below pooltool's EPS, or up to 300 rad/s."""
    x = rng.random()
    if x < 0.15:
        return 0.0
    if x < 0.25:
        return float(rng.choice([-1.0, 1.0]) * log_uniform(rng, 1e-17, 2e-14))
    return float(rng.choice([-1.0, 1.0]) * log_uniform(rng, 1e-3, 300.0))


def random_state(rng: np.random.Generator, params: BallParams, motion: int) -> np.ndarray:
    """An ``rvw`` for a ball in ``motion`` (sliding: spins of every kind; rolling: the rolling
    spin of its velocity; spinning and at rest: no velocity)."""
    x, y = float(rng.uniform(0.0, 2.54)), float(rng.uniform(0.0, 1.27))
    if rng.random() < 0.05:  # far from the origin: rounding relative to large coordinates
        x, y = x + float(rng.uniform(-1e4, 1e4)), y + float(rng.uniform(-1e4, 1e4))
    R = params.R
    vx, vy = random_velocity(rng)
    wz = random_spin(rng)
    if motion in (const.spinning, const.stationary, const.pocketed):
        vx = vy = wx = wy = 0.0
        if motion != const.spinning:
            wz = 0.0
    elif motion == const.rolling:
        wx, wy = -vy / R, vx / R
    else:
        mode = rng.random()
        scale = math.hypot(vx, vy) / R
        if mode < 0.35:  # any spin
            wx, wy = (float(w) for w in rng.normal(0.0, 1.5 * scale, 2))
        elif mode < 0.5:  # stun: no spin about a horizontal axis
            wx = wy = 0.0
        elif mode < 0.65:  # top or back spin along the velocity
            k = float(rng.uniform(-3.0, 3.0))
            wx, wy = -k * vy / R, k * vx / R
        elif mode < 0.75:  # spinning without moving (a masse's first instant)
            vx = vy = 0.0
            wx, wy = (float(w) for w in rng.normal(0.0, 50.0, 2))
        elif mode < 0.85:  # nearly rolling: a slip of a few roundings
            wx, wy = -vy / R, vx / R
        else:  # nearly rolling, with a small slip
            eps = log_uniform(rng, 1e-9, 1e-2)
            wx, wy = (-vy / R) * (1 + eps), (vx / R) * (1 - eps)
    return np.array([[x, y, R], [vx, vy, 0.0], [wx, wy, wz]], dtype=np.float64)


def random_time(rng: np.random.Generator, span: float) -> float:
    """A time within a state's span: inside it, exactly at its end, 0, tiny, or beyond."""
    x = rng.random()
    if not math.isfinite(span) or span == 0.0:
        return float(rng.uniform(0.0, 2.0))
    if x < 0.6:
        return float(rng.uniform(0.0, 1.0) * span)
    if x < 0.75:
        return float(span)
    if x < 0.8:
        return 0.0
    if x < 0.9:
        return float(span * log_uniform(rng, 1e-12, 1e-3))
    return float(span * rng.uniform(1.0, 3.0))


def fmt(*xs: float) -> str:
    return " ".join(repr(float(x)) for x in xs)


def fmt_params(p: BallParams) -> str:
    return fmt(p.m, p.R, p.u_s, p.u_r, p.u_sp_proportionality, p.g)


def fmt_state(s: int, rvw: np.ndarray) -> str:
    return f"{s} " + fmt(*rvw[0, :2], *rvw[1, :2], *rvw[2])


def fmt_rvw(rvw: np.ndarray) -> str:
    return fmt(*rvw[0, :2], *rvw[1, :2], *rvw[2])


def check_on_table(rvw_in: np.ndarray, rvw_out: np.ndarray) -> None:
    """pooltool keeps a ball's height and leaves its velocity horizontal (bit for bit)."""
    assert rvw_out[0, 2] == rvw_in[0, 2], (rvw_in, rvw_out)
    assert rvw_out[1, 2] == 0.0, (rvw_in, rvw_out)


def make_ball(params: BallParams, rvw: np.ndarray, s: int, t: float) -> Ball:
    return Ball(id="ball", params=params, state=BallState(rvw.copy(), s, t))


MOTIONS = [const.sliding, const.rolling, const.spinning, const.stationary, const.pocketed]


def random_ball(
    rng: np.random.Generator, weights: list[float], slipping: bool = True
) -> tuple[BallParams, int, np.ndarray]:
    """Parameters, a motion state drawn with ``weights`` (in the order of ``MOTIONS``) and a
    state in it; a sliding ball slips unless ``slipping`` is false (pooltool's slide divides
    by the slip, and gives NaN without one)."""
    while True:
        p = random_params(rng)
        s = int(rng.choice(MOTIONS, p=weights))
        rvw = random_state(rng, p, s)
        if not slipping or s != const.sliding or ptmath.norm3d(ptmath.rel_velocity(rvw, p.R)) > 0:
            return p, s, rvw


def times_cases(rng: np.random.Generator) -> Iterator[str]:
    while True:
        p, s, rvw = random_ball(rng, [0.5, 0.3, 0.1, 0.05, 0.05], slipping=False)
        u = ptmath.rel_velocity(rvw, p.R)
        assert u[2] == 0.0
        slide = ptmath.get_slide_time(rvw, p.R, p.u_s, p.g)
        roll = ptmath.get_roll_time(rvw, p.u_r, p.g)
        spin = ptmath.get_spin_time(rvw, p.R, p.u_sp, p.g)
        event = _next_transition(make_ball(p, rvw, s, 0.0))
        kind = "none" if event.event_type == EventType.NONE else str(event.event_type)
        delay = 0.0 if kind == "none" else event.time
        out = f"{fmt(u[0], u[1], slide, roll, spin)} {kind} {fmt(delay)}"
        yield f"times {state_name(s)} {fmt_params(p)} {fmt_state(s, rvw)} : {out}"


def spin_cases(rng: np.random.Generator) -> Iterator[str]:
    while True:
        p = random_params(rng)
        wz = random_spin(rng)
        alpha = 5 * p.u_sp * p.g / (2 * p.R)
        t = random_time(rng, abs(wz) / alpha)
        out = _evolve_perpendicular_spin_component(wz, p.R, p.u_sp, p.g, t)
        yield f"spin decay {fmt_params(p)} {fmt(wz, t)} : {fmt(out)}"


def slide_cases(rng: np.random.Generator) -> Iterator[str]:
    while True:
        p, _, rvw = random_ball(rng, [1.0, 0.0, 0.0, 0.0, 0.0])
        span = ptmath.get_slide_time(rvw, p.R, p.u_s, p.g)
        t = min(random_time(rng, span), span)  # the slide formula holds until the slide ends
        out = _evolve_slide_state(rvw.copy(), p.R, p.m, p.u_s, p.u_sp, p.g, t)
        check_on_table(rvw, out)
        s = const.sliding
        yield f"slide sliding {fmt_params(p)} {fmt_state(s, rvw)} {fmt(t)} : {fmt_rvw(out)}"


def roll_cases(rng: np.random.Generator) -> Iterator[str]:
    while True:
        p = random_params(rng)
        rvw = random_state(rng, p, const.rolling)
        span = ptmath.get_roll_time(rvw, p.u_r, p.g)
        t = min(random_time(rng, span), span)
        out = _evolve_roll_state(rvw.copy(), p.R, p.u_r, p.u_sp, p.g, t)
        check_on_table(rvw, out)
        s = const.rolling
        yield f"roll rolling {fmt_params(p)} {fmt_state(s, rvw)} {fmt(t)} : {fmt_rvw(out)}"


def total_time(p: BallParams, rvw: np.ndarray, s: int) -> float:
    """The time until the ball stops, by pooltool's evolution (for drawing times)."""
    total, state = 0.0, s
    rvw = rvw.copy()
    for _ in range(4):
        event = _next_transition(make_ball(p, rvw, state, 0.0))
        if event.event_type == EventType.NONE or not math.isfinite(event.time):
            break
        rvw, _ = evolve_ball_motion(state, rvw, p.R, p.m, p.u_s, p.u_sp, p.u_r, p.g, event.time)
        total += event.time
        state = transition_target(event.event_type)
    return total


def transition_target(event_type: EventType) -> int:
    return {
        EventType.SLIDING_ROLLING: const.rolling,
        EventType.ROLLING_SPINNING: const.spinning,
        EventType.ROLLING_STATIONARY: const.stationary,
        EventType.SPINNING_STATIONARY: const.stationary,
    }[event_type]


def state_name(s: int) -> str:
    return const.state_dict[s]


def evolve_cases(rng: np.random.Generator) -> Iterator[str]:
    while True:
        p, s, rvw = random_ball(rng, [0.6, 0.25, 0.09, 0.03, 0.03])
        span = total_time(p, rvw, s)
        if span > 0.0 and rng.random() < 0.3:
            # exactly at a transition (the chaining's `t >= time` edge)
            t = float(ptmath.get_slide_time(rvw, p.R, p.u_s, p.g))
            if s != const.sliding or not t < span:
                t = span
        else:
            t = random_time(rng, span)
        out, s_out = evolve_ball_motion(s, rvw.copy(), p.R, p.m, p.u_s, p.u_sp, p.u_r, p.g, t)
        check_on_table(rvw, out)
        line = f"{fmt_params(p)} {fmt_state(s, rvw)} {fmt(t)} : {s_out} {fmt_rvw(out)}"
        yield f"evolve {state_name(s)} {line}"


def path_cases(rng: np.random.Generator) -> Iterator[str]:
    transition = CanonicalTransition()
    while True:
        p, s, rvw = random_ball(rng, [0.7, 0.2, 0.07, 0.03, 0.0])
        start = 0.0 if rng.random() < 0.5 else float(rng.uniform(0.0, 100.0))
        ball = make_ball(p, rvw, s, start)
        records = []
        for _ in range(4):
            event = _next_transition(ball)
            if event.event_type == EventType.NONE or not math.isfinite(event.time):
                break
            # simulate's step: every ball evolved to the event's time, then resolved.
            dt = event.time - ball.state.t
            state = ball.state
            out, _ = evolve_ball_motion(state.s, state.rvw, p.R, p.m, p.u_s, p.u_sp, p.u_r, p.g, dt)
            check_on_table(state.rvw, out)
            ball.state = BallState(out, state.s, event.time)
            ball = transition.resolve(ball, event.event_type, inplace=True)
            records.append(
                f"{fmt(event.time)} {event.event_type} {ball.state.s} {fmt_rvw(ball.state.rvw)}"
            )
        head = f"path {state_name(s)} {fmt_params(p)} {fmt_state(s, rvw)} {fmt(start)}"
        yield f"{head} : {len(records)} " + " ".join(records)


GAPS = ["touching", "rounding", "spacer", "overlap", "apart"]


def contact_gap(rng: np.random.Generator, kind: str, R: float) -> float:
    """How far from 2R two balls' centres are at a collision of ``kind``: exactly 2R, a few
    roundings off, within pooltool's 1e-6 spacer, overlapping (its collisions of overlapping
    balls), or further apart than the spacer."""
    if kind == "touching":
        return 0.0
    if kind == "rounding":
        return float(rng.integers(-8, 9)) * 2 * R * 2.0**-53
    if kind == "spacer":
        return float(rng.uniform(0.0, 1e-6))
    if kind == "overlap":
        return -log_uniform(rng, 1e-12, 1e-3 * R)
    return log_uniform(rng, 1e-6, 1e-3)


def ball_ball_cases(rng: np.random.Generator) -> Iterator[str]:
    """Two balls at contact, resolved by pooltool's default model (``FrictionalInelastic``
    with ``AlciatoreBallBallFriction``): the kissed positions, the friction, the states."""
    model = FrictionalInelastic()
    while True:
        p1 = random_params(rng)
        p1 = attrs.evolve(p1, e_b=float(rng.uniform(0.5, 1.0))) if rng.random() < 0.3 else p1
        p2 = attrs.evolve(p1, e_b=float(rng.uniform(0.5, 1.0))) if rng.random() < 0.3 else p1
        s1 = int(rng.choice(MOTIONS[:4], p=[0.5, 0.3, 0.1, 0.1]))
        s2 = int(rng.choice(MOTIONS[:4], p=[0.3, 0.2, 0.1, 0.4]))
        rvw1, rvw2 = random_state(rng, p1, s1), random_state(rng, p2, s2)
        angle = rng.uniform(0.0, 2.0 * math.pi)
        normal = np.array([math.cos(angle), math.sin(angle)])
        if s1 in (const.sliding, const.rolling) and rng.random() < 0.7:
            # aimed at the other ball, at any cut up to 80 degrees
            speed = math.hypot(*rvw1[1, :2])
            cut = angle + rng.uniform(-1.4, 1.4)
            rvw1[1, :2] = [speed * math.cos(cut), speed * math.sin(cut)]
            if s1 == const.rolling:
                rvw1[2, :2] = [-rvw1[1, 1] / p1.R, rvw1[1, 0] / p1.R]
        together = s1 in (const.sliding, const.rolling) and rng.random() < 0.1
        if together:  # moving on nearly together (pooltool's resolve_continually_touching)
            s2 = s1
            rvw2[1, :2] = rvw1[1, :2] * (1 + rng.uniform(-2e-3, 2e-3))
            rvw2[2] = rvw1[2]
        gap = GAPS[int(rng.integers(len(GAPS)))]
        distance = 2 * p1.R + contact_gap(rng, gap, p1.R)
        rvw2[0, :2] = rvw1[0, :2] + distance * normal
        b1, b2 = make_ball(p1, rvw1, s1, 0.0), make_ball(p2, rvw2, s2, 0.0)
        try:
            k1, k2 = model.make_kiss(b1.copy(), b2.copy())
        except ValueError:
            continue  # no root kept: pooltool's make_kiss fails (argmin of nothing)
        u_b = model.friction.calculate_friction(k1, k2)
        f1, f2 = model.resolve(b1, b2, inplace=False)
        for before, after in ((b1, f1), (b2, f2)):
            assert after.state.rvw[0, 2] == before.state.rvw[0, 2]
            assert after.state.rvw[1, 2] == 0.0
        category = gap + ("_together" if together else "")
        inputs = f"{fmt_ball_params(p1)} {fmt_ball_params(p2)} {fmt_state(s1, rvw1)} "
        inputs += fmt_state(s2, rvw2)
        kissed = fmt(*k1.state.rvw[0, :2], *k2.state.rvw[0, :2], u_b)
        after = f"{fmt_state(f1.state.s, f1.state.rvw)} {fmt_state(f2.state.s, f2.state.rvw)}"
        yield f"ball_ball {category} {inputs} : {kissed} {after}"


def cushion_ball(rng: np.random.Generator) -> tuple[BallParams, int, np.ndarray, float]:
    """A ball aimed into a cushion along ``normal`` (the unit vector from the contact to the
    ball's centre, in the plane), at any angle up to 89 degrees from head on, with any spin,
    its restitution and friction with the cushion random a third of the time; and the
    cushion's height (pooltool's default nose, 0.64 of the diameter, or from 0.5R to 1.5R)."""
    while True:
        p = random_params(rng)
        if rng.random() < 0.35:
            p = attrs.evolve(p, e_c=float(rng.uniform(0.5, 1.0)), f_c=log_uniform(rng, 0.01, 0.8))
        s = int(rng.choice(MOTIONS[:2], p=[0.6, 0.4]))
        rvw = random_state(rng, p, s)
        if s == const.sliding and rng.random() < 0.5:  # little spin: sticking is possible
            rvw[2] *= log_uniform(rng, 1e-4, 1.0)
        height = 2 * 0.64 * p.R if rng.random() < 0.5 else float(rng.uniform(0.5, 1.5)) * p.R
        return p, s, rvw, height


def aim(rng: np.random.Generator, rvw: np.ndarray, normal: np.ndarray, p: BallParams, s: int):
    """Turn the ball's velocity (and a rolling ball's spin) to meet the cushion."""
    speed = math.hypot(*rvw[1, :2])
    if speed == 0.0:
        speed = log_uniform(rng, 1e-3, 10.0)
    if rng.random() < 0.3:
        off = rng.uniform(-1.55, 1.55)
    else:  # near head on, where the contact sticks
        off = rng.choice([-1.0, 1.0]) * log_uniform(rng, 1e-6, 0.5)
    heading = math.atan2(-normal[1], -normal[0]) + off
    rvw[1, :2] = [speed * math.cos(heading), speed * math.sin(heading)]
    if s == const.rolling:
        rvw[2, :2] = [-rvw[1, 1] / p.R, rvw[1, 0] / p.R]


def stronge_solve(model, ball: Ball, cushion) -> np.ndarray | None:
    """pooltool's ``solve``, or None where it fails (an assertion, or no bracket)."""
    try:
        out, _ = model.solve(ball, cushion)
    except (AssertionError, ValueError):
        return None
    return out.state.rvw


def cushion_cases(rng: np.random.Generator, kind: str, model, place) -> Iterator[str]:
    """A ball at contact with a cushion that ``place(rng, p, rvw, normal, height)`` puts
    against it (returning the cushion and its numbers), resolved by ``model.solve``; the
    regimes in turn."""
    made = 0
    while True:
        p, s, rvw, height = cushion_ball(rng)
        angle = rng.uniform(0.0, 2.0 * math.pi)
        normal = np.array([math.cos(angle), math.sin(angle)])
        cushion, numbers = place(rng, p, rvw, normal, height)
        aim(rng, rvw, normal, p, s)
        rvw_after = stronge_solve(model, make_ball(p, rvw, s, 0.0), cushion)
        category = regime(p, rvw, cushion)
        if rvw_after is None or category != REGIMES[made % 3]:
            continue
        made += 1
        # make_kiss on the ball moved off contact by up to 1e-5 (or not), then resolve
        shift = float(rng.choice([0.0, 1.0])) * float(rng.uniform(-1e-5, 1e-5))
        off = rvw.copy()
        off[0, :2] += shift * normal
        kissed = model.make_kiss(make_ball(p, off, s, 0.0), cushion).state.rvw[0, :2]
        resolved = stronge_solve(model, make_ball(p, kissed_rvw(off, kissed), s, 0.0), cushion)
        resolved_text = "none" if resolved is None else fmt_rvw(resolved)
        inputs = f"{fmt_cushion_params(p)} {fmt_state(s, rvw)} {fmt(*numbers)} {fmt(shift)}"
        outputs = f"{fmt_rvw(rvw_after)} {fmt(*kissed)} {resolved_text}"
        yield f"{kind} {category} {inputs} : {outputs}"


def kissed_rvw(rvw: np.ndarray, xy) -> np.ndarray:
    out = rvw.copy()
    out[0, :2] = xy
    return out


def place_linear(rng: np.random.Generator, p: BallParams, rvw, normal, height):
    """A straight cushion touching the ball, of any length, the ball anywhere along it."""
    along = np.array([-normal[1], normal[0]])
    length = float(rng.uniform(0.05, 2.5))
    a = rvw[0, :2] - p.R * normal - float(rng.uniform(0.0, 1.0)) * length * along
    b = a + length * along
    if rng.random() < 0.5:
        a, b = b, a
    cushion = LinearCushionSegment("c", p1=np.array([*a, height]), p2=np.array([*b, height]))
    return cushion, (*a, *b, height)


def place_circular(rng: np.random.Generator, p: BallParams, rvw, normal, height):
    """A rounded cushion (radius 1 mm to 20 cm) touching the ball."""
    radius = log_uniform(rng, 1e-3, 0.2)
    center = rvw[0, :2] - (p.R + radius) * normal
    cushion = CircularCushionSegment("c", center=np.array([*center, height]), radius=radius)
    return cushion, (*center, radius, height)


def linear_cushion_cases(rng: np.random.Generator) -> Iterator[str]:
    """``StrongeCompliantLinear`` (omega_ratio 1.8, as in the default resolver) at contact."""
    model = StrongeCompliantLinear(omega_ratio=1.8)
    return cushion_cases(rng, "linear_cushion", model, place_linear)


def circular_cushion_cases(rng: np.random.Generator) -> Iterator[str]:
    """``StrongeCompliantCircular`` (omega_ratio 1.8) at contact."""
    model = StrongeCompliantCircular(omega_ratio=1.8)
    return cushion_cases(rng, "circular_cushion", model, place_circular)


REGIMES = ["gross_slip", "stick_slip", "slip_stick_slip"]


def regime(p: BallParams, rvw: np.ndarray, cushion) -> str:
    """The Stronge regime pooltool's ``_solve`` takes for this ball (omega_ratio 1.8)."""
    normal = cushion.get_normal_3d(rvw[0])
    contact = ptmath.surface_velocity(rvw, -normal, p.R)
    v_n_0, v_t_0, _ = ptmath.decompose_normal_tangent(contact, normal, True)
    ratio, eta_squared = v_t_0 / v_n_0, 3.5 / 1.8**2
    if is_gross_slip(ratio, p.f_c, p.e_c, eta_squared, 3.5):
        return "gross_slip"
    if is_initial_stick(ratio, p.f_c, eta_squared):
        return "stick_slip"
    return "slip_stick_slip"


def fmt_cushion_params(p: BallParams) -> str:
    return f"{fmt_params(p)} {fmt(p.e_c, p.f_c)}"


def fmt_ball_params(p: BallParams) -> str:
    return f"{fmt_params(p)} {fmt(p.e_b)}"


def short(x: float, digits: int = 3) -> float:
    """``x`` rounded to ``digits`` significant decimal digits: an input that is still random
    but prints short (the table's size is mostly the outputs' 17 digits)."""
    return float(f"{x:.{digits}g}")


def pocket_cases(rng: np.random.Generator) -> Iterator[str]:
    """A ball in any motion state (pocketed too) dropping into a pocket anywhere, of any
    radius and depth (pooltool's 0.08 half of the time), resolved by ``CanonicalBallPocket``
    (pooltool's only ball–pocket model): the ball's state after, ``t`` included, and whether
    the pocket then holds it."""
    model = CanonicalBallPocket()
    while True:
        p = random_params(rng)
        s = int(rng.choice(MOTIONS, p=[0.4, 0.3, 0.1, 0.1, 0.1]))
        rvw = np.vectorize(lambda x: short(x, 2))(random_state(rng, p, s))
        rvw[0, 2], rvw[1, 2] = p.R, 0.0
        center = [short(x, 3) for x in rvw[0, :2] + rng.normal(0.0, 0.05, 2)]
        radius = short(log_uniform(rng, 0.02, 0.15), 3)
        depth = 0.08 if rng.random() < 0.5 else short(float(rng.uniform(0.0, 0.3)), 3)
        pocket = Pocket("p", center=np.array([*center, 0.0]), radius=radius, depth=depth)
        t = short(float(rng.uniform(0.0, 20.0)), 2)
        ball, pocket = model.resolve(make_ball(p, rvw, s, t), pocket, inplace=False)
        contains = int(pocket.contains == {"ball"})
        inputs = f"{fmt_state(s, rvw)} {fmt(*center, radius, depth, t)}"
        after = ball.state
        outputs = f"{after.s} {fmt(*after.rvw.ravel(), after.t)} {contains}"
        yield f"pocket {state_name(s)} {inputs} : {outputs}"


def random_cue(rng: np.random.Generator) -> tuple[float, float, float, float, float]:
    """``V0 phi theta a b``: a speed from 1 cm/s to 10 m/s; any direction (an axis a tenth of
    the time, and beyond [0, 360) sometimes); level a third of the time, else elevated up to
    90 degrees (massé); the contact point anywhere on the ball's face (at its centre, on an
    axis, or on its rim too)."""
    v0 = short(log_uniform(rng, 0.01, 10.0))
    phi = short(float(rng.uniform(0.0, 360.0)))
    if rng.random() < 0.1:
        phi = float(rng.choice([0.0, 90.0, 180.0, 270.0, 360.0, -45.0, 725.0]))
    x = rng.random()
    theta = 0.0 if x < 0.35 else short(float(rng.uniform(0.0, 90.0)), 4)
    if rng.random() < 0.03:
        theta = 90.0
    x = rng.random()
    if x < 0.1:
        return v0, phi, theta, 0.0, 0.0
    if x < 0.25:  # follow or draw, no side
        return v0, phi, theta, 0.0, short(float(rng.uniform(-0.9, 0.9)), 4)
    if x < 0.35:  # side only
        return v0, phi, theta, short(float(rng.uniform(-0.9, 0.9)), 4), 0.0
    if x < 0.4:  # on the rim: a^2 + b^2 as near 1 as the rounding lets it be
        angle = rng.uniform(0.0, 2.0 * math.pi)
        a, b = math.cos(angle), math.sin(angle)
        while 1.0 - a**2 - b**2 < 0.0:
            a, b = a * (1 - 2**-52), b * (1 - 2**-52)
        return v0, phi, theta, a, b
    while True:
        a, b = (short(float(x), 4) for x in rng.uniform(-1.0, 1.0, 2))
        if 1.0 - a**2 - b**2 >= 0.0:
            return v0, phi, theta, a, b


# (m, R) of pooltool's prebuilt balls: pool (its default), snooker, carom.
STICK_BALLS = [(0.170097, 0.028575), (0.140, 0.02619375), (0.210, 0.0615 / 2)]


def stick_cases(rng: np.random.Generator) -> Iterator[str]:
    """A cue striking a ball (``InstantaneousPoint``, with squirt): random strokes, cues and
    balls; pooltool's default cue and throttles (1) half of the time, and its default ball.
    The tip radius is drawn too, to show that the model does not use it."""
    while True:
        x = rng.random()
        m, R = STICK_BALLS[0 if x < 0.5 else 1 if x < 0.6 else 2]
        if rng.random() < 0.3:
            m, R = short(float(rng.uniform(0.1, 0.3)), 4), short(float(rng.uniform(0.02, 0.035)), 4)
        v0, phi, theta, a, b = random_cue(rng)
        specs = CueSpecs()
        if rng.random() < 0.5:
            specs = CueSpecs(
                M=short(float(rng.uniform(0.3, 0.7)), 4),
                tip_radius=short(float(rng.uniform(0.004, 0.012)), 4),
                end_mass=short(log_uniform(rng, m / 100, m / 5), 4),
            )
        english = squirt = 1.0
        if rng.random() < 0.3:
            english = short(float(rng.uniform(0.0, 2.0)), 3)
            squirt = float(rng.choice([0.0, short(float(rng.uniform(0.0, 2.0)), 3)]))
        cue = Cue(V0=v0, phi=phi, theta=theta, a=a, b=b, specs=specs)
        p = BallParams(m=m, R=R)
        s = int(rng.choice(MOTIONS[:4]))
        rvw = np.vectorize(short)(random_state(rng, p, s))
        rvw[0, 2], rvw[1, 2] = R, 0.0
        model = InstantaneousPoint(english_throttle=english, squirt_throttle=squirt)
        _, ball = model.resolve(cue, make_ball(p, rvw, s, 1.5), inplace=False)
        out = ball.state.rvw
        assert (out[0] == rvw[0]).all() and out[1, 2] == 0.0, (rvw, out)
        alpha = get_squirt_angle(m, specs.end_mass, a, squirt)
        category = ("elevated" if theta > 0.0 else "level") + ("_side" if a != 0.0 else "")
        inputs = f"{fmt(m, R, v0, phi, theta, a, b, specs.M, specs.end_mass, specs.tip_radius)}"
        inputs += f" {fmt(english, squirt, *rvw[0, :2])}"
        outputs = f"{ball.state.s} {fmt(*out[1, :2], *out[2], ball.state.t, alpha)}"
        yield f"stick {category} {inputs} : {outputs}"


KINDS: list[tuple[str, Callable[[np.random.Generator], Iterator[str]]]] = [
    ("times", times_cases),
    ("spin", spin_cases),
    ("slide", slide_cases),
    ("roll", roll_cases),
    ("evolve", evolve_cases),
    ("path", path_cases),
    ("ball_ball", ball_ball_cases),
    ("linear_cushion", linear_cushion_cases),
    ("circular_cushion", circular_cushion_cases),
    ("pocket", pocket_cases),
    ("stick", stick_cases),
]

HEADER = """\
# ballcollide billiards cases: pooltool {version}'s own functions on seeded random balls
# (tools/billiards_reference.py), {count} of each kind, seed {seed}. Numbers are float64 reprs.
# P = m R u_s u_r u_sp_proportionality g; S = motion rx ry vx vy wx wy wz (pooltool's
# motion numbers; r_z = R and v_z = 0 on the table, kept by pooltool to the bit).
# times CAT P S : ux uy slide roll spin next delay   (rel_velocity, get_*_time, _next_transition)
# spin CAT P wz t : wz'                              (_evolve_perpendicular_spin_component)
# slide|roll CAT P S t : rx ry vx vy wx wy wz        (_evolve_slide_state, _evolve_roll_state)
# evolve CAT P S t : motion rx ry vx vy wx wy wz     (evolve_ball_motion)
# path CAT P S start : n, then n times: time type motion rx ry vx vy wx wy wz
#   (a lone ball's transitions as simulate chains them: _next_transition, evolve_ball_motion
#   over event.time - t, CanonicalTransition.resolve)
# ball_ball CAT P1 e_b1 P2 e_b2 S1 S2 : kx1 ky1 kx2 ky2 u_b S1' S2'
#   (FrictionalInelastic: make_kiss's positions, AlciatoreBallBallFriction at them, resolve)
# linear_cushion CAT P e_c f_c S p1x p1y p2x p2y height shift : rvw' kx ky rvw''
# circular_cushion CAT P e_c f_c S cx cy radius height shift : rvw' kx ky rvw''
#   (StrongeCompliantLinear / StrongeCompliantCircular, omega_ratio 1.8: rvw' = solve at
#   contact; then the ball moved by shift along the normal, make_kiss's position kx ky, and
#   rvw'' = solve there, or "none" where pooltool fails;
#   CAT is the Stronge regime: gross_slip, stick_slip or slip_stick_slip)
# pocket CAT S ax ay radius depth t : motion rx ry rz vx vy vz wx wy wz t' contains
#   (CanonicalBallPocket.resolve on a ball at time t; contains 1 if the pocket holds it after)
# stick CAT m R V0 phi theta a b M end_mass tip_radius english squirt rx ry :
#   motion vx vy wx wy wz t' alpha
#   (InstantaneousPoint(english_throttle, squirt_throttle).resolve with a Cue of CueSpecs(M,
#   end_mass, tip_radius) on a ball of BallParams(m, R) at rx ry; alpha = get_squirt_angle;
#   CAT is level or elevated, with _side for a != 0)
"""


def cases(count: int, seed: int = SEED) -> Iterator[str]:
    """The table's lines: ``count`` of each kind, each kind from its own seeded stream."""
    for k, (_, generate) in enumerate(KINDS):
        rng = np.random.default_rng([seed, k])
        stream = generate(rng)
        for _ in range(count):
            yield next(stream)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--count", type=int, default=COUNT, help="cases of each kind")
    parser.add_argument("--out", type=Path, default=OUT)
    args = parser.parse_args(argv)
    import pooltool

    lines = list(cases(args.count))
    header = HEADER.format(version=pooltool.__version__, count=args.count, seed=SEED)
    args.out.write_text(header + "\n".join(lines) + "\n")
    print(f"{len(lines)} cases -> {args.out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
