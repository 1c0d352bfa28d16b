// GENERATED from shaders/enumeration_basis.wgsl + shaders/enumeration_tree.wgsl by src/gpu/shaders/compose.rs: do not edit.
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

// Enumeration down the tree of bases, for islands of exactly FN contacts
// whose M is positive definite or, with params.flags bit 0, symmetric
// positive semidefinite (resting contacts; a singular pivot then cuts its
// subtree, whose bases are all singular): one invocation per island screens all 2^FN
// bases by principal pivots taken depth first, then confirms the screened
// ones by elimination in enumeration's order. CPU twin:
// src/cpu/enumeration_tree.rs (same pivots in the same order, same screen,
// same confirmation); the module docs there derive it.
//
// The screen pass, `tree_pass`, is generated by the host for each FN
// (src/gpu/shaders/tree.rs, `tree_pass_source`): straight-line code in which
// every tableau entry is a named value and every index a constant (above
// FN = 8, a loop over the bases of the first FN - 8 indices runs the
// straight-line tree of the last 8 under each). That matters on llvmpipe,
// which runs both sides of every branch under a lane mask and turns
// run-time indices into private arrays into memory traffic: here there are
// neither, and the 2^FN - 1 pivots touch only the columns still to be
// pivoted. The function below is its placeholder (no basis passes), so that
// this file is valid on its own.
//
// Output, in the BasisResult: status 1 with the basis, its z, visited =
// 2^FN, the singular count among the confirmed bases and _pad1 = DECIDED;
// or, when a pivot (outside a cut subtree) was at most tol.tree_pivot * M_dd
// (and, if semidefinite, above tol.tree_singular * M_dd) or no screened basis
// among the first MAX_CONFIRMATIONS is feasible, a record left at the start
// of an elimination (status 0, mask 0) with _pad1 = UNDECIDED, counted in
// `unfinished`: the host's next round runs the elimination kernel of the
// same size on the island (its kernels carry _pad1 through).
//
// Shared with the other enumeration kernels: shaders/enumeration_basis.wgsl
// (prepended by the generator: Scalar, the tolerances uniform `tol`,
// Island, bindings 0-7, solve_basis, write_z). The generator
// (src/gpu/shaders/compose.rs) replaces the lines marked HOST and writes
// one file per precision and FN to shaders/generated/.
//
// tol.tree_pivot: a pivot at most this times M_dd leaves the island
// undecided; tol.tree_singular (semidefinite islands, params.flags bit 0):
// a pivot at most this times M_dd is singular and cuts its subtree
// (src/cpu/enumeration_tree.rs); tol.screen: the screen's tolerance.
const MAX_CONFIRMATIONS: u32 = 8u; // HOST max_confirmations
const FN: u32 = 9u; // HOST fixed_n
// Words of the candidate bitmap: ceil(2^FN / 32).
const WORDS: u32 = 16u; // HOST words

// Params and BasisResult: shaders/enumeration_basis.wgsl.

// BasisResult._pad1: what the tree did with the island.
const DECIDED: u32 = 1u;
const UNDECIDED: u32 = 2u;

// Bit `mask` of the candidate bitmap: basis `mask` passed the screen.
// Written by tree_pass.
var<private> cand: array<u32, WORDS>;

