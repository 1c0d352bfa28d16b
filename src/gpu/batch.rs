//! Batches of LCPs on the GPU: prediction on the CPU, the enumeration stage
//! for islands of any mix of sizes, then validation of every answer on the
//! CPU in f64.
//!
//! Scheduling: islands are sorted by n and dispatched one size at a time, so
//! that a workgroup never waits on a larger island than its own. A batch is
//! split into chunks whose buffers stay under the device's storage-binding
//! and buffer limits ([`super::buffers`]), and each dispatch into ranges of
//! at most 65,535 workgroups ([`super::dispatch`]); the caller sees one
//! result per island, in its order.

// Stage entry points (`enumerate_on_gpu`, the GPU's raw
// verdicts in `IslandOutcome`) serve the stage tests and the benches of
// single kernels; the Solver calls `solve_lcp_batch_warm`.
#![cfg_attr(not(test), allow(dead_code))]

use std::time::Instant;

use super::buffers::{limits_for, pack_chunks};
use super::enumeration::EnumerationJob;
pub use super::kernel::{EnumerationKernel, KernelPlan, TreeRoute};
use super::layout::BasisResult;
use super::pipelines::Tolerances;
use super::{GpuContext, Precision, MAX_GPU_N};
use crate::cpu::enumeration::EnumerationSettings;
use crate::cpu::enumeration_tree::TREE_MAX_N;
use crate::cpu::lemke::{lemke, LemkeSettings};
use crate::gpu::validation::{validate_island, BatchReport, GpuVerdict, Verdict};
use crate::lcp::{Lcp, LcpSolution};
use crate::prediction::{prediction, SolvePath, Unsettled};
use crate::settings::Method;
use crate::Error;

/// Default GPU tolerances in f32 (f64 shaders use the CPU's): accept more
/// than f64 would (the f64 polish rejects what is wrong and counts it as
/// repaired) and call a basis singular only when f32 cannot tell.
pub const F32_PIVOT_TOL: f64 = 1e-6;
pub const F32_FEASIBILITY_TOL: f64 = 1e-4;
/// f32 fallback tolerance: the least infeasible basis within it is named
/// when no basis is valid (the f64 check then decides).
pub const F32_RELAXED_TOL: f64 = 1e-3;

/// Settings of a GPU batch solve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpuSolveSettings {
    /// The CPU's enumeration settings: the f64 polish and repair use them,
    /// and f64 shaders use the same tolerances. `all_solutions` is not
    /// supported on the GPU.
    pub enumeration: EnumerationSettings,
    /// GPU pivot tolerance; None: the CPU's in f64, [`F32_PIVOT_TOL`] in f32.
    pub gpu_pivot_tol: Option<f64>,
    /// GPU feasibility tolerance; None: the CPU's in f64, [`F32_FEASIBILITY_TOL`] in f32.
    pub gpu_feasibility_tol: Option<f64>,
    /// GPU relaxed tolerance; None: the CPU's in f64, [`F32_RELAXED_TOL`] in f32.
    pub gpu_relaxed_tol: Option<f64>,
    /// Islands with n > 16 are solved on the CPU with these settings.
    pub lemke: LemkeSettings,
    /// Lower the size above which a batch is split (bytes per binding;
    /// capped at the device's limit). For tests of the splitting.
    pub max_binding_bytes: Option<u64>,
    /// Lower the workgroups per dispatch (capped at the device's limit).
    pub max_workgroups: Option<u32>,
    /// Loop work per invocation and enumeration round; None: by adapter
    /// ([`SOFTWARE_ROUND_BUDGET`] or [`HARDWARE_ROUND_BUDGET`]).
    pub round_budget: Option<u32>,
    /// Settle islands that need no enumeration on the CPU first
    /// ([`crate::prediction::predict`]: separating, single contact, warm
    /// start, predicted basis), so that only the others are uploaded and
    /// dispatched. Default true.
    pub predict: bool,
    /// Which enumeration shader runs (default [`EnumerationKernel::Auto`]).
    pub kernel: EnumerationKernel,
    /// Largest island the tree kernel takes (default [`TREE_MAX_N`]; values
    /// above it act as it; 0 turns the tree off).
    pub tree_max_n: usize,
}

impl Default for GpuSolveSettings {
    fn default() -> Self {
        GpuSolveSettings {
            enumeration: EnumerationSettings::default(),
            gpu_pivot_tol: None,
            gpu_feasibility_tol: None,
            gpu_relaxed_tol: None,
            lemke: LemkeSettings::default(),
            max_binding_bytes: None,
            max_workgroups: None,
            round_budget: None,
            predict: true,
            kernel: EnumerationKernel::Auto,
            tree_max_n: TREE_MAX_N,
        }
    }
}

