//! The proximal-point iteration on the Coulomb problem (as Siconos'
//! FC3D_PROX): around the last iterate r_k, solve the problem with W + αI
//! and q − α r_k, whose solution r_{k+1} is r_k exactly when r_k solves the
//! original problem (then u + α(r − r_k) = u). W + αI is positive definite
//! where W is only semidefinite (the four coplanar corners of a box, more
//! contact directions than the bodies' degrees of freedom), so that the
//! inner Alart–Curnier Newton ([`newton_in`]) meets a regular ∂Φ where it
//! stalls on the original problem.
//!
//! α follows the outer error e (Siconos' default strategy): α = σ e d̄,
//! σ = 5, with d̄ the mean of W's normal diagonal entries (so that scaling W
//! scales α: Siconos' α = σ e is in W's units); where the inner Newton does
//! not reach its tolerance, α grows tenfold (a stronger regularisation,
//! a shorter step). The inner tolerance is max(e / 10, tolerance): loose
//! while the outer iterate is far, the tolerance at the end.
//!
//! The inner Newton's scalings ρ_i = 1/(W_ii,nn + α) convert velocities
//! into impulses (x = r − ρ u) at the contact's own effective mass. On a
//! heavy box resting on a light one that mass is the light box's, while
//! the impulses carry the heavy box's momentum: r/u is up to the mass
//! ratio larger than 1/W_ii, so that in Φ the sliding directions and the
//! normal complementarity (ρ u) weigh next to nothing beside r's
//! rounding-scale mismatches; the inner Newton then takes steps of 1/8 to
//! 1/16 and fails its budget, α grows tenfold, shrinks again, and the
//! outer error creeps (a few percent per step). Where the outer error has
//! not halved over [`CREEP_STEPS`] inner steps, ρ is raised tenfold, at
//! most to [`RHO_MAX`] times W's (see those constants for the measures).

use super::newton::newton_in;
use super::problem::FrictionProblem;
use super::workspace::Workspace;

/// σ of α = σ e d̄ (Siconos' default 5).
const SIGMA: f64 = 5.0;

/// The inner tolerance is the outer error divided by this (Siconos' 10),
/// and at least the outer tolerance.
const INNER_RATIO: f64 = 10.0;

/// α's factor after a solved inner problem (Siconos keeps 1): the
/// factor shrinks while the inner problems are easy, so that the outer
/// steps lengthen where W is only semidefinite and σ e alone holds them
/// short (heavy boxes on light ones).
const SHRINK: f64 = 0.5;

/// The smallest factor.
const MIN_BOOST: f64 = 1e-6;

/// Newton steps of one inner solve at most. Near a degenerate solution
/// (W singular, q outside W's range by 1e-10 of ‖q‖: a pile that can rest
/// on its contacts only to rounding) an inner problem that Newton has not
/// solved in a few steps is rarely solved in more, and α grows only once
/// it gives up: of the 24 islands `rain:32` left unsolved over 4 worlds ×
/// 1,000 steps (replayed with their warm starts, 1e-12, the cap of
/// 1,000), 20 inner steps solved none, 5 solved 6 (3 to 8 solved 6 or 7);
/// of 482 islands that took `auto` more than 20 iterations in 10 worlds ×
/// 300 steps, 443 were solved with 20 and 448 with 5, in 5% fewer
/// iterations.
const INNER_STEPS: u64 = 5;

/// The inner Newton's line search is nonmonotone over this many merits
/// (`Workspace::window`): near a degenerate solution (a pile resting on
/// more contacts than its bodies' degrees of freedom, W + αI with α ~ 1e-9
/// of W's diagonal) the Newton direction crosses a kink of Φ and monotone
/// Armijo accepts only steps of 1e-4–1e-3, step after step; the full steps
/// it then takes converge. On the 107 islands left unsolved in `rain:32`
/// (4 worlds × 1,000 steps, 1e-12, cold), PROX alone at the cap of 1,000
/// solved 53 with a monotone search, 86 with this window.
const WINDOW: usize = 10;

/// Inner Newton steps over which the outer error must halve; where it
/// does not, the inner scalings ρ grow [`RHO_GAIN`]-fold (module docs).
/// On the stacks of `src/tests/friction_hard.rs` (648 of 2–4 boxes, mass
/// ratios 1e2–1e4, μ 0.3–2, three seeds: 1,944 islands at the default cap
/// of 1,000), without it 10 end `not_converged`, with 50 or 100 none; a
/// fixed ρ ten times W's left 2 of one seed's 648 unsolved, three times 1,
/// thirty times 42.
const CREEP_STEPS: u64 = 50;

/// ρ's factor where PROX creeps.
const RHO_GAIN: f64 = 10.0;

/// ρ at most this many times W's 1/W_ii,nn (a factor of 1e3 or more for
/// every island left 29 of the 216 stacks of one seed unsolved).
const RHO_MAX: f64 = 100.0;

