// Enumeration of complementary bases: one invocation per island.
// CPU twin: src/cpu/enumeration.rs (same order, same tests, same tolerances
// in f64; the f32 build uses looser ones and the f64 polish decides).
//
// A basis is a u32 mask, bit i set when z_i is basic. Bases are visited by
// increasing popcount, each popcount by increasing mask (Gosper's hack), and
// the first valid one is chosen: the fewest contacts carrying impulse, ties to
// the smallest mask. For each basis S: solve M_SS z_S = -q_S by Gaussian
// elimination with partial pivoting (singular when a pivot is at most
// PIVOT_TOL times its column's largest entry of M_SS), then feasible when
// z_i >= -tol * max|z_S| and w_i = q_i + sum_j M_ij z_j >= -tol * (|q_i| + sum_j |M_ij z_j|).
//
// The host replaces the three lines marked HOST (scalar type, tolerances).

alias Scalar = f32; // HOST scalar
const PIVOT_TOL: Scalar = 1e-6; // HOST pivot_tol
const FEASIBILITY_TOL: Scalar = 1e-4; // HOST feasibility_tol

const MAX_N: u32 = 16u;

// One island: n contacts; M (n*n, row-major) then q (n) start at `data` in
// `values`; z is written at `z` in `z_out`.
struct Island {
    n: u32,
    data: u32,
    z: u32,
    _pad: u32,
}

// One dispatch covers islands first .. first + count of the island table
// (one dispatch per island size n, split to stay under 65,535 workgroups).
struct Params {
    first: u32,
    count: u32,
    _pad0: u32,
    _pad1: u32,
}

// What the enumeration found: status 1 = a valid basis `mask` (z written),
// 0 = none of the 2^n bases is valid. visited / singular count bases as the
// CPU's Counters do.
struct BasisResult {
    mask: u32,
    status: u32,
    visited: u32,
    singular: u32,
}

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> islands: array<Island>;
@group(0) @binding(2) var<storage, read> values: array<Scalar>;
@group(0) @binding(3) var<storage, read_write> results: array<BasisResult>;
@group(0) @binding(4) var<storage, read_write> z_out: array<Scalar>;

// Private scratch of one invocation: the principal system and its solution.
var<private> a: array<Scalar, 256>;
var<private> x: array<Scalar, 16>;
var<private> colmax: array<Scalar, 16>;
var<private> idx: array<u32, 16>;

const SINGULAR: u32 = 0u;
const INFEASIBLE: u32 = 1u;
const FEASIBLE: u32 = 2u;

// Solves basis `mask` of the island whose M starts at `base`; z_S in x[0..k].
fn solve_basis(base: u32, n: u32, mask: u32) -> u32 {
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
        if !(best > PIVOT_TOL * colmax[c]) || best == Scalar(0.0) {
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
    // Feasibility of z_S.
    var zmax = Scalar(0.0);
    for (var r = 0u; r < k; r++) {
        zmax = max(zmax, abs(x[r]));
    }
    let ztol = FEASIBILITY_TOL * zmax;
    for (var r = 0u; r < k; r++) {
        if x[r] < -ztol {
            return INFEASIBLE;
        }
    }
    // Feasibility of w off S.
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
        if w < -FEASIBILITY_TOL * scale {
            return INFEASIBLE;
        }
    }
    return FEASIBLE;
}

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= params.count {
        return;
    }
    let island_index = params.first + gid.x;
    let island = islands[island_index];
    let n = min(island.n, MAX_N);
    let full = 1u << n;
    var result = BasisResult(0u, 0u, 0u, 0u);
    var done = false;
    for (var k = 0u; k <= n && !done; k++) {
        var s = (1u << k) - 1u;
        loop {
            if s >= full {
                break;
            }
            result.visited++;
            let verdict = solve_basis(island.data, n, s);
            if verdict == SINGULAR {
                result.singular++;
            } else if verdict == FEASIBLE {
                result.mask = s;
                result.status = 1u;
                done = true;
                break;
            }
            if k == 0u {
                break;
            }
            // Next larger mask with the same popcount.
            let c = s & (0u - s);
            let r = s + c;
            s = (((r ^ s) >> 2u) / c) | r;
        }
    }
    // z of the chosen basis (clamped at 0 like the CPU's solve_basis), zeros
    // when none was found.
    var r = 0u;
    for (var i = 0u; i < n; i++) {
        var zi = Scalar(0.0);
        if result.status == 1u && ((result.mask >> i) & 1u) == 1u {
            zi = max(x[r], Scalar(0.0));
            r++;
        }
        z_out[island.z + i] = zi;
    }
    results[island_index] = result;
}
