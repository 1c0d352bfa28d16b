//! The step's parts that belong to one world (a semi-implicit time step of
//! the contact DVI: Stewart & Trinkle 1996, Anitescu & Potra 1997);
//! [`crate::Solver::step_worlds`] runs them for a batch:
//!
//! 1. [`prepare`]: v* = v + Δt g for the awake dynamic bodies; contacts from
//!    collision with the signed gap φ; the frictionless bounces taken at
//!    their time of impact ([`super::impact`]); a [`Scene`] whose contacts carry the
//!    bias φ/Δt, so that the door's LCP w = Mγ + q ≥ 0 ⊥ γ ≥ 0 with
//!    q = J v* + φ/Δt is the time-stepping condition 0 ≤ γ_n ⊥ φ/Δt + v_n⁺ ≥ 0
//!    (the gap φ + Δt v_n⁺ at the step's end is ≥ 0, and an impulse acts only
//!    where it is 0).
//! 2. The door solves every world's islands in one batch.
//! 3. [`finish`]: v ← the door's velocities after the impulses; x += Δt v;
//!    q ← normalise(q + ½ Δt (ω, 0) ⊗ q); sleep counters.
//!
//! # The gap and restitution
//! A contact that is not bouncing gets ε = 0 and b = φ/Δt: a gap φ > 0 may
//! close within the step but not overshoot (speculative contact: no impulse
//! unless the body would pass the surface), and a penetration φ < 0 is
//! removed in one step (−φ/Δt). This is the DVI of the seed, not a
//! Baumgarte spring: no stiffness and no tuning factor; what it adds is the
//! velocity −φ/Δt, bounded by the penetration left by the linearised
//! contact (rotations), which is small at rest (tests measure it).
//!
//! A frictionless contact that bounces (the pair's ε > 0, closing faster
//! than [`bounce_threshold`] = 2|g|Δt: a resting contact closes at |g|Δt
//! per step and must not bounce) is resolved before the DVI step at its
//! time of impact within the step ([`super::impact`]): the bodies are
//! moved to where they touch, take the impulse of Newton's restitution
//! there and fly on to the step's end; the DVI step then starts them from
//! the pose that lands them there, and gives the contact ε = 0. An
//! elastic ball keeps its bounce height (before, a bounce applied from the
//! step's start reversed it up to one step's travel above the ground: +3%
//! of height per bounce for a ball dropped 0.5 m at Δt = 10 ms).
//!
//! A frictional contact (this pass has no friction), or any bounce still
//! due when the pass reached its bound ([`super::impact::MAX_IMPACTS`]),
//! bounces in the DVI step as before when the surfaces would meet within
//! the step (φ + Δt v_rel < 0): ε and b = min(φ, 0)/Δt, so v_rel⁺ ≥
//! −ε v_rel from where the bodies are, and a bouncing contact that already
//! penetrates is pushed out like any other.

use glam::{DQuat, DVec3};

use super::broad::{candidate_pairs, Aabb};
use super::collide::{collide_shapes, ContactPoint, Placed};
use super::impact::{resolve_impacts, Impacts};
use super::{RigidBody, World};
use crate::cpu::impulses::BodyVelocity;
use crate::scene::{Body, Contact, Scene};

/// One world ready for the door: its scene and what the step needs back.
#[derive(Clone, Debug)]
pub struct Prepared {
    /// Bodies (with v*) and contacts (with ε, bias φ/Δt, ids).
    pub scene: Scene,
    /// The contacts as collision found them, in the scene's order.
    pub contacts: Vec<ContactPoint>,
    /// Per contact the pair's friction coefficient √(μ_a μ_b), for the
    /// friction path (the frictionless door does not read it).
    pub friction: Vec<f64>,
    /// Sleeping bodies an awake one touched this step (woken).
    pub woken: Vec<usize>,
    /// The impacts resolved at their time before the DVI step
    /// ([`super::impact`]).
    pub impacts: Impacts,
}

/// The approach speed above which a contact with ε > 0 bounces: 2|g|Δt.
pub fn bounce_threshold(gravity: DVec3, dt: f64) -> f64 {
    2.0 * gravity.length() * dt
}

/// A contact's id: world (20 bits), body a and body b (16 bits each),
/// feature (12 bits); stable across steps while the same features touch.
/// Worlds beyond 2²⁰ share ids with earlier ones (warm start then only
/// guesses, and the guess is checked).
pub fn contact_id(world: usize, p: &ContactPoint) -> u64 {
    ((world as u64 & 0xf_ffff) << 44)
        | ((p.a as u64) << 28)
        | ((p.b as u64) << 12)
        | u64::from(p.feature & 0xfff)
}

