// GENERATED from shaders/enumeration_basis.wgsl + shaders/enumeration.wgsl by src/gpu/shaders/compose.rs: do not edit.
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

alias Scalar = f64; // HOST scalar

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

// Enumeration of complementary bases: one invocation per island.
// CPU twin: src/cpu/enumeration.rs (same order, same tests, same tolerances
// in f64; the f32 build uses looser ones and the f64 polish decides).
//
// A basis is a u32 mask, bit i set when z_i is basic. Bases are visited by
// increasing popcount, each popcount by increasing mask (Gosper's hack), and
// the first valid one is chosen: the fewest contacts carrying impulse, ties to
// the smallest mask. For each basis S: solve M_SS z_S = -q_S by Gaussian
// elimination with partial pivoting (singular when a pivot is at most
// tol.pivot times its column's largest entry of M_SS), then its relative
// infeasibility is the worst of -z_i / max|z_S| and
// -w_i / (|q_i| + sum_j |M_ij z_j|), w_i = q_i + sum_j M_ij z_j. Valid: at most
// tol.feasibility. When no basis is valid, the least infeasible basis within
// tol.relaxed is chosen (the first on a tie), as on the CPU.
//
// Rounds: an invocation visits bases until it has spent `params.budget` units
// of loop work (an upper bound of the loop iterations of one basis, see
// `basis_cost`), saves where it stopped in its BasisResult and counts itself
// in `unfinished`; the host dispatches rounds until no island of a size is
// unfinished. llvmpipe (lavapipe) ends every loop of an invocation after about
// 65,535 iterations in all, silently, so on software adapters the budget
// stays below that; on hardware it only bounds the time of one dispatch.
//
// Shared with the other enumeration kernels: shaders/enumeration_basis.wgsl
// (scalar type, tolerances, MAX_N, Island, bindings 0-7, the elimination
// scratch a / x / colmax / idx, SINGULAR, solve_basis, write_z,
// basis_cost), which the generator prepends to this file.
// The generator replaces the lines marked HOST (in the shared file: scalar
// type; here, for a specialised build: FIXED, FN, FNN).

// Specialised build for one island size (islands of exactly FN contacts):
// the generator sets FIXED, FN and FNN = FN * FN. solve_basis_fixed then works on
// the n x n system with the nonbasic rows and columns replaced by the
// identity, so that every loop has a constant trip count and every private
// array index is constant once unrolled (llvmpipe indexes private arrays
// dynamically through memory). Its arithmetic is solve_basis' operation for
// operation (the identity rows never pivot and add exact zeros), so its
// answers are the same bit for bit.
const FIXED: bool = true; // HOST fixed
const FN: u32 = 3u; // HOST fixed_n
const FNN: u32 = 9u; // HOST fixed_nn

// Params and BasisResult (where an island's enumeration stands):
// shaders/enumeration_basis.wgsl.

// z of solve_basis_fixed (0 off the basis), for write_z_fixed.
var<private> fx: array<Scalar, FN>;

