// GENERATED from shaders/collide.wgsl (functions above its pair functions) + shaders/lemke.wgsl (functions) + shaders/world_step.wgsl + shaders/world_bodies.wgsl + shaders/world_friction.wgsl + shaders/world_apgd.wgsl + shaders/friction_common.wgsl (project_on_cone on) by src/gpu/shaders/compose.rs: do not edit.
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

// The frictional phase of shaders/world_step.wgsl (two modules, one per
// method: composed after world_step.wgsl and world_bodies.wgsl, before
// world_sweeps.wgsl (module world_friction: Jacobi, Gauss–Seidel) or
// world_apgd.wgsl (module world_friction_apgd), and the cone projection of
// friction_common.wgsl; each module holds only its method's code):
// the islands of the worlds with friction (a contact with μ > 0 this step;
// world_solve_warm hands them over with the phase F_ASSEMBLE and the flag
// HANDED, which stays until the world is finished), one invocation per
// world. `world_friction` is dispatched several times per step (rounds,
// after the solve, in the same submission); each invocation goes on where
// the last round stopped and does at most `sp.friction_budget` of loop work
// (llvmpipe ends an invocation's loops after about 65,535 iterations in
// all, counted over 8 invocations in lockstep). A world
// not finished after the step's last round keeps HANDED: the host steps it
// on the CPU. The rounds a world was active in this step are its record's
// sixth scalar (the host sizes the next step's rounds by them).
//
// Per island, the CPU twin's arithmetic in its order
// (src/solver/world_friction.rs with a projected method):
// - the rows n, t₁, t₂ of each contact (friction/assembly.rs
//   assemble_friction_contact: scene.rs tangent_basis, q = v_rel + φ/Δt
//   for n, v_rel for the tangents), W = J M⁻¹ Jᵀ over the shared dynamic
//   bodies (assemble_friction_island), μ = √(μ_a μ_b);
// - the sweeps of friction/projected.rs `sweeps` (Gauss–Seidel or Jacobi,
//   η per contact by contact_steps, relaxation 1): each iteration u =
//   W x + q, the stop measure, a sweep; from the warm start (the last
//   step's reactions of the same (a, b, feature)) or 0,
//   projected on the cones;
// - the judgement in f64 (ProjectedSolution::judge, FrictionResiduals):
//   solved when r and u are finite and the cone error is at most the
//   tolerance, else the world is flagged NOT_SOLVED (the CPU steps it);
//   the Coulomb error (Siconos fc3d with De Saxcé's correction) is the
//   world's max_error, as the CPU reports it;
// - the impulses (apply_friction_impulses); the world, every island
//   solved, is left F_DONE: world_finish (after the last round) remembers
//   its reactions and finishes it.
//
// With APGD (sp.gauss_seidel == METHOD_APGD) instead of the sweeps: the
// twin of friction/apgd.rs `apgd` (from the same start; L from
// first_lipschitz, backtracking by accept_step, the momentum and gradient
// restarts of apgd_iteration, the best iterate kept), judged as above on
// the best iterate and its u (the product that gave it, as the CPU's
// judgement computes it again). A round may end between two backtracking
// tries: the next goes on with the L it saved, as the twin's loop does.
//
// Per world in `scratch` from sp.friction_at, FR scalars: the rows (48 ×
// 24: Jacobian 12, response 12), W (3k × 3k, row-major), q, x, u, two
// temporaries (48 each; APGD's trial x and its u), μ and η (16 each);
// APGD's y, u(y), best, u(best) (48 each), θ, L, the best error. Per
// world in `words` from sp.fstate_at, 4 words: phase, island, sweeps (APGD
// iterations) done, APGD's doublings of L in this iteration.

const FR: u32 = 3923u;
const F_ROWS: u32 = 0u;
const F_W: u32 = 1152u;
const F_Q: u32 = 3456u;
const F_X: u32 = 3504u;
const F_U: u32 = 3552u;
const F_T1: u32 = 3600u;
const F_T2: u32 = 3648u;
const F_MU: u32 = 3696u;
const F_ETA: u32 = 3712u;
const F_Y: u32 = 3728u;
const F_UY: u32 = 3776u;
const F_BEST: u32 = 3824u;
const F_UBEST: u32 = 3872u;
const F_APGD: u32 = 3920u;

// sp.gauss_seidel: 0 Jacobi, 1 Gauss–Seidel sweeps, METHOD_APGD (the
// module world_friction_apgd; the sweeps are the module world_friction).
const METHOD_APGD: u32 = 2u;

