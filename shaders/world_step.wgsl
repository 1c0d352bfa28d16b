// One step of resident worlds (restitution 0), one invocation per world,
// in entry points dispatched in one submission:
// `world_collide` (src/world/step.rs `prepare`: gravity, `world_contacts`),
// `world_solve_warm` (the worlds whose warm bases all hold, stepped without
// Lemke's code; the rest listed in `deferred`), then over those alone
// through an indirect dispatch `world_solve` (src/islands.rs `find_islands`, src/cpu/assembly.rs
// `assemble_contact` / `assemble_island`, Lemke's path `lemke_pivots`, the
// door's check `lcp_error` <= tolerance, `apply_impulses`, `finish` with
// `integrate_rotation`, the world's figures; worlds with friction are
// handed over to) `world_friction` (shaders/world_friction.wgsl, in
// rounds). Several entry points rather than one: llvmpipe ends every loop
// of an invocation after about 65,535 iterations in all, and each dispatch
// starts that count afresh.
//
// Composed (src/gpu/shaders/compose.rs) after shaders/collide.wgsl (its
// functions, up to its stage's bindings) and shaders/lemke.wgsl (up to its
// kernel's part), and before shaders/world_solve.wgsl (`world_solve`, a
// file of its own by phase), shaders/world_friction.wgsl and the cone
// projection of shaders/friction_common.wgsl: collide_shapes' pair
// functions (box_box, box_plane, sphere_plane, sphere_sphere, sphere_box,
// dispatched and flipped as it does), lemke_pivots and project_on_cone are
// called as they are.
//
// A world the kernel cannot step is flagged (`flags` below) and its state
// left as it was: the host steps it on the CPU from there. Flags: contact
// slots full (CONTACTS_FULL), an island above 16 contacts
// (ISLAND_TOO_LARGE), Lemke gave up or the check failed (NOT_SOLVED), a
// non-finite velocity or pose after the step (NON_FINITE), the loop budget
// spent (BUDGET).
//
// Layouts (src/gpu/resident/layout.rs, keep in sync):
// - worlds[w] = (first body, bodies, sleep steps, 0);
// - consts: per world WC scalars (gravity 3, margin, sleep linear, sleep
//   angular), then from params.bodies_at per body BC scalars (kind, size 3,
//   static flag, inverse mass, body-frame inverse inertia 3, mass,
//   bounding radius, friction coefficient);
// - state: per body BS scalars (position 3, orientation x, y, z, w,
//   velocity 3, angular velocity 3);
// - scratch: per body 6 scalars (v*, then v after the impulses), then per
//   contact slot CP scalars (point 3, normal 3, gap, z); from
//   params.pairs_at per world params.pair_slots pair records of CP scalars
//   (point 3, normal 3, gap, feature), SLOTS per candidate pair;
// - words: per body 2 (asleep, quiet steps); from params.out_at per world 4
//   (contacts, moving-body mask, flags, islands); from params.keys_at per
//   contact slot 4 (a, b, feature, island);
// - records: per world REC scalars (kinetic, potential, max penetration,
//   max error, awake, friction rounds, and world_solve's warm-start
//   memory: a hash of last step's contact ids, their bases);
// - deferred: the worlds `world_solve_warm` leaves to `world_solve`
//   (world_solve.wgsl): workgroups x, y, z of the indirect dispatch, the
//   count, then the worlds; x and the count reset by world_collide.

const SCALAR_EPSILON: Scalar = 1.1920929e-7; // HOST scalar_epsilon

const MAX_BODIES: u32 = 16u;
const WC: u32 = 6u;
const BC: u32 = 12u;
const BS: u32 = 13u;
const CP: u32 = 8u;
const REC: u32 = 8u;
const ISLAND_MAX: u32 = 16u;

const CONTACTS_FULL: u32 = 1u;
const ISLAND_TOO_LARGE: u32 = 2u;
const NOT_SOLVED: u32 = 4u;
const NON_FINITE: u32 = 8u;
const BUDGET: u32 = 16u;
const HANDED: u32 = 32u; // with world_friction until it finishes the world (world_solve.wgsl)

