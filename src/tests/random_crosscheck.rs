//! Randomized cross-checks with fixed seeds: enumeration against Lemke on
//! 10,000 physical islands, and the readers against random and mutated input.
//!
//! Agreement is measured (tests/common) as
//!
//! ```text
//! dw = max_i |w_enum,i − w_lemke,i| / (‖q‖∞ + ‖M‖∞ · max(‖z_enum‖∞, ‖z_lemke‖∞))
//! dz = max_i |z_enum,i − z_lemke,i| / max(‖z_enum‖∞, ‖z_lemke‖∞)
//! ```
//!
//! with dw ≤ 1e-9 on every island (w is unique for symmetric PSD M) and
//! dz ≤ 1e-9 where the solution is unique (M positive definite: a Cholesky
//! factorisation whose every pivot exceeds 1e-8 of the largest diagonal
//! entry), and the Siconos error of both ≤ 1e-12.

use super::common;

use super::common::{is_positive_definite, run, settings, w_rel_diff, z_rel_diff};
use crate::generate::{random_island, Rng};
use crate::io::parse_json;
use crate::io::siconos::parse_dat;
use crate::settings::Method;
use crate::tests::reference::build;
use crate::{Lcp, Status};
use proptest::prelude::*;

const ISLANDS: usize = 10_000;
const MAX_N: usize = 10;
const MASS_RATIO: f64 = 100.0;
const TOL: f64 = 1e-9;
const ERROR_TOL: f64 = 1e-12;
/// Cholesky pivots above this (relative to the largest diagonal entry) count
/// as positive definite: z is then unique and compared too.
const PD_TOL: f64 = 1e-8;

#[test]
fn enumeration_and_lemke_agree_on_random_islands() {
    let mut rng = Rng::new(0x5EED_2026);
    let (mut max_dw, mut max_dz) = (0.0f64, 0.0f64);
    let (mut max_err_enum, mut max_err_lemke) = (0.0f64, 0.0f64);
    let mut unique = 0;
    let mut separating = 0;
    let mut failures = Vec::new();
    for k in 0..ISLANDS {
        let n = 1 + k % MAX_N;
        let scene = random_island(&mut rng, n, MASS_RATIO);
        let (islands, _, lcps) = build(&scene, "island").expect("a valid scene");
        assert_eq!(islands.len(), 1, "random_island makes one island");
        let lcp = &lcps[0];
        assert_eq!(lcp.n(), n);
        let e = run(lcp, Method::Enumeration);
        let l = run(lcp, Method::Lemke);
        let pd = is_positive_definite(lcp, PD_TOL);
        let dw = w_rel_diff(lcp, &e.z, &e.w, &l.z, &l.w);
        let dz = z_rel_diff(&e.z, &l.z);
        if e.z.iter().all(|&v| v == 0.0) {
            separating += 1;
        }
        let ok = e.status == Status::Solved
            && l.status == Status::Solved
            && e.residuals.error <= ERROR_TOL
            && l.residuals.error <= ERROR_TOL
            && dw <= TOL
            && (!pd || dz <= TOL);
        if !ok {
            failures.push(format!(
                "island {k} (n = {n}, pd = {pd}): enum {} err {:.2e} z {:?} basis {:?}; lemke {} err {:.2e} z {:?} basis {:?}; dw {dw:.2e} dz {dz:.2e}\n  M = {:?}\n  q = {:?}",
                e.status, e.residuals.error, e.z, e.basis, l.status, l.residuals.error, l.z, l.basis, lcp.m, lcp.q
            ));
            continue;
        }
        max_dw = max_dw.max(dw);
        max_err_enum = max_err_enum.max(e.residuals.error);
        max_err_lemke = max_err_lemke.max(l.residuals.error);
        if pd {
            unique += 1;
            max_dz = max_dz.max(dz);
        }
    }
    eprintln!(
        "{ISLANDS} islands (n = 1..{MAX_N}, mass ratio {MASS_RATIO}): {unique} positive definite, \
         {separating} with z = 0; max dw {max_dw:.2e}, max dz (unique) {max_dz:.2e}, \
         max error enum {max_err_enum:.2e}, lemke {max_err_lemke:.2e}; {} failures",
        failures.len()
    );
    for f in failures.iter().take(5) {
        eprintln!("{f}");
    }
    assert!(failures.is_empty(), "{} islands failed", failures.len());
    // The check must not be vacuous: most islands have a unique solution,
    // and most need an impulse.
    assert!(unique > ISLANDS / 2, "{unique}");
    assert!(separating < ISLANDS / 2, "{separating}");
}

