//! Physics of the impact: what the solved impulses do to the bodies.
//!
//! Scenes come from `crate::generate`; the pipeline solves them and
//! `cpu::impulses` applies the impulses. Conventions (README, "Formats"): n
//! points from b to a, the impulse is +z n on a and −z n on b, and
//! q = v_rel + ε min(v_rel, 0) (Newton's restitution law on the approach).

use super::common;

use super::common::{inf_norm, settings, w_scale, METHODS};
use crate::cpu::assembly::{assemble_contacts, assemble_island};
use crate::cpu::impulses::{apply_impulses, relative_normal_velocities, BodyVelocity};
use crate::generate::{
    ball_body, box_body, box_on_ground, random_island, random_scene, seed_chain, Rng,
};
use crate::islands::{find_islands, Island};
use crate::settings::Method;
use crate::tests::reference::{build, solve, solve_scene};
use crate::{Contact, Scene, Status};
use glam::{DMat3, DVec3};

pub(super) fn contact(a: usize, b: Option<usize>, point: DVec3, normal: DVec3, e: f64) -> Contact {
    Contact {
        a,
        b,
        point: point.to_array(),
        normal: normal.to_array(),
        restitution: e,
        id: None,
        bias: 0.0,
        friction: 0.0,
        tangent: None,
    }
}

pub(super) fn inertia(inv: &[[f64; 3]; 3]) -> DMat3 {
    DMat3::from_cols_array_2d(inv).transpose().inverse()
}

/// Kinetic energy of the dynamic bodies (every generated dynamic body has an
/// invertible inverse inertia).
pub(super) fn kinetic_energy(scene: &Scene, v: &[BodyVelocity]) -> f64 {
    scene
        .bodies
        .iter()
        .zip(v)
        .filter(|(b, _)| !b.is_static())
        .map(|(b, v)| {
            let lin = DVec3::from_array(v.velocity);
            let ang = DVec3::from_array(v.angular_velocity);
            0.5 * lin.length_squared() / b.inv_mass + 0.5 * ang.dot(inertia(&b.inv_inertia) * ang)
        })
        .sum()
}

pub(super) fn initial_velocities(scene: &Scene) -> Vec<BodyVelocity> {
    scene
        .bodies
        .iter()
        .map(|b| BodyVelocity {
            velocity: b.velocity,
            angular_velocity: b.angular_velocity,
        })
        .collect()
}

/// Linear momentum Σ m v and angular momentum about `about`, Σ I ω + m (x − p) × v,
/// of the dynamic bodies, with the sum of the magnitudes of the terms (the
/// scale the rounding is relative to).
pub(super) fn momenta(scene: &Scene, v: &[BodyVelocity], about: DVec3) -> (DVec3, DVec3, f64) {
    let (mut p, mut l, mut scale) = (DVec3::ZERO, DVec3::ZERO, 0.0);
    for (b, v) in scene.bodies.iter().zip(v) {
        if b.is_static() {
            continue;
        }
        let m = 1.0 / b.inv_mass;
        let lin = DVec3::from_array(v.velocity) * m;
        let spin = inertia(&b.inv_inertia) * DVec3::from_array(v.angular_velocity);
        let orbit = (b.position() - about).cross(lin);
        p += lin;
        l += spin + orbit;
        scale += lin.length() + spin.length() + orbit.length();
    }
    (p, l, scale)
}

