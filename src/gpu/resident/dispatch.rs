//! One step's dispatches of resident worlds, recorded into the caller's
//! encoder in the order of `shaders/world_step.wgsl`'s header: the
//! collision phase ([`ResidentWorlds::record_collide`]: `candidate_pairs`,
//! the narrow phase per pair family over its list, `world_contacts`), then
//! the solve ([`ResidentWorlds::record_solve`]: `world_assemble`, `world_solve_warm`,
//! `world_lemke` and `world_lemke_check` over the worlds it listed), the rounds of
//! `world_friction` where any, `world_finish`. The lists'
//! sizes are on the device: the indirect dispatches read their workgroups
//! from a copy of the lists' headers ([`LIST_HEADERS`]), made between the
//! dispatch that fills a list and the one that reads it.

use super::ResidentWorlds;
use crate::gpu::pipelines::{Stage, WorldStages, WORKGROUP};
use crate::gpu::GpuContext;
use crate::Error;

/// Bytes of the lists' headers at the start of `lists` (4 lists × x, y,
/// z, count): the worlds listed for Lemke's path, then the box–box,
/// box–plane and sphere pairs (the shader's LIST_LEMKE, LIST_BOX_BOX, LIST_BOX_PLANE,
/// LIST_SPHERE).
pub(super) const LIST_HEADERS: u64 = 64;
/// Bytes of one list's header.
const HEADER: u64 = 16;

/// The lists' words at the start (`lists`, before any step): each header
/// 0 workgroups × 1 × 1 and count 0, the entries after them.
pub(super) fn empty_lists(words: usize) -> Vec<u32> {
    let mut list = vec![0u32; words];
    for header in list.chunks_mut(4).take((LIST_HEADERS / HEADER) as usize) {
        header[1..3].copy_from_slice(&[1, 1]);
    }
    list
}

/// One command of a step: a dispatch over the worlds, an indirect one over
/// a list (its workgroups at a byte of the headers' copy), or the copy of
/// the lists' first bytes into that copy.
pub(super) enum Op<'s> {
    Worlds(&'s Stage),
    Listed(&'s Stage, u64),
    CopyHeaders(u64),
}

impl Op<'_> {
    /// The entry point's name (a copy: "copy headers"), for the timings.
    #[cfg_attr(
        not(test),
        allow(dead_code, reason = "the kernel timings of the tests")
    )]
    pub(super) fn name(&self) -> &'static str {
        match self {
            Op::Worlds(s) | Op::Listed(s, _) => s.entry,
            Op::CopyHeaders(_) => "copy headers",
        }
    }
}

impl ResidentWorlds {
    /// Workgroups of a dispatch over the worlds.
    pub(super) fn groups(&self) -> u32 {
        (self.count() as u32).div_ceil(WORKGROUP)
    }

    /// The collision phase: `candidate_pairs` over the worlds, the narrow
    /// phase of each pair family over its list (indirect), `world_contacts`
    /// over the worlds.
    pub(super) fn collide_ops<'s>(&self, stages: &'s WorldStages) -> Vec<Op<'s>> {
        let mut ops = vec![
            Op::Worlds(&stages.candidate_pairs),
            Op::CopyHeaders(LIST_HEADERS),
        ];
        for (f, stage) in stages.narrow.iter().enumerate() {
            ops.push(Op::Listed(stage, HEADER * (f as u64 + 1)));
        }
        ops.push(Op::Worlds(&stages.world_contacts));
        ops
    }

    /// The solve's dispatches after the collision phase: `world_assemble`
    /// and `world_solve_warm` over the worlds, then `world_lemke` and
    /// `world_lemke_check` over the worlds it listed (indirect: none in a
    /// step where every warm basis held; every world with contacts without
    /// warm bases); then the
    /// frictional rounds (`friction`, where any) and `world_finish` over
    /// the worlds.
    pub(super) fn solve_ops<'s>(
        &self,
        stages: &'s WorldStages,
        friction: Option<(&'s Stage, u32)>,
    ) -> Vec<Op<'s>> {
        let mut ops = vec![
            Op::Worlds(&stages.world_assemble),
            Op::Worlds(&stages.world_solve_warm),
            Op::CopyHeaders(12),
            Op::Listed(&stages.world_lemke, 0),
            Op::Listed(&stages.world_lemke_check, 0),
        ];
        if let Some((stage, rounds)) = friction {
            ops.extend((0..rounds).map(|_| Op::Worlds(stage)));
        }
        ops.push(Op::Worlds(&stages.world_finish));
        ops
    }

    /// Records `ops` into `encoder`, in order.
    pub(super) fn record(&self, encoder: &mut wgpu::CommandEncoder, ops: &[Op]) {
        for op in ops {
            match *op {
                Op::Worlds(stage) => {
                    let mut pass = self.pass(encoder, stage);
                    pass.dispatch_workgroups(self.groups().max(1), 1, 1);
                }
                // A buffer bound for storage cannot be its own dispatch's
                // arguments: the headers' copy is.
                Op::Listed(stage, at) => {
                    let mut pass = self.pass(encoder, stage);
                    pass.dispatch_workgroups_indirect(&self.list_groups, at);
                }
                Op::CopyHeaders(len) => {
                    encoder.copy_buffer_to_buffer(&self.lists, 0, &self.list_groups, 0, len)
                }
            }
        }
    }

    fn pass<'e>(
        &self,
        encoder: &'e mut wgpu::CommandEncoder,
        stage: &Stage,
    ) -> wgpu::ComputePass<'e> {
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("world step"),
            timestamp_writes: None,
        });
        pass.set_pipeline(&stage.pipeline);
        pass.set_bind_group(0, &self.bind, &[]);
        pass
    }

    /// One step as [`Self::step`] does it (frictionless), but each command
    /// ([`Self::collide_ops`], [`Self::solve_ops`]) in a submission of its
    /// own, waited for: per command its name, its wall seconds and the
    /// difference of `clock` over it (a CPU clock of the caller's; for
    /// benches; nothing read back).
    ///
    /// # Errors
    /// [`Error::Gpu`] for device trouble.
    #[cfg_attr(
        not(test),
        allow(
            dead_code,
            reason = "the kernel measurement of src/tests/gpu_resident.rs"
        )
    )]
    pub fn time_kernels(
        &self,
        ctx: &GpuContext,
        dt: f64,
        clock: impl Fn() -> f64,
    ) -> Result<Vec<(&'static str, [f64; 2])>, Error> {
        let pipelines = ctx.pipelines()?;
        let stages = pipelines.world_step(ctx)?;
        self.write_params(ctx, dt);
        let mut ops = self.collide_ops(stages);
        ops.extend(self.solve_ops(stages, None));
        let mut times = Vec::with_capacity(ops.len());
        for op in &ops {
            let (start, cpu) = (std::time::Instant::now(), clock());
            ctx.scoped("resident world step", || {
                let mut encoder = ctx.encoder("resident world step");
                self.record(&mut encoder, std::slice::from_ref(op));
                ctx.queue.submit([encoder.finish()]);
                ctx.device
                    .poll(wgpu::PollType::wait_indefinitely())
                    .map_err(|e| Error::Gpu(format!("waiting for the GPU: {e}")))
            })??;
            times.push((op.name(), [start.elapsed().as_secs_f64(), clock() - cpu]));
        }
        Ok(times)
    }
}
