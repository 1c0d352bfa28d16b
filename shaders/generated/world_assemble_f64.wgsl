// GENERATED from shaders/collide.wgsl (functions above its pair functions) + shaders/lemke.wgsl (functions) + shaders/world_step.wgsl + shaders/world_bodies.wgsl + shaders/world_assemble.wgsl by src/gpu/shaders/compose.rs: do not edit.
// Regenerate: LCPBATCH_BLESS_SHADERS=1 cargo test --release generated_shaders_are_committed

// Narrow phase: the contact points of candidate pairs of bodies (entry
// point `collide_pairs`, one invocation per pair). CPU twins:
// src/world/collide.rs (collide_shapes, sphere_plane, sphere_sphere,
// corners, box_plane, sphere_box, reduce_to_four) and
// src/world/collide_box.rs (radius, best_axis, box_box, face_contact, clip,
// edge_contact): the same names, the same operations in the same order
// (glam's: dot (x·x' + y·y') + z·z', M v = (c0 v.x + c1 v.y) + c2 v.z,
// Mᵀ v by columns' dots, the quaternion normalised then turned into a
// matrix as DMat3::from_quat does), the same tolerances, margins and
// feature ids; ties broken as Rust's min_by (first) and max_by (last)
// with f64::total_cmp (−0 before +0), and f64::signum's sign of a zero.
//
// The functions up to the stage's bindings take values only, so that a
// kernel stepping resident worlds can call them on its own buffers.
//
// Packed layouts (src/gpu/collide.rs): body BODY = 12 scalars (position,
// orientation quaternion x, y, z, w (normalised here, as RigidBody::rotation
// does), shape kind (0 sphere, 1 box, 2 plane), shape parameters (radius,
// 0, 0 | half extents | plane normal), static flag (1: static)); per pair
// its bodies (i, j) and its margin; out, SLOTS = 4 contact slots per pair
// (point, normal, gap, pad: POINT = 8 scalars; keys a, b, feature, 0) and
// a count per pair: the manifold's points, with OVERFLOW set where they did
// not fit (more than SLOTS, or a manifold or clipped polygon past its
// capacity; the CPU twins never make one), so nothing is cut silently.
//
// The generator (src/gpu/shaders/compose.rs) replaces the line marked HOST
// (scalar type) and writes shaders/generated/<name>_f32.wgsl and _f64.wgsl.

alias Scalar = f64; // HOST scalar

const BODY: u32 = 12u;
const KIND_SPHERE: u32 = 0u;
const KIND_BOX: u32 = 1u;
const KIND_PLANE: u32 = 2u;
// Manifold::CAPACITY: 8 box corners; a face quad clipped by 4 side planes.
const CAPACITY: u32 = 8u;
// Contact slots per pair: every manifold is reduced to at most 4 points.
const SLOTS: u32 = 4u;
const POINT: u32 = 8u;
const OVERFLOW: u32 = 0x80000000u;
// collide_box.rs CLIP_TOL: of the reference box's largest half extent.
const CLIP_TOL: Scalar = 1e-7;

// A shape placed in the world (collide.rs Placed): the rotation by its
// columns (the body's axes); `size` is the radius (x), the half extents or
// the plane's normal.
struct Placed {
    kind: u32,
    size: vec3<Scalar>,
    centre: vec3<Scalar>,
    c0: vec3<Scalar>,
    c1: vec3<Scalar>,
    c2: vec3<Scalar>,
}

