//! The friction path of the [`Solver`]: batches of [`FrictionProblem`]s and
//! the islands of scenes with friction, solved on the CPU in f64 over every
//! core by the solvers of [`crate::friction`], or, for the projected
//! methods with a GPU open (see `Solver::friction_on_gpu`), assembled and
//! iterated on the GPU with every answer checked in f64 on the CPU; warm
//! start from the last call's impulses keyed by contact ids.

use std::time::Instant;

use super::{cpu_device, ids_of, Solver};
use crate::build::FrictionBuilt;
use crate::cpu::batch::parallel_map;
use crate::friction::assembly::{apply_friction_impulses, world_impulse, FrictionContactRows};
use crate::friction::solve::from_projected;
use crate::friction::{
    solve_friction_problem, FrictionMethod, FrictionProblem, FrictionSolution, ProjectedGpuFigures,
};
use crate::gpu::friction::solve_projected_on_gpu_against;
use crate::gpu::friction_assembly::assemble_built_friction_on_gpu;
use crate::gpu::GpuContext;
use crate::islands::Island;
use crate::report::{ContactImpulse, FrictionIslandReport, Report, SceneFriction, SceneReport};
use crate::scene::Scene;
use crate::warm::reaction_entries;
use crate::Error;

impl Solver {
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
        if ids.len() != problems.len() {
            return Err(Error::invalid(
                "ids",
                "len",
                format!("{} id lists for {} problems", ids.len(), problems.len()),
            ));
        }
        for (i, (p, k)) in problems.iter().zip(ids).enumerate() {
            if k.len() != p.contacts() {
                return Err(Error::invalid(
                    format!("problem {i}"),
                    "ids",
                    format!("{} ids for {} contacts", k.len(), p.contacts()),
                ));
            }
        }
        let keys: Vec<Vec<Option<u64>>> = ids
            .iter()
            .map(|k| k.iter().copied().map(Some).collect())
            .collect();
        self.solve_friction_warm(problems, Some(&keys))
    }

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
        let warm: Vec<Option<Vec<f64>>> = match keys {
            Some(keys) if self.settings.warm_start => {
                let memory = &self.warm.reactions;
                keys.iter()
                    .map(|k| memory.reactions(k.iter().copied()))
                    .collect()
            }
            _ => vec![None; problems.len()],
        };
        let s = self.settings.friction();
        let threads = self.threads;
        let cpu = |warm: &[Option<Vec<f64>>]| {
            parallel_map(problems.len(), threads, |i| {
                solve_friction_problem(&problems[i], warm[i].as_deref(), &s)
            })
        };
        // The projected methods run on the GPU where one is open (every
        // answer checked in f64 there); the exact Coulomb methods on the CPU.
        let mut figures = None;
        let (use_gpu, went) = self.friction_on_gpu(s.method);
        let solved = match self.gpu.clone().filter(|_| use_gpu) {
            Some(ctx) => {
                // The GPU takes a warm start for all problems or none.
                let all_warm: Option<Vec<Vec<f64>>> = warm.iter().cloned().collect();
                let ps = s.projected_settings();
                let on_gpu = super::gpu_path::guarded(|| {
                    // Every problem was validated above.
                    solve_projected_on_gpu_against(
                        &ctx,
                        problems,
                        problems,
                        all_warm.as_deref(),
                        &ps,
                        &self.settings.gpu,
                        true,
                    )
                });
                match on_gpu {
                    Ok((sols, f)) => {
                        figures = Some(f);
                        sols.into_iter()
                            .map(|x| from_projected(x, s.method))
                            .collect()
                    }
                    Err(Error::Gpu(why)) => {
                        self.fall_back(why);
                        cpu(&warm)
                    }
                    Err(e) => return Err(e),
                }
            }
            None => cpu(&warm),
        };
        let islands: Vec<FrictionIslandReport> = solved
            .into_iter()
            .zip(&warm)
            .enumerate()
            .map(|(i, (solution, w))| FrictionIslandReport {
                scene: None,
                contacts: (0..problems[i].contacts()).collect(),
                warm_started: w.is_some(),
                solution,
            })
            .collect();
        if let (Some(keys), true) = (keys, self.settings.warm_start) {
            let solved = keys.iter().zip(&islands);
            self.warm.reactions.record(
                solved
                    .filter(|(_, isl)| isl.status().is_solution())
                    .flat_map(|(k, isl)| reaction_entries(k.iter().copied(), &isl.solution.r)),
            );
        }
        let device = match figures {
            Some(_) => self.device(),
            None => cpu_device(self.threads),
        };
        let choice = match (&figures, self.fallback.is_some() && use_gpu) {
            (Some(f), _) => format!("{}; friction: {went}, {}", self.choice, origin_counts(f)),
            (None, true) => format!("{}; friction: on the CPU (the GPU failed)", self.choice),
            (None, false) => format!("{}; friction: {went}", self.choice),
        };
        let mut report = self.empty_report(device);
        report.choice = choice;
        report.timings.solve = start.elapsed().as_secs_f64();
        if let Some(f) = figures {
            add_gpu_figures(&mut report, &f);
        }
        report.set_friction(islands);
        report.timings.total = start.elapsed().as_secs_f64();
        Ok(report)
    }

    /// Checked scenes, some with friction: those without go through the LCP
    /// path (GPU or CPU), those with friction through the friction path; the
    /// two reports merged in the scenes' order.
    pub(super) fn scenes_with_friction(&mut self, scenes: &[Scene]) -> Result<Report, Error> {
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

    /// Whether this call's frictional islands go to the GPU, and where
    /// they go in words for the report: a projected method asked (the exact
    /// Coulomb methods run on the CPU only) and a GPU open without
    /// `Backend::Auto`'s cost model (explicit `Backend::Gpu` or
    /// [`Solver::with_device`]). The cost model has no figures of the
    /// friction iterations (it is calibrated on LCPs), so `Auto` keeps them
    /// on the CPU, where they also run faster on this machine's software
    /// adapter (BENCHMARKS.md, "GPU: cone projection iterations").
    pub(super) fn friction_on_gpu(&self, method: FrictionMethod) -> (bool, String) {
        let name = method.name();
        match (&self.gpu, method.projected(), &self.cost) {
            (None, _, _) => (false, format!("{name} on the CPU (no GPU open)")),
            (Some(_), None, _) => (
                false,
                format!("{name} on the CPU (the exact Coulomb methods run on the CPU only)"),
            ),
            (Some(_), Some(_), Some(_)) => (
                false,
                format!(
                    "{name} on the CPU (backend auto: the cost model has no figures of the friction iterations)"
                ),
            ),
            (Some(_), Some(_), None) => (true, format!("{name} on the GPU")),
        }
    }

    /// The friction path for checked scenes with friction, in phases (added
    /// to `report.timings`): build (islands and the f64 assembly on the
    /// CPU, the oracle), solve (on the GPU where [`Self::friction_on_gpu`]
    /// says so, see [`Self::friction_islands_on_gpu`]; else every island
    /// over the cores), impulses; the reactions remembered. `report` (empty)
    /// gets the scenes and their frictional islands (scene indices into
    /// `scenes`); its choice gains where the friction went, its counts and
    /// GPU figures what the GPU did.
    fn friction_scenes(&mut self, scenes: &[&Scene], report: &mut Report) -> Result<(), Error> {
        let t = Instant::now();
        let mut built: Vec<(FrictionBuilt, Vec<FrictionProblem>)> =
            parallel_map(scenes.len(), self.threads, |i| {
                let b = FrictionBuilt::new(scenes[i]);
                let problems = b.problems(scenes[i]);
                (b, problems)
            });
        report.timings.build += t.elapsed().as_secs_f64();
        let t = Instant::now();
        let mut problems = Vec::new();
        let mut warm = Vec::new();
        for (s, b) in built.iter_mut().enumerate() {
            for island in &b.0.islands {
                let ids = ids_of(scenes[s], &island.contacts);
                let on = self.settings.warm_start;
                warm.push(on.then(|| self.warm.reactions.reactions(ids)).flatten());
            }
            problems.append(&mut b.1);
        }
        let settings = self.settings.friction();
        let (use_gpu, mut went) = self.friction_on_gpu(settings.method);
        let mut solved = None;
        if let Some(ctx) = self.gpu.clone().filter(|_| use_gpu && !problems.is_empty()) {
            let on_gpu = super::gpu_path::guarded(|| {
                let islands: Vec<&[Island]> =
                    built.iter().map(|b| b.0.islands.as_slice()).collect();
                self.friction_islands_on_gpu(&ctx, scenes, &islands, &problems, &warm)
            });
            match on_gpu {
                Ok((solutions, figures, assembly)) => {
                    went = format!("{went}, {assembly}, {}", origin_counts(&figures));
                    add_gpu_figures(report, &figures);
                    report.device = self.device();
                    solved = Some(solutions);
                }
                Err(Error::Gpu(why)) => {
                    self.fall_back(why);
                    report.fallback = self.fallback.clone();
                    went = format!("{} on the CPU (the GPU failed)", settings.method.name());
                }
                Err(e) => return Err(e),
            }
        }
        let solved = solved.unwrap_or_else(|| {
            parallel_map(problems.len(), self.threads, |j| {
                solve_friction_problem(&problems[j], warm[j].as_deref(), &settings)
            })
        });
        report.choice = format!("{}; friction: {went}", report.choice);
        report.timings.solve += t.elapsed().as_secs_f64();
        let t = Instant::now();
        let (scene_reports, islands) = self.friction_scene_reports(scenes, built, solved, &warm);
        report.timings.impulses += t.elapsed().as_secs_f64();
        if self.settings.warm_start {
            let solved = islands.iter().filter(|i| i.status().is_solution());
            self.warm.reactions.record(solved.flat_map(|isl| {
                let s = scenes[isl.scene.unwrap_or(0)];
                let ids = ids_of(s, &isl.contacts);
                reaction_entries(ids, &isl.solution.r)
            }));
        }
        report.scenes = scene_reports;
        report.set_friction(islands);
        Ok(())
    }

    /// The frictional islands of `scenes` (in order, `problems` their f64
    /// assembly, `warm` their starts) on the GPU: assembled there
    /// ([`assemble_built_friction_on_gpu`]; a scene too large for one buffer
    /// makes the CPU's assembly the shader's input), iterated there by the
    /// projected method, every answer judged in f64 against `problems` and
    /// polished or repaired on the CPU where it misses the tolerance.
    /// Returns the solutions, the GPU's figures, and where the assembly ran
    /// in words (with the largest |W_gpu − W_cpu| / (1 + |W_cpu|)).
    fn friction_islands_on_gpu(
        &self,
        ctx: &GpuContext,
        scenes: &[&Scene],
        islands: &[&[Island]],
        problems: &[FrictionProblem],
        warm: &[Option<Vec<f64>>],
    ) -> Result<(Vec<FrictionSolution>, ProjectedGpuFigures, String), Error> {
        let assembled = assemble_built_friction_on_gpu(ctx, scenes, islands, &self.settings.gpu);
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
        let s = self.settings.friction();
        let (solutions, figures) = solve_projected_on_gpu_against(
            ctx,
            &on_gpu,
            problems,
            all_warm.as_deref(),
            &s.projected_settings(),
            &self.settings.gpu,
            false,
        )?;
        let solutions = solutions
            .into_iter()
            .map(|x| from_projected(x, s.method))
            .collect();
        Ok((solutions, figures, assembly))
    }

    /// Per scene its report (impulses, velocities after, contacts' parts)
    /// and per island its report, from the islands' solutions in order.
    fn friction_scene_reports(
        &self,
        scenes: &[&Scene],
        built: Vec<(FrictionBuilt, Vec<FrictionProblem>)>,
        solved: Vec<FrictionSolution>,
        warm: &[Option<Vec<f64>>],
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
        let out = parallel_map(scenes.len(), self.threads, |s| {
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
}

/// The GPU's counts, seconds and figures added into `report`.
fn add_gpu_figures(report: &mut Report, f: &ProjectedGpuFigures) {
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
fn origin_counts(f: &ProjectedGpuFigures) -> String {
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
