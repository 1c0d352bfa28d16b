//! The CPU path of the [`Solver`](super::Solver): f64, every core. LCP
//! batches ([`lcps_on_cpu`]) and the islands of built scenes
//! ([`scenes_on_cpu`], through [`scenes_with`]: solve, then impulses), one
//! island at a time by [`solve_island`] (prediction, checked Lemke,
//! enumeration; or the one method asked).

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use super::dense::Problems;
use super::SolverView;
use crate::build::Built;
use crate::cpu::batch::{parallel_fill, parallel_map};
use crate::cpu::enumeration::{
    enumerate, feasible_basis_into, EnumerationSettings, MAX_ENUMERATION_N,
};
use crate::cpu::impulses::apply_impulses;
use crate::cpu::lemke::{lemke, lemke_textbook_basis, LemkeSettings};
use crate::cpu::pgs::pgs;
use crate::lcp::{Lcp, LcpSolution, Status};
use crate::prediction::predict_into;
use crate::report::{IslandReport, Report, SceneReport, SolvePath};
use crate::scene::Scene;
use crate::settings::{Backend, Method, Settings};
use crate::short_vec::ShortVec;
use crate::Error;

/// LCPs on the CPU, each checked (`Lcp::validate`) in the parallel pass
/// that solves it: an error names the first bad problem. `keys[i]`:
/// problem i's contact ids, whose warm basis (with
/// `settings.warm_start`) is looked up in that pass too. Everything per
/// problem (check, warm basis, solve, the final check of the answer, its
/// report) runs on the threads; only the batch's counts are serial.
/// Enumeration (and all_solutions) on the CPU backend refuses n > 20;
/// after device trouble (or with backend Auto) such problems go to
/// Lemke, as on the GPU path.
pub(super) fn lcps_on_cpu(
    solver: &SolverView,
    lcps: &[Lcp],
    keys: Option<&[&[u64]]>,
) -> Result<Report, Error> {
    problems_on_cpu(solver, Problems::Built(lcps), keys)
}

/// [`lcps_on_cpu`] of a batch built or dense ([`Problems`]): each problem
/// is checked on its slices and solved through [`Problems::with`].
pub(super) fn problems_on_cpu(
    solver: &SolverView,
    lcps: Problems,
    keys: Option<&[&[u64]]>,
) -> Result<Report, Error> {
    let settings = solver.settings;
    let big_to_lemke = settings.backend != Backend::Cpu;
    let enumerates = settings.method == Method::Enumeration || settings.all_solutions;
    let t = Instant::now();
    let invalid = AtomicBool::new(false);
    // Every report is written where the batch's report keeps it (no
    // move of a few hundred bytes per island). A placeholder stays only
    // where a problem fails its checks, and never leaves: the call
    // returns the error.
    let mut islands: Vec<IslandReport> = Vec::with_capacity(lcps.len());
    islands.resize_with(lcps.len(), || IslandReport {
        scene: None,
        contacts: ShortVec::new(),
        method: settings.method,
        path: SolvePath::Invalid,
        solution: LcpSolution::invalid(0),
    });
    parallel_fill(&mut islands, solver.threads, |i, island| {
        let n = lcps.n(i);
        // The item's name is formatted only for the error, below.
        if lcps.validate(i, "problem").is_err()
            || (!big_to_lemke && enumerates && n > MAX_ENUMERATION_N)
        {
            invalid.store(true, Ordering::Relaxed);
            return;
        }
        let warm = keys.and_then(|k| solver.warm_basis(k[i]));
        let (mut method, mut path) = (Method::Lemke, SolvePath::Lemke);
        island.contacts = ShortVec::indices(n);
        lcps.with(i, |lcp| {
            solve_island(
                lcp,
                warm,
                settings,
                &mut method,
                &mut path,
                &mut island.solution,
            )
        });
        (island.method, island.path) = (method, path);
        check_solution(&mut island.solution, settings.tolerance);
    });
    if invalid.load(Ordering::Relaxed) {
        for i in 0..lcps.len() {
            lcps.validate(i, format_args!("problem {i}"))?;
        }
        for (i, n) in lcps.sizes().enumerate() {
            if !big_to_lemke && enumerates && n > MAX_ENUMERATION_N {
                return Err(Error::Unsupported(format!(
                    "problem {i}: enumeration visits 2^n bases and is limited to n ≤ {MAX_ENUMERATION_N} (this problem has n = {n}); use Lemke"
                )));
            }
        }
    }
    let mut r = solver.report(islands, Vec::new(), solver.cpu_device());
    r.timings.solve = t.elapsed().as_secs_f64();
    Ok(r)
}