/// The demo worlds' islands: balls, boxes landing flat on 4 coplanar
/// contacts and stacks of 2–3 boxes (8–12 contacts, M of rank 3 per box):
/// z is not unique there, w and the bodies' velocities are (M = J M⁻¹ Jᵀ with
/// every body's inverse mass matrix definite: J M⁻¹ Jᵀ (z₁ − z₂) = 0 gives
/// Jᵀ(z₁ − z₂) = 0). Enumeration and Lemke must agree on both.
#[test]
fn enumeration_and_lemke_agree_on_demo_world_islands() {
    use crate::tests::reference::solve_scene;
    let mut rng = Rng::new(0xDE30);
    let (mut islands, mut singular, mut max_dw, mut max_dv) = (0, 0, 0.0f64, 0.0f64);
    for k in 0..300 {
        let scene = crate::generate::demo_world(&mut rng);
        let e = solve_scene(&scene, &settings(Method::Enumeration)).unwrap();
        let l = solve_scene(&scene, &settings(Method::Lemke)).unwrap();
        let lcps = build(&scene, "demo").unwrap().2;
        assert_eq!(e.islands.len(), lcps.len());
        for ((ie, il), lcp) in e.islands.iter().zip(&l.islands).zip(&lcps) {
            islands += 1;
            if !is_positive_definite(lcp, PD_TOL) {
                singular += 1;
            }
            for (what, s) in [("enum", &ie.solution), ("lemke", &il.solution)] {
                assert!(
                    s.status.is_solution() && s.residuals.error <= ERROR_TOL,
                    "world {k} island {:?} {what}: {} {:?}\n  M = {:?}\n  q = {:?}",
                    ie.contacts,
                    s.status,
                    s.residuals,
                    lcp.m,
                    lcp.q
                );
            }
            let dw = w_rel_diff(
                lcp,
                &ie.solution.z,
                &ie.solution.w,
                &il.solution.z,
                &il.solution.w,
            );
            max_dw = max_dw.max(dw);
            assert!(dw <= TOL, "world {k} island {:?}: dw {dw:.2e}", ie.contacts);
        }
        let flat = |v: &[crate::cpu::impulses::BodyVelocity]| -> Vec<f64> {
            v.iter()
                .flat_map(|b| b.velocity.into_iter().chain(b.angular_velocity))
                .collect()
        };
        let (ve, vl) = (flat(&e.scenes[0].bodies), flat(&l.scenes[0].bodies));
        let scale = common::inf_norm(&ve).max(common::inf_norm(&vl)).max(1e-300);
        let dv = common::max_diff(&ve, &vl) / scale;
        max_dv = max_dv.max(dv);
        assert!(dv <= TOL, "world {k}: velocities differ by {dv:.2e}");
    }
    eprintln!("{islands} demo islands ({singular} with singular M): max dw {max_dw:.2e}, max dv {max_dv:.2e}");
    assert!(singular > 50, "{singular}");
}

/// A random LCP of size n: entries in −3..=3 (integers, degenerate) or
/// uniform in [−1, 1); with `psd` the matrix is AᵀA + S (S skew-symmetric),
/// positive semidefinite and so copositive-plus.
fn random_lcp(rng: &mut Rng, n: usize, integer: bool, psd: bool) -> Lcp {
    let draw = |rng: &mut Rng| {
        if integer {
            rng.int(0, 6) as f64 - 3.0
        } else {
            rng.range(-1.0, 1.0)
        }
    };
    let a: Vec<f64> = (0..n * n).map(|_| draw(rng)).collect();
    let q: Vec<f64> = (0..n).map(|_| draw(rng)).collect();
    let m = if psd {
        let s: Vec<f64> = (0..n * n).map(|_| draw(rng)).collect();
        (0..n * n)
            .map(|k| {
                let (i, j) = (k / n, k % n);
                (0..n).map(|r| a[r * n + i] * a[r * n + j]).sum::<f64>() + s[i * n + j]
                    - s[j * n + i]
            })
            .collect()
    } else {
        a
    };
    Lcp::new(m, q).unwrap()
}

