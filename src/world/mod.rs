//! Worlds in time: rigid bodies (spheres and boxes; static planes and
//! boxes), their poses and velocities, gravity and materials; contact
//! generation each step (`collide`); the step itself (a time-stepping
//! discretisation of the differential variational inequality of contact:
//! Stewart & Trinkle 1996, Anitescu & Potra 1997; Pang & Stewart 2008) is
//! [`crate::Solver::step_worlds`], built from `step`, and reports a
//! [`StepReport`]; world files are read and written by [`format`](mod@format), the
//! standard worlds built by [`generate`].
//!
//! # Conventions
//! - Poses: `position` is the centre of mass, `orientation` a unit
//!   quaternion written `[x, y, z, w]` (glam's order) taking body to world.
//! - Mass: `mass` given, or `density` × volume (kg/m³); the inertia is given
//!   (`inertia`, principal moments in the body frame) or that of the shape
//!   (sphere 2/5 m r², box m/3 (h_y² + h_z²), …, h the half extents). The
//!   world-frame inverse inertia R diag(1/I) Rᵀ is recomputed each step.
//! - Materials are per body; a pair combines them as Box2D and Bullet do:
//!   μ = √(μ_a μ_b) (one frictionless body makes the pair frictionless),
//!   ε = max(ε_a, ε_b) (a bouncy ball bounces off a dead floor).
//! - Planes are static, pass through `position`, their outward `normal` is
//!   given in the world frame.

use glam::{DMat3, DQuat, DVec3};
use serde::{Deserialize, Serialize};

use crate::Error;

pub(crate) mod broad;
pub(crate) mod collide;
mod collide_box;
pub mod format;
pub mod generate;
pub(crate) mod impact;
pub(crate) mod step;

pub use crate::solver::world_path::{ResidentStep, StepReport, StepTimings, WorldStepReport};
pub use crate::solver::Repairs;

/// The shape of a body, in its own frame.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Shape {
    /// A sphere of this radius (m).
    Sphere {
        /// Radius (m), > 0.
        radius: f64,
    },
    /// A box of these half extents (m) along its own axes.
    Box {
        /// Half extents (m), each > 0.
        half_extents: [f64; 3],
    },
    /// A static half-space {x : n·(x − position) ≤ 0}; `normal` points out of
    /// it (world frame, unit).
    Plane {
        /// Outward unit normal (world frame).
        normal: [f64; 3],
    },
}

/// Sleeping: a dynamic body whose speeds stay below these for `steps`
/// consecutive steps sleeps (not collided, not solved) until an awake body
/// touches it. `steps` = 0 turns sleeping off.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Sleep {
    /// Consecutive quiet steps before a body sleeps (0: never). Default 0.
    #[serde(default)]
    pub steps: u32,
    /// Largest linear speed (m/s) counted as quiet. Default 0.01.
    #[serde(default = "default_sleep_linear")]
    pub linear: f64,
    /// Largest angular speed (rad/s) counted as quiet. Default 0.05.
    #[serde(default = "default_sleep_angular")]
    pub angular: f64,
}

fn default_sleep_linear() -> f64 {
    0.01
}
fn default_sleep_angular() -> f64 {
    0.05
}

impl Default for Sleep {
    fn default() -> Self {
        Sleep {
            steps: 0,
            linear: default_sleep_linear(),
            angular: default_sleep_angular(),
        }
    }
}

