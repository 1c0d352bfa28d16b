//! The friction cone of one contact: the Euclidean projections on the cone
//! ‖r_t‖ ≤ μ r_n and on the disc ‖r_t‖ ≤ μ r_n of a given r_n (the
//! projections of the cone complementarity iterations, Anitescu & Tasora
//! 2010). The tangent basis is [`crate::scene`]'s.

pub use crate::scene::tangent_basis;

/// The Euclidean projection of x = (x_n, x_t₁, x_t₂) on the cone
/// K = {‖x_t‖ ≤ μ x_n}, with t = ‖x_t‖ (Siconos' fc3d projection):
///
/// ```text
/// μ t ≤ −x_n  →  0                      (in the polar cone)
/// t ≤ μ x_n   →  x                      (inside)
/// otherwise   →  p_n = (μ t + x_n) / (μ² + 1),  (p_n, μ p_n x_t / t)
/// ```
///
/// μ = 0 gives (max(x_n, 0), 0, 0). μ must be finite and ≥ 0.
///
/// t is computed as √(x_t₁² + x_t₂²), as `shaders/friction_projected.wgsl`
/// computes it (WGSL has no hypot): with the same formula the f64 shader
/// reproduces the CPU twin's iterates bit for bit on lavapipe (measured,
/// `src/tests/gpu_friction.rs`); `hypot` rounded differently. The squares
/// overflow only beyond 1e154.
#[inline]
pub fn project_on_cone(x: [f64; 3], mu: f64) -> [f64; 3] {
    let t = (x[1] * x[1] + x[2] * x[2]).sqrt();
    if mu * t <= -x[0] {
        [0.0; 3]
    } else if t <= mu * x[0] {
        x
    } else {
        let pn = (mu * t + x[0]) / (mu * mu + 1.0);
        // t > 0 here: t = 0 is one of the two cases above.
        let scale = mu * pn / t;
        [pn, x[1] * scale, x[2] * scale]
    }
}

