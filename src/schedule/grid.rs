//! The incremental broad phase: a uniform grid of cells, each listing the balls whose box
//! ([`Reach`]) meets it.
//!
//! The grid covers a region (the walls' box, or the balls' first boxes) in cubic cells of one
//! size; a box is listed in every cell its cell range covers, coordinates outside the region
//! being clamped to its border cells (so a box that is unbounded on an axis, or has left the
//! region, is listed along the border: still found, only at more cost). Clamping keeps order,
//! so two boxes that overlap always share a cell. Moving a ball touches only the cells of its
//! old and new boxes.
//!
//! A box whose range covers more than an eighth of the cells (a ball moving for ever in open
//! space from near a corner of the region, say, whose box runs to the far border on two axes)
//! is listed once, in a list of *wide* boxes that every query looks through, rather than in
//! each of its cells: listed there, it costs a push per cell to place and a search of the
//! cell's list per cell to take out, every time it moves, and a query meets it in at least an
//! eighth of the cases anyway. (Measured in one run on 1,000 balls moving side by side from a
//! corner of the grid, each box over most of it, `corner_open` in `examples/
//! open_space_timing.rs`: the first `next_collision` in 0.52 s, against 1.15 s with every box
//! listed in its cells and 0.64 s with half the cells as the threshold.)

use super::reach::Reach;
use crate::prefetch::prefetch;

/// At most this many cells per ball (plus a few): the cell size grows if the region would
/// need more.
const CELLS_PER_BALL: usize = 2;

/// The fewest balls for which the searches ask for their lines ahead ([`Grid::asks_ahead`]):
/// 2¹⁶ balls' boxes, lists and paths (some 10 MB) outgrow a core's second-level cache. In a
/// smaller scene, held in the caches, the prefetches cost more than they save (3 % more per
/// event at 1,024 balls, `schedule_timing`).
const PREFETCH_BALLS: usize = 1 << 16;

/// The most cells a search asks for ahead: a wider range (a box up to an eighth of the
/// grid) would ask for more lines than the first-level cache keeps until they are read.
const PREFETCH_RANGE: usize = 64;

/// Up to this many balls, one cell: each ball's boxes are compared with every other's, which
/// costs less than listing them in cells (measured on the benchmark's frictionless disks).
/// (The calendar keeps a bit per ball for the first 64 balls of a one-cell grid.)
pub(crate) const ONE_CELL: usize = 16;
const _: () = assert!(ONE_CELL <= 64);

/// A ball's cell range: the lowest and highest cell index on each axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct CellRange<const D: usize> {
    lo: [u32; D],
    hi: [u32; D],
}

impl<const D: usize> CellRange<D> {
    /// How many cells the range covers (saturating).
    fn cells(&self) -> usize {
        (0..D).fold(1usize, |n, k| {
            n.saturating_mul(self.hi[k].saturating_sub(self.lo[k]) as usize + 1)
        })
    }
}

/// The grid: cell size, origin, cells per axis, each cell's balls, and the wide boxes' balls.
#[derive(Clone, Debug)]
pub(crate) struct Grid<const D: usize> {
    origin: [f64; D],
    inverse_size: f64,
    counts: [usize; D],
    cells: Vec<Vec<u32>>,
    wide: Vec<u32>,
    /// Whether the searches ask for their lines ahead ([`PREFETCH_BALLS`]).
    asks_ahead: bool,
}

impl<const D: usize> Grid<D> {
    /// A grid over `[lo, hi]` with cells of about `size` (finite bounds, `size > 0`), made
    /// coarser if it would have more than about [`CELLS_PER_BALL`] cells per ball of `balls`.
    pub(crate) fn new(lo: [f64; D], hi: [f64; D], size: f64, balls: usize) -> Self {
        let most = CELLS_PER_BALL * balls + 16;
        let mut size = size;
        let counts = loop {
            if balls <= ONE_CELL {
                break [1; D];
            }
            let counts: [usize; D] =
                std::array::from_fn(|k| cells_along(hi[k] - lo[k], size).min(1 << 20));
            let total = counts.iter().try_fold(1usize, |n, &c| n.checked_mul(c));
            match total {
                Some(total) if total <= most => break counts,
                _ => size *= 2.0,
            }
        };
        let total = counts.iter().product();
        Self {
            origin: lo,
            inverse_size: 1.0 / size,
            counts,
            cells: vec![Vec::new(); total],
            wide: Vec::new(),
            asks_ahead: balls >= PREFETCH_BALLS && total > 1,
        }
    }

