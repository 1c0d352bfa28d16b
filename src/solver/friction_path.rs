//! The friction path of the [`Solver`](super::Solver): batches of
//! [`FrictionProblem`]s and the islands of scenes with friction, solved on
//! the CPU in f64 over every core by the solvers of [`crate::friction`]
//! ([`solve_on_cpu`]), or, for the projected methods with a GPU open (see
//! [`friction_on_gpu`]), assembled and iterated on the GPU with every
//! answer checked in f64 on the CPU ([`problems_on_gpu`],
//! [`islands_on_gpu`]); warm start from the last call's impulses keyed by
//! contact ids. The phases of a scene batch, in order: [`build`],
//! [`island_starts`], the solve, [`scene_reports`] (impulses),
//! [`remember_islands`].

use super::gpu_path::guarded;
use super::{ids_of, SolverView};
use crate::build::FrictionBuilt;
use crate::cpu::batch::parallel_map;
use crate::friction::assembly::{apply_friction_impulses, world_impulse, FrictionContactRows};
use crate::friction::solve::from_projected;
use crate::friction::{
    solve_friction_problem, FrictionMethod, FrictionProblem, FrictionSettings, FrictionSolution,
    ProjectedGpuFigures,
};
use crate::gpu::friction::solve_projected_on_gpu_against;
use crate::gpu::friction_assembly::assemble_built_friction_on_gpu;
use crate::gpu::GpuContext;
use crate::islands::Island;
use crate::report::{ContactImpulse, FrictionIslandReport, Report, SceneFriction, SceneReport};
use crate::scene::Scene;
use crate::settings::{GpuSettings, Settings};
use crate::warm::{reaction_entries, Warm};
use crate::Error;

/// Per problem of a batch, its start: its contacts' reactions remembered
/// under `keys` (None without keys or `settings.warm_start`, or where a
/// contact is not remembered).
pub(super) fn problem_starts(
    solver: &SolverView,
    keys: Option<&[Vec<Option<u64>>]>,
    count: usize,
) -> Vec<Option<Vec<f64>>> {
    match keys {
        Some(keys) if solver.settings.warm_start => {
            let memory = &solver.warm.reactions;
            keys.iter()
                .map(|k| memory.reactions(k.iter().copied()))
                .collect()
        }
        _ => vec![None; count],
    }
}

/// Every problem on the CPU in f64 over `threads` cores, each from its
/// start.
pub(super) fn solve_on_cpu(
    problems: &[FrictionProblem],
    starts: &[Option<Vec<f64>>],
    settings: &FrictionSettings,
    threads: usize,
) -> Vec<FrictionSolution> {
    parallel_map(problems.len(), threads, |i| {
        solve_friction_problem(&problems[i], starts[i].as_deref(), settings)
    })
}

/// A batch of checked problems on the GPU by the projected method, every
/// answer checked in f64; the GPU takes a warm start for all problems or
/// none. A panic inside wgpu becomes [`Error::Gpu`].
pub(super) fn problems_on_gpu(
    ctx: &GpuContext,
    problems: &[FrictionProblem],
    starts: &[Option<Vec<f64>>],
    settings: &FrictionSettings,
    gpu: &GpuSettings,
) -> Result<(Vec<FrictionSolution>, ProjectedGpuFigures), Error> {
    let all_warm: Option<Vec<Vec<f64>>> = starts.iter().cloned().collect();
    let ps = settings.projected_settings();
    let (solutions, figures) = guarded(|| {
        // Every problem was validated by the caller.
        solve_projected_on_gpu_against(ctx, problems, problems, all_warm.as_deref(), &ps, gpu, true)
    })?;
    let solutions = solutions
        .into_iter()
        .map(|x| from_projected(x, settings.method))
        .collect();
    Ok((solutions, figures))
}

/// The reports of a batch's answers, in the problems' order.
pub(super) fn problem_reports(
    problems: &[FrictionProblem],
    solved: Vec<FrictionSolution>,
    starts: &[Option<Vec<f64>>],
) -> Vec<FrictionIslandReport> {
    solved
        .into_iter()
        .zip(starts)
        .enumerate()
        .map(|(i, (solution, w))| FrictionIslandReport {
            scene: None,
            contacts: (0..problems[i].contacts()).collect(),
            warm_started: w.is_some(),
            solution,
        })
        .collect()
}

/// Records the reactions of a batch's solved problems under their
/// contacts' `keys`.
pub(super) fn remember_problems(
    warm: &mut Warm,
    keys: &[Vec<Option<u64>>],
    islands: &[FrictionIslandReport],
) {
    let solved = keys.iter().zip(islands);
    warm.reactions.record(
        solved
            .filter(|(_, isl)| isl.status().is_solution())
            .flat_map(|(k, isl)| reaction_entries(k.iter().copied(), &isl.solution.r)),
    );
}

