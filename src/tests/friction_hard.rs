//! Small hard frictional islands (issue: friction at every size, item 5):
//! stacks of 2–4 boxes whose masses differ by up to 1e4, at μ up to 2,
//! falling and drifting, solved by `auto` at its default settings (the
//! cap of 1,000 iterations, tolerance 1e-8) and judged by the checked
//! Coulomb error of each answer (the report's status), not against stored
//! answers: 648 stacks, 24 per (boxes, ratio, μ). Before PROX raised its
//! inner scalings ρ where it creeps (`friction::prox`, `Creep`), 5 of these
//! 648 ended `not_converged` at that cap (heavy boxes on light ones, μ 0.3,
//! PROX creeping: its inner Newton, scaled by the light box's effective
//! mass, could not weigh the heavy box's impulses; solved island by island
//! with `solve_friction_problem`, BENCHMARKS.md, 2026-11-28), and the test
//! ran 216 of them at a cap of 5,000.

use glam::{DMat3, DVec3};

use crate::generate::{box_body, Rng};
use crate::{Backend, Body, Contact, Scene, Settings, Solver, Status};

/// A stack of `levels` unit boxes on the ground, level l of mass
/// `masses[l]`, each falling and drifting at seeded speeds, μ = `mu`.
fn stack(masses: &[f64], mu: f64, rng: &mut Rng) -> Scene {
    let mut bodies = vec![Body::fixed([0.0, -0.5, 0.0])];
    let mut contacts = Vec::new();
    for (l, &m) in masses.iter().enumerate() {
        let mut b = box_body(
            m,
            DVec3::splat(0.5),
            DMat3::IDENTITY,
            DVec3::new(0.0, 0.5 + l as f64, 0.0),
        );
        b.velocity = [
            rng.range(-1.0, 1.0),
            -rng.range(0.0, 2.0),
            rng.range(-1.0, 1.0),
        ];
        b.angular_velocity = [
            rng.range(-0.5, 0.5),
            rng.range(-0.5, 0.5),
            rng.range(-0.5, 0.5),
        ];
        bodies.push(b);
        for (x, z) in [(-0.5, -0.5), (0.5, -0.5), (-0.5, 0.5), (0.5, 0.5)] {
            contacts.push(
                Contact::new(l + 1, Some(l), [x, l as f64, z], [0.0, 1.0, 0.0], 0.0)
                    .with_friction(mu),
            );
        }
    }
    Scene { bodies, contacts }
}

/// The seeded family: per (levels, ratio, μ) `per` stacks, masses 1 or
/// `ratio` in a seeded order with at least one of each.
fn family(per: usize) -> Vec<(String, Scene)> {
    let mut rng = Rng::new(2026);
    let mut out = Vec::new();
    for levels in 2..=4 {
        for ratio in [1e2, 1e3, 1e4] {
            for mu in [0.3, 1.0, 2.0] {
                for k in 0..per {
                    let mut masses: Vec<f64> = (0..levels)
                        .map(|_| if rng.unit() < 0.5 { 1.0 } else { ratio })
                        .collect();
                    masses[k % levels] = 1.0;
                    masses[(k + 1) % levels] = ratio;
                    let name =
                        format!("levels {levels}, ratio {ratio:e}, mu {mu}, masses {masses:?}");
                    out.push((name, stack(&masses, mu, &mut rng)));
                }
            }
        }
    }
    out
}

#[test]
fn stacks_with_mass_ratios_to_1e4_and_mu_to_2_are_solved_by_auto_at_its_defaults() {
    let mut solver = Solver::new(Settings {
        backend: Backend::Cpu,
        ..Settings::default()
    })
    .unwrap();
    let scenes = family(24);
    assert_eq!(scenes.len(), 648);
    let mut failed = Vec::new();
    for (name, scene) in &scenes {
        let r = solver.solve_scenes(std::slice::from_ref(scene)).unwrap();
        for f in &r.friction {
            if f.status() != Status::Solved {
                failed.push(format!(
                    "{name}: {:?} error {:e} iterations {}",
                    f.status(),
                    f.error(),
                    f.solution.iterations
                ));
            }
        }
    }
    assert!(
        failed.is_empty(),
        "{} of {} not solved:\n{}",
        failed.len(),
        scenes.len(),
        failed.join("\n")
    );
}
