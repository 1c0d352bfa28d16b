//! Box–box contact: the separating axis test over the 15 axes (3 faces of
//! each box, 9 edge pairs), then face clipping (the incident face of one box
//! clipped by the side planes of the other's reference face, up to 8 points
//! reduced to 4) or, when an edge pair separates best, the closest points of
//! the two edges. Faces are preferred unless an edge axis separates clearly
//! better (Box2D's relative 0.98 and an absolute 10⁻³ of the boxes' size),
//! so that a resting box keeps the same 4 feature ids step after step.
//!
//! Clipping keeps a vertex that lies outside a side plane by less than
//! [`CLIP_TOL`] times the reference box's size, as it is: two equal boxes stacked face to face have their
//! incident vertices exactly on the reference's side planes, where the
//! rounding of the poses would otherwise keep a vertex one step (its id a
//! vertex's) and cut it the next (its id a clipping's), and warm start,
//! which finds contacts by id, would miss every such step. Such a point
//! lies at most that tolerance outside the reference face; no point moves.
//!
//! Polygons and manifolds live on the stack: no allocation per pair.

use glam::DVec3;

use super::collide::{reduce_to_four, Hit, Manifold, Placed};

/// Relative tolerance of the clipping (see the module docs): 10⁻⁷ of the
/// reference box's largest half extent (0.05 µm for a unit box).
pub(super) const CLIP_TOL: f64 = 1e-7;

/// Which axis separates best, and by how much.
#[derive(Clone, Copy, Debug)]
enum Axis {
    /// Face `i` of box x (`of_x` true) or of box y.
    Face { of_x: bool, i: usize },
    /// Edge i of x against edge j of y; the unit axis from x towards y.
    Edge { i: usize, j: usize, axis: DVec3 },
}

/// The projection radius of a box (axes `r`, half extents h) on unit `u`.
fn radius(r: &glam::DMat3, h: DVec3, u: DVec3) -> f64 {
    (0..3).map(|k| h[k] * r.col(k).dot(u).abs()).sum()
}

/// The best separating axis, or None when some axis separates by ≥ margin.
fn best_axis(x: &Placed, hx: DVec3, y: &Placed, hy: DVec3, margin: f64) -> Option<Axis> {
    let d = y.centre - x.centre;
    let (rx, ry) = (&x.rotation, &y.rotation);
    let mut face: Option<Axis> = None;
    let mut face_sep = f64::NEG_INFINITY;
    for of_x in [true, false] {
        for i in 0..3 {
            let u = if of_x { rx.col(i) } else { ry.col(i) };
            let sep = d.dot(u).abs() - radius(rx, hx, u) - radius(ry, hy, u);
            if sep >= margin {
                return None;
            }
            // x's faces first; y's face only when clearly better.
            let tol = 1e-3 * hx.max_element().max(hy.max_element());
            let better = match face {
                None => true,
                Some(Axis::Face { of_x: true, .. }) if !of_x => sep > 0.98 * face_sep + tol,
                _ => sep > face_sep,
            };
            if better {
                face = Some(Axis::Face { of_x, i });
                face_sep = sep;
            }
        }
    }
    let mut edge: Option<Axis> = None;
    let mut edge_sep = f64::NEG_INFINITY;
    for i in 0..3 {
        for j in 0..3 {
            let u = rx.col(i).cross(ry.col(j));
            let len = u.length();
            if len < 1e-6 {
                continue; // parallel edges: a face axis covers them
            }
            let mut u = u / len;
            if u.dot(d) < 0.0 {
                u = -u;
            }
            let sep = d.dot(u) - radius(rx, hx, u) - radius(ry, hy, u);
            if sep >= margin {
                return None;
            }
            if sep > edge_sep {
                edge = Some(Axis::Edge { i, j, axis: u });
                edge_sep = sep;
            }
        }
    }
    let tol = 1e-3 * hx.max_element().max(hy.max_element());
    match edge {
        Some(e) if edge_sep > 0.98 * face_sep + tol => Some(e),
        _ => face,
    }
}

