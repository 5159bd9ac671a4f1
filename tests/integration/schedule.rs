//! `schedule`: the calendar's answers must be, bit for bit, those of recomputing every pair
//! with `path_collision_time` (and every ball's wall contact with `Walls::first_contact`),
//! ties to the lowest `i`, then `j`, after any sequence of updates: events resolved as a
//! simulation would, updates that skip events, refused updates (which must leave the
//! calendar exactly as it was). Scenes of every kind of path: frictionless, friction balls,
//! at rest, piecewise with jumps, accelerating for ever; on dyadic grids (exact contacts,
//! tangencies, ties) and with full-mantissa numbers; with and without walls and a horizon.
//! The scenes, the operations and the checks are `tests/support/schedule_invariants.rs`,
//! which the fuzz target `schedule` runs too (docs/fuzzing.md).

use crate::support::cases;
use crate::support::schedule_invariants;

use ballcollide::Ball;
use ballcollide::geometry::{LineSegment, SegmentSide, Table};
use ballcollide::path::{Path, Segment};
use ballcollide::schedule::{CollisionSchedule, Event, FrictionPath, ScheduleOptions, Side, Walls};
use nalgebra::{SVector, Vector2};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;
use schedule_invariants::{Choices, Draw, Numbers, Plan, Scene, Seen, brute_collision};

use crate::support::rng;
use rng::Rng;

impl Choices for Rng {
    fn below(&mut self, n: u64) -> u64 {
        Rng::below(self, n)
    }

    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        Rng::uniform(self, lo, hi)
    }
}

/// `fast` cases in the fast tier (`PROPTEST_CASES` in the thorough one) from a fixed seed.
fn config(fast: u32, seed: u64) -> ProptestConfig {
    ProptestConfig {
        cases: cases::cases(fast),
        rng_seed: RngSeed::Fixed(seed),
        ..ProptestConfig::default()
    }
}

/// Checks the calendar against brute force (`schedule_invariants::check`), and returns its
/// next event.
fn check<const D: usize>(s: &mut CollisionSchedule<D>) -> Option<Event> {
    schedule_invariants::check(s).unwrap_or_else(|e| panic!("{e}"))
}

/// `steps` random events and updates on `s`, checked against brute force throughout
/// (`schedule_invariants::play`, with the tests' plan); the events met, by class.
fn play<const D: usize>(s: &mut CollisionSchedule<D>, draw: &mut Draw<Rng>, steps: usize) -> Seen {
    schedule_invariants::play(s, draw, steps, Plan::TESTS).unwrap_or_else(|e| panic!("{e}"))
}

/// A random scene and a long random sequence of events and updates, checked throughout; the
/// events met, by class.
#[allow(clippy::too_many_arguments)]
fn run<const D: usize>(
    seed: u64,
    numbers: Numbers,
    n: usize,
    walls: bool,
    table: bool,
    transitions: bool,
    t_max: f64,
    steps: usize,
) -> Seen {
    let size = 1.0 + (n as f64).sqrt();
    let mut draw = Draw::new(Rng(seed | 1), numbers, size);
    let scene = Scene {
        n,
        walls,
        table,
        transitions,
        t_max,
        start: 0.0,
        stagger: false,
    };
    let (mut s, made) = schedule_invariants::calendar::<D, _>(&mut draw, &scene)
        .unwrap_or_else(|e| panic!("{e}"))
        .expect("a scene in its own units is valid");
    schedule_invariants::play(&mut s, &mut draw, steps, Plan::TESTS)
        .unwrap_or_else(|e| panic!("{e}\nscene: {made:?}"))
}

proptest! {
    #![proptest_config(config(48, 0x5C4E_D01E))]

    #[test]
    fn the_calendar_is_brute_force_bit_for_bit_in_2d(
        seed in any::<u64>(),
        dyadic in any::<bool>(),
        n in 0usize..24,
        walls in any::<bool>(),
        horizon in prop_oneof![Just(f64::INFINITY), 1.0f64..20.0],
    ) {
        let numbers = if dyadic { Numbers::Dyadic } else { Numbers::Full };
        run::<2>(seed, numbers, n, walls, false, false, horizon, 60);
    }

    #[test]
    fn the_calendar_is_brute_force_bit_for_bit_in_3d(
        seed in any::<u64>(),
        dyadic in any::<bool>(),
        n in 0usize..16,
        walls in any::<bool>(),
    ) {
        let numbers = if dyadic { Numbers::Dyadic } else { Numbers::Full };
        run::<3>(seed, numbers, n, walls, false, false, f64::INFINITY, 40);
    }
}