struct StepParams {
    // Worlds.
    count: u32,
    // Contact slots per world.
    slots: u32,
    // Where the bodies' constants start in `consts`.
    bodies_at: u32,
    // Where the worlds' out words and the contact keys start in `words`.
    out_at: u32,
    keys_at: u32,
    // Loop work per invocation and dispatch (shaders/lemke.wgsl).
    budget: u32,
    // Where the contact slots start in `scratch`.
    contacts_at: u32,
    // The frictional phase (shaders/world_friction.wgsl): where its
    // per-world regions start in `scratch` (0: none, no world has
    // friction), its per-world words in `words`, the sweeps' cap, 1 for
    // Gauss–Seidel (0: Jacobi, 2: APGD), 1 for warm starts; this step's reactions
    // and the warm-start memory (ids in `words`, reactions in `scratch`).
    friction_at: u32,
    fstate_at: u32,
    max_iterations: u32,
    gauss_seidel: u32,
    warm_start: u32,
    reactions_at: u32,
    memory_at: u32,
    memory_r_at: u32,
    // Loop work per invocation and round of world_friction: a quarter of
    // `budget` (llvmpipe runs 8 invocations in lockstep and counts their
    // loops together: lanes in different phases add up).
    friction_budget: u32,
    // world_collide's pair records: where they start in `scratch`, and
    // records per world (SLOTS per candidate pair).
    pairs_at: u32,
    pair_slots: u32,
    // 1: world_solve tries last step's bases first (the CPU path's
    // warm_settle: warm starts on, a method that predicts).
    warm_bases: u32,
    dt: Scalar,
    // The door's final check: lcp_error <= tolerance.
    tolerance: Scalar,
    // Lemke: pivot tolerance and pivot cap.
    pivot_tol: Scalar,
    max_pivots: Scalar,
    // The frictional islands' check: cone error <= friction_tolerance.
    friction_tolerance: Scalar,
}

@group(0) @binding(0) var<uniform> sp: StepParams;
@group(0) @binding(1) var<storage, read> worlds: array<vec4<u32>>;
@group(0) @binding(2) var<storage, read> consts: array<Scalar>;
@group(0) @binding(3) var<storage, read_write> state: array<Scalar>;
@group(0) @binding(4) var<storage, read_write> scratch: array<Scalar>;
@group(0) @binding(5) var<storage, read_write> words: array<u32>;
@group(0) @binding(6) var<storage, read_write> records: array<Scalar>;
@group(0) @binding(7) var<storage, read_write> deferred: array<atomic<u32>>;

fn vec3_at_consts(at: u32) -> vec3<Scalar> {
    return vec3<Scalar>(consts[at], consts[at + 1u], consts[at + 2u]);
}

fn vec3_at_state(at: u32) -> vec3<Scalar> {
    return vec3<Scalar>(state[at], state[at + 1u], state[at + 2u]);
}

fn vec3_at_scratch(at: u32) -> vec3<Scalar> {
    return vec3<Scalar>(scratch[at], scratch[at + 1u], scratch[at + 2u]);
}

fn put_scratch(at: u32, v: vec3<Scalar>) {
    scratch[at] = v.x;
    scratch[at + 1u] = v.y;
    scratch[at + 2u] = v.z;
}

fn put_state(at: u32, v: vec3<Scalar>) {
    state[at] = v.x;
    state[at + 1u] = v.y;
    state[at + 2u] = v.z;
}

fn body_const(k: u32, i: u32) -> Scalar {
    return consts[sp.bodies_at + k * BC + i];
}

fn is_static(k: u32) -> bool {
    return body_const(k, 4u) != Scalar(0.0);
}

fn asleep(k: u32) -> bool {
    return words[2u * k] != 0u;
}

// Body k at its pose (RigidBody::rotation normalises, as placed_from).
fn placed_body(k: u32) -> Placed {
    let o = k * BS;
    let q = vec4<Scalar>(state[o + 3u], state[o + 4u], state[o + 5u], state[o + 6u]);
    let kind = u32(body_const(k, 0u));
    let size = vec3_at_consts(sp.bodies_at + k * BC + 1u);
    return placed_from(kind, size, vec3_at_state(o), q);
}

