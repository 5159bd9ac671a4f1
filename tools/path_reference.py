"""Independent high-precision reference for first contacts of balls on paths.

This script generates test cases for ``ballcollide``'s general motion (SPEC.md,
"General motion") and computes their exact answers with mpmath.  It does not
import ballcollide.  Every input is a float64 number, converted exactly to mp
and processed at ``PREC_BITS`` = 256 bits (about 77 decimal digits).  Float64
arithmetic is used only to *invent* the inputs (simulating a billiard ball's
states, aiming shots, bouncing off walls); whatever float64 numbers come out of
that are then the exact inputs.  The polynomial root isolation is the one of
``tools/collision_reference.py`` (imported from it); the motion model, the
windows, the floor and the ambiguity rules are this file's own.

Usage::

    python tools/path_reference.py                  # writes tests/data/path_cases.txt
    python tools/path_reference.py --fraction 0.05  # a quick, smaller run
    python tools/path_reference.py --seed 7 --out /tmp/cases.txt

Model (see /work/shared/SPEC.md, "General motion")
--------------------------------------------------
A path in dimension D (2 or 3) is a list of segments (s_k, p_k, v_k, a_k) with
non-decreasing absolute starts s_k; on [s_k, s_{k+1}) the centre is
x(t) = p_k + v_k (t - s_k) + 1/2 a_k (t - s_k)^2, the last segment lasts for
ever, and a segment whose start equals the next one's is empty (never active).
"The segment active at t" is the last one with s_k <= t (from the right) or
with s_k < t (from the left).  With d(t) = x_A(t) - x_B(t) and
g(t) = |d(t)|^2 - R^2, searched from t_from = max(s_0^A, s_0^B):

* at t_from, with the segments active at t_from from the right: if g <= 0 and
  the first non-zero derivative of g (g', g'', g''', g'''') is negative, the
  collision is at t_from; otherwise (separating, tangential, or d' = d'' = 0)
  only a later entry counts;
* otherwise the collision is the earliest t > t_from at which g goes from
  positive (just before) to negative (just after).  This includes a segment
  start at which a path jumps into overlap (g > 0 just before, g < 0 just
  after: the collision is at that start) and a simple root that falls exactly
  on a segment start.  A tangency (g touching 0 and going back up) is none;
  an interval on which g is identically 0 (touching balls moving together) is
  neither positive nor negative, so leaving it into overlap is no "+ to -"
  transition (flagged ambiguous);
* a collision at t >= t_max is none (t_ref = inf).

Algorithm
---------
The time axis from t_from is cut at every segment start of either path that
is > t_from; on each window [lo, hi) both active segments are fixed and g is an
exact polynomial of degree <= 4 in tau = t - lo, built from the positions,
velocities and accelerations *at lo* (so that late absolute times cost no
accuracy, although at 256 bits they would not anyway).  Its real roots in
[0, hi - lo] are isolated by the derivative cascade of collision_reference
(roots of g''' bound the monotone pieces of g'', ..., critical points of g
bound its monotone pieces; safeguarded Newton/bisection to 2^-248 relative);
the last, infinite window is cut at the Cauchy bound of g and g' (beyond it
neither changes sign).  Values within 2^-232 of their evaluation scale (the
coefficient scale plus the squared position magnitudes and R^2) count as
zero.  The sign runs of all windows are then scanned in order for the first
"+ then -" transition; the left limit of a window is the last run of the one
before, so a jump at a segment start is a transition at that start.

Floor (eps = 2^-53, the float64 unit roundoff)
----------------------------------------------
The floor is eps * sum_i |x_i dt/dx_i| + eps * |t| over the inputs x_i that
decide the answer: the start, position, velocity and acceleration components
of the segment of A and of B active at the contact, and the radius.  (Each
segment carries its own position, so earlier segments do not move the centre
on a later one.)  With tau = t - s_k, the derivatives of x at fixed t are
dx/ds_k = -x'(t), dx/dp_k = I, dx/dv_k = tau I, dx/da_k = tau^2/2 I, and of
x' they are -a_k, 0, I, tau I.  Three kinds of contact:

* an entry root t (g(t) = 0, g'(t) < 0): dt/dx_i = -(dg/dx_i)/g'(t) (implicit
  differentiation), so floor = sigma_g(t)/|g'(t)| + eps |t| with
  sigma_g(t) = eps * sum_i |x_i dg/dx_i(t)|, the change of g caused by one
  rounding of every input.  A root exactly at a segment start takes the larger
  of the values from the segments on either side (those whose g' < 0).  A root
  with g'(t) = 0 (within 2^-232 of its scale; a flat, odd-multiplicity entry)
  has floor inf and is ambiguous;
* a jump at a segment start b (g_L = g(b-) > 0, g_R = g(b+) < 0): the time is
  the start itself, dt/ds = 1 for each path with a start at b, so
  floor = eps |b| (1 + n) with n = 1 or 2 such paths, plus, when a side is
  within one rounding of touching, the shift of a nearby crossing:
  max(0, sigma_L - g_L)/|g'_L| if g'_L < 0 and max(0, g_R + sigma_R)/|g'_R| if
  g'_R < 0;
* a hit at t = t_from (g(t_from) <= 0, approaching): the time is a start, so
  eps |t_from|, plus the delay one rounding could add to the contact of an
  exact touch: with X = max(0, g(t_from) + sigma_g(t_from)) and g = sum_k c_k
  tau^k on the first window, the smallest (X/|c_k|)^(1/k) over the k >= 1 with
  c_k < 0; i.e. nothing for a real overlap.  At t_from (here and in the
  touch_t0 band) sigma has one more input, the start that sets t_from:
  rounding it moves t_from, so a path whose active segment started earlier is
  evaluated at another time (d(d)/dt_from = +-x' of those paths).

floor = 0 when there is no collision (t_ref = inf).

Ambiguous flag
--------------
With delta = 1e-9 (GRAZE_DELTA), K = 4 (BAND_FACTOR), band(t) =
max(2 delta R^2, K sigma_g(t)) (2 delta R^2 is g at a closest approach of
R (1 + delta)), a case is ambiguous (1) when hit or miss, or which contact comes
first, could change within about 1e-9 relative, or within K roundings of every
input:

1. graze: a relevant critical value of g lies within band.  Critical values
   are g at the roots of g' inside windows, and the one-sided values g_L, g_R
   at a segment start b > t_from, except a side that is part of a crossing
   (g_L is benign if g'_L < 0 and g_R is either < -band or within band with
   g'_R < 0; g_R is benign if g'_R < 0 and g_L is either > band or within
   band with g'_L < 0).  This covers tangency at a segment boundary (a velocity
   kink or a jump to just touching).  Relevant are those at t_from < t <=
   t_max strictly before the collision (all of them for a miss), and for a
   collision before t_max all those at the first time at or after it, the
   bottom of the dip the balls enter (for a collision at t_from only when
   |g(t_from)| <= band(t_from));
2. touch_t0: g(t_from) <= band(t_from), g not constant on the first window,
   and h1 = d.d' within max(delta |d||d'|, K sigma_{g'}/2) (touching or
   overlapping while moving tangentially), unless h2 = |d'|^2 + d.d''
   (= g''/2) < -delta (|d'|^2 + |d||d''|) (accelerating into each other: a
   hit either way); when that band is 0 (h1 = 0 exactly and no input could
   change it) the case is ambiguous only if |h2| is within the delta band;
3. t_max: the collision time ignoring t_max is finite and within
   max(delta t_max, K floor) of t_max;
4. flat_entry: g'(t) = 0 at an entry root; zero_run: g identically 0 on a
   window and negative right after it.

When the collision time and t_max agree to the root accuracy (2^-244), the
sign of g(t_max) decides (a tie is no collision); a jump or t_from hit is
compared exactly.

Categories
----------
Billiard balls use pooltool's model (R = 0.028575 m, contact distance 2R,
u_s = 0.2, u_r = 0.01, g = 9.81): sliding with the slip v + w x (-R z) at any
angle to v, then rolling, then at rest, each segment's position and velocity
computed in float64 from the one before.  pool_random (pairs anywhere on the
table), pool_aimed (aimed shots), chasing_equal_acc (equal acceleration
vectors: rolling one way, side by side, one constant acceleration, equal
sliding), arbitrary_acc (1-4 random segments, 2-D/3-D), near_segment_start
(contacts 1e-9..1e-3 s from a segment start), late_start (first starts ~1e4 s,
up to 5 s apart), bouncing (4-8 segments in a unit box, some under gravity),
seed_friction (the seed model as paths; cross-checked against
collision_reference by the tests), airborne_3d (a ball in the air landing on
or passing over one on the cloth), gravity_3d (particles under one gravity,
some falling together), grazing (closest approach R (1 +- 1e-12..1e-3)),
touching_start and overlapping_start (at t_from; approaching, separating,
tangential, with accelerations), unit_scale (lengths times 2^k or
10^U(-6, 6)), horizon (finite t_max, often next to the contact) and
jump_overlap (a position jump at a later segment start).  The generator
docstrings give the details; the full run takes about 4 minutes on 2 cores.

Output (tests/data/path_cases.txt)
----------------------------------
One case per line, whitespace separated::

    category D KA KB  <KA segments of A>  <KB segments of B>  radius t_max t_ref floor ambiguous

where D is 2 or 3, KA, KB >= 1 the segment counts, and each segment is the
1 + 3 D numbers ``s p_1..p_D v_1..v_D a_1..a_D`` (``s px py vx vy ax ay`` in
2-D, ``s px py pz vx vy vz ax ay az`` in 3-D), so a line has
4 + (KA + KB)(1 + 3 D) + 5 fields.  Floats are Python ``repr`` (shortest
round trip, possibly ``-0.0``) or ``inf``; t_max = inf means no horizon; t_ref
is the exact absolute collision time rounded to the nearest float64 (inf =
none); floor has 3 significant digits; ambiguous is 0 or 1.  Lines starting
with ``#`` are comments.  ``read_cases(path)`` parses the file.
"""

