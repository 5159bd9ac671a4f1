//! Lengths, directions and cross products of vectors, computed as pooltool computes them (its
//! `norm3d`, `unit_vector` and `cross`; in the plane, on vectors whose third component is 0),
//! so that what is built from them has its bits.

use nalgebra::{Vector2, Vector3};

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

/// `|v|` in space, as pooltool's `norm3d`: `sqrt(x·x + y·y + z·z)`, left to right.
pub(super) fn norm3(v: Vector3<f64>) -> f64 {
    (v.x * v.x + v.y * v.y + v.z * v.z).sqrt()
}

/// `v / |v|` in space, as pooltool's `unit_vector` (NaN for `v = 0`, as pooltool's: callers
/// check first).
pub(super) fn unit3(v: Vector3<f64>) -> Vector3<f64> {
    v / norm3(v)
}

/// `a × b`, component by component as pooltool's `cross`.
pub(super) fn cross(a: Vector3<f64>, b: Vector3<f64>) -> Vector3<f64> {
    Vector3::new(
        a.y * b.z - a.z * b.y,
        a.z * b.x - a.x * b.z,
        a.x * b.y - a.y * b.x,
    )
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
