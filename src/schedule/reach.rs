//! The box a ball's disc covers over a span of time: its centre's range on each axis, grown
//! by its radius and a rounding margin.
//!
//! On each segment a coordinate is a quadratic in the time since the segment's start, so its
//! range over a span lies between its values at the span's ends and at its vertex (if inside);
//! a span that runs for ever is unbounded on every axis where the acceleration, or else the
//! velocity, is not zero, on the side it points to, and bounded on the others (a ball moving
//! for ever along `+y` keeps its `x`, and never comes below where it is now).
//!
//! ## The rounding margin
//!
//! Two balls whose boxes are disjoint on some axis never touch on the span; but the pair
//! search works in float64 and may report a contact for a pair whose exact closest approach
//! exceeds the contact distance by its rounding error. The margin covers that error at each
//! finite end of the box, so that pruning never changes an answer.
//!
//! *The search's error, seen on one axis `k`.* The search decides that two balls touch from
//! their separation `d = x_A − x_B`: by the sign of `|d|² − r²` at some time (an entry's
//! bracket, a dip's lowest point, a window's start), or, for a straight relative motion, from
//! the closest approach `|d × v|/|v|` in closed form (straight windows, narrow dips). Each
//! component `d_k` is formed on its own axis from that axis's numbers alone (positions,
//! velocities and accelerations on axis `k`, times the time since a window's start; the units
//! of length and time that scale them are powers of two, exact), so it is off by a few
//! roundings of the magnitudes `S_k` that form it, and a time off by `δt` moves it by
//! `|v_k|·δt`. A sum of squares is at least each of its terms, so `|d|² − r² ≤ 0` (to a few
//! roundings of `r²`) needs `|d_k|` within about `r`, up to the error of `d_k` alone. In a
//! cross product, a term `d_k·v_m` is off by `ε·|d_k·v_m|`, at most `ε·|d_k|` over `|v|`; a
//! term `d_m·v_k` by `ε·|d_m·v_k|`, and where the closest approach comes within about `r` a
//! time `s` after the window's start, `|d_m(0)| ≤ r + |v_m|·s`, so over `|v|` that is at most
//! `ε·(r + |v_k|·s)`: `|v_k|·s` is the motion along `k` itself, within the two boxes' extents
//! on `k` (before the span's start, within the magnitudes). So the error seen on axis `k` is
//! of order `ε·(S_k + E_k + r)`, `E_k` the two boxes' extents on axis `k`, whatever the other
//! axes do (the earlier bound, `ε·(S + D²/r)` with `S` and `D` over all axes, is larger).
//!
//! *The margin.* Each box is grown, at every finite end, by [`MARGIN`]` · (S + E·(E/r))` with
//! its own radius `r`, `S` the magnitudes that formed its numbers on every axis (those of the
//! axes where it runs for ever too, as below: they also set the search's units) and `E` its
//! largest extent with the radius over the axes where both ends are finite. For two boxes
//! that come close on axis `k`, the pair's `S_k`, `E_k` and `r` are at most the sums of the
//! two boxes' `S`, `E` and `E` (`E ≥ 2r`), and `E·(E/r) ≥ 2E`, so the two margins together
//! stay more than `2⁹` times above the search's error there: pruning never changes an
//! answer. A box bounded on every axis gets the margin it always had.
//!
//! *An end at infinity.* On an axis where the ball drifts for ever, towards `+∞` say, its
//! coordinate `x(s) = p + v·s + ½·a·s²` never comes below the range's low end `L`, which is
//! finite; but the magnitudes `M(s) = |p| + |v|·s + |a|·s²` that form it (and the separation,
//! and a window's offset and velocity) at a later time grow without bound. They grow at most
//! in proportion to the distance gone beyond `L`: `M(s) ≤ 6·(x(s) − L) + 7·F`, with `F` the
//! magnitudes at the span's start, or at the turn if the motion turns back inside the span,
//! which `S` counts. (At a constant speed `M` grows by the distance itself; driven on by the
//! acceleration, by at most twice the distance; turning back, at the turn `t = |v/a|`, beyond
//! three times its time by at most six times the distance from the turn, which is the distance
//! beyond `L` plus at most `F`, and before that it is at most `M(3t) ≤ 6·M(t)`.) So at a time
//! when a pruned pair might touch, the search's error on that axis is a few roundings of `7·F`
//! (and the other ball's part) plus `6·c·ε` times the distance gone beyond `L`, while the
//! separation gains that whole distance: it exceeds its error by what the margin covers at `L`
//! alone, as on a bounded axis, with 7 times less room (more than `2⁶`). (A box pruned against
//! such a one on that axis lies beyond its finite end, and the ball only drifts farther from
//! it.) A margin that overflows (magnitudes beyond the float range) makes the whole box
//! unbounded, as before: it prunes nothing. Caveat, as for the search itself: its units are
//! exact unless a field underflows in them, more than about `2¹⁰⁰⁰` times below the window's
//! largest, beyond the range where the search is exact.

