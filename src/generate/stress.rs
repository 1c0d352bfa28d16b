//! Stress families: contact LCPs that are badly conditioned, degenerate,
//! without a P-matrix, or without any solution, from fixed seeds. Every case
//! carries the parameter that makes it hard (a mass ratio, a scale, an angle)
//! so that a report can plot the error against it.

use glam::{DMat3, DVec3};

use super::{ball_body, box_body, random_island, Rng};
use crate::lcp::Lcp;
use crate::scene::{Body, Contact, Scene};

/// A family of stress problems.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Family {
    /// Random physical islands with masses spread over a ratio of 1 … 1e8.
    MassRatio,
    /// Random islands with every length multiplied by 1e-3 … 1e3 (inertia follows).
    LengthScale,
    /// Random islands with every velocity multiplied by 1e-3 … 1e3.
    VelocityScale,
    /// A ball on the ground touching it at two points whose normals differ by
    /// an angle down to 1e-8 (and 0: duplicate contacts).
    NearParallelNormals,
    /// Boxes resting on the ground and stacked, 4 coplanar contacts per face:
    /// rank-deficient M.
    RestingStacks,
    /// Chains of bodies in a row, each touching the next (as
    /// [`super::seed_chain`]), up to n = 16.
    Chains,
    /// Random non-symmetric matrices that are not P-matrices: several solutions or none.
    NonSymmetric,
    /// LCPs built to have no solution: a row with M_ij ≤ 0 everywhere and q_i < 0.
    Infeasible,
    /// The Siconos problems scaled by 1e±6 (from files: see [`siconos_scaled`];
    /// [`generate`] makes none).
    SiconosScaled,
}

impl Family {
    /// Every generated family (the Siconos one comes from files).
    pub const ALL: [Family; 8] = [
        Family::MassRatio,
        Family::LengthScale,
        Family::VelocityScale,
        Family::NearParallelNormals,
        Family::RestingStacks,
        Family::Chains,
        Family::NonSymmetric,
        Family::Infeasible,
    ];

    /// The snake_case name used in tables and JSON.
    pub fn name(self) -> &'static str {
        match self {
            Family::MassRatio => "mass_ratio",
            Family::LengthScale => "length_scale",
            Family::VelocityScale => "velocity_scale",
            Family::NearParallelNormals => "near_parallel_normals",
            Family::RestingStacks => "resting_stacks",
            Family::Chains => "chains",
            Family::NonSymmetric => "non_symmetric",
            Family::Infeasible => "infeasible",
            Family::SiconosScaled => "siconos_scaled",
        }
    }
}

/// One stress problem.
#[derive(Clone, Debug)]
pub struct StressCase {
    /// The family it belongs to.
    pub family: Family,
    /// What makes it hard: the mass ratio, the scale, the angle, n.
    pub parameter: f64,
    /// The problem.
    pub lcp: Lcp,
}

use super::families::island_lcps as islands_of;

fn scaled_lengths(mut scene: Scene, s: f64) -> Scene {
    for b in &mut scene.bodies {
        b.position = (DVec3::from_array(b.position) * s).to_array();
        for row in &mut b.inv_inertia {
            for v in row {
                *v /= s * s;
            }
        }
        // Keep point velocities comparable: ω scales with 1/s.
        b.angular_velocity = (DVec3::from_array(b.angular_velocity) / s).to_array();
    }
    for c in &mut scene.contacts {
        c.point = (DVec3::from_array(c.point) * s).to_array();
    }
    scene
}

fn scaled_velocities(mut scene: Scene, s: f64) -> Scene {
    for b in &mut scene.bodies {
        b.velocity = (DVec3::from_array(b.velocity) * s).to_array();
        b.angular_velocity = (DVec3::from_array(b.angular_velocity) * s).to_array();
    }
    scene
}

fn contact(a: usize, b: Option<usize>, point: DVec3, normal: DVec3, restitution: f64) -> Contact {
    Contact {
        a,
        b,
        point: point.to_array(),
        normal: normal.to_array(),
        restitution,
        id: None,
        bias: 0.0,
        friction: 0.0,
        tangent: None,
    }
}

/// A ball of radius 0.5 falling onto the ground with two contacts at the
/// bottom, the second normal tilted by `angle` about z.
fn near_parallel(angle: f64, rng: &mut Rng) -> Scene {
    let mut ball = ball_body(1.0, 0.5, DVec3::new(0.0, 0.5, 0.0));
    ball.velocity = [
        rng.range(-0.5, 0.5),
        -rng.range(0.5, 2.0),
        rng.range(-0.5, 0.5),
    ];
    let n2 = DVec3::new(-angle.sin(), angle.cos(), 0.0);
    Scene {
        bodies: vec![ball],
        contacts: vec![
            contact(0, None, DVec3::ZERO, DVec3::Y, 0.0),
            contact(0, None, DVec3::new(1e-3 * rng.unit(), 0.0, 0.0), n2, 0.0),
        ],
    }
}

