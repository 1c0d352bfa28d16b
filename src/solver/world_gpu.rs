//! The resident GPU path of [`Solver::step_worlds`] and
//! [`Solver::step_worlds_for`] (issue 23): worlds kept on the device
//! between calls and stepped there, up to 16 steps per submission
//! ([`crate::gpu::resident`], `shaders/world_step.wgsl`).
//!
//! **Scope.** `Backend::Gpu` on an adapter with SHADER_F64 (precision f64),
//! method Auto or Lemke without `all_solutions`, every world with
//! restitution 0 and at most 16 bodies, and either frictionless (no pair
//! with μ > 0) or with a friction method the kernel twins (below). Any other batch takes the path of `world_path.rs` as a whole
//! (the resident state is dropped).
//!
//! **State between calls, and what comes back.** The batch is uploaded
//! once and kept on the device while the worlds passed in are exactly
//! those it gave back last (compared field by field with a copy kept on the
//! host); worlds that differ in any way are uploaded afresh.
//! [`Solver::step_worlds_for`] takes many steps in one call: per step only
//! each world's record comes back (energies, penetration, counts, error,
//! flags: 80 bytes in f64), the states once, after the call's last step
//! ([`Solver::step_worlds`] is a call of one step). Steps go several to a
//! submission (1, then twice as many after each submission without a
//! flagged world, up to 16): a submission in which any world was flagged
//! is undone on the device (the state, the words and the warm-start memory
//! were copied aside before it) and taken again one step per submission, so
//! the trajectory is bit for bit that of one step per call.
//!
//! **Worlds the kernel could not step** (a flag: contact slots full, an
//! island above 16 contacts, Lemke gave up or its answer failed the f64
//! check, a non-finite state, the loop budget, a frictional world the
//! step's rounds of `world_friction` left unfinished) keep their state on the
//! device; the host steps them from there by the CPU path's own code
//! (`prepare`, `step_world_on_cpu`, with the world's warm memory) and
//! writes them back; [`StepReport::resident`] counts them. Device trouble
//! (an error or a panic inside wgpu, as `gpu_path::guarded` catches it)
//! drops the device (a warning) and the CPU path steps on from the last
//! good state: the states last read back, i.e. the worlds as passed to the
//! call, which are left untouched until the call's end; the steps the call
//! had reported are taken again on the CPU and not reported twice (the
//! CPU's warm-start memory of a world flagged in them is then a later
//! step's: a start, not the answer).
//!
//! **Friction** (issue 23): with `friction_method` `pgs`, `jacobi` or
//! `apgd` a batch with friction stays resident; `world_friction` is the
//! twin of the CPU path's projected sweeps or APGD. Warm starts (one call kept, the
//! default) live on the device: the last step's reactions by (a, b,
//! feature); a flagged world's memory comes to the host before its CPU step
//! and what that step recorded goes back. The exact Coulomb methods (the
//! default) take the other paths.
//!
//! Frictionless islands start from last step's basis (`world_solve_warm`'s
//! `warm_basis`, the twin of `world_cpu.rs`'s `warm_settle` without its
//! feasibility test before the check) where
//! `warm_start` is on and the method predicts; else Lemke from the empty
//! basis every step.

use std::time::Instant;