use crate::path::{Segment, spans};

/// The margin's size relative to `S + D²/r`: `2⁻³⁶ ≈ 1.5e-11`, about `2¹⁶·ε`.
const MARGIN: f64 = 1.0 / ((1u64 << 36) as f64);

/// An axis-aligned box (bounds may be infinite).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Reach<const D: usize> {
    pub(crate) lo: [f64; D],
    pub(crate) hi: [f64; D],
}

impl<const D: usize> Reach<D> {
    /// Whether the two boxes overlap (touching counts) on every axis.
    pub(crate) fn overlaps(&self, other: &Self) -> bool {
        // `&` rather than `&&`: no branch (a refresh asks this of every box in turn, and
        // which boxes overlap is hard to predict).
        (0..D).fold(true, |all, k| {
            all & (self.lo[k] <= other.hi[k]) & (other.lo[k] <= self.hi[k])
        })
    }
}

/// The box that a ball of `radius` on a valid path (`segments`) covers over `[t0, t1]`
/// (`t1` may be `+∞`; the path is taken from its first start on), with the margin.
pub(crate) fn reach<const D: usize>(
    segments: &[Segment<D>],
    radius: f64,
    t0: f64,
    t1: f64,
) -> Reach<D> {
    let late = t0.abs().max(if t1.is_finite() { t1.abs() } else { 0.0 });
    if let [segment] = segments
        && segment.start <= t0
        && t0 <= t1
        && t1 < f64::INFINITY
        && segment.acceleration.iter().all(|&a| a == 0.0)
    {
        return straight_reach(
            segment,
            radius,
            t0 - segment.start,
            t1 - segment.start,
            late,
        );
    }
    let (mut lo, mut hi) = ([f64::INFINITY; D], [f64::NEG_INFINITY; D]);
    let mut size = 0.0;
    for (segment, end) in spans(segments) {
        if segment.start > t1 {
            break;
        }
        if end <= t0 {
            continue; // over before the span
        }
        let from = t0.max(segment.start) - segment.start;
        let to = t1.min(end) - segment.start;
        for k in 0..D {
            let (p, v, a) = (
                segment.position[k],
                segment.velocity[k],
                segment.acceleration[k],
            );
            let (l, h, magnitude) = range_on(p, v, a, from, to);
            lo[k] = lo[k].min(l);
            hi[k] = hi[k].max(h);
            let length = if to.is_finite() { to } else { from };
            size += magnitude + late * (v.abs() + a.abs() * length);
        }
    }
    grown(lo, hi, size, radius)
}

