// An island of the resident step's solve (shaders/world_step.wgsl's
// header; composed after it and world_bodies.wgsl, before world_solve.wgsl
// or world_lemke.wgsl, each a module of its own): one island's contacts
// and rows (assembly), its M, the basis solve, the door's check, the
// impulses, and the end of a solve dispatch for a world.

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

// Block principal pivots tried from the warm basis (world_cpu.rs
// WARM_PIVOTS).
const WARM_PIVOTS: u32 = 3u;

// Island `isl` of world w (`count` contacts): its contacts (indices in
// the world) into `members` (the first ISLAND_MAX); its size.
fn island_members(w: u32, count: u32, isl: u32, members: ptr<function, array<u32, 16>>) -> u32 {
    let slot0 = w * sp.slots;
    var n = 0u;
    for (var c = 0u; c < count; c++) {
        if words[sp.keys_at + 4u * (slot0 + c) + 3u] == isl {
            if n < ISLAND_MAX {
                (*members)[n] = c;
            }
            n++;
        }
    }
    return n;
}

// Island `isl` of world w (`count` contacts, moving-body mask `moving`):
// its contacts into `members`, assembled (assemble_contact, fill_matrix);
// its size, above ISLAND_MAX where it is too large (nothing assembled
// then).
fn island_rows(w: u32, count: u32, moving: u32, isl: u32, members: ptr<function, array<u32, 16>>) -> u32 {
    let n = island_members(w, count, isl, members);
    if n > ISLAND_MAX {
        return n;
    }
    let slot0 = w * sp.slots;
    for (var i = 0u; i < n; i++) {
        assemble_contact(slot0 + (*members)[i], i, worlds[w].x, moving);
    }
    fill_matrix(n);
    return n;
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

// The end of a solve dispatch for world w: the flags (BUDGET where
// llvmpipe's loop limit was reached in this dispatch), the warm-start ids
// forgotten (-1: no warm bases next step) where the world is flagged, its
// bases so far (bit c: contact c basic), its largest error so far, the
// velocities after the impulses (for the next solve dispatch and
// world_finish). The flags.
fn end_solve(w: u32, flags0: u32, bases: u32, max_error: Scalar) -> u32 {
    var flags = flags0;
    if flags == 0u && !loops_left() {
        flags = BUDGET;
    }
    let rec = w * REC;
    if flags != 0u {
        records[rec + 6u] = Scalar(-1.0);
    }
    records[rec + 7u] = Scalar(bases);
    records[rec + 3u] = max_error;
    store_velocities(w);
    words[sp.out_at + 4u * w + 2u] = flags;
    return flags;
}

// The Lemke list's second word: bit i for island i (i < ISLAND_MAX), and
// WARM_TRIED where the world's warm bases were tried first.
const WARM_TRIED: u32 = 0x80000000u;
