//! The AVX2 level: [`Simd`] over two `__m256d` registers (lanes 0–3 and 4–7), masks as the
//! compares give them (`Lanes`: two registers of all-ones or all-zeros lanes), packed into
//! bits (`vmovmskpd`) only where a stage hands its lanes on.

use core::arch::x86_64::{
    __m128d, __m256d, _CMP_EQ_OQ, _CMP_GE_OQ, _CMP_GT_OQ, _CMP_LT_OQ, _CMP_NEQ_UQ, _mm_loadu_pd,
    _mm256_add_pd, _mm256_and_pd, _mm256_and_si256, _mm256_andnot_pd, _mm256_blendv_pd,
    _mm256_castpd_si256, _mm256_castpd128_pd256, _mm256_castsi256_pd, _mm256_cmp_pd,
    _mm256_cmpeq_epi64, _mm256_div_pd, _mm256_fmadd_pd, _mm256_insertf128_pd, _mm256_loadu_pd,
    _mm256_max_pd, _mm256_min_pd, _mm256_movemask_pd, _mm256_mul_pd, _mm256_or_pd,
    _mm256_permute2f128_pd, _mm256_set_pd, _mm256_set1_epi64x, _mm256_set1_pd, _mm256_setr_epi64x,
    _mm256_setzero_pd, _mm256_sqrt_pd, _mm256_storeu_pd, _mm256_sub_epi64, _mm256_sub_pd,
    _mm256_unpackhi_pd, _mm256_unpacklo_pd, _mm256_xor_pd,
};
use core::ops::{BitAnd, BitAndAssign, BitOr, BitOrAssign, BitXor, BitXorAssign, Not};

use super::Level;
use super::lanes::{EXPONENT, FRACTION, LANES, MOST, Mask, Simd};

/// The AVX2 level's token: a value of it is the proof that the CPU has AVX2 and FMA
/// ([`Level::Avx2Fma`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx2(());

impl Avx2 {
    /// The token, if this CPU runs the level.
    pub(crate) fn new() -> Option<Self> {
        Level::Avx2Fma.supported().then_some(Self(()))
    }
}

/// Lanes 0–3 and 4–7.
type V = [__m256d; 2];

// SAFETY (every `unsafe` block below): a value of `Avx2` exists only where the CPU has AVX2
// and FMA (`Avx2::new`), and a value of `Lanes` only where an `Avx2` made it (its field is
// private to this module, and only `Avx2`'s methods and the operators on two `Lanes` make
// one), which is all these intrinsics need; the loads and stores read and write only the
// arrays and slices named, in range.

// (No closures here or in the stages: a closure the compiler leaves out of line is compiled
// without the level's features, and every intrinsic in it becomes a call.)

/// The AVX2 level's mask: lanes 0–3 and 4–7, each all ones where set and all zeros where
/// not (what `vcmppd` gives and `vblendvpd` takes). Made only by `Avx2`'s methods, so that a
/// value of it is, like the token, the proof that the CPU runs AVX.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Lanes([__m256d; 2]);

/// Lane-wise `$op` on both halves of two masks.
macro_rules! mask_op {
    ($trait:ident, $method:ident, $assign:ident, $assign_method:ident, $op:ident) => {
        impl $trait for Lanes {
            type Output = Lanes;

            #[inline(always)]
            fn $method(self, other: Lanes) -> Lanes {
                let (x, y) = (self.0, other.0);
                Lanes(unsafe { [$op(x[0], y[0]), $op(x[1], y[1])] })
            }
        }

        impl $assign for Lanes {
            #[inline(always)]
            fn $assign_method(&mut self, other: Lanes) {
                *self = $trait::$method(*self, other);
            }
        }
    };
}

mask_op!(BitAnd, bitand, BitAndAssign, bitand_assign, _mm256_and_pd);
mask_op!(BitOr, bitor, BitOrAssign, bitor_assign, _mm256_or_pd);
mask_op!(BitXor, bitxor, BitXorAssign, bitxor_assign, _mm256_xor_pd);

impl Not for Lanes {
    type Output = Lanes;

    #[inline(always)]
    fn not(self) -> Lanes {
        self ^ ones()
    }
}

/// Every lane set.
#[inline(always)]
fn ones() -> Lanes {
    let ones = unsafe { _mm256_castsi256_pd(_mm256_set1_epi64x(-1)) };
    Lanes([ones, ones])
}

/// The mask's bits: lanes 0–3 from the low half's sign bits, 4–7 from the high half's.
#[inline(always)]
fn bits(mask: Lanes) -> Mask {
    let [low, high] = mask.0;
    let (low, high) = unsafe { (_mm256_movemask_pd(low), _mm256_movemask_pd(high)) };
    (low | high << 4) as Mask
}

