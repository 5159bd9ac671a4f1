//! Many balls on paths against one table of static objects at once:
//! [`path_geometry_times`], over rows, in parallel, into the caller's columns.
//!
//! The paths are one side of a path batch ([`PathRows`]: `(N, K)` and `(N, K, D)` rows,
//! padded with `+∞` starts; one path may stand for all); the objects are a
//! [`Table`], checked when it was made. Each path's answer is that of
//! [`path_table_contact`](crate::geometry::path_table_contact) (through the same
//! function), so batch and single answers are identical, and so are the answers for any number
//! of threads. The answers go into three columns, the layout numpy hands back
//! ([`ContactColumns`]): the time, the object's kind ([`ObjectKind::code`]) and its index.

use super::paths::{NAMES_ONE, PathRows, check_side, read_path, shared_path};
use super::{CHUNK, PerPair, Threads, check_len, run_chunks_of};
use crate::error::{InputError, check_ball_radius, check_horizon};
use crate::geometry::{ObjectContact, Table, first_table_contact};
use crate::path::Segment;

/// Where a batch of geometry queries writes its answers: for path `i`, `time[i]` (absolute;
/// `∞` for no contact), `kind[i]` (the object's kind, [`ObjectKind::code`], `−1` for none)
/// and `index[i]` (its index among the table's objects of its kind, `−1` for none). The three
/// columns must have the same length, the number of queries.
///
/// [`ObjectKind::code`]: crate::geometry::ObjectKind::code
///
/// ```
/// use ballcollide::batch::ContactColumns;
/// let (mut time, mut kind, mut index) = ([0.0; 2], [0i8; 2], [0i64; 2]);
/// let out = ContactColumns { time: &mut time, kind: &mut kind, index: &mut index };
/// assert_eq!(out.len(), 2);
/// ```
#[derive(Debug)]
pub struct ContactColumns<'a> {
    /// The contact times (`∞`: none).
    pub time: &'a mut [f64],
    /// The objects' kinds, as [`ObjectKind::code`](crate::geometry::ObjectKind::code) (`−1`:
    /// none).
    pub kind: &'a mut [i8],
    /// The objects' indices within their kind (`−1`: none).
    pub index: &'a mut [i64],
}

impl ContactColumns<'_> {
    /// The number of queries: the length of `time` (example: [`ContactColumns`]).
    pub fn len(&self) -> usize {
        self.time.len()
    }

    /// Whether there is no query.
    pub fn is_empty(&self) -> bool {
        self.time.is_empty()
    }

    /// Writes query `k`'s answer.
    fn set(&mut self, k: usize, contact: Option<ObjectContact>) {
        let (time, kind, index) = match contact {
            // (Kind codes are 0 to 3; indices of objects in memory fit in 64 bits.)
            Some(c) => (
                c.time,
                c.kind.code() as i8,
                i64::try_from(c.index).unwrap_or(i64::MAX),
            ),
            None => (f64::INFINITY, -1, -1),
        };
        self.time[k] = time;
        self.kind[k] = kind;
        self.index[k] = index;
    }

    /// The columns split into parts of `size` queries (the last may be shorter).
    fn parts(&mut self, size: usize) -> Vec<ContactColumns<'_>> {
        let size = size.max(1);
        self.time
            .chunks_mut(size)
            .zip(self.kind.chunks_mut(size))
            .zip(self.index.chunks_mut(size))
            .map(|((time, kind), index)| ContactColumns { time, kind, index })
            .collect()
    }
}

/// Object queries handed to one task: some milliseconds of work at most, so that a call stops
/// soon after its [`Interrupt`](crate::interrupt::Interrupt) flag is set, and enough that
/// scheduling costs nothing.
const QUERIES_A_CHUNK: usize = 8 * CHUNK;

/// The paths one task takes, for a table of `objects` objects: [`QUERIES_A_CHUNK`] object
/// queries, at least one path and at most [`CHUNK`].
fn paths_a_chunk(objects: usize) -> usize {
    (QUERIES_A_CHUNK / objects.max(1)).clamp(1, CHUNK)
}

