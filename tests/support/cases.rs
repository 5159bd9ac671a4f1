//! How many cases a property test runs: the fast tier (`./scripts/test`) runs each suite's own
//! reduced count; the thorough tier (`.ci/run`) sets `PROPTEST_CASES`, which then applies to
//! every suite, as it does to proptest's default configuration.

/// `PROPTEST_CASES` if it is set, else `fast` (this suite's count in the fast tier).
///
/// # Panics
/// If `PROPTEST_CASES` is set but is not a number (a typo must not run zero cases).
pub fn cases(fast: u32) -> u32 {
    match std::env::var("PROPTEST_CASES") {
        Ok(n) => n
            .trim()
            .parse()
            .unwrap_or_else(|_| panic!("PROPTEST_CASES={n:?} is not a number of cases")),
        Err(_) => fast,
    }
}
