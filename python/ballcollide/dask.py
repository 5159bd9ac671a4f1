"""Collision times of pairs held in Dask arrays: lazy, chunked, out of core, distributed.

:func:`collision_times` takes the arguments of :func:`ballcollide.collision_times` as Dask
arrays, numpy arrays or array-likes (mixed freely), split into chunks along the pair axis,
and returns a lazy Dask array of times. Each chunk of pairs is computed by one call of
:func:`ballcollide.collision_times` — the same kernel, so every time is bit for bit the one
an in-memory call gives — on one thread per chunk by default, so that a Dask worker with
``k`` threads keeps ``k`` cores busy and no more.

:func:`simulate_many` plays pooltool shots as :func:`ballcollide.pooltool.simulate_many`
does, in chunks of shots spread over Dask's workers, and gathers them into one
:class:`~ballcollide.pooltool.ShotResults` (the workers need pooltool too).

This module needs Dask's arrays: ``pip install 'ballcollide[dask]'``. Importing
``ballcollide`` alone never imports Dask.

>>> import dask.array as da
>>> import numpy as np
>>> import ballcollide.dask as bcd
>>> pos_a = da.zeros((3, 2), chunks=2)  # chunks of 2 pairs: blocks of 2 and 1 rows
>>> vel_a = np.array([[1.0, 0.0], [1.0, 0.0], [2.0, 0.0]])  # numpy arrays mix in
>>> pos_b = da.from_array(np.array([[1.0, 0.0], [1.0, 5.0], [1.0, 0.0]]), chunks=2)
>>> t = bcd.collision_times(pos_a, vel_a, 0.0, pos_b, np.zeros((3, 2)), 0.0, 0.5)
>>> t
dask.array<collision_times, shape=(3,), dtype=float64, chunksize=(2,), chunktype=numpy.ndarray>
>>> t.compute()
array([0.5 ,  inf, 0.25])
"""

from __future__ import annotations

import math
import re
import warnings
from collections.abc import Sequence
from typing import Any, Union

import numpy as np
import numpy.typing as npt

try:
    import dask.array as da
except ImportError as e:  # dask, or its array dependencies, missing
    raise ImportError(
        f"ballcollide.dask needs Dask's arrays ({e}); install them with "
        "`pip install 'ballcollide[dask]'` (or `pip install 'dask[array]'`)"
    ) from e

from . import InputError
from . import collision_times as _check_now  # the eager checks, on an empty batch
from . import collision_times as _collision_times  # one call for each chunk

__all__ = ["collision_times", "simulate_many"]

#: A Dask array, a numpy array or anything ``numpy.asarray`` reads.
ArrayInput = Union["da.Array", npt.ArrayLike]
#: A scalar (the same for every pair), or one value per pair (shape ``(N,)``).
PerPairInput = Union[float, "da.Array", npt.ArrayLike]

_ROWS = ("pos_a", "vel_a", "pos_b", "vel_b")
#: An argument left out (``None`` is a value, which the core names as a bad one).
_UNSET: Any = object()
_NAMES = (
    "pos_a",
    "vel_a",
    "friction_a",
    "pos_b",
    "vel_b",
    "friction_b",
    "contact_distance",
    "t_max",
)


def _input_error(
    argument: str,
    index: int | None,
    reason: str,
    kind: str = "shape",
    value: float | None = None,
) -> InputError:
    """An :class:`ballcollide.InputError` worded as the core words its own (``kind``: the
    core's names, docs/contract.md section 6)."""
    where = argument if index is None else f"{argument}[{index}]"
    error = InputError(f"{where}: {reason}")
    error.argument, error.index, error.reason = argument, index, reason
    error.segment, error.kind, error.value = None, kind, value
    return error


def _shaped(name: str, x: Any) -> Any:
    """``x`` (a Dask array, or anything the core reads) with its shape checked.

    Only the shape is looked at here, since a Dask array's values are not known yet; its
    dtype, and the values of everything that is not a Dask array, are the core's to check
    (:func:`collision_times` runs it on stand-ins).
    """
    a: da.Array | np.ndarray
    if isinstance(x, da.Array):
        a = x
    else:
        try:
            a = np.asarray(x)
        except (ValueError, TypeError) as e:  # ragged nested lists, unconvertible objects
            reason = f"cannot be read as an array of numbers ({e})"
            raise _input_error(name, None, reason, "not_numbers") from None
    if name in _ROWS:
        if a.ndim != 2 or a.shape[1] != 2:
            raise _input_error(name, None, f"expected shape (N, 2), got {a.shape}")
    elif a.ndim > 1:
        raise _input_error(name, None, f"expected a scalar or shape (N,), got shape {a.shape}")
    if a.ndim > 0 and math.isnan(a.shape[0]):
        raise _input_error(
            name,
            None,
            f"its chunk sizes are unknown (shape {a.shape}); "
            f"call {name}.compute_chunk_sizes() first",
        )
    return a if isinstance(a, da.Array) else x


