//! [`simulate`]: an event-driven simulation of smooth hard friction balls in a box, on the
//! calendar.
//!
//! Each ball is a friction [`Ball`] (slowed along its velocity until it stops; no friction,
//! and it moves straight on). At each event, in the calendar's order:
//! - two balls touch: momentum is exchanged along the line of centres `n` with the
//!   restitution `e` and the masses: `J = −(1 + e)·(Δv·n) / (1/m_i + 1/m_j)`,
//!   `v_i += J/m_i·n`, `v_j −= J/m_j·n` (the tangential components are kept: smooth balls);
//! - a ball touches a wall: its velocity's component normal to the wall is reflected;
//!
//! and the balls involved get new friction paths from the event's time. It runs until
//! `t_end`, `max_events` or until no event is left (every ball at rest, or moving away for
//! ever).

use super::calendar::{CollisionSchedule, ScheduleOptions};
use super::event::Event;
use super::walls::{Side, Walls};
use crate::error::{InputError, InputErrorKind, check_horizon, finite};
use crate::motion::Ball;
use nalgebra::Vector2;

/// Options of [`simulate`].
///
/// ```
/// use ballcollide::schedule::SimulationOptions;
/// let options = SimulationOptions { restitution: 0.9, ..Default::default() };
/// assert_eq!(options.max_events, None);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct SimulationOptions {
    /// Each ball's mass (one for all if a single value). Default `[1]`.
    pub mass: Vec<f64>,
    /// The coefficient of restitution of ball–ball collisions, in `[0, 1]`. Default 1.
    pub restitution: f64,
    /// The simulation ends at this time. Default `∞`.
    pub t_end: f64,
    /// The simulation ends after this many events. Default none.
    pub max_events: Option<usize>,
}

impl Default for SimulationOptions {
    fn default() -> Self {
        Self {
            mass: vec![1.0],
            restitution: 1.0,
            t_end: f64::INFINITY,
            max_events: None,
        }
    }
}

/// One event of a simulation's log: balls `i` and `j` collide at `time`, or ball `i` touches
/// a wall (`j = None`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LoggedEvent {
    /// When.
    pub time: f64,
    /// The (lower) ball.
    pub i: usize,
    /// The other ball, `None` for a wall.
    pub j: Option<usize>,
}

/// What [`simulate`] returns: the event log and the final state.
#[derive(Clone, Debug, PartialEq)]
pub struct Simulation {
    /// The events, in order.
    pub events: Vec<LoggedEvent>,
    /// The time of the final state: `t_end` if finite and reached; else the time of the last
    /// event (`max_events`), or the time every ball is at rest (no event left; `0`, the start,
    /// if some ball moves away for ever).
    pub end: f64,
    /// The balls at `end`.
    pub balls: Vec<Ball>,
}

