// Enumeration of complementary bases in Gray-code order: one invocation per
// island, one principal pivot (O(n^2)) per basis instead of one elimination.
// CPU twin: src/cpu/enumeration_gray.rs (same tableau, same screen, same
// confirmation by elimination, same choice rule).
//
// Tableau: for a basis S, [z_S; w_N] = T [w_S; z_N] + t; the basic solution
// is t. Gray code g(k) = k ^ (k >> 1) changes one index r = ctz(k) per step:
// the principal pivot on T_rr. The tableau (n*n + n scalars) lives in the
// invocation's private memory. It is rebuilt from M every REFACTOR_PERIOD
// pivots (params.flags & 0xffff) to bound the drift of rounding, whenever a
// pivot |T_rr| is at most TAB_PIVOT_TOL times its row's largest entry, and
// at the start of every round.
//
// Screen: t passes when z_S >= -SCREEN_TOL * max|t_S| and
// w_N >= -SCREEN_TOL * (max|q| + max|M| * sum|t_S|). A basis that passes (or
// has no tableau: singular to the pivot test, or a principal pivot order that
// does not exist) and could beat the best basis so far by (popcount, mask)
// is confirmed by `solve_basis`, enumeration.wgsl's elimination with its
// tolerances (shared: shaders/enumeration_basis.wgsl). The best confirmed basis is chosen; when none is valid, the
// least infeasible one within RELAXED_TOL (ties to the smaller key), as on
// the CPU. Every basis is visited (counters: visited 2^n, singular among the
// confirmed ones).
//
// Rounds, as in enumeration.wgsl: an invocation spends at most
// `params.budget` units of loop work per round (llvmpipe ends every loop of
// an invocation after about 65,535 iterations in all), then saves its place
// in its BasisResult: `mask` is the Gray index of the next basis while in
// progress, `_pad0`/`_pad1` the best confirmed basis and whether there is one.
//
// Drift (params.flags bit 16): at every scheduled refactorisation the
// pivoted t is compared with the rebuilt one; the largest difference,
// relative to the screen's scale of each entry, goes to `drift[island]`.
//
// Shared with the other enumeration kernels: shaders/enumeration_basis.wgsl
// (scalar type, PIVOT_TOL / FEASIBILITY_TOL / RELAXED_TOL, MAX_N, Island,
// bindings 0-6, the elimination scratch a / x / colmax / idx, SINGULAR,
// and enumeration.wgsl's elimination: solve_basis, write_z, basis_cost),
// which the host prepends to this file before templating. The host
// replaces the lines marked HOST (here: SCREEN_TOL, TAB_PIVOT_TOL).

const SCREEN_TOL: Scalar = 1e-3; // HOST screen_tol
const TAB_PIVOT_TOL: Scalar = 1e-3; // HOST tableau_pivot_tol

// Params and BasisResult: shaders/enumeration_basis.wgsl; params.flags is
// the refactorisation period (bits 0..15) and the drift switch (bit 16);
// BasisResult's `_pad0` is the best confirmed basis so far and `_pad1`
// whether there is one.

// Bindings 0-6: enumeration_basis.wgsl.
@group(0) @binding(7) var<storage, read_write> drift: array<Scalar>;

// The tableau: T (row-major, stride n) and t.
var<private> tab: array<Scalar, 256>;
var<private> rhs: array<Scalar, 16>;
var<private> saved: array<Scalar, 16>;
var<private> valid: bool;

// Principal pivot on r. False (tableau invalid) when |T_rr| is too small.
fn pivot(n: u32, r: u32) -> bool {
    let rr = r * n;
    let p = tab[rr + r];
    var rowmax = Scalar(0.0);
    for (var j = 0u; j < n; j++) {
        rowmax = max(rowmax, abs(tab[rr + j]));
    }
    if !(abs(p) > TAB_PIVOT_TOL * rowmax) {
        valid = false;
        return false;
    }
    let inv = Scalar(1.0) / p;
    for (var j = 0u; j < n; j++) {
        tab[rr + j] *= -inv;
    }
    let tr = -rhs[r] * inv;
    for (var i = 0u; i < n; i++) {
        if i == r {
            continue;
        }
        let ri = i * n;
        let f = tab[ri + r];
        for (var j = 0u; j < n; j++) {
            tab[ri + j] += f * tab[rr + j];
        }
        rhs[i] += f * tr;
        tab[ri + r] = f * inv;
    }
    tab[rr + r] = inv;
    rhs[r] = tr;
    return true;
}

fn pivot_cost(n: u32) -> u32 {
    return n * n + 3u * n + 2u;
}

// The tableau of basis `mask` from M by principal pivots from the empty
// basis, the remaining index with the largest |T_rr| first.
fn rebuild(base: u32, n: u32, mask: u32) -> bool {
    for (var i = 0u; i < n * n; i++) {
        tab[i] = values[base + i];
    }
    for (var i = 0u; i < n; i++) {
        rhs[i] = values[base + n * n + i];
    }
    valid = true;
    var left = mask;
    loop {
        if left == 0u {
            break;
        }
        var best = 0u;
        var best_v = Scalar(-1.0);
        var rest = left;
        loop {
            if rest == 0u {
                break;
            }
            let r = countTrailingZeros(rest);
            rest &= rest - 1u;
            let v = abs(tab[r * n + r]);
            if v > best_v {
                best_v = v;
                best = r;
            }
        }
        if !pivot(n, best) {
            return false;
        }
        left &= ~(1u << best);
    }
    return true;
}