/// `levels` unit boxes stacked on the ground, each face 4 contacts.
fn stack(levels: usize, rng: &mut Rng) -> Scene {
    let mut bodies = vec![Body::fixed([0.0, -0.5, 0.0])];
    let mut contacts = Vec::new();
    let e = if rng.unit() < 0.5 {
        0.0
    } else {
        rng.range(0.0, 0.5)
    };
    for l in 0..levels {
        let mut b = box_body(
            rng.log_range(0.5, 10.0),
            DVec3::splat(0.5),
            DMat3::IDENTITY,
            DVec3::new(0.0, 0.5 + l as f64, 0.0),
        );
        b.velocity = [0.0, -rng.range(0.0, 1.0), 0.0];
        bodies.push(b);
        let (a, below) = (bodies.len() - 1, bodies.len() - 2);
        for (dx, dz) in [(-0.5, -0.5), (0.5, -0.5), (-0.5, 0.5), (0.5, 0.5)] {
            contacts.push(contact(
                a,
                Some(below),
                DVec3::new(dx, l as f64, dz),
                DVec3::Y,
                e,
            ));
        }
    }
    Scene { bodies, contacts }
}

/// A chain of boxes along x with `n` contacts in all: one or two contacts per
/// interface, the first body pushed into the others ([`super::seed_chain`]
/// extended).
fn chain(n: usize, rng: &mut Rng) -> Scene {
    let mut bodies = Vec::new();
    let mut contacts = Vec::new();
    let mut i = 0;
    bodies.push({
        let mut b = box_body(
            rng.log_range(1.0, 10.0),
            DVec3::splat(0.5),
            DMat3::IDENTITY,
            DVec3::ZERO,
        );
        b.velocity = [1.0, 0.0, 0.0];
        b
    });
    while contacts.len() < n {
        i += 1;
        let mut b = box_body(
            rng.log_range(1.0, 10.0),
            DVec3::splat(0.5),
            DMat3::IDENTITY,
            DVec3::new(i as f64, 0.0, 0.0),
        );
        b.velocity = [rng.range(-0.5, 0.5), 0.0, 0.0];
        bodies.push(b);
        let per = if contacts.len() + 2 <= n && rng.unit() < 0.5 {
            2
        } else {
            1
        };
        for _ in 0..per {
            let p = DVec3::new(i as f64 - 0.5, rng.range(-0.4, 0.4), rng.range(-0.4, 0.4));
            contacts.push(contact(i, Some(i - 1), p, DVec3::X, rng.range(0.0, 1.0)));
        }
    }
    Scene { bodies, contacts }
}

/// Generates about `count` cases of `family` from `seed` (islands from one
/// scene are kept together, so the count can be exceeded slightly).
pub fn generate(family: Family, seed: u64, count: usize) -> Vec<StressCase> {
    let mut rng = Rng::new(seed ^ (family as u64).wrapping_mul(0x9E37_79B9));
    let mut out = Vec::with_capacity(count);
    if family == Family::SiconosScaled {
        return out;
    }
    let mut k = 0usize;
    while out.len() < count {
        let mut push = |parameter: f64, lcps: Vec<Lcp>| {
            out.extend(lcps.into_iter().map(|lcp| StressCase {
                family,
                parameter,
                lcp,
            }));
        };
        match family {
            Family::MassRatio => {
                let ratio = [1.0, 1e2, 1e4, 1e6, 1e8][k % 5];
                let n = rng.int(1, 8);
                push(ratio, islands_of(&random_island(&mut rng, n, ratio)));
            }
            Family::LengthScale => {
                let s = [1e-3, 1e-1, 1.0, 1e1, 1e3][k % 5];
                let n = rng.int(1, 8);
                push(
                    s,
                    islands_of(&scaled_lengths(random_island(&mut rng, n, 10.0), s)),
                );
            }
            Family::VelocityScale => {
                let s = [1e-3, 1e-1, 1.0, 1e1, 1e3][k % 5];
                let n = rng.int(1, 8);
                push(
                    s,
                    islands_of(&scaled_velocities(random_island(&mut rng, n, 10.0), s)),
                );
            }
            Family::NearParallelNormals => {
                let angle = [1e-2, 1e-4, 1e-6, 1e-8, 0.0][k % 5];
                push(angle, islands_of(&near_parallel(angle, &mut rng)));
            }
            Family::RestingStacks => {
                let levels = 1 + k % 3;
                push(levels as f64, islands_of(&stack(levels, &mut rng)));
            }
            Family::Chains => {
                let n = 1 + k % 16;
                push(n as f64, islands_of(&chain(n, &mut rng)));
            }
            Family::NonSymmetric => {
                let n = rng.int(2, 8);
                let m: Vec<f64> = (0..n * n).map(|_| rng.range(-1.0, 1.0)).collect();
                let q: Vec<f64> = (0..n).map(|_| rng.range(-1.0, 1.0)).collect();
                push(n as f64, vec![Lcp { m, q }]);
            }
            Family::Infeasible => {
                let n = rng.int(1, 8);
                let bad = rng.int(0, n - 1);
                let mut m: Vec<f64> = (0..n * n).map(|_| rng.range(-1.0, 1.0)).collect();
                for j in 0..n {
                    m[bad * n + j] = -rng.range(0.0, 1.0);
                }
                let mut q: Vec<f64> = (0..n).map(|_| rng.range(-1.0, 1.0)).collect();
                q[bad] = -rng.range(0.1, 1.0);
                push(n as f64, vec![Lcp { m, q }]);
            }
            Family::SiconosScaled => unreachable!("returned above"),
        }
        k += 1;
    }
    out
}

