// GENERATED from shaders/enumeration_basis.wgsl + shaders/lemke.wgsl by src/gpu/shaders/compose.rs: do not edit.
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

// Lemke's complementary pivoting method, the textbook run: one invocation
// per island. CPU twin: `lemke_textbook_basis` (src/cpu/lemke.rs) on
// `Workspace::pivot_path` (src/cpu/lemke_tableau.rs) with Noise::Column:
// the same tableau, tests and pivots in the same order, so that in f64 it
// ends on the CPU's basis.
//
// The tableau is B^-1 [I, -M, -e | q] (covering vector e = 1), n rows of
// 2n + 2 columns, row-major in the private array `t`: w_0..w_{n-1},
// z_0..z_{n-1}, z0, rhs; basic[i] is the variable basic in row i (w_i = i,
// z_i = n + i, z0 = 2n). A private array rather than a scratch storage
// buffer: it needs no binding or allocation per batch, and drivers already
// lay thread-private memory out interleaved by thread (coalesced), which is
// what a scratch buffer would have to arrange by hand.
//
// The island's record (BasisResult, shaders/enumeration_basis.wgsl): status
// FOUND (1) with `mask` the final basis (bit i: z_i basic), `visited` the
// pivots, z read from the tableau; or GAVE_UP (4): a secondary ray with z0
// not at zero, the pivot cap (tol._pad1), the loop budget, or a non-finite
// entry. There is no cycle detection: the host solves every island the
// kernel gave up on by the CPU path (which detects cycles). One round: the
// kernel never counts itself in `unfinished`.
//
// Loop budget: llvmpipe (lavapipe) ends every loop of an invocation after
// about 65,535 iterations in all, silently; an invocation gives up before a
// pivot whose loop work (an upper bound, `step`) would take it past
// params.budget (below that limit on software adapters).
//
// Tolerances (binding 7): _pad0 is the Lemke pivot tolerance (an entry of
// the entering column is a pivot when it exceeds it times the column's
// largest magnitude), _pad1 the pivot cap (src/gpu/pipelines.rs).

const SCALAR_MAX: Scalar = 1.7976931348623157e308; // HOST scalar_max

const GAVE_UP: u32 = 4u;

var<private> t: array<Scalar, 544>; // MAX_N * (2 * MAX_N + 2)
var<private> basic: array<u32, 16>;
// Rows whose entry in the entering column counts as a pivot.
var<private> cand: array<u32, 16>;
// Rows still tied in the lexicographic ratio test.
var<private> tied: array<u32, 16>;

fn finite(v: Scalar) -> bool {
    return abs(v) <= SCALAR_MAX;
}

// Gauss-Jordan pivot on (row r, column c): row r divided by its pivot, then
// every other row minus its entry in column c times row r (Workspace::pivot).
// False when an entry it wrote is not finite.
fn pivot(n: u32, r: u32, c: u32) -> bool {
    let cols = 2u * n + 2u;
    let pr = r * cols;
    let inv = Scalar(1.0) / t[pr + c];
    var ok = finite(inv);
    for (var j = 0u; j < cols; j++) {
        let v = t[pr + j] * inv;
        t[pr + j] = v;
        ok = ok && finite(v);
    }
    t[pr + c] = Scalar(1.0);
    for (var i = 0u; i < n; i++) {
        let ri = i * cols;
        let f = t[ri + c];
        if i != r && f != Scalar(0.0) {
            for (var j = 0u; j < cols; j++) {
                let v = t[ri + j] - f * t[pr + j];
                t[ri + j] = v;
                ok = ok && finite(v);
            }
            t[ri + c] = Scalar(0.0);
        }
    }
    return ok;
}

// The ratio-test key of row i in column col for the entering column e
// (Workspace::leaving_row): rhs values rounding made negative count as 0.
fn key(cols: u32, i: u32, col: u32, e: u32) -> Scalar {
    var v = t[i * cols + col];
    if col == cols - 1u {
        v = max(v, Scalar(0.0));
    }
    return v / t[i * cols + e];
}

// The lexicographic minimum-ratio test over cand[0..count]
// (Workspace::leaving_row): the minimum ratio; on a tie z0's row if it is
// tied, else the lexicographic minimum of the rows of B^-1 over the entry.
// n + 1 when a ratio is not finite (the caller gives up).
fn leaving_row(n: u32, e: u32, count: u32) -> u32 {
    let cols = 2u * n + 2u;
    let rhs = cols - 1u;
    var first = cand[0];
    var least = key(cols, first, rhs, e);
    var ties = 1u;
    for (var k = 1u; k < count; k++) {
        let v = key(cols, cand[k], rhs, e);
        if v < least {
            least = v;
            first = cand[k];
            ties = 1u;
        } else if v == least {
            ties++;
        }
    }
    if !finite(least) {
        return n + 1u;
    }
    if ties <= 1u {
        return first;
    }
    var m = 0u;
    for (var k = 0u; k < count; k++) {
        if key(cols, cand[k], rhs, e) <= least {
            tied[m] = cand[k];
            m++;
        }
    }
    for (var k = 0u; k < m; k++) {
        if basic[tied[k]] == 2u * n {
            return tied[k];
        }
    }
    for (var col = 0u; col < n; col++) {
        var low = key(cols, tied[0], col, e);
        for (var k = 1u; k < m; k++) {
            low = min(low, key(cols, tied[k], col, e));
        }
        var kept = 0u;
        for (var k = 0u; k < m; k++) {
            if key(cols, tied[k], col, e) <= low {
                tied[kept] = tied[k];
                kept++;
            }
        }
        m = kept;
        if m <= 1u {
            break;
        }
    }
    if m == 0u {
        return first;
    }
    return tied[0];
}

