//! [`simulate_shot`]: pooltool's event loop on the calendar. A shot on a [`BilliardTable`],
//! from an optional cue strike until every ball is at rest or pocketed, with its event log.

use super::slip_velocity;
use super::{
    BallBallResolver, BallCircularCushionResolver, BallLinearCushionResolver, BallParams, BallPath,
    BallPocketResolver, BallState, BilliardTable, CanonicalBallPocket, Cue, FrictionalInelastic,
    InstantaneousPoint, MotionState, StickBallResolver, StrongeCompliantCircular,
    StrongeCompliantLinear, TransitionKind, ball_path,
};
use crate::error::{InputError, InputErrorKind};
use crate::geometry::ObjectKind;
use crate::schedule::{CollisionSchedule, Event, MAX_EVENTS_AT_ONE_INSTANT, ScheduleOptions};

/// The models a shot's events are resolved with. [`Default`] is pooltool 0.6.0's default
/// resolver (VERSION 9): [`FrictionalInelastic`], [`StrongeCompliantLinear`],
/// [`StrongeCompliantCircular`], [`CanonicalBallPocket`], [`InstantaneousPoint`];
/// transitions are always [`TransitionKind::apply`] (pooltool's `CanonicalTransition`).
///
/// ```
/// use ballcollide::billiards::{ShotResolvers, StrongeCompliantLinear};
/// let softer = ShotResolvers { linear_cushion: Box::new(StrongeCompliantLinear { omega_ratio: 1.5 }), ..Default::default() };
/// # let _ = softer;
/// ```
pub struct ShotResolvers {
    /// Ball–ball collisions.
    pub ball_ball: Box<dyn BallBallResolver + Send + Sync>,
    /// Ball–straight-cushion collisions.
    pub linear_cushion: Box<dyn BallLinearCushionResolver + Send + Sync>,
    /// Ball–rounded-cushion collisions.
    pub circular_cushion: Box<dyn BallCircularCushionResolver + Send + Sync>,
    /// A ball dropping into a pocket.
    pub pocket: Box<dyn BallPocketResolver + Send + Sync>,
    /// The cue striking a ball.
    pub stick: Box<dyn StickBallResolver + Send + Sync>,
}

impl Default for ShotResolvers {
    fn default() -> Self {
        Self {
            ball_ball: Box::new(FrictionalInelastic::default()),
            linear_cushion: Box::new(StrongeCompliantLinear::default()),
            circular_cushion: Box::new(StrongeCompliantCircular::default()),
            pocket: Box::new(CanonicalBallPocket),
            stick: Box::new(InstantaneousPoint::default()),
        }
    }
}

impl std::fmt::Debug for ShotResolvers {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("ShotResolvers")
    }
}

/// Options of [`simulate_shot`].
///
/// ```
/// use ballcollide::billiards::ShotOptions;
/// let options = ShotOptions { max_events: Some(100), ..Default::default() };
/// assert!(options.strike.is_none());
/// ```
#[derive(Debug, Default)]
pub struct ShotOptions {
    /// The cue's stroke and the ball it strikes, at time 0 (pooltool's stick–ball event).
    /// Default none: the balls move as given.
    pub strike: Option<(usize, Cue)>,
    /// The models. Default pooltool's.
    pub resolvers: ShotResolvers,
    /// The shot ends after this many events (the strike counts). Default none.
    pub max_events: Option<usize>,
    /// When two balls collide. Default pooltool's rule.
    pub contact_rule: ContactRule,
}

/// When two balls collide: besides coming into contact, pooltool 0.6.0 collides some pairs at
/// once, and this engine follows it by default.
///
/// ```
/// use ballcollide::billiards::{ContactRule, ShotOptions};
/// assert_eq!(ShotOptions::default().contact_rule, ContactRule::Pooltool);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum ContactRule {
    /// pooltool 0.6.0's rule: when a pair's next contact is sought (at the start, and after
    /// every event of either ball, transitions included), unless one ball is pocketed or
    /// neither translates, the balls collide at once if their centres are closer than the
    /// sum of their radii (`is_overlapping`: rounding, or `make_kiss` moving a ball back by
    /// up to `5e-6 m` into a third one, as in a rack), even if they part; or if their
    /// accelerations, as pooltool's detector forms them, are the same to the bit (the gap
    /// quartic's leading coefficient is then 0, and pooltool's solver answers with four
    /// roots at 0: two balls rolling the same way along an axis, after a straight shot).
    /// `make_kiss` then brings the balls to `2R + 1e-6` apart wherever they were.
    #[default]
    Pooltool,
    /// The calendar's rule: balls collide only when they come into contact, approaching;
    /// overlapping balls that part are left to part.
    Approaching,
}

