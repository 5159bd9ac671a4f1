"""ballcollide as pooltool's ball–ball detector: its own simulations, exact contact times.

`pooltool <https://github.com/ekiefl/pooltool>`_ (``pip install pooltool-billiards``) finds
when two balls touch from a quartic of their current motion segments. That quartic breaks on
ordinary shots: balls rolling side by side at the same velocity "collide" at once (its
leading coefficients vanish), exactly touching balls that separate collide at ``t = 0``,
overlapping balls collide whether or not they approach, and roots past a segment's end stand
in for contacts. :func:`install` swaps in ballcollide: each ball's pooltool state becomes a
path of constant-acceleration segments — sliding (friction ``−u_s·g·û`` against the slip
``û``), rolling (``−u_r·g·v̂``), then at rest (a ball spinning in place does not move) — and
each pair's first contact on those paths is found by :func:`ballcollide.path_collision_times`
(balls that touch and separate do not collide; contact distance ``R₁ + R₂``, so balls of
different sizes are right too; a pair pooltool's resolution left overlapping collides when
its overlap would deepen past what it is, never "at once" while it separates). Everything
else — transitions, cushions, pockets, collision resolution, the event loop — stays
pooltool's own.

Or the whole shot natively: :func:`simulate` is ``pt.simulate`` run by ballcollide's Rust
engine (``ballcollide.billiards``: pooltool 0.6.0's physics, resolvers and event loop, its
quirks included by default), returning the same ``System``; :func:`simulate_many` runs many
shots across cores, with array results (:class:`ShotResults`).

The hook is pooltool's pair loop, ``pooltool.evolution.event_based.simulate.
get_next_ball_ball_collision``, which :func:`pooltool.simulate` looks up at each event: the
replacement, :func:`next_ball_ball_collision`, answers every pair missing from pooltool's
collision cache (after an event: each involved ball against all others) in one batch call,
and keeps the cache's keys, order and absolute times as pooltool's own loop does.

Supported: pooltool-billiards 0.6.0 (:data:`SUPPORTED_VERSIONS`); :func:`install` raises on
any other version. pooltool 0.6.0 installs only with ``--no-deps`` (it pins a development
build of panda3d that no package index has): ``scripts/install-pooltool VENV`` in the
repository installs it with the dependencies it needs. Importing ``ballcollide`` never imports
pooltool; this module imports it only inside :func:`install` and the functions that take
pooltool objects.

>>> import pooltool as pt
>>> import ballcollide.pooltool as bcp
>>> with bcp.install():                      # or bcp.install() ... bcp.uninstall()
...     system = pt.simulate(pt.System.example())
>>> bcp.is_installed()
False
>>> sum(e.event_type == pt.EventType.BALL_BALL for e in system.events) > 0
True
"""

from __future__ import annotations

import functools
import gc
import math
import weakref
from collections.abc import Sequence
from typing import Any, Callable

import numpy as np
import numpy.typing as npt

from . import InputError, path_collision_times

__all__ = [
    "CONTACT_RULES",
    "SUPPORTED_VERSIONS",
    "Installation",
    "ShotResults",
    "UnsupportedError",
    "ball_paths",
    "collision_time",
    "install",
    "is_installed",
    "next_ball_ball_collision",
    "simulate",
    "simulate_many",
    "uninstall",
]

#: The pooltool-billiards versions :func:`install` accepts.
SUPPORTED_VERSIONS: tuple[str, ...] = ("0.6.0",)

# pooltool's motion-state labels (pooltool.constants in 0.6.0).
_STATIONARY, _SPINNING, _SLIDING, _ROLLING, _POCKETED = 0, 1, 2, 3, 4
_NOT_MOVING = (_STATIONARY, _SPINNING, _POCKETED)

#: Segments per path: sliding, rolling, at rest (unused ones have zero length).
SEGMENTS = 3

_F64 = npt.NDArray[np.float64]
_Index = npt.NDArray[np.intp]
_Rows = tuple[list[float], list[list[float]], list[list[float]], list[list[float]]]

# pooltool's own pair loop while ours is installed, else None.
_original: Callable[..., Any] | None = None


