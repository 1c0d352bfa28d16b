// Assembly of the resident step's islands (shaders/world_step.wgsl's
// header; a module of its own, composed after world_step.wgsl and
// world_bodies.wgsl): per world the islands (src/islands.rs find_islands),
// the handover of a world with friction to world_friction, and per island
// its contact rows and M (src/cpu/assembly.rs assemble_contact /
// assemble_island), kept per contact slot (`row_at`: q, the response
// M⁻¹Jᵀ, the contact's row of M) for the solve (world_solve.wgsl,
// world_lemke.wgsl) and the impulses (world_finish.wgsl); the entry point
// `world_assemble`.

// One island's contact rows (src/cpu/assembly.rs ContactRow), row i of the
// island at 12 i: the Jacobian and the response M⁻¹Jᵀ of sides a (0..6)
// and b (6..12) (the dynamic body of each side: `sides`,
// shaders/world_bodies.wgsl); q.
var<private> jac: array<Scalar, 192>;
var<private> resp: array<Scalar, 192>;
var<private> qv: array<Scalar, 16>;
// The island's M (row i at ISLAND_MAX i).
var<private> mm: array<Scalar, 256>;

fn put_row(dst: ptr<private, array<Scalar, 192>>, at: u32, v: vec3<Scalar>) {
    (*dst)[at] = v.x;
    (*dst)[at + 1u] = v.y;
    (*dst)[at + 2u] = v.z;
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

// The island's n rows kept in their contact slots (`row_at`: q, the
// response of sides a and b, the row of M over the island's members).
fn keep_rows(w: u32, n: u32, members: ptr<function, array<u32, 16>>) {
    let slot0 = w * sp.slots;
    for (var i = 0u; i < n; i++) {
        let r = row_at(slot0 + (*members)[i]);
        scratch[r] = qv[i];
        for (var k = 0u; k < 12u; k++) {
            scratch[r + 1u + k] = resp[12u * i + k];
        }
        for (var j = 0u; j < n; j++) {
            scratch[r + 13u + j] = mm[ISLAND_MAX * i + j];
        }
    }
}

fn find(parent: ptr<function, array<u32, 16>>, x0: u32) -> u32 {
    var x = x0;
    while (*parent)[x] != x {
        (*parent)[x] = (*parent)[(*parent)[x]];
        x = (*parent)[x];
    }
    return x;
}



// A world's contacts as the solve starts (`begin_world`): contacts, the
// moving-body mask, the flags of world_contacts, islands, the deepest
// penetration; `handed`: the world has friction
// and went to world_friction (or was flagged NOT_SOLVED without it).
struct Begun {
    count: u32,
    moving: u32,
    flags: u32,
    islands: u32,
    max_penetration: Scalar,
    handed: bool,
}

// World w's islands (each contact's in its key's fourth word) and its
// deepest penetration; its velocities v* into lin, ang (assembly's v_rel). A world with friction (a contact with μ > 0: Scene::has_friction)
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
    for (var c = 0u; c < count; c++) {
        let key = sp.keys_at + 4u * (slot0 + c);
        let a = words[key];
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
    return Begun(count, moving, flags, islands, max_penetration, handed);
}


// Step part 2 up to the solve for world w: its islands, each assembled
// and kept (`keep_rows`) in island order; an island above ISLAND_MAX
// contacts flags the world (ISLAND_TOO_LARGE; the islands after it are
// not assembled), as does friction without the frictional phase
// (NOT_SOLVED). A world with friction is handed to world_friction.
@compute @workgroup_size(64)
fn world_assemble(@builtin(global_invocation_id) gid: vec3<u32>) {
    let w = gid.x;
    if w >= sp.count {
        return;
    }
    let b = begin_world(w);
    records[w * REC + 2u] = b.max_penetration;
    if b.handed {
        return;
    }
    var flags = b.flags;
    var members: array<u32, 16>;
    for (var isl = 0u; isl < b.islands && flags == 0u; isl++) {
        let n = island_members(w, b.count, isl, &members);
        if n > ISLAND_MAX {
            flags |= ISLAND_TOO_LARGE;
            break;
        }
        for (var i = 0u; i < n; i++) {
            assemble_contact(w * sp.slots + members[i], i, worlds[w].x, b.moving);
        }
        fill_matrix(n);
        keep_rows(w, n, &members);
    }
    words[sp.out_at + 4u * w + 2u] = flags;
}
