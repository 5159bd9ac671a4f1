//! `billiards::ball_path` against the evolution it stands for, and in the calendar.
//!
//! - the path's centre and velocity at random times agree with [`evolve`] (pooltool's
//!   closed-form motion, checked against pooltool itself in `tests/reference/billiards.rs`) to
//!   a few roundings; [`BallPath::state_at`] is that evolution;
//! - its shape: the motion states in order, the accelerations of the model, continuity at the
//!   segment starts, at rest at the end; made again from a segment's start state it is the
//!   same tail, to the bit (what an event loop does at a transition);
//! - bad input is an error naming the field;
//! - in a [`CollisionSchedule`] on a pool table with transitions on, a shot's events come out
//!   in order: the transitions at the segment starts, the collision where the centres are two
//!   radii apart, the cushion where the centre is a radius from the rail.

use crate::support::rng;

use ballcollide::billiards::{
    BallBallResolver, BallParams, BallPath, BallState, FrictionalInelastic, KISS_SPACER,
    MotionState, ball_path, evolve, make_kiss, slip_velocity,
};
use ballcollide::geometry::{ObjectKind, PoolTable};
use ballcollide::schedule::{CollisionSchedule, Event, ScheduleOptions};
use ballcollide::{InputErrorKind, Path2};
use nalgebra::{Vector2, Vector3};
use rng::Rng;

/// Random parameters: pooltool's three sets, or any within a wide range.
fn random_params(rng: &mut Rng) -> BallParams {
    match rng.below(5) {
        0 => BallParams::default(),
        1 => BallParams::snooker(),
        2 => BallParams::carom(),
        _ => BallParams {
            radius: rng.uniform(0.02, 0.035),
            u_s: rng.uniform(0.05, 0.8),
            u_r: rng.uniform(0.002, 0.05),
            u_sp_proportionality: rng.uniform(0.05, 2.0),
            g: rng.uniform(1.0, 20.0),
            ..BallParams::default()
        },
    }
}

/// A random ball: any motion state, speeds from 0.1 mm/s to 12 m/s, spins of every kind.
fn random_state(rng: &mut Rng, params: &BallParams) -> BallState {
    let position = Vector2::new(rng.uniform(0.0, 1.27), rng.uniform(0.0, 2.54));
    let speed = 10f64.powf(rng.uniform(-4.0, 1.08));
    let angle = rng.uniform(0.0, std::f64::consts::TAU);
    let velocity = Vector2::new(angle.cos(), angle.sin()) * speed;
    let r = params.radius;
    let rolling = Vector3::new(-velocity.y / r, velocity.x / r, 0.0);
    let side = rng.uniform(-150.0, 150.0);
    let motion = [
        MotionState::Sliding,
        MotionState::Sliding,
        MotionState::Rolling,
        MotionState::Spinning,
        MotionState::Stationary,
    ][rng.below(5) as usize];
    let (velocity, w) = match motion {
        MotionState::Sliding => {
            let w = match rng.below(4) {
                0 => Vector3::zeros(),
                1 => rolling * rng.uniform(-3.0, 3.0),
                2 => rolling,
                _ => {
                    Vector3::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), 0.0) * (speed / r)
                }
            };
            (velocity, w)
        }
        MotionState::Rolling => (velocity, rolling),
        _ => (Vector2::zeros(), Vector3::zeros()),
    };
    let mut w = w;
    if motion != MotionState::Stationary {
        w.z = side;
    }
    BallState::new(position, velocity, w, motion)
}

/// The scales of a ball's positions, velocities and spins (as in `billiards_reference.rs`),
/// and how far a rounding of the absolute time `t` moves each.
fn allowed(state: &BallState, params: &BallParams, motion: &BallPath, t: f64) -> [f64; 2] {
    let speed = state.velocity.norm() + slip_velocity(state, params.radius).norm();
    let moving =
        motion.path().segments().last().map_or(0.0, |s| s.start) - motion.path().first_start();
    let eps = f64::EPSILON;
    let dt = 8.0 * eps * t.abs().max(motion.path().first_start().abs() + moving);
    let deceleration = params.u_s.max(params.u_r) * params.g;
    [
        1e-13 * (state.position.amax() + speed * moving) + speed * dt,
        1e-13 * speed + deceleration * dt,
    ]
}

