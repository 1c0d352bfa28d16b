//! The Siconos numerics LCP test problems (../shared/conformance/siconos),
//! read by the .dat reader and solved by every solver, against the
//! independent reference in `reference.json`.
//!
//! Comparisons (see tests/common): w relative to ‖q‖∞ + ‖M‖∞·‖z‖∞, z relative
//! to ‖z‖∞, both to 1e-9; accuracy is the Siconos error measure.

use super::common;

use std::collections::BTreeMap;
use std::path::Path;

use super::common::{
    all_solutions_settings, run, settings, siconos_dir, w_rel_diff, z_rel_diff, METHODS,
};
use crate::cpu::enumeration::distinct_solutions;
use crate::cpu::pgs::PgsSettings;
use crate::io::siconos::parse_dat;
use crate::io::{read_input, Input};
use crate::settings::Method;
use crate::tests::reference::solve;
use crate::{Lcp, SolutionSet, Status};
use serde_json::Value;

const TOL: f64 = 1e-9;
/// Enumeration of every basis is asked to classify problems up to this n.
const ENUM_ALL_MAX_N: usize = 16;

struct Problem {
    name: String,
    lcp: Lcp,
    reference: Value,
}

impl Problem {
    fn expected_failure(&self, solver: &str) -> bool {
        self.reference["siconos_expected_failures"]
            .as_array()
            .is_some_and(|v| v.iter().any(|s| s == solver))
    }
    fn symmetric(&self) -> bool {
        self.reference["symmetric"] == true
    }
    fn sym_pd(&self) -> bool {
        self.symmetric() && self.reference["sym_part"] == "PD"
    }
    /// The reference solutions as (z, w), w recomputed where the reference omits it.
    fn solutions(&self) -> Vec<(Vec<f64>, Vec<f64>)> {
        self.reference["solutions"]
            .as_array()
            .map(|v| {
                v.iter()
                    .map(|s| {
                        let z = numbers(&s["z"]);
                        let w = if s["w"].is_array() {
                            numbers(&s["w"])
                        } else {
                            self.lcp.w(&z).into_vec()
                        };
                        (z, w)
                    })
                    .collect()
            })
            .unwrap_or_default()
    }
    /// The reference's solution set, in the library's terms. None for the
    /// descriptions enumeration is not asked to reproduce (n > 16).
    fn solution_set(&self) -> Option<SolutionSet> {
        let s = self.reference["solution_set"]
            .as_str()
            .expect("solution_set");
        Some(if s.starts_with("unique") {
            SolutionSet::Isolated { count: 1 }
        } else if s == "bounded continuum" {
            SolutionSet::BoundedContinuum
        } else if s == "unbounded continuum" {
            SolutionSet::UnboundedContinuum
        } else if s == "empty" {
            SolutionSet::Empty
        } else if let Some(rest) = s.strip_prefix("finite (") {
            let count = rest.split_whitespace().next()?.parse().ok()?;
            SolutionSet::Isolated { count }
        } else {
            return None;
        })
    }
    fn isolated(&self) -> bool {
        !matches!(
            self.solution_set(),
            Some(SolutionSet::BoundedContinuum | SolutionSet::UnboundedContinuum)
        )
    }
}

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .expect("array")
        .iter()
        .map(|x| x.as_f64().expect("number"))
        .collect()
}

