//! One entry point for both backends, with the CPU taking over on device
//! trouble.
//!
//! [`Backend`] says where to solve: [`Backend::Cpu`], [`Backend::Gpu`] or
//! [`Backend::Auto`] (the GPU whenever an adapter exists). A [`Session`]
//! opens the GPU once and solves batches of LCPs ([`Session::solve_lcps`]) or
//! scenes ([`Session::solve_scenes`]); [`solve_lcps`] and [`solve_scenes`]
//! are the one-shot forms.
//!
//! # Device trouble
//! Whenever the GPU fails with [`Error::Gpu`] — no adapter at all, a forced
//! adapter that does not exist, f64 asked of an adapter without
//! SHADER_F64, or an error in the middle of a batch (lost device,
//! validation error, out of memory) — the session warns once on stderr
//! (`warning: GPU: …; solving on the CPU (f64, exact)`), records the reason
//! in [`BackendReport::fallback`], drops the GPU context and solves the
//! whole batch, and every later one, on the CPU path. The results are the
//! CPU path's: [`crate::solve`] per problem, [`crate::pipeline::solve_scene`]
//! per scene, the same values the CPU backend gives. Errors that are the
//! caller's (invalid scenes, settings out of range, a request only the CPU
//! serves on `Backend::Gpu`) stay errors.
//!
//! Gpu and Auto differ only in what they refuse: `Auto` solves Lemke, PGS
//! and all-solutions requests on the CPU without a word, `Gpu` refuses them
//! with [`Error::Unsupported`].

use std::fmt;
use std::sync::Arc;

use crate::cpu::enumeration::MAX_ENUMERATION_N;
use crate::gpu::{self, GpuContext, GpuOptions, GpuSolveSettings, SolvedOn};
use crate::lcp::{Lcp, LcpSolution};
use crate::pipeline::{solve_scene, SceneSolution};
use crate::scene::Scene;
use crate::solvers::{solve, Solver, SolverSettings};
use crate::validation::BatchReport;
use crate::Error;

/// Where to solve.
#[derive(Clone, Debug, Default, PartialEq)]
pub enum Backend {
    /// The GPU whenever an adapter can be opened with these options, else
    /// the CPU (with a warning).
    Auto(GpuOptions),
    /// The GPU; on device trouble the CPU, with a warning.
    Gpu(GpuOptions),
    /// The CPU path (f64, exact).
    #[default]
    Cpu,
}

/// Where a batch was solved.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SolvedWhere {
    /// Enumeration on the GPU, every answer validated on the CPU in f64.
    Gpu,
    /// The CPU path.
    Cpu,
}

/// What a batch did.
#[derive(Clone, Debug, PartialEq)]
pub struct BackendReport {
    pub solved: SolvedWhere,
    /// The adapter (name, backend, how chosen, precision) when the GPU solved it.
    pub adapter: Option<String>,
    /// The GPU's batch report (islands, polished, repaired, …) when the GPU solved it.
    pub gpu: Option<BatchReport>,
    /// Largest deviation of the GPU's impulse stage from the f64 twin
    /// (scenes on the GPU only).
    pub max_velocity_deviation: Option<f64>,
    /// Why the CPU took over from the GPU (None: no device trouble).
    pub fallback: Option<String>,
}

impl fmt::Display for BackendReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (&self.gpu, &self.fallback) {
            (Some(g), _) => write!(f, "{g}"),
            (None, Some(why)) => write!(f, "solved on the CPU (GPU trouble: {why})"),
            (None, None) => write!(f, "solved on the CPU"),
        }
    }
}

/// One LCP's result.
#[derive(Clone, Debug)]
pub struct LcpResult {
    /// The algorithm whose answer this is.
    pub solver: Solver,
    pub solution: LcpSolution,
    /// Where the GPU path got it (None on the CPU path).
    pub solved_on: Option<SolvedOn>,
}

/// Results of an LCP batch, in the caller's order.
#[derive(Clone, Debug)]
pub struct LcpBatch {
    pub problems: Vec<LcpResult>,
    pub report: BackendReport,
}

/// Scenes after the impact, in the caller's order.
#[derive(Clone, Debug)]
pub struct SceneBatch {
    pub scenes: Vec<SceneSolution>,
    /// Per scene, per island: where the GPU path got it (None on the CPU path).
    pub solved_on: Option<Vec<Vec<SolvedOn>>>,
    pub report: BackendReport,
}