/// The calendar with a table (and transitions, half the time) against brute force, over
/// `cases` random scenes of dimension `D`; every class of event must come up.
fn tables_are_brute_force<const D: usize>(cases: u64, seed: u64, most: u64) {
    let mut seen = [0; 4];
    let mut rng = Rng(seed);
    for case in 0..cases {
        let numbers = if case % 2 == 0 {
            Numbers::Dyadic
        } else {
            Numbers::Full
        };
        let n = rng.below(most) as usize;
        let horizon = if case % 3 == 0 {
            rng.uniform(1.0, 20.0)
        } else {
            f64::INFINITY
        };
        let met = run::<D>(
            rng.below(u64::MAX),
            numbers,
            n,
            case % 4 != 1,
            true,
            case % 2 == 1,
            horizon,
            60,
        );
        for (total, k) in seen.iter_mut().zip(met.events) {
            *total += k;
        }
    }
    assert!(
        seen.iter().all(|&k| k >= 5),
        "events seen by class: {seen:?}"
    );
}

#[test]
fn the_calendar_with_a_table_and_transitions_is_brute_force_in_2d() {
    tables_are_brute_force::<2>(cases::cases(48).into(), 0x7AB1_E002, 24);
}

#[test]
fn the_calendar_with_a_table_and_transitions_is_brute_force_in_3d() {
    tables_are_brute_force::<3>(cases::cases(32).into(), 0x7AB1_E003, 16);
}

/// Grids that collapse to one cell with more balls than the calendar keeps bits for (64): a
/// box of ±1e308 (its width overflows), or first positions about 1.8e308 apart. Brute force
/// throughout, 65 to 1,000 balls.
#[test]
fn grids_of_one_cell_with_many_balls_are_brute_force() {
    for (seed, n, steps) in [
        (1u64, 65, 40),
        (2, 71, 40),
        (3, 130, 25),
        (4, 400, 6),
        (5, 1000, 3),
    ] {
        let size = 1.0 + (n as f64).sqrt();
        let mut draw = Draw::new(Rng(seed), Numbers::Full, size);
        let radii: Vec<f64> = (0..n).map(|_| draw.radius()).collect();
        // A box of ±1e308.
        let paths: Vec<Path<2>> = (0..n)
            .map(|_| draw.path(0.0, None).expect("valid"))
            .collect();
        let walls = Walls::new([-1e308; 2], [1e308; 2]).expect("a box");
        let options = ScheduleOptions {
            walls: Some(walls),
            ..Default::default()
        };
        let mut s = CollisionSchedule::new(paths, &radii, options).expect("valid");
        play(&mut s, &mut draw, steps);
        // No walls, one ball far away.
        let mut paths: Vec<Path<2>> = (0..n)
            .map(|_| draw.path(0.0, None).expect("valid"))
            .collect();
        let far = Vector2::new(-0.9e308, 0.9e308);
        paths[n / 2] = Path::new(vec![Segment::at_rest(0.0, far)]).expect("valid");
        let mut s =
            CollisionSchedule::new(paths, &radii, ScheduleOptions::default()).expect("valid");
        play(&mut s, &mut draw, steps);
    }
}

/// A ball of radius 3/8 `beyond` the near end `Q = (1.25, 1.25)` of a segment whose far end is
/// `2^k` away, within its radius of the line and moving towards it (its centre `(x, y)`, `z =
/// 0` in 3-D): the calendar's next event against brute force; whether it is the segment.
fn far_ended_segment<const D: usize>(k: i32, beyond: f64, side: SegmentSide) -> bool {
    let q = Vector2::new(1.25, 1.25);
    let along = Vector2::new(0.6, 0.8);
    let across = Vector2::new(-0.8, 0.6);
    let segment = LineSegment::new(q + along * 2f64.powi(k), q, side).expect("a segment");
    let centre = q - along * beyond + across * 0.125;
    let embed =
        |v: Vector2<f64>| SVector::<f64, D>::from_fn(|i, _| v.get(i).copied().unwrap_or(0.0));
    let line = |p: Vector2<f64>, v: Vector2<f64>| {
        Path::new(vec![Segment::new(
            0.0,
            embed(p),
            embed(v),
            SVector::zeros(),
        )])
        .expect("a path")
    };
    // Two more balls, far from the segment, that collide at t = 3/4: the calendar does not
    // move the first ball's box on past that.
    let paths = vec![
        line(centre, -across * 0.5),
        line(Vector2::new(-50.0, -50.0), Vector2::new(1.0, 0.0)),
        line(Vector2::new(-48.5, -50.0), Vector2::zeros()),
    ];
    let options = ScheduleOptions {
        table: Table {
            segments: vec![segment],
            ..Table::default()
        },
        ..ScheduleOptions::default()
    };
    let mut s = CollisionSchedule::new(paths, &[0.375; 3], options).expect("valid");
    matches!(check(&mut s), Some(Event::Object(_)))
}

