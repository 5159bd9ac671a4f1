//! `ballcollide::billiards` against pooltool 0.6.0's own functions.
//!
//! `tests/data/billiards_cases.txt` is written by `tools/billiards_reference.py`, which calls
//! pooltool's functions (never this library) on seeded random balls: 2,000 cases of each kind
//! (22,000: the ball, two balls, a ball against a straight or a rounded cushion, a ball
//! dropping into a pocket, and the cue striking a ball).
//! Each output is compared with ours two ways: equal as numbers (pooltool's arithmetic
//! reproduced), and the difference against the scale of the terms it is made of (the position,
//! the speeds and the spins that enter it, over the time it covers). The bar:
//!
//! - equal, every case: the slip (`rel_velocity`), the three transition times, the next
//!   transition and its delay, the spin decay, the roll (`_evolve_roll_state`), a ball in a
//!   pocket (`CanonicalBallPocket`, its whole state), the motion
//!   state `evolve` ends in (but at a transition's time to a few roundings) and the kinds of a
//!   lone ball's transitions, and for two balls at contact `make_kiss`'s positions and the
//!   Alciatore friction at them;
//! - within `1e-12` of the scale: the slide (pooltool turns into the velocity's frame and back,
//!   with `arctan2`, `cos`, `sin` and BLAS; we stay in the table's), `evolve` through its
//!   chain, a lone ball's transition times and states against [`ball_path`]'s,
//!   [`ball_path`]'s positions and velocities against pooltool's evolution, and the states
//!   after a ball–ball collision (`FrictionalInelastic.resolve`, in the line of centres' frame
//!   turned by its angle there, built from its unit vector here), and the states after a
//!   ball meets a cushion (`StrongeCompliantLinear` and `StrongeCompliantCircular`, in each of
//!   the three Stronge regimes; the two regimes with a root take TOMS748's steps as scipy's);
//!   and a ball struck by the cue (`InstantaneousPoint`, its velocity and spin, and the squirt
//!   angle: pooltool turns vectors by a matrix product in BLAS, and its `arctan2` is NumPy's).
//!
//! Run with `--nocapture` for the counts and the worst differences.

use crate::support::fields;

use ballcollide::billiards::{
    AlciatoreFriction, BallBallResolver, BallCircularCushionResolver, BallLinearCushionResolver,
    BallParams, BallPocketResolver, BallState, CanonicalBallPocket, CircularCushion, Cue, CueSpecs,
    FrictionalInelastic, InstantaneousPoint, LinearCushion, MotionState, Pocket, StickBallResolver,
    StrongeCompliantCircular, StrongeCompliantLinear, TransitionKind, ball_path, evolve,
    evolve_roll, evolve_slide, evolve_spin, kiss_circular_cushion, kiss_linear_cushion, make_kiss,
    next_transition, roll_time, slide_time, slip_velocity, spin_time, squirt_angle,
};
use fields::Fields;
use nalgebra::{Vector2, Vector3};

const DATA: &str = include_str!("../data/billiards_cases.txt");

/// The largest difference allowed, relative to the scale of the terms.
const TOLERANCE: f64 = 1e-12;

/// What one kind of output did over the table.
#[derive(Default)]
struct Tally {
    outputs: usize,
    equal: usize,
    /// The largest |ours − pooltool's| / scale, and the line it came from.
    worst: (f64, usize),
}

impl Tally {
    /// Counts one output; returns whether it is within the tolerance.
    fn add(&mut self, ours: f64, theirs: f64, scale: f64, line: usize) -> bool {
        self.outputs += 1;
        let same = ours == theirs || (ours.is_nan() && theirs.is_nan());
        if same {
            self.equal += 1;
            return true;
        }
        // A NaN difference counts as the worst, and fails.
        let error = (ours - theirs).abs() / scale;
        let error = if error.is_nan() { f64::INFINITY } else { error };
        if error > self.worst.0 {
            self.worst = (error, line);
        }
        error <= TOLERANCE
    }

