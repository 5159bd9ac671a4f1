"""Independent high-precision reference for contacts with static geometry.

This script generates test cases for ``ballcollide.geometry`` (docs/contract.md,
"Static geometry") and computes their exact answers with mpmath.  It does not
import ballcollide.  Every input is a float64 number, converted exactly to mp
(``mpf(float)`` is exact) and processed at ``PREC_BITS`` = 256 bits.  Float64
arithmetic is used only to *invent* the inputs (simulating billiard balls,
aiming at cushions, bouncing off walls); whatever float64 numbers come out of
that are then the exact inputs.  The polynomial root isolation is the one of
``tools/collision_reference.py`` and the exact path model and the generators'
motions (billiard balls, bouncing particles) those of ``tools/path_reference.py``
(imported from them); the objects, their gap functions, the filters of a
segment, the floor and the ambiguity rules are this file's own.

Usage::

    python tools/geometry_reference.py                  # tests/data/geometry_cases.txt
    python tools/geometry_reference.py --fraction 0.05  # a quick, smaller run

Model
-----
A ball of radius r on a path (segments (s_k, p_k, v_k, a_k), as for
path_collision_time; searched from the path's first start t_from) against one
static object, each with a gap function G(t), negative in contact:

* segment (P, Q, side), 2-D: with e = Q - P, D(t) = e x (x(t) - P) (|e| times
  the signed distance from the line, positive on its left) and
  G = D^2 - r^2 |e|^2; u(t) = (x - P).e / |e|^2;
* circle (C, rho >= 0): G = |x - C|^2 - (rho + r)^2;
* target (C, rho > 0): G = |x - C|^2 - rho^2 (r plays no part);
* plane (Q, n): G = n.(x - Q) - r |n| (|n| the mp square root).

The contact is the earliest t >= t_from at which G goes from > 0 to < 0
(including a jump at a later segment start and a simple root exactly on one),
or t_from itself if G(t_from) <= 0 and the first non-zero derivative of G there
is negative; a segment's candidate counts only if 0 <= u <= 1 at it and, for
side +1 (-1), D > 0 (D < 0) there (the state just after a segment start); a
refused candidate does not end the search.  A tangency is none; a contact at
t >= t_max is none.  This is the pair reference's rule (path_reference.py) for
one moving path and a fixed object.

Algorithm
---------
The time axis from t_from is cut at every later segment start; on each window
G is an exact polynomial (degree <= 4) in tau = t - lo, from the position,
velocity and acceleration at lo; its real roots and critical points are
isolated by collision_reference's derivative cascade, the last window cut at
a Cauchy bound.  Values within 2^-232 of their magnitude (the same polynomial
built from the inputs' absolute values, every difference a sum) count as zero.
The sign runs are scanned for "+ then -" transitions, each offered to the
filters in time order.

Floor (eps = 2^-53)
-------------------
sigma_G(t) = eps * sum_i |x_i dG/dx_i (t)| over the inputs that decide G at t:
the start, position, velocity and acceleration of the active segment, every
number of the object (P, Q; C, rho; Q, n) and r, each derivative by a central
difference of relative step 2^-90 on the exact G (G is a polynomial of degree
<= 4 in each input but |n|: the difference is exact to far below the floor).

* a root t (G(t) = 0, G'(t) < 0): floor = sigma_G(t)/|G'(t)| + eps |t| (at a
  segment start, the larger of the sides whose G' < 0); G'(t) = 0: floor inf,
  ambiguous (flat_entry);
* a jump at a segment start b: floor = 2 eps |b|, plus the shift of a nearby
  crossing on a side within one rounding of touching (as path_reference);
* a hit at t_from: floor = eps |t_from| + min over k >= 1 with c_k < 0 of
  (X/|c_k|)^(1/k), X = max(0, G(t_from) + sigma_G(t_from)), c_k the Taylor
  coefficients of G at t_from.

Ambiguous flag (delta = 1e-9, K = 4)
------------------------------------
1. graze: a critical value of G (interior minima and maxima, and one-sided
   values at segment starts that are not part of a crossing) within
   band = max(delta * (the object's G at a distance off by delta), K sigma_G),
   before the contact (all of them for a miss, up to t_max), or the first one
   at or after a contact before t_max; for a segment only those where the foot
   is within [-0.05, 1.05] of the segment and the side is one that counts;
2. touch_t0: G(t_from) <= band and G'(t_from) within max(delta m1,
   K sigma_G'), m1 the magnitude of G' (the sum of |x_i dG'/dx_i|): in contact
   (G < -band) the sign of that G' alone decides; touching (|G| <= band) it is
   a hit either way if G''(t_from) < -delta m2;
3. t_max: the contact time ignoring t_max within max(delta t_max, K floor) of
   t_max;
4. end: a segment's candidate (accepted or refused) before or at the contact
   (all of them for a miss) whose u is within max(delta, K sigma_u) of 0 or 1,
   sigma_u including u' times the candidate's floor;
5. flat_entry, zero_run (G identically 0 on a window), side (a jump that
   lands within K roundings of the line of a one-sided segment).

Categories
----------
Segments (2-D, side +1, -1 or 0): seg_table (billiard balls, sliding on curves,
rolling, resting, against cushions and jaws on and about the table, aimed at a
random point of the segment or its band, from either side), seg_ends (aimed at
u = 0 or 1 off by 1e-12 .. 1e-2 of the length either way), seg_graze (closest
approach to the line r (1 +- 1e-12 .. 1e-3) within the segment), seg_touch
(touching or overlapping at the start: approaching, separating, tangential,
curving in), seg_slide (entering the band beyond an end and sliding along it
onto the segment: no flat-part contact), seg_far (long segments far from the
origin touched next to either end), seg_jump (a position jump into, across or
beside the band), seg_late (first starts 1e3 .. 1e6 s), seg_scale (lengths
times 2^k, k in -60..60, or 10^U(-6, 6)), seg_horizon (t_max next to the
contact).  Circles (2-D and spheres in 3-D, rho = 0 in a third of the cases):
circ_table, circ_graze, circ_touch, circ_scale, circ_3d.  Targets: targ_table
(pockets), targ_graze, targ_touch, targ_scale, targ_3d.  Planes: plane_bounce
(particles bouncing in a box under gravity, planes at any angle), plane_graze
(a parabola's apex r (1 +- 1e-12 .. 1e-3) from the plane), plane_touch,
plane_2d (lines), plane_scale, plane_late, plane_jump.

Output (tests/data/geometry_cases.txt)
--------------------------------------
One case per line, whitespace separated::

    category kind D K <K segments> radius <object> t_max t_ref floor ambiguous

kind is segment, circle, target or plane; a segment of the path is the
1 + 3 D numbers ``s p[D] v[D] a[D]``; the object is ``px py qx qy side``
(segment), ``c[D] rho`` (circle, target) or ``q[D] n[D]`` (plane).  Floats are
Python ``repr`` or ``inf``; t_ref is the exact contact time rounded to the
nearest float64 (inf = none); floor has 3 significant digits; ambiguous is 0
or 1.  ``read_cases(path)`` parses the file.
"""

from __future__ import annotations

import argparse
import math
import os
import random
import sys
import time
from dataclasses import dataclass, field
from multiprocessing import Pool

from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from collision_reference import (
    fmt,
    fmt_floor,
    mp_to_float,
    padd,
    peval,
    pmul,
    pscale,
    ptrim,
)

# The window scan, the answer's record and the summary are path_reference's: geometry's
# windows hold the same sign runs of an exact polynomial.
from path_reference import (
    BALL_R,
    MPath,
    Path,
    Result,
    Vec,
    advance,
    airborne_path,
    bounce_path,
    clean_path,
    f_pos,
    f_vel,
    last_start,
    log_uniform,
    pool_path,
    pool_state,
    rand_unit,
    rand_vec,
    random_path,
    scale_path,
    scan_window,
    summarize,
    table_point,
    translate,
    vadd,
    vdot,
    vnorm,
    vscale,
    vsub,
)

PREC_BITS = 256
EPS = mpf(2) ** -53
GRAZE_DELTA = mpf("1e-9")
BAND_FACTOR = 4
ZERO_BITS = PREC_BITS - 24
ROOT_BITS = PREC_BITS - 8
DIFF_STEP = mpf(2) ** -90
INF = mp.inf

