"""Independent high-precision reference for ballcollide collision times.

This script generates test cases for ``ballcollide`` and computes their exact
answers with mpmath.  It does not import ballcollide and does no float64
arithmetic on the answer: every input is a float64 number, converted exactly
(``mpmath.mpf(float)`` is exact) and then processed at ``PREC_BITS`` = 256 bits
(about 77 decimal digits).  Float64 arithmetic is used only to *invent* the
inputs (aiming shots and so on); whatever inputs come out of that are then taken
as exact.

Usage::

    python tools/collision_reference.py                  # writes tests/data/collision_cases.txt
    python tools/collision_reference.py --fraction 0.05  # a quick, smaller run

Model (see docs/contract.md)
--------------------------------
Ball: position p, velocity v, friction mu >= 0.  For 0 <= t <= tau = |v|/mu,
x(t) = p + v t - mu/2 (v/|v|) t^2; afterwards it rests at p + v tau / 2.
mu = 0 means tau = inf; v = 0 means the ball is at rest (tau = 0).
With d(t) = x_A(t) - x_B(t) and g(t) = |d(t)|^2 - R^2 the collision time is:

* 0 if g(0) <= 0 and d.d' < 0 at t = 0 (both evaluated exactly);
* otherwise the earliest t > 0 at which g goes from positive (just before) to
  negative (just after); an overlap at t = 0 that is separating or at rest is
  not a collision, and an exact tangency (g touching 0 and going back up) is
  not one either;
* a collision at t >= t_max is reported as none (t_ref = inf).

Algorithm
---------
The time axis is cut at the two stop times.  On each window both motions are
polynomial, so g is an exact (256-bit) polynomial of degree <= 4 in absolute
time (a stopped ball contributes its resting position).  Its real roots in the
window are isolated by a derivative cascade: the roots of g''' bound the
monotone pieces of g'', whose roots bound the monotone pieces of g', whose
roots (the critical points of g) bound the monotone pieces of g.  A monotone
piece with a strict sign change holds exactly one simple root, found by
safeguarded Newton/bisection on the exact polynomial to ~2^-248 relative.
Values within 2^-232 of the evaluation scale sum_k |c_k| |t|^k count as zero,
so a double root (tangency) is a zero *at* a critical point, not a crossing.
The leading coefficient is never divided by (only the final, infinite window
uses a Cauchy root bound, and there g has degree <= 2 with exact leading
coefficient |dv|^2).  The sign pattern along all windows is then scanned for
the first "+ then -" transition.  Friction-vector differences smaller than
2^-240 of the friction vectors are set to zero (equal friction vectors that
differ only by the rounding of v/|v| in mp).

Floor (eps = 2^-53, the float64 unit roundoff)
----------------------------------------------
floor = eps * sum_i |x_i * dt/dx_i| + eps * t over the 11 inputs x_i (pax pay
vax vay fa pbx pby vbx vby fb radius), with dt/dx_i = -(dg/dx_i)/(dg/dt) at
the collision time (implicit differentiation, all in mp).  dg/dx_i is taken at
fixed t from the exact piecewise motion.  The motion is C^1 jointly in (t,
inputs) across a stop time (the moving and the stopped formulas differ by
-mu/2 (t - tau)^2 along v/|v|), so the same formula holds for a contact exactly
at a stop time; there dg/dt is also continuous.  Inputs equal to 0 contribute
nothing (their relative rounding is 0).
For a collision at t = 0 (g(0) <= 0, approaching):
floor = max(0, g(0) + sigma_g(0)) / |g'(0)|, where sigma_g(t) = eps * sum_i
|x_i * dg/dx_i(t)| is the change of g caused by one rounding of every input;
i.e. 0 for a real overlap and sigma_g(0)/|g'(0)| for an exact touch (rounding
could move the contact to that small positive time).
floor = 0 when there is no collision (t_ref = inf).  If the entry root has
dg/dt = 0 (a flat, odd-multiplicity crossing) the floor is inf and the case is
ambiguous.

Ambiguous flag
--------------
With delta = 1e-9 (GRAZE_DELTA), K = 4 (BAND_FACTOR), a case is ambiguous (1)
when the hit/miss answer, or which of two contacts comes first, could change
within about 1e-9 relative of a grazing configuration, or within K times the
effect of one rounding of every input:

1. grazing: a relevant critical point t_c of g has
   |g(t_c)| <= max(2 delta R^2, K sigma_g(t_c)); 2 delta R^2 is g at the
   closest approach R (1 + delta).  Critical points are the roots of g'
   inside a window and the window boundaries where g' = 0 (always including
   the time both balls have stopped).  Relevant are: those with
   0 <= t_c <= t_max strictly before the collision (all of them for a miss),
   and, for a collision before t_max, the first one at or after it, i.e. the
   bottom of the dip the balls enter (for a collision at t = 0 only when
   |g(0)| is within the same band).  This covers near-grazing hits and misses,
   tangency at a stop time (a ball coming to rest just touching, or just
   overlapping, the other), and a near-graze before the real contact;
2. touching at t = 0: the balls are not static (g not constant) and
   g(0) <= max(2 delta R^2, K sigma_g(0)) and
   |d.d'(0)| <= max(delta |d| |d'|, K sigma_{d.d'}) (touching or overlapping
   while moving tangentially: the approaching/separating decision is
   undecidable);
3. t_max: the collision time ignoring t_max is finite and within
   max(delta t_max, K floor) of t_max;
4. flat entry: g'(t) = 0 (within 2^-232 of its scale) at the entry time.

When the collision time and t_max agree to the root accuracy (2^-244), the
sign of g(t_max) decides: g(t_max) ~ 0 is a tie, i.e. no collision.

Output
------
One case per line, whitespace separated:
``category pax pay vax vay fa pbx pby vbx vby fb radius t_max t_ref floor ambiguous``
Floats are Python ``repr`` (shortest round trip) or ``inf``; t_ref is the exact
collision time rounded to the nearest float64; floor is given to 3 significant
digits; ambiguous is 0 or 1.  Lines starting with ``#`` are comments.
"""

from __future__ import annotations

import argparse
import math
import os
import random
import sys
import time
from collections import Counter
from dataclasses import dataclass, field
from multiprocessing import Pool

from mpmath import mp, mpf
from mpmath.libmp import to_float

PREC_BITS = 256
EPS = 2.0**-53
GRAZE_DELTA = 1e-9
BAND_FACTOR = 4
ZERO_BITS = PREC_BITS - 24
ROOT_BITS = PREC_BITS - 8
SNAP_BITS = PREC_BITS - 16

TABLE_W = 2.54
TABLE_H = 1.27
R_TABLE = 2 * 0.028575

INPUT_NAMES = (
    "pax",
    "pay",
    "vax",
    "vay",
    "fa",
    "pbx",
    "pby",
    "vbx",
    "vby",
    "fb",
    "radius",
)
COLUMNS = (
    "category",
    *INPUT_NAMES,
    "t_max",
    "t_ref",
    "floor",
    "ambiguous",
)
DEFAULT_OUT = os.path.join(
    os.path.dirname(os.path.abspath(__file__)),
    "..",
    "tests",
    "data",
    "collision_cases.txt",
)

mp.prec = PREC_BITS
INF = mp.inf


def set_precision() -> None:
    """Set the working precision (also used as the worker initialiser)."""
    mp.prec = PREC_BITS


# ---------------------------------------------------------------------------
# Exact ball motion (mp)
# ---------------------------------------------------------------------------


