//! `simulate` always moves on and ends, and never lets balls sink into each other: resting
//! contacts (restitution 0 with friction), touching chains against a wall, masses over the
//! whole float range, balls as wide as the box, impossible starts (refused, naming the
//! balls), and runs stopped by their observer.

use ballcollide::schedule::{
    MAX_EVENTS_AT_ONE_INSTANT, Simulation, SimulationOptions, Walls, simulate, simulate_observed,
};
use ballcollide::{Ball, InputErrorKind};
use nalgebra::Vector2;
use std::ops::ControlFlow;

use crate::support::rng;
use crate::support::simulation_invariants;
use proptest::prelude::*;
use proptest::test_runner::RngSeed;
use rng::Rng;
use simulation_invariants::{SimulationCase, simulation};

fn ball(p: [f64; 2], v: [f64; 2], friction: f64) -> Ball {
    Ball::new(Vector2::from(p), Vector2::from(v), friction).expect("a valid ball")
}

fn run(
    balls: &[Ball],
    radii: &[f64],
    walls: Walls<2>,
    restitution: f64,
    mass: Vec<f64>,
    t_end: f64,
) -> Simulation {
    let options = SimulationOptions {
        mass,
        restitution,
        t_end,
        max_events: Some(4_000_000),
        ..Default::default()
    };
    simulate(balls, radii, walls, &options).expect("a valid simulation")
}

/// The deepest overlap of any two balls (relative to their contact distance) and of any ball
/// with a wall (relative to its radius), in a simulation's final state.
fn deepest_overlap(run: &Simulation, radii: &[f64], walls: &Walls<2>) -> f64 {
    let mut deepest = 0.0f64;
    for (i, a) in run.balls.iter().enumerate() {
        for (j, b) in run.balls.iter().enumerate().skip(i + 1) {
            let contact = radii[i] + radii[j];
            let distance = (a.position() - b.position()).norm();
            deepest = deepest.max((contact - distance) / contact);
        }
        for axis in 0..2 {
            let p = a.position()[axis];
            let room = (p - walls.lo()[axis]).min(walls.hi()[axis] - p);
            deepest = deepest.max((radii[i] - room) / radii[i]);
        }
    }
    deepest
}

/// The state at several times along a run (each a run of its own to that `t_end`: the horizon
/// only cuts, so they are points of one trajectory) overlaps nowhere beyond 1e-9.
fn never_overlaps(balls: &[Ball], radii: &[f64], walls: Walls<2>, restitution: f64, t_end: f64) {
    for k in 1..=8 {
        let t = t_end * f64::from(k) / 8.0;
        let run = run(balls, radii, walls, restitution, vec![1.0], t);
        let deepest = deepest_overlap(&run, radii, &walls);
        assert!(
            deepest <= 1e-9,
            "overlap {deepest:e} at t = {t} (restitution {restitution}, {} events)",
            run.events.len()
        );
    }
}

#[test]
fn a_resting_contact_with_friction_parts_and_ends_at_every_restitution() {
    // Issue reproducers: a sliding ball pressing into a slower one (restitution 0 kept them
    // colliding at one instant, or sinking 1.2 % into each other with one event).
    let walls = Walls::new([-4.0, -4.0], [4.0, 4.0]).expect("a box");
    let scenes = [
        [
            ball([0.0, 0.0], [1.0, 0.0], 1.0),
            ball([0.5, 0.0], [0.0, 0.05], 1.0),
        ],
        [
            ball([0.0, 0.0], [1.0, 0.1], 1.0),
            ball([0.5, 0.0], [0.5, 0.0], 1.0),
        ],
    ];
    for balls in &scenes {
        for restitution in [0.0, 0.001, 0.01, 0.1, 0.5, 0.9, 1.0] {
            let run = run(
                balls,
                &[0.125; 2],
                walls,
                restitution,
                vec![1.0],
                f64::INFINITY,
            );
            assert!(run.events.len() < 100_000, "{} events", run.events.len());
            assert!(run.balls.iter().all(|b| b.is_at_rest()));
            never_overlaps(balls, &[0.125; 2], walls, restitution, run.end);
        }
    }
}