/// Maximal dissipation in closed form (Stewart & Trinkle 1996; Anitescu &
/// Tasora 2010): for a normal impulse γ_n and a sliding velocity v_T, the
/// tangential impulse of maximum dissipation (γ_T minimising γ_T · v_T over
/// the disc ‖γ_T‖ ≤ μ γ_n) is γ_T = −μ γ_n v_T / ‖v_T‖, on the disc's
/// boundary, opposing the slide. For v_T = 0 every point of the disc
/// dissipates nothing; this returns 0. A negative γ_n counts as 0.
#[inline]
pub fn project_on_disc(v_t: [f64; 2], mu: f64, gamma_n: f64) -> [f64; 2] {
    let speed = v_t[0].hypot(v_t[1]);
    if speed == 0.0 {
        return [0.0; 2];
    }
    let radius = mu * gamma_n.max(0.0);
    [-radius * v_t[0] / speed, -radius * v_t[1] / speed]
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn the_seeds_disc_examples() {
        // Worked by hand: v_T = (3, −4), μ = 0.5, γ_n = 10 → (−3, 4), on the
        // disc's boundary.
        let g = project_on_disc([3.0, -4.0], 0.5, 10.0);
        assert!(
            (g[0] + 3.0).abs() < 1e-15 && (g[1] - 4.0).abs() < 1e-15,
            "{g:?}"
        );
        // Exercise 3: v_T = (4, 3), μ = 0.6, γ_n = 5 → (−12/5, −9/5).
        let g = project_on_disc([4.0, 3.0], 0.6, 5.0);
        assert!(
            (g[0] + 2.4).abs() < 1e-15 && (g[1] + 1.8).abs() < 1e-15,
            "{g:?}"
        );
    }

    #[test]
    fn the_cone_projection_is_a_projection() {
        let mu = 0.6;
        let mut seed = 12345u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 11) as f64 / (1u64 << 53) as f64) * 4.0 - 2.0
        };
        for _ in 0..2000 {
            let x = [next(), next(), next()];
            let p = project_on_cone(x, mu);
            // In the cone.
            assert!(
                p[1].hypot(p[2]) <= mu * p[0] * (1.0 + 1e-14) + 1e-15,
                "{x:?} → {p:?}"
            );
            // Idempotent.
            let pp = project_on_cone(p, mu);
            for i in 0..3 {
                assert!((pp[i] - p[i]).abs() <= 1e-14, "{p:?} → {pp:?}");
            }
            // x − P(x) is normal to the cone at P(x): ⟨x − P(x), y − P(x)⟩ ≤ 0 for y in K.
            for _ in 0..4 {
                let yn = next().abs();
                let (a, b) = (next(), next());
                let s = mu * yn / a.hypot(b).max(1e-300) * next().abs().min(1.0);
                let y = [yn, a * s, b * s];
                let d: f64 = (0..3).map(|i| (x[i] - p[i]) * (y[i] - p[i])).sum();
                assert!(d <= 1e-12, "{x:?} {p:?} {y:?}: {d}");
            }
        }
    }

    #[test]
    fn frictionless_projection_keeps_the_normal_only() {
        assert_eq!(project_on_cone([2.0, 1.0, -1.0], 0.0), [2.0, 0.0, 0.0]);
        assert_eq!(project_on_cone([-2.0, 1.0, -1.0], 0.0), [0.0, 0.0, 0.0]);
    }

    #[test]
    fn tangents_are_an_orthonormal_right_handed_frame() {
        let mut normals = vec![
            DVec3::Y,
            DVec3::NEG_Y,
            DVec3::Z,
            DVec3::NEG_Z,
            DVec3::X,
            DVec3::new(0.0, 0.0, -0.0),
        ];
        for i in 0..200 {
            let a = i as f64 * 0.7;
            let b = i as f64 * 0.31;
            normals.push(DVec3::new(a.cos() * b.sin(), a.sin() * b.sin(), b.cos()));
        }
        for n in normals.into_iter().filter(|n| n.length() > 0.5) {
            let (t1, t2) = tangent_basis(n);
            assert!((t1.length() - 1.0).abs() < 1e-14, "{n}");
            assert!((t2.length() - 1.0).abs() < 1e-14, "{n}");
            assert!(t1.dot(n).abs() < 1e-14 && t2.dot(n).abs() < 1e-14 && t1.dot(t2).abs() < 1e-14);
            assert!((t1.cross(t2) - n).length() < 1e-14, "{n}: {t1} × {t2}");
        }
        let (t1, t2) = tangent_basis(DVec3::Y);
        assert_eq!((t1, t2), (DVec3::X, DVec3::NEG_Z));
    }

    /// The frame is continuous across n.z = 0 (where y-up worlds' normals
    /// lie): a normal whose n.z rounds to +0, −0 or −6e-19 gets the same
    /// frame to rounding, and tilting a normal through n.z = 0 turns its
    /// frame by no more than the tilt. It flips only across n.z = −½.
    #[test]
    fn tangents_do_not_flip_with_the_sign_of_a_zero_z() {
        let sides = [
            DVec3::X,
            DVec3::NEG_X,
            DVec3::new(0.6, 0.8, 0.0),
            DVec3::new(-0.8, 0.6, 0.0),
        ];
        for side in sides {
            let (t1, t2) = tangent_basis(side);
            for z in [-0.0, -6e-19, 6e-19, -1e-12] {
                let n = DVec3::new(side.x, side.y, z).normalize();
                let (u1, u2) = tangent_basis(n);
                assert!((u1 - t1).length() <= 1e-11, "{n}: {u1} vs {t1}");
                assert!((u2 - t2).length() <= 1e-11, "{n}: {u2} vs {t2}");
            }
            for step in -20..20 {
                let z = step as f64 * 0.01;
                let (a, b) = (
                    DVec3::new(side.x, side.y, z).normalize(),
                    DVec3::new(side.x, side.y, z + 0.01).normalize(),
                );
                let ((a1, _), (b1, _)) = (tangent_basis(a), tangent_basis(b));
                assert!((a1 - b1).length() < 0.05, "{a} to {b}: {a1} to {b1}");
            }
        }
        let below = |z: f64| tangent_basis(DVec3::new((1.0 - z * z).sqrt(), 0.0, z)).0;
        assert!(
            (below(-0.51) - below(-0.49)).length() > 1.0,
            "the flip at n.z = −½"
        );
    }
}