// glam's dot: (x x' + y y') + z z'.
fn dot3(a: vec3<Scalar>, b: vec3<Scalar>) -> Scalar {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

fn length3(a: vec3<Scalar>) -> Scalar {
    return sqrt(dot3(a, a));
}

// glam's cross.
fn cross3(a: vec3<Scalar>, b: vec3<Scalar>) -> vec3<Scalar> {
    return vec3<Scalar>(a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y);
}

// The sign bit of x (f32 keeps it through the conversion; WGSL has no f64
// bitcast).
fn sign_bit(x: Scalar) -> bool {
    return (bitcast<u32>(f32(x)) & 0x80000000u) != 0u;
}

// f64::signum: ±1 by the sign bit, −1 for −0.
fn signum(x: Scalar) -> Scalar {
    return select(Scalar(1.0), Scalar(-1.0), sign_bit(x));
}

// a < b in f64::total_cmp's order (finite values: −0 before +0).
fn total_less(a: Scalar, b: Scalar) -> bool {
    if a != b {
        return a < b;
    }
    return sign_bit(a) && !sign_bit(b);
}

// Column k of p's rotation.
fn col(p: Placed, k: u32) -> vec3<Scalar> {
    if k == 0u {
        return p.c0;
    }
    if k == 1u {
        return p.c1;
    }
    return p.c2;
}

// R v (glam's mul_vec3).
fn rotate(p: Placed, v: vec3<Scalar>) -> vec3<Scalar> {
    return p.c0 * v.x + p.c1 * v.y + p.c2 * v.z;
}

// Rᵀ v (glam's transpose then mul_vec3).
fn unrotate(p: Placed, v: vec3<Scalar>) -> vec3<Scalar> {
    return vec3<Scalar>(dot3(p.c0, v), dot3(p.c1, v), dot3(p.c2, v));
}

// The shape `kind` (`size`) at `centre` turned by the quaternion q
// (x, y, z, w), normalised as DQuat::normalize, as DMat3::from_quat.
fn placed_from(kind: u32, size: vec3<Scalar>, centre: vec3<Scalar>, q0: vec4<Scalar>) -> Placed {
    let len = sqrt(q0.x * q0.x + q0.y * q0.y + q0.z * q0.z + q0.w * q0.w);
    let recip = Scalar(1.0) / len;
    let q = q0 * recip;
    let x2 = q.x + q.x;
    let y2 = q.y + q.y;
    let z2 = q.z + q.z;
    let xx = q.x * x2;
    let xy = q.x * y2;
    let xz = q.x * z2;
    let yy = q.y * y2;
    let yz = q.y * z2;
    let zz = q.z * z2;
    let wx = q.w * x2;
    let wy = q.w * y2;
    let wz = q.w * z2;
    return Placed(
        kind,
        size,
        centre,
        vec3<Scalar>(Scalar(1.0) - (yy + zz), xy + wz, xz - wy),
        vec3<Scalar>(xy - wz, Scalar(1.0) - (xx + zz), yz + wx),
        vec3<Scalar>(xz + wy, yz - wx, Scalar(1.0) - (xx + yy)),
    );
}

fn max_element(h: vec3<Scalar>) -> Scalar {
    return max(h.x, max(h.y, h.z));
}


// Lemke's complementary pivoting method, the textbook run: one invocation
// per island. CPU twin: `lemke_textbook_basis` (src/cpu/lemke.rs) on
// `Workspace::pivot_path` (src/cpu/lemke_tableau.rs) with Noise::Column:
// the same tableau, tests and pivots in the same order, so that in f64 it
// ends on the CPU's basis.
//
// The tableau is B^-1 [I, -M, -e | q] (covering vector e = 1), n rows of
// 2n + 2 columns, row-major in the private array `t`: w_0..w_{n-1},
// z_0..z_{n-1}, z0, rhs; basic[i] is the variable basic in row i (w_i = i,
// z_i = n + i, z0 = 2n). A private array rather than a scratch storage
// buffer: it needs no binding or allocation per batch, and drivers already
// lay thread-private memory out interleaved by thread (coalesced), which is
// what a scratch buffer would have to arrange by hand.
//
// The island's record (BasisResult, shaders/enumeration_basis.wgsl): status
// FOUND (1) with `mask` the final basis (bit i: z_i basic), `visited` the
// pivots, z read from the tableau; or GAVE_UP (4): a secondary ray with z0
// not at zero, the pivot cap (tol._pad1), the loop budget, or a non-finite
// entry. There is no cycle detection: the host solves every island the
// kernel gave up on by the CPU path (which detects cycles). One round: the
// kernel never counts itself in `unfinished`.
//
// Loop budget: llvmpipe (lavapipe) ends every loop of an invocation after
// about 65,535 iterations in all, silently; an invocation gives up before a
// pivot whose loop work (an upper bound, `step`) would take it past
// params.budget (below that limit on software adapters).
//
// Tolerances (binding 7): _pad0 is the Lemke pivot tolerance (an entry of
// the entering column is a pivot when it exceeds it times the column's
// largest magnitude), _pad1 the pivot cap (src/gpu/pipelines.rs).

const SCALAR_MAX: Scalar = 1.7976931348623157e308; // HOST scalar_max

const GAVE_UP: u32 = 4u;

var<private> t: array<Scalar, 544>; // MAX_N * (2 * MAX_N + 2)
var<private> basic: array<u32, 16>;
// Rows whose entry in the entering column counts as a pivot.
var<private> cand: array<u32, 16>;
// Rows still tied in the lexicographic ratio test.
var<private> tied: array<u32, 16>;

fn finite(v: Scalar) -> bool {
    return abs(v) <= SCALAR_MAX;
}

// Gauss-Jordan pivot on (row r, column c): row r divided by its pivot, then
// every other row minus its entry in column c times row r (Workspace::pivot).
// False when an entry it wrote is not finite.
fn pivot(n: u32, r: u32, c: u32) -> bool {
    let cols = 2u * n + 2u;
    let pr = r * cols;
    let inv = Scalar(1.0) / t[pr + c];
    var ok = finite(inv);
    for (var j = 0u; j < cols; j++) {
        let v = t[pr + j] * inv;
        t[pr + j] = v;
        ok = ok && finite(v);
    }
    t[pr + c] = Scalar(1.0);
    for (var i = 0u; i < n; i++) {
        let ri = i * cols;
        let f = t[ri + c];
        if i != r && f != Scalar(0.0) {
            for (var j = 0u; j < cols; j++) {
                let v = t[ri + j] - f * t[pr + j];
                t[ri + j] = v;
                ok = ok && finite(v);
            }
            t[ri + c] = Scalar(0.0);
        }
    }
    return ok;
}

// The ratio-test key of row i in column col for the entering column e
// (Workspace::leaving_row): rhs values rounding made negative count as 0.
fn key(cols: u32, i: u32, col: u32, e: u32) -> Scalar {
    var v = t[i * cols + col];
    if col == cols - 1u {
        v = max(v, Scalar(0.0));
    }
    return v / t[i * cols + e];
}

// The lexicographic minimum-ratio test over cand[0..count]
// (Workspace::leaving_row): the minimum ratio; on a tie z0's row if it is
// tied, else the lexicographic minimum of the rows of B^-1 over the entry.
// n + 1 when a ratio is not finite (the caller gives up).
fn leaving_row(n: u32, e: u32, count: u32) -> u32 {
    let cols = 2u * n + 2u;
    let rhs = cols - 1u;
    var first = cand[0];
    var least = key(cols, first, rhs, e);
    var ties = 1u;
    for (var k = 1u; k < count; k++) {
        let v = key(cols, cand[k], rhs, e);
        if v < least {
            least = v;
            first = cand[k];
            ties = 1u;
        } else if v == least {
            ties++;
        }
    }
    if !finite(least) {
        return n + 1u;
    }
    if ties <= 1u {
        return first;
    }
    var m = 0u;
    for (var k = 0u; k < count; k++) {
        if key(cols, cand[k], rhs, e) <= least {
            tied[m] = cand[k];
            m++;
        }
    }
    for (var k = 0u; k < m; k++) {
        if basic[tied[k]] == 2u * n {
            return tied[k];
        }
    }
    for (var col = 0u; col < n; col++) {
        var low = key(cols, tied[0], col, e);
        for (var k = 1u; k < m; k++) {
            low = min(low, key(cols, tied[k], col, e));
        }
        var kept = 0u;
        for (var k = 0u; k < m; k++) {
            if key(cols, tied[k], col, e) <= low {
                tied[kept] = tied[k];
                kept++;
            }
        }
        m = kept;
        if m <= 1u {
            break;
        }
    }
    if m == 0u {
        return first;
    }
    return tied[0];
}

// The path from the tableau in `t` (B = I: rows w_i = q_i, columns
// [I, -M, -e | q], basic[i] = i), n contacts; `spent`: the loop work of
// filling it. Returns FOUND (1; the basis in `basic`, zero pivots where q >=
// 0) or GAVE_UP, the pivots in `visited`. Takes values only (the tableau is
// private), so that another kernel (shaders/world_step.wgsl) can fill `t`
// and call it.
fn lemke_pivots(n: u32, spent0: u32, pivot_tol: Scalar, max_pivots: u32, budget: u32, visited: ptr<function, u32>) -> u32 {
    let cols = 2u * n + 2u;
    let rhs = cols - 1u;
    let z0 = 2u * n;
    var q_scale = Scalar(0.0);
    var separating = true;
    var qmin = t[rhs];
    var first = 0u;
    for (var i = 0u; i < n; i++) {
        let qi = t[i * cols + rhs];
        separating = separating && qi >= Scalar(0.0);
        q_scale = max(q_scale, abs(qi));
        // The first leaving row: the most negative q_i, ties to the
        // largest index (Workspace::first_row).
        if qi <= qmin {
            qmin = qi;
            first = i;
        }
    }
    if separating {
        return 1u;
    }
    // Loop work of one pivot and its tests, an upper bound.
    let step = (n + 1u) * cols + 2u * n * n + 6u * n;
    var spent = spent0 + n + step;
    if !pivot(n, first, z0) {
        return GAVE_UP;
    }
    *visited = 1u;
    var entering = basic[first] + n;
    basic[first] = z0;
    loop {
        if *visited >= max_pivots || spent + step > budget {
            return GAVE_UP;
        }
        spent += step;
        var colmax = Scalar(0.0);
        for (var i = 0u; i < n; i++) {
            let v = abs(t[i * cols + entering]);
            if v > colmax {
                colmax = v;
            }
        }
        let floor = pivot_tol * colmax;
        var count = 0u;
        for (var i = 0u; i < n; i++) {
            if t[i * cols + entering] > floor {
                cand[count] = i;
                count++;
            }
        }
        if count == 0u || colmax == Scalar(0.0) {
            // A secondary ray: a solution only with z0 at zero to rounding.
            for (var i = 0u; i < n; i++) {
                if basic[i] == z0 {
                    if t[i * cols + rhs] <= pivot_tol * q_scale {
                        return 1u;
                    }
                    break;
                }
            }
            return GAVE_UP;
        }
        let best = leaving_row(n, entering, count);
        if best >= n || !pivot(n, best, entering) {
            return GAVE_UP;
        }
        *visited += 1u;
        let leaving = basic[best];
        basic[best] = entering;
        if leaving == z0 {
            return 1u;
        }
        if leaving < n {
            entering = leaving + n;
        } else {
            entering = leaving - n;
        }
    }
    return GAVE_UP;
}


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

const SCALAR_EPSILON: Scalar = 2.220446049250313e-16; // HOST scalar_epsilon

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

// Assembly of the resident step's islands (shaders/world_step.wgsl's
// header; a module of its own, composed after world_step.wgsl and
// world_bodies.wgsl): per world the islands (src/islands.rs find_islands),
// the handover of a world with friction to world_friction, and per island
// its contact rows and M (src/cpu/assembly.rs assemble_contact /
// assemble_island), kept per contact slot (`row_at`: q, the response
// M⁻¹Jᵀ, the contact's row of M) for the solve (world_solve.wgsl,
// world_lemke.wgsl) and the impulses (world_finish.wgsl); the entry point
// `world_assemble`.

// One island's contact rows (src/cpu/assembly.rs ContactRow), row i of the
// island at 12 i: the Jacobian and the response M⁻¹Jᵀ of sides a (0..6)
// and b (6..12) (the dynamic body of each side: `sides`,
// shaders/world_bodies.wgsl); q.
var<private> jac: array<Scalar, 192>;
var<private> resp: array<Scalar, 192>;
var<private> qv: array<Scalar, 16>;
// The island's M (row i at ISLAND_MAX i).
var<private> mm: array<Scalar, 256>;

fn put_row(dst: ptr<private, array<Scalar, 192>>, at: u32, v: vec3<Scalar>) {
    (*dst)[at] = v.x;
    (*dst)[at + 1u] = v.y;
    (*dst)[at + 2u] = v.z;
}

// The world-frame inverse inertia R diag(1/I) Rᵀ of body b (global index)
// times v, at the step's start pose.
fn inv_inertia_mul(b: u32, v: vec3<Scalar>) -> vec3<Scalar> {
    let p = placed_body(b);
    let inv = vec3_at_consts(sp.bodies_at + b * BC + 6u);
    return rotate(p, inv * unrotate(p, v));
}

// assemble_contact: row i of the island from contact `slot` of world with
// first body `first` and moving-body mask `moving`; bias φ/Δt, ε = 0.
fn assemble_contact(slot: u32, i: u32, first: u32, moving: u32) {
    let at = sp.contacts_at + slot * CP;
    let key = sp.keys_at + 4u * slot;
    let a = words[key];
    let b = words[key + 1u];
    let p = vec3_at_scratch(at);
    let n = vec3_at_scratch(at + 3u);
    let gap = scratch[at + 6u];
    let ga = first + a;
    let gb = first + b;
    let ra = p - vec3_at_state(ga * BS);
    let rb = p - vec3_at_state(gb * BS);
    let ra_n = cross3(ra, n);
    let rb_n = cross3(rb, n);
    let r = 12u * i;
    put_row(&jac, r, n);
    put_row(&jac, r + 3u, ra_n);
    put_row(&jac, r + 6u, -n);
    put_row(&jac, r + 9u, -rb_n);
    let s = contact_sides(slot, moving);
    if s.x != NONE {
        put_row(&resp, r, n * body_const(ga, 5u));
        put_row(&resp, r + 3u, inv_inertia_mul(ga, ra_n));
    }
    if s.y != NONE {
        put_row(&resp, r + 6u, -n * body_const(gb, 5u));
        put_row(&resp, r + 9u, -inv_inertia_mul(gb, rb_n));
    }
    sides[i] = s;
    let pdot = (lin[a] + cross3(ang[a], ra)) - (lin[b] + cross3(ang[b], rb));
    qv[i] = dot3(pdot, n) + gap / sp.dt;
}

fn dot6(x: u32, y: u32) -> Scalar {
    var m = Scalar(0.0);
    for (var k = 0u; k < 6u; k++) {
        m += jac[x + k] * resp[y + k];
    }
    return m;
}

// assembly.rs matrix_entry: M_ij over the dynamic bodies rows i and j
// share, the sides in its order (a–a, a–b, b–a, b–b), into `mm` for the
// island's n rows.
fn fill_matrix(n: u32) {
    for (var i = 0u; i < n; i++) {
        let si = sides[i];
        for (var j = 0u; j < n; j++) {
            let sj = sides[j];
            // A side of row i meets at most one side of row j (a row's
            // two bodies differ): one dot6 per side of row i, in order.
            let ja = select(6u, 0u, si.x == sj.x);
            let jb = select(6u, 0u, si.y == sj.x);
            var m = Scalar(0.0);
            if si.x != NONE && (si.x == sj.x || si.x == sj.y) {
                m += dot6(12u * i, 12u * j + ja);
            }
            if si.y != NONE && (si.y == sj.x || si.y == sj.y) {
                m += dot6(12u * i + 6u, 12u * j + jb);
            }
            mm[ISLAND_MAX * i + j] = m;
        }
    }
}

// The island's n rows kept in their contact slots (`row_at`: q, the
// response of sides a and b, the row of M over the island's members).
fn keep_rows(w: u32, n: u32, members: ptr<function, array<u32, 16>>) {
    let slot0 = w * sp.slots;
    for (var i = 0u; i < n; i++) {
        let r = row_at(slot0 + (*members)[i]);
        scratch[r] = qv[i];
        for (var k = 0u; k < 12u; k++) {
            scratch[r + 1u + k] = resp[12u * i + k];
        }
        for (var j = 0u; j < n; j++) {
            scratch[r + 13u + j] = mm[ISLAND_MAX * i + j];
        }
    }
}

fn find(parent: ptr<function, array<u32, 16>>, x0: u32) -> u32 {
    var x = x0;
    while (*parent)[x] != x {
        (*parent)[x] = (*parent)[(*parent)[x]];
        x = (*parent)[x];
    }
    return x;
}



// A world's contacts as the solve starts (`begin_world`): contacts, the
// moving-body mask, the flags of world_contacts, islands, the deepest
// penetration; `handed`: the world has friction
// and went to world_friction (or was flagged NOT_SOLVED without it).
struct Begun {
    count: u32,
    moving: u32,
    flags: u32,
    islands: u32,
    max_penetration: Scalar,
    handed: bool,
}

// World w's islands (each contact's in its key's fourth word) and its
// deepest penetration; its velocities v* into lin, ang (assembly's v_rel). A world with friction (a contact with μ > 0: Scene::has_friction)
// goes to world_friction, flagged HANDED until that finishes it; its
// rounds there are counted from 0 (the record's sixth scalar).
fn begin_world(w: u32) -> Begun {
    let first = worlds[w].x;
    let out = sp.out_at + 4u * w;
    let count = words[out];
    let moving = words[out + 1u];
    var flags = words[out + 2u];
    let slot0 = w * sp.slots;
    records[w * REC + 5u] = Scalar(0.0);
    load_velocities(w);
    var parent: array<u32, 16>;
    var island_of_root: array<u32, 16>;
    for (var k = 0u; k < MAX_BODIES; k++) {
        parent[k] = k;
        island_of_root[k] = NONE;
    }
    for (var c = 0u; c < count; c++) {
        let key = sp.keys_at + 4u * (slot0 + c);
        let a = words[key];
        let b = words[key + 1u];
        if ((moving >> a) & (moving >> b) & 1u) != 0u {
            let ra = find(&parent, a);
            let rb = find(&parent, b);
            parent[max(ra, rb)] = min(ra, rb);
        }
    }
    var islands = 0u;
    var max_penetration = Scalar(0.0);
    for (var c = 0u; c < count; c++) {
        let key = sp.keys_at + 4u * (slot0 + c);
        let a = words[key];
        let body = select(words[key + 1u], a, ((moving >> a) & 1u) != 0u);
        let root = find(&parent, body);
        if island_of_root[root] == NONE {
            island_of_root[root] = islands;
            islands++;
        }
        words[key + 3u] = island_of_root[root];
        max_penetration = max(max_penetration, -scratch[sp.contacts_at + (slot0 + c) * CP + 6u]);
    }
    var frictional = false;
    for (var c = 0u; c < count; c++) {
        let key = sp.keys_at + 4u * (slot0 + c);
        frictional = frictional || pair_friction(first + words[key], first + words[key + 1u]) > Scalar(0.0);
    }
    let fs = sp.fstate_at + 4u * w;
    words[fs] = F_IDLE;
    words[out + 3u] = islands;
    var handed = false;
    if frictional && flags == 0u {
        if sp.friction_at == 0u {
            flags |= NOT_SOLVED;
        } else {
            words[fs] = F_ASSEMBLE;
            words[fs + 1u] = 0u;
            words[fs + 2u] = 0u;
            words[out + 2u] = HANDED;
            records[w * REC + 2u] = max_penetration;
            records[w * REC + 3u] = Scalar(0.0);
            handed = true;
        }
    }
    return Begun(count, moving, flags, islands, max_penetration, handed);
}


// Step part 2 up to the solve for world w: its islands, each assembled
// and kept (`keep_rows`) in island order; an island above ISLAND_MAX
// contacts flags the world (ISLAND_TOO_LARGE; the islands after it are
// not assembled), as does friction without the frictional phase
// (NOT_SOLVED). A world with friction is handed to world_friction.
@compute @workgroup_size(64)
fn world_assemble(@builtin(global_invocation_id) gid: vec3<u32>) {
    let w = gid.x;
    if w >= sp.count {
        return;
    }
    let b = begin_world(w);
    records[w * REC + 2u] = b.max_penetration;
    if b.handed {
        return;
    }
    var flags = b.flags;
    var members: array<u32, 16>;
    for (var isl = 0u; isl < b.islands && flags == 0u; isl++) {
        let n = island_members(w, b.count, isl, &members);
        if n > ISLAND_MAX {
            flags |= ISLAND_TOO_LARGE;
            break;
        }
        for (var i = 0u; i < n; i++) {
            assemble_contact(w * sp.slots + members[i], i, worlds[w].x, b.moving);
        }
        fill_matrix(n);
        keep_rows(w, n, &members);
    }
    words[sp.out_at + 4u * w + 2u] = flags;
}
