// Shared by the resident step's solve (shaders/world_solve.wgsl) and
// frictional (shaders/world_friction.wgsl) phases, composed before both:
// the bodies' velocities of a world while its islands are solved, the
// sides of a contact's rows, and step.rs finish.

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

// step.rs integrate_rotation: normalise(q + ½Δt (ω, 0) ⊗ q).
fn integrate_rotation(q: vec4<Scalar>, w: vec3<Scalar>, dt: Scalar) -> vec4<Scalar> {
    // glam's DQuat product (w.x, w.y, w.z, 0) ⊗ q.
    let spin = vec4<Scalar>(
        w.x * q.w + w.y * q.z - w.z * q.y,
        -w.x * q.z + w.y * q.w + w.z * q.x,
        w.x * q.y - w.y * q.x + w.z * q.w,
        -w.x * q.x - w.y * q.y - w.z * q.z,
    );
    return normalize4(q + Scalar(0.5) * dt * spin);
}

fn normalize4(q: vec4<Scalar>) -> vec4<Scalar> {
    let len = sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
    return q * (Scalar(1.0) / len);
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

// step.rs finish for world w after its impulses (velocities in lin, ang):
// woken bodies awake, moving bodies integrated, sleep counters; then the
// world's flags and figures. A flagged world keeps its state.
fn finish_world(w: u32, flags0: u32, max_penetration: Scalar, max_error: Scalar) {
    let info = worlds[w];
    let first = info.x;
    let nb = min(info.y, MAX_BODIES);
    let out = sp.out_at + 4u * w;
    let moving = words[out + 1u];
    var flags = flags0;
    let dt = sp.dt;
    let g = vec3_at_consts(w * WC);
    let sleep_linear = consts[w * WC + 4u];
    let sleep_angular = consts[w * WC + 5u];
    var xs: array<vec3<Scalar>, 16>;
    var qs: array<vec4<Scalar>, 16>;
    for (var k = 0u; k < nb && flags == 0u; k++) {
        let b = first + k;
        if ((moving >> k) & 1u) == 0u {
            continue;
        }
        let o = b * BS;
        let q0 = normalize4(vec4<Scalar>(state[o + 3u], state[o + 4u], state[o + 5u], state[o + 6u]));
        xs[k] = vec3_at_state(o) + lin[k] * dt;
        qs[k] = integrate_rotation(q0, ang[k], dt);
        let mag = abs(xs[k]) + abs(qs[k].xyz) + abs(lin[k]) + abs(ang[k]);
        if !finite(mag.x + mag.y + mag.z + abs(qs[k].w)) {
            flags |= NON_FINITE;
        }
    }
    var kinetic = Scalar(0.0);
    var potential = Scalar(0.0);
    var awake = 0u;
    if flags == 0u {
        for (var k = 0u; k < nb; k++) {
            let b = first + k;
            if is_static(b) {
                continue;
            }
            let o = b * BS;
            if ((moving >> k) & 1u) != 0u {
                // A woken body counts its quiet steps afresh.
                var quiet = select(words[2u * b + 1u], 0u, asleep(b));
                let still = length3(lin[k]) < sleep_linear && length3(ang[k]) < sleep_angular;
                if still {
                    quiet = min(quiet, 0xfffffffeu) + 1u;
                } else {
                    quiet = 0u;
                }
                var sleeps = 0u;
                if info.z > 0u && quiet >= info.z {
                    sleeps = 1u;
                    lin[k] = vec3<Scalar>(0.0, 0.0, 0.0);
                    ang[k] = vec3<Scalar>(0.0, 0.0, 0.0);
                }
                words[2u * b] = sleeps;
                words[2u * b + 1u] = quiet;
                put_state(o, xs[k]);
                state[o + 3u] = qs[k].x;
                state[o + 4u] = qs[k].y;
                state[o + 5u] = qs[k].z;
                state[o + 6u] = qs[k].w;
                put_state(o + 7u, lin[k]);
                put_state(o + 10u, ang[k]);
            }
            // RigidBody::kinetic_energy and World::potential_energy after
            // the step.
            let v = vec3_at_state(o + 7u);
            let om = vec3_at_state(o + 10u);
            let p = placed_body(b);
            let wb = unrotate(p, om);
            let inertia = Scalar(1.0) / vec3_at_consts(sp.bodies_at + b * BC + 6u);
            let m = body_const(b, 9u);
            kinetic += Scalar(0.5) * m * dot3(v, v) + Scalar(0.5) * dot3(wb * wb, inertia);
            potential += -m * dot3(g, vec3_at_state(o));
            if !asleep(b) {
                awake++;
            }
        }
    }
    // The loop limit reached: flagged (the host steps the world from its
    // state before the step and writes it back).
    if flags == 0u && !loops_left() {
        flags = BUDGET;
    }
    words[out + 2u] = flags;
    let r = w * REC;
    records[r] = kinetic;
    records[r + 1u] = potential;
    records[r + 2u] = max_penetration;
    records[r + 3u] = max_error;
    records[r + 4u] = Scalar(awake);
}