#[test]
fn random_friction_scenes_never_overlap_at_any_restitution() {
    let walls = Walls::new([0.0, 0.0], [3.0, 3.0]).expect("a box");
    for seed in 1..=12u64 {
        let mut rng = Rng(seed);
        let n = 6;
        let radius = 0.2;
        // Balls on a grid, apart, with random velocities; some with no friction.
        let balls: Vec<Ball> = (0..n)
            .map(|k| {
                let p = [0.5 + (k % 3) as f64, 0.75 + (k / 3) as f64 * 1.5];
                let v = [rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)];
                ball(p, v, [0.0, 0.3, 1.0, 5.0][rng.below(4) as usize])
            })
            .collect();
        for restitution in [0.0, 0.01, 0.5, 1.0] {
            never_overlaps(&balls, &vec![radius; n], walls, restitution, 6.0);
        }
    }
}

#[test]
fn touching_chains_against_a_wall_resolve_at_every_restitution() {
    // k touching balls in a row, the first pushed into the others, the last touching the
    // wall (eight of them with restitution 0.5 stayed at t = 0 for 10⁵ events).
    for k in 2..=10usize {
        for restitution in [0.0, 0.25, 0.5, 0.9, 1.0] {
            for friction in [0.0, 0.1, 2.0] {
                let r = 0.5;
                let hi = 2.0 * r * k as f64;
                let walls = Walls::new([-10.0, -1.0], [hi, 1.0]).expect("a box");
                let balls: Vec<Ball> = (0..k)
                    .map(|m| {
                        let v = if m == 0 { [1.0, 0.0] } else { [0.0, 0.0] };
                        ball([r + 2.0 * r * m as f64, 0.0], v, friction)
                    })
                    .collect();
                let run = run(&balls, &vec![r; k], walls, restitution, vec![1.0], 30.0);
                let instant = MAX_EVENTS_AT_ONE_INSTANT.0 + MAX_EVENTS_AT_ONE_INSTANT.1 * k;
                assert!(
                    run.events.len() < 100 * instant,
                    "{} events",
                    run.events.len()
                );
                let deepest = deepest_overlap(&run, &vec![r; k], &walls);
                assert!(
                    deepest <= 1e-9,
                    "k {k}, e {restitution}: overlap {deepest:e}"
                );
            }
        }
    }
}

/// The most events a run logged at one instant.
fn most_at_one_instant(run: &Simulation) -> usize {
    let (mut most, mut here) = (0, 0);
    for (k, e) in run.events.iter().enumerate() {
        here = if k > 0 && run.events[k - 1].time == e.time {
            here + 1
        } else {
            1
        };
        most = most.max(here);
    }
    most
}

#[test]
fn touching_trains_settle_as_a_cradle_does() {
    // k touching balls moving as one along an axis, into a resting ball or a wall (a train of
    // ten into a resting ball was refused after 1,705 events at one instant: every pair
    // left moving together was nudged apart, and each nudge followed up its neighbours). An
    // elastic cradle settles in k events at one instant (2k when the first collision is
    // inelastic); against a wall the reversal passes along the train as in a bubble sort,
    // k(k+1)/2. The starts are off the grid of binary
    // fractions, so the centres carry rounding.
    let r = 0.125;
    for k in [2usize, 3, 5, 9, 10, 16, 24] {
        for axis in [0, 1] {
            for wall in [false, true] {
                for restitution in [0.0, 0.5, 1.0] {
                    for friction in [0.0, 0.2] {
                        let along = |x: f64| {
                            let mut p = [0.1234567, -0.3456789];
                            p[axis] += x;
                            p
                        };
                        let mut v = [0.0, 0.0];
                        v[axis] = 1.0;
                        let mut balls: Vec<Ball> = (0..k)
                            .map(|m| ball(along(2.0 * r * m as f64), v, friction))
                            .collect();
                        let front = 2.0 * r * (k - 1) as f64;
                        let (lo, mut hi) = ([-40.0, -40.0], [40.0, 40.0]);
                        if wall {
                            hi[axis] = along(front + 0.5)[axis] + r;
                        } else {
                            balls.push(ball(along(front + 0.5 + 2.0 * r), [0.0; 2], friction));
                        }
                        let walls = Walls::new(lo, hi).expect("a box");
                        let radii = vec![r; balls.len()];
                        let run = run(&balls, &radii, walls, restitution, vec![1.0], 8.0);
                        let case = format!("k {k}, axis {axis}, wall {wall}, e {restitution}");
                        let bound = match (wall, restitution) {
                            (true, _) => k * (k + 1) / 2,
                            (false, 1.0) => k,
                            // The first collision, inelastic, leaves the front pair parting
                            // slower than the train: the balls behind catch up, elastically
                            // (every later event of the instant), and the wave runs back.
                            (false, _) => 2 * k,
                        };
                        let most = most_at_one_instant(&run);
                        assert!(most <= bound, "{case}: {most} events at one instant");
                        let deepest = deepest_overlap(&run, &radii, &walls);
                        assert!(deepest <= 1e-9, "{case}: overlap {deepest:e}");
                    }
                }
            }
        }
    }
}