def _simulate_module() -> Any:
    """pooltool's event-based simulation module, once its version is checked."""
    try:
        import pooltool
        from pooltool.evolution.event_based import simulate
    except ImportError as e:
        raise ImportError(
            f"ballcollide.pooltool needs pooltool-billiards {' or '.join(SUPPORTED_VERSIONS)} "
            f"({e}); it installs only with --no-deps plus its dependencies: run "
            "`scripts/install-pooltool VENV` from ballcollide's repository"
        ) from e
    version = getattr(pooltool, "__version__", "unknown")
    if version not in SUPPORTED_VERSIONS:
        raise RuntimeError(
            f"ballcollide.pooltool supports pooltool-billiards "
            f"{', '.join(SUPPORTED_VERSIONS)}, not {version}: its pair loop "
            "(simulate.get_next_ball_ball_collision) may differ; install a supported version"
        )
    if not callable(getattr(simulate, "get_next_ball_ball_collision", None)):
        raise RuntimeError(
            f"pooltool {version} has no simulate.get_next_ball_ball_collision to replace"
        )
    return simulate


class Installation:
    """What :func:`install` returns: a context manager that undoes that install on exit.

    Leaving the ``with`` block calls :func:`uninstall` only if this :func:`install` call is
    the one that swapped the detector in (a nested ``with install():`` inside an installed
    detector leaves it installed).

    >>> import ballcollide.pooltool as bcp
    >>> with bcp.install() as handle:
    ...     bcp.is_installed(), handle.swapped
    (True, True)
    >>> bcp.is_installed()
    False
    """

    def __init__(self, swapped: bool) -> None:
        #: Whether this install() call replaced pooltool's own detector.
        self.swapped = swapped

    def __enter__(self) -> Installation:
        return self

    def __exit__(self, *exc: object) -> None:
        if self.swapped:
            uninstall()


def install() -> Installation:
    """Make pooltool's simulations use ballcollide for ball–ball contact times.

    Replaces ``pooltool.evolution.event_based.simulate.get_next_ball_ball_collision`` by
    :func:`next_ball_ball_collision` until :func:`uninstall` (or the end of a ``with``
    block). Installing twice is the same as once.

    Raises
    ------
    ImportError
        pooltool is not installed.
    RuntimeError
        pooltool's version is not one of :data:`SUPPORTED_VERSIONS`.

    >>> import pooltool as pt
    >>> import ballcollide.pooltool as bcp
    >>> _ = bcp.install()
    >>> pt.evolution.event_based.simulate.get_next_ball_ball_collision is (
    ...     bcp.next_ball_ball_collision)
    True
    >>> bcp.uninstall()
    """
    global _original
    simulate = _simulate_module()
    if _original is not None:
        return Installation(swapped=False)
    _original = simulate.get_next_ball_ball_collision
    simulate.get_next_ball_ball_collision = next_ball_ball_collision
    return Installation(swapped=True)


def uninstall() -> None:
    """Give pooltool its own ball–ball detector back (nothing happens if none is installed).

    Raises
    ------
    RuntimeError
        Something else replaced pooltool's pair loop after :func:`install`: it is left as it
        is rather than overwritten.

    >>> import pooltool as pt
    >>> import ballcollide.pooltool as bcp
    >>> stock = pt.evolution.event_based.simulate.get_next_ball_ball_collision
    >>> _ = bcp.install(); bcp.uninstall()
    >>> pt.evolution.event_based.simulate.get_next_ball_ball_collision is stock
    True
    """
    global _original
    if _original is None:
        return
    from pooltool.evolution.event_based import simulate

    if simulate.get_next_ball_ball_collision is not next_ball_ball_collision:
        raise RuntimeError(
            "pooltool's simulate.get_next_ball_ball_collision was replaced by something else "
            "after ballcollide.pooltool.install(); not restoring over it"
        )
    simulate.get_next_ball_ball_collision = _original
    _original = None


def is_installed() -> bool:
    """Whether :func:`install` is in force.

    >>> import ballcollide.pooltool as bcp
    >>> bcp.is_installed()
    False
    """
    return _original is not None


def _friction(
    p: tuple[float, float],
    v: tuple[float, float],
    against: tuple[float, float],
    mu: float,
    g: float,
    share: float,
) -> tuple[list[float], float, list[float], list[float]] | None:
    """A segment of friction ``−mu·g`` against the direction ``against`` from position ``p``
    at velocity ``v``, lasting until ``v`` has lost ``share`` of ``|against|`` (for ever if
    ``mu = 0``): ``(acceleration, duration, end position, end velocity)``; ``None`` if
    ``against`` is zero."""
    size = math.hypot(*against)
    if size == 0:
        return None
    k = mu * g / size
    a = [-k * against[0], -k * against[1]]
    if mu == 0:
        return a, math.inf, [math.nan, math.nan], [math.nan, math.nan]
    tau = share * size / (mu * g)
    end = [p[i] + v[i] * tau + 0.5 * a[i] * tau * tau for i in (0, 1)]
    return a, tau, end, [v[0] + a[0] * tau, v[1] + a[1] * tau]


