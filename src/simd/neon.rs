//! The NEON level (aarch64): [`Simd`] over four `float64x2_t` registers, masks packed from
//! the compares' lanes.

use core::arch::aarch64::{
    float64x2_t, uint64x2_t, vabsq_f64, vaddq_f64, vandq_u64, vbicq_u64, vbslq_f64, vceqq_f64,
    vcgeq_f64, vcgtq_f64, vcltq_f64, vdivq_f64, vdupq_n_f64, vdupq_n_u64, vfmaq_f64,
    vgetq_lane_u64, vld1q_f64, vld1q_u64, vmulq_f64, vmvnq_u32, vreinterpretq_f64_u64,
    vreinterpretq_u32_u64, vreinterpretq_u64_f64, vreinterpretq_u64_u32, vsqrtq_f64, vst1q_f64,
    vsubq_f64, vsubq_u64, vtstq_u64,
};

use super::Level;
use super::lanes::{
    EXPONENT, FRACTION, LANES, MOST, Mask, Simd, masks_are_bits, transposed_by_reads,
};

/// The NEON level's token: a value of it is the proof that the CPU has NEON
/// ([`Level::Neon`]; every aarch64 CPU does).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Neon(());

impl Neon {
    /// The token, if this CPU runs the level.
    pub(crate) fn new() -> Option<Self> {
        Level::Neon.supported().then_some(Self(()))
    }
}

/// Lanes 0–1, 2–3, 4–5 and 6–7.
type V = [float64x2_t; 4];

// SAFETY (every `unsafe` block below): a value of `Neon` exists only where the CPU has NEON
// (`Neon::new`), which is all these intrinsics need; the loads and stores read and write
// only the arrays named, in range.

#[inline(always)]
fn zip(x: V, y: V, f: impl Fn(float64x2_t, float64x2_t) -> float64x2_t) -> V {
    std::array::from_fn(|q| f(x[q], y[q]))
}

/// The compare's bits: two lanes from each quarter.
#[inline(always)]
fn mask(x: V, y: V, compare: impl Fn(float64x2_t, float64x2_t) -> uint64x2_t) -> Mask {
    let mut bits = 0;
    for q in 0..4 {
        let lanes = compare(x[q], y[q]);
        let (low, high) = unsafe { (vgetq_lane_u64::<0>(lanes), vgetq_lane_u64::<1>(lanes)) };
        bits |= ((low & 1) | (high & 2)) << (2 * q);
    }
    bits as Mask
}

/// `x < y ? x : y` on two lanes (NEON's own `fmin` returns a NaN operand).
#[inline(always)]
fn select_lt(x: float64x2_t, y: float64x2_t) -> float64x2_t {
    unsafe { vbslq_f64(vcltq_f64(x, y), x, y) }
}

impl Simd for Neon {
    type V = V;
    type M = Mask;
    const RUNS_LANE_STAGES: bool = false;

    #[inline(always)]
    fn splat(self, x: f64) -> V {
        [unsafe { vdupq_n_f64(x) }; 4]
    }

    #[inline(always)]
    fn load(self, x: [f64; LANES]) -> V {
        std::array::from_fn(|q| unsafe { vld1q_f64(x[2 * q..].as_ptr()) })
    }

    #[inline(always)]
    fn store(self, x: V) -> [f64; LANES] {
        let mut out = [0.0; LANES];
        for (q, x) in x.into_iter().enumerate() {
            unsafe { vst1q_f64(out[2 * q..].as_mut_ptr(), x) };
        }
        out
    }

    #[inline(always)]
    fn add(self, x: V, y: V) -> V {
        zip(x, y, |x, y| unsafe { vaddq_f64(x, y) })
    }

    #[inline(always)]
    fn sub(self, x: V, y: V) -> V {
        zip(x, y, |x, y| unsafe { vsubq_f64(x, y) })
    }

    #[inline(always)]
    fn mul(self, x: V, y: V) -> V {
        zip(x, y, |x, y| unsafe { vmulq_f64(x, y) })
    }

    #[inline(always)]
    fn div(self, x: V, y: V) -> V {
        zip(x, y, |x, y| unsafe { vdivq_f64(x, y) })
    }

    #[inline(always)]
    fn min(self, x: V, y: V) -> V {
        zip(x, y, select_lt)
    }

    #[inline(always)]
    fn max(self, x: V, y: V) -> V {
        // `x > y ? x : y` is `y < x ? x : y`.
        zip(x, y, |x, y| unsafe { vbslq_f64(vcltq_f64(y, x), x, y) })
    }

    #[inline(always)]
    fn abs(self, x: V) -> V {
        x.map(|x| unsafe { vabsq_f64(x) })
    }

    #[inline(always)]
    fn sqrt(self, x: V) -> V {
        x.map(|x| unsafe { vsqrtq_f64(x) })
    }

    #[inline(always)]
    fn blend(self, bits: Mask, x: V, y: V) -> V {
        std::array::from_fn(|q| unsafe {
            let select = vld1q_u64([1u64 << (2 * q), 2u64 << (2 * q)].as_ptr());
            let lanes = vtstq_u64(vdupq_n_u64(u64::from(bits)), select);
            vbslq_f64(lanes, y[q], x[q])
        })
    }

    masks_are_bits!();

    #[inline(always)]
    fn unit_scale(self, x: V) -> V {
        x.map(|x| unsafe {
            let field = vdupq_n_u64(EXPONENT);
            let bits = vandq_u64(vreinterpretq_u64_f64(x), field);
            vreinterpretq_f64_u64(vsubq_u64(field, bits))
        })
    }

    #[inline(always)]
    fn fraction_cleared(self, x: V) -> V {
        x.map(|x| unsafe {
            let bits = vbicq_u64(vreinterpretq_u64_f64(x), vdupq_n_u64(FRACTION));
            vreinterpretq_f64_u64(bits)
        })
    }

    #[inline(always)]
    fn mul_add(self, x: V, y: V, z: V) -> V {
        // `vfmaq_f64(a, b, c)` is `a + b·c`, rounded once.
        std::array::from_fn(|q| unsafe { vfmaq_f64(z[q], x[q], y[q]) })
    }

    #[inline(always)]
    fn lt(self, x: V, y: V) -> Mask {
        mask(x, y, |x, y| unsafe { vcltq_f64(x, y) })
    }

    #[inline(always)]
    fn gt(self, x: V, y: V) -> Mask {
        mask(x, y, |x, y| unsafe { vcgtq_f64(x, y) })
    }

    #[inline(always)]
    fn ge(self, x: V, y: V) -> Mask {
        mask(x, y, |x, y| unsafe { vcgeq_f64(x, y) })
    }

    #[inline(always)]
    fn eq(self, x: V, y: V) -> Mask {
        mask(x, y, |x, y| unsafe { vceqq_f64(x, y) })
    }

    #[inline(always)]
    fn ne(self, x: V, y: V) -> Mask {
        mask(x, y, |x, y| unsafe {
            vreinterpretq_u64_u32(vmvnq_u32(vreinterpretq_u32_u64(vceqq_f64(x, y))))
        })
    }

    #[inline(always)]
    fn transposed<const W: usize>(self, values: &[f64]) -> [V; MOST] {
        transposed_by_reads::<Self, W>(self, values)
    }
}
