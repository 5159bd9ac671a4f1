"""Every array layout and real dtype gives the bits of the C-ordered float64 call, at every
batch entry point that takes arrays; a NaN is named at its own index whatever the layout.

Each case gives every array argument of one call in one layout at once: C or Fortran order, a
column of a wider array, every other row, negative strides on every axis, unaligned memory,
float32, ints, big-endian or float16 (converted by numpy), nested lists. The reference is the
same call on ``np.array(x, dtype=np.float64, order="C")`` of each argument: the values the
layout holds, read as numpy reads them; where it raises, the layout must raise the same.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

import ballcollide as bc

Arrays = dict[str, np.ndarray]


def spread_last(x: np.ndarray) -> np.ndarray:
    """``x`` as a view into a wider array: its last axis a slice (a column of a 1-D one)."""
    if x.ndim == 0:
        return x
    if x.ndim == 1:
        wide = np.zeros((len(x), 3), x.dtype)
        wide[:, 1] = x
        return wide[:, 1]
    wide = np.zeros((*x.shape[:-1], x.shape[-1] + 3), x.dtype)
    wide[..., 1 : 1 + x.shape[-1]] = x
    return wide[..., 1 : 1 + x.shape[-1]]


def every_other(x: np.ndarray) -> np.ndarray:
    if x.ndim == 0:
        return x
    wide = np.zeros((2 * len(x), *x.shape[1:]), x.dtype)
    wide[::2] = x
    return wide[::2]


def flipped(x: np.ndarray) -> np.ndarray:
    """The same values with negative strides on every axis."""
    return np.flip(np.ascontiguousarray(np.flip(x)))


def unaligned(x: np.ndarray) -> np.ndarray:
    buf = np.zeros(x.nbytes + 1, np.uint8)
    y = buf[1:].view(np.float64).reshape(x.shape)
    y[...] = x
    return y


def read_only(x: np.ndarray) -> np.ndarray:
    y = np.asfortranarray(x)
    y.flags.writeable = False
    return y


LAYOUTS: dict[str, Callable[[np.ndarray], Any]] = {
    "C": np.ascontiguousarray,
    "F": np.asfortranarray,
    "column of wider": spread_last,
    "every other row": every_other,
    "negative strides": flipped,
    "unaligned": unaligned,
    "read-only F": read_only,
    "float32": lambda x: x.astype(np.float32),
    "float32 F": lambda x: np.asfortranarray(x.astype(np.float32)),
    "int64": lambda x: x.astype(np.int64),
    "int32 strided": lambda x: every_other(x.astype(np.int32)),
    "uint8 F": lambda x: np.asfortranarray(np.abs(x).astype(np.uint8)),
    "int16 negative strides": lambda x: flipped(x.astype(np.int16)),
    "big-endian F": lambda x: np.asfortranarray(x.astype(">f8")),
    "float16 strided": lambda x: every_other(x.astype(np.float16)),
    "lists": lambda x: x.tolist(),
}


def reference(x: Any) -> np.ndarray:
    return np.array(x, dtype=np.float64, order="C")


def laid_out(layout: str, inputs: Arrays) -> dict[str, Any]:
    """Every array of ``inputs`` in ``layout`` (numbers stay numbers)."""
    return {k: LAYOUTS[layout](v) if np.ndim(v) else v for k, v in inputs.items()}


# --- inputs of each entry point (integer-valued halves: exact in every dtype tried) ---------


def pairs(n: int, rng: np.random.Generator) -> Arrays:
    return {
        "pos_a": rng.integers(0, 40, (n, 2)) / 2,
        "vel_a": rng.integers(-6, 7, (n, 2)) / 2,
        "friction_a": rng.integers(0, 3, n) / 2,
        "pos_b": rng.integers(0, 40, (n, 2)) / 2,
        "vel_b": rng.integers(-6, 7, (n, 2)) / 2,
        "friction_b": rng.integers(0, 3, n) / 2,
        "contact_distance": rng.integers(1, 5, n) / 2,
        "t_max": rng.integers(1, 40, n) / 2,
    }


def paths(n: int, rng: np.random.Generator, prefix: str = "", first: float = 0.0) -> Arrays:
    start = np.cumsum(rng.integers(1, 4, (n, 3)), axis=1) / 2
    start[:, 0] = first
    return {
        f"start{prefix}": start,
        f"pos{prefix}": rng.integers(0, 40, (n, 3, 2)) / 2,
        f"vel{prefix}": rng.integers(-6, 7, (n, 3, 2)) / 2,
        f"acc{prefix}": rng.integers(-2, 3, (n, 3, 2)) / 2,
    }


def balls(n: int, rng: np.random.Generator) -> Arrays:
    """``n`` balls on a grid of spacing 4, radius ≤ 1 (apart), in the box (0, 0)–(40, 40)."""
    cells = rng.permutation(100)[:n]
    pos = np.stack([cells % 10, cells // 10], axis=1) * 4.0 + 2
    return {
        "pos": pos,
        "vel": rng.integers(-6, 7, (n, 2)) / 2,
        "friction": rng.integers(0, 3, n) / 2,
        "radius": rng.integers(1, 3, n) / 2,
    }


def schedule_result(s: bc.CollisionSchedule) -> list[Any]:
    return [len(s), s.time, s.next_collision()] + [s.next_event() for _ in range(5)]


BOX = ([0.0, 0.0], [40.0, 40.0])

# name → (inputs for n, call on them)
ENTRY_POINTS: dict[str, tuple[Callable[[int, np.random.Generator], Arrays], Callable[..., Any]]]
ENTRY_POINTS = {
    "collision_times": (pairs, lambda **a: bc.collision_times(**a, num_threads=1)),
    "collision_times, 2 threads": (pairs, lambda **a: bc.collision_times(**a, num_threads=2)),
    "positions_at": (
        lambda n, rng: {**balls(n, rng), "t": rng.integers(0, 9, n) / 2},
        lambda radius, **a: bc.positions_at(**a),
    ),
    "path_collision_times": (
        lambda n, rng: {
            **paths(n, rng, "_a"),
            **paths(n, rng, "_b"),
            "contact_distance": rng.integers(1, 5, n) / 2,
            "t_max": rng.integers(1, 40, n) / 2,
        },
        bc.path_collision_times,
    ),
    "path_positions_at": (
        lambda n, rng: {**paths(n, rng), "t": rng.integers(0, 12, n) / 2},
        bc.path_positions_at,
    ),
    "real_roots": (
        lambda n, rng: {"coeffs": rng.integers(-8, 9, (n, 5)) / 2},
        bc.real_roots,
    ),
    "pairwise_collision_times": (balls, bc.pairwise_collision_times),
    "earliest_collision": (balls, bc.earliest_collision),
    "first_contacts": (balls, bc.first_contacts),
    "CollisionSchedule": (
        lambda n, rng: {**paths(n, rng), "radius": np.full(n, 0.5)},
        lambda **a: schedule_result(bc.CollisionSchedule(**a, box=BOX)),
    ),
    "CollisionSchedule.from_balls": (
        balls,
        lambda **a: schedule_result(bc.CollisionSchedule.from_balls(**a, box=BOX)),
    ),
    "CollisionSchedule.update": (
        lambda n, rng: paths(n, rng, first=1.0),
        lambda **a: updated(lambda s, n: s.update(np.arange(n), **a), len(a["start"])),
    ),
    "CollisionSchedule.update_balls": (
        lambda n, rng: {k: v for k, v in balls(n, rng).items() if k != "radius"},
        lambda **a: updated(lambda s, n: s.update_balls(np.arange(n), 1.0, **a), len(a["pos"])),
    ),
    "simulate": (
        lambda n, rng: {**balls(n, rng), "mass": rng.integers(1, 4, n) / 2},
        lambda **a: bc.simulate(**a, box=BOX, max_events=50),
    ),
    "collision_time": (
        lambda n, rng: {k: v[0] for k, v in pairs(max(n, 1), rng).items()},
        bc.collision_time,
    ),
    "path_collision_time": (
        lambda n, rng: {k: v[0] for k, v in {**paths(1, rng, "_a"), **paths(1, rng, "_b")}.items()},
        lambda **a: bc.path_collision_time(
            tuple(a[f"{k}_a"] for k in ("start", "pos", "vel", "acc")),
            tuple(a[f"{k}_b"] for k in ("start", "pos", "vel", "acc")),
            1.0,
        ),
    ),
}


def updated(change: Callable[[bc.CollisionSchedule, int], None], n: int) -> list[Any]:
    """A calendar of ``n`` balls at rest on a grid, changed, and its next events."""
    pos = np.stack([np.arange(n) % 10, np.arange(n) // 10], axis=1) * 4.0 + 2
    s = bc.CollisionSchedule.from_balls(pos, np.zeros((n, 2)), 0.0, 0.5, box=BOX)
    change(s, n)
    return schedule_result(s)


def bits(result: Any) -> Any:
    """``result`` with every float as its bits, every array as its dtype, shape and bytes."""
    if isinstance(result, np.ndarray):
        return (result.dtype.str, result.shape, np.ascontiguousarray(result).tobytes())
    if isinstance(result, (tuple, list)):
        return tuple(bits(r) for r in result)
    if isinstance(result, float):
        return np.float64(result).tobytes()
    return result


def outcome(call: Callable[..., Any], args: dict[str, Any]) -> Any:
    try:
        return ("ok", bits(call(**args)))
    except (ValueError, TypeError) as e:
        return ("raised", type(e).__name__, str(e))


@pytest.mark.parametrize("n", [0, 1, 13])
@pytest.mark.parametrize("layout", list(LAYOUTS))
@pytest.mark.parametrize("entry", list(ENTRY_POINTS))
def test_every_layout_gives_the_bits_of_c_order(entry: str, layout: str, n: int) -> None:
    make, call = ENTRY_POINTS[entry]
    inputs = make(n, np.random.default_rng(n))
    given = laid_out(layout, inputs)
    expected = outcome(call, {k: reference(v) for k, v in given.items()})
    assert outcome(call, given) == expected
    if n == 13 and layout in ("C", "F", "column of wider", "negative strides"):
        assert expected[0] == "ok"  # the cases are answers, not only errors


# --- a NaN at its own index --------------------------------------------------------------


NAN_LAYOUTS = ["F", "column of wider", "every other row", "negative strides", "float32 F"]


@pytest.mark.parametrize("layout", NAN_LAYOUTS)
@pytest.mark.parametrize("name", ["pos_a", "vel_a", "friction_a", "vel_b", "contact_distance"])
@pytest.mark.parametrize("row", [0, 6, 12])
def test_a_nan_is_named_at_its_index_in_any_layout(layout: str, name: str, row: int) -> None:
    inputs = pairs(13, np.random.default_rng(2))
    x = inputs[name].copy()
    if x.ndim == 1:
        x[row] = np.nan
    else:
        x[row, -1] = np.nan
    inputs[name] = x
    given = laid_out(layout, inputs)
    with pytest.raises(bc.InputError) as e:
        bc.collision_times(**given)
    assert (e.value.argument, e.value.index) == (name, row)


@pytest.mark.parametrize("layout", NAN_LAYOUTS)
@pytest.mark.parametrize("name", ["start_b", "vel_a", "acc_b"])
def test_a_nan_in_a_path_is_named_at_its_path_and_segment(layout: str, name: str) -> None:
    rng = np.random.default_rng(3)
    inputs = {**paths(9, rng, "_a"), **paths(9, rng, "_b"), "contact_distance": np.full(9, 0.5)}
    x = inputs[name].copy()
    x[5, 2, ...] = np.nan
    inputs[name] = x
    given = laid_out(layout, inputs)
    with pytest.raises(bc.InputError) as e:
        bc.path_collision_times(**given)
    expected = outcome(bc.path_collision_times, {k: reference(v) for k, v in given.items()})
    assert expected[0] == "raised" and str(e.value) == expected[2]
    assert (e.value.argument, e.value.index, e.value.segment) == (name, 5, 2)


def test_layouts_of_batches_large_enough_to_release_the_gil() -> None:
    inputs = pairs(5000, np.random.default_rng(4))
    c = bits(bc.collision_times(**inputs))
    for layout in LAYOUTS:
        given = laid_out(layout, inputs)
        call = bc.collision_times
        assert outcome(call, given) == outcome(call, {k: reference(v) for k, v in given.items()})
        if layout in ("F", "column of wider", "every other row", "negative strides", "unaligned"):
            assert bits(call(**given, num_threads=2)) == c


# Nested lists and tuples of Python numbers are read directly (not through numpy): the same
# values and errors as numpy's reading of them, but for a bool among them, which numpy reads
# as a number and the call refuses (a TypeError, as for a bool given alone).
LISTS = [
    [[1, 2.5], [3, 4]],
    [(1.0, 2.0), (3.0, -0.0)],
    ((1.5, 2), (3, 4)),
    [[2**53 + 1, 0], [2**62 + 12345, -(2**63)], [2**63 - 1, 1]],
    [[1.0, True], [3.0, 4.0]],
    [[1.0, np.float64(2.0)], [3.0, 4.0]],
    [[1.0, np.int32(2)], [3.0, 4.0]],
    [[2**64, 1.0], [3.0, 4.0]],
    [[1.0, 2.0], [3.0]],
    [[1.0, 2.0], 3.0],
    [[1.0, 2.0], [3.0, "4"]],
    [[1.0, 2.0], [3.0, None]],
    [[[1.0, 2.0]], [[3.0, 4.0]]],
    [],
    [[]],
]


@pytest.mark.parametrize("rows", LISTS, ids=range(len(LISTS)))
def test_nested_lists_read_as_numpy_reads_them(rows: Any) -> None:
    def call(pos: Any) -> Any:
        return bc.positions_at(pos, [[1.0, 0.5]] * max(1, len(rows)), 0.0, 0.0)

    def seen(pos: Any) -> Any:
        try:
            return ("ok", bits(call(pos)))
        except (ValueError, TypeError) as e:
            return ("raised", type(e).__name__, str(e))

    try:
        as_numpy = np.asarray(rows)
    except ValueError:
        as_numpy = None  # ragged: numpy refuses it, and so must the call
    got = seen(rows)
    if any(isinstance(x, bool) for row in rows if isinstance(row, list | tuple) for x in row):
        assert got == ("raised", "TypeError", "pos: expected real numbers, got bool")
    elif as_numpy is None or as_numpy.dtype.kind not in "fiu":
        assert got[0] == "raised"
    else:
        assert got == seen(as_numpy.astype(np.float64))
