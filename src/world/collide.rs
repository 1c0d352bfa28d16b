//! Contact generation for the world's shapes: sphere–plane, sphere–sphere,
//! box–plane, sphere–box and box–box (in `collide_box.rs`), each giving up
//! to 4 points with the signed gap φ (negative: penetration).
//!
//! Own code rather than parry3d: five closed-form primitives on glam's f64
//! types, no conversion to and from nalgebra per body per step, and feature
//! ids (which vertex, which face) under our control so that contact ids
//! persist across steps for warm start.
//!
//! Conventions (those of [`crate::scene`] and the README's scene format):
//! the normal points from body b to body a; the
//! point is midway between the two surfaces; φ is the distance between the
//! surfaces along the normal.

use glam::{DMat3, DVec3};

use super::{RigidBody, Shape};

/// Most bodies a world may hold (body indices take 16 bits of a contact id).
pub const MAX_BODIES: usize = 1 << 16;

/// A contact point found between bodies a and b of one world.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactPoint {
    /// Body a (the normal points towards it).
    pub a: usize,
    /// Body b.
    pub b: usize,
    /// Midway between the two surfaces (world frame).
    pub point: DVec3,
    /// Unit normal from b to a.
    pub normal: DVec3,
    /// Signed gap φ along the normal (negative: penetration).
    pub gap: f64,
    /// Which features touch (vertex, face, edge pair), < 4096; with a and b
    /// it names the contact across steps.
    pub feature: u16,
}

/// A point of a pair's manifold before the body indices are attached.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Hit {
    pub point: DVec3,
    /// From the second shape to the first.
    pub normal: DVec3,
    pub gap: f64,
    pub feature: u16,
}

/// Up to [`Manifold::CAPACITY`] points of one pair, on the stack (no
/// allocation per pair): what the narrow phase returns, at most 4 after
/// [`reduce_to_four`]. Reads as a slice of [`Hit`]s.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Manifold {
    hits: [Hit; Manifold::CAPACITY],
    len: usize,
}

impl Manifold {
    /// The most points a pair's candidates can hold (8 box corners; a face
    /// quad clipped by 4 side planes).
    pub const CAPACITY: usize = 8;

    /// No points.
    pub fn new() -> Self {
        const NONE: Hit = Hit {
            point: DVec3::ZERO,
            normal: DVec3::ZERO,
            gap: 0.0,
            feature: 0,
        };
        Manifold {
            hits: [NONE; Manifold::CAPACITY],
            len: 0,
        }
    }

    /// One point.
    pub fn one(h: Hit) -> Self {
        let mut m = Manifold::new();
        m.push(h);
        m
    }

    /// Adds a point (a full manifold is a bug of the caller: every
    /// producer makes at most `CAPACITY`).
    pub fn push(&mut self, h: Hit) {
        assert!(
            self.len < Self::CAPACITY,
            "a manifold holds at most 8 points"
        );
        self.hits[self.len] = h;
        self.len += 1;
    }
}

impl std::ops::Deref for Manifold {
    type Target = [Hit];
    fn deref(&self) -> &[Hit] {
        &self.hits[..self.len]
    }
}

impl std::ops::DerefMut for Manifold {
    fn deref_mut(&mut self) -> &mut [Hit] {
        &mut self.hits[..self.len]
    }
}

impl<'a> IntoIterator for &'a Manifold {
    type Item = &'a Hit;
    type IntoIter = std::slice::Iter<'a, Hit>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

/// A shape placed in the world.
#[derive(Clone, Copy, Debug)]
pub struct Placed {
    /// The shape.
    pub shape: Shape,
    /// Centre (a point on a plane).
    pub centre: DVec3,
    /// Body-to-world rotation (columns: the body's axes).
    pub rotation: DMat3,
}

impl Placed {
    /// The body's shape at its pose.
    pub fn of(body: &RigidBody) -> Self {
        Placed {
            shape: body.shape,
            centre: body.position(),
            rotation: DMat3::from_quat(body.rotation()),
        }
    }

