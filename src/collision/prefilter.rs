//! A whole-trajectory proof that two balls never touch, cheap enough to run on every pair of a
//! batch before the search proper.
//!
//! A ball with friction runs along the segment from its start `p` to its resting point
//! `q = p + v·τ/2` and stays there, so two balls never touch if one ball's whole segment
//! stays farther than the contact distance from the other's line of motion (on one side of
//! it), whatever their timing. Both lines are tried. On random pairs on a table that settles
//! nine in ten with two square roots and a few dozen operations, no division, no branch and no
//! library call, so that a batch evaluates it lane-wise (its lane twin,
//! `batch/prefilter_lanes.rs`, the same operations over the SIMD layer) and sends only the
//! survivors on.
//!
//! Only proofs are taken: the separation must exceed the contact distance by a margin far
//! above every rounding error made here, so a pair said never to touch has no contact, and the
//! scalar search answers "none" for it too (its own rounding is smaller still). Anything
//! invalid (NaN, infinities, negative friction, a non-positive radius or a negative or NaN
//! horizon) or unbounded (a frictionless mover) fails the test and goes to the scalar path,
//! which reports it.

use crate::motion::Ball;

/// One pair's inputs, as a batch row holds them.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct PairInput {
    /// Centre of A.
    pub pos_a: [f64; 2],
    /// Velocity of A.
    pub vel_a: [f64; 2],
    /// Friction deceleration of A.
    pub friction_a: f64,
    /// Centre of B.
    pub pos_b: [f64; 2],
    /// Velocity of B.
    pub vel_b: [f64; 2],
    /// Friction deceleration of B.
    pub friction_b: f64,
    /// Contact distance.
    pub radius: f64,
    /// Horizon.
    pub t_max: f64,
}

impl PairInput {
    /// The inputs of two balls, as a batch row holds them.
    pub(crate) fn of(a: &Ball, b: &Ball, radius: f64, t_max: f64) -> Self {
        Self {
            pos_a: a.position().into(),
            vel_a: a.velocity().into(),
            friction_a: a.friction(),
            pos_b: b.position().into(),
            vel_b: b.velocity().into(),
            friction_b: b.friction(),
            radius,
            t_max,
        }
    }
}

/// Relative size of the margin: `2⁻⁴⁰ ≈ 9e-13` of the magnitudes involved, far above the
/// worst rounding error of the arithmetic below (a few `ε = 2⁻⁵³` of the same magnitudes).
pub(crate) const MARGIN: f64 = 1.0 / ((1u64 << 40) as f64);

/// Magnitudes (lengths, speeds, frictions) inside `[1/LIMIT, LIMIT]` keep every product of up
/// to three of them here in the normal range; pairs outside it are left to the scalar search.
pub(crate) const LIMIT: f64 = 1e100;

/// Whether the two balls of `pair` provably never touch (and the inputs are valid and the
/// motions bounded). `false` means "not proven".
///
/// ```text
/// screened_out_by_runs(pair) == in_range & apart, where (in_range, apart) = screen_runs(pair)
/// ```
#[inline(always)]
pub(crate) fn screened_out_by_runs(pair: &PairInput) -> bool {
    let (in_range, apart) = screen_runs(pair);
    in_range & apart
}

