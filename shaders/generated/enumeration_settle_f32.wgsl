// GENERATED from shaders/enumeration_basis.wgsl + shaders/enumeration_settle.wgsl by src/gpu/shaders/compose.rs: do not edit.
// Regenerate: LCPBATCH_BLESS_SHADERS=1 cargo test --release generated_shaders_are_committed

// Shared part of the enumeration kernels (shaders/enumeration.wgsl,
// shaders/enumeration_workgroup.wgsl, shaders/enumeration_tree.wgsl, and
// shaders/enumeration_settle.wgsl, shaders/lemke.wgsl): the
// scalar type, the tolerances uniform, the island table, Params and
// BasisResult, bindings 0-7, the elimination scratch, and the elimination
// itself (solve_basis, write_z, basis_cost). WGSL has no include, so the
// generator (src/gpu/shaders/compose.rs, run by the tests) prepends this
// file to each kernel's source, replaces the lines marked HOST in the
// combined text, and commits the result to shaders/generated/, which is
// what runs. One copy keeps the kernels' eliminations operation for
// operation the same, which the GPU tests check bit for bit against each
// other and against the CPU twin (src/cpu/enumeration.rs).
//
// Each kernel defines what differs between them: any further bindings,
// constants and scratch, and its entry point. Not valid on its own: compile
// it only with a kernel.

alias Scalar = f32; // HOST scalar

const MAX_N: u32 = 16u;

// One island: n contacts; M (n*n, row-major) then q (n) start at `data` in
// `values`; z is written at `z` in `z_out`. `hint`: the bases the settle
// kernel tries first (shaders/enumeration_settle.wgsl); the others ignore it.
struct Island {
    n: u32,
    data: u32,
    z: u32,
    hint: u32,
}

// One dispatch covers islands first .. first + count of the island table
// (one dispatch per island size n, split to stay under 65,535 workgroups);
// `budget`: loop work per invocation and round; `flags`: the tree kernel's
// semidefinite switch (bit 0), 0 for the others.
struct Params {
    first: u32,
    count: u32,
    budget: u32,
    flags: u32,
}

// Where the enumeration of one island stands. status 0: in progress, the
// next basis to visit is `mask` (zero-initialised: start at the empty basis);
// 1: `mask` is the chosen valid basis (z written); 2: no basis is valid or
// within tol.relaxed; 3: none is valid, `mask` is the least infeasible basis
// within tol.relaxed (z written). visited / singular count bases as the
// CPU's Counters do. `least` (when `has_least` is 1) is the least infeasible
// basis so far, its infeasibility in `least_infeasibility`. `_pad0` and
// `_pad1` are each kernel's own (see its header): the workgroup kernel's rank
// of the next basis, the tree kernel's DECIDED / UNDECIDED; the elimination
// kernel carries them through.
struct BasisResult {
    mask: u32,
    status: u32,
    visited: u32,
    singular: u32,
    least: u32,
    has_least: u32,
    _pad0: u32,
    _pad1: u32,
}

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> islands: array<Island>;
@group(0) @binding(2) var<storage, read> values: array<Scalar>;
@group(0) @binding(3) var<storage, read_write> results: array<BasisResult>;
@group(0) @binding(4) var<storage, read_write> z_out: array<Scalar>;
// Islands of each size n still in progress after this round.
@group(0) @binding(5) var<storage, read_write> unfinished: array<atomic<u32>, 17>;
// Infeasibility of each island's least infeasible basis so far.
@group(0) @binding(6) var<storage, read_write> least_infeasibility: array<Scalar>;

// The tolerances, set at run time (src/gpu/pipelines.rs, `Tolerances`):
// pivot, feasibility and relaxed are the elimination's (GpuSolveSettings'
// gpu_tolerances); screen, tree_pivot and tree_singular the tree kernel's.
// A uniform rather than constants, so that one committed shader serves
// every setting (WGSL pipeline overrides cannot be f64).
struct Tolerances {
    pivot: Scalar,
    feasibility: Scalar,
    relaxed: Scalar,
    screen: Scalar,
    tree_pivot: Scalar,
    tree_singular: Scalar,
    _pad0: Scalar,
    _pad1: Scalar,
}
@group(0) @binding(7) var<uniform> tol: Tolerances;

// Private scratch of one invocation: the principal system and its solution.
var<private> a: array<Scalar, 256>;
var<private> x: array<Scalar, 16>;
var<private> colmax: array<Scalar, 16>;
var<private> idx: array<u32, 16>;

// solve_basis' answer for a singular M_SS (infeasibilities are >= 0).
const SINGULAR: Scalar = -1.0;

