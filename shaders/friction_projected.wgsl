// Cone projection iterations for the cone complementarity problem of
// Anitescu-Tasora, one invocation per island of exactly FIXED_K <= 16
// contacts (one dispatch per k).
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
//   apgd:   x, u(x), y, u(y), best (3k each), padded to a multiple of 4.
// Both blocks start at multiples of 4 scalars (read as vec4 here).
// `scalars` holds 4 per island: theta, L, best error, last error.
//
// Loops marked UNROLL are unrolled by the generator for k <= 4 (every
// index into a private array a constant: see src/gpu/shaders/unroll_loops.rs).
//
// Private state: a dispatch copies its island's W, q, mu and vectors from
// the buffers into private arrays once, iterates on those, and writes the
// vectors back at the end of its round. llvmpipe turns every storage-buffer
// access at a per-island address into a loop over the SIMD lanes; private
// arrays indexed by the (constant-bound) loop counters are plain vector
// registers or stack slots. Measured 2026-11-25 (BENCHMARKS.md).
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

// Entries of an island: N = 3k; W has N * N.
const N: u32 = 3u * FIXED_K;
const NN: u32 = N * N;
// vec4s of an island's block in `values` (W, q, mu, padded by the host to
// a multiple of 4), of APGD's vectors (x, u(x), y, u(y), best, padded), of
// x alone (rounded up), and of the sweeps' vectors (x and eta: 4k
// scalars). The generator's unrolling takes the same values from
// compose.rs.
const VALUES4: u32 = (NN + N + FIXED_K + 3u) / 4u;
const APGD4: u32 = (5u * N + 3u) / 4u;
const X4: u32 = (N + 3u) / 4u;
const SWEEPS4: u32 = FIXED_K;

// The island's blocks as vec4: llvmpipe turns each buffer access at a
// per-island address into a loop over the SIMD lanes, one per access
// whatever its width, so a vec4 costs about what a scalar does (the reload
// of a k = 4 island at each round: 220 scalar reads, now 55). The blocks
// start at multiples of 4 scalars (island.data, island.vectors).
@group(0) @binding(2) var<storage, read> values: array<vec4<Scalar>>;
@group(0) @binding(3) var<storage, read_write> vectors: array<vec4<Scalar>>;

// The island's data and vectors, private to the invocation (see the top).
var<private> w: array<Scalar, NN>;
var<private> q: array<Scalar, N>;
var<private> mu: array<Scalar, FIXED_K>;
// Sweeps: x and the steps eta; APGD: x, u(x), y, u(y), best.
var<private> x: array<Scalar, N>;
var<private> ux: array<Scalar, N>;
var<private> y: array<Scalar, N>;
var<private> uy: array<Scalar, N>;
var<private> best: array<Scalar, N>;
var<private> eta: array<Scalar, FIXED_K>;
// APGD's trial iterate and its velocity; the sweeps' velocity u in `un`.
var<private> xn: array<Scalar, N>;
var<private> un: array<Scalar, N>;

// Entry e of the island's block in `values` into W, q or mu (e past the
// block: padding, dropped). Called with constant e only (unrolled loops),
// so every private index is a constant.
fn put_value(e: u32, v: Scalar) {
    if e < NN {
        w[e] = v;
    } else if e < NN + N {
        q[e - NN] = v;
    } else if e < NN + N + FIXED_K {
        mu[e - NN - N] = v;
    }
}

// Entry e of APGD's vectors (x, u(x), y, u(y), best) or of the sweeps'
// (x, eta) into the private arrays (padding dropped); constant e only.
fn put_vector(e: u32, v: Scalar, apgd: bool) {
    if e < N {
        x[e] = v;
    } else if !apgd {
        if e < N + FIXED_K {
            eta[e - N] = v;
        }
    } else if e < 2u * N {
        ux[e - N] = v;
    } else if e < 3u * N {
        y[e - 2u * N] = v;
    } else if e < 4u * N {
        uy[e - 3u * N] = v;
    } else if e < 5u * N {
        best[e - 4u * N] = v;
    }
}

