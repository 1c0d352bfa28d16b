// GENERATED from shaders/friction_common.wgsl + shaders/friction_projected.wgsl by src/gpu/shaders/compose.rs: do not edit.
// Regenerate: LCPBATCH_BLESS_SHADERS=1 cargo test --release generated_shaders_are_committed

// The part of the friction kernels common to both sources (prepended to
// shaders/friction_projected.wgsl for k <= 4 and to
// shaders/friction_projected_global.wgsl for k > 4 by
// src/gpu/shaders/compose.rs): the HOST lines, the constants, the records,
// the bindings, the finiteness test, the cone projection and APGD's
// scalar steps. Read the two sources' headers for the layout and the
// rounds. The world step kernel (shaders/world_friction.wgsl) takes this
// file from the cone projection on.

alias Scalar = f32; // HOST scalar
const SCALAR_MAX: Scalar = 3.4028234663852886e38; // HOST scalar_max
const SCALAR_EPSILON: Scalar = 1.1920929e-7; // HOST scalar_epsilon
// Islands of exactly FIXED_K contacts (the generator writes one kernel per
// k = 1...16): every loop bound is a constant, which llvmpipe unrolls.
const FIXED_K: u32 = 4u; // HOST fixed_k

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
{

        let t = values[d + 0u];
        put_value(4u * 0u, t.x);
        put_value(4u * 0u + 1u, t.y);
        put_value(4u * 0u + 2u, t.z);
        put_value(4u * 0u + 3u, t.w);
    }
{

        let t = values[d + 1u];
        put_value(4u * 1u, t.x);
        put_value(4u * 1u + 1u, t.y);
        put_value(4u * 1u + 2u, t.z);
        put_value(4u * 1u + 3u, t.w);
    }
{

        let t = values[d + 2u];
        put_value(4u * 2u, t.x);
        put_value(4u * 2u + 1u, t.y);
        put_value(4u * 2u + 2u, t.z);
        put_value(4u * 2u + 3u, t.w);
    }
{

        let t = values[d + 3u];
        put_value(4u * 3u, t.x);
        put_value(4u * 3u + 1u, t.y);
        put_value(4u * 3u + 2u, t.z);
        put_value(4u * 3u + 3u, t.w);
    }
{

        let t = values[d + 4u];
        put_value(4u * 4u, t.x);
        put_value(4u * 4u + 1u, t.y);
        put_value(4u * 4u + 2u, t.z);
        put_value(4u * 4u + 3u, t.w);
    }
{

        let t = values[d + 5u];
        put_value(4u * 5u, t.x);
        put_value(4u * 5u + 1u, t.y);
        put_value(4u * 5u + 2u, t.z);
        put_value(4u * 5u + 3u, t.w);
    }
{

        let t = values[d + 6u];
        put_value(4u * 6u, t.x);
        put_value(4u * 6u + 1u, t.y);
        put_value(4u * 6u + 2u, t.z);
        put_value(4u * 6u + 3u, t.w);
    }
{

        let t = values[d + 7u];
        put_value(4u * 7u, t.x);
        put_value(4u * 7u + 1u, t.y);
        put_value(4u * 7u + 2u, t.z);
        put_value(4u * 7u + 3u, t.w);
    }
{

        let t = values[d + 8u];
        put_value(4u * 8u, t.x);
        put_value(4u * 8u + 1u, t.y);
        put_value(4u * 8u + 2u, t.z);
        put_value(4u * 8u + 3u, t.w);
    }
{

        let t = values[d + 9u];
        put_value(4u * 9u, t.x);
        put_value(4u * 9u + 1u, t.y);
        put_value(4u * 9u + 2u, t.z);
        put_value(4u * 9u + 3u, t.w);
    }
{

        let t = values[d + 10u];
        put_value(4u * 10u, t.x);
        put_value(4u * 10u + 1u, t.y);
        put_value(4u * 10u + 2u, t.z);
        put_value(4u * 10u + 3u, t.w);
    }
{

        let t = values[d + 11u];
        put_value(4u * 11u, t.x);
        put_value(4u * 11u + 1u, t.y);
        put_value(4u * 11u + 2u, t.z);
        put_value(4u * 11u + 3u, t.w);
    }
{

        let t = values[d + 12u];
        put_value(4u * 12u, t.x);
        put_value(4u * 12u + 1u, t.y);
        put_value(4u * 12u + 2u, t.z);
        put_value(4u * 12u + 3u, t.w);
    }
{

        let t = values[d + 13u];
        put_value(4u * 13u, t.x);
        put_value(4u * 13u + 1u, t.y);
        put_value(4u * 13u + 2u, t.z);
        put_value(4u * 13u + 3u, t.w);
    }
{

        let t = values[d + 14u];
        put_value(4u * 14u, t.x);
        put_value(4u * 14u + 1u, t.y);
        put_value(4u * 14u + 2u, t.z);
        put_value(4u * 14u + 3u, t.w);
    }
{

        let t = values[d + 15u];
        put_value(4u * 15u, t.x);
        put_value(4u * 15u + 1u, t.y);
        put_value(4u * 15u + 2u, t.z);
        put_value(4u * 15u + 3u, t.w);
    }
{

        let t = values[d + 16u];
        put_value(4u * 16u, t.x);
        put_value(4u * 16u + 1u, t.y);
        put_value(4u * 16u + 2u, t.z);
        put_value(4u * 16u + 3u, t.w);
    }
{

        let t = values[d + 17u];
        put_value(4u * 17u, t.x);
        put_value(4u * 17u + 1u, t.y);
        put_value(4u * 17u + 2u, t.z);
        put_value(4u * 17u + 3u, t.w);
    }
{

        let t = values[d + 18u];
        put_value(4u * 18u, t.x);
        put_value(4u * 18u + 1u, t.y);
        put_value(4u * 18u + 2u, t.z);
        put_value(4u * 18u + 3u, t.w);
    }
{

        let t = values[d + 19u];
        put_value(4u * 19u, t.x);
        put_value(4u * 19u + 1u, t.y);
        put_value(4u * 19u + 2u, t.z);
        put_value(4u * 19u + 3u, t.w);
    }
{

        let t = values[d + 20u];
        put_value(4u * 20u, t.x);
        put_value(4u * 20u + 1u, t.y);
        put_value(4u * 20u + 2u, t.z);
        put_value(4u * 20u + 3u, t.w);
    }
{

        let t = values[d + 21u];
        put_value(4u * 21u, t.x);
        put_value(4u * 21u + 1u, t.y);
        put_value(4u * 21u + 2u, t.z);
        put_value(4u * 21u + 3u, t.w);
    }
{

        let t = values[d + 22u];
        put_value(4u * 22u, t.x);
        put_value(4u * 22u + 1u, t.y);
        put_value(4u * 22u + 2u, t.z);
        put_value(4u * 22u + 3u, t.w);
    }
{

        let t = values[d + 23u];
        put_value(4u * 23u, t.x);
        put_value(4u * 23u + 1u, t.y);
        put_value(4u * 23u + 2u, t.z);
        put_value(4u * 23u + 3u, t.w);
    }
{

        let t = values[d + 24u];
        put_value(4u * 24u, t.x);
        put_value(4u * 24u + 1u, t.y);
        put_value(4u * 24u + 2u, t.z);
        put_value(4u * 24u + 3u, t.w);
    }
{

        let t = values[d + 25u];
        put_value(4u * 25u, t.x);
        put_value(4u * 25u + 1u, t.y);
        put_value(4u * 25u + 2u, t.z);
        put_value(4u * 25u + 3u, t.w);
    }
{

        let t = values[d + 26u];
        put_value(4u * 26u, t.x);
        put_value(4u * 26u + 1u, t.y);
        put_value(4u * 26u + 2u, t.z);
        put_value(4u * 26u + 3u, t.w);
    }
{

        let t = values[d + 27u];
        put_value(4u * 27u, t.x);
        put_value(4u * 27u + 1u, t.y);
        put_value(4u * 27u + 2u, t.z);
        put_value(4u * 27u + 3u, t.w);
    }
{

        let t = values[d + 28u];
        put_value(4u * 28u, t.x);
        put_value(4u * 28u + 1u, t.y);
        put_value(4u * 28u + 2u, t.z);
        put_value(4u * 28u + 3u, t.w);
    }
{

        let t = values[d + 29u];
        put_value(4u * 29u, t.x);
        put_value(4u * 29u + 1u, t.y);
        put_value(4u * 29u + 2u, t.z);
        put_value(4u * 29u + 3u, t.w);
    }
{

        let t = values[d + 30u];
        put_value(4u * 30u, t.x);
        put_value(4u * 30u + 1u, t.y);
        put_value(4u * 30u + 2u, t.z);
        put_value(4u * 30u + 3u, t.w);
    }
{

        let t = values[d + 31u];
        put_value(4u * 31u, t.x);
        put_value(4u * 31u + 1u, t.y);
        put_value(4u * 31u + 2u, t.z);
        put_value(4u * 31u + 3u, t.w);
    }
{

        let t = values[d + 32u];
        put_value(4u * 32u, t.x);
        put_value(4u * 32u + 1u, t.y);
        put_value(4u * 32u + 2u, t.z);
        put_value(4u * 32u + 3u, t.w);
    }
{

        let t = values[d + 33u];
        put_value(4u * 33u, t.x);
        put_value(4u * 33u + 1u, t.y);
        put_value(4u * 33u + 2u, t.z);
        put_value(4u * 33u + 3u, t.w);
    }
{

        let t = values[d + 34u];
        put_value(4u * 34u, t.x);
        put_value(4u * 34u + 1u, t.y);
        put_value(4u * 34u + 2u, t.z);
        put_value(4u * 34u + 3u, t.w);
    }
{

        let t = values[d + 35u];
        put_value(4u * 35u, t.x);
        put_value(4u * 35u + 1u, t.y);
        put_value(4u * 35u + 2u, t.z);
        put_value(4u * 35u + 3u, t.w);
    }
{

        let t = values[d + 36u];
        put_value(4u * 36u, t.x);
        put_value(4u * 36u + 1u, t.y);
        put_value(4u * 36u + 2u, t.z);
        put_value(4u * 36u + 3u, t.w);
    }
{

        let t = values[d + 37u];
        put_value(4u * 37u, t.x);
        put_value(4u * 37u + 1u, t.y);
        put_value(4u * 37u + 2u, t.z);
        put_value(4u * 37u + 3u, t.w);
    }
{

        let t = values[d + 38u];
        put_value(4u * 38u, t.x);
        put_value(4u * 38u + 1u, t.y);
        put_value(4u * 38u + 2u, t.z);
        put_value(4u * 38u + 3u, t.w);
    }
{

        let t = values[d + 39u];
        put_value(4u * 39u, t.x);
        put_value(4u * 39u + 1u, t.y);
        put_value(4u * 39u + 2u, t.z);
        put_value(4u * 39u + 3u, t.w);
    }

    let v = rec.vectors / 4u;
    if vectors4 == X4 {
{

            let t = vectors[v + 0u];
            put_vector(4u * 0u, t.x, apgd);
            put_vector(4u * 0u + 1u, t.y, apgd);
            put_vector(4u * 0u + 2u, t.z, apgd);
            put_vector(4u * 0u + 3u, t.w, apgd);
        }
{

            let t = vectors[v + 1u];
            put_vector(4u * 1u, t.x, apgd);
            put_vector(4u * 1u + 1u, t.y, apgd);
            put_vector(4u * 1u + 2u, t.z, apgd);
            put_vector(4u * 1u + 3u, t.w, apgd);
        }
{

            let t = vectors[v + 2u];
            put_vector(4u * 2u, t.x, apgd);
            put_vector(4u * 2u + 1u, t.y, apgd);
            put_vector(4u * 2u + 2u, t.z, apgd);
            put_vector(4u * 2u + 3u, t.w, apgd);
        }

    } else if apgd {
{

            let t = vectors[v + 0u];
            put_vector(4u * 0u, t.x, true);
            put_vector(4u * 0u + 1u, t.y, true);
            put_vector(4u * 0u + 2u, t.z, true);
            put_vector(4u * 0u + 3u, t.w, true);
        }
{

            let t = vectors[v + 1u];
            put_vector(4u * 1u, t.x, true);
            put_vector(4u * 1u + 1u, t.y, true);
            put_vector(4u * 1u + 2u, t.z, true);
            put_vector(4u * 1u + 3u, t.w, true);
        }
{

            let t = vectors[v + 2u];
            put_vector(4u * 2u, t.x, true);
            put_vector(4u * 2u + 1u, t.y, true);
            put_vector(4u * 2u + 2u, t.z, true);
            put_vector(4u * 2u + 3u, t.w, true);
        }
{

            let t = vectors[v + 3u];
            put_vector(4u * 3u, t.x, true);
            put_vector(4u * 3u + 1u, t.y, true);
            put_vector(4u * 3u + 2u, t.z, true);
            put_vector(4u * 3u + 3u, t.w, true);
        }
{

            let t = vectors[v + 4u];
            put_vector(4u * 4u, t.x, true);
            put_vector(4u * 4u + 1u, t.y, true);
            put_vector(4u * 4u + 2u, t.z, true);
            put_vector(4u * 4u + 3u, t.w, true);
        }
{

            let t = vectors[v + 5u];
            put_vector(4u * 5u, t.x, true);
            put_vector(4u * 5u + 1u, t.y, true);
            put_vector(4u * 5u + 2u, t.z, true);
            put_vector(4u * 5u + 3u, t.w, true);
        }
{

            let t = vectors[v + 6u];
            put_vector(4u * 6u, t.x, true);
            put_vector(4u * 6u + 1u, t.y, true);
            put_vector(4u * 6u + 2u, t.z, true);
            put_vector(4u * 6u + 3u, t.w, true);
        }
{

            let t = vectors[v + 7u];
            put_vector(4u * 7u, t.x, true);
            put_vector(4u * 7u + 1u, t.y, true);
            put_vector(4u * 7u + 2u, t.z, true);
            put_vector(4u * 7u + 3u, t.w, true);
        }
{

            let t = vectors[v + 8u];
            put_vector(4u * 8u, t.x, true);
            put_vector(4u * 8u + 1u, t.y, true);
            put_vector(4u * 8u + 2u, t.z, true);
            put_vector(4u * 8u + 3u, t.w, true);
        }
{

            let t = vectors[v + 9u];
            put_vector(4u * 9u, t.x, true);
            put_vector(4u * 9u + 1u, t.y, true);
            put_vector(4u * 9u + 2u, t.z, true);
            put_vector(4u * 9u + 3u, t.w, true);
        }
{

            let t = vectors[v + 10u];
            put_vector(4u * 10u, t.x, true);
            put_vector(4u * 10u + 1u, t.y, true);
            put_vector(4u * 10u + 2u, t.z, true);
            put_vector(4u * 10u + 3u, t.w, true);
        }
{

            let t = vectors[v + 11u];
            put_vector(4u * 11u, t.x, true);
            put_vector(4u * 11u + 1u, t.y, true);
            put_vector(4u * 11u + 2u, t.z, true);
            put_vector(4u * 11u + 3u, t.w, true);
        }
{

            let t = vectors[v + 12u];
            put_vector(4u * 12u, t.x, true);
            put_vector(4u * 12u + 1u, t.y, true);
            put_vector(4u * 12u + 2u, t.z, true);
            put_vector(4u * 12u + 3u, t.w, true);
        }
{

            let t = vectors[v + 13u];
            put_vector(4u * 13u, t.x, true);
            put_vector(4u * 13u + 1u, t.y, true);
            put_vector(4u * 13u + 2u, t.z, true);
            put_vector(4u * 13u + 3u, t.w, true);
        }
{

            let t = vectors[v + 14u];
            put_vector(4u * 14u, t.x, true);
            put_vector(4u * 14u + 1u, t.y, true);
            put_vector(4u * 14u + 2u, t.z, true);
            put_vector(4u * 14u + 3u, t.w, true);
        }

    } else {
{

            let t = vectors[v + 0u];
            put_vector(4u * 0u, t.x, false);
            put_vector(4u * 0u + 1u, t.y, false);
            put_vector(4u * 0u + 2u, t.z, false);
            put_vector(4u * 0u + 3u, t.w, false);
        }
{

            let t = vectors[v + 1u];
            put_vector(4u * 1u, t.x, false);
            put_vector(4u * 1u + 1u, t.y, false);
            put_vector(4u * 1u + 2u, t.z, false);
            put_vector(4u * 1u + 3u, t.w, false);
        }
{

            let t = vectors[v + 2u];
            put_vector(4u * 2u, t.x, false);
            put_vector(4u * 2u + 1u, t.y, false);
            put_vector(4u * 2u + 2u, t.z, false);
            put_vector(4u * 2u + 3u, t.w, false);
        }
{

            let t = vectors[v + 3u];
            put_vector(4u * 3u, t.x, false);
            put_vector(4u * 3u + 1u, t.y, false);
            put_vector(4u * 3u + 2u, t.z, false);
            put_vector(4u * 3u + 3u, t.w, false);
        }

    }
    return v;
}

