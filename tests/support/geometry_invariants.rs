//! The invariants of the static-geometry entry points (`batch::path_geometry_times`,
//! `geometry::path_table_contact` and the object constructors), checked by the fuzz target
//! `geometry` (`fuzz/`) and by the property test `tests/integration/invariants_geometry.rs`: one
//! implementation for both.
//!
//! For 1 to 3 paths of 1 to 6 segments in 2-D or 3-D and up to 3 objects of each kind, any
//! values (valid or not):
//! - the constructors accept an object exactly when the contract calls it valid (finite
//!   numbers, `P ≠ Q`, a side in {−1, 0, 1}, `ρ ≥ 0` for a circle, `ρ > 0` for a target, a
//!   normal other than 0), and the batch accepts paths, radius and horizon exactly when the
//!   contract does; an invalid input is an error, never a panic;
//! - on valid input, for each path: the batch's answer is `path_table_contact`'s, bit for
//!   bit, and that is the earliest of the single-object queries (`path_segment_contact` on the
//!   path's `(x, y)`, `path_circle_contact`, `path_target_contact`, `path_plane_contact`) in
//!   the documented order: by time, then kind, then index; its time is never NaN, `−0`,
//!   before the first start or at or past the horizon; a horizon only cuts (the case's, the
//!   contact's time, the next float, one later, 10¹⁰); the batch gives the same bits on one
//!   thread and on two, and with one path standing for three queries;
//! - scaling every length by `2^k` (positions, velocities, accelerations, the radius, every
//!   number of the objects but the planes' normals) changes no bit of the batch's answers,
//!   whenever the scaled numbers are exact;
//! - translating every position (the paths' and the objects') by `2^j` on each axis, where
//!   every sum is exact, changes no bit of any segment's or plane's single query (the
//!   contract's promise: their queries form every difference from the caller's numbers),
//!   where the query is within the contract's range (its path's, radius' and object's
//!   non-zero magnitudes within `2^±400` of each other before and after, and so the normal's
//!   components: docs/contract.md §5).

#![allow(dead_code)]

use std::num::NonZeroUsize;

use ballcollide::CollisionOptions;
use ballcollide::batch::{ContactColumns, PerPair, Threads, path_geometry_times};
use ballcollide::geometry::{
    Circle, LineSegment, ObjectContact, ObjectKind, Plane, SegmentSide, Table, Target,
    path_circle_contact, path_plane_contact, path_segment_contact, path_table_contact,
    path_target_contact,
};
use ballcollide::path::{Path, Segment};
use nalgebra::{SVector, Vector2};

use super::invariants::within_contract_range;
use super::path_invariants::{
    Check, SegmentInput, path_of, scaled_exactly, table as one_path, valid_path,
};
use super::path_table::PathTable;

/// A segment's inputs: `P` and `Q` (`x, y` each), and its side as a number.
pub type SegmentObject = ([f64; 4], i64);
/// A circle's or a target's inputs: its centre (`x, y, z`; a 2-D case reads `x, y`) and `ρ`.
pub type DiscObject = [f64; 4];
/// A plane's inputs: its point and its normal (`x, y, z` each; a 2-D case reads `x, y`).
pub type PlaneObject = [f64; 6];

/// Balls on paths against a table of objects.
#[derive(Clone, Debug)]
pub struct GeometryCase {
    /// The paths, one per query (rows as in `path_invariants`).
    pub paths: Vec<Vec<SegmentInput>>,
    /// The segments.
    pub segments: Vec<SegmentObject>,
    /// The circles.
    pub circles: Vec<DiscObject>,
    /// The targets.
    pub targets: Vec<DiscObject>,
    /// The planes.
    pub planes: Vec<PlaneObject>,
    /// The balls' radius.
    pub radius: f64,
    /// The horizon.
    pub t_max: f64,
    /// 3-D (else 2-D).
    pub three_d: bool,
}

/// An answer as the batch writes it: the time's bits, the kind's code, the index.
type Answer = (u64, i8, i64);

fn answer(contact: Option<ObjectContact>) -> Answer {
    match contact {
        Some(c) => (
            c.time.to_bits(),
            c.kind.code() as i8,
            i64::try_from(c.index).unwrap_or(i64::MAX),
        ),
        None => (f64::INFINITY.to_bits(), -1, -1),
    }
}

