//! Coulomb friction through the product API: the maximum-dissipation
//! projections worked by hand (the tangential impulse is −v_T projected on
//! the disc of radius μ γ_n), a box sliding on the ground, a box on an incline, μ = 0 against
//! the frictionless solver, warm start, mixed batches, and a property test
//! that every returned impulse is in its cone.

use glam::DVec3;
use proptest::prelude::*;

use crate::generate::friction::{box_on_ground_moving, box_on_incline};
use crate::generate::{random_island, Rng};
use crate::{
    Backend, Body, Contact, FrictionMethod, FrictionProblem, Report, Scene, Settings, Solver,
    Status,
};

/// The CPU solver with friction tolerance 1e-12: these tests compare
/// impulses and velocities to 1e-9, finer than the default tolerance 1e-8
/// at which the exact path stops.
fn cpu() -> Solver {
    Solver::new(Settings {
        backend: Backend::Cpu,
        friction_tolerance: 1e-12,
        ..Settings::default()
    })
    .unwrap()
}

fn solve(scene: &Scene) -> Report {
    cpu().solve_scenes(std::slice::from_ref(scene)).unwrap()
}

/// A unit point mass (no rotation) on the ground, approaching at `v_n` and
/// sliding at v_T in the contact frame (t₁, t₂) = ((1, 0, 0), (0, 0, −1)).
fn point_mass(v_n: f64, v_t: [f64; 2], mu: f64) -> Scene {
    let mut b = Body::new(1.0, [0.0; 3], [0.0, 0.0, 0.0]);
    b.velocity = [v_t[0], -v_n, -v_t[1]];
    Scene {
        bodies: vec![b],
        contacts: vec![Contact::new(0, None, [0.0; 3], [0.0, 1.0, 0.0], 0.0).with_friction(mu)],
    }
}

#[test]
fn seed_001_projection_examples_through_the_solver() {
    // (μ, γ_n, v_T, γ_T), worked by hand. A unit mass approaching at γ_n
    // gets the normal impulse γ_n; sliding at v_T with ‖v_T‖ ≥ μ γ_n it gets
    // γ_T = −μ γ_n v_T / ‖v_T‖ (Coulomb's law with maximum dissipation). A
    // v_T and the same direction three times faster give the same γ_T.
    for (mu, gamma_n, v_t, want) in [
        (0.5, 10.0, [3.0, -4.0], [-3.0, 4.0]),
        (0.6, 5.0, [4.0, 3.0], [-12.0 / 5.0, -9.0 / 5.0]),
    ] {
        for speed in [1.0, 3.0] {
            let v = [v_t[0] * speed, v_t[1] * speed];
            let r = solve(&point_mass(gamma_n, v, mu));
            let isl = &r.friction[0];
            assert_eq!(isl.status(), Status::Solved);
            assert!(isl.error() < 1e-14, "{}", isl.error());
            let c = &r.scenes[0].friction.as_ref().unwrap().contacts[0];
            assert!((c.normal - gamma_n).abs() < 1e-12, "{c:?}");
            for k in 0..2 {
                assert!(
                    (c.tangential[k] - want[k]).abs() < 1e-12,
                    "μ {mu} v_T {v:?}: {c:?}"
                );
            }
            // World vector: r_n n + r_t1 t1 + r_t2 t2 with t1 = x, t2 = −z.
            let world = [want[0], gamma_n, -want[1]];
            for k in 0..3 {
                assert!((c.impulse[k] - world[k]).abs() < 1e-12, "{c:?}");
            }
        }
        // The same problem as a FrictionProblem (W = I, q = (−γ_n, v_T)).
        let mut w = vec![0.0; 9];
        w[0] = 1.0;
        w[4] = 1.0;
        w[8] = 1.0;
        let p = FrictionProblem::new(w, vec![-gamma_n, v_t[0], v_t[1]], vec![mu]).unwrap();
        let r = cpu().solve_friction(&[p]).unwrap();
        let s = &r.friction[0].solution;
        assert_eq!(s.status, Status::Solved);
        assert!(
            (s.r[1] - want[0]).abs() < 1e-12 && (s.r[2] - want[1]).abs() < 1e-12,
            "{:?}",
            s.r
        );
    }
}

