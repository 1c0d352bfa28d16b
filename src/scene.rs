//! Bodies and contacts: the scene a user hands in, and its checks.
//!
//! Conventions (those of impulse-based contact, e.g. Baraff 1994, Mirtich
//! 1996): the normal n of a contact points from body b to body a;
//! r = contact point − centre of mass; a point's velocity is ṗ = v + ω × r;
//! the impulse is +z n on a and −z n on b. Inverse inertia is given in the
//! world frame. A body with inv_mass 0 and inv_inertia 0 is static; a
//! contact's `b` may be absent, meaning the static world.

use std::fmt::Display;

use glam::{DMat3, DVec3};
use serde::{Deserialize, Serialize};

use crate::Error;

/// The two unit tangents (t₁, t₂) of a contact with unit normal n: an
/// orthonormal, right-handed frame (t₁ × t₂ = n), a deterministic function
/// of n alone (Duff et al., "Building an orthonormal basis, revisited",
/// JCGT 2017). With s = 1 when n.z ≥ −½ and −1 otherwise,
/// a = −1 / (s + n.z), b = n.x n.y a:
///
/// ```text
/// t₁ = (1 + s n.x² a, s b, −s n.x),   t₂ = (b, s + n.y² a, −n.y)
/// ```
///
/// Each branch is smooth where |s + n.z| ≥ ½ (|a| ≤ 2: no cancellation),
/// so the frame is continuous in n except across the circle n.z = −½,
/// where s flips. Duff's own rule flips s at n.z = 0, which is where the
/// normals of y-up worlds lie (ground n = (0, 1, 0), box sides (±1, 0, 0)):
/// a side normal whose n.z rounds to −0.0 one step and −6e-19 the next
/// turned (t₁, t₂) into (−t₁, −t₂), and the world's warm start (last
/// step's reactions by contact id) pointed its friction the wrong way.
/// The ground normal (0, 1, 0) gives t₁ = (1, 0, 0), t₂ = (0, 0, −1).
/// `shaders/world_friction.wgsl` computes the same.
pub fn tangent_basis(n: DVec3) -> (DVec3, DVec3) {
    let s = if n.z >= -0.5 { 1.0 } else { -1.0 };
    let a = -1.0 / (s + n.z);
    let b = n.x * n.y * a;
    (
        DVec3::new(1.0 + s * n.x * n.x * a, s * b, -s * n.x),
        DVec3::new(b, s + n.y * n.y * a, -n.y),
    )
}

/// A rigid body at the instant of the impact.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Body {
    /// 1/m; 0 for a body that cannot translate.
    pub inv_mass: f64,
    /// I⁻¹ in the world frame, rows; symmetric positive semidefinite.
    pub inv_inertia: [[f64; 3]; 3],
    /// Centre of mass.
    pub position: [f64; 3],
    /// Linear velocity of the centre of mass before the impact.
    pub velocity: [f64; 3],
    /// Angular velocity (world frame) before the impact.
    pub angular_velocity: [f64; 3],
}

/// A contact point between body `a` and body `b` (or the static world).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Contact {
    /// Body a (the normal points towards it).
    pub a: usize,
    /// Body b, or None for the static world.
    pub b: Option<usize>,
    /// The contact point (world frame).
    pub point: [f64; 3],
    /// Unit normal, pointing from b to a.
    pub normal: [f64; 3],
    /// Coefficient of restitution ε ∈ [0, 1].
    pub restitution: f64,
    /// The caller's id of this contact, stable across frames (e.g. a feature
    /// pair from collision detection): with `Settings::warm_start` an island
    /// starts from the basis its contacts had in the last call. Optional.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub id: Option<u64>,
    /// A velocity bias b added to the contact's q (m/s): q = v_rel +
    /// ε min(v_rel, 0) + b (`normal_q` in `src/cpu/assembly.rs`). Time
    /// stepping puts the gap here, b = φ/Δt (Stewart & Trinkle 1996:
    /// 0 ≤ γ_n ⊥ φ/Δt + v_n⁺ ≥ 0): a contact φ apart may close the gap
    /// within the step, a penetrating one (φ < 0) is pushed out by −φ/Δt.
    /// Optional, 0 when absent (and then not written, so frictionless
    /// single-frame outputs are unchanged).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub bias: f64,
    /// Coulomb's friction coefficient μ ≥ 0 (finite; default 0: frictionless,
    /// and then the field is left out of every output). An island with any
    /// contact of μ > 0 is solved by the friction path (README, "Friction").
    #[serde(default, skip_serializing_if = "is_zero")]
    pub friction: f64,
    /// The first tangent t₁ of the contact's friction frame, given by the
    /// caller (unit and orthogonal to the normal, to 1e-6); then
    /// t₂ = n × t₁. Default None: the tangent basis of the
    /// normal. Only the directions of the reported tangential impulse
    /// components depend on it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tangent: Option<[f64; 3]>,
}

fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

/// One simulation instance at one instant.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// The bodies, indexed by the contacts' `a` and `b`.
    pub bodies: Vec<Body>,
    /// The contacts.
    pub contacts: Vec<Contact>,
}

/// Relative tolerance on |n| = 1 (so that normals written with 7 digits pass).
pub const NORMAL_TOL: f64 = 1e-6;

impl Body {
    /// A body at rest with mass `mass` (∞ for static) and a diagonal inverse inertia.
    pub fn new(inv_mass: f64, inv_inertia_diag: [f64; 3], position: [f64; 3]) -> Self {
        let d = inv_inertia_diag;
        Body {
            inv_mass,
            inv_inertia: [[d[0], 0.0, 0.0], [0.0, d[1], 0.0], [0.0, 0.0, d[2]]],
            position,
            velocity: [0.0; 3],
            angular_velocity: [0.0; 3],
        }
    }

    /// A static body (inv_mass 0, inv_inertia 0) at `position`.
    pub fn fixed(position: [f64; 3]) -> Self {
        Body::new(0.0, [0.0; 3], position)
    }

    /// I⁻¹ as a glam matrix.
    pub fn inv_inertia_mat(&self) -> DMat3 {
        DMat3::from_cols_array_2d(&self.inv_inertia).transpose()
    }

    /// The centre of mass as a vector.
    pub fn position(&self) -> DVec3 {
        DVec3::from_array(self.position)
    }
    /// The linear velocity as a vector.
    pub fn velocity(&self) -> DVec3 {
        DVec3::from_array(self.velocity)
    }
    /// The angular velocity as a vector.
    pub fn angular_velocity(&self) -> DVec3 {
        DVec3::from_array(self.angular_velocity)
    }

    /// True when no impulse can move this body.
    pub fn is_static(&self) -> bool {
        self.inv_mass == 0.0 && self.inv_inertia.iter().flatten().all(|&v| v == 0.0)
    }

