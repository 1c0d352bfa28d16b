//! The GPU path of the [`Solver`](super::Solver): LCP batches
//! ([`lcps_on_gpu`]) and the islands of built scenes ([`scenes_on_gpu`])
//! solved on the device (`crate::gpu`), every answer validated on the CPU
//! in f64; `all_solutions` screens every basis on the device
//! ([`all_solutions_lcps_on_gpu`], [`all_solutions_scenes_on_gpu`]).

use super::SolverView;
use crate::build::Built;
use crate::gpu::{self, GpuContext};
use crate::lcp::Lcp;
use crate::report::{Device, GpuFigures, Report, SolvePath};
use crate::scene::Scene;
use crate::settings::Method;
use crate::Error;

use super::cpu_path::{check, lcp_islands, scenes_with, solve_on_cpu, Solved};
use crate::cpu::batch::parallel_map;
use crate::cpu::enumeration::enumerate_screened;
use crate::gpu::all_bases::{screen_all_bases, ScreenFigures, Screened};
use crate::gpu::MAX_GPU_N;

/// LCPs on the GPU, each checked and (with `keys` and
/// `settings.warm_start`) given its warm basis in the host's parallel
/// pass; an error names the first bad problem. A panic inside wgpu
/// becomes [`Error::Gpu`].
pub(super) fn lcps_on_gpu(
    solver: &SolverView,
    ctx: &GpuContext,
    lcps: &[Lcp],
    keys: Option<&[&[u64]]>,
) -> Result<Report, Error> {
    let mut gs = solver.settings.gpu_solve();
    gs.threads = solver.threads;
    let warm = |i: usize| keys.and_then(|k| solver.warm_basis(k[i]));
    let r = guarded(|| gpu::solve_lcp_batch_warm(ctx, lcps, &warm, &gs))?;
    if r.counts.invalid > 0 {
        for (i, lcp) in lcps.iter().enumerate() {
            lcp.validate(&format!("problem {i}"))?;
        }
    }
    Ok(gpu_report(solver, ctx, r))
}

/// Checked scenes on the GPU, from what was built of them. `warm`:
/// per scene, per island, the warm basis (empty: none).
pub(super) fn scenes_on_gpu(
    solver: &SolverView,
    ctx: &GpuContext,
    scenes: &[&Scene],
    built: &[Built],
    warm: &[Vec<Option<u32>>],
) -> Result<Report, Error> {
    let mut gs = solver.settings.gpu_solve();
    gs.threads = solver.threads;
    let warm = (!warm.is_empty()).then_some(warm);
    let r = guarded(|| gpu::solve_scenes_warm(ctx, scenes, built, warm, &gs))?;
    Ok(gpu_report(solver, ctx, r))
}

/// `all_solutions` for LCPs on the GPU ([`all_solutions_on_gpu`]).
pub(super) fn all_solutions_lcps_on_gpu(
    solver: &SolverView,
    ctx: &GpuContext,
    lcps: &[Lcp],
) -> Result<Report, Error> {
    for (i, lcp) in lcps.iter().enumerate() {
        // The item's name is formatted only for the error.
        if lcp.validate("problem").is_err() {
            lcp.validate(&format!("problem {i}"))?;
        }
    }
    let refs: Vec<&Lcp> = lcps.iter().collect();
    let t = std::time::Instant::now();
    let (solved, figures) = all_solutions_on_gpu(solver, ctx, &refs)?;
    let mut islands = lcp_islands(lcps, solved);
    check(&mut islands, solver.settings.tolerance);
    let mut r = solver.report(islands, Vec::new(), Device::of(ctx));
    r.timings.solve = t.elapsed().as_secs_f64();
    add_screen_figures(&mut r, figures);
    Ok(r)
}

/// `all_solutions` for scenes: islands and assembly on the CPU, every
/// basis screened on the GPU ([`all_solutions_on_gpu`]).
pub(super) fn all_solutions_scenes_on_gpu(
    solver: &SolverView,
    ctx: &GpuContext,
    scenes: &[&Scene],
    built: &[Built],
) -> Result<Report, Error> {
    let mut figures = ScreenFigures::default();
    let mut r = scenes_with(solver, scenes, built, |_, lcps| {
        let (solved, f) = all_solutions_on_gpu(solver, ctx, lcps)?;
        figures = f;
        Ok(solved)
    })?;
    r.device = Device::of(ctx);
    add_screen_figures(&mut r, figures);
    Ok(r)
}

/// Every basis of every island of n ≤ 16 screened on the GPU
/// (`shaders/enumeration_all.wgsl`), the flagged bases re-solved in f64
/// and decided by the CPU enumeration's rule, so that statuses, solution
/// sets and chosen bases are the CPU's; larger islands on the CPU
/// (enumeration up to n = 20, Lemke above). A panic inside wgpu becomes
/// [`Error::Gpu`].
fn all_solutions_on_gpu(
    solver: &SolverView,
    ctx: &GpuContext,
    lcps: &[&Lcp],
) -> Result<(Vec<Solved>, ScreenFigures), Error> {
    let gs = solver.settings.gpu_solve();
    let small: Vec<usize> = (0..lcps.len())
        .filter(|&i| lcps[i].n() <= MAX_GPU_N)
        .collect();
    let on_gpu: Vec<&Lcp> = small.iter().map(|&i| lcps[i]).collect();
    let (screened, figures) = guarded(|| screen_all_bases(ctx, &on_gpu, &gs))?;
    let mut of: Vec<Option<Screened>> = vec![None; lcps.len()];
    for (i, s) in small.into_iter().zip(screened) {
        of[i] = Some(s);
    }
    let e = solver.settings.enumeration();
    let solved = parallel_map(lcps.len(), solver.threads, |i| match &of[i] {
        Some(s) => {
            let mut candidates = s.candidates.clone();
            enumerate_screened(lcps[i], &e, &mut candidates, s.trusted_singular)
                .map(|sol| (Method::Enumeration, SolvePath::EnumeratedGpu, sol))
        }
        None => Ok(solve_on_cpu(lcps[i], None, solver.settings)),
    });
    Ok((solved.into_iter().collect::<Result<_, _>>()?, figures))
}

/// A GPU backend's report as the solver gives it: the device and why.
fn gpu_report(solver: &SolverView, ctx: &GpuContext, mut r: Report) -> Report {
    r.device = Device::of(ctx);
    r.choice = solver.choice.to_string();
    r
}

/// The screen's figures in a report: every GPU-screened island was decided
/// in f64 (polished), the others solved on the CPU.
fn add_screen_figures(r: &mut Report, f: ScreenFigures) {
    r.counts.polished = r.counts.enumerated_gpu;
    r.counts.cpu_fallback = r.islands.len() - r.counts.enumerated_gpu;
    r.timings.gpu = f.seconds;
    r.gpu = Some(GpuFigures {
        chunks: f.chunks,
        dispatches: f.dispatches,
        ..GpuFigures::default()
    });
}

/// Runs a GPU call, turning a panic inside it into [`Error::Gpu`]: on a lost
/// device wgpu itself panics in places (`create_buffer_init` cannot map the
/// new buffer), and a lost device is device trouble like any other. The
/// device is dropped afterwards, so nothing it left half-done is used again.
pub(super) fn guarded<T>(f: impl FnOnce() -> Result<T, Error>) -> Result<T, Error> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).unwrap_or_else(|p| {
        let msg = p
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| p.downcast_ref::<&str>().copied())
            .unwrap_or("no message");
        Err(Error::Gpu(format!(
            "the GPU path panicked (device lost?): {msg}"
        )))
    })
}
