//! Validation of every GPU answer on the CPU, in f64.
//!
//! The GPU's enumeration names a basis (or says that none is valid). The CPU
//! then
//! - solves that basis again in f64 ("polish",
//!   [`crate::cpu::enumeration::solve_basis`]: one k×k solve and one n×n
//!   product, O(n³)) and keeps it when it is valid in f64 with the CPU's
//!   tolerances: z and w then come from f64 arithmetic only;
//! - otherwise solves the island by the CPU enumeration and counts it as
//!   repaired;
//! - when the GPU found no valid basis, confirms it by the CPU enumeration
//!   (the rare path: physical islands nearly always have a solution), so that
//!   the status equals the CPU's.
//!
//! With the same visit order and rule (fewest basic z, then the smallest
//! mask) as the CPU, an island's chosen basis is the CPU's whenever the GPU
//! accepted every basis f64 accepts before it; the f64 shaders use the CPU's
//! tolerances for that reason.

use std::fmt;

use crate::cpu::enumeration::{enumerate, solve_basis, BasisOutcome, EnumerationSettings};
use crate::gpu::layout::{BasisResult, FOUND, RELAXED};
use crate::gpu::Precision;
use crate::lcp::{lcp_error, Counters, Lcp, LcpSolution, Status};
use crate::linalg::solve_in_place;
use crate::prediction::SolvePath;
use crate::Error;

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

/// A validated island.
#[derive(Clone, Debug)]
pub struct Checked {
    pub solution: LcpSolution,
    pub verdict: Verdict,
    /// Error measure of the GPU's own z against the f64 problem (NaN when the
    /// GPU gave no z).
    pub gpu_error: f64,
}

/// Validates the GPU's answer for `lcp` (see the module docs). A relaxed
/// basis (no valid one exists) is kept when `accept_relaxed` (the shaders are
/// the exact f64 twin, so it is the CPU's choice) and it is within the
/// relaxed tolerance in f64; otherwise the CPU decides.
pub fn validate_island(
    lcp: &Lcp,
    gpu: &GpuVerdict<'_>,
    settings: &EnumerationSettings,
    accept_relaxed: bool,
) -> Result<Checked, Error> {
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
                    let mut solution = LcpSolution::from_z(lcp, Status::Solved, z, counters);
                    solution.basis = Some(mask);
                    return Ok(Checked {
                        solution,
                        verdict: Verdict::Polished,
                        gpu_error,
                    });
                }
            }
        }
    }
    if let (Some(mask), false) = (gpu.basis, gpu.relaxed) {
        if mask >> n == 0 {
            if let BasisOutcome::Solved {
                z, feasible: true, ..
            } = solve_basis(lcp, mask, settings)
            {
                let mut solution = LcpSolution::from_z(lcp, Status::Solved, z, counters);
                solution.basis = Some(mask);
                return Ok(Checked {
                    solution,
                    verdict: Verdict::Polished,
                    gpu_error,
                });
            }
        }
    }
    let solution = enumerate(lcp, settings)?;
    let verdict = if gpu.basis.is_none() && solution.status == Status::NoSolution {
        Verdict::ConfirmedNoSolution
    } else {
        Verdict::Repaired
    };
    Ok(Checked {
        solution,
        verdict,
        gpu_error,
    })
}

/// What a batch did, for the caller and the demo.
#[derive(Clone, Debug, PartialEq)]
pub struct BatchReport {
    pub adapter: String,
    pub precision: Precision,
    /// Every island of the batch.
    pub islands: usize,
    /// Answered by the GPU and confirmed in f64 (polished + confirmed no solution).
    pub solved_on_gpu: usize,
    /// The GPU's basis was valid in f64.
    pub polished: usize,
    /// The GPU found no valid basis and the CPU agreed.
    pub confirmed_no_solution: usize,
    /// The GPU's answer failed in f64; the CPU enumeration solved the island.
    pub repaired: usize,
    /// n > 16: solved on the CPU (Lemke).
    pub cpu_fallback: usize,
    /// Problems that failed their checks.
    pub invalid: usize,
    /// Settled by prediction on the CPU before the GPU (never uploaded).
    pub predicted: usize,
    /// Islands per solve path, in the order of [`SolvePath::ALL`]; they add
    /// up to `islands − invalid` (GPU-answered and repaired islands count as
    /// Enumerated, CPU fallbacks as Lemke).
    pub paths: [usize; 6],
    /// Largest error measure (Siconos lcp_compute_error) over islands with a
    /// solution, after polish.
    pub max_error: f64,
    /// Largest error measure of the GPU's own z (before polish).
    pub max_gpu_error: f64,
    /// Islands per status, in the order of [`Status::ALL`].
    pub statuses: [usize; Status::ALL.len()],
    /// Seconds of GPU work (upload + dispatch + readback).
    pub gpu_seconds: f64,
    /// Seconds of validation on the CPU.
    pub validation_seconds: f64,
    /// Seconds of prediction on the CPU (before the GPU).
    pub prediction_seconds: f64,
    pub chunks: usize,
    pub dispatches: usize,
    /// Enumeration rounds (see `shaders/enumeration.wgsl`).
    pub rounds: usize,
    /// Islands the tree kernel (`shaders/enumeration_tree.wgsl`) decided,
    /// and those it left to the elimination kernel.
    pub tree_decided: usize,
    pub tree_undecided: usize,
}

