//! One pair, two queries: `collision_time` on friction balls and `path_collision_time` on the
//! same balls as paths (`Ball::path`) give the same hit or miss, and times within the floor,
//! down to contact distances of `2⁻⁴⁰⁰` of the separation (issue 39). The pairs and the check
//! are shared with the fuzz target `queries` (`tests/support/narrow_pairs.rs`).

use crate::support::{cases, narrow_pairs};

use narrow_pairs::{NarrowDraw, narrow_pair, queries_agree};
use proptest::prelude::*;

fn draw_strategy() -> impl Strategy<Value = NarrowDraw> {
    (
        (any::<u32>(), any::<bool>(), any::<i32>(), any::<i32>()),
        (
            any::<u32>(),
            any::<u32>(),
            any::<u32>(),
            any::<u32>(),
            any::<u32>(),
        ),
        prop::array::uniform6(0.0f64..1.0),
    )
        .prop_map(
            |((line, sideways, length, time), (sep, xa, sa, sb, b_kind), fractions)| NarrowDraw {
                line,
                sideways,
                length,
                time,
                sep,
                xa,
                sa,
                sb,
                b_kind,
                fractions,
            },
        )
}

proptest! {
    // Two cheap queries a case (about 10 µs): many cases (more if `PROPTEST_CASES` asks).
    #![proptest_config(ProptestConfig::with_cases(cases::cases(4096)))]

    #[test]
    fn both_queries_agree_on_one_pair(draw in draw_strategy()) {
        let (a, b, radius) = narrow_pair(&draw);
        if let Err(e) = queries_agree(&a, &b, radius) {
            prop_assert!(false, "{}", e);
        }
    }
}

/// Found by the `queries` fuzz target: a slow ball braking head on into a fast frictionless
/// one, the contact distance 2⁻⁵² of their distance, the contact at 2⁻²² of the slow ball's
/// run. `collision_time` came 85 floors late (its window search sized its steps by the
/// window); the exact time (mpmath, 60 digits, from the inputs' binary values) is
/// 7.94728597005229933e-8.
#[test]
fn a_fast_frictionless_ball_into_a_slow_braking_one_agrees_in_both_queries() {
    use ballcollide::{Ball, collision_time};
    use nalgebra::Vector2;
    let a = Ball::new(
        Vector2::new(0.0, 0.0),
        Vector2::new(1.1920928955078125e-7, 0.0),
        2.422030009920635e-7,
    )
    .expect("valid");
    let b = Ball::new(
        Vector2::new(2.7939677238464355e-8, 0.0),
        Vector2::new(-0.35156238079071045, -0.0),
        0.0,
    )
    .expect("valid");
    let radius = 5.5070888047512506e-24;
    queries_agree(&a, &b, radius).expect("the two queries agree");
    let t = collision_time(&a, &b, radius)
        .expect("valid")
        .expect("a contact");
    let exact = 7.947_285_970_052_3e-8; // (the nearest float to it)
    // Within the case's floor (ε·(t + distance / closing speed), about 1.8e-23).
    assert!((t - exact).abs() <= 2e-23, "{t:e} against {exact:e}");
}