#[test]
fn touching_trains_off_the_axes_move_on_without_overlap() {
    // The same trains at angles off the axes, whose exchanges leave the balls' velocities a
    // few ulps apart (the line of centres is rounded): pairs left so move as one body. An
    // elastic train of 80 at π/4 was refused after 6,185 events at one instant when only
    // equal velocities counted as one.
    let r = 0.125;
    for angle in [std::f64::consts::FRAC_PI_4, 0.0477, 0.3, 1.0] {
        let d = Vector2::new(angle.cos(), angle.sin());
        for (k, restitutions) in [
            (5usize, &[0.0, 0.5, 1.0][..]),
            (20, &[0.0, 1.0]),
            (80, &[1.0]),
        ] {
            for &restitution in restitutions {
                let mut balls: Vec<Ball> = (0..k)
                    .map(|m| {
                        let p = Vector2::new(0.1, 0.2) + d * (2.0 * r * m as f64);
                        ball(p.into(), d.into(), 0.0)
                    })
                    .collect();
                let front = Vector2::new(0.1, 0.2) + d * (2.0 * r * (k - 1) as f64 + 0.75);
                balls.push(ball(front.into(), [0.0; 2], 0.0));
                let walls = Walls::new([-60.0, -60.0], [60.0, 60.0]).expect("a box");
                let radii = vec![r; balls.len()];
                let run = run(&balls, &radii, walls, restitution, vec![1.0], 3.0);
                let case = format!("k {k}, angle {angle}, e {restitution}");
                if restitution == 1.0 {
                    let most = most_at_one_instant(&run);
                    assert!(most <= 2 * k, "{case}: {most} events at one instant");
                }
                let deepest = deepest_overlap(&run, &radii, &walls);
                assert!(deepest <= 1e-9, "{case}: overlap {deepest:e}");
            }
        }
    }
}

#[test]
fn masses_over_the_whole_float_range_give_finite_states_that_move_on() {
    let walls = Walls::new([-4.0, -4.0], [4.0, 4.0]).expect("a box");
    let masses = [
        5e-324,
        1e-308,
        1e-300,
        1e-10,
        1.0,
        1e10,
        1e300,
        1e308,
        f64::MAX,
    ];
    for &ma in &masses {
        for &mb in &masses {
            let balls = [
                ball([0.0, 0.0], [1.0, 0.1], 0.5),
                ball([0.5, 0.05], [0.0, 0.0], 0.5),
            ];
            let run = run(&balls, &[0.125; 2], walls, 0.5, vec![ma, mb], f64::INFINITY);
            assert!(!run.events.is_empty(), "masses {ma:e} {mb:e}");
            assert!(
                run.events.len() < 10_000,
                "masses {ma:e} {mb:e}: {}",
                run.events.len()
            );
            for b in &run.balls {
                assert!(
                    b.position()
                        .iter()
                        .chain(b.velocity().iter())
                        .all(|x| x.is_finite())
                );
            }
            // The heavier ball's velocity changes by the lighter's share at most.
            let first = run.events[0];
            assert_eq!((first.i, first.j), (0, Some(1)));
        }
    }
}

