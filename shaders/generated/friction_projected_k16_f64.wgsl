// GENERATED from shaders/friction_common.wgsl + shaders/friction_projected_global.wgsl by src/gpu/shaders/compose.rs: do not edit.
// Regenerate: LCPBATCH_BLESS_SHADERS=1 cargo test --release generated_shaders_are_committed

// The part of the friction kernels common to both sources (prepended to
// shaders/friction_projected.wgsl for k <= 4 and to
// shaders/friction_projected_global.wgsl for k > 4 by
// src/gpu/shaders/compose.rs): the HOST lines, the constants, the records,
// the bindings, the finiteness test, the cone projection and APGD's
// scalar steps. Read the two sources' headers for the layout and the
// rounds. The world step kernel (shaders/world_friction.wgsl) takes this
// file from the cone projection on.

alias Scalar = f64; // HOST scalar
const SCALAR_MAX: Scalar = 1.7976931348623157e308; // HOST scalar_max
const SCALAR_EPSILON: Scalar = 2.220446049250313e-16; // HOST scalar_epsilon
// Islands of exactly FIXED_K contacts (the generator writes one kernel per
// k = 1...16): every loop bound is a constant, which llvmpipe unrolls.
const FIXED_K: u32 = 16u; // HOST fixed_k

// Largest island: 16 contacts, 48 entries.
const MAX_DIM: u32 = 48u;
// Below this scale the stop measure is not divided (projected.rs SCALE_FLOOR).
const SCALE_FLOOR: Scalar = Scalar(2.220446049250313e-16);

// FrictionState.status
const NOT_STARTED: u32 = 0u;
const RUNNING: u32 = 1u;
const CONVERGED: u32 = 2u;
const AT_CAP: u32 = 3u;
const FAILED: u32 = 4u;

struct Params {
    first: u32,
    count: u32,
    budget: u32,
    // bit 0: Gauss-Seidel (sweeps)
    flags: u32,
}

// slot: the island's entry in `states` and `scalars`; the table holds
// only the islands still running (the host compacts it between
// submissions), so entry and slot differ.
struct FrictionIsland {
    k: u32,
    data: u32,
    vectors: u32,
    slot: u32,
}

struct FrictionState {
    status: u32,
    iterations: u32,
    restarts: u32,
    // APGD: doublings of L so far in the current iteration.
    doublings: u32,
}

struct Controls {
    max_iterations: u32,
    _p0: u32,
    _p1: u32,
    _p2: u32,
    tolerance: Scalar,
    relaxation: Scalar,
    _s0: Scalar,
    _s1: Scalar,
}

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> islands: array<FrictionIsland>;
// Bindings 2 (values) and 3 (vectors): declared by each kernel (scalars
// in friction_projected_global.wgsl, vec4 in friction_projected.wgsl).
@group(0) @binding(4) var<storage, read_write> scalars: array<Scalar>;
@group(0) @binding(5) var<storage, read_write> states: array<FrictionState>;
@group(0) @binding(6) var<storage, read_write> unfinished: array<atomic<u32>, 17>;
@group(0) @binding(7) var<uniform> controls: Controls;

fn finite(v: Scalar) -> bool {
    return v == v && abs(v) <= SCALAR_MAX;
}