/// The first contact of each path of `paths` (or of its only path, for every query) with any
/// object of `table`, a ball of radius `radius`, horizon `t_max`: what
/// [`path_table_contact`](crate::geometry::path_table_contact) gives for that path, written to
/// `out` (see [`ContactColumns`]): at equal times the lowest kind
/// ([`ObjectKind`](crate::geometry::ObjectKind)'s order), then the lowest index.
///
/// # Errors
/// The first invalid query's error (lowest index), naming the argument, and for a path's
/// values the path and the segment (``vel[3, 1]: must be finite, got NaN``): a radius not
/// finite and `> 0`, a negative or NaN horizon; the paths must number 1 or `out.len()`, and
/// `radius`, `t_max` (if per query), `out.kind` and `out.index` have `out.len()` values.
/// Shapes and shared values come first (a broadcast path at query 0, even in an empty batch).
/// On error, `out` holds unspecified values.
///
/// ```
/// use ballcollide::batch::{ContactColumns, PathRows, PerPair, Threads, path_geometry_times};
/// use ballcollide::geometry::{LineSegment, ObjectKind, SegmentSide, Table, Target};
/// use nalgebra::Vector2;
///
/// // A cushion along y = 0 from x = 0 to 1, and a pocket past its end.
/// let table = Table {
///     segments: vec![LineSegment::new(Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), SegmentSide::Left)?],
///     targets: vec![Target::new(Vector2::new(1.2, 0.0), 0.05)?],
///     ..Default::default()
/// };
/// // Three balls rolling down at 1 m/s from y = 1: onto the cushion, into the pocket, past both.
/// let down = [[0.0, -1.0]; 3];
/// let paths = PathRows {
///     start: &[0.0; 3],
///     pos: &[[0.5, 1.0], [1.2, 1.0], [3.0, 1.0]],
///     vel: &down,
///     acc: &[[0.0; 2]; 3],
///     segments: 1,
/// };
/// let (mut time, mut kind, mut index) = ([0.0; 3], [0i8; 3], [0i64; 3]);
/// let out = ContactColumns { time: &mut time, kind: &mut kind, index: &mut index };
/// path_geometry_times(&paths, &table, PerPair::All(0.1), PerPair::All(f64::INFINITY), out, Threads::All)?;
/// assert!((time[0] - 0.9).abs() < 1e-15 && (time[1] - 0.95).abs() < 1e-15);
/// assert_eq!(time[2], f64::INFINITY);
/// assert_eq!(kind, [ObjectKind::Segment.code() as i8, ObjectKind::Target.code() as i8, -1]);
/// assert_eq!(index, [0, 0, -1]);
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn path_geometry_times<const D: usize>(
    paths: &PathRows<'_, D>,
    table: &Table<D>,
    radius: PerPair<'_>,
    t_max: PerPair<'_>,
    mut out: ContactColumns<'_>,
    threads: Threads,
) -> Result<(), InputError> {
    let n = out.len();
    let shared = check_path_geometry(paths, radius, t_max, n)?;
    check_len("kind", out.kind.len(), n)?;
    check_len("index", out.index.len(), n)?;
    let size = paths_a_chunk(table.len());
    let mut parts = out.parts(size);
    let queries = |parts: &[ContactColumns<'_>]| parts.iter().map(ContactColumns::len).sum();
    run_chunks_of(1, &mut parts, threads, queries, |part, one| {
        let mut buffers = (Vec::new(), Vec::new());
        for columns in one {
            let first = part * size;
            for k in 0..columns.len() {
                let i = first + k;
                let contact = query(paths, table, [radius, t_max], &shared, i, &mut buffers)?;
                columns.set(k, contact);
            }
        }
        Ok(())
    })
}

/// Query `i`'s answer: its path is the shared one if there is one, else read into
/// `buffers.0`; `buffers.1` is the scratch of [`first_table_contact`].
fn query<const D: usize>(
    paths: &PathRows<'_, D>,
    table: &Table<D>,
    [radius, t_max]: [PerPair<'_>; 2],
    shared: &Option<Vec<Segment<D>>>,
    i: usize,
    (path, scratch): &mut (Vec<Segment<D>>, Vec<Segment<2>>),
) -> Result<Option<ObjectContact>, InputError> {
    let segments = match shared {
        Some(segments) => segments.as_slice(),
        None => read_path::<D, 0>(paths, i, &NAMES_ONE, path).map_err(|e| e.in_pair(i))?,
    };
    let radius = check_ball_radius("radius", radius.get(i)).map_err(|e| e.at(i))?;
    let t_max = check_horizon("t_max", t_max.get(i)).map_err(|e| e.at(i))?;
    Ok(first_table_contact(segments, table, radius, t_max, scratch))
}

/// The checks of [`path_geometry_times`] on the inputs that need no query, for `n` queries: the
/// rows, 1 or `n` paths, `radius` and `t_max` of `n` values if per query and valid if shared;
/// the broadcast path, read and checked. The Python binding runs them before it looks at a
/// caller's `out` arrays.
pub(crate) fn check_path_geometry<const D: usize>(
    paths: &PathRows<'_, D>,
    radius: PerPair<'_>,
    t_max: PerPair<'_>,
    n: usize,
) -> Result<Option<Vec<Segment<D>>>, InputError> {
    check_side(paths, &NAMES_ONE, n)?;
    radius.check_len("radius", n)?;
    t_max.check_len("t_max", n)?;
    radius.check_shared("radius", check_ball_radius)?;
    t_max.check_shared("t_max", check_horizon)?;
    // A broadcast path is a shared value: checked here, even with no query to answer.
    shared_path(paths, &NAMES_ONE)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{Circle, LineSegment, ObjectKind, Plane, SegmentSide, Target};
    use crate::test_path_rows::RowSpec;
    use crate::test_rng::Rng;
    use crate::{CollisionOptions, Path};
    use nalgebra::{SVector, Vector2};
    use std::num::NonZeroUsize;

    /// A table of every kind of object in `D` dimensions: four cushions (touched from inside),
    /// two posts (circles) on the table, a pocket (target) at each corner, and (in 3-D) the bed;
    /// in 3-D the posts and the pockets sit at a height of 0.1.
    fn test_table<const D: usize>() -> Table<D> {
        let (w, h) = (2.54, 1.27);
        let corners = [[0.0, 0.0], [w, 0.0], [w, h], [0.0, h]];
        let at = |c: [f64; 2]| SVector::<f64, D>::from_fn(|k, _| if k < 2 { c[k] } else { 0.1 });
        let segments = (0..4)
            .filter_map(|k| {
                let (p, q) = (corners[k], corners[(k + 1) % 4]);
                LineSegment::new(p.into(), q.into(), SegmentSide::Left).ok()
            })
            .collect();
        let circles = [[0.8, 0.6], [1.7, 0.7]]
            .iter()
            .filter_map(|&c| Circle::new(at(c), 0.05).ok())
            .collect();
        let targets = corners
            .iter()
            .filter_map(|&c| Target::new(at(c), 0.15).ok())
            .collect();
        let planes = (D == 3)
            .then(|| Plane::new(SVector::zeros(), SVector::from_fn(|k, _| f64::from(k == 2))))
            .and_then(Result::ok)
            .into_iter()
            .collect();
        Table {
            segments,
            circles,
            targets,
            planes,
        }
    }

    /// `n` random paths of up to 3 segments in rows of 3 (padded with `+∞` starts): balls on
    /// the table, sliding then rolling, some at rest; in 3-D some in the air under gravity.
    fn random_rows<const D: usize>(n: usize, seed: u64) -> (Vec<f64>, [Vec<[f64; D]>; 3]) {
        let axes = |ranges: [[f64; 2]; 3]| -> [[f64; 2]; D] { std::array::from_fn(|i| ranges[i]) };
        RowSpec::<D> {
            segments: 3,
            every_row_used: false,
            later_first_start: 0.0,
            first_start: [0.0, 0.0],
            length: [0.0, 2.0],
            empty: 0.0,
            pos: axes([[0.0, 2.54], [0.0, 1.27], [0.02, 0.5]]),
            continuous: false,
            vel: axes([[-3.0, 3.0], [-3.0, 3.0], [-2.0, 2.0]]),
            acc: axes([[-2.0, 2.0], [-2.0, 2.0], [-10.0, 0.0]]),
            last_at_rest: 0.0,
        }
        .draw(&mut Rng(seed), n)
    }

    fn rows<const D: usize>(data: &(Vec<f64>, [Vec<[f64; D]>; 3])) -> PathRows<'_, D> {
        let (start, [pos, vel, acc]) = data;
        PathRows {
            start,
            pos,
            vel,
            acc,
            segments: 3,
        }
    }

    /// The batch's answers on `threads` threads, as `(time bits, kind, index)`.
    fn run<const D: usize>(
        paths: &PathRows<'_, D>,
        table: &Table<D>,
        radius: PerPair<'_>,
        threads: usize,
    ) -> Result<Vec<(u64, i8, i64)>, InputError> {
        let n = paths.len();
        let (mut time, mut kind, mut index) = (vec![f64::NAN; n], vec![9; n], vec![9; n]);
        let out = ContactColumns {
            time: &mut time,
            kind: &mut kind,
            index: &mut index,
        };
        let threads = Threads::AtMost(NonZeroUsize::new(threads).unwrap_or(NonZeroUsize::MIN));
        path_geometry_times(
            paths,
            table,
            radius,
            PerPair::All(f64::INFINITY),
            out,
            threads,
        )?;
        Ok((0..n)
            .map(|i| (time[i].to_bits(), kind[i], index[i]))
            .collect())
    }

    fn batch_is_the_single_query<const D: usize>(seed: u64) {
        let n = 3_000;
        let data = random_rows::<D>(n, seed);
        let paths = rows(&data);
        let table = test_table::<D>();
        let radii: Vec<f64> = (0..n).map(|i| 0.02 + 0.01 * (i % 4) as f64).collect();
        let one = run(&paths, &table, PerPair::Each(&radii), 1).expect("valid");
        let two = run(&paths, &table, PerPair::Each(&radii), 2).expect("valid");
        assert_eq!(one, two, "one thread and two");
        let mut kinds = [0; 4];
        for (i, &(time, kind, index)) in one.iter().enumerate() {
            let (start, [pos, vel, acc]) = &data;
            let r = 3 * i..3 * i + 3;
            let path =
                Path::from_rows(&start[r.clone()], &pos[r.clone()], &vel[r.clone()], &acc[r])
                    .expect("valid");
            let single = crate::geometry::path_table_contact(
                &path,
                &table,
                radii[i],
                &CollisionOptions::default(),
            )
            .expect("valid");
            let want = match single {
                Some(c) => (c.time.to_bits(), c.kind.code() as i8, c.index as i64),
                None => (f64::INFINITY.to_bits(), -1, -1),
            };
            assert_eq!((time, kind, index), want, "path {i}");
            if let Ok(k) = usize::try_from(kind) {
                kinds[k] += 1;
            }
        }
        // Every kind the table has is met.
        for kind in ObjectKind::ALL {
            let expected = table.count(kind) > 0;
            assert_eq!(
                kinds[kind.code() as usize] > 0,
                expected,
                "{kind:?}: {kinds:?}"
            );
        }
    }

    #[test]
    fn the_batch_gives_the_single_querys_bits_on_any_thread_count() {
        batch_is_the_single_query::<2>(1);
        batch_is_the_single_query::<3>(2);
    }

    #[test]
    fn errors_name_the_lowest_query_and_shapes_come_first() {
        let n = 5_000;
        let mut data = random_rows::<2>(n, 3);
        data.1[1][3 * 4321][1] = f64::NAN;
        data.1[1][3 * 4000][0] = f64::INFINITY;
        let table = test_table::<2>();
        for threads in [1, 2] {
            let err = run(&rows(&data), &table, PerPair::All(0.03), threads).unwrap_err();
            assert_eq!(err.to_string(), "vel[4000, 0]: must be finite, got inf");
        }
        let mut radii = vec![0.03; n];
        radii[4999] = 0.0;
        radii[4500] = -1.0;
        let err = run(&rows(&data), &table, PerPair::Each(&radii), 2).unwrap_err();
        assert_eq!(err.to_string(), "vel[4000, 0]: must be finite, got inf");
        let good = random_rows::<2>(n, 3);
        let err = run(&rows(&good), &table, PerPair::Each(&radii), 2).unwrap_err();
        assert_eq!(
            err.to_string(),
            "radius[4500]: a ball's radius must be > 0, got -1"
        );
        // Shared values and lengths, before any query.
        let err = run(&rows(&good), &table, PerPair::All(f64::NAN), 2).unwrap_err();
        assert_eq!(err.to_string(), "radius: must be finite, got NaN");
        let err = run(&rows(&good), &table, PerPair::Each(&radii[..7]), 2).unwrap_err();
        assert_eq!(err.to_string(), "radius: has 7 rows, expected 5000");
        let (mut time, mut kind, mut index) = (vec![0.0; n], vec![0; n], vec![0; n - 1]);
        let out = ContactColumns {
            time: &mut time,
            kind: &mut kind,
            index: &mut index,
        };
        let (radius, t_max) = (PerPair::All(0.03), PerPair::All(-1.0));
        let err = path_geometry_times(&rows(&good), &table, radius, t_max, out, Threads::All);
        assert_eq!(
            err.unwrap_err().to_string(),
            "t_max: must be ≥ 0 (∞ for none), got -1"
        );
    }

    #[test]
    fn one_path_stands_for_every_query() {
        let data = random_rows::<3>(40, 4);
        let table = test_table::<3>();
        let all = rows(&data);
        let one_path = |i: usize| PathRows {
            start: &all.start[3 * i..3 * i + 3],
            pos: &all.pos[3 * i..3 * i + 3],
            vel: &all.vel[3 * i..3 * i + 3],
            acc: &all.acc[3 * i..3 * i + 3],
            segments: 3,
        };
        let radii = [0.01, 0.02, 0.04, 0.08];
        for i in 0..40 {
            let (mut time, mut kind, mut index) = ([0.0; 4], [0; 4], [0; 4]);
            let out = ContactColumns {
                time: &mut time,
                kind: &mut kind,
                index: &mut index,
            };
            let (radius, t_max) = (PerPair::Each(&radii), PerPair::All(f64::INFINITY));
            path_geometry_times(&one_path(i), &table, radius, t_max, out, Threads::All)
                .expect("valid");
            for (q, &r) in radii.iter().enumerate() {
                let alone = run(&one_path(i), &table, PerPair::All(r), 1).expect("valid");
                assert_eq!(
                    (time[q].to_bits(), kind[q], index[q]),
                    alone[0],
                    "path {i}, r {r}"
                );
            }
        }
        // No object: no contact, whatever the path.
        let none = run(&all, &Table::default(), PerPair::All(0.1), 2).expect("valid");
        assert!(none.iter().all(|&x| x == (f64::INFINITY.to_bits(), -1, -1)));
        // A ball exactly between two equal objects: the lower kind wins, then the lower index.
        let point = |x: f64| Vector2::new(x, 0.0);
        let table = Table {
            circles: vec![Circle::new(point(2.0), 0.0).expect("valid"); 2],
            targets: vec![Target::new(point(2.0), 0.5).expect("valid")],
            ..Default::default()
        };
        let path = PathRows {
            start: &[0.0],
            pos: &[[0.0, 0.0]],
            vel: &[[1.0, 0.0]],
            acc: &[[0.0, 0.0]],
            segments: 1,
        };
        let got = run(&path, &table, PerPair::All(0.5), 1).expect("valid");
        assert_eq!(
            got,
            [(1.5f64.to_bits(), ObjectKind::Circle.code() as i8, 0)]
        );
    }

    #[test]
    fn chunks_hold_a_few_thousand_queries() {
        assert_eq!(paths_a_chunk(0), CHUNK);
        assert_eq!(paths_a_chunk(36), QUERIES_A_CHUNK / 36);
        assert_eq!(paths_a_chunk(1 << 40), 1);
    }
}