/// Contacts of one world this step: pairs from the broad phase, points from
/// the narrow phase with margin `contact_margin` + how far the pair can close
/// within Δt. Sleeping bodies are not collided with each other or with
/// static ones; one an awake body touches is woken (its index in the second
/// list) and its own pairs are then collided too.
pub fn world_contacts(
    world: &World,
    v: &[(DVec3, DVec3)],
    dt: f64,
) -> (Vec<ContactPoint>, Vec<usize>) {
    let placed: Vec<Placed> = world.bodies.iter().map(Placed::of).collect();
    let mut active: Vec<bool> = world.bodies.iter().map(|b| !b.fixed && !b.asleep).collect();
    let movable: Vec<bool> = world.bodies.iter().map(|b| !b.fixed).collect();
    // How far each body can move within the step (0 for static/asleep).
    let reach: Vec<f64> = world
        .bodies
        .iter()
        .zip(v)
        .zip(&active)
        .map(|((b, (lin, ang)), &on)| {
            if on {
                (lin.length() + ang.length() * b.bounding_radius()) * dt
            } else {
                0.0
            }
        })
        .collect();
    let half = 0.5 * world.contact_margin;
    let aabbs: Vec<Option<Aabb>> = placed
        .iter()
        .zip(&reach)
        .map(|(p, r)| Aabb::of(p, r + half))
        .collect();
    let pairs = candidate_pairs(&aabbs, &movable);
    let mut done = vec![false; pairs.len()];
    let mut points = Vec::new();
    let mut woken = Vec::new();
    loop {
        let mut woke = false;
        for (k, &(i, j)) in pairs.iter().enumerate() {
            if done[k] || !(active[i] || active[j]) {
                continue;
            }
            done[k] = true;
            let margin = world.contact_margin + reach[i] + reach[j];
            let hits = collide_shapes(&placed[i], &placed[j], margin);
            if hits.is_empty() {
                continue;
            }
            for x in [i, j] {
                if movable[x] && !active[x] {
                    active[x] = true;
                    woken.push(x);
                    woke = true;
                }
            }
            // The dynamic body is a (normal from b to a).
            let swap = world.bodies[i].fixed;
            points.extend(hits.iter().map(|h| ContactPoint {
                a: if swap { j } else { i },
                b: if swap { i } else { j },
                point: h.point,
                normal: if swap { -h.normal } else { h.normal },
                gap: h.gap,
                feature: h.feature,
            }));
        }
        if !woke {
            break;
        }
    }
    (points, woken)
}

/// Step part 1 for world number `index` of the batch: gravity, collision and
/// the scene (see the module docs).
pub fn prepare(world: &World, index: usize, dt: f64) -> Prepared {
    let g = world.gravity();
    let awake = |b: &super::RigidBody| !b.fixed && !b.asleep;
    let mut v: Vec<(DVec3, DVec3)> = world
        .bodies
        .iter()
        .map(|b| {
            let lin = b.velocity() + if awake(b) { g * dt } else { DVec3::ZERO };
            (lin, b.angular_velocity())
        })
        .collect();
    let (contacts, woken) = world_contacts(world, &v, dt);
    for &k in &woken {
        v[k] = (g * dt, DVec3::ZERO);
    }
    let moving: Vec<bool> = (world.bodies.iter().enumerate())
        .map(|(k, b)| awake(b) || woken.contains(&k))
        .collect();
    let threshold = bounce_threshold(g, dt);
    let impacts = resolve_impacts(world, &contacts, &mut v, &moving, dt, threshold);
    let bodies: Vec<Body> = (world.bodies.iter().enumerate())
        .map(|(k, b)| scene_body(b, moving[k], b.position(), b.rotation(), v[k]))
        .collect();
    let mut scene_contacts = Vec::with_capacity(contacts.len());
    let mut friction = Vec::with_capacity(contacts.len());
    for p in &contacts {
        let (ba, bb) = (&world.bodies[p.a], &world.bodies[p.b]);
        let eps = ba.restitution.max(bb.restitution);
        let mu = (ba.friction * bb.friction).sqrt();
        friction.push(mu);
        let point_velocity = |k: usize| {
            let r = p.point - world.bodies[k].position();
            v[k].0 + v[k].1.cross(r)
        };
        let v_rel = (point_velocity(p.a) - point_velocity(p.b)).dot(p.normal);
        let gap = impacts.gap(world, p);
        // Frictionless bounces were taken at their time of impact, unless
        // more were due than the pass takes.
        let left = mu > 0.0 || impacts.deferred > 0;
        let bounces = eps > 0.0 && left && v_rel < -threshold && gap + dt * v_rel < 0.0;
        scene_contacts.push(Contact {
            a: p.a,
            b: Some(p.b),
            point: p.point.to_array(),
            normal: p.normal.to_array(),
            restitution: if bounces { eps } else { 0.0 },
            id: Some(contact_id(index, p)),
            bias: if bounces {
                gap.min(0.0) / dt
            } else if impacts.struck(p) {
                gap.max(0.0) / dt
            } else {
                gap / dt
            },
            friction: mu,
            tangent: None,
        });
    }
    Prepared {
        scene: Scene {
            bodies,
            contacts: scene_contacts,
        },
        contacts,
        friction,
        woken,
        impacts,
    }
}

