//! The first windows of the pairs of paths that the lane-wise screens take and leave open,
//! settled eight at a time on their first open eighth.
//!
//! The pairs the screens ([`path_lanes`](super::path_lanes)) take whole and cannot prove
//! apart are held back (a [`BlockQueue`](super::block_queue::BlockQueue)) until a block of them is full; each one's first
//! window is then formed as the walk over windows would form it
//! ([`PathFirstWindow`]), and all eight are settled at once, by the branch-free entry on
//! the window's first open eighth ([`PathFirstWindow::eighth_contact`]), in one loop that the
//! compiler runs in vectors. Most contacts of balls on a table come in the first window and
//! are plain there; the pairs answered so skip the walk; a pair whose first window is found
//! free of entries is walked from its second window on; the others are walked whole. The
//! answers are the same bits as if the pairs had never been held.
//!
//! On the seed model written as paths (200,000 random table pairs), the lanes leave 9,720
//! pairs: 3,801 are answered here, 2,003 are walked from their second window, and 3,916 walked
//! whole.

use super::paths::PathPairs;
use crate::collision::length_unit::largest;
use crate::collision::path_contact::PathFirstWindow;
use crate::path::Segment;
use crate::simd::LANES;

/// What the first windows of pairs `offset + block[l]` settle
/// ([`PathFirstWindow::eighth_contact`]): their answers where they find an entry, NaN for
/// the others, and which are free of entries. The pairs must be ones the lanes took whole:
/// valid, rows of `K` all used, starts increasing strictly, radius and horizon valid.
#[inline(always)]
pub(super) fn eighth_contacts<const D: usize, const K: usize>(
    pairs: &PathPairs<'_, D>,
    offset: usize,
    block: &[usize; LANES],
) -> ([f64; LANES], [bool; LANES]) {
    // (A loop, not `array::map`: its closure would be compiled apart, without the caller's
    // target features.)
    let mut windows = [PathFirstWindow::<D>::at_rest(); LANES];
    for (window, &k) in windows.iter_mut().zip(block) {
        *window = first_window::<D, K>(pairs, offset + k);
    }
    // A loop over the lanes with nothing but arithmetic and selects in it, into an array of
    // each kind (pairs of them are not vectorised): the compiler runs it in vectors, one
    // lane per pair.
    let (mut contacts, mut free) = ([f64::NAN; LANES], [false; LANES]);
    for ((contact, free), window) in contacts.iter_mut().zip(&mut free).zip(&windows) {
        (*contact, *free) = window.eighth_contact();
    }
    (contacts, free)
}

/// Pair `i`'s first window, as its walk forms it: at the later of the two first starts, the
/// segment of each path active then (the last whose start is not after it), until the earlier
/// of their ends.
#[inline(always)]
fn first_window<const D: usize, const K: usize>(
    pairs: &PathPairs<'_, D>,
    i: usize,
) -> PathFirstWindow<D> {
    let (start_a, rows_a) = pairs.a.rows::<K>(i);
    let (start_b, rows_b) = pairs.b.rows::<K>(i);
    // `+ 0.0`: as the walk's first time, +0 for a first start of −0.
    let start = start_a[0][0].max(start_b[0][0]) + 0.0;
    let (a, end_a) = active(start_a[0], rows_a, start);
    let (b, end_b) = active(start_b[0], rows_b, start);
    let mut most = 0.0;
    for rows in rows_a.iter().chain(&rows_b) {
        for row in rows.iter() {
            most = largest([most, largest(*row)]);
        }
    }
    PathFirstWindow {
        a,
        b,
        start,
        end: end_a.min(end_b),
        largest: most,
        radius: pairs.contact_distance.get(i),
        t_max: pairs.t_max.get(i),
    }
}

