"""ballcollide: when do two balls slowing under friction first touch?

Each ball moves on a straight line from its position ``p`` with velocity ``v``, slowed by a
constant friction deceleration ``μ ≥ 0`` (length / time²) until it stops at ``τ = |v|/μ``, and
stays there. Two balls collide when their centres come within ``radius`` (the sum of their
radii): the collision time is the first ``t ≥ 0`` at which they start to interpenetrate
(``0`` if they already touch and are approaching), ``inf`` if they never do (or not before
``t_max``). The times are as accurate as float64 inputs allow.

Functions (all take array-likes: lists, any real dtype, C or Fortran order, strided views):

- :func:`collision_time`: one pair;
- :func:`collision_times`: N pairs at once, on all cores, with the GIL released;
- :func:`positions_at`: where N balls are at a time ``t`` (a stopped ball stays put);
- :func:`real_roots`: real roots of N polynomials of degree 1 to 4, like ``numpy.roots``;
- :func:`pairwise_collision_times`, :func:`earliest_collision`, :func:`first_contacts`: a
  scene of N balls (which pairs touch, which touch first), with a broad phase that prunes
  the pairs that cannot meet.

Bad input (NaN or infinity, negative friction, ``radius ≤ 0``, wrong shapes or lengths)
raises ``ValueError`` naming the argument and, for batches, the first bad index; an argument
that is not made of real numbers raises ``TypeError``.

>>> import ballcollide as bc
>>> # A ball shot at 1 m/s (no friction) at a resting ball 1 m away; contact at 0.5 m.
>>> bc.collision_time([0, 0], [1, 0], 0.0, [1, 0], [0, 0], 0.0, 0.5)
0.5
"""

from __future__ import annotations

import operator
from typing import Any, Union

import numpy as np
import numpy.typing as npt

from . import _core

__version__: str = _core.__version__

__all__ = [
    "__version__",
    "collision_time",
    "collision_times",
    "earliest_collision",
    "first_contacts",
    "pairwise_collision_times",
    "positions_at",
    "real_roots",
]

#: One value for every pair (a scalar) or one per pair (shape ``(N,)``).
PerPair = Union[float, npt.ArrayLike]

_REAL_KINDS = "fiu"  # float, signed and unsigned integer dtypes


def _real_array(name: str, x: Any) -> np.ndarray:
    """``x`` as a numpy array of real numbers, or an error naming ``name``."""
    try:
        a = np.asarray(x)
    except (ValueError, TypeError) as e:  # ragged nested lists, unconvertible objects
        raise ValueError(f"{name}: cannot be read as an array of numbers ({e})") from None
    if a.dtype.kind not in _REAL_KINDS:
        raise TypeError(f"{name}: expected real numbers, got an array of dtype {a.dtype}")
    return a


def _rows(name: str, x: npt.ArrayLike) -> np.ndarray:
    """An ``(N, 2)`` array-like as a C-contiguous float64 array (copied only if needed)."""
    a = _real_array(name, x)
    if a.ndim != 2 or a.shape[1] != 2:
        raise ValueError(f"{name}: expected shape (N, 2), got {a.shape}")
    return np.ascontiguousarray(a, dtype=np.float64)


def _per_pair(name: str, x: PerPair) -> float | np.ndarray:
    """A scalar as a float, or an ``(N,)`` array-like as a contiguous float64 array."""
    a = _real_array(name, x)
    if a.ndim == 0:
        return float(a)
    if a.ndim == 1:
        return np.ascontiguousarray(a, dtype=np.float64)
    raise ValueError(f"{name}: expected a scalar or shape (N,), got shape {a.shape}")


def _point(name: str, x: npt.ArrayLike) -> tuple[float, float]:
    a = _real_array(name, x)
    if a.shape != (2,):
        raise ValueError(f"{name}: expected a 2-vector (x, y), got shape {a.shape}")
    return (float(a[0]), float(a[1]))


def _scalar(name: str, x: Any) -> float:
    a = _real_array(name, x)
    if a.ndim != 0:
        raise ValueError(f"{name}: expected a scalar, got shape {a.shape}")
    return float(a)