/// Simulates friction balls of `radii` in the box `walls` from time 0 (see the module
/// documentation).
///
/// # Errors
/// An [`InputError`]: a bad radius or mass (`mass[i]`, finite and `> 0`, one or one per
/// ball), a restitution outside `[0, 1]`, a NaN `t_end`; no `t_end`, no `max_events` and a
/// ball without friction (it would never end).
///
/// ```
/// use ballcollide::Ball;
/// use ballcollide::schedule::{SimulationOptions, Walls, simulate};
/// use nalgebra::Vector2;
///
/// // A ball at 1 m/s towards a resting one, in a 4 m × 1 m box: equal masses swap velocities.
/// let balls = [Ball::new(Vector2::new(0.5, 0.5), Vector2::new(1.0, 0.0), 0.0)?, Ball::at_rest(Vector2::new(2.0, 0.5))?];
/// let walls = Walls::new([0.0, 0.0], [4.0, 1.0])?;
/// let options = SimulationOptions { t_end: 3.0, ..Default::default() };
/// let run = simulate(&balls, &[0.25, 0.25], walls, &options)?;
/// assert_eq!((run.events[0].time, run.events[0].i, run.events[0].j), (1.0, 0, Some(1)));
/// assert_eq!((run.events[1].time, run.events[1].i, run.events[1].j), (2.75, 1, None));
/// assert_eq!(run.balls[0].velocity(), Vector2::zeros());
/// assert_eq!(run.balls[1].position(), Vector2::new(3.5, 0.5)); // back from the wall at 3.75
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn simulate(
    balls: &[Ball],
    radii: &[f64],
    walls: Walls<2>,
    options: &SimulationOptions,
) -> Result<Simulation, InputError> {
    let n = balls.len();
    let masses = masses(&options.mass, n)?;
    let e = options.restitution;
    if !(0.0..=1.0).contains(&e) {
        return Err(InputError::new(
            "restitution",
            InputErrorKind::NotInUnitInterval(e),
        ));
    }
    let t_end = check_horizon("t_end", options.t_end)?;
    let endless = t_end == f64::INFINITY
        && options.max_events.is_none()
        && balls.iter().any(|b| b.friction() == 0.0 && !b.is_at_rest());
    if endless {
        return Err(InputError::new("t_end", InputErrorKind::Endless));
    }
    let calendar_options = ScheduleOptions {
        walls: Some(walls),
        t_max: t_end,
    };
    let mut calendar = CollisionSchedule::<2>::from_balls(balls, radii, 0.0, calendar_options)?;
    let mut events = Vec::new();
    let max_events = options.max_events.unwrap_or(usize::MAX);
    let mut end = 0.0;
    while events.len() < max_events {
        let Some(event) = calendar.next_event() else {
            break;
        };
        let t = event.time();
        end = t;
        match event {
            Event::Collision(c) => {
                let (a, b) = (at(&calendar, c.i, t), at(&calendar, c.j, t));
                let (va, vb) = collide(a, b, masses.get(c.i), masses.get(c.j), e);
                let new = [
                    Ball::from_checked(a.0.into(), va.into(), balls[c.i].friction()),
                    Ball::from_checked(b.0.into(), vb.into(), balls[c.j].friction()),
                ];
                calendar.update_balls(&[c.i, c.j], t, &new)?;
                events.push(LoggedEvent {
                    time: t,
                    i: c.i,
                    j: Some(c.j),
                });
            }
            Event::Wall(w) => {
                let (p, mut v) = at(&calendar, w.ball, t);
                v[w.axis] = match w.side {
                    Side::Low => v[w.axis].abs(),
                    Side::High => -v[w.axis].abs(),
                };
                let new = [Ball::from_checked(
                    p.into(),
                    v.into(),
                    balls[w.ball].friction(),
                )];
                calendar.update_balls(&[w.ball], t, &new)?;
                events.push(LoggedEvent {
                    time: t,
                    i: w.ball,
                    j: None,
                });
            }
        }
    }
    let no_event_left = events.len() < max_events;
    if no_event_left {
        end = if t_end.is_finite() {
            t_end
        } else {
            // At rest from the last stop on.
            (0..n)
                .map(|i| calendar.path(i).segments().last().map_or(0.0, |s| s.start))
                .fold(end, f64::max)
        };
    }
    let balls = (0..n)
        .map(|i| {
            let (p, v) = at(&calendar, i, end);
            Ball::from_checked(p.into(), v.into(), balls[i].friction())
        })
        .collect();
    Ok(Simulation { events, end, balls })
}

/// Ball `i`'s centre and velocity at `t`, from its path.
fn at(calendar: &CollisionSchedule<2>, i: usize, t: f64) -> (Vector2<f64>, Vector2<f64>) {
    let path = calendar.path(i);
    (path.position_at(t), path.velocity_at(t))
}

/// The velocities after a collision of balls `a` and `b` (centre, velocity) of masses `ma`,
/// `mb` with restitution `e`; unchanged if they do not approach along the line of centres.
fn collide(
    a: (Vector2<f64>, Vector2<f64>),
    b: (Vector2<f64>, Vector2<f64>),
    ma: f64,
    mb: f64,
    e: f64,
) -> (Vector2<f64>, Vector2<f64>) {
    let d = a.0 - b.0;
    let distance = d.norm();
    if distance.is_nan() || distance <= 0.0 {
        return (a.1, b.1);
    }
    let n = d / distance;
    let approach = (a.1 - b.1).dot(&n);
    if approach >= 0.0 {
        return (a.1, b.1);
    }
    // Each ball's share of the change of relative velocity, m_b/(m_a + m_b) and
    // m_a/(m_a + m_b) (the impulse over each mass), from the mass ratio: in [0, 1] for any
    // masses from 5e-324 to f64::MAX, where 1/m and m_a + m_b overflow; ½ exactly for equal
    // masses.
    let share_a = 1.0 / (1.0 + ma / mb);
    let share_b = 1.0 / (1.0 + mb / ma);
    let change = -(1.0 + e) * approach;
    (a.1 + n * (change * share_a), b.1 - n * (change * share_b))
}

/// The masses: one for all, or one per ball; each finite and `> 0`.
fn masses(mass: &[f64], n: usize) -> Result<PerBall<'_>, InputError> {
    if mass.len() != 1 && mass.len() != n {
        let kind = InputErrorKind::LengthMismatch {
            expected: n,
            found: mass.len(),
        };
        return Err(InputError::new("mass", kind));
    }
    for (i, &m) in mass.iter().enumerate() {
        finite("mass", m).map_err(|e| e.at(i))?;
        if m <= 0.0 {
            return Err(InputError::new("mass", InputErrorKind::NonPositiveMass(m)).at(i));
        }
    }
    Ok(PerBall(mass))
}

/// One value for all balls, or one per ball.
struct PerBall<'a>(&'a [f64]);

impl PerBall<'_> {
    fn get(&self, i: usize) -> f64 {
        if self.0.len() == 1 {
            self.0[0]
        } else {
            self.0[i]
        }
    }
}