#[test]
pub(super) fn equal_balls_head_on_with_full_restitution_exchange_velocities() {
    for (va, vb) in [(3.0, -1.0), (2.0, 0.0), (0.5, -4.0)] {
        // Ball 0 on the left moving right at va, ball 1 on the right at vb.
        let mut left = ball_body(2.0, 0.5, DVec3::ZERO);
        let mut right = ball_body(2.0, 0.5, DVec3::X);
        left.velocity = [va, 0.0, 0.0];
        right.velocity = [vb, 0.0, 0.0];
        let scene = Scene {
            bodies: vec![left, right],
            // n from b (left) to a (right).
            contacts: vec![contact(1, Some(0), DVec3::X * 0.5, DVec3::X, 1.0)],
        };
        for s in METHODS {
            let sol = solve_scene(&scene, &settings(s)).unwrap();
            assert_eq!(sol.islands[0].solution.status, Status::Solved);
            let tol = if s == Method::Pgs { 1e-9 } else { 1e-14 };
            let v = &sol.scenes[0].bodies;
            assert!((v[0].velocity[0] - vb).abs() < tol, "{}: {v:?}", s.name());
            assert!((v[1].velocity[0] - va).abs() < tol, "{}: {v:?}", s.name());
            for b in v {
                assert_eq!(b.angular_velocity, [0.0; 3]);
                assert_eq!(&b.velocity[1..], &[0.0, 0.0]);
            }
            // Impulse m (va − vb) (1 + ε) / 2 with m = 2, ε = 1.
            assert!((sol.scenes[0].impulses[0] - 2.0 * (va - vb)).abs() < tol * 10.0);
        }
    }
}

/// Two random boxes touching at 1..4 points, with random restitutions.
pub(super) fn two_body_impact(rng: &mut Rng) -> Scene {
    let mut bodies = Vec::new();
    for i in 0..2 {
        let mut b = box_body(
            rng.log_range(1.0, 100.0),
            DVec3::new(
                rng.range(0.2, 1.0),
                rng.range(0.2, 1.0),
                rng.range(0.2, 1.0),
            ),
            rng.rotation(),
            DVec3::new(2.0 * i as f64, 0.0, 0.0) + rng.vector(0.3),
        );
        b.velocity = rng.vector(2.0).to_array();
        b.angular_velocity = rng.vector(2.0).to_array();
        bodies.push(b);
    }
    let (pa, pb) = (bodies[1].position(), bodies[0].position());
    let contacts = (0..rng.int(1, 4))
        .map(|_| {
            let normal = ((pa - pb).normalize() + rng.vector(0.5)).normalize();
            contact(
                1,
                Some(0),
                (pa + pb) * 0.5 + rng.vector(0.5),
                normal,
                rng.unit(),
            )
        })
        .collect();
    Scene { bodies, contacts }
}

#[test]
pub(super) fn momentum_is_conserved_in_two_body_impacts() {
    let mut rng = Rng::new(7);
    let mut max_rel = 0.0f64;
    for k in 0..2000 {
        let scene = two_body_impact(&mut rng);
        let about = rng.vector(5.0);
        let before = momenta(&scene, &initial_velocities(&scene), about);
        for s in [Method::Enumeration, Method::Lemke] {
            let sol = solve_scene(&scene, &settings(s)).unwrap();
            assert!(sol.islands[0].solution.status.is_solution());
            let after = momenta(&scene, &sol.scenes[0].bodies, about);
            let scale = before.2.max(after.2);
            let dp = (after.0 - before.0).length() / scale;
            let dl = (after.1 - before.1).length() / scale;
            max_rel = max_rel.max(dp).max(dl);
            assert!(
                dp <= 1e-12 && dl <= 1e-12,
                "impact {k} ({}): dp {dp:.1e}, dL {dl:.1e}",
                s.name()
            );
        }
    }
    eprintln!("momentum: max relative change {max_rel:.1e}");
}

#[test]
pub(super) fn inelastic_impacts_lose_exactly_half_z_m_z() {
    // With ε = 0, q = J v, so ΔKE = zᵀJv + ½ zᵀMz = zᵀq + ½ zᵀMz, and
    // complementarity (zᵀ(Mz + q) = 0) turns it into −½ zᵀMz ≤ 0.
    let mut rng = Rng::new(11);
    let mut max_rel = 0.0f64;
    for k in 0..3000 {
        let n = 1 + k % 10;
        let mut scene = random_island(&mut rng, n, 100.0);
        scene.contacts.iter_mut().for_each(|c| c.restitution = 0.0);
        let ke0 = kinetic_energy(&scene, &initial_velocities(&scene));
        let lcp = &build(&scene, "island").unwrap().2[0];
        for s in [Method::Enumeration, Method::Lemke] {
            let sol = solve_scene(&scene, &settings(s)).unwrap();
            let isl = &sol.islands[0];
            assert!(isl.solution.status.is_solution());
            let z = &isl.solution.z;
            let mz = lcp
                .w(z)
                .iter()
                .zip(&lcp.q)
                .map(|(w, q)| w - q)
                .collect::<Vec<_>>();
            let zmz: f64 = z.iter().zip(&mz).map(|(a, b)| a * b).sum();
            let ke1 = kinetic_energy(&scene, &sol.scenes[0].bodies);
            let rel = ((ke1 - ke0) + 0.5 * zmz).abs() / ke0;
            max_rel = max_rel.max(rel);
            assert!(
                rel <= 1e-10,
                "island {k} ({}): ΔKE {} vs −½zᵀMz {}",
                s.name(),
                ke1 - ke0,
                -0.5 * zmz
            );
            assert!(
                ke1 <= ke0 * (1.0 + 1e-12),
                "island {k}: energy grew {ke0} → {ke1}"
            );
        }
    }
    eprintln!("ΔKE = −½zᵀMz: max relative deviation {max_rel:.1e}");
}

