//! Worlds with Coulomb friction through the product (`Solver::step_worlds`
//! routes islands with μ > 0 to the friction path): a sliding box stops
//! where Coulomb says and never leaves the ground, a box on an incline
//! sticks or accelerates at g (sin θ − μ cos θ), a stack with friction rests.

use glam::DVec3;

use crate::settings::{Backend, Method, Settings};
use crate::world::generate::{incline, standard_world, WorldKind};
use crate::Solver;

/// The CPU solver, warm-started, with friction tolerance 1e-12: these tests
/// bound velocities to 1e-9 m/s and energies to 1e-9 J on 1000 kg boxes,
/// finer than the default tolerance 1e-8 gives (the Coulomb error is
/// normalised by ‖r‖, here hundreds of N·s), at which the exact path stops.
fn cpu() -> Solver {
    Solver::new(Settings {
        warm_start: true,
        friction_tolerance: 1e-12,
        ..Settings::new(Backend::Cpu, Method::Auto)
    })
    .unwrap()
}

/// A unit box sliding at v₀ = 2 m/s on the ground with μ = 0.5 stops after
/// v₀²/(2 μ g) = 0.4077 m, within 2% (Δt = 0.002 s: the semi-implicit sum
/// differs from the integral by about v₀ Δt / 2 = 2 mm, 0.5%). It never
/// leaves the ground: |v_y| ≤ 1e-9 m/s after every step.
#[test]
fn a_sliding_box_stops_where_coulomb_says() {
    let mut worlds = vec![standard_world(WorldKind::Slide, 1, 0)];
    let (v0, mu, g) = (2.0, 0.5, 9.81);
    let x0 = worlds[0].bodies[1].position[0];
    let mut solver = cpu();
    let mut stopped = None;
    for step in 0..1000 {
        let r = solver.step_worlds(&mut worlds, 0.002).unwrap();
        assert_eq!(r.unsolved, 0, "step {step}");
        let b = &worlds[0].bodies[1];
        assert!(
            b.velocity[1].abs() <= 1e-9,
            "step {step}: v_y = {:e}",
            b.velocity[1]
        );
        if stopped.is_none() && b.velocity().length() < 1e-9 {
            stopped = Some(step);
        }
    }
    let want = v0 * v0 / (2.0 * mu * g);
    let got = worlds[0].bodies[1].position[0] - x0;
    assert!(stopped.is_some(), "still sliding");
    assert!(
        ((got - want) / want).abs() < 0.02,
        "slid {got} m, Coulomb {want} m"
    );
}

/// 20° with μ = 0.5 (tan θ = 0.36 < μ): the box sticks, moving less than
/// 0.01 mm in 2 s. 30° with μ = 0.3 (tan θ = 0.58 > μ): it slides with
/// a = g (sin θ − μ cos θ) = 2.356 m/s², within 2% after 1 s.
#[test]
fn a_box_on_an_incline_sticks_or_slides_as_coulomb_says() {
    let mut worlds = vec![incline(20f64.to_radians(), 0.5, 0.5)];
    let x0 = worlds[0].bodies[1].position();
    let mut solver = cpu();
    for step in 0..200 {
        let r = solver.step_worlds(&mut worlds, 0.01).unwrap();
        assert_eq!(r.unsolved, 0, "step {step}");
    }
    let moved = (worlds[0].bodies[1].position() - x0).length();
    assert!(moved < 1e-5, "stuck box moved {moved} m");

    let (theta, mu, g) = (30f64.to_radians(), 0.3, 9.81);
    let mut worlds = vec![incline(theta, mu, 0.5)];
    let mut solver = cpu();
    for step in 0..100 {
        let r = solver.step_worlds(&mut worlds, 0.01).unwrap();
        assert_eq!(r.unsolved, 0, "step {step}");
    }
    let down = DVec3::new(-theta.cos(), -theta.sin(), 0.0);
    let v = worlds[0].bodies[1].velocity().dot(down);
    let want = g * (theta.sin() - mu * theta.cos()) * 1.0;
    assert!(
        ((v - want) / want).abs() < 0.02,
        "v = {v} m/s, want {want} m/s"
    );
    let normal = DVec3::new(-theta.sin(), theta.cos(), 0.0);
    assert!(worlds[0].bodies[1].velocity().dot(normal).abs() < 1e-9);
}

