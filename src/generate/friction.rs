//! Fixed-seed scenes with friction, for tests and the friction bench:
//! a box sliding on the ground, a box on an incline, and families of
//! frictional islands of k contacts (boxes resting or sliding, stacks,
//! random spheres).

use glam::{DMat3, DVec3};

use super::{ball_body, box_body, random_island, Rng};
use crate::friction::assembly::friction_islands;
use crate::friction::FrictionProblem;
use crate::scene::{Body, Contact, Scene};

/// A unit box of mass `mass` on the ground (static body 0) with its four
/// bottom corners as contacts of friction `mu`, moving with `velocity`
/// (approaching when its y is negative), no restitution.
pub fn box_on_ground_moving(mass: f64, mu: f64, velocity: DVec3) -> Scene {
    let ground = Body::fixed([0.0, -0.5, 0.0]);
    let mut b = box_body(
        mass,
        DVec3::splat(0.5),
        DMat3::IDENTITY,
        DVec3::new(0.0, 0.5, 0.0),
    );
    b.velocity = velocity.to_array();
    let contacts = [(-0.5, -0.5), (0.5, -0.5), (-0.5, 0.5), (0.5, 0.5)]
        .iter()
        .map(|&(x, z)| {
            Contact::new(1, Some(0), [x, 0.0, z], [0.0, 1.0, 0.0], 0.0).with_friction(mu)
        })
        .collect();
    Scene {
        bodies: vec![ground, b],
        contacts,
    }
}

/// A unit box of mass 1 resting on an incline of angle `theta` (radians,
/// rising along +x) with friction `mu`, after one time step of gravity:
/// velocity (0, −g Δt, 0) = `fall` downwards. Contacts: the four bottom
/// corners, normal n = (−sin θ, cos θ, 0).
pub fn box_on_incline(theta: f64, mu: f64, fall: f64) -> Scene {
    let (s, c) = theta.sin_cos();
    let n = DVec3::new(-s, c, 0.0);
    let along = DVec3::new(c, s, 0.0);
    let side = DVec3::Z;
    let rot = DMat3::from_cols(along, n, side);
    let centre = n * 0.5;
    let mut b = box_body(1.0, DVec3::splat(0.5), rot, centre);
    b.velocity = [0.0, -fall, 0.0];
    let contacts = [(-0.5, -0.5), (0.5, -0.5), (-0.5, 0.5), (0.5, 0.5)]
        .iter()
        .map(|&(x, z)| {
            let p = along * x + side * z;
            Contact::new(0, None, p.to_array(), n.to_array(), 0.0).with_friction(mu)
        })
        .collect();
    Scene {
        bodies: vec![b],
        contacts,
    }
}

/// A family of frictional islands for the friction bench.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrictionFamily {
    /// Boxes on the ground, 4 corner contacts each, falling slowly and
    /// at rest tangentially (sticking).
    RestingBoxes,
    /// Boxes on the ground, 4 corners, sliding fast (every contact slides).
    SlidingBoxes,
    /// Stacks of boxes: 4 contacts per level, k/4 levels.
    Stacks,
    /// Random spheres and boxes touching at k random contacts (random
    /// normals, velocities, μ in [0.1, 1]).
    RandomSpheres,
}

impl FrictionFamily {
    /// Every family, in the table's order.
    pub const ALL: [FrictionFamily; 4] = [
        FrictionFamily::RestingBoxes,
        FrictionFamily::SlidingBoxes,
        FrictionFamily::Stacks,
        FrictionFamily::RandomSpheres,
    ];

    /// The snake_case name used in tables.
    pub fn name(self) -> &'static str {
        match self {
            FrictionFamily::RestingBoxes => "resting_boxes",
            FrictionFamily::SlidingBoxes => "sliding_boxes",
            FrictionFamily::Stacks => "stacks",
            FrictionFamily::RandomSpheres => "random_spheres",
        }
    }

    /// Whether it has islands of `k` contacts (boxes: k = 4; stacks: k a
    /// multiple of 4; random spheres: any k ≥ 1).
    pub fn has_size(self, k: usize) -> bool {
        match self {
            FrictionFamily::RestingBoxes | FrictionFamily::SlidingBoxes => k == 4,
            FrictionFamily::Stacks => k % 4 == 0 && k >= 4,
            FrictionFamily::RandomSpheres => k >= 1,
        }
    }
}

