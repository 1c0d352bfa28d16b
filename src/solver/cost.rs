//! `Backend::Auto`'s choice per batch: a cost model of this machine, by
//! island size, measured once through the solver's own two paths and cached.
//!
//! A batch of islands of sizes n₁…n_B is estimated to take
//!
//! ```text
//! CPU: Σ_i cpu(n_i)            GPU: gpu_batch + Σ_i gpu(n_i)
//! ```
//!
//! seconds, where cpu(n) and gpu(n) are the measured seconds per island at
//! the calibrated sizes (linear in n between them, the first below them,
//! growing like n³ above them: see [`CostModel::per_island`]), and
//! gpu_batch the GPU's fixed cost per call (upload, submissions, readback).
//! `Auto` solves each batch where the estimate is lower; the report's
//! `choice` gives both estimates. The calibration's batches are one part
//! of the GPU path's pipeline (`crate::gpu::batch`); on hardware a batch
//! leaving 32,768+ islands to the GPU overlaps the host's share with the
//! kernels, which the estimate leaves out (the model has no split of
//! host and device seconds): it errs towards the CPU on such batches.
//!
//! Calibration ([`Solver::calibrate`](super::Solver::calibrate), [`calibrate`]): physical islands of each size in
//! [`CALIBRATION_SIZES`] solved by the CPU path (every core) and by the GPU
//! path at two batch sizes (each after an untimed call that warms the CPU's
//! workers or compiles the size's kernels), so that the GPU's per-batch cost separates from its per-island
//! cost; each figure is the fastest of three runs. It runs when `Backend::Auto` has a GPU open and no model is cached
//! for this device, precision and thread count; the model is written to
//! [`cache_dir`] and read by later processes.
//!
//! **Worlds** ([`WorldCosts`], `Solver::step_worlds`, `step_worlds_for`):
//! frictionless 4-box stacks ([`crate::world::generate`]) timed on the
//! CPU's per-world path (every core) and on the resident GPU path (adapters
//! with f64 only) at two batch sizes, one step per submission, so that its
//! fixed cost per submission separates from its cost per world-step. They
//! are measured when `Backend::Auto` first meets a batch of worlds in the
//! resident path's scope and the model has no world figures (a model
//! cached without them, e.g. before they existed, gains them then and is
//! cached again; a model given in the settings is used as it is), so that
//! solving LCPs never compiles the world kernels. A batch in scope goes
//! resident where [`CostModel::estimate_worlds`] says it is faster, else
//! to the CPU's per-world path.

use std::path::{Path, PathBuf};
use std::time::Instant;

use serde::{Deserialize, Serialize};

use super::cpu_path::lcps_on_cpu;
use super::gpu_path::lcps_on_gpu;
use super::{Solver, SolverView};
use crate::generate::families::islands_of_size;
use crate::gpu::resident::{ResidentWorlds, MOST_STEPS};
use crate::gpu::{GpuContext, Precision};
use crate::settings::{Backend, Settings};
use crate::world::generate::{standard_world, WorldKind};
use crate::world::World;
use crate::Error;

/// The island sizes a calibration measures.
pub const CALIBRATION_SIZES: [usize; 4] = [2, 4, 8, 12];
/// Islands per size in the CPU's timed batch and the GPU's larger one.
const CALIBRATION_ISLANDS: usize = 1024;
/// Islands per size in the GPU's smaller batch.
const CALIBRATION_SMALL: usize = 128;
/// The world the world figures are measured on: a stack of this many
/// boxes (frictionless, restitution 0) on its ground.
const CALIBRATION_STACK: usize = 4;
/// Worlds of the CPU's timed batch and of the resident path's two, and the
/// CPU's steps per timed call.
const CALIBRATION_WORLDS: [usize; 2] = [64, 512];
const CALIBRATION_CPU_STEPS: usize = 4;

