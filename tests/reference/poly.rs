//! The polynomial solvers against high-precision references.
//!
//! `tests/data/poly_cases.txt` is written by `tools/poly_reference.py`: float64 coefficients
//! (taken as exact), their real roots computed rigorously with FLINT, and for every root a
//! conditioning *floor* — how far it moves when every coefficient changes by one relative
//! rounding, 2⁻⁵³ (see the file's header). Each case must satisfy:
//!
//! - every computed root lies within [`K`] floors of a reference root, each reference root
//!   used at most once (matching in ascending order, multiplicity counted);
//! - every reference real root is found, unless it is *ambiguous*: within [`BAND`] floors of
//!   another root (a close pair or a multiple root), where float64 coefficients cannot tell a
//!   real pair from a complex one;
//! - a computed real root may stand for a complex reference root only if that root is within
//!   [`BAND`] floors of the real axis (same reason, the other way round);
//! - the classical multiple-root cases must come back with exactly their real roots.
//!
//! Run with `cargo test --release --test reference poly:: -- --nocapture` to see the accuracy
//! table (per category: max and p99.9 of error/floor and of relative error; per published
//! case: the accuracy reached). With `POLY_CASES=path`, the same checks run on another file
//! of the same format instead, such as a randomized search written by
//! `tools/poly_reference.py --only GENERATOR --count N --out path`.

use ballcollide::poly::{solve_cubic, solve_linear, solve_quadratic, solve_quartic};
use std::collections::BTreeMap;

/// A computed root must be within `K` floors of its reference root. A correctly rounded
/// root is already up to 4 floors off for a quartic (half an ulp against a floor that can be
/// as small as ε·|x|/4), so this allows a few roundings more.
const K: f64 = 8.0;

/// Roots within `BAND` floors of another root (or of the real axis, for complex ones) may be
/// reported either as a real pair or as a complex one.
const BAND: f64 = 4.0;

struct RefRoot {
    re_hi: f64,
    re_lo: f64,
    im: f64,
    floor: f64,
}

struct Case {
    category: String,
    name: String,
    coeffs: Vec<f64>,
    reals: Vec<RefRoot>,
    near_axis: Vec<RefRoot>,
}

fn parse_case(line: &str) -> Result<Case, String> {
    let mut it = line.split_whitespace();
    let mut next = |what: &str| {
        it.next()
            .ok_or_else(|| format!("missing {what} in: {line}"))
    };
    let num = |s: &str| s.parse::<f64>().map_err(|e| format!("{s}: {e}"));
    let category = next("category")?.to_string();
    let name = next("name")?.to_string();
    let degree: usize = next("degree")?
        .parse()
        .map_err(|e| format!("degree: {e}"))?;
    let mut coeffs = Vec::with_capacity(degree + 1);
    for _ in 0..=degree {
        coeffs.push(num(next("coefficient")?)?);
    }
    if next("R")? != "R" {
        return Err(format!("expected R in: {line}"));
    }
    let nreal: usize = next("nreal")?.parse().map_err(|e| format!("nreal: {e}"))?;
    let mut reals = Vec::with_capacity(nreal);
    for _ in 0..nreal {
        let re_hi = num(next("root")?)?;
        let re_lo = num(next("root lo")?)?;
        let floor = num(next("floor")?)?;
        reals.push(RefRoot {
            re_hi,
            re_lo,
            im: 0.0,
            floor,
        });
    }
    if next("A")? != "A" {
        return Err(format!("expected A in: {line}"));
    }
    let namb: usize = next("namb")?.parse().map_err(|e| format!("namb: {e}"))?;
    let mut near_axis = Vec::with_capacity(namb);
    for _ in 0..namb {
        let re_hi = num(next("re")?)?;
        let im = num(next("im")?)?;
        let floor = num(next("floor")?)?;
        near_axis.push(RefRoot {
            re_hi,
            re_lo: 0.0,
            im,
            floor,
        });
    }
    Ok(Case {
        category,
        name,
        coeffs,
        reals,
        near_axis,
    })
}

fn solve(c: &[f64]) -> Vec<f64> {
    let r = match *c {
        [a, b, cc, d, e] => solve_quartic(a, b, cc, d, e),
        [a, b, cc, d] => solve_cubic(a, b, cc, d),
        [a, b, cc] => solve_quadratic(a, b, cc),
        [a, b] => solve_linear(a, b),
        _ => Default::default(),
    };
    r.to_vec()
}

