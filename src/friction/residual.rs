//! How far a reaction r is from solving a [`FrictionProblem`]: the Coulomb
//! error of Siconos' fc3d (with De Saxcé's correction), the cone
//! complementarity residual, the cone violation and the complementarity gap.

use super::cone::project_on_cone;
use super::problem::FrictionProblem;
use crate::lcp::norm2;

/// Entries of an island of 16 contacts: the residuals' scratch stays on
/// the stack up to this size.
const SCRATCH: usize = 48;

/// The numbers that judge a reaction r (u = W r + q recomputed).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
#[non_exhaustive]
pub struct FrictionResiduals {
    /// Siconos' fc3d error (Coulomb, De Saxcé's correction):
    /// ‖r − P_K(r − u − μ‖u_t‖ e_n)‖ / max(‖q‖, ‖r‖, ‖u‖), not divided when
    /// that maximum is ≤ 2.22e-16. Zero exactly at a Coulomb solution.
    pub coulomb_error: f64,
    /// The cone complementarity (Anitescu–Tasora) residual, normalised the
    /// same way: ‖r − P_K(r − u)‖ / max(‖q‖, ‖r‖, ‖u‖). Zero exactly at a
    /// solution of the convex model; it differs from the Coulomb error where
    /// contacts slide.
    pub cone_error: f64,
    /// max_i max(0, ‖r_t,i‖ − μ_i r_n,i): how far r is outside its cones.
    pub cone_violation: f64,
    /// max_i |r_i · ũ_i|, ũ_i = u_i + μ_i ‖u_t,i‖ e_n: the Coulomb
    /// complementarity gap.
    pub complementarity: f64,
    /// max_i max(0, μ_i ‖u_t,i‖ − ũ_n,i), which is max_i max(0, −u_n,i): how
    /// far the modified velocity is outside the dual cone (an approaching
    /// contact).
    pub dual_cone_violation: f64,
}

impl FrictionResiduals {
    /// The residuals of r (u recomputed as W r + q).
    pub fn of(problem: &FrictionProblem, r: &[f64]) -> Self {
        let u = problem.velocity(r);
        Self::of_velocity(problem, r, &u)
    }

    /// The residuals of r given u = W r + q (the caller computed it).
    pub fn of_velocity(problem: &FrictionProblem, r: &[f64], u: &[f64]) -> Self {
        let q_norm = norm(&problem.q);
        let scale = q_norm.max(norm(r)).max(norm(u));
        let divide = |x: f64| if scale > f64::EPSILON { x / scale } else { x };
        // Scratch for the two vectors whose norms are the errors: on the
        // stack up to 16 contacts (every answer of a batch is judged here).
        let mut stack = [0.0; 2 * SCRATCH];
        let mut heap = Vec::new();
        let scratch: &mut [f64] = if 2 * u.len() <= stack.len() {
            &mut stack[..2 * u.len()]
        } else {
            heap.resize(2 * u.len(), 0.0);
            &mut heap
        };
        let (coulomb, cone) = scratch.split_at_mut(u.len());
        let coulomb_error = coulomb_error_into(problem, r, u, q_norm, coulomb);
        let (mut violation, mut gap, mut dual) = (0.0f64, 0.0f64, 0.0f64);
        for (i, &mu) in problem.mu.iter().enumerate() {
            let ri = [r[3 * i], r[3 * i + 1], r[3 * i + 2]];
            let ui = [u[3 * i], u[3 * i + 1], u[3 * i + 2]];
            let un_tilde = ui[0] + mu * (ui[1] * ui[1] + ui[2] * ui[2]).sqrt();
            let pa = project_on_cone([ri[0] - ui[0], ri[1] - ui[1], ri[2] - ui[2]], mu);
            for j in 0..3 {
                cone[3 * i + j] = ri[j] - pa[j];
            }
            violation = violation.max(ri[1].hypot(ri[2]) - mu * ri[0]);
            gap = gap.max((ri[0] * un_tilde + ri[1] * ui[1] + ri[2] * ui[2]).abs());
            dual = dual.max(-ui[0]);
        }
        FrictionResiduals {
            coulomb_error,
            cone_error: divide(norm2(cone.iter().copied())),
            cone_violation: violation.max(0.0),
            complementarity: gap,
            dual_cone_violation: dual.max(0.0),
        }
    }
}

