//! One pair, two queries: `collision_time` on friction balls and `path_collision_time` on the
//! same balls as paths (`Ball::path`) give the same hit or miss, and times within the floor,
//! down to contact distances of `2⁻⁴⁰⁰` of the separation (issue 39).
//!
//! The pairs are built so that their depth is known without a reference: head on along an
//! axis or a diagonal (where a friction ball's friction vector stays on the line, exactly), the
//! other ball displaced sideways by `β·r` (`β < 0.9`: a contact of depth `≥ 1 − 0.9`; `β > 1.1`:
//! a clear miss), and balls that stop clear of the contact point (stopping within 5 % of it is a
//! near-tangency at the stop, which either answer may settle): no pair is within the contract's
//! grazing band.

use ballcollide::{Ball, CollisionOptions, collision_time, path_collision_time};
use nalgebra::Vector2;
use proptest::prelude::*;

/// A pair and its contact distance, from the drawn numbers.
#[derive(Clone, Debug)]
struct Pair {
    a: Ball,
    b: Ball,
    radius: f64,
}

fn pair_strategy() -> impl Strategy<Value = Pair> {
    (
        (0usize..6, any::<bool>()),
        (-30i32..30, -20i32..20),
        (1u32..1 << 24, 0u32..1 << 20),
        (1u32..1 << 24, 0usize..3, 1u32..1 << 24),
        (0.0f64..1.0, 0.0f64..1.0, 1.05f64..4.0, 0.2f64..0.95),
        (0.0f64..400.0, 0.0f64..1.0),
    )
        .prop_map(
            |(
                (line, sideways),
                (length, time),
                (sep, xa),
                (sa, b_kind, sb),
                fric,
                (octave, beta),
            )| {
                // The line: an axis (either sign) or a diagonal.
                let w = [
                    Vector2::new(1.0, 0.0),
                    Vector2::new(-1.0, 0.0),
                    Vector2::new(0.0, 1.0),
                    Vector2::new(0.0, -1.0),
                    Vector2::new(1.0, 1.0),
                    Vector2::new(-1.0, 1.0),
                ][line];
                let lu = 2f64.powi(length);
                let vu = lu / 2f64.powi(time);
                let fu = vu / 2f64.powi(time);
                let (sep, xa) = (f64::from(sep), f64::from(xa));
                let sa = f64::from(sa);
                let sb = match b_kind {
                    0 => 0.0,
                    1 => -f64::from(sb),
                    _ => 0.25 * f64::from(sb >> 4),
                };
                // Friction: none, or a stop clear of the contact (past it by 5 % to 4×, or
                // short of it by 5 % at least: then the balls miss, or meet after a stop).
                let (no_friction, frictionless_b, past, short) = fric;
                let stop = if no_friction < 0.3 {
                    f64::INFINITY
                } else if no_friction < 0.8 {
                    past * sep
                } else {
                    short * sep
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
                let radius = 2f64.powf(-octave) * sep * lu;
                let mut pb = w * ((xa + sep) * lu);
                let diagonal = w.x != 0.0 && w.y != 0.0;
                if sideways && !diagonal {
                    let side = Vector2::new(w.y, w.x);
                    let beta = if beta < 0.7 {
                        beta / 0.7 * 0.9
                    } else {
                        1.1 + (beta - 0.7) * 6.0
                    };
                    pb += side * (beta * radius);
                }
                let ball = |p, v, f| Ball::new(p, v, f).expect("valid ball");
                Pair {
                    a: ball(w * (xa * lu), w * (sa * vu), friction(sa) * fu),
                    b: ball(pb, w * (sb * vu), fb * fu),
                    radius,
                }
            },
        )
}

proptest! {
    #[test]
    fn both_queries_agree_on_one_pair(pair in pair_strategy()) {
        let Pair { a, b, radius } = pair;
        let by_balls = collision_time(&a, &b, radius).expect("valid");
        let (pa, pb) = (a.path().expect("valid path"), b.path().expect("valid path"));
        let by_paths =
            path_collision_time(&pa, &pb, radius, &CollisionOptions::default()).expect("valid");
        prop_assert_eq!(by_balls.is_some(), by_paths.is_some(), "{:?} vs {:?}", by_balls, by_paths);
        if let (Some(t1), Some(t2)) = (by_balls, by_paths) {
            // The floor: a rounding of the time itself and of the distance covered, over the
            // closing speed at contact (the paths' segments are the balls' to a few ulps).
            let w = a.velocity_at(t1) - b.velocity_at(t1);
            let reach = (a.position() - b.position()).norm()
                + (a.velocity().norm() + b.velocity().norm()) * t1;
            let closing = w.norm().max(f64::MIN_POSITIVE);
            let floor = f64::EPSILON * (t1 + reach / closing);
            prop_assert!((t1 - t2).abs() <= 64.0 * floor, "{} vs {} (floor {:e})", t1, t2, floor);
        }
    }
}