/// One candidate a computed root may be matched to.
struct Candidate<'a> {
    root: &'a RefRoot,
    required: bool,
}

impl Candidate<'_> {
    /// Distance from a computed real root, in floors, and relative to the root's size.
    fn cost(&self, x: f64) -> (f64, f64) {
        // (x − hi) − lo is accurate where it matters (x close to hi).
        let dre = (x - self.root.re_hi) - self.root.re_lo;
        let dist = dre.hypot(self.root.im);
        let ratio = if self.root.floor > 0.0 {
            dist / self.root.floor
        } else if dist == 0.0 {
            0.0
        } else {
            f64::INFINITY
        };
        let size = self.root.re_hi.hypot(self.root.im);
        let rel = if size > 0.0 { dist / size } else { dist };
        (ratio, rel)
    }
}

struct Outcome {
    /// Largest error/floor over the matched roots (None: no valid matching).
    worst_ratio: Option<f64>,
    /// Per matched computed root: (error/floor, relative error).
    errors: Vec<(f64, f64)>,
    /// Whether the number of real roots differs from the reference.
    count_differs: bool,
}

/// Bottleneck order-preserving matching of the computed roots to the candidates (sorted by
/// real part), using every required candidate.
fn check(case: &Case, computed: &[f64]) -> Outcome {
    let mut cands: Vec<Candidate> = Vec::new();
    for (i, r) in case.reals.iter().enumerate() {
        let x = r.re_hi + r.re_lo;
        let ambiguous = case.reals.iter().enumerate().any(|(j, s)| {
            j != i
                && ((s.re_hi - r.re_hi) + (s.re_lo - r.re_lo)).abs() <= BAND * (r.floor + s.floor)
        }) || case
            .near_axis
            .iter()
            .any(|z| (z.re_hi - x).hypot(z.im) <= BAND * (r.floor + z.floor));
        cands.push(Candidate {
            root: r,
            required: !ambiguous,
        });
    }
    for z in &case.near_axis {
        if z.im <= BAND * z.floor {
            // A near-axis pair may come out as two real roots.
            cands.push(Candidate {
                root: z,
                required: false,
            });
            cands.push(Candidate {
                root: z,
                required: false,
            });
        }
    }
    cands.sort_by(|a, b| a.root.re_hi.total_cmp(&b.root.re_hi));
    let m = computed.len();
    let n = cands.len();
    // best[i][j]: smallest bottleneck for computed[..i] into cands[..j] using every required
    // candidate among cands[..j]; back-pointers rebuild the matching.
    let inf = f64::INFINITY;
    let mut best = vec![vec![inf; n + 1]; m + 1];
    best[0][0] = 0.0;
    for j in 1..=n {
        best[0][j] = if cands[j - 1].required {
            inf
        } else {
            best[0][j - 1]
        };
    }
    for i in 1..=m {
        for j in 1..=n {
            let skip = if cands[j - 1].required {
                inf
            } else {
                best[i][j - 1]
            };
            let take = best[i - 1][j - 1].max(cands[j - 1].cost(computed[i - 1]).0);
            best[i][j] = skip.min(take);
        }
    }
    let count_differs = m != case.reals.len();
    if m > n || !best[m][n].is_finite() {
        return Outcome {
            worst_ratio: None,
            errors: Vec::new(),
            count_differs,
        };
    }
    let mut errors = Vec::with_capacity(m);
    let (mut i, mut j) = (m, n);
    while i > 0 && j > 0 {
        let take = best[i - 1][j - 1].max(cands[j - 1].cost(computed[i - 1]).0);
        if take <= best[i][j] {
            errors.push(cands[j - 1].cost(computed[i - 1]));
            i -= 1;
        }
        j -= 1;
    }
    Outcome {
        worst_ratio: Some(best[m][n]),
        errors,
        count_differs,
    }
}

fn quantile(v: &mut [f64], q: f64) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(f64::total_cmp);
    let k = ((v.len() as f64 - 1.0) * q).ceil() as usize;
    v[k.min(v.len() - 1)]
}

#[derive(Default)]
struct Stats {
    cases: usize,
    roots: usize,
    in_band: usize,
    ratios: Vec<f64>,
    rels: Vec<f64>,
}

