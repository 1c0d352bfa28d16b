// GENERATED from shaders/enumeration_basis.wgsl + shaders/enumeration_workgroup.wgsl by src/gpu/shaders/compose.rs: do not edit.
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

// Enumeration of complementary bases: one workgroup per island.
// Same choice as shaders/enumeration.wgsl and its CPU twin
// (src/cpu/enumeration.rs): bases by increasing popcount k, each popcount by
// increasing mask, the first valid one chosen; when none is valid, the least
// infeasible within tol.relaxed (the first on a tie). solve_basis is
// enumeration.wgsl's (one copy, in shaders/enumeration_basis.wgsl), so in
// f64 the answers (basis, z, and the visited / singular counters) are the
// sequential kernel's.
//
// Parallelism inside one island: the bases of level k, in increasing mask
// order (colex rank 0 .. C(n, k) - 1), are visited in waves of WG = 64: in
// wave w invocation l solves the basis of rank 64 w + l (unranked with the
// binomial table). Masks increase with the rank, so the first wave with a
// valid basis holds the first valid basis of the sequential order, and its
// smallest valid lane (atomicMin) is the choice; the workgroup stops there
// (early exit). Otherwise lane 0 folds the wave's relaxed candidates into
// the least infeasible basis so far, in lane order (= sequential order).
// Every decision is made by lane 0 and published through workgroup memory;
// loop exits read it with workgroupUniformLoad, so every barrier stays in
// uniform control flow.
//
// Rounds: lane 0 counts the loop work of a wave for every lane (an upper
// bound: one basis_cost, the unranking, its scan of 64 lanes) and the
// workgroup stops before `params.budget` would be exceeded, saving where it
// stands in its BasisResult (mask: the next basis, _pad0: its rank in its
// level) and counting itself in `unfinished`. llvmpipe ends every loop of an
// invocation after about 65,535 iterations in all.
//
// Dispatch: workgroup params.first + workgroup_id.x handles that island
// (one workgroup per island, not per 64 islands).
//
// Shared with the other enumeration kernels: shaders/enumeration_basis.wgsl
// (scalar type, tolerances, MAX_N, Island, bindings 0-7, the elimination
// scratch a / x / colmax / idx, SINGULAR, solve_basis, write_z,
// basis_cost), which the generator prepends to this file;
// the generator replaces the lines marked HOST there (scalar type).

const WG: u32 = 64u;

// Params and BasisResult: shaders/enumeration_basis.wgsl. While status is
// 0, `mask` is the next basis to visit and `_pad0` its rank among the masks
// of its popcount.

// binom[c * 17 + i] = C(c, i), c, i = 0..16.
var<workgroup> binom: array<u32, 289>;
// The workgroup's state (lane 0 writes, everyone reads after a barrier).
var<workgroup> wg_state: BasisResult;
var<workgroup> wg_least_inf: Scalar;
// 1 while the workgroup visits another wave.
var<workgroup> wg_go: u32;
// Smallest lane with a valid basis in the wave (WG: none), by wave parity.
var<workgroup> wg_valid: array<atomic<u32>, 2>;
// 1 when some lane of the wave has a basis within tol.relaxed, by parity.
var<workgroup> wg_relaxed: array<atomic<u32>, 2>;
// Each lane's infeasibility in the wave (SINGULAR: not a relaxed candidate).
var<workgroup> wg_inf: array<Scalar, 64>;
// Singular bases of this round that count (before the chosen one).
var<workgroup> wg_singular: atomic<u32>;

// The mask of rank `r` among the masks of n bits with k set, in increasing
// order (colex: rank = sum of C(c_i, i) over the set bits c_1 < ... < c_k).
fn unrank(n: u32, k: u32, r: u32) -> u32 {
    var mask = 0u;
    var rest = r;
    var i = k;
    for (var cc = 0u; cc < n; cc++) {
        let c = n - 1u - cc;
        if i == 0u {
            break;
        }
        let b = binom[c * 17u + i];
        if b <= rest {
            mask |= 1u << c;
            rest -= b;
            i--;
        }
    }
    return mask;
}

// Loop work of one wave for any lane: its basis, the unranking, lane 0's
// scan of the wave, the loop itself.
fn wave_cost(n: u32, k: u32) -> u32 {
    return basis_cost(n, k) + n + WG + 4u;
}

