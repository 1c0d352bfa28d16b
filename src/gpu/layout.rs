//! The memory layout shared by the shaders and their CPU twins.
//!
//! Integer records are `#[repr(C)]` Pod structs with the same fields, in the
//! same order, as the WGSL structs of the same name. Floating-point data is
//! a flat array of scalars (f32 or f64, the shader's `Scalar`) with fixed
//! strides and the named offsets below, so that one packed buffer can be
//! handed to a shader and, converted back to f64, to its CPU twin.
//!
//! | record (scalars)        | stride | fields at offset                                                    |
//! |-------------------------|--------|---------------------------------------------------------------------|
//! | body ([`BODY`])         | 20     | inv_mass 0, inv_inertia (rows) 1..10, position 10..13, velocity 13..16, angular_velocity 16..19 |
//! | contact ([`CONTACT`])   | 8      | point 0..3, normal 3..6, restitution 6, bias 7                       |
//! | contact row ([`ROW`])   | 36     | K (rows) 0..9, jacobian 9..21, response 21..33, v_rel 33, q 34       |
//! | island data             | n²+n   | M row-major 0..n², q n²..n²+n                                        |
//! | body velocity ([`VELOCITY`]) | 8 | velocity 0..3, angular_velocity 4..7                                 |

// The packed layouts' CPU twins (pack, unpack, assembly on the packed
// layout) are used by the stage tests that compare each shader with them.
#![cfg_attr(not(test), allow(dead_code))]

use bytemuck::{Pod, Zeroable};
use glam::DMat3;

use crate::cpu::assembly::{assemble_contact, ContactRow};
use crate::scene::{Body, Contact};

use super::Precision;

/// Offsets and stride of a packed body.
pub mod body {
    pub const INV_MASS: usize = 0;
    pub const INV_INERTIA: usize = 1;
    pub const POSITION: usize = 10;
    pub const VELOCITY: usize = 13;
    pub const ANGULAR_VELOCITY: usize = 16;
    pub const STRIDE: usize = 20;
}
pub use body::STRIDE as BODY;

/// Offsets and stride of a packed contact's scalars.
pub mod contact {
    pub const POINT: usize = 0;
    pub const NORMAL: usize = 3;
    pub const RESTITUTION: usize = 6;
    pub const BIAS: usize = 7;
    pub const STRIDE: usize = 8;
}
pub use contact::STRIDE as CONTACT;

/// Offsets and stride of a packed contact row (assembly's output).
pub mod row {
    pub const K: usize = 0;
    pub const JACOBIAN: usize = 9;
    pub const RESPONSE: usize = 21;
    pub const V_REL: usize = 33;
    pub const Q: usize = 34;
    pub const STRIDE: usize = 36;
}
pub use row::STRIDE as ROW;

/// Offsets and stride of a packed body velocity (impulses' output).
pub mod velocity {
    pub const VELOCITY: usize = 0;
    pub const ANGULAR_VELOCITY: usize = 4;
    pub const STRIDE: usize = 8;
}
pub use velocity::STRIDE as VELOCITY;

/// Marks a contact with the static world (no body b).
pub const NO_BODY: u32 = u32::MAX;

/// WGSL `Island` (enumeration, assembly): n contacts; M then q start at
/// `data` in the values buffer, z at `z` in the z buffer.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Pod, Zeroable)]
pub struct PackedIsland {
    pub n: u32,
    pub data: u32,
    pub z: u32,
    /// Assembly: where the island's contact list starts in the slot table.
    /// LCP batches: the settle kernel's hint (WGSL `Island.hint`, see
    /// [`hint`]), 0 for none.
    pub contacts: u32,
}

/// WGSL `BasisResult`: where the enumeration of one island stands.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Pod, Zeroable)]
pub struct BasisResult {
    /// Status 1: the chosen basis (bit i: z_i basic); status 0: the next basis to visit.
    pub mask: u32,
    /// 0: in progress; 1 ([`FOUND`]): a valid basis was found; 2 ([`NONE`]):
    /// no basis is valid or within the relaxed tolerance; 3 ([`RELAXED`]): none
    /// is valid and `mask` is the least infeasible basis within the relaxed
    /// tolerance (every basis visited).
    pub status: u32,
    pub visited: u32,
    pub singular: u32,
    /// The least infeasible basis so far (when `has_least` is 1).
    pub least: u32,
    pub has_least: u32,
    /// Each kernel's own: the workgroup kernel's rank of the next basis
    /// (`_pad0`); after the tree kernel `_pad1` is [`TREE_DECIDED`] or
    /// [`TREE_UNDECIDED`] (then carried through the elimination that follows).
    pub _pad0: u32,
    pub _pad1: u32,
}

/// [`BasisResult::_pad1`] after the tree kernel: it chose the basis.
pub const TREE_DECIDED: u32 = 1;
/// [`BasisResult::_pad1`] after the tree kernel: it left the island to the
/// elimination kernel.
pub const TREE_UNDECIDED: u32 = 2;