@dataclass(frozen=True)
class Ball:
    """One ball in exact mp form: inputs plus speed, unit direction, stop time."""

    px: mpf
    py: mpf
    vx: mpf
    vy: mpf
    mu: mpf
    speed: mpf
    ux: mpf
    uy: mpf
    tau: mpf


def make_ball(px: float, py: float, vx: float, vy: float, mu: float) -> Ball:
    """Build a Ball from float64 inputs, converted exactly to mp."""
    px, py, vx, vy, mu = (mpf(x) for x in (px, py, vx, vy, mu))
    speed = mp.sqrt(vx * vx + vy * vy)
    if speed == 0:
        return Ball(px, py, vx, vy, mu, speed, mpf(0), mpf(0), mpf(0))
    tau = INF if mu == 0 else speed / mu
    return Ball(px, py, vx, vy, mu, speed, vx / speed, vy / speed, tau)


def ball_moving(ball: Ball, t: mpf) -> bool:
    """True if the ball is still moving just after time t."""
    return ball.speed > 0 and t < ball.tau


def ball_position(ball: Ball, t: mpf) -> tuple[mpf, mpf]:
    """Exact position at time t >= 0 (piecewise: moving, then resting)."""
    if ball.speed == 0:
        return ball.px, ball.py
    s = min(t, ball.tau)
    k = ball.mu * s * s / 2
    return ball.px + ball.vx * s - k * ball.ux, ball.py + ball.vy * s - k * ball.uy


def ball_velocity(ball: Ball, t: mpf) -> tuple[mpf, mpf]:
    """Exact velocity at time t >= 0 (zero once stopped)."""
    if not ball_moving(ball, t):
        return mpf(0), mpf(0)
    k = ball.mu * t
    return ball.vx - k * ball.ux, ball.vy - k * ball.uy


def ball_jacobian(ball: Ball, t: mpf) -> list[tuple[mpf, mpf]]:
    """d(position)/d(px, py, vx, vy, mu) at fixed time t, as 2-vectors.

    Moving: x = p + v t - mu t^2 v/(2|v|), so dx/dv = t I - mu t^2/(2|v|)
    (I - u u^T) and dx/dmu = -t^2/2 u.  Stopped: x = p + v |v|/(2 mu), so
    dx/dv = tau/2 (I + u u^T) and dx/dmu = -tau^2/2 u.  Both agree at t = tau.
    At rest (v = 0) the velocity derivative is t I if mu = 0 and 0 otherwise;
    it is multiplied by v = 0 in the floor anyway.
    """
    zero = mpf(0)
    one = mpf(1)
    jp = [(one, zero), (zero, one)]
    if ball.speed == 0:
        jv = t if ball.mu == 0 else zero
        return [*jp, (jv, zero), (zero, jv), (zero, zero)]
    ux, uy = ball.ux, ball.uy
    if t < ball.tau:
        k = ball.mu * t * t / (2 * ball.speed)
        jvx = (t - k * (1 - ux * ux), k * ux * uy)
        jvy = (k * ux * uy, t - k * (1 - uy * uy))
        h = t * t / 2
    else:
        h2 = ball.tau / 2
        jvx = (h2 * (1 + ux * ux), h2 * ux * uy)
        jvy = (h2 * ux * uy, h2 * (1 + uy * uy))
        h = ball.tau * ball.tau / 2
    return [*jp, jvx, jvy, (-h * ux, -h * uy)]


def ball_inputs(ball: Ball) -> tuple[mpf, ...]:
    """The five exact inputs of a ball, in column order."""
    return ball.px, ball.py, ball.vx, ball.vy, ball.mu


# ---------------------------------------------------------------------------
# Polynomials (coefficient lists, lowest degree first, mp)
# ---------------------------------------------------------------------------


def peval(c: list[mpf], t: mpf) -> mpf:
    """Horner evaluation."""
    acc = c[-1]
    for k in range(len(c) - 2, -1, -1):
        acc = acc * t + c[k]
    return acc


def pscale(c: list[mpf], t: mpf) -> mpf:
    """Evaluation scale sum_k |c_k| |t|^k (for the zero tolerance)."""
    at = abs(t)
    acc = abs(c[-1])
    for k in range(len(c) - 2, -1, -1):
        acc = acc * at + abs(c[k])
    return acc


def psign(c: list[mpf], t: mpf, value: mpf | None = None) -> int:
    """Sign of c(t): 0 if |c(t)| <= 2^-ZERO_BITS of its evaluation scale."""
    v = peval(c, t) if value is None else value
    if abs(v) <= mp.ldexp(pscale(c, t), -ZERO_BITS):
        return 0
    return 1 if v > 0 else -1


def pderiv(c: list[mpf]) -> list[mpf]:
    """Derivative polynomial."""
    return [k * c[k] for k in range(1, len(c))] or [mpf(0)]


def ptrim(c: list[mpf]) -> list[mpf]:
    """Drop exactly-zero leading coefficients (keep at least one)."""
    n = len(c)
    while n > 1 and c[n - 1] == 0:
        n -= 1
    return c[:n]


def pmul(a: list[mpf], b: list[mpf]) -> list[mpf]:
    """Polynomial product."""
    out = [mpf(0)] * (len(a) + len(b) - 1)
    for i, ai in enumerate(a):
        for j, bj in enumerate(b):
            out[i + j] += ai * bj
    return out


def padd(a: list[mpf], b: list[mpf]) -> list[mpf]:
    """Polynomial sum."""
    n = max(len(a), len(b))
    return [(a[k] if k < len(a) else 0) + (b[k] if k < len(b) else 0) for k in range(n)]


def root_bound(c: list[mpf]) -> mpf:
    """Cauchy bound: every real root t satisfies |t| < bound (c trimmed)."""
    lead = abs(c[-1])
    return 1 + max((abs(x) / lead for x in c[:-1]), default=mpf(0))


def bracket_root(c: list[mpf], dc: list[mpf], lo: mpf, hi: mpf, flo: mpf, fhi: mpf) -> mpf:
    """The root of c in (lo, hi), where c(lo) and c(hi) have strict opposite signs.

    Safeguarded Newton: a Newton step is taken when it stays inside the
    current bracket and at least halves the step before last, otherwise the
    bracket is bisected.  Stops at 2^-ROOT_BITS relative accuracy.
    """
    a, b = lo, hi
    s_lo = flo > 0
    x = a - flo * (b - a) / (fhi - flo)
    if not a < x < b:
        x = (a + b) / 2
    step_old = step = b - a
    for _ in range(4 * PREC_BITS):
        fx = peval(c, x)
        if fx == 0:
            return x
        if (fx > 0) == s_lo:
            a = x
        else:
            b = x
        width = b - a
        if width <= mp.ldexp(max(abs(a), abs(b)), -ROOT_BITS):
            return (a + b) / 2
        dfx = peval(dc, x)
        use_newton = False
        if dfx != 0:
            xn = x - fx / dfx
            use_newton = a < xn < b and abs(xn - x) <= step_old / 2
        step_old = step
        if use_newton:
            step = abs(xn - x)
            x = xn
            if step <= mp.ldexp(abs(x), -ROOT_BITS):
                return x
        else:
            x = (a + b) / 2
            step = width / 2
    raise RuntimeError("bracket_root did not converge")


