//! Cone projection iterations for the cone complementarity problem (CCP) of
//! Anitescu–Tasora: the CPU twin of `shaders/friction_projected.wgsl`.
//!
//! For an island of k contacts ([`FrictionProblem`]: W, q, μ, interleaved
//! per contact), find r with every r_i in its cone K_i = {‖r_t‖ ≤ μ_i r_n}
//! and u = W r + q with
//!
//! ```text
//! r = P_K(r − η D u)      for any positive step η D,
//! ```
//!
//! the optimality condition of the convex problem min ½ rᵀW r + qᵀr over
//! K = K_1 × … × K_k (W symmetric positive semidefinite). Its answer
//! differs from Coulomb's where a contact slides: the convex model gives a
//! sliding contact the normal velocity u_n = μ‖u_t‖ (it separates a little
//! while sliding), so its solutions are judged by the cone error
//! ‖r − P_K(r − u)‖ ([`FrictionResiduals::cone_error`]) and report the
//! Coulomb error beside it as the model's distance from Coulomb.
//!
//! Three methods ([`ProjectedMethod`]), each from a warm start r0 (projected
//! on K first) or from 0:
//! - **Jacobi** sweeps: every contact at once from u = W r + q,
//!   r_i ← P_K(r_i − ω η_i u_i), η_i = 1 / max over the contact's three rows
//!   of Σ_j |W_rj| (the whole row: Gershgorin's bound makes the largest
//!   eigenvalue of D W at most 1, so every ω in (0, 2) converges for
//!   symmetric positive semidefinite W).
//! - **Gauss–Seidel** sweeps (`pgs`): contact after contact with the
//!   velocity of the reactions already updated, η_i = 1 / max over the three
//!   rows of the contact's own 3×3 block of Σ_j |W_rj| (Gershgorin's bound of
//!   the block's largest eigenvalue: each contact's step then decreases
//!   ½ rᵀW r + qᵀr for ω in (0, 2)). The normal entry alone is not a safe
//!   step: a sphere's tangential entries are 3.5 times its normal one.
//! - **APGD** (Mazhar, Heyn, Negrut, Tasora 2015, "Using Nesterov's method
//!   to accelerate multibody dynamics with friction and contact", ACM TOG
//!   34(3), algorithm APGD): Nesterov/FISTA momentum, the step 1/L found by
//!   backtracking on the Lipschitz estimate L (doubled until
//!   dᵀW d ≤ L‖d‖², the exact sufficient-decrease test of a quadratic, then
//!   0.9 L for the next iteration), a gradient restart when
//!   ∇f(y)·(x_new − x) > 0, and the best iterate kept.
//!
//! Both sweeps and APGD stop when the stop measure (the cone error computed
//! with plain sums of squares, as the shader does) is at most the tolerance
//! (default [`F64_TOLERANCE`]; [`F32_TOLERANCE`] for f32 shaders), or after
//! `max_iterations`. The returned residuals are recomputed in f64 by
//! [`FrictionResiduals::of`]: `solved` only when that cone error is within
//! the tolerance. The arithmetic of every step is written in the shader's
//! order, so that f64 shaders reproduce these iterates (see
//! `src/tests/gpu_friction.rs` for the stated tolerances).

use super::cone::project_on_cone;
use super::problem::FrictionProblem;
use super::residual::FrictionResiduals;
use crate::cpu::batch::parallel_map;
use crate::lcp::Status;
use crate::Error;

/// Default tolerance on the cone error in f64 (the CPU, f64 shaders).
pub const F64_TOLERANCE: f64 = 1e-8;
/// Default tolerance on the cone error for f32 shaders (f32 rounds u = W r +
/// q to about 1e-7 of its terms; 1e-5 leaves a margin of 100).
pub const F32_TOLERANCE: f64 = 1e-5;
/// Largest number of consecutive doublings of APGD's Lipschitz estimate in
/// one iteration; more is a numerical failure (L overflows or W is not
/// positive semidefinite where it is probed).
pub const MAX_BACKTRACKS: u32 = 64;
/// Below this scale the stop measure is not divided (as Siconos does).
pub(crate) const SCALE_FLOOR: f64 = 2.220446049250313e-16;

/// Which cone projection iteration runs.
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
pub enum ProjectedMethod {
    /// Projected Jacobi sweeps (`jacobi`).
    Jacobi,
    /// Projected Gauss–Seidel sweeps over contacts (`pgs`).
    GaussSeidel,
    /// Accelerated projected gradient descent with restarts (`apgd`, default).
    #[default]
    Apgd,
}

impl ProjectedMethod {
    /// Every method.
    pub const ALL: [ProjectedMethod; 3] = [
        ProjectedMethod::Jacobi,
        ProjectedMethod::GaussSeidel,
        ProjectedMethod::Apgd,
    ];