/// The CPU path for checked scenes, from what was built of them: every
/// island of every scene over the cores. `warm`: per scene, per island,
/// the warm basis (empty: none).
pub(super) fn scenes_on_cpu(
    solver: &SolverView,
    scenes: &[&Scene],
    built: &[Built],
    warm: &[Vec<Option<u32>>],
) -> Result<Report, Error> {
    scenes_with(solver, scenes, built, |index, lcps| {
        Ok(parallel_map(index.len(), solver.threads, |j| {
            let (s, k) = index[j];
            let w = warm.get(s).and_then(|w| w[k]);
            solve_on_cpu(lcps[j], w, solver.settings)
        }))
    })
}

/// Checked scenes, from what was built of them, in phases: solve
/// (`solve` gets every island of every scene, flattened, as (scene,
/// island) and its LCP, and returns one result per island, in order),
/// impulses. The report's device is the CPU.
pub(super) fn scenes_with(
    solver: &SolverView,
    scenes: &[&Scene],
    built: &[Built],
    solve: impl FnOnce(&[(usize, usize)], &[&Lcp]) -> Result<Vec<Solved>, Error>,
) -> Result<Report, Error> {
    let t = Instant::now();
    // Every island of every scene, flattened: (scene, island).
    let index: Vec<(usize, usize)> = built
        .iter()
        .enumerate()
        .flat_map(|(s, b)| (0..b.lcps.len()).map(move |k| (s, k)))
        .collect();
    let lcps: Vec<&Lcp> = index.iter().map(|&(s, k)| &built[s].lcps[k]).collect();
    let solved = solve(&index, &lcps)?;
    let solve = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let mut islands = Vec::with_capacity(index.len());
    let mut out = Vec::with_capacity(scenes.len());
    let mut solved = solved.into_iter();
    for (s, (scene, b)) in scenes.iter().zip(built).enumerate() {
        let first = islands.len();
        let mut impulses = vec![0.0; scene.contacts.len()];
        for island in &b.islands {
            let (method, path, solution) = solved.next().expect("one result per island");
            for (&c, &zi) in island.contacts.iter().zip(&solution.z) {
                impulses[c] = zi;
            }
            islands.push(IslandReport {
                scene: Some(s),
                contacts: island.contacts.iter().copied().collect(),
                method,
                path,
                solution,
            });
        }
        let bodies = apply_impulses(scene, &b.rows, &impulses);
        out.push(SceneReport {
            impulses,
            bodies,
            islands: first..islands.len(),
            friction: None,
        });
    }
    check(&mut islands, solver.settings.tolerance);
    let mut report = solver.report(islands, out, solver.cpu_device());
    report.timings.solve = solve;
    report.timings.impulses = t.elapsed().as_secs_f64();
    Ok(report)
}

/// The final check of every island, on every backend and method
/// ([`check_solution`] on each answer).
pub(super) fn check(islands: &mut [IslandReport], tolerance: f64) {
    for isl in islands {
        check_solution(&mut isl.solution, tolerance);
    }
}

/// The final check of one answer: a solution whose z, w or error is not
/// finite, or whose error is above `tolerance` (`settings.tolerance`),
/// becomes `numerical_failure`.
pub(crate) fn check_solution(s: &mut crate::LcpSolution, tolerance: f64) {
    if s.status.is_solution() && !s.passes_check(tolerance) {
        s.status = crate::Status::NumericalFailure;
    }
}

/// The reports of an LCP batch's answers, in order.
pub(super) fn lcp_islands(lcps: &[Lcp], solved: Vec<Solved>) -> Vec<IslandReport> {
    solved
        .into_iter()
        .zip(lcps)
        .map(|((method, path, solution), lcp)| IslandReport {
            scene: None,
            contacts: ShortVec::indices(lcp.n()),
            method,
            path,
            solution,
        })
        .collect()
}