    fn report(&self, name: &str) {
        println!(
            "{name:<28} {:>6} outputs, {:>6} equal, worst {:.2e} of the scale (line {})",
            self.outputs, self.equal, self.worst.0, self.worst.1
        );
    }
}

/// One line: its kind, category, and the numbers before and after the `:`.
struct Case<'a> {
    line: usize,
    kind: &'a str,
    category: &'a str,
    inputs: Vec<&'a str>,
    outputs: Vec<&'a str>,
}

fn cases() -> impl Iterator<Item = Case<'static>> {
    DATA.lines().enumerate().filter_map(|(k, text)| {
        if text.starts_with('#') || text.trim().is_empty() {
            return None;
        }
        let (head, tail) = text
            .split_once(" : ")
            .expect("a ':' between inputs and outputs");
        let mut words = head.split_whitespace();
        let kind = words.next().expect("a kind");
        let category = words.next().expect("a category");
        Some(Case {
            line: k + 1,
            kind,
            category,
            inputs: words.collect(),
            outputs: tail.split_whitespace().collect(),
        })
    })
}

fn fields<'a>(line: usize, words: &'a [&'a str]) -> Fields<'a> {
    Fields {
        line,
        rest: words.iter(),
    }
}

fn read_params(f: &mut Fields<'_>) -> BallParams {
    BallParams {
        mass: f.number(),
        radius: f.number(),
        u_s: f.number(),
        u_r: f.number(),
        u_sp_proportionality: f.number(),
        g: f.number(),
        ..BallParams::default()
    }
}

fn read_motion(f: &mut Fields<'_>) -> MotionState {
    let code = f.number();
    MotionState::from_code(code as i64).unwrap_or_else(|| panic!("line {}: motion {code}", f.line))
}

/// The position, velocity and angular velocity, as `rx ry vx vy wx wy wz`.
fn read_vectors(f: &mut Fields<'_>, motion: MotionState) -> BallState {
    let position = f.vector::<2>();
    let velocity = f.vector::<2>();
    let angular_velocity = f.vector::<3>();
    BallState::new(position, velocity, angular_velocity, motion)
}

fn read_state(f: &mut Fields<'_>) -> BallState {
    let motion = read_motion(f);
    read_vectors(f, motion)
}

fn transition_name(name: &str, line: usize) -> TransitionKind {
    match name {
        "sliding_rolling" => TransitionKind::SlidingRolling,
        "rolling_spinning" => TransitionKind::RollingSpinning,
        "rolling_stationary" => TransitionKind::RollingStationary,
        "spinning_stationary" => TransitionKind::SpinningStationary,
        other => panic!("line {line}: transition {other}"),
    }
}

/// The scales of a state's outputs `t` after `state`: positions, velocities, spins. Speeds are
/// bounded by `|v| + |u|` (a slide changes `v` by at most `2|u|/7`, a roll only slows it),
/// spins by `|ω| + (|v| + |u|)/R`; the centre moves for at most the time until it stops.
struct Scales {
    position: f64,
    velocity: f64,
    spin: f64,
}

fn scales(state: &BallState, params: &BallParams, t: f64, position_out: Vector2<f64>) -> Scales {
    let speed = state.velocity.norm() + slip_velocity(state, params.radius).norm();
    let moving = ball_path(state, params, 0.0)
        .map(|m| m.path().segments().last().map_or(0.0, |s| s.start))
        .unwrap_or(f64::INFINITY);
    let magnitude = state.position.amax().max(position_out.amax());
    Scales {
        position: magnitude + speed * t.min(moving),
        velocity: speed.max(f64::MIN_POSITIVE),
        spin: (state.angular_velocity.amax() + speed / params.radius).max(f64::MIN_POSITIVE),
    }
}

/// How far `t` is from the nearest time at which `evolve` passes from one motion state to the
/// next (the sums of the stages' times, as `evolve` chains them).
fn boundary_distance(state: &BallState, params: &BallParams, t: f64) -> f64 {
    let motion = ball_path(state, params, 0.0).expect("a valid ball");
    let starts = motion.path().segments().iter().skip(1).map(|s| s.start);
    starts.map(|s| (s - t).abs()).fold(f64::INFINITY, f64::min)
}

/// Compares `rx ry vx vy wx wy wz` read from `f` with `ours`; false if any is out of bounds.
fn compare_state(f: &mut Fields<'_>, ours: &BallState, scales: &Scales, tally: &mut Tally) -> bool {
    let line = f.line;
    let theirs = read_vectors(f, ours.motion);
    let mut ok = true;
    for k in 0..2 {
        ok &= tally.add(ours.position[k], theirs.position[k], scales.position, line);
        ok &= tally.add(ours.velocity[k], theirs.velocity[k], scales.velocity, line);
    }
    for k in 0..3 {
        let (a, b) = (ours.angular_velocity[k], theirs.angular_velocity[k]);
        ok &= tally.add(a, b, scales.spin, line);
    }
    ok
}

#[test]
fn the_table_holds_every_kind() {
    let mut counts = std::collections::BTreeMap::new();
    for case in cases() {
        *counts.entry(case.kind).or_insert(0) += 1;
    }
    let kinds: Vec<_> = counts.keys().copied().collect();
    assert_eq!(
        kinds,
        [
            "ball_ball",
            "circular_cushion",
            "evolve",
            "linear_cushion",
            "path",
            "pocket",
            "roll",
            "slide",
            "spin",
            "stick",
            "times"
        ]
    );
    assert!(counts.values().all(|&n| n >= 2000), "{counts:?}");
}

/// The slip, the transition times and the next transition: pooltool's numbers exactly.
#[test]
fn transition_times_are_pooltools() {
    let mut tally = Tally::default();
    for case in cases().filter(|c| c.kind == "times") {
        let mut f = fields(case.line, &case.inputs);
        let (params, state) = (read_params(&mut f), read_state(&mut f));
        let mut out = fields(case.line, &case.outputs);
        let slip = slip_velocity(&state, params.radius);
        let ours = [
            slip.x,
            slip.y,
            slide_time(&state, &params),
            roll_time(&state, &params),
            spin_time(&state, &params),
        ];
        for x in ours {
            let theirs = out.number();
            assert!(
                tally.add(x, theirs, 1.0, case.line) && x == theirs,
                "line {}: {x} against {theirs}",
                case.line
            );
        }
        let kind = out.rest.next().expect("the next transition");
        let delay = out.number();
        match next_transition(&state, &params) {
            None => assert_eq!(*kind, "none", "line {}", case.line),
            Some(next) => {
                assert_eq!(
                    next.kind,
                    transition_name(kind, case.line),
                    "line {}",
                    case.line
                );
                assert_eq!(next.delay, delay, "line {}", case.line);
            }
        }
        tally.add(0.0, 0.0, 1.0, case.line);
    }
    tally.report("slip, times, next transition");
    assert_eq!(tally.equal, tally.outputs);
}

/// The spin about the vertical: pooltool's numbers exactly.
#[test]
fn spin_decay_is_pooltools() {
    let mut tally = Tally::default();
    for case in cases().filter(|c| c.kind == "spin") {
        let mut f = fields(case.line, &case.inputs);
        let params = read_params(&mut f);
        let (w_z, t) = (f.number(), f.number());
        let theirs = fields(case.line, &case.outputs).number();
        let ours = evolve_spin(w_z, &params, t);
        tally.add(ours, theirs, 1.0, case.line);
        assert_eq!(ours, theirs, "line {}", case.line);
    }
    tally.report("spin decay");
    assert_eq!(tally.equal, tally.outputs);
}

/// One motion state's evolution (`evolve_roll`, `evolve_slide`) on the table's cases of
/// `kind`, against pooltool's: every output within the tolerance.
fn compare_stage(kind: &str, stage: fn(&BallState, &BallParams, f64) -> BallState) -> Tally {
    let mut tally = Tally::default();
    for case in cases().filter(|c| c.kind == kind) {
        let mut f = fields(case.line, &case.inputs);
        let (params, state) = (read_params(&mut f), read_state(&mut f));
        let t = f.number();
        let ours = stage(&state, &params, t);
        let scales = scales(&state, &params, t, ours.position);
        let ok = compare_state(
            &mut fields(case.line, &case.outputs),
            &ours,
            &scales,
            &mut tally,
        );
        assert!(ok, "line {}: {ours:?}", case.line);
    }
    tally
}

/// The roll: pooltool's arithmetic, so its numbers exactly.
#[test]
fn roll_is_pooltools() {
    let tally = compare_stage("roll", evolve_roll);
    tally.report("roll");
    assert_eq!(tally.equal, tally.outputs, "every output equal");
}

/// The slide: the same formulas in another frame, so within a few roundings of the scale.
#[test]
fn slide_is_pooltools_within_roundings() {
    compare_stage("slide", evolve_slide).report("slide");
}

/// `evolve` through its chain of states: pooltool's motion state exactly, the vectors within
/// a few roundings (a slide comes first in most cases); and [`ball_path`]'s centre at the same
/// time against pooltool's.
#[test]
fn evolve_and_the_path_are_pooltools() {
    let (mut tally, mut path_tally) = (Tally::default(), Tally::default());
    let mut boundaries = 0;
    for case in cases().filter(|c| c.kind == "evolve") {
        let mut f = fields(case.line, &case.inputs);
        let (params, state) = (read_params(&mut f), read_state(&mut f));
        let t = f.number();
        let ours = evolve(&state, &params, t);
        let mut out = fields(case.line, &case.outputs);
        let motion = read_motion(&mut out);
        if ours.motion != motion {
            // Only where `t` is a transition's time to a few roundings: pooltool's chain
            // decides `t >= time` with its own slide's roundings.
            let boundary = boundary_distance(&state, &params, t);
            assert!(
                boundary <= 1e-14 * t,
                "line {}: {:?} against {motion:?}",
                case.line,
                ours.motion
            );
            boundaries += 1;
        }
        let scales = scales(&state, &params, t, ours.position);
        let theirs = read_vectors(&mut fields(case.line, &case.outputs[1..]), ours.motion);
        assert!(
            compare_state(&mut out, &ours, &scales, &mut tally),
            "line {}: {ours:?}",
            case.line
        );
        // The path's centre at the same time (from a start of 0: a later one would add the
        // rounding of the absolute time, `(start + t) − start ≠ t`).
        let motion = ball_path(&state, &params, 0.0).expect("a valid ball");
        let (p, v) = (motion.path().position_at(t), motion.path().velocity_at(t));
        for k in 0..2 {
            let ok = path_tally.add(p[k], theirs.position[k], scales.position, case.line)
                & path_tally.add(v[k], theirs.velocity[k], scales.velocity, case.line);
            assert!(ok, "line {}: path {p} {v} against {theirs:?}", case.line);
        }
    }
    tally.report("evolve");
    path_tally.report("ball_path against evolve");
    println!("evolve: {boundaries} cases end in another motion state, each at a transition's time");
    assert!(boundaries <= 20, "{boundaries}");
}

/// A lone ball's transitions as pooltool's loop chains them, against [`ball_path`]'s segment
/// starts and states: the same kinds, in the same order; the times and states within a few
/// roundings.
#[test]
fn a_lone_balls_transitions_are_pooltools() {
    let (mut times, mut states) = (Tally::default(), Tally::default());
    let mut counts = std::collections::BTreeMap::new();
    for case in cases().filter(|c| c.kind == "path") {
        let mut f = fields(case.line, &case.inputs);
        let (params, state) = (read_params(&mut f), read_state(&mut f));
        let start = f.number();
        let motion = ball_path(&state, &params, start).expect("a valid ball");
        let mut out = fields(case.line, &case.outputs);
        let n = out.count();
        assert_eq!(
            motion.states().len(),
            n + 1,
            "line {}: {motion:?}",
            case.line
        );
        let end = motion.path().segments()[n].start;
        for k in 1..=n {
            let (segment, ours) = (&motion.path().segments()[k], &motion.states()[k]);
            let time = out.number();
            let kind = transition_name(out.rest.next().expect("a transition"), case.line);
            *counts.entry(format!("{kind:?}")).or_insert(0) += 1;
            assert_eq!(
                (motion.states()[k - 1].motion, ours.motion),
                (kind.before(), kind.after())
            );
            assert_eq!(read_motion(&mut out), ours.motion, "line {}", case.line);
            assert!(
                times.add(segment.start, time, start.abs().max(end), case.line),
                "line {}",
                case.line
            );
            let scales = scales(&state, &params, end - start, ours.position);
            let ok = compare_state(&mut out, ours, &scales, &mut states);
            assert!(ok, "line {}: {ours:?}", case.line);
        }
    }
    times.report("lone ball: transition times");
    states.report("lone ball: states after them");
    println!("transitions seen: {counts:?}");
    assert_eq!(counts.len(), 4, "every kind of transition: {counts:?}");
}

/// The roll's quarter turn and the spin's clamp are where the bits would go astray: this is
/// the check that the reading of the table is right (a rolling spin exactly as pooltool's).
#[test]
fn a_rolling_spin_as_pooltool_turns_it() {
    let params = BallParams::default();
    let state = BallState::new(
        Vector2::new(1.0, 0.5),
        Vector2::new(1.0, 0.0),
        Vector3::new(0.0, 1.0 / params.radius, 0.0),
        MotionState::Rolling,
    );
    let later = evolve_roll(&state, &params, 0.5);
    let w = later.velocity.x / params.radius;
    // pooltool: cos(π/2)·(v_x/R) − v_y/R, with v_y = 0: a trace of 6e-17 of ω_y.
    assert_eq!(
        later.angular_velocity.x,
        std::f64::consts::FRAC_PI_2.cos() * w
    );
    assert_eq!(later.angular_velocity.y, w);
}

/// Two balls at contact through pooltool's default ball–ball model: `make_kiss`'s positions
/// and the friction at them equal pooltool's; the states after `resolve` within a few
/// roundings of the speeds and spins involved (pooltool turns into the line of centres' frame
/// by its angle, we by its unit vector).
#[test]
fn ball_ball_collisions_are_pooltools() {
    let model = FrictionalInelastic::default();
    let (mut kiss, mut friction, mut after) =
        (Tally::default(), Tally::default(), Tally::default());
    let mut categories = std::collections::BTreeMap::new();
    let mut separated = 0;
    for case in cases().filter(|c| c.kind == "ball_ball") {
        let line = case.line;
        *categories.entry(case.category).or_insert(0) += 1;
        let mut f = fields(line, &case.inputs);
        let read_ball_params = |f: &mut Fields<'_>| BallParams {
            e_b: 0.0,
            ..read_params(f)
        };
        let mut params = [read_ball_params(&mut f), BallParams::default()];
        params[0].e_b = f.number();
        params[1] = read_ball_params(&mut f);
        params[1].e_b = f.number();
        let balls = [read_state(&mut f), read_state(&mut f)];
        let mut out = fields(line, &case.outputs);
        let kissed = make_kiss([&balls[0], &balls[1]], params[0].radius);
        let magnitude = balls[0].position.amax().max(balls[1].position.amax());
        for ball in &kissed {
            for k in 0..2 {
                assert!(
                    kiss.add(ball.position[k], out.number(), magnitude, line),
                    "line {line}"
                );
            }
        }
        let u_b = AlciatoreFriction::default()
            .between([&kissed[0], &kissed[1]], [&params[0], &params[1]]);
        assert!(friction.add(u_b, out.number(), u_b, line), "line {line}");
        let resolved = model.resolve([&balls[0], &balls[1]], [&params[0], &params[1]]);
        let solved = model.solve([&kissed[0], &kissed[1]], [&params[0], &params[1]]);
        separated += usize::from(solved != resolved);
        let speed: f64 = balls
            .iter()
            .map(|b| b.velocity.norm() + b.angular_velocity.norm() * params[0].radius)
            .sum();
        let scales = Scales {
            position: magnitude,
            velocity: speed.max(f64::MIN_POSITIVE),
            spin: (speed / params[0].radius).max(f64::MIN_POSITIVE),
        };
        for ours in &resolved {
            assert_eq!(read_motion(&mut out), ours.motion, "line {line}");
            assert!(
                compare_state(&mut out, ours, &scales, &mut after),
                "line {line}: {ours:?}"
            );
        }
    }
    kiss.report("ball-ball: make_kiss");
    friction.report("ball-ball: friction");
    after.report("ball-ball: states after");
    println!("ball-ball categories: {categories:?}; {separated} moving on together (separated)");
    assert!(
        separated >= 50,
        "separate_touching's case seen: {separated}"
    );
}