def roots_in(c: list[mpf], lo: mpf, hi: mpf) -> list[mpf]:
    """All distinct real roots of c strictly inside (lo, hi), sorted.

    Derivative cascade: the critical points split (lo, hi) into monotone
    pieces; a strict sign change on a piece is a simple root, a zero value at
    a critical point is a multiple root.
    """
    c = ptrim(c)
    if len(c) <= 1:
        return []
    dc = pderiv(c)
    crit = roots_in(dc, lo, hi)
    pts = [lo, *crit, hi]
    vals = [peval(c, x) for x in pts]
    signs = [psign(c, x, v) for x, v in zip(pts, vals)]
    roots = []
    for i in range(len(pts) - 1):
        if i > 0 and signs[i] == 0:
            roots.append(pts[i])
        if signs[i] * signs[i + 1] < 0:
            roots.append(bracket_root(c, dc, pts[i], pts[i + 1], vals[i], vals[i + 1]))
    return roots


# ---------------------------------------------------------------------------
# Gap polynomial on time windows
# ---------------------------------------------------------------------------


def motion_poly(ball: Ball, moving: bool) -> tuple[list[mpf], list[mpf]]:
    """x(t), y(t) of a ball as polynomials in absolute time on one window."""
    if moving:
        half = ball.mu / 2
        return (
            [ball.px, ball.vx, -half * ball.ux],
            [ball.py, ball.vy, -half * ball.uy],
        )
    x, y = ball_position(ball, ball.tau)
    return [x], [y]


def difference_poly(a: list[mpf], b: list[mpf]) -> list[mpf]:
    """a - b, with the t^2 coefficient snapped to 0 if it is only mp rounding."""
    n = max(len(a), len(b))
    out = []
    for k in range(n):
        ak = a[k] if k < len(a) else mpf(0)
        bk = b[k] if k < len(b) else mpf(0)
        dk = ak - bk
        if k == 2 and abs(dk) <= mp.ldexp(abs(ak) + abs(bk), -SNAP_BITS):
            dk = mpf(0)
        out.append(dk)
    return out


def gap_poly(a: Ball, b: Ball, radius: mpf, lo: mpf) -> list[mpf]:
    """g(t) = |x_A(t) - x_B(t)|^2 - R^2 on the window starting at lo."""
    ax, ay = motion_poly(a, ball_moving(a, lo))
    bx, by = motion_poly(b, ball_moving(b, lo))
    dx = difference_poly(ax, bx)
    dy = difference_poly(ay, by)
    g = padd(pmul(dx, dx), pmul(dy, dy))
    g[0] -= radius * radius
    return ptrim(g)


def time_windows(a: Ball, b: Ball) -> list[tuple[mpf, mpf]]:
    """Windows [lo, hi] between 0, the finite positive stop times, and inf."""
    cuts = [mpf(0)]
    for tau in sorted({a.tau, b.tau}):
        if 0 < tau < INF:
            cuts.append(tau)
    return list(zip(cuts, [*cuts[1:], INF]))


@dataclass
class WindowScan:
    """Sign runs and critical points of g on one window."""

    runs: list[tuple[mpf, int]]
    crits: list[tuple[mpf, mpf]]
    constant: bool


def scan_window(c: list[mpf], lo: mpf, hi: mpf) -> WindowScan:
    """Split [lo, hi] into runs of constant sign of g and list its critical points.

    A run (start, sign) holds from start to the next run's start; for an
    infinite window the last run extends to infinity (beyond the Cauchy bound
    g keeps the sign of its leading coefficient).
    """
    if len(c) <= 1:
        return WindowScan([(lo, psign(c, lo))], [], True)
    if hi == INF:
        hi = max(lo + 1, root_bound(c) + 1)
    dc = pderiv(c)
    crit = roots_in(dc, lo, hi)
    pts = [lo, *crit, hi]
    vals = [peval(c, x) for x in pts]
    signs = [psign(c, x, v) for x, v in zip(pts, vals)]
    runs = []
    for i in range(len(pts) - 1):
        s0, s1 = signs[i], signs[i + 1]
        if s0 * s1 < 0:
            root = bracket_root(c, dc, pts[i], pts[i + 1], vals[i], vals[i + 1])
            runs.append((pts[i], s0))
            runs.append((root, s1))
        else:
            runs.append((pts[i], s0 if s0 != 0 else s1))
    return WindowScan(runs, list(zip(crit, vals[1:-1])), False)


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
    reasons: list[str] = field(default_factory=list)


@dataclass
class Problem:
    """Exact inputs of one case."""

    a: Ball
    b: Ball
    radius: mpf

    def gap(self, t: mpf) -> mpf:
        """g(t) from the piecewise positions (independent of the polynomials)."""
        ax, ay = ball_position(self.a, t)
        bx, by = ball_position(self.b, t)
        return (ax - bx) ** 2 + (ay - by) ** 2 - self.radius**2

    def gap_slope(self, t: mpf) -> mpf:
        """g'(t) = 2 d . d' (right derivative; g is C^1 anyway)."""
        ax, ay = ball_position(self.a, t)
        bx, by = ball_position(self.b, t)
        avx, avy = ball_velocity(self.a, t)
        bvx, bvy = ball_velocity(self.b, t)
        return 2 * ((ax - bx) * (avx - bvx) + (ay - by) * (avy - bvy))

    def input_terms(self, t: mpf) -> list[mpf]:
        """x_i * dg/dx_i at fixed t for the 11 inputs, in column order."""
        ax, ay = ball_position(self.a, t)
        bx, by = ball_position(self.b, t)
        dx, dy = ax - bx, ay - by
        terms = []
        for ball, sign in ((self.a, 2), (self.b, -2)):
            for x, (jx, jy) in zip(ball_inputs(ball), ball_jacobian(ball, t)):
                terms.append(x * sign * (dx * jx + dy * jy))
        terms.append(-2 * self.radius * self.radius)
        return terms

    def sigma_gap(self, t: mpf) -> mpf:
        """Change of g(t) caused by one rounding (eps) of every input."""
        return EPS * sum(abs(x) for x in self.input_terms(t))

    def sigma_approach(self) -> mpf:
        """Change of d.d'(0) = dp.dv caused by one rounding of every input."""
        a, b = self.a, self.b
        dpx, dpy = a.px - b.px, a.py - b.py
        dvx, dvy = a.vx - b.vx, a.vy - b.vy
        total = (
            abs(a.px * dvx)
            + abs(a.py * dvy)
            + abs(b.px * dvx)
            + abs(b.py * dvy)
            + abs(a.vx * dpx)
            + abs(a.vy * dpy)
            + abs(b.vx * dpx)
            + abs(b.vy * dpy)
        )
        return EPS * total


def make_problem(inputs: tuple[float, ...]) -> Problem:
    """Validate the 11 float inputs and build the exact Problem."""
    if len(inputs) != 11:
        raise ValueError("expected 11 inputs")
    for name, x in zip(INPUT_NAMES, inputs):
        if not math.isfinite(x):
            raise ValueError(f"{name} is not finite")
    if inputs[4] < 0 or inputs[9] < 0:
        raise ValueError("negative friction")
    if inputs[10] <= 0:
        raise ValueError("radius must be positive")
    a = make_ball(*inputs[0:5])
    b = make_ball(*inputs[5:10])
    return Problem(a, b, mpf(inputs[10]))


@dataclass
class Scan:
    """Result of scanning all windows: first entry time and all critical points."""

    entry: mpf
    crits: list[tuple[mpf, mpf]]
    static: bool