#[test]
fn a_light_ball_squeezed_against_a_wall_counts_the_digits_of_pi() {
    // Galperin's billiard: a ball of mass 100^k into one of mass 1 at rest before a wall,
    // elastic, along a line. The light ball shuttles between the heavy one and the wall
    // until the heavy one turns back; the collisions (both kinds) number the first k + 1
    // digits of π, ⌊π·10^k⌋, an independent reference for the event order of a squeeze.
    // (Past a ratio of ~2^52 the bounces crowd closer than float64 time resolves before the
    // heavy ball turns: such a run ends with no_progress; see the contract, § 4.5.)
    let walls = Walls::new([0.0, 0.0], [4.0, 1.0]).expect("a box");
    let digits = [3, 31, 314, 3_141, 31_415, 314_159, 3_141_592];
    for (k, &count) in digits.iter().enumerate() {
        let heavy = 100f64.powi(i32::try_from(k).expect("small"));
        let balls = [
            ball([0.5, 0.5], [-1.0, 0.0], 0.0),
            ball([0.2, 0.5], [0.0, 0.0], 0.0),
        ];
        let run = run(&balls, &[0.1; 2], walls, 1.0, vec![heavy, 1.0], 1.0);
        assert_eq!(run.events.len(), count, "mass ratio 100^{k}");
        let walls_hit = run.events.iter().filter(|e| e.wall.is_some()).count();
        assert_eq!(walls_hit, count / 2, "mass ratio 100^{k}");
        // The heavy ball leaves as fast as it came (energy kept), the light one slower.
        let [v_heavy, v_light] = [0, 1].map(|b| run.balls[b].velocity());
        assert!(v_heavy.x > 0.0 && v_light.x >= 0.0 && v_light.x < v_heavy.x);
        let energy = heavy * v_heavy.norm_squared() + v_light.norm_squared();
        assert!(
            (energy / heavy - 1.0).abs() < 1e-9,
            "mass ratio 100^{k}: {energy:e}"
        );
    }
}

#[test]
fn balls_as_wide_as_the_box_or_wider_are_refused_naming_the_radius() {
    for (width, radius) in [(1.0, 0.5), (1.0, 0.6), (1.0, 0.5 - 1e-12), (2.0, 1.0)] {
        let walls = Walls::new([0.0, 0.0], [width, 2.0]).expect("a box");
        let balls = [
            ball([width / 2.0, 1.9], [0.0, 0.0], 0.0),
            ball([width / 2.0, 1.0], [1.0, 0.3], 0.0),
        ];
        let options = SimulationOptions {
            t_end: 1.0,
            ..Default::default()
        };
        let err = simulate(&balls, &[0.01, radius], walls, &options).expect_err("too wide");
        assert_eq!((err.argument(), err.index()), ("radius", Some(1)), "{err}");
        assert!(
            matches!(err.kind(), InputErrorKind::WiderThanBox { axis: 0, .. }),
            "{err}"
        );
    }
}

#[test]
fn impossible_starts_are_refused_naming_the_balls() {
    let unit = Walls::new([0.0, 0.0], [1.0, 1.0]).expect("a box");
    let options = SimulationOptions {
        t_end: 1.0,
        ..Default::default()
    };
    // Two touching balls each overlapping a wall (200,000 events at t = 1.2e-16 before).
    let balls = [
        ball([0.2, 0.5], [1.0, 0.0], 0.1),
        ball([0.8, 0.5], [0.0, 0.0], 0.1),
    ];
    let err = simulate(&balls, &[0.3, 0.3], unit, &options).expect_err("overlaps a wall");
    assert_eq!((err.argument(), err.index()), ("pos", Some(0)));
    assert!(
        matches!(err.kind(), InputErrorKind::OutsideBox { axis: 0 }),
        "{err}"
    );
    // Wholly outside.
    let balls = [
        ball([0.5, 0.5], [0.0, 0.0], 0.0),
        ball([5.0, 0.5], [0.0, 0.0], 0.0),
    ];
    let err = simulate(&balls, &[0.1, 0.1], unit, &options).expect_err("outside");
    assert_eq!((err.argument(), err.index()), ("pos", Some(1)));
    // Overlapping balls: the lowest pair is named, whatever their order along x.
    let balls = [
        ball([0.7, 0.5], [0.0, 0.0], 0.0),
        ball([0.2, 0.2], [0.0, 0.0], 0.0),
        ball([0.55, 0.5], [0.0, 0.0], 0.0),
        ball([0.3, 0.3], [0.0, 0.0], 0.0),
    ];
    let err = simulate(&balls, &[0.1; 4], unit, &options).expect_err("overlap");
    assert_eq!((err.argument(), err.index()), ("pos", Some(2)));
    assert!(
        matches!(err.kind(), InputErrorKind::Overlap { other: 0, .. }),
        "{err}"
    );
    assert!(
        err.to_string()
            .starts_with("pos[2]: the ball overlaps ball 0"),
        "{err}"
    );
    // Touching (a rack: distances rounded) is fine.
    let s = 3f64.sqrt();
    let r = 0.05;
    let balls = [
        ball([0.5, 0.5], [0.0, 0.0], 0.0),
        ball([0.5 + r * s, 0.5 + r], [0.0, 0.0], 0.0),
        ball([0.5 + r * s, 0.5 - r], [0.0, 0.0], 0.0),
        ball([0.5 - 2.0 * r, 0.5], [1.0, 0.0], 0.0),
    ];
    simulate(&balls, &[r; 4], unit, &options).expect("touching is fine");
}

