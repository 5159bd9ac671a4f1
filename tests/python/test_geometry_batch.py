"""``path_geometry_times``: N balls on paths against a table of static objects (segments,
circles, targets, planes), 2-D and 3-D.

- agreement: the batch equals, bit for bit, the same call on each path alone, and the earliest
  of the calls on each object alone (ties to the lowest kind, then index);
- properties (hypothesis): lengths scaled by a power of two change no bit (every kind), a
  translation by an exact shift none (segments and planes, as docs/contract.md promises),
  permuting the objects permutes the index, a far object changes nothing, a horizon only
  cuts; ``num_threads`` and ``out=`` give the same bits;
- bad input: every case names the argument and the index, with its kind;
- exact cases worked out by hand: a cushion, a jaw's tip, a pocket, the bed under a bouncing
  ball in 3-D.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
import pytest
from hypothesis import assume, event, given
from hypothesis import strategies as st

import ballcollide as bc

W, H, R = 2.54, 1.27, 0.028575  # a 9-ft table, a pool ball's radius
KINDS = (bc.SEGMENT, bc.CIRCLE, bc.TARGET, bc.PLANE)
NAMES = ("segments", "circles", "targets", "planes")


def bits(x: np.ndarray) -> np.ndarray:
    return np.ascontiguousarray(x, dtype=np.float64).view(np.uint64)


@dataclass(frozen=True)
class Table:
    """A table's objects as the call takes them (``None``: none of that kind)."""

    segments: np.ndarray | None = None
    segment_sides: np.ndarray | None = None
    circles: np.ndarray | None = None
    targets: np.ndarray | None = None
    planes: np.ndarray | None = None

    def kwargs(self) -> dict:
        return {k: v for k, v in vars(self).items() if v is not None}

    def count(self, name: str) -> int:
        v = getattr(self, name)
        return 0 if v is None else len(v)

    def only(self, name: str, m: int) -> Table:
        """The table of object ``m`` of kind ``name`` alone."""
        one = {name: getattr(self, name)[m : m + 1]}
        if name == "segments" and self.segment_sides is not None:
            one["segment_sides"] = self.segment_sides[m : m + 1]
        return Table(**one)


def pool_table(dim: int) -> Table:
    """A pool table: six cushions (touched from the table, on their left going round it
    counter-clockwise) with a jaw at each end (a segment at 45° into the pocket, touched from
    both sides) and a rounded tip at each end (a circle of 7 mm), six pockets (targets of
    6 cm) and, in 3-D, the bed (the plane z = 0). In 3-D the tips and pockets sit at the
    balls' height."""
    corner, middle, jaw = 0.1, 0.065, 0.05
    stretches = [
        ((corner, 0), (W / 2 - middle, 0)),
        ((W / 2 + middle, 0), (W - corner, 0)),
        ((W, corner), (W, H - corner)),
        ((W - corner, H), (W / 2 + middle, H)),
        ((W / 2 - middle, H), (corner, H)),
        ((0, H - corner), (0, corner)),
    ]
    segments, sides, tips = [], [], []
    for p, q in stretches:
        p, q = np.array(p, float), np.array(q, float)
        e = (q - p) / np.linalg.norm(q - p)
        outward = np.array([e[1], -e[0]])
        segments += [(p, q), (p + jaw * (outward - e) / math.sqrt(2), p)]
        segments.append((q, q + jaw * (outward + e) / math.sqrt(2)))
        sides += [1, 0, 0]
        tips += [p, q]
    pockets = [(0, 0), (W / 2, -0.03), (W, 0), (W, H), (W / 2, H + 0.03), (0, H)]
    z = [R] if dim == 3 else []
    table = Table(
        segments=np.array(segments),
        segment_sides=np.array(sides),
        circles=np.array([[*c, *z, 0.007] for c in tips]),
        targets=np.array([[*c, *z, 0.06] for c in pockets]),
    )
    if dim == 3:
        table = replace(table, planes=np.array([[[0.0, 0.0, 0.0], [0.0, 0.0, 1.0]]]))
    return table


