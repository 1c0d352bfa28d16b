//! Small complementarity problems worked by hand, each with its answer,
//! through every solver that can take it.
//!
//! - Two coupled contacts, both active: the 2×2 LCP M = [[2,1],[1,2]],
//!   q = (−5,−6) → z = (4/3, 7/3) (the LCP of Cottle–Pang–Stone, *The
//!   Linear Complementarity Problem*: w = M z + q ≥ 0, z ≥ 0, zᵀw = 0).
//! - A 3×3 walk-through of Lemke's complementary pivoting (Lemke 1965) on a
//!   non-symmetric M with zero diagonal: its equations (w3 = z0 − z1 + z2 − 1)
//!   use q = (−3, 6, −1) → z = (0, 1, 3), w = (2, 0, 0). The same M with
//!   q3 = +1 (the sign slip easily made against those equations) has the
//!   solution z = (1, 0, 1.5).
//! - The textbook exercises of complementarity in contact: a QP through its
//!   KKT conditions, the 1-D interval QP, a coupled 2×2 NCP by active set,
//!   Coulomb's friction disc by maximum dissipation (the tangential impulse
//!   is −v_T projected on the disc of radius μ γ_n) and one velocity-level
//!   time step (Stewart–Trinkle, Anitescu–Potra).

use super::common::{all_solutions_settings, run, METHODS};
use crate::cpu::enumeration::{solve_basis, BasisOutcome, EnumerationSettings};
use crate::settings::Method;
use crate::tests::reference::solve;
use crate::{Lcp, LcpSolution, SolutionSet, Status};

/// Asserts that `sol` is a solution with the expected z (and w when given) to
/// `tol` absolute (the examples are of order 1).
fn assert_solution(what: &str, sol: &LcpSolution, z: &[f64], w: Option<&[f64]>, tol: f64) {
    assert!(
        sol.status.is_solution(),
        "{what}: status {} (z = {:?})",
        sol.status,
        sol.z
    );
    for (i, (a, b)) in sol.z.iter().zip(z).enumerate() {
        assert!(
            (a - b).abs() <= tol,
            "{what}: z[{i}] = {a}, expected {b} (z = {:?})",
            sol.z
        );
    }
    if let Some(w) = w {
        for (i, (a, b)) in sol.w.iter().zip(w).enumerate() {
            assert!(
                (a - b).abs() <= tol,
                "{what}: w[{i}] = {a}, expected {b} (w = {:?})",
                sol.w
            );
        }
    }
}

/// Tolerance per solver: the exact solvers to rounding, PGS to its stopping
/// tolerance (error measure 1e-10, so z to about 1e-9 on these well-scaled
/// examples).
fn tol(method: Method) -> f64 {
    match method {
        Method::Auto | Method::Enumeration | Method::Lemke => 1e-12,
        Method::Pgs => 1e-8,
    }
}

/// Enumeration of every basis must report exactly one solution.
fn assert_unique(what: &str, lcp: &Lcp) {
    let sol = solve(lcp, &all_solutions_settings()).unwrap();
    assert_eq!(
        sol.solution_set,
        Some(SolutionSet::Isolated { count: 1 }),
        "{what}: all bases: {:?}",
        sol.all_bases
    );
    assert_eq!(sol.status, Status::Solved, "{what}");
}

#[test]
fn seed_000_two_by_two() {
    let lcp = Lcp::new(vec![2.0, 1.0, 1.0, 2.0], vec![-5.0, -6.0]).unwrap();
    for s in METHODS {
        let sol = run(&lcp, s);
        assert_eq!(sol.status, Status::Solved, "{}", s.name());
        assert_solution(
            s.name(),
            &sol,
            &[4.0 / 3.0, 7.0 / 3.0],
            Some(&[0.0, 0.0]),
            tol(s),
        );
    }
    assert_unique("two coupled contacts", &lcp);
    // By hand: of the four complementary bases only (z1, z2) is feasible.
    let settings = EnumerationSettings::default();
    for mask in 0..4u32 {
        let feasible = matches!(
            solve_basis(&lcp, mask, &settings),
            BasisOutcome::Solved { feasible: true, .. }
        );
        assert_eq!(feasible, mask == 0b11, "basis {mask:02b}");
    }
}

/// The Lemke walk-through's matrix, row-major.
const LEMKE_M: [f64; 9] = [0.0, -1.0, 2.0, 2.0, 0.0, -2.0, -1.0, 1.0, 0.0];

#[test]
fn seed_002_lemke_walkthrough_as_its_equations_read() {
    let lcp = Lcp::new(LEMKE_M.to_vec(), vec![-3.0, 6.0, -1.0]).unwrap();
    for s in [Method::Enumeration, Method::Lemke] {
        let sol = run(&lcp, s);
        assert_eq!(sol.status, Status::Solved, "{}", s.name());
        assert_solution(
            s.name(),
            &sol,
            &[0.0, 1.0, 3.0],
            Some(&[2.0, 0.0, 0.0]),
            1e-12,
        );
        assert_eq!(sol.basis, Some(0b110), "{}: basis (z2, z3)", s.name());
    }
    // Lemke's walk by hand takes 5 pivots: z0 in, z1 in, z3 in, w1 in, z2 in.
    assert_eq!(run(&lcp, Method::Lemke).counters.pivots, 5);
    assert_unique("Lemke walk-through", &lcp);
    // M_11 = 0: PGS cannot divide by it and says so.
    assert_eq!(run(&lcp, Method::Pgs).status, Status::InvalidInput);
}