use super::gpu_path::guarded;
use super::world_cpu::step_world_on_cpu;
use super::world_friction::{solved_reactions, step_frictional_world_on_cpu};
use super::world_path::{
    Framing, ResidentStep, StepReport, StepTimings, WorldStep, WorldStepReport,
};
use super::world_repair::{repair_settings, Repairs};
use super::Solver;
use crate::friction::{FrictionMethod, ProjectedMethod};
use crate::gpu::resident::layout::{cpu_id, device_key, flags, may_have_friction, out_of_scope};
use crate::gpu::resident::{
    MemoryEntry, ResidentFriction, ResidentWorlds, States, WorldRecord, MAX_ROUNDS,
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

/// The rounds after `history`'s steps, each run with `rounds` rounds, where
/// they are the steps that one step per submission gives (None
/// otherwise): no world flagged in any, and none active in more rounds than
/// [`next_rounds`] would have given that step (the rounds come down after
/// easy steps; a world that needs more is left [`flags::HANDED`] then).
pub(crate) fn accepted(rounds: u32, history: &[Vec<WorldRecord>]) -> Option<u32> {
    let mut r = rounds;
    for records in history {
        if records.iter().any(|x| x.flags != 0 || x.rounds > r) {
            return None;
        }
        if r > 0 {
            r = next_rounds(r, records);
        }
    }
    Some(r)
}

/// The batch the device holds, the worlds as last read back, and how many
/// steps the next submission takes.
pub(super) struct Resident {
    worlds: ResidentWorlds,
    held: Vec<World>,
    /// Steps of the next submission: 1 after a step with a flagged world,
    /// twice the last submission's after one without (up to
    /// [`ResidentWorlds::most_steps`]).
    next: usize,
    /// Bytes read back that reports have counted.
    counted: u64,
    /// Every world's state read with the call's last step, and the worlds
    /// that step took on the CPU (their states after it).
    last: Option<(States, Vec<(usize, World)>)>,
}

impl Resident {
    /// Bytes read back since the last call.
    fn take_bytes(&mut self) -> u64 {
        let b = self.worlds.bytes_read() - self.counted;
        self.counted += b;
        b
    }
}

impl std::fmt::Debug for Resident {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Resident({} worlds)", self.held.len())
    }
}

impl Solver {
    /// Whether `steps` steps of `worlds` take the resident path, and with
    /// `Backend::Auto` why, in words for the step reports' `choice` (None:
    /// the solver's choice stands). `Backend::Gpu`: wherever the batch is
    /// in the path's scope; `Backend::Auto` with a GPU open: where it is in
    /// scope and the cost model's world figures estimate it faster than the
    /// CPU's per-world path, which takes the batch otherwise
    /// ([`crate::CostModel::estimate_worlds`]).
    /// The model's world figures are measured first where it has none
    /// (see `cost.rs`).
    /// `frames`: the steps after which the call reads some worlds' states.
    pub(super) fn world_route(
        &mut self,
        worlds: &[World],
        steps: usize,
        frames: &[usize],
    ) -> (bool, Option<String>) {
        let scope = self.resident_scope(worlds);
        if self.settings.backend != Backend::Auto || self.gpu.is_none() {
            return (scope, None);
        }
        if scope {
            self.world_costs();
            if self.gpu.is_none() {
                return (false, None);
            }
        }
        let bodies = worlds.iter().map(|w| w.bodies.len()).sum();
        // A batch still held goes on from its last submission's size.
        let first = match &self.resident {
            Some(r) if r.held == worlds => r.next,
            _ => 1,
        };
        let estimate =
            (self.cost.as_ref()).and_then(|m| m.estimate_worlds(bodies, steps, first, frames));
        let (resident, why) = match (scope, estimate) {
            (false, _) => (false, "out of the resident path's scope → CPU".into()),
            (true, None) => (false, "the cost model has no world figures → CPU".into()),
            (true, Some((cpu, gpu))) => (
                gpu < cpu,
                format!(
                    "cost model: CPU {:.3} ms, GPU {:.3} ms estimated → {}",
                    cpu * 1e3,
                    gpu * 1e3,
                    if gpu < cpu { "GPU" } else { "CPU" }
                ),
            ),
        };
        let n = worlds.len();
        let why = format!("{}; worlds: {n} × {steps} step(s), {why}", self.choice);
        (resident, Some(why))
    }

    /// Whether this batch is in the resident path's scope (see the module
    /// docs): a GPU open in f64, and the batch's method, worlds and
    /// friction.
    fn resident_scope(&self, worlds: &[World]) -> bool {
        let s = &self.settings;
        let on_gpu = (self.gpu.as_deref()).is_some_and(|c| c.precision() == Precision::F64);
        on_gpu
            && matches!(s.method, Method::Auto | Method::Lemke)
            && !s.all_solutions
            && !worlds.is_empty()
            && worlds.iter().all(|w| out_of_scope(w).is_none())
            && (self.resident_friction().is_some() || !worlds.iter().any(may_have_friction))
    }

