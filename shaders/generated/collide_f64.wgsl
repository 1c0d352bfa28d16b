// GENERATED from shaders/collide.wgsl + shaders/collide_box.wgsl by src/gpu/shaders/compose.rs: do not edit.
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

// Pair functions (the resident step's solve and frictional phases take
// the functions above this line only).

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

// Every index into a manifold's or polygon's array is a constant: a
// run-time index goes through a ladder over the slots (push_hit, hit_at,
// push_point, point_at; their loops marked UNROLL are unrolled by the
// composition, src/gpu/shaders/unroll_loops.rs, as are a few short loops
// over every slot). llvmpipe keeps a private array in registers only where
// every access to it has a constant index, else each access is a per-lane
// gather or scatter in memory (BENCHMARKS.md "reslvp": the box–box kernel
// 28.9 → 6.5 ms a step on 1,000 worlds). The longer loops stay loops (each
// unrolled copy would be in the SPIR-V of every collision entry point).
fn push_hit(m: ptr<function, Manifold>, h: Hit) {
    if (*m).len < CAPACITY {
{

            if (*m).len == 0u {
                (*m).hits[0u] = h;
            }
        }
{

            if (*m).len == 1u {
                (*m).hits[1u] = h;
            }
        }
{

            if (*m).len == 2u {
                (*m).hits[2u] = h;
            }
        }
{

            if (*m).len == 3u {
                (*m).hits[3u] = h;
            }
        }
{

            if (*m).len == 4u {
                (*m).hits[4u] = h;
            }
        }
{

            if (*m).len == 5u {
                (*m).hits[5u] = h;
            }
        }
{

            if (*m).len == 6u {
                (*m).hits[6u] = h;
            }
        }
{

            if (*m).len == 7u {
                (*m).hits[7u] = h;
            }
        }

        (*m).len += 1u;
    } else {
        (*m).overflow = true;
    }
}

// Hit k of m (k < CAPACITY), read by a ladder over the slots.
fn hit_at(m: Manifold, k: u32) -> Hit {
    var h = m.hits[0];
{

        if k == 1u {
            h = m.hits[1u];
        }
    }
{

        if k == 2u {
            h = m.hits[2u];
        }
    }
{

        if k == 3u {
            h = m.hits[3u];
        }
    }
{

        if k == 4u {
            h = m.hits[4u];
        }
    }
{

        if k == 5u {
            h = m.hits[5u];
        }
    }
{

        if k == 6u {
            h = m.hits[6u];
        }
    }
{

        if k == 7u {
            h = m.hits[7u];
        }
    }

    return h;
}

fn one_hit(h: Hit) -> Manifold {
    var m = Manifold();
    push_hit(&m, h);
    return m;
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
{

        let s = vec3<Scalar>(
            select(h.x, -h.x, (0u & 1u) == 0u),
            select(h.y, -h.y, (0u & 2u) == 0u),
            select(h.z, -h.z, (0u & 4u) == 0u),
        );
        out[0u] = b.centre + rotate(b, s);
    }
{

        let s = vec3<Scalar>(
            select(h.x, -h.x, (1u & 1u) == 0u),
            select(h.y, -h.y, (1u & 2u) == 0u),
            select(h.z, -h.z, (1u & 4u) == 0u),
        );
        out[1u] = b.centre + rotate(b, s);
    }
{

        let s = vec3<Scalar>(
            select(h.x, -h.x, (2u & 1u) == 0u),
            select(h.y, -h.y, (2u & 2u) == 0u),
            select(h.z, -h.z, (2u & 4u) == 0u),
        );
        out[2u] = b.centre + rotate(b, s);
    }
{

        let s = vec3<Scalar>(
            select(h.x, -h.x, (3u & 1u) == 0u),
            select(h.y, -h.y, (3u & 2u) == 0u),
            select(h.z, -h.z, (3u & 4u) == 0u),
        );
        out[3u] = b.centre + rotate(b, s);
    }
{

        let s = vec3<Scalar>(
            select(h.x, -h.x, (4u & 1u) == 0u),
            select(h.y, -h.y, (4u & 2u) == 0u),
            select(h.z, -h.z, (4u & 4u) == 0u),
        );
        out[4u] = b.centre + rotate(b, s);
    }
{

        let s = vec3<Scalar>(
            select(h.x, -h.x, (5u & 1u) == 0u),
            select(h.y, -h.y, (5u & 2u) == 0u),
            select(h.z, -h.z, (5u & 4u) == 0u),
        );
        out[5u] = b.centre + rotate(b, s);
    }
{

        let s = vec3<Scalar>(
            select(h.x, -h.x, (6u & 1u) == 0u),
            select(h.y, -h.y, (6u & 2u) == 0u),
            select(h.z, -h.z, (6u & 4u) == 0u),
        );
        out[6u] = b.centre + rotate(b, s);
    }
{

        let s = vec3<Scalar>(
            select(h.x, -h.x, (7u & 1u) == 0u),
            select(h.y, -h.y, (7u & 2u) == 0u),
            select(h.z, -h.z, (7u & 4u) == 0u),
        );
        out[7u] = b.centre + rotate(b, s);
    }

    return out;
}

