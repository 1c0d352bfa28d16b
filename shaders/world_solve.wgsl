// The solve phase of the resident step (shaders/world_step.wgsl's header;
// composed after it and shaders/world_finish.wgsl): one island's rows, the
// check, the islands, the entry points `world_solve_warm`, `world_solve`
// and `world_finish`.

// One island's contact rows (src/cpu/assembly.rs ContactRow), row i of the
// island at 12 i: the Jacobian and the response M⁻¹Jᵀ of sides a (0..6)
// and b (6..12); q (the dynamic body of each side: `sides`,
// shaders/world_finish.wgsl); the answer z.
var<private> jac: array<Scalar, 192>;
var<private> resp: array<Scalar, 192>;
var<private> qv: array<Scalar, 16>;
var<private> zv: array<Scalar, 16>;
// The island's M (row i at ISLAND_MAX i), assembled once for the tableau,
// the basis solves and the check; w = M z + q of the last check; the basis
// solve's x over cand.
var<private> mm: array<Scalar, 256>;
var<private> wv: array<Scalar, 16>;
var<private> xs: array<Scalar, 16>;

fn put_row(dst: ptr<private, array<Scalar, 192>>, at: u32, v: vec3<Scalar>) {
    (*dst)[at] = v.x;
    (*dst)[at + 1u] = v.y;
    (*dst)[at + 2u] = v.z;
}

fn row_vec3(src: ptr<private, array<Scalar, 192>>, at: u32) -> vec3<Scalar> {
    return vec3<Scalar>((*src)[at], (*src)[at + 1u], (*src)[at + 2u]);
}

// The world-frame inverse inertia R diag(1/I) Rᵀ of body b (global index)
// times v, at the step's start pose.
fn inv_inertia_mul(b: u32, v: vec3<Scalar>) -> vec3<Scalar> {
    let p = placed_body(b);
    let inv = vec3_at_consts(sp.bodies_at + b * BC + 6u);
    return rotate(p, inv * unrotate(p, v));
}

// assemble_contact: row i of the island from contact `slot` of world with
// first body `first` and moving-body mask `moving`; bias φ/Δt, ε = 0.
fn assemble_contact(slot: u32, i: u32, first: u32, moving: u32) {
    let at = sp.contacts_at + slot * CP;
    let key = sp.keys_at + 4u * slot;
    let a = words[key];
    let b = words[key + 1u];
    let p = vec3_at_scratch(at);
    let n = vec3_at_scratch(at + 3u);
    let gap = scratch[at + 6u];
    let ga = first + a;
    let gb = first + b;
    let ra = p - vec3_at_state(ga * BS);
    let rb = p - vec3_at_state(gb * BS);
    let ra_n = cross3(ra, n);
    let rb_n = cross3(rb, n);
    let r = 12u * i;
    put_row(&jac, r, n);
    put_row(&jac, r + 3u, ra_n);
    put_row(&jac, r + 6u, -n);
    put_row(&jac, r + 9u, -rb_n);
    let s = contact_sides(slot, moving);
    if s.x != NONE {
        put_row(&resp, r, n * body_const(ga, 5u));
        put_row(&resp, r + 3u, inv_inertia_mul(ga, ra_n));
    }
    if s.y != NONE {
        put_row(&resp, r + 6u, -n * body_const(gb, 5u));
        put_row(&resp, r + 9u, -inv_inertia_mul(gb, rb_n));
    }
    sides[i] = s;
    let pdot = (lin[a] + cross3(ang[a], ra)) - (lin[b] + cross3(ang[b], rb));
    qv[i] = dot3(pdot, n) + gap / sp.dt;
}

fn dot6(x: u32, y: u32) -> Scalar {
    var m = Scalar(0.0);
    for (var k = 0u; k < 6u; k++) {
        m += jac[x + k] * resp[y + k];
    }
    return m;
}

