//! The friction path of the [`Solver`]: batches of [`FrictionProblem`]s and
//! the islands of scenes with friction, solved on the CPU in f64 over every
//! core by the exact Coulomb solvers of [`crate::friction`], with warm start
//! from the last call's impulses keyed by contact ids.

use std::collections::HashMap;
use std::time::Instant;

use super::Solver;
use crate::cpu::batch::parallel_map;
use crate::friction::assembly::{
    apply_friction_impulses, assemble_friction_contacts, assemble_friction_island, world_impulse,
    FrictionContactRows,
};
use crate::friction::solve::from_projected;
use crate::friction::{solve_friction_problem, solve_projected_on_gpu, FrictionProblem};
use crate::islands::{find_islands, Island};
use crate::report::{ContactImpulse, FrictionIslandReport, Report, SceneFriction, SceneReport};
use crate::scene::Scene;
use crate::Error;

/// The reactions (r_n, r_t₁, r_t₂) of the last call's solved frictional
/// islands, by contact id.
#[derive(Clone, Debug, Default)]
pub(super) struct FrictionWarm(HashMap<u64, [f64; 3]>);

impl FrictionWarm {
    /// The warm start of contacts `ids` (one per contact; None for a contact
    /// without id): the remembered reaction, zero for a contact not
    /// remembered; None when no contact is remembered.
    fn start(&self, ids: &[Option<u64>]) -> Option<Vec<f64>> {
        let mut any = false;
        let r = ids
            .iter()
            .flat_map(|id| {
                let r = id.and_then(|id| self.0.get(&id)).copied();
                any |= r.is_some();
                r.unwrap_or([0.0; 3])
            })
            .collect();
        any.then_some(r)
    }

    /// Records a solved island's reactions under its contacts' ids.
    fn record(&mut self, ids: &[Option<u64>], isl: &FrictionIslandReport) {
        if !isl.status().is_solution() {
            return;
        }
        for (i, id) in ids.iter().enumerate() {
            if let Some(id) = id {
                let r = &isl.solution.r;
                self.0.insert(*id, [r[3 * i], r[3 * i + 1], r[3 * i + 2]]);
            }
        }
    }
}

impl Solver {
    /// Solves a batch of frictional problems, in the caller's order, on the
    /// CPU in f64 over every core with `settings.friction_method`; the
    /// results are in [`Report::friction`]. Every problem is checked first
    /// (an error names the first bad one and its field).
    pub fn solve_friction(&mut self, problems: &[FrictionProblem]) -> Result<Report, Error> {
        self.solve_friction_warm(problems, None)
    }

