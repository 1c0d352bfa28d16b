//! Assembly: per contact its K matrix, Jacobian row and q; per island the LCP
//! (M, q). CPU twin of `shaders/assembly.wgsl`, in f64.
//!
//! # Derivation (impulse-based contact: Mirtich 1996; Guendelman, Bridson
//! & Fedkiw 2003)
//! A unit impulse +n at the contact point on body a changes its velocity by
//! Δv = m_a⁻¹ n and Δω = I_a⁻¹ (r_a × n); body b gets the opposite. The
//! point velocity ṗ = v + ω × r changes accordingly, so the relative normal
//! velocity of contact i changes by
//!
//! ```text
//! Δv_rel,i = Σ_j M_ij z_j,   M_ij = J_i M⁻¹ J_jᵀ,
//! J_i = [n_i, r_a,i × n_i, −n_i, −r_b,i × n_i]
//! ```
//!
//! where only bodies shared by contacts i and j contribute. Written out per
//! shared body X with signs s = +1 when X is a and −1 when X is b:
//! M_ij = Σ_X s_i s_j (m_X⁻¹ n_i·n_j + (r_X,i × n_i)ᵀ I_X⁻¹ (r_X,j × n_j)).
//! On the diagonal this is n_iᵀ K_i n_i, with K the collision matrix
//! K = (m_a⁻¹ + m_b⁻¹) E − (r_a* I_a⁻¹ r_a* + r_b* I_b⁻¹ r_b*), r* the cross
//! product matrix (r × x = r* x).
//!
//! q_i = v_rel,i + ε_i min(v_rel,i, 0) + b_i ([`normal_q`]): Newton's
//! restitution on approaching contacts (v_rel⁺ ≥ −ε v_rel⁻), none on
//! separating ones, plus the contact's velocity bias b_i (time stepping puts
//! the gap there, b = φ/Δt; 0 for a single frame).

use glam::{DMat3, DVec3};

use crate::islands::Island;
use crate::lcp::Lcp;
use crate::scene::{Body, Contact, Scene};

/// What assembly computes for one contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactRow {
    /// K (3×3, world frame): the change of the relative point velocity of a
    /// against b per unit impulse vector at the point.
    pub k: DMat3,
    /// J = [n, r_a × n, −n, −r_b × n] (zeros for a missing b).
    pub jacobian: [f64; 12],
    /// M⁻¹ Jᵀ = [m_a⁻¹ n, I_a⁻¹(r_a × n), −m_b⁻¹ n, −I_b⁻¹(r_b × n)]: the change
    /// of (v_a, ω_a, v_b, ω_b) per unit impulse. Zero for static bodies.
    pub response: [f64; 12],
    /// (ṗ_a − ṗ_b)·n before the impulse; negative when approaching.
    pub v_rel: f64,
    /// v_rel + ε min(v_rel, 0) + bias ([`normal_q`]).
    pub q: f64,
}

/// r*: the matrix with r* x = r × x.
pub fn cross_matrix(r: DVec3) -> DMat3 {
    DMat3::from_cols(
        DVec3::new(0.0, r.z, -r.y),
        DVec3::new(-r.z, 0.0, r.x),
        DVec3::new(r.y, -r.x, 0.0),
    )
}

/// The normal q of a contact, the one formula every path uses (the shader's
/// twin is in `assembly.wgsl`, same order of operations):
/// q = v_rel + ε min(v_rel, 0) + b.
///
/// w = Mz + q ≥ 0 then reads v_rel⁺ ≥ −ε v_rel⁻ − b: Newton's restitution on
/// approach, and with b = φ/Δt the time stepper's gap condition
/// φ + Δt v_rel⁺ ≥ 0 (the time stepper chooses ε and b per contact; see
/// `crate::world::step`).
#[inline]
pub fn normal_q(v_rel: f64, restitution: f64, bias: f64) -> f64 {
    v_rel + restitution * v_rel.min(0.0) + bias
}

fn put(dst: &mut [f64; 12], at: usize, v: DVec3) {
    dst[at..at + 3].copy_from_slice(&v.to_array());
}

