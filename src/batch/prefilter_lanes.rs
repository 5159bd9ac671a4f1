//! The friction batch's first stage, lane-wise over [`Simd`]: a block of [`LANES`] pairs read
//! into lanes, each pair brought into its own unit of length as
//! [`normalised`](crate::collision::length_unit::normalised) brings it, and screened by the
//! straight runs to rest ([`screen_runs`](crate::collision::prefilter::screen_runs)): the same
//! numbers and the same proof, to the bit (the batch's tests compare its answers with the
//! scalar search's at every level).
//!
//! One factor per lane, without [`LengthUnit`](crate::collision::length_unit::LengthUnit)'s
//! pre-scaling of a subnormal largest length: such a pair comes out with infinities or NaNs,
//! which fail the screen's range test, so it goes to the search, which normalises it in two
//! steps. For every other pair the pre-scaling is by 1, and both give the same numbers.

use super::eighth_lanes::bigger;
use super::{Pairs, PerPair};
use crate::collision::prefilter::{LIMIT, MARGIN, PairInput};
use crate::simd::{LANES, Simd};

/// A block of pairs in lanes, each in its own unit of length (lane `l`: pair `start + l`;
/// zeros past the block's length, which fail the range test: a radius must be positive).
#[derive(Clone, Copy)]
pub(super) struct PairLanes<S: Simd> {
    pub pos_a: [S::V; 2],
    pub vel_a: [S::V; 2],
    pub friction_a: S::V,
    pub pos_b: [S::V; 2],
    pub vel_b: [S::V; 2],
    pub friction_b: S::V,
    pub radius: S::V,
    pub t_max: S::V,
}

impl<S: Simd> PairLanes<S> {
    /// Pairs `start..start + len` (`len ≤ LANES`) of `pairs`, each in its own unit of length.
    #[inline(always)]
    pub(super) fn normalised(s: S, pairs: &Pairs<'_>, start: usize, len: usize) -> Self {
        let (pos_a, vel_a) = (
            rows(s, pairs.pos_a, start, len),
            rows(s, pairs.vel_a, start, len),
        );
        let (pos_b, vel_b) = (
            rows(s, pairs.pos_b, start, len),
            rows(s, pairs.vel_b, start, len),
        );
        let (friction_a, friction_b) = (
            scalars(s, pairs.friction_a, start, len),
            scalars(s, pairs.friction_b, start, len),
        );
        let radius = scalars(s, pairs.contact_distance, start, len);
        // The largest magnitude of the pair's eleven lengths, as `largest` forms it (a NaN
        // ignored): the rows' coordinates axis by axis, then the frictions and the radius.
        let mut rows_largest = [s.zero(); 2];
        for (axis, m) in rows_largest.iter_mut().enumerate() {
            let most = bigger(s, s.zero(), pos_a[axis]);
            let most = bigger(s, most, vel_a[axis]);
            let most = bigger(s, most, pos_b[axis]);
            *m = bigger(s, most, vel_b[axis]);
        }
        let [x, y] = rows_largest;
        let most = bigger(s, bigger(s, x, y), friction_a);
        let scale = s.unit_scale(bigger(s, bigger(s, most, friction_b), radius));
        // `+ 0`: a friction of −0 is no friction (as `LengthUnit::friction`).
        let zero = s.zero();
        Self {
            pos_a: scaled(s, pos_a, scale),
            vel_a: scaled(s, vel_a, scale),
            friction_a: s.add(s.mul(friction_a, scale), zero),
            pos_b: scaled(s, pos_b, scale),
            vel_b: scaled(s, vel_b, scale),
            friction_b: s.add(s.mul(friction_b, scale), zero),
            radius: s.mul(radius, scale),
            // A time: not scaled.
            t_max: scalars(s, pairs.t_max, start, len),
        }
    }