// Row r of W x + q: s = sum_j W_rj x_j, then q_r + s.
fn velocity_row(r: u32) -> Scalar {
    var s = Scalar(0.0);
{

        s += w[r * N + 0u] * x[0u];
    }
{

        s += w[r * N + 1u] * x[1u];
    }
{

        s += w[r * N + 2u] * x[2u];
    }
{

        s += w[r * N + 3u] * x[3u];
    }
{

        s += w[r * N + 4u] * x[4u];
    }
{

        s += w[r * N + 5u] * x[5u];
    }
{

        s += w[r * N + 6u] * x[6u];
    }
{

        s += w[r * N + 7u] * x[7u];
    }
{

        s += w[r * N + 8u] * x[8u];
    }
{

        s += w[r * N + 9u] * x[9u];
    }
{

        s += w[r * N + 10u] * x[10u];
    }
{

        s += w[r * N + 11u] * x[11u];
    }

    return q[r] + s;
}

// un = W x + q.
fn velocity_of_x() {
{

        un[0u] = velocity_row(0u);
    }
{

        un[1u] = velocity_row(1u);
    }
{

        un[2u] = velocity_row(2u);
    }
{

        un[3u] = velocity_row(3u);
    }
{

        un[4u] = velocity_row(4u);
    }
{

        un[5u] = velocity_row(5u);
    }
{

        un[6u] = velocity_row(6u);
    }
{

        un[7u] = velocity_row(7u);
    }
{

        un[8u] = velocity_row(8u);
    }
{

        un[9u] = velocity_row(9u);
    }
{

        un[10u] = velocity_row(10u);
    }
{

        un[11u] = velocity_row(11u);
    }

}

