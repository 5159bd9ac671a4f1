//! One pair, two queries (issue 39): friction balls built so that their depth is known without a
//! reference, and the invariant that `collision_time` and `path_collision_time` on the same
//! balls as paths (`Ball::path`) agree. Shared by `tests/integration/narrow_properties.rs` (proptest) and
//! the fuzz target `queries` (`fuzz/`).
//!
//! The pairs: head on along an axis or a diagonal (where a friction ball's friction vector
//! stays on the line, exactly), the other ball displaced sideways by `β·r` (`β < 0.9`: a
//! contact of depth `≥ 1 − 0.9`; `β > 1.1`: a clear miss), contact distances from `1/64` of
//! the separation down to `2⁻⁴⁰⁰` of it, and frictions that stop the balls clear of the
//! contact point (stopping within 5 % of it is a near-tangency at the stop, which either
//! answer may settle): no pair is within the contract's grazing band.

#![allow(dead_code)]

use ballcollide::{Ball, CollisionOptions, collision_time, path_collision_time};
use nalgebra::Vector2;

/// The numbers a pair is drawn from (any values: each is brought into its range).
#[derive(Clone, Copy, Debug, Default)]
pub struct NarrowDraw {
    /// The line: an axis (either sign) or a diagonal, `line % 6`.
    pub line: u32,
    /// Displaced sideways (on an axis only).
    pub sideways: bool,
    /// Exponents of the units of length and time (`% 60 − 30`, `% 40 − 20`).
    pub length: i32,
    pub time: i32,
    /// The separation, A's position and speed, B's speed, in the units (24-bit integers).
    pub sep: u32,
    pub xa: u32,
    pub sa: u32,
    pub sb: u32,
    /// B at rest, running at A, or running away (`% 3`).
    pub b_kind: u32,
    /// In `[0, 1)`: friction or none, B's, how far past or short of the contact they stop,
    /// the octave of r/separation (× 400), the sideways offset.
    pub fractions: [f64; 6],
}

/// The balls and contact distance of `draw`.
pub fn narrow_pair(draw: &NarrowDraw) -> (Ball, Ball, f64) {
    let unit = |x: f64| if x.is_finite() { x.abs().fract() } else { 0.5 };
    let [no_friction, frictionless_b, past, short, octave, beta] = draw.fractions.map(unit);
    let w = [
        Vector2::new(1.0, 0.0),
        Vector2::new(-1.0, 0.0),
        Vector2::new(0.0, 1.0),
        Vector2::new(0.0, -1.0),
        Vector2::new(1.0, 1.0),
        Vector2::new(-1.0, 1.0),
    ][(draw.line % 6) as usize];
    let lu = 2f64.powi(draw.length.rem_euclid(60) - 30);
    let tu = 2f64.powi(draw.time.rem_euclid(40) - 20);
    let (vu, fu) = (lu / tu, lu / (tu * tu));
    let bits24 = |x: u32| f64::from(x % (1 << 24));
    let sep = bits24(draw.sep).max(1.0);
    let xa = f64::from(draw.xa % (1 << 20));
    let sa = bits24(draw.sa).max(1.0);
    let sb = match draw.b_kind % 3 {
        0 => 0.0,
        1 => -bits24(draw.sb).max(1.0),
        _ => 0.25 * f64::from(draw.sb % (1 << 20)),
    };
    // Friction: none, or a stop clear of the contact (past it by 5 % to 4×, or short of it by
    // 5 % at least: then the balls miss, or meet after a stop).
    let stop = if no_friction < 0.3 {
        f64::INFINITY
    } else if no_friction < 0.8 {
        (1.05 + 2.95 * past) * sep
    } else {
        (0.2 + 0.75 * short) * sep
    };
    let friction = |s: f64| {
        if stop.is_finite() && s != 0.0 {
            s * s / (2.0 * stop)
        } else {
            0.0
        }
    };
    let fb = if frictionless_b < 0.5 {
        0.0
    } else {
        friction(sb.abs())
    };
    // At most 1/64 of the separation, so that the stops above stay clear of the contact point
    // (at `sep − r`), and a ball running away that stops after the same distance as the other
    // ends at least `63·r` away (at `r = sep` both stopped exactly tangent: a graze).
    let radius = 2f64.powf(-6.0 - 394.0 * octave) * sep * lu;
    // Within the contract's 2^±400 of every other magnitude (the speeds and frictions too, in
    // their units, which may be far from the lengths'): 2^-390 of the largest at least.
    let largest = [
        (xa + sep) * lu,
        sa * vu,
        sb.abs() * vu,
        friction(sa) * fu,
        fb * fu,
    ]
    .into_iter()
    .fold(0.0, f64::max);
    let radius = radius.max(2f64.powi(-390) * largest);
    let mut pb = w * ((xa + sep) * lu);
    let diagonal = w.x != 0.0 && w.y != 0.0;
    if draw.sideways && !diagonal {
        let side = Vector2::new(w.y, w.x);
        let beta = if beta < 0.7 {
            beta / 0.7 * 0.9
        } else {
            1.1 + (beta - 0.7) * 6.0
        };
        pb += side * (beta * radius);
    }
    let ball = |p, v, f| Ball::new(p, v, f).expect("valid ball");
    (
        ball(w * (xa * lu), w * (sa * vu), friction(sa) * fu),
        ball(pb, w * (sb * vu), fb * fu),
        radius,
    )
}