fn load(dir: &Path) -> Vec<Problem> {
    let text = std::fs::read_to_string(dir.join("reference.json")).expect("reference.json");
    let reference: Value = serde_json::from_str(&text).expect("reference.json parses");
    let problems = reference["problems"].as_object().expect("problems");
    let mut out = Vec::new();
    for (name, r) in problems {
        let path = dir.join(r["file"].as_str().expect("file"));
        let Input::Lcps(mut lcps) = read_input(&path).unwrap_or_else(|e| panic!("{name}: {e}"))
        else {
            panic!("{name}: a .dat file reads as LCPs");
        };
        assert_eq!(lcps.len(), 1);
        let lcp = lcps.pop().unwrap();
        assert_eq!(lcp.n() as u64, r["n"].as_u64().unwrap(), "{name}: n");
        assert_eq!(
            lcp.is_symmetric(),
            r["symmetric"] == true,
            "{name}: symmetry"
        );
        out.push(Problem {
            name: name.clone(),
            lcp,
            reference: r.clone(),
        });
    }
    assert_eq!(out.len(), 20, "the folder holds 20 problems");
    out
}

/// Does (z, w) match one of the reference solutions (w always, z too when
/// the solution set is isolated)? Returns the best w and z differences.
fn closest(p: &Problem, z: &[f64], w: &[f64]) -> Option<(f64, f64)> {
    p.solutions()
        .iter()
        .map(|(rz, rw)| (w_rel_diff(&p.lcp, z, w, rz, rw), z_rel_diff(z, rz)))
        .min_by(|a, b| (a.0 + a.1).total_cmp(&(b.0 + b.1)))
}

#[test]
fn block_files_parse_to_their_dense_twins() {
    let Some(dir) = siconos_dir() else { return };
    for name in ["deudeu", "ortiz", "trivial"] {
        let read = |f: String| {
            let text = std::fs::read_to_string(dir.join(&f)).unwrap();
            parse_dat(&f, &text).unwrap_or_else(|e| panic!("{e}"))
        };
        let dense = read(format!("lcp_{name}.dat"));
        let block = read(format!("lcp_{name}_block.dat"));
        assert_eq!(dense, block, "{name}: block and dense storage differ");
        // Storage types really differ (the second token).
        let storage = |f: String| {
            std::fs::read_to_string(dir.join(f))
                .unwrap()
                .split_whitespace()
                .nth(1)
                .unwrap()
                .to_string()
        };
        assert_eq!(storage(format!("lcp_{name}.dat")), "0");
        assert_eq!(storage(format!("lcp_{name}_block.dat")), "1");
    }
}

#[test]
fn reference_solutions_solve_their_problems() {
    // A check of the reader: the documented solutions are solutions of what
    // it read. The error measure is ≤ 1e-12 except on lcp_tobenna (n = 40,
    // cond₂ ≈ 1.8e6, z up to 562), whose printed solutions give about 5e-10.
    let Some(dir) = siconos_dir() else { return };
    for p in load(&dir) {
        let bound = if p.name == "lcp_tobenna" { 1e-9 } else { 1e-12 };
        for (z, w) in p.solutions() {
            let r = p.lcp.residuals(&z);
            assert!(
                r.error <= bound,
                "{}: reference solution error {}",
                p.name,
                r.error
            );
            // The documented w is M z + q.
            let dw =
                common::max_diff(&w, &p.lcp.w(&z)) / common::w_scale(&p.lcp, common::inf_norm(&z));
            assert!(dw <= 1e-12, "{}: documented w differs by {dw:.1e}", p.name);
        }
    }
}

