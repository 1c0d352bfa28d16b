//! The GPU path of the [`Solver`]: enumeration on the device, every answer
//! validated on the CPU in f64.

use super::Solver;
use crate::gpu::{self, GpuContext, SolvedOn};
use crate::lcp::Lcp;
use crate::prediction;
use crate::report::{GpuFigures, IslandReport, Report, SceneReport, SolvePath};
use crate::scene::Scene;
use crate::settings::Method;
use crate::validation::BatchReport;
use crate::Error;

use super::cpu_path::prediction_path;

impl Solver {
    /// Checked LCPs on the GPU; a panic inside wgpu becomes [`Error::Gpu`].
    pub(super) fn lcps_on_gpu(
        &self,
        ctx: &GpuContext,
        lcps: &[Lcp],
        warm: Option<&[Option<u32>]>,
    ) -> Result<Report, Error> {
        let gs = self.settings.gpu_solve();
        let r = guarded(|| gpu::solve_lcp_batch_warm(ctx, lcps, warm, &gs))?;
        let islands = r
            .islands
            .into_iter()
            .enumerate()
            .map(|(i, o)| IslandReport {
                scene: None,
                contacts: (0..lcps[i].n()).collect(),
                method: if o.path == Some(prediction::SolvePath::Lemke) {
                    Method::Lemke
                } else {
                    Method::Enumeration
                },
                path: gpu_path(o.solved_on, o.path),
                solution: o.solution,
            })
            .collect();
        Ok(self.gpu_report(islands, Vec::new(), &r.report, 0.0))
    }

    /// Checked scenes on the GPU. `warm`: per scene, per island, the warm
    /// basis (empty: none).
    pub(super) fn scenes_on_gpu(
        &self,
        ctx: &GpuContext,
        scenes: &[Scene],
        warm: &[Vec<Option<u32>>],
    ) -> Result<Report, Error> {
        let gs = self.settings.gpu_solve();
        let warm = (!warm.is_empty()).then_some(warm);
        let r = guarded(|| gpu::solve_scenes_warm(ctx, scenes, warm, &gs))?;
        let mut islands = Vec::new();
        let mut out = Vec::with_capacity(r.scenes.len());
        for (s, (sol, on)) in r.scenes.into_iter().zip(&r.solved_on).enumerate() {
            let first = islands.len();
            for (k, isl) in sol.islands.into_iter().enumerate() {
                islands.push(IslandReport {
                    scene: Some(s),
                    contacts: isl.contacts,
                    method: match isl.solver {
                        crate::solvers::Solver::Lemke => Method::Lemke,
                        _ => Method::Enumeration,
                    },
                    path: gpu_path(on[k], Some(r.paths[s][k])),
                    solution: isl.solution,
                });
            }
            out.push(SceneReport {
                impulses: sol.impulses,
                bodies: sol.bodies,
                islands: first..islands.len(),
                friction: None,
            });
        }
        Ok(self.gpu_report(islands, out, &r.report, r.max_velocity_deviation))
    }

    fn gpu_report(
        &self,
        mut islands: Vec<IslandReport>,
        scenes: Vec<SceneReport>,
        b: &BatchReport,
        max_velocity_deviation: f64,
    ) -> Report {
        self.check(&mut islands);
        let mut r = Report::new(islands, scenes, self.device(), self.choice.clone());
        r.counts.polished = b.polished;
        r.counts.cpu_fallback = b.cpu_fallback;
        r.timings.prediction = b.prediction_seconds;
        r.timings.gpu = b.gpu_seconds;
        r.timings.validation = b.validation_seconds;
        r.gpu = Some(GpuFigures {
            chunks: b.chunks,
            dispatches: b.dispatches,
            rounds: b.rounds,
            tree_decided: b.tree_decided,
            tree_undecided: b.tree_undecided,
            max_gpu_error: b.max_gpu_error,
            max_velocity_deviation,
        });
        r
    }
}

/// The path of an island the GPU backend returned.
fn gpu_path(on: SolvedOn, path: Option<prediction::SolvePath>) -> SolvePath {
    match (on, path) {
        (SolvedOn::Gpu, _) => SolvePath::EnumeratedGpu,
        (SolvedOn::Repaired, _) => SolvePath::Repaired,
        (SolvedOn::CpuFallback, _) => SolvePath::Lemke,
        (SolvedOn::Invalid, _) => SolvePath::Invalid,
        (SolvedOn::Predicted, Some(p)) => prediction_path(p),
        // The GPU backend names the prediction case of every island it
        // settled that way; none is left without one.
        (SolvedOn::Predicted, None) => SolvePath::PredictedBasis,
    }
}

/// Runs a GPU call, turning a panic inside it into [`Error::Gpu`]: on a lost
/// device wgpu itself panics in places (`create_buffer_init` cannot map the
/// new buffer), and a lost device is device trouble like any other. The
/// device is dropped afterwards, so nothing it left half-done is used again.
fn guarded<T>(f: impl FnOnce() -> Result<T, Error>) -> Result<T, Error> {
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