// Entry e of APGD's vectors or the sweeps', 0 for padding; constant e only.
fn get_vector(e: u32, apgd: bool) -> Scalar {
    if e < N {
        return x[e];
    }
    if !apgd {
        if e < N + FIXED_K {
            return eta[e - N];
        }
        return Scalar(0.0);
    }
    if e < 2u * N {
        return ux[e - N];
    }
    if e < 3u * N {
        return y[e - 2u * N];
    }
    if e < 4u * N {
        return uy[e - 3u * N];
    }
    if e < 5u * N {
        return best[e - 4u * N];
    }
    return Scalar(0.0);
}

// Copies island `rec`'s W, q, mu into the private arrays, and its vectors:
// `vectors4` vec4s of them (x alone: X4, which may also fill the start of
// u(x); APGD's all: APGD4; the sweeps': SWEEPS4). Returns where its
// vectors lie in `vectors` (in vec4s).
fn load_island(rec: FrictionIsland, vectors4: u32, apgd: bool) -> u32 {
    let d = rec.data / 4u;
    for (var i = 0u; i < VALUES4; i++) { // UNROLL
        let t = values[d + i];
        put_value(4u * i, t.x);
        put_value(4u * i + 1u, t.y);
        put_value(4u * i + 2u, t.z);
        put_value(4u * i + 3u, t.w);
    }
    let v = rec.vectors / 4u;
    if vectors4 == X4 {
        for (var i = 0u; i < X4; i++) { // UNROLL
            let t = vectors[v + i];
            put_vector(4u * i, t.x, apgd);
            put_vector(4u * i + 1u, t.y, apgd);
            put_vector(4u * i + 2u, t.z, apgd);
            put_vector(4u * i + 3u, t.w, apgd);
        }
    } else if apgd {
        for (var i = 0u; i < APGD4; i++) { // UNROLL
            let t = vectors[v + i];
            put_vector(4u * i, t.x, true);
            put_vector(4u * i + 1u, t.y, true);
            put_vector(4u * i + 2u, t.z, true);
            put_vector(4u * i + 3u, t.w, true);
        }
    } else {
        for (var i = 0u; i < SWEEPS4; i++) { // UNROLL
            let t = vectors[v + i];
            put_vector(4u * i, t.x, false);
            put_vector(4u * i + 1u, t.y, false);
            put_vector(4u * i + 2u, t.z, false);
            put_vector(4u * i + 3u, t.w, false);
        }
    }
    return v;
}

// Row r of W x + q: s = sum_j W_rj x_j, then q_r + s.
fn velocity_row(r: u32) -> Scalar {
    var s = Scalar(0.0);
    for (var j = 0u; j < N; j++) { // UNROLL
        s += w[r * N + j] * x[j];
    }
    return q[r] + s;
}

// un = W x + q.
fn velocity_of_x() {
    for (var r = 0u; r < N; r++) { // UNROLL
        un[r] = velocity_row(r);
    }
}

// un = W xn + q.
fn velocity_of_trial() {
    for (var r = 0u; r < N; r++) { // UNROLL
        var s = Scalar(0.0);
        for (var j = 0u; j < N; j++) { // UNROLL
            s += w[r * N + j] * xn[j];
        }
        un[r] = q[r] + s;
    }
}

fn q_squared() -> Scalar {
    var s = Scalar(0.0);
    for (var r = 0u; r < N; r++) { // UNROLL
        s += q[r] * q[r];
    }
    return s;
}