#[test]
fn seed_002_with_the_printed_q() {
    let lcp = Lcp::new(LEMKE_M.to_vec(), vec![-3.0, 6.0, 1.0]).unwrap();
    for s in [Method::Enumeration, Method::Lemke] {
        let sol = run(&lcp, s);
        assert_eq!(sol.status, Status::Solved, "{}", s.name());
        // w = M z + q = (−3 + 3, 6 + 2 − 3, 1 − 1) = (0, 5, 0).
        assert_solution(
            s.name(),
            &sol,
            &[1.0, 0.0, 1.5],
            Some(&[0.0, 5.0, 0.0]),
            1e-12,
        );
    }
    assert_unique("Lemke walk-through, q3 = +1", &lcp);
}

#[test]
fn seed_001_qp_exercise() {
    // KKT of min ½xᵀQx + cᵀx s.t. x ≥ 0: 0 ≤ x ⊥ Qx + c ≥ 0, i.e. LCP(M = Q, q = c).
    let q_mat = vec![2.0, 0.0, 0.0, 8.0];
    for (c, x) in [
        // Unconstrained optimum (2, 1) is feasible, so it is the answer.
        ([-4.0, -8.0], [2.0, 1.0]),
        // Linear term (−1, −1): x = (1/2, 1/8).
        ([-1.0, -1.0], [0.5, 0.125]),
    ] {
        let lcp = Lcp::new(q_mat.clone(), c.to_vec()).unwrap();
        for s in METHODS {
            let sol = run(&lcp, s);
            assert_eq!(sol.status, Status::Solved, "{} c = {c:?}", s.name());
            assert_solution(s.name(), &sol, &x, Some(&[0.0, 0.0]), tol(s));
        }
        assert_unique("QP by its KKT conditions", &lcp);
    }
}

/// Projection onto the interval [lo, hi].
fn project_interval(x: f64, lo: f64, hi: f64) -> f64 {
    x.max(lo).min(hi)
}

#[test]
fn seed_001_interval_qp() {
    // min ½(x − 3)² s.t. 0 ≤ x ≤ 2. KKT with the multiplier λ of x ≤ 2 and
    // the bound x ≥ 0 kept as the complementarity sign constraint:
    //   0 ≤ x ⊥ (x − 3) + λ ≥ 0,   0 ≤ λ ⊥ 2 − x ≥ 0,
    // the LCP z = (x, λ), M = [[1, 1], [−1, 0]], q = (−3, 2)
    // (the QP's KKT LCP [[Q, Aᵀ], [−A, 0]], (c, b) for A = [1], b = 2).
    let lcp = Lcp::new(vec![1.0, 1.0, -1.0, 0.0], vec![-3.0, 2.0]).unwrap();
    for s in [Method::Enumeration, Method::Lemke] {
        let sol = run(&lcp, s);
        assert_eq!(sol.status, Status::Solved, "{}", s.name());
        // x = 2, λ = 1 (the force the bound exerts), w = 0.
        assert_solution(s.name(), &sol, &[2.0, 1.0], Some(&[0.0, 0.0]), 1e-12);
        assert_eq!(sol.z[0], project_interval(3.0, 0.0, 2.0));
    }
    assert_unique("interval QP", &lcp);
    // M_22 = 0: not a problem PGS can take.
    assert_eq!(run(&lcp, Method::Pgs).status, Status::InvalidInput);
    // The same answer as a projection: proj_[0,2](3) = 2.
    assert_eq!(project_interval(3.0, 0.0, 2.0), 2.0);
}

#[test]
fn seed_001_coupled_ncp_by_active_set() {
    // A = [[2, −1], [−1, 2]], b = (−1, 2): x = (1/2, 0), f(x) = Ax + b = (0, 3/2).
    let lcp = Lcp::new(vec![2.0, -1.0, -1.0, 2.0], vec![-1.0, 2.0]).unwrap();
    // Enumerate the active set by hand: every choice of which x_i solve
    // f_i = 0; exactly one gives x ≥ 0 and f ≥ 0.
    let settings = EnumerationSettings::default();
    let mut feasible = Vec::new();
    for mask in 0..4u32 {
        match solve_basis(&lcp, mask, &settings) {
            BasisOutcome::Solved {
                z,
                w,
                feasible: true,
                ..
            } => feasible.push((mask, z, w)),
            BasisOutcome::Solved { .. } => {}
            BasisOutcome::Singular => panic!("A is nonsingular, basis {mask:02b} too"),
        }
    }
    assert_eq!(feasible.len(), 1, "{feasible:?}");
    let (mask, z, w) = &feasible[0];
    assert_eq!(*mask, 0b01, "x1 free, x2 = 0");
    assert!((z[0] - 0.5).abs() < 1e-15 && z[1] == 0.0, "{z:?}");
    assert!(w[0].abs() < 1e-15 && (w[1] - 1.5).abs() < 1e-15, "{w:?}");
    for s in METHODS {
        let sol = run(&lcp, s);
        assert_eq!(sol.status, Status::Solved, "{}", s.name());
        assert_solution(s.name(), &sol, &[0.5, 0.0], Some(&[0.0, 1.5]), tol(s));
    }
}

