// Lemke's path for the islands of the resident step whose warm basis did
// not hold (shaders/world_solve.wgsl's header; a module of its own,
// composed after world_step.wgsl, world_bodies.wgsl, shaders/lemke.wgsl's
// functions and world_island.wgsl): the entry point `world_lemke`, an
// indirect dispatch over the worlds world_solve_warm listed (LIST_LEMKE),
// one invocation per listed world (not per island: a world's islands are
// few and share its velocities, and the loop work of the islands before
// counts toward an island's pivot budget as one pass over the world's
// islands counts it).

// The basis Lemke ended on, re-solved in f64 as the CPU path re-solves it
// (textbook_checked, `solve_on`): z = max(x, 0) over the basic z's; Lemke's
// own z where M_SS is singular or the answer not finite. The basis (bit i:
// z_i basic).
fn resolve_basis(n: u32) -> u32 {
    var k = 0u;
    var mask = 0u;
    for (var i = 0u; i < n; i++) {
        let v = basic[i];
        if v >= n && v < 2u * n {
            cand[k] = v - n;
            mask |= 1u << (v - n);
            k++;
        }
    }
    if solve_on(k) {
        for (var i = 0u; i < k; i++) {
            zv[cand[i]] = max(xs[i], Scalar(0.0));
        }
    }
    return mask;
}

// Lemke's path for the island's n rows (the tableau B⁻¹ [I, −M, −e | q]
// with B = I, lemke.wgsl; `spent`: loop work so far, grown), its basis
// re-solved (resolve_basis) and checked; the basis, or NONE where Lemke
// gave up or the check failed; the error into `error`.
fn lemke_island(n: u32, spent: ptr<function, u32>, error: ptr<function, Scalar>) -> u32 {
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
        return NONE;
    }
    for (var i = 0u; i < n; i++) {
        zv[i] = Scalar(0.0);
    }
    var basis = 0u;
    if visited > 0u {
        for (var i = 0u; i < n; i++) {
            let v = basic[i];
            if v >= n && v < 2u * n {
                zv[v - n] = max(t[i * cols + rhs], Scalar(0.0));
            }
        }
        basis = resolve_basis(n);
        *spent += n * n * n;
    }
    *error = check(n);
    return select(basis, NONE, *error < Scalar(0.0));
}

// The listed islands of the listed world (`listed`: bit i for island i,
// WARM_TRIED) by Lemke's path (`lemke_island`), in island order, their z
// into their contact slots; the loop work counts every island
// before, its warm bases tried where they were (world_solve_warm), as one
// pass over the islands counts it. A world Lemke cannot solve is flagged
// NOT_SOLVED (the CPU steps it from its state).
@compute @workgroup_size(64)
fn world_lemke(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= atomicLoad(&lists[4u * LIST_LEMKE + 3u]) {
        return;
    }
    let at = list_at(LIST_LEMKE) + 2u * gid.x;
    let w = atomicLoad(&lists[at]);
    let listed = atomicLoad(&lists[at + 1u]);
    let out = sp.out_at + 4u * w;
    let count = words[out];
    let islands = words[out + 3u];
    let rec = w * REC;
    var flags = 0u;
    var bases = u32(records[rec + 7u]);
    var max_error = records[rec + 3u];
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
        if !lemke {
            continue;
        }
        var error = Scalar(-1.0);
        let basis = lemke_island(n, &spent, &error);
        if basis == NONE {
            flags |= NOT_SOLVED;
            break;
        }
        bases |= keep_island(w, n, &members, basis);
        max_error = max(max_error, error);
    }
    end_solve(w, flags, bases, max_error);
}