/// A backend opened once and used for many batches; see the module docs.
#[derive(Debug)]
pub struct Session {
    /// True for [`Backend::Gpu`]: requests only the CPU serves are refused.
    strict: bool,
    ctx: Option<Arc<GpuContext>>,
    fallback: Option<String>,
    warned: bool,
    /// Settings of the GPU path (chunk sizes, tolerances); its
    /// `enumeration` is replaced by the solver settings of each call.
    pub gpu_settings: GpuSolveSettings,
}

impl Session {
    /// Opens the backend. On device trouble the session warns, records why
    /// and solves on the CPU; other errors from opening the GPU are returned.
    pub fn new(backend: &Backend) -> Result<Self, Error> {
        let mut s = Session {
            strict: matches!(backend, Backend::Gpu(_)),
            ctx: None,
            fallback: None,
            warned: false,
            gpu_settings: GpuSolveSettings::default(),
        };
        match backend {
            Backend::Cpu => {}
            Backend::Auto(o) | Backend::Gpu(o) => match GpuContext::new(o) {
                Ok(ctx) => s.ctx = Some(Arc::new(ctx)),
                Err(Error::Gpu(why)) => s.fall_back(why),
                Err(e) => return Err(e),
            },
        }
        Ok(s)
    }

    /// A GPU session on a context the caller already has.
    pub fn from_context(ctx: GpuContext) -> Self {
        Session {
            strict: true,
            ctx: Some(Arc::new(ctx)),
            fallback: None,
            warned: false,
            gpu_settings: GpuSolveSettings::default(),
        }
    }

    /// The GPU context while the GPU is in use (None on the CPU path).
    pub fn context(&self) -> Option<&GpuContext> {
        self.ctx.as_deref()
    }

    /// The GPU context, shared (for tests that lose the device from another
    /// thread in the middle of a batch).
    pub fn shared_context(&self) -> Option<Arc<GpuContext>> {
        self.ctx.clone()
    }

    /// Why the CPU took over (None: no device trouble so far).
    pub fn fallback(&self) -> Option<&str> {
        self.fallback.as_deref()
    }

    /// The adapter in words: name, backend, device type, how it was chosen, precision.
    pub fn describe_adapter(&self) -> Option<String> {
        self.ctx.as_deref().map(describe_context)
    }

    /// Device trouble: drop the context, remember why, warn once.
    fn fall_back(&mut self, why: String) {
        self.ctx = None;
        if !self.warned {
            eprintln!("warning: GPU: {why}; solving on the CPU (f64, exact)");
            self.warned = true;
        }
        self.fallback.get_or_insert(why);
    }

    /// The GPU settings for this call, or None when the request is the CPU's
    /// (an error on a strict GPU session).
    fn gpu_request(&self, settings: &SolverSettings) -> Result<Option<GpuSolveSettings>, Error> {
        if self.ctx.is_none() && self.fallback.is_none() {
            return Ok(None); // Backend::Cpu
        }
        let gpu_capable = settings.solver == Solver::Enum && !settings.enumeration.all_solutions;
        if !gpu_capable {
            if self.strict {
                return Err(Error::Unsupported(
                    "the GPU backend solves by enumeration only (no Lemke, PGS or all solutions)"
                        .into(),
                ));
            }
            return Ok(None);
        }
        Ok(Some(GpuSolveSettings {
            enumeration: settings.enumeration,
            ..self.gpu_settings
        }))
    }

    fn cpu_report(&self) -> BackendReport {
        BackendReport {
            solved: SolvedWhere::Cpu,
            adapter: None,
            gpu: None,
            max_velocity_deviation: None,
            fallback: self.fallback.clone(),
        }
    }

