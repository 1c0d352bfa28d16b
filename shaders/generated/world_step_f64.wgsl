// GENERATED from shaders/collide.wgsl (functions) + shaders/lemke.wgsl (functions) + shaders/world_step.wgsl + shaders/world_solve.wgsl + shaders/world_friction.wgsl + shaders/world_apgd.wgsl + shaders/friction_common.wgsl (project_on_cone on) by src/gpu/shaders/compose.rs: do not edit.
// Regenerate: LCPBATCH_BLESS_SHADERS=1 cargo test --release generated_shaders_are_committed

// Narrow phase: the contact points of candidate pairs of bodies (entry
// point `collide_pairs`, one invocation per pair). CPU twins:
// src/world/collide.rs (collide_shapes, sphere_plane, sphere_sphere,
// corners, box_plane, sphere_box, reduce_to_four) and
// src/world/collide_box.rs (radius, best_axis, box_box, face_contact, clip,
// edge_contact): the same names, the same operations in the same order
// (glam's: dot (x·x' + y·y') + z·z', M v = (c0 v.x + c1 v.y) + c2 v.z,
// Mᵀ v by columns' dots, the quaternion normalised then turned into a
// matrix as DMat3::from_quat does), the same tolerances, margins and
// feature ids; ties broken as Rust's min_by (first) and max_by (last)
// with f64::total_cmp (−0 before +0), and f64::signum's sign of a zero.
//
// The functions up to the stage's bindings take values only, so that a
// kernel stepping resident worlds can call them on its own buffers.
//
// Packed layouts (src/gpu/collide.rs): body BODY = 12 scalars (position,
// orientation quaternion x, y, z, w (normalised here, as RigidBody::rotation
// does), shape kind (0 sphere, 1 box, 2 plane), shape parameters (radius,
// 0, 0 | half extents | plane normal), static flag (1: static)); per pair
// its bodies (i, j) and its margin; out, SLOTS = 4 contact slots per pair
// (point, normal, gap, pad: POINT = 8 scalars; keys a, b, feature, 0) and
// a count per pair: the manifold's points, with OVERFLOW set where they did
// not fit (more than SLOTS, or a manifold or clipped polygon past its
// capacity; the CPU twins never make one), so nothing is cut silently.
//
// The generator (src/gpu/shaders/compose.rs) replaces the line marked HOST
// (scalar type) and writes shaders/generated/<name>_f32.wgsl and _f64.wgsl.

alias Scalar = f64; // HOST scalar

const BODY: u32 = 12u;
const KIND_SPHERE: u32 = 0u;
const KIND_BOX: u32 = 1u;
const KIND_PLANE: u32 = 2u;
// Manifold::CAPACITY: 8 box corners; a face quad clipped by 4 side planes.
const CAPACITY: u32 = 8u;
// Contact slots per pair: every manifold is reduced to at most 4 points.
const SLOTS: u32 = 4u;
const POINT: u32 = 8u;
const OVERFLOW: u32 = 0x80000000u;
// collide_box.rs CLIP_TOL: of the reference box's largest half extent.
const CLIP_TOL: Scalar = 1e-7;

// A shape placed in the world (collide.rs Placed): the rotation by its
// columns (the body's axes); `size` is the radius (x), the half extents or
// the plane's normal.
struct Placed {
    kind: u32,
    size: vec3<Scalar>,
    centre: vec3<Scalar>,
    c0: vec3<Scalar>,
    c1: vec3<Scalar>,
    c2: vec3<Scalar>,
}

struct Hit {
    point: vec3<Scalar>,
    // From the second shape to the first.
    normal: vec3<Scalar>,
    gap: Scalar,
    feature: u32,
}

// Up to CAPACITY hits; `overflow` set by a push past it.
struct Manifold {
    hits: array<Hit, 8>,
    len: u32,
    overflow: bool,
}

fn push_hit(m: ptr<function, Manifold>, h: Hit) {
    if (*m).len < CAPACITY {
        (*m).hits[(*m).len] = h;
        (*m).len += 1u;
    } else {
        (*m).overflow = true;
    }
}

fn one_hit(h: Hit) -> Manifold {
    var m = Manifold();
    push_hit(&m, h);
    return m;
}

