//! The SPEC's collision semantics, case by case, with answers worked out by hand.

use ballcollide::{Ball, CollisionOptions, InputErrorKind, collision_time, collision_time_with};
use nalgebra::Vector2;

const R: f64 = 0.05715;

fn ball(p: [f64; 2], v: [f64; 2], mu: f64) -> Ball {
    Ball::new(Vector2::from(p), Vector2::from(v), mu).expect("valid ball")
}

fn time(a: &Ball, b: &Ball, radius: f64) -> Option<f64> {
    collision_time(a, b, radius).expect("valid radius")
}

fn assert_close(got: Option<f64>, want: f64, rel: f64) {
    let got = got.unwrap_or_else(|| panic!("expected a collision at {want}, got none"));
    assert!(
        (got - want).abs() <= rel * want.abs().max(f64::MIN_POSITIVE),
        "got {got}, want {want} (relative error {:e})",
        (got - want).abs() / want
    );
}

#[test]
fn head_on_frictionless_is_exact() {
    // Closing speed 3, distance 1.5, radius 0.5 → t = 1/3.
    let a = ball([0.0, 0.0], [1.0, 0.0], 0.0);
    let b = ball([1.5, 0.0], [-2.0, 0.0], 0.0);
    assert_close(time(&a, &b, 0.5), 1.0 / 3.0, f64::EPSILON);
}

#[test]
fn a_ball_at_rest_is_hit() {
    // Stop time 0 must not rule the collision out (the seed note's mistake).
    let cue = ball([0.0, 0.0], [2.0, 0.0], 0.2);
    let target = ball([1.0, 0.0], [0.0, 0.0], 0.2);
    assert_eq!(target.stop_time(), 0.0);
    // 2t − 0.1t² = 1 − R
    let want = (2.0 - (4.0 - 0.4 * (1.0 - R)).sqrt()) / 0.2;
    assert_close(time(&cue, &target, R), want, 1e-14);
    assert_close(time(&target, &cue, R), want, 1e-14);
}

#[test]
fn hit_just_before_the_stop() {
    // The cue stops 1e-6 m after reaching contact distance: only the entry root lies before
    // its stop time (the seed note would have discarded it).
    let travel = 1.0 - R;
    let mu = 1.0 / (2.0 * (travel + 1e-6)); // v = 1: stop distance 1/(2μ)
    let cue = ball([0.0, 0.0], [1.0, 0.0], mu);
    let target = ball([1.0, 0.0], [0.0, 0.0], 0.0);
    let want = (1.0 - (1.0 - 2.0 * mu * travel).sqrt()) / mu;
    assert!(want < cue.stop_time());
    assert_close(time(&cue, &target, R), want, 1e-9);
}

#[test]
fn stopping_just_short_is_a_miss() {
    let travel = 1.0 - R;
    let mu = 1.0 / (2.0 * (travel - 1e-6));
    let cue = ball([0.0, 0.0], [1.0, 0.0], mu);
    let target = ball([1.0, 0.0], [0.0, 0.0], 0.0);
    assert_eq!(time(&cue, &target, R), None);
}

#[test]
fn hit_after_one_ball_has_stopped() {
    // A stops at x = 1 after 2 s; B, frictionless from x = −3 at 1 m/s, reaches contact
    // (x = 1 − R) at 4 − R seconds, when A has long stopped. Its formula continued past the
    // stop would have turned A round.
    let a = ball([0.0, 0.0], [1.0, 0.0], 0.5);
    let b = ball([-3.0, 0.0], [1.0, 0.0], 0.0);
    assert_eq!(a.stop_time(), 2.0);
    assert_close(time(&a, &b, R), 4.0 - R, 4.0 * f64::EPSILON);
}

#[test]
fn none_after_both_stopped() {
    // Rolling toward each other, both stop 0.5 m short.
    let a = ball([0.0, 0.0], [1.0, 0.0], 1.0); // stops at 0.5
    let b = ball([1.0 + 2.0 * R, 0.0], [-1.0, 0.0], 1.0); // stops at 0.5 + 2R
    assert_eq!(time(&a, &b, R), None);
}

#[test]
fn touching_and_approaching_is_zero() {
    let a = ball([0.0, 0.0], [1.0, 0.0], 0.1);
    let b = ball([0.5, 0.0], [0.0, 0.0], 0.0);
    assert_eq!(time(&a, &b, 0.5), Some(0.0));
}

#[test]
fn touching_or_overlapping_and_separating_is_not_a_collision() {
    let a = ball([0.0, 0.0], [-1.0, 0.0], 0.1);
    let b = ball([0.5, 0.0], [0.0, 0.0], 0.0);
    assert_eq!(time(&a, &b, 0.5), None); // touching
    assert_eq!(time(&a, &b, 0.7), None); // overlapping
    // Both at rest, overlapping: not a collision either.
    let c = ball([0.3, 0.0], [0.0, 0.0], 0.0);
    assert_eq!(time(&b, &c, 0.5), None);
}

#[test]
fn overlapping_and_separating_then_re_entering() {
    // A leaves B faster but brakes; frictionless B catches up: the first entry is the later
    // re-entry, never 0. A: x = 2t − t²/2 until t = 2 (then x = 2); B: x = t − 0.1.
    // Overlap ends when 2t − t²/2 − (t − 0.1) = 0.5, and re-entry when it falls back to 0.5:
    // t − t²/2 + 0.1 = 0.5 → t = 1 ± √0.2; the re-entry is 1 + √0.2 < 2.
    let a = ball([0.0, 0.0], [2.0, 0.0], 1.0);
    let b = ball([-0.1, 0.0], [1.0, 0.0], 0.0);
    assert_close(time(&a, &b, 0.5), 1.0 + 0.2f64.sqrt(), 1e-15);
}

