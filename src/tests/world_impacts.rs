//! Impacts at their time of impact (`crate::world::impact`), measured as a
//! physicist would on the bench: an elastic ball keeps its bounce height
//! and its energy, a ball on a ball and Newton's cradle keep theirs, each
//! bounce of a ball with ε < 1 is ε² times as high as the last, no standard
//! world gains energy, the GPU path takes the same impacts, and a fast
//! sphere never passes through a thin wall or another sphere.
//!
//! Energy: the step stores each body's mean velocity over the last step
//! (x₁ = x₀ + Δt v₁), so the energy the report gives, ½ m v² − m g·x,
//! swings by ½ m |g| Δt |v_y| about the energy of the parabola the body
//! follows (below it falling, above it rising; 1.5% for the ball below at
//! Δt = 10 ms, before it touches anything). The tests check that
//! energy, [`flight_energy`] (the velocity at the step's end, v + ½ Δt g),
//! at Δt = 10 ms, and the report's own at Δt = 5 ms, where the swing is
//! below the 1% asked.

use glam::DVec3;

use crate::settings::{Backend, Method, Settings};
use crate::world::generate::{standard_world, WorldKind};
use crate::world::{RigidBody, Shape, World, WorldStepReport};
use crate::Solver;

use super::world::{cpu, ground};

/// A sphere of 1,000 kg/m³, frictionless, restitution `eps`.
fn sphere(radius: f64, centre: [f64; 3], eps: f64) -> RigidBody {
    RigidBody {
        mass: None,
        density: Some(1000.0),
        restitution: eps,
        ..RigidBody::new(Shape::Sphere { radius }, centre, 0.0)
    }
}

/// The ball: radius 0.5 m, its surface `drop` m above the ground.
fn dropped_ball(drop: f64, eps: f64) -> World {
    World::new(
        [0.0, -9.81, 0.0],
        vec![ground(), sphere(0.5, [0.0, 0.5 + drop, 0.0], eps)],
    )
}

/// The energy of the motion the step follows: each body's velocity at the
/// step's end (v + ½ Δt g for a body that moves) in the kinetic energy.
fn flight_energy(w: &World, dt: f64) -> f64 {
    let g = w.gravity();
    let kinetic: f64 = (w.bodies.iter().filter(|b| !b.fixed))
        .map(|b| {
            let end = RigidBody {
                velocity: (b.velocity() + g * (0.5 * dt)).to_array(),
                ..b.clone()
            };
            end.kinetic_energy()
        })
        .sum();
    kinetic + w.potential_energy()
}

/// Steps `w` alone `steps` times; per step its report and the world after.
fn run(w: World, dt: f64, steps: usize) -> Vec<(WorldStepReport, World)> {
    let mut worlds = vec![w];
    let mut solver = cpu();
    (0..steps)
        .map(|_| {
            let r = solver.step_worlds(&mut worlds, dt).unwrap();
            (r.worlds[0], worlds[0].clone())
        })
        .collect()
}

/// Largest relative departure of `e` from `e0`, and where.
fn worst(e0: f64, e: impl Iterator<Item = f64>) -> (f64, usize) {
    e.map(|x| ((x - e0) / e0).abs())
        .enumerate()
        .fold((0.0, 0), |m, (i, d)| if d > m.0 { (d, i) } else { m })
}

/// The apexes of body `k`'s height: the top of the parabola through the
/// three samples around each local maximum (the step's positions lie on
/// the body's parabola between impacts, so this is its apex).
fn apexes(run: &[(WorldStepReport, World)], k: usize) -> Vec<f64> {
    let y: Vec<f64> = run.iter().map(|(_, w)| w.bodies[k].position[1]).collect();
    (1..y.len() - 1)
        .filter(|&i| y[i] >= y[i - 1] && y[i] > y[i + 1])
        .map(|i| {
            let (a, b, c) = (y[i - 1], y[i], y[i + 1]);
            b + (c - a) * (c - a) / (8.0 * (2.0 * b - a - c))
        })
        .collect()
}

