//! The solver: [`Solver::new`] once, then [`Solver::solve_lcps`] or
//! [`Solver::solve_scenes`] as often as needed, each returning a [`Report`].
//!
//! The solver owns the device, its pipelines and buffers (opened once, in
//! `new`), and the warm-start memory. Where it solves:
//! - [`Backend::Cpu`]: the f64 path over every core;
//! - [`Backend::Gpu`]: the GPU (software adapters too), every answer checked
//!   on the CPU in f64;
//! - [`Backend::Auto`]: where there is a hardware adapter or one was named
//!   in [`crate::GpuSettings::adapter`], each batch where a [`CostModel`] of
//!   this machine (measured once, cached) estimates it faster; else the CPU
//!   (an unnamed software adapter is not even opened: it is slower than the
//!   CPU path on every batch measured, BENCHMARKS.md, and calibrating it
//!   would compile its kernels for tens of seconds). [`Report::choice`]
//!   says why, with both estimates.
//!
//! # Device trouble
//! No adapter, a named adapter that does not exist, f64 asked of an adapter
//! without SHADER_F64, or a GPU error in the middle of a batch (lost device,
//! validation error, out of memory, a panic inside wgpu): the solver warns
//! once on stderr (`warning: GPU: …; solving on the CPU (f64, exact)`;
//! unless [`Settings::warn_on_stderr`] is off),
//! records the reason in [`Report::fallback`], drops the device and solves
//! this batch and every later one on the CPU, with the CPU's results. LCPs
//! beyond the CPU enumeration's n ≤ 20 then go to Lemke, as on the GPU path.
//! Errors that are the caller's (an invalid scene or LCP, settings out of
//! range) stay errors.

use std::sync::Arc;
use std::time::Instant;

mod cost;
mod cpu_path;
mod dense;
mod device;
pub(crate) use cpu_path::{check_solution, lemke_else_enumerate, textbook_checked};
mod friction_path;
mod gpu_path;
mod view;
mod world_cpu;
mod world_friction;
pub(crate) mod world_gpu;
pub mod world_path;
mod world_repair;

pub use world_repair::Repairs;

pub use cost::{cache_dir, CostModel, WorldCosts, CALIBRATION_SIZES};

use crate::build::Built;
use crate::cpu::batch::parallel_map;
use crate::friction::FrictionProblem;
use crate::gpu::GpuContext;
use crate::lcp::Lcp;
use crate::report::{Device, IslandReport, Report};
use crate::scene::Scene;
use crate::settings::{Backend, Settings};
use crate::warm::{basis_entries, Warm, SHARDS};
use crate::Error;
use device::cpu_device;
use view::SolverView;

/// A contact solver built once from [`Settings`]; see the module docs.
///
/// ```
/// use lcpbatch::{Backend, Lcp, Settings, Solver, Status};
///
/// // Two coupled contacts, both active: M = [[2, 1], [1, 2]], q = (−5, −6).
/// let lcp = Lcp::new(vec![2.0, 1.0, 1.0, 2.0], vec![-5.0, -6.0])?;
/// let mut solver = Solver::new(Settings { backend: Backend::Cpu, ..Settings::default() })?;
/// let report = solver.solve_lcps(&[lcp])?;
/// let island = &report.islands[0];
/// assert_eq!(island.status(), Status::Solved);
/// assert!((island.solution.z[0] - 4.0 / 3.0).abs() < 1e-12 && island.error() < 1e-15);
/// println!("{report}"); // device, islands per path, statuses, max error, time per phase
/// # Ok::<(), lcpbatch::Error>(())
/// ```
#[derive(Debug)]
pub struct Solver {
    settings: Settings,
    /// The device while the GPU is in use (None on the CPU path).
    gpu: Option<Arc<GpuContext>>,
    /// Why this device, in words (for the report).
    choice: String,
    /// Why the CPU took over, once it has.
    fallback: Option<String>,
    /// Bases and frictional reactions of the last calls by contact id
    /// (with `settings.warm_start`; kept `settings.warm_start_calls` calls).
    warm: Warm,
    threads: usize,
    /// Per world of the last `step_worlds` batch (by position): its
    /// contacts' bases and reactions of the last steps, on the CPU (with
    /// `settings.warm_start`).
    world_warm: Vec<Warm>,
    /// `Backend::Auto` with a GPU open: the costs that choose per batch.
    cost: Option<CostModel>,
    /// The worlds held on the device by `step_worlds`' resident path.
    resident: Option<world_gpu::Resident>,
}

