//! The broad phase: swept bounding boxes, and a sort-and-sweep over them in strips.
//!
//! Until the horizon, a ball's centre stays on a straight segment: from `p` to its rest point
//! `p + ½·v·τ` under friction, to `p + v·t_max` for a frictionless ball with a finite horizon,
//! along a ray for a frictionless ball without one, and at `p` for a ball at rest. The
//! segment's axis-aligned box, inflated by the ball's radius and a rounding margin, contains
//! every point the ball's disc covers before the horizon; two balls whose inflated boxes are
//! disjoint can never touch, and the pair kernel is not run on them.
//!
//! ## The rounding margin
//!
//! The boxes' corners are computed in floating point, and the pair kernel evaluates the gap
//! `|d(t)|² − radius²` from float coefficients: it may report a contact for a pair whose exact
//! closest approach exceeds the contact distance by a rounding error of order
//! `ε·(S + D²/r)`, where `S` is the largest coordinate, `D` the diameter of the scene's finite
//! box corners and `r` the smallest contact distance. Every box is inflated by
//! [`MARGIN_ULPS`]` · ε · (S + D²/r_min)` on top of its radius, far more than that error, so
//! that a pair the kernel would report is never pruned: the broad phase changes the work, never
//! the answer. On a pool table (`S ≈ 2.5 m`, `r ≈ 0.057 m`) the margin is about 5e-11 m.

use nalgebra::Vector2;
use rayon::prelude::*;

use crate::motion::Ball;

/// Safety factor of the rounding margin, in units of `ε·(S + D²/r_min)`.
pub(crate) const MARGIN_ULPS: f64 = 1024.0;

/// An axis-aligned box `[lo, hi]` per axis (bounds may be infinite).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Aabb {
    pub lo: [f64; 2],
    pub hi: [f64; 2],
}

impl Aabb {
    fn overlaps_on(&self, other: &Self, axis: usize) -> bool {
        self.lo[axis] <= other.hi[axis] && other.lo[axis] <= self.hi[axis]
    }
}

/// The segment a ball's centre sweeps over `[0, t_max)`: `(start, end)`, where an infinite
/// end coordinate stands for a ray that runs off in that direction.
fn swept_segment(ball: &Ball, t_max: f64) -> (Vector2<f64>, Vector2<f64>) {
    let p = ball.position();
    let until = ball.stop_time().min(t_max);
    if until.is_finite() {
        // A friction ball's rest point, or a frictionless ball's position at the horizon.
        (p, ball.position_at(until))
    } else {
        // A frictionless ray: unbounded in the directions it moves, exactly constant in a
        // coordinate whose velocity is zero.
        let v = ball.velocity();
        let run = |x: f64, vx: f64| {
            if vx > 0.0 {
                f64::INFINITY
            } else if vx < 0.0 {
                f64::NEG_INFINITY
            } else {
                x
            }
        };
        (p, Vector2::new(run(p.x, v.x), run(p.y, v.y)))
    }
}

/// The inflated swept boxes of all balls (`radii` validated, same length as `balls`).
pub(crate) fn swept_boxes(balls: &[Ball], radii: &[f64], t_max: f64) -> Vec<Aabb> {
    let segments: Vec<_> = balls.iter().map(|b| swept_segment(b, t_max)).collect();
    let margin = margin(&segments, radii);
    segments
        .iter()
        .zip(radii)
        .map(|((a, b), &r)| {
            let grow = r + margin;
            Aabb {
                lo: [a.x.min(b.x) - grow, a.y.min(b.y) - grow],
                hi: [a.x.max(b.x) + grow, a.y.max(b.y) + grow],
            }
        })
        .collect()
}

