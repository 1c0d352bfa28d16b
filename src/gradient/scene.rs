//! The vector–Jacobian product through assembly: ∂L/∂(bodies, contacts) of
//! a frictionless scene from ∂L/∂(impulses) and ∂L/∂(velocities after).
//!
//! # Derivation
//! Per contact i and body X on side s = ±1 (+1 for a, −1 for b; the
//! assembly's notation, `src/cpu/assembly.rs`), with r_X,i = p_i − x_X and
//! c_X,i = r_X,i × n_i (n_i as given, not renormalised):
//!
//! ```text
//! M_ij  = Σ_X s_iX s_jX (m_X n_i·n_j + c_X,iᵀ I_X c_X,j)   (dynamic X shared by i, j)
//! q_i   = v_rel,i + ε_i min(v_rel,i, 0) + b_i,   v_rel,i = Σ_X s_iX (v_X·n_i + ω_X·c_X,i)
//! v⁺_X  = v_X + Σ_i z_i s_iX m_X n_i,   ω⁺_X = ω_X + Σ_i z_i s_iX I_X c_X,i
//! ```
//!
//! (m = inverse mass, I = inverse inertia; (ω × r)·n = ω·(r × n)). Backwards,
//! from (∂L/∂z, ∂L/∂v⁺, ∂L/∂ω⁺):
//!
//! 1. the velocities after pass ∂L/∂v⁺ to v and ∂L/∂ω⁺ to ω, add
//!    s (m_X n_i·∂L/∂v⁺_X + (I_X c_X,i)·∂L/∂ω⁺_X) to ∂L/∂z_i (the
//!    contact's response row), and z_i s (n_i ∂L/∂v⁺_X, ∂L/∂ω⁺_X c_X,iᵀ,
//!    m_X ∂L/∂v⁺_X, I_Xᵀ ∂L/∂ω⁺_X) to (∂L/∂m_X, ∂L/∂I_X, ∂L/∂n_i, ∂L/∂c_X,i);
//! 2. each island's LCP product ([`super::lcp_vjp`]) gives G = ∂L/∂M and
//!    r = ∂L/∂q;
//! 3. q: ∂L/∂ε_i = r_i min(v_rel,i, 0), ∂L/∂b_i = r_i, and ρ_i =
//!    r_i (1 + ε_i [v_rel,i < 0]) to v_rel,i: s ρ_i n_i to ∂L/∂v_X,
//!    s ρ_i c_X,i to ∂L/∂ω_X, s ρ_i v_X to ∂L/∂n_i, s ρ_i ω_X to ∂L/∂c_X,i;
//! 4. M: for every G_ij and shared dynamic X, with σ = s_iX s_jX:
//!    σ G_ij n_i·n_j to ∂L/∂m_X, σ G_ij c_X,i c_X,jᵀ to ∂L/∂I_X, σ G_ij m_X n_j
//!    to ∂L/∂n_i and σ G_ij m_X n_i to ∂L/∂n_j, σ G_ij I_X c_X,j to ∂L/∂c_X,i
//!    and σ G_ij I_Xᵀ c_X,i to ∂L/∂c_X,j;
//! 5. c = r × n: ∂L/∂n_i += ∂L/∂c × r, ∂L/∂r = n × ∂L/∂c, which goes to the
//!    point (+) and to the body's position (−).
//!
//! Each entry of I⁻¹ and of n is a separate variable (a symmetric
//! perturbation dI changes L by Σ_rc ∂L/∂I_rc dI_rc). Static bodies (and
//! the world) are not differentiated in their inverse mass and inertia:
//! making one dynamic would join islands, so those entries are 0; their
//! velocities, angular velocities and positions are (they enter v_rel).
//!
//! # Friction
//! Not differentiated: a scene with a contact of μ > 0 is an
//! [`Error::Invalid`] naming that contact and `friction` (the projected
//! model's implicit derivative is not implemented).

use glam::{DMat3, DVec3};

use super::{check_tolerance, check_vector, island_vjp, Derivative, LcpGradient};
use crate::build::Built;
use crate::cpu::assembly::dynamic_sides;
use crate::cpu::batch::parallel_map;
use crate::report::BodyVelocity;
use crate::{Error, Report, Scene, Status};

