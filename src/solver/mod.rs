//! The one door: [`Solver::new`] once, then [`Solver::solve_lcps`] or
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
pub(crate) use cpu_path::{lemke_else_enumerate, textbook_checked};
mod friction_path;
mod gpu_path;
mod world_cpu;
mod world_friction;
pub mod world_path;
mod world_repair;

pub use world_repair::Repairs;

pub use cost::{cache_dir, CostModel, CALIBRATION_SIZES};

use crate::build::Built;
use crate::cpu::batch::parallel_map;
use crate::gpu::{self, GpuContext, Precision};
use crate::lcp::Lcp;
use crate::report::{Device, DeviceKind, IslandReport, Report, SceneReport};
use crate::scene::Scene;
use crate::settings::{Backend, Settings};
use crate::warm::{basis_entries, Warm, SHARDS};
use crate::Error;

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
}

/// What the phases (free functions in this folder's modules) read of the
/// [`Solver`], borrowed for one phase: the settings, the thread count, the
/// warm-start memory, and the words every report carries (why this
/// device, why the CPU took over). The solver itself stays with the
/// conductor (the methods in this file), which alone opens or drops the
/// device and records into the warm-start memory.
#[derive(Clone, Copy)]
pub(super) struct SolverView<'a> {
    pub(super) settings: &'a Settings,
    pub(super) threads: usize,
    pub(super) warm: &'a Warm,
    pub(super) choice: &'a str,
    pub(super) fallback: Option<&'a str>,
}

impl SolverView<'_> {
    /// The report of `islands` (already through [`check_solution`]) and
    /// `scenes` on `device`, with the solver's choice and fallback reason.
    pub(super) fn report(
        &self,
        islands: Vec<IslandReport>,
        scenes: Vec<SceneReport>,
        device: Device,
    ) -> Report {
        let mut r = Report::new(islands, scenes, device, self.choice.to_string());
        r.fallback = self.fallback.map(str::to_string);
        r
    }

    /// The CPU path as a device.
    pub(super) fn cpu_device(&self) -> Device {
        cpu_device(self.threads)
    }

    /// The warm basis remembered for an island's contact ids (None without
    /// `settings.warm_start` or without ids).
    pub(super) fn warm_basis(&self, ids: &[u64]) -> Option<u32> {
        if !self.settings.warm_start || ids.is_empty() {
            return None;
        }
        self.warm.bases.basis(ids.iter().map(|&id| Some(id)))
    }
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
        let s = &self.settings;
        let gpu_wanted = match s.backend {
            Backend::Cpu => {
                self.choice = "backend cpu".into();
                false
            }
            Backend::Gpu => {
                self.choice = "backend gpu".into();
                true
            }
            Backend::Auto if !s.gpu_capable() => {
                self.choice = format!("backend auto: {} runs on the CPU only", s.method.name());
                false
            }
            Backend::Auto if s.gpu.adapter.is_some() => {
                self.choice = "backend auto: adapter named".into();
                true
            }
            Backend::Auto => {
                let adapters = gpu::list_adapters(s.gpu.api);
                let hardware = adapters.iter().find(|a| !a.software);
                match (hardware, adapters.first()) {
                    (Some(a), _) => {
                        self.choice = format!("backend auto: hardware adapter {}", a.name);
                        true
                    }
                    (None, Some(a)) => {
                        self.choice = format!(
                            "backend auto: the only adapters are software ({}), slower than the CPU path; name one or ask for backend gpu to use it",
                            a.name
                        );
                        false
                    }
                    (None, None) => {
                        self.choice = "backend auto: no GPU adapter".into();
                        false
                    }
                }
            }
        };
        if gpu_wanted {
            match GpuContext::new(&s.gpu.options()) {
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
            None => match self.calibrate() {
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

    /// Measures this solver's CPU and GPU paths by island size (see
    /// [`CostModel`]); needs a GPU open.
    ///
    /// # Errors
    /// [`Error::Gpu`] without a GPU open or on device trouble.
    pub fn calibrate(&mut self) -> Result<CostModel, Error> {
        let Some(ctx) = self.gpu.clone() else {
            return Err(Error::Gpu("calibration needs a GPU".into()));
        };
        cost::calibrate(&self.view(), &ctx)
    }

    /// Whether the next batch of islands of `sizes` goes to the GPU, and
    /// why in words for the report (without a cost model: wherever a GPU
    /// is open).
    fn gpu_for(&self, sizes: impl Iterator<Item = usize>) -> (bool, String) {
        match (&self.gpu, &self.cost) {
            (None, _) => (false, self.choice.clone()),
            (Some(_), None) => (true, self.choice.clone()),
            (Some(_), Some(m)) => {
                let (cpu, gpu) = m.estimate(sizes);
                let on_gpu = gpu < cpu;
                let why = format!(
                    "{}; cost model: CPU {:.3} ms, GPU {:.3} ms estimated → {}",
                    self.choice,
                    cpu * 1e3,
                    gpu * 1e3,
                    if on_gpu { "GPU" } else { "CPU" }
                );
                (on_gpu, why)
            }
        }
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
        self.solve_lcps_warm(lcps, None)
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
        if ids.len() != lcps.len() {
            return Err(Error::invalid(
                "ids",
                "len",
                format!("{} id lists for {} problems", ids.len(), lcps.len()),
            ));
        }
        for (i, (l, k)) in lcps.iter().zip(ids).enumerate() {
            if k.len() != l.n() {
                return Err(Error::invalid(
                    format!("problem {i}"),
                    "ids",
                    format!("{} ids for n = {}", k.len(), l.n()),
                ));
            }
        }
        let keys: Vec<&[u64]> = ids.iter().map(Vec::as_slice).collect();
        self.solve_lcps_warm(lcps, Some(&keys))
    }

    fn solve_lcps_warm(&mut self, lcps: &[Lcp], keys: Option<&[&[u64]]>) -> Result<Report, Error> {
        let start = Instant::now();
        let (use_gpu, why) = self.gpu_for(lcps.iter().map(Lcp::n));
        let on_gpu = self.gpu.clone().filter(|_| use_gpu).map(|ctx| {
            if self.settings.all_solutions {
                gpu_path::all_solutions_lcps_on_gpu(&self.view(), &ctx, lcps)
            } else {
                let keys = keys.filter(|_| self.settings.warm_start);
                gpu_path::lcps_on_gpu(&self.view(), &ctx, lcps, keys)
            }
        });
        // Both paths check each problem and look up its warm basis on the
        // threads that solve it.
        let mut report = match self.gpu_outcome(on_gpu)? {
            Some(r) => r,
            None => cpu_path::lcps_on_cpu(&self.view(), lcps, keys)?,
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
        let (use_gpu, why) = self.gpu_for(sizes);
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

/// The final check of every island, on every backend and method
/// ([`check_solution`] on each answer).
pub(super) fn check(islands: &mut [IslandReport], tolerance: f64) {
    for isl in islands {
        check_solution(&mut isl.solution, tolerance);
    }
}

/// The final check of one answer: a solution whose z, w or error is not
/// finite, or whose error is above `tolerance` (`settings.tolerance`),
/// becomes `numerical_failure`.
pub(crate) fn check_solution(s: &mut crate::LcpSolution, tolerance: f64) {
    if s.status.is_solution() && !s.passes_check(tolerance) {
        s.status = crate::Status::NumericalFailure;
    }
}

/// The CPU path as a device.
pub(super) fn cpu_device(threads: usize) -> Device {
    Device {
        kind: DeviceKind::Cpu,
        name: format!("cpu ({threads} thread(s), f64)"),
        precision: Precision::F64,
    }
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