def _threads(num_threads: int | None) -> int | None:
    if num_threads is None:
        return None
    if isinstance(num_threads, (bool, np.bool_)):
        raise TypeError("num_threads: expected None or an int, got bool")
    try:
        n = operator.index(num_threads)
    except TypeError:
        raise TypeError(
            f"num_threads: expected None or an int, got {type(num_threads).__name__}"
        ) from None
    if n < 1:
        raise ValueError(f"num_threads: must be None (all cores) or ≥ 1, got {n}")
    return min(n, 1 << 30)  # the core uses at most as many threads as there are cores


def collision_time(
    pos_a: npt.ArrayLike,
    vel_a: npt.ArrayLike,
    friction_a: float,
    pos_b: npt.ArrayLike,
    vel_b: npt.ArrayLike,
    friction_b: float,
    radius: float,
    *,
    t_max: float = np.inf,
) -> float:
    """The time at which two balls first touch, or ``inf`` if they never do.

    Parameters
    ----------
    pos_a, vel_a, pos_b, vel_b
        Centre and velocity of each ball at time 0, as ``(x, y)``.
    friction_a, friction_b
        Each ball's friction deceleration ``μ ≥ 0`` (length / time²); ``0`` for none.
    radius
        The contact distance: the sum of the two balls' radii (``> 0``).
    t_max
        Horizon: a collision at ``t ≥ t_max`` is reported as ``inf``.

    Returns
    -------
    float
        The first time ``t ≥ 0`` at which the centres are ``radius`` apart and closing in
        (``0.0`` if they already touch or overlap and approach each other), else ``inf``.
        It is exactly the value :func:`collision_times` gives for the same pair.

    Raises
    ------
    ValueError
        A NaN or infinite number, a negative friction, ``radius ≤ 0``, a negative or NaN
        ``t_max``, or a vector that is not two numbers; the message names the argument.
    TypeError
        An argument that is not made of real numbers.

    Examples
    --------
    >>> import ballcollide as bc
    >>> # A cue ball at 2 m/s, slowed at 0.2 m/s², towards a resting ball 1 m away.
    >>> t = bc.collision_time([0, 0], [2, 0], 0.2, [1, 0], [0, 0], 0.2, 0.05715)
    >>> round(t, 6)
    0.483094
    >>> bc.collision_time([0, 0], [2, 0], 0.2, [1, 0.1], [0, 0], 0.2, 0.05715)  # misses
    inf
    """
    return _core.collision_time(
        _point("pos_a", pos_a),
        _point("vel_a", vel_a),
        _scalar("friction_a", friction_a),
        _point("pos_b", pos_b),
        _point("vel_b", vel_b),
        _scalar("friction_b", friction_b),
        _scalar("radius", radius),
        _scalar("t_max", t_max),
    )