// The method's iterations in a round (`method_round`: world_sweeps.wgsl or
// world_apgd.wgsl, one in each module): the budget spent first (the next
// round goes on), done, failed (the world flagged NOT_SOLVED), or done on
// a non-finite stop measure (judged as failed).
const ROUND_SPENT: u32 = 0u;
const ROUND_DONE: u32 = 1u;
const ROUND_FAILED: u32 = 2u;
const ROUND_NOT_FINITE: u32 = 3u;

// Below this scale the stop measure is not divided (projected.rs SCALE_FLOOR).
const SCALE_FLOOR: Scalar = Scalar(2.220446049250313e-16);

// The island's contact slots (global), in order.
var<private> fmembers: array<u32, 16>;

// scene.rs tangent_basis(n).
fn tangent_basis(n: vec3<Scalar>) -> array<vec3<Scalar>, 2> {
    let s = select(Scalar(-1.0), Scalar(1.0), n.z >= Scalar(-0.5));
    let a = Scalar(-1.0) / (s + n.z);
    let b = n.x * n.y * a;
    return array<vec3<Scalar>, 2>(
        vec3<Scalar>(Scalar(1.0) + s * n.x * n.x * a, s * b, -s * n.x),
        vec3<Scalar>(b, s + n.y * n.y * a, -n.y),
    );
}

// I⁻¹ v of body b (global) as the CPU's scene body holds I⁻¹: the matrix
// R diag(1/I) Rᵀ (RigidBody::inv_inertia_at, glam's products in their
// order), then glam's mul_vec3 (world_island.wgsl's inv_inertia_mul rotates the
// vector instead: the same up to rounding, which would part the sweeps'
// iterates from the CPU's).
fn inv_inertia_mat_mul(b: u32, v: vec3<Scalar>) -> vec3<Scalar> {
    let p = placed_body(b);
    let d = vec3_at_consts(sp.bodies_at + b * BC + 6u);
    let a0 = p.c0 * d.x;
    let a1 = p.c1 * d.y;
    let a2 = p.c2 * d.z;
    let m0 = a0 * p.c0.x + a1 * p.c1.x + a2 * p.c2.x;
    let m1 = a0 * p.c0.y + a1 * p.c1.y + a2 * p.c2.y;
    let m2 = a0 * p.c0.z + a1 * p.c1.z + a2 * p.c2.z;
    return m0 * v.x + m1 * v.y + m2 * v.z;
}

// Row `row` of the island at `base`: direction d at contact `slot` with
// sides `s` (tangent_row: assemble_contact's row with d for n). Returns
// v_rel = (ṗ_a − ṗ_b)·d.
fn assemble_direction(base: u32, row: u32, slot: u32, d: vec3<Scalar>, first: u32, s: vec2<u32>) -> Scalar {
    let key = sp.keys_at + 4u * slot;
    let a = words[key];
    let b = words[key + 1u];
    let p = vec3_at_scratch(sp.contacts_at + slot * CP);
    let ga = first + a;
    let gb = first + b;
    let ra = p - vec3_at_state(ga * BS);
    let rb = p - vec3_at_state(gb * BS);
    let ra_d = cross3(ra, d);
    let rb_d = cross3(rb, d);
    let o = base + F_ROWS + 24u * row;
    let zero = vec3<Scalar>(0.0, 0.0, 0.0);
    put_scratch(o, d);
    put_scratch(o + 3u, ra_d);
    put_scratch(o + 6u, -d);
    put_scratch(o + 9u, -rb_d);
    put_scratch(o + 12u, zero);
    put_scratch(o + 15u, zero);
    put_scratch(o + 18u, zero);
    put_scratch(o + 21u, zero);
    if s.x != NONE {
        put_scratch(o + 12u, d * body_const(ga, 5u));
        put_scratch(o + 15u, inv_inertia_mat_mul(ga, ra_d));
    }
    if s.y != NONE {
        put_scratch(o + 18u, -d * body_const(gb, 5u));
        put_scratch(o + 21u, -inv_inertia_mat_mul(gb, rb_d));
    }
    let pdot = (lin[a] + cross3(ang[a], ra)) - (lin[b] + cross3(ang[b], rb));
    return dot3(pdot, d);
}