#[test]
fn enumeration_finds_the_documented_solution_sets() {
    let Some(dir) = siconos_dir() else { return };
    let mut checked = 0;
    for p in load(&dir) {
        if p.lcp.n() > ENUM_ALL_MAX_N {
            // Beyond the enumeration limit the solver says so.
            if p.lcp.n() > crate::cpu::enumeration::MAX_ENUMERATION_N {
                assert!(
                    solve(&p.lcp, &all_solutions_settings()).is_err(),
                    "{}",
                    p.name
                );
            }
            continue;
        }
        checked += 1;
        let expected = p.solution_set().expect("solution set described");
        let sol = solve(&p.lcp, &all_solutions_settings()).unwrap();
        eprintln!(
            "{:34} n = {:2}  enum: {:18} set {:?}, {} valid bases, error {:.1e}",
            p.name,
            p.lcp.n(),
            sol.status.name(),
            sol.solution_set,
            sol.all_bases.len(),
            sol.residuals.error
        );
        assert_eq!(sol.solution_set.as_ref(), Some(&expected), "{}", p.name);
        let expected_status = match expected {
            SolutionSet::Empty => Status::NoSolution,
            SolutionSet::Isolated { count: 1 } => Status::Solved,
            _ => Status::MultipleSolutions,
        };
        assert_eq!(sol.status, expected_status, "{}", p.name);
        if expected == SolutionSet::Empty {
            assert!(sol.all_bases.is_empty());
            continue;
        }
        assert!(
            sol.residuals.error <= 1e-12,
            "{}: error {}",
            p.name,
            sol.residuals.error
        );
        // Feasible nonsingular bases: as many as the reference counts.
        assert_eq!(
            sol.all_bases.len() as u64,
            p.reference["feasible_nonsingular_complementary_bases"]
                .as_u64()
                .unwrap(),
            "{}: {:?}",
            p.name,
            sol.all_bases
        );
        // Every valid basis is a solution and one of the bases the reference
        // lists for the solution it gives.
        let refs = p.reference["solutions"].as_array().unwrap();
        for b in &sol.all_bases {
            let e = p.lcp.residuals(&b.z).error;
            assert!(e <= 1e-12, "{}: basis {:b} error {e}", p.name, b.basis);
            let idx: Vec<u64> = (0..p.lcp.n() as u64)
                .filter(|i| b.basis >> i & 1 == 1)
                .collect();
            let hit = refs.iter().find(|r| {
                r["bases_giving_it"].as_array().unwrap().iter().any(|bs| {
                    numbers(bs)
                        .iter()
                        .map(|&x| x as u64)
                        .eq(idx.iter().copied())
                })
            });
            let Some(r) = hit else {
                panic!("{}: basis {idx:?} is not a documented basis", p.name)
            };
            let (rz, rw) = (numbers(&r["z"]), numbers(&r["w"]));
            let (dw, dz) = (
                w_rel_diff(&p.lcp, &b.z, &b.w, &rz, &rw),
                z_rel_diff(&b.z, &rz),
            );
            assert!(
                dw <= TOL && dz <= TOL,
                "{}: basis {idx:?}: dw {dw:.1e}, dz {dz:.1e}",
                p.name
            );
        }
        // Every documented solution is found.
        let distinct = distinct_solutions(&sol.all_bases);
        for (rz, rw) in p.solutions() {
            let found = distinct.iter().any(|b| {
                w_rel_diff(&p.lcp, &b.z, &b.w, &rz, &rw) <= TOL && z_rel_diff(&b.z, &rz) <= TOL
            });
            assert!(found, "{}: reference solution {rz:?} not found", p.name);
        }
        if let SolutionSet::Isolated { count } = expected {
            assert_eq!(distinct.len(), count, "{}", p.name);
        }
    }
    assert_eq!(checked, 18);
}

/// Lemke on one problem: a ray where Siconos expects LEMKE to fail, else a
/// solution that matches the reference.
fn check_lemke(p: &Problem) {
    let sol = run(&p.lcp, Method::Lemke);
    eprintln!(
        "{:34} n = {:2}  lemke: {:16} pivots {:5} error {:.1e}",
        p.name,
        p.lcp.n(),
        sol.status.name(),
        sol.counters.pivots,
        sol.residuals.error
    );
    if p.expected_failure("LEMKE") {
        assert_eq!(sol.status, Status::RayTermination, "{}", p.name);
        return;
    }
    assert_eq!(
        sol.status,
        Status::Solved,
        "{}: {:?}",
        p.name,
        sol.residuals
    );
    assert!(
        sol.residuals.error <= 1e-12,
        "{}: error {}",
        p.name,
        sol.residuals.error
    );
    let (dw, dz) = closest(p, &sol.z, &sol.w).expect("reference solutions");
    if p.isolated() {
        assert!(
            dw <= TOL && dz <= TOL,
            "{}: dw {dw:.1e}, dz {dz:.1e}",
            p.name
        );
    } else if p.symmetric() {
        // Symmetric PSD M: w is the same at every solution of a continuum.
        assert!(dw <= TOL, "{}: dw {dw:.1e}", p.name);
    }
}

