//! An event calendar: the next collision among N balls on paths, kept up to date event by
//! event ([`CollisionSchedule`]).
//!
//! An event-driven simulation asks after every event which two balls touch next, changes the
//! paths of the balls the event involved, and asks again. The calendar answers from one
//! pending event per ball and recomputes, after an update, only the pairs of the balls it
//! changed; its answer is bit for bit that of recomputing every pair with
//! [`path_collision_time`](crate::path_collision_time).
//!
//! | concept | file | what it does |
//! |---|---|---|
//! | [`CollisionSchedule`] | `calendar.rs` | balls, current time, `next_collision`, `update` |
//! | pending-event queue | `queue.rs` | tournament tree of one key per ball |
//! | incremental broad phase | `grid.rs` | uniform grid of the balls' boxes |
//! | a ball's box | `reach.rs` | the box a ball covers over a span, with a rounding margin |
//! | [`Walls`] | `walls.rs` | an axis-aligned box and a ball's first wall contact |
//! | static objects | `objects.rs` | the table's objects in a grid of their own; a ball's first contact with those its box meets |
//! | [`Event`] | `event.rs` | what the calendar reports |
//! | [`simulate`] | `simulation.rs` | an event-driven simulation of friction balls in a box |
//!
//! ```
//! use ballcollide::Ball;
//! use ballcollide::schedule::{Collision, CollisionSchedule, ScheduleOptions};
//! use nalgebra::Vector2;
//!
//! let balls = [
//!     Ball::new(Vector2::zeros(), Vector2::new(1.0, 0.0), 0.0)?,
//!     Ball::at_rest(Vector2::new(1.0, 0.0))?,
//!     Ball::at_rest(Vector2::new(3.0, 0.0))?,
//! ];
//! let mut s = CollisionSchedule::from_balls(&balls, &[0.25; 3], 0.0, ScheduleOptions::default())?;
//! assert_eq!(s.next_collision(), Some(Collision { time: 0.5, i: 0, j: 1 }));
//! # Ok::<(), ballcollide::InputError>(())
//! ```

mod calendar;
mod event;
mod grid;
mod objects;
mod queue;
mod reach;
mod simulation;
mod walls;

pub use calendar::{CollisionSchedule, HeapBytes, ScheduleOptions, UPDATE_CHUNK};
// Re-exported from `path`, where it lives: the calendar's friction-ball
// constructors take balls that have it.
pub use crate::path::FrictionPath;
pub use event::{Collision, Event, ObjectEvent, Transition, WallContact};
pub use objects::ObjectCounts;
pub use simulation::{
    LoggedEvent, MAX_EVENTS_AT_ONE_INSTANT, Progress, Simulation, SimulationOptions, simulate,
    simulate_observed,
};
pub use walls::{Side, Walls};
