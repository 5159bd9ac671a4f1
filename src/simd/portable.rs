//! The portable level: [`Simd`] over `[f64; 8]` arrays, plain code with each loop over the
//! lanes branch-free (the compiler vectorises it for the target's baseline: SSE2 on x86-64,
//! NEON on aarch64). The reference the other levels are tested against.

use super::lanes::{
    LANES, MOST, Mask, Simd, fraction_cleared, masks_are_bits, transposed_by_reads, unit_scale,
};

/// The portable level's token (every CPU runs it).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Portable;

#[inline(always)]
fn zip(x: [f64; LANES], y: [f64; LANES], f: impl Fn(f64, f64) -> f64) -> [f64; LANES] {
    std::array::from_fn(|l| f(x[l], y[l]))
}

#[inline(always)]
fn mask(x: [f64; LANES], y: [f64; LANES], f: impl Fn(f64, f64) -> bool) -> Mask {
    // A byte of 0 or 1 per lane, packed into bits by one multiply (byte `l` to bit `l` of
    // the top byte): the compares stay vector compares.
    let bytes: [u8; LANES] = std::array::from_fn(|l| u8::from(f(x[l], y[l])));
    (u64::from_le_bytes(bytes).wrapping_mul(0x0102_0408_1020_4080) >> 56) as Mask
}

impl Simd for Portable {
    type V = [f64; LANES];
    type M = Mask;
    const RUNS_LANE_STAGES: bool = false;

    #[inline(always)]
    fn splat(self, x: f64) -> Self::V {
        [x; LANES]
    }

    #[inline(always)]
    fn load(self, x: [f64; LANES]) -> Self::V {
        x
    }

    #[inline(always)]
    fn store(self, x: Self::V) -> [f64; LANES] {
        x
    }

    #[inline(always)]
    fn add(self, x: Self::V, y: Self::V) -> Self::V {
        zip(x, y, |x, y| x + y)
    }

    #[inline(always)]
    fn sub(self, x: Self::V, y: Self::V) -> Self::V {
        zip(x, y, |x, y| x - y)
    }

    #[inline(always)]
    fn mul(self, x: Self::V, y: Self::V) -> Self::V {
        zip(x, y, |x, y| x * y)
    }

    #[inline(always)]
    fn div(self, x: Self::V, y: Self::V) -> Self::V {
        zip(x, y, |x, y| x / y)
    }

    #[inline(always)]
    fn min(self, x: Self::V, y: Self::V) -> Self::V {
        zip(x, y, |x, y| if x < y { x } else { y })
    }

    #[inline(always)]
    fn max(self, x: Self::V, y: Self::V) -> Self::V {
        zip(x, y, |x, y| if x > y { x } else { y })
    }

    #[inline(always)]
    fn abs(self, x: Self::V) -> Self::V {
        x.map(f64::abs)
    }

    #[inline(always)]
    fn sqrt(self, x: Self::V) -> Self::V {
        x.map(f64::sqrt)
    }

    #[inline(always)]
    fn blend(self, bits: Mask, x: Self::V, y: Self::V) -> Self::V {
        std::array::from_fn(|l| if bits >> l & 1 != 0 { y[l] } else { x[l] })
    }

    masks_are_bits!();

    #[inline(always)]
    fn unit_scale(self, x: Self::V) -> Self::V {
        x.map(unit_scale)
    }

    #[inline(always)]
    fn fraction_cleared(self, x: Self::V) -> Self::V {
        x.map(fraction_cleared)
    }

    #[inline(always)]
    fn mul_add(self, x: Self::V, y: Self::V, z: Self::V) -> Self::V {
        std::array::from_fn(|l| x[l].mul_add(y[l], z[l]))
    }

    #[inline(always)]
    fn lt(self, x: Self::V, y: Self::V) -> Mask {
        mask(x, y, |x, y| x < y)
    }

    #[inline(always)]
    fn gt(self, x: Self::V, y: Self::V) -> Mask {
        mask(x, y, |x, y| x > y)
    }

    #[inline(always)]
    fn ge(self, x: Self::V, y: Self::V) -> Mask {
        mask(x, y, |x, y| x >= y)
    }

    #[inline(always)]
    fn eq(self, x: Self::V, y: Self::V) -> Mask {
        mask(x, y, |x, y| x == y)
    }

    #[inline(always)]
    fn ne(self, x: Self::V, y: Self::V) -> Mask {
        mask(x, y, |x, y| x != y)
    }

    #[inline(always)]
    fn transposed<const W: usize>(self, values: &[f64]) -> [Self::V; MOST] {
        transposed_by_reads::<Self, W>(self, values)
    }
}