#[test]
fn an_observer_stops_a_run_and_sees_every_event() {
    let walls = Walls::new([0.0, 0.0], [1.0, 1.0]).expect("a box");
    let balls = [
        ball([0.5, 0.5], [1.0, 0.37], 0.0),
        ball([0.2, 0.2], [-0.3, 1.0], 0.0),
    ];
    let options = SimulationOptions {
        t_end: 1e6,
        ..Default::default()
    };
    let mut seen = Vec::new();
    let run = simulate_observed(&balls, &[0.1; 2], walls, &options, |p| {
        seen.push(p);
        if p.events == 500 {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    })
    .expect("valid");
    assert!(run.stopped);
    assert_eq!(run.events.len(), 500);
    assert_eq!(seen.len(), 500);
    assert!(seen.iter().zip(&run.events).all(|(p, e)| p.time == e.time));
    assert_eq!(run.end, run.events[499].time);
    // Without the break: the same first 500 events.
    let full = simulate(
        &balls,
        &[0.1; 2],
        walls,
        &SimulationOptions {
            max_events: Some(500),
            ..options
        },
    )
    .expect("valid");
    assert_eq!(full.events, run.events);
    assert!(!full.stopped);
}

/// A random simulation: 1 to 8 balls anywhere in a box (overlapping starts included), speeds
/// and frictions of every size, restitution 0 to 1, one mass or one each, at a power-of-two
/// scale.
fn simulation_cases() -> impl Strategy<Value = SimulationCase> {
    let ball = (
        0.0f64..1.0,
        0.0f64..1.0,
        -3.0f64..3.0,
        -3.0f64..3.0,
        4u8..=64,
    );
    let friction = prop_oneof![Just(0.0), 0.01f64..5.0, 1e-9f64..1e-6];
    (
        prop::collection::vec((ball, friction), 1..=8),
        -60i32..=60,
        prop_oneof![Just(0.0), Just(1.0), 0.0f64..=1.0],
        prop_oneof![Just(vec![1.0]), prop::collection::vec(1e-3f64..1e3, 8)],
        0.25f64..16.0,
    )
        .prop_map(|(balls, k, restitution, mass, t_end)| {
            let s = 2f64.powi(k);
            let mass = if mass.len() == 1 {
                mass
            } else {
                mass[..balls.len()].to_vec()
            };
            let balls: Vec<_> = balls
                .iter()
                .map(|&((x, y, vx, vy, r), f)| {
                    ([x, y], f64::from(r) / 256.0 * s, [vx * s, vy * s], f * s)
                })
                .collect();
            SimulationCase::in_square(2.0 * s, &balls, mass, restitution, t_end)
        })
}

proptest! {
    // Cases: PROPTEST_CASES, else proptest's default.
    #![proptest_config(ProptestConfig {
        rng_seed: RngSeed::Fixed(0x51A1_0001),
        ..ProptestConfig::default()
    })]

    #[test]
    fn random_simulations_keep_every_invariant(case in simulation_cases()) {
        if let Err(e) = simulation(&case) {
            panic!("{e}");
        }
    }
}