/// Box x against box y, normals from y to x; see the module docs.
pub(super) fn box_box(x: &Placed, hx: DVec3, y: &Placed, hy: DVec3, margin: f64) -> Manifold {
    match best_axis(x, hx, y, hy, margin) {
        None => Manifold::new(),
        Some(Axis::Face { of_x: true, i, .. }) => face_contact(x, hx, y, hy, i, margin, false),
        Some(Axis::Face { of_x: false, i, .. }) => face_contact(y, hy, x, hx, i, margin, true),
        Some(Axis::Edge { i, j, axis, .. }) => edge_contact(x, hx, y, hy, i, j, axis, margin),
    }
}

/// A point of the clipped polygon and its tag (which incident vertex, or
/// which side plane cut which edge), for the feature id.
type Tagged = (DVec3, u16);

/// A convex polygon of at most 8 tagged points (a quad clipped by 4 planes
/// gains at most one point per plane), on the stack.
#[derive(Clone, Copy)]
struct Polygon {
    points: [Tagged; 8],
    len: usize,
}

impl Polygon {
    fn new() -> Self {
        Polygon {
            points: [(DVec3::ZERO, 0); 8],
            len: 0,
        }
    }

    fn push(&mut self, p: Tagged) {
        assert!(self.len < 8, "a clipped quad has at most 8 points");
        self.points[self.len] = p;
        self.len += 1;
    }

    fn as_slice(&self) -> &[Tagged] {
        &self.points[..self.len]
    }
}

/// Clipping of the incident face of box `inc` by the side planes of face
/// `axis` of box `re` (the reference). Normals from y to x: the reference's
/// face normal points towards the incident box, so when the reference is x
/// (`ref_is_y` false) the normal is its negative.
// Seven parameters: the two boxes with their half extents, the axis, the
// margin and which of the pair is the reference; grouping them would only
// rename them.
#[allow(clippy::too_many_arguments)]
fn face_contact(
    re: &Placed,
    hr: DVec3,
    inc: &Placed,
    hi: DVec3,
    axis: usize,
    margin: f64,
    ref_is_y: bool,
) -> Manifold {
    let d = inc.centre - re.centre;
    let mut n = re.rotation.col(axis);
    let ref_face = 2 * axis + usize::from(n.dot(d) < 0.0);
    if n.dot(d) < 0.0 {
        n = -n;
    }
    // Incident face: the face of inc most anti-parallel to n.
    let dots = [0, 1, 2].map(|k| inc.rotation.col(k).dot(n));
    let k = (0..3)
        .max_by(|&a, &b| dots[a].abs().total_cmp(&dots[b].abs()))
        .expect("3 axes");
    let s = if dots[k] > 0.0 { -1.0 } else { 1.0 };
    let inc_face = 2 * k + usize::from(s < 0.0);
    let (u, v) = ((k + 1) % 3, (k + 2) % 3);
    let fc = inc.centre + inc.rotation.col(k) * (s * hi[k]);
    let eu = inc.rotation.col(u) * hi[u];
    let ev = inc.rotation.col(v) * hi[v];
    let mut poly = Polygon::new();
    for p in [
        (fc + eu + ev, 0),
        (fc - eu + ev, 1),
        (fc - eu - ev, 2),
        (fc + eu - ev, 3),
    ] {
        poly.push(p);
    }
    // Side planes of the reference face: ±t at distance h_t from the centre.
    let tol = CLIP_TOL * hr.max_element();
    let mut side = 0u16;
    for t in (0..3).filter(|&t| t != axis) {
        for sign in [1.0, -1.0] {
            let pn = re.rotation.col(t) * sign;
            let off = pn.dot(re.centre) + hr[t];
            poly = clip(poly.as_slice(), (pn, off), tol, side);
            side += 1;
        }
    }
    let face_point = re.centre + n * hr[axis];
    let normal = if ref_is_y { n } else { -n };
    let base = (u16::from(ref_is_y) << 11) | ((ref_face as u16) << 8) | ((inc_face as u16) << 5);
    let mut hits = Manifold::new();
    for &(p, tag) in poly.as_slice() {
        let gap = n.dot(p - face_point);
        if gap < margin {
            hits.push(Hit {
                point: p - n * (0.5 * gap),
                normal,
                gap,
                feature: base | (tag & 31),
            });
        }
    }
    reduce_to_four(hits)
}

