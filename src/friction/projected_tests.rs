//! Tests of the cone projection iterations' CPU twin.

use super::*;
use crate::friction::random::random_problems;

fn one_contact(w_diag: [f64; 3], q: [f64; 3], mu: f64) -> FrictionProblem {
    let mut w = vec![0.0; 9];
    for i in 0..3 {
        w[i * 3 + i] = w_diag[i];
    }
    FrictionProblem::new(w, q.to_vec(), vec![mu]).unwrap()
}

fn with(method: ProjectedMethod) -> ProjectedSettings {
    ProjectedSettings {
        method,
        ..Default::default()
    }
}

/// ‖a − b‖∞ / max(‖a‖∞, ‖b‖∞, 1e-300).
fn rel_diff(a: &[f64], b: &[f64]) -> f64 {
    let big = a.iter().chain(b).fold(1e-300f64, |m, x| m.max(x.abs()));
    a.iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
        / big
}

/// max|u_a − u_b| / (‖q‖∞ + ‖W‖∞ max(‖r_a‖∞, ‖r_b‖∞)): velocities
/// compared with the size of the terms whose sum they are.
pub(crate) fn velocity_diff(
    p: &FrictionProblem,
    a: &ProjectedSolution,
    b: &ProjectedSolution,
) -> f64 {
    let inf = |v: &[f64]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let n = p.dim();
    let w_inf = (0..n)
        .map(|r| p.w[r * n..(r + 1) * n].iter().map(|x| x.abs()).sum::<f64>())
        .fold(0.0, f64::max);
    let scale = inf(&p.q) + w_inf * inf(&a.r).max(inf(&b.r));
    let d =
        a.u.iter()
            .zip(&b.u)
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    d / scale.max(1e-300)
}

/// Every contact's reaction in its cone, up to rounding.
pub(crate) fn in_cones(p: &FrictionProblem, r: &[f64]) -> bool {
    p.mu.iter().enumerate().all(|(i, &mu)| {
        let (n, t) = (r[3 * i], r[3 * i + 1].hypot(r[3 * i + 2]));
        n >= 0.0 && t <= mu * n * (1.0 + 1e-14) + 1e-300
    })
}

#[test]
fn one_unit_contact_is_the_projection_of_minus_q() {
    // W = I: ½ rᵀr + qᵀr = ½‖r + q‖² − ½‖q‖², so the CCP's answer is the
    // point of K nearest −q: r = P_K(−q). By hand for q = (−1, 3, 0),
    // μ = 0.5: −q = (1, −3, 0), t = 3; neither μt ≤ −x_n (1.5 ≤ −1) nor
    // t ≤ μ x_n (3 ≤ 0.5), so p_n = (μt + x_n)/(μ² + 1) = 2.5/1.25 = 2 and
    // r_t = μ p_n (−3, 0)/3 = (−1, 0): r = (2, −1, 0), u = r + q = (1, 2, 0).
    // The sliding contact separates at u_n = μ‖u_t‖ = 1: the convex model,
    // not Coulomb's answer r = (1, −0.5, 0) (residual.rs).
    let p = one_contact([1.0; 3], [-1.0, 3.0, 0.0], 0.5);
    for m in ProjectedMethod::ALL {
        let s = solve_projected(&p, None, &with(m)).unwrap();
        assert_eq!(s.status, Status::Solved, "{m:?}: {s:?}");
        assert!(rel_diff(&s.r, &[2.0, -1.0, 0.0]) < 1e-7, "{m:?}: {:?}", s.r);
        assert!(s.residuals.cone_error <= 1e-8);
        // Reported beside it: the distance from Coulomb (u_n = 1 ≠ 0 while r_n > 0).
        assert!(s.residuals.coulomb_error > 0.1, "{m:?}: {:?}", s.residuals);
    }
    // More unit contacts, by the same formula.
    for (q, mu) in [
        ([-1.0, 0.1, -0.2], 0.8), // sticks: −q inside the cone
        ([0.5, 1.0, 1.0], 0.3),   // separates: −q in the polar cone
        ([-2.0, 1.0, -3.0], 0.2), // slides
        ([-1.0, 1.0, 0.0], 0.0),  // frictionless
    ] {
        let p = one_contact([1.0; 3], q, mu);
        let want = project_on_cone([-q[0], -q[1], -q[2]], mu);
        for m in ProjectedMethod::ALL {
            let s = solve_projected(&p, None, &with(m)).unwrap();
            assert_eq!(s.status, Status::Solved, "{m:?} {q:?}");
            let scale = want.iter().fold(1.0f64, |a, x| a.max(x.abs()));
            assert!(
                rel_diff(&s.r, &want) * scale < 1e-7,
                "{m:?} {q:?}: {:?} vs {want:?}",
                s.r
            );
        }
    }
}