#[test]
fn a_ball_faster_than_float_time_resolves_is_stopped_inside_its_box() {
    // Found by the fuzz target `simulate`: a ball at 1.4e303 in a box 6e-151 wide reaches
    // the wall 1.8e-455 time units on, which rounds to 0. The wall's entry root underflowed
    // and was dropped, so the ball left the box (at 5e300 in the end). Now every bounce is
    // found at t = 0, and the run stops there with "no progress" (beyond the contract's
    // range, where the invariants ask only for an end or an error).
    let case = SimulationCase {
        balls: vec![[
            5.750244294703702e-151,
            4.525499232072452e-152,
            1.3715310171984222e303,
            0.0,
            0.0,
        ]],
        radii: vec![1.0740010652928298e-152],
        lo: [0.0, 0.0],
        hi: [6.10987272699921e-151, 6.10987272699921e-151],
        mass: vec![5e-324],
        restitution: 0.0,
        t_end: 0.00390625,
    };
    assert!(!simulation_invariants::within_promise(&case));
    if let Err(e) = simulation(&case) {
        panic!("{e}");
    }
    let b = &case.balls[0];
    let balls = [ball([b[0], b[1]], [b[2], b[3]], b[4])];
    let walls = Walls::new(case.lo, case.hi).expect("a valid box");
    let options = SimulationOptions {
        mass: case.mass.clone(),
        restitution: case.restitution,
        t_end: case.t_end,
        max_events: None,
        ..Default::default()
    };
    let e = simulate(&balls, &case.radii, walls, &options).expect_err("no progress");
    assert!(
        matches!(e.kind(), InputErrorKind::NoProgress { other: None, time, .. } if time == 0.0)
    );
}

#[test]
fn friction_far_beyond_the_motion_scale_parts_a_pressed_pair_no_faster_than_it_came() {
    // Found by the fuzz target `simulate_table`: a friction of 121 beside a box 5e-32 wide
    // and speeds of 1e-29. A pair pressed together at restitution 0 parted at the resting
    // contacts' least speed `√(2⁻²⁰·R·a)`, 1e10 times the balls' speeds: they outran time's
    // resolution and overlapped. The least parting speed is now capped at the pair's speeds.
    let side = 5e-32;
    let r = side / 16.0;
    let case = SimulationCase::in_square(
        side,
        &[
            ([0.5, 0.5], r, [1e-29, 3e-30], 121.0),
            (
                [0.5 + 2.0 * r / (side - 2.0 * r), 0.5],
                r,
                [0.0, 0.0],
                121.0,
            ),
            ([0.2, 0.2], r, [-4e-30, 1e-29], 121.0),
        ],
        vec![1.0],
        0.0,
        1e-30,
    );
    assert!(simulation_invariants::within_promise(&case));
    if let Err(e) = simulation(&case) {
        panic!("{e}");
    }
    let (balls, walls) = simulation_invariants::balls_and_walls(&case).expect("a valid case");
    let options = SimulationOptions {
        mass: case.mass.clone(),
        restitution: case.restitution,
        t_end: case.t_end,
        max_events: Some(1000),
        ..Default::default()
    };
    let run = simulate(&balls, &case.radii, walls, &options).expect("a run");
    assert!(!run.events.is_empty());
    assert_eq!(
        run.end, case.t_end,
        "the run must end at t_end, not at max_events"
    );
    let energy = |balls: &[Ball]| {
        balls
            .iter()
            .map(|b| b.velocity().norm_squared())
            .sum::<f64>()
    };
    let (before, after) = (energy(&balls), energy(&run.balls));
    assert!(after <= 4.0 * before, "energy {before:e} → {after:e}");
}

/// The fuzzed cases below: `ball` `(x, y, vx, vy, friction)` and a ball at rest in the
/// corner of a box 2 wide, both of radius 1/64 and mass 5e-324, restitution 0, to 1/256.
fn against_a_ball_in_a_corner(ball: [f64; 5]) -> SimulationCase {
    SimulationCase {
        balls: vec![ball, [0.015625, 0.015625, 0.0, 0.0, 0.0]],
        radii: vec![0.015625, 0.015625],
        lo: [0.0, 0.0],
        hi: [2.0, 2.0],
        mass: vec![5e-324, 5e-324],
        restitution: 0.0,
        t_end: 0.00390625,
    }
}

