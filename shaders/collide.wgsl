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

alias Scalar = f32; // HOST scalar

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
        for (var s = 0u; s < CAPACITY; s++) { // UNROLL
            if (*m).len == s {
                (*m).hits[s] = h;
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
    for (var s = 1u; s < CAPACITY; s++) { // UNROLL
        if k == s {
            h = m.hits[s];
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
    for (var k = 0u; k < 8u; k++) { // UNROLL
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
    for (var k = 0u; k < 8u; k++) { // UNROLL
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

// BOX-BOX: shaders/collide_box.wgsl

// Normals of every hit reversed (a pair given the other way round).
fn flip(m: Manifold) -> Manifold {
    var out = m;
    for (var k = 0u; k < CAPACITY; k++) { // UNROLL
        if k < out.len {
            out.hits[k].normal = -out.hits[k].normal;
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
