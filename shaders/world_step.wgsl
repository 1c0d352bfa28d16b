// One step of resident worlds (restitution 0): the step's parameters,
// bindings, layouts and shared functions, composed (src/gpu/shaders/
// compose.rs) into one module per phase, each with only what its phase
// calls (naga writes every function of a module that touches no global
// the entry point omits into its SPIR-V: pair functions into the solve,
// Lemke into the collision, had they shared a module). The entry points,
// dispatched in this order in one submission, no host round trip between
// them (src/gpu/resident/dispatch.rs):
// - module world_collide (after shaders/collide.wgsl's functions):
//   `candidate_pairs` per world (src/world/step.rs `prepare`: gravity; the
//   candidates of broad.rs `candidate_pairs`, listed by pair family), the
//   narrow phase per listed pair and family in indirect dispatches
//   (`narrow_box_box`, `narrow_box_plane`, `narrow_sphere`: collide.rs
//   `collide_shapes`' pair functions), `world_contacts` per world (step.rs
//   `world_contacts`: waking rounds, the contacts in pair order);
//   shaders/world_collide.wgsl;
// - module world_solve (after collide.wgsl's functions above its pair
//   functions and shaders/lemke.wgsl's, with shaders/world_bodies.wgsl
//   and world_island.wgsl): `world_solve_warm` per world (src/islands.rs
//   `find_islands`, src/cpu/assembly.rs `assemble_contact` /
//   `assemble_island`, the warm bases of world_cpu.rs `warm_settle`, the
//   door's check `lcp_error` <= tolerance, `apply_impulses`; the islands
//   whose warm basis does not hold, every island without warm bases,
//   listed with their world); shaders/world_solve.wgsl;
// - module world_lemke (the same, shaders/world_lemke.wgsl):
//   `world_lemke` per listed world (its listed islands by Lemke's path
//   `lemke_pivots`, the basis re-solved, the check, the impulses);
// - module world_friction (after the same, shaders/world_bodies.wgsl,
//   world_friction.wgsl, world_apgd.wgsl and friction_common.wgsl's cone
//   projection): `world_friction` per world handed over by the solve, in
//   rounds;
// - module world_finish (shaders/world_bodies.wgsl, world_finish.wgsl):
//   `world_finish` per world (step.rs `finish` with `integrate_rotation`,
//   the world's figures; a world world_friction finished: its reactions
//   remembered first).
// Several entry points rather than one: llvmpipe ends every loop of an
// invocation after about 65,535 iterations in all, and each dispatch
// starts that count afresh; each phase's code is a fraction of the step's
// (a driver compiles each entry point on its own).
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
//   contact slot CP scalars (point 3, normal 3, gap, z), then per contact
//   slot ROW scalars (`row_at`: q, the response M⁻¹Jᵀ of sides a and b,
//   the contact's row of its island's M (world_assemble), the basic
//   variable of its row where Lemke's path ended (world_lemke)); from
//   params.pairs_at per world params.pair_slots pair records of CP scalars
//   (point 3, normal 3, gap, feature), SLOTS per candidate pair;
// - words: per body 2 (asleep, quiet steps); from params.out_at per world 4
//   (contacts, moving-body mask, flags, islands); from params.keys_at per
//   contact slot 4 (a, b, feature, island);
// - records: per world REC scalars (kinetic, potential, max penetration,
//   max error, awake, friction rounds, and the solve's warm-start
//   memory: a hash of last step's contact ids, their bases);
// - scratch, from params.reach_at: per body its reach this step
//   (candidate_pairs);
// - words, from params.cands_at: per world its candidates (their count,
//   then pairs_per_world() bodies i | j << 8, then as many count words of
//   the narrow phase: points | OVERFLOW | CUT);
// - lists: four headers (workgroups x, y, z of an indirect dispatch, the
//   count), then the entries of each list (`list_at`): the worlds
//   `world_solve_warm` leaves to `world_lemke` with their islands (two
//   words each; emptied by candidate_pairs), the box–box, box–plane and sphere pairs
//   (world << 8 | candidate; filled by candidate_pairs, emptied by
//   world_contacts for the next step).

const SCALAR_EPSILON: Scalar = 1.1920929e-7; // HOST scalar_epsilon