def _segments(ball: Any, t0: float) -> _Rows:
    """One ball's path from its state at absolute time ``t0``: ``(starts (3), pos (3×2),
    vel (3×2), acc (3×2))`` as nested lists (:func:`ball_paths` says what the segments
    are). Plain floats: for the one or two balls an event changes, a numpy call costs more
    than the arithmetic."""
    (x, y, _), (vx, vy, _), (wx, wy, _) = ball.state.rvw.tolist()
    state = ball.state.s
    params = ball.params
    inf = math.inf
    starts = [t0, t0, t0]
    pos = [[x, y], [x, y], [x, y]]
    vel = [[vx, vy], [vx, vy], [0.0, 0.0]]
    acc = [[0.0, 0.0], [0.0, 0.0], [0.0, 0.0]]
    if state != _SLIDING and state != _ROLLING:
        vel[0] = vel[1] = [0.0, 0.0]
        return starts, pos, vel, acc
    t = t0
    if state == _SLIDING:
        # The contact point's velocity over the cloth, v + ω × (−R ẑ): constant in
        # direction while the ball slides, friction against it, for 2|u|/(7·u_s·g). Without
        # slip the ball rolls at once, as pooltool evolves it.
        u = (vx - params.R * wy, vy + params.R * wx)
        sliding = _friction((x, y), (vx, vy), u, params.u_s, params.g, 2 / 7)
        if sliding is not None:
            acc[0], tau, (x, y), (vx, vy) = sliding
            if tau == inf:
                starts[1] = starts[2] = inf
                return starts, pos, vel, acc
            t = t0 + tau
            starts[1] = starts[2] = t
            pos[1] = pos[2] = [x, y]
            vel[1] = [vx, vy]
    rolling = _friction((x, y), (vx, vy), (vx, vy), params.u_r, params.g, 1.0)
    if rolling is not None:
        acc[1], tau, pos[2], _ = rolling
        starts[2] = inf if tau == inf else t + tau
    return starts, pos, vel, acc


def ball_paths(balls: Sequence[Any], t0: float = 0.0) -> tuple[_F64, _F64, _F64, _F64]:
    """Each pooltool ball's path from its current state, starting at time ``t0``.

    Returns ``(start (N, 3), pos (N, 3, 2), vel (N, 3, 2), acc (N, 3, 2))`` as
    :func:`ballcollide.path_collision_times` takes them: the segments sliding, rolling and at
    rest, on the table's plane (pooltool 0.6 moves balls in x and y only). A segment a ball
    skips has zero length (a rolling ball's sliding segment, say); one that never ends
    (``u_s = 0`` or ``u_r = 0``) is followed by ``+inf`` starts. Each ball's own ``R``,
    ``u_s``, ``u_r`` and ``g`` are used; ``u_sp`` only decays the spin of a ball whose centre
    is at rest, so it changes no path. Motion states are pooltool's labels, as its own
    evolution reads them: a *sliding* ball slides for ``2|u|/(7·u_s·g)`` with
    ``u = v + ω × (−R·ẑ)`` (none if ``u = 0``), then rolls, a *rolling* one rolls for
    ``|v|/(u_r·g)``, spinning, stationary and pocketed ones stay where they are.

    >>> import pooltool as pt
    >>> import ballcollide.pooltool as bcp
    >>> ball = pt.Ball.create("cue", xy=(0.5, 0.5))
    >>> ball.state.rvw[1] = (1.0, 0.0, 0.0)   # 1 m/s along x, rolling:
    >>> ball.state.rvw[2] = (0.0, 1.0 / ball.params.R, 0.0)
    >>> ball.state.s = 3
    >>> start, pos, vel, acc = bcp.ball_paths([ball])
    >>> start.round(6).tolist()                # no slide; rolls 1/(0.01·9.81) s, then rests
    [[0.0, 0.0, 10.19368]]
    >>> pos[0, 2].round(6).tolist()            # at rest |v|²/(2·u_r·g) further on
    [5.59684, 0.5]
    """
    rows = [_segments(b, t0) for b in balls]
    n = len(rows)
    start = np.array([r[0] for r in rows], dtype=np.float64).reshape(n, SEGMENTS)
    pos, vel, acc = (
        np.array([r[f] for r in rows], dtype=np.float64).reshape(n, SEGMENTS, 2) for f in (1, 2, 3)
    )
    return start, pos, vel, acc


