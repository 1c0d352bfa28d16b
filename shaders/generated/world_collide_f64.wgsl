// GENERATED from shaders/collide.wgsl (functions) + shaders/collide_box.wgsl + shaders/world_step.wgsl + shaders/world_collide.wgsl by src/gpu/shaders/compose.rs: do not edit.
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


// One step of resident worlds (restitution 0): the step's parameters,
// bindings, layouts and shared functions, composed (src/gpu/shaders/
// compose.rs) into one module per phase, each with only what its phase
// calls (naga writes every function of a module that touches no global
// the entry point omits into its SPIR-V: pair functions into the solve,
// Lemke into the collision, had they shared a module). The entry points,
// dispatched in this order in one submission, no host round trip between
// them (src/gpu/resident/dispatch.rs):
// - module world_collide (after shaders/collide.wgsl's functions):
//   `candidate_pairs` per world (src/world/step.rs `prepare`: gravity; the
//   candidates of broad.rs `candidate_pairs`, listed by pair family), the
//   narrow phase per listed pair and family in indirect dispatches
//   (`narrow_box_box`, `narrow_box_plane`, `narrow_sphere`: collide.rs
//   `collide_shapes`' pair functions), `world_contacts` per world (step.rs
//   `world_contacts`: waking rounds, the contacts in pair order);
//   shaders/world_collide.wgsl;
// - module world_solve (after collide.wgsl's functions above its pair
//   functions and shaders/lemke.wgsl's, with shaders/world_bodies.wgsl
//   and world_island.wgsl): `world_solve_warm` per world (src/islands.rs
//   `find_islands`, src/cpu/assembly.rs `assemble_contact` /
//   `assemble_island`, the warm bases of world_cpu.rs `warm_settle`, the
//   door's check `lcp_error` <= tolerance, `apply_impulses`; the islands
//   whose warm basis does not hold, every island without warm bases,
//   listed with their world); shaders/world_solve.wgsl;
// - module world_lemke (the same, shaders/world_lemke.wgsl):
//   `world_lemke` per listed world (its listed islands by Lemke's path
//   `lemke_pivots`, the basis re-solved, the check, the impulses);
// - module world_friction (after the same, shaders/world_bodies.wgsl,
//   world_friction.wgsl, world_apgd.wgsl and friction_common.wgsl's cone
//   projection): `world_friction` per world handed over by the solve, in
//   rounds;
// - module world_finish (shaders/world_bodies.wgsl, world_finish.wgsl):
//   `world_finish` per world (step.rs `finish` with `integrate_rotation`,
//   the world's figures; a world world_friction finished: its reactions
//   remembered first).
// Several entry points rather than one: llvmpipe ends every loop of an
// invocation after about 65,535 iterations in all, and each dispatch
// starts that count afresh; each phase's code is a fraction of the step's
// (a driver compiles each entry point on its own).
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
//   contact slot CP scalars (point 3, normal 3, gap, z), then per contact
//   slot ROW scalars (`row_at`: q, the response M⁻¹Jᵀ of sides a and b,
//   the contact's row of its island's M (world_assemble), the basic
//   variable of its row where Lemke's path ended (world_lemke)); from
//   params.pairs_at per world params.pair_slots pair records of CP scalars
//   (point 3, normal 3, gap, feature), SLOTS per candidate pair;
// - words: per body 2 (asleep, quiet steps); from params.out_at per world 4
//   (contacts, moving-body mask, flags, islands); from params.keys_at per
//   contact slot 4 (a, b, feature, island);
// - records: per world REC scalars (kinetic, potential, max penetration,
//   max error, awake, friction rounds, and the solve's warm-start
//   memory: a hash of last step's contact ids, their bases);
// - scratch, from params.reach_at: per body its reach this step
//   (candidate_pairs);
// - words, from params.cands_at: per world its candidates (their count,
//   then pairs_per_world() bodies i | j << 8, then as many count words of
//   the narrow phase: points | OVERFLOW | CUT);
// - lists: four headers (workgroups x, y, z of an indirect dispatch, the
//   count), then the entries of each list (`list_at`): the worlds
//   `world_solve_warm` leaves to `world_lemke` with their islands (two
//   words each; emptied by candidate_pairs), the box–box, box–plane and sphere pairs
//   (world << 8 | candidate; filled by candidate_pairs, emptied by
//   world_contacts for the next step).

const SCALAR_EPSILON: Scalar = 2.220446049250313e-16; // HOST scalar_epsilon

const MAX_BODIES: u32 = 16u;
const WC: u32 = 6u;
const BC: u32 = 12u;
const BS: u32 = 13u;
const CP: u32 = 8u;
const REC: u32 = 8u;
const ROW: u32 = 30u;
const ISLAND_MAX: u32 = 16u;