from __future__ import annotations

import argparse
import math
import os
import random
import statistics
import sys
import time
from collections import Counter
from dataclasses import dataclass, field
from multiprocessing import Pool

from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from collision_reference import (
    bracket_root,
    fmt,
    fmt_floor,
    mp_to_float,
    pderiv,
    peval,
    pscale,
    ptrim,
    root_bound,
    roots_in,
)

PREC_BITS = 256
EPS = 2.0**-53
GRAZE_DELTA = 1e-9
BAND_FACTOR = 4
ZERO_BITS = PREC_BITS - 24
ROOT_BITS = PREC_BITS - 8

# Billiards (pooltool's defaults): ball radius, friction coefficients, gravity.
BALL_R = 0.028575
CONTACT = 2 * BALL_R
U_SLIDE = 0.2
U_ROLL = 0.01
GRAVITY = 9.81
TABLE_W = 2.54
TABLE_H = 1.27

DEFAULT_OUT = os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data", "path_cases.txt"
)

mp.prec = PREC_BITS
INF = mp.inf


def set_precision() -> None:
    """Set the working precision (also used as the worker initialiser)."""
    mp.prec = PREC_BITS


Vec = tuple[float, ...]
Segment = tuple[float, Vec, Vec, Vec]
Path = tuple[Segment, ...]


# ---------------------------------------------------------------------------
# Exact paths (mp)
# ---------------------------------------------------------------------------


@dataclass(frozen=True)
class MSeg:
    """One segment in exact mp form."""

    s: mpf
    p: tuple[mpf, ...]
    v: tuple[mpf, ...]
    a: tuple[mpf, ...]


class MPath:
    """A path in exact mp form, with the active-segment rule of the model."""

    def __init__(self, path: Path):
        self.segs = [
            MSeg(mpf(s), tuple(map(mpf, p)), tuple(map(mpf, v)), tuple(map(mpf, a)))
            for s, p, v, a in path
        ]

    def index(self, t: mpf, right: bool) -> int:
        """Index of the segment active just after (right) or just before t."""
        k = 0
        for i, seg in enumerate(self.segs):
            if seg.s < t or (right and seg.s == t):
                k = i
        return k

    def state(self, t: mpf, right: bool) -> tuple[int, mpf, list[mpf], list[mpf], tuple]:
        """(k, tau, x, x', x'') at t on the segment active on the given side."""
        k = self.index(t, right)
        seg = self.segs[k]
        tau = t - seg.s
        x = [p + v * tau + a * tau * tau / 2 for p, v, a in zip(seg.p, seg.v, seg.a)]
        xd = [v + a * tau for v, a in zip(seg.v, seg.a)]
        return k, tau, x, xd, seg.a

    def starts(self) -> list[mpf]:
        """All segment starts."""
        return [seg.s for seg in self.segs]


def validate(dim: int, a: Path, b: Path, radius: float) -> None:
    """Reject malformed inputs (the generator must never produce them)."""
    if dim not in (2, 3):
        raise ValueError("dimension must be 2 or 3")
    for name, path in (("A", a), ("B", b)):
        if not path:
            raise ValueError(f"path {name} has no segment")
        prev = -math.inf
        for k, (s, p, v, acc) in enumerate(path):
            if not (len(p) == len(v) == len(acc) == dim):
                raise ValueError(f"path {name} segment {k}: wrong dimension")
            if not all(math.isfinite(x) for x in (s, *p, *v, *acc)):
                raise ValueError(f"path {name} segment {k}: not finite")
            if s < prev:
                raise ValueError(f"path {name} segment {k}: starts must not decrease")
            prev = s
    if not (radius > 0 and math.isfinite(radius)):
        raise ValueError("radius must be positive")


@dataclass
class Local:
    """Relative motion at one time from one side: d, d', d'' and the scales."""

    t: mpf
    right: bool
    d: list[mpf]
    d1: list[mpf]
    d2: list[mpf]
    g: mpf
    g1: mpf
    g2: mpf
    scale0: mpf
    scale1: mpf
    terms0: list[mpf]
    terms1: list[mpf]

    @property
    def sigma0(self) -> mpf:
        """Change of g caused by one rounding of every deciding input."""
        return EPS * sum(abs(x) for x in self.terms0)

    @property
    def sigma1(self) -> mpf:
        """Change of g' caused by one rounding of every deciding input."""
        return EPS * sum(abs(x) for x in self.terms1)

    def zero(self, value: mpf, scale: mpf) -> bool:
        """|value| is rounding-level relative to its scale."""
        return abs(value) <= mp.ldexp(scale, -ZERO_BITS)

    def sign_g(self) -> int:
        """Sign of g with the zero tolerance."""
        return 0 if self.zero(self.g, self.scale0) else (1 if self.g > 0 else -1)

    def sign_g1(self) -> int:
        """Sign of g' with the zero tolerance."""
        return 0 if self.zero(self.g1, self.scale1) else (1 if self.g1 > 0 else -1)


def dot(a: list[mpf], b: list[mpf]) -> mpf:
    """Dot product."""
    return sum((x * y for x, y in zip(a, b)), mpf(0))


@dataclass
class Problem:
    """Exact inputs of one case."""

    dim: int
    a: MPath
    b: MPath
    radius: mpf
    t_from: mpf

    def local(self, t: mpf, right: bool = True) -> Local:
        """d, g, g', g'' and the input sensitivities at t from one side."""
        ka, ta, xa, va, aa = self.a.state(t, right)
        kb, tb, xb, vb, ab = self.b.state(t, right)
        d = [p - q for p, q in zip(xa, xb)]
        d1 = [p - q for p, q in zip(va, vb)]
        d2 = [p - q for p, q in zip(aa, ab)]
        r2 = self.radius * self.radius
        g = dot(d, d) - r2
        g1 = 2 * dot(d, d1)
        g2 = 2 * (dot(d1, d1) + dot(d, d2))
        scale0 = sum((abs(p) + abs(q)) ** 2 for p, q in zip(xa, xb)) + r2
        scale1 = 2 * sum(
            (abs(p) + abs(q)) * (abs(u) + abs(w)) for p, q, u, w in zip(xa, xb, va, vb)
        )
        terms0: list[mpf] = []
        terms1: list[mpf] = []
        for path, k, tau, xdot, acc, sign in (
            (self.a, ka, ta, va, aa, 1),
            (self.b, kb, tb, vb, ab, -1),
        ):
            seg = path.segs[k]
            # d(d)/ds = -x', d(d')/ds = -a (times the sign of the path in d).
            dd = [-sign * x for x in xdot]
            dd1 = [-sign * x for x in acc]
            terms0.append(seg.s * 2 * dot(d, dd))
            terms1.append(seg.s * 2 * (dot(dd, d1) + dot(d, dd1)))
            for j in range(self.dim):
                # p_j: dd = e_j, dd' = 0; v_j: tau e_j, e_j; a_j: tau^2/2 e_j, tau e_j.
                for x, cd, cd1 in (
                    (seg.p[j], 1, 0),
                    (seg.v[j], tau, 1),
                    (seg.a[j], tau * tau / 2, tau),
                ):
                    terms0.append(x * 2 * sign * cd * d[j])
                    terms1.append(x * 2 * sign * (cd * d1[j] + cd1 * d[j]))
        if t == self.t_from:
            # Rounding the start that sets t_from moves t_from itself: the path
            # whose segment started earlier is then evaluated at another time.
            dd = [mpf(0)] * self.dim
            dd1 = [mpf(0)] * self.dim
            for path, k, xdot, acc, sign in ((self.a, ka, va, aa, 1), (self.b, kb, vb, ab, -1)):
                if path.segs[k].s < t:
                    dd = [x + sign * y for x, y in zip(dd, xdot)]
                    dd1 = [x + sign * y for x, y in zip(dd1, acc)]
            terms0.append(t * 2 * dot(d, dd))
            terms1.append(t * 2 * (dot(dd, d1) + dot(d, dd1)))
        terms0.append(-2 * r2)
        terms1.append(mpf(0))
        return Local(t, right, d, d1, d2, g, g1, g2, scale0, scale1, terms0, terms1)

    def band(self, loc: Local) -> mpf:
        """Graze band at a local state: max(2 delta R^2, K sigma_g)."""
        return max(2 * GRAZE_DELTA * self.radius**2, BAND_FACTOR * loc.sigma0)


def make_problem(dim: int, a: Path, b: Path, radius: float) -> Problem:
    """Validate and build the exact Problem."""
    validate(dim, a, b, radius)
    pa, pb = MPath(a), MPath(b)
    t_from = max(pa.segs[0].s, pb.segs[0].s)
    return Problem(dim, pa, pb, mpf(radius), t_from)


# ---------------------------------------------------------------------------
# Windows
# ---------------------------------------------------------------------------


@dataclass
class Window:
    """g on [lo, hi) as a polynomial in tau = t - lo, with its sign runs."""

    lo: mpf
    hi: mpf
    coeffs: list[mpf]
    mag: mpf
    runs: list[tuple[mpf, int]] = field(default_factory=list)
    crits: list[mpf] = field(default_factory=list)
    constant: bool = False

    def sign(self, tau: mpf, value: mpf | None = None) -> int:
        """Sign of g(lo + tau), 0 within 2^-ZERO_BITS of its evaluation scale."""
        v = peval(self.coeffs, tau) if value is None else value
        if abs(v) <= mp.ldexp(pscale(self.coeffs, tau) + self.mag, -ZERO_BITS):
            return 0
        return 1 if v > 0 else -1