// A sweep's status after measuring `err` at `iterations`, in the CPU twin's
// order (not finite, within tolerance, at the cap); RUNNING: sweep again.
fn sweep_status(err: Scalar, iterations: u32) -> u32 {
    if !finite(err) {
        return FAILED;
    }
    if err <= controls.tolerance {
        return CONVERGED;
    }
    if iterations >= controls.max_iterations {
        return AT_CAP;
    }
    return RUNNING;
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

// Cone projection iterations for the cone complementarity problem of
// Anitescu-Tasora, one invocation per island of exactly FIXED_K <= 16
// contacts (one dispatch per k): the kernels for k > 4, which read W and
// the vectors in the storage buffers at every use. The kernels for k <= 4
// come from friction_projected.wgsl (private copies, unrolled loops); a
// private W of 9k^2 entries at run-time indices made lavapipe's k = 16
// kernel run for minutes on 50 islands, measured. Same bindings, same
// arithmetic in the same order.
// CPU twin: src/friction/projected.rs (sweeps, the stop measure, the steps)
// and src/friction/apgd.rs (APGD), the same arithmetic in the same order;
// read their docs for the methods. Entry points:
//   sweeps: projected Jacobi (params.flags bit 0 clear) or Gauss-Seidel
//           (bit 0 set) sweeps over contacts;
//   apgd:   accelerated projected gradient descent with backtracking on the
//           Lipschitz estimate, gradient restarts and the best iterate.
//
// Interleaved per contact: entries 3i (normal), 3i + 1, 3i + 2 (tangents).
// An island's W (3k x 3k, row-major), q (3k) and mu (k) lie in `values`
// from island.data; its vectors in `vectors` from island.vectors:
//   sweeps: x (3k), then the contacts' steps eta (k);
//   apgd:   x, u(x), y, u(y), best (3k each).
// `scalars` holds 4 per island: theta, L, best error, last error.
//
// Rounds: llvmpipe (lavapipe) ends every loop of an invocation after about
// 65,535 iterations in all, silently. An invocation therefore spends at most
// params.budget units of loop work per dispatch (one unit per inner loop
// iteration: a product W x costs 9k^2 + 3k), keeps its state in the buffers
// and counts itself in `unfinished[k]` while it runs; the host reads the
// states back after each submission and dispatches only the islands still
// running (a compacted `islands` table) until none is. A round may end between two
// backtracking tries of APGD: the next one retries with the L it saved,
// which is what the CPU twin's loop does next.
//
// The generator (src/gpu/shaders/compose.rs) replaces the lines marked HOST
// (scalar type, its largest finite value, its machine epsilon, the
// island size k).

// Prepended by the generator: shaders/friction_common.wgsl (HOST lines,
// constants, records, bindings, finite, project_on_cone).

// An island's W, q, mu from island.data and its vectors from
// island.vectors, scalar by scalar (both multiples of 4: the host pads
// every island's blocks for the vec4 reads of friction_projected.wgsl).
@group(0) @binding(2) var<storage, read> values: array<Scalar>;
@group(0) @binding(3) var<storage, read_write> vectors: array<Scalar>;

// APGD's trial iterate and its velocity; the sweeps' velocity u in `un`.
var<private> xn: array<Scalar, MAX_DIM>;
var<private> un: array<Scalar, MAX_DIM>;

// Where one island's data lie.
struct Island {
    n: u32,
    k: u32,
    w: u32,
    q: u32,
    mu: u32,
    v: u32,
}

fn island_at(rec: FrictionIsland) -> Island {
    let k = FIXED_K;
    let n = 3u * k;
    return Island(n, k, rec.data, rec.data + n * n, rec.data + n * n + n, rec.vectors);
}

// Row r of W x + q with x = vectors[x0..x0 + n]: s = sum_j W_rj x_j, then q_r + s.
fn velocity_row(is: Island, x0: u32, r: u32) -> Scalar {
    var s = Scalar(0.0);
    let row = is.w + r * is.n;
    for (var j = 0u; j < is.n; j++) {
        s += values[row + j] * vectors[x0 + j];
    }
    return values[is.q + r] + s;
}

// un = W x + q for x = vectors[x0..x0 + n].
fn velocity_of_stored(is: Island, x0: u32) {
    for (var r = 0u; r < is.n; r++) {
        un[r] = velocity_row(is, x0, r);
    }
}

// un = W xn + q.
fn velocity_of_trial(is: Island) {
    for (var r = 0u; r < is.n; r++) {
        var s = Scalar(0.0);
        let row = is.w + r * is.n;
        for (var j = 0u; j < is.n; j++) {
            s += values[row + j] * xn[j];
        }
        un[r] = values[is.q + r] + s;
    }
}

fn q_squared(is: Island) -> Scalar {
    var s = Scalar(0.0);
    for (var r = 0u; r < is.n; r++) {
        s += values[is.q + r] * values[is.q + r];
    }
    return s;
}

// The stop measure (projected.rs stop_measure) of x with velocity u = un:
// x = xn (trial) or vectors[x0..x0 + n].
fn stop_measure(is: Island, x0: u32, trial: bool) -> Scalar {
    var e2 = Scalar(0.0);
    var x2 = Scalar(0.0);
    var u2 = Scalar(0.0);
    for (var i = 0u; i < is.k; i++) {
        let c = 3u * i;
        var x: vec3<Scalar>;
        if trial {
            x = vec3<Scalar>(xn[c], xn[c + 1u], xn[c + 2u]);
        } else {
            x = vec3<Scalar>(vectors[x0 + c], vectors[x0 + c + 1u], vectors[x0 + c + 2u]);
        }
        let u = vec3<Scalar>(un[c], un[c + 1u], un[c + 2u]);
        let p = project_on_cone(x - u, values[is.mu + i]);
        let d = x - p;
        e2 += d.x * d.x;
        e2 += d.y * d.y;
        e2 += d.z * d.z;
        x2 += x.x * x.x;
        x2 += x.y * x.y;
        x2 += x.z * x.z;
        u2 += u.x * u.x;
        u2 += u.y * u.y;
        u2 += u.z * u.z;
    }
    let scale = sqrt(max(max(q_squared(is), x2), u2));
    let e = sqrt(e2);
    if scale > SCALE_FLOOR {
        return e / scale;
    }
    return e;
}

// Every contact's reaction in vectors[x0..] projected on its cone.
fn project_stored(is: Island, x0: u32) {
    for (var i = 0u; i < is.k; i++) {
        let c = x0 + 3u * i;
        let p = project_on_cone(vec3<Scalar>(vectors[c], vectors[c + 1u], vectors[c + 2u]), values[is.mu + i]);
        vectors[c] = p.x;
        vectors[c + 1u] = p.y;
        vectors[c + 2u] = p.z;
    }
}

// One unit of loop work per inner iteration of W x.
fn product_cost(is: Island) -> u32 {
    return is.n * is.n + is.n;
}

// Saves the state; a running island counts itself in unfinished[k]. (k is
// passed in: indexing with min(islands[index].k, 16u) here counted every
// island in unfinished[0] on lavapipe, measured.)
fn finish_round(index: u32, k: u32, st: FrictionState) {
    states[index] = st;
    if st.status == RUNNING {
        atomicAdd(&unfinished[k], 1u);
    }
}

// The sweeps' steps (projected.rs contact_steps) into vectors[v + n..v + n + k].
fn contact_steps(is: Island, gauss_seidel: bool) {
    for (var i = 0u; i < is.k; i++) {
        var lo = 0u;
        var hi = is.n;
        if gauss_seidel {
            lo = 3u * i;
            hi = 3u * i + 3u;
        }
        var big = Scalar(0.0);
        for (var r = 3u * i; r < 3u * i + 3u; r++) {
            var s = Scalar(0.0);
            for (var j = lo; j < hi; j++) {
                s += abs(values[is.w + r * is.n + j]);
            }
            big = max(big, s);
        }
        var eta = Scalar(1.0);
        if big > Scalar(0.0) {
            eta = Scalar(1.0) / big;
        }
        vectors[is.v + is.n + i] = eta;
    }
}

// One sweep over the contacts from u = un (Gauss-Seidel: each contact's
// velocity recomputed from the reactions updated so far).
fn sweep(is: Island, gauss_seidel: bool) {
    for (var i = 0u; i < is.k; i++) {
        let c = 3u * i;
        if gauss_seidel {
            for (var r = c; r < c + 3u; r++) {
                un[r] = velocity_row(is, is.v, r);
            }
        }
        let h = controls.relaxation * vectors[is.v + is.n + i];
        let x = vec3<Scalar>(vectors[is.v + c], vectors[is.v + c + 1u], vectors[is.v + c + 2u]);
        let p = project_on_cone(
            vec3<Scalar>(x.x - h * un[c], x.y - h * un[c + 1u], x.z - h * un[c + 2u]),
            values[is.mu + i]
        );
        vectors[is.v + c] = p.x;
        vectors[is.v + c + 1u] = p.y;
        vectors[is.v + c + 2u] = p.z;
    }
}

@compute @workgroup_size(64)
fn sweeps(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= params.count {
        return;
    }
    let rec = islands[params.first + gid.x];
    let index = rec.slot;
    var st = states[index];
    if st.status > RUNNING {
        return;
    }
    let is = island_at(rec);
    let gauss_seidel = (params.flags & 1u) == 1u;
    var spent = 0u;
    if st.status == NOT_STARTED {
        project_stored(is, is.v);
        contact_steps(is, gauss_seidel);
        st.status = RUNNING;
        spent += product_cost(is);
    }
    var cost = product_cost(is) + 6u * is.n;
    if gauss_seidel {
        cost += product_cost(is);
    }
    loop {
        if spent > 0u && spent + cost > params.budget {
            break;
        }
        spent += cost;
        velocity_of_stored(is, is.v);
        let err = stop_measure(is, is.v, false);
        scalars[4u * index + 3u] = err;
        st.status = sweep_status(err, st.iterations);
        if st.status != RUNNING {
            break;
        }
        sweep(is, gauss_seidel);
        st.iterations++;
    }
    finish_round(index, is.k, st);
}

// APGD's start (apgd.rs apgd): x projected, u(x), its error, y = x,
// u(y) = u(x), best = x, theta = 1, L from first_lipschitz.
fn apgd_start(is: Island, index: u32) -> bool {
    project_stored(is, is.v);
    velocity_of_stored(is, is.v);
    let err = stop_measure(is, is.v, false);
    for (var r = 0u; r < is.n; r++) {
        let x = vectors[is.v + r];
        vectors[is.v + is.n + r] = un[r];
        vectors[is.v + 2u * is.n + r] = x;
        vectors[is.v + 3u * is.n + r] = un[r];
        vectors[is.v + 4u * is.n + r] = x;
    }
    let s = 4u * index;
    scalars[s] = Scalar(1.0);
    scalars[s + 1u] = first_lipschitz(is);
    scalars[s + 2u] = err;
    scalars[s + 3u] = err;
    return finite(err);
}

// ||W e|| / ||e|| for e = (1, ..., 1), else the largest |W_rr|, else 1.
fn first_lipschitz(is: Island) -> Scalar {
    var s2 = Scalar(0.0);
    for (var r = 0u; r < is.n; r++) {
        var s = Scalar(0.0);
        for (var j = 0u; j < is.n; j++) {
            s += values[is.w + r * is.n + j];
        }
        s2 += s * s;
    }
    let l = sqrt(s2 / Scalar(is.n));
    if l > Scalar(0.0) && finite(l) {
        return l;
    }
    var d = Scalar(0.0);
    for (var r = 0u; r < is.n; r++) {
        d = max(d, abs(values[is.w + r * is.n + r]));
    }
    if d > Scalar(0.0) && finite(d) {
        return d;
    }
    return Scalar(1.0);
}

// One backtracking try from y with step 1/L: xn = P_K(y - u(y) / L),
// un = u(xn); true when d^T W d <= L |d|^2, d = xn - y.
fn apgd_try(is: Island, lipschitz: Scalar) -> bool {
    let y0 = is.v + 2u * is.n;
    let uy0 = is.v + 3u * is.n;
    let t = Scalar(1.0) / lipschitz;
    for (var i = 0u; i < is.k; i++) {
        let c = 3u * i;
        let p = project_on_cone(
            vec3<Scalar>(
                vectors[y0 + c] - t * vectors[uy0 + c],
                vectors[y0 + c + 1u] - t * vectors[uy0 + c + 1u],
                vectors[y0 + c + 2u] - t * vectors[uy0 + c + 2u]
            ),
            values[is.mu + i]
        );
        xn[c] = p.x;
        xn[c + 1u] = p.y;
        xn[c + 2u] = p.z;
    }
    velocity_of_trial(is);
    var curvature = Scalar(0.0);
    var d2 = Scalar(0.0);
    var g2 = Scalar(0.0);
    for (var r = 0u; r < is.n; r++) {
        let d = xn[r] - vectors[y0 + r];
        curvature += d * (un[r] - vectors[uy0 + r]);
        d2 += d * d;
        g2 += vectors[uy0 + r] * vectors[uy0 + r];
    }
    return accept_step(curvature, d2, g2, lipschitz);
}

// After an accepted try: the best iterate, the momentum, the gradient
// restart, x = xn (apgd.rs apgd_iteration); counts the iteration and a
// restart in st, or writes FAILED into it.
fn apgd_accept(is: Island, index: u32, st: ptr<function, FrictionState>) {
    let s = 4u * index;
    let err = stop_measure(is, 0u, true);
    scalars[s + 3u] = err;
    if !finite(err) {
        (*st).status = FAILED;
        return;
    }
    if err < scalars[s + 2u] {
        scalars[s + 2u] = err;
        for (var r = 0u; r < is.n; r++) {
            vectors[is.v + 4u * is.n + r] = xn[r];
        }
    }
    let th = scalars[s];
    let m = apgd_momentum(th);
    let th_new = m.x;
    let beta = m.y;
    let x0 = is.v;
    let ux0 = is.v + is.n;
    let y0 = is.v + 2u * is.n;
    let uy0 = is.v + 3u * is.n;
    var g_dot = Scalar(0.0);
    for (var r = 0u; r < is.n; r++) {
        g_dot += vectors[uy0 + r] * (xn[r] - vectors[x0 + r]);
    }
    let restart = g_dot > Scalar(0.0);
    for (var r = 0u; r < is.n; r++) {
        if restart {
            vectors[y0 + r] = xn[r];
            vectors[uy0 + r] = un[r];
        } else {
            vectors[y0 + r] = xn[r] + beta * (xn[r] - vectors[x0 + r]);
            vectors[uy0 + r] = un[r] + beta * (un[r] - vectors[ux0 + r]);
        }
        vectors[x0 + r] = xn[r];
        vectors[ux0 + r] = un[r];
    }
    if restart {
        scalars[s] = Scalar(1.0);
        (*st).restarts++;
    } else {
        scalars[s] = th_new;
    }
    scalars[s + 1u] = scalars[s + 1u] * Scalar(0.9);
    (*st).iterations++;
    (*st).doublings = 0u;
}

@compute @workgroup_size(64)
fn apgd(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= params.count {
        return;
    }
    let rec = islands[params.first + gid.x];
    let index = rec.slot;
    var st = states[index];
    if st.status > RUNNING {
        return;
    }
    let is = island_at(rec);
    let s = 4u * index;
    var spent = 0u;
    if st.status == NOT_STARTED {
        st.status = RUNNING;
        if !apgd_start(is, index) {
            st.status = FAILED;
        }
        spent += 2u * product_cost(is) + 8u * is.n;
    }
    let cost = product_cost(is) + 10u * is.n;
    loop {
        if st.status != RUNNING {
            break;
        }
        if scalars[s + 2u] <= controls.tolerance {
            st.status = CONVERGED;
            break;
        }
        if st.iterations >= controls.max_iterations {
            st.status = AT_CAP;
            break;
        }
        if spent > 0u && spent + cost > params.budget {
            break;
        }
        spent += cost;
        let lipschitz = scalars[s + 1u];
        if apgd_try(is, lipschitz) {
            apgd_accept(is, index, &st);
        } else {
            let doubled = Scalar(2.0) * lipschitz;
            scalars[s + 1u] = doubled;
            st.doublings++;
            if st.doublings >= MAX_BACKTRACKS || !finite(doubled) {
                st.status = FAILED;
            }
        }
    }
    finish_round(index, is.k, st);
}
