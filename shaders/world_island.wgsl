// An island of the resident step's solve (shaders/world_step.wgsl's
// header; composed after it and world_bodies.wgsl, before world_solve.wgsl
// or world_lemke.wgsl, each a module of its own): the island's M and q as
// world_assemble kept them, the basis solve, the door's check, its answer
// kept in its contact slots, and the end of a solve dispatch for a world.

// The island's q and answer z (row i at i); its M (row i at ISLAND_MAX i);
// w = M z + q of the last check; the basis solve's x over cand.
var<private> qv: array<Scalar, 16>;
var<private> zv: array<Scalar, 16>;
var<private> mm: array<Scalar, 256>;
var<private> wv: array<Scalar, 16>;
var<private> xs: array<Scalar, 16>;

// Island `isl` of world w (`count` contacts): its members (island_members)
// and its M and q from their contact slots (world_assemble.wgsl
// keep_rows); its size (at most ISLAND_MAX: world_assemble flagged the
// world otherwise).
fn load_island(w: u32, count: u32, isl: u32, members: ptr<function, array<u32, 16>>) -> u32 {
    let n = island_members(w, count, isl, members);
    let slot0 = w * sp.slots;
    for (var i = 0u; i < n; i++) {
        let r = row_at(slot0 + (*members)[i]);
        qv[i] = scratch[r];
        for (var j = 0u; j < n; j++) {
            mm[ISLAND_MAX * i + j] = scratch[r + 13u + j];
        }
    }
    return n;
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

// The island's answer zv kept in its contact slots (world_finish.wgsl
// applies it); its basis (bit i: row i basic) as the world's bases (bit c:
// contact c basic, c < 32).
fn keep_island(w: u32, n: u32, members: ptr<function, array<u32, 16>>, basis: u32) -> u32 {
    let slot0 = w * sp.slots;
    var bases = 0u;
    for (var i = 0u; i < n; i++) {
        let m = (*members)[i];
        bases |= select(0u, ((basis >> i) & 1u) << m, m < 32u);
        scratch[sp.contacts_at + (slot0 + m) * CP + 7u] = zv[i];
    }
    return bases;
}

// The end of a solve dispatch for world w: the flags (BUDGET where
// llvmpipe's loop limit was reached in this dispatch), the warm-start ids
// forgotten (-1: no warm bases next step) where the world is flagged, its
// bases so far (bit c: contact c basic), its largest error so far. The
// flags.
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
    words[sp.out_at + 4u * w + 2u] = flags;
    return flags;
}

// The Lemke list's second word: bit i for island i (i < ISLAND_MAX), and
// WARM_TRIED where the world's warm bases were tried first.
const WARM_TRIED: u32 = 0x80000000u;

// Entry k of the Lemke list (world_solve.wgsl defer_world): the world and
// its listed islands; (NONE, 0) past the list's end (the indirect
// dispatch's last workgroup).
fn lemke_entry(k: u32) -> vec2<u32> {
    if k >= atomicLoad(&lists[4u * LIST_LEMKE + 3u]) {
        return vec2<u32>(NONE, 0u);
    }
    let at = list_at(LIST_LEMKE) + 2u * k;
    return vec2<u32>(atomicLoad(&lists[at]), atomicLoad(&lists[at + 1u]));
}