def windows(problem: Problem) -> list[Window]:
    """The windows from t_from, each with the exact gap polynomial."""
    cuts = sorted(
        {problem.t_from, *(s for s in problem.a.starts() if s > problem.t_from)}
        | {s for s in problem.b.starts() if s > problem.t_from}
    )
    out = []
    for lo, hi in zip(cuts, [*cuts[1:], INF]):
        _, _, xa, va, aa = problem.a.state(lo, True)
        _, _, xb, vb, ab = problem.b.state(lo, True)
        d0 = [p - q for p, q in zip(xa, xb)]
        d1 = [p - q for p, q in zip(va, vb)]
        d2 = [p - q for p, q in zip(aa, ab)]
        r2 = problem.radius**2
        c = [
            dot(d0, d0) - r2,
            2 * dot(d0, d1),
            dot(d1, d1) + dot(d0, d2),
            dot(d1, d2),
            dot(d2, d2) / 4,
        ]
        mag = sum((abs(p) + abs(q)) ** 2 for p, q in zip(xa, xb)) + r2
        out.append(Window(lo, hi, ptrim(c), mag))
    return out


def scan_window(w: Window) -> None:
    """Fill the sign runs and interior critical points of one window.

    A run (tau, sign) holds from tau to the next run's start; the last run of
    the infinite window extends to infinity.
    """
    c = w.coeffs
    if len(c) <= 1:
        w.runs = [(mpf(0), w.sign(mpf(0)))]
        w.constant = True
        return
    dc = ptrim(pderiv(c))
    if w.hi == INF:
        bound = root_bound(c)
        if len(dc) > 1:
            bound = max(bound, root_bound(dc))
        h = bound + 1
    else:
        h = w.hi - w.lo
    crit = roots_in(dc, mpf(0), h)
    pts = [mpf(0), *crit, h]
    vals = [peval(c, x) for x in pts]
    signs = [w.sign(x, v) for x, v in zip(pts, vals)]
    runs = []
    for i in range(len(pts) - 1):
        s0, s1 = signs[i], signs[i + 1]
        if s0 * s1 < 0:
            root = bracket_root(c, dc, pts[i], pts[i + 1], vals[i], vals[i + 1])
            runs.append((pts[i], s0))
            runs.append((root, s1))
        else:
            runs.append((pts[i], s0 if s0 != 0 else s1))
    w.runs = runs
    w.crits = crit


# ---------------------------------------------------------------------------
# Reference answer
# ---------------------------------------------------------------------------


@dataclass
class Result:
    """Reference answer for one case (mp values; see module docstring)."""

    t: mpf
    t_unbounded: mpf
    floor: mpf
    ambiguous: bool
    kind: str
    reasons: list[str] = field(default_factory=list)


@dataclass
class Crit:
    """A critical value of g: time, value, graze band there."""

    t: mpf
    g: mpf
    band: mpf


def approach_order(c: list[mpf], loc: Local) -> int:
    """Sign of the first non-zero derivative of g at tau = 0 (0: none).

    c are the first window's coefficients (c_k = g^(k)/k!); zero means within
    2^-ZERO_BITS of the magnitude of the products that make it up.
    """
    da = [abs(x) for x in loc.d]
    d1 = [abs(x) for x in loc.d1]
    d2 = [abs(x) for x in loc.d2]
    scales = [
        None,
        2 * dot(da, d1) + loc.scale1,
        dot(d1, d1) + dot(da, d2),
        dot(d1, d2),
        dot(d2, d2) / 4,
    ]
    for k in range(1, len(c)):
        if abs(c[k]) > mp.ldexp(scales[k], -ZERO_BITS):
            return 1 if c[k] > 0 else -1
    return 0


def collision(dim: int, a: Path, b: Path, radius: float, t_max: float = math.inf) -> Result:
    """Reference collision time, floor and ambiguity flag for one case."""
    problem = make_problem(dim, a, b, radius)
    t_from = problem.t_from
    wins = windows(problem)
    for w in wins:
        scan_window(w)
    loc0 = problem.local(t_from, True)
    band0 = problem.band(loc0)
    c_first = wins[0].coeffs
    reasons: list[str] = []

    # The t_from rule.
    approach = approach_order(c_first, loc0)
    if loc0.sign_g() <= 0 and approach < 0:
        t_unb, kind = t_from, "t_from"
    else:
        t_unb, kind = INF, "none"

    # Scan of the sign runs for the first + to - transition; critical values.
    crits: list[Crit] = []
    prev = 0
    zero_run = False
    entry_window = None
    for i, w in enumerate(wins):
        if i > 0:
            crits.extend(boundary_crits(problem, w.lo))
        for tau in w.crits:
            t = w.lo + tau
            loc = problem.local(t, True)
            crits.append(Crit(t, peval(w.coeffs, tau), problem.band(loc)))
        for tau, sign in w.runs:
            if kind == "none":
                if sign == -1 and prev == 1:
                    t_unb = w.lo + tau
                    entry_window = (i, tau)
                    kind = "jump" if tau == 0 and w.sign(mpf(0)) == -1 else "root"
                elif sign == -1 and prev == 0 and zero_run:
                    reasons.append("zero_run")
            if w.constant and sign == 0:
                zero_run = True
            elif sign != 0:
                zero_run = False
            prev = sign

    # Floor of the contact.
    if kind == "t_from":
        x = max(mpf(0), loc0.g + loc0.sigma0)
        delays = [(x / abs(ck)) ** (mpf(1) / k) for k, ck in enumerate(c_first) if k and ck < 0]
        floor = EPS * abs(t_from) + (min(delays) if delays else mpf(0))
    elif kind == "jump":
        floor = jump_floor(problem, t_unb)
    elif kind == "root":
        floor = root_floor(problem, t_unb, entry_window[1] == 0, reasons)
    else:
        floor = mpf(0)

    # Ambiguity.
    tmax_mp = mpf(t_max)
    near_touch = abs(loc0.g) <= band0
    for cr_ in relevant_crits(crits, t_from, t_unb, tmax_mp, near_touch, kind == "t_from"):
        if abs(cr_.g) <= cr_.band:
            reasons.append("graze")
            break
    if touch_ambiguous(loc0, c_first, band0):
        reasons.append("touch_t0")
    if t_unb < INF and tmax_mp < INF:
        if abs(t_unb - tmax_mp) <= max(GRAZE_DELTA * tmax_mp, BAND_FACTOR * floor):
            reasons.append("t_max")
    t = t_unb if hit_before(problem, t_unb, kind, tmax_mp) else INF
    if t == INF:
        floor = mpf(0)
    return Result(t, t_unb, floor, bool(reasons), kind, reasons)


def boundary_crits(problem: Problem, b: mpf) -> list[Crit]:
    """The one-sided values of g at a segment start b that are not part of a crossing."""
    left = problem.local(b, False)
    right = problem.local(b, True)
    bl, br = problem.band(left), problem.band(right)
    gl, gr = left.g, right.g
    out = []
    falling_l = left.sign_g1() < 0
    falling_r = right.sign_g1() < 0
    if not (falling_l and (gr < -br or (abs(gr) <= br and falling_r))):
        out.append(Crit(b, gl, bl))
    if not (falling_r and (gl > bl or (abs(gl) <= bl and falling_l))):
        out.append(Crit(b, gr, br))
    return out


def root_floor(problem: Problem, t: mpf, at_start: bool, reasons: list[str]) -> mpf:
    """sigma_g / |g'| + eps |t| at an entry root (both sides at a segment start)."""
    sides = [problem.local(t, True)]
    if at_start:
        left = problem.local(t, False)
        if left.sign_g1() < 0:
            sides.append(left)
    floor = mpf(0)
    for loc in sides:
        if loc.sign_g1() == 0:
            reasons.append("flat_entry")
            return INF
        floor = max(floor, loc.sigma0 / abs(loc.g1))
    return floor + EPS * abs(t)


def jump_floor(problem: Problem, b: mpf) -> mpf:
    """Floor of a jump into overlap at the segment start b (see the docstring)."""
    n = sum(1 for path in (problem.a, problem.b) if b in path.starts())
    floor = EPS * abs(b) * (1 + n)
    left = problem.local(b, False)
    right = problem.local(b, True)
    if left.sign_g1() < 0:
        floor += max(mpf(0), left.sigma0 - left.g) / abs(left.g1)
    if right.sign_g1() < 0:
        floor += max(mpf(0), right.g + right.sigma0) / abs(right.g1)
    return floor


def relevant_crits(
    crits: list[Crit], t_from: mpf, t_unb: mpf, t_max: mpf, near_touch: bool, at_from: bool
) -> list[Crit]:
    """Critical values whose sign decides the answer (see the docstring)."""
    out = [c for c in crits if t_from < c.t < t_unb and c.t <= t_max]
    if t_unb < t_max and (not at_from or near_touch):
        after = [c for c in crits if c.t >= t_unb and c.t > t_from]
        if after:
            first = min(c.t for c in after)
            out.extend(c for c in after if c.t == first)
    return out


