//! The invariants that every valid input must satisfy, checked by the fuzz targets (`fuzz/`)
//! and by the property tests (`tests/invariants.rs`): one implementation for both.
//!
//! Each check returns `Err` with a message naming the invariant and the inputs; the callers
//! panic with it (a fuzz crash, a failing property).
//!
//! - the pair search ([`pair`]): valid input never errors; a time is never NaN, negative or
//!   infinite; a horizon only cuts (with `t_max` the answer is the same bits as without it if
//!   `t < t_max`, else none), for the case's horizon and for horizons just past the contact
//!   time `t` and far beyond it (`t⁺`, `1.5t`, `t + 1`, 10, 1e10, 1e300); swapping A and B, flipping the sign of every zero, scaling every
//!   length (positions, velocities, frictions, radius) by `2^k`, and scaling time by `2^m`
//!   (velocities by `2^m`, frictions by `2^2m`, the horizon by `2^-m`) change no bit of the
//!   answer, whenever the scaled inputs are exact;
//! - the batch ([`batch`]): every pair's time is the scalar search's, bit for bit, on one
//!   thread and on two;
//! - the scene ([`scene`]): the broad phase, all pairs, one thread and two give the matrix of
//!   the brute-force pair loop, bit for bit, and the earliest collision and first contacts
//!   are read off it with the documented tie-breaking; flipping zeros and scaling lengths
//!   change no bit;
//! - the polynomial solvers ([`poly`]): roots sorted, not NaN, finite unless a root can exceed
//!   the float range; each a root within [`ROOT_ROUNDINGS`] roundings of every coefficient
//!   (exact evaluation), or within an ulp of one; no root lost: between two sample points with no computed root
//!   between them the exact polynomial keeps its sign, unless it is within rounding of zero at
//!   one of them; power-of-two scalings of the coefficients and of the variable, and flipping
//!   the sign of zeros, change no bit beyond the exact rescaling.

#![allow(dead_code)]

use ballcollide::batch::{Pairs, PerPair, Threads, collision_times};
use ballcollide::poly::real_roots;
use ballcollide::scene::{
    PairSearch, SceneOptions, earliest_collision, first_contacts, pairwise_collision_times,
};
use ballcollide::{Ball, CollisionOptions, collision_time_with};
use nalgebra::Vector2;
use std::num::NonZeroUsize;

use super::exact::{sign_exact, within_backward_error};

/// Contacts later than this are not reported (docs/contract.md); the time scaling is checked
/// only where every time involved, before and after scaling, is earlier.
pub const LATEST: f64 = 1e301;

/// The outcome of one check.
pub type Check = Result<(), String>;

/// One ball's inputs: position x, y, velocity x, y, friction.
pub type BallInput = [f64; 5];

/// A pair query: two balls, the contact distance and the horizon (`∞` for none).
#[derive(Clone, Copy, Debug)]
pub struct PairCase {
    /// Ball A.
    pub a: BallInput,
    /// Ball B.
    pub b: BallInput,
    /// Contact distance (> 0).
    pub radius: f64,
    /// Horizon (≥ 0, `∞` allowed).
    pub t_max: f64,
}

/// Whether the inputs of a ball are valid: finite, friction ≥ 0.
pub fn valid_ball(x: &BallInput) -> bool {
    x.iter().all(|v| v.is_finite()) && x[4] >= 0.0
}

impl PairCase {
    /// Whether every input is valid (the checks below are for valid inputs only).
    pub fn is_valid(&self) -> bool {
        valid_ball(&self.a)
            && valid_ball(&self.b)
            && self.radius.is_finite()
            && self.radius > 0.0
            && self.t_max >= 0.0
    }
}

fn ball(x: &BallInput) -> Result<Ball, String> {
    Ball::new(Vector2::new(x[0], x[1]), Vector2::new(x[2], x[3]), x[4])
        .map_err(|e| format!("valid ball {x:?} rejected: {e}"))
}

