//! Numerical stability under stress (the CPU path): tolerances scale with
//! the problem. (Every family through every method against the reference:
//! `lcpbatch stress`'s tests in src/bin/lcpbatch/stress.rs.)

use super::common;

use crate::cpu::enumeration::{enumerate, EnumerationSettings};
use crate::generate::stress::{generate, scaled, siconos_scaled, Family, StressCase};

const CASES: usize = 300;

fn all_cases() -> Vec<(String, Vec<StressCase>)> {
    let mut out: Vec<(String, Vec<StressCase>)> = Family::ALL
        .iter()
        .map(|&f| (f.name().to_string(), generate(f, 2026, CASES)))
        .collect();
    if let Some(dir) = common::siconos_dir() {
        let cases = siconos_scaled(&dir).expect("the Siconos files parse");
        out.push((
            "siconos_scaled".into(),
            cases.into_iter().map(|(_, c)| c).collect(),
        ));
    }
    out
}

#[test]
fn scaling_m_and_q_by_1e6_changes_no_status_and_no_basis() {
    let s = EnumerationSettings::default();
    let mut checked = 0;
    for (label, cases) in all_cases() {
        for c in &cases {
            let a = enumerate(&c.lcp, &s).unwrap();
            for f in [1e-6, 1e6] {
                let b = enumerate(&scaled(&c.lcp, f), &s).unwrap();
                assert_eq!(
                    (a.status, a.basis),
                    (b.status, b.basis),
                    "{label} p={} scaled by {f:e}",
                    c.parameter
                );
                checked += 1;
            }
        }
    }
    assert!(checked > 4000, "{checked}");
}