/// A rigid body of a world.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RigidBody {
    /// Its shape.
    pub shape: Shape,
    /// Static: never moves (planes must be).
    #[serde(default, skip_serializing_if = "is_false")]
    pub fixed: bool,
    /// Centre of mass (world frame); for a plane, a point on it.
    pub position: [f64; 3],
    /// Unit quaternion `[x, y, z, w]`, body to world. Default identity.
    #[serde(default = "identity")]
    pub orientation: [f64; 4],
    /// Linear velocity (m/s). Default 0.
    #[serde(default)]
    pub velocity: [f64; 3],
    /// Angular velocity (rad/s, world frame). Default 0.
    #[serde(default)]
    pub angular_velocity: [f64; 3],
    /// Mass (kg); or give `density`. Ignored for static bodies.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass: Option<f64>,
    /// Density (kg/m³): mass = density × volume, when `mass` is absent.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub density: Option<f64>,
    /// Principal moments of inertia in the body frame (kg m²); default the
    /// shape's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub inertia: Option<[f64; 3]>,
    /// Coulomb friction coefficient μ ≥ 0 of its surface. Default 0.
    #[serde(default)]
    pub friction: f64,
    /// Coefficient of restitution ε ∈ [0, 1] of its surface. Default 0.
    #[serde(default)]
    pub restitution: f64,
    /// Asleep (see [`Sleep`]); written in final states. Default false.
    #[serde(default, skip_serializing_if = "is_false")]
    pub asleep: bool,
    /// Consecutive quiet steps so far (runtime state, not read or written).
    #[serde(skip)]
    pub quiet_steps: u32,
}

fn is_false(b: &bool) -> bool {
    !*b
}
fn identity() -> [f64; 4] {
    [0.0, 0.0, 0.0, 1.0]
}

/// One simulation instance: bodies under gravity.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct World {
    /// Gravity (m/s²). Default (0, −9.81, 0).
    #[serde(default = "default_gravity")]
    pub gravity: [f64; 3],
    /// Contacts are generated for pairs closer than this (m), plus how far
    /// the pair can close within the step (speculative contacts). Default 0.005.
    #[serde(default = "default_margin")]
    pub contact_margin: f64,
    /// Sleeping thresholds; default off.
    #[serde(default)]
    pub sleep: Sleep,
    /// The bodies.
    pub bodies: Vec<RigidBody>,
}

fn default_gravity() -> [f64; 3] {
    [0.0, -9.81, 0.0]
}
fn default_margin() -> f64 {
    0.005
}

/// Mass properties of a body: 1/m and body-frame principal 1/I (0 for static).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MassProperties {
    /// 1/m (0 for static bodies).
    pub inv_mass: f64,
    /// Principal 1/I in the body frame (0 for static bodies).
    pub inv_inertia: DVec3,
}

impl RigidBody {
    /// A dynamic body at rest with identity orientation and mass `mass`.
    pub fn new(shape: Shape, position: [f64; 3], mass: f64) -> Self {
        RigidBody {
            shape,
            fixed: false,
            position,
            orientation: identity(),
            velocity: [0.0; 3],
            angular_velocity: [0.0; 3],
            mass: Some(mass),
            density: None,
            inertia: None,
            friction: 0.0,
            restitution: 0.0,
            asleep: false,
            quiet_steps: 0,
        }
    }

    /// A static body (a plane through `position`, or a fixed box).
    pub fn fixed(shape: Shape, position: [f64; 3]) -> Self {
        RigidBody {
            fixed: true,
            mass: None,
            ..RigidBody::new(shape, position, 0.0)
        }
    }

    /// The centre of mass as a vector.
    pub fn position(&self) -> DVec3 {
        DVec3::from_array(self.position)
    }
    /// The orientation (normalised).
    pub fn rotation(&self) -> DQuat {
        DQuat::from_array(self.orientation).normalize()
    }
    /// The linear velocity as a vector.
    pub fn velocity(&self) -> DVec3 {
        DVec3::from_array(self.velocity)
    }
    /// The angular velocity as a vector.
    pub fn angular_velocity(&self) -> DVec3 {
        DVec3::from_array(self.angular_velocity)
    }

    /// The volume of the shape (∞ for a plane).
    pub fn volume(&self) -> f64 {
        match self.shape {
            Shape::Sphere { radius } => 4.0 / 3.0 * std::f64::consts::PI * radius.powi(3),
            Shape::Box { half_extents: h } => 8.0 * h[0] * h[1] * h[2],
            Shape::Plane { .. } => f64::INFINITY,
        }
    }