#[test]
fn shrinking_at_second_order_from_contact_is_zero() {
    // Touching, same velocity (d·d′ = 0), but the front ball brakes harder: the gap closes at
    // once. The first non-zero derivative of the gap is negative, so this is a collision at 0.
    let front = ball([0.5, 0.0], [1.0, 0.0], 1.0);
    let back = ball([0.0, 0.0], [1.0, 0.0], 0.5);
    assert_eq!(time(&front, &back, 0.5), Some(0.0));
    // The other way round they drift apart.
    let front = ball([0.5, 0.0], [1.0, 0.0], 0.5);
    let back = ball([0.0, 0.0], [1.0, 0.0], 1.0);
    assert_eq!(time(&front, &back, 0.5), None);
}

#[test]
fn exact_tangency_is_not_a_collision() {
    // B passes A at a closest distance of exactly the radius.
    let a = ball([0.0, 0.0], [0.0, 0.0], 0.0);
    let b = ball([-1.0, 0.5], [1.0, 0.0], 0.0);
    assert_eq!(time(&a, &b, 0.5), None);
    // A hair closer is a collision.
    let b = ball([-1.0, 0.5 - 1e-9], [1.0, 0.0], 0.0);
    assert!(time(&a, &b, 0.5).is_some());
}

#[test]
fn equal_friction_vectors_need_no_special_case() {
    // Chasing on one line with equal friction while both move: the quartic's two leading
    // coefficients vanish exactly (Δf = 0). The gap is then linear in time until B stops.
    let a = ball([0.0, 0.0], [2.0, 0.0], 0.5); // stops at t = 4
    let b = ball([1.0, 0.0], [1.0, 0.0], 0.5); // stops at t = 2
    // Relative position: 1 − t while both move; contact at 1 − t = R.
    assert_close(time(&a, &b, R), 1.0 - R, f64::EPSILON);
    // Parallel lanes, same velocity, same friction: never touch.
    let c = ball([0.0, 1.0], [2.0, 0.0], 0.5);
    assert_eq!(time(&a, &c, R), None);
}

#[test]
fn nearly_equal_friction_vectors() {
    // Directions 1e-9 rad apart: a ~ 1e-18, b ~ 1e-9, where dividing by a would be ruinous.
    let angle: f64 = 1e-9;
    let a = ball([0.0, 0.0], [2.0, 0.0], 0.5);
    let b = ball([1.0, 0.0], [angle.cos(), angle.sin()], 0.5);
    let t = time(&a, &b, R).expect("a collision");
    assert!((t - (1.0 - R)).abs() < 1e-9, "{t}");
}

#[test]
fn frictionless_balls_move_for_ever() {
    let a = ball([0.0, 0.0], [1e-3, 0.0], 0.0);
    let b = ball([1000.0, 0.0], [0.0, 0.0], 0.0);
    assert_close(time(&a, &b, 0.5), (1000.0 - 0.5) / 1e-3, f64::EPSILON);
}

#[test]
fn horizon_cuts_later_collisions() {
    let a = ball([0.0, 0.0], [1.0, 0.0], 0.0);
    let b = ball([2.0, 0.0], [0.0, 0.0], 0.0);
    let at = |t_max| collision_time_with(&a, &b, 0.5, &CollisionOptions { t_max }).unwrap();
    assert_eq!(at(1.5), None); // a collision at t ≥ t_max is none
    assert_eq!(at(1.5 + 1e-15), Some(1.5));
    assert_eq!(at(0.0), None);
    let touching = ball([0.5, 0.0], [-1.0, 0.0], 0.0);
    let t0 = |t_max| collision_time_with(&a, &touching, 0.5, &CollisionOptions { t_max });
    assert_eq!(t0(0.0).unwrap(), None);
    assert_eq!(t0(1e-300).unwrap(), Some(0.0));
}

#[test]
fn invalid_input_is_an_error_naming_the_argument() {
    let a = ball([0.0, 0.0], [1.0, 0.0], 0.0);
    for radius in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let err = collision_time(&a, &a, radius).unwrap_err();
        assert_eq!(err.argument(), "contact_distance");
    }
    let err = collision_time_with(&a, &a, 1.0, &CollisionOptions { t_max: -1.0 }).unwrap_err();
    assert_eq!(err.kind(), InputErrorKind::InvalidHorizon(-1.0));
    let err = Ball::new(Vector2::zeros(), Vector2::new(f64::INFINITY, 0.0), 0.0).unwrap_err();
    assert_eq!(err.argument(), "velocity");
    assert!(Ball::new(Vector2::zeros(), Vector2::zeros(), f64::NAN).is_err());
}

#[test]
fn huge_and_tiny_units() {
    // The same shot in units from 1e-150 to 1e150 (times unchanged).
    let base = time(
        &ball([0.0, 0.0], [2.0, 0.3], 0.2),
        &ball([1.0, 0.1], [0.0, 0.0], 0.0),
        R,
    )
    .expect("a collision");
    for k in [-150, -100, -6, 6, 100, 150] {
        let s = 10f64.powi(k);
        let a = ball([0.0, 0.0], [2.0 * s, 0.3 * s], 0.2 * s);
        let b = ball([s, 0.1 * s], [0.0, 0.0], 0.0);
        assert_close(time(&a, &b, R * s), base, 1e-13);
    }
}
