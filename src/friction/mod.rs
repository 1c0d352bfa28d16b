//! Coulomb friction: the frictional contact problem of an island, its
//! friction cones, and the errors that judge an answer.
//!
//! For k contacts with reactions r (impulses) and local velocities
//! u = W r + q, contact i owns the entries 3i (normal), 3i + 1, 3i + 2
//! (tangents t₁, t₂ of [`crate::Contact::tangents`]): **interleaved**, as Siconos'
//! FrictionContact3D problems are stored. W = J M⁻¹ Jᵀ is the island's
//! Delassus matrix (3k × 3k) and q its free velocity (restitution on the
//! normal only).
//!
//! The Coulomb problem (De Saxcé & Feng 1991; Acary & Brogliato,
//! *Numerical Methods for Nonsmooth Dynamical Systems*, 2008; Siconos'
//! fc3d): for every contact, r_i in the cone K_i = {‖r_t‖ ≤ μ_i r_n},
//! De Saxcé's modified velocity ũ_i = u_i + μ_i ‖u_t,i‖ e_n in the dual
//! cone K_i*, and r_i · ũ_i = 0. The cone complementarity problem of Anitescu–Tasora drops
//! the μ‖u_t‖ term (a convex problem: min ½ rᵀW r + qᵀr over the cones);
//! a sliding contact then gains the normal velocity μ‖u_t‖.

pub(crate) mod apgd;
pub(crate) mod assembly;
pub(crate) mod cone;
pub(crate) mod faceted;
pub(crate) mod local;
pub(crate) mod newton;
pub(crate) mod nsgs;
pub(crate) mod problem;
pub(crate) mod projected;
pub(crate) mod prox;
pub(crate) mod random;
pub(crate) mod residual;
pub(crate) mod solve;
pub(crate) mod sparse;
pub(crate) mod workspace;

pub use cone::{project_on_cone, project_on_disc};
pub use problem::FrictionProblem;
pub use residual::{coulomb_error, FrictionResiduals};
pub use solve::{solve_friction_problem, FrictionMethod, FrictionSettings, FrictionSolution};

pub(crate) use crate::gpu::friction::ProjectedGpuFigures;
pub(crate) use projected::{ProjectedMethod, ProjectedSettings, ProjectedSolution};
// Paths the crate's tests name.
#[cfg(test)]
pub(crate) use {
    crate::gpu::friction::{solve_projected_on_gpu, FrictionOrigin, MAX_GPU_CONTACTS},
    projected::solve_projected_batch,
};
