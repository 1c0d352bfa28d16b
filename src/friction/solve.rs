//! The exact Coulomb solvers of one island on the CPU in f64, by method,
//! and what they report.

use super::cone::project_on_cone;
use super::newton::newton;
use super::nsgs::nsgs;
use super::problem::FrictionProblem;
use super::residual::FrictionResiduals;
use crate::lcp::Status;

/// The algorithm that solves an island's frictional problem. Each is judged
/// by the Coulomb error (Siconos' fc3d error with De Saxcé's correction).
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum FrictionMethod {
    /// The exact path (default): NSGS sweeps (one contact: exact after one
    /// sweep), then Alart–Curnier Newton polishing to an error of
    /// min(tolerance, 1e-12), alternating with more NSGS sweeps where
    /// Newton stalls, within the iteration cap.
    #[default]
    Auto,
    /// Non-smooth block Gauss–Seidel with exact local Coulomb solves, until
    /// the error is at most the tolerance.
    Nsgs,
    /// Alart–Curnier semismooth Newton with line search alone, from the warm
    /// start or r = 0.
    Newton,
}

impl FrictionMethod {
    /// The name used on the command line and in output: `auto`, `nsgs`, `newton`.
    pub fn name(self) -> &'static str {
        match self {
            FrictionMethod::Auto => "auto",
            FrictionMethod::Nsgs => "nsgs",
            FrictionMethod::Newton => "newton",
        }
    }

    /// The method of a name of [`Self::name`], None for another.
    pub fn from_name(name: &str) -> Option<Self> {
        [Self::Auto, Self::Nsgs, Self::Newton]
            .into_iter()
            .find(|m| m.name() == name)
    }
}

/// What the friction solvers need of [`crate::Settings`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrictionSettings {
    /// The algorithm.
    pub method: FrictionMethod,
    /// `solved` only when the Coulomb error is at most this.
    pub tolerance: f64,
    /// Cap on NSGS sweeps plus Newton steps.
    pub max_iterations: u64,
}

impl Default for FrictionSettings {
    fn default() -> Self {
        FrictionSettings {
            method: FrictionMethod::Auto,
            tolerance: 1e-8,
            max_iterations: 1000,
        }
    }
}

/// One island's frictional answer.
#[derive(Clone, Debug, PartialEq)]
pub struct FrictionSolution {
    /// `solved` (finite, Coulomb error ≤ tolerance), `not_converged` (the
    /// error reached is in `residuals`) or `numerical_failure` (not finite).
    pub status: Status,
    /// The reactions, 3k, interleaved (normal, t₁, t₂ per contact), each in
    /// its cone (projected there after the solve).
    pub r: Vec<f64>,
    /// u = W r + q.
    pub u: Vec<f64>,
    /// The errors of r.
    pub residuals: FrictionResiduals,
    /// NSGS sweeps plus Newton steps.
    pub iterations: u64,
    /// The method asked for.
    pub method: FrictionMethod,
}

/// The Newton target: the rounding of f64, or the tolerance where tighter.
const POLISH: f64 = 1e-12;

/// Solves one island from `warm` (3k reactions of the last call; ignored
/// when absent or of another length) with `s.method`.
pub fn solve_friction_problem(
    p: &FrictionProblem,
    warm: Option<&[f64]>,
    s: &FrictionSettings,
) -> FrictionSolution {
    let mut r = match warm {
        Some(w) if w.len() == p.dim() && w.iter().all(|v| v.is_finite()) => w.to_vec(),
        _ => vec![0.0; p.dim()],
    };
    let cap = s.max_iterations;
    let iterations = match s.method {
        FrictionMethod::Nsgs => nsgs(p, &mut r, cap, s.tolerance).0,
        FrictionMethod::Newton => newton(p, &mut r, cap, s.tolerance.min(POLISH)).0,
        FrictionMethod::Auto => hybrid(p, &mut r, cap, s.tolerance),
    };
    finish(p, r, iterations, s)
}

/// NSGS then Newton, alternating while Newton stalls (see
/// [`FrictionMethod::Auto`]); keeps the r of smallest error.
fn hybrid(p: &FrictionProblem, r: &mut Vec<f64>, cap: u64, tolerance: f64) -> u64 {
    let target = tolerance.min(POLISH);
    let mut used = 0;
    let mut sweeps_per_round = if p.contacts() == 1 { 1 } else { 2 };
    let mut best = (f64::INFINITY, r.clone());
    while used < cap {
        let (k, e) = nsgs(p, r, sweeps_per_round.min(cap - used), target);
        used += k;
        if e < best.0 {
            best = (e, r.clone());
        }
        if e <= target || used >= cap {
            break;
        }
        let (k, e) = newton(p, r, 50.min(cap - used), target);
        used += k;
        if e < best.0 {
            best = (e, r.clone());
        }
        if e <= target || (k == 0 && sweeps_per_round >= cap) {
            break;
        }
        sweeps_per_round *= 2;
    }
    if best.0.is_finite() {
        *r = best.1;
    }
    used
}

/// The status and residuals of the final r, first projected on its cones
/// (a no-op to rounding for a converged r; for a Newton iterate that
/// stopped outside, the nearest admissible impulses; for μ = 0 exactly
/// zero tangential parts), so that every returned impulse is in its cone.
fn finish(
    p: &FrictionProblem,
    mut r: Vec<f64>,
    iterations: u64,
    s: &FrictionSettings,
) -> FrictionSolution {
    for (i, &mu) in p.mu.iter().enumerate() {
        let ri = project_on_cone([r[3 * i], r[3 * i + 1], r[3 * i + 2]], mu);
        r[3 * i..3 * i + 3].copy_from_slice(&ri);
    }
    let u = p.velocity(&r);
    let residuals = FrictionResiduals::of_velocity(p, &r, &u);
    let finite = r.iter().chain(&u).all(|v| v.is_finite()) && residuals.coulomb_error.is_finite();
    let status = if !finite {
        Status::NumericalFailure
    } else if residuals.coulomb_error <= s.tolerance {
        Status::Solved
    } else {
        Status::NotConverged
    };
    FrictionSolution {
        status,
        r,
        u,
        residuals,
        iterations,
        method: s.method,
    }
}