#[test]
fn a_sphere_contact_with_large_tangential_entries_converges() {
    // A ball: tangential entries 3.5 times the normal one. A step of
    // 1 / W_nn would diverge in the tangents; the block's bound does not.
    let p = one_contact([1.0, 3.5, 3.5], [-1.0, 2.0, -1.0], 0.4);
    for m in ProjectedMethod::ALL {
        let s = solve_projected(&p, None, &with(m)).unwrap();
        assert_eq!(s.status, Status::Solved, "{m:?}: {s:?}");
        assert!(s.iterations < 200, "{m:?}: {}", s.iterations);
    }
}

#[test]
fn every_method_solves_random_islands_to_the_same_velocities() {
    for k in [1usize, 2, 3, 4, 6, 8, 12, 16] {
        let problems = random_problems(0xF00 + k as u64, 12, k);
        let settings = |m| ProjectedSettings {
            method: m,
            tolerance: Some(1e-10),
            max_iterations: 200_000,
            ..Default::default()
        };
        let apgd =
            solve_projected_batch(&problems, None, &settings(ProjectedMethod::Apgd), 2).unwrap();
        for m in [ProjectedMethod::Jacobi, ProjectedMethod::GaussSeidel] {
            let other = solve_projected_batch(&problems, None, &settings(m), 2).unwrap();
            for (i, (a, b)) in apgd.iter().zip(&other).enumerate() {
                assert_eq!(
                    a.status,
                    Status::Solved,
                    "apgd k={k} #{i}: {:?}",
                    a.residuals
                );
                assert_eq!(
                    b.status,
                    Status::Solved,
                    "{m:?} k={k} #{i}: {:?}",
                    b.residuals
                );
                // u = W r + q is unique for the convex problem (r need not be).
                let d = velocity_diff(&problems[i], a, b);
                assert!(d < 1e-8, "{m:?} k={k} #{i}: u differs by {d:e}");
            }
        }
        for (p, s) in problems.iter().zip(&apgd) {
            assert!(in_cones(p, &s.r), "k={k}: {:?}", s.r);
            assert_eq!(s.residuals, FrictionResiduals::of(p, &s.r));
        }
    }
}

#[test]
fn a_warm_start_from_the_solution_returns_at_once() {
    let problems = random_problems(7, 20, 5);
    for m in ProjectedMethod::ALL {
        let settings = ProjectedSettings {
            max_iterations: 1_000_000,
            ..with(m)
        };
        let cold = solve_projected_batch(&problems, None, &settings, 1).unwrap();
        let starts: Vec<Vec<f64>> = cold.iter().map(|s| s.r.clone()).collect();
        let warm = solve_projected_batch(&problems, Some(&starts), &settings, 1).unwrap();
        for (c, w) in cold.iter().zip(&warm) {
            assert_eq!(c.status, Status::Solved, "{m:?}");
            assert_eq!(w.status, Status::Solved, "{m:?}");
            assert!(w.iterations <= 1, "{m:?}: {} iterations", w.iterations);
            // The start is projected on the cones first: a reaction on a
            // cone's boundary may move by a rounding.
            assert!(rel_diff(&c.r, &w.r) < 1e-15, "{m:?}");
        }
        assert!(
            cold.iter().any(|c| c.iterations > 1),
            "{m:?}: the cold runs iterate"
        );
    }
}

/// The frictionless LCPs of `problems` (W's normal block, q's normal
/// entries) solved by Lemke through the Solver door.
pub(crate) fn lemke_on_the_normal_blocks(problems: &[FrictionProblem]) -> crate::Report {
    use crate::{Backend, Lcp, Method, Settings, Solver};
    let lcps: Vec<Lcp> = problems
        .iter()
        .map(|p| {
            let k = p.contacts();
            let m = (0..k * k).map(|e| p.at(3 * (e / k), 3 * (e % k))).collect();
            let q = (0..k).map(|i| p.q[3 * i]).collect();
            Lcp::new(m, q).unwrap()
        })
        .collect();
    let mut solver = Solver::new(Settings::new(Backend::Cpu, Method::Lemke)).unwrap();
    solver.solve_lcps(&lcps).unwrap()
}

