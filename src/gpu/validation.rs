//! Validation of every GPU answer on the CPU, in f64.
//!
//! The check, not a second solve: where the shader ran in f64 (the exact
//! twin: the CPU's tolerances) and named a basis with its z, the CPU
//! recomputes w = M z + q in f64 from the input and checks the GPU's z
//! ([`accept_gpu_z`]): every entry finite, z ≥ 0 and 0 outside the basis,
//! w ≥ 0 within the feasibility tolerance (relative, as the enumeration
//! measures it: −w_i ≤ tol·(|q_i| + Σ_j |M_ij z_j|)), and the error measure
//! (complementarity included) at most [`ACCEPT_ERROR`] and the door's
//! tolerance. Such an answer is kept as the GPU gave it ("accepted": z the
//! GPU's bytes, w and the residuals the CPU's f64), O(n²), nothing
//! allocated. Otherwise, and for every answer of an f32 shader, the CPU
//! - solves that basis again in f64 ("polished",
//!   [`crate::cpu::enumeration::feasible_basis_into`]: one k×k solve and
//!   one n×n product, O(k³ + n²), the very function the CPU path settles
//!   its islands with, so the bytes are the CPU's) and keeps it when it is
//!   valid in f64 with the CPU's tolerances (z ≥ 0, w = Mz + q ≥ 0 within
//!   the feasibility tolerance, M_SS not singular): z and w then come from
//!   f64 arithmetic only, and the door's final check recomputes the error
//!   from them;
//! - otherwise solves the island by the CPU enumeration and counts it as
//!   repaired;
//! - when the GPU found no valid basis, confirms it by the CPU enumeration
//!   (the rare path: physical islands nearly always have a solution), so that
//!   the status equals the CPU's.
//!
//! The Lemke kernel (methods Auto and Lemke) names the basis its textbook
//! path ended on; [`check_lemke_answer`] accepts its f64 z by the same
//! check, else re-solves and checks the basis with the CPU path's own test
//! of Lemke's textbook basis ([`crate::solver::textbook_checked`]), and
//! where that fails, or the kernel gave up, solves the island by the CPU
//! path's code for the rest.
//!
//! The settle kernel's answers (an island's warm or predicted basis,
//! tried on the device before the others run) are checked the same way
//! ([`check_settled`]) and keep prediction's paths and counters.
//!
//! With the same visit order and rule (fewest basic z, then the smallest
//! mask) as the CPU, an island's chosen basis is the CPU's whenever the GPU
//! accepted every basis f64 accepts before it; the f64 shaders use the CPU's
//! tolerances for that reason. An accepted z differs from the CPU's
//! re-solve of the same basis by rounding only (the error bound keeps it
//! within about 1e-12 of it, relative).

use crate::cpu::enumeration::{
    enumerate, feasible_basis_into, solved_on_basis, EnumerationSettings,
};
use crate::cpu::lemke::lemke;
use crate::gpu::batch::GpuSolveSettings;
use crate::gpu::layout::{hinted, BasisResult, FOUND, RELAXED, SETTLED_PREDICTED, SETTLED_WARM};
use crate::lcp::{Counters, Lcp, LcpSolution, Residuals, Status};
use crate::linalg::solve_in_place;
use crate::prediction::hinted_into;
use crate::report::IslandReport;
use crate::report::SolvePath;
use crate::settings::Method;
use crate::solver::check_solution;
use crate::solver::{lemke_else_enumerate, textbook_checked};
use crate::Error;

use std::time::Instant;

/// What the GPU reported for one island.
#[derive(Clone, Copy, Debug)]
pub struct GpuVerdict<'a> {
    /// The chosen basis, None when no basis was valid on the GPU.
    pub basis: Option<u32>,
    /// The basis is not valid but the least infeasible one within the relaxed
    /// tolerance (every basis was visited).
    pub relaxed: bool,
    pub visited: u64,
    pub singular: u64,
    /// The GPU's z (in its precision, widened to f64); may be empty.
    pub z: &'a [f64],
}

impl<'a> GpuVerdict<'a> {
    /// The verdict of the enumeration stage's record.
    pub fn of(r: &BasisResult, z: &'a [f64]) -> Self {
        GpuVerdict {
            basis: (r.status == FOUND || r.status == RELAXED).then_some(r.mask),
            relaxed: r.status == RELAXED,
            visited: r.visited as u64,
            singular: r.singular as u64,
            z,
        }
    }
}