/// Whether this call's frictional islands go to the GPU, and where
/// they go in words for the report: a projected method asked (the exact
/// Coulomb methods run on the CPU only) and a GPU open (`gpu_open`) without
/// `Backend::Auto`'s cost model (`cost_model`; explicit `Backend::Gpu` or
/// [`Solver::with_device`](super::Solver::with_device)). The cost model has
/// no figures of the friction iterations (it is calibrated on LCPs), so
/// `Auto` keeps them on the CPU, where they also run faster on this
/// machine's software adapter (BENCHMARKS.md, "GPU: cone projection
/// iterations").
pub(super) fn friction_on_gpu(
    gpu_open: bool,
    cost_model: bool,
    method: FrictionMethod,
) -> (bool, String) {
    let name = method.name();
    match (gpu_open, method.projected(), cost_model) {
        (false, _, _) => (false, format!("{name} on the CPU (no GPU open)")),
        (true, None, _) => (
            false,
            format!("{name} on the CPU (the exact Coulomb methods run on the CPU only)"),
        ),
        (true, Some(_), true) => (
            false,
            format!(
                "{name} on the CPU (backend auto: the cost model has no figures of the friction iterations)"
            ),
        ),
        (true, Some(_), false) => (true, format!("{name} on the GPU")),
    }
}

/// The build phase of checked scenes with friction, over `threads` cores:
/// per scene its islands and f64 rows on the CPU (the oracle) and its
/// islands' problems.
pub(super) fn build(
    scenes: &[&Scene],
    threads: usize,
) -> Vec<(FrictionBuilt, Vec<FrictionProblem>)> {
    parallel_map(scenes.len(), threads, |i| {
        let b = FrictionBuilt::new(scenes[i]);
        let problems = b.problems(scenes[i]);
        (b, problems)
    })
}

/// Every island's problem (moved out of `built`), in order, and its start:
/// its contacts' reactions remembered (with `settings.warm_start`).
pub(super) fn island_starts(
    solver: &SolverView,
    scenes: &[&Scene],
    built: &mut [(FrictionBuilt, Vec<FrictionProblem>)],
) -> (Vec<FrictionProblem>, Vec<Option<Vec<f64>>>) {
    let mut problems = Vec::new();
    let mut warm = Vec::new();
    for (s, b) in built.iter_mut().enumerate() {
        for island in &b.0.islands {
            let ids = ids_of(scenes[s], &island.contacts);
            let on = solver.settings.warm_start;
            warm.push(on.then(|| solver.warm.reactions.reactions(ids)).flatten());
        }
        problems.append(&mut b.1);
    }
    (problems, warm)
}

/// The frictional islands of `scenes` (in order, `problems` their f64
/// assembly, `warm` their starts) on the GPU: assembled there
/// ([`assemble_built_friction_on_gpu`]; a scene too large for one buffer
/// makes the CPU's assembly the shader's input), iterated there by the
/// projected method, every answer judged in f64 against `problems` and
/// polished or repaired on the CPU where it misses the tolerance.
/// Returns the solutions, the GPU's figures, and where the assembly ran
/// in words (with the largest |W_gpu − W_cpu| / (1 + |W_cpu|)). A panic
/// inside wgpu becomes [`Error::Gpu`].
pub(super) fn islands_on_gpu(
    ctx: &GpuContext,
    settings: &Settings,
    scenes: &[&Scene],
    built: &[(FrictionBuilt, Vec<FrictionProblem>)],
    problems: &[FrictionProblem],
    warm: &[Option<Vec<f64>>],
) -> Result<(Vec<FrictionSolution>, ProjectedGpuFigures, String), Error> {
    guarded(|| {
        let islands: Vec<&[Island]> = built.iter().map(|b| b.0.islands.as_slice()).collect();
        assembled_islands_on_gpu(ctx, settings, scenes, &islands, problems, warm)
    })
}

/// [`islands_on_gpu`] without the guard.
fn assembled_islands_on_gpu(
    ctx: &GpuContext,
    settings: &Settings,
    scenes: &[&Scene],
    islands: &[&[Island]],
    problems: &[FrictionProblem],
    warm: &[Option<Vec<f64>>],
) -> Result<(Vec<FrictionSolution>, ProjectedGpuFigures, String), Error> {
    let assembled = assemble_built_friction_on_gpu(ctx, scenes, islands, &settings.gpu);
    let (on_gpu, assembly) = match assembled {
        Ok(per_scene) => {
            let on_gpu: Vec<FrictionProblem> =
                per_scene.into_iter().flatten().map(|f| f.problem).collect();
            let deviation = on_gpu
                .iter()
                .zip(problems)
                .flat_map(|(g, c)| g.w.iter().zip(&c.w).chain(g.q.iter().zip(&c.q)))
                .map(|(g, c)| (g - c).abs() / (1.0 + c.abs()))
                .fold(0.0, f64::max);
            let how = format!(
                "assembled on the GPU (largest deviation from the f64 twin {deviation:.1e})"
            );
            (on_gpu, how)
        }
        Err(Error::Unsupported(why)) => {
            (problems.to_vec(), format!("assembled on the CPU ({why})"))
        }
        Err(e) => return Err(e),
    };
    // The GPU takes a start for every island or none: zero (the
    // default start) where an island has none.
    let all_warm: Option<Vec<Vec<f64>>> = warm.iter().any(Option::is_some).then(|| {
        warm.iter()
            .zip(problems)
            .map(|(w, p)| w.clone().unwrap_or_else(|| vec![0.0; p.dim()]))
            .collect()
    });
    let s = settings.friction();
    let (solutions, figures) = solve_projected_on_gpu_against(
        ctx,
        &on_gpu,
        problems,
        all_warm.as_deref(),
        &s.projected_settings(),
        &settings.gpu,
        false,
    )?;
    let solutions = solutions
        .into_iter()
        .map(|x| from_projected(x, s.method))
        .collect();
    Ok((solutions, figures, assembly))
}