KINDS = ("segment", "circle", "target", "plane")

DEFAULT_OUT = os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data", "geometry_cases.txt"
)

mp.prec = PREC_BITS


def set_precision() -> None:
    """Set the working precision (also the worker initialiser)."""
    mp.prec = PREC_BITS


# ---------------------------------------------------------------------------
# Cases
# ---------------------------------------------------------------------------


@dataclass(frozen=True)
class Case:
    """Generated inputs of one case.

    obj: segment (px, py, qx, qy, side), circle and target (*c, rho), plane
    (*q, *n).  t_max_rule, if set, is (relative_offset, fallback): t_max is
    float(t_u) * (1 + offset) once the contact time t_u without a horizon is
    known, fallback when there is none or it is at t_from.
    """

    category: str
    kind: str
    dim: int
    path: Path
    radius: float
    obj: tuple[float, ...]
    t_max: float = math.inf
    t_max_rule: tuple[float, float] | None = None


def validate(case: Case) -> None:
    """Reject malformed inputs (the generators must never make them)."""
    if case.kind not in KINDS or case.dim not in (2, 3):
        raise ValueError(f"bad kind or dimension: {case.kind} {case.dim}")
    prev = -math.inf
    for s, p, v, a in case.path:
        if not len(p) == len(v) == len(a) == case.dim:
            raise ValueError("wrong dimension")
        if not all(math.isfinite(x) for x in (s, *p, *v, *a)) or s < prev:
            raise ValueError("bad segment")
        prev = s
    if not (case.radius > 0 and math.isfinite(case.radius)):
        raise ValueError("bad radius")
    o = case.obj
    if not all(math.isfinite(x) for x in o):
        raise ValueError("object not finite")
    if case.kind == "segment":
        if case.dim != 2 or len(o) != 5 or o[4] not in (-1, 0, 1) or o[:2] == o[2:4]:
            raise ValueError("bad segment object")
    elif case.kind in ("circle", "target"):
        if len(o) != case.dim + 1 or o[-1] < 0 or (case.kind == "target" and o[-1] == 0):
            raise ValueError("bad disc")
    elif len(o) != 2 * case.dim or all(x == 0 for x in o[case.dim :]):
        raise ValueError("bad plane")


# ---------------------------------------------------------------------------
# The gap function of each object (mp)
# ---------------------------------------------------------------------------


def vec_polys(x0, v0, acc, magnitude: bool):
    """x(tau) = x0 + v0 tau + acc tau^2 / 2, one coefficient list per axis."""
    if magnitude:
        return [[abs(p), abs(v), abs(a) / 2] for p, v, a in zip(x0, v0, acc)]
    return [[p, v, a / 2] for p, v, a in zip(x0, v0, acc)]


def gap_poly(kind: str, obj: list[mpf], r: mpf, x0, v0, acc, magnitude: bool = False):
    """G(tau) for the motion x0 + v0 tau + acc tau^2/2 (lowest degree first).

    With magnitude, the same polynomial from the absolute values of every number
    and every difference made a sum: a bound on the size of the terms.
    """
    dim = len(x0)
    xs = vec_polys(x0, v0, acc, magnitude)

    def sub(poly: list[mpf], c: mpf) -> list[mpf]:
        return [poly[0] + abs(c) if magnitude else poly[0] - c, *poly[1:]]

    def neg(poly: list[mpf]) -> list[mpf]:
        return poly if magnitude else [-c for c in poly]

    if kind in ("circle", "target"):
        centre, rho = obj[:dim], obj[dim]
        reach = rho + r if kind == "circle" else rho
        g = [mpf(0)]
        for j in range(dim):
            d = sub(xs[j], centre[j])
            g = padd(g, pmul(d, d))
        return padd(g, [reach * reach if magnitude else -reach * reach])
    if kind == "plane":
        q, n = obj[:dim], obj[dim:]
        norm = mp.sqrt(sum(c * c for c in n))
        g = [mpf(0)]
        for j in range(dim):
            nj = abs(n[j]) if magnitude else n[j]
            g = padd(g, [nj * c for c in sub(xs[j], q[j])])
        return padd(g, [r * norm if magnitude else -r * norm])
    px, py, qx, qy = obj[:4]
    ex, ey = (abs(qx) + abs(px), abs(qy) + abs(py)) if magnitude else (qx - px, qy - py)
    wx, wy = sub(xs[0], px), sub(xs[1], py)
    d = padd([ex * c for c in wy], neg([ey * c for c in wx]))
    return padd(pmul(d, d), [r * r * (ex * ex + ey * ey) * (1 if magnitude else -1)])


def seg_d_u(obj: list[mpf], x, xd):
    """(D, u, u') of a segment object at position x, velocity xd."""
    px, py, qx, qy = obj[:4]
    ex, ey = qx - px, qy - py
    wx, wy = x[0] - px, x[1] - py
    l2 = ex * ex + ey * ey
    return ex * wy - ey * wx, (wx * ex + wy * ey) / l2, (xd[0] * ex + xd[1] * ey) / l2


def graze_scale(kind: str, obj: list[mpf], r: mpf, dim: int) -> mpf:
    """G at a closest approach off by a relative delta, per unit delta."""
    if kind == "circle":
        reach = obj[dim] + r
        return 2 * reach * reach
    if kind == "target":
        return 2 * obj[dim] ** 2
    if kind == "plane":
        return r * mp.sqrt(sum(c * c for c in obj[dim:]))
    px, py, qx, qy = obj[:4]
    return 2 * r * r * ((qx - px) ** 2 + (qy - py) ** 2)


# ---------------------------------------------------------------------------
# The exact problem
# ---------------------------------------------------------------------------


@dataclass
class Local:
    """G and its Taylor coefficients at one time, from one side, with sensitivities."""

    t: mpf
    right: bool
    coeffs: list[mpf]
    mags: list[mpf]
    sigma: list[mpf]  # eps * sum |x_i dc_k/dx_i| for c_0 and c_1
    size: list[mpf]  # sum |x_i dc_k/dx_i| for c_1 and c_2
    x: list[mpf]
    xd: list[mpf]

    @property
    def g(self) -> mpf:
        return self.coeffs[0]

    @property
    def g1(self) -> mpf:
        return self.coeffs[1] if len(self.coeffs) > 1 else mpf(0)

    def zero(self, k: int) -> bool:
        """Coefficient k is rounding-level (or absent)."""
        if k >= len(self.coeffs):
            return True
        return abs(self.coeffs[k]) <= mp.ldexp(self.mags[k], -ZERO_BITS)

    def sign(self, k: int) -> int:
        """Sign of coefficient k with the zero tolerance."""
        return 0 if self.zero(k) else (1 if self.coeffs[k] > 0 else -1)


