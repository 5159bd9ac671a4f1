//! Billiards with pooltool 0.6.0's physics: a ball's parameters and state, its motion through
//! sliding, rolling and spinning, and that motion as a [`Path2`](crate::Path2) for the
//! calendar.
//!
//! A billiard ball on the cloth is in one of pooltool's motion states ([`MotionState`]):
//! sliding (its contact point slips, and the cloth's friction acts against the slip), rolling,
//! spinning in place about the vertical, stationary, or pocketed. Each state ends at a time
//! known in closed form, and the next one follows ([`next_transition`]). Two balls that meet
//! are resolved by a [`BallBallResolver`] ([`FrictionalInelastic`], pooltool's default), a
//! ball and a cushion by a [`BallLinearCushionResolver`] or a [`BallCircularCushionResolver`],
//! a ball dropping into a [`Pocket`] by a [`BallPocketResolver`] ([`CanonicalBallPocket`]), and
//! the cue striking a ball by a [`StickBallResolver`] ([`InstantaneousPoint`], with squirt). The
//! functions here compute what pooltool's do, to the bit where the arithmetic can be the same
//! (the times, the roll, the spin, the placing of colliding balls and their friction), and to
//! a few roundings where pooltool's goes through rotations and BLAS (the slide, the
//! collision); `tests/reference/billiards.rs` checks them against pooltool's own functions on
//! thousands of cases (`tools/billiards_reference.py`).
//!
//! ## The map
//!
//! | file | what it holds |
//! |---|---|
//! | `params.rs` | [`BallParams`]: mass, radius, the frictions and restitutions, `g`, with pooltool's defaults |
//! | `state.rs` | [`BallState`] (position, velocity, angular velocity, motion state) and [`MotionState`] |
//! | `direction.rs` | lengths, unit vectors and cross products, with pooltool's arithmetic |
//! | `slip_velocity.rs` | [`slip_velocity`]: the contact point's velocity on the cloth (pooltool's `rel_velocity`) |
//! | `transition_time.rs` | [`slide_time`], [`roll_time`], [`spin_time`]: how long each state lasts |
//! | `transition.rs` | [`TransitionKind`], [`NextTransition`], [`next_transition`]: which state comes next, and when; [`TransitionKind::apply`] (pooltool's `CanonicalTransition`) |
//! | `evolve_spin.rs` | [`evolve_spin`]: the spin about the vertical decaying to 0 |
//! | `evolve_slide.rs` | [`evolve_slide`]: a sliding ball `t` later |
//! | `evolve_roll.rs` | [`evolve_roll`]: a rolling ball `t` later |
//! | `evolve.rs` | [`evolve`]: any state `t` later, through its transitions (pooltool's `evolve_ball_motion`) |
//! | `ball_ball.rs` | [`BallBallResolver`], the trait of ball–ball collision models, and the steps pooltool runs around each: [`make_kiss`], [`separate_touching`] |
//! | `frictional_inelastic.rs` | [`FrictionalInelastic`], pooltool's default ball–ball model, and its friction [`AlciatoreFriction`] |
//! | `cushion_linear.rs` | [`LinearCushion`], [`BallLinearCushionResolver`], the trait of straight-cushion models, and [`StrongeCompliantLinear`], pooltool's default |
//! | `cushion_circular.rs` | [`CircularCushion`], [`BallCircularCushionResolver`] and [`StrongeCompliantCircular`], the same for rounded cushions |
//! | `stronge.rs` | [`compliant_collinear_collision`]: Stronge's compliant frictional collision, in closed-form stick and slip phases, as pooltool solves it |
//! | `root.rs` | TOMS748 (Alefeld–Potra–Shi) ported from scipy step for step, for the two Stronge regimes where pooltool calls it |
//! | `ball_pocket.rs` | [`Pocket`], [`BallPocketResolver`], the trait of ball–pocket models, and [`CanonicalBallPocket`], pooltool's (the ball put still at the pocket's bottom) |
//! | `stick_ball.rs` | [`Cue`], [`CueSpecs`] (a stroke and the cue) and [`StickBallResolver`], the trait of stick–ball models |
//! | `instantaneous_point.rs` | [`InstantaneousPoint`], pooltool's stick–ball model, and its [`squirt_angle`] |
//! | `many.rs` | [`simulate_shots`]: many shots over threads ([`ShotSetup`]), taken one at a time, most balls first ([`simulate_shots_then`]: and what the caller makes of each, on its thread); [`shot_history`]: every ball's state at every event, as pooltool's histories ([`ShotHistory`]) |
//! | `ball_path.rs` | [`ball_path`], [`BallPath`]: the motion until the ball stops as constant-acceleration segments, with the state at each segment's start |
//! | `table.rs` | [`BilliardTable`]: straight and rounded cushions and pockets, as the calendar's table; [`side_of_direction`] (pooltool's cushion `direction`) |
//! | `shot.rs` | [`simulate_shot`]: pooltool's event loop on the calendar, from the cue's strike until every ball is at rest or pocketed ([`Shot`], [`ShotEvent`], [`ShotEventKind`], [`ShotOptions`], [`ShotResolvers`]) |
//!
//! ```
//! use ballcollide::billiards::{BallParams, BallState, MotionState, ball_path, evolve};
//! use nalgebra::{Vector2, Vector3};
//!
//! // A draw shot: 2 m/s with back spin. It slides on, its spin reversing, then rolls.
//! let params = BallParams::default();
//! let shot = BallState::new(Vector2::new(0.3, 0.6), Vector2::new(2.0, 0.0), Vector3::new(0.0, -100.0, 0.0), MotionState::Sliding);
//! let motion = ball_path(&shot, &params, 0.0)?;
//! let stages: Vec<_> = motion.states().iter().map(|s| s.motion).collect();
//! assert_eq!(stages, [MotionState::Sliding, MotionState::Rolling, MotionState::Stationary]);
//! let t = 0.4; // rolling by then
//! let by_path = motion.path().position_at(t);
//! assert!((by_path - evolve(&shot, &params, t).position).norm() < 1e-15);
//! # Ok::<(), ballcollide::InputError>(())
//! ```