/// `x·2^k` if that is exact (finite, and back to `x` when scaled back), else `None`.
pub fn scaled_exactly(x: f64, k: i32) -> Option<f64> {
    let y = x * 2f64.powi(k / 2) * 2f64.powi(k - k / 2);
    let back = y * 2f64.powi(-(k / 2)) * 2f64.powi(-(k - k / 2));
    (y.is_finite() && back.to_bits() == x.to_bits()).then_some(y)
}

/// Every zero of `x` with its sign flipped.
fn flip_zeros(x: f64) -> f64 {
    if x == 0.0 { -x } else { x }
}

/// The search's answer for a pair (valid input must not error).
fn time_of(a: &BallInput, b: &BallInput, radius: f64, t_max: f64) -> Result<Option<f64>, String> {
    let (ba, bb) = (ball(a)?, ball(b)?);
    collision_time_with(&ba, &bb, radius, &CollisionOptions { t_max })
        .map_err(|e| format!("valid pair {a:?} {b:?} radius {radius:e} t_max {t_max:e}: {e}"))
}

fn same(x: Option<f64>, y: Option<f64>) -> bool {
    x.map(f64::to_bits) == y.map(f64::to_bits)
}

/// Whether the non-zero magnitudes among `values` are within 2^±400 of each other: the range
/// in which the contract promises exact answers (docs/contract.md §5).
pub fn within_contract_range(values: impl Iterator<Item = f64>) -> bool {
    let (lo, hi) = values
        .map(f64::abs)
        .filter(|&x| x > 0.0)
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), x| {
            (lo.min(x), hi.max(x))
        });
    hi <= lo * 2f64.powi(400)
}