def first_entry(problem: Problem) -> Scan:
    """Earliest + to - transition of g over all windows (t = 0 rule excluded).

    All windows are scanned (also after the entry) so that the critical points
    after the entry, i.e. the bottom of the dip it enters, are known too.
    Window boundaries where g' = 0 from the left (in particular the time both
    balls have stopped) count as critical points.
    """
    a, b, radius = problem.a, problem.b, problem.radius
    prev = 0
    entry = INF
    crits: list[tuple[mpf, mpf]] = []
    static = True
    prev_poly = None
    for lo, hi in time_windows(a, b):
        c = gap_poly(a, b, radius, lo)
        if prev_poly is not None and len(prev_poly) > 1:
            if psign(pderiv(prev_poly), lo) == 0:
                crits.append((lo, peval(prev_poly, lo)))
        scan = scan_window(c, lo, hi)
        static = static and scan.constant
        crits.extend(scan.crits)
        for start, sign in scan.runs:
            if entry == INF and sign == -1 and prev == 1:
                entry = start
            prev = sign
        prev_poly = c
    return Scan(entry, crits, static)


def relevant_crits(
    crits: list[tuple[mpf, mpf]], t_unb: mpf, t_max: mpf, near_touch: bool
) -> list[tuple[mpf, mpf]]:
    """Critical points whose sign decides the answer.

    Those before the collision (and before t_max), and for a hit before t_max
    the first one at or after the collision: the bottom of the dip the balls
    enter.  For a collision at t = 0 only the latter, and only when g(0) is
    near 0 (otherwise the overlap at t = 0 decides alone).
    """
    out = []
    if t_unb > 0:
        out = [x for x in crits if x[0] < t_unb and x[0] <= t_max]
    if t_unb < t_max and (t_unb > 0 or near_touch):
        after = [x for x in crits if x[0] >= t_unb and x[0] > 0]
        if after:
            out.append(min(after, key=lambda x: x[0]))
    return out


def collision(inputs: tuple[float, ...], t_max: float = math.inf) -> Result:
    """Reference collision time, floor and ambiguity flag for one case."""
    problem = make_problem(inputs)
    a, b, radius = problem.a, problem.b, problem.radius
    dpx, dpy = a.px - b.px, a.py - b.py
    dvx, dvy = a.vx - b.vx, a.vy - b.vy
    g0 = dpx * dpx + dpy * dpy - radius * radius
    g1 = 2 * (dpx * dvx + dpy * dvy)
    scan = first_entry(problem)
    t_unb = mpf(0) if (g0 <= 0 and g1 < 0) else scan.entry
    reasons = []
    sigma0 = problem.sigma_gap(mpf(0))
    if t_unb == 0:
        floor = max(mpf(0), g0 + sigma0) / abs(g1)
    elif t_unb < INF:
        slope = problem.gap_slope(t_unb)
        if abs(slope) <= mp.ldexp(slope_scale(problem, t_unb), -ZERO_BITS):
            floor = INF
            reasons.append("flat_entry")
        else:
            floor = problem.sigma_gap(t_unb) / abs(slope) + EPS * t_unb
    else:
        floor = mpf(0)
    tmax_mp = mpf(t_max)
    band_g = 2 * GRAZE_DELTA * radius * radius
    near_touch = abs(g0) <= max(band_g, BAND_FACTOR * sigma0)
    for tc, gc in relevant_crits(scan.crits, t_unb, tmax_mp, near_touch):
        if abs(gc) <= band_g or abs(gc) <= BAND_FACTOR * problem.sigma_gap(tc):
            reasons.append("graze")
            break
    if not scan.static and g0 <= max(band_g, BAND_FACTOR * sigma0):
        rel = GRAZE_DELTA * mp.sqrt((dpx**2 + dpy**2) * (dvx**2 + dvy**2))
        if abs(g1 / 2) <= max(rel, BAND_FACTOR * problem.sigma_approach()):
            reasons.append("touch_t0")
    if t_unb < INF and tmax_mp < INF:
        if abs(t_unb - tmax_mp) <= max(GRAZE_DELTA * tmax_mp, BAND_FACTOR * floor):
            reasons.append("t_max")
    t = t_unb if hit_before(problem, t_unb, tmax_mp) else INF
    if t == INF:
        floor = mpf(0)
    return Result(t, t_unb, floor, bool(reasons), reasons)


def hit_before(problem: Problem, t_unb: mpf, t_max: mpf) -> bool:
    """True if the collision time t_unb is strictly before t_max.

    When the two agree to the root accuracy, the sign of g(t_max) decides (g is
    decreasing through a non-flat entry): g(t_max) ~ 0 is a tie, i.e. none.
    """
    if t_unb == INF or t_max == INF:
        return t_unb < t_max
    if abs(t_unb - t_max) > mp.ldexp(t_max, -(ROOT_BITS - 4)):
        return t_unb < t_max
    ax, ay = ball_position(problem.a, t_max)
    bx, by = ball_position(problem.b, t_max)
    scale = (abs(ax) + abs(bx)) ** 2 + (abs(ay) + abs(by)) ** 2 + problem.radius**2
    return problem.gap(t_max) < -mp.ldexp(scale, -ZERO_BITS)


def slope_scale(problem: Problem, t: mpf) -> mpf:
    """Magnitude scale of g'(t): 2 |d| |d'| summed componentwise."""
    ax, ay = ball_position(problem.a, t)
    bx, by = ball_position(problem.b, t)
    avx, avy = ball_velocity(problem.a, t)
    bvx, bvy = ball_velocity(problem.b, t)
    return 2 * (
        (abs(ax) + abs(bx)) * (abs(avx) + abs(bvx)) + (abs(ay) + abs(by)) * (abs(avy) + abs(bvy))
    )


# ---------------------------------------------------------------------------
# Formatting
# ---------------------------------------------------------------------------


def mp_to_float(x: mpf) -> float:
    """Round an mp number to the nearest float64 (inf stays inf)."""
    if x == INF:
        return math.inf
    return to_float(x._mpf_, rnd="n")


def fmt(x: float) -> str:
    """Shortest round-trip text of a float; 'inf' for infinity."""
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    return repr(float(x))


def fmt_floor(x: mpf) -> str:
    """Floor to 3 significant digits (it is a tolerance, not an answer)."""
    f = mp_to_float(x)
    if math.isinf(f):
        return "inf"
    return fmt(float(f"{f:.3g}"))


# ---------------------------------------------------------------------------
# Case generation (float64 only: it merely invents inputs)
# ---------------------------------------------------------------------------

Vec = tuple[float, float]


@dataclass(frozen=True)
class Case:
    """Generated inputs of one case.

    t_max_rule, if set, is (relative_offset, fallback): t_max is chosen after
    the unbounded collision time t_u is known, as float(t_u) * (1 + offset)
    (offset 0: t_max is t_u rounded to float64); fallback is used when there
    is no collision or it is at t = 0.
    """

    category: str
    inputs: tuple[float, ...]
    t_max: float = math.inf
    t_max_rule: tuple[float, float] | None = None


def clean(x: float, digits: int | None = None) -> float:
    """Optionally round to `digits` significant decimal digits; never -0.0."""
    if digits is not None:
        x = float(f"{x:.{digits}g}")
    return x + 0.0


def unit(theta: float) -> Vec:
    """Unit vector at angle theta."""
    return math.cos(theta), math.sin(theta)


def scale_vec(s: float, v: Vec) -> Vec:
    """s * v."""
    return s * v[0], s * v[1]


def add(a: Vec, b: Vec) -> Vec:
    """a + b."""
    return a[0] + b[0], a[1] + b[1]


def sub(a: Vec, b: Vec) -> Vec:
    """a - b."""
    return a[0] - b[0], a[1] - b[1]


def random_dir(rng: random.Random) -> Vec:
    """Uniformly random unit vector."""
    return unit(rng.uniform(0.0, 2.0 * math.pi))


def table_point(rng: random.Random) -> Vec:
    """Uniform point on the 2.54 m x 1.27 m table."""
    return rng.uniform(0.0, TABLE_W), rng.uniform(0.0, TABLE_H)


