//! Worlds in time: [`Solver::step_worlds`] advances a batch of
//! [`World`]s by one step Δt (the velocity-level time-stepping of
//! Stewart–Trinkle and Anitescu–Potra: impulses from a complementarity
//! problem per step; the parts per world are in [`crate::world::step`]) in two passes over the worlds, each spread over
//! the cores:
//!
//! 1. **collision**: gravity, broad and narrow phase, each world's scene;
//! 2. the **solve**, then the velocities, poses and sleep counters.
//!
//! Where the islands are solved:
//! - on the CPU, a frictionless world is solved inside pass 2, world by
//!   world ([`step_world_on_cpu`]): its islands found once, its
//!   LCPs assembled and solved by the same per-island functions as
//!   [`Solver::solve_scenes`] (prediction, checked Lemke, enumeration; the
//!   same final check), warm-started from that world's own memory of the
//!   last step, so that its bits do not depend on the batch around it;
//! - on the CPU, a world with friction (any contact with μ > 0) is solved
//!   inside pass 2 too ([`step_frictional_world_on_cpu`]): its
//!   frictional islands by the exact Coulomb solvers, each to
//!   `friction_tolerance`, warm-started from that world's own reactions of
//!   the last step;
//! - while a GPU is open, every world goes in ONE batch through
//!   [`Solver::solve_built_scenes`] between the two passes; pass 2 then
//!   repairs and moves each world ([`finish_batch_world`]).
//!
//! The scenes are built here from worlds checked at the start of the step,
//! so `solve_scenes`' checks are skipped for them: every index is in
//! range, every normal unit, every number finite and every mass and inertia
//! ≥ 0 by construction. Islands the solver leaves unsolved are repaired
//! before any body moves ([`super::world_repair`]).

use std::time::Instant;

use serde::Serialize;

use super::friction_path::friction_on_gpu;
use super::world_cpu::{finish_batch_world, parallel_map_mut, step_world_on_cpu};
use super::world_friction::step_frictional_world_on_cpu;
use super::world_repair::{repair_settings, Repairs};
use super::{cpu_device, Solver};
use crate::cpu::batch::parallel_map;
use crate::cpu::impulses::BodyVelocity;
use crate::report::{FrictionIslandReport, IslandReport, Report, SceneReport, Timings};
use crate::scene::Scene;
use crate::settings::Backend;
use crate::warm::Warm;
use crate::world::step::{prepare, Prepared};
use crate::world::World;
use crate::Error;

/// One world after a step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
#[non_exhaustive]
pub struct WorldStepReport {
    /// Kinetic energy (J) after the step.
    pub kinetic: f64,
    /// Potential energy −Σ m g·x (J) after the step.
    pub potential: f64,
    /// Deepest penetration (m, ≥ 0) among this step's contacts, before the
    /// step's correction (collision's −φ).
    pub max_penetration: f64,
    /// Contacts this step.
    pub contacts: usize,
    /// Islands this step.
    pub islands: usize,
    /// Largest error measure of this world's islands (0 when none): the
    /// LCP error of frictionless islands, the Coulomb error of frictional ones.
    pub max_error: f64,
    /// Dynamic bodies awake after the step.
    pub awake: usize,
    /// Islands of this world the solver left unsolved (repaired, see
    /// [`StepReport::repairs`]).
    pub unsolved: usize,
    /// Bounces resolved at their time of impact within the step (sub-steps
    /// before the DVI step; their impulses are in the step's report, added
    /// to their contacts').
    pub impacts: usize,
    /// Bounces still due when the step's bound on impacts (16) was reached:
    /// left to the DVI step, which bounces them from where they are.
    pub impacts_deferred: usize,
}

/// Seconds per phase of one step (wall time; within pass 2, each phase's
/// share of the pass as the threads measured it).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
#[non_exhaustive]
pub struct StepTimings {
    /// The worlds' checks, gravity, broad and narrow phase, the scenes (all
    /// worlds; one pass over the cores).
    pub collision: f64,
    /// Islands, assembly, solves, repairs and impulses (the batch's solve
    /// included); its parts are in [`StepReport::solve`]'s timings.
    pub solve: f64,
    /// Velocities and poses.
    pub integrate: f64,
}