/// The invariants, with `k` the exponent of the length scaling and `j` that of the
/// translation.
pub fn geometry(case: &GeometryCase, k: i32, j: i32) -> Check {
    if case.three_d {
        geometry_in::<3>(case, k, j)
    } else {
        geometry_in::<2>(case, k, j)
    }
}

fn vector<const D: usize>(x: &[f64]) -> SVector<f64, D> {
    SVector::from_fn(|i, _| x[i])
}

/// The case's table, each object made by its constructor, which must accept it exactly when
/// the contract calls it valid; `None` if some object is invalid (and refused).
fn table_of<const D: usize>(case: &GeometryCase) -> Result<Option<Table<D>>, String> {
    let mut table = Table::default();
    let mut valid = true;
    let mut keep = |what: &str, m: usize, ok: bool, made: Result<(), String>| {
        valid &= ok;
        match (ok, made) {
            (true, Ok(())) | (false, Err(_)) => Ok(()),
            (true, Err(e)) => Err(format!("{what} {m} is valid but refused: {e}")),
            (false, Ok(())) => Err(format!("{what} {m} is invalid but accepted")),
        }
    };
    let finite = |x: &[f64]| x.iter().all(|v| v.is_finite());
    for (m, &(e, side)) in case.segments.iter().enumerate() {
        let ok = finite(&e) && (e[0], e[1]) != (e[2], e[3]) && (-1..=1).contains(&side);
        let made = SegmentSide::from_sign(side).and_then(|side| {
            LineSegment::new(Vector2::new(e[0], e[1]), Vector2::new(e[2], e[3]), side)
        });
        let made = made
            .map(|s| table.segments.push(s))
            .map_err(|e| e.to_string());
        keep("segment", m, ok, made)?;
    }
    for (m, c) in case.circles.iter().enumerate() {
        let ok = finite(&c[..D]) && c[3].is_finite() && c[3] >= 0.0;
        let made = Circle::new(vector::<D>(c), c[3]).map(|c| table.circles.push(c));
        keep("circle", m, ok, made.map_err(|e| e.to_string()))?;
    }
    for (m, c) in case.targets.iter().enumerate() {
        let ok = finite(&c[..D]) && c[3].is_finite() && c[3] > 0.0;
        let made = Target::new(vector::<D>(c), c[3]).map(|t| table.targets.push(t));
        keep("target", m, ok, made.map_err(|e| e.to_string()))?;
    }
    for (m, p) in case.planes.iter().enumerate() {
        let normal = &p[3..3 + D];
        let ok = finite(&p[..D]) && finite(normal) && normal.iter().any(|&x| x != 0.0);
        let made = Plane::new(vector::<D>(p), vector::<D>(normal)).map(|p| table.planes.push(p));
        keep("plane", m, ok, made.map_err(|e| e.to_string()))?;
    }
    Ok(valid.then_some(table))
}

/// The paths as the batch's rows, each padded to the longest with `+∞` starts (and NaN).
fn rows<const D: usize>(paths: &[Vec<SegmentInput>]) -> PathTable<D> {
    let k = paths.iter().map(Vec::len).max().unwrap_or(1).max(1);
    let mut rows = PathTable::new(k);
    let part = |s: &SegmentInput, at: usize| -> [f64; D] { std::array::from_fn(|i| s[at + i]) };
    for path in paths {
        for s in path {
            rows.start.push(s[0]);
            rows.pos.push(part(s, 1));
            rows.vel.push(part(s, 4));
            rows.acc.push(part(s, 7));
        }
        for _ in path.len()..k {
            rows.start.push(f64::INFINITY);
            rows.pos.push([f64::NAN; D]);
            rows.vel.push([f64::NAN; D]);
            rows.acc.push([f64::NAN; D]);
        }
    }
    rows
}

