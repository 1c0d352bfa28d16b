//! Impulse application: the bodies' velocities after the impact. CPU twin of
//! `shaders/impulses.wgsl`, in f64.
//!
//! Contact i with impulse z_i changes body a by z_i·(m_a⁻¹ n_i, I_a⁻¹(r_a × n_i))
//! and body b by the opposite (its `response` row from assembly). Then for an
//! active contact (z_i > 0, w_i = 0) the relative normal velocity after the
//! impact is v_rel + (M z)_i = w_i − ε min(v_rel, 0): −ε v_rel when it was
//! approaching, 0 when it was separating.

// `relative_normal_velocities` serves the physics tests (Newton's law).
#![cfg_attr(not(test), allow(dead_code))]

use glam::DVec3;

use crate::cpu::assembly::ContactRow;
use crate::scene::{Contact, Scene};

/// A body's velocities after the impact.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct BodyVelocity {
    /// Linear velocity of the centre of mass.
    pub velocity: [f64; 3],
    /// Angular velocity (world frame).
    pub angular_velocity: [f64; 3],
}

/// Applies the impulses `z` (one per contact of the scene) to every body.
pub fn apply_impulses(scene: &Scene, rows: &[ContactRow], z: &[f64]) -> Vec<BodyVelocity> {
    let pushes = scene
        .contacts
        .iter()
        .zip(rows)
        .zip(z)
        .map(|((c, row), &zi)| (c, &row.response, zi));
    velocities_after(scene, pushes)
}

/// The bodies' velocities after impulses given as (contact, the row's
/// M⁻¹Jᵀ, impulse along the row): body a gains z times the a blocks of the
/// response, body b the b blocks (already negative). The frictional path
/// passes three rows per contact (n, t₁, t₂).
pub(crate) fn velocities_after<'a>(
    scene: &Scene,
    pushes: impl Iterator<Item = (&'a Contact, &'a [f64; 12], f64)>,
) -> Vec<BodyVelocity> {
    let mut v: Vec<(DVec3, DVec3)> = scene
        .bodies
        .iter()
        .map(|b| (b.velocity(), b.angular_velocity()))
        .collect();
    for (c, r, zi) in pushes {
        if zi == 0.0 {
            continue;
        }
        let block = |at: usize| DVec3::new(r[at], r[at + 1], r[at + 2]);
        v[c.a].0 += block(0) * zi;
        v[c.a].1 += block(3) * zi;
        if let Some(b) = c.b {
            v[b].0 += block(6) * zi;
            v[b].1 += block(9) * zi;
        }
    }
    v.into_iter()
        .map(|(lin, ang)| BodyVelocity {
            velocity: lin.to_array(),
            angular_velocity: ang.to_array(),
        })
        .collect()
}

/// Relative normal velocity of every contact from the given body velocities:
/// (ṗ_a − ṗ_b)·n with ṗ = v + ω × r.
pub fn relative_normal_velocities(scene: &Scene, velocities: &[BodyVelocity]) -> Vec<f64> {
    scene
        .contacts
        .iter()
        .map(|c| {
            let p = c.point();
            let pdot = |i: usize| {
                let v = &velocities[i];
                DVec3::from_array(v.velocity)
                    + DVec3::from_array(v.angular_velocity).cross(p - scene.bodies[i].position())
            };
            let mut d = pdot(c.a);
            if let Some(b) = c.b {
                d -= pdot(b);
            }
            d.dot(c.normal())
        })
        .collect()
}