    /// The method's name: `jacobi`, `pgs` or `apgd`.
    pub fn name(self) -> &'static str {
        match self {
            ProjectedMethod::Jacobi => "jacobi",
            ProjectedMethod::GaussSeidel => "pgs",
            ProjectedMethod::Apgd => "apgd",
        }
    }

    /// The method named `name` (`jacobi`, `pgs`, `apgd`).
    ///
    /// # Errors
    /// [`Error::Invalid`] when `name` is none of them.
    pub fn parse(name: &str) -> Result<Self, Error> {
        Self::ALL
            .into_iter()
            .find(|m| m.name() == name)
            .ok_or_else(|| {
                Error::invalid(
                    "settings",
                    "method",
                    format!("unknown projected method `{name}` (jacobi, pgs, apgd)"),
                )
            })
    }
}

/// Settings of the cone projection iterations (CPU twin and shaders).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ProjectedSettings {
    /// The iteration (default [`ProjectedMethod::Apgd`]).
    pub method: ProjectedMethod,
    /// Largest acceptable cone error (normalised as Siconos' error, see
    /// [`FrictionResiduals::cone_error`]). None (default): `F64_TOLERANCE`
    /// on the CPU and for f64 shaders, `F32_TOLERANCE` for f32 shaders.
    /// When given: finite and > 0.
    pub tolerance: Option<f64>,
    /// Iterations (sweeps for Jacobi and Gauss–Seidel) before giving up with
    /// `not_converged` (default 5,000; 0 only evaluates the start).
    pub max_iterations: u32,
    /// Relaxation ω of the sweeps' step ω η_i (default 1; in (0, 2), where
    /// both sweeps converge). APGD ignores it.
    pub relaxation: f64,
}

impl Default for ProjectedSettings {
    fn default() -> Self {
        ProjectedSettings {
            method: ProjectedMethod::Apgd,
            tolerance: None,
            max_iterations: 5_000,
            relaxation: 1.0,
        }
    }
}

impl ProjectedSettings {
    /// Checks every field; the error names it.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the first field out of range.
    pub fn validate(&self) -> Result<(), Error> {
        if let Some(t) = self.tolerance {
            if !(t.is_finite() && t > 0.0) {
                return Err(Error::invalid(
                    "settings",
                    "tolerance",
                    format!("{t} is not a finite number > 0"),
                ));
            }
        }
        let w = self.relaxation;
        if w.is_nan() || w <= 0.0 || w >= 2.0 {
            return Err(Error::invalid(
                "settings",
                "relaxation",
                format!("{w} is not in (0, 2)"),
            ));
        }
        Ok(())
    }

    /// The tolerance in f64 (the CPU, f64 shaders).
    pub fn f64_tolerance(&self) -> f64 {
        self.tolerance.unwrap_or(F64_TOLERANCE)
    }

    /// The tolerance for f32 shaders.
    pub fn f32_tolerance(&self) -> f64 {
        self.tolerance.unwrap_or(F32_TOLERANCE)
    }
}

/// One island's answer.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ProjectedSolution {
    /// `Solved` (cone error within the tolerance, recomputed in f64),
    /// `NotConverged` (r is the best iterate; its error is in
    /// `residuals`), `NumericalFailure` (an iterate or APGD's step was not
    /// finite; r is the best finite iterate), or `InvalidInput` (the
    /// problem failed its checks; r = 0).
    pub status: Status,
    /// The reaction (impulse), 3k, interleaved per contact; in the cones.
    pub r: Vec<f64>,
    /// u = W r + q (f64).
    pub u: Vec<f64>,
    /// Residuals of r in f64: `cone_error` judges it, `coulomb_error` is
    /// the convex model's distance from Coulomb.
    pub residuals: FrictionResiduals,
    /// Iterations done (sweeps for Jacobi and Gauss–Seidel): 0 when the
    /// start already met the tolerance.
    pub iterations: u32,
    /// APGD's gradient restarts (0 for the sweeps).
    pub restarts: u32,
}

impl ProjectedSolution {
    /// The solution of r in f64: its residuals, u, and the status they
    /// give against `tolerance` (`failed`: the iteration broke down).
    pub(crate) fn judge(
        problem: &FrictionProblem,
        r: Vec<f64>,
        tolerance: f64,
        failed: bool,
    ) -> Self {
        let u = problem.velocity(&r);
        let residuals = FrictionResiduals::of_velocity(problem, &r, &u);
        let finite = r.iter().chain(&u).all(|v| v.is_finite()) && residuals.cone_error.is_finite();
        let status = if failed || !finite {
            Status::NumericalFailure
        } else if residuals.cone_error <= tolerance {
            Status::Solved
        } else {
            Status::NotConverged
        };
        ProjectedSolution {
            status,
            r,
            u,
            residuals,
            iterations: 0,
            restarts: 0,
        }
    }

