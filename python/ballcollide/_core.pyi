# Types only. The docstrings of these functions and of InputError are the Rust doc comments
# in src/python/mod.rs and src/python/*.rs (what `help()` shows): the one place the
# Python API is documented.

from collections.abc import Callable, Sequence
from typing import Any, Final, NamedTuple, Protocol, SupportsFloat, SupportsIndex, final

import numpy as np
import numpy.typing as npt

# A number: anything `float()` accepts (not a bool, which is refused at run time).
_Number = SupportsFloat | SupportsIndex
# One number for every pair (ball), or one per pair: shape (N,).
_PerPair = _Number | npt.ArrayLike
_F64Array = npt.NDArray[np.float64]
# One path: (start (K,), pos (K, D), vel (K, D), acc (K, D)).
_Path = tuple[npt.ArrayLike, npt.ArrayLike, npt.ArrayLike, npt.ArrayLike] | list[npt.ArrayLike]
_I64Array = npt.NDArray[np.int64]
_I8Array = npt.NDArray[np.int8]
# Static objects (path_geometry_times): an array each, None or [] for none; segment_sides
# None (both sides), one int for all, or M ints in {-1, 0, 1}.
_Objects = npt.ArrayLike | None
_Sides = SupportsIndex | Sequence[SupportsIndex] | npt.NDArray[np.integer[Any]] | None

__all__ = [
    "BALL",
    "CIRCLE",
    "PLANE",
    "SEGMENT",
    "TARGET",
    "TRANSITION",
    "WALL",
    "CollisionSchedule",
    "Event",
    "InputError",
    "Simulation",
    "__version__",
    "collision_time",
    "collision_times",
    "earliest_collision",
    "first_contacts",
    "pairwise_collision_times",
    "path_collision_time",
    "path_collision_times",
    "path_geometry_times",
    "path_positions_at",
    "pool_table",
    "positions_at",
    "real_roots",
    "simd_level",
    "simulate",
    "simulate_shots",
]

__version__: Final[str]

# The kinds of static object (path_geometry_times' `kind`, geometry::ObjectKind::code()), and
# of the calendar's other events (Event.kind).
SEGMENT: Final = 0
CIRCLE: Final = 1
TARGET: Final = 2
PLANE: Final = 3
BALL: Final = 4
WALL: Final = 5
TRANSITION: Final = 6

class InputError(ValueError):
    argument: str
    index: int | None
    segment: int | None
    reason: str
    kind: str
    value: float | None

def collision_time(
    pos_a: npt.ArrayLike,
    vel_a: npt.ArrayLike,
    friction_a: _Number,
    pos_b: npt.ArrayLike,
    vel_b: npt.ArrayLike,
    friction_b: _Number,
    contact_distance: _Number,
    *,
    t_max: _Number = ...,
) -> float: ...

# progress=: a tqdm-like bar (set_postfix is used if it has one), or a callable shown the
# number of new items done.
class _ProgressBar(Protocol):
    def update(self, n: int = ..., /) -> Any: ...
    def close(self) -> Any: ...

_Progress = bool | _ProgressBar | Callable[[int], object] | None

def collision_times(
    pos_a: npt.ArrayLike,
    vel_a: npt.ArrayLike,
    friction_a: _PerPair,
    pos_b: npt.ArrayLike,
    vel_b: npt.ArrayLike,
    friction_b: _PerPair,
    contact_distance: _PerPair,
    *,
    t_max: _PerPair = ...,
    num_threads: SupportsIndex | None = None,
    out: _F64Array | None = None,
    progress: _Progress = None,
) -> _F64Array: ...
def _last_kernel_seconds() -> float: ...
def positions_at(
    pos: npt.ArrayLike,
    vel: npt.ArrayLike,
    friction: _PerPair,
    t: _PerPair,
    *,
    num_threads: SupportsIndex | None = None,
    out: _F64Array | None = None,
) -> _F64Array: ...
def path_collision_times(
    start_a: npt.ArrayLike,
    pos_a: npt.ArrayLike,
    vel_a: npt.ArrayLike,
    acc_a: npt.ArrayLike,
    start_b: npt.ArrayLike,
    pos_b: npt.ArrayLike,
    vel_b: npt.ArrayLike,
    acc_b: npt.ArrayLike,
    contact_distance: _PerPair,
    *,
    t_max: _PerPair = ...,
    num_threads: SupportsIndex | None = None,
    out: _F64Array | None = None,
    progress: _Progress = None,
) -> _F64Array: ...
def path_collision_time(
    path_a: _Path,
    path_b: _Path,
    contact_distance: _Number,
    *,
    t_max: _Number = ...,
) -> float: ...
def path_positions_at(
    start: npt.ArrayLike,
    pos: npt.ArrayLike,
    vel: npt.ArrayLike,
    acc: npt.ArrayLike,
    t: _PerPair,
    *,
    num_threads: SupportsIndex | None = None,
    out: _F64Array | None = None,
) -> _F64Array: ...
def path_geometry_times(
    start: npt.ArrayLike,
    pos: npt.ArrayLike,
    vel: npt.ArrayLike,
    acc: npt.ArrayLike,
    radius: _PerPair,
    *,
    segments: _Objects = None,
    segment_sides: _Sides = None,
    circles: _Objects = None,
    targets: _Objects = None,
    planes: _Objects = None,
    t_max: _PerPair = ...,
    num_threads: SupportsIndex | None = None,
    out: tuple[_F64Array, _I8Array, _I64Array] | list[Any] | None = None,
    progress: _Progress = None,
) -> tuple[_F64Array, _I8Array, _I64Array]: ...
def real_roots(coeffs: npt.ArrayLike) -> _F64Array: ...
def simd_level() -> str: ...
def pairwise_collision_times(
    pos: npt.ArrayLike,
    vel: npt.ArrayLike,
    friction: _PerPair,
    radius: _PerPair,
    *,
    t_max: _Number = ...,
    num_threads: SupportsIndex | None = None,
) -> _F64Array: ...
def earliest_collision(
    pos: npt.ArrayLike,
    vel: npt.ArrayLike,
    friction: _PerPair,
    radius: _PerPair,
    *,
    t_max: _Number = ...,
    num_threads: SupportsIndex | None = None,
) -> tuple[float, int, int]: ...
def first_contacts(
    pos: npt.ArrayLike,
    vel: npt.ArrayLike,
    friction: _PerPair,
    radius: _PerPair,
    *,
    t_max: _Number = ...,
    num_threads: SupportsIndex | None = None,
) -> tuple[_F64Array, _I64Array]: ...