/// Fuzz finding (target `schedule`): the foot test of a segment's contact was exact to a few
/// roundings of its far end's magnitude, so that next to the near end a ball up to about
/// `2⁻⁵³` of the segment's length beyond it counted as on it. The calendar pruned those
/// contacts (the segment's box was its ends' box to the ulp), and so missed object events
/// that asking every object gave. The foot test is now exact next to either end (each end's
/// test from the centre's offset from that end): the ball is on the flat part exactly when it
/// is before the near end (and on a side that counts), and the calendar agrees with brute
/// force either way.
#[test]
fn segments_with_a_far_end_are_brute_force_next_to_the_near_one() {
    for k in [20, 53, 60, 80, 100, 107, 150, 300] {
        for beyond in [-0.5, -0.0625, 0.0625, 0.5, 1.0, 1e3, 1e9, 1e15, 1e30] {
            for side in [SegmentSide::Both, SegmentSide::Left] {
                // The ball is on the segment's right (P is the far end).
                let on = beyond < 0.0 && side == SegmentSide::Both;
                for reported in [
                    far_ended_segment::<2>(k, beyond, side),
                    far_ended_segment::<3>(k, beyond, side),
                ] {
                    assert_eq!(reported, on, "2^{k}, beyond {beyond}, {side:?}");
                }
            }
        }
    }
}

#[test]
fn a_dense_frictionless_box_is_brute_force_over_a_thousand_events() {
    // Many balls on a grid in a box, every path one segment: the simulation's case, with
    // re-checks as the horizons are passed and walls all the time.
    for seed in [1u64, 2, 3] {
        let mut rng = Rng(seed);
        let side = 8usize;
        let n = side * side;
        let r = 0.25 / side as f64;
        let mut paths = Vec::new();
        for k in 0..n {
            let p = Vector2::new((k % side) as f64 + 0.5, (k / side) as f64 + 0.5) / side as f64;
            let v = Vector2::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
            paths.push(Path::new(vec![Segment::new(0.0, p, v, Vector2::zeros())]).expect("valid"));
        }
        let walls = Walls::new([0.0, 0.0], [1.0, 1.0]).expect("a box");
        let options = ScheduleOptions {
            walls: Some(walls),
            ..Default::default()
        };
        let mut s = CollisionSchedule::new(paths, &vec![r; n], options).expect("valid");
        for _ in 0..1000 {
            let event = check(&mut s).expect("balls in a box always meet something");
            let t = event.time();
            // Reflect: a wall flips the normal velocity, a collision swaps normal components.
            let velocity = |s: &CollisionSchedule<2>, i: usize| s.path(i).velocity_at(t);
            let position = |s: &CollisionSchedule<2>, i: usize| s.path(i).position_at(t);
            let line = |p: Vector2<f64>, v: Vector2<f64>| {
                Path::new(vec![Segment::new(t, p, v, Vector2::zeros())]).expect("valid")
            };
            match event {
                Event::Wall(w) => {
                    let mut v = velocity(&s, w.ball);
                    v[w.axis] = match w.side {
                        Side::Low => v[w.axis].abs(),
                        Side::High => -v[w.axis].abs(),
                    };
                    let p = position(&s, w.ball);
                    s.update(&[w.ball], vec![line(p, v)]).expect("valid");
                }
                Event::Collision(c) => {
                    let (pi, pj) = (position(&s, c.i), position(&s, c.j));
                    let (vi, vj) = (velocity(&s, c.i), velocity(&s, c.j));
                    let n = (pi - pj).normalize();
                    let dv = n * (vi - vj).dot(&n);
                    s.update(&[c.i, c.j], vec![line(pi, vi - dv), line(pj, vj + dv)])
                        .expect("valid");
                }
                Event::Object(_) | Event::Transition(_) => unreachable!("no table, no transitions"),
            }
        }
    }
}

/// `n` friction balls in `[0, 3]²` at up to 2 m/s on each axis, their friction from `friction`.
fn random_balls(rng: &mut Rng, n: usize, mut friction: impl FnMut(&mut Rng) -> f64) -> Vec<Ball> {
    (0..n)
        .map(|_| {
            let p = Vector2::new(rng.uniform(0.0, 3.0), rng.uniform(0.0, 3.0));
            let v = Vector2::new(rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0));
            Ball::new(p, v, friction(rng)).expect("valid")
        })
        .collect()
}

#[test]
fn friction_balls_from_balls_are_their_paths_from_t() {
    let mut rng = Rng(9);
    let balls = random_balls(&mut rng, 30, |rng| rng.uniform(0.0, 0.5));
    let radii = vec![0.1; balls.len()];
    let mut s = CollisionSchedule::<2>::from_balls(&balls, &radii, 2.5, ScheduleOptions::default())
        .expect("valid");
    assert_eq!(s.time(), 2.5);
    for (i, b) in balls.iter().enumerate() {
        let path = b.path().expect("valid");
        assert_eq!(s.path(i).position_at(2.5 + 1.0), path.position_at(1.0));
    }
    check(&mut s);
    let moved = [Ball::at_rest(Vector2::new(1.5, 1.5)).expect("valid")];
    s.update_balls(&[3], 3.0, &moved).expect("valid");
    check(&mut s);
    let err = s
        .update_balls(&[3], 2.0, &moved)
        .expect_err("before the current time");
    assert_eq!(
        err.to_string(),
        "t: must not be before the calendar's time 3, got 2"
    );
}

