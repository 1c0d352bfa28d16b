// The collision phase of the resident step (shaders/world_step.wgsl's
// header; composed after it and every function of shaders/collide.wgsl):
// the entry points `candidate_pairs`, `narrow_box_box`,
// `narrow_box_plane`, `narrow_sphere` and `world_contacts`.
//
// Step part 1 (step.rs prepare without impacts: restitution 0): v* = v +
// Δt g for the awake dynamic bodies, then world_contacts: candidate pairs
// (broad.rs candidate_pairs: boxes grown by half the margin plus the reach,
// planes with every movable body; all pairs, in the sweep's sorted order
// i < j), the narrow phase with margin + both reaches, sleeping bodies
// woken by an awake one's contact (their v* = Δt g), until none wakes.
//
// In five dispatches, for llvmpipe, which runs every branch of an
// invocation under a mask and every loop as often as its busiest lane, and
// for drivers whose compilers balk at one large entry point:
// `candidate_pairs` (per world) lists the candidates in pair order, less
// box–plane pairs that cannot touch (box_far_from_plane), and of those
// that an awake body can reach through candidates (those world_contacts
// may collide: a pair's manifold depends on the poses and reaches only,
// not on when it is collided) lists each in its family's work list
// (box–box, box–plane, with a sphere); the narrow phase per family
// (`narrow_box_box`, `narrow_box_plane`, `narrow_sphere`: per listed pair,
// indirect dispatches over the lists) keeps each manifold in the pair
// records; `world_contacts` (per world) runs world_contacts' rounds over
// the candidates in pair order, taking the kept manifolds: the same
// contacts in the same order as collided there.

// A candidate's count word (keep_manifold) with the narrow phase's loops
// cut short by llvmpipe's loop limit (`loops_left`): the world is flagged
// BUDGET.
const CUT: u32 = 0x40000000u;

// World w's candidates in `words`: their count, then per candidate c its
// bodies (i | j << 8), then per candidate its count word (keep_manifold).
fn cands_of(w: u32) -> u32 {
    return sp.cands_at + w * (1u + 2u * pairs_per_world());
}

// An axis-aligned box (broad.rs Aabb::of): `ok` false for a plane.
struct Aabb {
    lo: vec3<Scalar>,
    hi: vec3<Scalar>,
    ok: bool,
}

fn aabb_of(p: Placed, margin: Scalar) -> Aabb {
    var half = vec3<Scalar>(p.size.x, p.size.x, p.size.x);
    if p.kind == KIND_PLANE {
        return Aabb(p.centre, p.centre, false);
    }
    if p.kind == KIND_BOX {
        let h = p.size;
        // |R| h by rows of R (the columns' components).
        half = vec3<Scalar>(
            dot3(abs(vec3<Scalar>(p.c0.x, p.c1.x, p.c2.x)), h),
            dot3(abs(vec3<Scalar>(p.c0.y, p.c1.y, p.c2.y)), h),
            dot3(abs(vec3<Scalar>(p.c0.z, p.c1.z, p.c2.z)), h),
        );
    }
    half += vec3<Scalar>(margin, margin, margin);
    return Aabb(p.centre - half, p.centre + half, true);
}

fn overlaps(a: Aabb, b: Aabb) -> bool {
    return all(a.lo <= b.hi) && all(b.lo <= a.hi);
}

// A box and a plane too far apart for any corner to come within `margin`
// (box_plane would find nothing): the centre's height over the plane less
// the box's half diagonal, with a slack above the rounding of box_plane's
// corners (relative to the coordinates' size), at least `margin`.
fn box_far_from_plane(b: Placed, p: Placed, margin: Scalar) -> bool {
    let n = p.size;
    let height = dot3(n, b.centre - p.centre);
    let reach = length3(b.size) * length3(n);
    let size = dot3(abs(n), abs(b.centre) + abs(p.centre)) + reach + abs(margin);
    return height - reach >= margin + Scalar(64.0) * SCALAR_EPSILON * size;
}