    /// The frictional phase's settings where the friction method has a
    /// resident twin (`pgs`, `jacobi`: the sweeps of `friction/projected.rs`;
    /// `apgd`: `friction/apgd.rs`; as the CPU path runs them) and warm
    /// starts (if on) keep one call's reactions (`warm_start_calls` 1, the
    /// default); None otherwise (a batch with friction then takes the
    /// other paths).
    fn resident_friction(&self) -> Option<ResidentFriction> {
        let s = &self.settings;
        let method = match s.friction_method {
            FrictionMethod::Pgs => ProjectedMethod::GaussSeidel,
            FrictionMethod::Jacobi => ProjectedMethod::Jacobi,
            FrictionMethod::Apgd => ProjectedMethod::Apgd,
            _ => return None,
        };
        let p = s.friction().projected_settings();
        (!s.warm_start || s.warm_start_calls == 1).then_some(ResidentFriction {
            tolerance: p.f64_tolerance(),
            max_iterations: p.max_iterations,
            method,
            warm_start: s.warm_start,
        })
    }

    /// `steps` steps of `worlds` on the resident path (the caller routed
    /// them here, [`Self::world_route`]), each step's report given to
    /// `observe` (steps counted from 0), the frames `framing` asks for
    /// handed over as their steps end, every state read back with the
    /// last step. The worlds were checked by the caller. Returns (steps
    /// reported, steps the worlds are at): (`steps`, `steps`) when the
    /// device took them all; (0, 0) where the device failed before a step;
    /// (j, 0) after device trouble in step j: the device is dropped (a
    /// warning), the worlds are as passed in (the last states read back)
    /// and the caller steps them on the CPU path from there, giving
    /// `observe` the steps from j on (and `framing` the frames not yet
    /// handed over).
    pub(super) fn step_worlds_resident(
        &mut self,
        worlds: &mut [World],
        dt: f64,
        steps: usize,
        observe: &mut dyn FnMut(usize, StepReport),
        framing: Option<&mut Framing>,
    ) -> (usize, usize) {
        let Some(ctx) = self.gpu.clone() else {
            return (0, 0);
        };
        let mut done = 0;
        match self.resident_run(&ctx, worlds, dt, steps, observe, framing, &mut done) {
            Ok(()) => (steps, steps),
            Err(e) => {
                self.resident = None;
                if let Error::Gpu(why) = e {
                    self.fall_back(why);
                }
                (done, 0)
            }
        }
    }

    /// [`Self::step_worlds_resident`]'s steps, `done` counting those
    /// reported: the device's parts guarded (a panic inside wgpu is device
    /// trouble), `observe` and the frames' hand-over called outside them
    /// (their panics are their own). Submissions end where a frame is
    /// wanted (its worlds' states read, a ranged read) and at the call's
    /// end, whose last submission reads every state with its records.
    #[allow(clippy::too_many_arguments, reason = "the call's parts, passed on")]
    fn resident_run(
        &mut self,
        ctx: &GpuContext,
        worlds: &mut [World],
        dt: f64,
        steps: usize,
        observe: &mut dyn FnMut(usize, StepReport),
        mut framing: Option<&mut Framing>,
        done: &mut usize,
    ) -> Result<(), Error> {
        guarded(|| self.hold(ctx, worlds))?;
        while *done < steps {
            let stop = (framing.as_deref())
                .and_then(|f| f.next(*done, steps))
                .unwrap_or(steps);
            while *done < stop {
                let (left, last) = (stop - *done, stop == steps);
                for report in guarded(|| self.resident_steps(ctx, worlds, dt, left, last))? {
                    observe(*done, report);
                    *done += 1;
                }
            }
            if let (Some(f), true) = (framing.as_deref_mut(), stop < steps) {
                let ks = f.frames.worlds;
                let mut states: Vec<World> = ks.iter().map(|&k| worlds[k].clone()).collect();
                let r = self.resident.as_ref().expect("held");
                if !ks.is_empty() {
                    guarded(|| r.worlds.read_worlds(ctx, ks, &mut states))?;
                }
                f.give(stop, &states);
            }
        }
        let r = self.resident.as_mut().expect("held");
        let (states, on_cpu) = r.last.take().expect("read with the last step");
        r.worlds.unpack_states(&states, worlds)?;
        for (k, w) in on_cpu {
            worlds[k] = w;
        }
        r.held.clear();
        r.held.extend_from_slice(worlds);
        Ok(())
    }