/// What happened at an event of a shot (pooltool's `EventType`), with the cushion's or the
/// pocket's index in its [`BilliardTable`] list.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ShotEventKind {
    /// The cue strikes the ball (`stick_ball`).
    Stick,
    /// A ball changes motion state by itself (`sliding_rolling`, `rolling_spinning`,
    /// `rolling_stationary`, `spinning_stationary`).
    Transition(TransitionKind),
    /// Two balls collide (`ball_ball`).
    BallBall,
    /// A ball meets straight cushion `index` (`ball_linear_cushion`).
    LinearCushion(usize),
    /// A ball meets rounded cushion `index` (`ball_circular_cushion`).
    CircularCushion(usize),
    /// A ball drops into pocket `index` (`ball_pocket`).
    Pocket(usize),
}

impl ShotEventKind {
    /// pooltool's event type names in the order of [`code`](Self::code): a kind's code is
    /// the index of its [`name`](Self::name) here.
    ///
    /// ```
    /// use ballcollide::billiards::ShotEventKind;
    /// let kind = ShotEventKind::Pocket(2);
    /// assert_eq!(ShotEventKind::NAMES[kind.code() as usize], kind.name());
    /// ```
    pub const NAMES: [&'static str; 9] = [
        "stick_ball",
        "sliding_rolling",
        "rolling_spinning",
        "rolling_stationary",
        "spinning_stationary",
        "ball_ball",
        "ball_linear_cushion",
        "ball_circular_cushion",
        "ball_pocket",
    ];

    /// The kind's number: the index of its name in [`NAMES`](Self::NAMES) (example there).
    pub const fn code(&self) -> i64 {
        match self {
            Self::Stick => 0,
            Self::Transition(TransitionKind::SlidingRolling) => 1,
            Self::Transition(TransitionKind::RollingSpinning) => 2,
            Self::Transition(TransitionKind::RollingStationary) => 3,
            Self::Transition(TransitionKind::SpinningStationary) => 4,
            Self::BallBall => 5,
            Self::LinearCushion(_) => 6,
            Self::CircularCushion(_) => 7,
            Self::Pocket(_) => 8,
        }
    }

    /// The index of the cushion or pocket in its [`BilliardTable`] list, if the event has
    /// one.
    ///
    /// ```
    /// use ballcollide::billiards::ShotEventKind;
    /// assert_eq!(ShotEventKind::LinearCushion(3).object(), Some(3));
    /// assert_eq!(ShotEventKind::BallBall.object(), None);
    /// ```
    pub const fn object(&self) -> Option<usize> {
        match self {
            Self::LinearCushion(k) | Self::CircularCushion(k) | Self::Pocket(k) => Some(*k),
            Self::Stick | Self::Transition(_) | Self::BallBall => None,
        }
    }

    /// pooltool's name of the event type (its `EventType` value).
    ///
    /// ```
    /// use ballcollide::billiards::{ShotEventKind, TransitionKind};
    /// assert_eq!(ShotEventKind::Transition(TransitionKind::SlidingRolling).name(), "sliding_rolling");
    /// assert_eq!(ShotEventKind::LinearCushion(3).name(), "ball_linear_cushion");
    /// ```
    pub const fn name(&self) -> &'static str {
        match self {
            Self::Stick => "stick_ball",
            Self::Transition(TransitionKind::SlidingRolling) => "sliding_rolling",
            Self::Transition(TransitionKind::RollingSpinning) => "rolling_spinning",
            Self::Transition(TransitionKind::RollingStationary) => "rolling_stationary",
            Self::Transition(TransitionKind::SpinningStationary) => "spinning_stationary",
            Self::BallBall => "ball_ball",
            Self::LinearCushion(_) => "ball_linear_cushion",
            Self::CircularCushion(_) => "ball_circular_cushion",
            Self::Pocket(_) => "ball_pocket",
        }
    }
}