// An axis-aligned box (broad.rs Aabb::of): `ok` false for a plane.
struct Aabb {
    lo: vec3<Scalar>,
    hi: vec3<Scalar>,
    ok: bool,
}

fn aabb_of(p: Placed, margin: Scalar) -> Aabb {
    var half = vec3<Scalar>(p.size.x, p.size.x, p.size.x);
    if p.kind == KIND_PLANE {
        return Aabb(p.centre, p.centre, false);
    }
    if p.kind == KIND_BOX {
        let h = p.size;
        // |R| h by rows of R (the columns' components).
        half = vec3<Scalar>(
            dot3(abs(vec3<Scalar>(p.c0.x, p.c1.x, p.c2.x)), h),
            dot3(abs(vec3<Scalar>(p.c0.y, p.c1.y, p.c2.y)), h),
            dot3(abs(vec3<Scalar>(p.c0.z, p.c1.z, p.c2.z)), h),
        );
    }
    half += vec3<Scalar>(margin, margin, margin);
    return Aabb(p.centre - half, p.centre + half, true);
}

fn overlaps(a: Aabb, b: Aabb) -> bool {
    return all(a.lo <= b.hi) && all(b.lo <= a.hi);
}

// A box and a plane too far apart for any corner to come within `margin`
// (box_plane would find nothing): the centre's height over the plane less
// the box's half diagonal, with a slack above the rounding of box_plane's
// corners (relative to the coordinates' size), at least `margin`.
fn box_far_from_plane(b: Placed, p: Placed, margin: Scalar) -> bool {
    let n = p.size;
    let height = dot3(n, b.centre - p.centre);
    let reach = length3(b.size) * length3(n);
    let size = dot3(abs(n), abs(b.centre) + abs(p.centre)) + reach + abs(margin);
    return height - reach >= margin + Scalar(64.0) * SCALAR_EPSILON * size;
}

// collide.wgsl's collide_shapes for a pair with a sphere: the sphere as
// the first shape, the same calls; the caller flips the normals where the
// sphere was the pair's second shape (collide_shapes' flip).
fn collide_sphere(s: Placed, o: Placed, margin: Scalar) -> Manifold {
    if o.kind == KIND_PLANE {
        return sphere_plane(s.centre, s.size.x, o.centre, o.size, margin);
    }
    if o.kind == KIND_SPHERE {
        return sphere_sphere(s.centre, s.size.x, o.centre, o.size.x, margin);
    }
    return sphere_box(s.centre, s.size.x, o, o.size, margin);
}

// Keeps candidate c's manifold (normals reversed where `flipped`) in world
// w's pair records: its first SLOTS hits (point, normal, gap, feature); returns
// its count word (length | OVERFLOW where the manifold overflowed).
fn keep_manifold(w: u32, c: u32, m: Manifold, flipped: bool) -> u32 {
    for (var h = 0u; h < min(m.len, SLOTS); h++) {
        let hit = m.hits[h];
        let at = sp.pairs_at + (w * sp.pair_slots + SLOTS * c + h) * CP;
        put_scratch(at, hit.point);
        put_scratch(at + 3u, select(hit.normal, -hit.normal, flipped));
        scratch[at + 6u] = hit.gap;
        scratch[at + 7u] = Scalar(hit.feature);
    }
    return m.len | select(0u, OVERFLOW, m.overflow);
}