// J_x (side si) · M⁻¹J_yᵀ (side sj) of rows x, y (dot6, summed in order).
fn rows_dot6(base: u32, x: u32, si: u32, y: u32, sj: u32) -> Scalar {
    let j = base + F_ROWS + 24u * x + 6u * si;
    let r = base + F_ROWS + 24u * y + 12u + 6u * sj;
    return scratch[j] * scratch[r] + scratch[j + 1u] * scratch[r + 1u]
        + scratch[j + 2u] * scratch[r + 2u] + scratch[j + 3u] * scratch[r + 3u]
        + scratch[j + 4u] * scratch[r + 4u] + scratch[j + 5u] * scratch[r + 5u];
}

// W's entry of rows x and y (assembly.rs matrix_entry over the dynamic
// bodies their contacts share; written out, without loops).
fn friction_entry(base: u32, x: u32, y: u32) -> Scalar {
    let si = sides[x / 3u];
    let sj = sides[y / 3u];
    var m = Scalar(0.0);
    if si.x != NONE && si.x == sj.x {
        m += rows_dot6(base, x, 0u, y, 0u);
    }
    if si.x != NONE && si.x == sj.y {
        m += rows_dot6(base, x, 0u, y, 1u);
    }
    if si.y != NONE && si.y == sj.x {
        m += rows_dot6(base, x, 1u, y, 0u);
    }
    if si.y != NONE && si.y == sj.y {
        m += rows_dot6(base, x, 1u, y, 1u);
    }
    return m;
}

// The island's problem (its n contacts in fmembers): rows, q, μ, W, η, and
// the start x (the warm start where one was kept, else 0),
// projected on the cones.
fn assemble_friction(base: u32, n: u32, first: u32, moving: u32) {
    for (var i = 0u; i < n; i++) {
        let slot = fmembers[i];
        let at = sp.contacts_at + slot * CP;
        let nrm = vec3_at_scratch(at + 3u);
        let t = tangent_basis(nrm);
        let gap = scratch[at + 6u];
        let key = sp.keys_at + 4u * slot;
        let s = contact_sides(slot, moving);
        sides[i] = s;
        let q = base + F_Q + 3u * i;
        scratch[q] = assemble_direction(base, 3u * i, slot, nrm, first, s) + gap / sp.dt;
        scratch[q + 1u] = assemble_direction(base, 3u * i + 1u, slot, t[0], first, s);
        scratch[q + 2u] = assemble_direction(base, 3u * i + 2u, slot, t[1], first, s);
        let m = pair_friction(first + words[key], first + words[key + 1u]);
        scratch[base + F_MU + i] = m;
        let r = warm_start(slot);
        put_scratch(base + F_X + 3u * i, project_on_cone(r, m));
    }
    let dim = 3u * n;
    // One entry per loop iteration: three (as contact_velocity takes them)
    // made llvmpipe's compilation of the kernel ten times as long.
    for (var x = 0u; x < dim; x++) {
        for (var y = 0u; y < dim; y++) {
            scratch[base + F_W + x * dim + y] = friction_entry(base, x, y);
        }
    }
    // projected.rs contact_steps.
    for (var i = 0u; i < n; i++) {
        var lo = 0u;
        var hi = dim;
        if sp.gauss_seidel != 0u {
            lo = 3u * i;
            hi = lo + 3u;
        }
        var big = Scalar(0.0);
        for (var x = 3u * i; x < 3u * i + 3u; x++) {
            var s = Scalar(0.0);
            for (var y = lo; y < hi; y += 3u) {
                let at = base + F_W + x * dim + y;
                s += abs(scratch[at]);
                s += abs(scratch[at + 1u]);
                s += abs(scratch[at + 2u]);
            }
            big = max(big, s);
        }
        scratch[base + F_ETA + i] = select(Scalar(1.0), Scalar(1.0) / big, big > Scalar(0.0));
    }
}

// The loops below take three entries (a contact's rows or columns) per
// iteration, summed in the CPU's order: llvmpipe counts loop iterations
// against its limit and pays each one's mask bookkeeping. `len` and `dim`
// are multiples of 3.