/// The segment of a path (its rows, starts increasing strictly) active at `t`, at or after
/// its first start, and when it ends.
#[inline(always)]
fn active<const D: usize>(
    starts: &[f64],
    [pos, vel, acc]: [&[[f64; D]]; 3],
    t: f64,
) -> (Segment<D>, f64) {
    let k = starts[1..].iter().filter(|&&s| s <= t).count();
    let segment = Segment {
        start: starts[k],
        position: pos[k].into(),
        velocity: vel[k].into(),
        acceleration: acc[k].into(),
    };
    (segment, starts.get(k + 1).copied().unwrap_or(f64::INFINITY))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::batch::{PathRows, PerPair};
    use crate::collision::path_bounds::PathBounds;
    use crate::collision::path_contact::{Prior, first_contact_bounded};
    use crate::path::Path2;
    use crate::test_path_rows::RowSpec;
    use crate::test_rng::Rng;
    use nalgebra::Vector2;

    /// `n` 2-D paths of `K` segments with starts increasing strictly (what the lanes take),
    /// near each other on a table: random accelerations, the last segment often at rest, a
    /// first start of 0 or a little later.
    fn rows<const K: usize>(rng: &mut Rng, n: usize) -> (Vec<f64>, [Vec<[f64; 2]>; 3]) {
        RowSpec::<2> {
            segments: K,
            every_row_used: true,
            later_first_start: 0.25,
            first_start: [0.0, 0.3],
            length: [0.01, 0.8],
            empty: 0.0,
            pos: RowSpec::each_axis(0.0, 0.6),
            continuous: true,
            vel: RowSpec::each_axis(-2.0, 2.0),
            acc: RowSpec::each_axis(-3.0, 3.0),
            last_at_rest: 0.5,
        }
        .draw(rng, n)
    }

    fn first_window_lanes_give_the_walks_bits<const K: usize>() {
        let mut rng = Rng(40 + K as u64);
        let n = 8 * 2_000;
        let (start_a, [pos_a, vel_a, acc_a]) = rows::<K>(&mut rng, n);
        let (start_b, [pos_b, vel_b, acc_b]) = rows::<K>(&mut rng, n);
        let side = |start, pos, vel, acc| PathRows {
            start,
            pos,
            vel,
            acc,
            segments: K,
        };
        let radius: Vec<f64> = (0..n).map(|_| rng.uniform(0.05, 0.3)).collect();
        let t_max: Vec<f64> = (0..n)
            .map(|_| {
                if rng.below(5) == 0 {
                    rng.uniform(0.0, 1.0)
                } else {
                    f64::INFINITY
                }
            })
            .collect();
        let pairs = PathPairs {
            a: side(&start_a, &pos_a, &vel_a, &acc_a),
            b: side(&start_b, &pos_b, &vel_b, &acc_b),
            contact_distance: PerPair::Each(&radius),
            t_max: PerPair::Each(&t_max),
        };
        let path = |side: &PathRows<'_, 2>, i: usize| {
            let (start, [pos, vel, acc]) = side.rows::<K>(i);
            let segments = (0..K).map(|k| {
                Segment::new(
                    start[0][k],
                    Vector2::from(pos[k]),
                    Vector2::from(vel[k]),
                    Vector2::from(acc[k]),
                )
            });
            Path2::new(segments.collect()).expect("valid rows")
        };
        let (mut found, mut free) = (0, 0);
        for first in (0..n).step_by(LANES) {
            let block: [usize; LANES] = std::array::from_fn(|l| first + l);
            let (contacts, frees) = eighth_contacts::<2, K>(&pairs, 0, &block);
            for (l, (&contact, &is_free)) in contacts.iter().zip(&frees).enumerate() {
                let i = first + l;
                let (a, b) = (path(&pairs.a, i), path(&pairs.b, i));
                let (a, b) = (a.segments(), b.segments());
                let bounds = (PathBounds::<2>::of(a), PathBounds::<2>::of(b));
                let walk = |prior| {
                    first_contact_bounded(
                        (a, &bounds.0),
                        (b, &bounds.1),
                        [radius[i], 0.0],
                        t_max[i],
                        prior,
                    )
                    .unwrap_or(f64::INFINITY)
                };
                let answer = walk(Prior::Nothing);
                assert!(!is_free || contact.is_nan(), "pair {i}: both");
                if !contact.is_nan() {
                    assert_eq!(contact.to_bits(), answer.to_bits(), "pair {i}");
                    found += 1;
                }
                if is_free {
                    let after = walk(Prior::FirstWindowScreenedOut);
                    assert_eq!(after.to_bits(), answer.to_bits(), "pair {i} (free)");
                    free += 1;
                }
            }
        }
        // Both findings, often (else the test could not fail).
        assert!(found > 1_000 && free > 1_000, "{found} found, {free} free");
    }

    #[test]
    fn first_window_lanes_give_the_walks_bits_in_rows_of_two() {
        first_window_lanes_give_the_walks_bits::<2>();
    }

    #[test]
    fn first_window_lanes_give_the_walks_bits_in_rows_of_three() {
        first_window_lanes_give_the_walks_bits::<3>();
    }
}
