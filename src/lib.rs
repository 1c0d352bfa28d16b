//! lcpbatch: the contact problems of rigid bodies, thousands of small
//! independent islands at once, solved exactly and checked in f64.
//!
//! For each island it finds normal impulses z with
//!
//! ```text
//! w = M z + q ≥ 0,   z ≥ 0,   zᵀw = 0
//! ```
//!
//! (a linear complementarity problem), where M = J M⁻¹ Jᵀ is the island's
//! effective-mass matrix and q its approach velocities with restitution.
//!
//! One door: build a [`Solver`] once from [`Settings`], then call
//! [`Solver::solve_lcps`] (LCP batches) or [`Solver::solve_scenes`] (bodies
//! and contacts) as often as needed; both return a [`Report`] — per island
//! the status, z, w, error, basis and the path that settled it, per batch the
//! counts per path, time per phase, the device and why.
//!
//! ```
//! use lcpbatch::{Body, Contact, Scene, Settings, Solver, Status};
//!
//! // A ball of 1 kg falling at 1 m/s onto the ground, restitution 0.5.
//! let mut ball = Body::new(1.0, [2.5; 3], [0.0, 0.5, 0.0]);
//! ball.velocity = [0.0, -1.0, 0.0];
//! let ground = Contact::new(0, None, [0.0; 3], [0.0, 1.0, 0.0], 0.5);
//! let scene = Scene { bodies: vec![ball], contacts: vec![ground] };
//!
//! let mut solver = Solver::new(Settings::default())?; // GPU if a hardware one, else all CPU cores
//! let report = solver.solve_scenes(&[scene])?;
//! assert_eq!(report.islands[0].status(), Status::Solved);
//! assert!((report.scenes[0].impulses[0] - 1.5).abs() < 1e-12); // (1 + ε) m v
//! assert!((report.scenes[0].bodies[0].velocity[1] - 0.5).abs() < 1e-12);
//! println!("{report}");
//! # Ok::<(), lcpbatch::Error>(())
//! ```
//!
//! The path of the data: [`scene`] (bodies and contacts) → [`islands`]
//! (independent groups of contacts) → assembly (K matrices, Jacobian rows,
//! each island's (M, q); `shaders/assembly.wgsl` and its CPU twin) →
//! prediction (islands that need no enumeration) → enumeration of the
//! complementary bases (GPU kernels and their CPU twins), Lemke or PGS →
//! validation in f64 → impulses. [`io`] reads and writes the file formats.

#![warn(missing_docs)]

pub(crate) mod build;
pub(crate) mod cpu;
pub mod error;
pub mod friction;
pub mod generate;
pub(crate) mod gpu;
pub mod io;
pub(crate) mod islands;
pub mod lcp;
pub(crate) mod linalg;
pub(crate) mod prediction;
pub mod report;
pub mod scene;
pub mod settings;
pub mod short_vec;
pub mod solver;
pub(crate) mod warm;
pub mod world;

pub use cpu::impulses::BodyVelocity;
pub use cpu::lemke::{lemke, lemke_textbook_basis, LemkeSettings};
pub use error::Error;
pub use friction::{
    FrictionMethod, FrictionProblem, FrictionResiduals, FrictionSettings, FrictionSolution,
};
pub use gpu::{AdapterSummary, BackendChoice, EnumerationKernel, GpuContext, Precision};
pub use islands::IslandProblem;
pub use lcp::{Lcp, LcpSolution, Residuals, SolutionSet, Status};
pub use report::{
    ContactImpulse, Device, DeviceKind, FrictionIslandReport, GpuFigures, IslandReport, PathCounts,
    Report, SceneFriction, SceneReport, SolvePath, Timings,
};
pub use scene::{Body, Contact, Scene};
pub use settings::{Backend, GpuSettings, Method, Settings};
pub use short_vec::{ShortVec, SHORT_INLINE};
pub use solver::world_path::{StepReport, StepTimings, WorldStepReport};
pub use solver::Repairs;
pub use solver::{CostModel, Solver};
pub use world::{RigidBody, Shape, World};

/// Every adapter wgpu finds on `api` (for `lcpbatch info`); empty when none.
pub fn list_adapters(api: BackendChoice) -> Vec<AdapterSummary> {
    gpu::list_adapters(api)
}

/// How to install a software GPU adapter, for messages.
pub const INSTALL_HINT: &str = gpu::INSTALL_HINT;

#[cfg(test)]
mod tests;