// The stop measure (projected.rs stop_measure) of x (trial: xn) with
// velocity u = un.
fn stop_measure(trial: bool) -> Scalar {
    var e2 = Scalar(0.0);
    var x2 = Scalar(0.0);
    var u2 = Scalar(0.0);
    for (var i = 0u; i < FIXED_K; i++) { // UNROLL
        let c = 3u * i;
        var xi: vec3<Scalar>;
        if trial {
            xi = vec3<Scalar>(xn[c], xn[c + 1u], xn[c + 2u]);
        } else {
            xi = vec3<Scalar>(x[c], x[c + 1u], x[c + 2u]);
        }
        let u = vec3<Scalar>(un[c], un[c + 1u], un[c + 2u]);
        let p = project_on_cone(xi - u, mu[i]);
        let d = xi - p;
        e2 += d.x * d.x;
        e2 += d.y * d.y;
        e2 += d.z * d.z;
        x2 += xi.x * xi.x;
        x2 += xi.y * xi.y;
        x2 += xi.z * xi.z;
        u2 += u.x * u.x;
        u2 += u.y * u.y;
        u2 += u.z * u.z;
    }
    let scale = sqrt(max(max(q_squared(), x2), u2));
    let e = sqrt(e2);
    if scale > SCALE_FLOOR {
        return e / scale;
    }
    return e;
}

// Every contact's reaction in x projected on its cone.
fn project_x() {
    for (var i = 0u; i < FIXED_K; i++) { // UNROLL
        let c = 3u * i;
        let p = project_on_cone(vec3<Scalar>(x[c], x[c + 1u], x[c + 2u]), mu[i]);
        x[c] = p.x;
        x[c + 1u] = p.y;
        x[c + 2u] = p.z;
    }
}

// One unit of loop work per inner iteration of W x.
fn product_cost() -> u32 {
    return N * N + N;
}

// Saves the state; a running island counts itself in unfinished[k]. (k is
// the constant: indexing with min(islands[index].k, 16u) here counted
// every island in unfinished[0] on lavapipe, measured.)
fn finish_round(index: u32, st: FrictionState) {
    states[index] = st;
    if st.status == RUNNING {
        atomicAdd(&unfinished[FIXED_K], 1u);
    }
}

// The sweeps' steps (projected.rs contact_steps) into eta: the sums run
// over every column and skip those outside the contact's block for
// Gauss-Seidel (the same additions in the same order as the twin's
// loop over the block, with constant bounds for the unrolling).
fn contact_steps(gauss_seidel: bool) {
    for (var i = 0u; i < FIXED_K; i++) { // UNROLL
        var big = Scalar(0.0);
        for (var r = 3u * i; r < 3u * i + 3u; r++) { // UNROLL
            var s = Scalar(0.0);
            for (var j = 0u; j < N; j++) { // UNROLL
                if !gauss_seidel || (j >= 3u * i && j < 3u * i + 3u) {
                    s += abs(w[r * N + j]);
                }
            }
            big = max(big, s);
        }
        var e = Scalar(1.0);
        if big > Scalar(0.0) {
            e = Scalar(1.0) / big;
        }
        eta[i] = e;
    }
}

