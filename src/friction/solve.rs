//! The exact Coulomb solvers of one island on the CPU in f64, by method,
//! and what they report.

use super::cone::project_on_cone;
use super::faceted::{faceted_start, polish, FACETED_MAX};
use super::newton::newton_in;
use super::nsgs::{nsgs_in, Patience};
use super::problem::FrictionProblem;
use super::projected::{solve_checked, ProjectedMethod, ProjectedSettings, ProjectedSolution};
use super::prox::prox_in;
use super::residual::FrictionResiduals;
use super::sparse::{
    bandwidth_order, gather, permuted, scatter, velocity_sparse, Pattern, SPARSE_FROM,
};
use super::workspace::{velocity_into, with_workspace, Workspace};
use crate::lcp::Status;

/// The algorithm that solves an island's frictional problem. Each is judged
/// by the Coulomb error (Siconos' fc3d error with De Saxcé's correction).
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum FrictionMethod {
    /// The exact path (default): a start already within the tolerance is
    /// returned as it is (0 iterations: the warm start of a time-stepping
    /// world at rest); else NSGS sweeps (one contact: exact after one sweep)
    /// while they converge fast enough, then Alart–Curnier Newton, each
    /// stopping as soon as the Coulomb error is at most the tolerance
    /// (ask for a smaller `tolerance` to polish further: Newton converges
    /// quadratically, so 1e-12 costs a step or two more than 1e-8),
    /// within the iteration cap; where Newton stalls, once Newton from the
    /// start, then (islands of at most 24 contacts) the faceted round:
    /// Lemke on the LCP of the island with pyramids for cones, its active
    /// set (lifted, sticking, sliding) polished by Gauss–Newton, then the
    /// neighbouring sets of the best one (its worst contacts flipped), kept
    /// only within the tolerance; then [`Self::Prox`] (the first Newton
    /// round and Newton from the start both short of the tolerance), for
    /// the rest of the cap, from the faceted round's r where that is the
    /// best iterate so far, else from the start.
    #[default]
    Auto,
    /// Non-smooth block Gauss–Seidel with exact local Coulomb solves, until
    /// the error is at most the tolerance.
    Nsgs,
    /// Alart–Curnier semismooth Newton with line search alone, from the warm
    /// start or r = 0, until the error is at most the tolerance.
    Newton,
    /// The proximal-point iteration (as Siconos' PROX): Newton on W + αI
    /// around the last iterate, α adapted to the error; the cap counts its
    /// Newton steps. Converges where W is only semidefinite and Newton
    /// alone stalls (large piles, heavy boxes on light ones).
    Prox,
    /// Projected Jacobi sweeps over contacts on the cone complementarity
    /// model of Anitescu–Tasora (`friction::projected`; on the GPU too),
    /// judged by that model's residual `cone_error`, not the Coulomb error
    /// (which the report gives beside it: the model's distance from Coulomb).
    Jacobi,
    /// Projected Gauss–Seidel sweeps, as [`Self::Jacobi`] otherwise.
    Pgs,
    /// Accelerated projected gradient (APGD with restarts: Mazhar, Heyn,
    /// Negrut & Tasora, ACM TOG 2015), as [`Self::Jacobi`] otherwise.
    Apgd,
}

impl FrictionMethod {
    /// The name used on the command line and in output: `auto`, `nsgs`,
    /// `newton`, `prox`, `jacobi`, `pgs`, `apgd`.
    pub fn name(self) -> &'static str {
        match self {
            FrictionMethod::Auto => "auto",
            FrictionMethod::Nsgs => "nsgs",
            FrictionMethod::Newton => "newton",
            FrictionMethod::Prox => "prox",
            FrictionMethod::Jacobi => "jacobi",
            FrictionMethod::Pgs => "pgs",
            FrictionMethod::Apgd => "apgd",
        }
    }

    /// The cone projection iteration of a projected method (None for the
    /// exact Coulomb methods).
    pub fn projected(self) -> Option<ProjectedMethod> {
        match self {
            FrictionMethod::Jacobi => Some(ProjectedMethod::Jacobi),
            FrictionMethod::Pgs => Some(ProjectedMethod::GaussSeidel),
            FrictionMethod::Apgd => Some(ProjectedMethod::Apgd),
            _ => None,
        }
    }

    /// Every method, in the order of the help texts.
    pub const ALL: [FrictionMethod; 7] = [
        Self::Auto,
        Self::Nsgs,
        Self::Newton,
        Self::Prox,
        Self::Jacobi,
        Self::Pgs,
        Self::Apgd,
    ];
}

