//! Assembly of a frictional island: per contact the Jacobian rows of its
//! normal n and tangents t₁, t₂, and per island the Delassus matrix
//! W = J M⁻¹ Jᵀ (3k × 3k, interleaved per contact) and the free velocity q.
//! Then the impulses stage: the bodies' velocities after the impulse vectors.
//! CPU f64 twin of the future WGSL stages of the same names
//! (`assemble_friction_contacts`, `assemble_friction_island`,
//! `apply_friction_impulses`).
//!
//! # Derivation
//! A direction d at the contact (d = n, t₁ or t₂) has, like the normal of
//! the frictionless problem (`src/cpu/assembly.rs`, its derivation), the Jacobian
//! row J_d = [d, r_a × d, −d, −r_b × d] and the response M⁻¹ J_dᵀ; so each
//! direction is assembled by [`assemble_contact`] with d in place of n, and
//! W's entry for direction α of contact i and β of contact j is
//! [`matrix_entry`] of those rows: the sum over the dynamic bodies the two
//! contacts share (static bodies and the world contribute nothing).
//!
//! q: the normal entry is [`normal_q`] of v_rel = (ṗ_a − ṗ_b)·n (restitution
//! and the contact's bias, e.g. time stepping's gap φ/Δt), the same q as the
//! LCP path, one function; a tangent entry is t·(ṗ_a − ṗ_b), no restitution
//! and no bias.
//!
//! # Packed layout (for the GPU twin)
//! Per island of k contacts, in one storage buffer of the batch's scalar
//! type, at the island's offset `Σ 9k²` of the islands before it: W as 9k²
//! scalars row-major, entry (3i + α, 3j + β) for contact i direction α and
//! contact j direction β (α, β: 0 normal, 1 t₁, 2 t₂); q (3k) and μ (k) in
//! two more buffers at offsets `Σ 3k` and `Σ k`. Per contact the rows are
//! three [`ContactRow`]s (jacobian 12, response 12, q 1) in the order n, t₁, t₂.

use glam::{DMat3, DVec3};

use super::problem::FrictionProblem;
use crate::cpu::assembly::{assemble_contact, dynamic_sides, normal_q, ContactRow};
use crate::cpu::impulses::{velocities_after, BodyVelocity};
use crate::islands::Island;
use crate::scene::{Body, Contact, Scene};

#[cfg(doc)]
use crate::cpu::assembly::matrix_entry;

/// The three rows of one contact: normal, t₁, t₂. `rows[0]` is exactly the
/// frictionless path's row (q with restitution); the tangents' q is the
/// sliding velocity t·(ṗ_a − ṗ_b).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrictionContactRows {
    /// n, t₁, t₂ rows.
    pub rows: [ContactRow; 3],
    /// The directions n, t₁, t₂ (world frame).
    pub frame: [DVec3; 3],
}

/// Assembles one contact's three rows (stage `assemble_friction_contacts`,
/// one invocation per contact): the normal row is `assemble_contact`'s;
/// each tangent's is that of the same contact with normal t, no
/// restitution and no bias (q = t·(ṗ_a − ṗ_b): every normal-only term of q
/// switched off, so that tangents keep the bare sliding velocity), built by
/// [`tangent_row`] from what the three directions share.
pub fn assemble_friction_contact(bodies: &[Body], c: &Contact) -> FrictionContactRows {
    let (t1, t2) = c.tangents();
    let normal = assemble_contact(bodies, c);
    let shared = Lever::of(bodies, c);
    FrictionContactRows {
        rows: [
            normal,
            tangent_row(&normal, &shared, t1),
            tangent_row(&normal, &shared, t2),
        ],
        frame: [c.normal(), t1, t2],
    }
}

/// What a contact's rows share whatever their direction: each body's lever
/// arm r, I⁻¹ and 1/m, and the relative point velocity ṗ_a − ṗ_b.
struct Lever {
    a: (DVec3, DMat3, f64),
    b: Option<(DVec3, DMat3, f64)>,
    pdot: DVec3,
}

impl Lever {
    /// The same quantities, in the same operations, as `assemble_contact`.
    fn of(bodies: &[Body], c: &Contact) -> Lever {
        let p = c.point();
        let body = |i: usize| {
            let b = &bodies[i];
            let r = p - b.position();
            (
                (r, b.inv_inertia_mat(), b.inv_mass),
                b.velocity() + b.angular_velocity().cross(r),
            )
        };
        let (a, mut pdot) = body(c.a);
        let b = c.b.map(|i| {
            let (side, v) = body(i);
            pdot -= v;
            side
        });
        Lever { a, b, pdot }
    }
}