/// A stack of `levels` unit boxes on the ground (4 corner contacts per
/// level), each falling at `fall` and drifting sideways at `drift`, μ = `mu`.
pub fn box_stack(levels: usize, mu: f64, fall: f64, drift: f64) -> Scene {
    let mut bodies = vec![Body::fixed([0.0, -0.5, 0.0])];
    let mut contacts = Vec::new();
    for l in 0..levels {
        let mut b = box_body(
            1.0,
            DVec3::splat(0.5),
            DMat3::IDENTITY,
            DVec3::new(0.0, 0.5 + l as f64, 0.0),
        );
        b.velocity = [drift * (l + 1) as f64, -fall * (l + 1) as f64, 0.0];
        bodies.push(b);
        let below = l; // body index: the ground is 0, level l is l + 1
        for (x, z) in [(-0.5, -0.5), (0.5, -0.5), (-0.5, 0.5), (0.5, 0.5)] {
            contacts.push(
                Contact::new(l + 1, Some(below), [x, l as f64, z], [0.0, 1.0, 0.0], 0.0)
                    .with_friction(mu),
            );
        }
    }
    Scene { bodies, contacts }
}

/// `count` frictional problems of exactly `k` contacts of `family` from `seed`
/// (None when the family has no island of that size).
pub fn friction_batch(
    family: FrictionFamily,
    k: usize,
    seed: u64,
    count: usize,
) -> Option<Vec<FrictionProblem>> {
    if !family.has_size(k) {
        return None;
    }
    let mut rng = Rng::new(seed);
    let mut out = Vec::with_capacity(count);
    while out.len() < count {
        let mu = rng.range(0.1, 1.0);
        let scene = match family {
            FrictionFamily::RestingBoxes => box_on_ground_moving(
                rng.range(0.5, 2.0),
                mu,
                DVec3::new(
                    rng.range(-0.01, 0.01),
                    -rng.range(0.05, 0.2),
                    rng.range(-0.01, 0.01),
                ),
            ),
            FrictionFamily::SlidingBoxes => {
                let dir = rng.range(0.0, std::f64::consts::TAU);
                box_on_ground_moving(
                    rng.range(0.5, 2.0),
                    mu,
                    DVec3::new(5.0 * dir.cos(), -rng.range(0.05, 0.2), 5.0 * dir.sin()),
                )
            }
            FrictionFamily::Stacks => {
                box_stack(k / 4, mu, rng.range(0.05, 0.2), rng.range(-0.5, 0.5))
            }
            FrictionFamily::RandomSpheres => random_frictional_island(&mut rng, k),
        };
        for isl in friction_islands(&scene) {
            if isl.problem.contacts() == k && out.len() < count {
                out.push(isl.problem);
            }
        }
    }
    Some(out)
}

/// One random island of exactly k contacts with μ ∈ [0.1, 1] per contact
/// (a random physical island of [`random_island`], mass ratio 10); for
/// k = 1 a ball hitting the ground obliquely.
fn random_frictional_island(rng: &mut Rng, k: usize) -> Scene {
    let mut scene = if k == 1 {
        let mut b = ball_body(rng.range(0.5, 2.0), 0.5, DVec3::new(0.0, 0.5, 0.0));
        b.velocity = [
            rng.range(-2.0, 2.0),
            -rng.range(0.1, 2.0),
            rng.range(-2.0, 2.0),
        ];
        b.angular_velocity = rng.vector(2.0).to_array();
        Scene {
            bodies: vec![b],
            contacts: vec![Contact::new(0, None, [0.0; 3], [0.0, 1.0, 0.0], rng.unit())],
        }
    } else {
        random_island(rng, k, 10.0)
    };
    for c in &mut scene.contacts {
        c.friction = rng.range(0.1, 1.0);
    }
    scene
}
