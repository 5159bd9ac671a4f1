//! The broad phase: swept bounding boxes and a sort-and-sweep over them.
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
    MARGIN_ULPS * f64::EPSILON * (largest + diameter * diameter / r_min)
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

/// The sort-and-sweep structure: boxes sorted by their lower bound on the sweep axis.
pub(crate) struct Sweep {
    boxes: Vec<Aabb>,
    order: Vec<usize>,
    axis: usize,
}

impl Sweep {
    /// Boxes of `balls` (validated `radii`, same length) and their order along the sweep axis.
    pub(crate) fn new(balls: &[Ball], radii: &[f64], t_max: f64) -> Self {
        let boxes = swept_boxes(balls, radii, t_max);
        let axis = sweep_axis(balls);
        let mut order: Vec<usize> = (0..boxes.len()).collect();
        // Bounds are never NaN; `total_cmp` with the index makes the order total.
        order.sort_unstable_by(|&i, &j| {
            boxes[i].lo[axis]
                .total_cmp(&boxes[j].lo[axis])
                .then(i.cmp(&j))
        });
        Self { boxes, order, axis }
    }

    /// Number of balls (rank positions).
    pub(crate) fn len(&self) -> usize {
        self.order.len()
    }

    /// Calls `visit(i, j)` with `i < j` for every pair whose boxes overlap, where one of the
    /// two is the ball at `rank` in the sweep order and the other comes later in it.
    pub(crate) fn for_each_after(&self, rank: usize, mut visit: impl FnMut(usize, usize)) {
        let (axis, other) = (self.axis, 1 - self.axis);
        let i = self.order[rank];
        let bi = &self.boxes[i];
        for &j in &self.order[rank + 1..] {
            let bj = &self.boxes[j];
            if bj.lo[axis] > bi.hi[axis] {
                break; // sorted by lower bound: no later box reaches back
            }
            if bi.overlaps_on(bj, other) {
                visit(i.min(j), i.max(j));
            }
        }
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
        let sweep = Sweep::new(&balls, &[0.3; 3], f64::INFINITY);
        let mut pairs = Vec::new();
        for rank in 0..sweep.len() {
            sweep.for_each_after(rank, |i, j| pairs.push((i, j)));
        }
        assert_eq!(pairs, vec![(0, 1)]);
    }
}