/// What one step of a batch of worlds found.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct StepReport {
    /// One per world, in the caller's order.
    pub worlds: Vec<WorldStepReport>,
    /// Every world's islands as one report (statuses, paths, device;
    /// scene k is world k), as [`Solver::solve_scenes`] gives it.
    pub solve: Report,
    /// Seconds per phase.
    pub timings: StepTimings,
    /// Islands whose status was not a solution (before their repair).
    pub unsolved: usize,
    /// What the unsolved islands got instead (see `world_repair`).
    pub repairs: Repairs,
    /// The resident GPU path's figures (None on the other paths; see
    /// `world_gpu.rs`). Its steps report no islands in `solve`: the
    /// per-world figures in `worlds` come from the device.
    pub resident: Option<ResidentStep>,
}

/// One step on the resident GPU path: where the worlds were stepped, why
/// the kernel left some to the CPU (worlds per flag), bytes moved.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
#[non_exhaustive]
pub struct ResidentStep {
    /// Worlds the kernel stepped.
    pub on_device: usize,
    /// Worlds it flagged, stepped on the CPU from their state before the
    /// step and written back.
    pub on_cpu: usize,
    /// Flagged worlds by flag: contact slots full, an island above 16
    /// contacts, Lemke gave up or the f64 check failed, a non-finite state,
    /// the loop budget spent.
    pub contacts_full: usize,
    /// See `contacts_full`.
    pub island_too_large: usize,
    /// See `contacts_full`.
    pub not_solved: usize,
    /// See `contacts_full`.
    pub non_finite: usize,
    /// See `contacts_full`.
    pub budget: usize,
    /// Bytes uploaded when the batch went to the device (once per batch).
    pub bytes_up: u64,
    /// Bytes read back from the device for this step: the worlds' records
    /// (80 bytes a world in f64), the states of the worlds it flagged
    /// (and their warm-start memories), and after a call's last step
    /// every state (13 scalars and 2 words a body). Several steps of one
    /// submission share its bytes out; an undone submission's go to the
    /// first step taken again.
    pub bytes_back: u64,
    /// Steps in the submission that took this step (1: a submission of its
    /// own; up to 16, see `world_gpu.rs`); over several steps, the most.
    pub submission_steps: usize,
}

/// What pass 2 gives back for one world.
pub(super) struct Stepped {
    /// Its islands (worlds solved in pass 2 only).
    pub islands: Vec<IslandReport>,
    /// Its frictional islands (worlds with friction solved in pass 2 only).
    pub friction: Vec<FrictionIslandReport>,
    /// Its scene's results.
    pub solved: SceneResults,
    /// The world's figures.
    pub world: WorldStepReport,
    /// Thread seconds: islands and assembly, solves, repairs and impulses,
    /// integration.
    pub times: [f64; 4],
    /// Repaired islands.
    pub repairs: Repairs,
}

/// Where a world's scene results are.
pub(super) enum SceneResults {
    /// Solved in pass 2: its scene report (island ranges set by the step's
    /// report).
    Own(SceneReport),
    /// In the batch solved in one call (scene k of its report is
    /// world k); the bodies' velocities when a repair changed them.
    InBatch(Option<Vec<BodyVelocity>>),
}

impl ResidentStep {
    /// Adds another step's counts and bytes read back (`bytes_up`: the
    /// latest step's).
    pub fn add(&mut self, o: &ResidentStep) {
        self.on_device += o.on_device;
        self.on_cpu += o.on_cpu;
        self.contacts_full += o.contacts_full;
        self.island_too_large += o.island_too_large;
        self.not_solved += o.not_solved;
        self.non_finite += o.non_finite;
        self.budget += o.budget;
        self.bytes_up = o.bytes_up;
        self.bytes_back += o.bytes_back;
        self.submission_steps = self.submission_steps.max(o.submission_steps);
    }
}

/// One world in pass 2.
pub(super) struct WorldStep<'a> {
    pub world: &'a mut World,
    pub prepared: Prepared,
    /// Its memory of the last steps (worlds solved in pass 2).
    pub warm: &'a mut Warm,
}

