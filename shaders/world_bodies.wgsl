// Shared by the resident step's solve (shaders/world_solve.wgsl,
// world_lemke.wgsl), frictional (world_friction.wgsl) and finish
// (world_finish.wgsl) modules, composed before each: the bodies'
// velocities of a world while its islands are solved, the sides of a
// contact's rows, a contact's id.

// A side of a contact row with no dynamic body (static in the step's scene).
const NONE: u32 = 0xffffffffu;
// The dynamic body of each side of an island's rows (contact_sides), row
// i at i.
var<private> sides: array<vec2<u32>, 16>;
// Per body of the world: v* and then the velocities after the impulses.
var<private> lin: array<vec3<Scalar>, 16>;
var<private> ang: array<vec3<Scalar>, 16>;

// The dynamic body of each side of contact `slot` (global) in the step's
// scene, NONE where that side is static or not moving: the `sides` of its
// rows (friction rows of world_friction.wgsl included).
fn contact_sides(slot: u32, moving: u32) -> vec2<u32> {
    let key = sp.keys_at + 4u * slot;
    let a = words[key];
    let b = words[key + 1u];
    var s = vec2<u32>(NONE, NONE);
    if ((moving >> a) & 1u) != 0u {
        s.x = a;
    }
    if ((moving >> b) & 1u) != 0u {
        s.y = b;
    }
    return s;
}

// lin, ang: the velocities of world w's bodies in `scratch`.
fn load_velocities(w: u32) {
    let first = worlds[w].x;
    for (var k = 0u; k < min(worlds[w].y, MAX_BODIES); k++) {
        lin[k] = vec3_at_scratch(6u * (first + k));
        ang[k] = vec3_at_scratch(6u * (first + k) + 3u);
    }
}

// World w's velocities (lin, ang) into `scratch`, for world_finish.
fn store_velocities(w: u32) {
    let first = worlds[w].x;
    for (var k = 0u; k < min(worlds[w].y, MAX_BODIES); k++) {
        put_scratch(6u * (first + k), lin[k]);
        put_scratch(6u * (first + k) + 3u, ang[k]);
    }
}

// A contact's id in the world's memories: (a << 16) | (b << 12) |
// (feature & 0xfff), as step.rs contact_id without the world.
fn contact_key(slot: u32) -> u32 {
    let key = sp.keys_at + 4u * slot;
    return (words[key] << 16u) | (words[key + 1u] << 12u) | (words[key + 2u] & 0xfffu);
}

// Island `isl` of world w (`count` contacts): its contacts (indices in
// the world) into `members` (the first ISLAND_MAX); its size.
fn island_members(w: u32, count: u32, isl: u32, members: ptr<function, array<u32, 16>>) -> u32 {
    let slot0 = w * sp.slots;
    var n = 0u;
    for (var c = 0u; c < count; c++) {
        if words[sp.keys_at + 4u * (slot0 + c) + 3u] == isl {
            if n < ISLAND_MAX {
                (*members)[n] = c;
            }
            n++;
        }
    }
    return n;
}