    /// The cells a box covers, clamped to the grid.
    pub(crate) fn range(&self, reach: &Reach<D>) -> CellRange<D> {
        if self.is_one_cell() {
            return CellRange {
                lo: [0; D],
                hi: [0; D],
            };
        }
        CellRange {
            lo: std::array::from_fn(|k| self.cell_along(k, reach.lo[k])),
            hi: std::array::from_fn(|k| self.cell_along(k, reach.hi[k])),
        }
    }

    /// Whether the grid is one cell (few balls): every ball is listed there.
    pub(crate) fn is_one_cell(&self) -> bool {
        self.cells.len() == 1
    }

    /// Whether a box of this range is listed among the wide ones (see the module's notes):
    /// it covers more than an eighth of the cells.
    fn is_wide(&self, range: &CellRange<D>) -> bool {
        range.cells() > self.cells.len() / 8
    }

    /// Lists `ball` in the cells of `range` (or among the wide boxes).
    pub(crate) fn insert(&mut self, ball: u32, range: &CellRange<D>) {
        if self.is_wide(range) {
            self.wide.push(ball);
            return;
        }
        self.for_each_cell(range, |cells, c| cells[c].push(ball));
    }

    /// Takes `ball` out of the cells of `range` (where it was listed, or the wide boxes).
    pub(crate) fn remove(&mut self, ball: u32, range: &CellRange<D>) {
        let take = |list: &mut Vec<u32>| {
            if let Some(at) = list.iter().position(|&b| b == ball) {
                list.swap_remove(at);
            }
        };
        if self.is_wide(range) {
            take(&mut self.wide);
            return;
        }
        self.for_each_cell(range, |cells, c| take(&mut cells[c]));
    }

    /// Calls `visit` with every ball listed in the cells of `range` (a ball once per cell it
    /// shares with the range), and with every ball of a wide box.
    pub(crate) fn for_each_ball(&self, range: &CellRange<D>, mut visit: impl FnMut(u32)) {
        self.for_each_cell_in(range, |_, cell| {
            for &ball in cell {
                visit(ball);
            }
        });
        for &ball in &self.wide {
            visit(ball);
        }
    }

    /// Calls `visit` once with every ball whose box (`boxes[ball]`) overlaps `own`, among
    /// those listed in the cells of `range` (`own`'s range) and the wide boxes, each listed
    /// ball's range being that of its box. A ball listed in several of those cells is
    /// visited only in the lowest cell both ranges share (its range's low corner, or
    /// `range`'s, whichever is higher on each axis): no marks to read and write per ball,
    /// only its box, which the overlap needs anyway.
    pub(crate) fn for_each_overlapping(
        &self,
        range: &CellRange<D>,
        own: &Reach<D>,
        boxes: &[Reach<D>],
        mut visit: impl FnMut(u32),
    ) {
        // In a large scene each cell's list and each listed ball's box is a cache miss, and
        // each list's address is read from its cell: the lines are asked for a step at a
        // time over the whole range (the cells, then their lists, then the boxes), so that
        // the misses of a step overlap, before the boxes are compared.
        if self.asks_ahead && range.cells() <= PREFETCH_RANGE {
            self.for_each_cell_in(range, |_, cell| prefetch(cell));
            self.for_each_cell_in(range, |_, cell| prefetch(cell.as_ptr()));
            self.for_each_cell_in(range, |_, cell| {
                for &ball in cell {
                    prefetch(&boxes[ball as usize]);
                }
            });
        }
        self.for_each_cell_in(range, |index, cell| {
            for &ball in cell {
                let other = &boxes[ball as usize];
                if other.overlaps(own) && self.first_shared(index, range, other) {
                    visit(ball);
                }
            }
        });
        for &ball in &self.wide {
            if boxes[ball as usize].overlaps(own) {
                visit(ball);
            }
        }
    }

    /// Whether the scene is large enough for the searches (the grid's, and the pair searches
    /// after them) to ask for their lines ahead: see [`PREFETCH_BALLS`].
    #[inline(always)]
    pub(crate) fn asks_ahead(&self) -> bool {
        self.asks_ahead
    }

    /// Each cell of `range`, with its index, in order.
    #[inline(always)]
    fn for_each_cell_in(&self, range: &CellRange<D>, mut visit: impl FnMut(&[u32; D], &Vec<u32>)) {
        for (index, c) in self.cells_of(range) {
            visit(&index, &self.cells[c]);
        }
    }