/// The ball (r 0.5 m, 1,000 kg/m³, ε = 1, μ = 0, dropped 0.5 m,
/// Δt = 10 ms) bounces for 1,000 steps: every apex at the start height
/// within 1% (it gained 3 cm, +3%, at each bounce before), the energy of
/// its motion within 1% at every step; at Δt = 5 ms the reported energy
/// too. Each bounce is one impact at its time.
#[test]
fn an_elastic_ball_keeps_its_height_and_energy() {
    let dt = 0.01;
    let steps = run(dropped_ball(0.5, 1.0), dt, 1000);
    let tops = apexes(&steps, 1);
    assert!(tops.len() >= 14, "{tops:?}");
    for (i, top) in tops.iter().enumerate() {
        assert!((top - 1.0).abs() < 0.01, "apex {i}: {top} m (from 1 m)");
    }
    let e0 = flight_energy(&dropped_ball(0.5, 1.0), dt);
    let (d, at) = worst(e0, steps.iter().map(|(_, w)| flight_energy(w, dt)));
    assert!(d < 0.01, "step {at}: {d:e}");
    let impacts: usize = steps.iter().map(|(r, _)| r.impacts).sum();
    assert_eq!(impacts, tops.len() + 1, "one impact per bounce");
    assert!(steps.iter().all(|(r, _)| r.impacts_deferred == 0));

    let dt = 0.005;
    let w = dropped_ball(0.5, 1.0);
    let e0 = w.kinetic_energy() + w.potential_energy();
    let steps = run(w, dt, 1000);
    let (d, at) = worst(e0, steps.iter().map(|(r, _)| r.kinetic + r.potential));
    assert!(d < 0.01, "Δt = 5 ms, step {at}: {d:e}");
}

/// A ball dropped 0.5 m onto a ball resting on the ground (both ε = 1,
/// μ = 0, equal): each bounce passes through the lower ball to the ground
/// and back within one step (three impacts); over 1,000 steps the upper
/// ball's apexes stay at its start and the energy within 1%.
#[test]
fn a_ball_on_a_ball_keeps_its_energy() {
    let make = || {
        World::new(
            [0.0, -9.81, 0.0],
            vec![
                ground(),
                sphere(0.5, [0.0, 0.5, 0.0], 1.0),
                sphere(0.5, [0.0, 2.0, 0.0], 1.0),
            ],
        )
    };
    let dt = 0.01;
    let steps = run(make(), dt, 1000);
    let tops = apexes(&steps, 2);
    assert!(tops.len() >= 10, "{tops:?}");
    for (i, top) in tops.iter().enumerate() {
        assert!((top - 2.0).abs() < 0.02, "apex {i}: {top} m (from 2 m)");
    }
    let e0 = flight_energy(&make(), dt);
    let (d, at) = worst(e0, steps.iter().map(|(_, w)| flight_energy(w, dt)));
    assert!(d < 0.01, "step {at}: {d:e}");
    assert!(
        steps.iter().any(|(r, _)| r.impacts >= 3),
        "a chain in a step"
    );
    let w = make();
    let e0 = w.kinetic_energy() + w.potential_energy();
    let steps = run(w, 0.005, 1000);
    let (d, at) = worst(e0, steps.iter().map(|(r, _)| r.kinetic + r.potential));
    assert!(d < 0.01, "Δt = 5 ms, step {at}: {d:e}");
}