class _PathTable:
    """The paths of a simulation's balls in absolute time, kept between calls of the pair
    loop: a ball's path changes only at an event that involves it, and then pooltool drops
    all of that ball's pairs from its cache, so a ball none of whose pairs is cached is the
    one to rebuild (at the current time); the others' paths still hold."""

    def __init__(self, ids: list[str]) -> None:
        n = len(ids)
        self.ids = ids
        self.start = np.zeros((n, SEGMENTS))
        self.pos = np.zeros((n, SEGMENTS, 2))
        self.vel = np.zeros((n, SEGMENTS, 2))
        self.acc = np.zeros((n, SEGMENTS, 2))

    def rebuild(self, balls: Sequence[Any], which: Sequence[int], t0: float) -> None:
        for i in which:
            start, pos, vel, acc = _segments(balls[i], t0)
            self.start[i], self.pos[i], self.vel[i], self.acc[i] = start, pos, vel, acc


# Each collision cache's path table (by the cache's id: pooltool's caches are not
# hashable), dropped when pooltool drops the cache.
_tables: dict[int, _PathTable] = {}


def _table_of(collision_cache: Any, ids: list[str]) -> tuple[_PathTable, bool]:
    """The path table kept for ``collision_cache``, and whether it is new (for other balls:
    a new one)."""
    table = _tables.get(id(collision_cache))
    if table is not None and table.ids == ids:
        return table, False
    if table is None:
        weakref.finalize(collision_cache, _tables.pop, id(collision_cache), None)
    table = _tables[id(collision_cache)] = _PathTable(ids)
    return table, True


def _pair_times(balls: Sequence[Any], table: _PathTable, first: _Index, second: _Index) -> _F64:
    """Absolute contact times of the pairs ``balls[first[p]]``, ``balls[second[p]]`` on the
    paths of ``table``, searched from the later of their starts: ``inf`` where either is
    pocketed or neither moves, else one call of :func:`ballcollide.path_collision_times`
    on the rest."""
    times = np.full(len(first), np.inf)
    state = np.array([b.state.s for b in balls])
    moving = (state == _SLIDING) | (state == _ROLLING)
    on_table = state != _POCKETED
    asked = (on_table[first] & on_table[second] & (moving[first] | moving[second])).nonzero()[0]
    if not len(asked):
        return times
    ia, ja = first[asked], second[asked]
    radius = np.array([b.params.R for b in balls], dtype=np.float64)
    contact = radius[ia] + radius[ja]
    # A pair that pooltool's resolution left overlapping (it moves a contact's two balls
    # apart, which in a cluster can push one into a third) touches at its present distance:
    # at once if closing in, else when the overlap comes back to what it is now.
    xy = np.array([b.state.rvw[0, :2] for b in balls], dtype=np.float64).reshape(-1, 2)
    apart = xy[ja] - xy[ia]
    dist = np.hypot(apart[:, 0], apart[:, 1])
    contact = np.where((dist < contact) & (dist > 0), dist, contact)
    t = table
    try:
        times[asked] = path_collision_times(
            t.start[ia], t.pos[ia], t.vel[ia], t.acc[ia],
            t.start[ja], t.pos[ja], t.vel[ja], t.acc[ja],
            contact,
        )  # fmt: skip
    except InputError as e:
        raise _ball_error(e, balls, ia, ja) from e
    return times


def _ball_error(e: InputError, balls: Sequence[Any], ia: _Index, ja: _Index) -> ValueError:
    """A bad path's error, naming the pooltool balls instead of the batch's arrays."""
    if e.index is None:
        return ValueError(f"ballcollide.pooltool: {e}")
    if e.argument.endswith("_a"):
        ball = balls[int(ia[e.index])]
    elif e.argument.endswith("_b"):
        ball = balls[int(ja[e.index])]
    else:
        pair = (balls[int(ia[e.index])].id, balls[int(ja[e.index])].id)
        return ValueError(f"ballcollide.pooltool: balls {pair}: {e.reason}")
    return ValueError(
        f"ballcollide.pooltool: ball {ball.id!r} (motion state {ball.state.s}, rvw "
        f"{ball.state.rvw.tolist()}, params R={ball.params.R} u_s={ball.params.u_s} "
        f"u_r={ball.params.u_r} g={ball.params.g}): {e.reason}"
    )


