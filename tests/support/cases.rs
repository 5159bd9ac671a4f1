//! How many cases a property test runs: the fast tier (`./scripts/test`) runs each suite's own
//! reduced count; the thorough tier (`.ci/run`) sets `PROPTEST_CASES`, which then raises every
//! suite to that count, as it sets proptest's default configuration's. A suite whose cases are
//! cheap enough to run more of them in the fast tier keeps its count: the thorough tier never
//! runs fewer cases than the fast one.

/// `PROPTEST_CASES` if it is set and above `fast`, else `fast` (this suite's count in the fast
/// tier).
///
/// # Panics
/// If `PROPTEST_CASES` is set but is not a number (a typo must not run zero cases).
pub fn cases(fast: u32) -> u32 {
    match std::env::var("PROPTEST_CASES") {
        Ok(n) => n
            .trim()
            .parse::<u32>()
            .unwrap_or_else(|_| panic!("PROPTEST_CASES={n:?} is not a number of cases"))
            .max(fast),
        Err(_) => fast,
    }
}
