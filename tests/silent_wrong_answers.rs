//! Regression tests for valid inputs that once got silently wrong answers (found by a
//! bad-input campaign): each reproducer, and the class it stands for.

use ballcollide::batch::{Pairs, PerPair, Threads, collision_times};
use ballcollide::scene::{SceneOptions, earliest_collision, pairwise_collision_times};
use ballcollide::{Ball, CollisionOptions, collision_time, collision_time_with};
use nalgebra::Vector2;

fn ball(p: [f64; 2], v: [f64; 2], mu: f64) -> Ball {
    Ball::new(Vector2::from(p), Vector2::from(v), mu).expect("valid ball")
}

fn with_horizon(a: &Ball, b: &Ball, radius: f64, t_max: f64) -> Option<f64> {
    collision_time_with(a, b, radius, &CollisionOptions { t_max }).expect("valid input")
}

#[test]
fn a_friction_of_minus_zero_is_no_friction() {
    let b = ball([3.0, 0.0], [-1.0, 0.0], 0.0);
    let plus = ball([0.0, 0.0], [1.0, 0.0], 0.0);
    let minus = ball([0.0, 0.0], [1.0, 0.0], -0.0);
    assert_eq!(minus.stop_time(), f64::INFINITY);
    assert_eq!(collision_time(&minus, &b, 1.0).unwrap(), Some(1.0));
    assert_eq!(collision_time(&plus, &b, 1.0).unwrap(), Some(1.0));
    // The batch's lanes read frictions from the caller's rows, not from a `Ball`.
    let mut out = [0.0; 2];
    let pairs = Pairs {
        pos_a: &[[0.0, 0.0], [0.0, 0.0]],
        vel_a: &[[1.0, 0.0], [1.0, 0.0]],
        friction_a: PerPair::Each(&[-0.0, 0.0]),
        pos_b: &[[3.0, 0.0], [3.0, 0.0]],
        vel_b: &[[-1.0, 0.0], [-1.0, 0.0]],
        friction_b: PerPair::Each(&[0.0, -0.0]),
        radius: PerPair::All(1.0),
        t_max: PerPair::All(f64::INFINITY),
    };
    collision_times(&pairs, &mut out, Threads::All).unwrap();
    assert_eq!(out, [1.0, 1.0]);
    let balls = [minus, b];
    let hit = earliest_collision(&balls, &[0.5, 0.5], &SceneOptions::default()).unwrap();
    assert_eq!(hit, Some((1.0, 0, 1)));
}

#[test]
fn a_long_window_keeps_an_early_contact() {
    // Frictionless balls meeting at t = 1, whatever the horizon.
    let a = ball([0.0, 0.0], [1.0, 0.0], 0.0);
    let b = ball([3.0, 0.0], [-1.0, 0.0], 0.0);
    for t_max in [2.0, 1e10, 1e30, 1e100, 1e300, f64::MAX, f64::INFINITY] {
        assert_eq!(
            with_horizon(&a, &b, 1.0, t_max),
            Some(1.0),
            "t_max = {t_max:e}"
        );
    }
    // Balls that barely decelerate: the window runs to their stop, ~1e32 s away.
    for mu in [1e-10, 1e-20, 1e-32, 1e-100, 1e-300] {
        let a = ball([0.0, 0.0], [1.0, 0.0], mu);
        let b = ball([3.0, 0.0], [-1.0, 0.0], mu);
        let t = collision_time(&a, &b, 1.0).unwrap().expect("they meet");
        assert!((t - 1.0).abs() < 1e-9, "mu = {mu:e}: {t}");
        let c = ball([3.0, 0.5], [-1.0, 0.0], 0.0);
        let t = collision_time(&a, &c, 1.0).unwrap().expect("they meet");
        let exact = (3.0 - 0.75f64.sqrt()) / 2.0;
        assert!((t - exact).abs() < 1e-9, "mu = {mu:e}: {t} vs {exact}");
    }
}