impl Solver {
    /// Advances every world by one step of `dt` seconds; see the module
    /// docs. Every world is checked first (an error names the world, the
    /// body and the field) and none moves then; `dt` must be finite and > 0.
    /// The same world gives the same trajectory alone or in a batch (bit for
    /// bit on the CPU: each island is solved on its own, warm start is per
    /// world, contact ids carry the world's index).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the first bad world, its body and the
    /// field, or `dt`; no world moves then.
    pub fn step_worlds(&mut self, worlds: &mut [World], dt: f64) -> Result<StepReport, Error> {
        // The resident GPU path where the batch is routed there
        // (`world_gpu.rs`), the worlds checked first.
        let mut stepped = None;
        self.step_worlds_call(worlds, dt, 1, &mut |_, r| stepped = Some(r), None)?;
        Ok(stepped.expect("one step is reported"))
    }

    /// One step of `worlds` on the host: each world on the CPU's per-world
    /// path, or with a GPU open (not `Backend::Auto`, which keeps worlds
    /// off the resident path on the CPU's per-world path) its islands in
    /// one batch through `solve_built_scenes`; see the module docs.
    fn step_worlds_host(&mut self, worlds: &mut [World], dt: f64) -> Result<StepReport, Error> {
        // Checked and collided in one pass over the cores (nothing is
        // changed before every world has passed); the first bad world (in
        // order) is checked again by name for the error (the name is
        // formatted only then).
        let start = Instant::now();
        let shared: &[World] = worlds;
        let prepared = parallel_map(shared.len(), self.threads, |i| {
            let ok = shared[i].validate("world").is_ok();
            ok.then(|| prepare(&shared[i], i, dt))
        });
        if let Some(i) = prepared.iter().position(Option::is_none) {
            return Err(named_error(worlds, i));
        }
        let mut prepared: Vec<Prepared> = prepared.into_iter().flatten().collect();
        let kicks: Vec<Vec<f64>> = (prepared.iter_mut())
            .map(|p| std::mem::take(&mut p.impacts.impulses))
            .collect();
        let collision = start.elapsed().as_secs_f64();
        // The batch: every world while a GPU is open (not with Auto), solved by
        // `solve_built_scenes` in one call; on the CPU every world is solved in pass 2.
        let start = Instant::now();
        let mut scenes: Vec<Scene> = Vec::new();
        let in_batch = self.gpu.is_some() && self.settings.backend != Backend::Auto;
        if in_batch {
            scenes = prepared
                .iter_mut()
                .map(|p| std::mem::take(&mut p.scene))
                .collect();
        }
        let batch = match scenes.is_empty() {
            true => None,
            false => Some(self.solve_built_scenes(&scenes)?),
        };
        let batch_seconds = start.elapsed().as_secs_f64();
        let start = Instant::now();
        let mut memory = std::mem::take(&mut self.world_warm);
        let keep = self.settings.warm_start_calls;
        memory.resize_with(worlds.len(), || Warm::new(keep, 1));
        let mut items: Vec<WorldStep> = worlds
            .iter_mut()
            .zip(prepared)
            .zip(memory.iter_mut())
            .map(|((world, prepared), warm)| WorldStep {
                world,
                prepared,
                warm,
            })
            .collect();
        let fix = repair_settings(&self.settings);
        let settings = &self.settings;
        let stepped = parallel_map_mut(&mut items, self.threads, |k, item| match &batch {
            None if item.prepared.scene.has_friction() => {
                step_frictional_world_on_cpu(settings, k, item, dt, &fix)
            }
            None => step_world_on_cpu(settings, k, item, dt, &fix),
            Some(report) => finish_batch_world(item, (&scenes[k], k, report), dt, &fix),
        });
        drop(items);
        self.world_warm = memory;
        let pass = start.elapsed().as_secs_f64();
        let solve = batch.unwrap_or_else(|| self.empty_report(cpu_device(self.threads)));
        // Where pass 2's frictional islands go, in the solver's words.
        let method = self.settings.friction_method;
        let (_, went) = friction_on_gpu(in_batch, self.cost.is_some(), method);
        let mut report = step_report(stepped, solve, &went, collision, batch_seconds, pass);
        // The impacts' impulses join their contacts' (none in most worlds).
        for (scene, kick) in report.solve.scenes.iter_mut().zip(&kicks) {
            scene
                .impulses
                .iter_mut()
                .zip(kick)
                .for_each(|(z, k)| *z += k);
        }
        Ok(report)
    }
}