// u of contact i's rows 3i..3i+3: u_x = q_x + Σ_j W_xj x_j, each row's sum
// in the order of j (projected.rs velocity_into), x from `xs` into u at
// `us` (offsets in the world's region): n loop iterations.
fn contact_velocity(base: u32, dim: u32, i: u32, xs: u32, us: u32) {
    let r0 = base + F_W + 3u * i * dim;
    let r1 = r0 + dim;
    let r2 = r1 + dim;
    var s0 = Scalar(0.0);
    var s1 = Scalar(0.0);
    var s2 = Scalar(0.0);
    for (var j = 0u; j < dim; j += 3u) {
        let x0 = scratch[xs + j];
        let x1 = scratch[xs + j + 1u];
        let x2 = scratch[xs + j + 2u];
        s0 += scratch[r0 + j] * x0;
        s0 += scratch[r0 + j + 1u] * x1;
        s0 += scratch[r0 + j + 2u] * x2;
        s1 += scratch[r1 + j] * x0;
        s1 += scratch[r1 + j + 1u] * x1;
        s1 += scratch[r1 + j + 2u] * x2;
        s2 += scratch[r2 + j] * x0;
        s2 += scratch[r2 + j + 1u] * x1;
        s2 += scratch[r2 + j + 2u] * x2;
    }
    let u = us + 3u * i;
    let q = base + F_Q + 3u * i;
    scratch[u] = scratch[q] + s0;
    scratch[u + 1u] = scratch[q + 1u] + s1;
    scratch[u + 2u] = scratch[q + 2u] + s2;
}

// u = W x + q for the island's n contacts, x at base + `xs`, u at base + `us`.
fn friction_velocity(base: u32, n: u32, xs: u32, us: u32) {
    for (var i = 0u; i < n; i++) {
        contact_velocity(base, 3u * n, i, base + xs, base + us);
    }
}

// Σ v², from the start (projected.rs sum_squares) of `len` entries at `at`.
fn sum_squares_at(at: u32, len: u32) -> Scalar {
    var s = Scalar(0.0);
    for (var i = 0u; i < len; i += 3u) {
        s += scratch[at + i] * scratch[at + i];
        s += scratch[at + i + 1u] * scratch[at + i + 1u];
        s += scratch[at + i + 2u] * scratch[at + i + 2u];
    }
    return s;
}

// lcp.rs norm2 of `len` entries at `at` (scaled by the largest).
fn norm2_at(at: u32, len: u32) -> Scalar {
    var big = Scalar(0.0);
    for (var i = 0u; i < len; i += 3u) {
        big = max(big, abs(scratch[at + i]));
        big = max(big, abs(scratch[at + i + 1u]));
        big = max(big, abs(scratch[at + i + 2u]));
    }
    if big == Scalar(0.0) || !finite(big) {
        return big;
    }
    var s = Scalar(0.0);
    for (var i = 0u; i < len; i += 3u) {
        let v0 = scratch[at + i] / big;
        let v1 = scratch[at + i + 1u] / big;
        let v2 = scratch[at + i + 2u] / big;
        s += v0 * v0;
        s += v1 * v1;
        s += v2 * v2;
    }
    return big * sqrt(s);
}

// residual.rs norm: the plain sum of squares where it is finite and above
// 1e-280, else norm2.
fn norm_at(at: u32, len: u32) -> Scalar {
    let s = sum_squares_at(at, len);
    if finite(s) && s > Scalar(1e-280) {
        return sqrt(s);
    }
    return norm2_at(at, len);
}

fn vec3_x(base: u32, i: u32) -> vec3<Scalar> {
    return vec3_at_scratch(base + F_X + 3u * i);
}

fn vec3_u(base: u32, i: u32) -> vec3<Scalar> {
    return vec3_at_scratch(base + F_U + 3u * i);
}

// projected.rs stop_measure of x at base + `xs` with u at base + `us`;
// q2 = ‖q‖².
fn stop_measure(base: u32, n: u32, q2: Scalar, xs: u32, us: u32) -> Scalar {
    var e2 = Scalar(0.0);
    for (var i = 0u; i < n; i++) {
        let x = vec3_at_scratch(base + xs + 3u * i);
        let p = project_on_cone(x - vec3_at_scratch(base + us + 3u * i), scratch[base + F_MU + i]);
        let d = x - p;
        e2 += d.x * d.x;
        e2 += d.y * d.y;
        e2 += d.z * d.z;
    }
    let dim = 3u * n;
    let scale = sqrt(max(max(q2, sum_squares_at(base + xs, dim)), sum_squares_at(base + us, dim)));
    let e = sqrt(e2);
    if scale > SCALE_FLOOR {
        return e / scale;
    }
    return e;
}