    /// Checks the body's fields; `item` names it in errors (rendered only
    /// when a check fails: pass `format_args!(..)` rather than `&format!(..)`).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `item` and the first field at fault.
    // Long (about 90 lines) on purpose: one check per field, in the order of
    // the format, each naming the field.
    pub fn validate(&self, item: impl Display) -> Result<(), Error> {
        let item = &item;
        if !self.inv_mass.is_finite() {
            return Err(Error::invalid(item, "inv_mass", "not a finite number"));
        }
        if self.inv_mass < 0.0 {
            return Err(Error::invalid(
                item,
                "inv_mass",
                format!("{} is negative", self.inv_mass),
            ));
        }
        for (name, v) in [
            ("position", &self.position),
            ("velocity", &self.velocity),
            ("angular_velocity", &self.angular_velocity),
        ] {
            if let Some(i) = v.iter().position(|x| !x.is_finite()) {
                return Err(Error::invalid(
                    item,
                    format!("{name}[{i}]"),
                    "not a finite number",
                ));
            }
        }
        let a = &self.inv_inertia;
        for i in 0..3 {
            for j in 0..3 {
                if !a[i][j].is_finite() {
                    return Err(Error::invalid(
                        item,
                        format!("inv_inertia[{i}][{j}]"),
                        "not a finite number",
                    ));
                }
            }
        }
        let scale = a.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
        let tol = 1e-9 * scale;
        for i in 0..3 {
            for j in 0..i {
                if (a[i][j] - a[j][i]).abs() > tol {
                    return Err(Error::invalid(
                        item,
                        "inv_inertia",
                        format!(
                            "not symmetric: [{i}][{j}] = {} but [{j}][{i}] = {}",
                            a[i][j], a[j][i]
                        ),
                    ));
                }
            }
        }
        // Positive semidefinite: every principal minor ≥ 0 (to rounding).
        let minors = [
            ("diagonal entry [0][0]", a[0][0], scale),
            ("diagonal entry [1][1]", a[1][1], scale),
            ("diagonal entry [2][2]", a[2][2], scale),
            (
                "minor {0,1}",
                a[0][0] * a[1][1] - a[0][1] * a[1][0],
                scale * scale,
            ),
            (
                "minor {0,2}",
                a[0][0] * a[2][2] - a[0][2] * a[2][0],
                scale * scale,
            ),
            (
                "minor {1,2}",
                a[1][1] * a[2][2] - a[1][2] * a[2][1],
                scale * scale,
            ),
            (
                "determinant",
                self.inv_inertia_mat().determinant(),
                scale * scale * scale,
            ),
        ];
        for (what, v, s) in minors {
            if v < -1e-9 * s {
                return Err(Error::invalid(
                    item,
                    "inv_inertia",
                    format!("not positive semidefinite: {what} is {v}"),
                ));
            }
        }
        Ok(())
    }
}

impl Contact {
    /// A contact without an id: normal `normal` (unit, from b to a) at
    /// `point`, between body `a` and body `b` (None: the static world).
    pub fn new(
        a: usize,
        b: Option<usize>,
        point: [f64; 3],
        normal: [f64; 3],
        restitution: f64,
    ) -> Self {
        Contact {
            a,
            b,
            point,
            normal,
            restitution,
            id: None,
            bias: 0.0,
            friction: 0.0,
            tangent: None,
        }
    }

    /// The same contact with friction coefficient `mu`.
    pub fn with_friction(mut self, mu: f64) -> Self {
        self.friction = mu;
        self
    }

    /// The contact's friction frame (t₁, t₂): the caller's tangent t₁ with
    /// t₂ = n × t₁, or the tangent basis of the normal.
    /// Right-handed: t₁ × t₂ = n.
    pub fn tangents(&self) -> (DVec3, DVec3) {
        let n = self.normal();
        match self.tangent {
            Some(t) => {
                let t1 = DVec3::from_array(t);
                (t1, n.cross(t1))
            }
            None => tangent_basis(n),
        }
    }

    /// The contact point as a vector.
    pub fn point(&self) -> DVec3 {
        DVec3::from_array(self.point)
    }
    /// The normal as a vector.
    pub fn normal(&self) -> DVec3 {
        DVec3::from_array(self.normal)
    }

