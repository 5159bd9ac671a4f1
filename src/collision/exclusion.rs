//! A cheap, rigorous proof that two balls cannot touch on a window.
//!
//! On `u ∈ [0, 1]` the gap quartic `g(u) = Σ aᵢ uⁱ` equals `Σ bⱼ Bⱼ(u)` in the Bernstein basis
//! `Bⱼ(u) = C(4, j) uʲ (1 − u)⁴⁻ʲ`, whose functions are non-negative and sum to one: `g` lies
//! between the smallest and the largest `bⱼ`. So if every `bⱼ` exceeds the rounding error made
//! in computing it, `g > 0` on the whole interval and there is no contact. On random pairs on
//! a table this settles most pairs with a dozen multiply-adds and no division or root.

use crate::coefficients::Gap;

/// Whether `g(u) > 0` is proven for every `u ∈ [0, 1]` (time already scaled to the window).
///
/// `false` means "not proven", not "there is a root".
///
/// The margin bounds the rounding error of the dot products and of the basis change: each
/// `bⱼ` is a combination with weights ≤ 1 of terms each bounded by products of the
/// components' magnitudes, so `8·ε·M²`, with `M` the sum of all components' magnitudes and
/// the radius, exceeds it.
pub(crate) fn proves_positive(gap: &Gap) -> bool {
    let [a4, a3, a2, a1, a0] = gap.quartic();
    let b0 = a0;
    let b1 = a0 + 0.25 * a1;
    let b2 = a0 + 0.5 * a1 + a2 / 6.0;
    let b3 = a0 + 0.75 * a1 + 0.5 * a2 + 0.25 * a3;
    let b4 = a0 + a1 + a2 + a3 + a4;
    let m = gap.offset.abs().sum()
        + gap.velocity.abs().sum()
        + gap.acceleration.abs().sum()
        + gap.radius;
    let margin = 8.0 * f64::EPSILON * m * m;
    b0.min(b1).min(b2).min(b3).min(b4) > margin
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
            radius: 1.0,
        }
    }

    #[test]
    fn far_apart_and_receding_is_excluded() {
        assert!(proves_positive(&gap([5.0, 0.0], [1.0, 0.0], [-0.5, 0.0])));
    }

    #[test]
    fn contact_inside_the_window_is_never_excluded() {
        // Head-on: |d| = 3 − 4u reaches 1 at u = 0.5.
        assert!(!proves_positive(&gap([3.0, 0.0], [-4.0, 0.0], [0.0, 0.0])));
        // Grazing from above by 1e-12: not provable, so not excluded either.
        assert!(!proves_positive(&gap(
            [-1.0, 1.0 + 1e-12],
            [2.0, 0.0],
            [0.0, 0.0]
        )));
    }
}