impl Solver {
    /// Advances every world by `steps` steps of `dt` seconds, as `steps`
    /// calls of [`Self::step_worlds`] do (the same trajectory, bit for bit,
    /// and the same per-world figures), giving each step's report to `observe` with
    /// its number (from 0) as the step ends; the worlds hold the states
    /// after the last step when it returns.
    ///
    /// On the resident GPU path (`Backend::Gpu`, see `world_gpu.rs`) the
    /// states stay on the device for the whole call: per step only a small
    /// fixed record per world comes back (energies, deepest penetration,
    /// contacts, islands, largest error, awake bodies, flags; 80 bytes in
    /// f64, [`ResidentStep::bytes_back`]) and the states once, at the end;
    /// steps go up to 16 to a submission, with no host sync in between.
    /// To see the states after some step, end a call there: the batch stays
    /// on the device between calls while the worlds are those it gave back.
    /// Elsewhere (CPU, other GPU paths) the call is a loop of `step_worlds`.
    ///
    /// Device trouble in the middle drops the GPU (a warning) and the CPU
    /// path goes on from the last good state, the worlds as passed in (the
    /// states last read back): the steps already reported are taken again
    /// on the CPU without being reported again, then the rest.
    ///
    /// # Errors
    /// As [`Self::step_worlds`]: [`Error::Invalid`] naming the first bad
    /// world, its body and the field, or `dt`, and no world moves. With
    /// `steps` 0 nothing happens (the worlds are not checked).
    ///
    /// # Example
    /// ```
    /// use lcpbatch::world::generate::{standard_world, WorldKind};
    /// use lcpbatch::{Settings, Solver};
    /// let mut worlds = vec![standard_world(WorldKind::Stack, 2, 1)];
    /// let mut solver = Solver::new(Settings::default()).unwrap();
    /// let mut energy = Vec::new();
    /// solver
    ///     .step_worlds_for(&mut worlds, 0.01, 50, |_, r| {
    ///         energy.push(r.worlds[0].kinetic + r.worlds[0].potential)
    ///     })
    ///     .unwrap();
    /// assert_eq!(energy.len(), 50);
    /// ```
    ///
    /// See also [`Self::step_worlds`] (one step, the worlds handed back).
    pub fn step_worlds_for(
        &mut self,
        worlds: &mut [World],
        dt: f64,
        steps: usize,
        mut observe: impl FnMut(usize, StepReport),
    ) -> Result<(), Error> {
        self.step_worlds_call(worlds, dt, steps, &mut observe, None)
    }

    /// [`Self::step_worlds_for`], handing `show` the states of the worlds
    /// `frames.worlds` (in that order) after each step `s` (counted from 1)
    /// where `frames.at(s)`, after that step's report. On the resident GPU
    /// path only those worlds' states come back for a frame (a ranged
    /// read; submissions end there), every state once, with the last step;
    /// elsewhere they are copies of the worlds as they step. After device
    /// trouble the frames not yet handed over come from the CPU path.
    ///
    /// # Errors
    /// Those of [`Self::step_worlds_for`], and [`Error::Invalid`] where an
    /// index of `frames.worlds` is out of the batch (nothing is stepped).
    ///
    /// # Example
    /// ```
    /// use lcpbatch::world::generate::{standard_world, WorldKind};
    /// use lcpbatch::{Frames, Settings, Solver};
    /// let mut worlds: Vec<_> = (0..4).map(|k| standard_world(WorldKind::Spheres, 2, k)).collect();
    /// let mut solver = Solver::new(Settings::default()).unwrap();
    /// let frames = Frames { worlds: &[0, 3], at: &|s| s % 10 == 0 };
    /// let mut shown = Vec::new();
    /// solver
    ///     .step_worlds_framed(&mut worlds, 0.01, 30, frames, |_, _| {}, |s, w| shown.push((s, w.len())))
    ///     .unwrap();
    /// assert_eq!(shown, [(10, 2), (20, 2), (30, 2)]);
    /// ```
    pub fn step_worlds_framed(
        &mut self,
        worlds: &mut [World],
        dt: f64,
        steps: usize,
        frames: Frames,
        mut observe: impl FnMut(usize, StepReport),
        mut show: impl FnMut(usize, &[World]),
    ) -> Result<(), Error> {
        if let Some(&k) = frames.worlds.iter().find(|&&k| k >= worlds.len()) {
            let why = format!("world {k} of a batch of {}", worlds.len());
            return Err(Error::invalid("frames", "worlds", why));
        }
        let mut framing = Framing {
            frames,
            show: &mut show,
            shown: 0,
        };
        self.step_worlds_call(worlds, dt, steps, &mut observe, Some(&mut framing))
    }