impl std::str::FromStr for FrictionMethod {
    type Err = crate::Error;
    /// The method of [`FrictionMethod::name`]; an error listing the names otherwise.
    fn from_str(s: &str) -> Result<Self, crate::Error> {
        crate::settings::from_name("friction_method", s, &Self::ALL, Self::name)
    }
}

/// What the friction solvers need of [`crate::Settings`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrictionSettings {
    /// The algorithm.
    pub method: FrictionMethod,
    /// `solved` only when the solver's error is at most this, and where
    /// each method stops: `auto`, `nsgs` and `newton` return as soon as the
    /// Coulomb error (Siconos' fc3d error, De Saxcé) is at most this, a
    /// start already there included (no polishing beyond it); the
    /// projected methods judge their own residual `cone_error` by it (see
    /// [`FrictionMethod::Jacobi`]).
    pub tolerance: f64,
    /// Cap on NSGS sweeps plus Newton steps, PROX's inner steps and the
    /// faceted round's Lemke pivots and Gauss–Newton steps included (the
    /// projected methods: on their iterations).
    pub max_iterations: u64,
}

/// The default tolerance of the friction solvers (f64).
pub const DEFAULT_TOLERANCE: f64 = 1e-8;

impl Default for FrictionSettings {
    fn default() -> Self {
        FrictionSettings {
            method: FrictionMethod::Auto,
            tolerance: DEFAULT_TOLERANCE,
            max_iterations: 1000,
        }
    }
}

/// One island's frictional answer.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
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
    /// NSGS sweeps plus Newton steps (PROX: its inner Newton steps; the
    /// faceted round: Lemke's pivots and the Gauss–Newton steps).
    pub iterations: u64,
    /// The method asked for.
    pub method: FrictionMethod,
}

/// Solves one island from `warm` (3k reactions of the last call; ignored
/// when absent, of another length or not finite) with `s.method`. The exact
/// methods start from the warm start projected on the cones, check its
/// Coulomb error first and return it unchanged (0 iterations) when it is
/// within the tolerance. They reuse one workspace per thread across calls.
/// Islands of at least [`SPARSE_FROM`] contacts are solved with their
/// contacts reordered ([`bandwidth_order`]: W's nonzeros near its diagonal,
/// the Newton steps factored within its envelope); the answer is given in
/// the problem's own order.
pub fn solve_friction_problem(
    p: &FrictionProblem,
    warm: Option<&[f64]>,
    s: &FrictionSettings,
) -> FrictionSolution {
    let mut r = match warm {
        Some(w) if usable_start(w, p.dim()) => w.to_vec(),
        _ => vec![0.0; p.dim()],
    };
    if s.method.projected().is_some() {
        let ps = s.projected_settings();
        let sol = solve_checked(p, Some(&r), &ps, ps.f64_tolerance());
        return from_projected(sol, s.method);
    }
    project_on_cones(p, &mut r);
    if p.contacts() >= SPARSE_FROM {
        // W's pattern once: the order from it, then the reordered
        // problem's by permuting it (the problem's own kept for `finish`).
        let mut natural = Pattern::default();
        let (order, iterations) = with_workspace(|ws| {
            ws.pattern.build(p);
            natural.copy_from(&ws.pattern);
            let order = bandwidth_order(&ws.pattern);
            ws.pattern.permute(&order);
            let reordered = permuted(p, &order, &ws.pattern);
            r = gather(&r, &order);
            (order, solve_in(&reordered, ws, &mut r, s, true).0)
        });
        let r = scatter(&r, &order);
        return finish(p, r, iterations, Known::Pattern(&natural), s);
    }
    let (iterations, u) = with_workspace(|ws| {
        let (iterations, exact) = solve_in(p, ws, &mut r, s, false);
        // No iteration: r is the start and `ws.u` its exact W r + q (the
        // warm start of a time step, accepted as it is); `exact`: a checked
        // Newton iterate, whose u was recomputed for it (the same bits
        // `finish` would compute again).
        (iterations, (iterations == 0 || exact).then(|| ws.u.clone()))
    });
    let known = u.map_or(Known::Nothing, Known::Velocity);
    finish(p, r, iterations, known, s)
}