def collision_time(ball1: Any, ball2: Any) -> float:
    """When two pooltool balls first touch, in time from their current state; ``inf`` if
    they never do (as nothing else happens to them).

    The answer :func:`next_ball_ball_collision` puts in pooltool's cache (less the current
    time), for pooltool's ``solve.ball_ball_collision_time``'s question. Balls touching now
    touch at ``0`` only if they approach. Balls overlapping now (pooltool's resolution of a
    contact can push a ball a little into a third) touch at their present distance: at ``0``
    if closing in, else when their overlap comes back to what it is now, or never.

    >>> import pooltool as pt
    >>> import ballcollide.pooltool as bcp
    >>> a = pt.Ball.create("a", xy=(0.5, 0.5))
    >>> b = pt.Ball.create("b", xy=(1.0, 0.5))
    >>> a.state.rvw[1] = (1.0, 0.0, 0.0)       # sliding towards b with no spin (a stun
    >>> a.state.s = 2                          # shot): slides 0.146 s, then rolls
    >>> round(bcp.collision_time(a, b), 6)     # touches after 0.5 − 2R of travel
    0.60538
    >>> bcp.collision_time(b, a) == bcp.collision_time(a, b)
    True
    """
    balls = [ball1, ball2]
    table = _PathTable([ball1.id, ball2.id])
    table.rebuild(balls, (0, 1), 0.0)
    return float(_pair_times(balls, table, np.array([0]), np.array([1]))[0])


@functools.cache
def _pairs(n: int) -> tuple[_Index, _Index]:
    """The pairs ``i < j`` of ``n`` balls in pooltool's order (``itertools.combinations``)."""
    first, second = np.triu_indices(n, 1)
    return first, second


def next_ball_ball_collision(shot: Any, collision_cache: Any) -> Any:
    """pooltool's next ball–ball collision event, with ballcollide's contact times.

    The drop-in for ``pooltool.evolution.event_based.simulate.get_next_ball_ball_collision``
    (same arguments and result): every pair of ``shot.balls`` missing from the cache's
    ball–ball times gets its absolute contact time (``inf`` for none), all in one batch call,
    in pooltool's key order; the earliest cached pair is returned as a
    ``ball_ball`` event (the first such pair on ties, as pooltool picks it), or a null event
    at ``inf`` if there are no pairs.

    >>> import pooltool as pt
    >>> from pooltool.evolution.event_based.cache import CollisionCache
    >>> import ballcollide.pooltool as bcp
    >>> balls = {i: pt.Ball.create(i, xy=(0.5, y)) for i, y in [("cue", 0.5), ("1", 1.0),
    ...                                                        ("2", 1.5)]}
    >>> balls["cue"].state.rvw[1] = (0.0, 1.0, 0.0)   # towards 1, sliding
    >>> balls["cue"].state.s = 2
    >>> system = pt.System(cue=pt.Cue(cue_ball_id="cue"), table=pt.Table.default(),
    ...                    balls=balls)
    >>> cache = CollisionCache.create()
    >>> event = bcp.next_ball_ball_collision(system, cache)
    >>> event.event_type == pt.EventType.BALL_BALL, event.ids, round(event.time, 6)
    (True, ('cue', '1'), 0.60538)
    >>> # Each pair's contact as if nothing else happened, in absolute time:
    >>> {k: round(t, 6) for k, t in cache.times[pt.EventType.BALL_BALL].items()}
    {('cue', '1'): 0.60538, ('cue', '2'): 1.398689, ('1', '2'): inf}
    """
    from pooltool.events import EventType, ball_ball_collision, null_event

    cache = collision_cache.times.setdefault(EventType.BALL_BALL, {})
    balls = list(shot.balls.values())
    ids = [b.id for b in balls]
    n = len(balls)
    first, second = _pairs(n)
    keys = [(ids[i], ids[j]) for i, j in zip(first.tolist(), second.tolist())]
    missing = [p for p, key in enumerate(keys) if key not in cache]
    if missing:
        table, new = _table_of(collision_cache, ids)
        if new:
            changed = range(n)
        else:
            pairs_left = np.bincount(first[missing], minlength=n)
            pairs_left += np.bincount(second[missing], minlength=n)
            changed = (pairs_left == n - 1).nonzero()[0].tolist()
        table.rebuild(balls, changed, shot.t)
        times = _pair_times(balls, table, first[missing], second[missing])
        # In pooltool's key order, as its own loop fills the cache.
        cache.update(zip((keys[p] for p in missing), times.tolist()))
    if not cache:
        return null_event(np.inf)
    pair = min(cache, key=cache.__getitem__)
    return ball_ball_collision(
        ball1=shot.balls[pair[0]], ball2=shot.balls[pair[1]], time=cache[pair]
    )