/// The batch's answers for `paths` (one per query, or one for `radii.len()` queries), on
/// `threads` threads.
fn batch<const D: usize>(
    paths: &PathTable<D>,
    table: &Table<D>,
    radii: PerPair<'_>,
    t_max: f64,
    n: usize,
    threads: usize,
) -> Result<Vec<Answer>, ballcollide::InputError> {
    let (mut time, mut kind, mut index) = (vec![f64::NAN; n], vec![9; n], vec![9; n]);
    let out = ContactColumns {
        time: &mut time,
        kind: &mut kind,
        index: &mut index,
    };
    let threads = Threads::AtMost(NonZeroUsize::new(threads).unwrap_or(NonZeroUsize::MIN));
    let t_max = PerPair::All(t_max);
    path_geometry_times(&paths.side(), table, radii, t_max, out, threads)?;
    Ok((0..n)
        .map(|i| (time[i].to_bits(), kind[i], index[i]))
        .collect())
}

/// The path's `(x, y)`: what a segment's query reads (in 3-D the segment is a vertical wall).
fn planar<const D: usize>(path: &Path<D>) -> Result<Path<2>, String> {
    let xy = |v: &SVector<f64, D>| Vector2::new(v[0], v[1]);
    let segments = path
        .segments()
        .iter()
        .map(|s| {
            Segment::new(
                s.start,
                xy(&s.position),
                xy(&s.velocity),
                xy(&s.acceleration),
            )
        })
        .collect();
    Path::new(segments).map_err(|e| format!("a valid path's (x, y) refused: {e}"))
}

/// The earliest of the single-object queries, by time, then kind, then index.
fn earliest_of_each<const D: usize>(
    path: &Path<D>,
    table: &Table<D>,
    radius: f64,
    t_max: f64,
) -> Result<Option<ObjectContact>, String> {
    let options = CollisionOptions { t_max };
    let flat = planar(path)?;
    let refused = |e: ballcollide::InputError| format!("a valid single query refused: {e}");
    let mut best: Option<ObjectContact> = None;
    let mut consider = |time: Option<f64>, kind, index| {
        if let Some(time) = time {
            let c = ObjectContact { time, kind, index };
            if best.is_none_or(|b| c.before(&b)) {
                best = Some(c);
            }
        }
    };
    for (m, s) in table.segments.iter().enumerate() {
        let time = path_segment_contact(&flat, s, radius, &options).map_err(refused)?;
        consider(time, ObjectKind::Segment, m);
    }
    for (m, c) in table.circles.iter().enumerate() {
        let time = path_circle_contact(path, c, radius, &options).map_err(refused)?;
        consider(time, ObjectKind::Circle, m);
    }
    for (m, t) in table.targets.iter().enumerate() {
        let time = path_target_contact(path, t, &options).map_err(refused)?;
        consider(time, ObjectKind::Target, m);
    }
    for (m, p) in table.planes.iter().enumerate() {
        let time = path_plane_contact(path, p, radius, &options).map_err(refused)?;
        consider(time, ObjectKind::Plane, m);
    }
    Ok(best)
}

fn geometry_in<const D: usize>(case: &GeometryCase, k: i32, j: i32) -> Check {
    let Some(table) = table_of::<D>(case)? else {
        return Ok(());
    };
    let (radius, t_max, n) = (case.radius, case.t_max, case.paths.len());
    let paths = rows::<D>(&case.paths);
    let valid = case.paths.iter().all(|p| valid_path::<D>(p))
        && radius.is_finite()
        && radius > 0.0
        && t_max >= 0.0;
    let got = batch(&paths, &table, PerPair::All(radius), t_max, n, 1);
    if !valid {
        return match got {
            Ok(_) => Err(format!("invalid input accepted by the batch: {case:?}")),
            Err(_) => Ok(()),
        };
    }
    let got = got.map_err(|e| format!("valid batch refused: {e}, for {case:?}"))?;
    let two = batch(&paths, &table, PerPair::All(radius), t_max, n, 2)
        .map_err(|e| format!("valid batch refused on two threads: {e}, for {case:?}"))?;
    if two != got {
        return Err(format!("one thread {got:?}, two {two:?}, for {case:?}"));
    }
    for (i, rows) in case.paths.iter().enumerate() {
        each_path::<D>(case, &table, rows, got[i])
            .map_err(|e| format!("path {i}: {e}, for {case:?}"))?;
    }
    scaled::<D>(case, k, &got)?;
    translated::<D>(case, &table, j)
}