def pool_paths(n: int, dim: int, seed: int) -> tuple[np.ndarray, ...]:
    """``n`` balls on the table that slide (on a curve), roll and stop: rows of 3 segments,
    some padded (a ball at rest from the start, one that only rolls). In 3-D a third of them
    start in the air above the bed and fall under gravity onto it before they roll."""
    rng = np.random.default_rng(seed)
    start = np.full((n, 3), np.inf)
    pos, vel, acc = (np.full((n, 3, dim), np.nan) for _ in range(3))
    for i in range(n):
        p = np.zeros(dim)
        p[:2] = rng.uniform([0.1, 0.1], [W - 0.1, H - 0.1])
        v = np.zeros(dim)
        v[:2] = rng.normal(0, 1.5, 2)
        rows = []
        if dim == 3:
            p[2] = R
            if rng.random() < 1 / 3:  # in the air: falls onto the bed (z = R) at t1
                p[2] = rng.uniform(R, 0.3)
                v[2] = rng.uniform(-1.0, 2.0)
                g = 9.81
                t1 = (v[2] + math.sqrt(v[2] ** 2 + 2 * g * (p[2] - R))) / g
                a = np.zeros(dim)
                a[2] = -g
                rows.append((0.0, p.copy(), v.copy(), a))
                p = p + v * t1 + 0.5 * a * t1 * t1
                p[2], v = R, v + a * t1
                v[2] = 0.0
        t = t1 if rows else 0.0
        kind = rng.integers(3)  # 0: at rest, 1: rolls, 2: slides then rolls
        if kind == 2 and len(rows) < 2:
            a = np.zeros(dim)
            a[:2] = rng.normal(0, 2.0, 2)
            tau = rng.uniform(0.05, 0.5)
            rows.append((t, p.copy(), v.copy(), a))
            p, v, t = p + v * tau + 0.5 * a * tau * tau, v + a * tau, t + tau
        speed = np.linalg.norm(v[:2])
        if kind >= 1 and speed > 0 and len(rows) < 2:
            a = np.zeros(dim)
            a[:2] = -0.1 * v[:2] / speed
            tau = speed / 0.1
            rows.append((t, p.copy(), v.copy(), a))
            p, t = p + v * tau + 0.5 * a * tau * tau, t + tau
        rows.append((t, p, np.zeros(dim), np.zeros(dim)))
        for k, (s, x, u, a) in enumerate(rows[:3]):
            start[i, k], pos[i, k], vel[i, k], acc[i, k] = s, x, u, a
    return start, pos, vel, acc


def objects_mapped(table: Table, f) -> Table:
    """``f`` applied to each object array (not to the sides)."""
    return Table(**{k: v if v is None or k not in NAMES else f(v) for k, v in vars(table).items()})


def first(result) -> tuple:
    """Path 0's answer, as Python numbers."""
    time, kind, index = result
    return float(time[0]), int(kind[0]), int(index[0])


def answers(paths, table: Table, radius, **kw) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    return bc.path_geometry_times(*paths, radius, **table.kwargs(), **kw)


def earliest(results: list[tuple[np.ndarray, np.ndarray, np.ndarray]]):
    """Of several calls' answers, per path the earliest: by time, then kind, then index."""
    time = np.stack([r[0] for r in results])
    kind = np.stack([r[1].astype(np.int64) for r in results])
    index = np.stack([r[2] for r in results])
    # Lexicographic: np.lexsort sorts by the last key first.
    order = np.lexsort((index, kind, time), axis=0)[0]
    pick = lambda a: np.take_along_axis(a, order[None], 0)[0]  # noqa: E731
    return pick(time), pick(kind).astype(np.int8), pick(index)


# --- agreement --------------------------------------------------------------------------


@pytest.mark.parametrize("dim", [2, 3])
def test_the_batch_is_each_path_alone_and_the_earliest_object(dim: int) -> None:
    n = 400
    paths = pool_paths(n, dim, seed=dim)
    table = pool_table(dim)
    radius = np.where(np.arange(n) % 3 == 0, R, 1.5 * R)
    time, kind, index = answers(paths, table, radius)
    assert time.dtype == np.float64 and kind.dtype == np.int8 and index.dtype == np.int64
    # Every kind of the table is met (the test covers them all), and none is reported with a
    # time of inf.
    for k in KINDS[: 3 + (dim == 3)]:
        assert (kind == k).sum() > 0, (k, np.bincount(kind + 1))
    assert np.array_equal(np.isinf(time), kind == -1) and np.array_equal(kind == -1, index == -1)
    # A plain loop over the paths, each a batch of one.
    for i in range(n):
        one = tuple(x[i : i + 1] for x in paths)
        t, k, j = answers(one, table, radius[i])
        assert (bits(t)[0], k[0], j[0]) == (bits(time)[i], kind[i], index[i]), i
    # The earliest of the objects, each asked alone.
    alone = []
    for name in NAMES:
        for m in range(table.count(name)):
            t, k, j = answers(paths, table.only(name, m), radius)
            alone.append((t, k, np.where(j == 0, m, j)))
    t, k, j = earliest(alone)
    np.testing.assert_array_equal(bits(t), bits(time))
    np.testing.assert_array_equal(k, kind)
    np.testing.assert_array_equal(j, index)