/// [`BasisResult::_pad1`] after the settle kernel
/// (`shaders/enumeration_settle.wgsl`): the island's warm basis is its
/// answer (status [`FOUND`], visited 1).
pub const SETTLED_WARM: u32 = 3;
/// [`BasisResult::_pad1`] after the settle kernel: the island's predicted
/// basis is its answer.
pub const SETTLED_PREDICTED: u32 = 4;

/// The settle kernel's word per island ([`PackedIsland::contacts`] of an
/// LCP batch): the warm basis in bits 0–15, the predicted basis in bits
/// 16–31 (masks of n ≤ 16 contacts), 0 for none (an empty basis never
/// settles an island that is not separating).
pub fn hint(warm: u32, predicted: u32) -> u32 {
    (warm & 0xffff) | predicted << 16
}

/// The (warm, predicted) bases of a [`hint`].
pub fn hinted(hint: u32) -> (u32, u32) {
    (hint & 0xffff, hint >> 16)
}

/// [`BasisResult::status`]: a valid basis was found.
pub const FOUND: u32 = 1;
/// [`BasisResult::status`]: every basis was visited, none is valid or within
/// the relaxed tolerance.
pub const NONE: u32 = 2;
/// [`BasisResult::status`]: every basis was visited, none is valid; the mask
/// is the least infeasible one within the relaxed tolerance.
pub const RELAXED: u32 = 3;
/// [`BasisResult::status`] from the Lemke kernel (`shaders/lemke.wgsl`): it
/// gave up (a secondary ray with z0 not at zero, the pivot cap, the loop
/// budget, or a non-finite entry); the host solves the island on the CPU.
/// The kernel's FOUND carries its final basis in `mask` and its pivots in
/// `visited`.
pub const GAVE_UP: u32 = 4;

/// WGSL `Params`: the range of a table one dispatch covers, and (enumeration)
/// the loop work each invocation may spend in one round.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Pod, Zeroable)]
pub struct Params {
    pub first: u32,
    pub count: u32,
    pub budget: u32,
    /// The tree kernel: bit 0 set for semidefinite islands; unused by the
    /// other stages.
    pub flags: u32,
}

/// WGSL `ContactBodies`: the two bodies of a contact (b = [`NO_BODY`] for the
/// world), as indices into the packed bodies, and which of them are dynamic
/// (16 bytes).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Pod, Zeroable)]
pub struct ContactBodies {
    pub a: u32,
    pub b: u32,
    /// [`DYNAMIC_A`] | [`DYNAMIC_B`]: the sides whose body is not static
    /// ([`Body::is_static`]); the island stage skips the others, as
    /// [`crate::cpu::assembly::dynamic_sides`] does. Never set for the world.
    pub flags: u32,
    pub _pad: u32,
}

/// [`ContactBodies::flags`]: body a is dynamic.
pub const DYNAMIC_A: u32 = 1;
/// [`ContactBodies::flags`]: body b is dynamic.
pub const DYNAMIC_B: u32 = 2;

/// WGSL `Slot`: one row of one island (assembly's island stage runs one
/// invocation per slot): the island and the contact of that row.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Pod, Zeroable)]
pub struct Slot {
    pub island: u32,
    pub contact: u32,
}

/// WGSL `BodyContacts`: a body's range in the CSR list of (contact, side)
/// pairs the impulse stage gathers from.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Pod, Zeroable)]
pub struct BodyContacts {
    pub start: u32,
    pub count: u32,
}

/// WGSL `ContactSide` (impulses): a contact touching a body, on side 0 (a) or 1 (b).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Pod, Zeroable)]
pub struct ContactSide {
    pub contact: u32,
    pub side: u32,
}

/// Packs one body (see the table above).
pub fn pack_body(b: &Body, out: &mut Vec<f64>) {
    let start = out.len();
    out.resize(start + BODY, 0.0);
    let o = &mut out[start..];
    o[body::INV_MASS] = b.inv_mass;
    for r in 0..3 {
        for c in 0..3 {
            o[body::INV_INERTIA + 3 * r + c] = b.inv_inertia[r][c];
        }
    }
    o[body::POSITION..body::POSITION + 3].copy_from_slice(&b.position);
    o[body::VELOCITY..body::VELOCITY + 3].copy_from_slice(&b.velocity);
    o[body::ANGULAR_VELOCITY..body::ANGULAR_VELOCITY + 3].copy_from_slice(&b.angular_velocity);
}

/// Unpacks one body.
pub fn unpack_body(v: &[f64]) -> Body {
    let mut inv_inertia = [[0.0; 3]; 3];
    for (r, row) in inv_inertia.iter_mut().enumerate() {
        for (c, e) in row.iter_mut().enumerate() {
            *e = v[body::INV_INERTIA + 3 * r + c];
        }
    }
    let v3 = |at: usize| [v[at], v[at + 1], v[at + 2]];
    Body {
        inv_mass: v[body::INV_MASS],
        inv_inertia,
        position: v3(body::POSITION),
        velocity: v3(body::VELOCITY),
        angular_velocity: v3(body::ANGULAR_VELOCITY),
    }
}