#[test]
fn the_path_is_the_evolution() {
    let mut rng = Rng(0x5eed_b177_1a2d_5001);
    let mut worst = [0.0f64; 2];
    for case in 0..4000 {
        let params = random_params(&mut rng);
        let state = random_state(&mut rng, &params);
        let start = if case % 2 == 0 {
            0.0
        } else {
            rng.uniform(-50.0, 100.0)
        };
        let motion = ball_path(&state, &params, start).expect("a valid ball");
        let end = motion.path().segments().last().map_or(start, |s| s.start);
        for _ in 0..8 {
            let t = start + (end - start) * rng.uniform(0.0, 1.2);
            let by_evolution = evolve(&state, &params, t - start);
            let (p, v) = (motion.path().position_at(t), motion.path().velocity_at(t));
            let [pos_bar, vel_bar] = allowed(&state, &params, &motion, t);
            let errors = [
                (p - by_evolution.position).amax(),
                (v - by_evolution.velocity).amax(),
            ];
            assert!(
                errors[0] <= pos_bar && errors[1] <= vel_bar,
                "case {case}, t = {t}: {errors:?} beyond {pos_bar:e}, {vel_bar:e}\n{state:?}\n{motion:?}"
            );
            for k in 0..2 {
                worst[k] = worst[k].max(errors[k] / [pos_bar, vel_bar][k]);
            }
            // The full state at t: the same evolution, from the segment's start.
            let at = motion.state_at(t);
            assert!((at.position - p).amax() <= pos_bar, "case {case}: {at:?}");
            assert!(
                (at.velocity - by_evolution.velocity).amax() <= vel_bar,
                "case {case}: {at:?}"
            );
        }
    }
    println!(
        "worst error over its bound: position {:.2}, velocity {:.2}",
        worst[0], worst[1]
    );
}

#[test]
fn the_paths_shape() {
    let mut rng = Rng(0xb411_5eed_0000_0002);
    let mut seen = std::collections::BTreeSet::new();
    for case in 0..4000 {
        let params = random_params(&mut rng);
        let state = random_state(&mut rng, &params);
        let start = rng.uniform(0.0, 10.0);
        let motion = ball_path(&state, &params, start).expect("a valid ball");
        let (segments, states) = (motion.path().segments(), motion.states());
        assert_eq!(segments.len(), states.len());
        assert_eq!((segments[0].start, states[0]), (start, state));
        // The stages in their order, ending at rest for good.
        let order = |m: MotionState| {
            [
                MotionState::Sliding,
                MotionState::Rolling,
                MotionState::Spinning,
                MotionState::Stationary,
            ]
            .iter()
            .position(|&x| x == m)
        };
        let stages: Vec<_> = states
            .iter()
            .map(|s| order(s.motion).expect("on the table"))
            .collect();
        assert!(
            stages.windows(2).all(|w| w[0] < w[1]),
            "case {case}: {states:?}"
        );
        assert_eq!(
            states.last().map(|s| s.motion),
            Some(MotionState::Stationary)
        );
        seen.insert(
            states
                .iter()
                .map(|s| format!("{:?}", s.motion))
                .collect::<Vec<_>>()
                .join("-"),
        );
        let last = segments.last().expect("a segment");
        assert_eq!(
            (last.velocity, last.acceleration),
            (Vector2::zeros(), Vector2::zeros())
        );
        for (k, (segment, s)) in segments.iter().zip(states).enumerate() {
            // The accelerations of the model: u_s·g against the slip, u_r·g against v.
            let a = segment.acceleration.norm();
            match s.motion {
                MotionState::Sliding if slip_velocity(s, params.radius) != Vector2::zeros() => {
                    assert!(
                        (a - params.u_s * params.g).abs() <= 1e-15 * a,
                        "case {case}"
                    );
                    let slip = slip_velocity(s, params.radius);
                    let along = segment.acceleration.dot(&slip) / (a * slip.norm());
                    assert!(along < -1.0 + 1e-15, "case {case}: against the slip");
                }
                MotionState::Rolling if s.velocity != Vector2::zeros() => {
                    assert!(
                        (a - params.u_r * params.g).abs() <= 1e-15 * a,
                        "case {case}"
                    );
                }
                _ => assert_eq!(a, 0.0),
            }
            // Where a segment starts, the one before ended (to roundings).
            if k > 0 {
                let before = segments[k - 1];
                let [pos_bar, vel_bar] = allowed(&state, &params, &motion, segment.start);
                let jump = (before.position_at(segment.start) - segment.position).amax();
                assert!(jump <= pos_bar, "case {case}, segment {k}: {jump:e}");
                let kink = (before.velocity_at(segment.start) - segment.velocity).amax();
                assert!(kink <= vel_bar, "case {case}, segment {k}: {kink:e}");
                // The state there is the path's, to the bit: evolved for no time.
                assert_eq!(motion.state_at(segment.start), *s, "case {case}");
            }
            // From its own start state, the same tail: an event loop re-making the path at a
            // transition changes nothing.
            let tail = ball_path(s, &params, segment.start).expect("a valid ball");
            assert_eq!(
                tail.path().segments(),
                &segments[k..],
                "case {case}, segment {k}"
            );
            assert_eq!(tail.states(), &states[k..]);
        }
    }
    println!("stage sequences seen: {seen:?}");
    assert_eq!(seen.len(), 6, "every sequence of stages: {seen:?}");
}