/// The ball moved by `shift` along `direction` (made a unit vector).
fn moved(ball: &BallState, shift: f64, direction: &Vector2<f64>) -> BallState {
    let mut out = *ball;
    out.position += direction / direction.norm() * shift;
    out
}

/// The normal of a straight cushion towards the ball, in the plane.
fn linear_normal(cushion: &LinearCushion, ball: &BallState) -> Vector2<f64> {
    let n = cushion.normal_3d(Vector3::new(
        ball.position.x,
        ball.position.y,
        cushion.height,
    ));
    Vector2::new(n.x, n.y)
}

/// The Stronge cushion models: pooltool's `StrongeCompliantLinear` and
/// `StrongeCompliantCircular` (`omega_ratio` 1.8) at contact, in each of the three regimes
/// (gross slip; stick then slip; slip, stick, slip — the last two with a root found by Brent's
/// method here, TOMS748 there). The state after within `1e-12` of its scale (the ball's speed
/// and its spin's surface speed before; over the radius for spins), each regime tallied apart.
#[test]
fn cushion_collisions_are_pooltools() {
    for kind in ["linear_cushion", "circular_cushion"] {
        let mut tallies: std::collections::BTreeMap<&str, Tally> = Default::default();
        let mut beyond = Vec::new();
        let (mut kiss, mut after_kiss, mut unresolved) = (Tally::default(), Tally::default(), 0);
        for case in cases().filter(|c| c.kind == kind) {
            let line = case.line;
            let mut f = fields(line, &case.inputs);
            let mut params = read_params(&mut f);
            params.e_c = f.number();
            params.f_c = f.number();
            let ball = read_state(&mut f);
            let count = if kind == "linear_cushion" { 4 } else { 3 };
            let mut cushion_numbers = [0.0; 4];
            for x in cushion_numbers.iter_mut().take(count) {
                *x = f.number();
            }
            let height = f.number();
            let shift = f.number();
            let [a, b, c, d] = cushion_numbers;
            let linear = LinearCushion::new(Vector2::new(a, b), Vector2::new(c, d), height);
            let circular = CircularCushion::new(Vector2::new(a, b), c, height);
            // make_kiss and resolve on the ball moved by `shift` off contact, straight out.
            let (solved, kissed, resolved) = if kind == "linear_cushion" {
                let model = StrongeCompliantLinear::default();
                let off = moved(&ball, shift, &linear_normal(&linear, &ball));
                (
                    model.solve(&ball, &params, &linear),
                    Some(kiss_linear_cushion(&off, params.radius, &linear)),
                    model.resolve(&off, &params, &linear),
                )
            } else {
                let model = StrongeCompliantCircular::default();
                let off = moved(&ball, shift, &(ball.position - circular.center));
                (
                    model.solve(&ball, &params, &circular),
                    kiss_circular_cushion(&off, params.radius, &circular),
                    model.resolve(&off, &params, &circular),
                )
            };
            let ours = solved.unwrap_or_else(|| panic!("line {line}: not resolved"));
            assert_eq!(ours.motion, MotionState::Sliding, "line {line}");
            let speed = ball.velocity.norm() + ball.angular_velocity.norm() * params.radius;
            let scales = Scales {
                position: ball.position.amax(),
                velocity: speed.max(f64::MIN_POSITIVE),
                spin: (speed / params.radius).max(f64::MIN_POSITIVE),
            };
            let tally = tallies.entry(case.category).or_default();
            let mut out = fields(line, &case.outputs);
            if !compare_state(&mut out, &ours, &scales, tally) {
                beyond.push(line);
            }
            let kissed = kissed.unwrap_or_else(|| panic!("line {line}: no kiss"));
            for k in 0..2 {
                if !kiss.add(kissed.position[k], out.number(), scales.position, line) {
                    beyond.push(line);
                }
            }
            if out.rest.clone().next() == Some(&"none") {
                assert!(
                    resolved.is_none(),
                    "line {line}: pooltool fails, we resolve"
                );
                unresolved += 1;
            } else {
                let resolved = resolved.unwrap_or_else(|| panic!("line {line}: not resolved"));
                if !compare_state(&mut out, &resolved, &scales, &mut after_kiss) {
                    beyond.push(line);
                }
            }
        }
        assert_eq!(tallies.len(), 3, "{kind}: every regime");
        for (regime, tally) in &tallies {
            assert!(tally.outputs >= 600 * 7, "{kind} {regime}");
            tally.report(&format!("{kind} {regime}"));
        }
        kiss.report(&format!("{kind} make_kiss"));
        after_kiss.report(&format!("{kind} resolve"));
        println!("{kind}: {unresolved} cases where pooltool's solve fails after make_kiss");
        assert!(
            kiss.outputs >= 4000 && after_kiss.outputs >= 7 * 1900,
            "{kind}"
        );
        assert!(
            beyond.is_empty(),
            "{kind}: beyond the tolerance on lines {beyond:?}"
        );
    }
}

