//! Second opinion: the first-contact search against a full quartic solve.
//!
//! On random table pairs whose contact (if any) happens while both balls still move, the
//! collision time must be the first root of the window's gap quartic, found by
//! [`solve_quartic`], where the gap goes from positive to negative. The two methods share
//! only the coefficients, so a root missed or invented by either shows up here. Cases within
//! rounding of a grazing contact (a root pair closer than 1e-6 of the window) are skipped:
//! there either answer is acceptable and the mpmath reference test decides.

use ballcollide::poly::{eval, solve_quartic};
use ballcollide::{Ball, Gap, collision_time};
use nalgebra::Vector2;

use crate::support::rng;
use rng::Rng;

#[test]
fn first_contact_is_the_first_entry_root_of_the_quartic() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let radius = 0.05715;
    let (mut hits, mut checked, mut skipped) = (0, 0, 0);
    for _ in 0..200_000 {
        let mut ball = |aim: Option<Vector2<f64>>| {
            let p = Vector2::new(rng.uniform(0.0, 2.54), rng.uniform(0.0, 1.27));
            let speed = rng.uniform(0.0, 3.0);
            let angle = match aim {
                Some(target) => {
                    let d = target - p;
                    d.y.atan2(d.x) + rng.uniform(-0.1, 0.1)
                }
                None => rng.uniform(0.0, std::f64::consts::TAU),
            };
            let v = Vector2::new(angle.cos(), angle.sin()) * speed;
            Ball::new(p, v, rng.uniform(0.05, 2.0)).expect("valid ball")
        };
        let b = ball(None);
        let mut a = ball(Some(b.position()));
        if rng.uniform(0.0, 1.0) < 0.25 {
            // Nearly parallel with equal friction: the quartic's leading coefficients are
            // ~ε² and ~ε, with huge spurious roots far outside the window.
            let angle = 10f64.powf(rng.uniform(-12.0, -6.0));
            let v = nalgebra::Rotation2::new(angle) * b.velocity() * rng.uniform(0.5, 2.0);
            a = Ball::new(a.position(), v, b.friction()).expect("valid ball");
        }
        let window = a.stop_time().min(b.stop_time());
        let gap = Gap::between(&a, &b, radius, 0.0);
        let [qa, qb, qc, qd, qe] = gap.quartic();
        if qe <= 0.0 {
            continue; // starting in contact: semantics tested elsewhere
        }
        let roots = solve_quartic(qa, qb, qc, qd, qe);
        let in_window: Vec<f64> = roots
            .iter()
            .copied()
            .filter(|&t| t >= 0.0 && t < window)
            .collect();
        // The first root where the quartic goes from + to −.
        let coeffs = [qa, qb, qc, qd, qe];
        let slope = |t: f64| eval(&[4.0 * qa, 3.0 * qb, 2.0 * qc, qd], t);
        let expected = in_window.iter().copied().find(|&t| slope(t) < 0.0);
        let close_pair = roots
            .windows(2)
            .any(|w| (w[1] - w[0]).abs() < 1e-6 * window.max(1.0));
        let got = collision_time(&a, &b, radius).expect("valid radius");
        // A contact after the first stop is another window's business; one within rounding of
        // the stop may fall on either side.
        let got = got.filter(|&t| t < window);
        let near_stop = got.is_some_and(|t| t > window * (1.0 - 1e-9))
            || expected.is_some_and(|t| t > window * (1.0 - 1e-9));
        if close_pair || near_stop {
            skipped += 1;
            continue;
        }
        checked += 1;
        match (got, expected) {
            (None, None) => {}
            (Some(t), Some(root)) => {
                hits += 1;
                assert!(
                    (t - root).abs() <= 1e-9 * t.max(1e-3),
                    "a = {a:?}, b = {b:?}: search {t}, quartic {root}, g(root) = {}",
                    eval(&coeffs, root)
                );
            }
            (got, expected) => panic!(
                "a = {a:?}, b = {b:?}: search {got:?}, quartic {expected:?}, roots {roots:?}"
            ),
        }
    }
    eprintln!(
        "checked {checked} pairs ({hits} hits), skipped {skipped} near-grazing or after a stop"
    );
    assert!(hits > 1000, "too few hits to mean anything: {hits}");
}