def touch_ambiguous(loc: Local, c_first: list[mpf], band0: mpf) -> bool:
    """Touching or overlapping at t_from while moving tangentially (docstring rule 2)."""
    if len(c_first) <= 1 or loc.g > band0:
        return False
    norm = lambda v: mp.sqrt(dot(v, v))  # noqa: E731
    dn, d1n, d2n = norm(loc.d), norm(loc.d1), norm(loc.d2)
    h1 = loc.g1 / 2
    h2 = loc.g2 / 2
    band1 = max(GRAZE_DELTA * dn * d1n, BAND_FACTOR * loc.sigma1 / 2)
    band2 = GRAZE_DELTA * (d1n * d1n + dn * d2n)
    if abs(h1) > band1:
        return False
    if band1 == 0:
        return abs(h2) <= band2
    return not h2 < -band2


def hit_before(problem: Problem, t_unb: mpf, kind: str, t_max: mpf) -> bool:
    """True if the collision at t_unb is strictly before t_max.

    Jumps and t_from hits are at exact inputs and compare exactly; for a root
    that agrees with t_max to the root accuracy the sign of g(t_max) decides
    (g decreases through a non-flat entry): g(t_max) ~ 0 is a tie, i.e. none.
    """
    if t_unb == INF or t_max == INF or kind != "root":
        return t_unb < t_max
    if abs(t_unb - t_max) > mp.ldexp(t_max, -(ROOT_BITS - 4)):
        return t_unb < t_max
    loc = problem.local(t_max, True)
    return loc.g < -mp.ldexp(loc.scale0, -ZERO_BITS)


# ---------------------------------------------------------------------------
# Formatting and parsing
# ---------------------------------------------------------------------------


@dataclass(frozen=True)
class Case:
    """Generated inputs of one case.

    t_max_rule, if set, is (relative_offset, fallback): t_max is chosen once
    the unbounded collision time t_u is known, as float(t_u) * (1 + offset)
    (offset 0: t_u rounded to float64); fallback is used when there is no
    collision or it is at t_from.  meta holds generator data that is not
    written (the seed-model balls, for the cross-check with
    collision_reference).
    """

    category: str
    dim: int
    a: Path
    b: Path
    radius: float
    t_max: float = math.inf
    t_max_rule: tuple[float, float] | None = None
    meta: tuple | None = field(default=None, compare=False)


@dataclass(frozen=True)
class ParsedCase:
    """One line of the data file (see the module docstring)."""

    category: str
    dim: int
    a: Path
    b: Path
    radius: float
    t_max: float
    t_ref: float
    floor: float
    ambiguous: bool


def seg_fields(seg: Segment) -> list[str]:
    """s p v a of one segment as text."""
    s, p, v, a = seg
    return [fmt(x) for x in (s, *p, *v, *a)]


def format_line(case: Case, result: Result) -> str:
    """One output line."""
    fields = [case.category, str(case.dim), str(len(case.a)), str(len(case.b))]
    for seg in (*case.a, *case.b):
        fields += seg_fields(seg)
    fields += [fmt(case.radius), fmt(case.t_max), fmt(mp_to_float(result.t))]
    fields += [fmt_floor(result.floor), "1" if result.ambiguous else "0"]
    return " ".join(fields)


def parse_line(line: str) -> ParsedCase:
    """Parse one data line (raises ValueError on a malformed line)."""
    tok = line.split()
    category, dim, ka, kb = tok[0], int(tok[1]), int(tok[2]), int(tok[3])
    width = 1 + 3 * dim
    expected = 4 + (ka + kb) * width + 5
    if len(tok) != expected:
        raise ValueError(f"expected {expected} fields, got {len(tok)}")
    nums = [float(x) for x in tok[4:]]
    segs = []
    for k in range(ka + kb):
        r = nums[k * width : (k + 1) * width]
        segs.append(
            (r[0], tuple(r[1 : 1 + dim]), tuple(r[1 + dim : 1 + 2 * dim]), tuple(r[1 + 2 * dim :]))
        )
    radius, t_max, t_ref, floor, amb = nums[(ka + kb) * width :]
    if amb not in (0.0, 1.0):
        raise ValueError("ambiguous must be 0 or 1")
    return ParsedCase(
        category, dim, tuple(segs[:ka]), tuple(segs[ka:]), radius, t_max, t_ref, floor, amb == 1
    )


def read_cases(path: str) -> list[ParsedCase]:
    """All cases of a data file written by this script."""
    out = []
    with open(path, encoding="ascii") as fh:
        for line in fh:
            if line.startswith("#") or not line.strip():
                continue
            out.append(parse_line(line))
    return out


# ---------------------------------------------------------------------------
# Case generation (float64 only: it merely invents inputs)
# ---------------------------------------------------------------------------


def vadd(a: Vec, b: Vec) -> Vec:
    """a + b."""
    return tuple(x + y for x, y in zip(a, b))


def vsub(a: Vec, b: Vec) -> Vec:
    """a - b."""
    return tuple(x - y for x, y in zip(a, b))


def vscale(s: float, a: Vec) -> Vec:
    """s * a."""
    return tuple(s * x for x in a)


def vnorm(a: Vec) -> float:
    """|a|."""
    return math.hypot(*a)


def vdot(a: Vec, b: Vec) -> float:
    """a . b."""
    return sum(x * y for x, y in zip(a, b))


def zeros(dim: int) -> Vec:
    """The zero vector."""
    return (0.0,) * dim


def log_uniform(rng: random.Random, lo_exp: float, hi_exp: float) -> float:
    """10 ** U(lo_exp, hi_exp)."""
    return 10.0 ** rng.uniform(lo_exp, hi_exp)


def rand_unit(rng: random.Random, dim: int) -> Vec:
    """Uniformly random unit vector."""
    if dim == 2:
        th = rng.uniform(0.0, 2.0 * math.pi)
        return math.cos(th), math.sin(th)
    while True:
        v = tuple(rng.gauss(0.0, 1.0) for _ in range(dim))
        n = vnorm(v)
        if n > 1e-3:
            return vscale(1.0 / n, v)


def axis_unit(rng: random.Random, dim: int) -> Vec:
    """A random signed coordinate axis."""
    j = rng.randrange(dim)
    return tuple(rng.choice((-1.0, 1.0)) if i == j else 0.0 for i in range(dim))


def perp_unit(rng: random.Random, w: Vec) -> Vec:
    """A random unit vector perpendicular to w (w != 0)."""
    wn = vnorm(w)
    u = vscale(1.0 / wn, w)
    if len(w) == 2:
        side = rng.choice((-1.0, 1.0))
        return -side * u[1], side * u[0]
    while True:
        r = rand_unit(rng, 3)
        q = vsub(r, vscale(vdot(r, u), u))
        n = vnorm(q)
        if n > 1e-3:
            return vscale(1.0 / n, q)


def rand_vec(rng: random.Random, dim: int, lo: float, hi: float) -> Vec:
    """Random direction, magnitude U(lo, hi)."""
    return vscale(rng.uniform(lo, hi), rand_unit(rng, dim))


def seg_index(path: Path, t: float) -> int:
    """Float version of the active-segment rule (from the right)."""
    k = 0
    for i, seg in enumerate(path):
        if seg[0] <= t:
            k = i
    return k


def advance(p: Vec, v: Vec, a: Vec, tau: float) -> Vec:
    """p + v tau + a tau^2 / 2 in float, as a simulator computes it."""
    return tuple(pj + vj * tau + 0.5 * aj * tau * tau for pj, vj, aj in zip(p, v, a))


def f_pos(path: Path, t: float) -> Vec:
    """Float position on a path."""
    s, p, v, a = path[seg_index(path, t)]
    return advance(p, v, a, t - s)


def f_vel(path: Path, t: float) -> Vec:
    """Float velocity on a path."""
    s, _, v, a = path[seg_index(path, t)]
    return tuple(vj + aj * (t - s) for vj, aj in zip(v, a))


def translate(path: Path, shift: Vec) -> Path:
    """Every segment position moved by shift (float adds)."""
    return tuple((s, vadd(p, shift), v, a) for s, p, v, a in path)


def scale_path(path: Path, k: float) -> Path:
    """All lengths scaled by k (times unchanged)."""
    return tuple((s, vscale(k, p), vscale(k, v), vscale(k, a)) for s, p, v, a in path)


def embed3(path: Path, z: float) -> Path:
    """A 2-D path on the plane z (vz = az = 0)."""
    return tuple((s, (*p, z), (*v, 0.0), (*a, 0.0)) for s, p, v, a in path)


def last_start(path: Path) -> float:
    """Start of the last segment."""
    return path[-1][0]


def clean_path(path: Path) -> Path:
    """No -0.0 anywhere (x + 0.0)."""
    return tuple(
        (s + 0.0, tuple(x + 0.0 for x in p), tuple(x + 0.0 for x in v), tuple(x + 0.0 for x in a))
        for s, p, v, a in path
    )


def make_case(
    category: str,
    rng: random.Random,
    dim: int,
    a: Path,
    b: Path,
    radius: float,
    t_max: float = math.inf,
    t_max_rule: tuple[float, float] | None = None,
    meta: tuple | None = None,
    swap: bool = True,
) -> Case:
    """Assemble a Case; A and B are swapped with probability 1/2 if `swap`."""
    if swap and rng.random() < 0.5:
        a, b = b, a
        if meta is not None:
            meta = (meta[1], meta[0], *meta[2:])
    return Case(category, dim, clean_path(a), clean_path(b), radius, t_max, t_max_rule, meta)