/// Seconds per island on each path, by island size, on one device.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CostModel {
    /// The GPU it was measured on: adapter name, wgpu backend, device type
    /// and precision.
    pub device: String,
    /// CPU worker threads during the measurement.
    pub threads: usize,
    /// Island sizes measured, ascending.
    pub sizes: Vec<usize>,
    /// Seconds per island of the CPU path (all `threads`), one per size.
    pub cpu_per_island: Vec<f64>,
    /// Seconds per island of the GPU path, one per size.
    pub gpu_per_island: Vec<f64>,
    /// Seconds of one GPU call beyond its islands.
    pub gpu_per_batch: f64,
    /// The world figures (None: not measured, e.g. on an adapter without
    /// f64, where no world takes the resident path; a model given in the
    /// settings without them keeps worlds on the CPU).
    #[serde(default)]
    pub worlds: Option<WorldCosts>,
}

/// Seconds per world-step of `Solver::step_worlds`' two routes, measured on
/// frictionless stacks of [`CALIBRATION_STACK`] boxes; a batch's worlds
/// count by their bodies against the measured world's.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct WorldCosts {
    /// Bodies of the measured world (ground included).
    pub bodies: usize,
    /// Seconds per world-step on the CPU's per-world path (all threads).
    pub cpu_per_world_step: f64,
    /// Seconds per world-step on the resident GPU path.
    pub gpu_per_world_step: f64,
    /// Seconds of one resident submission beyond its world-steps (the
    /// dispatches, the wait, the records' readback).
    pub gpu_per_submission: f64,
}

impl CostModel {
    /// Checks shapes and values (finite, ≥ 0; sizes ascending, ≥ 1).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `settings: cost_model` and the field at fault.
    pub fn validate(&self) -> Result<(), Error> {
        let bad = |field: &str, why: &str| Err(Error::invalid("settings: cost_model", field, why));
        let k = self.sizes.len();
        if k == 0 || self.cpu_per_island.len() != k || self.gpu_per_island.len() != k {
            return bad("sizes", "needs one CPU and one GPU figure per size");
        }
        if self.sizes[0] == 0 || self.sizes.windows(2).any(|w| w[0] >= w[1]) {
            return bad("sizes", "must be ≥ 1 and strictly ascending");
        }
        let figures = self.cpu_per_island.iter().chain(&self.gpu_per_island);
        if figures
            .chain([&self.gpu_per_batch])
            .any(|v| !(v.is_finite() && *v >= 0.0))
        {
            return bad("cpu_per_island", "every figure must be finite and ≥ 0");
        }
        if let Some(w) = &self.worlds {
            let figures = [
                w.cpu_per_world_step,
                w.gpu_per_world_step,
                w.gpu_per_submission,
            ];
            if w.bodies == 0 || figures.iter().any(|v| !(v.is_finite() && *v >= 0.0)) {
                return bad("worlds", "bodies ≥ 1 and every figure finite and ≥ 0");
            }
        }
        Ok(())
    }

    /// (CPU seconds, GPU seconds) estimated for `steps` steps of worlds of
    /// `bodies` bodies in all, in one `step_worlds_for` call: on the CPU
    /// per world-step, on the resident path per world-step and per
    /// submission, the submissions counted as the path takes them: the
    /// first of `first` steps, each next twice the last (up to
    /// [`MOST_STEPS`]), each ending at a frame (`frames`: the steps after
    /// which some worlds' states are read, ascending, each read a
    /// submission of its own) and at the call's end; None without the
    /// world figures.
    pub fn estimate_worlds(
        &self,
        bodies: usize,
        steps: usize,
        first: usize,
        frames: &[usize],
    ) -> Option<(f64, f64)> {
        let w = self.worlds?;
        let world_steps = bodies as f64 / w.bodies as f64 * steps as f64;
        let (mut submissions, mut taken, mut k) = (frames.len(), 0usize, first.max(1));
        for stop in frames.iter().copied().chain([steps]) {
            while taken < stop {
                let took = k.min(stop - taken).min(MOST_STEPS);
                taken += took;
                submissions += 1;
                k = (2 * took).min(MOST_STEPS);
            }
        }
        let cpu = world_steps * w.cpu_per_world_step;
        let gpu = submissions as f64 * w.gpu_per_submission + world_steps * w.gpu_per_world_step;
        Some((cpu, gpu))
    }