    /// A call of `steps` steps (see [`Self::step_worlds_for`]): routed once
    /// ([`Self::world_route`]), the resident path where it goes there, the
    /// CPU path for the steps it did not take; the frames `framing` asks
    /// for handed over.
    fn step_worlds_call(
        &mut self,
        worlds: &mut [World],
        dt: f64,
        steps: usize,
        observe: &mut dyn FnMut(usize, StepReport),
        mut framing: Option<&mut Framing>,
    ) -> Result<(), Error> {
        let gpu = self.gpu.is_some() && steps > 0;
        check_step(worlds, dt, gpu)?;
        let (resident, why) = match gpu {
            true => {
                let frames: Vec<usize> = match framing.as_deref() {
                    Some(f) => (1..steps).filter(|&s| (f.frames.at)(s)).collect(),
                    None => Vec::new(),
                };
                self.world_route(worlds, steps, &frames)
            }
            false => (false, None),
        };
        let mut tell = |step, mut r: StepReport| {
            tell_route(&mut r, resident, why.as_deref());
            observe(step, r)
        };
        let (mut reported, mut at) = (0, 0);
        if resident {
            let f = framing.as_deref_mut();
            (reported, at) = self.step_worlds_resident(worlds, dt, steps, &mut tell, f);
        } else {
            self.resident = None;
        }
        for step in at..steps {
            let r = self.step_worlds_host(worlds, dt)?;
            if step >= reported {
                tell(step, r);
            }
            if let Some(f) = framing.as_deref_mut() {
                f.take(step + 1, worlds);
            }
        }
        if let Some(f) = framing {
            f.take(steps, worlds);
        }
        Ok(())
    }
}

/// Which worlds' states [`Solver::step_worlds_framed`] hands over, and
/// after which steps.
#[derive(Clone, Copy)]
pub struct Frames<'a> {
    /// The worlds (indices into the batch) whose states are handed over.
    pub worlds: &'a [usize],
    /// Whether they are wanted after step `s` (counted from 1, up to the
    /// call's steps).
    pub at: &'a dyn Fn(usize) -> bool,
}

/// A call's frames: what it asks for, the hand-over, the last step handed
/// over (frames are handed over once, in order, also when the CPU path
/// takes a call again after device trouble).
pub(super) struct Framing<'a> {
    pub frames: Frames<'a>,
    show: &'a mut dyn FnMut(usize, &[World]),
    shown: usize,
}

impl Framing<'_> {
    /// The first step after `done` and before `steps` whose frame is
    /// wanted and not yet handed over.
    pub fn next(&self, done: usize, steps: usize) -> Option<usize> {
        (done.max(self.shown) + 1..steps).find(|&s| (self.frames.at)(s))
    }

    /// Hands over the frame of step `s` (`states`: the frame's worlds).
    pub fn give(&mut self, s: usize, states: &[World]) {
        (self.show)(s, states);
        self.shown = s;
    }

    /// After step `s` of the whole batch `worlds`: the frame where wanted
    /// and not yet handed over.
    fn take(&mut self, s: usize, worlds: &[World]) {
        if s > self.shown && (self.frames.at)(s) {
            let states: Vec<World> = self
                .frames
                .worlds
                .iter()
                .map(|&k| worlds[k].clone())
                .collect();
            self.give(s, &states);
        }
    }
}