@pytest.mark.parametrize("dim", [2, 3])
def test_threads_out_and_layouts_give_the_same_bits(dim: int) -> None:
    n = 3_000  # some chunks: a pool table's 36 objects make chunks of 227 paths
    paths = pool_paths(n, dim, seed=10 + dim)
    table = pool_table(dim)
    time, kind, index = answers(paths, table, R)
    assert np.isfinite(time).sum() > n // 2
    for threads in (1, 2, None, 2**70):
        t, k, j = answers(paths, table, R, num_threads=threads)
        np.testing.assert_array_equal(bits(t), bits(time))
        np.testing.assert_array_equal(k, kind)
        np.testing.assert_array_equal(j, index)
    out = (np.full(n, np.nan), np.full(n, 9, np.int8), np.full(n, 9, np.int64))
    got = answers(paths, table, R, num_threads=2, out=out)
    assert all(g is o for g, o in zip(got, out, strict=True))
    np.testing.assert_array_equal(bits(out[0]), bits(time))
    np.testing.assert_array_equal(out[1], kind)
    np.testing.assert_array_equal(out[2], index)
    # A list of three arrays is as good as a tuple; Fortran-ordered float32 objects, lists
    # and per-ball radii as good as C-ordered float64.
    answers(paths, table, R, out=list(out))
    np.testing.assert_array_equal(bits(out[0]), bits(time))
    exact = objects_mapped(pool_table(dim), lambda v: v.astype(np.float32))
    as_f64 = objects_mapped(exact, lambda v: v.astype(np.float64))
    fortran = objects_mapped(exact, np.asfortranarray)
    lists = objects_mapped(as_f64, lambda v: v.tolist())
    want = answers(paths, as_f64, np.full(n, R))
    for table in (exact, fortran, lists):
        got = answers(paths, table, np.full(n, R))
        np.testing.assert_array_equal(bits(got[0]), bits(want[0]))
        np.testing.assert_array_equal(got[1], want[1])


def test_one_path_stands_for_every_ball_and_no_object_is_no_contact() -> None:
    paths = pool_paths(30, 2, seed=5)
    table = pool_table(2)
    radii = np.linspace(0.01, 0.1, 7)
    for i in range(30):
        one = tuple(x[i : i + 1] for x in paths)
        t, k, j = answers(one, table, radii)
        for q, r in enumerate(radii):
            u, c, m = answers(one, table, r)
            assert (bits(t)[q], k[q], j[q]) == (bits(u)[0], c[0], m[0])
    t, k, j = answers(paths, Table(), R)
    assert np.all(np.isinf(t)) and np.all(k == -1) and np.all(j == -1)
    empty = dict(segments=[], segment_sides=[], circles=np.empty((0, 3)), targets=[], planes=[])
    t, k, j = bc.path_geometry_times(*paths, R, **empty)
    assert np.all(np.isinf(t)) and np.all(k == -1)
    # N = 0.
    t, k, j = bc.path_geometry_times(*(x[:0] for x in paths), R, **table.kwargs())
    assert t.shape == k.shape == j.shape == (0,)


def test_the_kinds_are_the_cores_codes_and_exported() -> None:
    assert (bc.SEGMENT, bc.CIRCLE, bc.TARGET, bc.PLANE) == (0, 1, 2, 3)
    for name in ("SEGMENT", "CIRCLE", "TARGET", "PLANE", "path_geometry_times"):
        assert name in bc.__all__


# --- hand-checked cases ------------------------------------------------------------------


def rows(*segments) -> tuple[np.ndarray, ...]:
    """One path (N = 1) from segments ``(start, pos, vel, acc)``."""
    return tuple(np.array([[s[k] for s in segments]], dtype=float) for k in range(4))


def test_a_cushion() -> None:
    cushion = dict(segments=[[[0.0, 0.0], [2.0, 0.0]]], segment_sides=[1])
    # Down at 1 m/s from y = 0.625, radius 0.125: the centre reaches y = 0.125 at t = 0.5.
    down = rows((0.0, [1.0, 0.625], [0.0, -1.0], [0.0, 0.0]))
    assert first(bc.path_geometry_times(*down, 0.125, **cushion)) == (0.5, bc.SEGMENT, 0)
    # Slowing: y = 1 − 2t + t²/2 (decelerating at 1 m/s² until it stops at t = 2) reaches
    # y = 0.5 at t² − 4t + 1 = 0, t = 2 − √3.
    slowing = rows(
        (0.0, [1.0, 1.0], [0.0, -2.0], [0.0, 1.0]), (2.0, [1.0, -1.0], [0.0, 0.0], [0.0, 0.0])
    )
    t, kind, index = bc.path_geometry_times(*slowing, 0.5, **cushion)
    assert t[0] == pytest.approx(2 - math.sqrt(3), rel=4e-16) and kind[0] == bc.SEGMENT
    # From below, the left-side cushion is not there; a right-side one is, at the mirror time.
    up = rows((0.0, [1.0, -0.625], [0.0, 1.0], [0.0, 0.0]))
    t, kind, index = bc.path_geometry_times(*up, 0.125, **cushion)
    assert (t[0], kind[0], index[0]) == (math.inf, -1, -1)
    right = dict(segments=cushion["segments"], segment_sides=-1)
    assert bc.path_geometry_times(*up, 0.125, **right)[0][0] == 0.5
    # Beyond the end (x = 2.5): the flat part is missed.
    beyond = rows((0.0, [2.5, 0.625], [0.0, -1.0], [0.0, 0.0]))
    assert bc.path_geometry_times(*beyond, 0.125, **cushion)[1][0] == -1