/// Relative infeasibility of basis `mask` in f64, as the CPU enumeration
/// measures it (the worst of −z_i/‖z_S‖∞ and −w_i/(|q_i| + Σ_j |M_ij z_j|)),
/// with z (clamped at 0); None when M_SS is singular. O(k³ + n²).
pub fn basis_infeasibility(
    lcp: &Lcp,
    mask: u32,
    settings: &EnumerationSettings,
) -> Option<(f64, Vec<f64>)> {
    let n = lcp.n();
    let idx: Vec<usize> = (0..n).filter(|&i| mask >> i & 1 == 1).collect();
    let k = idx.len();
    let mut a = vec![0.0; k * k];
    let mut x = vec![0.0; k];
    for (r, &i) in idx.iter().enumerate() {
        for (c, &j) in idx.iter().enumerate() {
            a[r * k + c] = lcp.at(i, j);
        }
        x[r] = -lcp.q[i];
    }
    if !solve_in_place(&mut a, &mut x, k, settings.pivot_tol) {
        return None;
    }
    let zmax = x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let mut worst = 0.0f64;
    for &v in &x {
        if v < 0.0 {
            worst = worst.max(-v / zmax);
        }
    }
    let mut z = vec![0.0; n];
    for (r, &i) in idx.iter().enumerate() {
        z[i] = x[r];
    }
    for i in (0..n).filter(|&i| mask >> i & 1 == 0) {
        let (mut w, mut scale) = (lcp.q[i], lcp.q[i].abs());
        for &j in &idx {
            let t = lcp.at(i, j) * z[j];
            w += t;
            scale += t.abs();
        }
        if w < 0.0 {
            worst = worst.max(-w / scale);
        }
    }
    Some((worst, z.into_iter().map(|v| v.max(0.0)).collect()))
}

/// The largest error measure at which the GPU's own z is accepted (the
/// door's tolerance caps it too): the CPU path's bound for Lemke's
/// textbook basis (`TEXTBOOK_ACCEPT` in `src/solver/cpu_path.rs`), which
/// keeps an accepted z within rounding of its basis's f64 re-solve.
pub const ACCEPT_ERROR: f64 = 1e-12;

/// The GPU's `z` for basis `mask` written into `out` as an answer would
/// be: z as given, w = M z + q and the residuals recomputed in f64 from
/// the input. Returns the error measure of the GPU's z (NaN where it has
/// not n entries: then `out` is untouched) and whether z is well formed
/// and feasible: every z_i and w_i finite, z ≥ 0 and 0 outside the basis,
/// and −w_i ≤ `feasibility_tol` · (|q_i| + Σ_j |M_ij z_j|) (the
/// enumeration's relative measure). O(n²), nothing allocated for n ≤ 8
/// (`out`'s own z and w are the scratch).
pub(crate) fn gpu_answer_into(
    lcp: &Lcp,
    mask: u32,
    z: &[f64],
    feasibility_tol: f64,
    out: &mut LcpSolution,
) -> (f64, bool) {
    let n = lcp.n();
    if z.len() != n {
        return (f64::NAN, false);
    }
    out.z.reset(0.0, n);
    out.z.copy_from_slice(z);
    out.w.reset(0.0, n);
    lcp.w_into(&out.z, &mut out.w);
    out.residuals = Residuals::of(&out.z, &out.w, &lcp.q);
    let feasible = mask >> n == 0
        && (0..n).all(|i| {
            let (zi, wi, basic) = (out.z[i], out.w[i], mask >> i & 1 == 1);
            let row = &lcp.m[i * n..(i + 1) * n];
            zi.is_finite()
                && wi.is_finite()
                && zi >= 0.0
                && (basic || zi == 0.0)
                && (basic
                    || wi >= 0.0
                    || -wi
                        <= feasibility_tol
                            * row
                                .iter()
                                .zip(z)
                                .fold(lcp.q[i].abs(), |s, (a, b)| s + (a * b).abs()))
        });
    (out.residuals.error, feasible)
}