    /// The answer to a problem that failed its checks: r = 0.
    pub(crate) fn invalid(problem: &FrictionProblem) -> Self {
        let n = problem.q.len();
        ProjectedSolution {
            status: Status::InvalidInput,
            r: vec![0.0; n],
            u: vec![0.0; n],
            residuals: FrictionResiduals::default(),
            iterations: 0,
            restarts: 0,
        }
    }
}

/// Solves one island's CCP from `r0` (3k; None: 0) with `settings`
/// (tolerance in f64). Errors: settings or problem failing their checks,
/// r0 of the wrong length or not finite.
#[cfg(test)]
pub fn solve_projected(
    problem: &FrictionProblem,
    r0: Option<&[f64]>,
    settings: &ProjectedSettings,
) -> Result<ProjectedSolution, Error> {
    settings.validate()?;
    problem.validate("problem")?;
    check_warm("problem", problem, r0)?;
    Ok(solve_checked(
        problem,
        r0,
        settings,
        settings.f64_tolerance(),
    ))
}

/// Solves every island on up to `threads` threads (0: every core), in
/// order. `warm[i]`, where given, is island i's start. A problem that fails
/// its checks gets status `InvalidInput`; a bad warm start or bad settings
/// are an error naming it.
///
/// # Errors
/// [`Error::Invalid`] for settings out of range or a warm start of the wrong
/// length or not finite (naming the island).
pub fn solve_projected_batch(
    problems: &[FrictionProblem],
    warm: Option<&[Vec<f64>]>,
    settings: &ProjectedSettings,
    threads: usize,
) -> Result<Vec<ProjectedSolution>, Error> {
    settings.validate()?;
    let start = |i: usize| warm.and_then(|w| w.get(i)).map(Vec::as_slice);
    for (i, p) in problems.iter().enumerate() {
        if p.validate("problem").is_ok() {
            check_warm(format_args!("problem {i}"), p, start(i))?;
        }
    }
    let threads = if threads == 0 {
        std::thread::available_parallelism().map_or(1, |n| n.get())
    } else {
        threads
    };
    let tol = settings.f64_tolerance();
    Ok(parallel_map(problems.len(), threads, |i| {
        let p = &problems[i];
        match p.validate("problem") {
            Ok(()) => solve_checked(p, start(i), settings, tol),
            Err(_) => ProjectedSolution::invalid(p),
        }
    }))
}

/// A warm start must have 3k finite entries.
pub(crate) fn check_warm(
    item: impl std::fmt::Display,
    problem: &FrictionProblem,
    r0: Option<&[f64]>,
) -> Result<(), Error> {
    let Some(r0) = r0 else { return Ok(()) };
    if r0.len() != problem.dim() {
        return Err(Error::invalid(
            item,
            "r0",
            format!("has {} entries, expected 3k = {}", r0.len(), problem.dim()),
        ));
    }
    if let Some(i) = r0.iter().position(|v| !v.is_finite()) {
        return Err(Error::invalid(
            item,
            format!("r0[{i}]"),
            "not a finite number",
        ));
    }
    Ok(())
}

/// [`solve_projected`] on a checked problem and start, to `tolerance`.
pub(crate) fn solve_checked(
    problem: &FrictionProblem,
    r0: Option<&[f64]>,
    settings: &ProjectedSettings,
    tolerance: f64,
) -> ProjectedSolution {
    let run = match settings.method {
        ProjectedMethod::Apgd => super::apgd::apgd(problem, r0, settings.max_iterations, tolerance),
        m => sweeps(
            problem,
            r0,
            settings,
            m == ProjectedMethod::GaussSeidel,
            tolerance,
        ),
    };
    let mut s = ProjectedSolution::judge(problem, run.r, tolerance, run.failed);
    s.iterations = run.iterations;
    s.restarts = run.restarts;
    s
}

/// What an iteration ended with, before the f64 judgement.
pub(crate) struct Run {
    pub(crate) r: Vec<f64>,
    pub(crate) iterations: u32,
    pub(crate) restarts: u32,
    pub(crate) failed: bool,
}

/// The start: r0 (or 0) projected on the cones.
pub(crate) fn start(problem: &FrictionProblem, r0: Option<&[f64]>) -> Vec<f64> {
    let mut x = r0.map_or_else(|| vec![0.0; problem.dim()], <[f64]>::to_vec);
    project_all(problem, &mut x);
    x
}

/// Every contact's reaction projected on its cone, in place.
pub(crate) fn project_all(problem: &FrictionProblem, x: &mut [f64]) {
    for (i, &mu) in problem.mu.iter().enumerate() {
        let p = project_on_cone([x[3 * i], x[3 * i + 1], x[3 * i + 2]], mu);
        x[3 * i..3 * i + 3].copy_from_slice(&p);
    }
}