/// PROX from `r` with `ws` prepared for `p` and `ws.u` = W r + q: outer
/// steps until the Coulomb error of `p` is at most `tolerance` or
/// `max_steps` inner Newton steps ran (an inner solve that makes no step
/// counts one). Returns (inner steps, error of the final r); `ws.u` is then
/// exact for r. The inner problems are solved in a workspace of their own
/// ([`ProxScratch`], kept in `ws` between calls).
pub(crate) fn prox_in(
    p: &FrictionProblem,
    ws: &mut Workspace,
    r: &mut [f64],
    max_steps: u64,
    tolerance: f64,
) -> (u64, f64) {
    let (n, k) = (p.dim(), p.contacts());
    let mut error = ws.error(p, r);
    let mean = (0..k).map(|i| p.at(3 * i, 3 * i)).sum::<f64>() / k as f64;
    let scale = if mean > 0.0 && mean.is_finite() {
        mean
    } else {
        1.0
    };
    let mut boost = 1.0;
    let mut alpha = SIGMA * error * scale;
    let mut scratch = ws.prox.take().unwrap_or_default();
    let ProxScratch {
        problem: inner,
        workspace: inner_ws,
    } = &mut *scratch;
    inner.w.clone_from(&p.w);
    inner.q.clone_from(&p.q);
    inner.mu.clone_from(&p.mu);
    // W + αI has W's block pattern (the diagonal blocks are always in it).
    inner_ws.pattern.copy_from(&ws.pattern);
    // The outer Newton's 3k × 3k buffers, idle while PROX runs, serve the
    // inner one (given back below).
    ws.lend_newton_buffers(inner_ws);
    let mut steps = 0;
    let mut creep = Creep::new(error);
    while steps < max_steps && !(error <= tolerance) && error.is_finite() {
        for i in 0..n {
            inner.w[i * n + i] = p.w[i * n + i] + alpha;
            inner.q[i] = p.q[i] - alpha * r[i];
        }
        if steps == 0 {
            inner_ws.prepare_with(inner, r, true);
            inner_ws.window = WINDOW;
        } else {
            inner_ws.refit(inner, r);
        }
        let rho_scale = creep.rho_scale(steps, error);
        if rho_scale != 1.0 {
            inner_ws.rho.iter_mut().for_each(|rho| *rho *= rho_scale);
        }
        let inner_tolerance = (error / INNER_RATIO).max(tolerance);
        let budget = INNER_STEPS.min(max_steps - steps);
        let (taken, inner_error) = newton_in(inner, inner_ws, r, budget, inner_tolerance);
        steps += taken.max(1);
        ws.refresh(p, r);
        error = ws.error(p, r);
        // A solved inner problem: a weaker regularisation next (longer
        // steps); an unsolved one: a stronger one.
        boost = if inner_error <= inner_tolerance {
            (boost * SHRINK).max(MIN_BOOST)
        } else {
            boost * 10.0
        };
        alpha = SIGMA * error * scale * boost;
    }
    inner_ws.lend_newton_buffers(ws);
    ws.prox = Some(scratch);
    (steps, error)
}

/// PROX's watch on its own progress: the factor on the inner Newton's
/// scalings ρ, raised [`RHO_GAIN`]-fold (to at most [`RHO_MAX`]) each time
/// the outer error has not halved over [`CREEP_STEPS`] inner steps.
struct Creep {
    /// The factor on ρ (1 at first: W's own scalings).
    scale: f64,
    /// The inner steps and the outer error where the last window began.
    mark: (u64, f64),
}

impl Creep {
    fn new(error: f64) -> Self {
        Creep {
            scale: 1.0,
            mark: (0, error),
        }
    }

    /// The factor on ρ after `steps` inner steps at outer `error`: a new
    /// window starts every [`CREEP_STEPS`] steps, and the factor grows
    /// where the error did not halve over the one that ended (a non-finite
    /// error never reaches here: PROX stops on it).
    fn rho_scale(&mut self, steps: u64, error: f64) -> f64 {
        let (from, then) = self.mark;
        if steps >= from + CREEP_STEPS {
            if error > then / 2.0 && self.scale < RHO_MAX {
                self.scale *= RHO_GAIN;
            }
            self.mark = (steps, error);
        }
        self.scale
    }
}

/// PROX's inner problem W + αI, q − α r_k and the workspace that solves
/// it, kept in the outer [`Workspace`] (`Workspace::prox`) so that a PROX
/// call allocates nothing after a thread's first on an island of its size:
/// W's copy (3k × 3k; on 276 contacts 5.5 MB, whose fresh pages and a
/// fresh workspace's cost half the time of a PROX call) reuses its buffer.
#[derive(Debug)]
pub(crate) struct ProxScratch {
    problem: FrictionProblem,
    workspace: Workspace,
}

impl Default for ProxScratch {
    fn default() -> Self {
        ProxScratch {
            problem: FrictionProblem {
                w: Vec::new(),
                q: Vec::new(),
                mu: Vec::new(),
            },
            workspace: Workspace::default(),
        }
    }
}
