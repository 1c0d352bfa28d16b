//! Fixed-seed generators of physical scenes, for tests, benches and the demo.
//! Every island they make comes from real bodies and contacts, so its M is
//! symmetric positive semidefinite (M = J M⁻¹ Jᵀ).

pub mod families;
pub mod friction;
pub mod stress;

use glam::{DMat3, DQuat, DVec3};

use crate::scene::{Body, Contact, Scene};

/// SplitMix64: small, fast, and the same on every platform.
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    /// A generator seeded with `seed` (the same sequence on every platform).
    pub fn new(seed: u64) -> Self {
        Rng(seed)
    }
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    /// Uniform integer in [lo, hi] (inclusive).
    pub fn int(&mut self, lo: usize, hi: usize) -> usize {
        lo + (self.next_u64() % (hi - lo + 1) as u64) as usize
    }
    /// Log-uniform in [lo, hi].
    pub fn log_range(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + (hi.ln() - lo.ln()) * self.unit()).exp()
    }
    /// Uniformly distributed unit vector.
    pub fn unit_vector(&mut self) -> DVec3 {
        loop {
            let v = DVec3::new(
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
            );
            let l = v.length();
            if l > 0.1 && l <= 1.0 {
                return v / l;
            }
        }
    }
    /// A random rotation.
    pub fn rotation(&mut self) -> DMat3 {
        DMat3::from_quat(DQuat::from_axis_angle(
            self.unit_vector(),
            self.range(0.0, std::f64::consts::TAU),
        ))
    }
    /// A vector with components uniform in [−scale, scale].
    pub fn vector(&mut self, scale: f64) -> DVec3 {
        DVec3::new(
            self.range(-scale, scale),
            self.range(-scale, scale),
            self.range(-scale, scale),
        )
    }
}

/// A box of mass m and half extents h, rotated by `rot`, at `position`, at rest:
/// world inverse inertia R I⁻¹ Rᵀ.
pub fn box_body(mass: f64, half: DVec3, rot: DMat3, position: DVec3) -> Body {
    let s = half * 2.0;
    let i = DVec3::new(
        s.y * s.y + s.z * s.z,
        s.x * s.x + s.z * s.z,
        s.x * s.x + s.y * s.y,
    ) * (mass / 12.0);
    let inv_local = DMat3::from_diagonal(DVec3::ONE / i);
    let inv_world = rot * inv_local * rot.transpose();
    body_with(1.0 / mass, inv_world, position)
}

/// A solid ball of mass m and radius r at `position`, at rest.
pub fn ball_body(mass: f64, radius: f64, position: DVec3) -> Body {
    let inv_i = 1.0 / (0.4 * mass * radius * radius);
    body_with(
        1.0 / mass,
        DMat3::from_diagonal(DVec3::splat(inv_i)),
        position,
    )
}

fn body_with(inv_mass: f64, inv_inertia: DMat3, position: DVec3) -> Body {
    let t = inv_inertia.transpose(); // columns of the transpose are rows
    Body {
        inv_mass,
        inv_inertia: [
            t.x_axis.to_array(),
            t.y_axis.to_array(),
            t.z_axis.to_array(),
        ],
        position: position.to_array(),
        velocity: [0.0; 3],
        angular_velocity: [0.0; 3],
    }
}

fn contact(a: usize, b: Option<usize>, point: DVec3, normal: DVec3, restitution: f64) -> Contact {
    Contact {
        a,
        b,
        point: point.to_array(),
        normal: normal.to_array(),
        restitution,
        id: None,
        bias: 0.0,
        friction: 0.0,
        tangent: None,
    }
}