#[test]
fn a_ball_faster_than_time_resolves_later_on_is_stopped_with_no_progress() {
    // Found by the fuzz target `simulate`: a ball at 3e82 in a box 2 wide meets a wall every
    // 6.6e-83 time units; near t = 2.5e-32, whose ulp is 3.7e-48, every event of it comes at
    // one instant. Outside the contract's range (time must resolve the motion), where a run
    // must end or be refused: it is refused, naming the balls.
    let case = against_a_ball_in_a_corner([
        0.8651901178759442,
        0.042361667429617764,
        3.035420144102863e82,
        0.0,
        0.0,
    ]);
    assert!(!simulation_invariants::within_promise(&case));
    if let Err(e) = simulation(&case) {
        panic!("{e}");
    }
}

#[test]
fn a_pair_left_parting_slowly_at_an_instant_collides_again_rather_than_sink_in() {
    // Found by the fuzz target `simulate`: ball 0 hits the top wall, comes down onto ball 1
    // in the corner; at that instant ball 1 bounces off the bottom wall between two
    // collisions with ball 0, and the last left the pair parting at 3.7e-9 while ball 0's
    // friction pressed it into ball 1: they sank 4.2e-7 of their contact distance into each
    // other with no event, as rounding had put their centres a hair within it.
    let case = against_a_ball_in_a_corner([
        0.015625,
        0.677552786678874,
        -0.0,
        4111.0,
        0.06280549760056367,
    ]);
    assert!(simulation_invariants::within_promise(&case));
    if let Err(e) = simulation(&case) {
        panic!("{e}");
    }
}

#[test]
fn a_dense_gas_at_low_restitution_moves_on_and_never_overlaps() {
    // Issue 39 audit: 100 balls on a 10 × 10 grid, 0.01 apart, at restitution 0 stopped
    // with "no progress" in about a third of the runs: a pair parted at the least speed
    // `2⁻⁴⁰·(|va| + |vb|)` by an earlier event of the instant formed its parting speed again
    // a few ulps below it, was moved up to it once more (an ulp's change), and its follow-up
    // collided it again, 7,400 times at one instant. Restitution 0 to 0.1, with and without
    // friction, several seeds; each run ends at t_end without overlap.
    let side = 10usize;
    let n = side * side;
    let radius = 0.045;
    let walls = Walls::new([0.0, 0.0], [1.0, 1.0]).expect("a box");
    let radii = vec![radius; n];
    for seed in 1..=4u64 {
        let mut rng = Rng(seed);
        let velocities: Vec<[f64; 2]> = (0..n).map(|_| [rng.normal(), rng.normal()]).collect();
        for restitution in [0.0, 0.01, 0.1] {
            for friction in [0.0, 0.2] {
                let balls: Vec<Ball> = (0..n)
                    .map(|k| {
                        let at = |m: usize| (m as f64 + 0.5) / side as f64;
                        ball([at(k % side), at(k / side)], velocities[k], friction)
                    })
                    .collect();
                let run = run(&balls, &radii, walls, restitution, vec![1.0], 1.0);
                assert_eq!(run.end, 1.0);
                let deepest = deepest_overlap(&run, &radii, &walls);
                assert!(
                    deepest <= 1e-9,
                    "seed {seed}, e {restitution}, friction {friction}: overlap {deepest:e}"
                );
            }
        }
    }
}

/// A scene to scale: its name, balls (centre, velocity, friction), radius, box `[lo, hi]²`,
/// restitution and `t_end`.
type Scene = (
    &'static str,
    Vec<([f64; 2], [f64; 2], f64)>,
    f64,
    [f64; 2],
    f64,
    f64,
);

/// `simulate` of `balls` (centre, velocity, friction) of `radius` in the box `[lo, hi]²`,
/// with every length scaled by `2^e`.
fn scaled_run(
    balls: &[([f64; 2], [f64; 2], f64)],
    radius: f64,
    [lo, hi]: [f64; 2],
    options: &SimulationOptions,
    e: i32,
) -> Simulation {
    let s = 2f64.powi(e);
    let scaled: Vec<Ball> = balls
        .iter()
        .map(|&(p, v, f)| ball(p.map(|x| x * s), v.map(|x| x * s), f * s))
        .collect();
    let walls = Walls::new([lo * s; 2], [hi * s; 2]).expect("a box");
    let radii = vec![radius * s; balls.len()];
    simulate(&scaled, &radii, walls, options).expect("a valid simulation")
}