def collision_times(
    pos_a: npt.ArrayLike,
    vel_a: npt.ArrayLike,
    friction_a: PerPair,
    pos_b: npt.ArrayLike,
    vel_b: npt.ArrayLike,
    friction_b: PerPair,
    radius: PerPair,
    *,
    t_max: PerPair = np.inf,
    num_threads: int | None = None,
    out: npt.NDArray[np.float64] | None = None,
) -> npt.NDArray[np.float64]:
    """The collision time of each of N pairs of balls (``inf`` where they never touch).

    Pair ``i`` is ball A (``pos_a[i]``, ``vel_a[i]``, ``friction_a``) against ball B
    (``pos_b[i]``, ``vel_b[i]``, ``friction_b``) at contact distance ``radius``; each answer
    is exactly what :func:`collision_time` gives for that pair.

    Parameters
    ----------
    pos_a, vel_a, pos_b, vel_b
        Shape ``(N, 2)``: centres and velocities at time 0. Any real dtype, C or Fortran
        order, strided views and nested lists are accepted (converted once to C-ordered
        float64; arrays that already are so are not copied).
    friction_a, friction_b, radius, t_max
        Scalars (the same for every pair) or shape ``(N,)``: friction decelerations
        (``≥ 0``), contact distances (sums of the radii, ``> 0``), horizons (``≥ 0``,
        ``inf`` for none).
    num_threads
        ``None`` (default): all cores. An int ``n ≥ 1``: at most ``n`` threads. The result
        does not depend on it, bit for bit.
    out
        ``None`` (default): the times go into a new array. Else a writeable, C-contiguous
        float64 array of shape ``(N,)`` that shares no memory with the inputs: the times are
        written into it and it is returned, as numpy's ``out=``. A simulator that asks again
        after every event saves the allocation, and the page faults of a fresh array, on
        each call. If the call raises, its contents are unspecified.

    Returns
    -------
    numpy.ndarray
        Shape ``(N,)``, float64 (``out`` itself if given).

    Raises
    ------
    ValueError
        A NaN or infinite number, a negative friction, ``radius ≤ 0``, a negative ``t_max``,
        a wrong shape or a length that differs from ``pos_a``'s; the message names the
        argument and the first offending index, e.g. ``friction_b[7]: friction must be ≥ 0,
        got -0.1``. An ``out`` of the wrong shape, not C-contiguous, read-only or sharing
        memory with an input.
    TypeError
        An argument that is not made of real numbers, a non-integer ``num_threads``, or an
        ``out`` that is not a float64 array of one dimension.

    Notes
    -----
    The GIL is released while the pairs are computed, so other Python threads keep running.
    C-ordered float64 inputs are read in place, without a copy: do not modify them from
    another thread during the call.

    Examples
    --------
    >>> import numpy as np
    >>> import ballcollide as bc
    >>> pos_a = np.zeros((3, 2))
    >>> vel_a = np.array([[1.0, 0.0], [1.0, 0.0], [2.0, 0.0]])
    >>> pos_b = np.array([[1.0, 0.0], [1.0, 5.0], [1.0, 0.0]])
    >>> bc.collision_times(pos_a, vel_a, 0.0, pos_b, np.zeros((3, 2)), 0.0, 0.5)
    array([0.5 ,  inf, 0.25])
    >>> bc.collision_times(pos_a, vel_a, [0.0, 0.0, 8.0], pos_b, np.zeros((3, 2)), 0.0, 0.5)
    array([0.5, inf, inf])
    >>> times = np.empty(3)
    >>> bc.collision_times(pos_a, vel_a, 0.0, pos_b, np.zeros((3, 2)), 0.0, 0.5, out=times)
    array([0.5 ,  inf, 0.25])
    """
    return _core.collision_times(
        _rows("pos_a", pos_a),
        _rows("vel_a", vel_a),
        _per_pair("friction_a", friction_a),
        _rows("pos_b", pos_b),
        _rows("vel_b", vel_b),
        _per_pair("friction_b", friction_b),
        _per_pair("radius", radius),
        _per_pair("t_max", t_max),
        _threads(num_threads),
        out,
    )


def positions_at(
    pos: npt.ArrayLike,
    vel: npt.ArrayLike,
    friction: PerPair,
    t: PerPair,
    *,
    num_threads: int | None = None,
    out: npt.NDArray[np.float64] | None = None,
) -> npt.NDArray[np.float64]:
    """The centres of N balls at time ``t``; a ball that has stopped stays where it stopped.

    Ball ``i`` starts at ``pos[i]`` with velocity ``vel[i]`` and decelerates at
    ``friction`` until it stops at ``τ = |v|/μ``; its centre at ``0 ≤ t ≤ τ`` is
    ``p + v·t·(1 − t/(2τ))`` and ``p + v·τ/2`` afterwards. Negative times count as ``0``.

    Parameters
    ----------
    pos, vel
        Shape ``(N, 2)``, as in :func:`collision_times`.
    friction, t
        Scalars or shape ``(N,)``: friction decelerations (``≥ 0``) and times (finite).
    num_threads
        As in :func:`collision_times`.
    out
        As in :func:`collision_times`, of shape ``(N, 2)``.

    Returns
    -------
    numpy.ndarray
        Shape ``(N, 2)``, float64 (``out`` itself if given).

    Examples
    --------
    >>> import ballcollide as bc
    >>> # 2 m/s slowed at 0.5 m/s²: it stops after 4 s, 4 m further on, and stays.
    >>> bc.positions_at([[0, 0], [0, 0]], [[2, 0], [2, 0]], 0.5, [2.0, 10.0])
    array([[3., 0.],
           [4., 0.]])
    """
    return _core.positions_at(
        _rows("pos", pos),
        _rows("vel", vel),
        _per_pair("friction", friction),
        _per_pair("t", t),
        _threads(num_threads),
        out,
    )


