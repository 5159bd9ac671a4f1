//! [`Simd`]: the operations the lane stages are written in, on a block of [`LANES`] pairs (one
//! `f64` per pair in a vector, one truth value per pair in a mask: the level's own form,
//! [`Simd::M`], inside a stage, and a [`Mask`] of bits where a stage hands its lanes on), with
//! one implementation per level (`Portable`, `Avx2`, `Avx512`, `Neon`).
//!
//! Every operation gives the same bits at every level, to the NaN and the signed zero:
//!
//! - `add`, `sub`, `mul`, `div` and `sqrt` are IEEE-754's, correctly rounded, and
//!   [`Simd::mul_add`] is the fused multiply-add, rounded once (`f64::mul_add`); no other
//!   operation forms one;
//! - [`Simd::min`] and [`Simd::max`] are `x < y ? x : y` and `x > y ? x : y` (what x86's
//!   `minpd` and `maxpd` compute): the second operand where either is NaN or both are zeros,
//!   unlike `f64::min`, which drops a NaN, and unlike NEON's `fmin`, which returns it; the
//!   stages' proofs are written for these;
//! - the comparisons are ordered (false with a NaN operand), but [`Simd::ne`], which is true
//!   with a NaN operand;
//! - [`Simd::blend`] takes the second operand where the mask is set; the masks' logic
//!   (`&`, `|`, `^`, `!`, [`Simd::any`], [`Simd::every`]) is lane-wise, as on a mask's bits;
//! - [`Simd::unit_scale`] and [`Simd::fraction_cleared`] work on the bits (exact, NaN
//!   included): [`unit_scale`] and [`fraction_cleared`].
//!
//! The portable level is the reference; the tests compare every level the CPU has with it.

use core::ops::{BitAnd, BitAndAssign, BitOr, BitOrAssign, BitXor, Not};

/// Pairs per block: one AVX-512 register, two AVX2 registers, four NEON registers.
pub(crate) const LANES: usize = 8;

/// A bit per lane (bit `l` for lane `l`): a mask as the stages hand it on, and as the
/// portable, AVX-512 and NEON levels hold it.
pub(crate) type Mask = u8;

/// [`Simd::bits`] and [`Simd::mask`] for a level whose [`Simd::M`] is the [`Mask`] itself.
macro_rules! masks_are_bits {
    () => {
        #[inline(always)]
        fn bits(self, mask: Mask) -> Mask {
            mask
        }

        #[inline(always)]
        fn mask(self, bits: Mask) -> Mask {
            bits
        }
    };
}
pub(super) use masks_are_bits;

/// The values of the block's lanes, widest value type first: row `c` of a block read by
/// [`Simd::transposed`] is at most this many values wide (3 segments of 3-D rows).
pub(crate) const MOST: usize = 9;

/// One instruction-set level's operations on [`LANES`] `f64` lanes.
///
/// A value of an implementing type is the proof that the CPU runs the instructions its
/// methods use (it is made only by a constructor that checks, see
/// [`dispatch`](super::dispatch)): so the methods are safe to call, and they are meant to be
/// inlined into a function compiled for the level's features (the dispatch's shims), where
/// each becomes one or two instructions.
pub(crate) trait Simd: Copy {
    /// `LANES` values.
    type V: Copy;

    /// A truth value per lane, in the level's own form: what its compares give and its
    /// [`blend`](Simd::blend) takes, so that a compare feeding a select costs no conversion.
    /// The bits of a [`Mask`] at the portable, AVX-512 (a `k` register) and NEON levels;
    /// at AVX2 a vector of all-ones or all-zeros lanes, which a conversion to bits
    /// (`vmovmskpd`) and back (a broadcast and a compare) would cost several instructions
    /// each way. [`bits`](Simd::bits) and [`mask`](Simd::mask) convert.
    type M: Copy
        + BitAnd<Output = Self::M>
        + BitOr<Output = Self::M>
        + BitXor<Output = Self::M>
        + Not<Output = Self::M>
        + BitAndAssign
        + BitOrAssign;

    /// Whether the batches run their lane stages at this level: where the vectors are 16
    /// bytes (the portable level's SSE2 on x86-64, NEON) a block of eight pairs spills out
    /// of the registers, and on the 200,000-pair pool table the portable level's lanes cost
    /// more than they save (43 ms against 29 ms without, AMD EPYC, one thread). The stages
    /// are tested at every level all the same (`batch::path_lanes`' tests).
    const RUNS_LANE_STAGES: bool;

