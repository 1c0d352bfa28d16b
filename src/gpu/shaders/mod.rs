//! The WGSL that runs: one committed file per shader, precision and
//! specialised island size in `shaders/generated/`, compiled into the
//! binary through the one table [`GENERATED`].
//!
//! The files are composed from the sources in `shaders/` by [`compose`]
//! (test builds only): the shared `shaders/enumeration_basis.wgsl` is
//! prepended to each enumeration kernel, the lines marked `// HOST` (scalar
//! type, island size, tree confirmations) are replaced, and the specialised
//! kernels get their generated straight-line functions ([`unrolled`],
//! [`tree`]). Nothing that depends on run-time settings is baked in: the
//! tolerances reach the enumeration kernels through a uniform
//! ([`super::pipelines::Tolerances`]). The test
//! `generated_shaders_are_committed` fails when a committed file differs
//! from what the generator makes; `LCPBATCH_BLESS_SHADERS=1 cargo test
//! --release generated_shaders_are_committed` rewrites them.

#[cfg(test)]
mod compose;
#[cfg(test)]
mod tree;
#[cfg(test)]
mod unroll_loops;
#[cfg(test)]
mod unrolled;

use super::Precision;
#[cfg(test)]
use crate::cpu::enumeration_tree::TREE_MAX_N;
use crate::Error;

/// Largest frictional island (contacts) of the cone projection kernels.
pub const FRICTION_MAX_K: usize = 16;

/// Largest island size with a specialised (constant-size) elimination kernel.
pub const FIXED_MAX_N: usize = 8;

/// One shader that can run (in either precision).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Shader {
    /// `shaders/enumeration.wgsl`, any island size.
    Enumeration,
    /// `shaders/enumeration.wgsl` specialised to islands of exactly n
    /// contacts (1 ≤ n ≤ [`FIXED_MAX_N`]).
    Unrolled(usize),
    /// `shaders/enumeration_workgroup.wgsl`.
    Workgroup,
    /// `shaders/enumeration_tree.wgsl` for islands of exactly n contacts
    /// (1 ≤ n ≤ [`crate::cpu::enumeration_tree::TREE_MAX_N`]).
    Tree(usize),
    /// `shaders/enumeration_settle.wgsl`: each island's warm, then
    /// predicted basis, tried before the enumeration or Lemke kernels.
    Settle,
    /// `shaders/lemke.wgsl`: Lemke's textbook path, one invocation per
    /// island of any size up to [`super::MAX_GPU_N`].
    Lemke,
    /// `shaders/enumeration_all.wgsl`: every basis of every island
    /// (`all_solutions`), one invocation per (island, basis).
    AllBases,
    /// `shaders/assembly.wgsl` (entry points assemble_contacts, assemble_islands).
    Assembly,
    /// `shaders/impulses.wgsl`.
    Impulses,
    /// `shaders/friction_projected.wgsl` (entry points sweeps, apgd)
    /// specialised to islands of exactly k contacts (1 ≤ k ≤ 16): constant
    /// loop bounds, which llvmpipe unrolls.
    FrictionProjected(usize),
    /// `shaders/collide.wgsl` (entry point collide_pairs): the narrow phase.
    Collide,
    /// One step of resident worlds, one module per phase, each
    /// `shaders/world_step.wgsl` (the step's parameters, bindings and
    /// shared functions) with what its phase calls:
    /// the collision phase, `shaders/world_collide.wgsl` after every
    /// function of `collide.wgsl` (entry points candidate_pairs,
    /// narrow_box_box, narrow_box_plane, narrow_sphere, world_contacts);
    WorldCollide,
    /// the islands and their assembly, `world_bodies.wgsl` and
    /// `world_assemble.wgsl` after `collide.wgsl`'s functions above its
    /// pair functions and `lemke.wgsl`'s (entry point world_assemble);
    WorldAssemble,
    /// the solve from the warm bases, `world_bodies.wgsl`,
    /// `world_island.wgsl` and `world_solve.wgsl` after the same functions
    /// (entry point world_solve_warm);
    WorldSolve,
    /// Lemke's path, as the solve's with `world_lemke.wgsl` for
    /// `world_solve.wgsl` (entry point world_lemke);
    WorldLemke,
    /// its basis re-solved and checked, `world_lemke_check.wgsl` for
    /// `world_lemke.wgsl` (entry point world_lemke_check);
    WorldLemkeCheck,
    /// the frictional phase with the projected sweeps, as the solve's but
    /// `world_friction.wgsl`, `world_sweeps.wgsl` and
    /// `friction_common.wgsl` from its cone projection on for
    /// `world_island.wgsl` and `world_solve.wgsl` (entry point
    /// world_friction);
    WorldFriction,
    /// the same with APGD, `world_apgd.wgsl` for `world_sweeps.wgsl`
    /// (entry point world_friction);
    WorldFrictionApgd,
    /// the finish, `world_bodies.wgsl` and `world_finish.wgsl` after the
    /// same functions (entry point world_finish).
    WorldFinish,
}