# --- The native engine: whole shots in Rust (ballcollide._core.simulate_shots) -------------


class UnsupportedError(ValueError):
    """A pooltool setting the native engine (:func:`simulate`, :func:`simulate_many`) does
    not reproduce: a resolver other than pooltool 0.6.0's default, ``continuous=True``,
    ``t_final``, ``include``, ``max_events``. The message names it. Use ``pt.simulate``
    (optionally with :func:`install`) for those."""


#: The contact rules of :func:`simulate`: ``"pooltool"`` (pooltool 0.6.0's own, the
#: default: overlapping balls, and balls whose accelerations are equal to the bit, collide at
#: once when their pair is looked at, even if they part) and ``"approaching"`` (balls collide
#: only when they come into contact, approaching).
CONTACT_RULES: tuple[str, ...] = ("pooltool", "approaching")


@functools.lru_cache(maxsize=1)
def _pooltool_types() -> dict[str, Any]:
    """pooltool's classes and factories the engine's results are built from (looked up once,
    after the version check)."""
    simulate_module = _simulate_module()
    from pooltool.events import Agent, AgentType, Event, EventType, null_event
    from pooltool.evolution.event_based.config import INCLUDED_EVENTS
    from pooltool.objects.ball.datatypes import Ball, BallHistory, BallState
    from pooltool.physics.resolve.resolver import default_resolver
    from pooltool.system.datatypes import System

    return {
        "module": simulate_module,
        "Agent": Agent,
        "AgentType": AgentType,
        "Event": Event,
        "EventType": EventType,
        "null_event": null_event,
        "INCLUDED_EVENTS": frozenset(INCLUDED_EVENTS),
        "Ball": Ball,
        "BallHistory": BallHistory,
        "BallState": BallState,
        "System": System,
        "default_resolver": default_resolver(),
    }


def _check_supported(
    engine: Any,
    continuous: bool,
    dt: Any,
    t_final: Any,
    include: Any,
    max_events: int,
    contact_rule: str,
) -> None:
    """Raises :class:`UnsupportedError` for what the engine does not reproduce."""
    pt = _pooltool_types()
    if contact_rule not in CONTACT_RULES:
        raise UnsupportedError(f"contact_rule must be one of {CONTACT_RULES}, got {contact_rule!r}")
    if continuous or dt is not None:
        raise UnsupportedError(
            "continuous=True (and dt) is not supported: call "
            "pooltool.evolution.continuize(system) on the result"
        )
    if t_final is not None:
        raise UnsupportedError("t_final is not supported: the shot runs until every ball rests")
    if include is not None and frozenset(include) != pt["INCLUDED_EVENTS"]:
        raise UnsupportedError("include other than pooltool's INCLUDED_EVENTS is not supported")
    if max_events:
        raise UnsupportedError(
            "max_events is not supported (pooltool stops the balls after it; "
            "_core.simulate_shots' max_events cuts the log instead)"
        )
    resolver = (engine if engine is not None else pt["module"].DEFAULT_ENGINE).resolver
    default = pt["default_resolver"]
    if resolver != default:
        # The resolver's attrs fields (ball_ball, ball_linear_cushion, ...) that differ.
        fields = [f.name for f in getattr(type(default), "__attrs_attrs__", ())]
        differ = [f for f in fields if getattr(resolver, f, None) != getattr(default, f)]
        raise UnsupportedError(
            "only pooltool 0.6.0's default resolver is supported; this engine's differs in "
            f"{', '.join(differ) or 'its type'} (see ~/.config/pooltool/physics/resolver.yaml)"
        )


def _inputs(shots: Sequence[Any]) -> dict[str, Any]:
    """``_core.simulate_shots``' arguments for pooltool ``System`` s (read in Rust:
    ``_core._pooltool_inputs``; each distinct table read once, and tables of equal rows
    sharing one index)."""
    from . import _core

    return _core._pooltool_inputs(shots)