def _stand_in(x: Any) -> Any:
    """What the core checks now in place of ``x``: an empty array of a Dask array's dtype (its
    values are checked chunk by chunk when computed), and everything else itself, emptied."""
    if isinstance(x, da.Array):
        return np.empty((0, *x.shape[1:]), dtype=x.dtype) if x.ndim else np.ones((), x.dtype)
    a = np.asarray(x)
    return a[:0] if a.ndim else x


def _pair_chunks(arrays: Sequence[Any], n: int) -> tuple[int, ...]:
    """The pair-axis chunks: the first Dask argument's, or Dask's "auto" for numpy only."""
    for a in arrays:
        if isinstance(a, da.Array) and a.ndim > 0:
            chunks: tuple[int, ...] = a.chunks[0]
            return chunks
    # Dask is typed but not these functions: each untyped call below is marked as such.
    auto = da.core.normalize_chunks(  # type: ignore[no-untyped-call]
        ("auto", -1), shape=(n, 2), dtype=np.float64
    )
    return tuple(auto[0])


def _block(
    pos_a: np.ndarray,
    vel_a: np.ndarray,
    friction_a: Any,
    pos_b: np.ndarray,
    vel_b: np.ndarray,
    friction_b: Any,
    contact_distance: Any,
    t_max: Any,
    *,
    num_threads: int | None,
    block_info: dict[Any, Any] | None = None,
) -> npt.NDArray[np.float64]:
    """One chunk of pairs: one call of the kernel; errors name the global index."""
    # Per-pair arrays arrive as (n, 1) blocks (see collision_times), scalars as they were
    # given or as 0-d arrays.
    fa, fb, r, tm = (_flat(x) for x in (friction_a, friction_b, contact_distance, t_max))
    try:
        return _collision_times(
            pos_a, vel_a, fa, pos_b, vel_b, fb, r, t_max=tm, num_threads=num_threads
        )
    except InputError as e:
        if e.index is None:  # a scalar's error: no pair of its own
            raise
        # Where this chunk starts in the whole result (map_blocks tells it).
        start = 0 if block_info is None else int(block_info[None]["array-location"][0][0])
        raise _input_error(e.argument, start + e.index, e.reason, e.kind, e.value) from None


def _flat(x: Any) -> Any:
    return np.reshape(x, -1) if np.ndim(x) == 2 else x


