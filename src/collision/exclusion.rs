//! A cheap, rigorous proof that two balls cannot touch on a window, or the isolation of their
//! first crossing on a piece of it.
//!
//! On `w ∈ [0, 1]` a quartic `q(w) = Σ aᵢ wⁱ` equals `Σ bⱼ Bⱼ(w)` in the Bernstein basis
//! `Bⱼ(w) = C(4, j) wʲ (1 − w)⁴⁻ʲ`, whose functions are non-negative and sum to one: `q` lies
//! between the smallest and the largest `bⱼ`. So if every `bⱼ` exceeds the rounding error made
//! in computing it, `q > 0` on the whole interval and there is no contact. On random pairs on
//! a table this settles most pairs with a few dozen multiply-adds and no division or root.
//!
//! The test runs on the window itself, `u ∈ [0, end]` (substituting `u = end·w`), not on the
//! power-of-two interval `[0, 1]` that contains it: past a stop the gap's formula turns the
//! ball round, and that fictitious return would often spoil the proof. Where the first test
//! fails, the window is halved (de Casteljau, exact halvings and one rounding per average),
//! which tightens the bounds quadratically around a near miss: three times at most in the
//! batch's lane-wise test ([`window_screened_out`]), six in the search ([`OpenPieces`]), which
//! lists the pieces, in time order, that it cannot prove positive, with what their
//! coefficients show: a single root (the first crossing, if it is the first such piece), or a
//! single minimum (a near miss or a grazing contact, settled there by the search).

use crate::gap::Gap;

/// How many times [`OpenPieces`] may halve a window (its margin, shared with
/// [`window_screened_out`], covers the rounding of that many halvings).
const ISOLATING_SPLITS: u32 = 6;

/// The Bernstein coefficients' margin ([`bernstein`]) over the square of the window's
/// magnitudes.
pub(crate) const MARGIN_PER_SQUARE: f64 = (16.0 + 4.0 * ISOLATING_SPLITS as f64) * f64::EPSILON;

/// Whether `g(u) > 0` is proven for every `u ∈ [0, end]` (time already scaled so that
/// `0 ≤ end ≤ 1`), by the Bernstein coefficients of the window or of its pieces down to three
/// halvings.
///
/// `false` means "not proven", not "there is a root".
///
/// Branch-free (every piece is evaluated), so that a batch runs it lane-wise over many
/// windows. The search itself runs [`OpenPieces`], which takes the same
/// coefficients and margin and subdivides further: every window proven here, it proves too,
/// so a pair that the batch settles with this test is one the search answers the same way.
#[inline(always)]
pub(crate) fn window_screened_out<const D: usize>(gap: &Gap<D>, end: f64) -> bool {
    let (b, margin) = bernstein(gap, end);
    positive_within_3_halvings(b, margin)
}

/// The first eighth of the window `[0, end]` (time scaled so that `end ≤ 1`) whose Bernstein
/// coefficients do not prove `g > 0`, as its index `0..8` (`8` if there is none), and its
/// shape: whether it holds exactly one root ([`Shape::OneRoot`]: then that root is the
/// window's first crossing, from + to −), or a single minimum ([`Shape::OneDip`]); and
/// whether every later eighth is proven positive.
///
/// Every eighth is evaluated, as the lane twin (`batch/eighth_lanes.rs`) evaluates them. The margin is
/// that of [`window_screened_out`], and each eighth comes from three exact halvings.
#[inline(always)]
pub(crate) fn first_open_eighth<const D: usize>(gap: &Gap<D>, end: f64) -> OpenEighth {
    let (b, margin) = bernstein(gap, end);
    let (l, r) = halves(b);
    let ((ll, lr), (rl, rr)) = (halves(l), halves(r));
    let ((e0, e1), (e2, e3), (e4, e5), (e6, e7)) = (halves(ll), halves(lr), halves(rl), halves(rr));
    let eighths = [e0, e1, e2, e3, e4, e5, e6, e7];
    // From the last to the first, so that the first open eighth is the one kept.
    let (mut index, mut piece, mut open) = (8.0, e7, 0u32);
    for k in (0..8).rev() {
        let positive = above(&eighths[k], margin);
        index = if positive { index } else { k as f64 };
        piece = if positive { piece } else { eighths[k] };
        open += u32::from(!positive);
    }
    OpenEighth {
        index,
        one_root: (open > 0) & one_root(&piece, margin),
        one_dip: (open > 0) & one_dip(&piece, margin),
        rest_positive: open <= 1,
    }
}

/// Whether the Bernstein coefficients of the whole window `[0, end]` prove `g > 0`: the first
/// test of [`window_screened_out`] and [`OpenPieces`], alone.
#[inline(always)]
pub(crate) fn window_screened_out_at_once<const D: usize>(gap: &Gap<D>, end: f64) -> bool {
    let (b, margin) = bernstein(gap, end);
    above(&b, margin)
}