// assembly.rs matrix_entry: M_ij over the dynamic bodies rows i and j
// share, the sides in its order (a–a, a–b, b–a, b–b), into `mm` for the
// island's n rows.
fn fill_matrix(n: u32) {
    for (var i = 0u; i < n; i++) {
        let si = sides[i];
        for (var j = 0u; j < n; j++) {
            let sj = sides[j];
            // A side of row i meets at most one side of row j (a row's
            // two bodies differ): one dot6 per side of row i, in order.
            let ja = select(6u, 0u, si.x == sj.x);
            let jb = select(6u, 0u, si.y == sj.x);
            var m = Scalar(0.0);
            if si.x != NONE && (si.x == sj.x || si.x == sj.y) {
                m += dot6(12u * i, 12u * j + ja);
            }
            if si.y != NONE && (si.y == sj.x || si.y == sj.y) {
                m += dot6(12u * i + 6u, 12u * j + jb);
            }
            mm[ISLAND_MAX * i + j] = m;
        }
    }
}

// lcp.rs norm2 of the first n entries of the rows given by `which`: 0: z −
// max(0, z − w) (w in `wv`), 1: q.
fn scaled_norm(n: u32, which: u32) -> Scalar {
    var big = Scalar(0.0);
    for (var i = 0u; i < n; i++) {
        var x = qv[i];
        if which == 0u {
            x = zv[i] - max(Scalar(0.0), zv[i] - wv[i]);
        }
        big = max(big, abs(x));
    }
    if big == Scalar(0.0) || !finite(big) {
        return big;
    }
    var sum = Scalar(0.0);
    for (var i = 0u; i < n; i++) {
        var x = qv[i];
        if which == 0u {
            x = zv[i] - max(Scalar(0.0), zv[i] - wv[i]);
        }
        sum += (x / big) * (x / big);
    }
    return big * sqrt(sum);
}

// The door's final check of the island's z (check_solution): w = M z + q
// (into `wv`), z and w finite, lcp_error(z, w, q) finite and <= tolerance.
// The error, or -1 where the check fails.
fn check(n: u32) -> Scalar {
    var ok = true;
    for (var i = 0u; i < n; i++) {
        var s = Scalar(0.0);
        for (var j = 0u; j < n; j++) {
            s += mm[ISLAND_MAX * i + j] * zv[j];
        }
        wv[i] = qv[i] + s;
        ok = ok && finite(wv[i]) && finite(zv[i]);
    }
    let num = scaled_norm(n, 0u);
    let qn = scaled_norm(n, 1u);
    var error = num;
    if qn > SCALAR_EPSILON {
        error = num / qn;
    }
    if !ok || !finite(error) || !(error <= sp.tolerance) {
        return Scalar(-1.0);
    }
    return error;
}

// M_SS x = −q_S over the contacts S = cand[0..k] by Gaussian elimination
// with partial pivoting (textbook_checked), in the tableau `t`, x into
// `xs`. False where M_SS is singular or x not finite.
fn solve_on(k: u32) -> bool {
    let cols = k + 1u;
    for (var r = 0u; r < k; r++) {
        for (var c = 0u; c < k; c++) {
            t[r * cols + c] = mm[ISLAND_MAX * cand[r] + cand[c]];
        }
        t[r * cols + k] = -qv[cand[r]];
    }
    for (var p = 0u; p < k; p++) {
        var best = p;
        var big = abs(t[p * cols + p]);
        for (var r = p + 1u; r < k; r++) {
            let v = abs(t[r * cols + p]);
            if v > big {
                big = v;
                best = r;
            }
        }
        if !(big > Scalar(0.0)) || !finite(big) {
            return false;
        }
        for (var c = p; c <= k; c++) {
            let v = t[p * cols + c];
            t[p * cols + c] = t[best * cols + c];
            t[best * cols + c] = v;
        }
        for (var r = p + 1u; r < k; r++) {
            let f = t[r * cols + p] / t[p * cols + p];
            for (var c = p; c <= k; c++) {
                t[r * cols + c] -= f * t[p * cols + c];
            }
        }
    }
    var ok = true;
    for (var r = k; r > 0u; r--) {
        let i = r - 1u;
        var s = t[i * cols + k];
        for (var c = i + 1u; c < k; c++) {
            s -= t[i * cols + c] * xs[c];
        }
        xs[i] = s / t[i * cols + i];
        ok = ok && finite(xs[i]);
    }
    return ok;
}

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