#[test]
fn a_scene_scaled_by_a_power_of_two_runs_to_the_same_bits_over_the_float_range() {
    // Contract §1: scaling every length by 2^e changes no time. The collisions were resolved
    // with squares of the caller's lengths: from 2^512 up they overflowed (two elastic balls
    // stuck together, or kept their velocities and collided at one instant without end),
    // from 2^-537 down they underflowed (balls sank into each other with no event; apart
    // balls were refused as overlapping at the start).
    let mut rng = Rng(0x5ca1e);
    let gas: Vec<_> = (0..36)
        .map(|k| {
            let (x, y) = (1.1 + 0.16 * f64::from(k % 6), 1.1 + 0.16 * f64::from(k / 6));
            (
                [x, y],
                [rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)],
                0.3,
            )
        })
        .collect();
    let scenes: [Scene; 4] = [
        (
            "elastic pair",
            vec![([0.0, 0.0], [1.0, 0.0], 0.0), ([1.0, 0.3], [0.0, 0.0], 0.0)],
            0.25,
            [-2.0, 3.0],
            1.0,
            20.0,
        ),
        (
            "resting contact",
            vec![([0.0, 0.0], [1.0, 0.1], 1.0), ([0.5, 0.0], [0.5, 0.0], 1.0)],
            0.125,
            [-4.0, 4.0],
            0.0,
            f64::INFINITY,
        ),
        (
            "pressed pair",
            vec![
                ([0.0, 0.0], [1.0, 0.0], 1.0),
                ([0.5, 0.0], [0.0, 0.05], 1.0),
            ],
            0.125,
            [-4.0, 4.0],
            0.0,
            f64::INFINITY,
        ),
        ("gas", gas, 0.05, [1.0, 2.0], 0.0, 3.0),
    ];
    for (name, balls, radius, walls, restitution, t_end) in &scenes {
        let options = SimulationOptions {
            restitution: *restitution,
            t_end: *t_end,
            max_events: Some(20_000),
            ..Default::default()
        };
        let reference = scaled_run(balls, *radius, *walls, &options, 0);
        assert!(reference.events.len() > 1, "{name}");
        for e in [-900, -600, -538, -520, -300, 300, 488, 512, 600, 900] {
            let run = scaled_run(balls, *radius, *walls, &options, e);
            assert_eq!(run.events, reference.events, "{name} at 2^{e}");
            let s = 2f64.powi(e);
            for (got, want) in run.balls.iter().zip(&reference.balls) {
                assert_eq!(got.position(), want.position() * s, "{name} at 2^{e}");
                assert_eq!(got.velocity(), want.velocity() * s, "{name} at 2^{e}");
            }
        }
    }
}

#[test]
fn a_collision_far_faster_than_its_contact_distance_is_resolved() {
    // A radius of 2^-k beside a speed of 1: the collision's unit came from the speed, where
    // the separation's square underflowed (from k = 515 the energy drifted, 0.8 % at 535;
    // at 540 the distance was 0, the velocities kept, and the run stopped with no progress).
    for k in [0, 300, 515, 520, 535, 540, 600, 900] {
        let r = 2f64.powi(-k);
        let walls = Walls::new([-4.0 * r, -4.0 * r], [8.0 * r, 4.0 * r]).expect("a box");
        let balls = [
            ball([0.0, 0.0], [1.0, 0.0], 0.0),
            ball([2.0 * r, 0.5 * r], [0.0, 0.0], 0.0),
        ];
        let options = SimulationOptions {
            max_events: Some(1),
            ..Default::default()
        };
        let run = simulate(&balls, &[0.7 * r; 2], walls, &options).expect("a valid run");
        assert_eq!((run.events[0].i, run.events[0].j), (0, Some(1)), "2^-{k}");
        let energy: f64 = run.balls.iter().map(|b| b.velocity().norm_squared()).sum();
        assert!((energy - 1.0).abs() < 1e-14, "2^-{k}: {energy}");
    }
}
