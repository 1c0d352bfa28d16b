//! Random frictional islands from random contact Jacobians, for tests and
//! benches of the friction solvers (fixed seeds, the same on every
//! platform).

use glam::DVec3;

use super::cone::tangent_basis;
use super::problem::FrictionProblem;
use crate::generate::Rng;

/// One body of a random island: inverse mass and inverse principal inertia
/// (world axes).
struct RandomBody {
    inv_mass: f64,
    inv_inertia: DVec3,
    velocity: DVec3,
    angular_velocity: DVec3,
}

/// One side of a contact row: the body, and the row's linear and angular
/// parts (d and r × d, negated on body b).
type Side = (usize, DVec3, DVec3);

/// A random island of `k` contacts on ⌈k/2⌉ bodies: each contact joins a
/// random body a to another body or the ground (b), with a random unit
/// normal n, random lever arms (|r| ≤ 1), and the tangents of
/// [`tangent_basis`]. Bodies have masses log-uniform in [1, `mass_ratio`]
/// and inertias of a unit-size box of that mass, randomly 1–3× per axis.
/// W = J M⁻¹ Jᵀ (symmetric positive semidefinite, singular where a body
/// carries more contact rows than its 6 degrees of freedom), q = J v for
/// random body velocities (|v|, |ω| ≤ 1 per axis; in the range of J, so a
/// solution exists), μ uniform in [0, 1].
pub fn random_problem(rng: &mut Rng, k: usize, mass_ratio: f64) -> FrictionProblem {
    let k = k.max(1);
    let nb = k.div_ceil(2);
    let bodies: Vec<RandomBody> = (0..nb)
        .map(|_| {
            let m = rng.log_range(1.0, mass_ratio.max(1.0));
            let i0 = m / 6.0;
            RandomBody {
                inv_mass: 1.0 / m,
                inv_inertia: DVec3::new(
                    1.0 / (i0 * rng.range(1.0, 3.0)),
                    1.0 / (i0 * rng.range(1.0, 3.0)),
                    1.0 / (i0 * rng.range(1.0, 3.0)),
                ),
                velocity: rng.vector(1.0),
                angular_velocity: rng.vector(1.0),
            }
        })
        .collect();
    // rows[3i + a]: the sides of contact i's row a (normal, t1, t2).
    let mut rows: Vec<Vec<Side>> = Vec::with_capacity(3 * k);
    for _ in 0..k {
        let a = rng.int(0, nb - 1);
        let b = rng.int(0, nb); // nb: the ground
        let n = rng.unit_vector();
        let (t1, t2) = tangent_basis(n);
        let ra = rng.vector(1.0);
        let rb = rng.vector(1.0);
        for d in [n, t1, t2] {
            let mut sides = vec![(a, d, ra.cross(d))];
            if b < nb && b != a {
                sides.push((b, -d, -rb.cross(d)));
            }
            rows.push(sides);
        }
    }
    let n = 3 * k;
    let mut w = vec![0.0; n * n];
    for r in 0..n {
        for s in 0..n {
            let mut v = 0.0;
            for &(br, lr, ar) in &rows[r] {
                for &(bs, ls, as_) in &rows[s] {
                    if br == bs {
                        let body = &bodies[br];
                        v += body.inv_mass * lr.dot(ls) + (ar * body.inv_inertia).dot(as_);
                    }
                }
            }
            w[r * n + s] = v;
        }
    }
    // q = J v: in the range of J, so the convex problem has a solution.
    let q = rows
        .iter()
        .map(|sides| {
            sides
                .iter()
                .map(|&(b, l, a)| l.dot(bodies[b].velocity) + a.dot(bodies[b].angular_velocity))
                .sum()
        })
        .collect();
    let mu = (0..k).map(|_| rng.unit()).collect();
    FrictionProblem { w, q, mu }
}

/// `count` islands of `k` contacts each (`random_problem`, mass ratios 1,
/// 10 and 100 in turn) from `seed`.
pub fn random_problems(seed: u64, count: usize, k: usize) -> Vec<FrictionProblem> {
    let mut rng = Rng::new(seed);
    (0..count)
        .map(|i| random_problem(&mut rng, k, [1.0, 10.0, 100.0][i % 3]))
        .collect()
}
