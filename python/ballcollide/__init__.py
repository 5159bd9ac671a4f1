"""ballcollide: when do two balls slowing under friction first touch?

Each ball moves on a straight line from its position ``p`` with velocity ``v``, slowed by a
constant friction deceleration ``μ ≥ 0`` (length / time²) until it stops at ``τ = |v|/μ``, and
stays there. Two balls collide when their centres come within ``contact_distance`` (the sum
of their radii; ``radius`` always means one ball's own): the collision time is the first
``t ≥ 0`` at which they start to interpenetrate (``0`` if they already touch and are
approaching), ``inf`` if they never do (or not before ``t_max``). The times are as accurate
as float64 inputs allow. The contract is ``docs/contract.md`` in the repository.

Functions (all take array-likes: lists, any real dtype, C or Fortran order, strided views;
and any real number ``float()`` accepts, but not a bool, where a number goes):

- :func:`collision_time`: one pair;
- :func:`collision_times`: N pairs at once, on all cores, with the GIL released;
- :func:`positions_at`: where N balls are at a time ``t`` (a stopped ball stays put);
- :func:`path_collision_times`, :func:`path_collision_time`, :func:`path_positions_at`: balls
  on paths of constant-acceleration segments in 2-D or 3-D (a billiard ball sliding on a
  curve, then rolling, then at rest; a ball in the air), the same questions;
- :func:`path_geometry_times`: balls on paths against a table's static objects (cushions and
  jaws as segments, jaw tips as circles, pockets as targets, the bed as a plane), their kinds
  :data:`SEGMENT`, :data:`CIRCLE`, :data:`TARGET`, :data:`PLANE`;
- :func:`real_roots`: real roots of N polynomials of degree 1 to 4, like ``numpy.roots``;
- :func:`pairwise_collision_times`, :func:`earliest_collision`, :func:`first_contacts`: a
  scene of N balls (which pairs touch, which touch first), with a broad phase that prunes
  the pairs that cannot meet;
- :class:`CollisionSchedule`: an event calendar, the next collision (and wall contact) among N
  balls on paths, kept up to date as an event-driven simulation changes a few paths at a time;
- :func:`simulate`: an event-driven simulation of friction balls in a box, run natively on it;
- :func:`pool_table`: a pool table's cushions, jaws and pockets as the objects above;
- :func:`simulate_shots`: billiard shots with pooltool's physics, many at once (see
  :mod:`ballcollide.pooltool` for pooltool's own objects);
- :func:`simd_level`: the SIMD level the batches run at.

The exported names are ``ballcollide.__all__``.

Bad input (NaN or infinity, negative friction, ``contact_distance ≤ 0``, wrong shapes or
lengths) raises :class:`InputError`, a ``ValueError`` naming the argument and, for batches,
the first bad index (``.argument``, ``.index``, ``.reason``, ``.segment`` for a path's
segment, ``.kind``, a stable code to branch on, and ``.value``, the offending number); an
argument that is not made of real numbers raises ``TypeError``.

The functions are those of the compiled ``_core`` module, re-exported: it reads and checks
every argument itself. Their docstrings are the Rust doc comments of the bindings
(``src/python/``).

>>> import ballcollide as bc
>>> # A ball shot at 1 m/s (no friction) at a resting ball 1 m away; contact at 0.5 m.
>>> bc.collision_time([0, 0], [1, 0], 0.0, [1, 0], [0, 0], 0.0, 0.5)
0.5
"""

from __future__ import annotations

# The exports are listed once, where the compiled module is built (src/python/mod.rs: what it
# adds goes into `_core.__all__`); its stub, `_core.pyi`, lists them for type checkers, and
# stubtest checks that both agree.
from . import _core
from ._core import *  # noqa: F403

__all__ = list(_core.__all__)