    /// The pairs `inputs` (each already in its own unit of length) in lanes.
    #[inline(always)]
    pub(super) fn of_inputs(s: S, inputs: &[PairInput; LANES]) -> Self {
        let mut values = [[0.0; LANES]; 12];
        for (l, p) in inputs.iter().enumerate() {
            let row = [
                p.pos_a[0],
                p.pos_a[1],
                p.vel_a[0],
                p.vel_a[1],
                p.friction_a,
                p.pos_b[0],
                p.pos_b[1],
                p.vel_b[0],
                p.vel_b[1],
                p.friction_b,
                p.radius,
                p.t_max,
            ];
            for (lanes, x) in values.iter_mut().zip(row) {
                lanes[l] = x;
            }
        }
        let v = |k: usize| s.load(values[k]);
        Self {
            pos_a: [v(0), v(1)],
            vel_a: [v(2), v(3)],
            friction_a: v(4),
            pos_b: [v(5), v(6)],
            vel_b: [v(7), v(8)],
            friction_b: v(9),
            radius: v(10),
            t_max: v(11),
        }
    }

    /// The lanes whose ball A, or B, is at rest (both velocity components zero).
    #[inline(always)]
    pub(super) fn at_rest(&self, s: S) -> (S::M, S::M) {
        (rests(s, self.vel_a), rests(s, self.vel_b))
    }

    /// The pairs of the lanes, one by one (for the stages that are not lane-wise).
    #[inline(always)]
    pub(super) fn inputs(&self, s: S) -> [PairInput; LANES] {
        let (pos_a, vel_a) = (stored(s, self.pos_a), stored(s, self.vel_a));
        let (pos_b, vel_b) = (stored(s, self.pos_b), stored(s, self.vel_b));
        let (friction_a, friction_b) = (s.store(self.friction_a), s.store(self.friction_b));
        let (radius, t_max) = (s.store(self.radius), s.store(self.t_max));
        let mut inputs = [PairInput::default(); LANES];
        for (l, input) in inputs.iter_mut().enumerate() {
            *input = PairInput {
                pos_a: [pos_a[0][l], pos_a[1][l]],
                vel_a: [vel_a[0][l], vel_a[1][l]],
                friction_a: friction_a[l],
                pos_b: [pos_b[0][l], pos_b[1][l]],
                vel_b: [vel_b[0][l], vel_b[1][l]],
                friction_b: friction_b[l],
                radius: radius[l],
                t_max: t_max[l],
            };
        }
        inputs
    }
}

/// The lanes where a ball with these velocities is at rest.
#[inline(always)]
fn rests<S: Simd>(s: S, [x, y]: [S::V; 2]) -> S::M {
    s.eq(x, s.zero()) & s.eq(y, s.zero())
}

/// Both coordinates' lanes.
#[inline(always)]
fn stored<S: Simd>(s: S, [x, y]: [S::V; 2]) -> [[f64; LANES]; 2] {
    [s.store(x), s.store(y)]
}

/// Both coordinates times `scale`.
#[inline(always)]
fn scaled<S: Simd>(s: S, [x, y]: [S::V; 2], scale: S::V) -> [S::V; 2] {
    [s.mul(x, scale), s.mul(y, scale)]
}

/// `x·x + y·y`.
#[inline(always)]
fn square<S: Simd>(s: S, [x, y]: [S::V; 2]) -> S::V {
    s.add(s.mul(x, x), s.mul(y, y))
}

/// `lo ≤ x ≤ hi`, as two ordered compares (NaN fails both).
#[inline(always)]
fn within<S: Simd>(s: S, x: S::V, lo: f64, hi: f64) -> S::M {
    s.ge(x, s.splat(lo)) & s.ge(s.splat(hi), x)
}

/// Rows `start..start + len` of `src` as lanes of x and of y (zeros past `len`).
#[inline(always)]
fn rows<S: Simd>(s: S, src: &[[f64; 2]], start: usize, len: usize) -> [S::V; 2] {
    let mut block = [[0.0; 2]; LANES];
    let values = match src.get(start..start + LANES) {
        Some(full) if len == LANES => full,
        _ => {
            for (slot, row) in block.iter_mut().zip(src.iter().skip(start).take(len)) {
                *slot = *row;
            }
            &block
        }
    };
    let [x, y, ..] = s.transposed::<2>(values.as_flattened());
    [x, y]
}

/// A per-pair scalar's values for pairs `start..start + len` as lanes (zeros past `len`).
#[inline(always)]
fn scalars<S: Simd>(s: S, src: PerPair<'_>, start: usize, len: usize) -> S::V {
    match src {
        PerPair::All(x) => s.splat(x),
        PerPair::Each(xs) => {
            let mut block = [0.0; LANES];
            match xs.get(start..start + LANES) {
                Some(full) if len == LANES => block.copy_from_slice(full),
                _ => {
                    for (slot, x) in block.iter_mut().zip(xs.iter().skip(start).take(len)) {
                        *slot = *x;
                    }
                }
            }
            s.load(block)
        }
    }
}

