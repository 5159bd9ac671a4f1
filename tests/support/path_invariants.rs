//! The invariants of the path entry points, checked by the fuzz target `path` (`fuzz/`) and
//! by the property test `tests/integration/invariants_path.rs`: one implementation for both.
//!
//! For two paths of 1 to 6 segments in 2-D or 3-D, any values (valid or not):
//! - construction and the batch agree on validity: a path is accepted exactly when every value
//!   is finite and the starts do not decrease; an invalid radius or horizon is refused; an
//!   invalid input is an error, never a panic;
//! - on valid input: the time is never NaN, `−0`, earlier than the later first start, or at or
//!   past the horizon; a horizon only cuts (the answer with `t_max` is the unbounded answer if
//!   earlier, else none, for the case's horizon and for horizons just past the contact);
//!   swapping A and B, flipping the sign of every zero and scaling every length (positions,
//!   velocities, accelerations, radius) by `2^k` change no bit, whenever the scaled inputs are
//!   exact; without the screens that prove balls apart, every window searched, the answer is
//!   the same bits; the batch gives the single query's bits, per pair and with either side or
//!   both broadcast, on one thread and on two.

#![allow(dead_code)]

use ballcollide::batch::{PathPairs, PerPair, Threads, path_collision_times};
use ballcollide::collision::path_collision_time_unscreened;
use ballcollide::path::Path;
use ballcollide::{CollisionOptions, path_collision_time};
use std::num::NonZeroUsize;

use super::path_table::PathTable;

/// One segment's inputs: start, then position, velocity and acceleration, three components
/// each (a 2-D case uses the first two of each).
pub type SegmentInput = [f64; 10];

/// A query on two paths.
#[derive(Clone, Debug)]
pub struct PathCase {
    /// Path A's segments (rows).
    pub a: Vec<SegmentInput>,
    /// Path B's segments.
    pub b: Vec<SegmentInput>,
    /// Contact distance.
    pub radius: f64,
    /// Horizon.
    pub t_max: f64,
    /// 3-D (else 2-D).
    pub three_d: bool,
}

/// The outcome of one check.
pub type Check = Result<(), String>;

/// One path's rows as a table of one path (the batch layout), whatever their values.
pub fn table<const D: usize>(segments: &[SegmentInput]) -> PathTable<D> {
    let part = |s: &SegmentInput, at: usize| -> [f64; D] { std::array::from_fn(|i| s[at + i]) };
    PathTable {
        start: segments.iter().map(|s| s[0]).collect(),
        pos: segments.iter().map(|s| part(s, 1)).collect(),
        vel: segments.iter().map(|s| part(s, 4)).collect(),
        acc: segments.iter().map(|s| part(s, 7)).collect(),
        segments: segments.len(),
    }
}

/// The path of a table of one path.
pub fn path_of<const D: usize>(t: &PathTable<D>) -> Result<Path<D>, ballcollide::InputError> {
    Path::from_rows(&t.start, &t.pos, &t.vel, &t.acc)
}

/// Whether a path is valid, by the contract's own words: its used rows are those before the
/// first `+∞` start, and every row after it must be padding (start `+∞`, other values
/// ignored); at least one used row, every used value finite, used starts that do not
/// decrease.
pub fn valid_path<const D: usize>(segments: &[SegmentInput]) -> bool {
    let used = segments
        .iter()
        .position(|s| s[0] == f64::INFINITY)
        .unwrap_or(segments.len());
    let values = |s: &SegmentInput| {
        let s = *s;
        std::iter::once(s[0])
            .chain((0..3).flat_map(move |part| (0..D).map(move |i| s[1 + 3 * part + i])))
    };
    used > 0
        && segments[used..].iter().all(|s| s[0] == f64::INFINITY)
        && segments[..used]
            .iter()
            .all(|s| values(s).all(f64::is_finite))
        && segments[..used].windows(2).all(|w| w[0][0] <= w[1][0])
}

pub fn same(x: Option<f64>, y: Option<f64>) -> bool {
    x.map(f64::to_bits) == y.map(f64::to_bits)
}

/// `x·2^k` if that is exact (finite, and back to `x` when scaled back), else `None`.
pub fn scaled_exactly(x: f64, k: i32) -> Option<f64> {
    let y = x * 2f64.powi(k / 2) * 2f64.powi(k - k / 2);
    let back = y * 2f64.powi(-(k / 2)) * 2f64.powi(-(k - k / 2));
    (y.is_finite() && back.to_bits() == x.to_bits()).then_some(y)
}