/// The door's body for world body `b` at pose (`x`, `q`) with velocities
/// `v` (linear, angular): its inverse mass and world-frame inverse inertia
/// where the step moves it (`moving`), else static.
pub(super) fn scene_body(
    b: &RigidBody,
    moving: bool,
    x: DVec3,
    q: DQuat,
    v: (DVec3, DVec3),
) -> Body {
    let props = b.mass_properties();
    let mut body = Body::new(0.0, [0.0; 3], x.to_array());
    if moving {
        body.inv_mass = props.inv_mass;
        body.inv_inertia = b.inv_inertia_at(&props, q).transpose().to_cols_array_2d();
    }
    body.velocity = v.0.to_array();
    body.angular_velocity = v.1.to_array();
    body
}

/// Step part 3: the velocities after the impulses (`after`, one per body),
/// positions and orientations integrated over Δt, sleep counters.
pub fn finish(world: &mut World, prepared: &Prepared, after: &[BodyVelocity], dt: f64) {
    for &k in &prepared.woken {
        world.bodies[k].asleep = false;
        world.bodies[k].quiet_steps = 0;
    }
    let sleep = world.sleep;
    for (k, (b, v)) in world.bodies.iter_mut().zip(after).enumerate() {
        if b.fixed || b.asleep {
            continue;
        }
        b.velocity = v.velocity;
        b.angular_velocity = v.angular_velocity;
        // From where the impact pass put it, if it took an impact.
        let (x0, q0) = (prepared.impacts.start(k)).unwrap_or((b.position(), b.rotation()));
        let x = x0 + b.velocity() * dt;
        b.position = x.to_array();
        b.orientation = integrate_rotation(q0, b.angular_velocity(), dt).to_array();
        let quiet =
            b.velocity().length() < sleep.linear && b.angular_velocity().length() < sleep.angular;
        b.quiet_steps = if quiet {
            b.quiet_steps.saturating_add(1)
        } else {
            0
        };
        if sleep.steps > 0 && b.quiet_steps >= sleep.steps {
            b.asleep = true;
            b.velocity = [0.0; 3];
            b.angular_velocity = [0.0; 3];
        }
    }
}

/// q ← normalise(q + ½ Δt (ω, 0) ⊗ q): the quaternion's derivative
/// q̇ = ½ (ω, 0) ⊗ q for a world-frame ω, one explicit step, renormalised.
pub fn integrate_rotation(q: DQuat, w: DVec3, dt: f64) -> DQuat {
    let spin = DQuat::from_xyzw(w.x, w.y, w.z, 0.0) * q;
    let next = DQuat::from_xyzw(
        q.x + 0.5 * dt * spin.x,
        q.y + 0.5 * dt * spin.y,
        q.z + 0.5 * dt * spin.z,
        q.w + 0.5 * dt * spin.w,
    );
    next.normalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_small_rotation_step_turns_by_omega_dt() {
        let q = integrate_rotation(DQuat::IDENTITY, DVec3::new(0.0, 0.0, 1.0), 1e-3);
        let (axis, angle) = q.to_axis_angle();
        assert!((angle - 1e-3).abs() < 1e-9 && (axis - DVec3::Z).length() < 1e-9);
    }

    #[test]
    fn contact_ids_keep_world_bodies_and_feature_apart() {
        let p = |a, b, feature| ContactPoint {
            a,
            b,
            point: DVec3::ZERO,
            normal: DVec3::Y,
            gap: 0.0,
            feature,
        };
        let ids = [
            contact_id(0, &p(1, 2, 3)),
            contact_id(1, &p(1, 2, 3)),
            contact_id(0, &p(2, 1, 3)),
            contact_id(0, &p(1, 2, 4)),
        ];
        let mut distinct = ids.to_vec();
        distinct.sort_unstable();
        distinct.dedup();
        assert_eq!(distinct.len(), 4);
    }
}