impl Shader {
    /// Every shader that can run.
    #[cfg(test)]
    pub(crate) fn all() -> Vec<Shader> {
        let mut v = vec![
            Shader::Enumeration,
            Shader::Workgroup,
            Shader::AllBases,
            Shader::Settle,
            Shader::Lemke,
        ];
        v.extend((1..=FIXED_MAX_N).map(Shader::Unrolled));
        v.extend((1..=TREE_MAX_N).map(Shader::Tree));
        v.extend([Shader::Assembly, Shader::Impulses]);
        v.extend((1..=FRICTION_MAX_K).map(Shader::FrictionProjected));
        v.extend([Shader::Collide, Shader::WorldCollide]);
        v.extend([
            Shader::WorldAssemble,
            Shader::WorldSolve,
            Shader::WorldLemke,
            Shader::WorldLemkeCheck,
        ]);
        v.extend([
            Shader::WorldFriction,
            Shader::WorldFrictionApgd,
            Shader::WorldFinish,
        ]);
        v
    }

    /// The generated file's name without precision and extension.
    pub(crate) fn name(self) -> String {
        match self {
            Shader::Enumeration => "enumeration".into(),
            Shader::Unrolled(n) => format!("enumeration_n{n}"),
            Shader::Workgroup => "enumeration_workgroup".into(),
            Shader::Tree(n) => format!("enumeration_tree_n{n}"),
            Shader::AllBases => "enumeration_all".into(),
            Shader::Settle => "enumeration_settle".into(),
            Shader::Lemke => "lemke".into(),
            Shader::Assembly => "assembly".into(),
            Shader::Impulses => "impulses".into(),
            Shader::FrictionProjected(k) => format!("friction_projected_k{k}"),
            Shader::Collide => "collide".into(),
            Shader::WorldCollide => "world_collide".into(),
            Shader::WorldAssemble => "world_assemble".into(),
            Shader::WorldSolve => "world_solve".into(),
            Shader::WorldLemke => "world_lemke".into(),
            Shader::WorldLemkeCheck => "world_lemke_check".into(),
            Shader::WorldFriction => "world_friction".into(),
            Shader::WorldFrictionApgd => "world_friction_apgd".into(),
            Shader::WorldFinish => "world_finish".into(),
        }
    }

    /// The generated file, relative to the crate root.
    #[cfg(test)]
    pub(crate) fn path(self, precision: Precision) -> String {
        format!(
            "shaders/generated/{}_{}.wgsl",
            self.name(),
            precision.name()
        )
    }

    /// The committed source of this shader in `precision` (F32 or F64).
    pub(crate) fn source(self, precision: Precision) -> Result<&'static str, Error> {
        let name = self.name();
        let (_, f32_src, f64_src) = GENERATED
            .iter()
            .find(|(n, _, _)| *n == name)
            .ok_or_else(|| Error::Gpu(format!("no generated shader `{name}`")))?;
        match precision {
            Precision::F32 => Ok(f32_src),
            Precision::F64 => Ok(f64_src),
            Precision::Auto => Err(Error::Gpu(format!(
                "shader `{name}`: precision not resolved"
            ))),
        }
    }
}

/// (name, f32 source, f64 source) of every generated shader.
macro_rules! generated {
    ($($name:literal),* $(,)?) => {
        &[$((
            $name,
            include_str!(concat!("../../../shaders/generated/", $name, "_f32.wgsl")),
            include_str!(concat!("../../../shaders/generated/", $name, "_f64.wgsl")),
        )),*]
    };
}

/// Every committed shader: the only WGSL the GPU path runs.
pub(crate) static GENERATED: &[(&str, &str, &str)] = generated!(
    "enumeration",
    "enumeration_workgroup",
    "enumeration_all",
    "enumeration_settle",
    "lemke",
    "enumeration_n1",
    "enumeration_n2",
    "enumeration_n3",
    "enumeration_n4",
    "enumeration_n5",
    "enumeration_n6",
    "enumeration_n7",
    "enumeration_n8",
    "enumeration_tree_n1",
    "enumeration_tree_n2",
    "enumeration_tree_n3",
    "enumeration_tree_n4",
    "enumeration_tree_n5",
    "enumeration_tree_n6",
    "enumeration_tree_n7",
    "enumeration_tree_n8",
    "enumeration_tree_n9",
    "enumeration_tree_n10",
    "enumeration_tree_n11",
    "enumeration_tree_n12",
    "assembly",
    "impulses",
    "friction_projected_k1",
    "friction_projected_k2",
    "friction_projected_k3",
    "friction_projected_k4",
    "friction_projected_k5",
    "friction_projected_k6",
    "friction_projected_k7",
    "friction_projected_k8",
    "friction_projected_k9",
    "friction_projected_k10",
    "friction_projected_k11",
    "friction_projected_k12",
    "friction_projected_k13",
    "friction_projected_k14",
    "friction_projected_k15",
    "friction_projected_k16",
    "collide",
    "world_collide",
    "world_assemble",
    "world_solve",
    "world_lemke",
    "world_lemke_check",
    "world_friction",
    "world_friction_apgd",
    "world_finish",
);