// un = W xn + q.
fn velocity_of_trial() {
{

        var s = Scalar(0.0);
{

            s += w[0u * N + 0u] * xn[0u];
        }
{

            s += w[0u * N + 1u] * xn[1u];
        }
{

            s += w[0u * N + 2u] * xn[2u];
        }
{

            s += w[0u * N + 3u] * xn[3u];
        }
{

            s += w[0u * N + 4u] * xn[4u];
        }
{

            s += w[0u * N + 5u] * xn[5u];
        }
{

            s += w[0u * N + 6u] * xn[6u];
        }
{

            s += w[0u * N + 7u] * xn[7u];
        }
{

            s += w[0u * N + 8u] * xn[8u];
        }
{

            s += w[0u * N + 9u] * xn[9u];
        }
{

            s += w[0u * N + 10u] * xn[10u];
        }
{

            s += w[0u * N + 11u] * xn[11u];
        }

        un[0u] = q[0u] + s;
    }
{

        var s = Scalar(0.0);
{

            s += w[1u * N + 0u] * xn[0u];
        }
{

            s += w[1u * N + 1u] * xn[1u];
        }
{

            s += w[1u * N + 2u] * xn[2u];
        }
{

            s += w[1u * N + 3u] * xn[3u];
        }
{

            s += w[1u * N + 4u] * xn[4u];
        }
{

            s += w[1u * N + 5u] * xn[5u];
        }
{

            s += w[1u * N + 6u] * xn[6u];
        }
{

            s += w[1u * N + 7u] * xn[7u];
        }
{

            s += w[1u * N + 8u] * xn[8u];
        }
{

            s += w[1u * N + 9u] * xn[9u];
        }
{

            s += w[1u * N + 10u] * xn[10u];
        }
{

            s += w[1u * N + 11u] * xn[11u];
        }

        un[1u] = q[1u] + s;
    }
{

        var s = Scalar(0.0);
{

            s += w[2u * N + 0u] * xn[0u];
        }
{

            s += w[2u * N + 1u] * xn[1u];
        }
{

            s += w[2u * N + 2u] * xn[2u];
        }
{

            s += w[2u * N + 3u] * xn[3u];
        }
{

            s += w[2u * N + 4u] * xn[4u];
        }
{

            s += w[2u * N + 5u] * xn[5u];
        }
{

            s += w[2u * N + 6u] * xn[6u];
        }
{

            s += w[2u * N + 7u] * xn[7u];
        }
{

            s += w[2u * N + 8u] * xn[8u];
        }
{

            s += w[2u * N + 9u] * xn[9u];
        }
{

            s += w[2u * N + 10u] * xn[10u];
        }
{

            s += w[2u * N + 11u] * xn[11u];
        }

        un[2u] = q[2u] + s;
    }
{

        var s = Scalar(0.0);
{

            s += w[3u * N + 0u] * xn[0u];
        }
{

            s += w[3u * N + 1u] * xn[1u];
        }
{

            s += w[3u * N + 2u] * xn[2u];
        }
{

            s += w[3u * N + 3u] * xn[3u];
        }
{

            s += w[3u * N + 4u] * xn[4u];
        }
{

            s += w[3u * N + 5u] * xn[5u];
        }
{

            s += w[3u * N + 6u] * xn[6u];
        }
{

            s += w[3u * N + 7u] * xn[7u];
        }
{

            s += w[3u * N + 8u] * xn[8u];
        }
{

            s += w[3u * N + 9u] * xn[9u];
        }
{

            s += w[3u * N + 10u] * xn[10u];
        }
{

            s += w[3u * N + 11u] * xn[11u];
        }

        un[3u] = q[3u] + s;
    }
{

        var s = Scalar(0.0);
{

            s += w[4u * N + 0u] * xn[0u];
        }
{

            s += w[4u * N + 1u] * xn[1u];
        }
{

            s += w[4u * N + 2u] * xn[2u];
        }
{

            s += w[4u * N + 3u] * xn[3u];
        }
{

            s += w[4u * N + 4u] * xn[4u];
        }
{

            s += w[4u * N + 5u] * xn[5u];
        }
{

            s += w[4u * N + 6u] * xn[6u];
        }
{

            s += w[4u * N + 7u] * xn[7u];
        }
{

            s += w[4u * N + 8u] * xn[8u];
        }
{

            s += w[4u * N + 9u] * xn[9u];
        }
{

            s += w[4u * N + 10u] * xn[10u];
        }
{

            s += w[4u * N + 11u] * xn[11u];
        }

        un[4u] = q[4u] + s;
    }
{

        var s = Scalar(0.0);
{

            s += w[5u * N + 0u] * xn[0u];
        }
{

            s += w[5u * N + 1u] * xn[1u];
        }
{

            s += w[5u * N + 2u] * xn[2u];
        }
{

            s += w[5u * N + 3u] * xn[3u];
        }
{

            s += w[5u * N + 4u] * xn[4u];
        }
{

            s += w[5u * N + 5u] * xn[5u];
        }
{

            s += w[5u * N + 6u] * xn[6u];
        }
{

            s += w[5u * N + 7u] * xn[7u];
        }
{

            s += w[5u * N + 8u] * xn[8u];
        }
{

            s += w[5u * N + 9u] * xn[9u];
        }
{

            s += w[5u * N + 10u] * xn[10u];
        }
{

            s += w[5u * N + 11u] * xn[11u];
        }

        un[5u] = q[5u] + s;
    }
{

        var s = Scalar(0.0);
{

            s += w[6u * N + 0u] * xn[0u];
        }
{

            s += w[6u * N + 1u] * xn[1u];
        }
{

            s += w[6u * N + 2u] * xn[2u];
        }
{

            s += w[6u * N + 3u] * xn[3u];
        }
{

            s += w[6u * N + 4u] * xn[4u];
        }
{

            s += w[6u * N + 5u] * xn[5u];
        }
{

            s += w[6u * N + 6u] * xn[6u];
        }
{

            s += w[6u * N + 7u] * xn[7u];
        }
{

            s += w[6u * N + 8u] * xn[8u];
        }
{

            s += w[6u * N + 9u] * xn[9u];
        }
{

            s += w[6u * N + 10u] * xn[10u];
        }
{

            s += w[6u * N + 11u] * xn[11u];
        }

        un[6u] = q[6u] + s;
    }
{

        var s = Scalar(0.0);
{

            s += w[7u * N + 0u] * xn[0u];
        }
{

            s += w[7u * N + 1u] * xn[1u];
        }
{

            s += w[7u * N + 2u] * xn[2u];
        }
{

            s += w[7u * N + 3u] * xn[3u];
        }
{

            s += w[7u * N + 4u] * xn[4u];
        }
{

            s += w[7u * N + 5u] * xn[5u];
        }
{

            s += w[7u * N + 6u] * xn[6u];
        }
{

            s += w[7u * N + 7u] * xn[7u];
        }
{

            s += w[7u * N + 8u] * xn[8u];
        }
{

            s += w[7u * N + 9u] * xn[9u];
        }
{

            s += w[7u * N + 10u] * xn[10u];
        }
{

            s += w[7u * N + 11u] * xn[11u];
        }

        un[7u] = q[7u] + s;
    }
{

        var s = Scalar(0.0);
{

            s += w[8u * N + 0u] * xn[0u];
        }
{

            s += w[8u * N + 1u] * xn[1u];
        }
{

            s += w[8u * N + 2u] * xn[2u];
        }
{

            s += w[8u * N + 3u] * xn[3u];
        }
{

            s += w[8u * N + 4u] * xn[4u];
        }
{

            s += w[8u * N + 5u] * xn[5u];
        }
{

            s += w[8u * N + 6u] * xn[6u];
        }
{

            s += w[8u * N + 7u] * xn[7u];
        }
{

            s += w[8u * N + 8u] * xn[8u];
        }
{

            s += w[8u * N + 9u] * xn[9u];
        }
{

            s += w[8u * N + 10u] * xn[10u];
        }
{

            s += w[8u * N + 11u] * xn[11u];
        }

        un[8u] = q[8u] + s;
    }
{

        var s = Scalar(0.0);
{

            s += w[9u * N + 0u] * xn[0u];
        }
{

            s += w[9u * N + 1u] * xn[1u];
        }
{

            s += w[9u * N + 2u] * xn[2u];
        }
{

            s += w[9u * N + 3u] * xn[3u];
        }
{

            s += w[9u * N + 4u] * xn[4u];
        }
{

            s += w[9u * N + 5u] * xn[5u];
        }
{

            s += w[9u * N + 6u] * xn[6u];
        }
{

            s += w[9u * N + 7u] * xn[7u];
        }
{

            s += w[9u * N + 8u] * xn[8u];
        }
{

            s += w[9u * N + 9u] * xn[9u];
        }
{

            s += w[9u * N + 10u] * xn[10u];
        }
{

            s += w[9u * N + 11u] * xn[11u];
        }

        un[9u] = q[9u] + s;
    }
{

        var s = Scalar(0.0);
{

            s += w[10u * N + 0u] * xn[0u];
        }
{

            s += w[10u * N + 1u] * xn[1u];
        }
{

            s += w[10u * N + 2u] * xn[2u];
        }
{

            s += w[10u * N + 3u] * xn[3u];
        }
{

            s += w[10u * N + 4u] * xn[4u];
        }
{

            s += w[10u * N + 5u] * xn[5u];
        }
{

            s += w[10u * N + 6u] * xn[6u];
        }
{

            s += w[10u * N + 7u] * xn[7u];
        }
{

            s += w[10u * N + 8u] * xn[8u];
        }
{

            s += w[10u * N + 9u] * xn[9u];
        }
{

            s += w[10u * N + 10u] * xn[10u];
        }
{

            s += w[10u * N + 11u] * xn[11u];
        }

        un[10u] = q[10u] + s;
    }
{

        var s = Scalar(0.0);
{

            s += w[11u * N + 0u] * xn[0u];
        }
{

            s += w[11u * N + 1u] * xn[1u];
        }
{

            s += w[11u * N + 2u] * xn[2u];
        }
{

            s += w[11u * N + 3u] * xn[3u];
        }
{

            s += w[11u * N + 4u] * xn[4u];
        }
{

            s += w[11u * N + 5u] * xn[5u];
        }
{

            s += w[11u * N + 6u] * xn[6u];
        }
{

            s += w[11u * N + 7u] * xn[7u];
        }
{

            s += w[11u * N + 8u] * xn[8u];
        }
{

            s += w[11u * N + 9u] * xn[9u];
        }
{

            s += w[11u * N + 10u] * xn[10u];
        }
{

            s += w[11u * N + 11u] * xn[11u];
        }

        un[11u] = q[11u] + s;
    }

}

fn q_squared() -> Scalar {
    var s = Scalar(0.0);
{

        s += q[0u] * q[0u];
    }
{

        s += q[1u] * q[1u];
    }
{

        s += q[2u] * q[2u];
    }
{

        s += q[3u] * q[3u];
    }
{

        s += q[4u] * q[4u];
    }
{

        s += q[5u] * q[5u];
    }
{

        s += q[6u] * q[6u];
    }
{

        s += q[7u] * q[7u];
    }
{

        s += q[8u] * q[8u];
    }
{

        s += q[9u] * q[9u];
    }
{

        s += q[10u] * q[10u];
    }
{

        s += q[11u] * q[11u];
    }

    return s;
}

