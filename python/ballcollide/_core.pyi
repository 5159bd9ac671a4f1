"""ballcollide's compiled core (Rust, pyo3).

These functions take arrays exactly as the Rust core reads them — C-contiguous float64, of
the right shapes — and raise ``ValueError`` otherwise. Use the functions of the
``ballcollide`` package, which accept any array-like and convert it once.
"""

import numpy as np
import numpy.typing as npt

_F64Array1 = npt.NDArray[np.float64]
_F64Array2 = npt.NDArray[np.float64]
_PerPair = float | npt.NDArray[np.float64]
_I64Array1 = npt.NDArray[np.int64]

__all__ = [
    "__version__",
    "_last_kernel_seconds",
    "collision_time",
    "collision_times",
    "earliest_collision",
    "first_contacts",
    "pairwise_collision_times",
    "positions_at",
    "real_roots",
]

__version__: str

def collision_times(
    pos_a: _F64Array2,
    vel_a: _F64Array2,
    friction_a: _PerPair,
    pos_b: _F64Array2,
    vel_b: _F64Array2,
    friction_b: _PerPair,
    radius: _PerPair,
    t_max: _PerPair | None = None,
    num_threads: int | None = None,
    out: _F64Array1 | None = None,
) -> _F64Array1:
    """Collision times of N pairs, ``inf`` where none (see ``ballcollide.collision_times``).

    ``pos_*``, ``vel_*``: C-contiguous float64 arrays of shape ``(N, 2)``; ``friction_*``,
    ``radius``, ``t_max`` (``None``: ``inf``): a float or a contiguous float64 array of shape
    ``(N,)``. ``num_threads``: ``None`` for all cores, else ``≥ 1``. ``out``: ``None``, or a
    writeable C-contiguous float64 array of shape ``(N,)`` sharing no memory with the
    inputs, written and returned. Releases the GIL.

    Raises ``ValueError`` naming the argument and first bad index for invalid values,
    wrong shapes, lengths or layouts, and ``TypeError`` for other types or dtypes.
    """

def _last_kernel_seconds() -> float:
    """Seconds the Rust kernel took inside this thread's last :func:`collision_times` call
    (NaN before any). Private: for ``benchmarks/compare.py``'s overhead measurement."""

def collision_time(
    pos_a: tuple[float, float],
    vel_a: tuple[float, float],
    friction_a: float,
    pos_b: tuple[float, float],
    vel_b: tuple[float, float],
    friction_b: float,
    radius: float,
    t_max: float = ...,
) -> float:
    """The collision time of one pair, ``inf`` if none (see ``ballcollide.collision_time``).

    Identical to the corresponding row of :func:`collision_times`; errors name the argument
    without an index.
    """

def positions_at(
    pos: _F64Array2,
    vel: _F64Array2,
    friction: _PerPair,
    t: _PerPair,
    num_threads: int | None = None,
    out: _F64Array2 | None = None,
) -> _F64Array2:
    """Centres of N balls at time ``t``, shape ``(N, 2)`` (see ``ballcollide.positions_at``).

    A ball that has stopped stays where it stopped. ``out``: as in :func:`collision_times`,
    shape ``(N, 2)``. Releases the GIL.
    """

def real_roots(coeffs: _F64Array2) -> _F64Array2:
    """Real roots of N polynomials (see ``ballcollide.real_roots``).

    ``coeffs``: C-contiguous float64, shape ``(N, k+1)`` with ``k = 1..4``, highest degree
    first. Returns shape ``(N, k)``: real roots ascending with multiplicity, NaN-padded.
    A non-finite coefficient raises ``ValueError`` naming ``coeffs[i]``. Releases the GIL.
    """

def pairwise_collision_times(
    pos: _F64Array2,
    vel: _F64Array2,
    friction: _PerPair,
    radius: _PerPair,
    t_max: float = ...,
    num_threads: int | None = None,
) -> _F64Array2:
    """Collision times of every pair of N balls, shape ``(N, N)``, ``inf`` on the diagonal and
    for no contact (see ``ballcollide.pairwise_collision_times``).

    ``pos``, ``vel``: C-contiguous float64 ``(N, 2)``; ``friction``, ``radius`` (per ball): a
    float or a contiguous float64 ``(N,)``. Broad phase, then the exact pair kernel; releases
    the GIL. Errors name the argument and first bad index (``ValueError``).
    """

def earliest_collision(
    pos: _F64Array2,
    vel: _F64Array2,
    friction: _PerPair,
    radius: _PerPair,
    t_max: float = ...,
    num_threads: int | None = None,
) -> tuple[float, int, int]:
    """The first collision ``(t, i, j)``, ``i < j``, ties to the lowest ``i`` then ``j``;
    ``(inf, -1, -1)`` if none before ``t_max`` (see ``ballcollide.earliest_collision``).

    Arguments as in :func:`pairwise_collision_times`. Releases the GIL.
    """

def first_contacts(
    pos: _F64Array2,
    vel: _F64Array2,
    friction: _PerPair,
    radius: _PerPair,
    t_max: float = ...,
    num_threads: int | None = None,
) -> tuple[_F64Array1, _I64Array1]:
    """Each ball's first collision time (``inf`` if none) and partner (int64, ``-1`` if none),
    ties to the lowest partner (see ``ballcollide.first_contacts``).

    Arguments as in :func:`pairwise_collision_times`. Releases the GIL.
    """