/// The cases of `POLY_CASES` if set, else the committed file's (whether it was the committed
/// file is returned too).
fn load() -> (Vec<Case>, bool) {
    let committed = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/poly_cases.txt");
    let chosen = std::env::var("POLY_CASES").ok();
    let path = chosen.as_deref().unwrap_or(committed);
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let cases = text
        .lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .map(|l| parse_case(l).unwrap_or_else(|e| panic!("{e}")))
        .collect();
    (cases, chosen.is_none())
}

#[test]
fn every_reference_case_within_k_floors() {
    let (cases, committed) = load();
    if committed {
        assert!(cases.len() > 110_000, "only {} cases", cases.len());
    } else {
        assert!(!cases.is_empty(), "POLY_CASES holds no case");
    }
    let mut stats: BTreeMap<String, Stats> = BTreeMap::new();
    let mut failures = Vec::new();
    let mut published = Vec::new();
    for case in &cases {
        let computed = solve(&case.coeffs);
        let out = check(case, &computed);
        let st = stats.entry(case.category.clone()).or_default();
        st.cases += 1;
        st.roots += computed.len();
        st.in_band += usize::from(out.count_differs);
        for &(r, rel) in &out.errors {
            st.ratios.push(r);
            st.rels.push(rel);
        }
        let strict = ["classical", "extreme", "regression"].contains(&case.category.as_str());
        let ok = match out.worst_ratio {
            Some(w) => w <= K && !(strict && out.count_differs),
            None => false,
        };
        if !ok {
            failures.push(format!(
                "{} {}: coeffs {:?} computed {:?} reference {:?} worst ratio {:?}",
                case.category,
                case.name,
                case.coeffs,
                computed,
                case.reals
                    .iter()
                    .map(|r| r.re_hi + r.re_lo)
                    .collect::<Vec<_>>(),
                out.worst_ratio
            ));
        }
        if ["published", "classical", "extreme", "regression"].contains(&case.category.as_str()) {
            let max_rel = out.errors.iter().map(|e| e.1).fold(0.0, f64::max);
            published.push(format!(
                "| {} | {} | {} | {} | {:.2} | {:.1e} |",
                case.category,
                case.name,
                case.reals.len(),
                computed.len(),
                out.worst_ratio.unwrap_or(f64::NAN),
                max_rel
            ));
        }
    }
    eprintln!("\nK = {K}, BAND = {BAND}");
    eprintln!(
        "| category | cases | real roots found | count differs (in band) | max err/floor | p99.9 err/floor | max rel err | p99.9 rel err |"
    );
    eprintln!("|---|---|---|---|---|---|---|---|");
    for (cat, st) in &mut stats {
        let max_r = st.ratios.iter().copied().fold(0.0, f64::max);
        let max_rel = st.rels.iter().copied().fold(0.0, f64::max);
        let p_r = quantile(&mut st.ratios, 0.999);
        let p_rel = quantile(&mut st.rels, 0.999);
        eprintln!(
            "| {cat} | {} | {} | {} | {max_r:.2} | {p_r:.2} | {max_rel:.1e} | {p_rel:.1e} |",
            st.cases, st.roots, st.in_band
        );
    }
    eprintln!(
        "\n| category | case | real roots (reference) | real roots (computed) | max err/floor | max rel err |"
    );
    eprintln!("|---|---|---|---|---|---|");
    for line in &published {
        eprintln!("{line}");
    }
    assert!(
        failures.is_empty(),
        "{} of {} cases fail:\n{}",
        failures.len(),
        cases.len(),
        failures
            .iter()
            .take(40)
            .cloned()
            .collect::<Vec<_>>()
            .join("\n")
    );
}

#[test]
fn matching_rejects_wrong_answers() {
    // The checker itself must be able to fail: a shifted root, a missing root and an extra
    // root are all caught on a well-conditioned case.
    let case = parse_case(
        "classical w 4 1.0 -10.0 35.0 -50.0 24.0 R 4 1.0 0.0 1e-15 2.0 0.0 1e-15 3.0 0.0 1e-15 4.0 0.0 1e-15 A 0",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(check(&case, &[1.0, 2.0, 3.0, 4.0]).worst_ratio, Some(0.0));
    assert!(
        check(&case, &[1.0, 2.0, 3.0, 4.0 + 1e-13])
            .worst_ratio
            .is_some_and(|w| w > K)
    );
    assert!(check(&case, &[1.0, 2.0, 3.0]).worst_ratio.is_none());
    assert!(
        check(&case, &[1.0, 2.0, 3.0, 4.0, 5.0])
            .worst_ratio
            .is_none()
    );
}