/// The pair invariants, with `k` the exponent of the length scaling and `m` that of the
/// time scaling.
pub fn pair(case: &PairCase, k: i32, m: i32) -> Check {
    if !case.is_valid() {
        return Ok(());
    }
    let PairCase {
        a,
        b,
        radius,
        t_max,
    } = *case;
    let free = time_of(&a, &b, radius, f64::INFINITY)?;
    let cut = time_of(&a, &b, radius, t_max)?;
    for (what, t) in [("without horizon", free), ("with horizon", cut)] {
        if let Some(t) = t
            && !(t >= 0.0 && t.is_finite())
        {
            return Err(format!("{what}: time {t:e} for {case:?}"));
        }
    }
    let want = free.filter(|&t| t < t_max);
    if !same(cut, want) {
        return Err(format!(
            "a horizon must only cut: without it {free:?}, with t_max = {t_max:e} {cut:?}, for {case:?}"
        ));
    }
    // Horizons just past the contact and far beyond it, where the search's windows differ
    // most from the unbounded search's.
    if let Some(t) = free {
        for h in [t.next_up(), t * 1.5, t + 1.0, 10.0, 1e10, 1e300] {
            let got = time_of(&a, &b, radius, h)?;
            if !same(got, free.filter(|&t| t < h)) {
                return Err(format!(
                    "a horizon must only cut: without it {free:?}, with t_max = {h:e} {got:?}, \
                     for {case:?}"
                ));
            }
        }
    }
    let swapped = time_of(&b, &a, radius, t_max)?;
    if !same(swapped, cut) {
        return Err(format!(
            "A/B swap: {cut:?} became {swapped:?}, for {case:?}"
        ));
    }
    let z = |x: &BallInput| x.map(flip_zeros);
    let flipped = time_of(&z(&a), &z(&b), radius, flip_zeros(t_max))?;
    if !same(flipped, cut) {
        return Err(format!(
            "−0.0 = +0.0: {cut:?} became {flipped:?} with every zero's sign flipped, for {case:?}"
        ));
    }
    let scale_len = |x: &BallInput| -> Option<BallInput> {
        let mut y = [0.0; 5];
        for (yi, &xi) in y.iter_mut().zip(x) {
            *yi = scaled_exactly(xi, k)?;
        }
        Some(y)
    };
    if let (Some(sa), Some(sb), Some(sr)) =
        (scale_len(&a), scale_len(&b), scaled_exactly(radius, k))
    {
        let s_free = time_of(&sa, &sb, sr, f64::INFINITY)?;
        let s_cut = time_of(&sa, &sb, sr, t_max)?;
        if !same(s_free, free) || !same(s_cut, cut) {
            return Err(format!(
                "lengths scaled by 2^{k}: {free:?} / {cut:?} (without / with horizon) became \
                 {s_free:?} / {s_cut:?}, for {case:?}"
            ));
        }
    }
    let scale_time = |x: &BallInput| -> Option<BallInput> {
        Some([
            x[0],
            x[1],
            scaled_exactly(x[2], m)?,
            scaled_exactly(x[3], m)?,
            scaled_exactly(x[4], 2 * m)?,
        ])
    };
    let horizon = if t_max.is_infinite() {
        Some(t_max)
    } else {
        scaled_exactly(t_max, -m)
    };
    let want_t = cut.map(|t| scaled_exactly(t, -m));
    // The unit of time is promised only within 2^±30 (the contract promises units of length
    // over the whole float range): a pair's unit of length comes from its lengths, speeds and
    // frictions together, so a time unit far from 1 makes the frictions choose it, and the
    // positions' squares can then underflow (2^±359 lost a contact at 0).
    // And only within the contract's range: the pair's non-zero magnitudes within 2^±400 of
    // each other (a friction of 1e154 beside positions of 0.1 is outside it).
    if m.abs() <= 30
        && within_contract_range(a.iter().chain(&b).chain(std::iter::once(&radius)).copied())
        && let (Some(sa), Some(sb), Some(st)) = (scale_time(&a), scale_time(&b), horizon)
        && want_t.is_none_or(|w| w.is_some_and(|w| w < LATEST))
        && free.is_none_or(|t| scaled_exactly(t, -m).is_some_and(|w| w < LATEST))
    {
        let s_cut = time_of(&sa, &sb, radius, st)?;
        let want = want_t.map(|w| w.unwrap_or(f64::NAN));
        if !same(s_cut, want) {
            return Err(format!(
                "time scaled by 2^{m}: {cut:?} should become {want:?}, got {s_cut:?}, for {case:?}"
            ));
        }
    }
    Ok(())
}

/// Which parameters of a batch are shared by all pairs (the first pair's value), in the order
/// friction_a, friction_b, radius, t_max.
pub type Shared = [bool; 4];