/// The GPU's own `z` for basis `mask` checked in f64, not solved again
/// ([`gpu_answer_into`], then the error measure at most [`ACCEPT_ERROR`]
/// and `tolerance`): where it passes and `exact_twin` (an f64 shader with
/// the CPU's tolerances), `out` is that answer (status Solved, basis
/// `mask`, `counters`) and the first value is true. The second is the
/// error of the GPU's z (NaN where it gave none), measured in every case.
pub(crate) fn accept_gpu_z(
    lcp: &Lcp,
    (mask, z): (u32, &[f64]),
    (exact_twin, feasibility_tol, tolerance): (bool, f64, f64),
    counters: Counters,
    out: &mut LcpSolution,
) -> (bool, f64) {
    let (error, feasible) = gpu_answer_into(lcp, mask, z, feasibility_tol, out);
    let accepted = exact_twin && feasible && error <= ACCEPT_ERROR.min(tolerance);
    if accepted {
        solved_on_basis(mask, counters, out);
    }
    (accepted, error)
}

/// What validation decided.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// The GPU's z passed the f64 check and is the answer as it gave it
    /// (w and the residuals recomputed in f64): [`accept_gpu_z`].
    Accepted,
    /// The GPU's basis is valid in f64; z, w recomputed in f64 (the basis
    /// re-solved).
    Polished,
    /// The GPU found no valid basis and the CPU agrees.
    ConfirmedNoSolution,
    /// The GPU's answer was wrong in f64; the CPU enumeration's is used.
    Repaired,
    /// The settle kernel's warm or predicted basis, checked in f64
    /// ([`check_settled`]): counted with prediction's islands (path
    /// WarmStart or PredictedBasis), not as a GPU answer.
    Predicted,
}

/// Checks the GPU's answer for `lcp` in f64 and writes the island's answer
/// into `out` (see the module docs): its own z accepted where `accept`
/// (an f64 shader with the CPU's tolerances that solved `lcp` itself) and
/// it passes [`accept_gpu_z`] (`tolerance`: the door's), else its basis
/// re-solved.
/// A relaxed basis (no valid one exists) is kept when `exact_twin` (the
/// shaders are the exact f64 twin, so it is the CPU's choice) and it is
/// within the relaxed tolerance in f64; otherwise the CPU decides. Returns
/// the verdict and the error measure of the GPU's own z against the f64
/// problem (NaN when the GPU gave none). The seconds of a repair (the CPU
/// enumeration) are added to `repair`.
///
/// # Errors
/// Those of the CPU enumeration (none for a checked problem of n ≤ 20).
pub fn check_answer(
    lcp: &Lcp,
    gpu: &GpuVerdict<'_>,
    settings: &EnumerationSettings,
    (exact_twin, accept, tolerance): (bool, bool, f64),
    out: &mut LcpSolution,
    repair: &mut f64,
) -> Result<(Verdict, f64), Error> {
    let n = lcp.n();
    let counters = Counters {
        bases_visited: gpu.visited,
        singular_bases: gpu.singular,
        ..Counters::default()
    };
    let Some(mask) = gpu.basis else {
        return enumerate_instead(lcp, settings, true, out, repair).map(|v| (v, f64::NAN));
    };
    let feasibility = settings.feasibility_tol;
    let strict = accept && !gpu.relaxed;
    let check = (strict, feasibility, tolerance);
    let (accepted, gpu_error) = accept_gpu_z(lcp, (mask, gpu.z), check, counters, out);
    if accepted {
        return Ok((Verdict::Accepted, gpu_error));
    }
    if gpu.relaxed && exact_twin && mask >> n == 0 {
        if let Some((v, z)) = basis_infeasibility(lcp, mask, settings) {
            if v > settings.feasibility_tol && v <= settings.relaxed_feasibility_tol {
                *out = LcpSolution::from_z(lcp, Status::Solved, z, counters);
                out.basis = Some(mask);
                return Ok((Verdict::Polished, gpu_error));
            }
        }
    }
    if !gpu.relaxed
        && mask >> n == 0
        && feasible_basis_into(lcp, mask, settings, counters, || true, out)
    {
        return Ok((Verdict::Polished, gpu_error));
    }
    enumerate_instead(lcp, settings, false, out, repair).map(|v| (v, gpu_error))
}

