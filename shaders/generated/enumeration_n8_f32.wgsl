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
const FN: u32 = 8u; // HOST fixed_n
const FNN: u32 = 64u; // HOST fixed_nn

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
    let b3 = ((mask >> 3u) & 1u) == 1u;
    let b4 = ((mask >> 4u) & 1u) == 1u;
    let b5 = ((mask >> 5u) & 1u) == 1u;
    let b6 = ((mask >> 6u) & 1u) == 1u;
    let b7 = ((mask >> 7u) & 1u) == 1u;
    var a0_0 = select(Scalar(1.0), values[base + 0u], b0);
    var a0_1 = select(Scalar(0.0), values[base + 1u], b0 && b1);
    var a0_2 = select(Scalar(0.0), values[base + 2u], b0 && b2);
    var a0_3 = select(Scalar(0.0), values[base + 3u], b0 && b3);
    var a0_4 = select(Scalar(0.0), values[base + 4u], b0 && b4);
    var a0_5 = select(Scalar(0.0), values[base + 5u], b0 && b5);
    var a0_6 = select(Scalar(0.0), values[base + 6u], b0 && b6);
    var a0_7 = select(Scalar(0.0), values[base + 7u], b0 && b7);
    var x0 = select(Scalar(0.0), -values[qbase + 0u], b0);
    var a1_0 = select(Scalar(0.0), values[base + 8u], b1 && b0);
    var a1_1 = select(Scalar(1.0), values[base + 9u], b1);
    var a1_2 = select(Scalar(0.0), values[base + 10u], b1 && b2);
    var a1_3 = select(Scalar(0.0), values[base + 11u], b1 && b3);
    var a1_4 = select(Scalar(0.0), values[base + 12u], b1 && b4);
    var a1_5 = select(Scalar(0.0), values[base + 13u], b1 && b5);
    var a1_6 = select(Scalar(0.0), values[base + 14u], b1 && b6);
    var a1_7 = select(Scalar(0.0), values[base + 15u], b1 && b7);
    var x1 = select(Scalar(0.0), -values[qbase + 1u], b1);
    var a2_0 = select(Scalar(0.0), values[base + 16u], b2 && b0);
    var a2_1 = select(Scalar(0.0), values[base + 17u], b2 && b1);
    var a2_2 = select(Scalar(1.0), values[base + 18u], b2);
    var a2_3 = select(Scalar(0.0), values[base + 19u], b2 && b3);
    var a2_4 = select(Scalar(0.0), values[base + 20u], b2 && b4);
    var a2_5 = select(Scalar(0.0), values[base + 21u], b2 && b5);
    var a2_6 = select(Scalar(0.0), values[base + 22u], b2 && b6);
    var a2_7 = select(Scalar(0.0), values[base + 23u], b2 && b7);
    var x2 = select(Scalar(0.0), -values[qbase + 2u], b2);
    var a3_0 = select(Scalar(0.0), values[base + 24u], b3 && b0);
    var a3_1 = select(Scalar(0.0), values[base + 25u], b3 && b1);
    var a3_2 = select(Scalar(0.0), values[base + 26u], b3 && b2);
    var a3_3 = select(Scalar(1.0), values[base + 27u], b3);
    var a3_4 = select(Scalar(0.0), values[base + 28u], b3 && b4);
    var a3_5 = select(Scalar(0.0), values[base + 29u], b3 && b5);
    var a3_6 = select(Scalar(0.0), values[base + 30u], b3 && b6);
    var a3_7 = select(Scalar(0.0), values[base + 31u], b3 && b7);
    var x3 = select(Scalar(0.0), -values[qbase + 3u], b3);
    var a4_0 = select(Scalar(0.0), values[base + 32u], b4 && b0);
    var a4_1 = select(Scalar(0.0), values[base + 33u], b4 && b1);
    var a4_2 = select(Scalar(0.0), values[base + 34u], b4 && b2);
    var a4_3 = select(Scalar(0.0), values[base + 35u], b4 && b3);
    var a4_4 = select(Scalar(1.0), values[base + 36u], b4);
    var a4_5 = select(Scalar(0.0), values[base + 37u], b4 && b5);
    var a4_6 = select(Scalar(0.0), values[base + 38u], b4 && b6);
    var a4_7 = select(Scalar(0.0), values[base + 39u], b4 && b7);
    var x4 = select(Scalar(0.0), -values[qbase + 4u], b4);
    var a5_0 = select(Scalar(0.0), values[base + 40u], b5 && b0);
    var a5_1 = select(Scalar(0.0), values[base + 41u], b5 && b1);
    var a5_2 = select(Scalar(0.0), values[base + 42u], b5 && b2);
    var a5_3 = select(Scalar(0.0), values[base + 43u], b5 && b3);
    var a5_4 = select(Scalar(0.0), values[base + 44u], b5 && b4);
    var a5_5 = select(Scalar(1.0), values[base + 45u], b5);
    var a5_6 = select(Scalar(0.0), values[base + 46u], b5 && b6);
    var a5_7 = select(Scalar(0.0), values[base + 47u], b5 && b7);
    var x5 = select(Scalar(0.0), -values[qbase + 5u], b5);
    var a6_0 = select(Scalar(0.0), values[base + 48u], b6 && b0);
    var a6_1 = select(Scalar(0.0), values[base + 49u], b6 && b1);
    var a6_2 = select(Scalar(0.0), values[base + 50u], b6 && b2);
    var a6_3 = select(Scalar(0.0), values[base + 51u], b6 && b3);
    var a6_4 = select(Scalar(0.0), values[base + 52u], b6 && b4);
    var a6_5 = select(Scalar(0.0), values[base + 53u], b6 && b5);
    var a6_6 = select(Scalar(1.0), values[base + 54u], b6);
    var a6_7 = select(Scalar(0.0), values[base + 55u], b6 && b7);
    var x6 = select(Scalar(0.0), -values[qbase + 6u], b6);
    var a7_0 = select(Scalar(0.0), values[base + 56u], b7 && b0);
    var a7_1 = select(Scalar(0.0), values[base + 57u], b7 && b1);
    var a7_2 = select(Scalar(0.0), values[base + 58u], b7 && b2);
    var a7_3 = select(Scalar(0.0), values[base + 59u], b7 && b3);
    var a7_4 = select(Scalar(0.0), values[base + 60u], b7 && b4);
    var a7_5 = select(Scalar(0.0), values[base + 61u], b7 && b5);
    var a7_6 = select(Scalar(0.0), values[base + 62u], b7 && b6);
    var a7_7 = select(Scalar(1.0), values[base + 63u], b7);
    var x7 = select(Scalar(0.0), -values[qbase + 7u], b7);
    let cm0 = max(max(max(max(max(max(max(max(Scalar(0.0), abs(a0_0)), abs(a1_0)), abs(a2_0)), abs(a3_0)), abs(a4_0)), abs(a5_0)), abs(a6_0)), abs(a7_0));
    let cm1 = max(max(max(max(max(max(max(max(Scalar(0.0), abs(a0_1)), abs(a1_1)), abs(a2_1)), abs(a3_1)), abs(a4_1)), abs(a5_1)), abs(a6_1)), abs(a7_1));
    let cm2 = max(max(max(max(max(max(max(max(Scalar(0.0), abs(a0_2)), abs(a1_2)), abs(a2_2)), abs(a3_2)), abs(a4_2)), abs(a5_2)), abs(a6_2)), abs(a7_2));
    let cm3 = max(max(max(max(max(max(max(max(Scalar(0.0), abs(a0_3)), abs(a1_3)), abs(a2_3)), abs(a3_3)), abs(a4_3)), abs(a5_3)), abs(a6_3)), abs(a7_3));
    let cm4 = max(max(max(max(max(max(max(max(Scalar(0.0), abs(a0_4)), abs(a1_4)), abs(a2_4)), abs(a3_4)), abs(a4_4)), abs(a5_4)), abs(a6_4)), abs(a7_4));
    let cm5 = max(max(max(max(max(max(max(max(Scalar(0.0), abs(a0_5)), abs(a1_5)), abs(a2_5)), abs(a3_5)), abs(a4_5)), abs(a5_5)), abs(a6_5)), abs(a7_5));
    let cm6 = max(max(max(max(max(max(max(max(Scalar(0.0), abs(a0_6)), abs(a1_6)), abs(a2_6)), abs(a3_6)), abs(a4_6)), abs(a5_6)), abs(a6_6)), abs(a7_6));
    let cm7 = max(max(max(max(max(max(max(max(Scalar(0.0), abs(a0_7)), abs(a1_7)), abs(a2_7)), abs(a3_7)), abs(a4_7)), abs(a5_7)), abs(a6_7)), abs(a7_7));
    {
        var best = abs(a0_0);
        var p = 0u;
        { let v = abs(a1_0); let g = v > best; p = select(p, 1u, g); best = select(best, v, g); }
        { let v = abs(a2_0); let g = v > best; p = select(p, 2u, g); best = select(best, v, g); }
        { let v = abs(a3_0); let g = v > best; p = select(p, 3u, g); best = select(best, v, g); }
        { let v = abs(a4_0); let g = v > best; p = select(p, 4u, g); best = select(best, v, g); }
        { let v = abs(a5_0); let g = v > best; p = select(p, 5u, g); best = select(best, v, g); }
        { let v = abs(a6_0); let g = v > best; p = select(p, 6u, g); best = select(best, v, g); }
        { let v = abs(a7_0); let g = v > best; p = select(p, 7u, g); best = select(best, v, g); }
        if !(best > tol.pivot * cm0) || best == Scalar(0.0) { return SINGULAR; }
        { let sw = p == 1u;
            { let t = a0_0; a0_0 = select(a0_0, a1_0, sw); a1_0 = select(a1_0, t, sw); }
            { let t = a0_1; a0_1 = select(a0_1, a1_1, sw); a1_1 = select(a1_1, t, sw); }
            { let t = a0_2; a0_2 = select(a0_2, a1_2, sw); a1_2 = select(a1_2, t, sw); }
            { let t = a0_3; a0_3 = select(a0_3, a1_3, sw); a1_3 = select(a1_3, t, sw); }
            { let t = a0_4; a0_4 = select(a0_4, a1_4, sw); a1_4 = select(a1_4, t, sw); }
            { let t = a0_5; a0_5 = select(a0_5, a1_5, sw); a1_5 = select(a1_5, t, sw); }
            { let t = a0_6; a0_6 = select(a0_6, a1_6, sw); a1_6 = select(a1_6, t, sw); }
            { let t = a0_7; a0_7 = select(a0_7, a1_7, sw); a1_7 = select(a1_7, t, sw); }
            { let t = x0; x0 = select(x0, x1, sw); x1 = select(x1, t, sw); } }
        { let sw = p == 2u;
            { let t = a0_0; a0_0 = select(a0_0, a2_0, sw); a2_0 = select(a2_0, t, sw); }
            { let t = a0_1; a0_1 = select(a0_1, a2_1, sw); a2_1 = select(a2_1, t, sw); }
            { let t = a0_2; a0_2 = select(a0_2, a2_2, sw); a2_2 = select(a2_2, t, sw); }
            { let t = a0_3; a0_3 = select(a0_3, a2_3, sw); a2_3 = select(a2_3, t, sw); }
            { let t = a0_4; a0_4 = select(a0_4, a2_4, sw); a2_4 = select(a2_4, t, sw); }
            { let t = a0_5; a0_5 = select(a0_5, a2_5, sw); a2_5 = select(a2_5, t, sw); }
            { let t = a0_6; a0_6 = select(a0_6, a2_6, sw); a2_6 = select(a2_6, t, sw); }
            { let t = a0_7; a0_7 = select(a0_7, a2_7, sw); a2_7 = select(a2_7, t, sw); }
            { let t = x0; x0 = select(x0, x2, sw); x2 = select(x2, t, sw); } }
        { let sw = p == 3u;
            { let t = a0_0; a0_0 = select(a0_0, a3_0, sw); a3_0 = select(a3_0, t, sw); }
            { let t = a0_1; a0_1 = select(a0_1, a3_1, sw); a3_1 = select(a3_1, t, sw); }
            { let t = a0_2; a0_2 = select(a0_2, a3_2, sw); a3_2 = select(a3_2, t, sw); }
            { let t = a0_3; a0_3 = select(a0_3, a3_3, sw); a3_3 = select(a3_3, t, sw); }
            { let t = a0_4; a0_4 = select(a0_4, a3_4, sw); a3_4 = select(a3_4, t, sw); }
            { let t = a0_5; a0_5 = select(a0_5, a3_5, sw); a3_5 = select(a3_5, t, sw); }
            { let t = a0_6; a0_6 = select(a0_6, a3_6, sw); a3_6 = select(a3_6, t, sw); }
            { let t = a0_7; a0_7 = select(a0_7, a3_7, sw); a3_7 = select(a3_7, t, sw); }
            { let t = x0; x0 = select(x0, x3, sw); x3 = select(x3, t, sw); } }
        { let sw = p == 4u;
            { let t = a0_0; a0_0 = select(a0_0, a4_0, sw); a4_0 = select(a4_0, t, sw); }
            { let t = a0_1; a0_1 = select(a0_1, a4_1, sw); a4_1 = select(a4_1, t, sw); }
            { let t = a0_2; a0_2 = select(a0_2, a4_2, sw); a4_2 = select(a4_2, t, sw); }
            { let t = a0_3; a0_3 = select(a0_3, a4_3, sw); a4_3 = select(a4_3, t, sw); }
            { let t = a0_4; a0_4 = select(a0_4, a4_4, sw); a4_4 = select(a4_4, t, sw); }
            { let t = a0_5; a0_5 = select(a0_5, a4_5, sw); a4_5 = select(a4_5, t, sw); }
            { let t = a0_6; a0_6 = select(a0_6, a4_6, sw); a4_6 = select(a4_6, t, sw); }
            { let t = a0_7; a0_7 = select(a0_7, a4_7, sw); a4_7 = select(a4_7, t, sw); }
            { let t = x0; x0 = select(x0, x4, sw); x4 = select(x4, t, sw); } }
        { let sw = p == 5u;
            { let t = a0_0; a0_0 = select(a0_0, a5_0, sw); a5_0 = select(a5_0, t, sw); }
            { let t = a0_1; a0_1 = select(a0_1, a5_1, sw); a5_1 = select(a5_1, t, sw); }
            { let t = a0_2; a0_2 = select(a0_2, a5_2, sw); a5_2 = select(a5_2, t, sw); }
            { let t = a0_3; a0_3 = select(a0_3, a5_3, sw); a5_3 = select(a5_3, t, sw); }
            { let t = a0_4; a0_4 = select(a0_4, a5_4, sw); a5_4 = select(a5_4, t, sw); }
            { let t = a0_5; a0_5 = select(a0_5, a5_5, sw); a5_5 = select(a5_5, t, sw); }
            { let t = a0_6; a0_6 = select(a0_6, a5_6, sw); a5_6 = select(a5_6, t, sw); }
            { let t = a0_7; a0_7 = select(a0_7, a5_7, sw); a5_7 = select(a5_7, t, sw); }
            { let t = x0; x0 = select(x0, x5, sw); x5 = select(x5, t, sw); } }
        { let sw = p == 6u;
            { let t = a0_0; a0_0 = select(a0_0, a6_0, sw); a6_0 = select(a6_0, t, sw); }
            { let t = a0_1; a0_1 = select(a0_1, a6_1, sw); a6_1 = select(a6_1, t, sw); }
            { let t = a0_2; a0_2 = select(a0_2, a6_2, sw); a6_2 = select(a6_2, t, sw); }
            { let t = a0_3; a0_3 = select(a0_3, a6_3, sw); a6_3 = select(a6_3, t, sw); }
            { let t = a0_4; a0_4 = select(a0_4, a6_4, sw); a6_4 = select(a6_4, t, sw); }
            { let t = a0_5; a0_5 = select(a0_5, a6_5, sw); a6_5 = select(a6_5, t, sw); }
            { let t = a0_6; a0_6 = select(a0_6, a6_6, sw); a6_6 = select(a6_6, t, sw); }
            { let t = a0_7; a0_7 = select(a0_7, a6_7, sw); a6_7 = select(a6_7, t, sw); }
            { let t = x0; x0 = select(x0, x6, sw); x6 = select(x6, t, sw); } }
        { let sw = p == 7u;
            { let t = a0_0; a0_0 = select(a0_0, a7_0, sw); a7_0 = select(a7_0, t, sw); }
            { let t = a0_1; a0_1 = select(a0_1, a7_1, sw); a7_1 = select(a7_1, t, sw); }
            { let t = a0_2; a0_2 = select(a0_2, a7_2, sw); a7_2 = select(a7_2, t, sw); }
            { let t = a0_3; a0_3 = select(a0_3, a7_3, sw); a7_3 = select(a7_3, t, sw); }
            { let t = a0_4; a0_4 = select(a0_4, a7_4, sw); a7_4 = select(a7_4, t, sw); }
            { let t = a0_5; a0_5 = select(a0_5, a7_5, sw); a7_5 = select(a7_5, t, sw); }
            { let t = a0_6; a0_6 = select(a0_6, a7_6, sw); a7_6 = select(a7_6, t, sw); }
            { let t = a0_7; a0_7 = select(a0_7, a7_7, sw); a7_7 = select(a7_7, t, sw); }
            { let t = x0; x0 = select(x0, x7, sw); x7 = select(x7, t, sw); } }
        let inv = Scalar(1.0) / a0_0;
        { let f = a1_0 * inv; let nz = f != Scalar(0.0);
            a1_1 = select(a1_1, a1_1 - f * a0_1, nz);
            a1_2 = select(a1_2, a1_2 - f * a0_2, nz);
            a1_3 = select(a1_3, a1_3 - f * a0_3, nz);
            a1_4 = select(a1_4, a1_4 - f * a0_4, nz);
            a1_5 = select(a1_5, a1_5 - f * a0_5, nz);
            a1_6 = select(a1_6, a1_6 - f * a0_6, nz);
            a1_7 = select(a1_7, a1_7 - f * a0_7, nz);
            x1 = select(x1, x1 - f * x0, nz); }
        { let f = a2_0 * inv; let nz = f != Scalar(0.0);
            a2_1 = select(a2_1, a2_1 - f * a0_1, nz);
            a2_2 = select(a2_2, a2_2 - f * a0_2, nz);
            a2_3 = select(a2_3, a2_3 - f * a0_3, nz);
            a2_4 = select(a2_4, a2_4 - f * a0_4, nz);
            a2_5 = select(a2_5, a2_5 - f * a0_5, nz);
            a2_6 = select(a2_6, a2_6 - f * a0_6, nz);
            a2_7 = select(a2_7, a2_7 - f * a0_7, nz);
            x2 = select(x2, x2 - f * x0, nz); }
        { let f = a3_0 * inv; let nz = f != Scalar(0.0);
            a3_1 = select(a3_1, a3_1 - f * a0_1, nz);
            a3_2 = select(a3_2, a3_2 - f * a0_2, nz);
            a3_3 = select(a3_3, a3_3 - f * a0_3, nz);
            a3_4 = select(a3_4, a3_4 - f * a0_4, nz);
            a3_5 = select(a3_5, a3_5 - f * a0_5, nz);
            a3_6 = select(a3_6, a3_6 - f * a0_6, nz);
            a3_7 = select(a3_7, a3_7 - f * a0_7, nz);
            x3 = select(x3, x3 - f * x0, nz); }
        { let f = a4_0 * inv; let nz = f != Scalar(0.0);
            a4_1 = select(a4_1, a4_1 - f * a0_1, nz);
            a4_2 = select(a4_2, a4_2 - f * a0_2, nz);
            a4_3 = select(a4_3, a4_3 - f * a0_3, nz);
            a4_4 = select(a4_4, a4_4 - f * a0_4, nz);
            a4_5 = select(a4_5, a4_5 - f * a0_5, nz);
            a4_6 = select(a4_6, a4_6 - f * a0_6, nz);
            a4_7 = select(a4_7, a4_7 - f * a0_7, nz);
            x4 = select(x4, x4 - f * x0, nz); }
        { let f = a5_0 * inv; let nz = f != Scalar(0.0);
            a5_1 = select(a5_1, a5_1 - f * a0_1, nz);
            a5_2 = select(a5_2, a5_2 - f * a0_2, nz);
            a5_3 = select(a5_3, a5_3 - f * a0_3, nz);
            a5_4 = select(a5_4, a5_4 - f * a0_4, nz);
            a5_5 = select(a5_5, a5_5 - f * a0_5, nz);
            a5_6 = select(a5_6, a5_6 - f * a0_6, nz);
            a5_7 = select(a5_7, a5_7 - f * a0_7, nz);
            x5 = select(x5, x5 - f * x0, nz); }
        { let f = a6_0 * inv; let nz = f != Scalar(0.0);
            a6_1 = select(a6_1, a6_1 - f * a0_1, nz);
            a6_2 = select(a6_2, a6_2 - f * a0_2, nz);
            a6_3 = select(a6_3, a6_3 - f * a0_3, nz);
            a6_4 = select(a6_4, a6_4 - f * a0_4, nz);
            a6_5 = select(a6_5, a6_5 - f * a0_5, nz);
            a6_6 = select(a6_6, a6_6 - f * a0_6, nz);
            a6_7 = select(a6_7, a6_7 - f * a0_7, nz);
            x6 = select(x6, x6 - f * x0, nz); }
        { let f = a7_0 * inv; let nz = f != Scalar(0.0);
            a7_1 = select(a7_1, a7_1 - f * a0_1, nz);
            a7_2 = select(a7_2, a7_2 - f * a0_2, nz);
            a7_3 = select(a7_3, a7_3 - f * a0_3, nz);
            a7_4 = select(a7_4, a7_4 - f * a0_4, nz);
            a7_5 = select(a7_5, a7_5 - f * a0_5, nz);
            a7_6 = select(a7_6, a7_6 - f * a0_6, nz);
            a7_7 = select(a7_7, a7_7 - f * a0_7, nz);
            x7 = select(x7, x7 - f * x0, nz); }
    }
    {
        var best = abs(a1_1);
        var p = 1u;
        { let v = abs(a2_1); let g = v > best; p = select(p, 2u, g); best = select(best, v, g); }
        { let v = abs(a3_1); let g = v > best; p = select(p, 3u, g); best = select(best, v, g); }
        { let v = abs(a4_1); let g = v > best; p = select(p, 4u, g); best = select(best, v, g); }
        { let v = abs(a5_1); let g = v > best; p = select(p, 5u, g); best = select(best, v, g); }
        { let v = abs(a6_1); let g = v > best; p = select(p, 6u, g); best = select(best, v, g); }
        { let v = abs(a7_1); let g = v > best; p = select(p, 7u, g); best = select(best, v, g); }
        if !(best > tol.pivot * cm1) || best == Scalar(0.0) { return SINGULAR; }
        { let sw = p == 2u;
            { let t = a1_1; a1_1 = select(a1_1, a2_1, sw); a2_1 = select(a2_1, t, sw); }
            { let t = a1_2; a1_2 = select(a1_2, a2_2, sw); a2_2 = select(a2_2, t, sw); }
            { let t = a1_3; a1_3 = select(a1_3, a2_3, sw); a2_3 = select(a2_3, t, sw); }
            { let t = a1_4; a1_4 = select(a1_4, a2_4, sw); a2_4 = select(a2_4, t, sw); }
            { let t = a1_5; a1_5 = select(a1_5, a2_5, sw); a2_5 = select(a2_5, t, sw); }
            { let t = a1_6; a1_6 = select(a1_6, a2_6, sw); a2_6 = select(a2_6, t, sw); }
            { let t = a1_7; a1_7 = select(a1_7, a2_7, sw); a2_7 = select(a2_7, t, sw); }
            { let t = x1; x1 = select(x1, x2, sw); x2 = select(x2, t, sw); } }
        { let sw = p == 3u;
            { let t = a1_1; a1_1 = select(a1_1, a3_1, sw); a3_1 = select(a3_1, t, sw); }
            { let t = a1_2; a1_2 = select(a1_2, a3_2, sw); a3_2 = select(a3_2, t, sw); }
            { let t = a1_3; a1_3 = select(a1_3, a3_3, sw); a3_3 = select(a3_3, t, sw); }
            { let t = a1_4; a1_4 = select(a1_4, a3_4, sw); a3_4 = select(a3_4, t, sw); }
            { let t = a1_5; a1_5 = select(a1_5, a3_5, sw); a3_5 = select(a3_5, t, sw); }
            { let t = a1_6; a1_6 = select(a1_6, a3_6, sw); a3_6 = select(a3_6, t, sw); }
            { let t = a1_7; a1_7 = select(a1_7, a3_7, sw); a3_7 = select(a3_7, t, sw); }
            { let t = x1; x1 = select(x1, x3, sw); x3 = select(x3, t, sw); } }
        { let sw = p == 4u;
            { let t = a1_1; a1_1 = select(a1_1, a4_1, sw); a4_1 = select(a4_1, t, sw); }
            { let t = a1_2; a1_2 = select(a1_2, a4_2, sw); a4_2 = select(a4_2, t, sw); }
            { let t = a1_3; a1_3 = select(a1_3, a4_3, sw); a4_3 = select(a4_3, t, sw); }
            { let t = a1_4; a1_4 = select(a1_4, a4_4, sw); a4_4 = select(a4_4, t, sw); }
            { let t = a1_5; a1_5 = select(a1_5, a4_5, sw); a4_5 = select(a4_5, t, sw); }
            { let t = a1_6; a1_6 = select(a1_6, a4_6, sw); a4_6 = select(a4_6, t, sw); }
            { let t = a1_7; a1_7 = select(a1_7, a4_7, sw); a4_7 = select(a4_7, t, sw); }
            { let t = x1; x1 = select(x1, x4, sw); x4 = select(x4, t, sw); } }
        { let sw = p == 5u;
            { let t = a1_1; a1_1 = select(a1_1, a5_1, sw); a5_1 = select(a5_1, t, sw); }
            { let t = a1_2; a1_2 = select(a1_2, a5_2, sw); a5_2 = select(a5_2, t, sw); }
            { let t = a1_3; a1_3 = select(a1_3, a5_3, sw); a5_3 = select(a5_3, t, sw); }
            { let t = a1_4; a1_4 = select(a1_4, a5_4, sw); a5_4 = select(a5_4, t, sw); }
            { let t = a1_5; a1_5 = select(a1_5, a5_5, sw); a5_5 = select(a5_5, t, sw); }
            { let t = a1_6; a1_6 = select(a1_6, a5_6, sw); a5_6 = select(a5_6, t, sw); }
            { let t = a1_7; a1_7 = select(a1_7, a5_7, sw); a5_7 = select(a5_7, t, sw); }
            { let t = x1; x1 = select(x1, x5, sw); x5 = select(x5, t, sw); } }
        { let sw = p == 6u;
            { let t = a1_1; a1_1 = select(a1_1, a6_1, sw); a6_1 = select(a6_1, t, sw); }
            { let t = a1_2; a1_2 = select(a1_2, a6_2, sw); a6_2 = select(a6_2, t, sw); }
            { let t = a1_3; a1_3 = select(a1_3, a6_3, sw); a6_3 = select(a6_3, t, sw); }
            { let t = a1_4; a1_4 = select(a1_4, a6_4, sw); a6_4 = select(a6_4, t, sw); }
            { let t = a1_5; a1_5 = select(a1_5, a6_5, sw); a6_5 = select(a6_5, t, sw); }
            { let t = a1_6; a1_6 = select(a1_6, a6_6, sw); a6_6 = select(a6_6, t, sw); }
            { let t = a1_7; a1_7 = select(a1_7, a6_7, sw); a6_7 = select(a6_7, t, sw); }
            { let t = x1; x1 = select(x1, x6, sw); x6 = select(x6, t, sw); } }
        { let sw = p == 7u;
            { let t = a1_1; a1_1 = select(a1_1, a7_1, sw); a7_1 = select(a7_1, t, sw); }
            { let t = a1_2; a1_2 = select(a1_2, a7_2, sw); a7_2 = select(a7_2, t, sw); }
            { let t = a1_3; a1_3 = select(a1_3, a7_3, sw); a7_3 = select(a7_3, t, sw); }
            { let t = a1_4; a1_4 = select(a1_4, a7_4, sw); a7_4 = select(a7_4, t, sw); }
            { let t = a1_5; a1_5 = select(a1_5, a7_5, sw); a7_5 = select(a7_5, t, sw); }
            { let t = a1_6; a1_6 = select(a1_6, a7_6, sw); a7_6 = select(a7_6, t, sw); }
            { let t = a1_7; a1_7 = select(a1_7, a7_7, sw); a7_7 = select(a7_7, t, sw); }
            { let t = x1; x1 = select(x1, x7, sw); x7 = select(x7, t, sw); } }
        let inv = Scalar(1.0) / a1_1;
        { let f = a2_1 * inv; let nz = f != Scalar(0.0);
            a2_2 = select(a2_2, a2_2 - f * a1_2, nz);
            a2_3 = select(a2_3, a2_3 - f * a1_3, nz);
            a2_4 = select(a2_4, a2_4 - f * a1_4, nz);
            a2_5 = select(a2_5, a2_5 - f * a1_5, nz);
            a2_6 = select(a2_6, a2_6 - f * a1_6, nz);
            a2_7 = select(a2_7, a2_7 - f * a1_7, nz);
            x2 = select(x2, x2 - f * x1, nz); }
        { let f = a3_1 * inv; let nz = f != Scalar(0.0);
            a3_2 = select(a3_2, a3_2 - f * a1_2, nz);
            a3_3 = select(a3_3, a3_3 - f * a1_3, nz);
            a3_4 = select(a3_4, a3_4 - f * a1_4, nz);
            a3_5 = select(a3_5, a3_5 - f * a1_5, nz);
            a3_6 = select(a3_6, a3_6 - f * a1_6, nz);
            a3_7 = select(a3_7, a3_7 - f * a1_7, nz);
            x3 = select(x3, x3 - f * x1, nz); }
        { let f = a4_1 * inv; let nz = f != Scalar(0.0);
            a4_2 = select(a4_2, a4_2 - f * a1_2, nz);
            a4_3 = select(a4_3, a4_3 - f * a1_3, nz);
            a4_4 = select(a4_4, a4_4 - f * a1_4, nz);
            a4_5 = select(a4_5, a4_5 - f * a1_5, nz);
            a4_6 = select(a4_6, a4_6 - f * a1_6, nz);
            a4_7 = select(a4_7, a4_7 - f * a1_7, nz);
            x4 = select(x4, x4 - f * x1, nz); }
        { let f = a5_1 * inv; let nz = f != Scalar(0.0);
            a5_2 = select(a5_2, a5_2 - f * a1_2, nz);
            a5_3 = select(a5_3, a5_3 - f * a1_3, nz);
            a5_4 = select(a5_4, a5_4 - f * a1_4, nz);
            a5_5 = select(a5_5, a5_5 - f * a1_5, nz);
            a5_6 = select(a5_6, a5_6 - f * a1_6, nz);
            a5_7 = select(a5_7, a5_7 - f * a1_7, nz);
            x5 = select(x5, x5 - f * x1, nz); }
        { let f = a6_1 * inv; let nz = f != Scalar(0.0);
            a6_2 = select(a6_2, a6_2 - f * a1_2, nz);
            a6_3 = select(a6_3, a6_3 - f * a1_3, nz);
            a6_4 = select(a6_4, a6_4 - f * a1_4, nz);
            a6_5 = select(a6_5, a6_5 - f * a1_5, nz);
            a6_6 = select(a6_6, a6_6 - f * a1_6, nz);
            a6_7 = select(a6_7, a6_7 - f * a1_7, nz);
            x6 = select(x6, x6 - f * x1, nz); }
        { let f = a7_1 * inv; let nz = f != Scalar(0.0);
            a7_2 = select(a7_2, a7_2 - f * a1_2, nz);
            a7_3 = select(a7_3, a7_3 - f * a1_3, nz);
            a7_4 = select(a7_4, a7_4 - f * a1_4, nz);
            a7_5 = select(a7_5, a7_5 - f * a1_5, nz);
            a7_6 = select(a7_6, a7_6 - f * a1_6, nz);
            a7_7 = select(a7_7, a7_7 - f * a1_7, nz);
            x7 = select(x7, x7 - f * x1, nz); }
    }
    {
        var best = abs(a2_2);
        var p = 2u;
        { let v = abs(a3_2); let g = v > best; p = select(p, 3u, g); best = select(best, v, g); }
        { let v = abs(a4_2); let g = v > best; p = select(p, 4u, g); best = select(best, v, g); }
        { let v = abs(a5_2); let g = v > best; p = select(p, 5u, g); best = select(best, v, g); }
        { let v = abs(a6_2); let g = v > best; p = select(p, 6u, g); best = select(best, v, g); }
        { let v = abs(a7_2); let g = v > best; p = select(p, 7u, g); best = select(best, v, g); }
        if !(best > tol.pivot * cm2) || best == Scalar(0.0) { return SINGULAR; }
        { let sw = p == 3u;
            { let t = a2_2; a2_2 = select(a2_2, a3_2, sw); a3_2 = select(a3_2, t, sw); }
            { let t = a2_3; a2_3 = select(a2_3, a3_3, sw); a3_3 = select(a3_3, t, sw); }
            { let t = a2_4; a2_4 = select(a2_4, a3_4, sw); a3_4 = select(a3_4, t, sw); }
            { let t = a2_5; a2_5 = select(a2_5, a3_5, sw); a3_5 = select(a3_5, t, sw); }
            { let t = a2_6; a2_6 = select(a2_6, a3_6, sw); a3_6 = select(a3_6, t, sw); }
            { let t = a2_7; a2_7 = select(a2_7, a3_7, sw); a3_7 = select(a3_7, t, sw); }
            { let t = x2; x2 = select(x2, x3, sw); x3 = select(x3, t, sw); } }
        { let sw = p == 4u;
            { let t = a2_2; a2_2 = select(a2_2, a4_2, sw); a4_2 = select(a4_2, t, sw); }
            { let t = a2_3; a2_3 = select(a2_3, a4_3, sw); a4_3 = select(a4_3, t, sw); }
            { let t = a2_4; a2_4 = select(a2_4, a4_4, sw); a4_4 = select(a4_4, t, sw); }
            { let t = a2_5; a2_5 = select(a2_5, a4_5, sw); a4_5 = select(a4_5, t, sw); }
            { let t = a2_6; a2_6 = select(a2_6, a4_6, sw); a4_6 = select(a4_6, t, sw); }
            { let t = a2_7; a2_7 = select(a2_7, a4_7, sw); a4_7 = select(a4_7, t, sw); }
            { let t = x2; x2 = select(x2, x4, sw); x4 = select(x4, t, sw); } }
        { let sw = p == 5u;
            { let t = a2_2; a2_2 = select(a2_2, a5_2, sw); a5_2 = select(a5_2, t, sw); }
            { let t = a2_3; a2_3 = select(a2_3, a5_3, sw); a5_3 = select(a5_3, t, sw); }
            { let t = a2_4; a2_4 = select(a2_4, a5_4, sw); a5_4 = select(a5_4, t, sw); }
            { let t = a2_5; a2_5 = select(a2_5, a5_5, sw); a5_5 = select(a5_5, t, sw); }
            { let t = a2_6; a2_6 = select(a2_6, a5_6, sw); a5_6 = select(a5_6, t, sw); }
            { let t = a2_7; a2_7 = select(a2_7, a5_7, sw); a5_7 = select(a5_7, t, sw); }
            { let t = x2; x2 = select(x2, x5, sw); x5 = select(x5, t, sw); } }
        { let sw = p == 6u;
            { let t = a2_2; a2_2 = select(a2_2, a6_2, sw); a6_2 = select(a6_2, t, sw); }
            { let t = a2_3; a2_3 = select(a2_3, a6_3, sw); a6_3 = select(a6_3, t, sw); }
            { let t = a2_4; a2_4 = select(a2_4, a6_4, sw); a6_4 = select(a6_4, t, sw); }
            { let t = a2_5; a2_5 = select(a2_5, a6_5, sw); a6_5 = select(a6_5, t, sw); }
            { let t = a2_6; a2_6 = select(a2_6, a6_6, sw); a6_6 = select(a6_6, t, sw); }
            { let t = a2_7; a2_7 = select(a2_7, a6_7, sw); a6_7 = select(a6_7, t, sw); }
            { let t = x2; x2 = select(x2, x6, sw); x6 = select(x6, t, sw); } }
        { let sw = p == 7u;
            { let t = a2_2; a2_2 = select(a2_2, a7_2, sw); a7_2 = select(a7_2, t, sw); }
            { let t = a2_3; a2_3 = select(a2_3, a7_3, sw); a7_3 = select(a7_3, t, sw); }
            { let t = a2_4; a2_4 = select(a2_4, a7_4, sw); a7_4 = select(a7_4, t, sw); }
            { let t = a2_5; a2_5 = select(a2_5, a7_5, sw); a7_5 = select(a7_5, t, sw); }
            { let t = a2_6; a2_6 = select(a2_6, a7_6, sw); a7_6 = select(a7_6, t, sw); }
            { let t = a2_7; a2_7 = select(a2_7, a7_7, sw); a7_7 = select(a7_7, t, sw); }
            { let t = x2; x2 = select(x2, x7, sw); x7 = select(x7, t, sw); } }
        let inv = Scalar(1.0) / a2_2;
        { let f = a3_2 * inv; let nz = f != Scalar(0.0);
            a3_3 = select(a3_3, a3_3 - f * a2_3, nz);
            a3_4 = select(a3_4, a3_4 - f * a2_4, nz);
            a3_5 = select(a3_5, a3_5 - f * a2_5, nz);
            a3_6 = select(a3_6, a3_6 - f * a2_6, nz);
            a3_7 = select(a3_7, a3_7 - f * a2_7, nz);
            x3 = select(x3, x3 - f * x2, nz); }
        { let f = a4_2 * inv; let nz = f != Scalar(0.0);
            a4_3 = select(a4_3, a4_3 - f * a2_3, nz);
            a4_4 = select(a4_4, a4_4 - f * a2_4, nz);
            a4_5 = select(a4_5, a4_5 - f * a2_5, nz);
            a4_6 = select(a4_6, a4_6 - f * a2_6, nz);
            a4_7 = select(a4_7, a4_7 - f * a2_7, nz);
            x4 = select(x4, x4 - f * x2, nz); }
        { let f = a5_2 * inv; let nz = f != Scalar(0.0);
            a5_3 = select(a5_3, a5_3 - f * a2_3, nz);
            a5_4 = select(a5_4, a5_4 - f * a2_4, nz);
            a5_5 = select(a5_5, a5_5 - f * a2_5, nz);
            a5_6 = select(a5_6, a5_6 - f * a2_6, nz);
            a5_7 = select(a5_7, a5_7 - f * a2_7, nz);
            x5 = select(x5, x5 - f * x2, nz); }
        { let f = a6_2 * inv; let nz = f != Scalar(0.0);
            a6_3 = select(a6_3, a6_3 - f * a2_3, nz);
            a6_4 = select(a6_4, a6_4 - f * a2_4, nz);
            a6_5 = select(a6_5, a6_5 - f * a2_5, nz);
            a6_6 = select(a6_6, a6_6 - f * a2_6, nz);
            a6_7 = select(a6_7, a6_7 - f * a2_7, nz);
            x6 = select(x6, x6 - f * x2, nz); }
        { let f = a7_2 * inv; let nz = f != Scalar(0.0);
            a7_3 = select(a7_3, a7_3 - f * a2_3, nz);
            a7_4 = select(a7_4, a7_4 - f * a2_4, nz);
            a7_5 = select(a7_5, a7_5 - f * a2_5, nz);
            a7_6 = select(a7_6, a7_6 - f * a2_6, nz);
            a7_7 = select(a7_7, a7_7 - f * a2_7, nz);
            x7 = select(x7, x7 - f * x2, nz); }
    }
    {
        var best = abs(a3_3);
        var p = 3u;
        { let v = abs(a4_3); let g = v > best; p = select(p, 4u, g); best = select(best, v, g); }
        { let v = abs(a5_3); let g = v > best; p = select(p, 5u, g); best = select(best, v, g); }
        { let v = abs(a6_3); let g = v > best; p = select(p, 6u, g); best = select(best, v, g); }
        { let v = abs(a7_3); let g = v > best; p = select(p, 7u, g); best = select(best, v, g); }
        if !(best > tol.pivot * cm3) || best == Scalar(0.0) { return SINGULAR; }
        { let sw = p == 4u;
            { let t = a3_3; a3_3 = select(a3_3, a4_3, sw); a4_3 = select(a4_3, t, sw); }
            { let t = a3_4; a3_4 = select(a3_4, a4_4, sw); a4_4 = select(a4_4, t, sw); }
            { let t = a3_5; a3_5 = select(a3_5, a4_5, sw); a4_5 = select(a4_5, t, sw); }
            { let t = a3_6; a3_6 = select(a3_6, a4_6, sw); a4_6 = select(a4_6, t, sw); }
            { let t = a3_7; a3_7 = select(a3_7, a4_7, sw); a4_7 = select(a4_7, t, sw); }
            { let t = x3; x3 = select(x3, x4, sw); x4 = select(x4, t, sw); } }
        { let sw = p == 5u;
            { let t = a3_3; a3_3 = select(a3_3, a5_3, sw); a5_3 = select(a5_3, t, sw); }
            { let t = a3_4; a3_4 = select(a3_4, a5_4, sw); a5_4 = select(a5_4, t, sw); }
            { let t = a3_5; a3_5 = select(a3_5, a5_5, sw); a5_5 = select(a5_5, t, sw); }
            { let t = a3_6; a3_6 = select(a3_6, a5_6, sw); a5_6 = select(a5_6, t, sw); }
            { let t = a3_7; a3_7 = select(a3_7, a5_7, sw); a5_7 = select(a5_7, t, sw); }
            { let t = x3; x3 = select(x3, x5, sw); x5 = select(x5, t, sw); } }
        { let sw = p == 6u;
            { let t = a3_3; a3_3 = select(a3_3, a6_3, sw); a6_3 = select(a6_3, t, sw); }
            { let t = a3_4; a3_4 = select(a3_4, a6_4, sw); a6_4 = select(a6_4, t, sw); }
            { let t = a3_5; a3_5 = select(a3_5, a6_5, sw); a6_5 = select(a6_5, t, sw); }
            { let t = a3_6; a3_6 = select(a3_6, a6_6, sw); a6_6 = select(a6_6, t, sw); }
            { let t = a3_7; a3_7 = select(a3_7, a6_7, sw); a6_7 = select(a6_7, t, sw); }
            { let t = x3; x3 = select(x3, x6, sw); x6 = select(x6, t, sw); } }
        { let sw = p == 7u;
            { let t = a3_3; a3_3 = select(a3_3, a7_3, sw); a7_3 = select(a7_3, t, sw); }
            { let t = a3_4; a3_4 = select(a3_4, a7_4, sw); a7_4 = select(a7_4, t, sw); }
            { let t = a3_5; a3_5 = select(a3_5, a7_5, sw); a7_5 = select(a7_5, t, sw); }
            { let t = a3_6; a3_6 = select(a3_6, a7_6, sw); a7_6 = select(a7_6, t, sw); }
            { let t = a3_7; a3_7 = select(a3_7, a7_7, sw); a7_7 = select(a7_7, t, sw); }
            { let t = x3; x3 = select(x3, x7, sw); x7 = select(x7, t, sw); } }
        let inv = Scalar(1.0) / a3_3;
        { let f = a4_3 * inv; let nz = f != Scalar(0.0);
            a4_4 = select(a4_4, a4_4 - f * a3_4, nz);
            a4_5 = select(a4_5, a4_5 - f * a3_5, nz);
            a4_6 = select(a4_6, a4_6 - f * a3_6, nz);
            a4_7 = select(a4_7, a4_7 - f * a3_7, nz);
            x4 = select(x4, x4 - f * x3, nz); }
        { let f = a5_3 * inv; let nz = f != Scalar(0.0);
            a5_4 = select(a5_4, a5_4 - f * a3_4, nz);
            a5_5 = select(a5_5, a5_5 - f * a3_5, nz);
            a5_6 = select(a5_6, a5_6 - f * a3_6, nz);
            a5_7 = select(a5_7, a5_7 - f * a3_7, nz);
            x5 = select(x5, x5 - f * x3, nz); }
        { let f = a6_3 * inv; let nz = f != Scalar(0.0);
            a6_4 = select(a6_4, a6_4 - f * a3_4, nz);
            a6_5 = select(a6_5, a6_5 - f * a3_5, nz);
            a6_6 = select(a6_6, a6_6 - f * a3_6, nz);
            a6_7 = select(a6_7, a6_7 - f * a3_7, nz);
            x6 = select(x6, x6 - f * x3, nz); }
        { let f = a7_3 * inv; let nz = f != Scalar(0.0);
            a7_4 = select(a7_4, a7_4 - f * a3_4, nz);
            a7_5 = select(a7_5, a7_5 - f * a3_5, nz);
            a7_6 = select(a7_6, a7_6 - f * a3_6, nz);
            a7_7 = select(a7_7, a7_7 - f * a3_7, nz);
            x7 = select(x7, x7 - f * x3, nz); }
    }
    {
        var best = abs(a4_4);
        var p = 4u;
        { let v = abs(a5_4); let g = v > best; p = select(p, 5u, g); best = select(best, v, g); }
        { let v = abs(a6_4); let g = v > best; p = select(p, 6u, g); best = select(best, v, g); }
        { let v = abs(a7_4); let g = v > best; p = select(p, 7u, g); best = select(best, v, g); }
        if !(best > tol.pivot * cm4) || best == Scalar(0.0) { return SINGULAR; }
        { let sw = p == 5u;
            { let t = a4_4; a4_4 = select(a4_4, a5_4, sw); a5_4 = select(a5_4, t, sw); }
            { let t = a4_5; a4_5 = select(a4_5, a5_5, sw); a5_5 = select(a5_5, t, sw); }
            { let t = a4_6; a4_6 = select(a4_6, a5_6, sw); a5_6 = select(a5_6, t, sw); }
            { let t = a4_7; a4_7 = select(a4_7, a5_7, sw); a5_7 = select(a5_7, t, sw); }
            { let t = x4; x4 = select(x4, x5, sw); x5 = select(x5, t, sw); } }
        { let sw = p == 6u;
            { let t = a4_4; a4_4 = select(a4_4, a6_4, sw); a6_4 = select(a6_4, t, sw); }
            { let t = a4_5; a4_5 = select(a4_5, a6_5, sw); a6_5 = select(a6_5, t, sw); }
            { let t = a4_6; a4_6 = select(a4_6, a6_6, sw); a6_6 = select(a6_6, t, sw); }
            { let t = a4_7; a4_7 = select(a4_7, a6_7, sw); a6_7 = select(a6_7, t, sw); }
            { let t = x4; x4 = select(x4, x6, sw); x6 = select(x6, t, sw); } }
        { let sw = p == 7u;
            { let t = a4_4; a4_4 = select(a4_4, a7_4, sw); a7_4 = select(a7_4, t, sw); }
            { let t = a4_5; a4_5 = select(a4_5, a7_5, sw); a7_5 = select(a7_5, t, sw); }
            { let t = a4_6; a4_6 = select(a4_6, a7_6, sw); a7_6 = select(a7_6, t, sw); }
            { let t = a4_7; a4_7 = select(a4_7, a7_7, sw); a7_7 = select(a7_7, t, sw); }
            { let t = x4; x4 = select(x4, x7, sw); x7 = select(x7, t, sw); } }
        let inv = Scalar(1.0) / a4_4;
        { let f = a5_4 * inv; let nz = f != Scalar(0.0);
            a5_5 = select(a5_5, a5_5 - f * a4_5, nz);
            a5_6 = select(a5_6, a5_6 - f * a4_6, nz);
            a5_7 = select(a5_7, a5_7 - f * a4_7, nz);
            x5 = select(x5, x5 - f * x4, nz); }
        { let f = a6_4 * inv; let nz = f != Scalar(0.0);
            a6_5 = select(a6_5, a6_5 - f * a4_5, nz);
            a6_6 = select(a6_6, a6_6 - f * a4_6, nz);
            a6_7 = select(a6_7, a6_7 - f * a4_7, nz);
            x6 = select(x6, x6 - f * x4, nz); }
        { let f = a7_4 * inv; let nz = f != Scalar(0.0);
            a7_5 = select(a7_5, a7_5 - f * a4_5, nz);
            a7_6 = select(a7_6, a7_6 - f * a4_6, nz);
            a7_7 = select(a7_7, a7_7 - f * a4_7, nz);
            x7 = select(x7, x7 - f * x4, nz); }
    }
    {
        var best = abs(a5_5);
        var p = 5u;
        { let v = abs(a6_5); let g = v > best; p = select(p, 6u, g); best = select(best, v, g); }
        { let v = abs(a7_5); let g = v > best; p = select(p, 7u, g); best = select(best, v, g); }
        if !(best > tol.pivot * cm5) || best == Scalar(0.0) { return SINGULAR; }
        { let sw = p == 6u;
            { let t = a5_5; a5_5 = select(a5_5, a6_5, sw); a6_5 = select(a6_5, t, sw); }
            { let t = a5_6; a5_6 = select(a5_6, a6_6, sw); a6_6 = select(a6_6, t, sw); }
            { let t = a5_7; a5_7 = select(a5_7, a6_7, sw); a6_7 = select(a6_7, t, sw); }
            { let t = x5; x5 = select(x5, x6, sw); x6 = select(x6, t, sw); } }
        { let sw = p == 7u;
            { let t = a5_5; a5_5 = select(a5_5, a7_5, sw); a7_5 = select(a7_5, t, sw); }
            { let t = a5_6; a5_6 = select(a5_6, a7_6, sw); a7_6 = select(a7_6, t, sw); }
            { let t = a5_7; a5_7 = select(a5_7, a7_7, sw); a7_7 = select(a7_7, t, sw); }
            { let t = x5; x5 = select(x5, x7, sw); x7 = select(x7, t, sw); } }
        let inv = Scalar(1.0) / a5_5;
        { let f = a6_5 * inv; let nz = f != Scalar(0.0);
            a6_6 = select(a6_6, a6_6 - f * a5_6, nz);
            a6_7 = select(a6_7, a6_7 - f * a5_7, nz);
            x6 = select(x6, x6 - f * x5, nz); }
        { let f = a7_5 * inv; let nz = f != Scalar(0.0);
            a7_6 = select(a7_6, a7_6 - f * a5_6, nz);
            a7_7 = select(a7_7, a7_7 - f * a5_7, nz);
            x7 = select(x7, x7 - f * x5, nz); }
    }
    {
        var best = abs(a6_6);
        var p = 6u;
        { let v = abs(a7_6); let g = v > best; p = select(p, 7u, g); best = select(best, v, g); }
        if !(best > tol.pivot * cm6) || best == Scalar(0.0) { return SINGULAR; }
        { let sw = p == 7u;
            { let t = a6_6; a6_6 = select(a6_6, a7_6, sw); a7_6 = select(a7_6, t, sw); }
            { let t = a6_7; a6_7 = select(a6_7, a7_7, sw); a7_7 = select(a7_7, t, sw); }
            { let t = x6; x6 = select(x6, x7, sw); x7 = select(x7, t, sw); } }
        let inv = Scalar(1.0) / a6_6;
        { let f = a7_6 * inv; let nz = f != Scalar(0.0);
            a7_7 = select(a7_7, a7_7 - f * a6_7, nz);
            x7 = select(x7, x7 - f * x6, nz); }
    }
    {
        var best = abs(a7_7);
        var p = 7u;
        if !(best > tol.pivot * cm7) || best == Scalar(0.0) { return SINGULAR; }
        let inv = Scalar(1.0) / a7_7;
    }
    { var s = x7;
        x7 = s / a7_7; }
    { var s = x6;
        s = s - a6_7 * x7;
        x6 = s / a6_6; }
    { var s = x5;
        s = s - a5_6 * x6;
        s = s - a5_7 * x7;
        x5 = s / a5_5; }
    { var s = x4;
        s = s - a4_5 * x5;
        s = s - a4_6 * x6;
        s = s - a4_7 * x7;
        x4 = s / a4_4; }
    { var s = x3;
        s = s - a3_4 * x4;
        s = s - a3_5 * x5;
        s = s - a3_6 * x6;
        s = s - a3_7 * x7;
        x3 = s / a3_3; }
    { var s = x2;
        s = s - a2_3 * x3;
        s = s - a2_4 * x4;
        s = s - a2_5 * x5;
        s = s - a2_6 * x6;
        s = s - a2_7 * x7;
        x2 = s / a2_2; }
    { var s = x1;
        s = s - a1_2 * x2;
        s = s - a1_3 * x3;
        s = s - a1_4 * x4;
        s = s - a1_5 * x5;
        s = s - a1_6 * x6;
        s = s - a1_7 * x7;
        x1 = s / a1_1; }
    { var s = x0;
        s = s - a0_1 * x1;
        s = s - a0_2 * x2;
        s = s - a0_3 * x3;
        s = s - a0_4 * x4;
        s = s - a0_5 * x5;
        s = s - a0_6 * x6;
        s = s - a0_7 * x7;
        x0 = s / a0_0; }
    fx[0] = x0;
    fx[1] = x1;
    fx[2] = x2;
    fx[3] = x3;
    fx[4] = x4;
    fx[5] = x5;
    fx[6] = x6;
    fx[7] = x7;
    var zmax = Scalar(0.0);
    if b0 { zmax = max(zmax, abs(x0)); }
    if b1 { zmax = max(zmax, abs(x1)); }
    if b2 { zmax = max(zmax, abs(x2)); }
    if b3 { zmax = max(zmax, abs(x3)); }
    if b4 { zmax = max(zmax, abs(x4)); }
    if b5 { zmax = max(zmax, abs(x5)); }
    if b6 { zmax = max(zmax, abs(x6)); }
    if b7 { zmax = max(zmax, abs(x7)); }
    var worst = Scalar(0.0);
    if b0 && x0 < Scalar(0.0) { worst = max(worst, -x0 / zmax); }
    if b1 && x1 < Scalar(0.0) { worst = max(worst, -x1 / zmax); }
    if b2 && x2 < Scalar(0.0) { worst = max(worst, -x2 / zmax); }
    if b3 && x3 < Scalar(0.0) { worst = max(worst, -x3 / zmax); }
    if b4 && x4 < Scalar(0.0) { worst = max(worst, -x4 / zmax); }
    if b5 && x5 < Scalar(0.0) { worst = max(worst, -x5 / zmax); }
    if b6 && x6 < Scalar(0.0) { worst = max(worst, -x6 / zmax); }
    if b7 && x7 < Scalar(0.0) { worst = max(worst, -x7 / zmax); }
    if worst > tol.relaxed { return worst; }
    if !b0 {
        var w = values[qbase + 0u];
        var scale = abs(w);
        if b0 { let t = values[base + 0u] * x0; w += t; scale += abs(t); }
        if b1 { let t = values[base + 1u] * x1; w += t; scale += abs(t); }
        if b2 { let t = values[base + 2u] * x2; w += t; scale += abs(t); }
        if b3 { let t = values[base + 3u] * x3; w += t; scale += abs(t); }
        if b4 { let t = values[base + 4u] * x4; w += t; scale += abs(t); }
        if b5 { let t = values[base + 5u] * x5; w += t; scale += abs(t); }
        if b6 { let t = values[base + 6u] * x6; w += t; scale += abs(t); }
        if b7 { let t = values[base + 7u] * x7; w += t; scale += abs(t); }
        if w < Scalar(0.0) { worst = max(worst, -w / scale); if worst > tol.relaxed { return worst; } }
    }
    if !b1 {
        var w = values[qbase + 1u];
        var scale = abs(w);
        if b0 { let t = values[base + 8u] * x0; w += t; scale += abs(t); }
        if b1 { let t = values[base + 9u] * x1; w += t; scale += abs(t); }
        if b2 { let t = values[base + 10u] * x2; w += t; scale += abs(t); }
        if b3 { let t = values[base + 11u] * x3; w += t; scale += abs(t); }
        if b4 { let t = values[base + 12u] * x4; w += t; scale += abs(t); }
        if b5 { let t = values[base + 13u] * x5; w += t; scale += abs(t); }
        if b6 { let t = values[base + 14u] * x6; w += t; scale += abs(t); }
        if b7 { let t = values[base + 15u] * x7; w += t; scale += abs(t); }
        if w < Scalar(0.0) { worst = max(worst, -w / scale); if worst > tol.relaxed { return worst; } }
    }
    if !b2 {
        var w = values[qbase + 2u];
        var scale = abs(w);
        if b0 { let t = values[base + 16u] * x0; w += t; scale += abs(t); }
        if b1 { let t = values[base + 17u] * x1; w += t; scale += abs(t); }
        if b2 { let t = values[base + 18u] * x2; w += t; scale += abs(t); }
        if b3 { let t = values[base + 19u] * x3; w += t; scale += abs(t); }
        if b4 { let t = values[base + 20u] * x4; w += t; scale += abs(t); }
        if b5 { let t = values[base + 21u] * x5; w += t; scale += abs(t); }
        if b6 { let t = values[base + 22u] * x6; w += t; scale += abs(t); }
        if b7 { let t = values[base + 23u] * x7; w += t; scale += abs(t); }
        if w < Scalar(0.0) { worst = max(worst, -w / scale); if worst > tol.relaxed { return worst; } }
    }
    if !b3 {
        var w = values[qbase + 3u];
        var scale = abs(w);
        if b0 { let t = values[base + 24u] * x0; w += t; scale += abs(t); }
        if b1 { let t = values[base + 25u] * x1; w += t; scale += abs(t); }
        if b2 { let t = values[base + 26u] * x2; w += t; scale += abs(t); }
        if b3 { let t = values[base + 27u] * x3; w += t; scale += abs(t); }
        if b4 { let t = values[base + 28u] * x4; w += t; scale += abs(t); }
        if b5 { let t = values[base + 29u] * x5; w += t; scale += abs(t); }
        if b6 { let t = values[base + 30u] * x6; w += t; scale += abs(t); }
        if b7 { let t = values[base + 31u] * x7; w += t; scale += abs(t); }
        if w < Scalar(0.0) { worst = max(worst, -w / scale); if worst > tol.relaxed { return worst; } }
    }
    if !b4 {
        var w = values[qbase + 4u];
        var scale = abs(w);
        if b0 { let t = values[base + 32u] * x0; w += t; scale += abs(t); }
        if b1 { let t = values[base + 33u] * x1; w += t; scale += abs(t); }
        if b2 { let t = values[base + 34u] * x2; w += t; scale += abs(t); }
        if b3 { let t = values[base + 35u] * x3; w += t; scale += abs(t); }
        if b4 { let t = values[base + 36u] * x4; w += t; scale += abs(t); }
        if b5 { let t = values[base + 37u] * x5; w += t; scale += abs(t); }
        if b6 { let t = values[base + 38u] * x6; w += t; scale += abs(t); }
        if b7 { let t = values[base + 39u] * x7; w += t; scale += abs(t); }
        if w < Scalar(0.0) { worst = max(worst, -w / scale); if worst > tol.relaxed { return worst; } }
    }
    if !b5 {
        var w = values[qbase + 5u];
        var scale = abs(w);
        if b0 { let t = values[base + 40u] * x0; w += t; scale += abs(t); }
        if b1 { let t = values[base + 41u] * x1; w += t; scale += abs(t); }
        if b2 { let t = values[base + 42u] * x2; w += t; scale += abs(t); }
        if b3 { let t = values[base + 43u] * x3; w += t; scale += abs(t); }
        if b4 { let t = values[base + 44u] * x4; w += t; scale += abs(t); }
        if b5 { let t = values[base + 45u] * x5; w += t; scale += abs(t); }
        if b6 { let t = values[base + 46u] * x6; w += t; scale += abs(t); }
        if b7 { let t = values[base + 47u] * x7; w += t; scale += abs(t); }
        if w < Scalar(0.0) { worst = max(worst, -w / scale); if worst > tol.relaxed { return worst; } }
    }
    if !b6 {
        var w = values[qbase + 6u];
        var scale = abs(w);
        if b0 { let t = values[base + 48u] * x0; w += t; scale += abs(t); }
        if b1 { let t = values[base + 49u] * x1; w += t; scale += abs(t); }
        if b2 { let t = values[base + 50u] * x2; w += t; scale += abs(t); }
        if b3 { let t = values[base + 51u] * x3; w += t; scale += abs(t); }
        if b4 { let t = values[base + 52u] * x4; w += t; scale += abs(t); }
        if b5 { let t = values[base + 53u] * x5; w += t; scale += abs(t); }
        if b6 { let t = values[base + 54u] * x6; w += t; scale += abs(t); }
        if b7 { let t = values[base + 55u] * x7; w += t; scale += abs(t); }
        if w < Scalar(0.0) { worst = max(worst, -w / scale); if worst > tol.relaxed { return worst; } }
    }
    if !b7 {
        var w = values[qbase + 7u];
        var scale = abs(w);
        if b0 { let t = values[base + 56u] * x0; w += t; scale += abs(t); }
        if b1 { let t = values[base + 57u] * x1; w += t; scale += abs(t); }
        if b2 { let t = values[base + 58u] * x2; w += t; scale += abs(t); }
        if b3 { let t = values[base + 59u] * x3; w += t; scale += abs(t); }
        if b4 { let t = values[base + 60u] * x4; w += t; scale += abs(t); }
        if b5 { let t = values[base + 61u] * x5; w += t; scale += abs(t); }
        if b6 { let t = values[base + 62u] * x6; w += t; scale += abs(t); }
        if b7 { let t = values[base + 63u] * x7; w += t; scale += abs(t); }
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