// ProjectedSolution::judge of x with u = W x + q (the sweeps' last
// iteration computed it from this x, which it left as it was), the cone
// error (the status) and the Coulomb error
// (FrictionResiduals::of_velocity). The Coulomb error, or -1 where x is
// not solved (not finite, or the cone error above the tolerance, or
// `failed`).
fn judge(base: u32, n: u32, failed: bool) -> Scalar {
    let dim = 3u * n;
    var ok = !failed;
    for (var i = 0u; i < n; i++) {
        let x = vec3_x(base, i);
        let u = vec3_u(base, i);
        let m = scratch[base + F_MU + i];
        let ok3 = finite(x.x) && finite(x.y) && finite(x.z) && finite(u.x) && finite(u.y) && finite(u.z);
        ok = ok && ok3;
        put_scratch(base + F_T1 + 3u * i, x - project_on_cone(x - u, m));
        let un = u.x + m * sqrt(u.y * u.y + u.z * u.z);
        let pc = project_on_cone(vec3<Scalar>(x.x - un, x.y - u.y, x.z - u.z), m);
        put_scratch(base + F_T2 + 3u * i, x - pc);
    }
    let scale = max(max(norm_at(base + F_Q, dim), norm_at(base + F_X, dim)), norm_at(base + F_U, dim));
    var cone = norm2_at(base + F_T1, dim);
    var coulomb = norm_at(base + F_T2, dim);
    if scale > SCALAR_EPSILON {
        cone = cone / scale;
        coulomb = coulomb / scale;
    }
    if !ok || !finite(cone) || !(cone <= sp.friction_tolerance) {
        return Scalar(-1.0);
    }
    return coulomb;
}

// apply_friction_impulses for the island: v += Σ_α r_α M⁻¹J_αᵀ per side,
// contact after contact, n, t₁, t₂ (zero reactions skipped); each
// contact's reaction kept for the next step's warm start.
fn apply_friction(base: u32, n: u32, moving: u32) {
    for (var i = 0u; i < n; i++) {
        let s = contact_sides(fmembers[i], moving);
        for (var d = 0u; d < 3u; d++) {
            let z = scratch[base + F_X + 3u * i + d];
            if z == Scalar(0.0) {
                continue;
            }
            let o = base + F_ROWS + 24u * (3u * i + d);
            if s.x != NONE {
                lin[s.x] += vec3_at_scratch(o + 12u) * z;
                ang[s.x] += vec3_at_scratch(o + 15u) * z;
            }
            if s.y != NONE {
                lin[s.y] += vec3_at_scratch(o + 18u) * z;
                ang[s.y] += vec3_at_scratch(o + 21u) * z;
            }
        }
        keep_reaction(fmembers[i], vec3_x(base, i));
    }
}

// Step part 2 for the worlds with friction, in rounds (see the header).
@compute @workgroup_size(64)
fn world_friction(@builtin(global_invocation_id) gid: vec3<u32>) {
    let w = gid.x;
    if w >= sp.count {
        return;
    }
    let fs = sp.fstate_at + 4u * w;
    var phase = words[fs];
    if phase == F_IDLE || phase == F_DONE {
        return;
    }
    records[w * REC + 5u] += Scalar(1.0);
    let first = worlds[w].x;
    let nb = min(worlds[w].y, MAX_BODIES);
    let out = sp.out_at + 4u * w;
    let count = words[out];
    let moving = words[out + 1u];
    let islands = words[out + 3u];
    let slot0 = w * sp.slots;
    let base = sp.friction_at + w * FR;
    load_velocities(w);
    var flags = 0u;
    var spent = 0u;
    var finished = false;
    loop {
        let isl = words[fs + 1u];
        if isl >= islands {
            finished = true;
            break;
        }
        var n = 0u;
        for (var c = 0u; c < count; c++) {
            if words[sp.keys_at + 4u * (slot0 + c) + 3u] == isl {
                if n < ISLAND_MAX {
                    fmembers[n] = slot0 + c;
                }
                n++;
            }
        }
        spent += count;
        if n > ISLAND_MAX {
            flags |= ISLAND_TOO_LARGE;
            break;
        }
        let dim = 3u * n;
        // Costs: the loop iterations of each part (see contact_velocity).
        if phase == F_ASSEMBLE {
            let cost = 12u * n * n + n * (sp.slots + 1u) + 64u + method_start_cost(n);
            if spent > count && spent + cost > sp.friction_budget {
                break;
            }
            spent += cost;
            assemble_friction(base, n, first, moving);
            words[fs + 2u] = 0u;
            words[fs + 3u] = 0u;
            phase = F_SWEEP;
            words[fs] = phase;
            if !method_start(base, n) {
                flags |= NOT_SOLVED;
                break;
            }
        }
        let q2 = sum_squares_at(base + F_Q, dim);
        let r = method_round(base, n, q2, fs, spent);
        spent = r.x;
        if r.y == ROUND_FAILED {
            flags |= NOT_SOLVED;
            break;
        }
        let done = r.y == ROUND_DONE || r.y == ROUND_NOT_FINITE;
        let failed = r.y == ROUND_NOT_FINITE;
        // The judgement's loops (no product: u is the last iteration's).
        let judged = 16u * n + 64u;
        if !done || spent + judged > sp.friction_budget {
            // The next round goes on from x (and judges it there).
            break;
        }
        spent += judged;
        let error = judge(base, n, failed);
        if error < Scalar(0.0) {
            flags |= NOT_SOLVED;
            break;
        }
        records[w * REC + 3u] = max(records[w * REC + 3u], error);
        apply_friction(base, n, moving);
        words[fs + 1u] = isl + 1u;
        phase = F_ASSEMBLE;
        words[fs] = phase;
    }
    if flags != 0u {
        words[fs] = F_IDLE;
        words[out + 2u] = flags;
        return;
    }
    for (var k = 0u; k < nb; k++) {
        put_scratch(6u * (first + k), lin[k]);
        put_scratch(6u * (first + k) + 3u, ang[k]);
    }
    if !loops_left() {
        // The loop limit reached (world_step.wgsl loops_left): this
        // round's work may be cut short; flagged, the CPU steps the world.
        words[fs] = F_IDLE;
        words[out + 2u] = BUDGET;
        return;
    }
    if finished {
        // world_finish remembers its reactions and finishes it after the
        // step's last round.
        words[fs] = F_DONE;
    }
}