/// Lemke against enumeration of every basis on small general LCPs: when
/// Lemke says solved, its z solves the LCP and is one of enumeration's
/// solutions (when they are isolated); when enumeration finds no solution,
/// Lemke does not claim one; for copositive-plus M (PSD here) a secondary
/// ray proves that there is none. Lemke's pivot cap (NotConverged) is
/// counted here and asserted absent in `lemke_terminates_on_degenerate_lcps`.
#[test]
fn lemke_agrees_with_enumeration_on_small_random_lcps() {
    use crate::cpu::enumeration::distinct_solutions;
    use crate::SolutionSet;
    let mut rng = Rng::new(0x1E3E);
    let (mut solved, mut rays, mut capped) = (0, 0, 0);
    for k in 0..20_000 {
        let n = 1 + k % 7;
        let (integer, psd) = (k % 2 == 0, k % 3 == 0);
        let lcp = random_lcp(&mut rng, n, integer, psd);
        let e = crate::tests::reference::solve(&lcp, &common::all_solutions_settings()).unwrap();
        let l = run(&lcp, Method::Lemke);
        let set = e.solution_set.clone().unwrap();
        let what = format!("LCP {k}: M = {:?}, q = {:?}, enum {set:?}", lcp.m, lcp.q);
        if e.status.is_solution() {
            assert!(
                e.residuals.error <= ERROR_TOL * 100.0,
                "{what}: enum error {:e}",
                e.residuals.error
            );
        }
        match l.status {
            Status::Solved => {
                solved += 1;
                assert!(
                    l.residuals.error <= 1e-9,
                    "{what}: lemke error {:e}",
                    l.residuals.error
                );
                assert_ne!(
                    set,
                    SolutionSet::Empty,
                    "{what}: lemke solved it: {:?}",
                    l.z
                );
                if let SolutionSet::Isolated { .. } = set {
                    let found = distinct_solutions(&e.all_bases)
                        .iter()
                        .any(|b| z_rel_diff(&b.z, &l.z) <= 1e-8);
                    assert!(
                        found,
                        "{what}: lemke's z {:?} is not among enumeration's",
                        l.z
                    );
                }
            }
            Status::RayTermination => {
                rays += 1;
                if psd {
                    assert_eq!(
                        set,
                        SolutionSet::Empty,
                        "{what}: a ray on copositive-plus M"
                    );
                }
            }
            Status::NotConverged => capped += 1,
            other => panic!("{what}: lemke {other}"),
        }
    }
    eprintln!("20000 small LCPs: lemke solved {solved}, ray {rays}, pivot cap {capped}");
    assert!(solved > 5000 && rays > 1000);
}

/// Lemke terminates (solution or ray) on every LCP. In floating point its
/// lexicographic rule can still cycle where rounding decides a tie; before
/// the fix it ran into its pivot cap on some degenerate integer problems,
/// e.g. the n = 4 one below (enumeration: two isolated solutions; M is not
/// copositive, so a ray is a legitimate end). Lemke now detects the repeated
/// basis and restarts on a perturbed q.
#[test]
fn lemke_terminates_on_degenerate_lcps() {
    let lcp = Lcp::new(
        vec![
            0.0, 2.0, 2.0, 0.0, 2.0, -1.0, -1.0, 3.0, 0.0, 0.0, -3.0, -3.0, 3.0, 3.0, 2.0, -1.0,
        ],
        vec![-1.0, -1.0, 1.0, -1.0],
    )
    .unwrap();
    let l = run(&lcp, Method::Lemke);
    assert!(
        matches!(l.status, Status::Solved | Status::RayTermination),
        "{:?} {:?}",
        l.status,
        l.counters
    );
    assert!(l.counters.pivots < 100, "{:?}", l.counters);
    if l.status == Status::Solved {
        assert!(l.residuals.error <= 1e-9, "{:e}", l.residuals.error);
    }
    let mut rng = Rng::new(0x1E3E);
    let mut capped = Vec::new();
    for k in 0..20_000 {
        let n = 1 + k % 7;
        let lcp = random_lcp(&mut rng, n, k % 2 == 0, k % 3 == 0);
        if run(&lcp, Method::Lemke).status == Status::NotConverged {
            capped.push(k);
        }
    }
    assert!(capped.is_empty(), "pivot cap on LCPs {capped:?}");
}