    /// The cells of `range`, in order: each one's index and its place in `cells` (the
    /// iterator holds no borrow of the grid, so that the cells can be changed meanwhile).
    #[inline(always)]
    fn cells_of(&self, range: &CellRange<D>) -> impl Iterator<Item = ([u32; D], usize)> + use<D> {
        let (counts, range) = (self.counts, *range);
        let mut next = Some(range.lo);
        std::iter::from_fn(move || {
            let index = next?;
            let mut following = index;
            next = next_index(&mut following, &range).then_some(following);
            let mut c = 0;
            for k in (0..D).rev() {
                c = c * counts[k] + index[k] as usize;
            }
            Some((index, c))
        })
    }

    /// Whether the cell at `index` (in `range`, and in the range of `other`, a box listed
    /// there) is the lowest cell the two ranges share.
    fn first_shared(&self, index: &[u32; D], range: &CellRange<D>, other: &Reach<D>) -> bool {
        (0..D).fold(true, |all, k| {
            all & (index[k] == range.lo[k].max(self.cell_along(k, other.lo[k])))
        })
    }

    /// The cell along axis `k` of coordinate `x`, clamped to the grid (as [`range`](Self::range)).
    fn cell_along(&self, k: usize, x: f64) -> u32 {
        // Clamped first, then truncated: the floor (no call to `floor` in a build without
        // SSE4.1). NaN (never from valid boxes) and −∞ go to cell 0.
        let last = (self.counts[k] - 1) as f64;
        ((x - self.origin[k]) * self.inverse_size)
            .clamp(0.0, last)
            .max(0.0) as u32
    }

    /// The heap memory of the grid, in bytes.
    pub(crate) fn heap_bytes(&self) -> usize {
        self.wide.capacity() * std::mem::size_of::<u32>()
            + self.cells.capacity() * std::mem::size_of::<Vec<u32>>()
            + self
                .cells
                .iter()
                .map(|c| c.capacity() * std::mem::size_of::<u32>())
                .sum::<usize>()
    }

    fn for_each_cell(
        &mut self,
        range: &CellRange<D>,
        mut visit: impl FnMut(&mut [Vec<u32>], usize),
    ) {
        for (_, c) in self.cells_of(range) {
            visit(&mut self.cells, c);
        }
    }
}

/// Cells of `size` needed along a length (at least one; a non-finite quotient gives one).
fn cells_along(length: f64, size: f64) -> usize {
    let n = (length / size).ceil();
    if n.is_finite() && n >= 1.0 {
        n as usize
    } else {
        1
    }
}