// The warm-start memory of world w (kept while its steps have friction):
// in `words` from sp.memory_at, slots + 1 words per world (entries, then
// each entry's id (a << 16) | (b << 12) | (feature & 0xfff), as
// step.rs contact_id without the world); in `scratch` from
// sp.memory_r_at, 3 scalars per entry (r_n, r_t₁, r_t₂). This step's
// reactions wait in `scratch` from sp.reactions_at (3 per contact slot)
// until the world is finished (world_finish.wgsl remember_reactions).

// The warm start of contact `slot` (world_friction.rs: the remembered
// reaction of its id, the last entry of that id; 0 where none or warm
// starts are off).
fn warm_start(slot: u32) -> vec3<Scalar> {
    var r = vec3<Scalar>(0.0, 0.0, 0.0);
    if sp.warm_start == 0u {
        return r;
    }
    let w = slot / sp.slots;
    let m = sp.memory_at + w * (sp.slots + 1u);
    let id = contact_key(slot);
    for (var e = 0u; e < words[m]; e++) {
        if words[m + 1u + e] == id {
            r = vec3_at_scratch(sp.memory_r_at + 3u * (w * sp.slots + e));
        }
    }
    return r;
}

fn keep_reaction(slot: u32, r: vec3<Scalar>) {
    scratch[sp.contacts_at + slot * CP + 7u] = r.x;
    put_scratch(sp.reactions_at + 3u * slot, r);
}

// APGD in the frictional phase of shaders/world_step.wgsl (module
// world_friction_apgd, composed after world_friction.wgsl, whose header
// gives the method, the layout of a world's region and the rounds;
// `world_friction` calls method_start (apgd_start) after an island's
// assembly and method_round (apgd_round) in each round): the twin of
// friction/apgd.rs, its arithmetic in its order, on the island's W, q and
// μ in `scratch`. accept_step and apgd_momentum are friction_common.wgsl's
// (the batch APGD kernels' own).

// Copies contact after contact 3n entries from base + `src` to base + `dst`.
fn copy_entries(base: u32, n: u32, src: u32, dst: u32) {
    for (var i = 0u; i < n; i++) {
        put_scratch(base + dst + 3u * i, vec3_at_scratch(base + src + 3u * i));
    }
}

