//! `lcpbatch::gradient::scene_vjp`: ∂L/∂(bodies, contacts) against central
//! differences of `Solver::solve_scenes` outputs, a closed form, and the
//! errors.

use glam::DVec3;

use crate::generate::{random_island, seed_chain, Rng};
use crate::gradient::{scene_vjp, Derivative, SceneGradient};
use crate::report::BodyVelocity;
use crate::settings::{Backend, Method, Settings};
use crate::{Body, Contact, Report, Scene, Solver};

const STEP: f64 = 1e-6;

fn solve(scene: &Scene) -> Report {
    Solver::new(Settings::new(Backend::Cpu, Method::Enumeration))
        .unwrap()
        .solve_scenes(std::slice::from_ref(scene))
        .unwrap()
}

/// L = Σ gz·impulses + Σ gv·(velocities after), and which contacts push.
fn loss(scene: &Scene, gz: &[f64], gv: &[BodyVelocity]) -> (f64, Vec<bool>) {
    let r = solve(scene);
    let s = &r.scenes[0];
    let big = s.impulses.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    let mut l: f64 = s.impulses.iter().zip(gz).map(|(a, b)| a * b).sum();
    for (b, g) in s.bodies.iter().zip(gv) {
        let v = b.velocity.iter().chain(&b.angular_velocity);
        l += v
            .zip(g.velocity.iter().chain(&g.angular_velocity))
            .map(|(a, b)| a * b)
            .sum::<f64>();
    }
    (l, s.impulses.iter().map(|&z| z > 1e-9 * big).collect())
}

/// A parameter of the scene: how to move it by h, and the gradient's
/// directional derivative along that move.
type Param = (String, Box<dyn Fn(&mut Scene, f64)>, f64);

fn params(scene: &Scene, g: &SceneGradient) -> Vec<Param> {
    let mut out: Vec<Param> = Vec::new();
    for (x, b) in scene.bodies.iter().enumerate() {
        let gb = g.bodies[x].clone();
        for d in 0..3 {
            out.push((
                format!("body {x} velocity[{d}]"),
                Box::new(move |s, h| s.bodies[x].velocity[d] += h),
                gb.velocity[d],
            ));
            out.push((
                format!("body {x} angular_velocity[{d}]"),
                Box::new(move |s, h| s.bodies[x].angular_velocity[d] += h),
                gb.angular_velocity[d],
            ));
            out.push((
                format!("body {x} position[{d}]"),
                Box::new(move |s, h| s.bodies[x].position[d] += h),
                gb.position[d],
            ));
        }
        if b.is_static() {
            continue;
        }
        out.push((
            format!("body {x} inv_mass"),
            Box::new(move |s, h| s.bodies[x].inv_mass += h),
            gb.inv_mass,
        ));
        for r in 0..3 {
            for c in r..3 {
                // A symmetric move: both entries.
                let want = gb.inv_inertia[r][c] + if r == c { 0.0 } else { gb.inv_inertia[c][r] };
                let mv = move |s: &mut Scene, h: f64| {
                    s.bodies[x].inv_inertia[r][c] += h;
                    if r != c {
                        s.bodies[x].inv_inertia[c][r] += h;
                    }
                };
                out.push((
                    format!("body {x} inv_inertia[{r}][{c}]"),
                    Box::new(mv),
                    want,
                ));
            }
        }
    }
    for (i, c) in scene.contacts.iter().enumerate() {
        let gc = g.contacts[i].clone();
        for d in 0..3 {
            out.push((
                format!("contact {i} point[{d}]"),
                Box::new(move |s, h| s.contacts[i].point[d] += h),
                gc.point[d],
            ));
        }
        // The normal moved along its tangents (it stays unit to h²).
        let (t1, t2) = c.tangents();
        for (k, t) in [t1, t2].into_iter().enumerate() {
            let want = DVec3::from_array(gc.normal).dot(t);
            let mv = move |s: &mut Scene, h: f64| {
                s.contacts[i].normal = (s.contacts[i].normal() + h * t).to_array();
            };
            out.push((
                format!("contact {i} normal along t{}", k + 1),
                Box::new(mv),
                want,
            ));
        }
        out.push((
            format!("contact {i} restitution"),
            Box::new(move |s, h| s.contacts[i].restitution += h),
            gc.restitution,
        ));
        out.push((
            format!("contact {i} bias"),
            Box::new(move |s, h| s.contacts[i].bias += h),
            gc.bias,
        ));
    }
    out
}

