//! The AVX-512 level: [`Simd`] over one `__m512d` register (AVX-512 F), masks in `k`
//! registers.

use core::arch::x86_64::{
    __m512d, __mmask8, _CMP_EQ_OQ, _CMP_GE_OQ, _CMP_GT_OQ, _CMP_LT_OQ, _CMP_NEQ_UQ, _mm512_abs_pd,
    _mm512_add_pd, _mm512_and_si512, _mm512_andnot_si512, _mm512_castpd_si512, _mm512_castsi512_pd,
    _mm512_cmp_pd_mask, _mm512_div_pd, _mm512_fmadd_pd, _mm512_loadu_epi64, _mm512_loadu_pd,
    _mm512_mask_blend_pd, _mm512_max_pd, _mm512_min_pd, _mm512_mul_pd, _mm512_permutex2var_pd,
    _mm512_set1_epi64, _mm512_set1_pd, _mm512_setzero_pd, _mm512_sqrt_pd, _mm512_storeu_pd,
    _mm512_sub_epi64, _mm512_sub_pd,
};

use super::Level;
use super::lanes::{EXPONENT, FRACTION, LANES, MOST, Mask, Simd, masks_are_bits};

/// The AVX-512 level's token: a value of it is the proof that the CPU has AVX-512 F, VL and
/// DQ, AVX2 and FMA ([`Level::Avx512`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx512(());

impl Avx512 {
    /// The token, if this CPU runs the level.
    pub(crate) fn new() -> Option<Self> {
        Level::Avx512.supported().then_some(Self(()))
    }
}

// SAFETY (every `unsafe` block below): a value of `Avx512` exists only where the CPU has
// AVX-512 F (`Avx512::new`), which is all these intrinsics need; the loads and stores read
// and write only the arrays and slices named, in range.

impl Simd for Avx512 {
    type V = __m512d;
    type M = Mask;
    const RUNS_LANE_STAGES: bool = true;

    #[inline(always)]
    fn splat(self, x: f64) -> __m512d {
        unsafe { _mm512_set1_pd(x) }
    }

    #[inline(always)]
    fn zero(self) -> __m512d {
        unsafe { _mm512_setzero_pd() }
    }

    #[inline(always)]
    fn load(self, x: [f64; LANES]) -> __m512d {
        unsafe { _mm512_loadu_pd(x.as_ptr()) }
    }

    #[inline(always)]
    fn store(self, x: __m512d) -> [f64; LANES] {
        let mut out = [0.0; LANES];
        unsafe { _mm512_storeu_pd(out.as_mut_ptr(), x) };
        out
    }

    #[inline(always)]
    fn add(self, x: __m512d, y: __m512d) -> __m512d {
        unsafe { _mm512_add_pd(x, y) }
    }

    #[inline(always)]
    fn sub(self, x: __m512d, y: __m512d) -> __m512d {
        unsafe { _mm512_sub_pd(x, y) }
    }

    #[inline(always)]
    fn mul(self, x: __m512d, y: __m512d) -> __m512d {
        unsafe { _mm512_mul_pd(x, y) }
    }

    #[inline(always)]
    fn div(self, x: __m512d, y: __m512d) -> __m512d {
        unsafe { _mm512_div_pd(x, y) }
    }

    #[inline(always)]
    fn min(self, x: __m512d, y: __m512d) -> __m512d {
        // `vminpd`: `x < y ? x : y`.
        unsafe { _mm512_min_pd(x, y) }
    }

    #[inline(always)]
    fn max(self, x: __m512d, y: __m512d) -> __m512d {
        unsafe { _mm512_max_pd(x, y) }
    }

    #[inline(always)]
    fn abs(self, x: __m512d) -> __m512d {
        unsafe { _mm512_abs_pd(x) }
    }

    #[inline(always)]
    fn sqrt(self, x: __m512d) -> __m512d {
        unsafe { _mm512_sqrt_pd(x) }
    }

