//! The resident GPU path of [`Solver::step_worlds`] (issue 23): worlds
//! kept on the device between calls and stepped there, one submission per
//! step ([`crate::gpu::resident`], `shaders/world_step.wgsl`).
//!
//! **Scope.** `Backend::Gpu` on an adapter with SHADER_F64 (precision f64),
//! method Auto or Lemke without `all_solutions`, and every world
//! frictionless (no pair with μ > 0), with restitution 0 and at most 16
//! bodies. Any other batch takes the path of `world_path.rs` as a whole
//! (the resident state is dropped).
//!
//! **State between calls.** `step_worlds` takes the worlds by `&mut` and
//! gives them back stepped, so each call reads the states back (the
//! device's own bytes, unpacked in place). The device keeps the batch
//! between calls while the worlds passed in are exactly those it gave back
//! (compared field by field with a copy kept on the host); worlds that
//! differ in any way are uploaded afresh.
//!
//! **Worlds the kernel could not step** (a flag: contact slots full, an
//! island above 16 contacts, Lemke gave up or its answer failed the f64
//! check, a non-finite state, the loop budget) keep their state on the
//! device; the host steps them from there by the CPU path's own code
//! (`prepare`, `step_world_on_cpu`, with the world's warm memory) and
//! writes them back; [`StepReport::resident`] counts them. Device trouble
//! (an error or a panic inside wgpu, as `gpu_path::guarded` catches it)
//! before the states came back leaves every world as it was: the device is
//! dropped (a warning) and the CPU path steps the batch from there.
//!
//! No warm start in the kernel: Lemke starts from the empty basis every
//! step.

use std::time::Instant;

use super::gpu_path::guarded;
use super::world_cpu::step_world_on_cpu;
use super::world_path::{ResidentStep, StepReport, StepTimings, WorldStep, WorldStepReport};
use super::world_repair::{repair_settings, Repairs};
use super::Solver;
use crate::gpu::resident::layout::{flags, out_of_scope};
use crate::gpu::resident::{ResidentWorlds, WorldRecord};
use crate::gpu::{GpuContext, Precision};
use crate::report::Device;
use crate::settings::{Backend, Method};
use crate::warm::Warm;
use crate::world::step::prepare;
use crate::world::World;
use crate::Error;

#[cfg(test)]
thread_local! {
    static TEST_SLOTS: std::cell::Cell<Option<usize>> = const { std::cell::Cell::new(None) };
}

/// Tests: contact slots per world of the batches this thread uploads from
/// now on (None: `layout::contact_slots`' bound), to force an overflow.
#[cfg(test)]
pub(crate) fn set_test_slots(slots: Option<usize>) {
    TEST_SLOTS.with(|s| s.set(slots));
}

/// Contact slots per world where a test set them.
fn test_slots() -> Option<usize> {
    #[cfg(test)]
    return TEST_SLOTS.with(|s| s.get());
    #[cfg(not(test))]
    None
}

/// The batch the device holds and the worlds as it gave them back.
pub(super) struct Resident {
    worlds: ResidentWorlds,
    held: Vec<World>,
}

impl std::fmt::Debug for Resident {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Resident({} worlds)", self.held.len())
    }
}

impl Solver {
    /// Whether this batch takes the resident path (see the module docs).
    fn resident_scope(&self, worlds: &[World]) -> bool {
        let s = &self.settings;
        let on_gpu = s.backend == Backend::Gpu
            && (self.gpu.as_deref()).is_some_and(|c| c.precision() == Precision::F64);
        on_gpu
            && matches!(s.method, Method::Auto | Method::Lemke)
            && !s.all_solutions
            && !worlds.is_empty()
            && worlds.iter().all(|w| out_of_scope(w).is_none())
    }