/// One island's answer: the method that ran, the path, the solution.
pub(super) type Solved = (Method, SolvePath, LcpSolution);

/// One island on the CPU with the chosen method: (method that ran, path, solution).
///
/// Auto and Enumeration: prediction first (with `settings.predict`), then
/// Auto's checked Lemke ([`lemke_checked`]), then enumeration by size;
/// islands above n = 20 go to Lemke (the LCP path refuses them on the CPU
/// backend with Enumeration before it gets here).
pub(super) fn solve_on_cpu(lcp: &Lcp, warm: Option<u32>, s: &Settings) -> Solved {
    let (mut method, mut path) = (Method::Lemke, SolvePath::Lemke);
    let mut solution = LcpSolution::invalid(0);
    solve_island(lcp, warm, s, &mut method, &mut path, &mut solution);
    (method, path, solution)
}

/// [`solve_on_cpu`] with the method and path written to `method` and
/// `path` (both as they come in where Lemke answers) and the solution to
/// `out`: the LCP batch's path writes each answer where its report keeps
/// it (see [`crate::cpu::enumeration::feasible_basis_into`]).
pub(super) fn solve_island(
    lcp: &Lcp,
    warm: Option<u32>,
    s: &Settings,
    method: &mut Method,
    path: &mut SolvePath,
    out: &mut LcpSolution,
) {
    match s.method {
        Method::Lemke => *out = lemke(lcp, &s.lemke()),
        Method::Pgs => {
            (*method, *path) = (Method::Pgs, SolvePath::Pgs);
            *out = pgs(lcp, &s.pgs());
        }
        Method::Auto | Method::Enumeration if lcp.n() > MAX_ENUMERATION_N => {
            *out = lemke(lcp, &s.lemke());
        }
        Method::Auto | Method::Enumeration => {
            let e = s.enumeration();
            if s.predict && !s.all_solutions {
                let mut how = SolvePath::Separating;
                if predict_into(lcp, warm, &e, &mut how, out) {
                    (*method, *path) = (Method::Enumeration, how);
                    return;
                }
            }
            if s.method == Method::Auto && !s.all_solutions {
                lemke_else_enumerate(lcp, &s.lemke(), &e, s.tolerance, method, path, out);
            } else {
                (*method, *path) = (Method::Enumeration, SolvePath::EnumeratedCpu);
                *out = enumerate(lcp, &e).expect("n ≤ 20 and settings validated in Solver::new");
            }
        }
    }
}

/// Auto's answer for an island of n ≤ 20 that prediction did not settle:
/// the checked Lemke ([`lemke_checked`]; method and path left as they come
/// in), else the CPU enumeration (method Enumeration, path EnumeratedCpu,
/// Lemke's pivots added to its counters). The GPU path's Lemke kernel
/// hands the islands whose basis it cannot settle to this.
pub(crate) fn lemke_else_enumerate(
    lcp: &Lcp,
    lemke_settings: &LemkeSettings,
    e: &EnumerationSettings,
    tolerance: f64,
    method: &mut Method,
    path: &mut SolvePath,
    out: &mut LcpSolution,
) {
    let mut pivots = 0;
    if lemke_checked(lcp, lemke_settings, e, tolerance, &mut pivots, out) {
        return;
    }
    (*method, *path) = (Method::Enumeration, SolvePath::EnumeratedCpu);
    *out = enumerate(lcp, e).expect("n ≤ 20 and settings validated in Solver::new");
    out.counters.pivots += pivots;
}