    /// [`Solver::solve_friction`] with the caller's contact ids, one per
    /// contact of each problem (`ids[i].len() == problems[i].contacts()`),
    /// stable across calls: with `settings.warm_start` each contact starts
    /// from its reaction of the last call.
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
                keys.iter().map(|k| self.friction_warm.start(k)).collect()
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
        let solved = match (self.gpu.clone(), s.method.projected()) {
            (Some(ctx), Some(_)) => {
                // The GPU takes a warm start for all problems or none.
                let all_warm: Option<Vec<Vec<f64>>> = warm.iter().cloned().collect();
                let ps = s.projected_settings();
                let on_gpu = super::gpu_path::guarded(|| {
                    solve_projected_on_gpu(
                        &ctx,
                        problems,
                        all_warm.as_deref(),
                        &ps,
                        &self.settings.gpu,
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
            _ => cpu(&warm),
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
            for (k, isl) in keys.iter().zip(&islands) {
                self.friction_warm.record(k, isl);
            }
        }
        let device = match figures {
            Some(_) => self.device(),
            None => self.cpu_device(),
        };
        let mut report = Report::new(Vec::new(), Vec::new(), device, self.choice.clone());
        report.fallback = self.fallback.clone();
        report.timings.solve = start.elapsed().as_secs_f64();
        if let Some(f) = figures {
            report.counts.polished = f.polished;
            report.counts.repaired = f.repaired;
            report.counts.cpu_fallback = f.cpu_fallback;
            report.timings.gpu = f.gpu_seconds;
            report.timings.validation = f.validation_seconds;
            report.gpu = Some(crate::report::GpuFigures {
                chunks: f.chunks,
                dispatches: f.dispatches,
                rounds: f.rounds,
                ..Default::default()
            });
        }
        report.set_friction(islands);
        report.timings.total = start.elapsed().as_secs_f64();
        Ok(report)
    }

    /// Checked scenes, some with friction: those without go through the LCP
    /// path (GPU or CPU), those with friction through the friction path; the
    /// report keeps the scenes' order.
    pub(super) fn scenes_with_friction(&mut self, scenes: &[Scene]) -> Result<Report, Error> {
        let (with, without): (Vec<usize>, Vec<usize>) =
            (0..scenes.len()).partition(|&i| scenes[i].has_friction());
        let plain: Vec<Scene> = without.iter().map(|&i| scenes[i].clone()).collect();
        let mut report = if plain.is_empty() {
            let mut r = Report::new(Vec::new(), Vec::new(), self.device(), self.choice.clone());
            r.fallback = self.fallback.clone();
            r
        } else {
            self.frictionless_scenes(&plain)?
        };
        for isl in &mut report.islands {
            isl.scene = isl.scene.map(|s| without[s]);
        }
        let frictional: Vec<&Scene> = with.iter().map(|&i| &scenes[i]).collect();
        let (mut scene_reports, mut islands) =
            self.friction_scenes_on_cpu(&frictional, &mut report);
        for isl in &mut islands {
            isl.scene = isl.scene.map(|s| with[s]);
        }
        // Back into the caller's order.
        let mut plain_reports = std::mem::take(&mut report.scenes).into_iter();
        let mut friction_reports = scene_reports.drain(..);
        let lcp_islands = report.islands.len();
        report.scenes = scenes
            .iter()
            .map(|s| match s.has_friction() {
                true => friction_reports
                    .next()
                    .expect("one report per scene with friction"),
                false => plain_reports
                    .next()
                    .expect("one report per scene without friction"),
            })
            .collect();
        // A scene with friction has no LCP islands: an empty range in place.
        let mut next = 0;
        for sr in &mut report.scenes {
            if sr.friction.is_some() {
                sr.islands = next..next;
            } else {
                next = sr.islands.end;
            }
        }
        debug_assert!(next <= lcp_islands);
        if self.settings.warm_start {
            for isl in &islands {
                let s = &scenes[isl.scene.unwrap_or(0)];
                let ids: Vec<Option<u64>> =
                    isl.contacts.iter().map(|&c| s.contacts[c].id).collect();
                self.friction_warm.record(&ids, isl);
            }
        }
        report.set_friction(islands);
        Ok(report)
    }

    /// The friction path for checked scenes with friction, in phases (added
    /// to `report.timings`): build (islands and assembly), solve (every
    /// island over the cores), impulses. Scene indices are into `scenes`.
    fn friction_scenes_on_cpu(
        &self,
        scenes: &[&Scene],
        report: &mut Report,
    ) -> (Vec<SceneReport>, Vec<FrictionIslandReport>) {
        let t = Instant::now();
        let built: Vec<(Vec<Island>, Vec<FrictionContactRows>, Vec<FrictionProblem>)> =
            parallel_map(scenes.len(), self.threads, |i| {
                let s = scenes[i];
                let islands = find_islands(s);
                let rows = assemble_friction_contacts(s);
                let problems = islands
                    .iter()
                    .map(|isl| assemble_friction_island(s, &rows, isl))
                    .collect();
                (islands, rows, problems)
            });
        report.timings.build += t.elapsed().as_secs_f64();
        let t = Instant::now();
        let index: Vec<(usize, usize)> = built
            .iter()
            .enumerate()
            .flat_map(|(s, b)| (0..b.2.len()).map(move |k| (s, k)))
            .collect();
        let settings = self.settings.friction();
        let solved = parallel_map(index.len(), self.threads, |j| {
            let (s, k) = index[j];
            let warm = self.settings.warm_start.then(|| {
                let ids: Vec<Option<u64>> = built[s].0[k]
                    .contacts
                    .iter()
                    .map(|&c| scenes[s].contacts[c].id)
                    .collect();
                self.friction_warm.start(&ids)
            });
            let warm = warm.flatten();
            let solution = solve_friction_problem(&built[s].2[k], warm.as_deref(), &settings);
            (warm.is_some(), solution)
        });
        report.timings.solve += t.elapsed().as_secs_f64();
        let t = Instant::now();
        let mut islands = Vec::with_capacity(index.len());
        let mut out = Vec::with_capacity(scenes.len());
        let mut solved = solved.into_iter();
        for (s, (scene, (isl, rows, _))) in scenes.iter().zip(built).enumerate() {
            let first = islands.len();
            let mut r = vec![[0.0; 3]; scene.contacts.len()];
            let mut u = vec![[0.0; 3]; scene.contacts.len()];
            for island in isl {
                let (warm_started, solution) = solved.next().expect("one result per island");
                for (i, &c) in island.contacts.iter().enumerate() {
                    r[c].copy_from_slice(&solution.r[3 * i..3 * i + 3]);
                    u[c].copy_from_slice(&solution.u[3 * i..3 * i + 3]);
                }
                islands.push(FrictionIslandReport {
                    scene: Some(s),
                    contacts: island.contacts,
                    warm_started,
                    solution,
                });
            }
            out.push(SceneReport {
                impulses: r.iter().map(|ri| ri[0]).collect(),
                bodies: apply_friction_impulses(scene, &rows, &r),
                islands: 0..0,
                friction: Some(SceneFriction {
                    contacts: (0..r.len())
                        .map(|c| contact_impulse(&rows[c], r[c], u[c]))
                        .collect(),
                    islands: first..islands.len(),
                }),
            });
        }
        report.timings.impulses += t.elapsed().as_secs_f64();
        (out, islands)
    }
}

/// A contact's impulse with its parts, from its rows and local reaction.
fn contact_impulse(rows: &FrictionContactRows, r: [f64; 3], u: [f64; 3]) -> ContactImpulse {
    ContactImpulse {
        impulse: world_impulse(rows, r).to_array(),
        normal: r[0],
        tangential: [r[1], r[2]],
        tangential_impulse: world_impulse(rows, [0.0, r[1], r[2]]).to_array(),
        tangents: [rows.frame[1].to_array(), rows.frame[2].to_array()],
        velocity: u,
    }
}
