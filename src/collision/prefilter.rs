//! A whole-trajectory proof that two balls never touch, cheap enough to run on every pair of a
//! batch before the search proper.
//!
//! A ball with friction runs along the segment from its start `p` to its resting point
//! `q = p + v·τ/2` and stays there, so two balls whose segments are farther apart than the
//! contact distance never touch, whatever their timing. The segments are shown apart along
//! one of six directions (separating axes): the two coordinate axes, each ball's direction
//! of motion and its normal. That settles nine in ten random pairs on a table with a few
//! dozen operations, no branch and no library call, so that a batch evaluates it lane-wise
//! (the compiler vectorises [`never_touch`] over a block of pairs) and sends only the
//! survivors to the scalar search.
//!
//! Only proofs are taken: the separation must exceed the contact distance by a margin far
//! above every rounding error made here, so a pair said never to touch has no contact, and the
//! scalar search answers "none" for it too (its own rounding is smaller still). Anything
//! invalid (NaN, infinities, negative friction, a non-positive radius or a negative or NaN
//! horizon) or unbounded (a frictionless mover) fails the test and goes to the scalar path,
//! which reports it.

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

/// Relative size of the margin: `2⁻⁴⁰ ≈ 9e-13` of the magnitudes involved, some sixty times
/// the worst rounding error of the arithmetic below (each computed coordinate errs by at most
/// about `8ε` of the largest coordinate, each projection by `≤ 20ε·|w|·S`, `ε = 2⁻⁵³`).
const MARGIN: f64 = 1.0 / ((1u64 << 40) as f64);

/// Magnitudes (lengths, speeds) inside `[1/LIMIT, LIMIT]` keep every product here in the
/// normal range; pairs outside it are left to the scalar search.
const LIMIT: f64 = 1e100;

/// A speed computed without overflow or loss to underflow: exactly zero for a ball at rest,
/// or within `[1/LIMIT, LIMIT]`.
#[inline(always)]
fn plain_speed(speed: f64, vx: f64, vy: f64) -> bool {
    ((vx == 0.0) & (vy == 0.0)) | (1.0 / LIMIT..=LIMIT).contains(&speed)
}

/// Whether the two balls of `pair` provably never touch (and the inputs are valid and the
/// motions bounded). `false` means "not proven".
///
/// Written without branches (comparisons combine with `&`, choices are `min`/`max`) so that a
/// loop over a block of pairs vectorises; the same function serves one pair.
#[inline(always)]
pub(crate) fn never_touch(pair: &PairInput) -> bool {
    let [pax, pay] = pair.pos_a;
    let [vax, vay] = pair.vel_a;
    let [pbx, pby] = pair.pos_b;
    let [vbx, vby] = pair.vel_b;
    let (mu_a, mu_b, radius) = (pair.friction_a, pair.friction_b, pair.radius);

    // τ/2 = |v|/(2μ); a ball at rest has none (its 0/0 becomes 0 through `min`), a
    // frictionless mover an infinite one, rejected below.
    let speed_a = (vax * vax + vay * vay).sqrt();
    let speed_b = (vbx * vbx + vby * vby).sqrt();
    let half_a = (speed_a / (2.0 * mu_a)).min(f64::MAX);
    let half_b = (speed_b / (2.0 * mu_b)).min(f64::MAX);
    let half_a = if speed_a > 0.0 { half_a } else { 0.0 };
    let half_b = if speed_b > 0.0 { half_b } else { 0.0 };
    let (qax, qay) = (pax + vax * half_a, pay + vay * half_a);
    let (qbx, qby) = (pbx + vbx * half_b, pby + vby * half_b);

    // S: the largest coordinate magnitude, which bounds every rounding error below.
    let size = (pax.abs().max(pay.abs()).max(qax.abs()).max(qay.abs()))
        .max(pbx.abs().max(pby.abs()).max(qbx.abs()).max(qby.abs()));
    let slack = MARGIN * (size + radius);

    // Separation of the two segments' shadows on direction w = (wx, wy), against
    // (radius + slack)·|w| (|w| ≤ |wx| + |wy|, the bound the margin is taken on).
    let apart = |wx: f64, wy: f64, length: f64| {
        let (a0, a1) = (wx * pax + wy * pay, wx * qax + wy * qay);
        let (b0, b1) = (wx * pbx + wy * pby, wx * qbx + wy * qby);
        let gap = (b0.min(b1) - a0.max(a1)).max(a0.min(a1) - b0.max(b1));
        gap > radius * length + slack * (wx.abs() + wy.abs())
    };
    let separated = apart(1.0, 0.0, 1.0)
        | apart(0.0, 1.0, 1.0)
        | apart(vax, vay, speed_a)
        | apart(-vay, vax, speed_a)
        | apart(vbx, vby, speed_b)
        | apart(-vby, vbx, speed_b);

    // Valid and bounded: both stop points finite, magnitudes plain.
    let valid = valid(pair)
        & (half_a < f64::MAX)
        & (half_b < f64::MAX)
        // Magnitudes where no product overflows and none underflows enough to matter
        // against the margin (every rounding error stays relative, or far below the slack).
        & (size <= LIMIT)
        & (1.0 / LIMIT..=LIMIT).contains(&radius)
        & plain_speed(speed_a, vax, vay)
        & plain_speed(speed_b, vbx, vby);
    separated & valid
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

#[cfg(test)]
mod tests {
    use super::*;

    fn pair(pos_a: [f64; 2], vel_a: [f64; 2], pos_b: [f64; 2], vel_b: [f64; 2]) -> PairInput {
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

    #[test]
    fn parallel_lanes_never_touch() {
        // Both run along x, 1 apart: the normal of either motion separates them.
        assert!(never_touch(&pair(
            [0.0, 0.0],
            [2.0, 0.0],
            [1.0, 1.0],
            [-2.0, 0.0]
        )));
    }

    #[test]
    fn crossing_paths_are_not_proven_apart() {
        // The paths cross (whether the balls meet depends on timing: the search decides).
        assert!(!never_touch(&pair(
            [0.0, 0.0],
            [2.0, 0.0],
            [1.0, -1.0],
            [0.0, 2.0]
        )));
    }

    #[test]
    fn a_ball_stopping_short_is_proven_apart() {
        // A stops after 2 (v²/2μ), 0.5 short of B at rest: the direction of motion separates.
        assert!(never_touch(&pair(
            [0.0, 0.0],
            [2.0, 0.0],
            [2.6, 0.0],
            [0.0, 0.0]
        )));
        // 0.05 further it would touch.
        assert!(!never_touch(&pair(
            [0.0, 0.0],
            [2.0, 0.0],
            [2.05, 0.0],
            [0.0, 0.0]
        )));
    }

    #[test]
    fn invalid_or_unbounded_inputs_are_never_proven() {
        let far = pair([0.0, 0.0], [1.0, 0.0], [0.0, 10.0], [0.0, 0.0]);
        assert!(never_touch(&far));
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
            assert!(!never_touch(&bad), "{bad:?}");
        }
        // Balls at rest, with or without friction, are points.
        assert!(never_touch(&PairInput {
            friction_a: 0.0,
            vel_a: [0.0, 0.0],
            ..far
        }));
    }

    #[test]
    fn overlapping_balls_are_never_proven_apart() {
        assert!(!never_touch(&pair(
            [0.0, 0.0],
            [1.0, 0.0],
            [0.05, 0.0],
            [0.0, 0.0]
        )));
    }
}
