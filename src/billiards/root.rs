//! A bracketing root finder for the Stronge cushion model's two regimes where pooltool calls
//! `scipy.optimize.toms748` (xtol `2e-12`): Alefeld, Potra and Shi's TOMS748, ported from
//! scipy step for step (inverse cubic interpolation, Newton steps on a quadratic, a
//! double-length secant, and a bisection whenever the bracket did not halve). It keeps a
//! bracket with a sign change at every step and at least halves it every iteration, so it
//! converges on any continuous function with one; it never leaves the bracket. Taking
//! scipy's steps, it returns scipy's bits on the same function, so where pooltool stops at
//! `2e-12` we stop at the same point.

/// Alefeld, Potra and Shi's Algorithm 748 (ACM TOMS 21, 1995), ported step for step from
/// scipy's `toms748` (its `TOMS748Solver`, with `k`) so that on the same function it takes the
/// same steps and returns the same bits: a root of `f` in `[a, b]`, stopping when the bracket
/// is within `xtol + rtol·|b|` (pooltool: `xtol = 2e-12`, `rtol = 4ε`, `k = 1`). `None` where
/// scipy raises: `f(a)`, `f(b)` of one sign, a non-finite value, or `max_iter` iterations.
pub(super) fn toms748(
    mut f: impl FnMut(f64) -> f64,
    a: f64,
    b: f64,
    k: usize,
    xtol: f64,
    rtol: f64,
    max_iter: usize,
) -> Option<f64> {
    let mut call = |x: f64| {
        let fx = f(x);
        fx.is_finite().then_some(fx)
    };
    if !a.is_finite() || !b.is_finite() {
        return None;
    }
    let fa = call(a)?;
    if fa == 0.0 {
        return Some(a);
    }
    let fb = call(b)?;
    if fb == 0.0 {
        return Some(b);
    }
    if sign(fb) * sign(fa) > 0.0 {
        return None;
    }
    let mut ab = [a, b];
    let mut fab = [fa, fb];
    let c = secant(ab, fab);
    let c = if ab[0] < c && c < ab[1] {
        c
    } else {
        (ab[0] + ab[1]) / 2.0
    };
    let fc = call(c)?;
    if fc == 0.0 {
        return Some(c);
    }
    let (mut d, mut fd) = update_bracket(&mut ab, &mut fab, c, fc);
    let (mut e, mut fe): (Option<f64>, Option<f64>) = (None, None);
    let mut iterations = 1;
    let eps = f64::EPSILON;
    loop {
        iterations += 1;
        let ab_width = ab[1] - ab[0];
        let (mut d_, mut fd_, mut e_, mut fe_) = (d, fd, e, fe);
        // As scipy's: `c` is kept from one step to the next (with k > 1 a later step reuses
        // it unless the interpolation lands inside).
        let mut c: Option<f64> = None;
        for nsteps in 2..k.max(1) + 2 {
            if let (Some(e), Some(fe)) = (e_, fe_)
                && not_close(&[fab[0], fab[1], fd_, fe], 32.0 * eps)
            {
                let c0 = inverse_poly_zero([ab[0], ab[1], d_, e], [fab[0], fab[1], fd_, fe]);
                if ab[0] < c0 && c0 < ab[1] {
                    c = Some(c0);
                }
            }
            let step = match c {
                Some(c) => c,
                None => newton_quadratic(ab, fab, d_, fd_, nsteps),
            };
            c = Some(step);
            let c = step;
            let fc = call(c)?;
            if fc == 0.0 {
                return Some(c);
            }
            (e_, fe_, d_, fd_) = shift(&mut ab, &mut fab, (d_, fd_), c, fc);
        }
        let uix = usize::from(fab[0].abs() >= fab[1].abs());
        let (u, fu) = (ab[uix], fab[uix]);
        let slope = (fab[1] - fab[0]) / (ab[1] - ab[0]);
        let mut c = u - 2.0 * fu / slope;
        if (c - u).abs() > 0.5 * (ab[1] - ab[0]) {
            c = (ab[0] + ab[1]) / 2.0;
        } else {
            if (c - u).abs() <= eps * u.abs() {
                if frexp_exp(fab[uix]) < frexp_exp(fab[1 - uix]) - 50 {
                    c = (31.0 * ab[uix] + ab[1 - uix]) / 32.0;
                } else {
                    let mm = if uix == 0 { 1.0 } else { -1.0 };
                    let adj = mm * c.abs() * rtol + mm * xtol;
                    c = u + adj;
                }
                if !(ab[0] < c && c < ab[1]) {
                    c = (ab[0] + ab[1]) / 2.0;
                }
            }
        }
        let fc = call(c)?;
        if fc == 0.0 {
            return Some(c);
        }
        (e_, fe_, d_, fd_) = shift(&mut ab, &mut fab, (d_, fd_), c, fc);
        if ab[1] - ab[0] > 0.5 * ab_width {
            e_ = Some(d_);
            fe_ = Some(fd_);
            let z = (ab[0] + ab[1]) / 2.0;
            let fz = call(z)?;
            if fz == 0.0 {
                return Some(z);
            }
            (d_, fd_) = update_bracket(&mut ab, &mut fab, z, fz);
        }
        (d, fd, e, fe) = (d_, fd_, e_, fe_);
        if (ab[0] - ab[1]).abs() <= xtol + rtol * ab[1].abs() {
            return Some((ab[0] + ab[1]) / 2.0);
        }
        if iterations >= max_iter {
            return None;
        }
    }
}