/// One event of a shot: when, what, and the balls it involved (their indices, the lower
/// first for a collision) with each one's state just after it.
#[derive(Clone, Debug, PartialEq)]
pub struct ShotEvent {
    /// When (seconds from the strike).
    pub time: f64,
    /// What, with the cushion's or pocket's index.
    pub kind: ShotEventKind,
    /// The balls: one, or two for a collision.
    pub balls: Vec<usize>,
    /// Each ball's state just after the event, in the order of `balls`.
    pub states: Vec<BallState>,
}

/// What [`simulate_shot`] returns.
#[derive(Clone, Debug, PartialEq)]
pub struct Shot {
    /// The events, in order.
    pub events: Vec<ShotEvent>,
    /// The time of the last event (0 without events).
    pub end: f64,
    /// Each ball's state at `end`: at rest, pocketed, or (a friction of 0, or `max_events`)
    /// still moving.
    pub states: Vec<BallState>,
    /// Whether `max_events` ended the shot.
    pub stopped: bool,
}

/// Simulates a shot as pooltool 0.6.0's event-based `simulate` does: balls in `balls` (one
/// [`BallParams`] each in `params`) on `table`, struck at time 0 by the cue if
/// `options.strike` says so, until every ball is at rest or pocketed.
///
/// Each ball moves on its [`ball_path`]; the calendar ([`CollisionSchedule`], with the
/// table's [`geometry`](BilliardTable::geometry) and transitions) gives the next event, the
/// earliest of: a ball's change of motion state (its path's next segment start), two balls
/// touching (contact distance `R_i + R_j`), a ball touching a straight or a rounded cushion,
/// a ball's centre entering a pocket. The event is resolved by its model
/// ([`ShotResolvers`]) from the balls' states at its time
/// ([`BallPath::state_at`]), and the paths of the balls it changed are replaced from then
/// on; a pocketed ball leaves play ([`CollisionSchedule::retire`]).
///
/// **Collisions at once.** Under pooltool's rule ([`ContactRule::Pooltool`], the default),
/// two balls found overlapping, or with the same acceleration, when their pair is looked at
/// again (after an event of either) collide at once, even if they part.
///
/// **Ties.** pooltool takes events at the same instant by `get_event_priority`: the stick,
/// then transitions and pockets (tier 2), then collisions and cushions (tier 3), the ball of
/// higher energy first within a tier, then by the order of its detectors and caches. Here:
/// the stick first; collisions at once after the instant's transitions and pockets and before
/// its other events, among themselves in the order of pooltool's cache (pairs still waiting
/// first, then those just found, `(i, j)` in the order of `itertools.combinations`); the
/// calendar's events in the calendar's order (by the lower ball index, then a ball's
/// transition, its cushion and pocket contacts, its collisions). So one ball's transition
/// comes before its contacts as in pooltool, but a tie between two balls' events goes by
/// their indices, not their energies. Such exact ties did not come in the 312 shots of
/// pooltool's that `tests/reference/shots.rs` was run on.
///
/// **Rounding.** pooltool evolves every ball to every event and detects from the evolved
/// states; here each ball follows its path from its last change. Their times differ by
/// roundings, which a long run of collisions amplifies (in one of 200 breaks to `2.8e-6 s`
/// after 100 events, the events themselves the same).
///
/// # Errors
/// An [`InputError`]: `params` of another length than `balls`; no `max_events` when a ball
/// with a sliding or rolling friction of 0 may move (`max_events`,
/// [`InputErrorKind::Endless`]: it may never stop); a ball's state or parameters
/// that fail their checks (`position[i, k]`, `mass[i]`, …: the ball, then the component); a
/// bad table object ([`BilliardTable::geometry`]); a strike of a ball out of range
/// (`strike`) or that fails the stick model's checks; a contact its model cannot resolve
/// ([`InputErrorKind::UnresolvedContact`], `balls[i]`); more events at one instant than
/// [`MAX_EVENTS_AT_ONE_INSTANT`] allows ([`InputErrorKind::NoProgress`]).
///
/// ```
/// use ballcollide::billiards::{BallParams, BallState, BilliardTable, Cue, LinearCushion, ShotEventKind, ShotOptions, simulate_shot};
/// use ballcollide::geometry::SegmentSide;
/// use nalgebra::Vector2;
///
/// // A ball struck at 1.5 m/s straight at a rail 0.5 m away.
/// let params = BallParams::default();
/// let rail = LinearCushion::new(Vector2::new(0.0, 1.0), Vector2::new(1.0, 1.0), 0.036576);
/// let table = BilliardTable { linear: vec![(rail, SegmentSide::Right)], ..Default::default() };
/// let cue = Cue { v0: 1.5, phi: 90.0, ..Cue::default() };
/// let options = ShotOptions { strike: Some((0, cue)), ..Default::default() };
/// let shot = simulate_shot(&table, &[BallState::at_rest(Vector2::new(0.5, 0.5))], &[params], &options)?;
/// let kinds: Vec<&str> = shot.events.iter().map(|e| e.kind.name()).collect();
/// assert_eq!(kinds[..3], ["stick_ball", "sliding_rolling", "ball_linear_cushion"]);
/// assert_eq!(shot.events[2].kind, ShotEventKind::LinearCushion(0));
/// assert!(shot.states[0].position.y < 1.0 - params.radius);
/// assert_eq!(shot.states[0].velocity, Vector2::zeros()); // at rest in the end
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn simulate_shot(
    table: &BilliardTable,
    balls: &[BallState],
    params: &[BallParams],
    options: &ShotOptions,
) -> Result<Shot, InputError> {
    simulate_struck(table, balls, params, options.strike.as_ref(), options)
}