/// [`screen_runs`](crate::collision::prefilter::screen_runs) in every lane: the lanes in range
/// (valid, bounded, magnitudes in `[1/LIMIT, LIMIT]`), and those whose balls are proven never
/// to touch (meaningless where not in range). The same operations in the same order.
#[inline(always)]
pub(super) fn screen_runs<S: Simd>(s: S, p: &PairLanes<S>) -> (S::M, S::M) {
    let ([pax, pay], [vax, vay]) = (p.pos_a, p.vel_a);
    let ([pbx, pby], [vbx, vby]) = (p.pos_b, p.vel_b);
    let (square_a, square_b) = (square(s, p.vel_a), square(s, p.vel_b));
    let (speed_a, speed_b) = (s.sqrt(square_a), s.sqrt(square_b));
    let size = s.add(
        s.add(s.add(s.abs(pax), s.abs(pay)), s.add(s.abs(pbx), s.abs(pby))),
        p.radius,
    );
    let (dx, dy) = (s.sub(pbx, pax), s.sub(pby, pay));
    // (`−x` as `−1·x`: exact, the zeros' signs flipped too.)
    let minus = s.splat(-1.0);
    let off_a = line_side(
        s,
        [vax, vay],
        speed_a,
        [dx, dy],
        [vbx, vby],
        speed_b,
        p.friction_b,
        p.radius,
        size,
    );
    let off_b = line_side(
        s,
        [vbx, vby],
        speed_b,
        [s.mul(minus, dx), s.mul(minus, dy)],
        [vax, vay],
        speed_a,
        p.friction_a,
        p.radius,
        size,
    );
    let (rests_a, rests_b) = p.at_rest(s);
    let in_range = s.ge(s.splat(LIMIT), size)
        & within(s, p.radius, 1.0 / LIMIT, LIMIT)
        & s.ge(p.t_max, s.zero())
        & bounded(s, rests_a, square_a, p.friction_a)
        & bounded(s, rests_b, square_b, p.friction_b);
    (in_range, off_a | off_b)
}

/// The lanes whose ball (at rest or not, `|v|²`, friction `mu`) has a bounded motion, as
/// [`screen_runs`](crate::collision::prefilter::screen_runs) asks: at rest with a friction
/// ≥ 0, or moving at a speed in range with a friction in range.
#[inline(always)]
fn bounded<S: Simd>(s: S, rests: S::M, square: S::V, mu: S::V) -> S::M {
    s.ge(s.splat(LIMIT), mu)
        & ((rests & s.ge(mu, s.zero()))
            | (within(s, square, 1.0 / (LIMIT * LIMIT), LIMIT * LIMIT)
                & s.ge(mu, s.splat(1.0 / LIMIT))))
}

/// `line_side` of [`screen_runs`](crate::collision::prefilter::screen_runs) in every lane.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn line_side<S: Simd>(
    s: S,
    line: [S::V; 2],
    line_speed: S::V,
    offset: [S::V; 2],
    v: [S::V; 2],
    speed: S::V,
    mu: S::V,
    radius: S::V,
    size: S::V,
) -> S::M {
    let rests = s.eq(speed, s.zero());
    let scale = s.blend(rests, s.mul(s.splat(2.0), mu), s.splat(1.0));
    let start = s.mul(scale, cross(s, line, offset));
    let end = s.add(start, s.mul(cross(s, line, v), speed));
    let line_size = s.add(s.abs(line[0]), s.abs(line[1]));
    let slack = s.add(s.mul(scale, size), s.mul(speed, speed));
    let reach = s.add(
        s.mul(scale, s.mul(radius, line_speed)),
        s.mul(s.mul(s.splat(MARGIN), line_size), slack),
    );
    let below = s.mul(s.splat(-1.0), reach);
    (s.gt(start, reach) & s.gt(end, reach)) | (s.lt(start, below) & s.lt(end, below))
}

/// `line.x·v.y − line.y·v.x`.
#[inline(always)]
fn cross<S: Simd>(s: S, line: [S::V; 2], [x, y]: [S::V; 2]) -> S::V {
    s.sub(s.mul(line[0], y), s.mul(line[1], x))
}