// The path from the tableau in `t` (B = I: rows w_i = q_i, columns
// [I, -M, -e | q], basic[i] = i), n contacts; `spent`: the loop work of
// filling it. Returns FOUND (1; the basis in `basic`, zero pivots where q >=
// 0) or GAVE_UP, the pivots in `visited`. Takes values only (the tableau is
// private), so that another kernel (shaders/world_step.wgsl) can fill `t`
// and call it.
fn lemke_pivots(n: u32, spent0: u32, pivot_tol: Scalar, max_pivots: u32, budget: u32, visited: ptr<function, u32>) -> u32 {
    let cols = 2u * n + 2u;
    let rhs = cols - 1u;
    let z0 = 2u * n;
    var q_scale = Scalar(0.0);
    var separating = true;
    var qmin = t[rhs];
    var first = 0u;
    for (var i = 0u; i < n; i++) {
        let qi = t[i * cols + rhs];
        separating = separating && qi >= Scalar(0.0);
        q_scale = max(q_scale, abs(qi));
        // The first leaving row: the most negative q_i, ties to the
        // largest index (Workspace::first_row).
        if qi <= qmin {
            qmin = qi;
            first = i;
        }
    }
    if separating {
        return 1u;
    }
    // Loop work of one pivot and its tests, an upper bound.
    let step = (n + 1u) * cols + 2u * n * n + 6u * n;
    var spent = spent0 + n + step;
    if !pivot(n, first, z0) {
        return GAVE_UP;
    }
    *visited = 1u;
    var entering = basic[first] + n;
    basic[first] = z0;
    loop {
        if *visited >= max_pivots || spent + step > budget {
            return GAVE_UP;
        }
        spent += step;
        var colmax = Scalar(0.0);
        for (var i = 0u; i < n; i++) {
            let v = abs(t[i * cols + entering]);
            if v > colmax {
                colmax = v;
            }
        }
        let floor = pivot_tol * colmax;
        var count = 0u;
        for (var i = 0u; i < n; i++) {
            if t[i * cols + entering] > floor {
                cand[count] = i;
                count++;
            }
        }
        if count == 0u || colmax == Scalar(0.0) {
            // A secondary ray: a solution only with z0 at zero to rounding.
            for (var i = 0u; i < n; i++) {
                if basic[i] == z0 {
                    if t[i * cols + rhs] <= pivot_tol * q_scale {
                        return 1u;
                    }
                    break;
                }
            }
            return GAVE_UP;
        }
        let best = leaving_row(n, entering, count);
        if best >= n || !pivot(n, best, entering) {
            return GAVE_UP;
        }
        *visited += 1u;
        let leaving = basic[best];
        basic[best] = entering;
        if leaving == z0 {
            return 1u;
        }
        if leaving < n {
            entering = leaving + n;
        } else {
            entering = leaving - n;
        }
    }
    return GAVE_UP;
}

// LEMKE KERNEL: the kernel's own part (reads its bindings) from here on;
// shaders/world_step.wgsl is composed with the text above this line.

// The path on island `island` of n contacts (M, q from `values`); returns
// FOUND (the basis in state.mask) or GAVE_UP, the pivots in state.visited.
fn lemke_path(island: Island, n: u32, state: ptr<function, BasisResult>) -> u32 {
    let cols = 2u * n + 2u;
    let rhs = cols - 1u;
    let z0 = 2u * n;
    let qbase = island.data + n * n;
    for (var i = 0u; i < n; i++) {
        let ri = i * cols;
        let mi = island.data + i * n;
        for (var j = 0u; j < n; j++) {
            t[ri + j] = Scalar(0.0);
            t[ri + n + j] = -values[mi + j];
        }
        t[ri + i] = Scalar(1.0);
        t[ri + z0] = Scalar(-1.0);
        t[ri + rhs] = values[qbase + i];
        basic[i] = i;
    }
    let pivot_tol = tol._pad0;
    let max_pivots = u32(max(tol._pad1, Scalar(1.0)));
    var visited = 0u;
    let status = lemke_pivots(n, n * cols, pivot_tol, max_pivots, params.budget, &visited);
    (*state).visited = visited;
    return status;
}

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= params.count {
        return;
    }
    let island_index = params.first + gid.x;
    // Settled before the round by its warm or predicted basis
    // (shaders/enumeration_settle.wgsl; the record is cleared otherwise).
    if results[island_index].status != 0u {
        return;
    }
    let island = islands[island_index];
    let n = min(island.n, MAX_N);
    var state = BasisResult(0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
    state.status = lemke_path(island, n, &state);
    if state.status == 1u && state.visited > 0u {
        let cols = 2u * n + 2u;
        for (var i = 0u; i < n; i++) {
            let v = basic[i];
            if v >= n && v < 2u * n {
                state.mask |= 1u << (v - n);
                z_out[island.z + v - n] = max(t[i * cols + cols - 1u], Scalar(0.0));
            }
        }
    }
    results[island_index] = state;
}
