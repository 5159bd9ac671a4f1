//! The calendar's static objects: a [`Table`] in a grid of its own, and a ball's first
//! contact with the objects its box meets.
//!
//! Each object is listed, by its box (rounded outwards), in the cells of a uniform grid over
//! the objects' region; objects unbounded on every axis (a plane at an angle to every axis)
//! in a list of their own, always asked. A ball's box ([`Reach`], its radius and rounding
//! margin included) meets the box of every object it touches over its span, so the objects
//! whose boxes it misses are left out without changing the answer: on a pool table a rolling
//! ball asks the two or three objects near it, not all 36.

use super::grid::Grid;
use super::reach::Reach;
use crate::geometry::{ObjectContact, ObjectKind, Table, TablePath, object_contact};
use crate::path::Segment;

/// One object: its kind, index among its kind, and box.
#[derive(Clone, Copy, Debug)]
struct Entry<const D: usize> {
    kind: ObjectKind,
    index: u32,
    reach: Reach<D>,
}

/// A calendar's objects (see the module documentation).
#[derive(Clone, Debug)]
pub(crate) struct Objects<const D: usize> {
    table: Table<D>,
    entries: Vec<Entry<D>>,
    /// The entries bounded on some axis, by box (ids into `entries`).
    grid: Grid<D>,
    /// The entries unbounded on every axis.
    everywhere: Vec<u32>,
    /// Scratch: a mark per entry (to ask each once), the candidates, a planar path.
    marks: Vec<u32>,
    mark: u32,
    candidates: Vec<u32>,
    planar: Vec<Segment<2>>,
    /// How many ball–object pairs the grid and the boxes left out, and how many were asked.
    pub(crate) counts: ObjectCounts,
}

/// How many ball–object pairs a calendar's object searches left out (their boxes apart) and
/// asked (see [`CollisionSchedule::object_counts`](super::CollisionSchedule::object_counts)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ObjectCounts {
    /// Object searches (one per ball key refreshed).
    pub searches: u64,
    /// Ball–object pairs left out: objects not listed in the ball's cells, or whose box
    /// misses the ball's.
    pub pruned: u64,
    /// Ball–object pairs asked (each a query of its own).
    pub asked: u64,
}

impl<const D: usize> Objects<D> {
    /// The objects of `table`, in a grid of cells of about `cell`.
    pub(crate) fn new(table: Table<D>, cell: f64) -> Self {
        let mut entries = Vec::with_capacity(table.len());
        for kind in ObjectKind::ALL {
            for index in 0..table.count(kind) {
                let (lo, hi) = table
                    .object_box(kind, index)
                    .unwrap_or(([f64::NEG_INFINITY; D], [f64::INFINITY; D]));
                entries.push(Entry {
                    kind,
                    index: index as u32,
                    reach: Reach { lo, hi },
                });
            }
        }
        let bounded =
            |e: &Entry<D>| (0..D).any(|k| e.reach.lo[k].is_finite() || e.reach.hi[k].is_finite());
        // The region: the finite bounds of the bounded boxes.
        let (mut lo, mut hi) = ([f64::INFINITY; D], [f64::NEG_INFINITY; D]);
        for e in entries.iter().filter(|e| bounded(e)) {
            for k in 0..D {
                for x in [e.reach.lo[k], e.reach.hi[k]] {
                    if x.is_finite() {
                        lo[k] = lo[k].min(x);
                        hi[k] = hi[k].max(x);
                    }
                }
            }
        }
        for k in 0..D {
            if lo[k] > hi[k] {
                (lo[k], hi[k]) = (0.0, 1.0);
            }
        }
        let listed = entries.iter().filter(|e| bounded(e)).count();
        let mut grid = Grid::new(lo, hi, cell, listed);
        let mut everywhere = Vec::new();
        for (id, e) in entries.iter().enumerate() {
            if bounded(e) {
                let range = grid.range(&e.reach);
                grid.insert(id as u32, &range);
            } else {
                everywhere.push(id as u32);
            }
        }
        Self {
            marks: vec![0; entries.len()],
            table,
            entries,
            grid,
            everywhere,
            mark: 0,
            candidates: Vec::new(),
            planar: Vec::new(),
            counts: ObjectCounts::default(),
        }
    }

    /// The table.
    pub(crate) fn table(&self) -> &Table<D> {
        &self.table
    }

    /// The earliest contact at or after `from` of a ball of `radius` on `segments` with the
    /// objects whose boxes meet `reach`, each object's contact its first from the path's
    /// first start (as [`crate::geometry::path_table_contact`] finds it); in the order of
    /// [`ObjectContact::before`].
    pub(crate) fn first_contact(
        &mut self,
        segments: &[Segment<D>],
        radius: f64,
        reach: &Reach<D>,
        from: f64,
        t_max: f64,
    ) -> Option<ObjectContact> {
        self.mark = self.mark.wrapping_add(1);
        if self.mark == 0 {
            self.marks.fill(0);
            self.mark = 1;
        }
        let (marks, mark, entries) = (&mut self.marks, self.mark, &self.entries);
        let mut candidates = std::mem::take(&mut self.candidates);
        candidates.clear();
        let mut consider = |id: u32| {
            let m = &mut marks[id as usize];
            if *m != mark {
                *m = mark;
                if entries[id as usize].reach.overlaps(reach) {
                    candidates.push(id);
                }
            }
        };
        let range = self.grid.range(reach);
        self.grid.for_each_ball(&range, &mut consider);
        for &id in &self.everywhere {
            consider(id);
        }
        self.counts.searches += 1;
        self.counts.pruned += self.entries.len() as u64 - candidates.len() as u64;
        self.counts.asked += candidates.len() as u64;
        let mut path = TablePath::new(segments, &mut self.planar);
        let mut best: Option<ObjectContact> = None;
        for &id in &candidates {
            let e = self.entries[id as usize];
            let index = e.index as usize;
            let Some(time) = object_contact(&mut path, &self.table, e.kind, index, radius, t_max)
            else {
                continue;
            };
            let contact = ObjectContact {
                time,
                kind: e.kind,
                index,
            };
            if time >= from && best.is_none_or(|b| contact.before(&b)) {
                best = Some(contact);
            }
        }
        self.candidates = candidates;
        best
    }

    /// The heap memory held, in bytes.
    pub(crate) fn heap_bytes(&self) -> usize {
        use std::mem::size_of;
        self.entries.capacity() * size_of::<Entry<D>>()
            + self.grid.heap_bytes()
            + (self.everywhere.capacity() + self.marks.capacity() + self.candidates.capacity())
                * size_of::<u32>()
            + self.planar.capacity() * size_of::<Segment<2>>()
            + self.table.segments.capacity() * size_of::<crate::geometry::LineSegment>()
            + self.table.circles.capacity() * size_of::<crate::geometry::Circle<D>>()
            + self.table.targets.capacity() * size_of::<crate::geometry::Target<D>>()
            + self.table.planes.capacity() * size_of::<crate::geometry::Plane<D>>()
    }
}
