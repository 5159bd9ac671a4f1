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
import math
import weakref
from collections.abc import Sequence
from typing import Any, Callable

import numpy as np
import numpy.typing as npt

from . import InputError, path_collision_times

__all__ = [
    "SUPPORTED_VERSIONS",
    "Installation",
    "ball_paths",
    "collision_time",
    "install",
    "is_installed",
    "next_ball_ball_collision",
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