#[test]
fn frictionless_islands_give_the_lcp_solvers_answer_on_the_normal_block() {
    let mut problems = random_problems(11, 30, 4);
    for p in &mut problems {
        p.mu.iter_mut().for_each(|m| *m = 0.0);
    }
    let report = lemke_on_the_normal_blocks(&problems);
    let settings = ProjectedSettings {
        tolerance: Some(1e-12),
        max_iterations: 100_000,
        ..Default::default()
    };
    for m in ProjectedMethod::ALL {
        let out = solve_projected_batch(
            &problems,
            None,
            &ProjectedSettings {
                method: m,
                ..settings
            },
            1,
        )
        .unwrap();
        for (i, (s, lcp)) in out.iter().zip(&report.islands).enumerate() {
            assert_eq!(s.status, Status::Solved, "{m:?} #{i}");
            assert!(lcp.status().is_solution(), "#{i}");
            let k = s.r.len() / 3;
            let rn: Vec<f64> = (0..k).map(|c| s.r[3 * c]).collect();
            let wn = |u: &[f64]| (0..k).map(|c| u[3 * c]).collect::<Vec<f64>>();
            let lcp_as = ProjectedSolution {
                r: (0..3 * k)
                    .map(|e| {
                        if e % 3 == 0 {
                            lcp.solution.z[e / 3]
                        } else {
                            0.0
                        }
                    })
                    .collect(),
                u: s.u
                    .iter()
                    .enumerate()
                    .map(|(e, &v)| if e % 3 == 0 { lcp.solution.w[e / 3] } else { v })
                    .collect(),
                ..s.clone()
            };
            assert!((0..k).all(|c| s.r[3 * c + 1] == 0.0 && s.r[3 * c + 2] == 0.0));
            // w is unique; z where the normal block is definite (checked by w).
            let dw = velocity_diff(&problems[i], s, &lcp_as);
            let dz = rel_diff(&rn, &lcp.solution.z);
            assert!(
                dw < 1e-10,
                "{m:?} #{i}: w differs by {dw:e}: {:?} vs {:?}",
                wn(&s.u),
                lcp.solution.w
            );
            assert!(
                dz < 1e-5,
                "{m:?} #{i}: z differs by {dz:e}: {rn:?} vs {:?}",
                lcp.solution.z
            );
        }
    }
}

#[test]
fn the_iteration_cap_and_bad_settings_are_reported() {
    let p = &random_problems(3, 1, 6)[0];
    for m in ProjectedMethod::ALL {
        let s = solve_projected(
            p,
            None,
            &ProjectedSettings {
                max_iterations: 2,
                ..with(m)
            },
        )
        .unwrap();
        assert_eq!(s.status, Status::NotConverged, "{m:?}");
        assert_eq!(s.iterations, 2);
        assert!(s.residuals.cone_error > 1e-8 && in_cones(p, &s.r));
        let s = solve_projected(
            p,
            None,
            &ProjectedSettings {
                max_iterations: 0,
                ..with(m)
            },
        )
        .unwrap();
        assert_eq!((s.status, s.iterations), (Status::NotConverged, 0), "{m:?}");
    }
    for (bad, field) in [
        (
            ProjectedSettings {
                tolerance: Some(0.0),
                ..Default::default()
            },
            "tolerance",
        ),
        (
            ProjectedSettings {
                tolerance: Some(f64::NAN),
                ..Default::default()
            },
            "tolerance",
        ),
        (
            ProjectedSettings {
                relaxation: 2.0,
                ..Default::default()
            },
            "relaxation",
        ),
        (
            ProjectedSettings {
                relaxation: 0.0,
                ..Default::default()
            },
            "relaxation",
        ),
    ] {
        let e = solve_projected(p, None, &bad).unwrap_err();
        assert!(e.to_string().contains(field), "{e}");
    }
    let e = solve_projected(p, Some(&[0.0; 2]), &Default::default()).unwrap_err();
    assert!(e.to_string().contains("r0"), "{e}");
    let e = ProjectedMethod::parse("newton").unwrap_err();
    assert!(e.to_string().contains("method"), "{e}");
    for m in ProjectedMethod::ALL {
        assert_eq!(ProjectedMethod::parse(m.name()).unwrap(), m);
    }
    // In a batch, a problem that fails its checks is InvalidInput; a bad warm start an error.
    let mut bad = p.clone();
    bad.mu[0] = -1.0;
    let out = solve_projected_batch(&[p.clone(), bad], None, &Default::default(), 1).unwrap();
    assert_eq!(out[0].status, Status::Solved);
    assert_eq!(out[1].status, Status::InvalidInput);
    let warm = vec![vec![f64::NAN; p.dim()]];
    let e = solve_projected_batch(std::slice::from_ref(p), Some(&warm), &Default::default(), 1)
        .unwrap_err();
    assert!(
        e.to_string().contains("problem 0") && e.to_string().contains("r0[0]"),
        "{e}"
    );
}

#[test]
fn a_start_outside_the_cones_is_projected_first() {
    let p = one_contact([1.0; 3], [-1.0, 0.0, 0.0], 0.5);
    // r0 = (−1, 5, 5) is outside; its projection is 0 (the polar cone side).
    let s = solve_projected(&p, Some(&[-1.0, 5.0, 5.0]), &Default::default()).unwrap();
    assert_eq!(s.status, Status::Solved);
    assert!(rel_diff(&s.r, &[1.0, 0.0, 0.0]) < 1e-8, "{:?}", s.r);
}