def test_a_jaw_tip_at_a_cushions_end() -> None:
    # The cushion from (0, 0) to (1, 0) with its rounded ends (circles of radius 0); a ball of
    # radius 0.1 rolls down at x = 1.05, past the end: it meets the end at Q, when
    # 0.05² + y² = 0.1², y = √0.0075.
    table = dict(
        segments=[[[0.0, 0.0], [1.0, 0.0]]],
        segment_sides=1,
        circles=[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]],
    )
    path = rows((0.0, [1.05, 1.0], [0.0, -1.0], [0.0, 0.0]))
    t, kind, index = bc.path_geometry_times(*path, 0.1, **table)
    assert (kind[0], index[0]) == (bc.CIRCLE, 1)
    assert t[0] == pytest.approx(1 - math.sqrt(0.0075), rel=1e-15)
    # A jaw's tip of radius 0.25 at (2, 0) and a ball of radius 0.5 along y = 0: 2 − 0.75.
    tip = rows((0.0, [0.0, 0.0], [1.0, 0.0], [0.0, 0.0]))
    t, kind, _ = bc.path_geometry_times(*tip, 0.5, circles=[[2.0, 0.0, 0.25]])
    assert (t[0], kind[0]) == (1.25, bc.CIRCLE)
    # Off its line, at height b = 0.6: (x − 2)² + 0.36 = 0.75², x = 2 − 0.45.
    off = rows((0.0, [0.0, 0.6], [1.0, 0.0], [0.0, 0.0]))
    t, kind, _ = bc.path_geometry_times(*off, 0.5, circles=[[2.0, 0.0, 0.25]])
    assert t[0] == pytest.approx(1.55, rel=1e-15)


def test_a_pocket_takes_the_centre_whatever_the_radius() -> None:
    # Towards the corner at (−1, −1) m/s from (1, 1): the centre enters the pocket of radius
    # 0.06 about the corner when (1 − t)·√2 = 0.06. The cushions along both rails and their
    # jaws would be touched later (or never) by a ball aimed into the pocket's middle.
    table = pool_table(2)
    path = rows((0.0, [1.0, 1.0], [-1.0, -1.0], [0.0, 0.0]))
    expected = 1 - 0.06 / math.sqrt(2)
    for r in (0.001, 0.01):
        t, kind, index = bc.path_geometry_times(*path, r, targets=table.targets)
        assert (kind[0], index[0]) == (bc.TARGET, 0)
        assert t[0] == pytest.approx(expected, rel=1e-15)
    # With the rest of the table, a ball of 0.001 still drops in (it misses the jaws'
    # tips), and one of a pool ball's radius is taken by the pocket before anything else.
    for r in (0.001, R):
        t, kind, index = answers(path, table, r)
        assert (kind[0], index[0]) == (bc.TARGET, 0) and t[0] == pytest.approx(expected)