/// The rounding margin `MARGIN_ULPS · ε · (S + D²/r_min)` (see the module documentation);
/// `∞` when it overflows, which only disables pruning.
fn margin(segments: &[(Vector2<f64>, Vector2<f64>)], radii: &[f64]) -> f64 {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    let mut largest = 0.0_f64;
    for (a, b) in segments {
        for point in [a, b] {
            for axis in 0..2 {
                let x = point[axis];
                if x.is_finite() {
                    lo[axis] = lo[axis].min(x);
                    hi[axis] = hi[axis].max(x);
                    largest = largest.max(x.abs());
                }
            }
        }
    }
    let diameter = (0..2)
        .map(|axis| (hi[axis] - lo[axis]).max(0.0))
        .fold(0.0, f64::max);
    // The smallest contact distance is at least twice the smallest radius.
    let r_min = 2.0 * radii.iter().copied().fold(f64::INFINITY, f64::min);
    if !(r_min.is_finite() && r_min > 0.0) {
        return 0.0; // fewer than one ball: nothing to prune
    }
    // D·(D/r), not D²/r: the same number where neither overflows nor underflows, and no
    // square that underflows to 0 at the small end of the float range (where it would drop
    // the margin below the kernel's rounding error).
    MARGIN_ULPS * f64::EPSILON * (largest + diameter * (diameter / r_min))
}

/// The axis along which the balls' start positions spread the most (ties: x).
fn sweep_axis(balls: &[Ball]) -> usize {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for b in balls {
        let p = b.position();
        for axis in 0..2 {
            lo[axis] = lo[axis].min(p[axis]);
            hi[axis] = hi[axis].max(p[axis]);
        }
    }
    // Differences of finite numbers: at worst +∞, never NaN (with at least one ball).
    if hi[1] - lo[1] > hi[0] - lo[0] { 1 } else { 0 }
}

/// From this many strip entries on, the strips are sorted in parallel.
const PARALLEL_SORT_FROM: usize = 1 << 14;

/// At most this many strip entries per ball on average: a scene whose boxes are so tall that
/// they would cross more strips gets fewer, taller strips (down to one, a plain sweep).
const ENTRIES_PER_BALL: usize = 16;

/// The sort-and-sweep structure. The cross axis is cut into strips about as high as a typical
/// box; each box is listed in every strip it crosses, and each strip is swept along the sweep
/// axis. A pair is reported only in the lowest strip the two boxes share, so once. With strips,
/// a ball meets in its sweep only the boxes of its own strips: the work grows as `N log N` (the
/// sort) plus the overlapping pairs, where a single sweep would scan `O(N^1.5)` boxes on a
/// table of constant density.
pub(crate) struct Sweep {
    boxes: Vec<Aabb>,
    /// Sorted by strip, then by the box's lower bound on the sweep axis.
    entries: Vec<Entry>,
    /// Each ball's lowest strip.
    first_strip: Vec<usize>,
    axis: usize,
}

impl Sweep {
    /// Boxes of `balls` (validated `radii`, same length) and their order along the sweep axis;
    /// `parallel`: whether large sorts may use rayon's current pool.
    pub(crate) fn new(balls: &[Ball], radii: &[f64], t_max: f64, parallel: bool) -> Self {
        let boxes = swept_boxes(balls, radii, t_max);
        let axis = sweep_axis(balls);
        let strips = Strips::fit(balls, &boxes, 1 - axis);
        // Bucket the entries by strip (counting sort), then sort each strip by lower bound.
        let spans: Vec<(usize, usize)> = boxes.iter().map(|b| strips.span(b)).collect();
        let mut start = vec![0usize; strips.count + 1];
        for &(lo, hi) in &spans {
            for s in lo..=hi {
                start[s + 1] += 1;
            }
        }
        for s in 0..strips.count {
            start[s + 1] += start[s];
        }
        let mut fill = start.clone();
        let empty = Entry {
            lo: 0.0,
            ball: 0,
            strip: 0,
        };
        let mut entries = vec![empty; start[strips.count]];
        for (ball, &(lo, hi)) in spans.iter().enumerate() {
            for s in lo..=hi {
                entries[fill[s]] = Entry {
                    lo: boxes[ball].lo[axis],
                    // Both fit in 32 bits: larger scenes go to all pairs, strips are fewer.
                    ball: ball as u32,
                    strip: s as u32,
                };
                fill[s] += 1;
            }
        }
        let entries_len = entries.len();
        let mut rest = entries.as_mut_slice();
        let mut buckets = Vec::with_capacity(strips.count);
        for s in 0..strips.count {
            let (bucket, tail) = rest.split_at_mut(start[s + 1] - start[s]);
            buckets.push(bucket);
            rest = tail;
        }
        // Bounds are never NaN; the ball index makes the order total.
        let sort = |bucket: &mut &mut [Entry]| {
            bucket.sort_unstable_by(|x, y| x.lo.total_cmp(&y.lo).then(x.ball.cmp(&y.ball)));
        };
        // Small scenes stay on the calling thread: waking the pool costs more than the sort.
        if !parallel || entries_len < PARALLEL_SORT_FROM {
            buckets.iter_mut().for_each(sort);
        } else {
            buckets.par_iter_mut().with_min_len(16).for_each(sort);
        }
        let first_strip = spans.iter().map(|&(lo, _)| lo).collect();
        Self {
            boxes,
            entries,
            first_strip,
            axis,
        }
    }

