// The finish of the resident step (shaders/world_step.wgsl's header; a
// module of its own, composed after world_step.wgsl and world_bodies.wgsl):
// the impulses of the solve (cpu/impulses.rs), step.rs finish (poses, sleep
// counters) and the world's figures, for every world the solve stepped or
// flagged and every world world_friction
// finished (F_DONE: its reactions remembered first), in one dispatch after
// the frictional rounds. A world world_friction has not finished (still
// HANDED) is left to the host.

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


// cpu/impulses.rs velocities_after for world w's contacts: v += M⁻¹Jᵀ z
// per side (the response world_assemble kept, z the solve's), contact
// after contact in slot order (zero impulses skipped): each body takes its
// island's impulses in the island's order.
fn apply_impulses(w: u32) {
    let out = sp.out_at + 4u * w;
    let moving = words[out + 1u];
    let slot0 = w * sp.slots;
    for (var c = 0u; c < words[out]; c++) {
        let z = scratch[sp.contacts_at + (slot0 + c) * CP + 7u];
        if z == Scalar(0.0) {
            continue;
        }
        let s = contact_sides(slot0 + c, moving);
        let r = row_at(slot0 + c);
        if s.x != NONE {
            lin[s.x] += vec3_at_scratch(r + 1u) * z;
            ang[s.x] += vec3_at_scratch(r + 4u) * z;
        }
        if s.y != NONE {
            lin[s.y] += vec3_at_scratch(r + 7u) * z;
            ang[s.y] += vec3_at_scratch(r + 10u) * z;
        }
    }
}

// WarmMemory::record of a finished world's step (every island solved):
// its contacts' ids and reactions replace the memory (world_friction.wgsl's
// header gives the layout).
fn remember_reactions(w: u32, count: u32) {
    if sp.warm_start == 0u {
        return;
    }
    let m = sp.memory_at + w * (sp.slots + 1u);
    words[m] = count;
    for (var e = 0u; e < count; e++) {
        let slot = w * sp.slots + e;
        words[m + 1u + e] = contact_key(slot);
        put_scratch(sp.memory_r_at + 3u * slot, vec3_at_scratch(sp.reactions_at + 3u * slot));
    }
}

// step.rs finish for world w: from v* and the solve's impulses
// (`apply_impulses`), or from the velocities world_friction left in
// `scratch` (F_DONE); a world still with world_friction (HANDED, not
// F_DONE) is skipped, a flagged world keeps its state.
@compute @workgroup_size(64)
fn world_finish(@builtin(global_invocation_id) gid: vec3<u32>) {
    let w = gid.x;
    if w >= sp.count {
        return;
    }
    let out = sp.out_at + 4u * w;
    var flags = words[out + 2u];
    if flags == HANDED {
        let fs = sp.fstate_at + 4u * w;
        if words[fs] != F_DONE {
            return;
        }
        words[fs] = F_IDLE;
        remember_reactions(w, words[out]);
        flags = 0u;
        load_velocities(w);
    } else {
        load_velocities(w);
        if flags == 0u {
            apply_impulses(w);
        }
    }
    finish_world(w, flags, records[w * REC + 2u], records[w * REC + 3u]);
}
