// Impulse application: one invocation per body gathers the impulses of its
// contacts through a CSR list (no float atomics), in contact order, and
// writes its velocities after the impact. CPU twin: src/cpu/impulses.rs
// (apply_impulses), same sums in the same order.
//
// Contact c with impulse z_c changes body a by z_c * response[0..6] and body
// b by z_c * response[6..12] (response = M^-1 J^T from assembly).
//
// The generator (src/gpu/shaders/compose.rs) replaces the line marked HOST
// (scalar type) and writes shaders/generated/<name>_f32.wgsl and _f64.wgsl.

alias Scalar = f32; // HOST scalar

const BODY: u32 = 20u;
const ROW: u32 = 36u;
const ROW_RESPONSE: u32 = 21u;
const VELOCITY: u32 = 8u;

struct Params {
    first: u32,
    count: u32,
    _pad0: u32,
    _pad1: u32,
}

// A body's range in `contact_sides`.
struct BodyContacts {
    start: u32,
    count: u32,
}

// One contact touching the body, and on which side (0: a, 1: b).
struct ContactSide {
    contact: u32,
    side: u32,
}

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> bodies: array<Scalar>;
@group(0) @binding(2) var<storage, read> rows: array<Scalar>;
@group(0) @binding(3) var<storage, read> body_contacts: array<BodyContacts>;
@group(0) @binding(4) var<storage, read> contact_sides: array<ContactSide>;
@group(0) @binding(5) var<storage, read> z: array<Scalar>;
@group(0) @binding(6) var<storage, read_write> velocities: array<Scalar>;

fn row_vec3(at: u32) -> vec3<Scalar> {
    return vec3<Scalar>(rows[at], rows[at + 1u], rows[at + 2u]);
}

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= params.count {
        return;
    }
    let body = params.first + gid.x;
    let bo = body * BODY;
    var v = vec3<Scalar>(bodies[bo + 13u], bodies[bo + 14u], bodies[bo + 15u]);
    var w = vec3<Scalar>(bodies[bo + 16u], bodies[bo + 17u], bodies[bo + 18u]);
    let range = body_contacts[body];
    for (var e = 0u; e < range.count; e++) {
        let cs = contact_sides[range.start + e];
        let zc = z[cs.contact];
        if zc == Scalar(0.0) {
            continue;
        }
        let at = cs.contact * ROW + ROW_RESPONSE + 6u * cs.side;
        v += row_vec3(at) * zc;
        w += row_vec3(at + 3u) * zc;
    }
    let o = body * VELOCITY;
    velocities[o] = v.x;
    velocities[o + 1u] = v.y;
    velocities[o + 2u] = v.z;
    velocities[o + 3u] = Scalar(0.0);
    velocities[o + 4u] = w.x;
    velocities[o + 5u] = w.y;
    velocities[o + 6u] = w.z;
    velocities[o + 7u] = Scalar(0.0);
}