/// Coulomb's friction law with maximum dissipation: for a sliding
/// velocity v_T the tangential impulse is γ_T = −μ γ_n v_T/‖v_T‖, the
/// product's [`crate::friction::project_on_disc`]; through the solver, a
/// unit point mass approaching at γ_n and sliding at v_T (W = I) gets it
/// when ‖v_T‖ ≥ μ γ_n, and sticks (γ_T = −v_T, inside the disc) otherwise.
fn solver_friction_impulse(v_t: [f64; 2], mu: f64, gamma_n: f64) -> [f64; 3] {
    let w = vec![1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    let p = crate::FrictionProblem::new(w, vec![-gamma_n, v_t[0], v_t[1]], vec![mu]).unwrap();
    let mut solver = crate::Solver::new(crate::Settings {
        backend: crate::Backend::Cpu,
        ..crate::Settings::default()
    })
    .unwrap();
    let r = solver.solve_friction(&[p]).unwrap();
    let s = &r.friction[0].solution;
    assert_eq!(s.status, Status::Solved);
    [s.r[0], s.r[1], s.r[2]]
}

#[test]
fn seed_001_friction_disc_projections() {
    for (mu, gamma_n, v_t, expected) in [
        (0.5, 10.0, [3.0, -4.0], [-3.0, 4.0]),
        (0.6, 5.0, [4.0, 3.0], [-12.0 / 5.0, -9.0 / 5.0]),
    ] {
        let g = crate::friction::project_on_disc(v_t, mu, gamma_n);
        let r = solver_friction_impulse(v_t, mu, gamma_n);
        assert!((r[0] - gamma_n).abs() < 1e-12, "{r:?}");
        for i in 0..2 {
            assert!(
                (g[i] - expected[i]).abs() < 1e-14 && (r[i + 1] - expected[i]).abs() < 1e-12,
                "μ = {mu}, γn = {gamma_n}, v_T = {v_t:?}: {g:?} / {r:?}, expected {expected:?}"
            );
        }
        // On the disc's boundary, opposite to v_T.
        assert!((g[0].hypot(g[1]) - mu * gamma_n).abs() < 1e-14);
        assert!(
            (g[0] * v_t[1] - g[1] * v_t[0]).abs() < 1e-14 && g[0] * v_t[0] + g[1] * v_t[1] < 0.0
        );
    }
    // Slow sliding inside the disc sticks: γ_T = −v_T (the sticking case).
    let r = solver_friction_impulse([0.3, -0.4], 0.1, 10.0);
    assert!(
        (r[1] + 0.3).abs() < 1e-12 && (r[2] - 0.4).abs() < 1e-12,
        "{r:?}"
    );
}

#[test]
fn seed_001_one_step_dvi() {
    // m(v⁺ − v) = −m g Δt + γ, 0 ≤ γ ⊥ φ + Δt v⁺ ≥ 0. With v⁺ = v − gΔt + γ/m:
    //   w = φ + Δt v⁺ = (Δt/m) γ + φ + Δt (v − g Δt),
    // the 1×1 LCP M = Δt/m, q = φ + Δt (v − gΔt).
    let (m, g, dt, phi) = (1.0, 10.0, 0.01, 0.0);
    let dvi = |v: f64| Lcp::new(vec![dt / m], vec![phi + dt * (v - g * dt)]).unwrap();
    let v_plus = |v: f64, gamma: f64| v - g * dt + gamma / m;
    // At rest on the ground: γ = m g Δt = 0.1 and v⁺ = 0.
    let lcp = dvi(0.0);
    for s in METHODS {
        let sol = run(&lcp, s);
        assert_eq!(sol.status, Status::Solved, "{}", s.name());
        assert!(
            (sol.z[0] - 0.1).abs() < 1e-14,
            "{}: γ = {}",
            s.name(),
            sol.z[0]
        );
        assert!(v_plus(0.0, sol.z[0]).abs() < 1e-13, "{}", s.name());
        assert!(sol.w[0].abs() < 1e-15, "{}", s.name());
    }
    // Moving away fast enough (v = 1 > gΔt): no impulse, v⁺ = v − gΔt.
    let lcp = dvi(1.0);
    for s in METHODS {
        let sol = run(&lcp, s);
        assert_eq!(sol.status, Status::Solved, "{}", s.name());
        assert_eq!(sol.z[0], 0.0, "{}", s.name());
        assert!((v_plus(1.0, 0.0) - 0.9).abs() < 1e-15);
    }
}
