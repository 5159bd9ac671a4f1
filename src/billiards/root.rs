//! A bracketing root finder for the Stronge cushion model's two regimes where pooltool calls
//! `scipy.optimize.toms748` (xtol `2e-12`): Brent's method (Brent 1973, as in scipy's
//! `brentq`: inverse quadratic interpolation, secant, and bisection whenever those do not
//! shrink the bracket fast enough). Like TOMS748 it keeps a bracket with a sign change at
//! every step, so it converges on any continuous function with one, in at most about
//! `log2(width / tolerance)²` evaluations; it never leaves the bracket.

/// A root of `f` in `[a, b]`, to within `xtol + rtol·|x|`: `None` if `f(a)` and `f(b)` are of
/// the same sign (no bracket), if either is NaN, or if `max_iter` steps do not converge.
pub(super) fn brent(
    mut f: impl FnMut(f64) -> f64,
    a: f64,
    b: f64,
    xtol: f64,
    rtol: f64,
    max_iter: usize,
) -> Option<f64> {
    let (mut xpre, mut xcur) = (a, b);
    let (mut fpre, mut fcur) = (f(xpre), f(xcur));
    if fpre.is_nan() || fcur.is_nan() {
        return None;
    }
    if fpre == 0.0 {
        return Some(xpre);
    }
    if fcur == 0.0 {
        return Some(xcur);
    }
    if fpre.is_sign_negative() == fcur.is_sign_negative() {
        return None;
    }
    let (mut xblk, mut fblk, mut spre, mut scur) = (0.0, 0.0, 0.0, 0.0);
    for _ in 0..max_iter {
        if fpre != 0.0 && fcur != 0.0 && fpre.is_sign_negative() != fcur.is_sign_negative() {
            xblk = xpre;
            fblk = fpre;
            spre = xcur - xpre;
            scur = spre;
        }
        if fblk.abs() < fcur.abs() {
            xpre = xcur;
            xcur = xblk;
            xblk = xpre;
            fpre = fcur;
            fcur = fblk;
            fblk = fpre;
        }
        let delta = (xtol + rtol * xcur.abs()) / 2.0;
        let sbis = (xblk - xcur) / 2.0;
        if fcur == 0.0 || sbis.abs() < delta {
            return Some(xcur);
        }
        if spre.abs() > delta && fcur.abs() < fpre.abs() {
            let stry = if xpre == xblk {
                -fcur * (xcur - xpre) / (fcur - fpre)
            } else {
                let dpre = (fpre - fcur) / (xpre - xcur);
                let dblk = (fblk - fcur) / (xblk - xcur);
                -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
            };
            if 2.0 * stry.abs() < spre.abs().min(3.0 * sbis.abs() - delta) {
                spre = scur;
                scur = stry;
            } else {
                spre = sbis;
                scur = sbis;
            }
        } else {
            spre = sbis;
            scur = sbis;
        }
        xpre = xcur;
        fpre = fcur;
        xcur += if scur.abs() > delta {
            scur
        } else if sbis > 0.0 {
            delta
        } else {
            -delta
        };
        fcur = f(xcur);
        if fcur.is_nan() {
            return None;
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::brent;

    const RTOL: f64 = 4.0 * f64::EPSILON;

    fn root(f: impl FnMut(f64) -> f64, a: f64, b: f64) -> (f64, usize) {
        let mut calls = 0;
        let mut counted = f;
        let x = brent(
            |x| {
                calls += 1;
                counted(x)
            },
            a,
            b,
            1e-300,
            RTOL,
            200,
        )
        .expect("a bracketed root");
        (x, calls)
    }

    /// Hard classic functions (Alefeld, Potra and Shi's test set, and others): each root to a
    /// few roundings, in few evaluations.
    #[test]
    fn classic_functions() {
        let cases: Vec<(Box<dyn Fn(f64) -> f64>, f64, f64, f64)> = vec![
            (
                Box::new(|x: f64| x.sin() - x / 2.0),
                1.5707963267948966,
                3.141592653589793,
                1.895494267033981,
            ),
            (
                Box::new(|x: f64| x * x * x - 2.0 * x - 5.0),
                2.0,
                3.0,
                2.0945514815423265,
            ),
            (Box::new(|x: f64| (x - 1.0).powi(3)), 0.0, 3.5, 1.0), // triple root: flat
            (
                Box::new(|x: f64| x.powi(19) - 0.2),
                0.0,
                5.0,
                0.2f64.powf(1.0 / 19.0),
            ),
            (Box::new(|x: f64| (1.0 - x).exp() - 1.0), 0.0, 100.0, 1.0), // steep, then flat
            (
                Box::new(|x: f64| {
                    if x == 0.0 {
                        0.0
                    } else {
                        x * (-1.0 / (x * x)).exp()
                    }
                }),
                -1.0,
                4.0,
                0.0,
            ),
            (
                Box::new(|x: f64| 20.0 * x.powi(20) - 1.0),
                0.0,
                1.0,
                0.05f64.powf(1.0 / 20.0),
            ),
            (Box::new(|x: f64| (x - 0.3).signum()), 0.0, 1.0, 0.3), // a jump: bisection
            (Box::new(|x: f64| x.ln()), 0.5, 1e6, 1.0),
            (Box::new(|x: f64| 1e-9 * (x - 0.7)), 0.0, 1.0, 0.7), // tiny values
        ];
        for (k, (f, a, b, want)) in cases.into_iter().enumerate() {
            let (x, calls) = root(&f, a, b);
            let close = (x - want).abs() <= 8.0 * f64::EPSILON * want.abs().max(1e-300)
                || f(x) == 0.0
                || (k == 2 && (x - want).abs() < 1e-5); // a triple root: f flat to ~1e-16
            assert!(close, "case {k}: {x} against {want}");
            // A triple root is flat to a rounding over ~1e-5: bisection's steps, to the bit.
            let cap = if k == 2 { 200 } else { 120 };
            assert!(calls <= cap, "case {k}: {calls} evaluations");
        }
    }

    #[test]
    fn no_bracket_or_nan_is_none() {
        assert_eq!(brent(|x| x * x + 1.0, -1.0, 1.0, 0.0, RTOL, 100), None);
        assert_eq!(brent(|_| f64::NAN, -1.0, 1.0, 0.0, RTOL, 100), None);
        assert_eq!(brent(|x| x, 0.0, 1.0, 0.0, RTOL, 100), Some(0.0));
    }
}