/// Per scene its report (impulses, velocities after, contacts' parts)
/// and per island its report, from the islands' solutions in order
/// (impulses over `threads` cores).
pub(super) fn scene_reports(
    scenes: &[&Scene],
    built: Vec<(FrictionBuilt, Vec<FrictionProblem>)>,
    solved: Vec<FrictionSolution>,
    warm: &[Option<Vec<f64>>],
    threads: usize,
) -> (Vec<SceneReport>, Vec<FrictionIslandReport>) {
    let mut islands = Vec::with_capacity(solved.len());
    // Per scene the contacts' r and u and its islands' range (in order),
    // then the scenes' reports over the cores.
    let mut local = Vec::with_capacity(scenes.len());
    let mut solved = solved.into_iter().zip(warm);
    let mut built = built;
    for (s, (scene, (b, _))) in scenes.iter().zip(&mut built).enumerate() {
        let first = islands.len();
        let mut r = vec![[0.0; 3]; scene.contacts.len()];
        let mut u = vec![[0.0; 3]; scene.contacts.len()];
        for island in b.islands.iter_mut() {
            let (solution, w) = solved.next().expect("one result per island");
            for (i, &c) in island.contacts.iter().enumerate() {
                r[c].copy_from_slice(&solution.r[3 * i..3 * i + 3]);
                u[c].copy_from_slice(&solution.u[3 * i..3 * i + 3]);
            }
            islands.push(FrictionIslandReport {
                scene: Some(s),
                contacts: std::mem::take(&mut island.contacts),
                warm_started: w.is_some(),
                solution,
            });
        }
        local.push((r, u, first..islands.len()));
    }
    let out = parallel_map(scenes.len(), threads, |s| {
        let (scene, rows, (r, u, range)) = (scenes[s], &built[s].0.rows, &local[s]);
        SceneReport {
            impulses: r.iter().map(|ri| ri[0]).collect(),
            bodies: apply_friction_impulses(scene, rows, r),
            islands: 0..0,
            friction: Some(SceneFriction {
                contacts: (0..r.len())
                    .map(|c| contact_impulse(&rows[c], r[c], u[c]))
                    .collect(),
                islands: range.clone(),
            }),
        }
    });
    (out, islands)
}

/// Records the reactions of the solved frictional islands of `scenes`
/// under their contacts' ids.
pub(super) fn remember_islands(
    warm: &mut Warm,
    scenes: &[&Scene],
    islands: &[FrictionIslandReport],
) {
    let solved = islands.iter().filter(|i| i.status().is_solution());
    warm.reactions.record(solved.flat_map(|isl| {
        let s = scenes[isl.scene.unwrap_or(0)];
        let ids = ids_of(s, &isl.contacts);
        reaction_entries(ids, &isl.solution.r)
    }));
}

/// The GPU's counts, seconds and figures added into `report`.
pub(super) fn add_gpu_figures(report: &mut Report, f: &ProjectedGpuFigures) {
    report.counts.polished += f.polished;
    report.counts.repaired += f.repaired;
    report.counts.cpu_fallback += f.cpu_fallback;
    report.timings.gpu += f.gpu_seconds;
    report.timings.validation += f.validation_seconds;
    let g = report.gpu.get_or_insert_with(Default::default);
    g.chunks += f.chunks;
    g.dispatches += f.dispatches;
    g.rounds += f.rounds;
}

/// Where the GPU batch's answers came from, in words.
pub(super) fn origin_counts(f: &ProjectedGpuFigures) -> String {
    format!(
        "{} kept from the GPU, {} polished and {} repaired on the CPU, {} on the CPU for their size",
        f.gpu, f.polished, f.repaired, f.cpu_fallback
    )
}

/// A contact's impulse with its parts, from its rows and local reaction.
pub(super) fn contact_impulse(
    rows: &FrictionContactRows,
    r: [f64; 3],
    u: [f64; 3],
) -> ContactImpulse {
    ContactImpulse {
        impulse: world_impulse(rows, r).to_array(),
        normal: r[0],
        tangential: [r[1], r[2]],
        tangential_impulse: world_impulse(rows, [0.0, r[1], r[2]]).to_array(),
        tangents: [rows.frame[1].to_array(), rows.frame[2].to_array()],
        velocity: u,
    }
}
