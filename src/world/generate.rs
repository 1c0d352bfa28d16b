//! Standard worlds, parameterised and seeded: the same kind, size and seed
//! give the same world on every platform. Ground: the plane y = 0; gravity
//! (0, −9.81, 0); boxes of 1 m (half extents 0.5) and 1,000 kg/m³ unless said.

use glam::{DQuat, DVec3};

use super::{RigidBody, Shape, World};
use crate::generate::Rng;
use crate::Error;

/// The kinds of standard world.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WorldKind {
    /// `size` spheres (radius 0.25–0.5) dropped from up to 2 m, apart.
    Spheres,
    /// A stack of `size` unit boxes resting on the ground.
    Stack,
    /// A pyramid of boxes, `size` on its bottom row (a 2-D wall).
    Pyramid,
    /// One unit box sliding at 2 m/s along x on the ground (μ = 0.5).
    Slide,
    /// One unit box resting on a 20° incline (μ = 0.5: it sticks).
    Incline,
    /// `size` spheres and boxes of mixed sizes falling on the ground from
    /// random poses and heights.
    Rain,
}

impl WorldKind {
    /// Every kind with its name.
    pub const ALL: [(WorldKind, &'static str); 6] = [
        (WorldKind::Spheres, "spheres"),
        (WorldKind::Stack, "stack"),
        (WorldKind::Pyramid, "pyramid"),
        (WorldKind::Slide, "slide"),
        (WorldKind::Incline, "incline"),
        (WorldKind::Rain, "rain"),
    ];

    /// The kind's name.
    pub fn name(self) -> &'static str {
        WorldKind::ALL
            .iter()
            .find(|(k, _)| *k == self)
            .map(|(_, n)| *n)
            .expect("every kind is named")
    }

    /// The default size (bodies, boxes in the stack, bottom row).
    pub fn default_size(self) -> usize {
        match self {
            WorldKind::Spheres => 8,
            WorldKind::Stack => 4,
            WorldKind::Pyramid => 4,
            WorldKind::Slide | WorldKind::Incline => 1,
            WorldKind::Rain => 32,
        }
    }

    /// Parses `KIND` or `KIND:SIZE` (e.g. `stack:5`); the error names the
    /// item `what` and lists the kinds.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `what` for an unknown kind or a size that is
    /// not a whole number in 1..=4096.
    pub fn parse(what: &str, text: &str) -> Result<(WorldKind, usize), Error> {
        let (name, size) = text.split_once(':').unwrap_or((text, ""));
        let kind = WorldKind::ALL
            .iter()
            .find(|(_, n)| *n == name)
            .map(|(k, _)| *k)
            .ok_or_else(|| {
                let names: Vec<&str> = WorldKind::ALL.iter().map(|(_, n)| *n).collect();
                Error::invalid(
                    what,
                    "kind",
                    format!("`{name}` is not a world kind ({})", names.join(", ")),
                )
            })?;
        let size = if size.is_empty() {
            kind.default_size()
        } else {
            match size.parse::<usize>() {
                Ok(n) if (1..=4096).contains(&n) => n,
                _ => {
                    return Err(Error::invalid(
                        what,
                        "size",
                        format!("`{size}` is not a whole number in 1..=4096"),
                    ))
                }
            }
        };
        Ok((kind, size))
    }
}

/// A unit box (half extents `h`) of 1,000 kg/m³.
fn cube(h: f64, position: DVec3) -> RigidBody {
    RigidBody {
        density: Some(1000.0),
        mass: None,
        ..RigidBody::new(
            Shape::Box {
                half_extents: [h; 3],
            },
            position.to_array(),
            0.0,
        )
    }
}

fn ground(friction: f64) -> RigidBody {
    RigidBody {
        friction,
        ..RigidBody::fixed(
            Shape::Plane {
                normal: [0.0, 1.0, 0.0],
            },
            [0.0; 3],
        )
    }
}

/// The standard world `kind` of `size`, from `seed` (kinds without
/// randomness ignore it).
pub fn standard_world(kind: WorldKind, size: usize, seed: u64) -> World {
    let g = [0.0, -9.81, 0.0];
    let mut rng = Rng::new(seed);
    match kind {
        WorldKind::Stack => {
            let mut bodies = vec![ground(0.5)];
            for k in 0..size {
                let mut b = cube(0.5, DVec3::new(0.0, 0.5 + k as f64, 0.0));
                b.friction = 0.5;
                bodies.push(b);
            }
            World::new(g, bodies)
        }
        WorldKind::Pyramid => {
            let mut bodies = vec![ground(0.5)];
            for row in 0..size {
                for k in 0..size - row {
                    let x = k as f64 * 1.0 + 0.5 * row as f64 - 0.5 * (size - 1) as f64;
                    let mut b = cube(0.5, DVec3::new(x, 0.5 + row as f64, 0.0));
                    b.friction = 0.5;
                    bodies.push(b);
                }
            }
            World::new(g, bodies)
        }
        WorldKind::Slide => {
            let mut b = cube(0.5, DVec3::new(0.0, 0.5, 0.0));
            b.velocity = [2.0, 0.0, 0.0];
            b.friction = 0.5;
            World::new(g, vec![ground(0.5), b])
        }
        WorldKind::Incline => incline(20f64.to_radians(), 0.5, 0.5),
        WorldKind::Spheres => {
            let mut bodies = vec![ground(0.3)];
            let side = (size as f64).sqrt().ceil() as usize;
            for k in 0..size {
                let r = rng.range(0.25, 0.5);
                let p = DVec3::new(
                    1.2 * (k % side) as f64,
                    r + rng.range(0.0, 2.0),
                    1.2 * (k / side) as f64,
                );
                let mut b = RigidBody::new(Shape::Sphere { radius: r }, p.to_array(), 0.0);
                b.mass = None;
                b.density = Some(1000.0);
                b.friction = 0.3;
                bodies.push(b);
            }
            World::new(g, bodies)
        }
        WorldKind::Rain => rain(size, &mut rng),
    }
}