def impact_offset(rng: random.Random, w: Vec, beta: float, radius: float) -> Vec:
    """d = x_A - x_B at the aimed time for impact parameter beta * radius.

    beta < 1: a contact on the approaching side (d . w < 0); beta >= 1: side by
    side at distance beta * radius.
    """
    dim = len(w)
    wn = vnorm(w)
    if wn == 0.0:
        return vscale(radius * max(beta, 1.05), rand_unit(rng, dim))
    uw = vscale(1.0 / wn, w)
    n = perp_unit(rng, w)
    if beta < 1.0:
        c = math.sqrt(1.0 - beta * beta)
        return vscale(radius, vsub(vscale(beta, n), vscale(c, uw)))
    return vscale(radius * beta, n)


def graze_offset(rng: random.Random, w: Vec, delta: float, radius: float) -> Vec:
    """d at the aimed time: length R (1 + delta), perpendicular to d' = w."""
    dist = radius * (1.0 + delta)
    if vnorm(w) == 0.0:
        return vscale(dist, rand_unit(rng, len(w)))
    return vscale(dist, perp_unit(rng, w))


def aim(a: Path, b: Path, t_c: float, d: Vec) -> Path:
    """A translated so that x_A(t_c) - x_B(t_c) = d (in float)."""
    shift = vsub(vadd(f_pos(b, t_c), d), f_pos(a, t_c))
    return translate(a, shift)


def rel_vel(a: Path, b: Path, t: float) -> Vec:
    """Float velocity of A relative to B at t."""
    return vsub(f_vel(a, t), f_vel(b, t))


# --- billiard balls ----------------------------------------------------------


@dataclass(frozen=True)
class BallState:
    """A pooltool-style state: translational velocity and angular velocity."""

    kind: str  # "sliding", "rolling" or "rest"
    v: Vec
    w: tuple[float, float, float]


def pool_state(rng: random.Random, rest_prob: float = 0.0, roll_prob: float = 0.3) -> BallState:
    """Random state: at rest, rolling, or sliding with the slip at any angle to v."""
    if rng.random() < rest_prob:
        return BallState("rest", (0.0, 0.0), (0.0, 0.0, rng.uniform(-30, 30)))
    v = rand_vec(rng, 2, 0.05, 3.0)
    if rng.random() < roll_prob:
        return BallState("rolling", v, (-v[1] / BALL_R, v[0] / BALL_R, 0.0))
    sp = vnorm(v)
    phi = rng.uniform(0.0, 2.0 * math.pi)
    un = rng.uniform(0.02, 1.5) * max(sp, 0.3)
    c, s = math.cos(phi), math.sin(phi)
    u = (un * (c * v[0] - s * v[1]) / sp, un * (s * v[0] + c * v[1]) / sp)
    w = ((u[1] - v[1]) / BALL_R, (v[0] - u[0]) / BALL_R, rng.uniform(-30, 30))
    return BallState("sliding", v, w)


def pool_path(t0: float, p: Vec, st: BallState, slide_acc: Vec | None = None) -> Path:
    """Sliding -> rolling -> rest from a state, in float64 as a simulator would.

    Sliding: slip u = v + w x (-R z) = (vx - R wy, vy + R wx), acceleration
    -u_s g u/|u| for 2 |u| / (7 u_s g); rolling: -u_r g v/|v| for |v| / (u_r g).
    slide_acc overrides the sliding acceleration (equal-acceleration cases).
    """
    segs: list[Segment] = []
    t = t0
    v = st.v
    ug = U_SLIDE * GRAVITY
    rg = U_ROLL * GRAVITY
    if st.kind == "sliding":
        u = (v[0] - BALL_R * st.w[1], v[1] + BALL_R * st.w[0])
        un = vnorm(u)
        if un > 0.0:
            acc = slide_acc if slide_acc is not None else (-ug * u[0] / un, -ug * u[1] / un)
            tau = 2.0 * un / (7.0 * ug)
            segs.append((t, p, v, acc))
            p = advance(p, v, acc, tau)
            v = (v[0] + acc[0] * tau, v[1] + acc[1] * tau)
            t = t + tau
    sp = vnorm(v)
    if st.kind != "rest" and sp > 0.0:
        acc = (-rg * v[0] / sp, -rg * v[1] / sp)
        tau = sp / rg
        segs.append((t, p, v, acc))
        p = advance(p, v, acc, tau)
        t = t + tau
    segs.append((t, p, (0.0, 0.0), (0.0, 0.0)))
    return tuple(segs)


def table_point(rng: random.Random) -> Vec:
    """Uniform point on the 2.54 m x 1.27 m table."""
    return rng.uniform(0.0, TABLE_W), rng.uniform(0.0, TABLE_H)


def aimed_pool(
    rng: random.Random, t0a: float = 0.0, t0b: float = 0.0, beta: float | None = None
) -> tuple[Path, Path, float]:
    """A random aimed pool shot: contact near a random time while A moves."""
    sa = pool_state(rng)
    sb = pool_state(rng, rest_prob=0.3)
    a = pool_path(t0a, (0.0, 0.0), sa)
    b = pool_path(t0b, table_point(rng), sb)
    t_from = max(t0a, t0b)
    end = max(last_start(a), t_from + 0.05)
    t_c = t_from + rng.uniform(0.01, 0.95) * (end - t_from)
    beta = rng.uniform(0.0, 1.2) if beta is None else beta
    d = impact_offset(rng, rel_vel(a, b, t_c), beta, CONTACT)
    return aim(a, b, t_c, d), b, t_c


# --- general paths ----------------------------------------------------------


def random_path(
    rng: random.Random,
    dim: int,
    t0: float,
    k: int,
    first: tuple[Vec, Vec, Vec] | None = None,
    jump_prob: float = 0.0,
    rest_last: float = 0.2,
) -> Path:
    """k segments of random constant accelerations, positions continuous (float).

    Velocities get random kicks at segment starts; with jump_prob a position
    jumps by up to 0.1; 5 % of the segments are empty.
    """
    if first is None:
        p = tuple(rng.uniform(0.0, 2.0) for _ in range(dim))
        v = rand_vec(rng, dim, 0.0, 3.0)
        acc = zeros(dim) if rng.random() < 0.2 else rand_vec(rng, dim, 0.0, 8.0)
    else:
        p, v, acc = first
    segs: list[Segment] = []
    t = t0
    for i in range(k):
        segs.append((t, p, v, acc))
        if i == k - 1:
            break
        dt = 0.0 if rng.random() < 0.05 else rng.uniform(0.05, 1.0)
        p = advance(p, v, acc, dt)
        v = tuple(vj + aj * dt for vj, aj in zip(v, acc))
        if rng.random() < jump_prob:
            p = vadd(p, rand_vec(rng, dim, 0.0, 0.1))
        t = t + dt
        if i == k - 2 and rng.random() < rest_last:
            v, acc = zeros(dim), zeros(dim)
            continue
        if rng.random() < 0.5:
            v = vadd(v, rand_vec(rng, dim, 0.0, 2.0))
        acc = zeros(dim) if rng.random() < 0.2 else rand_vec(rng, dim, 0.0, 8.0)
    return tuple(segs)


def aimed_general(
    rng: random.Random,
    dim: int,
    radius: float,
    t0a: float = 0.0,
    t0b: float = 0.0,
    beta: float | None = None,
    graze: float | None = None,
) -> tuple[Path, Path, float]:
    """Two random general paths, A aimed at B at a random time."""
    a = random_path(rng, dim, t0a, rng.randint(1, 4))
    b = random_path(rng, dim, t0b, rng.randint(1, 4))
    t_from = max(t0a, t0b)
    end = max(last_start(a), last_start(b), t_from) + 1.0
    t_c = t_from + rng.uniform(0.02, 1.0) * (end - t_from)
    w = rel_vel(a, b, t_c)
    if graze is not None:
        d = graze_offset(rng, w, graze, radius)
    else:
        d = impact_offset(rng, w, rng.uniform(0.0, 1.2) if beta is None else beta, radius)
    return aim(a, b, t_c, d), b, t_c


def bounce_path(
    rng: random.Random, dim: int, t0: float, k: int, gravity: bool, box: float = 1.0
) -> Path:
    """A particle bouncing in [0, box]^dim: k segments, reflected velocity at walls.

    With gravity the last axis accelerates at -9.81 and only its floor reflects.
    Positions are continuous (float formula at the wall time).
    """
    p = tuple(rng.uniform(0.1, 0.9) * box for _ in range(dim))
    v = rand_vec(rng, dim, 0.3, 3.0)
    acc = (*zeros(dim - 1), -GRAVITY) if gravity else zeros(dim)
    segs: list[Segment] = []
    t = t0
    for i in range(k):
        segs.append((t, p, v, acc))
        if i == k - 1:
            break
        best, axis = math.inf, -1
        for j in range(dim):
            if gravity and j == dim - 1:
                disc = v[j] * v[j] + 2.0 * GRAVITY * max(p[j], 0.0)
                dt = (v[j] + math.sqrt(disc)) / GRAVITY
            elif v[j] > 0:
                dt = (box - p[j]) / v[j]
            elif v[j] < 0:
                dt = -p[j] / v[j]
            else:
                dt = math.inf
            if 1e-12 < dt < best:
                best, axis = dt, j
        if axis < 0:
            break
        p = advance(p, v, acc, best)
        v = tuple(vj + aj * best for vj, aj in zip(v, acc))
        v = tuple(-x if j == axis else x for j, x in enumerate(v))
        t = t + best
    return tuple(segs)


