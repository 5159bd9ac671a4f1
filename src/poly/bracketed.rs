//! Newton's method kept inside a sign-change bracket, with bisection as the safeguard.

/// A root of `f` in `[lo, hi]`, where `f(lo)` and `f(hi)` have opposite signs.
///
/// `f(x)` returns `(f(x), f′(x))`. Newton steps are taken from `start` (clamped into the
/// bracket); a step that leaves the bracket, or that would not shrink it fast enough (as near a
/// multiple root), is replaced by bisection. Every evaluation tightens the bracket, so the
/// method always converges: quadratically near a simple root, at worst as fast as bisection.
/// It stops when a step no longer moves the iterate by more than rounding, when the bracket
/// shrinks to adjacent floats, when `f` is exactly zero, or when `|f| ≤ noise`: `noise` is
/// the caller's bound on the rounding error of `f` near the root: below it, Newton steps are
/// kept only while they lower `|f|`, which ends the search as soon as rounding dominates. `noise = 0` iterates to full
/// precision.
///
/// `f_lo` and `f_hi` are the already known values at the ends (not re-evaluated).
///
/// ```
/// use ballcollide::poly::bracketed_newton;
/// // √2 as the root of x² − 2 on [1, 2].
/// let r = bracketed_newton(|x| (x * x - 2.0, 2.0 * x), 1.0, 2.0, -1.0, 2.0, 1.5, 0.0);
/// assert!((r - 2f64.sqrt()).abs() <= f64::EPSILON);
/// // A triple root: slow for Newton, but the bracket keeps it converging.
/// let cube = |x: f64| ((x - 1.0).powi(3), 3.0 * (x - 1.0).powi(2));
/// let r = bracketed_newton(cube, 0.0, 3.0, -1.0, 8.0, 3.0, 0.0);
/// assert!((r - 1.0).abs() < 1e-5);
/// ```
#[inline(always)]
pub fn bracketed_newton(
    mut f: impl FnMut(f64) -> (f64, f64),
    lo: f64,
    hi: f64,
    f_lo: f64,
    f_hi: f64,
    start: f64,
    noise: f64,
) -> f64 {
    // Orient the bracket so that f < 0 at `neg` and f > 0 at `pos`.
    let (mut neg, mut pos) = if f_lo < 0.0 { (lo, hi) } else { (hi, lo) };
    if f_lo == 0.0 {
        return lo;
    }
    if f_hi == 0.0 {
        return hi;
    }
    let (min, max) = (lo.min(hi), lo.max(hi));
    let mut x = if start > min && start < max {
        start
    } else {
        0.5 * (lo + hi)
    };
    let mut previous_step = (hi - lo).abs();
    let mut step = previous_step;
    // 2 × 64 iterations: each halves the bracket at worst, and the float interval has at
    // most 2⁶⁴ points.
    for _ in 0..128 {
        let (fx, dfx) = f(x);
        if fx == 0.0 || fx.is_nan() {
            return x;
        }
        if fx < 0.0 {
            neg = x;
        } else {
            pos = x;
        }
        let (a, b) = (neg.min(pos), neg.max(pos));
        let newton = x - fx / dfx;
        if fx.abs() <= noise {
            return polish(&mut f, x, fx, dfx, (a, b));
        }
        let shrinks = (2.0 * fx).abs() <= (previous_step * dfx).abs();
        let next = if newton > a && newton < b && shrinks {
            previous_step = step;
            newton
        } else {
            previous_step = step;
            let mid = 0.5 * (a + b);
            if mid <= a || mid >= b {
                return x; // the bracket holds no float between its ends
            }
            mid
        };
        step = (next - x).abs();
        if step <= f64::EPSILON * x.abs().max(next.abs()) || step == 0.0 {
            return next;
        }
        x = next;
    }
    x
}

/// Newton steps from `x`, inside `(a, b)`, kept only while they lower `|f|`: once `f` is within
/// rounding noise of zero, its computed values stop improving at the point that float
/// arithmetic makes the root, usually within two steps. A step that raises `|f|` (rounding,
/// or a near-multiple root's tiny `f′` sending it far) ends the search at the best point.
#[inline(always)]
fn polish(
    f: &mut impl FnMut(f64) -> (f64, f64),
    mut x: f64,
    mut fx: f64,
    mut dfx: f64,
    (a, b): (f64, f64),
) -> f64 {
    for _ in 0..4 {
        let next = x - fx / dfx;
        if !(next > a && next < b) || next == x {
            break;
        }
        let (f_next, df_next) = f(next);
        if f_next.abs() >= fx.abs() {
            break;
        }
        (x, fx, dfx) = (next, f_next, df_next);
        if fx == 0.0 {
            break;
        }
    }
    x
}