    /// The batch on the device: kept where the worlds are those it gave
    /// back last, else uploaded.
    fn hold(&mut self, ctx: &GpuContext, worlds: &[World]) -> Result<(), Error> {
        if matches!(&self.resident, Some(r) if r.held == worlds) {
            return Ok(());
        }
        self.resident = None;
        let gpu = self.settings.gpu_solve();
        let tolerance = self.settings.tolerance;
        // The CPU path's `warm_settle` runs where warm starts are on and
        // the method predicts (`gpu.predict`: not Lemke).
        let warm = self.settings.warm_start && gpu.predict;
        let friction = self.resident_friction();
        let slots = test_slots();
        self.resident = Some(Resident {
            worlds: ResidentWorlds::new(ctx, worlds, tolerance, &gpu, warm, friction, slots)?,
            held: worlds.to_vec(),
            next: 1,
            counted: 0,
            last: None,
        });
        Ok(())
    }

    /// Up to `left` steps, the next submission's: several in one where the
    /// last had no flagged world and these have none either (and the rounds
    /// a step at a time would give, [`accepted`]); else (the submission
    /// undone) one step per submission as [`Self::resident_step`] takes it.
    /// `last`: the `left`-th step is the call's last, whose submission
    /// reads every state too (kept in [`Resident::last`]).
    fn resident_steps(
        &mut self,
        ctx: &GpuContext,
        worlds: &[World],
        dt: f64,
        left: usize,
        last: bool,
    ) -> Result<Vec<StepReport>, Error> {
        let r = self.resident.as_mut().expect("held");
        let most = r.worlds.most_steps();
        let k = r.next.min(left).min(most);
        if k > 1 {
            let start = Instant::now();
            let (history, states) = r.worlds.steps_and_states(ctx, dt, k, last && k == left)?;
            let seconds = start.elapsed().as_secs_f64() / k as f64;
            if let Some(rounds) = accepted(r.worlds.rounds(), &history) {
                r.last = states.map(|s| (s, Vec::new()));
                r.worlds.set_rounds(rounds);
                r.next = (2 * k).min(most);
                let bytes = r.take_bytes();
                let up = r.worlds.bytes_up;
                let reports = history.iter().enumerate().map(|(j, records)| {
                    let figures = ResidentStep {
                        on_device: records.len(),
                        bytes_up: up,
                        submission_steps: k,
                        bytes_back: bytes * (j as u64 + 1) / k as u64 - bytes * j as u64 / k as u64,
                        ..ResidentStep::default()
                    };
                    let worlds = records.iter().map(world_report).collect();
                    self.resident_report(ctx, worlds, Repairs::default(), figures, [seconds, 0.0])
                });
                return Ok(reports.collect());
            }
            // Undone: its records' bytes go to the steps taken again.
            r.worlds.restore(ctx)?;
        }
        let mut reports = Vec::with_capacity(k);
        let mut clean = true;
        for i in 0..k {
            let states = last && i + 1 == left;
            let (report, flagged) = self.resident_step(ctx, worlds, dt, states)?;
            clean = flagged == 0;
            reports.push(report);
        }
        let r = self.resident.as_mut().expect("held");
        r.next = if clean { 2.min(most) } else { 1 };
        Ok(reports)
    }