class Problem:
    """Exact inputs of one case."""

    def __init__(self, case: Case):
        validate(case)
        self.case = case
        self.kind = case.kind
        self.dim = case.dim
        self.path = MPath(case.path)
        self.r = mpf(case.radius)
        self.obj = [mpf(x) for x in case.obj]
        self.t_from = self.path.segs[0].s
        self.graze = graze_scale(self.kind, self.obj, self.r, self.dim)
        side = int(case.obj[4]) if self.kind == "segment" else 0
        self.side = side

    def params(self, t: mpf, right: bool) -> list[mpf]:
        """The inputs that decide G at t: active segment, object, radius."""
        seg = self.path.segs[self.path.index(t, right)]
        return [seg.s, *seg.p, *seg.v, *seg.a, *self.obj, self.r]

    def taylor(self, params: list[mpf], t: mpf, magnitude: bool = False) -> list[mpf]:
        """Taylor coefficients of G at t (in tau = time since t) from params."""
        d = self.dim
        s, p, v, a = params[0], params[1 : 1 + d], params[1 + d : 1 + 2 * d], params[1 + 2 * d :]
        a, obj, r = a[:d], params[1 + 3 * d : -1], params[-1]
        tau = t - s
        x = [pj + vj * tau + aj * tau * tau / 2 for pj, vj, aj in zip(p, v, a)]
        xd = [vj + aj * tau for vj, aj in zip(v, a)]
        g = gap_poly(self.kind, obj, r, x, xd, a, magnitude)
        return g + [mpf(0)] * (5 - len(g))

    def local(self, t: mpf, right: bool = True) -> Local:
        """G at t from one side, its coefficients, magnitudes and sensitivities."""
        params = self.params(t, right)
        coeffs = self.taylor(params, t)
        mags = self.taylor([abs(x) for x in params], t, magnitude=True)
        sens0 = mpf(0)
        sens1 = mpf(0)
        sens2 = mpf(0)
        for i, xi in enumerate(params):
            if xi == 0:
                continue
            up = list(params)
            down = list(params)
            up[i] = xi * (1 + DIFF_STEP)
            down[i] = xi * (1 - DIFF_STEP)
            cu, cd = self.taylor(up, t), self.taylor(down, t)
            sens0 += abs(cu[0] - cd[0]) / (2 * DIFF_STEP)
            sens1 += abs(cu[1] - cd[1]) / (2 * DIFF_STEP)
            sens2 += abs(cu[2] - cd[2]) / (2 * DIFF_STEP)
        seg = self.path.segs[self.path.index(t, right)]
        tau = t - seg.s
        x = [p + v * tau + a * tau * tau / 2 for p, v, a in zip(seg.p, seg.v, seg.a)]
        xd = [v + a * tau for v, a in zip(seg.v, seg.a)]
        return Local(t, right, coeffs, mags, [EPS * sens0, EPS * sens1], [sens1, sens2], x, xd)

    def band(self, loc: Local) -> mpf:
        """Graze band at a local state."""
        return max(GRAZE_DELTA * self.graze, BAND_FACTOR * loc.sigma[0])

    def seg_state(self, loc: Local) -> tuple[mpf, mpf, mpf]:
        """(D, u, u') of a segment object at a local state."""
        return seg_d_u(self.obj, loc.x, loc.xd)

    def sigma_u(self, t: mpf, right: bool) -> mpf:
        """Change of u at fixed t under one rounding of every input."""
        params = self.params(t, right)
        d = self.dim

        def u_of(ps: list[mpf]) -> mpf:
            s, p, v, a = ps[0], ps[1 : 1 + d], ps[1 + d : 1 + 2 * d], ps[1 + 2 * d : 1 + 3 * d]
            tau = t - s
            x = [pj + vj * tau + aj * tau * tau / 2 for pj, vj, aj in zip(p, v, a)]
            return seg_d_u(ps[1 + 3 * d : -1], x, x)[1]

        total = mpf(0)
        for i, xi in enumerate(params):
            if xi == 0:
                continue
            up, down = list(params), list(params)
            up[i] = xi * (1 + DIFF_STEP)
            down[i] = xi * (1 - DIFF_STEP)
            total += abs(u_of(up) - u_of(down)) / (2 * DIFF_STEP)
        return EPS * total


# ---------------------------------------------------------------------------
# Windows
# ---------------------------------------------------------------------------


@dataclass
class Window:
    """G on [lo, hi) as a polynomial in tau = t - lo, with its sign runs."""

    lo: mpf
    hi: mpf
    coeffs: list[mpf]
    mags: list[mpf]
    runs: list[tuple[mpf, int]] = field(default_factory=list)
    crits: list[mpf] = field(default_factory=list)
    constant: bool = False

    def sign(self, tau: mpf, value: mpf | None = None) -> int:
        """Sign of G(lo + tau), 0 within 2^-ZERO_BITS of its magnitude."""
        v = peval(self.coeffs, tau) if value is None else value
        if abs(v) <= mp.ldexp(pscale(self.coeffs, tau) + peval(self.mags, abs(tau)), -ZERO_BITS):
            return 0
        return 1 if v > 0 else -1


def windows(problem: Problem) -> list[Window]:
    """The windows from t_from, each with its exact G polynomial."""
    starts = sorted({problem.t_from, *(s for s in problem.path.starts() if s > problem.t_from)})
    out = []
    for lo, hi in zip(starts, [*starts[1:], INF]):
        params = problem.params(lo, True)
        coeffs = ptrim(problem.taylor(params, lo))
        mags = problem.taylor([abs(x) for x in params], lo, magnitude=True)
        out.append(Window(lo, hi, coeffs, mags))
    return out


# ---------------------------------------------------------------------------
# The reference answer
# ---------------------------------------------------------------------------


@dataclass
class Candidate:
    """A '+ to -' transition of G (or the t_from hit), before the filters."""

    t: mpf
    kind: str  # "t_from", "jump" or "root"
    window: int
    tau: mpf


def approach_order(loc: Local) -> int:
    """Sign of the first non-zero Taylor coefficient of G beyond the value."""
    for k in range(1, len(loc.coeffs)):
        if not loc.zero(k):
            return loc.sign(k)
    return 0


def candidate_floor(problem: Problem, cand: Candidate, reasons: list[str]) -> mpf:
    """The floor of a candidate contact (see the docstring)."""
    if cand.kind == "t_from":
        loc = problem.local(cand.t, True)
        x = max(mpf(0), loc.g + loc.sigma[0])
        delays = [
            (x / abs(ck)) ** (mpf(1) / k)
            for k, ck in enumerate(loc.coeffs)
            if k and ck < 0 and not loc.zero(k)
        ]
        return EPS * abs(cand.t) + (min(delays) if delays else mpf(0))
    if cand.kind == "jump":
        b = cand.t
        floor = 2 * EPS * abs(b)
        left, right = problem.local(b, False), problem.local(b, True)
        if left.sign(1) < 0:
            floor += max(mpf(0), left.sigma[0] - left.g) / abs(left.g1)
        if right.sign(1) < 0:
            floor += max(mpf(0), right.g + right.sigma[0]) / abs(right.g1)
        return floor
    sides = [problem.local(cand.t, True)]
    if cand.tau == 0 and cand.t > problem.t_from:
        left = problem.local(cand.t, False)
        if left.sign(1) < 0:
            sides.append(left)
    floor = mpf(0)
    for loc in sides:
        if loc.sign(1) == 0:
            reasons.append("flat_entry")
            return INF
        floor = max(floor, loc.sigma[0] / abs(loc.g1))
    return floor + EPS * abs(cand.t)


def accepted(problem: Problem, cand: Candidate, floor: mpf, reasons: list[str]) -> bool:
    """The segment's filters (foot on the segment, side); always true otherwise.

    Notes an ambiguity when u is within its band of 0 or 1, or a one-sided
    segment's jump lands within rounding of the line.
    """
    if problem.kind != "segment":
        return True
    loc = problem.local(cand.t, True)
    d, u, du = problem.seg_state(loc)
    band_u = max(
        GRAZE_DELTA,
        BAND_FACTOR * (problem.sigma_u(cand.t, True) + abs(du) * (0 if floor == INF else floor)),
    )
    if abs(u) <= band_u or abs(u - 1) <= band_u:
        reasons.append("end")
    if problem.side != 0 and cand.kind == "jump":
        px, py, qx, qy = problem.obj[:4]
        size = abs(qx - px) + abs(qy - py)
        d_band = BAND_FACTOR * EPS * size * sum(abs(c) + abs(o) for c, o in zip(loc.x, (px, py)))
        if abs(d) <= d_band:
            reasons.append("side")
    if not 0 <= u <= 1:
        return False
    if problem.side == 0:
        return True
    return (d > 0) if problem.side > 0 else (d < 0)


def crit_relevant(problem: Problem, t: mpf, loc: Local) -> bool:
    """A segment's critical value matters only near the segment, on a side that counts."""
    if problem.kind != "segment":
        return True
    d, u, _ = problem.seg_state(loc)
    if not -0.05 <= u <= 1.05:
        return False
    return problem.side == 0 or (d > 0) == (problem.side > 0)


def boundary_crits(problem: Problem, b: mpf) -> list[tuple[mpf, Local]]:
    """The one-sided values of G at a segment start b that are not part of a crossing."""
    left, right = problem.local(b, False), problem.local(b, True)
    bl, br = problem.band(left), problem.band(right)
    gl, gr = left.g, right.g
    falling_l = left.sign(1) < 0
    falling_r = right.sign(1) < 0
    out = []
    if not (falling_l and (gr < -br or (abs(gr) <= br and falling_r))):
        out.append((b, left))
    if not (falling_r and (gl > bl or (abs(gl) <= bl and falling_l))):
        out.append((b, right))
    return out