#[test]
pub(super) fn a_single_elastic_contact_keeps_kinetic_energy() {
    let mut rng = Rng::new(13);
    let mut approaching = 0;
    for k in 0..2000 {
        let mut scene = random_island(&mut rng, 1, 100.0);
        scene.contacts[0].restitution = 1.0;
        let ke0 = kinetic_energy(&scene, &initial_velocities(&scene));
        for s in METHODS {
            let sol = solve_scene(&scene, &settings(s)).unwrap();
            let ke1 = kinetic_energy(&scene, &sol.scenes[0].bodies);
            assert!(
                (ke1 - ke0).abs() <= 1e-12 * ke0,
                "island {k} ({}): {ke0} → {ke1}",
                s.name()
            );
        }
        if sol_z(&scene) > 0.0 {
            approaching += 1;
        }
    }
    assert!(approaching > 500, "{approaching} of 2000 contacts approach");
}

pub(super) fn sol_z(scene: &Scene) -> f64 {
    solve_scene(scene, &settings(Method::Enumeration))
        .unwrap()
        .scenes[0]
        .impulses[0]
}

#[test]
pub(super) fn a_box_landing_flat_on_four_contacts() {
    // Four coplanar contacts: M is 4×4 of rank 3, z is not unique, but w
    // (hence J v⁺) and the velocities are.
    for speed in [0.0, 0.1, 1.0, 7.5] {
        for e in [0.0, 0.3, 1.0] {
            let scene = box_on_ground(speed, e);
            for s in METHODS {
                let sol = solve_scene(&scene, &settings(s)).unwrap();
                let isl = &sol.islands[0];
                let what = format!("{} speed {speed} ε {e}", s.name());
                assert!(
                    isl.solution.status.is_solution(),
                    "{what}: {}",
                    isl.solution.status
                );
                assert!(
                    isl.solution.residuals.error <= 1e-9,
                    "{what}: {:?}",
                    isl.solution.residuals
                );
                assert!(
                    sol.scenes[0]
                        .impulses
                        .iter()
                        .all(|z| z.is_finite() && *z >= 0.0),
                    "{what}: {:?}",
                    sol.scenes[0].impulses
                );
                let b = &sol.scenes[0].bodies[1];
                assert!(b
                    .velocity
                    .iter()
                    .chain(&b.angular_velocity)
                    .all(|v| v.is_finite()));
                // Bounces straight up at ε·speed without spinning; total impulse m(1 + ε)·speed.
                let tol = if s == Method::Pgs { 1e-8 } else { 1e-12 } * speed.max(1.0);
                assert!((b.velocity[1] - e * speed).abs() <= tol, "{what}: {b:?}");
                assert!(
                    b.velocity[0].abs() <= tol && b.velocity[2].abs() <= tol,
                    "{what}"
                );
                assert!(
                    b.angular_velocity.iter().all(|w| w.abs() <= tol),
                    "{what}: {b:?}"
                );
                let total: f64 = sol.scenes[0].impulses.iter().sum();
                assert!(
                    (total - (1.0 + e) * speed).abs() <= tol,
                    "{what}: Σz = {total}"
                );
                // The ground does not move.
                assert_eq!(sol.scenes[0].bodies[0].velocity, [0.0; 3]);
            }
        }
    }
    // The singularity is real: enumeration of every basis finds a continuum.
    let scene = box_on_ground(1.0, 0.5);
    let isl = &solve_scene(&scene, &common::all_solutions_settings())
        .unwrap()
        .islands[0];
    assert_eq!(isl.solution.status, Status::MultipleSolutions);
    let lcp = &build(&scene, "box").unwrap().2[0];
    assert!(!common::is_positive_definite(lcp, 1e-8));
}

