// The solve phase of the resident step, per world (shaders/world_step.wgsl's
// header; a module of its own, composed after world_step.wgsl,
// world_bodies.wgsl and world_island.wgsl): each island of a world
// world_assemble did not hand over or flag from last step's basis; the
// entry point `world_solve_warm`.
//
// The warm-start memory is the world's record (scalars 6 and 7): a hash of
// last step's contact ids (a, b, feature, in order) and its bases (bit c:
// contact c basic, c < 32). With `sp.warm_bases` the bases are hints where
// this step's ids hash alike, as the CPU path's memory by id: every answer
// passes the door's check whatever basis it came from.
//
// The solve in two entry points, two modules (llvmpipe runs every branch
// of an invocation under a mask, so Lemke's path, rarely taken once the
// warm bases hold, would cost every world every step; and a driver
// compiles each entry point with all it may call): `world_solve_warm` per
// world solves each island whose warm basis holds, its z into its
// contact slots; the other islands (every island without warm bases) it
// lists with their world (LIST_LEMKE) for `world_lemke`
// (shaders/world_lemke.wgsl), an indirect dispatch over the listed worlds,
// which solves them by Lemke's path, their z into the same slots
// (`world_lemke` counts the loop work of the islands before as one pass
// over the islands would). Then `world_finish` (shaders/world_finish.wgsl)
// per world applies every contact's impulse in slot order: the islands'
// dynamic bodies are disjoint, so each body takes its own island's
// impulses in the island's order, as the CPU path applies them.

// The hash of world w's contact ids (a, b, feature, in order; FNV-1a
// over its `count` contacts): the warm-start memory's key.
fn contact_ids(w: u32, count: u32) -> u32 {
    var ids = 2166136261u ^ count;
    for (var c = 0u; c < count; c++) {
        let key = sp.keys_at + 4u * (w * sp.slots + c);
        ids = (ids ^ words[key]) * 16777619u;
        ids = (ids ^ words[key + 1u]) * 16777619u;
        ids = (ids ^ words[key + 2u]) * 16777619u;
    }
    return ids;
}

// The CPU path's warm start (world_cpu.rs warm_settle) for an island of n
// contacts: last step's basis `hint` (bit i: contact i basic) solved
// (`solve_on`), z = max(x, 0), kept where the door's check passes (its
// error into `error`); else up to WARM_PIVOTS block principal pivots from
// it: basic contacts at z = 0 leave, the others with w < 0 enter. The
// basis kept, or NONE (Lemke's path then): singular, no pivot left to
// make, or the pivots spent.
fn warm_basis(n: u32, hint: u32, error: ptr<function, Scalar>) -> u32 {
    var mask = hint;
    for (var round = 0u; round <= WARM_PIVOTS; round++) {
        var k = 0u;
        for (var i = 0u; i < n; i++) {
            zv[i] = Scalar(0.0);
            if ((mask >> i) & 1u) != 0u {
                cand[k] = i;
                k++;
            }
        }
        if !solve_on(k) {
            return NONE;
        }
        for (var r = 0u; r < k; r++) {
            zv[cand[r]] = max(xs[r], Scalar(0.0));
        }
        *error = check(n);
        if *error >= Scalar(0.0) {
            return mask;
        }
        var next = mask;
        for (var i = 0u; i < n; i++) {
            let bit = 1u << i;
            if (mask & bit) != 0u && zv[i] <= Scalar(0.0) {
                next &= ~bit;
            }
            if (mask & bit) == 0u && wv[i] < Scalar(0.0) {
                next |= bit;
            }
        }
        if next == mask {
            return NONE;
        }
        mask = next;
    }
    return NONE;
}

// The island's warm basis (warm_basis) from the world's bases `hints` (bit
// c: contact c basic), its error into `error`; NONE where none holds.
fn warm_island(n: u32, members: ptr<function, array<u32, 16>>, hints: u32, error: ptr<function, Scalar>) -> u32 {
    var hint = 0u;
    for (var i = 0u; i < n; i++) {
        hint |= select(0u, (((hints >> (*members)[i]) & 1u) << i), (*members)[i] < 32u);
    }
    return warm_basis(n, hint, error);
}

// Lists world w for `world_lemke` with its islands `listed` (bit i:
// island i; WARM_TRIED) in LIST_LEMKE (two words an entry; workgroups of
// WORKGROUP entries).
fn defer_world(w: u32, listed: u32) {
    let k = atomicAdd(&lists[4u * LIST_LEMKE + 3u], 1u);
    atomicMax(&lists[4u * LIST_LEMKE], k / 64u + 1u);
    atomicStore(&lists[list_at(LIST_LEMKE) + 2u * k], w);
    atomicStore(&lists[list_at(LIST_LEMKE) + 2u * k + 1u], listed);
}

// Step part 3 for world w (the CPU path's warm_settle per island, the
// door's check) where its islands' warm bases hold; the others listed for
// world_lemke. A world handed to world_friction is left to it; a flagged
// world (world_contacts, world_assemble) keeps its state.
@compute @workgroup_size(64)
fn world_solve_warm(@builtin(global_invocation_id) gid: vec3<u32>) {
    let w = gid.x;
    if w >= sp.count {
        return;
    }
    let out = sp.out_at + 4u * w;
    var flags = words[out + 2u];
    if flags == HANDED {
        return;
    }
    let count = words[out];
    let islands = words[out + 3u];
    let ids = contact_ids(w, count);
    let rec = w * REC;
    let warm = sp.warm_bases != 0u && records[rec + 6u] == Scalar(ids);
    let hints = u32(records[rec + 7u]);
    records[rec + 6u] = Scalar(ids);
    var bases = 0u;
    var max_error = Scalar(0.0);
    var listed = 0u;
    var members: array<u32, 16>;
    for (var isl = 0u; isl < islands && flags == 0u; isl++) {
        let n = load_island(w, count, isl, &members);
        var error = Scalar(-1.0);
        var basis = NONE;
        if warm {
            basis = warm_island(n, &members, hints, &error);
        }
        if basis == NONE {
            listed |= 1u << isl;
            continue;
        }
        bases |= keep_island(w, n, &members, basis);
        max_error = max(max_error, error);
    }
    flags = end_solve(w, flags, bases, max_error);
    if flags == 0u && listed != 0u {
        defer_world(w, listed | select(0u, WARM_TRIED, warm));
    }
}
