// Lemke's path for the islands of the resident step whose warm basis did
// not hold (shaders/world_solve.wgsl's header; a module of its own,
// composed after world_step.wgsl, world_bodies.wgsl, shaders/lemke.wgsl's
// functions and world_island.wgsl): the entry point `world_lemke`, an
// indirect dispatch over the worlds world_solve_warm listed (LIST_LEMKE),
// one invocation per listed world (not per island: the loop work of the
// islands before counts toward an island's pivot budget, as one pass over
// the world's islands counts it). The basis each island's path ended on
// and its z wait in the island's contact slots for `world_lemke_check`
// (shaders/world_lemke_check.wgsl: the basis re-solved in f64, the door's
// check), the CPU path's lemke_textbook_basis then textbook_checked.

// Lemke's path for the island's n rows (the tableau B⁻¹ [I, −M, −e | q]
// with B = I, lemke.wgsl; `spent`: loop work so far, grown as one pass
// with the re-solve counts it): z = max(rhs, 0) over the basic z's (0
// elsewhere) into the members' z slots, each row's basic variable into its
// row (`row_at` + 29; row i's own w where no pivot was made, which
// world_lemke_check's re-solve leaves alone). False where Lemke gave up.
fn lemke_island(w: u32, n: u32, members: ptr<function, array<u32, 16>>, spent: ptr<function, u32>) -> bool {
    let cols = 2u * n + 2u;
    let rhs = cols - 1u;
    for (var i = 0u; i < n; i++) {
        let ri = i * cols;
        for (var j = 0u; j < n; j++) {
            t[ri + j] = Scalar(0.0);
            t[ri + n + j] = -mm[ISLAND_MAX * i + j];
        }
        t[ri + i] = Scalar(1.0);
        t[ri + 2u * n] = Scalar(-1.0);
        t[ri + rhs] = qv[i];
        basic[i] = i;
    }
    *spent += n * cols;
    var visited = 0u;
    let max_pivots = u32(max(sp.max_pivots, Scalar(1.0)));
    let status = lemke_pivots(n, *spent, sp.pivot_tol, max_pivots, sp.budget, &visited);
    *spent += n + (visited + 1u) * ((n + 1u) * cols + 2u * n * n + 6u * n);
    if status != 1u {
        return false;
    }
    let slot0 = w * sp.slots;
    for (var i = 0u; i < n; i++) {
        scratch[sp.contacts_at + (slot0 + (*members)[i]) * CP + 7u] = Scalar(0.0);
        scratch[row_at(slot0 + (*members)[i]) + 29u] = Scalar(select(basic[i], i, visited == 0u));
    }
    if visited > 0u {
        for (var i = 0u; i < n; i++) {
            let v = basic[i];
            if v >= n && v < 2u * n {
                scratch[sp.contacts_at + (slot0 + (*members)[v - n]) * CP + 7u] = max(t[i * cols + rhs], Scalar(0.0));
            }
        }
        *spent += n * n * n;
    }
    return true;
}

// The listed islands of the listed world (`listed`: bit i for island i,
// WARM_TRIED) by Lemke's path (`lemke_island`), in island order; the loop
// work counts every island before, its warm bases tried where they were
// (world_solve_warm), as one pass over the islands counts it. A world
// where Lemke gives up is flagged NOT_SOLVED (the CPU steps it from its
// state).
@compute @workgroup_size(64)
fn world_lemke(@builtin(global_invocation_id) gid: vec3<u32>) {
    let entry = lemke_entry(gid.x);
    if entry.x == NONE {
        return;
    }
    let w = entry.x;
    let listed = entry.y;
    let out = sp.out_at + 4u * w;
    let count = words[out];
    let islands = words[out + 3u];
    var flags = 0u;
    var spent = 0u;
    var members: array<u32, 16>;
    for (var isl = 0u; isl < islands; isl++) {
        if ((listed & ~WARM_TRIED) >> isl) == 0u {
            break;
        }
        let lemke = ((listed >> isl) & 1u) != 0u;
        var n = 0u;
        if lemke {
            n = load_island(w, count, isl, &members);
        } else {
            n = island_members(w, count, isl, &members);
        }
        spent += n * n + count;
        if (listed & WARM_TRIED) != 0u {
            spent += (WARM_PIVOTS + 1u) * (n * n * n + 3u * n * n);
        }
        if lemke && !lemke_island(w, n, &members, &spent) {
            flags |= NOT_SOLVED;
            break;
        }
    }
    let rec = w * REC;
    end_solve(w, flags, u32(records[rec + 7u]), records[rec + 3u]);
}
