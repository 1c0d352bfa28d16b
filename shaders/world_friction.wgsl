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
