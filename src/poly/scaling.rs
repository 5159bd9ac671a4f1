//! Exact power-of-two scaling of coefficients and of the variable.
//!
//! Multiplying a float by a power of two is exact (barring overflow and underflow), so the
//! solvers rescale a polynomial to unit-sized coefficients and roots without changing the
//! problem they solve. That is what lets them take coefficients from 1e-300 to 1e300.

/// The binary exponent `e` of a finite non-zero `x`, such that `2^e ≤ |x| < 2^(e+1)`
/// (subnormals included); `None` for zero, infinity and NaN.
///
/// ```
/// use ballcollide::poly::scaling::exponent;
/// assert_eq!(exponent(1.0), Some(0));
/// assert_eq!(exponent(-0.75), Some(-1));
/// assert_eq!(exponent(f64::MIN_POSITIVE / 4.0), Some(-1024));
/// assert_eq!(exponent(0.0), None);
/// ```
pub fn exponent(x: f64) -> Option<i32> {
    if x == 0.0 || !x.is_finite() {
        return None;
    }
    let bits = x.abs().to_bits();
    let biased = (bits >> 52) as i32;
    if biased == 0 {
        // Subnormal: the exponent is set by the leading bit of the mantissa.
        let mantissa = bits & ((1u64 << 52) - 1);
        Some(-1074 + 63 - mantissa.leading_zeros() as i32)
    } else {
        Some(biased - 1023)
    }
}

/// `2^e` as a float, exactly, for any `e` whose power is representable (including subnormal
/// powers); saturates to `0` or `∞` outside that range.
///
/// ```
/// use ballcollide::poly::scaling::pow2;
/// assert_eq!(pow2(10), 1024.0);
/// assert_eq!(pow2(-1074), f64::from_bits(1));
/// assert_eq!(pow2(2000), f64::INFINITY);
/// ```
pub fn pow2(e: i32) -> f64 {
    if e > 1023 {
        f64::INFINITY
    } else if e >= -1022 {
        f64::from_bits(((e + 1023) as u64) << 52)
    } else if e >= -1074 {
        f64::from_bits(1u64 << (e + 1074))
    } else {
        0.0
    }
}

/// `x · 2^e`, computed in at most three exact steps so that an intermediate power of two
/// never overflows or underflows when the result does not.
///
/// ```
/// use ballcollide::poly::scaling::scale;
/// assert_eq!(scale(3.0, -2), 0.75);
/// assert_eq!(scale(1e-300, 1500), 1e-300 * 2f64.powi(1500 - 1000) * 2f64.powi(1000));
/// ```
pub fn scale(x: f64, e: i32) -> f64 {
    // Each step's factor stays within the normal range; only the final product may round
    // (when the result is subnormal), as a single multiplication would.
    let mut x = x;
    let mut e = e;
    while e > 1000 {
        x *= pow2(1000);
        e -= 1000;
    }
    while e < -1000 {
        x *= pow2(-1000);
        e += 1000;
    }
    x * pow2(e)
}
