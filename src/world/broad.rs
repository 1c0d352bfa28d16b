//! Broad phase: which pairs of a world's bodies may touch this step.
//! Sweep and prune on x over axis-aligned boxes (each grown by the body's
//! margin): sorting is O(n log n), the sweep visits only pairs whose x
//! intervals overlap, so hundreds of bodies do not cost all n² pairs.
//! Planes (unbounded) are paired with every body that is not static.

use glam::DVec3;

use super::collide::Placed;
use super::Shape;

/// An axis-aligned box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// Lower corner.
    pub min: DVec3,
    /// Upper corner.
    pub max: DVec3,
}

impl Aabb {
    /// The box around a placed shape, grown by `margin` (None for a plane).
    pub fn of(s: &Placed, margin: f64) -> Option<Aabb> {
        let half = match s.shape {
            Shape::Sphere { radius } => DVec3::splat(radius),
            Shape::Box { half_extents } => {
                let r = &s.rotation;
                let h = DVec3::from_array(half_extents);
                // |R| h: the extent of the rotated box along each world axis.
                DVec3::new(
                    r.row(0).abs().dot(h),
                    r.row(1).abs().dot(h),
                    r.row(2).abs().dot(h),
                )
            }
            Shape::Plane { .. } => return None,
        } + DVec3::splat(margin);
        Some(Aabb {
            min: s.centre - half,
            max: s.centre + half,
        })
    }

    /// True when the two boxes overlap (touching counts).
    pub fn overlaps(&self, o: &Aabb) -> bool {
        self.min.cmple(o.max).all() && o.min.cmple(self.max).all()
    }
}

/// The candidate pairs (i < j) among bodies with boxes `aabbs` (None:
/// plane); `active[i]` false (static or asleep) bodies pair only with active
/// ones. Sorted, so the result does not depend on the sweep's order.
pub fn candidate_pairs(aabbs: &[Option<Aabb>], active: &[bool]) -> Vec<(usize, usize)> {
    let mut pairs = Vec::new();
    let planes: Vec<usize> = (0..aabbs.len()).filter(|&i| aabbs[i].is_none()).collect();
    let mut order: Vec<usize> = (0..aabbs.len()).filter(|&i| aabbs[i].is_some()).collect();
    let bx = |i: usize| aabbs[i].expect("bounded");
    order.sort_by(|&i, &j| bx(i).min.x.total_cmp(&bx(j).min.x).then(i.cmp(&j)));
    let mut open: Vec<usize> = Vec::new();
    for &i in &order {
        let b = bx(i);
        open.retain(|&j| bx(j).max.x >= b.min.x);
        for &j in &open {
            if (active[i] || active[j]) && b.overlaps(&bx(j)) {
                pairs.push((i.min(j), i.max(j)));
            }
        }
        open.push(i);
        for &p in &planes {
            if active[i] {
                pairs.push((i.min(p), i.max(p)));
            }
        }
    }
    pairs.sort_unstable();
    pairs
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube(x: f64, y: f64) -> Option<Aabb> {
        Some(Aabb {
            min: DVec3::new(x - 0.5, y - 0.5, -0.5),
            max: DVec3::new(x + 0.5, y + 0.5, 0.5),
        })
    }

    #[test]
    fn the_sweep_finds_exactly_the_overlapping_pairs() {
        // A row of 200 cubes 0.9 apart plus a plane: neighbours overlap.
        let mut boxes: Vec<Option<Aabb>> = (0..200).map(|k| cube(0.9 * k as f64, 0.0)).collect();
        boxes.push(None);
        let mut active = vec![true; 201];
        active[200] = false;
        let pairs = candidate_pairs(&boxes, &active);
        let mut brute = Vec::new();
        for i in 0..200 {
            for j in i + 1..200 {
                if boxes[i].unwrap().overlaps(&boxes[j].unwrap()) {
                    brute.push((i, j));
                }
            }
            brute.push((i, 200));
        }
        brute.sort_unstable();
        assert_eq!(pairs, brute);
        assert_eq!(pairs.len(), 199 + 200);
        // Two inactive bodies are not paired.
        let quiet = vec![false; 201];
        assert!(candidate_pairs(&boxes, &quiet).is_empty());
    }
}