def touch_ambiguous(problem: Problem, loc: Local) -> bool:
    """Touching or in contact at t_from while moving tangentially.

    In contact (G < -band), the sign of a G' within rounding decides alone
    (approaching: a hit at t_from; separating: G stays negative, none).
    Touching (|G| <= band), a G'' clearly negative makes it a hit either way (at
    t_from, or just after a rise within rounding).
    """
    band0 = problem.band(loc)
    if loc.g > band0:
        return False
    band1 = max(GRAZE_DELTA * loc.size[0], BAND_FACTOR * loc.sigma[1])
    if abs(loc.g1) > band1:
        return False
    if loc.g < -band0:
        return True
    band2 = GRAZE_DELTA * loc.size[1]
    c2 = loc.coeffs[2] if len(loc.coeffs) > 2 else mpf(0)
    return not c2 < -band2


def hit_before(problem: Problem, t_unb: mpf, kind: str, t_max: mpf) -> bool:
    """True if the contact at t_unb is strictly before t_max (see path_reference)."""
    if t_unb == INF or t_max == INF or kind != "root":
        return t_unb < t_max
    if abs(t_unb - t_max) > mp.ldexp(t_max, -(ROOT_BITS - 4)):
        return t_unb < t_max
    loc = problem.local(t_max, True)
    return loc.g < -mp.ldexp(loc.mags[0], -ZERO_BITS)


def contact(case: Case, t_max: float | None = None) -> Result:
    """Reference contact time, floor and ambiguity flag for one case."""
    problem = Problem(case)
    t_max = case.t_max if t_max is None else t_max
    tmax_mp = mpf(t_max)
    wins = windows(problem)
    for w in wins:
        scan_window(w)
    reasons: list[str] = []
    loc0 = problem.local(problem.t_from, True)

    # Candidates in time order: the t_from rule, then the '+ to -' transitions.
    cands: list[Candidate] = []
    if wins[0].sign(mpf(0)) <= 0 and approach_order(loc0) < 0:
        cands.append(Candidate(problem.t_from, "t_from", 0, mpf(0)))
    crits: list[tuple[mpf, Local]] = []
    prev = 0
    zero_run = False
    for i, w in enumerate(wins):
        if i > 0:
            crits.extend(boundary_crits(problem, w.lo))
        for tau in w.crits:
            crits.append((w.lo + tau, problem.local(w.lo + tau, True)))
        for tau, sign in w.runs:
            if sign == -1 and prev == 1:
                kind = "jump" if tau == 0 and w.sign(mpf(0)) == -1 else "root"
                cands.append(Candidate(w.lo + tau, kind, i, tau))
            elif sign == -1 and prev == 0 and zero_run:
                reasons.append("zero_run")
            if w.constant and sign == 0:
                zero_run = True
            elif sign != 0:
                zero_run = False
            prev = sign

    # The first candidate the filters accept.
    # (Candidates after t_max note no ambiguity: they cannot be the answer.)
    t_unb, kind, floor = INF, "none", mpf(0)
    for cand in cands:
        notes = reasons if cand.t <= tmax_mp else []
        cand_floor = candidate_floor(problem, cand, notes)
        if accepted(problem, cand, cand_floor, notes):
            t_unb, kind, floor = cand.t, cand.kind, cand_floor
            break

    # Grazes.
    near_touch = abs(loc0.g) <= problem.band(loc0)
    relevant = [(t, loc) for t, loc in crits if problem.t_from < t < t_unb and t <= tmax_mp]
    if t_unb < tmax_mp and (kind != "t_from" or near_touch):
        after = [(t, loc) for t, loc in crits if t >= t_unb and t > problem.t_from]
        if after:
            first = min(t for t, _ in after)
            relevant.extend((t, loc) for t, loc in after if t == first)
    for t, loc in relevant:
        if abs(loc.g) <= problem.band(loc) and crit_relevant(problem, t, loc):
            reasons.append("graze")
            break
    if touch_ambiguous(problem, loc0) and crit_relevant(problem, problem.t_from, loc0):
        reasons.append("touch_t0")
    if t_unb < INF and tmax_mp < INF:
        if abs(t_unb - tmax_mp) <= max(GRAZE_DELTA * tmax_mp, BAND_FACTOR * floor):
            reasons.append("t_max")
    t = t_unb if hit_before(problem, t_unb, kind, tmax_mp) else INF
    if t == INF:
        floor = mpf(0)
    return Result(t, t_unb, floor, bool(reasons), kind, reasons)


# ---------------------------------------------------------------------------
# Formatting and parsing
# ---------------------------------------------------------------------------


def obj_fields(case: Case) -> list[str]:
    """The object's numbers as text (a segment's side as an int)."""
    if case.kind == "segment":
        return [*(fmt(x) for x in case.obj[:4]), str(int(case.obj[4]))]
    return [fmt(x) for x in case.obj]


def format_line(case: Case, res: Result) -> str:
    """One data line."""
    segs = [fmt(x) for s, p, v, a in case.path for x in (s, *p, *v, *a)]
    return " ".join(
        [
            case.category,
            case.kind,
            str(case.dim),
            str(len(case.path)),
            *segs,
            fmt(case.radius),
            *obj_fields(case),
            fmt(case.t_max),
            fmt(mp_to_float(res.t)),
            fmt_floor(res.floor),
            "1" if res.ambiguous else "0",
        ]
    )


@dataclass(frozen=True)
class ParsedCase:
    """One line of the data file."""

    case: Case
    t_ref: float
    floor: float
    ambiguous: bool


def parse_line(line: str) -> ParsedCase:
    """Parse one data line."""
    w = line.split()
    category, kind, dim, k = w[0], w[1], int(w[2]), int(w[3])
    nums = [float(x) for x in w[4:]]
    path = []
    at = 0
    for _ in range(k):
        s = nums[at]
        p = tuple(nums[at + 1 : at + 1 + dim])
        v = tuple(nums[at + 1 + dim : at + 1 + 2 * dim])
        a = tuple(nums[at + 1 + 2 * dim : at + 1 + 3 * dim])
        path.append((s, p, v, a))
        at += 1 + 3 * dim
    radius = nums[at]
    at += 1
    size = {"segment": 5, "circle": dim + 1, "target": dim + 1, "plane": 2 * dim}[kind]
    obj = tuple(nums[at : at + size])
    at += size
    t_max, t_ref, floor, amb = nums[at : at + 4]
    case = Case(category, kind, dim, tuple(path), radius, obj, t_max)
    return ParsedCase(case, t_ref, floor, amb == 1.0)


def read_cases(path: str) -> list[ParsedCase]:
    """All cases of a data file."""
    with open(path, encoding="ascii") as fh:
        return [parse_line(line) for line in fh if line.strip() and not line.startswith("#")]


# ---------------------------------------------------------------------------
# Case generation (float64 only: it merely invents inputs)
# ---------------------------------------------------------------------------


def rounded(x: float, digits: int = 9) -> float:
    """x to `digits` significant decimal digits (shorter lines), never -0.0."""
    return float(f"{x:.{digits}g}") + 0.0


def rvec(v: Vec, digits: int = 9) -> Vec:
    """A vector's components rounded to `digits` digits."""
    return tuple(rounded(x, digits) for x in v)


def perp(v: Vec) -> Vec:
    """v turned a quarter to the left (2-D)."""
    return -v[1], v[0]


def unit2(theta: float) -> Vec:
    """The unit vector at angle theta."""
    return math.cos(theta), math.sin(theta)


def make(
    category: str,
    kind: str,
    path: Path,
    radius: float,
    obj: tuple[float, ...],
    t_max: float = math.inf,
    rule: tuple[float, float] | None = None,
) -> Case:
    """Assemble a case (no -0.0 in the path)."""
    dim = len(path[0][1])
    return Case(category, kind, dim, clean_path(path), radius, obj, t_max, rule)