/// The checks of one path whose batch answer is `got`.
fn each_path<const D: usize>(
    case: &GeometryCase,
    table: &Table<D>,
    rows: &[SegmentInput],
    got: Answer,
) -> Check {
    let (radius, t_max) = (case.radius, case.t_max);
    let path =
        path_of::<D>(&one_path::<D>(rows)).map_err(|e| format!("valid path refused: {e}"))?;
    let single = |t_max: f64| {
        path_table_contact(&path, table, radius, &CollisionOptions { t_max })
            .map_err(|e| format!("valid query refused: {e}"))
    };
    let cut = single(t_max)?;
    if answer(cut) != got {
        return Err(format!("batch {got:?} ≠ path_table_contact {cut:?}"));
    }
    let each = earliest_of_each(&path, table, radius, t_max)?;
    if answer(each) != got {
        return Err(format!(
            "path_table_contact {cut:?} ≠ the earliest single-object query {each:?}"
        ));
    }
    let first = rows[0][0];
    if let Some(c) = cut
        && !(c.time.is_finite()
            && c.time >= first
            && c.time < t_max
            && c.time.to_bits() != (-0.0f64).to_bits())
    {
        return Err(format!(
            "time {:e} (first start {first:e}, t_max {t_max:e})",
            c.time
        ));
    }
    // A horizon only cuts.
    let free = single(f64::INFINITY)?;
    let mut horizons = vec![t_max, 1e10];
    if let Some(c) = free {
        horizons.extend([c.time, c.time.next_up(), c.time + 1.0]);
    }
    for h in horizons.into_iter().filter(|&h| h >= 0.0) {
        let with = single(h)?;
        if answer(with) != answer(free.filter(|c| c.time < h)) {
            return Err(format!(
                "a horizon must only cut: without it {free:?}, with t_max = {h:e} {with:?}"
            ));
        }
    }
    // One path for three queries, per-query radii.
    let alone = one_path::<D>(rows);
    let three = batch(&alone, table, PerPair::Each(&[radius; 3]), t_max, 3, 2)
        .map_err(|e| format!("valid broadcast refused: {e}"))?;
    if three.iter().any(|&a| a != got) {
        return Err(format!("one path for three queries {three:?} ≠ {got:?}"));
    }
    Ok(())
}

/// Every length of the case scaled by `2^k` (`None` if a scaled number is not exact).
fn scaled_case<const D: usize>(case: &GeometryCase, k: i32) -> Option<GeometryCase> {
    let s = |x: f64| scaled_exactly(x, k);
    let used = |x: &mut [f64], at: usize| -> Option<()> {
        for v in &mut x[at..at + D] {
            *v = s(*v)?;
        }
        Some(())
    };
    let mut out = case.clone();
    for path in &mut out.paths {
        for row in path.iter_mut().filter(|r| r[0] != f64::INFINITY) {
            for at in [1, 4, 7] {
                used(row, at)?;
            }
        }
    }
    for (e, _) in &mut out.segments {
        for v in e.iter_mut() {
            *v = s(*v)?;
        }
    }
    for c in out.circles.iter_mut().chain(&mut out.targets) {
        used(c, 0)?;
        c[3] = s(c[3])?;
    }
    for p in &mut out.planes {
        used(p, 0)?;
    }
    out.radius = s(case.radius)?;
    Some(out)
}

fn scaled<const D: usize>(case: &GeometryCase, k: i32, got: &[Answer]) -> Check {
    let Some(scaled) = scaled_case::<D>(case, k) else {
        return Ok(());
    };
    let scaled_table = table_of::<D>(&scaled)?
        .ok_or_else(|| format!("objects scaled by 2^{k} refused, for {case:?}"))?;
    let n = case.paths.len();
    let paths = rows::<D>(&scaled.paths);
    let again = batch(
        &paths,
        &scaled_table,
        PerPair::All(scaled.radius),
        case.t_max,
        n,
        2,
    )
    .map_err(|e| format!("scaled by 2^{k}: refused: {e}, for {case:?}"))?;
    if again != got {
        return Err(format!(
            "lengths scaled by 2^{k}: {got:?} became {again:?}, for {case:?}"
        ));
    }
    Ok(())
}

/// `x + c` if that sum is exact (and finite).
fn shifted_exactly(x: f64, c: f64) -> Option<f64> {
    let s = x + c;
    // Knuth's two-sum: the rounding error of `x + c`, exactly.
    let b = s - x;
    let error = (x - (s - b)) + (c - b);
    (s.is_finite() && error == 0.0).then_some(s)
}