/// The same LCP with M and q both multiplied by `s`: the same z, w scaled by s.
pub fn scaled(lcp: &Lcp, s: f64) -> Lcp {
    Lcp {
        m: lcp.m.iter().map(|v| v * s).collect(),
        q: lcp.q.iter().map(|v| v * s).collect(),
    }
}

/// 1-norm condition number ‖A‖₁‖A⁻¹‖₁ of the principal submatrix M_SS of a
/// basis (1 for the empty basis, ∞ when singular to working precision).
pub fn basis_condition(lcp: &Lcp, mask: u32) -> f64 {
    let n = lcp.n();
    let idx: Vec<usize> = (0..n).filter(|&i| mask >> i & 1 == 1).collect();
    let k = idx.len();
    if k == 0 {
        return 1.0;
    }
    let a: Vec<f64> = idx
        .iter()
        .flat_map(|&i| idx.iter().map(move |&j| lcp.at(i, j)))
        .collect();
    let norm1 = |m: &[f64]| {
        (0..k)
            .map(|c| (0..k).map(|r| m[r * k + c].abs()).sum::<f64>())
            .fold(0.0, f64::max)
    };
    let mut inv = vec![0.0; k * k];
    for c in 0..k {
        let mut work = a.clone();
        let mut x = vec![0.0; k];
        x[c] = 1.0;
        if !crate::linalg::solve_in_place(&mut work, &mut x, k, 0.0) {
            return f64::INFINITY;
        }
        for r in 0..k {
            inv[r * k + c] = x[r];
        }
    }
    norm1(&a) * norm1(&inv)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_family_generates_valid_problems() {
        for f in Family::ALL {
            let cases = generate(f, 7, 20);
            assert!(cases.len() >= 20, "{f:?}");
            for c in &cases {
                c.lcp.validate(f.name()).unwrap();
            }
        }
    }

    #[test]
    fn condition_number_of_diagonal_basis() {
        let lcp = Lcp::new(vec![2.0, 0.0, 0.0, 1e-6], vec![-1.0, -1.0]).unwrap();
        assert!((basis_condition(&lcp, 0b11) - 2e6).abs() < 1e-3);
        assert_eq!(basis_condition(&lcp, 0), 1.0);
    }
}

/// The Siconos problems of `dir` (a folder of `.dat` files) with n ≤ 16,
/// each scaled by 1e-6 and by 1e6 (M and q together: same z, w scaled).
///
/// # Errors
/// [`crate::Error::Io`] when `dir` or a file in it cannot be read; the
/// errors of [`crate::io::read_input`] for a malformed file.
pub fn siconos_scaled(dir: &std::path::Path) -> Result<Vec<(String, StressCase)>, crate::Error> {
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .map_err(|source| crate::Error::Io {
            path: dir.to_path_buf(),
            source,
        })?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "dat"))
        .collect();
    files.sort();
    let mut out = Vec::new();
    for f in files {
        let crate::io::Input::Lcps(lcps) = crate::io::read_input(&f)? else {
            continue;
        };
        for lcp in lcps.into_iter().filter(|l| l.n() <= 16) {
            for s in [1e-6, 1e6] {
                let name = f
                    .file_stem()
                    .map(|s| s.to_string_lossy().into_owned())
                    .unwrap_or_default();
                out.push((
                    name,
                    StressCase {
                        family: Family::SiconosScaled,
                        parameter: s,
                        lcp: scaled(&lcp, s),
                    },
                ));
            }
        }
    }
    Ok(out)
}