def pool_ball_path(rng: random.Random, t0: float = 0.0, p: Vec = (0.0, 0.0)) -> Path:
    """A billiard ball's path: sliding (curving), rolling, at rest; or rolling only."""
    st = pool_state(rng, rest_prob=0.0, roll_prob=0.35)
    return pool_path(t0, p, st)


def general_path(rng: random.Random, dim: int, t0: float = 0.0) -> Path:
    """One to three segments of random constant accelerations (continuous)."""
    return random_path(rng, dim, t0, rng.randint(1, 3), rest_last=0.2)


def moving_time(rng: random.Random, path: Path) -> float:
    """A time at which the path still moves (or soon after its start)."""
    t0 = path[0][0]
    end = max(last_start(path), t0 + 0.2)
    return t0 + rng.uniform(0.02, 0.95) * (end - t0)


def aim_point(path: Path, t_c: float, x: Vec) -> Path:
    """The path translated so that it is at x at t_c (float)."""
    return translate(path, vsub(x, f_pos(path, t_c)))


def segment_object(p: Vec, q: Vec, side: int) -> tuple[float, ...]:
    """A segment's numbers."""
    return (*p, *q, float(side))


def random_side(rng: random.Random) -> int:
    """0 half the time, else +1 or -1."""
    return rng.choice((0, 0, 1, -1))


def cushion(rng: random.Random, length: tuple[float, float] = (0.05, 2.5)) -> tuple[Vec, Vec]:
    """A segment somewhere about the table, at any angle (a third axis-aligned)."""
    c = table_point(rng)
    if rng.random() < 0.33:
        th = rng.choice((0.0, 0.5, 1.0, 1.5)) * math.pi
    else:
        th = rng.uniform(0.0, 2.0 * math.pi)
    half = rng.uniform(*length) / 2
    e = vscale(half, unit2(th))
    return rvec(vsub(c, e)), rvec(vadd(c, e))


def seg_aimed(
    rng: random.Random,
    path: Path,
    p: Vec,
    q: Vec,
    radius: float,
    u: float,
    offset: float | None = None,
) -> tuple[Path, int]:
    """The path moved to be at the band's edge (or offset r off it) over u at a time.

    The side is the one the path comes from at that time (+1 left); offset is
    the distance from the line in units of r (default: a crossing of the edge).
    """
    t_c = moving_time(rng, path)
    e = vsub(q, p)
    n = vscale(1.0 / vnorm(e), perp(e))
    vel = f_vel(path, t_c)
    towards = vdot(vel, n)
    side = -1 if towards > 0 else 1
    dist = radius if offset is None else offset * radius
    x = vadd(vadd(p, vscale(u, e)), vscale(side * dist, n))
    return aim_point(path, t_c, x), side


def gen_seg_table(rng: random.Random, n: int) -> list[Case]:
    """Billiard balls against cushions about the table, aimed or at random."""
    out = []
    for _ in range(n):
        p, q = cushion(rng)
        path = pool_ball_path(rng)
        if rng.random() < 0.75:
            path, side = seg_aimed(rng, path, p, q, BALL_R, rng.uniform(-0.1, 1.1))
            side = side if rng.random() < 0.5 else random_side(rng)
        else:
            path = translate(path, table_point(rng))
            side = random_side(rng)
        out.append(make("seg_table", "segment", path, BALL_R, segment_object(p, q, side)))
    return out


def gen_seg_ends(rng: random.Random, n: int) -> list[Case]:
    """Aimed at u = 0 or 1, off by 1e-12 .. 1e-2 either way (or exactly)."""
    out = []
    for _ in range(n):
        p, q = cushion(rng)
        path = pool_ball_path(rng) if rng.random() < 0.5 else general_path(rng, 2)
        end = rng.choice((0.0, 1.0))
        off = 0.0 if rng.random() < 0.1 else rng.choice((-1, 1)) * log_uniform(rng, -12, -2)
        path, side = seg_aimed(rng, path, p, q, BALL_R, end + off)
        side = side if rng.random() < 0.7 else random_side(rng)
        out.append(make("seg_ends", "segment", path, BALL_R, segment_object(p, q, side)))
    return out


def gen_seg_graze(rng: random.Random, n: int) -> list[Case]:
    """Closest approach to the line r (1 +- 1e-12 .. 1e-3) over the segment."""
    out = []
    for _ in range(n):
        p, q = cushion(rng, (0.2, 2.5))
        e = vsub(q, p)
        n_hat = vscale(1.0 / vnorm(e), perp(e))
        side = rng.choice((1, -1))
        delta = rng.choice((-1, 1)) * log_uniform(rng, -12, -3)
        t_c = rng.uniform(0.1, 2.0)
        u = rng.uniform(0.05, 0.95)
        x = vadd(vadd(p, vscale(u, e)), vscale(side * BALL_R * (1 + delta), n_hat))
        along = vscale(rng.uniform(0.2, 2.0) * rng.choice((-1, 1)) / vnorm(e), e)
        # A parabola whose apex is at t_c: velocity along the line, acceleration away;
        # on one segment, or two (at rest from 2 t_c on).
        acc = vscale(side * rng.uniform(0.1, 3.0), n_hat)
        vel0 = vadd(along, vscale(-t_c, acc))
        start = vsub(vsub(x, vscale(t_c, vel0)), vscale(0.5 * t_c * t_c, acc))
        path: Path = ((0.0, start, vel0, acc),)
        if rng.random() < 0.5:
            rest = advance(start, vel0, acc, 2 * t_c)
            path = (*path, (2 * t_c, rest, (0.0, 0.0), (0.0, 0.0)))
        out.append(make("seg_graze", "segment", path, BALL_R, segment_object(p, q, side)))
    return out


def gen_seg_touch(rng: random.Random, n: int) -> list[Case]:
    """Touching or overlapping the band at the first start, in every way of moving."""
    out = []
    for _ in range(n):
        p, q = cushion(rng, (0.2, 2.5))
        e = vsub(q, p)
        ue = vscale(1.0 / vnorm(e), e)
        n_hat = perp(ue)
        side = rng.choice((1, -1))
        depth = rng.choice((1.0, 1.0, rng.uniform(0.0, 1.0), 1.0 - log_uniform(rng, -12, -4)))
        x = vadd(vadd(p, vscale(rng.uniform(-0.05, 1.05), e)), vscale(side * depth * BALL_R, n_hat))
        mode = rng.choice(("towards", "away", "along", "curve_in", "curve_out", "rest"))
        speed = rng.uniform(0.1, 2.0)
        acc = (0.0, 0.0)
        if mode == "towards":
            vel = vadd(vscale(-side * speed, n_hat), vscale(rng.uniform(-1, 1), ue))
        elif mode == "away":
            vel = vadd(vscale(side * speed, n_hat), vscale(rng.uniform(-1, 1), ue))
        elif mode == "rest":
            vel = (0.0, 0.0)
        else:
            vel = vscale(speed * rng.choice((-1, 1)), ue)
            sign = -side if mode == "curve_in" else side
            acc = vscale(sign * rng.uniform(0.1, 3.0), n_hat)
        t0 = rng.choice((0.0, rng.uniform(0.0, 100.0)))
        x = rvec(x, 12)
        path: Path = ((t0, x, vel, acc),)
        if rng.random() < 0.3:
            path = (*path, (t0 + 1.0, advance(x, vel, acc, 1.0), (0.0, 0.0), (0.0, 0.0)))
        out.append(
            make("seg_touch", "segment", path, BALL_R, segment_object(p, q, random_side(rng)))
        )
    return out