/// The batch invariants: on one thread and on two, every pair's time is the scalar search's,
/// bit for bit (`∞` for none); valid input never errors.
pub fn batch(cases: &[PairCase], shared: Shared) -> Check {
    let n = cases.len();
    let mut cases = cases.to_vec();
    if let Some(&first) = cases.first() {
        for c in &mut cases {
            if shared[0] {
                c.a[4] = first.a[4];
            }
            if shared[1] {
                c.b[4] = first.b[4];
            }
            if shared[2] {
                c.radius = first.radius;
            }
            if shared[3] {
                c.t_max = first.t_max;
            }
        }
    }
    if !cases.iter().all(PairCase::is_valid) {
        return Ok(());
    }
    let pos_a: Vec<[f64; 2]> = cases.iter().map(|c| [c.a[0], c.a[1]]).collect();
    let vel_a: Vec<[f64; 2]> = cases.iter().map(|c| [c.a[2], c.a[3]]).collect();
    let pos_b: Vec<[f64; 2]> = cases.iter().map(|c| [c.b[0], c.b[1]]).collect();
    let vel_b: Vec<[f64; 2]> = cases.iter().map(|c| [c.b[2], c.b[3]]).collect();
    let fa: Vec<f64> = cases.iter().map(|c| c.a[4]).collect();
    let fb: Vec<f64> = cases.iter().map(|c| c.b[4]).collect();
    let radius: Vec<f64> = cases.iter().map(|c| c.radius).collect();
    let t_max: Vec<f64> = cases.iter().map(|c| c.t_max).collect();
    fn param(is_shared: bool, xs: &[f64]) -> PerPair<'_> {
        match (is_shared, xs.first()) {
            (true, Some(&x)) => PerPair::All(x),
            _ => PerPair::Each(xs),
        }
    }
    let pairs = Pairs {
        pos_a: &pos_a,
        vel_a: &vel_a,
        friction_a: param(shared[0], &fa),
        pos_b: &pos_b,
        vel_b: &vel_b,
        friction_b: param(shared[1], &fb),
        contact_distance: param(shared[2], &radius),
        t_max: param(shared[3], &t_max),
    };
    let mut runs = Vec::new();
    for threads in [1, 2] {
        let mut out = vec![f64::NAN; n];
        let t = Threads::AtMost(NonZeroUsize::new(threads).unwrap_or(NonZeroUsize::MIN));
        collision_times(&pairs, &mut out, t)
            .map_err(|e| format!("valid batch rejected on {threads} thread(s): {e}"))?;
        runs.push(out);
    }
    for (i, c) in cases.iter().enumerate() {
        let scalar = time_of(&c.a, &c.b, c.radius, c.t_max)?.unwrap_or(f64::INFINITY);
        for (r, run) in runs.iter().enumerate() {
            if run[i].to_bits() != scalar.to_bits() {
                return Err(format!(
                    "batch ≠ scalar: pair {i} of {n} on {} thread(s) gives {:e}, the scalar \
                     search {scalar:e}, for {c:?} (shared {shared:?})",
                    r + 1,
                    run[i]
                ));
            }
        }
    }
    Ok(())
}

/// A scene query: balls, one radius per ball, the horizon.
#[derive(Clone, Debug)]
pub struct SceneCase {
    /// The balls' inputs.
    pub balls: Vec<BallInput>,
    /// One radius per ball (> 0).
    pub radii: Vec<f64>,
    /// Horizon (≥ 0, `∞` allowed).
    pub t_max: f64,
}

impl SceneCase {
    /// Whether every input is valid: valid balls, finite positive radii, `t_max ≥ 0`.
    pub fn is_valid(&self) -> bool {
        self.balls.len() == self.radii.len()
            && self.balls.iter().all(valid_ball)
            && self.radii.iter().all(|r| r.is_finite() && *r > 0.0)
            && self.t_max >= 0.0
    }
}

/// The time of pair `(i, j)` as the pair kernel gives it: the contact distance is
/// `radii[i] + radii[j]`; where that sum overflows, every length of the pair is halved first
/// (exact, and the times do not depend on units).
fn brute_pair(case: &SceneCase, i: usize, j: usize) -> Result<f64, String> {
    let (a, b) = (case.balls[i], case.balls[j]);
    let sum = case.radii[i] + case.radii[j];
    let t = if sum.is_finite() {
        time_of(&a, &b, sum, case.t_max)?
    } else {
        let h = |x: &BallInput| x.map(|v| v / 2.0);
        time_of(
            &h(&a),
            &h(&b),
            case.radii[i] / 2.0 + case.radii[j] / 2.0,
            case.t_max,
        )?
    };
    Ok(t.unwrap_or(f64::INFINITY))
}