#[test]
fn scaling_every_length_by_a_power_of_two_changes_no_time() {
    let pairs = [
        (
            [1.0, 0.0],
            [-1.0, 0.0],
            0.0,
            [-1.0, 0.0],
            [1.0, 0.0],
            0.0,
            1.0,
        ),
        (
            [0.0, 0.0],
            [2.0, 0.1],
            0.2,
            [1.0, 0.0],
            [0.0, 0.0],
            0.0,
            0.05715,
        ),
        (
            [0.0, 0.0],
            [2.0, 0.0],
            0.3,
            [1.0, 0.02],
            [-0.5, 0.0],
            0.1,
            0.05715,
        ),
        (
            [0.3, 0.9],
            [1.0, -1.0],
            0.5,
            [0.8, 0.42],
            [-0.05, 0.0],
            0.1,
            0.05715,
        ),
    ];
    for (pa, va, fa, pb, vb, fb, r) in pairs {
        let base = collision_time(&ball(pa, va, fa), &ball(pb, vb, fb), r).unwrap();
        assert!(base.is_some());
        for k in (-1070..=1020).step_by(10) {
            let s = 2f64.powi(k);
            let sc = |x: [f64; 2]| [x[0] * s, x[1] * s];
            let a = ball(sc(pa), sc(va), fa * s);
            let b = ball(sc(pb), sc(vb), fb * s);
            // Inputs that lost bits to underflow are not an exact scaling.
            if sc(pa)
                .iter()
                .chain(&sc(va))
                .chain(&sc(pb))
                .chain(&sc(vb))
                .any(|x| x.abs() < f64::MIN_POSITIVE && *x != 0.0)
                || (r * s) < f64::MIN_POSITIVE
            {
                continue;
            }
            let t = collision_time(&a, &b, r * s).unwrap();
            assert_eq!(t, base, "scale 2^{k}");
        }
    }
    // The campaign's reproducer.
    for s in [1e-300, 1e160, 1e300] {
        let a = ball([s, 0.0], [-s, 0.0], 0.0);
        let b = ball([-s, 0.0], [s, 0.0], 0.0);
        assert_eq!(collision_time(&a, &b, s).unwrap(), Some(0.5), "s = {s:e}");
    }
}

#[test]
fn a_horizon_only_cuts() {
    let cases = [
        ([0.0, 0.0], [2.0, 0.1], 0.2, [1.0, 0.0], [0.0, 0.0], 0.0),
        ([0.0, 0.0], [2.0, 0.0], 0.3, [1.0, 0.02], [-0.5, 0.0], 0.1),
        ([0.3, 0.9], [1.0, -1.0], 0.5, [0.8, 0.42], [-0.05, 0.0], 0.1),
        ([0.0, 0.0], [1.0, 0.0], 0.0, [3.0, 0.02], [-1.0, 0.0], 0.0),
        ([0.0, 0.0], [1.0, 0.0], 0.01, [3.0, 0.02], [0.0, 0.0], 0.0),
    ];
    for (pa, va, fa, pb, vb, fb) in cases {
        let (a, b) = (ball(pa, va, fa), ball(pb, vb, fb));
        let t = collision_time(&a, &b, 0.05715).unwrap().expect("a contact");
        for t_max in [
            t * 1.5,
            t + 1.0,
            10.0,
            1e10,
            1e300,
            f64::from_bits(t.to_bits() + 1),
        ] {
            assert_eq!(
                with_horizon(&a, &b, 0.05715, t_max),
                Some(t),
                "t_max = {t_max:e}"
            );
        }
        assert_eq!(with_horizon(&a, &b, 0.05715, t), None);
    }
}

#[test]
fn radii_whose_sum_overflows_are_valid() {
    let balls = [
        ball([-1e308, 0.0], [1e308, 0.0], 0.0),
        ball([1e308, 0.0], [-1e308, 0.0], 0.0),
    ];
    let times = pairwise_collision_times(&balls, &[1e308, 1e308], &SceneOptions::default())
        .expect("finite, positive radii");
    assert_eq!(times[1], 0.0);
    let balls = [
        ball([-1.0, 0.0], [1.0, 0.0], 0.0),
        ball([1.0, 0.0], [-1.0, 0.0], 0.0),
    ];
    let times = pairwise_collision_times(&balls, &[1e308, 1e308], &SceneOptions::default())
        .expect("finite, positive radii");
    assert_eq!(times[1], 0.0);
}

#[test]
fn a_window_whose_time_scale_underflows_still_ends() {
    // Centres and radius 1e-170 of the speeds: the gap's own time scale (|d|² + r² underflows
    // to 0) once stalled the pieces of a long window. Run in a thread, so that a stall fails
    // the test instead of hanging it.
    let (send, receive) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let a = ball([0.0, 0.0], [1.0, 0.0], 1e-3);
        let b = ball([3e-170, 1e-171], [2.0, 1e-3], 1e-3);
        let _ = send.send(collision_time(&a, &b, 1e-170));
        // What hypothesis found (a radius 1e-300 of the positions, a friction of 7.8e232).
        let a = ball(
            [-4.70655934, -4.70655934],
            [-0.0, 6.22191567],
            7.7778273e232,
        );
        let b = ball(
            [-1.57801527, -7.39298934e-72],
            [-9.75603582e76, 7.43727028],
            1.5,
        );
        let _ = send.send(with_horizon_checked(&a, &b, 1e-300, 2.38238312));
    });
    for _ in 0..2 {
        let got = receive
            .recv_timeout(std::time::Duration::from_secs(20))
            .expect("the search ends");
        // Squares of 1e-170 underflow: beyond the range where the answer is exact (whether
        // the balls approach is decided by numbers that underflow), so only that it ends.
        assert!(got.expect("valid input").is_none_or(|t| t >= 0.0));
    }
}

fn with_horizon_checked(
    a: &Ball,
    b: &Ball,
    radius: f64,
    t_max: f64,
) -> Result<Option<f64>, ballcollide::InputError> {
    collision_time_with(a, b, radius, &CollisionOptions { t_max })
}