/// Newton's cradle: 5 touching spheres (r 0.1 m, ε = 1, μ = 0) on the
/// ground, a sixth rolling in at 1 m/s: in one step the impact runs through
/// the row (5 impacts) and the last sphere leaves at 1 m/s while the others
/// stay; the energy stays within 1% for 1,000 steps.
#[test]
fn newtons_cradle_passes_the_impact_through() {
    let r = 0.1;
    let mut bodies = vec![ground()];
    let mut first = sphere(r, [-0.3, r, 0.0], 1.0);
    first.velocity = [1.0, 0.0, 0.0];
    bodies.push(first);
    bodies.extend((0..5).map(|k| sphere(r, [2.0 * r * k as f64, r, 0.0], 1.0)));
    let w = World::new([0.0, -9.81, 0.0], bodies);
    let e0 = w.kinetic_energy() + w.potential_energy();
    let steps = run(w, 0.01, 1000);
    let (d, at) = worst(e0, steps.iter().map(|(r, _)| r.kinetic + r.potential));
    assert!(d < 0.01, "step {at}: {d:e}");
    let most = steps.iter().map(|(r, _)| r.impacts).max().unwrap();
    assert_eq!(most, 5, "the row's impacts in one step");
    let end = &steps.last().unwrap().1;
    let vx: Vec<f64> = end.bodies[1..].iter().map(|b| b.velocity[0]).collect();
    assert!((vx[5] - 1.0).abs() < 1e-6, "{vx:?}");
    assert!(vx[..5].iter().all(|v| v.abs() < 1e-6), "{vx:?}");
}

/// A ball with ε = 0.5 and 0.8 dropped 0.5 m: each bounce's height (apex of
/// the centre above its resting height) is ε² times the last within 2%,
/// while it is higher than 5 steps' fall (½ g (5 Δt)² = 1.2 cm).
#[test]
fn each_bounce_is_eps_squared_as_high_as_the_last() {
    let dt = 0.01;
    let low = 0.5 * 9.81 * (5.0 * dt) * (5.0 * dt);
    for (eps, count) in [(0.5, 2), (0.8, 7)] {
        let steps = run(dropped_ball(0.5, eps), dt, 500);
        let mut heights = vec![0.5];
        heights.extend(apexes(&steps, 1).iter().map(|y| y - 0.5));
        let pairs: Vec<(f64, f64)> = heights
            .windows(2)
            .map(|h| (h[0], h[1]))
            .take_while(|&(_, h)| h > low)
            .collect();
        assert!(pairs.len() >= count, "ε {eps}: {heights:?}");
        for (i, (a, b)) in pairs.into_iter().enumerate() {
            let ratio = b / a / (eps * eps);
            assert!((ratio - 1.0).abs() < 0.02, "ε {eps} bounce {i}: {a} -> {b}");
        }
    }
}

/// Every standard world kind, every body's ε 0.5 (rain: as generated, up to
/// 0.3), with its friction and frictionless, 300 steps of 10 ms: the total
/// energy never rises more than 1% above its start.
#[test]
fn no_standard_world_gains_energy() {
    for (kind, name) in WorldKind::ALL {
        for mu in [None, Some(0.0)] {
            let mut w = standard_world(kind, kind.default_size(), 5);
            for b in &mut w.bodies {
                if kind != WorldKind::Rain {
                    b.restitution = 0.5;
                }
                if let Some(mu) = mu {
                    b.friction = mu;
                }
            }
            let e0 = w.kinetic_energy() + w.potential_energy();
            let steps = run(w, 0.01, 300);
            for (step, (r, _)) in steps.iter().enumerate() {
                let e = r.kinetic + r.potential;
                assert!(
                    e <= e0 + 0.01 * e0.abs(),
                    "{name} μ {mu:?} step {step}: {e} > {e0}"
                );
            }
        }
    }
}