/// Assembles one contact (stage `assemble_contacts`, one invocation per contact).
pub fn assemble_contact(bodies: &[Body], c: &Contact) -> ContactRow {
    let n = c.normal();
    let p = c.point();
    let a = &bodies[c.a];
    let ra = p - a.position();
    let ia = a.inv_inertia_mat();
    let ra_x = cross_matrix(ra);
    let mut k = DMat3::IDENTITY * a.inv_mass - ra_x * ia * ra_x;
    let mut jacobian = [0.0; 12];
    let mut response = [0.0; 12];
    let ra_n = ra.cross(n);
    put(&mut jacobian, 0, n);
    put(&mut jacobian, 3, ra_n);
    put(&mut response, 0, n * a.inv_mass);
    put(&mut response, 3, ia * ra_n);
    let mut pdot = a.velocity() + a.angular_velocity().cross(ra);
    if let Some(bi) = c.b {
        let b = &bodies[bi];
        let rb = p - b.position();
        let ib = b.inv_inertia_mat();
        let rb_x = cross_matrix(rb);
        k += DMat3::IDENTITY * b.inv_mass - rb_x * ib * rb_x;
        let rb_n = rb.cross(n);
        put(&mut jacobian, 6, -n);
        put(&mut jacobian, 9, -rb_n);
        put(&mut response, 6, -n * b.inv_mass);
        put(&mut response, 9, -(ib * rb_n));
        pdot -= b.velocity() + b.angular_velocity().cross(rb);
    }
    let v_rel = pdot.dot(n);
    ContactRow {
        k,
        jacobian,
        response,
        v_rel,
        q: normal_q(v_rel, c.restitution, c.bias),
    }
}

/// Assembles every contact of a scene.
pub fn assemble_contacts(scene: &Scene) -> Vec<ContactRow> {
    scene
        .contacts
        .iter()
        .map(|c| assemble_contact(&scene.bodies, c))
        .collect()
}

/// Dot product of two 6-entry body blocks.
#[inline]
fn dot6(x: &[f64], y: &[f64]) -> f64 {
    x[..6].iter().zip(&y[..6]).map(|(a, b)| a * b).sum()
}

/// The bodies an impulse at contact `c` can move: [a, b], a static body (or
/// the world) as None. Static partners contribute no terms to M.
pub fn dynamic_sides(scene: &Scene, c: &Contact) -> [Option<usize>; 2] {
    let dynamic = |i: usize| (!scene.bodies[i].is_static()).then_some(i);
    [dynamic(c.a), c.b.and_then(dynamic)]
}

/// M_ij for contacts i and j: J_i · (M⁻¹ J_jᵀ) over the dynamic bodies they
/// share (`sides` from [`dynamic_sides`]). Side 0 is body a (entries 0..6),
/// side 1 body b (entries 6..12).
pub fn matrix_entry(
    sides_i: [Option<usize>; 2],
    ri: &ContactRow,
    sides_j: [Option<usize>; 2],
    rj: &ContactRow,
) -> f64 {
    let mut m = 0.0;
    for si in 0..2 {
        for sj in 0..2 {
            if sides_i[si].is_some() && sides_i[si] == sides_j[sj] {
                m += dot6(&ri.jacobian[6 * si..], &rj.response[6 * sj..]);
            }
        }
    }
    m
}

/// Assembles one island's LCP (stage `assemble_islands`): M_ij over the
/// island's contacts in order, and q.
pub fn assemble_island(scene: &Scene, rows: &[ContactRow], island: &Island) -> Lcp {
    let n = island.len();
    let sides: Vec<[Option<usize>; 2]> = island
        .contacts
        .iter()
        .map(|&c| dynamic_sides(scene, &scene.contacts[c]))
        .collect();
    let mut m = vec![0.0; n * n];
    for (i, &ci) in island.contacts.iter().enumerate() {
        for (j, &cj) in island.contacts.iter().enumerate() {
            m[i * n + j] = matrix_entry(sides[i], &rows[ci], sides[j], &rows[cj]);
        }
    }
    let q = island.contacts.iter().map(|&c| rows[c].q).collect();
    Lcp { m, q }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cross_matrix_is_the_cross_product() {
        let r = DVec3::new(1.0, -2.0, 3.0);
        let x = DVec3::new(0.5, 4.0, -1.0);
        assert!((cross_matrix(r) * x - r.cross(x)).length() < 1e-15);
    }

    #[test]
    fn restitution_acts_only_on_approach() {
        assert_eq!(normal_q(-2.0, 0.5, 0.0), -3.0);
        assert_eq!(normal_q(2.0, 0.5, 0.0), 2.0);
    }

    #[test]
    fn the_bias_adds_to_q_after_restitution() {
        assert_eq!(normal_q(-2.0, 0.5, 0.25), -2.75);
        assert_eq!(normal_q(2.0, 0.5, -0.5), 1.5);
    }
}