    /// `x` in every lane.
    fn splat(self, x: f64) -> Self::V;
    /// The lanes of an array, lane `l` from element `l`.
    fn load(self, x: [f64; LANES]) -> Self::V;
    /// The lanes as an array, element `l` from lane `l`.
    fn store(self, x: Self::V) -> [f64; LANES];
    /// Lanes `x + y`.
    fn add(self, x: Self::V, y: Self::V) -> Self::V;
    /// Lanes `x − y`.
    fn sub(self, x: Self::V, y: Self::V) -> Self::V;
    /// Lanes `x · y`.
    fn mul(self, x: Self::V, y: Self::V) -> Self::V;
    /// Lanes `x / y`.
    fn div(self, x: Self::V, y: Self::V) -> Self::V;
    /// Lanes `x < y ? x : y` (the second operand where either is NaN).
    fn min(self, x: Self::V, y: Self::V) -> Self::V;
    /// Lanes `x > y ? x : y` (the second operand where either is NaN).
    fn max(self, x: Self::V, y: Self::V) -> Self::V;
    /// Lanes `|x|` (the sign bit cleared).
    fn abs(self, x: Self::V) -> Self::V;
    /// Lanes `x·y + z`, rounded once.
    fn mul_add(self, x: Self::V, y: Self::V, z: Self::V) -> Self::V;
    /// Lanes `√x`.
    fn sqrt(self, x: Self::V) -> Self::V;
    /// `y` where the mask is set, else `x`.
    fn blend(self, mask: Self::M, x: Self::V, y: Self::V) -> Self::V;
    /// The mask's bits, bit `l` for lane `l`.
    fn bits(self, mask: Self::M) -> Mask;
    /// The mask whose bits are `bits`.
    fn mask(self, bits: Mask) -> Self::M;
    /// Lanes [`unit_scale`]`(x)`: the power of two that brings a normal `|x|` into `[2, 4)`.
    fn unit_scale(self, x: Self::V) -> Self::V;
    /// Lanes [`fraction_cleared`]`(x)`: for a normal `x`, the signed power of two at or below
    /// `|x|`.
    fn fraction_cleared(self, x: Self::V) -> Self::V;
    /// Lanes `x < y`.
    fn lt(self, x: Self::V, y: Self::V) -> Self::M;
    /// Lanes `x > y`.
    fn gt(self, x: Self::V, y: Self::V) -> Self::M;
    /// Lanes `x ≥ y`.
    fn ge(self, x: Self::V, y: Self::V) -> Self::M;
    /// Lanes `x = y`.
    fn eq(self, x: Self::V, y: Self::V) -> Self::M;
    /// Lanes `x ≠ y`, or unordered (true with a NaN operand).
    fn ne(self, x: Self::V, y: Self::V) -> Self::M;

    /// `LANES` records of `W` values, stored one after another from `values[0]`, as `W`
    /// vectors: lane `l` of vector `c` is `values[l·W + c]` (the first `W` of the array; the
    /// rest are zeros). The rows of a block of paths, a path per lane.
    ///
    /// # Panics
    /// If `values` holds fewer than `LANES·W` values, or `W` is 0 or above [`MOST`].
    fn transposed<const W: usize>(self, values: &[f64]) -> [Self::V; MOST];

    /// `0` in every lane.
    #[inline(always)]
    fn zero(self) -> Self::V {
        self.splat(0.0)
    }

    /// The mask set in no lane.
    #[inline(always)]
    fn none(self) -> Self::M {
        self.mask(0)
    }

    /// The mask set in every lane.
    #[inline(always)]
    fn all(self) -> Self::M {
        self.mask(Mask::MAX)
    }

    /// Whether the mask is set in any lane.
    #[inline(always)]
    fn any(self, mask: Self::M) -> bool {
        self.bits(mask) != 0
    }

    /// Whether the mask is set in every lane.
    #[inline(always)]
    fn every(self, mask: Self::M) -> bool {
        self.bits(mask) == Mask::MAX
    }
}

/// The power of two that brings a normal `|x|` into `[2, 4)`: `2^(1024 − f)`, `f` the exponent
/// field of `x` (its sign ignored), by an integer subtraction on the bits (normal for every
/// field from 1 to 2046); `+∞` for a zero or subnormal `x` (field 0), `+0` for an infinite or
/// NaN one (field 2047): either turns the numbers it scales into infinities or NaNs. The
/// scalar reference of [`Simd::unit_scale`], and the unit of length's scale
/// (`collision::length_unit`).
#[inline(always)]
pub(crate) fn unit_scale(x: f64) -> f64 {
    f64::from_bits(EXPONENT - (x.to_bits() & EXPONENT))
}

/// `x` with its 52 fraction bits cleared (its sign and exponent kept): for a normal `x` the
/// power of two at or below `|x|`, with `x`'s sign; `±0` for a subnormal, itself for a zero or
/// an infinity, an infinity for a NaN. The scalar reference of [`Simd::fraction_cleared`].
#[inline(always)]
pub(crate) fn fraction_cleared(x: f64) -> f64 {
    f64::from_bits(x.to_bits() & !FRACTION)
}