// Block principal pivots tried from the warm basis (world_cpu.rs
// WARM_PIVOTS).
const WARM_PIVOTS: u32 = 3u;

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

fn find(parent: ptr<function, array<u32, 16>>, x0: u32) -> u32 {
    var x = x0;
    while (*parent)[x] != x {
        (*parent)[x] = (*parent)[(*parent)[x]];
        x = (*parent)[x];
    }
    return x;
}


// Step parts 2 and 3 for one world: find_islands (union–find through the
// moving bodies, islands in the order of their first contact), per island
// assembly, the warm basis (`warm_basis`) and where it fails Lemke
// (lemke_pivots), the check, the impulses (`world_solve_warm`,
// `world_solve`); then finish (poses, sleep counters) and the world's
// figures (`world_finish`). A flagged world (here or in world_contacts)
// keeps its state.
//
// The warm-start memory is the world's record (scalars 6 and 7): a hash of
// last step's contact ids (a, b, feature, in order) and its bases (bit c:
// contact c basic, c < 32). With `sp.warm_bases` the bases are hints where
// this step's ids hash alike, as the CPU path's memory by id: every answer
// passes the door's check whatever basis it came from.
//
// In separate entry points, each a dispatch: where `sp.warm_bases`
// (llvmpipe runs every branch of an invocation under a mask, so Lemke's
// path, rarely taken once the warm bases hold, would cost every world
// every step) `world_solve_warm` over every world, without Lemke's code:
// a world with an island whose warm basis fails (or without a warm basis)
// is left as it is and listed (LIST_SOLVE); then `world_solve`,
// dispatched indirectly over the listed worlds only, steps them from the
// start with Lemke's path. Both rewrite what they write before the island
// loop alike, so a listed world ends as it would in `world_solve` alone.
// Without `sp.warm_bases`, `world_solve` alone over every world. Then
// `world_finish` over every world not handed to world_friction, from the
// velocities the solve left in `scratch`.

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

