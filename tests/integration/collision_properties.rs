//! Invariances of the collision time (SPEC "Accuracy"), as property tests.
//!
//! Exact symmetries of float arithmetic (A/B swap, 90° rotations, reflections, scaling lengths
//! or time by powers of two) must give bit-identical answers. Inexact ones (translation,
//! general rotation and scaling, advancing along the trajectories) must agree within a
//! tolerance, on configurations that are not within rounding of a grazing contact or of a stop
//! (where the hit/miss answer is legitimately undecided).

use crate::support::cases;

use ballcollide::{Ball, collision_time};
use nalgebra::{Rotation2, Vector2};
use proptest::prelude::*;

#[derive(Clone, Copy, Debug)]
struct Config {
    a: [f64; 5], // px, py, vx, vy, μ
    b: [f64; 5],
    radius: f64,
}

fn make(c: &[f64; 5]) -> Ball {
    Ball::new(Vector2::new(c[0], c[1]), Vector2::new(c[2], c[3]), c[4]).expect("valid ball")
}

fn time(cfg: &Config) -> Option<f64> {
    collision_time(&make(&cfg.a), &make(&cfg.b), cfg.radius).expect("valid radius")
}

fn map(
    cfg: &Config,
    pos: impl Fn([f64; 2]) -> [f64; 2],
    vel: impl Fn([f64; 2]) -> [f64; 2],
    mu: impl Fn(f64) -> f64,
    radius: f64,
) -> Config {
    let m = |c: [f64; 5]| {
        let p = pos([c[0], c[1]]);
        let v = vel([c[2], c[3]]);
        [p[0], p[1], v[0], v[1], mu(c[4])]
    };
    Config {
        a: m(cfg.a),
        b: m(cfg.b),
        radius,
    }
}

/// Pairs on a 2.54 × 1.27 m table, half of them aimed at each other so that many collide.
fn config() -> impl Strategy<Value = Config> {
    let pos = (0.0..2.54f64, 0.0..1.27f64);
    (
        pos.clone(),
        pos,
        (0.05..3.0f64, 0.0..std::f64::consts::TAU),
        (0.0..3.0f64, 0.0..std::f64::consts::TAU),
        (0.0..2.0f64, 0.0..2.0f64),
        prop::bool::ANY,
        -1.5..1.5f64,
    )
        .prop_map(|(pa, pb, (sa, ta), (sb, tb), (ma, mb), aimed, impact)| {
            let radius = 0.05715;
            let mut dir_a = ta;
            if aimed {
                // Aim A at B, offset by `impact` radii sideways.
                let (dx, dy) = (pb.0 - pa.0, pb.1 - pa.1);
                let dist = dx.hypot(dy).max(1e-3);
                dir_a = dy.atan2(dx) + (impact * radius / dist).clamp(-1.0, 1.0).asin();
            }
            Config {
                a: [pa.0, pa.1, sa * dir_a.cos(), sa * dir_a.sin(), ma],
                b: [pb.0, pb.1, sb * tb.cos(), sb * tb.sin(), mb],
                radius,
            }
        })
}

/// Whether the answer is robust: the same hit/miss for a radius 1e-7 larger and smaller,
/// and a contact not within 1e-7 (relative) of either ball's stop time.
fn robust(cfg: &Config) -> bool {
    let t = time(cfg);
    let bigger = time(&Config {
        radius: cfg.radius * (1.0 + 1e-7),
        ..*cfg
    });
    let smaller = time(&Config {
        radius: cfg.radius * (1.0 - 1e-7),
        ..*cfg
    });
    if t.is_some() != bigger.is_some() || t.is_some() != smaller.is_some() {
        return false;
    }
    match t {
        Some(t) => [make(&cfg.a).stop_time(), make(&cfg.b).stop_time()]
            .iter()
            .all(|&tau| (t - tau).abs() > 1e-7 * tau),
        None => true,
    }
}