// collide.wgsl's collide_shapes for a pair with a sphere: the sphere as
// the first shape, the same calls; the caller flips the normals where the
// sphere was the pair's second shape (collide_shapes' flip).
fn collide_sphere(s: Placed, o: Placed, margin: Scalar) -> Manifold {
    if o.kind == KIND_PLANE {
        return sphere_plane(s.centre, s.size.x, o.centre, o.size, margin);
    }
    if o.kind == KIND_SPHERE {
        return sphere_sphere(s.centre, s.size.x, o.centre, o.size.x, margin);
    }
    return sphere_box(s.centre, s.size.x, o, o.size, margin);
}

// Keeps candidate c's manifold (normals reversed where `flipped`) in world
// w's pair records: its first SLOTS hits (point, normal, gap, feature); returns
// its count word (length | OVERFLOW where the manifold overflowed).
fn keep_manifold(w: u32, c: u32, m: Manifold, flipped: bool) -> u32 {
    // Each index a constant (collide.wgsl push_hit).
    for (var h = 0u; h < SLOTS; h++) { // UNROLL
        if h < min(m.len, SLOTS) {
            let hit = m.hits[h];
            let at = sp.pairs_at + (w * sp.pair_slots + SLOTS * c + h) * CP;
            put_scratch(at, hit.point);
            put_scratch(at + 3u, select(hit.normal, -hit.normal, flipped));
            scratch[at + 6u] = hit.gap;
            scratch[at + 7u] = Scalar(hit.feature);
        }
    }
    return m.len | select(0u, OVERFLOW, m.overflow);
}

@compute @workgroup_size(64)
fn candidate_pairs(@builtin(global_invocation_id) gid: vec3<u32>) {
    let w = gid.x;
    if w == 0u {
        // No world left to world_lemke yet this step.
        clear_list(LIST_LEMKE);
    }
    if w >= sp.count {
        return;
    }
    let info = worlds[w];
    let first = info.x;
    let nb = min(info.y, MAX_BODIES);
    let g = vec3_at_consts(w * WC);
    let margin = consts[w * WC + 3u];
    let dt = sp.dt;
    var placed: array<Placed, 16>;
    var boxes: array<Aabb, 16>;
    var reach: array<Scalar, 16>;
    var awake_mask = 0u;
    var movable = 0u;
    for (var k = 0u; k < nb; k++) {
        let b = first + k;
        let awake = !is_static(b) && !asleep(b);
        let o = b * BS;
        var lin = vec3_at_state(o + 7u);
        let ang = vec3_at_state(o + 10u);
        if awake {
            lin = lin + g * dt;
            awake_mask |= 1u << k;
            reach[k] = (length3(lin) + length3(ang) * body_const(b, 10u)) * dt;
        } else {
            reach[k] = Scalar(0.0);
        }
        if !is_static(b) {
            movable |= 1u << k;
        }
        scratch[sp.reach_at + b] = reach[k];
        put_scratch(6u * b, lin);
        put_scratch(6u * b + 3u, ang);
        placed[k] = placed_body(b);
        boxes[k] = aabb_of(placed[k], reach[k] + Scalar(0.5) * margin);
    }
    // Candidates, packed i | j << 8.
    let at = cands_of(w);
    let got_at = at + 1u + pairs_per_world();
    var nc = 0u;
    for (var i = 0u; i < nb; i++) {
        for (var j = i + 1u; j < nb; j++) {
            let bi = boxes[i];
            let bj = boxes[j];
            let either = ((movable >> i) | (movable >> j)) & 1u;
            var candidate = false;
            if bi.ok && bj.ok {
                candidate = either != 0u && overlaps(bi, bj);
            } else if bi.ok != bj.ok {
                // A plane with a movable bounded body.
                let other = select(i, j, bj.ok);
                let plane = select(j, i, bj.ok);
                candidate = ((movable >> other) & 1u) != 0u;
                if placed[other].kind == KIND_BOX {
                    let pm = margin + reach[i] + reach[j];
                    candidate = candidate && !box_far_from_plane(placed[other], placed[plane], pm);
                }
            }
            if candidate {
                words[at + 1u + nc] = i | (j << 8u);
                words[got_at + nc] = 0u;
                nc++;
            }
        }
    }
    words[at] = nc;
    // Bodies an awake body can reach through candidates.
    var live = awake_mask;
    loop {
        let before = live;
        for (var c = 0u; c < nc; c++) {
            let ij = words[at + 1u + c];
            let pair = (1u << (ij & 0xffu)) | (1u << (ij >> 8u));
            if (live & pair) != 0u {
                live |= movable & pair;
            }
        }
        if live == before {
            break;
        }
    }
    // Their candidates, each to its family's list.
    for (var c = 0u; c < nc; c++) {
        let ij = words[at + 1u + c];
        let i = ij & 0xffu;
        let j = ij >> 8u;
        if (live & ((1u << i) | (1u << j))) == 0u {
            continue;
        }
        let ki = placed[i].kind;
        let kj = placed[j].kind;
        var f = LIST_SPHERE;
        if ki == KIND_BOX && kj == KIND_BOX {
            f = LIST_BOX_BOX;
        } else if ki != KIND_SPHERE && kj != KIND_SPHERE {
            f = LIST_BOX_PLANE;
        }
        push_list(f, (w << 8u) | c);
    }
    let out = sp.out_at + 4u * w;
    words[out] = 0u;
    words[out + 1u] = awake_mask;
    words[out + 2u] = select(0u, BUDGET, !loops_left());
    words[out + 3u] = 0u;
}