/// The row of direction d as `assemble_contact` builds it for the contact
/// with normal d, restitution 0 and bias 0, bit for bit: K is the normal
/// row's (it does not depend on the direction), the rest from `shared`.
fn tangent_row(normal: &ContactRow, shared: &Lever, d: DVec3) -> ContactRow {
    let mut jacobian = [0.0; 12];
    let mut response = [0.0; 12];
    let (ra, ia, ma) = shared.a;
    let ra_d = ra.cross(d);
    jacobian[0..3].copy_from_slice(&d.to_array());
    jacobian[3..6].copy_from_slice(&ra_d.to_array());
    response[0..3].copy_from_slice(&(d * ma).to_array());
    response[3..6].copy_from_slice(&(ia * ra_d).to_array());
    if let Some((rb, ib, mb)) = shared.b {
        let rb_d = rb.cross(d);
        jacobian[6..9].copy_from_slice(&(-d).to_array());
        jacobian[9..12].copy_from_slice(&(-rb_d).to_array());
        response[6..9].copy_from_slice(&(-d * mb).to_array());
        response[9..12].copy_from_slice(&(-(ib * rb_d)).to_array());
    }
    let v_rel = shared.pdot.dot(d);
    ContactRow {
        k: normal.k,
        jacobian,
        response,
        v_rel,
        q: normal_q(v_rel, 0.0, 0.0),
    }
}

/// Assembles every contact of a scene.
pub fn assemble_friction_contacts(scene: &Scene) -> Vec<FrictionContactRows> {
    scene
        .contacts
        .iter()
        .map(|c| assemble_friction_contact(&scene.bodies, c))
        .collect()
}

/// Assembles one island's frictional problem (stage
/// `assemble_friction_island`): W (3k × 3k, interleaved), q (3k) and μ (k),
/// over the island's contacts in order.
///
/// W's entries are those of [`matrix_entry`] over the rows, bit for bit,
/// but only the pairs of contacts that share a dynamic body are visited
/// (W's block sparsity: a contact couples only with those): per dynamic
/// body, the contacts touching it (a side each), and per pair of them the
/// 3 × 3 block's body term J_iα · M⁻¹ J_jβᵀ added to W, which starts at
/// zero. A pair shares at most two bodies, so each entry is `0 + x` or
/// `0 + x + y` in some order, the same number as `matrix_entry` gives
/// (two terms add commutatively in IEEE arithmetic).
pub fn assemble_friction_island(
    scene: &Scene,
    rows: &[FrictionContactRows],
    island: &Island,
) -> FrictionProblem {
    let mut p = FrictionProblem {
        w: Vec::new(),
        q: Vec::new(),
        mu: Vec::new(),
    };
    assemble_friction_island_into(scene, rows, island, &mut p);
    p
}

/// [`assemble_friction_island`] into `out`, reusing its buffers (a thread
/// that assembles island after island allocates W once).
pub fn assemble_friction_island_into(
    scene: &Scene,
    rows: &[FrictionContactRows],
    island: &Island,
    out: &mut FrictionProblem,
) {
    let k = island.len();
    let n = 3 * k;
    // (body, contact in the island, side) for every dynamic side, grouped
    // by body.
    let mut touches: Vec<(usize, usize, usize)> = Vec::with_capacity(2 * k);
    for (i, &c) in island.contacts.iter().enumerate() {
        for (side, body) in dynamic_sides(scene, &scene.contacts[c])
            .into_iter()
            .enumerate()
        {
            if let Some(body) = body {
                touches.push((body, i, side));
            }
        }
    }
    touches.sort_unstable();
    // Each side's 6-entry parts of its three rows, found once (the pair
    // loop below reads them per partner, without bounds checks).
    let sides: Vec<Side> = touches
        .iter()
        .map(|&(_, i, side)| Side::of(&rows[island.contacts[i]], i, side))
        .collect();
    let w = &mut out.w;
    w.clear();
    w.resize(n * n, 0.0);
    let mut start = 0;
    for group in touches.chunk_by(|x, y| x.0 == y.0) {
        let group_sides = &sides[start..start + group.len()];
        start += group.len();
        for si in group_sides {
            for sj in group_sides {
                let block = body_block(&si.jacobian, &sj.response);
                let at = 3 * si.contact * n + 3 * sj.contact;
                for (a, terms) in block.iter().enumerate() {
                    let out = &mut w[at + a * n..at + a * n + 3];
                    out[0] += terms[0];
                    out[1] += terms[1];
                    out[2] += terms[2];
                }
            }
        }
    }
    out.q.clear();
    out.q.extend(
        island
            .contacts
            .iter()
            .flat_map(|&c| rows[c].rows.map(|r| r.q)),
    );
    out.mu.clear();
    out.mu
        .extend(island.contacts.iter().map(|&c| scene.contacts[c].friction));
}