#[test]
fn friction_ball_updates_are_path_updates_and_refused_ones_change_nothing() {
    let mut rng = Rng(11);
    let balls = random_balls(&mut rng, 12, |rng| rng.uniform(0.0, 0.5));
    let radii = vec![0.2; balls.len()];
    let options = ScheduleOptions {
        walls: Some(Walls::new([-1.0, -1.0], [4.0, 4.0]).expect("a box")),
        ..Default::default()
    };
    let mut by_balls =
        CollisionSchedule::<2>::from_balls(&balls, &radii, 0.0, options).expect("valid");
    let mut by_paths = by_balls.clone();
    let overflows = Ball::new(Vector2::zeros(), Vector2::new(1e5, 0.0), 2e-300).expect("valid");
    let mut t = 0.0;
    for step in 0..40 {
        let i = rng.below(12) as usize;
        let j = (i + 1 + rng.below(11) as usize) % 12;
        let friction = if step % 3 == 0 { 0.0 } else { 0.3 };
        let new = random_balls(&mut rng, 2, |_| friction);
        // Refused: nothing changes, whichever check fails.
        let before = format!("{by_balls:?}");
        let refusals = [
            (vec![i, i], new.clone(), "indices[1]"),
            (vec![i, 12], new.clone(), "indices[1]"),
            (vec![i], new.clone(), "paths"),
            (
                vec![i, j],
                vec![new[0], overflows],
                "vel[1]: the ball's resting point",
            ),
        ];
        for (indices, balls, argument) in refusals {
            let err = by_balls
                .update_balls(&indices, t, &balls)
                .expect_err("refused");
            assert!(err.to_string().starts_with(argument), "{err}");
            assert_eq!(format!("{by_balls:?}"), before);
        }
        let paths = new
            .iter()
            .map(|b| FrictionPath::<2>::path_from(b, t).expect("valid"))
            .collect();
        by_balls.update_balls(&[i, j], t, &new).expect("valid");
        by_paths.update(&[i, j], paths).expect("valid");
        for k in 0..12 {
            assert_eq!(by_balls.path(k), by_paths.path(k));
        }
        assert_eq!(check(&mut by_balls), by_paths.next_event());
        t += rng.uniform(0.0, 0.5);
    }
}

#[test]
fn refused_updates_name_the_argument_and_the_index() {
    let rest =
        |t: f64, x: f64| Path::new(vec![Segment::at_rest(t, Vector2::new(x, 0.0))]).expect("valid");
    let mut s = CollisionSchedule::new(
        vec![rest(1.0, 0.0), rest(1.0, 2.0)],
        &[0.5, 0.5],
        ScheduleOptions::default(),
    )
    .expect("valid");
    let message = |s: &mut CollisionSchedule<2>, indices: &[usize], paths| {
        s.update(indices, paths).expect_err("refused").to_string()
    };
    assert_eq!(
        message(&mut s, &[0], vec![rest(0.5, 0.0)]),
        "start[0, 0]: must not be before the calendar's time 1, got 0.5"
    );
    assert_eq!(
        message(&mut s, &[0, 2], vec![rest(1.0, 0.0), rest(1.0, 0.0)]),
        "indices[1]: ball index must be in 0..2, got 2"
    );
    assert_eq!(
        message(
            &mut s,
            &[1, 0, 1],
            vec![rest(1.0, 0.0), rest(1.0, 0.0), rest(1.0, 0.0)]
        ),
        "indices[2]: ball 1 is given more than once"
    );
    assert_eq!(
        message(&mut s, &[0, 1], vec![rest(2.0, 0.0), rest(3.0, 0.0)]),
        "start[1, 0]: an update's paths must all start at one time, got 3 after 2"
    );
    let err = CollisionSchedule::new(vec![rest(0.0, 0.0)], &[0.0], ScheduleOptions::default())
        .expect_err("radius");
    assert_eq!(
        err.to_string(),
        "radius[0]: a ball's radius must be > 0, got 0"
    );
    // A ball as wide as its box, or wider: two walls at once wherever it is (a wall event at
    // t = 0 for ever, calling next_event after each update).
    for (r, refused) in [(0.49, false), (0.5, true), (0.75, true)] {
        let options = ScheduleOptions {
            walls: Some(Walls::new([0.0, 0.0], [1.0, 2.0]).expect("a box")),
            ..Default::default()
        };
        let at = |x: f64, y: f64| {
            Path::new(vec![Segment::at_rest(0.0, Vector2::new(x, y))]).expect("valid")
        };
        let made = CollisionSchedule::new(vec![at(0.5, 0.5), at(0.5, 1.5)], &[0.25, r], options);
        match (made, refused) {
            (Ok(_), false) => {}
            (Err(e), true) => assert_eq!(e.kind().code(), "wider_than_box", "{e}"),
            (made, _) => panic!("radius {r}: {made:?}"),
        }
    }
}

