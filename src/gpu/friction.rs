//! Batches of frictional islands through the cone projection iterations on
//! the GPU (`shaders/friction_projected.wgsl`, CPU twin
//! [`crate::friction::projected`]), every answer checked in f64 on the CPU.
//!
//! Islands that fail their checks get `InvalidInput`; islands of more than
//! [`MAX_GPU_CONTACTS`] contacts are solved by the CPU twin (counted as
//! `cpu_fallback`); the others run on the GPU in rounds
//! ([`super::friction_rounds`]). Validation: the GPU's r is projected on the
//! cones in f64 and its residuals recomputed in f64; within the tolerance it
//! is kept (`gpu`), and so is an f64 shader's answer at the iteration cap
//! (the twin's own at that cap: `not_converged`, as the twin ends it); else
//! the CPU twin continues from it (`polished` when that meets the
//! tolerance); else the CPU twin solves the island again from its start
//! (`repaired`, with the status that gives).

use std::time::Instant;

use super::buffers::limits_for;
pub use super::friction_rounds::MAX_GPU_CONTACTS;
use super::friction_rounds::{
    controls_buffer, pack_friction_chunks, GpuIslandRun, RoundsJob, AT_CAP, FAILED, FIRST_TRIES,
};
use super::kernel::round_budget;
use super::{GpuContext, GpuSolveSettings, Precision};
use crate::cpu::batch::parallel_fill;
use crate::friction::projected::{check_warm, project_all, solve_checked};
use crate::friction::{FrictionProblem, ProjectedSettings, ProjectedSolution};
use crate::settings::GpuSettings;
use crate::{Error, Status};

/// Where an island's answer came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FrictionOrigin {
    /// The GPU's answer: within the tolerance in f64, or, from an f64
    /// shader, where it stopped at the iteration cap (status
    /// `not_converged`, as the CPU twin, whose iterates it repeats, would
    /// end; see [`solve_projected_on_gpu`]).
    Gpu,
    /// The GPU's answer missed the tolerance in f64; the CPU twin continued
    /// from it and met it.
    Polished,
    /// The GPU's answer missed the tolerance (or broke down) and continuing
    /// from it did not meet it: the CPU twin solved the island again from
    /// its start (its status says how that went).
    Repaired,
    /// More than [`MAX_GPU_CONTACTS`] contacts: solved by the CPU twin.
    CpuFallback,
    /// The problem failed its checks (status `InvalidInput`).
    Invalid,
}

impl FrictionOrigin {
    /// `gpu`, `polished`, `repaired`, `cpu_fallback` or `invalid`.
    pub fn name(self) -> &'static str {
        match self {
            FrictionOrigin::Gpu => "gpu",
            FrictionOrigin::Polished => "polished",
            FrictionOrigin::Repaired => "repaired",
            FrictionOrigin::CpuFallback => "cpu_fallback",
            FrictionOrigin::Invalid => "invalid",
        }
    }
}

/// What a GPU batch did, for the report.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ProjectedGpuFigures {
    /// Per island, in the caller's order: where its answer came from.
    pub origins: Vec<FrictionOrigin>,
    /// Per island: the GPU's iterations (0 where it did not run).
    pub gpu_iterations: Vec<u32>,
    /// Islands whose GPU answer was kept, polished, repaired; solved on the
    /// CPU for their size; invalid.
    pub gpu: usize,
    /// See [`FrictionOrigin::Polished`].
    pub polished: usize,
    /// See [`FrictionOrigin::Repaired`].
    pub repaired: usize,
    /// See [`FrictionOrigin::CpuFallback`].
    pub cpu_fallback: usize,
    /// See [`FrictionOrigin::Invalid`].
    pub invalid: usize,
    /// Chunks (batches split under the binding limits), dispatches, rounds.
    pub chunks: usize,
    /// Dispatches recorded.
    pub dispatches: usize,
    /// Rounds, summed over chunks.
    pub rounds: usize,
    /// Seconds of upload, rounds and readback.
    pub gpu_seconds: f64,
    /// Seconds of the f64 validation (and polish, repair, CPU fallback).
    pub validation_seconds: f64,
}

/// The tolerance the shaders and the validation use at `precision`.
pub(crate) fn tolerance_for(settings: &ProjectedSettings, precision: Precision) -> f64 {
    if precision == Precision::F64 {
        settings.f64_tolerance()
    } else {
        settings.f32_tolerance()
    }
}