/// [`reach`] of one segment without acceleration over `[from, to]` after its start
/// (`0 ≤ from ≤ to < ∞`, `late` as there): the same box, each coordinate's range between
/// its two ends.
fn straight_reach<const D: usize>(
    segment: &Segment<D>,
    radius: f64,
    from: f64,
    to: f64,
    late: f64,
) -> Reach<D> {
    let (mut lo, mut hi) = ([0.0; D], [0.0; D]);
    let mut size = 0.0;
    for k in 0..D {
        let (p, v) = (segment.position[k], segment.velocity[k]);
        let (start, end) = (p + v * from, p + v * to);
        (lo[k], hi[k]) = if v >= 0.0 { (start, end) } else { (end, start) };
        size += (p.abs() + v.abs() * to) + late * v.abs();
    }
    grown(lo, hi, size, radius)
}

/// The box from `lo` to `hi` grown by the radius and the margin, `size` the sum of the
/// magnitudes that formed it so far; an end at `−∞` or `+∞` (a ball that drifts that way for
/// ever) stays there. See the module's notes.
fn grown<const D: usize>(lo: [f64; D], hi: [f64; D], mut size: f64, radius: f64) -> Reach<D> {
    // (A span before the path's first start leaves `lo = +∞`, `hi = −∞` on every axis: both
    // ends "finite" here, its size infinite, so the box is NaN, which overlaps nothing, as it
    // always was.)
    let mut extent = 0.0_f64;
    for k in 0..D {
        match (lo[k] == f64::NEG_INFINITY, hi[k] == f64::INFINITY) {
            (false, false) => {
                size += lo[k].abs().max(hi[k].abs());
                extent = extent.max(hi[k] - lo[k]);
            }
            (false, true) => size += lo[k].abs(),
            (true, false) => size += hi[k].abs(),
            (true, true) => {}
        }
    }
    let extent = extent + 2.0 * radius;
    // `D·(D/r)`, not `D²/r`: no square that overflows or underflows on its own. A NaN or an
    // infinite margin (magnitudes beyond the float range) prunes nothing, on any axis.
    let margin = MARGIN * (size + extent * (extent / radius));
    let grow = if margin.is_finite() {
        radius + margin
    } else {
        f64::INFINITY
    };
    // (`±∞ ∓ grow` is `±∞`: a drifting end stays where it is.)
    Reach {
        lo: lo.map(|x| x - grow),
        hi: hi.map(|x| x + grow),
    }
}