    /// One step of `worlds` on the resident path, or None where the batch
    /// is out of its scope or the device failed before any world moved
    /// (the caller steps them on the CPU path then). The worlds were
    /// checked by the caller.
    pub(super) fn step_worlds_resident(
        &mut self,
        worlds: &mut [World],
        dt: f64,
    ) -> Option<StepReport> {
        if !self.resident_scope(worlds) {
            self.resident = None;
            return None;
        }
        let ctx = self.gpu.clone()?;
        let start = Instant::now();
        let stepped = guarded(|| self.device_step(&ctx, worlds, dt));
        let device_seconds = start.elapsed().as_secs_f64();
        let (records, states) = match stepped {
            Ok(r) => r,
            Err(e) => {
                self.resident = None;
                if let Error::Gpu(why) = e {
                    self.fall_back(why);
                }
                return None;
            }
        };
        let start = Instant::now();
        let resident = self.resident.as_mut()?;
        let mut flagged = Vec::new();
        for (k, (w, r)) in worlds.iter_mut().zip(&records).enumerate() {
            match r.flags {
                0 => states.unpack(resident.worlds.first_body(k), w),
                _ => flagged.push(k),
            }
        }
        // The flagged worlds from their state before the step, by the CPU
        // path's code.
        let keep = self.settings.warm_start_calls;
        self.world_warm
            .resize_with(worlds.len(), || Warm::new(keep, 1));
        let fix = repair_settings(&self.settings);
        let mut reports: Vec<WorldStepReport> = records.iter().map(world_report).collect();
        let mut repairs = Repairs::default();
        let mut trouble = None;
        for &k in &flagged {
            let prepared = prepare(&worlds[k], k, dt);
            let mut item = WorldStep {
                world: &mut worlds[k],
                prepared,
                warm: &mut self.world_warm[k],
            };
            let s = step_world_on_cpu(&self.settings, k, &mut item, dt, &fix);
            reports[k] = s.world;
            repairs.merge(s.repairs);
            let written = guarded(|| resident.worlds.write_world(&ctx, k, &worlds[k]));
            if let Err(Error::Gpu(why)) = written {
                trouble = Some(why);
            }
        }
        resident.held.clear();
        resident.held.extend_from_slice(worlds);
        let mut figures = ResidentStep {
            on_device: worlds.len() - flagged.len(),
            on_cpu: flagged.len(),
            bytes_up: resident.worlds.bytes_up,
            bytes_back: resident.worlds.bytes_back,
            ..ResidentStep::default()
        };
        for r in &records {
            figures.count(r.flags);
        }
        if let Some(why) = trouble {
            // The worlds are stepped; the next step starts on the CPU.
            self.resident = None;
            self.fall_back(why);
        }
        let cpu_seconds = start.elapsed().as_secs_f64();
        let mut solve = self.empty_report(Device::of(&ctx));
        solve.timings.gpu = device_seconds;
        solve.timings.solve = cpu_seconds;
        solve.timings.total = device_seconds + cpu_seconds;
        Some(StepReport {
            unsolved: reports.iter().map(|w| w.unsolved).sum(),
            worlds: reports,
            timings: StepTimings {
                collision: 0.0,
                solve: solve.timings.total,
                integrate: 0.0,
            },
            solve,
            repairs,
            resident: Some(figures),
        })
    }

    /// The device's part of a step: the batch uploaded where the device
    /// does not hold these worlds, one step, the records and states back.
    fn device_step(
        &mut self,
        ctx: &GpuContext,
        worlds: &[World],
        dt: f64,
    ) -> Result<(Vec<WorldRecord>, crate::gpu::resident::States), Error> {
        let held = matches!(&self.resident, Some(r) if r.held == worlds);
        if !held {
            self.resident = None;
            let gpu = self.settings.gpu_solve();
            let tolerance = self.settings.tolerance;
            self.resident = Some(Resident {
                worlds: ResidentWorlds::new(ctx, worlds, tolerance, &gpu, test_slots())?,
                held: Vec::new(),
            });
        }
        let r = self.resident.as_ref().expect("uploaded above");
        r.worlds.step(ctx, dt)
    }
}

/// A world's figures from its record (the kernel stepped it).
fn world_report(r: &WorldRecord) -> WorldStepReport {
    WorldStepReport {
        kinetic: r.kinetic,
        potential: r.potential,
        max_penetration: r.max_penetration,
        contacts: r.contacts,
        islands: r.islands,
        max_error: r.max_error,
        awake: r.awake,
        ..WorldStepReport::default()
    }
}

impl ResidentStep {
    /// Counts a world's flags.
    fn count(&mut self, f: u32) {
        let bits = [
            flags::CONTACTS_FULL,
            flags::ISLAND_TOO_LARGE,
            flags::NOT_SOLVED,
            flags::NON_FINITE,
            flags::BUDGET,
        ];
        let counts = [
            &mut self.contacts_full,
            &mut self.island_too_large,
            &mut self.not_solved,
            &mut self.non_finite,
            &mut self.budget,
        ];
        for (bit, n) in bits.into_iter().zip(counts) {
            *n += usize::from(f & bit != 0);
        }
    }
}