/// What [`finish`] is given towards u = W r + q of the final r.
enum Known<'a> {
    /// Nothing: u is computed from W's dense rows.
    Nothing,
    /// W r + q of r as given (kept when the projection leaves r as it is).
    Velocity(Vec<f64>),
    /// W's block pattern: u is computed over its nonzero blocks (the dense
    /// rows' bits, `velocity_sparse`; on 570 contacts 13 thousand blocks of
    /// 325 thousand).
    Pattern(&'a Pattern),
}

/// Prepares `ws` for `p` and r (`patterned`: `ws.pattern` is W's already)
/// and runs `s.method` (an exact one) from r: (iterations, whether `ws.u`
/// is W r + q of the final r as [`velocity_into`] computes it).
fn solve_in(
    p: &FrictionProblem,
    ws: &mut Workspace,
    r: &mut [f64],
    s: &FrictionSettings,
    patterned: bool,
) -> (u64, bool) {
    let (cap, tolerance) = (s.max_iterations, s.tolerance);
    ws.prepare_with(p, r, patterned);
    match s.method {
        FrictionMethod::Nsgs => (nsgs_in(p, ws, r, cap, tolerance, None).0, false),
        FrictionMethod::Newton => (newton_in(p, ws, r, cap, tolerance).0, false),
        FrictionMethod::Prox => (prox_in(p, ws, r, cap, tolerance).0, false),
        _ => hybrid(p, ws, r, cap, tolerance),
    }
}

/// Whether a warm start `w` can start a problem of `dim` unknowns: its
/// length is `dim` and every entry is finite (otherwise the solve starts
/// from r = 0).
pub(crate) fn usable_start(w: &[f64], dim: usize) -> bool {
    w.len() == dim && w.iter().all(|v| v.is_finite())
}

/// Each contact's reaction projected on its cone, in place; whether any
/// entry changed.
fn project_on_cones(p: &FrictionProblem, r: &mut [f64]) -> bool {
    let mut changed = false;
    for (i, &mu) in p.mu.iter().enumerate() {
        let old = [r[3 * i], r[3 * i + 1], r[3 * i + 2]];
        let ri = project_on_cone(old, mu);
        changed |= ri.map(f64::to_bits) != old.map(f64::to_bits);
        r[3 * i..3 * i + 3].copy_from_slice(&ri);
    }
    changed
}

/// A projected iteration's answer as a [`FrictionSolution`] (its status
/// judged by `cone_error`; see [`FrictionMethod::Jacobi`]).
pub(crate) fn from_projected(sol: ProjectedSolution, method: FrictionMethod) -> FrictionSolution {
    FrictionSolution {
        status: sol.status,
        r: sol.r,
        u: sol.u,
        residuals: sol.residuals,
        iterations: sol.iterations as u64,
        method,
    }
}

impl FrictionSettings {
    /// The settings of the cone projection iterations: the method, the
    /// iteration cap, and the tolerance where it is not the default (then
    /// f64 runs stop at 1e-8 and f32 shaders at 1e-5, their own defaults).
    pub fn projected_settings(&self) -> ProjectedSettings {
        ProjectedSettings {
            method: self.method.projected().unwrap_or_default(),
            tolerance: (self.tolerance != DEFAULT_TOLERANCE).then_some(self.tolerance),
            max_iterations: self.max_iterations.min(u32::MAX as u64) as u32,
            ..ProjectedSettings::default()
        }
    }
}