def log_uniform(rng: random.Random, lo_exp: float, hi_exp: float) -> float:
    """10 ** U(lo_exp, hi_exp)."""
    return 10.0 ** rng.uniform(lo_exp, hi_exp)


def friction(rng: random.Random) -> float:
    """Table friction deceleration, m/s^2."""
    return rng.uniform(0.05, 2.0)


def stop_time(v: Vec, mu: float) -> float:
    """Float stop time |v|/mu (0 at rest, inf without friction)."""
    s = math.hypot(*v)
    if s == 0.0:
        return 0.0
    return math.inf if mu == 0.0 else s / mu


def f_state(p: Vec, v: Vec, mu: float, t: float) -> tuple[Vec, Vec]:
    """Float position and velocity of a ball at time t (generator only)."""
    s = math.hypot(*v)
    if s == 0.0:
        return p, (0.0, 0.0)
    tau = stop_time(v, mu)
    u = (v[0] / s, v[1] / s)
    if t >= tau:
        return add(p, scale_vec(tau / 2, v)), (0.0, 0.0)
    pos = (
        p[0] + v[0] * t - 0.5 * mu * u[0] * t * t,
        p[1] + v[1] * t - 0.5 * mu * u[1] * t * t,
    )
    return pos, (v[0] - mu * u[0] * t, v[1] - mu * u[1] * t)


def rel_velocity(va: Vec, fa: float, vb: Vec, fb: float, t: float) -> Vec:
    """Float velocity of A relative to B at time t."""
    return sub(f_state((0, 0), va, fa, t)[1], f_state((0, 0), vb, fb, t)[1])


def impact_offset(rng: random.Random, w: Vec, beta: float, radius: float) -> Vec:
    """d = x_A - x_B at the aimed time, for impact parameter beta * radius.

    beta < 1: a contact point on the approaching side (d . w < 0);
    beta >= 1: side-by-side at distance beta * radius (a local miss).
    """
    wn = math.hypot(*w)
    if wn == 0.0:
        return scale_vec(radius * max(beta, 1.05), random_dir(rng))
    uw = (w[0] / wn, w[1] / wn)
    side = rng.choice((-1.0, 1.0))
    n = (-side * uw[1], side * uw[0])
    if beta < 1.0:
        c = math.sqrt(1.0 - beta * beta)
        return (radius * (beta * n[0] - c * uw[0]), radius * (beta * n[1] - c * uw[1]))
    return scale_vec(radius * beta, n)


def graze_offset(rng: random.Random, w: Vec, delta: float, radius: float) -> Vec:
    """d at the aimed time: length R (1 + delta), perpendicular to d' = w."""
    dist = radius * (1.0 + delta)
    wn = math.hypot(*w)
    if wn == 0.0:
        return scale_vec(dist, random_dir(rng))
    side = rng.choice((-1.0, 1.0))
    return (-side * w[1] / wn * dist, side * w[0] / wn * dist)


def aim_a(pb: Vec, va: Vec, fa: float, vb: Vec, fb: float, t_c: float, d: Vec) -> Vec:
    """Initial position of A such that x_A(t_c) - x_B(t_c) = d (in float)."""
    xa, _ = f_state((0.0, 0.0), va, fa, t_c)
    xb, _ = f_state(pb, vb, fb, t_c)
    return xb[0] + d[0] - xa[0], xb[1] + d[1] - xa[1]


def make_case(
    category: str,
    rng: random.Random,
    a: tuple[Vec, Vec, float],
    b: tuple[Vec, Vec, float],
    radius: float,
    digits: int | None = None,
    t_max: float = math.inf,
    t_max_rule: tuple[float, float] | None = None,
    swap: bool = True,
) -> Case:
    """Assemble a Case; A and B are swapped with probability 1/2 if `swap`."""
    if swap and rng.random() < 0.5:
        a, b = b, a
    vals = []
    for p, v, mu in (a, b):
        vals += [p[0], p[1], v[0], v[1], mu]
    vals.append(radius)
    inputs = tuple(clean(x, digits) for x in vals)
    return Case(category, inputs, t_max, t_max_rule)


def random_motion(
    rng: random.Random, rest_prob: float = 0.0, zero_mu_prob: float = 0.0
) -> tuple[Vec, float]:
    """Random velocity (speed U(0.05, 3)) and friction, possibly at rest/frictionless."""
    if rng.random() < rest_prob:
        v: Vec = (0.0, 0.0)
    else:
        v = scale_vec(rng.uniform(0.05, 3.0), random_dir(rng))
    mu = 0.0 if rng.random() < zero_mu_prob else friction(rng)
    return v, mu


def moving_limit(va: Vec, fa: float, vb: Vec, fb: float) -> float:
    """Float time until the first moving ball stops (inf if none stops)."""
    taus = [t for t in (stop_time(va, fa), stop_time(vb, fb)) if t > 0.0]
    return min(taus, default=math.inf)


def both_stop(va: Vec, fa: float, vb: Vec, fb: float) -> float:
    """Float time both balls have stopped (inf if one never stops)."""
    return max(stop_time(va, fa), stop_time(vb, fb))


def aimed_case(
    category: str,
    rng: random.Random,
    beta: float | None = None,
    digits: int | None = 12,
    radius: float = R_TABLE,
    **kw,
) -> tuple[Case, float]:
    """A random aimed shot: contact near a random time t_c while both move.

    Returns the case and the nominal contact time t_c.
    """
    pb = table_point(rng)
    va, fa = random_motion(rng, zero_mu_prob=0.05)
    vb, fb = random_motion(rng, rest_prob=0.3, zero_mu_prob=0.05)
    lim = moving_limit(va, fa, vb, fb)
    if math.isinf(lim):
        lim = 3.0
    t_c = rng.uniform(0.02, 0.95) * lim
    if beta is None:
        beta = rng.uniform(0.0, 1.2)
    w = rel_velocity(va, fa, vb, fb, t_c)
    pa = aim_a(pb, va, fa, vb, fb, t_c, impact_offset(rng, w, beta, radius))
    case = make_case(category, rng, (pa, va, fa), (pb, vb, fb), radius, digits, **kw)
    return case, t_c


# --- categories -------------------------------------------------------------


def gen_random_table(rng: random.Random, n: int) -> list[Case]:
    """Both balls uniformly on the table (half: B within 0.5 m of A)."""
    out = []
    for i in range(n):
        pa = table_point(rng)
        while True:
            if i % 2:
                pb = add(pa, scale_vec(rng.uniform(0.0, 0.5), random_dir(rng)))
            else:
                pb = table_point(rng)
            if math.dist(pa, pb) > 1.001 * R_TABLE:
                break
        va = scale_vec(rng.uniform(0.0, 3.0), random_dir(rng))
        vb = scale_vec(rng.uniform(0.0, 3.0), random_dir(rng))
        a = (pa, va, friction(rng))
        b = (pb, vb, friction(rng))
        out.append(make_case("random_table", rng, a, b, R_TABLE, 8))
    return out


def gen_aimed(rng: random.Random, n: int) -> list[Case]:
    """Aimed shots with impact parameter U(0, 1.2) R while both move."""
    return [aimed_case("aimed", rng)[0] for _ in range(n)]