#[test]
fn a_sliding_box_is_braked_on_the_cone_and_stops_exactly_when_friction_suffices() {
    let (mass, mu, v_n) = (2.0, 0.4, 1.0);
    // μ γ_n = μ m v_n = 0.8: speeds below stop, above keep sliding.
    for speed in [0.3, 0.79, 0.81, 2.0, 5.0] {
        let dir = DVec3::new(0.6, 0.0, 0.8);
        let v_t = dir * speed;
        let scene = box_on_ground_moving(mass, mu, v_t + DVec3::new(0.0, -v_n, 0.0));
        let r = solve(&scene);
        assert_eq!(r.friction[0].status(), Status::Solved, "{speed}");
        let f = r.scenes[0].friction.as_ref().unwrap();
        let total_n: f64 = f.contacts.iter().map(|c| c.normal).sum();
        assert!(
            (total_n - mass * v_n).abs() < 1e-9,
            "{speed}: Σγ_n = {total_n}"
        );
        let tangential: DVec3 = f
            .contacts
            .iter()
            .map(|c| DVec3::from_array(c.tangential_impulse))
            .sum();
        // Opposes the velocity.
        assert!(
            tangential.cross(dir).length() < 1e-9 * (1.0 + tangential.length()),
            "{speed}"
        );
        assert!(tangential.dot(dir) < 0.0, "{speed}");
        let after = DVec3::from_array(r.scenes[0].bodies[1].velocity);
        let spin = DVec3::from_array(r.scenes[0].bodies[1].angular_velocity);
        if mu * mass * v_n >= mass * speed {
            // Stops exactly: every point of the box at rest.
            assert!(
                after.length() < 1e-9 && spin.length() < 1e-9,
                "{speed}: {after} {spin}"
            );
        } else {
            // Slides: each contact on its cone's boundary, the box slowed by μ γ_n / m.
            for c in &f.contacts {
                let t = c.tangential[0].hypot(c.tangential[1]);
                assert!((t - mu * c.normal).abs() < 1e-9, "{speed}: {c:?}");
            }
            let want = v_t * (1.0 - mu * v_n / speed);
            assert!((after - want).length() < 1e-9, "{speed}: {after} vs {want}");
        }
    }
}

#[test]
fn a_box_on_an_incline_sticks_below_the_friction_angle_and_slides_above() {
    let (mu, fall) = (0.5, 0.1);
    for theta_deg in [10.0f64, 20.0, 26.0, 27.0, 35.0, 45.0] {
        let theta = theta_deg.to_radians();
        let r = solve(&box_on_incline(theta, mu, fall));
        assert_eq!(r.friction[0].status(), Status::Solved, "{theta_deg}°");
        let v = DVec3::from_array(r.scenes[0].bodies[0].velocity);
        let w = DVec3::from_array(r.scenes[0].bodies[0].angular_velocity);
        let down = DVec3::new(-theta.cos(), -theta.sin(), 0.0);
        if theta.tan() < mu {
            assert!(
                v.length() < 1e-9 && w.length() < 1e-9,
                "{theta_deg}°: sticks, {v} {w}"
            );
        } else {
            // Slides down the slope at Δv = g Δt (sin θ − μ cos θ), no spin.
            let speed = fall * (theta.sin() - mu * theta.cos());
            assert!(
                (v - down * speed).length() < 1e-9,
                "{theta_deg}°: {v} vs {}",
                down * speed
            );
        }
    }
}