/// Each of `bits`' four low bits spread to its lane: all ones where it is set.
#[inline(always)]
fn lanes_of_bits(bits: u8) -> __m256d {
    unsafe {
        let select = _mm256_setr_epi64x(1, 2, 4, 8);
        let set = _mm256_and_si256(_mm256_set1_epi64x(i64::from(bits)), select);
        _mm256_castsi256_pd(_mm256_cmpeq_epi64(set, select))
    }
}

/// Lanes `lanes::unit_scale`: the exponent field subtracted from its all-ones value.
#[inline(always)]
fn unit_scale(x: __m256d) -> __m256d {
    unsafe {
        let field = _mm256_set1_epi64x(EXPONENT as i64);
        let bits = _mm256_and_si256(_mm256_castpd_si256(x), field);
        _mm256_castsi256_pd(_mm256_sub_epi64(field, bits))
    }
}

/// `values[from..from + 2]`.
#[inline(always)]
fn read2(values: &[f64], from: usize) -> __m128d {
    unsafe { _mm_loadu_pd(values[from..from + 2].as_ptr()) }
}

/// `values[from..from + 4]`.
#[inline(always)]
fn read4(values: &[f64], from: usize) -> __m256d {
    unsafe { _mm256_loadu_pd(values[from..from + 4].as_ptr()) }
}

/// Column `c` of the four records of `W` values from `values[at]` on: lane `l` is
/// `values[at + l·W + c]` (four scalar reads).
#[inline(always)]
fn column<const W: usize>(values: &[f64], at: usize, c: usize) -> __m256d {
    let at = at + c;
    unsafe {
        _mm256_set_pd(
            values[at + 3 * W],
            values[at + 2 * W],
            values[at + W],
            values[at],
        )
    }
}

/// Columns `c..c + 2` of the four records of `W` values from `values[at]` on: a 16-byte read
/// per record, paired by inserts and split by unpacks.
#[inline(always)]
fn two_columns<const W: usize>(values: &[f64], at: usize, c: usize) -> [__m256d; 2] {
    let at = at + c;
    let (r0, r1) = (read2(values, at), read2(values, at + W));
    let (r2, r3) = (read2(values, at + 2 * W), read2(values, at + 3 * W));
    unsafe {
        // [r0 r2] and [r1 r3], each record's two values side by side.
        let even = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(r0), r2);
        let odd = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(r1), r3);
        [_mm256_unpacklo_pd(even, odd), _mm256_unpackhi_pd(even, odd)]
    }
}

/// Columns `c..c + 4` of the four records of `W` values from `values[at]` on: a 32-byte read
/// per record and a 4 × 4 transposition in registers.
#[inline(always)]
fn four_columns<const W: usize>(values: &[f64], at: usize, c: usize) -> [__m256d; 4] {
    let at = at + c;
    let (r0, r1) = (read4(values, at), read4(values, at + W));
    let (r2, r3) = (read4(values, at + 2 * W), read4(values, at + 3 * W));
    unsafe {
        let (t0, t1) = (_mm256_unpacklo_pd(r0, r1), _mm256_unpackhi_pd(r0, r1));
        let (t2, t3) = (_mm256_unpacklo_pd(r2, r3), _mm256_unpackhi_pd(r2, r3));
        [
            _mm256_permute2f128_pd::<0x20>(t0, t2),
            _mm256_permute2f128_pd::<0x20>(t1, t3),
            _mm256_permute2f128_pd::<0x31>(t0, t2),
            _mm256_permute2f128_pd::<0x31>(t1, t3),
        ]
    }
}

/// Lane-wise `$op` on both halves.
macro_rules! both {
    ($op:ident, $x:expr, $y:expr) => {{
        let (x, y) = ($x, $y);
        unsafe { [$op(x[0], y[0]), $op(x[1], y[1])] }
    }};
}

/// The compare `$cmp` on both halves, as a mask.
macro_rules! compare {
    ($cmp:ident, $x:expr, $y:expr) => {{
        let (x, y) = ($x, $y);
        Lanes(unsafe {
            [
                _mm256_cmp_pd::<$cmp>(x[0], y[0]),
                _mm256_cmp_pd::<$cmp>(x[1], y[1]),
            ]
        })
    }};
}

impl Simd for Avx2 {
    type V = V;
    type M = Lanes;
    const RUNS_LANE_STAGES: bool = true;

    #[inline(always)]
    fn splat(self, x: f64) -> V {
        let x = unsafe { _mm256_set1_pd(x) };
        [x, x]
    }

    #[inline(always)]
    fn zero(self) -> V {
        let x = unsafe { _mm256_setzero_pd() };
        [x, x]
    }

    #[inline(always)]
    fn load(self, x: [f64; LANES]) -> V {
        unsafe {
            [
                _mm256_loadu_pd(x.as_ptr()),
                _mm256_loadu_pd(x[4..].as_ptr()),
            ]
        }
    }

