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
const FIXED: bool = false; // HOST fixed
const FN: u32 = 1u; // HOST fixed_n
const FNN: u32 = 1u; // HOST fixed_nn

// Params and BasisResult (where an island's enumeration stands):
// shaders/enumeration_basis.wgsl.

// z of solve_basis_fixed (0 off the basis), for write_z_fixed.
var<private> fx: array<Scalar, FN>;

// solve_basis for islands of exactly FN contacts; z (0 off the basis) in
// fx. Placeholder: the generator replaces it with straight-line code for FN
// (src/gpu/shaders/unrolled.rs, `straight_line_solver`) in every specialised build,
// and the general build (FIXED false) never calls it.
fn solve_basis_fixed(base: u32, mask: u32) -> Scalar {
    return SINGULAR;
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
