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