def gen_head_on(rng: random.Random, n: int) -> list[Case]:
    """Both on one line moving along it (half exactly axis-aligned)."""
    out = []
    for _ in range(n):
        if rng.random() < 0.5:
            e = rng.choice(((1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)))
        else:
            e = random_dir(rng)
        sa = clean(rng.uniform(0.1, 3.0), 8)
        r = rng.random()
        sb = 0.0 if r < 0.4 else clean(rng.uniform(0.1, 3.0), 8)
        sb = -sb if r < 0.8 else clean(rng.uniform(0.0, sa), 8)
        fa = 0.0 if rng.random() < 0.1 else clean(friction(rng), 8)
        fb = 0.0 if rng.random() < 0.1 else clean(friction(rng), 8)
        reach = math.inf if fa == 0.0 else sa * sa / (2 * fa)
        if sb < 0:
            reach += math.inf if fb == 0.0 else sb * sb / (2 * fb)
        elif sb > 0:
            reach -= sb * sb / (2 * fb) if fb > 0 else math.inf
        if math.isfinite(reach) and reach > 0:
            gap = rng.uniform(0.0, 1.6) * reach
        else:
            gap = rng.uniform(0.01, 2.0)
        pa = (clean(rng.uniform(0.1, 2.4), 8), clean(rng.uniform(0.1, 1.2), 8))
        pb = add(pa, scale_vec(R_TABLE + gap, e))
        a = (pa, scale_vec(sa, e), fa)
        b = (pb, scale_vec(sb, e), fb)
        out.append(make_case("head_on", rng, a, b, R_TABLE, 12))
    return out


def gen_stationary_target(rng: random.Random, n: int) -> list[Case]:
    """B at rest; A aimed at it (70 %) or stopping short of it (30 %)."""
    out = []
    for _ in range(n):
        pb = table_point(rng)
        fb = 0.0 if rng.random() < 0.2 else friction(rng)
        va, fa = random_motion(rng, zero_mu_prob=0.1)
        tau = stop_time(va, fa)
        if rng.random() < 0.7:
            t_c = rng.uniform(0.01, 0.999) * (tau if math.isfinite(tau) else 5.0)
            w = va if fa == 0.0 else f_state((0, 0), va, fa, t_c)[1]
            d = impact_offset(rng, w, rng.uniform(0.0, 1.2), R_TABLE)
            pa = aim_a(pb, va, fa, (0.0, 0.0), fb, t_c, d)
        else:
            fa = fa or friction(rng)
            stop, _ = f_state((0.0, 0.0), va, fa, math.inf)
            s = math.hypot(*va)
            ahead = scale_vec(1.0 / s, va)
            short = R_TABLE * (1.0 + log_uniform(rng, -6, 0))
            tilt = unit(rng.uniform(-0.6, 0.6))
            dirn = (
                ahead[0] * tilt[0] - ahead[1] * tilt[1],
                ahead[0] * tilt[1] + ahead[1] * tilt[0],
            )
            pa = sub(sub(pb, scale_vec(short, dirn)), stop)
        a = (pa, va, fa)
        b = (pb, (0.0, 0.0), fb)
        out.append(make_case("stationary_target", rng, a, b, R_TABLE, 12))
    return out


def gen_frictionless(rng: random.Random, n: int) -> list[Case]:
    """mu = 0 for both (40 %) or for A only, B moving with friction or at rest."""
    out = []
    for _ in range(n):
        pb = table_point(rng)
        va = scale_vec(rng.uniform(0.05, 3.0), random_dir(rng))
        if rng.random() < 0.4:
            vb = scale_vec(rng.uniform(0.0, 3.0), random_dir(rng))
            fb = 0.0
            t_c = rng.uniform(0.01, 3.0)
        else:
            vb, fb = random_motion(rng, rest_prob=0.2)
            tau_b = stop_time(vb, fb)
            t_c = rng.uniform(0.01, 3.0) * (tau_b if tau_b > 0 else 1.0)
        w = rel_velocity(va, 0.0, vb, fb, t_c)
        d = impact_offset(rng, w, rng.uniform(0.0, 1.2), R_TABLE)
        pa = aim_a(pb, va, 0.0, vb, fb, t_c, d)
        a = (pa, va, 0.0)
        b = (pb, vb, fb)
        out.append(make_case("frictionless", rng, a, b, R_TABLE, 12))
    return out


def gen_equal_friction(rng: random.Random, n: int) -> list[Case]:
    """Exactly parallel velocities (axis, power-of-two multiple, equal) and equal mu."""
    out = []
    for _ in range(n):
        mu = clean(friction(rng), 8)
        r = rng.random()
        if r < 0.4:
            e = rng.choice(((1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)))
            va = scale_vec(clean(rng.uniform(0.05, 3.0), 8), e)
            vb = scale_vec(clean(rng.uniform(0.05, 3.0), 8), e)
        else:
            va0 = scale_vec(rng.uniform(0.05, 3.0), random_dir(rng))
            va = (clean(va0[0], 8), clean(va0[1], 8))
            k = 0 if r >= 0.85 else rng.choice((-3, -2, -1, 1, 2, 3))
            vb = scale_vec(2.0**k, va)
        pb = table_point(rng)
        t_c = rng.uniform(0.02, 0.999) * both_stop(va, mu, vb, mu)
        w = rel_velocity(va, mu, vb, mu, t_c)
        d = impact_offset(rng, w, rng.uniform(0.0, 1.2), R_TABLE)
        pa = aim_a(pb, va, mu, vb, mu, t_c, d)
        a = (pa, va, mu)
        b = (pb, vb, mu)
        out.append(make_case("equal_friction", rng, a, b, R_TABLE, 12))
    return out


def gen_near_equal_friction(rng: random.Random, n: int) -> list[Case]:
    """Directions differ by 1e-12..1e-6 rad; mu equal or differing by 1e-12..1e-6."""
    out = []
    for _ in range(n):
        theta = rng.uniform(0.0, 2.0 * math.pi)
        eps_dir = rng.choice((-1, 1)) * log_uniform(rng, -12, -6)
        sa = rng.uniform(0.05, 3.0)
        sb = rng.uniform(0.05, 3.0)
        va = scale_vec(sa, unit(theta))
        vb = scale_vec(sb, unit(theta + eps_dir))
        fa = friction(rng)
        fb = fa
        if rng.random() < 0.5:
            fb = fa * (1.0 + rng.choice((-1, 1)) * log_uniform(rng, -12, -6))
        pb = table_point(rng)
        t_c = rng.uniform(0.02, 0.999) * both_stop(va, fa, vb, fb)
        w = rel_velocity(va, fa, vb, fb, t_c)
        d = impact_offset(rng, w, rng.uniform(0.0, 1.2), R_TABLE)
        pa = aim_a(pb, va, fa, vb, fb, t_c, d)
        a = (pa, va, fa)
        b = (pb, vb, fb)
        out.append(make_case("near_equal_friction", rng, a, b, R_TABLE, None))
    return out


def gen_near_stop(rng: random.Random, n: int) -> list[Case]:
    """Contact within 1e-14..1e-8 (relative) of A's stop time, before or after.

    80 %: a moving B hits A near its stop time (transversal contact);
    20 %: B at rest, A reaches it 1e-9..1e-1 (relative) before stopping.
    """
    out = []
    for _ in range(n):
        va = scale_vec(rng.uniform(0.2, 3.0), random_dir(rng))
        fa = friction(rng)
        tau = stop_time(va, fa)
        pb = table_point(rng)
        if rng.random() < 0.8:
            t_c = tau * (1.0 + rng.choice((-1, 1)) * log_uniform(rng, -14, -8))
            vb = scale_vec(rng.uniform(0.3, 3.0), random_dir(rng))
            sb = math.hypot(*vb)
            fb = 0.0 if rng.random() < 0.3 else rng.uniform(0.0, sb / (1.2 * t_c))
            beta = rng.uniform(0.0, 0.95) if rng.random() < 0.8 else rng.uniform(1, 1.2)
        else:
            t_c = tau * (1.0 - log_uniform(rng, -9, -1))
            vb, fb, beta = (0.0, 0.0), friction(rng), 0.0
        w = rel_velocity(va, fa, vb, fb, t_c)
        d = impact_offset(rng, w, beta, R_TABLE)
        pa = aim_a(pb, va, fa, vb, fb, t_c, d)
        a = (pa, va, fa)
        b = (pb, vb, fb)
        out.append(make_case("near_stop", rng, a, b, R_TABLE, None))
    return out