def test_the_bed_under_a_bouncing_ball_in_3d() -> None:
    bed = dict(planes=[[[0.0, 0.0, 0.0], [0.0, 0.0, 1.0]]])
    # Radius 0.25, dropped from z = 4.25 at rest under g = 8: lands when 4.25 − 4t² = 0.25,
    # t = 1; bounces up at 8 m/s and lands again at t = 3 (0.25 + 8s − 4s² = 0.25, s = 2).
    g = [0.0, 0.0, -8.0]
    bounce = rows(
        (0.0, [0.5, 0.5, 4.25], [0.0, 0.0, 0.0], g), (1.0, [0.5, 0.5, 0.25], [0.0, 0.0, 8.0], g)
    )
    fall = tuple(x[:, :1] for x in bounce)
    assert first(bc.path_geometry_times(*fall, 0.25, **bed)) == (1.0, bc.PLANE, 0)
    # From the bounce on: touching the bed and moving away is no contact; the next landing is.
    after = tuple(x[:, 1:] for x in bounce)
    assert first(bc.path_geometry_times(*after, 0.25, **bed)) == (3.0, bc.PLANE, 0)
    # The whole path: it reaches the bed exactly where the bounce starts, which moves away
    # (a simulator's path after it resolved the landing): no contact then (docs/contract.md
    # section 4.7), the next landing is.
    assert first(bc.path_geometry_times(*bounce, 0.25, **bed)) == (3.0, bc.PLANE, 0)
    # A normal of any length, through another point of the bed: the same bits.
    long = dict(planes=[[[3.0, -7.0, 0.0], [0.0, 0.0, 1e-300]]])
    assert bc.path_geometry_times(*after, 0.25, **long)[0][0] == 3.0
    # Rolling on the bed (touching it, no vertical motion) is no contact with it: the ball
    # meets the cushion's wall at x = 1 at t = 0.75.
    roll = rows((0.0, [0.0, 0.5, 0.25], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]))
    wall = dict(segments=[[[1.0, 0.0], [1.0, 1.0]]], segment_sides=1)  # x < 1: its left
    t, kind, index = bc.path_geometry_times(*roll, 0.25, **bed, **wall)
    assert (t[0], kind[0], index[0]) == (0.75, bc.SEGMENT, 0)
    # A segment in 3-D is the vertical wall over its line, whatever the height.
    high = rows((0.0, [0.0, 0.5, 9.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]))
    assert bc.path_geometry_times(*high, 0.25, **wall)[0][0] == 0.75


# --- properties (hypothesis) --------------------------------------------------------------

# Lengths on a grid of 2⁻²⁰ within ±4: a shift by a multiple of 2⁻¹⁰ within ±64 is exact.
grid = st.integers(-(2**22), 2**22).map(lambda i: i / 2**20)
speed = st.integers(-(2**22), 2**22).map(lambda i: i / 2**20)
shift = st.integers(-(2**16), 2**16).map(lambda i: i / 2**10)


@st.composite
def paths(draw, dim: int, n: int, at_rest: bool) -> tuple[np.ndarray, ...]:
    """``n`` paths of 1 to 3 segments (rows of 3, padded), on the grid; with ``at_rest``
    each ends at rest (its reach is bounded)."""
    start = np.full((n, 3), np.inf)
    pos, vel, acc = (np.full((n, 3, dim), np.nan) for _ in range(3))
    vec = lambda s: [draw(s) for _ in range(dim)]  # noqa: E731
    for i in range(n):
        k = draw(st.integers(1, 3))
        t = draw(st.sampled_from([0.0, 0.5, 1.0]))
        for j in range(k):
            still = at_rest and j == k - 1
            start[i, j] = t
            pos[i, j] = vec(grid)
            vel[i, j] = [0.0] * dim if still else vec(speed)
            acc[i, j] = [0.0] * dim if still else vec(speed)
            t += draw(st.sampled_from([0.0, 0.25, 1.0, 1.5]))
    return start, pos, vel, acc


@st.composite
def tables(draw, dim: int, kinds: tuple[str, ...] = NAMES) -> Table:
    """Up to 4 objects of each kind in ``kinds``, on the grid."""
    found: dict = {}
    count = lambda: draw(st.integers(0, 4))  # noqa: E731
    if "segments" in kinds:
        segments = []
        for _ in range(count()):
            p = [draw(grid), draw(grid)]
            q = [draw(grid), draw(grid)]
            assume(p != q)
            segments.append([p, q])
        found["segments"] = np.array(segments).reshape(-1, 2, 2)
        sides = [draw(st.sampled_from([-1, 0, 1])) for _ in segments]
        found["segment_sides"] = np.array(sides, dtype=np.int64)
    for name, low in (("circles", 0), ("targets", 1)):
        if name in kinds:
            rho = st.integers(low, 2**20).map(lambda i: i / 2**20)
            rows = [[*(draw(grid) for _ in range(dim)), draw(rho)] for _ in range(count())]
            found[name] = np.array(rows).reshape(-1, dim + 1)
    if "planes" in kinds:
        normal = st.integers(-3, 3)
        planes = []
        for _ in range(count()):
            n = [draw(normal) for _ in range(dim)]
            assume(any(n))
            planes.append([[draw(grid) for _ in range(dim)], n])
        found["planes"] = np.array(planes, dtype=float).reshape(-1, 2, dim)
    return Table(**found)


radii = st.integers(1, 2**19).map(lambda i: i / 2**20)


@st.composite
def scenes(draw, kinds: tuple[str, ...] = NAMES, at_rest: bool = False):
    dim = draw(st.sampled_from([2, 3]))
    n = draw(st.integers(1, 5))
    return dim, draw(paths(dim, n, at_rest)), draw(tables(dim, kinds)), draw(radii)