/// u = W x + q in the shader's order: s = Σ_j W_rj x_j from j = 0, then
/// u_r = q_r + s.
pub(crate) fn velocity_into(problem: &FrictionProblem, x: &[f64], u: &mut [f64]) {
    let n = problem.dim();
    for (r, ur) in u.iter_mut().enumerate().take(n) {
        let row = &problem.w[r * n..(r + 1) * n];
        let mut s = 0.0;
        for (a, b) in row.iter().zip(x) {
            s += a * b;
        }
        *ur = problem.q[r] + s;
    }
}

/// Σ v_r², from r = 0 (the shader's order).
pub(crate) fn sum_squares(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |s, x| s + x * x)
}

/// The stop measure: ‖x − P_K(x − u)‖ / max(‖q‖, ‖x‖, ‖u‖) with plain
/// sums of squares (not divided when that maximum is at most
/// [`SCALE_FLOOR`]); `q2` = ‖q‖². Non-finite when x or u is.
pub(crate) fn stop_measure(problem: &FrictionProblem, x: &[f64], u: &[f64], q2: f64) -> f64 {
    let mut e2 = 0.0;
    for (i, &mu) in problem.mu.iter().enumerate() {
        let c = 3 * i;
        let p = project_on_cone([x[c] - u[c], x[c + 1] - u[c + 1], x[c + 2] - u[c + 2]], mu);
        for j in 0..3 {
            let d = x[c + j] - p[j];
            e2 += d * d;
        }
    }
    let scale = q2.max(sum_squares(x)).max(sum_squares(u)).sqrt();
    let e = e2.sqrt();
    if scale > SCALE_FLOOR {
        e / scale
    } else {
        e
    }
}

/// The sweeps' step per contact (see the module docs): 1 / max over the
/// contact's rows of Σ_j |W_rj| over the whole row (Jacobi) or over the
/// contact's own block (Gauss–Seidel); 1 where that sum is 0.
pub(crate) fn contact_steps(problem: &FrictionProblem, gauss_seidel: bool) -> Vec<f64> {
    let n = problem.dim();
    (0..problem.contacts())
        .map(|i| {
            let (lo, hi) = if gauss_seidel {
                (3 * i, 3 * i + 3)
            } else {
                (0, n)
            };
            let mut big = 0.0f64;
            for r in 3 * i..3 * i + 3 {
                let mut s = 0.0;
                for j in lo..hi {
                    s += problem.w[r * n + j].abs();
                }
                big = big.max(s);
            }
            if big > 0.0 {
                1.0 / big
            } else {
                1.0
            }
        })
        .collect()
}

/// Projected Jacobi or Gauss–Seidel sweeps (see the module docs). Each
/// iteration: u = W x + q, stop when the stop measure of x is within
/// `tolerance`, else one sweep.
#[allow(clippy::needless_range_loop, reason = "mirrors the WGSL loops")]
fn sweeps(
    problem: &FrictionProblem,
    r0: Option<&[f64]>,
    settings: &ProjectedSettings,
    gauss_seidel: bool,
    tolerance: f64,
) -> Run {
    let n = problem.dim();
    let steps = contact_steps(problem, gauss_seidel);
    let q2 = sum_squares(&problem.q);
    let mut x = start(problem, r0);
    let mut u = vec![0.0; n];
    let mut iterations = 0;
    loop {
        velocity_into(problem, &x, &mut u);
        let err = stop_measure(problem, &x, &u, q2);
        if !err.is_finite() {
            return Run {
                r: x,
                iterations,
                restarts: 0,
                failed: true,
            };
        }
        if err <= tolerance || iterations >= settings.max_iterations {
            return Run {
                r: x,
                iterations,
                restarts: 0,
                failed: false,
            };
        }
        for (i, &mu) in problem.mu.iter().enumerate() {
            let c = 3 * i;
            if gauss_seidel {
                // The contact's velocity from the reactions updated so far.
                for r in c..c + 3 {
                    let row = &problem.w[r * n..(r + 1) * n];
                    let mut s = 0.0;
                    for (a, b) in row.iter().zip(&x) {
                        s += a * b;
                    }
                    u[r] = problem.q[r] + s;
                }
            }
            let h = settings.relaxation * steps[i];
            let p = project_on_cone(
                [
                    x[c] - h * u[c],
                    x[c + 1] - h * u[c + 1],
                    x[c + 2] - h * u[c + 2],
                ],
                mu,
            );
            x[c..c + 3].copy_from_slice(&p);
        }
        iterations += 1;
    }
}

#[cfg(test)]
#[path = "projected_tests.rs"]
pub(crate) mod tests;