// solve_basis for islands of exactly FN contacts; z (0 off the basis) in
// fx. Placeholder: the generator replaces it with straight-line code for FN
// (src/gpu/shaders/unrolled.rs, `straight_line_solver`) in every specialised build,
// and the general build (FIXED false) never calls it.
fn solve_basis_fixed(base: u32, mask: u32) -> Scalar {
    let qbase = base + FNN;
    let b0 = ((mask >> 0u) & 1u) == 1u;
    let b1 = ((mask >> 1u) & 1u) == 1u;
    let b2 = ((mask >> 2u) & 1u) == 1u;
    var a0_0 = select(Scalar(1.0), values[base + 0u], b0);
    var a0_1 = select(Scalar(0.0), values[base + 1u], b0 && b1);
    var a0_2 = select(Scalar(0.0), values[base + 2u], b0 && b2);
    var x0 = select(Scalar(0.0), -values[qbase + 0u], b0);
    var a1_0 = select(Scalar(0.0), values[base + 3u], b1 && b0);
    var a1_1 = select(Scalar(1.0), values[base + 4u], b1);
    var a1_2 = select(Scalar(0.0), values[base + 5u], b1 && b2);
    var x1 = select(Scalar(0.0), -values[qbase + 1u], b1);
    var a2_0 = select(Scalar(0.0), values[base + 6u], b2 && b0);
    var a2_1 = select(Scalar(0.0), values[base + 7u], b2 && b1);
    var a2_2 = select(Scalar(1.0), values[base + 8u], b2);
    var x2 = select(Scalar(0.0), -values[qbase + 2u], b2);
    let cm0 = max(max(max(Scalar(0.0), abs(a0_0)), abs(a1_0)), abs(a2_0));
    let cm1 = max(max(max(Scalar(0.0), abs(a0_1)), abs(a1_1)), abs(a2_1));
    let cm2 = max(max(max(Scalar(0.0), abs(a0_2)), abs(a1_2)), abs(a2_2));
    {
        var best = abs(a0_0);
        var p = 0u;
        { let v = abs(a1_0); let g = v > best; p = select(p, 1u, g); best = select(best, v, g); }
        { let v = abs(a2_0); let g = v > best; p = select(p, 2u, g); best = select(best, v, g); }
        if !(best > tol.pivot * cm0) || best == Scalar(0.0) { return SINGULAR; }
        { let sw = p == 1u;
            { let t = a0_0; a0_0 = select(a0_0, a1_0, sw); a1_0 = select(a1_0, t, sw); }
            { let t = a0_1; a0_1 = select(a0_1, a1_1, sw); a1_1 = select(a1_1, t, sw); }
            { let t = a0_2; a0_2 = select(a0_2, a1_2, sw); a1_2 = select(a1_2, t, sw); }
            { let t = x0; x0 = select(x0, x1, sw); x1 = select(x1, t, sw); } }
        { let sw = p == 2u;
            { let t = a0_0; a0_0 = select(a0_0, a2_0, sw); a2_0 = select(a2_0, t, sw); }
            { let t = a0_1; a0_1 = select(a0_1, a2_1, sw); a2_1 = select(a2_1, t, sw); }
            { let t = a0_2; a0_2 = select(a0_2, a2_2, sw); a2_2 = select(a2_2, t, sw); }
            { let t = x0; x0 = select(x0, x2, sw); x2 = select(x2, t, sw); } }
        let inv = Scalar(1.0) / a0_0;
        { let f = a1_0 * inv; let nz = f != Scalar(0.0);
            a1_1 = select(a1_1, a1_1 - f * a0_1, nz);
            a1_2 = select(a1_2, a1_2 - f * a0_2, nz);
            x1 = select(x1, x1 - f * x0, nz); }
        { let f = a2_0 * inv; let nz = f != Scalar(0.0);
            a2_1 = select(a2_1, a2_1 - f * a0_1, nz);
            a2_2 = select(a2_2, a2_2 - f * a0_2, nz);
            x2 = select(x2, x2 - f * x0, nz); }
    }
    {
        var best = abs(a1_1);
        var p = 1u;
        { let v = abs(a2_1); let g = v > best; p = select(p, 2u, g); best = select(best, v, g); }
        if !(best > tol.pivot * cm1) || best == Scalar(0.0) { return SINGULAR; }
        { let sw = p == 2u;
            { let t = a1_1; a1_1 = select(a1_1, a2_1, sw); a2_1 = select(a2_1, t, sw); }
            { let t = a1_2; a1_2 = select(a1_2, a2_2, sw); a2_2 = select(a2_2, t, sw); }
            { let t = x1; x1 = select(x1, x2, sw); x2 = select(x2, t, sw); } }
        let inv = Scalar(1.0) / a1_1;
        { let f = a2_1 * inv; let nz = f != Scalar(0.0);
            a2_2 = select(a2_2, a2_2 - f * a1_2, nz);
            x2 = select(x2, x2 - f * x1, nz); }
    }
    {
        var best = abs(a2_2);
        var p = 2u;
        if !(best > tol.pivot * cm2) || best == Scalar(0.0) { return SINGULAR; }
        let inv = Scalar(1.0) / a2_2;
    }
    { var s = x2;
        x2 = s / a2_2; }
    { var s = x1;
        s = s - a1_2 * x2;
        x1 = s / a1_1; }
    { var s = x0;
        s = s - a0_1 * x1;
        s = s - a0_2 * x2;
        x0 = s / a0_0; }
    fx[0] = x0;
    fx[1] = x1;
    fx[2] = x2;
    var zmax = Scalar(0.0);
    if b0 { zmax = max(zmax, abs(x0)); }
    if b1 { zmax = max(zmax, abs(x1)); }
    if b2 { zmax = max(zmax, abs(x2)); }
    var worst = Scalar(0.0);
    if b0 && x0 < Scalar(0.0) { worst = max(worst, -x0 / zmax); }
    if b1 && x1 < Scalar(0.0) { worst = max(worst, -x1 / zmax); }
    if b2 && x2 < Scalar(0.0) { worst = max(worst, -x2 / zmax); }
    if worst > tol.relaxed { return worst; }
    if !b0 {
        var w = values[qbase + 0u];
        var scale = abs(w);
        if b0 { let t = values[base + 0u] * x0; w += t; scale += abs(t); }
        if b1 { let t = values[base + 1u] * x1; w += t; scale += abs(t); }
        if b2 { let t = values[base + 2u] * x2; w += t; scale += abs(t); }
        if w < Scalar(0.0) { worst = max(worst, -w / scale); if worst > tol.relaxed { return worst; } }
    }
    if !b1 {
        var w = values[qbase + 1u];
        var scale = abs(w);
        if b0 { let t = values[base + 3u] * x0; w += t; scale += abs(t); }
        if b1 { let t = values[base + 4u] * x1; w += t; scale += abs(t); }
        if b2 { let t = values[base + 5u] * x2; w += t; scale += abs(t); }
        if w < Scalar(0.0) { worst = max(worst, -w / scale); if worst > tol.relaxed { return worst; } }
    }
    if !b2 {
        var w = values[qbase + 2u];
        var scale = abs(w);
        if b0 { let t = values[base + 6u] * x0; w += t; scale += abs(t); }
        if b1 { let t = values[base + 7u] * x1; w += t; scale += abs(t); }
        if b2 { let t = values[base + 8u] * x2; w += t; scale += abs(t); }
        if w < Scalar(0.0) { worst = max(worst, -w / scale); if worst > tol.relaxed { return worst; } }
    }
    return worst;
}