/// The scene's pairwise matrix, with the given search and threads.
fn matrix(case: &SceneCase, search: PairSearch, threads: usize) -> Result<Vec<f64>, String> {
    let balls: Vec<Ball> = case.balls.iter().map(ball).collect::<Result<_, _>>()?;
    let options = SceneOptions {
        t_max: case.t_max,
        threads: Threads::AtMost(NonZeroUsize::new(threads).unwrap_or(NonZeroUsize::MIN)),
        search,
    };
    pairwise_collision_times(&balls, &case.radii, &options)
        .map_err(|e| format!("valid scene rejected ({search:?}, {threads} thread(s)): {e}"))
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

/// The scene invariants, with `k` the exponent of the length scaling.
pub fn scene(case: &SceneCase, k: i32) -> Check {
    if !case.is_valid() {
        return Ok(());
    }
    let n = case.balls.len();
    let mut brute = vec![f64::INFINITY; n * n];
    for i in 0..n {
        for j in i + 1..n {
            let t = brute_pair(case, i, j)?;
            brute[i * n + j] = t;
            brute[j * n + i] = t;
        }
    }
    if let Some(i) = (0..n * n).find(|&i| brute[i].is_nan() || brute[i] < 0.0) {
        return Err(format!(
            "pair ({}, {}): time {:e}, for {case:?}",
            i / n,
            i % n,
            brute[i]
        ));
    }
    // The broad phase proves pairs apart correctly everywhere; the pair kernel is exact only
    // within the contract's range (a pair's non-zero magnitudes within 2^±400 of each other:
    // docs/contract.md §5), so outside it the two may differ, and only all pairs is compared.
    let in_range = within_contract_range(case.balls.iter().flatten().chain(&case.radii).copied());
    for search in [PairSearch::BroadPhase, PairSearch::AllPairs] {
        if search == PairSearch::BroadPhase && !in_range {
            continue;
        }
        for threads in [1, 2] {
            let m = matrix(case, search, threads)?;
            if let Some(i) = (0..n * n).find(|&i| m[i].to_bits() != brute[i].to_bits()) {
                return Err(format!(
                    "scene ({search:?}, {threads} thread(s)) ≠ brute-force pairs: pair ({}, {}) \
                     is {:e}, the pair kernel says {:e}, for {case:?}",
                    i / n,
                    i % n,
                    m[i],
                    brute[i]
                ));
            }
        }
    }
    let balls: Vec<Ball> = case.balls.iter().map(ball).collect::<Result<_, _>>()?;
    let search = if in_range {
        PairSearch::BroadPhase
    } else {
        PairSearch::AllPairs
    };
    let options = SceneOptions {
        t_max: case.t_max,
        search,
        ..SceneOptions::default()
    };
    let earliest = earliest_collision(&balls, &case.radii, &options)
        .map_err(|e| format!("valid scene rejected by earliest_collision: {e}"))?;
    let mut want = None;
    for i in 0..n {
        for j in i + 1..n {
            let t = brute[i * n + j];
            if t.is_finite() && want.is_none_or(|(w, _, _)| t < w) {
                want = Some((t, i, j));
            }
        }
    }
    if earliest.map(|(t, i, j)| (t.to_bits(), i, j)) != want.map(|(t, i, j)| (t.to_bits(), i, j)) {
        return Err(format!(
            "earliest_collision {earliest:?}, brute force {want:?}, for {case:?}"
        ));
    }
    let (times, partners) = first_contacts(&balls, &case.radii, &options)
        .map_err(|e| format!("valid scene rejected by first_contacts: {e}"))?;
    for i in 0..n {
        let mut best = (f64::INFINITY, None);
        for j in 0..n {
            let t = brute[i * n + j];
            if j != i && t < best.0 {
                best = (t, Some(j));
            }
        }
        if times[i].to_bits() != best.0.to_bits() || partners[i] != best.1 {
            return Err(format!(
                "first_contacts of ball {i}: ({:e}, {:?}), brute force ({:e}, {:?}), for {case:?}",
                times[i], partners[i], best.0, best.1
            ));
        }
    }
    let flipped = SceneCase {
        balls: case.balls.iter().map(|b| b.map(flip_zeros)).collect(),
        radii: case.radii.clone(),
        t_max: flip_zeros(case.t_max),
    };
    // The same search as above: outside the contract's range, all pairs.
    let m = matrix(&flipped, search, 2)?;
    if bits(&m) != bits(&brute) {
        return Err(format!(
            "−0.0 = +0.0: the scene's matrix changed, for {case:?}"
        ));
    }
    let scaled = (|| {
        Some(SceneCase {
            balls: case
                .balls
                .iter()
                .map(|b| {
                    let mut y = [0.0; 5];
                    for (yi, &xi) in y.iter_mut().zip(b) {
                        *yi = scaled_exactly(xi, k)?;
                    }
                    Some(y)
                })
                .collect::<Option<_>>()?,
            radii: case
                .radii
                .iter()
                .map(|&r| scaled_exactly(r, k))
                .collect::<Option<_>>()?,
            t_max: case.t_max,
        })
    })();
    if let Some(scaled) = scaled {
        let m = matrix(&scaled, search, 2)?;
        if bits(&m) != bits(&brute) {
            return Err(format!(
                "lengths scaled by 2^{k}: the scene's matrix changed, for {case:?}"
            ));
        }
    }
    Ok(())
}

/// How many roundings of every coefficient a computed root may be off by (its backward error),
/// and how far from zero the exact polynomial must be at a sample point for a sign change
/// there to prove a lost root. `8⁴`: the reference suite allows 8 conditioning floors, which for
/// a 4-fold root is 8⁴ roundings of backward error.
pub const ROOT_ROUNDINGS: u64 = 4096;

/// Whether the exact polynomial vanishes or changes sign between the floats next to `x`: `x`
/// is then within an ulp of a true root, as close as a float can be (which, for a root in the
/// subnormal range, can be far more than a relative rounding).
fn brackets_a_root(p: &[f64], x: f64) -> bool {
    let (lo, hi) = (sign_exact(p, x.next_down()), sign_exact(p, x.next_up()));
    lo * hi <= 0
}

/// The polynomial invariants for coefficients `coeffs` (highest degree first, any length),
/// with `k` and `m` the exponents of a scaling of the coefficients (`2^k`) and of the
/// variable (`x → 2^m·x`).
pub fn poly(coeffs: &[f64], k: i32, m: i32) -> Check {
    let roots = real_roots(coeffs);
    let r = roots.as_slice();
    if r.iter().any(|x| x.is_nan()) || r.windows(2).any(|w| w[0] > w[1]) {
        return Err(format!("roots {r:?} not sorted or NaN, for {coeffs:?}"));
    }
    if !(2..=5).contains(&coeffs.len()) || coeffs.iter().any(|c| !c.is_finite()) {
        return if r.is_empty() {
            Ok(())
        } else {
            Err(format!("roots {r:?} for the invalid {coeffs:?}"))
        };
    }
    // The polynomial as it is: leading zeros dropped.
    let start = coeffs
        .iter()
        .position(|&c| c != 0.0)
        .unwrap_or(coeffs.len());
    let p = &coeffs[start..];
    if p.len() <= 1 {
        return if r.is_empty() {
            Ok(())
        } else {
            Err(format!("roots {r:?} of the constant {coeffs:?}"))
        };
    }
    if r.len() > p.len() - 1 {
        return Err(format!(
            "{} roots of a degree-{} {coeffs:?}",
            r.len(),
            p.len() - 1
        ));
    }
    // 2^bound exceeds every root's magnitude (Fujiwara's bound, in powers of two).
    let exp = |c: f64| c.abs().log2().floor() as i32;
    let n = p.len() - 1;
    let bound = (1..=n)
        .filter(|&d| p[d] != 0.0)
        .map(|d| ((exp(p[d]) - exp(p[0]) + 1) as f64 / d as f64).ceil() as i32)
        .max()
        .unwrap_or(0)
        + 2;
    for &x in r {
        if x.is_infinite() {
            if bound <= 1023 {
                return Err(format!(
                    "root {x} but every root is below 2^{bound}, for {coeffs:?}"
                ));
            }
        } else if !within_backward_error(p, x, ROOT_ROUNDINGS) && !brackets_a_root(p, x) {
            return Err(format!(
                "{x:e} is not a root within {ROOT_ROUNDINGS} roundings (exact residual), \
                 roots {r:?}, for {coeffs:?}"
            ));
        }
    }
    // Sample points: ±2^bound (or ±MAX), beyond which there is no root, and three points
    // inside every gap between distinct computed roots.
    let far = if bound <= 1023 {
        2f64.powi(bound)
    } else {
        f64::MAX
    };
    let mut marks: Vec<f64> = vec![-far, far];
    marks.extend(r.iter().copied().filter(|x| x.is_finite() && x.abs() < far));
    marks.sort_by(f64::total_cmp);
    marks.dedup();
    let last = marks.len() - 2;
    let mut samples: Vec<(f64, bool)> = Vec::new(); // (point, a computed root just before it)
    for (w, gap) in marks.windows(2).enumerate() {
        let (lo, hi) = (gap[0], gap[1]);
        let mut points = Vec::with_capacity(5);
        if w == 0 {
            points.push(lo);
        }
        for f in [0.125, 0.5, 0.875] {
            // No overflow: both weights are at most 1.
            let x = lo * (1.0 - f) + hi * f;
            if x > lo && x < hi && points.last().is_none_or(|&y| y < x) {
                points.push(x);
            }
        }
        if w == last {
            points.push(hi);
        }
        for (i, x) in points.into_iter().enumerate() {
            samples.push((x, i == 0 && w > 0));
        }
    }
    let clear = |x: f64| !within_backward_error(p, x, ROOT_ROUNDINGS);
    for w in samples.windows(2) {
        let ((x0, _), (x1, root_between)) = (w[0], w[1]);
        if !root_between {
            let (s0, s1) = (sign_exact(p, x0), sign_exact(p, x1));
            if s0 * s1 < 0 && clear(x0) && clear(x1) {
                return Err(format!(
                    "a root lost between {x0:e} and {x1:e} (the polynomial changes sign there, \
                     far from rounding), roots {r:?}, for {coeffs:?}"
                ));
            }
        }
    }
    // Bit-level invariances.
    let flipped: Vec<f64> = coeffs.iter().map(|&c| flip_zeros(c)).collect();
    let rf = real_roots(&flipped);
    if bits(&rf) != bits(r) {
        return Err(format!(
            "−0.0 = +0.0: roots {r:?} became {rf:?}, for {coeffs:?}"
        ));
    }
    if let Some(sc) = coeffs
        .iter()
        .map(|&c| scaled_exactly(c, k))
        .collect::<Option<Vec<_>>>()
    {
        let rs = real_roots(&sc);
        if bits(&rs) != bits(r) {
            return Err(format!(
                "coefficients scaled by 2^{k}: roots {r:?} became {rs:?}, for {coeffs:?}"
            ));
        }
    }
    let deg = coeffs.len() - 1;
    let by_var: Option<Vec<f64>> = (0..=deg)
        .map(|i| scaled_exactly(coeffs[i], m * (deg - i) as i32))
        .collect();
    // A root in the subnormal range (or flushed to zero) is rounded to fewer bits than its
    // rescaled copy: the comparison needs every root, before and after, in the normal range,
    // or an exact zero root (a zero constant term).
    let zero_roots = coeffs.iter().rev().take_while(|&&c| c == 0.0).count();
    let exact_zeros = r.iter().filter(|&&x| x == 0.0).count() == zero_roots;
    let want: Option<Vec<f64>> = r
        .iter()
        .map(|&x| scaled_exactly(x, -m).filter(|&y| x == 0.0 || (x.is_normal() && y.is_normal())))
        .collect::<Option<Vec<f64>>>()
        .filter(|_| exact_zeros);
    if let (Some(sc), Some(want)) = (by_var, want) {
        let rs = real_roots(&sc);
        if bits(&rs) != bits(&want) {
            return Err(format!(
                "variable scaled by 2^{m}: roots {r:?} should become {want:?}, got {rs:?}, \
                 for {coeffs:?}"
            ));
        }
    }
    Ok(())
}
