// Assembly: per contact its K matrix, Jacobian row, response M^-1 J^T, v_rel
// and q (entry point `assemble_contacts`, one invocation per contact); per
// island its LCP: M_ij = J_i M^-1 J_j^T over the bodies contacts i and j
// share, and q (entry point `assemble_islands`, one invocation per island
// row). CPU twin: src/cpu/assembly.rs (assemble_contact, matrix_entry,
// assemble_island), same formulas in the same order.
//
// Packed layouts (src/gpu/layout.rs): body 20 scalars (inv_mass, inverse
// inertia rows, position, velocity, angular velocity), contact 8 scalars
// (point, normal, restitution, bias), row 36 scalars (K rows, jacobian, response,
// v_rel, q), island data M row-major then q.
//
// The generator (src/gpu/shaders/compose.rs) replaces the line marked HOST
// (scalar type) and writes shaders/generated/<name>_f32.wgsl and _f64.wgsl.

alias Scalar = f32; // HOST scalar

const BODY: u32 = 20u;
const CONTACT: u32 = 8u;
const ROW: u32 = 36u;
const ROW_K: u32 = 0u;
const ROW_JACOBIAN: u32 = 9u;
const ROW_RESPONSE: u32 = 21u;
const ROW_V_REL: u32 = 33u;
const ROW_Q: u32 = 34u;
const NO_BODY: u32 = 0xffffffffu;

struct Params {
    first: u32,
    count: u32,
    _pad0: u32,
    _pad1: u32,
}

// flags: bit 0 (DYNAMIC_A) a is dynamic, bit 1 (DYNAMIC_B) b is dynamic
// (not static; never set for the world).
struct ContactBodies {
    a: u32,
    b: u32,
    flags: u32,
    _pad: u32,
}

struct Island {
    n: u32,
    data: u32,
    z: u32,
    contacts: u32,
}

struct Slot {
    island: u32,
    contact: u32,
}

// Stage `assemble_contacts`.
@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> bodies: array<Scalar>;
@group(0) @binding(2) var<storage, read> contact_bodies: array<ContactBodies>;
@group(0) @binding(3) var<storage, read> contacts: array<Scalar>;
@group(0) @binding(4) var<storage, read_write> rows: array<Scalar>;
// Stage `assemble_islands` (also params, contact_bodies and rows).
@group(0) @binding(5) var<storage, read> islands: array<Island>;
@group(0) @binding(6) var<storage, read> slots: array<Slot>;
@group(0) @binding(7) var<storage, read_write> values: array<Scalar>;

fn body_vec3(body: u32, at: u32) -> vec3<Scalar> {
    let o = body * BODY + at;
    return vec3<Scalar>(bodies[o], bodies[o + 1u], bodies[o + 2u]);
}

// I^-1 of a body (stored by rows).
fn inv_inertia(body: u32) -> mat3x3<Scalar> {
    let by_rows = mat3x3<Scalar>(body_vec3(body, 1u), body_vec3(body, 4u), body_vec3(body, 7u));
    return transpose(by_rows);
}

// r*: the matrix with r* x = r cross x (columns as in glam's cross_matrix).
fn cross_matrix(r: vec3<Scalar>) -> mat3x3<Scalar> {
    return mat3x3<Scalar>(
        vec3<Scalar>(Scalar(0.0), r.z, -r.y),
        vec3<Scalar>(-r.z, Scalar(0.0), r.x),
        vec3<Scalar>(r.y, -r.x, Scalar(0.0)),
    );
}

fn put3(at: u32, v: vec3<Scalar>) {
    rows[at] = v.x;
    rows[at + 1u] = v.y;
    rows[at + 2u] = v.z;
}

fn identity() -> mat3x3<Scalar> {
    return mat3x3<Scalar>(
        vec3<Scalar>(Scalar(1.0), Scalar(0.0), Scalar(0.0)),
        vec3<Scalar>(Scalar(0.0), Scalar(1.0), Scalar(0.0)),
        vec3<Scalar>(Scalar(0.0), Scalar(0.0), Scalar(1.0)),
    );
}