    /// Seconds per island of size n from `table` (one figure per size):
    /// linear in n between measured sizes; below the first, the first;
    /// above the last, the last scaled by (n / n_last)³ (an island's work
    /// grows at least like n³ there).
    pub fn per_island(&self, table: &[f64], n: usize) -> f64 {
        let s = &self.sizes;
        let last = s.len() - 1;
        if n <= s[0] {
            return table[0];
        }
        if n >= s[last] {
            return table[last] * (n as f64 / s[last] as f64).powi(3);
        }
        let j = s.iter().position(|&m| m >= n).unwrap_or(last);
        let t = (n - s[j - 1]) as f64 / (s[j] - s[j - 1]) as f64;
        table[j - 1] + t * (table[j] - table[j - 1])
    }

    /// (CPU seconds, GPU seconds) estimated for a batch of islands of `sizes`.
    pub fn estimate(&self, sizes: impl Iterator<Item = usize>) -> (f64, f64) {
        let (mut cpu, mut gpu) = (0.0, self.gpu_per_batch);
        for n in sizes {
            cpu += self.per_island(&self.cpu_per_island, n);
            gpu += self.per_island(&self.gpu_per_island, n);
        }
        (cpu, gpu)
    }
}

impl std::fmt::Display for CostModel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(
            f,
            "cost model ({}; CPU {} thread(s)); GPU per call {:.2} ms",
            self.device,
            self.threads,
            self.gpu_per_batch * 1e3
        )?;
        writeln!(f, "   n   CPU µs/island   GPU µs/island")?;
        for (k, n) in self.sizes.iter().enumerate() {
            writeln!(
                f,
                "{n:>4}   {:>13.3}   {:>13.3}",
                self.cpu_per_island[k] * 1e6,
                self.gpu_per_island[k] * 1e6
            )?;
        }
        match &self.worlds {
            Some(w) => writeln!(
                f,
                "worlds ({} bodies): CPU {:.3} µs/world-step; resident GPU {:.3} µs/world-step + {:.3} ms/submission",
                w.bodies,
                w.cpu_per_world_step * 1e6,
                w.gpu_per_world_step * 1e6,
                w.gpu_per_submission * 1e3
            ),
            None => writeln!(
                f,
                "worlds: no figures yet (measured when auto first meets worlds the resident path can take)"
            ),
        }
    }
}

/// Where models are cached: `$LCPBATCH_CACHE_DIR`, else
/// `$XDG_CACHE_HOME/lcpbatch`, else `$HOME/.cache/lcpbatch`.
pub fn cache_dir() -> Option<PathBuf> {
    let env = |k| {
        std::env::var_os(k)
            .filter(|v| !v.is_empty())
            .map(PathBuf::from)
    };
    env("LCPBATCH_CACHE_DIR")
        .or_else(|| env("XDG_CACHE_HOME").map(|d| d.join("lcpbatch")))
        .or_else(|| env("HOME").map(|d| d.join(".cache").join("lcpbatch")))
}

/// The cache file in `dir` of a device and thread count (FNV-1a of both,
/// with the crate's version: a new version measures again).
fn cache_file(dir: &Path, device: &str, threads: usize) -> PathBuf {
    let key = format!("{} {device} {threads}", env!("CARGO_PKG_VERSION"));
    let hash = key.bytes().fold(0xcbf29ce484222325u64, |h, b| {
        (h ^ b as u64).wrapping_mul(0x100000001b3)
    });
    dir.join(format!("cost-model-{hash:016x}.json"))
}

/// The model of this device and thread count cached in `dir`, if one was
/// measured (an unreadable or invalid file counts as none; one without the
/// world figures reads with none: they are measured when first needed).
pub(super) fn cached(dir: &Path, device: &str, threads: usize) -> Option<CostModel> {
    let text = std::fs::read_to_string(cache_file(dir, device, threads)).ok()?;
    let m: CostModel = serde_json::from_str(&text).ok()?;
    (m.device == device && m.threads == threads && m.validate().is_ok()).then_some(m)
}

/// Writes `model` to the cache in `dir` (atomically); returns the file.
pub(super) fn store(dir: &Path, model: &CostModel) -> Result<PathBuf, Error> {
    let path = cache_file(dir, &model.device, model.threads);
    let text = serde_json::to_string_pretty(model).map_err(|e| Error::json("cost model", e))?;
    std::fs::create_dir_all(dir).map_err(|source| Error::Io {
        path: dir.to_path_buf(),
        source,
    })?;
    crate::io::write_atomically(&path, &text)?;
    Ok(path)
}