impl BatchReport {
    pub fn new(adapter: String, precision: Precision) -> Self {
        BatchReport {
            adapter,
            precision,
            islands: 0,
            solved_on_gpu: 0,
            polished: 0,
            confirmed_no_solution: 0,
            repaired: 0,
            cpu_fallback: 0,
            invalid: 0,
            predicted: 0,
            paths: [0; 6],
            max_error: 0.0,
            max_gpu_error: 0.0,
            statuses: [0; Status::ALL.len()],
            gpu_seconds: 0.0,
            validation_seconds: 0.0,
            prediction_seconds: 0.0,
            chunks: 0,
            dispatches: 0,
            rounds: 0,
            tree_decided: 0,
            tree_undecided: 0,
        }
    }

    fn status(&mut self, sol: &LcpSolution) {
        self.islands += 1;
        if let Some(i) = Status::ALL.iter().position(|&x| x == sol.status) {
            self.statuses[i] += 1;
        }
        // NaN is kept: it must show.
        let e = sol.residuals.error;
        if sol.status.is_solution() && (e.is_nan() || e > self.max_error) {
            self.max_error = sol.residuals.error;
        }
    }

    /// Islands settled by this path.
    #[cfg(test)]
    pub fn path_count(&self, p: SolvePath) -> usize {
        SolvePath::ALL
            .iter()
            .position(|&x| x == p)
            .map_or(0, |i| self.paths[i])
    }

    fn path(&mut self, p: SolvePath) {
        if let Some(i) = SolvePath::ALL.iter().position(|&x| x == p) {
            self.paths[i] += 1;
        }
    }

    /// Records an island settled by prediction before the GPU.
    pub fn record_predicted(&mut self, path: SolvePath, sol: &LcpSolution) {
        self.status(sol);
        self.path(path);
        self.predicted += 1;
    }

    /// Records an island the GPU answered.
    pub fn record_gpu(&mut self, c: &Checked) {
        self.status(&c.solution);
        self.path(SolvePath::Enumerated);
        match c.verdict {
            Verdict::Polished => {
                self.polished += 1;
                self.solved_on_gpu += 1;
            }
            Verdict::ConfirmedNoSolution => {
                self.confirmed_no_solution += 1;
                self.solved_on_gpu += 1;
            }
            Verdict::Repaired => self.repaired += 1,
        }
        if c.gpu_error > self.max_gpu_error {
            self.max_gpu_error = c.gpu_error;
        }
    }

    /// Records an island solved on the CPU because it is too large.
    pub fn record_cpu_fallback(&mut self, sol: &LcpSolution) {
        self.status(sol);
        self.path(SolvePath::Lemke);
        self.cpu_fallback += 1;
    }

    /// Records a problem that failed its checks.
    pub fn record_invalid(&mut self) {
        self.islands += 1;
        self.invalid += 1;
        self.statuses[5] += 1;
    }

    /// Adds another report's counts (a batch solved in parts).
    pub fn merge(&mut self, o: &BatchReport) {
        self.islands += o.islands;
        self.solved_on_gpu += o.solved_on_gpu;
        self.polished += o.polished;
        self.confirmed_no_solution += o.confirmed_no_solution;
        self.repaired += o.repaired;
        self.cpu_fallback += o.cpu_fallback;
        self.invalid += o.invalid;
        self.predicted += o.predicted;
        for (a, b) in self.paths.iter_mut().zip(o.paths) {
            *a += b;
        }
        self.prediction_seconds += o.prediction_seconds;
        self.max_error = self.max_error.max(o.max_error);
        self.max_gpu_error = self.max_gpu_error.max(o.max_gpu_error);
        for (a, b) in self.statuses.iter_mut().zip(o.statuses) {
            *a += b;
        }
        self.gpu_seconds += o.gpu_seconds;
        self.validation_seconds += o.validation_seconds;
        self.chunks += o.chunks;
        self.dispatches += o.dispatches;
        self.rounds += o.rounds;
        self.tree_decided += o.tree_decided;
        self.tree_undecided += o.tree_undecided;
    }
}

impl fmt::Display for BatchReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "adapter: {} ({})", self.adapter, self.precision.name())?;
        writeln!(
            f,
            "islands: {} (predicted on the CPU {}; solved on the GPU {}: polished {}, no solution confirmed {}; repaired {}; CPU fallback n > 16: {}; invalid {})",
            self.islands,
            self.predicted,
            self.solved_on_gpu,
            self.polished,
            self.confirmed_no_solution,
            self.repaired,
            self.cpu_fallback,
            self.invalid
        )?;
        let statuses: Vec<String> = Status::ALL
            .iter()
            .zip(self.statuses)
            .filter(|(_, c)| *c > 0)
            .map(|(s, c)| format!("{s} {c}"))
            .collect();
        writeln!(f, "statuses: {}", statuses.join(", "))?;
        let paths: Vec<String> = SolvePath::ALL
            .iter()
            .zip(self.paths)
            .filter(|(_, c)| *c > 0)
            .map(|(p, c)| format!("{} {c}", p.name()))
            .collect();
        writeln!(f, "paths: {}", paths.join(", "))?;
        if self.tree_decided + self.tree_undecided > 0 {
            writeln!(
                f,
                "tree kernel: decided {}, left to elimination {}",
                self.tree_decided, self.tree_undecided
            )?;
        }
        writeln!(
            f,
            "max error after polish: {:.3e} (GPU's own z: {:.3e})",
            self.max_error, self.max_gpu_error
        )?;
        write!(
            f,
            "prediction {:.3} s; GPU {:.3} s in {} chunk(s), {} dispatch(es), {} enumeration round(s); validation {:.3} s",
            self.prediction_seconds,
            self.gpu_seconds,
            self.chunks,
            self.dispatches,
            self.rounds,
            self.validation_seconds
        )
    }
}