const MAX_BODIES: u32 = 16u;
const WC: u32 = 6u;
const BC: u32 = 12u;
const BS: u32 = 13u;
const CP: u32 = 8u;
const REC: u32 = 8u;
const ROW: u32 = 30u;
const ISLAND_MAX: u32 = 16u;

const CONTACTS_FULL: u32 = 1u;
const ISLAND_TOO_LARGE: u32 = 2u;
const NOT_SOLVED: u32 = 4u;
const NON_FINITE: u32 = 8u;
const BUDGET: u32 = 16u;
const HANDED: u32 = 32u; // with world_friction until it finishes the world (world_solve.wgsl begin_world)

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
    // The narrow phase's pair records: where they start in `scratch`, and
    // records per world (SLOTS per candidate pair).
    pairs_at: u32,
    pair_slots: u32,
    // 1: world_solve_warm tries last step's bases first (the CPU path's
    // warm_settle: warm starts on, a method that predicts).
    warm_bases: u32,
    // candidate_pairs' lists: where the worlds' candidates start in
    // `words`, where the bodies' reaches start in `scratch`.
    cands_at: u32,
    reach_at: u32,
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
@group(0) @binding(7) var<storage, read_write> lists: array<atomic<u32>>;

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

// Where contact slot `slot`'s row starts in `scratch`: after the contact
// slots (q, response 12, the row of M over the island's members 16, the
// row's basic variable at Lemke's end 1).
fn row_at(slot: u32) -> u32 {
    return sp.contacts_at + sp.count * sp.slots * CP + slot * ROW;
}

// The frictional phase's (shaders/world_friction.wgsl) per-world phases,
// set by the solve's handover (world_solve.wgsl begin_world); F_DONE:
// every island solved, for world_finish to finish.
const F_IDLE: u32 = 0u;
const F_ASSEMBLE: u32 = 1u;
const F_SWEEP: u32 = 2u;
const F_DONE: u32 = 3u;

// μ = √(μ_a μ_b) of bodies ga, gb (global).
fn pair_friction(ga: u32, gb: u32) -> Scalar {
    return sqrt(body_const(ga, 11u) * body_const(gb, 11u));
}

// Work lists in `lists` (header at 4 f: workgroups x, y, z, count): 0
// the worlds world_solve_warm leaves to world_lemke (two words each: the
// world, its islands for Lemke's path), 1 box–box pairs, 2 box–plane
// pairs, 3 pairs with a sphere.
const LIST_LEMKE: u32 = 0u;
const LIST_BOX_BOX: u32 = 1u;
const LIST_BOX_PLANE: u32 = 2u;
const LIST_SPHERE: u32 = 3u;

// Candidates per world at most: SLOTS pair records each.
fn pairs_per_world() -> u32 {
    return sp.pair_slots / SLOTS;
}

// Where list f's entries start in `lists`: after the four headers, the
// Lemke list (two words a world), then the pair lists (pairs_per_world()
// per world each).
fn list_at(f: u32) -> u32 {
    if f == LIST_LEMKE {
        return 16u;
    }
    return 16u + 2u * sp.count + (f - 1u) * sp.count * pairs_per_world();
}

// Appends `entry` to list f, its workgroups (of 64) grown to cover it.
fn push_list(f: u32, entry: u32) {
    let k = atomicAdd(&lists[4u * f + 3u], 1u);
    atomicMax(&lists[4u * f], k / 64u + 1u);
    atomicStore(&lists[list_at(f) + k], entry);
}

// Empties list f (its workgroups 0; y and z stay 1).
fn clear_list(f: u32) {
    atomicStore(&lists[4u * f], 0u);
    atomicStore(&lists[4u * f + 3u], 0u);
}

// False where llvmpipe's loop limit was reached in this invocation: past
// about 65,535 loop iterations of its group of invocations in one dispatch
// every loop ends after its current iteration, so whatever the
// invocation computed since may be cut short; this loop of two
// iterations then ends after one. (Its bound is not a constant, so the
// compiler keeps the loop.) Elsewhere always true.
fn loops_left() -> bool {
    let r = 2u + (sp.count >> 31u);
    var k = 0u;
    loop {
        if k >= r {
            break;
        }
        k++;
    }
    return k == r;
}