/// [`simulate_shot`] with `strike` in place of `options.strike` (which is not read): the
/// loop that [`simulate_shots`](super::simulate_shots) shares.
pub(crate) fn simulate_struck(
    table: &BilliardTable,
    balls: &[BallState],
    params: &[BallParams],
    strike: Option<&(usize, Cue)>,
    options: &ShotOptions,
) -> Result<Shot, InputError> {
    let n = balls.len();
    crate::batch::check_len("params", params.len(), n)?;
    // A ball without sliding or rolling friction that is set moving may go on for ever,
    // between the cushions.
    let moves = strike.is_some() || balls.iter().any(|b| b.motion.translates());
    let frictionless = params.iter().any(|p| p.u_s == 0.0 || p.u_r == 0.0);
    if moves && frictionless && options.max_events.is_none() {
        return Err(InputError::new("max_events", InputErrorKind::Endless));
    }
    let geometry = table.geometry()?;
    let resolvers = &options.resolvers;
    let max_events = options.max_events.unwrap_or(usize::MAX);
    let mut states = balls.to_vec();
    let mut events = Vec::new();
    if let Some((i, cue)) = strike {
        let Some(ball) = states.get_mut(*i) else {
            let kind = InputErrorKind::IndexOutOfRange {
                index: i64::try_from(*i).unwrap_or(i64::MAX),
                len: n,
            };
            return Err(InputError::new("strike", kind));
        };
        *ball = resolvers.stick.resolve(cue, ball, &params[*i])?;
        if max_events > 0 {
            events.push(ShotEvent {
                time: 0.0,
                kind: ShotEventKind::Stick,
                balls: vec![*i],
                states: vec![*ball],
            });
        }
    }
    let mut motions = states
        .iter()
        .zip(params)
        .enumerate()
        .map(|(i, (state, p))| ball_path(state, p, 0.0).map_err(|e| e.in_pair(i)))
        .collect::<Result<Vec<BallPath>, _>>()?;
    let radii: Vec<f64> = params.iter().map(|p| p.radius).collect();
    let calendar_options = ScheduleOptions {
        table: geometry,
        transitions: true,
        ..Default::default()
    };
    let paths = motions.iter().map(|m| m.path().clone()).collect();
    let mut calendar = CollisionSchedule::new(paths, &radii, calendar_options)?;
    for (i, state) in states.iter().enumerate() {
        if state.motion == MotionState::Pocketed {
            calendar.retire(i)?;
        }
    }
    let most_at_one_instant = MAX_EVENTS_AT_ONE_INSTANT
        .1
        .saturating_mul(n)
        .saturating_add(MAX_EVENTS_AT_ONE_INSTANT.0);
    let mut at_this_instant = 0usize;
    let mut end = 0.0;
    let mut stopped = false;
    // pooltool's collisions at once (see `ContactRule::Pooltool`): the pairs it would collide
    // at once when their contact was last sought, in the order it would take them.
    let mut at_once: Vec<[usize; 2]> = Vec::new();
    let at_once_rule = options.contact_rule == ContactRule::Pooltool;
    if at_once_rule {
        let all: Vec<usize> = (0..n).collect();
        collisions_at_once(&motions, params, &all, 0.0, &mut at_once);
    }
    loop {
        if events.len() >= max_events {
            stopped = true;
            break;
        }
        let next = calendar.next_event();
        let event = match (at_once.first(), next) {
            // The calendar's transitions and pockets at the same instant come first, as
            // pooltool's priority has it (its tier 2 before collisions' tier 3).
            (Some(&pair), next) if next.is_none_or(|e| !before_collisions(&e, end)) => {
                at_once.remove(0);
                Next::AtOnce(pair)
            }
            (_, Some(event)) => Next::Calendar(event),
            (_, None) => break,
        };
        let t = match event {
            Next::Calendar(event) => event.time(),
            Next::AtOnce(_) => end,
        };
        at_this_instant = if t == end { at_this_instant + 1 } else { 1 };
        end = t;
        let logged = match event {
            Next::AtOnce([i, j]) => {
                collide(resolvers, &mut calendar, &mut motions, params, [i, j], t)?
            }
            Next::Calendar(event) => match event {
                Event::Transition(transition) => {
                    let i = transition.ball;
                    let states = motions[i].states();
                    let (Some(before), Some(after)) = (
                        states.get(transition.segment.wrapping_sub(1)),
                        states.get(transition.segment),
                    ) else {
                        return Err(unresolved(i, t));
                    };
                    let Some(kind) = transition_kind(before.motion, after.motion) else {
                        return Err(unresolved(i, t));
                    };
                    let after = *after;
                    replace(&mut calendar, &mut motions, &[i], &[after], params, t)?;
                    ShotEvent {
                        time: t,
                        kind: ShotEventKind::Transition(kind),
                        balls: vec![i],
                        states: vec![after],
                    }
                }
                Event::Collision(c) => {
                    at_once.retain(|&pair| pair != [c.i, c.j]);
                    collide(
                        resolvers,
                        &mut calendar,
                        &mut motions,
                        params,
                        [c.i, c.j],
                        t,
                    )?
                }
                Event::Object(contact) => {
                    let i = contact.ball;
                    let state = motions[i].state_at(t);
                    let p = &params[i];
                    let (after, kind) = match contact.kind {
                        ObjectKind::Segment => {
                            let cushion = &table.linear[contact.index].0;
                            let after = resolvers.linear_cushion.resolve(&state, p, cushion);
                            (after, ShotEventKind::LinearCushion(contact.index))
                        }
                        ObjectKind::Circle => {
                            let cushion = &table.circular[contact.index];
                            let after = resolvers.circular_cushion.resolve(&state, p, cushion);
                            (after, ShotEventKind::CircularCushion(contact.index))
                        }
                        ObjectKind::Target => {
                            let pocket = &table.pockets[contact.index];
                            let after = resolvers.pocket.resolve(&state, p, pocket);
                            (Some(after), ShotEventKind::Pocket(contact.index))
                        }
                        // The table has no planes.
                        ObjectKind::Plane => return Err(unresolved(i, t)),
                    };
                    let after = after.ok_or_else(|| unresolved(i, t))?;
                    replace(&mut calendar, &mut motions, &[i], &[after], params, t)?;
                    if after.motion == MotionState::Pocketed {
                        calendar.retire(i)?;
                    }
                    ShotEvent {
                        time: t,
                        kind,
                        balls: vec![i],
                        states: vec![after],
                    }
                }
                // The calendar has no walls.
                Event::Wall(w) => return Err(unresolved(w.ball, t)),
            },
        };
        if at_once_rule {
            // As pooltool's cache after the event: the pairs of its balls sought again.
            at_once.retain(|pair| !pair.iter().any(|b| logged.balls.contains(b)));
            collisions_at_once(&motions, params, &logged.balls, t, &mut at_once);
        }
        if at_this_instant > most_at_one_instant {
            let other = logged.balls.get(1).copied();
            let kind = InputErrorKind::NoProgress {
                other,
                time: t,
                events: at_this_instant,
            };
            return Err(InputError::new("balls", kind).at(logged.balls[0]));
        }
        events.push(logged);
    }
    let states = motions.iter().map(|m| m.state_at(end)).collect();
    Ok(Shot {
        events,
        end,
        states,
        stopped,
    })
}