// Island `isl` of world w (begun as `b`): its contacts (indices in the
// world) into `members`, assembled (assemble_contact, fill_matrix); its
// size, above ISLAND_MAX where it is too large (nothing assembled then).
fn island_rows(w: u32, b: Begun, isl: u32, members: ptr<function, array<u32, 16>>) -> u32 {
    let slot0 = w * sp.slots;
    var n = 0u;
    for (var c = 0u; c < b.count; c++) {
        if words[sp.keys_at + 4u * (slot0 + c) + 3u] == isl {
            if n < ISLAND_MAX {
                (*members)[n] = c;
            }
            n++;
        }
    }
    if n > ISLAND_MAX {
        return n;
    }
    for (var i = 0u; i < n; i++) {
        assemble_contact(slot0 + (*members)[i], i, worlds[w].x, b.moving);
    }
    fill_matrix(n);
    return n;
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

// The island's answer zv applied (cpu/impulses.rs velocities_after: v +=
// M⁻¹Jᵀ z per side) and kept in its contact slots; its basis (bit i: row
// i basic) as the world's bases (bit c: contact c basic, c < 32).
fn apply_island(w: u32, n: u32, members: ptr<function, array<u32, 16>>, basis: u32) -> u32 {
    let slot0 = w * sp.slots;
    var bases = 0u;
    for (var i = 0u; i < n; i++) {
        let m = (*members)[i];
        bases |= select(0u, ((basis >> i) & 1u) << m, m < 32u);
        let zi = zv[i];
        scratch[sp.contacts_at + (slot0 + m) * CP + 7u] = zi;
        if zi == Scalar(0.0) {
            continue;
        }
        let s = sides[i];
        let r = 12u * i;
        if s.x != NONE {
            lin[s.x] += row_vec3(&resp, r) * zi;
            ang[s.x] += row_vec3(&resp, r + 3u) * zi;
        }
        if s.y != NONE {
            lin[s.y] += row_vec3(&resp, r + 6u) * zi;
            ang[s.y] += row_vec3(&resp, r + 9u) * zi;
        }
    }
    return bases;
}

// The end of world w's solve: last step's ids and bases kept where the
// world was stepped here, the velocities after the impulses, the flags
// (BUDGET where llvmpipe's loop limit was reached in this dispatch) and
// the figures world_finish reads.
fn end_world(w: u32, b: Begun, flags0: u32, bases: u32, max_error: Scalar) {
    var flags = flags0;
    if flags == 0u && !loops_left() {
        flags = BUDGET;
    }
    let rec = w * REC;
    records[rec + 6u] = select(Scalar(-1.0), Scalar(b.ids), flags == 0u);
    records[rec + 7u] = Scalar(bases);
    records[rec + 2u] = b.max_penetration;
    records[rec + 3u] = max_error;
    store_velocities(w);
    words[sp.out_at + 4u * w + 2u] = flags;
}

// The world's bases of last step where its contact ids are last step's
// (`sp.warm_bases`), else None: the hints of warm_island.
fn warm_hints(w: u32, b: Begun) -> vec2<u32> {
    let rec = w * REC;
    let warm = sp.warm_bases != 0u && records[rec + 6u] == Scalar(b.ids);
    return vec2<u32>(u32(warm), u32(records[rec + 7u]));
}

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
    let hints = warm_hints(w, b);
    var flags = b.flags;
    var bases = 0u;
    var max_error = Scalar(0.0);
    var members: array<u32, 16>;
    for (var isl = 0u; isl < b.islands && flags == 0u; isl++) {
        let n = island_rows(w, b, isl, &members);
        if n > ISLAND_MAX {
            flags |= ISLAND_TOO_LARGE;
            break;
        }
        var error = Scalar(-1.0);
        var basis = NONE;
        if hints.x != 0u {
            basis = warm_island(n, &members, hints.y, &error);
        }
        if basis == NONE {
            defer_world(w);
            return;
        }
        bases |= apply_island(w, n, &members, basis);
        max_error = max(max_error, error);
    }
    end_world(w, b, flags, bases, max_error);
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

@compute @workgroup_size(64)
fn world_solve(@builtin(global_invocation_id) gid: vec3<u32>) {
    var w = gid.x;
    if sp.warm_bases != 0u {
        if w >= atomicLoad(&lists[4u * LIST_SOLVE + 3u]) {
            return;
        }
        w = atomicLoad(&lists[list_at(LIST_SOLVE) + w]);
    }
    if w >= sp.count {
        return;
    }
    let b = begin_world(w);
    if b.handed {
        return;
    }
    let hints = warm_hints(w, b);
    var flags = b.flags;
    var bases = 0u;
    var max_error = Scalar(0.0);
    var spent = 0u;
    var members: array<u32, 16>;
    for (var isl = 0u; isl < b.islands && flags == 0u; isl++) {
        let n = island_rows(w, b, isl, &members);
        if n > ISLAND_MAX {
            flags |= ISLAND_TOO_LARGE;
            break;
        }
        spent += n * n + b.count;
        var error = Scalar(-1.0);
        var basis = NONE;
        if hints.x != 0u {
            basis = warm_island(n, &members, hints.y, &error);
            spent += (WARM_PIVOTS + 1u) * (n * n * n + 3u * n * n);
        }
        if basis == NONE {
            basis = lemke_island(n, &spent, &error);
        }
        if basis == NONE {
            flags |= NOT_SOLVED;
            break;
        }
        bases |= apply_island(w, n, &members, basis);
        max_error = max(max_error, error);
    }
    end_world(w, b, flags, bases, max_error);
}

// Lists world w for `world_solve` (its indirect dispatch: workgroups of
// WORKGROUP worlds).
fn defer_world(w: u32) {
    push_list(LIST_SOLVE, w);
}

// step.rs finish for every world the solve stepped or flagged (a world
// handed to world_friction is finished there).
@compute @workgroup_size(64)
fn world_finish(@builtin(global_invocation_id) gid: vec3<u32>) {
    let w = gid.x;
    if w >= sp.count {
        return;
    }
    let flags = words[sp.out_at + 4u * w + 2u];
    if flags == HANDED {
        return;
    }
    load_velocities(w);
    finish_world(w, flags, records[w * REC + 2u], records[w * REC + 3u]);
}