/// Enumeration's tolerances are all relative (module docs), so scaling M
/// and q, together or apart, changes no verdict: the chosen basis is the same
/// and z scales by s_q / s_M.
#[test]
fn enumeration_verdicts_do_not_depend_on_scale() {
    let mut rng = Rng::new(0x5CA1E);
    let mut lcps = Vec::new();
    for k in 0..2000 {
        let scene = random_island(&mut rng, 1 + k % 10, MASS_RATIO);
        lcps.extend(build(&scene, "island").unwrap().2);
    }
    for _ in 0..100 {
        let scene = crate::generate::demo_world(&mut rng);
        lcps.extend(build(&scene, "demo").unwrap().2);
    }
    for (sm, sq) in [
        (1e-9, 1e-9),
        (3e7, 3e7),
        (1.0, 1e-10),
        (1.0, 7e9),
        (1e-8, 1.0),
        (0.1, 0.1),
    ] {
        for (k, lcp) in lcps.iter().enumerate() {
            let scaled = Lcp::new(
                lcp.m.iter().map(|v| v * sm).collect(),
                lcp.q.iter().map(|v| v * sq).collect(),
            )
            .unwrap();
            let a = run(lcp, Method::Enumeration);
            let b = run(&scaled, Method::Enumeration);
            assert_eq!(a.status, b.status, "problem {k}, M × {sm:e}, q × {sq:e}");
            assert_eq!(a.basis, b.basis, "problem {k}, M × {sm:e}, q × {sq:e}");
            let back: Vec<f64> = b.z.iter().map(|z| z * sm / sq).collect();
            assert!(
                z_rel_diff(&a.z, &back) <= 1e-12,
                "problem {k}, M × {sm:e}, q × {sq:e}"
            );
        }
    }
}

// ---- The readers never panic: Ok or a clear Err. ----

const DAT: &str = "3\n0\n3\n3\n3 3\n2 1 0\n1 2 1\n0 1 2\n-1 -2 -3\ncomment\n";
const DAT_BLOCK: &str = "2\n1\n2\n2\n1\n1\n1\n2\n2\n2\n1\n0 1\n0\n0\n2 1 3 4\n-5 -6";
const JSON_BATCH: &str = r#"{"problems":[{"M":[[2,1],[1,2]],"q":[-5,-6]},{"M":[[1]],"q":[-1]}]}"#;
const JSON_SCENE: &str = r#"{"bodies":[{"inv_mass":1,"inv_inertia":[[1,0,0],[0,1,0],[0,0,1]],"position":[0,1,0],"velocity":[0,-1,0],"angular_velocity":[0,0,0]}],"contacts":[{"a":0,"b":null,"point":[0,0,0],"normal":[0,1,0],"restitution":0.5}]}"#;

/// A mutation of a valid text: replace, insert or delete a byte or a token.
fn mutate(base: &str, ops: &[(u8, usize, u8)]) -> String {
    let mut b = base.as_bytes().to_vec();
    for &(op, at, byte) in ops {
        if b.is_empty() {
            b.push(byte);
            continue;
        }
        let i = at % b.len();
        match op % 4 {
            0 => b[i] = byte,
            1 => b.insert(i, byte),
            2 => {
                b.remove(i);
            }
            _ => {
                // Replace the token at i with a tricky one.
                const TOKENS: [&str; 10] = [
                    "nan",
                    "inf",
                    "-1",
                    "1e308",
                    "1e400",
                    "0",
                    "99999999999",
                    "",
                    "-0",
                    "null",
                ];
                let t = TOKENS[byte as usize % TOKENS.len()];
                let start = b[..i]
                    .iter()
                    .rposition(|c| c.is_ascii_whitespace() || b",[]{}:".contains(c))
                    .map_or(0, |p| p + 1);
                let end = b[i..]
                    .iter()
                    .position(|c| c.is_ascii_whitespace() || b",[]{}:".contains(c))
                    .map_or(b.len(), |p| i + p);
                b.splice(start..end, t.bytes());
            }
        }
    }
    String::from_utf8_lossy(&b).into_owned()
}