    /// Number of strip entries (the ranks [`Sweep::for_each_after`] takes).
    pub(crate) fn len(&self) -> usize {
        self.entries.len()
    }

    /// Calls `visit(i, j)` with `i < j` for every pair whose boxes overlap, where one of the
    /// two is the entry at `rank` and the other comes later in its strip, and that strip is the
    /// lowest the two share. Over all ranks, every overlapping pair is visited exactly once.
    pub(crate) fn for_each_after(&self, rank: usize, mut visit: impl FnMut(usize, usize)) {
        let (axis, other) = (self.axis, 1 - self.axis);
        let Entry { strip, ball, .. } = self.entries[rank];
        let i = ball as usize;
        let bi = &self.boxes[i];
        for e in &self.entries[rank + 1..] {
            if e.strip != strip || e.lo > bi.hi[axis] {
                break; // sorted by lower bound: no later box of this strip reaches back
            }
            let j = e.ball as usize;
            let strip = strip as usize;
            let bj = &self.boxes[j];
            if bi.overlaps_on(bj, other) && strip == self.first_strip[i].max(self.first_strip[j]) {
                visit(i.min(j), i.max(j));
            }
        }
    }
}

/// One box in one strip.
#[derive(Clone, Copy, Debug)]
struct Entry {
    /// The box's lower bound on the sweep axis.
    lo: f64,
    ball: u32,
    strip: u32,
}

/// Equal strips `[y0 + k·h, y0 + (k+1)·h)` across an axis; values beyond either end belong to
/// the end strips.
struct Strips {
    y0: f64,
    height: f64,
    count: usize,
    axis: usize,
}

impl Strips {
    /// Strips about as high as the median box, over the spread of the start positions, with
    /// at most [`ENTRIES_PER_BALL`] entries per ball on average.
    fn fit(balls: &[Ball], boxes: &[Aabb], axis: usize) -> Self {
        let one = Self {
            y0: 0.0,
            height: f64::INFINITY,
            count: 1,
            axis,
        };
        let n = balls.len();
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for b in balls {
            lo = lo.min(b.position()[axis]);
            hi = hi.max(b.position()[axis]);
        }
        let mut heights: Vec<f64> = boxes
            .iter()
            .map(|b| b.hi[axis] - b.lo[axis])
            .filter(|h| h.is_finite())
            .collect();
        if heights.is_empty() || n < 2 {
            return one;
        }
        let middle = heights.len() / 2;
        let (_, &mut median, _) = heights.select_nth_unstable_by(middle, f64::total_cmp);
        let spread = hi - lo;
        if !(spread.is_finite() && median > 0.0 && spread > median) {
            return one;
        }
        // Ceiling of spread/median, at most 4√N strips (a few balls per strip at least).
        let cap = 4 * (n as f64).sqrt() as usize + 1;
        let mut count = ((spread / median).ceil() as usize).clamp(1, cap);
        loop {
            let strips = Self {
                y0: lo,
                height: spread / count as f64,
                count,
                axis,
            };
            if count == 1 {
                return one;
            }
            let entries: usize = boxes
                .iter()
                .map(|b| {
                    let (a, z) = strips.span(b);
                    z - a + 1
                })
                .sum();
            if entries <= ENTRIES_PER_BALL * n {
                return strips;
            }
            count /= 2;
        }
    }