#[test]
fn zero_friction_equals_the_frictionless_solver() {
    let mut rng = Rng::new(42);
    let mut compared = 0;
    for _ in 0..200 {
        let n = rng.int(1, 4);
        let scene = random_island(&mut rng, n, 10.0);
        let lcp = solve(&scene);
        if !lcp.islands.iter().all(|i| i.status() == Status::Solved) {
            continue;
        }
        // μ = 0 through the friction path: one contact with a tiny μ routes
        // the scene there; the same problems with μ = 0 by solve_friction.
        let mut problems: Vec<_> = scene.friction_islands("scene").unwrap();
        for isl in &mut problems {
            isl.problem.mu.iter_mut().for_each(|m| *m = 0.0);
        }
        let list: Vec<FrictionProblem> = problems.iter().map(|i| i.problem.clone()).collect();
        let fr = cpu().solve_friction(&list).unwrap();
        for (isl, res) in problems.iter().zip(&fr.friction) {
            assert_eq!(res.status(), Status::Solved);
            for (i, &c) in isl.contacts.iter().enumerate() {
                let z = lcp.scenes[0].impulses[c];
                // The LCP's w: the normal velocities agree even where z is not unique.
                let lcp_isl = lcp
                    .islands
                    .iter()
                    .find(|l| l.contacts.contains(&c))
                    .unwrap();
                let k = lcp_isl.contacts.iter().position(|&x| x == c).unwrap();
                let scale = 1.0 + z.abs();
                assert!((res.solution.u[3 * i] - lcp_isl.solution.w[k]).abs() < 1e-8 * scale);
                assert!(
                    res.solution.r[3 * i + 1] == 0.0 && res.solution.r[3 * i + 2] == 0.0,
                    "{:?} {:?}",
                    res.solution,
                    isl.problem
                );
                compared += 1;
            }
        }
    }
    assert!(compared > 200, "{compared}");
    // And a scene whose contacts all have μ = 0 stays on the LCP path:
    // byte-identical impulses and velocities, no friction results.
    let scene = crate::generate::box_on_ground(1.0, 0.3);
    let r = solve(&scene);
    assert!(r.friction.is_empty() && r.scenes[0].friction.is_none());
}

#[test]
fn zero_friction_scenes_match_the_lcp_path_impulses_and_velocities_on_unique_islands() {
    // Balls on the ground and on each other: M positive definite, z unique.
    let mut bodies = vec![];
    let mut contacts = vec![];
    for i in 0..3 {
        let mut b =
            crate::generate::ball_body(1.0 + i as f64, 0.5, DVec3::new(0.0, 0.5 + i as f64, 0.0));
        b.velocity = [0.3 * i as f64, -1.0 - i as f64, 0.1];
        bodies.push(b);
        let below = if i == 0 { None } else { Some(i - 1) };
        contacts.push(Contact::new(
            i,
            below,
            [0.0, i as f64, 0.0],
            [0.0, 1.0, 0.0],
            0.2,
        ));
    }
    let plain = Scene { bodies, contacts };
    let lcp = solve(&plain);
    let mut with = plain.clone();
    // A second, separate island with friction routes the scene to the friction path.
    let mut ball = crate::generate::ball_body(1.0, 0.5, DVec3::new(5.0, 0.5, 0.0));
    ball.velocity = [1.0, -1.0, 0.0];
    with.bodies.push(ball);
    with.contacts
        .push(Contact::new(3, None, [5.0, 0.0, 0.0], [0.0, 1.0, 0.0], 0.0).with_friction(0.3));
    let fr = solve(&with);
    assert!(fr.scenes[0].friction.is_some() && fr.islands.is_empty());
    for c in 0..3 {
        assert!((fr.scenes[0].impulses[c] - lcp.scenes[0].impulses[c]).abs() < 1e-12);
    }
    for b in 0..3 {
        for k in 0..3 {
            let (x, y) = (&fr.scenes[0].bodies[b], &lcp.scenes[0].bodies[b]);
            assert!((x.velocity[k] - y.velocity[k]).abs() < 1e-12);
            assert!((x.angular_velocity[k] - y.angular_velocity[k]).abs() < 1e-12);
        }
    }
}