/// Random islands of 1…6 contacts (mass ratios 1 and 100) and a chain:
/// every parameter's central difference of the solver's outputs equals the
/// gradient (relative error ≤ 1e-5 of the scene's largest), where the
/// contacts that push stay the same within the step; at most 5% skipped.
#[test]
fn scene_vjp_matches_central_differences_of_solve_scenes() {
    let mut rng = Rng::new(0x5CE7E);
    let mut scenes = vec![seed_chain(0.3)];
    for k in 0..30 {
        scenes.push(random_island(&mut rng, 1 + k % 6, [1.0, 100.0][k % 2]));
    }
    let (mut checked, mut flagged, mut skipped, mut total, mut worst) = (0, 0, 0, 0, 0.0f64);
    for (k, scene) in scenes.iter().enumerate() {
        let report = solve(scene);
        let gz: Vec<f64> = scene
            .contacts
            .iter()
            .map(|_| rng.range(-1.0, 1.0))
            .collect();
        let gv: Vec<BodyVelocity> = scene
            .bodies
            .iter()
            .map(|_| BodyVelocity {
                velocity: rng.vector(1.0).to_array(),
                angular_velocity: rng.vector(1.0).to_array(),
            })
            .collect();
        let g = scene_vjp(
            scene,
            &report.scenes[0].impulses,
            Some(&gz),
            Some(&gv),
            1e-8,
        )
        .unwrap();
        let via_report = report
            .scene_vjps(std::slice::from_ref(scene), Some(&[&gz]), Some(&[&gv]))
            .unwrap();
        assert_eq!(via_report[0].bodies, g.bodies);
        assert_eq!(via_report[0].contacts, g.contacts);
        if g.derivative != Derivative::Exact {
            flagged += 1;
            continue;
        }
        let (_, pushing) = loss(scene, &gz, &gv);
        let mut rows = Vec::new();
        for (name, mv, want) in params(scene, &g) {
            let at = |h: f64| {
                let mut s = scene.clone();
                mv(&mut s, h);
                let (l, p) = loss(&s, &gz, &gv);
                (p == pushing).then_some(l)
            };
            total += 1;
            match (at(STEP), at(-STEP)) {
                (Some(a), Some(b)) => rows.push((name, (a - b) / (2.0 * STEP), want)),
                _ => skipped += 1,
            }
        }
        let scale = rows.iter().fold(1e-300f64, |a, r| a.max(r.1.abs()));
        for (name, fd, want) in rows {
            let e = (fd - want).abs() / scale;
            assert!(
                e <= 1e-5,
                "scene {k}, {name}: finite difference {fd}, gradient {want} ({e:.1e})"
            );
            worst = worst.max(e);
        }
        checked += 1;
    }
    eprintln!("{checked} scenes checked, {flagged} not exact; {skipped} of {total} parameters skipped; worst {worst:.2e}");
    assert!(checked >= 20, "{checked}");
    assert!(skipped * 20 <= total, "{skipped} of {total}");
}

/// The crate's doc example: a ball of 1 kg at 1 m/s down onto the ground,
/// restitution ε: z = (1 + ε) m v and v⁺ = ε v, so ∂z/∂ε = 1 and
/// ∂v⁺_y/∂ε = 1; ∂z/∂v_y = −(1 + ε); ∂z/∂m⁻¹ = −(1 + ε) v m² = −1.5.
#[test]
fn a_ball_on_the_ground_in_closed_form() {
    let mut ball = Body::new(1.0, [2.5; 3], [0.0, 0.5, 0.0]);
    ball.velocity = [0.0, -1.0, 0.0];
    let ground = Contact::new(0, None, [0.0; 3], [0.0, 1.0, 0.0], 0.5);
    let scene = Scene {
        bodies: vec![ball],
        contacts: vec![ground],
    };
    let report = solve(&scene);
    let z = &report.scenes[0].impulses;
    let g = scene_vjp(&scene, z, Some(&[1.0]), None, 1e-8).unwrap();
    assert_eq!(g.derivative, Derivative::Exact);
    assert!((g.contacts[0].restitution - 1.0).abs() < 1e-12, "{g:?}");
    assert!((g.bodies[0].velocity[1] + 1.5).abs() < 1e-12, "{g:?}");
    assert!((g.bodies[0].inv_mass + 1.5).abs() < 1e-12, "{g:?}");
    let up = BodyVelocity {
        velocity: [0.0, 1.0, 0.0],
        angular_velocity: [0.0; 3],
    };
    let g = scene_vjp(&scene, z, None, Some(&[up]), 1e-8).unwrap();
    assert!((g.contacts[0].restitution - 1.0).abs() < 1e-12, "{g:?}");
    assert!((g.bodies[0].velocity[1] + 0.5).abs() < 1e-12, "{g:?}");
}

#[test]
fn friction_and_bad_input_are_named() {
    let scene = seed_chain(0.3);
    let z = solve(&scene).scenes[0].impulses.clone();
    let err = |r: Result<SceneGradient, crate::Error>| r.unwrap_err().to_string();
    assert_eq!(
        err(scene_vjp(&scene, &z[1..], None, None, 1e-8)),
        format!(
            "scene 0: field `impulses`: has {} entries, expected {}",
            z.len() - 1,
            z.len()
        )
    );
    let mut bad = z.clone();
    bad[0] = f64::NAN;
    assert_eq!(
        err(scene_vjp(&scene, &z, Some(&bad), None, 1e-8)),
        "scene 0: field `d_impulses[0]`: not a finite number"
    );
    let mut rough = scene.clone();
    rough.contacts[1].friction = 0.5;
    assert_eq!(
        err(scene_vjp(&rough, &z, None, None, 1e-8)),
        "scene 0, contact 1: field `friction`: μ > 0 is not differentiable here: gradients cover frictionless scenes only"
    );
    let report = solve(&scene);
    let e = report.scene_vjps(&[], None, None).unwrap_err().to_string();
    assert_eq!(e, "batch: field `scenes`: has 0 entries, expected 1");
}