/// Solves the scene's LCP over all its contacts at once (one "island" holding
/// every contact) and compares it with the pipeline's island-by-island solve:
/// w per contact and every body's velocities, to 1e-9 of their scales.
pub(super) fn whole_equals_islands(scene: &Scene, what: &str) -> (f64, f64) {
    let rows = assemble_contacts(scene);
    let all = Island {
        contacts: (0..scene.contacts.len()).collect(),
    };
    let lcp = assemble_island(scene, &rows, &all);
    // Contacts of different islands do not couple: M is block diagonal.
    let islands = find_islands(scene);
    let mut island_of = vec![0; scene.contacts.len()];
    for (k, isl) in islands.iter().enumerate() {
        for &c in &isl.contacts {
            island_of[c] = k;
        }
    }
    let n = lcp.n();
    for i in 0..n {
        for j in 0..n {
            if island_of[i] != island_of[j] {
                assert_eq!(lcp.at(i, j), 0.0, "{what}: M[{i}][{j}] couples two islands");
            }
        }
    }
    let solver = if n <= 20 {
        Method::Enumeration
    } else {
        Method::Lemke
    };
    let whole = solve(&lcp, &settings(solver)).unwrap();
    assert!(
        whole.status.is_solution(),
        "{what}: whole scene {}",
        whole.status
    );
    let by_island = solve_scene(scene, &settings(Method::Enumeration)).unwrap();
    let mut w_islands = vec![f64::NAN; n];
    for r in &by_island.islands {
        assert!(r.solution.status.is_solution(), "{what}");
        for (&c, &w) in r.contacts.iter().zip(&r.solution.w) {
            w_islands[c] = w;
        }
    }
    let zmax = inf_norm(&whole.z).max(inf_norm(&by_island.scenes[0].impulses));
    let dw = common::max_diff(&whole.w, &w_islands) / w_scale(&lcp, zmax);
    let v_whole = apply_impulses(scene, &rows, &whole.z);
    let flat = |v: &[BodyVelocity]| -> Vec<f64> {
        v.iter()
            .flat_map(|b| b.velocity.into_iter().chain(b.angular_velocity))
            .collect()
    };
    let (a, b) = (flat(&v_whole), flat(&by_island.scenes[0].bodies));
    let v0 = flat(&initial_velocities(scene));
    let dv = common::max_diff(&a, &b) / inf_norm(&a).max(inf_norm(&v0)).max(f64::MIN_POSITIVE);
    assert!(dw <= 1e-9 && dv <= 1e-9, "{what}: dw {dw:.1e}, dv {dv:.1e}");
    (dw, dv)
}

#[test]
pub(super) fn the_seed_chain_island_by_island_equals_the_whole_scene() {
    for e in [0.0, 0.5, 1.0] {
        let scene = seed_chain(e);
        assert_eq!(find_islands(&scene).len(), 1, "the chain is one island");
        whole_equals_islands(&scene, &format!("seed chain ε = {e}"));
        // Every contact of figure 7 approaches, and every active contact
        // leaves at −ε times its approach speed.
        let rows = assemble_contacts(&scene);
        assert!(rows.iter().all(|r| r.v_rel < 0.0));
        let sol = solve_scene(&scene, &settings(Method::Enumeration)).unwrap();
        let after = relative_normal_velocities(&scene, &sol.scenes[0].bodies);
        for (i, r) in rows.iter().enumerate() {
            if sol.scenes[0].impulses[i] > 0.0 {
                assert!(
                    (after[i] + e * r.v_rel).abs() < 1e-12,
                    "ε {e} contact {i}: {after:?}"
                );
            } else {
                assert!(after[i] >= -e * r.v_rel - 1e-12);
            }
        }
    }
}

