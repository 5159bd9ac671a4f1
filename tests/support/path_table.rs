//! [`PathTable`]: paths stored as the batch functions' rows (`N` paths of `K` segments,
//! padded with `+∞` starts), built from [`Path`]s, for the benchmarks and the path invariants.
//!
//! Included by path: `#[path = "../tests/support/path_table.rs"] mod path_table;`.
#![allow(dead_code)]

use ballcollide::batch::PathRows;
use ballcollide::path::Path;

/// Rows of paths, owned: row `k` of path `i` at `i·segments + k` of every vector.
pub struct PathTable<const D: usize> {
    pub start: Vec<f64>,
    pub pos: Vec<[f64; D]>,
    pub vel: Vec<[f64; D]>,
    pub acc: Vec<[f64; D]>,
    /// `K`, the rows per path.
    pub segments: usize,
}

impl<const D: usize> PathTable<D> {
    /// An empty table of paths of up to `segments` segments.
    pub fn new(segments: usize) -> Self {
        Self {
            start: Vec::new(),
            pos: Vec::new(),
            vel: Vec::new(),
            acc: Vec::new(),
            segments,
        }
    }

    /// The table of `paths`, `segments` rows each.
    pub fn of<'p>(segments: usize, paths: impl IntoIterator<Item = &'p Path<D>>) -> Self {
        let mut table = Self::new(segments);
        for path in paths {
            table.push(path);
        }
        table
    }

    /// Appends `path`, padded to `K` rows with `+∞` starts (and zeros).
    ///
    /// # Panics
    /// If the path has more than `K` segments (a bug in the benchmark's set-up).
    pub fn push(&mut self, path: &Path<D>) {
        let segments = path.segments();
        assert!(segments.len() <= self.segments, "a path longer than K");
        for s in segments {
            self.start.push(s.start);
            self.pos.push(s.position.into());
            self.vel.push(s.velocity.into());
            self.acc.push(s.acceleration.into());
        }
        for _ in segments.len()..self.segments {
            self.start.push(f64::INFINITY);
            self.pos.push([0.0; D]);
            self.vel.push([0.0; D]);
            self.acc.push([0.0; D]);
        }
    }

    /// The table of paths `indices` of this one, in that order.
    pub fn pick(&self, indices: &[usize]) -> Self {
        let k = self.segments;
        let rows = || indices.iter().flat_map(|&i| i * k..(i + 1) * k);
        Self {
            start: rows().map(|r| self.start[r]).collect(),
            pos: rows().map(|r| self.pos[r]).collect(),
            vel: rows().map(|r| self.vel[r]).collect(),
            acc: rows().map(|r| self.acc[r]).collect(),
            segments: k,
        }
    }

    /// The number of paths.
    pub fn len(&self) -> usize {
        self.start.len() / self.segments
    }

    /// Path `i`'s used rows: `(start, position, velocity, acceleration)` per segment.
    pub fn rows(&self, i: usize) -> impl Iterator<Item = (f64, [f64; D], [f64; D], [f64; D])> {
        (i * self.segments..(i + 1) * self.segments)
            .filter(|&r| self.start[r] < f64::INFINITY)
            .map(|r| (self.start[r], self.pos[r], self.vel[r], self.acc[r]))
    }

    /// The table as one side of a batch.
    pub fn side(&self) -> PathRows<'_, D> {
        PathRows {
            start: &self.start,
            pos: &self.pos,
            vel: &self.vel,
            acc: &self.acc,
            segments: self.segments,
        }
    }
}