/// `collision_time` and `path_collision_time` on the balls' paths give the same hit or miss,
/// and times within 64 floors (a rounding of the time itself and of the distance covered, over
/// the closing speed at contact: the paths' segments are the balls' to a few ulps).
pub fn queries_agree(a: &Ball, b: &Ball, radius: f64) -> Result<(), String> {
    let by_balls = collision_time(a, b, radius).map_err(|e| e.to_string())?;
    let (pa, pb) = (
        a.path().map_err(|e| e.to_string())?,
        b.path().map_err(|e| e.to_string())?,
    );
    let by_paths = path_collision_time(&pa, &pb, radius, &CollisionOptions::default())
        .map_err(|e| e.to_string())?;
    let case = || format!("{a:?} {b:?} radius {radius:e}");
    if by_balls.is_some() != by_paths.is_some() && !near_tangent(a, b, radius) {
        return Err(format!(
            "one pair, two answers: collision_time {by_balls:?}, path_collision_time \
             {by_paths:?}, for {}",
            case()
        ));
    }
    if let (Some(t1), Some(t2)) = (by_balls, by_paths) {
        let w = a.velocity_at(t1) - b.velocity_at(t1);
        let reach =
            (a.position() - b.position()).norm() + (a.velocity().norm() + b.velocity().norm()) * t1;
        let floor = f64::EPSILON * (t1 + reach / w.norm().max(f64::MIN_POSITIVE));
        if (t1 - t2).abs() > 64.0 * floor {
            return Err(format!(
                "one pair, two times: {t1} and {t2} (floor {floor:e}), for {}",
                case()
            ));
        }
    }
    Ok(())
}

/// Whether the balls' closest approach is within `1e-7` (relative) of the contact distance,
/// where either answer is the contract's (a ball catching up with one running away may turn
/// back at any distance; a stop may come just at the contact point). The candidates: the
/// start, each stop, and each time the relative velocity vanishes between them (the balls
/// move on one line, so the distance's minimum is at one of them unless they cross, which is
/// a clear contact).
pub fn near_tangent(a: &Ball, b: &Ball, radius: f64) -> bool {
    let mut times = vec![0.0, a.stop_time(), b.stop_time()];
    times.retain(|t| t.is_finite());
    times.sort_by(f64::total_cmp);
    let mut candidates = times.clone();
    for (k, &t0) in times.iter().enumerate() {
        let t1 = times.get(k + 1).copied().unwrap_or(f64::INFINITY);
        // The relative velocity, linear on the piece: where it vanishes.
        let probe = if t1.is_finite() {
            0.5 * (t0 + t1)
        } else {
            t0 + 1.0
        };
        let w0 = b.velocity_at(t0) - a.velocity_at(t0);
        let slope = (b.velocity_at(probe) - a.velocity_at(probe) - w0) / (probe - t0);
        if slope.norm() > 0.0 {
            let t = t0 - w0.dot(&slope) / slope.norm_squared();
            if t > t0 && t < t1 {
                candidates.push(t);
            }
        }
    }
    let scale = (b.position() - a.position()).norm() + radius;
    candidates.iter().any(|&t| {
        let d = (b.position_at(t) - a.position_at(t)).norm();
        (d - radius).abs() <= 1e-7 * scale
    })
}