#[test]
fn a_pocketed_ball_rests_and_a_frictionless_slide_never_ends() {
    let params = BallParams::default();
    let mut state = BallState::at_rest(Vector2::new(0.1, 0.1));
    state.motion = MotionState::Pocketed;
    let motion = ball_path(&state, &params, 1.0).expect("valid");
    assert_eq!(motion.path().segments().len(), 1);
    let slide = BallState::new(
        Vector2::zeros(),
        Vector2::new(1.0, 0.0),
        Vector3::zeros(),
        MotionState::Sliding,
    );
    let ice = BallParams { u_s: 0.0, ..params };
    let motion = ball_path(&slide, &ice, 0.0).expect("valid");
    assert_eq!(motion.path().segments().len(), 1);
    assert_eq!(motion.path().position_at(10.0), Vector2::new(10.0, 0.0));
    // A slide without slip is an empty segment, and the ball rolls at once.
    let rolling = BallState::new(
        Vector2::zeros(),
        Vector2::new(1.0, 0.0),
        Vector3::new(0.0, 0.5 / 0.25, 0.0),
        MotionState::Sliding,
    );
    let round = BallParams {
        radius: 0.5,
        ..params
    };
    let motion = ball_path(&rolling, &round, 0.0).expect("valid");
    let starts: Vec<_> = motion.path().segments().iter().map(|s| s.start).collect();
    assert_eq!(starts[..2], [0.0, 0.0]);
    assert_eq!(motion.states()[1].motion, MotionState::Rolling);
}

#[test]
fn bad_input_is_named() {
    let params = BallParams::default();
    let state = BallState::at_rest(Vector2::new(0.5, 0.5));
    let err = ball_path(
        &state,
        &BallParams {
            radius: 0.0,
            ..params
        },
        0.0,
    )
    .unwrap_err();
    assert_eq!(
        (err.argument(), err.kind()),
        ("radius", InputErrorKind::NonPositiveBallRadius(0.0))
    );
    let err = ball_path(&state, &BallParams { g: -1.0, ..params }, 0.0).unwrap_err();
    assert_eq!(err.to_string(), "g: gravity must be > 0, got -1");
    let mut bad = state;
    bad.velocity.y = f64::INFINITY;
    let err = ball_path(&bad, &params, 0.0).unwrap_err();
    assert_eq!((err.argument(), err.index()), ("velocity", Some(1)));
    let err = ball_path(&state, &params, f64::NAN).unwrap_err();
    assert_eq!(err.argument(), "start");
    // Speeds whose squares overflow (pooltool's norm, `sqrt(x² + y²)`, is then infinite, and
    // so is the roll's time): an answer or an error, never a panic.
    let mut fast = state;
    fast.velocity.x = 1e300;
    fast.motion = MotionState::Rolling;
    let _ = ball_path(&fast, &params, 0.0);
    fast.motion = MotionState::Sliding;
    let _ = ball_path(&fast, &params, 0.0);
}

/// The events of a calendar of billiard balls until the first collision of two balls, as an
/// event loop would drive it: at a transition the ball's path is made again from the state
/// there (the same tail), at a cushion the ball is taken off the table (no resolver yet).
fn events_until_a_collision(
    schedule: &mut CollisionSchedule<2>,
    motions: &mut [BallPath],
) -> Vec<Event> {
    let mut events = Vec::new();
    while let Some(event) = schedule.next_event() {
        events.push(event);
        match event {
            Event::Transition(t) => {
                let motion = &motions[t.ball];
                assert_eq!(t.time, motion.path().segments()[t.segment].start);
                let state = motion.states()[t.segment];
                let again = ball_path(&state, motion.params(), t.time).expect("valid");
                schedule
                    .update(&[t.ball], vec![again.path().clone()])
                    .expect("an update");
                motions[t.ball] = again;
            }
            Event::Object(hit) => schedule.retire(hit.ball).expect("in range"),
            _ => break,
        }
    }
    events
}