impl GpuSolveSettings {
    /// (pivot, feasibility, relaxed) tolerances of the shaders at `precision`.
    pub fn gpu_tolerances(&self, precision: Precision) -> (f64, f64, f64) {
        let e = &self.enumeration;
        let (p, f, r) = if precision == Precision::F64 {
            (e.pivot_tol, e.feasibility_tol, e.relaxed_feasibility_tol)
        } else {
            (F32_PIVOT_TOL, F32_FEASIBILITY_TOL, F32_RELAXED_TOL)
        };
        (
            self.gpu_pivot_tol.unwrap_or(p),
            self.gpu_feasibility_tol.unwrap_or(f),
            self.gpu_relaxed_tol.unwrap_or(r),
        )
    }

    /// True when the shaders run the CPU twin's arithmetic and tolerances
    /// (f64): then a least-infeasible basis the GPU names after visiting
    /// every basis is the CPU's choice, and validation keeps it when it is
    /// within the relaxed tolerance in f64.
    pub fn exact_twin(&self, precision: Precision) -> bool {
        let e = &self.enumeration;
        precision == Precision::F64
            && self.gpu_tolerances(precision)
                == (e.pivot_tol, e.feasibility_tol, e.relaxed_feasibility_tol)
    }
}

/// Where an island's answer came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SolvedOn {
    /// The GPU's basis, valid in f64 (polished), or the GPU's "no
    /// solution" confirmed on the CPU.
    Gpu,
    /// The GPU's answer failed the f64 check; the CPU enumeration solved it.
    Repaired,
    /// n > 16: solved on the CPU by Lemke.
    CpuFallback,
    /// Settled on the CPU by prediction before the GPU (see
    /// [`IslandOutcome::path`] for which case).
    Predicted,
    /// The problem failed its checks (status InvalidInput).
    Invalid,
}

impl SolvedOn {
    /// The report's path of an island solved here; `path`: its prediction
    /// case where it was settled by prediction.
    pub(crate) fn path(self, path: Option<SolvePath>) -> crate::report::SolvePath {
        use crate::report::SolvePath as Path;
        match (self, path) {
            (SolvedOn::Gpu, _) => Path::EnumeratedGpu,
            (SolvedOn::Repaired, _) => Path::Repaired,
            (SolvedOn::CpuFallback, _) => Path::Lemke,
            (SolvedOn::Invalid, _) => Path::Invalid,
            (SolvedOn::Predicted, Some(p)) => p.into(),
            // The GPU backend names the prediction case of every island it
            // settled that way; none is left without one.
            (SolvedOn::Predicted, None) => Path::PredictedBasis,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            SolvedOn::Gpu => "gpu",
            SolvedOn::Repaired => "repaired",
            SolvedOn::CpuFallback => "cpu_fallback",
            SolvedOn::Predicted => "predicted",
            SolvedOn::Invalid => "invalid",
        }
    }
}

/// One island's result.
#[derive(Clone, Debug)]
pub struct IslandOutcome {
    /// The validated solution (z, w and residuals in f64).
    pub solution: LcpSolution,
    pub solved_on: SolvedOn,
    /// How the island was settled: a prediction case, Enumerated (GPU,
    /// validated) or Lemke; None for a problem that failed its checks.
    pub path: Option<SolvePath>,
    /// The algorithm whose answer this is: Enum (GPU or CPU) or Lemke.
    pub solver: Method,
    /// What the GPU's enumeration stage reported (None when it did not run).
    pub gpu: Option<BasisResult>,
    /// The GPU's own z, before the f64 polish (empty when it did not run).
    pub gpu_z: Vec<f64>,
}

/// Results in the caller's order and the batch's report.
#[derive(Clone, Debug)]
pub struct GpuBatchResult {
    pub islands: Vec<IslandOutcome>,
    pub report: BatchReport,
}

/// Output of the enumeration stage for one island, before validation.
#[derive(Clone, Debug, PartialEq)]
pub struct EnumerationOutput {
    pub result: BasisResult,
    /// z of the chosen basis in the shader's precision (zeros when none).
    pub z: Vec<f64>,
}

/// What one GPU run did (for the report and the benches).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RunStats {
    pub chunks: usize,
    pub dispatches: usize,
    /// Enumeration rounds (summed over chunks).
    pub rounds: usize,
    /// Seconds of upload + dispatch + readback.
    pub seconds: f64,
    /// Islands the tree kernel decided, and those it left to elimination.
    pub tree_decided: usize,
    pub tree_undecided: usize,
}