/// The CPU enumeration's answer for `lcp` in `out`, its seconds added to
/// `repair`: [`Verdict::ConfirmedNoSolution`] where the GPU found no basis
/// (`gpu_none`) and neither does the CPU, else [`Verdict::Repaired`].
fn enumerate_instead(
    lcp: &Lcp,
    settings: &EnumerationSettings,
    gpu_none: bool,
    out: &mut LcpSolution,
    repair: &mut f64,
) -> Result<Verdict, Error> {
    let t = Instant::now();
    *out = enumerate(lcp, settings)?;
    *repair += t.elapsed().as_secs_f64();
    Ok(if gpu_none && out.status == Status::NoSolution {
        Verdict::ConfirmedNoSolution
    } else {
        Verdict::Repaired
    })
}

/// The Lemke kernel's answer for `lcp` (its record and z) checked in f64
/// into `out`: a FOUND basis whose z passes [`accept_gpu_z`] (with
/// `accept`: an f64 shader that solved `lcp` itself) is the answer as the
/// GPU gave it (verdict Accepted); else
/// one that passes the CPU path's check of Lemke's textbook basis is
/// (re-solved in f64, verdict Polished: the CPU's bytes where the GPU
/// ended on the CPU's basis); both method Lemke, path LemkeGpu. Otherwise
/// the CPU path solves the island as it would after prediction:
/// `settings.method` Lemke by [`lemke`] (path Lemke), Auto by the checked
/// Lemke (path Lemke), else the CPU enumeration (path Repaired), verdict
/// Repaired. Returns (method, path, verdict) and the error of the GPU's
/// own z (NaN where it gave none). The seconds of the CPU path's solve
/// are added to `repair`.
pub fn check_lemke_answer(
    lcp: &Lcp,
    (result, z): (&BasisResult, &[f64]),
    (settings, accept): (&GpuSolveSettings, bool),
    out: &mut LcpSolution,
    repair: &mut f64,
) -> (Method, SolvePath, Verdict, f64) {
    let e = &settings.enumeration;
    let found = result.status == FOUND && result.mask >> lcp.n() == 0;
    let mut gpu_error = f64::NAN;
    if found {
        let counters = Counters {
            pivots: result.visited.into(),
            ..Counters::default()
        };
        let check = (accept, e.feasibility_tol, settings.tolerance);
        let accepted;
        (accepted, gpu_error) = accept_gpu_z(lcp, (result.mask, z), check, counters, out);
        if accepted {
            return (
                Method::Lemke,
                SolvePath::LemkeGpu,
                Verdict::Accepted,
                gpu_error,
            );
        }
    }
    if found && textbook_checked(lcp, result.mask, result.visited.into(), e, out) {
        return (
            Method::Lemke,
            SolvePath::LemkeGpu,
            Verdict::Polished,
            gpu_error,
        );
    }
    let (method, path) = lemke_instead(lcp, settings, out, repair);
    (method, path, Verdict::Repaired, gpu_error)
}

/// The CPU path's answer for `lcp` after prediction with `settings.method`
/// Lemke ([`lemke`]) or Auto (the checked Lemke, else the CPU enumeration:
/// then path Repaired), into `out`, as (method, path), its seconds added
/// to `repair`.
fn lemke_instead(
    lcp: &Lcp,
    settings: &GpuSolveSettings,
    out: &mut LcpSolution,
    repair: &mut f64,
) -> (Method, SolvePath) {
    let t = Instant::now();
    let (mut method, mut path) = (Method::Lemke, SolvePath::Lemke);
    if settings.method == Method::Lemke {
        *out = lemke(lcp, &settings.lemke);
    } else {
        let (l, e, tol) = (&settings.lemke, &settings.enumeration, settings.tolerance);
        lemke_else_enumerate(lcp, l, e, tol, &mut method, &mut path, out);
        if path == SolvePath::EnumeratedCpu {
            path = SolvePath::Repaired;
        }
    }
    *repair += t.elapsed().as_secs_f64();
    (method, path)
}

