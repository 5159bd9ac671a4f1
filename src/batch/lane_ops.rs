//! The operations of the lane stages ([`path_lanes`](super::path_lanes),
//! [`window_lanes`](super::window_lanes)) on a block of [`LANES`] pairs: one `f64` per pair in
//! an array, a bit per pair in a mask. Plain scalar code, each loop over the lanes
//! branch-free, that the compiler turns into vector instructions in each copy of the batch
//! (`#[target_feature]` wrappers: AVX-512, AVX2 + FMA, the portable build; see
//! [`simd`](crate::simd)): the stages are written once, and each of these is the operation the
//! AVX-512 intrinsics they replace computed, to the bit:
//!
//! - [`min`] and [`max`] are `x < y ? x : y` and `x > y ? x : y` (`minpd`, `maxpd`): the
//!   second operand where either is NaN or both are zeros (unlike `f64::min`, which drops a
//!   NaN);
//! - the comparisons are ordered (false with a NaN operand), but [`ne`], which is true with a
//!   NaN operand (`_CMP_NEQ_UQ`);
//! - [`blend`] takes the second operand where the mask's bit is set.

/// Pairs per block.
pub(crate) const LANES: usize = 8;

/// A value per lane.
pub(super) type V = [f64; LANES];

/// A bit per lane (bit `l` for lane `l`).
pub(super) type Mask = u8;

#[inline(always)]
fn map(x: V, f: impl Fn(f64) -> f64) -> V {
    std::array::from_fn(|l| f(x[l]))
}

#[inline(always)]
fn zip(x: V, y: V, f: impl Fn(f64, f64) -> f64) -> V {
    std::array::from_fn(|l| f(x[l], y[l]))
}

#[inline(always)]
fn mask(x: V, y: V, f: impl Fn(f64, f64) -> bool) -> Mask {
    // A byte of 0 or 1 per lane, packed into bits by one multiply (byte `l` to bit `l` of
    // the top byte): the compares stay vector compares.
    let bytes: [u8; LANES] = std::array::from_fn(|l| u8::from(f(x[l], y[l])));
    (u64::from_le_bytes(bytes).wrapping_mul(0x0102_0408_1020_4080) >> 56) as Mask
}

/// `x` in every lane.
#[inline(always)]
pub(super) fn splat(x: f64) -> V {
    [x; LANES]
}

/// `0` in every lane.
#[inline(always)]
pub(super) fn zero() -> V {
    [0.0; LANES]
}

#[inline(always)]
pub(super) fn add(x: V, y: V) -> V {
    zip(x, y, |x, y| x + y)
}

#[inline(always)]
pub(super) fn sub(x: V, y: V) -> V {
    zip(x, y, |x, y| x - y)
}

#[inline(always)]
pub(super) fn mul(x: V, y: V) -> V {
    zip(x, y, |x, y| x * y)
}

#[inline(always)]
pub(super) fn div(x: V, y: V) -> V {
    zip(x, y, |x, y| x / y)
}

/// `x < y ? x : y` (the second operand where either is NaN).
#[inline(always)]
pub(super) fn min(x: V, y: V) -> V {
    zip(x, y, |x, y| if x < y { x } else { y })
}

/// `x > y ? x : y` (the second operand where either is NaN).
#[inline(always)]
pub(super) fn max(x: V, y: V) -> V {
    zip(x, y, |x, y| if x > y { x } else { y })
}

#[inline(always)]
pub(super) fn abs(x: V) -> V {
    map(x, f64::abs)
}

#[inline(always)]
pub(super) fn sqrt(x: V) -> V {
    map(x, f64::sqrt)
}

/// `y` where the mask's bit is set, else `x`.
#[inline(always)]
pub(super) fn blend(bits: Mask, x: V, y: V) -> V {
    std::array::from_fn(|l| if bits >> l & 1 != 0 { y[l] } else { x[l] })
}

#[inline(always)]
pub(super) fn lt(x: V, y: V) -> Mask {
    mask(x, y, |x, y| x < y)
}

#[inline(always)]
pub(super) fn gt(x: V, y: V) -> Mask {
    mask(x, y, |x, y| x > y)
}

#[inline(always)]
pub(super) fn ge(x: V, y: V) -> Mask {
    mask(x, y, |x, y| x >= y)
}

#[inline(always)]
pub(super) fn eq(x: V, y: V) -> Mask {
    mask(x, y, |x, y| x == y)
}

/// Not equal, or unordered (true with a NaN operand).
#[inline(always)]
pub(super) fn ne(x: V, y: V) -> Mask {
    mask(x, y, |x, y| x != y)
}
