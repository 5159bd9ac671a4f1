//! The first entry (+ → − sign change of the gap) on one time window.

use super::exclusion::{OpenPieces, Shape};
use super::narrow_dip::{narrow, narrow_entry};
use crate::gap::Gap;
use crate::poly::{bracketed_newton, solve_quadratic};

/// The critical points of `g` in `(0, end)`, ascending: the roots of `½g′ = d·d′`.
///
/// `½g′` is a cubic whose turning points are the roots of `½g″`, a quadratic solved stably;
/// between them `½g′` is monotone, so each sign change there brackets exactly one critical
/// point, found by bracketed Newton on the accurate `d·d′` form. Never divides by the leading
/// coefficient, so equal friction vectors (a cubic that is really a linear function) need no
/// special case.
pub(crate) fn critical_points<const D: usize>(
    gap: &Gap<D>,
    end: f64,
    noise: f64,
) -> ([f64; 3], usize) {
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
            let x = slope_root(
                gap,
                (left, right),
                (slope_left, slope_right),
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

/// A critical point of `g` (a root of `½g′ = d·d′`) in `(left, right)`, where the slope changes
/// sign, by bracketed Newton from `start`; below `noise` the slope's sign is rounding.
#[inline(always)]
fn slope_root<const D: usize>(
    gap: &Gap<D>,
    (left, right): (f64, f64),
    (slope_left, slope_right): (f64, f64),
    start: f64,
    noise: f64,
) -> f64 {
    bracketed_newton(
        |u| (gap.half_slope(u), gap.half_curvature(u)),
        left,
        right,
        slope_left,
        slope_right,
        start,
        noise,
    )
}

/// The outcome of searching one window.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum WindowSearch {
    /// The balls start to interpenetrate at this time since the window's start.
    Entry(f64),
    /// No entry; whether the balls end the window apart: the gap, having been positive, is
    /// still `≥ 0` at the window's end (carried to the next window, so that a crossing that
    /// falls exactly between two windows, or at a boundary where the gap is exactly 0, is an
    /// entry at the next window's start).
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
pub(crate) fn first_entry<const D: usize>(
    gap: &Gap<D>,
    end: f64,
    previous_positive: bool,
) -> WindowSearch {
    let g_start = gap.value(0.0);
    if previous_positive && g_start < 0.0 {
        return WindowSearch::Entry(0.0);
    }
    let (critical, count) = critical_points(gap, end, gap.half_slope_noise());
    let narrow_gap = narrow(gap);
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
        // A minimum whose float samples stay positive may still be a dip narrower than the
        // float grid: decided on the closest approach.
        if narrow_gap
            && seen_positive
            && g_left > 0.0
            && right < end
            && gap.half_curvature(right) > 0.0
            && let Some(u) = narrow_entry(gap, left, right)
        {
            return WindowSearch::Entry(u);
        }
        seen_positive |= g_right > 0.0;
        (left, g_left) = (right, g_right);
    }
    WindowSearch::NoEntry {
        ends_positive: seen_positive & (g_left >= 0.0),
    }
}

/// The window `[0, end]` settled piece by piece ([`OpenPieces`]), without the critical points
/// of the whole window: the pieces proven positive need nothing; the first open piece with a
/// single root holds the entry; an open piece with a single minimum holds the entry if `g` is
/// negative there (found between the piece's start and the minimum), and none otherwise.
/// `None` leaves the window to [`first_entry`]: a piece of another shape, or values that do not
/// confirm what the coefficients promise.
///
/// On random pairs this settles nearly all contacts and near misses at about half the cost of
/// [`first_entry`].
#[inline(always)]
pub(crate) fn piecewise_entry<const D: usize>(gap: &Gap<D>, end: f64) -> Option<WindowSearch> {
    let noise = gap.value_noise();
    for piece in OpenPieces::new(gap, end) {
        let (left, right) = (end * piece.start, end * piece.stop);
        let g_left = gap.value(left);
        if g_left <= 0.0 {
            return None;
        }
        match piece.shape {
            Shape::OneRoot => {
                let g_right = gap.value(right);
                return (g_right < 0.0).then(|| {
                    WindowSearch::Entry(entry_root(gap, (left, right), (g_left, g_right), noise))
                });
            }
            Shape::OneDip => {
                let (slope_left, slope_right) = (gap.half_slope(left), gap.half_slope(right));
                if !(slope_left < 0.0 && slope_right > 0.0) {
                    return None;
                }
                let lowest = slope_root(
                    gap,
                    (left, right),
                    (slope_left, slope_right),
                    // The slope is nearly linear on a small piece: start from its secant root.
                    left + (right - left) * (slope_left / (slope_left - slope_right)),
                    gap.half_slope_noise(),
                );
                let g_lowest = gap.value(lowest);
                if g_lowest < 0.0 {
                    return Some(WindowSearch::Entry(entry_root(
                        gap,
                        (left, lowest),
                        (g_left, g_lowest),
                        noise,
                    )));
                }
                // A dip narrower than the float grid: decided on the closest approach.
                if let Some(u) = narrow_entry(gap, left, lowest) {
                    return Some(WindowSearch::Entry(u));
                }
            }
            Shape::Other => return None,
        }
    }
    Some(WindowSearch::NoEntry {
        // The window started positive (every open piece starts so).
        ends_positive: gap.value(end) >= 0.0,
    })
}

/// The root of `g` in `(left, right)`, where `g(left) > 0 > g(right)` and `g` is monotone.
///
/// Newton starts from the root of the quadratic Taylor model of `g` at `right`. Where `right`
/// is a local minimum, or the end of a window where a ball comes to rest (the slope vanishes
/// there too), the root may be near-double (a grazing contact, or a contact just before a
/// stop): the model is then already close, where Newton from afar would crawl in, and where
/// `g` is within rounding of zero over a band far wider than the root's accuracy.
#[inline(always)]
fn entry_root<const D: usize>(
    gap: &Gap<D>,
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

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;

    fn gap(offset: [f64; 2], velocity: [f64; 2]) -> Gap {
        Gap {
            offset: Vector2::from(offset),
            velocity: Vector2::from(velocity),
            acceleration: Vector2::zeros(),
            contact_distance: 1.0,
        }
    }

    #[test]
    fn a_dip_is_settled_on_its_piece_as_the_whole_window_search_does() {
        // Passing 1e-7 above the other ball: no entry; 1e-4 below: an entry just before the
        // closest approach (u = 0.45), where |d|² = 1 first: (2u − 0.9)² = 1 − 0.9999²·…
        for (y, entry) in [
            (1.0000001, None),
            (0.9999, Some(0.45 - (1.0 - 0.9999f64 * 0.9999).sqrt() / 2.0)),
        ] {
            let g = gap([-0.9, y], [2.0, 0.0]);
            let piecewise = piecewise_entry(&g, 1.0);
            let whole = first_entry(&g, 1.0, true);
            match entry {
                None => {
                    assert_eq!(
                        piecewise,
                        Some(WindowSearch::NoEntry {
                            ends_positive: true
                        })
                    );
                    assert_eq!(
                        whole,
                        WindowSearch::NoEntry {
                            ends_positive: true
                        }
                    );
                }
                Some(u) => {
                    let (Some(WindowSearch::Entry(a)), WindowSearch::Entry(b)) = (piecewise, whole)
                    else {
                        panic!("{piecewise:?} {whole:?}")
                    };
                    assert!(
                        (a - u).abs() < 1e-15 && (b - u).abs() < 1e-15,
                        "{a} {b} {u}"
                    );
                }
            }
        }
    }
}