# A box of walls: (lo, hi), each D numbers.
_Box = tuple[npt.ArrayLike, npt.ArrayLike] | list[npt.ArrayLike]
_Indices = SupportsIndex | npt.ArrayLike

class Event(NamedTuple):
    time: float
    i: int
    j: int
    kind: int
    # The object's index, as the contract names it: it shadows `tuple.index` (the method stays
    # reachable as `tuple.index(event, value)`).
    index: int  # type: ignore[assignment]

class Simulation(NamedTuple):
    times: _F64Array
    i: _I64Array
    j: _I64Array
    pos: _F64Array
    vel: _F64Array
    kind: _I64Array
    # As Event.index: it shadows `tuple.index`.
    index: _I64Array  # type: ignore[assignment]
    captured: _I64Array

@final
class CollisionSchedule:
    def __new__(
        cls,
        start: npt.ArrayLike,
        pos: npt.ArrayLike,
        vel: npt.ArrayLike,
        acc: npt.ArrayLike,
        radius: _PerPair,
        *,
        box: _Box | None = None,
        t_max: _Number = ...,
        segments: _Objects = None,
        segment_sides: _Sides = None,
        circles: _Objects = None,
        targets: _Objects = None,
        planes: _Objects = None,
        transitions: bool | None = False,
        progress: _Progress = None,
    ) -> CollisionSchedule: ...
    @staticmethod
    def from_balls(
        pos: npt.ArrayLike,
        vel: npt.ArrayLike,
        friction: _PerPair,
        radius: _PerPair,
        t: _Number = ...,
        box: _Box | None = None,
        *,
        t_max: _Number = ...,
        segments: _Objects = None,
        segment_sides: _Sides = None,
        circles: _Objects = None,
        targets: _Objects = None,
        planes: _Objects = None,
        transitions: bool | None = False,
        progress: _Progress = None,
    ) -> CollisionSchedule: ...
    @property
    def time(self) -> float: ...
    def __len__(self) -> int: ...
    def next_collision(self) -> tuple[float, int, int]: ...
    def next_event(self) -> Event: ...
    def retire(self, i: SupportsIndex) -> None: ...
    def in_play(self, i: SupportsIndex) -> bool: ...
    def update(
        self,
        indices: _Indices,
        start: npt.ArrayLike,
        pos: npt.ArrayLike,
        vel: npt.ArrayLike,
        acc: npt.ArrayLike,
    ) -> None: ...
    def update_balls(
        self,
        indices: _Indices,
        t: _Number,
        pos: npt.ArrayLike,
        vel: npt.ArrayLike,
        friction: _PerPair,
    ) -> None: ...

def simulate(
    pos: npt.ArrayLike,
    vel: npt.ArrayLike,
    friction: _PerPair,
    radius: _PerPair,
    *,
    box: _Box,
    mass: _PerPair = ...,
    restitution: _Number = 1.0,
    t_end: _Number = ...,
    max_events: SupportsIndex | None = None,
    progress: _Progress = False,
    segments: _Objects = None,
    segment_sides: _Sides = None,
    circles: _Objects = None,
    targets: _Objects = None,
    planes: _Objects = None,
    table_restitution: _Number = 1.0,
) -> Simulation: ...
def simulate_shots(
    tables: Sequence[tuple[npt.ArrayLike, npt.ArrayLike, npt.ArrayLike]],
    shot_table: npt.ArrayLike,
    ball_start: npt.ArrayLike,
    rvw: npt.ArrayLike,
    s: npt.ArrayLike,
    params: npt.ArrayLike,
    strike: npt.ArrayLike,
    cue: npt.ArrayLike,
    *,
    contact_rule: str | None = None,
    max_events: SupportsIndex | None = None,
    history: bool | None = None,
    num_threads: SupportsIndex | None = None,
) -> dict[str, Any]: ...
def _pooltool_inputs(shots: Sequence[Any]) -> dict[str, Any]: ...

@final
class _PooltoolBuilder:
    def __new__(cls, types: dict[str, Any]) -> _PooltoolBuilder: ...
    def build(self, system: Any, results: dict[str, Any], k: int, new_balls: bool) -> None: ...

def pool_table(
    *,
    width: _Number = 1.27,
    length: _Number = 2.54,
    corner_mouth: _Number = 0.1168,
    side_mouth: _Number = 0.1295,
    jaw_length: _Number = 0.04,
    jaw_radius: _Number = 0.005,
    corner_jaw_angle: _Number = 7.0,
    side_jaw_angle: _Number = 14.0,
    pocket_radius: _Number = 0.045,
) -> dict[str, npt.NDArray[Any]]: ...