def gen_seg_slide(rng: random.Random, n: int) -> list[Case]:
    """Into the band beyond an end, then along it onto (or past) the segment."""
    out = []
    for _ in range(n):
        p, q = cushion(rng, (0.2, 2.5))
        e = vsub(q, p)
        le = vnorm(e)
        ue = vscale(1.0 / le, e)
        n_hat = perp(ue)
        side = rng.choice((1, -1))
        end_u = rng.choice((-0.2, 1.2))
        inside = rng.uniform(0.1, 0.9) * BALL_R
        x = vadd(vadd(p, vscale(end_u, e)), vscale(side * (BALL_R + 0.05), n_hat))
        towards = 1.0 if end_u < 0 else -1.0
        vel = vadd(vscale(towards * rng.uniform(0.5, 2.0), ue), vscale(-side * 0.5, n_hat))
        # Into the band: then the sideways motion stops and it slides along.
        t_in = (0.05 + BALL_R - inside) / 0.5
        x1 = advance(x, vel, (0.0, 0.0), t_in)
        vel1 = vscale(towards * rng.uniform(0.3, 2.0), ue)
        acc1 = (0.0, 0.0) if rng.random() < 0.5 else vscale(-towards * rng.uniform(0.0, 0.3), ue)
        path: Path = ((0.0, x, vel, (0.0, 0.0)), (t_in, x1, vel1, acc1))
        if rng.random() < 0.4:
            # Then away from the line, and back in over the segment.
            t2 = t_in + rng.uniform(0.1, 1.0)
            x2 = advance(x1, vel1, acc1, t2 - t_in)
            vel2 = vadd(vscale(towards * 0.3, ue), vscale(side * 1.0, n_hat))
            acc2 = vscale(-side * rng.uniform(1.0, 6.0), n_hat)
            path = (*path, (t2, x2, vel2, acc2))
        out.append(make("seg_slide", "segment", path, BALL_R, segment_object(p, q, side)))
    return out


def gen_seg_far(rng: random.Random, n: int) -> list[Case]:
    """Long segments far from the origin, or one end far away: touched next to an end."""
    out = []
    for _ in range(n):
        far = log_uniform(rng, 2, 7)
        th = rng.uniform(0.0, 2.0 * math.pi)
        near = rvec(table_point(rng))
        far_end = rvec(vadd(near, vscale(far, unit2(th))))
        p, q = (near, far_end) if rng.random() < 0.5 else (far_end, near)
        if rng.random() < 0.3:
            shift = vscale(log_uniform(rng, 2, 6), rand_unit(rng, 2))
            p, q = rvec(vadd(p, shift)), rvec(vadd(q, shift))
        e = vsub(q, p)
        le = vnorm(e)
        u_near = 0.0 if p == near else 1.0
        u = u_near + (1 if u_near == 0 else -1) * rng.uniform(-0.5, 3.0) / le
        path = pool_ball_path(rng) if rng.random() < 0.5 else general_path(rng, 2)
        path, side = seg_aimed(rng, path, p, q, BALL_R, u)
        side = side if rng.random() < 0.7 else random_side(rng)
        out.append(make("seg_far", "segment", path, BALL_R, segment_object(p, q, side)))
    return out


def gen_seg_jump(rng: random.Random, n: int) -> list[Case]:
    """A position jump at a later segment start: into, across or beside the band."""
    out = []
    for _ in range(n):
        p, q = cushion(rng, (0.2, 2.5))
        e = vsub(q, p)
        n_hat = vscale(1.0 / vnorm(e), perp(e))
        side = rng.choice((1, -1))
        before = vadd(vadd(p, vscale(rng.uniform(0, 1), e)), vscale(side * 3 * BALL_R, n_hat))
        land = rng.choice((0.5, -0.5, 0.0, 1.0, -1.0, 2.0, -2.0, 1.0 - 1e-9))
        u = rng.uniform(-0.1, 1.1)
        after = rvec(vadd(vadd(p, vscale(u, e)), vscale(side * land * BALL_R, n_hat)), 12)
        t1 = rng.uniform(0.1, 2.0)
        vel = rand_vec(rng, 2, 0.0, 1.0) if rng.random() < 0.5 else (0.0, 0.0)
        path = ((0.0, before, (0.0, 0.0), (0.0, 0.0)), (t1, after, vel, (0.0, 0.0)))
        out.append(
            make("seg_jump", "segment", path, BALL_R, segment_object(p, q, random_side(rng)))
        )
    return out


def gen_seg_late(rng: random.Random, n: int) -> list[Case]:
    """Aimed contacts on paths that start late (1e3 .. 1e6 s)."""
    out = []
    for _ in range(n):
        p, q = cushion(rng)
        t0 = rounded(log_uniform(rng, 3, 6), 12)
        path = pool_ball_path(rng, t0) if rng.random() < 0.6 else general_path(rng, 2, t0)
        path, side = seg_aimed(rng, path, p, q, BALL_R, rng.uniform(-0.1, 1.1))
        out.append(make("seg_late", "segment", path, BALL_R, segment_object(p, q, side)))
    return out


def scaled_case(case: Case, category: str, k: float) -> Case:
    """All lengths of a case times k (times unchanged)."""
    dim = case.dim
    o = case.obj
    if case.kind == "segment":
        obj = (*(x * k for x in o[:4]), o[4])
    elif case.kind in ("circle", "target"):
        obj = (*(x * k for x in o[:dim]), o[dim] * k)
    else:
        obj = (*(x * k for x in o[:dim]), *(x * k for x in o[dim:]))
    return Case(
        category, case.kind, dim, scale_path(case.path, k), case.radius * k, obj, case.t_max
    )


def scale_factor(rng: random.Random) -> float:
    """2^k, k in -60..60, or 10^U(-6, 6)."""
    if rng.random() < 0.6:
        return 2.0 ** rng.randint(-60, 60)
    return log_uniform(rng, -6, 6)