#[test]
fn grazing_passes_at_the_edge_of_the_boxes_are_brute_force() {
    // A ball passes one at rest (or stops just short of it, or beyond) at a distance within
    // a few ulps of the contact distance: the pair search decides these to its rounding,
    // and the boxes, only just overlapping or only just apart, must never prune a pair it
    // reports.
    let mut cases = 0;
    let mut contacts = 0;
    for r in [0.25f64, 0.3, 1.0 / 3.0] {
        let reach: f64 = 2.0 * r;
        for ulps in -6i64..=6 {
            for scale in [1.0, 1e3, 1e6] {
                let distance =
                    f64::from_bits((reach.to_bits() as i64 + ulps * scale as i64) as u64);
                for (v, mu) in [(1.0, 0.0), (1.0, 0.5), (0.7, 0.0), (2.0, 1.0)] {
                    for y_first in [true, false] {
                        let (pa, pb) = if y_first {
                            (Vector2::new(0.0, 0.0), Vector2::new(1.0, distance))
                        } else {
                            (Vector2::new(0.0, 0.0), Vector2::new(1.0 + distance, 0.0))
                        };
                        let moving = Ball::new(pa, Vector2::new(v, 0.0), mu).expect("valid");
                        let rest = Ball::at_rest(pb).expect("valid");
                        // A third ball far away so that the grid has more than one cell.
                        let far = Ball::at_rest(Vector2::new(50.0, 50.0)).expect("valid");
                        let balls = [moving, rest, far];
                        let options = ScheduleOptions::default();
                        let mut s =
                            CollisionSchedule::<2>::from_balls(&balls, &[r; 3], 0.0, options)
                                .expect("valid");
                        cases += 1;
                        contacts += usize::from(brute_collision(&s).expect("valid").is_some());
                        check(&mut s);
                    }
                }
            }
        }
    }
    // Both outcomes occur: the cases straddle the contact distance.
    assert!(contacts > 0 && contacts < cases, "{contacts} of {cases}");
}

/// A path from `p` at time `t` that moves along the last axis for ever (a *ray*): at rest,
/// at a constant speed, accelerating, or after a roll to rest at `p` across the rays.
fn ray<const D: usize>(rng: &mut Rng, t: f64, p: SVector<f64, D>) -> Path<D> {
    let along = |x: f64| SVector::<f64, D>::from_fn(|k, _| if k == D - 1 { x } else { 0.0 });
    let across = |x: f64| SVector::<f64, D>::from_fn(|k, _| if k == 0 { x } else { 0.0 });
    let v = along(rng.uniform(-2.0, 2.0));
    let segments = match rng.below(5) {
        0 => vec![Segment::at_rest(t, p)],
        1 => vec![Segment::new(t, p, v, along(rng.uniform(-0.5, 0.5)))],
        2 => {
            // Rolls to rest at `p` at speed `u` slowed at `mu`, then goes on along the ray.
            let (u, mu) = (rng.uniform(-1.0, 1.0), rng.uniform(0.25, 1.0));
            let tau = u.abs() / mu;
            let roll = Segment::new(
                t,
                p - across(0.5 * u * tau),
                across(u),
                across(-u.signum() * mu),
            );
            vec![roll, Segment::new(t + tau, p, v, SVector::zeros())]
        }
        _ => vec![Segment::new(t, p, v, SVector::zeros())],
    };
    Path::new(segments).expect("finite numbers")
}