/// Runs the enumeration stage alone on every problem (each must be valid
/// with n ≤ 16) and returns its raw output, in order. This is the stage the
/// tests compare with its CPU twin, [`crate::cpu::enumeration::enumerate`].
pub fn enumerate_on_gpu(
    ctx: &GpuContext,
    lcps: &[&Lcp],
    settings: &GpuSolveSettings,
) -> Result<(Vec<EnumerationOutput>, RunStats), Error> {
    enumerate_known(ctx, lcps, &[], settings)
}

/// [`enumerate_on_gpu`] with `definite[i]`: whether island i's M is
/// positive definite, where prediction found out (empty: nothing known).
fn enumerate_known(
    ctx: &GpuContext,
    lcps: &[&Lcp],
    definite: &[Option<bool>],
    settings: &GpuSolveSettings,
) -> Result<(Vec<EnumerationOutput>, RunStats), Error> {
    let start = Instant::now();
    let mut stats = RunStats::default();
    check_gpu_sizes(lcps)?;
    let precision = ctx.precision();
    let pipelines = ctx.pipelines()?;
    let tolerances = Tolerances::new(precision, settings).upload(ctx);
    let (max_bytes, max_groups) = limits_for(ctx, settings);
    let plan = KernelPlan::new(ctx, settings);

    let mut out = vec![
        EnumerationOutput {
            result: BasisResult::default(),
            z: Vec::new(),
        };
        lcps.len()
    ];
    let tree: Vec<TreeRoute> = lcps
        .iter()
        .enumerate()
        .map(|(i, l)| plan.tree_for(l, definite.get(i).copied().flatten()))
        .collect();
    for chunk in pack_chunks(lcps, &tree, max_bytes, precision.bytes()) {
        let run = ctx.scoped("enumeration", || {
            let (islands, values) = chunk.upload(ctx, precision);
            let job = EnumerationJob {
                ctx,
                pipelines: &pipelines,
                islands: &islands,
                values: &values,
                tolerances: &tolerances,
                table: &chunk.table,
                tree: &chunk.tree,
                max_groups,
                plan: &plan,
            };
            job.run(ctx.encoder("enumeration"), true)
        })??;
        for ((&i, rec), res) in chunk.order.iter().zip(&chunk.table).zip(&run.results) {
            let (z0, n) = (rec.z as usize, rec.n as usize);
            out[i] = EnumerationOutput {
                result: *res,
                z: run
                    .z
                    .get(z0..z0 + n)
                    .map(<[f64]>::to_vec)
                    .unwrap_or_default(),
            };
        }
        stats.chunks += 1;
        stats.dispatches += run.dispatches;
        stats.rounds += run.rounds;
        stats.tree_decided += run.tree_decided;
        stats.tree_undecided += run.tree_undecided;
    }
    stats.seconds = start.elapsed().as_secs_f64();
    Ok((out, stats))
}

fn check_gpu_sizes(lcps: &[&Lcp]) -> Result<(), Error> {
    for (i, l) in lcps.iter().enumerate() {
        if l.n() == 0 || l.n() > MAX_GPU_N || l.m.len() != l.n() * l.n() {
            return Err(Error::Unsupported(format!(
                "problem {i}: the GPU enumerates 1 ≤ n ≤ {MAX_GPU_N} (n = {})",
                l.n()
            )));
        }
    }
    Ok(())
}

/// Problem i settled on the CPU: invalid, n > [`MAX_GPU_N`] (Lemke), or
/// by prediction (with `settings.predict`); else what prediction learnt.
fn settle_on_cpu(
    i: usize,
    lcp: &Lcp,
    warm: Option<u32>,
    settings: &GpuSolveSettings,
) -> Result<IslandOutcome, Unsettled> {
    let outcome = |solution, solved_on, path, solver| IslandOutcome {
        solution,
        solved_on,
        path,
        solver,
        gpu: None,
        gpu_z: Vec::new(),
    };
    if lcp.validate(format_args!("problem {i}")).is_err() {
        let s = LcpSolution::invalid(lcp.q.len());
        return Ok(outcome(s, SolvedOn::Invalid, None, Method::Enumeration));
    }
    if lcp.n() > MAX_GPU_N {
        let s = lemke(lcp, &settings.lemke);
        let path = Some(SolvePath::Lemke);
        return Ok(outcome(s, SolvedOn::CpuFallback, path, Method::Lemke));
    }
    if !settings.predict {
        return Err(Unsettled { definite: None });
    }
    let (path, s) = prediction(lcp, warm, &settings.enumeration)?;
    Ok(outcome(
        s,
        SolvedOn::Predicted,
        Some(path),
        Method::Enumeration,
    ))
}