    /// A shape at `centre` rotated by `q`.
    #[cfg(test)]
    pub fn new(shape: Shape, centre: DVec3, q: glam::DQuat) -> Self {
        Placed {
            shape,
            centre,
            rotation: DMat3::from_quat(q),
        }
    }
}

/// The contact points of shapes `x` and `y` closer than `margin`, normals
/// from y to x. Two planes (or an unsupported pair) give none.
pub(crate) fn collide_shapes(x: &Placed, y: &Placed, margin: f64) -> Manifold {
    use Shape::*;
    let flip = |mut hits: Manifold| -> Manifold {
        hits.iter_mut().for_each(|h| h.normal = -h.normal);
        hits
    };
    match (x.shape, y.shape) {
        (Sphere { radius: r }, Plane { normal }) => {
            sphere_plane(x.centre, r, y.centre, DVec3::from_array(normal), margin)
        }
        (Plane { normal }, Sphere { radius: r }) => flip(sphere_plane(
            y.centre,
            r,
            x.centre,
            DVec3::from_array(normal),
            margin,
        )),
        (Sphere { radius: ra }, Sphere { radius: rb }) => {
            sphere_sphere(x.centre, ra, y.centre, rb, margin)
        }
        (Box { half_extents: h }, Plane { normal }) => box_plane(
            x,
            DVec3::from_array(h),
            y.centre,
            DVec3::from_array(normal),
            margin,
        ),
        (Plane { normal }, Box { half_extents: h }) => flip(box_plane(
            y,
            DVec3::from_array(h),
            x.centre,
            DVec3::from_array(normal),
            margin,
        )),
        (Sphere { radius: r }, Box { half_extents: h }) => {
            sphere_box(x.centre, r, y, DVec3::from_array(h), margin)
        }
        (Box { half_extents: h }, Sphere { radius: r }) => {
            flip(sphere_box(y.centre, r, x, DVec3::from_array(h), margin))
        }
        (Box { half_extents: ha }, Box { half_extents: hb }) => {
            super::collide_box::box_box(x, DVec3::from_array(ha), y, DVec3::from_array(hb), margin)
        }
        (Plane { .. }, Plane { .. }) => Manifold::new(),
    }
}

/// Sphere (centre c, radius r) against the plane through p with outward
/// normal n: φ = n·(c − p) − r, normal n (plane to sphere).
pub(super) fn sphere_plane(c: DVec3, r: f64, p: DVec3, n: DVec3, margin: f64) -> Manifold {
    let gap = n.dot(c - p) - r;
    if gap >= margin {
        return Manifold::new();
    }
    Manifold::one(Hit {
        point: c - n * (r + 0.5 * gap),
        normal: n,
        gap,
        feature: 0,
    })
}

/// Sphere a against sphere b: φ = |c_a − c_b| − r_a − r_b, normal along
/// c_a − c_b (+y when the centres coincide).
pub(super) fn sphere_sphere(ca: DVec3, ra: f64, cb: DVec3, rb: f64, margin: f64) -> Manifold {
    let d = ca - cb;
    let dist = d.length();
    let gap = dist - ra - rb;
    if gap >= margin {
        return Manifold::new();
    }
    let normal = if dist > 0.0 { d / dist } else { DVec3::Y };
    Manifold::one(Hit {
        point: cb + normal * (rb + 0.5 * gap),
        normal,
        gap,
        feature: 0,
    })
}

/// The 8 corners of a box (half extents h), corner k having sign −/+ on
/// axis i as bit i of k is 0/1.
pub(super) fn corners(b: &Placed, h: DVec3) -> [DVec3; 8] {
    std::array::from_fn(|k| {
        let s = DVec3::new(
            if k & 1 == 0 { -h.x } else { h.x },
            if k & 2 == 0 { -h.y } else { h.y },
            if k & 4 == 0 { -h.z } else { h.z },
        );
        b.centre + b.rotation * s
    })
}

/// Box against the plane through p with outward normal n: every corner
/// closer than `margin` (feature: the corner's index), reduced to 4.
pub(super) fn box_plane(b: &Placed, h: DVec3, p: DVec3, n: DVec3, margin: f64) -> Manifold {
    let mut hits = Manifold::new();
    for (k, &v) in corners(b, h).iter().enumerate() {
        let gap = n.dot(v - p);
        if gap < margin {
            hits.push(Hit {
                point: v - n * (0.5 * gap),
                normal: n,
                gap,
                feature: k as u16,
            });
        }
    }
    reduce_to_four(hits)
}

/// Sphere (centre c, radius r) against a box: the closest point of the box
/// to the centre; a centre inside the box leaves through the nearest face.
/// Normal from the box to the sphere.
pub(super) fn sphere_box(c: DVec3, r: f64, b: &Placed, h: DVec3, margin: f64) -> Manifold {
    let local = b.rotation.transpose() * (c - b.centre);
    let clamped = local.clamp(-h, h);
    let (surface, normal_local, dist) = if clamped != local {
        let d = local - clamped;
        let len = d.length();
        (clamped, d / len, len)
    } else {
        // Inside: the face with the least depth h_i − |x_i|.
        let depth = h - local.abs();
        let i = if depth.x <= depth.y && depth.x <= depth.z {
            0
        } else if depth.y <= depth.z {
            1
        } else {
            2
        };
        let sign = if local[i] >= 0.0 { 1.0 } else { -1.0 };
        let mut surface = local;
        surface[i] = sign * h[i];
        let mut n = DVec3::ZERO;
        n[i] = sign;
        (surface, n, -depth[i])
    };
    let gap = dist - r;
    if gap >= margin {
        return Manifold::new();
    }
    let normal = b.rotation * normal_local;
    let on_box = b.centre + b.rotation * surface;
    Manifold::one(Hit {
        point: on_box + normal * (0.5 * gap),
        normal,
        gap,
        feature: 0,
    })
}

/// At most 4 points of a manifold, spread over its area: the deepest, the
/// farthest from it, then the two on either side of their line farthest from
/// it (the largest quadrilateral these choices give). Order is kept.
pub(super) fn reduce_to_four(hits: Manifold) -> Manifold {
    if hits.len() <= 4 {
        return hits;
    }
    let n = hits[0].normal;
    let first = (0..hits.len())
        .min_by(|&i, &j| hits[i].gap.total_cmp(&hits[j].gap))
        .expect("non-empty");
    let p = |i: usize| hits[i].point;
    let second = (0..hits.len())
        .max_by(|&i, &j| {
            p(i).distance_squared(p(first))
                .total_cmp(&p(j).distance_squared(p(first)))
        })
        .expect("non-empty");
    // Signed area of triangle (first, second, i) about the normal.
    let area = |i: usize| (p(second) - p(first)).cross(p(i) - p(first)).dot(n);
    let third = (0..hits.len())
        .max_by(|&i, &j| area(i).total_cmp(&area(j)))
        .expect("non-empty");
    let fourth = (0..hits.len())
        .min_by(|&i, &j| area(i).total_cmp(&area(j)))
        .expect("non-empty");
    let mut keep = [first, second, third, fourth];
    keep.sort_unstable();
    let mut out = Manifold::new();
    for (k, &i) in keep.iter().enumerate() {
        if k == 0 || keep[k - 1] != i {
            out.push(hits[i]);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DQuat;

    fn close(a: DVec3, b: DVec3) -> bool {
        (a - b).length() < 1e-12
    }

    #[test]
    fn sphere_on_a_plane_by_hand() {
        // Radius 0.5 at height 0.4 over the ground: 0.1 deep.
        let h = sphere_plane(DVec3::new(1.0, 0.4, 2.0), 0.5, DVec3::ZERO, DVec3::Y, 0.01);
        assert_eq!(h.len(), 1);
        assert!((h[0].gap + 0.1).abs() < 1e-15);
        assert!(close(h[0].normal, DVec3::Y));
        assert!(close(h[0].point, DVec3::new(1.0, -0.05, 2.0)));
        assert!(
            sphere_plane(DVec3::new(0.0, 0.52, 0.0), 0.5, DVec3::ZERO, DVec3::Y, 0.01).is_empty()
        );
    }

    #[test]
    fn two_spheres_by_hand() {
        // Centres 1.5 apart along x, radii 1 and 1: 0.5 deep, normal from b to a.
        let h = sphere_sphere(DVec3::new(1.5, 0.0, 0.0), 1.0, DVec3::ZERO, 1.0, 0.0);
        assert_eq!(h.len(), 1);
        assert!((h[0].gap + 0.5).abs() < 1e-15);
        assert!(close(h[0].normal, DVec3::X));
        assert!(close(h[0].point, DVec3::new(0.75, 0.0, 0.0)));
    }

    #[test]
    fn box_on_a_plane_by_hand() {
        // Unit cube (h = 0.5) at height 0.49: four corners 0.01 deep.
        let b = Placed::new(
            Shape::Box {
                half_extents: [0.5; 3],
            },
            DVec3::new(0.0, 0.49, 0.0),
            DQuat::IDENTITY,
        );
        let h = box_plane(&b, DVec3::splat(0.5), DVec3::ZERO, DVec3::Y, 0.005);
        assert_eq!(h.len(), 4);
        for hit in &h {
            assert!((hit.gap + 0.01).abs() < 1e-14);
            assert!(close(hit.normal, DVec3::Y));
            assert!((hit.point.y + 0.005).abs() < 1e-14);
            assert!(
                (hit.point.x.abs() - 0.5).abs() < 1e-14 && (hit.point.z.abs() - 0.5).abs() < 1e-14
            );
            assert_eq!(hit.feature & 2, 0, "bottom corners have bit 1 clear");
        }
        // Tilted 45° about z: one edge (corners 0 and 4) touches.
        let q = DQuat::from_rotation_z(std::f64::consts::FRAC_PI_4);
        let b = Placed::new(b.shape, DVec3::new(0.0, 0.5f64.sqrt(), 0.0), q);
        let h = box_plane(&b, DVec3::splat(0.5), DVec3::ZERO, DVec3::Y, 0.005);
        assert_eq!(h.len(), 2);
        assert!(h.iter().all(|x| x.gap.abs() < 1e-12));
    }

    #[test]
    fn sphere_against_a_box_by_hand() {
        let b = Placed::new(
            Shape::Box {
                half_extents: [1.0, 0.5, 1.0],
            },
            DVec3::ZERO,
            DQuat::IDENTITY,
        );
        let h = DVec3::new(1.0, 0.5, 1.0);
        // Over the top face, 0.05 deep.
        let hit = sphere_box(DVec3::new(0.2, 0.75, 0.0), 0.3, &b, h, 0.0);
        assert_eq!(hit.len(), 1);
        assert!((hit[0].gap + 0.05).abs() < 1e-15);
        assert!(close(hit[0].normal, DVec3::Y));
        assert!(close(hit[0].point, DVec3::new(0.2, 0.475, 0.0)));
        // Off a corner: the closest point is the corner (1, 0.5, 1).
        let c = DVec3::new(1.0, 0.5, 1.0) + DVec3::splat(0.2 / 3f64.sqrt());
        let hit = sphere_box(c, 0.25, &b, h, 0.0);
        assert!((hit[0].gap + 0.05).abs() < 1e-14);
        assert!(close(hit[0].normal, DVec3::splat(1.0 / 3f64.sqrt())));
        // Centre inside, nearest the top face: pushed out upwards.
        let hit = sphere_box(DVec3::new(0.0, 0.4, 0.0), 0.1, &b, h, 0.0);
        assert!((hit[0].gap + 0.2).abs() < 1e-15);
        assert!(close(hit[0].normal, DVec3::Y));
    }

    #[test]
    fn flipped_pairs_point_the_other_way() {
        let s = Placed::new(
            Shape::Sphere { radius: 0.5 },
            DVec3::new(0.0, 0.4, 0.0),
            DQuat::IDENTITY,
        );
        let p = Placed::new(
            Shape::Plane {
                normal: [0.0, 1.0, 0.0],
            },
            DVec3::ZERO,
            DQuat::IDENTITY,
        );
        let a = collide_shapes(&s, &p, 0.0);
        let b = collide_shapes(&p, &s, 0.0);
        assert!(close(a[0].normal, -b[0].normal) && a[0].gap == b[0].gap);
    }
}