def gen_after_stop(rng: random.Random, n: int) -> list[Case]:
    """A stops first, then B (still moving) runs into it (or past it)."""
    out = []
    for _ in range(n):
        va, fa = random_motion(rng)
        tau_a = stop_time(va, fa)
        t_c = tau_a * rng.uniform(1.05, 4.0)
        vb = scale_vec(rng.uniform(0.3, 3.0), random_dir(rng))
        sb = math.hypot(*vb)
        fb = 0.0 if rng.random() < 0.3 else rng.uniform(0.0, sb / (1.1 * t_c))
        pb = table_point(rng)
        w = rel_velocity(va, fa, vb, fb, t_c)
        d = impact_offset(rng, w, rng.uniform(0.0, 1.2), R_TABLE)
        pa = aim_a(pb, va, fa, vb, fb, t_c, d)
        a = (pa, va, fa)
        b = (pb, vb, fb)
        out.append(make_case("after_stop", rng, a, b, R_TABLE, 12))
    return out


def gen_near_grazing(rng: random.Random, n: int) -> list[Case]:
    """Closest approach R (1 + delta), |delta| = 1e-12..1e-3, either sign."""
    out = []
    for _ in range(n):
        pb = table_point(rng)
        va, fa = random_motion(rng, zero_mu_prob=0.1)
        vb, fb = random_motion(rng, rest_prob=0.3, zero_mu_prob=0.1)
        lim = moving_limit(va, fa, vb, fb)
        lim = 3.0 if math.isinf(lim) else lim
        end = both_stop(va, fa, vb, fb)
        end = 3.0 * lim if math.isinf(end) else end
        if rng.random() < 0.7 or end <= lim:
            t_c = rng.uniform(0.05, 0.95) * lim
        else:
            t_c = rng.uniform(lim, end)
            t_c = lim + (t_c - lim) * rng.uniform(0.05, 0.95)
        delta = rng.choice((-1, 1)) * log_uniform(rng, -12, -3)
        w = rel_velocity(va, fa, vb, fb, t_c)
        d = graze_offset(rng, w, delta, R_TABLE)
        pa = aim_a(pb, va, fa, vb, fb, t_c, d)
        a = (pa, va, fa)
        b = (pb, vb, fb)
        out.append(make_case("near_grazing", rng, a, b, R_TABLE, None))
    return out


def scaled(case: Case, category: str, s: float, offset: Vec = (0.0, 0.0)) -> Case:
    """All lengths scaled by s, then positions moved by offset (float ops)."""
    x = list(case.inputs)
    out = [
        x[0] * s + offset[0],
        x[1] * s + offset[1],
        x[2] * s,
        x[3] * s,
        x[4] * s,
        x[5] * s + offset[0],
        x[6] * s + offset[1],
        x[7] * s,
        x[8] * s,
        x[9] * s,
        x[10] * s,
    ]
    return Case(category, tuple(clean(v) for v in out), case.t_max, case.t_max_rule)


def gen_unit_scale(rng: random.Random, n: int) -> list[Case]:
    """Aimed shots scaled by 2^k (k = -40..40) or by 10^U(-6, 6)."""
    out = []
    for _ in range(n):
        base, _ = aimed_case("unit_scale", rng, digits=10)
        if rng.random() < 0.5:
            s = 2.0 ** rng.randint(-40, 40)
        else:
            s = log_uniform(rng, -6, 6)
        out.append(scaled(base, "unit_scale", s))
    return out


def gen_far_origin(rng: random.Random, n: int) -> list[Case]:
    """Aimed shots moved by an offset of 1e3..1e6 in each coordinate."""
    out = []
    for _ in range(n):
        base, _ = aimed_case("far_origin", rng, digits=None)
        off = tuple(rng.choice((-1, 1)) * log_uniform(rng, 3, 6) for _ in range(2))
        out.append(scaled(base, "far_origin", 1.0, off))
    return out


def gen_touching(rng: random.Random, n: int) -> list[Case]:
    """|d(0)| = R: exactly (axis-aligned, radius = exact difference) or to rounding.

    Relative velocity approaching, separating, or tangential.
    """
    out = []
    for _ in range(n):
        pa = (clean(rng.uniform(0.2, 2.3), 9), clean(rng.uniform(0.2, 1.1), 9))
        if rng.random() < 0.5:
            e = rng.choice(((1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)))
            pb = add(pa, scale_vec(R_TABLE, e))
            radius = abs((pb[0] - pa[0]) + (pb[1] - pa[1]))
        else:
            e = random_dir(rng)
            pb = add(pa, scale_vec(R_TABLE, e))
            radius = R_TABLE
        # d = pa - pb = -R e; approaching means dv . e > 0.
        perp = (-e[1], e[0])
        r = rng.random()
        along = rng.uniform(0.05, 3.0)
        across = rng.uniform(-3.0, 3.0)
        if r < 0.4:
            dv = add(scale_vec(along, e), scale_vec(across, perp))
        elif r < 0.8:
            dv = add(scale_vec(-along, e), scale_vec(across, perp))
        else:
            dv = scale_vec(across, perp)
        vb, fb = random_motion(rng, rest_prob=0.4, zero_mu_prob=0.1)
        va = add(vb, dv)
        fa = 0.0 if rng.random() < 0.1 else friction(rng)
        a = (pa, va, fa)
        b = (pb, vb, fb)
        out.append(make_case("touching", rng, a, b, radius, None))
    return out


def gen_overlapping(rng: random.Random, n: int) -> list[Case]:
    """|d(0)| = R U(0.05, 0.999): approaching, separating, or separating then re-entering.

    Re-entry: B runs away from A with high friction, A follows with low friction.
    """
    out = []
    for _ in range(n):
        pa = table_point(rng)
        e = random_dir(rng)
        pb = add(pa, scale_vec(R_TABLE * rng.uniform(0.05, 0.999), e))
        r = rng.random()
        if r < 0.35:
            vb, fb = random_motion(rng, rest_prob=0.3)
            dv = scale_vec(rng.uniform(0.05, 3.0), unit(rng.uniform(-1.4, 1.4)))
            dv = (dv[0] * e[0] - dv[1] * e[1], dv[0] * e[1] + dv[1] * e[0])
            va, fa = add(vb, dv), friction(rng)
        elif r < 0.7:
            sb = rng.uniform(0.5, 3.0)
            vb = scale_vec(sb, add(e, scale_vec(rng.uniform(-0.3, 0.3), (-e[1], e[0]))))
            fb = rng.uniform(1.0, 4.0)
            va = scale_vec(sb * rng.uniform(0.3, 0.95), e)
            fa = 0.0 if rng.random() < 0.3 else rng.uniform(0.01, 0.5)
        else:
            va, fa = random_motion(rng, rest_prob=0.2)
            vb, fb = random_motion(rng, rest_prob=0.2)
            dvx, dvy = va[0] - vb[0], va[1] - vb[1]
            if dvx * (pa[0] - pb[0]) + dvy * (pa[1] - pb[1]) < 0:
                va, vb = vb, va
        a = (pa, va, fa)
        b = (pb, vb, fb)
        out.append(make_case("overlapping", rng, a, b, R_TABLE, 12))
    return out


