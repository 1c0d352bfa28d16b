//! The resident GPU path of [`Solver::step_worlds`] (issue 23): worlds
//! kept on the device between calls and stepped there, one submission per
//! step ([`crate::gpu::resident`], `shaders/world_step.wgsl`).
//!
//! **Scope.** `Backend::Gpu` on an adapter with SHADER_F64 (precision f64),
//! method Auto or Lemke without `all_solutions`, every world with
//! restitution 0 and at most 16 bodies, and either frictionless (no pair
//! with μ > 0) or with a friction method the kernel twins (below). Any other batch takes the path of `world_path.rs` as a whole
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
//! check, a non-finite state, the loop budget, a frictional world the
//! step's rounds of `world_friction` left unfinished) keep their state on the
//! device; the host steps them from there by the CPU path's own code
//! (`prepare`, `step_world_on_cpu`, with the world's warm memory) and
//! writes them back; [`StepReport::resident`] counts them. Device trouble
//! (an error or a panic inside wgpu, as `gpu_path::guarded` catches it)
//! before the states came back leaves every world as it was: the device is
//! dropped (a warning) and the CPU path steps the batch from there.
//!
//! **Friction** (issue 23): with `friction_method` `pgs` or `jacobi` a
//! batch with friction stays resident; `world_friction` is the twin of
//! the CPU path's projected sweeps. Warm starts (one call kept, the
//! default) live on the device: the last step's reactions by (a, b,
//! feature); a flagged world's memory comes to the host before its CPU step
//! and what that step recorded goes back. Other friction methods (the
//! exact Coulomb default, `apgd`) take the other paths.
//!
//! No warm start for the frictionless islands: Lemke starts from the empty
//! basis every step.

use std::time::Instant;

use super::gpu_path::guarded;
use super::world_cpu::step_world_on_cpu;
use super::world_friction::{solved_reactions, step_frictional_world_on_cpu};
use super::world_path::{ResidentStep, StepReport, StepTimings, WorldStep, WorldStepReport};
use super::world_repair::{repair_settings, Repairs};
use super::Solver;
use crate::friction::FrictionMethod;
use crate::gpu::resident::layout::{cpu_id, device_key, flags, may_have_friction, out_of_scope};
use crate::gpu::resident::{
    MemoryEntry, ResidentFriction, ResidentWorlds, WorldRecord, MAX_ROUNDS,
};
use crate::gpu::{GpuContext, Precision};
use crate::report::{Device, FrictionIslandReport};
use crate::scene::Scene;
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

/// The rounds of `world_friction` for the step after one of `rounds`
/// rounds that gave `records`: twice as many where a world was left
/// unfinished (flagged [`flags::HANDED`]), else twice the most any world needed,
/// if that is fewer (the rounds come back down after a hard step); as they
/// were where no world had friction. Within 1 to [`MAX_ROUNDS`].
pub(crate) fn next_rounds(rounds: u32, records: &[WorldRecord]) -> u32 {
    let needed = records.iter().map(|r| r.rounds).max().unwrap_or(0);
    let next = match records.iter().any(|r| r.flags & flags::HANDED != 0) {
        true => rounds.saturating_mul(2),
        false if needed > 0 => rounds.min(needed.saturating_mul(2)),
        false => rounds,
    };
    next.clamp(1, MAX_ROUNDS)
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
            && (self.resident_friction().is_some() || !worlds.iter().any(may_have_friction))
    }

    /// The frictional phase's settings where the friction method has a
    /// resident twin (`pgs`, `jacobi`: the sweeps of `friction/projected.rs`,
    /// as the CPU path runs them) and warm starts (if on) keep one call's
    /// reactions (`warm_start_calls` 1, the default); None otherwise (a
    /// batch with friction then takes the other paths).
    fn resident_friction(&self) -> Option<ResidentFriction> {
        let s = &self.settings;
        let gauss_seidel = match s.friction_method {
            FrictionMethod::Pgs => true,
            FrictionMethod::Jacobi => false,
            _ => return None,
        };
        let p = s.friction().projected_settings();
        (!s.warm_start || s.warm_start_calls == 1).then_some(ResidentFriction {
            tolerance: p.f64_tolerance(),
            max_iterations: p.max_iterations,
            gauss_seidel,
            warm_start: s.warm_start,
        })
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
        let warm = self.settings.warm_start && self.resident_friction().is_some();
        let resident = self.resident.as_mut()?;
        let rounds = next_rounds(resident.worlds.rounds(), &records);
        resident.worlds.set_rounds(rounds);
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
            // The world's warm-start memory is the device's (a step there
            // recorded it last, or one here wrote it).
            if warm && may_have_friction(&worlds[k]) {
                match guarded(|| resident.worlds.read_memory(&ctx, k)) {
                    Ok(m) => {
                        let entries = m.into_iter().map(|(key, r)| (cpu_id(k, key), r));
                        self.world_warm[k].reactions.record(entries);
                    }
                    Err(Error::Gpu(why)) => trouble = Some(why),
                    Err(_) => {}
                }
            }
            let prepared = prepare(&worlds[k], k, dt);
            let mut item = WorldStep {
                world: &mut worlds[k],
                prepared,
                warm: &mut self.world_warm[k],
            };
            let frictional = item.prepared.scene.has_friction();
            let s = match frictional {
                true => step_frictional_world_on_cpu(&self.settings, k, &mut item, dt, &fix),
                false => step_world_on_cpu(&self.settings, k, &mut item, dt, &fix),
            };
            // What the step recorded goes to the device's memory.
            if warm && frictional {
                let entries = recorded(&item.prepared.scene, &s.friction);
                let written = guarded(|| resident.worlds.write_memory(&ctx, k, &entries));
                if let Err(Error::Gpu(why)) = written {
                    trouble = Some(why);
                }
            }
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
            let friction = self.resident_friction();
            self.resident = Some(Resident {
                worlds: ResidentWorlds::new(ctx, worlds, tolerance, &gpu, friction, test_slots())?,
                held: Vec::new(),
            });
        }
        let r = self.resident.as_ref().expect("uploaded above");
        r.worlds.step(ctx, dt)
    }
}

/// The warm-start entries a frictional step on the CPU recorded (its
/// solved islands' reactions by contact id), as the device keeps them.
fn recorded(scene: &Scene, islands: &[FrictionIslandReport]) -> Vec<MemoryEntry> {
    solved_reactions(scene, islands)
        .map(|(id, r)| (device_key(id), r))
        .collect()
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
    /// Counts a world's flags (a world the rounds left unfinished, still
    /// [`flags::HANDED`], as the loop budget).
    fn count(&mut self, f: u32) {
        let f = match f & flags::HANDED {
            0 => f,
            _ => (f & !flags::HANDED) | flags::BUDGET,
        };
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