const CONTACTS_FULL: u32 = 1u;
const ISLAND_TOO_LARGE: u32 = 2u;
const NOT_SOLVED: u32 = 4u;
const NON_FINITE: u32 = 8u;
const BUDGET: u32 = 16u;
const HANDED: u32 = 32u; // with world_friction until it finishes the world (world_solve.wgsl begin_world)

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
    // The narrow phase's pair records: where they start in `scratch`, and
    // records per world (SLOTS per candidate pair).
    pairs_at: u32,
    pair_slots: u32,
    // 1: world_solve_warm tries last step's bases first (the CPU path's
    // warm_settle: warm starts on, a method that predicts).
    warm_bases: u32,
    // candidate_pairs' lists: where the worlds' candidates start in
    // `words`, where the bodies' reaches start in `scratch`.
    cands_at: u32,
    reach_at: u32,
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
@group(0) @binding(7) var<storage, read_write> lists: array<atomic<u32>>;

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

// Where contact slot `slot`'s row starts in `scratch`: after the contact
// slots (q, response 12, the row of M over the island's members 16, the
// row's basic variable at Lemke's end 1).
fn row_at(slot: u32) -> u32 {
    return sp.contacts_at + sp.count * sp.slots * CP + slot * ROW;
}

// The frictional phase's (shaders/world_friction.wgsl) per-world phases,
// set by the solve's handover (world_solve.wgsl begin_world); F_DONE:
// every island solved, for world_finish to finish.
const F_IDLE: u32 = 0u;
const F_ASSEMBLE: u32 = 1u;
const F_SWEEP: u32 = 2u;
const F_DONE: u32 = 3u;

// μ = √(μ_a μ_b) of bodies ga, gb (global).
fn pair_friction(ga: u32, gb: u32) -> Scalar {
    return sqrt(body_const(ga, 11u) * body_const(gb, 11u));
}

// Work lists in `lists` (header at 4 f: workgroups x, y, z, count): 0
// the worlds world_solve_warm leaves to world_lemke (two words each: the
// world, its islands for Lemke's path), 1 box–box pairs, 2 box–plane
// pairs, 3 pairs with a sphere.
const LIST_LEMKE: u32 = 0u;
const LIST_BOX_BOX: u32 = 1u;
const LIST_BOX_PLANE: u32 = 2u;
const LIST_SPHERE: u32 = 3u;

// Candidates per world at most: SLOTS pair records each.
fn pairs_per_world() -> u32 {
    return sp.pair_slots / SLOTS;
}

// Where list f's entries start in `lists`: after the four headers, the
// Lemke list (two words a world), then the pair lists (pairs_per_world()
// per world each).
fn list_at(f: u32) -> u32 {
    if f == LIST_LEMKE {
        return 16u;
    }
    return 16u + 2u * sp.count + (f - 1u) * sp.count * pairs_per_world();
}

// Appends `entry` to list f, its workgroups (of 64) grown to cover it.
fn push_list(f: u32, entry: u32) {
    let k = atomicAdd(&lists[4u * f + 3u], 1u);
    atomicMax(&lists[4u * f], k / 64u + 1u);
    atomicStore(&lists[list_at(f) + k], entry);
}

// Empties list f (its workgroups 0; y and z stay 1).
fn clear_list(f: u32) {
    atomicStore(&lists[4u * f], 0u);
    atomicStore(&lists[4u * f + 3u], 0u);
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
{

        if 0u < min(m.len, SLOTS) {
            let hit = m.hits[0u];
            let at = sp.pairs_at + (w * sp.pair_slots + SLOTS * c + 0u) * CP;
            put_scratch(at, hit.point);
            put_scratch(at + 3u, select(hit.normal, -hit.normal, flipped));
            scratch[at + 6u] = hit.gap;
            scratch[at + 7u] = Scalar(hit.feature);
        }
    }
{

        if 1u < min(m.len, SLOTS) {
            let hit = m.hits[1u];
            let at = sp.pairs_at + (w * sp.pair_slots + SLOTS * c + 1u) * CP;
            put_scratch(at, hit.point);
            put_scratch(at + 3u, select(hit.normal, -hit.normal, flipped));
            scratch[at + 6u] = hit.gap;
            scratch[at + 7u] = Scalar(hit.feature);
        }
    }
{

        if 2u < min(m.len, SLOTS) {
            let hit = m.hits[2u];
            let at = sp.pairs_at + (w * sp.pair_slots + SLOTS * c + 2u) * CP;
            put_scratch(at, hit.point);
            put_scratch(at + 3u, select(hit.normal, -hit.normal, flipped));
            scratch[at + 6u] = hit.gap;
            scratch[at + 7u] = Scalar(hit.feature);
        }
    }
{

        if 3u < min(m.len, SLOTS) {
            let hit = m.hits[3u];
            let at = sp.pairs_at + (w * sp.pair_slots + SLOTS * c + 3u) * CP;
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