def airborne_path(t0: float, p: Vec, v: Vec) -> Path:
    """A ball in the air (z > R) under gravity, bouncing on the cloth, then rolling.

    Landing when z = R (float formula); restitution 0.5; below 0.3 m/s upwards
    it stays on the cloth (z snapped to R) and rolls, then rests.
    """
    acc = (0.0, 0.0, -GRAVITY)
    segs: list[Segment] = []
    t = t0
    for _ in range(3):
        segs.append((t, p, v, acc))
        h = p[2] - BALL_R
        dt = (v[2] + math.sqrt(v[2] * v[2] + 2.0 * GRAVITY * max(h, 0.0))) / GRAVITY
        p = advance(p, v, acc, dt)
        vz = -0.5 * (v[2] - GRAVITY * dt)
        t = t + dt
        v = (v[0], v[1], vz)
        if vz < 0.3:
            break
        p = (p[0], p[1], BALL_R)
    st = BallState("rolling", (v[0], v[1]), (0.0, 0.0, 0.0))
    rest = embed3(pool_path(t, (p[0], p[1]), st), BALL_R)
    return (*segs, *rest)


# --- categories -------------------------------------------------------------


def gen_pool_random(rng: random.Random, n: int) -> list[Case]:
    """Two billiard balls anywhere on the table (3/4: B within 0.3 m of A)."""
    out = []
    for i in range(n):
        pa = table_point(rng)
        while True:
            if i % 4:
                pb = vadd(pa, rand_vec(rng, 2, 0.0, 0.3))
            else:
                pb = table_point(rng)
            if math.dist(pa, pb) > 1.001 * CONTACT:
                break
        a = pool_path(0.0, pa, pool_state(rng))
        b = pool_path(0.0, pb, pool_state(rng, rest_prob=0.2))
        out.append(make_case("pool_random", rng, 2, a, b, CONTACT))
    return out


def gen_pool_aimed(rng: random.Random, n: int) -> list[Case]:
    """Aimed billiard shots, impact parameter U(0, 1.2) R, while A moves."""
    out = []
    for _ in range(n):
        a, b, _ = aimed_pool(rng)
        out.append(make_case("pool_aimed", rng, 2, a, b, CONTACT))
    return out


def gen_chasing(rng: random.Random, n: int) -> list[Case]:
    """Equal accelerations: two balls rolling one way, or under one acceleration vector.

    50 %: both roll along e (axis or random) with the same acceleration -u_r g e,
    speeds in ratio 2^-k or equal (side by side; some exactly touching: no
    contact); 30 %: one constant acceleration vector for both, 2-D or 3-D,
    forever; 20 %: both slide with the same acceleration, then roll apart.
    """
    out = []
    rg = U_ROLL * GRAVITY
    for _ in range(n):
        r = rng.random()
        if r < 0.5:
            e = axis_unit(rng, 2) if rng.random() < 0.4 else rand_unit(rng, 2)
            acc = (-rg * e[0], -rg * e[1])
            sa = rng.uniform(0.3, 3.0)
            k = rng.choice((0, 0, 1, 2, 3))
            sb = sa * 2.0**-k
            va, vb = vscale(sa, e), vscale(sb, e)
            pb = table_point(rng)
            a = (
                (0.0, (0.0, 0.0), va, acc),
                (sa / rg, advance((0.0, 0.0), va, acc, sa / rg), (0.0, 0.0), (0.0, 0.0)),
            )
            b = (
                (0.0, pb, vb, acc),
                (sb / rg, advance(pb, vb, acc, sb / rg), (0.0, 0.0), (0.0, 0.0)),
            )
            if k == 0 and rng.random() < 0.4:
                # Side by side, exactly touching along an axis perpendicular to e.
                side = (-e[1], e[0]) if rng.random() < 0.5 else (e[1], -e[0])
                a = translate(a, vadd(pb, vscale(CONTACT, side)))
                radius = CONTACT
                if e[0] == 0.0 or e[1] == 0.0:
                    radius = vnorm(vsub(a[0][1], pb))
                out.append(make_case("chasing_equal_acc", rng, 2, a, b, radius))
                continue
            t_c = rng.uniform(0.02, 0.95) * sb / rg
            d = impact_offset(rng, rel_vel(a, b, t_c), rng.uniform(0.0, 1.2), CONTACT)
            out.append(make_case("chasing_equal_acc", rng, 2, aim(a, b, t_c, d), b, CONTACT))
        elif r < 0.8:
            dim = rng.choice((2, 3))
            acc = rand_vec(rng, dim, 0.1, 10.0)
            t0a, t0b = rng.uniform(0.0, 1.0), rng.uniform(0.0, 1.0)
            a = ((t0a, zeros(dim), rand_vec(rng, dim, 0.0, 3.0), acc),)
            b = ((t0b, rand_vec(rng, dim, 0.0, 2.0), rand_vec(rng, dim, 0.0, 3.0), acc),)
            radius = rng.uniform(0.05, 0.3)
            t_c = max(t0a, t0b) + rng.uniform(0.01, 2.0)
            d = impact_offset(rng, rel_vel(a, b, t_c), rng.uniform(0.0, 1.2), radius)
            out.append(make_case("chasing_equal_acc", rng, dim, aim(a, b, t_c, d), b, radius))
        else:
            sa, sb = pool_state(rng, roll_prob=0.0), pool_state(rng, roll_prob=0.0)
            u = rand_unit(rng, 2)
            acc = vscale(-U_SLIDE * GRAVITY, u)
            a = pool_path(0.0, (0.0, 0.0), sa, slide_acc=acc)
            b = pool_path(0.0, table_point(rng), sb, slide_acc=acc)
            t_c = rng.uniform(0.01, 1.0) * min(a[1][0], b[1][0])
            d = impact_offset(rng, rel_vel(a, b, t_c), rng.uniform(0.0, 1.2), CONTACT)
            out.append(make_case("chasing_equal_acc", rng, 2, aim(a, b, t_c, d), b, CONTACT))
    return out


def gen_arbitrary(rng: random.Random, n: int) -> list[Case]:
    """1-4 segments of random accelerations each, 2-D or 3-D, aimed (or not)."""
    out = []
    for _ in range(n):
        dim = rng.choice((2, 3))
        radius = rng.uniform(0.05, 0.3)
        t0a, t0b = rng.choice((0.0, rng.uniform(0.0, 1.0))), rng.uniform(0.0, 1.0)
        a, b, _ = aimed_general(rng, dim, radius, t0a, t0b)
        out.append(make_case("arbitrary_acc", rng, dim, a, b, radius))
    return out


def gen_near_start(rng: random.Random, n: int) -> list[Case]:
    """Billiard contacts 1e-9..1e-3 s before or after a segment start of A or B."""
    out = []
    for _ in range(n):
        a = pool_path(0.0, (0.0, 0.0), pool_state(rng, roll_prob=0.0))
        b = pool_path(0.0, table_point(rng), pool_state(rng, rest_prob=0.2))
        # Mostly the slide -> roll starts (velocity continuous, not small).
        moving = [seg[0] for seg in (*a[1:], *b[1:]) if vnorm(seg[2]) > 0.0]
        starts = moving if moving and rng.random() < 0.75 else [x[0] for x in (*a[1:], *b[1:])]
        s = rng.choice(starts)
        t_c = s + rng.choice((-1, 1)) * log_uniform(rng, -9, -3)
        if t_c <= 0:
            t_c = s + log_uniform(rng, -9, -3)
        beta = rng.uniform(0.0, 0.95) if rng.random() < 0.85 else rng.uniform(1.0, 1.2)
        d = impact_offset(rng, rel_vel(a, b, t_c), beta, CONTACT)
        out.append(make_case("near_segment_start", rng, 2, aim(a, b, t_c, d), b, CONTACT))
    return out


def gen_late_start(rng: random.Random, n: int) -> list[Case]:
    """First starts ~ 1e4 s, the two paths starting up to 5 s apart (billiards, general)."""
    out = []
    for _ in range(n):
        t0a = rng.uniform(5e3, 2e4)
        t0b = t0a + rng.choice((-1, 1)) * rng.uniform(0.0, 5.0)
        if rng.random() < 0.7:
            a, b, _ = aimed_pool(rng, t0a, t0b)
            out.append(make_case("late_start", rng, 2, a, b, CONTACT))
        else:
            dim = rng.choice((2, 3))
            radius = rng.uniform(0.05, 0.3)
            a, b, _ = aimed_general(rng, dim, radius, t0a, t0b)
            out.append(make_case("late_start", rng, dim, a, b, radius))
    return out


def gen_bouncing(rng: random.Random, n: int) -> list[Case]:
    """Particles bouncing in a unit box, 4-8 segments each (half: B aimed at A)."""
    out = []
    for _ in range(n):
        dim = rng.choice((2, 3))
        gravity = rng.random() < 0.3
        radius = rng.uniform(0.03, 0.15)
        t0a, t0b = 0.0, rng.choice((0.0, rng.uniform(0.0, 0.5)))
        a = bounce_path(rng, dim, t0a, rng.randint(4, 8), gravity)
        b = bounce_path(rng, dim, t0b, rng.randint(4, 8), gravity)
        if rng.random() < 0.5:
            t_from = max(t0a, t0b)
            t_c = rng.uniform(t_from, max(last_start(a), last_start(b), t_from + 0.1))
            d = impact_offset(rng, rel_vel(b, a, t_c), rng.uniform(0.0, 1.2), radius)
            b = aim(b, a, t_c, d)
        out.append(make_case("bouncing", rng, dim, a, b, radius))
    return out