fn write_z_fixed(at: u32, mask: u32) {
    for (var i = 0u; i < FN; i++) {
        var v = Scalar(0.0);
        if ((mask >> i) & 1u) == 1u {
            v = max(fx[i], Scalar(0.0));
        }
        z_out[at + i] = v;
    }
}

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= params.count {
        return;
    }
    let island_index = params.first + gid.x;
    var state = results[island_index];
    if state.status != 0u {
        return;
    }
    let island = islands[island_index];
    var n = min(island.n, MAX_N);
    if FIXED {
        n = FN;
    }
    let full = 1u << n;
    let worst = basis_cost(n, n);
    // The next basis: s, with k = popcount(s) basic variables.
    var s = state.mask;
    var k = countOneBits(s);
    var spent = 0u;
    loop {
        if spent > 0u && spent + worst > params.budget {
            break;
        }
        spent += basis_cost(n, k);
        state.visited++;
        var infeasibility: Scalar;
        if FIXED {
            infeasibility = solve_basis_fixed(island.data, s);
        } else {
            infeasibility = solve_basis(island.data, n, s);
        }
        if infeasibility == SINGULAR {
            state.singular++;
        } else if infeasibility <= tol.feasibility {
            if FIXED {
                write_z_fixed(island.z, s);
            } else {
                write_z(island.z, n, k);
            }
            state.status = 1u;
            break;
        } else if infeasibility <= tol.relaxed {
            if state.has_least == 0u || infeasibility < least_infeasibility[island_index] {
                state.least = s;
                state.has_least = 1u;
                least_infeasibility[island_index] = infeasibility;
                if FIXED {
                    write_z_fixed(island.z, s);
                } else {
                    write_z(island.z, n, k);
                }
            }
        }
        if s == full - 1u {
            if state.has_least == 1u {
                state.status = 3u;
                s = state.least;
            } else {
                state.status = 2u;
            }
            break;
        }
        if k == 0u {
            k = 1u;
            s = 1u;
        } else {
            // Next larger mask with the same popcount (Gosper's hack), or the
            // smallest mask with one more bit.
            let c = s & (0u - s);
            let r = s + c;
            let next = (((r ^ s) >> 2u) >> countTrailingZeros(s)) | r;
            if next >= full {
                k++;
                s = (1u << k) - 1u;
            } else {
                s = next;
            }
        }
    }
    state.mask = s;
    results[island_index] = state;
    if state.status == 0u {
        atomicAdd(&unfinished[n], 1u);
    }
}