def same(x, y) -> None:
    np.testing.assert_array_equal(bits(x[0]), bits(y[0]))
    np.testing.assert_array_equal(x[1], y[1])
    np.testing.assert_array_equal(x[2], y[2])


def map_lengths(paths, table: Table, f, g=None):
    """``f`` applied to every position, velocity and acceleration of the paths and to every
    number of the objects but the planes' normals (``g``, if given, to those)."""
    start, pos, vel, acc = paths
    new = {}
    for name, v in vars(table).items():
        if v is None or name == "segment_sides":
            new[name] = v
        elif name == "planes":
            new[name] = np.stack([f(v[:, 0]), (g or (lambda x: x))(v[:, 1])], axis=1)
        else:
            new[name] = f(v)
    return (start, f(pos), f(vel), f(acc)), Table(**new)


@given(scenes(), st.integers(-60, 60))
def test_lengths_scaled_by_a_power_of_two_change_no_bit(scene, k: int) -> None:
    _dim, paths, table, r = scene
    scale = lambda x: np.ldexp(x, k)  # noqa: E731
    scaled_paths, scaled = map_lengths(paths, table, scale, lambda n: np.ldexp(n, -k // 2))
    found = answers(paths, table, r)
    for kind in found[1]:
        event("none" if kind < 0 else NAMES[kind])
    same(found, answers(scaled_paths, scaled, math.ldexp(r, k)))


@given(scenes(kinds=("segments", "planes")), st.lists(shift, min_size=3, max_size=3))
def test_an_exact_translation_changes_no_bit_for_segments_and_planes(scene, c) -> None:
    dim, paths, table, r = scene
    start, pos, vel, acc = paths
    c = np.array(c[:dim])
    moved = Table(
        segments=None if table.segments is None else table.segments + c[:2],
        segment_sides=table.segment_sides,
        planes=None
        if table.planes is None
        else np.stack([table.planes[:, 0] + c, table.planes[:, 1]], axis=1),
    )
    same(answers(paths, table, r), answers((start, pos + c, vel, acc), moved, r))


@given(scenes(), st.randoms(use_true_random=False))
def test_permuting_the_objects_permutes_the_index(scene, random) -> None:
    _dim, paths, table, r = scene
    time, kind, index = answers(paths, table, r)
    perms = {name: random.sample(range(table.count(name)), table.count(name)) for name in NAMES}
    new = {}
    for name, v in vars(table).items():
        of = "segments" if name == "segment_sides" else name
        new[name] = None if v is None else v[perms[of]]
    permuted = Table(**new)
    t, k, j = answers(paths, permuted, r)
    np.testing.assert_array_equal(bits(t), bits(time))
    np.testing.assert_array_equal(k, kind)
    for i in np.flatnonzero(k >= 0):
        name = NAMES[k[i]]
        was = perms[name][j[i]]
        # The same object unless another of its kind touches at the same time (a tie goes to
        # the lowest index, which the permutation changes).
        if was != index[i]:
            one = tuple(x[i : i + 1] for x in paths)
            alone = answers(one, table.only(name, was), r)[0]
            assert bits(alone)[0] == bits(time)[i], (i, name, was, index[i])


@given(scenes(at_rest=True), st.sampled_from(NAMES), st.booleans())
def test_a_far_object_changes_nothing(scene, name: str, first: bool) -> None:
    dim, paths, table, r = scene
    far = 1e6
    obj = {
        "segments": np.array([[[far, far], [far, 2 * far]]]),
        "circles": np.array([[far] * dim + [1.0]]),
        "targets": np.array([[far] * dim + [1.0]]),
        "planes": np.array([[[0.0] * (dim - 1) + [-far], [0.0] * (dim - 1) + [1.0]]]),
    }[name]
    old = getattr(table, name)
    both = (obj, old) if first else (old, obj)
    new = replace(table, **{name: np.concatenate([x for x in both if x is not None])})
    if name == "segments":
        sides = table.segment_sides if table.segment_sides is not None else np.zeros(0, int)
        new = replace(
            new, segment_sides=np.concatenate((np.ones(1, int), sides) if first else (sides, [1]))
        )
    time, kind, index = answers(paths, table, r)
    t, k, j = answers(paths, new, r)
    np.testing.assert_array_equal(bits(t), bits(time))
    np.testing.assert_array_equal(k, kind)
    shifted = index + ((kind == NAMES.index(name)) & first)
    np.testing.assert_array_equal(j, shifted)


@given(scenes(), st.floats(0.0, 4.0))
def test_a_horizon_only_cuts(scene, h: float) -> None:
    _dim, paths, table, r = scene
    time, kind, index = answers(paths, table, r)
    horizons = [h, math.inf, 0.0]
    for t in time[np.isfinite(time)]:
        horizons += [t, np.nextafter(t, math.inf), t + 1.0, t / 2]
    for h in horizons:
        t, k, j = answers(paths, table, r, t_max=h)
        kept = time < h
        np.testing.assert_array_equal(bits(t), bits(np.where(kept, time, math.inf)))
        np.testing.assert_array_equal(k, np.where(kept, kind, -1))
        np.testing.assert_array_equal(j, np.where(kept, index, -1))
    # Per ball: each its own horizon.
    per_ball = np.linspace(0.0, 3.0, len(time))
    t, k, j = answers(paths, table, r, t_max=per_ball)
    np.testing.assert_array_equal(bits(t), bits(np.where(time < per_ball, time, math.inf)))


# --- bad input ----------------------------------------------------------------------------

PATH2 = rows((0.0, [0.0, 0.0], [1.0, 0.0], [0.0, 0.0]), (1.0, [1.0, 0.0], [0.0, 0.0], [0.0, 0.0]))
PATH3 = tuple(
    np.concatenate([x, np.zeros(x.shape[:-1] + (1,))], axis=-1) if x.ndim == 3 else x for x in PATH2
)
TWO = tuple(np.concatenate([x, x]) for x in PATH2)
SEG = [[0.0, 1.0], [1.0, 1.0]]
NAN = math.nan


def bad(paths=PATH2, radius=0.1, **kw):
    return lambda: bc.path_geometry_times(*paths, radius, **kw)


def with_nan(paths, array: int, i: int, k: int, value: float = NAN):
    paths = tuple(np.array(x) for x in paths)
    paths[array][i, k, ...] = value
    return paths


BAD_INPUT = [
    # (call, argument, index, kind, message start)
    (bad(segments=[SEG, [[2.0, 2.0], [2.0, 2.0]]]), "segments", 1, "degenerate_segment", None),
    (bad(segments=[[[NAN, 0.0], [1.0, 1.0]]]), "segments", 0, "not_finite", None),
    (bad(segments=[SEG, SEG, [[0, 0], [math.inf, 0]]]), "segments", 2, "not_finite", None),
    (bad(segments=[SEG, SEG], segment_sides=[1, 2]), "segment_sides", 1, "invalid_side", None),
    (bad(segments=[SEG], segment_sides=np.array([-2])), "segment_sides", 0, "invalid_side", None),
    (bad(segments=[SEG], segment_sides=5), "segment_sides", None, "invalid_side", None),
    (bad(segments=[SEG], segment_sides=[2**70]), "segment_sides", 0, "invalid_side", None),
    (bad(segments=[SEG], segment_sides=[1, 1]), "segment_sides", None, "length_mismatch", None),
    (bad(segment_sides=[1]), "segment_sides", None, "length_mismatch", None),
    (bad(segments=[SEG], segment_sides=np.array([[1]])), "segment_sides", None, "shape", None),
    (bad(circles=[[0, 5, 1], [0, 5, -0.5]]), "circles", 1, "negative_circle_radius", None),
    (bad(circles=[[0, 5, NAN]]), "circles", 0, "not_finite", None),
    (bad(circles=[[0, math.inf, 1.0]]), "circles", 0, "not_finite", None),
    (
        bad(targets=[[0, 5, 1], [0, 5, 1], [0, 5, 0]]),
        "targets",
        2,
        "non_positive_target_radius",
        None,
    ),
    (bad(targets=[[0, 5, -1e300]]), "targets", 0, "non_positive_target_radius", None),
    (bad(planes=[[[0, -5], [0, 1]], [[0, -5], [0, 0]]]), "planes", 1, "zero_normal", None),
    (bad(planes=[[[0, NAN], [0, 1]]]), "planes", 0, "not_finite", None),
    # Shapes: a 2-D row where 3-D ones go and the other way round.
    (bad(segments=[[[0, 0, 0], [1, 1, 1]]]), "segments", None, "shape", None),
    (bad(circles=[[0, 5, 0, 1]]), "circles", None, "shape", None),
    (bad(PATH3, circles=[[0, 5, 1]]), "circles", None, "shape", None),
    (bad(PATH3, targets=[[0, 5, 1]]), "targets", None, "shape", None),
    (bad(PATH3, planes=[[[0, -5], [0, 1]]]), "planes", None, "shape", None),
    (bad(PATH3, circles=[[0, 5, 0, -1]]), "circles", 0, "negative_circle_radius", None),
    (bad(PATH3, planes=[[[0, 0, 0], [0, 0, 0]]]), "planes", 0, "zero_normal", None),
    # The paths, the radius and the horizon.
    (bad(with_nan(TWO, 2, 1, 0)), "vel", 1, "not_finite", "vel[1, 0]: must be finite"),
    (bad(with_nan(TWO, 0, 1, 1, -0.5)), "start", 1, "decreasing_start", "start[1, 1]: starts"),
    (bad(TWO, radius=[0.1, 0.0]), "radius", 1, "non_positive_ball_radius", "radius[1]: a ball"),
    (bad(TWO, radius=[0.1, 0.1, 0.1]), "radius", None, "length_mismatch", None),
    (bad(TWO, t_max=[1.0, -1.0]), "t_max", 1, "invalid_horizon", "t_max[1]: must be ≥ 0"),
    (bad(radius=NAN), "radius", None, "not_finite", None),
    (bad(num_threads=0), "num_threads", None, "out_of_range", None),
    # out=: its arrays by their place in the tuple.
    (
        bad(out=(np.empty(2), np.empty(1, np.int8), np.empty(1, np.int64))),
        "out",
        0,
        "out_layout",
        None,
    ),
    (
        bad(TWO, out=(np.empty(2), np.empty(4, np.int8)[::2], np.empty(2, np.int64))),
        "out",
        1,
        "out_layout",
        "out[1]: expected a C-contiguous",
    ),
    (bad(out=(np.empty(1), np.empty(1, np.int8))), "out", None, "out_layout", None),
    (bad(TWO, radius=np.full(2, 0.1), out=(np.empty(2),) * 3), "out", 1, None, None),
]


@pytest.mark.parametrize(("call", "argument", "index", "kind", "start"), BAD_INPUT)
def test_bad_input_names_the_argument_and_index(call, argument, index, kind, start) -> None:
    with pytest.raises((bc.InputError, TypeError)) as info:
        call()
    error = info.value
    if kind is None:  # an out array of another dtype: a TypeError naming it
        assert isinstance(error, TypeError) and str(error).startswith(f"{argument}[{index}]:")
        return
    assert isinstance(error, bc.InputError), repr(error)
    assert (error.argument, error.index, error.kind) == (argument, index, kind), repr(error)
    where = "" if index is None else f"[{index}"
    assert str(error).startswith(f"{argument}{where}"), str(error)
    if start is not None:
        assert str(error).startswith(start), str(error)


def test_out_must_not_share_memory_with_an_input_or_another_out() -> None:
    paths = tuple(np.array(x) for x in TWO)
    time, kind, index = np.empty(2), np.empty(2, np.int8), np.empty(2, np.int64)
    radius = np.full(2, 0.1)
    with pytest.raises(bc.InputError, match=r"^out\[0\]: the array shares memory with an input"):
        bc.path_geometry_times(*paths, radius, out=(radius, kind, index))
    with pytest.raises(bc.InputError, match=r"^out\[2\]: the array shares memory with an input"):
        bc.path_geometry_times(*paths, 0.1, out=(time, kind, paths[0].view(np.int64)[0]))
    with pytest.raises(bc.InputError, match=r"^out\[2\]: the array shares memory with out\[0\]"):
        bc.path_geometry_times(*paths, 0.1, out=(time, kind, time.view(np.int64)))
    read_only = np.empty(2, np.int8)
    read_only.flags.writeable = False
    with pytest.raises(bc.InputError, match=r"^out\[1\]: the array is read-only"):
        bc.path_geometry_times(*paths, 0.1, out=(time, read_only, index))
    with pytest.raises(TypeError, match=r"^out: expected None or a tuple"):
        bc.path_geometry_times(*paths, 0.1, out=time)
    # The objects are copied before anything is written: an object array may be an out.
    memory = np.array([5.0, 0.0, 0.5, 1.0, 0.0, 0.5])
    targets = memory.reshape(2, 3)
    t, _, j = bc.path_geometry_times(*paths, 0.1, targets=targets, out=(memory[:2], kind, index))
    assert t is not None and list(memory[:2]) == [0.5, 0.5] and list(j) == [1, 1]


def test_sides_are_ints() -> None:
    for sides, message in [
        ([True], r"^segment_sides\[0\]: expected an int \(-1, 0 or 1\), got bool"),
        ([1.0], r"^segment_sides\[0\]: expected an int \(-1, 0 or 1\), got float"),
        (np.array([1.0]), r"^segment_sides: expected ints \(-1, 0 or 1\), got an array of dtype"),
        (np.array([True]), r"^segment_sides: expected ints"),
        ("1", r"^segment_sides: expected an int"),
    ]:
        with pytest.raises(TypeError, match=message):
            bc.path_geometry_times(*PATH2, 0.1, segments=[SEG], segment_sides=sides)
    # numpy ints, Python ints of any width that are -1, 0 or 1, one for all, a tuple.
    for sides in (np.array([1], np.uint8), np.int64(-1), (0,), [np.int16(1)]):
        bc.path_geometry_times(*PATH2, 0.1, segments=[SEG], segment_sides=sides)