/// Rays side by side, each pair of neighbours across them at the contact distance to within
/// a few ulps of the coordinates, passing each other at other speeds from far apart along
/// them: the pair search decides these grazes to its rounding, and the boxes, which run for
/// ever along the rays (from where each ball is, or turns back) and are bounded across them
/// by their margins alone, must never prune a pair it reports. Then the rays change (from
/// later and later times, so from farther along) and the events are resolved, brute force
/// throughout.
fn rays_at_the_edge<const D: usize>(
    seed: u64,
    n: usize,
    (x0, spread): (f64, f64),
    rounds: usize,
) -> usize {
    let mut rng = Rng(seed);
    let radii: Vec<f64> = (0..n).map(|_| rng.uniform(0.25, 0.5)).collect();
    // The rays from `x0` on: the gaps in ulps of the coordinates.
    let ulp = f64::from_bits(x0.to_bits() + 1) - x0;
    let mut x = x0;
    let mut starts = Vec::new();
    for k in 0..n {
        if k > 0 {
            let reach: f64 = radii[k - 1] + radii[k];
            let ulps = [0.0, 1.0, 2.0, 3.0, 6.0, 64.0][rng.below(6) as usize];
            x += reach + ulps * ulp * (rng.below(3) as f64 - 1.0);
        }
        let p = SVector::<f64, D>::from_fn(|i, _| match i {
            0 => x,
            i if i == D - 1 => rng.uniform(-spread, spread),
            _ => 0.0,
        });
        starts.push(p);
    }
    let paths = starts.iter().map(|&p| ray(&mut rng, 0.0, p)).collect();
    let mut s = CollisionSchedule::new(paths, &radii, ScheduleOptions::default()).expect("valid");
    let mut contacts = 0;
    for _ in 0..rounds {
        let now = s.time();
        let (indices, t) = match check(&mut s) {
            Some(Event::Collision(c)) => {
                contacts += 1;
                (vec![c.i, c.j], c.time)
            }
            _ => {
                let i = rng.below(n as u64) as usize;
                (vec![i], now + rng.uniform(0.0, spread))
            }
        };
        // From where each ball is (across the rays, where it rests).
        let paths = indices
            .iter()
            .map(|&i| ray(&mut rng, t, s.path(i).position_at(t)))
            .collect();
        s.update(&indices, paths).expect("a valid update");
    }
    contacts
}

#[test]
fn rays_passing_at_the_edge_of_their_boxes_are_brute_force() {
    let mut contacts = 0;
    for seed in 1..=6u64 {
        for (n, x0, spread) in [
            (12, 0.0, 4.0),
            (40, 0.0, 4.0),
            (12, 1e3, 1e3),
            (40, 1e6, 4.0),
            (40, 1e6, 1e6),
            (40, 3e9, 1e3),
        ] {
            contacts += rays_at_the_edge::<2>(seed, n, (x0, spread), 30);
            contacts += rays_at_the_edge::<3>(seed, n, (x0, spread), 15);
        }
    }
    // Grazes that touch occur (and the others miss by construction).
    assert!(contacts > 20, "{contacts}");
}

/// A ball thrown at another from far away, slowed along its line until it turns back for
/// ever just short of it or just beyond contact (within a few ulps of the turning point's
/// magnitudes), with balls around so that the grid has cells or not: its box runs to
/// infinity behind it, and its finite end, the turning point, is computed from magnitudes
/// far larger than the gap. Brute force throughout.
#[test]
fn a_ball_turning_back_at_the_edge_of_its_box_is_brute_force() {
    let mut cases = 0;
    let mut contacts = 0;
    for (speed, deceleration) in [(1e3, 1.0), (3.0, 1e-3), (1e4, 7.0)] {
        // From y = 0 at `speed` downwards, turning at y = −speed²/(2·deceleration).
        let turn: f64 = -0.5 * speed * (speed / deceleration);
        let ulp = f64::from_bits(turn.abs().to_bits() + 1) - turn.abs();
        for ulps in [-64.0, -8.0, -2.0, -1.0, 0.0, 1.0, 2.0, 8.0, 64.0] {
            for others in [0usize, 20] {
                let r = 0.25;
                let target = turn - 2.0 * r + ulps * ulp;
                let mut paths = vec![
                    Path::new(vec![Segment::new(
                        0.0,
                        Vector2::new(0.0, 0.0),
                        Vector2::new(0.0, -speed),
                        Vector2::new(0.0, deceleration),
                    )])
                    .expect("valid"),
                    Path::new(vec![Segment::at_rest(0.0, Vector2::new(0.0, target))])
                        .expect("valid"),
                ];
                // Balls at rest far to the side, across the whole run.
                for k in 0..others {
                    let y = turn * k as f64 / others as f64;
                    let p = Vector2::new(10.0 + (k % 3) as f64, y);
                    paths.push(Path::new(vec![Segment::at_rest(0.0, p)]).expect("valid"));
                }
                let n = paths.len();
                let mut s = CollisionSchedule::new(paths, &vec![r; n], ScheduleOptions::default())
                    .expect("valid");
                cases += 1;
                contacts += usize::from(check(&mut s).is_some());
            }
        }
    }
    assert!(contacts > 0 && contacts < cases, "{contacts} of {cases}");
}

/// 400 balls moving side by side in open space for ever, with no horizon: each box is the
/// whole line of its ray and a margin across it, listed in the few grid cells of its column
/// (an unbounded margin on every axis listed each ball in every cell: 400 × 800 entries, and
/// the first `next_collision` searched every pair). No collision, as brute force says.
#[test]
fn parallel_balls_in_open_space_are_listed_in_a_few_cells() {
    let n = 400;
    let paths = (0..n)
        .map(|k| {
            let p = Vector2::new(3.0 * k as f64, 0.0);
            Path::new(vec![Segment::new(
                0.0,
                p,
                Vector2::new(0.0, 1.0),
                Vector2::zeros(),
            )])
        })
        .collect::<Result<Vec<_>, _>>()
        .expect("valid");
    let mut s =
        CollisionSchedule::new(paths, &vec![0.5; n], ScheduleOptions::default()).expect("valid");
    assert_eq!(s.next_collision(), None);
    assert_eq!(brute_collision(&s).expect("valid"), None);
    let grid = s.heap_bytes().grid as f64 / n as f64;
    assert!(grid < 100.0, "{grid} grid bytes per ball");
}

