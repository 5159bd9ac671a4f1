//! The per-category table of errors against a high-precision reference, shared by the
//! reference tests: each case's time is compared with the exact one in units of its floor.
//! SPEC's bar: no hit/miss disagreement outside the cases flagged ambiguous, and
//! `|t − t_ref| ≤ 64·floor` (or 4 ulp of `t_ref` where that is larger).

use std::collections::BTreeMap;

/// One ulp of `x`.
pub fn ulp(x: f64) -> f64 {
    let x = x.abs();
    f64::from_bits(x.to_bits() + 1) - x
}

/// One category's counts and error ratios.
#[derive(Default)]
pub struct Stats {
    cases: usize,
    hits: usize,
    ambiguous: usize,
    ratios: Vec<f64>,
    worst: (f64, usize),
    failures: Vec<String>,
}

/// The table, by category.
#[derive(Default)]
pub struct Table {
    by_category: BTreeMap<String, Stats>,
    total: usize,
}

fn percentile(sorted: &[f64], p: f64) -> f64 {
    if sorted.is_empty() {
        return 0.0;
    }
    let k = ((sorted.len() as f64 - 1.0) * p).round() as usize;
    sorted[k]
}

impl Table {
    /// Records one case: what the library gave and what the reference says.
    #[allow(clippy::too_many_arguments)]
    pub fn record(
        &mut self,
        category: &str,
        line: usize,
        got: Option<f64>,
        t_ref: f64,
        floor: f64,
        ambiguous: bool,
    ) {
        self.total += 1;
        let stats = self.by_category.entry(category.to_string()).or_default();
        stats.cases += 1;
        stats.ambiguous += ambiguous as usize;
        let want = t_ref.is_finite().then_some(t_ref);
        stats.hits += want.is_some() as usize;
        match (got, want) {
            (Some(t), Some(t_ref)) => {
                let err = (t - t_ref).abs();
                let tolerance = (64.0 * floor).max(4.0 * ulp(t_ref));
                let scale = floor.max(ulp(t_ref));
                // The distribution is of the cases the bar applies to: either answer may come
                // back for an ambiguous one (a contact or another, much later).
                if !ambiguous {
                    stats.ratios.push(err / scale);
                    if err / scale > stats.worst.0 {
                        stats.worst = (err / scale, line);
                    }
                }
                if err > tolerance && !ambiguous {
                    stats.failures.push(format!(
                        "line {line}: t = {t:e}, t_ref = {t_ref:e}, error/floor = {:.1}",
                        err / floor
                    ));
                }
            }
            (None, None) => {}
            _ if ambiguous => {}
            (got, _) => stats.failures.push(format!(
                "line {line}: hit/miss differs: got {got:?}, reference {want:?}"
            )),
        }
    }

    /// Prints the table (run with `--nocapture`; error/floor over the cases not flagged
    /// ambiguous) and fails on any failure, or on fewer than `at_least` cases.
    pub fn check(mut self, at_least: usize) {
        assert!(
            self.total >= at_least,
            "only {} reference cases",
            self.total
        );
        eprintln!(
            "{:<22} {:>6} {:>6} {:>6} {:>12} {:>12} {:>6} {:>7}",
            "category", "cases", "hits", "ambig", "p99.9 err/fl", "max err/fl", "fails", "at line"
        );
        let mut failures = Vec::new();
        for (name, stats) in &mut self.by_category {
            stats.ratios.sort_by(f64::total_cmp);
            eprintln!(
                "{:<22} {:>6} {:>6} {:>6} {:>12.2} {:>12.2} {:>6} {:>7}",
                name,
                stats.cases,
                stats.hits,
                stats.ambiguous,
                percentile(&stats.ratios, 0.999),
                stats.ratios.last().copied().unwrap_or(0.0),
                stats.failures.len(),
                stats.worst.1
            );
            failures.extend(stats.failures.iter().map(|f| format!("{name}: {f}")));
        }
        assert!(
            failures.is_empty(),
            "{} failures, first ones:\n{}",
            failures.len(),
            failures
                .iter()
                .take(30)
                .cloned()
                .collect::<Vec<_>>()
                .join("\n")
        );
    }
}