/// Packs one contact: its body indices (offset by `first_body`, the scene's
/// first body in the packed buffer), which of them are dynamic (`bodies`:
/// the scene's bodies, indexed by the contact) and its scalars.
pub fn pack_contact(
    c: &Contact,
    bodies: &[Body],
    first_body: u32,
    ids: &mut Vec<ContactBodies>,
    out: &mut Vec<f64>,
) {
    let dynamic = |i: usize| !bodies[i].is_static();
    let mut flags = 0;
    if dynamic(c.a) {
        flags |= DYNAMIC_A;
    }
    if c.b.is_some_and(dynamic) {
        flags |= DYNAMIC_B;
    }
    ids.push(ContactBodies {
        a: first_body + c.a as u32,
        b: c.b.map_or(NO_BODY, |b| first_body + b as u32),
        flags,
        _pad: 0,
    });
    let start = out.len();
    out.resize(start + CONTACT, 0.0);
    let o = &mut out[start..];
    o[contact::POINT..contact::POINT + 3].copy_from_slice(&c.point);
    o[contact::NORMAL..contact::NORMAL + 3].copy_from_slice(&c.normal);
    o[contact::RESTITUTION] = c.restitution;
    o[contact::BIAS] = c.bias;
}

/// Packs one contact row.
pub fn pack_row(r: &ContactRow, out: &mut Vec<f64>) {
    let start = out.len();
    out.resize(start + ROW, 0.0);
    let o = &mut out[start..];
    let k = r.k.transpose().to_cols_array(); // rows of K
    o[row::K..row::K + 9].copy_from_slice(&k);
    o[row::JACOBIAN..row::JACOBIAN + 12].copy_from_slice(&r.jacobian);
    o[row::RESPONSE..row::RESPONSE + 12].copy_from_slice(&r.response);
    o[row::V_REL] = r.v_rel;
    o[row::Q] = r.q;
}

/// Unpacks one contact row.
pub fn unpack_row(v: &[f64]) -> ContactRow {
    let mut jacobian = [0.0; 12];
    let mut response = [0.0; 12];
    jacobian.copy_from_slice(&v[row::JACOBIAN..row::JACOBIAN + 12]);
    response.copy_from_slice(&v[row::RESPONSE..row::RESPONSE + 12]);
    let k_rows: [f64; 9] = v[row::K..row::K + 9].try_into().expect("9 entries");
    ContactRow {
        k: DMat3::from_cols_array(&k_rows).transpose(),
        jacobian,
        response,
        v_rel: v[row::V_REL],
        q: v[row::Q],
    }
}

/// CPU twin of the shader's `assemble_contacts` entry point on the packed
/// layout: unpacks bodies and contacts, calls
/// [`crate::cpu::assembly::assemble_contact`] in f64, packs the rows.
pub fn assemble_contacts_packed(
    bodies: &[f64],
    ids: &[ContactBodies],
    contacts: &[f64],
) -> Vec<f64> {
    let bodies: Vec<Body> = bodies.chunks_exact(BODY).map(unpack_body).collect();
    let mut out = Vec::with_capacity(ids.len() * ROW);
    for (id, v) in ids.iter().zip(contacts.chunks_exact(CONTACT)) {
        // The twin indexes bodies by the packed (batch-wide) indices.
        let c = Contact {
            a: id.a as usize,
            b: (id.b != NO_BODY).then_some(id.b as usize),
            point: [v[0], v[1], v[2]],
            normal: [v[3], v[4], v[5]],
            restitution: v[contact::RESTITUTION],
            id: None,
            bias: v[contact::BIAS],
            friction: 0.0,
            tangent: None,
        };
        pack_row(&assemble_contact(&bodies, &c), &mut out);
    }
    out
}

/// f64 values as the shader's scalars, in bytes.
pub fn scalars_to_bytes(values: &[f64], precision: Precision) -> Vec<u8> {
    match precision {
        Precision::F64 => bytemuck::cast_slice(values).to_vec(),
        _ => {
            let v: Vec<f32> = values.iter().map(|&x| x as f32).collect();
            bytemuck::cast_slice(&v).to_vec()
        }
    }
}

/// The one scalar of `bytes` (its first 8 bytes in f64, 4 in f32; NaN when
/// there are fewer): [`scalars_from_bytes`] without a vector.
pub(crate) fn scalar_from_bytes(bytes: &[u8], precision: Precision) -> f64 {
    match precision {
        Precision::F64 => bytes
            .first_chunk::<8>()
            .map_or(f64::NAN, |b| f64::from_le_bytes(*b)),
        _ => bytes
            .first_chunk::<4>()
            .map_or(f64::NAN, |b| f32::from_le_bytes(*b) as f64),
    }
}

/// The shader's scalars, from bytes, as f64.
pub fn scalars_from_bytes(bytes: &[u8], precision: Precision) -> Vec<f64> {
    match precision {
        Precision::F64 => bytes
            .chunks_exact(8)
            .map(|c| f64::from_le_bytes(c.try_into().expect("8 bytes")))
            .collect(),
        _ => bytes
            .chunks_exact(4)
            .map(|c| f32::from_le_bytes(c.try_into().expect("4 bytes")) as f64)
            .collect(),
    }
}
