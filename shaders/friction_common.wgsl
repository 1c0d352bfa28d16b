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
const FIXED_K: u32 = 1u; // HOST fixed_k

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