/// Kinetic energy and momentum of a state.
fn energy_momentum(balls: &[Ball], masses: &[f64]) -> (f64, Vector2<f64>) {
    let mut e = 0.0;
    let mut p = Vector2::zeros();
    for (b, &m) in balls.iter().zip(masses) {
        e += 0.5 * m * b.velocity().norm_squared();
        p += b.velocity() * m;
    }
    (e, p)
}

/// A random scene in the unit box: balls on a grid, normal-ish velocities.
fn box_scene(seed: u64, side: usize, friction: f64) -> (Vec<Ball>, Vec<f64>, Walls<2>) {
    let mut rng = Rng(seed);
    let n = side * side;
    let r = 0.25 / side as f64;
    let balls = (0..n)
        .map(|k| {
            let p = Vector2::new((k % side) as f64 + 0.5, (k / side) as f64 + 0.5) / side as f64;
            let v = Vector2::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
            Ball::new(p, v, friction * rng.uniform(0.5, 1.5)).expect("valid")
        })
        .collect();
    let walls = Walls::new([0.0, 0.0], [1.0, 1.0]).expect("a box");
    (balls, vec![r; n], walls)
}

#[test]
fn elastic_frictionless_balls_keep_their_energy_and_never_overlap() {
    use ballcollide::schedule::{SimulationOptions, simulate};
    for seed in [1u64, 2] {
        let (balls, radii, walls) = box_scene(seed, 6, 0.0);
        let n = balls.len();
        let masses: Vec<f64> = (0..n).map(|i| 1.0 + (i % 3) as f64).collect();
        let options = SimulationOptions {
            mass: masses.clone(),
            max_events: Some(2000),
            ..Default::default()
        };
        let run = simulate(&balls, &radii, walls, &options).expect("valid");
        assert_eq!(run.events.len(), 2000);
        let (e0, _) = energy_momentum(&balls, &masses);
        let (e1, _) = energy_momentum(&run.balls, &masses);
        assert!((e1 - e0).abs() <= 1e-12 * e0, "{e0} → {e1}");
        // No overlap at the end beyond rounding, and every ball inside the box.
        for i in 0..n {
            let p = run.balls[i].position();
            assert!(p.x >= radii[i] * (1.0 - 1e-9) && p.x <= 1.0 - radii[i] * (1.0 - 1e-9));
            for j in i + 1..n {
                let d = (p - run.balls[j].position()).norm();
                assert!(d >= (radii[i] + radii[j]) * (1.0 - 1e-9), "{i} {j} {d}");
            }
        }
    }
}

#[test]
fn momentum_is_kept_at_collisions_and_energy_never_rises() {
    // The state after k events against the state after k − 1: a collision keeps the total
    // momentum of frictionless balls (their velocities are constant between events); with
    // friction or restitution below 1 the energy never rises; no overlap at any event.
    use ballcollide::schedule::{SimulationOptions, simulate};
    for (friction, e) in [(0.0, 1.0), (0.0, 0.7), (0.4, 1.0), (0.4, 0.5)] {
        let (balls, radii, walls) = box_scene(5, 4, friction);
        let n = balls.len();
        let masses: Vec<f64> = (0..n).map(|i| 0.5 + (i % 4) as f64).collect();
        let mut previous: Option<(f64, Vector2<f64>)> = None;
        let mut collisions = 0;
        for k in 1..=60 {
            let options = SimulationOptions {
                mass: masses.clone(),
                restitution: e,
                max_events: Some(k),
                ..Default::default()
            };
            let run = simulate(&balls, &radii, walls, &options).expect("valid");
            if run.events.len() < k {
                break; // everything has stopped
            }
            let (energy, momentum) = energy_momentum(&run.balls, &masses);
            if let Some((e_before, p_before)) = previous {
                assert!(
                    energy <= e_before * (1.0 + 1e-12),
                    "energy rose at event {k}"
                );
                if e == 1.0 && friction == 0.0 {
                    assert!((energy - e_before).abs() <= 1e-12 * e_before);
                }
                if run.events[k - 1].j.is_some() && friction == 0.0 {
                    collisions += 1;
                    assert!((momentum - p_before).norm() <= 1e-12 * (1.0 + p_before.norm()));
                }
            }
            for i in 0..n {
                for j in i + 1..n {
                    let d = (run.balls[i].position() - run.balls[j].position()).norm();
                    assert!(
                        d >= (radii[i] + radii[j]) * (1.0 - 1e-9),
                        "overlap at event {k}"
                    );
                }
            }
            previous = Some((energy, momentum));
        }
        if friction == 0.0 {
            assert!(collisions > 5);
        }
    }
}