@compute @workgroup_size(64)
fn assemble_contacts(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= params.count {
        return;
    }
    let ci = params.first + gid.x;
    let ids = contact_bodies[ci];
    let co = ci * CONTACT;
    let p = vec3<Scalar>(contacts[co], contacts[co + 1u], contacts[co + 2u]);
    let n = vec3<Scalar>(contacts[co + 3u], contacts[co + 4u], contacts[co + 5u]);
    let restitution = contacts[co + 6u];
    let bias = contacts[co + 7u];
    let out = ci * ROW;

    let a = ids.a;
    let inv_mass_a = bodies[a * BODY];
    let ra = p - body_vec3(a, 10u);
    let ia = inv_inertia(a);
    let ra_x = cross_matrix(ra);
    var k = identity() * inv_mass_a - ra_x * ia * ra_x;
    let ra_n = cross(ra, n);
    put3(out + ROW_JACOBIAN, n);
    put3(out + ROW_JACOBIAN + 3u, ra_n);
    put3(out + ROW_RESPONSE, n * inv_mass_a);
    put3(out + ROW_RESPONSE + 3u, ia * ra_n);
    var pdot = body_vec3(a, 13u) + cross(body_vec3(a, 16u), ra);
    if ids.b != NO_BODY {
        let b = ids.b;
        let inv_mass_b = bodies[b * BODY];
        let rb = p - body_vec3(b, 10u);
        let ib = inv_inertia(b);
        let rb_x = cross_matrix(rb);
        k += identity() * inv_mass_b - rb_x * ib * rb_x;
        let rb_n = cross(rb, n);
        put3(out + ROW_JACOBIAN + 6u, -n);
        put3(out + ROW_JACOBIAN + 9u, -rb_n);
        put3(out + ROW_RESPONSE + 6u, -n * inv_mass_b);
        put3(out + ROW_RESPONSE + 9u, -(ib * rb_n));
        pdot -= body_vec3(b, 13u) + cross(body_vec3(b, 16u), rb);
    } else {
        let zero = vec3<Scalar>(Scalar(0.0));
        put3(out + ROW_JACOBIAN + 6u, zero);
        put3(out + ROW_JACOBIAN + 9u, zero);
        put3(out + ROW_RESPONSE + 6u, zero);
        put3(out + ROW_RESPONSE + 9u, zero);
    }
    // K by rows.
    let kt = transpose(k);
    put3(out + ROW_K, kt[0]);
    put3(out + ROW_K + 3u, kt[1]);
    put3(out + ROW_K + 6u, kt[2]);
    let v_rel = dot(pdot, n);
    rows[out + ROW_V_REL] = v_rel;
    // normal_q of the twin: v_rel + eps min(v_rel, 0) + bias.
    rows[out + ROW_Q] = v_rel + restitution * min(v_rel, Scalar(0.0)) + bias;
    rows[out + 35u] = Scalar(0.0);
}

// J_i . (M^-1 J_j^T) over one side of each contact: a 6-entry dot product.
fn dot6(row_i: u32, side_i: u32, row_j: u32, side_j: u32) -> Scalar {
    let ji = row_i * ROW + ROW_JACOBIAN + 6u * side_i;
    let rj = row_j * ROW + ROW_RESPONSE + 6u * side_j;
    var s = Scalar(0.0);
    for (var e = 0u; e < 6u; e++) {
        s += rows[ji + e] * rows[rj + e];
    }
    return s;
}

// M_ij over the dynamic bodies contacts ci and cj share: static partners
// (and the world) contribute no terms, as in the twin's dynamic_sides. A
// side of ci that is dynamic is a body, and the same body in cj is dynamic
// there too.
fn matrix_entry(ci: u32, cj: u32) -> Scalar {
    let bi = contact_bodies[ci];
    let bj = contact_bodies[cj];
    let side_i = array<u32, 2>(bi.a, bi.b);
    let side_j = array<u32, 2>(bj.a, bj.b);
    var m = Scalar(0.0);
    for (var si = 0u; si < 2u; si++) {
        if ((bi.flags >> si) & 1u) == 0u {
            continue;
        }
        for (var sj = 0u; sj < 2u; sj++) {
            if side_i[si] == side_j[sj] {
                m += dot6(ci, si, cj, sj);
            }
        }
    }
    return m;
}

@compute @workgroup_size(64)
fn assemble_islands(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= params.count {
        return;
    }
    let t = params.first + gid.x;
    let slot = slots[t];
    let island = islands[slot.island];
    let n = island.n;
    let i = t - island.contacts;
    let ci = slot.contact;
    for (var j = 0u; j < n; j++) {
        let cj = slots[island.contacts + j].contact;
        values[island.data + i * n + j] = matrix_entry(ci, cj);
    }
    values[island.data + n * n + i] = rows[ci * ROW + ROW_Q];
}
