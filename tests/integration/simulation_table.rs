//! `simulate` on a table: balls reflect off segments, circles and planes with the table's
//! restitution, and targets capture them. Checked on breaks on a pool table
//! ([`PoolTable`]): no ball overlaps another, a wall or an object beyond `1e-9` of its
//! radius at any state of the run (the run cut at many times: a horizon only cuts), captured
//! balls never move again and take part in no later event; elastic frictionless balls on a
//! table without pockets keep their energy.

use ballcollide::Ball;
use ballcollide::InputErrorKind;
use ballcollide::geometry::{
    Circle, LineSegment, ObjectKind, Plane, PoolTable, SegmentSide, Table, Target,
};
use ballcollide::schedule::{Simulation, SimulationOptions, Walls, simulate};
use nalgebra::Vector2;

use crate::support::rng;
use crate::support::simulation_invariants;
use rng::Rng;
use simulation_invariants::{SimulationCase, TableCase, table_simulation};

/// A pool ball's radius (2¼ in).
const R: f64 = 0.028575;

/// Fifteen balls racked at the foot spot (a hair apart) and the cue ball at the head spot,
/// shot at `speed` towards the rack, `aim` off its axis.
fn rack(spec: &PoolTable, speed: f64, aim: f64, friction: f64) -> Vec<Ball> {
    let gap = 1.0 + 1e-6;
    let apex = Vector2::new(spec.width / 2.0, 0.75 * spec.length);
    let mut balls = vec![
        Ball::new(
            Vector2::new(spec.width / 2.0, spec.length / 4.0),
            Vector2::new(aim.sin(), aim.cos()) * speed,
            friction,
        )
        .expect("a ball"),
    ];
    for row in 0..5 {
        for k in 0..=row {
            let x = apex.x + (2.0 * k as f64 - row as f64) * R * gap;
            let y = apex.y + row as f64 * 3f64.sqrt() * R * gap;
            balls.push(Ball::new(Vector2::new(x, y), Vector2::zeros(), friction).expect("a ball"));
        }
    }
    balls
}

/// The box around the table and its pockets.
fn walls(spec: &PoolTable) -> Walls<2> {
    let margin = 0.25;
    Walls::new(
        [-margin, -margin],
        [spec.width + margin, spec.length + margin],
    )
    .expect("a box")
}

/// How deep ball `i` at `x` overlaps the table's segments, circles and planes, relative to
/// its radius (negative: clear), written out here on its own.
fn object_overlap(table: &Table<2>, x: Vector2<f64>, r: f64) -> (f64, String) {
    let mut worst = (f64::NEG_INFINITY, String::new());
    let mut see = |depth: f64, what: String| {
        if depth > worst.0 {
            worst = (depth, what);
        }
    };
    for (k, s) in table.segments.iter().enumerate() {
        let (e, w) = (s.q() - s.p(), x - s.p());
        let u = w.dot(&e) / e.norm_squared();
        let d = (e.x * w.y - e.y * w.x) / e.norm();
        let counts = match s.side() {
            SegmentSide::Both => true,
            SegmentSide::Left => d > 0.0,
            SegmentSide::Right => d < 0.0,
        };
        if (0.0..=1.0).contains(&u) && counts {
            see((r - d.abs()) / r, format!("segment {k}"));
        }
    }
    for (k, c) in table.circles.iter().enumerate() {
        see(
            (r + c.rho() - (x - c.centre()).norm()) / r,
            format!("circle {k}"),
        );
    }
    for (k, p) in table.planes.iter().enumerate() {
        let h = p.normal().dot(&(x - p.point())) / p.normal().norm();
        see((r - h) / r, format!("plane {k}"));
    }
    worst
}