impl Solver {
    /// Checks the settings and opens the device they ask for. Device trouble
    /// is not an error (see the module docs); a setting out of range is.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the setting out of range.
    pub fn new(settings: Settings) -> Result<Self, Error> {
        settings.validate()?;
        let threads = match settings.threads {
            0 => std::thread::available_parallelism().map_or(1, |n| n.get()),
            t => t,
        };
        let mut solver = Solver {
            warm: Warm::new(settings.warm_start_calls, SHARDS),
            settings,
            gpu: None,
            choice: String::new(),
            fallback: None,
            threads,
            world_warm: Vec::new(),
            cost: None,
            resident: None,
        };
        solver.choose_device()?;
        if solver.settings.backend == Backend::Auto && solver.gpu.is_some() {
            solver.load_cost_model();
        }
        Ok(solver)
    }

    /// A GPU solver on a device the caller opened (tests pass their own
    /// adapter through this seam). `settings.backend` is taken as Gpu.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the setting out of range.
    pub fn with_device(mut settings: Settings, device: GpuContext) -> Result<Self, Error> {
        settings.backend = Backend::Gpu;
        settings.validate()?;
        let mut solver = Solver::new(Settings {
            backend: Backend::Cpu,
            ..settings.clone()
        })?;
        solver.settings = settings;
        solver.choice = "the device given to Solver::with_device".into();
        solver.gpu = Some(Arc::new(device));
        Ok(solver)
    }

    fn choose_device(&mut self) -> Result<(), Error> {
        let gpu_wanted;
        (gpu_wanted, self.choice) = device::choose(&self.settings);
        if gpu_wanted {
            match GpuContext::new(&self.settings.gpu.options()) {
                Ok(ctx) => self.gpu = Some(Arc::new(ctx)),
                Err(Error::Gpu(why)) => self.fall_back(why),
                Err(e) => return Err(e),
            }
        }
        Ok(())
    }

    /// `Backend::Auto` with a GPU open: the model given in the settings,
    /// else the cached one, else a calibration (cached). Device trouble
    /// during the calibration falls back to the CPU.
    fn load_cost_model(&mut self) {
        let device = cost::cost_key(self.gpu.as_deref());
        let dir = cost::cache_dir();
        let model = self.settings.cost_model.clone().or_else(|| {
            dir.as_deref()
                .and_then(|d| cost::cached(d, &device, self.threads))
        });
        self.cost = match model {
            Some(m) => Some(m),
            // The world figures wait for the first batch of worlds.
            None => match self.calibrate_for(false) {
                Ok(m) => {
                    // A cache that cannot be written is skipped: the next
                    // process measures again.
                    if let Some(d) = &dir {
                        let _ = cost::store(d, &m);
                    }
                    Some(m)
                }
                Err(e) => {
                    self.fall_back(format!("calibrating the cost model: {e}"));
                    None
                }
            },
        };
    }

    /// The cost model `Backend::Auto` chooses by (None: no GPU open, or
    /// another backend).
    pub fn cost_model(&self) -> Option<&CostModel> {
        self.cost.as_ref()
    }

    /// Measures this solver's CPU and GPU paths by island size, and where
    /// the adapter has f64 the world figures (see [`CostModel`]); needs a
    /// GPU open.
    ///
    /// # Errors
    /// [`Error::Gpu`] without a GPU open or on device trouble.
    pub fn calibrate(&mut self) -> Result<CostModel, Error> {
        self.calibrate_for(true)
    }