/// The GPU path (its twin) takes the same impacts: an elastic ball, a ball
/// with ε = 0.8, Newton's cradle and a frictionless rain of 8 stepped 150
/// times on each, positions within 1e-9 m and the same impacts every step.
#[test]
fn the_gpu_path_takes_the_same_impacts() {
    let Some(gpu) = super::common::gpu_settings_or_skip() else {
        return;
    };
    let make = || {
        let mut rain = standard_world(WorldKind::Rain, 8, 3);
        rain.bodies.iter_mut().for_each(|b| b.friction = 0.0);
        let mut cradle = vec![ground()];
        let mut first = sphere(0.1, [-0.3, 0.1, 0.0], 1.0);
        first.velocity = [1.0, 0.0, 0.0];
        cradle.push(first);
        cradle.extend((0..5).map(|k| sphere(0.1, [0.2 * k as f64, 0.1, 0.0], 1.0)));
        let cradle = World::new([0.0, -9.81, 0.0], cradle);
        vec![dropped_ball(0.5, 1.0), dropped_ball(0.5, 0.8), cradle, rain]
    };
    let (mut on_gpu, mut on_cpu) = (make(), make());
    let settings = Settings::new(Backend::Gpu, Method::Enumeration);
    let mut g = Solver::new(Settings { gpu, ..settings }).unwrap();
    let mut c = cpu();
    let mut impacts = 0;
    for step in 0..150 {
        let rg = g.step_worlds(&mut on_gpu, 0.01).unwrap();
        let rc = c.step_worlds(&mut on_cpu, 0.01).unwrap();
        let counts =
            |r: &crate::world::StepReport| r.worlds.iter().map(|w| w.impacts).collect::<Vec<_>>();
        assert_eq!(counts(&rg), counts(&rc), "step {step}");
        impacts += counts(&rg).iter().sum::<usize>();
    }
    assert!(impacts > 8, "{impacts}");
    let bodies = |w: &[World]| w.iter().flat_map(|w| w.bodies.clone()).collect::<Vec<_>>();
    let apart = (bodies(&on_gpu).iter().zip(&bodies(&on_cpu)))
        .map(|(a, b)| (a.position() - b.position()).length())
        .fold(0.0, f64::max);
    assert!(apart < 1e-9, "{apart} m apart");
}

/// A sphere of radius 5 cm at 100 m/s (1 m per 10 ms step, no gravity)
/// against a fixed wall 4 cm thick and against a resting sphere of its
/// size, with ε = 0 (speculative contacts stop it) and ε = 1 (an impact at
/// its time): it never passes through. At the wall it stops or bounces
/// back at 100 m/s; the sphere takes half its momentum (both at 50 m/s)
/// or all of it (velocities exchanged).
#[test]
fn a_fast_sphere_never_passes_a_thin_wall_or_a_sphere() {
    let (r, speed, dt) = (0.05, 100.0, 0.01);
    for eps in [0.0, 1.0] {
        let mut ball = sphere(r, [-1.0, 0.0, 0.0], eps);
        ball.velocity = [speed, 0.0, 0.0];
        let wall = RigidBody::fixed(
            Shape::Box {
                half_extents: [0.02, 1.0, 1.0],
            },
            [0.0; 3],
        );
        let steps = run(World::new([0.0; 3], vec![wall, ball.clone()]), dt, 50);
        for (step, (_, w)) in steps.iter().enumerate() {
            let x = w.bodies[1].position[0];
            assert!(x + r <= -0.02 + 1e-9, "ε {eps} step {step}: at {x}");
        }
        let v = steps.last().unwrap().1.bodies[1].velocity();
        let expect = DVec3::new(-eps * speed, 0.0, 0.0);
        assert!((v - expect).length() < 1e-6, "ε {eps}: {v}");

        let target = sphere(r, [0.0; 3], eps);
        let steps = run(World::new([0.0; 3], vec![ball, target]), dt, 50);
        for (step, (_, w)) in steps.iter().enumerate() {
            let (a, b) = (w.bodies[0].position(), w.bodies[1].position());
            assert!(b.x - a.x >= 2.0 * r - 1e-9, "ε {eps} step {step}: {a} {b}");
        }
        let end = &steps.last().unwrap().1;
        let (va, vb) = (end.bodies[0].velocity[0], end.bodies[1].velocity[0]);
        let (ea, eb) = (0.5 * (1.0 - eps) * speed, 0.5 * (1.0 + eps) * speed);
        assert!(
            (va - ea).abs() < 1e-6 && (vb - eb).abs() < 1e-6,
            "ε {eps}: {va} {vb}"
        );
    }
}