/// Whether `pair` is in range: valid (as [`valid`]: every number finite, frictions ≥ 0,
/// radius > 0, horizon ≥ 0) with bounded motions (each ball at rest, or moving with friction)
/// and every magnitude in `[1/LIMIT, LIMIT]`; and, if so, whether its balls provably never
/// touch (if not, that is meaningless).
///
/// A batch gets both for the price of the proof: its survivors that are in range need no other
/// validation before the lane-wise stages.
///
/// Written without branches (comparisons combine with `&`, choices are selects) so that a
/// loop over a block of pairs vectorises; the same function serves one pair.
#[inline(always)]
pub(crate) fn screen_runs(pair: &PairInput) -> (bool, bool) {
    let [pax, pay] = pair.pos_a;
    let [vax, vay] = pair.vel_a;
    let [pbx, pby] = pair.pos_b;
    let [vbx, vby] = pair.vel_b;
    let (mu_a, mu_b, radius) = (pair.friction_a, pair.friction_b, pair.radius);
    let (square_a, square_b) = (vax * vax + vay * vay, vbx * vbx + vby * vby);
    let speed_a = square_a.sqrt();
    let speed_b = square_b.sqrt();
    // Every coordinate the two segments start from is below `size` in magnitude. A sum
    // rather than a maximum: one instruction each, and a NaN or an infinity carries through
    // to the range test below.
    let size = ((pax.abs() + pay.abs()) + (pbx.abs() + pby.abs())) + radius;
    let (dx, dy) = (pbx - pax, pby - pay);
    // B's segment against A's line, then A's against B's (the offset reversed).
    let off_a = line_side(
        [vax, vay],
        speed_a,
        [dx, dy],
        [vbx, vby],
        speed_b,
        mu_b,
        radius,
        size,
    );
    let off_b = line_side(
        [vbx, vby],
        speed_b,
        [-dx, -dy],
        [vax, vay],
        speed_a,
        mu_a,
        radius,
        size,
    );
    // Valid and bounded, magnitudes in range: every rounding error stays relative (nothing
    // overflows, nothing underflows enough to matter against the margin). This implies
    // [`valid`]: every number is finite (NaN fails every comparison), frictions ≥ 0,
    // radius > 0, horizon ≥ 0.
    let magnitude_in_range = |x: f64| (1.0 / LIMIT..=LIMIT).contains(&x);
    // At rest (exactly) with a friction ≥ 0, or moving at a speed in range with a friction in
    // range (a frictionless mover runs for ever, and an underflowing |v|² would pass for rest).
    // The speed's range is tested on its square, which is ready sooner.
    let square_in_range = |x: f64| (1.0 / (LIMIT * LIMIT)..=LIMIT * LIMIT).contains(&x);
    let bounded = |[vx, vy]: [f64; 2], square: f64, mu: f64| {
        (mu <= LIMIT)
            & (((vx == 0.0) & (vy == 0.0) & (mu >= 0.0))
                | (square_in_range(square) & (mu >= 1.0 / LIMIT)))
    };
    let in_range = (size <= LIMIT)
        & magnitude_in_range(radius)
        & (pair.t_max >= 0.0)
        & bounded(pair.vel_a, square_a, mu_a)
        & bounded(pair.vel_b, square_b, mu_b);
    (in_range, off_a | off_b)
}

/// Whether the segment of the ball with velocity `v`, speed `speed` and friction `mu`, which
/// starts at `offset` from a point of the line through the other ball along `line` (speed
/// `line_speed`), stays on one side of that line, more than `radius` from it.
///
/// Distances to the line are measured along its normal `(−line.y, line.x)`, of length
/// `line_speed`, and scaled by `2μ` so that the segment's end `offset + v·|v|/(2μ)` needs no
/// division (a ball at rest is its own end, with scale 1). The slack covers every rounding
/// error in units of the magnitudes: the start's coordinates (`size`) and the travel
/// (`|v|²/2μ`, scaled: `|v|²`).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn line_side(
    line: [f64; 2],
    line_speed: f64,
    offset: [f64; 2],
    v: [f64; 2],
    speed: f64,
    mu: f64,
    radius: f64,
    size: f64,
) -> bool {
    let rests = speed == 0.0;
    let scale = if rests { 1.0 } else { 2.0 * mu };
    let start = scale * (line[0] * offset[1] - line[1] * offset[0]);
    let end = start + (line[0] * v[1] - line[1] * v[0]) * speed;
    let reach = scale * (radius * line_speed)
        + MARGIN * (line[0].abs() + line[1].abs()) * (scale * size + speed * speed);
    ((start > reach) & (end > reach)) | ((start < -reach) & (end < -reach))
}