/// Solves a batch of LCPs: islands with n ≤ 16 by enumeration on the GPU,
/// each answer validated in f64 on the CPU (polished, or repaired by the CPU
/// enumeration), larger ones by Lemke on the CPU. Problems that fail their
/// checks get status InvalidInput. Results come back in the caller's order.
/// With `settings.predict`, islands that need no enumeration are settled on
/// the CPU first and never uploaded (see [`solve_lcp_batch_warm`]).
pub fn solve_lcp_batch(
    ctx: &GpuContext,
    lcps: &[Lcp],
    settings: &GpuSolveSettings,
) -> Result<GpuBatchResult, Error> {
    solve_lcp_batch_warm(ctx, lcps, None, settings)
}

/// [`solve_lcp_batch`] with warm bases: `warm[i]` is island i's basis from
/// the previous frame, if the caller has one (used by prediction only, so
/// ignored when `settings.predict` is false).
pub fn solve_lcp_batch_warm(
    ctx: &GpuContext,
    lcps: &[Lcp],
    warm: Option<&[Option<u32>]>,
    settings: &GpuSolveSettings,
) -> Result<GpuBatchResult, Error> {
    settings.enumeration.validate()?;
    if settings.enumeration.all_solutions {
        return Err(Error::Unsupported(
            "all_solutions is not supported on the GPU; use the CPU backend".into(),
        ));
    }
    let mut report = BatchReport::new(ctx.adapter_info().name.clone(), ctx.precision());
    let mut slots: Vec<Option<IslandOutcome>> = vec![None; lcps.len()];
    let mut on_gpu: Vec<usize> = Vec::new();
    // Per island on the GPU: whether M is positive definite, if prediction found out.
    let mut definite: Vec<Option<bool>> = Vec::new();
    let warm_of = |i: usize| warm.and_then(|w| w.get(i).copied().flatten());
    let t_predict = Instant::now();
    for (i, lcp) in lcps.iter().enumerate() {
        match settle_on_cpu(i, lcp, warm_of(i), settings) {
            Ok(outcome) => slots[i] = Some(outcome),
            Err(unsettled) => {
                on_gpu.push(i);
                definite.push(unsettled.definite);
            }
        }
    }
    report.prediction_seconds = t_predict.elapsed().as_secs_f64();
    let refs: Vec<&Lcp> = on_gpu.iter().map(|&i| &lcps[i]).collect();
    let (outputs, stats) = enumerate_known(ctx, &refs, &definite, settings)?;
    report.gpu_seconds = stats.seconds;
    report.chunks = stats.chunks;
    report.dispatches = stats.dispatches;
    report.rounds = stats.rounds;
    report.tree_decided = stats.tree_decided;
    report.tree_undecided = stats.tree_undecided;
    let start = Instant::now();
    for (&i, o) in on_gpu.iter().zip(outputs) {
        let verdict = GpuVerdict::of(&o.result, &o.z);
        let checked = validate_island(
            &lcps[i],
            &verdict,
            &settings.enumeration,
            settings.exact_twin(ctx.precision()),
        )?;
        report.record_gpu(&checked);
        let solved_on = match checked.verdict {
            Verdict::Polished | Verdict::ConfirmedNoSolution => SolvedOn::Gpu,
            Verdict::Repaired => SolvedOn::Repaired,
        };
        slots[i] = Some(IslandOutcome {
            solution: checked.solution,
            solved_on,
            path: Some(SolvePath::Enumerated),
            solver: Method::Enumeration,
            gpu: Some(o.result),
            gpu_z: o.z,
        });
    }
    report.validation_seconds = start.elapsed().as_secs_f64();
    let islands: Vec<IslandOutcome> = slots
        .into_iter()
        .map(|s| s.ok_or_else(|| Error::Gpu("an island got no result".into())))
        .collect::<Result<_, _>>()?;
    for o in &islands {
        match (o.solved_on, o.path) {
            (SolvedOn::CpuFallback, _) => report.record_cpu_fallback(&o.solution),
            (SolvedOn::Invalid, _) => report.record_invalid(),
            (SolvedOn::Predicted, Some(p)) => report.record_predicted(p, &o.solution),
            _ => {}
        }
    }
    Ok(GpuBatchResult { islands, report })
}