/// The Coulomb error of r given u = W r + q and ‖q‖ (see
/// [`FrictionResiduals::coulomb_error`]), with `diff` (3k) as scratch for
/// the vector r − P_K(r − ũ): no allocation, for the solvers' checks; the
/// same number, bit for bit, as [`FrictionResiduals::of_velocity`] gives.
pub(crate) fn coulomb_error_into(
    problem: &FrictionProblem,
    r: &[f64],
    u: &[f64],
    q_norm: f64,
    diff: &mut [f64],
) -> f64 {
    for (i, &mu) in problem.mu.iter().enumerate() {
        let ri = [r[3 * i], r[3 * i + 1], r[3 * i + 2]];
        let ui = [u[3 * i], u[3 * i + 1], u[3 * i + 2]];
        let un_tilde = ui[0] + mu * (ui[1] * ui[1] + ui[2] * ui[2]).sqrt();
        let pc = project_on_cone([ri[0] - un_tilde, ri[1] - ui[1], ri[2] - ui[2]], mu);
        for j in 0..3 {
            diff[3 * i + j] = ri[j] - pc[j];
        }
    }
    let scale = q_norm.max(norm(r)).max(norm(u));
    let e = norm(diff);
    if scale > f64::EPSILON {
        e / scale
    } else {
        e
    }
}

/// The Euclidean norm of v: √(Σ v²) in one pass where the sum neither
/// overflows nor underflows (every f64 in ±[1e-140, 1e140] squared), else
/// [`norm2`]'s scaled two passes (no division per entry on the fast path:
/// the solvers evaluate it after every sweep).
pub(crate) fn norm(v: &[f64]) -> f64 {
    let sum: f64 = v.iter().map(|x| x * x).sum();
    if sum.is_finite() && (sum > 1e-280 || sum == 0.0 && v.iter().all(|x| *x == 0.0)) {
        sum.sqrt()
    } else {
        norm2(v.iter().copied())
    }
}

/// Siconos' fc3d error of r (see [`FrictionResiduals::coulomb_error`]).
pub fn coulomb_error(problem: &FrictionProblem, r: &[f64]) -> f64 {
    FrictionResiduals::of(problem, r).coulomb_error
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one_contact(mu: f64, q: [f64; 3]) -> FrictionProblem {
        // W = I: one contact of a unit point mass.
        let mut w = vec![0.0; 9];
        for i in 0..3 {
            w[i * 3 + i] = 1.0;
        }
        FrictionProblem::new(w, q.to_vec(), vec![mu]).unwrap()
    }

    #[test]
    fn a_sliding_contact_is_a_coulomb_solution_not_a_cone_one() {
        // Approaching at 1, sliding at 3 along t1, μ = 0.5, W = I: the
        // Coulomb answer is r_n = 1 (u_n = 0), r_t = −0.5 (on the cone
        // boundary, opposing the slide), u_t = 2.5.
        let p = one_contact(0.5, [-1.0, 3.0, 0.0]);
        let r = [1.0, -0.5, 0.0];
        let res = FrictionResiduals::of(&p, &r);
        assert!(res.coulomb_error < 1e-15, "{res:?}");
        assert!(res.cone_violation <= 1e-15 && res.complementarity < 1e-15);
        // The convex model wants u_n = μ‖u_t‖ here, so r is not its solution.
        assert!(res.cone_error > 0.1, "{res:?}");
    }

    #[test]
    fn a_separating_contact_has_zero_reaction() {
        let p = one_contact(0.3, [2.0, 1.0, -1.0]);
        let res = FrictionResiduals::of(&p, &[0.0; 3]);
        assert_eq!(res.coulomb_error, 0.0);
        assert_eq!(res.cone_error, 0.0);
        let wrong = FrictionResiduals::of(&p, &[1.0, 0.0, 0.0]);
        assert!(wrong.coulomb_error > 0.1 && wrong.complementarity > 1.0);
    }

    #[test]
    fn bad_problems_are_errors_naming_the_field() {
        let e = FrictionProblem::new(vec![1.0; 9], vec![0.0; 3], vec![-0.1]).unwrap_err();
        assert!(e.to_string().contains("mu[0]"), "{e}");
        let e = FrictionProblem::new(vec![1.0; 4], vec![0.0; 3], vec![0.1]).unwrap_err();
        assert!(e.to_string().contains("W"), "{e}");
        let e =
            FrictionProblem::new(vec![1.0; 9], vec![0.0, f64::NAN, 0.0], vec![0.1]).unwrap_err();
        assert!(e.to_string().contains("q[1]"), "{e}");
    }
}