/// A reader's answer is fine when it is Ok (with a finite problem) or an
/// Err whose message names the file.
fn check_dat(text: &str) {
    match parse_dat("fuzz.dat", text) {
        Ok(lcp) => {
            assert!(lcp.validate("fuzz").is_ok());
        }
        Err(e) => {
            let msg = e.to_string();
            assert!(msg.contains("fuzz.dat") || msg.contains("problem"), "{msg}");
        }
    }
}

fn check_json(text: &str) {
    match parse_json("fuzz.json", text) {
        Ok(_) => {}
        Err(e) => {
            let msg = e.to_string();
            assert!(!msg.is_empty());
            assert!(
                msg.contains("fuzz.json") || msg.contains("scene") || msg.contains("problem"),
                "{msg}"
            );
            // Shape errors name item and field, or at least a real position.
            assert!(!msg.contains("line 0, column 0"), "{msg}");
        }
    }
}

/// Cases per reader property: 2000 in every test run; `LCPBATCH_FUZZ_CASES`
/// raises it for a long fuzzing run (recorded in BENCHMARKS.md).
fn fuzz_cases() -> u32 {
    std::env::var("LCPBATCH_FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(2000)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: fuzz_cases(), failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn dat_reader_never_panics_on_random_bytes(bytes in proptest::collection::vec(any::<u8>(), 0..200)) {
        check_dat(&String::from_utf8_lossy(&bytes));
    }

    #[test]
    fn dat_reader_never_panics_on_random_tokens(tokens in proptest::collection::vec(
        prop_oneof![(0usize..12).prop_map(|v| v.to_string()), any::<f64>().prop_map(|v| v.to_string()),
                    Just("nan".to_string()), Just("-3".to_string())], 0..40)) {
        check_dat(&tokens.join(" "));
    }

    #[test]
    fn dat_reader_never_panics_on_mutated_files(
        which in any::<bool>(),
        ops in proptest::collection::vec((any::<u8>(), any::<usize>(), any::<u8>()), 1..6),
    ) {
        check_dat(&mutate(if which { DAT } else { DAT_BLOCK }, &ops));
    }

    #[test]
    fn json_reader_never_panics_on_random_bytes(bytes in proptest::collection::vec(any::<u8>(), 0..200)) {
        check_json(&String::from_utf8_lossy(&bytes));
    }

    #[test]
    fn json_reader_never_panics_on_mutated_files(
        which in any::<bool>(),
        ops in proptest::collection::vec((any::<u8>(), any::<usize>(), any::<u8>()), 1..6),
    ) {
        check_json(&mutate(if which { JSON_BATCH } else { JSON_SCENE }, &ops));
    }
}

#[test]
fn mutated_conformance_files_never_panic_the_dat_reader() {
    // Every Siconos file, dense and sparse-block, mutated 300 times each with
    // a fixed seed: Ok (then a finite LCP) or a clear Err, never a panic.
    let Some(dir) = common::siconos_dir() else {
        return;
    };
    let mut rng = Rng::new(0xDA7);
    let mut files = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "dat") {
            continue;
        }
        files += 1;
        let text = std::fs::read_to_string(&path).unwrap();
        check_dat(&text);
        assert!(parse_dat("fuzz.dat", &text).is_ok(), "{}", path.display());
        for _ in 0..300 {
            let ops: Vec<(u8, usize, u8)> = (0..rng.int(1, 4))
                .map(|_| {
                    (
                        rng.next_u64() as u8,
                        rng.next_u64() as usize,
                        rng.next_u64() as u8,
                    )
                })
                .collect();
            check_dat(&mutate(&text, &ops));
        }
    }
    assert_eq!(files, 20);
}

#[test]
fn unmutated_fuzz_bases_are_valid() {
    // The mutation bases themselves parse, so mutations start from valid files.
    assert!(parse_dat("t.dat", DAT).is_ok());
    assert!(parse_dat("t.dat", DAT_BLOCK).is_ok());
    assert!(parse_json("t.json", JSON_BATCH).is_ok());
    assert!(parse_json("t.json", JSON_SCENE).is_ok());
}
