//! Billiard balls as paths, built as pooltool builds its balls' motion: a [`PoolBall`]'s state
//! (position, velocity, spin) becomes a path that slides, rolls and rests ([`PoolBall::path`]);
//! random balls on a table ([`PoolBall::random`]) and the rack of a break ([`rack`]).
//!
//! Included by path next to `rng.rs`, which it uses as `super::rng`:
//! `#[path = "../tests/support/pool_balls.rs"] mod pool_balls;`.
#![allow(dead_code)]

use ballcollide::path::{Path2, Segment2};
use nalgebra::Vector2;

use super::rng::Rng;

/// Ball radius (m); two balls touch at `2·BALL_RADIUS`.
pub const BALL_RADIUS: f64 = 0.028575;
/// Sliding friction coefficient.
pub const U_SLIDE: f64 = 0.2;
/// Rolling friction coefficient.
pub const U_ROLL: f64 = 0.01;
/// Gravity (m/s²).
pub const GRAVITY: f64 = 9.81;
/// The playing area of a 9-ft table (m).
pub const TABLE: [f64; 2] = [2.54, 1.27];

/// A ball's state on the cloth at time 0.
#[derive(Clone, Copy, Debug)]
pub struct PoolBall {
    /// Centre (m).
    pub position: [f64; 2],
    /// Velocity (m/s).
    pub velocity: [f64; 2],
    /// The angular velocity's components in the plane, `(ωx, ωy)` (rad/s): the ones that make
    /// the contact point slip (`ωz` does not change a path in the plane).
    pub spin: [f64; 2],
}

impl PoolBall {
    /// A ball at rest at `position`.
    pub fn at_rest(position: [f64; 2]) -> Self {
        Self {
            position,
            velocity: [0.0; 2],
            spin: [0.0; 2],
        }
    }

    /// A random ball: anywhere on the table, speed uniform in 0–3 m/s in a random direction,
    /// and each spin component uniform in ±(3 m/s)/R, so that the slip is as fast as the ball
    /// and points any way.
    pub fn random(rng: &mut Rng) -> Self {
        let position = [rng.uniform(0.0, TABLE[0]), rng.uniform(0.0, TABLE[1])];
        let (speed, angle) = (
            rng.uniform(0.0, 3.0),
            rng.uniform(0.0, std::f64::consts::TAU),
        );
        let w = 3.0 / BALL_RADIUS;
        Self {
            position,
            velocity: [speed * angle.cos(), speed * angle.sin()],
            spin: [rng.uniform(-w, w), rng.uniform(-w, w)],
        }
    }

    /// The ball's motion from time 0 as pooltool models it, each segment's start values
    /// computed in float64 from the segment before:
    /// 1. sliding while the contact point slips, `u = v + ω × (−R ẑ) = (vx − R·ωy, vy + R·ωx)`:
    ///    acceleration `−u_s·g·û` for `2|u|/(7·u_s·g)`;
    /// 2. rolling: `−u_r·g·v̂` for `|v|/(u_r·g)`;
    /// 3. at rest.
    ///
    /// A ball without slip skips the slide, a ball without velocity after it the roll.
    pub fn path(&self) -> Path2 {
        let (slide, roll) = (U_SLIDE * GRAVITY, U_ROLL * GRAVITY);
        let mut segments = Vec::with_capacity(3);
        let (mut t, mut p, mut v) = (
            0.0,
            Vector2::from(self.position),
            Vector2::from(self.velocity),
        );
        let slip = Vector2::new(
            v.x - BALL_RADIUS * self.spin[1],
            v.y + BALL_RADIUS * self.spin[0],
        );
        let mut advance =
            |a: Vector2<f64>, tau: f64, p: &mut Vector2<f64>, v: &mut Vector2<f64>| {
                segments.push(Segment2::new(t, *p, *v, a));
                *p += *v * tau + a * (0.5 * tau * tau);
                *v += a * tau;
                t += tau;
            };
        let u = slip.norm();
        if u > 0.0 {
            advance(-slip * (slide / u), 2.0 * u / (7.0 * slide), &mut p, &mut v);
        }
        let speed = v.norm();
        if speed > 0.0 {
            advance(-v * (roll / speed), speed / roll, &mut p, &mut v);
        }
        segments.push(Segment2::at_rest(t, p));
        Path2::new(segments).expect("a pool ball's path is valid")
    }
}

/// The 15 balls of a rack, touching, apex at (1.9, 0.635), rows of 1 … 5 towards +x.
pub fn rack() -> Vec<[f64; 2]> {
    let d = 2.0 * BALL_RADIUS;
    (0..5)
        .flat_map(|row| {
            (0..=row).map(move |k| {
                [
                    1.9 + row as f64 * d * 3f64.sqrt() / 2.0,
                    0.635 + (k as f64 - row as f64 / 2.0) * d,
                ]
            })
        })
        .collect()
}

/// Where the cue ball is placed for a break.
pub const CUE_SPOT: [f64; 2] = [0.635, 0.64];