impl CostModel {
    /// Writes the model to [`cache_dir`], where later solvers on the same
    /// device and thread count find it; returns the file.
    ///
    /// # Errors
    /// [`Error::Unsupported`] when there is no cache folder; [`Error::Io`]
    /// when it or the file cannot be written.
    pub fn save(&self) -> Result<PathBuf, Error> {
        let dir = cache_dir().ok_or_else(|| {
            Error::Unsupported("no cache folder: set LCPBATCH_CACHE_DIR or HOME".into())
        })?;
        store(&dir, self)
    }
}

/// What a cost model is kept under: the GPU's name, wgpu backend, type
/// and precision, however it was chosen (by name or not); empty without a
/// GPU.
pub(super) fn cost_key(gpu: Option<&GpuContext>) -> String {
    gpu.map_or_else(String::new, |ctx| {
        let a = ctx.adapter_info();
        format!(
            "{} ({}, {}; {})",
            a.name,
            a.backend,
            a.device_type,
            ctx.precision().name()
        )
    })
}

impl Solver {
    /// [`Solver::calibrate`], with the world figures where `worlds` asks
    /// for them (and the adapter has f64).
    pub(super) fn calibrate_for(&mut self, worlds: bool) -> Result<CostModel, Error> {
        let Some(ctx) = self.gpu.clone() else {
            return Err(Error::Gpu("calibration needs a GPU".into()));
        };
        let mut m = calibrate(&self.view(), &ctx)?;
        if worlds && ctx.precision() == Precision::F64 {
            m.worlds = Some(calibrate_worlds(&self.view(), &ctx)?);
        }
        Ok(m)
    }

    /// `Backend::Auto` with a GPU open in f64 and a model without world
    /// figures, not given in the settings: the figures measured now (a
    /// batch of worlds in the resident path's scope needs them) and the
    /// model cached again with them. Device trouble falls back to the CPU.
    pub(super) fn world_costs(&mut self) {
        let needed = self.settings.backend == Backend::Auto
            && self.settings.cost_model.is_none()
            && (self.cost.as_ref()).is_some_and(|m| m.worlds.is_none())
            && (self.gpu.as_deref()).is_some_and(|c| c.precision() == Precision::F64);
        let Some(ctx) = self.gpu.clone().filter(|_| needed) else {
            return;
        };
        match calibrate_worlds(&self.view(), &ctx) {
            Ok(w) => {
                let m = self.cost.as_mut().expect("checked");
                m.worlds = Some(w);
                // A cache that cannot be written is skipped (as in `new`).
                if let Some(d) = cache_dir() {
                    let _ = store(&d, m);
                }
            }
            Err(e) => self.fall_back(format!("calibrating the cost model's worlds: {e}")),
        }
    }
}

/// Measures the CPU path and the GPU path on `ctx` by island size (see the
/// module docs).
///
/// # Errors
/// [`Error::Gpu`] on device trouble.
pub(super) fn calibrate(solver: &SolverView, ctx: &GpuContext) -> Result<CostModel, Error> {
    let mut m = CostModel {
        device: cost_key(Some(ctx)),
        threads: solver.threads,
        sizes: CALIBRATION_SIZES.to_vec(),
        cpu_per_island: Vec::new(),
        gpu_per_island: Vec::new(),
        gpu_per_batch: 0.0,
        worlds: None,
    };
    let mut per_batch = Vec::new();
    for n in CALIBRATION_SIZES {
        let lcps = islands_of_size(n, CALIBRATION_ISLANDS, 0xC0FFEE);
        // Untimed: starts the workers and sizes their workspaces.
        lcps_on_cpu(solver, &lcps[..16], None)?;
        let cpu = fastest_of(TIMINGS, || lcps_on_cpu(solver, &lcps, None))?;
        m.cpu_per_island.push(cpu / lcps.len() as f64);
        // Untimed: compiles this size's kernels.
        lcps_on_gpu(solver, ctx, &lcps[..16], None)?;
        let small = &lcps[..CALIBRATION_SMALL];
        let t_small = fastest_of(TIMINGS, || lcps_on_gpu(solver, ctx, small, None))?;
        let t_large = fastest_of(TIMINGS, || lcps_on_gpu(solver, ctx, &lcps, None))?;
        let (fixed, per_island) = line_through((small.len(), t_small), (lcps.len(), t_large));
        m.gpu_per_island.push(per_island);
        per_batch.push(fixed);
    }
    per_batch.sort_by(f64::total_cmp);
    m.gpu_per_batch = per_batch[per_batch.len() / 2];
    Ok(m)
}