/// A ball dropping into a pocket, `CanonicalBallPocket`: pooltool's state after to the bit
/// (the pocket's centre, its bottom as the ball's height, no velocity, no spin, pocketed), from
/// balls in every motion state; pooltool's pocket holds the ball after, and its state's time
/// is 0 (its loop sets it after; our states carry no time).
#[test]
fn pockets_are_pooltools() {
    let mut tally = Tally::default();
    let mut categories = std::collections::BTreeMap::new();
    for case in cases().filter(|c| c.kind == "pocket") {
        let line = case.line;
        *categories.entry(case.category).or_insert(0) += 1;
        let mut f = fields(line, &case.inputs);
        let ball = read_state(&mut f);
        let pocket = Pocket::new(f.vector::<2>(), f.number(), f.number());
        pocket
            .check()
            .unwrap_or_else(|e| panic!("line {line}: {e}"));
        let ours = CanonicalBallPocket.resolve(&ball, &BallParams::default(), &pocket);
        let mut out = fields(line, &case.outputs);
        assert_eq!(read_motion(&mut out), ours.motion, "line {line}");
        let [rx, ry, rz, vx, vy, vz, wx, wy, wz, t, contains] = [(); 11].map(|_| out.number());
        let theirs = [rx, ry, rz, vx, vy, vz, wx, wy, wz];
        let w = ours.angular_velocity;
        let (p, v) = (ours.position, ours.velocity);
        let ours = [p.x, p.y, pocket.bottom(), v.x, v.y, 0.0, w.x, w.y, w.z];
        for (a, b) in ours.into_iter().zip(theirs) {
            assert!(
                tally.add(a, b, 1.0, line) && a == b,
                "line {line}: {a} against {b}"
            );
        }
        assert_eq!((t, contains), (0.0, 1.0), "line {line}");
    }
    tally.report("pocket");
    println!("pocket: balls that were {categories:?}");
    assert_eq!(categories.len(), 5, "every motion state: {categories:?}");
    assert_eq!(tally.equal, tally.outputs);
}