/// What [`first_open_eighth`] found.
#[derive(Clone, Copy, Debug)]
pub(crate) struct OpenEighth {
    /// The first eighth not proven positive, `0..8` (`8` if there is none).
    pub index: f64,
    /// It holds a single root ([`Shape::OneRoot`]).
    pub one_root: bool,
    /// It holds a single minimum ([`Shape::OneDip`]).
    pub one_dip: bool,
    /// Every eighth after it is proven positive.
    pub rest_positive: bool,
}

/// Whether the coefficients `b` show exactly one root, from positive to negative, robustly:
/// none within `margin` of zero, and one sign change ([`Shape::OneRoot`]), without a branch.
#[inline(always)]
fn one_root(b: &[f64; 5], margin: f64) -> bool {
    let clear = b.iter().fold(true, |all, &x| all & (x.abs() > margin));
    let changes = b
        .windows(2)
        .fold(0u32, |n, w| n + u32::from((w[0] > 0.0) != (w[1] > 0.0)));
    clear & (b[0] > 0.0) & (changes == 1)
}

/// The pieces of a window that a subdivision down to [`ISOLATING_SPLITS`] halvings leaves
/// open (not proven positive), in time order: an iterator.
///
/// Pieces not proven positive are halved (even where `g` may cross zero at their end, to
/// isolate the crossing) until their shape is isolated (a single root or a single minimum), or
/// they are at the finest level, or start at or below the margin; those are the open pieces.
/// Everything between them is proven positive.
pub(crate) struct OpenPieces {
    margin: f64,
    /// Pieces still to visit, the next on top: coefficients, start and depth (at most one per
    /// level, plus the one being halved).
    stack: [([f64; 5], f64, u32); ISOLATING_SPLITS as usize + 1],
    pending: usize,
}

/// An open piece of a window: where it lies (fractions of the window) and what `g` does there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct OpenPiece {
    /// Start, as a fraction of the window.
    pub start: f64,
    /// End, as a fraction of the window.
    pub stop: f64,
    /// The shape of `g` on it.
    pub shape: Shape,
}

/// What the Bernstein coefficients of `g` on a piece show, robustly (no coefficient, nor
/// difference of two, within the rounding margin of zero).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Shape {
    /// From positive to negative, with exactly one root (one sign change among the
    /// coefficients: Descartes' rule of signs for the Bernstein basis).
    OneRoot,
    /// Positive at the start, falling then rising, with exactly one critical point, a minimum
    /// (one sign change, − to +, among the differences of the coefficients, which are those of
    /// `g′`): a near miss, a grazing contact, or an entry and an exit close together.
    OneDip,
    /// Anything else.
    Other,
}

impl OpenPieces {
    /// The open pieces of `g` on `[0, end]` (time scaled so that `end ≤ 1`).
    pub(crate) fn new<const D: usize>(gap: &Gap<D>, end: f64) -> Self {
        let (b, margin) = bernstein(gap, end);
        let mut stack = [([0.0; 5], 0.0, 0); ISOLATING_SPLITS as usize + 1];
        stack[0] = (b, 0.0, 0);
        Self {
            margin,
            stack,
            pending: 1,
        }
    }
}

impl Iterator for OpenPieces {
    type Item = OpenPiece;

    fn next(&mut self) -> Option<OpenPiece> {
        let margin = self.margin;
        while self.pending > 0 {
            self.pending -= 1;
            let (b, start, depth) = self.stack[self.pending];
            if above(&b, margin) {
                continue;
            }
            // A piece whose shape is isolated already needs no halving.
            let shape = shape(&b, margin);
            if shape != Shape::Other || depth == ISOLATING_SPLITS || b[0] <= margin {
                return Some(OpenPiece {
                    start,
                    stop: start + piece_width(depth),
                    shape,
                });
            }
            let (left, right) = halves(b);
            let depth = depth + 1;
            // The right half under the left one, so that the left is visited first (the stack
            // holds one piece per level and the one being halved: there is always room).
            if self.pending + 2 <= self.stack.len() {
                self.stack[self.pending] = (right, start + piece_width(depth), depth);
                self.stack[self.pending + 1] = (left, start, depth);
                self.pending += 2;
            }
        }
        None
    }
}

/// The shape of `g` on a piece with Bernstein coefficients `b`.
fn shape(b: &[f64; 5], margin: f64) -> Shape {
    match (one_root(b, margin), one_dip(b, margin)) {
        (true, _) => Shape::OneRoot,
        (false, true) => Shape::OneDip,
        (false, false) => Shape::Other,
    }
}

