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
const FN: u32 = 11u; // HOST fixed_n
// Words of the candidate bitmap: ceil(2^FN / 32).
const WORDS: u32 = 64u; // HOST words

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
let m0_9 = values[base + 9u];
let m0_10 = values[base + 10u];
let rm0 = max(max(max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m0_0)), abs(m0_1)), abs(m0_2)), abs(m0_3)), abs(m0_4)), abs(m0_5)), abs(m0_6)), abs(m0_7)), abs(m0_8)), abs(m0_9)), abs(m0_10));
let m1_0 = values[base + 11u];
let m1_1 = values[base + 12u];
let m1_2 = values[base + 13u];
let m1_3 = values[base + 14u];
let m1_4 = values[base + 15u];
let m1_5 = values[base + 16u];
let m1_6 = values[base + 17u];
let m1_7 = values[base + 18u];
let m1_8 = values[base + 19u];
let m1_9 = values[base + 20u];
let m1_10 = values[base + 21u];
let rm1 = max(max(max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m1_0)), abs(m1_1)), abs(m1_2)), abs(m1_3)), abs(m1_4)), abs(m1_5)), abs(m1_6)), abs(m1_7)), abs(m1_8)), abs(m1_9)), abs(m1_10));
let m2_0 = values[base + 22u];
let m2_1 = values[base + 23u];
let m2_2 = values[base + 24u];
let m2_3 = values[base + 25u];
let m2_4 = values[base + 26u];
let m2_5 = values[base + 27u];
let m2_6 = values[base + 28u];
let m2_7 = values[base + 29u];
let m2_8 = values[base + 30u];
let m2_9 = values[base + 31u];
let m2_10 = values[base + 32u];
let rm2 = max(max(max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m2_0)), abs(m2_1)), abs(m2_2)), abs(m2_3)), abs(m2_4)), abs(m2_5)), abs(m2_6)), abs(m2_7)), abs(m2_8)), abs(m2_9)), abs(m2_10));
let m3_0 = values[base + 33u];
let m3_1 = values[base + 34u];
let m3_2 = values[base + 35u];
let m3_3 = values[base + 36u];
let m3_4 = values[base + 37u];
let m3_5 = values[base + 38u];
let m3_6 = values[base + 39u];
let m3_7 = values[base + 40u];
let m3_8 = values[base + 41u];
let m3_9 = values[base + 42u];
let m3_10 = values[base + 43u];
let rm3 = max(max(max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m3_0)), abs(m3_1)), abs(m3_2)), abs(m3_3)), abs(m3_4)), abs(m3_5)), abs(m3_6)), abs(m3_7)), abs(m3_8)), abs(m3_9)), abs(m3_10));
let m4_0 = values[base + 44u];
let m4_1 = values[base + 45u];
let m4_2 = values[base + 46u];
let m4_3 = values[base + 47u];
let m4_4 = values[base + 48u];
let m4_5 = values[base + 49u];
let m4_6 = values[base + 50u];
let m4_7 = values[base + 51u];
let m4_8 = values[base + 52u];
let m4_9 = values[base + 53u];
let m4_10 = values[base + 54u];
let rm4 = max(max(max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m4_0)), abs(m4_1)), abs(m4_2)), abs(m4_3)), abs(m4_4)), abs(m4_5)), abs(m4_6)), abs(m4_7)), abs(m4_8)), abs(m4_9)), abs(m4_10));
let m5_0 = values[base + 55u];
let m5_1 = values[base + 56u];
let m5_2 = values[base + 57u];
let m5_3 = values[base + 58u];
let m5_4 = values[base + 59u];
let m5_5 = values[base + 60u];
let m5_6 = values[base + 61u];
let m5_7 = values[base + 62u];
let m5_8 = values[base + 63u];
let m5_9 = values[base + 64u];
let m5_10 = values[base + 65u];
let rm5 = max(max(max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m5_0)), abs(m5_1)), abs(m5_2)), abs(m5_3)), abs(m5_4)), abs(m5_5)), abs(m5_6)), abs(m5_7)), abs(m5_8)), abs(m5_9)), abs(m5_10));
let m6_0 = values[base + 66u];
let m6_1 = values[base + 67u];
let m6_2 = values[base + 68u];
let m6_3 = values[base + 69u];
let m6_4 = values[base + 70u];
let m6_5 = values[base + 71u];
let m6_6 = values[base + 72u];
let m6_7 = values[base + 73u];
let m6_8 = values[base + 74u];
let m6_9 = values[base + 75u];
let m6_10 = values[base + 76u];
let rm6 = max(max(max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m6_0)), abs(m6_1)), abs(m6_2)), abs(m6_3)), abs(m6_4)), abs(m6_5)), abs(m6_6)), abs(m6_7)), abs(m6_8)), abs(m6_9)), abs(m6_10));
let m7_0 = values[base + 77u];
let m7_1 = values[base + 78u];
let m7_2 = values[base + 79u];
let m7_3 = values[base + 80u];
let m7_4 = values[base + 81u];
let m7_5 = values[base + 82u];
let m7_6 = values[base + 83u];
let m7_7 = values[base + 84u];
let m7_8 = values[base + 85u];
let m7_9 = values[base + 86u];
let m7_10 = values[base + 87u];
let rm7 = max(max(max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m7_0)), abs(m7_1)), abs(m7_2)), abs(m7_3)), abs(m7_4)), abs(m7_5)), abs(m7_6)), abs(m7_7)), abs(m7_8)), abs(m7_9)), abs(m7_10));
let m8_0 = values[base + 88u];
let m8_1 = values[base + 89u];
let m8_2 = values[base + 90u];
let m8_3 = values[base + 91u];
let m8_4 = values[base + 92u];
let m8_5 = values[base + 93u];
let m8_6 = values[base + 94u];
let m8_7 = values[base + 95u];
let m8_8 = values[base + 96u];
let m8_9 = values[base + 97u];
let m8_10 = values[base + 98u];
let rm8 = max(max(max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m8_0)), abs(m8_1)), abs(m8_2)), abs(m8_3)), abs(m8_4)), abs(m8_5)), abs(m8_6)), abs(m8_7)), abs(m8_8)), abs(m8_9)), abs(m8_10));
let m9_0 = values[base + 99u];
let m9_1 = values[base + 100u];
let m9_2 = values[base + 101u];
let m9_3 = values[base + 102u];
let m9_4 = values[base + 103u];
let m9_5 = values[base + 104u];
let m9_6 = values[base + 105u];
let m9_7 = values[base + 106u];
let m9_8 = values[base + 107u];
let m9_9 = values[base + 108u];
let m9_10 = values[base + 109u];
let rm9 = max(max(max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m9_0)), abs(m9_1)), abs(m9_2)), abs(m9_3)), abs(m9_4)), abs(m9_5)), abs(m9_6)), abs(m9_7)), abs(m9_8)), abs(m9_9)), abs(m9_10));
let m10_0 = values[base + 110u];
let m10_1 = values[base + 111u];
let m10_2 = values[base + 112u];
let m10_3 = values[base + 113u];
let m10_4 = values[base + 114u];
let m10_5 = values[base + 115u];
let m10_6 = values[base + 116u];
let m10_7 = values[base + 117u];
let m10_8 = values[base + 118u];
let m10_9 = values[base + 119u];
let m10_10 = values[base + 120u];
let rm10 = max(max(max(max(max(max(max(max(max(max(max(Scalar(0.0), abs(m10_0)), abs(m10_1)), abs(m10_2)), abs(m10_3)), abs(m10_4)), abs(m10_5)), abs(m10_6)), abs(m10_7)), abs(m10_8)), abs(m10_9)), abs(m10_10));
let q0 = values[base + 121u];
let qa0 = abs(q0);
let q1 = values[base + 122u];
let qa1 = abs(q1);
let q2 = values[base + 123u];
let qa2 = abs(q2);
let q3 = values[base + 124u];
let qa3 = abs(q3);
let q4 = values[base + 125u];
let qa4 = abs(q4);
let q5 = values[base + 126u];
let qa5 = abs(q5);
let q6 = values[base + 127u];
let qa6 = abs(q6);
let q7 = values[base + 128u];
let qa7 = abs(q7);
let q8 = values[base + 129u];
let qa8 = abs(q8);
let q9 = values[base + 130u];
let qa9 = abs(q9);
let q10 = values[base + 131u];
let qa10 = abs(q10);
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
var c16 = 0u;
var c17 = 0u;
var c18 = 0u;
var c19 = 0u;
var c20 = 0u;
var c21 = 0u;
var c22 = 0u;
var c23 = 0u;
var c24 = 0u;
var c25 = 0u;
var c26 = 0u;
var c27 = 0u;
var c28 = 0u;
var c29 = 0u;
var c30 = 0u;
var c31 = 0u;
var c32 = 0u;
var c33 = 0u;
var c34 = 0u;
var c35 = 0u;
var c36 = 0u;
var c37 = 0u;
var c38 = 0u;
var c39 = 0u;
var c40 = 0u;
var c41 = 0u;
var c42 = 0u;
var c43 = 0u;
var c44 = 0u;
var c45 = 0u;
var c46 = 0u;
var c47 = 0u;
var c48 = 0u;
var c49 = 0u;
var c50 = 0u;
var c51 = 0u;
var c52 = 0u;
var c53 = 0u;
var c54 = 0u;
var c55 = 0u;
var c56 = 0u;
var c57 = 0u;
var c58 = 0u;
var c59 = 0u;
var c60 = 0u;
var c61 = 0u;
var c62 = 0u;
var c63 = 0u;
for (var pre = 0u; pre < 8u; pre++) {
var live = true;
var x0_1 = m0_1;
var x0_2 = m0_2;
var x0_3 = m0_3;
var x0_4 = m0_4;
var x0_5 = m0_5;
var x0_6 = m0_6;
var x0_7 = m0_7;
var x0_8 = m0_8;
var x0_9 = m0_9;
var x0_10 = m0_10;
var y0 = q0;
var x1_1 = m1_1;
var x1_2 = m1_2;
var x1_3 = m1_3;
var x1_4 = m1_4;
var x1_5 = m1_5;
var x1_6 = m1_6;
var x1_7 = m1_7;
var x1_8 = m1_8;
var x1_9 = m1_9;
var x1_10 = m1_10;
var y1 = q1;
var x2_1 = m2_1;
var x2_2 = m2_2;
var x2_3 = m2_3;
var x2_4 = m2_4;
var x2_5 = m2_5;
var x2_6 = m2_6;
var x2_7 = m2_7;
var x2_8 = m2_8;
var x2_9 = m2_9;
var x2_10 = m2_10;
var y2 = q2;
var x3_1 = m3_1;
var x3_2 = m3_2;
var x3_3 = m3_3;
var x3_4 = m3_4;
var x3_5 = m3_5;
var x3_6 = m3_6;
var x3_7 = m3_7;
var x3_8 = m3_8;
var x3_9 = m3_9;
var x3_10 = m3_10;
var y3 = q3;
var x4_1 = m4_1;
var x4_2 = m4_2;
var x4_3 = m4_3;
var x4_4 = m4_4;
var x4_5 = m4_5;
var x4_6 = m4_6;
var x4_7 = m4_7;
var x4_8 = m4_8;
var x4_9 = m4_9;
var x4_10 = m4_10;
var y4 = q4;
var x5_1 = m5_1;
var x5_2 = m5_2;
var x5_3 = m5_3;
var x5_4 = m5_4;
var x5_5 = m5_5;
var x5_6 = m5_6;
var x5_7 = m5_7;
var x5_8 = m5_8;
var x5_9 = m5_9;
var x5_10 = m5_10;
var y5 = q5;
var x6_1 = m6_1;
var x6_2 = m6_2;
var x6_3 = m6_3;
var x6_4 = m6_4;
var x6_5 = m6_5;
var x6_6 = m6_6;
var x6_7 = m6_7;
var x6_8 = m6_8;
var x6_9 = m6_9;
var x6_10 = m6_10;
var y6 = q6;
var x7_1 = m7_1;
var x7_2 = m7_2;
var x7_3 = m7_3;
var x7_4 = m7_4;
var x7_5 = m7_5;
var x7_6 = m7_6;
var x7_7 = m7_7;
var x7_8 = m7_8;
var x7_9 = m7_9;
var x7_10 = m7_10;
var y7 = q7;
var x8_1 = m8_1;
var x8_2 = m8_2;
var x8_3 = m8_3;
var x8_4 = m8_4;
var x8_5 = m8_5;
var x8_6 = m8_6;
var x8_7 = m8_7;
var x8_8 = m8_8;
var x8_9 = m8_9;
var x8_10 = m8_10;
var y8 = q8;
var x9_1 = m9_1;
var x9_2 = m9_2;
var x9_3 = m9_3;
var x9_4 = m9_4;
var x9_5 = m9_5;
var x9_6 = m9_6;
var x9_7 = m9_7;
var x9_8 = m9_8;
var x9_9 = m9_9;
var x9_10 = m9_10;
var y9 = q9;
var x10_1 = m10_1;
var x10_2 = m10_2;
var x10_3 = m10_3;
var x10_4 = m10_4;
var x10_5 = m10_5;
var x10_6 = m10_6;
var x10_7 = m10_7;
var x10_8 = m10_8;
var x10_9 = m10_9;
var x10_10 = m10_10;
var y10 = q10;
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
let r9 = x0_9 * n0;
let r10 = x0_10 * n0;
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
x1_9 = x1_9 + f1 * r9;
x1_10 = x1_10 + f1 * r10;
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
x2_9 = x2_9 + f2 * r9;
x2_10 = x2_10 + f2 * r10;
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
x3_9 = x3_9 + f3 * r9;
x3_10 = x3_10 + f3 * r10;
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
x4_9 = x4_9 + f4 * r9;
x4_10 = x4_10 + f4 * r10;
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
x5_9 = x5_9 + f5 * r9;
x5_10 = x5_10 + f5 * r10;
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
x6_9 = x6_9 + f6 * r9;
x6_10 = x6_10 + f6 * r10;
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
x7_9 = x7_9 + f7 * r9;
x7_10 = x7_10 + f7 * r10;
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
x8_9 = x8_9 + f8 * r9;
x8_10 = x8_10 + f8 * r10;
y8 = y8 + f8 * tr;
let f9 = m9_0;
x9_1 = x9_1 + f9 * r1;
x9_2 = x9_2 + f9 * r2;
x9_3 = x9_3 + f9 * r3;
x9_4 = x9_4 + f9 * r4;
x9_5 = x9_5 + f9 * r5;
x9_6 = x9_6 + f9 * r6;
x9_7 = x9_7 + f9 * r7;
x9_8 = x9_8 + f9 * r8;
x9_9 = x9_9 + f9 * r9;
x9_10 = x9_10 + f9 * r10;
y9 = y9 + f9 * tr;
let f10 = m10_0;
x10_1 = x10_1 + f10 * r1;
x10_2 = x10_2 + f10 * r2;
x10_3 = x10_3 + f10 * r3;
x10_4 = x10_4 + f10 * r4;
x10_5 = x10_5 + f10 * r5;
x10_6 = x10_6 + f10 * r6;
x10_7 = x10_7 + f10 * r7;
x10_8 = x10_8 + f10 * r8;
x10_9 = x10_9 + f10 * r9;
x10_10 = x10_10 + f10 * r10;
y10 = y10 + f10 * tr;
x0_1 = r1;
x0_2 = r2;
x0_3 = r3;
x0_4 = r4;
x0_5 = r5;
x0_6 = r6;
x0_7 = r7;
x0_8 = r8;
x0_9 = r9;
x0_10 = r10;
y0 = tr;
}
let b1 = ((pre >> 1u) & 1u) == 1u;
if b1 {
let dead1 = semi & !(x1_1 > tol.tree_singular * m1_1);
ok = ok & !(live & !dead1 & !(x1_1 > tol.tree_pivot * m1_1));
live = live & !dead1;
let i1 = Scalar(1.0) / x1_1;
let n1 = -i1;
let r2 = x1_2 * n1;
let r3 = x1_3 * n1;
let r4 = x1_4 * n1;
let r5 = x1_5 * n1;
let r6 = x1_6 * n1;
let r7 = x1_7 * n1;
let r8 = x1_8 * n1;
let r9 = x1_9 * n1;
let r10 = x1_10 * n1;
let tr = -y1 * i1;
let f0 = x0_1;
x0_2 = x0_2 + f0 * r2;
x0_3 = x0_3 + f0 * r3;
x0_4 = x0_4 + f0 * r4;
x0_5 = x0_5 + f0 * r5;
x0_6 = x0_6 + f0 * r6;
x0_7 = x0_7 + f0 * r7;
x0_8 = x0_8 + f0 * r8;
x0_9 = x0_9 + f0 * r9;
x0_10 = x0_10 + f0 * r10;
y0 = y0 + f0 * tr;
let f2 = x2_1;
x2_2 = x2_2 + f2 * r2;
x2_3 = x2_3 + f2 * r3;
x2_4 = x2_4 + f2 * r4;
x2_5 = x2_5 + f2 * r5;
x2_6 = x2_6 + f2 * r6;
x2_7 = x2_7 + f2 * r7;
x2_8 = x2_8 + f2 * r8;
x2_9 = x2_9 + f2 * r9;
x2_10 = x2_10 + f2 * r10;
y2 = y2 + f2 * tr;
let f3 = x3_1;
x3_2 = x3_2 + f3 * r2;
x3_3 = x3_3 + f3 * r3;
x3_4 = x3_4 + f3 * r4;
x3_5 = x3_5 + f3 * r5;
x3_6 = x3_6 + f3 * r6;
x3_7 = x3_7 + f3 * r7;
x3_8 = x3_8 + f3 * r8;
x3_9 = x3_9 + f3 * r9;
x3_10 = x3_10 + f3 * r10;
y3 = y3 + f3 * tr;
let f4 = x4_1;
x4_2 = x4_2 + f4 * r2;
x4_3 = x4_3 + f4 * r3;
x4_4 = x4_4 + f4 * r4;
x4_5 = x4_5 + f4 * r5;
x4_6 = x4_6 + f4 * r6;
x4_7 = x4_7 + f4 * r7;
x4_8 = x4_8 + f4 * r8;
x4_9 = x4_9 + f4 * r9;
x4_10 = x4_10 + f4 * r10;
y4 = y4 + f4 * tr;
let f5 = x5_1;
x5_2 = x5_2 + f5 * r2;
x5_3 = x5_3 + f5 * r3;
x5_4 = x5_4 + f5 * r4;
x5_5 = x5_5 + f5 * r5;
x5_6 = x5_6 + f5 * r6;
x5_7 = x5_7 + f5 * r7;
x5_8 = x5_8 + f5 * r8;
x5_9 = x5_9 + f5 * r9;
x5_10 = x5_10 + f5 * r10;
y5 = y5 + f5 * tr;
let f6 = x6_1;
x6_2 = x6_2 + f6 * r2;
x6_3 = x6_3 + f6 * r3;
x6_4 = x6_4 + f6 * r4;
x6_5 = x6_5 + f6 * r5;
x6_6 = x6_6 + f6 * r6;
x6_7 = x6_7 + f6 * r7;
x6_8 = x6_8 + f6 * r8;
x6_9 = x6_9 + f6 * r9;
x6_10 = x6_10 + f6 * r10;
y6 = y6 + f6 * tr;
let f7 = x7_1;
x7_2 = x7_2 + f7 * r2;
x7_3 = x7_3 + f7 * r3;
x7_4 = x7_4 + f7 * r4;
x7_5 = x7_5 + f7 * r5;
x7_6 = x7_6 + f7 * r6;
x7_7 = x7_7 + f7 * r7;
x7_8 = x7_8 + f7 * r8;
x7_9 = x7_9 + f7 * r9;
x7_10 = x7_10 + f7 * r10;
y7 = y7 + f7 * tr;
let f8 = x8_1;
x8_2 = x8_2 + f8 * r2;
x8_3 = x8_3 + f8 * r3;
x8_4 = x8_4 + f8 * r4;
x8_5 = x8_5 + f8 * r5;
x8_6 = x8_6 + f8 * r6;
x8_7 = x8_7 + f8 * r7;
x8_8 = x8_8 + f8 * r8;
x8_9 = x8_9 + f8 * r9;
x8_10 = x8_10 + f8 * r10;
y8 = y8 + f8 * tr;
let f9 = x9_1;
x9_2 = x9_2 + f9 * r2;
x9_3 = x9_3 + f9 * r3;
x9_4 = x9_4 + f9 * r4;
x9_5 = x9_5 + f9 * r5;
x9_6 = x9_6 + f9 * r6;
x9_7 = x9_7 + f9 * r7;
x9_8 = x9_8 + f9 * r8;
x9_9 = x9_9 + f9 * r9;
x9_10 = x9_10 + f9 * r10;
y9 = y9 + f9 * tr;
let f10 = x10_1;
x10_2 = x10_2 + f10 * r2;
x10_3 = x10_3 + f10 * r3;
x10_4 = x10_4 + f10 * r4;
x10_5 = x10_5 + f10 * r5;
x10_6 = x10_6 + f10 * r6;
x10_7 = x10_7 + f10 * r7;
x10_8 = x10_8 + f10 * r8;
x10_9 = x10_9 + f10 * r9;
x10_10 = x10_10 + f10 * r10;
y10 = y10 + f10 * tr;
x1_2 = r2;
x1_3 = r3;
x1_4 = r4;
x1_5 = r5;
x1_6 = r6;
x1_7 = r7;
x1_8 = r8;
x1_9 = r9;
x1_10 = r10;
y1 = tr;
}
let b2 = ((pre >> 2u) & 1u) == 1u;
if b2 {
let dead2 = semi & !(x2_2 > tol.tree_singular * m2_2);
ok = ok & !(live & !dead2 & !(x2_2 > tol.tree_pivot * m2_2));
live = live & !dead2;
let i2 = Scalar(1.0) / x2_2;
let n2 = -i2;
let r3 = x2_3 * n2;
let r4 = x2_4 * n2;
let r5 = x2_5 * n2;
let r6 = x2_6 * n2;
let r7 = x2_7 * n2;
let r8 = x2_8 * n2;
let r9 = x2_9 * n2;
let r10 = x2_10 * n2;
let tr = -y2 * i2;
let f0 = x0_2;
x0_3 = x0_3 + f0 * r3;
x0_4 = x0_4 + f0 * r4;
x0_5 = x0_5 + f0 * r5;
x0_6 = x0_6 + f0 * r6;
x0_7 = x0_7 + f0 * r7;
x0_8 = x0_8 + f0 * r8;
x0_9 = x0_9 + f0 * r9;
x0_10 = x0_10 + f0 * r10;
y0 = y0 + f0 * tr;
let f1 = x1_2;
x1_3 = x1_3 + f1 * r3;
x1_4 = x1_4 + f1 * r4;
x1_5 = x1_5 + f1 * r5;
x1_6 = x1_6 + f1 * r6;
x1_7 = x1_7 + f1 * r7;
x1_8 = x1_8 + f1 * r8;
x1_9 = x1_9 + f1 * r9;
x1_10 = x1_10 + f1 * r10;
y1 = y1 + f1 * tr;
let f3 = x3_2;
x3_3 = x3_3 + f3 * r3;
x3_4 = x3_4 + f3 * r4;
x3_5 = x3_5 + f3 * r5;
x3_6 = x3_6 + f3 * r6;
x3_7 = x3_7 + f3 * r7;
x3_8 = x3_8 + f3 * r8;
x3_9 = x3_9 + f3 * r9;
x3_10 = x3_10 + f3 * r10;
y3 = y3 + f3 * tr;
let f4 = x4_2;
x4_3 = x4_3 + f4 * r3;
x4_4 = x4_4 + f4 * r4;
x4_5 = x4_5 + f4 * r5;
x4_6 = x4_6 + f4 * r6;
x4_7 = x4_7 + f4 * r7;
x4_8 = x4_8 + f4 * r8;
x4_9 = x4_9 + f4 * r9;
x4_10 = x4_10 + f4 * r10;
y4 = y4 + f4 * tr;
let f5 = x5_2;
x5_3 = x5_3 + f5 * r3;
x5_4 = x5_4 + f5 * r4;
x5_5 = x5_5 + f5 * r5;
x5_6 = x5_6 + f5 * r6;
x5_7 = x5_7 + f5 * r7;
x5_8 = x5_8 + f5 * r8;
x5_9 = x5_9 + f5 * r9;
x5_10 = x5_10 + f5 * r10;
y5 = y5 + f5 * tr;
let f6 = x6_2;
x6_3 = x6_3 + f6 * r3;
x6_4 = x6_4 + f6 * r4;
x6_5 = x6_5 + f6 * r5;
x6_6 = x6_6 + f6 * r6;
x6_7 = x6_7 + f6 * r7;
x6_8 = x6_8 + f6 * r8;
x6_9 = x6_9 + f6 * r9;
x6_10 = x6_10 + f6 * r10;
y6 = y6 + f6 * tr;
let f7 = x7_2;
x7_3 = x7_3 + f7 * r3;
x7_4 = x7_4 + f7 * r4;
x7_5 = x7_5 + f7 * r5;
x7_6 = x7_6 + f7 * r6;
x7_7 = x7_7 + f7 * r7;
x7_8 = x7_8 + f7 * r8;
x7_9 = x7_9 + f7 * r9;
x7_10 = x7_10 + f7 * r10;
y7 = y7 + f7 * tr;
let f8 = x8_2;
x8_3 = x8_3 + f8 * r3;
x8_4 = x8_4 + f8 * r4;
x8_5 = x8_5 + f8 * r5;
x8_6 = x8_6 + f8 * r6;
x8_7 = x8_7 + f8 * r7;
x8_8 = x8_8 + f8 * r8;
x8_9 = x8_9 + f8 * r9;
x8_10 = x8_10 + f8 * r10;
y8 = y8 + f8 * tr;
let f9 = x9_2;
x9_3 = x9_3 + f9 * r3;
x9_4 = x9_4 + f9 * r4;
x9_5 = x9_5 + f9 * r5;
x9_6 = x9_6 + f9 * r6;
x9_7 = x9_7 + f9 * r7;
x9_8 = x9_8 + f9 * r8;
x9_9 = x9_9 + f9 * r9;
x9_10 = x9_10 + f9 * r10;
y9 = y9 + f9 * tr;
let f10 = x10_2;
x10_3 = x10_3 + f10 * r3;
x10_4 = x10_4 + f10 * r4;
x10_5 = x10_5 + f10 * r5;
x10_6 = x10_6 + f10 * r6;
x10_7 = x10_7 + f10 * r7;
x10_8 = x10_8 + f10 * r8;
x10_9 = x10_9 + f10 * r9;
x10_10 = x10_10 + f10 * r10;
y10 = y10 + f10 * tr;
x2_3 = r3;
x2_4 = r4;
x2_5 = r5;
x2_6 = r6;
x2_7 = r7;
x2_8 = r8;
x2_9 = r9;
x2_10 = r10;
y2 = tr;
}
{
let zm = max(max(max(Scalar(0.0), select(Scalar(0.0), abs(y0), b0)), select(Scalar(0.0), abs(y1), b1)), select(Scalar(0.0), abs(y2), b2));
let zs = (((Scalar(0.0) + select(Scalar(0.0), abs(y0), b0)) + select(Scalar(0.0), abs(y1), b1)) + select(Scalar(0.0), abs(y2), b2));
c0 = c0 | select(0u, 1u << (pre | 0u), live & (y0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (y1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (y2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (y3 >= -tol.screen * (qa3 + rm3 * zs)) & (y4 >= -tol.screen * (qa4 + rm4 * zs)) & (y5 >= -tol.screen * (qa5 + rm5 * zs)) & (y6 >= -tol.screen * (qa6 + rm6 * zs)) & (y7 >= -tol.screen * (qa7 + rm7 * zs)) & (y8 >= -tol.screen * (qa8 + rm8 * zs)) & (y9 >= -tol.screen * (qa9 + rm9 * zs)) & (y10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(x10_10 > tol.tree_singular * m10_10);
ok = ok & !(live & !dead10 & !(x10_10 > tol.tree_pivot * m10_10));
let l10 = live & !dead10;
let i10 = Scalar(1.0) / x10_10;
let n10 = -i10;
let t10_10 = -y10 * i10;
let t10_0 = y0 + x0_10 * t10_10;
let t10_1 = y1 + x1_10 * t10_10;
let t10_2 = y2 + x2_10 * t10_10;
let t10_3 = y3 + x3_10 * t10_10;
let t10_4 = y4 + x4_10 * t10_10;
let t10_5 = y5 + x5_10 * t10_10;
let t10_6 = y6 + x6_10 * t10_10;
let t10_7 = y7 + x7_10 * t10_10;
let t10_8 = y8 + x8_10 * t10_10;
let t10_9 = y9 + x9_10 * t10_10;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_10));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_10));
c32 = c32 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(x9_9 > tol.tree_singular * m9_9);
ok = ok & !(live & !dead9 & !(x9_9 > tol.tree_pivot * m9_9));
let l9 = live & !dead9;
let i9 = Scalar(1.0) / x9_9;
let n9 = -i9;
let a9_9_10 = x9_10 * n9;
let t9_9 = -y9 * i9;
let a9_0_10 = x0_10 + x0_9 * a9_9_10;
let t9_0 = y0 + x0_9 * t9_9;
let a9_1_10 = x1_10 + x1_9 * a9_9_10;
let t9_1 = y1 + x1_9 * t9_9;
let a9_2_10 = x2_10 + x2_9 * a9_9_10;
let t9_2 = y2 + x2_9 * t9_9;
let a9_3_10 = x3_10 + x3_9 * a9_9_10;
let t9_3 = y3 + x3_9 * t9_9;
let a9_4_10 = x4_10 + x4_9 * a9_9_10;
let t9_4 = y4 + x4_9 * t9_9;
let a9_5_10 = x5_10 + x5_9 * a9_9_10;
let t9_5 = y5 + x5_9 * t9_9;
let a9_6_10 = x6_10 + x6_9 * a9_9_10;
let t9_6 = y6 + x6_9 * t9_9;
let a9_7_10 = x7_10 + x7_9 * a9_9_10;
let t9_7 = y7 + x7_9 * t9_9;
let a9_8_10 = x8_10 + x8_9 * a9_9_10;
let t9_8 = y8 + x8_9 * t9_9;
let a9_10_10 = x10_10 + x10_9 * a9_9_10;
let t9_10 = y10 + x10_9 * t9_9;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_9));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_9));
c16 = c16 | select(0u, 1u << (pre | 0u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_9)), abs(t10_10));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_9)) + abs(t10_10));
c48 = c48 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(x8_8 > tol.tree_singular * m8_8);
ok = ok & !(live & !dead8 & !(x8_8 > tol.tree_pivot * m8_8));
let l8 = live & !dead8;
let i8 = Scalar(1.0) / x8_8;
let n8 = -i8;
let a8_8_9 = x8_9 * n8;
let a8_8_10 = x8_10 * n8;
let t8_8 = -y8 * i8;
let a8_0_9 = x0_9 + x0_8 * a8_8_9;
let a8_0_10 = x0_10 + x0_8 * a8_8_10;
let t8_0 = y0 + x0_8 * t8_8;
let a8_1_9 = x1_9 + x1_8 * a8_8_9;
let a8_1_10 = x1_10 + x1_8 * a8_8_10;
let t8_1 = y1 + x1_8 * t8_8;
let a8_2_9 = x2_9 + x2_8 * a8_8_9;
let a8_2_10 = x2_10 + x2_8 * a8_8_10;
let t8_2 = y2 + x2_8 * t8_8;
let a8_3_9 = x3_9 + x3_8 * a8_8_9;
let a8_3_10 = x3_10 + x3_8 * a8_8_10;
let t8_3 = y3 + x3_8 * t8_8;
let a8_4_9 = x4_9 + x4_8 * a8_8_9;
let a8_4_10 = x4_10 + x4_8 * a8_8_10;
let t8_4 = y4 + x4_8 * t8_8;
let a8_5_9 = x5_9 + x5_8 * a8_8_9;
let a8_5_10 = x5_10 + x5_8 * a8_8_10;
let t8_5 = y5 + x5_8 * t8_8;
let a8_6_9 = x6_9 + x6_8 * a8_8_9;
let a8_6_10 = x6_10 + x6_8 * a8_8_10;
let t8_6 = y6 + x6_8 * t8_8;
let a8_7_9 = x7_9 + x7_8 * a8_8_9;
let a8_7_10 = x7_10 + x7_8 * a8_8_10;
let t8_7 = y7 + x7_8 * t8_8;
let a8_9_9 = x9_9 + x9_8 * a8_8_9;
let a8_9_10 = x9_10 + x9_8 * a8_8_10;
let t8_9 = y9 + x9_8 * t8_8;
let a8_10_9 = x10_9 + x10_8 * a8_8_9;
let a8_10_10 = x10_10 + x10_8 * a8_8_10;
let t8_10 = y10 + x10_8 * t8_8;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_8));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 0u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_8)), abs(t10_10));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_8)) + abs(t10_10));
c40 = c40 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_8)), abs(t9_9));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_8)) + abs(t9_9));
c24 = c24 | select(0u, 1u << (pre | 0u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c56 = c56 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
}
{
let dead7 = semi & !(x7_7 > tol.tree_singular * m7_7);
ok = ok & !(live & !dead7 & !(x7_7 > tol.tree_pivot * m7_7));
let l7 = live & !dead7;
let i7 = Scalar(1.0) / x7_7;
let n7 = -i7;
let a7_7_8 = x7_8 * n7;
let a7_7_9 = x7_9 * n7;
let a7_7_10 = x7_10 * n7;
let t7_7 = -y7 * i7;
let a7_0_8 = x0_8 + x0_7 * a7_7_8;
let a7_0_9 = x0_9 + x0_7 * a7_7_9;
let a7_0_10 = x0_10 + x0_7 * a7_7_10;
let t7_0 = y0 + x0_7 * t7_7;
let a7_1_8 = x1_8 + x1_7 * a7_7_8;
let a7_1_9 = x1_9 + x1_7 * a7_7_9;
let a7_1_10 = x1_10 + x1_7 * a7_7_10;
let t7_1 = y1 + x1_7 * t7_7;
let a7_2_8 = x2_8 + x2_7 * a7_7_8;
let a7_2_9 = x2_9 + x2_7 * a7_7_9;
let a7_2_10 = x2_10 + x2_7 * a7_7_10;
let t7_2 = y2 + x2_7 * t7_7;
let a7_3_8 = x3_8 + x3_7 * a7_7_8;
let a7_3_9 = x3_9 + x3_7 * a7_7_9;
let a7_3_10 = x3_10 + x3_7 * a7_7_10;
let t7_3 = y3 + x3_7 * t7_7;
let a7_4_8 = x4_8 + x4_7 * a7_7_8;
let a7_4_9 = x4_9 + x4_7 * a7_7_9;
let a7_4_10 = x4_10 + x4_7 * a7_7_10;
let t7_4 = y4 + x4_7 * t7_7;
let a7_5_8 = x5_8 + x5_7 * a7_7_8;
let a7_5_9 = x5_9 + x5_7 * a7_7_9;
let a7_5_10 = x5_10 + x5_7 * a7_7_10;
let t7_5 = y5 + x5_7 * t7_7;
let a7_6_8 = x6_8 + x6_7 * a7_7_8;
let a7_6_9 = x6_9 + x6_7 * a7_7_9;
let a7_6_10 = x6_10 + x6_7 * a7_7_10;
let t7_6 = y6 + x6_7 * t7_7;
let a7_8_8 = x8_8 + x8_7 * a7_7_8;
let a7_8_9 = x8_9 + x8_7 * a7_7_9;
let a7_8_10 = x8_10 + x8_7 * a7_7_10;
let t7_8 = y8 + x8_7 * t7_7;
let a7_9_8 = x9_8 + x9_7 * a7_7_8;
let a7_9_9 = x9_9 + x9_7 * a7_7_9;
let a7_9_10 = x9_10 + x9_7 * a7_7_10;
let t7_9 = y9 + x9_7 * t7_7;
let a7_10_8 = x10_8 + x10_7 * a7_7_8;
let a7_10_9 = x10_9 + x10_7 * a7_7_9;
let a7_10_10 = x10_10 + x10_7 * a7_7_10;
let t7_10 = y10 + x10_7 * t7_7;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), select(Scalar(0.0), abs(t7_1), b1)), select(Scalar(0.0), abs(t7_2), b2)), abs(t7_7));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + select(Scalar(0.0), abs(t7_1), b1)) + select(Scalar(0.0), abs(t7_2), b2)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 0u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t7_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t7_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t7_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a7_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l7 & !dead10 & !(a7_10_10 > tol.tree_pivot * m10_10));
let l10 = l7 & !dead10;
let i10 = Scalar(1.0) / a7_10_10;
let n10 = -i10;
let t10_10 = -t7_10 * i10;
let t10_0 = t7_0 + a7_0_10 * t10_10;
let t10_1 = t7_1 + a7_1_10 * t10_10;
let t10_2 = t7_2 + a7_2_10 * t10_10;
let t10_3 = t7_3 + a7_3_10 * t10_10;
let t10_4 = t7_4 + a7_4_10 * t10_10;
let t10_5 = t7_5 + a7_5_10 * t10_10;
let t10_6 = t7_6 + a7_6_10 * t10_10;
let t10_7 = t7_7 + a7_7_10 * t10_10;
let t10_8 = t7_8 + a7_8_10 * t10_10;
let t10_9 = t7_9 + a7_9_10 * t10_10;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_7)), abs(t10_10));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_7)) + abs(t10_10));
c36 = c36 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a7_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l7 & !dead9 & !(a7_9_9 > tol.tree_pivot * m9_9));
let l9 = l7 & !dead9;
let i9 = Scalar(1.0) / a7_9_9;
let n9 = -i9;
let a9_9_10 = a7_9_10 * n9;
let t9_9 = -t7_9 * i9;
let a9_0_10 = a7_0_10 + a7_0_9 * a9_9_10;
let t9_0 = t7_0 + a7_0_9 * t9_9;
let a9_1_10 = a7_1_10 + a7_1_9 * a9_9_10;
let t9_1 = t7_1 + a7_1_9 * t9_9;
let a9_2_10 = a7_2_10 + a7_2_9 * a9_9_10;
let t9_2 = t7_2 + a7_2_9 * t9_9;
let a9_3_10 = a7_3_10 + a7_3_9 * a9_9_10;
let t9_3 = t7_3 + a7_3_9 * t9_9;
let a9_4_10 = a7_4_10 + a7_4_9 * a9_9_10;
let t9_4 = t7_4 + a7_4_9 * t9_9;
let a9_5_10 = a7_5_10 + a7_5_9 * a9_9_10;
let t9_5 = t7_5 + a7_5_9 * t9_9;
let a9_6_10 = a7_6_10 + a7_6_9 * a9_9_10;
let t9_6 = t7_6 + a7_6_9 * t9_9;
let a9_7_10 = a7_7_10 + a7_7_9 * a9_9_10;
let t9_7 = t7_7 + a7_7_9 * t9_9;
let a9_8_10 = a7_8_10 + a7_8_9 * a9_9_10;
let t9_8 = t7_8 + a7_8_9 * t9_9;
let a9_10_10 = a7_10_10 + a7_10_9 * a9_9_10;
let t9_10 = t7_10 + a7_10_9 * t9_9;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_7)), abs(t9_9));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_7)) + abs(t9_9));
c20 = c20 | select(0u, 1u << (pre | 0u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_7)), abs(t10_9)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_7)) + abs(t10_9)) + abs(t10_10));
c52 = c52 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let a8_8_9 = a7_8_9 * n8;
let a8_8_10 = a7_8_10 * n8;
let t8_8 = -t7_8 * i8;
let a8_0_9 = a7_0_9 + a7_0_8 * a8_8_9;
let a8_0_10 = a7_0_10 + a7_0_8 * a8_8_10;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let a8_1_9 = a7_1_9 + a7_1_8 * a8_8_9;
let a8_1_10 = a7_1_10 + a7_1_8 * a8_8_10;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let a8_2_9 = a7_2_9 + a7_2_8 * a8_8_9;
let a8_2_10 = a7_2_10 + a7_2_8 * a8_8_10;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let a8_3_9 = a7_3_9 + a7_3_8 * a8_8_9;
let a8_3_10 = a7_3_10 + a7_3_8 * a8_8_10;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let a8_4_9 = a7_4_9 + a7_4_8 * a8_8_9;
let a8_4_10 = a7_4_10 + a7_4_8 * a8_8_10;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let a8_5_9 = a7_5_9 + a7_5_8 * a8_8_9;
let a8_5_10 = a7_5_10 + a7_5_8 * a8_8_10;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let a8_6_9 = a7_6_9 + a7_6_8 * a8_8_9;
let a8_6_10 = a7_6_10 + a7_6_8 * a8_8_10;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let a8_7_9 = a7_7_9 + a7_7_8 * a8_8_9;
let a8_7_10 = a7_7_10 + a7_7_8 * a8_8_10;
let t8_7 = t7_7 + a7_7_8 * t8_8;
let a8_9_9 = a7_9_9 + a7_9_8 * a8_8_9;
let a8_9_10 = a7_9_10 + a7_9_8 * a8_8_10;
let t8_9 = t7_9 + a7_9_8 * t8_8;
let a8_10_9 = a7_10_9 + a7_10_8 * a8_8_9;
let a8_10_10 = a7_10_10 + a7_10_8 * a8_8_10;
let t8_10 = t7_10 + a7_10_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_7)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 0u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_7)), abs(t10_8)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_7)) + abs(t10_8)) + abs(t10_10));
c44 = c44 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_7)), abs(t9_8)), abs(t9_9));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_7)) + abs(t9_8)) + abs(t9_9));
c28 = c28 | select(0u, 1u << (pre | 0u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_7)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_7)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c60 = c60 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
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
let a6_6_9 = x6_9 * n6;
let a6_6_10 = x6_10 * n6;
let t6_6 = -y6 * i6;
let a6_0_7 = x0_7 + x0_6 * a6_6_7;
let a6_0_8 = x0_8 + x0_6 * a6_6_8;
let a6_0_9 = x0_9 + x0_6 * a6_6_9;
let a6_0_10 = x0_10 + x0_6 * a6_6_10;
let t6_0 = y0 + x0_6 * t6_6;
let a6_1_7 = x1_7 + x1_6 * a6_6_7;
let a6_1_8 = x1_8 + x1_6 * a6_6_8;
let a6_1_9 = x1_9 + x1_6 * a6_6_9;
let a6_1_10 = x1_10 + x1_6 * a6_6_10;
let t6_1 = y1 + x1_6 * t6_6;
let a6_2_7 = x2_7 + x2_6 * a6_6_7;
let a6_2_8 = x2_8 + x2_6 * a6_6_8;
let a6_2_9 = x2_9 + x2_6 * a6_6_9;
let a6_2_10 = x2_10 + x2_6 * a6_6_10;
let t6_2 = y2 + x2_6 * t6_6;
let a6_3_7 = x3_7 + x3_6 * a6_6_7;
let a6_3_8 = x3_8 + x3_6 * a6_6_8;
let a6_3_9 = x3_9 + x3_6 * a6_6_9;
let a6_3_10 = x3_10 + x3_6 * a6_6_10;
let t6_3 = y3 + x3_6 * t6_6;
let a6_4_7 = x4_7 + x4_6 * a6_6_7;
let a6_4_8 = x4_8 + x4_6 * a6_6_8;
let a6_4_9 = x4_9 + x4_6 * a6_6_9;
let a6_4_10 = x4_10 + x4_6 * a6_6_10;
let t6_4 = y4 + x4_6 * t6_6;
let a6_5_7 = x5_7 + x5_6 * a6_6_7;
let a6_5_8 = x5_8 + x5_6 * a6_6_8;
let a6_5_9 = x5_9 + x5_6 * a6_6_9;
let a6_5_10 = x5_10 + x5_6 * a6_6_10;
let t6_5 = y5 + x5_6 * t6_6;
let a6_7_7 = x7_7 + x7_6 * a6_6_7;
let a6_7_8 = x7_8 + x7_6 * a6_6_8;
let a6_7_9 = x7_9 + x7_6 * a6_6_9;
let a6_7_10 = x7_10 + x7_6 * a6_6_10;
let t6_7 = y7 + x7_6 * t6_6;
let a6_8_7 = x8_7 + x8_6 * a6_6_7;
let a6_8_8 = x8_8 + x8_6 * a6_6_8;
let a6_8_9 = x8_9 + x8_6 * a6_6_9;
let a6_8_10 = x8_10 + x8_6 * a6_6_10;
let t6_8 = y8 + x8_6 * t6_6;
let a6_9_7 = x9_7 + x9_6 * a6_6_7;
let a6_9_8 = x9_8 + x9_6 * a6_6_8;
let a6_9_9 = x9_9 + x9_6 * a6_6_9;
let a6_9_10 = x9_10 + x9_6 * a6_6_10;
let t6_9 = y9 + x9_6 * t6_6;
let a6_10_7 = x10_7 + x10_6 * a6_6_7;
let a6_10_8 = x10_8 + x10_6 * a6_6_8;
let a6_10_9 = x10_9 + x10_6 * a6_6_9;
let a6_10_10 = x10_10 + x10_6 * a6_6_10;
let t6_10 = y10 + x10_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), select(Scalar(0.0), abs(t6_1), b1)), select(Scalar(0.0), abs(t6_2), b2)), abs(t6_6));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + select(Scalar(0.0), abs(t6_1), b1)) + select(Scalar(0.0), abs(t6_2), b2)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 0u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t6_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t6_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t6_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a6_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l6 & !dead10 & !(a6_10_10 > tol.tree_pivot * m10_10));
let l10 = l6 & !dead10;
let i10 = Scalar(1.0) / a6_10_10;
let n10 = -i10;
let t10_10 = -t6_10 * i10;
let t10_0 = t6_0 + a6_0_10 * t10_10;
let t10_1 = t6_1 + a6_1_10 * t10_10;
let t10_2 = t6_2 + a6_2_10 * t10_10;
let t10_3 = t6_3 + a6_3_10 * t10_10;
let t10_4 = t6_4 + a6_4_10 * t10_10;
let t10_5 = t6_5 + a6_5_10 * t10_10;
let t10_6 = t6_6 + a6_6_10 * t10_10;
let t10_7 = t6_7 + a6_7_10 * t10_10;
let t10_8 = t6_8 + a6_8_10 * t10_10;
let t10_9 = t6_9 + a6_9_10 * t10_10;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_6)), abs(t10_10));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_6)) + abs(t10_10));
c34 = c34 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a6_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l6 & !dead9 & !(a6_9_9 > tol.tree_pivot * m9_9));
let l9 = l6 & !dead9;
let i9 = Scalar(1.0) / a6_9_9;
let n9 = -i9;
let a9_9_10 = a6_9_10 * n9;
let t9_9 = -t6_9 * i9;
let a9_0_10 = a6_0_10 + a6_0_9 * a9_9_10;
let t9_0 = t6_0 + a6_0_9 * t9_9;
let a9_1_10 = a6_1_10 + a6_1_9 * a9_9_10;
let t9_1 = t6_1 + a6_1_9 * t9_9;
let a9_2_10 = a6_2_10 + a6_2_9 * a9_9_10;
let t9_2 = t6_2 + a6_2_9 * t9_9;
let a9_3_10 = a6_3_10 + a6_3_9 * a9_9_10;
let t9_3 = t6_3 + a6_3_9 * t9_9;
let a9_4_10 = a6_4_10 + a6_4_9 * a9_9_10;
let t9_4 = t6_4 + a6_4_9 * t9_9;
let a9_5_10 = a6_5_10 + a6_5_9 * a9_9_10;
let t9_5 = t6_5 + a6_5_9 * t9_9;
let a9_6_10 = a6_6_10 + a6_6_9 * a9_9_10;
let t9_6 = t6_6 + a6_6_9 * t9_9;
let a9_7_10 = a6_7_10 + a6_7_9 * a9_9_10;
let t9_7 = t6_7 + a6_7_9 * t9_9;
let a9_8_10 = a6_8_10 + a6_8_9 * a9_9_10;
let t9_8 = t6_8 + a6_8_9 * t9_9;
let a9_10_10 = a6_10_10 + a6_10_9 * a9_9_10;
let t9_10 = t6_10 + a6_10_9 * t9_9;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_6)), abs(t9_9));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_6)) + abs(t9_9));
c18 = c18 | select(0u, 1u << (pre | 0u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_6)), abs(t10_9)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_6)) + abs(t10_9)) + abs(t10_10));
c50 = c50 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let a8_8_9 = a6_8_9 * n8;
let a8_8_10 = a6_8_10 * n8;
let t8_8 = -t6_8 * i8;
let a8_0_9 = a6_0_9 + a6_0_8 * a8_8_9;
let a8_0_10 = a6_0_10 + a6_0_8 * a8_8_10;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let a8_1_9 = a6_1_9 + a6_1_8 * a8_8_9;
let a8_1_10 = a6_1_10 + a6_1_8 * a8_8_10;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let a8_2_9 = a6_2_9 + a6_2_8 * a8_8_9;
let a8_2_10 = a6_2_10 + a6_2_8 * a8_8_10;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let a8_3_9 = a6_3_9 + a6_3_8 * a8_8_9;
let a8_3_10 = a6_3_10 + a6_3_8 * a8_8_10;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let a8_4_9 = a6_4_9 + a6_4_8 * a8_8_9;
let a8_4_10 = a6_4_10 + a6_4_8 * a8_8_10;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let a8_5_9 = a6_5_9 + a6_5_8 * a8_8_9;
let a8_5_10 = a6_5_10 + a6_5_8 * a8_8_10;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let a8_6_9 = a6_6_9 + a6_6_8 * a8_8_9;
let a8_6_10 = a6_6_10 + a6_6_8 * a8_8_10;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let a8_7_9 = a6_7_9 + a6_7_8 * a8_8_9;
let a8_7_10 = a6_7_10 + a6_7_8 * a8_8_10;
let t8_7 = t6_7 + a6_7_8 * t8_8;
let a8_9_9 = a6_9_9 + a6_9_8 * a8_8_9;
let a8_9_10 = a6_9_10 + a6_9_8 * a8_8_10;
let t8_9 = t6_9 + a6_9_8 * t8_8;
let a8_10_9 = a6_10_9 + a6_10_8 * a8_8_9;
let a8_10_10 = a6_10_10 + a6_10_8 * a8_8_10;
let t8_10 = t6_10 + a6_10_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_6)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 0u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_6)), abs(t10_8)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_6)) + abs(t10_8)) + abs(t10_10));
c42 = c42 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_6)), abs(t9_8)), abs(t9_9));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_6)) + abs(t9_8)) + abs(t9_9));
c26 = c26 | select(0u, 1u << (pre | 0u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_6)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_6)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c58 = c58 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let a7_7_9 = a6_7_9 * n7;
let a7_7_10 = a6_7_10 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let a7_0_9 = a6_0_9 + a6_0_7 * a7_7_9;
let a7_0_10 = a6_0_10 + a6_0_7 * a7_7_10;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let a7_1_9 = a6_1_9 + a6_1_7 * a7_7_9;
let a7_1_10 = a6_1_10 + a6_1_7 * a7_7_10;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let a7_2_9 = a6_2_9 + a6_2_7 * a7_7_9;
let a7_2_10 = a6_2_10 + a6_2_7 * a7_7_10;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let a7_3_9 = a6_3_9 + a6_3_7 * a7_7_9;
let a7_3_10 = a6_3_10 + a6_3_7 * a7_7_10;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let a7_4_9 = a6_4_9 + a6_4_7 * a7_7_9;
let a7_4_10 = a6_4_10 + a6_4_7 * a7_7_10;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let a7_5_9 = a6_5_9 + a6_5_7 * a7_7_9;
let a7_5_10 = a6_5_10 + a6_5_7 * a7_7_10;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let a7_6_9 = a6_6_9 + a6_6_7 * a7_7_9;
let a7_6_10 = a6_6_10 + a6_6_7 * a7_7_10;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let a7_8_9 = a6_8_9 + a6_8_7 * a7_7_9;
let a7_8_10 = a6_8_10 + a6_8_7 * a7_7_10;
let t7_8 = t6_8 + a6_8_7 * t7_7;
let a7_9_8 = a6_9_8 + a6_9_7 * a7_7_8;
let a7_9_9 = a6_9_9 + a6_9_7 * a7_7_9;
let a7_9_10 = a6_9_10 + a6_9_7 * a7_7_10;
let t7_9 = t6_9 + a6_9_7 * t7_7;
let a7_10_8 = a6_10_8 + a6_10_7 * a7_7_8;
let a7_10_9 = a6_10_9 + a6_10_7 * a7_7_9;
let a7_10_10 = a6_10_10 + a6_10_7 * a7_7_10;
let t7_10 = t6_10 + a6_10_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), select(Scalar(0.0), abs(t7_1), b1)), select(Scalar(0.0), abs(t7_2), b2)), abs(t7_6)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + select(Scalar(0.0), abs(t7_1), b1)) + select(Scalar(0.0), abs(t7_2), b2)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 0u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t7_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t7_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t7_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a7_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l7 & !dead10 & !(a7_10_10 > tol.tree_pivot * m10_10));
let l10 = l7 & !dead10;
let i10 = Scalar(1.0) / a7_10_10;
let n10 = -i10;
let t10_10 = -t7_10 * i10;
let t10_0 = t7_0 + a7_0_10 * t10_10;
let t10_1 = t7_1 + a7_1_10 * t10_10;
let t10_2 = t7_2 + a7_2_10 * t10_10;
let t10_3 = t7_3 + a7_3_10 * t10_10;
let t10_4 = t7_4 + a7_4_10 * t10_10;
let t10_5 = t7_5 + a7_5_10 * t10_10;
let t10_6 = t7_6 + a7_6_10 * t10_10;
let t10_7 = t7_7 + a7_7_10 * t10_10;
let t10_8 = t7_8 + a7_8_10 * t10_10;
let t10_9 = t7_9 + a7_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_6)), abs(t10_7)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_6)) + abs(t10_7)) + abs(t10_10));
c38 = c38 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a7_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l7 & !dead9 & !(a7_9_9 > tol.tree_pivot * m9_9));
let l9 = l7 & !dead9;
let i9 = Scalar(1.0) / a7_9_9;
let n9 = -i9;
let a9_9_10 = a7_9_10 * n9;
let t9_9 = -t7_9 * i9;
let a9_0_10 = a7_0_10 + a7_0_9 * a9_9_10;
let t9_0 = t7_0 + a7_0_9 * t9_9;
let a9_1_10 = a7_1_10 + a7_1_9 * a9_9_10;
let t9_1 = t7_1 + a7_1_9 * t9_9;
let a9_2_10 = a7_2_10 + a7_2_9 * a9_9_10;
let t9_2 = t7_2 + a7_2_9 * t9_9;
let a9_3_10 = a7_3_10 + a7_3_9 * a9_9_10;
let t9_3 = t7_3 + a7_3_9 * t9_9;
let a9_4_10 = a7_4_10 + a7_4_9 * a9_9_10;
let t9_4 = t7_4 + a7_4_9 * t9_9;
let a9_5_10 = a7_5_10 + a7_5_9 * a9_9_10;
let t9_5 = t7_5 + a7_5_9 * t9_9;
let a9_6_10 = a7_6_10 + a7_6_9 * a9_9_10;
let t9_6 = t7_6 + a7_6_9 * t9_9;
let a9_7_10 = a7_7_10 + a7_7_9 * a9_9_10;
let t9_7 = t7_7 + a7_7_9 * t9_9;
let a9_8_10 = a7_8_10 + a7_8_9 * a9_9_10;
let t9_8 = t7_8 + a7_8_9 * t9_9;
let a9_10_10 = a7_10_10 + a7_10_9 * a9_9_10;
let t9_10 = t7_10 + a7_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_6)), abs(t9_7)), abs(t9_9));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_6)) + abs(t9_7)) + abs(t9_9));
c22 = c22 | select(0u, 1u << (pre | 0u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_6)), abs(t10_7)), abs(t10_9)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_6)) + abs(t10_7)) + abs(t10_9)) + abs(t10_10));
c54 = c54 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let a8_8_9 = a7_8_9 * n8;
let a8_8_10 = a7_8_10 * n8;
let t8_8 = -t7_8 * i8;
let a8_0_9 = a7_0_9 + a7_0_8 * a8_8_9;
let a8_0_10 = a7_0_10 + a7_0_8 * a8_8_10;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let a8_1_9 = a7_1_9 + a7_1_8 * a8_8_9;
let a8_1_10 = a7_1_10 + a7_1_8 * a8_8_10;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let a8_2_9 = a7_2_9 + a7_2_8 * a8_8_9;
let a8_2_10 = a7_2_10 + a7_2_8 * a8_8_10;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let a8_3_9 = a7_3_9 + a7_3_8 * a8_8_9;
let a8_3_10 = a7_3_10 + a7_3_8 * a8_8_10;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let a8_4_9 = a7_4_9 + a7_4_8 * a8_8_9;
let a8_4_10 = a7_4_10 + a7_4_8 * a8_8_10;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let a8_5_9 = a7_5_9 + a7_5_8 * a8_8_9;
let a8_5_10 = a7_5_10 + a7_5_8 * a8_8_10;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let a8_6_9 = a7_6_9 + a7_6_8 * a8_8_9;
let a8_6_10 = a7_6_10 + a7_6_8 * a8_8_10;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let a8_7_9 = a7_7_9 + a7_7_8 * a8_8_9;
let a8_7_10 = a7_7_10 + a7_7_8 * a8_8_10;
let t8_7 = t7_7 + a7_7_8 * t8_8;
let a8_9_9 = a7_9_9 + a7_9_8 * a8_8_9;
let a8_9_10 = a7_9_10 + a7_9_8 * a8_8_10;
let t8_9 = t7_9 + a7_9_8 * t8_8;
let a8_10_9 = a7_10_9 + a7_10_8 * a8_8_9;
let a8_10_10 = a7_10_10 + a7_10_8 * a8_8_10;
let t8_10 = t7_10 + a7_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 0u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_6)), abs(t10_7)), abs(t10_8)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_6)) + abs(t10_7)) + abs(t10_8)) + abs(t10_10));
c46 = c46 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_6)), abs(t9_7)), abs(t9_8)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_6)) + abs(t9_7)) + abs(t9_8)) + abs(t9_9));
c30 = c30 | select(0u, 1u << (pre | 0u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_6)), abs(t10_7)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_6)) + abs(t10_7)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c62 = c62 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
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
let a5_5_9 = x5_9 * n5;
let a5_5_10 = x5_10 * n5;
let t5_5 = -y5 * i5;
let a5_0_6 = x0_6 + x0_5 * a5_5_6;
let a5_0_7 = x0_7 + x0_5 * a5_5_7;
let a5_0_8 = x0_8 + x0_5 * a5_5_8;
let a5_0_9 = x0_9 + x0_5 * a5_5_9;
let a5_0_10 = x0_10 + x0_5 * a5_5_10;
let t5_0 = y0 + x0_5 * t5_5;
let a5_1_6 = x1_6 + x1_5 * a5_5_6;
let a5_1_7 = x1_7 + x1_5 * a5_5_7;
let a5_1_8 = x1_8 + x1_5 * a5_5_8;
let a5_1_9 = x1_9 + x1_5 * a5_5_9;
let a5_1_10 = x1_10 + x1_5 * a5_5_10;
let t5_1 = y1 + x1_5 * t5_5;
let a5_2_6 = x2_6 + x2_5 * a5_5_6;
let a5_2_7 = x2_7 + x2_5 * a5_5_7;
let a5_2_8 = x2_8 + x2_5 * a5_5_8;
let a5_2_9 = x2_9 + x2_5 * a5_5_9;
let a5_2_10 = x2_10 + x2_5 * a5_5_10;
let t5_2 = y2 + x2_5 * t5_5;
let a5_3_6 = x3_6 + x3_5 * a5_5_6;
let a5_3_7 = x3_7 + x3_5 * a5_5_7;
let a5_3_8 = x3_8 + x3_5 * a5_5_8;
let a5_3_9 = x3_9 + x3_5 * a5_5_9;
let a5_3_10 = x3_10 + x3_5 * a5_5_10;
let t5_3 = y3 + x3_5 * t5_5;
let a5_4_6 = x4_6 + x4_5 * a5_5_6;
let a5_4_7 = x4_7 + x4_5 * a5_5_7;
let a5_4_8 = x4_8 + x4_5 * a5_5_8;
let a5_4_9 = x4_9 + x4_5 * a5_5_9;
let a5_4_10 = x4_10 + x4_5 * a5_5_10;
let t5_4 = y4 + x4_5 * t5_5;
let a5_6_6 = x6_6 + x6_5 * a5_5_6;
let a5_6_7 = x6_7 + x6_5 * a5_5_7;
let a5_6_8 = x6_8 + x6_5 * a5_5_8;
let a5_6_9 = x6_9 + x6_5 * a5_5_9;
let a5_6_10 = x6_10 + x6_5 * a5_5_10;
let t5_6 = y6 + x6_5 * t5_5;
let a5_7_6 = x7_6 + x7_5 * a5_5_6;
let a5_7_7 = x7_7 + x7_5 * a5_5_7;
let a5_7_8 = x7_8 + x7_5 * a5_5_8;
let a5_7_9 = x7_9 + x7_5 * a5_5_9;
let a5_7_10 = x7_10 + x7_5 * a5_5_10;
let t5_7 = y7 + x7_5 * t5_5;
let a5_8_6 = x8_6 + x8_5 * a5_5_6;
let a5_8_7 = x8_7 + x8_5 * a5_5_7;
let a5_8_8 = x8_8 + x8_5 * a5_5_8;
let a5_8_9 = x8_9 + x8_5 * a5_5_9;
let a5_8_10 = x8_10 + x8_5 * a5_5_10;
let t5_8 = y8 + x8_5 * t5_5;
let a5_9_6 = x9_6 + x9_5 * a5_5_6;
let a5_9_7 = x9_7 + x9_5 * a5_5_7;
let a5_9_8 = x9_8 + x9_5 * a5_5_8;
let a5_9_9 = x9_9 + x9_5 * a5_5_9;
let a5_9_10 = x9_10 + x9_5 * a5_5_10;
let t5_9 = y9 + x9_5 * t5_5;
let a5_10_6 = x10_6 + x10_5 * a5_5_6;
let a5_10_7 = x10_7 + x10_5 * a5_5_7;
let a5_10_8 = x10_8 + x10_5 * a5_5_8;
let a5_10_9 = x10_9 + x10_5 * a5_5_9;
let a5_10_10 = x10_10 + x10_5 * a5_5_10;
let t5_10 = y10 + x10_5 * t5_5;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), select(Scalar(0.0), abs(t5_1), b1)), select(Scalar(0.0), abs(t5_2), b2)), abs(t5_5));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + select(Scalar(0.0), abs(t5_1), b1)) + select(Scalar(0.0), abs(t5_2), b2)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 0u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t5_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t5_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t5_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a5_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l5 & !dead10 & !(a5_10_10 > tol.tree_pivot * m10_10));
let l10 = l5 & !dead10;
let i10 = Scalar(1.0) / a5_10_10;
let n10 = -i10;
let t10_10 = -t5_10 * i10;
let t10_0 = t5_0 + a5_0_10 * t10_10;
let t10_1 = t5_1 + a5_1_10 * t10_10;
let t10_2 = t5_2 + a5_2_10 * t10_10;
let t10_3 = t5_3 + a5_3_10 * t10_10;
let t10_4 = t5_4 + a5_4_10 * t10_10;
let t10_5 = t5_5 + a5_5_10 * t10_10;
let t10_6 = t5_6 + a5_6_10 * t10_10;
let t10_7 = t5_7 + a5_7_10 * t10_10;
let t10_8 = t5_8 + a5_8_10 * t10_10;
let t10_9 = t5_9 + a5_9_10 * t10_10;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_5)), abs(t10_10));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_5)) + abs(t10_10));
c33 = c33 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a5_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l5 & !dead9 & !(a5_9_9 > tol.tree_pivot * m9_9));
let l9 = l5 & !dead9;
let i9 = Scalar(1.0) / a5_9_9;
let n9 = -i9;
let a9_9_10 = a5_9_10 * n9;
let t9_9 = -t5_9 * i9;
let a9_0_10 = a5_0_10 + a5_0_9 * a9_9_10;
let t9_0 = t5_0 + a5_0_9 * t9_9;
let a9_1_10 = a5_1_10 + a5_1_9 * a9_9_10;
let t9_1 = t5_1 + a5_1_9 * t9_9;
let a9_2_10 = a5_2_10 + a5_2_9 * a9_9_10;
let t9_2 = t5_2 + a5_2_9 * t9_9;
let a9_3_10 = a5_3_10 + a5_3_9 * a9_9_10;
let t9_3 = t5_3 + a5_3_9 * t9_9;
let a9_4_10 = a5_4_10 + a5_4_9 * a9_9_10;
let t9_4 = t5_4 + a5_4_9 * t9_9;
let a9_5_10 = a5_5_10 + a5_5_9 * a9_9_10;
let t9_5 = t5_5 + a5_5_9 * t9_9;
let a9_6_10 = a5_6_10 + a5_6_9 * a9_9_10;
let t9_6 = t5_6 + a5_6_9 * t9_9;
let a9_7_10 = a5_7_10 + a5_7_9 * a9_9_10;
let t9_7 = t5_7 + a5_7_9 * t9_9;
let a9_8_10 = a5_8_10 + a5_8_9 * a9_9_10;
let t9_8 = t5_8 + a5_8_9 * t9_9;
let a9_10_10 = a5_10_10 + a5_10_9 * a9_9_10;
let t9_10 = t5_10 + a5_10_9 * t9_9;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_5)), abs(t9_9));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_5)) + abs(t9_9));
c17 = c17 | select(0u, 1u << (pre | 0u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_5)), abs(t10_9)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_5)) + abs(t10_9)) + abs(t10_10));
c49 = c49 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let a8_8_9 = a5_8_9 * n8;
let a8_8_10 = a5_8_10 * n8;
let t8_8 = -t5_8 * i8;
let a8_0_9 = a5_0_9 + a5_0_8 * a8_8_9;
let a8_0_10 = a5_0_10 + a5_0_8 * a8_8_10;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let a8_1_9 = a5_1_9 + a5_1_8 * a8_8_9;
let a8_1_10 = a5_1_10 + a5_1_8 * a8_8_10;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let a8_2_9 = a5_2_9 + a5_2_8 * a8_8_9;
let a8_2_10 = a5_2_10 + a5_2_8 * a8_8_10;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let a8_3_9 = a5_3_9 + a5_3_8 * a8_8_9;
let a8_3_10 = a5_3_10 + a5_3_8 * a8_8_10;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let a8_4_9 = a5_4_9 + a5_4_8 * a8_8_9;
let a8_4_10 = a5_4_10 + a5_4_8 * a8_8_10;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let a8_5_9 = a5_5_9 + a5_5_8 * a8_8_9;
let a8_5_10 = a5_5_10 + a5_5_8 * a8_8_10;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let a8_6_9 = a5_6_9 + a5_6_8 * a8_8_9;
let a8_6_10 = a5_6_10 + a5_6_8 * a8_8_10;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let a8_7_9 = a5_7_9 + a5_7_8 * a8_8_9;
let a8_7_10 = a5_7_10 + a5_7_8 * a8_8_10;
let t8_7 = t5_7 + a5_7_8 * t8_8;
let a8_9_9 = a5_9_9 + a5_9_8 * a8_8_9;
let a8_9_10 = a5_9_10 + a5_9_8 * a8_8_10;
let t8_9 = t5_9 + a5_9_8 * t8_8;
let a8_10_9 = a5_10_9 + a5_10_8 * a8_8_9;
let a8_10_10 = a5_10_10 + a5_10_8 * a8_8_10;
let t8_10 = t5_10 + a5_10_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_5)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 0u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_5)), abs(t10_8)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_5)) + abs(t10_8)) + abs(t10_10));
c41 = c41 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_5)), abs(t9_8)), abs(t9_9));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_5)) + abs(t9_8)) + abs(t9_9));
c25 = c25 | select(0u, 1u << (pre | 0u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_5)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_5)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c57 = c57 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let a7_7_9 = a5_7_9 * n7;
let a7_7_10 = a5_7_10 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let a7_0_9 = a5_0_9 + a5_0_7 * a7_7_9;
let a7_0_10 = a5_0_10 + a5_0_7 * a7_7_10;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let a7_1_9 = a5_1_9 + a5_1_7 * a7_7_9;
let a7_1_10 = a5_1_10 + a5_1_7 * a7_7_10;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let a7_2_9 = a5_2_9 + a5_2_7 * a7_7_9;
let a7_2_10 = a5_2_10 + a5_2_7 * a7_7_10;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let a7_3_9 = a5_3_9 + a5_3_7 * a7_7_9;
let a7_3_10 = a5_3_10 + a5_3_7 * a7_7_10;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let a7_4_9 = a5_4_9 + a5_4_7 * a7_7_9;
let a7_4_10 = a5_4_10 + a5_4_7 * a7_7_10;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let a7_5_9 = a5_5_9 + a5_5_7 * a7_7_9;
let a7_5_10 = a5_5_10 + a5_5_7 * a7_7_10;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let a7_6_9 = a5_6_9 + a5_6_7 * a7_7_9;
let a7_6_10 = a5_6_10 + a5_6_7 * a7_7_10;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let a7_8_9 = a5_8_9 + a5_8_7 * a7_7_9;
let a7_8_10 = a5_8_10 + a5_8_7 * a7_7_10;
let t7_8 = t5_8 + a5_8_7 * t7_7;
let a7_9_8 = a5_9_8 + a5_9_7 * a7_7_8;
let a7_9_9 = a5_9_9 + a5_9_7 * a7_7_9;
let a7_9_10 = a5_9_10 + a5_9_7 * a7_7_10;
let t7_9 = t5_9 + a5_9_7 * t7_7;
let a7_10_8 = a5_10_8 + a5_10_7 * a7_7_8;
let a7_10_9 = a5_10_9 + a5_10_7 * a7_7_9;
let a7_10_10 = a5_10_10 + a5_10_7 * a7_7_10;
let t7_10 = t5_10 + a5_10_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), select(Scalar(0.0), abs(t7_1), b1)), select(Scalar(0.0), abs(t7_2), b2)), abs(t7_5)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + select(Scalar(0.0), abs(t7_1), b1)) + select(Scalar(0.0), abs(t7_2), b2)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 0u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t7_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t7_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t7_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a7_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l7 & !dead10 & !(a7_10_10 > tol.tree_pivot * m10_10));
let l10 = l7 & !dead10;
let i10 = Scalar(1.0) / a7_10_10;
let n10 = -i10;
let t10_10 = -t7_10 * i10;
let t10_0 = t7_0 + a7_0_10 * t10_10;
let t10_1 = t7_1 + a7_1_10 * t10_10;
let t10_2 = t7_2 + a7_2_10 * t10_10;
let t10_3 = t7_3 + a7_3_10 * t10_10;
let t10_4 = t7_4 + a7_4_10 * t10_10;
let t10_5 = t7_5 + a7_5_10 * t10_10;
let t10_6 = t7_6 + a7_6_10 * t10_10;
let t10_7 = t7_7 + a7_7_10 * t10_10;
let t10_8 = t7_8 + a7_8_10 * t10_10;
let t10_9 = t7_9 + a7_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_5)), abs(t10_7)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_5)) + abs(t10_7)) + abs(t10_10));
c37 = c37 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a7_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l7 & !dead9 & !(a7_9_9 > tol.tree_pivot * m9_9));
let l9 = l7 & !dead9;
let i9 = Scalar(1.0) / a7_9_9;
let n9 = -i9;
let a9_9_10 = a7_9_10 * n9;
let t9_9 = -t7_9 * i9;
let a9_0_10 = a7_0_10 + a7_0_9 * a9_9_10;
let t9_0 = t7_0 + a7_0_9 * t9_9;
let a9_1_10 = a7_1_10 + a7_1_9 * a9_9_10;
let t9_1 = t7_1 + a7_1_9 * t9_9;
let a9_2_10 = a7_2_10 + a7_2_9 * a9_9_10;
let t9_2 = t7_2 + a7_2_9 * t9_9;
let a9_3_10 = a7_3_10 + a7_3_9 * a9_9_10;
let t9_3 = t7_3 + a7_3_9 * t9_9;
let a9_4_10 = a7_4_10 + a7_4_9 * a9_9_10;
let t9_4 = t7_4 + a7_4_9 * t9_9;
let a9_5_10 = a7_5_10 + a7_5_9 * a9_9_10;
let t9_5 = t7_5 + a7_5_9 * t9_9;
let a9_6_10 = a7_6_10 + a7_6_9 * a9_9_10;
let t9_6 = t7_6 + a7_6_9 * t9_9;
let a9_7_10 = a7_7_10 + a7_7_9 * a9_9_10;
let t9_7 = t7_7 + a7_7_9 * t9_9;
let a9_8_10 = a7_8_10 + a7_8_9 * a9_9_10;
let t9_8 = t7_8 + a7_8_9 * t9_9;
let a9_10_10 = a7_10_10 + a7_10_9 * a9_9_10;
let t9_10 = t7_10 + a7_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_5)), abs(t9_7)), abs(t9_9));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_5)) + abs(t9_7)) + abs(t9_9));
c21 = c21 | select(0u, 1u << (pre | 0u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_5)), abs(t10_7)), abs(t10_9)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_5)) + abs(t10_7)) + abs(t10_9)) + abs(t10_10));
c53 = c53 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let a8_8_9 = a7_8_9 * n8;
let a8_8_10 = a7_8_10 * n8;
let t8_8 = -t7_8 * i8;
let a8_0_9 = a7_0_9 + a7_0_8 * a8_8_9;
let a8_0_10 = a7_0_10 + a7_0_8 * a8_8_10;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let a8_1_9 = a7_1_9 + a7_1_8 * a8_8_9;
let a8_1_10 = a7_1_10 + a7_1_8 * a8_8_10;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let a8_2_9 = a7_2_9 + a7_2_8 * a8_8_9;
let a8_2_10 = a7_2_10 + a7_2_8 * a8_8_10;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let a8_3_9 = a7_3_9 + a7_3_8 * a8_8_9;
let a8_3_10 = a7_3_10 + a7_3_8 * a8_8_10;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let a8_4_9 = a7_4_9 + a7_4_8 * a8_8_9;
let a8_4_10 = a7_4_10 + a7_4_8 * a8_8_10;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let a8_5_9 = a7_5_9 + a7_5_8 * a8_8_9;
let a8_5_10 = a7_5_10 + a7_5_8 * a8_8_10;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let a8_6_9 = a7_6_9 + a7_6_8 * a8_8_9;
let a8_6_10 = a7_6_10 + a7_6_8 * a8_8_10;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let a8_7_9 = a7_7_9 + a7_7_8 * a8_8_9;
let a8_7_10 = a7_7_10 + a7_7_8 * a8_8_10;
let t8_7 = t7_7 + a7_7_8 * t8_8;
let a8_9_9 = a7_9_9 + a7_9_8 * a8_8_9;
let a8_9_10 = a7_9_10 + a7_9_8 * a8_8_10;
let t8_9 = t7_9 + a7_9_8 * t8_8;
let a8_10_9 = a7_10_9 + a7_10_8 * a8_8_9;
let a8_10_10 = a7_10_10 + a7_10_8 * a8_8_10;
let t8_10 = t7_10 + a7_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 0u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_5)), abs(t10_7)), abs(t10_8)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_5)) + abs(t10_7)) + abs(t10_8)) + abs(t10_10));
c45 = c45 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_5)), abs(t9_7)), abs(t9_8)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_5)) + abs(t9_7)) + abs(t9_8)) + abs(t9_9));
c29 = c29 | select(0u, 1u << (pre | 0u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_5)), abs(t10_7)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_5)) + abs(t10_7)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c61 = c61 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
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
let a6_6_9 = a5_6_9 * n6;
let a6_6_10 = a5_6_10 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let a6_0_9 = a5_0_9 + a5_0_6 * a6_6_9;
let a6_0_10 = a5_0_10 + a5_0_6 * a6_6_10;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let a6_1_9 = a5_1_9 + a5_1_6 * a6_6_9;
let a6_1_10 = a5_1_10 + a5_1_6 * a6_6_10;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let a6_2_9 = a5_2_9 + a5_2_6 * a6_6_9;
let a6_2_10 = a5_2_10 + a5_2_6 * a6_6_10;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let a6_3_9 = a5_3_9 + a5_3_6 * a6_6_9;
let a6_3_10 = a5_3_10 + a5_3_6 * a6_6_10;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let a6_4_9 = a5_4_9 + a5_4_6 * a6_6_9;
let a6_4_10 = a5_4_10 + a5_4_6 * a6_6_10;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let a6_5_9 = a5_5_9 + a5_5_6 * a6_6_9;
let a6_5_10 = a5_5_10 + a5_5_6 * a6_6_10;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let a6_7_9 = a5_7_9 + a5_7_6 * a6_6_9;
let a6_7_10 = a5_7_10 + a5_7_6 * a6_6_10;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let a6_8_9 = a5_8_9 + a5_8_6 * a6_6_9;
let a6_8_10 = a5_8_10 + a5_8_6 * a6_6_10;
let t6_8 = t5_8 + a5_8_6 * t6_6;
let a6_9_7 = a5_9_7 + a5_9_6 * a6_6_7;
let a6_9_8 = a5_9_8 + a5_9_6 * a6_6_8;
let a6_9_9 = a5_9_9 + a5_9_6 * a6_6_9;
let a6_9_10 = a5_9_10 + a5_9_6 * a6_6_10;
let t6_9 = t5_9 + a5_9_6 * t6_6;
let a6_10_7 = a5_10_7 + a5_10_6 * a6_6_7;
let a6_10_8 = a5_10_8 + a5_10_6 * a6_6_8;
let a6_10_9 = a5_10_9 + a5_10_6 * a6_6_9;
let a6_10_10 = a5_10_10 + a5_10_6 * a6_6_10;
let t6_10 = t5_10 + a5_10_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), select(Scalar(0.0), abs(t6_1), b1)), select(Scalar(0.0), abs(t6_2), b2)), abs(t6_5)), abs(t6_6));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + select(Scalar(0.0), abs(t6_1), b1)) + select(Scalar(0.0), abs(t6_2), b2)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 0u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t6_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t6_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t6_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a6_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l6 & !dead10 & !(a6_10_10 > tol.tree_pivot * m10_10));
let l10 = l6 & !dead10;
let i10 = Scalar(1.0) / a6_10_10;
let n10 = -i10;
let t10_10 = -t6_10 * i10;
let t10_0 = t6_0 + a6_0_10 * t10_10;
let t10_1 = t6_1 + a6_1_10 * t10_10;
let t10_2 = t6_2 + a6_2_10 * t10_10;
let t10_3 = t6_3 + a6_3_10 * t10_10;
let t10_4 = t6_4 + a6_4_10 * t10_10;
let t10_5 = t6_5 + a6_5_10 * t10_10;
let t10_6 = t6_6 + a6_6_10 * t10_10;
let t10_7 = t6_7 + a6_7_10 * t10_10;
let t10_8 = t6_8 + a6_8_10 * t10_10;
let t10_9 = t6_9 + a6_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_5)), abs(t10_6)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_5)) + abs(t10_6)) + abs(t10_10));
c35 = c35 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a6_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l6 & !dead9 & !(a6_9_9 > tol.tree_pivot * m9_9));
let l9 = l6 & !dead9;
let i9 = Scalar(1.0) / a6_9_9;
let n9 = -i9;
let a9_9_10 = a6_9_10 * n9;
let t9_9 = -t6_9 * i9;
let a9_0_10 = a6_0_10 + a6_0_9 * a9_9_10;
let t9_0 = t6_0 + a6_0_9 * t9_9;
let a9_1_10 = a6_1_10 + a6_1_9 * a9_9_10;
let t9_1 = t6_1 + a6_1_9 * t9_9;
let a9_2_10 = a6_2_10 + a6_2_9 * a9_9_10;
let t9_2 = t6_2 + a6_2_9 * t9_9;
let a9_3_10 = a6_3_10 + a6_3_9 * a9_9_10;
let t9_3 = t6_3 + a6_3_9 * t9_9;
let a9_4_10 = a6_4_10 + a6_4_9 * a9_9_10;
let t9_4 = t6_4 + a6_4_9 * t9_9;
let a9_5_10 = a6_5_10 + a6_5_9 * a9_9_10;
let t9_5 = t6_5 + a6_5_9 * t9_9;
let a9_6_10 = a6_6_10 + a6_6_9 * a9_9_10;
let t9_6 = t6_6 + a6_6_9 * t9_9;
let a9_7_10 = a6_7_10 + a6_7_9 * a9_9_10;
let t9_7 = t6_7 + a6_7_9 * t9_9;
let a9_8_10 = a6_8_10 + a6_8_9 * a9_9_10;
let t9_8 = t6_8 + a6_8_9 * t9_9;
let a9_10_10 = a6_10_10 + a6_10_9 * a9_9_10;
let t9_10 = t6_10 + a6_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_5)), abs(t9_6)), abs(t9_9));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_5)) + abs(t9_6)) + abs(t9_9));
c19 = c19 | select(0u, 1u << (pre | 0u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_5)), abs(t10_6)), abs(t10_9)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_5)) + abs(t10_6)) + abs(t10_9)) + abs(t10_10));
c51 = c51 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let a8_8_9 = a6_8_9 * n8;
let a8_8_10 = a6_8_10 * n8;
let t8_8 = -t6_8 * i8;
let a8_0_9 = a6_0_9 + a6_0_8 * a8_8_9;
let a8_0_10 = a6_0_10 + a6_0_8 * a8_8_10;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let a8_1_9 = a6_1_9 + a6_1_8 * a8_8_9;
let a8_1_10 = a6_1_10 + a6_1_8 * a8_8_10;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let a8_2_9 = a6_2_9 + a6_2_8 * a8_8_9;
let a8_2_10 = a6_2_10 + a6_2_8 * a8_8_10;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let a8_3_9 = a6_3_9 + a6_3_8 * a8_8_9;
let a8_3_10 = a6_3_10 + a6_3_8 * a8_8_10;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let a8_4_9 = a6_4_9 + a6_4_8 * a8_8_9;
let a8_4_10 = a6_4_10 + a6_4_8 * a8_8_10;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let a8_5_9 = a6_5_9 + a6_5_8 * a8_8_9;
let a8_5_10 = a6_5_10 + a6_5_8 * a8_8_10;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let a8_6_9 = a6_6_9 + a6_6_8 * a8_8_9;
let a8_6_10 = a6_6_10 + a6_6_8 * a8_8_10;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let a8_7_9 = a6_7_9 + a6_7_8 * a8_8_9;
let a8_7_10 = a6_7_10 + a6_7_8 * a8_8_10;
let t8_7 = t6_7 + a6_7_8 * t8_8;
let a8_9_9 = a6_9_9 + a6_9_8 * a8_8_9;
let a8_9_10 = a6_9_10 + a6_9_8 * a8_8_10;
let t8_9 = t6_9 + a6_9_8 * t8_8;
let a8_10_9 = a6_10_9 + a6_10_8 * a8_8_9;
let a8_10_10 = a6_10_10 + a6_10_8 * a8_8_10;
let t8_10 = t6_10 + a6_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 0u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_5)), abs(t10_6)), abs(t10_8)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_5)) + abs(t10_6)) + abs(t10_8)) + abs(t10_10));
c43 = c43 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_5)), abs(t9_6)), abs(t9_8)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_5)) + abs(t9_6)) + abs(t9_8)) + abs(t9_9));
c27 = c27 | select(0u, 1u << (pre | 0u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_5)), abs(t10_6)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_5)) + abs(t10_6)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c59 = c59 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let a7_7_9 = a6_7_9 * n7;
let a7_7_10 = a6_7_10 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let a7_0_9 = a6_0_9 + a6_0_7 * a7_7_9;
let a7_0_10 = a6_0_10 + a6_0_7 * a7_7_10;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let a7_1_9 = a6_1_9 + a6_1_7 * a7_7_9;
let a7_1_10 = a6_1_10 + a6_1_7 * a7_7_10;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let a7_2_9 = a6_2_9 + a6_2_7 * a7_7_9;
let a7_2_10 = a6_2_10 + a6_2_7 * a7_7_10;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let a7_3_9 = a6_3_9 + a6_3_7 * a7_7_9;
let a7_3_10 = a6_3_10 + a6_3_7 * a7_7_10;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let a7_4_9 = a6_4_9 + a6_4_7 * a7_7_9;
let a7_4_10 = a6_4_10 + a6_4_7 * a7_7_10;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let a7_5_9 = a6_5_9 + a6_5_7 * a7_7_9;
let a7_5_10 = a6_5_10 + a6_5_7 * a7_7_10;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let a7_6_9 = a6_6_9 + a6_6_7 * a7_7_9;
let a7_6_10 = a6_6_10 + a6_6_7 * a7_7_10;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let a7_8_9 = a6_8_9 + a6_8_7 * a7_7_9;
let a7_8_10 = a6_8_10 + a6_8_7 * a7_7_10;
let t7_8 = t6_8 + a6_8_7 * t7_7;
let a7_9_8 = a6_9_8 + a6_9_7 * a7_7_8;
let a7_9_9 = a6_9_9 + a6_9_7 * a7_7_9;
let a7_9_10 = a6_9_10 + a6_9_7 * a7_7_10;
let t7_9 = t6_9 + a6_9_7 * t7_7;
let a7_10_8 = a6_10_8 + a6_10_7 * a7_7_8;
let a7_10_9 = a6_10_9 + a6_10_7 * a7_7_9;
let a7_10_10 = a6_10_10 + a6_10_7 * a7_7_10;
let t7_10 = t6_10 + a6_10_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), select(Scalar(0.0), abs(t7_1), b1)), select(Scalar(0.0), abs(t7_2), b2)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + select(Scalar(0.0), abs(t7_1), b1)) + select(Scalar(0.0), abs(t7_2), b2)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 0u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t7_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t7_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t7_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a7_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l7 & !dead10 & !(a7_10_10 > tol.tree_pivot * m10_10));
let l10 = l7 & !dead10;
let i10 = Scalar(1.0) / a7_10_10;
let n10 = -i10;
let t10_10 = -t7_10 * i10;
let t10_0 = t7_0 + a7_0_10 * t10_10;
let t10_1 = t7_1 + a7_1_10 * t10_10;
let t10_2 = t7_2 + a7_2_10 * t10_10;
let t10_3 = t7_3 + a7_3_10 * t10_10;
let t10_4 = t7_4 + a7_4_10 * t10_10;
let t10_5 = t7_5 + a7_5_10 * t10_10;
let t10_6 = t7_6 + a7_6_10 * t10_10;
let t10_7 = t7_7 + a7_7_10 * t10_10;
let t10_8 = t7_8 + a7_8_10 * t10_10;
let t10_9 = t7_9 + a7_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_5)), abs(t10_6)), abs(t10_7)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_5)) + abs(t10_6)) + abs(t10_7)) + abs(t10_10));
c39 = c39 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a7_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l7 & !dead9 & !(a7_9_9 > tol.tree_pivot * m9_9));
let l9 = l7 & !dead9;
let i9 = Scalar(1.0) / a7_9_9;
let n9 = -i9;
let a9_9_10 = a7_9_10 * n9;
let t9_9 = -t7_9 * i9;
let a9_0_10 = a7_0_10 + a7_0_9 * a9_9_10;
let t9_0 = t7_0 + a7_0_9 * t9_9;
let a9_1_10 = a7_1_10 + a7_1_9 * a9_9_10;
let t9_1 = t7_1 + a7_1_9 * t9_9;
let a9_2_10 = a7_2_10 + a7_2_9 * a9_9_10;
let t9_2 = t7_2 + a7_2_9 * t9_9;
let a9_3_10 = a7_3_10 + a7_3_9 * a9_9_10;
let t9_3 = t7_3 + a7_3_9 * t9_9;
let a9_4_10 = a7_4_10 + a7_4_9 * a9_9_10;
let t9_4 = t7_4 + a7_4_9 * t9_9;
let a9_5_10 = a7_5_10 + a7_5_9 * a9_9_10;
let t9_5 = t7_5 + a7_5_9 * t9_9;
let a9_6_10 = a7_6_10 + a7_6_9 * a9_9_10;
let t9_6 = t7_6 + a7_6_9 * t9_9;
let a9_7_10 = a7_7_10 + a7_7_9 * a9_9_10;
let t9_7 = t7_7 + a7_7_9 * t9_9;
let a9_8_10 = a7_8_10 + a7_8_9 * a9_9_10;
let t9_8 = t7_8 + a7_8_9 * t9_9;
let a9_10_10 = a7_10_10 + a7_10_9 * a9_9_10;
let t9_10 = t7_10 + a7_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_5)), abs(t9_6)), abs(t9_7)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_5)) + abs(t9_6)) + abs(t9_7)) + abs(t9_9));
c23 = c23 | select(0u, 1u << (pre | 0u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_5)), abs(t10_6)), abs(t10_7)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_5)) + abs(t10_6)) + abs(t10_7)) + abs(t10_9)) + abs(t10_10));
c55 = c55 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let a8_8_9 = a7_8_9 * n8;
let a8_8_10 = a7_8_10 * n8;
let t8_8 = -t7_8 * i8;
let a8_0_9 = a7_0_9 + a7_0_8 * a8_8_9;
let a8_0_10 = a7_0_10 + a7_0_8 * a8_8_10;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let a8_1_9 = a7_1_9 + a7_1_8 * a8_8_9;
let a8_1_10 = a7_1_10 + a7_1_8 * a8_8_10;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let a8_2_9 = a7_2_9 + a7_2_8 * a8_8_9;
let a8_2_10 = a7_2_10 + a7_2_8 * a8_8_10;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let a8_3_9 = a7_3_9 + a7_3_8 * a8_8_9;
let a8_3_10 = a7_3_10 + a7_3_8 * a8_8_10;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let a8_4_9 = a7_4_9 + a7_4_8 * a8_8_9;
let a8_4_10 = a7_4_10 + a7_4_8 * a8_8_10;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let a8_5_9 = a7_5_9 + a7_5_8 * a8_8_9;
let a8_5_10 = a7_5_10 + a7_5_8 * a8_8_10;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let a8_6_9 = a7_6_9 + a7_6_8 * a8_8_9;
let a8_6_10 = a7_6_10 + a7_6_8 * a8_8_10;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let a8_7_9 = a7_7_9 + a7_7_8 * a8_8_9;
let a8_7_10 = a7_7_10 + a7_7_8 * a8_8_10;
let t8_7 = t7_7 + a7_7_8 * t8_8;
let a8_9_9 = a7_9_9 + a7_9_8 * a8_8_9;
let a8_9_10 = a7_9_10 + a7_9_8 * a8_8_10;
let t8_9 = t7_9 + a7_9_8 * t8_8;
let a8_10_9 = a7_10_9 + a7_10_8 * a8_8_9;
let a8_10_10 = a7_10_10 + a7_10_8 * a8_8_10;
let t8_10 = t7_10 + a7_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 0u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_5)), abs(t10_6)), abs(t10_7)), abs(t10_8)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_5)) + abs(t10_6)) + abs(t10_7)) + abs(t10_8)) + abs(t10_10));
c47 = c47 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_5)), abs(t9_6)), abs(t9_7)), abs(t9_8)), abs(t9_9));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_5)) + abs(t9_6)) + abs(t9_7)) + abs(t9_8)) + abs(t9_9));
c31 = c31 | select(0u, 1u << (pre | 0u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_5)), abs(t10_6)), abs(t10_7)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_5)) + abs(t10_6)) + abs(t10_7)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c63 = c63 | select(0u, 1u << (pre | 0u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
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
let a4_4_9 = x4_9 * n4;
let a4_4_10 = x4_10 * n4;
let t4_4 = -y4 * i4;
let a4_0_5 = x0_5 + x0_4 * a4_4_5;
let a4_0_6 = x0_6 + x0_4 * a4_4_6;
let a4_0_7 = x0_7 + x0_4 * a4_4_7;
let a4_0_8 = x0_8 + x0_4 * a4_4_8;
let a4_0_9 = x0_9 + x0_4 * a4_4_9;
let a4_0_10 = x0_10 + x0_4 * a4_4_10;
let t4_0 = y0 + x0_4 * t4_4;
let a4_1_5 = x1_5 + x1_4 * a4_4_5;
let a4_1_6 = x1_6 + x1_4 * a4_4_6;
let a4_1_7 = x1_7 + x1_4 * a4_4_7;
let a4_1_8 = x1_8 + x1_4 * a4_4_8;
let a4_1_9 = x1_9 + x1_4 * a4_4_9;
let a4_1_10 = x1_10 + x1_4 * a4_4_10;
let t4_1 = y1 + x1_4 * t4_4;
let a4_2_5 = x2_5 + x2_4 * a4_4_5;
let a4_2_6 = x2_6 + x2_4 * a4_4_6;
let a4_2_7 = x2_7 + x2_4 * a4_4_7;
let a4_2_8 = x2_8 + x2_4 * a4_4_8;
let a4_2_9 = x2_9 + x2_4 * a4_4_9;
let a4_2_10 = x2_10 + x2_4 * a4_4_10;
let t4_2 = y2 + x2_4 * t4_4;
let a4_3_5 = x3_5 + x3_4 * a4_4_5;
let a4_3_6 = x3_6 + x3_4 * a4_4_6;
let a4_3_7 = x3_7 + x3_4 * a4_4_7;
let a4_3_8 = x3_8 + x3_4 * a4_4_8;
let a4_3_9 = x3_9 + x3_4 * a4_4_9;
let a4_3_10 = x3_10 + x3_4 * a4_4_10;
let t4_3 = y3 + x3_4 * t4_4;
let a4_5_5 = x5_5 + x5_4 * a4_4_5;
let a4_5_6 = x5_6 + x5_4 * a4_4_6;
let a4_5_7 = x5_7 + x5_4 * a4_4_7;
let a4_5_8 = x5_8 + x5_4 * a4_4_8;
let a4_5_9 = x5_9 + x5_4 * a4_4_9;
let a4_5_10 = x5_10 + x5_4 * a4_4_10;
let t4_5 = y5 + x5_4 * t4_4;
let a4_6_5 = x6_5 + x6_4 * a4_4_5;
let a4_6_6 = x6_6 + x6_4 * a4_4_6;
let a4_6_7 = x6_7 + x6_4 * a4_4_7;
let a4_6_8 = x6_8 + x6_4 * a4_4_8;
let a4_6_9 = x6_9 + x6_4 * a4_4_9;
let a4_6_10 = x6_10 + x6_4 * a4_4_10;
let t4_6 = y6 + x6_4 * t4_4;
let a4_7_5 = x7_5 + x7_4 * a4_4_5;
let a4_7_6 = x7_6 + x7_4 * a4_4_6;
let a4_7_7 = x7_7 + x7_4 * a4_4_7;
let a4_7_8 = x7_8 + x7_4 * a4_4_8;
let a4_7_9 = x7_9 + x7_4 * a4_4_9;
let a4_7_10 = x7_10 + x7_4 * a4_4_10;
let t4_7 = y7 + x7_4 * t4_4;
let a4_8_5 = x8_5 + x8_4 * a4_4_5;
let a4_8_6 = x8_6 + x8_4 * a4_4_6;
let a4_8_7 = x8_7 + x8_4 * a4_4_7;
let a4_8_8 = x8_8 + x8_4 * a4_4_8;
let a4_8_9 = x8_9 + x8_4 * a4_4_9;
let a4_8_10 = x8_10 + x8_4 * a4_4_10;
let t4_8 = y8 + x8_4 * t4_4;
let a4_9_5 = x9_5 + x9_4 * a4_4_5;
let a4_9_6 = x9_6 + x9_4 * a4_4_6;
let a4_9_7 = x9_7 + x9_4 * a4_4_7;
let a4_9_8 = x9_8 + x9_4 * a4_4_8;
let a4_9_9 = x9_9 + x9_4 * a4_4_9;
let a4_9_10 = x9_10 + x9_4 * a4_4_10;
let t4_9 = y9 + x9_4 * t4_4;
let a4_10_5 = x10_5 + x10_4 * a4_4_5;
let a4_10_6 = x10_6 + x10_4 * a4_4_6;
let a4_10_7 = x10_7 + x10_4 * a4_4_7;
let a4_10_8 = x10_8 + x10_4 * a4_4_8;
let a4_10_9 = x10_9 + x10_4 * a4_4_9;
let a4_10_10 = x10_10 + x10_4 * a4_4_10;
let t4_10 = y10 + x10_4 * t4_4;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t4_0), b0)), select(Scalar(0.0), abs(t4_1), b1)), select(Scalar(0.0), abs(t4_2), b2)), abs(t4_4));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t4_0), b0)) + select(Scalar(0.0), abs(t4_1), b1)) + select(Scalar(0.0), abs(t4_2), b2)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 16u), l4 & (t4_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t4_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t4_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t4_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t4_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t4_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t4_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t4_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a4_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l4 & !dead10 & !(a4_10_10 > tol.tree_pivot * m10_10));
let l10 = l4 & !dead10;
let i10 = Scalar(1.0) / a4_10_10;
let n10 = -i10;
let t10_10 = -t4_10 * i10;
let t10_0 = t4_0 + a4_0_10 * t10_10;
let t10_1 = t4_1 + a4_1_10 * t10_10;
let t10_2 = t4_2 + a4_2_10 * t10_10;
let t10_3 = t4_3 + a4_3_10 * t10_10;
let t10_4 = t4_4 + a4_4_10 * t10_10;
let t10_5 = t4_5 + a4_5_10 * t10_10;
let t10_6 = t4_6 + a4_6_10 * t10_10;
let t10_7 = t4_7 + a4_7_10 * t10_10;
let t10_8 = t4_8 + a4_8_10 * t10_10;
let t10_9 = t4_9 + a4_9_10 * t10_10;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_10));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_10));
c32 = c32 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a4_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l4 & !dead9 & !(a4_9_9 > tol.tree_pivot * m9_9));
let l9 = l4 & !dead9;
let i9 = Scalar(1.0) / a4_9_9;
let n9 = -i9;
let a9_9_10 = a4_9_10 * n9;
let t9_9 = -t4_9 * i9;
let a9_0_10 = a4_0_10 + a4_0_9 * a9_9_10;
let t9_0 = t4_0 + a4_0_9 * t9_9;
let a9_1_10 = a4_1_10 + a4_1_9 * a9_9_10;
let t9_1 = t4_1 + a4_1_9 * t9_9;
let a9_2_10 = a4_2_10 + a4_2_9 * a9_9_10;
let t9_2 = t4_2 + a4_2_9 * t9_9;
let a9_3_10 = a4_3_10 + a4_3_9 * a9_9_10;
let t9_3 = t4_3 + a4_3_9 * t9_9;
let a9_4_10 = a4_4_10 + a4_4_9 * a9_9_10;
let t9_4 = t4_4 + a4_4_9 * t9_9;
let a9_5_10 = a4_5_10 + a4_5_9 * a9_9_10;
let t9_5 = t4_5 + a4_5_9 * t9_9;
let a9_6_10 = a4_6_10 + a4_6_9 * a9_9_10;
let t9_6 = t4_6 + a4_6_9 * t9_9;
let a9_7_10 = a4_7_10 + a4_7_9 * a9_9_10;
let t9_7 = t4_7 + a4_7_9 * t9_9;
let a9_8_10 = a4_8_10 + a4_8_9 * a9_9_10;
let t9_8 = t4_8 + a4_8_9 * t9_9;
let a9_10_10 = a4_10_10 + a4_10_9 * a9_9_10;
let t9_10 = t4_10 + a4_10_9 * t9_9;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_4)), abs(t9_9));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_4)) + abs(t9_9));
c16 = c16 | select(0u, 1u << (pre | 16u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_9)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_9)) + abs(t10_10));
c48 = c48 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a4_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l4 & !dead8 & !(a4_8_8 > tol.tree_pivot * m8_8));
let l8 = l4 & !dead8;
let i8 = Scalar(1.0) / a4_8_8;
let n8 = -i8;
let a8_8_9 = a4_8_9 * n8;
let a8_8_10 = a4_8_10 * n8;
let t8_8 = -t4_8 * i8;
let a8_0_9 = a4_0_9 + a4_0_8 * a8_8_9;
let a8_0_10 = a4_0_10 + a4_0_8 * a8_8_10;
let t8_0 = t4_0 + a4_0_8 * t8_8;
let a8_1_9 = a4_1_9 + a4_1_8 * a8_8_9;
let a8_1_10 = a4_1_10 + a4_1_8 * a8_8_10;
let t8_1 = t4_1 + a4_1_8 * t8_8;
let a8_2_9 = a4_2_9 + a4_2_8 * a8_8_9;
let a8_2_10 = a4_2_10 + a4_2_8 * a8_8_10;
let t8_2 = t4_2 + a4_2_8 * t8_8;
let a8_3_9 = a4_3_9 + a4_3_8 * a8_8_9;
let a8_3_10 = a4_3_10 + a4_3_8 * a8_8_10;
let t8_3 = t4_3 + a4_3_8 * t8_8;
let a8_4_9 = a4_4_9 + a4_4_8 * a8_8_9;
let a8_4_10 = a4_4_10 + a4_4_8 * a8_8_10;
let t8_4 = t4_4 + a4_4_8 * t8_8;
let a8_5_9 = a4_5_9 + a4_5_8 * a8_8_9;
let a8_5_10 = a4_5_10 + a4_5_8 * a8_8_10;
let t8_5 = t4_5 + a4_5_8 * t8_8;
let a8_6_9 = a4_6_9 + a4_6_8 * a8_8_9;
let a8_6_10 = a4_6_10 + a4_6_8 * a8_8_10;
let t8_6 = t4_6 + a4_6_8 * t8_8;
let a8_7_9 = a4_7_9 + a4_7_8 * a8_8_9;
let a8_7_10 = a4_7_10 + a4_7_8 * a8_8_10;
let t8_7 = t4_7 + a4_7_8 * t8_8;
let a8_9_9 = a4_9_9 + a4_9_8 * a8_8_9;
let a8_9_10 = a4_9_10 + a4_9_8 * a8_8_10;
let t8_9 = t4_9 + a4_9_8 * t8_8;
let a8_10_9 = a4_10_9 + a4_10_8 * a8_8_9;
let a8_10_10 = a4_10_10 + a4_10_8 * a8_8_10;
let t8_10 = t4_10 + a4_10_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_4)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_4)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 16u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_8)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_8)) + abs(t10_10));
c40 = c40 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_4)), abs(t9_8)), abs(t9_9));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_4)) + abs(t9_8)) + abs(t9_9));
c24 = c24 | select(0u, 1u << (pre | 16u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c56 = c56 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
}
{
let dead7 = semi & !(a4_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l4 & !dead7 & !(a4_7_7 > tol.tree_pivot * m7_7));
let l7 = l4 & !dead7;
let i7 = Scalar(1.0) / a4_7_7;
let n7 = -i7;
let a7_7_8 = a4_7_8 * n7;
let a7_7_9 = a4_7_9 * n7;
let a7_7_10 = a4_7_10 * n7;
let t7_7 = -t4_7 * i7;
let a7_0_8 = a4_0_8 + a4_0_7 * a7_7_8;
let a7_0_9 = a4_0_9 + a4_0_7 * a7_7_9;
let a7_0_10 = a4_0_10 + a4_0_7 * a7_7_10;
let t7_0 = t4_0 + a4_0_7 * t7_7;
let a7_1_8 = a4_1_8 + a4_1_7 * a7_7_8;
let a7_1_9 = a4_1_9 + a4_1_7 * a7_7_9;
let a7_1_10 = a4_1_10 + a4_1_7 * a7_7_10;
let t7_1 = t4_1 + a4_1_7 * t7_7;
let a7_2_8 = a4_2_8 + a4_2_7 * a7_7_8;
let a7_2_9 = a4_2_9 + a4_2_7 * a7_7_9;
let a7_2_10 = a4_2_10 + a4_2_7 * a7_7_10;
let t7_2 = t4_2 + a4_2_7 * t7_7;
let a7_3_8 = a4_3_8 + a4_3_7 * a7_7_8;
let a7_3_9 = a4_3_9 + a4_3_7 * a7_7_9;
let a7_3_10 = a4_3_10 + a4_3_7 * a7_7_10;
let t7_3 = t4_3 + a4_3_7 * t7_7;
let a7_4_8 = a4_4_8 + a4_4_7 * a7_7_8;
let a7_4_9 = a4_4_9 + a4_4_7 * a7_7_9;
let a7_4_10 = a4_4_10 + a4_4_7 * a7_7_10;
let t7_4 = t4_4 + a4_4_7 * t7_7;
let a7_5_8 = a4_5_8 + a4_5_7 * a7_7_8;
let a7_5_9 = a4_5_9 + a4_5_7 * a7_7_9;
let a7_5_10 = a4_5_10 + a4_5_7 * a7_7_10;
let t7_5 = t4_5 + a4_5_7 * t7_7;
let a7_6_8 = a4_6_8 + a4_6_7 * a7_7_8;
let a7_6_9 = a4_6_9 + a4_6_7 * a7_7_9;
let a7_6_10 = a4_6_10 + a4_6_7 * a7_7_10;
let t7_6 = t4_6 + a4_6_7 * t7_7;
let a7_8_8 = a4_8_8 + a4_8_7 * a7_7_8;
let a7_8_9 = a4_8_9 + a4_8_7 * a7_7_9;
let a7_8_10 = a4_8_10 + a4_8_7 * a7_7_10;
let t7_8 = t4_8 + a4_8_7 * t7_7;
let a7_9_8 = a4_9_8 + a4_9_7 * a7_7_8;
let a7_9_9 = a4_9_9 + a4_9_7 * a7_7_9;
let a7_9_10 = a4_9_10 + a4_9_7 * a7_7_10;
let t7_9 = t4_9 + a4_9_7 * t7_7;
let a7_10_8 = a4_10_8 + a4_10_7 * a7_7_8;
let a7_10_9 = a4_10_9 + a4_10_7 * a7_7_9;
let a7_10_10 = a4_10_10 + a4_10_7 * a7_7_10;
let t7_10 = t4_10 + a4_10_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), select(Scalar(0.0), abs(t7_1), b1)), select(Scalar(0.0), abs(t7_2), b2)), abs(t7_4)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + select(Scalar(0.0), abs(t7_1), b1)) + select(Scalar(0.0), abs(t7_2), b2)) + abs(t7_4)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 16u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t7_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t7_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t7_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a7_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l7 & !dead10 & !(a7_10_10 > tol.tree_pivot * m10_10));
let l10 = l7 & !dead10;
let i10 = Scalar(1.0) / a7_10_10;
let n10 = -i10;
let t10_10 = -t7_10 * i10;
let t10_0 = t7_0 + a7_0_10 * t10_10;
let t10_1 = t7_1 + a7_1_10 * t10_10;
let t10_2 = t7_2 + a7_2_10 * t10_10;
let t10_3 = t7_3 + a7_3_10 * t10_10;
let t10_4 = t7_4 + a7_4_10 * t10_10;
let t10_5 = t7_5 + a7_5_10 * t10_10;
let t10_6 = t7_6 + a7_6_10 * t10_10;
let t10_7 = t7_7 + a7_7_10 * t10_10;
let t10_8 = t7_8 + a7_8_10 * t10_10;
let t10_9 = t7_9 + a7_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_7)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_7)) + abs(t10_10));
c36 = c36 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a7_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l7 & !dead9 & !(a7_9_9 > tol.tree_pivot * m9_9));
let l9 = l7 & !dead9;
let i9 = Scalar(1.0) / a7_9_9;
let n9 = -i9;
let a9_9_10 = a7_9_10 * n9;
let t9_9 = -t7_9 * i9;
let a9_0_10 = a7_0_10 + a7_0_9 * a9_9_10;
let t9_0 = t7_0 + a7_0_9 * t9_9;
let a9_1_10 = a7_1_10 + a7_1_9 * a9_9_10;
let t9_1 = t7_1 + a7_1_9 * t9_9;
let a9_2_10 = a7_2_10 + a7_2_9 * a9_9_10;
let t9_2 = t7_2 + a7_2_9 * t9_9;
let a9_3_10 = a7_3_10 + a7_3_9 * a9_9_10;
let t9_3 = t7_3 + a7_3_9 * t9_9;
let a9_4_10 = a7_4_10 + a7_4_9 * a9_9_10;
let t9_4 = t7_4 + a7_4_9 * t9_9;
let a9_5_10 = a7_5_10 + a7_5_9 * a9_9_10;
let t9_5 = t7_5 + a7_5_9 * t9_9;
let a9_6_10 = a7_6_10 + a7_6_9 * a9_9_10;
let t9_6 = t7_6 + a7_6_9 * t9_9;
let a9_7_10 = a7_7_10 + a7_7_9 * a9_9_10;
let t9_7 = t7_7 + a7_7_9 * t9_9;
let a9_8_10 = a7_8_10 + a7_8_9 * a9_9_10;
let t9_8 = t7_8 + a7_8_9 * t9_9;
let a9_10_10 = a7_10_10 + a7_10_9 * a9_9_10;
let t9_10 = t7_10 + a7_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_4)), abs(t9_7)), abs(t9_9));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_4)) + abs(t9_7)) + abs(t9_9));
c20 = c20 | select(0u, 1u << (pre | 16u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_7)), abs(t10_9)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_7)) + abs(t10_9)) + abs(t10_10));
c52 = c52 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let a8_8_9 = a7_8_9 * n8;
let a8_8_10 = a7_8_10 * n8;
let t8_8 = -t7_8 * i8;
let a8_0_9 = a7_0_9 + a7_0_8 * a8_8_9;
let a8_0_10 = a7_0_10 + a7_0_8 * a8_8_10;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let a8_1_9 = a7_1_9 + a7_1_8 * a8_8_9;
let a8_1_10 = a7_1_10 + a7_1_8 * a8_8_10;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let a8_2_9 = a7_2_9 + a7_2_8 * a8_8_9;
let a8_2_10 = a7_2_10 + a7_2_8 * a8_8_10;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let a8_3_9 = a7_3_9 + a7_3_8 * a8_8_9;
let a8_3_10 = a7_3_10 + a7_3_8 * a8_8_10;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let a8_4_9 = a7_4_9 + a7_4_8 * a8_8_9;
let a8_4_10 = a7_4_10 + a7_4_8 * a8_8_10;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let a8_5_9 = a7_5_9 + a7_5_8 * a8_8_9;
let a8_5_10 = a7_5_10 + a7_5_8 * a8_8_10;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let a8_6_9 = a7_6_9 + a7_6_8 * a8_8_9;
let a8_6_10 = a7_6_10 + a7_6_8 * a8_8_10;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let a8_7_9 = a7_7_9 + a7_7_8 * a8_8_9;
let a8_7_10 = a7_7_10 + a7_7_8 * a8_8_10;
let t8_7 = t7_7 + a7_7_8 * t8_8;
let a8_9_9 = a7_9_9 + a7_9_8 * a8_8_9;
let a8_9_10 = a7_9_10 + a7_9_8 * a8_8_10;
let t8_9 = t7_9 + a7_9_8 * t8_8;
let a8_10_9 = a7_10_9 + a7_10_8 * a8_8_9;
let a8_10_10 = a7_10_10 + a7_10_8 * a8_8_10;
let t8_10 = t7_10 + a7_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_4)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_4)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 16u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_7)), abs(t10_8)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_7)) + abs(t10_8)) + abs(t10_10));
c44 = c44 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_4)), abs(t9_7)), abs(t9_8)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_4)) + abs(t9_7)) + abs(t9_8)) + abs(t9_9));
c28 = c28 | select(0u, 1u << (pre | 16u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_7)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_7)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c60 = c60 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
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
let a6_6_9 = a4_6_9 * n6;
let a6_6_10 = a4_6_10 * n6;
let t6_6 = -t4_6 * i6;
let a6_0_7 = a4_0_7 + a4_0_6 * a6_6_7;
let a6_0_8 = a4_0_8 + a4_0_6 * a6_6_8;
let a6_0_9 = a4_0_9 + a4_0_6 * a6_6_9;
let a6_0_10 = a4_0_10 + a4_0_6 * a6_6_10;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let a6_1_7 = a4_1_7 + a4_1_6 * a6_6_7;
let a6_1_8 = a4_1_8 + a4_1_6 * a6_6_8;
let a6_1_9 = a4_1_9 + a4_1_6 * a6_6_9;
let a6_1_10 = a4_1_10 + a4_1_6 * a6_6_10;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let a6_2_7 = a4_2_7 + a4_2_6 * a6_6_7;
let a6_2_8 = a4_2_8 + a4_2_6 * a6_6_8;
let a6_2_9 = a4_2_9 + a4_2_6 * a6_6_9;
let a6_2_10 = a4_2_10 + a4_2_6 * a6_6_10;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let a6_3_7 = a4_3_7 + a4_3_6 * a6_6_7;
let a6_3_8 = a4_3_8 + a4_3_6 * a6_6_8;
let a6_3_9 = a4_3_9 + a4_3_6 * a6_6_9;
let a6_3_10 = a4_3_10 + a4_3_6 * a6_6_10;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let a6_4_7 = a4_4_7 + a4_4_6 * a6_6_7;
let a6_4_8 = a4_4_8 + a4_4_6 * a6_6_8;
let a6_4_9 = a4_4_9 + a4_4_6 * a6_6_9;
let a6_4_10 = a4_4_10 + a4_4_6 * a6_6_10;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let a6_5_7 = a4_5_7 + a4_5_6 * a6_6_7;
let a6_5_8 = a4_5_8 + a4_5_6 * a6_6_8;
let a6_5_9 = a4_5_9 + a4_5_6 * a6_6_9;
let a6_5_10 = a4_5_10 + a4_5_6 * a6_6_10;
let t6_5 = t4_5 + a4_5_6 * t6_6;
let a6_7_7 = a4_7_7 + a4_7_6 * a6_6_7;
let a6_7_8 = a4_7_8 + a4_7_6 * a6_6_8;
let a6_7_9 = a4_7_9 + a4_7_6 * a6_6_9;
let a6_7_10 = a4_7_10 + a4_7_6 * a6_6_10;
let t6_7 = t4_7 + a4_7_6 * t6_6;
let a6_8_7 = a4_8_7 + a4_8_6 * a6_6_7;
let a6_8_8 = a4_8_8 + a4_8_6 * a6_6_8;
let a6_8_9 = a4_8_9 + a4_8_6 * a6_6_9;
let a6_8_10 = a4_8_10 + a4_8_6 * a6_6_10;
let t6_8 = t4_8 + a4_8_6 * t6_6;
let a6_9_7 = a4_9_7 + a4_9_6 * a6_6_7;
let a6_9_8 = a4_9_8 + a4_9_6 * a6_6_8;
let a6_9_9 = a4_9_9 + a4_9_6 * a6_6_9;
let a6_9_10 = a4_9_10 + a4_9_6 * a6_6_10;
let t6_9 = t4_9 + a4_9_6 * t6_6;
let a6_10_7 = a4_10_7 + a4_10_6 * a6_6_7;
let a6_10_8 = a4_10_8 + a4_10_6 * a6_6_8;
let a6_10_9 = a4_10_9 + a4_10_6 * a6_6_9;
let a6_10_10 = a4_10_10 + a4_10_6 * a6_6_10;
let t6_10 = t4_10 + a4_10_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), select(Scalar(0.0), abs(t6_1), b1)), select(Scalar(0.0), abs(t6_2), b2)), abs(t6_4)), abs(t6_6));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + select(Scalar(0.0), abs(t6_1), b1)) + select(Scalar(0.0), abs(t6_2), b2)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 16u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t6_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t6_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t6_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a6_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l6 & !dead10 & !(a6_10_10 > tol.tree_pivot * m10_10));
let l10 = l6 & !dead10;
let i10 = Scalar(1.0) / a6_10_10;
let n10 = -i10;
let t10_10 = -t6_10 * i10;
let t10_0 = t6_0 + a6_0_10 * t10_10;
let t10_1 = t6_1 + a6_1_10 * t10_10;
let t10_2 = t6_2 + a6_2_10 * t10_10;
let t10_3 = t6_3 + a6_3_10 * t10_10;
let t10_4 = t6_4 + a6_4_10 * t10_10;
let t10_5 = t6_5 + a6_5_10 * t10_10;
let t10_6 = t6_6 + a6_6_10 * t10_10;
let t10_7 = t6_7 + a6_7_10 * t10_10;
let t10_8 = t6_8 + a6_8_10 * t10_10;
let t10_9 = t6_9 + a6_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_6)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_6)) + abs(t10_10));
c34 = c34 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a6_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l6 & !dead9 & !(a6_9_9 > tol.tree_pivot * m9_9));
let l9 = l6 & !dead9;
let i9 = Scalar(1.0) / a6_9_9;
let n9 = -i9;
let a9_9_10 = a6_9_10 * n9;
let t9_9 = -t6_9 * i9;
let a9_0_10 = a6_0_10 + a6_0_9 * a9_9_10;
let t9_0 = t6_0 + a6_0_9 * t9_9;
let a9_1_10 = a6_1_10 + a6_1_9 * a9_9_10;
let t9_1 = t6_1 + a6_1_9 * t9_9;
let a9_2_10 = a6_2_10 + a6_2_9 * a9_9_10;
let t9_2 = t6_2 + a6_2_9 * t9_9;
let a9_3_10 = a6_3_10 + a6_3_9 * a9_9_10;
let t9_3 = t6_3 + a6_3_9 * t9_9;
let a9_4_10 = a6_4_10 + a6_4_9 * a9_9_10;
let t9_4 = t6_4 + a6_4_9 * t9_9;
let a9_5_10 = a6_5_10 + a6_5_9 * a9_9_10;
let t9_5 = t6_5 + a6_5_9 * t9_9;
let a9_6_10 = a6_6_10 + a6_6_9 * a9_9_10;
let t9_6 = t6_6 + a6_6_9 * t9_9;
let a9_7_10 = a6_7_10 + a6_7_9 * a9_9_10;
let t9_7 = t6_7 + a6_7_9 * t9_9;
let a9_8_10 = a6_8_10 + a6_8_9 * a9_9_10;
let t9_8 = t6_8 + a6_8_9 * t9_9;
let a9_10_10 = a6_10_10 + a6_10_9 * a9_9_10;
let t9_10 = t6_10 + a6_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_4)), abs(t9_6)), abs(t9_9));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_4)) + abs(t9_6)) + abs(t9_9));
c18 = c18 | select(0u, 1u << (pre | 16u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_6)), abs(t10_9)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_6)) + abs(t10_9)) + abs(t10_10));
c50 = c50 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let a8_8_9 = a6_8_9 * n8;
let a8_8_10 = a6_8_10 * n8;
let t8_8 = -t6_8 * i8;
let a8_0_9 = a6_0_9 + a6_0_8 * a8_8_9;
let a8_0_10 = a6_0_10 + a6_0_8 * a8_8_10;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let a8_1_9 = a6_1_9 + a6_1_8 * a8_8_9;
let a8_1_10 = a6_1_10 + a6_1_8 * a8_8_10;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let a8_2_9 = a6_2_9 + a6_2_8 * a8_8_9;
let a8_2_10 = a6_2_10 + a6_2_8 * a8_8_10;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let a8_3_9 = a6_3_9 + a6_3_8 * a8_8_9;
let a8_3_10 = a6_3_10 + a6_3_8 * a8_8_10;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let a8_4_9 = a6_4_9 + a6_4_8 * a8_8_9;
let a8_4_10 = a6_4_10 + a6_4_8 * a8_8_10;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let a8_5_9 = a6_5_9 + a6_5_8 * a8_8_9;
let a8_5_10 = a6_5_10 + a6_5_8 * a8_8_10;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let a8_6_9 = a6_6_9 + a6_6_8 * a8_8_9;
let a8_6_10 = a6_6_10 + a6_6_8 * a8_8_10;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let a8_7_9 = a6_7_9 + a6_7_8 * a8_8_9;
let a8_7_10 = a6_7_10 + a6_7_8 * a8_8_10;
let t8_7 = t6_7 + a6_7_8 * t8_8;
let a8_9_9 = a6_9_9 + a6_9_8 * a8_8_9;
let a8_9_10 = a6_9_10 + a6_9_8 * a8_8_10;
let t8_9 = t6_9 + a6_9_8 * t8_8;
let a8_10_9 = a6_10_9 + a6_10_8 * a8_8_9;
let a8_10_10 = a6_10_10 + a6_10_8 * a8_8_10;
let t8_10 = t6_10 + a6_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_4)), abs(t8_6)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_4)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 16u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_6)), abs(t10_8)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_6)) + abs(t10_8)) + abs(t10_10));
c42 = c42 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_4)), abs(t9_6)), abs(t9_8)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_4)) + abs(t9_6)) + abs(t9_8)) + abs(t9_9));
c26 = c26 | select(0u, 1u << (pre | 16u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_6)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_6)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c58 = c58 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let a7_7_9 = a6_7_9 * n7;
let a7_7_10 = a6_7_10 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let a7_0_9 = a6_0_9 + a6_0_7 * a7_7_9;
let a7_0_10 = a6_0_10 + a6_0_7 * a7_7_10;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let a7_1_9 = a6_1_9 + a6_1_7 * a7_7_9;
let a7_1_10 = a6_1_10 + a6_1_7 * a7_7_10;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let a7_2_9 = a6_2_9 + a6_2_7 * a7_7_9;
let a7_2_10 = a6_2_10 + a6_2_7 * a7_7_10;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let a7_3_9 = a6_3_9 + a6_3_7 * a7_7_9;
let a7_3_10 = a6_3_10 + a6_3_7 * a7_7_10;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let a7_4_9 = a6_4_9 + a6_4_7 * a7_7_9;
let a7_4_10 = a6_4_10 + a6_4_7 * a7_7_10;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let a7_5_9 = a6_5_9 + a6_5_7 * a7_7_9;
let a7_5_10 = a6_5_10 + a6_5_7 * a7_7_10;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let a7_6_9 = a6_6_9 + a6_6_7 * a7_7_9;
let a7_6_10 = a6_6_10 + a6_6_7 * a7_7_10;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let a7_8_9 = a6_8_9 + a6_8_7 * a7_7_9;
let a7_8_10 = a6_8_10 + a6_8_7 * a7_7_10;
let t7_8 = t6_8 + a6_8_7 * t7_7;
let a7_9_8 = a6_9_8 + a6_9_7 * a7_7_8;
let a7_9_9 = a6_9_9 + a6_9_7 * a7_7_9;
let a7_9_10 = a6_9_10 + a6_9_7 * a7_7_10;
let t7_9 = t6_9 + a6_9_7 * t7_7;
let a7_10_8 = a6_10_8 + a6_10_7 * a7_7_8;
let a7_10_9 = a6_10_9 + a6_10_7 * a7_7_9;
let a7_10_10 = a6_10_10 + a6_10_7 * a7_7_10;
let t7_10 = t6_10 + a6_10_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), select(Scalar(0.0), abs(t7_1), b1)), select(Scalar(0.0), abs(t7_2), b2)), abs(t7_4)), abs(t7_6)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + select(Scalar(0.0), abs(t7_1), b1)) + select(Scalar(0.0), abs(t7_2), b2)) + abs(t7_4)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 16u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t7_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t7_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t7_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a7_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l7 & !dead10 & !(a7_10_10 > tol.tree_pivot * m10_10));
let l10 = l7 & !dead10;
let i10 = Scalar(1.0) / a7_10_10;
let n10 = -i10;
let t10_10 = -t7_10 * i10;
let t10_0 = t7_0 + a7_0_10 * t10_10;
let t10_1 = t7_1 + a7_1_10 * t10_10;
let t10_2 = t7_2 + a7_2_10 * t10_10;
let t10_3 = t7_3 + a7_3_10 * t10_10;
let t10_4 = t7_4 + a7_4_10 * t10_10;
let t10_5 = t7_5 + a7_5_10 * t10_10;
let t10_6 = t7_6 + a7_6_10 * t10_10;
let t10_7 = t7_7 + a7_7_10 * t10_10;
let t10_8 = t7_8 + a7_8_10 * t10_10;
let t10_9 = t7_9 + a7_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_6)), abs(t10_7)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_6)) + abs(t10_7)) + abs(t10_10));
c38 = c38 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a7_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l7 & !dead9 & !(a7_9_9 > tol.tree_pivot * m9_9));
let l9 = l7 & !dead9;
let i9 = Scalar(1.0) / a7_9_9;
let n9 = -i9;
let a9_9_10 = a7_9_10 * n9;
let t9_9 = -t7_9 * i9;
let a9_0_10 = a7_0_10 + a7_0_9 * a9_9_10;
let t9_0 = t7_0 + a7_0_9 * t9_9;
let a9_1_10 = a7_1_10 + a7_1_9 * a9_9_10;
let t9_1 = t7_1 + a7_1_9 * t9_9;
let a9_2_10 = a7_2_10 + a7_2_9 * a9_9_10;
let t9_2 = t7_2 + a7_2_9 * t9_9;
let a9_3_10 = a7_3_10 + a7_3_9 * a9_9_10;
let t9_3 = t7_3 + a7_3_9 * t9_9;
let a9_4_10 = a7_4_10 + a7_4_9 * a9_9_10;
let t9_4 = t7_4 + a7_4_9 * t9_9;
let a9_5_10 = a7_5_10 + a7_5_9 * a9_9_10;
let t9_5 = t7_5 + a7_5_9 * t9_9;
let a9_6_10 = a7_6_10 + a7_6_9 * a9_9_10;
let t9_6 = t7_6 + a7_6_9 * t9_9;
let a9_7_10 = a7_7_10 + a7_7_9 * a9_9_10;
let t9_7 = t7_7 + a7_7_9 * t9_9;
let a9_8_10 = a7_8_10 + a7_8_9 * a9_9_10;
let t9_8 = t7_8 + a7_8_9 * t9_9;
let a9_10_10 = a7_10_10 + a7_10_9 * a9_9_10;
let t9_10 = t7_10 + a7_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_4)), abs(t9_6)), abs(t9_7)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_4)) + abs(t9_6)) + abs(t9_7)) + abs(t9_9));
c22 = c22 | select(0u, 1u << (pre | 16u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_6)), abs(t10_7)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_6)) + abs(t10_7)) + abs(t10_9)) + abs(t10_10));
c54 = c54 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let a8_8_9 = a7_8_9 * n8;
let a8_8_10 = a7_8_10 * n8;
let t8_8 = -t7_8 * i8;
let a8_0_9 = a7_0_9 + a7_0_8 * a8_8_9;
let a8_0_10 = a7_0_10 + a7_0_8 * a8_8_10;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let a8_1_9 = a7_1_9 + a7_1_8 * a8_8_9;
let a8_1_10 = a7_1_10 + a7_1_8 * a8_8_10;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let a8_2_9 = a7_2_9 + a7_2_8 * a8_8_9;
let a8_2_10 = a7_2_10 + a7_2_8 * a8_8_10;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let a8_3_9 = a7_3_9 + a7_3_8 * a8_8_9;
let a8_3_10 = a7_3_10 + a7_3_8 * a8_8_10;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let a8_4_9 = a7_4_9 + a7_4_8 * a8_8_9;
let a8_4_10 = a7_4_10 + a7_4_8 * a8_8_10;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let a8_5_9 = a7_5_9 + a7_5_8 * a8_8_9;
let a8_5_10 = a7_5_10 + a7_5_8 * a8_8_10;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let a8_6_9 = a7_6_9 + a7_6_8 * a8_8_9;
let a8_6_10 = a7_6_10 + a7_6_8 * a8_8_10;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let a8_7_9 = a7_7_9 + a7_7_8 * a8_8_9;
let a8_7_10 = a7_7_10 + a7_7_8 * a8_8_10;
let t8_7 = t7_7 + a7_7_8 * t8_8;
let a8_9_9 = a7_9_9 + a7_9_8 * a8_8_9;
let a8_9_10 = a7_9_10 + a7_9_8 * a8_8_10;
let t8_9 = t7_9 + a7_9_8 * t8_8;
let a8_10_9 = a7_10_9 + a7_10_8 * a8_8_9;
let a8_10_10 = a7_10_10 + a7_10_8 * a8_8_10;
let t8_10 = t7_10 + a7_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_4)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_4)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 16u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_6)), abs(t10_7)), abs(t10_8)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_6)) + abs(t10_7)) + abs(t10_8)) + abs(t10_10));
c46 = c46 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_4)), abs(t9_6)), abs(t9_7)), abs(t9_8)), abs(t9_9));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_4)) + abs(t9_6)) + abs(t9_7)) + abs(t9_8)) + abs(t9_9));
c30 = c30 | select(0u, 1u << (pre | 16u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_6)), abs(t10_7)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_6)) + abs(t10_7)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c62 = c62 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
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
let a5_5_9 = a4_5_9 * n5;
let a5_5_10 = a4_5_10 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let a5_0_7 = a4_0_7 + a4_0_5 * a5_5_7;
let a5_0_8 = a4_0_8 + a4_0_5 * a5_5_8;
let a5_0_9 = a4_0_9 + a4_0_5 * a5_5_9;
let a5_0_10 = a4_0_10 + a4_0_5 * a5_5_10;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let a5_1_7 = a4_1_7 + a4_1_5 * a5_5_7;
let a5_1_8 = a4_1_8 + a4_1_5 * a5_5_8;
let a5_1_9 = a4_1_9 + a4_1_5 * a5_5_9;
let a5_1_10 = a4_1_10 + a4_1_5 * a5_5_10;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let a5_2_7 = a4_2_7 + a4_2_5 * a5_5_7;
let a5_2_8 = a4_2_8 + a4_2_5 * a5_5_8;
let a5_2_9 = a4_2_9 + a4_2_5 * a5_5_9;
let a5_2_10 = a4_2_10 + a4_2_5 * a5_5_10;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let a5_3_7 = a4_3_7 + a4_3_5 * a5_5_7;
let a5_3_8 = a4_3_8 + a4_3_5 * a5_5_8;
let a5_3_9 = a4_3_9 + a4_3_5 * a5_5_9;
let a5_3_10 = a4_3_10 + a4_3_5 * a5_5_10;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let a5_4_7 = a4_4_7 + a4_4_5 * a5_5_7;
let a5_4_8 = a4_4_8 + a4_4_5 * a5_5_8;
let a5_4_9 = a4_4_9 + a4_4_5 * a5_5_9;
let a5_4_10 = a4_4_10 + a4_4_5 * a5_5_10;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let a5_6_7 = a4_6_7 + a4_6_5 * a5_5_7;
let a5_6_8 = a4_6_8 + a4_6_5 * a5_5_8;
let a5_6_9 = a4_6_9 + a4_6_5 * a5_5_9;
let a5_6_10 = a4_6_10 + a4_6_5 * a5_5_10;
let t5_6 = t4_6 + a4_6_5 * t5_5;
let a5_7_6 = a4_7_6 + a4_7_5 * a5_5_6;
let a5_7_7 = a4_7_7 + a4_7_5 * a5_5_7;
let a5_7_8 = a4_7_8 + a4_7_5 * a5_5_8;
let a5_7_9 = a4_7_9 + a4_7_5 * a5_5_9;
let a5_7_10 = a4_7_10 + a4_7_5 * a5_5_10;
let t5_7 = t4_7 + a4_7_5 * t5_5;
let a5_8_6 = a4_8_6 + a4_8_5 * a5_5_6;
let a5_8_7 = a4_8_7 + a4_8_5 * a5_5_7;
let a5_8_8 = a4_8_8 + a4_8_5 * a5_5_8;
let a5_8_9 = a4_8_9 + a4_8_5 * a5_5_9;
let a5_8_10 = a4_8_10 + a4_8_5 * a5_5_10;
let t5_8 = t4_8 + a4_8_5 * t5_5;
let a5_9_6 = a4_9_6 + a4_9_5 * a5_5_6;
let a5_9_7 = a4_9_7 + a4_9_5 * a5_5_7;
let a5_9_8 = a4_9_8 + a4_9_5 * a5_5_8;
let a5_9_9 = a4_9_9 + a4_9_5 * a5_5_9;
let a5_9_10 = a4_9_10 + a4_9_5 * a5_5_10;
let t5_9 = t4_9 + a4_9_5 * t5_5;
let a5_10_6 = a4_10_6 + a4_10_5 * a5_5_6;
let a5_10_7 = a4_10_7 + a4_10_5 * a5_5_7;
let a5_10_8 = a4_10_8 + a4_10_5 * a5_5_8;
let a5_10_9 = a4_10_9 + a4_10_5 * a5_5_9;
let a5_10_10 = a4_10_10 + a4_10_5 * a5_5_10;
let t5_10 = t4_10 + a4_10_5 * t5_5;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), select(Scalar(0.0), abs(t5_1), b1)), select(Scalar(0.0), abs(t5_2), b2)), abs(t5_4)), abs(t5_5));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + select(Scalar(0.0), abs(t5_1), b1)) + select(Scalar(0.0), abs(t5_2), b2)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 16u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t5_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t5_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t5_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a5_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l5 & !dead10 & !(a5_10_10 > tol.tree_pivot * m10_10));
let l10 = l5 & !dead10;
let i10 = Scalar(1.0) / a5_10_10;
let n10 = -i10;
let t10_10 = -t5_10 * i10;
let t10_0 = t5_0 + a5_0_10 * t10_10;
let t10_1 = t5_1 + a5_1_10 * t10_10;
let t10_2 = t5_2 + a5_2_10 * t10_10;
let t10_3 = t5_3 + a5_3_10 * t10_10;
let t10_4 = t5_4 + a5_4_10 * t10_10;
let t10_5 = t5_5 + a5_5_10 * t10_10;
let t10_6 = t5_6 + a5_6_10 * t10_10;
let t10_7 = t5_7 + a5_7_10 * t10_10;
let t10_8 = t5_8 + a5_8_10 * t10_10;
let t10_9 = t5_9 + a5_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_5)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_5)) + abs(t10_10));
c33 = c33 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a5_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l5 & !dead9 & !(a5_9_9 > tol.tree_pivot * m9_9));
let l9 = l5 & !dead9;
let i9 = Scalar(1.0) / a5_9_9;
let n9 = -i9;
let a9_9_10 = a5_9_10 * n9;
let t9_9 = -t5_9 * i9;
let a9_0_10 = a5_0_10 + a5_0_9 * a9_9_10;
let t9_0 = t5_0 + a5_0_9 * t9_9;
let a9_1_10 = a5_1_10 + a5_1_9 * a9_9_10;
let t9_1 = t5_1 + a5_1_9 * t9_9;
let a9_2_10 = a5_2_10 + a5_2_9 * a9_9_10;
let t9_2 = t5_2 + a5_2_9 * t9_9;
let a9_3_10 = a5_3_10 + a5_3_9 * a9_9_10;
let t9_3 = t5_3 + a5_3_9 * t9_9;
let a9_4_10 = a5_4_10 + a5_4_9 * a9_9_10;
let t9_4 = t5_4 + a5_4_9 * t9_9;
let a9_5_10 = a5_5_10 + a5_5_9 * a9_9_10;
let t9_5 = t5_5 + a5_5_9 * t9_9;
let a9_6_10 = a5_6_10 + a5_6_9 * a9_9_10;
let t9_6 = t5_6 + a5_6_9 * t9_9;
let a9_7_10 = a5_7_10 + a5_7_9 * a9_9_10;
let t9_7 = t5_7 + a5_7_9 * t9_9;
let a9_8_10 = a5_8_10 + a5_8_9 * a9_9_10;
let t9_8 = t5_8 + a5_8_9 * t9_9;
let a9_10_10 = a5_10_10 + a5_10_9 * a9_9_10;
let t9_10 = t5_10 + a5_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_4)), abs(t9_5)), abs(t9_9));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_4)) + abs(t9_5)) + abs(t9_9));
c17 = c17 | select(0u, 1u << (pre | 16u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_5)), abs(t10_9)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_5)) + abs(t10_9)) + abs(t10_10));
c49 = c49 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let a8_8_9 = a5_8_9 * n8;
let a8_8_10 = a5_8_10 * n8;
let t8_8 = -t5_8 * i8;
let a8_0_9 = a5_0_9 + a5_0_8 * a8_8_9;
let a8_0_10 = a5_0_10 + a5_0_8 * a8_8_10;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let a8_1_9 = a5_1_9 + a5_1_8 * a8_8_9;
let a8_1_10 = a5_1_10 + a5_1_8 * a8_8_10;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let a8_2_9 = a5_2_9 + a5_2_8 * a8_8_9;
let a8_2_10 = a5_2_10 + a5_2_8 * a8_8_10;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let a8_3_9 = a5_3_9 + a5_3_8 * a8_8_9;
let a8_3_10 = a5_3_10 + a5_3_8 * a8_8_10;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let a8_4_9 = a5_4_9 + a5_4_8 * a8_8_9;
let a8_4_10 = a5_4_10 + a5_4_8 * a8_8_10;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let a8_5_9 = a5_5_9 + a5_5_8 * a8_8_9;
let a8_5_10 = a5_5_10 + a5_5_8 * a8_8_10;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let a8_6_9 = a5_6_9 + a5_6_8 * a8_8_9;
let a8_6_10 = a5_6_10 + a5_6_8 * a8_8_10;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let a8_7_9 = a5_7_9 + a5_7_8 * a8_8_9;
let a8_7_10 = a5_7_10 + a5_7_8 * a8_8_10;
let t8_7 = t5_7 + a5_7_8 * t8_8;
let a8_9_9 = a5_9_9 + a5_9_8 * a8_8_9;
let a8_9_10 = a5_9_10 + a5_9_8 * a8_8_10;
let t8_9 = t5_9 + a5_9_8 * t8_8;
let a8_10_9 = a5_10_9 + a5_10_8 * a8_8_9;
let a8_10_10 = a5_10_10 + a5_10_8 * a8_8_10;
let t8_10 = t5_10 + a5_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_4)), abs(t8_5)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_4)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 16u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_5)), abs(t10_8)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_5)) + abs(t10_8)) + abs(t10_10));
c41 = c41 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_4)), abs(t9_5)), abs(t9_8)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_4)) + abs(t9_5)) + abs(t9_8)) + abs(t9_9));
c25 = c25 | select(0u, 1u << (pre | 16u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_5)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_5)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c57 = c57 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let a7_7_9 = a5_7_9 * n7;
let a7_7_10 = a5_7_10 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let a7_0_9 = a5_0_9 + a5_0_7 * a7_7_9;
let a7_0_10 = a5_0_10 + a5_0_7 * a7_7_10;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let a7_1_9 = a5_1_9 + a5_1_7 * a7_7_9;
let a7_1_10 = a5_1_10 + a5_1_7 * a7_7_10;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let a7_2_9 = a5_2_9 + a5_2_7 * a7_7_9;
let a7_2_10 = a5_2_10 + a5_2_7 * a7_7_10;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let a7_3_9 = a5_3_9 + a5_3_7 * a7_7_9;
let a7_3_10 = a5_3_10 + a5_3_7 * a7_7_10;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let a7_4_9 = a5_4_9 + a5_4_7 * a7_7_9;
let a7_4_10 = a5_4_10 + a5_4_7 * a7_7_10;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let a7_5_9 = a5_5_9 + a5_5_7 * a7_7_9;
let a7_5_10 = a5_5_10 + a5_5_7 * a7_7_10;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let a7_6_9 = a5_6_9 + a5_6_7 * a7_7_9;
let a7_6_10 = a5_6_10 + a5_6_7 * a7_7_10;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let a7_8_9 = a5_8_9 + a5_8_7 * a7_7_9;
let a7_8_10 = a5_8_10 + a5_8_7 * a7_7_10;
let t7_8 = t5_8 + a5_8_7 * t7_7;
let a7_9_8 = a5_9_8 + a5_9_7 * a7_7_8;
let a7_9_9 = a5_9_9 + a5_9_7 * a7_7_9;
let a7_9_10 = a5_9_10 + a5_9_7 * a7_7_10;
let t7_9 = t5_9 + a5_9_7 * t7_7;
let a7_10_8 = a5_10_8 + a5_10_7 * a7_7_8;
let a7_10_9 = a5_10_9 + a5_10_7 * a7_7_9;
let a7_10_10 = a5_10_10 + a5_10_7 * a7_7_10;
let t7_10 = t5_10 + a5_10_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), select(Scalar(0.0), abs(t7_1), b1)), select(Scalar(0.0), abs(t7_2), b2)), abs(t7_4)), abs(t7_5)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + select(Scalar(0.0), abs(t7_1), b1)) + select(Scalar(0.0), abs(t7_2), b2)) + abs(t7_4)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 16u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t7_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t7_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t7_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a7_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l7 & !dead10 & !(a7_10_10 > tol.tree_pivot * m10_10));
let l10 = l7 & !dead10;
let i10 = Scalar(1.0) / a7_10_10;
let n10 = -i10;
let t10_10 = -t7_10 * i10;
let t10_0 = t7_0 + a7_0_10 * t10_10;
let t10_1 = t7_1 + a7_1_10 * t10_10;
let t10_2 = t7_2 + a7_2_10 * t10_10;
let t10_3 = t7_3 + a7_3_10 * t10_10;
let t10_4 = t7_4 + a7_4_10 * t10_10;
let t10_5 = t7_5 + a7_5_10 * t10_10;
let t10_6 = t7_6 + a7_6_10 * t10_10;
let t10_7 = t7_7 + a7_7_10 * t10_10;
let t10_8 = t7_8 + a7_8_10 * t10_10;
let t10_9 = t7_9 + a7_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_5)), abs(t10_7)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_5)) + abs(t10_7)) + abs(t10_10));
c37 = c37 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a7_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l7 & !dead9 & !(a7_9_9 > tol.tree_pivot * m9_9));
let l9 = l7 & !dead9;
let i9 = Scalar(1.0) / a7_9_9;
let n9 = -i9;
let a9_9_10 = a7_9_10 * n9;
let t9_9 = -t7_9 * i9;
let a9_0_10 = a7_0_10 + a7_0_9 * a9_9_10;
let t9_0 = t7_0 + a7_0_9 * t9_9;
let a9_1_10 = a7_1_10 + a7_1_9 * a9_9_10;
let t9_1 = t7_1 + a7_1_9 * t9_9;
let a9_2_10 = a7_2_10 + a7_2_9 * a9_9_10;
let t9_2 = t7_2 + a7_2_9 * t9_9;
let a9_3_10 = a7_3_10 + a7_3_9 * a9_9_10;
let t9_3 = t7_3 + a7_3_9 * t9_9;
let a9_4_10 = a7_4_10 + a7_4_9 * a9_9_10;
let t9_4 = t7_4 + a7_4_9 * t9_9;
let a9_5_10 = a7_5_10 + a7_5_9 * a9_9_10;
let t9_5 = t7_5 + a7_5_9 * t9_9;
let a9_6_10 = a7_6_10 + a7_6_9 * a9_9_10;
let t9_6 = t7_6 + a7_6_9 * t9_9;
let a9_7_10 = a7_7_10 + a7_7_9 * a9_9_10;
let t9_7 = t7_7 + a7_7_9 * t9_9;
let a9_8_10 = a7_8_10 + a7_8_9 * a9_9_10;
let t9_8 = t7_8 + a7_8_9 * t9_9;
let a9_10_10 = a7_10_10 + a7_10_9 * a9_9_10;
let t9_10 = t7_10 + a7_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_4)), abs(t9_5)), abs(t9_7)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_4)) + abs(t9_5)) + abs(t9_7)) + abs(t9_9));
c21 = c21 | select(0u, 1u << (pre | 16u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_5)), abs(t10_7)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_5)) + abs(t10_7)) + abs(t10_9)) + abs(t10_10));
c53 = c53 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let a8_8_9 = a7_8_9 * n8;
let a8_8_10 = a7_8_10 * n8;
let t8_8 = -t7_8 * i8;
let a8_0_9 = a7_0_9 + a7_0_8 * a8_8_9;
let a8_0_10 = a7_0_10 + a7_0_8 * a8_8_10;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let a8_1_9 = a7_1_9 + a7_1_8 * a8_8_9;
let a8_1_10 = a7_1_10 + a7_1_8 * a8_8_10;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let a8_2_9 = a7_2_9 + a7_2_8 * a8_8_9;
let a8_2_10 = a7_2_10 + a7_2_8 * a8_8_10;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let a8_3_9 = a7_3_9 + a7_3_8 * a8_8_9;
let a8_3_10 = a7_3_10 + a7_3_8 * a8_8_10;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let a8_4_9 = a7_4_9 + a7_4_8 * a8_8_9;
let a8_4_10 = a7_4_10 + a7_4_8 * a8_8_10;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let a8_5_9 = a7_5_9 + a7_5_8 * a8_8_9;
let a8_5_10 = a7_5_10 + a7_5_8 * a8_8_10;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let a8_6_9 = a7_6_9 + a7_6_8 * a8_8_9;
let a8_6_10 = a7_6_10 + a7_6_8 * a8_8_10;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let a8_7_9 = a7_7_9 + a7_7_8 * a8_8_9;
let a8_7_10 = a7_7_10 + a7_7_8 * a8_8_10;
let t8_7 = t7_7 + a7_7_8 * t8_8;
let a8_9_9 = a7_9_9 + a7_9_8 * a8_8_9;
let a8_9_10 = a7_9_10 + a7_9_8 * a8_8_10;
let t8_9 = t7_9 + a7_9_8 * t8_8;
let a8_10_9 = a7_10_9 + a7_10_8 * a8_8_9;
let a8_10_10 = a7_10_10 + a7_10_8 * a8_8_10;
let t8_10 = t7_10 + a7_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_4)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_4)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 16u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_5)), abs(t10_7)), abs(t10_8)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_5)) + abs(t10_7)) + abs(t10_8)) + abs(t10_10));
c45 = c45 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_4)), abs(t9_5)), abs(t9_7)), abs(t9_8)), abs(t9_9));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_4)) + abs(t9_5)) + abs(t9_7)) + abs(t9_8)) + abs(t9_9));
c29 = c29 | select(0u, 1u << (pre | 16u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_5)), abs(t10_7)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_5)) + abs(t10_7)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c61 = c61 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
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
let a6_6_9 = a5_6_9 * n6;
let a6_6_10 = a5_6_10 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let a6_0_9 = a5_0_9 + a5_0_6 * a6_6_9;
let a6_0_10 = a5_0_10 + a5_0_6 * a6_6_10;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let a6_1_9 = a5_1_9 + a5_1_6 * a6_6_9;
let a6_1_10 = a5_1_10 + a5_1_6 * a6_6_10;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let a6_2_9 = a5_2_9 + a5_2_6 * a6_6_9;
let a6_2_10 = a5_2_10 + a5_2_6 * a6_6_10;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let a6_3_9 = a5_3_9 + a5_3_6 * a6_6_9;
let a6_3_10 = a5_3_10 + a5_3_6 * a6_6_10;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let a6_4_9 = a5_4_9 + a5_4_6 * a6_6_9;
let a6_4_10 = a5_4_10 + a5_4_6 * a6_6_10;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let a6_5_9 = a5_5_9 + a5_5_6 * a6_6_9;
let a6_5_10 = a5_5_10 + a5_5_6 * a6_6_10;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let a6_7_9 = a5_7_9 + a5_7_6 * a6_6_9;
let a6_7_10 = a5_7_10 + a5_7_6 * a6_6_10;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let a6_8_9 = a5_8_9 + a5_8_6 * a6_6_9;
let a6_8_10 = a5_8_10 + a5_8_6 * a6_6_10;
let t6_8 = t5_8 + a5_8_6 * t6_6;
let a6_9_7 = a5_9_7 + a5_9_6 * a6_6_7;
let a6_9_8 = a5_9_8 + a5_9_6 * a6_6_8;
let a6_9_9 = a5_9_9 + a5_9_6 * a6_6_9;
let a6_9_10 = a5_9_10 + a5_9_6 * a6_6_10;
let t6_9 = t5_9 + a5_9_6 * t6_6;
let a6_10_7 = a5_10_7 + a5_10_6 * a6_6_7;
let a6_10_8 = a5_10_8 + a5_10_6 * a6_6_8;
let a6_10_9 = a5_10_9 + a5_10_6 * a6_6_9;
let a6_10_10 = a5_10_10 + a5_10_6 * a6_6_10;
let t6_10 = t5_10 + a5_10_6 * t6_6;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), select(Scalar(0.0), abs(t6_1), b1)), select(Scalar(0.0), abs(t6_2), b2)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + select(Scalar(0.0), abs(t6_1), b1)) + select(Scalar(0.0), abs(t6_2), b2)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 16u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t6_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t6_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t6_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a6_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l6 & !dead10 & !(a6_10_10 > tol.tree_pivot * m10_10));
let l10 = l6 & !dead10;
let i10 = Scalar(1.0) / a6_10_10;
let n10 = -i10;
let t10_10 = -t6_10 * i10;
let t10_0 = t6_0 + a6_0_10 * t10_10;
let t10_1 = t6_1 + a6_1_10 * t10_10;
let t10_2 = t6_2 + a6_2_10 * t10_10;
let t10_3 = t6_3 + a6_3_10 * t10_10;
let t10_4 = t6_4 + a6_4_10 * t10_10;
let t10_5 = t6_5 + a6_5_10 * t10_10;
let t10_6 = t6_6 + a6_6_10 * t10_10;
let t10_7 = t6_7 + a6_7_10 * t10_10;
let t10_8 = t6_8 + a6_8_10 * t10_10;
let t10_9 = t6_9 + a6_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_5)), abs(t10_6)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_5)) + abs(t10_6)) + abs(t10_10));
c35 = c35 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a6_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l6 & !dead9 & !(a6_9_9 > tol.tree_pivot * m9_9));
let l9 = l6 & !dead9;
let i9 = Scalar(1.0) / a6_9_9;
let n9 = -i9;
let a9_9_10 = a6_9_10 * n9;
let t9_9 = -t6_9 * i9;
let a9_0_10 = a6_0_10 + a6_0_9 * a9_9_10;
let t9_0 = t6_0 + a6_0_9 * t9_9;
let a9_1_10 = a6_1_10 + a6_1_9 * a9_9_10;
let t9_1 = t6_1 + a6_1_9 * t9_9;
let a9_2_10 = a6_2_10 + a6_2_9 * a9_9_10;
let t9_2 = t6_2 + a6_2_9 * t9_9;
let a9_3_10 = a6_3_10 + a6_3_9 * a9_9_10;
let t9_3 = t6_3 + a6_3_9 * t9_9;
let a9_4_10 = a6_4_10 + a6_4_9 * a9_9_10;
let t9_4 = t6_4 + a6_4_9 * t9_9;
let a9_5_10 = a6_5_10 + a6_5_9 * a9_9_10;
let t9_5 = t6_5 + a6_5_9 * t9_9;
let a9_6_10 = a6_6_10 + a6_6_9 * a9_9_10;
let t9_6 = t6_6 + a6_6_9 * t9_9;
let a9_7_10 = a6_7_10 + a6_7_9 * a9_9_10;
let t9_7 = t6_7 + a6_7_9 * t9_9;
let a9_8_10 = a6_8_10 + a6_8_9 * a9_9_10;
let t9_8 = t6_8 + a6_8_9 * t9_9;
let a9_10_10 = a6_10_10 + a6_10_9 * a9_9_10;
let t9_10 = t6_10 + a6_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_4)), abs(t9_5)), abs(t9_6)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_4)) + abs(t9_5)) + abs(t9_6)) + abs(t9_9));
c19 = c19 | select(0u, 1u << (pre | 16u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_5)), abs(t10_6)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_5)) + abs(t10_6)) + abs(t10_9)) + abs(t10_10));
c51 = c51 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let a8_8_9 = a6_8_9 * n8;
let a8_8_10 = a6_8_10 * n8;
let t8_8 = -t6_8 * i8;
let a8_0_9 = a6_0_9 + a6_0_8 * a8_8_9;
let a8_0_10 = a6_0_10 + a6_0_8 * a8_8_10;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let a8_1_9 = a6_1_9 + a6_1_8 * a8_8_9;
let a8_1_10 = a6_1_10 + a6_1_8 * a8_8_10;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let a8_2_9 = a6_2_9 + a6_2_8 * a8_8_9;
let a8_2_10 = a6_2_10 + a6_2_8 * a8_8_10;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let a8_3_9 = a6_3_9 + a6_3_8 * a8_8_9;
let a8_3_10 = a6_3_10 + a6_3_8 * a8_8_10;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let a8_4_9 = a6_4_9 + a6_4_8 * a8_8_9;
let a8_4_10 = a6_4_10 + a6_4_8 * a8_8_10;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let a8_5_9 = a6_5_9 + a6_5_8 * a8_8_9;
let a8_5_10 = a6_5_10 + a6_5_8 * a8_8_10;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let a8_6_9 = a6_6_9 + a6_6_8 * a8_8_9;
let a8_6_10 = a6_6_10 + a6_6_8 * a8_8_10;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let a8_7_9 = a6_7_9 + a6_7_8 * a8_8_9;
let a8_7_10 = a6_7_10 + a6_7_8 * a8_8_10;
let t8_7 = t6_7 + a6_7_8 * t8_8;
let a8_9_9 = a6_9_9 + a6_9_8 * a8_8_9;
let a8_9_10 = a6_9_10 + a6_9_8 * a8_8_10;
let t8_9 = t6_9 + a6_9_8 * t8_8;
let a8_10_9 = a6_10_9 + a6_10_8 * a8_8_9;
let a8_10_10 = a6_10_10 + a6_10_8 * a8_8_10;
let t8_10 = t6_10 + a6_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 16u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_5)), abs(t10_6)), abs(t10_8)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_5)) + abs(t10_6)) + abs(t10_8)) + abs(t10_10));
c43 = c43 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_4)), abs(t9_5)), abs(t9_6)), abs(t9_8)), abs(t9_9));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_4)) + abs(t9_5)) + abs(t9_6)) + abs(t9_8)) + abs(t9_9));
c27 = c27 | select(0u, 1u << (pre | 16u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_5)), abs(t10_6)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_5)) + abs(t10_6)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c59 = c59 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let a7_7_9 = a6_7_9 * n7;
let a7_7_10 = a6_7_10 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let a7_0_9 = a6_0_9 + a6_0_7 * a7_7_9;
let a7_0_10 = a6_0_10 + a6_0_7 * a7_7_10;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let a7_1_9 = a6_1_9 + a6_1_7 * a7_7_9;
let a7_1_10 = a6_1_10 + a6_1_7 * a7_7_10;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let a7_2_9 = a6_2_9 + a6_2_7 * a7_7_9;
let a7_2_10 = a6_2_10 + a6_2_7 * a7_7_10;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let a7_3_9 = a6_3_9 + a6_3_7 * a7_7_9;
let a7_3_10 = a6_3_10 + a6_3_7 * a7_7_10;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let a7_4_9 = a6_4_9 + a6_4_7 * a7_7_9;
let a7_4_10 = a6_4_10 + a6_4_7 * a7_7_10;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let a7_5_9 = a6_5_9 + a6_5_7 * a7_7_9;
let a7_5_10 = a6_5_10 + a6_5_7 * a7_7_10;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let a7_6_9 = a6_6_9 + a6_6_7 * a7_7_9;
let a7_6_10 = a6_6_10 + a6_6_7 * a7_7_10;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let a7_8_9 = a6_8_9 + a6_8_7 * a7_7_9;
let a7_8_10 = a6_8_10 + a6_8_7 * a7_7_10;
let t7_8 = t6_8 + a6_8_7 * t7_7;
let a7_9_8 = a6_9_8 + a6_9_7 * a7_7_8;
let a7_9_9 = a6_9_9 + a6_9_7 * a7_7_9;
let a7_9_10 = a6_9_10 + a6_9_7 * a7_7_10;
let t7_9 = t6_9 + a6_9_7 * t7_7;
let a7_10_8 = a6_10_8 + a6_10_7 * a7_7_8;
let a7_10_9 = a6_10_9 + a6_10_7 * a7_7_9;
let a7_10_10 = a6_10_10 + a6_10_7 * a7_7_10;
let t7_10 = t6_10 + a6_10_7 * t7_7;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), select(Scalar(0.0), abs(t7_1), b1)), select(Scalar(0.0), abs(t7_2), b2)), abs(t7_4)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + select(Scalar(0.0), abs(t7_1), b1)) + select(Scalar(0.0), abs(t7_2), b2)) + abs(t7_4)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 16u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t7_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t7_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t7_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t7_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a7_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l7 & !dead10 & !(a7_10_10 > tol.tree_pivot * m10_10));
let l10 = l7 & !dead10;
let i10 = Scalar(1.0) / a7_10_10;
let n10 = -i10;
let t10_10 = -t7_10 * i10;
let t10_0 = t7_0 + a7_0_10 * t10_10;
let t10_1 = t7_1 + a7_1_10 * t10_10;
let t10_2 = t7_2 + a7_2_10 * t10_10;
let t10_3 = t7_3 + a7_3_10 * t10_10;
let t10_4 = t7_4 + a7_4_10 * t10_10;
let t10_5 = t7_5 + a7_5_10 * t10_10;
let t10_6 = t7_6 + a7_6_10 * t10_10;
let t10_7 = t7_7 + a7_7_10 * t10_10;
let t10_8 = t7_8 + a7_8_10 * t10_10;
let t10_9 = t7_9 + a7_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_5)), abs(t10_6)), abs(t10_7)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_5)) + abs(t10_6)) + abs(t10_7)) + abs(t10_10));
c39 = c39 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a7_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l7 & !dead9 & !(a7_9_9 > tol.tree_pivot * m9_9));
let l9 = l7 & !dead9;
let i9 = Scalar(1.0) / a7_9_9;
let n9 = -i9;
let a9_9_10 = a7_9_10 * n9;
let t9_9 = -t7_9 * i9;
let a9_0_10 = a7_0_10 + a7_0_9 * a9_9_10;
let t9_0 = t7_0 + a7_0_9 * t9_9;
let a9_1_10 = a7_1_10 + a7_1_9 * a9_9_10;
let t9_1 = t7_1 + a7_1_9 * t9_9;
let a9_2_10 = a7_2_10 + a7_2_9 * a9_9_10;
let t9_2 = t7_2 + a7_2_9 * t9_9;
let a9_3_10 = a7_3_10 + a7_3_9 * a9_9_10;
let t9_3 = t7_3 + a7_3_9 * t9_9;
let a9_4_10 = a7_4_10 + a7_4_9 * a9_9_10;
let t9_4 = t7_4 + a7_4_9 * t9_9;
let a9_5_10 = a7_5_10 + a7_5_9 * a9_9_10;
let t9_5 = t7_5 + a7_5_9 * t9_9;
let a9_6_10 = a7_6_10 + a7_6_9 * a9_9_10;
let t9_6 = t7_6 + a7_6_9 * t9_9;
let a9_7_10 = a7_7_10 + a7_7_9 * a9_9_10;
let t9_7 = t7_7 + a7_7_9 * t9_9;
let a9_8_10 = a7_8_10 + a7_8_9 * a9_9_10;
let t9_8 = t7_8 + a7_8_9 * t9_9;
let a9_10_10 = a7_10_10 + a7_10_9 * a9_9_10;
let t9_10 = t7_10 + a7_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_4)), abs(t9_5)), abs(t9_6)), abs(t9_7)), abs(t9_9));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_4)) + abs(t9_5)) + abs(t9_6)) + abs(t9_7)) + abs(t9_9));
c23 = c23 | select(0u, 1u << (pre | 16u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_5)), abs(t10_6)), abs(t10_7)), abs(t10_9)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_5)) + abs(t10_6)) + abs(t10_7)) + abs(t10_9)) + abs(t10_10));
c55 = c55 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let a8_8_9 = a7_8_9 * n8;
let a8_8_10 = a7_8_10 * n8;
let t8_8 = -t7_8 * i8;
let a8_0_9 = a7_0_9 + a7_0_8 * a8_8_9;
let a8_0_10 = a7_0_10 + a7_0_8 * a8_8_10;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let a8_1_9 = a7_1_9 + a7_1_8 * a8_8_9;
let a8_1_10 = a7_1_10 + a7_1_8 * a8_8_10;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let a8_2_9 = a7_2_9 + a7_2_8 * a8_8_9;
let a8_2_10 = a7_2_10 + a7_2_8 * a8_8_10;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let a8_3_9 = a7_3_9 + a7_3_8 * a8_8_9;
let a8_3_10 = a7_3_10 + a7_3_8 * a8_8_10;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let a8_4_9 = a7_4_9 + a7_4_8 * a8_8_9;
let a8_4_10 = a7_4_10 + a7_4_8 * a8_8_10;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let a8_5_9 = a7_5_9 + a7_5_8 * a8_8_9;
let a8_5_10 = a7_5_10 + a7_5_8 * a8_8_10;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let a8_6_9 = a7_6_9 + a7_6_8 * a8_8_9;
let a8_6_10 = a7_6_10 + a7_6_8 * a8_8_10;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let a8_7_9 = a7_7_9 + a7_7_8 * a8_8_9;
let a8_7_10 = a7_7_10 + a7_7_8 * a8_8_10;
let t8_7 = t7_7 + a7_7_8 * t8_8;
let a8_9_9 = a7_9_9 + a7_9_8 * a8_8_9;
let a8_9_10 = a7_9_10 + a7_9_8 * a8_8_10;
let t8_9 = t7_9 + a7_9_8 * t8_8;
let a8_10_9 = a7_10_9 + a7_10_8 * a8_8_9;
let a8_10_10 = a7_10_10 + a7_10_8 * a8_8_10;
let t8_10 = t7_10 + a7_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 16u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_5)), abs(t10_6)), abs(t10_7)), abs(t10_8)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_5)) + abs(t10_6)) + abs(t10_7)) + abs(t10_8)) + abs(t10_10));
c47 = c47 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_4)), abs(t9_5)), abs(t9_6)), abs(t9_7)), abs(t9_8)), abs(t9_9));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_4)) + abs(t9_5)) + abs(t9_6)) + abs(t9_7)) + abs(t9_8)) + abs(t9_9));
c31 = c31 | select(0u, 1u << (pre | 16u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_4)), abs(t10_5)), abs(t10_6)), abs(t10_7)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = ((((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_4)) + abs(t10_5)) + abs(t10_6)) + abs(t10_7)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c63 = c63 | select(0u, 1u << (pre | 16u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
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
let a3_3_9 = x3_9 * n3;
let a3_3_10 = x3_10 * n3;
let t3_3 = -y3 * i3;
let a3_0_4 = x0_4 + x0_3 * a3_3_4;
let a3_0_5 = x0_5 + x0_3 * a3_3_5;
let a3_0_6 = x0_6 + x0_3 * a3_3_6;
let a3_0_7 = x0_7 + x0_3 * a3_3_7;
let a3_0_8 = x0_8 + x0_3 * a3_3_8;
let a3_0_9 = x0_9 + x0_3 * a3_3_9;
let a3_0_10 = x0_10 + x0_3 * a3_3_10;
let t3_0 = y0 + x0_3 * t3_3;
let a3_1_4 = x1_4 + x1_3 * a3_3_4;
let a3_1_5 = x1_5 + x1_3 * a3_3_5;
let a3_1_6 = x1_6 + x1_3 * a3_3_6;
let a3_1_7 = x1_7 + x1_3 * a3_3_7;
let a3_1_8 = x1_8 + x1_3 * a3_3_8;
let a3_1_9 = x1_9 + x1_3 * a3_3_9;
let a3_1_10 = x1_10 + x1_3 * a3_3_10;
let t3_1 = y1 + x1_3 * t3_3;
let a3_2_4 = x2_4 + x2_3 * a3_3_4;
let a3_2_5 = x2_5 + x2_3 * a3_3_5;
let a3_2_6 = x2_6 + x2_3 * a3_3_6;
let a3_2_7 = x2_7 + x2_3 * a3_3_7;
let a3_2_8 = x2_8 + x2_3 * a3_3_8;
let a3_2_9 = x2_9 + x2_3 * a3_3_9;
let a3_2_10 = x2_10 + x2_3 * a3_3_10;
let t3_2 = y2 + x2_3 * t3_3;
let a3_4_4 = x4_4 + x4_3 * a3_3_4;
let a3_4_5 = x4_5 + x4_3 * a3_3_5;
let a3_4_6 = x4_6 + x4_3 * a3_3_6;
let a3_4_7 = x4_7 + x4_3 * a3_3_7;
let a3_4_8 = x4_8 + x4_3 * a3_3_8;
let a3_4_9 = x4_9 + x4_3 * a3_3_9;
let a3_4_10 = x4_10 + x4_3 * a3_3_10;
let t3_4 = y4 + x4_3 * t3_3;
let a3_5_4 = x5_4 + x5_3 * a3_3_4;
let a3_5_5 = x5_5 + x5_3 * a3_3_5;
let a3_5_6 = x5_6 + x5_3 * a3_3_6;
let a3_5_7 = x5_7 + x5_3 * a3_3_7;
let a3_5_8 = x5_8 + x5_3 * a3_3_8;
let a3_5_9 = x5_9 + x5_3 * a3_3_9;
let a3_5_10 = x5_10 + x5_3 * a3_3_10;
let t3_5 = y5 + x5_3 * t3_3;
let a3_6_4 = x6_4 + x6_3 * a3_3_4;
let a3_6_5 = x6_5 + x6_3 * a3_3_5;
let a3_6_6 = x6_6 + x6_3 * a3_3_6;
let a3_6_7 = x6_7 + x6_3 * a3_3_7;
let a3_6_8 = x6_8 + x6_3 * a3_3_8;
let a3_6_9 = x6_9 + x6_3 * a3_3_9;
let a3_6_10 = x6_10 + x6_3 * a3_3_10;
let t3_6 = y6 + x6_3 * t3_3;
let a3_7_4 = x7_4 + x7_3 * a3_3_4;
let a3_7_5 = x7_5 + x7_3 * a3_3_5;
let a3_7_6 = x7_6 + x7_3 * a3_3_6;
let a3_7_7 = x7_7 + x7_3 * a3_3_7;
let a3_7_8 = x7_8 + x7_3 * a3_3_8;
let a3_7_9 = x7_9 + x7_3 * a3_3_9;
let a3_7_10 = x7_10 + x7_3 * a3_3_10;
let t3_7 = y7 + x7_3 * t3_3;
let a3_8_4 = x8_4 + x8_3 * a3_3_4;
let a3_8_5 = x8_5 + x8_3 * a3_3_5;
let a3_8_6 = x8_6 + x8_3 * a3_3_6;
let a3_8_7 = x8_7 + x8_3 * a3_3_7;
let a3_8_8 = x8_8 + x8_3 * a3_3_8;
let a3_8_9 = x8_9 + x8_3 * a3_3_9;
let a3_8_10 = x8_10 + x8_3 * a3_3_10;
let t3_8 = y8 + x8_3 * t3_3;
let a3_9_4 = x9_4 + x9_3 * a3_3_4;
let a3_9_5 = x9_5 + x9_3 * a3_3_5;
let a3_9_6 = x9_6 + x9_3 * a3_3_6;
let a3_9_7 = x9_7 + x9_3 * a3_3_7;
let a3_9_8 = x9_8 + x9_3 * a3_3_8;
let a3_9_9 = x9_9 + x9_3 * a3_3_9;
let a3_9_10 = x9_10 + x9_3 * a3_3_10;
let t3_9 = y9 + x9_3 * t3_3;
let a3_10_4 = x10_4 + x10_3 * a3_3_4;
let a3_10_5 = x10_5 + x10_3 * a3_3_5;
let a3_10_6 = x10_6 + x10_3 * a3_3_6;
let a3_10_7 = x10_7 + x10_3 * a3_3_7;
let a3_10_8 = x10_8 + x10_3 * a3_3_8;
let a3_10_9 = x10_9 + x10_3 * a3_3_9;
let a3_10_10 = x10_10 + x10_3 * a3_3_10;
let t3_10 = y10 + x10_3 * t3_3;
{
let zm = max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t3_0), b0)), select(Scalar(0.0), abs(t3_1), b1)), select(Scalar(0.0), abs(t3_2), b2)), abs(t3_3));
let zs = ((((Scalar(0.0) + select(Scalar(0.0), abs(t3_0), b0)) + select(Scalar(0.0), abs(t3_1), b1)) + select(Scalar(0.0), abs(t3_2), b2)) + abs(t3_3));
c0 = c0 | select(0u, 1u << (pre | 8u), l3 & (t3_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t3_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t3_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t3_3 >= -tol.screen * zm) & (t3_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t3_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t3_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t3_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t3_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t3_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t3_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a3_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l3 & !dead10 & !(a3_10_10 > tol.tree_pivot * m10_10));
let l10 = l3 & !dead10;
let i10 = Scalar(1.0) / a3_10_10;
let n10 = -i10;
let t10_10 = -t3_10 * i10;
let t10_0 = t3_0 + a3_0_10 * t10_10;
let t10_1 = t3_1 + a3_1_10 * t10_10;
let t10_2 = t3_2 + a3_2_10 * t10_10;
let t10_3 = t3_3 + a3_3_10 * t10_10;
let t10_4 = t3_4 + a3_4_10 * t10_10;
let t10_5 = t3_5 + a3_5_10 * t10_10;
let t10_6 = t3_6 + a3_6_10 * t10_10;
let t10_7 = t3_7 + a3_7_10 * t10_10;
let t10_8 = t3_8 + a3_8_10 * t10_10;
let t10_9 = t3_9 + a3_9_10 * t10_10;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_10));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_10));
c32 = c32 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a3_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l3 & !dead9 & !(a3_9_9 > tol.tree_pivot * m9_9));
let l9 = l3 & !dead9;
let i9 = Scalar(1.0) / a3_9_9;
let n9 = -i9;
let a9_9_10 = a3_9_10 * n9;
let t9_9 = -t3_9 * i9;
let a9_0_10 = a3_0_10 + a3_0_9 * a9_9_10;
let t9_0 = t3_0 + a3_0_9 * t9_9;
let a9_1_10 = a3_1_10 + a3_1_9 * a9_9_10;
let t9_1 = t3_1 + a3_1_9 * t9_9;
let a9_2_10 = a3_2_10 + a3_2_9 * a9_9_10;
let t9_2 = t3_2 + a3_2_9 * t9_9;
let a9_3_10 = a3_3_10 + a3_3_9 * a9_9_10;
let t9_3 = t3_3 + a3_3_9 * t9_9;
let a9_4_10 = a3_4_10 + a3_4_9 * a9_9_10;
let t9_4 = t3_4 + a3_4_9 * t9_9;
let a9_5_10 = a3_5_10 + a3_5_9 * a9_9_10;
let t9_5 = t3_5 + a3_5_9 * t9_9;
let a9_6_10 = a3_6_10 + a3_6_9 * a9_9_10;
let t9_6 = t3_6 + a3_6_9 * t9_9;
let a9_7_10 = a3_7_10 + a3_7_9 * a9_9_10;
let t9_7 = t3_7 + a3_7_9 * t9_9;
let a9_8_10 = a3_8_10 + a3_8_9 * a9_9_10;
let t9_8 = t3_8 + a3_8_9 * t9_9;
let a9_10_10 = a3_10_10 + a3_10_9 * a9_9_10;
let t9_10 = t3_10 + a3_10_9 * t9_9;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_9));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_9));
c16 = c16 | select(0u, 1u << (pre | 8u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_9)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_9)) + abs(t10_10));
c48 = c48 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a3_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l3 & !dead8 & !(a3_8_8 > tol.tree_pivot * m8_8));
let l8 = l3 & !dead8;
let i8 = Scalar(1.0) / a3_8_8;
let n8 = -i8;
let a8_8_9 = a3_8_9 * n8;
let a8_8_10 = a3_8_10 * n8;
let t8_8 = -t3_8 * i8;
let a8_0_9 = a3_0_9 + a3_0_8 * a8_8_9;
let a8_0_10 = a3_0_10 + a3_0_8 * a8_8_10;
let t8_0 = t3_0 + a3_0_8 * t8_8;
let a8_1_9 = a3_1_9 + a3_1_8 * a8_8_9;
let a8_1_10 = a3_1_10 + a3_1_8 * a8_8_10;
let t8_1 = t3_1 + a3_1_8 * t8_8;
let a8_2_9 = a3_2_9 + a3_2_8 * a8_8_9;
let a8_2_10 = a3_2_10 + a3_2_8 * a8_8_10;
let t8_2 = t3_2 + a3_2_8 * t8_8;
let a8_3_9 = a3_3_9 + a3_3_8 * a8_8_9;
let a8_3_10 = a3_3_10 + a3_3_8 * a8_8_10;
let t8_3 = t3_3 + a3_3_8 * t8_8;
let a8_4_9 = a3_4_9 + a3_4_8 * a8_8_9;
let a8_4_10 = a3_4_10 + a3_4_8 * a8_8_10;
let t8_4 = t3_4 + a3_4_8 * t8_8;
let a8_5_9 = a3_5_9 + a3_5_8 * a8_8_9;
let a8_5_10 = a3_5_10 + a3_5_8 * a8_8_10;
let t8_5 = t3_5 + a3_5_8 * t8_8;
let a8_6_9 = a3_6_9 + a3_6_8 * a8_8_9;
let a8_6_10 = a3_6_10 + a3_6_8 * a8_8_10;
let t8_6 = t3_6 + a3_6_8 * t8_8;
let a8_7_9 = a3_7_9 + a3_7_8 * a8_8_9;
let a8_7_10 = a3_7_10 + a3_7_8 * a8_8_10;
let t8_7 = t3_7 + a3_7_8 * t8_8;
let a8_9_9 = a3_9_9 + a3_9_8 * a8_8_9;
let a8_9_10 = a3_9_10 + a3_9_8 * a8_8_10;
let t8_9 = t3_9 + a3_9_8 * t8_8;
let a8_10_9 = a3_10_9 + a3_10_8 * a8_8_9;
let a8_10_10 = a3_10_10 + a3_10_8 * a8_8_10;
let t8_10 = t3_10 + a3_10_8 * t8_8;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_3)), abs(t8_8));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_3)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 8u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_8)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_8)) + abs(t10_10));
c40 = c40 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_8)), abs(t9_9));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_8)) + abs(t9_9));
c24 = c24 | select(0u, 1u << (pre | 8u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c56 = c56 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
}
{
let dead7 = semi & !(a3_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l3 & !dead7 & !(a3_7_7 > tol.tree_pivot * m7_7));
let l7 = l3 & !dead7;
let i7 = Scalar(1.0) / a3_7_7;
let n7 = -i7;
let a7_7_8 = a3_7_8 * n7;
let a7_7_9 = a3_7_9 * n7;
let a7_7_10 = a3_7_10 * n7;
let t7_7 = -t3_7 * i7;
let a7_0_8 = a3_0_8 + a3_0_7 * a7_7_8;
let a7_0_9 = a3_0_9 + a3_0_7 * a7_7_9;
let a7_0_10 = a3_0_10 + a3_0_7 * a7_7_10;
let t7_0 = t3_0 + a3_0_7 * t7_7;
let a7_1_8 = a3_1_8 + a3_1_7 * a7_7_8;
let a7_1_9 = a3_1_9 + a3_1_7 * a7_7_9;
let a7_1_10 = a3_1_10 + a3_1_7 * a7_7_10;
let t7_1 = t3_1 + a3_1_7 * t7_7;
let a7_2_8 = a3_2_8 + a3_2_7 * a7_7_8;
let a7_2_9 = a3_2_9 + a3_2_7 * a7_7_9;
let a7_2_10 = a3_2_10 + a3_2_7 * a7_7_10;
let t7_2 = t3_2 + a3_2_7 * t7_7;
let a7_3_8 = a3_3_8 + a3_3_7 * a7_7_8;
let a7_3_9 = a3_3_9 + a3_3_7 * a7_7_9;
let a7_3_10 = a3_3_10 + a3_3_7 * a7_7_10;
let t7_3 = t3_3 + a3_3_7 * t7_7;
let a7_4_8 = a3_4_8 + a3_4_7 * a7_7_8;
let a7_4_9 = a3_4_9 + a3_4_7 * a7_7_9;
let a7_4_10 = a3_4_10 + a3_4_7 * a7_7_10;
let t7_4 = t3_4 + a3_4_7 * t7_7;
let a7_5_8 = a3_5_8 + a3_5_7 * a7_7_8;
let a7_5_9 = a3_5_9 + a3_5_7 * a7_7_9;
let a7_5_10 = a3_5_10 + a3_5_7 * a7_7_10;
let t7_5 = t3_5 + a3_5_7 * t7_7;
let a7_6_8 = a3_6_8 + a3_6_7 * a7_7_8;
let a7_6_9 = a3_6_9 + a3_6_7 * a7_7_9;
let a7_6_10 = a3_6_10 + a3_6_7 * a7_7_10;
let t7_6 = t3_6 + a3_6_7 * t7_7;
let a7_8_8 = a3_8_8 + a3_8_7 * a7_7_8;
let a7_8_9 = a3_8_9 + a3_8_7 * a7_7_9;
let a7_8_10 = a3_8_10 + a3_8_7 * a7_7_10;
let t7_8 = t3_8 + a3_8_7 * t7_7;
let a7_9_8 = a3_9_8 + a3_9_7 * a7_7_8;
let a7_9_9 = a3_9_9 + a3_9_7 * a7_7_9;
let a7_9_10 = a3_9_10 + a3_9_7 * a7_7_10;
let t7_9 = t3_9 + a3_9_7 * t7_7;
let a7_10_8 = a3_10_8 + a3_10_7 * a7_7_8;
let a7_10_9 = a3_10_9 + a3_10_7 * a7_7_9;
let a7_10_10 = a3_10_10 + a3_10_7 * a7_7_10;
let t7_10 = t3_10 + a3_10_7 * t7_7;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), select(Scalar(0.0), abs(t7_1), b1)), select(Scalar(0.0), abs(t7_2), b2)), abs(t7_3)), abs(t7_7));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + select(Scalar(0.0), abs(t7_1), b1)) + select(Scalar(0.0), abs(t7_2), b2)) + abs(t7_3)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 8u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t7_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t7_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t7_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a7_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l7 & !dead10 & !(a7_10_10 > tol.tree_pivot * m10_10));
let l10 = l7 & !dead10;
let i10 = Scalar(1.0) / a7_10_10;
let n10 = -i10;
let t10_10 = -t7_10 * i10;
let t10_0 = t7_0 + a7_0_10 * t10_10;
let t10_1 = t7_1 + a7_1_10 * t10_10;
let t10_2 = t7_2 + a7_2_10 * t10_10;
let t10_3 = t7_3 + a7_3_10 * t10_10;
let t10_4 = t7_4 + a7_4_10 * t10_10;
let t10_5 = t7_5 + a7_5_10 * t10_10;
let t10_6 = t7_6 + a7_6_10 * t10_10;
let t10_7 = t7_7 + a7_7_10 * t10_10;
let t10_8 = t7_8 + a7_8_10 * t10_10;
let t10_9 = t7_9 + a7_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_7)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_7)) + abs(t10_10));
c36 = c36 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a7_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l7 & !dead9 & !(a7_9_9 > tol.tree_pivot * m9_9));
let l9 = l7 & !dead9;
let i9 = Scalar(1.0) / a7_9_9;
let n9 = -i9;
let a9_9_10 = a7_9_10 * n9;
let t9_9 = -t7_9 * i9;
let a9_0_10 = a7_0_10 + a7_0_9 * a9_9_10;
let t9_0 = t7_0 + a7_0_9 * t9_9;
let a9_1_10 = a7_1_10 + a7_1_9 * a9_9_10;
let t9_1 = t7_1 + a7_1_9 * t9_9;
let a9_2_10 = a7_2_10 + a7_2_9 * a9_9_10;
let t9_2 = t7_2 + a7_2_9 * t9_9;
let a9_3_10 = a7_3_10 + a7_3_9 * a9_9_10;
let t9_3 = t7_3 + a7_3_9 * t9_9;
let a9_4_10 = a7_4_10 + a7_4_9 * a9_9_10;
let t9_4 = t7_4 + a7_4_9 * t9_9;
let a9_5_10 = a7_5_10 + a7_5_9 * a9_9_10;
let t9_5 = t7_5 + a7_5_9 * t9_9;
let a9_6_10 = a7_6_10 + a7_6_9 * a9_9_10;
let t9_6 = t7_6 + a7_6_9 * t9_9;
let a9_7_10 = a7_7_10 + a7_7_9 * a9_9_10;
let t9_7 = t7_7 + a7_7_9 * t9_9;
let a9_8_10 = a7_8_10 + a7_8_9 * a9_9_10;
let t9_8 = t7_8 + a7_8_9 * t9_9;
let a9_10_10 = a7_10_10 + a7_10_9 * a9_9_10;
let t9_10 = t7_10 + a7_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_7)), abs(t9_9));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_7)) + abs(t9_9));
c20 = c20 | select(0u, 1u << (pre | 8u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_7)), abs(t10_9)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_7)) + abs(t10_9)) + abs(t10_10));
c52 = c52 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let a8_8_9 = a7_8_9 * n8;
let a8_8_10 = a7_8_10 * n8;
let t8_8 = -t7_8 * i8;
let a8_0_9 = a7_0_9 + a7_0_8 * a8_8_9;
let a8_0_10 = a7_0_10 + a7_0_8 * a8_8_10;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let a8_1_9 = a7_1_9 + a7_1_8 * a8_8_9;
let a8_1_10 = a7_1_10 + a7_1_8 * a8_8_10;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let a8_2_9 = a7_2_9 + a7_2_8 * a8_8_9;
let a8_2_10 = a7_2_10 + a7_2_8 * a8_8_10;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let a8_3_9 = a7_3_9 + a7_3_8 * a8_8_9;
let a8_3_10 = a7_3_10 + a7_3_8 * a8_8_10;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let a8_4_9 = a7_4_9 + a7_4_8 * a8_8_9;
let a8_4_10 = a7_4_10 + a7_4_8 * a8_8_10;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let a8_5_9 = a7_5_9 + a7_5_8 * a8_8_9;
let a8_5_10 = a7_5_10 + a7_5_8 * a8_8_10;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let a8_6_9 = a7_6_9 + a7_6_8 * a8_8_9;
let a8_6_10 = a7_6_10 + a7_6_8 * a8_8_10;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let a8_7_9 = a7_7_9 + a7_7_8 * a8_8_9;
let a8_7_10 = a7_7_10 + a7_7_8 * a8_8_10;
let t8_7 = t7_7 + a7_7_8 * t8_8;
let a8_9_9 = a7_9_9 + a7_9_8 * a8_8_9;
let a8_9_10 = a7_9_10 + a7_9_8 * a8_8_10;
let t8_9 = t7_9 + a7_9_8 * t8_8;
let a8_10_9 = a7_10_9 + a7_10_8 * a8_8_9;
let a8_10_10 = a7_10_10 + a7_10_8 * a8_8_10;
let t8_10 = t7_10 + a7_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_3)), abs(t8_7)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_3)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 8u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_7)), abs(t10_8)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_7)) + abs(t10_8)) + abs(t10_10));
c44 = c44 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_7)), abs(t9_8)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_7)) + abs(t9_8)) + abs(t9_9));
c28 = c28 | select(0u, 1u << (pre | 8u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_7)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_7)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c60 = c60 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
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
let a6_6_9 = a3_6_9 * n6;
let a6_6_10 = a3_6_10 * n6;
let t6_6 = -t3_6 * i6;
let a6_0_7 = a3_0_7 + a3_0_6 * a6_6_7;
let a6_0_8 = a3_0_8 + a3_0_6 * a6_6_8;
let a6_0_9 = a3_0_9 + a3_0_6 * a6_6_9;
let a6_0_10 = a3_0_10 + a3_0_6 * a6_6_10;
let t6_0 = t3_0 + a3_0_6 * t6_6;
let a6_1_7 = a3_1_7 + a3_1_6 * a6_6_7;
let a6_1_8 = a3_1_8 + a3_1_6 * a6_6_8;
let a6_1_9 = a3_1_9 + a3_1_6 * a6_6_9;
let a6_1_10 = a3_1_10 + a3_1_6 * a6_6_10;
let t6_1 = t3_1 + a3_1_6 * t6_6;
let a6_2_7 = a3_2_7 + a3_2_6 * a6_6_7;
let a6_2_8 = a3_2_8 + a3_2_6 * a6_6_8;
let a6_2_9 = a3_2_9 + a3_2_6 * a6_6_9;
let a6_2_10 = a3_2_10 + a3_2_6 * a6_6_10;
let t6_2 = t3_2 + a3_2_6 * t6_6;
let a6_3_7 = a3_3_7 + a3_3_6 * a6_6_7;
let a6_3_8 = a3_3_8 + a3_3_6 * a6_6_8;
let a6_3_9 = a3_3_9 + a3_3_6 * a6_6_9;
let a6_3_10 = a3_3_10 + a3_3_6 * a6_6_10;
let t6_3 = t3_3 + a3_3_6 * t6_6;
let a6_4_7 = a3_4_7 + a3_4_6 * a6_6_7;
let a6_4_8 = a3_4_8 + a3_4_6 * a6_6_8;
let a6_4_9 = a3_4_9 + a3_4_6 * a6_6_9;
let a6_4_10 = a3_4_10 + a3_4_6 * a6_6_10;
let t6_4 = t3_4 + a3_4_6 * t6_6;
let a6_5_7 = a3_5_7 + a3_5_6 * a6_6_7;
let a6_5_8 = a3_5_8 + a3_5_6 * a6_6_8;
let a6_5_9 = a3_5_9 + a3_5_6 * a6_6_9;
let a6_5_10 = a3_5_10 + a3_5_6 * a6_6_10;
let t6_5 = t3_5 + a3_5_6 * t6_6;
let a6_7_7 = a3_7_7 + a3_7_6 * a6_6_7;
let a6_7_8 = a3_7_8 + a3_7_6 * a6_6_8;
let a6_7_9 = a3_7_9 + a3_7_6 * a6_6_9;
let a6_7_10 = a3_7_10 + a3_7_6 * a6_6_10;
let t6_7 = t3_7 + a3_7_6 * t6_6;
let a6_8_7 = a3_8_7 + a3_8_6 * a6_6_7;
let a6_8_8 = a3_8_8 + a3_8_6 * a6_6_8;
let a6_8_9 = a3_8_9 + a3_8_6 * a6_6_9;
let a6_8_10 = a3_8_10 + a3_8_6 * a6_6_10;
let t6_8 = t3_8 + a3_8_6 * t6_6;
let a6_9_7 = a3_9_7 + a3_9_6 * a6_6_7;
let a6_9_8 = a3_9_8 + a3_9_6 * a6_6_8;
let a6_9_9 = a3_9_9 + a3_9_6 * a6_6_9;
let a6_9_10 = a3_9_10 + a3_9_6 * a6_6_10;
let t6_9 = t3_9 + a3_9_6 * t6_6;
let a6_10_7 = a3_10_7 + a3_10_6 * a6_6_7;
let a6_10_8 = a3_10_8 + a3_10_6 * a6_6_8;
let a6_10_9 = a3_10_9 + a3_10_6 * a6_6_9;
let a6_10_10 = a3_10_10 + a3_10_6 * a6_6_10;
let t6_10 = t3_10 + a3_10_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), select(Scalar(0.0), abs(t6_1), b1)), select(Scalar(0.0), abs(t6_2), b2)), abs(t6_3)), abs(t6_6));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + select(Scalar(0.0), abs(t6_1), b1)) + select(Scalar(0.0), abs(t6_2), b2)) + abs(t6_3)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 8u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t6_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t6_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t6_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a6_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l6 & !dead10 & !(a6_10_10 > tol.tree_pivot * m10_10));
let l10 = l6 & !dead10;
let i10 = Scalar(1.0) / a6_10_10;
let n10 = -i10;
let t10_10 = -t6_10 * i10;
let t10_0 = t6_0 + a6_0_10 * t10_10;
let t10_1 = t6_1 + a6_1_10 * t10_10;
let t10_2 = t6_2 + a6_2_10 * t10_10;
let t10_3 = t6_3 + a6_3_10 * t10_10;
let t10_4 = t6_4 + a6_4_10 * t10_10;
let t10_5 = t6_5 + a6_5_10 * t10_10;
let t10_6 = t6_6 + a6_6_10 * t10_10;
let t10_7 = t6_7 + a6_7_10 * t10_10;
let t10_8 = t6_8 + a6_8_10 * t10_10;
let t10_9 = t6_9 + a6_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_6)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_6)) + abs(t10_10));
c34 = c34 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a6_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l6 & !dead9 & !(a6_9_9 > tol.tree_pivot * m9_9));
let l9 = l6 & !dead9;
let i9 = Scalar(1.0) / a6_9_9;
let n9 = -i9;
let a9_9_10 = a6_9_10 * n9;
let t9_9 = -t6_9 * i9;
let a9_0_10 = a6_0_10 + a6_0_9 * a9_9_10;
let t9_0 = t6_0 + a6_0_9 * t9_9;
let a9_1_10 = a6_1_10 + a6_1_9 * a9_9_10;
let t9_1 = t6_1 + a6_1_9 * t9_9;
let a9_2_10 = a6_2_10 + a6_2_9 * a9_9_10;
let t9_2 = t6_2 + a6_2_9 * t9_9;
let a9_3_10 = a6_3_10 + a6_3_9 * a9_9_10;
let t9_3 = t6_3 + a6_3_9 * t9_9;
let a9_4_10 = a6_4_10 + a6_4_9 * a9_9_10;
let t9_4 = t6_4 + a6_4_9 * t9_9;
let a9_5_10 = a6_5_10 + a6_5_9 * a9_9_10;
let t9_5 = t6_5 + a6_5_9 * t9_9;
let a9_6_10 = a6_6_10 + a6_6_9 * a9_9_10;
let t9_6 = t6_6 + a6_6_9 * t9_9;
let a9_7_10 = a6_7_10 + a6_7_9 * a9_9_10;
let t9_7 = t6_7 + a6_7_9 * t9_9;
let a9_8_10 = a6_8_10 + a6_8_9 * a9_9_10;
let t9_8 = t6_8 + a6_8_9 * t9_9;
let a9_10_10 = a6_10_10 + a6_10_9 * a9_9_10;
let t9_10 = t6_10 + a6_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_6)), abs(t9_9));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_6)) + abs(t9_9));
c18 = c18 | select(0u, 1u << (pre | 8u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_6)), abs(t10_9)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_6)) + abs(t10_9)) + abs(t10_10));
c50 = c50 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let a8_8_9 = a6_8_9 * n8;
let a8_8_10 = a6_8_10 * n8;
let t8_8 = -t6_8 * i8;
let a8_0_9 = a6_0_9 + a6_0_8 * a8_8_9;
let a8_0_10 = a6_0_10 + a6_0_8 * a8_8_10;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let a8_1_9 = a6_1_9 + a6_1_8 * a8_8_9;
let a8_1_10 = a6_1_10 + a6_1_8 * a8_8_10;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let a8_2_9 = a6_2_9 + a6_2_8 * a8_8_9;
let a8_2_10 = a6_2_10 + a6_2_8 * a8_8_10;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let a8_3_9 = a6_3_9 + a6_3_8 * a8_8_9;
let a8_3_10 = a6_3_10 + a6_3_8 * a8_8_10;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let a8_4_9 = a6_4_9 + a6_4_8 * a8_8_9;
let a8_4_10 = a6_4_10 + a6_4_8 * a8_8_10;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let a8_5_9 = a6_5_9 + a6_5_8 * a8_8_9;
let a8_5_10 = a6_5_10 + a6_5_8 * a8_8_10;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let a8_6_9 = a6_6_9 + a6_6_8 * a8_8_9;
let a8_6_10 = a6_6_10 + a6_6_8 * a8_8_10;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let a8_7_9 = a6_7_9 + a6_7_8 * a8_8_9;
let a8_7_10 = a6_7_10 + a6_7_8 * a8_8_10;
let t8_7 = t6_7 + a6_7_8 * t8_8;
let a8_9_9 = a6_9_9 + a6_9_8 * a8_8_9;
let a8_9_10 = a6_9_10 + a6_9_8 * a8_8_10;
let t8_9 = t6_9 + a6_9_8 * t8_8;
let a8_10_9 = a6_10_9 + a6_10_8 * a8_8_9;
let a8_10_10 = a6_10_10 + a6_10_8 * a8_8_10;
let t8_10 = t6_10 + a6_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_3)), abs(t8_6)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_3)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 8u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_6)), abs(t10_8)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_6)) + abs(t10_8)) + abs(t10_10));
c42 = c42 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_6)), abs(t9_8)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_6)) + abs(t9_8)) + abs(t9_9));
c26 = c26 | select(0u, 1u << (pre | 8u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_6)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_6)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c58 = c58 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let a7_7_9 = a6_7_9 * n7;
let a7_7_10 = a6_7_10 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let a7_0_9 = a6_0_9 + a6_0_7 * a7_7_9;
let a7_0_10 = a6_0_10 + a6_0_7 * a7_7_10;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let a7_1_9 = a6_1_9 + a6_1_7 * a7_7_9;
let a7_1_10 = a6_1_10 + a6_1_7 * a7_7_10;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let a7_2_9 = a6_2_9 + a6_2_7 * a7_7_9;
let a7_2_10 = a6_2_10 + a6_2_7 * a7_7_10;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let a7_3_9 = a6_3_9 + a6_3_7 * a7_7_9;
let a7_3_10 = a6_3_10 + a6_3_7 * a7_7_10;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let a7_4_9 = a6_4_9 + a6_4_7 * a7_7_9;
let a7_4_10 = a6_4_10 + a6_4_7 * a7_7_10;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let a7_5_9 = a6_5_9 + a6_5_7 * a7_7_9;
let a7_5_10 = a6_5_10 + a6_5_7 * a7_7_10;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let a7_6_9 = a6_6_9 + a6_6_7 * a7_7_9;
let a7_6_10 = a6_6_10 + a6_6_7 * a7_7_10;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let a7_8_9 = a6_8_9 + a6_8_7 * a7_7_9;
let a7_8_10 = a6_8_10 + a6_8_7 * a7_7_10;
let t7_8 = t6_8 + a6_8_7 * t7_7;
let a7_9_8 = a6_9_8 + a6_9_7 * a7_7_8;
let a7_9_9 = a6_9_9 + a6_9_7 * a7_7_9;
let a7_9_10 = a6_9_10 + a6_9_7 * a7_7_10;
let t7_9 = t6_9 + a6_9_7 * t7_7;
let a7_10_8 = a6_10_8 + a6_10_7 * a7_7_8;
let a7_10_9 = a6_10_9 + a6_10_7 * a7_7_9;
let a7_10_10 = a6_10_10 + a6_10_7 * a7_7_10;
let t7_10 = t6_10 + a6_10_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), select(Scalar(0.0), abs(t7_1), b1)), select(Scalar(0.0), abs(t7_2), b2)), abs(t7_3)), abs(t7_6)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + select(Scalar(0.0), abs(t7_1), b1)) + select(Scalar(0.0), abs(t7_2), b2)) + abs(t7_3)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 8u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t7_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t7_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t7_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a7_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l7 & !dead10 & !(a7_10_10 > tol.tree_pivot * m10_10));
let l10 = l7 & !dead10;
let i10 = Scalar(1.0) / a7_10_10;
let n10 = -i10;
let t10_10 = -t7_10 * i10;
let t10_0 = t7_0 + a7_0_10 * t10_10;
let t10_1 = t7_1 + a7_1_10 * t10_10;
let t10_2 = t7_2 + a7_2_10 * t10_10;
let t10_3 = t7_3 + a7_3_10 * t10_10;
let t10_4 = t7_4 + a7_4_10 * t10_10;
let t10_5 = t7_5 + a7_5_10 * t10_10;
let t10_6 = t7_6 + a7_6_10 * t10_10;
let t10_7 = t7_7 + a7_7_10 * t10_10;
let t10_8 = t7_8 + a7_8_10 * t10_10;
let t10_9 = t7_9 + a7_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_6)), abs(t10_7)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_6)) + abs(t10_7)) + abs(t10_10));
c38 = c38 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a7_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l7 & !dead9 & !(a7_9_9 > tol.tree_pivot * m9_9));
let l9 = l7 & !dead9;
let i9 = Scalar(1.0) / a7_9_9;
let n9 = -i9;
let a9_9_10 = a7_9_10 * n9;
let t9_9 = -t7_9 * i9;
let a9_0_10 = a7_0_10 + a7_0_9 * a9_9_10;
let t9_0 = t7_0 + a7_0_9 * t9_9;
let a9_1_10 = a7_1_10 + a7_1_9 * a9_9_10;
let t9_1 = t7_1 + a7_1_9 * t9_9;
let a9_2_10 = a7_2_10 + a7_2_9 * a9_9_10;
let t9_2 = t7_2 + a7_2_9 * t9_9;
let a9_3_10 = a7_3_10 + a7_3_9 * a9_9_10;
let t9_3 = t7_3 + a7_3_9 * t9_9;
let a9_4_10 = a7_4_10 + a7_4_9 * a9_9_10;
let t9_4 = t7_4 + a7_4_9 * t9_9;
let a9_5_10 = a7_5_10 + a7_5_9 * a9_9_10;
let t9_5 = t7_5 + a7_5_9 * t9_9;
let a9_6_10 = a7_6_10 + a7_6_9 * a9_9_10;
let t9_6 = t7_6 + a7_6_9 * t9_9;
let a9_7_10 = a7_7_10 + a7_7_9 * a9_9_10;
let t9_7 = t7_7 + a7_7_9 * t9_9;
let a9_8_10 = a7_8_10 + a7_8_9 * a9_9_10;
let t9_8 = t7_8 + a7_8_9 * t9_9;
let a9_10_10 = a7_10_10 + a7_10_9 * a9_9_10;
let t9_10 = t7_10 + a7_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_6)), abs(t9_7)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_6)) + abs(t9_7)) + abs(t9_9));
c22 = c22 | select(0u, 1u << (pre | 8u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_6)), abs(t10_7)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_6)) + abs(t10_7)) + abs(t10_9)) + abs(t10_10));
c54 = c54 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let a8_8_9 = a7_8_9 * n8;
let a8_8_10 = a7_8_10 * n8;
let t8_8 = -t7_8 * i8;
let a8_0_9 = a7_0_9 + a7_0_8 * a8_8_9;
let a8_0_10 = a7_0_10 + a7_0_8 * a8_8_10;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let a8_1_9 = a7_1_9 + a7_1_8 * a8_8_9;
let a8_1_10 = a7_1_10 + a7_1_8 * a8_8_10;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let a8_2_9 = a7_2_9 + a7_2_8 * a8_8_9;
let a8_2_10 = a7_2_10 + a7_2_8 * a8_8_10;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let a8_3_9 = a7_3_9 + a7_3_8 * a8_8_9;
let a8_3_10 = a7_3_10 + a7_3_8 * a8_8_10;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let a8_4_9 = a7_4_9 + a7_4_8 * a8_8_9;
let a8_4_10 = a7_4_10 + a7_4_8 * a8_8_10;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let a8_5_9 = a7_5_9 + a7_5_8 * a8_8_9;
let a8_5_10 = a7_5_10 + a7_5_8 * a8_8_10;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let a8_6_9 = a7_6_9 + a7_6_8 * a8_8_9;
let a8_6_10 = a7_6_10 + a7_6_8 * a8_8_10;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let a8_7_9 = a7_7_9 + a7_7_8 * a8_8_9;
let a8_7_10 = a7_7_10 + a7_7_8 * a8_8_10;
let t8_7 = t7_7 + a7_7_8 * t8_8;
let a8_9_9 = a7_9_9 + a7_9_8 * a8_8_9;
let a8_9_10 = a7_9_10 + a7_9_8 * a8_8_10;
let t8_9 = t7_9 + a7_9_8 * t8_8;
let a8_10_9 = a7_10_9 + a7_10_8 * a8_8_9;
let a8_10_10 = a7_10_10 + a7_10_8 * a8_8_10;
let t8_10 = t7_10 + a7_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_3)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_3)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 8u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_6)), abs(t10_7)), abs(t10_8)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_6)) + abs(t10_7)) + abs(t10_8)) + abs(t10_10));
c46 = c46 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_6)), abs(t9_7)), abs(t9_8)), abs(t9_9));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_6)) + abs(t9_7)) + abs(t9_8)) + abs(t9_9));
c30 = c30 | select(0u, 1u << (pre | 8u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_6)), abs(t10_7)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_6)) + abs(t10_7)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c62 = c62 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
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
let a5_5_9 = a3_5_9 * n5;
let a5_5_10 = a3_5_10 * n5;
let t5_5 = -t3_5 * i5;
let a5_0_6 = a3_0_6 + a3_0_5 * a5_5_6;
let a5_0_7 = a3_0_7 + a3_0_5 * a5_5_7;
let a5_0_8 = a3_0_8 + a3_0_5 * a5_5_8;
let a5_0_9 = a3_0_9 + a3_0_5 * a5_5_9;
let a5_0_10 = a3_0_10 + a3_0_5 * a5_5_10;
let t5_0 = t3_0 + a3_0_5 * t5_5;
let a5_1_6 = a3_1_6 + a3_1_5 * a5_5_6;
let a5_1_7 = a3_1_7 + a3_1_5 * a5_5_7;
let a5_1_8 = a3_1_8 + a3_1_5 * a5_5_8;
let a5_1_9 = a3_1_9 + a3_1_5 * a5_5_9;
let a5_1_10 = a3_1_10 + a3_1_5 * a5_5_10;
let t5_1 = t3_1 + a3_1_5 * t5_5;
let a5_2_6 = a3_2_6 + a3_2_5 * a5_5_6;
let a5_2_7 = a3_2_7 + a3_2_5 * a5_5_7;
let a5_2_8 = a3_2_8 + a3_2_5 * a5_5_8;
let a5_2_9 = a3_2_9 + a3_2_5 * a5_5_9;
let a5_2_10 = a3_2_10 + a3_2_5 * a5_5_10;
let t5_2 = t3_2 + a3_2_5 * t5_5;
let a5_3_6 = a3_3_6 + a3_3_5 * a5_5_6;
let a5_3_7 = a3_3_7 + a3_3_5 * a5_5_7;
let a5_3_8 = a3_3_8 + a3_3_5 * a5_5_8;
let a5_3_9 = a3_3_9 + a3_3_5 * a5_5_9;
let a5_3_10 = a3_3_10 + a3_3_5 * a5_5_10;
let t5_3 = t3_3 + a3_3_5 * t5_5;
let a5_4_6 = a3_4_6 + a3_4_5 * a5_5_6;
let a5_4_7 = a3_4_7 + a3_4_5 * a5_5_7;
let a5_4_8 = a3_4_8 + a3_4_5 * a5_5_8;
let a5_4_9 = a3_4_9 + a3_4_5 * a5_5_9;
let a5_4_10 = a3_4_10 + a3_4_5 * a5_5_10;
let t5_4 = t3_4 + a3_4_5 * t5_5;
let a5_6_6 = a3_6_6 + a3_6_5 * a5_5_6;
let a5_6_7 = a3_6_7 + a3_6_5 * a5_5_7;
let a5_6_8 = a3_6_8 + a3_6_5 * a5_5_8;
let a5_6_9 = a3_6_9 + a3_6_5 * a5_5_9;
let a5_6_10 = a3_6_10 + a3_6_5 * a5_5_10;
let t5_6 = t3_6 + a3_6_5 * t5_5;
let a5_7_6 = a3_7_6 + a3_7_5 * a5_5_6;
let a5_7_7 = a3_7_7 + a3_7_5 * a5_5_7;
let a5_7_8 = a3_7_8 + a3_7_5 * a5_5_8;
let a5_7_9 = a3_7_9 + a3_7_5 * a5_5_9;
let a5_7_10 = a3_7_10 + a3_7_5 * a5_5_10;
let t5_7 = t3_7 + a3_7_5 * t5_5;
let a5_8_6 = a3_8_6 + a3_8_5 * a5_5_6;
let a5_8_7 = a3_8_7 + a3_8_5 * a5_5_7;
let a5_8_8 = a3_8_8 + a3_8_5 * a5_5_8;
let a5_8_9 = a3_8_9 + a3_8_5 * a5_5_9;
let a5_8_10 = a3_8_10 + a3_8_5 * a5_5_10;
let t5_8 = t3_8 + a3_8_5 * t5_5;
let a5_9_6 = a3_9_6 + a3_9_5 * a5_5_6;
let a5_9_7 = a3_9_7 + a3_9_5 * a5_5_7;
let a5_9_8 = a3_9_8 + a3_9_5 * a5_5_8;
let a5_9_9 = a3_9_9 + a3_9_5 * a5_5_9;
let a5_9_10 = a3_9_10 + a3_9_5 * a5_5_10;
let t5_9 = t3_9 + a3_9_5 * t5_5;
let a5_10_6 = a3_10_6 + a3_10_5 * a5_5_6;
let a5_10_7 = a3_10_7 + a3_10_5 * a5_5_7;
let a5_10_8 = a3_10_8 + a3_10_5 * a5_5_8;
let a5_10_9 = a3_10_9 + a3_10_5 * a5_5_9;
let a5_10_10 = a3_10_10 + a3_10_5 * a5_5_10;
let t5_10 = t3_10 + a3_10_5 * t5_5;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), select(Scalar(0.0), abs(t5_1), b1)), select(Scalar(0.0), abs(t5_2), b2)), abs(t5_3)), abs(t5_5));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + select(Scalar(0.0), abs(t5_1), b1)) + select(Scalar(0.0), abs(t5_2), b2)) + abs(t5_3)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 8u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t5_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t5_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t5_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a5_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l5 & !dead10 & !(a5_10_10 > tol.tree_pivot * m10_10));
let l10 = l5 & !dead10;
let i10 = Scalar(1.0) / a5_10_10;
let n10 = -i10;
let t10_10 = -t5_10 * i10;
let t10_0 = t5_0 + a5_0_10 * t10_10;
let t10_1 = t5_1 + a5_1_10 * t10_10;
let t10_2 = t5_2 + a5_2_10 * t10_10;
let t10_3 = t5_3 + a5_3_10 * t10_10;
let t10_4 = t5_4 + a5_4_10 * t10_10;
let t10_5 = t5_5 + a5_5_10 * t10_10;
let t10_6 = t5_6 + a5_6_10 * t10_10;
let t10_7 = t5_7 + a5_7_10 * t10_10;
let t10_8 = t5_8 + a5_8_10 * t10_10;
let t10_9 = t5_9 + a5_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_5)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_5)) + abs(t10_10));
c33 = c33 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a5_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l5 & !dead9 & !(a5_9_9 > tol.tree_pivot * m9_9));
let l9 = l5 & !dead9;
let i9 = Scalar(1.0) / a5_9_9;
let n9 = -i9;
let a9_9_10 = a5_9_10 * n9;
let t9_9 = -t5_9 * i9;
let a9_0_10 = a5_0_10 + a5_0_9 * a9_9_10;
let t9_0 = t5_0 + a5_0_9 * t9_9;
let a9_1_10 = a5_1_10 + a5_1_9 * a9_9_10;
let t9_1 = t5_1 + a5_1_9 * t9_9;
let a9_2_10 = a5_2_10 + a5_2_9 * a9_9_10;
let t9_2 = t5_2 + a5_2_9 * t9_9;
let a9_3_10 = a5_3_10 + a5_3_9 * a9_9_10;
let t9_3 = t5_3 + a5_3_9 * t9_9;
let a9_4_10 = a5_4_10 + a5_4_9 * a9_9_10;
let t9_4 = t5_4 + a5_4_9 * t9_9;
let a9_5_10 = a5_5_10 + a5_5_9 * a9_9_10;
let t9_5 = t5_5 + a5_5_9 * t9_9;
let a9_6_10 = a5_6_10 + a5_6_9 * a9_9_10;
let t9_6 = t5_6 + a5_6_9 * t9_9;
let a9_7_10 = a5_7_10 + a5_7_9 * a9_9_10;
let t9_7 = t5_7 + a5_7_9 * t9_9;
let a9_8_10 = a5_8_10 + a5_8_9 * a9_9_10;
let t9_8 = t5_8 + a5_8_9 * t9_9;
let a9_10_10 = a5_10_10 + a5_10_9 * a9_9_10;
let t9_10 = t5_10 + a5_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_5)), abs(t9_9));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_5)) + abs(t9_9));
c17 = c17 | select(0u, 1u << (pre | 8u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_5)), abs(t10_9)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_5)) + abs(t10_9)) + abs(t10_10));
c49 = c49 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let a8_8_9 = a5_8_9 * n8;
let a8_8_10 = a5_8_10 * n8;
let t8_8 = -t5_8 * i8;
let a8_0_9 = a5_0_9 + a5_0_8 * a8_8_9;
let a8_0_10 = a5_0_10 + a5_0_8 * a8_8_10;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let a8_1_9 = a5_1_9 + a5_1_8 * a8_8_9;
let a8_1_10 = a5_1_10 + a5_1_8 * a8_8_10;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let a8_2_9 = a5_2_9 + a5_2_8 * a8_8_9;
let a8_2_10 = a5_2_10 + a5_2_8 * a8_8_10;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let a8_3_9 = a5_3_9 + a5_3_8 * a8_8_9;
let a8_3_10 = a5_3_10 + a5_3_8 * a8_8_10;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let a8_4_9 = a5_4_9 + a5_4_8 * a8_8_9;
let a8_4_10 = a5_4_10 + a5_4_8 * a8_8_10;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let a8_5_9 = a5_5_9 + a5_5_8 * a8_8_9;
let a8_5_10 = a5_5_10 + a5_5_8 * a8_8_10;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let a8_6_9 = a5_6_9 + a5_6_8 * a8_8_9;
let a8_6_10 = a5_6_10 + a5_6_8 * a8_8_10;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let a8_7_9 = a5_7_9 + a5_7_8 * a8_8_9;
let a8_7_10 = a5_7_10 + a5_7_8 * a8_8_10;
let t8_7 = t5_7 + a5_7_8 * t8_8;
let a8_9_9 = a5_9_9 + a5_9_8 * a8_8_9;
let a8_9_10 = a5_9_10 + a5_9_8 * a8_8_10;
let t8_9 = t5_9 + a5_9_8 * t8_8;
let a8_10_9 = a5_10_9 + a5_10_8 * a8_8_9;
let a8_10_10 = a5_10_10 + a5_10_8 * a8_8_10;
let t8_10 = t5_10 + a5_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_3)), abs(t8_5)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_3)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 8u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_5)), abs(t10_8)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_5)) + abs(t10_8)) + abs(t10_10));
c41 = c41 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_5)), abs(t9_8)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_5)) + abs(t9_8)) + abs(t9_9));
c25 = c25 | select(0u, 1u << (pre | 8u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_5)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_5)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c57 = c57 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let a7_7_9 = a5_7_9 * n7;
let a7_7_10 = a5_7_10 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let a7_0_9 = a5_0_9 + a5_0_7 * a7_7_9;
let a7_0_10 = a5_0_10 + a5_0_7 * a7_7_10;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let a7_1_9 = a5_1_9 + a5_1_7 * a7_7_9;
let a7_1_10 = a5_1_10 + a5_1_7 * a7_7_10;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let a7_2_9 = a5_2_9 + a5_2_7 * a7_7_9;
let a7_2_10 = a5_2_10 + a5_2_7 * a7_7_10;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let a7_3_9 = a5_3_9 + a5_3_7 * a7_7_9;
let a7_3_10 = a5_3_10 + a5_3_7 * a7_7_10;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let a7_4_9 = a5_4_9 + a5_4_7 * a7_7_9;
let a7_4_10 = a5_4_10 + a5_4_7 * a7_7_10;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let a7_5_9 = a5_5_9 + a5_5_7 * a7_7_9;
let a7_5_10 = a5_5_10 + a5_5_7 * a7_7_10;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let a7_6_9 = a5_6_9 + a5_6_7 * a7_7_9;
let a7_6_10 = a5_6_10 + a5_6_7 * a7_7_10;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let a7_8_9 = a5_8_9 + a5_8_7 * a7_7_9;
let a7_8_10 = a5_8_10 + a5_8_7 * a7_7_10;
let t7_8 = t5_8 + a5_8_7 * t7_7;
let a7_9_8 = a5_9_8 + a5_9_7 * a7_7_8;
let a7_9_9 = a5_9_9 + a5_9_7 * a7_7_9;
let a7_9_10 = a5_9_10 + a5_9_7 * a7_7_10;
let t7_9 = t5_9 + a5_9_7 * t7_7;
let a7_10_8 = a5_10_8 + a5_10_7 * a7_7_8;
let a7_10_9 = a5_10_9 + a5_10_7 * a7_7_9;
let a7_10_10 = a5_10_10 + a5_10_7 * a7_7_10;
let t7_10 = t5_10 + a5_10_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), select(Scalar(0.0), abs(t7_1), b1)), select(Scalar(0.0), abs(t7_2), b2)), abs(t7_3)), abs(t7_5)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + select(Scalar(0.0), abs(t7_1), b1)) + select(Scalar(0.0), abs(t7_2), b2)) + abs(t7_3)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 8u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t7_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t7_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t7_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a7_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l7 & !dead10 & !(a7_10_10 > tol.tree_pivot * m10_10));
let l10 = l7 & !dead10;
let i10 = Scalar(1.0) / a7_10_10;
let n10 = -i10;
let t10_10 = -t7_10 * i10;
let t10_0 = t7_0 + a7_0_10 * t10_10;
let t10_1 = t7_1 + a7_1_10 * t10_10;
let t10_2 = t7_2 + a7_2_10 * t10_10;
let t10_3 = t7_3 + a7_3_10 * t10_10;
let t10_4 = t7_4 + a7_4_10 * t10_10;
let t10_5 = t7_5 + a7_5_10 * t10_10;
let t10_6 = t7_6 + a7_6_10 * t10_10;
let t10_7 = t7_7 + a7_7_10 * t10_10;
let t10_8 = t7_8 + a7_8_10 * t10_10;
let t10_9 = t7_9 + a7_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_5)), abs(t10_7)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_5)) + abs(t10_7)) + abs(t10_10));
c37 = c37 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a7_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l7 & !dead9 & !(a7_9_9 > tol.tree_pivot * m9_9));
let l9 = l7 & !dead9;
let i9 = Scalar(1.0) / a7_9_9;
let n9 = -i9;
let a9_9_10 = a7_9_10 * n9;
let t9_9 = -t7_9 * i9;
let a9_0_10 = a7_0_10 + a7_0_9 * a9_9_10;
let t9_0 = t7_0 + a7_0_9 * t9_9;
let a9_1_10 = a7_1_10 + a7_1_9 * a9_9_10;
let t9_1 = t7_1 + a7_1_9 * t9_9;
let a9_2_10 = a7_2_10 + a7_2_9 * a9_9_10;
let t9_2 = t7_2 + a7_2_9 * t9_9;
let a9_3_10 = a7_3_10 + a7_3_9 * a9_9_10;
let t9_3 = t7_3 + a7_3_9 * t9_9;
let a9_4_10 = a7_4_10 + a7_4_9 * a9_9_10;
let t9_4 = t7_4 + a7_4_9 * t9_9;
let a9_5_10 = a7_5_10 + a7_5_9 * a9_9_10;
let t9_5 = t7_5 + a7_5_9 * t9_9;
let a9_6_10 = a7_6_10 + a7_6_9 * a9_9_10;
let t9_6 = t7_6 + a7_6_9 * t9_9;
let a9_7_10 = a7_7_10 + a7_7_9 * a9_9_10;
let t9_7 = t7_7 + a7_7_9 * t9_9;
let a9_8_10 = a7_8_10 + a7_8_9 * a9_9_10;
let t9_8 = t7_8 + a7_8_9 * t9_9;
let a9_10_10 = a7_10_10 + a7_10_9 * a9_9_10;
let t9_10 = t7_10 + a7_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_5)), abs(t9_7)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_5)) + abs(t9_7)) + abs(t9_9));
c21 = c21 | select(0u, 1u << (pre | 8u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_5)), abs(t10_7)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_5)) + abs(t10_7)) + abs(t10_9)) + abs(t10_10));
c53 = c53 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let a8_8_9 = a7_8_9 * n8;
let a8_8_10 = a7_8_10 * n8;
let t8_8 = -t7_8 * i8;
let a8_0_9 = a7_0_9 + a7_0_8 * a8_8_9;
let a8_0_10 = a7_0_10 + a7_0_8 * a8_8_10;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let a8_1_9 = a7_1_9 + a7_1_8 * a8_8_9;
let a8_1_10 = a7_1_10 + a7_1_8 * a8_8_10;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let a8_2_9 = a7_2_9 + a7_2_8 * a8_8_9;
let a8_2_10 = a7_2_10 + a7_2_8 * a8_8_10;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let a8_3_9 = a7_3_9 + a7_3_8 * a8_8_9;
let a8_3_10 = a7_3_10 + a7_3_8 * a8_8_10;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let a8_4_9 = a7_4_9 + a7_4_8 * a8_8_9;
let a8_4_10 = a7_4_10 + a7_4_8 * a8_8_10;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let a8_5_9 = a7_5_9 + a7_5_8 * a8_8_9;
let a8_5_10 = a7_5_10 + a7_5_8 * a8_8_10;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let a8_6_9 = a7_6_9 + a7_6_8 * a8_8_9;
let a8_6_10 = a7_6_10 + a7_6_8 * a8_8_10;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let a8_7_9 = a7_7_9 + a7_7_8 * a8_8_9;
let a8_7_10 = a7_7_10 + a7_7_8 * a8_8_10;
let t8_7 = t7_7 + a7_7_8 * t8_8;
let a8_9_9 = a7_9_9 + a7_9_8 * a8_8_9;
let a8_9_10 = a7_9_10 + a7_9_8 * a8_8_10;
let t8_9 = t7_9 + a7_9_8 * t8_8;
let a8_10_9 = a7_10_9 + a7_10_8 * a8_8_9;
let a8_10_10 = a7_10_10 + a7_10_8 * a8_8_10;
let t8_10 = t7_10 + a7_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_3)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_3)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 8u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_5)), abs(t10_7)), abs(t10_8)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_5)) + abs(t10_7)) + abs(t10_8)) + abs(t10_10));
c45 = c45 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_5)), abs(t9_7)), abs(t9_8)), abs(t9_9));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_5)) + abs(t9_7)) + abs(t9_8)) + abs(t9_9));
c29 = c29 | select(0u, 1u << (pre | 8u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_5)), abs(t10_7)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_5)) + abs(t10_7)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c61 = c61 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
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
let a6_6_9 = a5_6_9 * n6;
let a6_6_10 = a5_6_10 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let a6_0_9 = a5_0_9 + a5_0_6 * a6_6_9;
let a6_0_10 = a5_0_10 + a5_0_6 * a6_6_10;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let a6_1_9 = a5_1_9 + a5_1_6 * a6_6_9;
let a6_1_10 = a5_1_10 + a5_1_6 * a6_6_10;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let a6_2_9 = a5_2_9 + a5_2_6 * a6_6_9;
let a6_2_10 = a5_2_10 + a5_2_6 * a6_6_10;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let a6_3_9 = a5_3_9 + a5_3_6 * a6_6_9;
let a6_3_10 = a5_3_10 + a5_3_6 * a6_6_10;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let a6_4_9 = a5_4_9 + a5_4_6 * a6_6_9;
let a6_4_10 = a5_4_10 + a5_4_6 * a6_6_10;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let a6_5_9 = a5_5_9 + a5_5_6 * a6_6_9;
let a6_5_10 = a5_5_10 + a5_5_6 * a6_6_10;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let a6_7_9 = a5_7_9 + a5_7_6 * a6_6_9;
let a6_7_10 = a5_7_10 + a5_7_6 * a6_6_10;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let a6_8_9 = a5_8_9 + a5_8_6 * a6_6_9;
let a6_8_10 = a5_8_10 + a5_8_6 * a6_6_10;
let t6_8 = t5_8 + a5_8_6 * t6_6;
let a6_9_7 = a5_9_7 + a5_9_6 * a6_6_7;
let a6_9_8 = a5_9_8 + a5_9_6 * a6_6_8;
let a6_9_9 = a5_9_9 + a5_9_6 * a6_6_9;
let a6_9_10 = a5_9_10 + a5_9_6 * a6_6_10;
let t6_9 = t5_9 + a5_9_6 * t6_6;
let a6_10_7 = a5_10_7 + a5_10_6 * a6_6_7;
let a6_10_8 = a5_10_8 + a5_10_6 * a6_6_8;
let a6_10_9 = a5_10_9 + a5_10_6 * a6_6_9;
let a6_10_10 = a5_10_10 + a5_10_6 * a6_6_10;
let t6_10 = t5_10 + a5_10_6 * t6_6;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), select(Scalar(0.0), abs(t6_1), b1)), select(Scalar(0.0), abs(t6_2), b2)), abs(t6_3)), abs(t6_5)), abs(t6_6));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + select(Scalar(0.0), abs(t6_1), b1)) + select(Scalar(0.0), abs(t6_2), b2)) + abs(t6_3)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 8u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t6_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t6_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t6_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a6_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l6 & !dead10 & !(a6_10_10 > tol.tree_pivot * m10_10));
let l10 = l6 & !dead10;
let i10 = Scalar(1.0) / a6_10_10;
let n10 = -i10;
let t10_10 = -t6_10 * i10;
let t10_0 = t6_0 + a6_0_10 * t10_10;
let t10_1 = t6_1 + a6_1_10 * t10_10;
let t10_2 = t6_2 + a6_2_10 * t10_10;
let t10_3 = t6_3 + a6_3_10 * t10_10;
let t10_4 = t6_4 + a6_4_10 * t10_10;
let t10_5 = t6_5 + a6_5_10 * t10_10;
let t10_6 = t6_6 + a6_6_10 * t10_10;
let t10_7 = t6_7 + a6_7_10 * t10_10;
let t10_8 = t6_8 + a6_8_10 * t10_10;
let t10_9 = t6_9 + a6_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_5)), abs(t10_6)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_5)) + abs(t10_6)) + abs(t10_10));
c35 = c35 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a6_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l6 & !dead9 & !(a6_9_9 > tol.tree_pivot * m9_9));
let l9 = l6 & !dead9;
let i9 = Scalar(1.0) / a6_9_9;
let n9 = -i9;
let a9_9_10 = a6_9_10 * n9;
let t9_9 = -t6_9 * i9;
let a9_0_10 = a6_0_10 + a6_0_9 * a9_9_10;
let t9_0 = t6_0 + a6_0_9 * t9_9;
let a9_1_10 = a6_1_10 + a6_1_9 * a9_9_10;
let t9_1 = t6_1 + a6_1_9 * t9_9;
let a9_2_10 = a6_2_10 + a6_2_9 * a9_9_10;
let t9_2 = t6_2 + a6_2_9 * t9_9;
let a9_3_10 = a6_3_10 + a6_3_9 * a9_9_10;
let t9_3 = t6_3 + a6_3_9 * t9_9;
let a9_4_10 = a6_4_10 + a6_4_9 * a9_9_10;
let t9_4 = t6_4 + a6_4_9 * t9_9;
let a9_5_10 = a6_5_10 + a6_5_9 * a9_9_10;
let t9_5 = t6_5 + a6_5_9 * t9_9;
let a9_6_10 = a6_6_10 + a6_6_9 * a9_9_10;
let t9_6 = t6_6 + a6_6_9 * t9_9;
let a9_7_10 = a6_7_10 + a6_7_9 * a9_9_10;
let t9_7 = t6_7 + a6_7_9 * t9_9;
let a9_8_10 = a6_8_10 + a6_8_9 * a9_9_10;
let t9_8 = t6_8 + a6_8_9 * t9_9;
let a9_10_10 = a6_10_10 + a6_10_9 * a9_9_10;
let t9_10 = t6_10 + a6_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_5)), abs(t9_6)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_5)) + abs(t9_6)) + abs(t9_9));
c19 = c19 | select(0u, 1u << (pre | 8u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_5)), abs(t10_6)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_5)) + abs(t10_6)) + abs(t10_9)) + abs(t10_10));
c51 = c51 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let a8_8_9 = a6_8_9 * n8;
let a8_8_10 = a6_8_10 * n8;
let t8_8 = -t6_8 * i8;
let a8_0_9 = a6_0_9 + a6_0_8 * a8_8_9;
let a8_0_10 = a6_0_10 + a6_0_8 * a8_8_10;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let a8_1_9 = a6_1_9 + a6_1_8 * a8_8_9;
let a8_1_10 = a6_1_10 + a6_1_8 * a8_8_10;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let a8_2_9 = a6_2_9 + a6_2_8 * a8_8_9;
let a8_2_10 = a6_2_10 + a6_2_8 * a8_8_10;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let a8_3_9 = a6_3_9 + a6_3_8 * a8_8_9;
let a8_3_10 = a6_3_10 + a6_3_8 * a8_8_10;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let a8_4_9 = a6_4_9 + a6_4_8 * a8_8_9;
let a8_4_10 = a6_4_10 + a6_4_8 * a8_8_10;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let a8_5_9 = a6_5_9 + a6_5_8 * a8_8_9;
let a8_5_10 = a6_5_10 + a6_5_8 * a8_8_10;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let a8_6_9 = a6_6_9 + a6_6_8 * a8_8_9;
let a8_6_10 = a6_6_10 + a6_6_8 * a8_8_10;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let a8_7_9 = a6_7_9 + a6_7_8 * a8_8_9;
let a8_7_10 = a6_7_10 + a6_7_8 * a8_8_10;
let t8_7 = t6_7 + a6_7_8 * t8_8;
let a8_9_9 = a6_9_9 + a6_9_8 * a8_8_9;
let a8_9_10 = a6_9_10 + a6_9_8 * a8_8_10;
let t8_9 = t6_9 + a6_9_8 * t8_8;
let a8_10_9 = a6_10_9 + a6_10_8 * a8_8_9;
let a8_10_10 = a6_10_10 + a6_10_8 * a8_8_10;
let t8_10 = t6_10 + a6_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_3)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_3)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 8u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_5)), abs(t10_6)), abs(t10_8)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_5)) + abs(t10_6)) + abs(t10_8)) + abs(t10_10));
c43 = c43 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_5)), abs(t9_6)), abs(t9_8)), abs(t9_9));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_5)) + abs(t9_6)) + abs(t9_8)) + abs(t9_9));
c27 = c27 | select(0u, 1u << (pre | 8u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_5)), abs(t10_6)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_5)) + abs(t10_6)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c59 = c59 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let a7_7_9 = a6_7_9 * n7;
let a7_7_10 = a6_7_10 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let a7_0_9 = a6_0_9 + a6_0_7 * a7_7_9;
let a7_0_10 = a6_0_10 + a6_0_7 * a7_7_10;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let a7_1_9 = a6_1_9 + a6_1_7 * a7_7_9;
let a7_1_10 = a6_1_10 + a6_1_7 * a7_7_10;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let a7_2_9 = a6_2_9 + a6_2_7 * a7_7_9;
let a7_2_10 = a6_2_10 + a6_2_7 * a7_7_10;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let a7_3_9 = a6_3_9 + a6_3_7 * a7_7_9;
let a7_3_10 = a6_3_10 + a6_3_7 * a7_7_10;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let a7_4_9 = a6_4_9 + a6_4_7 * a7_7_9;
let a7_4_10 = a6_4_10 + a6_4_7 * a7_7_10;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let a7_5_9 = a6_5_9 + a6_5_7 * a7_7_9;
let a7_5_10 = a6_5_10 + a6_5_7 * a7_7_10;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let a7_6_9 = a6_6_9 + a6_6_7 * a7_7_9;
let a7_6_10 = a6_6_10 + a6_6_7 * a7_7_10;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let a7_8_9 = a6_8_9 + a6_8_7 * a7_7_9;
let a7_8_10 = a6_8_10 + a6_8_7 * a7_7_10;
let t7_8 = t6_8 + a6_8_7 * t7_7;
let a7_9_8 = a6_9_8 + a6_9_7 * a7_7_8;
let a7_9_9 = a6_9_9 + a6_9_7 * a7_7_9;
let a7_9_10 = a6_9_10 + a6_9_7 * a7_7_10;
let t7_9 = t6_9 + a6_9_7 * t7_7;
let a7_10_8 = a6_10_8 + a6_10_7 * a7_7_8;
let a7_10_9 = a6_10_9 + a6_10_7 * a7_7_9;
let a7_10_10 = a6_10_10 + a6_10_7 * a7_7_10;
let t7_10 = t6_10 + a6_10_7 * t7_7;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), select(Scalar(0.0), abs(t7_1), b1)), select(Scalar(0.0), abs(t7_2), b2)), abs(t7_3)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + select(Scalar(0.0), abs(t7_1), b1)) + select(Scalar(0.0), abs(t7_2), b2)) + abs(t7_3)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 8u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t7_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t7_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t7_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a7_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l7 & !dead10 & !(a7_10_10 > tol.tree_pivot * m10_10));
let l10 = l7 & !dead10;
let i10 = Scalar(1.0) / a7_10_10;
let n10 = -i10;
let t10_10 = -t7_10 * i10;
let t10_0 = t7_0 + a7_0_10 * t10_10;
let t10_1 = t7_1 + a7_1_10 * t10_10;
let t10_2 = t7_2 + a7_2_10 * t10_10;
let t10_3 = t7_3 + a7_3_10 * t10_10;
let t10_4 = t7_4 + a7_4_10 * t10_10;
let t10_5 = t7_5 + a7_5_10 * t10_10;
let t10_6 = t7_6 + a7_6_10 * t10_10;
let t10_7 = t7_7 + a7_7_10 * t10_10;
let t10_8 = t7_8 + a7_8_10 * t10_10;
let t10_9 = t7_9 + a7_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_5)), abs(t10_6)), abs(t10_7)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_5)) + abs(t10_6)) + abs(t10_7)) + abs(t10_10));
c39 = c39 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a7_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l7 & !dead9 & !(a7_9_9 > tol.tree_pivot * m9_9));
let l9 = l7 & !dead9;
let i9 = Scalar(1.0) / a7_9_9;
let n9 = -i9;
let a9_9_10 = a7_9_10 * n9;
let t9_9 = -t7_9 * i9;
let a9_0_10 = a7_0_10 + a7_0_9 * a9_9_10;
let t9_0 = t7_0 + a7_0_9 * t9_9;
let a9_1_10 = a7_1_10 + a7_1_9 * a9_9_10;
let t9_1 = t7_1 + a7_1_9 * t9_9;
let a9_2_10 = a7_2_10 + a7_2_9 * a9_9_10;
let t9_2 = t7_2 + a7_2_9 * t9_9;
let a9_3_10 = a7_3_10 + a7_3_9 * a9_9_10;
let t9_3 = t7_3 + a7_3_9 * t9_9;
let a9_4_10 = a7_4_10 + a7_4_9 * a9_9_10;
let t9_4 = t7_4 + a7_4_9 * t9_9;
let a9_5_10 = a7_5_10 + a7_5_9 * a9_9_10;
let t9_5 = t7_5 + a7_5_9 * t9_9;
let a9_6_10 = a7_6_10 + a7_6_9 * a9_9_10;
let t9_6 = t7_6 + a7_6_9 * t9_9;
let a9_7_10 = a7_7_10 + a7_7_9 * a9_9_10;
let t9_7 = t7_7 + a7_7_9 * t9_9;
let a9_8_10 = a7_8_10 + a7_8_9 * a9_9_10;
let t9_8 = t7_8 + a7_8_9 * t9_9;
let a9_10_10 = a7_10_10 + a7_10_9 * a9_9_10;
let t9_10 = t7_10 + a7_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_5)), abs(t9_6)), abs(t9_7)), abs(t9_9));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_5)) + abs(t9_6)) + abs(t9_7)) + abs(t9_9));
c23 = c23 | select(0u, 1u << (pre | 8u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_5)), abs(t10_6)), abs(t10_7)), abs(t10_9)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_5)) + abs(t10_6)) + abs(t10_7)) + abs(t10_9)) + abs(t10_10));
c55 = c55 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let a8_8_9 = a7_8_9 * n8;
let a8_8_10 = a7_8_10 * n8;
let t8_8 = -t7_8 * i8;
let a8_0_9 = a7_0_9 + a7_0_8 * a8_8_9;
let a8_0_10 = a7_0_10 + a7_0_8 * a8_8_10;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let a8_1_9 = a7_1_9 + a7_1_8 * a8_8_9;
let a8_1_10 = a7_1_10 + a7_1_8 * a8_8_10;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let a8_2_9 = a7_2_9 + a7_2_8 * a8_8_9;
let a8_2_10 = a7_2_10 + a7_2_8 * a8_8_10;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let a8_3_9 = a7_3_9 + a7_3_8 * a8_8_9;
let a8_3_10 = a7_3_10 + a7_3_8 * a8_8_10;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let a8_4_9 = a7_4_9 + a7_4_8 * a8_8_9;
let a8_4_10 = a7_4_10 + a7_4_8 * a8_8_10;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let a8_5_9 = a7_5_9 + a7_5_8 * a8_8_9;
let a8_5_10 = a7_5_10 + a7_5_8 * a8_8_10;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let a8_6_9 = a7_6_9 + a7_6_8 * a8_8_9;
let a8_6_10 = a7_6_10 + a7_6_8 * a8_8_10;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let a8_7_9 = a7_7_9 + a7_7_8 * a8_8_9;
let a8_7_10 = a7_7_10 + a7_7_8 * a8_8_10;
let t8_7 = t7_7 + a7_7_8 * t8_8;
let a8_9_9 = a7_9_9 + a7_9_8 * a8_8_9;
let a8_9_10 = a7_9_10 + a7_9_8 * a8_8_10;
let t8_9 = t7_9 + a7_9_8 * t8_8;
let a8_10_9 = a7_10_9 + a7_10_8 * a8_8_9;
let a8_10_10 = a7_10_10 + a7_10_8 * a8_8_10;
let t8_10 = t7_10 + a7_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_3)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_3)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 8u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_5)), abs(t10_6)), abs(t10_7)), abs(t10_8)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_5)) + abs(t10_6)) + abs(t10_7)) + abs(t10_8)) + abs(t10_10));
c47 = c47 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_5)), abs(t9_6)), abs(t9_7)), abs(t9_8)), abs(t9_9));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_5)) + abs(t9_6)) + abs(t9_7)) + abs(t9_8)) + abs(t9_9));
c31 = c31 | select(0u, 1u << (pre | 8u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_5)), abs(t10_6)), abs(t10_7)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = ((((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_5)) + abs(t10_6)) + abs(t10_7)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c63 = c63 | select(0u, 1u << (pre | 8u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
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
let a4_4_9 = a3_4_9 * n4;
let a4_4_10 = a3_4_10 * n4;
let t4_4 = -t3_4 * i4;
let a4_0_5 = a3_0_5 + a3_0_4 * a4_4_5;
let a4_0_6 = a3_0_6 + a3_0_4 * a4_4_6;
let a4_0_7 = a3_0_7 + a3_0_4 * a4_4_7;
let a4_0_8 = a3_0_8 + a3_0_4 * a4_4_8;
let a4_0_9 = a3_0_9 + a3_0_4 * a4_4_9;
let a4_0_10 = a3_0_10 + a3_0_4 * a4_4_10;
let t4_0 = t3_0 + a3_0_4 * t4_4;
let a4_1_5 = a3_1_5 + a3_1_4 * a4_4_5;
let a4_1_6 = a3_1_6 + a3_1_4 * a4_4_6;
let a4_1_7 = a3_1_7 + a3_1_4 * a4_4_7;
let a4_1_8 = a3_1_8 + a3_1_4 * a4_4_8;
let a4_1_9 = a3_1_9 + a3_1_4 * a4_4_9;
let a4_1_10 = a3_1_10 + a3_1_4 * a4_4_10;
let t4_1 = t3_1 + a3_1_4 * t4_4;
let a4_2_5 = a3_2_5 + a3_2_4 * a4_4_5;
let a4_2_6 = a3_2_6 + a3_2_4 * a4_4_6;
let a4_2_7 = a3_2_7 + a3_2_4 * a4_4_7;
let a4_2_8 = a3_2_8 + a3_2_4 * a4_4_8;
let a4_2_9 = a3_2_9 + a3_2_4 * a4_4_9;
let a4_2_10 = a3_2_10 + a3_2_4 * a4_4_10;
let t4_2 = t3_2 + a3_2_4 * t4_4;
let a4_3_5 = a3_3_5 + a3_3_4 * a4_4_5;
let a4_3_6 = a3_3_6 + a3_3_4 * a4_4_6;
let a4_3_7 = a3_3_7 + a3_3_4 * a4_4_7;
let a4_3_8 = a3_3_8 + a3_3_4 * a4_4_8;
let a4_3_9 = a3_3_9 + a3_3_4 * a4_4_9;
let a4_3_10 = a3_3_10 + a3_3_4 * a4_4_10;
let t4_3 = t3_3 + a3_3_4 * t4_4;
let a4_5_5 = a3_5_5 + a3_5_4 * a4_4_5;
let a4_5_6 = a3_5_6 + a3_5_4 * a4_4_6;
let a4_5_7 = a3_5_7 + a3_5_4 * a4_4_7;
let a4_5_8 = a3_5_8 + a3_5_4 * a4_4_8;
let a4_5_9 = a3_5_9 + a3_5_4 * a4_4_9;
let a4_5_10 = a3_5_10 + a3_5_4 * a4_4_10;
let t4_5 = t3_5 + a3_5_4 * t4_4;
let a4_6_5 = a3_6_5 + a3_6_4 * a4_4_5;
let a4_6_6 = a3_6_6 + a3_6_4 * a4_4_6;
let a4_6_7 = a3_6_7 + a3_6_4 * a4_4_7;
let a4_6_8 = a3_6_8 + a3_6_4 * a4_4_8;
let a4_6_9 = a3_6_9 + a3_6_4 * a4_4_9;
let a4_6_10 = a3_6_10 + a3_6_4 * a4_4_10;
let t4_6 = t3_6 + a3_6_4 * t4_4;
let a4_7_5 = a3_7_5 + a3_7_4 * a4_4_5;
let a4_7_6 = a3_7_6 + a3_7_4 * a4_4_6;
let a4_7_7 = a3_7_7 + a3_7_4 * a4_4_7;
let a4_7_8 = a3_7_8 + a3_7_4 * a4_4_8;
let a4_7_9 = a3_7_9 + a3_7_4 * a4_4_9;
let a4_7_10 = a3_7_10 + a3_7_4 * a4_4_10;
let t4_7 = t3_7 + a3_7_4 * t4_4;
let a4_8_5 = a3_8_5 + a3_8_4 * a4_4_5;
let a4_8_6 = a3_8_6 + a3_8_4 * a4_4_6;
let a4_8_7 = a3_8_7 + a3_8_4 * a4_4_7;
let a4_8_8 = a3_8_8 + a3_8_4 * a4_4_8;
let a4_8_9 = a3_8_9 + a3_8_4 * a4_4_9;
let a4_8_10 = a3_8_10 + a3_8_4 * a4_4_10;
let t4_8 = t3_8 + a3_8_4 * t4_4;
let a4_9_5 = a3_9_5 + a3_9_4 * a4_4_5;
let a4_9_6 = a3_9_6 + a3_9_4 * a4_4_6;
let a4_9_7 = a3_9_7 + a3_9_4 * a4_4_7;
let a4_9_8 = a3_9_8 + a3_9_4 * a4_4_8;
let a4_9_9 = a3_9_9 + a3_9_4 * a4_4_9;
let a4_9_10 = a3_9_10 + a3_9_4 * a4_4_10;
let t4_9 = t3_9 + a3_9_4 * t4_4;
let a4_10_5 = a3_10_5 + a3_10_4 * a4_4_5;
let a4_10_6 = a3_10_6 + a3_10_4 * a4_4_6;
let a4_10_7 = a3_10_7 + a3_10_4 * a4_4_7;
let a4_10_8 = a3_10_8 + a3_10_4 * a4_4_8;
let a4_10_9 = a3_10_9 + a3_10_4 * a4_4_9;
let a4_10_10 = a3_10_10 + a3_10_4 * a4_4_10;
let t4_10 = t3_10 + a3_10_4 * t4_4;
{
let zm = max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t4_0), b0)), select(Scalar(0.0), abs(t4_1), b1)), select(Scalar(0.0), abs(t4_2), b2)), abs(t4_3)), abs(t4_4));
let zs = (((((Scalar(0.0) + select(Scalar(0.0), abs(t4_0), b0)) + select(Scalar(0.0), abs(t4_1), b1)) + select(Scalar(0.0), abs(t4_2), b2)) + abs(t4_3)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 24u), l4 & (t4_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t4_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t4_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t4_3 >= -tol.screen * zm) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t4_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t4_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t4_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t4_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a4_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l4 & !dead10 & !(a4_10_10 > tol.tree_pivot * m10_10));
let l10 = l4 & !dead10;
let i10 = Scalar(1.0) / a4_10_10;
let n10 = -i10;
let t10_10 = -t4_10 * i10;
let t10_0 = t4_0 + a4_0_10 * t10_10;
let t10_1 = t4_1 + a4_1_10 * t10_10;
let t10_2 = t4_2 + a4_2_10 * t10_10;
let t10_3 = t4_3 + a4_3_10 * t10_10;
let t10_4 = t4_4 + a4_4_10 * t10_10;
let t10_5 = t4_5 + a4_5_10 * t10_10;
let t10_6 = t4_6 + a4_6_10 * t10_10;
let t10_7 = t4_7 + a4_7_10 * t10_10;
let t10_8 = t4_8 + a4_8_10 * t10_10;
let t10_9 = t4_9 + a4_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_10));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_10));
c32 = c32 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a4_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l4 & !dead9 & !(a4_9_9 > tol.tree_pivot * m9_9));
let l9 = l4 & !dead9;
let i9 = Scalar(1.0) / a4_9_9;
let n9 = -i9;
let a9_9_10 = a4_9_10 * n9;
let t9_9 = -t4_9 * i9;
let a9_0_10 = a4_0_10 + a4_0_9 * a9_9_10;
let t9_0 = t4_0 + a4_0_9 * t9_9;
let a9_1_10 = a4_1_10 + a4_1_9 * a9_9_10;
let t9_1 = t4_1 + a4_1_9 * t9_9;
let a9_2_10 = a4_2_10 + a4_2_9 * a9_9_10;
let t9_2 = t4_2 + a4_2_9 * t9_9;
let a9_3_10 = a4_3_10 + a4_3_9 * a9_9_10;
let t9_3 = t4_3 + a4_3_9 * t9_9;
let a9_4_10 = a4_4_10 + a4_4_9 * a9_9_10;
let t9_4 = t4_4 + a4_4_9 * t9_9;
let a9_5_10 = a4_5_10 + a4_5_9 * a9_9_10;
let t9_5 = t4_5 + a4_5_9 * t9_9;
let a9_6_10 = a4_6_10 + a4_6_9 * a9_9_10;
let t9_6 = t4_6 + a4_6_9 * t9_9;
let a9_7_10 = a4_7_10 + a4_7_9 * a9_9_10;
let t9_7 = t4_7 + a4_7_9 * t9_9;
let a9_8_10 = a4_8_10 + a4_8_9 * a9_9_10;
let t9_8 = t4_8 + a4_8_9 * t9_9;
let a9_10_10 = a4_10_10 + a4_10_9 * a9_9_10;
let t9_10 = t4_10 + a4_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_4)), abs(t9_9));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_4)) + abs(t9_9));
c16 = c16 | select(0u, 1u << (pre | 24u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_9)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_9)) + abs(t10_10));
c48 = c48 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a4_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l4 & !dead8 & !(a4_8_8 > tol.tree_pivot * m8_8));
let l8 = l4 & !dead8;
let i8 = Scalar(1.0) / a4_8_8;
let n8 = -i8;
let a8_8_9 = a4_8_9 * n8;
let a8_8_10 = a4_8_10 * n8;
let t8_8 = -t4_8 * i8;
let a8_0_9 = a4_0_9 + a4_0_8 * a8_8_9;
let a8_0_10 = a4_0_10 + a4_0_8 * a8_8_10;
let t8_0 = t4_0 + a4_0_8 * t8_8;
let a8_1_9 = a4_1_9 + a4_1_8 * a8_8_9;
let a8_1_10 = a4_1_10 + a4_1_8 * a8_8_10;
let t8_1 = t4_1 + a4_1_8 * t8_8;
let a8_2_9 = a4_2_9 + a4_2_8 * a8_8_9;
let a8_2_10 = a4_2_10 + a4_2_8 * a8_8_10;
let t8_2 = t4_2 + a4_2_8 * t8_8;
let a8_3_9 = a4_3_9 + a4_3_8 * a8_8_9;
let a8_3_10 = a4_3_10 + a4_3_8 * a8_8_10;
let t8_3 = t4_3 + a4_3_8 * t8_8;
let a8_4_9 = a4_4_9 + a4_4_8 * a8_8_9;
let a8_4_10 = a4_4_10 + a4_4_8 * a8_8_10;
let t8_4 = t4_4 + a4_4_8 * t8_8;
let a8_5_9 = a4_5_9 + a4_5_8 * a8_8_9;
let a8_5_10 = a4_5_10 + a4_5_8 * a8_8_10;
let t8_5 = t4_5 + a4_5_8 * t8_8;
let a8_6_9 = a4_6_9 + a4_6_8 * a8_8_9;
let a8_6_10 = a4_6_10 + a4_6_8 * a8_8_10;
let t8_6 = t4_6 + a4_6_8 * t8_8;
let a8_7_9 = a4_7_9 + a4_7_8 * a8_8_9;
let a8_7_10 = a4_7_10 + a4_7_8 * a8_8_10;
let t8_7 = t4_7 + a4_7_8 * t8_8;
let a8_9_9 = a4_9_9 + a4_9_8 * a8_8_9;
let a8_9_10 = a4_9_10 + a4_9_8 * a8_8_10;
let t8_9 = t4_9 + a4_9_8 * t8_8;
let a8_10_9 = a4_10_9 + a4_10_8 * a8_8_9;
let a8_10_10 = a4_10_10 + a4_10_8 * a8_8_10;
let t8_10 = t4_10 + a4_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_3)), abs(t8_4)), abs(t8_8));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_8));
c8 = c8 | select(0u, 1u << (pre | 24u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_8)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_8)) + abs(t10_10));
c40 = c40 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_4)), abs(t9_8)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_4)) + abs(t9_8)) + abs(t9_9));
c24 = c24 | select(0u, 1u << (pre | 24u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c56 = c56 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
}
{
let dead7 = semi & !(a4_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l4 & !dead7 & !(a4_7_7 > tol.tree_pivot * m7_7));
let l7 = l4 & !dead7;
let i7 = Scalar(1.0) / a4_7_7;
let n7 = -i7;
let a7_7_8 = a4_7_8 * n7;
let a7_7_9 = a4_7_9 * n7;
let a7_7_10 = a4_7_10 * n7;
let t7_7 = -t4_7 * i7;
let a7_0_8 = a4_0_8 + a4_0_7 * a7_7_8;
let a7_0_9 = a4_0_9 + a4_0_7 * a7_7_9;
let a7_0_10 = a4_0_10 + a4_0_7 * a7_7_10;
let t7_0 = t4_0 + a4_0_7 * t7_7;
let a7_1_8 = a4_1_8 + a4_1_7 * a7_7_8;
let a7_1_9 = a4_1_9 + a4_1_7 * a7_7_9;
let a7_1_10 = a4_1_10 + a4_1_7 * a7_7_10;
let t7_1 = t4_1 + a4_1_7 * t7_7;
let a7_2_8 = a4_2_8 + a4_2_7 * a7_7_8;
let a7_2_9 = a4_2_9 + a4_2_7 * a7_7_9;
let a7_2_10 = a4_2_10 + a4_2_7 * a7_7_10;
let t7_2 = t4_2 + a4_2_7 * t7_7;
let a7_3_8 = a4_3_8 + a4_3_7 * a7_7_8;
let a7_3_9 = a4_3_9 + a4_3_7 * a7_7_9;
let a7_3_10 = a4_3_10 + a4_3_7 * a7_7_10;
let t7_3 = t4_3 + a4_3_7 * t7_7;
let a7_4_8 = a4_4_8 + a4_4_7 * a7_7_8;
let a7_4_9 = a4_4_9 + a4_4_7 * a7_7_9;
let a7_4_10 = a4_4_10 + a4_4_7 * a7_7_10;
let t7_4 = t4_4 + a4_4_7 * t7_7;
let a7_5_8 = a4_5_8 + a4_5_7 * a7_7_8;
let a7_5_9 = a4_5_9 + a4_5_7 * a7_7_9;
let a7_5_10 = a4_5_10 + a4_5_7 * a7_7_10;
let t7_5 = t4_5 + a4_5_7 * t7_7;
let a7_6_8 = a4_6_8 + a4_6_7 * a7_7_8;
let a7_6_9 = a4_6_9 + a4_6_7 * a7_7_9;
let a7_6_10 = a4_6_10 + a4_6_7 * a7_7_10;
let t7_6 = t4_6 + a4_6_7 * t7_7;
let a7_8_8 = a4_8_8 + a4_8_7 * a7_7_8;
let a7_8_9 = a4_8_9 + a4_8_7 * a7_7_9;
let a7_8_10 = a4_8_10 + a4_8_7 * a7_7_10;
let t7_8 = t4_8 + a4_8_7 * t7_7;
let a7_9_8 = a4_9_8 + a4_9_7 * a7_7_8;
let a7_9_9 = a4_9_9 + a4_9_7 * a7_7_9;
let a7_9_10 = a4_9_10 + a4_9_7 * a7_7_10;
let t7_9 = t4_9 + a4_9_7 * t7_7;
let a7_10_8 = a4_10_8 + a4_10_7 * a7_7_8;
let a7_10_9 = a4_10_9 + a4_10_7 * a7_7_9;
let a7_10_10 = a4_10_10 + a4_10_7 * a7_7_10;
let t7_10 = t4_10 + a4_10_7 * t7_7;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), select(Scalar(0.0), abs(t7_1), b1)), select(Scalar(0.0), abs(t7_2), b2)), abs(t7_3)), abs(t7_4)), abs(t7_7));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + select(Scalar(0.0), abs(t7_1), b1)) + select(Scalar(0.0), abs(t7_2), b2)) + abs(t7_3)) + abs(t7_4)) + abs(t7_7));
c4 = c4 | select(0u, 1u << (pre | 24u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t7_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t7_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t7_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a7_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l7 & !dead10 & !(a7_10_10 > tol.tree_pivot * m10_10));
let l10 = l7 & !dead10;
let i10 = Scalar(1.0) / a7_10_10;
let n10 = -i10;
let t10_10 = -t7_10 * i10;
let t10_0 = t7_0 + a7_0_10 * t10_10;
let t10_1 = t7_1 + a7_1_10 * t10_10;
let t10_2 = t7_2 + a7_2_10 * t10_10;
let t10_3 = t7_3 + a7_3_10 * t10_10;
let t10_4 = t7_4 + a7_4_10 * t10_10;
let t10_5 = t7_5 + a7_5_10 * t10_10;
let t10_6 = t7_6 + a7_6_10 * t10_10;
let t10_7 = t7_7 + a7_7_10 * t10_10;
let t10_8 = t7_8 + a7_8_10 * t10_10;
let t10_9 = t7_9 + a7_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_7)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_7)) + abs(t10_10));
c36 = c36 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a7_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l7 & !dead9 & !(a7_9_9 > tol.tree_pivot * m9_9));
let l9 = l7 & !dead9;
let i9 = Scalar(1.0) / a7_9_9;
let n9 = -i9;
let a9_9_10 = a7_9_10 * n9;
let t9_9 = -t7_9 * i9;
let a9_0_10 = a7_0_10 + a7_0_9 * a9_9_10;
let t9_0 = t7_0 + a7_0_9 * t9_9;
let a9_1_10 = a7_1_10 + a7_1_9 * a9_9_10;
let t9_1 = t7_1 + a7_1_9 * t9_9;
let a9_2_10 = a7_2_10 + a7_2_9 * a9_9_10;
let t9_2 = t7_2 + a7_2_9 * t9_9;
let a9_3_10 = a7_3_10 + a7_3_9 * a9_9_10;
let t9_3 = t7_3 + a7_3_9 * t9_9;
let a9_4_10 = a7_4_10 + a7_4_9 * a9_9_10;
let t9_4 = t7_4 + a7_4_9 * t9_9;
let a9_5_10 = a7_5_10 + a7_5_9 * a9_9_10;
let t9_5 = t7_5 + a7_5_9 * t9_9;
let a9_6_10 = a7_6_10 + a7_6_9 * a9_9_10;
let t9_6 = t7_6 + a7_6_9 * t9_9;
let a9_7_10 = a7_7_10 + a7_7_9 * a9_9_10;
let t9_7 = t7_7 + a7_7_9 * t9_9;
let a9_8_10 = a7_8_10 + a7_8_9 * a9_9_10;
let t9_8 = t7_8 + a7_8_9 * t9_9;
let a9_10_10 = a7_10_10 + a7_10_9 * a9_9_10;
let t9_10 = t7_10 + a7_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_4)), abs(t9_7)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_4)) + abs(t9_7)) + abs(t9_9));
c20 = c20 | select(0u, 1u << (pre | 24u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_7)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_7)) + abs(t10_9)) + abs(t10_10));
c52 = c52 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let a8_8_9 = a7_8_9 * n8;
let a8_8_10 = a7_8_10 * n8;
let t8_8 = -t7_8 * i8;
let a8_0_9 = a7_0_9 + a7_0_8 * a8_8_9;
let a8_0_10 = a7_0_10 + a7_0_8 * a8_8_10;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let a8_1_9 = a7_1_9 + a7_1_8 * a8_8_9;
let a8_1_10 = a7_1_10 + a7_1_8 * a8_8_10;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let a8_2_9 = a7_2_9 + a7_2_8 * a8_8_9;
let a8_2_10 = a7_2_10 + a7_2_8 * a8_8_10;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let a8_3_9 = a7_3_9 + a7_3_8 * a8_8_9;
let a8_3_10 = a7_3_10 + a7_3_8 * a8_8_10;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let a8_4_9 = a7_4_9 + a7_4_8 * a8_8_9;
let a8_4_10 = a7_4_10 + a7_4_8 * a8_8_10;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let a8_5_9 = a7_5_9 + a7_5_8 * a8_8_9;
let a8_5_10 = a7_5_10 + a7_5_8 * a8_8_10;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let a8_6_9 = a7_6_9 + a7_6_8 * a8_8_9;
let a8_6_10 = a7_6_10 + a7_6_8 * a8_8_10;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let a8_7_9 = a7_7_9 + a7_7_8 * a8_8_9;
let a8_7_10 = a7_7_10 + a7_7_8 * a8_8_10;
let t8_7 = t7_7 + a7_7_8 * t8_8;
let a8_9_9 = a7_9_9 + a7_9_8 * a8_8_9;
let a8_9_10 = a7_9_10 + a7_9_8 * a8_8_10;
let t8_9 = t7_9 + a7_9_8 * t8_8;
let a8_10_9 = a7_10_9 + a7_10_8 * a8_8_9;
let a8_10_10 = a7_10_10 + a7_10_8 * a8_8_10;
let t8_10 = t7_10 + a7_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_3)), abs(t8_4)), abs(t8_7)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_7)) + abs(t8_8));
c12 = c12 | select(0u, 1u << (pre | 24u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_7)), abs(t10_8)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_7)) + abs(t10_8)) + abs(t10_10));
c44 = c44 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_4)), abs(t9_7)), abs(t9_8)), abs(t9_9));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_4)) + abs(t9_7)) + abs(t9_8)) + abs(t9_9));
c28 = c28 | select(0u, 1u << (pre | 24u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_7)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_7)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c60 = c60 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
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
let a6_6_9 = a4_6_9 * n6;
let a6_6_10 = a4_6_10 * n6;
let t6_6 = -t4_6 * i6;
let a6_0_7 = a4_0_7 + a4_0_6 * a6_6_7;
let a6_0_8 = a4_0_8 + a4_0_6 * a6_6_8;
let a6_0_9 = a4_0_9 + a4_0_6 * a6_6_9;
let a6_0_10 = a4_0_10 + a4_0_6 * a6_6_10;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let a6_1_7 = a4_1_7 + a4_1_6 * a6_6_7;
let a6_1_8 = a4_1_8 + a4_1_6 * a6_6_8;
let a6_1_9 = a4_1_9 + a4_1_6 * a6_6_9;
let a6_1_10 = a4_1_10 + a4_1_6 * a6_6_10;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let a6_2_7 = a4_2_7 + a4_2_6 * a6_6_7;
let a6_2_8 = a4_2_8 + a4_2_6 * a6_6_8;
let a6_2_9 = a4_2_9 + a4_2_6 * a6_6_9;
let a6_2_10 = a4_2_10 + a4_2_6 * a6_6_10;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let a6_3_7 = a4_3_7 + a4_3_6 * a6_6_7;
let a6_3_8 = a4_3_8 + a4_3_6 * a6_6_8;
let a6_3_9 = a4_3_9 + a4_3_6 * a6_6_9;
let a6_3_10 = a4_3_10 + a4_3_6 * a6_6_10;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let a6_4_7 = a4_4_7 + a4_4_6 * a6_6_7;
let a6_4_8 = a4_4_8 + a4_4_6 * a6_6_8;
let a6_4_9 = a4_4_9 + a4_4_6 * a6_6_9;
let a6_4_10 = a4_4_10 + a4_4_6 * a6_6_10;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let a6_5_7 = a4_5_7 + a4_5_6 * a6_6_7;
let a6_5_8 = a4_5_8 + a4_5_6 * a6_6_8;
let a6_5_9 = a4_5_9 + a4_5_6 * a6_6_9;
let a6_5_10 = a4_5_10 + a4_5_6 * a6_6_10;
let t6_5 = t4_5 + a4_5_6 * t6_6;
let a6_7_7 = a4_7_7 + a4_7_6 * a6_6_7;
let a6_7_8 = a4_7_8 + a4_7_6 * a6_6_8;
let a6_7_9 = a4_7_9 + a4_7_6 * a6_6_9;
let a6_7_10 = a4_7_10 + a4_7_6 * a6_6_10;
let t6_7 = t4_7 + a4_7_6 * t6_6;
let a6_8_7 = a4_8_7 + a4_8_6 * a6_6_7;
let a6_8_8 = a4_8_8 + a4_8_6 * a6_6_8;
let a6_8_9 = a4_8_9 + a4_8_6 * a6_6_9;
let a6_8_10 = a4_8_10 + a4_8_6 * a6_6_10;
let t6_8 = t4_8 + a4_8_6 * t6_6;
let a6_9_7 = a4_9_7 + a4_9_6 * a6_6_7;
let a6_9_8 = a4_9_8 + a4_9_6 * a6_6_8;
let a6_9_9 = a4_9_9 + a4_9_6 * a6_6_9;
let a6_9_10 = a4_9_10 + a4_9_6 * a6_6_10;
let t6_9 = t4_9 + a4_9_6 * t6_6;
let a6_10_7 = a4_10_7 + a4_10_6 * a6_6_7;
let a6_10_8 = a4_10_8 + a4_10_6 * a6_6_8;
let a6_10_9 = a4_10_9 + a4_10_6 * a6_6_9;
let a6_10_10 = a4_10_10 + a4_10_6 * a6_6_10;
let t6_10 = t4_10 + a4_10_6 * t6_6;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), select(Scalar(0.0), abs(t6_1), b1)), select(Scalar(0.0), abs(t6_2), b2)), abs(t6_3)), abs(t6_4)), abs(t6_6));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + select(Scalar(0.0), abs(t6_1), b1)) + select(Scalar(0.0), abs(t6_2), b2)) + abs(t6_3)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 24u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t6_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t6_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t6_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a6_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l6 & !dead10 & !(a6_10_10 > tol.tree_pivot * m10_10));
let l10 = l6 & !dead10;
let i10 = Scalar(1.0) / a6_10_10;
let n10 = -i10;
let t10_10 = -t6_10 * i10;
let t10_0 = t6_0 + a6_0_10 * t10_10;
let t10_1 = t6_1 + a6_1_10 * t10_10;
let t10_2 = t6_2 + a6_2_10 * t10_10;
let t10_3 = t6_3 + a6_3_10 * t10_10;
let t10_4 = t6_4 + a6_4_10 * t10_10;
let t10_5 = t6_5 + a6_5_10 * t10_10;
let t10_6 = t6_6 + a6_6_10 * t10_10;
let t10_7 = t6_7 + a6_7_10 * t10_10;
let t10_8 = t6_8 + a6_8_10 * t10_10;
let t10_9 = t6_9 + a6_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_6)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_6)) + abs(t10_10));
c34 = c34 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a6_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l6 & !dead9 & !(a6_9_9 > tol.tree_pivot * m9_9));
let l9 = l6 & !dead9;
let i9 = Scalar(1.0) / a6_9_9;
let n9 = -i9;
let a9_9_10 = a6_9_10 * n9;
let t9_9 = -t6_9 * i9;
let a9_0_10 = a6_0_10 + a6_0_9 * a9_9_10;
let t9_0 = t6_0 + a6_0_9 * t9_9;
let a9_1_10 = a6_1_10 + a6_1_9 * a9_9_10;
let t9_1 = t6_1 + a6_1_9 * t9_9;
let a9_2_10 = a6_2_10 + a6_2_9 * a9_9_10;
let t9_2 = t6_2 + a6_2_9 * t9_9;
let a9_3_10 = a6_3_10 + a6_3_9 * a9_9_10;
let t9_3 = t6_3 + a6_3_9 * t9_9;
let a9_4_10 = a6_4_10 + a6_4_9 * a9_9_10;
let t9_4 = t6_4 + a6_4_9 * t9_9;
let a9_5_10 = a6_5_10 + a6_5_9 * a9_9_10;
let t9_5 = t6_5 + a6_5_9 * t9_9;
let a9_6_10 = a6_6_10 + a6_6_9 * a9_9_10;
let t9_6 = t6_6 + a6_6_9 * t9_9;
let a9_7_10 = a6_7_10 + a6_7_9 * a9_9_10;
let t9_7 = t6_7 + a6_7_9 * t9_9;
let a9_8_10 = a6_8_10 + a6_8_9 * a9_9_10;
let t9_8 = t6_8 + a6_8_9 * t9_9;
let a9_10_10 = a6_10_10 + a6_10_9 * a9_9_10;
let t9_10 = t6_10 + a6_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_4)), abs(t9_6)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_4)) + abs(t9_6)) + abs(t9_9));
c18 = c18 | select(0u, 1u << (pre | 24u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_6)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_6)) + abs(t10_9)) + abs(t10_10));
c50 = c50 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let a8_8_9 = a6_8_9 * n8;
let a8_8_10 = a6_8_10 * n8;
let t8_8 = -t6_8 * i8;
let a8_0_9 = a6_0_9 + a6_0_8 * a8_8_9;
let a8_0_10 = a6_0_10 + a6_0_8 * a8_8_10;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let a8_1_9 = a6_1_9 + a6_1_8 * a8_8_9;
let a8_1_10 = a6_1_10 + a6_1_8 * a8_8_10;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let a8_2_9 = a6_2_9 + a6_2_8 * a8_8_9;
let a8_2_10 = a6_2_10 + a6_2_8 * a8_8_10;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let a8_3_9 = a6_3_9 + a6_3_8 * a8_8_9;
let a8_3_10 = a6_3_10 + a6_3_8 * a8_8_10;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let a8_4_9 = a6_4_9 + a6_4_8 * a8_8_9;
let a8_4_10 = a6_4_10 + a6_4_8 * a8_8_10;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let a8_5_9 = a6_5_9 + a6_5_8 * a8_8_9;
let a8_5_10 = a6_5_10 + a6_5_8 * a8_8_10;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let a8_6_9 = a6_6_9 + a6_6_8 * a8_8_9;
let a8_6_10 = a6_6_10 + a6_6_8 * a8_8_10;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let a8_7_9 = a6_7_9 + a6_7_8 * a8_8_9;
let a8_7_10 = a6_7_10 + a6_7_8 * a8_8_10;
let t8_7 = t6_7 + a6_7_8 * t8_8;
let a8_9_9 = a6_9_9 + a6_9_8 * a8_8_9;
let a8_9_10 = a6_9_10 + a6_9_8 * a8_8_10;
let t8_9 = t6_9 + a6_9_8 * t8_8;
let a8_10_9 = a6_10_9 + a6_10_8 * a8_8_9;
let a8_10_10 = a6_10_10 + a6_10_8 * a8_8_10;
let t8_10 = t6_10 + a6_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_3)), abs(t8_4)), abs(t8_6)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_6)) + abs(t8_8));
c10 = c10 | select(0u, 1u << (pre | 24u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_6)), abs(t10_8)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_6)) + abs(t10_8)) + abs(t10_10));
c42 = c42 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_4)), abs(t9_6)), abs(t9_8)), abs(t9_9));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_4)) + abs(t9_6)) + abs(t9_8)) + abs(t9_9));
c26 = c26 | select(0u, 1u << (pre | 24u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_6)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_6)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c58 = c58 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let a7_7_9 = a6_7_9 * n7;
let a7_7_10 = a6_7_10 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let a7_0_9 = a6_0_9 + a6_0_7 * a7_7_9;
let a7_0_10 = a6_0_10 + a6_0_7 * a7_7_10;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let a7_1_9 = a6_1_9 + a6_1_7 * a7_7_9;
let a7_1_10 = a6_1_10 + a6_1_7 * a7_7_10;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let a7_2_9 = a6_2_9 + a6_2_7 * a7_7_9;
let a7_2_10 = a6_2_10 + a6_2_7 * a7_7_10;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let a7_3_9 = a6_3_9 + a6_3_7 * a7_7_9;
let a7_3_10 = a6_3_10 + a6_3_7 * a7_7_10;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let a7_4_9 = a6_4_9 + a6_4_7 * a7_7_9;
let a7_4_10 = a6_4_10 + a6_4_7 * a7_7_10;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let a7_5_9 = a6_5_9 + a6_5_7 * a7_7_9;
let a7_5_10 = a6_5_10 + a6_5_7 * a7_7_10;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let a7_6_9 = a6_6_9 + a6_6_7 * a7_7_9;
let a7_6_10 = a6_6_10 + a6_6_7 * a7_7_10;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let a7_8_9 = a6_8_9 + a6_8_7 * a7_7_9;
let a7_8_10 = a6_8_10 + a6_8_7 * a7_7_10;
let t7_8 = t6_8 + a6_8_7 * t7_7;
let a7_9_8 = a6_9_8 + a6_9_7 * a7_7_8;
let a7_9_9 = a6_9_9 + a6_9_7 * a7_7_9;
let a7_9_10 = a6_9_10 + a6_9_7 * a7_7_10;
let t7_9 = t6_9 + a6_9_7 * t7_7;
let a7_10_8 = a6_10_8 + a6_10_7 * a7_7_8;
let a7_10_9 = a6_10_9 + a6_10_7 * a7_7_9;
let a7_10_10 = a6_10_10 + a6_10_7 * a7_7_10;
let t7_10 = t6_10 + a6_10_7 * t7_7;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), select(Scalar(0.0), abs(t7_1), b1)), select(Scalar(0.0), abs(t7_2), b2)), abs(t7_3)), abs(t7_4)), abs(t7_6)), abs(t7_7));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + select(Scalar(0.0), abs(t7_1), b1)) + select(Scalar(0.0), abs(t7_2), b2)) + abs(t7_3)) + abs(t7_4)) + abs(t7_6)) + abs(t7_7));
c6 = c6 | select(0u, 1u << (pre | 24u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t7_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t7_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t7_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a7_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l7 & !dead10 & !(a7_10_10 > tol.tree_pivot * m10_10));
let l10 = l7 & !dead10;
let i10 = Scalar(1.0) / a7_10_10;
let n10 = -i10;
let t10_10 = -t7_10 * i10;
let t10_0 = t7_0 + a7_0_10 * t10_10;
let t10_1 = t7_1 + a7_1_10 * t10_10;
let t10_2 = t7_2 + a7_2_10 * t10_10;
let t10_3 = t7_3 + a7_3_10 * t10_10;
let t10_4 = t7_4 + a7_4_10 * t10_10;
let t10_5 = t7_5 + a7_5_10 * t10_10;
let t10_6 = t7_6 + a7_6_10 * t10_10;
let t10_7 = t7_7 + a7_7_10 * t10_10;
let t10_8 = t7_8 + a7_8_10 * t10_10;
let t10_9 = t7_9 + a7_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_6)), abs(t10_7)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_6)) + abs(t10_7)) + abs(t10_10));
c38 = c38 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a7_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l7 & !dead9 & !(a7_9_9 > tol.tree_pivot * m9_9));
let l9 = l7 & !dead9;
let i9 = Scalar(1.0) / a7_9_9;
let n9 = -i9;
let a9_9_10 = a7_9_10 * n9;
let t9_9 = -t7_9 * i9;
let a9_0_10 = a7_0_10 + a7_0_9 * a9_9_10;
let t9_0 = t7_0 + a7_0_9 * t9_9;
let a9_1_10 = a7_1_10 + a7_1_9 * a9_9_10;
let t9_1 = t7_1 + a7_1_9 * t9_9;
let a9_2_10 = a7_2_10 + a7_2_9 * a9_9_10;
let t9_2 = t7_2 + a7_2_9 * t9_9;
let a9_3_10 = a7_3_10 + a7_3_9 * a9_9_10;
let t9_3 = t7_3 + a7_3_9 * t9_9;
let a9_4_10 = a7_4_10 + a7_4_9 * a9_9_10;
let t9_4 = t7_4 + a7_4_9 * t9_9;
let a9_5_10 = a7_5_10 + a7_5_9 * a9_9_10;
let t9_5 = t7_5 + a7_5_9 * t9_9;
let a9_6_10 = a7_6_10 + a7_6_9 * a9_9_10;
let t9_6 = t7_6 + a7_6_9 * t9_9;
let a9_7_10 = a7_7_10 + a7_7_9 * a9_9_10;
let t9_7 = t7_7 + a7_7_9 * t9_9;
let a9_8_10 = a7_8_10 + a7_8_9 * a9_9_10;
let t9_8 = t7_8 + a7_8_9 * t9_9;
let a9_10_10 = a7_10_10 + a7_10_9 * a9_9_10;
let t9_10 = t7_10 + a7_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_4)), abs(t9_6)), abs(t9_7)), abs(t9_9));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_4)) + abs(t9_6)) + abs(t9_7)) + abs(t9_9));
c22 = c22 | select(0u, 1u << (pre | 24u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_6)), abs(t10_7)), abs(t10_9)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_6)) + abs(t10_7)) + abs(t10_9)) + abs(t10_10));
c54 = c54 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let a8_8_9 = a7_8_9 * n8;
let a8_8_10 = a7_8_10 * n8;
let t8_8 = -t7_8 * i8;
let a8_0_9 = a7_0_9 + a7_0_8 * a8_8_9;
let a8_0_10 = a7_0_10 + a7_0_8 * a8_8_10;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let a8_1_9 = a7_1_9 + a7_1_8 * a8_8_9;
let a8_1_10 = a7_1_10 + a7_1_8 * a8_8_10;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let a8_2_9 = a7_2_9 + a7_2_8 * a8_8_9;
let a8_2_10 = a7_2_10 + a7_2_8 * a8_8_10;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let a8_3_9 = a7_3_9 + a7_3_8 * a8_8_9;
let a8_3_10 = a7_3_10 + a7_3_8 * a8_8_10;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let a8_4_9 = a7_4_9 + a7_4_8 * a8_8_9;
let a8_4_10 = a7_4_10 + a7_4_8 * a8_8_10;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let a8_5_9 = a7_5_9 + a7_5_8 * a8_8_9;
let a8_5_10 = a7_5_10 + a7_5_8 * a8_8_10;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let a8_6_9 = a7_6_9 + a7_6_8 * a8_8_9;
let a8_6_10 = a7_6_10 + a7_6_8 * a8_8_10;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let a8_7_9 = a7_7_9 + a7_7_8 * a8_8_9;
let a8_7_10 = a7_7_10 + a7_7_8 * a8_8_10;
let t8_7 = t7_7 + a7_7_8 * t8_8;
let a8_9_9 = a7_9_9 + a7_9_8 * a8_8_9;
let a8_9_10 = a7_9_10 + a7_9_8 * a8_8_10;
let t8_9 = t7_9 + a7_9_8 * t8_8;
let a8_10_9 = a7_10_9 + a7_10_8 * a8_8_9;
let a8_10_10 = a7_10_10 + a7_10_8 * a8_8_10;
let t8_10 = t7_10 + a7_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_3)), abs(t8_4)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c14 = c14 | select(0u, 1u << (pre | 24u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_6)), abs(t10_7)), abs(t10_8)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_6)) + abs(t10_7)) + abs(t10_8)) + abs(t10_10));
c46 = c46 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_4)), abs(t9_6)), abs(t9_7)), abs(t9_8)), abs(t9_9));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_4)) + abs(t9_6)) + abs(t9_7)) + abs(t9_8)) + abs(t9_9));
c30 = c30 | select(0u, 1u << (pre | 24u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_6)), abs(t10_7)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = ((((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_6)) + abs(t10_7)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c62 = c62 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
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
let a5_5_9 = a4_5_9 * n5;
let a5_5_10 = a4_5_10 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let a5_0_7 = a4_0_7 + a4_0_5 * a5_5_7;
let a5_0_8 = a4_0_8 + a4_0_5 * a5_5_8;
let a5_0_9 = a4_0_9 + a4_0_5 * a5_5_9;
let a5_0_10 = a4_0_10 + a4_0_5 * a5_5_10;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let a5_1_7 = a4_1_7 + a4_1_5 * a5_5_7;
let a5_1_8 = a4_1_8 + a4_1_5 * a5_5_8;
let a5_1_9 = a4_1_9 + a4_1_5 * a5_5_9;
let a5_1_10 = a4_1_10 + a4_1_5 * a5_5_10;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let a5_2_7 = a4_2_7 + a4_2_5 * a5_5_7;
let a5_2_8 = a4_2_8 + a4_2_5 * a5_5_8;
let a5_2_9 = a4_2_9 + a4_2_5 * a5_5_9;
let a5_2_10 = a4_2_10 + a4_2_5 * a5_5_10;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let a5_3_7 = a4_3_7 + a4_3_5 * a5_5_7;
let a5_3_8 = a4_3_8 + a4_3_5 * a5_5_8;
let a5_3_9 = a4_3_9 + a4_3_5 * a5_5_9;
let a5_3_10 = a4_3_10 + a4_3_5 * a5_5_10;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let a5_4_7 = a4_4_7 + a4_4_5 * a5_5_7;
let a5_4_8 = a4_4_8 + a4_4_5 * a5_5_8;
let a5_4_9 = a4_4_9 + a4_4_5 * a5_5_9;
let a5_4_10 = a4_4_10 + a4_4_5 * a5_5_10;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let a5_6_7 = a4_6_7 + a4_6_5 * a5_5_7;
let a5_6_8 = a4_6_8 + a4_6_5 * a5_5_8;
let a5_6_9 = a4_6_9 + a4_6_5 * a5_5_9;
let a5_6_10 = a4_6_10 + a4_6_5 * a5_5_10;
let t5_6 = t4_6 + a4_6_5 * t5_5;
let a5_7_6 = a4_7_6 + a4_7_5 * a5_5_6;
let a5_7_7 = a4_7_7 + a4_7_5 * a5_5_7;
let a5_7_8 = a4_7_8 + a4_7_5 * a5_5_8;
let a5_7_9 = a4_7_9 + a4_7_5 * a5_5_9;
let a5_7_10 = a4_7_10 + a4_7_5 * a5_5_10;
let t5_7 = t4_7 + a4_7_5 * t5_5;
let a5_8_6 = a4_8_6 + a4_8_5 * a5_5_6;
let a5_8_7 = a4_8_7 + a4_8_5 * a5_5_7;
let a5_8_8 = a4_8_8 + a4_8_5 * a5_5_8;
let a5_8_9 = a4_8_9 + a4_8_5 * a5_5_9;
let a5_8_10 = a4_8_10 + a4_8_5 * a5_5_10;
let t5_8 = t4_8 + a4_8_5 * t5_5;
let a5_9_6 = a4_9_6 + a4_9_5 * a5_5_6;
let a5_9_7 = a4_9_7 + a4_9_5 * a5_5_7;
let a5_9_8 = a4_9_8 + a4_9_5 * a5_5_8;
let a5_9_9 = a4_9_9 + a4_9_5 * a5_5_9;
let a5_9_10 = a4_9_10 + a4_9_5 * a5_5_10;
let t5_9 = t4_9 + a4_9_5 * t5_5;
let a5_10_6 = a4_10_6 + a4_10_5 * a5_5_6;
let a5_10_7 = a4_10_7 + a4_10_5 * a5_5_7;
let a5_10_8 = a4_10_8 + a4_10_5 * a5_5_8;
let a5_10_9 = a4_10_9 + a4_10_5 * a5_5_9;
let a5_10_10 = a4_10_10 + a4_10_5 * a5_5_10;
let t5_10 = t4_10 + a4_10_5 * t5_5;
{
let zm = max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t5_0), b0)), select(Scalar(0.0), abs(t5_1), b1)), select(Scalar(0.0), abs(t5_2), b2)), abs(t5_3)), abs(t5_4)), abs(t5_5));
let zs = ((((((Scalar(0.0) + select(Scalar(0.0), abs(t5_0), b0)) + select(Scalar(0.0), abs(t5_1), b1)) + select(Scalar(0.0), abs(t5_2), b2)) + abs(t5_3)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 24u), l5 & (t5_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t5_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t5_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t5_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t5_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t5_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t5_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a5_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l5 & !dead10 & !(a5_10_10 > tol.tree_pivot * m10_10));
let l10 = l5 & !dead10;
let i10 = Scalar(1.0) / a5_10_10;
let n10 = -i10;
let t10_10 = -t5_10 * i10;
let t10_0 = t5_0 + a5_0_10 * t10_10;
let t10_1 = t5_1 + a5_1_10 * t10_10;
let t10_2 = t5_2 + a5_2_10 * t10_10;
let t10_3 = t5_3 + a5_3_10 * t10_10;
let t10_4 = t5_4 + a5_4_10 * t10_10;
let t10_5 = t5_5 + a5_5_10 * t10_10;
let t10_6 = t5_6 + a5_6_10 * t10_10;
let t10_7 = t5_7 + a5_7_10 * t10_10;
let t10_8 = t5_8 + a5_8_10 * t10_10;
let t10_9 = t5_9 + a5_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_5)), abs(t10_10));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_5)) + abs(t10_10));
c33 = c33 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a5_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l5 & !dead9 & !(a5_9_9 > tol.tree_pivot * m9_9));
let l9 = l5 & !dead9;
let i9 = Scalar(1.0) / a5_9_9;
let n9 = -i9;
let a9_9_10 = a5_9_10 * n9;
let t9_9 = -t5_9 * i9;
let a9_0_10 = a5_0_10 + a5_0_9 * a9_9_10;
let t9_0 = t5_0 + a5_0_9 * t9_9;
let a9_1_10 = a5_1_10 + a5_1_9 * a9_9_10;
let t9_1 = t5_1 + a5_1_9 * t9_9;
let a9_2_10 = a5_2_10 + a5_2_9 * a9_9_10;
let t9_2 = t5_2 + a5_2_9 * t9_9;
let a9_3_10 = a5_3_10 + a5_3_9 * a9_9_10;
let t9_3 = t5_3 + a5_3_9 * t9_9;
let a9_4_10 = a5_4_10 + a5_4_9 * a9_9_10;
let t9_4 = t5_4 + a5_4_9 * t9_9;
let a9_5_10 = a5_5_10 + a5_5_9 * a9_9_10;
let t9_5 = t5_5 + a5_5_9 * t9_9;
let a9_6_10 = a5_6_10 + a5_6_9 * a9_9_10;
let t9_6 = t5_6 + a5_6_9 * t9_9;
let a9_7_10 = a5_7_10 + a5_7_9 * a9_9_10;
let t9_7 = t5_7 + a5_7_9 * t9_9;
let a9_8_10 = a5_8_10 + a5_8_9 * a9_9_10;
let t9_8 = t5_8 + a5_8_9 * t9_9;
let a9_10_10 = a5_10_10 + a5_10_9 * a9_9_10;
let t9_10 = t5_10 + a5_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_4)), abs(t9_5)), abs(t9_9));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_4)) + abs(t9_5)) + abs(t9_9));
c17 = c17 | select(0u, 1u << (pre | 24u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_5)), abs(t10_9)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_5)) + abs(t10_9)) + abs(t10_10));
c49 = c49 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a5_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l5 & !dead8 & !(a5_8_8 > tol.tree_pivot * m8_8));
let l8 = l5 & !dead8;
let i8 = Scalar(1.0) / a5_8_8;
let n8 = -i8;
let a8_8_9 = a5_8_9 * n8;
let a8_8_10 = a5_8_10 * n8;
let t8_8 = -t5_8 * i8;
let a8_0_9 = a5_0_9 + a5_0_8 * a8_8_9;
let a8_0_10 = a5_0_10 + a5_0_8 * a8_8_10;
let t8_0 = t5_0 + a5_0_8 * t8_8;
let a8_1_9 = a5_1_9 + a5_1_8 * a8_8_9;
let a8_1_10 = a5_1_10 + a5_1_8 * a8_8_10;
let t8_1 = t5_1 + a5_1_8 * t8_8;
let a8_2_9 = a5_2_9 + a5_2_8 * a8_8_9;
let a8_2_10 = a5_2_10 + a5_2_8 * a8_8_10;
let t8_2 = t5_2 + a5_2_8 * t8_8;
let a8_3_9 = a5_3_9 + a5_3_8 * a8_8_9;
let a8_3_10 = a5_3_10 + a5_3_8 * a8_8_10;
let t8_3 = t5_3 + a5_3_8 * t8_8;
let a8_4_9 = a5_4_9 + a5_4_8 * a8_8_9;
let a8_4_10 = a5_4_10 + a5_4_8 * a8_8_10;
let t8_4 = t5_4 + a5_4_8 * t8_8;
let a8_5_9 = a5_5_9 + a5_5_8 * a8_8_9;
let a8_5_10 = a5_5_10 + a5_5_8 * a8_8_10;
let t8_5 = t5_5 + a5_5_8 * t8_8;
let a8_6_9 = a5_6_9 + a5_6_8 * a8_8_9;
let a8_6_10 = a5_6_10 + a5_6_8 * a8_8_10;
let t8_6 = t5_6 + a5_6_8 * t8_8;
let a8_7_9 = a5_7_9 + a5_7_8 * a8_8_9;
let a8_7_10 = a5_7_10 + a5_7_8 * a8_8_10;
let t8_7 = t5_7 + a5_7_8 * t8_8;
let a8_9_9 = a5_9_9 + a5_9_8 * a8_8_9;
let a8_9_10 = a5_9_10 + a5_9_8 * a8_8_10;
let t8_9 = t5_9 + a5_9_8 * t8_8;
let a8_10_9 = a5_10_9 + a5_10_8 * a8_8_9;
let a8_10_10 = a5_10_10 + a5_10_8 * a8_8_10;
let t8_10 = t5_10 + a5_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_8));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_8));
c9 = c9 | select(0u, 1u << (pre | 24u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_5)), abs(t10_8)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_5)) + abs(t10_8)) + abs(t10_10));
c41 = c41 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_4)), abs(t9_5)), abs(t9_8)), abs(t9_9));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_4)) + abs(t9_5)) + abs(t9_8)) + abs(t9_9));
c25 = c25 | select(0u, 1u << (pre | 24u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_5)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_5)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c57 = c57 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
}
{
let dead7 = semi & !(a5_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l5 & !dead7 & !(a5_7_7 > tol.tree_pivot * m7_7));
let l7 = l5 & !dead7;
let i7 = Scalar(1.0) / a5_7_7;
let n7 = -i7;
let a7_7_8 = a5_7_8 * n7;
let a7_7_9 = a5_7_9 * n7;
let a7_7_10 = a5_7_10 * n7;
let t7_7 = -t5_7 * i7;
let a7_0_8 = a5_0_8 + a5_0_7 * a7_7_8;
let a7_0_9 = a5_0_9 + a5_0_7 * a7_7_9;
let a7_0_10 = a5_0_10 + a5_0_7 * a7_7_10;
let t7_0 = t5_0 + a5_0_7 * t7_7;
let a7_1_8 = a5_1_8 + a5_1_7 * a7_7_8;
let a7_1_9 = a5_1_9 + a5_1_7 * a7_7_9;
let a7_1_10 = a5_1_10 + a5_1_7 * a7_7_10;
let t7_1 = t5_1 + a5_1_7 * t7_7;
let a7_2_8 = a5_2_8 + a5_2_7 * a7_7_8;
let a7_2_9 = a5_2_9 + a5_2_7 * a7_7_9;
let a7_2_10 = a5_2_10 + a5_2_7 * a7_7_10;
let t7_2 = t5_2 + a5_2_7 * t7_7;
let a7_3_8 = a5_3_8 + a5_3_7 * a7_7_8;
let a7_3_9 = a5_3_9 + a5_3_7 * a7_7_9;
let a7_3_10 = a5_3_10 + a5_3_7 * a7_7_10;
let t7_3 = t5_3 + a5_3_7 * t7_7;
let a7_4_8 = a5_4_8 + a5_4_7 * a7_7_8;
let a7_4_9 = a5_4_9 + a5_4_7 * a7_7_9;
let a7_4_10 = a5_4_10 + a5_4_7 * a7_7_10;
let t7_4 = t5_4 + a5_4_7 * t7_7;
let a7_5_8 = a5_5_8 + a5_5_7 * a7_7_8;
let a7_5_9 = a5_5_9 + a5_5_7 * a7_7_9;
let a7_5_10 = a5_5_10 + a5_5_7 * a7_7_10;
let t7_5 = t5_5 + a5_5_7 * t7_7;
let a7_6_8 = a5_6_8 + a5_6_7 * a7_7_8;
let a7_6_9 = a5_6_9 + a5_6_7 * a7_7_9;
let a7_6_10 = a5_6_10 + a5_6_7 * a7_7_10;
let t7_6 = t5_6 + a5_6_7 * t7_7;
let a7_8_8 = a5_8_8 + a5_8_7 * a7_7_8;
let a7_8_9 = a5_8_9 + a5_8_7 * a7_7_9;
let a7_8_10 = a5_8_10 + a5_8_7 * a7_7_10;
let t7_8 = t5_8 + a5_8_7 * t7_7;
let a7_9_8 = a5_9_8 + a5_9_7 * a7_7_8;
let a7_9_9 = a5_9_9 + a5_9_7 * a7_7_9;
let a7_9_10 = a5_9_10 + a5_9_7 * a7_7_10;
let t7_9 = t5_9 + a5_9_7 * t7_7;
let a7_10_8 = a5_10_8 + a5_10_7 * a7_7_8;
let a7_10_9 = a5_10_9 + a5_10_7 * a7_7_9;
let a7_10_10 = a5_10_10 + a5_10_7 * a7_7_10;
let t7_10 = t5_10 + a5_10_7 * t7_7;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), select(Scalar(0.0), abs(t7_1), b1)), select(Scalar(0.0), abs(t7_2), b2)), abs(t7_3)), abs(t7_4)), abs(t7_5)), abs(t7_7));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + select(Scalar(0.0), abs(t7_1), b1)) + select(Scalar(0.0), abs(t7_2), b2)) + abs(t7_3)) + abs(t7_4)) + abs(t7_5)) + abs(t7_7));
c5 = c5 | select(0u, 1u << (pre | 24u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t7_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t7_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t7_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a7_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l7 & !dead10 & !(a7_10_10 > tol.tree_pivot * m10_10));
let l10 = l7 & !dead10;
let i10 = Scalar(1.0) / a7_10_10;
let n10 = -i10;
let t10_10 = -t7_10 * i10;
let t10_0 = t7_0 + a7_0_10 * t10_10;
let t10_1 = t7_1 + a7_1_10 * t10_10;
let t10_2 = t7_2 + a7_2_10 * t10_10;
let t10_3 = t7_3 + a7_3_10 * t10_10;
let t10_4 = t7_4 + a7_4_10 * t10_10;
let t10_5 = t7_5 + a7_5_10 * t10_10;
let t10_6 = t7_6 + a7_6_10 * t10_10;
let t10_7 = t7_7 + a7_7_10 * t10_10;
let t10_8 = t7_8 + a7_8_10 * t10_10;
let t10_9 = t7_9 + a7_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_5)), abs(t10_7)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_5)) + abs(t10_7)) + abs(t10_10));
c37 = c37 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a7_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l7 & !dead9 & !(a7_9_9 > tol.tree_pivot * m9_9));
let l9 = l7 & !dead9;
let i9 = Scalar(1.0) / a7_9_9;
let n9 = -i9;
let a9_9_10 = a7_9_10 * n9;
let t9_9 = -t7_9 * i9;
let a9_0_10 = a7_0_10 + a7_0_9 * a9_9_10;
let t9_0 = t7_0 + a7_0_9 * t9_9;
let a9_1_10 = a7_1_10 + a7_1_9 * a9_9_10;
let t9_1 = t7_1 + a7_1_9 * t9_9;
let a9_2_10 = a7_2_10 + a7_2_9 * a9_9_10;
let t9_2 = t7_2 + a7_2_9 * t9_9;
let a9_3_10 = a7_3_10 + a7_3_9 * a9_9_10;
let t9_3 = t7_3 + a7_3_9 * t9_9;
let a9_4_10 = a7_4_10 + a7_4_9 * a9_9_10;
let t9_4 = t7_4 + a7_4_9 * t9_9;
let a9_5_10 = a7_5_10 + a7_5_9 * a9_9_10;
let t9_5 = t7_5 + a7_5_9 * t9_9;
let a9_6_10 = a7_6_10 + a7_6_9 * a9_9_10;
let t9_6 = t7_6 + a7_6_9 * t9_9;
let a9_7_10 = a7_7_10 + a7_7_9 * a9_9_10;
let t9_7 = t7_7 + a7_7_9 * t9_9;
let a9_8_10 = a7_8_10 + a7_8_9 * a9_9_10;
let t9_8 = t7_8 + a7_8_9 * t9_9;
let a9_10_10 = a7_10_10 + a7_10_9 * a9_9_10;
let t9_10 = t7_10 + a7_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_4)), abs(t9_5)), abs(t9_7)), abs(t9_9));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_4)) + abs(t9_5)) + abs(t9_7)) + abs(t9_9));
c21 = c21 | select(0u, 1u << (pre | 24u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_5)), abs(t10_7)), abs(t10_9)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_5)) + abs(t10_7)) + abs(t10_9)) + abs(t10_10));
c53 = c53 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let a8_8_9 = a7_8_9 * n8;
let a8_8_10 = a7_8_10 * n8;
let t8_8 = -t7_8 * i8;
let a8_0_9 = a7_0_9 + a7_0_8 * a8_8_9;
let a8_0_10 = a7_0_10 + a7_0_8 * a8_8_10;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let a8_1_9 = a7_1_9 + a7_1_8 * a8_8_9;
let a8_1_10 = a7_1_10 + a7_1_8 * a8_8_10;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let a8_2_9 = a7_2_9 + a7_2_8 * a8_8_9;
let a8_2_10 = a7_2_10 + a7_2_8 * a8_8_10;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let a8_3_9 = a7_3_9 + a7_3_8 * a8_8_9;
let a8_3_10 = a7_3_10 + a7_3_8 * a8_8_10;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let a8_4_9 = a7_4_9 + a7_4_8 * a8_8_9;
let a8_4_10 = a7_4_10 + a7_4_8 * a8_8_10;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let a8_5_9 = a7_5_9 + a7_5_8 * a8_8_9;
let a8_5_10 = a7_5_10 + a7_5_8 * a8_8_10;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let a8_6_9 = a7_6_9 + a7_6_8 * a8_8_9;
let a8_6_10 = a7_6_10 + a7_6_8 * a8_8_10;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let a8_7_9 = a7_7_9 + a7_7_8 * a8_8_9;
let a8_7_10 = a7_7_10 + a7_7_8 * a8_8_10;
let t8_7 = t7_7 + a7_7_8 * t8_8;
let a8_9_9 = a7_9_9 + a7_9_8 * a8_8_9;
let a8_9_10 = a7_9_10 + a7_9_8 * a8_8_10;
let t8_9 = t7_9 + a7_9_8 * t8_8;
let a8_10_9 = a7_10_9 + a7_10_8 * a8_8_9;
let a8_10_10 = a7_10_10 + a7_10_8 * a8_8_10;
let t8_10 = t7_10 + a7_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_7)), abs(t8_8));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_7)) + abs(t8_8));
c13 = c13 | select(0u, 1u << (pre | 24u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_5)), abs(t10_7)), abs(t10_8)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_5)) + abs(t10_7)) + abs(t10_8)) + abs(t10_10));
c45 = c45 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_4)), abs(t9_5)), abs(t9_7)), abs(t9_8)), abs(t9_9));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_4)) + abs(t9_5)) + abs(t9_7)) + abs(t9_8)) + abs(t9_9));
c29 = c29 | select(0u, 1u << (pre | 24u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_5)), abs(t10_7)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = ((((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_5)) + abs(t10_7)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c61 = c61 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * (qa6 + rm6 * zs)) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
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
let a6_6_9 = a5_6_9 * n6;
let a6_6_10 = a5_6_10 * n6;
let t6_6 = -t5_6 * i6;
let a6_0_7 = a5_0_7 + a5_0_6 * a6_6_7;
let a6_0_8 = a5_0_8 + a5_0_6 * a6_6_8;
let a6_0_9 = a5_0_9 + a5_0_6 * a6_6_9;
let a6_0_10 = a5_0_10 + a5_0_6 * a6_6_10;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let a6_1_7 = a5_1_7 + a5_1_6 * a6_6_7;
let a6_1_8 = a5_1_8 + a5_1_6 * a6_6_8;
let a6_1_9 = a5_1_9 + a5_1_6 * a6_6_9;
let a6_1_10 = a5_1_10 + a5_1_6 * a6_6_10;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let a6_2_7 = a5_2_7 + a5_2_6 * a6_6_7;
let a6_2_8 = a5_2_8 + a5_2_6 * a6_6_8;
let a6_2_9 = a5_2_9 + a5_2_6 * a6_6_9;
let a6_2_10 = a5_2_10 + a5_2_6 * a6_6_10;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let a6_3_7 = a5_3_7 + a5_3_6 * a6_6_7;
let a6_3_8 = a5_3_8 + a5_3_6 * a6_6_8;
let a6_3_9 = a5_3_9 + a5_3_6 * a6_6_9;
let a6_3_10 = a5_3_10 + a5_3_6 * a6_6_10;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let a6_4_7 = a5_4_7 + a5_4_6 * a6_6_7;
let a6_4_8 = a5_4_8 + a5_4_6 * a6_6_8;
let a6_4_9 = a5_4_9 + a5_4_6 * a6_6_9;
let a6_4_10 = a5_4_10 + a5_4_6 * a6_6_10;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let a6_5_7 = a5_5_7 + a5_5_6 * a6_6_7;
let a6_5_8 = a5_5_8 + a5_5_6 * a6_6_8;
let a6_5_9 = a5_5_9 + a5_5_6 * a6_6_9;
let a6_5_10 = a5_5_10 + a5_5_6 * a6_6_10;
let t6_5 = t5_5 + a5_5_6 * t6_6;
let a6_7_7 = a5_7_7 + a5_7_6 * a6_6_7;
let a6_7_8 = a5_7_8 + a5_7_6 * a6_6_8;
let a6_7_9 = a5_7_9 + a5_7_6 * a6_6_9;
let a6_7_10 = a5_7_10 + a5_7_6 * a6_6_10;
let t6_7 = t5_7 + a5_7_6 * t6_6;
let a6_8_7 = a5_8_7 + a5_8_6 * a6_6_7;
let a6_8_8 = a5_8_8 + a5_8_6 * a6_6_8;
let a6_8_9 = a5_8_9 + a5_8_6 * a6_6_9;
let a6_8_10 = a5_8_10 + a5_8_6 * a6_6_10;
let t6_8 = t5_8 + a5_8_6 * t6_6;
let a6_9_7 = a5_9_7 + a5_9_6 * a6_6_7;
let a6_9_8 = a5_9_8 + a5_9_6 * a6_6_8;
let a6_9_9 = a5_9_9 + a5_9_6 * a6_6_9;
let a6_9_10 = a5_9_10 + a5_9_6 * a6_6_10;
let t6_9 = t5_9 + a5_9_6 * t6_6;
let a6_10_7 = a5_10_7 + a5_10_6 * a6_6_7;
let a6_10_8 = a5_10_8 + a5_10_6 * a6_6_8;
let a6_10_9 = a5_10_9 + a5_10_6 * a6_6_9;
let a6_10_10 = a5_10_10 + a5_10_6 * a6_6_10;
let t6_10 = t5_10 + a5_10_6 * t6_6;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t6_0), b0)), select(Scalar(0.0), abs(t6_1), b1)), select(Scalar(0.0), abs(t6_2), b2)), abs(t6_3)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = (((((((Scalar(0.0) + select(Scalar(0.0), abs(t6_0), b0)) + select(Scalar(0.0), abs(t6_1), b1)) + select(Scalar(0.0), abs(t6_2), b2)) + abs(t6_3)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 24u), l6 & (t6_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t6_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t6_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm) & (t6_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t6_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t6_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t6_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a6_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l6 & !dead10 & !(a6_10_10 > tol.tree_pivot * m10_10));
let l10 = l6 & !dead10;
let i10 = Scalar(1.0) / a6_10_10;
let n10 = -i10;
let t10_10 = -t6_10 * i10;
let t10_0 = t6_0 + a6_0_10 * t10_10;
let t10_1 = t6_1 + a6_1_10 * t10_10;
let t10_2 = t6_2 + a6_2_10 * t10_10;
let t10_3 = t6_3 + a6_3_10 * t10_10;
let t10_4 = t6_4 + a6_4_10 * t10_10;
let t10_5 = t6_5 + a6_5_10 * t10_10;
let t10_6 = t6_6 + a6_6_10 * t10_10;
let t10_7 = t6_7 + a6_7_10 * t10_10;
let t10_8 = t6_8 + a6_8_10 * t10_10;
let t10_9 = t6_9 + a6_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_5)), abs(t10_6)), abs(t10_10));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_5)) + abs(t10_6)) + abs(t10_10));
c35 = c35 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a6_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l6 & !dead9 & !(a6_9_9 > tol.tree_pivot * m9_9));
let l9 = l6 & !dead9;
let i9 = Scalar(1.0) / a6_9_9;
let n9 = -i9;
let a9_9_10 = a6_9_10 * n9;
let t9_9 = -t6_9 * i9;
let a9_0_10 = a6_0_10 + a6_0_9 * a9_9_10;
let t9_0 = t6_0 + a6_0_9 * t9_9;
let a9_1_10 = a6_1_10 + a6_1_9 * a9_9_10;
let t9_1 = t6_1 + a6_1_9 * t9_9;
let a9_2_10 = a6_2_10 + a6_2_9 * a9_9_10;
let t9_2 = t6_2 + a6_2_9 * t9_9;
let a9_3_10 = a6_3_10 + a6_3_9 * a9_9_10;
let t9_3 = t6_3 + a6_3_9 * t9_9;
let a9_4_10 = a6_4_10 + a6_4_9 * a9_9_10;
let t9_4 = t6_4 + a6_4_9 * t9_9;
let a9_5_10 = a6_5_10 + a6_5_9 * a9_9_10;
let t9_5 = t6_5 + a6_5_9 * t9_9;
let a9_6_10 = a6_6_10 + a6_6_9 * a9_9_10;
let t9_6 = t6_6 + a6_6_9 * t9_9;
let a9_7_10 = a6_7_10 + a6_7_9 * a9_9_10;
let t9_7 = t6_7 + a6_7_9 * t9_9;
let a9_8_10 = a6_8_10 + a6_8_9 * a9_9_10;
let t9_8 = t6_8 + a6_8_9 * t9_9;
let a9_10_10 = a6_10_10 + a6_10_9 * a9_9_10;
let t9_10 = t6_10 + a6_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_4)), abs(t9_5)), abs(t9_6)), abs(t9_9));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_4)) + abs(t9_5)) + abs(t9_6)) + abs(t9_9));
c19 = c19 | select(0u, 1u << (pre | 24u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_5)), abs(t10_6)), abs(t10_9)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_5)) + abs(t10_6)) + abs(t10_9)) + abs(t10_10));
c51 = c51 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a6_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l6 & !dead8 & !(a6_8_8 > tol.tree_pivot * m8_8));
let l8 = l6 & !dead8;
let i8 = Scalar(1.0) / a6_8_8;
let n8 = -i8;
let a8_8_9 = a6_8_9 * n8;
let a8_8_10 = a6_8_10 * n8;
let t8_8 = -t6_8 * i8;
let a8_0_9 = a6_0_9 + a6_0_8 * a8_8_9;
let a8_0_10 = a6_0_10 + a6_0_8 * a8_8_10;
let t8_0 = t6_0 + a6_0_8 * t8_8;
let a8_1_9 = a6_1_9 + a6_1_8 * a8_8_9;
let a8_1_10 = a6_1_10 + a6_1_8 * a8_8_10;
let t8_1 = t6_1 + a6_1_8 * t8_8;
let a8_2_9 = a6_2_9 + a6_2_8 * a8_8_9;
let a8_2_10 = a6_2_10 + a6_2_8 * a8_8_10;
let t8_2 = t6_2 + a6_2_8 * t8_8;
let a8_3_9 = a6_3_9 + a6_3_8 * a8_8_9;
let a8_3_10 = a6_3_10 + a6_3_8 * a8_8_10;
let t8_3 = t6_3 + a6_3_8 * t8_8;
let a8_4_9 = a6_4_9 + a6_4_8 * a8_8_9;
let a8_4_10 = a6_4_10 + a6_4_8 * a8_8_10;
let t8_4 = t6_4 + a6_4_8 * t8_8;
let a8_5_9 = a6_5_9 + a6_5_8 * a8_8_9;
let a8_5_10 = a6_5_10 + a6_5_8 * a8_8_10;
let t8_5 = t6_5 + a6_5_8 * t8_8;
let a8_6_9 = a6_6_9 + a6_6_8 * a8_8_9;
let a8_6_10 = a6_6_10 + a6_6_8 * a8_8_10;
let t8_6 = t6_6 + a6_6_8 * t8_8;
let a8_7_9 = a6_7_9 + a6_7_8 * a8_8_9;
let a8_7_10 = a6_7_10 + a6_7_8 * a8_8_10;
let t8_7 = t6_7 + a6_7_8 * t8_8;
let a8_9_9 = a6_9_9 + a6_9_8 * a8_8_9;
let a8_9_10 = a6_9_10 + a6_9_8 * a8_8_10;
let t8_9 = t6_9 + a6_9_8 * t8_8;
let a8_10_9 = a6_10_9 + a6_10_8 * a8_8_9;
let a8_10_10 = a6_10_10 + a6_10_8 * a8_8_10;
let t8_10 = t6_10 + a6_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_8));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_8));
c11 = c11 | select(0u, 1u << (pre | 24u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_5)), abs(t10_6)), abs(t10_8)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_5)) + abs(t10_6)) + abs(t10_8)) + abs(t10_10));
c43 = c43 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_4)), abs(t9_5)), abs(t9_6)), abs(t9_8)), abs(t9_9));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_4)) + abs(t9_5)) + abs(t9_6)) + abs(t9_8)) + abs(t9_9));
c27 = c27 | select(0u, 1u << (pre | 24u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_5)), abs(t10_6)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = ((((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_5)) + abs(t10_6)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c59 = c59 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * (qa7 + rm7 * zs)) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
}
{
let dead7 = semi & !(a6_7_7 > tol.tree_singular * m7_7);
ok = ok & !(l6 & !dead7 & !(a6_7_7 > tol.tree_pivot * m7_7));
let l7 = l6 & !dead7;
let i7 = Scalar(1.0) / a6_7_7;
let n7 = -i7;
let a7_7_8 = a6_7_8 * n7;
let a7_7_9 = a6_7_9 * n7;
let a7_7_10 = a6_7_10 * n7;
let t7_7 = -t6_7 * i7;
let a7_0_8 = a6_0_8 + a6_0_7 * a7_7_8;
let a7_0_9 = a6_0_9 + a6_0_7 * a7_7_9;
let a7_0_10 = a6_0_10 + a6_0_7 * a7_7_10;
let t7_0 = t6_0 + a6_0_7 * t7_7;
let a7_1_8 = a6_1_8 + a6_1_7 * a7_7_8;
let a7_1_9 = a6_1_9 + a6_1_7 * a7_7_9;
let a7_1_10 = a6_1_10 + a6_1_7 * a7_7_10;
let t7_1 = t6_1 + a6_1_7 * t7_7;
let a7_2_8 = a6_2_8 + a6_2_7 * a7_7_8;
let a7_2_9 = a6_2_9 + a6_2_7 * a7_7_9;
let a7_2_10 = a6_2_10 + a6_2_7 * a7_7_10;
let t7_2 = t6_2 + a6_2_7 * t7_7;
let a7_3_8 = a6_3_8 + a6_3_7 * a7_7_8;
let a7_3_9 = a6_3_9 + a6_3_7 * a7_7_9;
let a7_3_10 = a6_3_10 + a6_3_7 * a7_7_10;
let t7_3 = t6_3 + a6_3_7 * t7_7;
let a7_4_8 = a6_4_8 + a6_4_7 * a7_7_8;
let a7_4_9 = a6_4_9 + a6_4_7 * a7_7_9;
let a7_4_10 = a6_4_10 + a6_4_7 * a7_7_10;
let t7_4 = t6_4 + a6_4_7 * t7_7;
let a7_5_8 = a6_5_8 + a6_5_7 * a7_7_8;
let a7_5_9 = a6_5_9 + a6_5_7 * a7_7_9;
let a7_5_10 = a6_5_10 + a6_5_7 * a7_7_10;
let t7_5 = t6_5 + a6_5_7 * t7_7;
let a7_6_8 = a6_6_8 + a6_6_7 * a7_7_8;
let a7_6_9 = a6_6_9 + a6_6_7 * a7_7_9;
let a7_6_10 = a6_6_10 + a6_6_7 * a7_7_10;
let t7_6 = t6_6 + a6_6_7 * t7_7;
let a7_8_8 = a6_8_8 + a6_8_7 * a7_7_8;
let a7_8_9 = a6_8_9 + a6_8_7 * a7_7_9;
let a7_8_10 = a6_8_10 + a6_8_7 * a7_7_10;
let t7_8 = t6_8 + a6_8_7 * t7_7;
let a7_9_8 = a6_9_8 + a6_9_7 * a7_7_8;
let a7_9_9 = a6_9_9 + a6_9_7 * a7_7_9;
let a7_9_10 = a6_9_10 + a6_9_7 * a7_7_10;
let t7_9 = t6_9 + a6_9_7 * t7_7;
let a7_10_8 = a6_10_8 + a6_10_7 * a7_7_8;
let a7_10_9 = a6_10_9 + a6_10_7 * a7_7_9;
let a7_10_10 = a6_10_10 + a6_10_7 * a7_7_10;
let t7_10 = t6_10 + a6_10_7 * t7_7;
{
let zm = max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t7_0), b0)), select(Scalar(0.0), abs(t7_1), b1)), select(Scalar(0.0), abs(t7_2), b2)), abs(t7_3)), abs(t7_4)), abs(t7_5)), abs(t7_6)), abs(t7_7));
let zs = ((((((((Scalar(0.0) + select(Scalar(0.0), abs(t7_0), b0)) + select(Scalar(0.0), abs(t7_1), b1)) + select(Scalar(0.0), abs(t7_2), b2)) + abs(t7_3)) + abs(t7_4)) + abs(t7_5)) + abs(t7_6)) + abs(t7_7));
c7 = c7 | select(0u, 1u << (pre | 24u), l7 & (t7_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t7_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t7_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t7_3 >= -tol.screen * zm) & (t7_4 >= -tol.screen * zm) & (t7_5 >= -tol.screen * zm) & (t7_6 >= -tol.screen * zm) & (t7_7 >= -tol.screen * zm) & (t7_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t7_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t7_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a7_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l7 & !dead10 & !(a7_10_10 > tol.tree_pivot * m10_10));
let l10 = l7 & !dead10;
let i10 = Scalar(1.0) / a7_10_10;
let n10 = -i10;
let t10_10 = -t7_10 * i10;
let t10_0 = t7_0 + a7_0_10 * t10_10;
let t10_1 = t7_1 + a7_1_10 * t10_10;
let t10_2 = t7_2 + a7_2_10 * t10_10;
let t10_3 = t7_3 + a7_3_10 * t10_10;
let t10_4 = t7_4 + a7_4_10 * t10_10;
let t10_5 = t7_5 + a7_5_10 * t10_10;
let t10_6 = t7_6 + a7_6_10 * t10_10;
let t10_7 = t7_7 + a7_7_10 * t10_10;
let t10_8 = t7_8 + a7_8_10 * t10_10;
let t10_9 = t7_9 + a7_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_5)), abs(t10_6)), abs(t10_7)), abs(t10_10));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_5)) + abs(t10_6)) + abs(t10_7)) + abs(t10_10));
c39 = c39 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a7_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l7 & !dead9 & !(a7_9_9 > tol.tree_pivot * m9_9));
let l9 = l7 & !dead9;
let i9 = Scalar(1.0) / a7_9_9;
let n9 = -i9;
let a9_9_10 = a7_9_10 * n9;
let t9_9 = -t7_9 * i9;
let a9_0_10 = a7_0_10 + a7_0_9 * a9_9_10;
let t9_0 = t7_0 + a7_0_9 * t9_9;
let a9_1_10 = a7_1_10 + a7_1_9 * a9_9_10;
let t9_1 = t7_1 + a7_1_9 * t9_9;
let a9_2_10 = a7_2_10 + a7_2_9 * a9_9_10;
let t9_2 = t7_2 + a7_2_9 * t9_9;
let a9_3_10 = a7_3_10 + a7_3_9 * a9_9_10;
let t9_3 = t7_3 + a7_3_9 * t9_9;
let a9_4_10 = a7_4_10 + a7_4_9 * a9_9_10;
let t9_4 = t7_4 + a7_4_9 * t9_9;
let a9_5_10 = a7_5_10 + a7_5_9 * a9_9_10;
let t9_5 = t7_5 + a7_5_9 * t9_9;
let a9_6_10 = a7_6_10 + a7_6_9 * a9_9_10;
let t9_6 = t7_6 + a7_6_9 * t9_9;
let a9_7_10 = a7_7_10 + a7_7_9 * a9_9_10;
let t9_7 = t7_7 + a7_7_9 * t9_9;
let a9_8_10 = a7_8_10 + a7_8_9 * a9_9_10;
let t9_8 = t7_8 + a7_8_9 * t9_9;
let a9_10_10 = a7_10_10 + a7_10_9 * a9_9_10;
let t9_10 = t7_10 + a7_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_4)), abs(t9_5)), abs(t9_6)), abs(t9_7)), abs(t9_9));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_4)) + abs(t9_5)) + abs(t9_6)) + abs(t9_7)) + abs(t9_9));
c23 = c23 | select(0u, 1u << (pre | 24u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_5)), abs(t10_6)), abs(t10_7)), abs(t10_9)), abs(t10_10));
let zs = ((((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_5)) + abs(t10_6)) + abs(t10_7)) + abs(t10_9)) + abs(t10_10));
c55 = c55 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * (qa8 + rm8 * zs)) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
}
}
}
{
let dead8 = semi & !(a7_8_8 > tol.tree_singular * m8_8);
ok = ok & !(l7 & !dead8 & !(a7_8_8 > tol.tree_pivot * m8_8));
let l8 = l7 & !dead8;
let i8 = Scalar(1.0) / a7_8_8;
let n8 = -i8;
let a8_8_9 = a7_8_9 * n8;
let a8_8_10 = a7_8_10 * n8;
let t8_8 = -t7_8 * i8;
let a8_0_9 = a7_0_9 + a7_0_8 * a8_8_9;
let a8_0_10 = a7_0_10 + a7_0_8 * a8_8_10;
let t8_0 = t7_0 + a7_0_8 * t8_8;
let a8_1_9 = a7_1_9 + a7_1_8 * a8_8_9;
let a8_1_10 = a7_1_10 + a7_1_8 * a8_8_10;
let t8_1 = t7_1 + a7_1_8 * t8_8;
let a8_2_9 = a7_2_9 + a7_2_8 * a8_8_9;
let a8_2_10 = a7_2_10 + a7_2_8 * a8_8_10;
let t8_2 = t7_2 + a7_2_8 * t8_8;
let a8_3_9 = a7_3_9 + a7_3_8 * a8_8_9;
let a8_3_10 = a7_3_10 + a7_3_8 * a8_8_10;
let t8_3 = t7_3 + a7_3_8 * t8_8;
let a8_4_9 = a7_4_9 + a7_4_8 * a8_8_9;
let a8_4_10 = a7_4_10 + a7_4_8 * a8_8_10;
let t8_4 = t7_4 + a7_4_8 * t8_8;
let a8_5_9 = a7_5_9 + a7_5_8 * a8_8_9;
let a8_5_10 = a7_5_10 + a7_5_8 * a8_8_10;
let t8_5 = t7_5 + a7_5_8 * t8_8;
let a8_6_9 = a7_6_9 + a7_6_8 * a8_8_9;
let a8_6_10 = a7_6_10 + a7_6_8 * a8_8_10;
let t8_6 = t7_6 + a7_6_8 * t8_8;
let a8_7_9 = a7_7_9 + a7_7_8 * a8_8_9;
let a8_7_10 = a7_7_10 + a7_7_8 * a8_8_10;
let t8_7 = t7_7 + a7_7_8 * t8_8;
let a8_9_9 = a7_9_9 + a7_9_8 * a8_8_9;
let a8_9_10 = a7_9_10 + a7_9_8 * a8_8_10;
let t8_9 = t7_9 + a7_9_8 * t8_8;
let a8_10_9 = a7_10_9 + a7_10_8 * a8_8_9;
let a8_10_10 = a7_10_10 + a7_10_8 * a8_8_10;
let t8_10 = t7_10 + a7_10_8 * t8_8;
{
let zm = max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t8_0), b0)), select(Scalar(0.0), abs(t8_1), b1)), select(Scalar(0.0), abs(t8_2), b2)), abs(t8_3)), abs(t8_4)), abs(t8_5)), abs(t8_6)), abs(t8_7)), abs(t8_8));
let zs = (((((((((Scalar(0.0) + select(Scalar(0.0), abs(t8_0), b0)) + select(Scalar(0.0), abs(t8_1), b1)) + select(Scalar(0.0), abs(t8_2), b2)) + abs(t8_3)) + abs(t8_4)) + abs(t8_5)) + abs(t8_6)) + abs(t8_7)) + abs(t8_8));
c15 = c15 | select(0u, 1u << (pre | 24u), l8 & (t8_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t8_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t8_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t8_3 >= -tol.screen * zm) & (t8_4 >= -tol.screen * zm) & (t8_5 >= -tol.screen * zm) & (t8_6 >= -tol.screen * zm) & (t8_7 >= -tol.screen * zm) & (t8_8 >= -tol.screen * zm) & (t8_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t8_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a8_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l8 & !dead10 & !(a8_10_10 > tol.tree_pivot * m10_10));
let l10 = l8 & !dead10;
let i10 = Scalar(1.0) / a8_10_10;
let n10 = -i10;
let t10_10 = -t8_10 * i10;
let t10_0 = t8_0 + a8_0_10 * t10_10;
let t10_1 = t8_1 + a8_1_10 * t10_10;
let t10_2 = t8_2 + a8_2_10 * t10_10;
let t10_3 = t8_3 + a8_3_10 * t10_10;
let t10_4 = t8_4 + a8_4_10 * t10_10;
let t10_5 = t8_5 + a8_5_10 * t10_10;
let t10_6 = t8_6 + a8_6_10 * t10_10;
let t10_7 = t8_7 + a8_7_10 * t10_10;
let t10_8 = t8_8 + a8_8_10 * t10_10;
let t10_9 = t8_9 + a8_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_5)), abs(t10_6)), abs(t10_7)), abs(t10_8)), abs(t10_10));
let zs = ((((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_5)) + abs(t10_6)) + abs(t10_7)) + abs(t10_8)) + abs(t10_10));
c47 = c47 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * (qa9 + rm9 * zs)) & (t10_10 >= -tol.screen * zm));
}
}
{
let dead9 = semi & !(a8_9_9 > tol.tree_singular * m9_9);
ok = ok & !(l8 & !dead9 & !(a8_9_9 > tol.tree_pivot * m9_9));
let l9 = l8 & !dead9;
let i9 = Scalar(1.0) / a8_9_9;
let n9 = -i9;
let a9_9_10 = a8_9_10 * n9;
let t9_9 = -t8_9 * i9;
let a9_0_10 = a8_0_10 + a8_0_9 * a9_9_10;
let t9_0 = t8_0 + a8_0_9 * t9_9;
let a9_1_10 = a8_1_10 + a8_1_9 * a9_9_10;
let t9_1 = t8_1 + a8_1_9 * t9_9;
let a9_2_10 = a8_2_10 + a8_2_9 * a9_9_10;
let t9_2 = t8_2 + a8_2_9 * t9_9;
let a9_3_10 = a8_3_10 + a8_3_9 * a9_9_10;
let t9_3 = t8_3 + a8_3_9 * t9_9;
let a9_4_10 = a8_4_10 + a8_4_9 * a9_9_10;
let t9_4 = t8_4 + a8_4_9 * t9_9;
let a9_5_10 = a8_5_10 + a8_5_9 * a9_9_10;
let t9_5 = t8_5 + a8_5_9 * t9_9;
let a9_6_10 = a8_6_10 + a8_6_9 * a9_9_10;
let t9_6 = t8_6 + a8_6_9 * t9_9;
let a9_7_10 = a8_7_10 + a8_7_9 * a9_9_10;
let t9_7 = t8_7 + a8_7_9 * t9_9;
let a9_8_10 = a8_8_10 + a8_8_9 * a9_9_10;
let t9_8 = t8_8 + a8_8_9 * t9_9;
let a9_10_10 = a8_10_10 + a8_10_9 * a9_9_10;
let t9_10 = t8_10 + a8_10_9 * t9_9;
{
let zm = max(max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t9_0), b0)), select(Scalar(0.0), abs(t9_1), b1)), select(Scalar(0.0), abs(t9_2), b2)), abs(t9_3)), abs(t9_4)), abs(t9_5)), abs(t9_6)), abs(t9_7)), abs(t9_8)), abs(t9_9));
let zs = ((((((((((Scalar(0.0) + select(Scalar(0.0), abs(t9_0), b0)) + select(Scalar(0.0), abs(t9_1), b1)) + select(Scalar(0.0), abs(t9_2), b2)) + abs(t9_3)) + abs(t9_4)) + abs(t9_5)) + abs(t9_6)) + abs(t9_7)) + abs(t9_8)) + abs(t9_9));
c31 = c31 | select(0u, 1u << (pre | 24u), l9 & (t9_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t9_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t9_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t9_3 >= -tol.screen * zm) & (t9_4 >= -tol.screen * zm) & (t9_5 >= -tol.screen * zm) & (t9_6 >= -tol.screen * zm) & (t9_7 >= -tol.screen * zm) & (t9_8 >= -tol.screen * zm) & (t9_9 >= -tol.screen * zm) & (t9_10 >= -tol.screen * (qa10 + rm10 * zs)));
}
{
let dead10 = semi & !(a9_10_10 > tol.tree_singular * m10_10);
ok = ok & !(l9 & !dead10 & !(a9_10_10 > tol.tree_pivot * m10_10));
let l10 = l9 & !dead10;
let i10 = Scalar(1.0) / a9_10_10;
let n10 = -i10;
let t10_10 = -t9_10 * i10;
let t10_0 = t9_0 + a9_0_10 * t10_10;
let t10_1 = t9_1 + a9_1_10 * t10_10;
let t10_2 = t9_2 + a9_2_10 * t10_10;
let t10_3 = t9_3 + a9_3_10 * t10_10;
let t10_4 = t9_4 + a9_4_10 * t10_10;
let t10_5 = t9_5 + a9_5_10 * t10_10;
let t10_6 = t9_6 + a9_6_10 * t10_10;
let t10_7 = t9_7 + a9_7_10 * t10_10;
let t10_8 = t9_8 + a9_8_10 * t10_10;
let t10_9 = t9_9 + a9_9_10 * t10_10;
{
let zm = max(max(max(max(max(max(max(max(max(max(max(Scalar(0.0), select(Scalar(0.0), abs(t10_0), b0)), select(Scalar(0.0), abs(t10_1), b1)), select(Scalar(0.0), abs(t10_2), b2)), abs(t10_3)), abs(t10_4)), abs(t10_5)), abs(t10_6)), abs(t10_7)), abs(t10_8)), abs(t10_9)), abs(t10_10));
let zs = (((((((((((Scalar(0.0) + select(Scalar(0.0), abs(t10_0), b0)) + select(Scalar(0.0), abs(t10_1), b1)) + select(Scalar(0.0), abs(t10_2), b2)) + abs(t10_3)) + abs(t10_4)) + abs(t10_5)) + abs(t10_6)) + abs(t10_7)) + abs(t10_8)) + abs(t10_9)) + abs(t10_10));
c63 = c63 | select(0u, 1u << (pre | 24u), l10 & (t10_0 >= -tol.screen * select((qa0 + rm0 * zs), zm, b0)) & (t10_1 >= -tol.screen * select((qa1 + rm1 * zs), zm, b1)) & (t10_2 >= -tol.screen * select((qa2 + rm2 * zs), zm, b2)) & (t10_3 >= -tol.screen * zm) & (t10_4 >= -tol.screen * zm) & (t10_5 >= -tol.screen * zm) & (t10_6 >= -tol.screen * zm) & (t10_7 >= -tol.screen * zm) & (t10_8 >= -tol.screen * zm) & (t10_9 >= -tol.screen * zm) & (t10_10 >= -tol.screen * zm));
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
cand[16] = c16;
cand[17] = c17;
cand[18] = c18;
cand[19] = c19;
cand[20] = c20;
cand[21] = c21;
cand[22] = c22;
cand[23] = c23;
cand[24] = c24;
cand[25] = c25;
cand[26] = c26;
cand[27] = c27;
cand[28] = c28;
cand[29] = c29;
cand[30] = c30;
cand[31] = c31;
cand[32] = c32;
cand[33] = c33;
cand[34] = c34;
cand[35] = c35;
cand[36] = c36;
cand[37] = c37;
cand[38] = c38;
cand[39] = c39;
cand[40] = c40;
cand[41] = c41;
cand[42] = c42;
cand[43] = c43;
cand[44] = c44;
cand[45] = c45;
cand[46] = c46;
cand[47] = c47;
cand[48] = c48;
cand[49] = c49;
cand[50] = c50;
cand[51] = c51;
cand[52] = c52;
cand[53] = c53;
cand[54] = c54;
cand[55] = c55;
cand[56] = c56;
cand[57] = c57;
cand[58] = c58;
cand[59] = c59;
cand[60] = c60;
cand[61] = c61;
cand[62] = c62;
cand[63] = c63;
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