// Solves basis `mask` of the island whose M starts at `base`; z_S in x[0..k].
// Returns SINGULAR, or the basis' relative infeasibility (0: feasible; the
// measure stops growing once it exceeds tol.relaxed, as on the CPU).
fn solve_basis(base: u32, n: u32, mask: u32) -> Scalar {
    var k = 0u;
    for (var i = 0u; i < n; i++) {
        if ((mask >> i) & 1u) == 1u {
            idx[k] = i;
            k++;
        }
    }
    let qbase = base + n * n;
    for (var r = 0u; r < k; r++) {
        let row = base + idx[r] * n;
        for (var c = 0u; c < k; c++) {
            a[r * k + c] = values[row + idx[c]];
        }
        x[r] = -values[qbase + idx[r]];
    }
    // Column maxima of M_SS before elimination (the pivot scale).
    for (var c = 0u; c < k; c++) {
        var m = Scalar(0.0);
        for (var r = 0u; r < k; r++) {
            m = max(m, abs(a[r * k + c]));
        }
        colmax[c] = m;
    }
    for (var c = 0u; c < k; c++) {
        var p = c;
        var best = abs(a[c * k + c]);
        for (var r = c + 1u; r < k; r++) {
            let v = abs(a[r * k + c]);
            if v > best {
                best = v;
                p = r;
            }
        }
        if !(best > tol.pivot * colmax[c]) || best == Scalar(0.0) {
            return SINGULAR;
        }
        if p != c {
            for (var j = 0u; j < k; j++) {
                let t = a[c * k + j];
                a[c * k + j] = a[p * k + j];
                a[p * k + j] = t;
            }
            let t = x[c];
            x[c] = x[p];
            x[p] = t;
        }
        let inv = Scalar(1.0) / a[c * k + c];
        for (var r = c + 1u; r < k; r++) {
            let f = a[r * k + c] * inv;
            if f != Scalar(0.0) {
                for (var j = c + 1u; j < k; j++) {
                    a[r * k + j] -= f * a[c * k + j];
                }
                x[r] -= f * x[c];
            }
        }
    }
    for (var cc = 0u; cc < k; cc++) {
        let c = k - 1u - cc;
        var s = x[c];
        for (var j = c + 1u; j < k; j++) {
            s -= a[c * k + j] * x[j];
        }
        x[c] = s / a[c * k + c];
    }
    // Infeasibility of z_S.
    var zmax = Scalar(0.0);
    for (var r = 0u; r < k; r++) {
        zmax = max(zmax, abs(x[r]));
    }
    var worst = Scalar(0.0);
    for (var r = 0u; r < k; r++) {
        if x[r] < Scalar(0.0) {
            worst = max(worst, -x[r] / zmax);
        }
    }
    if worst > tol.relaxed {
        return worst;
    }
    // Infeasibility of w off S.
    for (var i = 0u; i < n; i++) {
        if ((mask >> i) & 1u) == 1u {
            continue;
        }
        let row = base + i * n;
        var w = values[qbase + i];
        var scale = abs(w);
        for (var r = 0u; r < k; r++) {
            let t = values[row + idx[r]] * x[r];
            w += t;
            scale += abs(t);
        }
        if w < Scalar(0.0) {
            worst = max(worst, -w / scale);
            if worst > tol.relaxed {
                return worst;
            }
        }
    }
    return worst;
}

// Writes z of the basis whose z_S is in x (clamped at 0 like the CPU's
// solve_basis), zeros off the basis.
fn write_z(at: u32, n: u32, k: u32) {
    for (var i = 0u; i < n; i++) {
        z_out[at + i] = Scalar(0.0);
    }
    for (var r = 0u; r < k; r++) {
        z_out[at + idx[r]] = max(x[r], Scalar(0.0));
    }
}

// Upper bound of the loop iterations `solve_basis` spends on a basis with k
// basic variables out of n, plus one for the caller's loop.
fn basis_cost(n: u32, k: u32) -> u32 {
    return 9u + 4u * n + 8u * k + 5u * k * k + (k * k * k) / 3u + n * k;
}

// The settle kernel: prediction's steps 3 and 4 on the device, before the
// enumeration or Lemke kernels (one dispatch over a chunk's table, recorded
// ahead of the first round in the same submission). CPU twin: `steps` in
// src/prediction.rs (warm start, then the predicted basis), each basis
// solved by the shared elimination (shaders/enumeration_basis.wgsl,
// prepended by the generator) as the CPU's `feasible_basis_into` solves it.
//
// Island.hint (LCP batches; src/prediction.rs, `prediction_hint_into`): bits
// 0-15 the island's warm basis, bits 16-31 its predicted basis (the
// approaching contacts, given only where M is positive definite: the host
// tested that); 0: none. An empty basis is never a hint: the host settled
// the islands with q >= 0 (separating), and on the others the empty basis is
// infeasible.
//
// Each hinted basis is tried in that order; the first that is nonsingular
// and feasible to tol.feasibility (the enumeration's test) is written as the
// island's answer: status FOUND, its mask, its z, visited 1 (the CPU's
// counters for a basis prediction settles), and _pad1 SETTLED_WARM or
// SETTLED_PREDICTED (src/gpu/layout.rs), so that the host counts the island
// with prediction's. The other kernels skip an island whose status is not 0;
// where neither basis settles it, its record stays cleared and it is
// enumerated (or pivoted) as if no hint had been given.

const SETTLED_WARM: u32 = 3u;
const SETTLED_PREDICTED: u32 = 4u;

// Whether basis `mask` of `island` (n contacts) is a valid answer; its z
// written where it is.
fn settles(island: Island, n: u32, mask: u32) -> bool {
    if mask == 0u || (mask >> n) != 0u {
        return false;
    }
    let infeasibility = solve_basis(island.data, n, mask);
    if infeasibility == SINGULAR || !(infeasibility <= tol.feasibility) {
        return false;
    }
    write_z(island.z, n, countOneBits(mask));
    return true;
}

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= params.count {
        return;
    }
    let island_index = params.first + gid.x;
    let island = islands[island_index];
    let n = min(island.n, MAX_N);
    var state = BasisResult(0u, 1u, 1u, 0u, 0u, 0u, 0u, 0u);
    if settles(island, n, island.hint & 0xffffu) {
        state.mask = island.hint & 0xffffu;
        state._pad1 = SETTLED_WARM;
    } else if settles(island, n, island.hint >> 16u) {
        state.mask = island.hint >> 16u;
        state._pad1 = SETTLED_PREDICTED;
    } else {
        return;
    }
    results[island_index] = state;
}