/// Lemke, its final basis re-solved in f64 and checked with enumeration's
/// tolerances (the check every GPU answer goes through: feasible, M_SS not
/// singular); the solution is the re-solve's. Where that basis (and the
/// bases of its answer's support) fail the check, Lemke's own answer is
/// taken when the final check ([`check_solution`]) passes it.
/// Written into `out` (true); false when Lemke did not end on a solution
/// or none passes (`out` then holds no answer: a refused one, or what it
/// held); `pivots`: the pivots spent.
///
/// The textbook run's basis is checked first ([`lemke_textbook_basis`]:
/// no tableau read-back, no polish, since the re-solve here is the answer);
/// where it does not give a checked solution with an error of at most 1e-12,
/// the whole of [`lemke`] (its scaled and covering-vector retries) runs.
fn lemke_checked(
    lcp: &Lcp,
    lemke_settings: &LemkeSettings,
    e: &EnumerationSettings,
    tolerance: f64,
    pivots: &mut u64,
    out: &mut LcpSolution,
) -> bool {
    let (mask, first_pivots) = lemke_textbook_basis(lcp, lemke_settings);
    *pivots = first_pivots;
    if let Some(mask) = mask {
        if textbook_checked(lcp, mask, first_pivots, e, out) {
            return true;
        }
    }
    let l = lemke(lcp, lemke_settings);
    *pivots = l.counters.pivots;
    let (Status::Solved, Some(mask)) = (l.status, l.basis) else {
        return false;
    };
    let p = *pivots;
    if checked_basis(lcp, mask, p, e, out)
        || checked_basis(lcp, support(&l.z, 0.0), p, e, out)
        || checked_basis(lcp, support(&l.z, SUPPORT_DROP), p, e, out)
    {
        return true;
    }
    // Lemke's own answer where the final check passes it (z, w
    // finite, the error recomputed from M and q in f64 within the
    // tolerance). On a degenerate island every basis through it can be
    // singular or ill-conditioned to the basis check (a resting 4-box
    // stack, 16 contacts, M of rank 12: a box held on two diagonal
    // corners) while the answer is right to 1e-11…1e-9; 1 world × 6,000
    // steps of that stack enumerated 2^16 bases (~70 ms each) on 459
    // steps without this, on 2 with it (`a_resting_stack_is_seldom_enumerated`).
    let passes = l.passes_check(tolerance);
    if passes {
        *out = l;
    }
    passes
}

/// Impulses at or below this fraction of the largest are left out of the
/// second support tried (see [`support`]).
const SUPPORT_DROP: f64 = 1e-9;

/// The contacts whose impulse exceeds `drop` × the largest, as a basis mask.
/// On a degenerate problem (a resting 4-box stack: 16 contacts, M of rank 12)
/// Lemke can end on a basis that holds some z_i = 0, or z_i ≈ 1e-10 beside
/// impulses of 200, whose M_SS is singular, which the check refuses. The
/// same answer on its (large) support is usually a regular basis; it is
/// re-solved and checked like any other (an infeasible one is refused), for
/// far less than enumerating 2^16 bases.
fn support(z: &[f64], drop: f64) -> u32 {
    let floor = drop * z.iter().fold(0.0_f64, |m, &zi| m.max(zi));
    z.iter()
        .enumerate()
        .filter(|(_, &zi)| zi > floor)
        .fold(0, |m, (i, _)| m | 1 << i)
}

/// The error at or below which the textbook run's checked basis is the
/// answer ([`lemke`] itself retries above it).
const TEXTBOOK_ACCEPT: f64 = 1e-12;

/// The textbook run's basis `mask` (after `pivots` pivots) re-solved in f64
/// and checked ([`checked_basis`]), taken when its error is at most
/// [`TEXTBOOK_ACCEPT`]: true with the answer in `out` (else `out` holds a
/// refused answer or what it held). The CPU path's first test of Lemke's
/// answer, and the GPU's of the Lemke kernel's basis: where the two name
/// the same basis, the answers are the same bytes.
pub(crate) fn textbook_checked(
    lcp: &Lcp,
    mask: u32,
    pivots: u64,
    e: &EnumerationSettings,
    out: &mut LcpSolution,
) -> bool {
    checked_basis(lcp, mask, pivots, e, out) && out.residuals.error <= TEXTBOOK_ACCEPT
}

/// Basis `mask` re-solved in f64 and checked (feasible, M_SS not singular):
/// the solution with `pivots` in its counters written into `out` (true),
/// or false with `out` untouched.
fn checked_basis(
    lcp: &Lcp,
    mask: u32,
    pivots: u64,
    e: &EnumerationSettings,
    out: &mut LcpSolution,
) -> bool {
    let counters = crate::lcp::Counters {
        pivots,
        ..Default::default()
    };
    feasible_basis_into(lcp, mask, e, counters, || true, out)
}