mod ball_ball;
mod ball_path;
mod ball_pocket;
mod cushion_circular;
mod cushion_linear;
mod direction;
mod evolve;
mod evolve_roll;
mod evolve_slide;
mod evolve_spin;
mod frictional_inelastic;
mod instantaneous_point;
mod many;
mod params;
mod root;
mod shot;
mod slip_velocity;
mod state;
mod stick_ball;
mod stronge;
mod table;
mod transition;
mod transition_time;

pub use ball_ball::{BallBallResolver, KISS_SPACER, make_kiss, separate_touching};
pub use ball_path::{BallPath, ball_path};
pub use ball_pocket::{BallPocketResolver, CanonicalBallPocket, Pocket};
pub use cushion_circular::{
    BallCircularCushionResolver, CircularCushion, StrongeCompliantCircular, kiss_circular_cushion,
};
pub use cushion_linear::{
    BallLinearCushionResolver, LinearCushion, StrongeCompliantLinear, kiss_linear_cushion,
};
pub use evolve::evolve;
pub use evolve_roll::evolve_roll;
pub use evolve_slide::evolve_slide;
pub use evolve_spin::evolve_spin;
pub use frictional_inelastic::{AlciatoreFriction, FrictionalInelastic};
pub use instantaneous_point::{InstantaneousPoint, squirt_angle};
pub use many::{ShotHistory, ShotSetup, shot_history, simulate_shots, simulate_shots_then};
pub use params::BallParams;
pub use shot::{
    ContactRule, Shot, ShotEvent, ShotEventKind, ShotOptions, ShotResolvers, simulate_shot,
};
pub use slip_velocity::slip_velocity;
pub use state::{BallState, MotionState};
pub use stick_ball::{Cue, CueSpecs, StickBallResolver};
pub use stronge::compliant_collinear_collision;
pub use table::{BilliardTable, side_of_direction};
pub use transition::{NextTransition, TransitionKind, next_transition};
pub use transition_time::{roll_time, slide_time, spin_time};