/// A start with a Coulomb error at most this goes to Newton first (see
/// [`hybrid`]).
const NEAR: f64 = 1e-6;

/// Newton steps tried first from a start within [`NEAR`].
const NEAR_STEPS: u64 = 3;

/// NSGS, then Newton, then PROX (see [`FrictionMethod::Auto`]), with `ws`
/// prepared for `p` and r. NSGS (at most 2(4 + 3k/2) sweeps) gives way to
/// Newton once its linear rate predicts more than 4 + 3k/2 further sweeps
/// (about a Newton step's cost at k ≤ 4).
/// A start within [`NEAR`] (a time step's warm start) gets up to
/// [`NEAR_STEPS`] Newton steps before any sweep; else, after the first
/// Newton round that stalls, Newton runs once from the start itself.
/// A Newton iterate is projected on the cones and checked again before it
/// is accepted. Once the first Newton round and Newton from the start are
/// both short of the tolerance, islands of at most [`FACETED_MAX`]
/// contacts get [`faceted_round`] (a finite pivoting step that picks which
/// contacts lift and slide, where the residual-driven steps creep:
/// `rain:32` over 4 worlds × 1,000 steps ends 11 islands unsolved instead
/// of 19, and its 229 islands that take over 20 iterations, replayed
/// warm, take 18,499 iterations in all instead of 31,774 (11 unsolved);
/// with the polish's search of neighbouring active sets and the round up
/// to 24 contacts, 10, and over 100 worlds × 300 steps 101 instead of 211;
/// with PROX's raised ρ as well, 1 and 43; with PROX from the faceted
/// round's r, 1 and 30),
/// then PROX ([`prox_rounds`]) runs from the faceted round's r where that
/// is the best iterate so far, else from the start,
/// for the rest of the cap instead of more sweeps (NSGS creeps and Newton
/// stalls where W is only semidefinite: piles, heavy boxes on light ones;
/// on 216 seeded stacks of 2–4 boxes with mass ratios to 1e4 and μ to 2,
/// `src/tests/friction_hard.rs`, this took the unsolved from 92 to 3 at the
/// default cap, and PROX's raised ρ where it creeps to none of 648).
/// Keeps the r of smallest error when the cap is
/// reached.
/// Returns the iterations and whether `ws.u` is W r + q of the final r as
/// [`velocity_into`] computes it (not updated incrementally by sweeps).
fn hybrid(
    p: &FrictionProblem,
    ws: &mut Workspace,
    r: &mut [f64],
    cap: u64,
    tolerance: f64,
) -> (u64, bool) {
    let mut error = ws.error(p, r);
    if error <= tolerance {
        return (0, true);
    }
    let budget = 4.0 + p.dim() as f64 / 2.0;
    let mut used = 0;
    let mut best = error;
    ws.best.copy_from_slice(r);
    ws.start.copy_from_slice(r);
    // Newton from the start is tried once in all (first when it is near).
    let from_start = error <= NEAR;
    if from_start {
        // A start this close (a time step's warm start): Newton first, whose
        // convergence is quadratic from here, where NSGS creeps (stacks).
        let (k, e) = newton_checked(p, ws, r, NEAR_STEPS.min(cap), tolerance);
        used += k;
        error = e;
        if error <= tolerance {
            return (used, true);
        }
        keep_best(ws, r, error, &mut best);
    }
    if used < cap {
        let (k, e) = nsgs_in(
            p,
            ws,
            r,
            (2 * budget as u64).min(cap - used),
            tolerance,
            Some(Patience { budget }),
        );
        used += k;
        error = e;
        if !(error <= tolerance) && used < cap {
            keep_best(ws, r, error, &mut best);
            error = newton_round(p, ws, r, (&mut used, cap), tolerance, &mut best).1;
            if error <= tolerance {
                return (used, true);
            }
            if !from_start && used < cap {
                // Newton stalled from the sweeps' iterate (where ½‖Φ‖² has a
                // local minimum that is no solution, or no descent: the sweeps
                // can cycle there, random spheres k = 3): once, Newton from
                // the start instead, which takes another path.
                r.copy_from_slice(&ws.start);
                ws.refresh(p, r);
                error = newton_round(p, ws, r, (&mut used, cap), tolerance, &mut best).1;
                if error <= tolerance {
                    return (used, true);
                }
            }
            // Whether the faceted round's polished r is the best so far.
            let mut faceted_best = false;
            if used < cap && p.contacts() <= FACETED_MAX {
                error = faceted_round(p, ws, r, (&mut used, cap), tolerance);
                faceted_best = error < best;
                keep_best(ws, r, error, &mut best);
                if error <= tolerance {
                    return (used, true);
                }
            }
            if used < cap {
                // PROX from the faceted round's r where that is the best
                // so far, else from the start. Not from the sweeps' and
                // Newton's best: it lies within 1e-9 of a degenerate
                // solution, where α = σ e d̄ leaves W + αI as singular as W
                // and the inner Newton creeps (of the 107 islands `rain:32`
                // left unsolved over 4 worlds × 1,000 steps, warm-started as
                // the world does, `auto` solved 24 from the best, 65 from
                // the start); from the start α is large first and shrinks
                // with the error. The faceted round's r sits on a Coulomb
                // answer's active set short of it by 1e-12–1e-10, and PROX
                // from the start takes more than the 500–800 steps left to
                // get there (of 103 islands main left unsolved in
                // `rain:32`, dumped with their warm starts from 4 worlds ×
                // 1,000 steps and 100 worlds × 300 steps, seeds 1 and 501:
                // from the start 103 unsolved warm, 81 cold; from the
                // faceted r 71 and 57; from the best whatever it is 62 and
                // 62, but 3 instead of 1 over 4 worlds × 1,000 steps).
                let from = if faceted_best { &ws.best } else { &ws.start };
                r.copy_from_slice(from);
                ws.refresh(p, r);
                error = prox_rounds(p, ws, r, (&mut used, cap), tolerance, &mut best);
                if error <= tolerance {
                    return (used, true);
                }
            }
        }
    }
    if !(error <= tolerance) && best < error {
        r.copy_from_slice(&ws.best);
    }
    (used, false)
}