def real_roots(coeffs: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """The real roots of N polynomials of degree ``k`` (1 to 4), sorted, NaN-padded.

    Parameters
    ----------
    coeffs
        Shape ``(N, k+1)``, highest degree first like ``numpy.roots``: row ``i`` is
        ``c[i,0]·x^k + … + c[i,k]``. A 1-D array of ``k+1`` coefficients is one polynomial.
        A zero leading coefficient lowers the degree (the row just has fewer roots).

    Returns
    -------
    numpy.ndarray
        Shape ``(N, k)`` (``(k,)`` for 1-D input), float64: each row's real roots in
        ascending order, a multiple root repeated, then NaN for the missing ones. A constant
        row (no isolated root) is all NaN.

    Raises
    ------
    ValueError
        A NaN or infinite coefficient (named as ``coeffs[i]``, ``i`` the row), or a shape
        other than ``(N, 2..5)``.
    TypeError
        Coefficients that are not real numbers.

    Examples
    --------
    >>> import ballcollide as bc
    >>> bc.real_roots([[1, -3, 2], [1, -2, 1], [1, 0, 1]])  # (x−1)(x−2), (x−1)², x²+1
    array([[ 1.,  2.],
           [ 1.,  1.],
           [nan, nan]])
    >>> bc.real_roots([1, -10, 35, -50, 24])  # (x−1)(x−2)(x−3)(x−4)
    array([1., 2., 3., 4.])
    """
    a = _real_array("coeffs", coeffs)
    if a.ndim == 1:
        one: npt.NDArray[np.float64] = real_roots(a[np.newaxis, :])[0]
        return one
    if a.ndim != 2:
        raise ValueError(f"coeffs: expected shape (N, k+1) with k = 1..4, got {a.shape}")
    return _core.real_roots(np.ascontiguousarray(a, dtype=np.float64))


def _scene(
    pos: npt.ArrayLike, vel: npt.ArrayLike, friction: PerPair, radius: PerPair
) -> tuple[np.ndarray, np.ndarray, float | np.ndarray, float | np.ndarray]:
    """A scene's arrays, normalised; lengths are checked by the core (naming the argument)."""
    return (
        _rows("pos", pos),
        _rows("vel", vel),
        _per_pair("friction", friction),
        _per_pair("radius", radius),
    )


def pairwise_collision_times(
    pos: npt.ArrayLike,
    vel: npt.ArrayLike,
    friction: PerPair,
    radius: PerPair,
    *,
    t_max: float = np.inf,
    num_threads: int | None = None,
) -> npt.NDArray[np.float64]:
    """The collision time of every pair of N balls, as an ``(N, N)`` matrix.

    Entry ``[i, j]`` is the time at which balls ``i`` and ``j`` first touch (what
    :func:`collision_time` gives for ball ``i`` as A, ball ``j`` as B and the sum of their
    radii, for ``i < j``; the matrix is symmetric), ``inf`` if they never do (or not before
    ``t_max``), and ``inf`` on the diagonal. Only pairs whose swept bounding boxes overlap
    are computed (the others cannot touch); the answer is the all-pairs answer, bit for bit.

    Parameters
    ----------
    pos, vel
        Shape ``(N, 2)``: each ball's centre and velocity at time 0 (any array-like, as in
        :func:`collision_times`).
    friction
        A scalar or shape ``(N,)``: each ball's friction deceleration ``μ ≥ 0``.
    radius
        A scalar or shape ``(N,)``: each ball's radius (``> 0``). A pair touches when its
        centres are the *sum* of its two radii apart.
    t_max
        Horizon: a collision at ``t ≥ t_max`` is reported as ``inf``.
    num_threads
        ``None``: all cores; an int ``≥ 1``: at most that many. The result does not depend
        on it.

    Returns
    -------
    numpy.ndarray
        Shape ``(N, N)``, float64 (``N²`` numbers: for large N prefer
        :func:`earliest_collision` or :func:`first_contacts`).

    Raises
    ------
    ValueError
        A NaN or infinite number, a negative friction, a radius ``≤ 0``, a negative ``t_max``,
        a wrong shape or length; the message names the argument and the first bad index,
        e.g. ``radius[3]: ...``.
    TypeError
        An argument that is not made of real numbers.
    MemoryError
        An ``(N, N)`` matrix too large to allocate (checked before any work is done).

    Examples
    --------
    >>> import ballcollide as bc
    >>> # A ball at 1 m/s (no friction) towards a resting ball 1 m away; radii 0.2 and 0.3.
    >>> bc.pairwise_collision_times([[0, 0], [1, 0]], [[1, 0], [0, 0]], 0.0, [0.2, 0.3])
    array([[inf, 0.5],
           [0.5, inf]])
    """
    return _core.pairwise_collision_times(
        *_scene(pos, vel, friction, radius), _scalar("t_max", t_max), _threads(num_threads)
    )


def earliest_collision(
    pos: npt.ArrayLike,
    vel: npt.ArrayLike,
    friction: PerPair,
    radius: PerPair,
    *,
    t_max: float = np.inf,
    num_threads: int | None = None,
) -> tuple[float, int, int]:
    """The first collision among N balls: ``(t, i, j)`` with ``i < j``.

    ``(inf, -1, -1)`` if no two balls touch before ``t_max``. Of pairs colliding at the same
    time, the lowest ``i`` wins, then the lowest ``j``. This is the question an event-driven
    simulator asks after every event; only the pairs whose swept bounding boxes overlap are
    computed, and the answer equals the all-pairs answer exactly.

    Parameters
    ----------
    pos, vel
        Shape ``(N, 2)``: each ball's centre and velocity at time 0 (any array-like, as in
        :func:`collision_times`).
    friction
        A scalar or shape ``(N,)``: each ball's friction deceleration ``μ ≥ 0``.
    radius
        A scalar or shape ``(N,)``: each ball's radius (``> 0``). A pair touches when its
        centres are the *sum* of its two radii apart.
    t_max
        Horizon: a collision at ``t ≥ t_max`` is reported as none.
    num_threads
        As in :func:`pairwise_collision_times`.

    Raises
    ------
    ValueError, TypeError
        As :func:`pairwise_collision_times`.

    Examples
    --------
    >>> import ballcollide as bc
    >>> pos = [[0, 0], [5, 5], [1, 0]]
    >>> vel = [[1, 0], [0, 0], [-1, 0]]
    >>> t, i, j = bc.earliest_collision(pos, vel, 0.5, 0.05)
    >>> (round(t, 6), i, j)
    (0.51676, 0, 2)
    >>> bc.earliest_collision(pos, vel, 0.5, 0.05, t_max=0.1)
    (inf, -1, -1)
    """
    t, i, j = _core.earliest_collision(
        *_scene(pos, vel, friction, radius), _scalar("t_max", t_max), _threads(num_threads)
    )
    return (t, i, j)


def first_contacts(
    pos: npt.ArrayLike,
    vel: npt.ArrayLike,
    friction: PerPair,
    radius: PerPair,
    *,
    t_max: float = np.inf,
    num_threads: int | None = None,
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """Each ball's first collision: ``(times, partner)``, both of shape ``(N,)``.

    Ball ``i`` first touches ball ``partner[i]`` at ``times[i]``, ignoring every other
    collision (each is the earliest entry of row ``i`` of :func:`pairwise_collision_times`);
    ``inf`` and ``-1`` if it touches none before ``t_max``. Of partners at the same time, the
    lowest index wins.

    Parameters
    ----------
    pos, vel
        Shape ``(N, 2)``: each ball's centre and velocity at time 0 (any array-like, as in
        :func:`collision_times`).
    friction
        A scalar or shape ``(N,)``: each ball's friction deceleration ``μ ≥ 0``.
    radius
        A scalar or shape ``(N,)``: each ball's radius (``> 0``). A pair touches when its
        centres are the *sum* of its two radii apart.
    t_max
        Horizon: a collision at ``t ≥ t_max`` is reported as none.
    num_threads
        As in :func:`pairwise_collision_times`.

    Returns
    -------
    tuple of numpy.ndarray
        ``times`` (float64) and ``partner`` (int64, ``-1`` for none).

    Raises
    ------
    ValueError, TypeError
        As :func:`pairwise_collision_times`.

    Examples
    --------
    >>> import ballcollide as bc
    >>> times, partner = bc.first_contacts([[0, 0], [0, 2], [9, 9]], [[0, 1], [0, 0], [0, 0]],
    ...                                    0.0, 0.5)
    >>> times, partner
    (array([ 1.,  1., inf]), array([ 1,  0, -1]))
    """
    return _core.first_contacts(
        *_scene(pos, vel, friction, radius), _scalar("t_max", t_max), _threads(num_threads)
    )