/// What comes next: the calendar's event, or one of pooltool's collisions at once.
#[derive(Clone, Copy, Debug)]
enum Next {
    Calendar(Event),
    AtOnce([usize; 2]),
}

/// Whether the calendar's `event` comes before a collision at once at `now`: it is at `now`
/// and of pooltool's tier 2 (a transition, a ball dropping into a pocket).
fn before_collisions(event: &Event, now: f64) -> bool {
    let tier_2 = match event {
        Event::Transition(_) => true,
        Event::Object(o) => o.kind == ObjectKind::Target,
        _ => false,
    };
    tier_2 && event.time() <= now
}

/// The collision of balls `[i, j]` at `t`, resolved and put in the calendar.
fn collide(
    resolvers: &ShotResolvers,
    calendar: &mut CollisionSchedule<2>,
    motions: &mut [BallPath],
    params: &[BallParams],
    [i, j]: [usize; 2],
    t: f64,
) -> Result<ShotEvent, InputError> {
    let (a, b) = (motions[i].state_at(t), motions[j].state_at(t));
    let after = resolvers
        .ball_ball
        .resolve([&a, &b], [&params[i], &params[j]]);
    replace(calendar, motions, &[i, j], &after, params, t)?;
    Ok(ShotEvent {
        time: t,
        kind: ShotEventKind::BallBall,
        balls: vec![i, j],
        states: after.to_vec(),
    })
}

