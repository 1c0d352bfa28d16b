// The settle kernel: prediction's steps 3 and 4 on the device, before the
// enumeration or Lemke kernels (one dispatch over a chunk's table, recorded
// ahead of the first round in the same submission). CPU twin: `steps` in
// src/prediction.rs (warm start, then the predicted basis), each basis
// solved by the shared elimination (shaders/enumeration_basis.wgsl,
// prepended by the generator) as the CPU's `feasible_basis_into` solves it.
//
// Island.hint (LCP batches; src/prediction.rs, `prediction_hint_into`): bits
// 0-15 the island's warm basis, bits 16-31 its predicted basis (the
// approaching contacts, given only where M is positive definite: the host
// tested that); 0: none. An empty basis is never a hint: the host settled
// the islands with q >= 0 (separating), and on the others the empty basis is
// infeasible.
//
// Each hinted basis is tried in that order; the first that is nonsingular
// and feasible to tol.feasibility (the enumeration's test) is written as the
// island's answer: status FOUND, its mask, its z, visited 1 (the CPU's
// counters for a basis prediction settles), and _pad1 SETTLED_WARM or
// SETTLED_PREDICTED (src/gpu/layout.rs), so that the host counts the island
// with prediction's. The other kernels skip an island whose status is not 0;
// where neither basis settles it, its record stays cleared and it is
// enumerated (or pivoted) as if no hint had been given.

const SETTLED_WARM: u32 = 3u;
const SETTLED_PREDICTED: u32 = 4u;

// Whether basis `mask` of `island` (n contacts) is a valid answer; its z
// written where it is.
fn settles(island: Island, n: u32, mask: u32) -> bool {
    if mask == 0u || (mask >> n) != 0u {
        return false;
    }
    let infeasibility = solve_basis(island.data, n, mask);
    if infeasibility == SINGULAR || !(infeasibility <= tol.feasibility) {
        return false;
    }
    write_z(island.z, n, countOneBits(mask));
    return true;
}

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= params.count {
        return;
    }
    let island_index = params.first + gid.x;
    let island = islands[island_index];
    let n = min(island.n, MAX_N);
    var state = BasisResult(0u, 1u, 1u, 0u, 0u, 0u, 0u, 0u);
    if settles(island, n, island.hint & 0xffffu) {
        state.mask = island.hint & 0xffffu;
        state._pad1 = SETTLED_WARM;
    } else if settles(island, n, island.hint >> 16u) {
        state.mask = island.hint >> 16u;
        state._pad1 = SETTLED_PREDICTED;
    } else {
        return;
    }
    results[island_index] = state;
}