// One sweep over the contacts from u = un (Gauss-Seidel: each contact's
// velocity recomputed from the reactions updated so far).
fn sweep(gauss_seidel: bool) {
    for (var i = 0u; i < FIXED_K; i++) { // UNROLL
        let c = 3u * i;
        if gauss_seidel {
            for (var r = 3u * i; r < 3u * i + 3u; r++) { // UNROLL
                un[r] = velocity_row(r);
            }
        }
        let h = controls.relaxation * eta[i];
        let p = project_on_cone(
            vec3<Scalar>(x[c] - h * un[c], x[c + 1u] - h * un[c + 1u], x[c + 2u] - h * un[c + 2u]),
            mu[i]
        );
        x[c] = p.x;
        x[c + 1u] = p.y;
        x[c + 2u] = p.z;
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
    // x and eta (eta is 0 before the first round, then computed here).
    let v = load_island(rec, SWEEPS4, false);
    let gauss_seidel = (params.flags & 1u) == 1u;
    var spent = NN + 4u * N;
    if st.status == NOT_STARTED {
        project_x();
        contact_steps(gauss_seidel);
        st.status = RUNNING;
        spent += product_cost();
    }
    var cost = product_cost() + 6u * N;
    if gauss_seidel {
        cost += product_cost();
    }
    var err = Scalar(0.0);
    var tried = false;
    loop {
        if tried && spent + cost > params.budget {
            break;
        }
        tried = true;
        spent += cost;
        velocity_of_x();
        err = stop_measure(false);
        st.status = sweep_status(err, st.iterations);
        if st.status != RUNNING {
            break;
        }
        sweep(gauss_seidel);
        st.iterations++;
    }
    scalars[4u * index + 3u] = err;
    // An island that is done: x alone (its answer; see store_best).
    var stored = SWEEPS4;
    if st.status != RUNNING {
        stored = X4;
    }
    for (var i = 0u; i < SWEEPS4; i++) { // UNROLL
        if i < stored {
            vectors[v + i] = vec4<Scalar>(
                get_vector(4u * i, false),
                get_vector(4u * i + 1u, false),
                get_vector(4u * i + 2u, false),
                get_vector(4u * i + 3u, false)
            );
        }
    }
    finish_round(index, st);
}

// Writes APGD's vectors back to `vectors` from v (in vec4s).
fn store_apgd(v: u32) {
    for (var i = 0u; i < APGD4; i++) { // UNROLL
        vectors[v + i] = vec4<Scalar>(
            get_vector(4u * i, true),
            get_vector(4u * i + 1u, true),
            get_vector(4u * i + 2u, true),
            get_vector(4u * i + 3u, true)
        );
    }
}

// Writes APGD's best iterate alone (the answer the host reads, from 4N:
// a multiple of 4 scalars) from v: an island that is done needs nothing
// else, and llvmpipe turns every vec4 store at a per-island address into a
// loop over the SIMD lanes (15 of them at k = 4 for all the vectors).
fn store_best(v: u32) {
    for (var i = 0u; i < X4; i++) { // UNROLL
        vectors[v + N + i] = vec4<Scalar>(
            get_vector(4u * N + 4u * i, true),
            get_vector(4u * N + 4u * i + 1u, true),
            get_vector(4u * N + 4u * i + 2u, true),
            get_vector(4u * N + 4u * i + 3u, true)
        );
    }
}

// ||W e|| / ||e|| for e = (1, ..., 1), else the largest |W_rr|, else 1.
fn first_lipschitz() -> Scalar {
    var s2 = Scalar(0.0);
    for (var r = 0u; r < N; r++) { // UNROLL
        var s = Scalar(0.0);
        for (var j = 0u; j < N; j++) { // UNROLL
            s += w[r * N + j];
        }
        s2 += s * s;
    }
    let l = sqrt(s2 / Scalar(N));
    if l > Scalar(0.0) && finite(l) {
        return l;
    }
    var d = Scalar(0.0);
    for (var r = 0u; r < N; r++) { // UNROLL
        d = max(d, abs(w[r * N + r]));
    }
    if d > Scalar(0.0) && finite(d) {
        return d;
    }
    return Scalar(1.0);
}

// One backtracking try from y with step 1/L: xn = P_K(y - u(y) / L),
// un = u(xn); true when d^T W d <= L |d|^2, d = xn - y.
fn apgd_try(lipschitz: Scalar) -> bool {
    let t = Scalar(1.0) / lipschitz;
    for (var i = 0u; i < FIXED_K; i++) { // UNROLL
        let c = 3u * i;
        let p = project_on_cone(
            vec3<Scalar>(y[c] - t * uy[c], y[c + 1u] - t * uy[c + 1u], y[c + 2u] - t * uy[c + 2u]),
            mu[i]
        );
        xn[c] = p.x;
        xn[c + 1u] = p.y;
        xn[c + 2u] = p.z;
    }
    velocity_of_trial();
    var curvature = Scalar(0.0);
    var d2 = Scalar(0.0);
    var g2 = Scalar(0.0);
    for (var r = 0u; r < N; r++) { // UNROLL
        let d = xn[r] - y[r];
        curvature += d * (un[r] - uy[r]);
        d2 += d * d;
        g2 += uy[r] * uy[r];
    }
    return accept_step(curvature, d2, g2, lipschitz);
}

// APGD's scalars of one island: theta, L, best error, last error.
struct ApgdScalars {
    theta: Scalar,
    lipschitz: Scalar,
    best: Scalar,
    last: Scalar,
}

// After an accepted try: the best iterate, the momentum, the gradient
// restart, x = xn (apgd.rs apgd_iteration); counts the iteration and a
// restart in st, or writes FAILED into it.
fn apgd_accept(a: ptr<function, ApgdScalars>, st: ptr<function, FrictionState>) {
    let err = stop_measure(true);
    (*a).last = err;
    if !finite(err) {
        (*st).status = FAILED;
        return;
    }
    if err < (*a).best {
        (*a).best = err;
        for (var r = 0u; r < N; r++) { // UNROLL
            best[r] = xn[r];
        }
    }
    let th = (*a).theta;
    let m = apgd_momentum(th);
    let th_new = m.x;
    let beta = m.y;
    var g_dot = Scalar(0.0);
    for (var r = 0u; r < N; r++) { // UNROLL
        g_dot += uy[r] * (xn[r] - x[r]);
    }
    let restart = g_dot > Scalar(0.0);
    for (var r = 0u; r < N; r++) { // UNROLL
        if restart {
            y[r] = xn[r];
            uy[r] = un[r];
        } else {
            y[r] = xn[r] + beta * (xn[r] - x[r]);
            uy[r] = un[r] + beta * (un[r] - ux[r]);
        }
        x[r] = xn[r];
        ux[r] = un[r];
    }
    if restart {
        (*a).theta = Scalar(1.0);
        (*st).restarts++;
    } else {
        (*a).theta = th_new;
    }
    (*a).lipschitz = (*a).lipschitz * Scalar(0.9);
    (*st).iterations++;
    (*st).doublings = 0u;
}

// APGD's start (apgd.rs apgd): x projected, u(x), its error, y = x,
// u(y) = u(x), best = x, theta = 1, L from first_lipschitz; false when the
// error is not finite.
fn apgd_start(a: ptr<function, ApgdScalars>) -> bool {
    project_x();
    velocity_of_x();
    let err = stop_measure(false);
    for (var r = 0u; r < N; r++) { // UNROLL
        ux[r] = un[r];
        y[r] = x[r];
        uy[r] = un[r];
        best[r] = x[r];
    }
    *a = ApgdScalars(Scalar(1.0), first_lipschitz(), err, err);
    return finite(err);
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
    let s = 4u * index;
    var spent = NN + 6u * N;
    var a: ApgdScalars;
    var v: u32;
    if st.status == NOT_STARTED {
        v = load_island(rec, X4, true);
        st.status = RUNNING;
        if !apgd_start(&a) {
            st.status = FAILED;
        }
        spent += 2u * product_cost() + 8u * N;
    } else {
        v = load_island(rec, APGD4, true);
        a = ApgdScalars(scalars[s], scalars[s + 1u], scalars[s + 2u], scalars[s + 3u]);
    }
    let cost = product_cost() + 10u * N;
    var tried = false;
    loop {
        if st.status != RUNNING {
            break;
        }
        if a.best <= controls.tolerance {
            st.status = CONVERGED;
            break;
        }
        if st.iterations >= controls.max_iterations {
            st.status = AT_CAP;
            break;
        }
        if tried && spent + cost > params.budget {
            break;
        }
        tried = true;
        spent += cost;
        let lipschitz = a.lipschitz;
        if apgd_try(lipschitz) {
            apgd_accept(&a, &st);
        } else {
            let doubled = Scalar(2.0) * lipschitz;
            a.lipschitz = doubled;
            st.doublings++;
            if st.doublings >= MAX_BACKTRACKS || !finite(doubled) {
                st.status = FAILED;
            }
        }
    }
    scalars[s] = a.theta;
    scalars[s + 1u] = a.lipschitz;
    scalars[s + 2u] = a.best;
    scalars[s + 3u] = a.last;
    if st.status == RUNNING {
        store_apgd(v);
    } else {
        store_best(v);
    }
    finish_round(index, st);
}
