// The solve phase of the resident step, per world (shaders/world_step.wgsl's
// header; a module of its own, composed after world_step.wgsl,
// world_bodies.wgsl and world_island.wgsl): the islands (find_islands),
// the handover of a world with friction, and each island from last step's
// basis; the entry point `world_solve_warm`.
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
// world solves each island whose warm basis holds and applies its
// impulses; the other islands (every island without warm bases) it lists
// with their world (LIST_LEMKE) for `world_lemke` (shaders/world_lemke.wgsl),
// an indirect dispatch over the listed worlds, which solves them by
// Lemke's path from the velocities left here. The islands' dynamic bodies
// are disjoint, so each body takes its own island's impulses in the
// island's order, as in one pass over the islands; `world_lemke` counts
// the loop work of the islands before as that pass would. Then
// `world_finish` (shaders/world_finish.wgsl) per world.

fn find(parent: ptr<function, array<u32, 16>>, x0: u32) -> u32 {
    var x = x0;
    while (*parent)[x] != x {
        (*parent)[x] = (*parent)[(*parent)[x]];
        x = (*parent)[x];
    }
    return x;
}



// A world's contacts as the solve starts (`begin_world`): contacts, the
// moving-body mask, the flags of world_contacts, islands, the hash of the
// contact ids, the deepest penetration; `handed`: the world has friction
// and went to world_friction (or was flagged NOT_SOLVED without it).
struct Begun {
    count: u32,
    moving: u32,
    flags: u32,
    islands: u32,
    ids: u32,
    max_penetration: Scalar,
    handed: bool,
}

// World w's islands (each contact's in its key's fourth word), the hash of
// its contact ids and its deepest penetration; its velocities v* into lin,
// ang. A world with friction (a contact with μ > 0: Scene::has_friction)
// goes to world_friction, flagged HANDED until that finishes it; its
// rounds there are counted from 0 (the record's sixth scalar).
fn begin_world(w: u32) -> Begun {
    let first = worlds[w].x;
    let out = sp.out_at + 4u * w;
    let count = words[out];
    let moving = words[out + 1u];
    var flags = words[out + 2u];
    let slot0 = w * sp.slots;
    records[w * REC + 5u] = Scalar(0.0);
    load_velocities(w);
    var parent: array<u32, 16>;
    var island_of_root: array<u32, 16>;
    for (var k = 0u; k < MAX_BODIES; k++) {
        parent[k] = k;
        island_of_root[k] = NONE;
    }
    for (var c = 0u; c < count; c++) {
        let key = sp.keys_at + 4u * (slot0 + c);
        let a = words[key];
        let b = words[key + 1u];
        if ((moving >> a) & (moving >> b) & 1u) != 0u {
            let ra = find(&parent, a);
            let rb = find(&parent, b);
            parent[max(ra, rb)] = min(ra, rb);
        }
    }
    var islands = 0u;
    var max_penetration = Scalar(0.0);
    var ids = 2166136261u ^ count;
    for (var c = 0u; c < count; c++) {
        let key = sp.keys_at + 4u * (slot0 + c);
        let a = words[key];
        ids = (ids ^ a) * 16777619u;
        ids = (ids ^ words[key + 1u]) * 16777619u;
        ids = (ids ^ words[key + 2u]) * 16777619u;
        let body = select(words[key + 1u], a, ((moving >> a) & 1u) != 0u);
        let root = find(&parent, body);
        if island_of_root[root] == NONE {
            island_of_root[root] = islands;
            islands++;
        }
        words[key + 3u] = island_of_root[root];
        max_penetration = max(max_penetration, -scratch[sp.contacts_at + (slot0 + c) * CP + 6u]);
    }
    var frictional = false;
    for (var c = 0u; c < count; c++) {
        let key = sp.keys_at + 4u * (slot0 + c);
        frictional = frictional || pair_friction(first + words[key], first + words[key + 1u]) > Scalar(0.0);
    }
    let fs = sp.fstate_at + 4u * w;
    words[fs] = F_IDLE;
    words[out + 3u] = islands;
    var handed = false;
    if frictional && flags == 0u {
        if sp.friction_at == 0u {
            flags |= NOT_SOLVED;
        } else {
            words[fs] = F_ASSEMBLE;
            words[fs + 1u] = 0u;
            words[fs + 2u] = 0u;
            words[out + 2u] = HANDED;
            records[w * REC + 2u] = max_penetration;
            records[w * REC + 3u] = Scalar(0.0);
            handed = true;
        }
    }
    return Begun(count, moving, flags, islands, ids, max_penetration, handed);
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

// Step parts 2 and 3 for world w (src/islands.rs find_islands, per island
// assembly and the CPU path's warm_settle, the door's check, the
// impulses) where its islands' warm bases hold; the others listed for
// world_lemke. A flagged world (here or in world_contacts) keeps its
// state.
@compute @workgroup_size(64)
fn world_solve_warm(@builtin(global_invocation_id) gid: vec3<u32>) {
    let w = gid.x;
    if w >= sp.count {
        return;
    }
    let b = begin_world(w);
    if b.handed {
        return;
    }
    let rec = w * REC;
    let warm = sp.warm_bases != 0u && records[rec + 6u] == Scalar(b.ids);
    let hints = u32(records[rec + 7u]);
    records[rec + 6u] = Scalar(b.ids);
    records[rec + 2u] = b.max_penetration;
    var flags = b.flags;
    var bases = 0u;
    var max_error = Scalar(0.0);
    var listed = 0u;
    var members: array<u32, 16>;
    for (var isl = 0u; isl < b.islands && flags == 0u; isl++) {
        let n = island_rows(w, b.count, b.moving, isl, &members);
        if n > ISLAND_MAX {
            flags |= ISLAND_TOO_LARGE;
            break;
        }
        var error = Scalar(-1.0);
        var basis = NONE;
        if warm {
            basis = warm_island(n, &members, hints, &error);
        }
        if basis == NONE {
            listed |= 1u << isl;
            continue;
        }
        bases |= apply_island(w, n, &members, basis);
        max_error = max(max_error, error);
    }
    flags = end_solve(w, flags, bases, max_error);
    if flags == 0u && listed != 0u {
        defer_world(w, listed | select(0u, WARM_TRIED, warm));
    }
}