/// PROX rounds on [`hybrid`]'s behalf from r (`ws.u` exact for it): PROX
/// to a target error, its iterate projected on the cones and checked; where
/// PROX reached its target but the projected iterate is still short of
/// `tolerance` (PROX's last Newton iterate lies just outside a cone), again
/// from there with a target ten times finer, at most [`PROX_ROUNDS`]
/// times. Returns the error of r; the best r is kept in `ws.best`.
fn prox_rounds(
    p: &FrictionProblem,
    ws: &mut Workspace,
    r: &mut [f64],
    budget: (&mut u64, u64),
    tolerance: f64,
    best: &mut f64,
) -> f64 {
    let (used, cap) = budget;
    let mut target = tolerance;
    let mut error = f64::INFINITY;
    for _ in 0..PROX_ROUNDS {
        let left = cap - *used;
        let mut reached = false;
        let (k, e) = checked(p, ws, r, target, |p, ws, r| {
            let (k, e) = prox_in(p, ws, r, left, target);
            reached = e <= target;
            (k, e)
        });
        *used += k;
        error = e;
        keep_best(ws, r, error, best);
        if error <= tolerance || !reached || *used >= cap {
            break;
        }
        target /= 10.0;
    }
    error
}

/// The faceted round of [`hybrid`] (islands of at most [`FACETED_MAX`]
/// contacts where Newton stalled twice): r set to the answer of the
/// island's faceted LCP ([`faceted_start`]: which contacts lift, stick and
/// slide, by pivoting), polished where it is short of `tolerance`
/// ([`polish`]: Gauss–Newton on the equations of that active set). Lemke's
/// pivots and the Gauss–Newton steps count as iterations. Returns the
/// error of r (r is left as it was where Lemke found no answer: error
/// infinite; `ws.u` is exact for r).
fn faceted_round(
    p: &FrictionProblem,
    ws: &mut Workspace,
    r: &mut [f64],
    (used, cap): (&mut u64, u64),
    tolerance: f64,
) -> f64 {
    let mut slide = vec![0.0; p.contacts()];
    let (pivots, found) = faceted_start(p, r, &mut slide, cap - *used);
    *used += pivots.min(cap - *used);
    if !found {
        return f64::INFINITY;
    }
    ws.refresh(p, r);
    let mut error = ws.error(p, r);
    if !(error <= tolerance) && *used < cap {
        // Half the steps left at most: PROX gets the rest.
        let (k, e) = polish(p, r, &slide, (cap - *used).div_ceil(2), tolerance);
        *used += k;
        if e <= tolerance {
            ws.refresh(p, r);
            error = ws.error(p, r);
        }
    }
    error
}

