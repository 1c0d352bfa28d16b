//! The GPU path: WGSL compute shaders assemble and enumerate thousands of
//! contact islands at once; every answer is then checked on the CPU in f64
//! ([`validation`]).
//!
//! Stages (each a shader in `shaders/` with a CPU twin of the same name in
//! [`crate::cpu`], fed the same packed records of [`layout`]):
//!
//! | shader                    | CPU twin                         | what it computes                              |
//! |---------------------------|----------------------------------|-----------------------------------------------|
//! | `shaders/assembly.wgsl`   | [`crate::cpu::assembly`]         | per contact K, J, M⁻¹Jᵀ, v_rel, q; per island M, q |
//! | `shaders/enumeration.wgsl`| [`crate::cpu::enumeration`]      | per island the first valid complementary basis |
//! | `shaders/impulses.wgsl`   | [`crate::cpu::impulses`]         | per body its velocities after the impulses    |
//! | `shaders/collide.wgsl`    | `world::collide`, `collide_box`  | per candidate pair its contact points (narrow phase) |
//! | `shaders/world_step.wgsl` | `world::step`, `solver::world_cpu` | per resident world one step ([`resident`]) |
//!
//! A [`GpuContext`] is created once (adapter, device, queue, pipelines) and
//! reused for every batch; tests create their own. wgpu's errors never panic:
//! an uncaptured-error handler and an error scope around every submission
//! turn them into [`Error::Gpu`].
//!
//! # Adapter choice
//! [`GpuOptions`]: a forced adapter (name part, `--adapter` or
//! [`ENV_ADAPTER`]) and backend (`--gpu-backend` or [`ENV_BACKEND`]); else
//! `request_adapter` with PowerPreference::HighPerformance, a hardware
//! adapter on another backend preferred over a software one; else the
//! software fallback (Mesa lavapipe through Vulkan, llvmpipe through GL).
//! [`GpuContext::selection`] says which it was. No adapter: [`Error::Gpu`]
//! with [`INSTALL_HINT`].
//!
//! # Precision
//! f32 everywhere, f64 where the adapter has SHADER_F64 ([`Precision::Auto`]
//! picks f64 then). The f64 shaders do the CPU twins' arithmetic in the
//! same order with the same tolerances: every island's basis, counters and
//! z equal the CPU's (checked in `src/tests/gpu_stages.rs`). In f32 the
//! enumeration accepts more (feasibility 1e-4) and the f64 validation decides.
//!
//! # llvmpipe ends long loops
//! On lavapipe an invocation's loops stop, silently, after about 65,535
//! iterations in all (measured: an island of n = 9 came back "no basis" after
//! 393 of its 512 bases). The enumeration therefore runs in rounds with a
//! loop-work budget per invocation ([`batch::SOFTWARE_ROUND_BUDGET`]), saving
//! its place between rounds; see `shaders/enumeration.wgsl`.

//! # Modules, by concern
//! - [`context`]: adapter choice, device, error handling ([`GpuContext`]);
//! - [`shaders`]: the committed WGSL (`shaders/generated/`) and, in test
//!   builds, the generator that composes it from `shaders/`;
//! - [`pipelines`]: bind group layouts (declared once), pipelines, the
//!   enumeration kernels' run-time tolerances;
//! - [`buffers`]: storage buffers, readback, batches split under the
//!   device's limits; [`dispatch`]: dispatches in ranges of workgroups;
//! - [`kernel`]: which enumeration kernel runs which island;
//!   [`enumeration`]: the enumeration stage in rounds;
//! - [`batch`] (LCP batches) and [`scenes`] (whole scenes): orchestration;
//! - [`friction`] (frictional islands through the cone projection
//!   iterations, validated in f64) and [`friction_rounds`] (their packing
//!   and rounds); [`friction_assembly`] (W and q of frictional islands on
//!   the GPU, through assembly.wgsl on the direction contacts);
//! - [`layout`]: buffer layouts shared with the CPU twins;
//! - [`collide`]: the narrow phase (`shaders/collide.wgsl`), its test door;
//! - [`resident`]: worlds kept on the device and stepped there
//!   (`shaders/world_step.wgsl`).

pub(crate) mod all_bases;
pub mod batch;
pub(crate) mod buffers;
pub(crate) mod collide;
pub mod context;
pub(crate) mod dispatch;
pub(crate) mod enumeration;
pub mod friction;
pub mod friction_assembly;
pub(crate) mod friction_rounds;
pub mod kernel;
pub mod layout;
pub(crate) mod pipelines;
pub(crate) mod resident;
pub(crate) mod scene_chunks;
pub mod scenes;
pub(crate) mod shaders;
pub(crate) mod validation;

#[cfg(test)]
pub use batch::solve_lcp_batch;
pub use batch::{solve_lcp_batch_warm, EnumerationKernel, GpuSolveSettings};
pub use context::{
    list_adapters, AdapterSummary, BackendChoice, GpuContext, GpuOptions, Precision, INSTALL_HINT,
};
pub use scenes::solve_scenes_warm;
// The one-shot form, for the stage tests.
#[cfg(test)]
pub use scenes::solve_scenes;

/// Largest island the GPU enumerates (2¹⁶ bases per island). Larger islands
/// go to the CPU (Lemke) and are reported as `cpu_fallback`.
pub const MAX_GPU_N: usize = 16;

impl crate::report::Device {
    /// The device `ctx` as a report names it: hardware or software, the
    /// adapter in words (name, backend, type, how chosen, precision).
    pub(crate) fn of(ctx: &GpuContext) -> Self {
        use crate::report::DeviceKind;
        let a = ctx.adapter_info();
        crate::report::Device {
            kind: if a.software {
                DeviceKind::SoftwareGpu
            } else {
                DeviceKind::HardwareGpu
            },
            name: format!(
                "{} ({}, {}; {}; {})",
                a.name,
                a.backend,
                a.device_type,
                ctx.selection(),
                ctx.precision().name()
            ),
            precision: ctx.precision(),
        }
    }
}