fn assert_near(x: Option<f64>, y: Option<f64>, rel: f64) -> Result<(), TestCaseError> {
    match (x, y) {
        (None, None) => Ok(()),
        (Some(x), Some(y)) => {
            prop_assert!((x - y).abs() <= rel * x.abs().max(1.0), "{x} vs {y}");
            Ok(())
        }
        _ => Err(TestCaseError::fail(format!(
            "hit/miss differ: {x:?} vs {y:?}"
        ))),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases::cases(500)))]

    #[test]
    fn swapping_a_and_b_is_exact(cfg in config()) {
        let swapped = Config { a: cfg.b, b: cfg.a, radius: cfg.radius };
        prop_assert_eq!(time(&cfg), time(&swapped));
    }

    #[test]
    fn quarter_turns_and_reflections_are_exact(cfg in config()) {
        let turn = |[x, y]: [f64; 2]| [-y, x];
        let flip = |[x, y]: [f64; 2]| [-x, y];
        prop_assert_eq!(time(&cfg), time(&map(&cfg, turn, turn, |m| m, cfg.radius)));
        prop_assert_eq!(time(&cfg), time(&map(&cfg, flip, flip, |m| m, cfg.radius)));
    }

    #[test]
    fn power_of_two_units_are_exact(cfg in config(), k in -60i32..60) {
        let s = 2f64.powi(k);
        let scale = |[x, y]: [f64; 2]| [x * s, y * s];
        prop_assert_eq!(time(&cfg), time(&map(&cfg, scale, scale, |m| m * s, cfg.radius * s)));
    }

    #[test]
    fn power_of_two_time_units_are_exact(cfg in config(), k in -30i32..30) {
        // Time measured in units 2^k times longer: velocities × 2^k, decelerations × 4^k.
        let s = 2f64.powi(k);
        let vel = |[x, y]: [f64; 2]| [x * s, y * s];
        let scaled = map(&cfg, |p| p, vel, |m| m * s * s, cfg.radius);
        prop_assert_eq!(time(&cfg).map(|t| t / s), time(&scaled));
    }

    #[test]
    fn translation_moves_nothing(cfg in config(), dx in -1e3..1e3f64, dy in -1e3..1e3f64) {
        prop_assume!(robust(&cfg));
        let shifted = map(&cfg, |[x, y]| [x + dx, y + dy], |v| v, |m| m, cfg.radius);
        assert_near(time(&cfg), time(&shifted), 1e-9)?;
    }

    #[test]
    fn rotation_moves_nothing(cfg in config(), angle in 0.0..std::f64::consts::TAU) {
        prop_assume!(robust(&cfg));
        let rot = Rotation2::new(angle);
        let turn = |p: [f64; 2]| (rot * Vector2::from(p)).into();
        assert_near(time(&cfg), time(&map(&cfg, turn, turn, |m| m, cfg.radius)), 1e-9)?;
    }

    #[test]
    fn units_do_not_matter(cfg in config(), e in -6.0..6.0f64) {
        prop_assume!(robust(&cfg));
        let s = 10f64.powf(e);
        let scale = |[x, y]: [f64; 2]| [x * s, y * s];
        assert_near(time(&cfg), time(&map(&cfg, scale, scale, |m| m * s, cfg.radius * s)), 1e-12)?;
    }

    #[test]
    fn advancing_both_balls_shifts_the_time(cfg in config(), fraction in 0.0..0.9f64) {
        prop_assume!(robust(&cfg));
        let Some(t) = time(&cfg) else { return Ok(()) };
        let t0 = fraction * t;
        let advance = |c: &[f64; 5]| {
            let ball = make(c);
            let (p, v) = (ball.position_at(t0), ball.velocity_at(t0));
            [p.x, p.y, v.x, v.y, c[4]]
        };
        let later = Config { a: advance(&cfg.a), b: advance(&cfg.b), radius: cfg.radius };
        let t_later = time(&later).map(|t| t + t0);
        assert_near(Some(t), t_later, 1e-9)?;
    }
}