/// Appends to `pairs` each pair with a ball of `changed` that pooltool's ball–ball detector
/// would collide at once at `t` (`get_next_ball_ball_collision`; see [`at_once`]), in
/// pooltool's order: the pairs `(i, j)`, `i < j`, in the order of `itertools.combinations`
/// over the balls, skipping those already listed.
fn collisions_at_once(
    motions: &[BallPath],
    params: &[BallParams],
    changed: &[usize],
    t: f64,
    pairs: &mut Vec<[usize; 2]>,
) {
    // Each ball's state and detector acceleration once per call (the trigonometry of the
    // acceleration is most of the cost).
    let seen = |b: usize| {
        let state = motions[b].state_at(t);
        (state, detector_acceleration(&state, &params[b]))
    };
    let changed: Vec<(usize, (BallState, [f64; 2]))> =
        changed.iter().map(|&b| (b, seen(b))).collect();
    let mut found: Vec<[usize; 2]> = Vec::new();
    for o in 0..motions.len() {
        // Each other ball's only if some pair needs it.
        let mut other = None;
        for (b, ball) in &changed {
            let pair = [o.min(*b), o.max(*b)];
            if *b == o || found.contains(&pair) || pairs.contains(&pair) {
                continue;
            }
            let other = *other.get_or_insert_with(|| seen(o));
            let (first, second) = if *b < o {
                (ball, &other)
            } else {
                (&other, ball)
            };
            if at_once([first, second], [&params[pair[0]], &params[pair[1]]]) {
                found.push(pair);
            }
        }
    }
    found.sort_unstable();
    pairs.extend(found);
}

/// Whether pooltool's ball–ball detector collides two balls (each its state and
/// [`detector_acceleration`]) at once: neither pocketed, not both without translation
/// (stationary or spinning), and their centres closer than the sum of their radii
/// (`is_overlapping`) or their accelerations the same to the bit (the leading coefficient of
/// its quartic 0; see [`ContactRule::Pooltool`]).
fn at_once(
    [(a, acc_a), (b, acc_b)]: [&(BallState, [f64; 2]); 2],
    [pa, pb]: [&BallParams; 2],
) -> bool {
    let out = |s: &BallState| s.motion == MotionState::Pocketed;
    let still = |s: &BallState| !s.motion.translates();
    if out(a) || out(b) || (still(a) && still(b)) {
        return false;
    }
    let d = a.position - b.position;
    // pooltool's norm3d: the heights are equal, so their difference adds an exact 0.
    let distance = (d.x * d.x + d.y * d.y + 0.0).sqrt();
    let (ax, ay) = (acc_b[0] - acc_a[0], acc_b[1] - acc_a[1]);
    distance < pa.radius + pb.radius || ax * ax + ay * ay == 0.0
}