    /// The settings it was built with.
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// The device that solves batches on the GPU while one is open (with
    /// `Backend::Auto`'s cost model, the batches it estimates faster there),
    /// else the CPU.
    pub fn device(&self) -> Device {
        match self.gpu.as_deref() {
            Some(ctx) => Device::of(ctx),
            None => cpu_device(self.threads),
        }
    }

    /// What the phases read of this solver (see [`SolverView`]).
    fn view(&self) -> SolverView<'_> {
        SolverView {
            settings: &self.settings,
            threads: self.threads,
            warm: &self.warm,
            choice: &self.choice,
            fallback: self.fallback.as_deref(),
        }
    }

    /// A report of no islands on `device`, with this solver's choice and
    /// fallback reason.
    fn empty_report(&self, device: Device) -> Report {
        self.view().report(Vec::new(), Vec::new(), device)
    }

    /// Why this device: the backend asked for and what was found.
    pub fn choice(&self) -> &str {
        &self.choice
    }

    /// Why the CPU took over from the GPU (None: no device trouble so far).
    pub fn fallback(&self) -> Option<&str> {
        self.fallback.as_deref()
    }

    /// Forgets the bases remembered for warm start.
    pub fn clear_warm_start(&mut self) {
        self.warm = Warm::new(self.settings.warm_start_calls, SHARDS);
        self.world_warm.clear();
    }

    /// `true`: the calls that follow count as one call of the warm-start
    /// memory until `join_warm_start_calls(false)`, so that
    /// `settings.warm_start_calls` counts the caller's batches, not the
    /// parts it splits them into (the Python package's chunks). Every part
    /// finds the ids of the calls before the join (and those of the parts
    /// before it); the ids past `warm_start_calls` calls go when it ends.
    #[doc(hidden)]
    pub fn join_warm_start_calls(&mut self, join: bool) {
        self.warm.join_calls(join);
    }

    /// The device, shared, while the GPU is in use (for tests that lose it
    /// from another thread in the middle of a batch).
    #[doc(hidden)]
    pub fn shared_device(&self) -> Option<Arc<GpuContext>> {
        self.gpu.clone()
    }

    /// Device trouble: drop the device, remember why, warn once.
    fn fall_back(&mut self, why: String) {
        self.gpu = None;
        if self.fallback.is_none() {
            if self.settings.warn_on_stderr {
                eprintln!("warning: GPU: {why}; solving on the CPU (f64, exact)");
            }
            self.fallback = Some(why);
        }
    }

    /// What a GPU phase gave (None: it did not run): its answer, or None
    /// after device trouble ([`Error::Gpu`]: the device is dropped, see
    /// [`Self::fall_back`], and the CPU takes the batch). The caller's
    /// errors stay errors.
    fn gpu_outcome<T>(&mut self, on_gpu: Option<Result<T, Error>>) -> Result<Option<T>, Error> {
        match on_gpu {
            Some(Ok(r)) => Ok(Some(r)),
            Some(Err(Error::Gpu(why))) => {
                self.fall_back(why);
                Ok(None)
            }
            Some(Err(e)) => Err(e),
            None => Ok(None),
        }
    }

    /// Solves a batch of LCPs, in the caller's order. Every problem is
    /// checked first (an error names the first bad one). Enumeration on the
    /// CPU backend refuses n > 20 (an error naming the problem); after device
    /// trouble or on the GPU such problems go to Lemke.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the first bad problem and its field;
    /// [`Error::Unsupported`] for enumeration of n > 20 on the CPU backend.
    /// Device trouble is not an error (the CPU takes the batch).
    pub fn solve_lcps(&mut self, lcps: &[Lcp]) -> Result<Report, Error> {
        self.solve_lcps_warm(dense::Problems::Built(lcps), None)
    }

    /// [`Solver::solve_lcps`] with the caller's contact ids, one per row of
    /// each problem (`ids[i].len() == lcps[i].n()`), stable across calls: with
    /// `settings.warm_start` each problem starts from the basis its contacts
    /// had in the last call.
    ///
    /// # Errors
    /// Those of [`Solver::solve_lcps`], and [`Error::Invalid`] where `ids`
    /// has not one entry per problem or per row.
    pub fn solve_lcps_keyed(&mut self, lcps: &[Lcp], ids: &[Vec<u64>]) -> Result<Report, Error> {
        check_ids(ids, lcps.iter().map(Lcp::n), |n| format!("n = {n}"))?;
        let keys: Vec<&[u64]> = ids.iter().map(Vec::as_slice).collect();
        self.solve_lcps_warm(dense::Problems::Built(lcps), Some(&keys))
    }

    /// Solves a batch of frictional problems, in the caller's order, on the
    /// CPU in f64 over every core with `settings.friction_method`; the
    /// results are in [`Report::friction`]. Every problem is checked first
    /// (an error names the first bad one and its field).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the first bad problem and its field.
    pub fn solve_friction(&mut self, problems: &[FrictionProblem]) -> Result<Report, Error> {
        self.solve_friction_warm(problems, None)
    }

    /// [`Solver::solve_friction`] with the caller's contact ids, one per
    /// contact of each problem (`ids[i].len() == problems[i].contacts()`),
    /// stable across calls: with `settings.warm_start` each contact starts
    /// from its reaction of the last call.
    ///
    /// # Errors
    /// Those of [`Solver::solve_friction`], and [`Error::Invalid`] where
    /// `ids` has not one entry per problem or per contact.
    pub fn solve_friction_keyed(
        &mut self,
        problems: &[FrictionProblem],
        ids: &[Vec<u64>],
    ) -> Result<Report, Error> {
        let contacts = problems.iter().map(FrictionProblem::contacts);
        check_ids(ids, contacts, |k| format!("{k} contacts"))?;
        let keys: Vec<Vec<Option<u64>>> = ids
            .iter()
            .map(|k| k.iter().copied().map(Some).collect())
            .collect();
        self.solve_friction_warm(problems, Some(&keys))
    }

    fn solve_lcps_warm(
        &mut self,
        lcps: dense::Problems,
        keys: Option<&[&[u64]]>,
    ) -> Result<Report, Error> {
        let start = Instant::now();
        let (use_gpu, why) = device::gpu_for(
            self.gpu.is_some(),
            self.cost.as_ref(),
            &self.choice,
            lcps.sizes(),
        );
        let on_gpu = self.gpu.clone().filter(|_| use_gpu).map(|ctx| {
            let built = lcps.built();
            if self.settings.all_solutions {
                gpu_path::all_solutions_lcps_on_gpu(&self.view(), &ctx, &built)
            } else {
                let keys = keys.filter(|_| self.settings.warm_start);
                gpu_path::lcps_on_gpu(&self.view(), &ctx, &built, keys)
            }
        });
        // Both paths check each problem and look up its warm basis on the
        // threads that solve it.
        let mut report = match self.gpu_outcome(on_gpu)? {
            Some(r) => r,
            None => cpu_path::problems_on_cpu(&self.view(), lcps, keys)?,
        };
        if self.cost.is_some() {
            report.choice = why;
        }
        if let Some(keys) = keys {
            self.remember(report.islands.iter().zip(keys).map(|(isl, k)| (*k, isl)));
        }
        report.timings.total = start.elapsed().as_secs_f64();
        Ok(report)
    }

    /// Solves scenes: per scene the impulse of every contact, the bodies'
    /// velocities after them, and one [`IslandReport`] per island. Every
    /// scene is checked first (an error names the scene, the item and the
    /// field). Islands above the enumeration's limit go to Lemke. Scenes
    /// with friction (any contact with μ > 0) go, every island of them, to
    /// the friction path ([`Report::friction`],
    /// [`SceneReport::friction`](crate::report::SceneReport::friction); on the GPU
    /// for a projected `friction_method` with `Backend::Gpu`, else on the
    /// CPU; `Report::choice` says which); the others are solved as without
    /// friction.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the first bad scene, its contact or body
    /// and the field. Device trouble is not an error (the CPU takes the
    /// batch).
    pub fn solve_scenes(&mut self, scenes: &[Scene]) -> Result<Report, Error> {
        let start = Instant::now();
        for (i, s) in scenes.iter().enumerate() {
            s.validate(format_args!("scene {i}"))?;
        }
        let mut report = self.solve_built_scenes(scenes)?;
        report.timings.total = start.elapsed().as_secs_f64();
        Ok(report)
    }

    /// [`Solver::solve_scenes`] without the scene checks, for scenes built
    /// by the library itself from checked input (the world step builds them
    /// from worlds checked at the start of the step: indices in range, unit
    /// normals, finite numbers, masses and inertias ≥ 0, by construction).
    /// Never for a caller's scenes: unchecked input could panic in assembly.
    pub(crate) fn solve_built_scenes(&mut self, scenes: &[Scene]) -> Result<Report, Error> {
        let start = Instant::now();
        if scenes.iter().any(Scene::has_friction) {
            let mut report = self.scenes_with_friction(scenes)?;
            report.timings.total = start.elapsed().as_secs_f64();
            return Ok(report);
        }
        let refs: Vec<&Scene> = scenes.iter().collect();
        let mut report = self.frictionless_scenes(&refs)?;
        report.timings.total = start.elapsed().as_secs_f64();
        Ok(report)
    }

    /// Checked scenes without friction: the LCP path. Each scene is built
    /// once ([`Built`]); the warm bases, the cost model's sizes and the
    /// solve (GPU, or CPU) take what was built.
    fn frictionless_scenes(&mut self, scenes: &[&Scene]) -> Result<Report, Error> {
        let t = Instant::now();
        let built = Built::all(scenes, self.threads);
        let build = t.elapsed().as_secs_f64();
        // Per scene, per island: the warm basis of its contacts' ids (on
        // every thread: the ids are gathered per island).
        let view = self.view();
        let warm: Vec<Vec<Option<u32>>> = if self.settings.warm_start {
            parallel_map(scenes.len(), self.threads, |s| {
                built[s]
                    .islands
                    .iter()
                    .map(|isl| view.warm_basis(&contact_ids(scenes[s], &isl.contacts)))
                    .collect()
            })
        } else {
            Vec::new()
        };
        let sizes = built
            .iter()
            .flat_map(|b| b.islands.iter().map(|i| i.contacts.len()));
        let (use_gpu, why) =
            device::gpu_for(self.gpu.is_some(), self.cost.as_ref(), &self.choice, sizes);
        let on_gpu = self.gpu.clone().filter(|_| use_gpu).map(|ctx| {
            if self.settings.all_solutions {
                gpu_path::all_solutions_scenes_on_gpu(&self.view(), &ctx, scenes, &built)
            } else {
                gpu_path::scenes_on_gpu(&self.view(), &ctx, scenes, &built, &warm)
            }
        });
        let mut report = match self.gpu_outcome(on_gpu)? {
            Some(r) => r,
            None => cpu_path::scenes_on_cpu(&self.view(), scenes, &built, &warm)?,
        };
        report.timings.build = build;
        if self.cost.is_some() {
            report.choice = why;
        }
        if self.settings.warm_start {
            let islands = &report.islands;
            let ids: Vec<Vec<u64>> = parallel_map(islands.len(), self.threads, |i| {
                contact_ids(scenes[islands[i].scene.unwrap_or(0)], &islands[i].contacts)
            });
            let keyed: Vec<(&[u64], &IslandReport)> =
                ids.iter().map(Vec::as_slice).zip(&report.islands).collect();
            self.remember(keyed.into_iter());
        }
        Ok(report)
    }

    /// Checked scenes, some with friction: those without go through the LCP
    /// path (GPU or CPU), those with friction through the friction path; the
    /// two reports merged in the scenes' order.
    fn scenes_with_friction(&mut self, scenes: &[Scene]) -> Result<Report, Error> {
        let with: Vec<bool> = scenes.iter().map(Scene::has_friction).collect();
        let pick =
            |f: bool| -> Vec<&Scene> { scenes.iter().filter(|s| s.has_friction() == f).collect() };
        let plain = pick(false);
        let mut report = match plain.is_empty() {
            true => self.empty_report(self.device()),
            false => self.frictionless_scenes(&plain)?,
        };
        let device = report.device.clone();
        let mut friction = Report::new(Vec::new(), Vec::new(), device, report.choice.clone());
        self.friction_scenes(&pick(true), &mut friction)?;
        report.merge_scenes(friction, &with);
        Ok(report)
    }

    /// The friction path for checked scenes with friction, in phases (added
    /// to `report.timings`): build (islands and the f64 assembly on the
    /// CPU, the oracle), solve (on the GPU where
    /// [`friction_path::friction_on_gpu`] says so, see
    /// [`friction_path::islands_on_gpu`]; else every island over the
    /// cores), impulses; the reactions remembered. `report` (empty) gets
    /// the scenes and their frictional islands (scene indices into
    /// `scenes`); its choice gains where the friction went, its counts and
    /// GPU figures what the GPU did.
    fn friction_scenes(&mut self, scenes: &[&Scene], report: &mut Report) -> Result<(), Error> {
        let t = Instant::now();
        let mut built = friction_path::build(scenes, self.threads);
        report.timings.build += t.elapsed().as_secs_f64();
        let t = Instant::now();
        let (problems, warm) = friction_path::island_starts(&self.view(), scenes, &mut built);
        let settings = self.settings.friction();
        let (use_gpu, mut went) = friction_path::friction_on_gpu(
            self.gpu.is_some(),
            self.cost.is_some(),
            settings.method,
        );
        let on_gpu = (self.gpu.clone())
            .filter(|_| use_gpu && !problems.is_empty())
            .map(|ctx| {
                friction_path::islands_on_gpu(
                    &ctx,
                    &self.settings,
                    scenes,
                    &built,
                    &problems,
                    &warm,
                )
            });
        let tried = on_gpu.is_some();
        let solved = match self.gpu_outcome(on_gpu)? {
            Some((solutions, figures, assembly)) => {
                let origin = friction_path::origin_counts(&figures);
                went = format!("{went}, {assembly}, {origin}");
                friction_path::add_gpu_figures(report, &figures);
                report.device = self.device();
                solutions
            }
            None => {
                if tried {
                    report.fallback = self.fallback.clone();
                    went = format!("{} on the CPU (the GPU failed)", settings.method.name());
                }
                friction_path::solve_on_cpu(&problems, &warm, &settings, self.threads)
            }
        };
        report.choice = format!("{}; friction: {went}", report.choice);
        report.timings.solve += t.elapsed().as_secs_f64();
        let t = Instant::now();
        let (scene_reports, islands) =
            friction_path::scene_reports(scenes, built, solved, &warm, self.threads);
        report.timings.impulses += t.elapsed().as_secs_f64();
        if self.settings.warm_start {
            friction_path::remember_islands(&mut self.warm, scenes, &islands);
        }
        report.scenes = scene_reports;
        report.set_friction(islands);
        Ok(())
    }

    /// A batch of frictional problems (keyed: `keys`, their contacts' ids)
    /// in phases: the checks, the starts, the solve (on the GPU where
    /// [`friction_path::friction_on_gpu`] says so, else over the cores),
    /// the reports; the reactions remembered.
    fn solve_friction_warm(
        &mut self,
        problems: &[FrictionProblem],
        keys: Option<&[Vec<Option<u64>>]>,
    ) -> Result<Report, Error> {
        let start = Instant::now();
        for (i, p) in problems.iter().enumerate() {
            if p.validate("problem").is_err() {
                p.validate(&format!("problem {i}"))?;
            }
        }
        let warm = friction_path::problem_starts(&self.view(), keys, problems.len());
        let s = self.settings.friction();
        // The projected methods run on the GPU where one is open (every
        // answer checked in f64 there); the exact Coulomb methods on the CPU.
        let (use_gpu, went) =
            friction_path::friction_on_gpu(self.gpu.is_some(), self.cost.is_some(), s.method);
        let on_gpu = (self.gpu.clone()).filter(|_| use_gpu).map(|ctx| {
            friction_path::problems_on_gpu(&ctx, problems, &warm, &s, &self.settings.gpu)
        });
        let (solved, figures) = match self.gpu_outcome(on_gpu)? {
            Some((solved, figures)) => (solved, Some(figures)),
            None => {
                let cpu = friction_path::solve_on_cpu(problems, &warm, &s, self.threads);
                (cpu, None)
            }
        };
        let islands = friction_path::problem_reports(problems, solved, &warm);
        if let (Some(keys), true) = (keys, self.settings.warm_start) {
            friction_path::remember_problems(&mut self.warm, keys, &islands);
        }
        let device = match figures {
            Some(_) => self.device(),
            None => cpu_device(self.threads),
        };
        let choice = match (&figures, self.fallback.is_some() && use_gpu) {
            (Some(f), _) => {
                let origin = friction_path::origin_counts(f);
                format!("{}; friction: {went}, {origin}", self.choice)
            }
            (None, true) => format!("{}; friction: on the CPU (the GPU failed)", self.choice),
            (None, false) => format!("{}; friction: {went}", self.choice),
        };
        let mut report = self.empty_report(device);
        report.choice = choice;
        report.timings.solve = start.elapsed().as_secs_f64();
        if let Some(f) = figures {
            friction_path::add_gpu_figures(&mut report, &f);
        }
        report.set_friction(islands);
        report.timings.total = start.elapsed().as_secs_f64();
        Ok(report)
    }

    /// Records each island's basis under its contact ids.
    fn remember<'a>(&mut self, islands: impl Iterator<Item = (&'a [u64], &'a IslandReport)>) {
        if !self.settings.warm_start {
            return;
        }
        let records: Vec<(&[u64], u32)> = islands
            .filter(|(ids, isl)| !ids.is_empty() && isl.solution.status.is_solution())
            .filter_map(|(ids, isl)| Some((ids, isl.solution.basis?)))
            .collect();
        let ids = records.iter().map(|(k, _)| k.len()).sum();
        self.warm
            .bases
            .record_all(&records, ids, self.threads, |&(k, basis)| {
                basis_entries(k.iter().map(|&id| Some(id)), basis)
            });
    }
}