fn flip_zeros(x: f64) -> f64 {
    if x == 0.0 { -x } else { x }
}

/// The path invariants, with `k` the exponent of the length scaling.
pub fn path(case: &PathCase, k: i32) -> Check {
    if case.three_d {
        path_in::<3>(case, k)
    } else {
        path_in::<2>(case, k)
    }
}

fn time_of<const D: usize>(
    a: &[SegmentInput],
    b: &[SegmentInput],
    radius: f64,
    t_max: f64,
) -> Result<Option<f64>, String> {
    let (pa, pb) = (path_of(&table::<D>(a)), path_of(&table::<D>(b)));
    let (pa, pb) = (
        pa.map_err(|e| format!("valid path A {a:?} rejected: {e}"))?,
        pb.map_err(|e| format!("valid path B {b:?} rejected: {e}"))?,
    );
    path_collision_time(&pa, &pb, radius, &CollisionOptions { t_max })
        .map_err(|e| format!("valid query rejected: {e}, radius {radius:e}, t_max {t_max:e}"))
}

fn path_in<const D: usize>(case: &PathCase, k: i32) -> Check {
    let PathCase {
        a,
        b,
        radius,
        t_max,
        ..
    } = case;
    let (radius, t_max) = (*radius, *t_max);
    let valid = [valid_path::<D>(a), valid_path::<D>(b)];
    for (side, (segments, ok)) in [a, b].iter().zip(valid).enumerate() {
        if path_of(&table::<D>(segments)).is_ok() != ok {
            return Err(format!(
                "path {side} {segments:?}: construction accepts it: {}, the contract: {ok}",
                !ok
            ));
        }
    }
    let params_ok = radius.is_finite() && radius > 0.0 && t_max >= 0.0;
    let (rows_a, rows_b) = (table::<D>(a), table::<D>(b));
    let pairs = PathPairs {
        a: rows_a.side(),
        b: rows_b.side(),
        contact_distance: PerPair::All(radius),
        t_max: PerPair::All(t_max),
    };
    let mut out = [f64::NAN];
    let batch = path_collision_times(&pairs, &mut out, Threads::All);
    if !(valid[0] && valid[1] && params_ok) {
        if batch.is_ok() {
            return Err(format!("invalid input accepted by the batch: {case:?}"));
        }
        // Nine pairs of it, a block of the batch's lanes: refused too.
        let (nine_a, nine_b) = (rows_a.pick(&[0; 9]), rows_b.pick(&[0; 9]));
        let pairs = PathPairs {
            a: nine_a.side(),
            b: nine_b.side(),
            contact_distance: PerPair::All(radius),
            t_max: PerPair::All(t_max),
        };
        if path_collision_times(&pairs, &mut [f64::NAN; 9], Threads::All).is_ok() {
            return Err(format!(
                "invalid input accepted in a batch of nine: {case:?}"
            ));
        }
        // Valid paths with an invalid radius or horizon: the single query refuses it too.
        if let (Ok(pa), Ok(pb)) = (path_of(&rows_a), path_of(&rows_b)) {
            let single = path_collision_time(&pa, &pb, radius, &CollisionOptions { t_max });
            if single.is_ok() {
                return Err(format!("invalid radius or horizon accepted: {case:?}"));
            }
        }
        return Ok(());
    }
    batch.map_err(|e| format!("valid batch rejected: {e}, for {case:?}"))?;
    let free = time_of::<D>(a, b, radius, f64::INFINITY)?;
    let cut = time_of::<D>(a, b, radius, t_max)?;
    let from = a[0][0].max(b[0][0]);
    for (what, t) in [("without horizon", free), ("with horizon", cut)] {
        if let Some(t) = t
            && !(t >= from && t.is_finite() && t.to_bits() != (-0.0f64).to_bits())
        {
            return Err(format!(
                "{what}: time {t:e} (first time {from:e}) for {case:?}"
            ));
        }
    }
    if cut.is_some_and(|t| t >= t_max) {
        return Err(format!(
            "a contact at or past the horizon: {cut:?}, for {case:?}"
        ));
    }
    if out[0].to_bits() != cut.unwrap_or(f64::INFINITY).to_bits() {
        return Err(format!("batch {:e} ≠ single {cut:?}, for {case:?}", out[0]));
    }
    // The screens are proofs: without them, every window searched, the same bits.
    let (pa, pb) = (path_of(&rows_a), path_of(&rows_b));
    if let (Ok(pa), Ok(pb)) = (&pa, &pb) {
        let unscreened =
            path_collision_time_unscreened(pa, pb, radius, &CollisionOptions { t_max })
                .map_err(|e| format!("valid query rejected without screens: {e}, for {case:?}"))?;
        if !same(unscreened, cut) {
            return Err(format!(
                "the screens changed the answer: {cut:?}, without them {unscreened:?}, for {case:?}"
            ));
        }
    }
    let horizons = free.map_or(vec![t_max], |t| vec![t_max, t, t.next_up(), t + 1.0, 1e10]);
    // Horizons are ≥ 0 (absolute times before 0 are always earlier than any horizon).
    for h in horizons.into_iter().filter(|&h| h >= 0.0) {
        let got = time_of::<D>(a, b, radius, h)?;
        if !same(got, free.filter(|&t| t < h)) {
            return Err(format!(
                "a horizon must only cut: without it {free:?}, with t_max = {h:e} {got:?}, for \
                 {case:?}"
            ));
        }
    }
    let swapped = time_of::<D>(b, a, radius, t_max)?;
    if !same(swapped, cut) {
        return Err(format!(
            "A/B swap: {cut:?} became {swapped:?}, for {case:?}"
        ));
    }
    let flip =
        |p: &[SegmentInput]| -> Vec<SegmentInput> { p.iter().map(|s| s.map(flip_zeros)).collect() };
    let flipped = time_of::<D>(&flip(a), &flip(b), radius, flip_zeros(t_max))?;
    if !same(flipped, cut) {
        return Err(format!(
            "−0.0 = +0.0: {cut:?} became {flipped:?} with every zero's sign flipped, for {case:?}"
        ));
    }
    let scale = |p: &[SegmentInput]| -> Option<Vec<SegmentInput>> {
        p.iter()
            .map(|s| {
                let mut out = *s;
                if s[0] == f64::INFINITY {
                    return Some(out); // padding
                }
                for x in &mut out[1..] {
                    *x = scaled_exactly(*x, k)?;
                }
                Some(out)
            })
            .collect()
    };
    if let (Some(sa), Some(sb), Some(sr)) = (scale(a), scale(b), scaled_exactly(radius, k)) {
        let s_cut = time_of::<D>(&sa, &sb, sr, t_max)?;
        if !same(s_cut, cut) {
            return Err(format!(
                "lengths scaled by 2^{k}: {cut:?} became {s_cut:?}, for {case:?}"
            ));
        }
    }
    // Broadcasts: A against three copies of B, three copies of A against B, one against one;
    // nine copies against nine (a block of the batch's lanes, where it has them); per-pair
    // radii; on one thread and on two.
    let (copies_a, copies_b) = (rows_a.pick(&[0, 0, 0]), rows_b.pick(&[0, 0, 0]));
    let (nine_a, nine_b) = (rows_a.pick(&[0; 9]), rows_b.pick(&[0; 9]));
    let radii = [radius; 9];
    let sides = [
        (rows_a.side(), copies_b.side(), 3),
        (copies_a.side(), rows_b.side(), 3),
        (rows_a.side(), rows_b.side(), 1),
        (nine_a.side(), nine_b.side(), 9),
    ];
    for (side_a, side_b, n) in sides {
        let pairs = PathPairs {
            a: side_a,
            b: side_b,
            contact_distance: PerPair::Each(&radii[..n]),
            t_max: PerPair::All(t_max),
        };
        for threads in [1, 2] {
            let mut out = vec![f64::NAN; n];
            let t = Threads::AtMost(NonZeroUsize::new(threads).unwrap_or(NonZeroUsize::MIN));
            path_collision_times(&pairs, &mut out, t)
                .map_err(|e| format!("valid broadcast batch rejected: {e}, for {case:?}"))?;
            let want = cut.unwrap_or(f64::INFINITY).to_bits();
            if out.iter().any(|x| x.to_bits() != want) {
                return Err(format!(
                    "broadcast batch ({n} pairs, {threads} thread(s)) {out:?} ≠ single {cut:?}, \
                     for {case:?}"
                ));
            }
        }
    }
    Ok(())
}