/// A ball's acceleration `(a_x, a_y)` as pooltool's ball–ball detector forms it
/// (`ball_ball_collision_coeffs` with `get_u`), where only whether two balls' are the same to
/// the bit matters: `0` without translation; else `K·(u_0·cos φ − u_1·sin φ, u_0·sin φ +
/// u_1·cos φ)` with `φ` the velocity's angle (in `[0, 2π)`), `K = −½·μ·g` (`μ` the sliding
/// friction while sliding, else the rolling one) and `u` the unit slip turned by `−φ`
/// (`(1, 0)` while rolling or without slip).
fn detector_acceleration(state: &BallState, params: &BallParams) -> [f64; 2] {
    let mu = match state.motion {
        MotionState::Sliding => params.u_s,
        MotionState::Rolling => params.u_r,
        _ => return [0.0; 2],
    };
    let v = state.velocity;
    let angle = v.y.atan2(v.x) - 0.0f64.atan2(1.0);
    let phi = if angle < 0.0 {
        2.0 * std::f64::consts::PI + angle
    } else {
        angle
    };
    let (sin, cos) = (phi.sin(), phi.cos());
    let slip = slip_velocity(state, params.radius);
    let u = if state.motion == MotionState::Rolling || (slip.x == 0.0 && slip.y == 0.0) {
        [1.0, 0.0]
    } else {
        let n = (slip.x * slip.x + slip.y * slip.y + 0.0).sqrt();
        let (x, y) = (slip.x / n, slip.y / n);
        // The rotation by −φ: cos(−φ), sin(−φ) as pooltool's coordinate_rotation takes them.
        let (s, c) = ((-phi).sin(), (-phi).cos());
        [c * x + -s * y, s * x + c * y]
    };
    let k = -0.5 * mu * params.g;
    [k * (u[0] * cos - u[1] * sin), k * (u[0] * sin + u[1] * cos)]
}

/// The transition from motion state `before` to `after`, if one leads there.
fn transition_kind(before: MotionState, after: MotionState) -> Option<TransitionKind> {
    use MotionState::{Rolling, Sliding, Spinning, Stationary};
    match (before, after) {
        (Sliding, Rolling) => Some(TransitionKind::SlidingRolling),
        (Rolling, Spinning) => Some(TransitionKind::RollingSpinning),
        (Rolling, Stationary) => Some(TransitionKind::RollingStationary),
        (Spinning, Stationary) => Some(TransitionKind::SpinningStationary),
        _ => None,
    }
}

/// The error for a contact of ball `i` at `t` that its model could not resolve.
fn unresolved(i: usize, t: f64) -> InputError {
    InputError::new("balls", InputErrorKind::UnresolvedContact { time: t }).at(i)
}