/// The fraction field's bits of an `f64`.
pub(super) const FRACTION: u64 = (1 << 52) - 1;

/// The exponent field's bits of an `f64`.
pub(super) const EXPONENT: u64 = 0x7ff << 52;

/// The records-to-lanes transposition written with scalar reads, for levels that have no
/// faster one: lane `l` of vector `c` is `values[l·W + c]`.
///
/// # Panics
/// As [`Simd::transposed`].
#[inline(always)]
pub(super) fn transposed_by_reads<S: Simd, const W: usize>(s: S, values: &[f64]) -> [S::V; MOST] {
    const { assert!(W >= 1 && W <= MOST, "records of 1 to MOST values") };
    let values = &values[..LANES * W];
    let mut out = [s.zero(); MOST];
    for (c, vector) in out.iter_mut().enumerate().take(W) {
        let mut lanes = [0.0; LANES];
        for (l, lane) in lanes.iter_mut().enumerate() {
            *lane = values[l * W + c];
        }
        *vector = s.load(lanes);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simd::{Kernel, Level, dispatch, test_levels};
    use crate::test_rng::Rng;

    /// Every operation on `x` and `y` (and the mask `bits`), as bits, at a level.
    struct EveryOperation {
        x: [f64; LANES],
        y: [f64; LANES],
        bits: Mask,
        records: [f64; LANES * MOST],
    }

    impl Kernel for &EveryOperation {
        type Output = Vec<u64>;

        #[inline(always)]
        fn run<S: Simd>(self, s: S) -> Vec<u64> {
            let (x, y) = (s.load(self.x), s.load(self.y));
            let vectors = [
                s.splat(self.x[0]),
                s.zero(),
                s.add(x, y),
                s.sub(x, y),
                s.mul(x, y),
                s.div(x, y),
                s.min(x, y),
                s.max(x, y),
                s.abs(x),
                s.sqrt(x),
                s.blend(s.mask(self.bits), x, y),
                s.unit_scale(x),
                s.fraction_cleared(x),
                s.mul_add(
                    x,
                    y,
                    s.load(self.records[..LANES].try_into().unwrap_or_default()),
                ),
                // A mask made by logic on a compare, through a select.
                s.blend(!s.lt(x, y) ^ s.mask(self.bits), x, y),
            ];
            let masks =
                [s.lt(x, y), s.gt(x, y), s.ge(x, y), s.eq(x, y), s.ne(x, y)].map(|m| s.bits(m));
            let m = s.mask(self.bits);
            let n = s.lt(x, y);
            let logic = [
                s.bits(m & n),
                s.bits(m | n),
                s.bits(m ^ n),
                s.bits(!m),
                u8::from(s.any(m)),
                u8::from(s.every(m)),
                s.bits(s.none()),
                s.bits(s.all()),
            ];
            let records = &self.records;
            let transposed = [
                s.transposed::<1>(records),
                s.transposed::<2>(records),
                s.transposed::<3>(records),
                s.transposed::<4>(records),
                s.transposed::<6>(records),
                s.transposed::<9>(records),
            ];
            // Which NaN an arithmetic operation on two NaNs returns is not fixed (the compiler
            // may swap the operands of `+` and `·`): there a NaN counts as any NaN. The
            // selections (min, max, abs, blend, the loads and the transposition) by bits.
            const ARITHMETIC: [usize; 6] = [2, 3, 4, 5, 9, 13];
            let mut out = Vec::new();
            for (k, v) in vectors.into_iter().enumerate() {
                for x in s.store(v) {
                    let any_nan = ARITHMETIC.contains(&k) && x.is_nan();
                    out.push(if any_nan {
                        f64::NAN.to_bits()
                    } else {
                        x.to_bits()
                    });
                }
            }
            for v in transposed.into_iter().flatten() {
                out.extend(s.store(v).map(f64::to_bits));
            }
            out.extend(logic.map(u64::from));
            out.extend(masks.map(u64::from));
            out
        }
    }

    /// Values where the levels could differ: NaNs, zeros of both signs, infinities,
    /// subnormals, the extremes, and ordinary numbers.
    fn value(rng: &mut Rng) -> f64 {
        match rng.below(12) {
            0 => f64::NAN,
            1 => -f64::NAN,
            2 => 0.0,
            3 => -0.0,
            4 => f64::INFINITY,
            5 => f64::NEG_INFINITY,
            6 => f64::MIN_POSITIVE * rng.uniform(-1.0, 1.0),
            7 => f64::MAX * rng.uniform(-1.0, 1.0),
            8 => (rng.below(5) as f64) - 2.0,
            _ => rng.uniform(-4.0, 4.0),
        }
    }

    #[test]
    fn every_operation_gives_the_portable_bits_at_every_level() {
        let levels = test_levels();
        let mut rng = Rng(35);
        for _ in 0..20_000 {
            let case = EveryOperation {
                x: std::array::from_fn(|_| value(&mut rng)),
                y: std::array::from_fn(|_| value(&mut rng)),
                bits: rng.below(256) as Mask,
                records: std::array::from_fn(|_| value(&mut rng)),
            };
            let portable = dispatch(Level::Portable, &case);
            for &level in &levels {
                let ours = dispatch(level, &case);
                let differ: Vec<_> = (0..ours.len())
                    .filter(|&k| ours[k] != portable[k])
                    .collect();
                assert!(
                    differ.is_empty(),
                    "{level}: at {differ:?} (vector, lane = k / 8, k % 8): {:x?} against {:x?}",
                    differ.iter().map(|&k| ours[k]).collect::<Vec<_>>(),
                    differ.iter().map(|&k| portable[k]).collect::<Vec<_>>(),
                );
            }
        }
        // The semantics the stages rely on, at the portable level.
        let nan = f64::NAN;
        let case = EveryOperation {
            x: [nan, 1.0, 0.0, -0.0, nan, 2.0, 3.0, 1.0],
            y: [1.0, nan, -0.0, 0.0, nan, 2.0, 1.0, 3.0],
            bits: 0b1010_1010,
            records: std::array::from_fn(|i| i as f64),
        };
        let out = dispatch(Level::Portable, &case);
        let lanes = |k: usize| -> Vec<u64> { out[k * LANES..(k + 1) * LANES].to_vec() };
        let bits = |v: [f64; LANES]| {
            v.map(|x| {
                if x.is_nan() {
                    f64::NAN.to_bits()
                } else {
                    x.to_bits()
                }
            })
            .to_vec()
        };
        // min: the second operand where either is NaN or both are zeros.
        assert_eq!(lanes(6), bits([1.0, nan, -0.0, 0.0, nan, 2.0, 1.0, 1.0]));
        assert_eq!(lanes(7), bits([1.0, nan, -0.0, 0.0, nan, 2.0, 3.0, 3.0]));
        let mask = |k: usize| out[out.len() - 5 + k] as Mask;
        assert_eq!(mask(0), 0b1000_0000, "lt: ordered");
        assert_eq!(mask(4), 0b1101_0011, "ne: unordered");
        // The mask logic on `m` = bits 0b1010_1010 and `n` = lt; `any`, `every`, `none`
        // and `all` are the trait's defaults at most levels, so they are checked here.
        let logic = |k: usize| out[out.len() - 13 + k] as Mask;
        assert_eq!(logic(0), 0b1000_0000, "m & n");
        assert_eq!(logic(1), 0b1010_1010, "m | n");
        assert_eq!(logic(2), 0b0010_1010, "m ^ n");
        assert_eq!(logic(3), 0b0101_0101, "!m");
        assert_eq!([logic(4), logic(5)], [1, 0], "any, every");
        assert_eq!([logic(6), logic(7)], [0, Mask::MAX], "none, all");
        // `!lt ^ m` selects y where exactly one of `x ≥ y or unordered` and m holds.
        assert_eq!(lanes(14), bits([1.0, 1.0, -0.0, -0.0, nan, 2.0, 1.0, 3.0]));
        // The unit scale: a normal number times it is in `[2, 4)`; `+∞` for a zero of either
        // sign, `+0` for a NaN.
        let inf = f64::INFINITY;
        assert_eq!(lanes(11), bits([0.0, 2.0, inf, inf, 0.0, 1.0, 1.0, 2.0]));
        assert_eq!(lanes(12), bits([inf, 1.0, 0.0, -0.0, inf, 2.0, 2.0, 1.0]));
        // The fused multiply-add: rounded once (`x·y + z` with `z = −x·y` rounded gives the
        // product's rounding error, 0 when rounded twice).
        let third = 1.0 + f64::EPSILON;
        let product = third * third;
        let case = EveryOperation {
            x: [third; LANES],
            y: [third; LANES],
            bits: 0,
            records: std::array::from_fn(|i| if i < LANES { -product } else { 0.0 }),
        };
        let out = dispatch(Level::Portable, &case);
        let fused = f64::from_bits(out[13 * LANES]);
        assert_eq!(
            fused,
            f64::EPSILON * f64::EPSILON,
            "the product's rounding error"
        );
        // Records of 3: lane `l` of vector `c` is value `3·l + c`.
        let three = 15 + MOST * 2;
        assert_eq!(
            lanes(three + 1),
            bits(std::array::from_fn(|l| (3 * l + 1) as f64))
        );
    }
}