/// Sutherland–Hodgman with a tolerance: the part of `poly` with
/// pn·p ≤ off, where a vertex outside by at most `tol` is kept as it is
/// (and then stands for the crossing on its edges). A point made on the
/// plane is tagged 4 + 4·side + (the edge's first vertex's tag mod 4).
fn clip(poly: &[Tagged], plane: (DVec3, f64), tol: f64, side: u16) -> Polygon {
    let (pn, off) = plane;
    let mut out = Polygon::new();
    for (k, &(p, tp)) in poly.iter().enumerate() {
        let (q, _) = poly[(k + 1) % poly.len()];
        let dp = pn.dot(p) - off;
        let dq = pn.dot(q) - off;
        if dp <= tol {
            out.push((p, tp));
        }
        // Crossing: the kept end is inside (d ≤ 0), the other beyond tol,
        // so t ∈ [0, 1]; a kept end within tol is the crossing itself.
        if (dp <= tol) != (dq <= tol) && dp.min(dq) <= 0.0 {
            let t = dp / (dp - dq);
            out.push((p + (q - p) * t, 4 + 4 * side + (tp & 3)));
        }
    }
    out
}

/// Edge i of x against edge j of y along `axis` (from x to y): the closest
/// points of the two supporting edges, one contact.
// Eight parameters: the pair with half extents, the two edge directions,
// the axis and the margin, as `best_axis` found them.
#[allow(clippy::too_many_arguments)]
fn edge_contact(
    x: &Placed,
    hx: DVec3,
    y: &Placed,
    hy: DVec3,
    i: usize,
    j: usize,
    axis: DVec3,
    margin: f64,
) -> Manifold {
    // The edge of x farthest along the axis, the edge of y farthest against it.
    let mut pa = x.centre;
    let mut pb = y.centre;
    for k in 0..3 {
        if k != i {
            let c = x.rotation.col(k);
            pa += c * (hx[k] * c.dot(axis).signum());
        }
        if k != j {
            let c = y.rotation.col(k);
            pb -= c * (hy[k] * c.dot(axis).signum());
        }
    }
    let (da, db) = (x.rotation.col(i), y.rotation.col(j));
    // Closest points of the lines pa + s da and pb + t db (unit directions).
    let r = pa - pb;
    let b = da.dot(db);
    let denom = 1.0 - b * b;
    let (c, f) = (da.dot(r), db.dot(r));
    let s = if denom > 1e-12 {
        ((b * f - c) / denom).clamp(-hx[i], hx[i])
    } else {
        0.0
    };
    let t = (b * s + f).clamp(-hy[j], hy[j]);
    let qa = pa + da * s;
    let qb = pb + db * t;
    let gap = (qb - qa).dot(axis);
    if gap >= margin {
        return Manifold::new();
    }
    Manifold::one(Hit {
        point: (qa + qb) * 0.5,
        normal: -axis,
        gap,
        feature: (7 << 8) | (3 * i + j) as u16,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::world::Shape;
    use glam::DQuat;

    fn cube(centre: DVec3, q: DQuat, h: f64) -> Placed {
        Placed::new(
            Shape::Box {
                half_extents: [h; 3],
            },
            centre,
            q,
        )
    }

    #[test]
    fn a_box_resting_on_a_box_touches_at_four_corners() {
        // Unit cube on a 2×2×2 cube, 0.01 deep, shifted by 0.2 in x.
        let top = cube(DVec3::new(0.2, 1.49, 0.0), DQuat::IDENTITY, 0.5);
        let bottom = cube(DVec3::ZERO, DQuat::IDENTITY, 1.0);
        let h = box_box(&top, DVec3::splat(0.5), &bottom, DVec3::splat(1.0), 0.005);
        assert_eq!(h.len(), 4, "{h:?}");
        for hit in &h {
            assert!((hit.gap + 0.01).abs() < 1e-12, "{hit:?}");
            assert!((hit.normal - DVec3::Y).length() < 1e-12);
            assert!((hit.point.y - 0.995).abs() < 1e-12);
            assert!(((hit.point.x - 0.2).abs() - 0.5).abs() < 1e-12);
            assert!((hit.point.z.abs() - 0.5).abs() < 1e-12);
        }
        let mut ids: Vec<u16> = h.iter().map(|x| x.feature).collect();
        ids.sort_unstable();
        ids.dedup();
        assert_eq!(ids.len(), 4, "distinct feature ids");
        // The same pair the other way round: the same points, normals flipped.
        let g = box_box(&bottom, DVec3::splat(1.0), &top, DVec3::splat(0.5), 0.005);
        assert_eq!(g.len(), 4);
        assert!(g.iter().all(|x| (x.normal + DVec3::Y).length() < 1e-12));
    }

    #[test]
    fn an_overhanging_box_is_clipped_to_the_overlap() {
        // Top cube shifted by 1.2: its face overlaps [0.7, 1.0] in x.
        let top = cube(DVec3::new(1.2, 1.5, 0.0), DQuat::IDENTITY, 0.5);
        let bottom = cube(DVec3::ZERO, DQuat::IDENTITY, 1.0);
        let h = box_box(&top, DVec3::splat(0.5), &bottom, DVec3::splat(1.0), 0.005);
        assert_eq!(h.len(), 4);
        let mut xs: Vec<f64> = h.iter().map(|x| x.point.x).collect();
        xs.sort_by(f64::total_cmp);
        assert!(
            (xs[0] - 0.7).abs() < 1e-12 && (xs[3] - 1.0).abs() < 1e-12,
            "{xs:?}"
        );
        assert!(h.iter().all(|x| x.gap.abs() < 1e-12));
    }

    #[test]
    fn crossed_edges_touch_at_one_point() {
        // Cube x rotated 45° about z, cube y rotated 45° about x, y above x:
        // x's top edge (along z) crosses y's bottom edge (along x).
        let s = 0.5 * 2f64.sqrt();
        let x = cube(
            DVec3::ZERO,
            DQuat::from_rotation_z(std::f64::consts::FRAC_PI_4),
            0.5,
        );
        let y = cube(
            DVec3::new(0.0, 2.0 * s - 0.02, 0.0),
            DQuat::from_rotation_x(std::f64::consts::FRAC_PI_4),
            0.5,
        );
        let h = box_box(&x, DVec3::splat(0.5), &y, DVec3::splat(0.5), 0.005);
        assert_eq!(h.len(), 1, "{h:?}");
        assert!((h[0].gap + 0.02).abs() < 1e-12, "{:?}", h[0]);
        assert!(
            (h[0].normal + DVec3::Y).length() < 1e-9,
            "normal from y to x"
        );
        assert!((h[0].point - DVec3::new(0.0, s - 0.01, 0.0)).length() < 1e-9);
    }

    #[test]
    fn separated_boxes_give_nothing() {
        let x = cube(DVec3::ZERO, DQuat::IDENTITY, 0.5);
        let y = cube(DVec3::new(0.0, 1.1, 0.0), DQuat::from_rotation_y(0.3), 0.5);
        assert!(box_box(&x, DVec3::splat(0.5), &y, DVec3::splat(0.5), 0.05).is_empty());
    }

    /// Two equal boxes face to face: rounding-size changes of the pose keep
    /// the same 4 points and feature ids (warm start finds them by id).
    #[test]
    fn equal_stacked_boxes_keep_their_feature_ids_under_rounding() {
        let h = DVec3::splat(0.5);
        let bottom = cube(DVec3::new(0.0, 0.5, 0.0), DQuat::IDENTITY, 0.5);
        let ids = |top: &Placed| {
            let m = box_box(top, h, &bottom, h, 0.005);
            let mut f: Vec<u16> = m.iter().map(|x| x.feature).collect();
            f.sort_unstable();
            f
        };
        let exact = ids(&cube(DVec3::new(0.0, 1.5, 0.0), DQuat::IDENTITY, 0.5));
        assert_eq!(exact.len(), 4);
        for (dx, dz, angle) in [
            (1e-15, -1e-15, 0.0),
            (-3e-16, 2e-15, 1e-15),
            (2e-12, 0.0, -1e-13),
            (-1e-9, 1e-9, 1e-12),
        ] {
            let q = DQuat::from_rotation_y(angle);
            let top = cube(DVec3::new(dx, 1.5 - 1e-12, dz), q, 0.5);
            assert_eq!(ids(&top), exact, "offset ({dx}, {dz}), angle {angle}");
        }
    }
}