/// ∂L/∂ one body's fields (the names of [`crate::Body`]).
#[non_exhaustive]
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BodyGradient {
    /// ∂L/∂ inverse mass (0 for a static body).
    pub inv_mass: f64,
    /// ∂L/∂ each entry of the inverse inertia, rows as
    /// [`crate::Body::inv_inertia`] (0 for a static body).
    pub inv_inertia: [[f64; 3]; 3],
    /// ∂L/∂ centre of mass.
    pub position: [f64; 3],
    /// ∂L/∂ linear velocity before the impact.
    pub velocity: [f64; 3],
    /// ∂L/∂ angular velocity before the impact.
    pub angular_velocity: [f64; 3],
}

/// ∂L/∂ one contact's fields (the names of [`crate::Contact`]).
#[non_exhaustive]
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ContactGradient {
    /// ∂L/∂ contact point.
    pub point: [f64; 3],
    /// ∂L/∂ each component of the normal as given.
    pub normal: [f64; 3],
    /// ∂L/∂ coefficient of restitution.
    pub restitution: f64,
    /// ∂L/∂ velocity bias.
    pub bias: f64,
}

/// A scene's vector–Jacobian product.
#[non_exhaustive]
#[derive(Clone, Debug)]
pub struct SceneGradient {
    /// One per body, in the scene's order.
    pub bodies: Vec<BodyGradient>,
    /// One per contact, in the scene's order.
    pub contacts: Vec<ContactGradient>,
    /// Per island (in the order of the report's islands of the scene).
    pub islands: Vec<Derivative>,
    /// The worst of `islands` ([`Derivative::Exact`] for a scene without contacts).
    pub derivative: Derivative,
}

/// One frictionless scene (derivation in the module docs): given its
/// contacts' impulses (a report's [`crate::report::SceneReport::impulses`]),
/// ∂L/∂impulses and/or ∂L/∂(velocities after), one per body (None: 0),
/// ∂L/∂ every body's and contact's fields. `tolerance` as for
/// [`super::lcp_vjp`]; an island whose derivative is undefined passes
/// nothing through its M and q (its contacts still pass ∂L/∂(velocities
/// after) through their impulses).
///
/// # Errors
/// [`Error::Invalid`] naming "scene 0" and the field: the scene's own
/// checks, a contact with friction, `impulses`, `d_impulses` or
/// `d_velocities` of the wrong length or not finite, `tolerance` not in
/// [0, 1).
pub fn scene_vjp(
    scene: &Scene,
    impulses: &[f64],
    d_impulses: Option<&[f64]>,
    d_velocities: Option<&[BodyVelocity]>,
    tolerance: f64,
) -> Result<SceneGradient, Error> {
    check_tolerance(tolerance)?;
    scene_at(
        0,
        scene,
        impulses,
        d_impulses,
        d_velocities,
        tolerance,
        None,
    )
}

impl Report {
    /// [`scene_vjp`] for every scene of this report (solved from
    /// `scenes`), at its impulses, on every core. An island whose status is
    /// not a solution is [`Derivative::Undefined`] (one with several
    /// solutions at least [`Derivative::OneSided`]); the tolerance is the
    /// default [`crate::Settings::tolerance`] (a report does not keep its
    /// settings).
    ///
    /// # Errors
    /// "batch" and the field when `scenes`, `d_impulses` or `d_velocities`
    /// does not have one entry per scene; else as [`scene_vjp`], naming
    /// "scene s".
    pub fn scene_vjps(
        &self,
        scenes: &[Scene],
        d_impulses: Option<&[&[f64]]>,
        d_velocities: Option<&[&[BodyVelocity]]>,
    ) -> Result<Vec<SceneGradient>, Error> {
        let k = self.scenes.len();
        let count = |field: &str, got: usize| super::check_count(field, got, k);
        count("scenes", scenes.len())?;
        d_impulses.map_or(Ok(()), |d| count("d_impulses", d.len()))?;
        d_velocities.map_or(Ok(()), |d| count("d_velocities", d.len()))?;
        let tolerance = crate::Settings::default().tolerance;
        parallel_map(k, super::threads(), |s| {
            let statuses: Vec<Status> = self.islands[self.scenes[s].islands.clone()]
                .iter()
                .map(|i| i.status())
                .collect();
            scene_at(
                s,
                &scenes[s],
                &self.scenes[s].impulses,
                d_impulses.map(|d| d[s]),
                d_velocities.map(|d| d[s]),
                tolerance,
                Some(&statuses),
            )
        })
        .into_iter()
        .collect()
    }
}