/// One contact's side (one dynamic body) in an island: its index in the
/// island and, per direction n, t₁, t₂, the side's 6 entries of J and of
/// M⁻¹ Jᵀ (borrowed from the contact's rows: nothing is copied).
struct Side<'a> {
    contact: usize,
    jacobian: [&'a [f64; 6]; 3],
    response: [&'a [f64; 6]; 3],
}

impl<'a> Side<'a> {
    /// Side `side` (0: body a, 1: body b) of contact number `contact` of
    /// the island, from its rows.
    fn of(rows: &'a FrictionContactRows, contact: usize, side: usize) -> Self {
        let part = |v: &'a [f64; 12]| -> &'a [f64; 6] {
            v[6 * side..6 * side + 6].try_into().expect("6 entries")
        };
        Side {
            contact,
            jacobian: rows.rows.each_ref().map(|r| part(&r.jacobian)),
            response: rows.rows.each_ref().map(|r| part(&r.response)),
        }
    }
}

/// One body's terms of a 3 × 3 block of W: entry (α, β) is J_α · (M⁻¹ J_βᵀ)
/// over that body's 6 entries, summed in order k = 0..6 as [`matrix_entry`]
/// sums them, the nine sums side by side (the compiler keeps them in vector
/// registers; each is the same chain of additions, so bit for bit
/// `matrix_entry`'s term up to the sign of a zero sum, which the entry's
/// `0 + term` erases).
#[inline]
fn body_block(jacobian: &[&[f64; 6]; 3], response: &[&[f64; 6]; 3]) -> [[f64; 3]; 3] {
    let [r0, r1, r2] = response;
    let row = |j: &[f64; 6]| {
        let mut s = [j[0] * r0[0], j[0] * r1[0], j[0] * r2[0]];
        for k in 1..6 {
            s = [
                s[0] + j[k] * r0[k],
                s[1] + j[k] * r1[k],
                s[2] + j[k] * r2[k],
            ];
        }
        s
    };
    [row(jacobian[0]), row(jacobian[1]), row(jacobian[2])]
}

/// One island of a scene and its frictional problem.
#[derive(Clone, Debug, PartialEq)]
pub struct FrictionIsland {
    /// The scene's contact indices, in the order of the problem's contacts.
    pub contacts: Vec<usize>,
    /// Its W, q and μ.
    pub problem: FrictionProblem,
}

/// Every island of a validated scene with its frictional problem (what the
/// friction path of [`crate::Solver::solve_scenes`] solves).
pub fn friction_islands(scene: &Scene) -> Vec<FrictionIsland> {
    let built = crate::build::FrictionBuilt::new(scene);
    let problems = built.problems(scene);
    built
        .islands
        .into_iter()
        .zip(problems)
        .map(|(isl, problem)| FrictionIsland {
            contacts: isl.contacts,
            problem,
        })
        .collect()
}

impl Scene {
    /// Checks the scene (errors name `item`) and returns its islands with
    /// their frictional problems, assembled in f64 (μ = 0 contacts included).
    #[cfg(test)]
    pub(crate) fn friction_islands(&self, item: &str) -> Result<Vec<FrictionIsland>, crate::Error> {
        self.validate(item)?;
        Ok(friction_islands(self))
    }
}

/// The impulse vector of a contact in the world frame from its local
/// reaction (r_n, r_t₁, r_t₂): r_n n + r_t₁ t₁ + r_t₂ t₂.
pub fn world_impulse(rows: &FrictionContactRows, r: [f64; 3]) -> DVec3 {
    rows.frame[0] * r[0] + rows.frame[1] * r[1] + rows.frame[2] * r[2]
}

/// Applies every contact's local reaction `r[c]` (stage
/// `apply_friction_impulses`): body a gains Σ_α r_α M⁻¹ J_αᵀ (its
/// `response` blocks), body b the b blocks (already negative).
pub fn apply_friction_impulses(
    scene: &Scene,
    rows: &[FrictionContactRows],
    r: &[[f64; 3]],
) -> Vec<BodyVelocity> {
    let pushes = scene
        .contacts
        .iter()
        .zip(rows)
        .zip(r)
        .flat_map(|((c, row), ri)| {
            row.rows
                .iter()
                .zip(ri)
                .map(move |(dir, &z)| (c, &dir.response, z))
        });
    velocities_after(scene, pushes)
}

/// Local velocity (u_n, u_t₁, u_t₂) of every contact from the bodies'
/// velocities: each direction's (ṗ_a − ṗ_b)·d.
#[cfg(test)]
pub fn local_velocities(scene: &Scene, velocities: &[BodyVelocity]) -> Vec<[f64; 3]> {
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
            let (t1, t2) = c.tangents();
            [d.dot(c.normal()), d.dot(t1), d.dot(t2)]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cpu::assembly::{assemble_contacts, assemble_island};
    use crate::generate::{random_island, Rng};
    use crate::islands::find_islands;

    /// Random islands of 1 to 8 contacts (one or two dynamic bodies per
    /// contact) and a world's 4-box stack (contacts shared by two dynamic
    /// boxes).
    fn scenes(seed: u64) -> Vec<Scene> {
        let mut rng = Rng::new(seed);
        let mut scenes: Vec<Scene> = (1..9).map(|n| random_island(&mut rng, n, 10.0)).collect();
        let world =
            crate::world::generate::standard_world(crate::world::generate::WorldKind::Stack, 4, 1);
        scenes.push(crate::world::step::prepare(&world, 0, 0.01).scene);
        scenes
    }

    #[test]
    fn tangent_rows_are_assemble_contact_along_the_tangent_bit_for_bit() {
        let bits = |r: &ContactRow| {
            let k = r.k.to_cols_array();
            k.iter()
                .chain(&r.jacobian)
                .chain(&r.response)
                .chain([&r.v_rel, &r.q])
                .map(|v| v.to_bits())
                .collect::<Vec<u64>>()
        };
        for scene in &scenes(23) {
            for c in &scene.contacts {
                let rows = assemble_friction_contact(&scene.bodies, c);
                let (t1, t2) = c.tangents();
                for (row, d) in rows.rows[1..].iter().zip([t1, t2]) {
                    let mut dc = c.clone();
                    dc.normal = d.to_array();
                    dc.restitution = 0.0;
                    dc.bias = 0.0;
                    assert_eq!(bits(row), bits(&assemble_contact(&scene.bodies, &dc)));
                }
                assert_eq!(
                    bits(&rows.rows[0]),
                    bits(&assemble_contact(&scene.bodies, c))
                );
            }
        }
    }

    #[test]
    fn w_is_matrix_entry_of_the_rows_bit_for_bit() {
        for scene in &scenes(19) {
            let rows = assemble_friction_contacts(scene);
            for isl in find_islands(scene) {
                let p = assemble_friction_island(scene, &rows, &isl);
                let n = 3 * isl.len();
                for (i, &ci) in isl.contacts.iter().enumerate() {
                    for (j, &cj) in isl.contacts.iter().enumerate() {
                        let (si, sj) = (
                            dynamic_sides(scene, &scene.contacts[ci]),
                            dynamic_sides(scene, &scene.contacts[cj]),
                        );
                        for a in 0..3 {
                            for b in 0..3 {
                                let want = crate::cpu::assembly::matrix_entry(
                                    si,
                                    &rows[ci].rows[a],
                                    sj,
                                    &rows[cj].rows[b],
                                );
                                let got = p.w[(3 * i + a) * n + 3 * j + b];
                                assert_eq!(got.to_bits(), want.to_bits(), "{i} {j} {a} {b}");
                            }
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn the_normal_block_is_the_lcp_and_w_is_symmetric_and_consistent() {
        let mut rng = Rng::new(7);
        for n in 1..6 {
            let mut scene = random_island(&mut rng, n, 10.0);
            for c in &mut scene.contacts {
                c.friction = 0.5;
            }
            let rows = assemble_friction_contacts(&scene);
            let lrows = assemble_contacts(&scene);
            for isl in find_islands(&scene) {
                let p = assemble_friction_island(&scene, &rows, &isl);
                let lcp = assemble_island(&scene, &lrows, &isl);
                let k = isl.len();
                let m = 3 * k;
                for i in 0..k {
                    assert_eq!(p.q[3 * i], lcp.q[i]);
                    for j in 0..k {
                        assert_eq!(p.w[3 * i * m + 3 * j], lcp.m[i * k + j]);
                    }
                }
                for i in 0..m {
                    for j in 0..m {
                        let (a, b) = (p.w[i * m + j], p.w[j * m + i]);
                        assert!((a - b).abs() <= 1e-12 * (1.0 + a.abs()), "{i} {j}");
                    }
                }
                // u = W r + q equals the local velocities after the impulses.
                let mut r = vec![[0.0; 3]; scene.contacts.len()];
                for (i, &c) in isl.contacts.iter().enumerate() {
                    r[c] = [1.0 + i as f64, 0.3, -0.2 * i as f64];
                }
                let flat: Vec<f64> = isl.contacts.iter().flat_map(|&c| r[c]).collect();
                let u = p.velocity(&flat);
                let after = local_velocities(&scene, &apply_friction_impulses(&scene, &rows, &r));
                for (i, &c) in isl.contacts.iter().enumerate() {
                    // Normal: restitution shifts q, not the velocities.
                    let e = scene.contacts[c].restitution * rows[c].rows[0].v_rel.min(0.0);
                    assert!((u[3 * i] - e - after[c][0]).abs() < 1e-9, "{n}");
                    for a in 1..3 {
                        assert!((u[3 * i + a] - after[c][a]).abs() < 1e-9, "{n}");
                    }
                }
            }
        }
    }
}