// A listed pair of list f (`push_list`): its world, its candidate index,
// its bodies (world indices i < j), the world's first body and the
// narrow phase's margin (the world's margin + both reaches).
struct ListedPair {
    w: u32,
    c: u32,
    i: u32,
    j: u32,
    first: u32,
    margin: Scalar,
}

fn listed_pair(f: u32, t: u32) -> ListedPair {
    let entry = atomicLoad(&lists[list_at(f) + t]);
    let w = entry >> 8u;
    let c = entry & 0xffu;
    let ij = words[cands_of(w) + 1u + c];
    let i = ij & 0xffu;
    let j = ij >> 8u;
    let first = worlds[w].x;
    let margin = consts[w * WC + 3u] + scratch[sp.reach_at + first + i] + scratch[sp.reach_at + first + j];
    return ListedPair(w, c, i, j, first, margin);
}

// Keeps listed pair p's manifold (keep_manifold) and its count word, CUT
// set where llvmpipe's loop limit was reached.
fn keep_listed(p: ListedPair, m: Manifold, flipped: bool) {
    var got = keep_manifold(p.w, p.c, m, flipped);
    if !loops_left() {
        got |= CUT;
    }
    words[cands_of(p.w) + 1u + pairs_per_world() + p.c] = got;
}

@compute @workgroup_size(64)
fn narrow_box_box(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= atomicLoad(&lists[4u * LIST_BOX_BOX + 3u]) {
        return;
    }
    let p = listed_pair(LIST_BOX_BOX, gid.x);
    let x = placed_body(p.first + p.i);
    let y = placed_body(p.first + p.j);
    keep_listed(p, box_box(x, x.size, y, y.size, p.margin), false);
}

@compute @workgroup_size(64)
fn narrow_box_plane(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= atomicLoad(&lists[4u * LIST_BOX_PLANE + 3u]) {
        return;
    }
    let p = listed_pair(LIST_BOX_PLANE, gid.x);
    // collide_shapes: box_plane with the box first, flipped where the
    // plane was the first shape.
    let x = placed_body(p.first + p.i);
    let y = placed_body(p.first + p.j);
    if x.kind == KIND_PLANE {
        keep_listed(p, box_plane(y, y.size, x.centre, x.size, p.margin), true);
    } else {
        keep_listed(p, box_plane(x, x.size, y.centre, y.size, p.margin), false);
    }
}

@compute @workgroup_size(64)
fn narrow_sphere(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= atomicLoad(&lists[4u * LIST_SPHERE + 3u]) {
        return;
    }
    let p = listed_pair(LIST_SPHERE, gid.x);
    let x = placed_body(p.first + p.i);
    let y = placed_body(p.first + p.j);
    // collide_shapes: the sphere first, flipped where it was the second
    // shape.
    if x.kind != KIND_SPHERE {
        keep_listed(p, collide_sphere(y, x, p.margin), true);
    } else {
        keep_listed(p, collide_sphere(x, y, p.margin), false);
    }
}