/// Balls `indices` go on from `t` in `states`: their motions and the calendar's paths.
fn replace(
    calendar: &mut CollisionSchedule<2>,
    motions: &mut [BallPath],
    indices: &[usize],
    states: &[BallState],
    params: &[BallParams],
    t: f64,
) -> Result<(), InputError> {
    let mut paths = Vec::with_capacity(indices.len());
    for (&i, state) in indices.iter().zip(states) {
        let motion = ball_path(state, &params[i], t).map_err(|e| e.in_pair(i))?;
        paths.push(motion.path().clone());
        motions[i] = motion;
    }
    calendar.update(indices, paths)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::billiards::LinearCushion;
    use crate::geometry::SegmentSide;
    use nalgebra::{Vector2, Vector3};

    fn one_rail() -> BilliardTable {
        let rail = LinearCushion::new(Vector2::new(0.0, 1.0), Vector2::new(1.0, 1.0), 0.036576);
        BilliardTable {
            linear: vec![(rail, SegmentSide::Right)],
            ..Default::default()
        }
    }

    fn strike(ball: usize) -> ShotOptions {
        ShotOptions {
            strike: Some((ball, Cue::default())),
            ..Default::default()
        }
    }

    #[test]
    fn bad_input_is_an_error_naming_it() {
        let table = one_rail();
        let ball = [BallState::at_rest(Vector2::new(0.5, 0.5))];
        let params = [BallParams::default()];
        let run = |table: &BilliardTable, balls: &[BallState], params: &[BallParams], options| {
            simulate_shot(table, balls, params, &options).map(|_| ())
        };
        let err = run(&table, &ball, &[], strike(0)).unwrap_err();
        assert_eq!(err.argument(), "params");
        let err = run(&table, &ball, &params, strike(1)).unwrap_err();
        assert_eq!(
            (err.argument(), err.kind().code()),
            ("strike", "index_out_of_range")
        );
        let mut nan = ball;
        nan[0].velocity.y = f64::NAN;
        let err = run(&table, &nan, &params, ShotOptions::default()).unwrap_err();
        assert_eq!(
            (err.argument(), err.index(), err.segment()),
            ("velocity", Some(0), Some(1))
        );
        let slick = [BallParams {
            u_r: 0.0,
            ..BallParams::default()
        }];
        let err = run(&table, &ball, &slick, strike(0)).unwrap_err();
        assert_eq!(
            (err.argument(), err.kind()),
            ("max_events", InputErrorKind::Endless)
        );
        // Up to the rail, back, and rolling away for ever: the last state still moves.
        let up = ShotOptions {
            strike: Some((
                0,
                Cue {
                    phi: 90.0,
                    ..Cue::default()
                },
            )),
            max_events: Some(100),
            ..Default::default()
        };
        let shot = simulate_shot(&table, &ball, &slick, &up).unwrap();
        let kinds: Vec<_> = shot.events.iter().map(|e| e.kind.name()).collect();
        assert_eq!(
            kinds,
            [
                "stick_ball",
                "sliding_rolling",
                "ball_linear_cushion",
                "sliding_rolling"
            ]
        );
        assert_eq!(
            (shot.stopped, shot.states[0].motion),
            (false, MotionState::Rolling)
        );
        let shot = simulate_shot(
            &table,
            &ball,
            &slick,
            &ShotOptions {
                max_events: Some(3),
                ..up
            },
        )
        .unwrap();
        assert_eq!((shot.events.len(), shot.stopped), (3, true));
        let mut degenerate = one_rail();
        degenerate.linear[0].0.p2 = degenerate.linear[0].0.p1;
        let err = run(&degenerate, &ball, &params, strike(0)).unwrap_err();
        assert_eq!((err.argument(), err.index()), ("linear", Some(0)));
    }

    #[test]
    fn pooltools_detector_sees_equal_accelerations_by_the_velocitys_angle() {
        let params = BallParams::default();
        let rolling = |vx: f64, vy: f64| {
            let w = Vector3::new(-vy / params.radius, vx / params.radius, 0.0);
            BallState::new(
                Vector2::zeros(),
                Vector2::new(vx, vy),
                w,
                MotionState::Rolling,
            )
        };
        let along = detector_acceleration(&rolling(0.5, 0.0), &params);
        assert_eq!(along, detector_acceleration(&rolling(0.1, 0.0), &params));
        // Below the x axis by a rounding, the angle is 2π: the same bits as along it...
        let below = detector_acceleration(&rolling(0.1, -2e-18), &params);
        assert_eq!(below[0], along[0]);
        // ... above it, not.
        assert_ne!(detector_acceleration(&rolling(0.1, 7e-16), &params), along);
        let still = BallState::at_rest(Vector2::zeros());
        assert_eq!(detector_acceleration(&still, &params), [0.0; 2]);
    }

    #[test]
    fn a_ball_at_rest_has_no_events_and_a_pocketed_one_stays_out() {
        let table = one_rail();
        let params = [BallParams::default(); 2];
        let pocketed = BallState::new(
            Vector2::new(0.5, 0.5),
            Vector2::zeros(),
            Vector3::zeros(),
            MotionState::Pocketed,
        );
        let balls = [BallState::at_rest(Vector2::new(0.5, 0.2)), pocketed];
        // The struck ball runs through the pocketed one's spot to the rail.
        let options = ShotOptions {
            strike: Some((
                0,
                Cue {
                    phi: 90.0,
                    ..Cue::default()
                },
            )),
            ..Default::default()
        };
        let shot = simulate_shot(&table, &balls, &params, &options).unwrap();
        assert!(shot.events.iter().all(|e| e.balls == [0]));
        assert!(
            shot.events
                .iter()
                .any(|e| e.kind == ShotEventKind::LinearCushion(0))
        );
        assert_eq!(shot.states[1], pocketed);
        let still = simulate_shot(&table, &balls, &params, &ShotOptions::default()).unwrap();
        assert_eq!((still.events.len(), still.end), (0, 0.0));
        assert_eq!(still.states, balls);
    }
}