/// The next cell index of `range` in odometer order; `false` after the last.
fn next_index<const D: usize>(index: &mut [u32; D], range: &CellRange<D>) -> bool {
    for (k, i) in index.iter_mut().enumerate() {
        if *i < range.hi[k] {
            *i += 1;
            return true;
        }
        *i = range.lo[k];
    }
    false
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overlapping_boxes_share_a_cell_even_outside_the_region() {
        // 8 × 8 cells: no box here covers more than an eighth of them.
        let mut grid = Grid::<2>::new([0.0, 0.0], [8.0, 8.0], 1.0, 100);
        let a = Reach {
            lo: [0.5, 0.5],
            hi: [1.5, 1.2],
        };
        let far = Reach {
            lo: [9.0, -3.0],
            hi: [f64::INFINITY, -2.0],
        };
        let (ra, rf) = (grid.range(&a), grid.range(&far));
        grid.insert(0, &ra);
        grid.insert(1, &rf);
        let mut seen = Vec::new();
        grid.for_each_ball(
            &grid.range(&Reach {
                lo: [8.0, -9.0],
                hi: [10.0, -1.0],
            }),
            |b| seen.push(b),
        );
        assert_eq!(seen, [1]);
        seen.clear();
        grid.for_each_ball(
            &grid.range(&Reach {
                lo: [1.4, 1.1],
                hi: [1.6, 1.3],
            }),
            |b| seen.push(b),
        );
        assert_eq!(seen, [0]);
        grid.remove(0, &ra);
        seen.clear();
        grid.for_each_ball(&ra, |b| seen.push(b));
        assert!(seen.is_empty());
    }

    #[test]
    fn a_box_over_more_than_an_eighth_of_the_cells_is_listed_once_and_found_everywhere() {
        // 4 × 4 cells; ball 0 everywhere (its margin overflowed), ball 1 over 3 × 3 cells
        // (from near a corner to the far border), ball 2 over 2 cells, ball 3 in one.
        let mut grid = Grid::<2>::new([0.0, 0.0], [4.0, 4.0], 1.0, 100);
        assert_eq!(grid.cells.len(), 16);
        let range = |grid: &Grid<2>, lo: [f64; 2], hi: [f64; 2]| grid.range(&Reach { lo, hi });
        let everywhere = range(&grid, [f64::NEG_INFINITY; 2], [f64::INFINITY; 2]);
        let corner = range(&grid, [1.5, 1.5], [f64::INFINITY; 2]);
        let two = range(&grid, [0.5, 0.5], [0.9, 1.5]);
        let one = range(&grid, [0.2, 3.2], [0.4, 3.4]);
        assert!(grid.is_wide(&everywhere) && grid.is_wide(&corner));
        assert!(!grid.is_wide(&two) && !grid.is_wide(&one));
        for (ball, r) in [&everywhere, &corner, &two, &one].into_iter().enumerate() {
            grid.insert(ball as u32, r);
        }
        assert_eq!(grid.wide, [0, 1]);
        let listed: usize = grid.cells.iter().map(Vec::len).sum();
        assert_eq!(listed, 2 + 1);
        let seen = |grid: &Grid<2>, range: &CellRange<2>| {
            let mut seen = Vec::new();
            grid.for_each_ball(range, |b| seen.push(b));
            seen.sort_unstable();
            seen.dedup();
            seen
        };
        assert_eq!(seen(&grid, &one), [0, 1, 3]);
        assert_eq!(seen(&grid, &everywhere), [0, 1, 2, 3]);
        grid.remove(0, &everywhere);
        grid.remove(2, &two);
        assert_eq!(grid.wide, [1]);
        assert_eq!(seen(&grid, &everywhere), [1, 3]);
    }

    #[test]
    fn only_a_large_scene_asks_for_its_lines_ahead() {
        let grid = |balls| Grid::<2>::new([0.0, 0.0], [1000.0, 1000.0], 1.0, balls);
        assert!(grid(PREFETCH_BALLS).asks_ahead());
        assert!(!grid(PREFETCH_BALLS - 1).asks_ahead());
        assert!(!grid(1024).asks_ahead());
    }

    #[test]
    fn every_overlapping_box_is_visited_once() {
        let mut rng = crate::test_rng::Rng(3);
        for round in 0..200 {
            let n = 2 + rng.below(80) as usize;
            let mut grid = Grid::<2>::new([0.0, 0.0], [10.0, 10.0], 0.7, n);
            // Every other round as in a large scene, the lines asked for ahead (the same
            // visits, whatever the hint).
            grid.asks_ahead = round % 2 == 1;
            // Boxes of every size, some past the region, some unbounded, some NaN (retired).
            let boxes: Vec<Reach<2>> = (0..n)
                .map(|k| {
                    let lo = [rng.uniform(-2.0, 11.0), rng.uniform(-2.0, 11.0)];
                    let w = if k % 7 == 0 { 8.0 } else { 1.5 };
                    let mut hi = [lo[0] + rng.uniform(0.0, w), lo[1] + rng.uniform(0.0, w)];
                    if k % 11 == 0 {
                        hi[round % 2] = f64::INFINITY;
                    }
                    let nan = k % 13 == 5;
                    Reach {
                        lo: if nan { [f64::NAN; 2] } else { lo },
                        hi: if nan { [f64::NAN; 2] } else { hi },
                    }
                })
                .collect();
            // Listed where its box was before it went NaN: anywhere.
            let ranges: Vec<CellRange<2>> = boxes
                .iter()
                .map(|b| match b.lo[0].is_nan() {
                    true => grid.range(&Reach {
                        lo: [1.0, 1.0],
                        hi: [2.0, 2.0],
                    }),
                    false => grid.range(b),
                })
                .collect();
            for (k, range) in ranges.iter().enumerate() {
                grid.insert(k as u32, range);
            }
            for (i, own) in boxes.iter().enumerate() {
                let mut seen = Vec::new();
                grid.for_each_overlapping(&ranges[i], own, &boxes, |k| seen.push(k as usize));
                seen.sort_unstable();
                let expected: Vec<usize> = (0..n).filter(|&k| boxes[k].overlaps(own)).collect();
                assert_eq!(seen, expected, "round {round}, box {i}");
            }
        }
    }

    #[test]
    fn a_grid_that_would_be_too_fine_is_coarsened() {
        let grid = Grid::<3>::new([0.0; 3], [1.0; 3], 1e-6, 10);
        assert!(grid.cells.len() <= CELLS_PER_BALL * 10 + 16);
    }
}