/// [`CALIBRATION_WORLDS`]`[k]` frictionless stacks of [`CALIBRATION_STACK`] boxes.
fn calibration_stacks(count: usize) -> Vec<World> {
    (0..count as u64)
        .map(|seed| {
            let mut w = standard_world(WorldKind::Stack, CALIBRATION_STACK, seed);
            for b in &mut w.bodies {
                b.friction = 0.0;
                b.restitution = 0.0;
            }
            w
        })
        .collect()
}

/// The world figures (see the module docs): the CPU's per-world path on
/// the larger batch, [`CALIBRATION_CPU_STEPS`] steps a call; the resident
/// path one step per submission on both batches (each after an untimed
/// step that compiles its kernels), the line through the two times
/// separating the submission's fixed cost. Each the fastest of three.
fn calibrate_worlds(solver: &SolverView, ctx: &GpuContext) -> Result<WorldCosts, Error> {
    let dt = 0.01;
    let [small, large] = CALIBRATION_WORLDS.map(calibration_stacks);
    let mut cpu = Solver::new(Settings {
        backend: Backend::Cpu,
        cost_model: None,
        threads: solver.threads,
        ..solver.settings.clone()
    })?;
    let mut worlds = large.clone();
    cpu.step_worlds_for(&mut worlds, dt, 1, |_, _| {})?;
    let steps = CALIBRATION_CPU_STEPS;
    let t_cpu = fastest_of(TIMINGS, || {
        cpu.step_worlds_for(&mut worlds, dt, steps, |_, _| {})
    })?;
    let s = solver.settings;
    let warm = s.warm_start && s.predict;
    let gpu = s.gpu_solve();
    let mut t_gpu = [0.0; 2];
    for (t, batch) in t_gpu.iter_mut().zip([&small, &large]) {
        let r = ResidentWorlds::new(ctx, batch, s.tolerance, &gpu, warm, None, None)?;
        r.step(ctx, dt)?;
        *t = fastest_of(TIMINGS, || r.step(ctx, dt))?;
    }
    let [a, b] = CALIBRATION_WORLDS;
    let (per_submission, per_world) = line_through((a, t_gpu[0]), (b, t_gpu[1]));
    Ok(WorldCosts {
        bodies: large[0].bodies.len(),
        cpu_per_world_step: t_cpu / (steps * b) as f64,
        gpu_per_world_step: per_world,
        gpu_per_submission: per_submission,
    })
}

/// (fixed, per item) of t(n) = fixed + n per_item through two timed
/// batches (n, t), n₁ < n₂; each ≥ 0.
fn line_through((n1, t1): (usize, f64), (n2, t2): (usize, f64)) -> (f64, f64) {
    let per_item = ((t2 - t1) / (n2 - n1) as f64).max(0.0);
    ((t1 - n1 as f64 * per_item).max(0.0), per_item)
}

/// Each figure is the fastest of this many runs (other work on the machine
/// only slows a run down).
const TIMINGS: usize = 3;