/// How many times [`prox_rounds`] tightens PROX's target.
const PROX_ROUNDS: usize = 4;

/// Newton ([`newton_in`]) whose converged iterate is projected on the
/// cones and checked again with u recomputed: (steps, error of r).
fn newton_checked(
    p: &FrictionProblem,
    ws: &mut Workspace,
    r: &mut [f64],
    max_steps: u64,
    tolerance: f64,
) -> (u64, f64) {
    checked(p, ws, r, tolerance, |p, ws, r| {
        newton_in(p, ws, r, max_steps, tolerance)
    })
}

/// `solver` (Newton or PROX: (steps, error), `ws.u` exact for its final
/// r) whose converged iterate is projected on the cones and, where that
/// moved it, checked again with u recomputed.
fn checked(
    p: &FrictionProblem,
    ws: &mut Workspace,
    r: &mut [f64],
    tolerance: f64,
    solver: impl FnOnce(&FrictionProblem, &mut Workspace, &mut [f64]) -> (u64, f64),
) -> (u64, f64) {
    let (k, mut error) = solver(p, ws, r);
    // `ws.u` is exact for the solver's r: computed again only where the
    // projection moved r.
    if error <= tolerance && project_on_cones(p, r) {
        ws.refresh(p, r);
        error = ws.error(p, r);
    }
    (k, error)
}

/// One of [`hybrid`]'s Newton rounds: [`newton_checked`] for at most 50
/// steps within the cap (`budget` = (steps used so far, cap), the steps
/// added), r recorded as the best when it is. Returns (steps, error).
fn newton_round(
    p: &FrictionProblem,
    ws: &mut Workspace,
    r: &mut [f64],
    budget: (&mut u64, u64),
    tolerance: f64,
    best: &mut f64,
) -> (u64, f64) {
    let (used, cap) = budget;
    let (k, error) = newton_checked(p, ws, r, 50.min(cap - *used), tolerance);
    *used += k;
    keep_best(ws, r, error, best);
    (k, error)
}

/// Records r in `ws.best` when its error beats `best`.
fn keep_best(ws: &mut Workspace, r: &[f64], error: f64, best: &mut f64) {
    if error < *best {
        *best = error;
        ws.best.copy_from_slice(r);
    }
}

/// The status and residuals of the final r, first projected on its cones
/// (a no-op to rounding for a converged r; for a Newton iterate that
/// stopped outside, the nearest admissible impulses; for μ = 0 exactly
/// zero tangential parts), so that every returned impulse is in its cone.
fn finish(
    p: &FrictionProblem,
    mut r: Vec<f64>,
    iterations: u64,
    known: Known,
    s: &FrictionSettings,
) -> FrictionSolution {
    let u = match (project_on_cones(p, &mut r), known) {
        (false, Known::Velocity(u)) => u,
        (_, Known::Pattern(pattern)) => {
            let mut u = vec![0.0; p.dim()];
            velocity_sparse(p, pattern, &r, &mut u);
            u
        }
        _ => {
            let mut u = vec![0.0; p.dim()];
            velocity_into(p, &r, &mut u);
            u
        }
    };
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