    /// The mass (kg): given, or density × volume; ∞ for static bodies.
    pub fn mass(&self) -> f64 {
        if self.fixed {
            return f64::INFINITY;
        }
        self.mass
            .unwrap_or_else(|| self.density.unwrap_or(0.0) * self.volume())
    }

    /// 1/m and the principal 1/I of the body frame (zeros when static).
    pub fn mass_properties(&self) -> MassProperties {
        if self.fixed {
            return MassProperties {
                inv_mass: 0.0,
                inv_inertia: DVec3::ZERO,
            };
        }
        let m = self.mass();
        let inertia = match (self.inertia, self.shape) {
            (Some(i), _) => DVec3::from_array(i),
            (None, Shape::Sphere { radius }) => DVec3::splat(0.4 * m * radius * radius),
            (None, Shape::Box { half_extents: h }) => {
                let s = DVec3::from_array(h) * DVec3::from_array(h);
                DVec3::new(s.y + s.z, s.x + s.z, s.x + s.y) * (m / 3.0)
            }
            (None, Shape::Plane { .. }) => DVec3::ZERO, // refused by validate
        };
        MassProperties {
            inv_mass: 1.0 / m,
            inv_inertia: DVec3::ONE / inertia,
        }
    }

    /// The world-frame inverse inertia R diag(1/I) Rᵀ.
    pub fn world_inv_inertia(&self, props: &MassProperties) -> DMat3 {
        self.inv_inertia_at(props, self.rotation())
    }

    /// The inverse inertia R diag(1/I) Rᵀ at orientation `q`.
    pub(crate) fn inv_inertia_at(&self, props: &MassProperties, q: DQuat) -> DMat3 {
        let r = DMat3::from_quat(q);
        r * DMat3::from_diagonal(props.inv_inertia) * r.transpose()
    }

    /// Kinetic energy ½ m v² + ½ ωᵀ I ω (0 for static bodies).
    pub fn kinetic_energy(&self) -> f64 {
        if self.fixed {
            return 0.0;
        }
        let props = self.mass_properties();
        let r = DMat3::from_quat(self.rotation());
        let w_body = r.transpose() * self.angular_velocity();
        let inertia = DVec3::ONE / props.inv_inertia;
        0.5 * self.mass() * self.velocity().length_squared() + 0.5 * (w_body * w_body).dot(inertia)
    }

    /// A radius of a sphere around the centre holding the shape (∞ for planes).
    pub fn bounding_radius(&self) -> f64 {
        match self.shape {
            Shape::Sphere { radius } => radius,
            Shape::Box { half_extents: h } => DVec3::from_array(h).length(),
            Shape::Plane { .. } => f64::INFINITY,
        }
    }
}

impl World {
    /// A world with this gravity and these bodies, default margin, no sleeping.
    pub fn new(gravity: [f64; 3], bodies: Vec<RigidBody>) -> Self {
        World {
            gravity,
            contact_margin: default_margin(),
            sleep: Sleep::default(),
            bodies,
        }
    }

    /// Gravity as a vector.
    pub fn gravity(&self) -> DVec3 {
        DVec3::from_array(self.gravity)
    }

    /// Kinetic energy of every body.
    pub fn kinetic_energy(&self) -> f64 {
        self.bodies.iter().map(RigidBody::kinetic_energy).sum()
    }

    /// Potential energy −m g·x of the dynamic bodies (0 at the origin).
    pub fn potential_energy(&self) -> f64 {
        let g = self.gravity();
        self.bodies
            .iter()
            .filter(|b| !b.fixed)
            .map(|b| -b.mass() * g.dot(b.position()))
            .sum()
    }

    /// Checks every field; `item` names the world in errors ("world 3").
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `item`, the body and the field.
    pub fn validate(&self, item: &str) -> Result<(), Error> {
        format::validate_world(self, item)
    }
}