    #[inline(always)]
    fn store(self, x: V) -> [f64; LANES] {
        let mut out = [0.0; LANES];
        unsafe {
            _mm256_storeu_pd(out.as_mut_ptr(), x[0]);
            _mm256_storeu_pd(out[4..].as_mut_ptr(), x[1]);
        }
        out
    }

    #[inline(always)]
    fn add(self, x: V, y: V) -> V {
        both!(_mm256_add_pd, x, y)
    }

    #[inline(always)]
    fn sub(self, x: V, y: V) -> V {
        both!(_mm256_sub_pd, x, y)
    }

    #[inline(always)]
    fn mul(self, x: V, y: V) -> V {
        both!(_mm256_mul_pd, x, y)
    }

    #[inline(always)]
    fn div(self, x: V, y: V) -> V {
        both!(_mm256_div_pd, x, y)
    }

    #[inline(always)]
    fn min(self, x: V, y: V) -> V {
        // `vminpd`: `x < y ? x : y`.
        both!(_mm256_min_pd, x, y)
    }

    #[inline(always)]
    fn max(self, x: V, y: V) -> V {
        both!(_mm256_max_pd, x, y)
    }

    #[inline(always)]
    fn abs(self, x: V) -> V {
        let sign = self.splat(-0.0);
        both!(_mm256_andnot_pd, sign, x)
    }

    #[inline(always)]
    fn sqrt(self, x: V) -> V {
        unsafe { [_mm256_sqrt_pd(x[0]), _mm256_sqrt_pd(x[1])] }
    }

    #[inline(always)]
    fn blend(self, mask: Lanes, x: V, y: V) -> V {
        let [low, high] = mask.0;
        unsafe {
            [
                _mm256_blendv_pd(x[0], y[0], low),
                _mm256_blendv_pd(x[1], y[1], high),
            ]
        }
    }

    #[inline(always)]
    fn bits(self, mask: Lanes) -> Mask {
        bits(mask)
    }

    #[inline(always)]
    fn mask(self, bits: Mask) -> Lanes {
        Lanes([lanes_of_bits(bits & 15), lanes_of_bits(bits >> 4)])
    }

    #[inline(always)]
    fn none(self) -> Lanes {
        let zero = unsafe { _mm256_setzero_pd() };
        Lanes([zero, zero])
    }

    #[inline(always)]
    fn all(self) -> Lanes {
        ones()
    }

    #[inline(always)]
    fn unit_scale(self, x: V) -> V {
        [unit_scale(x[0]), unit_scale(x[1])]
    }

    #[inline(always)]
    fn fraction_cleared(self, x: V) -> V {
        let fraction = unsafe { _mm256_castsi256_pd(_mm256_set1_epi64x(FRACTION as i64)) };
        both!(_mm256_andnot_pd, [fraction; 2], x)
    }

    #[inline(always)]
    fn mul_add(self, x: V, y: V, z: V) -> V {
        unsafe {
            [
                _mm256_fmadd_pd(x[0], y[0], z[0]),
                _mm256_fmadd_pd(x[1], y[1], z[1]),
            ]
        }
    }

    #[inline(always)]
    fn lt(self, x: V, y: V) -> Lanes {
        compare!(_CMP_LT_OQ, x, y)
    }

    #[inline(always)]
    fn gt(self, x: V, y: V) -> Lanes {
        compare!(_CMP_GT_OQ, x, y)
    }

    #[inline(always)]
    fn ge(self, x: V, y: V) -> Lanes {
        compare!(_CMP_GE_OQ, x, y)
    }

    #[inline(always)]
    fn eq(self, x: V, y: V) -> Lanes {
        compare!(_CMP_EQ_OQ, x, y)
    }

    #[inline(always)]
    fn ne(self, x: V, y: V) -> Lanes {
        compare!(_CMP_NEQ_UQ, x, y)
    }

    #[inline(always)]
    fn transposed<const W: usize>(self, values: &[f64]) -> [V; MOST] {
        const { assert!(W >= 1 && W <= MOST, "records of 1 to MOST values") };
        let values = &values[..LANES * W];
        let mut out = [self.zero(); MOST];
        // Each half's four records: whole columns four at a time, then two, then one.
        for (h, at) in [0, 4 * W].into_iter().enumerate() {
            let mut c = 0;
            while c + 4 <= W {
                for (j, column) in four_columns::<W>(values, at, c).into_iter().enumerate() {
                    out[c + j][h] = column;
                }
                c += 4;
            }
            if c + 2 <= W {
                let [first, second] = two_columns::<W>(values, at, c);
                (out[c][h], out[c + 1][h]) = (first, second);
                c += 2;
            }
            if c < W {
                out[c][h] = column::<W>(values, at, c);
            }
        }
        out
    }
}