/// Whether the coefficients `b` show [`Shape::OneDip`], without a branch: a start above
/// `margin`, and one sign change, − to +, among the differences (the coefficients of `g′`),
/// none of them within the rounding of two coefficients (`2·margin`) of zero.
#[inline(always)]
fn one_dip(b: &[f64; 5], margin: f64) -> bool {
    let slopes = [b[1] - b[0], b[2] - b[1], b[3] - b[2], b[4] - b[3]];
    let steep = slopes
        .iter()
        .fold(true, |all, &x| all & (x.abs() > 2.0 * margin));
    let turns = slopes
        .windows(2)
        .fold(0u32, |n, w| n + u32::from((w[0] > 0.0) != (w[1] > 0.0)));
    (b[0] > margin) & steep & (slopes[0] < 0.0) & (turns == 1)
}

/// `2^−depth`, the width of a piece `depth` halvings deep (exact: a power of two).
fn piece_width(depth: u32) -> f64 {
    f64::from_bits((1023 - u64::from(depth)) << 52)
}

/// The Bernstein coefficients of `g` on `[0, end]`, and the margin above their rounding errors
/// and those of [`ISOLATING_SPLITS`] halvings.
///
/// With `M` the sum of all components' magnitudes and the radius, `Σ|aᵢ| ≤ M²`, and every
/// Bernstein coefficient of every piece is a combination with weights ≤ 1 of the `aᵢ`, so each
/// stays below `M²` in magnitude. The coefficients' dot products err by `≤ 3ε·M²`, the powers
/// `endⁱ` by `≤ 4ε·M²`, the basis change by `≤ 5ε·M²` (four additions and the rounded `1/6`),
/// and each level of halving by `≤ 4ε·M²` (four rounds of averages): the margin
/// `(16 + 4·ISOLATING_SPLITS)·ε·M²` is above it all.
#[inline(always)]
fn bernstein<const D: usize>(gap: &Gap<D>, end: f64) -> ([f64; 5], f64) {
    let [a4, a3, a2, a1, a0] = gap.quartic();
    let end2 = end * end;
    let (a1, a2, a3, a4) = (a1 * end, a2 * end2, a3 * (end2 * end), a4 * (end2 * end2));
    let b = [
        a0,
        a0 + 0.25 * a1,
        a0 + 0.5 * a1 + a2 * (1.0 / 6.0),
        a0 + 0.75 * a1 + 0.5 * a2 + 0.25 * a3,
        a0 + a1 + a2 + a3 + a4,
    ];
    let l1 = |v: &nalgebra::SVector<f64, D>| v.iter().fold(0.0, |sum, x| sum + x.abs());
    let m = l1(&gap.offset) + l1(&gap.velocity) + l1(&gap.acceleration) + gap.contact_distance;
    let margin = MARGIN_PER_SQUARE * (m * m);
    (b, margin)
}

/// Whether the quartic with Bernstein coefficients `b` on an interval is above `margin` on it,
/// by its coefficients or, where they do not show it, by those of its halves, recursively, up
/// to three halvings. A piece whose end values (values of `g`) are not above the margin
/// settles nothing further. Every piece is evaluated, without a branch.
#[inline(always)]
fn positive_within_3_halvings(b: [f64; 5], margin: f64) -> bool {
    let settled = |b: &[f64; 5], halves_settled: bool| {
        above(b, margin) | ((b[0] > margin) & (b[4] > margin) & halves_settled)
    };
    let level1 = |b: [f64; 5]| {
        let (l, r) = halves(b);
        settled(&b, above(&l, margin) & above(&r, margin))
    };
    let level2 = |b: [f64; 5]| {
        let (l, r) = halves(b);
        settled(&b, level1(l) & level1(r))
    };
    let (l, r) = halves(b);
    settled(&b, level2(l) & level2(r))
}

/// Whether every coefficient of `b` is above `margin`.
#[inline(always)]
fn above(b: &[f64; 5], margin: f64) -> bool {
    b.iter().fold(true, |all, &x| all & (x > margin))
}