class ShotResults:
    """What :func:`simulate_many` returns: the shots' events and final states as arrays
    (``_core.simulate_shots``' results, one attribute each), and :meth:`to_system`.

    Shot ``k``'s events are rows ``event_start[k]:event_start[k + 1]`` of ``time``,
    ``type`` (codes: ``type_names[code]`` is pooltool's ``EventType`` value), ``ball`` (the
    balls, by their index in the shot's ``balls`` dict, ``-1`` for none), ``object`` (the
    cushion's or pocket's index in its table dict, else ``-1``), ``rvw`` and ``s`` (each
    ball's state just after the event); its balls' final states are rows
    ``ball_start[k]:ball_start[k + 1]`` of ``final_rvw`` and ``final_s``. ``len()`` is the
    number of shots.
    """

    event_start: npt.NDArray[np.int64]
    time: _F64
    type: npt.NDArray[np.int64]
    ball: npt.NDArray[np.int64]
    object: npt.NDArray[np.int64]
    rvw: _F64
    s: npt.NDArray[np.int64]
    final_rvw: _F64
    final_s: npt.NDArray[np.int64]
    end: _F64
    stopped: npt.NDArray[np.bool_]
    type_names: tuple[str, ...]
    ball_start: npt.NDArray[np.int64]

    def __init__(self, shots: Sequence[Any], arrays: dict[str, Any], contact_rule: str) -> None:
        self._shots = list(shots)
        self._arrays = arrays
        self._contact_rule = contact_rule
        for key, value in arrays.items():
            setattr(self, key, value)
        self.ball_start = np.cumsum([0] + [len(s.balls) for s in self._shots], dtype=np.int64)

    def __len__(self) -> int:
        return len(self._shots)

    def to_system(self, k: int) -> Any:
        """Shot ``k`` as the pooltool ``System`` :func:`simulate` returns (a new one; the
        shot given to :func:`simulate_many` is not changed)."""
        if "history_rvw" in self._arrays:
            return _build(self._shots[k], self._arrays, k, inplace=False)
        return simulate(self._shots[k], contact_rule=self._contact_rule)


def simulate_many(
    shots: Sequence[Any],
    num_threads: int | None = None,
    *,
    contact_rule: str = "pooltool",
    history: bool = False,
) -> ShotResults:
    """Simulates pooltool ``System`` s natively, on up to ``num_threads`` threads (``None``:
    all cores), with the GIL released; the shots are not changed.

    Each shot is what :func:`simulate` gives it (the same events, bit for bit, whatever
    ``num_threads``), returned as arrays (:class:`ShotResults`), which cost a small part of
    building pooltool objects; :meth:`ShotResults.to_system` builds shot ``k``'s ``System``.
    ``history=True`` also computes every ball's state at every event (so that ``to_system``
    needs no second run).
    Raises :class:`UnsupportedError` as :func:`simulate` does for pooltool's default engine,
    ``ballcollide.InputError`` naming the shot (``shots[3].position``) for one the engine
    rejects, and ``ValueError`` for a cue whose ``cue_ball_id`` is not among its shot's
    balls.

    >>> import pooltool as pt
    >>> import ballcollide.pooltool as bcp
    >>> results = bcp.simulate_many([pt.System.example()] * 3, num_threads=2)
    >>> len(results), results.type_names[results.type[0]]
    (3, 'stick_ball')
    >>> system = results.to_system(1)
    >>> [e.event_type for e in system.events[:2]] == [pt.EventType.NONE, pt.EventType.STICK_BALL]
    True
    """
    from . import _core

    _check_supported(None, False, None, None, None, 0, contact_rule)
    shots = list(shots)

    def played(inputs: dict[str, Any]) -> dict[str, Any]:
        return _core.simulate_shots(
            **inputs,
            contact_rule=contact_rule,
            history=history,
            num_threads=num_threads,
        )

    # The reading holds the GIL, on this thread alone. It is not overlapped with the engine:
    # the engine's threads keep every core busy, so a reading thread would only take turns
    # with them (measured on 2 cores: no gain).
    return ShotResults(shots, played(_inputs(shots)), contact_rule)


#: The results of ``_core.simulate_shots`` that are offsets into the others (one per shot, and
#: one past the end): shifted when parts are joined; every other array is concatenated.
_OFFSETS = ("event_start", "history_start")