/// One connected island of exactly `n` contacts among 1..=n dynamic bodies,
/// masses log-uniform over a ratio of `mass_ratio`, random boxes, points,
/// normals, velocities and restitutions; contacts with the world are mixed
/// in. Its M is symmetric positive semidefinite, usually definite.
pub fn random_island(rng: &mut Rng, n: usize, mass_ratio: f64) -> Scene {
    assert!(n >= 1);
    let k = rng.int(1, n);
    let mut bodies = Vec::with_capacity(k);
    for i in 0..k {
        let mass = rng.log_range(1.0, mass_ratio.max(1.0));
        let half = DVec3::new(
            rng.range(0.2, 1.0),
            rng.range(0.2, 1.0),
            rng.range(0.2, 1.0),
        );
        let mut b = box_body(
            mass,
            half,
            rng.rotation(),
            DVec3::new(2.0 * i as f64, 0.0, 0.0) + rng.vector(0.3),
        );
        b.velocity = rng.vector(1.0).to_array();
        b.angular_velocity = rng.vector(1.0).to_array();
        bodies.push(b);
    }
    let mut contacts = Vec::with_capacity(n);
    // A spanning chain first, so the island is connected.
    for i in 1..k {
        let mid = (DVec3::from_array(bodies[i - 1].position)
            + DVec3::from_array(bodies[i].position))
            * 0.5;
        let normal = (DVec3::from_array(bodies[i].position)
            - DVec3::from_array(bodies[i - 1].position))
        .normalize();
        let normal = (normal + rng.vector(0.3)).normalize();
        contacts.push(contact(
            i,
            Some(i - 1),
            mid + rng.vector(0.3),
            normal,
            rng.unit(),
        ));
    }
    while contacts.len() < n {
        let a = rng.int(0, k - 1);
        let pa = DVec3::from_array(bodies[a].position);
        if k > 1 && rng.unit() < 0.5 {
            let mut b = rng.int(0, k - 2);
            if b >= a {
                b += 1;
            }
            let pb = DVec3::from_array(bodies[b].position);
            let normal = ((pa - pb).normalize() + rng.vector(0.5)).normalize();
            contacts.push(contact(
                a,
                Some(b),
                (pa + pb) * 0.5 + rng.vector(0.5),
                normal,
                rng.unit(),
            ));
        } else {
            let normal = (DVec3::Y + rng.vector(0.3)).normalize();
            contacts.push(contact(
                a,
                None,
                pa + rng.vector(0.6) - DVec3::Y * 0.5,
                normal,
                rng.unit(),
            ));
        }
    }
    Scene { bodies, contacts }
}

/// A box of side 1 and mass 1 resting flat on the ground (a static body 0) with
/// its 4 bottom corners as contacts, falling at `speed`: M is 4×4 of rank 3.
pub fn box_on_ground(speed: f64, restitution: f64) -> Scene {
    let ground = Body::fixed([0.0, -0.5, 0.0]);
    let mut b = box_body(
        1.0,
        DVec3::splat(0.5),
        DMat3::IDENTITY,
        DVec3::new(0.0, 0.5, 0.0),
    );
    b.velocity = [0.0, -speed, 0.0];
    let contacts = [(-0.5, -0.5), (0.5, -0.5), (-0.5, 0.5), (0.5, 0.5)]
        .iter()
        .map(|&(x, z)| contact(1, Some(0), DVec3::new(x, 0.0, z), DVec3::Y, restitution))
        .collect();
    Scene {
        bodies: vec![ground, b],
        contacts,
    }
}

/// The textbook case of coupled contacts (each impulse changes the other
/// contacts' velocities): four bodies in a row, bodies 1 and 2 touching at
/// two points, 2–3 and 3–4 at one each (contacts p1…p4), all moving
/// together so that every contact approaches.
pub fn seed_chain(restitution: f64) -> Scene {
    let mut bodies = Vec::new();
    for i in 0..4 {
        let mut b = box_body(
            1.0 + i as f64,
            DVec3::new(0.5, 0.5, 0.5),
            DMat3::IDENTITY,
            DVec3::new(i as f64, 0.0, 0.0),
        );
        b.velocity = [1.0 - i as f64, 0.0, 0.0];
        bodies.push(b);
    }
    let x = DVec3::X;
    let contacts = vec![
        // Normal from b to a: b = 0 is on the left of a = 1, so n = +x.
        contact(1, Some(0), DVec3::new(0.5, 0.3, 0.0), x, restitution),
        contact(1, Some(0), DVec3::new(0.5, -0.3, 0.1), x, restitution),
        contact(2, Some(1), DVec3::new(1.5, 0.1, 0.0), x, restitution),
        contact(3, Some(2), DVec3::new(2.5, 0.0, 0.2), x, restitution),
    ];
    Scene { bodies, contacts }
}