/// The caller's contact ids of a keyed call: one list per problem, one id
/// per row or contact of it (`sizes`; `per` names a size in the error).
fn check_ids(
    ids: &[Vec<u64>],
    sizes: impl ExactSizeIterator<Item = usize>,
    per: impl Fn(usize) -> String,
) -> Result<(), Error> {
    if ids.len() != sizes.len() {
        return Err(Error::invalid(
            "ids",
            "len",
            format!("{} id lists for {} problems", ids.len(), sizes.len()),
        ));
    }
    for (i, (n, k)) in sizes.zip(ids).enumerate() {
        if k.len() != n {
            return Err(Error::invalid(
                format!("problem {i}"),
                "ids",
                format!("{} ids for {}", k.len(), per(n)),
            ));
        }
    }
    Ok(())
}

/// The caller's ids of an island's contacts; empty when one has none (such
/// an island is not warm-started).
fn contact_ids(scene: &Scene, contacts: &[usize]) -> Vec<u64> {
    ids_of(scene, contacts)
        .collect::<Option<Vec<u64>>>()
        .unwrap_or_default()
}

/// The ids of an island's contacts (None for a contact without one).
pub(super) fn ids_of<'a>(
    scene: &'a Scene,
    contacts: &'a [usize],
) -> impl Iterator<Item = Option<u64>> + 'a {
    contacts.iter().map(|&c| scene.contacts[c].id)
}