def _joined(blocks: Sequence[dict[str, Any]]) -> dict[str, Any]:
    """Consecutive parts' results (``_core.simulate_shots``' dicts) as one call's: arrays
    concatenated, offsets shifted."""
    joined: dict[str, Any] = {}
    for key, first in blocks[0].items():
        if key in _OFFSETS:
            parts, end = [first[:1]], 0
            for block in blocks:
                parts.append(block[key][1:] + end)
                end += int(block[key][-1])
            joined[key] = np.concatenate(parts)
        elif isinstance(first, np.ndarray):
            joined[key] = np.concatenate([block[key] for block in blocks])
        else:  # type_names: the same in every part
            joined[key] = first
    return joined


def simulate(
    shot: Any,
    engine: Any = None,
    inplace: bool = False,
    continuous: bool = False,
    dt: float | None = None,
    t_final: float | None = None,
    include: Any = None,
    max_events: int = 0,
    *,
    contact_rule: str = "pooltool",
) -> Any:
    """``pooltool.simulate`` run natively: the shot in Rust, returned as pooltool's ``System``.

    The same call as ``pt.simulate(shot, ...)`` for what it supports, and the same result:
    ``events`` (the null events at both ends, each event with its agents' ``initial`` and
    ``final`` copies), every ball's ``history`` (its state at every event), ``state``, the
    pockets' ``contains``, ``t``. By default (``contact_rule="pooltool"``) the events are
    stock pooltool 0.6.0's, its quirks included (overlapping balls, and balls with equal
    accelerations, collide at once); ``contact_rule="approaching"`` collides balls only when
    they come into contact. Times agree with pooltool's to rounding (pooltool evolves every
    ball to every event; here each ball follows its own path), which a long break amplifies
    to about ``1e-6 s``.

    Raises :class:`UnsupportedError` for ``engine`` (or pooltool's default engine, from
    ``~/.config/pooltool/physics/resolver.yaml``) with a resolver other than pooltool 0.6.0's
    default, ``continuous=True``, ``dt``, ``t_final``, ``include``, ``max_events``.

    >>> import pooltool as pt
    >>> import ballcollide.pooltool as bcp
    >>> system = bcp.simulate(pt.System.example())
    >>> stock = pt.simulate(pt.System.example())
    >>> [e.event_type for e in system.events] == [e.event_type for e in stock.events]
    True
    >>> abs(system.t - stock.t) < 1e-9
    True
    """
    from . import _core

    _check_supported(engine, continuous, dt, t_final, include, max_events, contact_rule)
    arrays = _core.simulate_shots(
        **_inputs([shot]), contact_rule=contact_rule, history=True, num_threads=1
    )
    return _build(shot, arrays, 0, inplace=inplace)


def _build(shot: Any, r: dict[str, Any], k: int, inplace: bool) -> Any:
    """Shot ``k`` of ``_core.simulate_shots``' results (with history) as pooltool's
    ``simulate(shot, inplace=inplace)`` leaves it: written into ``shot``, or into a copy.

    The copy is ``shot.copy()`` (pooltool's ``System.copy``) less the balls' copies, whose
    states and histories the build replaces: it makes the balls itself, each sharing its
    ``id``, ``params``, ``ballset`` and ``initial_orientation`` with the ball of ``shot``, as
    ``Ball.copy`` does. The objects are made in Rust (``_core._PooltoolBuilder``: each as
    ``object.__new__`` with its slots filled directly; pooltool's attrs constructors cost
    about a microsecond an object, and a break's ``System`` holds thousands).

    Python's cyclic garbage collector is paused meanwhile. The thousands of new objects
    would otherwise set off collections in the middle, each of which moves the live ones on
    to an older generation, and so brings on collections of the whole heap sooner (with
    pooltool and numba loaded, hundreds of thousands of objects): measured on the
    benchmark's shots, 2.3 ms a shot without the pause, 0.7 ms with it. None of the objects
    made here forms a cycle; the collector runs again as usual afterwards.
    """
    if inplace:
        system = shot
    else:
        system = _pooltool_types()["System"](
            cue=shot.cue.copy(), table=shot.table.copy(), balls=dict(shot.balls), t=shot.t
        )
    paused = gc.isenabled()
    gc.disable()
    try:
        _builder().build(system, r, k, not inplace)
    finally:
        if paused:
            gc.enable()
    return system


@functools.lru_cache(maxsize=1)
def _builder() -> Any:
    """The builder of pooltool's objects, made once (it looks up how to fill each class)."""
    from . import _core

    return _core._PooltoolBuilder(_pooltool_types())
