//! Coulomb friction: the frictional contact problem of an island, its
//! friction cones, and the errors that judge an answer.
//!
//! For k contacts with reactions r (impulses) and local velocities
//! u = W r + q, contact i owns the entries 3i (normal), 3i + 1, 3i + 2
//! (tangents t₁, t₂ of [`tangent_basis`]): **interleaved**, as Siconos'
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
pub mod assembly;
pub mod cone;
pub mod local;
pub mod newton;
pub mod nsgs;
pub mod problem;
pub mod projected;
pub mod random;
pub mod residual;
pub mod solve;
pub mod workspace;

pub use crate::gpu::friction::{
    solve_projected_on_gpu, FrictionOrigin, ProjectedGpuFigures, MAX_GPU_CONTACTS,
};
pub use crate::gpu::friction_assembly::assemble_friction_on_gpu;
pub use cone::{project_on_cone, project_on_disc, tangent_basis};
pub use problem::FrictionProblem;
pub use projected::{
    solve_projected, solve_projected_batch, ProjectedMethod, ProjectedSettings, ProjectedSolution,
};
pub use residual::{coulomb_error, FrictionResiduals};
pub use solve::{solve_friction_problem, FrictionMethod, FrictionSettings, FrictionSolution};