/// An update of `k` balls of a calendar of `n` friction balls on a grid in a box, each given
/// a new velocity at `t = 0.25`.
fn grid_calendar(n: usize) -> (CollisionSchedule<2>, Vec<Ball>) {
    let side = (n as f64).sqrt().ceil() as usize;
    let mut rng = Rng(7);
    let ball = |k: usize, rng: &mut Rng| {
        let p = Vector2::new((k % side) as f64 + 0.5, (k / side) as f64 + 0.5) / side as f64;
        let v = Vector2::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
        Ball::new(p, v, 0.5).expect("a ball")
    };
    let balls: Vec<Ball> = (0..n).map(|k| ball(k, &mut rng)).collect();
    let options = ScheduleOptions {
        walls: Some(Walls::new([0.0, 0.0], [1.0, 1.0]).expect("a box")),
        ..Default::default()
    };
    let radius = 0.3 / side as f64;
    let s = CollisionSchedule::from_balls(&balls, &vec![radius; n], 0.0, options).expect("valid");
    let later: Vec<Ball> = (0..n)
        .map(|k| {
            let p = balls[k].position_at(0.25);
            let v = Vector2::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
            Ball::new(p, v, 0.5).expect("a ball")
        })
        .collect();
    (s, later)
}

#[test]
fn an_interrupted_update_leaves_the_calendar_as_if_its_first_chunks_alone_were_updated() {
    // Issue 39: Ctrl-C stops a long call within a fraction of a second. An update of 10⁶
    // balls took 5 s with no look at the flag; now it looks every UPDATE_CHUNK balls and,
    // stopped, leaves the chunks done in: the calendar is the one updated with those alone.
    use ballcollide::InputErrorKind;
    use ballcollide::interrupt::interruptible;
    use ballcollide::schedule::UPDATE_CHUNK;
    use std::sync::Arc;
    use std::sync::atomic::AtomicBool;
    let n = 2 * UPDATE_CHUNK + 100;
    let indices: Vec<usize> = (0..n).rev().collect();
    let (mut stopped, later) = grid_calendar(n);
    let new: Vec<Ball> = indices.iter().map(|&i| later[i]).collect();
    let stop = Arc::new(AtomicBool::new(true));
    let result = interruptible(stop, || stopped.update_balls(&indices, 0.25, &new));
    assert_eq!(
        result.map_err(|e| e.kind()),
        Err(InputErrorKind::Interrupted)
    );
    let (mut first_chunk, _) = grid_calendar(n);
    first_chunk
        .update_balls(&indices[..UPDATE_CHUNK], 0.25, &new[..UPDATE_CHUNK])
        .expect("valid");
    assert_eq!(stopped.time(), 0.25);
    // The same events, each resolved on both (its balls stopped where they are).
    for _ in 0..40 {
        let event = stopped.next_event();
        assert_eq!(event, first_chunk.next_event());
        let Some(event) = event else { break };
        let t = event.time();
        let moved: Vec<usize> = match event {
            Event::Collision(c) => vec![c.i, c.j],
            Event::Wall(w) => vec![w.ball],
            _ => unreachable!("no table, no transitions"),
        };
        let at_rest: Vec<Ball> = moved
            .iter()
            .map(|&i| Ball::at_rest(stopped.path(i).position_at(t)).expect("a ball"))
            .collect();
        stopped.update_balls(&moved, t, &at_rest).expect("valid");
        first_chunk
            .update_balls(&moved, t, &at_rest)
            .expect("valid");
    }
    // Uninterrupted, the whole update goes in, in chunks: the calendar is the one built from
    // the new balls.
    let (mut whole, _) = grid_calendar(n);
    whole.update_balls(&indices, 0.25, &new).expect("valid");
    let options = ScheduleOptions {
        walls: Some(Walls::new([0.0, 0.0], [1.0, 1.0]).expect("a box")),
        ..Default::default()
    };
    let radii = vec![0.3 / (n as f64).sqrt().ceil(); n];
    let mut built = CollisionSchedule::from_balls(&later, &radii, 0.25, options).expect("valid");
    for _ in 0..40 {
        let event = whole.next_event();
        assert_eq!(event, built.next_event());
        let Some(event) = event else { break };
        let t = event.time();
        let moved: Vec<usize> = match event {
            Event::Collision(c) => vec![c.i, c.j],
            Event::Wall(w) => vec![w.ball],
            _ => unreachable!("no table, no transitions"),
        };
        let at_rest: Vec<Ball> = moved
            .iter()
            .map(|&i| Ball::at_rest(whole.path(i).position_at(t)).expect("a ball"))
            .collect();
        whole.update_balls(&moved, t, &at_rest).expect("valid");
        built.update_balls(&moved, t, &at_rest).expect("valid");
    }
}