#[test]
fn a_mixed_batch_keeps_the_order_and_the_frictionless_answers() {
    let plain = crate::generate::box_on_ground(1.0, 0.0);
    let rough = box_on_ground_moving(1.0, 0.5, DVec3::new(1.0, -1.0, 0.0));
    let alone = solve(&plain);
    let r = cpu()
        .solve_scenes(&[rough.clone(), plain.clone(), rough])
        .unwrap();
    assert_eq!(r.scenes.len(), 3);
    assert!(r.scenes[0].friction.is_some() && r.scenes[2].friction.is_some());
    assert!(r.scenes[1].friction.is_none());
    assert_eq!(r.scenes[1].impulses, alone.scenes[0].impulses);
    assert_eq!(r.islands.len(), alone.islands.len());
    assert!(r.islands.iter().all(|i| i.scene == Some(1)));
    assert_eq!(r.scenes[1].islands, 0..alone.islands.len());
    assert_eq!(r.friction.len(), 2);
    assert_eq!(
        (r.friction[0].scene, r.friction[1].scene),
        (Some(0), Some(2))
    );
    assert_eq!(r.friction_statuses[0], 2);
    let text = r.to_string();
    assert!(
        text.contains("2 frictional islands") && text.contains("max Coulomb error"),
        "{text}"
    );
}

#[test]
fn warm_start_by_contact_ids_starts_from_the_last_impulses() {
    let mut scene = box_on_ground_moving(1.0, 0.5, DVec3::new(0.2, -1.0, 0.1));
    for (k, c) in scene.contacts.iter_mut().enumerate() {
        c.id = Some(10 + k as u64);
    }
    let mut solver = Solver::new(Settings {
        backend: Backend::Cpu,
        warm_start: true,
        friction_method: FrictionMethod::Nsgs,
        ..Settings::default()
    })
    .unwrap();
    let cold = solver.solve_scenes(std::slice::from_ref(&scene)).unwrap();
    let hot = solver.solve_scenes(std::slice::from_ref(&scene)).unwrap();
    assert!(!cold.friction[0].warm_started && hot.friction[0].warm_started);
    assert!(hot.friction[0].solution.iterations < cold.friction[0].solution.iterations);
    assert_eq!(hot.friction[0].solution.iterations, 0, "already a solution");
    let (a, b) = (&cold.scenes[0].bodies[1], &hot.scenes[0].bodies[1]);
    for k in 0..3 {
        assert!((a.velocity[k] - b.velocity[k]).abs() < 1e-8);
    }
    // Problems keyed by ids, through the same door.
    let problems: Vec<FrictionProblem> = scene
        .friction_islands("s")
        .unwrap()
        .into_iter()
        .map(|i| i.problem)
        .collect();
    let ids = vec![vec![1, 2, 3, 4]];
    let first = solver.solve_friction_keyed(&problems, &ids).unwrap();
    let again = solver.solve_friction_keyed(&problems, &ids).unwrap();
    assert!(!first.friction[0].warm_started && again.friction[0].warm_started);
    let e = solver
        .solve_friction_keyed(&problems, &[vec![1]])
        .unwrap_err();
    assert!(e.to_string().contains("problem 0"), "{e}");
    solver.clear_warm_start();
    let third = solver.solve_friction_keyed(&problems, &ids).unwrap();
    assert!(!third.friction[0].warm_started);
}