// apgd.rs first_lipschitz: ‖W e‖ / ‖e‖ for e = (1, …, 1), else the largest
// |W_rr|, else 1.
fn first_lipschitz(base: u32, n: u32) -> Scalar {
    let dim = 3u * n;
    var s2 = Scalar(0.0);
    for (var r = 0u; r < dim; r++) {
        let row = base + F_W + r * dim;
        var s = Scalar(0.0);
        for (var j = 0u; j < dim; j += 3u) {
            s += scratch[row + j];
            s += scratch[row + j + 1u];
            s += scratch[row + j + 2u];
        }
        s2 += s * s;
    }
    let l = sqrt(s2 / Scalar(dim));
    if l > Scalar(0.0) && finite(l) {
        return l;
    }
    var d = Scalar(0.0);
    for (var r = 0u; r < dim; r++) {
        d = max(d, abs(scratch[base + F_W + r * dim + r]));
    }
    return select(Scalar(1.0), d, d > Scalar(0.0) && finite(d));
}

// APGD's start (apgd.rs apgd) from x (projected by assemble_friction):
// u(x), its error, y = x, u(y) = u(x), best = x, θ = 1, L; false where
// the error is not finite (the twin fails).
fn apgd_start(base: u32, n: u32, q2: Scalar) -> bool {
    friction_velocity(base, n, F_X, F_U);
    let err = stop_measure(base, n, q2, F_X, F_U);
    copy_entries(base, n, F_X, F_Y);
    copy_entries(base, n, F_U, F_UY);
    copy_entries(base, n, F_X, F_BEST);
    copy_entries(base, n, F_U, F_UBEST);
    let a = base + F_APGD;
    scratch[a] = Scalar(1.0);
    scratch[a + 1u] = first_lipschitz(base, n);
    scratch[a + 2u] = err;
    return finite(err);
}

// One backtracking try from y with step 1/L (apgd_iteration): the trial
// xn = P_K(y − u(y) / L) into T1, u(xn) into T2; whether accept_step takes
// it (d = xn − y, W d = u(xn) − u(y)).
fn apgd_try(base: u32, n: u32, lipschitz: Scalar) -> bool {
    let t = Scalar(1.0) / lipschitz;
    for (var i = 0u; i < n; i++) {
        let y = vec3_at_scratch(base + F_Y + 3u * i);
        let uy = vec3_at_scratch(base + F_UY + 3u * i);
        put_scratch(base + F_T1 + 3u * i, project_on_cone(y - t * uy, scratch[base + F_MU + i]));
    }
    friction_velocity(base, n, F_T1, F_T2);
    var curvature = Scalar(0.0);
    var d2 = Scalar(0.0);
    var g2 = Scalar(0.0);
    for (var i = 0u; i < n; i++) {
        let d = vec3_at_scratch(base + F_T1 + 3u * i) - vec3_at_scratch(base + F_Y + 3u * i);
        let uy = vec3_at_scratch(base + F_UY + 3u * i);
        let wd = vec3_at_scratch(base + F_T2 + 3u * i) - uy;
        curvature += d.x * wd.x;
        curvature += d.y * wd.y;
        curvature += d.z * wd.z;
        d2 += d.x * d.x;
        d2 += d.y * d.y;
        d2 += d.z * d.z;
        g2 += uy.x * uy.x;
        g2 += uy.y * uy.y;
        g2 += uy.z * uy.z;
    }
    return accept_step(curvature, d2, g2, lipschitz);
}

// After an accepted try (apgd_iteration): the best iterate (with its u),
// the momentum, the gradient restart, x = xn, L × 0.9, the iteration
// counted in words[fs + 2]; false where the trial's error is not finite.
fn apgd_accept(base: u32, n: u32, q2: Scalar, fs: u32) -> bool {
    let err = stop_measure(base, n, q2, F_T1, F_T2);
    if !finite(err) {
        return false;
    }
    let a = base + F_APGD;
    if err < scratch[a + 2u] {
        scratch[a + 2u] = err;
        copy_entries(base, n, F_T1, F_BEST);
        copy_entries(base, n, F_T2, F_UBEST);
    }
    let m = apgd_momentum(scratch[a]);
    var g_dot = Scalar(0.0);
    for (var i = 0u; i < n; i++) {
        let d = vec3_at_scratch(base + F_T1 + 3u * i) - vec3_x(base, i);
        let uy = vec3_at_scratch(base + F_UY + 3u * i);
        g_dot += uy.x * d.x;
        g_dot += uy.y * d.y;
        g_dot += uy.z * d.z;
    }
    let restart = g_dot > Scalar(0.0);
    for (var i = 0u; i < n; i++) {
        let xn = vec3_at_scratch(base + F_T1 + 3u * i);
        let un = vec3_at_scratch(base + F_T2 + 3u * i);
        var y = xn;
        var uy = un;
        if !restart {
            y = xn + m.y * (xn - vec3_x(base, i));
            uy = un + m.y * (un - vec3_u(base, i));
        }
        put_scratch(base + F_Y + 3u * i, y);
        put_scratch(base + F_UY + 3u * i, uy);
        put_scratch(base + F_X + 3u * i, xn);
        put_scratch(base + F_U + 3u * i, un);
    }
    scratch[a] = select(m.x, Scalar(1.0), restart);
    scratch[a + 1u] = scratch[a + 1u] * Scalar(0.9);
    words[fs + 2u] += 1u;
    words[fs + 3u] = 0u;
    return true;
}