/// The fastest of `runs` timed calls of `f`, in seconds.
fn fastest_of<T>(runs: usize, mut f: impl FnMut() -> Result<T, Error>) -> Result<f64, Error> {
    let mut best = f64::INFINITY;
    for _ in 0..runs {
        let t = Instant::now();
        f()?;
        best = best.min(t.elapsed().as_secs_f64());
    }
    Ok(best)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn model() -> CostModel {
        CostModel {
            device: "test".into(),
            threads: 2,
            sizes: vec![1, 4, 8],
            cpu_per_island: vec![1e-6, 4e-6, 16e-6],
            gpu_per_island: vec![2e-6, 2e-6, 4e-6],
            gpu_per_batch: 1e-3,
            worlds: Some(WorldCosts {
                bodies: 5,
                cpu_per_world_step: 20e-6,
                gpu_per_world_step: 2e-6,
                gpu_per_submission: 1e-3,
            }),
        }
    }

    #[test]
    fn per_island_interpolates_and_extrapolates() {
        let m = model();
        assert_eq!(m.per_island(&m.cpu_per_island, 1), 1e-6);
        assert!((m.per_island(&m.cpu_per_island, 6) - 10e-6).abs() < 1e-18);
        assert!((m.per_island(&m.cpu_per_island, 16) - 128e-6).abs() < 1e-15);
    }

    #[test]
    fn small_batches_go_to_the_cpu_and_large_heavy_ones_to_the_gpu() {
        let m = model();
        let (cpu, gpu) = m.estimate([8usize; 10].into_iter());
        assert!(cpu < gpu, "{cpu} {gpu}");
        let (cpu, gpu) = m.estimate(std::iter::repeat_n(8usize, 10_000));
        assert!(gpu < cpu, "{cpu} {gpu}");
    }

    #[test]
    fn a_bad_model_is_an_error_naming_the_field() {
        let mut m = model();
        m.sizes = vec![4, 1, 8];
        assert!(m.validate().unwrap_err().to_string().contains("sizes"));
        let mut m = model();
        m.gpu_per_island[1] = f64::NAN;
        assert!(m.validate().is_err());
        let mut m = model();
        m.worlds.as_mut().unwrap().gpu_per_submission = -1.0;
        assert!(m.validate().unwrap_err().to_string().contains("worlds"));
    }

    #[test]
    fn few_worlds_or_steps_stay_on_the_cpu_and_many_go_resident() {
        let m = model();
        // 10 stacks of 5 bodies, 1 step: 0.2 ms on the CPU, 1 ms + 20 µs resident.
        let (cpu, gpu) = m.estimate_worlds(50, 1, 1, &[]).unwrap();
        assert!(cpu < gpu, "{cpu} {gpu}");
        // 1,000 stacks, 100 steps: 2 s on the CPU; 0.2 s + 10 submissions
        // (1, 2, 4, 8, 16, then 16s) of 1 ms resident.
        let (cpu, gpu) = m.estimate_worlds(5000, 100, 1, &[]).unwrap();
        assert!(
            (cpu - 2.0).abs() < 1e-9 && (gpu - 0.21).abs() < 1e-9,
            "{cpu} {gpu}"
        );
        // Frames after steps 3 and 10: submissions of 1, 2 | a read | 4, 3
        // | a read | 6, 12, 16, 16, 16, 16, 8: 13 in all.
        let (_, framed) = m.estimate_worlds(5000, 100, 1, &[3, 10]).unwrap();
        assert!((framed - 0.213).abs() < 1e-9, "{framed}");
        // A batch held since a clean submission of 16 steps starts at 16.
        let (_, held) = m.estimate_worlds(5000, 100, 16, &[]).unwrap();
        assert!((held - 0.207).abs() < 1e-9, "{held}");
        let none = CostModel { worlds: None, ..m };
        assert_eq!(none.estimate_worlds(5000, 100, 1, &[]), None);
    }

    #[test]
    fn the_cache_round_trips_and_is_keyed_by_device() {
        let dir = std::env::temp_dir().join(format!("lcpbatch-cost-{}", std::process::id()));
        let m = model();
        store(&dir, &m).unwrap();
        assert_eq!(cached(&dir, "test", 2), Some(m.clone()));
        assert_eq!(cached(&dir, "test", 4), None);
        assert_eq!(cached(&dir, "other", 2), None);
        // A model cached before the world figures (no such field) reads
        // with none, so that they are measured when first needed.
        let mut old: serde_json::Value = serde_json::to_value(&m).unwrap();
        old.as_object_mut().unwrap().remove("worlds");
        let path = cache_file(&dir, "test", 2);
        std::fs::write(&path, old.to_string()).unwrap();
        assert_eq!(
            cached(&dir, "test", 2),
            Some(CostModel { worlds: None, ..m })
        );
        std::fs::remove_dir_all(dir).ok();
    }
}