def gen_slow_far(rng: random.Random, n: int) -> list[Case]:
    """Speeds 1e-6..1e-2 m/s, tiny or no friction, contact after 1e2..1e8 s."""
    out = []
    for _ in range(n):
        t_c = log_uniform(rng, 2, 8)
        sa = log_uniform(rng, -6, -2)
        va = scale_vec(sa, random_dir(rng))
        fa = 0.0 if rng.random() < 0.3 else sa / (t_c * rng.uniform(1.05, 10.0))
        if rng.random() < 0.4:
            vb, fb = (0.0, 0.0), 0.0
        else:
            sb = log_uniform(rng, -6, -2)
            vb = scale_vec(sb, random_dir(rng))
            fb = 0.0 if rng.random() < 0.3 else sb / (t_c * rng.uniform(0.5, 10.0))
        pb = scale_vec(rng.uniform(0.0, 1e3), random_dir(rng))
        w = rel_velocity(va, fa, vb, fb, t_c)
        d = impact_offset(rng, w, rng.uniform(0.0, 1.2), R_TABLE)
        pa = aim_a(pb, va, fa, vb, fb, t_c, d)
        a = (pa, va, fa)
        b = (pb, vb, fb)
        out.append(make_case("slow_far", rng, a, b, R_TABLE, 12))
    return out


def gen_chasing(rng: random.Random, n: int) -> list[Case]:
    """Roughly the same direction (within 0.3 rad), the faster ball behind."""
    out = []
    for _ in range(n):
        theta = rng.uniform(0.0, 2.0 * math.pi)
        sa = rng.uniform(0.5, 3.0)
        sb = sa * rng.uniform(0.05, 0.9)
        va = scale_vec(sa, unit(theta))
        vb = scale_vec(sb, unit(theta + rng.uniform(-0.3, 0.3)))
        fa = 0.0 if rng.random() < 0.1 else friction(rng)
        fb = friction(rng)
        pb = table_point(rng)
        end = both_stop(va, fa, vb, fb)
        end = 3.0 if math.isinf(end) else end
        t_c = rng.uniform(0.02, 0.999) * end
        w = rel_velocity(va, fa, vb, fb, t_c)
        d = impact_offset(rng, w, rng.uniform(0.0, 1.2), R_TABLE)
        pa = aim_a(pb, va, fa, vb, fb, t_c, d)
        a = (pa, va, fa)
        b = (pb, vb, fb)
        out.append(make_case("chasing", rng, a, b, R_TABLE, 12))
    return out


def gen_t_max(rng: random.Random, n: int) -> list[Case]:
    """Aimed shots with a finite t_max: near the contact (rule) or random."""
    out = []
    for _ in range(n):
        r = rng.random()
        case, t_c = aimed_case("t_max", rng, beta=rng.uniform(0.0, 1.1))
        fallback = t_c * rng.uniform(0.2, 2.0)
        if r < 0.5:
            rel = rng.choice((-1, 1)) * log_uniform(rng, -16, -2)
            case = Case("t_max", case.inputs, math.inf, (rel, fallback))
        elif r < 0.6:
            case = Case("t_max", case.inputs, math.inf, (0.0, fallback))
        else:
            case = Case("t_max", case.inputs, fallback)
        out.append(case)
    return out


CATEGORIES = (
    ("random_table", gen_random_table, 2000),
    ("aimed", gen_aimed, 1300),
    ("head_on", gen_head_on, 1200),
    ("stationary_target", gen_stationary_target, 1200),
    ("frictionless", gen_frictionless, 1200),
    ("equal_friction", gen_equal_friction, 1200),
    ("near_equal_friction", gen_near_equal_friction, 1200),
    ("near_stop", gen_near_stop, 1200),
    ("after_stop", gen_after_stop, 1200),
    ("near_grazing", gen_near_grazing, 1300),
    ("unit_scale", gen_unit_scale, 1400),
    ("far_origin", gen_far_origin, 1200),
    ("touching", gen_touching, 1200),
    ("overlapping", gen_overlapping, 1200),
    ("slow_far", gen_slow_far, 1200),
    ("chasing", gen_chasing, 1200),
    ("t_max", gen_t_max, 1200),
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
        return case, collision(case.inputs, case.t_max)
    rel, fallback = case.t_max_rule
    unbounded = collision(case.inputs)
    t_u = mp_to_float(unbounded.t_unbounded)
    t_max = t_u * (1.0 + rel) if 0.0 < t_u < math.inf else fallback
    case = Case(case.category, case.inputs, t_max, None)
    return case, collision(case.inputs, t_max)


def format_line(case: Case, result: Result) -> str:
    """One output line."""
    fields = [case.category, *(fmt(x) for x in case.inputs), fmt(case.t_max)]
    fields += [fmt(mp_to_float(result.t)), fmt_floor(result.floor)]
    fields.append("1" if result.ambiguous else "0")
    return " ".join(fields)


def header(seed: int, n: int) -> list[str]:
    """Comment lines at the top of the data file."""
    return [
        "# ballcollide reference collision cases (tools/collision_reference.py)",
        f"# {n} cases, seed {seed}; mpmath at {PREC_BITS} bits from the exact float64 inputs",
        "# columns: " + " ".join(COLUMNS),
        "# floats: Python repr (exact round trip) or inf; t_max = inf: no horizon;",
        "# t_ref: exact collision time rounded to nearest float64, inf = none;",
        "# floor: eps * sum_i |x_i dt/dx_i| + eps * t_ref with eps = 2^-53 "
        "(unit roundoff), 0 for a miss",
        "#   (3 significant digits); t = 0 hits: max(0, g(0) + sigma_g) / |g'(0)|;",
        "# ambiguous = 1: within 1e-9 relative (or 4 roundings of every input) of a grazing",
        "#   contact, of a tangency at a stop, of touching while moving tangentially at t = 0,",
        "#   or of t_max: hit or miss may go either way; see the script docstring.",
    ]


def summarize(rows: list[tuple[Case, Result]]) -> str:
    """Per-category table of counts, hits, misses, ambiguous."""
    stats: dict[str, Counter] = {}
    for case, res in rows:
        c = stats.setdefault(case.category, Counter())
        c["n"] += 1
        c["hit" if res.t < INF else "miss"] += 1
        c["amb"] += res.ambiguous
        c["amb_hit" if res.t < INF else "amb_miss"] += res.ambiguous
    lines = [f"{'category':22s} {'n':>6s} {'hits':>6s} {'misses':>6s} {'ambig':>6s}"]
    total: Counter = Counter()
    for name, c in stats.items():
        total.update(c)
        lines.append(f"{name:22s} {c['n']:6d} {c['hit']:6d} {c['miss']:6d} {c['amb']:6d}")
    lines.append(
        f"{'total':22s} {total['n']:6d} {total['hit']:6d} {total['miss']:6d} {total['amb']:6d}"
    )
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    """Generate the cases, solve them in parallel, write the data file."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.normpath(DEFAULT_OUT))
    parser.add_argument("--seed", type=int, default=20240611)
    parser.add_argument("--fraction", type=float, default=1.0)
    parser.add_argument("--processes", type=int, default=2)
    args = parser.parse_args(argv)
    start = time.time()
    cases = generate_cases(args.seed, args.fraction)
    if args.processes > 1:
        with Pool(args.processes, initializer=set_precision) as pool:
            rows = list(pool.imap(solve_case, cases, chunksize=32))
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