/// Whether the scalar path would accept `pair`: every number finite (NaN fails every
/// comparison; the horizon may be `∞`), frictions ≥ 0, radius > 0, horizon ≥ 0.
#[inline(always)]
pub(crate) fn valid(pair: &PairInput) -> bool {
    let finite = |x: f64| x.abs() <= f64::MAX;
    let [pax, pay] = pair.pos_a;
    let [vax, vay] = pair.vel_a;
    let [pbx, pby] = pair.pos_b;
    let [vbx, vby] = pair.vel_b;
    finite(pax)
        & finite(pay)
        & finite(vax)
        & finite(vay)
        & finite(pbx)
        & finite(pby)
        & finite(vbx)
        & finite(vby)
        & finite(pair.friction_a)
        & finite(pair.friction_b)
        & finite(pair.radius)
        & (pair.friction_a >= 0.0)
        & (pair.friction_b >= 0.0)
        & (pair.radius > 0.0)
        & (pair.t_max >= 0.0)
}

/// Helpers for the tests of this module and of [`crossing`](super::crossing).
#[cfg(test)]
pub(crate) mod test_support {
    use super::PairInput;
    use crate::collision::first_contact;
    use crate::motion::Ball;
    use crate::test_rng::Rng;
    use nalgebra::Vector2;

    /// A pair with friction 1 on both balls, contact distance 0.1 and no horizon.
    pub(crate) fn pair(
        pos_a: [f64; 2],
        vel_a: [f64; 2],
        pos_b: [f64; 2],
        vel_b: [f64; 2],
    ) -> PairInput {
        PairInput {
            pos_a,
            vel_a,
            friction_a: 1.0,
            pos_b,
            vel_b,
            friction_b: 1.0,
            radius: 0.1,
            t_max: f64::INFINITY,
        }
    }

    /// A ball anywhere in the square of half-side `scale` round the origin, moving in any
    /// direction at 0.1–3 `scale` per unit time, with friction 0.05–2 `scale`: position,
    /// velocity and friction.
    pub(crate) fn moving_ball(rng: &mut Rng, scale: f64) -> Drawn {
        let p = [
            rng.uniform(-1.0, 1.0) * scale,
            rng.uniform(-1.0, 1.0) * scale,
        ];
        let (s, a) = (rng.uniform(0.1, 3.0) * scale, rng.uniform(0.0, 6.3));
        (
            p,
            [s * a.cos(), s * a.sin()],
            rng.uniform(0.05, 2.0) * scale,
        )
    }

    /// A ball as [`moving_ball`] draws it: position, velocity and friction.
    pub(crate) type Drawn = ([f64; 2], [f64; 2], f64);

    /// Balls `a` and `b` (as [`moving_ball`] draws them) at contact distance `radius`, with
    /// horizon `t_max`.
    pub(crate) fn pair_of(a: Drawn, b: Drawn, radius: f64, t_max: f64) -> PairInput {
        PairInput {
            pos_a: a.0,
            vel_a: a.1,
            friction_a: a.2,
            pos_b: b.0,
            vel_b: b.1,
            friction_b: b.2,
            radius,
            t_max,
        }
    }