/// Solves a batch of frictional islands by `settings.method` on the GPU of
/// `ctx`, each answer validated in f64 (see the module docs; an f64
/// shader's answer at the iteration cap is judged and kept: it is the
/// twin's answer at the same cap, and polishing or solving it again would
/// give the island two or three times the iterations the CPU path gives
/// it); `warm[i]`,
/// where given, is island i's start (3k). Results in the caller's order.
/// The tolerance is [`ProjectedSettings::f64_tolerance`] on an f64 context,
/// [`ProjectedSettings::f32_tolerance`] on an f32 one. `gpu` gives the
/// splitting limits and the round budget (its other fields are the
/// context's business). Errors: bad settings or warm starts (naming them);
/// device trouble as [`Error::Gpu`].
pub fn solve_projected_on_gpu(
    ctx: &GpuContext,
    problems: &[FrictionProblem],
    warm: Option<&[Vec<f64>]>,
    settings: &ProjectedSettings,
    gpu: &GpuSettings,
) -> Result<(Vec<ProjectedSolution>, ProjectedGpuFigures), Error> {
    solve_projected_on_gpu_against(ctx, problems, problems, warm, settings, gpu, false)
}

/// [`solve_projected_on_gpu`] where the shader iterates on `on_gpu[i]`
/// (the same island as `problems[i]`, assembled elsewhere: on the GPU, in
/// the shader's precision) while every answer is judged, polished and
/// repaired against `problems[i]`, the f64 oracle. Shapes (k, μ) must
/// match: a mismatch is an [`Error::Gpu`]. `checked`: the caller has
/// validated every problem (the door, which stops at the first bad one),
/// so they are not read once more for it (a pass over every W: 1.4 ms of
/// about 25 at 10,000 islands of k = 4 on lavapipe, measured).
pub(crate) fn solve_projected_on_gpu_against(
    ctx: &GpuContext,
    on_gpu: &[FrictionProblem],
    problems: &[FrictionProblem],
    warm: Option<&[Vec<f64>]>,
    settings: &ProjectedSettings,
    gpu: &GpuSettings,
    checked: bool,
) -> Result<(Vec<ProjectedSolution>, ProjectedGpuFigures), Error> {
    settings.validate()?;
    // The same slice (the usual call) is the same shape and validity; the
    // checks below cost a few ms per 10,000 islands, a tenth of the GPU's
    // whole time on lavapipe at k = 4 (measured), so they run once.
    let same = std::ptr::eq(on_gpu, problems);
    let same_shape = |(a, b): (&FrictionProblem, &FrictionProblem)| {
        let same_mu = a.mu.len() == b.mu.len()
            && a.mu
                .iter()
                .zip(&b.mu)
                .all(|(x, y)| x.to_bits() == y.to_bits());
        same_mu && a.q.len() == b.q.len() && a.w.len() == b.w.len()
    };
    if on_gpu.len() != problems.len() || !(same || on_gpu.iter().zip(problems).all(same_shape)) {
        return Err(Error::Gpu(
            "the GPU's frictional islands differ in shape from the CPU's".into(),
        ));
    }
    let r0 = |i: usize| warm.and_then(|w| w.get(i)).map(Vec::as_slice);
    let valid: Vec<bool> = problems
        .iter()
        .map(|p| checked || p.validate("problem").is_ok())
        .collect();
    if warm.is_some() {
        for (i, p) in problems.iter().enumerate() {
            // The island's name only for the error (a format per island costs).
            if valid[i] && check_warm("problem", p, r0(i)).is_err() {
                check_warm(&format!("problem {i}"), p, r0(i))?;
            }
        }
    }
    let gpu_problems = on_gpu;
    let on_gpu: Vec<usize> = (0..problems.len())
        .filter(|&i| valid[i] && (same || gpu_problems[i].validate("problem").is_ok()))
        .filter(|&i| problems[i].contacts() <= MAX_GPU_CONTACTS)
        .collect();
    let t_gpu = Instant::now();
    let (runs, mut figures) = run_on_gpu(ctx, gpu_problems, &on_gpu, warm, settings, gpu)?;
    figures.gpu_seconds = t_gpu.elapsed().as_secs_f64();

    let t_check = Instant::now();
    let tol = tolerance_for(settings, ctx.precision());
    figures.gpu_iterations = vec![0; problems.len()];
    // Per island its GPU run (taken by its check, which keeps its r), then
    // the check's answer and origin.
    type Slot = (
        Option<GpuIslandRun>,
        Option<(ProjectedSolution, FrictionOrigin)>,
    );
    let mut slots: Vec<Slot> = (0..problems.len()).map(|_| (None, None)).collect();
    for (&i, run) in on_gpu.iter().zip(runs) {
        figures.gpu_iterations[i] = run.state.iterations;
        slots[i].0 = Some(run);
    }
    // The f64 shaders repeat the twin's iterates (to rounding).
    let twin = ctx.precision() == Precision::F64;
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    parallel_fill(&mut slots, threads, |i, (run, out)| {
        let p = &problems[i];
        *out = Some(match run.take() {
            _ if !valid[i] => (ProjectedSolution::invalid(p), FrictionOrigin::Invalid),
            None => (
                solve_checked(p, r0(i), settings, tol),
                FrictionOrigin::CpuFallback,
            ),
            Some(run) => validate_friction_island(p, run, r0(i), settings, tol, twin),
        });
    });
    let answers = slots.into_iter().filter_map(|(_, out)| out);
    figures.validation_seconds = t_check.elapsed().as_secs_f64();
    let mut solutions = Vec::with_capacity(problems.len());
    for (s, origin) in answers {
        match origin {
            FrictionOrigin::Gpu => figures.gpu += 1,
            FrictionOrigin::Polished => figures.polished += 1,
            FrictionOrigin::Repaired => figures.repaired += 1,
            FrictionOrigin::CpuFallback => figures.cpu_fallback += 1,
            FrictionOrigin::Invalid => figures.invalid += 1,
        }
        figures.origins.push(origin);
        solutions.push(s);
    }
    Ok((solutions, figures))
}