// world_contacts' rounds for world w over its candidates in pair order,
// taking the kept manifolds: contacts into the world's slots (the dynamic
// body first), sleeping bodies woken by an awake one's contact.
@compute @workgroup_size(64)
fn world_contacts(@builtin(global_invocation_id) gid: vec3<u32>) {
    let w = gid.x;
    if w == 0u {
        // The pair lists, empty for the next step's candidate_pairs.
        clear_list(LIST_BOX_BOX);
        clear_list(LIST_BOX_PLANE);
        clear_list(LIST_SPHERE);
    }
    if w >= sp.count {
        return;
    }
    let info = worlds[w];
    let first = info.x;
    let nb = min(info.y, MAX_BODIES);
    let g = vec3_at_consts(w * WC);
    let dt = sp.dt;
    let out = sp.out_at + 4u * w;
    var awake_mask = words[out + 1u];
    var flags = words[out + 2u];
    var movable = 0u;
    for (var k = 0u; k < nb; k++) {
        if !is_static(first + k) {
            movable |= 1u << k;
        }
    }
    let at = cands_of(w);
    let got_at = at + 1u + pairs_per_world();
    let nc = words[at];
    var done: array<u32, 4>;
    var count = 0u;
    var spent = 0u;
    let slot0 = w * sp.slots;
    loop {
        var woke = false;
        for (var c = 0u; c < nc; c++) {
            let ij = words[at + 1u + c];
            let i = ij & 0xffu;
            let j = ij >> 8u;
            spent += 1u;
            let bit = 1u << (c & 31u);
            let seen = (done[c >> 5u] & bit) != 0u;
            let on = (((awake_mask >> i) | (awake_mask >> j)) & 1u) != 0u;
            if seen || !on {
                continue;
            }
            done[c >> 5u] |= bit;
            let got = words[got_at + c];
            if (got & CUT) != 0u {
                flags |= BUDGET;
            }
            let len = got & ~(OVERFLOW | CUT);
            if len == 0u {
                continue;
            }
            for (var s = 0u; s < 2u; s++) {
                let x = select(i, j, s == 1u);
                if ((movable >> x) & 1u) != 0u && ((awake_mask >> x) & 1u) == 0u {
                    awake_mask |= 1u << x;
                    // step.rs prepare: a woken body's v* is Δt g.
                    put_scratch(6u * (first + x), g * dt);
                    put_scratch(6u * (first + x) + 3u, vec3<Scalar>(0.0, 0.0, 0.0));
                    woke = true;
                }
            }
            if (got & OVERFLOW) != 0u || len > SLOTS {
                flags |= CONTACTS_FULL;
            }
            // The dynamic body is a (normal from b to a).
            let swap = is_static(first + i);
            for (var h = 0u; h < min(len, SLOTS); h++) {
                if count >= sp.slots {
                    flags |= CONTACTS_FULL;
                    break;
                }
                let kept = sp.pairs_at + (w * sp.pair_slots + SLOTS * c + h) * CP;
                let normal = vec3_at_scratch(kept + 3u);
                let slot = slot0 + count;
                count++;
                let to = sp.contacts_at + slot * CP;
                put_scratch(to, vec3_at_scratch(kept));
                put_scratch(to + 3u, select(normal, -normal, swap));
                scratch[to + 6u] = scratch[kept + 6u];
                scratch[to + 7u] = Scalar(0.0);
                let a = select(i, j, swap);
                let b = select(j, i, swap);
                let key = sp.keys_at + 4u * slot;
                words[key] = a;
                words[key + 1u] = b;
                words[key + 2u] = u32(scratch[kept + 7u]);
                words[key + 3u] = 0u;
            }
        }
        if !woke || spent > sp.budget {
            break;
        }
    }
    if spent > sp.budget || !loops_left() {
        flags |= BUDGET;
    }
    words[out] = count;
    words[out + 1u] = awake_mask;
    words[out + 2u] = flags;
    words[out + 3u] = 0u;
}