    /// The search's answer for a valid `pair`.
    pub(crate) fn search(pair: &PairInput) -> Option<f64> {
        let ball = |p: [f64; 2], v: [f64; 2], mu: f64| {
            Ball::new(Vector2::from(p), Vector2::from(v), mu).map_err(|e| e.to_string())
        };
        match (
            ball(pair.pos_a, pair.vel_a, pair.friction_a),
            ball(pair.pos_b, pair.vel_b, pair.friction_b),
        ) {
            (Ok(a), Ok(b)) => first_contact(&a, &b, pair.radius, pair.t_max),
            (a, b) => panic!("invalid test pair: {a:?} {b:?}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::test_support::{pair, search};
    use super::*;
    use crate::test_rng::Rng;

    #[test]
    fn parallel_lanes_never_touch() {
        // Both run along x, 1 apart: the normal of either motion separates them.
        assert!(screened_out_by_runs(&pair(
            [0.0, 0.0],
            [2.0, 0.0],
            [1.0, 1.0],
            [-2.0, 0.0]
        )));
    }

    #[test]
    fn crossing_paths_are_not_proven_apart() {
        // The paths cross (whether the balls meet depends on timing: the search decides).
        assert!(!screened_out_by_runs(&pair(
            [0.0, 0.0],
            [2.0, 0.0],
            [1.0, -1.0],
            [0.0, 2.0]
        )));
    }

    #[test]
    fn a_segment_ending_short_of_the_line_is_proven_apart() {
        // B runs down from y = 3 at 2 m/s, μ = 1: it stops at y = 1, 0.9 beyond A's line
        // (which A follows up to x = 8, past B's).
        assert!(screened_out_by_runs(&pair(
            [0.0, 0.0],
            [4.0, 0.0],
            [5.0, 3.0],
            [0.0, -2.0]
        )));
        // From y = 2.05 it stops within 0.05 of the line, and A might meet it there.
        assert!(!screened_out_by_runs(&pair(
            [0.0, 0.0],
            [4.0, 0.0],
            [5.0, 2.05],
            [0.0, -2.0]
        )));
        // Timing and extent along the line are not this test's business: a ball stopping
        // short of a resting ball on its own line is left to the search.
        assert!(!screened_out_by_runs(&pair(
            [0.0, 0.0],
            [2.0, 0.0],
            [2.6, 0.0],
            [0.0, 0.0]
        )));
    }

    #[test]
    fn invalid_or_unbounded_inputs_are_never_proven() {
        let far = pair([0.0, 0.0], [1.0, 0.0], [0.0, 10.0], [0.0, 0.0]);
        assert!(screened_out_by_runs(&far));
        for bad in [
            PairInput {
                friction_a: 0.0,
                ..far
            }, // frictionless: an unbounded ray
            PairInput {
                friction_a: -1.0,
                ..far
            },
            PairInput {
                friction_b: f64::NAN,
                ..far
            },
            PairInput { radius: 0.0, ..far },
            PairInput {
                radius: f64::INFINITY,
                ..far
            },
            PairInput { t_max: -1.0, ..far },
            PairInput {
                t_max: f64::NAN,
                ..far
            },
            PairInput {
                pos_b: [0.0, f64::INFINITY],
                ..far
            },
            PairInput {
                vel_a: [f64::NAN, 0.0],
                ..far
            },
            PairInput {
                pos_a: [1e308, 0.0],
                vel_a: [1e308, 0.0],
                ..far
            }, // stop point overflows
            PairInput {
                vel_a: [1e-170, 0.0],
                friction_a: 1e-300,
                ..far
            }, // v² underflows
        ] {
            assert!(!screened_out_by_runs(&bad), "{bad:?}");
        }
        // A ball at rest, with or without friction, is a point (here 10 from B's line).
        assert!(screened_out_by_runs(&PairInput {
            friction_a: 0.0,
            vel_a: [0.0, 0.0],
            vel_b: [1.0, 0.0],
            ..far
        }));
    }

    #[test]
    fn pairs_in_range_are_valid() {
        // Every field ordinary (0 included) or, one time in ten, hostile: whatever
        // `screen_runs` calls in range, `valid` accepts (the batch sends survivors in range on
        // without validating them).
        let hostile = [
            -0.0,
            -1.0,
            1e-120,
            1e120,
            f64::MAX,
            f64::MIN_POSITIVE,
            f64::INFINITY,
            -f64::INFINITY,
            f64::NAN,
        ];
        let mut rng = Rng(0xba5e);
        let mut draw = |low: f64, high: f64| {
            let pick = rng.uniform(0.0, 10.0 * hostile.len() as f64) as usize;
            match hostile.get(pick) {
                Some(&x) => x,
                None if pick.is_multiple_of(4) => 0.0,
                None => rng.uniform(low, high),
            }
        };
        let (mut in_range_count, mut rejected) = (0, 0);
        for _ in 0..100_000 {
            let pair = PairInput {
                pos_a: [draw(-2.0, 2.0), draw(-2.0, 2.0)],
                vel_a: [draw(-3.0, 3.0), draw(-3.0, 3.0)],
                friction_a: draw(0.0, 2.0),
                pos_b: [draw(-2.0, 2.0), draw(-2.0, 2.0)],
                vel_b: [draw(-3.0, 3.0), draw(-3.0, 3.0)],
                friction_b: draw(0.0, 2.0),
                radius: draw(0.01, 0.1),
                t_max: draw(0.0, 10.0),
            };
            let (in_range, _) = screen_runs(&pair);
            assert!(!in_range || valid(&pair), "{pair:?}");
            in_range_count += usize::from(in_range);
            rejected += usize::from(!valid(&pair));
        }
        assert!(
            in_range_count > 10_000 && rejected > 10_000,
            "{in_range_count} in range, {rejected} invalid"
        );
    }

    #[test]
    fn overlapping_balls_are_never_proven_apart() {
        assert!(!screened_out_by_runs(&pair(
            [0.0, 0.0],
            [1.0, 0.0],
            [0.05, 0.0],
            [0.0, 0.0]
        )));
    }

    #[test]
    fn a_proof_is_never_contradicted_by_the_search() {
        // B's path ends (or, at rest, B sits) within R·(1 ± δ) of A's line, δ from 1e-2 down
        // to 1e-15, at scales from 1e-6 to 1e6: the proofs must hold where the search looks
        // hardest, and must still settle most of the pairs that clear the line by 1e-10 or more.
        let mut rng = Rng(0x5eed);
        let (mut proven, mut clear) = (0, 0);
        for k in 0..20_000 {
            let scale = 10f64.powf(rng.uniform(-6.0, 6.0));
            let radius = 0.05715 * scale;
            let angle = rng.uniform(0.0, 6.3);
            let (ux, uy) = (angle.cos(), angle.sin());
            let speed_a = rng.uniform(0.1, 3.0) * scale;
            let pa = [
                rng.uniform(-1.0, 1.0) * scale,
                rng.uniform(-1.0, 1.0) * scale,
            ];
            let delta = 10f64.powf(rng.uniform(-15.0, -2.0));
            let side = if k % 2 == 0 { 1.0 } else { -1.0 };
            let aside = side * radius * (1.0 + if k % 4 < 2 { delta } else { -delta });
            // B's end: `along` down A's line, `aside` off it; B comes from farther out.
            let along = rng.uniform(0.0, 2.0) * scale;
            let end = [
                pa[0] + along * ux - aside * uy,
                pa[1] + along * uy + aside * ux,
            ];
            let (mu_b, speed_b) = (
                rng.uniform(0.05, 2.0) * scale,
                rng.uniform(0.0, 3.0) * scale,
            );
            let travel = speed_b * speed_b / (2.0 * mu_b);
            let b_angle = rng.uniform(0.0, 6.3);
            let (bx, by) = (b_angle.cos(), b_angle.sin());
            // Only directions that keep B's start on the same side as its end.
            let (bx, by) = if (bx * -uy + by * ux) * side > 0.0 {
                (-bx, -by)
            } else {
                (bx, by)
            };
            let pb = [end[0] - bx * travel, end[1] - by * travel];
            let pair = PairInput {
                pos_a: pa,
                vel_a: [speed_a * ux, speed_a * uy],
                friction_a: rng.uniform(0.05, 2.0) * scale,
                pos_b: pb,
                vel_b: [speed_b * bx, speed_b * by],
                friction_b: mu_b,
                radius,
                t_max: f64::INFINITY,
            };
            if screened_out_by_runs(&pair) {
                proven += 1;
                assert_eq!(search(&pair), None, "{pair:?}");
            }
            clear += usize::from(aside.abs() > radius * (1.0 + 1e-10));
        }
        assert!(
            proven > clear / 2,
            "only {proven} of {clear} clear pairs proven apart"
        );
    }
}
