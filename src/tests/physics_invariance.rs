//! Physics of the impact, invariances: a rigid motion of the scene, a
//! contact's bodies swapped with its normal flipped, velocities scaled or
//! shifted by a common drift change the impulses as they must.

use super::common;
use super::common::{inf_norm, settings};
use super::physics::*;
use crate::cpu::impulses::BodyVelocity;
use crate::generate::{ball_body, box_body, random_island, random_scene, Rng};
use crate::islands::find_islands;
use crate::settings::Method;
use crate::tests::reference::{build, solve_scene};
use crate::{Scene, Status};
use glam::{DMat3, DVec3};

/// Impulses of a scene through the pipeline (enumeration), checked solved.
fn impulses(scene: &Scene) -> (Vec<f64>, Vec<BodyVelocity>) {
    let mut sol = solve_scene(scene, &settings(Method::Enumeration)).unwrap();
    assert!(sol.islands.iter().all(|i| i.solution.status.is_solution()));
    let s = sol.scenes.swap_remove(0);
    (s.impulses, s.bodies)
}

fn rotate(r: DMat3, v: [f64; 3]) -> [f64; 3] {
    (r * DVec3::from_array(v)).to_array()
}

#[test]
fn a_rigid_motion_of_the_scene_changes_nothing_but_the_frame() {
    // Rotating and translating every position, point, normal, velocity and
    // inverse inertia (R I⁻¹ Rᵀ) gives the same impulses and rotated velocities.
    let mut rng = Rng::new(29);
    for k in 0..1000 {
        let scene = random_scene(&mut rng, 2, 6, 100.0);
        let (r, t) = (rng.rotation(), rng.vector(10.0));
        let mut moved = scene.clone();
        for b in &mut moved.bodies {
            b.position = (r * b.position() + t).to_array();
            b.velocity = rotate(r, b.velocity);
            b.angular_velocity = rotate(r, b.angular_velocity);
            let inv = r * b.inv_inertia_mat() * r.transpose();
            b.inv_inertia = inv.transpose().to_cols_array_2d();
        }
        for c in &mut moved.contacts {
            c.point = (r * c.point() + t).to_array();
            c.normal = rotate(r, c.normal);
        }
        let (z0, v0) = impulses(&scene);
        let (z1, v1) = impulses(&moved);
        let zs = inf_norm(&z0).max(1e-300);
        assert!(
            common::max_diff(&z0, &z1) <= 1e-9 * zs,
            "scene {k}: {z0:?} vs {z1:?}"
        );
        for (a, b) in v0.iter().zip(&v1) {
            let va = DVec3::from_array(rotate(r, a.velocity));
            let wa = DVec3::from_array(rotate(r, a.angular_velocity));
            let scale = va.length().max(wa.length()).max(1.0);
            assert!(
                (va - DVec3::from_array(b.velocity)).length() <= 1e-9 * scale,
                "scene {k}"
            );
            assert!(
                (wa - DVec3::from_array(b.angular_velocity)).length() <= 1e-9 * scale,
                "scene {k}"
            );
        }
    }
}

#[test]
fn swapping_a_contacts_bodies_and_flipping_its_normal_changes_nothing() {
    // (a, b, n) and (b, a, −n) are the same contact: J changes sign, so M and
    // v_rel do not. World contacts become contacts with a static body.
    let mut rng = Rng::new(31);
    for k in 0..1000 {
        let scene = random_island(&mut rng, 1 + k % 8, 100.0);
        let mut flipped = scene.clone();
        let world = flipped.bodies.len();
        flipped.bodies.push(crate::Body::fixed([0.0, -3.0, 0.0]));
        for c in &mut flipped.contacts {
            let b = c.b.unwrap_or(world);
            c.b = Some(c.a);
            c.a = b;
            c.normal = (-c.normal()).to_array();
        }
        let (z0, v0) = impulses(&scene);
        let (z1, v1) = impulses(&flipped);
        let zs = inf_norm(&z0).max(1e-300);
        assert!(
            common::max_diff(&z0, &z1) <= 1e-9 * zs,
            "island {k}: {z0:?} vs {z1:?}"
        );
        for (a, b) in v0.iter().zip(&v1) {
            assert!(
                common::max_diff(&a.velocity, &b.velocity) <= 1e-9 * inf_norm(&a.velocity).max(1.0)
            );
        }
        assert_eq!(v1[world].velocity, [0.0; 3], "the static body stays put");
    }
}

#[test]
fn impulses_scale_with_velocities_and_ignore_a_common_drift() {
    let mut rng = Rng::new(37);
    for k in 0..1000 {
        // Body–body contacts only, so that a common velocity changes no v_rel.
        let mut scene = random_island(&mut rng, 1 + k % 8, 100.0);
        scene.contacts.retain(|c| c.b.is_some());
        if scene.contacts.is_empty() {
            continue;
        }
        let (z0, _) = impulses(&scene);
        let zs = inf_norm(&z0).max(1e-300);
        // Every velocity × s: every v_rel and q × s, z × s.
        for s in [1e-6, 3.0, 1e6] {
            let mut scaled = scene.clone();
            for b in &mut scaled.bodies {
                b.velocity = b.velocity.map(|v| v * s);
                b.angular_velocity = b.angular_velocity.map(|v| v * s);
            }
            let (z1, _) = impulses(&scaled);
            let back: Vec<f64> = z1.iter().map(|z| z / s).collect();
            assert!(
                common::max_diff(&z0, &back) <= 1e-9 * zs,
                "island {k}, s = {s}"
            );
        }
        let drift = rng.vector(5.0);
        let mut drifting = scene.clone();
        for b in &mut drifting.bodies {
            b.velocity = (b.velocity() + drift).to_array();
        }
        let (z1, _) = impulses(&drifting);
        assert!(
            common::max_diff(&z0, &z1) <= 1e-9 * zs.max(drift.length()),
            "island {k}: {z0:?} vs {z1:?}"
        );
    }
}