// Step part 1 (step.rs prepare without impacts: restitution 0): v* = v +
// Δt g for the awake dynamic bodies, then world_contacts: candidate pairs
// (broad.rs candidate_pairs: boxes grown by half the margin plus the reach,
// planes with every movable body; all pairs, in the sweep's sorted order
// i < j), the narrow phase with margin + both reaches, sleeping bodies
// woken by an awake one's contact (their v* = Δt g), until none wakes.
//
// In three phases, for llvmpipe, which runs every branch of an invocation
// under a mask and every loop as often as its busiest lane: (1) the
// candidates in pair order, less box–plane pairs that cannot touch
// (box_far_from_plane); (2) the narrow phase of every candidate that an
// awake body can reach through candidates (those world_contacts may
// collide: a pair's manifold depends on the poses and reaches only, not on
// when it is collided), in one loop per family (box–box, box–plane, with a
// sphere) so that each lane pays for box_box only per box–box pair, the
// manifolds kept in the pair records; (3) world_contacts' rounds over the
// candidates in pair order, taking the kept manifolds: the same contacts in
// the same order as collided there.
@compute @workgroup_size(64)
fn world_collide(@builtin(global_invocation_id) gid: vec3<u32>) {
    let w = gid.x;
    if w == 0u {
        // No world left to world_solve yet this step.
        atomicStore(&deferred[0], 0u);
        atomicStore(&deferred[3], 0u);
    }
    if w >= sp.count {
        return;
    }
    let info = worlds[w];
    let first = info.x;
    let nb = min(info.y, MAX_BODIES);
    let g = vec3_at_consts(w * WC);
    let margin = consts[w * WC + 3u];
    let dt = sp.dt;
    var placed: array<Placed, 16>;
    var boxes: array<Aabb, 16>;
    var reach: array<Scalar, 16>;
    var awake_mask = 0u;
    var movable = 0u;
    for (var k = 0u; k < nb; k++) {
        let b = first + k;
        let awake = !is_static(b) && !asleep(b);
        let o = b * BS;
        var lin = vec3_at_state(o + 7u);
        let ang = vec3_at_state(o + 10u);
        if awake {
            lin = lin + g * dt;
            awake_mask |= 1u << k;
            reach[k] = (length3(lin) + length3(ang) * body_const(b, 10u)) * dt;
        } else {
            reach[k] = Scalar(0.0);
        }
        if !is_static(b) {
            movable |= 1u << k;
        }
        put_scratch(6u * b, lin);
        put_scratch(6u * b + 3u, ang);
        placed[k] = placed_body(b);
        boxes[k] = aabb_of(placed[k], reach[k] + Scalar(0.5) * margin);
    }
    // (1) Candidates, packed i | j << 8.
    var cands: array<u32, 120>;
    var nc = 0u;
    var spent = 0u;
    for (var i = 0u; i < nb; i++) {
        for (var j = i + 1u; j < nb; j++) {
            let bi = boxes[i];
            let bj = boxes[j];
            let either = ((movable >> i) | (movable >> j)) & 1u;
            var candidate = false;
            if bi.ok && bj.ok {
                candidate = either != 0u && overlaps(bi, bj);
            } else if bi.ok != bj.ok {
                // A plane with a movable bounded body.
                let other = select(i, j, bj.ok);
                let plane = select(j, i, bj.ok);
                candidate = ((movable >> other) & 1u) != 0u;
                if placed[other].kind == KIND_BOX {
                    let pm = margin + reach[i] + reach[j];
                    candidate = candidate && !box_far_from_plane(placed[other], placed[plane], pm);
                }
            }
            spent += 1u;
            if candidate {
                cands[nc] = i | (j << 8u);
                nc++;
            }
        }
    }
    // (2) Bodies an awake body can reach through candidates.
    var live = awake_mask;
    loop {
        let before = live;
        for (var c = 0u; c < nc; c++) {
            let ij = (1u << (cands[c] & 0xffu)) | (1u << (cands[c] >> 8u));
            if (live & ij) != 0u {
                live |= movable & ij;
            }
        }
        if live == before {
            break;
        }
    }
    // Their candidates by family: box–box, box–plane, with a sphere.
    var family: array<array<u32, 120>, 3>;
    var members = vec3<u32>(0u, 0u, 0u);
    for (var c = 0u; c < nc; c++) {
        let i = cands[c] & 0xffu;
        let j = cands[c] >> 8u;
        if (live & ((1u << i) | (1u << j))) == 0u {
            continue;
        }
        let ki = placed[i].kind;
        let kj = placed[j].kind;
        var f = 2u;
        if ki == KIND_BOX && kj == KIND_BOX {
            f = 0u;
        } else if ki != KIND_SPHERE && kj != KIND_SPHERE {
            f = 1u;
        }
        family[f][members[f]] = c;
        members[f] += 1u;
    }
    var got: array<u32, 120>;
    for (var t = 0u; t < members.x; t++) {
        let c = family[0][t];
        let i = cands[c] & 0xffu;
        let j = cands[c] >> 8u;
        let x = placed[i];
        let y = placed[j];
        got[c] = keep_manifold(w, c, box_box(x, x.size, y, y.size, margin + reach[i] + reach[j]), false);
    }
    for (var t = 0u; t < members.y; t++) {
        let c = family[1][t];
        let i = cands[c] & 0xffu;
        let j = cands[c] >> 8u;
        // collide_shapes: box_plane with the box first, flipped where the
        // plane was the first shape.
        let flipped = placed[i].kind == KIND_PLANE;
        let b = placed[select(i, j, flipped)];
        let p = placed[select(j, i, flipped)];
        let m = box_plane(b, b.size, p.centre, p.size, margin + reach[i] + reach[j]);
        got[c] = keep_manifold(w, c, m, flipped);
    }
    for (var t = 0u; t < members.z; t++) {
        let c = family[2][t];
        let i = cands[c] & 0xffu;
        let j = cands[c] >> 8u;
        let flipped = placed[i].kind != KIND_SPHERE;
        let s = placed[select(i, j, flipped)];
        let o = placed[select(j, i, flipped)];
        let m = collide_sphere(s, o, margin + reach[i] + reach[j]);
        got[c] = keep_manifold(w, c, m, flipped);
    }
    spent += 400u * (members.x + members.y + members.z);
    // (3) world_contacts' rounds.
    var done: array<u32, 4>;
    var count = 0u;
    var flags = 0u;
    let slot0 = w * sp.slots;
    loop {
        var woke = false;
        for (var c = 0u; c < nc; c++) {
            let i = cands[c] & 0xffu;
            let j = cands[c] >> 8u;
            spent += 1u;
            let bit = 1u << (c & 31u);
            let seen = (done[c >> 5u] & bit) != 0u;
            let on = (((awake_mask >> i) | (awake_mask >> j)) & 1u) != 0u;
            if seen || !on {
                continue;
            }
            done[c >> 5u] |= bit;
            let len = got[c] & ~OVERFLOW;
            if len == 0u {
                continue;
            }
            for (var s = 0u; s < 2u; s++) {
                let x = select(i, j, s == 1u);
                if ((movable >> x) & 1u) != 0u && ((awake_mask >> x) & 1u) == 0u {
                    awake_mask |= 1u << x;
                    // step.rs prepare: a woken body's v* is Δt g.
                    put_scratch(6u * (first + x), g * dt);
                    put_scratch(6u * (first + x) + 3u, vec3<Scalar>(0.0, 0.0, 0.0));
                    woke = true;
                }
            }
            if (got[c] & OVERFLOW) != 0u || len > SLOTS {
                flags |= CONTACTS_FULL;
            }
            // The dynamic body is a (normal from b to a).
            let swap = is_static(first + i);
            for (var h = 0u; h < min(len, SLOTS); h++) {
                if count >= sp.slots {
                    flags |= CONTACTS_FULL;
                    break;
                }
                let kept = sp.pairs_at + (w * sp.pair_slots + SLOTS * c + h) * CP;
                let normal = vec3_at_scratch(kept + 3u);
                let slot = slot0 + count;
                count++;
                let at = sp.contacts_at + slot * CP;
                put_scratch(at, vec3_at_scratch(kept));
                put_scratch(at + 3u, select(normal, -normal, swap));
                scratch[at + 6u] = scratch[kept + 6u];
                scratch[at + 7u] = Scalar(0.0);
                let a = select(i, j, swap);
                let b = select(j, i, swap);
                let key = sp.keys_at + 4u * slot;
                words[key] = a;
                words[key + 1u] = b;
                words[key + 2u] = u32(scratch[kept + 7u]);
                words[key + 3u] = 0u;
            }
        }
        if !woke || spent > sp.budget {
            break;
        }
    }
    if spent > sp.budget || !loops_left() {
        flags |= BUDGET;
    }
    let out = sp.out_at + 4u * w;
    words[out] = count;
    words[out + 1u] = awake_mask;
    words[out + 2u] = flags;
    words[out + 3u] = 0u;
}
