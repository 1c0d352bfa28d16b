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

impl ResidentWorlds {
    /// Workgroups of a dispatch over the worlds.
    pub(super) fn groups(&self) -> u32 {
        (self.count() as u32).div_ceil(WORKGROUP)
    }

    /// The collision phase: `candidate_pairs` over the worlds, the narrow
    /// phase of each pair family over its list (indirect), `world_contacts`
    /// over the worlds.
    pub(super) fn record_collide(&self, encoder: &mut wgpu::CommandEncoder, stages: &WorldStages) {
        self.record(encoder, &stages.candidate_pairs);
        encoder.copy_buffer_to_buffer(&self.lists, 0, &self.list_groups, 0, LIST_HEADERS);
        for (f, stage) in stages.narrow.iter().enumerate() {
            self.record_listed(encoder, stage, HEADER * (f as u64 + 1));
        }
        self.record(encoder, &stages.world_contacts);
    }

    /// The solve's dispatches after the collision phase: `world_assemble`
    /// and `world_solve_warm` over the worlds, then `world_lemke` and
    /// `world_lemke_check` over the worlds it listed (indirect: none in a
    /// step where every warm basis held; every world with contacts without
    /// warm bases); then the
    /// frictional rounds (`friction`, where any) and `world_finish` over
    /// the worlds.
    pub(super) fn record_solve(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        stages: &WorldStages,
        friction: Option<(&Stage, u32)>,
    ) {
        self.record(encoder, &stages.world_assemble);
        self.record(encoder, &stages.world_solve_warm);
        encoder.copy_buffer_to_buffer(&self.lists, 0, &self.list_groups, 0, 12);
        self.record_listed(encoder, &stages.world_lemke, 0);
        self.record_listed(encoder, &stages.world_lemke_check, 0);
        if let Some((stage, rounds)) = friction {
            for _ in 0..rounds {
                self.record(encoder, stage);
            }
        }
        self.record(encoder, &stages.world_finish);
    }

    /// A dispatch of `stage` over the worlds.
    pub(super) fn record(&self, encoder: &mut wgpu::CommandEncoder, stage: &Stage) {
        let mut pass = self.pass(encoder, stage);
        pass.dispatch_workgroups(self.groups().max(1), 1, 1);
    }

    /// An indirect dispatch of `stage` over a list: its workgroups at byte
    /// `at` of the headers' copy (a buffer bound for storage cannot be its
    /// own dispatch's arguments).
    fn record_listed(&self, encoder: &mut wgpu::CommandEncoder, stage: &Stage, at: u64) {
        let mut pass = self.pass(encoder, stage);
        pass.dispatch_workgroups_indirect(&self.list_groups, at);
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

    /// One step as [`Self::step`] does it, but the collision phase
    /// ([`Self::record_collide`]) and the solve ([`Self::record_solve`])
    /// in a submission of their own each, waited for: per phase its wall
    /// seconds and the difference of `clock` over it (a CPU clock of the
    /// caller's; for benches; nothing read back).
    ///
    /// # Errors
    /// [`Error::Gpu`] for device trouble.
    #[cfg_attr(
        not(test),
        allow(
            dead_code,
            reason = "the phase measurement of src/tests/gpu_resident.rs"
        )
    )]
    pub fn time_phases(
        &self,
        ctx: &GpuContext,
        dt: f64,
        clock: impl Fn() -> f64,
    ) -> Result<[[f64; 2]; 2], Error> {
        let stages = ctx.pipelines()?;
        let mut seconds = [[0.0; 2]; 2];
        self.write_params(ctx, dt);
        let step_stages = stages.world_step(ctx)?;
        for (phase, s) in seconds.iter_mut().enumerate() {
            let (start, cpu) = (std::time::Instant::now(), clock());
            ctx.scoped("resident world step", || {
                let mut encoder = ctx.encoder("resident world step");
                match phase {
                    0 => self.record_collide(&mut encoder, step_stages),
                    _ => self.record_solve(&mut encoder, step_stages, None),
                }
                ctx.queue.submit([encoder.finish()]);
                ctx.device
                    .poll(wgpu::PollType::wait_indefinitely())
                    .map_err(|e| Error::Gpu(format!("waiting for the GPU: {e}")))
            })??;
            *s = [start.elapsed().as_secs_f64(), clock() - cpu];
        }
        Ok(seconds)
    }
}