def seed_ball_path(p: Vec, v: Vec, mu: float) -> Path:
    """The seed's friction ball as a path, formed in float64 (SPEC)."""
    sp = vnorm(v)
    if sp == 0.0:
        return ((0.0, p, (0.0, 0.0), (0.0, 0.0)),)
    if mu == 0.0:
        return ((0.0, p, v, (0.0, 0.0)),)
    u = (v[0] / sp, v[1] / sp)
    tau = sp / mu
    rest = (p[0] + 0.5 * v[0] * tau, p[1] + 0.5 * v[1] * tau)
    return ((0.0, p, v, (-mu * u[0], -mu * u[1])), (tau, rest, (0.0, 0.0), (0.0, 0.0)))


def gen_seed_friction(rng: random.Random, n: int) -> list[Case]:
    """Seed-model balls (p, v, mu) written as paths; meta keeps the balls.

    Half random pairs on the table, half A aimed at B while A moves; 10 % of
    the balls frictionless, 20 % of the B balls at rest.
    """
    out = []
    for i in range(n):
        balls = []
        for j in range(2):
            if j == 1 and rng.random() < 0.2:
                v: Vec = (0.0, 0.0)
            else:
                v = rand_vec(rng, 2, 0.05, 3.0)
            mu = 0.0 if rng.random() < 0.1 else rng.uniform(0.05, 2.0)
            balls.append([table_point(rng), v, mu])
        (pa, va, fa), (pb, vb, fb) = balls
        if i % 2:
            a0 = seed_ball_path((0.0, 0.0), va, fa)
            b = seed_ball_path(pb, vb, fb)
            end = last_start(a0) if fa > 0 else 3.0
            t_c = rng.uniform(0.02, 0.95) * end
            d = impact_offset(rng, rel_vel(a0, b, t_c), rng.uniform(0.0, 1.2), CONTACT)
            pa = vsub(vadd(f_pos(b, t_c), d), f_pos(a0, t_c))
        a = seed_ball_path(pa, va, fa)
        b = seed_ball_path(pb, vb, fb)
        meta = ((pa, va, fa), (pb, vb, fb))
        out.append(make_case("seed_friction", rng, 2, a, b, CONTACT, meta=meta))
    return out


def gen_airborne(rng: random.Random, n: int) -> list[Case]:
    """3-D: a ball in the air landing on, or passing over, a ball on the cloth."""
    out = []
    for _ in range(n):
        pz = BALL_R + rng.uniform(0.0, 0.3)
        v = (*rand_vec(rng, 2, 0.2, 3.0), rng.uniform(-1.0, 2.5))
        a = airborne_path(0.0, (0.0, 0.0, pz), v)
        st = pool_state(rng, rest_prob=0.5)
        b = embed3(
            pool_path(rng.choice((0.0, rng.uniform(0.0, 0.2))), table_point(rng), st), BALL_R
        )
        t_from = max(a[0][0], b[0][0])
        t_c = t_from + rng.uniform(0.1, 1.0) * max(a[1][0] - t_from, 0.01)
        xa, xb = f_pos(a, t_c), f_pos(b, t_c)
        dz = xa[2] - xb[2]
        w = rel_vel(a, b, t_c)
        wxy = (w[0], w[1])
        wn = vnorm(wxy) or 1.0
        ang = rng.uniform(-1.0, 1.0)
        c, s = math.cos(ang), math.sin(ang)
        dirn = (-(c * wxy[0] - s * wxy[1]) / wn, -(s * wxy[0] + c * wxy[1]) / wn)
        if dz < CONTACT:
            h = math.sqrt(CONTACT * CONTACT - dz * dz) * rng.uniform(0.0, 1.3)
        else:
            h = CONTACT * rng.uniform(0.0, 1.0)
        shift = (xb[0] + h * dirn[0] - xa[0], xb[1] + h * dirn[1] - xa[1], 0.0)
        out.append(make_case("airborne_3d", rng, 3, translate(a, shift), b, CONTACT))
    return out


def gen_gravity(rng: random.Random, n: int) -> list[Case]:
    """3-D particles under the same gravity, some bouncing on the floor z = 0.

    60 % aimed, 20 % random, 20 % falling together (equal velocities, some
    exactly touching): no contact.
    """
    out = []
    acc = (0.0, 0.0, -GRAVITY)
    for _ in range(n):
        radius = rng.uniform(0.05, 0.2)
        t0a, t0b = rng.uniform(0.0, 1.0), rng.uniform(0.0, 1.0)
        r = rng.random()
        va, vb = rand_vec(rng, 3, 0.0, 3.0), rand_vec(rng, 3, 0.0, 3.0)
        if r < 0.2:
            t0b = t0a
            vb = va
        pa = (rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0.5, 2.0))
        pb = (rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0.5, 2.0))
        if r < 0.1:
            pb = vadd(pa, vscale(radius, axis_unit(rng, 3)))
        a = falling_path(t0a, pa, va, acc, rng.randint(1, 3))
        b = falling_path(t0b, pb, vb, acc, rng.randint(1, 3))
        if r >= 0.4:
            t_from = max(t0a, t0b)
            t_c = t_from + rng.uniform(0.01, 1.0) * max(a[-1][0] - t_from, 0.3)
            d = impact_offset(rng, rel_vel(a, b, t_c), rng.uniform(0.0, 1.2), radius)
            a = aim(a, b, t_c, d)
        out.append(make_case("gravity_3d", rng, 3, a, b, radius))
    return out


def falling_path(t0: float, p: Vec, v: Vec, acc: Vec, k: int) -> Path:
    """k parabolic segments bouncing on z = 0 (restitution 0.8, float64)."""
    segs: list[Segment] = []
    t = t0
    for i in range(k):
        segs.append((t, p, v, acc))
        if i == k - 1:
            break
        dt = (v[2] + math.sqrt(v[2] * v[2] + 2.0 * GRAVITY * max(p[2], 0.0))) / GRAVITY
        p = advance(p, v, acc, dt)
        v = (v[0], v[1], -0.8 * (v[2] - GRAVITY * dt))
        t = t + dt
    return tuple(segs)


def gen_grazing(rng: random.Random, n: int) -> list[Case]:
    """Closest approach R (1 + delta), |delta| = 1e-12..1e-3: billiards, general, gravity."""
    out = []
    for _ in range(n):
        delta = rng.choice((-1, 1)) * log_uniform(rng, -12, -3)
        r = rng.random()
        if r < 0.5:
            a = pool_path(0.0, (0.0, 0.0), pool_state(rng))
            b = pool_path(0.0, table_point(rng), pool_state(rng, rest_prob=0.3))
            t_c = rng.uniform(0.01, 0.95) * last_start(a)
            d = graze_offset(rng, rel_vel(a, b, t_c), delta, CONTACT)
            out.append(make_case("grazing", rng, 2, aim(a, b, t_c, d), b, CONTACT))
        else:
            dim = rng.choice((2, 3))
            radius = rng.uniform(0.05, 0.3)
            a, b, _ = aimed_general(rng, dim, radius, 0.0, rng.uniform(0.0, 1.0), graze=delta)
            out.append(make_case("grazing", rng, dim, a, b, radius))
    return out


def rel_motion(rng: random.Random, e: Vec, mode: str, scale: float) -> Vec:
    """A relative velocity or acceleration along/against/across e (d = -R e)."""
    dim = len(e)
    across = perp_unit(rng, e)
    along = rng.uniform(0.05, 3.0) * scale
    side = rng.uniform(-3.0, 3.0) * scale
    if mode == "in":  # d = x_A - x_B = -R e: A moves towards B along +e
        return vadd(vscale(along, e), vscale(side, across))
    if mode == "out":
        return vadd(vscale(-along, e), vscale(side, across))
    if mode == "across":
        return vscale(side, across)
    return zeros(dim)


def gen_touching(rng: random.Random, n: int) -> list[Case]:
    """|d(t_from)| = R exactly (axis-aligned) or to rounding; approaching, separating, across.

    The relative acceleration is towards, away, across or zero, also with zero
    relative velocity (then g'' decides).  Later segments random.
    """
    out = []
    modes = ("in", "out", "across", "zero")
    weights = (0.35, 0.35, 0.15, 0.15)
    for _ in range(n):
        dim = rng.choice((2, 3))
        t0 = rng.choice((0.0, rng.uniform(0.0, 100.0)))
        radius = rng.uniform(0.05, 0.3)
        pa = tuple(rng.uniform(0.0, 2.0) for _ in range(dim))
        if rng.random() < 0.5:
            e = axis_unit(rng, dim)
            pb = vadd(pa, vscale(radius, e))
            radius = abs(sum(vsub(pb, pa)))
        else:
            e = rand_unit(rng, dim)
            pb = vadd(pa, vscale(radius, e))
        dv = rel_motion(rng, e, rng.choices(modes, weights)[0], 1.0)
        da = rel_motion(rng, e, rng.choices(modes, weights)[0], 3.0)
        vb = rand_vec(rng, dim, 0.0, 2.0) if rng.random() < 0.6 else zeros(dim)
        ab = rand_vec(rng, dim, 0.0, 5.0) if rng.random() < 0.5 else zeros(dim)
        a = random_path(rng, dim, t0, rng.randint(1, 3), first=(pa, vadd(vb, dv), vadd(ab, da)))
        b = random_path(rng, dim, t0, rng.randint(1, 3), first=(pb, vb, ab))
        out.append(make_case("touching_start", rng, dim, a, b, radius))
    return out


