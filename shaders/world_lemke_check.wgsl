// The check of Lemke's islands in the resident step (shaders/world_solve.wgsl's
// header; a module of its own, composed after world_step.wgsl,
// world_bodies.wgsl, shaders/lemke.wgsl's functions and world_island.wgsl):
// the entry point `world_lemke_check`, an indirect dispatch over the worlds
// world_solve_warm listed, after `world_lemke` (shaders/world_lemke.wgsl):
// per listed island the basis Lemke's path ended on re-solved in f64 and
// the door's check (the CPU path's textbook_checked).

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

// The listed islands of a listed world world_lemke did not flag: each
// island's z and basis from its contact slots (world_lemke), re-solved
// (`resolve_basis`), checked (`check`), its z kept in its slots; a world
// whose check fails is flagged NOT_SOLVED (the CPU steps it).
@compute @workgroup_size(64)
fn world_lemke_check(@builtin(global_invocation_id) gid: vec3<u32>) {
    let entry = lemke_entry(gid.x);
    if entry.x == NONE {
        return;
    }
    let w = entry.x;
    let listed = entry.y;
    let out = sp.out_at + 4u * w;
    if words[out + 2u] != 0u {
        return;
    }
    let count = words[out];
    let islands = words[out + 3u];
    let rec = w * REC;
    var flags = 0u;
    var bases = u32(records[rec + 7u]);
    var max_error = records[rec + 3u];
    var members: array<u32, 16>;
    let slot0 = w * sp.slots;
    for (var isl = 0u; isl < islands; isl++) {
        if ((listed >> isl) & 1u) == 0u {
            continue;
        }
        let n = load_island(w, count, isl, &members);
        for (var i = 0u; i < n; i++) {
            let slot = slot0 + members[i];
            zv[i] = scratch[sp.contacts_at + slot * CP + 7u];
            basic[i] = u32(scratch[row_at(slot) + 29u]);
        }
        let basis = resolve_basis(n);
        let error = check(n);
        if error < Scalar(0.0) {
            flags |= NOT_SOLVED;
            break;
        }
        bases |= keep_island(w, n, &members, basis);
        max_error = max(max_error, error);
    }
    end_solve(w, flags, bases, max_error);
}
