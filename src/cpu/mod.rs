//! The CPU side, in f64: the twins of the GPU stages and the solvers that
//! run on the CPU only.
//!
//! Each twin computes what its shader computes, from the same inputs:
//! `assembly` (`shaders/assembly.wgsl`), `enumeration` (`enumeration.wgsl`,
//! its unrolled specialisations, `enumeration_workgroup.wgsl`,
//! `enumeration_all.wgsl`), `enumeration_tree` (`enumeration_tree.wgsl`),
//! `impulses` (`impulses.wgsl`); the friction shaders' twins are in
//! `crate::friction` (`projected`, `apgd`). The tests hold each GPU stage to
//! its twin; at run time every GPU answer is checked by
//! `crate::gpu::validation`, which re-solves the GPU's basis in f64
//! (`enumeration::solve_basis`) and enumerates here where that fails.
//!
//! The CPU path solves with the same functions and with `lemke` (its
//! pivoting on a per-thread tableau in `lemke_tableau`) and `pgs`; `batch`
//! spreads a batch over the cores.

pub mod assembly;
pub mod batch;
pub mod enumeration;
pub mod enumeration_tree;
pub mod impulses;
pub mod lemke;
mod lemke_tableau;
pub mod pgs;