def collision_times(
    pos_a: ArrayInput,
    vel_a: ArrayInput,
    friction_a: PerPairInput,
    pos_b: ArrayInput,
    vel_b: ArrayInput,
    friction_b: PerPairInput,
    contact_distance: Any = _UNSET,
    *,
    t_max: PerPairInput = np.inf,
    num_threads: int | None = 1,
    radius: Any = _UNSET,
) -> da.Array:
    """The collision times of N pairs held in Dask arrays, as a lazy Dask array.

    The arguments and the result are those of :func:`ballcollide.collision_times`, with
    Dask arrays allowed wherever arrays are: pair ``i`` is ball A (``pos_a[i]``,
    ``vel_a[i]``, ``friction_a``) against ball B (``pos_b[i]``, ``vel_b[i]``,
    ``friction_b``) at contact distance ``contact_distance``, and its time is ``inf`` if they never
    touch (or not before ``t_max``). Nothing is computed until the result is (``.compute()``,
    ``.sum()``, ``.to_zarr()`` …); each chunk of pairs is then one call of
    :func:`ballcollide.collision_times`, so the times are bit for bit those of one in-memory
    call, whatever the chunks and the scheduler.

    Parameters
    ----------
    pos_a, vel_a, pos_b, vel_b
        Shape ``(N, 2)``: Dask arrays, numpy arrays or array-likes of real numbers.
    friction_a, friction_b, contact_distance, t_max
        Scalars (one value for all pairs; a 0-d Dask array too) or shape ``(N,)``.
        ``radius=`` is ``contact_distance``'s former name, deprecated (as in
        :func:`ballcollide.collision_times`).
    num_threads
        Threads of the kernel for each chunk: ``1`` (default) — Dask already runs one chunk
        per worker thread, so more would oversubscribe the cores; ``None`` for all cores
        (rayon's pool, sized by ``RAYON_NUM_THREADS`` if set), e.g. with one worker thread
        per process; or an int ``n ≥ 1``. The times do not depend on it.

    Returns
    -------
    dask.array.Array
        Shape ``(N,)``, float64, lazy; chunked along the pairs like the arguments.

    Raises
    ------
    ballcollide.InputError, TypeError
        At once, for what can be seen without computing: a wrong shape, a length that
        differs from ``pos_a``'s, a non-real dtype (``TypeError``), unknown chunk sizes, a
        bad scalar (``contact_distance ≤ 0`` …) or ``num_threads``. Bad values inside arrays (NaN or
        infinite numbers, a negative friction, ``contact_distance ≤ 0``, a negative ``t_max``)
        raise
        :class:`ballcollide.InputError` (a ``ValueError``) when the result is computed,
        naming the argument and, as ``.index``, the index of the bad pair in the whole array
        (the first one of its chunk; if several chunks have bad pairs, whichever fails first
        is reported).

    Notes
    -----
    The pairs are chunked like the first Dask argument with at least one dimension, in
    argument order; other Dask arguments are rechunked to match, and numpy arguments are
    split the same way (they are embedded in the task graph: keep big inputs in Dask). With
    numpy arguments only, Dask's ``"auto"`` chunks are used. The two columns of an
    ``(N, 2)`` argument are always put in one chunk. Chunks may be of any size, even empty.

    Examples
    --------
    >>> import dask.array as da
    >>> import numpy as np
    >>> import ballcollide.dask as bcd
    >>> # 10 pairs in chunks of 4: ball A shot at 1 m/s at a resting ball B at x = 2.5 … 11.5,
    >>> # slowed at 1/16 m/s² (per pair here) so that it stops at x = 8.
    >>> n = 10
    >>> pos_a = da.zeros((n, 2), chunks=(4, 2))
    >>> vel_a = da.broadcast_to(da.from_array([1.0, 0.0]), (n, 2)).rechunk((4, 2))
    >>> pos_b = np.column_stack([np.arange(2.5, 2.5 + n), np.zeros(n)])
    >>> friction = da.full(n, 1 / 16, chunks=4)
    >>> t = bcd.collision_times(pos_a, vel_a, friction, pos_b, np.zeros((n, 2)), 0.0, 1.0)
    >>> t.chunks
    ((4, 4, 2),)
    >>> np.isfinite(t).sum().compute()  # contact at x_B − 1 < 8: balls B at x ≤ 8.5 are hit
    np.int64(7)
    >>> # A bad value in a later chunk: the error names the pair's index in the whole array.
    >>> bad = friction.copy()
    >>> bad[6] = -1.0
    >>> bcd.collision_times(pos_a, vel_a, bad, pos_b, np.zeros((n, 2)), 0.0, 1.0).compute()
    Traceback (most recent call last):
    ...
    ballcollide.InputError: friction_a[6]: friction must be ≥ 0, got -1
    """
    contact_distance = _contact_distance(contact_distance, radius)
    given = (pos_a, vel_a, friction_a, pos_b, vel_b, friction_b, contact_distance, t_max)
    args = [_shaped(name, x) for name, x in zip(_NAMES, given)]
    n = np.shape(args[0])[0]
    for name, a in zip(_NAMES, args):
        if np.ndim(a) > 0 and np.shape(a)[0] != n:
            rows = np.shape(a)[0]
            reason = f"has {rows} rows, expected {n}"
            raise _input_error(name, None, reason, "length_mismatch", rows)
    # The core checks the rest at once, on an empty batch of the same dtypes and scalars:
    # dtypes, lists it cannot read, bad scalars (as it words them, without an index), and
    # num_threads.
    standing = [_stand_in(a) for a in args]
    _check_now(*standing[:7], t_max=standing[7], num_threads=num_threads)
    args = [a if isinstance(a, da.Array) or np.ndim(a) == 0 else np.asarray(a) for a in args]

    chunks = _pair_chunks(args, n)
    blocks: list[Any] = []
    for name, a in zip(_NAMES, args):
        if np.ndim(a) == 0:  # a number, or a 0-d array (Dask: one value for every chunk)
            blocks.append(a)
        elif name in _ROWS:
            blocks.append(_rechunked(a, (chunks, (2,))))
        else:  # (N,) as (N, 1), so that map_blocks lines its pairs up with the rows'
            blocks.append(_rechunked(a[:, np.newaxis], (chunks, (1,))))

    out: da.Array = da.map_blocks(  # type: ignore[no-untyped-call]
        _block,
        *blocks,
        num_threads=num_threads,
        drop_axis=1,
        dtype=np.float64,
        meta=np.empty((0,), dtype=np.float64),
        token="collision_times",
    )
    return out