    /// Checks the contact against the scene's bodies; `item` names it in
    /// errors (rendered only when a check fails).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `item` and the first field at fault (a body
    /// index out of range among them).
    pub fn validate(&self, item: impl Display, bodies: &[Body]) -> Result<(), Error> {
        let item = &item;
        let nb = bodies.len();
        if self.a >= nb {
            return Err(Error::invalid(
                item,
                "a",
                format!("body index {} out of range (scene has {nb} bodies)", self.a),
            ));
        }
        if let Some(b) = self.b {
            if b >= nb {
                return Err(Error::invalid(
                    item,
                    "b",
                    format!("body index {b} out of range (scene has {nb} bodies)"),
                ));
            }
            if b == self.a {
                return Err(Error::invalid(item, "b", format!("same body as a ({b})")));
            }
        }
        if let Some(i) = self.point.iter().position(|x| !x.is_finite()) {
            return Err(Error::invalid(
                item,
                format!("point[{i}]"),
                "not a finite number",
            ));
        }
        if let Some(i) = self.normal.iter().position(|x| !x.is_finite()) {
            return Err(Error::invalid(
                item,
                format!("normal[{i}]"),
                "not a finite number",
            ));
        }
        let len = self.normal().length();
        if len == 0.0 {
            return Err(Error::invalid(item, "normal", "zero vector"));
        }
        if (len - 1.0).abs() > NORMAL_TOL {
            return Err(Error::invalid(
                item,
                "normal",
                format!("not a unit vector (length {len})"),
            ));
        }
        if !self.restitution.is_finite() || !(0.0..=1.0).contains(&self.restitution) {
            return Err(Error::invalid(
                item,
                "restitution",
                format!("{} is not in [0, 1]", self.restitution),
            ));
        }
        self.validate_friction(item)?;
        let a_static = bodies[self.a].is_static();
        let b_static = self.b.is_none_or(|b| bodies[b].is_static());
        if a_static && b_static {
            return Err(Error::invalid(
                item,
                "a",
                "neither body of the contact can move (both static)",
            ));
        }
        if !self.bias.is_finite() {
            return Err(Error::invalid(item, "bias", "not a finite number"));
        }
        Ok(())
    }
}

impl Contact {
    /// Checks `friction` and `tangent`; `item` names the contact.
    fn validate_friction(&self, item: &impl Display) -> Result<(), Error> {
        if !self.friction.is_finite() || self.friction < 0.0 {
            return Err(Error::invalid(
                item,
                "friction",
                format!("{} is not a finite number ≥ 0", self.friction),
            ));
        }
        let Some(t) = self.tangent else {
            return Ok(());
        };
        if let Some(i) = t.iter().position(|x| !x.is_finite()) {
            return Err(Error::invalid(
                item,
                format!("tangent[{i}]"),
                "not a finite number",
            ));
        }
        let t = DVec3::from_array(t);
        if (t.length() - 1.0).abs() > NORMAL_TOL {
            return Err(Error::invalid(
                item,
                "tangent",
                format!("not a unit vector (length {})", t.length()),
            ));
        }
        let cos = t.dot(self.normal() / self.normal().length());
        if cos.abs() > NORMAL_TOL {
            return Err(Error::invalid(
                item,
                "tangent",
                format!("not orthogonal to the normal (t₁·n = {cos})"),
            ));
        }
        Ok(())
    }
}

impl Scene {
    /// Whether any contact has friction (μ > 0).
    pub fn has_friction(&self) -> bool {
        self.contacts.iter().any(|c| c.friction > 0.0)
    }