#[test]
fn pinned_bodies_couple_their_contacts() {
    // A body with inv_mass 0 but a finite inertia (pinned at its centre) can
    // still turn, so it couples the contacts that touch it: one island.
    let mut pinned = box_body(1.0, DVec3::splat(0.5), DMat3::IDENTITY, DVec3::ZERO);
    pinned.inv_mass = 0.0;
    pinned.angular_velocity = [0.0, 0.0, 1.0];
    let mut left = ball_body(1.0, 0.25, DVec3::new(-0.75, 0.4, 0.0));
    let mut right = ball_body(2.0, 0.25, DVec3::new(0.75, -0.4, 0.0));
    left.velocity = [0.0, -1.0, 0.0];
    right.velocity = [0.0, 1.0, 0.0];
    let scene = Scene {
        bodies: vec![pinned, left, right],
        contacts: vec![
            contact(1, Some(0), DVec3::new(-0.5, 0.4, 0.0), -DVec3::X, 0.3),
            contact(2, Some(0), DVec3::new(0.5, -0.4, 0.0), DVec3::X, 0.3),
            contact(1, None, DVec3::new(-0.75, 0.15, 0.0), DVec3::Y, 0.3),
        ],
    };
    assert_eq!(find_islands(&scene).len(), 1);
    whole_equals_islands(&scene, "pinned");
    let lcp = &build(&scene, "p").unwrap().2[0];
    assert!(
        lcp.at(0, 1) != 0.0,
        "the pinned body couples contacts 0 and 1"
    );
}

#[test]
fn islands_beyond_the_enumeration_limit_go_to_lemke() {
    // Enumeration takes n ≤ 20; the pipeline hands larger islands to Lemke
    // and says so, and the result is still a solution.
    let mut rng = Rng::new(41);
    for n in [21, 24, 30] {
        let scene = random_island(&mut rng, n, 100.0);
        let sol = solve_scene(&scene, &settings(Method::Enumeration)).unwrap();
        assert_eq!(sol.islands.len(), 1);
        let isl = &sol.islands[0];
        assert_eq!(isl.contacts.len(), n);
        assert_eq!(isl.method, Method::Lemke, "n = {n}");
        assert_eq!(isl.solution.status, Status::Solved, "n = {n}");
        assert!(
            isl.solution.residuals.error <= 1e-12,
            "n = {n}: {:?}",
            isl.solution.residuals
        );
    }
    // At n = 20 enumeration itself runs.
    let scene = random_island(&mut rng, 20, 100.0);
    let sol = solve_scene(&scene, &settings(Method::Enumeration)).unwrap();
    assert_eq!(sol.islands[0].method, Method::Enumeration);
    assert!(sol.islands[0].solution.status.is_solution());
}

#[test]
fn a_wedged_ball_with_restitution_has_no_newton_solution() {
    // A ball touching two parallel walls (normals +x and −x), moving toward
    // the left one. Newton's law asks it to leave the left wall at ε·v, which
    // the right wall forbids: with d = (1, 1), J d = 0 (M d = 0) and
    // dᵀq = −ε v < 0, so no z ≥ 0 makes w ≥ 0. With ε = 0 it simply stops.
    let mut ball = ball_body(1.0, 0.5, DVec3::ZERO);
    ball.velocity = [-2.0, 0.0, 0.0];
    let walls = |e: f64| Scene {
        bodies: vec![ball.clone()],
        contacts: vec![
            contact(0, None, DVec3::new(-0.5, 0.0, 0.0), DVec3::X, e),
            contact(0, None, DVec3::new(0.5, 0.0, 0.0), -DVec3::X, e),
        ],
    };
    let sol = solve_scene(&walls(0.5), &settings(Method::Enumeration)).unwrap();
    assert_eq!(sol.islands[0].solution.status, Status::NoSolution);
    assert_eq!(sol.scenes[0].impulses, vec![0.0, 0.0]);
    assert_eq!(
        sol.scenes[0].bodies[0].velocity,
        [-2.0, 0.0, 0.0],
        "unchanged, not NaN"
    );
    let sol = solve_scene(&walls(0.5), &settings(Method::Lemke)).unwrap();
    assert_eq!(sol.islands[0].solution.status, Status::RayTermination);
    assert!(sol.scenes[0].bodies[0]
        .velocity
        .iter()
        .all(|v| v.is_finite()));
    // ε = 0: it stops dead (a continuum of impulse pairs, one velocity).
    for s in [Method::Enumeration, Method::Lemke, Method::Pgs] {
        let sol = solve_scene(&walls(0.0), &settings(s)).unwrap();
        assert!(sol.islands[0].solution.status.is_solution(), "{}", s.name());
        assert!(
            sol.scenes[0].bodies[0].velocity[0].abs() < 1e-9,
            "{}: {:?}",
            s.name(),
            sol.scenes[0].bodies[0]
        );
    }
}