def _contact_distance(contact_distance: Any, radius: Any) -> Any:
    """``contact_distance``, or the same value under its deprecated name ``radius=``, read as
    :func:`ballcollide.collision_times` reads them (with its warning and its errors)."""
    if radius is _UNSET:
        if contact_distance is _UNSET:
            raise TypeError(
                "contact_distance: missing (the distance between the centres at contact)"
            )
        return contact_distance
    if contact_distance is not _UNSET:
        raise TypeError("contact_distance: given twice (radius= is its deprecated name)")
    warnings.warn(
        "radius= is deprecated in the pair calls, where it is the contact distance "
        "(the sum of the two radii): pass contact_distance= instead",
        DeprecationWarning,
        stacklevel=3,
    )
    return radius


def _rechunked(a: da.Array | np.ndarray, chunks: tuple[tuple[int, ...], ...]) -> da.Array:
    if isinstance(a, da.Array):
        if a.chunks == chunks:
            return a
        rechunked: da.Array = a.rechunk(chunks)  # type: ignore[no-untyped-call]
        return rechunked
    whole: da.Array = da.from_array(a, chunks=chunks)  # type: ignore[no-untyped-call]
    return whole


def simulate_many(
    shots: Sequence[Any],
    *,
    chunk_size: int = 16,
    contact_rule: str = "pooltool",
    history: bool = False,
    num_threads: int | None = 1,
) -> Any:
    """pooltool shots played as :func:`ballcollide.pooltool.simulate_many` plays them, in
    chunks of ``chunk_size`` shots spread over Dask's workers (the active scheduler: a
    ``distributed.Client``'s cluster if one is set up), gathered into one
    :class:`~ballcollide.pooltool.ShotResults`.

    Each chunk is one ``simulate_many`` call on ``num_threads`` threads (default 1: a worker
    with ``k`` threads keeps ``k`` cores busy), so every shot's events are bit for bit those of
    an in-memory call, on any cluster and chunking. The shots are pickled to the workers, which
    need pooltool 0.6.0. Errors are ``simulate_many``'s, naming the shot by its index in
    ``shots`` (``shots[37].position``).

    >>> import pooltool as pt
    >>> import ballcollide.dask as bcd
    >>> results = bcd.simulate_many([pt.System.example()] * 5, chunk_size=2)
    >>> len(results), results.type_names[results.type[0]]
    (5, 'stick_ball')
    """
    import dask

    from . import pooltool as bcp

    if isinstance(chunk_size, bool) or not isinstance(chunk_size, int) or chunk_size < 1:
        reason = f"must be an int ≥ 1, got {chunk_size!r}"
        raise _input_error("chunk_size", None, reason, "out_of_range")
    shots = list(shots)
    # What is not supported fails now, not on a worker.
    bcp._check_supported(None, False, None, None, None, 0, contact_rule)
    parts = [
        dask.delayed(_shot_block, pure=False)(  # type: ignore[attr-defined]
            shots[start : start + chunk_size], start, contact_rule, history, num_threads
        )
        for start in range(0, len(shots), chunk_size)
    ]
    if not parts:
        return bcp.simulate_many(shots, num_threads, contact_rule=contact_rule, history=history)
    blocks = dask.compute(*parts)  # type: ignore[attr-defined,no-untyped-call]
    return bcp.ShotResults(shots, bcp._joined(blocks), contact_rule)


def _shot_block(
    shots: list[Any], start: int, contact_rule: str, history: bool, num_threads: int | None
) -> dict[str, Any]:
    """One chunk of shots, from ``shots[start]`` on: ``_core.simulate_shots``' arrays; errors
    name the shot's index in the whole sequence."""
    from . import _core
    from . import pooltool as bcp

    try:
        return _core.simulate_shots(
            **bcp._inputs(shots),
            contact_rule=contact_rule,
            history=history,
            num_threads=num_threads,
        )
    except InputError as e:
        local = _SHOT.match(e.argument or "")
        if local is None:
            raise
        argument = _renumbered(local, start) + e.argument[local.end() :]
        error = InputError(argument + str(e)[len(e.argument) :])
        error.argument, error.index, error.segment = argument, e.index, e.segment
        error.reason, error.kind, error.value = e.reason, e.kind, e.value
        raise error from None
    except ValueError as e:  # a cue whose ball is not among its shot's: "shots[k]: ..."
        local = _SHOT.match(str(e))
        if local is None:
            raise
        raise ValueError(_renumbered(local, start) + str(e)[local.end() :]) from None


#: A shot named by its index in a chunk: ``shots[3]``.
_SHOT = re.compile(r"shots\[(\d+)\]")


def _renumbered(local: re.Match[str], start: int) -> str:
    """``shots[k]`` of a chunk starting at ``start`` as ``shots[start + k]``."""
    return f"shots[{start + int(local.group(1))}]"