/// The GPU stage alone: `problems[i]` for i in `indices` (each valid, k ≤
/// [`MAX_GPU_CONTACTS`], warm starts checked) through the shader, the raw
/// answers in the order of `indices`. The stage tests compare these with
/// the CPU twin.
pub(crate) fn run_on_gpu(
    ctx: &GpuContext,
    problems: &[FrictionProblem],
    indices: &[usize],
    warm: Option<&[Vec<f64>]>,
    settings: &ProjectedSettings,
    gpu: &GpuSettings,
) -> Result<(Vec<GpuIslandRun>, ProjectedGpuFigures), Error> {
    let mut figures = ProjectedGpuFigures::default();
    let mut runs: Vec<Option<GpuIslandRun>> = vec![None; problems.len()];
    if indices.is_empty() {
        return Ok((Vec::new(), figures));
    }
    let limits = GpuSolveSettings {
        max_binding_bytes: gpu.max_binding_bytes,
        max_workgroups: gpu.max_workgroups,
        round_budget: gpu.round_budget,
        ..GpuSolveSettings::default()
    };
    let (max_bytes, max_groups) = limits_for(ctx, &limits);
    let chunks = pack_friction_chunks(
        problems,
        indices,
        settings.method,
        max_bytes,
        ctx.precision().bytes(),
    );
    let pipelines = ctx.pipelines()?;
    let tol = tolerance_for(settings, ctx.precision());
    for chunk in &chunks {
        let run = ctx.scoped("friction iterations", || {
            let controls = controls_buffer(ctx, settings.max_iterations, tol, settings.relaxation);
            let job = RoundsJob {
                ctx,
                pipelines: &pipelines,
                method: settings.method,
                controls: &controls,
                budget: round_budget(ctx, &limits),
                // The caller's own round budget: every round at it.
                first_tries: gpu.round_budget.is_none().then_some(FIRST_TRIES),
                max_groups,
                max_iterations: settings.max_iterations,
            };
            job.run(chunk, problems, warm)
        })??;
        figures.chunks += 1;
        figures.dispatches += run.dispatches;
        figures.rounds += run.rounds;
        for (&i, r) in chunk.order.iter().zip(run.islands) {
            runs[i] = Some(r);
        }
    }
    let out = indices
        .iter()
        .map(|&i| {
            runs[i]
                .take()
                .ok_or_else(|| Error::Gpu("a frictional island got no result".into()))
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok((out, figures))
}

/// The f64 check of one GPU answer (see the module docs): kept, polished
/// or repaired. `r0` is the island's start, for a repair. `twin`: the
/// shader ran in f64, so an island it stopped at the iteration cap holds
/// the twin's answer at that cap, judged here and kept (`not_converged`
/// unless the f64 check finds it within the tolerance).
pub(crate) fn validate_friction_island(
    problem: &FrictionProblem,
    run: GpuIslandRun,
    r0: Option<&[f64]>,
    settings: &ProjectedSettings,
    tolerance: f64,
    twin: bool,
) -> (ProjectedSolution, FrictionOrigin) {
    let usable = run.state.status != FAILED && run.r.iter().all(|v| v.is_finite());
    if usable {
        let at_cap = twin && run.state.status == AT_CAP;
        let mut r = run.r;
        project_all(problem, &mut r);
        let mut kept = ProjectedSolution::judge(problem, r, tolerance, false);
        kept.iterations = run.state.iterations;
        kept.restarts = run.state.restarts;
        if kept.status.is_solution() || at_cap && kept.status == Status::NotConverged {
            return (kept, FrictionOrigin::Gpu);
        }
        let mut polished = solve_checked(problem, Some(&kept.r), settings, tolerance);
        if polished.status.is_solution() {
            polished.iterations += kept.iterations;
            polished.restarts += kept.restarts;
            return (polished, FrictionOrigin::Polished);
        }
    }
    (
        solve_checked(problem, r0, settings, tolerance),
        FrictionOrigin::Repaired,
    )
}