/// The deepest overlap of the balls in play (not `captured`) at a state: with each other,
/// the walls and the table's objects, relative to the radius.
fn deepest(
    balls: &[Ball],
    captured: &[Option<usize>],
    table: &Table<2>,
    walls: &Walls<2>,
) -> (f64, String) {
    let mut worst = (f64::NEG_INFINITY, String::new());
    let in_play: Vec<usize> = (0..balls.len())
        .filter(|&i| captured[i].is_none())
        .collect();
    for &i in &in_play {
        let x = balls[i].position();
        let (depth, what) = object_overlap(table, x, R);
        if depth > worst.0 {
            worst = (depth, format!("ball {i} and {what}"));
        }
        for axis in 0..2 {
            let room = (x[axis] - walls.lo()[axis]).min(walls.hi()[axis] - x[axis]);
            if (R - room) / R > worst.0 {
                worst = ((R - room) / R, format!("ball {i} and a wall"));
            }
        }
        for &j in in_play.iter().filter(|&&j| j > i) {
            let d = (x - balls[j].position()).norm();
            if (2.0 * R - d) / (2.0 * R) > worst.0 {
                worst = ((2.0 * R - d) / (2.0 * R), format!("balls {i} and {j}"));
            }
        }
    }
    worst
}

fn options(table: &Table<2>, friction_free: bool, t_end: f64) -> SimulationOptions {
    SimulationOptions {
        restitution: if friction_free { 1.0 } else { 0.95 },
        table_restitution: if friction_free { 1.0 } else { 0.8 },
        t_end,
        max_events: Some(200_000),
        table: table.clone(),
        ..Default::default()
    }
}

fn run(balls: &[Ball], spec: &PoolTable, options: &SimulationOptions) -> Simulation {
    simulate(balls, &[R; 16], walls(spec), options).expect("a valid break")
}

#[test]
fn breaks_never_overlap_and_captured_balls_stay_where_they_fell() {
    let spec = PoolTable::default();
    let table = spec.table().expect("a table");
    let mut rng = Rng(11);
    let (mut captures, mut object_events) = (0, 0);
    for shot in 0..6 {
        let speed = rng.uniform(4.0, 9.0);
        let aim = rng.uniform(-0.02, 0.02);
        let balls = rack(&spec, speed, aim, 0.4);
        let full = run(&balls, &spec, &options(&table, false, f64::INFINITY));
        assert!(
            full.events.len() < 200_000,
            "shot {shot} did not come to rest"
        );
        // Events in order; a captured ball takes part in nothing after its capture.
        let mut captured_at = [f64::INFINITY; 16];
        let mut previous = 0.0;
        for e in &full.events {
            assert!(e.time >= previous, "shot {shot}: events out of order");
            previous = e.time;
            for b in [Some(e.i), e.j].into_iter().flatten() {
                assert!(
                    e.time <= captured_at[b],
                    "shot {shot}: ball {b} after its capture"
                );
            }
            match e.object {
                Some((ObjectKind::Target, k)) => {
                    captured_at[e.i] = e.time;
                    assert_eq!(full.captured[e.i], Some(k));
                    captures += 1;
                }
                Some(_) => object_events += 1,
                None => {}
            }
        }
        for (i, c) in full.captured.iter().enumerate() {
            assert_eq!(
                c.is_some(),
                captured_at[i].is_finite(),
                "shot {shot}, ball {i}"
            );
        }
        // The state at many cuts of the run: no overlap; captured balls at rest where the
        // whole run leaves them.
        let cuts = 12;
        for k in 1..=cuts {
            let t = full.end * k as f64 / cuts as f64;
            let part = run(&balls, &spec, &options(&table, false, t));
            let (depth, what) = deepest(&part.balls, &part.captured, &table, &walls(&spec));
            assert!(
                depth <= 1e-9,
                "shot {shot} at {t}: {what} overlap by {depth:e}"
            );
            for i in 0..16 {
                if let Some(target) = part.captured[i] {
                    assert_eq!(full.captured[i], Some(target));
                    assert_eq!(part.balls[i].position(), full.balls[i].position());
                    assert_eq!(part.balls[i].velocity(), Vector2::zeros());
                }
            }
        }
    }
    // The runs met the table: captures and rebounds off rails, jaws or tips.
    assert!(
        captures >= 3 && object_events >= 20,
        "{captures} captures, {object_events} rebounds"
    );
}