    /// Solves a batch of LCPs (see the module docs). On the CPU path each
    /// problem is solved by [`crate::solve`]; enumeration beyond n = 20 is an
    /// error there, except after device trouble, where such a problem goes
    /// to Lemke as it does on the GPU path.
    pub fn solve_lcps(
        &mut self,
        lcps: &[Lcp],
        settings: &SolverSettings,
    ) -> Result<LcpBatch, Error> {
        let gs = self.gpu_request(settings)?;
        if let (Some(gs), Some(ctx)) = (gs, self.ctx.as_deref()) {
            match guarded(|| gpu::solve_lcp_batch(ctx, lcps, &gs)) {
                Ok(r) => {
                    let adapter = self.describe_adapter();
                    return Ok(LcpBatch {
                        problems: r
                            .islands
                            .into_iter()
                            .map(|o| LcpResult {
                                solver: o.solver,
                                solution: o.solution,
                                solved_on: Some(o.solved_on),
                            })
                            .collect(),
                        report: BackendReport {
                            solved: SolvedWhere::Gpu,
                            adapter,
                            gpu: Some(r.report),
                            max_velocity_deviation: None,
                            fallback: None,
                        },
                    });
                }
                Err(Error::Gpu(why)) => self.fall_back(why),
                Err(e) => return Err(e),
            }
        }
        let after_trouble = self.fallback.is_some();
        let problems = lcps
            .iter()
            .enumerate()
            .map(|(i, lcp)| {
                let mut s = *settings;
                if after_trouble && s.solver == Solver::Enum && lcp.n() > MAX_ENUMERATION_N {
                    s.solver = Solver::Lemke;
                }
                solve(lcp, &s)
                    .map(|solution| LcpResult {
                        solver: s.solver,
                        solution,
                        solved_on: None,
                    })
                    .map_err(|e| Error::Unsupported(format!("problem {i}: {e}")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(LcpBatch {
            problems,
            report: self.cpu_report(),
        })
    }

    /// Solves scenes (see the module docs). On the CPU path each scene is
    /// solved by [`crate::pipeline::solve_scene`] (islands above n = 20 by
    /// Lemke); an invalid scene is an error naming it on either path.
    pub fn solve_scenes(
        &mut self,
        scenes: &[Scene],
        settings: &SolverSettings,
    ) -> Result<SceneBatch, Error> {
        let gs = self.gpu_request(settings)?;
        if let (Some(gs), Some(ctx)) = (gs, self.ctx.as_deref()) {
            match guarded(|| gpu::solve_scenes(ctx, scenes, &gs)) {
                Ok(r) => {
                    let adapter = self.describe_adapter();
                    return Ok(SceneBatch {
                        scenes: r.scenes,
                        solved_on: Some(r.solved_on),
                        report: BackendReport {
                            solved: SolvedWhere::Gpu,
                            adapter,
                            gpu: Some(r.report),
                            max_velocity_deviation: Some(r.max_velocity_deviation),
                            fallback: None,
                        },
                    });
                }
                Err(Error::Gpu(why)) => self.fall_back(why),
                Err(e) => return Err(e),
            }
        }
        let scenes = scenes
            .iter()
            .enumerate()
            .map(|(i, s)| solve_scene(s, settings, &format!("scene {i}")))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(SceneBatch {
            scenes,
            solved_on: None,
            report: self.cpu_report(),
        })
    }
}

/// Runs a GPU call, turning a panic inside it into [`Error::Gpu`]: on a lost
/// device wgpu itself panics in places (`create_buffer_init` cannot map the
/// new buffer), and a lost device is device trouble like any other. The
/// context is dropped afterwards, so nothing it left half-done is used again.
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

/// Solves a batch of LCPs on `backend` (one-shot [`Session::solve_lcps`]).
pub fn solve_lcps(
    backend: &Backend,
    lcps: &[Lcp],
    settings: &SolverSettings,
) -> Result<LcpBatch, Error> {
    Session::new(backend)?.solve_lcps(lcps, settings)
}

/// Solves scenes on `backend` (one-shot [`Session::solve_scenes`]).
pub fn solve_scenes(
    backend: &Backend,
    scenes: &[Scene],
    settings: &SolverSettings,
) -> Result<SceneBatch, Error> {
    Session::new(backend)?.solve_scenes(scenes, settings)
}

/// A GPU context in words: adapter name, backend, device type, how it was
/// chosen, precision.
pub fn describe_context(ctx: &GpuContext) -> String {
    let a = ctx.adapter_info();
    format!(
        "{} ({}, {}; {}; {})",
        a.name,
        a.backend,
        a.device_type,
        ctx.selection(),
        ctx.precision().name()
    )
}