/// The range `(lo, hi)` of `p + v·s + ½·a·s²` over `s ∈ [from, to]` (`to` may be `+∞`), and
/// a bound on the magnitudes that form it.
fn range_on(p: f64, v: f64, a: f64, from: f64, to: f64) -> (f64, f64, f64) {
    let at = |s: f64| p + (v + 0.5 * a * s) * s;
    let start = at(from);
    let (mut lo, mut hi) = (start, start);
    // No acceleration, no vertex (and no division: `-v / 0` would be `±∞` or NaN, outside).
    let vertex_inside = a != 0.0 && {
        let turn = -v / a;
        turn > from && turn < to
    };
    if vertex_inside {
        let vertex = p - 0.5 * v * (v / a);
        lo = lo.min(vertex);
        hi = hi.max(vertex);
    }
    if to.is_finite() {
        let end = at(to);
        lo = lo.min(end);
        hi = hi.max(end);
        return (lo, hi, p.abs() + (v.abs() + a.abs() * to) * to);
    }
    // For ever: towards wherever the acceleration, or else the velocity, points. The
    // magnitudes at the start of the span, or at the turn if the motion turns back inside it
    // (later ones grow with the distance from the range's finite end: see the module's
    // notes).
    let drift = if a != 0.0 { a } else { v };
    if drift < 0.0 {
        lo = f64::NEG_INFINITY;
    } else if drift > 0.0 {
        hi = f64::INFINITY;
    }
    let last = if vertex_inside { -v / a } else { from };
    (lo, hi, p.abs() + (v.abs() + a.abs() * last) * last)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Vector2, Vector3};

    fn segment(s: f64, p: [f64; 2], v: [f64; 2], a: [f64; 2]) -> Segment<2> {
        Segment::new(s, Vector2::from(p), Vector2::from(v), Vector2::from(a))
    }

    #[test]
    fn a_friction_ball_covers_its_run_to_rest_and_no_more() {
        // From (0, 0) at 1 m/s along x, slowed at 0.5 m/s², at rest at x = 1 from t = 2.
        let path = [
            segment(0.0, [0.0, 0.0], [1.0, 0.0], [-0.5, 0.0]),
            segment(2.0, [1.0, 0.0], [0.0, 0.0], [0.0, 0.0]),
        ];
        let r = reach(&path, 0.25, 0.0, f64::INFINITY);
        assert!((r.lo[0] + 0.25).abs() < 1e-9 && (r.hi[0] - 1.25).abs() < 1e-9);
        assert!(r.lo[0] < -0.25 && r.hi[0] > 1.25); // the margin, outside
        // From t = 1 on: x from 0.75.
        let r = reach(&path, 0.25, 1.0, f64::INFINITY);
        assert!((r.lo[0] - 0.5).abs() < 1e-9);
    }

    #[test]
    fn a_ball_turning_back_covers_its_vertex_and_a_moving_one_for_ever_is_unbounded() {
        let up = [segment(0.0, [0.0, 0.0], [0.0, 1.0], [0.0, -1.0])];
        let r = reach(&up, 0.1, 0.0, 3.0);
        assert!((r.hi[1] - 0.6).abs() < 1e-8); // the top, y = ½
        assert!((r.lo[1] - (-1.5 - 0.1)).abs() < 1e-8); // y(3) = 3 − 4.5
        // For ever: y below its top, x still bounded.
        let r = reach(&up, 0.1, 0.0, f64::INFINITY);
        assert_eq!(r.lo[1], f64::NEG_INFINITY);
        assert!((r.hi[1] - 0.6).abs() < 1e-8);
        assert!((r.lo[0] + 0.1).abs() < 1e-9 && (r.hi[0] - 0.1).abs() < 1e-9);
    }

    #[test]
    fn a_ray_along_one_axis_keeps_the_others_bounded_and_its_start() {
        // Frictionless along +y for ever from (2, 3): x stays within the radius and a margin
        // of about 2⁻³⁶ of the magnitudes (which include y at the span's start), and y above
        // where it is at the span's start, from any time on.
        let ray = [segment(0.0, [2.0, 3.0], [0.0, 1.0], [0.0, 0.0])];
        for t0 in [0.0, 10.0, 1e6] {
            let r = reach(&ray, 0.5, t0, f64::INFINITY);
            let most = 1e-9 * (1.0 + t0);
            assert!(r.lo[0] < 1.5 && r.lo[0] > 1.5 - most, "{t0}: {r:?}");
            assert!(r.hi[0] > 2.5 && r.hi[0] < 2.5 + most, "{t0}: {r:?}");
            let y = 3.0 + t0 - 0.5;
            assert!(r.lo[1] < y && r.lo[1] > y - most, "{t0}: {r:?}");
            assert_eq!(r.hi[1], f64::INFINITY);
        }
        // A roll along x to rest, then on along −y for ever: x covers the roll.
        let turn = [
            segment(0.0, [0.0, 0.0], [1.0, 0.0], [-0.5, 0.0]),
            segment(2.0, [1.0, 0.0], [0.0, -2.0], [0.0, 0.0]),
        ];
        let r = reach(&turn, 0.25, 0.0, f64::INFINITY);
        assert!(r.lo[0] < -0.25 && r.lo[0] > -0.25 - 1e-9);
        assert!(r.hi[0] > 1.25 && r.hi[0] < 1.25 + 1e-9);
        assert_eq!(r.lo[1], f64::NEG_INFINITY);
        assert!(r.hi[1] > 0.25 && r.hi[1] < 0.25 + 1e-9);
        // In space, a ball in the air thrown along x from height 1 at 2 up: y bounded, x from
        // where it is on, z below the top of its flight (1 + 2²/(2·9.81)).
        let throw = [Segment::new(
            0.0,
            Vector3::new(0.0, 4.0, 1.0),
            Vector3::new(1.0, 0.0, 2.0),
            Vector3::new(0.0, 0.0, -9.81),
        )];
        let r = reach(&throw, 0.1, 0.0, f64::INFINITY);
        assert!(r.lo[1] < 3.9 && r.lo[1] > 3.9 - 1e-9 && r.hi[1] > 4.1 && r.hi[1] < 4.1 + 1e-9);
        assert!(r.lo[0] < -0.1 && r.lo[0] > -0.1 - 1e-9 && r.hi[0] == f64::INFINITY);
        let top = 1.0 + 4.0 / (2.0 * 9.81) + 0.1;
        assert!(r.hi[2] > top && r.hi[2] < top + 1e-9 && r.lo[2] == f64::NEG_INFINITY);
    }

    #[test]
    fn boxes_beyond_the_float_range_or_before_the_path_are_as_they_were() {
        // Magnitudes that overflow: the whole plane, the bounded axis too.
        let far = [segment(0.0, [1.5e308, 0.0], [0.0, 1.0], [0.0, 0.0])];
        let r = reach(&far, 0.5, 0.0, f64::INFINITY);
        assert_eq!(r.lo, [f64::NEG_INFINITY; 2]);
        assert_eq!(r.hi, [f64::INFINITY; 2]);
        // A span before the path's first start: a NaN box, which overlaps nothing.
        let later = [segment(5.0, [0.0, 0.0], [1.0, 0.0], [0.0, 0.0])];
        let r = reach(&later, 0.5, 0.0, 1.0);
        assert!(r.lo.iter().chain(&r.hi).all(|x| x.is_nan()), "{r:?}");
        let everything = Reach {
            lo: [f64::NEG_INFINITY; 2],
            hi: [f64::INFINITY; 2],
        };
        assert!(!r.overlaps(&everything) && !everything.overlaps(&r));
    }

    #[test]
    fn one_straight_segment_covers_what_the_general_sweep_does() {
        let mut rng = crate::test_rng::Rng(17);
        let mut draw = |lo: f64, hi: f64| rng.uniform(lo, hi);
        for n in 0..1000 {
            let v = [
                draw(-3.0, 3.0),
                if n % 5 == 0 { 0.0 } else { draw(-3.0, 3.0) },
            ];
            let one = segment(
                draw(0.0, 2.0),
                [draw(-1.0, 1.0), draw(-1.0, 1.0)],
                v,
                [0.0; 2],
            );
            let t0 = one.start + if n % 7 == 0 { 0.0 } else { draw(0.0, 1.0) };
            let t1 = t0 + if n % 11 == 0 { 0.0 } else { draw(0.0, 1.0) };
            // The same motion with a later segment that starts after the span: the general
            // sweep over segments, which stops before that one.
            let later = segment(t1 + 1.0, [5.0, 5.0], [0.0; 2], [0.0; 2]);
            let expected = reach(&[one, later], 0.25, t0, t1);
            assert_eq!(reach(&[one], 0.25, t0, t1), expected, "{one:?} {t0} {t1}");
        }
    }

    #[test]
    fn boxes_overlap_when_they_touch() {
        let a = Reach {
            lo: [0.0, 0.0],
            hi: [1.0, 1.0],
        };
        let b = Reach {
            lo: [1.0, 0.5],
            hi: [2.0, 2.0],
        };
        let c = Reach {
            lo: [1.5, 0.5],
            hi: [2.0, 2.0],
        };
        assert!(a.overlaps(&b) && b.overlaps(&a));
        assert!(!a.overlaps(&c));
    }
}