/// The bracket updated with `(c, fc)`: the old `d` becomes `e`, the discarded end `d`.
fn shift(
    ab: &mut [f64; 2],
    fab: &mut [f64; 2],
    (d, fd): (f64, f64),
    c: f64,
    fc: f64,
) -> (Option<f64>, Option<f64>, f64, f64) {
    let (new_d, new_fd) = update_bracket(ab, fab, c, fc);
    (Some(d), Some(fd), new_d, new_fd)
}

/// numpy's `sign`.
fn sign(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        0.0
    }
}

/// The exponent numpy's `frexp` gives (`x = m·2^e`, `0.5 ≤ |m| < 1`).
fn frexp_exp(x: f64) -> i32 {
    if x == 0.0 || !x.is_finite() {
        return 0;
    }
    let bits = x.abs().to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i32;
    if exp == 0 {
        // subnormal
        let lead = (bits << 12).leading_zeros() as i32;
        -1022 - lead
    } else {
        exp - 1022
    }
}

fn secant(x: [f64; 2], fx: [f64; 2]) -> f64 {
    let ([x0, x1], [f0, f1]) = (x, fx);
    if f0 == f1 {
        return f64::NAN;
    }
    if f1.abs() > f0.abs() {
        (-f0 / f1 * x1 + x0) / (1.0 - f0 / f1)
    } else {
        (-f1 / f0 * x0 + x1) / (1.0 - f1 / f0)
    }
}

fn update_bracket(ab: &mut [f64; 2], fab: &mut [f64; 2], c: f64, fc: f64) -> (f64, f64) {
    let idx = if sign(fab[0]) * sign(fc) > 0.0 { 0 } else { 1 };
    let (rx, rfx) = (ab[idx], fab[idx]);
    fab[idx] = fc;
    ab[idx] = c;
    (rx, rfx)
}

/// scipy's `_notclose` with `rtol = 0`: every value nonzero and finite, no two within `atol`.
fn not_close(fs: &[f64; 4], atol: f64) -> bool {
    fs.iter().all(|&x| x != 0.0 && x.is_finite())
        && (0..4).all(|i| (i + 1..4).all(|j| (fs[i] - fs[j]).abs() > atol))
}

/// scipy's `_inverse_poly_zero`: Neville's interpolation of `x(f)` through the four points, at
/// `f = 0`.
fn inverse_poly_zero(xs: [f64; 4], fs: [f64; 4]) -> f64 {
    // _interpolated_poly(xvals = fs, fvals = xs, x = 0)
    let n = 4;
    let mut q = [[0.0; 4]; 4];
    let mut dm = [[0.0; 4]; 4];
    for i in 0..n {
        q[i][0] = xs[i];
        dm[i][0] = xs[i];
    }
    for k in 1..n {
        for (m, i) in (k..n).enumerate() {
            let alpha = dm[i][k - 1] - q[m + k - 1][k - 1];
            let diffik = fs[m] - fs[m + k];
            q[i][k] = (fs[i] - 0.0) / diffik * alpha;
            dm[i][k] = (fs[m] - 0.0) / diffik * alpha;
        }
    }
    (q[3][1] + q[3][2]) + q[3][3] + q[3][0]
}

/// scipy's `_newton_quadratic`: `k` Newton steps on the quadratic through `a`, `b`, `d`.
fn newton_quadratic(ab: [f64; 2], fab: [f64; 2], d: f64, fd: f64, k: usize) -> f64 {
    let ([a, b], [fa, fb]) = (ab, fab);
    let r0 = [(fb - fa) / (b - a), (fd - fb) / (d - b)];
    let big_b = r0[0];
    let big_a = (r0[1] - r0[0]) / (d - a);
    let p = |x: f64| (big_a * (x - b) + big_b) * (x - a) + fa;
    if big_a == 0.0 {
        return a - fa / big_b;
    }
    let mut r = if sign(big_a) * sign(fa) > 0.0 { a } else { b };
    for _ in 0..k {
        let r1 = r - p(r) / (big_b + big_a * (2.0 * r - a - b));
        if !(ab[0] < r1 && r1 < ab[1]) {
            if ab[0] < r && r < ab[1] {
                return r;
            }
            return (ab[0] + ab[1]) / 2.0;
        }
        r = r1;
    }
    r
}

#[cfg(test)]
mod tests {
    use super::toms748;