#[test]
fn lemke_agrees_with_the_reference() {
    let Some(dir) = siconos_dir() else { return };
    for p in load(&dir).iter().filter(|p| p.name != "lcp_tobenna") {
        check_lemke(p);
    }
}

/// The reference says Lemke solves lcp_tobenna (n = 40, 13 isolated
/// solutions); before commit 0d80653 (exact lexicographic ratio test) Lemke
/// cycled into its pivot cap there.
#[test]
fn lemke_solves_tobenna() {
    let Some(dir) = siconos_dir() else { return };
    let problems = load(&dir);
    let p = problems.iter().find(|p| p.name == "lcp_tobenna").unwrap();
    assert!(!p.expected_failure("LEMKE"));
    check_lemke(p);
}

#[test]
fn pgs_statuses_and_errors() {
    let Some(dir) = siconos_dir() else { return };
    let defaults = PgsSettings::default();
    for p in load(&dir) {
        let sol = run(&p.lcp, Method::Pgs);
        eprintln!(
            "{:34} n = {:2}  pgs: {:14} sweeps {:5} error {:.1e}",
            p.name,
            p.lcp.n(),
            sol.status.name(),
            sol.counters.iterations,
            sol.residuals.error
        );
        // The reported error is the error of the reported z.
        let r = p.lcp.residuals(&sol.z);
        assert_eq!(r.error, sol.residuals.error, "{}", p.name);
        // Never "solved" with an error above its tolerance.
        if sol.status == Status::Solved {
            assert!(sol.residuals.error <= defaults.tolerance, "{}", p.name);
        }
        // Zero diagonal entries are refused, not divided by.
        let zero_diag = (0..p.lcp.n()).any(|i| p.lcp.at(i, i).is_nan() || p.lcp.at(i, i) <= 0.0);
        assert_eq!(sol.status == Status::InvalidInput, zero_diag, "{}", p.name);
        if p.sym_pd() {
            // Symmetric positive definite: PGS converges within its default
            // sweep cap (lcp_mmc, n = 26, cond₂ ≈ 1.2e3, takes the most: ~460).
            assert_eq!(
                sol.status,
                Status::Solved,
                "{}: {:?}",
                p.name,
                sol.residuals
            );
            let (dw, dz) = closest(&p, &sol.z, &sol.w).unwrap();
            // PGS stops at error 1e-10: agreement to about that.
            assert!(
                dw <= 1e-8 && dz <= 1e-7,
                "{}: dw {dw:.1e}, dz {dz:.1e}",
                p.name
            );
        }
    }
}

#[test]
fn every_problem_reads_and_the_statuses_are_summarised() {
    // One table of every solver's status per problem (shown with --nocapture).
    let Some(dir) = siconos_dir() else { return };
    let mut table = BTreeMap::new();
    for p in load(&dir) {
        let mut row = Vec::new();
        for s in METHODS {
            match solve(&p.lcp, &settings(s)) {
                Ok(sol) => row.push(format!(
                    "{}:{}({:.0e})",
                    s.name(),
                    sol.status,
                    sol.residuals.error
                )),
                Err(e) => {
                    assert!(p.lcp.n() > 20, "{}: {e}", p.name);
                    row.push(format!("{}:n/a", s.name()))
                }
            }
        }
        table.insert(p.name.clone(), row.join(" "));
    }
    for (k, v) in &table {
        eprintln!("{k:34} {v}");
    }
    assert_eq!(table.len(), 20);
}
