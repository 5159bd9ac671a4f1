//! Random path rows for the batch tests, from one generator: `n` paths of `segments` rows each
//! (`start`, `pos`, `vel`, `acc`, as the batch arrays hold them), drawn as a [`RowSpec`]
//! says. Each test states its own spec (a table's positions and speeds, the shapes the lanes
//! take, rows padded with `+∞` starts, scaled rows); the draws are the same kinds of numbers
//! from the same ranges whoever asks.
//!
//! Included by path in the library's unit tests (`src/lib.rs`) and in the test binaries
//! (`tests/support/mod.rs`); it names its sibling `super::rng`.
#![allow(dead_code)]

use super::rng::Rng;

/// The rows of `n` paths: the starts, and the positions, velocities and accelerations.
pub type Rows<const D: usize> = (Vec<f64>, [Vec<[f64; D]>; 3]);

/// What a test's path rows look like.
#[derive(Clone, Copy, Debug)]
pub struct RowSpec<const D: usize> {
    /// Rows per path.
    pub segments: usize,
    /// Every row used; else `1..=segments` of them (uniformly), the rest padding (`+∞`
    /// starts, their other values drawn all the same).
    pub every_row_used: bool,
    /// How often the first start is drawn from `first_start`, else it is 0.
    pub later_first_start: f64,
    /// The range of a first start that is drawn.
    pub first_start: [f64; 2],
    /// The range of a segment's length (the next start minus its own).
    pub length: [f64; 2],
    /// How often a segment is empty (length 0; the next row starts where it does).
    pub empty: f64,
    /// Each axis's range of a path's positions: of every row's, or (`continuous`) of the first
    /// row's, the others then where the motion before them ends.
    pub pos: [[f64; 2]; D],
    /// Whether a row starts where the one before it ends (else every position is drawn).
    pub continuous: bool,
    /// Each axis's range of the velocities.
    pub vel: [[f64; 2]; D],
    /// Each axis's range of the accelerations.
    pub acc: [[f64; 2]; D],
    /// How often the last used row is at rest (zero velocity and acceleration).
    pub last_at_rest: f64,
}

impl<const D: usize> RowSpec<D> {
    /// Every axis in `[lo, hi)`.
    pub fn each_axis(lo: f64, hi: f64) -> [[f64; 2]; D] {
        [[lo, hi]; D]
    }

    /// `n` paths' rows.
    pub fn draw(&self, rng: &mut Rng, n: usize) -> Rows<D> {
        let k = self.segments;
        let (mut start, mut pos, mut vel, mut acc) = (vec![], vec![], vec![], vec![]);
        let chance = |rng: &mut Rng, p: f64| p > 0.0 && rng.uniform(0.0, 1.0) < p;
        let vector = |rng: &mut Rng, ranges: &[[f64; 2]; D]| -> [f64; D] {
            std::array::from_fn(|i| rng.uniform(ranges[i][0], ranges[i][1]))
        };
        for _ in 0..n {
            let used = if self.every_row_used {
                k
            } else {
                1 + rng.below(k as u64) as usize
            };
            let mut t = if chance(rng, self.later_first_start) {
                rng.uniform(self.first_start[0], self.first_start[1])
            } else {
                0.0
            };
            let mut p = vector(rng, &self.pos);
            for row in 0..k {
                let at_rest = row + 1 == used && chance(rng, self.last_at_rest);
                if row > 0 && !self.continuous {
                    p = vector(rng, &self.pos);
                }
                let (v, a) = if at_rest {
                    ([0.0; D], [0.0; D])
                } else {
                    (vector(rng, &self.vel), vector(rng, &self.acc))
                };
                let length = if chance(rng, self.empty) {
                    0.0
                } else {
                    rng.uniform(self.length[0], self.length[1])
                };
                start.push(if row < used { t } else { f64::INFINITY });
                pos.push(p);
                vel.push(v);
                acc.push(a);
                if self.continuous {
                    for i in 0..D {
                        p[i] += (v[i] + 0.5 * a[i] * length) * length;
                    }
                }
                t += length;
            }
        }
        (start, [pos, vel, acc])
    }
}
