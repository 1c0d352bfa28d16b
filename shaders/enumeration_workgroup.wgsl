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