/// De Casteljau's subdivision at the midpoint: the Bernstein coefficients on each half.
#[inline(always)]
fn halves(b: [f64; 5]) -> ([f64; 5], [f64; 5]) {
    let mid = |x: f64, y: f64| 0.5 * (x + y);
    let c = [
        mid(b[0], b[1]),
        mid(b[1], b[2]),
        mid(b[2], b[3]),
        mid(b[3], b[4]),
    ];
    let d = [mid(c[0], c[1]), mid(c[1], c[2]), mid(c[2], c[3])];
    let e = [mid(d[0], d[1]), mid(d[1], d[2])];
    let f = mid(e[0], e[1]);
    ([b[0], c[0], d[0], e[0], f], [f, e[1], d[2], c[3], b[4]])
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;

    fn gap(offset: [f64; 2], velocity: [f64; 2], acceleration: [f64; 2]) -> Gap {
        Gap {
            offset: Vector2::from(offset),
            velocity: Vector2::from(velocity),
            acceleration: Vector2::from(acceleration),
            contact_distance: 1.0,
        }
    }

    #[test]
    fn far_apart_and_receding_is_excluded() {
        assert!(window_screened_out(
            &gap([5.0, 0.0], [1.0, 0.0], [-0.5, 0.0]),
            1.0
        ));
    }

    #[test]
    fn contact_inside_the_window_is_never_excluded() {
        // Head-on: |d| = 3 − 4u reaches 1 at u = 0.5.
        assert!(!window_screened_out(
            &gap([3.0, 0.0], [-4.0, 0.0], [0.0, 0.0]),
            1.0
        ));
        // Grazing from above by 1e-15: within rounding, so not excluded either.
        assert!(!window_screened_out(
            &gap([-1.0, 1.0 + 1e-15], [2.0, 0.0], [0.0, 0.0]),
            1.0
        ));
        // Grazing from above by 1e-12: above rounding, and halving proves the miss.
        assert!(window_screened_out(
            &gap([-1.0, 1.0 + 1e-12], [2.0, 0.0], [0.0, 0.0]),
            1.0
        ));
        // Contact just inside the window's end (|d| = 3 − 4u = 1 at u = 0.5).
        assert!(!window_screened_out(
            &gap([3.0, 0.0], [-4.0, 0.0], [0.0, 0.0]),
            0.5 + 1e-9
        ));
    }

    #[test]
    fn the_exact_window_excludes_what_lies_past_its_end() {
        // |d| = 3 − 4u reaches 1 at u = 0.5, after a window that ends at u = 0.4 (a ball
        // stops there: past it the formula is fictitious). [0, 1] could not be proven.
        let g = gap([3.0, 0.0], [-4.0, 0.0], [0.0, 0.0]);
        assert!(window_screened_out(&g, 0.4));
        assert!(!window_screened_out(&g, 1.0));
    }

    #[test]
    fn halving_proves_a_near_miss_the_coefficients_alone_do_not() {
        // Passing 1e-3 above the other ball: the one-piece bounds are too loose.
        let g = gap([-1.0, 1.001], [2.0, 0.0], [0.0, 0.0]);
        let [a4, a3, a2, a1, a0] = g.quartic();
        let b2 = a0 + 0.5 * a1 + a2 / 6.0;
        assert!(b2 < 0.0 && a4 == 0.0 && a3 == 0.0); // not provable without halving
        assert!(window_screened_out(&g, 1.0));
    }

    #[test]
    fn the_first_crossing_is_isolated_on_a_piece_that_brackets_it() {
        // Head-on: |d| = 3.3 − 4u reaches 1 at u = 0.575 (entry), and leaves after the window:
        // a single root on the whole window.
        let g = gap([3.3, 0.0], [-4.0, 0.0], [0.0, 0.0]);
        let first = OpenPieces::new(&g, 1.0).next();
        let Some(OpenPiece {
            start,
            stop,
            shape: Shape::OneRoot,
        }) = first
        else {
            panic!("not isolated: {first:?}")
        };
        assert!(start < 0.575 && 0.575 < stop, "{start} {stop}");
        // With |d| = 2.9 − 4u the balls enter at u = 0.475 and leave at u = 0.975: the window
        // shows a single minimum (at 0.725), which the search resolves.
        let g = gap([2.9, 0.0], [-4.0, 0.0], [0.0, 0.0]);
        let pieces: Vec<_> = OpenPieces::new(&g, 1.0).collect();
        assert_eq!(pieces.len(), 1, "{pieces:?}");
        assert_eq!(pieces[0].shape, Shape::OneDip);
        assert!(
            pieces[0].start < 0.725 && 0.725 < pieces[0].stop,
            "{pieces:?}"
        );
    }

    #[test]
    fn a_near_miss_shows_as_a_single_dip() {
        // Passing 1e-7 above or below the other ball (closest at u = 0.45): too close for the
        // coefficients to decide; the piece around it shows a single minimum, which the search
        // settles. Three halvings prove nothing either way.
        for y in [1.0000001, 0.9999999] {
            let g = gap([-0.9, y], [2.0, 0.0], [0.0, 0.0]);
            assert!(!window_screened_out(&g, 1.0));
            let pieces: Vec<_> = OpenPieces::new(&g, 1.0).collect();
            assert_eq!(pieces.len(), 1, "{pieces:?}");
            assert_eq!(pieces[0].shape, Shape::OneDip);
            assert!(pieces[0].start < 0.45 && 0.45 < pieces[0].stop);
        }
        // Passing 0.2 above: a miss the coefficients show at once.
        let g = gap([-0.9, 1.2], [2.0, 0.0], [0.0, 0.0]);
        assert!(window_screened_out(&g, 1.0));
        assert_eq!(OpenPieces::new(&g, 1.0).next(), None);
    }
}