/// A step's report on the route chosen (`resident` or the CPU): `why`
/// (`Backend::Auto`'s reasons and estimates) as its choice, where it took
/// that route (after device trouble the report keeps the solver's).
fn tell_route(report: &mut StepReport, resident: bool, why: Option<&str>) {
    if let (Some(why), true) = (why, report.resident.is_some() == resident) {
        report.solve.choice = why.to_string();
    }
}

/// The checks before any step: `dt` finite and > 0, and with `worlds_too`
/// every world (the first bad one named; the CPU path checks them in its
/// collision pass instead).
fn check_step(worlds: &[World], dt: f64, worlds_too: bool) -> Result<(), Error> {
    if !dt.is_finite() || dt <= 0.0 {
        return Err(Error::invalid(
            "step",
            "dt",
            format!("{dt} is not a positive number"),
        ));
    }
    match worlds_too {
        true => match worlds.iter().position(|w| w.validate("world").is_err()) {
            Some(i) => Err(named_error(worlds, i)),
            None => Ok(()),
        },
        false => Ok(()),
    }
}

/// The error of world `i`, which failed its check: checked again by name.
fn named_error(worlds: &[World], i: usize) -> Error {
    let item = format!("world {i}");
    match worlds[i].validate(&item) {
        Err(e) => e,
        Ok(()) => Error::invalid(&item, "world", "failed its check".to_string()),
    }
}

/// The step's report: `solve`, the batch's report (or an empty one on the
/// CPU device), with every world solved in pass 2 pushed in world order,
/// the repairs' velocities in place; pass 2's seconds added per phase;
/// `friction_went`: where pass 2's frictional islands went, in words.
fn step_report(
    stepped: Vec<Stepped>,
    mut solve: Report,
    friction_went: &str,
    collision: f64,
    batch_seconds: f64,
    pass: f64,
) -> StepReport {
    let mut sums = [0.0; 4];
    let mut repairs = Repairs::default();
    for s in &stepped {
        for (t, x) in sums.iter_mut().zip(s.times) {
            *t += x;
        }
        repairs.merge(s.repairs);
    }
    // Wall seconds of pass 2 shared out by the threads' measured times.
    let all: f64 = sums.iter().sum();
    let share = |x: f64| if all > 0.0 { pass * x / all } else { 0.0 };
    if stepped.iter().any(|s| !s.friction.is_empty()) {
        solve.choice = format!("{}; friction: {friction_went}", solve.choice);
    }
    let mut worlds = Vec::with_capacity(stepped.len());
    for (k, s) in stepped.into_iter().enumerate() {
        worlds.push(s.world);
        match s.solved {
            SceneResults::Own(scene) => solve.push_scene(scene, s.islands, s.friction),
            SceneResults::InBatch(Some(bodies)) => solve.scenes[k].bodies = bodies,
            SceneResults::InBatch(None) => {}
        }
    }
    solve.timings += Timings {
        build: share(sums[0]),
        solve: share(sums[1]),
        impulses: share(sums[2]),
        ..Timings::default()
    };
    solve.timings.total = batch_seconds + share(sums[0] + sums[1] + sums[2]);
    StepReport {
        unsolved: worlds.iter().map(|w| w.unsolved).sum(),
        worlds,
        timings: StepTimings {
            collision,
            solve: solve.timings.total,
            integrate: share(sums[3]),
        },
        solve,
        repairs,
        resident: None,
    }
}

/// Largest error of the solved islands among `lcp` and `friction` (0 when
/// none).
pub(super) fn max_error<'a>(
    lcp: impl Iterator<Item = &'a IslandReport>,
    friction: impl Iterator<Item = &'a FrictionIslandReport>,
) -> f64 {
    lcp.filter(|i| i.status().is_solution())
        .map(|i| i.error())
        .chain(
            friction
                .filter(|i| i.status().is_solution())
                .map(|i| i.error()),
        )
        .fold(0.0, f64::max)
}
