//! The first entry (+ → − sign change of the gap) on one time window.

use super::exclusion::{Isolation, isolate_first_crossing};
use crate::coefficients::Gap;
use crate::poly::{bracketed_newton, solve_quadratic};

/// The critical points of `g` in `(0, end)`, ascending: the roots of `½g′ = d·d′`.
///
/// `½g′` is a cubic whose turning points are the roots of `½g″`, a quadratic solved stably;
/// between them `½g′` is monotone, so each sign change there brackets exactly one critical
/// point, found by bracketed Newton on the accurate `d·d′` form. Never divides by the leading
/// coefficient, so equal friction vectors (a cubic that is really a linear function) need no
/// special case.
pub(crate) fn critical_points(gap: &Gap, end: f64, noise: f64) -> ([f64; 3], usize) {
    let (v, f) = (gap.velocity, gap.acceleration);
    let turning = solve_quadratic(
        1.5 * f.norm_squared(),
        3.0 * v.dot(&f),
        v.norm_squared() + gap.offset.dot(&f),
    );
    let mut out = [0.0; 3];
    let mut count = 0;
    let mut left = 0.0;
    let mut slope_left = gap.half_slope(0.0);
    let inner = turning.iter().copied().filter(|&x| x > 0.0 && x < end);
    for right in inner.chain(std::iter::once(end)) {
        let slope_right = gap.half_slope(right);
        if (slope_left < 0.0 && slope_right > 0.0) || (slope_left > 0.0 && slope_right < 0.0) {
            let x = bracketed_newton(
                |u| (gap.half_slope(u), gap.half_curvature(u)),
                left,
                right,
                slope_left,
                slope_right,
                0.5 * (left + right),
                noise,
            );
            if x > 0.0 && x < end && count < out.len() {
                out[count] = x;
                count += 1;
            }
        } else if slope_right == 0.0 && right < end && count < out.len() {
            out[count] = right; // a critical point exactly at a turning point
            count += 1;
        }
        left = right;
        slope_left = slope_right;
    }
    (out, count)
}

/// The outcome of searching one window.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum WindowSearch {
    /// The balls start to interpenetrate at this time since the window's start.
    Entry(f64),
    /// No entry; whether the gap is positive at the window's end (carried to the next
    /// window, to catch a crossing that falls exactly between two windows).
    NoEntry { ends_positive: bool },
}

/// The first + → − crossing of `g` on `[0, end]`, time already scaled so that `end ≤ 1`.
///
/// `previous_positive` says that the gap was positive just before the window (at the end of
/// the previous one, or at time 0 for the first), so that a gap that is already negative at
/// the start counts as an entry at the start: the windows' formulas meet only up to rounding.
///
/// `g` is monotone between consecutive critical points, so the first piece that goes from
/// ≥ 0 (after having been positive) to < 0 holds the entry, found by bracketed Newton.
pub(crate) fn first_entry(gap: &Gap, end: f64, previous_positive: bool) -> WindowSearch {
    let g_start = gap.value(0.0);
    if previous_positive && g_start < 0.0 {
        return WindowSearch::Entry(0.0);
    }
    let (critical, count) = critical_points(gap, end, gap.half_slope_noise());
    let mut seen_positive = previous_positive || g_start > 0.0;
    let (mut left, mut g_left) = (0.0, g_start);
    for &right in critical[..count].iter().chain([end].iter()) {
        let g_right = gap.value(right);
        if seen_positive && g_left >= 0.0 && g_right < 0.0 {
            if g_left == 0.0 {
                return WindowSearch::Entry(left);
            }
            return WindowSearch::Entry(entry_root(
                gap,
                (left, right),
                (g_left, g_right),
                gap.value_noise(),
            ));
        }
        seen_positive |= g_right > 0.0;
        (left, g_left) = (right, g_right);
    }
    WindowSearch::NoEntry {
        ends_positive: g_left > 0.0,
    }
}

/// The window `[0, end]` settled by a finer Bernstein subdivision
/// ([`isolate_first_crossing`]), without the critical points: proven positive, or its first
/// crossing isolated on a piece holding exactly one root, found there. `None` leaves the window
/// to [`first_entry`]. On random pairs this settles most contacts and near misses at about
/// half the cost.
pub(crate) fn isolated_entry(gap: &Gap, end: f64) -> Option<WindowSearch> {
    match isolate_first_crossing(gap, end) {
        Isolation::Positive => Some(WindowSearch::NoEntry {
            ends_positive: true,
        }),
        Isolation::Crossing(start, stop) => {
            let (left, right) = (end * start, end * stop);
            let (g_left, g_right) = (gap.value(left), gap.value(right));
            // The accurate values must confirm the bracket that the coefficients promise.
            (g_left > 0.0 && g_right < 0.0).then(|| {
                WindowSearch::Entry(entry_root(
                    gap,
                    (left, right),
                    (g_left, g_right),
                    gap.value_noise(),
                ))
            })
        }
        Isolation::Unsettled => None,
    }
}

/// The root of `g` in `(left, right)`, where `g(left) > 0 > g(right)` and `g` is monotone.
///
/// Newton starts from the root of the quadratic Taylor model of `g` at `right`. Where `right`
/// is a local minimum, or the end of a window where a ball comes to rest (the slope vanishes
/// there too), the root may be near-double (a grazing contact, or a contact just before a
/// stop): the model is then already close, where Newton from afar would crawl in, and where
/// `g` is within rounding of zero over a band far wider than the root's accuracy.
fn entry_root(
    gap: &Gap,
    (left, right): (f64, f64),
    (g_left, g_right): (f64, f64),
    noise: f64,
) -> f64 {
    let model = solve_quadratic(
        gap.half_curvature(right),
        2.0 * gap.half_slope(right),
        g_right,
    );
    let start = model
        .iter()
        .map(|delta| right + delta)
        .find(|&x| x > left && x < right)
        .unwrap_or(left + (right - left) * (g_left / (g_left - g_right)));
    bracketed_newton(
        |u| (gap.value(u), 2.0 * gap.half_slope(u)),
        left,
        right,
        g_left,
        g_right,
        start,
        noise,
    )
}