    /// The strip holding coordinate `y`.
    fn of(&self, y: f64) -> usize {
        let k = ((y - self.y0) / self.height).floor();
        // `as` saturates (−∞ and negatives to 0, +∞ to the maximum) and NaN cannot occur.
        (k as usize).min(self.count - 1)
    }

    /// The first and last strips a box crosses.
    fn span(&self, b: &Aabb) -> (usize, usize) {
        if self.count == 1 {
            return (0, 0);
        }
        (self.of(b.lo[self.axis]), self.of(b.hi[self.axis]))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ball(p: [f64; 2], v: [f64; 2], mu: f64) -> Ball {
        Ball::new(Vector2::from(p), Vector2::from(v), mu).unwrap()
    }

    #[test]
    fn segments_of_each_kind_of_ball() {
        let stopping = ball([0.0, 0.0], [2.0, 0.0], 0.5);
        assert_eq!(
            swept_segment(&stopping, f64::INFINITY).1,
            Vector2::new(4.0, 0.0)
        );
        let ray = ball([1.0, 2.0], [-1.0, 0.0], 0.0);
        assert_eq!(
            swept_segment(&ray, f64::INFINITY).1,
            Vector2::new(f64::NEG_INFINITY, 2.0)
        );
        assert_eq!(swept_segment(&ray, 3.0).1, Vector2::new(-2.0, 2.0));
        let rest = ball([1.0, 2.0], [0.0, 0.0], 0.3);
        assert_eq!(
            swept_segment(&rest, f64::INFINITY).1,
            Vector2::new(1.0, 2.0)
        );
    }

    #[test]
    fn rays_have_infinite_boxes_and_overlap_what_lies_ahead() {
        let balls = [
            ball([0.0, 0.0], [1.0, 0.0], 0.0),
            ball([100.0, 0.5], [0.0, 0.0], 0.0),
            ball([-100.0, 0.0], [0.0, 0.0], 0.0),
        ];
        let sweep = Sweep::new(&balls, &[0.3; 3], f64::INFINITY, false);
        let mut pairs = Vec::new();
        for rank in 0..sweep.len() {
            sweep.for_each_after(rank, |i, j| pairs.push((i, j)));
        }
        assert_eq!(pairs, vec![(0, 1)]);
    }

    #[test]
    fn strips_visit_every_overlapping_pair_exactly_once() {
        // A table-like scene: long segments, balls at rest, a few rays; several strips.
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut uniform = |lo: f64, hi: f64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            lo + (hi - lo) * ((state >> 11) as f64 / (1u64 << 53) as f64)
        };
        let balls: Vec<Ball> = (0..600)
            .map(|k| {
                let p = [uniform(0.0, 16.0), uniform(0.0, 8.0)];
                let v = [uniform(-1.0, 1.0), uniform(-1.0, 1.0)];
                match k % 10 {
                    0 => ball(p, v, 0.0),
                    1..=4 => ball(p, [0.0, 0.0], 0.0),
                    _ => ball(p, v, uniform(0.1, 1.0)),
                }
            })
            .collect();
        let radii = vec![0.03; balls.len()];
        let sweep = Sweep::new(&balls, &radii, f64::INFINITY, true);
        assert!(sweep.len() > balls.len()); // boxes cross strips
        let mut found = Vec::new();
        for rank in 0..sweep.len() {
            sweep.for_each_after(rank, |i, j| found.push((i, j)));
        }
        found.sort_unstable();
        let boxes = swept_boxes(&balls, &radii, f64::INFINITY);
        let mut expected = Vec::new();
        for i in 0..boxes.len() {
            for j in i + 1..boxes.len() {
                if boxes[i].overlaps_on(&boxes[j], 0) && boxes[i].overlaps_on(&boxes[j], 1) {
                    expected.push((i, j));
                }
            }
        }
        assert_eq!(found, expected);
    }
}
