//! Lengths and directions of vectors in the plane, computed as pooltool computes them (its
//! `norm3d` and `unit_vector` on vectors whose third component is 0), so that the times and
//! states built from them have its bits.

use nalgebra::Vector2;

/// `|v|` as pooltool's `norm3d`: `sqrt(x·x + y·y)`, without the scaling of `hypot` (its
/// third term, `0·0`, changes no bit).
pub(super) fn norm(v: Vector2<f64>) -> f64 {
    (v.x * v.x + v.y * v.y).sqrt()
}

/// `v / |v|`, each component divided by the [`norm`] as pooltool's `unit_vector` does; the
/// zero vector for `v = 0`, where pooltool divides by zero (its direction is then unused:
/// a zero slip or a zero velocity has nothing to slow down).
pub(super) fn unit(v: Vector2<f64>) -> Vector2<f64> {
    let n = norm(v);
    if n == 0.0 { Vector2::zeros() } else { v / n }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_vectors() {
        assert_eq!(unit(Vector2::new(3.0, -4.0)), Vector2::new(0.6, -0.8));
        assert_eq!(unit(Vector2::zeros()), Vector2::zeros());
        assert_eq!(norm(Vector2::new(-3.0, 4.0)), 5.0);
    }
}