// Box against the plane through p with outward normal n: every corner
// closer than `margin` (feature: the corner's index), reduced to 4.
fn box_plane(b: Placed, h: vec3<Scalar>, p: vec3<Scalar>, n: vec3<Scalar>, margin: Scalar) -> Manifold {
    var hits = Manifold();
    let vs = corners(b, h);
{

        let v = vs[0u];
        let gap = dot3(n, v - p);
        if gap < margin {
            push_hit(&hits, Hit(v - n * (Scalar(0.5) * gap), n, gap, 0u));
        }
    }
{

        let v = vs[1u];
        let gap = dot3(n, v - p);
        if gap < margin {
            push_hit(&hits, Hit(v - n * (Scalar(0.5) * gap), n, gap, 1u));
        }
    }
{

        let v = vs[2u];
        let gap = dot3(n, v - p);
        if gap < margin {
            push_hit(&hits, Hit(v - n * (Scalar(0.5) * gap), n, gap, 2u));
        }
    }
{

        let v = vs[3u];
        let gap = dot3(n, v - p);
        if gap < margin {
            push_hit(&hits, Hit(v - n * (Scalar(0.5) * gap), n, gap, 3u));
        }
    }
{

        let v = vs[4u];
        let gap = dot3(n, v - p);
        if gap < margin {
            push_hit(&hits, Hit(v - n * (Scalar(0.5) * gap), n, gap, 4u));
        }
    }
{

        let v = vs[5u];
        let gap = dot3(n, v - p);
        if gap < margin {
            push_hit(&hits, Hit(v - n * (Scalar(0.5) * gap), n, gap, 5u));
        }
    }
{

        let v = vs[6u];
        let gap = dot3(n, v - p);
        if gap < margin {
            push_hit(&hits, Hit(v - n * (Scalar(0.5) * gap), n, gap, 6u));
        }
    }
{

        let v = vs[7u];
        let gap = dot3(n, v - p);
        if gap < margin {
            push_hit(&hits, Hit(v - n * (Scalar(0.5) * gap), n, gap, 7u));
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

// Signed area of triangle (p0, p1, p) about n.
fn area(p0: vec3<Scalar>, p1: vec3<Scalar>, p: vec3<Scalar>, n: vec3<Scalar>) -> Scalar {
    return dot3(cross3(p1 - p0, p - p0), n);
}

// At most 4 points of a manifold, spread over its area: the deepest, the
// farthest from it, then the two on either side of their line farthest from
// it. Order is kept. Hits read through hit_at (see push_hit).
fn reduce_to_four(hits: Manifold) -> Manifold {
    if hits.len <= 4u {
        return hits;
    }
    let n = hits.hits[0].normal;
    // min_by keeps the first of equals, max_by the last.
    var first = 0u;
    var low = hits.hits[0].gap;
    for (var i = 1u; i < hits.len; i++) {
        let gap = hit_at(hits, i).gap;
        if total_less(gap, low) {
            first = i;
            low = gap;
        }
    }
    let pf = hit_at(hits, first).point;
    var second = 0u;
    var far = dot3(hits.hits[0].point - pf, hits.hits[0].point - pf);
    for (var i = 1u; i < hits.len; i++) {
        let d = hit_at(hits, i).point - pf;
        let di = dot3(d, d);
        if !total_less(di, far) {
            second = i;
            far = di;
        }
    }
    let ps = hit_at(hits, second).point;
    var third = 0u;
    var fourth = 0u;
    var hi = area(pf, ps, hits.hits[0].point, n);
    var lo = hi;
    for (var i = 1u; i < hits.len; i++) {
        let a = area(pf, ps, hit_at(hits, i).point, n);
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
            push_hit(&out, hit_at(hits, i));
        }
    }
    return out;
}

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
{

            if (*poly).len == 0u {
                (*poly).points[0u] = p;
                (*poly).tags[0u] = tag;
            }
        }
{

            if (*poly).len == 1u {
                (*poly).points[1u] = p;
                (*poly).tags[1u] = tag;
            }
        }
{

            if (*poly).len == 2u {
                (*poly).points[2u] = p;
                (*poly).tags[2u] = tag;
            }
        }
{

            if (*poly).len == 3u {
                (*poly).points[3u] = p;
                (*poly).tags[3u] = tag;
            }
        }
{

            if (*poly).len == 4u {
                (*poly).points[4u] = p;
                (*poly).tags[4u] = tag;
            }
        }
{

            if (*poly).len == 5u {
                (*poly).points[5u] = p;
                (*poly).tags[5u] = tag;
            }
        }
{

            if (*poly).len == 6u {
                (*poly).points[6u] = p;
                (*poly).tags[6u] = tag;
            }
        }
{

            if (*poly).len == 7u {
                (*poly).points[7u] = p;
                (*poly).tags[7u] = tag;
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
{

        if k == 1u {
            p = poly.points[1u];
        }
    }
{

        if k == 2u {
            p = poly.points[2u];
        }
    }
{

        if k == 3u {
            p = poly.points[3u];
        }
    }
{

        if k == 4u {
            p = poly.points[4u];
        }
    }
{

        if k == 5u {
            p = poly.points[5u];
        }
    }
{

        if k == 6u {
            p = poly.points[6u];
        }
    }
{

        if k == 7u {
            p = poly.points[7u];
        }
    }

    return p;
}

fn tag_at(poly: Polygon, k: u32) -> u32 {
    var t = poly.tags[0];
{

        if k == 1u {
            t = poly.tags[1u];
        }
    }
{

        if k == 2u {
            t = poly.tags[2u];
        }
    }
{

        if k == 3u {
            t = poly.tags[3u];
        }
    }
{

        if k == 4u {
            t = poly.tags[4u];
        }
    }
{

        if k == 5u {
            t = poly.tags[5u];
        }
    }
{

        if k == 6u {
            t = poly.tags[6u];
        }
    }
{

        if k == 7u {
            t = poly.tags[7u];
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

// Normals of every hit reversed (a pair given the other way round).
fn flip(m: Manifold) -> Manifold {
    var out = m;
{

        if 0u < out.len {
            out.hits[0u].normal = -out.hits[0u].normal;
        }
    }
{

        if 1u < out.len {
            out.hits[1u].normal = -out.hits[1u].normal;
        }
    }
{

        if 2u < out.len {
            out.hits[2u].normal = -out.hits[2u].normal;
        }
    }
{

        if 3u < out.len {
            out.hits[3u].normal = -out.hits[3u].normal;
        }
    }
{

        if 4u < out.len {
            out.hits[4u].normal = -out.hits[4u].normal;
        }
    }
{

        if 5u < out.len {
            out.hits[5u].normal = -out.hits[5u].normal;
        }
    }
{

        if 6u < out.len {
            out.hits[6u].normal = -out.hits[6u].normal;
        }
    }
{

        if 7u < out.len {
            out.hits[7u].normal = -out.hits[7u].normal;
        }
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

// Stage `collide_pairs`.
struct Params {
    first: u32,
    count: u32,
    _pad0: u32,
    _pad1: u32,
}

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> bodies: array<Scalar>;
@group(0) @binding(2) var<storage, read> pairs: array<vec2<u32>>;
@group(0) @binding(3) var<storage, read> margins: array<Scalar>;
@group(0) @binding(4) var<storage, read_write> points: array<Scalar>;
@group(0) @binding(5) var<storage, read_write> keys: array<vec4<u32>>;
@group(0) @binding(6) var<storage, read_write> counts: array<u32>;

fn body_vec3(at: u32) -> vec3<Scalar> {
    return vec3<Scalar>(bodies[at], bodies[at + 1u], bodies[at + 2u]);
}

fn load_placed(body: u32) -> Placed {
    let o = body * BODY;
    let q = vec4<Scalar>(bodies[o + 3u], bodies[o + 4u], bodies[o + 5u], bodies[o + 6u]);
    return placed_from(u32(bodies[o + 7u]), body_vec3(o + 8u), body_vec3(o), q);
}

fn write_vec3(at: u32, v: vec3<Scalar>) {
    points[at] = v.x;
    points[at + 1u] = v.y;
    points[at + 2u] = v.z;
}

@compute @workgroup_size(64)
fn collide_pairs(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= params.count {
        return;
    }
    let pair = params.first + gid.x;
    let ij = pairs[pair];
    let m = collide_shapes(load_placed(ij.x), load_placed(ij.y), margins[pair]);
    // The dynamic body is a (normal from b to a), as world_contacts puts it.
    let swap = bodies[ij.x * BODY + 11u] != Scalar(0.0);
    var a = ij.x;
    var b = ij.y;
    if swap {
        a = ij.y;
        b = ij.x;
    }
    for (var k = 0u; k < min(m.len, SLOTS); k++) {
        let h = m.hits[k];
        let slot = pair * SLOTS + k;
        let o = slot * POINT;
        write_vec3(o, h.point);
        write_vec3(o + 3u, select(h.normal, -h.normal, swap));
        points[o + 6u] = h.gap;
        points[o + 7u] = Scalar(0.0);
        keys[slot] = vec4<u32>(a, b, h.feature, 0u);
    }
    let over = m.overflow || m.len > SLOTS;
    counts[pair] = m.len | select(0u, OVERFLOW, over);
}