#[test]
fn elastic_frictionless_balls_on_a_table_without_pockets_keep_their_energy() {
    let spec = PoolTable::default();
    let mut table = spec.table().expect("a table");
    table.targets.clear();
    let balls = rack(&spec, 6.0, 0.013, 0.0);
    let energy = |balls: &[Ball]| {
        balls
            .iter()
            .map(|b| b.velocity().norm_squared())
            .sum::<f64>()
    };
    let full = run(&balls, &spec, &options(&table, true, 4.0));
    let rebounds = full.events.iter().filter(|e| e.object.is_some()).count();
    assert!(rebounds >= 10, "{rebounds} rebounds off the table");
    let (before, after) = (energy(&balls), energy(&full.balls));
    assert!(
        ((after - before) / before).abs() < 1e-9,
        "energy {before} → {after}"
    );
}

#[test]
fn a_rebound_off_an_angled_cushion_keeps_the_tangent_and_scales_the_normal() {
    // A cushion along y = x, played from below-right; a ball comes straight up at 1 m/s.
    let cushion = LineSegment::new(
        Vector2::new(0.0, 0.0),
        Vector2::new(2.0, 2.0),
        SegmentSide::Right,
    )
    .expect("a segment");
    let table = Table {
        segments: vec![cushion],
        ..Default::default()
    };
    let ball = Ball::new(Vector2::new(1.5, 0.5), Vector2::new(0.0, 1.0), 0.0).expect("a ball");
    let options = SimulationOptions {
        table,
        table_restitution: 0.5,
        max_events: Some(1),
        ..Default::default()
    };
    let walls = Walls::new([-5.0, -5.0], [5.0, 5.0]).expect("a box");
    let run = simulate(&[ball], &[0.1], walls, &options).expect("a run");
    let e = run.events[0];
    assert_eq!(e.object, Some((ObjectKind::Segment, 0)));
    // The normal (1, −1)/√2 component −1/√2 becomes +½/√2; the tangent (1, 1)/√2 one stays.
    let v = run.balls[0].velocity();
    let n = Vector2::new(1.0, -1.0) / 2f64.sqrt();
    let t = Vector2::new(1.0, 1.0) / 2f64.sqrt();
    assert!((v.dot(&n) - 0.5 / 2f64.sqrt()).abs() < 1e-15, "{v}");
    assert!((v.dot(&t) - 1.0 / 2f64.sqrt()).abs() < 1e-15, "{v}");
}

#[test]
fn a_ball_that_starts_on_an_object_or_in_a_pocket_is_refused() {
    let spec = PoolTable::default();
    let table = spec.table().expect("a table");
    let options = SimulationOptions {
        table: table.clone(),
        t_end: 1.0,
        ..Default::default()
    };
    let walls = walls(&spec);
    // Across the bottom rail.
    let on_rail = Ball::new(Vector2::new(0.5, R / 2.0), Vector2::zeros(), 0.0).expect("a ball");
    let fine = Ball::new(Vector2::new(0.5, 0.5), Vector2::zeros(), 0.0).expect("a ball");
    let err = simulate(&[fine, on_rail], &[R; 2], walls, &options).expect_err("refused");
    assert!(matches!(
        err.kind(),
        InputErrorKind::OverlapsObject {
            kind: ObjectKind::Segment,
            index: 0,
            ..
        }
    ));
    assert_eq!(err.index(), Some(1));
    assert_eq!(err.kind().code(), "overlaps_object");
    // In the corner pocket at (0, 0).
    let pocket = table.targets[0].centre();
    let fallen = Ball::new(pocket, Vector2::zeros(), 0.0).expect("a ball");
    let err = simulate(&[fallen], &[R], walls, &options).expect_err("refused");
    assert!(matches!(
        err.kind(),
        InputErrorKind::OverlapsObject {
            kind: ObjectKind::Target,
            index: 0,
            ..
        }
    ));
    // Touching is fine.
    let touching = Ball::new(Vector2::new(0.5, R), Vector2::zeros(), 0.0).expect("a ball");
    assert!(simulate(&[touching], &[R], walls, &options).is_ok());
}