/// Every position of the case moved by `c` on each axis (`None` if a sum is not exact).
fn translated_case<const D: usize>(case: &GeometryCase, c: f64) -> Option<GeometryCase> {
    let t = |x: f64| shifted_exactly(x, c);
    let mut out = case.clone();
    for path in &mut out.paths {
        for row in path.iter_mut().filter(|r| r[0] != f64::INFINITY) {
            for v in &mut row[1..1 + D] {
                *v = t(*v)?;
            }
        }
    }
    for (e, _) in &mut out.segments {
        for v in e.iter_mut() {
            *v = t(*v)?;
        }
    }
    for p in &mut out.planes {
        for v in &mut p[..D] {
            *v = t(*v)?;
        }
    }
    Some(out)
}

/// `Ok` if a query and the same one moved give the same bits (or errors).
fn unmoved<E: std::fmt::Debug>(x: Result<Option<f64>, E>, y: Result<Option<f64>, E>) -> Check {
    let bits = |r: &Result<Option<f64>, E>| r.as_ref().ok().map(|t| t.map(f64::to_bits));
    match bits(&x) == bits(&y) && x.is_ok() == y.is_ok() {
        true => Ok(()),
        false => Err(format!("{x:?} became {y:?}")),
    }
}

fn translated<const D: usize>(case: &GeometryCase, table: &Table<D>, j: i32) -> Check {
    let c = if j < 0 { -2f64.powi(-j) } else { 2f64.powi(j) };
    let Some(moved) = translated_case::<D>(case, c) else {
        return Ok(());
    };
    let of_case = |e: String| format!("{e}, for {case:?}");
    let moved_table = table_of::<D>(&moved)?
        .ok_or_else(|| format!("objects moved by {c:e} refused, for {case:?}"))?;
    let options = CollisionOptions { t_max: case.t_max };
    let radius = case.radius;
    for (i, (before, after)) in case.paths.iter().zip(&moved.paths).enumerate() {
        let (p, q) = (
            path_of::<D>(&one_path::<D>(before)),
            path_of::<D>(&one_path::<D>(after)),
        );
        let (Ok(p), Ok(q)) = (p, q) else {
            return Err(format!("path {i} moved by {c:e}: refused, for {case:?}"));
        };
        let (p2, q2) = (planar(&p)?, planar(&q)?);
        // The magnitudes of the query of path `i` and an object's numbers `of`, before and
        // after, must be in the contract's range.
        let numbers = |path: &[SegmentInput]| -> Vec<f64> {
            let used = path.iter().filter(|r| r[0] != f64::INFINITY);
            let mut v: Vec<f64> = used
                .flat_map(|r| {
                    [1, 4, 7]
                        .into_iter()
                        .flat_map(move |at| r[at..at + D].to_vec())
                })
                .collect();
            v.push(radius);
            v
        };
        let in_range = |of: [&[f64]; 2]| {
            [(before, of[0]), (after, of[1])]
                .iter()
                .all(|(path, object)| {
                    within_contract_range(numbers(path).into_iter().chain(object.iter().copied()))
                })
        };
        for (m, (s, t)) in table.segments.iter().zip(&moved_table.segments).enumerate() {
            let ends = |s: &LineSegment| [s.p().x, s.p().y, s.q().x, s.q().y];
            if !in_range([&ends(s), &ends(t)]) {
                continue;
            }
            let x = path_segment_contact(&p2, s, radius, &options);
            let y = path_segment_contact(&q2, t, radius, &options);
            unmoved(x, y)
                .map_err(|e| of_case(format!("path {i}, segment {m} moved by {c:e}: {e}")))?;
        }
        for (m, (s, t)) in table.planes.iter().zip(&moved_table.planes).enumerate() {
            let (a, b) = (s.point(), t.point());
            if !in_range([a.as_slice(), b.as_slice()])
                || !within_contract_range(s.normal().iter().copied())
            {
                continue;
            }
            let x = path_plane_contact(&p, s, radius, &options);
            let y = path_plane_contact(&q, t, radius, &options);
            unmoved(x, y)
                .map_err(|e| of_case(format!("path {i}, plane {m} moved by {c:e}: {e}")))?;
        }
    }
    Ok(())
}