/// The settle kernel's answer for `lcp` (its record FOUND with `_pad1`
/// [`SETTLED_WARM`] or [`SETTLED_PREDICTED`], and z; `hint`: the island's
/// [`crate::gpu::layout::hint`]) checked in f64 into `out`: its z kept as
/// the GPU gave it where it passes [`accept_gpu_z`] (with `accept`: an f64
/// shader with the CPU's tolerances, which then judged each basis as the
/// CPU does); else the hint's bases solved on the host in the CPU path's
/// order ([`hinted_into`]: the CPU's bytes; f32 shaders always come here);
/// else, where neither is valid in f64, the CPU path's solve after
/// prediction (verdict Repaired; the enumeration's path Repaired). Returns
/// (method, path, verdict) and the error of the GPU's own z.
///
/// # Errors
/// Those of the CPU enumeration (none for a checked problem of n ≤ 20).
pub(crate) fn check_settled(
    lcp: &Lcp,
    (result, z): (&BasisResult, &[f64]),
    hint: u32,
    (settings, accept): (&GpuSolveSettings, bool),
    out: &mut LcpSolution,
    repair: &mut f64,
) -> Result<(Method, SolvePath, Verdict, f64), Error> {
    let e = &settings.enumeration;
    let path = match result._pad1 {
        SETTLED_WARM => SolvePath::WarmStart,
        _ => SolvePath::PredictedBasis,
    };
    let counters = Counters {
        bases_visited: 1,
        ..Counters::default()
    };
    let check = (accept, e.feasibility_tol, settings.tolerance);
    let (accepted, gpu_error) = accept_gpu_z(lcp, (result.mask, z), check, counters, out);
    if accepted {
        return Ok((Method::Enumeration, path, Verdict::Predicted, gpu_error));
    }
    if let Some(path) = hinted_into(lcp, hinted(hint), e, out) {
        return Ok((Method::Enumeration, path, Verdict::Predicted, gpu_error));
    }
    if settings.method != Method::Enumeration {
        let (method, path) = lemke_instead(lcp, settings, out, repair);
        return Ok((method, path, Verdict::Repaired, gpu_error));
    }
    let verdict = enumerate_instead(lcp, e, false, out, repair)?;
    Ok((Method::Enumeration, SolvePath::Repaired, verdict, gpu_error))
}

/// The GPU's answer for `lcp` (its record, z, and the island's
/// [`crate::gpu::layout::hint`]
/// word) checked in f64 into `out` ([`check_answer`]; the Lemke kernel's,
/// with `settings.method` Auto or Lemke, by [`check_lemke_answer`]; the
/// settle kernel's by [`check_settled`]), path and method set, the final check
/// applied; the seconds of a repair added to `repair`. `exact_twin`: the
/// shaders are the f64 twin; `accept`: and the GPU solved `lcp` itself (M
/// and q uploaded as given, not assembled on the device), so that its z,
/// where it passes the check, is kept as it is.
/// Returns the verdict and the error of the GPU's own z.
pub(crate) fn settle_from_gpu(
    lcp: &Lcp,
    (result, z, hint): (&BasisResult, &[f64], u32),
    settings: &GpuSolveSettings,
    (exact_twin, accept): (bool, bool),
    out: &mut IslandReport,
    repair: &mut f64,
) -> Result<(Verdict, f64), Error> {
    let accept = exact_twin && accept;
    if result.status == FOUND && matches!(result._pad1, SETTLED_WARM | SETTLED_PREDICTED) {
        let how = (settings, accept);
        let checked = check_settled(lcp, (result, z), hint, how, &mut out.solution, repair)?;
        let (method, path, verdict, gpu_error) = checked;
        (out.method, out.path) = (method, path);
        check_solution(&mut out.solution, settings.tolerance);
        return Ok((verdict, gpu_error));
    }
    if settings.method != Method::Enumeration {
        let (method, path, verdict, gpu_error) = check_lemke_answer(
            lcp,
            (result, z),
            (settings, accept),
            &mut out.solution,
            repair,
        );
        (out.method, out.path) = (method, path);
        check_solution(&mut out.solution, settings.tolerance);
        return Ok((verdict, gpu_error));
    }
    let verdict = GpuVerdict::of(result, z);
    let checked = check_answer(
        lcp,
        &verdict,
        &settings.enumeration,
        (exact_twin, accept, settings.tolerance),
        &mut out.solution,
        repair,
    )?;
    out.method = Method::Enumeration;
    out.path = match checked.0 {
        Verdict::Repaired => SolvePath::Repaired,
        _ => SolvePath::EnumeratedGpu,
    };
    check_solution(&mut out.solution, settings.tolerance);
    Ok(checked)
}