@compute @workgroup_size(64)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(local_invocation_index) lid: u32) {
    // The binomial table: lane c (<= 16) fills row c.
    if lid <= MAX_N {
        var v = 1u;
        for (var i = 0u; i <= MAX_N; i++) {
            if i > lid {
                v = 0u;
            } else if i > 0u {
                v = v * (lid - i + 1u) / i;
            }
            binom[lid * 17u + i] = v;
        }
    }
    let in_range = wid.x < params.count;
    let island_index = params.first + min(wid.x, max(params.count, 1u) - 1u);
    if lid == 0u {
        let s = results[island_index];
        wg_state = s;
        wg_go = select(0u, 1u, in_range && s.status == 0u);
        if s.has_least == 1u {
            wg_least_inf = least_infeasibility[island_index];
        }
        atomicStore(&wg_valid[0], WG);
        atomicStore(&wg_valid[1], WG);
        atomicStore(&wg_relaxed[0], 0u);
        atomicStore(&wg_relaxed[1], 0u);
        atomicStore(&wg_singular, 0u);
    }
    if workgroupUniformLoad(&wg_go) == 0u {
        return;
    }
    let island = islands[island_index];
    let n = min(island.n, MAX_N);
    // Lane 0's bookkeeping (the same for every lane: a wave costs each lane
    // at most wave_cost).
    var spent = 0u;
    var parity = 0u;
    // The lane that holds the chosen basis' z_S in x (status 1).
    var chosen_lane = WG;
    var chosen_k = 0u;
    loop {
        if workgroupUniformLoad(&wg_go) == 0u {
            break;
        }
        let mask0 = wg_state.mask;
        let k = countOneBits(mask0);
        let level = binom[n * 17u + k];
        let rank = wg_state._pad0 + lid;
        var singular = false;
        if rank < level {
            let s = unrank(n, k, rank);
            let inf = solve_basis(island.data, n, s);
            var mine = SINGULAR;
            if inf == SINGULAR {
                singular = true;
            } else if inf <= tol.feasibility {
                atomicMin(&wg_valid[parity], lid);
            } else if inf <= tol.relaxed {
                mine = inf;
                atomicStore(&wg_relaxed[parity], 1u);
            }
            wg_inf[lid] = mine;
        }
        workgroupBarrier();
        let found = atomicLoad(&wg_valid[parity]);
        if singular && lid < found {
            atomicAdd(&wg_singular, 1u);
        }
        if found < WG {
            chosen_lane = found;
            chosen_k = k;
        }
        if lid == 0u {
            // The other parity's flags are next used after the next barrier.
            atomicStore(&wg_valid[1u - parity], WG);
            atomicStore(&wg_relaxed[1u - parity], 0u);
            spent += wave_cost(n, k);
            var st = wg_state;
            let in_wave = min(WG, level - st._pad0);
            if found < WG {
                st.visited += found + 1u;
                st.mask = unrank(n, k, st._pad0 + found);
                st.status = 1u;
                wg_go = 0u;
            } else {
                st.visited += in_wave;
                if atomicLoad(&wg_relaxed[parity]) == 1u {
                    // Lane order is the sequential order: strict < keeps
                    // the first on a tie, as on the CPU.
                    var best = WG;
                    for (var l = 0u; l < in_wave; l++) {
                        let v = wg_inf[l];
                        if v != SINGULAR && (st.has_least == 0u || v < wg_least_inf) {
                            st.has_least = 1u;
                            best = l;
                            wg_least_inf = v;
                        }
                    }
                    if best < WG {
                        st.least = unrank(n, k, st._pad0 + best);
                    }
                }
                st._pad0 += in_wave;
                if st._pad0 >= level {
                    // Level k done.
                    st._pad0 = 0u;
                    if k == n {
                        if st.has_least == 1u {
                            st.status = 3u;
                            st.mask = st.least;
                        } else {
                            st.status = 2u;
                        }
                        wg_go = 0u;
                    } else {
                        st.mask = (1u << (k + 1u)) - 1u;
                    }
                } else {
                    st.mask = unrank(n, k, st._pad0);
                }
                if st.status == 0u {
                    // The next wave (at most n basic) and the final solve must fit.
                    let next_k = countOneBits(st.mask);
                    if spent + wave_cost(n, next_k) + basis_cost(n, n) + n > params.budget {
                        wg_go = 0u;
                    }
                }
            }
            wg_state = st;
        }
        parity = 1u - parity;
    }
    // wg_state and wg_singular are final (the loop exited after a barrier
    // that followed lane 0's last write).
    let st = wg_state;
    if st.status == 1u && lid == chosen_lane {
        // This lane's x holds the chosen basis' z_S.
        write_z(island.z, n, chosen_k);
    }
    if lid == 0u {
        var out = st;
        out.singular += atomicLoad(&wg_singular);
        if out.status != 0u {
            // Finished: the record reads as the elimination kernel's.
            out._pad0 = 0u;
        }
        if st.status == 3u {
            // z of the least infeasible basis, solved again (the same
            // arithmetic, the same answer).
            let kk = countOneBits(st.least);
            let inf = solve_basis(island.data, n, st.least);
            if inf != SINGULAR {
                write_z(island.z, n, kk);
            }
        }
        if out.has_least == 1u {
            least_infeasibility[island_index] = wg_least_inf;
        }
        results[island_index] = out;
        if out.status == 0u {
            atomicAdd(&unfinished[n], 1u);
        }
    }
}
