// Box–box pairs: separating axes, the reference face's clipping, edge
// against edge (CPU twin: src/world/collide_box.rs, same names). The
// composition (src/gpu/shaders/compose.rs) splices this file into
// shaders/collide.wgsl at its `// BOX-BOX` line.

// The projection radius of box p (half extents h) on unit u.
fn radius(p: Placed, h: vec3<Scalar>, u: vec3<Scalar>) -> Scalar {
    return h.x * abs(dot3(p.c0, u)) + h.y * abs(dot3(p.c1, u)) + h.z * abs(dot3(p.c2, u));
}

// best_axis's answer: kind 0 (some axis separates by ≥ margin), 1 (face i
// of x where of_x, else of y), 2 (edge i of x against edge j of y; unit
// axis from x towards y).
struct Axis {
    kind: u32,
    of_x: bool,
    i: u32,
    j: u32,
    axis: vec3<Scalar>,
}

const AXIS_NONE: u32 = 0u;
const AXIS_FACE: u32 = 1u;
const AXIS_EDGE: u32 = 2u;

// The best separating axis (see collide_box.rs best_axis).
fn best_axis(x: Placed, hx: vec3<Scalar>, y: Placed, hy: vec3<Scalar>, margin: Scalar) -> Axis {
    let d = y.centre - x.centre;
    var face = Axis(AXIS_NONE, false, 0u, 0u, vec3<Scalar>(Scalar(0.0)));
    var face_sep = Scalar(0.0);
    let tol = Scalar(1e-3) * max(max_element(hx), max_element(hy));
    for (var f = 0u; f < 6u; f++) {
        let of_x = f < 3u;
        let i = f % 3u;
        var u = col(y, i);
        if of_x {
            u = col(x, i);
        }
        let sep = abs(dot3(d, u)) - radius(x, hx, u) - radius(y, hy, u);
        if sep >= margin {
            return Axis(AXIS_NONE, false, 0u, 0u, vec3<Scalar>(Scalar(0.0)));
        }
        // x's faces first; y's face only when clearly better.
        var better: bool;
        if face.kind == AXIS_NONE {
            better = true;
        } else if face.of_x && !of_x {
            better = sep > Scalar(0.98) * face_sep + tol;
        } else {
            better = sep > face_sep;
        }
        if better {
            face = Axis(AXIS_FACE, of_x, i, 0u, vec3<Scalar>(Scalar(0.0)));
            face_sep = sep;
        }
    }
    var edge = Axis(AXIS_NONE, false, 0u, 0u, vec3<Scalar>(Scalar(0.0)));
    var edge_sep = Scalar(0.0);
    for (var e = 0u; e < 9u; e++) {
        let i = e / 3u;
        let j = e % 3u;
        let c = cross3(col(x, i), col(y, j));
        let len = length3(c);
        if len < Scalar(1e-6) {
            continue; // parallel edges: a face axis covers them
        }
        var u = c / len;
        if dot3(u, d) < Scalar(0.0) {
            u = -u;
        }
        let sep = dot3(d, u) - radius(x, hx, u) - radius(y, hy, u);
        if sep >= margin {
            return Axis(AXIS_NONE, false, 0u, 0u, vec3<Scalar>(Scalar(0.0)));
        }
        if edge.kind == AXIS_NONE || sep > edge_sep {
            edge = Axis(AXIS_EDGE, false, i, j, u);
            edge_sep = sep;
        }
    }
    if edge.kind == AXIS_EDGE && edge_sep > Scalar(0.98) * face_sep + tol {
        return edge;
    }
    return face;
}

// Box x against box y, normals from y to x. The face of either box goes
// through one call of face_contact, its reference box chosen first
// (llvmpipe runs both sides of every branch under a mask: two calls would
// cost two).
fn box_box(x: Placed, hx: vec3<Scalar>, y: Placed, hy: vec3<Scalar>, margin: Scalar) -> Manifold {
    let a = best_axis(x, hx, y, hy, margin);
    if a.kind == AXIS_FACE {
        let ref_is_y = !a.of_x;
        var re = x;
        var hr = hx;
        var inc = y;
        var hi = hy;
        if ref_is_y {
            re = y;
            hr = hy;
            inc = x;
            hi = hx;
        }
        return face_contact(re, hr, inc, hi, a.i, margin, ref_is_y);
    }
    if a.kind == AXIS_EDGE {
        return edge_contact(x, hx, y, hy, a.i, a.j, a.axis, margin);
    }
    return Manifold();
}

// A convex polygon of at most 8 tagged points (which incident vertex, or
// which side plane cut which edge); `overflow` set by a push past 8.
struct Polygon {
    points: array<vec3<Scalar>, 8>,
    tags: array<u32, 8>,
    len: u32,
    overflow: bool,
}

// Appends p (tag) by a ladder over the slots (see push_hit).
fn push_point(poly: ptr<function, Polygon>, p: vec3<Scalar>, tag: u32) {
    if (*poly).len < 8u {
        for (var s = 0u; s < 8u; s++) { // UNROLL
            if (*poly).len == s {
                (*poly).points[s] = p;
                (*poly).tags[s] = tag;
            }
        }
        (*poly).len += 1u;
    } else {
        (*poly).overflow = true;
    }
}

// Point k of poly (k < 8) and its tag, read by a ladder over the slots.
fn point_at(poly: Polygon, k: u32) -> vec3<Scalar> {
    var p = poly.points[0];
    for (var s = 1u; s < 8u; s++) { // UNROLL
        if k == s {
            p = poly.points[s];
        }
    }
    return p;
}

fn tag_at(poly: Polygon, k: u32) -> u32 {
    var t = poly.tags[0];
    for (var s = 1u; s < 8u; s++) { // UNROLL
        if k == s {
            t = poly.tags[s];
        }
    }
    return t;
}