/// A demo world: one simulation instance with a static ground (body 0) and a
/// mix of falling balls, boxes resting on the ground and stacks of boxes.
/// Islands have 1 to about 12 contacts.
// Long (about 100 lines) on purpose: the world's recipe (ground, balls,
// boxes, stacks) reads top to bottom, one object after another.
pub fn demo_world(rng: &mut Rng) -> Scene {
    let mut scene = Scene {
        bodies: vec![Body::fixed([0.0, -0.5, 0.0])],
        contacts: Vec::new(),
    };
    let objects = rng.int(4, 10);
    for o in 0..objects {
        let x = 3.0 * o as f64;
        match rng.int(0, 3) {
            0 => {
                // A ball hitting the ground.
                let r = rng.range(0.2, 0.6);
                let mut b = ball_body(rng.log_range(0.5, 5.0), r, DVec3::new(x, r, 0.0));
                b.velocity =
                    (DVec3::new(0.0, -rng.range(0.5, 3.0), 0.0) + rng.vector(0.5)).to_array();
                let i = scene.bodies.len();
                scene.bodies.push(b);
                scene.contacts.push(contact(
                    i,
                    Some(0),
                    DVec3::new(x, 0.0, 0.0),
                    DVec3::Y,
                    rng.range(0.0, 0.9),
                ));
            }
            1 => {
                // A box landing flat or tilted on the ground (4 corners).
                let mut b = box_body(
                    rng.log_range(0.5, 10.0),
                    DVec3::splat(0.5),
                    DMat3::IDENTITY,
                    DVec3::new(x, 0.5, 0.0),
                );
                b.velocity = [
                    rng.range(-0.5, 0.5),
                    -rng.range(0.1, 2.0),
                    rng.range(-0.5, 0.5),
                ];
                b.angular_velocity = rng.vector(0.5).to_array();
                let i = scene.bodies.len();
                scene.bodies.push(b);
                let e = rng.range(0.0, 0.5);
                for (dx, dz) in [(-0.5, -0.5), (0.5, -0.5), (-0.5, 0.5), (0.5, 0.5)] {
                    scene.contacts.push(contact(
                        i,
                        Some(0),
                        DVec3::new(x + dx, 0.0, dz),
                        DVec3::Y,
                        e,
                    ));
                }
            }
            2 => {
                // A stack of 2 or 3 boxes, 4 contacts per interface.
                let levels = rng.int(2, 3);
                let e = rng.range(0.0, 0.3);
                for l in 0..levels {
                    let mut b = box_body(
                        rng.log_range(0.5, 20.0),
                        DVec3::splat(0.5),
                        DMat3::IDENTITY,
                        DVec3::new(x, 0.5 + l as f64, 0.0),
                    );
                    b.velocity = [0.0, -rng.range(0.0, 1.0) * (l + 1) as f64, 0.0];
                    let i = scene.bodies.len();
                    scene.bodies.push(b);
                    let below = if l == 0 { 0 } else { i - 1 };
                    for (dx, dz) in [(-0.5, -0.5), (0.5, -0.5), (-0.5, 0.5), (0.5, 0.5)] {
                        let p = DVec3::new(x + dx, l as f64, dz);
                        scene.contacts.push(contact(i, Some(below), p, DVec3::Y, e));
                    }
                }
            }
            _ => {
                // Two balls colliding with each other and one resting on the ground.
                let r = 0.4;
                let mut a = ball_body(rng.log_range(0.5, 5.0), r, DVec3::new(x, r, 0.0));
                let mut b = ball_body(rng.log_range(0.5, 5.0), r, DVec3::new(x + 2.0 * r, r, 0.0));
                a.velocity = [rng.range(0.5, 2.0), -rng.range(0.0, 1.0), 0.0];
                b.velocity = [-rng.range(0.5, 2.0), 0.0, 0.0];
                let i = scene.bodies.len();
                scene.bodies.push(a);
                scene.bodies.push(b);
                scene.contacts.push(contact(
                    i + 1,
                    Some(i),
                    DVec3::new(x + r, r, 0.0),
                    DVec3::X,
                    rng.range(0.0, 1.0),
                ));
                scene.contacts.push(contact(
                    i,
                    Some(0),
                    DVec3::new(x, 0.0, 0.0),
                    DVec3::Y,
                    rng.range(0.0, 1.0),
                ));
            }
        }
    }
    scene
}

/// Several independent random islands in one scene: `islands` calls of
/// [`random_island`] with 1..=`max_n` contacts each, moved apart along z, and
/// a static ground (body 0) that about half of their world contacts touch
/// instead of the world. Static bodies couple nothing, so the scene has
/// exactly `islands` islands, each one of the generated ones.
pub fn random_scene(rng: &mut Rng, islands: usize, max_n: usize, mass_ratio: f64) -> Scene {
    let mut scene = Scene {
        bodies: vec![Body::fixed([0.0, -10.0, 0.0])],
        contacts: Vec::new(),
    };
    for i in 0..islands {
        let n = rng.int(1, max_n.max(1));
        let island = random_island(rng, n, mass_ratio);
        let offset = scene.bodies.len();
        let shift = DVec3::new(0.0, 0.0, 10.0 * i as f64);
        for mut b in island.bodies {
            b.position = (DVec3::from_array(b.position) + shift).to_array();
            scene.bodies.push(b);
        }
        for mut c in island.contacts {
            c.a += offset;
            c.b = match c.b {
                Some(b) => Some(b + offset),
                None if rng.unit() < 0.5 => Some(0),
                None => None,
            };
            c.point = (DVec3::from_array(c.point) + shift).to_array();
            scene.contacts.push(c);
        }
    }
    scene
}
