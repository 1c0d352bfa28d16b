//! Validation of every GPU answer on the CPU, in f64.
//!
//! The GPU's enumeration names a basis (or says that none is valid). The CPU
//! then
//! - solves that basis again in f64 ("polish",
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
//! path ended on; [`check_lemke_answer`] re-solves and checks it with the
//! CPU path's own test of Lemke's textbook basis
//! ([`crate::solver::textbook_checked`]), and where that fails, or the
//! kernel gave up, solves the island by the CPU path's code for the rest.
//!
//! With the same visit order and rule (fewest basic z, then the smallest
//! mask) as the CPU, an island's chosen basis is the CPU's whenever the GPU
//! accepted every basis f64 accepts before it; the f64 shaders use the CPU's
//! tolerances for that reason.

use crate::cpu::enumeration::{enumerate, feasible_basis_into, EnumerationSettings};
use crate::cpu::lemke::lemke;
use crate::gpu::batch::GpuSolveSettings;
use crate::gpu::layout::{BasisResult, FOUND, RELAXED};
use crate::lcp::{lcp_error, Counters, Lcp, LcpSolution, Status};
use crate::linalg::solve_in_place;
use crate::report::SolvePath;
use crate::settings::Method;
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

/// What validation decided.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// The GPU's basis is valid in f64; z, w recomputed in f64.
    Polished,
    /// The GPU found no valid basis and the CPU agrees.
    ConfirmedNoSolution,
    /// The GPU's answer was wrong in f64; the CPU enumeration's is used.
    Repaired,
}

/// Checks the GPU's answer for `lcp` in f64 and writes the island's answer
/// into `out` (see the module docs). A relaxed basis (no valid one exists)
/// is kept when `accept_relaxed` (the shaders are the exact f64 twin, so it
/// is the CPU's choice) and it is within the relaxed tolerance in f64;
/// otherwise the CPU decides. Returns the verdict and the error measure of
/// the GPU's own z against the f64 problem (NaN when the GPU gave none).
/// The seconds of a repair (the CPU enumeration) are added to `repair`.
///
/// # Errors
/// Those of the CPU enumeration (none for a checked problem of n ≤ 20).
pub fn check_answer(
    lcp: &Lcp,
    gpu: &GpuVerdict<'_>,
    settings: &EnumerationSettings,
    accept_relaxed: bool,
    out: &mut LcpSolution,
    repair: &mut f64,
) -> Result<(Verdict, f64), Error> {
    let n = lcp.n();
    let gpu_error = if gpu.basis.is_some() && gpu.z.len() == n {
        lcp_error(gpu.z, &lcp.w(gpu.z), &lcp.q)
    } else {
        f64::NAN
    };
    let counters = Counters {
        bases_visited: gpu.visited,
        singular_bases: gpu.singular,
        ..Counters::default()
    };
    if let (Some(mask), true) = (gpu.basis, gpu.relaxed && accept_relaxed) {
        if mask >> n == 0 {
            if let Some((v, z)) = basis_infeasibility(lcp, mask, settings) {
                if v > settings.feasibility_tol && v <= settings.relaxed_feasibility_tol {
                    *out = LcpSolution::from_z(lcp, Status::Solved, z, counters);
                    out.basis = Some(mask);
                    return Ok((Verdict::Polished, gpu_error));
                }
            }
        }
    }
    if let (Some(mask), false) = (gpu.basis, gpu.relaxed) {
        if mask >> n == 0 && feasible_basis_into(lcp, mask, settings, counters, || true, out) {
            return Ok((Verdict::Polished, gpu_error));
        }
    }
    let t = Instant::now();
    *out = enumerate(lcp, settings)?;
    *repair += t.elapsed().as_secs_f64();
    let verdict = if gpu.basis.is_none() && out.status == Status::NoSolution {
        Verdict::ConfirmedNoSolution
    } else {
        Verdict::Repaired
    };
    Ok((verdict, gpu_error))
}

/// The Lemke kernel's answer for `lcp` (its record and z) checked in f64
/// into `out`: a FOUND basis that passes the CPU path's check of Lemke's
/// textbook basis is the answer (method Lemke, path LemkeGpu: the CPU's
/// bytes where the GPU ended on the CPU's basis); otherwise the CPU path
/// solves the island as it would after prediction: `settings.method` Lemke
/// by [`lemke`] (path Lemke), Auto by the checked Lemke (path Lemke), else
/// the CPU enumeration (path Repaired). Returns (method, path, verdict:
/// Polished for the GPU's basis, else Repaired) and the error of the GPU's
/// own z (NaN where it gave none). The seconds of the CPU path's solve
/// are added to `repair`.
pub fn check_lemke_answer(
    lcp: &Lcp,
    (result, z): (&BasisResult, &[f64]),
    settings: &GpuSolveSettings,
    out: &mut LcpSolution,
    repair: &mut f64,
) -> (Method, SolvePath, Verdict, f64) {
    let e = &settings.enumeration;
    let found = result.status == FOUND && result.mask >> lcp.n() == 0;
    let gpu_error = if found && z.len() == lcp.n() {
        lcp_error(z, &lcp.w(z), &lcp.q)
    } else {
        f64::NAN
    };
    if found && textbook_checked(lcp, result.mask, result.visited.into(), e, out) {
        return (
            Method::Lemke,
            SolvePath::LemkeGpu,
            Verdict::Polished,
            gpu_error,
        );
    }
    let t = Instant::now();
    let (mut method, mut path) = (Method::Lemke, SolvePath::Lemke);
    if settings.method == Method::Lemke {
        *out = lemke(lcp, &settings.lemke);
    } else {
        let (l, t) = (&settings.lemke, settings.tolerance);
        lemke_else_enumerate(lcp, l, e, t, &mut method, &mut path, out);
        if path == SolvePath::EnumeratedCpu {
            path = SolvePath::Repaired;
        }
    }
    *repair += t.elapsed().as_secs_f64();
    (method, path, Verdict::Repaired, gpu_error)
}
