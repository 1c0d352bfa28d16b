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
//! The path of the data: a [`Scene`] (bodies and contacts) → islands
//! (independent groups of contacts) → assembly (K matrices, Jacobian rows,
//! each island's (M, q); `shaders/assembly.wgsl` and its CPU twin) →
//! prediction (islands that need no enumeration) → enumeration of the
//! complementary bases (GPU kernels and their CPU twins), Lemke or PGS →
//! validation in f64 → impulses (ARCHITECTURE.md has the stage table).
//!
//! The face: the door ([`Solver`], [`Settings`] and its enums, [`Report`]
//! and [`Error`]), the model it takes ([`Lcp`], [`Scene`], [`Body`],
//! [`Contact`], [`FrictionProblem`], [`World`]), and modules for the rest:
//! [`report`] (the parts of a report), [`lcp`] (solutions and residuals),
//! [`friction`] (Coulomb's problem, its settings and errors), [`gradient`]
//! (vector–Jacobian products of solved batches and scenes), [`world`]
//! (bodies in time, world files, standard worlds, step reports), [`io`]
//! (the file formats), [`generate`] (seeded test scenes and problems) and
//! [`device`] (adapters, the GPU context, the cost model).

#![warn(missing_docs)]

pub(crate) mod build;
pub(crate) mod cpu;
pub(crate) mod error;
pub mod friction;
pub mod generate;
pub(crate) mod gpu;
pub mod gradient;
pub mod io;
pub(crate) mod islands;
pub mod lcp;
pub(crate) mod linalg;
pub(crate) mod prediction;
pub mod report;
pub(crate) mod scene;
pub(crate) mod settings;
pub mod short_vec;
pub(crate) mod solver;
pub(crate) mod warm;
pub mod world;

// The face: the door, its settings, what it reports, the model it takes.
pub use error::Error;
pub use friction::{FrictionMethod, FrictionProblem};
pub use gpu::{BackendChoice, EnumerationKernel, Precision};
pub use lcp::{Lcp, Status};
pub use report::Report;
pub use scene::{Body, Contact, Scene};
pub use settings::{Backend, GpuSettings, Method, Settings};
pub use short_vec::ShortVec;
pub use solver::world_path::{Frames, StepReport};
pub use solver::Solver;
pub use world::World;

// Paths inside the crate that name these from the root.
pub(crate) use lcp::LcpSolution;
pub(crate) use solver::CostModel;
#[cfg(test)]
pub(crate) use {
    gpu::GpuContext,
    lcp::SolutionSet,
    report::{DeviceKind, SolvePath},
};

/// The compute device: the adapters wgpu finds, the GPU context a
/// [`Solver`] opens (or is handed, [`Solver::with_device`]), and the cost
/// model by which [`Backend::Auto`] chooses between the CPU and the GPU.
pub mod device {
    pub use crate::gpu::{list_adapters, AdapterSummary, GpuContext, INSTALL_HINT};
    pub use crate::solver::{cache_dir, CostModel, WorldCosts, CALIBRATION_SIZES};
}

/// Side doors for the benches and the command-line tool: inner solvers and
/// steps, timed or called one by one. Not part of the public API: no
/// stability promised.
#[doc(hidden)]
pub mod internals {
    pub use crate::cpu::lemke::{lemke, lemke_textbook_basis, LemkeSettings};
    pub use crate::friction::assembly::{friction_islands, FrictionIsland};
    pub use crate::friction::projected::{
        solve_projected_batch, ProjectedMethod, ProjectedSettings, ProjectedSolution,
    };
    pub use crate::friction::random::random_problems;
    pub use crate::gpu::friction::solve_projected_on_gpu;
    pub use crate::gpu::friction_assembly::assemble_friction_on_gpu;
    pub use crate::world::step::{prepare, Prepared};
}

#[cfg(test)]
mod tests;