// The APGD iterations of a round within `budget` from `spent` (the twin's
// loop: stop at the tolerance or the cap, else a try, doubling L where it
// fails): (loop work spent, ROUND_DONE or ROUND_FAILED; ROUND_SPENT where
// the budget ends it first), the best iterate and its u
// in x and u where done.
fn apgd_round(base: u32, n: u32, q2: Scalar, fs: u32, spent0: u32) -> vec2<u32> {
    let cost = n * n + 10u * n + 16u;
    let a = base + F_APGD;
    var spent = spent0;
    var end = ROUND_SPENT;
    loop {
        if scratch[a + 2u] <= sp.friction_tolerance || words[fs + 2u] >= sp.max_iterations {
            copy_entries(base, n, F_BEST, F_X);
            copy_entries(base, n, F_UBEST, F_U);
            spent += 2u * n;
            end = ROUND_DONE;
            break;
        }
        if spent + cost > sp.friction_budget {
            break;
        }
        spent += cost;
        let l = scratch[a + 1u];
        if apgd_try(base, n, l) {
            if !apgd_accept(base, n, q2, fs) {
                end = ROUND_FAILED;
                break;
            }
        } else {
            scratch[a + 1u] = Scalar(2.0) * l;
            words[fs + 3u] += 1u;
            if words[fs + 3u] >= MAX_BACKTRACKS || !finite(scratch[a + 1u]) {
                end = ROUND_FAILED;
                break;
            }
        }
    }
    return vec2<u32>(spent, end);
}

// Loop work of APGD's start after an island's assembly.
fn method_start_cost(n: u32) -> u32 {
    return 4u * n * n + 16u * n + 16u;
}

// APGD's start after an island's assembly (apgd_start).
fn method_start(base: u32, n: u32) -> bool {
    return apgd_start(base, n, sum_squares_at(base + F_Q, 3u * n));
}

// APGD's iterations of a round (apgd_round).
fn method_round(base: u32, n: u32, q2: Scalar, fs: u32, spent0: u32) -> vec2<u32> {
    return apgd_round(base, n, q2, fs, spent0);
}

// Siconos' fc3d projection on {|x_t| <= mu x_n} (cone.rs project_on_cone).
fn project_on_cone(v: vec3<Scalar>, m: Scalar) -> vec3<Scalar> {
    let t = sqrt(v.y * v.y + v.z * v.z);
    if m * t <= -v.x {
        return vec3<Scalar>(Scalar(0.0));
    }
    if t <= m * v.x {
        return v;
    }
    let pn = (m * t + v.x) / (m * m + Scalar(1.0));
    let scale = m * pn / t;
    return vec3<Scalar>(pn, v.y * scale, v.z * scale);
}

// Consecutive doublings of L in one APGD iteration before a numerical failure.
const MAX_BACKTRACKS: u32 = 64u;

// APGD's backtracking test (apgd.rs accept_step): dᵀW d ≤ L‖d‖²
// (`curvature`, `d2`), or a step that rounding decides: L‖d‖ ≤ 16 ε
// ‖∇f(y)‖ (`g2` = ‖∇f(y)‖²).
fn accept_step(curvature: Scalar, d2: Scalar, g2: Scalar, lipschitz: Scalar) -> bool {
    let noise = Scalar(16.0) * SCALAR_EPSILON;
    return curvature <= lipschitz * d2 || lipschitz * lipschitz * d2 <= noise * noise * g2;
}

// APGD's momentum after an accepted step from θ (apgd.rs apgd_iteration):
// (θ_new, β).
fn apgd_momentum(th: Scalar) -> vec2<Scalar> {
    let th_new = Scalar(0.5) * (th * sqrt(th * th + Scalar(4.0)) - th * th);
    let beta = th * (Scalar(1.0) - th) / (th * th + th_new);
    return vec2<Scalar>(th_new, beta);
}