// glam's dot: (x x' + y y') + z z'.
fn dot3(a: vec3<Scalar>, b: vec3<Scalar>) -> Scalar {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

fn length3(a: vec3<Scalar>) -> Scalar {
    return sqrt(dot3(a, a));
}

// glam's cross.
fn cross3(a: vec3<Scalar>, b: vec3<Scalar>) -> vec3<Scalar> {
    return vec3<Scalar>(a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y);
}

// The sign bit of x (f32 keeps it through the conversion; WGSL has no f64
// bitcast).
fn sign_bit(x: Scalar) -> bool {
    return (bitcast<u32>(f32(x)) & 0x80000000u) != 0u;
}

// f64::signum: ±1 by the sign bit, −1 for −0.
fn signum(x: Scalar) -> Scalar {
    return select(Scalar(1.0), Scalar(-1.0), sign_bit(x));
}

// a < b in f64::total_cmp's order (finite values: −0 before +0).
fn total_less(a: Scalar, b: Scalar) -> bool {
    if a != b {
        return a < b;
    }
    return sign_bit(a) && !sign_bit(b);
}

// Column k of p's rotation.
fn col(p: Placed, k: u32) -> vec3<Scalar> {
    if k == 0u {
        return p.c0;
    }
    if k == 1u {
        return p.c1;
    }
    return p.c2;
}

// R v (glam's mul_vec3).
fn rotate(p: Placed, v: vec3<Scalar>) -> vec3<Scalar> {
    return p.c0 * v.x + p.c1 * v.y + p.c2 * v.z;
}

// Rᵀ v (glam's transpose then mul_vec3).
fn unrotate(p: Placed, v: vec3<Scalar>) -> vec3<Scalar> {
    return vec3<Scalar>(dot3(p.c0, v), dot3(p.c1, v), dot3(p.c2, v));
}

// The shape `kind` (`size`) at `centre` turned by the quaternion q
// (x, y, z, w), normalised as DQuat::normalize, as DMat3::from_quat.
fn placed_from(kind: u32, size: vec3<Scalar>, centre: vec3<Scalar>, q0: vec4<Scalar>) -> Placed {
    let len = sqrt(q0.x * q0.x + q0.y * q0.y + q0.z * q0.z + q0.w * q0.w);
    let recip = Scalar(1.0) / len;
    let q = q0 * recip;
    let x2 = q.x + q.x;
    let y2 = q.y + q.y;
    let z2 = q.z + q.z;
    let xx = q.x * x2;
    let xy = q.x * y2;
    let xz = q.x * z2;
    let yy = q.y * y2;
    let yz = q.y * z2;
    let zz = q.z * z2;
    let wx = q.w * x2;
    let wy = q.w * y2;
    let wz = q.w * z2;
    return Placed(
        kind,
        size,
        centre,
        vec3<Scalar>(Scalar(1.0) - (yy + zz), xy + wz, xz - wy),
        vec3<Scalar>(xy - wz, Scalar(1.0) - (xx + zz), yz + wx),
        vec3<Scalar>(xz + wy, yz - wx, Scalar(1.0) - (xx + yy)),
    );
}

fn max_element(h: vec3<Scalar>) -> Scalar {
    return max(h.x, max(h.y, h.z));
}

// Sphere (centre c, radius r) against the plane through p with outward
// normal n: φ = n·(c − p) − r, normal n (plane to sphere).
fn sphere_plane(c: vec3<Scalar>, r: Scalar, p: vec3<Scalar>, n: vec3<Scalar>, margin: Scalar) -> Manifold {
    let gap = dot3(n, c - p) - r;
    if gap >= margin {
        return Manifold();
    }
    return one_hit(Hit(c - n * (r + Scalar(0.5) * gap), n, gap, 0u));
}

// Sphere a against sphere b: φ = |c_a − c_b| − r_a − r_b, normal along
// c_a − c_b (+y when the centres coincide).
fn sphere_sphere(ca: vec3<Scalar>, ra: Scalar, cb: vec3<Scalar>, rb: Scalar, margin: Scalar) -> Manifold {
    let d = ca - cb;
    let dist = length3(d);
    let gap = dist - ra - rb;
    if gap >= margin {
        return Manifold();
    }
    var normal = vec3<Scalar>(Scalar(0.0), Scalar(1.0), Scalar(0.0));
    if dist > Scalar(0.0) {
        normal = d / dist;
    }
    return one_hit(Hit(cb + normal * (rb + Scalar(0.5) * gap), normal, gap, 0u));
}

// The 8 corners of a box (half extents h), corner k having sign −/+ on
// axis i as bit i of k is 0/1.
fn corners(b: Placed, h: vec3<Scalar>) -> array<vec3<Scalar>, 8> {
    var out: array<vec3<Scalar>, 8>;
    for (var k = 0u; k < 8u; k++) {
        let s = vec3<Scalar>(
            select(h.x, -h.x, (k & 1u) == 0u),
            select(h.y, -h.y, (k & 2u) == 0u),
            select(h.z, -h.z, (k & 4u) == 0u),
        );
        out[k] = b.centre + rotate(b, s);
    }
    return out;
}

// Box against the plane through p with outward normal n: every corner
// closer than `margin` (feature: the corner's index), reduced to 4.
fn box_plane(b: Placed, h: vec3<Scalar>, p: vec3<Scalar>, n: vec3<Scalar>, margin: Scalar) -> Manifold {
    var hits = Manifold();
    let vs = corners(b, h);
    for (var k = 0u; k < 8u; k++) {
        let v = vs[k];
        let gap = dot3(n, v - p);
        if gap < margin {
            push_hit(&hits, Hit(v - n * (Scalar(0.5) * gap), n, gap, k));
        }
    }
    return reduce_to_four(hits);
}

// Sphere (centre c, radius r) against a box: the closest point of the box
// to the centre; a centre inside the box leaves through the nearest face.
// Normal from the box to the sphere.
fn sphere_box(c: vec3<Scalar>, r: Scalar, b: Placed, h: vec3<Scalar>, margin: Scalar) -> Manifold {
    let local = unrotate(b, c - b.centre);
    // glam's clamp: max(−h) then min(h).
    let clamped = min(max(local, -h), h);
    var surface: vec3<Scalar>;
    var normal_local = vec3<Scalar>(Scalar(0.0));
    var dist: Scalar;
    if any(clamped != local) {
        let d = local - clamped;
        let len = length3(d);
        surface = clamped;
        normal_local = d / len;
        dist = len;
    } else {
        // Inside: the face with the least depth h_i − |x_i|.
        let depth = h - abs(local);
        var i = 2u;
        if depth.x <= depth.y && depth.x <= depth.z {
            i = 0u;
        } else if depth.y <= depth.z {
            i = 1u;
        }
        let sign = select(Scalar(-1.0), Scalar(1.0), local[i] >= Scalar(0.0));
        surface = local;
        surface[i] = sign * h[i];
        normal_local[i] = sign;
        dist = -depth[i];
    }
    let gap = dist - r;
    if gap >= margin {
        return Manifold();
    }
    let normal = rotate(b, normal_local);
    let on_box = b.centre + rotate(b, surface);
    return one_hit(Hit(on_box + normal * (Scalar(0.5) * gap), normal, gap, 0u));
}

// Signed area of triangle (first, second, i) about n.
fn area(hits: Manifold, first: u32, second: u32, i: u32, n: vec3<Scalar>) -> Scalar {
    let p0 = hits.hits[first].point;
    return dot3(cross3(hits.hits[second].point - p0, hits.hits[i].point - p0), n);
}

// At most 4 points of a manifold, spread over its area: the deepest, the
// farthest from it, then the two on either side of their line farthest from
// it. Order is kept.
fn reduce_to_four(hits: Manifold) -> Manifold {
    if hits.len <= 4u {
        return hits;
    }
    let n = hits.hits[0].normal;
    // min_by keeps the first of equals, max_by the last.
    var first = 0u;
    for (var i = 1u; i < hits.len; i++) {
        if total_less(hits.hits[i].gap, hits.hits[first].gap) {
            first = i;
        }
    }
    let pf = hits.hits[first].point;
    var second = 0u;
    var far = dot3(hits.hits[0].point - pf, hits.hits[0].point - pf);
    for (var i = 1u; i < hits.len; i++) {
        let d = hits.hits[i].point - pf;
        let di = dot3(d, d);
        if !total_less(di, far) {
            second = i;
            far = di;
        }
    }
    var third = 0u;
    var fourth = 0u;
    var hi = area(hits, first, second, 0u, n);
    var lo = hi;
    for (var i = 1u; i < hits.len; i++) {
        let a = area(hits, first, second, i, n);
        if !total_less(a, hi) {
            third = i;
            hi = a;
        }
        if total_less(a, lo) {
            fourth = i;
            lo = a;
        }
    }
    var out = Manifold();
    out.overflow = hits.overflow;
    for (var i = 0u; i < hits.len; i++) {
        if i == first || i == second || i == third || i == fourth {
            push_hit(&out, hits.hits[i]);
        }
    }
    return out;
}

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

fn push_point(poly: ptr<function, Polygon>, p: vec3<Scalar>, tag: u32) {
    if (*poly).len < 8u {
        (*poly).points[(*poly).len] = p;
        (*poly).tags[(*poly).len] = tag;
        (*poly).len += 1u;
    } else {
        (*poly).overflow = true;
    }
}

// Sutherland–Hodgman with a tolerance: the part of `poly` with pn·p ≤ off,
// a vertex outside by at most `tol` kept as it is. A point made on the
// plane is tagged 4 + 4·side + (the edge's first vertex's tag mod 4).
fn clip(poly: Polygon, pn: vec3<Scalar>, off: Scalar, tol: Scalar, side: u32) -> Polygon {
    var out = Polygon();
    out.overflow = poly.overflow;
    for (var k = 0u; k < poly.len; k++) {
        let p = poly.points[k];
        let tp = poly.tags[k];
        let q = poly.points[(k + 1u) % poly.len];
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
        let p = poly.points[m];
        let gap = dot3(n, p - face_point);
        if gap < margin {
            push_hit(&hits, Hit(p - n * (Scalar(0.5) * gap), normal, gap, base | (poly.tags[m] & 31u)));
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

// Normals of every hit reversed (a pair given the other way round).
fn flip(m: Manifold) -> Manifold {
    var out = m;
    for (var k = 0u; k < out.len; k++) {
        out.hits[k].normal = -out.hits[k].normal;
    }
    return out;
}

// The contact points of shapes x and y closer than `margin`, normals from
// y to x. Two planes give none.
fn collide_shapes(x: Placed, y: Placed, margin: Scalar) -> Manifold {
    if x.kind == KIND_SPHERE && y.kind == KIND_PLANE {
        return sphere_plane(x.centre, x.size.x, y.centre, y.size, margin);
    }
    if x.kind == KIND_PLANE && y.kind == KIND_SPHERE {
        return flip(sphere_plane(y.centre, y.size.x, x.centre, x.size, margin));
    }
    if x.kind == KIND_SPHERE && y.kind == KIND_SPHERE {
        return sphere_sphere(x.centre, x.size.x, y.centre, y.size.x, margin);
    }
    if x.kind == KIND_BOX && y.kind == KIND_PLANE {
        return box_plane(x, x.size, y.centre, y.size, margin);
    }
    if x.kind == KIND_PLANE && y.kind == KIND_BOX {
        return flip(box_plane(y, y.size, x.centre, x.size, margin));
    }
    if x.kind == KIND_SPHERE && y.kind == KIND_BOX {
        return sphere_box(x.centre, x.size.x, y, y.size, margin);
    }
    if x.kind == KIND_BOX && y.kind == KIND_SPHERE {
        return flip(sphere_box(y.centre, y.size.x, x, x.size, margin));
    }
    if x.kind == KIND_BOX && y.kind == KIND_BOX {
        return box_box(x, x.size, y, y.size, margin);
    }
    return Manifold();
}


// Lemke's complementary pivoting method, the textbook run: one invocation
// per island. CPU twin: `lemke_textbook_basis` (src/cpu/lemke.rs) on
// `Workspace::pivot_path` (src/cpu/lemke_tableau.rs) with Noise::Column:
// the same tableau, tests and pivots in the same order, so that in f64 it
// ends on the CPU's basis.
//
// The tableau is B^-1 [I, -M, -e | q] (covering vector e = 1), n rows of
// 2n + 2 columns, row-major in the private array `t`: w_0..w_{n-1},
// z_0..z_{n-1}, z0, rhs; basic[i] is the variable basic in row i (w_i = i,
// z_i = n + i, z0 = 2n). A private array rather than a scratch storage
// buffer: it needs no binding or allocation per batch, and drivers already
// lay thread-private memory out interleaved by thread (coalesced), which is
// what a scratch buffer would have to arrange by hand.
//
// The island's record (BasisResult, shaders/enumeration_basis.wgsl): status
// FOUND (1) with `mask` the final basis (bit i: z_i basic), `visited` the
// pivots, z read from the tableau; or GAVE_UP (4): a secondary ray with z0
// not at zero, the pivot cap (tol._pad1), the loop budget, or a non-finite
// entry. There is no cycle detection: the host solves every island the
// kernel gave up on by the CPU path (which detects cycles). One round: the
// kernel never counts itself in `unfinished`.
//
// Loop budget: llvmpipe (lavapipe) ends every loop of an invocation after
// about 65,535 iterations in all, silently; an invocation gives up before a
// pivot whose loop work (an upper bound, `step`) would take it past
// params.budget (below that limit on software adapters).
//
// Tolerances (binding 7): _pad0 is the Lemke pivot tolerance (an entry of
// the entering column is a pivot when it exceeds it times the column's
// largest magnitude), _pad1 the pivot cap (src/gpu/pipelines.rs).

const SCALAR_MAX: Scalar = 1.7976931348623157e308; // HOST scalar_max

const GAVE_UP: u32 = 4u;

var<private> t: array<Scalar, 544>; // MAX_N * (2 * MAX_N + 2)
var<private> basic: array<u32, 16>;
// Rows whose entry in the entering column counts as a pivot.
var<private> cand: array<u32, 16>;
// Rows still tied in the lexicographic ratio test.
var<private> tied: array<u32, 16>;

fn finite(v: Scalar) -> bool {
    return abs(v) <= SCALAR_MAX;
}

// Gauss-Jordan pivot on (row r, column c): row r divided by its pivot, then
// every other row minus its entry in column c times row r (Workspace::pivot).
// False when an entry it wrote is not finite.
fn pivot(n: u32, r: u32, c: u32) -> bool {
    let cols = 2u * n + 2u;
    let pr = r * cols;
    let inv = Scalar(1.0) / t[pr + c];
    var ok = finite(inv);
    for (var j = 0u; j < cols; j++) {
        let v = t[pr + j] * inv;
        t[pr + j] = v;
        ok = ok && finite(v);
    }
    t[pr + c] = Scalar(1.0);
    for (var i = 0u; i < n; i++) {
        let ri = i * cols;
        let f = t[ri + c];
        if i != r && f != Scalar(0.0) {
            for (var j = 0u; j < cols; j++) {
                let v = t[ri + j] - f * t[pr + j];
                t[ri + j] = v;
                ok = ok && finite(v);
            }
            t[ri + c] = Scalar(0.0);
        }
    }
    return ok;
}

// The ratio-test key of row i in column col for the entering column e
// (Workspace::leaving_row): rhs values rounding made negative count as 0.
fn key(cols: u32, i: u32, col: u32, e: u32) -> Scalar {
    var v = t[i * cols + col];
    if col == cols - 1u {
        v = max(v, Scalar(0.0));
    }
    return v / t[i * cols + e];
}

// The lexicographic minimum-ratio test over cand[0..count]
// (Workspace::leaving_row): the minimum ratio; on a tie z0's row if it is
// tied, else the lexicographic minimum of the rows of B^-1 over the entry.
// n + 1 when a ratio is not finite (the caller gives up).
fn leaving_row(n: u32, e: u32, count: u32) -> u32 {
    let cols = 2u * n + 2u;
    let rhs = cols - 1u;
    var first = cand[0];
    var least = key(cols, first, rhs, e);
    var ties = 1u;
    for (var k = 1u; k < count; k++) {
        let v = key(cols, cand[k], rhs, e);
        if v < least {
            least = v;
            first = cand[k];
            ties = 1u;
        } else if v == least {
            ties++;
        }
    }
    if !finite(least) {
        return n + 1u;
    }
    if ties <= 1u {
        return first;
    }
    var m = 0u;
    for (var k = 0u; k < count; k++) {
        if key(cols, cand[k], rhs, e) <= least {
            tied[m] = cand[k];
            m++;
        }
    }
    for (var k = 0u; k < m; k++) {
        if basic[tied[k]] == 2u * n {
            return tied[k];
        }
    }
    for (var col = 0u; col < n; col++) {
        var low = key(cols, tied[0], col, e);
        for (var k = 1u; k < m; k++) {
            low = min(low, key(cols, tied[k], col, e));
        }
        var kept = 0u;
        for (var k = 0u; k < m; k++) {
            if key(cols, tied[k], col, e) <= low {
                tied[kept] = tied[k];
                kept++;
            }
        }
        m = kept;
        if m <= 1u {
            break;
        }
    }
    if m == 0u {
        return first;
    }
    return tied[0];
}

// The path from the tableau in `t` (B = I: rows w_i = q_i, columns
// [I, -M, -e | q], basic[i] = i), n contacts; `spent`: the loop work of
// filling it. Returns FOUND (1; the basis in `basic`, zero pivots where q >=
// 0) or GAVE_UP, the pivots in `visited`. Takes values only (the tableau is
// private), so that another kernel (shaders/world_step.wgsl) can fill `t`
// and call it.
fn lemke_pivots(n: u32, spent0: u32, pivot_tol: Scalar, max_pivots: u32, budget: u32, visited: ptr<function, u32>) -> u32 {
    let cols = 2u * n + 2u;
    let rhs = cols - 1u;
    let z0 = 2u * n;
    var q_scale = Scalar(0.0);
    var separating = true;
    var qmin = t[rhs];
    var first = 0u;
    for (var i = 0u; i < n; i++) {
        let qi = t[i * cols + rhs];
        separating = separating && qi >= Scalar(0.0);
        q_scale = max(q_scale, abs(qi));
        // The first leaving row: the most negative q_i, ties to the
        // largest index (Workspace::first_row).
        if qi <= qmin {
            qmin = qi;
            first = i;
        }
    }
    if separating {
        return 1u;
    }
    // Loop work of one pivot and its tests, an upper bound.
    let step = (n + 1u) * cols + 2u * n * n + 6u * n;
    var spent = spent0 + n + step;
    if !pivot(n, first, z0) {
        return GAVE_UP;
    }
    *visited = 1u;
    var entering = basic[first] + n;
    basic[first] = z0;
    loop {
        if *visited >= max_pivots || spent + step > budget {
            return GAVE_UP;
        }
        spent += step;
        var colmax = Scalar(0.0);
        for (var i = 0u; i < n; i++) {
            let v = abs(t[i * cols + entering]);
            if v > colmax {
                colmax = v;
            }
        }
        let floor = pivot_tol * colmax;
        var count = 0u;
        for (var i = 0u; i < n; i++) {
            if t[i * cols + entering] > floor {
                cand[count] = i;
                count++;
            }
        }
        if count == 0u || colmax == Scalar(0.0) {
            // A secondary ray: a solution only with z0 at zero to rounding.
            for (var i = 0u; i < n; i++) {
                if basic[i] == z0 {
                    if t[i * cols + rhs] <= pivot_tol * q_scale {
                        return 1u;
                    }
                    break;
                }
            }
            return GAVE_UP;
        }
        let best = leaving_row(n, entering, count);
        if best >= n || !pivot(n, best, entering) {
            return GAVE_UP;
        }
        *visited += 1u;
        let leaving = basic[best];
        basic[best] = entering;
        if leaving == z0 {
            return 1u;
        }
        if leaving < n {
            entering = leaving + n;
        } else {
            entering = leaving - n;
        }
    }
    return GAVE_UP;
}


// One step of resident worlds (restitution 0), one invocation per world,
// in entry points dispatched in one submission:
// `world_collide` (src/world/step.rs `prepare`: gravity, `world_contacts`),
// `world_solve_warm` (the worlds whose warm bases all hold, stepped without
// Lemke's code; the rest listed in `deferred`), then over those alone
// through an indirect dispatch `world_solve` (src/islands.rs `find_islands`, src/cpu/assembly.rs
// `assemble_contact` / `assemble_island`, Lemke's path `lemke_pivots`, the
// door's check `lcp_error` <= tolerance, `apply_impulses`, `finish` with
// `integrate_rotation`, the world's figures; worlds with friction are
// handed over to) `world_friction` (shaders/world_friction.wgsl, in
// rounds). Several entry points rather than one: llvmpipe ends every loop
// of an invocation after about 65,535 iterations in all, and each dispatch
// starts that count afresh.
//
// Composed (src/gpu/shaders/compose.rs) after shaders/collide.wgsl (its
// functions, up to its stage's bindings) and shaders/lemke.wgsl (up to its
// kernel's part), and before shaders/world_solve.wgsl (`world_solve`, a
// file of its own by phase), shaders/world_friction.wgsl and the cone
// projection of shaders/friction_common.wgsl: collide_shapes' pair
// functions (box_box, box_plane, sphere_plane, sphere_sphere, sphere_box,
// dispatched and flipped as it does), lemke_pivots and project_on_cone are
// called as they are.
//
// A world the kernel cannot step is flagged (`flags` below) and its state
// left as it was: the host steps it on the CPU from there. Flags: contact
// slots full (CONTACTS_FULL), an island above 16 contacts
// (ISLAND_TOO_LARGE), Lemke gave up or the check failed (NOT_SOLVED), a
// non-finite velocity or pose after the step (NON_FINITE), the loop budget
// spent (BUDGET).
//
// Layouts (src/gpu/resident/layout.rs, keep in sync):
// - worlds[w] = (first body, bodies, sleep steps, 0);
// - consts: per world WC scalars (gravity 3, margin, sleep linear, sleep
//   angular), then from params.bodies_at per body BC scalars (kind, size 3,
//   static flag, inverse mass, body-frame inverse inertia 3, mass,
//   bounding radius, friction coefficient);
// - state: per body BS scalars (position 3, orientation x, y, z, w,
//   velocity 3, angular velocity 3);
// - scratch: per body 6 scalars (v*, then v after the impulses), then per
//   contact slot CP scalars (point 3, normal 3, gap, z); from
//   params.pairs_at per world params.pair_slots pair records of CP scalars
//   (point 3, normal 3, gap, feature), SLOTS per candidate pair;
// - words: per body 2 (asleep, quiet steps); from params.out_at per world 4
//   (contacts, moving-body mask, flags, islands); from params.keys_at per
//   contact slot 4 (a, b, feature, island);
// - records: per world REC scalars (kinetic, potential, max penetration,
//   max error, awake, friction rounds, and world_solve's warm-start
//   memory: a hash of last step's contact ids, their bases);
// - deferred: the worlds `world_solve_warm` leaves to `world_solve`
//   (world_solve.wgsl): workgroups x, y, z of the indirect dispatch, the
//   count, then the worlds; x and the count reset by world_collide.

const SCALAR_EPSILON: Scalar = 2.220446049250313e-16; // HOST scalar_epsilon

const MAX_BODIES: u32 = 16u;
const WC: u32 = 6u;
const BC: u32 = 12u;
const BS: u32 = 13u;
const CP: u32 = 8u;
const REC: u32 = 8u;
const ISLAND_MAX: u32 = 16u;

const CONTACTS_FULL: u32 = 1u;
const ISLAND_TOO_LARGE: u32 = 2u;
const NOT_SOLVED: u32 = 4u;
const NON_FINITE: u32 = 8u;
const BUDGET: u32 = 16u;
const HANDED: u32 = 32u; // with world_friction until it finishes the world (world_solve.wgsl)

struct StepParams {
    // Worlds.
    count: u32,
    // Contact slots per world.
    slots: u32,
    // Where the bodies' constants start in `consts`.
    bodies_at: u32,
    // Where the worlds' out words and the contact keys start in `words`.
    out_at: u32,
    keys_at: u32,
    // Loop work per invocation and dispatch (shaders/lemke.wgsl).
    budget: u32,
    // Where the contact slots start in `scratch`.
    contacts_at: u32,
    // The frictional phase (shaders/world_friction.wgsl): where its
    // per-world regions start in `scratch` (0: none, no world has
    // friction), its per-world words in `words`, the sweeps' cap, 1 for
    // Gauss–Seidel (0: Jacobi, 2: APGD), 1 for warm starts; this step's reactions
    // and the warm-start memory (ids in `words`, reactions in `scratch`).
    friction_at: u32,
    fstate_at: u32,
    max_iterations: u32,
    gauss_seidel: u32,
    warm_start: u32,
    reactions_at: u32,
    memory_at: u32,
    memory_r_at: u32,
    // Loop work per invocation and round of world_friction: a quarter of
    // `budget` (llvmpipe runs 8 invocations in lockstep and counts their
    // loops together: lanes in different phases add up).
    friction_budget: u32,
    // world_collide's pair records: where they start in `scratch`, and
    // records per world (SLOTS per candidate pair).
    pairs_at: u32,
    pair_slots: u32,
    // 1: world_solve tries last step's bases first (the CPU path's
    // warm_settle: warm starts on, a method that predicts).
    warm_bases: u32,
    dt: Scalar,
    // The door's final check: lcp_error <= tolerance.
    tolerance: Scalar,
    // Lemke: pivot tolerance and pivot cap.
    pivot_tol: Scalar,
    max_pivots: Scalar,
    // The frictional islands' check: cone error <= friction_tolerance.
    friction_tolerance: Scalar,
}

@group(0) @binding(0) var<uniform> sp: StepParams;
@group(0) @binding(1) var<storage, read> worlds: array<vec4<u32>>;
@group(0) @binding(2) var<storage, read> consts: array<Scalar>;
@group(0) @binding(3) var<storage, read_write> state: array<Scalar>;
@group(0) @binding(4) var<storage, read_write> scratch: array<Scalar>;
@group(0) @binding(5) var<storage, read_write> words: array<u32>;
@group(0) @binding(6) var<storage, read_write> records: array<Scalar>;
@group(0) @binding(7) var<storage, read_write> deferred: array<atomic<u32>>;

fn vec3_at_consts(at: u32) -> vec3<Scalar> {
    return vec3<Scalar>(consts[at], consts[at + 1u], consts[at + 2u]);
}

fn vec3_at_state(at: u32) -> vec3<Scalar> {
    return vec3<Scalar>(state[at], state[at + 1u], state[at + 2u]);
}

fn vec3_at_scratch(at: u32) -> vec3<Scalar> {
    return vec3<Scalar>(scratch[at], scratch[at + 1u], scratch[at + 2u]);
}

fn put_scratch(at: u32, v: vec3<Scalar>) {
    scratch[at] = v.x;
    scratch[at + 1u] = v.y;
    scratch[at + 2u] = v.z;
}

fn put_state(at: u32, v: vec3<Scalar>) {
    state[at] = v.x;
    state[at + 1u] = v.y;
    state[at + 2u] = v.z;
}

fn body_const(k: u32, i: u32) -> Scalar {
    return consts[sp.bodies_at + k * BC + i];
}

fn is_static(k: u32) -> bool {
    return body_const(k, 4u) != Scalar(0.0);
}

fn asleep(k: u32) -> bool {
    return words[2u * k] != 0u;
}

// Body k at its pose (RigidBody::rotation normalises, as placed_from).
fn placed_body(k: u32) -> Placed {
    let o = k * BS;
    let q = vec4<Scalar>(state[o + 3u], state[o + 4u], state[o + 5u], state[o + 6u]);
    let kind = u32(body_const(k, 0u));
    let size = vec3_at_consts(sp.bodies_at + k * BC + 1u);
    return placed_from(kind, size, vec3_at_state(o), q);
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
    for (var h = 0u; h < min(m.len, SLOTS); h++) {
        let hit = m.hits[h];
        let at = sp.pairs_at + (w * sp.pair_slots + SLOTS * c + h) * CP;
        put_scratch(at, hit.point);
        put_scratch(at + 3u, select(hit.normal, -hit.normal, flipped));
        scratch[at + 6u] = hit.gap;
        scratch[at + 7u] = Scalar(hit.feature);
    }
    return m.len | select(0u, OVERFLOW, m.overflow);
}

// Step part 1 (step.rs prepare without impacts: restitution 0): v* = v +
// Δt g for the awake dynamic bodies, then world_contacts: candidate pairs
// (broad.rs candidate_pairs: boxes grown by half the margin plus the reach,
// planes with every movable body; all pairs, in the sweep's sorted order
// i < j), the narrow phase with margin + both reaches, sleeping bodies
// woken by an awake one's contact (their v* = Δt g), until none wakes.
//
// In three phases, for llvmpipe, which runs every branch of an invocation
// under a mask and every loop as often as its busiest lane: (1) the
// candidates in pair order, less box–plane pairs that cannot touch
// (box_far_from_plane); (2) the narrow phase of every candidate that an
// awake body can reach through candidates (those world_contacts may
// collide: a pair's manifold depends on the poses and reaches only, not on
// when it is collided), in one loop per family (box–box, box–plane, with a
// sphere) so that each lane pays for box_box only per box–box pair, the
// manifolds kept in the pair records; (3) world_contacts' rounds over the
// candidates in pair order, taking the kept manifolds: the same contacts in
// the same order as collided there.
@compute @workgroup_size(64)
fn world_collide(@builtin(global_invocation_id) gid: vec3<u32>) {
    let w = gid.x;
    if w == 0u {
        // No world left to world_solve yet this step.
        atomicStore(&deferred[0], 0u);
        atomicStore(&deferred[3], 0u);
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
        put_scratch(6u * b, lin);
        put_scratch(6u * b + 3u, ang);
        placed[k] = placed_body(b);
        boxes[k] = aabb_of(placed[k], reach[k] + Scalar(0.5) * margin);
    }
    // (1) Candidates, packed i | j << 8.
    var cands: array<u32, 120>;
    var nc = 0u;
    var spent = 0u;
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
            spent += 1u;
            if candidate {
                cands[nc] = i | (j << 8u);
                nc++;
            }
        }
    }
    // (2) Bodies an awake body can reach through candidates.
    var live = awake_mask;
    loop {
        let before = live;
        for (var c = 0u; c < nc; c++) {
            let ij = (1u << (cands[c] & 0xffu)) | (1u << (cands[c] >> 8u));
            if (live & ij) != 0u {
                live |= movable & ij;
            }
        }
        if live == before {
            break;
        }
    }
    // Their candidates by family: box–box, box–plane, with a sphere.
    var family: array<array<u32, 120>, 3>;
    var members = vec3<u32>(0u, 0u, 0u);
    for (var c = 0u; c < nc; c++) {
        let i = cands[c] & 0xffu;
        let j = cands[c] >> 8u;
        if (live & ((1u << i) | (1u << j))) == 0u {
            continue;
        }
        let ki = placed[i].kind;
        let kj = placed[j].kind;
        var f = 2u;
        if ki == KIND_BOX && kj == KIND_BOX {
            f = 0u;
        } else if ki != KIND_SPHERE && kj != KIND_SPHERE {
            f = 1u;
        }
        family[f][members[f]] = c;
        members[f] += 1u;
    }
    var got: array<u32, 120>;
    for (var t = 0u; t < members.x; t++) {
        let c = family[0][t];
        let i = cands[c] & 0xffu;
        let j = cands[c] >> 8u;
        let x = placed[i];
        let y = placed[j];
        got[c] = keep_manifold(w, c, box_box(x, x.size, y, y.size, margin + reach[i] + reach[j]), false);
    }
    for (var t = 0u; t < members.y; t++) {
        let c = family[1][t];
        let i = cands[c] & 0xffu;
        let j = cands[c] >> 8u;
        // collide_shapes: box_plane with the box first, flipped where the
        // plane was the first shape.
        let flipped = placed[i].kind == KIND_PLANE;
        let b = placed[select(i, j, flipped)];
        let p = placed[select(j, i, flipped)];
        let m = box_plane(b, b.size, p.centre, p.size, margin + reach[i] + reach[j]);
        got[c] = keep_manifold(w, c, m, flipped);
    }
    for (var t = 0u; t < members.z; t++) {
        let c = family[2][t];
        let i = cands[c] & 0xffu;
        let j = cands[c] >> 8u;
        let flipped = placed[i].kind != KIND_SPHERE;
        let s = placed[select(i, j, flipped)];
        let o = placed[select(j, i, flipped)];
        let m = collide_sphere(s, o, margin + reach[i] + reach[j]);
        got[c] = keep_manifold(w, c, m, flipped);
    }
    spent += 400u * (members.x + members.y + members.z);
    // (3) world_contacts' rounds.
    var done: array<u32, 4>;
    var count = 0u;
    var flags = 0u;
    let slot0 = w * sp.slots;
    loop {
        var woke = false;
        for (var c = 0u; c < nc; c++) {
            let i = cands[c] & 0xffu;
            let j = cands[c] >> 8u;
            spent += 1u;
            let bit = 1u << (c & 31u);
            let seen = (done[c >> 5u] & bit) != 0u;
            let on = (((awake_mask >> i) | (awake_mask >> j)) & 1u) != 0u;
            if seen || !on {
                continue;
            }
            done[c >> 5u] |= bit;
            let len = got[c] & ~OVERFLOW;
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
            if (got[c] & OVERFLOW) != 0u || len > SLOTS {
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
                let at = sp.contacts_at + slot * CP;
                put_scratch(at, vec3_at_scratch(kept));
                put_scratch(at + 3u, select(normal, -normal, swap));
                scratch[at + 6u] = scratch[kept + 6u];
                scratch[at + 7u] = Scalar(0.0);
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
    let out = sp.out_at + 4u * w;
    words[out] = count;
    words[out + 1u] = awake_mask;
    words[out + 2u] = flags;
    words[out + 3u] = 0u;
}

// The second phase of shaders/world_step.wgsl (composed after it): one
// island's rows, the check, the islands, `world_solve`.

// One island's contact rows (src/cpu/assembly.rs ContactRow), row i of the
// island at 12 i: the Jacobian and the response M⁻¹Jᵀ of sides a (0..6)
// and b (6..12); q; the dynamic body of each side (NONE: static in the
// step's scene); the answer z.
const NONE: u32 = 0xffffffffu;
var<private> jac: array<Scalar, 192>;
var<private> resp: array<Scalar, 192>;
var<private> qv: array<Scalar, 16>;
var<private> sides: array<vec2<u32>, 16>;
var<private> zv: array<Scalar, 16>;
// The island's M (row i at ISLAND_MAX i), assembled once for the tableau,
// the basis solves and the check; w = M z + q of the last check; the basis
// solve's x over cand.
var<private> mm: array<Scalar, 256>;
var<private> wv: array<Scalar, 16>;
var<private> xs: array<Scalar, 16>;
// Per body of the world: v* and then the velocities after the impulses.
var<private> lin: array<vec3<Scalar>, 16>;
var<private> ang: array<vec3<Scalar>, 16>;

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

// The dynamic body of each side of contact `slot` (global) in the step's
// scene, NONE where that side is static or not moving: the `sides` of its
// rows (friction rows of world_friction.wgsl included).
fn contact_sides(slot: u32, moving: u32) -> vec2<u32> {
    let key = sp.keys_at + 4u * slot;
    let a = words[key];
    let b = words[key + 1u];
    var s = vec2<u32>(NONE, NONE);
    if ((moving >> a) & 1u) != 0u {
        s.x = a;
    }
    if ((moving >> b) & 1u) != 0u {
        s.y = b;
    }
    return s;
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

// False where llvmpipe's loop limit was reached in this invocation: past
// about 65,535 loop iterations of its group of invocations in one dispatch
// every loop ends after its current iteration, so whatever the
// invocation computed since may be cut short; this loop of two
// iterations then ends after one. (Its bound is not a constant, so the
// compiler keeps the loop.) Elsewhere always true.
fn loops_left() -> bool {
    let r = 2u + (sp.count >> 31u);
    var k = 0u;
    loop {
        if k >= r {
            break;
        }
        k++;
    }
    return k == r;
}

fn find(parent: ptr<function, array<u32, 16>>, x0: u32) -> u32 {
    var x = x0;
    while (*parent)[x] != x {
        (*parent)[x] = (*parent)[(*parent)[x]];
        x = (*parent)[x];
    }
    return x;
}

// step.rs integrate_rotation: normalise(q + ½Δt (ω, 0) ⊗ q).
fn integrate_rotation(q: vec4<Scalar>, w: vec3<Scalar>, dt: Scalar) -> vec4<Scalar> {
    // glam's DQuat product (w.x, w.y, w.z, 0) ⊗ q.
    let spin = vec4<Scalar>(
        w.x * q.w + w.y * q.z - w.z * q.y,
        -w.x * q.z + w.y * q.w + w.z * q.x,
        w.x * q.y - w.y * q.x + w.z * q.w,
        -w.x * q.x - w.y * q.y - w.z * q.z,
    );
    return normalize4(q + Scalar(0.5) * dt * spin);
}

fn normalize4(q: vec4<Scalar>) -> vec4<Scalar> {
    let len = sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
    return q * (Scalar(1.0) / len);
}

// lin, ang: the velocities of world w's bodies in `scratch`.
fn load_velocities(w: u32) {
    let first = worlds[w].x;
    for (var k = 0u; k < min(worlds[w].y, MAX_BODIES); k++) {
        lin[k] = vec3_at_scratch(6u * (first + k));
        ang[k] = vec3_at_scratch(6u * (first + k) + 3u);
    }
}

// Step parts 2 and 3 for one world: find_islands (union–find through the
// moving bodies, islands in the order of their first contact), per island
// assembly, the warm basis (`warm_basis`) and where it fails Lemke
// (lemke_pivots), the check, the impulses; then finish (poses, sleep
// counters) and the world's figures. A flagged world (here or in
// world_collide) keeps its state.
//
// The warm-start memory is the world's record (scalars 6 and 7): a hash of
// last step's contact ids (a, b, feature, in order) and its bases (bit c:
// contact c basic, c < 32). With `sp.warm_bases` the bases are hints where
// this step's ids hash alike, as the CPU path's memory by id: every answer
// passes the door's check whatever basis it came from.
//
// In two entry points where `sp.warm_bases` (llvmpipe runs every branch
// of an invocation under a mask, so Lemke's path, rarely taken once the
// warm bases hold, would cost every world every step): `world_solve_warm`
// over every world, without Lemke's path: a world with an island whose
// warm basis fails (or without a warm basis) is left as it is and listed
// in `deferred`; then `world_solve`, dispatched indirectly over the listed
// worlds only, steps them from the start with Lemke's path. Both rewrite
// what they write before the island loop alike, so a listed world ends as
// it would in `world_solve` alone. Without `sp.warm_bases`, `world_solve`
// alone over every world.
@compute @workgroup_size(64)
fn world_solve(@builtin(global_invocation_id) gid: vec3<u32>) {
    var w = gid.x;
    if sp.warm_bases != 0u {
        if w >= atomicLoad(&deferred[3]) {
            return;
        }
        w = atomicLoad(&deferred[4u + w]);
    }
    if w >= sp.count {
        return;
    }
    solve_world(w, true);
}

@compute @workgroup_size(64)
fn world_solve_warm(@builtin(global_invocation_id) gid: vec3<u32>) {
    let w = gid.x;
    if w >= sp.count {
        return;
    }
    solve_world(w, false);
}

// Lists world w for `world_solve` (its indirect dispatch: workgroups of
// WORKGROUP worlds).
fn defer_world(w: u32) {
    let k = atomicAdd(&deferred[3], 1u);
    atomicMax(&deferred[0], k / 64u + 1u);
    atomicStore(&deferred[4u + k], w);
}

// world_solve for world w; without `lemke`, a world that would take
// Lemke's path is deferred (`defer_world`) instead.
fn solve_world(w: u32, lemke: bool) {
    let first = worlds[w].x;
    let out = sp.out_at + 4u * w;
    let count = words[out];
    let moving = words[out + 1u];
    var flags = words[out + 2u];
    let slot0 = w * sp.slots;
    records[w * REC + 5u] = Scalar(0.0);
    load_velocities(w);
    // Islands.
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
    // A world with friction (a contact with μ > 0: Scene::has_friction)
    // goes to world_friction, flagged HANDED until that finishes it; its
    // rounds there are counted from 0 (the record's sixth scalar).
    var frictional = false;
    for (var c = 0u; c < count; c++) {
        let key = sp.keys_at + 4u * (slot0 + c);
        frictional = frictional || pair_friction(first + words[key], first + words[key + 1u]) > Scalar(0.0);
    }
    let fs = sp.fstate_at + 4u * w;
    words[fs] = F_IDLE;
    words[out + 3u] = islands;
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
            return;
        }
    }
    // Per island: assembly, the warm basis or Lemke, check, impulses.
    let rec = w * REC;
    let warm = sp.warm_bases != 0u && records[rec + 6u] == Scalar(ids);
    let hints = u32(records[rec + 7u]);
    var bases = 0u;
    var max_error = Scalar(0.0);
    var spent = 0u;
    var members: array<u32, 16>;
    for (var isl = 0u; isl < islands && flags == 0u; isl++) {
        var n = 0u;
        for (var c = 0u; c < count; c++) {
            if words[sp.keys_at + 4u * (slot0 + c) + 3u] == isl {
                if n < ISLAND_MAX {
                    members[n] = c;
                }
                n++;
            }
        }
        if n > ISLAND_MAX {
            flags |= ISLAND_TOO_LARGE;
            break;
        }
        for (var i = 0u; i < n; i++) {
            assemble_contact(slot0 + members[i], i, first, moving);
        }
        fill_matrix(n);
        spent += n * n + count;
        var error = Scalar(-1.0);
        var basis = NONE;
        if warm {
            var hint = 0u;
            for (var i = 0u; i < n; i++) {
                hint |= select(0u, ((hints >> members[i]) & 1u) << i, members[i] < 32u);
            }
            basis = warm_basis(n, hint, &error);
            spent += (WARM_PIVOTS + 1u) * (n * n * n + 3u * n * n);
        }
        if basis == NONE && !lemke {
            defer_world(w);
            return;
        }
        if basis == NONE {
            // The tableau B⁻¹ [I, −M, −e | q] with B = I (lemke.wgsl).
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
            spent += n * cols;
            var visited = 0u;
            let max_pivots = u32(max(sp.max_pivots, Scalar(1.0)));
            let status = lemke_pivots(n, spent, sp.pivot_tol, max_pivots, sp.budget, &visited);
            spent += n + (visited + 1u) * ((n + 1u) * cols + 2u * n * n + 6u * n);
            if status != 1u {
                flags |= NOT_SOLVED;
                break;
            }
            for (var i = 0u; i < n; i++) {
                zv[i] = Scalar(0.0);
            }
            basis = 0u;
            if visited > 0u {
                for (var i = 0u; i < n; i++) {
                    let v = basic[i];
                    if v >= n && v < 2u * n {
                        zv[v - n] = max(t[i * cols + rhs], Scalar(0.0));
                    }
                }
                basis = resolve_basis(n);
                spent += n * n * n;
            }
            error = check(n);
            if error < Scalar(0.0) {
                flags |= NOT_SOLVED;
                break;
            }
        }
        for (var i = 0u; i < n; i++) {
            bases |= select(0u, ((basis >> i) & 1u) << members[i], members[i] < 32u);
        }
        max_error = max(max_error, error);
        // cpu/impulses.rs velocities_after: v += M⁻¹Jᵀ z per side.
        for (var i = 0u; i < n; i++) {
            let zi = zv[i];
            scratch[sp.contacts_at + (slot0 + members[i]) * CP + 7u] = zi;
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
    }
    // Last step's ids and bases: kept where the world was stepped here.
    records[rec + 6u] = select(Scalar(-1.0), Scalar(ids), flags == 0u);
    records[rec + 7u] = Scalar(bases);
    finish_world(w, flags, max_penetration, max_error);
}

// step.rs finish for world w after its impulses (velocities in lin, ang):
// woken bodies awake, moving bodies integrated, sleep counters; then the
// world's flags and figures. A flagged world keeps its state.
fn finish_world(w: u32, flags0: u32, max_penetration: Scalar, max_error: Scalar) {
    let info = worlds[w];
    let first = info.x;
    let nb = min(info.y, MAX_BODIES);
    let out = sp.out_at + 4u * w;
    let moving = words[out + 1u];
    var flags = flags0;
    let dt = sp.dt;
    let g = vec3_at_consts(w * WC);
    let sleep_linear = consts[w * WC + 4u];
    let sleep_angular = consts[w * WC + 5u];
    var xs: array<vec3<Scalar>, 16>;
    var qs: array<vec4<Scalar>, 16>;
    for (var k = 0u; k < nb && flags == 0u; k++) {
        let b = first + k;
        if ((moving >> k) & 1u) == 0u {
            continue;
        }
        let o = b * BS;
        let q0 = normalize4(vec4<Scalar>(state[o + 3u], state[o + 4u], state[o + 5u], state[o + 6u]));
        xs[k] = vec3_at_state(o) + lin[k] * dt;
        qs[k] = integrate_rotation(q0, ang[k], dt);
        let mag = abs(xs[k]) + abs(qs[k].xyz) + abs(lin[k]) + abs(ang[k]);
        if !finite(mag.x + mag.y + mag.z + abs(qs[k].w)) {
            flags |= NON_FINITE;
        }
    }
    var kinetic = Scalar(0.0);
    var potential = Scalar(0.0);
    var awake = 0u;
    if flags == 0u {
        for (var k = 0u; k < nb; k++) {
            let b = first + k;
            if is_static(b) {
                continue;
            }
            let o = b * BS;
            if ((moving >> k) & 1u) != 0u {
                // A woken body counts its quiet steps afresh.
                var quiet = select(words[2u * b + 1u], 0u, asleep(b));
                let still = length3(lin[k]) < sleep_linear && length3(ang[k]) < sleep_angular;
                if still {
                    quiet = min(quiet, 0xfffffffeu) + 1u;
                } else {
                    quiet = 0u;
                }
                var sleeps = 0u;
                if info.z > 0u && quiet >= info.z {
                    sleeps = 1u;
                    lin[k] = vec3<Scalar>(0.0, 0.0, 0.0);
                    ang[k] = vec3<Scalar>(0.0, 0.0, 0.0);
                }
                words[2u * b] = sleeps;
                words[2u * b + 1u] = quiet;
                put_state(o, xs[k]);
                state[o + 3u] = qs[k].x;
                state[o + 4u] = qs[k].y;
                state[o + 5u] = qs[k].z;
                state[o + 6u] = qs[k].w;
                put_state(o + 7u, lin[k]);
                put_state(o + 10u, ang[k]);
            }
            // RigidBody::kinetic_energy and World::potential_energy after
            // the step.
            let v = vec3_at_state(o + 7u);
            let om = vec3_at_state(o + 10u);
            let p = placed_body(b);
            let wb = unrotate(p, om);
            let inertia = Scalar(1.0) / vec3_at_consts(sp.bodies_at + b * BC + 6u);
            let m = body_const(b, 9u);
            kinetic += Scalar(0.5) * m * dot3(v, v) + Scalar(0.5) * dot3(wb * wb, inertia);
            potential += -m * dot3(g, vec3_at_state(o));
            if !asleep(b) {
                awake++;
            }
        }
    }
    // The loop limit reached: flagged (the host steps the world from its
    // state before the step and writes it back).
    if flags == 0u && !loops_left() {
        flags = BUDGET;
    }
    words[out + 2u] = flags;
    let r = w * REC;
    records[r] = kinetic;
    records[r + 1u] = potential;
    records[r + 2u] = max_penetration;
    records[r + 3u] = max_error;
    records[r + 4u] = Scalar(awake);
}

// The frictional phase of shaders/world_step.wgsl (composed after
// world_solve.wgsl, before the cone projection of friction_common.wgsl):
// the islands of the worlds with friction (a contact with μ > 0 this step;
// world_solve hands them over with the phase F_ASSEMBLE and the flag HANDED,
// which stays until the world is finished), one invocation per world.
// `world_friction` is dispatched several times per step (rounds, after
// world_solve, in the same submission); each invocation goes on where the
// last round stopped and does at most `sp.friction_budget` of loop work
// (llvmpipe ends an invocation's loops after about 65,535 iterations in
// all, counted over 8 invocations in lockstep). A world
// not finished after the step's last round keeps HANDED: the host steps it
// on the CPU. The rounds a world was active in this step are its record's
// sixth scalar (the host sizes the next step's rounds by them).
//
// Per island, the CPU twin's arithmetic in its order
// (src/solver/world_friction.rs with a projected method):
// - the rows n, t₁, t₂ of each contact (friction/assembly.rs
//   assemble_friction_contact: scene.rs tangent_basis, q = v_rel + φ/Δt
//   for n, v_rel for the tangents), W = J M⁻¹ Jᵀ over the shared dynamic
//   bodies (assemble_friction_island), μ = √(μ_a μ_b);
// - the sweeps of friction/projected.rs `sweeps` (Gauss–Seidel or Jacobi,
//   η per contact by contact_steps, relaxation 1): each iteration u =
//   W x + q, the stop measure, a sweep; from the warm start (the last
//   step's reactions of the same (a, b, feature), world_collide) or 0,
//   projected on the cones;
// - the judgement in f64 (ProjectedSolution::judge, FrictionResiduals):
//   solved when r and u are finite and the cone error is at most the
//   tolerance, else the world is flagged NOT_SOLVED (the CPU steps it);
//   the Coulomb error (Siconos fc3d with De Saxcé's correction) is the
//   world's max_error, as the CPU reports it;
// - the impulses (apply_friction_impulses), then `finish_world`.
//
// With APGD (sp.gauss_seidel == METHOD_APGD) instead of the sweeps: the
// twin of friction/apgd.rs `apgd` (from the same start; L from
// first_lipschitz, backtracking by accept_step, the momentum and gradient
// restarts of apgd_iteration, the best iterate kept), judged as above on
// the best iterate and its u (the product that gave it, as the CPU's
// judgement computes it again). A round may end between two backtracking
// tries: the next goes on with the L it saved, as the twin's loop does.
//
// Per world in `scratch` from sp.friction_at, FR scalars: the rows (48 ×
// 24: Jacobian 12, response 12), W (3k × 3k, row-major), q, x, u, two
// temporaries (48 each; APGD's trial x and its u), μ and η (16 each);
// APGD's y, u(y), best, u(best) (48 each), θ, L, the best error. Per
// world in `words` from sp.fstate_at, 4 words: phase, island, sweeps (APGD
// iterations) done, APGD's doublings of L in this iteration.

const FR: u32 = 3923u;
const F_ROWS: u32 = 0u;
const F_W: u32 = 1152u;
const F_Q: u32 = 3456u;
const F_X: u32 = 3504u;
const F_U: u32 = 3552u;
const F_T1: u32 = 3600u;
const F_T2: u32 = 3648u;
const F_MU: u32 = 3696u;
const F_ETA: u32 = 3712u;
const F_Y: u32 = 3728u;
const F_UY: u32 = 3776u;
const F_BEST: u32 = 3824u;
const F_UBEST: u32 = 3872u;
const F_APGD: u32 = 3920u;

// sp.gauss_seidel: 0 Jacobi, 1 Gauss–Seidel sweeps, METHOD_APGD.
const METHOD_APGD: u32 = 2u;

// Below this scale the stop measure is not divided (projected.rs SCALE_FLOOR).
const SCALE_FLOOR: Scalar = Scalar(2.220446049250313e-16);

// Phases.
const F_IDLE: u32 = 0u;
const F_ASSEMBLE: u32 = 1u;
const F_SWEEP: u32 = 2u;

// The island's contact slots (global), in order.
var<private> fmembers: array<u32, 16>;

// μ = √(μ_a μ_b) of bodies ga, gb (global).
fn pair_friction(ga: u32, gb: u32) -> Scalar {
    return sqrt(body_const(ga, 11u) * body_const(gb, 11u));
}

// scene.rs tangent_basis(n).
fn tangent_basis(n: vec3<Scalar>) -> array<vec3<Scalar>, 2> {
    let s = select(Scalar(-1.0), Scalar(1.0), n.z >= Scalar(-0.5));
    let a = Scalar(-1.0) / (s + n.z);
    let b = n.x * n.y * a;
    return array<vec3<Scalar>, 2>(
        vec3<Scalar>(Scalar(1.0) + s * n.x * n.x * a, s * b, -s * n.x),
        vec3<Scalar>(b, s + n.y * n.y * a, -n.y),
    );
}

// I⁻¹ v of body b (global) as the CPU's scene body holds I⁻¹: the matrix
// R diag(1/I) Rᵀ (RigidBody::inv_inertia_at, glam's products in their
// order), then glam's mul_vec3 (world_solve's inv_inertia_mul rotates the
// vector instead: the same up to rounding, which would part the sweeps'
// iterates from the CPU's).
fn inv_inertia_mat_mul(b: u32, v: vec3<Scalar>) -> vec3<Scalar> {
    let p = placed_body(b);
    let d = vec3_at_consts(sp.bodies_at + b * BC + 6u);
    let a0 = p.c0 * d.x;
    let a1 = p.c1 * d.y;
    let a2 = p.c2 * d.z;
    let m0 = a0 * p.c0.x + a1 * p.c1.x + a2 * p.c2.x;
    let m1 = a0 * p.c0.y + a1 * p.c1.y + a2 * p.c2.y;
    let m2 = a0 * p.c0.z + a1 * p.c1.z + a2 * p.c2.z;
    return m0 * v.x + m1 * v.y + m2 * v.z;
}

// Row `row` of the island at `base`: direction d at contact `slot` with
// sides `s` (tangent_row: assemble_contact's row with d for n). Returns
// v_rel = (ṗ_a − ṗ_b)·d.
fn assemble_direction(base: u32, row: u32, slot: u32, d: vec3<Scalar>, first: u32, s: vec2<u32>) -> Scalar {
    let key = sp.keys_at + 4u * slot;
    let a = words[key];
    let b = words[key + 1u];
    let p = vec3_at_scratch(sp.contacts_at + slot * CP);
    let ga = first + a;
    let gb = first + b;
    let ra = p - vec3_at_state(ga * BS);
    let rb = p - vec3_at_state(gb * BS);
    let ra_d = cross3(ra, d);
    let rb_d = cross3(rb, d);
    let o = base + F_ROWS + 24u * row;
    let zero = vec3<Scalar>(0.0, 0.0, 0.0);
    put_scratch(o, d);
    put_scratch(o + 3u, ra_d);
    put_scratch(o + 6u, -d);
    put_scratch(o + 9u, -rb_d);
    put_scratch(o + 12u, zero);
    put_scratch(o + 15u, zero);
    put_scratch(o + 18u, zero);
    put_scratch(o + 21u, zero);
    if s.x != NONE {
        put_scratch(o + 12u, d * body_const(ga, 5u));
        put_scratch(o + 15u, inv_inertia_mat_mul(ga, ra_d));
    }
    if s.y != NONE {
        put_scratch(o + 18u, -d * body_const(gb, 5u));
        put_scratch(o + 21u, -inv_inertia_mat_mul(gb, rb_d));
    }
    let pdot = (lin[a] + cross3(ang[a], ra)) - (lin[b] + cross3(ang[b], rb));
    return dot3(pdot, d);
}

// J_x (side si) · M⁻¹J_yᵀ (side sj) of rows x, y (dot6, summed in order).
fn rows_dot6(base: u32, x: u32, si: u32, y: u32, sj: u32) -> Scalar {
    let j = base + F_ROWS + 24u * x + 6u * si;
    let r = base + F_ROWS + 24u * y + 12u + 6u * sj;
    return scratch[j] * scratch[r] + scratch[j + 1u] * scratch[r + 1u]
        + scratch[j + 2u] * scratch[r + 2u] + scratch[j + 3u] * scratch[r + 3u]
        + scratch[j + 4u] * scratch[r + 4u] + scratch[j + 5u] * scratch[r + 5u];
}

// W's entry of rows x and y (assembly.rs matrix_entry over the dynamic
// bodies their contacts share; written out, without loops).
fn friction_entry(base: u32, x: u32, y: u32) -> Scalar {
    let si = sides[x / 3u];
    let sj = sides[y / 3u];
    var m = Scalar(0.0);
    if si.x != NONE && si.x == sj.x {
        m += rows_dot6(base, x, 0u, y, 0u);
    }
    if si.x != NONE && si.x == sj.y {
        m += rows_dot6(base, x, 0u, y, 1u);
    }
    if si.y != NONE && si.y == sj.x {
        m += rows_dot6(base, x, 1u, y, 0u);
    }
    if si.y != NONE && si.y == sj.y {
        m += rows_dot6(base, x, 1u, y, 1u);
    }
    return m;
}

// The island's problem (its n contacts in fmembers): rows, q, μ, W, η, and
// the start x (the warm start where world_collide found one, else 0),
// projected on the cones.
fn assemble_friction(base: u32, n: u32, first: u32, moving: u32) {
    for (var i = 0u; i < n; i++) {
        let slot = fmembers[i];
        let at = sp.contacts_at + slot * CP;
        let nrm = vec3_at_scratch(at + 3u);
        let t = tangent_basis(nrm);
        let gap = scratch[at + 6u];
        let key = sp.keys_at + 4u * slot;
        let s = contact_sides(slot, moving);
        sides[i] = s;
        let q = base + F_Q + 3u * i;
        scratch[q] = assemble_direction(base, 3u * i, slot, nrm, first, s) + gap / sp.dt;
        scratch[q + 1u] = assemble_direction(base, 3u * i + 1u, slot, t[0], first, s);
        scratch[q + 2u] = assemble_direction(base, 3u * i + 2u, slot, t[1], first, s);
        let m = pair_friction(first + words[key], first + words[key + 1u]);
        scratch[base + F_MU + i] = m;
        let r = warm_start(slot);
        put_scratch(base + F_X + 3u * i, project_on_cone(r, m));
    }
    let dim = 3u * n;
    // One entry per loop iteration: three (as contact_velocity takes them)
    // made llvmpipe's compilation of the kernel ten times as long.
    for (var x = 0u; x < dim; x++) {
        for (var y = 0u; y < dim; y++) {
            scratch[base + F_W + x * dim + y] = friction_entry(base, x, y);
        }
    }
    // projected.rs contact_steps.
    for (var i = 0u; i < n; i++) {
        var lo = 0u;
        var hi = dim;
        if sp.gauss_seidel != 0u {
            lo = 3u * i;
            hi = lo + 3u;
        }
        var big = Scalar(0.0);
        for (var x = 3u * i; x < 3u * i + 3u; x++) {
            var s = Scalar(0.0);
            for (var y = lo; y < hi; y += 3u) {
                let at = base + F_W + x * dim + y;
                s += abs(scratch[at]);
                s += abs(scratch[at + 1u]);
                s += abs(scratch[at + 2u]);
            }
            big = max(big, s);
        }
        scratch[base + F_ETA + i] = select(Scalar(1.0), Scalar(1.0) / big, big > Scalar(0.0));
    }
}

// The loops below take three entries (a contact's rows or columns) per
// iteration, summed in the CPU's order: llvmpipe counts loop iterations
// against its limit and pays each one's mask bookkeeping. `len` and `dim`
// are multiples of 3.

// u of contact i's rows 3i..3i+3: u_x = q_x + Σ_j W_xj x_j, each row's sum
// in the order of j (projected.rs velocity_into), x from `xs` into u at
// `us` (offsets in the world's region): n loop iterations.
fn contact_velocity(base: u32, dim: u32, i: u32, xs: u32, us: u32) {
    let r0 = base + F_W + 3u * i * dim;
    let r1 = r0 + dim;
    let r2 = r1 + dim;
    var s0 = Scalar(0.0);
    var s1 = Scalar(0.0);
    var s2 = Scalar(0.0);
    for (var j = 0u; j < dim; j += 3u) {
        let x0 = scratch[xs + j];
        let x1 = scratch[xs + j + 1u];
        let x2 = scratch[xs + j + 2u];
        s0 += scratch[r0 + j] * x0;
        s0 += scratch[r0 + j + 1u] * x1;
        s0 += scratch[r0 + j + 2u] * x2;
        s1 += scratch[r1 + j] * x0;
        s1 += scratch[r1 + j + 1u] * x1;
        s1 += scratch[r1 + j + 2u] * x2;
        s2 += scratch[r2 + j] * x0;
        s2 += scratch[r2 + j + 1u] * x1;
        s2 += scratch[r2 + j + 2u] * x2;
    }
    let u = us + 3u * i;
    let q = base + F_Q + 3u * i;
    scratch[u] = scratch[q] + s0;
    scratch[u + 1u] = scratch[q + 1u] + s1;
    scratch[u + 2u] = scratch[q + 2u] + s2;
}

// u = W x + q for the island's n contacts, x at base + `xs`, u at base + `us`.
fn friction_velocity(base: u32, n: u32, xs: u32, us: u32) {
    for (var i = 0u; i < n; i++) {
        contact_velocity(base, 3u * n, i, base + xs, base + us);
    }
}

// Σ v², from the start (projected.rs sum_squares) of `len` entries at `at`.
fn sum_squares_at(at: u32, len: u32) -> Scalar {
    var s = Scalar(0.0);
    for (var i = 0u; i < len; i += 3u) {
        s += scratch[at + i] * scratch[at + i];
        s += scratch[at + i + 1u] * scratch[at + i + 1u];
        s += scratch[at + i + 2u] * scratch[at + i + 2u];
    }
    return s;
}

// lcp.rs norm2 of `len` entries at `at` (scaled by the largest).
fn norm2_at(at: u32, len: u32) -> Scalar {
    var big = Scalar(0.0);
    for (var i = 0u; i < len; i += 3u) {
        big = max(big, abs(scratch[at + i]));
        big = max(big, abs(scratch[at + i + 1u]));
        big = max(big, abs(scratch[at + i + 2u]));
    }
    if big == Scalar(0.0) || !finite(big) {
        return big;
    }
    var s = Scalar(0.0);
    for (var i = 0u; i < len; i += 3u) {
        let v0 = scratch[at + i] / big;
        let v1 = scratch[at + i + 1u] / big;
        let v2 = scratch[at + i + 2u] / big;
        s += v0 * v0;
        s += v1 * v1;
        s += v2 * v2;
    }
    return big * sqrt(s);
}

// residual.rs norm: the plain sum of squares where it is finite and above
// 1e-280, else norm2.
fn norm_at(at: u32, len: u32) -> Scalar {
    let s = sum_squares_at(at, len);
    if finite(s) && s > Scalar(1e-280) {
        return sqrt(s);
    }
    return norm2_at(at, len);
}

fn vec3_x(base: u32, i: u32) -> vec3<Scalar> {
    return vec3_at_scratch(base + F_X + 3u * i);
}

fn vec3_u(base: u32, i: u32) -> vec3<Scalar> {
    return vec3_at_scratch(base + F_U + 3u * i);
}

// projected.rs stop_measure of x at base + `xs` with u at base + `us`;
// q2 = ‖q‖².
fn stop_measure(base: u32, n: u32, q2: Scalar, xs: u32, us: u32) -> Scalar {
    var e2 = Scalar(0.0);
    for (var i = 0u; i < n; i++) {
        let x = vec3_at_scratch(base + xs + 3u * i);
        let p = project_on_cone(x - vec3_at_scratch(base + us + 3u * i), scratch[base + F_MU + i]);
        let d = x - p;
        e2 += d.x * d.x;
        e2 += d.y * d.y;
        e2 += d.z * d.z;
    }
    let dim = 3u * n;
    let scale = sqrt(max(max(q2, sum_squares_at(base + xs, dim)), sum_squares_at(base + us, dim)));
    let e = sqrt(e2);
    if scale > SCALE_FLOOR {
        return e / scale;
    }
    return e;
}

// One sweep of projected.rs `sweeps` (u from the iteration's start; for
// Gauss–Seidel each contact's rows again from the reactions so far).
fn sweep(base: u32, n: u32) {
    let dim = 3u * n;
    for (var i = 0u; i < n; i++) {
        let c = 3u * i;
        if sp.gauss_seidel != 0u {
            contact_velocity(base, dim, i, base + F_X, base + F_U);
        }
        let h = scratch[base + F_ETA + i];
        let x = vec3_x(base, i);
        let u = vec3_u(base, i);
        let p = project_on_cone(
            vec3<Scalar>(x.x - h * u.x, x.y - h * u.y, x.z - h * u.z),
            scratch[base + F_MU + i],
        );
        put_scratch(base + F_X + c, p);
    }
}

// ProjectedSolution::judge of x with u = W x + q (the sweeps' last
// iteration computed it from this x, which it left as it was), the cone
// error (the status) and the Coulomb error
// (FrictionResiduals::of_velocity). The Coulomb error, or -1 where x is
// not solved (not finite, or the cone error above the tolerance, or
// `failed`).
fn judge(base: u32, n: u32, failed: bool) -> Scalar {
    let dim = 3u * n;
    var ok = !failed;
    for (var i = 0u; i < n; i++) {
        let x = vec3_x(base, i);
        let u = vec3_u(base, i);
        let m = scratch[base + F_MU + i];
        let ok3 = finite(x.x) && finite(x.y) && finite(x.z) && finite(u.x) && finite(u.y) && finite(u.z);
        ok = ok && ok3;
        put_scratch(base + F_T1 + 3u * i, x - project_on_cone(x - u, m));
        let un = u.x + m * sqrt(u.y * u.y + u.z * u.z);
        let pc = project_on_cone(vec3<Scalar>(x.x - un, x.y - u.y, x.z - u.z), m);
        put_scratch(base + F_T2 + 3u * i, x - pc);
    }
    let scale = max(max(norm_at(base + F_Q, dim), norm_at(base + F_X, dim)), norm_at(base + F_U, dim));
    var cone = norm2_at(base + F_T1, dim);
    var coulomb = norm_at(base + F_T2, dim);
    if scale > SCALAR_EPSILON {
        cone = cone / scale;
        coulomb = coulomb / scale;
    }
    if !ok || !finite(cone) || !(cone <= sp.friction_tolerance) {
        return Scalar(-1.0);
    }
    return coulomb;
}

// apply_friction_impulses for the island: v += Σ_α r_α M⁻¹J_αᵀ per side,
// contact after contact, n, t₁, t₂ (zero reactions skipped); each
// contact's reaction kept for the next step's warm start.
fn apply_friction(base: u32, n: u32, moving: u32) {
    for (var i = 0u; i < n; i++) {
        let s = contact_sides(fmembers[i], moving);
        for (var d = 0u; d < 3u; d++) {
            let z = scratch[base + F_X + 3u * i + d];
            if z == Scalar(0.0) {
                continue;
            }
            let o = base + F_ROWS + 24u * (3u * i + d);
            if s.x != NONE {
                lin[s.x] += vec3_at_scratch(o + 12u) * z;
                ang[s.x] += vec3_at_scratch(o + 15u) * z;
            }
            if s.y != NONE {
                lin[s.y] += vec3_at_scratch(o + 18u) * z;
                ang[s.y] += vec3_at_scratch(o + 21u) * z;
            }
        }
        keep_reaction(fmembers[i], vec3_x(base, i));
    }
}

// Step part 2 for the worlds with friction, in rounds (see the header).
@compute @workgroup_size(64)
fn world_friction(@builtin(global_invocation_id) gid: vec3<u32>) {
    let w = gid.x;
    if w >= sp.count {
        return;
    }
    let fs = sp.fstate_at + 4u * w;
    var phase = words[fs];
    if phase == F_IDLE {
        return;
    }
    records[w * REC + 5u] += Scalar(1.0);
    let first = worlds[w].x;
    let nb = min(worlds[w].y, MAX_BODIES);
    let out = sp.out_at + 4u * w;
    let count = words[out];
    let moving = words[out + 1u];
    let islands = words[out + 3u];
    let slot0 = w * sp.slots;
    let base = sp.friction_at + w * FR;
    load_velocities(w);
    var flags = 0u;
    var spent = 0u;
    var finished = false;
    loop {
        let isl = words[fs + 1u];
        if isl >= islands {
            finished = true;
            break;
        }
        var n = 0u;
        for (var c = 0u; c < count; c++) {
            if words[sp.keys_at + 4u * (slot0 + c) + 3u] == isl {
                if n < ISLAND_MAX {
                    fmembers[n] = slot0 + c;
                }
                n++;
            }
        }
        spent += count;
        if n > ISLAND_MAX {
            flags |= ISLAND_TOO_LARGE;
            break;
        }
        let dim = 3u * n;
        // Costs: the loop iterations of each part (see contact_velocity).
        let apgd = sp.gauss_seidel == METHOD_APGD;
        if phase == F_ASSEMBLE {
            var cost = 12u * n * n + n * (sp.slots + 1u) + 64u;
            if apgd {
                cost += 4u * n * n + 16u * n + 16u;
            }
            if spent > count && spent + cost > sp.friction_budget {
                break;
            }
            spent += cost;
            assemble_friction(base, n, first, moving);
            words[fs + 2u] = 0u;
            words[fs + 3u] = 0u;
            phase = F_SWEEP;
            words[fs] = phase;
            if apgd && !apgd_start(base, n, sum_squares_at(base + F_Q, dim)) {
                flags |= NOT_SOLVED;
                break;
            }
        }
        // Iterations of `sweeps`: u, the stop measure, a sweep.
        let cost = 2u * n * n + 8u * n + 16u;
        let q2 = sum_squares_at(base + F_Q, dim);
        var done = false;
        var failed = false;
        if apgd {
            let r = apgd_round(base, n, q2, fs, spent);
            spent = r.x;
            if r.y == 2u {
                flags |= NOT_SOLVED;
                break;
            }
            done = r.y == 1u;
        }
        loop {
            if apgd {
                break;
            }
            if spent + cost > sp.friction_budget {
                break;
            }
            spent += cost;
            let it = words[fs + 2u];
            friction_velocity(base, n, F_X, F_U);
            let err = stop_measure(base, n, q2, F_X, F_U);
            if !finite(err) {
                failed = true;
                done = true;
                break;
            }
            if err <= sp.friction_tolerance || it >= sp.max_iterations {
                done = true;
                break;
            }
            sweep(base, n);
            words[fs + 2u] = it + 1u;
        }
        // The judgement's loops (no product: u is the last iteration's).
        let judged = 16u * n + 64u;
        if !done || spent + judged > sp.friction_budget {
            // The next round goes on from x (and judges it there).
            break;
        }
        spent += judged;
        let error = judge(base, n, failed);
        if error < Scalar(0.0) {
            flags |= NOT_SOLVED;
            break;
        }
        records[w * REC + 3u] = max(records[w * REC + 3u], error);
        apply_friction(base, n, moving);
        words[fs + 1u] = isl + 1u;
        phase = F_ASSEMBLE;
        words[fs] = phase;
    }
    if flags != 0u {
        words[fs] = F_IDLE;
        words[out + 2u] = flags;
        return;
    }
    for (var k = 0u; k < nb; k++) {
        put_scratch(6u * (first + k), lin[k]);
        put_scratch(6u * (first + k) + 3u, ang[k]);
    }
    if !loops_left() {
        // The loop limit reached (world_solve.wgsl loops_left): this
        // round's work may be cut short; flagged, the CPU steps the world.
        words[fs] = F_IDLE;
        words[out + 2u] = BUDGET;
        return;
    }
    if finished {
        words[fs] = F_IDLE;
        remember_reactions(w, count);
        let r = w * REC;
        finish_world(w, 0u, records[r + 2u], records[r + 3u]);
    }
}

// The warm-start memory of world w (kept while its steps have friction):
// in `words` from sp.memory_at, slots + 1 words per world (entries, then
// each entry's id (a << 16) | (b << 12) | (feature & 0xfff), as
// step.rs contact_id without the world); in `scratch` from
// sp.memory_r_at, 3 scalars per entry (r_n, r_t₁, r_t₂). This step's
// reactions wait in `scratch` from sp.reactions_at (3 per contact slot)
// until the world is finished.
fn contact_key(slot: u32) -> u32 {
    let key = sp.keys_at + 4u * slot;
    return (words[key] << 16u) | (words[key + 1u] << 12u) | (words[key + 2u] & 0xfffu);
}

// The warm start of contact `slot` (world_friction.rs: the remembered
// reaction of its id, the last entry of that id; 0 where none or warm
// starts are off).
fn warm_start(slot: u32) -> vec3<Scalar> {
    var r = vec3<Scalar>(0.0, 0.0, 0.0);
    if sp.warm_start == 0u {
        return r;
    }
    let w = slot / sp.slots;
    let m = sp.memory_at + w * (sp.slots + 1u);
    let id = contact_key(slot);
    for (var e = 0u; e < words[m]; e++) {
        if words[m + 1u + e] == id {
            r = vec3_at_scratch(sp.memory_r_at + 3u * (w * sp.slots + e));
        }
    }
    return r;
}

fn keep_reaction(slot: u32, r: vec3<Scalar>) {
    scratch[sp.contacts_at + slot * CP + 7u] = r.x;
    put_scratch(sp.reactions_at + 3u * slot, r);
}

// WarmMemory::record of a finished world's step (every island solved):
// its contacts' ids and reactions replace the memory.
fn remember_reactions(w: u32, count: u32) {
    if sp.warm_start == 0u {
        return;
    }
    let m = sp.memory_at + w * (sp.slots + 1u);
    words[m] = count;
    for (var e = 0u; e < count; e++) {
        let slot = w * sp.slots + e;
        words[m + 1u + e] = contact_key(slot);
        put_scratch(sp.memory_r_at + 3u * slot, vec3_at_scratch(sp.reactions_at + 3u * slot));
    }
}

// APGD in the frictional phase of shaders/world_step.wgsl (composed after
// world_friction.wgsl, whose header gives the method, the layout of a
// world's region and the rounds; `world_friction` calls apgd_start after
// an island's assembly and apgd_round in each round): the twin of
// friction/apgd.rs, its arithmetic in its order, on the island's W, q and
// μ in `scratch`. accept_step and apgd_momentum are friction_common.wgsl's
// (the batch APGD kernels' own).

// Copies contact after contact 3n entries from base + `src` to base + `dst`.
fn copy_entries(base: u32, n: u32, src: u32, dst: u32) {
    for (var i = 0u; i < n; i++) {
        put_scratch(base + dst + 3u * i, vec3_at_scratch(base + src + 3u * i));
    }
}

// apgd.rs first_lipschitz: ‖W e‖ / ‖e‖ for e = (1, …, 1), else the largest
// |W_rr|, else 1.
fn first_lipschitz(base: u32, n: u32) -> Scalar {
    let dim = 3u * n;
    var s2 = Scalar(0.0);
    for (var r = 0u; r < dim; r++) {
        let row = base + F_W + r * dim;
        var s = Scalar(0.0);
        for (var j = 0u; j < dim; j += 3u) {
            s += scratch[row + j];
            s += scratch[row + j + 1u];
            s += scratch[row + j + 2u];
        }
        s2 += s * s;
    }
    let l = sqrt(s2 / Scalar(dim));
    if l > Scalar(0.0) && finite(l) {
        return l;
    }
    var d = Scalar(0.0);
    for (var r = 0u; r < dim; r++) {
        d = max(d, abs(scratch[base + F_W + r * dim + r]));
    }
    return select(Scalar(1.0), d, d > Scalar(0.0) && finite(d));
}

// APGD's start (apgd.rs apgd) from x (projected by assemble_friction):
// u(x), its error, y = x, u(y) = u(x), best = x, θ = 1, L; false where
// the error is not finite (the twin fails).
fn apgd_start(base: u32, n: u32, q2: Scalar) -> bool {
    friction_velocity(base, n, F_X, F_U);
    let err = stop_measure(base, n, q2, F_X, F_U);
    copy_entries(base, n, F_X, F_Y);
    copy_entries(base, n, F_U, F_UY);
    copy_entries(base, n, F_X, F_BEST);
    copy_entries(base, n, F_U, F_UBEST);
    let a = base + F_APGD;
    scratch[a] = Scalar(1.0);
    scratch[a + 1u] = first_lipschitz(base, n);
    scratch[a + 2u] = err;
    return finite(err);
}

// One backtracking try from y with step 1/L (apgd_iteration): the trial
// xn = P_K(y − u(y) / L) into T1, u(xn) into T2; whether accept_step takes
// it (d = xn − y, W d = u(xn) − u(y)).
fn apgd_try(base: u32, n: u32, lipschitz: Scalar) -> bool {
    let t = Scalar(1.0) / lipschitz;
    for (var i = 0u; i < n; i++) {
        let y = vec3_at_scratch(base + F_Y + 3u * i);
        let uy = vec3_at_scratch(base + F_UY + 3u * i);
        put_scratch(base + F_T1 + 3u * i, project_on_cone(y - t * uy, scratch[base + F_MU + i]));
    }
    friction_velocity(base, n, F_T1, F_T2);
    var curvature = Scalar(0.0);
    var d2 = Scalar(0.0);
    var g2 = Scalar(0.0);
    for (var i = 0u; i < n; i++) {
        let d = vec3_at_scratch(base + F_T1 + 3u * i) - vec3_at_scratch(base + F_Y + 3u * i);
        let uy = vec3_at_scratch(base + F_UY + 3u * i);
        let wd = vec3_at_scratch(base + F_T2 + 3u * i) - uy;
        curvature += d.x * wd.x;
        curvature += d.y * wd.y;
        curvature += d.z * wd.z;
        d2 += d.x * d.x;
        d2 += d.y * d.y;
        d2 += d.z * d.z;
        g2 += uy.x * uy.x;
        g2 += uy.y * uy.y;
        g2 += uy.z * uy.z;
    }
    return accept_step(curvature, d2, g2, lipschitz);
}

// After an accepted try (apgd_iteration): the best iterate (with its u),
// the momentum, the gradient restart, x = xn, L × 0.9, the iteration
// counted in words[fs + 2]; false where the trial's error is not finite.
fn apgd_accept(base: u32, n: u32, q2: Scalar, fs: u32) -> bool {
    let err = stop_measure(base, n, q2, F_T1, F_T2);
    if !finite(err) {
        return false;
    }
    let a = base + F_APGD;
    if err < scratch[a + 2u] {
        scratch[a + 2u] = err;
        copy_entries(base, n, F_T1, F_BEST);
        copy_entries(base, n, F_T2, F_UBEST);
    }
    let m = apgd_momentum(scratch[a]);
    var g_dot = Scalar(0.0);
    for (var i = 0u; i < n; i++) {
        let d = vec3_at_scratch(base + F_T1 + 3u * i) - vec3_x(base, i);
        let uy = vec3_at_scratch(base + F_UY + 3u * i);
        g_dot += uy.x * d.x;
        g_dot += uy.y * d.y;
        g_dot += uy.z * d.z;
    }
    let restart = g_dot > Scalar(0.0);
    for (var i = 0u; i < n; i++) {
        let xn = vec3_at_scratch(base + F_T1 + 3u * i);
        let un = vec3_at_scratch(base + F_T2 + 3u * i);
        var y = xn;
        var uy = un;
        if !restart {
            y = xn + m.y * (xn - vec3_x(base, i));
            uy = un + m.y * (un - vec3_u(base, i));
        }
        put_scratch(base + F_Y + 3u * i, y);
        put_scratch(base + F_UY + 3u * i, uy);
        put_scratch(base + F_X + 3u * i, xn);
        put_scratch(base + F_U + 3u * i, un);
    }
    scratch[a] = select(m.x, Scalar(1.0), restart);
    scratch[a + 1u] = scratch[a + 1u] * Scalar(0.9);
    words[fs + 2u] += 1u;
    words[fs + 3u] = 0u;
    return true;
}

// The APGD iterations of a round within `budget` from `spent` (the twin's
// loop: stop at the tolerance or the cap, else a try, doubling L where it
// fails): (loop work spent, 1 done, 2 failed), the best iterate and its u
// in x and u where done.
fn apgd_round(base: u32, n: u32, q2: Scalar, fs: u32, spent0: u32) -> vec2<u32> {
    let cost = n * n + 10u * n + 16u;
    let a = base + F_APGD;
    var spent = spent0;
    var end = 0u;
    loop {
        if scratch[a + 2u] <= sp.friction_tolerance || words[fs + 2u] >= sp.max_iterations {
            copy_entries(base, n, F_BEST, F_X);
            copy_entries(base, n, F_UBEST, F_U);
            spent += 2u * n;
            end = 1u;
            break;
        }
        if spent + cost > sp.friction_budget {
            break;
        }
        spent += cost;
        let l = scratch[a + 1u];
        if apgd_try(base, n, l) {
            if !apgd_accept(base, n, q2, fs) {
                end = 2u;
                break;
            }
        } else {
            scratch[a + 1u] = Scalar(2.0) * l;
            words[fs + 3u] += 1u;
            if words[fs + 3u] >= MAX_BACKTRACKS || !finite(scratch[a + 1u]) {
                end = 2u;
                break;
            }
        }
    }
    return vec2<u32>(spent, end);
}

// Siconos' fc3d projection on {|x_t| <= mu x_n} (cone.rs project_on_cone).
fn project_on_cone(v: vec3<Scalar>, m: Scalar) -> vec3<Scalar> {
    let t = sqrt(v.y * v.y + v.z * v.z);
    if m * t <= -v.x {
        return vec3<Scalar>(Scalar(0.0));
    }
    if t <= m * v.x {
        return v;
    }
    let pn = (m * t + v.x) / (m * m + Scalar(1.0));
    let scale = m * pn / t;
    return vec3<Scalar>(pn, v.y * scale, v.z * scale);
}

// Consecutive doublings of L in one APGD iteration before a numerical failure.
const MAX_BACKTRACKS: u32 = 64u;

// APGD's backtracking test (apgd.rs accept_step): dᵀW d ≤ L‖d‖²
// (`curvature`, `d2`), or a step that rounding decides: L‖d‖ ≤ 16 ε
// ‖∇f(y)‖ (`g2` = ‖∇f(y)‖²).
fn accept_step(curvature: Scalar, d2: Scalar, g2: Scalar, lipschitz: Scalar) -> bool {
    let noise = Scalar(16.0) * SCALAR_EPSILON;
    return curvature <= lipschitz * d2 || lipschitz * lipschitz * d2 <= noise * noise * g2;
}

// APGD's momentum after an accepted step from θ (apgd.rs apgd_iteration):
// (θ_new, β).
fn apgd_momentum(th: Scalar) -> vec2<Scalar> {
    let th_new = Scalar(0.5) * (th * sqrt(th * th + Scalar(4.0)) - th * th);
    let beta = th * (Scalar(1.0) - th) / (th * th + th_new);
    return vec2<Scalar>(th_new, beta);
}