def gen_seg_scale(rng: random.Random, n: int) -> list[Case]:
    """seg_table and seg_ends cases with every length scaled."""
    base = gen_seg_table(rng, n // 2) + gen_seg_ends(rng, n - n // 2)
    return [scaled_case(c, "seg_scale", scale_factor(rng)) for c in base]


def with_horizon(rng: random.Random, case: Case, category: str) -> Case:
    """The case with t_max next to its contact (chosen once that is known)."""
    offset = rng.choice((0.0, 1e-12, -1e-12, 1e-6, -1e-6, 0.1, -0.1))
    fallback = case.path[0][0] + rng.uniform(0.0, 3.0)
    return Case(
        category,
        case.kind,
        case.dim,
        case.path,
        case.radius,
        case.obj,
        math.inf,
        (offset, fallback),
    )


def gen_seg_horizon(rng: random.Random, n: int) -> list[Case]:
    """Aimed segment contacts with t_max next to them."""
    return [with_horizon(rng, c, "seg_horizon") for c in gen_seg_table(rng, n)]


# --- circles and targets -----------------------------------------------------


def disc_aimed(rng: random.Random, path: Path, centre: Vec, reach: float, beta: float) -> Path:
    """The path moved to pass the centre at impact parameter beta * reach at a time."""
    t_c = moving_time(rng, path)
    vel = f_vel(path, t_c)
    dim = len(vel)
    speed = vnorm(vel)
    if speed == 0.0:
        off = vscale(reach * max(beta, 1.05), rand_unit(rng, dim))
        return aim_point(path, t_c, vadd(centre, off))
    uv = vscale(1.0 / speed, vel)
    if dim == 2:
        side_dir = perp(uv)
    else:
        r = rand_unit(rng, 3)
        side_dir = vsub(r, vscale(vdot(r, uv), uv))
        side_dir = vscale(1.0 / vnorm(side_dir), side_dir)
    if beta < 1.0:
        c = math.sqrt(1.0 - beta * beta)
        off = vscale(reach, vsub(vscale(beta, side_dir), vscale(c, uv)))
    else:
        off = vscale(reach * beta, side_dir)
    return aim_point(path, t_c, vadd(centre, off))


def disc_case(
    rng: random.Random, category: str, kind: str, dim: int, beta: float | None = None
) -> Case:
    """A ball aimed at a circle or target (rho = 0 for a third of the circles)."""
    if kind == "circle":
        rho = 0.0 if rng.random() < 0.33 else rounded(log_uniform(rng, -3, -0.5))
        reach = rho + BALL_R
    else:
        rho = rounded(rng.uniform(0.03, 0.12))
        reach = rho
    if dim == 2:
        centre = rvec(table_point(rng))
        path = pool_ball_path(rng) if rng.random() < 0.6 else general_path(rng, 2)
    else:
        centre = rvec(tuple(rng.uniform(0.0, 1.0) for _ in range(3)))
        path = bounce_path(rng, 3, 0.0, rng.randint(2, 4), gravity=rng.random() < 0.5)
    beta = rng.uniform(0.0, 1.3) if beta is None else beta
    if rng.random() < 0.85:
        path = disc_aimed(rng, path, centre, reach, beta)
    obj = (*centre, rho)
    return make(category, kind, path, BALL_R, obj)


def gen_disc_table(kind: str, category: str):
    """Generator of aimed circle or target cases in 2-D."""

    def gen(rng: random.Random, n: int) -> list[Case]:
        return [disc_case(rng, category, kind, 2) for _ in range(n)]

    return gen


def gen_disc_3d(kind: str, category: str):
    """Generator of aimed sphere cases (bouncing paths in 3-D)."""

    def gen(rng: random.Random, n: int) -> list[Case]:
        return [disc_case(rng, category, kind, 3) for _ in range(n)]

    return gen


def gen_disc_graze(kind: str, category: str):
    """Closest approach reach (1 +- 1e-12 .. 1e-3): a straight pass or a parabola's apex."""

    def gen(rng: random.Random, n: int) -> list[Case]:
        out = []
        for _ in range(n):
            point = kind == "circle" and rng.random() < 0.3
            rho = 0.0 if point else rounded(rng.uniform(0.02, 0.1))
            reach = rho + BALL_R if kind == "circle" else rho
            centre = rvec(table_point(rng))
            delta = rng.choice((-1, 1)) * log_uniform(rng, -12, -3)
            th = rng.uniform(0.0, 2.0 * math.pi)
            out_dir = unit2(th)
            x = vadd(centre, vscale(reach * (1 + delta), out_dir))
            along = vscale(rng.uniform(0.2, 2.0) * rng.choice((-1, 1)), perp(out_dir))
            t_c = rng.uniform(0.1, 2.0)
            acc = (0.0, 0.0)
            if rng.random() < 0.5:
                acc = vscale(rng.uniform(0.1, 2.0), out_dir)
            vel0 = vadd(along, vscale(-t_c, acc))
            start = vsub(vsub(x, vscale(t_c, vel0)), vscale(0.5 * t_c * t_c, acc))
            path = ((0.0, start, vel0, acc),)
            out.append(make(category, kind, path, BALL_R, (*centre, rho)))
        return out

    return gen


def gen_disc_touch(kind: str, category: str):
    """On or within the contact circle at the first start, moving every way."""

    def gen(rng: random.Random, n: int) -> list[Case]:
        out = []
        for _ in range(n):
            point = kind == "circle" and rng.random() < 0.3
            rho = 0.0 if point else rounded(rng.uniform(0.02, 0.1))
            reach = rho + BALL_R if kind == "circle" else rho
            centre = rvec(table_point(rng))
            out_dir = unit2(rng.uniform(0.0, 2.0 * math.pi))
            depth = rng.choice((1.0, 1.0, rng.uniform(0.05, 1.0)))
            x = rvec(vadd(centre, vscale(depth * reach, out_dir)), 12)
            mode = rng.choice(("in", "out", "tangent", "curve_in", "curve_out", "rest"))
            speed = rng.uniform(0.1, 2.0)
            acc = (0.0, 0.0)
            if mode == "in":
                vel = vadd(vscale(-speed, out_dir), vscale(rng.uniform(-1, 1), perp(out_dir)))
            elif mode == "out":
                vel = vadd(vscale(speed, out_dir), vscale(rng.uniform(-1, 1), perp(out_dir)))
            elif mode == "rest":
                vel = (0.0, 0.0)
            else:
                vel = vscale(speed, perp(out_dir))
                sign = -1 if mode == "curve_in" else 1
                acc = vscale(sign * rng.uniform(0.1, 3.0), out_dir)
            t0 = rng.choice((0.0, rounded(rng.uniform(0.0, 100.0))))
            path = ((t0, x, vel, acc),)
            out.append(make(category, kind, path, BALL_R, (*centre, rho)))
        return out

    return gen


def gen_disc_scale(kind: str, category: str):
    """Aimed disc cases with every length scaled."""

    def gen(rng: random.Random, n: int) -> list[Case]:
        base = [disc_case(rng, category, kind, 2) for _ in range(n)]
        return [scaled_case(c, category, scale_factor(rng)) for c in base]

    return gen


# --- planes ------------------------------------------------------------------


def plane_through(rng: random.Random, point: Vec, normal: Vec) -> tuple[float, ...]:
    """A plane's numbers: a point on it (moved within it) and a normal of any length."""
    dim = len(point)
    n_len = rng.choice((1.0, rng.uniform(0.1, 10.0), 2.0 ** rng.randint(-20, 20)))
    nvec = rvec(vscale(n_len, normal))
    if dim == 3:
        r = rand_unit(rng, 3)
        un = vscale(1.0 / vnorm(normal), normal)
        along = vsub(r, vscale(vdot(r, un), un))
    else:
        along = perp(normal)
    q = rvec(vadd(point, vscale(rng.uniform(-1.0, 1.0), along)))
    return (*q, *nvec)


def plane_normal(rng: random.Random, dim: int) -> Vec:
    """A unit normal: an axis a third of the time, else any direction."""
    if rng.random() < 0.33:
        j = rng.randrange(dim)
        return tuple(rng.choice((-1.0, 1.0)) if i == j else 0.0 for i in range(dim))
    return rand_unit(rng, dim)


def plane_aimed(rng: random.Random, path: Path, radius: float, dim: int) -> tuple[float, ...]:
    """A plane the path crosses (the contact where it moves towards it)."""
    t_c = moving_time(rng, path)
    x = f_pos(path, t_c)
    vel = f_vel(path, t_c)
    normal = plane_normal(rng, dim)
    if vdot(vel, normal) > 0:
        normal = vscale(-1.0, normal)
    point = vsub(x, vscale(radius * rng.choice((1.0, 1.0, 0.5, 2.0)), normal))
    return plane_through(rng, point, normal)


def gen_plane_bounce(rng: random.Random, n: int) -> list[Case]:
    """Particles bouncing in a box (some under gravity, some in the air) against planes."""
    out = []
    for _ in range(n):
        if rng.random() < 0.3:
            p = (rng.uniform(0, 2), rng.uniform(0, 1), rng.uniform(0.05, 0.5))
            path = airborne_path(0.0, p, (*rand_vec(rng, 2, 0.1, 2.0), rng.uniform(-1, 3)))
        else:
            path = bounce_path(rng, 3, 0.0, rng.randint(2, 5), gravity=rng.random() < 0.6)
        if rng.random() < 0.8:
            obj = plane_aimed(rng, path, BALL_R, 3)
        else:
            point = tuple(rng.uniform(0.0, 1.0) for _ in range(3))
            obj = plane_through(rng, point, plane_normal(rng, 3))
        out.append(make("plane_bounce", "plane", path, BALL_R, obj))
    return out


def gen_plane_graze(rng: random.Random, n: int) -> list[Case]:
    """A parabola whose apex is r (1 +- 1e-12 .. 1e-3) above the plane."""
    out = []
    for _ in range(n):
        dim = rng.choice((2, 3))
        normal = plane_normal(rng, dim)
        delta = rng.choice((-1, 1)) * log_uniform(rng, -12, -3)
        point = tuple(rng.uniform(0.0, 1.0) for _ in range(dim))
        apex = vadd(point, vscale(BALL_R * (1 + delta), normal))
        t_c = rng.uniform(0.1, 2.0)
        r = rand_unit(rng, dim)
        along = vsub(r, vscale(vdot(r, normal), normal))
        acc = vscale(rng.uniform(0.5, 10.0), normal)
        vel0 = vadd(vscale(rng.uniform(0.0, 2.0), along), vscale(-t_c, acc))
        start = vsub(vsub(apex, vscale(t_c, vel0)), vscale(0.5 * t_c * t_c, acc))
        path = ((0.0, start, vel0, acc),)
        out.append(make("plane_graze", "plane", path, BALL_R, plane_through(rng, point, normal)))
    return out


def gen_plane_touch(rng: random.Random, n: int) -> list[Case]:
    """On or beyond the plane at the first start, moving every way."""
    out = []
    for _ in range(n):
        dim = rng.choice((2, 3))
        normal = plane_normal(rng, dim)
        point = tuple(rng.uniform(0.0, 1.0) for _ in range(dim))
        depth = rng.choice((1.0, 1.0, rng.uniform(-1.0, 1.0)))
        x = rvec(vadd(point, vscale(depth * BALL_R, normal)), 12)
        r = rand_unit(rng, dim)
        along = vsub(r, vscale(vdot(r, normal), normal))
        mode = rng.choice(("in", "out", "along", "curve_in", "curve_out", "rest"))
        acc = zeros_of(dim)
        if mode == "in":
            vel = vadd(vscale(-rng.uniform(0.1, 2), normal), along)
        elif mode == "out":
            vel = vadd(vscale(rng.uniform(0.1, 2), normal), along)
        elif mode == "rest":
            vel = zeros_of(dim)
        else:
            vel = along
            sign = -1 if mode == "curve_in" else 1
            acc = vscale(sign * rng.uniform(0.1, 10.0), normal)
        path = ((rng.choice((0.0, 3.5)), x, vel, acc),)
        obj = (*rvec(point, 12), *normal)
        out.append(make("plane_touch", "plane", path, BALL_R, obj))
    return out


def zeros_of(dim: int) -> Vec:
    """The zero vector."""
    return (0.0,) * dim


def gen_plane_2d(rng: random.Random, n: int) -> list[Case]:
    """Lines in the plane against billiard balls and general paths."""
    out = []
    for _ in range(n):
        path = pool_ball_path(rng) if rng.random() < 0.5 else general_path(rng, 2)
        path = translate(path, table_point(rng))
        if rng.random() < 0.8:
            obj = plane_aimed(rng, path, BALL_R, 2)
        else:
            obj = plane_through(rng, table_point(rng), plane_normal(rng, 2))
        out.append(make("plane_2d", "plane", path, BALL_R, obj))
    return out


def gen_plane_scale(rng: random.Random, n: int) -> list[Case]:
    """Bouncing and 2-D plane cases with every length scaled."""
    base = gen_plane_bounce(rng, n // 2) + gen_plane_2d(rng, n - n // 2)
    return [scaled_case(c, "plane_scale", scale_factor(rng)) for c in base]


def gen_plane_late(rng: random.Random, n: int) -> list[Case]:
    """Bouncing paths that start late (1e3 .. 1e6 s)."""
    out = []
    for _ in range(n):
        t0 = rounded(log_uniform(rng, 3, 6), 12)
        path = bounce_path(rng, 3, t0, rng.randint(2, 4), gravity=rng.random() < 0.6)
        out.append(make("plane_late", "plane", path, BALL_R, plane_aimed(rng, path, BALL_R, 3)))
    return out


def gen_plane_jump(rng: random.Random, n: int) -> list[Case]:
    """A jump to on, beyond or just above the plane at a later segment start."""
    out = []
    for _ in range(n):
        dim = rng.choice((2, 3))
        normal = plane_normal(rng, dim)
        point = tuple(rng.uniform(0.0, 1.0) for _ in range(dim))
        before = vadd(point, vscale(3 * BALL_R, normal))
        land = rng.choice((0.5, -0.5, 1.0, 2.0, -3.0, 1.0 + 1e-9))
        after = rvec(vadd(point, vscale(land * BALL_R, normal)), 12)
        vel = rand_vec(rng, dim, 0.0, 1.0) if rng.random() < 0.5 else zeros_of(dim)
        t1 = rng.uniform(0.1, 2.0)
        path = ((0.0, before, zeros_of(dim), zeros_of(dim)), (t1, after, vel, zeros_of(dim)))
        obj = (*rvec(point, 12), *normal)
        out.append(make("plane_jump", "plane", path, BALL_R, obj))
    return out


CATEGORIES = (
    ("seg_table", gen_seg_table, 1300),
    ("seg_ends", gen_seg_ends, 700),
    ("seg_graze", gen_seg_graze, 500),
    ("seg_touch", gen_seg_touch, 500),
    ("seg_slide", gen_seg_slide, 500),
    ("seg_far", gen_seg_far, 500),
    ("seg_jump", gen_seg_jump, 300),
    ("seg_late", gen_seg_late, 400),
    ("seg_scale", gen_seg_scale, 500),
    ("seg_horizon", gen_seg_horizon, 300),
    ("circ_table", gen_disc_table("circle", "circ_table"), 800),
    ("circ_graze", gen_disc_graze("circle", "circ_graze"), 400),
    ("circ_touch", gen_disc_touch("circle", "circ_touch"), 400),
    ("circ_scale", gen_disc_scale("circle", "circ_scale"), 300),
    ("circ_3d", gen_disc_3d("circle", "circ_3d"), 400),
    ("targ_table", gen_disc_table("target", "targ_table"), 700),
    ("targ_graze", gen_disc_graze("target", "targ_graze"), 300),
    ("targ_touch", gen_disc_touch("target", "targ_touch"), 300),
    ("targ_scale", gen_disc_scale("target", "targ_scale"), 200),
    ("targ_3d", gen_disc_3d("target", "targ_3d"), 300),
    ("plane_bounce", gen_plane_bounce, 800),
    ("plane_graze", gen_plane_graze, 400),
    ("plane_touch", gen_plane_touch, 400),
    ("plane_2d", gen_plane_2d, 400),
    ("plane_scale", gen_plane_scale, 300),
    ("plane_late", gen_plane_late, 300),
    ("plane_jump", gen_plane_jump, 200),
)


def generate_cases(seed: int, fraction: float = 1.0) -> list[Case]:
    """All cases, deterministic for a seed (one generator per category)."""
    cases = []
    for index, (name, gen, count) in enumerate(CATEGORIES):
        rng = random.Random(f"{seed}:{index}:{name}")
        cases.extend(gen(rng, max(1, round(count * fraction))))
    return cases


# ---------------------------------------------------------------------------
# Driver
# ---------------------------------------------------------------------------


def solve_case(case: Case) -> tuple[Case, Result]:
    """Reference answer for a case, choosing t_max first if it has a rule."""
    if case.t_max_rule is None:
        return case, contact(case)
    rel, fallback = case.t_max_rule
    unbounded = contact(case, math.inf)
    t_u = mp_to_float(unbounded.t_unbounded)
    t_from = case.path[0][0]
    t_max = t_u * (1.0 + rel) if t_from < t_u < math.inf else fallback
    case = Case(case.category, case.kind, case.dim, case.path, case.radius, case.obj, t_max)
    return case, contact(case)


def header(seed: int, n: int) -> list[str]:
    """Comment lines at the top of the data file."""
    return [
        "# ballcollide reference static-geometry cases (tools/geometry_reference.py)",
        f"# {n} cases, seed {seed}; mpmath at {PREC_BITS} bits from the exact float64 inputs",
        "# line: category kind D K <K segments> radius <object> t_max t_ref floor ambiguous",
        "#   kind: segment (object px py qx qy side), circle or target (c[D] rho),",
        "#   plane (q[D] n[D]); a segment of the path: s p[D] v[D] a[D]",
        "# t_ref: exact first contact rounded to float64, inf = none; floor: eps = 2^-53 times",
        "#   sum |x_i dt/dx_i| over the active segment, the object and the radius, plus eps |t|",
        "#   (3 significant digits; 0 for a miss); ambiguous = 1: within 1e-9 relative (or 4",
        "#   roundings) of a graze, a segment's end, touching tangentially at the start, t_max.",
    ]


def main(argv: list[str] | None = None) -> int:
    """Generate the cases, solve them in parallel, write the data file."""
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--out", default=os.path.normpath(DEFAULT_OUT))
    parser.add_argument("--seed", type=int, default=20261236)
    parser.add_argument("--fraction", type=float, default=1.0)
    parser.add_argument("--processes", type=int, default=2)
    args = parser.parse_args(argv)
    start = time.time()
    cases = generate_cases(args.seed, args.fraction)
    if args.processes > 1:
        with Pool(args.processes, initializer=set_precision) as pool:
            rows = list(pool.imap(solve_case, cases, chunksize=16))
    else:
        rows = [solve_case(c) for c in cases]
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, "w", encoding="ascii") as fh:
        for line in header(args.seed, len(rows)):
            fh.write(line + "\n")
        for case, res in rows:
            fh.write(format_line(case, res) + "\n")
    print(summarize(rows))
    print(f"wrote {len(rows)} cases to {args.out} in {time.time() - start:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