// Sutherland–Hodgman with a tolerance: the part of `poly` with pn·p ≤ off,
// a vertex outside by at most `tol` kept as it is. A point made on the
// plane is tagged 4 + 4·side + (the edge's first vertex's tag mod 4).
fn clip(poly: Polygon, pn: vec3<Scalar>, off: Scalar, tol: Scalar, side: u32) -> Polygon {
    var out = Polygon();
    out.overflow = poly.overflow;
    // Points read through point_at (see push_hit).
    for (var k = 0u; k < poly.len; k++) {
        let p = point_at(poly, k);
        let tp = tag_at(poly, k);
        let q = point_at(poly, (k + 1u) % poly.len);
        let dp = dot3(pn, p) - off;
        let dq = dot3(pn, q) - off;
        if dp <= tol {
            push_point(&out, p, tp);
        }
        // Crossing: the kept end is inside (d ≤ 0), the other beyond tol.
        if (dp <= tol) != (dq <= tol) && min(dp, dq) <= Scalar(0.0) {
            let t = dp / (dp - dq);
            push_point(&out, p + (q - p) * t, 4u + 4u * side + (tp & 3u));
        }
    }
    return out;
}

// The incident face of box `inc` clipped by the side planes of face `axis`
// of box `re` (the reference); normals from y to x.
fn face_contact(re: Placed, hr: vec3<Scalar>, inc: Placed, hi: vec3<Scalar>, axis: u32, margin: Scalar, ref_is_y: bool) -> Manifold {
    let d = inc.centre - re.centre;
    var n = col(re, axis);
    let flipped = dot3(n, d) < Scalar(0.0);
    let ref_face = 2u * axis + select(0u, 1u, flipped);
    if flipped {
        n = -n;
    }
    // Incident face: the face of inc most anti-parallel to n (max_by: the
    // last of equals).
    let dots = vec3<Scalar>(dot3(inc.c0, n), dot3(inc.c1, n), dot3(inc.c2, n));
    var k = 0u;
    for (var m = 1u; m < 3u; m++) {
        if !total_less(abs(dots[m]), abs(dots[k])) {
            k = m;
        }
    }
    let s = select(Scalar(1.0), Scalar(-1.0), dots[k] > Scalar(0.0));
    let inc_face = 2u * k + select(0u, 1u, s < Scalar(0.0));
    let u = (k + 1u) % 3u;
    let v = (k + 2u) % 3u;
    let fc = inc.centre + col(inc, k) * (s * hi[k]);
    let eu = col(inc, u) * hi[u];
    let ev = col(inc, v) * hi[v];
    var poly = Polygon();
    push_point(&poly, fc + eu + ev, 0u);
    push_point(&poly, fc - eu + ev, 1u);
    push_point(&poly, fc - eu - ev, 2u);
    push_point(&poly, fc + eu - ev, 3u);
    // Side planes of the reference face: ±t at distance h_t from the centre.
    let tol = CLIP_TOL * max_element(hr);
    var side = 0u;
    for (var t = 0u; t < 3u; t++) {
        if t == axis {
            continue;
        }
        for (var sg = 0u; sg < 2u; sg++) {
            let pn = col(re, t) * select(Scalar(-1.0), Scalar(1.0), sg == 0u);
            let off = dot3(pn, re.centre) + hr[t];
            poly = clip(poly, pn, off, tol, side);
            side += 1u;
        }
    }
    let face_point = re.centre + n * hr[axis];
    var normal = -n;
    if ref_is_y {
        normal = n;
    }
    let base = (select(0u, 1u, ref_is_y) << 11u) | (ref_face << 8u) | (inc_face << 5u);
    var hits = Manifold();
    hits.overflow = poly.overflow;
    for (var m = 0u; m < poly.len; m++) {
        let p = point_at(poly, m);
        let gap = dot3(n, p - face_point);
        if gap < margin {
            push_hit(&hits, Hit(p - n * (Scalar(0.5) * gap), normal, gap, base | (tag_at(poly, m) & 31u)));
        }
    }
    return reduce_to_four(hits);
}

// Edge i of x against edge j of y along `axis` (from x to y): the closest
// points of the two supporting edges, one contact.
fn edge_contact(x: Placed, hx: vec3<Scalar>, y: Placed, hy: vec3<Scalar>, i: u32, j: u32, axis: vec3<Scalar>, margin: Scalar) -> Manifold {
    // The edge of x farthest along the axis, the edge of y farthest against it.
    var pa = x.centre;
    var pb = y.centre;
    for (var k = 0u; k < 3u; k++) {
        if k != i {
            let c = col(x, k);
            pa += c * (hx[k] * signum(dot3(c, axis)));
        }
        if k != j {
            let c = col(y, k);
            pb -= c * (hy[k] * signum(dot3(c, axis)));
        }
    }
    let da = col(x, i);
    let db = col(y, j);
    // Closest points of the lines pa + s da and pb + t db (unit directions).
    let r = pa - pb;
    let b = dot3(da, db);
    let denom = Scalar(1.0) - b * b;
    let c = dot3(da, r);
    let f = dot3(db, r);
    var s = Scalar(0.0);
    if denom > Scalar(1e-12) {
        s = clamp((b * f - c) / denom, -hx[i], hx[i]);
    }
    let t = clamp(b * s + f, -hy[j], hy[j]);
    let qa = pa + da * s;
    let qb = pb + db * t;
    let gap = dot3(qb - qa, axis);
    if gap >= margin {
        return Manifold();
    }
    return one_hit(Hit((qa + qb) * Scalar(0.5), -axis, gap, (7u << 8u) | (3u * i + j)));
}