// Placeholder of the generated screen pass: fills `cand`, returns false
// when a pivot was too small (`semi`: M is symmetric positive
// semidefinite, singular pivots cut their subtree instead).
fn tree_pass(base: u32, semi: bool) -> bool {
let m0_0 = values[base + 0u];
let m0_1 = values[base + 1u];
let m0_2 = values[base + 2u];
let m0_3 = values[base + 3u];
let m0_4 = values[base + 4u];
let m0_5 = values[base + 5u];
let m0_6 = values[base + 6u];
let m0_7 = values[base + 7u];
let m0_8 = values[base + 8u];
let rm0 = max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m0_0)), abs(m0_1)), abs(m0_2)), abs(m0_3)), abs(m0_4)), abs(m0_5)), abs(m0_6)), abs(m0_7)), abs(m0_8));
let m1_0 = values[base + 9u];
let m1_1 = values[base + 10u];
let m1_2 = values[base + 11u];
let m1_3 = values[base + 12u];
let m1_4 = values[base + 13u];
let m1_5 = values[base + 14u];
let m1_6 = values[base + 15u];
let m1_7 = values[base + 16u];
let m1_8 = values[base + 17u];
let rm1 = max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m1_0)), abs(m1_1)), abs(m1_2)), abs(m1_3)), abs(m1_4)), abs(m1_5)), abs(m1_6)), abs(m1_7)), abs(m1_8));
let m2_0 = values[base + 18u];
let m2_1 = values[base + 19u];
let m2_2 = values[base + 20u];
let m2_3 = values[base + 21u];
let m2_4 = values[base + 22u];
let m2_5 = values[base + 23u];
let m2_6 = values[base + 24u];
let m2_7 = values[base + 25u];
let m2_8 = values[base + 26u];
let rm2 = max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m2_0)), abs(m2_1)), abs(m2_2)), abs(m2_3)), abs(m2_4)), abs(m2_5)), abs(m2_6)), abs(m2_7)), abs(m2_8));
let m3_0 = values[base + 27u];
let m3_1 = values[base + 28u];
let m3_2 = values[base + 29u];
let m3_3 = values[base + 30u];
let m3_4 = values[base + 31u];
let m3_5 = values[base + 32u];
let m3_6 = values[base + 33u];
let m3_7 = values[base + 34u];
let m3_8 = values[base + 35u];
let rm3 = max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m3_0)), abs(m3_1)), abs(m3_2)), abs(m3_3)), abs(m3_4)), abs(m3_5)), abs(m3_6)), abs(m3_7)), abs(m3_8));
let m4_0 = values[base + 36u];
let m4_1 = values[base + 37u];
let m4_2 = values[base + 38u];
let m4_3 = values[base + 39u];
let m4_4 = values[base + 40u];
let m4_5 = values[base + 41u];
let m4_6 = values[base + 42u];
let m4_7 = values[base + 43u];
let m4_8 = values[base + 44u];
let rm4 = max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m4_0)), abs(m4_1)), abs(m4_2)), abs(m4_3)), abs(m4_4)), abs(m4_5)), abs(m4_6)), abs(m4_7)), abs(m4_8));
let m5_0 = values[base + 45u];
let m5_1 = values[base + 46u];
let m5_2 = values[base + 47u];
let m5_3 = values[base + 48u];
let m5_4 = values[base + 49u];
let m5_5 = values[base + 50u];
let m5_6 = values[base + 51u];
let m5_7 = values[base + 52u];
let m5_8 = values[base + 53u];
let rm5 = max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m5_0)), abs(m5_1)), abs(m5_2)), abs(m5_3)), abs(m5_4)), abs(m5_5)), abs(m5_6)), abs(m5_7)), abs(m5_8));
let m6_0 = values[base + 54u];
let m6_1 = values[base + 55u];
let m6_2 = values[base + 56u];
let m6_3 = values[base + 57u];
let m6_4 = values[base + 58u];
let m6_5 = values[base + 59u];
let m6_6 = values[base + 60u];
let m6_7 = values[base + 61u];
let m6_8 = values[base + 62u];
let rm6 = max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m6_0)), abs(m6_1)), abs(m6_2)), abs(m6_3)), abs(m6_4)), abs(m6_5)), abs(m6_6)), abs(m6_7)), abs(m6_8));
let m7_0 = values[base + 63u];
let m7_1 = values[base + 64u];
let m7_2 = values[base + 65u];
let m7_3 = values[base + 66u];
let m7_4 = values[base + 67u];
let m7_5 = values[base + 68u];
let m7_6 = values[base + 69u];
let m7_7 = values[base + 70u];
let m7_8 = values[base + 71u];
let rm7 = max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m7_0)), abs(m7_1)), abs(m7_2)), abs(m7_3)), abs(m7_4)), abs(m7_5)), abs(m7_6)), abs(m7_7)), abs(m7_8));
let m8_0 = values[base + 72u];
let m8_1 = values[base + 73u];
let m8_2 = values[base + 74u];
let m8_3 = values[base + 75u];
let m8_4 = values[base + 76u];
let m8_5 = values[base + 77u];
let m8_6 = values[base + 78u];
let m8_7 = values[base + 79u];
let m8_8 = values[base + 80u];
let rm8 = max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m8_0)), abs(m8_1)), abs(m8_2)), abs(m8_3)), abs(m8_4)), abs(m8_5)), abs(m8_6)), abs(m8_7)), abs(m8_8));
let q0 = values[base + 81u];
let qa0 = abs(q0);
let q1 = values[base + 82u];
let qa1 = abs(q1);
let q2 = values[base + 83u];
let qa2 = abs(q2);
let q3 = values[base + 84u];
let qa3 = abs(q3);
let q4 = values[base + 85u];
let qa4 = abs(q4);
let q5 = values[base + 86u];
let qa5 = abs(q5);
let q6 = values[base + 87u];
let qa6 = abs(q6);
let q7 = values[base + 88u];
let qa7 = abs(q7);
let q8 = values[base + 89u];
let qa8 = abs(q8);
var ok = true;
var c0 = 0u;
var c1 = 0u;
var c2 = 0u;
var c3 = 0u;
var c4 = 0u;
var c5 = 0u;
var c6 = 0u;
var c7 = 0u;
var c8 = 0u;
var c9 = 0u;
var c10 = 0u;
var c11 = 0u;
var c12 = 0u;
var c13 = 0u;
var c14 = 0u;
var c15 = 0u;
for (var pre = 0u; pre < 2u; pre++) {
var live = true;
var x0_1 = m0_1;
var x0_2 = m0_2;
var x0_3 = m0_3;
var x0_4 = m0_4;
var x0_5 = m0_5;
var x0_6 = m0_6;
var x0_7 = m0_7;
var x0_8 = m0_8;
var y0 = q0;
var x1_1 = m1_1;
var x1_2 = m1_2;
var x1_3 = m1_3;
var x1_4 = m1_4;
var x1_5 = m1_5;
var x1_6 = m1_6;
var x1_7 = m1_7;
var x1_8 = m1_8;
var y1 = q1;
var x2_1 = m2_1;
var x2_2 = m2_2;
var x2_3 = m2_3;
var x2_4 = m2_4;
var x2_5 = m2_5;
var x2_6 = m2_6;
var x2_7 = m2_7;
var x2_8 = m2_8;
var y2 = q2;
var x3_1 = m3_1;
var x3_2 = m3_2;
var x3_3 = m3_3;
var x3_4 = m3_4;
var x3_5 = m3_5;
var x3_6 = m3_6;
var x3_7 = m3_7;
var x3_8 = m3_8;
var y3 = q3;
var x4_1 = m4_1;
var x4_2 = m4_2;
var x4_3 = m4_3;
var x4_4 = m4_4;
var x4_5 = m4_5;
var x4_6 = m4_6;
var x4_7 = m4_7;
var x4_8 = m4_8;
var y4 = q4;
var x5_1 = m5_1;
var x5_2 = m5_2;
var x5_3 = m5_3;
var x5_4 = m5_4;
var x5_5 = m5_5;
var x5_6 = m5_6;
var x5_7 = m5_7;
var x5_8 = m5_8;
var y5 = q5;
var x6_1 = m6_1;
var x6_2 = m6_2;
var x6_3 = m6_3;
var x6_4 = m6_4;
var x6_5 = m6_5;
var x6_6 = m6_6;
var x6_7 = m6_7;
var x6_8 = m6_8;
var y6 = q6;
var x7_1 = m7_1;
var x7_2 = m7_2;
var x7_3 = m7_3;
var x7_4 = m7_4;
var x7_5 = m7_5;
var x7_6 = m7_6;
var x7_7 = m7_7;
var x7_8 = m7_8;
var y7 = q7;
var x8_1 = m8_1;
var x8_2 = m8_2;
var x8_3 = m8_3;
var x8_4 = m8_4;
var x8_5 = m8_5;
var x8_6 = m8_6;
var x8_7 = m8_7;
var x8_8 = m8_8;
var y8 = q8;
let b0 = ((pre >> 0u) & 1u) == 1u;
if b0 {
let dead0 = semi & !(m0_0 > tol.tree_singular * m0_0);
ok = ok & !(live & !dead0 & !(m0_0 > tol.tree_pivot * m0_0));
live = live & !dead0;
let i0 = Scalar(1.0) / m0_0;
let n0 = -i0;
let r1 = x0_1 * n0;
let r2 = x0_2 * n0;
let r3 = x0_3 * n0;
let r4 = x0_4 * n0;
let r5 = x0_5 * n0;
let r6 = x0_6 * n0;
let r7 = x0_7 * n0;
let r8 = x0_8 * n0;
let tr = -y0 * i0;
let f1 = m1_0;
x1_1 = x1_1 + f1 * r1;
x1_2 = x1_2 + f1 * r2;
x1_3 = x1_3 + f1 * r3;
x1_4 = x1_4 + f1 * r4;
x1_5 = x1_5 + f1 * r5;
x1_6 = x1_6 + f1 * r6;
x1_7 = x1_7 + f1 * r7;
x1_8 = x1_8 + f1 * r8;
y1 = y1 + f1 * tr;
let f2 = m2_0;
x2_1 = x2_1 + f2 * r1;
x2_2 = x2_2 + f2 * r2;
x2_3 = x2_3 + f2 * r3;
x2_4 = x2_4 + f2 * r4;
x2_5 = x2_5 + f2 * r5;
x2_6 = x2_6 + f2 * r6;
x2_7 = x2_7 + f2 * r7;
x2_8 = x2_8 + f2 * r8;
y2 = y2 + f2 * tr;
let f3 = m3_0;
x3_1 = x3_1 + f3 * r1;
x3_2 = x3_2 + f3 * r2;
x3_3 = x3_3 + f3 * r3;
x3_4 = x3_4 + f3 * r4;
x3_5 = x3_5 + f3 * r5;
x3_6 = x3_6 + f3 * r6;
x3_7 = x3_7 + f3 * r7;
x3_8 = x3_8 + f3 * r8;
y3 = y3 + f3 * tr;
let f4 = m4_0;
x4_1 = x4_1 + f4 * r1;
x4_2 = x4_2 + f4 * r2;
x4_3 = x4_3 + f4 * r3;
x4_4 = x4_4 + f4 * r4;
x4_5 = x4_5 + f4 * r5;
x4_6 = x4_6 + f4 * r6;
x4_7 = x4_7 + f4 * r7;
x4_8 = x4_8 + f4 * r8;
y4 = y4 + f4 * tr;
let f5 = m5_0;
x5_1 = x5_1 + f5 * r1;
x5_2 = x5_2 + f5 * r2;
x5_3 = x5_3 + f5 * r3;
x5_4 = x5_4 + f5 * r4;
x5_5 = x5_5 + f5 * r5;
x5_6 = x5_6 + f5 * r6;
x5_7 = x5_7 + f5 * r7;
x5_8 = x5_8 + f5 * r8;
y5 = y5 + f5 * tr;
let f6 = m6_0;
x6_1 = x6_1 + f6 * r1;
x6_2 = x6_2 + f6 * r2;
x6_3 = x6_3 + f6 * r3;
x6_4 = x6_4 + f6 * r4;
x6_5 = x6_5 + f6 * r5;
x6_6 = x6_6 + f6 * r6;
x6_7 = x6_7 + f6 * r7;
x6_8 = x6_8 + f6 * r8;
y6 = y6 + f6 * tr;
let f7 = m7_0;
x7_1 = x7_1 + f7 * r1;
x7_2 = x7_2 + f7 * r2;
x7_3 = x7_3 + f7 * r3;
x7_4 = x7_4 + f7 * r4;
x7_5 = x7_5 + f7 * r5;
x7_6 = x7_6 + f7 * r6;
x7_7 = x7_7 + f7 * r7;
x7_8 = x7_8 + f7 * r8;
y7 = y7 + f7 * tr;
let f8 = m8_0;
x8_1 = x8_1 + f8 * r1;
x8_2 = x8_2 + f8 * r2;
x8_3 = x8_3 + f8 * r3;
x8_4 = x8_4 + f8 * r4;
x8_5 = x8_5 + f8 * r5;
x8_6 = x8_6 + f8 * r6;
x8_7 = x8_7 + f8 * r7;
x8_8 = x8_8 + f8 * r8;
y8 = y8 + f8 * tr;
x0_1 = r1;
x0_2 = r2;
x0_3 = r3;
x0_4 = r4;
x0_5 = r5;
x0_6 = r6;
x0_7 = r7;
x0_8 = r8;
y0 = tr;
}
{
let zm = max(Scalar(0.0), select(Scalar(0.0), abs(y0), b0));
let zs = (Scalar(0.0) + select(Scalar(0.0), abs(y0), b0));
c0 = c0 | select(0u, 1u << (pre | 0u), live & (y0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (y1 >= -tol.screen * (qa1 + rm1 * zs)) & (y2 >= -tol.screen * (qa2 + rm2 * zs)) & (y3 >= -tol.screen * (qa3 + rm3 * zs)) & (y4 >= -tol.screen * (qa4 + rm4 * zs)) & (y5 >= -tol.screen * (qa5 + rm5 * zs)) & (y6 >= -tol.screen * (qa6 + rm6 * zs)) & (y7 >= -tol.screen * (qa7 + rm7 * zs)) & (y8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(x8_8 > tol.tree_singular * m8_8);
ok = ok & !(live & !dead8 & !(x8_8 > tol.tree_pivot * m8_8));
let l8 = live & !dead8;
let i8 = Scalar(1.0) / x8_8;
let n8 = -i8;
let t8_8 = -y8 * i8;
let t8_0 = y0 + x0_8 * t8_8;
let t8_1 = y1 + x1_8 * t8_8;
let t8_2 = y2 + x2_8 * t8_8;
let t8_3 = y3 + x3_8 * t8_8;
let t8_4 = y4 + x4_8 * t8_8;
let t8_5 = y5 + x5_8 * t8_8;
let t8_6 = y6 + x6_8 * t8_8;
let t8_7 = y7 + x7_8 * t8_8;
{
let zm = max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_8));
let zs = ((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 0u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(x7_7 > tol.tree_singular * m7_7);
ok = ok & !(live & !dead7 & !(x7_7 > tol.tree_pivot * m7_7));
let l7 = live & !dead7;
let i7 = Scalar(1.0) / x7_7;
let n7 = -i7;
let a7_7_8 = x7_8 * n7;
let t7_7 = -y7 * i7;
let a7_0_8 = x0_8 + x0_7 * a7_7_8;
let t7_0 = y0 + x0_7 * t7_7;
let a7_1_8 = x1_8 + x1_7 * a7_7_8;
let t7_1 = y1 + x1_7 * t7_7;
let a7_2_8 = x2_8 + x2_7 * a7_7_8;
let t7_2 = y2 + x2_7 * t7_7;
let a7_3_8 = x3_8 + x3_7 * a7_7_8;
let t7_3 = y3 + x3_7 * t7_7;
let a7_4_8 = x4_8 + x4_7 * a7_7_8;
let t7_4 = y4 + x4_7 * t7_7;
let a7_5_8 = x5_8 + x5_7 * a7_7_8;
let t7_5 = y5 + x5_7 * t7_7;
let a7_6_8 = x6_8 + x6_7 * a7_7_8;
let t7_6 = y6 + x6_7 * t7_7;
let a7_8_8 = x8_8 + x8_7 * a7_7_8;
let t7_8 = y8 + x8_7 * t7_7;
{
let zm = max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_7));
let zs = ((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 0u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_7)), abs(t8_8));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 0u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(x6_6 > tol.tree_singular * m6_6);
ok = ok & !(live & !dead6 & !(x6_6 > tol.tree_pivot * m6_6));
let l6 = live & !dead6;
let i6 = Scalar(1.0) / x6_6;
let n6 = -i6;
let a6_6_7 = x6_7 * n6;
let a6_6_8 = x6_8 * n6;
let t6_6 = -y6 * i6;
let a6_0_7 = x0_7 + x0_6 * a6_6_7;
let a6_0_8 = x0_8 + x0_6 * a6_6_8;
let t6_0 = y0 + x0_6 * t6_6;
let a6_1_7 = x1_7 + x1_6 * a6_6_7;
let a6_1_8 = x1_8 + x1_6 * a6_6_8;
let t6_1 = y1 + x1_6 * t6_6;
let a6_2_7 = x2_7 + x2_6 * a6_6_7;
let a6_2_8 = x2_8 + x2_6 * a6_6_8;
let t6_2 = y2 + x2_6 * t6_6;
let a6_3_7 = x3_7 + x3_6 * a6_6_7;
let a6_3_8 = x3_8 + x3_6 * a6_6_8;
let t6_3 = y3 + x3_6 * t6_6;
let a6_4_7 = x4_7 + x4_6 * a6_6_7;
let a6_4_8 = x4_8 + x4_6 * a6_6_8;
let t6_4 = y4 + x4_6 * t6_6;
let a6_5_7 = x5_7 + x5_6 * a6_6_7;
let a6_5_8 = x5_8 + x5_6 * a6_6_8;
let t6_5 = y5 + x5_6 * t6_6;
let a6_7_7 = x7_7 + x7_6 * a6_6_7;
let a6_7_8 = x7_8 + x7_6 * a6_6_8;
let t6_7 = y7 + x7_6 * t6_6;
let a6_8_7 = x8_7 + x8_6 * a6_6_7;
let a6_8_8 = x8_8 + x8_6 * a6_6_8;
let t6_8 = y8 + x8_6 * t6_6;
{
let zm = max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_6));
let zs = ((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 0u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_6)), abs(t8_8));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 0u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_6)), abs(t7_7));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 0u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 0u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
{
let dead5 = semi & !(x5_5 > tol.tree_singular * m5_5);
ok = ok & !(live & !dead5 & !(x5_5 > tol.tree_pivot * m5_5));
let l5 = live & !dead5;
let i5 = Scalar(1.0) / x5_5;
let n5 = -i5;
let a5_5_6 = x5_6 * n5;
let a5_5_7 = x5_7 * n5;
let a5_5_8 = x5_8 * n5;
let t5_5 = -y5 * i5;
let a5_0_6 = x0_6 + x0_5 * a5_5_6;
let a5_0_7 = x0_7 + x0_5 * a5_5_7;
let a5_0_8 = x0_8 + x0_5 * a5_5_8;
let t5_0 = y0 + x0_5 * t5_5;
let a5_1_6 = x1_6 + x1_5 * a5_5_6;
let a5_1_7 = x1_7 + x1_5 * a5_5_7;
let a5_1_8 = x1_8 + x1_5 * a5_5_8;
let t5_1 = y1 + x1_5 * t5_5;
let a5_2_6 = x2_6 + x2_5 * a5_5_6;
let a5_2_7 = x2_7 + x2_5 * a5_5_7;
let a5_2_8 = x2_8 + x2_5 * a5_5_8;
let t5_2 = y2 + x2_5 * t5_5;
let a5_3_6 = x3_6 + x3_5 * a5_5_6;
let a5_3_7 = x3_7 + x3_5 * a5_5_7;
let a5_3_8 = x3_8 + x3_5 * a5_5_8;
let t5_3 = y3 + x3_5 * t5_5;
let a5_4_6 = x4_6 + x4_5 * a5_5_6;
let a5_4_7 = x4_7 + x4_5 * a5_5_7;
let a5_4_8 = x4_8 + x4_5 * a5_5_8;
let t5_4 = y4 + x4_5 * t5_5;
let a5_6_6 = x6_6 + x6_5 * a5_5_6;
let a5_6_7 = x6_7 + x6_5 * a5_5_7;
let a5_6_8 = x6_8 + x6_5 * a5_5_8;
let t5_6 = y6 + x6_5 * t5_5;
let a5_7_6 = x7_6 + x7_5 * a5_5_6;
let a5_7_7 = x7_7 + x7_5 * a5_5_7;
let a5_7_8 = x7_8 + x7_5 * a5_5_8;
let t5_7 = y7 + x7_5 * t5_5;
let a5_8_6 = x8_6 + x8_5 * a5_5_6;
let a5_8_7 = x8_7 + x8_5 * a5_5_7;
let a5_8_8 = x8_8 + x8_5 * a5_5_8;
let t5_8 = y8 + x8_5 * t5_5;
{
let zm = max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), abs(t5_5));
let zs = ((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 0u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let t8_8 = -t5_8 * i8;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let t8_7 = t5_7 + a5_7_8 * t8_8;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_5)), abs(t8_8));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 0u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let t7_8 = t5_8 + a5_8_7 * t7_7;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_5)), abs(t7_7));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 0u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 0u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let a6_6_7 = a5_6_7 * n6;
let a6_6_8 = a5_6_8 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let t6_8 = t5_8 + a5_8_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_5)), abs(t6_6));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 0u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 0u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 0u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 0u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
}
{
let dead4 = semi & !(x4_4 > tol.tree_singular * m4_4);
ok = ok & !(live & !dead4 & !(x4_4 > tol.tree_pivot * m4_4));
let l4 = live & !dead4;
let i4 = Scalar(1.0) / x4_4;
let n4 = -i4;
let a4_4_5 = x4_5 * n4;
let a4_4_6 = x4_6 * n4;
let a4_4_7 = x4_7 * n4;
let a4_4_8 = x4_8 * n4;
let t4_4 = -y4 * i4;
let a4_0_5 = x0_5 + x0_4 * a4_4_5;
let a4_0_6 = x0_6 + x0_4 * a4_4_6;
let a4_0_7 = x0_7 + x0_4 * a4_4_7;
let a4_0_8 = x0_8 + x0_4 * a4_4_8;
let t4_0 = y0 + x0_4 * t4_4;
let a4_1_5 = x1_5 + x1_4 * a4_4_5;
let a4_1_6 = x1_6 + x1_4 * a4_4_6;
let a4_1_7 = x1_7 + x1_4 * a4_4_7;
let a4_1_8 = x1_8 + x1_4 * a4_4_8;
let t4_1 = y1 + x1_4 * t4_4;
let a4_2_5 = x2_5 + x2_4 * a4_4_5;
let a4_2_6 = x2_6 + x2_4 * a4_4_6;
let a4_2_7 = x2_7 + x2_4 * a4_4_7;
let a4_2_8 = x2_8 + x2_4 * a4_4_8;
let t4_2 = y2 + x2_4 * t4_4;
let a4_3_5 = x3_5 + x3_4 * a4_4_5;
let a4_3_6 = x3_6 + x3_4 * a4_4_6;
let a4_3_7 = x3_7 + x3_4 * a4_4_7;
let a4_3_8 = x3_8 + x3_4 * a4_4_8;
let t4_3 = y3 + x3_4 * t4_4;
let a4_5_5 = x5_5 + x5_4 * a4_4_5;
let a4_5_6 = x5_6 + x5_4 * a4_4_6;
let a4_5_7 = x5_7 + x5_4 * a4_4_7;
let a4_5_8 = x5_8 + x5_4 * a4_4_8;
let t4_5 = y5 + x5_4 * t4_4;
let a4_6_5 = x6_5 + x6_4 * a4_4_5;
let a4_6_6 = x6_6 + x6_4 * a4_4_6;
let a4_6_7 = x6_7 + x6_4 * a4_4_7;
let a4_6_8 = x6_8 + x6_4 * a4_4_8;
let t4_6 = y6 + x6_4 * t4_4;
let a4_7_5 = x7_5 + x7_4 * a4_4_5;
let a4_7_6 = x7_6 + x7_4 * a4_4_6;
let a4_7_7 = x7_7 + x7_4 * a4_4_7;
let a4_7_8 = x7_8 + x7_4 * a4_4_8;
let t4_7 = y7 + x7_4 * t4_4;
let a4_8_5 = x8_5 + x8_4 * a4_4_5;
let a4_8_6 = x8_6 + x8_4 * a4_4_6;
let a4_8_7 = x8_7 + x8_4 * a4_4_7;
let a4_8_8 = x8_8 + x8_4 * a4_4_8;
let t4_8 = y8 + x8_4 * t4_4;
{
let zm = max(max(Scalar(0.0), select(Scalar(0.0), abs(t4_0), b0)), abs(t4_4));
let zs = ((Scalar(0.0) + select(Scalar(0.0), abs(t4_0), b0)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 16u), l4 & (t4_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t4_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t4_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t4_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t4_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t4_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a4_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l4 & !dead8 & !(a4_8_8 > tol.tree_pivot * m8_8));
let l8 = l4 & !dead8;
let i8 = Scalar(1.0) / a4_8_8;
let n8 = -i8;
let t8_8 = -t4_8 * i8;
let t8_0 = t4_0 + a4_0_8 * t8_8;
let t8_1 = t4_1 + a4_1_8 * t8_8;
let t8_2 = t4_2 + a4_2_8 * t8_8;
let t8_3 = t4_3 + a4_3_8 * t8_8;
let t8_4 = t4_4 + a4_4_8 * t8_8;
let t8_5 = t4_5 + a4_5_8 * t8_8;
let t8_6 = t4_6 + a4_6_8 * t8_8;
let t8_7 = t4_7 + a4_7_8 * t8_8;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_4)), abs(t8_8));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_4)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 16u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a4_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l4 & !dead7 & !(a4_7_7 > tol.tree_pivot * m7_7));
let l7 = l4 & !dead7;
let i7 = Scalar(1.0) / a4_7_7;
let n7 = -i7;
let a7_7_8 = a4_7_8 * n7;
let t7_7 = -t4_7 * i7;
let a7_0_8 = a4_0_8 + a4_0_7 * a7_7_8;
let t7_0 = t4_0 + a4_0_7 * t7_7;
let a7_1_8 = a4_1_8 + a4_1_7 * a7_7_8;
let t7_1 = t4_1 + a4_1_7 * t7_7;
let a7_2_8 = a4_2_8 + a4_2_7 * a7_7_8;
let t7_2 = t4_2 + a4_2_7 * t7_7;
let a7_3_8 = a4_3_8 + a4_3_7 * a7_7_8;
let t7_3 = t4_3 + a4_3_7 * t7_7;
let a7_4_8 = a4_4_8 + a4_4_7 * a7_7_8;
let t7_4 = t4_4 + a4_4_7 * t7_7;
let a7_5_8 = a4_5_8 + a4_5_7 * a7_7_8;
let t7_5 = t4_5 + a4_5_7 * t7_7;
let a7_6_8 = a4_6_8 + a4_6_7 * a7_7_8;
let t7_6 = t4_6 + a4_6_7 * t7_7;
let a7_8_8 = a4_8_8 + a4_8_7 * a7_7_8;
let t7_8 = t4_8 + a4_8_7 * t7_7;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_4)), abs(t7_7));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_4)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 16u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_4)), abs(t8_7)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_4)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 16u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let a6_6_7 = a4_6_7 * n6;
let a6_6_8 = a4_6_8 * n6;
let t6_6 = -t4_6 * i6;
let a6_0_7 = a4_0_7 + a4_0_6 * a6_6_7;
let a6_0_8 = a4_0_8 + a4_0_6 * a6_6_8;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let a6_1_7 = a4_1_7 + a4_1_6 * a6_6_7;
let a6_1_8 = a4_1_8 + a4_1_6 * a6_6_8;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let a6_2_7 = a4_2_7 + a4_2_6 * a6_6_7;
let a6_2_8 = a4_2_8 + a4_2_6 * a6_6_8;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let a6_3_7 = a4_3_7 + a4_3_6 * a6_6_7;
let a6_3_8 = a4_3_8 + a4_3_6 * a6_6_8;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let a6_4_7 = a4_4_7 + a4_4_6 * a6_6_7;
let a6_4_8 = a4_4_8 + a4_4_6 * a6_6_8;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let a6_5_7 = a4_5_7 + a4_5_6 * a6_6_7;
let a6_5_8 = a4_5_8 + a4_5_6 * a6_6_8;
let t6_5 = t4_5 + a4_5_6 * t6_6;
let a6_7_7 = a4_7_7 + a4_7_6 * a6_6_7;
let a6_7_8 = a4_7_8 + a4_7_6 * a6_6_8;
let t6_7 = t4_7 + a4_7_6 * t6_6;
let a6_8_7 = a4_8_7 + a4_8_6 * a6_6_7;
let a6_8_8 = a4_8_8 + a4_8_6 * a6_6_8;
let t6_8 = t4_8 + a4_8_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_4)), abs(t6_6));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 16u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_4)), abs(t8_6)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_4)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 16u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_4)), abs(t7_6)), abs(t7_7));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_4)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 16u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_4)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_4)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 16u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let a5_5_7 = a4_5_7 * n5;
let a5_5_8 = a4_5_8 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let a5_0_7 = a4_0_7 + a4_0_5 * a5_5_7;
let a5_0_8 = a4_0_8 + a4_0_5 * a5_5_8;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let a5_1_7 = a4_1_7 + a4_1_5 * a5_5_7;
let a5_1_8 = a4_1_8 + a4_1_5 * a5_5_8;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let a5_2_7 = a4_2_7 + a4_2_5 * a5_5_7;
let a5_2_8 = a4_2_8 + a4_2_5 * a5_5_8;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let a5_3_7 = a4_3_7 + a4_3_5 * a5_5_7;
let a5_3_8 = a4_3_8 + a4_3_5 * a5_5_8;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let a5_4_7 = a4_4_7 + a4_4_5 * a5_5_7;
let a5_4_8 = a4_4_8 + a4_4_5 * a5_5_8;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let a5_6_7 = a4_6_7 + a4_6_5 * a5_5_7;
let a5_6_8 = a4_6_8 + a4_6_5 * a5_5_8;
let t5_6 = t4_6 + a4_6_5 * t5_5;
let a5_7_6 = a4_7_6 + a4_7_5 * a5_5_6;
let a5_7_7 = a4_7_7 + a4_7_5 * a5_5_7;
let a5_7_8 = a4_7_8 + a4_7_5 * a5_5_8;
let t5_7 = t4_7 + a4_7_5 * t5_5;
let a5_8_6 = a4_8_6 + a4_8_5 * a5_5_6;
let a5_8_7 = a4_8_7 + a4_8_5 * a5_5_7;
let a5_8_8 = a4_8_8 + a4_8_5 * a5_5_8;
let t5_8 = t4_8 + a4_8_5 * t5_5;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), abs(t5_4)), abs(t5_5));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 16u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let t8_8 = -t5_8 * i8;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let t8_7 = t5_7 + a5_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_4)), abs(t8_5)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_4)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 16u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let t7_8 = t5_8 + a5_8_7 * t7_7;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_4)), abs(t7_5)), abs(t7_7));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_4)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 16u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_4)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_4)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 16u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let a6_6_7 = a5_6_7 * n6;
let a6_6_8 = a5_6_8 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let t6_8 = t5_8 + a5_8_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 16u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 16u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_4)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_4)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 16u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 16u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
}
}
{
let dead3 = semi & !(x3_3 > tol.tree_singular * m3_3);
ok = ok & !(live & !dead3 & !(x3_3 > tol.tree_pivot * m3_3));
let l3 = live & !dead3;
let i3 = Scalar(1.0) / x3_3;
let n3 = -i3;
let a3_3_4 = x3_4 * n3;
let a3_3_5 = x3_5 * n3;
let a3_3_6 = x3_6 * n3;
let a3_3_7 = x3_7 * n3;
let a3_3_8 = x3_8 * n3;
let t3_3 = -y3 * i3;
let a3_0_4 = x0_4 + x0_3 * a3_3_4;
let a3_0_5 = x0_5 + x0_3 * a3_3_5;
let a3_0_6 = x0_6 + x0_3 * a3_3_6;
let a3_0_7 = x0_7 + x0_3 * a3_3_7;
let a3_0_8 = x0_8 + x0_3 * a3_3_8;
let t3_0 = y0 + x0_3 * t3_3;
let a3_1_4 = x1_4 + x1_3 * a3_3_4;
let a3_1_5 = x1_5 + x1_3 * a3_3_5;
let a3_1_6 = x1_6 + x1_3 * a3_3_6;
let a3_1_7 = x1_7 + x1_3 * a3_3_7;
let a3_1_8 = x1_8 + x1_3 * a3_3_8;
let t3_1 = y1 + x1_3 * t3_3;
let a3_2_4 = x2_4 + x2_3 * a3_3_4;
let a3_2_5 = x2_5 + x2_3 * a3_3_5;
let a3_2_6 = x2_6 + x2_3 * a3_3_6;
let a3_2_7 = x2_7 + x2_3 * a3_3_7;
let a3_2_8 = x2_8 + x2_3 * a3_3_8;
let t3_2 = y2 + x2_3 * t3_3;
let a3_4_4 = x4_4 + x4_3 * a3_3_4;
let a3_4_5 = x4_5 + x4_3 * a3_3_5;
let a3_4_6 = x4_6 + x4_3 * a3_3_6;
let a3_4_7 = x4_7 + x4_3 * a3_3_7;
let a3_4_8 = x4_8 + x4_3 * a3_3_8;
let t3_4 = y4 + x4_3 * t3_3;
let a3_5_4 = x5_4 + x5_3 * a3_3_4;
let a3_5_5 = x5_5 + x5_3 * a3_3_5;
let a3_5_6 = x5_6 + x5_3 * a3_3_6;
let a3_5_7 = x5_7 + x5_3 * a3_3_7;
let a3_5_8 = x5_8 + x5_3 * a3_3_8;
let t3_5 = y5 + x5_3 * t3_3;
let a3_6_4 = x6_4 + x6_3 * a3_3_4;
let a3_6_5 = x6_5 + x6_3 * a3_3_5;
let a3_6_6 = x6_6 + x6_3 * a3_3_6;
let a3_6_7 = x6_7 + x6_3 * a3_3_7;
let a3_6_8 = x6_8 + x6_3 * a3_3_8;
let t3_6 = y6 + x6_3 * t3_3;
let a3_7_4 = x7_4 + x7_3 * a3_3_4;
let a3_7_5 = x7_5 + x7_3 * a3_3_5;
let a3_7_6 = x7_6 + x7_3 * a3_3_6;
let a3_7_7 = x7_7 + x7_3 * a3_3_7;
let a3_7_8 = x7_8 + x7_3 * a3_3_8;
let t3_7 = y7 + x7_3 * t3_3;
let a3_8_4 = x8_4 + x8_3 * a3_3_4;
let a3_8_5 = x8_5 + x8_3 * a3_3_5;
let a3_8_6 = x8_6 + x8_3 * a3_3_6;
let a3_8_7 = x8_7 + x8_3 * a3_3_7;
let a3_8_8 = x8_8 + x8_3 * a3_3_8;
let t3_8 = y8 + x8_3 * t3_3;
{
let zm = max(max(Scalar(0.0), select(Scalar(0.0), abs(t3_0), b0)), abs(t3_3));
let zs = ((Scalar(0.0) + select(Scalar(0.0), abs(t3_0), b0)) + abs(t3_3));
c0 = c0 | select(0u, 1u << (pre | 8u), l3 & (t3_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t3_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t3_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t3_3 >= -tol.screen * zm) & (t3_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t3_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t3_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t3_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t3_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a3_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l3 & !dead8 & !(a3_8_8 > tol.tree_pivot * m8_8));
let l8 = l3 & !dead8;
let i8 = Scalar(1.0) / a3_8_8;
let n8 = -i8;
let t8_8 = -t3_8 * i8;
let t8_0 = t3_0 + a3_0_8 * t8_8;
let t8_1 = t3_1 + a3_1_8 * t8_8;
let t8_2 = t3_2 + a3_2_8 * t8_8;
let t8_3 = t3_3 + a3_3_8 * t8_8;
let t8_4 = t3_4 + a3_4_8 * t8_8;
let t8_5 = t3_5 + a3_5_8 * t8_8;
let t8_6 = t3_6 + a3_6_8 * t8_8;
let t8_7 = t3_7 + a3_7_8 * t8_8;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_3)), abs(t8_8));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_3)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 8u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a3_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l3 & !dead7 & !(a3_7_7 > tol.tree_pivot * m7_7));
let l7 = l3 & !dead7;
let i7 = Scalar(1.0) / a3_7_7;
let n7 = -i7;
let a7_7_8 = a3_7_8 * n7;
let t7_7 = -t3_7 * i7;
let a7_0_8 = a3_0_8 + a3_0_7 * a7_7_8;
let t7_0 = t3_0 + a3_0_7 * t7_7;
let a7_1_8 = a3_1_8 + a3_1_7 * a7_7_8;
let t7_1 = t3_1 + a3_1_7 * t7_7;
let a7_2_8 = a3_2_8 + a3_2_7 * a7_7_8;
let t7_2 = t3_2 + a3_2_7 * t7_7;
let a7_3_8 = a3_3_8 + a3_3_7 * a7_7_8;
let t7_3 = t3_3 + a3_3_7 * t7_7;
let a7_4_8 = a3_4_8 + a3_4_7 * a7_7_8;
let t7_4 = t3_4 + a3_4_7 * t7_7;
let a7_5_8 = a3_5_8 + a3_5_7 * a7_7_8;
let t7_5 = t3_5 + a3_5_7 * t7_7;
let a7_6_8 = a3_6_8 + a3_6_7 * a7_7_8;
let t7_6 = t3_6 + a3_6_7 * t7_7;
let a7_8_8 = a3_8_8 + a3_8_7 * a7_7_8;
let t7_8 = t3_8 + a3_8_7 * t7_7;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_3)), abs(t7_7));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_3)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 8u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_3)), abs(t8_7)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_3)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 8u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a3_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l3 & !dead6 & !(a3_6_6 > tol.tree_pivot * m6_6));
let l6 = l3 & !dead6;
let i6 = Scalar(1.0) / a3_6_6;
let n6 = -i6;
let a6_6_7 = a3_6_7 * n6;
let a6_6_8 = a3_6_8 * n6;
let t6_6 = -t3_6 * i6;
let a6_0_7 = a3_0_7 + a3_0_6 * a6_6_7;
let a6_0_8 = a3_0_8 + a3_0_6 * a6_6_8;
let t6_0 = t3_0 + a3_0_6 * t6_6;
let a6_1_7 = a3_1_7 + a3_1_6 * a6_6_7;
let a6_1_8 = a3_1_8 + a3_1_6 * a6_6_8;
let t6_1 = t3_1 + a3_1_6 * t6_6;
let a6_2_7 = a3_2_7 + a3_2_6 * a6_6_7;
let a6_2_8 = a3_2_8 + a3_2_6 * a6_6_8;
let t6_2 = t3_2 + a3_2_6 * t6_6;
let a6_3_7 = a3_3_7 + a3_3_6 * a6_6_7;
let a6_3_8 = a3_3_8 + a3_3_6 * a6_6_8;
let t6_3 = t3_3 + a3_3_6 * t6_6;
let a6_4_7 = a3_4_7 + a3_4_6 * a6_6_7;
let a6_4_8 = a3_4_8 + a3_4_6 * a6_6_8;
let t6_4 = t3_4 + a3_4_6 * t6_6;
let a6_5_7 = a3_5_7 + a3_5_6 * a6_6_7;
let a6_5_8 = a3_5_8 + a3_5_6 * a6_6_8;
let t6_5 = t3_5 + a3_5_6 * t6_6;
let a6_7_7 = a3_7_7 + a3_7_6 * a6_6_7;
let a6_7_8 = a3_7_8 + a3_7_6 * a6_6_8;
let t6_7 = t3_7 + a3_7_6 * t6_6;
let a6_8_7 = a3_8_7 + a3_8_6 * a6_6_7;
let a6_8_8 = a3_8_8 + a3_8_6 * a6_6_8;
let t6_8 = t3_8 + a3_8_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_3)), abs(t6_6));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_3)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 8u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_3)), abs(t8_6)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_3)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 8u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_3)), abs(t7_6)), abs(t7_7));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_3)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 8u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_3)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_3)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 8u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
{
let dead5 = semi & !(a3_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l3 & !dead5 & !(a3_5_5 > tol.tree_pivot * m5_5));
let l5 = l3 & !dead5;
let i5 = Scalar(1.0) / a3_5_5;
let n5 = -i5;
let a5_5_6 = a3_5_6 * n5;
let a5_5_7 = a3_5_7 * n5;
let a5_5_8 = a3_5_8 * n5;
let t5_5 = -t3_5 * i5;
let a5_0_6 = a3_0_6 + a3_0_5 * a5_5_6;
let a5_0_7 = a3_0_7 + a3_0_5 * a5_5_7;
let a5_0_8 = a3_0_8 + a3_0_5 * a5_5_8;
let t5_0 = t3_0 + a3_0_5 * t5_5;
let a5_1_6 = a3_1_6 + a3_1_5 * a5_5_6;
let a5_1_7 = a3_1_7 + a3_1_5 * a5_5_7;
let a5_1_8 = a3_1_8 + a3_1_5 * a5_5_8;
let t5_1 = t3_1 + a3_1_5 * t5_5;
let a5_2_6 = a3_2_6 + a3_2_5 * a5_5_6;
let a5_2_7 = a3_2_7 + a3_2_5 * a5_5_7;
let a5_2_8 = a3_2_8 + a3_2_5 * a5_5_8;
let t5_2 = t3_2 + a3_2_5 * t5_5;
let a5_3_6 = a3_3_6 + a3_3_5 * a5_5_6;
let a5_3_7 = a3_3_7 + a3_3_5 * a5_5_7;
let a5_3_8 = a3_3_8 + a3_3_5 * a5_5_8;
let t5_3 = t3_3 + a3_3_5 * t5_5;
let a5_4_6 = a3_4_6 + a3_4_5 * a5_5_6;
let a5_4_7 = a3_4_7 + a3_4_5 * a5_5_7;
let a5_4_8 = a3_4_8 + a3_4_5 * a5_5_8;
let t5_4 = t3_4 + a3_4_5 * t5_5;
let a5_6_6 = a3_6_6 + a3_6_5 * a5_5_6;
let a5_6_7 = a3_6_7 + a3_6_5 * a5_5_7;
let a5_6_8 = a3_6_8 + a3_6_5 * a5_5_8;
let t5_6 = t3_6 + a3_6_5 * t5_5;
let a5_7_6 = a3_7_6 + a3_7_5 * a5_5_6;
let a5_7_7 = a3_7_7 + a3_7_5 * a5_5_7;
let a5_7_8 = a3_7_8 + a3_7_5 * a5_5_8;
let t5_7 = t3_7 + a3_7_5 * t5_5;
let a5_8_6 = a3_8_6 + a3_8_5 * a5_5_6;
let a5_8_7 = a3_8_7 + a3_8_5 * a5_5_7;
let a5_8_8 = a3_8_8 + a3_8_5 * a5_5_8;
let t5_8 = t3_8 + a3_8_5 * t5_5;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), abs(t5_3)), abs(t5_5));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + abs(t5_3)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 8u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let t8_8 = -t5_8 * i8;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let t8_7 = t5_7 + a5_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_3)), abs(t8_5)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_3)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 8u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let t7_8 = t5_8 + a5_8_7 * t7_7;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_3)), abs(t7_5)), abs(t7_7));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_3)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 8u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_3)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_3)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 8u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let a6_6_7 = a5_6_7 * n6;
let a6_6_8 = a5_6_8 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let t6_8 = t5_8 + a5_8_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_3)), abs(t6_5)), abs(t6_6));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_3)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 8u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_3)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_3)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 8u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_3)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_3)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 8u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_3)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_3)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 8u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
}
{
let dead4 = semi & !(a3_4_4 > tol.tree_singular * m4_4);
ok = ok & !(l3 & !dead4 & !(a3_4_4 > tol.tree_pivot * m4_4));
let l4 = l3 & !dead4;
let i4 = Scalar(1.0) / a3_4_4;
let n4 = -i4;
let a4_4_5 = a3_4_5 * n4;
let a4_4_6 = a3_4_6 * n4;
let a4_4_7 = a3_4_7 * n4;
let a4_4_8 = a3_4_8 * n4;
let t4_4 = -t3_4 * i4;
let a4_0_5 = a3_0_5 + a3_0_4 * a4_4_5;
let a4_0_6 = a3_0_6 + a3_0_4 * a4_4_6;
let a4_0_7 = a3_0_7 + a3_0_4 * a4_4_7;
let a4_0_8 = a3_0_8 + a3_0_4 * a4_4_8;
let t4_0 = t3_0 + a3_0_4 * t4_4;
let a4_1_5 = a3_1_5 + a3_1_4 * a4_4_5;
let a4_1_6 = a3_1_6 + a3_1_4 * a4_4_6;
let a4_1_7 = a3_1_7 + a3_1_4 * a4_4_7;
let a4_1_8 = a3_1_8 + a3_1_4 * a4_4_8;
let t4_1 = t3_1 + a3_1_4 * t4_4;
let a4_2_5 = a3_2_5 + a3_2_4 * a4_4_5;
let a4_2_6 = a3_2_6 + a3_2_4 * a4_4_6;
let a4_2_7 = a3_2_7 + a3_2_4 * a4_4_7;
let a4_2_8 = a3_2_8 + a3_2_4 * a4_4_8;
let t4_2 = t3_2 + a3_2_4 * t4_4;
let a4_3_5 = a3_3_5 + a3_3_4 * a4_4_5;
let a4_3_6 = a3_3_6 + a3_3_4 * a4_4_6;
let a4_3_7 = a3_3_7 + a3_3_4 * a4_4_7;
let a4_3_8 = a3_3_8 + a3_3_4 * a4_4_8;
let t4_3 = t3_3 + a3_3_4 * t4_4;
let a4_5_5 = a3_5_5 + a3_5_4 * a4_4_5;
let a4_5_6 = a3_5_6 + a3_5_4 * a4_4_6;
let a4_5_7 = a3_5_7 + a3_5_4 * a4_4_7;
let a4_5_8 = a3_5_8 + a3_5_4 * a4_4_8;
let t4_5 = t3_5 + a3_5_4 * t4_4;
let a4_6_5 = a3_6_5 + a3_6_4 * a4_4_5;
let a4_6_6 = a3_6_6 + a3_6_4 * a4_4_6;
let a4_6_7 = a3_6_7 + a3_6_4 * a4_4_7;
let a4_6_8 = a3_6_8 + a3_6_4 * a4_4_8;
let t4_6 = t3_6 + a3_6_4 * t4_4;
let a4_7_5 = a3_7_5 + a3_7_4 * a4_4_5;
let a4_7_6 = a3_7_6 + a3_7_4 * a4_4_6;
let a4_7_7 = a3_7_7 + a3_7_4 * a4_4_7;
let a4_7_8 = a3_7_8 + a3_7_4 * a4_4_8;
let t4_7 = t3_7 + a3_7_4 * t4_4;
let a4_8_5 = a3_8_5 + a3_8_4 * a4_4_5;
let a4_8_6 = a3_8_6 + a3_8_4 * a4_4_6;
let a4_8_7 = a3_8_7 + a3_8_4 * a4_4_7;
let a4_8_8 = a3_8_8 + a3_8_4 * a4_4_8;
let t4_8 = t3_8 + a3_8_4 * t4_4;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t4_0), b0)), abs(t4_3)), abs(t4_4));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t4_0), b0)) + abs(t4_3)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 24u), l4 & (t4_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t4_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t4_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t4_3 >= -tol.screen * zm) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t4_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t4_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a4_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l4 & !dead8 & !(a4_8_8 > tol.tree_pivot * m8_8));
let l8 = l4 & !dead8;
let i8 = Scalar(1.0) / a4_8_8;
let n8 = -i8;
let t8_8 = -t4_8 * i8;
let t8_0 = t4_0 + a4_0_8 * t8_8;
let t8_1 = t4_1 + a4_1_8 * t8_8;
let t8_2 = t4_2 + a4_2_8 * t8_8;
let t8_3 = t4_3 + a4_3_8 * t8_8;
let t8_4 = t4_4 + a4_4_8 * t8_8;
let t8_5 = t4_5 + a4_5_8 * t8_8;
let t8_6 = t4_6 + a4_6_8 * t8_8;
let t8_7 = t4_7 + a4_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_3)), abs(t8_4)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_3)) + abs(t8_4)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 24u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a4_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l4 & !dead7 & !(a4_7_7 > tol.tree_pivot * m7_7));
let l7 = l4 & !dead7;
let i7 = Scalar(1.0) / a4_7_7;
let n7 = -i7;
let a7_7_8 = a4_7_8 * n7;
let t7_7 = -t4_7 * i7;
let a7_0_8 = a4_0_8 + a4_0_7 * a7_7_8;
let t7_0 = t4_0 + a4_0_7 * t7_7;
let a7_1_8 = a4_1_8 + a4_1_7 * a7_7_8;
let t7_1 = t4_1 + a4_1_7 * t7_7;
let a7_2_8 = a4_2_8 + a4_2_7 * a7_7_8;
let t7_2 = t4_2 + a4_2_7 * t7_7;
let a7_3_8 = a4_3_8 + a4_3_7 * a7_7_8;
let t7_3 = t4_3 + a4_3_7 * t7_7;
let a7_4_8 = a4_4_8 + a4_4_7 * a7_7_8;
let t7_4 = t4_4 + a4_4_7 * t7_7;
let a7_5_8 = a4_5_8 + a4_5_7 * a7_7_8;
let t7_5 = t4_5 + a4_5_7 * t7_7;
let a7_6_8 = a4_6_8 + a4_6_7 * a7_7_8;
let t7_6 = t4_6 + a4_6_7 * t7_7;
let a7_8_8 = a4_8_8 + a4_8_7 * a7_7_8;
let t7_8 = t4_8 + a4_8_7 * t7_7;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_3)), abs(t7_4)), abs(t7_7));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_3)) + abs(t7_4)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 24u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_3)), abs(t8_4)), abs(t8_7)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_3)) + abs(t8_4)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 24u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let a6_6_7 = a4_6_7 * n6;
let a6_6_8 = a4_6_8 * n6;
let t6_6 = -t4_6 * i6;
let a6_0_7 = a4_0_7 + a4_0_6 * a6_6_7;
let a6_0_8 = a4_0_8 + a4_0_6 * a6_6_8;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let a6_1_7 = a4_1_7 + a4_1_6 * a6_6_7;
let a6_1_8 = a4_1_8 + a4_1_6 * a6_6_8;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let a6_2_7 = a4_2_7 + a4_2_6 * a6_6_7;
let a6_2_8 = a4_2_8 + a4_2_6 * a6_6_8;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let a6_3_7 = a4_3_7 + a4_3_6 * a6_6_7;
let a6_3_8 = a4_3_8 + a4_3_6 * a6_6_8;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let a6_4_7 = a4_4_7 + a4_4_6 * a6_6_7;
let a6_4_8 = a4_4_8 + a4_4_6 * a6_6_8;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let a6_5_7 = a4_5_7 + a4_5_6 * a6_6_7;
let a6_5_8 = a4_5_8 + a4_5_6 * a6_6_8;
let t6_5 = t4_5 + a4_5_6 * t6_6;
let a6_7_7 = a4_7_7 + a4_7_6 * a6_6_7;
let a6_7_8 = a4_7_8 + a4_7_6 * a6_6_8;
let t6_7 = t4_7 + a4_7_6 * t6_6;
let a6_8_7 = a4_8_7 + a4_8_6 * a6_6_7;
let a6_8_8 = a4_8_8 + a4_8_6 * a6_6_8;
let t6_8 = t4_8 + a4_8_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_3)), abs(t6_4)), abs(t6_6));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_3)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 24u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_3)), abs(t8_4)), abs(t8_6)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_3)) + abs(t8_4)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 24u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_3)), abs(t7_4)), abs(t7_6)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_3)) + abs(t7_4)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 24u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_3)), abs(t8_4)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_3)) + abs(t8_4)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 24u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let a5_5_7 = a4_5_7 * n5;
let a5_5_8 = a4_5_8 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let a5_0_7 = a4_0_7 + a4_0_5 * a5_5_7;
let a5_0_8 = a4_0_8 + a4_0_5 * a5_5_8;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let a5_1_7 = a4_1_7 + a4_1_5 * a5_5_7;
let a5_1_8 = a4_1_8 + a4_1_5 * a5_5_8;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let a5_2_7 = a4_2_7 + a4_2_5 * a5_5_7;
let a5_2_8 = a4_2_8 + a4_2_5 * a5_5_8;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let a5_3_7 = a4_3_7 + a4_3_5 * a5_5_7;
let a5_3_8 = a4_3_8 + a4_3_5 * a5_5_8;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let a5_4_7 = a4_4_7 + a4_4_5 * a5_5_7;
let a5_4_8 = a4_4_8 + a4_4_5 * a5_5_8;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let a5_6_7 = a4_6_7 + a4_6_5 * a5_5_7;
let a5_6_8 = a4_6_8 + a4_6_5 * a5_5_8;
let t5_6 = t4_6 + a4_6_5 * t5_5;
let a5_7_6 = a4_7_6 + a4_7_5 * a5_5_6;
let a5_7_7 = a4_7_7 + a4_7_5 * a5_5_7;
let a5_7_8 = a4_7_8 + a4_7_5 * a5_5_8;
let t5_7 = t4_7 + a4_7_5 * t5_5;
let a5_8_6 = a4_8_6 + a4_8_5 * a5_5_6;
let a5_8_7 = a4_8_7 + a4_8_5 * a5_5_7;
let a5_8_8 = a4_8_8 + a4_8_5 * a5_5_8;
let t5_8 = t4_8 + a4_8_5 * t5_5;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), abs(t5_3)), abs(t5_4)), abs(t5_5));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + abs(t5_3)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 24u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let t8_8 = -t5_8 * i8;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let t8_7 = t5_7 + a5_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 24u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let t7_8 = t5_8 + a5_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_3)), abs(t7_4)), abs(t7_5)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_3)) + abs(t7_4)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 24u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 24u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let a6_6_7 = a5_6_7 * n6;
let a6_6_8 = a5_6_8 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let t6_8 = t5_8 + a5_8_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_3)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_3)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 24u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 24u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_3)), abs(t7_4)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_3)) + abs(t7_4)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 24u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 24u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
}
}
}
{
let dead2 = semi & !(x2_2 > tol.tree_singular * m2_2);
ok = ok & !(live & !dead2 & !(x2_2 > tol.tree_pivot * m2_2));
let l2 = live & !dead2;
let i2 = Scalar(1.0) / x2_2;
let n2 = -i2;
let a2_2_3 = x2_3 * n2;
let a2_2_4 = x2_4 * n2;
let a2_2_5 = x2_5 * n2;
let a2_2_6 = x2_6 * n2;
let a2_2_7 = x2_7 * n2;
let a2_2_8 = x2_8 * n2;
let t2_2 = -y2 * i2;
let a2_0_3 = x0_3 + x0_2 * a2_2_3;
let a2_0_4 = x0_4 + x0_2 * a2_2_4;
let a2_0_5 = x0_5 + x0_2 * a2_2_5;
let a2_0_6 = x0_6 + x0_2 * a2_2_6;
let a2_0_7 = x0_7 + x0_2 * a2_2_7;
let a2_0_8 = x0_8 + x0_2 * a2_2_8;
let t2_0 = y0 + x0_2 * t2_2;
let a2_1_3 = x1_3 + x1_2 * a2_2_3;
let a2_1_4 = x1_4 + x1_2 * a2_2_4;
let a2_1_5 = x1_5 + x1_2 * a2_2_5;
let a2_1_6 = x1_6 + x1_2 * a2_2_6;
let a2_1_7 = x1_7 + x1_2 * a2_2_7;
let a2_1_8 = x1_8 + x1_2 * a2_2_8;
let t2_1 = y1 + x1_2 * t2_2;
let a2_3_3 = x3_3 + x3_2 * a2_2_3;
let a2_3_4 = x3_4 + x3_2 * a2_2_4;
let a2_3_5 = x3_5 + x3_2 * a2_2_5;
let a2_3_6 = x3_6 + x3_2 * a2_2_6;
let a2_3_7 = x3_7 + x3_2 * a2_2_7;
let a2_3_8 = x3_8 + x3_2 * a2_2_8;
let t2_3 = y3 + x3_2 * t2_2;
let a2_4_3 = x4_3 + x4_2 * a2_2_3;
let a2_4_4 = x4_4 + x4_2 * a2_2_4;
let a2_4_5 = x4_5 + x4_2 * a2_2_5;
let a2_4_6 = x4_6 + x4_2 * a2_2_6;
let a2_4_7 = x4_7 + x4_2 * a2_2_7;
let a2_4_8 = x4_8 + x4_2 * a2_2_8;
let t2_4 = y4 + x4_2 * t2_2;
let a2_5_3 = x5_3 + x5_2 * a2_2_3;
let a2_5_4 = x5_4 + x5_2 * a2_2_4;
let a2_5_5 = x5_5 + x5_2 * a2_2_5;
let a2_5_6 = x5_6 + x5_2 * a2_2_6;
let a2_5_7 = x5_7 + x5_2 * a2_2_7;
let a2_5_8 = x5_8 + x5_2 * a2_2_8;
let t2_5 = y5 + x5_2 * t2_2;
let a2_6_3 = x6_3 + x6_2 * a2_2_3;
let a2_6_4 = x6_4 + x6_2 * a2_2_4;
let a2_6_5 = x6_5 + x6_2 * a2_2_5;
let a2_6_6 = x6_6 + x6_2 * a2_2_6;
let a2_6_7 = x6_7 + x6_2 * a2_2_7;
let a2_6_8 = x6_8 + x6_2 * a2_2_8;
let t2_6 = y6 + x6_2 * t2_2;
let a2_7_3 = x7_3 + x7_2 * a2_2_3;
let a2_7_4 = x7_4 + x7_2 * a2_2_4;
let a2_7_5 = x7_5 + x7_2 * a2_2_5;
let a2_7_6 = x7_6 + x7_2 * a2_2_6;
let a2_7_7 = x7_7 + x7_2 * a2_2_7;
let a2_7_8 = x7_8 + x7_2 * a2_2_8;
let t2_7 = y7 + x7_2 * t2_2;
let a2_8_3 = x8_3 + x8_2 * a2_2_3;
let a2_8_4 = x8_4 + x8_2 * a2_2_4;
let a2_8_5 = x8_5 + x8_2 * a2_2_5;
let a2_8_6 = x8_6 + x8_2 * a2_2_6;
let a2_8_7 = x8_7 + x8_2 * a2_2_7;
let a2_8_8 = x8_8 + x8_2 * a2_2_8;
let t2_8 = y8 + x8_2 * t2_2;
{
let zm = max(max(Scalar(0.0), select(Scalar(0.0), abs(t2_0), b0)), abs(t2_2));
let zs = ((Scalar(0.0) + select(Scalar(0.0), abs(t2_0), b0)) + abs(t2_2));
c0 = c0 | select(0u, 1u << (pre | 4u), l2 & (t2_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t2_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t2_2 >= -tol.screen * zm) & (t2_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t2_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t2_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t2_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t2_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t2_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a2_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l2 & !dead8 & !(a2_8_8 > tol.tree_pivot * m8_8));
let l8 = l2 & !dead8;
let i8 = Scalar(1.0) / a2_8_8;
let n8 = -i8;
let t8_8 = -t2_8 * i8;
let t8_0 = t2_0 + a2_0_8 * t8_8;
let t8_1 = t2_1 + a2_1_8 * t8_8;
let t8_2 = t2_2 + a2_2_8 * t8_8;
let t8_3 = t2_3 + a2_3_8 * t8_8;
let t8_4 = t2_4 + a2_4_8 * t8_8;
let t8_5 = t2_5 + a2_5_8 * t8_8;
let t8_6 = t2_6 + a2_6_8 * t8_8;
let t8_7 = t2_7 + a2_7_8 * t8_8;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_8));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 4u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a2_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l2 & !dead7 & !(a2_7_7 > tol.tree_pivot * m7_7));
let l7 = l2 & !dead7;
let i7 = Scalar(1.0) / a2_7_7;
let n7 = -i7;
let a7_7_8 = a2_7_8 * n7;
let t7_7 = -t2_7 * i7;
let a7_0_8 = a2_0_8 + a2_0_7 * a7_7_8;
let t7_0 = t2_0 + a2_0_7 * t7_7;
let a7_1_8 = a2_1_8 + a2_1_7 * a7_7_8;
let t7_1 = t2_1 + a2_1_7 * t7_7;
let a7_2_8 = a2_2_8 + a2_2_7 * a7_7_8;
let t7_2 = t2_2 + a2_2_7 * t7_7;
let a7_3_8 = a2_3_8 + a2_3_7 * a7_7_8;
let t7_3 = t2_3 + a2_3_7 * t7_7;
let a7_4_8 = a2_4_8 + a2_4_7 * a7_7_8;
let t7_4 = t2_4 + a2_4_7 * t7_7;
let a7_5_8 = a2_5_8 + a2_5_7 * a7_7_8;
let t7_5 = t2_5 + a2_5_7 * t7_7;
let a7_6_8 = a2_6_8 + a2_6_7 * a7_7_8;
let t7_6 = t2_6 + a2_6_7 * t7_7;
let a7_8_8 = a2_8_8 + a2_8_7 * a7_7_8;
let t7_8 = t2_8 + a2_8_7 * t7_7;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_2)), abs(t7_7));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_2)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 4u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_7)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 4u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a2_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l2 & !dead6 & !(a2_6_6 > tol.tree_pivot * m6_6));
let l6 = l2 & !dead6;
let i6 = Scalar(1.0) / a2_6_6;
let n6 = -i6;
let a6_6_7 = a2_6_7 * n6;
let a6_6_8 = a2_6_8 * n6;
let t6_6 = -t2_6 * i6;
let a6_0_7 = a2_0_7 + a2_0_6 * a6_6_7;
let a6_0_8 = a2_0_8 + a2_0_6 * a6_6_8;
let t6_0 = t2_0 + a2_0_6 * t6_6;
let a6_1_7 = a2_1_7 + a2_1_6 * a6_6_7;
let a6_1_8 = a2_1_8 + a2_1_6 * a6_6_8;
let t6_1 = t2_1 + a2_1_6 * t6_6;
let a6_2_7 = a2_2_7 + a2_2_6 * a6_6_7;
let a6_2_8 = a2_2_8 + a2_2_6 * a6_6_8;
let t6_2 = t2_2 + a2_2_6 * t6_6;
let a6_3_7 = a2_3_7 + a2_3_6 * a6_6_7;
let a6_3_8 = a2_3_8 + a2_3_6 * a6_6_8;
let t6_3 = t2_3 + a2_3_6 * t6_6;
let a6_4_7 = a2_4_7 + a2_4_6 * a6_6_7;
let a6_4_8 = a2_4_8 + a2_4_6 * a6_6_8;
let t6_4 = t2_4 + a2_4_6 * t6_6;
let a6_5_7 = a2_5_7 + a2_5_6 * a6_6_7;
let a6_5_8 = a2_5_8 + a2_5_6 * a6_6_8;
let t6_5 = t2_5 + a2_5_6 * t6_6;
let a6_7_7 = a2_7_7 + a2_7_6 * a6_6_7;
let a6_7_8 = a2_7_8 + a2_7_6 * a6_6_8;
let t6_7 = t2_7 + a2_7_6 * t6_6;
let a6_8_7 = a2_8_7 + a2_8_6 * a6_6_7;
let a6_8_8 = a2_8_8 + a2_8_6 * a6_6_8;
let t6_8 = t2_8 + a2_8_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_2)), abs(t6_6));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_2)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 4u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_6)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 4u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_2)), abs(t7_6)), abs(t7_7));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_2)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 4u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 4u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
{
let dead5 = semi & !(a2_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l2 & !dead5 & !(a2_5_5 > tol.tree_pivot * m5_5));
let l5 = l2 & !dead5;
let i5 = Scalar(1.0) / a2_5_5;
let n5 = -i5;
let a5_5_6 = a2_5_6 * n5;
let a5_5_7 = a2_5_7 * n5;
let a5_5_8 = a2_5_8 * n5;
let t5_5 = -t2_5 * i5;
let a5_0_6 = a2_0_6 + a2_0_5 * a5_5_6;
let a5_0_7 = a2_0_7 + a2_0_5 * a5_5_7;
let a5_0_8 = a2_0_8 + a2_0_5 * a5_5_8;
let t5_0 = t2_0 + a2_0_5 * t5_5;
let a5_1_6 = a2_1_6 + a2_1_5 * a5_5_6;
let a5_1_7 = a2_1_7 + a2_1_5 * a5_5_7;
let a5_1_8 = a2_1_8 + a2_1_5 * a5_5_8;
let t5_1 = t2_1 + a2_1_5 * t5_5;
let a5_2_6 = a2_2_6 + a2_2_5 * a5_5_6;
let a5_2_7 = a2_2_7 + a2_2_5 * a5_5_7;
let a5_2_8 = a2_2_8 + a2_2_5 * a5_5_8;
let t5_2 = t2_2 + a2_2_5 * t5_5;
let a5_3_6 = a2_3_6 + a2_3_5 * a5_5_6;
let a5_3_7 = a2_3_7 + a2_3_5 * a5_5_7;
let a5_3_8 = a2_3_8 + a2_3_5 * a5_5_8;
let t5_3 = t2_3 + a2_3_5 * t5_5;
let a5_4_6 = a2_4_6 + a2_4_5 * a5_5_6;
let a5_4_7 = a2_4_7 + a2_4_5 * a5_5_7;
let a5_4_8 = a2_4_8 + a2_4_5 * a5_5_8;
let t5_4 = t2_4 + a2_4_5 * t5_5;
let a5_6_6 = a2_6_6 + a2_6_5 * a5_5_6;
let a5_6_7 = a2_6_7 + a2_6_5 * a5_5_7;
let a5_6_8 = a2_6_8 + a2_6_5 * a5_5_8;
let t5_6 = t2_6 + a2_6_5 * t5_5;
let a5_7_6 = a2_7_6 + a2_7_5 * a5_5_6;
let a5_7_7 = a2_7_7 + a2_7_5 * a5_5_7;
let a5_7_8 = a2_7_8 + a2_7_5 * a5_5_8;
let t5_7 = t2_7 + a2_7_5 * t5_5;
let a5_8_6 = a2_8_6 + a2_8_5 * a5_5_6;
let a5_8_7 = a2_8_7 + a2_8_5 * a5_5_7;
let a5_8_8 = a2_8_8 + a2_8_5 * a5_5_8;
let t5_8 = t2_8 + a2_8_5 * t5_5;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), abs(t5_2)), abs(t5_5));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + abs(t5_2)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 4u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let t8_8 = -t5_8 * i8;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let t8_7 = t5_7 + a5_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_5)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 4u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let t7_8 = t5_8 + a5_8_7 * t7_7;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_2)), abs(t7_5)), abs(t7_7));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_2)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 4u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 4u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let a6_6_7 = a5_6_7 * n6;
let a6_6_8 = a5_6_8 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let t6_8 = t5_8 + a5_8_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_2)), abs(t6_5)), abs(t6_6));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_2)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 4u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 4u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_2)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_2)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 4u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 4u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
}
{
let dead4 = semi & !(a2_4_4 > tol.tree_singular * m4_4);
ok = ok & !(l2 & !dead4 & !(a2_4_4 > tol.tree_pivot * m4_4));
let l4 = l2 & !dead4;
let i4 = Scalar(1.0) / a2_4_4;
let n4 = -i4;
let a4_4_5 = a2_4_5 * n4;
let a4_4_6 = a2_4_6 * n4;
let a4_4_7 = a2_4_7 * n4;
let a4_4_8 = a2_4_8 * n4;
let t4_4 = -t2_4 * i4;
let a4_0_5 = a2_0_5 + a2_0_4 * a4_4_5;
let a4_0_6 = a2_0_6 + a2_0_4 * a4_4_6;
let a4_0_7 = a2_0_7 + a2_0_4 * a4_4_7;
let a4_0_8 = a2_0_8 + a2_0_4 * a4_4_8;
let t4_0 = t2_0 + a2_0_4 * t4_4;
let a4_1_5 = a2_1_5 + a2_1_4 * a4_4_5;
let a4_1_6 = a2_1_6 + a2_1_4 * a4_4_6;
let a4_1_7 = a2_1_7 + a2_1_4 * a4_4_7;
let a4_1_8 = a2_1_8 + a2_1_4 * a4_4_8;
let t4_1 = t2_1 + a2_1_4 * t4_4;
let a4_2_5 = a2_2_5 + a2_2_4 * a4_4_5;
let a4_2_6 = a2_2_6 + a2_2_4 * a4_4_6;
let a4_2_7 = a2_2_7 + a2_2_4 * a4_4_7;
let a4_2_8 = a2_2_8 + a2_2_4 * a4_4_8;
let t4_2 = t2_2 + a2_2_4 * t4_4;
let a4_3_5 = a2_3_5 + a2_3_4 * a4_4_5;
let a4_3_6 = a2_3_6 + a2_3_4 * a4_4_6;
let a4_3_7 = a2_3_7 + a2_3_4 * a4_4_7;
let a4_3_8 = a2_3_8 + a2_3_4 * a4_4_8;
let t4_3 = t2_3 + a2_3_4 * t4_4;
let a4_5_5 = a2_5_5 + a2_5_4 * a4_4_5;
let a4_5_6 = a2_5_6 + a2_5_4 * a4_4_6;
let a4_5_7 = a2_5_7 + a2_5_4 * a4_4_7;
let a4_5_8 = a2_5_8 + a2_5_4 * a4_4_8;
let t4_5 = t2_5 + a2_5_4 * t4_4;
let a4_6_5 = a2_6_5 + a2_6_4 * a4_4_5;
let a4_6_6 = a2_6_6 + a2_6_4 * a4_4_6;
let a4_6_7 = a2_6_7 + a2_6_4 * a4_4_7;
let a4_6_8 = a2_6_8 + a2_6_4 * a4_4_8;
let t4_6 = t2_6 + a2_6_4 * t4_4;
let a4_7_5 = a2_7_5 + a2_7_4 * a4_4_5;
let a4_7_6 = a2_7_6 + a2_7_4 * a4_4_6;
let a4_7_7 = a2_7_7 + a2_7_4 * a4_4_7;
let a4_7_8 = a2_7_8 + a2_7_4 * a4_4_8;
let t4_7 = t2_7 + a2_7_4 * t4_4;
let a4_8_5 = a2_8_5 + a2_8_4 * a4_4_5;
let a4_8_6 = a2_8_6 + a2_8_4 * a4_4_6;
let a4_8_7 = a2_8_7 + a2_8_4 * a4_4_7;
let a4_8_8 = a2_8_8 + a2_8_4 * a4_4_8;
let t4_8 = t2_8 + a2_8_4 * t4_4;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t4_0), b0)), abs(t4_2)), abs(t4_4));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t4_0), b0)) + abs(t4_2)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 20u), l4 & (t4_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t4_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t4_2 >= -tol.screen * zm) & (t4_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t4_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t4_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a4_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l4 & !dead8 & !(a4_8_8 > tol.tree_pivot * m8_8));
let l8 = l4 & !dead8;
let i8 = Scalar(1.0) / a4_8_8;
let n8 = -i8;
let t8_8 = -t4_8 * i8;
let t8_0 = t4_0 + a4_0_8 * t8_8;
let t8_1 = t4_1 + a4_1_8 * t8_8;
let t8_2 = t4_2 + a4_2_8 * t8_8;
let t8_3 = t4_3 + a4_3_8 * t8_8;
let t8_4 = t4_4 + a4_4_8 * t8_8;
let t8_5 = t4_5 + a4_5_8 * t8_8;
let t8_6 = t4_6 + a4_6_8 * t8_8;
let t8_7 = t4_7 + a4_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_4)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_4)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 20u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a4_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l4 & !dead7 & !(a4_7_7 > tol.tree_pivot * m7_7));
let l7 = l4 & !dead7;
let i7 = Scalar(1.0) / a4_7_7;
let n7 = -i7;
let a7_7_8 = a4_7_8 * n7;
let t7_7 = -t4_7 * i7;
let a7_0_8 = a4_0_8 + a4_0_7 * a7_7_8;
let t7_0 = t4_0 + a4_0_7 * t7_7;
let a7_1_8 = a4_1_8 + a4_1_7 * a7_7_8;
let t7_1 = t4_1 + a4_1_7 * t7_7;
let a7_2_8 = a4_2_8 + a4_2_7 * a7_7_8;
let t7_2 = t4_2 + a4_2_7 * t7_7;
let a7_3_8 = a4_3_8 + a4_3_7 * a7_7_8;
let t7_3 = t4_3 + a4_3_7 * t7_7;
let a7_4_8 = a4_4_8 + a4_4_7 * a7_7_8;
let t7_4 = t4_4 + a4_4_7 * t7_7;
let a7_5_8 = a4_5_8 + a4_5_7 * a7_7_8;
let t7_5 = t4_5 + a4_5_7 * t7_7;
let a7_6_8 = a4_6_8 + a4_6_7 * a7_7_8;
let t7_6 = t4_6 + a4_6_7 * t7_7;
let a7_8_8 = a4_8_8 + a4_8_7 * a7_7_8;
let t7_8 = t4_8 + a4_8_7 * t7_7;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_2)), abs(t7_4)), abs(t7_7));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_2)) + abs(t7_4)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 20u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_4)), abs(t8_7)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_4)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 20u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let a6_6_7 = a4_6_7 * n6;
let a6_6_8 = a4_6_8 * n6;
let t6_6 = -t4_6 * i6;
let a6_0_7 = a4_0_7 + a4_0_6 * a6_6_7;
let a6_0_8 = a4_0_8 + a4_0_6 * a6_6_8;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let a6_1_7 = a4_1_7 + a4_1_6 * a6_6_7;
let a6_1_8 = a4_1_8 + a4_1_6 * a6_6_8;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let a6_2_7 = a4_2_7 + a4_2_6 * a6_6_7;
let a6_2_8 = a4_2_8 + a4_2_6 * a6_6_8;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let a6_3_7 = a4_3_7 + a4_3_6 * a6_6_7;
let a6_3_8 = a4_3_8 + a4_3_6 * a6_6_8;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let a6_4_7 = a4_4_7 + a4_4_6 * a6_6_7;
let a6_4_8 = a4_4_8 + a4_4_6 * a6_6_8;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let a6_5_7 = a4_5_7 + a4_5_6 * a6_6_7;
let a6_5_8 = a4_5_8 + a4_5_6 * a6_6_8;
let t6_5 = t4_5 + a4_5_6 * t6_6;
let a6_7_7 = a4_7_7 + a4_7_6 * a6_6_7;
let a6_7_8 = a4_7_8 + a4_7_6 * a6_6_8;
let t6_7 = t4_7 + a4_7_6 * t6_6;
let a6_8_7 = a4_8_7 + a4_8_6 * a6_6_7;
let a6_8_8 = a4_8_8 + a4_8_6 * a6_6_8;
let t6_8 = t4_8 + a4_8_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_2)), abs(t6_4)), abs(t6_6));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_2)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 20u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_4)), abs(t8_6)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_4)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 20u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_2)), abs(t7_4)), abs(t7_6)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_2)) + abs(t7_4)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 20u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_4)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_4)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 20u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let a5_5_7 = a4_5_7 * n5;
let a5_5_8 = a4_5_8 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let a5_0_7 = a4_0_7 + a4_0_5 * a5_5_7;
let a5_0_8 = a4_0_8 + a4_0_5 * a5_5_8;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let a5_1_7 = a4_1_7 + a4_1_5 * a5_5_7;
let a5_1_8 = a4_1_8 + a4_1_5 * a5_5_8;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let a5_2_7 = a4_2_7 + a4_2_5 * a5_5_7;
let a5_2_8 = a4_2_8 + a4_2_5 * a5_5_8;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let a5_3_7 = a4_3_7 + a4_3_5 * a5_5_7;
let a5_3_8 = a4_3_8 + a4_3_5 * a5_5_8;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let a5_4_7 = a4_4_7 + a4_4_5 * a5_5_7;
let a5_4_8 = a4_4_8 + a4_4_5 * a5_5_8;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let a5_6_7 = a4_6_7 + a4_6_5 * a5_5_7;
let a5_6_8 = a4_6_8 + a4_6_5 * a5_5_8;
let t5_6 = t4_6 + a4_6_5 * t5_5;
let a5_7_6 = a4_7_6 + a4_7_5 * a5_5_6;
let a5_7_7 = a4_7_7 + a4_7_5 * a5_5_7;
let a5_7_8 = a4_7_8 + a4_7_5 * a5_5_8;
let t5_7 = t4_7 + a4_7_5 * t5_5;
let a5_8_6 = a4_8_6 + a4_8_5 * a5_5_6;
let a5_8_7 = a4_8_7 + a4_8_5 * a5_5_7;
let a5_8_8 = a4_8_8 + a4_8_5 * a5_5_8;
let t5_8 = t4_8 + a4_8_5 * t5_5;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), abs(t5_2)), abs(t5_4)), abs(t5_5));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + abs(t5_2)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 20u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let t8_8 = -t5_8 * i8;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let t8_7 = t5_7 + a5_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_4)), abs(t8_5)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_4)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 20u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let t7_8 = t5_8 + a5_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_2)), abs(t7_4)), abs(t7_5)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_2)) + abs(t7_4)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 20u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_4)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_4)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 20u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let a6_6_7 = a5_6_7 * n6;
let a6_6_8 = a5_6_8 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let t6_8 = t5_8 + a5_8_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_2)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_2)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 20u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 20u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_2)), abs(t7_4)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_2)) + abs(t7_4)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 20u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 20u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
}
}
{
let dead3 = semi & !(a2_3_3 > tol.tree_singular * m3_3);
ok = ok & !(l2 & !dead3 & !(a2_3_3 > tol.tree_pivot * m3_3));
let l3 = l2 & !dead3;
let i3 = Scalar(1.0) / a2_3_3;
let n3 = -i3;
let a3_3_4 = a2_3_4 * n3;
let a3_3_5 = a2_3_5 * n3;
let a3_3_6 = a2_3_6 * n3;
let a3_3_7 = a2_3_7 * n3;
let a3_3_8 = a2_3_8 * n3;
let t3_3 = -t2_3 * i3;
let a3_0_4 = a2_0_4 + a2_0_3 * a3_3_4;
let a3_0_5 = a2_0_5 + a2_0_3 * a3_3_5;
let a3_0_6 = a2_0_6 + a2_0_3 * a3_3_6;
let a3_0_7 = a2_0_7 + a2_0_3 * a3_3_7;
let a3_0_8 = a2_0_8 + a2_0_3 * a3_3_8;
let t3_0 = t2_0 + a2_0_3 * t3_3;
let a3_1_4 = a2_1_4 + a2_1_3 * a3_3_4;
let a3_1_5 = a2_1_5 + a2_1_3 * a3_3_5;
let a3_1_6 = a2_1_6 + a2_1_3 * a3_3_6;
let a3_1_7 = a2_1_7 + a2_1_3 * a3_3_7;
let a3_1_8 = a2_1_8 + a2_1_3 * a3_3_8;
let t3_1 = t2_1 + a2_1_3 * t3_3;
let a3_2_4 = a2_2_4 + a2_2_3 * a3_3_4;
let a3_2_5 = a2_2_5 + a2_2_3 * a3_3_5;
let a3_2_6 = a2_2_6 + a2_2_3 * a3_3_6;
let a3_2_7 = a2_2_7 + a2_2_3 * a3_3_7;
let a3_2_8 = a2_2_8 + a2_2_3 * a3_3_8;
let t3_2 = t2_2 + a2_2_3 * t3_3;
let a3_4_4 = a2_4_4 + a2_4_3 * a3_3_4;
let a3_4_5 = a2_4_5 + a2_4_3 * a3_3_5;
let a3_4_6 = a2_4_6 + a2_4_3 * a3_3_6;
let a3_4_7 = a2_4_7 + a2_4_3 * a3_3_7;
let a3_4_8 = a2_4_8 + a2_4_3 * a3_3_8;
let t3_4 = t2_4 + a2_4_3 * t3_3;
let a3_5_4 = a2_5_4 + a2_5_3 * a3_3_4;
let a3_5_5 = a2_5_5 + a2_5_3 * a3_3_5;
let a3_5_6 = a2_5_6 + a2_5_3 * a3_3_6;
let a3_5_7 = a2_5_7 + a2_5_3 * a3_3_7;
let a3_5_8 = a2_5_8 + a2_5_3 * a3_3_8;
let t3_5 = t2_5 + a2_5_3 * t3_3;
let a3_6_4 = a2_6_4 + a2_6_3 * a3_3_4;
let a3_6_5 = a2_6_5 + a2_6_3 * a3_3_5;
let a3_6_6 = a2_6_6 + a2_6_3 * a3_3_6;
let a3_6_7 = a2_6_7 + a2_6_3 * a3_3_7;
let a3_6_8 = a2_6_8 + a2_6_3 * a3_3_8;
let t3_6 = t2_6 + a2_6_3 * t3_3;
let a3_7_4 = a2_7_4 + a2_7_3 * a3_3_4;
let a3_7_5 = a2_7_5 + a2_7_3 * a3_3_5;
let a3_7_6 = a2_7_6 + a2_7_3 * a3_3_6;
let a3_7_7 = a2_7_7 + a2_7_3 * a3_3_7;
let a3_7_8 = a2_7_8 + a2_7_3 * a3_3_8;
let t3_7 = t2_7 + a2_7_3 * t3_3;
let a3_8_4 = a2_8_4 + a2_8_3 * a3_3_4;
let a3_8_5 = a2_8_5 + a2_8_3 * a3_3_5;
let a3_8_6 = a2_8_6 + a2_8_3 * a3_3_6;
let a3_8_7 = a2_8_7 + a2_8_3 * a3_3_7;
let a3_8_8 = a2_8_8 + a2_8_3 * a3_3_8;
let t3_8 = t2_8 + a2_8_3 * t3_3;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t3_0), b0)), abs(t3_2)), abs(t3_3));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t3_0), b0)) + abs(t3_2)) + abs(t3_3));
c0 = c0 | select(0u, 1u << (pre | 12u), l3 & (t3_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t3_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t3_2 >= -tol.screen * zm) & (t3_3 >= -tol.screen * zm) & (t3_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t3_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t3_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t3_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t3_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a3_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l3 & !dead8 & !(a3_8_8 > tol.tree_pivot * m8_8));
let l8 = l3 & !dead8;
let i8 = Scalar(1.0) / a3_8_8;
let n8 = -i8;
let t8_8 = -t3_8 * i8;
let t8_0 = t3_0 + a3_0_8 * t8_8;
let t8_1 = t3_1 + a3_1_8 * t8_8;
let t8_2 = t3_2 + a3_2_8 * t8_8;
let t8_3 = t3_3 + a3_3_8 * t8_8;
let t8_4 = t3_4 + a3_4_8 * t8_8;
let t8_5 = t3_5 + a3_5_8 * t8_8;
let t8_6 = t3_6 + a3_6_8 * t8_8;
let t8_7 = t3_7 + a3_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_3)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_3)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 12u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a3_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l3 & !dead7 & !(a3_7_7 > tol.tree_pivot * m7_7));
let l7 = l3 & !dead7;
let i7 = Scalar(1.0) / a3_7_7;
let n7 = -i7;
let a7_7_8 = a3_7_8 * n7;
let t7_7 = -t3_7 * i7;
let a7_0_8 = a3_0_8 + a3_0_7 * a7_7_8;
let t7_0 = t3_0 + a3_0_7 * t7_7;
let a7_1_8 = a3_1_8 + a3_1_7 * a7_7_8;
let t7_1 = t3_1 + a3_1_7 * t7_7;
let a7_2_8 = a3_2_8 + a3_2_7 * a7_7_8;
let t7_2 = t3_2 + a3_2_7 * t7_7;
let a7_3_8 = a3_3_8 + a3_3_7 * a7_7_8;
let t7_3 = t3_3 + a3_3_7 * t7_7;
let a7_4_8 = a3_4_8 + a3_4_7 * a7_7_8;
let t7_4 = t3_4 + a3_4_7 * t7_7;
let a7_5_8 = a3_5_8 + a3_5_7 * a7_7_8;
let t7_5 = t3_5 + a3_5_7 * t7_7;
let a7_6_8 = a3_6_8 + a3_6_7 * a7_7_8;
let t7_6 = t3_6 + a3_6_7 * t7_7;
let a7_8_8 = a3_8_8 + a3_8_7 * a7_7_8;
let t7_8 = t3_8 + a3_8_7 * t7_7;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_2)), abs(t7_3)), abs(t7_7));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_2)) + abs(t7_3)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 12u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_3)), abs(t8_7)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_3)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 12u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a3_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l3 & !dead6 & !(a3_6_6 > tol.tree_pivot * m6_6));
let l6 = l3 & !dead6;
let i6 = Scalar(1.0) / a3_6_6;
let n6 = -i6;
let a6_6_7 = a3_6_7 * n6;
let a6_6_8 = a3_6_8 * n6;
let t6_6 = -t3_6 * i6;
let a6_0_7 = a3_0_7 + a3_0_6 * a6_6_7;
let a6_0_8 = a3_0_8 + a3_0_6 * a6_6_8;
let t6_0 = t3_0 + a3_0_6 * t6_6;
let a6_1_7 = a3_1_7 + a3_1_6 * a6_6_7;
let a6_1_8 = a3_1_8 + a3_1_6 * a6_6_8;
let t6_1 = t3_1 + a3_1_6 * t6_6;
let a6_2_7 = a3_2_7 + a3_2_6 * a6_6_7;
let a6_2_8 = a3_2_8 + a3_2_6 * a6_6_8;
let t6_2 = t3_2 + a3_2_6 * t6_6;
let a6_3_7 = a3_3_7 + a3_3_6 * a6_6_7;
let a6_3_8 = a3_3_8 + a3_3_6 * a6_6_8;
let t6_3 = t3_3 + a3_3_6 * t6_6;
let a6_4_7 = a3_4_7 + a3_4_6 * a6_6_7;
let a6_4_8 = a3_4_8 + a3_4_6 * a6_6_8;
let t6_4 = t3_4 + a3_4_6 * t6_6;
let a6_5_7 = a3_5_7 + a3_5_6 * a6_6_7;
let a6_5_8 = a3_5_8 + a3_5_6 * a6_6_8;
let t6_5 = t3_5 + a3_5_6 * t6_6;
let a6_7_7 = a3_7_7 + a3_7_6 * a6_6_7;
let a6_7_8 = a3_7_8 + a3_7_6 * a6_6_8;
let t6_7 = t3_7 + a3_7_6 * t6_6;
let a6_8_7 = a3_8_7 + a3_8_6 * a6_6_7;
let a6_8_8 = a3_8_8 + a3_8_6 * a6_6_8;
let t6_8 = t3_8 + a3_8_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_2)), abs(t6_3)), abs(t6_6));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_2)) + abs(t6_3)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 12u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_3)), abs(t8_6)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_3)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 12u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_2)), abs(t7_3)), abs(t7_6)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_2)) + abs(t7_3)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 12u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_3)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_3)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 12u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
{
let dead5 = semi & !(a3_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l3 & !dead5 & !(a3_5_5 > tol.tree_pivot * m5_5));
let l5 = l3 & !dead5;
let i5 = Scalar(1.0) / a3_5_5;
let n5 = -i5;
let a5_5_6 = a3_5_6 * n5;
let a5_5_7 = a3_5_7 * n5;
let a5_5_8 = a3_5_8 * n5;
let t5_5 = -t3_5 * i5;
let a5_0_6 = a3_0_6 + a3_0_5 * a5_5_6;
let a5_0_7 = a3_0_7 + a3_0_5 * a5_5_7;
let a5_0_8 = a3_0_8 + a3_0_5 * a5_5_8;
let t5_0 = t3_0 + a3_0_5 * t5_5;
let a5_1_6 = a3_1_6 + a3_1_5 * a5_5_6;
let a5_1_7 = a3_1_7 + a3_1_5 * a5_5_7;
let a5_1_8 = a3_1_8 + a3_1_5 * a5_5_8;
let t5_1 = t3_1 + a3_1_5 * t5_5;
let a5_2_6 = a3_2_6 + a3_2_5 * a5_5_6;
let a5_2_7 = a3_2_7 + a3_2_5 * a5_5_7;
let a5_2_8 = a3_2_8 + a3_2_5 * a5_5_8;
let t5_2 = t3_2 + a3_2_5 * t5_5;
let a5_3_6 = a3_3_6 + a3_3_5 * a5_5_6;
let a5_3_7 = a3_3_7 + a3_3_5 * a5_5_7;
let a5_3_8 = a3_3_8 + a3_3_5 * a5_5_8;
let t5_3 = t3_3 + a3_3_5 * t5_5;
let a5_4_6 = a3_4_6 + a3_4_5 * a5_5_6;
let a5_4_7 = a3_4_7 + a3_4_5 * a5_5_7;
let a5_4_8 = a3_4_8 + a3_4_5 * a5_5_8;
let t5_4 = t3_4 + a3_4_5 * t5_5;
let a5_6_6 = a3_6_6 + a3_6_5 * a5_5_6;
let a5_6_7 = a3_6_7 + a3_6_5 * a5_5_7;
let a5_6_8 = a3_6_8 + a3_6_5 * a5_5_8;
let t5_6 = t3_6 + a3_6_5 * t5_5;
let a5_7_6 = a3_7_6 + a3_7_5 * a5_5_6;
let a5_7_7 = a3_7_7 + a3_7_5 * a5_5_7;
let a5_7_8 = a3_7_8 + a3_7_5 * a5_5_8;
let t5_7 = t3_7 + a3_7_5 * t5_5;
let a5_8_6 = a3_8_6 + a3_8_5 * a5_5_6;
let a5_8_7 = a3_8_7 + a3_8_5 * a5_5_7;
let a5_8_8 = a3_8_8 + a3_8_5 * a5_5_8;
let t5_8 = t3_8 + a3_8_5 * t5_5;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), abs(t5_2)), abs(t5_3)), abs(t5_5));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + abs(t5_2)) + abs(t5_3)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 12u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let t8_8 = -t5_8 * i8;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let t8_7 = t5_7 + a5_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_3)), abs(t8_5)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_3)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 12u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let t7_8 = t5_8 + a5_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_2)), abs(t7_3)), abs(t7_5)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_2)) + abs(t7_3)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 12u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_3)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_3)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 12u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let a6_6_7 = a5_6_7 * n6;
let a6_6_8 = a5_6_8 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let t6_8 = t5_8 + a5_8_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_2)), abs(t6_3)), abs(t6_5)), abs(t6_6));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_2)) + abs(t6_3)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 12u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_3)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_3)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 12u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_2)), abs(t7_3)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_2)) + abs(t7_3)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 12u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_3)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_3)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 12u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
}
{
let dead4 = semi & !(a3_4_4 > tol.tree_singular * m4_4);
ok = ok & !(l3 & !dead4 & !(a3_4_4 > tol.tree_pivot * m4_4));
let l4 = l3 & !dead4;
let i4 = Scalar(1.0) / a3_4_4;
let n4 = -i4;
let a4_4_5 = a3_4_5 * n4;
let a4_4_6 = a3_4_6 * n4;
let a4_4_7 = a3_4_7 * n4;
let a4_4_8 = a3_4_8 * n4;
let t4_4 = -t3_4 * i4;
let a4_0_5 = a3_0_5 + a3_0_4 * a4_4_5;
let a4_0_6 = a3_0_6 + a3_0_4 * a4_4_6;
let a4_0_7 = a3_0_7 + a3_0_4 * a4_4_7;
let a4_0_8 = a3_0_8 + a3_0_4 * a4_4_8;
let t4_0 = t3_0 + a3_0_4 * t4_4;
let a4_1_5 = a3_1_5 + a3_1_4 * a4_4_5;
let a4_1_6 = a3_1_6 + a3_1_4 * a4_4_6;
let a4_1_7 = a3_1_7 + a3_1_4 * a4_4_7;
let a4_1_8 = a3_1_8 + a3_1_4 * a4_4_8;
let t4_1 = t3_1 + a3_1_4 * t4_4;
let a4_2_5 = a3_2_5 + a3_2_4 * a4_4_5;
let a4_2_6 = a3_2_6 + a3_2_4 * a4_4_6;
let a4_2_7 = a3_2_7 + a3_2_4 * a4_4_7;
let a4_2_8 = a3_2_8 + a3_2_4 * a4_4_8;
let t4_2 = t3_2 + a3_2_4 * t4_4;
let a4_3_5 = a3_3_5 + a3_3_4 * a4_4_5;
let a4_3_6 = a3_3_6 + a3_3_4 * a4_4_6;
let a4_3_7 = a3_3_7 + a3_3_4 * a4_4_7;
let a4_3_8 = a3_3_8 + a3_3_4 * a4_4_8;
let t4_3 = t3_3 + a3_3_4 * t4_4;
let a4_5_5 = a3_5_5 + a3_5_4 * a4_4_5;
let a4_5_6 = a3_5_6 + a3_5_4 * a4_4_6;
let a4_5_7 = a3_5_7 + a3_5_4 * a4_4_7;
let a4_5_8 = a3_5_8 + a3_5_4 * a4_4_8;
let t4_5 = t3_5 + a3_5_4 * t4_4;
let a4_6_5 = a3_6_5 + a3_6_4 * a4_4_5;
let a4_6_6 = a3_6_6 + a3_6_4 * a4_4_6;
let a4_6_7 = a3_6_7 + a3_6_4 * a4_4_7;
let a4_6_8 = a3_6_8 + a3_6_4 * a4_4_8;
let t4_6 = t3_6 + a3_6_4 * t4_4;
let a4_7_5 = a3_7_5 + a3_7_4 * a4_4_5;
let a4_7_6 = a3_7_6 + a3_7_4 * a4_4_6;
let a4_7_7 = a3_7_7 + a3_7_4 * a4_4_7;
let a4_7_8 = a3_7_8 + a3_7_4 * a4_4_8;
let t4_7 = t3_7 + a3_7_4 * t4_4;
let a4_8_5 = a3_8_5 + a3_8_4 * a4_4_5;
let a4_8_6 = a3_8_6 + a3_8_4 * a4_4_6;
let a4_8_7 = a3_8_7 + a3_8_4 * a4_4_7;
let a4_8_8 = a3_8_8 + a3_8_4 * a4_4_8;
let t4_8 = t3_8 + a3_8_4 * t4_4;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t4_0), b0)), abs(t4_2)), abs(t4_3)), abs(t4_4));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t4_0), b0)) + abs(t4_2)) + abs(t4_3)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 28u), l4 & (t4_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t4_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t4_2 >= -tol.screen * zm) & (t4_3 >= -tol.screen * zm) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t4_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t4_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a4_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l4 & !dead8 & !(a4_8_8 > tol.tree_pivot * m8_8));
let l8 = l4 & !dead8;
let i8 = Scalar(1.0) / a4_8_8;
let n8 = -i8;
let t8_8 = -t4_8 * i8;
let t8_0 = t4_0 + a4_0_8 * t8_8;
let t8_1 = t4_1 + a4_1_8 * t8_8;
let t8_2 = t4_2 + a4_2_8 * t8_8;
let t8_3 = t4_3 + a4_3_8 * t8_8;
let t8_4 = t4_4 + a4_4_8 * t8_8;
let t8_5 = t4_5 + a4_5_8 * t8_8;
let t8_6 = t4_6 + a4_6_8 * t8_8;
let t8_7 = t4_7 + a4_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_3)), abs(t8_4)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 28u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a4_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l4 & !dead7 & !(a4_7_7 > tol.tree_pivot * m7_7));
let l7 = l4 & !dead7;
let i7 = Scalar(1.0) / a4_7_7;
let n7 = -i7;
let a7_7_8 = a4_7_8 * n7;
let t7_7 = -t4_7 * i7;
let a7_0_8 = a4_0_8 + a4_0_7 * a7_7_8;
let t7_0 = t4_0 + a4_0_7 * t7_7;
let a7_1_8 = a4_1_8 + a4_1_7 * a7_7_8;
let t7_1 = t4_1 + a4_1_7 * t7_7;
let a7_2_8 = a4_2_8 + a4_2_7 * a7_7_8;
let t7_2 = t4_2 + a4_2_7 * t7_7;
let a7_3_8 = a4_3_8 + a4_3_7 * a7_7_8;
let t7_3 = t4_3 + a4_3_7 * t7_7;
let a7_4_8 = a4_4_8 + a4_4_7 * a7_7_8;
let t7_4 = t4_4 + a4_4_7 * t7_7;
let a7_5_8 = a4_5_8 + a4_5_7 * a7_7_8;
let t7_5 = t4_5 + a4_5_7 * t7_7;
let a7_6_8 = a4_6_8 + a4_6_7 * a7_7_8;
let t7_6 = t4_6 + a4_6_7 * t7_7;
let a7_8_8 = a4_8_8 + a4_8_7 * a7_7_8;
let t7_8 = t4_8 + a4_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_2)), abs(t7_3)), abs(t7_4)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_2)) + abs(t7_3)) + abs(t7_4)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 28u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_3)), abs(t8_4)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 28u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let a6_6_7 = a4_6_7 * n6;
let a6_6_8 = a4_6_8 * n6;
let t6_6 = -t4_6 * i6;
let a6_0_7 = a4_0_7 + a4_0_6 * a6_6_7;
let a6_0_8 = a4_0_8 + a4_0_6 * a6_6_8;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let a6_1_7 = a4_1_7 + a4_1_6 * a6_6_7;
let a6_1_8 = a4_1_8 + a4_1_6 * a6_6_8;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let a6_2_7 = a4_2_7 + a4_2_6 * a6_6_7;
let a6_2_8 = a4_2_8 + a4_2_6 * a6_6_8;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let a6_3_7 = a4_3_7 + a4_3_6 * a6_6_7;
let a6_3_8 = a4_3_8 + a4_3_6 * a6_6_8;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let a6_4_7 = a4_4_7 + a4_4_6 * a6_6_7;
let a6_4_8 = a4_4_8 + a4_4_6 * a6_6_8;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let a6_5_7 = a4_5_7 + a4_5_6 * a6_6_7;
let a6_5_8 = a4_5_8 + a4_5_6 * a6_6_8;
let t6_5 = t4_5 + a4_5_6 * t6_6;
let a6_7_7 = a4_7_7 + a4_7_6 * a6_6_7;
let a6_7_8 = a4_7_8 + a4_7_6 * a6_6_8;
let t6_7 = t4_7 + a4_7_6 * t6_6;
let a6_8_7 = a4_8_7 + a4_8_6 * a6_6_7;
let a6_8_8 = a4_8_8 + a4_8_6 * a6_6_8;
let t6_8 = t4_8 + a4_8_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_2)), abs(t6_3)), abs(t6_4)), abs(t6_6));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_2)) + abs(t6_3)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 28u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_3)), abs(t8_4)), abs(t8_6)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 28u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_2)), abs(t7_3)), abs(t7_4)), abs(t7_6)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_2)) + abs(t7_3)) + abs(t7_4)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 28u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_3)), abs(t8_4)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 28u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let a5_5_7 = a4_5_7 * n5;
let a5_5_8 = a4_5_8 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let a5_0_7 = a4_0_7 + a4_0_5 * a5_5_7;
let a5_0_8 = a4_0_8 + a4_0_5 * a5_5_8;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let a5_1_7 = a4_1_7 + a4_1_5 * a5_5_7;
let a5_1_8 = a4_1_8 + a4_1_5 * a5_5_8;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let a5_2_7 = a4_2_7 + a4_2_5 * a5_5_7;
let a5_2_8 = a4_2_8 + a4_2_5 * a5_5_8;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let a5_3_7 = a4_3_7 + a4_3_5 * a5_5_7;
let a5_3_8 = a4_3_8 + a4_3_5 * a5_5_8;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let a5_4_7 = a4_4_7 + a4_4_5 * a5_5_7;
let a5_4_8 = a4_4_8 + a4_4_5 * a5_5_8;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let a5_6_7 = a4_6_7 + a4_6_5 * a5_5_7;
let a5_6_8 = a4_6_8 + a4_6_5 * a5_5_8;
let t5_6 = t4_6 + a4_6_5 * t5_5;
let a5_7_6 = a4_7_6 + a4_7_5 * a5_5_6;
let a5_7_7 = a4_7_7 + a4_7_5 * a5_5_7;
let a5_7_8 = a4_7_8 + a4_7_5 * a5_5_8;
let t5_7 = t4_7 + a4_7_5 * t5_5;
let a5_8_6 = a4_8_6 + a4_8_5 * a5_5_6;
let a5_8_7 = a4_8_7 + a4_8_5 * a5_5_7;
let a5_8_8 = a4_8_8 + a4_8_5 * a5_5_8;
let t5_8 = t4_8 + a4_8_5 * t5_5;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), abs(t5_2)), abs(t5_3)), abs(t5_4)), abs(t5_5));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + abs(t5_2)) + abs(t5_3)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 28u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let t8_8 = -t5_8 * i8;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let t8_7 = t5_7 + a5_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 28u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let t7_8 = t5_8 + a5_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_2)), abs(t7_3)), abs(t7_4)), abs(t7_5)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_2)) + abs(t7_3)) + abs(t7_4)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 28u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 28u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let a6_6_7 = a5_6_7 * n6;
let a6_6_8 = a5_6_8 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let t6_8 = t5_8 + a5_8_6 * t6_6;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_2)), abs(t6_3)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_2)) + abs(t6_3)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 28u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 28u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_2)), abs(t7_3)), abs(t7_4)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_2)) + abs(t7_3)) + abs(t7_4)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 28u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_2)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 28u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
}
}
}
}
{
let dead1 = semi & !(x1_1 > tol.tree_singular * m1_1);
ok = ok & !(live & !dead1 & !(x1_1 > tol.tree_pivot * m1_1));
let l1 = live & !dead1;
let i1 = Scalar(1.0) / x1_1;
let n1 = -i1;
let a1_1_2 = x1_2 * n1;
let a1_1_3 = x1_3 * n1;
let a1_1_4 = x1_4 * n1;
let a1_1_5 = x1_5 * n1;
let a1_1_6 = x1_6 * n1;
let a1_1_7 = x1_7 * n1;
let a1_1_8 = x1_8 * n1;
let t1_1 = -y1 * i1;
let a1_0_2 = x0_2 + x0_1 * a1_1_2;
let a1_0_3 = x0_3 + x0_1 * a1_1_3;
let a1_0_4 = x0_4 + x0_1 * a1_1_4;
let a1_0_5 = x0_5 + x0_1 * a1_1_5;
let a1_0_6 = x0_6 + x0_1 * a1_1_6;
let a1_0_7 = x0_7 + x0_1 * a1_1_7;
let a1_0_8 = x0_8 + x0_1 * a1_1_8;
let t1_0 = y0 + x0_1 * t1_1;
let a1_2_2 = x2_2 + x2_1 * a1_1_2;
let a1_2_3 = x2_3 + x2_1 * a1_1_3;
let a1_2_4 = x2_4 + x2_1 * a1_1_4;
let a1_2_5 = x2_5 + x2_1 * a1_1_5;
let a1_2_6 = x2_6 + x2_1 * a1_1_6;
let a1_2_7 = x2_7 + x2_1 * a1_1_7;
let a1_2_8 = x2_8 + x2_1 * a1_1_8;
let t1_2 = y2 + x2_1 * t1_1;
let a1_3_2 = x3_2 + x3_1 * a1_1_2;
let a1_3_3 = x3_3 + x3_1 * a1_1_3;
let a1_3_4 = x3_4 + x3_1 * a1_1_4;
let a1_3_5 = x3_5 + x3_1 * a1_1_5;
let a1_3_6 = x3_6 + x3_1 * a1_1_6;
let a1_3_7 = x3_7 + x3_1 * a1_1_7;
let a1_3_8 = x3_8 + x3_1 * a1_1_8;
let t1_3 = y3 + x3_1 * t1_1;
let a1_4_2 = x4_2 + x4_1 * a1_1_2;
let a1_4_3 = x4_3 + x4_1 * a1_1_3;
let a1_4_4 = x4_4 + x4_1 * a1_1_4;
let a1_4_5 = x4_5 + x4_1 * a1_1_5;
let a1_4_6 = x4_6 + x4_1 * a1_1_6;
let a1_4_7 = x4_7 + x4_1 * a1_1_7;
let a1_4_8 = x4_8 + x4_1 * a1_1_8;
let t1_4 = y4 + x4_1 * t1_1;
let a1_5_2 = x5_2 + x5_1 * a1_1_2;
let a1_5_3 = x5_3 + x5_1 * a1_1_3;
let a1_5_4 = x5_4 + x5_1 * a1_1_4;
let a1_5_5 = x5_5 + x5_1 * a1_1_5;
let a1_5_6 = x5_6 + x5_1 * a1_1_6;
let a1_5_7 = x5_7 + x5_1 * a1_1_7;
let a1_5_8 = x5_8 + x5_1 * a1_1_8;
let t1_5 = y5 + x5_1 * t1_1;
let a1_6_2 = x6_2 + x6_1 * a1_1_2;
let a1_6_3 = x6_3 + x6_1 * a1_1_3;
let a1_6_4 = x6_4 + x6_1 * a1_1_4;
let a1_6_5 = x6_5 + x6_1 * a1_1_5;
let a1_6_6 = x6_6 + x6_1 * a1_1_6;
let a1_6_7 = x6_7 + x6_1 * a1_1_7;
let a1_6_8 = x6_8 + x6_1 * a1_1_8;
let t1_6 = y6 + x6_1 * t1_1;
let a1_7_2 = x7_2 + x7_1 * a1_1_2;
let a1_7_3 = x7_3 + x7_1 * a1_1_3;
let a1_7_4 = x7_4 + x7_1 * a1_1_4;
let a1_7_5 = x7_5 + x7_1 * a1_1_5;
let a1_7_6 = x7_6 + x7_1 * a1_1_6;
let a1_7_7 = x7_7 + x7_1 * a1_1_7;
let a1_7_8 = x7_8 + x7_1 * a1_1_8;
let t1_7 = y7 + x7_1 * t1_1;
let a1_8_2 = x8_2 + x8_1 * a1_1_2;
let a1_8_3 = x8_3 + x8_1 * a1_1_3;
let a1_8_4 = x8_4 + x8_1 * a1_1_4;
let a1_8_5 = x8_5 + x8_1 * a1_1_5;
let a1_8_6 = x8_6 + x8_1 * a1_1_6;
let a1_8_7 = x8_7 + x8_1 * a1_1_7;
let a1_8_8 = x8_8 + x8_1 * a1_1_8;
let t1_8 = y8 + x8_1 * t1_1;
{
let zm = max(max(Scalar(0.0), select(Scalar(0.0), abs(t1_0), b0)), abs(t1_1));
let zs = ((Scalar(0.0) + select(Scalar(0.0), abs(t1_0), b0)) + abs(t1_1));
c0 = c0 | select(0u, 1u << (pre | 2u), l1 & (t1_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t1_1 >= -tol.screen * zm) & (t1_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t1_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t1_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t1_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t1_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t1_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t1_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a1_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l1 & !dead8 & !(a1_8_8 > tol.tree_pivot * m8_8));
let l8 = l1 & !dead8;
let i8 = Scalar(1.0) / a1_8_8;
let n8 = -i8;
let t8_8 = -t1_8 * i8;
let t8_0 = t1_0 + a1_0_8 * t8_8;
let t8_1 = t1_1 + a1_1_8 * t8_8;
let t8_2 = t1_2 + a1_2_8 * t8_8;
let t8_3 = t1_3 + a1_3_8 * t8_8;
let t8_4 = t1_4 + a1_4_8 * t8_8;
let t8_5 = t1_5 + a1_5_8 * t8_8;
let t8_6 = t1_6 + a1_6_8 * t8_8;
let t8_7 = t1_7 + a1_7_8 * t8_8;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_8));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 2u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a1_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l1 & !dead7 & !(a1_7_7 > tol.tree_pivot * m7_7));
let l7 = l1 & !dead7;
let i7 = Scalar(1.0) / a1_7_7;
let n7 = -i7;
let a7_7_8 = a1_7_8 * n7;
let t7_7 = -t1_7 * i7;
let a7_0_8 = a1_0_8 + a1_0_7 * a7_7_8;
let t7_0 = t1_0 + a1_0_7 * t7_7;
let a7_1_8 = a1_1_8 + a1_1_7 * a7_7_8;
let t7_1 = t1_1 + a1_1_7 * t7_7;
let a7_2_8 = a1_2_8 + a1_2_7 * a7_7_8;
let t7_2 = t1_2 + a1_2_7 * t7_7;
let a7_3_8 = a1_3_8 + a1_3_7 * a7_7_8;
let t7_3 = t1_3 + a1_3_7 * t7_7;
let a7_4_8 = a1_4_8 + a1_4_7 * a7_7_8;
let t7_4 = t1_4 + a1_4_7 * t7_7;
let a7_5_8 = a1_5_8 + a1_5_7 * a7_7_8;
let t7_5 = t1_5 + a1_5_7 * t7_7;
let a7_6_8 = a1_6_8 + a1_6_7 * a7_7_8;
let t7_6 = t1_6 + a1_6_7 * t7_7;
let a7_8_8 = a1_8_8 + a1_8_7 * a7_7_8;
let t7_8 = t1_8 + a1_8_7 * t7_7;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_7));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 2u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_7)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 2u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a1_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l1 & !dead6 & !(a1_6_6 > tol.tree_pivot * m6_6));
let l6 = l1 & !dead6;
let i6 = Scalar(1.0) / a1_6_6;
let n6 = -i6;
let a6_6_7 = a1_6_7 * n6;
let a6_6_8 = a1_6_8 * n6;
let t6_6 = -t1_6 * i6;
let a6_0_7 = a1_0_7 + a1_0_6 * a6_6_7;
let a6_0_8 = a1_0_8 + a1_0_6 * a6_6_8;
let t6_0 = t1_0 + a1_0_6 * t6_6;
let a6_1_7 = a1_1_7 + a1_1_6 * a6_6_7;
let a6_1_8 = a1_1_8 + a1_1_6 * a6_6_8;
let t6_1 = t1_1 + a1_1_6 * t6_6;
let a6_2_7 = a1_2_7 + a1_2_6 * a6_6_7;
let a6_2_8 = a1_2_8 + a1_2_6 * a6_6_8;
let t6_2 = t1_2 + a1_2_6 * t6_6;
let a6_3_7 = a1_3_7 + a1_3_6 * a6_6_7;
let a6_3_8 = a1_3_8 + a1_3_6 * a6_6_8;
let t6_3 = t1_3 + a1_3_6 * t6_6;
let a6_4_7 = a1_4_7 + a1_4_6 * a6_6_7;
let a6_4_8 = a1_4_8 + a1_4_6 * a6_6_8;
let t6_4 = t1_4 + a1_4_6 * t6_6;
let a6_5_7 = a1_5_7 + a1_5_6 * a6_6_7;
let a6_5_8 = a1_5_8 + a1_5_6 * a6_6_8;
let t6_5 = t1_5 + a1_5_6 * t6_6;
let a6_7_7 = a1_7_7 + a1_7_6 * a6_6_7;
let a6_7_8 = a1_7_8 + a1_7_6 * a6_6_8;
let t6_7 = t1_7 + a1_7_6 * t6_6;
let a6_8_7 = a1_8_7 + a1_8_6 * a6_6_7;
let a6_8_8 = a1_8_8 + a1_8_6 * a6_6_8;
let t6_8 = t1_8 + a1_8_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_1)), abs(t6_6));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_1)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 2u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_6)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 2u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_6)), abs(t7_7));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 2u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 2u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
{
let dead5 = semi & !(a1_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l1 & !dead5 & !(a1_5_5 > tol.tree_pivot * m5_5));
let l5 = l1 & !dead5;
let i5 = Scalar(1.0) / a1_5_5;
let n5 = -i5;
let a5_5_6 = a1_5_6 * n5;
let a5_5_7 = a1_5_7 * n5;
let a5_5_8 = a1_5_8 * n5;
let t5_5 = -t1_5 * i5;
let a5_0_6 = a1_0_6 + a1_0_5 * a5_5_6;
let a5_0_7 = a1_0_7 + a1_0_5 * a5_5_7;
let a5_0_8 = a1_0_8 + a1_0_5 * a5_5_8;
let t5_0 = t1_0 + a1_0_5 * t5_5;
let a5_1_6 = a1_1_6 + a1_1_5 * a5_5_6;
let a5_1_7 = a1_1_7 + a1_1_5 * a5_5_7;
let a5_1_8 = a1_1_8 + a1_1_5 * a5_5_8;
let t5_1 = t1_1 + a1_1_5 * t5_5;
let a5_2_6 = a1_2_6 + a1_2_5 * a5_5_6;
let a5_2_7 = a1_2_7 + a1_2_5 * a5_5_7;
let a5_2_8 = a1_2_8 + a1_2_5 * a5_5_8;
let t5_2 = t1_2 + a1_2_5 * t5_5;
let a5_3_6 = a1_3_6 + a1_3_5 * a5_5_6;
let a5_3_7 = a1_3_7 + a1_3_5 * a5_5_7;
let a5_3_8 = a1_3_8 + a1_3_5 * a5_5_8;
let t5_3 = t1_3 + a1_3_5 * t5_5;
let a5_4_6 = a1_4_6 + a1_4_5 * a5_5_6;
let a5_4_7 = a1_4_7 + a1_4_5 * a5_5_7;
let a5_4_8 = a1_4_8 + a1_4_5 * a5_5_8;
let t5_4 = t1_4 + a1_4_5 * t5_5;
let a5_6_6 = a1_6_6 + a1_6_5 * a5_5_6;
let a5_6_7 = a1_6_7 + a1_6_5 * a5_5_7;
let a5_6_8 = a1_6_8 + a1_6_5 * a5_5_8;
let t5_6 = t1_6 + a1_6_5 * t5_5;
let a5_7_6 = a1_7_6 + a1_7_5 * a5_5_6;
let a5_7_7 = a1_7_7 + a1_7_5 * a5_5_7;
let a5_7_8 = a1_7_8 + a1_7_5 * a5_5_8;
let t5_7 = t1_7 + a1_7_5 * t5_5;
let a5_8_6 = a1_8_6 + a1_8_5 * a5_5_6;
let a5_8_7 = a1_8_7 + a1_8_5 * a5_5_7;
let a5_8_8 = a1_8_8 + a1_8_5 * a5_5_8;
let t5_8 = t1_8 + a1_8_5 * t5_5;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), abs(t5_1)), abs(t5_5));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + abs(t5_1)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 2u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let t8_8 = -t5_8 * i8;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let t8_7 = t5_7 + a5_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_5)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 2u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let t7_8 = t5_8 + a5_8_7 * t7_7;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_5)), abs(t7_7));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 2u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 2u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let a6_6_7 = a5_6_7 * n6;
let a6_6_8 = a5_6_8 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let t6_8 = t5_8 + a5_8_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_1)), abs(t6_5)), abs(t6_6));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_1)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 2u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 2u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 2u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 2u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
}
{
let dead4 = semi & !(a1_4_4 > tol.tree_singular * m4_4);
ok = ok & !(l1 & !dead4 & !(a1_4_4 > tol.tree_pivot * m4_4));
let l4 = l1 & !dead4;
let i4 = Scalar(1.0) / a1_4_4;
let n4 = -i4;
let a4_4_5 = a1_4_5 * n4;
let a4_4_6 = a1_4_6 * n4;
let a4_4_7 = a1_4_7 * n4;
let a4_4_8 = a1_4_8 * n4;
let t4_4 = -t1_4 * i4;
let a4_0_5 = a1_0_5 + a1_0_4 * a4_4_5;
let a4_0_6 = a1_0_6 + a1_0_4 * a4_4_6;
let a4_0_7 = a1_0_7 + a1_0_4 * a4_4_7;
let a4_0_8 = a1_0_8 + a1_0_4 * a4_4_8;
let t4_0 = t1_0 + a1_0_4 * t4_4;
let a4_1_5 = a1_1_5 + a1_1_4 * a4_4_5;
let a4_1_6 = a1_1_6 + a1_1_4 * a4_4_6;
let a4_1_7 = a1_1_7 + a1_1_4 * a4_4_7;
let a4_1_8 = a1_1_8 + a1_1_4 * a4_4_8;
let t4_1 = t1_1 + a1_1_4 * t4_4;
let a4_2_5 = a1_2_5 + a1_2_4 * a4_4_5;
let a4_2_6 = a1_2_6 + a1_2_4 * a4_4_6;
let a4_2_7 = a1_2_7 + a1_2_4 * a4_4_7;
let a4_2_8 = a1_2_8 + a1_2_4 * a4_4_8;
let t4_2 = t1_2 + a1_2_4 * t4_4;
let a4_3_5 = a1_3_5 + a1_3_4 * a4_4_5;
let a4_3_6 = a1_3_6 + a1_3_4 * a4_4_6;
let a4_3_7 = a1_3_7 + a1_3_4 * a4_4_7;
let a4_3_8 = a1_3_8 + a1_3_4 * a4_4_8;
let t4_3 = t1_3 + a1_3_4 * t4_4;
let a4_5_5 = a1_5_5 + a1_5_4 * a4_4_5;
let a4_5_6 = a1_5_6 + a1_5_4 * a4_4_6;
let a4_5_7 = a1_5_7 + a1_5_4 * a4_4_7;
let a4_5_8 = a1_5_8 + a1_5_4 * a4_4_8;
let t4_5 = t1_5 + a1_5_4 * t4_4;
let a4_6_5 = a1_6_5 + a1_6_4 * a4_4_5;
let a4_6_6 = a1_6_6 + a1_6_4 * a4_4_6;
let a4_6_7 = a1_6_7 + a1_6_4 * a4_4_7;
let a4_6_8 = a1_6_8 + a1_6_4 * a4_4_8;
let t4_6 = t1_6 + a1_6_4 * t4_4;
let a4_7_5 = a1_7_5 + a1_7_4 * a4_4_5;
let a4_7_6 = a1_7_6 + a1_7_4 * a4_4_6;
let a4_7_7 = a1_7_7 + a1_7_4 * a4_4_7;
let a4_7_8 = a1_7_8 + a1_7_4 * a4_4_8;
let t4_7 = t1_7 + a1_7_4 * t4_4;
let a4_8_5 = a1_8_5 + a1_8_4 * a4_4_5;
let a4_8_6 = a1_8_6 + a1_8_4 * a4_4_6;
let a4_8_7 = a1_8_7 + a1_8_4 * a4_4_7;
let a4_8_8 = a1_8_8 + a1_8_4 * a4_4_8;
let t4_8 = t1_8 + a1_8_4 * t4_4;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t4_0), b0)), abs(t4_1)), abs(t4_4));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t4_0), b0)) + abs(t4_1)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 18u), l4 & (t4_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t4_1 >= -tol.screen * zm) & (t4_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t4_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t4_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t4_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a4_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l4 & !dead8 & !(a4_8_8 > tol.tree_pivot * m8_8));
let l8 = l4 & !dead8;
let i8 = Scalar(1.0) / a4_8_8;
let n8 = -i8;
let t8_8 = -t4_8 * i8;
let t8_0 = t4_0 + a4_0_8 * t8_8;
let t8_1 = t4_1 + a4_1_8 * t8_8;
let t8_2 = t4_2 + a4_2_8 * t8_8;
let t8_3 = t4_3 + a4_3_8 * t8_8;
let t8_4 = t4_4 + a4_4_8 * t8_8;
let t8_5 = t4_5 + a4_5_8 * t8_8;
let t8_6 = t4_6 + a4_6_8 * t8_8;
let t8_7 = t4_7 + a4_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_4)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_4)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 18u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a4_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l4 & !dead7 & !(a4_7_7 > tol.tree_pivot * m7_7));
let l7 = l4 & !dead7;
let i7 = Scalar(1.0) / a4_7_7;
let n7 = -i7;
let a7_7_8 = a4_7_8 * n7;
let t7_7 = -t4_7 * i7;
let a7_0_8 = a4_0_8 + a4_0_7 * a7_7_8;
let t7_0 = t4_0 + a4_0_7 * t7_7;
let a7_1_8 = a4_1_8 + a4_1_7 * a7_7_8;
let t7_1 = t4_1 + a4_1_7 * t7_7;
let a7_2_8 = a4_2_8 + a4_2_7 * a7_7_8;
let t7_2 = t4_2 + a4_2_7 * t7_7;
let a7_3_8 = a4_3_8 + a4_3_7 * a7_7_8;
let t7_3 = t4_3 + a4_3_7 * t7_7;
let a7_4_8 = a4_4_8 + a4_4_7 * a7_7_8;
let t7_4 = t4_4 + a4_4_7 * t7_7;
let a7_5_8 = a4_5_8 + a4_5_7 * a7_7_8;
let t7_5 = t4_5 + a4_5_7 * t7_7;
let a7_6_8 = a4_6_8 + a4_6_7 * a7_7_8;
let t7_6 = t4_6 + a4_6_7 * t7_7;
let a7_8_8 = a4_8_8 + a4_8_7 * a7_7_8;
let t7_8 = t4_8 + a4_8_7 * t7_7;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_4)), abs(t7_7));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_4)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 18u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_4)), abs(t8_7)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_4)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 18u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let a6_6_7 = a4_6_7 * n6;
let a6_6_8 = a4_6_8 * n6;
let t6_6 = -t4_6 * i6;
let a6_0_7 = a4_0_7 + a4_0_6 * a6_6_7;
let a6_0_8 = a4_0_8 + a4_0_6 * a6_6_8;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let a6_1_7 = a4_1_7 + a4_1_6 * a6_6_7;
let a6_1_8 = a4_1_8 + a4_1_6 * a6_6_8;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let a6_2_7 = a4_2_7 + a4_2_6 * a6_6_7;
let a6_2_8 = a4_2_8 + a4_2_6 * a6_6_8;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let a6_3_7 = a4_3_7 + a4_3_6 * a6_6_7;
let a6_3_8 = a4_3_8 + a4_3_6 * a6_6_8;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let a6_4_7 = a4_4_7 + a4_4_6 * a6_6_7;
let a6_4_8 = a4_4_8 + a4_4_6 * a6_6_8;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let a6_5_7 = a4_5_7 + a4_5_6 * a6_6_7;
let a6_5_8 = a4_5_8 + a4_5_6 * a6_6_8;
let t6_5 = t4_5 + a4_5_6 * t6_6;
let a6_7_7 = a4_7_7 + a4_7_6 * a6_6_7;
let a6_7_8 = a4_7_8 + a4_7_6 * a6_6_8;
let t6_7 = t4_7 + a4_7_6 * t6_6;
let a6_8_7 = a4_8_7 + a4_8_6 * a6_6_7;
let a6_8_8 = a4_8_8 + a4_8_6 * a6_6_8;
let t6_8 = t4_8 + a4_8_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_1)), abs(t6_4)), abs(t6_6));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_1)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 18u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_4)), abs(t8_6)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_4)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 18u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_4)), abs(t7_6)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_4)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 18u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_4)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_4)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 18u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let a5_5_7 = a4_5_7 * n5;
let a5_5_8 = a4_5_8 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let a5_0_7 = a4_0_7 + a4_0_5 * a5_5_7;
let a5_0_8 = a4_0_8 + a4_0_5 * a5_5_8;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let a5_1_7 = a4_1_7 + a4_1_5 * a5_5_7;
let a5_1_8 = a4_1_8 + a4_1_5 * a5_5_8;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let a5_2_7 = a4_2_7 + a4_2_5 * a5_5_7;
let a5_2_8 = a4_2_8 + a4_2_5 * a5_5_8;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let a5_3_7 = a4_3_7 + a4_3_5 * a5_5_7;
let a5_3_8 = a4_3_8 + a4_3_5 * a5_5_8;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let a5_4_7 = a4_4_7 + a4_4_5 * a5_5_7;
let a5_4_8 = a4_4_8 + a4_4_5 * a5_5_8;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let a5_6_7 = a4_6_7 + a4_6_5 * a5_5_7;
let a5_6_8 = a4_6_8 + a4_6_5 * a5_5_8;
let t5_6 = t4_6 + a4_6_5 * t5_5;
let a5_7_6 = a4_7_6 + a4_7_5 * a5_5_6;
let a5_7_7 = a4_7_7 + a4_7_5 * a5_5_7;
let a5_7_8 = a4_7_8 + a4_7_5 * a5_5_8;
let t5_7 = t4_7 + a4_7_5 * t5_5;
let a5_8_6 = a4_8_6 + a4_8_5 * a5_5_6;
let a5_8_7 = a4_8_7 + a4_8_5 * a5_5_7;
let a5_8_8 = a4_8_8 + a4_8_5 * a5_5_8;
let t5_8 = t4_8 + a4_8_5 * t5_5;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), abs(t5_1)), abs(t5_4)), abs(t5_5));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + abs(t5_1)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 18u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let t8_8 = -t5_8 * i8;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let t8_7 = t5_7 + a5_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_4)), abs(t8_5)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_4)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 18u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let t7_8 = t5_8 + a5_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_4)), abs(t7_5)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_4)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 18u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_4)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_4)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 18u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let a6_6_7 = a5_6_7 * n6;
let a6_6_8 = a5_6_8 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let t6_8 = t5_8 + a5_8_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_1)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_1)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 18u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 18u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_4)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_4)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 18u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 18u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
}
}
{
let dead3 = semi & !(a1_3_3 > tol.tree_singular * m3_3);
ok = ok & !(l1 & !dead3 & !(a1_3_3 > tol.tree_pivot * m3_3));
let l3 = l1 & !dead3;
let i3 = Scalar(1.0) / a1_3_3;
let n3 = -i3;
let a3_3_4 = a1_3_4 * n3;
let a3_3_5 = a1_3_5 * n3;
let a3_3_6 = a1_3_6 * n3;
let a3_3_7 = a1_3_7 * n3;
let a3_3_8 = a1_3_8 * n3;
let t3_3 = -t1_3 * i3;
let a3_0_4 = a1_0_4 + a1_0_3 * a3_3_4;
let a3_0_5 = a1_0_5 + a1_0_3 * a3_3_5;
let a3_0_6 = a1_0_6 + a1_0_3 * a3_3_6;
let a3_0_7 = a1_0_7 + a1_0_3 * a3_3_7;
let a3_0_8 = a1_0_8 + a1_0_3 * a3_3_8;
let t3_0 = t1_0 + a1_0_3 * t3_3;
let a3_1_4 = a1_1_4 + a1_1_3 * a3_3_4;
let a3_1_5 = a1_1_5 + a1_1_3 * a3_3_5;
let a3_1_6 = a1_1_6 + a1_1_3 * a3_3_6;
let a3_1_7 = a1_1_7 + a1_1_3 * a3_3_7;
let a3_1_8 = a1_1_8 + a1_1_3 * a3_3_8;
let t3_1 = t1_1 + a1_1_3 * t3_3;
let a3_2_4 = a1_2_4 + a1_2_3 * a3_3_4;
let a3_2_5 = a1_2_5 + a1_2_3 * a3_3_5;
let a3_2_6 = a1_2_6 + a1_2_3 * a3_3_6;
let a3_2_7 = a1_2_7 + a1_2_3 * a3_3_7;
let a3_2_8 = a1_2_8 + a1_2_3 * a3_3_8;
let t3_2 = t1_2 + a1_2_3 * t3_3;
let a3_4_4 = a1_4_4 + a1_4_3 * a3_3_4;
let a3_4_5 = a1_4_5 + a1_4_3 * a3_3_5;
let a3_4_6 = a1_4_6 + a1_4_3 * a3_3_6;
let a3_4_7 = a1_4_7 + a1_4_3 * a3_3_7;
let a3_4_8 = a1_4_8 + a1_4_3 * a3_3_8;
let t3_4 = t1_4 + a1_4_3 * t3_3;
let a3_5_4 = a1_5_4 + a1_5_3 * a3_3_4;
let a3_5_5 = a1_5_5 + a1_5_3 * a3_3_5;
let a3_5_6 = a1_5_6 + a1_5_3 * a3_3_6;
let a3_5_7 = a1_5_7 + a1_5_3 * a3_3_7;
let a3_5_8 = a1_5_8 + a1_5_3 * a3_3_8;
let t3_5 = t1_5 + a1_5_3 * t3_3;
let a3_6_4 = a1_6_4 + a1_6_3 * a3_3_4;
let a3_6_5 = a1_6_5 + a1_6_3 * a3_3_5;
let a3_6_6 = a1_6_6 + a1_6_3 * a3_3_6;
let a3_6_7 = a1_6_7 + a1_6_3 * a3_3_7;
let a3_6_8 = a1_6_8 + a1_6_3 * a3_3_8;
let t3_6 = t1_6 + a1_6_3 * t3_3;
let a3_7_4 = a1_7_4 + a1_7_3 * a3_3_4;
let a3_7_5 = a1_7_5 + a1_7_3 * a3_3_5;
let a3_7_6 = a1_7_6 + a1_7_3 * a3_3_6;
let a3_7_7 = a1_7_7 + a1_7_3 * a3_3_7;
let a3_7_8 = a1_7_8 + a1_7_3 * a3_3_8;
let t3_7 = t1_7 + a1_7_3 * t3_3;
let a3_8_4 = a1_8_4 + a1_8_3 * a3_3_4;
let a3_8_5 = a1_8_5 + a1_8_3 * a3_3_5;
let a3_8_6 = a1_8_6 + a1_8_3 * a3_3_6;
let a3_8_7 = a1_8_7 + a1_8_3 * a3_3_7;
let a3_8_8 = a1_8_8 + a1_8_3 * a3_3_8;
let t3_8 = t1_8 + a1_8_3 * t3_3;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t3_0), b0)), abs(t3_1)), abs(t3_3));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t3_0), b0)) + abs(t3_1)) + abs(t3_3));
c0 = c0 | select(0u, 1u << (pre | 10u), l3 & (t3_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t3_1 >= -tol.screen * zm) & (t3_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t3_3 >= -tol.screen * zm) & (t3_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t3_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t3_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t3_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t3_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a3_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l3 & !dead8 & !(a3_8_8 > tol.tree_pivot * m8_8));
let l8 = l3 & !dead8;
let i8 = Scalar(1.0) / a3_8_8;
let n8 = -i8;
let t8_8 = -t3_8 * i8;
let t8_0 = t3_0 + a3_0_8 * t8_8;
let t8_1 = t3_1 + a3_1_8 * t8_8;
let t8_2 = t3_2 + a3_2_8 * t8_8;
let t8_3 = t3_3 + a3_3_8 * t8_8;
let t8_4 = t3_4 + a3_4_8 * t8_8;
let t8_5 = t3_5 + a3_5_8 * t8_8;
let t8_6 = t3_6 + a3_6_8 * t8_8;
let t8_7 = t3_7 + a3_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_3)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_3)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 10u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a3_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l3 & !dead7 & !(a3_7_7 > tol.tree_pivot * m7_7));
let l7 = l3 & !dead7;
let i7 = Scalar(1.0) / a3_7_7;
let n7 = -i7;
let a7_7_8 = a3_7_8 * n7;
let t7_7 = -t3_7 * i7;
let a7_0_8 = a3_0_8 + a3_0_7 * a7_7_8;
let t7_0 = t3_0 + a3_0_7 * t7_7;
let a7_1_8 = a3_1_8 + a3_1_7 * a7_7_8;
let t7_1 = t3_1 + a3_1_7 * t7_7;
let a7_2_8 = a3_2_8 + a3_2_7 * a7_7_8;
let t7_2 = t3_2 + a3_2_7 * t7_7;
let a7_3_8 = a3_3_8 + a3_3_7 * a7_7_8;
let t7_3 = t3_3 + a3_3_7 * t7_7;
let a7_4_8 = a3_4_8 + a3_4_7 * a7_7_8;
let t7_4 = t3_4 + a3_4_7 * t7_7;
let a7_5_8 = a3_5_8 + a3_5_7 * a7_7_8;
let t7_5 = t3_5 + a3_5_7 * t7_7;
let a7_6_8 = a3_6_8 + a3_6_7 * a7_7_8;
let t7_6 = t3_6 + a3_6_7 * t7_7;
let a7_8_8 = a3_8_8 + a3_8_7 * a7_7_8;
let t7_8 = t3_8 + a3_8_7 * t7_7;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_3)), abs(t7_7));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_3)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 10u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_3)), abs(t8_7)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_3)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 10u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a3_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l3 & !dead6 & !(a3_6_6 > tol.tree_pivot * m6_6));
let l6 = l3 & !dead6;
let i6 = Scalar(1.0) / a3_6_6;
let n6 = -i6;
let a6_6_7 = a3_6_7 * n6;
let a6_6_8 = a3_6_8 * n6;
let t6_6 = -t3_6 * i6;
let a6_0_7 = a3_0_7 + a3_0_6 * a6_6_7;
let a6_0_8 = a3_0_8 + a3_0_6 * a6_6_8;
let t6_0 = t3_0 + a3_0_6 * t6_6;
let a6_1_7 = a3_1_7 + a3_1_6 * a6_6_7;
let a6_1_8 = a3_1_8 + a3_1_6 * a6_6_8;
let t6_1 = t3_1 + a3_1_6 * t6_6;
let a6_2_7 = a3_2_7 + a3_2_6 * a6_6_7;
let a6_2_8 = a3_2_8 + a3_2_6 * a6_6_8;
let t6_2 = t3_2 + a3_2_6 * t6_6;
let a6_3_7 = a3_3_7 + a3_3_6 * a6_6_7;
let a6_3_8 = a3_3_8 + a3_3_6 * a6_6_8;
let t6_3 = t3_3 + a3_3_6 * t6_6;
let a6_4_7 = a3_4_7 + a3_4_6 * a6_6_7;
let a6_4_8 = a3_4_8 + a3_4_6 * a6_6_8;
let t6_4 = t3_4 + a3_4_6 * t6_6;
let a6_5_7 = a3_5_7 + a3_5_6 * a6_6_7;
let a6_5_8 = a3_5_8 + a3_5_6 * a6_6_8;
let t6_5 = t3_5 + a3_5_6 * t6_6;
let a6_7_7 = a3_7_7 + a3_7_6 * a6_6_7;
let a6_7_8 = a3_7_8 + a3_7_6 * a6_6_8;
let t6_7 = t3_7 + a3_7_6 * t6_6;
let a6_8_7 = a3_8_7 + a3_8_6 * a6_6_7;
let a6_8_8 = a3_8_8 + a3_8_6 * a6_6_8;
let t6_8 = t3_8 + a3_8_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_1)), abs(t6_3)), abs(t6_6));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_1)) + abs(t6_3)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 10u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_3)), abs(t8_6)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_3)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 10u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_3)), abs(t7_6)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_3)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 10u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_3)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_3)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 10u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
{
let dead5 = semi & !(a3_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l3 & !dead5 & !(a3_5_5 > tol.tree_pivot * m5_5));
let l5 = l3 & !dead5;
let i5 = Scalar(1.0) / a3_5_5;
let n5 = -i5;
let a5_5_6 = a3_5_6 * n5;
let a5_5_7 = a3_5_7 * n5;
let a5_5_8 = a3_5_8 * n5;
let t5_5 = -t3_5 * i5;
let a5_0_6 = a3_0_6 + a3_0_5 * a5_5_6;
let a5_0_7 = a3_0_7 + a3_0_5 * a5_5_7;
let a5_0_8 = a3_0_8 + a3_0_5 * a5_5_8;
let t5_0 = t3_0 + a3_0_5 * t5_5;
let a5_1_6 = a3_1_6 + a3_1_5 * a5_5_6;
let a5_1_7 = a3_1_7 + a3_1_5 * a5_5_7;
let a5_1_8 = a3_1_8 + a3_1_5 * a5_5_8;
let t5_1 = t3_1 + a3_1_5 * t5_5;
let a5_2_6 = a3_2_6 + a3_2_5 * a5_5_6;
let a5_2_7 = a3_2_7 + a3_2_5 * a5_5_7;
let a5_2_8 = a3_2_8 + a3_2_5 * a5_5_8;
let t5_2 = t3_2 + a3_2_5 * t5_5;
let a5_3_6 = a3_3_6 + a3_3_5 * a5_5_6;
let a5_3_7 = a3_3_7 + a3_3_5 * a5_5_7;
let a5_3_8 = a3_3_8 + a3_3_5 * a5_5_8;
let t5_3 = t3_3 + a3_3_5 * t5_5;
let a5_4_6 = a3_4_6 + a3_4_5 * a5_5_6;
let a5_4_7 = a3_4_7 + a3_4_5 * a5_5_7;
let a5_4_8 = a3_4_8 + a3_4_5 * a5_5_8;
let t5_4 = t3_4 + a3_4_5 * t5_5;
let a5_6_6 = a3_6_6 + a3_6_5 * a5_5_6;
let a5_6_7 = a3_6_7 + a3_6_5 * a5_5_7;
let a5_6_8 = a3_6_8 + a3_6_5 * a5_5_8;
let t5_6 = t3_6 + a3_6_5 * t5_5;
let a5_7_6 = a3_7_6 + a3_7_5 * a5_5_6;
let a5_7_7 = a3_7_7 + a3_7_5 * a5_5_7;
let a5_7_8 = a3_7_8 + a3_7_5 * a5_5_8;
let t5_7 = t3_7 + a3_7_5 * t5_5;
let a5_8_6 = a3_8_6 + a3_8_5 * a5_5_6;
let a5_8_7 = a3_8_7 + a3_8_5 * a5_5_7;
let a5_8_8 = a3_8_8 + a3_8_5 * a5_5_8;
let t5_8 = t3_8 + a3_8_5 * t5_5;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), abs(t5_1)), abs(t5_3)), abs(t5_5));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + abs(t5_1)) + abs(t5_3)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 10u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let t8_8 = -t5_8 * i8;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let t8_7 = t5_7 + a5_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_3)), abs(t8_5)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_3)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 10u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let t7_8 = t5_8 + a5_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_3)), abs(t7_5)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_3)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 10u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_3)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_3)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 10u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let a6_6_7 = a5_6_7 * n6;
let a6_6_8 = a5_6_8 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let t6_8 = t5_8 + a5_8_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_1)), abs(t6_3)), abs(t6_5)), abs(t6_6));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_1)) + abs(t6_3)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 10u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_3)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_3)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 10u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_3)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_3)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 10u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_3)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_3)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 10u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
}
{
let dead4 = semi & !(a3_4_4 > tol.tree_singular * m4_4);
ok = ok & !(l3 & !dead4 & !(a3_4_4 > tol.tree_pivot * m4_4));
let l4 = l3 & !dead4;
let i4 = Scalar(1.0) / a3_4_4;
let n4 = -i4;
let a4_4_5 = a3_4_5 * n4;
let a4_4_6 = a3_4_6 * n4;
let a4_4_7 = a3_4_7 * n4;
let a4_4_8 = a3_4_8 * n4;
let t4_4 = -t3_4 * i4;
let a4_0_5 = a3_0_5 + a3_0_4 * a4_4_5;
let a4_0_6 = a3_0_6 + a3_0_4 * a4_4_6;
let a4_0_7 = a3_0_7 + a3_0_4 * a4_4_7;
let a4_0_8 = a3_0_8 + a3_0_4 * a4_4_8;
let t4_0 = t3_0 + a3_0_4 * t4_4;
let a4_1_5 = a3_1_5 + a3_1_4 * a4_4_5;
let a4_1_6 = a3_1_6 + a3_1_4 * a4_4_6;
let a4_1_7 = a3_1_7 + a3_1_4 * a4_4_7;
let a4_1_8 = a3_1_8 + a3_1_4 * a4_4_8;
let t4_1 = t3_1 + a3_1_4 * t4_4;
let a4_2_5 = a3_2_5 + a3_2_4 * a4_4_5;
let a4_2_6 = a3_2_6 + a3_2_4 * a4_4_6;
let a4_2_7 = a3_2_7 + a3_2_4 * a4_4_7;
let a4_2_8 = a3_2_8 + a3_2_4 * a4_4_8;
let t4_2 = t3_2 + a3_2_4 * t4_4;
let a4_3_5 = a3_3_5 + a3_3_4 * a4_4_5;
let a4_3_6 = a3_3_6 + a3_3_4 * a4_4_6;
let a4_3_7 = a3_3_7 + a3_3_4 * a4_4_7;
let a4_3_8 = a3_3_8 + a3_3_4 * a4_4_8;
let t4_3 = t3_3 + a3_3_4 * t4_4;
let a4_5_5 = a3_5_5 + a3_5_4 * a4_4_5;
let a4_5_6 = a3_5_6 + a3_5_4 * a4_4_6;
let a4_5_7 = a3_5_7 + a3_5_4 * a4_4_7;
let a4_5_8 = a3_5_8 + a3_5_4 * a4_4_8;
let t4_5 = t3_5 + a3_5_4 * t4_4;
let a4_6_5 = a3_6_5 + a3_6_4 * a4_4_5;
let a4_6_6 = a3_6_6 + a3_6_4 * a4_4_6;
let a4_6_7 = a3_6_7 + a3_6_4 * a4_4_7;
let a4_6_8 = a3_6_8 + a3_6_4 * a4_4_8;
let t4_6 = t3_6 + a3_6_4 * t4_4;
let a4_7_5 = a3_7_5 + a3_7_4 * a4_4_5;
let a4_7_6 = a3_7_6 + a3_7_4 * a4_4_6;
let a4_7_7 = a3_7_7 + a3_7_4 * a4_4_7;
let a4_7_8 = a3_7_8 + a3_7_4 * a4_4_8;
let t4_7 = t3_7 + a3_7_4 * t4_4;
let a4_8_5 = a3_8_5 + a3_8_4 * a4_4_5;
let a4_8_6 = a3_8_6 + a3_8_4 * a4_4_6;
let a4_8_7 = a3_8_7 + a3_8_4 * a4_4_7;
let a4_8_8 = a3_8_8 + a3_8_4 * a4_4_8;
let t4_8 = t3_8 + a3_8_4 * t4_4;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t4_0), b0)), abs(t4_1)), abs(t4_3)), abs(t4_4));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t4_0), b0)) + abs(t4_1)) + abs(t4_3)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 26u), l4 & (t4_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t4_1 >= -tol.screen * zm) & (t4_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t4_3 >= -tol.screen * zm) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t4_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t4_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a4_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l4 & !dead8 & !(a4_8_8 > tol.tree_pivot * m8_8));
let l8 = l4 & !dead8;
let i8 = Scalar(1.0) / a4_8_8;
let n8 = -i8;
let t8_8 = -t4_8 * i8;
let t8_0 = t4_0 + a4_0_8 * t8_8;
let t8_1 = t4_1 + a4_1_8 * t8_8;
let t8_2 = t4_2 + a4_2_8 * t8_8;
let t8_3 = t4_3 + a4_3_8 * t8_8;
let t8_4 = t4_4 + a4_4_8 * t8_8;
let t8_5 = t4_5 + a4_5_8 * t8_8;
let t8_6 = t4_6 + a4_6_8 * t8_8;
let t8_7 = t4_7 + a4_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_3)), abs(t8_4)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_3)) + abs(t8_4)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 26u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a4_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l4 & !dead7 & !(a4_7_7 > tol.tree_pivot * m7_7));
let l7 = l4 & !dead7;
let i7 = Scalar(1.0) / a4_7_7;
let n7 = -i7;
let a7_7_8 = a4_7_8 * n7;
let t7_7 = -t4_7 * i7;
let a7_0_8 = a4_0_8 + a4_0_7 * a7_7_8;
let t7_0 = t4_0 + a4_0_7 * t7_7;
let a7_1_8 = a4_1_8 + a4_1_7 * a7_7_8;
let t7_1 = t4_1 + a4_1_7 * t7_7;
let a7_2_8 = a4_2_8 + a4_2_7 * a7_7_8;
let t7_2 = t4_2 + a4_2_7 * t7_7;
let a7_3_8 = a4_3_8 + a4_3_7 * a7_7_8;
let t7_3 = t4_3 + a4_3_7 * t7_7;
let a7_4_8 = a4_4_8 + a4_4_7 * a7_7_8;
let t7_4 = t4_4 + a4_4_7 * t7_7;
let a7_5_8 = a4_5_8 + a4_5_7 * a7_7_8;
let t7_5 = t4_5 + a4_5_7 * t7_7;
let a7_6_8 = a4_6_8 + a4_6_7 * a7_7_8;
let t7_6 = t4_6 + a4_6_7 * t7_7;
let a7_8_8 = a4_8_8 + a4_8_7 * a7_7_8;
let t7_8 = t4_8 + a4_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_3)), abs(t7_4)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_3)) + abs(t7_4)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 26u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_3)), abs(t8_4)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_3)) + abs(t8_4)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 26u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let a6_6_7 = a4_6_7 * n6;
let a6_6_8 = a4_6_8 * n6;
let t6_6 = -t4_6 * i6;
let a6_0_7 = a4_0_7 + a4_0_6 * a6_6_7;
let a6_0_8 = a4_0_8 + a4_0_6 * a6_6_8;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let a6_1_7 = a4_1_7 + a4_1_6 * a6_6_7;
let a6_1_8 = a4_1_8 + a4_1_6 * a6_6_8;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let a6_2_7 = a4_2_7 + a4_2_6 * a6_6_7;
let a6_2_8 = a4_2_8 + a4_2_6 * a6_6_8;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let a6_3_7 = a4_3_7 + a4_3_6 * a6_6_7;
let a6_3_8 = a4_3_8 + a4_3_6 * a6_6_8;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let a6_4_7 = a4_4_7 + a4_4_6 * a6_6_7;
let a6_4_8 = a4_4_8 + a4_4_6 * a6_6_8;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let a6_5_7 = a4_5_7 + a4_5_6 * a6_6_7;
let a6_5_8 = a4_5_8 + a4_5_6 * a6_6_8;
let t6_5 = t4_5 + a4_5_6 * t6_6;
let a6_7_7 = a4_7_7 + a4_7_6 * a6_6_7;
let a6_7_8 = a4_7_8 + a4_7_6 * a6_6_8;
let t6_7 = t4_7 + a4_7_6 * t6_6;
let a6_8_7 = a4_8_7 + a4_8_6 * a6_6_7;
let a6_8_8 = a4_8_8 + a4_8_6 * a6_6_8;
let t6_8 = t4_8 + a4_8_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_1)), abs(t6_3)), abs(t6_4)), abs(t6_6));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_1)) + abs(t6_3)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 26u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_3)), abs(t8_4)), abs(t8_6)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_3)) + abs(t8_4)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 26u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_3)), abs(t7_4)), abs(t7_6)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_3)) + abs(t7_4)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 26u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_3)), abs(t8_4)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_3)) + abs(t8_4)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 26u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let a5_5_7 = a4_5_7 * n5;
let a5_5_8 = a4_5_8 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let a5_0_7 = a4_0_7 + a4_0_5 * a5_5_7;
let a5_0_8 = a4_0_8 + a4_0_5 * a5_5_8;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let a5_1_7 = a4_1_7 + a4_1_5 * a5_5_7;
let a5_1_8 = a4_1_8 + a4_1_5 * a5_5_8;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let a5_2_7 = a4_2_7 + a4_2_5 * a5_5_7;
let a5_2_8 = a4_2_8 + a4_2_5 * a5_5_8;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let a5_3_7 = a4_3_7 + a4_3_5 * a5_5_7;
let a5_3_8 = a4_3_8 + a4_3_5 * a5_5_8;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let a5_4_7 = a4_4_7 + a4_4_5 * a5_5_7;
let a5_4_8 = a4_4_8 + a4_4_5 * a5_5_8;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let a5_6_7 = a4_6_7 + a4_6_5 * a5_5_7;
let a5_6_8 = a4_6_8 + a4_6_5 * a5_5_8;
let t5_6 = t4_6 + a4_6_5 * t5_5;
let a5_7_6 = a4_7_6 + a4_7_5 * a5_5_6;
let a5_7_7 = a4_7_7 + a4_7_5 * a5_5_7;
let a5_7_8 = a4_7_8 + a4_7_5 * a5_5_8;
let t5_7 = t4_7 + a4_7_5 * t5_5;
let a5_8_6 = a4_8_6 + a4_8_5 * a5_5_6;
let a5_8_7 = a4_8_7 + a4_8_5 * a5_5_7;
let a5_8_8 = a4_8_8 + a4_8_5 * a5_5_8;
let t5_8 = t4_8 + a4_8_5 * t5_5;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), abs(t5_1)), abs(t5_3)), abs(t5_4)), abs(t5_5));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + abs(t5_1)) + abs(t5_3)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 26u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let t8_8 = -t5_8 * i8;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let t8_7 = t5_7 + a5_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 26u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let t7_8 = t5_8 + a5_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_3)), abs(t7_4)), abs(t7_5)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_3)) + abs(t7_4)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 26u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 26u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let a6_6_7 = a5_6_7 * n6;
let a6_6_8 = a5_6_8 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let t6_8 = t5_8 + a5_8_6 * t6_6;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_1)), abs(t6_3)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_1)) + abs(t6_3)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 26u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 26u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_3)), abs(t7_4)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_3)) + abs(t7_4)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 26u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 26u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
}
}
}
{
let dead2 = semi & !(a1_2_2 > tol.tree_singular * m2_2);
ok = ok & !(l1 & !dead2 & !(a1_2_2 > tol.tree_pivot * m2_2));
let l2 = l1 & !dead2;
let i2 = Scalar(1.0) / a1_2_2;
let n2 = -i2;
let a2_2_3 = a1_2_3 * n2;
let a2_2_4 = a1_2_4 * n2;
let a2_2_5 = a1_2_5 * n2;
let a2_2_6 = a1_2_6 * n2;
let a2_2_7 = a1_2_7 * n2;
let a2_2_8 = a1_2_8 * n2;
let t2_2 = -t1_2 * i2;
let a2_0_3 = a1_0_3 + a1_0_2 * a2_2_3;
let a2_0_4 = a1_0_4 + a1_0_2 * a2_2_4;
let a2_0_5 = a1_0_5 + a1_0_2 * a2_2_5;
let a2_0_6 = a1_0_6 + a1_0_2 * a2_2_6;
let a2_0_7 = a1_0_7 + a1_0_2 * a2_2_7;
let a2_0_8 = a1_0_8 + a1_0_2 * a2_2_8;
let t2_0 = t1_0 + a1_0_2 * t2_2;
let a2_1_3 = a1_1_3 + a1_1_2 * a2_2_3;
let a2_1_4 = a1_1_4 + a1_1_2 * a2_2_4;
let a2_1_5 = a1_1_5 + a1_1_2 * a2_2_5;
let a2_1_6 = a1_1_6 + a1_1_2 * a2_2_6;
let a2_1_7 = a1_1_7 + a1_1_2 * a2_2_7;
let a2_1_8 = a1_1_8 + a1_1_2 * a2_2_8;
let t2_1 = t1_1 + a1_1_2 * t2_2;
let a2_3_3 = a1_3_3 + a1_3_2 * a2_2_3;
let a2_3_4 = a1_3_4 + a1_3_2 * a2_2_4;
let a2_3_5 = a1_3_5 + a1_3_2 * a2_2_5;
let a2_3_6 = a1_3_6 + a1_3_2 * a2_2_6;
let a2_3_7 = a1_3_7 + a1_3_2 * a2_2_7;
let a2_3_8 = a1_3_8 + a1_3_2 * a2_2_8;
let t2_3 = t1_3 + a1_3_2 * t2_2;
let a2_4_3 = a1_4_3 + a1_4_2 * a2_2_3;
let a2_4_4 = a1_4_4 + a1_4_2 * a2_2_4;
let a2_4_5 = a1_4_5 + a1_4_2 * a2_2_5;
let a2_4_6 = a1_4_6 + a1_4_2 * a2_2_6;
let a2_4_7 = a1_4_7 + a1_4_2 * a2_2_7;
let a2_4_8 = a1_4_8 + a1_4_2 * a2_2_8;
let t2_4 = t1_4 + a1_4_2 * t2_2;
let a2_5_3 = a1_5_3 + a1_5_2 * a2_2_3;
let a2_5_4 = a1_5_4 + a1_5_2 * a2_2_4;
let a2_5_5 = a1_5_5 + a1_5_2 * a2_2_5;
let a2_5_6 = a1_5_6 + a1_5_2 * a2_2_6;
let a2_5_7 = a1_5_7 + a1_5_2 * a2_2_7;
let a2_5_8 = a1_5_8 + a1_5_2 * a2_2_8;
let t2_5 = t1_5 + a1_5_2 * t2_2;
let a2_6_3 = a1_6_3 + a1_6_2 * a2_2_3;
let a2_6_4 = a1_6_4 + a1_6_2 * a2_2_4;
let a2_6_5 = a1_6_5 + a1_6_2 * a2_2_5;
let a2_6_6 = a1_6_6 + a1_6_2 * a2_2_6;
let a2_6_7 = a1_6_7 + a1_6_2 * a2_2_7;
let a2_6_8 = a1_6_8 + a1_6_2 * a2_2_8;
let t2_6 = t1_6 + a1_6_2 * t2_2;
let a2_7_3 = a1_7_3 + a1_7_2 * a2_2_3;
let a2_7_4 = a1_7_4 + a1_7_2 * a2_2_4;
let a2_7_5 = a1_7_5 + a1_7_2 * a2_2_5;
let a2_7_6 = a1_7_6 + a1_7_2 * a2_2_6;
let a2_7_7 = a1_7_7 + a1_7_2 * a2_2_7;
let a2_7_8 = a1_7_8 + a1_7_2 * a2_2_8;
let t2_7 = t1_7 + a1_7_2 * t2_2;
let a2_8_3 = a1_8_3 + a1_8_2 * a2_2_3;
let a2_8_4 = a1_8_4 + a1_8_2 * a2_2_4;
let a2_8_5 = a1_8_5 + a1_8_2 * a2_2_5;
let a2_8_6 = a1_8_6 + a1_8_2 * a2_2_6;
let a2_8_7 = a1_8_7 + a1_8_2 * a2_2_7;
let a2_8_8 = a1_8_8 + a1_8_2 * a2_2_8;
let t2_8 = t1_8 + a1_8_2 * t2_2;
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t2_0), b0)), abs(t2_1)), abs(t2_2));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(t2_0), b0)) + abs(t2_1)) + abs(t2_2));
c0 = c0 | select(0u, 1u << (pre | 6u), l2 & (t2_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t2_1 >= -tol.screen * zm) & (t2_2 >= -tol.screen * zm) & (t2_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t2_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t2_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t2_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t2_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t2_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a2_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l2 & !dead8 & !(a2_8_8 > tol.tree_pivot * m8_8));
let l8 = l2 & !dead8;
let i8 = Scalar(1.0) / a2_8_8;
let n8 = -i8;
let t8_8 = -t2_8 * i8;
let t8_0 = t2_0 + a2_0_8 * t8_8;
let t8_1 = t2_1 + a2_1_8 * t8_8;
let t8_2 = t2_2 + a2_2_8 * t8_8;
let t8_3 = t2_3 + a2_3_8 * t8_8;
let t8_4 = t2_4 + a2_4_8 * t8_8;
let t8_5 = t2_5 + a2_5_8 * t8_8;
let t8_6 = t2_6 + a2_6_8 * t8_8;
let t8_7 = t2_7 + a2_7_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 6u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a2_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l2 & !dead7 & !(a2_7_7 > tol.tree_pivot * m7_7));
let l7 = l2 & !dead7;
let i7 = Scalar(1.0) / a2_7_7;
let n7 = -i7;
let a7_7_8 = a2_7_8 * n7;
let t7_7 = -t2_7 * i7;
let a7_0_8 = a2_0_8 + a2_0_7 * a7_7_8;
let t7_0 = t2_0 + a2_0_7 * t7_7;
let a7_1_8 = a2_1_8 + a2_1_7 * a7_7_8;
let t7_1 = t2_1 + a2_1_7 * t7_7;
let a7_2_8 = a2_2_8 + a2_2_7 * a7_7_8;
let t7_2 = t2_2 + a2_2_7 * t7_7;
let a7_3_8 = a2_3_8 + a2_3_7 * a7_7_8;
let t7_3 = t2_3 + a2_3_7 * t7_7;
let a7_4_8 = a2_4_8 + a2_4_7 * a7_7_8;
let t7_4 = t2_4 + a2_4_7 * t7_7;
let a7_5_8 = a2_5_8 + a2_5_7 * a7_7_8;
let t7_5 = t2_5 + a2_5_7 * t7_7;
let a7_6_8 = a2_6_8 + a2_6_7 * a7_7_8;
let t7_6 = t2_6 + a2_6_7 * t7_7;
let a7_8_8 = a2_8_8 + a2_8_7 * a7_7_8;
let t7_8 = t2_8 + a2_8_7 * t7_7;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_2)), abs(t7_7));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_2)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 6u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_7)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 6u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a2_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l2 & !dead6 & !(a2_6_6 > tol.tree_pivot * m6_6));
let l6 = l2 & !dead6;
let i6 = Scalar(1.0) / a2_6_6;
let n6 = -i6;
let a6_6_7 = a2_6_7 * n6;
let a6_6_8 = a2_6_8 * n6;
let t6_6 = -t2_6 * i6;
let a6_0_7 = a2_0_7 + a2_0_6 * a6_6_7;
let a6_0_8 = a2_0_8 + a2_0_6 * a6_6_8;
let t6_0 = t2_0 + a2_0_6 * t6_6;
let a6_1_7 = a2_1_7 + a2_1_6 * a6_6_7;
let a6_1_8 = a2_1_8 + a2_1_6 * a6_6_8;
let t6_1 = t2_1 + a2_1_6 * t6_6;
let a6_2_7 = a2_2_7 + a2_2_6 * a6_6_7;
let a6_2_8 = a2_2_8 + a2_2_6 * a6_6_8;
let t6_2 = t2_2 + a2_2_6 * t6_6;
let a6_3_7 = a2_3_7 + a2_3_6 * a6_6_7;
let a6_3_8 = a2_3_8 + a2_3_6 * a6_6_8;
let t6_3 = t2_3 + a2_3_6 * t6_6;
let a6_4_7 = a2_4_7 + a2_4_6 * a6_6_7;
let a6_4_8 = a2_4_8 + a2_4_6 * a6_6_8;
let t6_4 = t2_4 + a2_4_6 * t6_6;
let a6_5_7 = a2_5_7 + a2_5_6 * a6_6_7;
let a6_5_8 = a2_5_8 + a2_5_6 * a6_6_8;
let t6_5 = t2_5 + a2_5_6 * t6_6;
let a6_7_7 = a2_7_7 + a2_7_6 * a6_6_7;
let a6_7_8 = a2_7_8 + a2_7_6 * a6_6_8;
let t6_7 = t2_7 + a2_7_6 * t6_6;
let a6_8_7 = a2_8_7 + a2_8_6 * a6_6_7;
let a6_8_8 = a2_8_8 + a2_8_6 * a6_6_8;
let t6_8 = t2_8 + a2_8_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_1)), abs(t6_2)), abs(t6_6));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_1)) + abs(t6_2)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 6u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_6)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 6u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_2)), abs(t7_6)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_2)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 6u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 6u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
{
let dead5 = semi & !(a2_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l2 & !dead5 & !(a2_5_5 > tol.tree_pivot * m5_5));
let l5 = l2 & !dead5;
let i5 = Scalar(1.0) / a2_5_5;
let n5 = -i5;
let a5_5_6 = a2_5_6 * n5;
let a5_5_7 = a2_5_7 * n5;
let a5_5_8 = a2_5_8 * n5;
let t5_5 = -t2_5 * i5;
let a5_0_6 = a2_0_6 + a2_0_5 * a5_5_6;
let a5_0_7 = a2_0_7 + a2_0_5 * a5_5_7;
let a5_0_8 = a2_0_8 + a2_0_5 * a5_5_8;
let t5_0 = t2_0 + a2_0_5 * t5_5;
let a5_1_6 = a2_1_6 + a2_1_5 * a5_5_6;
let a5_1_7 = a2_1_7 + a2_1_5 * a5_5_7;
let a5_1_8 = a2_1_8 + a2_1_5 * a5_5_8;
let t5_1 = t2_1 + a2_1_5 * t5_5;
let a5_2_6 = a2_2_6 + a2_2_5 * a5_5_6;
let a5_2_7 = a2_2_7 + a2_2_5 * a5_5_7;
let a5_2_8 = a2_2_8 + a2_2_5 * a5_5_8;
let t5_2 = t2_2 + a2_2_5 * t5_5;
let a5_3_6 = a2_3_6 + a2_3_5 * a5_5_6;
let a5_3_7 = a2_3_7 + a2_3_5 * a5_5_7;
let a5_3_8 = a2_3_8 + a2_3_5 * a5_5_8;
let t5_3 = t2_3 + a2_3_5 * t5_5;
let a5_4_6 = a2_4_6 + a2_4_5 * a5_5_6;
let a5_4_7 = a2_4_7 + a2_4_5 * a5_5_7;
let a5_4_8 = a2_4_8 + a2_4_5 * a5_5_8;
let t5_4 = t2_4 + a2_4_5 * t5_5;
let a5_6_6 = a2_6_6 + a2_6_5 * a5_5_6;
let a5_6_7 = a2_6_7 + a2_6_5 * a5_5_7;
let a5_6_8 = a2_6_8 + a2_6_5 * a5_5_8;
let t5_6 = t2_6 + a2_6_5 * t5_5;
let a5_7_6 = a2_7_6 + a2_7_5 * a5_5_6;
let a5_7_7 = a2_7_7 + a2_7_5 * a5_5_7;
let a5_7_8 = a2_7_8 + a2_7_5 * a5_5_8;
let t5_7 = t2_7 + a2_7_5 * t5_5;
let a5_8_6 = a2_8_6 + a2_8_5 * a5_5_6;
let a5_8_7 = a2_8_7 + a2_8_5 * a5_5_7;
let a5_8_8 = a2_8_8 + a2_8_5 * a5_5_8;
let t5_8 = t2_8 + a2_8_5 * t5_5;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), abs(t5_1)), abs(t5_2)), abs(t5_5));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + abs(t5_1)) + abs(t5_2)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 6u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let t8_8 = -t5_8 * i8;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let t8_7 = t5_7 + a5_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_5)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 6u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let t7_8 = t5_8 + a5_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_2)), abs(t7_5)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_2)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 6u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 6u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let a6_6_7 = a5_6_7 * n6;
let a6_6_8 = a5_6_8 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let t6_8 = t5_8 + a5_8_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_1)), abs(t6_2)), abs(t6_5)), abs(t6_6));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_1)) + abs(t6_2)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 6u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 6u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_2)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_2)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 6u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 6u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
}
{
let dead4 = semi & !(a2_4_4 > tol.tree_singular * m4_4);
ok = ok & !(l2 & !dead4 & !(a2_4_4 > tol.tree_pivot * m4_4));
let l4 = l2 & !dead4;
let i4 = Scalar(1.0) / a2_4_4;
let n4 = -i4;
let a4_4_5 = a2_4_5 * n4;
let a4_4_6 = a2_4_6 * n4;
let a4_4_7 = a2_4_7 * n4;
let a4_4_8 = a2_4_8 * n4;
let t4_4 = -t2_4 * i4;
let a4_0_5 = a2_0_5 + a2_0_4 * a4_4_5;
let a4_0_6 = a2_0_6 + a2_0_4 * a4_4_6;
let a4_0_7 = a2_0_7 + a2_0_4 * a4_4_7;
let a4_0_8 = a2_0_8 + a2_0_4 * a4_4_8;
let t4_0 = t2_0 + a2_0_4 * t4_4;
let a4_1_5 = a2_1_5 + a2_1_4 * a4_4_5;
let a4_1_6 = a2_1_6 + a2_1_4 * a4_4_6;
let a4_1_7 = a2_1_7 + a2_1_4 * a4_4_7;
let a4_1_8 = a2_1_8 + a2_1_4 * a4_4_8;
let t4_1 = t2_1 + a2_1_4 * t4_4;
let a4_2_5 = a2_2_5 + a2_2_4 * a4_4_5;
let a4_2_6 = a2_2_6 + a2_2_4 * a4_4_6;
let a4_2_7 = a2_2_7 + a2_2_4 * a4_4_7;
let a4_2_8 = a2_2_8 + a2_2_4 * a4_4_8;
let t4_2 = t2_2 + a2_2_4 * t4_4;
let a4_3_5 = a2_3_5 + a2_3_4 * a4_4_5;
let a4_3_6 = a2_3_6 + a2_3_4 * a4_4_6;
let a4_3_7 = a2_3_7 + a2_3_4 * a4_4_7;
let a4_3_8 = a2_3_8 + a2_3_4 * a4_4_8;
let t4_3 = t2_3 + a2_3_4 * t4_4;
let a4_5_5 = a2_5_5 + a2_5_4 * a4_4_5;
let a4_5_6 = a2_5_6 + a2_5_4 * a4_4_6;
let a4_5_7 = a2_5_7 + a2_5_4 * a4_4_7;
let a4_5_8 = a2_5_8 + a2_5_4 * a4_4_8;
let t4_5 = t2_5 + a2_5_4 * t4_4;
let a4_6_5 = a2_6_5 + a2_6_4 * a4_4_5;
let a4_6_6 = a2_6_6 + a2_6_4 * a4_4_6;
let a4_6_7 = a2_6_7 + a2_6_4 * a4_4_7;
let a4_6_8 = a2_6_8 + a2_6_4 * a4_4_8;
let t4_6 = t2_6 + a2_6_4 * t4_4;
let a4_7_5 = a2_7_5 + a2_7_4 * a4_4_5;
let a4_7_6 = a2_7_6 + a2_7_4 * a4_4_6;
let a4_7_7 = a2_7_7 + a2_7_4 * a4_4_7;
let a4_7_8 = a2_7_8 + a2_7_4 * a4_4_8;
let t4_7 = t2_7 + a2_7_4 * t4_4;
let a4_8_5 = a2_8_5 + a2_8_4 * a4_4_5;
let a4_8_6 = a2_8_6 + a2_8_4 * a4_4_6;
let a4_8_7 = a2_8_7 + a2_8_4 * a4_4_7;
let a4_8_8 = a2_8_8 + a2_8_4 * a4_4_8;
let t4_8 = t2_8 + a2_8_4 * t4_4;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t4_0), b0)), abs(t4_1)), abs(t4_2)), abs(t4_4));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t4_0), b0)) + abs(t4_1)) + abs(t4_2)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 22u), l4 & (t4_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t4_1 >= -tol.screen * zm) & (t4_2 >= -tol.screen * zm) & (t4_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t4_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t4_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a4_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l4 & !dead8 & !(a4_8_8 > tol.tree_pivot * m8_8));
let l8 = l4 & !dead8;
let i8 = Scalar(1.0) / a4_8_8;
let n8 = -i8;
let t8_8 = -t4_8 * i8;
let t8_0 = t4_0 + a4_0_8 * t8_8;
let t8_1 = t4_1 + a4_1_8 * t8_8;
let t8_2 = t4_2 + a4_2_8 * t8_8;
let t8_3 = t4_3 + a4_3_8 * t8_8;
let t8_4 = t4_4 + a4_4_8 * t8_8;
let t8_5 = t4_5 + a4_5_8 * t8_8;
let t8_6 = t4_6 + a4_6_8 * t8_8;
let t8_7 = t4_7 + a4_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_4)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_4)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 22u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a4_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l4 & !dead7 & !(a4_7_7 > tol.tree_pivot * m7_7));
let l7 = l4 & !dead7;
let i7 = Scalar(1.0) / a4_7_7;
let n7 = -i7;
let a7_7_8 = a4_7_8 * n7;
let t7_7 = -t4_7 * i7;
let a7_0_8 = a4_0_8 + a4_0_7 * a7_7_8;
let t7_0 = t4_0 + a4_0_7 * t7_7;
let a7_1_8 = a4_1_8 + a4_1_7 * a7_7_8;
let t7_1 = t4_1 + a4_1_7 * t7_7;
let a7_2_8 = a4_2_8 + a4_2_7 * a7_7_8;
let t7_2 = t4_2 + a4_2_7 * t7_7;
let a7_3_8 = a4_3_8 + a4_3_7 * a7_7_8;
let t7_3 = t4_3 + a4_3_7 * t7_7;
let a7_4_8 = a4_4_8 + a4_4_7 * a7_7_8;
let t7_4 = t4_4 + a4_4_7 * t7_7;
let a7_5_8 = a4_5_8 + a4_5_7 * a7_7_8;
let t7_5 = t4_5 + a4_5_7 * t7_7;
let a7_6_8 = a4_6_8 + a4_6_7 * a7_7_8;
let t7_6 = t4_6 + a4_6_7 * t7_7;
let a7_8_8 = a4_8_8 + a4_8_7 * a7_7_8;
let t7_8 = t4_8 + a4_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_2)), abs(t7_4)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_2)) + abs(t7_4)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 22u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_4)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_4)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 22u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let a6_6_7 = a4_6_7 * n6;
let a6_6_8 = a4_6_8 * n6;
let t6_6 = -t4_6 * i6;
let a6_0_7 = a4_0_7 + a4_0_6 * a6_6_7;
let a6_0_8 = a4_0_8 + a4_0_6 * a6_6_8;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let a6_1_7 = a4_1_7 + a4_1_6 * a6_6_7;
let a6_1_8 = a4_1_8 + a4_1_6 * a6_6_8;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let a6_2_7 = a4_2_7 + a4_2_6 * a6_6_7;
let a6_2_8 = a4_2_8 + a4_2_6 * a6_6_8;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let a6_3_7 = a4_3_7 + a4_3_6 * a6_6_7;
let a6_3_8 = a4_3_8 + a4_3_6 * a6_6_8;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let a6_4_7 = a4_4_7 + a4_4_6 * a6_6_7;
let a6_4_8 = a4_4_8 + a4_4_6 * a6_6_8;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let a6_5_7 = a4_5_7 + a4_5_6 * a6_6_7;
let a6_5_8 = a4_5_8 + a4_5_6 * a6_6_8;
let t6_5 = t4_5 + a4_5_6 * t6_6;
let a6_7_7 = a4_7_7 + a4_7_6 * a6_6_7;
let a6_7_8 = a4_7_8 + a4_7_6 * a6_6_8;
let t6_7 = t4_7 + a4_7_6 * t6_6;
let a6_8_7 = a4_8_7 + a4_8_6 * a6_6_7;
let a6_8_8 = a4_8_8 + a4_8_6 * a6_6_8;
let t6_8 = t4_8 + a4_8_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_1)), abs(t6_2)), abs(t6_4)), abs(t6_6));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_1)) + abs(t6_2)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 22u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_4)), abs(t8_6)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_4)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 22u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_2)), abs(t7_4)), abs(t7_6)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_2)) + abs(t7_4)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 22u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_4)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_4)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 22u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let a5_5_7 = a4_5_7 * n5;
let a5_5_8 = a4_5_8 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let a5_0_7 = a4_0_7 + a4_0_5 * a5_5_7;
let a5_0_8 = a4_0_8 + a4_0_5 * a5_5_8;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let a5_1_7 = a4_1_7 + a4_1_5 * a5_5_7;
let a5_1_8 = a4_1_8 + a4_1_5 * a5_5_8;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let a5_2_7 = a4_2_7 + a4_2_5 * a5_5_7;
let a5_2_8 = a4_2_8 + a4_2_5 * a5_5_8;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let a5_3_7 = a4_3_7 + a4_3_5 * a5_5_7;
let a5_3_8 = a4_3_8 + a4_3_5 * a5_5_8;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let a5_4_7 = a4_4_7 + a4_4_5 * a5_5_7;
let a5_4_8 = a4_4_8 + a4_4_5 * a5_5_8;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let a5_6_7 = a4_6_7 + a4_6_5 * a5_5_7;
let a5_6_8 = a4_6_8 + a4_6_5 * a5_5_8;
let t5_6 = t4_6 + a4_6_5 * t5_5;
let a5_7_6 = a4_7_6 + a4_7_5 * a5_5_6;
let a5_7_7 = a4_7_7 + a4_7_5 * a5_5_7;
let a5_7_8 = a4_7_8 + a4_7_5 * a5_5_8;
let t5_7 = t4_7 + a4_7_5 * t5_5;
let a5_8_6 = a4_8_6 + a4_8_5 * a5_5_6;
let a5_8_7 = a4_8_7 + a4_8_5 * a5_5_7;
let a5_8_8 = a4_8_8 + a4_8_5 * a5_5_8;
let t5_8 = t4_8 + a4_8_5 * t5_5;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), abs(t5_1)), abs(t5_2)), abs(t5_4)), abs(t5_5));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + abs(t5_1)) + abs(t5_2)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 22u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let t8_8 = -t5_8 * i8;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let t8_7 = t5_7 + a5_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_4)), abs(t8_5)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_4)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 22u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let t7_8 = t5_8 + a5_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_2)), abs(t7_4)), abs(t7_5)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_2)) + abs(t7_4)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 22u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_4)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_4)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 22u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let a6_6_7 = a5_6_7 * n6;
let a6_6_8 = a5_6_8 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let t6_8 = t5_8 + a5_8_6 * t6_6;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_1)), abs(t6_2)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_1)) + abs(t6_2)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 22u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 22u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_2)), abs(t7_4)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_2)) + abs(t7_4)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 22u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 22u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
}
}
{
let dead3 = semi & !(a2_3_3 > tol.tree_singular * m3_3);
ok = ok & !(l2 & !dead3 & !(a2_3_3 > tol.tree_pivot * m3_3));
let l3 = l2 & !dead3;
let i3 = Scalar(1.0) / a2_3_3;
let n3 = -i3;
let a3_3_4 = a2_3_4 * n3;
let a3_3_5 = a2_3_5 * n3;
let a3_3_6 = a2_3_6 * n3;
let a3_3_7 = a2_3_7 * n3;
let a3_3_8 = a2_3_8 * n3;
let t3_3 = -t2_3 * i3;
let a3_0_4 = a2_0_4 + a2_0_3 * a3_3_4;
let a3_0_5 = a2_0_5 + a2_0_3 * a3_3_5;
let a3_0_6 = a2_0_6 + a2_0_3 * a3_3_6;
let a3_0_7 = a2_0_7 + a2_0_3 * a3_3_7;
let a3_0_8 = a2_0_8 + a2_0_3 * a3_3_8;
let t3_0 = t2_0 + a2_0_3 * t3_3;
let a3_1_4 = a2_1_4 + a2_1_3 * a3_3_4;
let a3_1_5 = a2_1_5 + a2_1_3 * a3_3_5;
let a3_1_6 = a2_1_6 + a2_1_3 * a3_3_6;
let a3_1_7 = a2_1_7 + a2_1_3 * a3_3_7;
let a3_1_8 = a2_1_8 + a2_1_3 * a3_3_8;
let t3_1 = t2_1 + a2_1_3 * t3_3;
let a3_2_4 = a2_2_4 + a2_2_3 * a3_3_4;
let a3_2_5 = a2_2_5 + a2_2_3 * a3_3_5;
let a3_2_6 = a2_2_6 + a2_2_3 * a3_3_6;
let a3_2_7 = a2_2_7 + a2_2_3 * a3_3_7;
let a3_2_8 = a2_2_8 + a2_2_3 * a3_3_8;
let t3_2 = t2_2 + a2_2_3 * t3_3;
let a3_4_4 = a2_4_4 + a2_4_3 * a3_3_4;
let a3_4_5 = a2_4_5 + a2_4_3 * a3_3_5;
let a3_4_6 = a2_4_6 + a2_4_3 * a3_3_6;
let a3_4_7 = a2_4_7 + a2_4_3 * a3_3_7;
let a3_4_8 = a2_4_8 + a2_4_3 * a3_3_8;
let t3_4 = t2_4 + a2_4_3 * t3_3;
let a3_5_4 = a2_5_4 + a2_5_3 * a3_3_4;
let a3_5_5 = a2_5_5 + a2_5_3 * a3_3_5;
let a3_5_6 = a2_5_6 + a2_5_3 * a3_3_6;
let a3_5_7 = a2_5_7 + a2_5_3 * a3_3_7;
let a3_5_8 = a2_5_8 + a2_5_3 * a3_3_8;
let t3_5 = t2_5 + a2_5_3 * t3_3;
let a3_6_4 = a2_6_4 + a2_6_3 * a3_3_4;
let a3_6_5 = a2_6_5 + a2_6_3 * a3_3_5;
let a3_6_6 = a2_6_6 + a2_6_3 * a3_3_6;
let a3_6_7 = a2_6_7 + a2_6_3 * a3_3_7;
let a3_6_8 = a2_6_8 + a2_6_3 * a3_3_8;
let t3_6 = t2_6 + a2_6_3 * t3_3;
let a3_7_4 = a2_7_4 + a2_7_3 * a3_3_4;
let a3_7_5 = a2_7_5 + a2_7_3 * a3_3_5;
let a3_7_6 = a2_7_6 + a2_7_3 * a3_3_6;
let a3_7_7 = a2_7_7 + a2_7_3 * a3_3_7;
let a3_7_8 = a2_7_8 + a2_7_3 * a3_3_8;
let t3_7 = t2_7 + a2_7_3 * t3_3;
let a3_8_4 = a2_8_4 + a2_8_3 * a3_3_4;
let a3_8_5 = a2_8_5 + a2_8_3 * a3_3_5;
let a3_8_6 = a2_8_6 + a2_8_3 * a3_3_6;
let a3_8_7 = a2_8_7 + a2_8_3 * a3_3_7;
let a3_8_8 = a2_8_8 + a2_8_3 * a3_3_8;
let t3_8 = t2_8 + a2_8_3 * t3_3;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t3_0), b0)), abs(t3_1)), abs(t3_2)), abs(t3_3));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t3_0), b0)) + abs(t3_1)) + abs(t3_2)) + abs(t3_3));
c0 = c0 | select(0u, 1u << (pre | 14u), l3 & (t3_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t3_1 >= -tol.screen * zm) & (t3_2 >= -tol.screen * zm) & (t3_3 >= -tol.screen * zm) & (t3_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t3_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t3_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t3_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t3_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a3_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l3 & !dead8 & !(a3_8_8 > tol.tree_pivot * m8_8));
let l8 = l3 & !dead8;
let i8 = Scalar(1.0) / a3_8_8;
let n8 = -i8;
let t8_8 = -t3_8 * i8;
let t8_0 = t3_0 + a3_0_8 * t8_8;
let t8_1 = t3_1 + a3_1_8 * t8_8;
let t8_2 = t3_2 + a3_2_8 * t8_8;
let t8_3 = t3_3 + a3_3_8 * t8_8;
let t8_4 = t3_4 + a3_4_8 * t8_8;
let t8_5 = t3_5 + a3_5_8 * t8_8;
let t8_6 = t3_6 + a3_6_8 * t8_8;
let t8_7 = t3_7 + a3_7_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_3)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_3)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 14u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a3_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l3 & !dead7 & !(a3_7_7 > tol.tree_pivot * m7_7));
let l7 = l3 & !dead7;
let i7 = Scalar(1.0) / a3_7_7;
let n7 = -i7;
let a7_7_8 = a3_7_8 * n7;
let t7_7 = -t3_7 * i7;
let a7_0_8 = a3_0_8 + a3_0_7 * a7_7_8;
let t7_0 = t3_0 + a3_0_7 * t7_7;
let a7_1_8 = a3_1_8 + a3_1_7 * a7_7_8;
let t7_1 = t3_1 + a3_1_7 * t7_7;
let a7_2_8 = a3_2_8 + a3_2_7 * a7_7_8;
let t7_2 = t3_2 + a3_2_7 * t7_7;
let a7_3_8 = a3_3_8 + a3_3_7 * a7_7_8;
let t7_3 = t3_3 + a3_3_7 * t7_7;
let a7_4_8 = a3_4_8 + a3_4_7 * a7_7_8;
let t7_4 = t3_4 + a3_4_7 * t7_7;
let a7_5_8 = a3_5_8 + a3_5_7 * a7_7_8;
let t7_5 = t3_5 + a3_5_7 * t7_7;
let a7_6_8 = a3_6_8 + a3_6_7 * a7_7_8;
let t7_6 = t3_6 + a3_6_7 * t7_7;
let a7_8_8 = a3_8_8 + a3_8_7 * a7_7_8;
let t7_8 = t3_8 + a3_8_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_2)), abs(t7_3)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_2)) + abs(t7_3)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 14u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_3)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_3)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 14u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a3_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l3 & !dead6 & !(a3_6_6 > tol.tree_pivot * m6_6));
let l6 = l3 & !dead6;
let i6 = Scalar(1.0) / a3_6_6;
let n6 = -i6;
let a6_6_7 = a3_6_7 * n6;
let a6_6_8 = a3_6_8 * n6;
let t6_6 = -t3_6 * i6;
let a6_0_7 = a3_0_7 + a3_0_6 * a6_6_7;
let a6_0_8 = a3_0_8 + a3_0_6 * a6_6_8;
let t6_0 = t3_0 + a3_0_6 * t6_6;
let a6_1_7 = a3_1_7 + a3_1_6 * a6_6_7;
let a6_1_8 = a3_1_8 + a3_1_6 * a6_6_8;
let t6_1 = t3_1 + a3_1_6 * t6_6;
let a6_2_7 = a3_2_7 + a3_2_6 * a6_6_7;
let a6_2_8 = a3_2_8 + a3_2_6 * a6_6_8;
let t6_2 = t3_2 + a3_2_6 * t6_6;
let a6_3_7 = a3_3_7 + a3_3_6 * a6_6_7;
let a6_3_8 = a3_3_8 + a3_3_6 * a6_6_8;
let t6_3 = t3_3 + a3_3_6 * t6_6;
let a6_4_7 = a3_4_7 + a3_4_6 * a6_6_7;
let a6_4_8 = a3_4_8 + a3_4_6 * a6_6_8;
let t6_4 = t3_4 + a3_4_6 * t6_6;
let a6_5_7 = a3_5_7 + a3_5_6 * a6_6_7;
let a6_5_8 = a3_5_8 + a3_5_6 * a6_6_8;
let t6_5 = t3_5 + a3_5_6 * t6_6;
let a6_7_7 = a3_7_7 + a3_7_6 * a6_6_7;
let a6_7_8 = a3_7_8 + a3_7_6 * a6_6_8;
let t6_7 = t3_7 + a3_7_6 * t6_6;
let a6_8_7 = a3_8_7 + a3_8_6 * a6_6_7;
let a6_8_8 = a3_8_8 + a3_8_6 * a6_6_8;
let t6_8 = t3_8 + a3_8_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_1)), abs(t6_2)), abs(t6_3)), abs(t6_6));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_1)) + abs(t6_2)) + abs(t6_3)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 14u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_3)), abs(t8_6)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_3)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 14u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_2)), abs(t7_3)), abs(t7_6)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_2)) + abs(t7_3)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 14u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_3)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_3)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 14u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
{
let dead5 = semi & !(a3_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l3 & !dead5 & !(a3_5_5 > tol.tree_pivot * m5_5));
let l5 = l3 & !dead5;
let i5 = Scalar(1.0) / a3_5_5;
let n5 = -i5;
let a5_5_6 = a3_5_6 * n5;
let a5_5_7 = a3_5_7 * n5;
let a5_5_8 = a3_5_8 * n5;
let t5_5 = -t3_5 * i5;
let a5_0_6 = a3_0_6 + a3_0_5 * a5_5_6;
let a5_0_7 = a3_0_7 + a3_0_5 * a5_5_7;
let a5_0_8 = a3_0_8 + a3_0_5 * a5_5_8;
let t5_0 = t3_0 + a3_0_5 * t5_5;
let a5_1_6 = a3_1_6 + a3_1_5 * a5_5_6;
let a5_1_7 = a3_1_7 + a3_1_5 * a5_5_7;
let a5_1_8 = a3_1_8 + a3_1_5 * a5_5_8;
let t5_1 = t3_1 + a3_1_5 * t5_5;
let a5_2_6 = a3_2_6 + a3_2_5 * a5_5_6;
let a5_2_7 = a3_2_7 + a3_2_5 * a5_5_7;
let a5_2_8 = a3_2_8 + a3_2_5 * a5_5_8;
let t5_2 = t3_2 + a3_2_5 * t5_5;
let a5_3_6 = a3_3_6 + a3_3_5 * a5_5_6;
let a5_3_7 = a3_3_7 + a3_3_5 * a5_5_7;
let a5_3_8 = a3_3_8 + a3_3_5 * a5_5_8;
let t5_3 = t3_3 + a3_3_5 * t5_5;
let a5_4_6 = a3_4_6 + a3_4_5 * a5_5_6;
let a5_4_7 = a3_4_7 + a3_4_5 * a5_5_7;
let a5_4_8 = a3_4_8 + a3_4_5 * a5_5_8;
let t5_4 = t3_4 + a3_4_5 * t5_5;
let a5_6_6 = a3_6_6 + a3_6_5 * a5_5_6;
let a5_6_7 = a3_6_7 + a3_6_5 * a5_5_7;
let a5_6_8 = a3_6_8 + a3_6_5 * a5_5_8;
let t5_6 = t3_6 + a3_6_5 * t5_5;
let a5_7_6 = a3_7_6 + a3_7_5 * a5_5_6;
let a5_7_7 = a3_7_7 + a3_7_5 * a5_5_7;
let a5_7_8 = a3_7_8 + a3_7_5 * a5_5_8;
let t5_7 = t3_7 + a3_7_5 * t5_5;
let a5_8_6 = a3_8_6 + a3_8_5 * a5_5_6;
let a5_8_7 = a3_8_7 + a3_8_5 * a5_5_7;
let a5_8_8 = a3_8_8 + a3_8_5 * a5_5_8;
let t5_8 = t3_8 + a3_8_5 * t5_5;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), abs(t5_1)), abs(t5_2)), abs(t5_3)), abs(t5_5));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + abs(t5_1)) + abs(t5_2)) + abs(t5_3)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 14u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let t8_8 = -t5_8 * i8;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let t8_7 = t5_7 + a5_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_3)), abs(t8_5)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_3)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 14u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let t7_8 = t5_8 + a5_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_2)), abs(t7_3)), abs(t7_5)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_2)) + abs(t7_3)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 14u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_3)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_3)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 14u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let a6_6_7 = a5_6_7 * n6;
let a6_6_8 = a5_6_8 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let t6_8 = t5_8 + a5_8_6 * t6_6;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_1)), abs(t6_2)), abs(t6_3)), abs(t6_5)), abs(t6_6));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_1)) + abs(t6_2)) + abs(t6_3)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 14u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_3)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_3)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 14u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_2)), abs(t7_3)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_2)) + abs(t7_3)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 14u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_3)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_3)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 14u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
}
{
let dead4 = semi & !(a3_4_4 > tol.tree_singular * m4_4);
ok = ok & !(l3 & !dead4 & !(a3_4_4 > tol.tree_pivot * m4_4));
let l4 = l3 & !dead4;
let i4 = Scalar(1.0) / a3_4_4;
let n4 = -i4;
let a4_4_5 = a3_4_5 * n4;
let a4_4_6 = a3_4_6 * n4;
let a4_4_7 = a3_4_7 * n4;
let a4_4_8 = a3_4_8 * n4;
let t4_4 = -t3_4 * i4;
let a4_0_5 = a3_0_5 + a3_0_4 * a4_4_5;
let a4_0_6 = a3_0_6 + a3_0_4 * a4_4_6;
let a4_0_7 = a3_0_7 + a3_0_4 * a4_4_7;
let a4_0_8 = a3_0_8 + a3_0_4 * a4_4_8;
let t4_0 = t3_0 + a3_0_4 * t4_4;
let a4_1_5 = a3_1_5 + a3_1_4 * a4_4_5;
let a4_1_6 = a3_1_6 + a3_1_4 * a4_4_6;
let a4_1_7 = a3_1_7 + a3_1_4 * a4_4_7;
let a4_1_8 = a3_1_8 + a3_1_4 * a4_4_8;
let t4_1 = t3_1 + a3_1_4 * t4_4;
let a4_2_5 = a3_2_5 + a3_2_4 * a4_4_5;
let a4_2_6 = a3_2_6 + a3_2_4 * a4_4_6;
let a4_2_7 = a3_2_7 + a3_2_4 * a4_4_7;
let a4_2_8 = a3_2_8 + a3_2_4 * a4_4_8;
let t4_2 = t3_2 + a3_2_4 * t4_4;
let a4_3_5 = a3_3_5 + a3_3_4 * a4_4_5;
let a4_3_6 = a3_3_6 + a3_3_4 * a4_4_6;
let a4_3_7 = a3_3_7 + a3_3_4 * a4_4_7;
let a4_3_8 = a3_3_8 + a3_3_4 * a4_4_8;
let t4_3 = t3_3 + a3_3_4 * t4_4;
let a4_5_5 = a3_5_5 + a3_5_4 * a4_4_5;
let a4_5_6 = a3_5_6 + a3_5_4 * a4_4_6;
let a4_5_7 = a3_5_7 + a3_5_4 * a4_4_7;
let a4_5_8 = a3_5_8 + a3_5_4 * a4_4_8;
let t4_5 = t3_5 + a3_5_4 * t4_4;
let a4_6_5 = a3_6_5 + a3_6_4 * a4_4_5;
let a4_6_6 = a3_6_6 + a3_6_4 * a4_4_6;
let a4_6_7 = a3_6_7 + a3_6_4 * a4_4_7;
let a4_6_8 = a3_6_8 + a3_6_4 * a4_4_8;
let t4_6 = t3_6 + a3_6_4 * t4_4;
let a4_7_5 = a3_7_5 + a3_7_4 * a4_4_5;
let a4_7_6 = a3_7_6 + a3_7_4 * a4_4_6;
let a4_7_7 = a3_7_7 + a3_7_4 * a4_4_7;
let a4_7_8 = a3_7_8 + a3_7_4 * a4_4_8;
let t4_7 = t3_7 + a3_7_4 * t4_4;
let a4_8_5 = a3_8_5 + a3_8_4 * a4_4_5;
let a4_8_6 = a3_8_6 + a3_8_4 * a4_4_6;
let a4_8_7 = a3_8_7 + a3_8_4 * a4_4_7;
let a4_8_8 = a3_8_8 + a3_8_4 * a4_4_8;
let t4_8 = t3_8 + a3_8_4 * t4_4;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t4_0), b0)), abs(t4_1)), abs(t4_2)), abs(t4_3)), abs(t4_4));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t4_0), b0)) + abs(t4_1)) + abs(t4_2)) + abs(t4_3)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 30u), l4 & (t4_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t4_1 >= -tol.screen * zm) & (t4_2 >= -tol.screen * zm) & (t4_3 >= -tol.screen * zm) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t4_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t4_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a4_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l4 & !dead8 & !(a4_8_8 > tol.tree_pivot * m8_8));
let l8 = l4 & !dead8;
let i8 = Scalar(1.0) / a4_8_8;
let n8 = -i8;
let t8_8 = -t4_8 * i8;
let t8_0 = t4_0 + a4_0_8 * t8_8;
let t8_1 = t4_1 + a4_1_8 * t8_8;
let t8_2 = t4_2 + a4_2_8 * t8_8;
let t8_3 = t4_3 + a4_3_8 * t8_8;
let t8_4 = t4_4 + a4_4_8 * t8_8;
let t8_5 = t4_5 + a4_5_8 * t8_8;
let t8_6 = t4_6 + a4_6_8 * t8_8;
let t8_7 = t4_7 + a4_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_3)), abs(t8_4)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 30u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a4_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l4 & !dead7 & !(a4_7_7 > tol.tree_pivot * m7_7));
let l7 = l4 & !dead7;
let i7 = Scalar(1.0) / a4_7_7;
let n7 = -i7;
let a7_7_8 = a4_7_8 * n7;
let t7_7 = -t4_7 * i7;
let a7_0_8 = a4_0_8 + a4_0_7 * a7_7_8;
let t7_0 = t4_0 + a4_0_7 * t7_7;
let a7_1_8 = a4_1_8 + a4_1_7 * a7_7_8;
let t7_1 = t4_1 + a4_1_7 * t7_7;
let a7_2_8 = a4_2_8 + a4_2_7 * a7_7_8;
let t7_2 = t4_2 + a4_2_7 * t7_7;
let a7_3_8 = a4_3_8 + a4_3_7 * a7_7_8;
let t7_3 = t4_3 + a4_3_7 * t7_7;
let a7_4_8 = a4_4_8 + a4_4_7 * a7_7_8;
let t7_4 = t4_4 + a4_4_7 * t7_7;
let a7_5_8 = a4_5_8 + a4_5_7 * a7_7_8;
let t7_5 = t4_5 + a4_5_7 * t7_7;
let a7_6_8 = a4_6_8 + a4_6_7 * a7_7_8;
let t7_6 = t4_6 + a4_6_7 * t7_7;
let a7_8_8 = a4_8_8 + a4_8_7 * a7_7_8;
let t7_8 = t4_8 + a4_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_2)), abs(t7_3)), abs(t7_4)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_2)) + abs(t7_3)) + abs(t7_4)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 30u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_3)), abs(t8_4)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 30u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let a6_6_7 = a4_6_7 * n6;
let a6_6_8 = a4_6_8 * n6;
let t6_6 = -t4_6 * i6;
let a6_0_7 = a4_0_7 + a4_0_6 * a6_6_7;
let a6_0_8 = a4_0_8 + a4_0_6 * a6_6_8;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let a6_1_7 = a4_1_7 + a4_1_6 * a6_6_7;
let a6_1_8 = a4_1_8 + a4_1_6 * a6_6_8;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let a6_2_7 = a4_2_7 + a4_2_6 * a6_6_7;
let a6_2_8 = a4_2_8 + a4_2_6 * a6_6_8;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let a6_3_7 = a4_3_7 + a4_3_6 * a6_6_7;
let a6_3_8 = a4_3_8 + a4_3_6 * a6_6_8;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let a6_4_7 = a4_4_7 + a4_4_6 * a6_6_7;
let a6_4_8 = a4_4_8 + a4_4_6 * a6_6_8;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let a6_5_7 = a4_5_7 + a4_5_6 * a6_6_7;
let a6_5_8 = a4_5_8 + a4_5_6 * a6_6_8;
let t6_5 = t4_5 + a4_5_6 * t6_6;
let a6_7_7 = a4_7_7 + a4_7_6 * a6_6_7;
let a6_7_8 = a4_7_8 + a4_7_6 * a6_6_8;
let t6_7 = t4_7 + a4_7_6 * t6_6;
let a6_8_7 = a4_8_7 + a4_8_6 * a6_6_7;
let a6_8_8 = a4_8_8 + a4_8_6 * a6_6_8;
let t6_8 = t4_8 + a4_8_6 * t6_6;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_1)), abs(t6_2)), abs(t6_3)), abs(t6_4)), abs(t6_6));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_1)) + abs(t6_2)) + abs(t6_3)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 30u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_3)), abs(t8_4)), abs(t8_6)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 30u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_2)), abs(t7_3)), abs(t7_4)), abs(t7_6)), abs(t7_7));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_2)) + abs(t7_3)) + abs(t7_4)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 30u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_3)), abs(t8_4)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 30u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let a5_5_7 = a4_5_7 * n5;
let a5_5_8 = a4_5_8 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let a5_0_7 = a4_0_7 + a4_0_5 * a5_5_7;
let a5_0_8 = a4_0_8 + a4_0_5 * a5_5_8;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let a5_1_7 = a4_1_7 + a4_1_5 * a5_5_7;
let a5_1_8 = a4_1_8 + a4_1_5 * a5_5_8;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let a5_2_7 = a4_2_7 + a4_2_5 * a5_5_7;
let a5_2_8 = a4_2_8 + a4_2_5 * a5_5_8;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let a5_3_7 = a4_3_7 + a4_3_5 * a5_5_7;
let a5_3_8 = a4_3_8 + a4_3_5 * a5_5_8;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let a5_4_7 = a4_4_7 + a4_4_5 * a5_5_7;
let a5_4_8 = a4_4_8 + a4_4_5 * a5_5_8;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let a5_6_7 = a4_6_7 + a4_6_5 * a5_5_7;
let a5_6_8 = a4_6_8 + a4_6_5 * a5_5_8;
let t5_6 = t4_6 + a4_6_5 * t5_5;
let a5_7_6 = a4_7_6 + a4_7_5 * a5_5_6;
let a5_7_7 = a4_7_7 + a4_7_5 * a5_5_7;
let a5_7_8 = a4_7_8 + a4_7_5 * a5_5_8;
let t5_7 = t4_7 + a4_7_5 * t5_5;
let a5_8_6 = a4_8_6 + a4_8_5 * a5_5_6;
let a5_8_7 = a4_8_7 + a4_8_5 * a5_5_7;
let a5_8_8 = a4_8_8 + a4_8_5 * a5_5_8;
let t5_8 = t4_8 + a4_8_5 * t5_5;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), abs(t5_1)), abs(t5_2)), abs(t5_3)), abs(t5_4)), abs(t5_5));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + abs(t5_1)) + abs(t5_2)) + abs(t5_3)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 30u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let t8_8 = -t5_8 * i8;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let t8_7 = t5_7 + a5_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 30u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let t7_8 = t5_8 + a5_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_2)), abs(t7_3)), abs(t7_4)), abs(t7_5)), abs(t7_7));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_2)) + abs(t7_3)) + abs(t7_4)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 30u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 30u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let a6_6_7 = a5_6_7 * n6;
let a6_6_8 = a5_6_8 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let t6_8 = t5_8 + a5_8_6 * t6_6;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), abs(t6_1)), abs(t6_2)), abs(t6_3)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + abs(t6_1)) + abs(t6_2)) + abs(t6_3)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 30u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let t8_8 = -t6_8 * i8;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let t8_7 = t6_7 + a6_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 30u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm));
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let t7_8 = t6_8 + a6_8_7 * t7_7;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), abs(t7_1)), abs(t7_2)), abs(t7_3)), abs(t7_4)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + abs(t7_1)) + abs(t7_2)) + abs(t7_3)) + abs(t7_4)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 30u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * zm) & (t7_2 >= -tol.screen * zm) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)));
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let t8_8 = -t7_8 * i8;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let t8_7 = t7_7 + a7_7_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), abs(t8_1)), abs(t8_2)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + abs(t8_1)) + abs(t8_2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 30u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * zm) & (t8_2 >= -tol.screen * zm) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm));
}
}
}
}
}
}
}
}
}
}
cand[0] = c0;
cand[1] = c1;
cand[2] = c2;
cand[3] = c3;
cand[4] = c4;
cand[5] = c5;
cand[6] = c6;
cand[7] = c7;
cand[8] = c8;
cand[9] = c9;
cand[10] = c10;
cand[11] = c11;
cand[12] = c12;
cand[13] = c13;
cand[14] = c14;
cand[15] = c15;
return ok;
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
    var ok = island.n == FN;
    if ok {
        ok = tree_pass(island.data, (params.flags & 1u) == 1u);
    }
    var singular = 0u;
    var chosen = 0u;
    var found = false;
    if ok {
        // The screened bases in enumeration's order (popcount, then mask),
        // until one is feasible.
        for (var c = 0u; c < MAX_CONFIRMATIONS; c++) {
            var best_key = 0xffffffffu;
            for (var w = 0u; w < WORDS; w++) {
                var bits = cand[w];
                loop {
                    if bits == 0u {
                        break;
                    }
                    let m = w * 32u + countTrailingZeros(bits);
                    bits &= bits - 1u;
                    best_key = min(best_key, (countOneBits(m) << 16u) | m);
                }
            }
            if best_key == 0xffffffffu {
                break;
            }
            let mask = best_key & 0xffffu;
            cand[mask / 32u] &= ~(1u << (mask % 32u));
            let inf = solve_basis(island.data, FN, mask);
            if inf == SINGULAR {
                singular++;
            } else if inf <= tol.feasibility {
                write_z(island.z, FN, countOneBits(mask));
                chosen = mask;
                found = true;
                break;
            }
        }
    }
    if found {
        state.mask = chosen;
        state.status = 1u;
        state.visited = 1u << FN;
        state.singular = singular;
        state._pad1 = DECIDED;
    } else {
        state._pad1 = UNDECIDED;
        atomicAdd(&unfinished[island.n], 1u);
    }
    results[island_index] = state;
}