    const RTOL: f64 = 4.0 * f64::EPSILON;

    fn root(f: impl FnMut(f64) -> f64, a: f64, b: f64) -> (f64, usize) {
        let mut calls = 0;
        let mut counted = f;
        let x = toms748(
            |x| {
                calls += 1;
                counted(x)
            },
            a,
            b,
            1,
            f64::from_bits(1), // scipy's advice for full accuracy: the smallest subnormal
            RTOL,
            100,
        )
        .expect("a bracketed root");
        (x, calls)
    }

    /// Hard classic functions (Alefeld, Potra and Shi's test set, and others): each root to a
    /// few roundings, in few evaluations.
    #[test]
    fn classic_functions() {
        type Case = (Box<dyn Fn(f64) -> f64>, f64, f64, f64);
        let cases: Vec<Case> = vec![
            (
                Box::new(|x: f64| x.sin() - x / 2.0),
                std::f64::consts::FRAC_PI_2,
                std::f64::consts::PI,
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
        assert_eq!(
            toms748(|x| x * x + 1.0, -1.0, 1.0, 1, 2e-12, RTOL, 100),
            None
        );
        assert_eq!(toms748(|_| f64::NAN, -1.0, 1.0, 1, 2e-12, RTOL, 100), None);
        assert_eq!(toms748(|x| x, 0.0, 1.0, 1, 2e-12, RTOL, 100), Some(0.0));
    }

    /// The Stronge regimes' own equations (pooltool's `slip_time_for_initial_stick` and
    /// `slip_time_for_stick` with the default ball and cushion, over their whole ranges of
    /// `v_t/v_n`): with pooltool's tolerances the root is within `2e-12` of the full-accuracy
    /// one, inside `[t_c, t_f]`, where the function changes sign.
    #[test]
    fn stronge_regime_equations() {
        use std::f64::consts::PI;
        let (mu, e_n, beta) = (0.2, 0.85, 3.5);
        let eta_squared = beta / (1.8f64 * 1.8);
        let omega_n = (1e3f64 / 0.170097).sqrt();
        let omega_t = omega_n * (beta / eta_squared).sqrt();
        let (t_c, t_f) = (PI / (2.0 * omega_n), (1.0 + e_n) * PI / (2.0 * omega_n));
        let phase = |t: f64| omega_n * t / e_n + (PI / 2.0) * (1.0 - 1.0 / e_n);
        let check = |f: &dyn Fn(f64) -> f64, what: &str| {
            let coarse = toms748(f, t_c, t_f, 1, 2e-12, RTOL, 100).expect(what);
            let (fine, _) = root(f, t_c, t_f);
            assert!((t_c..=t_f).contains(&coarse), "{what}: {coarse}");
            assert!(
                (coarse - fine).abs() <= 2e-12 + RTOL * fine,
                "{what}: {coarse} {fine}"
            );
            let h = 1e-12 * t_f;
            assert!(
                f(fine - h).signum() != f(fine + h).signum() || f(fine) == 0.0,
                "{what}"
            );
        };
        for k in 1..100 {
            // Stick, then slip: 0 < v_t/v_n < mu·eta².
            let ratio = mu * eta_squared * f64::from(k) / 100.0;
            let f = |t: f64| {
                (-ratio * (omega_t * t).sin()).abs()
                    - mu * eta_squared * omega_t / omega_n * phase(t).sin()
            };
            check(&f, &format!("stick-slip {ratio}"));
        }
        let gross = mu * ((1.0 + e_n) * beta - eta_squared / e_n);
        let v_n_0 = -1.0;
        for k in 1..100 {
            // Slip, stick, slip: mu·eta² < v_t/v_n < the gross-slip bound.
            let ratio = mu * eta_squared + (gross - mu * eta_squared) * f64::from(k) / 100.0;
            let v_t_0 = ratio * v_n_0;
            let tau = super::super::stronge::nondimensional_stick_time(
                ratio,
                beta,
                mu,
                e_n,
                eta_squared,
                t_c,
            )
            .expect("a stick time");
            let t_stick = t_c * tau;
            let (u, v) = if t_stick <= t_c {
                (
                    -mu * v_n_0 * eta_squared / omega_n * (omega_n * t_stick).sin(),
                    v_t_0 - mu * beta * v_n_0 * (1.0 - (omega_n * t_stick).cos()),
                )
            } else {
                (
                    -mu * v_n_0 * eta_squared / omega_n * phase(t_stick).sin(),
                    v_t_0 - mu * beta * v_n_0 * (1.0 - e_n * phase(t_stick).cos()),
                )
            };
            let f = |t: f64| {
                (omega_n / (mu * v_n_0)
                    * (u * (omega_t * (t - t_stick)).cos()
                        - v / omega_t * (omega_t * (t - t_stick)).sin()))
                .abs()
                    - eta_squared * phase(t).sin()
            };
            check(&f, &format!("slip-stick-slip {ratio}"));
        }
    }
}