def gen_overlapping(rng: random.Random, n: int) -> list[Case]:
    """|d(t_from)| = R U(0.05, 0.999): approaching, separating, or separating then back."""
    out = []
    for _ in range(n):
        dim = rng.choice((2, 3))
        t0 = rng.choice((0.0, rng.uniform(0.0, 100.0)))
        radius = rng.uniform(0.05, 0.3)
        pa = tuple(rng.uniform(0.0, 2.0) for _ in range(dim))
        e = rand_unit(rng, dim)
        pb = vadd(pa, vscale(radius * rng.uniform(0.05, 0.999), e))
        r = rng.random()
        if r < 0.35:
            dv, da = (
                rel_motion(rng, e, "in", 1.0),
                rel_motion(rng, e, rng.choice(("in", "zero")), 1.0),
            )
        elif r < 0.7:
            dv, da = rel_motion(rng, e, "out", 1.0), rel_motion(rng, e, "zero", 1.0)
        else:
            dv = rel_motion(rng, e, "out", 0.3)
            da = rel_motion(rng, e, "in", 3.0)
        vb = rand_vec(rng, dim, 0.0, 2.0)
        ab = rand_vec(rng, dim, 0.0, 5.0) if rng.random() < 0.5 else zeros(dim)
        a = random_path(rng, dim, t0, rng.randint(1, 3), first=(pa, vadd(vb, dv), vadd(ab, da)))
        b = random_path(rng, dim, t0, rng.randint(1, 3), first=(pb, vb, ab))
        out.append(make_case("overlapping_start", rng, dim, a, b, radius))
    return out


def gen_unit_scale(rng: random.Random, n: int) -> list[Case]:
    """Aimed billiard or general shots with every length scaled by 2^k or 10^U(-6, 6)."""
    out = []
    for _ in range(n):
        if rng.random() < 0.5:
            dim, radius = 2, CONTACT
            a, b, _ = aimed_pool(rng)
        else:
            dim, radius = rng.choice((2, 3)), rng.uniform(0.05, 0.3)
            a, b, _ = aimed_general(rng, dim, radius)
        k = 2.0 ** rng.randint(-20, 20) if rng.random() < 0.3 else log_uniform(rng, -6, 6)
        case = make_case("unit_scale", rng, dim, scale_path(a, k), scale_path(b, k), radius * k)
        out.append(case)
    return out


def gen_horizon(rng: random.Random, n: int) -> list[Case]:
    """Finite t_max: within 1e-16..1e-2 (relative) of the contact, equal to it, or random."""
    out = []
    for _ in range(n):
        if rng.random() < 0.5:
            dim, radius = 2, CONTACT
            a, b, t_c = aimed_pool(rng, beta=rng.uniform(0.0, 1.1))
        else:
            dim, radius = rng.choice((2, 3)), rng.uniform(0.05, 0.3)
            a, b, t_c = aimed_general(rng, dim, radius, beta=rng.uniform(0.0, 1.1))
        fallback = t_c * rng.uniform(0.2, 2.0)
        r = rng.random()
        if r < 0.5:
            rule = (rng.choice((-1, 1)) * log_uniform(rng, -16, -2), fallback)
            out.append(make_case("horizon", rng, dim, a, b, radius, t_max_rule=rule))
        elif r < 0.6:
            out.append(make_case("horizon", rng, dim, a, b, radius, t_max_rule=(0.0, fallback)))
        else:
            out.append(make_case("horizon", rng, dim, a, b, radius, t_max=fallback))
    return out


def gen_jump(rng: random.Random, n: int) -> list[Case]:
    """B's position jumps at its second segment start: into overlap, to near touching, or out.

    60 %: to R U(0.1, 0.99) from A; 15 %: to R (1 +- 1e-12..1e-4); 25 %: to
    R U(1.01, 3).  Before the jump B is elsewhere (random, usually apart).
    """
    out = []
    for _ in range(n):
        dim = rng.choice((2, 3))
        radius = rng.uniform(0.05, 0.3)
        t0b = rng.choice((0.0, rng.uniform(0.0, 1.0)))
        a = random_path(rng, dim, rng.uniform(0.0, 1.0), rng.randint(1, 3))
        b = random_path(rng, dim, t0b, rng.randint(2, 4))
        s = max(b[1][0], max(a[0][0], t0b) + 1e-3)
        b = ((b[0][0], *b[0][1:]), (s, *b[1][1:]), *((max(x[0], s), *x[1:]) for x in b[2:]))
        r = rng.random()
        if r < 0.6:
            rho = rng.uniform(0.1, 0.99)
        elif r < 0.75:
            rho = 1.0 + rng.choice((-1, 1)) * log_uniform(rng, -12, -4)
        else:
            rho = rng.uniform(1.01, 3.0)
        xa = f_pos(a, s)
        pb = vadd(xa, vscale(radius * rho, rand_unit(rng, dim)))
        seg1 = (s, pb, rand_vec(rng, dim, 0.0, 3.0), b[1][3])
        b = (b[0], seg1, *b[2:])
        out.append(make_case("jump_overlap", rng, dim, a, b, radius))
    return out


CATEGORIES = (
    ("pool_random", gen_pool_random, 1500),
    ("pool_aimed", gen_pool_aimed, 1500),
    ("chasing_equal_acc", gen_chasing, 1300),
    ("arbitrary_acc", gen_arbitrary, 1400),
    ("near_segment_start", gen_near_start, 1300),
    ("late_start", gen_late_start, 1300),
    ("bouncing", gen_bouncing, 1300),
    ("seed_friction", gen_seed_friction, 1300),
    ("airborne_3d", gen_airborne, 1300),
    ("gravity_3d", gen_gravity, 1300),
    ("grazing", gen_grazing, 1300),
    ("touching_start", gen_touching, 1300),
    ("overlapping_start", gen_overlapping, 1300),
    ("unit_scale", gen_unit_scale, 1300),
    ("horizon", gen_horizon, 1300),
    ("jump_overlap", gen_jump, 1300),
)


def generate_cases(seed: int, fraction: float = 1.0) -> list[Case]:
    """All cases, deterministic for a given seed (one RNG per category)."""
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
        return case, collision(case.dim, case.a, case.b, case.radius, case.t_max)
    rel, fallback = case.t_max_rule
    unbounded = collision(case.dim, case.a, case.b, case.radius)
    t_u = mp_to_float(unbounded.t_unbounded)
    t_from = max(case.a[0][0], case.b[0][0])
    t_max = t_u * (1.0 + rel) if t_from < t_u < math.inf else fallback
    case = Case(case.category, case.dim, case.a, case.b, case.radius, t_max, None, case.meta)
    return case, collision(case.dim, case.a, case.b, case.radius, t_max)


def header(seed: int, n: int) -> list[str]:
    """Comment lines at the top of the data file."""
    return [
        "# ballcollide reference path cases (tools/path_reference.py)",
        f"# {n} cases, seed {seed}; mpmath at {PREC_BITS} bits from the exact float64 inputs",
        "# line: category D KA KB <KA segments of A> <KB segments of B> "
        "radius t_max t_ref floor ambiguous",
        "#   D = 2 or 3; KA, KB >= 1; a segment is 1 + 3D numbers: s p[D] v[D] a[D]",
        "#   (2-D: s px py vx vy ax ay; 3-D: s px py pz vx vy vz ax ay az);",
        "#   fields per line: 4 + (KA + KB) * (1 + 3D) + 5",
        "# model: on [s_k, s_k+1) x = p + v (t - s) + a (t - s)^2 / 2, last segment for ever;",
        "#   search from t_from = max(first starts); times absolute (SPEC.md, General motion)",
        "# floats: Python repr (exact round trip) or inf; t_max = inf: no horizon;",
        "# t_ref: exact collision time rounded to nearest float64, inf = none;",
        "# floor: eps * sum_i |x_i dt/dx_i| + eps * |t_ref| with eps = 2^-53 over the start,",
        "#   position, velocity, acceleration of the two active segments and the radius,",
        "#   0 for a miss (3 significant digits); jumps and t_from hits: see the script;",
        "# ambiguous = 1: within 1e-9 relative (or 4 roundings of every input) of a graze,",
        "#   of a tangency at a segment start, of touching while moving tangentially at",
        "#   t_from, or of t_max: hit or miss may go either way; see the script docstring.",
    ]


def summarize(rows: list[tuple[Case, Result]]) -> str:
    """Per-category counts, hits, ambiguous, and the floors of the hits."""
    stats: dict[str, Counter] = {}
    floors: dict[str, list[float]] = {}
    for case, res in rows:
        c = stats.setdefault(case.category, Counter())
        c["n"] += 1
        c["hit" if res.t < INF else "miss"] += 1
        c["amb"] += res.ambiguous
        c[res.kind] += res.t < INF
        if 0 < abs(res.t) < INF and res.floor < INF:
            rel = mp_to_float(res.floor) / max(abs(mp_to_float(res.t)), 1e-300)
            floors.setdefault(case.category, []).append(rel)
    lines = [
        f"{'category':20s} {'n':>6s} {'hits':>6s} {'jump':>5s} {'t_from':>6s} {'ambig':>6s}"
        f" {'floor/t median':>15s} {'max':>9s}"
    ]
    total: Counter = Counter()
    for name, c in stats.items():
        total.update(c)
        fl = floors.get(name, [])
        med = f"{statistics.median(fl):.2e}" if fl else "-"
        top = f"{max(fl):.2e}" if fl else "-"
        lines.append(
            f"{name:20s} {c['n']:6d} {c['hit']:6d} {c['jump']:5d} {c['t_from']:6d} "
            f"{c['amb']:6d} {med:>15s} {top:>9s}"
        )
    lines.append(
        f"{'total':20s} {total['n']:6d} {total['hit']:6d} {total['jump']:5d} "
        f"{total['t_from']:6d} {total['amb']:6d}"
    )
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    """Generate the cases, solve them in parallel, write the data file."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.normpath(DEFAULT_OUT))
    parser.add_argument("--seed", type=int, default=20261201)
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