#[test]
pub(super) fn islands_one_by_one_equal_the_whole_scene_lcp() {
    let mut rng = Rng::new(17);
    let (mut max_dw, mut max_dv) = (0.0f64, 0.0f64);
    for k in 0..300 {
        let count = rng.int(2, 5);
        let scene = random_scene(&mut rng, count, 5, 100.0);
        assert_eq!(find_islands(&scene).len(), count, "scene {k}");
        let (dw, dv) = whole_equals_islands(&scene, &format!("scene {k}"));
        max_dw = max_dw.max(dw);
        max_dv = max_dv.max(dv);
    }
    eprintln!("islands vs whole scene: max dw {max_dw:.1e}, max dv {max_dv:.1e}");
}

#[test]
pub(super) fn diagonal_of_m_is_n_k_n() {
    let mut rng = Rng::new(19);
    for k in 0..1000 {
        let scene = random_island(&mut rng, 1 + k % 10, 100.0);
        let rows = assemble_contacts(&scene);
        let lcp = &build(&scene, "i").unwrap().2[0];
        for (i, (c, r)) in scene.contacts.iter().zip(&rows).enumerate() {
            let n = c.normal();
            let nkn = n.dot(r.k * n);
            let m_ii = lcp.at(i, i);
            assert!(
                (nkn - m_ii).abs() <= 1e-12 * m_ii.abs(),
                "island {k} contact {i}: nᵀKn = {nkn}, M_ii = {m_ii}"
            );
            assert!(m_ii > 0.0);
            // K is symmetric.
            let asym = (r.k - r.k.transpose()).to_cols_array();
            assert!(asym.iter().all(|v| v.abs() <= 1e-12 * m_ii.max(1.0)));
        }
        // M is symmetric.
        assert!(lcp.is_symmetric(), "island {k}");
    }
}

#[test]
pub(super) fn active_contacts_obey_newtons_law_after_the_solve() {
    let mut rng = Rng::new(23);
    let (mut active_approaching, mut active_separating) = (0, 0);
    for k in 0..3000 {
        let scene = random_island(&mut rng, 1 + k % 10, 100.0);
        let (_, rows, lcps) = build(&scene, "island").unwrap();
        for s in [Method::Enumeration, Method::Lemke] {
            let sol = solve_scene(&scene, &settings(s)).unwrap();
            let isl = &sol.islands[0];
            assert!(isl.solution.status.is_solution());
            let after = relative_normal_velocities(&scene, &sol.scenes[0].bodies);
            let tol = 1e-9 * w_scale(&lcps[0], inf_norm(&isl.solution.z));
            for (i, c) in scene.contacts.iter().enumerate() {
                let v0 = rows[i].v_rel;
                let e = c.restitution;
                // Everywhere: v_rel⁺ = v_rel⁻ + (Mz)_i = w − ε min(v_rel⁻, 0)
                // (the applied impulses agree with the LCP's M z + q).
                let w = isl.solution.w[i];
                assert!(
                    (after[i] - (w - e * v0.min(0.0))).abs() <= tol,
                    "island {k} contact {i}: v⁺ {} w {w} v⁻ {v0} ε {e}",
                    after[i]
                );
                if sol.scenes[0].impulses[i] > 0.0 {
                    let target = if v0 < 0.0 { -e * v0 } else { 0.0 };
                    if s == Method::Enumeration {
                        if v0 < 0.0 {
                            active_approaching += 1;
                        } else {
                            active_separating += 1;
                        }
                    }
                    assert!(
                        (after[i] - target).abs() <= tol,
                        "island {k} contact {i} ({}): v⁻ {v0}, ε {e}, v⁺ {} ≠ {target}",
                        s.name(),
                        after[i]
                    );
                } else {
                    // An inactive contact does not penetrate more than Newton allows.
                    assert!(after[i] >= -e * v0.min(0.0) - tol);
                }
            }
        }
    }
    eprintln!("active contacts: {active_approaching} approaching, {active_separating} separating");
    assert!(active_approaching > 1000 && active_separating > 10);
}