#[test]
fn a_shots_events_in_the_calendar() {
    let params = BallParams::default();
    let r = params.radius;
    let table = PoolTable::default().table().expect("the table");
    // A stun shot with side spin up the table at a ball at rest; a third ball rolls slowly
    // into the bottom rail.
    let shots = [
        BallState::new(
            Vector2::new(0.635, 0.4),
            Vector2::new(0.0, 1.2),
            Vector3::new(0.0, 0.0, 40.0),
            MotionState::Sliding,
        ),
        BallState::at_rest(Vector2::new(0.64, 1.5)),
        BallState::new(
            Vector2::new(1.0, 0.3),
            Vector2::new(0.05, -0.6),
            Vector3::new(0.6 / r, 0.05 / r, 0.0),
            MotionState::Rolling,
        ),
    ];
    let mut motions: Vec<BallPath> = shots
        .iter()
        .map(|s| ball_path(s, &params, 0.0).expect("valid"))
        .collect();
    let paths: Vec<Path2> = motions.iter().map(|m| m.path().clone()).collect();
    let options = ScheduleOptions {
        table,
        transitions: true,
        ..Default::default()
    };
    let mut schedule = CollisionSchedule::new(paths, &[r; 3], options).expect("a calendar");
    let events = events_until_a_collision(&mut schedule, &mut motions);
    // The cue ball starts rolling, the third ball reaches the rail, the cue ball meets the
    // object ball.
    let [
        Event::Transition(roll),
        Event::Object(rail),
        Event::Collision(hit),
    ] = events[..]
    else {
        panic!("{events:?}");
    };
    assert_eq!((roll.ball, roll.segment), (0, 1));
    // Made again at the transition: it starts there, rolling.
    assert_eq!(motions[0].states()[0].motion, MotionState::Rolling);
    assert_eq!(roll.time, motions[0].path().first_start());
    // The rail at y = 0: the centre a radius from it.
    assert_eq!((rail.ball, rail.kind), (2, ObjectKind::Segment));
    let centre = motions[2].path().position_at(rail.time);
    assert!((centre.y - r).abs() < 1e-12, "{centre}");
    // The two balls: centres two radii apart.
    assert_eq!((hit.i, hit.j), (0, 1));
    let gap =
        (motions[0].path().position_at(hit.time) - motions[1].path().position_at(hit.time)).norm();
    assert!((gap - 2.0 * r).abs() < 1e-12, "{gap}");
    assert!(roll.time < rail.time && rail.time < hit.time);
}

/// Where pooltool's `make_kiss` fails (balls with the same velocity: its quadratic has no
/// root, and it takes the argmin of nothing), the balls are pushed apart along the line of
/// centres; a collision of them is resolved all the same, momentum kept.
#[test]
fn balls_moving_together_are_pushed_apart() {
    let params = BallParams::default();
    let r = params.radius;
    let v = Vector2::new(0.3, 0.4);
    let w = Vector3::new(-0.4 / r, 0.3 / r, 0.0);
    let a = BallState::new(Vector2::new(0.5, 0.5), v, w, MotionState::Rolling);
    let b = BallState {
        position: Vector2::new(0.5 + 2.0 * r - 1e-7, 0.5),
        ..a
    };
    let [ka, kb] = make_kiss([&a, &b], r);
    let gap = (kb.position - ka.position).norm();
    assert!((gap - (2.0 * r + KISS_SPACER)).abs() < 1e-15, "{gap}");
    assert_eq!((ka.position.y, kb.position.y), (0.5, 0.5));
    let [ra, rb] = FrictionalInelastic::default().resolve([&a, &b], [&params, &params]);
    let momentum = (ra.velocity + rb.velocity - 2.0 * v).norm();
    assert!(momentum < 1e-15, "{momentum}");
    // Along the line they had one speed: pooltool's tie-break makes the second ball the
    // "chaser", which gives a tenth of its speed along the line to the first.
    assert!((ra.velocity.x - 0.33).abs() < 1e-15 && (rb.velocity.x - 0.27).abs() < 1e-15);
}