    /// Checks every body and contact; `item` names the scene in errors
    /// (e.g. "scene 3", or `format_args!("scene {i}")`: names are rendered
    /// only when a check fails, so a passing check allocates nothing).
    /// The first failure is returned.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the scene, its body or contact, and the field.
    pub fn validate(&self, item: impl Display) -> Result<(), Error> {
        for (i, b) in self.bodies.iter().enumerate() {
            b.validate(format_args!("{item}, body {i}"))?;
        }
        for (i, c) in self.contacts.iter().enumerate() {
            c.validate(format_args!("{item}, contact {i}"), &self.bodies)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ball() -> Body {
        Body::new(1.0, [2.5; 3], [0.0, 1.0, 0.0])
    }

    fn ground_contact() -> Contact {
        Contact {
            a: 0,
            b: None,
            point: [0.0; 3],
            normal: [0.0, 1.0, 0.0],
            restitution: 0.5,
            id: None,
            bias: 0.0,
            friction: 0.0,
            tangent: None,
        }
    }

    #[test]
    fn bad_fields_are_named() {
        let mut b = ball();
        b.inv_mass = -1.0;
        assert!(b
            .validate("body 0")
            .unwrap_err()
            .to_string()
            .contains("inv_mass"));
        let mut b = ball();
        b.inv_inertia[0][1] = 1.0;
        let e = b.validate("body 0").unwrap_err().to_string();
        assert!(e.contains("not symmetric"), "{e}");
        let mut b = ball();
        b.inv_inertia[2][2] = -1.0;
        assert!(b
            .validate("body 0")
            .unwrap_err()
            .to_string()
            .contains("semidefinite"));
        let mut b = ball();
        b.velocity[1] = f64::NAN;
        assert!(b
            .validate("body 0")
            .unwrap_err()
            .to_string()
            .contains("velocity[1]"));

        let s = |c: Contact| Scene {
            bodies: vec![ball()],
            contacts: vec![c],
        };
        let mut c = ground_contact();
        c.normal = [0.0; 3];
        assert!(s(c)
            .validate("scene 0")
            .unwrap_err()
            .to_string()
            .contains("zero vector"));
        let mut c = ground_contact();
        c.normal = [0.0, 2.0, 0.0];
        assert!(s(c)
            .validate("scene 0")
            .unwrap_err()
            .to_string()
            .contains("unit"));
        let mut c = ground_contact();
        c.b = Some(7);
        let e = s(c).validate("scene 0").unwrap_err().to_string();
        assert!(
            e.contains("scene 0, contact 0") && e.contains("`b`") && e.contains("out of range"),
            "{e}"
        );
        assert!(s(ground_contact()).validate("scene 0").is_ok());
        let mut c = ground_contact();
        c.friction = -0.5;
        let e = s(c).validate("scene 0").unwrap_err().to_string();
        assert!(e.contains("contact 0") && e.contains("`friction`"), "{e}");
        let mut c = ground_contact();
        c.friction = f64::INFINITY;
        assert!(s(c).validate("scene 0").is_err());
        let mut c = ground_contact();
        c.tangent = Some([0.0, 1.0, 0.0]);
        let e = s(c).validate("scene 0").unwrap_err().to_string();
        assert!(e.contains("`tangent`") && e.contains("orthogonal"), "{e}");
        let mut c = ground_contact();
        c.tangent = Some([0.0, 0.0, 1.0]);
        c.friction = 0.4;
        let (t1, t2) = c.tangents();
        assert_eq!((t1, t2), (DVec3::Z, DVec3::X));
        assert!(s(c).validate("scene 0").is_ok());
    }

    /// The error texts, byte for byte, whether the scene is named by a
    /// `&str` or by `format_args!` (rendered only when a check fails).
    #[test]
    fn error_texts_are_exact() {
        let scene = |b: Body, c: Contact| Scene {
            bodies: vec![ball(), b],
            contacts: vec![ground_contact(), c],
        };
        let mut bad_body = ball();
        bad_body.inv_mass = -1.0;
        let mut zero_normal = ground_contact();
        zero_normal.normal = [0.0; 3];
        let mut no_body = ground_contact();
        no_body.b = Some(7);
        let mut rough = ground_contact();
        rough.friction = -0.5;
        let mut bad_tangent = ground_contact();
        bad_tangent.tangent = Some([1.0, f64::NAN, 0.0]);
        let cases = [
            (
                scene(bad_body, ground_contact()),
                "scene 3, body 1: field `inv_mass`: -1 is negative",
            ),
            (
                scene(ball(), zero_normal),
                "scene 3, contact 1: field `normal`: zero vector",
            ),
            (
                scene(ball(), no_body),
                "scene 3, contact 1: field `b`: body index 7 out of range (scene has 2 bodies)",
            ),
            (
                scene(ball(), rough),
                "scene 3, contact 1: field `friction`: -0.5 is not a finite number ≥ 0",
            ),
            (
                scene(ball(), bad_tangent),
                "scene 3, contact 1: field `tangent[1]`: not a finite number",
            ),
        ];
        let i = 3;
        for (s, want) in cases {
            assert_eq!(s.validate("scene 3").unwrap_err().to_string(), want);
            let e = s.validate(format_args!("scene {i}")).unwrap_err();
            assert_eq!(e.to_string(), want);
        }
        let mut b = ball();
        b.inv_inertia[1][0] = 1.0;
        assert_eq!(
            b.validate(format_args!("scene {i}, body {}", 0))
                .unwrap_err()
                .to_string(),
            "scene 3, body 0: field `inv_inertia`: not symmetric: [1][0] = 1 but [0][1] = 0"
        );
    }
}