/// A unit box resting on an incline of `angle` (rad, about z; the plane
/// through the origin with normal (−sin θ, cos θ, 0)), friction μ on both.
/// `h` is the box's half extent.
pub fn incline(angle: f64, mu: f64, h: f64) -> World {
    let n = DVec3::new(-angle.sin(), angle.cos(), 0.0);
    let mut plane = RigidBody::fixed(
        Shape::Plane {
            normal: n.to_array(),
        },
        [0.0; 3],
    );
    plane.friction = mu;
    let mut b = cube(h, n * h);
    b.orientation = DQuat::from_rotation_z(angle).to_array();
    b.friction = mu;
    World::new([0.0, -9.81, 0.0], vec![plane, b])
}

/// Spheres and boxes of mixed sizes from random poses, in a column of cells
/// (one body per cell). The cells are wider than the bounding spheres of
/// two of the largest bodies plus both centres' jitter, so that no two
/// bodies start overlapping, whatever their sizes and orientations (cells
/// of 1.2 m let two tumbled boxes start 4.55 cm inside each other); the
/// lowest row's centres, 1 m up, are more than that reach above the ground.
fn rain(size: usize, rng: &mut Rng) -> World {
    /// Largest sphere radius and box half extent.
    const RADIUS: f64 = 0.5;
    const HALF: f64 = 0.45;
    /// Largest offset of a centre from its cell's, per axis.
    const JITTER: f64 = 0.05;
    let reach = RADIUS.max(HALF * 3f64.sqrt());
    // Neighbours' centres are at least `pitch - 2 JITTER` apart: 4 cm more
    // than two bounding spheres.
    let pitch = 2.0 * (reach + JITTER) + 0.04;
    let mut bodies = vec![ground(0.4)];
    let side = (size as f64).cbrt().ceil().max(1.0) as usize;
    for k in 0..size {
        let cell = DVec3::new(
            (k % side) as f64,
            (k / (side * side)) as f64,
            ((k / side) % side) as f64,
        );
        let p = cell * pitch + DVec3::new(0.0, 1.0, 0.0) + rng.vector(JITTER);
        let shape = if rng.unit() < 0.5 {
            Shape::Sphere {
                radius: rng.range(0.2, RADIUS),
            }
        } else {
            Shape::Box {
                half_extents: [
                    rng.range(0.15, HALF),
                    rng.range(0.15, HALF),
                    rng.range(0.15, HALF),
                ],
            }
        };
        let mut b = RigidBody::new(shape, p.to_array(), 0.0);
        b.mass = None;
        b.density = Some(rng.range(500.0, 2000.0));
        b.orientation =
            DQuat::from_axis_angle(rng.unit_vector(), rng.range(0.0, std::f64::consts::TAU))
                .to_array();
        b.velocity = rng.vector(0.5).to_array();
        b.friction = 0.4;
        b.restitution = rng.range(0.0, 0.3);
        bodies.push(b);
    }
    World::new([0.0, -9.81, 0.0], bodies)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::world::step::world_contacts;

    /// Every kind at several sizes and seeds starts with no two shapes
    /// inside each other, as the world's own collision measures it: the
    /// contacts of the bodies at rest (every pair closer than the contact
    /// margin, with its signed gap) have gaps ≥ 0 (to rounding: stacked
    /// boxes touch).
    #[test]
    fn every_kind_starts_without_overlap() {
        for (kind, name) in WorldKind::ALL {
            for size in [kind.default_size(), 1, 2, 7, 64] {
                for seed in 0..100 {
                    let w = standard_world(kind, size, seed);
                    let at_rest = vec![(DVec3::ZERO, DVec3::ZERO); w.bodies.len()];
                    for p in world_contacts(&w, &at_rest, 0.01).0 {
                        assert!(
                            p.gap >= -1e-12,
                            "{name}:{size} seed {seed}: bodies {} and {} overlap by {} m",
                            p.a,
                            p.b,
                            -p.gap
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn every_kind_is_valid_and_seeded() {
        for (kind, name) in WorldKind::ALL {
            let w = standard_world(kind, kind.default_size(), 7);
            w.validate(name).unwrap();
            assert_eq!(w, standard_world(kind, kind.default_size(), 7), "{name}");
            assert_eq!(WorldKind::parse("--world", name).unwrap().0, kind);
        }
        assert_eq!(standard_world(WorldKind::Stack, 5, 0).bodies.len(), 6);
        assert_eq!(standard_world(WorldKind::Pyramid, 4, 0).bodies.len(), 11);
        assert_ne!(
            standard_world(WorldKind::Rain, 10, 1),
            standard_world(WorldKind::Rain, 10, 2)
        );
        let e = WorldKind::parse("--world", "tower:3")
            .unwrap_err()
            .to_string();
        assert!(e.contains("kind") && e.contains("stack"), "{e}");
        let e = WorldKind::parse("--world", "stack:0")
            .unwrap_err()
            .to_string();
        assert!(e.contains("size"), "{e}");
    }
}