/// A vector of 3 from an array.
fn v3(a: [f64; 3]) -> DVec3 {
    DVec3::from_array(a)
}

/// The derivative of one scene, `s` its name in errors; `statuses` (from a
/// report) mark islands without a solution undefined.
fn scene_at(
    s: usize,
    scene: &Scene,
    impulses: &[f64],
    d_impulses: Option<&[f64]>,
    d_velocities: Option<&[BodyVelocity]>,
    tolerance: f64,
    statuses: Option<&[Status]>,
) -> Result<SceneGradient, Error> {
    scene.validate(format_args!("scene {s}"))?;
    if let Some(c) = scene.contacts.iter().position(|c| c.friction > 0.0) {
        return Err(Error::invalid(
            format_args!("scene {s}, contact {c}"),
            "friction",
            "μ > 0 is not differentiable here: gradients cover frictionless scenes only",
        ));
    }
    let (nb, nc) = (scene.bodies.len(), scene.contacts.len());
    let item = format_args!("scene {s}");
    check_vector(item, "impulses", impulses, nc)?;
    if let Some(d) = d_impulses {
        check_vector(item, "d_impulses", d, nc)?;
    }
    let zero = BodyVelocity {
        velocity: [0.0; 3],
        angular_velocity: [0.0; 3],
    };
    if let Some(d) = d_velocities {
        let flat: Vec<f64> = d
            .iter()
            .flat_map(|b| b.velocity.into_iter().chain(b.angular_velocity))
            .collect();
        // Six numbers per body: (velocity, angular_velocity).
        check_vector(item, "d_velocities", &flat, 6 * nb)?;
    }
    let dv = |x: usize| d_velocities.map_or(zero, |d| d[x]);
    let built = Built::new(scene);
    let mut bodies = vec![BodyGradient::default(); nb];
    let mut gm = vec![0.0; nb];
    let mut gi = vec![DMat3::ZERO; nb];
    let (mut gv, mut gw) = (vec![DVec3::ZERO; nb], vec![DVec3::ZERO; nb]);
    let mut gn = vec![DVec3::ZERO; nc];
    let mut gc = vec![[DVec3::ZERO; 2]; nc];
    let mut contacts = vec![ContactGradient::default(); nc];
    let sides: Vec<[Option<usize>; 2]> = scene.contacts.iter().map(|c| [Some(c.a), c.b]).collect();
    let dynamic: Vec<[Option<usize>; 2]> = scene
        .contacts
        .iter()
        .map(|c| dynamic_sides(scene, c))
        .collect();
    let sign = |k: usize| if k == 0 { 1.0 } else { -1.0 };
    let cvec = |i: usize, x: usize| {
        let c = &scene.contacts[i];
        (v3(c.point) - scene.bodies[x].position()).cross(c.normal())
    };
    // 1. The velocities after the impulses.
    for x in 0..nb {
        gv[x] += v3(dv(x).velocity);
        gw[x] += v3(dv(x).angular_velocity);
    }
    let mut gz: Vec<f64> = d_impulses.map_or_else(|| vec![0.0; nc], <[f64]>::to_vec);
    for i in 0..nc {
        let n = scene.contacts[i].normal();
        for (k, x) in dynamic[i].iter().enumerate() {
            let Some(x) = *x else { continue };
            let (s_, b, d) = (sign(k), &scene.bodies[x], dv(x));
            let (dlin, dang, ci) = (v3(d.velocity), v3(d.angular_velocity), cvec(i, x));
            let ib = b.inv_inertia_mat();
            gz[i] += s_ * (b.inv_mass * n.dot(dlin) + (ib * ci).dot(dang));
            let zi = impulses[i];
            gm[x] += zi * s_ * n.dot(dlin);
            gi[x] += zi * s_ * outer(dang, ci);
            gn[i] += zi * s_ * b.inv_mass * dlin;
            gc[i][k] += zi * s_ * (ib.transpose() * dang);
        }
    }
    // 2. Each island's LCP.
    let mut flags = Vec::with_capacity(built.islands.len());
    for (k, (island, lcp)) in built.islands.iter().zip(&built.lcps).enumerate() {
        let z: Vec<f64> = island.contacts.iter().map(|&c| impulses[c]).collect();
        let g: Vec<f64> = island.contacts.iter().map(|&c| gz[c]).collect();
        let mut grad: LcpGradient = island_vjp(k, lcp, &z, &g, None, tolerance)?;
        match statuses.map(|st| st[k]) {
            None | Some(Status::Solved) => {}
            Some(Status::MultipleSolutions) => {
                grad.derivative = grad.derivative.worst(Derivative::OneSided)
            }
            Some(_) => grad = LcpGradient::undefined(lcp.n()),
        }
        flags.push(grad.derivative);
        let n = island.len();
        // 3. q.
        for (a, &i) in island.contacts.iter().enumerate() {
            let c = &scene.contacts[i];
            let (r, v_rel) = (grad.q[a], built.rows[i].v_rel);
            contacts[i].restitution = r * v_rel.min(0.0);
            contacts[i].bias = r;
            let rho = r * if v_rel < 0.0 {
                1.0 + c.restitution
            } else {
                1.0
            };
            for (k, x) in sides[i].iter().enumerate() {
                let Some(x) = *x else { continue };
                let (s_, b) = (sign(k) * rho, &scene.bodies[x]);
                gv[x] += s_ * c.normal();
                gw[x] += s_ * cvec(i, x);
                gn[i] += s_ * b.velocity();
                gc[i][k] += s_ * b.angular_velocity();
            }
        }
        // 4. M.
        for (a, &i) in island.contacts.iter().enumerate() {
            for (bj, &j) in island.contacts.iter().enumerate() {
                let g = grad.m[a * n + bj];
                if g == 0.0 {
                    continue;
                }
                let (ni, nj) = (scene.contacts[i].normal(), scene.contacts[j].normal());
                for (ki, xi) in dynamic[i].iter().enumerate() {
                    for (kj, xj) in dynamic[j].iter().enumerate() {
                        let (Some(x), true) = (*xi, xi == xj) else {
                            continue;
                        };
                        let (sg, b) = (g * sign(ki) * sign(kj), &scene.bodies[x]);
                        let (ci, cj, ib) = (cvec(i, x), cvec(j, x), b.inv_inertia_mat());
                        gm[x] += sg * ni.dot(nj);
                        gi[x] += sg * outer(ci, cj);
                        gn[i] += sg * b.inv_mass * nj;
                        gn[j] += sg * b.inv_mass * ni;
                        gc[i][ki] += sg * (ib * cj);
                        gc[j][kj] += sg * (ib.transpose() * ci);
                    }
                }
            }
        }
    }
    // 5. c = r × n, r = p − x.
    for i in 0..nc {
        let c = &scene.contacts[i];
        let mut gp = DVec3::ZERO;
        for (k, x) in sides[i].iter().enumerate() {
            let Some(x) = *x else { continue };
            let r = c.point() - scene.bodies[x].position();
            gn[i] += gc[i][k].cross(r);
            let gr = c.normal().cross(gc[i][k]);
            gp += gr;
            bodies[x].position = (v3(bodies[x].position) - gr).to_array();
        }
        contacts[i].point = gp.to_array();
        contacts[i].normal = gn[i].to_array();
    }
    for (x, b) in bodies.iter_mut().enumerate() {
        b.velocity = gv[x].to_array();
        b.angular_velocity = gw[x].to_array();
        if !scene.bodies[x].is_static() {
            b.inv_mass = gm[x];
            // glam is column-major: row r of the result is row r of gi.
            b.inv_inertia = gi[x].transpose().to_cols_array_2d();
        }
    }
    let derivative = flags.iter().fold(Derivative::Exact, |a, &d| a.worst(d));
    Ok(SceneGradient {
        bodies,
        contacts,
        islands: flags,
        derivative,
    })
}

/// a bᵀ.
fn outer(a: DVec3, b: DVec3) -> DMat3 {
    DMat3::from_cols(a * b.x, a * b.y, a * b.z)
}