/// The cue striking a ball, `InstantaneousPoint` with squirt: pooltool's velocity and spin
/// within `1e-12` of their scale (the ball's speed after plus its spin's at the surface, and
/// that over the radius for spins;
/// pooltool turns vectors by a matrix product in BLAS, and squares and takes `arctan2` with
/// NumPy), and its squirt angle within `1e-12` relative (NumPy's `arctan2`); nearly every
/// stroke to the bit; the position kept to the bit, the ball sliding, its time 0.
#[test]
fn cue_strikes_are_pooltools() {
    let (mut velocity, mut spin, mut squirt) =
        (Tally::default(), Tally::default(), Tally::default());
    let (mut categories, mut identical) = (std::collections::BTreeMap::new(), 0);
    // The largest difference of a component relative to itself, where they differ.
    let mut own_scale: f64 = 0.0;
    for case in cases().filter(|c| c.kind == "stick") {
        let line = case.line;
        *categories.entry(case.category).or_insert(0) += 1;
        let mut f = fields(line, &case.inputs);
        let params = BallParams {
            mass: f.number(),
            radius: f.number(),
            ..BallParams::default()
        };
        let [v0, phi, theta, a, b, mass, end_mass, tip_radius] = [(); 8].map(|_| f.number());
        let specs = CueSpecs {
            mass,
            end_mass,
            tip_radius,
        };
        let cue = Cue {
            v0,
            phi,
            theta,
            a,
            b,
            specs,
        };
        let model = InstantaneousPoint {
            english_throttle: f.number(),
            squirt_throttle: f.number(),
        };
        // Whatever the ball did before the stroke, only its position stays.
        let before = BallState::new(
            f.vector::<2>(),
            Vector2::new(0.5, -0.25),
            Vector3::new(3.0, -7.0, 11.0),
            MotionState::Rolling,
        );
        let ours = model
            .resolve(&cue, &before, &params)
            .unwrap_or_else(|e| panic!("line {line}: {e}"));
        let mut out = fields(line, &case.outputs);
        assert_eq!(read_motion(&mut out), MotionState::Sliding, "line {line}");
        assert_eq!(ours.motion, MotionState::Sliding);
        assert_eq!(ours.position, before.position, "line {line}");
        let (v, w) = (out.vector::<2>(), out.vector::<3>());
        let (t, alpha) = (out.number(), out.number());
        assert_eq!(t, 0.0, "line {line}");
        // The scale: the speeds of the centre and of the surface about it (a massé's velocity
        // is a trace beside its spin: cos 90° · v).
        let scale = (v.norm() + w.norm() * params.radius).max(f64::MIN_POSITIVE);
        let mut ok = true;
        for k in 0..2 {
            ok &= velocity.add(ours.velocity[k], v[k], scale, line);
        }
        for k in 0..3 {
            ok &= spin.add(ours.angular_velocity[k], w[k], scale / params.radius, line);
        }
        let our_alpha = squirt_angle(params.mass, end_mass, a, model.squirt_throttle);
        ok &= squirt.add(our_alpha, alpha, alpha.abs().max(f64::MIN_POSITIVE), line);
        assert!(ok, "line {line}: {ours:?}, squirt {our_alpha}");
        identical += usize::from(ours.velocity == v && ours.angular_velocity == w);
        let pairs = ours.velocity.iter().zip(&v);
        for (x, y) in pairs.chain(ours.angular_velocity.iter().zip(&w)) {
            if x != y {
                own_scale = own_scale.max((x - y).abs() / y.abs());
            }
        }
    }
    velocity.report("stick: velocity");
    spin.report("stick: spin");
    squirt.report("stick: squirt angle");
    println!(
        "stick: strokes {categories:?}; {identical} with pooltool's velocity and spin to the bit"
    );
    println!("stick: worst component relative to itself {own_scale:.2e}");
    assert_eq!(
        categories.len(),
        4,
        "level and elevated, with and without side: {categories:?}"
    );
    assert!(categories.values().all(|&n| n >= 100), "{categories:?}");
    // The arithmetic is pooltool's, its matrix products as OpenBLAS computes them: all but
    // the few where NumPy's `**` and `arctan2` round otherwise than the C library (2 of 2,000
    // where the table was written). Not all: another C library's sin and cos may differ.
    assert!(identical >= 1900, "{identical} strokes to the bit");
}