// The stop measure (projected.rs stop_measure) of x (trial: xn) with
// velocity u = un.
fn stop_measure(trial: bool) -> Scalar {
    var e2 = Scalar(0.0);
    var x2 = Scalar(0.0);
    var u2 = Scalar(0.0);
{

        let c = 3u * 0u;
        var xi: vec3<Scalar>;
        if trial {
            xi = vec3<Scalar>(xn[c], xn[c + 1u], xn[c + 2u]);
        } else {
            xi = vec3<Scalar>(x[c], x[c + 1u], x[c + 2u]);
        }
        let u = vec3<Scalar>(un[c], un[c + 1u], un[c + 2u]);
        let p = project_on_cone(xi - u, mu[0u]);
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
{

        let c = 3u * 1u;
        var xi: vec3<Scalar>;
        if trial {
            xi = vec3<Scalar>(xn[c], xn[c + 1u], xn[c + 2u]);
        } else {
            xi = vec3<Scalar>(x[c], x[c + 1u], x[c + 2u]);
        }
        let u = vec3<Scalar>(un[c], un[c + 1u], un[c + 2u]);
        let p = project_on_cone(xi - u, mu[1u]);
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
{

        let c = 3u * 2u;
        var xi: vec3<Scalar>;
        if trial {
            xi = vec3<Scalar>(xn[c], xn[c + 1u], xn[c + 2u]);
        } else {
            xi = vec3<Scalar>(x[c], x[c + 1u], x[c + 2u]);
        }
        let u = vec3<Scalar>(un[c], un[c + 1u], un[c + 2u]);
        let p = project_on_cone(xi - u, mu[2u]);
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
{

        let c = 3u * 3u;
        var xi: vec3<Scalar>;
        if trial {
            xi = vec3<Scalar>(xn[c], xn[c + 1u], xn[c + 2u]);
        } else {
            xi = vec3<Scalar>(x[c], x[c + 1u], x[c + 2u]);
        }
        let u = vec3<Scalar>(un[c], un[c + 1u], un[c + 2u]);
        let p = project_on_cone(xi - u, mu[3u]);
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
{

        let c = 3u * 0u;
        let p = project_on_cone(vec3<Scalar>(x[c], x[c + 1u], x[c + 2u]), mu[0u]);
        x[c] = p.x;
        x[c + 1u] = p.y;
        x[c + 2u] = p.z;
    }
{

        let c = 3u * 1u;
        let p = project_on_cone(vec3<Scalar>(x[c], x[c + 1u], x[c + 2u]), mu[1u]);
        x[c] = p.x;
        x[c + 1u] = p.y;
        x[c + 2u] = p.z;
    }
{

        let c = 3u * 2u;
        let p = project_on_cone(vec3<Scalar>(x[c], x[c + 1u], x[c + 2u]), mu[2u]);
        x[c] = p.x;
        x[c + 1u] = p.y;
        x[c + 2u] = p.z;
    }
{

        let c = 3u * 3u;
        let p = project_on_cone(vec3<Scalar>(x[c], x[c + 1u], x[c + 2u]), mu[3u]);
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
{

        var big = Scalar(0.0);
{

            var s = Scalar(0.0);
{

                if !gauss_seidel || (0u >= 3u * 0u && 0u < 3u * 0u + 3u) {
                    s += abs(w[0u * N + 0u]);
                }
            }
{

                if !gauss_seidel || (1u >= 3u * 0u && 1u < 3u * 0u + 3u) {
                    s += abs(w[0u * N + 1u]);
                }
            }
{

                if !gauss_seidel || (2u >= 3u * 0u && 2u < 3u * 0u + 3u) {
                    s += abs(w[0u * N + 2u]);
                }
            }
{

                if !gauss_seidel || (3u >= 3u * 0u && 3u < 3u * 0u + 3u) {
                    s += abs(w[0u * N + 3u]);
                }
            }
{

                if !gauss_seidel || (4u >= 3u * 0u && 4u < 3u * 0u + 3u) {
                    s += abs(w[0u * N + 4u]);
                }
            }
{

                if !gauss_seidel || (5u >= 3u * 0u && 5u < 3u * 0u + 3u) {
                    s += abs(w[0u * N + 5u]);
                }
            }
{

                if !gauss_seidel || (6u >= 3u * 0u && 6u < 3u * 0u + 3u) {
                    s += abs(w[0u * N + 6u]);
                }
            }
{

                if !gauss_seidel || (7u >= 3u * 0u && 7u < 3u * 0u + 3u) {
                    s += abs(w[0u * N + 7u]);
                }
            }
{

                if !gauss_seidel || (8u >= 3u * 0u && 8u < 3u * 0u + 3u) {
                    s += abs(w[0u * N + 8u]);
                }
            }
{

                if !gauss_seidel || (9u >= 3u * 0u && 9u < 3u * 0u + 3u) {
                    s += abs(w[0u * N + 9u]);
                }
            }
{

                if !gauss_seidel || (10u >= 3u * 0u && 10u < 3u * 0u + 3u) {
                    s += abs(w[0u * N + 10u]);
                }
            }
{

                if !gauss_seidel || (11u >= 3u * 0u && 11u < 3u * 0u + 3u) {
                    s += abs(w[0u * N + 11u]);
                }
            }

            big = max(big, s);
        }
{

            var s = Scalar(0.0);
{

                if !gauss_seidel || (0u >= 3u * 0u && 0u < 3u * 0u + 3u) {
                    s += abs(w[1u * N + 0u]);
                }
            }
{

                if !gauss_seidel || (1u >= 3u * 0u && 1u < 3u * 0u + 3u) {
                    s += abs(w[1u * N + 1u]);
                }
            }
{

                if !gauss_seidel || (2u >= 3u * 0u && 2u < 3u * 0u + 3u) {
                    s += abs(w[1u * N + 2u]);
                }
            }
{

                if !gauss_seidel || (3u >= 3u * 0u && 3u < 3u * 0u + 3u) {
                    s += abs(w[1u * N + 3u]);
                }
            }
{

                if !gauss_seidel || (4u >= 3u * 0u && 4u < 3u * 0u + 3u) {
                    s += abs(w[1u * N + 4u]);
                }
            }
{

                if !gauss_seidel || (5u >= 3u * 0u && 5u < 3u * 0u + 3u) {
                    s += abs(w[1u * N + 5u]);
                }
            }
{

                if !gauss_seidel || (6u >= 3u * 0u && 6u < 3u * 0u + 3u) {
                    s += abs(w[1u * N + 6u]);
                }
            }
{

                if !gauss_seidel || (7u >= 3u * 0u && 7u < 3u * 0u + 3u) {
                    s += abs(w[1u * N + 7u]);
                }
            }
{

                if !gauss_seidel || (8u >= 3u * 0u && 8u < 3u * 0u + 3u) {
                    s += abs(w[1u * N + 8u]);
                }
            }
{

                if !gauss_seidel || (9u >= 3u * 0u && 9u < 3u * 0u + 3u) {
                    s += abs(w[1u * N + 9u]);
                }
            }
{

                if !gauss_seidel || (10u >= 3u * 0u && 10u < 3u * 0u + 3u) {
                    s += abs(w[1u * N + 10u]);
                }
            }
{

                if !gauss_seidel || (11u >= 3u * 0u && 11u < 3u * 0u + 3u) {
                    s += abs(w[1u * N + 11u]);
                }
            }

            big = max(big, s);
        }
{

            var s = Scalar(0.0);
{

                if !gauss_seidel || (0u >= 3u * 0u && 0u < 3u * 0u + 3u) {
                    s += abs(w[2u * N + 0u]);
                }
            }
{

                if !gauss_seidel || (1u >= 3u * 0u && 1u < 3u * 0u + 3u) {
                    s += abs(w[2u * N + 1u]);
                }
            }
{

                if !gauss_seidel || (2u >= 3u * 0u && 2u < 3u * 0u + 3u) {
                    s += abs(w[2u * N + 2u]);
                }
            }
{

                if !gauss_seidel || (3u >= 3u * 0u && 3u < 3u * 0u + 3u) {
                    s += abs(w[2u * N + 3u]);
                }
            }
{

                if !gauss_seidel || (4u >= 3u * 0u && 4u < 3u * 0u + 3u) {
                    s += abs(w[2u * N + 4u]);
                }
            }
{

                if !gauss_seidel || (5u >= 3u * 0u && 5u < 3u * 0u + 3u) {
                    s += abs(w[2u * N + 5u]);
                }
            }
{

                if !gauss_seidel || (6u >= 3u * 0u && 6u < 3u * 0u + 3u) {
                    s += abs(w[2u * N + 6u]);
                }
            }
{

                if !gauss_seidel || (7u >= 3u * 0u && 7u < 3u * 0u + 3u) {
                    s += abs(w[2u * N + 7u]);
                }
            }
{

                if !gauss_seidel || (8u >= 3u * 0u && 8u < 3u * 0u + 3u) {
                    s += abs(w[2u * N + 8u]);
                }
            }
{

                if !gauss_seidel || (9u >= 3u * 0u && 9u < 3u * 0u + 3u) {
                    s += abs(w[2u * N + 9u]);
                }
            }
{

                if !gauss_seidel || (10u >= 3u * 0u && 10u < 3u * 0u + 3u) {
                    s += abs(w[2u * N + 10u]);
                }
            }
{

                if !gauss_seidel || (11u >= 3u * 0u && 11u < 3u * 0u + 3u) {
                    s += abs(w[2u * N + 11u]);
                }
            }

            big = max(big, s);
        }

        var e = Scalar(1.0);
        if big > Scalar(0.0) {
            e = Scalar(1.0) / big;
        }
        eta[0u] = e;
    }
{

        var big = Scalar(0.0);
{

            var s = Scalar(0.0);
{

                if !gauss_seidel || (0u >= 3u * 1u && 0u < 3u * 1u + 3u) {
                    s += abs(w[3u * N + 0u]);
                }
            }
{

                if !gauss_seidel || (1u >= 3u * 1u && 1u < 3u * 1u + 3u) {
                    s += abs(w[3u * N + 1u]);
                }
            }
{

                if !gauss_seidel || (2u >= 3u * 1u && 2u < 3u * 1u + 3u) {
                    s += abs(w[3u * N + 2u]);
                }
            }
{

                if !gauss_seidel || (3u >= 3u * 1u && 3u < 3u * 1u + 3u) {
                    s += abs(w[3u * N + 3u]);
                }
            }
{

                if !gauss_seidel || (4u >= 3u * 1u && 4u < 3u * 1u + 3u) {
                    s += abs(w[3u * N + 4u]);
                }
            }
{

                if !gauss_seidel || (5u >= 3u * 1u && 5u < 3u * 1u + 3u) {
                    s += abs(w[3u * N + 5u]);
                }
            }
{

                if !gauss_seidel || (6u >= 3u * 1u && 6u < 3u * 1u + 3u) {
                    s += abs(w[3u * N + 6u]);
                }
            }
{

                if !gauss_seidel || (7u >= 3u * 1u && 7u < 3u * 1u + 3u) {
                    s += abs(w[3u * N + 7u]);
                }
            }
{

                if !gauss_seidel || (8u >= 3u * 1u && 8u < 3u * 1u + 3u) {
                    s += abs(w[3u * N + 8u]);
                }
            }
{

                if !gauss_seidel || (9u >= 3u * 1u && 9u < 3u * 1u + 3u) {
                    s += abs(w[3u * N + 9u]);
                }
            }
{

                if !gauss_seidel || (10u >= 3u * 1u && 10u < 3u * 1u + 3u) {
                    s += abs(w[3u * N + 10u]);
                }
            }
{

                if !gauss_seidel || (11u >= 3u * 1u && 11u < 3u * 1u + 3u) {
                    s += abs(w[3u * N + 11u]);
                }
            }

            big = max(big, s);
        }
{

            var s = Scalar(0.0);
{

                if !gauss_seidel || (0u >= 3u * 1u && 0u < 3u * 1u + 3u) {
                    s += abs(w[4u * N + 0u]);
                }
            }
{

                if !gauss_seidel || (1u >= 3u * 1u && 1u < 3u * 1u + 3u) {
                    s += abs(w[4u * N + 1u]);
                }
            }
{

                if !gauss_seidel || (2u >= 3u * 1u && 2u < 3u * 1u + 3u) {
                    s += abs(w[4u * N + 2u]);
                }
            }
{

                if !gauss_seidel || (3u >= 3u * 1u && 3u < 3u * 1u + 3u) {
                    s += abs(w[4u * N + 3u]);
                }
            }
{

                if !gauss_seidel || (4u >= 3u * 1u && 4u < 3u * 1u + 3u) {
                    s += abs(w[4u * N + 4u]);
                }
            }
{

                if !gauss_seidel || (5u >= 3u * 1u && 5u < 3u * 1u + 3u) {
                    s += abs(w[4u * N + 5u]);
                }
            }
{

                if !gauss_seidel || (6u >= 3u * 1u && 6u < 3u * 1u + 3u) {
                    s += abs(w[4u * N + 6u]);
                }
            }
{

                if !gauss_seidel || (7u >= 3u * 1u && 7u < 3u * 1u + 3u) {
                    s += abs(w[4u * N + 7u]);
                }
            }
{

                if !gauss_seidel || (8u >= 3u * 1u && 8u < 3u * 1u + 3u) {
                    s += abs(w[4u * N + 8u]);
                }
            }
{

                if !gauss_seidel || (9u >= 3u * 1u && 9u < 3u * 1u + 3u) {
                    s += abs(w[4u * N + 9u]);
                }
            }
{

                if !gauss_seidel || (10u >= 3u * 1u && 10u < 3u * 1u + 3u) {
                    s += abs(w[4u * N + 10u]);
                }
            }
{

                if !gauss_seidel || (11u >= 3u * 1u && 11u < 3u * 1u + 3u) {
                    s += abs(w[4u * N + 11u]);
                }
            }

            big = max(big, s);
        }
{

            var s = Scalar(0.0);
{

                if !gauss_seidel || (0u >= 3u * 1u && 0u < 3u * 1u + 3u) {
                    s += abs(w[5u * N + 0u]);
                }
            }
{

                if !gauss_seidel || (1u >= 3u * 1u && 1u < 3u * 1u + 3u) {
                    s += abs(w[5u * N + 1u]);
                }
            }
{

                if !gauss_seidel || (2u >= 3u * 1u && 2u < 3u * 1u + 3u) {
                    s += abs(w[5u * N + 2u]);
                }
            }
{

                if !gauss_seidel || (3u >= 3u * 1u && 3u < 3u * 1u + 3u) {
                    s += abs(w[5u * N + 3u]);
                }
            }
{

                if !gauss_seidel || (4u >= 3u * 1u && 4u < 3u * 1u + 3u) {
                    s += abs(w[5u * N + 4u]);
                }
            }
{

                if !gauss_seidel || (5u >= 3u * 1u && 5u < 3u * 1u + 3u) {
                    s += abs(w[5u * N + 5u]);
                }
            }
{

                if !gauss_seidel || (6u >= 3u * 1u && 6u < 3u * 1u + 3u) {
                    s += abs(w[5u * N + 6u]);
                }
            }
{

                if !gauss_seidel || (7u >= 3u * 1u && 7u < 3u * 1u + 3u) {
                    s += abs(w[5u * N + 7u]);
                }
            }
{

                if !gauss_seidel || (8u >= 3u * 1u && 8u < 3u * 1u + 3u) {
                    s += abs(w[5u * N + 8u]);
                }
            }
{

                if !gauss_seidel || (9u >= 3u * 1u && 9u < 3u * 1u + 3u) {
                    s += abs(w[5u * N + 9u]);
                }
            }
{

                if !gauss_seidel || (10u >= 3u * 1u && 10u < 3u * 1u + 3u) {
                    s += abs(w[5u * N + 10u]);
                }
            }
{

                if !gauss_seidel || (11u >= 3u * 1u && 11u < 3u * 1u + 3u) {
                    s += abs(w[5u * N + 11u]);
                }
            }

            big = max(big, s);
        }

        var e = Scalar(1.0);
        if big > Scalar(0.0) {
            e = Scalar(1.0) / big;
        }
        eta[1u] = e;
    }
{

        var big = Scalar(0.0);
{

            var s = Scalar(0.0);
{

                if !gauss_seidel || (0u >= 3u * 2u && 0u < 3u * 2u + 3u) {
                    s += abs(w[6u * N + 0u]);
                }
            }
{

                if !gauss_seidel || (1u >= 3u * 2u && 1u < 3u * 2u + 3u) {
                    s += abs(w[6u * N + 1u]);
                }
            }
{

                if !gauss_seidel || (2u >= 3u * 2u && 2u < 3u * 2u + 3u) {
                    s += abs(w[6u * N + 2u]);
                }
            }
{

                if !gauss_seidel || (3u >= 3u * 2u && 3u < 3u * 2u + 3u) {
                    s += abs(w[6u * N + 3u]);
                }
            }
{

                if !gauss_seidel || (4u >= 3u * 2u && 4u < 3u * 2u + 3u) {
                    s += abs(w[6u * N + 4u]);
                }
            }
{

                if !gauss_seidel || (5u >= 3u * 2u && 5u < 3u * 2u + 3u) {
                    s += abs(w[6u * N + 5u]);
                }
            }
{

                if !gauss_seidel || (6u >= 3u * 2u && 6u < 3u * 2u + 3u) {
                    s += abs(w[6u * N + 6u]);
                }
            }
{

                if !gauss_seidel || (7u >= 3u * 2u && 7u < 3u * 2u + 3u) {
                    s += abs(w[6u * N + 7u]);
                }
            }
{

                if !gauss_seidel || (8u >= 3u * 2u && 8u < 3u * 2u + 3u) {
                    s += abs(w[6u * N + 8u]);
                }
            }
{

                if !gauss_seidel || (9u >= 3u * 2u && 9u < 3u * 2u + 3u) {
                    s += abs(w[6u * N + 9u]);
                }
            }
{

                if !gauss_seidel || (10u >= 3u * 2u && 10u < 3u * 2u + 3u) {
                    s += abs(w[6u * N + 10u]);
                }
            }
{

                if !gauss_seidel || (11u >= 3u * 2u && 11u < 3u * 2u + 3u) {
                    s += abs(w[6u * N + 11u]);
                }
            }

            big = max(big, s);
        }
{

            var s = Scalar(0.0);
{

                if !gauss_seidel || (0u >= 3u * 2u && 0u < 3u * 2u + 3u) {
                    s += abs(w[7u * N + 0u]);
                }
            }
{

                if !gauss_seidel || (1u >= 3u * 2u && 1u < 3u * 2u + 3u) {
                    s += abs(w[7u * N + 1u]);
                }
            }
{

                if !gauss_seidel || (2u >= 3u * 2u && 2u < 3u * 2u + 3u) {
                    s += abs(w[7u * N + 2u]);
                }
            }
{

                if !gauss_seidel || (3u >= 3u * 2u && 3u < 3u * 2u + 3u) {
                    s += abs(w[7u * N + 3u]);
                }
            }
{

                if !gauss_seidel || (4u >= 3u * 2u && 4u < 3u * 2u + 3u) {
                    s += abs(w[7u * N + 4u]);
                }
            }
{

                if !gauss_seidel || (5u >= 3u * 2u && 5u < 3u * 2u + 3u) {
                    s += abs(w[7u * N + 5u]);
                }
            }
{

                if !gauss_seidel || (6u >= 3u * 2u && 6u < 3u * 2u + 3u) {
                    s += abs(w[7u * N + 6u]);
                }
            }
{

                if !gauss_seidel || (7u >= 3u * 2u && 7u < 3u * 2u + 3u) {
                    s += abs(w[7u * N + 7u]);
                }
            }
{

                if !gauss_seidel || (8u >= 3u * 2u && 8u < 3u * 2u + 3u) {
                    s += abs(w[7u * N + 8u]);
                }
            }
{

                if !gauss_seidel || (9u >= 3u * 2u && 9u < 3u * 2u + 3u) {
                    s += abs(w[7u * N + 9u]);
                }
            }
{

                if !gauss_seidel || (10u >= 3u * 2u && 10u < 3u * 2u + 3u) {
                    s += abs(w[7u * N + 10u]);
                }
            }
{

                if !gauss_seidel || (11u >= 3u * 2u && 11u < 3u * 2u + 3u) {
                    s += abs(w[7u * N + 11u]);
                }
            }

            big = max(big, s);
        }
{

            var s = Scalar(0.0);
{

                if !gauss_seidel || (0u >= 3u * 2u && 0u < 3u * 2u + 3u) {
                    s += abs(w[8u * N + 0u]);
                }
            }
{

                if !gauss_seidel || (1u >= 3u * 2u && 1u < 3u * 2u + 3u) {
                    s += abs(w[8u * N + 1u]);
                }
            }
{

                if !gauss_seidel || (2u >= 3u * 2u && 2u < 3u * 2u + 3u) {
                    s += abs(w[8u * N + 2u]);
                }
            }
{

                if !gauss_seidel || (3u >= 3u * 2u && 3u < 3u * 2u + 3u) {
                    s += abs(w[8u * N + 3u]);
                }
            }
{

                if !gauss_seidel || (4u >= 3u * 2u && 4u < 3u * 2u + 3u) {
                    s += abs(w[8u * N + 4u]);
                }
            }
{

                if !gauss_seidel || (5u >= 3u * 2u && 5u < 3u * 2u + 3u) {
                    s += abs(w[8u * N + 5u]);
                }
            }
{

                if !gauss_seidel || (6u >= 3u * 2u && 6u < 3u * 2u + 3u) {
                    s += abs(w[8u * N + 6u]);
                }
            }
{

                if !gauss_seidel || (7u >= 3u * 2u && 7u < 3u * 2u + 3u) {
                    s += abs(w[8u * N + 7u]);
                }
            }
{

                if !gauss_seidel || (8u >= 3u * 2u && 8u < 3u * 2u + 3u) {
                    s += abs(w[8u * N + 8u]);
                }
            }
{

                if !gauss_seidel || (9u >= 3u * 2u && 9u < 3u * 2u + 3u) {
                    s += abs(w[8u * N + 9u]);
                }
            }
{

                if !gauss_seidel || (10u >= 3u * 2u && 10u < 3u * 2u + 3u) {
                    s += abs(w[8u * N + 10u]);
                }
            }
{

                if !gauss_seidel || (11u >= 3u * 2u && 11u < 3u * 2u + 3u) {
                    s += abs(w[8u * N + 11u]);
                }
            }

            big = max(big, s);
        }

        var e = Scalar(1.0);
        if big > Scalar(0.0) {
            e = Scalar(1.0) / big;
        }
        eta[2u] = e;
    }
{

        var big = Scalar(0.0);
{

            var s = Scalar(0.0);
{

                if !gauss_seidel || (0u >= 3u * 3u && 0u < 3u * 3u + 3u) {
                    s += abs(w[9u * N + 0u]);
                }
            }
{

                if !gauss_seidel || (1u >= 3u * 3u && 1u < 3u * 3u + 3u) {
                    s += abs(w[9u * N + 1u]);
                }
            }
{

                if !gauss_seidel || (2u >= 3u * 3u && 2u < 3u * 3u + 3u) {
                    s += abs(w[9u * N + 2u]);
                }
            }
{

                if !gauss_seidel || (3u >= 3u * 3u && 3u < 3u * 3u + 3u) {
                    s += abs(w[9u * N + 3u]);
                }
            }
{

                if !gauss_seidel || (4u >= 3u * 3u && 4u < 3u * 3u + 3u) {
                    s += abs(w[9u * N + 4u]);
                }
            }
{

                if !gauss_seidel || (5u >= 3u * 3u && 5u < 3u * 3u + 3u) {
                    s += abs(w[9u * N + 5u]);
                }
            }
{

                if !gauss_seidel || (6u >= 3u * 3u && 6u < 3u * 3u + 3u) {
                    s += abs(w[9u * N + 6u]);
                }
            }
{

                if !gauss_seidel || (7u >= 3u * 3u && 7u < 3u * 3u + 3u) {
                    s += abs(w[9u * N + 7u]);
                }
            }
{

                if !gauss_seidel || (8u >= 3u * 3u && 8u < 3u * 3u + 3u) {
                    s += abs(w[9u * N + 8u]);
                }
            }
{

                if !gauss_seidel || (9u >= 3u * 3u && 9u < 3u * 3u + 3u) {
                    s += abs(w[9u * N + 9u]);
                }
            }
{

                if !gauss_seidel || (10u >= 3u * 3u && 10u < 3u * 3u + 3u) {
                    s += abs(w[9u * N + 10u]);
                }
            }
{

                if !gauss_seidel || (11u >= 3u * 3u && 11u < 3u * 3u + 3u) {
                    s += abs(w[9u * N + 11u]);
                }
            }

            big = max(big, s);
        }
{

            var s = Scalar(0.0);
{

                if !gauss_seidel || (0u >= 3u * 3u && 0u < 3u * 3u + 3u) {
                    s += abs(w[10u * N + 0u]);
                }
            }
{

                if !gauss_seidel || (1u >= 3u * 3u && 1u < 3u * 3u + 3u) {
                    s += abs(w[10u * N + 1u]);
                }
            }
{

                if !gauss_seidel || (2u >= 3u * 3u && 2u < 3u * 3u + 3u) {
                    s += abs(w[10u * N + 2u]);
                }
            }
{

                if !gauss_seidel || (3u >= 3u * 3u && 3u < 3u * 3u + 3u) {
                    s += abs(w[10u * N + 3u]);
                }
            }
{

                if !gauss_seidel || (4u >= 3u * 3u && 4u < 3u * 3u + 3u) {
                    s += abs(w[10u * N + 4u]);
                }
            }
{

                if !gauss_seidel || (5u >= 3u * 3u && 5u < 3u * 3u + 3u) {
                    s += abs(w[10u * N + 5u]);
                }
            }
{

                if !gauss_seidel || (6u >= 3u * 3u && 6u < 3u * 3u + 3u) {
                    s += abs(w[10u * N + 6u]);
                }
            }
{

                if !gauss_seidel || (7u >= 3u * 3u && 7u < 3u * 3u + 3u) {
                    s += abs(w[10u * N + 7u]);
                }
            }
{

                if !gauss_seidel || (8u >= 3u * 3u && 8u < 3u * 3u + 3u) {
                    s += abs(w[10u * N + 8u]);
                }
            }
{

                if !gauss_seidel || (9u >= 3u * 3u && 9u < 3u * 3u + 3u) {
                    s += abs(w[10u * N + 9u]);
                }
            }
{

                if !gauss_seidel || (10u >= 3u * 3u && 10u < 3u * 3u + 3u) {
                    s += abs(w[10u * N + 10u]);
                }
            }
{

                if !gauss_seidel || (11u >= 3u * 3u && 11u < 3u * 3u + 3u) {
                    s += abs(w[10u * N + 11u]);
                }
            }

            big = max(big, s);
        }
{

            var s = Scalar(0.0);
{

                if !gauss_seidel || (0u >= 3u * 3u && 0u < 3u * 3u + 3u) {
                    s += abs(w[11u * N + 0u]);
                }
            }
{

                if !gauss_seidel || (1u >= 3u * 3u && 1u < 3u * 3u + 3u) {
                    s += abs(w[11u * N + 1u]);
                }
            }
{

                if !gauss_seidel || (2u >= 3u * 3u && 2u < 3u * 3u + 3u) {
                    s += abs(w[11u * N + 2u]);
                }
            }
{

                if !gauss_seidel || (3u >= 3u * 3u && 3u < 3u * 3u + 3u) {
                    s += abs(w[11u * N + 3u]);
                }
            }
{

                if !gauss_seidel || (4u >= 3u * 3u && 4u < 3u * 3u + 3u) {
                    s += abs(w[11u * N + 4u]);
                }
            }
{

                if !gauss_seidel || (5u >= 3u * 3u && 5u < 3u * 3u + 3u) {
                    s += abs(w[11u * N + 5u]);
                }
            }
{

                if !gauss_seidel || (6u >= 3u * 3u && 6u < 3u * 3u + 3u) {
                    s += abs(w[11u * N + 6u]);
                }
            }
{

                if !gauss_seidel || (7u >= 3u * 3u && 7u < 3u * 3u + 3u) {
                    s += abs(w[11u * N + 7u]);
                }
            }
{

                if !gauss_seidel || (8u >= 3u * 3u && 8u < 3u * 3u + 3u) {
                    s += abs(w[11u * N + 8u]);
                }
            }
{

                if !gauss_seidel || (9u >= 3u * 3u && 9u < 3u * 3u + 3u) {
                    s += abs(w[11u * N + 9u]);
                }
            }
{

                if !gauss_seidel || (10u >= 3u * 3u && 10u < 3u * 3u + 3u) {
                    s += abs(w[11u * N + 10u]);
                }
            }
{

                if !gauss_seidel || (11u >= 3u * 3u && 11u < 3u * 3u + 3u) {
                    s += abs(w[11u * N + 11u]);
                }
            }

            big = max(big, s);
        }

        var e = Scalar(1.0);
        if big > Scalar(0.0) {
            e = Scalar(1.0) / big;
        }
        eta[3u] = e;
    }

}

// One sweep over the contacts from u = un (Gauss-Seidel: each contact's
// velocity recomputed from the reactions updated so far).
fn sweep(gauss_seidel: bool) {
{

        let c = 3u * 0u;
        if gauss_seidel {
{

                un[0u] = velocity_row(0u);
            }
{

                un[1u] = velocity_row(1u);
            }
{

                un[2u] = velocity_row(2u);
            }

        }
        let h = controls.relaxation * eta[0u];
        let p = project_on_cone(
            vec3<Scalar>(x[c] - h * un[c], x[c + 1u] - h * un[c + 1u], x[c + 2u] - h * un[c + 2u]),
            mu[0u]
        );
        x[c] = p.x;
        x[c + 1u] = p.y;
        x[c + 2u] = p.z;
    }
{

        let c = 3u * 1u;
        if gauss_seidel {
{

                un[3u] = velocity_row(3u);
            }
{

                un[4u] = velocity_row(4u);
            }
{

                un[5u] = velocity_row(5u);
            }

        }
        let h = controls.relaxation * eta[1u];
        let p = project_on_cone(
            vec3<Scalar>(x[c] - h * un[c], x[c + 1u] - h * un[c + 1u], x[c + 2u] - h * un[c + 2u]),
            mu[1u]
        );
        x[c] = p.x;
        x[c + 1u] = p.y;
        x[c + 2u] = p.z;
    }
{

        let c = 3u * 2u;
        if gauss_seidel {
{

                un[6u] = velocity_row(6u);
            }
{

                un[7u] = velocity_row(7u);
            }
{

                un[8u] = velocity_row(8u);
            }

        }
        let h = controls.relaxation * eta[2u];
        let p = project_on_cone(
            vec3<Scalar>(x[c] - h * un[c], x[c + 1u] - h * un[c + 1u], x[c + 2u] - h * un[c + 2u]),
            mu[2u]
        );
        x[c] = p.x;
        x[c + 1u] = p.y;
        x[c + 2u] = p.z;
    }
{

        let c = 3u * 3u;
        if gauss_seidel {
{

                un[9u] = velocity_row(9u);
            }
{

                un[10u] = velocity_row(10u);
            }
{

                un[11u] = velocity_row(11u);
            }

        }
        let h = controls.relaxation * eta[3u];
        let p = project_on_cone(
            vec3<Scalar>(x[c] - h * un[c], x[c + 1u] - h * un[c + 1u], x[c + 2u] - h * un[c + 2u]),
            mu[3u]
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
{

        if 0u < stored {
            vectors[v + 0u] = vec4<Scalar>(
                get_vector(4u * 0u, false),
                get_vector(4u * 0u + 1u, false),
                get_vector(4u * 0u + 2u, false),
                get_vector(4u * 0u + 3u, false)
            );
        }
    }
{

        if 1u < stored {
            vectors[v + 1u] = vec4<Scalar>(
                get_vector(4u * 1u, false),
                get_vector(4u * 1u + 1u, false),
                get_vector(4u * 1u + 2u, false),
                get_vector(4u * 1u + 3u, false)
            );
        }
    }
{

        if 2u < stored {
            vectors[v + 2u] = vec4<Scalar>(
                get_vector(4u * 2u, false),
                get_vector(4u * 2u + 1u, false),
                get_vector(4u * 2u + 2u, false),
                get_vector(4u * 2u + 3u, false)
            );
        }
    }
{

        if 3u < stored {
            vectors[v + 3u] = vec4<Scalar>(
                get_vector(4u * 3u, false),
                get_vector(4u * 3u + 1u, false),
                get_vector(4u * 3u + 2u, false),
                get_vector(4u * 3u + 3u, false)
            );
        }
    }

    finish_round(index, st);
}

// Writes APGD's vectors back to `vectors` from v (in vec4s).
fn store_apgd(v: u32) {
{

        vectors[v + 0u] = vec4<Scalar>(
            get_vector(4u * 0u, true),
            get_vector(4u * 0u + 1u, true),
            get_vector(4u * 0u + 2u, true),
            get_vector(4u * 0u + 3u, true)
        );
    }
{

        vectors[v + 1u] = vec4<Scalar>(
            get_vector(4u * 1u, true),
            get_vector(4u * 1u + 1u, true),
            get_vector(4u * 1u + 2u, true),
            get_vector(4u * 1u + 3u, true)
        );
    }
{

        vectors[v + 2u] = vec4<Scalar>(
            get_vector(4u * 2u, true),
            get_vector(4u * 2u + 1u, true),
            get_vector(4u * 2u + 2u, true),
            get_vector(4u * 2u + 3u, true)
        );
    }
{

        vectors[v + 3u] = vec4<Scalar>(
            get_vector(4u * 3u, true),
            get_vector(4u * 3u + 1u, true),
            get_vector(4u * 3u + 2u, true),
            get_vector(4u * 3u + 3u, true)
        );
    }
{

        vectors[v + 4u] = vec4<Scalar>(
            get_vector(4u * 4u, true),
            get_vector(4u * 4u + 1u, true),
            get_vector(4u * 4u + 2u, true),
            get_vector(4u * 4u + 3u, true)
        );
    }
{

        vectors[v + 5u] = vec4<Scalar>(
            get_vector(4u * 5u, true),
            get_vector(4u * 5u + 1u, true),
            get_vector(4u * 5u + 2u, true),
            get_vector(4u * 5u + 3u, true)
        );
    }
{

        vectors[v + 6u] = vec4<Scalar>(
            get_vector(4u * 6u, true),
            get_vector(4u * 6u + 1u, true),
            get_vector(4u * 6u + 2u, true),
            get_vector(4u * 6u + 3u, true)
        );
    }
{

        vectors[v + 7u] = vec4<Scalar>(
            get_vector(4u * 7u, true),
            get_vector(4u * 7u + 1u, true),
            get_vector(4u * 7u + 2u, true),
            get_vector(4u * 7u + 3u, true)
        );
    }
{

        vectors[v + 8u] = vec4<Scalar>(
            get_vector(4u * 8u, true),
            get_vector(4u * 8u + 1u, true),
            get_vector(4u * 8u + 2u, true),
            get_vector(4u * 8u + 3u, true)
        );
    }
{

        vectors[v + 9u] = vec4<Scalar>(
            get_vector(4u * 9u, true),
            get_vector(4u * 9u + 1u, true),
            get_vector(4u * 9u + 2u, true),
            get_vector(4u * 9u + 3u, true)
        );
    }
{

        vectors[v + 10u] = vec4<Scalar>(
            get_vector(4u * 10u, true),
            get_vector(4u * 10u + 1u, true),
            get_vector(4u * 10u + 2u, true),
            get_vector(4u * 10u + 3u, true)
        );
    }
{

        vectors[v + 11u] = vec4<Scalar>(
            get_vector(4u * 11u, true),
            get_vector(4u * 11u + 1u, true),
            get_vector(4u * 11u + 2u, true),
            get_vector(4u * 11u + 3u, true)
        );
    }
{

        vectors[v + 12u] = vec4<Scalar>(
            get_vector(4u * 12u, true),
            get_vector(4u * 12u + 1u, true),
            get_vector(4u * 12u + 2u, true),
            get_vector(4u * 12u + 3u, true)
        );
    }
{

        vectors[v + 13u] = vec4<Scalar>(
            get_vector(4u * 13u, true),
            get_vector(4u * 13u + 1u, true),
            get_vector(4u * 13u + 2u, true),
            get_vector(4u * 13u + 3u, true)
        );
    }
{

        vectors[v + 14u] = vec4<Scalar>(
            get_vector(4u * 14u, true),
            get_vector(4u * 14u + 1u, true),
            get_vector(4u * 14u + 2u, true),
            get_vector(4u * 14u + 3u, true)
        );
    }

}

// Writes APGD's best iterate alone (the answer the host reads, from 4N:
// a multiple of 4 scalars) from v: an island that is done needs nothing
// else, and llvmpipe turns every vec4 store at a per-island address into a
// loop over the SIMD lanes (15 of them at k = 4 for all the vectors).
fn store_best(v: u32) {
{

        vectors[v + N + 0u] = vec4<Scalar>(
            get_vector(4u * N + 4u * 0u, true),
            get_vector(4u * N + 4u * 0u + 1u, true),
            get_vector(4u * N + 4u * 0u + 2u, true),
            get_vector(4u * N + 4u * 0u + 3u, true)
        );
    }
{

        vectors[v + N + 1u] = vec4<Scalar>(
            get_vector(4u * N + 4u * 1u, true),
            get_vector(4u * N + 4u * 1u + 1u, true),
            get_vector(4u * N + 4u * 1u + 2u, true),
            get_vector(4u * N + 4u * 1u + 3u, true)
        );
    }
{

        vectors[v + N + 2u] = vec4<Scalar>(
            get_vector(4u * N + 4u * 2u, true),
            get_vector(4u * N + 4u * 2u + 1u, true),
            get_vector(4u * N + 4u * 2u + 2u, true),
            get_vector(4u * N + 4u * 2u + 3u, true)
        );
    }

}

// ||W e|| / ||e|| for e = (1, ..., 1), else the largest |W_rr|, else 1.
fn first_lipschitz() -> Scalar {
    var s2 = Scalar(0.0);
{

        var s = Scalar(0.0);
{

            s += w[0u * N + 0u];
        }
{

            s += w[0u * N + 1u];
        }
{

            s += w[0u * N + 2u];
        }
{

            s += w[0u * N + 3u];
        }
{

            s += w[0u * N + 4u];
        }
{

            s += w[0u * N + 5u];
        }
{

            s += w[0u * N + 6u];
        }
{

            s += w[0u * N + 7u];
        }
{

            s += w[0u * N + 8u];
        }
{

            s += w[0u * N + 9u];
        }
{

            s += w[0u * N + 10u];
        }
{

            s += w[0u * N + 11u];
        }

        s2 += s * s;
    }
{

        var s = Scalar(0.0);
{

            s += w[1u * N + 0u];
        }
{

            s += w[1u * N + 1u];
        }
{

            s += w[1u * N + 2u];
        }
{

            s += w[1u * N + 3u];
        }
{

            s += w[1u * N + 4u];
        }
{

            s += w[1u * N + 5u];
        }
{

            s += w[1u * N + 6u];
        }
{

            s += w[1u * N + 7u];
        }
{

            s += w[1u * N + 8u];
        }
{

            s += w[1u * N + 9u];
        }
{

            s += w[1u * N + 10u];
        }
{

            s += w[1u * N + 11u];
        }

        s2 += s * s;
    }
{

        var s = Scalar(0.0);
{

            s += w[2u * N + 0u];
        }
{

            s += w[2u * N + 1u];
        }
{

            s += w[2u * N + 2u];
        }
{

            s += w[2u * N + 3u];
        }
{

            s += w[2u * N + 4u];
        }
{

            s += w[2u * N + 5u];
        }
{

            s += w[2u * N + 6u];
        }
{

            s += w[2u * N + 7u];
        }
{

            s += w[2u * N + 8u];
        }
{

            s += w[2u * N + 9u];
        }
{

            s += w[2u * N + 10u];
        }
{

            s += w[2u * N + 11u];
        }

        s2 += s * s;
    }
{

        var s = Scalar(0.0);
{

            s += w[3u * N + 0u];
        }
{

            s += w[3u * N + 1u];
        }
{

            s += w[3u * N + 2u];
        }
{

            s += w[3u * N + 3u];
        }
{

            s += w[3u * N + 4u];
        }
{

            s += w[3u * N + 5u];
        }
{

            s += w[3u * N + 6u];
        }
{

            s += w[3u * N + 7u];
        }
{

            s += w[3u * N + 8u];
        }
{

            s += w[3u * N + 9u];
        }
{

            s += w[3u * N + 10u];
        }
{

            s += w[3u * N + 11u];
        }

        s2 += s * s;
    }
{

        var s = Scalar(0.0);
{

            s += w[4u * N + 0u];
        }
{

            s += w[4u * N + 1u];
        }
{

            s += w[4u * N + 2u];
        }
{

            s += w[4u * N + 3u];
        }
{

            s += w[4u * N + 4u];
        }
{

            s += w[4u * N + 5u];
        }
{

            s += w[4u * N + 6u];
        }
{

            s += w[4u * N + 7u];
        }
{

            s += w[4u * N + 8u];
        }
{

            s += w[4u * N + 9u];
        }
{

            s += w[4u * N + 10u];
        }
{

            s += w[4u * N + 11u];
        }

        s2 += s * s;
    }
{

        var s = Scalar(0.0);
{

            s += w[5u * N + 0u];
        }
{

            s += w[5u * N + 1u];
        }
{

            s += w[5u * N + 2u];
        }
{

            s += w[5u * N + 3u];
        }
{

            s += w[5u * N + 4u];
        }
{

            s += w[5u * N + 5u];
        }
{

            s += w[5u * N + 6u];
        }
{

            s += w[5u * N + 7u];
        }
{

            s += w[5u * N + 8u];
        }
{

            s += w[5u * N + 9u];
        }
{

            s += w[5u * N + 10u];
        }
{

            s += w[5u * N + 11u];
        }

        s2 += s * s;
    }
{

        var s = Scalar(0.0);
{

            s += w[6u * N + 0u];
        }
{

            s += w[6u * N + 1u];
        }
{

            s += w[6u * N + 2u];
        }
{

            s += w[6u * N + 3u];
        }
{

            s += w[6u * N + 4u];
        }
{

            s += w[6u * N + 5u];
        }
{

            s += w[6u * N + 6u];
        }
{

            s += w[6u * N + 7u];
        }
{

            s += w[6u * N + 8u];
        }
{

            s += w[6u * N + 9u];
        }
{

            s += w[6u * N + 10u];
        }
{

            s += w[6u * N + 11u];
        }

        s2 += s * s;
    }
{

        var s = Scalar(0.0);
{

            s += w[7u * N + 0u];
        }
{

            s += w[7u * N + 1u];
        }
{

            s += w[7u * N + 2u];
        }
{

            s += w[7u * N + 3u];
        }
{

            s += w[7u * N + 4u];
        }
{

            s += w[7u * N + 5u];
        }
{

            s += w[7u * N + 6u];
        }
{

            s += w[7u * N + 7u];
        }
{

            s += w[7u * N + 8u];
        }
{

            s += w[7u * N + 9u];
        }
{

            s += w[7u * N + 10u];
        }
{

            s += w[7u * N + 11u];
        }

        s2 += s * s;
    }
{

        var s = Scalar(0.0);
{

            s += w[8u * N + 0u];
        }
{

            s += w[8u * N + 1u];
        }
{

            s += w[8u * N + 2u];
        }
{

            s += w[8u * N + 3u];
        }
{

            s += w[8u * N + 4u];
        }
{

            s += w[8u * N + 5u];
        }
{

            s += w[8u * N + 6u];
        }
{

            s += w[8u * N + 7u];
        }
{

            s += w[8u * N + 8u];
        }
{

            s += w[8u * N + 9u];
        }
{

            s += w[8u * N + 10u];
        }
{

            s += w[8u * N + 11u];
        }

        s2 += s * s;
    }
{

        var s = Scalar(0.0);
{

            s += w[9u * N + 0u];
        }
{

            s += w[9u * N + 1u];
        }
{

            s += w[9u * N + 2u];
        }
{

            s += w[9u * N + 3u];
        }
{

            s += w[9u * N + 4u];
        }
{

            s += w[9u * N + 5u];
        }
{

            s += w[9u * N + 6u];
        }
{

            s += w[9u * N + 7u];
        }
{

            s += w[9u * N + 8u];
        }
{

            s += w[9u * N + 9u];
        }
{

            s += w[9u * N + 10u];
        }
{

            s += w[9u * N + 11u];
        }

        s2 += s * s;
    }
{

        var s = Scalar(0.0);
{

            s += w[10u * N + 0u];
        }
{

            s += w[10u * N + 1u];
        }
{

            s += w[10u * N + 2u];
        }
{

            s += w[10u * N + 3u];
        }
{

            s += w[10u * N + 4u];
        }
{

            s += w[10u * N + 5u];
        }
{

            s += w[10u * N + 6u];
        }
{

            s += w[10u * N + 7u];
        }
{

            s += w[10u * N + 8u];
        }
{

            s += w[10u * N + 9u];
        }
{

            s += w[10u * N + 10u];
        }
{

            s += w[10u * N + 11u];
        }

        s2 += s * s;
    }
{

        var s = Scalar(0.0);
{

            s += w[11u * N + 0u];
        }
{

            s += w[11u * N + 1u];
        }
{

            s += w[11u * N + 2u];
        }
{

            s += w[11u * N + 3u];
        }
{

            s += w[11u * N + 4u];
        }
{

            s += w[11u * N + 5u];
        }
{

            s += w[11u * N + 6u];
        }
{

            s += w[11u * N + 7u];
        }
{

            s += w[11u * N + 8u];
        }
{

            s += w[11u * N + 9u];
        }
{

            s += w[11u * N + 10u];
        }
{

            s += w[11u * N + 11u];
        }

        s2 += s * s;
    }

    let l = sqrt(s2 / Scalar(N));
    if l > Scalar(0.0) && finite(l) {
        return l;
    }
    var d = Scalar(0.0);
{

        d = max(d, abs(w[0u * N + 0u]));
    }
{

        d = max(d, abs(w[1u * N + 1u]));
    }
{

        d = max(d, abs(w[2u * N + 2u]));
    }
{

        d = max(d, abs(w[3u * N + 3u]));
    }
{

        d = max(d, abs(w[4u * N + 4u]));
    }
{

        d = max(d, abs(w[5u * N + 5u]));
    }
{

        d = max(d, abs(w[6u * N + 6u]));
    }
{

        d = max(d, abs(w[7u * N + 7u]));
    }
{

        d = max(d, abs(w[8u * N + 8u]));
    }
{

        d = max(d, abs(w[9u * N + 9u]));
    }
{

        d = max(d, abs(w[10u * N + 10u]));
    }
{

        d = max(d, abs(w[11u * N + 11u]));
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
{

        let c = 3u * 0u;
        let p = project_on_cone(
            vec3<Scalar>(y[c] - t * uy[c], y[c + 1u] - t * uy[c + 1u], y[c + 2u] - t * uy[c + 2u]),
            mu[0u]
        );
        xn[c] = p.x;
        xn[c + 1u] = p.y;
        xn[c + 2u] = p.z;
    }
{

        let c = 3u * 1u;
        let p = project_on_cone(
            vec3<Scalar>(y[c] - t * uy[c], y[c + 1u] - t * uy[c + 1u], y[c + 2u] - t * uy[c + 2u]),
            mu[1u]
        );
        xn[c] = p.x;
        xn[c + 1u] = p.y;
        xn[c + 2u] = p.z;
    }
{

        let c = 3u * 2u;
        let p = project_on_cone(
            vec3<Scalar>(y[c] - t * uy[c], y[c + 1u] - t * uy[c + 1u], y[c + 2u] - t * uy[c + 2u]),
            mu[2u]
        );
        xn[c] = p.x;
        xn[c + 1u] = p.y;
        xn[c + 2u] = p.z;
    }
{

        let c = 3u * 3u;
        let p = project_on_cone(
            vec3<Scalar>(y[c] - t * uy[c], y[c + 1u] - t * uy[c + 1u], y[c + 2u] - t * uy[c + 2u]),
            mu[3u]
        );
        xn[c] = p.x;
        xn[c + 1u] = p.y;
        xn[c + 2u] = p.z;
    }

    velocity_of_trial();
    var curvature = Scalar(0.0);
    var d2 = Scalar(0.0);
    var g2 = Scalar(0.0);
{

        let d = xn[0u] - y[0u];
        curvature += d * (un[0u] - uy[0u]);
        d2 += d * d;
        g2 += uy[0u] * uy[0u];
    }
{

        let d = xn[1u] - y[1u];
        curvature += d * (un[1u] - uy[1u]);
        d2 += d * d;
        g2 += uy[1u] * uy[1u];
    }
{

        let d = xn[2u] - y[2u];
        curvature += d * (un[2u] - uy[2u]);
        d2 += d * d;
        g2 += uy[2u] * uy[2u];
    }
{

        let d = xn[3u] - y[3u];
        curvature += d * (un[3u] - uy[3u]);
        d2 += d * d;
        g2 += uy[3u] * uy[3u];
    }
{

        let d = xn[4u] - y[4u];
        curvature += d * (un[4u] - uy[4u]);
        d2 += d * d;
        g2 += uy[4u] * uy[4u];
    }
{

        let d = xn[5u] - y[5u];
        curvature += d * (un[5u] - uy[5u]);
        d2 += d * d;
        g2 += uy[5u] * uy[5u];
    }
{

        let d = xn[6u] - y[6u];
        curvature += d * (un[6u] - uy[6u]);
        d2 += d * d;
        g2 += uy[6u] * uy[6u];
    }
{

        let d = xn[7u] - y[7u];
        curvature += d * (un[7u] - uy[7u]);
        d2 += d * d;
        g2 += uy[7u] * uy[7u];
    }
{

        let d = xn[8u] - y[8u];
        curvature += d * (un[8u] - uy[8u]);
        d2 += d * d;
        g2 += uy[8u] * uy[8u];
    }
{

        let d = xn[9u] - y[9u];
        curvature += d * (un[9u] - uy[9u]);
        d2 += d * d;
        g2 += uy[9u] * uy[9u];
    }
{

        let d = xn[10u] - y[10u];
        curvature += d * (un[10u] - uy[10u]);
        d2 += d * d;
        g2 += uy[10u] * uy[10u];
    }
{

        let d = xn[11u] - y[11u];
        curvature += d * (un[11u] - uy[11u]);
        d2 += d * d;
        g2 += uy[11u] * uy[11u];
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
{

            best[0u] = xn[0u];
        }
{

            best[1u] = xn[1u];
        }
{

            best[2u] = xn[2u];
        }
{

            best[3u] = xn[3u];
        }
{

            best[4u] = xn[4u];
        }
{

            best[5u] = xn[5u];
        }
{

            best[6u] = xn[6u];
        }
{

            best[7u] = xn[7u];
        }
{

            best[8u] = xn[8u];
        }
{

            best[9u] = xn[9u];
        }
{

            best[10u] = xn[10u];
        }
{

            best[11u] = xn[11u];
        }

    }
    let th = (*a).theta;
    let m = apgd_momentum(th);
    let th_new = m.x;
    let beta = m.y;
    var g_dot = Scalar(0.0);
{

        g_dot += uy[0u] * (xn[0u] - x[0u]);
    }
{

        g_dot += uy[1u] * (xn[1u] - x[1u]);
    }
{

        g_dot += uy[2u] * (xn[2u] - x[2u]);
    }
{

        g_dot += uy[3u] * (xn[3u] - x[3u]);
    }
{

        g_dot += uy[4u] * (xn[4u] - x[4u]);
    }
{

        g_dot += uy[5u] * (xn[5u] - x[5u]);
    }
{

        g_dot += uy[6u] * (xn[6u] - x[6u]);
    }
{

        g_dot += uy[7u] * (xn[7u] - x[7u]);
    }
{

        g_dot += uy[8u] * (xn[8u] - x[8u]);
    }
{

        g_dot += uy[9u] * (xn[9u] - x[9u]);
    }
{

        g_dot += uy[10u] * (xn[10u] - x[10u]);
    }
{

        g_dot += uy[11u] * (xn[11u] - x[11u]);
    }

    let restart = g_dot > Scalar(0.0);
{

        if restart {
            y[0u] = xn[0u];
            uy[0u] = un[0u];
        } else {
            y[0u] = xn[0u] + beta * (xn[0u] - x[0u]);
            uy[0u] = un[0u] + beta * (un[0u] - ux[0u]);
        }
        x[0u] = xn[0u];
        ux[0u] = un[0u];
    }
{

        if restart {
            y[1u] = xn[1u];
            uy[1u] = un[1u];
        } else {
            y[1u] = xn[1u] + beta * (xn[1u] - x[1u]);
            uy[1u] = un[1u] + beta * (un[1u] - ux[1u]);
        }
        x[1u] = xn[1u];
        ux[1u] = un[1u];
    }
{

        if restart {
            y[2u] = xn[2u];
            uy[2u] = un[2u];
        } else {
            y[2u] = xn[2u] + beta * (xn[2u] - x[2u]);
            uy[2u] = un[2u] + beta * (un[2u] - ux[2u]);
        }
        x[2u] = xn[2u];
        ux[2u] = un[2u];
    }
{

        if restart {
            y[3u] = xn[3u];
            uy[3u] = un[3u];
        } else {
            y[3u] = xn[3u] + beta * (xn[3u] - x[3u]);
            uy[3u] = un[3u] + beta * (un[3u] - ux[3u]);
        }
        x[3u] = xn[3u];
        ux[3u] = un[3u];
    }
{

        if restart {
            y[4u] = xn[4u];
            uy[4u] = un[4u];
        } else {
            y[4u] = xn[4u] + beta * (xn[4u] - x[4u]);
            uy[4u] = un[4u] + beta * (un[4u] - ux[4u]);
        }
        x[4u] = xn[4u];
        ux[4u] = un[4u];
    }
{

        if restart {
            y[5u] = xn[5u];
            uy[5u] = un[5u];
        } else {
            y[5u] = xn[5u] + beta * (xn[5u] - x[5u]);
            uy[5u] = un[5u] + beta * (un[5u] - ux[5u]);
        }
        x[5u] = xn[5u];
        ux[5u] = un[5u];
    }
{

        if restart {
            y[6u] = xn[6u];
            uy[6u] = un[6u];
        } else {
            y[6u] = xn[6u] + beta * (xn[6u] - x[6u]);
            uy[6u] = un[6u] + beta * (un[6u] - ux[6u]);
        }
        x[6u] = xn[6u];
        ux[6u] = un[6u];
    }
{

        if restart {
            y[7u] = xn[7u];
            uy[7u] = un[7u];
        } else {
            y[7u] = xn[7u] + beta * (xn[7u] - x[7u]);
            uy[7u] = un[7u] + beta * (un[7u] - ux[7u]);
        }
        x[7u] = xn[7u];
        ux[7u] = un[7u];
    }
{

        if restart {
            y[8u] = xn[8u];
            uy[8u] = un[8u];
        } else {
            y[8u] = xn[8u] + beta * (xn[8u] - x[8u]);
            uy[8u] = un[8u] + beta * (un[8u] - ux[8u]);
        }
        x[8u] = xn[8u];
        ux[8u] = un[8u];
    }
{

        if restart {
            y[9u] = xn[9u];
            uy[9u] = un[9u];
        } else {
            y[9u] = xn[9u] + beta * (xn[9u] - x[9u]);
            uy[9u] = un[9u] + beta * (un[9u] - ux[9u]);
        }
        x[9u] = xn[9u];
        ux[9u] = un[9u];
    }
{

        if restart {
            y[10u] = xn[10u];
            uy[10u] = un[10u];
        } else {
            y[10u] = xn[10u] + beta * (xn[10u] - x[10u]);
            uy[10u] = un[10u] + beta * (un[10u] - ux[10u]);
        }
        x[10u] = xn[10u];
        ux[10u] = un[10u];
    }
{

        if restart {
            y[11u] = xn[11u];
            uy[11u] = un[11u];
        } else {
            y[11u] = xn[11u] + beta * (xn[11u] - x[11u]);
            uy[11u] = un[11u] + beta * (un[11u] - ux[11u]);
        }
        x[11u] = xn[11u];
        ux[11u] = un[11u];
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
{

        ux[0u] = un[0u];
        y[0u] = x[0u];
        uy[0u] = un[0u];
        best[0u] = x[0u];
    }
{

        ux[1u] = un[1u];
        y[1u] = x[1u];
        uy[1u] = un[1u];
        best[1u] = x[1u];
    }
{

        ux[2u] = un[2u];
        y[2u] = x[2u];
        uy[2u] = un[2u];
        best[2u] = x[2u];
    }
{

        ux[3u] = un[3u];
        y[3u] = x[3u];
        uy[3u] = un[3u];
        best[3u] = x[3u];
    }
{

        ux[4u] = un[4u];
        y[4u] = x[4u];
        uy[4u] = un[4u];
        best[4u] = x[4u];
    }
{

        ux[5u] = un[5u];
        y[5u] = x[5u];
        uy[5u] = un[5u];
        best[5u] = x[5u];
    }
{

        ux[6u] = un[6u];
        y[6u] = x[6u];
        uy[6u] = un[6u];
        best[6u] = x[6u];
    }
{

        ux[7u] = un[7u];
        y[7u] = x[7u];
        uy[7u] = un[7u];
        best[7u] = x[7u];
    }
{

        ux[8u] = un[8u];
        y[8u] = x[8u];
        uy[8u] = un[8u];
        best[8u] = x[8u];
    }
{

        ux[9u] = un[9u];
        y[9u] = x[9u];
        uy[9u] = un[9u];
        best[9u] = x[9u];
    }
{

        ux[10u] = un[10u];
        y[10u] = x[10u];
        uy[10u] = un[10u];
        best[10u] = x[10u];
    }
{

        ux[11u] = un[11u];
        y[11u] = x[11u];
        uy[11u] = un[11u];
        best[11u] = x[11u];
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
