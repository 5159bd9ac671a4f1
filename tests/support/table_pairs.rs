//! Sets of friction-ball pairs for the benchmarks ([`set`], in the batch layout of
//! [`Pairs`]): random table pairs, grazing shots, shots at a ball at rest, grazing chases.
//!
//! Included by path next to `rng.rs`, which it uses as `super::rng`:
//! `#[path = "../tests/support/rng.rs"] mod rng;` and
//! `#[path = "../tests/support/table_pairs.rs"] mod table_pairs;`. Not every includer uses
//! every kind.
#![allow(dead_code)]

use ballcollide::batch::{Pairs, PerPair};

use super::rng::Rng;

/// The contact distance: two pool balls of radius 28.575 mm.
pub const RADIUS: f64 = 2.0 * 0.028575;

/// A set of pairs, owned: ball A's and ball B's position, velocity and friction per pair.
pub struct Set {
    pub pos_a: Vec<[f64; 2]>,
    pub vel_a: Vec<[f64; 2]>,
    pub mu_a: Vec<f64>,
    pub pos_b: Vec<[f64; 2]>,
    pub vel_b: Vec<[f64; 2]>,
    pub mu_b: Vec<f64>,
}

impl Set {
    /// The set in the batch layout, at contact distance [`RADIUS`], without horizon.
    pub fn pairs(&self) -> Pairs<'_> {
        Pairs {
            pos_a: &self.pos_a,
            vel_a: &self.vel_a,
            friction_a: PerPair::Each(&self.mu_a),
            pos_b: &self.pos_b,
            vel_b: &self.vel_b,
            friction_b: PerPair::Each(&self.mu_b),
            contact_distance: PerPair::All(RADIUS),
            t_max: PerPair::All(f64::INFINITY),
        }
    }
}

/// The recipes of the sets.
#[derive(Clone, Copy)]
pub enum Kind {
    /// Both balls anywhere on a 2.54 × 1.27 m table, speeds 0–3 m/s, friction 0.05–2 m/s².
    RandomTable,
    /// B at rest, A aimed so that the closest approach is within 1e-2 … 1e-12 of the radius.
    Grazing,
    /// Cue ball (A) to an object ball at rest (B).
    AtRest,
    /// Both balls moving the same way with the same friction, A catching B up on a parallel
    /// track `radius·(1 ± 1e-2 … 1e-12)` aside, before B stops: grazing contacts that the
    /// general search (not the one-ball-at-rest closed form) has to settle.
    GrazingMoving,
}

/// `n` pairs of the given kind, drawn from `seed`.
pub fn set(kind: Kind, n: usize, seed: u64) -> Set {
    let mut rng = Rng(seed);
    let mut s = Set {
        pos_a: Vec::with_capacity(n),
        vel_a: Vec::with_capacity(n),
        mu_a: Vec::with_capacity(n),
        pos_b: Vec::with_capacity(n),
        vel_b: Vec::with_capacity(n),
        mu_b: Vec::with_capacity(n),
    };
    for _ in 0..n {
        let pa = [rng.uniform(0.0, 2.54), rng.uniform(0.0, 1.27)];
        let pb = [rng.uniform(0.0, 2.54), rng.uniform(0.0, 1.27)];
        let speed = rng.uniform(0.0, 3.0);
        let mu = rng.uniform(0.05, 2.0);
        let (pb, va, vb, mu, mu_b) = match kind {
            Kind::RandomTable => {
                let (ta, tb) = (rng.uniform(0.0, 6.3), rng.uniform(0.0, 6.3));
                let sb = rng.uniform(0.0, 3.0);
                (
                    pb,
                    [speed * ta.cos(), speed * ta.sin()],
                    [sb * tb.cos(), sb * tb.sin()],
                    mu,
                    rng.uniform(0.05, 2.0),
                )
            }
            Kind::GrazingMoving => {
                let angle = rng.uniform(0.0, 6.3);
                let (ux, uy) = (angle.cos(), angle.sin());
                let delta = 10f64.powf(rng.uniform(-12.0, -2.0));
                let side = if rng.uniform(0.0, 1.0) < 0.5 {
                    1.0
                } else {
                    -1.0
                };
                let aside = RADIUS * (1.0 + side * delta);
                let ahead = rng.uniform(2.0 * RADIUS, 0.5);
                let pb = [
                    pa[0] + ahead * ux - aside * uy,
                    pa[1] + ahead * uy + aside * ux,
                ];
                let (speed_b, closing) = (rng.uniform(0.5, 2.0), rng.uniform(0.5, 1.5));
                // The same deceleration; A reaches B (after about ahead/closing) before B stops.
                let mu = rng.uniform(0.05, 2.0f64.min(0.9 * speed_b * closing / ahead));
                let speed_a = speed_b + closing;
                (
                    pb,
                    [speed_a * ux, speed_a * uy],
                    [speed_b * ux, speed_b * uy],
                    mu,
                    mu,
                )
            }
            Kind::Grazing | Kind::AtRest => {
                let (dx, dy) = (pb[0] - pa[0], pb[1] - pa[1]);
                let dist = dx.hypot(dy).max(2.0 * RADIUS);
                let offset = match kind {
                    Kind::Grazing => {
                        let delta = 10f64.powf(rng.uniform(-12.0, -2.0));
                        RADIUS
                            * (1.0
                                + if rng.uniform(0.0, 1.0) < 0.5 {
                                    delta
                                } else {
                                    -delta
                                })
                    }
                    _ => rng.uniform(-1.5, 1.5) * RADIUS,
                };
                let angle = dy.atan2(dx) + (offset / dist).clamp(-1.0, 1.0).asin();
                // Fast enough to reach the target before stopping.
                let speed = (2.0 * mu * dist).sqrt() * rng.uniform(1.05, 2.0);
                (
                    pb,
                    [speed * angle.cos(), speed * angle.sin()],
                    [0.0, 0.0],
                    mu,
                    0.0,
                )
            }
        };
        s.pos_a.push(pa);
        s.vel_a.push(va);
        s.mu_a.push(mu);
        s.pos_b.push(pb);
        s.vel_b.push(vb);
        s.mu_b.push(mu_b);
    }
    s
}