/// Five unit boxes with μ = 0.5 rest for 1,000 steps: every island solved,
/// every box moves less than 1 mm and none gains kinetic energy beyond 1e-9 J.
#[test]
fn a_stack_with_friction_stays_at_rest() {
    let mut worlds = vec![standard_world(WorldKind::Stack, 5, 0)];
    let start: Vec<DVec3> = worlds[0].bodies.iter().map(|b| b.position()).collect();
    let mut solver = cpu();
    for step in 0..1000 {
        let r = solver.step_worlds(&mut worlds, 0.01).unwrap();
        assert_eq!(r.unsolved, 0, "step {step}");
        for (k, b) in worlds[0].bodies.iter().enumerate().skip(1) {
            assert!(b.kinetic_energy() < 1e-9, "step {step}, box {k}");
        }
    }
    for (k, b) in worlds[0].bodies.iter().enumerate().skip(1) {
        let drift = (b.position() - start[k]).length();
        assert!(drift < 1e-3, "box {k} drifted {drift} m");
    }
}

/// A resting pyramid of ten boxes (one island of 88 contacts, y up: its
/// side normals have n.z = ±0 or a rounding's −6e-19) keeps its tangent
/// frames from step to step, so that last step's reactions start the next
/// step within reach: after the cold first step, over 99 steps, every
/// island is solved within 1e-12 from its warm start, none repaired, in at
/// most 300 iterations in all (stick steps: its contacts on the edge of
/// their cones and its faint sliding ones taken through W's rows; 147
/// measured). With frames that flipped with the sign of n.z these steps
/// took 627 (14–48 NSGS sweeps and Levenberg–Marquardt steps on 25 steps).
#[test]
fn a_resting_pyramid_is_solved_from_its_warm_start_in_a_few_steps() {
    let mut worlds = vec![standard_world(WorldKind::Pyramid, 4, 0)];
    let mut solver = cpu();
    let mut iterations = Vec::new();
    for step in 0..100 {
        let r = solver.step_worlds(&mut worlds, 0.01).unwrap();
        assert_eq!(r.unsolved, 0, "step {step}");
        assert_eq!(r.solve.friction.len(), 1, "step {step}: one island");
        let island = &r.solve.friction[0];
        assert!(island.error() <= 1e-12, "step {step}");
        if step > 0 {
            assert!(island.warm_started, "step {step}");
            iterations.push(island.solution.iterations);
        }
    }
    let all: u64 = iterations.iter().sum();
    assert!(all <= 300, "{all} iterations: {iterations:?}");
}

/// Frictional worlds stepped on 1, 2 and 3 threads: bit for bit the same
/// worlds and the same reports (each world is solved on its own, warm
/// start from its own memory, whatever thread steps it). The rain (more
/// than one chunk of worlds) falls, touches and slides with μ > 0; each
/// step's solved frictional islands are within 1e-12 and reported in world
/// order (an unsolved one, repaired, counts the same on every thread count).
#[test]
fn frictional_worlds_step_the_same_on_any_thread_count() {
    let make = || -> Vec<crate::World> {
        (0..40)
            .map(|k| match k % 3 {
                0 => standard_world(WorldKind::Stack, 3, k),
                1 => standard_world(WorldKind::Rain, 8, k),
                _ => standard_world(WorldKind::Slide, 1, k),
            })
            .collect()
    };
    let run = |threads: usize| {
        let mut worlds = make();
        let mut solver = Solver::new(Settings {
            threads,
            ..cpu().settings().clone()
        })
        .unwrap();
        let mut coulomb = Vec::new();
        for _ in 0..60 {
            let r = solver.step_worlds(&mut worlds, 0.01).unwrap();
            for (k, s) in r.solve.scenes.iter().enumerate() {
                if let Some(f) = &s.friction {
                    let own = &r.solve.friction[f.islands.clone()];
                    assert!(own.iter().all(|i| i.scene == Some(k)));
                    let mut solved = own.iter().filter(|i| i.status().is_solution());
                    assert!(solved.all(|i| i.error() <= 1e-12));
                }
            }
            coulomb.push((r.solve.friction.len(), r.unsolved));
        }
        (worlds, coulomb)
    };
    let one = run(1);
    assert!(one.1.iter().all(|&(n, _)| n > 0), "islands with friction");
    for threads in [2, 3] {
        assert!(run(threads) == one, "{threads} threads");
    }
}