    /// One step in a submission of its own: the worlds the kernel flagged
    /// stepped on the CPU from their state before the step (which the
    /// device kept; read back) by the CPU path's code and written back.
    /// `worlds`: the batch held (for the bodies' constants). With
    /// `all_states` every state comes back with the records, in one map (the
    /// flagged worlds' taken from it), kept in [`Resident::last`]. Returns
    /// the step's report and the worlds flagged.
    fn resident_step(
        &mut self,
        ctx: &GpuContext,
        worlds: &[World],
        dt: f64,
        all_states: bool,
    ) -> Result<(StepReport, usize), Error> {
        let start = Instant::now();
        let warm = self.settings.warm_start && self.resident_friction().is_some();
        let r = self.resident.as_mut().expect("held");
        let (mut history, all) = r.worlds.steps_and_states(ctx, dt, 1, all_states)?;
        let records = history.pop().expect("one step");
        let device_seconds = start.elapsed().as_secs_f64();
        let start = Instant::now();
        r.worlds
            .set_rounds(next_rounds(r.worlds.rounds(), &records));
        let flagged: Vec<usize> = (0..records.len())
            .filter(|&k| records[k].flags != 0)
            .collect();
        let mut reports: Vec<WorldStepReport> = records.iter().map(world_report).collect();
        let mut repairs = Repairs::default();
        let mut states: Vec<World> = flagged.iter().map(|&k| worlds[k].clone()).collect();
        match &all {
            Some(all) => (flagged.iter().zip(&mut states))
                .for_each(|(&k, w)| r.worlds.unpack_world(all, k, w)),
            None if !flagged.is_empty() => r.worlds.read_worlds(ctx, &flagged, &mut states)?,
            None => {}
        }
        let keep = self.settings.warm_start_calls;
        self.world_warm
            .resize_with(worlds.len(), || Warm::new(keep, 1));
        let fix = repair_settings(&self.settings);
        for (&k, w) in flagged.iter().zip(&mut states) {
            // The world's warm-start memory is the device's (a step there
            // recorded it last, or one here wrote it).
            if warm && may_have_friction(w) {
                let entries = r.worlds.read_memory(ctx, k)?;
                let entries = entries.into_iter().map(|(key, x)| (cpu_id(k, key), x));
                self.world_warm[k].reactions.record(entries);
            }
            let prepared = prepare(w, k, dt);
            let mut item = WorldStep {
                world: w,
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
                r.worlds.write_memory(ctx, k, &entries)?;
            }
            reports[k] = s.world;
            repairs.merge(s.repairs);
            r.worlds.write_world(ctx, k, w)?;
        }
        r.last = all.map(|all| (all, flagged.iter().copied().zip(states).collect()));
        let mut figures = ResidentStep {
            on_device: worlds.len() - flagged.len(),
            on_cpu: flagged.len(),
            bytes_up: r.worlds.bytes_up,
            bytes_back: r.take_bytes(),
            submission_steps: 1,
            ..ResidentStep::default()
        };
        for x in &records {
            figures.count(x.flags);
        }
        let seconds = [device_seconds, start.elapsed().as_secs_f64()];
        let report = self.resident_report(ctx, reports, repairs, figures, seconds);
        Ok((report, flagged.len()))
    }

    /// A resident step's report: the worlds' figures, `seconds` on the
    /// device and on the host.
    fn resident_report(
        &self,
        ctx: &GpuContext,
        worlds: Vec<WorldStepReport>,
        repairs: Repairs,
        figures: ResidentStep,
        [device_seconds, cpu_seconds]: [f64; 2],
    ) -> StepReport {
        let mut solve = self.empty_report(Device::of(ctx));
        solve.timings.gpu = device_seconds;
        solve.timings.solve = cpu_seconds;
        solve.timings.total = device_seconds + cpu_seconds;
        StepReport {
            unsolved: worlds.iter().map(|w| w.unsolved).sum(),
            worlds,
            timings: StepTimings {
                collision: 0.0,
                solve: solve.timings.total,
                integrate: 0.0,
            },
            solve,
            repairs,
            resident: Some(figures),
        }
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