    #[inline(always)]
    fn blend(self, bits: Mask, x: __m512d, y: __m512d) -> __m512d {
        unsafe { _mm512_mask_blend_pd(bits as __mmask8, x, y) }
    }

    masks_are_bits!();

    #[inline(always)]
    fn unit_scale(self, x: __m512d) -> __m512d {
        unsafe {
            let field = _mm512_set1_epi64(EXPONENT as i64);
            let bits = _mm512_and_si512(_mm512_castpd_si512(x), field);
            _mm512_castsi512_pd(_mm512_sub_epi64(field, bits))
        }
    }

    #[inline(always)]
    fn fraction_cleared(self, x: __m512d) -> __m512d {
        unsafe {
            let fraction = _mm512_set1_epi64(FRACTION as i64);
            _mm512_castsi512_pd(_mm512_andnot_si512(fraction, _mm512_castpd_si512(x)))
        }
    }

    #[inline(always)]
    fn mul_add(self, x: __m512d, y: __m512d, z: __m512d) -> __m512d {
        unsafe { _mm512_fmadd_pd(x, y, z) }
    }

    #[inline(always)]
    fn lt(self, x: __m512d, y: __m512d) -> Mask {
        unsafe { _mm512_cmp_pd_mask::<_CMP_LT_OQ>(x, y) }
    }

    #[inline(always)]
    fn gt(self, x: __m512d, y: __m512d) -> Mask {
        unsafe { _mm512_cmp_pd_mask::<_CMP_GT_OQ>(x, y) }
    }

    #[inline(always)]
    fn ge(self, x: __m512d, y: __m512d) -> Mask {
        unsafe { _mm512_cmp_pd_mask::<_CMP_GE_OQ>(x, y) }
    }

    #[inline(always)]
    fn eq(self, x: __m512d, y: __m512d) -> Mask {
        unsafe { _mm512_cmp_pd_mask::<_CMP_EQ_OQ>(x, y) }
    }

    #[inline(always)]
    fn ne(self, x: __m512d, y: __m512d) -> Mask {
        unsafe { _mm512_cmp_pd_mask::<_CMP_NEQ_UQ>(x, y) }
    }

    /// Read as whole vectors and put in place by permutes and blends, a fraction of the cost
    /// of gathers (the block's values are contiguous); `W` is a constant, so are the lane
    /// indices and masks.
    #[inline(always)]
    fn transposed<const W: usize>(self, values: &[f64]) -> [__m512d; MOST] {
        const { assert!(W >= 1 && W <= MOST, "records of 1 to MOST values") };
        let values = &values[..LANES * W];
        let zero = self.zero();
        let mut loaded = [zero; MOST];
        for (j, vector) in loaded.iter_mut().enumerate().take(W) {
            // (Vectors `0..W` are the `LANES·W` values, in range.)
            *vector = unsafe { _mm512_loadu_pd(values[LANES * j..].as_ptr()) };
        }
        let mut out = [zero; MOST];
        for (c, vector) in out.iter_mut().enumerate().take(W) {
            // Lane `l`'s value is value `l·W + c` of the block: in the pair of loaded vectors
            // `g = (l·W + c) / 16`, at `(l·W + c) % 16` of the two.
            let mut index = [0i64; LANES];
            for (l, at) in index.iter_mut().enumerate() {
                *at = ((l * W + c) % (2 * LANES)) as i64;
            }
            let index = unsafe { _mm512_loadu_epi64(index.as_ptr()) };
            for g in 0..W.div_ceil(2) {
                let mut mask: __mmask8 = 0;
                for l in 0..LANES {
                    if (l * W + c) / (2 * LANES) == g {
                        mask |= 1 << l;
                    }
                }
                if mask == 0 {
                    continue;
                }
                // (With an odd `W` the last pair's second vector is never indexed.)
                let (low, high) = (loaded[2 * g], loaded[(2 * g + 1).min(W - 1)]);
                let part = unsafe { _mm512_permutex2var_pd(low, index, high) };
                *vector = unsafe { _mm512_mask_blend_pd(mask, *vector, part) };
            }
        }
        out
    }
}