/// A random table in the square `[0, 2]²`: up to 3 segments (capped by circles of radius 0 at
/// their ends; sides both, left or right), 2 circles, 2 targets and a plane, and up to 6
/// balls off them, as the fuzz target `simulate_table` makes them.
fn random_table_case(rng: &mut Rng) -> TableCase {
    let point = |rng: &mut Rng| Vector2::new(rng.uniform(0.0, 2.0), rng.uniform(0.0, 2.0));
    let mut table = Table::<2>::default();
    for _ in 0..rng.below(4) {
        let (p, q) = (point(rng), point(rng));
        let side =
            [SegmentSide::Both, SegmentSide::Left, SegmentSide::Right][rng.below(3) as usize];
        table
            .segments
            .push(LineSegment::new(p, q, side).expect("a segment"));
        for end in [p, q] {
            table.circles.push(Circle::new(end, 0.0).expect("a cap"));
        }
    }
    for _ in 0..rng.below(3) {
        let rho = if rng.below(4) == 0 {
            0.0
        } else {
            rng.uniform(0.0, 0.25)
        };
        table
            .circles
            .push(Circle::new(point(rng), rho).expect("a circle"));
    }
    for _ in 0..rng.below(3) {
        let rho = rng.uniform(0.01, 0.25);
        table
            .targets
            .push(Target::new(point(rng), rho).expect("a target"));
    }
    if rng.below(3) == 0 {
        let normal = Vector2::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
        table
            .planes
            .push(Plane::new(point(rng) * 0.25, normal).expect("a plane"));
    }
    let n = 1 + rng.below(6) as usize;
    let balls: Vec<_> = (0..n)
        .map(|_| {
            let r = rng.uniform(1.0 / 64.0, 0.2);
            let at = [rng.uniform(0.0, 1.0), rng.uniform(0.0, 1.0)];
            let v = [rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0)];
            (at, r, v, [0.0, 0.3, 2.0][rng.below(3) as usize])
        })
        .collect();
    let restitution = [0.0, 0.5, 1.0][rng.below(3) as usize];
    let case = SimulationCase::in_square(2.0, &balls, vec![1.0], restitution, 4.0).clear_of(&table);
    let table_restitution = [0.0, 0.7, 1.0][rng.below(3) as usize];
    TableCase {
        case,
        table,
        table_restitution,
    }
}

#[test]
fn random_tables_keep_every_invariant() {
    // The fuzz target `simulate_table`'s invariants (tests/support/simulation_invariants.rs):
    // no overlap with a ball, a wall or an object at any cut, captured balls never move
    // again, energy never grows, a cut run logs the same events.
    let mut rng = Rng(36);
    let (mut ran, mut events, mut object_events) = (0, 0, 0);
    for _ in 0..150 {
        let tc = random_table_case(&mut rng);
        if let Err(e) = table_simulation(&tc) {
            panic!("{e}");
        }
        let c = &tc.case;
        let balls: Vec<Ball> = c
            .balls
            .iter()
            .map(|b| Ball::new(Vector2::new(b[0], b[1]), Vector2::new(b[2], b[3]), b[4]))
            .collect::<Result<_, _>>()
            .expect("balls");
        let options = SimulationOptions {
            restitution: c.restitution,
            t_end: c.t_end,
            max_events: Some(1000),
            table: tc.table.clone(),
            table_restitution: tc.table_restitution,
            ..Default::default()
        };
        let walls = Walls::new(c.lo, c.hi).expect("a box");
        if let Ok(run) = simulate(&balls, &c.radii, walls, &options) {
            ran += 1;
            events += run.events.len();
            object_events += run.events.iter().filter(|e| e.object.is_some()).count();
        }
    }
    assert!(
        ran > 100 && events > 2000 && object_events > 300,
        "{ran} runs, {events} events, {object_events} with objects"
    );
}