#[test]
fn bad_friction_input_is_an_error_naming_the_item_and_field() {
    let mut scene = point_mass(1.0, [1.0, 0.0], 0.5);
    scene.contacts[0].friction = f64::NAN;
    let e = cpu().solve_scenes(&[scene]).unwrap_err().to_string();
    assert!(
        e.contains("scene 0, contact 0") && e.contains("`friction`"),
        "{e}"
    );
    let good = FrictionProblem::new(
        vec![1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0],
        vec![-1.0, 0.0, 0.0],
        vec![0.3],
    )
    .unwrap();
    let mut bad = good.clone();
    bad.mu[0] = -1.0;
    let e = cpu().solve_friction(&[good, bad]).unwrap_err().to_string();
    assert!(e.contains("problem 1") && e.contains("mu[0]"), "{e}");
}

/// W = A Aᵀ + δ I (symmetric positive definite), q and μ random.
/// Regression (issue 12): every island of the benchmark's families at
/// k ≤ 4 (`benches/friction.rs`, seed 0xF1C7, 1000 per set) is solved by
/// `auto` at the default tolerance. Random spheres k = 3, island 306, used
/// to stop `not_converged` at the 1000-iteration cap (error 8.3e-3): NSGS
/// cycles there and Newton stalled from every sweep's iterate; Newton from
/// the start converges in 6 steps, which `auto` now tries once.
#[test]
fn auto_solves_every_benchmark_island_of_at_most_four_contacts() {
    use crate::generate::friction::{friction_batch, FrictionFamily};
    let mut solver = Solver::new(Settings {
        backend: Backend::Cpu,
        ..Settings::default()
    })
    .unwrap();
    for family in FrictionFamily::ALL {
        for k in 1..=4 {
            let Some(batch) = friction_batch(family, k, 0xF1C7, 1000) else {
                continue;
            };
            let report = solver.solve_friction(&batch).unwrap();
            for (i, isl) in report.friction.iter().enumerate() {
                assert_eq!(
                    isl.status(),
                    Status::Solved,
                    "{} k = {k} island {i}: error {:e}",
                    family.name(),
                    isl.error()
                );
                assert!(isl.error() <= 1e-8);
            }
        }
    }
}

fn random_problem(seed: u64, k: usize) -> FrictionProblem {
    let mut rng = Rng::new(seed);
    let n = 3 * k;
    let a: Vec<f64> = (0..n * n).map(|_| rng.range(-1.0, 1.0)).collect();
    let w = (0..n * n)
        .map(|e| {
            let (i, j) = (e / n, e % n);
            (0..n).map(|m| a[i * n + m] * a[j * n + m]).sum::<f64>()
                + if i == j { 0.05 } else { 0.0 }
        })
        .collect();
    let q = (0..n).map(|_| rng.range(-1.0, 1.0)).collect();
    let mu = (0..k).map(|_| rng.range(0.0, 1.5)).collect();
    FrictionProblem::new(w, q, mu).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn every_returned_impulse_is_in_its_cone(seed in 0u64..1_000_000, k in 1usize..7) {
        let p = random_problem(seed, k);
        for method in [FrictionMethod::Auto, FrictionMethod::Nsgs] {
            let mut solver = Solver::new(Settings {
                backend: Backend::Cpu,
                friction_method: method,
                ..Settings::default()
            }).unwrap();
            let r = solver.solve_friction(std::slice::from_ref(&p)).unwrap();
            let s = &r.friction[0].solution;
            let scale = s.r.iter().fold(1.0f64, |m, v| m.max(v.abs()));
            for i in 0..k {
                let t = s.r[3 * i + 1].hypot(s.r[3 * i + 2]);
                prop_assert!(t <= p.mu[i] * s.r[3 * i] + 1e-12 * scale,
                    "{:?} contact {i}: ‖r_t‖ {t} > μ r_n {}", method, p.mu[i] * s.r[3 * i]);
                prop_assert!(s.r[3 * i] >= 0.0);
            }
            if method == FrictionMethod::Auto {
                prop_assert_eq!(s.status, Status::Solved, "error {:e}", s.residuals.coulomb_error);
            }
        }
    }
}
