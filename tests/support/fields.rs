//! The numbers of one line of a reference table (`tests/data/*_cases.txt`), read in order:
//! shared by the reference tests that read paths and balls (included by path).

#![allow(dead_code)]

use ballcollide::Ball;
use ballcollide::path::{Path, Segment};
use nalgebra::SVector;

/// The numbers of a line after its leading words, and the line's number for messages.
pub struct Fields<'a> {
    pub line: usize,
    pub rest: std::slice::Iter<'a, &'a str>,
}

impl Fields<'_> {
    pub fn number(&mut self) -> f64 {
        let line = self.line;
        let f = self
            .rest
            .next()
            .unwrap_or_else(|| panic!("line {line}: too few fields"));
        f.parse()
            .unwrap_or_else(|_| panic!("line {line}: bad number {f}"))
    }

    pub fn count(&mut self) -> usize {
        self.number() as usize
    }

    pub fn vector<const D: usize>(&mut self) -> SVector<f64, D> {
        SVector::from_fn(|_, _| self.number())
    }

    /// A path of `k` segments, each `start, p, v, a`.
    pub fn path<const D: usize>(&mut self, k: usize) -> Path<D> {
        let segments = (0..k)
            .map(|_| {
                let start = self.number();
                let (p, v, a) = (self.vector(), self.vector(), self.vector());
                Segment::new(start, p, v, a)
            })
            .collect();
        Path::new(segments).unwrap_or_else(|e| panic!("line {}: {e}", self.line))
    }

    /// A friction ball: `p, v, friction` in 2-D.
    pub fn ball(&mut self) -> Ball {
        let (p, v) = (self.vector::<2>(), self.vector::<2>());
        let friction = self.number();
        Ball::new(p, v, friction).unwrap_or_else(|e| panic!("line {}: {e}", self.line))
    }
}
