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
const FN: u32 = 7u; // HOST fixed_n
// Words of the candidate bitmap: ceil(2^FN / 32).
const WORDS: u32 = 4u; // HOST words

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
let rm0 = max(max(max(max(max(max(max(Scalar(0.0), abs(m0_0)), abs(m0_1)), abs(m0_2)), abs(m0_3)), abs(m0_4)), abs(m0_5)), abs(m0_6));
let m1_0 = values[base + 7u];
let m1_1 = values[base + 8u];
let m1_2 = values[base + 9u];
let m1_3 = values[base + 10u];
let m1_4 = values[base + 11u];
let m1_5 = values[base + 12u];
let m1_6 = values[base + 13u];
let rm1 = max(max(max(max(max(max(max(Scalar(0.0), abs(m1_0)), abs(m1_1)), abs(m1_2)), abs(m1_3)), abs(m1_4)), abs(m1_5)), abs(m1_6));
let m2_0 = values[base + 14u];
let m2_1 = values[base + 15u];
let m2_2 = values[base + 16u];
let m2_3 = values[base + 17u];
let m2_4 = values[base + 18u];
let m2_5 = values[base + 19u];
let m2_6 = values[base + 20u];
let rm2 = max(max(max(max(max(max(max(Scalar(0.0), abs(m2_0)), abs(m2_1)), abs(m2_2)), abs(m2_3)), abs(m2_4)), abs(m2_5)), abs(m2_6));
let m3_0 = values[base + 21u];
let m3_1 = values[base + 22u];
let m3_2 = values[base + 23u];
let m3_3 = values[base + 24u];
let m3_4 = values[base + 25u];
let m3_5 = values[base + 26u];
let m3_6 = values[base + 27u];
let rm3 = max(max(max(max(max(max(max(Scalar(0.0), abs(m3_0)), abs(m3_1)), abs(m3_2)), abs(m3_3)), abs(m3_4)), abs(m3_5)), abs(m3_6));
let m4_0 = values[base + 28u];
let m4_1 = values[base + 29u];
let m4_2 = values[base + 30u];
let m4_3 = values[base + 31u];
let m4_4 = values[base + 32u];
let m4_5 = values[base + 33u];
let m4_6 = values[base + 34u];
let rm4 = max(max(max(max(max(max(max(Scalar(0.0), abs(m4_0)), abs(m4_1)), abs(m4_2)), abs(m4_3)), abs(m4_4)), abs(m4_5)), abs(m4_6));
let m5_0 = values[base + 35u];
let m5_1 = values[base + 36u];
let m5_2 = values[base + 37u];
let m5_3 = values[base + 38u];
let m5_4 = values[base + 39u];
let m5_5 = values[base + 40u];
let m5_6 = values[base + 41u];
let rm5 = max(max(max(max(max(max(max(Scalar(0.0), abs(m5_0)), abs(m5_1)), abs(m5_2)), abs(m5_3)), abs(m5_4)), abs(m5_5)), abs(m5_6));
let m6_0 = values[base + 42u];
let m6_1 = values[base + 43u];
let m6_2 = values[base + 44u];
let m6_3 = values[base + 45u];
let m6_4 = values[base + 46u];
let m6_5 = values[base + 47u];
let m6_6 = values[base + 48u];
let rm6 = max(max(max(max(max(max(max(Scalar(0.0), abs(m6_0)), abs(m6_1)), abs(m6_2)), abs(m6_3)), abs(m6_4)), abs(m6_5)), abs(m6_6));
let q0 = values[base + 49u];
let qa0 = abs(q0);
let q1 = values[base + 50u];
let qa1 = abs(q1);
let q2 = values[base + 51u];
let qa2 = abs(q2);
let q3 = values[base + 52u];
let qa3 = abs(q3);
let q4 = values[base + 53u];
let qa4 = abs(q4);
let q5 = values[base + 54u];
let qa5 = abs(q5);
let q6 = values[base + 55u];
let qa6 = abs(q6);
var ok = true;
var c0 = 0u;
var c1 = 0u;
var c2 = 0u;
var c3 = 0u;
let pre = 0u;
{
let zm = Scalar(0.0);
let zs = Scalar(0.0);
c0 = c0 | select(0u, 1u << (pre | 0u), true & (q0 >= -tol.screen * (qa0 + rm0 * zs)) & (q1 >= -tol.screen * (qa1 + rm1 * zs)) & (q2 >= -tol.screen * (qa2 + rm2 * zs)) & (q3 >= -tol.screen * (qa3 + rm3 * zs)) & (q4 >= -tol.screen * (qa4 + rm4 * zs)) & (q5 >= -tol.screen * (qa5 + rm5 * zs)) & (q6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(m6_6 > tol.tree_singular * m6_6);
ok = ok & !(true & !dead6 & !(m6_6 > tol.tree_pivot * m6_6));
let l6 = true & !dead6;
let i6 = Scalar(1.0) / m6_6;
let n6 = -i6;
let t6_6 = -q6 * i6;
let t6_0 = q0 + m0_6 * t6_6;
let t6_1 = q1 + m1_6 * t6_6;
let t6_2 = q2 + m2_6 * t6_6;
let t6_3 = q3 + m3_6 * t6_6;
let t6_4 = q4 + m4_6 * t6_6;
let t6_5 = q5 + m5_6 * t6_6;
{
let zm = max(Scalar(0.0), abs(t6_6));
let zs = (Scalar(0.0) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 0u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(m5_5 > tol.tree_singular * m5_5);
ok = ok & !(true & !dead5 & !(m5_5 > tol.tree_pivot * m5_5));
let l5 = true & !dead5;
let i5 = Scalar(1.0) / m5_5;
let n5 = -i5;
let a5_5_6 = m5_6 * n5;
let t5_5 = -q5 * i5;
let a5_0_6 = m0_6 + m0_5 * a5_5_6;
let t5_0 = q0 + m0_5 * t5_5;
let a5_1_6 = m1_6 + m1_5 * a5_5_6;
let t5_1 = q1 + m1_5 * t5_5;
let a5_2_6 = m2_6 + m2_5 * a5_5_6;
let t5_2 = q2 + m2_5 * t5_5;
let a5_3_6 = m3_6 + m3_5 * a5_5_6;
let t5_3 = q3 + m3_5 * t5_5;
let a5_4_6 = m4_6 + m4_5 * a5_5_6;
let t5_4 = q4 + m4_5 * t5_5;
let a5_6_6 = m6_6 + m6_5 * a5_5_6;
let t5_6 = q6 + m6_5 * t5_5;
{
let zm = max(Scalar(0.0), abs(t5_5));
let zs = (Scalar(0.0) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 0u), l5 & (t5_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(Scalar(0.0), abs(t6_5)), abs(t6_6));
let zs = ((Scalar(0.0) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 0u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
}
}
}
{
let dead4 = semi & !(m4_4 > tol.tree_singular * m4_4);
ok = ok & !(true & !dead4 & !(m4_4 > tol.tree_pivot * m4_4));
let l4 = true & !dead4;
let i4 = Scalar(1.0) / m4_4;
let n4 = -i4;
let a4_4_5 = m4_5 * n4;
let a4_4_6 = m4_6 * n4;
let t4_4 = -q4 * i4;
let a4_0_5 = m0_5 + m0_4 * a4_4_5;
let a4_0_6 = m0_6 + m0_4 * a4_4_6;
let t4_0 = q0 + m0_4 * t4_4;
let a4_1_5 = m1_5 + m1_4 * a4_4_5;
let a4_1_6 = m1_6 + m1_4 * a4_4_6;
let t4_1 = q1 + m1_4 * t4_4;
let a4_2_5 = m2_5 + m2_4 * a4_4_5;
let a4_2_6 = m2_6 + m2_4 * a4_4_6;
let t4_2 = q2 + m2_4 * t4_4;
let a4_3_5 = m3_5 + m3_4 * a4_4_5;
let a4_3_6 = m3_6 + m3_4 * a4_4_6;
let t4_3 = q3 + m3_4 * t4_4;
let a4_5_5 = m5_5 + m5_4 * a4_4_5;
let a4_5_6 = m5_6 + m5_4 * a4_4_6;
let t4_5 = q5 + m5_4 * t4_4;
let a4_6_5 = m6_5 + m6_4 * a4_4_5;
let a4_6_6 = m6_6 + m6_4 * a4_4_6;
let t4_6 = q6 + m6_4 * t4_4;
{
let zm = max(Scalar(0.0), abs(t4_4));
let zs = (Scalar(0.0) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 16u), l4 & (t4_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t4_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t4_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t4_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let t6_6 = -t4_6 * i6;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let t6_5 = t4_5 + a4_5_6 * t6_6;
{
let zm = max(max(Scalar(0.0), abs(t6_4)), abs(t6_6));
let zs = ((Scalar(0.0) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 16u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let t5_6 = t4_6 + a4_6_5 * t5_5;
{
let zm = max(max(Scalar(0.0), abs(t5_4)), abs(t5_5));
let zs = ((Scalar(0.0) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 16u), l5 & (t5_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = (((Scalar(0.0) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 16u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
}
}
}
}
{
let dead3 = semi & !(m3_3 > tol.tree_singular * m3_3);
ok = ok & !(true & !dead3 & !(m3_3 > tol.tree_pivot * m3_3));
let l3 = true & !dead3;
let i3 = Scalar(1.0) / m3_3;
let n3 = -i3;
let a3_3_4 = m3_4 * n3;
let a3_3_5 = m3_5 * n3;
let a3_3_6 = m3_6 * n3;
let t3_3 = -q3 * i3;
let a3_0_4 = m0_4 + m0_3 * a3_3_4;
let a3_0_5 = m0_5 + m0_3 * a3_3_5;
let a3_0_6 = m0_6 + m0_3 * a3_3_6;
let t3_0 = q0 + m0_3 * t3_3;
let a3_1_4 = m1_4 + m1_3 * a3_3_4;
let a3_1_5 = m1_5 + m1_3 * a3_3_5;
let a3_1_6 = m1_6 + m1_3 * a3_3_6;
let t3_1 = q1 + m1_3 * t3_3;
let a3_2_4 = m2_4 + m2_3 * a3_3_4;
let a3_2_5 = m2_5 + m2_3 * a3_3_5;
let a3_2_6 = m2_6 + m2_3 * a3_3_6;
let t3_2 = q2 + m2_3 * t3_3;
let a3_4_4 = m4_4 + m4_3 * a3_3_4;
let a3_4_5 = m4_5 + m4_3 * a3_3_5;
let a3_4_6 = m4_6 + m4_3 * a3_3_6;
let t3_4 = q4 + m4_3 * t3_3;
let a3_5_4 = m5_4 + m5_3 * a3_3_4;
let a3_5_5 = m5_5 + m5_3 * a3_3_5;
let a3_5_6 = m5_6 + m5_3 * a3_3_6;
let t3_5 = q5 + m5_3 * t3_3;
let a3_6_4 = m6_4 + m6_3 * a3_3_4;
let a3_6_5 = m6_5 + m6_3 * a3_3_5;
let a3_6_6 = m6_6 + m6_3 * a3_3_6;
let t3_6 = q6 + m6_3 * t3_3;
{
let zm = max(Scalar(0.0), abs(t3_3));
let zs = (Scalar(0.0) + abs(t3_3));
c0 = c0 | select(0u, 1u << (pre | 8u), l3 & (t3_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t3_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t3_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t3_3 >= -tol.screen * zm) & (t3_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t3_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t3_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a3_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l3 & !dead6 & !(a3_6_6 > tol.tree_pivot * m6_6));
let l6 = l3 & !dead6;
let i6 = Scalar(1.0) / a3_6_6;
let n6 = -i6;
let t6_6 = -t3_6 * i6;
let t6_0 = t3_0 + a3_0_6 * t6_6;
let t6_1 = t3_1 + a3_1_6 * t6_6;
let t6_2 = t3_2 + a3_2_6 * t6_6;
let t6_3 = t3_3 + a3_3_6 * t6_6;
let t6_4 = t3_4 + a3_4_6 * t6_6;
let t6_5 = t3_5 + a3_5_6 * t6_6;
{
let zm = max(max(Scalar(0.0), abs(t6_3)), abs(t6_6));
let zs = ((Scalar(0.0) + abs(t6_3)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 8u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a3_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l3 & !dead5 & !(a3_5_5 > tol.tree_pivot * m5_5));
let l5 = l3 & !dead5;
let i5 = Scalar(1.0) / a3_5_5;
let n5 = -i5;
let a5_5_6 = a3_5_6 * n5;
let t5_5 = -t3_5 * i5;
let a5_0_6 = a3_0_6 + a3_0_5 * a5_5_6;
let t5_0 = t3_0 + a3_0_5 * t5_5;
let a5_1_6 = a3_1_6 + a3_1_5 * a5_5_6;
let t5_1 = t3_1 + a3_1_5 * t5_5;
let a5_2_6 = a3_2_6 + a3_2_5 * a5_5_6;
let t5_2 = t3_2 + a3_2_5 * t5_5;
let a5_3_6 = a3_3_6 + a3_3_5 * a5_5_6;
let t5_3 = t3_3 + a3_3_5 * t5_5;
let a5_4_6 = a3_4_6 + a3_4_5 * a5_5_6;
let t5_4 = t3_4 + a3_4_5 * t5_5;
let a5_6_6 = a3_6_6 + a3_6_5 * a5_5_6;
let t5_6 = t3_6 + a3_6_5 * t5_5;
{
let zm = max(max(Scalar(0.0), abs(t5_3)), abs(t5_5));
let zs = ((Scalar(0.0) + abs(t5_3)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 8u), l5 & (t5_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), abs(t6_3)), abs(t6_5)), abs(t6_6));
let zs = (((Scalar(0.0) + abs(t6_3)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 8u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t4_4 = -t3_4 * i4;
let a4_0_5 = a3_0_5 + a3_0_4 * a4_4_5;
let a4_0_6 = a3_0_6 + a3_0_4 * a4_4_6;
let t4_0 = t3_0 + a3_0_4 * t4_4;
let a4_1_5 = a3_1_5 + a3_1_4 * a4_4_5;
let a4_1_6 = a3_1_6 + a3_1_4 * a4_4_6;
let t4_1 = t3_1 + a3_1_4 * t4_4;
let a4_2_5 = a3_2_5 + a3_2_4 * a4_4_5;
let a4_2_6 = a3_2_6 + a3_2_4 * a4_4_6;
let t4_2 = t3_2 + a3_2_4 * t4_4;
let a4_3_5 = a3_3_5 + a3_3_4 * a4_4_5;
let a4_3_6 = a3_3_6 + a3_3_4 * a4_4_6;
let t4_3 = t3_3 + a3_3_4 * t4_4;
let a4_5_5 = a3_5_5 + a3_5_4 * a4_4_5;
let a4_5_6 = a3_5_6 + a3_5_4 * a4_4_6;
let t4_5 = t3_5 + a3_5_4 * t4_4;
let a4_6_5 = a3_6_5 + a3_6_4 * a4_4_5;
let a4_6_6 = a3_6_6 + a3_6_4 * a4_4_6;
let t4_6 = t3_6 + a3_6_4 * t4_4;
{
let zm = max(max(Scalar(0.0), abs(t4_3)), abs(t4_4));
let zs = ((Scalar(0.0) + abs(t4_3)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 24u), l4 & (t4_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t4_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t4_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t4_3 >= -tol.screen * zm) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let t6_6 = -t4_6 * i6;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let t6_5 = t4_5 + a4_5_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), abs(t6_3)), abs(t6_4)), abs(t6_6));
let zs = (((Scalar(0.0) + abs(t6_3)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 24u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let t5_6 = t4_6 + a4_6_5 * t5_5;
{
let zm = max(max(max(Scalar(0.0), abs(t5_3)), abs(t5_4)), abs(t5_5));
let zs = (((Scalar(0.0) + abs(t5_3)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 24u), l5 & (t5_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_3)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_3)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 24u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
}
}
}
}
}
{
let dead2 = semi & !(m2_2 > tol.tree_singular * m2_2);
ok = ok & !(true & !dead2 & !(m2_2 > tol.tree_pivot * m2_2));
let l2 = true & !dead2;
let i2 = Scalar(1.0) / m2_2;
let n2 = -i2;
let a2_2_3 = m2_3 * n2;
let a2_2_4 = m2_4 * n2;
let a2_2_5 = m2_5 * n2;
let a2_2_6 = m2_6 * n2;
let t2_2 = -q2 * i2;
let a2_0_3 = m0_3 + m0_2 * a2_2_3;
let a2_0_4 = m0_4 + m0_2 * a2_2_4;
let a2_0_5 = m0_5 + m0_2 * a2_2_5;
let a2_0_6 = m0_6 + m0_2 * a2_2_6;
let t2_0 = q0 + m0_2 * t2_2;
let a2_1_3 = m1_3 + m1_2 * a2_2_3;
let a2_1_4 = m1_4 + m1_2 * a2_2_4;
let a2_1_5 = m1_5 + m1_2 * a2_2_5;
let a2_1_6 = m1_6 + m1_2 * a2_2_6;
let t2_1 = q1 + m1_2 * t2_2;
let a2_3_3 = m3_3 + m3_2 * a2_2_3;
let a2_3_4 = m3_4 + m3_2 * a2_2_4;
let a2_3_5 = m3_5 + m3_2 * a2_2_5;
let a2_3_6 = m3_6 + m3_2 * a2_2_6;
let t2_3 = q3 + m3_2 * t2_2;
let a2_4_3 = m4_3 + m4_2 * a2_2_3;
let a2_4_4 = m4_4 + m4_2 * a2_2_4;
let a2_4_5 = m4_5 + m4_2 * a2_2_5;
let a2_4_6 = m4_6 + m4_2 * a2_2_6;
let t2_4 = q4 + m4_2 * t2_2;
let a2_5_3 = m5_3 + m5_2 * a2_2_3;
let a2_5_4 = m5_4 + m5_2 * a2_2_4;
let a2_5_5 = m5_5 + m5_2 * a2_2_5;
let a2_5_6 = m5_6 + m5_2 * a2_2_6;
let t2_5 = q5 + m5_2 * t2_2;
let a2_6_3 = m6_3 + m6_2 * a2_2_3;
let a2_6_4 = m6_4 + m6_2 * a2_2_4;
let a2_6_5 = m6_5 + m6_2 * a2_2_5;
let a2_6_6 = m6_6 + m6_2 * a2_2_6;
let t2_6 = q6 + m6_2 * t2_2;
{
let zm = max(Scalar(0.0), abs(t2_2));
let zs = (Scalar(0.0) + abs(t2_2));
c0 = c0 | select(0u, 1u << (pre | 4u), l2 & (t2_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t2_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t2_2 >= -tol.screen * zm) & (t2_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t2_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t2_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t2_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a2_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l2 & !dead6 & !(a2_6_6 > tol.tree_pivot * m6_6));
let l6 = l2 & !dead6;
let i6 = Scalar(1.0) / a2_6_6;
let n6 = -i6;
let t6_6 = -t2_6 * i6;
let t6_0 = t2_0 + a2_0_6 * t6_6;
let t6_1 = t2_1 + a2_1_6 * t6_6;
let t6_2 = t2_2 + a2_2_6 * t6_6;
let t6_3 = t2_3 + a2_3_6 * t6_6;
let t6_4 = t2_4 + a2_4_6 * t6_6;
let t6_5 = t2_5 + a2_5_6 * t6_6;
{
let zm = max(max(Scalar(0.0), abs(t6_2)), abs(t6_6));
let zs = ((Scalar(0.0) + abs(t6_2)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 4u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a2_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l2 & !dead5 & !(a2_5_5 > tol.tree_pivot * m5_5));
let l5 = l2 & !dead5;
let i5 = Scalar(1.0) / a2_5_5;
let n5 = -i5;
let a5_5_6 = a2_5_6 * n5;
let t5_5 = -t2_5 * i5;
let a5_0_6 = a2_0_6 + a2_0_5 * a5_5_6;
let t5_0 = t2_0 + a2_0_5 * t5_5;
let a5_1_6 = a2_1_6 + a2_1_5 * a5_5_6;
let t5_1 = t2_1 + a2_1_5 * t5_5;
let a5_2_6 = a2_2_6 + a2_2_5 * a5_5_6;
let t5_2 = t2_2 + a2_2_5 * t5_5;
let a5_3_6 = a2_3_6 + a2_3_5 * a5_5_6;
let t5_3 = t2_3 + a2_3_5 * t5_5;
let a5_4_6 = a2_4_6 + a2_4_5 * a5_5_6;
let t5_4 = t2_4 + a2_4_5 * t5_5;
let a5_6_6 = a2_6_6 + a2_6_5 * a5_5_6;
let t5_6 = t2_6 + a2_6_5 * t5_5;
{
let zm = max(max(Scalar(0.0), abs(t5_2)), abs(t5_5));
let zs = ((Scalar(0.0) + abs(t5_2)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 4u), l5 & (t5_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), abs(t6_2)), abs(t6_5)), abs(t6_6));
let zs = (((Scalar(0.0) + abs(t6_2)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 4u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t4_4 = -t2_4 * i4;
let a4_0_5 = a2_0_5 + a2_0_4 * a4_4_5;
let a4_0_6 = a2_0_6 + a2_0_4 * a4_4_6;
let t4_0 = t2_0 + a2_0_4 * t4_4;
let a4_1_5 = a2_1_5 + a2_1_4 * a4_4_5;
let a4_1_6 = a2_1_6 + a2_1_4 * a4_4_6;
let t4_1 = t2_1 + a2_1_4 * t4_4;
let a4_2_5 = a2_2_5 + a2_2_4 * a4_4_5;
let a4_2_6 = a2_2_6 + a2_2_4 * a4_4_6;
let t4_2 = t2_2 + a2_2_4 * t4_4;
let a4_3_5 = a2_3_5 + a2_3_4 * a4_4_5;
let a4_3_6 = a2_3_6 + a2_3_4 * a4_4_6;
let t4_3 = t2_3 + a2_3_4 * t4_4;
let a4_5_5 = a2_5_5 + a2_5_4 * a4_4_5;
let a4_5_6 = a2_5_6 + a2_5_4 * a4_4_6;
let t4_5 = t2_5 + a2_5_4 * t4_4;
let a4_6_5 = a2_6_5 + a2_6_4 * a4_4_5;
let a4_6_6 = a2_6_6 + a2_6_4 * a4_4_6;
let t4_6 = t2_6 + a2_6_4 * t4_4;
{
let zm = max(max(Scalar(0.0), abs(t4_2)), abs(t4_4));
let zs = ((Scalar(0.0) + abs(t4_2)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 20u), l4 & (t4_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t4_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t4_2 >= -tol.screen * zm) & (t4_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let t6_6 = -t4_6 * i6;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let t6_5 = t4_5 + a4_5_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), abs(t6_2)), abs(t6_4)), abs(t6_6));
let zs = (((Scalar(0.0) + abs(t6_2)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 20u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let t5_6 = t4_6 + a4_6_5 * t5_5;
{
let zm = max(max(max(Scalar(0.0), abs(t5_2)), abs(t5_4)), abs(t5_5));
let zs = (((Scalar(0.0) + abs(t5_2)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 20u), l5 & (t5_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_2)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_2)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 20u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t3_3 = -t2_3 * i3;
let a3_0_4 = a2_0_4 + a2_0_3 * a3_3_4;
let a3_0_5 = a2_0_5 + a2_0_3 * a3_3_5;
let a3_0_6 = a2_0_6 + a2_0_3 * a3_3_6;
let t3_0 = t2_0 + a2_0_3 * t3_3;
let a3_1_4 = a2_1_4 + a2_1_3 * a3_3_4;
let a3_1_5 = a2_1_5 + a2_1_3 * a3_3_5;
let a3_1_6 = a2_1_6 + a2_1_3 * a3_3_6;
let t3_1 = t2_1 + a2_1_3 * t3_3;
let a3_2_4 = a2_2_4 + a2_2_3 * a3_3_4;
let a3_2_5 = a2_2_5 + a2_2_3 * a3_3_5;
let a3_2_6 = a2_2_6 + a2_2_3 * a3_3_6;
let t3_2 = t2_2 + a2_2_3 * t3_3;
let a3_4_4 = a2_4_4 + a2_4_3 * a3_3_4;
let a3_4_5 = a2_4_5 + a2_4_3 * a3_3_5;
let a3_4_6 = a2_4_6 + a2_4_3 * a3_3_6;
let t3_4 = t2_4 + a2_4_3 * t3_3;
let a3_5_4 = a2_5_4 + a2_5_3 * a3_3_4;
let a3_5_5 = a2_5_5 + a2_5_3 * a3_3_5;
let a3_5_6 = a2_5_6 + a2_5_3 * a3_3_6;
let t3_5 = t2_5 + a2_5_3 * t3_3;
let a3_6_4 = a2_6_4 + a2_6_3 * a3_3_4;
let a3_6_5 = a2_6_5 + a2_6_3 * a3_3_5;
let a3_6_6 = a2_6_6 + a2_6_3 * a3_3_6;
let t3_6 = t2_6 + a2_6_3 * t3_3;
{
let zm = max(max(Scalar(0.0), abs(t3_2)), abs(t3_3));
let zs = ((Scalar(0.0) + abs(t3_2)) + abs(t3_3));
c0 = c0 | select(0u, 1u << (pre | 12u), l3 & (t3_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t3_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t3_2 >= -tol.screen * zm) & (t3_3 >= -tol.screen * zm) & (t3_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t3_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t3_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a3_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l3 & !dead6 & !(a3_6_6 > tol.tree_pivot * m6_6));
let l6 = l3 & !dead6;
let i6 = Scalar(1.0) / a3_6_6;
let n6 = -i6;
let t6_6 = -t3_6 * i6;
let t6_0 = t3_0 + a3_0_6 * t6_6;
let t6_1 = t3_1 + a3_1_6 * t6_6;
let t6_2 = t3_2 + a3_2_6 * t6_6;
let t6_3 = t3_3 + a3_3_6 * t6_6;
let t6_4 = t3_4 + a3_4_6 * t6_6;
let t6_5 = t3_5 + a3_5_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), abs(t6_2)), abs(t6_3)), abs(t6_6));
let zs = (((Scalar(0.0) + abs(t6_2)) + abs(t6_3)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 12u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a3_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l3 & !dead5 & !(a3_5_5 > tol.tree_pivot * m5_5));
let l5 = l3 & !dead5;
let i5 = Scalar(1.0) / a3_5_5;
let n5 = -i5;
let a5_5_6 = a3_5_6 * n5;
let t5_5 = -t3_5 * i5;
let a5_0_6 = a3_0_6 + a3_0_5 * a5_5_6;
let t5_0 = t3_0 + a3_0_5 * t5_5;
let a5_1_6 = a3_1_6 + a3_1_5 * a5_5_6;
let t5_1 = t3_1 + a3_1_5 * t5_5;
let a5_2_6 = a3_2_6 + a3_2_5 * a5_5_6;
let t5_2 = t3_2 + a3_2_5 * t5_5;
let a5_3_6 = a3_3_6 + a3_3_5 * a5_5_6;
let t5_3 = t3_3 + a3_3_5 * t5_5;
let a5_4_6 = a3_4_6 + a3_4_5 * a5_5_6;
let t5_4 = t3_4 + a3_4_5 * t5_5;
let a5_6_6 = a3_6_6 + a3_6_5 * a5_5_6;
let t5_6 = t3_6 + a3_6_5 * t5_5;
{
let zm = max(max(max(Scalar(0.0), abs(t5_2)), abs(t5_3)), abs(t5_5));
let zs = (((Scalar(0.0) + abs(t5_2)) + abs(t5_3)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 12u), l5 & (t5_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_2)), abs(t6_3)), abs(t6_5)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_2)) + abs(t6_3)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 12u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t4_4 = -t3_4 * i4;
let a4_0_5 = a3_0_5 + a3_0_4 * a4_4_5;
let a4_0_6 = a3_0_6 + a3_0_4 * a4_4_6;
let t4_0 = t3_0 + a3_0_4 * t4_4;
let a4_1_5 = a3_1_5 + a3_1_4 * a4_4_5;
let a4_1_6 = a3_1_6 + a3_1_4 * a4_4_6;
let t4_1 = t3_1 + a3_1_4 * t4_4;
let a4_2_5 = a3_2_5 + a3_2_4 * a4_4_5;
let a4_2_6 = a3_2_6 + a3_2_4 * a4_4_6;
let t4_2 = t3_2 + a3_2_4 * t4_4;
let a4_3_5 = a3_3_5 + a3_3_4 * a4_4_5;
let a4_3_6 = a3_3_6 + a3_3_4 * a4_4_6;
let t4_3 = t3_3 + a3_3_4 * t4_4;
let a4_5_5 = a3_5_5 + a3_5_4 * a4_4_5;
let a4_5_6 = a3_5_6 + a3_5_4 * a4_4_6;
let t4_5 = t3_5 + a3_5_4 * t4_4;
let a4_6_5 = a3_6_5 + a3_6_4 * a4_4_5;
let a4_6_6 = a3_6_6 + a3_6_4 * a4_4_6;
let t4_6 = t3_6 + a3_6_4 * t4_4;
{
let zm = max(max(max(Scalar(0.0), abs(t4_2)), abs(t4_3)), abs(t4_4));
let zs = (((Scalar(0.0) + abs(t4_2)) + abs(t4_3)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 28u), l4 & (t4_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t4_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t4_2 >= -tol.screen * zm) & (t4_3 >= -tol.screen * zm) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let t6_6 = -t4_6 * i6;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let t6_5 = t4_5 + a4_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_2)), abs(t6_3)), abs(t6_4)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_2)) + abs(t6_3)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 28u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let t5_6 = t4_6 + a4_6_5 * t5_5;
{
let zm = max(max(max(max(Scalar(0.0), abs(t5_2)), abs(t5_3)), abs(t5_4)), abs(t5_5));
let zs = ((((Scalar(0.0) + abs(t5_2)) + abs(t5_3)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 28u), l5 & (t5_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t6_2)), abs(t6_3)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = (((((Scalar(0.0) + abs(t6_2)) + abs(t6_3)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 28u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
}
}
}
}
}
}
{
let dead1 = semi & !(m1_1 > tol.tree_singular * m1_1);
ok = ok & !(true & !dead1 & !(m1_1 > tol.tree_pivot * m1_1));
let l1 = true & !dead1;
let i1 = Scalar(1.0) / m1_1;
let n1 = -i1;
let a1_1_2 = m1_2 * n1;
let a1_1_3 = m1_3 * n1;
let a1_1_4 = m1_4 * n1;
let a1_1_5 = m1_5 * n1;
let a1_1_6 = m1_6 * n1;
let t1_1 = -q1 * i1;
let a1_0_2 = m0_2 + m0_1 * a1_1_2;
let a1_0_3 = m0_3 + m0_1 * a1_1_3;
let a1_0_4 = m0_4 + m0_1 * a1_1_4;
let a1_0_5 = m0_5 + m0_1 * a1_1_5;
let a1_0_6 = m0_6 + m0_1 * a1_1_6;
let t1_0 = q0 + m0_1 * t1_1;
let a1_2_2 = m2_2 + m2_1 * a1_1_2;
let a1_2_3 = m2_3 + m2_1 * a1_1_3;
let a1_2_4 = m2_4 + m2_1 * a1_1_4;
let a1_2_5 = m2_5 + m2_1 * a1_1_5;
let a1_2_6 = m2_6 + m2_1 * a1_1_6;
let t1_2 = q2 + m2_1 * t1_1;
let a1_3_2 = m3_2 + m3_1 * a1_1_2;
let a1_3_3 = m3_3 + m3_1 * a1_1_3;
let a1_3_4 = m3_4 + m3_1 * a1_1_4;
let a1_3_5 = m3_5 + m3_1 * a1_1_5;
let a1_3_6 = m3_6 + m3_1 * a1_1_6;
let t1_3 = q3 + m3_1 * t1_1;
let a1_4_2 = m4_2 + m4_1 * a1_1_2;
let a1_4_3 = m4_3 + m4_1 * a1_1_3;
let a1_4_4 = m4_4 + m4_1 * a1_1_4;
let a1_4_5 = m4_5 + m4_1 * a1_1_5;
let a1_4_6 = m4_6 + m4_1 * a1_1_6;
let t1_4 = q4 + m4_1 * t1_1;
let a1_5_2 = m5_2 + m5_1 * a1_1_2;
let a1_5_3 = m5_3 + m5_1 * a1_1_3;
let a1_5_4 = m5_4 + m5_1 * a1_1_4;
let a1_5_5 = m5_5 + m5_1 * a1_1_5;
let a1_5_6 = m5_6 + m5_1 * a1_1_6;
let t1_5 = q5 + m5_1 * t1_1;
let a1_6_2 = m6_2 + m6_1 * a1_1_2;
let a1_6_3 = m6_3 + m6_1 * a1_1_3;
let a1_6_4 = m6_4 + m6_1 * a1_1_4;
let a1_6_5 = m6_5 + m6_1 * a1_1_5;
let a1_6_6 = m6_6 + m6_1 * a1_1_6;
let t1_6 = q6 + m6_1 * t1_1;
{
let zm = max(Scalar(0.0), abs(t1_1));
let zs = (Scalar(0.0) + abs(t1_1));
c0 = c0 | select(0u, 1u << (pre | 2u), l1 & (t1_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t1_1 >= -tol.screen * zm) & (t1_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t1_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t1_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t1_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t1_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a1_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l1 & !dead6 & !(a1_6_6 > tol.tree_pivot * m6_6));
let l6 = l1 & !dead6;
let i6 = Scalar(1.0) / a1_6_6;
let n6 = -i6;
let t6_6 = -t1_6 * i6;
let t6_0 = t1_0 + a1_0_6 * t6_6;
let t6_1 = t1_1 + a1_1_6 * t6_6;
let t6_2 = t1_2 + a1_2_6 * t6_6;
let t6_3 = t1_3 + a1_3_6 * t6_6;
let t6_4 = t1_4 + a1_4_6 * t6_6;
let t6_5 = t1_5 + a1_5_6 * t6_6;
{
let zm = max(max(Scalar(0.0), abs(t6_1)), abs(t6_6));
let zs = ((Scalar(0.0) + abs(t6_1)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 2u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a1_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l1 & !dead5 & !(a1_5_5 > tol.tree_pivot * m5_5));
let l5 = l1 & !dead5;
let i5 = Scalar(1.0) / a1_5_5;
let n5 = -i5;
let a5_5_6 = a1_5_6 * n5;
let t5_5 = -t1_5 * i5;
let a5_0_6 = a1_0_6 + a1_0_5 * a5_5_6;
let t5_0 = t1_0 + a1_0_5 * t5_5;
let a5_1_6 = a1_1_6 + a1_1_5 * a5_5_6;
let t5_1 = t1_1 + a1_1_5 * t5_5;
let a5_2_6 = a1_2_6 + a1_2_5 * a5_5_6;
let t5_2 = t1_2 + a1_2_5 * t5_5;
let a5_3_6 = a1_3_6 + a1_3_5 * a5_5_6;
let t5_3 = t1_3 + a1_3_5 * t5_5;
let a5_4_6 = a1_4_6 + a1_4_5 * a5_5_6;
let t5_4 = t1_4 + a1_4_5 * t5_5;
let a5_6_6 = a1_6_6 + a1_6_5 * a5_5_6;
let t5_6 = t1_6 + a1_6_5 * t5_5;
{
let zm = max(max(Scalar(0.0), abs(t5_1)), abs(t5_5));
let zs = ((Scalar(0.0) + abs(t5_1)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 2u), l5 & (t5_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), abs(t6_1)), abs(t6_5)), abs(t6_6));
let zs = (((Scalar(0.0) + abs(t6_1)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 2u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t4_4 = -t1_4 * i4;
let a4_0_5 = a1_0_5 + a1_0_4 * a4_4_5;
let a4_0_6 = a1_0_6 + a1_0_4 * a4_4_6;
let t4_0 = t1_0 + a1_0_4 * t4_4;
let a4_1_5 = a1_1_5 + a1_1_4 * a4_4_5;
let a4_1_6 = a1_1_6 + a1_1_4 * a4_4_6;
let t4_1 = t1_1 + a1_1_4 * t4_4;
let a4_2_5 = a1_2_5 + a1_2_4 * a4_4_5;
let a4_2_6 = a1_2_6 + a1_2_4 * a4_4_6;
let t4_2 = t1_2 + a1_2_4 * t4_4;
let a4_3_5 = a1_3_5 + a1_3_4 * a4_4_5;
let a4_3_6 = a1_3_6 + a1_3_4 * a4_4_6;
let t4_3 = t1_3 + a1_3_4 * t4_4;
let a4_5_5 = a1_5_5 + a1_5_4 * a4_4_5;
let a4_5_6 = a1_5_6 + a1_5_4 * a4_4_6;
let t4_5 = t1_5 + a1_5_4 * t4_4;
let a4_6_5 = a1_6_5 + a1_6_4 * a4_4_5;
let a4_6_6 = a1_6_6 + a1_6_4 * a4_4_6;
let t4_6 = t1_6 + a1_6_4 * t4_4;
{
let zm = max(max(Scalar(0.0), abs(t4_1)), abs(t4_4));
let zs = ((Scalar(0.0) + abs(t4_1)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 18u), l4 & (t4_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t4_1 >= -tol.screen * zm) & (t4_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t4_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let t6_6 = -t4_6 * i6;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let t6_5 = t4_5 + a4_5_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), abs(t6_1)), abs(t6_4)), abs(t6_6));
let zs = (((Scalar(0.0) + abs(t6_1)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 18u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let t5_6 = t4_6 + a4_6_5 * t5_5;
{
let zm = max(max(max(Scalar(0.0), abs(t5_1)), abs(t5_4)), abs(t5_5));
let zs = (((Scalar(0.0) + abs(t5_1)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 18u), l5 & (t5_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_1)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_1)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 18u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t3_3 = -t1_3 * i3;
let a3_0_4 = a1_0_4 + a1_0_3 * a3_3_4;
let a3_0_5 = a1_0_5 + a1_0_3 * a3_3_5;
let a3_0_6 = a1_0_6 + a1_0_3 * a3_3_6;
let t3_0 = t1_0 + a1_0_3 * t3_3;
let a3_1_4 = a1_1_4 + a1_1_3 * a3_3_4;
let a3_1_5 = a1_1_5 + a1_1_3 * a3_3_5;
let a3_1_6 = a1_1_6 + a1_1_3 * a3_3_6;
let t3_1 = t1_1 + a1_1_3 * t3_3;
let a3_2_4 = a1_2_4 + a1_2_3 * a3_3_4;
let a3_2_5 = a1_2_5 + a1_2_3 * a3_3_5;
let a3_2_6 = a1_2_6 + a1_2_3 * a3_3_6;
let t3_2 = t1_2 + a1_2_3 * t3_3;
let a3_4_4 = a1_4_4 + a1_4_3 * a3_3_4;
let a3_4_5 = a1_4_5 + a1_4_3 * a3_3_5;
let a3_4_6 = a1_4_6 + a1_4_3 * a3_3_6;
let t3_4 = t1_4 + a1_4_3 * t3_3;
let a3_5_4 = a1_5_4 + a1_5_3 * a3_3_4;
let a3_5_5 = a1_5_5 + a1_5_3 * a3_3_5;
let a3_5_6 = a1_5_6 + a1_5_3 * a3_3_6;
let t3_5 = t1_5 + a1_5_3 * t3_3;
let a3_6_4 = a1_6_4 + a1_6_3 * a3_3_4;
let a3_6_5 = a1_6_5 + a1_6_3 * a3_3_5;
let a3_6_6 = a1_6_6 + a1_6_3 * a3_3_6;
let t3_6 = t1_6 + a1_6_3 * t3_3;
{
let zm = max(max(Scalar(0.0), abs(t3_1)), abs(t3_3));
let zs = ((Scalar(0.0) + abs(t3_1)) + abs(t3_3));
c0 = c0 | select(0u, 1u << (pre | 10u), l3 & (t3_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t3_1 >= -tol.screen * zm) & (t3_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t3_3 >= -tol.screen * zm) & (t3_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t3_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t3_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a3_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l3 & !dead6 & !(a3_6_6 > tol.tree_pivot * m6_6));
let l6 = l3 & !dead6;
let i6 = Scalar(1.0) / a3_6_6;
let n6 = -i6;
let t6_6 = -t3_6 * i6;
let t6_0 = t3_0 + a3_0_6 * t6_6;
let t6_1 = t3_1 + a3_1_6 * t6_6;
let t6_2 = t3_2 + a3_2_6 * t6_6;
let t6_3 = t3_3 + a3_3_6 * t6_6;
let t6_4 = t3_4 + a3_4_6 * t6_6;
let t6_5 = t3_5 + a3_5_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), abs(t6_1)), abs(t6_3)), abs(t6_6));
let zs = (((Scalar(0.0) + abs(t6_1)) + abs(t6_3)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 10u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a3_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l3 & !dead5 & !(a3_5_5 > tol.tree_pivot * m5_5));
let l5 = l3 & !dead5;
let i5 = Scalar(1.0) / a3_5_5;
let n5 = -i5;
let a5_5_6 = a3_5_6 * n5;
let t5_5 = -t3_5 * i5;
let a5_0_6 = a3_0_6 + a3_0_5 * a5_5_6;
let t5_0 = t3_0 + a3_0_5 * t5_5;
let a5_1_6 = a3_1_6 + a3_1_5 * a5_5_6;
let t5_1 = t3_1 + a3_1_5 * t5_5;
let a5_2_6 = a3_2_6 + a3_2_5 * a5_5_6;
let t5_2 = t3_2 + a3_2_5 * t5_5;
let a5_3_6 = a3_3_6 + a3_3_5 * a5_5_6;
let t5_3 = t3_3 + a3_3_5 * t5_5;
let a5_4_6 = a3_4_6 + a3_4_5 * a5_5_6;
let t5_4 = t3_4 + a3_4_5 * t5_5;
let a5_6_6 = a3_6_6 + a3_6_5 * a5_5_6;
let t5_6 = t3_6 + a3_6_5 * t5_5;
{
let zm = max(max(max(Scalar(0.0), abs(t5_1)), abs(t5_3)), abs(t5_5));
let zs = (((Scalar(0.0) + abs(t5_1)) + abs(t5_3)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 10u), l5 & (t5_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_1)), abs(t6_3)), abs(t6_5)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_1)) + abs(t6_3)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 10u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t4_4 = -t3_4 * i4;
let a4_0_5 = a3_0_5 + a3_0_4 * a4_4_5;
let a4_0_6 = a3_0_6 + a3_0_4 * a4_4_6;
let t4_0 = t3_0 + a3_0_4 * t4_4;
let a4_1_5 = a3_1_5 + a3_1_4 * a4_4_5;
let a4_1_6 = a3_1_6 + a3_1_4 * a4_4_6;
let t4_1 = t3_1 + a3_1_4 * t4_4;
let a4_2_5 = a3_2_5 + a3_2_4 * a4_4_5;
let a4_2_6 = a3_2_6 + a3_2_4 * a4_4_6;
let t4_2 = t3_2 + a3_2_4 * t4_4;
let a4_3_5 = a3_3_5 + a3_3_4 * a4_4_5;
let a4_3_6 = a3_3_6 + a3_3_4 * a4_4_6;
let t4_3 = t3_3 + a3_3_4 * t4_4;
let a4_5_5 = a3_5_5 + a3_5_4 * a4_4_5;
let a4_5_6 = a3_5_6 + a3_5_4 * a4_4_6;
let t4_5 = t3_5 + a3_5_4 * t4_4;
let a4_6_5 = a3_6_5 + a3_6_4 * a4_4_5;
let a4_6_6 = a3_6_6 + a3_6_4 * a4_4_6;
let t4_6 = t3_6 + a3_6_4 * t4_4;
{
let zm = max(max(max(Scalar(0.0), abs(t4_1)), abs(t4_3)), abs(t4_4));
let zs = (((Scalar(0.0) + abs(t4_1)) + abs(t4_3)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 26u), l4 & (t4_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t4_1 >= -tol.screen * zm) & (t4_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t4_3 >= -tol.screen * zm) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let t6_6 = -t4_6 * i6;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let t6_5 = t4_5 + a4_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_1)), abs(t6_3)), abs(t6_4)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_1)) + abs(t6_3)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 26u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let t5_6 = t4_6 + a4_6_5 * t5_5;
{
let zm = max(max(max(max(Scalar(0.0), abs(t5_1)), abs(t5_3)), abs(t5_4)), abs(t5_5));
let zs = ((((Scalar(0.0) + abs(t5_1)) + abs(t5_3)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 26u), l5 & (t5_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t6_1)), abs(t6_3)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = (((((Scalar(0.0) + abs(t6_1)) + abs(t6_3)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 26u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t2_2 = -t1_2 * i2;
let a2_0_3 = a1_0_3 + a1_0_2 * a2_2_3;
let a2_0_4 = a1_0_4 + a1_0_2 * a2_2_4;
let a2_0_5 = a1_0_5 + a1_0_2 * a2_2_5;
let a2_0_6 = a1_0_6 + a1_0_2 * a2_2_6;
let t2_0 = t1_0 + a1_0_2 * t2_2;
let a2_1_3 = a1_1_3 + a1_1_2 * a2_2_3;
let a2_1_4 = a1_1_4 + a1_1_2 * a2_2_4;
let a2_1_5 = a1_1_5 + a1_1_2 * a2_2_5;
let a2_1_6 = a1_1_6 + a1_1_2 * a2_2_6;
let t2_1 = t1_1 + a1_1_2 * t2_2;
let a2_3_3 = a1_3_3 + a1_3_2 * a2_2_3;
let a2_3_4 = a1_3_4 + a1_3_2 * a2_2_4;
let a2_3_5 = a1_3_5 + a1_3_2 * a2_2_5;
let a2_3_6 = a1_3_6 + a1_3_2 * a2_2_6;
let t2_3 = t1_3 + a1_3_2 * t2_2;
let a2_4_3 = a1_4_3 + a1_4_2 * a2_2_3;
let a2_4_4 = a1_4_4 + a1_4_2 * a2_2_4;
let a2_4_5 = a1_4_5 + a1_4_2 * a2_2_5;
let a2_4_6 = a1_4_6 + a1_4_2 * a2_2_6;
let t2_4 = t1_4 + a1_4_2 * t2_2;
let a2_5_3 = a1_5_3 + a1_5_2 * a2_2_3;
let a2_5_4 = a1_5_4 + a1_5_2 * a2_2_4;
let a2_5_5 = a1_5_5 + a1_5_2 * a2_2_5;
let a2_5_6 = a1_5_6 + a1_5_2 * a2_2_6;
let t2_5 = t1_5 + a1_5_2 * t2_2;
let a2_6_3 = a1_6_3 + a1_6_2 * a2_2_3;
let a2_6_4 = a1_6_4 + a1_6_2 * a2_2_4;
let a2_6_5 = a1_6_5 + a1_6_2 * a2_2_5;
let a2_6_6 = a1_6_6 + a1_6_2 * a2_2_6;
let t2_6 = t1_6 + a1_6_2 * t2_2;
{
let zm = max(max(Scalar(0.0), abs(t2_1)), abs(t2_2));
let zs = ((Scalar(0.0) + abs(t2_1)) + abs(t2_2));
c0 = c0 | select(0u, 1u << (pre | 6u), l2 & (t2_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t2_1 >= -tol.screen * zm) & (t2_2 >= -tol.screen * zm) & (t2_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t2_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t2_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t2_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a2_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l2 & !dead6 & !(a2_6_6 > tol.tree_pivot * m6_6));
let l6 = l2 & !dead6;
let i6 = Scalar(1.0) / a2_6_6;
let n6 = -i6;
let t6_6 = -t2_6 * i6;
let t6_0 = t2_0 + a2_0_6 * t6_6;
let t6_1 = t2_1 + a2_1_6 * t6_6;
let t6_2 = t2_2 + a2_2_6 * t6_6;
let t6_3 = t2_3 + a2_3_6 * t6_6;
let t6_4 = t2_4 + a2_4_6 * t6_6;
let t6_5 = t2_5 + a2_5_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), abs(t6_1)), abs(t6_2)), abs(t6_6));
let zs = (((Scalar(0.0) + abs(t6_1)) + abs(t6_2)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 6u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a2_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l2 & !dead5 & !(a2_5_5 > tol.tree_pivot * m5_5));
let l5 = l2 & !dead5;
let i5 = Scalar(1.0) / a2_5_5;
let n5 = -i5;
let a5_5_6 = a2_5_6 * n5;
let t5_5 = -t2_5 * i5;
let a5_0_6 = a2_0_6 + a2_0_5 * a5_5_6;
let t5_0 = t2_0 + a2_0_5 * t5_5;
let a5_1_6 = a2_1_6 + a2_1_5 * a5_5_6;
let t5_1 = t2_1 + a2_1_5 * t5_5;
let a5_2_6 = a2_2_6 + a2_2_5 * a5_5_6;
let t5_2 = t2_2 + a2_2_5 * t5_5;
let a5_3_6 = a2_3_6 + a2_3_5 * a5_5_6;
let t5_3 = t2_3 + a2_3_5 * t5_5;
let a5_4_6 = a2_4_6 + a2_4_5 * a5_5_6;
let t5_4 = t2_4 + a2_4_5 * t5_5;
let a5_6_6 = a2_6_6 + a2_6_5 * a5_5_6;
let t5_6 = t2_6 + a2_6_5 * t5_5;
{
let zm = max(max(max(Scalar(0.0), abs(t5_1)), abs(t5_2)), abs(t5_5));
let zs = (((Scalar(0.0) + abs(t5_1)) + abs(t5_2)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 6u), l5 & (t5_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_1)), abs(t6_2)), abs(t6_5)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_1)) + abs(t6_2)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 6u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t4_4 = -t2_4 * i4;
let a4_0_5 = a2_0_5 + a2_0_4 * a4_4_5;
let a4_0_6 = a2_0_6 + a2_0_4 * a4_4_6;
let t4_0 = t2_0 + a2_0_4 * t4_4;
let a4_1_5 = a2_1_5 + a2_1_4 * a4_4_5;
let a4_1_6 = a2_1_6 + a2_1_4 * a4_4_6;
let t4_1 = t2_1 + a2_1_4 * t4_4;
let a4_2_5 = a2_2_5 + a2_2_4 * a4_4_5;
let a4_2_6 = a2_2_6 + a2_2_4 * a4_4_6;
let t4_2 = t2_2 + a2_2_4 * t4_4;
let a4_3_5 = a2_3_5 + a2_3_4 * a4_4_5;
let a4_3_6 = a2_3_6 + a2_3_4 * a4_4_6;
let t4_3 = t2_3 + a2_3_4 * t4_4;
let a4_5_5 = a2_5_5 + a2_5_4 * a4_4_5;
let a4_5_6 = a2_5_6 + a2_5_4 * a4_4_6;
let t4_5 = t2_5 + a2_5_4 * t4_4;
let a4_6_5 = a2_6_5 + a2_6_4 * a4_4_5;
let a4_6_6 = a2_6_6 + a2_6_4 * a4_4_6;
let t4_6 = t2_6 + a2_6_4 * t4_4;
{
let zm = max(max(max(Scalar(0.0), abs(t4_1)), abs(t4_2)), abs(t4_4));
let zs = (((Scalar(0.0) + abs(t4_1)) + abs(t4_2)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 22u), l4 & (t4_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t4_1 >= -tol.screen * zm) & (t4_2 >= -tol.screen * zm) & (t4_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let t6_6 = -t4_6 * i6;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let t6_5 = t4_5 + a4_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_1)), abs(t6_2)), abs(t6_4)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_1)) + abs(t6_2)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 22u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let t5_6 = t4_6 + a4_6_5 * t5_5;
{
let zm = max(max(max(max(Scalar(0.0), abs(t5_1)), abs(t5_2)), abs(t5_4)), abs(t5_5));
let zs = ((((Scalar(0.0) + abs(t5_1)) + abs(t5_2)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 22u), l5 & (t5_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t6_1)), abs(t6_2)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = (((((Scalar(0.0) + abs(t6_1)) + abs(t6_2)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 22u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t3_3 = -t2_3 * i3;
let a3_0_4 = a2_0_4 + a2_0_3 * a3_3_4;
let a3_0_5 = a2_0_5 + a2_0_3 * a3_3_5;
let a3_0_6 = a2_0_6 + a2_0_3 * a3_3_6;
let t3_0 = t2_0 + a2_0_3 * t3_3;
let a3_1_4 = a2_1_4 + a2_1_3 * a3_3_4;
let a3_1_5 = a2_1_5 + a2_1_3 * a3_3_5;
let a3_1_6 = a2_1_6 + a2_1_3 * a3_3_6;
let t3_1 = t2_1 + a2_1_3 * t3_3;
let a3_2_4 = a2_2_4 + a2_2_3 * a3_3_4;
let a3_2_5 = a2_2_5 + a2_2_3 * a3_3_5;
let a3_2_6 = a2_2_6 + a2_2_3 * a3_3_6;
let t3_2 = t2_2 + a2_2_3 * t3_3;
let a3_4_4 = a2_4_4 + a2_4_3 * a3_3_4;
let a3_4_5 = a2_4_5 + a2_4_3 * a3_3_5;
let a3_4_6 = a2_4_6 + a2_4_3 * a3_3_6;
let t3_4 = t2_4 + a2_4_3 * t3_3;
let a3_5_4 = a2_5_4 + a2_5_3 * a3_3_4;
let a3_5_5 = a2_5_5 + a2_5_3 * a3_3_5;
let a3_5_6 = a2_5_6 + a2_5_3 * a3_3_6;
let t3_5 = t2_5 + a2_5_3 * t3_3;
let a3_6_4 = a2_6_4 + a2_6_3 * a3_3_4;
let a3_6_5 = a2_6_5 + a2_6_3 * a3_3_5;
let a3_6_6 = a2_6_6 + a2_6_3 * a3_3_6;
let t3_6 = t2_6 + a2_6_3 * t3_3;
{
let zm = max(max(max(Scalar(0.0), abs(t3_1)), abs(t3_2)), abs(t3_3));
let zs = (((Scalar(0.0) + abs(t3_1)) + abs(t3_2)) + abs(t3_3));
c0 = c0 | select(0u, 1u << (pre | 14u), l3 & (t3_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t3_1 >= -tol.screen * zm) & (t3_2 >= -tol.screen * zm) & (t3_3 >= -tol.screen * zm) & (t3_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t3_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t3_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a3_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l3 & !dead6 & !(a3_6_6 > tol.tree_pivot * m6_6));
let l6 = l3 & !dead6;
let i6 = Scalar(1.0) / a3_6_6;
let n6 = -i6;
let t6_6 = -t3_6 * i6;
let t6_0 = t3_0 + a3_0_6 * t6_6;
let t6_1 = t3_1 + a3_1_6 * t6_6;
let t6_2 = t3_2 + a3_2_6 * t6_6;
let t6_3 = t3_3 + a3_3_6 * t6_6;
let t6_4 = t3_4 + a3_4_6 * t6_6;
let t6_5 = t3_5 + a3_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_1)), abs(t6_2)), abs(t6_3)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_1)) + abs(t6_2)) + abs(t6_3)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 14u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a3_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l3 & !dead5 & !(a3_5_5 > tol.tree_pivot * m5_5));
let l5 = l3 & !dead5;
let i5 = Scalar(1.0) / a3_5_5;
let n5 = -i5;
let a5_5_6 = a3_5_6 * n5;
let t5_5 = -t3_5 * i5;
let a5_0_6 = a3_0_6 + a3_0_5 * a5_5_6;
let t5_0 = t3_0 + a3_0_5 * t5_5;
let a5_1_6 = a3_1_6 + a3_1_5 * a5_5_6;
let t5_1 = t3_1 + a3_1_5 * t5_5;
let a5_2_6 = a3_2_6 + a3_2_5 * a5_5_6;
let t5_2 = t3_2 + a3_2_5 * t5_5;
let a5_3_6 = a3_3_6 + a3_3_5 * a5_5_6;
let t5_3 = t3_3 + a3_3_5 * t5_5;
let a5_4_6 = a3_4_6 + a3_4_5 * a5_5_6;
let t5_4 = t3_4 + a3_4_5 * t5_5;
let a5_6_6 = a3_6_6 + a3_6_5 * a5_5_6;
let t5_6 = t3_6 + a3_6_5 * t5_5;
{
let zm = max(max(max(max(Scalar(0.0), abs(t5_1)), abs(t5_2)), abs(t5_3)), abs(t5_5));
let zs = ((((Scalar(0.0) + abs(t5_1)) + abs(t5_2)) + abs(t5_3)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 14u), l5 & (t5_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t6_1)), abs(t6_2)), abs(t6_3)), abs(t6_5)), abs(t6_6));
let zs = (((((Scalar(0.0) + abs(t6_1)) + abs(t6_2)) + abs(t6_3)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 14u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t4_4 = -t3_4 * i4;
let a4_0_5 = a3_0_5 + a3_0_4 * a4_4_5;
let a4_0_6 = a3_0_6 + a3_0_4 * a4_4_6;
let t4_0 = t3_0 + a3_0_4 * t4_4;
let a4_1_5 = a3_1_5 + a3_1_4 * a4_4_5;
let a4_1_6 = a3_1_6 + a3_1_4 * a4_4_6;
let t4_1 = t3_1 + a3_1_4 * t4_4;
let a4_2_5 = a3_2_5 + a3_2_4 * a4_4_5;
let a4_2_6 = a3_2_6 + a3_2_4 * a4_4_6;
let t4_2 = t3_2 + a3_2_4 * t4_4;
let a4_3_5 = a3_3_5 + a3_3_4 * a4_4_5;
let a4_3_6 = a3_3_6 + a3_3_4 * a4_4_6;
let t4_3 = t3_3 + a3_3_4 * t4_4;
let a4_5_5 = a3_5_5 + a3_5_4 * a4_4_5;
let a4_5_6 = a3_5_6 + a3_5_4 * a4_4_6;
let t4_5 = t3_5 + a3_5_4 * t4_4;
let a4_6_5 = a3_6_5 + a3_6_4 * a4_4_5;
let a4_6_6 = a3_6_6 + a3_6_4 * a4_4_6;
let t4_6 = t3_6 + a3_6_4 * t4_4;
{
let zm = max(max(max(max(Scalar(0.0), abs(t4_1)), abs(t4_2)), abs(t4_3)), abs(t4_4));
let zs = ((((Scalar(0.0) + abs(t4_1)) + abs(t4_2)) + abs(t4_3)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 30u), l4 & (t4_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t4_1 >= -tol.screen * zm) & (t4_2 >= -tol.screen * zm) & (t4_3 >= -tol.screen * zm) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let t6_6 = -t4_6 * i6;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let t6_5 = t4_5 + a4_5_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t6_1)), abs(t6_2)), abs(t6_3)), abs(t6_4)), abs(t6_6));
let zs = (((((Scalar(0.0) + abs(t6_1)) + abs(t6_2)) + abs(t6_3)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 30u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let t5_6 = t4_6 + a4_6_5 * t5_5;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t5_1)), abs(t5_2)), abs(t5_3)), abs(t5_4)), abs(t5_5));
let zs = (((((Scalar(0.0) + abs(t5_1)) + abs(t5_2)) + abs(t5_3)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 30u), l5 & (t5_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(max(max(Scalar(0.0), abs(t6_1)), abs(t6_2)), abs(t6_3)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = ((((((Scalar(0.0) + abs(t6_1)) + abs(t6_2)) + abs(t6_3)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 30u), l6 & (t6_0 >= -tol.screen * (qa0 + rm0 * zs)) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
}
}
}
}
}
}
}
{
let dead0 = semi & !(m0_0 > tol.tree_singular * m0_0);
ok = ok & !(true & !dead0 & !(m0_0 > tol.tree_pivot * m0_0));
let l0 = true & !dead0;
let i0 = Scalar(1.0) / m0_0;
let n0 = -i0;
let a0_0_1 = m0_1 * n0;
let a0_0_2 = m0_2 * n0;
let a0_0_3 = m0_3 * n0;
let a0_0_4 = m0_4 * n0;
let a0_0_5 = m0_5 * n0;
let a0_0_6 = m0_6 * n0;
let t0_0 = -q0 * i0;
let a0_1_1 = m1_1 + m1_0 * a0_0_1;
let a0_1_2 = m1_2 + m1_0 * a0_0_2;
let a0_1_3 = m1_3 + m1_0 * a0_0_3;
let a0_1_4 = m1_4 + m1_0 * a0_0_4;
let a0_1_5 = m1_5 + m1_0 * a0_0_5;
let a0_1_6 = m1_6 + m1_0 * a0_0_6;
let t0_1 = q1 + m1_0 * t0_0;
let a0_2_1 = m2_1 + m2_0 * a0_0_1;
let a0_2_2 = m2_2 + m2_0 * a0_0_2;
let a0_2_3 = m2_3 + m2_0 * a0_0_3;
let a0_2_4 = m2_4 + m2_0 * a0_0_4;
let a0_2_5 = m2_5 + m2_0 * a0_0_5;
let a0_2_6 = m2_6 + m2_0 * a0_0_6;
let t0_2 = q2 + m2_0 * t0_0;
let a0_3_1 = m3_1 + m3_0 * a0_0_1;
let a0_3_2 = m3_2 + m3_0 * a0_0_2;
let a0_3_3 = m3_3 + m3_0 * a0_0_3;
let a0_3_4 = m3_4 + m3_0 * a0_0_4;
let a0_3_5 = m3_5 + m3_0 * a0_0_5;
let a0_3_6 = m3_6 + m3_0 * a0_0_6;
let t0_3 = q3 + m3_0 * t0_0;
let a0_4_1 = m4_1 + m4_0 * a0_0_1;
let a0_4_2 = m4_2 + m4_0 * a0_0_2;
let a0_4_3 = m4_3 + m4_0 * a0_0_3;
let a0_4_4 = m4_4 + m4_0 * a0_0_4;
let a0_4_5 = m4_5 + m4_0 * a0_0_5;
let a0_4_6 = m4_6 + m4_0 * a0_0_6;
let t0_4 = q4 + m4_0 * t0_0;
let a0_5_1 = m5_1 + m5_0 * a0_0_1;
let a0_5_2 = m5_2 + m5_0 * a0_0_2;
let a0_5_3 = m5_3 + m5_0 * a0_0_3;
let a0_5_4 = m5_4 + m5_0 * a0_0_4;
let a0_5_5 = m5_5 + m5_0 * a0_0_5;
let a0_5_6 = m5_6 + m5_0 * a0_0_6;
let t0_5 = q5 + m5_0 * t0_0;
let a0_6_1 = m6_1 + m6_0 * a0_0_1;
let a0_6_2 = m6_2 + m6_0 * a0_0_2;
let a0_6_3 = m6_3 + m6_0 * a0_0_3;
let a0_6_4 = m6_4 + m6_0 * a0_0_4;
let a0_6_5 = m6_5 + m6_0 * a0_0_5;
let a0_6_6 = m6_6 + m6_0 * a0_0_6;
let t0_6 = q6 + m6_0 * t0_0;
{
let zm = max(Scalar(0.0), abs(t0_0));
let zs = (Scalar(0.0) + abs(t0_0));
c0 = c0 | select(0u, 1u << (pre | 1u), l0 & (t0_0 >= -tol.screen * zm) & (t0_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t0_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t0_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t0_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t0_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t0_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a0_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l0 & !dead6 & !(a0_6_6 > tol.tree_pivot * m6_6));
let l6 = l0 & !dead6;
let i6 = Scalar(1.0) / a0_6_6;
let n6 = -i6;
let t6_6 = -t0_6 * i6;
let t6_0 = t0_0 + a0_0_6 * t6_6;
let t6_1 = t0_1 + a0_1_6 * t6_6;
let t6_2 = t0_2 + a0_2_6 * t6_6;
let t6_3 = t0_3 + a0_3_6 * t6_6;
let t6_4 = t0_4 + a0_4_6 * t6_6;
let t6_5 = t0_5 + a0_5_6 * t6_6;
{
let zm = max(max(Scalar(0.0), abs(t6_0)), abs(t6_6));
let zs = ((Scalar(0.0) + abs(t6_0)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 1u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a0_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l0 & !dead5 & !(a0_5_5 > tol.tree_pivot * m5_5));
let l5 = l0 & !dead5;
let i5 = Scalar(1.0) / a0_5_5;
let n5 = -i5;
let a5_5_6 = a0_5_6 * n5;
let t5_5 = -t0_5 * i5;
let a5_0_6 = a0_0_6 + a0_0_5 * a5_5_6;
let t5_0 = t0_0 + a0_0_5 * t5_5;
let a5_1_6 = a0_1_6 + a0_1_5 * a5_5_6;
let t5_1 = t0_1 + a0_1_5 * t5_5;
let a5_2_6 = a0_2_6 + a0_2_5 * a5_5_6;
let t5_2 = t0_2 + a0_2_5 * t5_5;
let a5_3_6 = a0_3_6 + a0_3_5 * a5_5_6;
let t5_3 = t0_3 + a0_3_5 * t5_5;
let a5_4_6 = a0_4_6 + a0_4_5 * a5_5_6;
let t5_4 = t0_4 + a0_4_5 * t5_5;
let a5_6_6 = a0_6_6 + a0_6_5 * a5_5_6;
let t5_6 = t0_6 + a0_6_5 * t5_5;
{
let zm = max(max(Scalar(0.0), abs(t5_0)), abs(t5_5));
let zs = ((Scalar(0.0) + abs(t5_0)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 1u), l5 & (t5_0 >= -tol.screen * zm) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_5)), abs(t6_6));
let zs = (((Scalar(0.0) + abs(t6_0)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 1u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
}
}
}
{
let dead4 = semi & !(a0_4_4 > tol.tree_singular * m4_4);
ok = ok & !(l0 & !dead4 & !(a0_4_4 > tol.tree_pivot * m4_4));
let l4 = l0 & !dead4;
let i4 = Scalar(1.0) / a0_4_4;
let n4 = -i4;
let a4_4_5 = a0_4_5 * n4;
let a4_4_6 = a0_4_6 * n4;
let t4_4 = -t0_4 * i4;
let a4_0_5 = a0_0_5 + a0_0_4 * a4_4_5;
let a4_0_6 = a0_0_6 + a0_0_4 * a4_4_6;
let t4_0 = t0_0 + a0_0_4 * t4_4;
let a4_1_5 = a0_1_5 + a0_1_4 * a4_4_5;
let a4_1_6 = a0_1_6 + a0_1_4 * a4_4_6;
let t4_1 = t0_1 + a0_1_4 * t4_4;
let a4_2_5 = a0_2_5 + a0_2_4 * a4_4_5;
let a4_2_6 = a0_2_6 + a0_2_4 * a4_4_6;
let t4_2 = t0_2 + a0_2_4 * t4_4;
let a4_3_5 = a0_3_5 + a0_3_4 * a4_4_5;
let a4_3_6 = a0_3_6 + a0_3_4 * a4_4_6;
let t4_3 = t0_3 + a0_3_4 * t4_4;
let a4_5_5 = a0_5_5 + a0_5_4 * a4_4_5;
let a4_5_6 = a0_5_6 + a0_5_4 * a4_4_6;
let t4_5 = t0_5 + a0_5_4 * t4_4;
let a4_6_5 = a0_6_5 + a0_6_4 * a4_4_5;
let a4_6_6 = a0_6_6 + a0_6_4 * a4_4_6;
let t4_6 = t0_6 + a0_6_4 * t4_4;
{
let zm = max(max(Scalar(0.0), abs(t4_0)), abs(t4_4));
let zs = ((Scalar(0.0) + abs(t4_0)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 17u), l4 & (t4_0 >= -tol.screen * zm) & (t4_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t4_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t4_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let t6_6 = -t4_6 * i6;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let t6_5 = t4_5 + a4_5_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_4)), abs(t6_6));
let zs = (((Scalar(0.0) + abs(t6_0)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 17u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let t5_6 = t4_6 + a4_6_5 * t5_5;
{
let zm = max(max(max(Scalar(0.0), abs(t5_0)), abs(t5_4)), abs(t5_5));
let zs = (((Scalar(0.0) + abs(t5_0)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 17u), l5 & (t5_0 >= -tol.screen * zm) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_0)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 17u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
}
}
}
}
{
let dead3 = semi & !(a0_3_3 > tol.tree_singular * m3_3);
ok = ok & !(l0 & !dead3 & !(a0_3_3 > tol.tree_pivot * m3_3));
let l3 = l0 & !dead3;
let i3 = Scalar(1.0) / a0_3_3;
let n3 = -i3;
let a3_3_4 = a0_3_4 * n3;
let a3_3_5 = a0_3_5 * n3;
let a3_3_6 = a0_3_6 * n3;
let t3_3 = -t0_3 * i3;
let a3_0_4 = a0_0_4 + a0_0_3 * a3_3_4;
let a3_0_5 = a0_0_5 + a0_0_3 * a3_3_5;
let a3_0_6 = a0_0_6 + a0_0_3 * a3_3_6;
let t3_0 = t0_0 + a0_0_3 * t3_3;
let a3_1_4 = a0_1_4 + a0_1_3 * a3_3_4;
let a3_1_5 = a0_1_5 + a0_1_3 * a3_3_5;
let a3_1_6 = a0_1_6 + a0_1_3 * a3_3_6;
let t3_1 = t0_1 + a0_1_3 * t3_3;
let a3_2_4 = a0_2_4 + a0_2_3 * a3_3_4;
let a3_2_5 = a0_2_5 + a0_2_3 * a3_3_5;
let a3_2_6 = a0_2_6 + a0_2_3 * a3_3_6;
let t3_2 = t0_2 + a0_2_3 * t3_3;
let a3_4_4 = a0_4_4 + a0_4_3 * a3_3_4;
let a3_4_5 = a0_4_5 + a0_4_3 * a3_3_5;
let a3_4_6 = a0_4_6 + a0_4_3 * a3_3_6;
let t3_4 = t0_4 + a0_4_3 * t3_3;
let a3_5_4 = a0_5_4 + a0_5_3 * a3_3_4;
let a3_5_5 = a0_5_5 + a0_5_3 * a3_3_5;
let a3_5_6 = a0_5_6 + a0_5_3 * a3_3_6;
let t3_5 = t0_5 + a0_5_3 * t3_3;
let a3_6_4 = a0_6_4 + a0_6_3 * a3_3_4;
let a3_6_5 = a0_6_5 + a0_6_3 * a3_3_5;
let a3_6_6 = a0_6_6 + a0_6_3 * a3_3_6;
let t3_6 = t0_6 + a0_6_3 * t3_3;
{
let zm = max(max(Scalar(0.0), abs(t3_0)), abs(t3_3));
let zs = ((Scalar(0.0) + abs(t3_0)) + abs(t3_3));
c0 = c0 | select(0u, 1u << (pre | 9u), l3 & (t3_0 >= -tol.screen * zm) & (t3_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t3_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t3_3 >= -tol.screen * zm) & (t3_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t3_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t3_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a3_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l3 & !dead6 & !(a3_6_6 > tol.tree_pivot * m6_6));
let l6 = l3 & !dead6;
let i6 = Scalar(1.0) / a3_6_6;
let n6 = -i6;
let t6_6 = -t3_6 * i6;
let t6_0 = t3_0 + a3_0_6 * t6_6;
let t6_1 = t3_1 + a3_1_6 * t6_6;
let t6_2 = t3_2 + a3_2_6 * t6_6;
let t6_3 = t3_3 + a3_3_6 * t6_6;
let t6_4 = t3_4 + a3_4_6 * t6_6;
let t6_5 = t3_5 + a3_5_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_3)), abs(t6_6));
let zs = (((Scalar(0.0) + abs(t6_0)) + abs(t6_3)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 9u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a3_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l3 & !dead5 & !(a3_5_5 > tol.tree_pivot * m5_5));
let l5 = l3 & !dead5;
let i5 = Scalar(1.0) / a3_5_5;
let n5 = -i5;
let a5_5_6 = a3_5_6 * n5;
let t5_5 = -t3_5 * i5;
let a5_0_6 = a3_0_6 + a3_0_5 * a5_5_6;
let t5_0 = t3_0 + a3_0_5 * t5_5;
let a5_1_6 = a3_1_6 + a3_1_5 * a5_5_6;
let t5_1 = t3_1 + a3_1_5 * t5_5;
let a5_2_6 = a3_2_6 + a3_2_5 * a5_5_6;
let t5_2 = t3_2 + a3_2_5 * t5_5;
let a5_3_6 = a3_3_6 + a3_3_5 * a5_5_6;
let t5_3 = t3_3 + a3_3_5 * t5_5;
let a5_4_6 = a3_4_6 + a3_4_5 * a5_5_6;
let t5_4 = t3_4 + a3_4_5 * t5_5;
let a5_6_6 = a3_6_6 + a3_6_5 * a5_5_6;
let t5_6 = t3_6 + a3_6_5 * t5_5;
{
let zm = max(max(max(Scalar(0.0), abs(t5_0)), abs(t5_3)), abs(t5_5));
let zs = (((Scalar(0.0) + abs(t5_0)) + abs(t5_3)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 9u), l5 & (t5_0 >= -tol.screen * zm) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_3)), abs(t6_5)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_0)) + abs(t6_3)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 9u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t4_4 = -t3_4 * i4;
let a4_0_5 = a3_0_5 + a3_0_4 * a4_4_5;
let a4_0_6 = a3_0_6 + a3_0_4 * a4_4_6;
let t4_0 = t3_0 + a3_0_4 * t4_4;
let a4_1_5 = a3_1_5 + a3_1_4 * a4_4_5;
let a4_1_6 = a3_1_6 + a3_1_4 * a4_4_6;
let t4_1 = t3_1 + a3_1_4 * t4_4;
let a4_2_5 = a3_2_5 + a3_2_4 * a4_4_5;
let a4_2_6 = a3_2_6 + a3_2_4 * a4_4_6;
let t4_2 = t3_2 + a3_2_4 * t4_4;
let a4_3_5 = a3_3_5 + a3_3_4 * a4_4_5;
let a4_3_6 = a3_3_6 + a3_3_4 * a4_4_6;
let t4_3 = t3_3 + a3_3_4 * t4_4;
let a4_5_5 = a3_5_5 + a3_5_4 * a4_4_5;
let a4_5_6 = a3_5_6 + a3_5_4 * a4_4_6;
let t4_5 = t3_5 + a3_5_4 * t4_4;
let a4_6_5 = a3_6_5 + a3_6_4 * a4_4_5;
let a4_6_6 = a3_6_6 + a3_6_4 * a4_4_6;
let t4_6 = t3_6 + a3_6_4 * t4_4;
{
let zm = max(max(max(Scalar(0.0), abs(t4_0)), abs(t4_3)), abs(t4_4));
let zs = (((Scalar(0.0) + abs(t4_0)) + abs(t4_3)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 25u), l4 & (t4_0 >= -tol.screen * zm) & (t4_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t4_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t4_3 >= -tol.screen * zm) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let t6_6 = -t4_6 * i6;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let t6_5 = t4_5 + a4_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_3)), abs(t6_4)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_0)) + abs(t6_3)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 25u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let t5_6 = t4_6 + a4_6_5 * t5_5;
{
let zm = max(max(max(max(Scalar(0.0), abs(t5_0)), abs(t5_3)), abs(t5_4)), abs(t5_5));
let zs = ((((Scalar(0.0) + abs(t5_0)) + abs(t5_3)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 25u), l5 & (t5_0 >= -tol.screen * zm) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_3)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = (((((Scalar(0.0) + abs(t6_0)) + abs(t6_3)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 25u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
}
}
}
}
}
{
let dead2 = semi & !(a0_2_2 > tol.tree_singular * m2_2);
ok = ok & !(l0 & !dead2 & !(a0_2_2 > tol.tree_pivot * m2_2));
let l2 = l0 & !dead2;
let i2 = Scalar(1.0) / a0_2_2;
let n2 = -i2;
let a2_2_3 = a0_2_3 * n2;
let a2_2_4 = a0_2_4 * n2;
let a2_2_5 = a0_2_5 * n2;
let a2_2_6 = a0_2_6 * n2;
let t2_2 = -t0_2 * i2;
let a2_0_3 = a0_0_3 + a0_0_2 * a2_2_3;
let a2_0_4 = a0_0_4 + a0_0_2 * a2_2_4;
let a2_0_5 = a0_0_5 + a0_0_2 * a2_2_5;
let a2_0_6 = a0_0_6 + a0_0_2 * a2_2_6;
let t2_0 = t0_0 + a0_0_2 * t2_2;
let a2_1_3 = a0_1_3 + a0_1_2 * a2_2_3;
let a2_1_4 = a0_1_4 + a0_1_2 * a2_2_4;
let a2_1_5 = a0_1_5 + a0_1_2 * a2_2_5;
let a2_1_6 = a0_1_6 + a0_1_2 * a2_2_6;
let t2_1 = t0_1 + a0_1_2 * t2_2;
let a2_3_3 = a0_3_3 + a0_3_2 * a2_2_3;
let a2_3_4 = a0_3_4 + a0_3_2 * a2_2_4;
let a2_3_5 = a0_3_5 + a0_3_2 * a2_2_5;
let a2_3_6 = a0_3_6 + a0_3_2 * a2_2_6;
let t2_3 = t0_3 + a0_3_2 * t2_2;
let a2_4_3 = a0_4_3 + a0_4_2 * a2_2_3;
let a2_4_4 = a0_4_4 + a0_4_2 * a2_2_4;
let a2_4_5 = a0_4_5 + a0_4_2 * a2_2_5;
let a2_4_6 = a0_4_6 + a0_4_2 * a2_2_6;
let t2_4 = t0_4 + a0_4_2 * t2_2;
let a2_5_3 = a0_5_3 + a0_5_2 * a2_2_3;
let a2_5_4 = a0_5_4 + a0_5_2 * a2_2_4;
let a2_5_5 = a0_5_5 + a0_5_2 * a2_2_5;
let a2_5_6 = a0_5_6 + a0_5_2 * a2_2_6;
let t2_5 = t0_5 + a0_5_2 * t2_2;
let a2_6_3 = a0_6_3 + a0_6_2 * a2_2_3;
let a2_6_4 = a0_6_4 + a0_6_2 * a2_2_4;
let a2_6_5 = a0_6_5 + a0_6_2 * a2_2_5;
let a2_6_6 = a0_6_6 + a0_6_2 * a2_2_6;
let t2_6 = t0_6 + a0_6_2 * t2_2;
{
let zm = max(max(Scalar(0.0), abs(t2_0)), abs(t2_2));
let zs = ((Scalar(0.0) + abs(t2_0)) + abs(t2_2));
c0 = c0 | select(0u, 1u << (pre | 5u), l2 & (t2_0 >= -tol.screen * zm) & (t2_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t2_2 >= -tol.screen * zm) & (t2_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t2_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t2_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t2_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a2_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l2 & !dead6 & !(a2_6_6 > tol.tree_pivot * m6_6));
let l6 = l2 & !dead6;
let i6 = Scalar(1.0) / a2_6_6;
let n6 = -i6;
let t6_6 = -t2_6 * i6;
let t6_0 = t2_0 + a2_0_6 * t6_6;
let t6_1 = t2_1 + a2_1_6 * t6_6;
let t6_2 = t2_2 + a2_2_6 * t6_6;
let t6_3 = t2_3 + a2_3_6 * t6_6;
let t6_4 = t2_4 + a2_4_6 * t6_6;
let t6_5 = t2_5 + a2_5_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_2)), abs(t6_6));
let zs = (((Scalar(0.0) + abs(t6_0)) + abs(t6_2)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 5u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a2_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l2 & !dead5 & !(a2_5_5 > tol.tree_pivot * m5_5));
let l5 = l2 & !dead5;
let i5 = Scalar(1.0) / a2_5_5;
let n5 = -i5;
let a5_5_6 = a2_5_6 * n5;
let t5_5 = -t2_5 * i5;
let a5_0_6 = a2_0_6 + a2_0_5 * a5_5_6;
let t5_0 = t2_0 + a2_0_5 * t5_5;
let a5_1_6 = a2_1_6 + a2_1_5 * a5_5_6;
let t5_1 = t2_1 + a2_1_5 * t5_5;
let a5_2_6 = a2_2_6 + a2_2_5 * a5_5_6;
let t5_2 = t2_2 + a2_2_5 * t5_5;
let a5_3_6 = a2_3_6 + a2_3_5 * a5_5_6;
let t5_3 = t2_3 + a2_3_5 * t5_5;
let a5_4_6 = a2_4_6 + a2_4_5 * a5_5_6;
let t5_4 = t2_4 + a2_4_5 * t5_5;
let a5_6_6 = a2_6_6 + a2_6_5 * a5_5_6;
let t5_6 = t2_6 + a2_6_5 * t5_5;
{
let zm = max(max(max(Scalar(0.0), abs(t5_0)), abs(t5_2)), abs(t5_5));
let zs = (((Scalar(0.0) + abs(t5_0)) + abs(t5_2)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 5u), l5 & (t5_0 >= -tol.screen * zm) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_2)), abs(t6_5)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_0)) + abs(t6_2)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 5u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t4_4 = -t2_4 * i4;
let a4_0_5 = a2_0_5 + a2_0_4 * a4_4_5;
let a4_0_6 = a2_0_6 + a2_0_4 * a4_4_6;
let t4_0 = t2_0 + a2_0_4 * t4_4;
let a4_1_5 = a2_1_5 + a2_1_4 * a4_4_5;
let a4_1_6 = a2_1_6 + a2_1_4 * a4_4_6;
let t4_1 = t2_1 + a2_1_4 * t4_4;
let a4_2_5 = a2_2_5 + a2_2_4 * a4_4_5;
let a4_2_6 = a2_2_6 + a2_2_4 * a4_4_6;
let t4_2 = t2_2 + a2_2_4 * t4_4;
let a4_3_5 = a2_3_5 + a2_3_4 * a4_4_5;
let a4_3_6 = a2_3_6 + a2_3_4 * a4_4_6;
let t4_3 = t2_3 + a2_3_4 * t4_4;
let a4_5_5 = a2_5_5 + a2_5_4 * a4_4_5;
let a4_5_6 = a2_5_6 + a2_5_4 * a4_4_6;
let t4_5 = t2_5 + a2_5_4 * t4_4;
let a4_6_5 = a2_6_5 + a2_6_4 * a4_4_5;
let a4_6_6 = a2_6_6 + a2_6_4 * a4_4_6;
let t4_6 = t2_6 + a2_6_4 * t4_4;
{
let zm = max(max(max(Scalar(0.0), abs(t4_0)), abs(t4_2)), abs(t4_4));
let zs = (((Scalar(0.0) + abs(t4_0)) + abs(t4_2)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 21u), l4 & (t4_0 >= -tol.screen * zm) & (t4_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t4_2 >= -tol.screen * zm) & (t4_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let t6_6 = -t4_6 * i6;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let t6_5 = t4_5 + a4_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_2)), abs(t6_4)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_0)) + abs(t6_2)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 21u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let t5_6 = t4_6 + a4_6_5 * t5_5;
{
let zm = max(max(max(max(Scalar(0.0), abs(t5_0)), abs(t5_2)), abs(t5_4)), abs(t5_5));
let zs = ((((Scalar(0.0) + abs(t5_0)) + abs(t5_2)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 21u), l5 & (t5_0 >= -tol.screen * zm) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_2)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = (((((Scalar(0.0) + abs(t6_0)) + abs(t6_2)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 21u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t3_3 = -t2_3 * i3;
let a3_0_4 = a2_0_4 + a2_0_3 * a3_3_4;
let a3_0_5 = a2_0_5 + a2_0_3 * a3_3_5;
let a3_0_6 = a2_0_6 + a2_0_3 * a3_3_6;
let t3_0 = t2_0 + a2_0_3 * t3_3;
let a3_1_4 = a2_1_4 + a2_1_3 * a3_3_4;
let a3_1_5 = a2_1_5 + a2_1_3 * a3_3_5;
let a3_1_6 = a2_1_6 + a2_1_3 * a3_3_6;
let t3_1 = t2_1 + a2_1_3 * t3_3;
let a3_2_4 = a2_2_4 + a2_2_3 * a3_3_4;
let a3_2_5 = a2_2_5 + a2_2_3 * a3_3_5;
let a3_2_6 = a2_2_6 + a2_2_3 * a3_3_6;
let t3_2 = t2_2 + a2_2_3 * t3_3;
let a3_4_4 = a2_4_4 + a2_4_3 * a3_3_4;
let a3_4_5 = a2_4_5 + a2_4_3 * a3_3_5;
let a3_4_6 = a2_4_6 + a2_4_3 * a3_3_6;
let t3_4 = t2_4 + a2_4_3 * t3_3;
let a3_5_4 = a2_5_4 + a2_5_3 * a3_3_4;
let a3_5_5 = a2_5_5 + a2_5_3 * a3_3_5;
let a3_5_6 = a2_5_6 + a2_5_3 * a3_3_6;
let t3_5 = t2_5 + a2_5_3 * t3_3;
let a3_6_4 = a2_6_4 + a2_6_3 * a3_3_4;
let a3_6_5 = a2_6_5 + a2_6_3 * a3_3_5;
let a3_6_6 = a2_6_6 + a2_6_3 * a3_3_6;
let t3_6 = t2_6 + a2_6_3 * t3_3;
{
let zm = max(max(max(Scalar(0.0), abs(t3_0)), abs(t3_2)), abs(t3_3));
let zs = (((Scalar(0.0) + abs(t3_0)) + abs(t3_2)) + abs(t3_3));
c0 = c0 | select(0u, 1u << (pre | 13u), l3 & (t3_0 >= -tol.screen * zm) & (t3_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t3_2 >= -tol.screen * zm) & (t3_3 >= -tol.screen * zm) & (t3_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t3_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t3_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a3_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l3 & !dead6 & !(a3_6_6 > tol.tree_pivot * m6_6));
let l6 = l3 & !dead6;
let i6 = Scalar(1.0) / a3_6_6;
let n6 = -i6;
let t6_6 = -t3_6 * i6;
let t6_0 = t3_0 + a3_0_6 * t6_6;
let t6_1 = t3_1 + a3_1_6 * t6_6;
let t6_2 = t3_2 + a3_2_6 * t6_6;
let t6_3 = t3_3 + a3_3_6 * t6_6;
let t6_4 = t3_4 + a3_4_6 * t6_6;
let t6_5 = t3_5 + a3_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_2)), abs(t6_3)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_0)) + abs(t6_2)) + abs(t6_3)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 13u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a3_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l3 & !dead5 & !(a3_5_5 > tol.tree_pivot * m5_5));
let l5 = l3 & !dead5;
let i5 = Scalar(1.0) / a3_5_5;
let n5 = -i5;
let a5_5_6 = a3_5_6 * n5;
let t5_5 = -t3_5 * i5;
let a5_0_6 = a3_0_6 + a3_0_5 * a5_5_6;
let t5_0 = t3_0 + a3_0_5 * t5_5;
let a5_1_6 = a3_1_6 + a3_1_5 * a5_5_6;
let t5_1 = t3_1 + a3_1_5 * t5_5;
let a5_2_6 = a3_2_6 + a3_2_5 * a5_5_6;
let t5_2 = t3_2 + a3_2_5 * t5_5;
let a5_3_6 = a3_3_6 + a3_3_5 * a5_5_6;
let t5_3 = t3_3 + a3_3_5 * t5_5;
let a5_4_6 = a3_4_6 + a3_4_5 * a5_5_6;
let t5_4 = t3_4 + a3_4_5 * t5_5;
let a5_6_6 = a3_6_6 + a3_6_5 * a5_5_6;
let t5_6 = t3_6 + a3_6_5 * t5_5;
{
let zm = max(max(max(max(Scalar(0.0), abs(t5_0)), abs(t5_2)), abs(t5_3)), abs(t5_5));
let zs = ((((Scalar(0.0) + abs(t5_0)) + abs(t5_2)) + abs(t5_3)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 13u), l5 & (t5_0 >= -tol.screen * zm) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_2)), abs(t6_3)), abs(t6_5)), abs(t6_6));
let zs = (((((Scalar(0.0) + abs(t6_0)) + abs(t6_2)) + abs(t6_3)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 13u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t4_4 = -t3_4 * i4;
let a4_0_5 = a3_0_5 + a3_0_4 * a4_4_5;
let a4_0_6 = a3_0_6 + a3_0_4 * a4_4_6;
let t4_0 = t3_0 + a3_0_4 * t4_4;
let a4_1_5 = a3_1_5 + a3_1_4 * a4_4_5;
let a4_1_6 = a3_1_6 + a3_1_4 * a4_4_6;
let t4_1 = t3_1 + a3_1_4 * t4_4;
let a4_2_5 = a3_2_5 + a3_2_4 * a4_4_5;
let a4_2_6 = a3_2_6 + a3_2_4 * a4_4_6;
let t4_2 = t3_2 + a3_2_4 * t4_4;
let a4_3_5 = a3_3_5 + a3_3_4 * a4_4_5;
let a4_3_6 = a3_3_6 + a3_3_4 * a4_4_6;
let t4_3 = t3_3 + a3_3_4 * t4_4;
let a4_5_5 = a3_5_5 + a3_5_4 * a4_4_5;
let a4_5_6 = a3_5_6 + a3_5_4 * a4_4_6;
let t4_5 = t3_5 + a3_5_4 * t4_4;
let a4_6_5 = a3_6_5 + a3_6_4 * a4_4_5;
let a4_6_6 = a3_6_6 + a3_6_4 * a4_4_6;
let t4_6 = t3_6 + a3_6_4 * t4_4;
{
let zm = max(max(max(max(Scalar(0.0), abs(t4_0)), abs(t4_2)), abs(t4_3)), abs(t4_4));
let zs = ((((Scalar(0.0) + abs(t4_0)) + abs(t4_2)) + abs(t4_3)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 29u), l4 & (t4_0 >= -tol.screen * zm) & (t4_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t4_2 >= -tol.screen * zm) & (t4_3 >= -tol.screen * zm) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let t6_6 = -t4_6 * i6;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let t6_5 = t4_5 + a4_5_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_2)), abs(t6_3)), abs(t6_4)), abs(t6_6));
let zs = (((((Scalar(0.0) + abs(t6_0)) + abs(t6_2)) + abs(t6_3)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 29u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let t5_6 = t4_6 + a4_6_5 * t5_5;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t5_0)), abs(t5_2)), abs(t5_3)), abs(t5_4)), abs(t5_5));
let zs = (((((Scalar(0.0) + abs(t5_0)) + abs(t5_2)) + abs(t5_3)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 29u), l5 & (t5_0 >= -tol.screen * zm) & (t5_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_2)), abs(t6_3)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = ((((((Scalar(0.0) + abs(t6_0)) + abs(t6_2)) + abs(t6_3)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 29u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * (qa1 + rm1 * zs)) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
}
}
}
}
}
}
{
let dead1 = semi & !(a0_1_1 > tol.tree_singular * m1_1);
ok = ok & !(l0 & !dead1 & !(a0_1_1 > tol.tree_pivot * m1_1));
let l1 = l0 & !dead1;
let i1 = Scalar(1.0) / a0_1_1;
let n1 = -i1;
let a1_1_2 = a0_1_2 * n1;
let a1_1_3 = a0_1_3 * n1;
let a1_1_4 = a0_1_4 * n1;
let a1_1_5 = a0_1_5 * n1;
let a1_1_6 = a0_1_6 * n1;
let t1_1 = -t0_1 * i1;
let a1_0_2 = a0_0_2 + a0_0_1 * a1_1_2;
let a1_0_3 = a0_0_3 + a0_0_1 * a1_1_3;
let a1_0_4 = a0_0_4 + a0_0_1 * a1_1_4;
let a1_0_5 = a0_0_5 + a0_0_1 * a1_1_5;
let a1_0_6 = a0_0_6 + a0_0_1 * a1_1_6;
let t1_0 = t0_0 + a0_0_1 * t1_1;
let a1_2_2 = a0_2_2 + a0_2_1 * a1_1_2;
let a1_2_3 = a0_2_3 + a0_2_1 * a1_1_3;
let a1_2_4 = a0_2_4 + a0_2_1 * a1_1_4;
let a1_2_5 = a0_2_5 + a0_2_1 * a1_1_5;
let a1_2_6 = a0_2_6 + a0_2_1 * a1_1_6;
let t1_2 = t0_2 + a0_2_1 * t1_1;
let a1_3_2 = a0_3_2 + a0_3_1 * a1_1_2;
let a1_3_3 = a0_3_3 + a0_3_1 * a1_1_3;
let a1_3_4 = a0_3_4 + a0_3_1 * a1_1_4;
let a1_3_5 = a0_3_5 + a0_3_1 * a1_1_5;
let a1_3_6 = a0_3_6 + a0_3_1 * a1_1_6;
let t1_3 = t0_3 + a0_3_1 * t1_1;
let a1_4_2 = a0_4_2 + a0_4_1 * a1_1_2;
let a1_4_3 = a0_4_3 + a0_4_1 * a1_1_3;
let a1_4_4 = a0_4_4 + a0_4_1 * a1_1_4;
let a1_4_5 = a0_4_5 + a0_4_1 * a1_1_5;
let a1_4_6 = a0_4_6 + a0_4_1 * a1_1_6;
let t1_4 = t0_4 + a0_4_1 * t1_1;
let a1_5_2 = a0_5_2 + a0_5_1 * a1_1_2;
let a1_5_3 = a0_5_3 + a0_5_1 * a1_1_3;
let a1_5_4 = a0_5_4 + a0_5_1 * a1_1_4;
let a1_5_5 = a0_5_5 + a0_5_1 * a1_1_5;
let a1_5_6 = a0_5_6 + a0_5_1 * a1_1_6;
let t1_5 = t0_5 + a0_5_1 * t1_1;
let a1_6_2 = a0_6_2 + a0_6_1 * a1_1_2;
let a1_6_3 = a0_6_3 + a0_6_1 * a1_1_3;
let a1_6_4 = a0_6_4 + a0_6_1 * a1_1_4;
let a1_6_5 = a0_6_5 + a0_6_1 * a1_1_5;
let a1_6_6 = a0_6_6 + a0_6_1 * a1_1_6;
let t1_6 = t0_6 + a0_6_1 * t1_1;
{
let zm = max(max(Scalar(0.0), abs(t1_0)), abs(t1_1));
let zs = ((Scalar(0.0) + abs(t1_0)) + abs(t1_1));
c0 = c0 | select(0u, 1u << (pre | 3u), l1 & (t1_0 >= -tol.screen * zm) & (t1_1 >= -tol.screen * zm) & (t1_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t1_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t1_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t1_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t1_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a1_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l1 & !dead6 & !(a1_6_6 > tol.tree_pivot * m6_6));
let l6 = l1 & !dead6;
let i6 = Scalar(1.0) / a1_6_6;
let n6 = -i6;
let t6_6 = -t1_6 * i6;
let t6_0 = t1_0 + a1_0_6 * t6_6;
let t6_1 = t1_1 + a1_1_6 * t6_6;
let t6_2 = t1_2 + a1_2_6 * t6_6;
let t6_3 = t1_3 + a1_3_6 * t6_6;
let t6_4 = t1_4 + a1_4_6 * t6_6;
let t6_5 = t1_5 + a1_5_6 * t6_6;
{
let zm = max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_1)), abs(t6_6));
let zs = (((Scalar(0.0) + abs(t6_0)) + abs(t6_1)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 3u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a1_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l1 & !dead5 & !(a1_5_5 > tol.tree_pivot * m5_5));
let l5 = l1 & !dead5;
let i5 = Scalar(1.0) / a1_5_5;
let n5 = -i5;
let a5_5_6 = a1_5_6 * n5;
let t5_5 = -t1_5 * i5;
let a5_0_6 = a1_0_6 + a1_0_5 * a5_5_6;
let t5_0 = t1_0 + a1_0_5 * t5_5;
let a5_1_6 = a1_1_6 + a1_1_5 * a5_5_6;
let t5_1 = t1_1 + a1_1_5 * t5_5;
let a5_2_6 = a1_2_6 + a1_2_5 * a5_5_6;
let t5_2 = t1_2 + a1_2_5 * t5_5;
let a5_3_6 = a1_3_6 + a1_3_5 * a5_5_6;
let t5_3 = t1_3 + a1_3_5 * t5_5;
let a5_4_6 = a1_4_6 + a1_4_5 * a5_5_6;
let t5_4 = t1_4 + a1_4_5 * t5_5;
let a5_6_6 = a1_6_6 + a1_6_5 * a5_5_6;
let t5_6 = t1_6 + a1_6_5 * t5_5;
{
let zm = max(max(max(Scalar(0.0), abs(t5_0)), abs(t5_1)), abs(t5_5));
let zs = (((Scalar(0.0) + abs(t5_0)) + abs(t5_1)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 3u), l5 & (t5_0 >= -tol.screen * zm) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_1)), abs(t6_5)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_0)) + abs(t6_1)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 3u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t4_4 = -t1_4 * i4;
let a4_0_5 = a1_0_5 + a1_0_4 * a4_4_5;
let a4_0_6 = a1_0_6 + a1_0_4 * a4_4_6;
let t4_0 = t1_0 + a1_0_4 * t4_4;
let a4_1_5 = a1_1_5 + a1_1_4 * a4_4_5;
let a4_1_6 = a1_1_6 + a1_1_4 * a4_4_6;
let t4_1 = t1_1 + a1_1_4 * t4_4;
let a4_2_5 = a1_2_5 + a1_2_4 * a4_4_5;
let a4_2_6 = a1_2_6 + a1_2_4 * a4_4_6;
let t4_2 = t1_2 + a1_2_4 * t4_4;
let a4_3_5 = a1_3_5 + a1_3_4 * a4_4_5;
let a4_3_6 = a1_3_6 + a1_3_4 * a4_4_6;
let t4_3 = t1_3 + a1_3_4 * t4_4;
let a4_5_5 = a1_5_5 + a1_5_4 * a4_4_5;
let a4_5_6 = a1_5_6 + a1_5_4 * a4_4_6;
let t4_5 = t1_5 + a1_5_4 * t4_4;
let a4_6_5 = a1_6_5 + a1_6_4 * a4_4_5;
let a4_6_6 = a1_6_6 + a1_6_4 * a4_4_6;
let t4_6 = t1_6 + a1_6_4 * t4_4;
{
let zm = max(max(max(Scalar(0.0), abs(t4_0)), abs(t4_1)), abs(t4_4));
let zs = (((Scalar(0.0) + abs(t4_0)) + abs(t4_1)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 19u), l4 & (t4_0 >= -tol.screen * zm) & (t4_1 >= -tol.screen * zm) & (t4_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t4_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let t6_6 = -t4_6 * i6;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let t6_5 = t4_5 + a4_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_1)), abs(t6_4)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_0)) + abs(t6_1)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 19u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let t5_6 = t4_6 + a4_6_5 * t5_5;
{
let zm = max(max(max(max(Scalar(0.0), abs(t5_0)), abs(t5_1)), abs(t5_4)), abs(t5_5));
let zs = ((((Scalar(0.0) + abs(t5_0)) + abs(t5_1)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 19u), l5 & (t5_0 >= -tol.screen * zm) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_1)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = (((((Scalar(0.0) + abs(t6_0)) + abs(t6_1)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 19u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t3_3 = -t1_3 * i3;
let a3_0_4 = a1_0_4 + a1_0_3 * a3_3_4;
let a3_0_5 = a1_0_5 + a1_0_3 * a3_3_5;
let a3_0_6 = a1_0_6 + a1_0_3 * a3_3_6;
let t3_0 = t1_0 + a1_0_3 * t3_3;
let a3_1_4 = a1_1_4 + a1_1_3 * a3_3_4;
let a3_1_5 = a1_1_5 + a1_1_3 * a3_3_5;
let a3_1_6 = a1_1_6 + a1_1_3 * a3_3_6;
let t3_1 = t1_1 + a1_1_3 * t3_3;
let a3_2_4 = a1_2_4 + a1_2_3 * a3_3_4;
let a3_2_5 = a1_2_5 + a1_2_3 * a3_3_5;
let a3_2_6 = a1_2_6 + a1_2_3 * a3_3_6;
let t3_2 = t1_2 + a1_2_3 * t3_3;
let a3_4_4 = a1_4_4 + a1_4_3 * a3_3_4;
let a3_4_5 = a1_4_5 + a1_4_3 * a3_3_5;
let a3_4_6 = a1_4_6 + a1_4_3 * a3_3_6;
let t3_4 = t1_4 + a1_4_3 * t3_3;
let a3_5_4 = a1_5_4 + a1_5_3 * a3_3_4;
let a3_5_5 = a1_5_5 + a1_5_3 * a3_3_5;
let a3_5_6 = a1_5_6 + a1_5_3 * a3_3_6;
let t3_5 = t1_5 + a1_5_3 * t3_3;
let a3_6_4 = a1_6_4 + a1_6_3 * a3_3_4;
let a3_6_5 = a1_6_5 + a1_6_3 * a3_3_5;
let a3_6_6 = a1_6_6 + a1_6_3 * a3_3_6;
let t3_6 = t1_6 + a1_6_3 * t3_3;
{
let zm = max(max(max(Scalar(0.0), abs(t3_0)), abs(t3_1)), abs(t3_3));
let zs = (((Scalar(0.0) + abs(t3_0)) + abs(t3_1)) + abs(t3_3));
c0 = c0 | select(0u, 1u << (pre | 11u), l3 & (t3_0 >= -tol.screen * zm) & (t3_1 >= -tol.screen * zm) & (t3_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t3_3 >= -tol.screen * zm) & (t3_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t3_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t3_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a3_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l3 & !dead6 & !(a3_6_6 > tol.tree_pivot * m6_6));
let l6 = l3 & !dead6;
let i6 = Scalar(1.0) / a3_6_6;
let n6 = -i6;
let t6_6 = -t3_6 * i6;
let t6_0 = t3_0 + a3_0_6 * t6_6;
let t6_1 = t3_1 + a3_1_6 * t6_6;
let t6_2 = t3_2 + a3_2_6 * t6_6;
let t6_3 = t3_3 + a3_3_6 * t6_6;
let t6_4 = t3_4 + a3_4_6 * t6_6;
let t6_5 = t3_5 + a3_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_1)), abs(t6_3)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_0)) + abs(t6_1)) + abs(t6_3)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 11u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a3_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l3 & !dead5 & !(a3_5_5 > tol.tree_pivot * m5_5));
let l5 = l3 & !dead5;
let i5 = Scalar(1.0) / a3_5_5;
let n5 = -i5;
let a5_5_6 = a3_5_6 * n5;
let t5_5 = -t3_5 * i5;
let a5_0_6 = a3_0_6 + a3_0_5 * a5_5_6;
let t5_0 = t3_0 + a3_0_5 * t5_5;
let a5_1_6 = a3_1_6 + a3_1_5 * a5_5_6;
let t5_1 = t3_1 + a3_1_5 * t5_5;
let a5_2_6 = a3_2_6 + a3_2_5 * a5_5_6;
let t5_2 = t3_2 + a3_2_5 * t5_5;
let a5_3_6 = a3_3_6 + a3_3_5 * a5_5_6;
let t5_3 = t3_3 + a3_3_5 * t5_5;
let a5_4_6 = a3_4_6 + a3_4_5 * a5_5_6;
let t5_4 = t3_4 + a3_4_5 * t5_5;
let a5_6_6 = a3_6_6 + a3_6_5 * a5_5_6;
let t5_6 = t3_6 + a3_6_5 * t5_5;
{
let zm = max(max(max(max(Scalar(0.0), abs(t5_0)), abs(t5_1)), abs(t5_3)), abs(t5_5));
let zs = ((((Scalar(0.0) + abs(t5_0)) + abs(t5_1)) + abs(t5_3)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 11u), l5 & (t5_0 >= -tol.screen * zm) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_1)), abs(t6_3)), abs(t6_5)), abs(t6_6));
let zs = (((((Scalar(0.0) + abs(t6_0)) + abs(t6_1)) + abs(t6_3)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 11u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t4_4 = -t3_4 * i4;
let a4_0_5 = a3_0_5 + a3_0_4 * a4_4_5;
let a4_0_6 = a3_0_6 + a3_0_4 * a4_4_6;
let t4_0 = t3_0 + a3_0_4 * t4_4;
let a4_1_5 = a3_1_5 + a3_1_4 * a4_4_5;
let a4_1_6 = a3_1_6 + a3_1_4 * a4_4_6;
let t4_1 = t3_1 + a3_1_4 * t4_4;
let a4_2_5 = a3_2_5 + a3_2_4 * a4_4_5;
let a4_2_6 = a3_2_6 + a3_2_4 * a4_4_6;
let t4_2 = t3_2 + a3_2_4 * t4_4;
let a4_3_5 = a3_3_5 + a3_3_4 * a4_4_5;
let a4_3_6 = a3_3_6 + a3_3_4 * a4_4_6;
let t4_3 = t3_3 + a3_3_4 * t4_4;
let a4_5_5 = a3_5_5 + a3_5_4 * a4_4_5;
let a4_5_6 = a3_5_6 + a3_5_4 * a4_4_6;
let t4_5 = t3_5 + a3_5_4 * t4_4;
let a4_6_5 = a3_6_5 + a3_6_4 * a4_4_5;
let a4_6_6 = a3_6_6 + a3_6_4 * a4_4_6;
let t4_6 = t3_6 + a3_6_4 * t4_4;
{
let zm = max(max(max(max(Scalar(0.0), abs(t4_0)), abs(t4_1)), abs(t4_3)), abs(t4_4));
let zs = ((((Scalar(0.0) + abs(t4_0)) + abs(t4_1)) + abs(t4_3)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 27u), l4 & (t4_0 >= -tol.screen * zm) & (t4_1 >= -tol.screen * zm) & (t4_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t4_3 >= -tol.screen * zm) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let t6_6 = -t4_6 * i6;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let t6_5 = t4_5 + a4_5_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_1)), abs(t6_3)), abs(t6_4)), abs(t6_6));
let zs = (((((Scalar(0.0) + abs(t6_0)) + abs(t6_1)) + abs(t6_3)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 27u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let t5_6 = t4_6 + a4_6_5 * t5_5;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t5_0)), abs(t5_1)), abs(t5_3)), abs(t5_4)), abs(t5_5));
let zs = (((((Scalar(0.0) + abs(t5_0)) + abs(t5_1)) + abs(t5_3)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 27u), l5 & (t5_0 >= -tol.screen * zm) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_1)), abs(t6_3)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = ((((((Scalar(0.0) + abs(t6_0)) + abs(t6_1)) + abs(t6_3)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 27u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * (qa2 + rm2 * zs)) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t2_2 = -t1_2 * i2;
let a2_0_3 = a1_0_3 + a1_0_2 * a2_2_3;
let a2_0_4 = a1_0_4 + a1_0_2 * a2_2_4;
let a2_0_5 = a1_0_5 + a1_0_2 * a2_2_5;
let a2_0_6 = a1_0_6 + a1_0_2 * a2_2_6;
let t2_0 = t1_0 + a1_0_2 * t2_2;
let a2_1_3 = a1_1_3 + a1_1_2 * a2_2_3;
let a2_1_4 = a1_1_4 + a1_1_2 * a2_2_4;
let a2_1_5 = a1_1_5 + a1_1_2 * a2_2_5;
let a2_1_6 = a1_1_6 + a1_1_2 * a2_2_6;
let t2_1 = t1_1 + a1_1_2 * t2_2;
let a2_3_3 = a1_3_3 + a1_3_2 * a2_2_3;
let a2_3_4 = a1_3_4 + a1_3_2 * a2_2_4;
let a2_3_5 = a1_3_5 + a1_3_2 * a2_2_5;
let a2_3_6 = a1_3_6 + a1_3_2 * a2_2_6;
let t2_3 = t1_3 + a1_3_2 * t2_2;
let a2_4_3 = a1_4_3 + a1_4_2 * a2_2_3;
let a2_4_4 = a1_4_4 + a1_4_2 * a2_2_4;
let a2_4_5 = a1_4_5 + a1_4_2 * a2_2_5;
let a2_4_6 = a1_4_6 + a1_4_2 * a2_2_6;
let t2_4 = t1_4 + a1_4_2 * t2_2;
let a2_5_3 = a1_5_3 + a1_5_2 * a2_2_3;
let a2_5_4 = a1_5_4 + a1_5_2 * a2_2_4;
let a2_5_5 = a1_5_5 + a1_5_2 * a2_2_5;
let a2_5_6 = a1_5_6 + a1_5_2 * a2_2_6;
let t2_5 = t1_5 + a1_5_2 * t2_2;
let a2_6_3 = a1_6_3 + a1_6_2 * a2_2_3;
let a2_6_4 = a1_6_4 + a1_6_2 * a2_2_4;
let a2_6_5 = a1_6_5 + a1_6_2 * a2_2_5;
let a2_6_6 = a1_6_6 + a1_6_2 * a2_2_6;
let t2_6 = t1_6 + a1_6_2 * t2_2;
{
let zm = max(max(max(Scalar(0.0), abs(t2_0)), abs(t2_1)), abs(t2_2));
let zs = (((Scalar(0.0) + abs(t2_0)) + abs(t2_1)) + abs(t2_2));
c0 = c0 | select(0u, 1u << (pre | 7u), l2 & (t2_0 >= -tol.screen * zm) & (t2_1 >= -tol.screen * zm) & (t2_2 >= -tol.screen * zm) & (t2_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t2_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t2_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t2_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a2_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l2 & !dead6 & !(a2_6_6 > tol.tree_pivot * m6_6));
let l6 = l2 & !dead6;
let i6 = Scalar(1.0) / a2_6_6;
let n6 = -i6;
let t6_6 = -t2_6 * i6;
let t6_0 = t2_0 + a2_0_6 * t6_6;
let t6_1 = t2_1 + a2_1_6 * t6_6;
let t6_2 = t2_2 + a2_2_6 * t6_6;
let t6_3 = t2_3 + a2_3_6 * t6_6;
let t6_4 = t2_4 + a2_4_6 * t6_6;
let t6_5 = t2_5 + a2_5_6 * t6_6;
{
let zm = max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_1)), abs(t6_2)), abs(t6_6));
let zs = ((((Scalar(0.0) + abs(t6_0)) + abs(t6_1)) + abs(t6_2)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 7u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a2_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l2 & !dead5 & !(a2_5_5 > tol.tree_pivot * m5_5));
let l5 = l2 & !dead5;
let i5 = Scalar(1.0) / a2_5_5;
let n5 = -i5;
let a5_5_6 = a2_5_6 * n5;
let t5_5 = -t2_5 * i5;
let a5_0_6 = a2_0_6 + a2_0_5 * a5_5_6;
let t5_0 = t2_0 + a2_0_5 * t5_5;
let a5_1_6 = a2_1_6 + a2_1_5 * a5_5_6;
let t5_1 = t2_1 + a2_1_5 * t5_5;
let a5_2_6 = a2_2_6 + a2_2_5 * a5_5_6;
let t5_2 = t2_2 + a2_2_5 * t5_5;
let a5_3_6 = a2_3_6 + a2_3_5 * a5_5_6;
let t5_3 = t2_3 + a2_3_5 * t5_5;
let a5_4_6 = a2_4_6 + a2_4_5 * a5_5_6;
let t5_4 = t2_4 + a2_4_5 * t5_5;
let a5_6_6 = a2_6_6 + a2_6_5 * a5_5_6;
let t5_6 = t2_6 + a2_6_5 * t5_5;
{
let zm = max(max(max(max(Scalar(0.0), abs(t5_0)), abs(t5_1)), abs(t5_2)), abs(t5_5));
let zs = ((((Scalar(0.0) + abs(t5_0)) + abs(t5_1)) + abs(t5_2)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 7u), l5 & (t5_0 >= -tol.screen * zm) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_1)), abs(t6_2)), abs(t6_5)), abs(t6_6));
let zs = (((((Scalar(0.0) + abs(t6_0)) + abs(t6_1)) + abs(t6_2)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 7u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t4_4 = -t2_4 * i4;
let a4_0_5 = a2_0_5 + a2_0_4 * a4_4_5;
let a4_0_6 = a2_0_6 + a2_0_4 * a4_4_6;
let t4_0 = t2_0 + a2_0_4 * t4_4;
let a4_1_5 = a2_1_5 + a2_1_4 * a4_4_5;
let a4_1_6 = a2_1_6 + a2_1_4 * a4_4_6;
let t4_1 = t2_1 + a2_1_4 * t4_4;
let a4_2_5 = a2_2_5 + a2_2_4 * a4_4_5;
let a4_2_6 = a2_2_6 + a2_2_4 * a4_4_6;
let t4_2 = t2_2 + a2_2_4 * t4_4;
let a4_3_5 = a2_3_5 + a2_3_4 * a4_4_5;
let a4_3_6 = a2_3_6 + a2_3_4 * a4_4_6;
let t4_3 = t2_3 + a2_3_4 * t4_4;
let a4_5_5 = a2_5_5 + a2_5_4 * a4_4_5;
let a4_5_6 = a2_5_6 + a2_5_4 * a4_4_6;
let t4_5 = t2_5 + a2_5_4 * t4_4;
let a4_6_5 = a2_6_5 + a2_6_4 * a4_4_5;
let a4_6_6 = a2_6_6 + a2_6_4 * a4_4_6;
let t4_6 = t2_6 + a2_6_4 * t4_4;
{
let zm = max(max(max(max(Scalar(0.0), abs(t4_0)), abs(t4_1)), abs(t4_2)), abs(t4_4));
let zs = ((((Scalar(0.0) + abs(t4_0)) + abs(t4_1)) + abs(t4_2)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 23u), l4 & (t4_0 >= -tol.screen * zm) & (t4_1 >= -tol.screen * zm) & (t4_2 >= -tol.screen * zm) & (t4_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let t6_6 = -t4_6 * i6;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let t6_5 = t4_5 + a4_5_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_1)), abs(t6_2)), abs(t6_4)), abs(t6_6));
let zs = (((((Scalar(0.0) + abs(t6_0)) + abs(t6_1)) + abs(t6_2)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 23u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let t5_6 = t4_6 + a4_6_5 * t5_5;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t5_0)), abs(t5_1)), abs(t5_2)), abs(t5_4)), abs(t5_5));
let zs = (((((Scalar(0.0) + abs(t5_0)) + abs(t5_1)) + abs(t5_2)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 23u), l5 & (t5_0 >= -tol.screen * zm) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_1)), abs(t6_2)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = ((((((Scalar(0.0) + abs(t6_0)) + abs(t6_1)) + abs(t6_2)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 23u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * (qa3 + rm3 * zs)) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t3_3 = -t2_3 * i3;
let a3_0_4 = a2_0_4 + a2_0_3 * a3_3_4;
let a3_0_5 = a2_0_5 + a2_0_3 * a3_3_5;
let a3_0_6 = a2_0_6 + a2_0_3 * a3_3_6;
let t3_0 = t2_0 + a2_0_3 * t3_3;
let a3_1_4 = a2_1_4 + a2_1_3 * a3_3_4;
let a3_1_5 = a2_1_5 + a2_1_3 * a3_3_5;
let a3_1_6 = a2_1_6 + a2_1_3 * a3_3_6;
let t3_1 = t2_1 + a2_1_3 * t3_3;
let a3_2_4 = a2_2_4 + a2_2_3 * a3_3_4;
let a3_2_5 = a2_2_5 + a2_2_3 * a3_3_5;
let a3_2_6 = a2_2_6 + a2_2_3 * a3_3_6;
let t3_2 = t2_2 + a2_2_3 * t3_3;
let a3_4_4 = a2_4_4 + a2_4_3 * a3_3_4;
let a3_4_5 = a2_4_5 + a2_4_3 * a3_3_5;
let a3_4_6 = a2_4_6 + a2_4_3 * a3_3_6;
let t3_4 = t2_4 + a2_4_3 * t3_3;
let a3_5_4 = a2_5_4 + a2_5_3 * a3_3_4;
let a3_5_5 = a2_5_5 + a2_5_3 * a3_3_5;
let a3_5_6 = a2_5_6 + a2_5_3 * a3_3_6;
let t3_5 = t2_5 + a2_5_3 * t3_3;
let a3_6_4 = a2_6_4 + a2_6_3 * a3_3_4;
let a3_6_5 = a2_6_5 + a2_6_3 * a3_3_5;
let a3_6_6 = a2_6_6 + a2_6_3 * a3_3_6;
let t3_6 = t2_6 + a2_6_3 * t3_3;
{
let zm = max(max(max(max(Scalar(0.0), abs(t3_0)), abs(t3_1)), abs(t3_2)), abs(t3_3));
let zs = ((((Scalar(0.0) + abs(t3_0)) + abs(t3_1)) + abs(t3_2)) + abs(t3_3));
c0 = c0 | select(0u, 1u << (pre | 15u), l3 & (t3_0 >= -tol.screen * zm) & (t3_1 >= -tol.screen * zm) & (t3_2 >= -tol.screen * zm) & (t3_3 >= -tol.screen * zm) & (t3_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t3_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t3_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a3_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l3 & !dead6 & !(a3_6_6 > tol.tree_pivot * m6_6));
let l6 = l3 & !dead6;
let i6 = Scalar(1.0) / a3_6_6;
let n6 = -i6;
let t6_6 = -t3_6 * i6;
let t6_0 = t3_0 + a3_0_6 * t6_6;
let t6_1 = t3_1 + a3_1_6 * t6_6;
let t6_2 = t3_2 + a3_2_6 * t6_6;
let t6_3 = t3_3 + a3_3_6 * t6_6;
let t6_4 = t3_4 + a3_4_6 * t6_6;
let t6_5 = t3_5 + a3_5_6 * t6_6;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_1)), abs(t6_2)), abs(t6_3)), abs(t6_6));
let zs = (((((Scalar(0.0) + abs(t6_0)) + abs(t6_1)) + abs(t6_2)) + abs(t6_3)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 15u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a3_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l3 & !dead5 & !(a3_5_5 > tol.tree_pivot * m5_5));
let l5 = l3 & !dead5;
let i5 = Scalar(1.0) / a3_5_5;
let n5 = -i5;
let a5_5_6 = a3_5_6 * n5;
let t5_5 = -t3_5 * i5;
let a5_0_6 = a3_0_6 + a3_0_5 * a5_5_6;
let t5_0 = t3_0 + a3_0_5 * t5_5;
let a5_1_6 = a3_1_6 + a3_1_5 * a5_5_6;
let t5_1 = t3_1 + a3_1_5 * t5_5;
let a5_2_6 = a3_2_6 + a3_2_5 * a5_5_6;
let t5_2 = t3_2 + a3_2_5 * t5_5;
let a5_3_6 = a3_3_6 + a3_3_5 * a5_5_6;
let t5_3 = t3_3 + a3_3_5 * t5_5;
let a5_4_6 = a3_4_6 + a3_4_5 * a5_5_6;
let t5_4 = t3_4 + a3_4_5 * t5_5;
let a5_6_6 = a3_6_6 + a3_6_5 * a5_5_6;
let t5_6 = t3_6 + a3_6_5 * t5_5;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t5_0)), abs(t5_1)), abs(t5_2)), abs(t5_3)), abs(t5_5));
let zs = (((((Scalar(0.0) + abs(t5_0)) + abs(t5_1)) + abs(t5_2)) + abs(t5_3)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 15u), l5 & (t5_0 >= -tol.screen * zm) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_1)), abs(t6_2)), abs(t6_3)), abs(t6_5)), abs(t6_6));
let zs = ((((((Scalar(0.0) + abs(t6_0)) + abs(t6_1)) + abs(t6_2)) + abs(t6_3)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 15u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * (qa4 + rm4 * zs)) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
let t4_4 = -t3_4 * i4;
let a4_0_5 = a3_0_5 + a3_0_4 * a4_4_5;
let a4_0_6 = a3_0_6 + a3_0_4 * a4_4_6;
let t4_0 = t3_0 + a3_0_4 * t4_4;
let a4_1_5 = a3_1_5 + a3_1_4 * a4_4_5;
let a4_1_6 = a3_1_6 + a3_1_4 * a4_4_6;
let t4_1 = t3_1 + a3_1_4 * t4_4;
let a4_2_5 = a3_2_5 + a3_2_4 * a4_4_5;
let a4_2_6 = a3_2_6 + a3_2_4 * a4_4_6;
let t4_2 = t3_2 + a3_2_4 * t4_4;
let a4_3_5 = a3_3_5 + a3_3_4 * a4_4_5;
let a4_3_6 = a3_3_6 + a3_3_4 * a4_4_6;
let t4_3 = t3_3 + a3_3_4 * t4_4;
let a4_5_5 = a3_5_5 + a3_5_4 * a4_4_5;
let a4_5_6 = a3_5_6 + a3_5_4 * a4_4_6;
let t4_5 = t3_5 + a3_5_4 * t4_4;
let a4_6_5 = a3_6_5 + a3_6_4 * a4_4_5;
let a4_6_6 = a3_6_6 + a3_6_4 * a4_4_6;
let t4_6 = t3_6 + a3_6_4 * t4_4;
{
let zm = max(max(max(max(max(Scalar(0.0), abs(t4_0)), abs(t4_1)), abs(t4_2)), abs(t4_3)), abs(t4_4));
let zs = (((((Scalar(0.0) + abs(t4_0)) + abs(t4_1)) + abs(t4_2)) + abs(t4_3)) + abs(t4_4));
c0 = c0 | select(0u, 1u << (pre | 31u), l4 & (t4_0 >= -tol.screen * zm) & (t4_1 >= -tol.screen * zm) & (t4_2 >= -tol.screen * zm) & (t4_3 >= -tol.screen * zm) & (t4_4 >= -tol.screen * zm) & (t4_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t4_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a4_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l4 & !dead6 & !(a4_6_6 > tol.tree_pivot * m6_6));
let l6 = l4 & !dead6;
let i6 = Scalar(1.0) / a4_6_6;
let n6 = -i6;
let t6_6 = -t4_6 * i6;
let t6_0 = t4_0 + a4_0_6 * t6_6;
let t6_1 = t4_1 + a4_1_6 * t6_6;
let t6_2 = t4_2 + a4_2_6 * t6_6;
let t6_3 = t4_3 + a4_3_6 * t6_6;
let t6_4 = t4_4 + a4_4_6 * t6_6;
let t6_5 = t4_5 + a4_5_6 * t6_6;
{
let zm = max(max(max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_1)), abs(t6_2)), abs(t6_3)), abs(t6_4)), abs(t6_6));
let zs = ((((((Scalar(0.0) + abs(t6_0)) + abs(t6_1)) + abs(t6_2)) + abs(t6_3)) + abs(t6_4)) + abs(t6_6));
c2 = c2 | select(0u, 1u << (pre | 31u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * (qa5 + rm5 * zs)) & (t6_6 >= -tol.screen * zm));
}
}
{
let dead5 = semi & !(a4_5_5 > tol.tree_singular * m5_5);
ok = ok & !(l4 & !dead5 & !(a4_5_5 > tol.tree_pivot * m5_5));
let l5 = l4 & !dead5;
let i5 = Scalar(1.0) / a4_5_5;
let n5 = -i5;
let a5_5_6 = a4_5_6 * n5;
let t5_5 = -t4_5 * i5;
let a5_0_6 = a4_0_6 + a4_0_5 * a5_5_6;
let t5_0 = t4_0 + a4_0_5 * t5_5;
let a5_1_6 = a4_1_6 + a4_1_5 * a5_5_6;
let t5_1 = t4_1 + a4_1_5 * t5_5;
let a5_2_6 = a4_2_6 + a4_2_5 * a5_5_6;
let t5_2 = t4_2 + a4_2_5 * t5_5;
let a5_3_6 = a4_3_6 + a4_3_5 * a5_5_6;
let t5_3 = t4_3 + a4_3_5 * t5_5;
let a5_4_6 = a4_4_6 + a4_4_5 * a5_5_6;
let t5_4 = t4_4 + a4_4_5 * t5_5;
let a5_6_6 = a4_6_6 + a4_6_5 * a5_5_6;
let t5_6 = t4_6 + a4_6_5 * t5_5;
{
let zm = max(max(max(max(max(max(Scalar(0.0), abs(t5_0)), abs(t5_1)), abs(t5_2)), abs(t5_3)), abs(t5_4)), abs(t5_5));
let zs = ((((((Scalar(0.0) + abs(t5_0)) + abs(t5_1)) + abs(t5_2)) + abs(t5_3)) + abs(t5_4)) + abs(t5_5));
c1 = c1 | select(0u, 1u << (pre | 31u), l5 & (t5_0 >= -tol.screen * zm) & (t5_1 >= -tol.screen * zm) & (t5_2 >= -tol.screen * zm) & (t5_3 >= -tol.screen * zm) & (t5_4 >= -tol.screen * zm) & (t5_5 >= -tol.screen * zm) & (t5_6 >= -tol.screen * (qa6 + rm6 * zs)));
}
{
let dead6 = semi & !(a5_6_6 > tol.tree_singular * m6_6);
ok = ok & !(l5 & !dead6 & !(a5_6_6 > tol.tree_pivot * m6_6));
let l6 = l5 & !dead6;
let i6 = Scalar(1.0) / a5_6_6;
let n6 = -i6;
let t6_6 = -t5_6 * i6;
let t6_0 = t5_0 + a5_0_6 * t6_6;
let t6_1 = t5_1 + a5_1_6 * t6_6;
let t6_2 = t5_2 + a5_2_6 * t6_6;
let t6_3 = t5_3 + a5_3_6 * t6_6;
let t6_4 = t5_4 + a5_4_6 * t6_6;
let t6_5 = t5_5 + a5_5_6 * t6_6;
{
let zm = max(max(max(max(max(max(max(Scalar(0.0), abs(t6_0)), abs(t6_1)), abs(t6_2)), abs(t6_3)), abs(t6_4)), abs(t6_5)), abs(t6_6));
let zs = (((((((Scalar(0.0) + abs(t6_0)) + abs(t6_1)) + abs(t6_2)) + abs(t6_3)) + abs(t6_4)) + abs(t6_5)) + abs(t6_6));
c3 = c3 | select(0u, 1u << (pre | 31u), l6 & (t6_0 >= -tol.screen * zm) & (t6_1 >= -tol.screen * zm) & (t6_2 >= -tol.screen * zm) & (t6_3 >= -tol.screen * zm) & (t6_4 >= -tol.screen * zm) & (t6_5 >= -tol.screen * zm) & (t6_6 >= -tol.screen * zm));
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
