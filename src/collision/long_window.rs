//! Windows far longer than the motion's own time scale are searched in pieces.
//!
//! The window search scales time to the window, so a window of length `h` resolves what
//! happens on it to about `ε·h`. When the gap's own time scale `T` (how long the relative
//! motion takes to change the separation by about its size, [`natural_time`]) is far shorter
//! than the window (a ball that barely decelerates runs for 10³² s; a frictionless pair
//! searched up to a distant closest approach), an early contact is a feature of width `~T`
//! in a window of `h ≫ T`, and beyond about `h/T ~ 10²⁸` the search loses it.
//!
//! So a window longer than [`LONG`]` · T` is cut: a first piece of `LONG · T`, then pieces
//! each `LONG` times the time scale of the gap at their own start (re-expanded there, as
//! [`Gap::between`](crate::gap::Gap::between) does at a window's start), at least
//! doubling, until the window's end. The time scale can shrink inside a piece (a ball that
//! runs far away and comes back), so a piece is searched as it is only where it is short even
//! measured by the radius ([`short_piece`]), and otherwise halved, its halves proven apart by
//! their boxes or halved again, within a budget. Windows up to `LONG · T` (every window of
//! balls on a table, by many orders of magnitude) are searched whole, as before.
//!
//! The test is [`long_window`], shared by the search and the batch's lanes (which leave long
//! windows to the search), on the same numbers, so both take the same steps.

use crate::gap::Gap;

/// How many of its own time scales a window may last before it is cut: `2⁴⁰ ≈ 1.1e12`, far
/// below where the window search loses contacts (`~10²⁸`), far above any window on a table.
pub(crate) const LONG: f64 = (1u64 << 40) as f64;

/// Whether a window of `length` is longer than [`LONG`] times the time scale of `gap`:
/// `length·|v| > LONG·L` or `length²·|a| > LONG²·L`, with `L² = |d|² + r²`, both compared
/// squared (no square root). Without a branch, so that a batch runs it lane-wise. An
/// overflowing product counts as long (so does every window beyond about 1e154).
#[inline(always)]
pub(crate) fn long_window<const D: usize>(gap: &Gap<D>, length: f64) -> bool {
    const LONG2: f64 = LONG * LONG;
    let size2 = gap.offset.norm_squared() + gap.contact_distance * gap.contact_distance;
    let length2 = length * length;
    let run2 = length2 * gap.velocity.norm_squared();
    let bend2 = length2 * (length2 * gap.acceleration.norm_squared());
    // `>`: a motion at rest (0 times an overflowing length², NaN) is never long.
    (run2 > LONG2 * size2) | (bend2 > LONG2 * (LONG2 * size2))
}

/// Whether a piece of `length` is short wherever the balls may touch on it: no longer than
/// [`LONG`] times the time the motion takes to cover the radius at its largest speed on the
/// piece (`|v| + |a|·length`), nor than `LONG` times `√(r/|a|)`. Near a contact the
/// separation is about the radius, so this bounds the time scale there, whatever it is at the
/// piece's start.
pub(crate) fn short_piece<const D: usize>(gap: &Gap<D>, length: f64) -> bool {
    let a = gap.acceleration.norm();
    let speed = gap.velocity.norm() + a * length;
    (length * speed <= LONG * gap.contact_distance)
        & (length * (length * a) <= LONG * (LONG * gap.contact_distance))
}

/// The gap's own time scale: `min(L/|v|, √(L/|a|))`, `L² = |d|² + r²` (`∞` for a motion at
/// rest).
pub(crate) fn natural_time<const D: usize>(gap: &Gap<D>) -> f64 {
    let size = (gap.offset.norm_squared() + gap.contact_distance * gap.contact_distance).sqrt();
    let by_speed = size / gap.velocity.norm();
    let by_acceleration = (size / gap.acceleration.norm()).sqrt();
    by_speed.min(by_acceleration)
}

/// The pieces of a long window of `length` that starts with `gap`: the first is
/// `[0, LONG · T]`; the caller searches each and asks for the next from where it ended
/// ([`next_piece`]).
pub(crate) fn first_piece<const D: usize>(gap: &Gap<D>, length: f64) -> f64 {
    (LONG * natural_time(gap)).max(LEAST_PIECE).min(length)
}

/// The shortest piece: the smallest normal time, so that a time scale that rounds to 0
/// (lengths whose squares underflow: beyond the range where the search is exact) cannot stall
/// the pieces, which then double up to the window's end (at most about 2,100 of them).
const LEAST_PIECE: f64 = f64::MIN_POSITIVE;

/// The end of the piece that starts at `start` (where the gap is `gap`, re-expanded there),
/// in a window of `length`: `LONG` of the gap's time scales on, at least twice as far from the
/// window's start, and at most the window's end.
pub(crate) fn next_piece<const D: usize>(gap: &Gap<D>, start: f64, length: f64) -> f64 {
    let step = (LONG * natural_time(gap)).max(start).max(LEAST_PIECE);
    (start + step).min(length)
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
            contact_distance: 0.5,
        }
    }

    #[test]
    fn a_table_window_is_not_long() {
        let g = gap([1.0, 0.5], [-2.0, 0.1], [0.1, -0.05]);
        assert!(!long_window(&g, 100.0));
        assert!(long_window(&g, 1e20));
    }

    #[test]
    fn a_window_at_rest_is_never_long() {
        let g = gap([1.0, 0.5], [0.0, 0.0], [0.0, 0.0]);
        assert!(!long_window(&g, 1e300));
        assert_eq!(natural_time(&g), f64::INFINITY);
    }

    #[test]
    fn an_overflowing_window_is_long() {
        let g = gap([1.0, 0.5], [1e-10, 0.0], [1e-30, 0.0]);
        assert!(long_window(&g, 1e300));
    }

    #[test]
    fn pieces_grow_at_least_geometrically() {
        let g = gap([1.0, 0.0], [1.0, 0.0], [0.0, 0.0]);
        let first = first_piece(&g, 1e300);
        assert!(first > 1e12 && first < 1e13);
        assert!(next_piece(&g, 1e20, 1e300) >= 2e20);
        assert_eq!(next_piece(&g, 6e299, 1e300), 1e300);
    }
}