fn rebuild_cost(n: u32, k: u32) -> u32 {
    return n * n + n + 2u + k * (k + 1u + pivot_cost(n));
}

// Screen scales: (max|t_S|, max|q| + max|M| * sum|t_S|).
fn scales(n: u32, mask: u32, qmax: Scalar, mmax: Scalar) -> vec2<Scalar> {
    var zmax = Scalar(0.0);
    var zsum = Scalar(0.0);
    for (var i = 0u; i < n; i++) {
        if ((mask >> i) & 1u) == 1u {
            zmax = max(zmax, abs(rhs[i]));
            zsum += abs(rhs[i]);
        }
    }
    return vec2<Scalar>(zmax, qmax + mmax * zsum);
}

fn screen(n: u32, mask: u32, qmax: Scalar, mmax: Scalar) -> bool {
    let s = scales(n, mask, qmax, mmax);
    for (var i = 0u; i < n; i++) {
        let basic = ((mask >> i) & 1u) == 1u;
        let scale = select(s.y, s.x, basic);
        if rhs[i] < -SCREEN_TOL * scale {
            return false;
        }
    }
    return true;
}

// (popcount, mask) order: does a come before b?
fn key_less(a: u32, b: u32) -> bool {
    let ca = countOneBits(a);
    let cb = countOneBits(b);
    return ca < cb || (ca == cb && a < b);
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
    let n = min(island.n, MAX_N);
    let base = island.data;
    let period = max(params.flags & 0xffffu, 1u);
    let measure = (params.flags >> 16u) & 1u;
    let full = 1u << n;
    var spent = 0u;
    var qmax = Scalar(0.0);
    var mmax = Scalar(0.0);
    for (var i = 0u; i < n * n; i++) {
        mmax = max(mmax, abs(values[base + i]));
    }
    for (var i = 0u; i < n; i++) {
        qmax = max(qmax, abs(values[base + n * n + i]));
    }
    spent += n * n + n + 2u;
    var worst_drift = Scalar(0.0);
    if measure == 1u && state.visited > 0u {
        worst_drift = drift[island_index];
    }
    // The tableau of the round's first basis.
    var k = state.mask;
    var mask = k ^ (k >> 1u);
    rebuild(base, n, mask);
    spent += rebuild_cost(n, countOneBits(mask));
    var since = 0u;
    var first = true;
    let worst = 2u * pivot_cost(n) + rebuild_cost(n, n) + 3u * n + basis_cost(n, n) + 4u;
    loop {
        if !first {
            if spent + worst > params.budget {
                break;
            }
            let r = countTrailingZeros(k);
            mask ^= 1u << r;
            since++;
            if valid && since < period {
                pivot(n, r);
                spent += pivot_cost(n);
            } else {
                let scheduled = valid;
                if measure == 1u && scheduled {
                    // Drift: the pivoted t against the rebuilt one.
                    let ok = pivot(n, r);
                    spent += pivot_cost(n) + n;
                    for (var i = 0u; i < n; i++) {
                        saved[i] = rhs[i];
                    }
                    if rebuild(base, n, mask) && ok {
                        let s = scales(n, mask, qmax, mmax);
                        for (var i = 0u; i < n; i++) {
                            let basic = ((mask >> i) & 1u) == 1u;
                            let scale = max(select(s.y, s.x, basic), Scalar(1e-30));
                            worst_drift = max(worst_drift, abs(saved[i] - rhs[i]) / scale);
                        }
                    }
                    spent += 2u * n;
                } else {
                    rebuild(base, n, mask);
                }
                since = 0u;
                spent += rebuild_cost(n, countOneBits(mask));
            }
        }
        first = false;
        state.visited++;
        // A basis that cannot beat the best confirmed one needs no check.
        var check = state._pad1 == 0u || key_less(mask, state._pad0);
        if check && valid {
            check = screen(n, mask, qmax, mmax);
            spent += 2u * n;
        }
        if check {
            let nk = countOneBits(mask);
            spent += basis_cost(n, nk);
            let inf = solve_basis(base, n, mask);
            if inf == SINGULAR {
                state.singular++;
            } else if inf <= FEASIBILITY_TOL {
                state._pad0 = mask;
                state._pad1 = 1u;
                write_z(island.z, n, nk);
            } else if inf <= RELAXED_TOL {
                let li = least_infeasibility[island_index];
                if state.has_least == 0u || inf < li || (inf == li && key_less(mask, state.least)) {
                    state.least = mask;
                    state.has_least = 1u;
                    least_infeasibility[island_index] = inf;
                    if state._pad1 == 0u {
                        write_z(island.z, n, nk);
                    }
                }
            }
        }
        k++;
        if k == full {
            if state._pad1 == 1u {
                state.status = 1u;
                k = state._pad0;
            } else if state.has_least == 1u {
                state.status = 3u;
                k = state.least;
                // z of the least infeasible basis (a later best never came).
            } else {
                state.status = 2u;
                k = 0u;
            }
            break;
        }
    }
    state.mask = k;
    results[island_index] = state;
    if measure == 1u {
        drift[island_index] = worst_drift;
    }
    if state.status == 0u {
        atomicAdd(&unfinished[n], 1u);
    }
}
