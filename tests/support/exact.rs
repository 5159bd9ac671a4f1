//! Exact evaluation of a polynomial with float64 coefficients at a float64 point.
//!
//! Every float is a dyadic rational `m·2^e`, and so is every term `c_k·x^k`: summed as big
//! integers over their smallest exponent, the value `p(x)` and the size of its terms
//! `Σ|c_k|·|x|^k` are exact, with no overflow or underflow whatever the exponents. That gives
//! the true sign of `p(x)` and its true backward error at `x`, independently of the library's
//! float arithmetic.

#![allow(dead_code)]

use num_bigint::BigInt;
use num_traits::{Signed, Zero};

/// `x = m·2^e` exactly (`m = 0` for a zero).
fn dyadic(x: f64) -> (BigInt, i64) {
    if x == 0.0 {
        return (BigInt::zero(), 0);
    }
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i64;
    let frac = bits & ((1u64 << 52) - 1);
    let (mant, exp) = if biased == 0 {
        (frac, -1074)
    } else {
        (frac | (1u64 << 52), biased - 1075)
    };
    let m = BigInt::from(mant);
    (if x < 0.0 { -m } else { m }, exp)
}

/// `p(x)` and `Σ|c_k|·|x|^k` for the coefficients `coeffs` (highest degree first), as big
/// integers over the common exponent `2^e`: `(value, size, e)`.
pub fn eval_exact(coeffs: &[f64], x: f64) -> (BigInt, BigInt, i64) {
    let n = coeffs.len();
    let (mx, ex) = dyadic(x);
    let mut terms = Vec::with_capacity(n);
    let mut power = BigInt::from(1);
    let mut power_exp = 0i64;
    for k in 0..n {
        let (mc, ec) = dyadic(coeffs[n - 1 - k]);
        if !mc.is_zero() && (k == 0 || !mx.is_zero()) {
            terms.push((&mc * &power, ec + power_exp));
        }
        power *= &mx;
        power_exp += ex;
    }
    let Some(e) = terms.iter().map(|t| t.1).min() else {
        return (BigInt::zero(), BigInt::zero(), 0);
    };
    let mut value = BigInt::zero();
    let mut size = BigInt::zero();
    for (m, te) in terms {
        let shifted = m << ((te - e) as usize);
        size += shifted.abs();
        value += shifted;
    }
    (value, size, e)
}

/// Whether `|p(x)| ≤ factor·2⁻⁵³·Σ|c_k|·|x|^k`: whether `x` is an exact root of a polynomial
/// whose coefficients differ from `coeffs` by at most `factor` roundings each (the
/// componentwise backward error of `x` as a root).
pub fn within_backward_error(coeffs: &[f64], x: f64, factor: u64) -> bool {
    let (value, size, _) = eval_exact(coeffs, x);
    (value.abs() << 53usize) <= size * BigInt::from(factor)
}

/// The sign of `p(x)`, exactly: −1, 0 or 1.
pub fn sign_exact(coeffs: &[f64], x: f64) -> i32 {
    let (value, _, _) = eval_exact(coeffs, x);
    if value.is_zero() {
        0
    } else if value.is_positive() {
        1
    } else {
        -1
    }
}
