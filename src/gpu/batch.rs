//! Batches of LCPs on the GPU: prediction on the CPU, the enumeration stage
//! for islands of any mix of sizes, then validation of every answer on the
//! CPU in f64.
//!
//! Scheduling: islands are sorted by n and dispatched one size at a time, so
//! that a workgroup never waits on a larger island than its own. A batch is
//! split into chunks whose buffers stay under the device's storage-binding
//! and buffer limits ([`super::buffers`]), and each dispatch into ranges of
//! at most 65,535 workgroups ([`super::dispatch`]); the caller sees one
//! result per island, in its order.
//!
//! The host's share runs on every core, in blocks of consecutive islands
//! ([`BLOCK`]) written where the report keeps them: one pass checks each
//! problem and settles what needs no linear solve (separating, single
//! contact; Lemke above n = 16); an island's warm and predicted bases go
//! with it to the device, into its table entry, where the settle kernel
//! tries them before the enumeration or Lemke kernels
//! (`shaders/enumeration_settle.wgsl`). The rest is written by every
//! thread, in the shader's precision, straight into mapped buffers the
//! context keeps between calls (on hardware a kept staging buffer, copied
//! on the device), and after the kernels a second pass checks each answer
//! in f64 ([`super::validation`]); the reports are made and counted on
//! every thread too. Nothing is allocated per island for n ≤ 8.
//!
//! Overlap: on hardware, a batch leaving 2 × [`PART_ISLANDS`] islands or
//! more to the GPU is cut into parts (at most [`MAX_PARTS`], consecutive
//! blocks), each planned into its own chunks; while the device runs chunk
//! k the host writes chunk k + 1 into the other kept buffers and checks
//! the last part whose answers are all in (`enumerate_known`). wgpu 30 has
//! one queue per device, so uploads and readbacks share it with the
//! kernels: what overlaps is the host's work, not transfers. On a software
//! adapter the batch stays one part (its device is the host's cores).
//! Where the device has `TIMESTAMP_QUERY`, each submission's rounds are
//! timed on the device too ([`GpuFigures::kernel_device_seconds`]).

// The stage entry point `enumerate_on_gpu` (the GPU's raw verdicts)
// serves the stage tests; the Solver calls `solve_lcp_batch_warm`.
#![cfg_attr(not(test), allow(dead_code))]

use std::time::Instant;

use super::buffers::{limits_for, pack_chunks, Role};
use super::enumeration::{EnumerationJob, InFlight};
pub use super::kernel::{EnumerationKernel, KernelPlan, TreeRoute};
use super::layout::{hint as hint_word, BasisResult};
use super::pipelines::Tolerances;
pub(crate) use super::validation::settle_from_gpu;
use super::validation::Verdict;
use super::{GpuContext, Precision, MAX_GPU_N};
use crate::cpu::batch::{parallel_fill_by, parallel_map};
use crate::cpu::enumeration::EnumerationSettings;
use crate::cpu::enumeration_tree::TREE_MAX_N;
use crate::cpu::lemke::{lemke, LemkeSettings};
use crate::lcp::{Lcp, LcpSolution};
use crate::prediction::{predict_into, prediction_hint_into, prediction_into};
use crate::report::{Device, GpuFigures, IslandReport, Report, SolvePath};
use crate::settings::Method;
use crate::short_vec::ShortVec;
use crate::solver::check_solution;
use crate::Error;

/// Default GPU tolerances in f32 (f64 shaders use the CPU's): accept more
/// than f64 would (the f64 polish rejects what is wrong and counts it as
/// repaired) and call a basis singular only when f32 cannot tell.
pub const F32_PIVOT_TOL: f64 = 1e-6;
pub const F32_FEASIBILITY_TOL: f64 = 1e-4;
/// f32 fallback tolerance: the least infeasible basis within it is named
/// when no basis is valid (the f64 check then decides).
pub const F32_RELAXED_TOL: f64 = 1e-3;

/// Settings of a GPU batch solve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpuSolveSettings {
    /// The CPU's enumeration settings: the f64 polish and repair use them,
    /// and f64 shaders use the same tolerances. `all_solutions` is not
    /// supported on the GPU.
    pub enumeration: EnumerationSettings,
    /// GPU pivot tolerance; None: the CPU's in f64, [`F32_PIVOT_TOL`] in f32.
    pub gpu_pivot_tol: Option<f64>,
    /// GPU feasibility tolerance; None: the CPU's in f64, [`F32_FEASIBILITY_TOL`] in f32.
    pub gpu_feasibility_tol: Option<f64>,
    /// GPU relaxed tolerance; None: the CPU's in f64, [`F32_RELAXED_TOL`] in f32.
    pub gpu_relaxed_tol: Option<f64>,
    /// Islands with n > 16 are solved on the CPU with these settings.
    pub lemke: LemkeSettings,
    /// Lower the size above which a batch is split (bytes per binding;
    /// capped at the device's limit). For tests of the splitting.
    pub max_binding_bytes: Option<u64>,
    /// Lower the workgroups per dispatch (capped at the device's limit).
    pub max_workgroups: Option<u32>,
    /// Loop work per invocation and enumeration round; None: by adapter
    /// ([`SOFTWARE_ROUND_BUDGET`] or [`HARDWARE_ROUND_BUDGET`]).
    pub round_budget: Option<u32>,
    /// Settle islands that need no enumeration first
    /// ([`crate::prediction::predict`]: separating, single contact, warm
    /// start, predicted basis). LCP batches: the first two on the host
    /// (those islands are never uploaded), the warm and predicted bases by
    /// the settle kernel before the others run; scenes: all four on the
    /// host. Default true.
    pub predict: bool,
    /// Which enumeration shader runs (default [`EnumerationKernel::Auto`]).
    pub kernel: EnumerationKernel,
    /// The method (default [`Method::Enumeration`]: the enumeration
    /// kernels). Auto and Lemke: the Lemke kernel (`shaders/lemke.wgsl`),
    /// each basis it ends on checked in f64 as the CPU path checks Lemke's,
    /// the rest solved by the CPU path ([`crate::gpu::validation`]).
    pub method: Method,
    /// Largest island the tree kernel takes (default [`TREE_MAX_N`]; values
    /// above it act as it; 0 turns the tree off).
    pub tree_max_n: usize,
    /// The door's final check: an answer whose error exceeds this is a
    /// numerical failure (default: [`crate::Settings`]'s, 1e-8).
    pub tolerance: f64,
    /// Threads of the host's passes (default: every core).
    pub threads: usize,
    /// Islands left to the GPU per part of the pipeline, at the least
    /// (capped at [`MAX_PARTS`] parts); None: by adapter, [`PART_ISLANDS`]
    /// on hardware, one part on a software adapter (its "device" is the
    /// host's own cores: nothing to overlap, and every part runs its
    /// rounds and waits again). For tests of the overlap.
    pub part_islands: Option<usize>,
    /// LCP batches: whether the warm and predicted bases are tried on the
    /// device (the settle kernel, `shaders/enumeration_settle.wgsl`) rather
    /// than on the host before upload; None: by adapter, on the device on
    /// hardware, on the host on a software adapter (its "device" is the
    /// host's own cores, where the kernel's solve costs more than the
    /// host's: the warm family at 47–83 k islands/s against 262–294 k on
    /// lavapipe, BENCHMARKS.md "kernelwarm"). For tests of the kernel.
    pub settle_on_device: Option<bool>,
}

impl Default for GpuSolveSettings {
    fn default() -> Self {
        GpuSolveSettings {
            enumeration: EnumerationSettings::default(),
            gpu_pivot_tol: None,
            gpu_feasibility_tol: None,
            gpu_relaxed_tol: None,
            lemke: LemkeSettings::default(),
            max_binding_bytes: None,
            max_workgroups: None,
            round_budget: None,
            predict: true,
            kernel: EnumerationKernel::Auto,
            method: Method::Enumeration,
            tree_max_n: TREE_MAX_N,
            tolerance: crate::Settings::default().tolerance,
            threads: std::thread::available_parallelism().map_or(1, |n| n.get()),
            part_islands: None,
            settle_on_device: None,
        }
    }
}

impl GpuSolveSettings {
    /// (pivot, feasibility, relaxed) tolerances of the shaders at `precision`.
    pub fn gpu_tolerances(&self, precision: Precision) -> (f64, f64, f64) {
        let e = &self.enumeration;
        let (p, f, r) = if precision == Precision::F64 {
            (e.pivot_tol, e.feasibility_tol, e.relaxed_feasibility_tol)
        } else {
            (F32_PIVOT_TOL, F32_FEASIBILITY_TOL, F32_RELAXED_TOL)
        };
        (
            self.gpu_pivot_tol.unwrap_or(p),
            self.gpu_feasibility_tol.unwrap_or(f),
            self.gpu_relaxed_tol.unwrap_or(r),
        )
    }

    /// The enumeration settings checked, and `all_solutions` refused (the
    /// GPU batches name one basis per island).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the setting out of range;
    /// [`Error::Unsupported`] for `all_solutions`.
    pub fn check(&self) -> Result<(), Error> {
        self.enumeration.validate()?;
        if self.enumeration.all_solutions {
            return Err(Error::Unsupported(
                "all_solutions is not supported on the GPU; use the CPU backend".into(),
            ));
        }
        Ok(())
    }

    /// True when the shaders run the CPU twin's arithmetic and tolerances
    /// (f64): then a least-infeasible basis the GPU names after visiting
    /// every basis is the CPU's choice, and validation keeps it when it is
    /// within the relaxed tolerance in f64.
    pub fn exact_twin(&self, precision: Precision) -> bool {
        let e = &self.enumeration;
        precision == Precision::F64
            && self.gpu_tolerances(precision)
                == (e.pivot_tol, e.feasibility_tol, e.relaxed_feasibility_tol)
    }
}

/// Output of the enumeration stage for one island, before validation.
#[derive(Clone, Debug, PartialEq)]
pub struct EnumerationOutput {
    pub result: BasisResult,
    /// z of the chosen basis in the shader's precision (zeros when none).
    pub z: Vec<f64>,
}

/// What the enumeration stage gave for a list of islands: per island, in
/// the list's order, its record and where its z starts in `z`.
pub(crate) struct Answers {
    results: Vec<BasisResult>,
    z_at: Vec<usize>,
    /// Every chunk's z, in the shader's precision widened to f64.
    z: Vec<f64>,
}

impl Answers {
    /// Island `pos`'s record and z (of `n` entries; empty if out of range).
    pub(crate) fn of(&self, pos: usize, n: usize) -> (&BasisResult, &[f64]) {
        let at = self.z_at[pos];
        (&self.results[pos], self.z.get(at..at + n).unwrap_or(&[]))
    }
}

/// Runs the enumeration stage alone on every problem (each must be valid
/// with n ≤ 16) and returns its raw output, in order. This is the stage the
/// tests compare with its CPU twin, [`crate::cpu::enumeration::enumerate`].
pub fn enumerate_on_gpu(
    ctx: &GpuContext,
    lcps: &[&Lcp],
    settings: &GpuSolveSettings,
) -> Result<(Vec<EnumerationOutput>, GpuFigures), Error> {
    let whole = [0..lcps.len()];
    let known = (&[][..], &[][..]);
    let (answers, figures) =
        enumerate_known(ctx, lcps, known, settings, &whole, &mut |_, _| Ok(()))?;
    let out = (0..lcps.len())
        .map(|i| {
            let (result, z) = answers.of(i, lcps[i].n());
            EnumerationOutput {
                result: *result,
                z: z.to_vec(),
            }
        })
        .collect();
    Ok((out, figures))
}

/// [`enumerate_on_gpu`] with `definite[i]`: whether island i's M is
/// positive definite, where prediction found out (empty: nothing known),
/// and `hints[i]`: its [`super::layout::hint`] word for the settle kernel
/// (empty: none), pipelined over `parts` (consecutive ranges of `lcps` covering it, each
/// planned into chunks under the device's limits): while the device runs
/// chunk k, the host writes chunk k + 1 into the other kept buffers and
/// runs `check(j, answers)` on every part j whose answers are all in.
/// wgpu has one queue: uploads and readbacks share it with the kernels.
/// The figures' seconds: packing, upload, kernels, readback.
fn enumerate_known(
    ctx: &GpuContext,
    lcps: &[&Lcp],
    (definite, hints): (&[Option<bool>], &[u32]),
    settings: &GpuSolveSettings,
    parts: &[std::ops::Range<usize>],
    check: &mut dyn FnMut(usize, &Answers) -> Result<(), Error>,
) -> Result<(Answers, GpuFigures), Error> {
    let mut figures = GpuFigures::default();
    check_gpu_sizes(lcps)?;
    let precision = ctx.precision();
    let pipelines = ctx.pipelines()?;
    let tolerances = Tolerances::new(precision, settings).upload(ctx);
    let (max_bytes, max_groups) = limits_for(ctx, settings);
    let plan = KernelPlan::new(ctx, settings);

    let t = Instant::now();
    // Each island's route through the tree kernel, on every thread (the
    // test of M's semidefiniteness is O(n³) where prediction did not run).
    let tree: Vec<TreeRoute> = parallel_map(lcps.len(), settings.threads, |i| {
        plan.tree_for(lcps[i], definite.get(i).copied().flatten())
    });
    // (part, chunk) in order; a chunk's `order` indexes `lcps`.
    let mut chunks = Vec::new();
    for (j, r) in parts.iter().enumerate() {
        let hints = hints.get(r.clone()).unwrap_or(&[]);
        for mut c in pack_chunks(
            &lcps[r.clone()],
            (&tree[r.clone()], hints),
            max_bytes,
            precision.bytes(),
        ) {
            c.order.iter_mut().for_each(|i| *i += r.start);
            chunks.push((j, c));
        }
    }
    figures.pack_seconds += t.elapsed().as_secs_f64();
    let mut answers = Answers {
        results: vec![BasisResult::default(); lcps.len()],
        z_at: vec![0; lcps.len()],
        z: Vec::new(),
    };
    let (mut next, mut read, mut checked) = (0, 0, 0);
    let mut in_flight: Option<(usize, InFlight)> = None;
    loop {
        // The host's share while the chunk in flight runs: write the next
        // chunk, check the parts read.
        let t = Instant::now();
        let job = match chunks.get(next) {
            Some((_, chunk)) => Some(ctx.scoped("enumeration", || {
                let (islands, values) = chunk.upload(ctx, lcps, precision, settings.threads)?;
                Ok::<_, Error>(EnumerationJob {
                    ctx,
                    pipelines: &pipelines,
                    islands,
                    values,
                    tolerances: &tolerances,
                    table: &chunk.table,
                    tree: &chunk.tree,
                    settle: chunk.table.iter().any(|t| t.contacts != 0),
                    max_groups,
                    plan: &plan,
                })
            })??),
            None => None,
        };
        figures.upload_seconds += t.elapsed().as_secs_f64();
        while checked < read {
            check(checked, &answers)?;
            checked += 1;
        }
        if in_flight.is_some() {
            figures.overlapped_seconds += t.elapsed().as_secs_f64();
        }
        if let Some((at, flight)) = in_flight.take() {
            let (islands, values) = flight.buffers();
            let run = ctx.scoped("enumeration", || flight.finish(true))??;
            // The run waited for its last submission: the next chunk or
            // call may write them again.
            ctx.keep(Role::Islands, islands);
            ctx.keep(Role::Values, values);
            let (part, chunk) = &chunks[at];
            let base = answers.z.len();
            for ((&i, rec), res) in chunk.order.iter().zip(&chunk.table).zip(&run.results) {
                answers.results[i] = *res;
                answers.z_at[i] = base + rec.z as usize;
            }
            answers.z.extend_from_slice(&run.z);
            figures += run.figures;
            figures.chunks += 1;
            if chunks.get(at + 1).is_none_or(|(p, _)| p != part) {
                read = part + 1;
            }
        }
        let Some(job) = job else { break };
        let flight = ctx.scoped("enumeration", || job.start(ctx.encoder("enumeration")))??;
        in_flight = Some((next, flight));
        next += 1;
    }
    while checked < read {
        check(checked, &answers)?;
        checked += 1;
    }
    Ok((answers, figures))
}

fn check_gpu_sizes(lcps: &[&Lcp]) -> Result<(), Error> {
    for (i, l) in lcps.iter().enumerate() {
        if l.n() == 0 || l.n() > MAX_GPU_N || l.m.len() != l.n() * l.n() {
            return Err(Error::Unsupported(format!(
                "problem {i}: the GPU enumerates 1 ≤ n ≤ {MAX_GPU_N} (n = {})",
                l.n()
            )));
        }
    }
    Ok(())
}

/// Islands of a batch one thread takes at a time in the host's passes.
const BLOCK: usize = 256;

/// A thread's share of a batch in the host's passes: consecutive islands,
/// their reports, and those of them left to the GPU.
struct Block<'a> {
    /// Index of the first island in the batch.
    first: usize,
    islands: &'a mut [IslandReport],
    /// (island, whether its M is positive definite where prediction found
    /// out, its [`super::layout::hint`] word) for each island left to the
    /// GPU, in order.
    pending: Vec<(usize, Option<bool>, u32)>,
    /// Position of the first of them in the GPU's list.
    gpu_first: usize,
    /// The answers kept as the GPU gave them (accepted), those re-solved on
    /// their basis (polished), and the largest error of the GPU's own z.
    accepted: usize,
    polished: usize,
    max_gpu_error: f64,
    /// Seconds this block's thread spent on repairs.
    repair: f64,
    /// A failure of the f64 check (none is expected: n ≤ 16).
    error: Option<Error>,
}

/// Splits `islands` into [`Block`]s.
fn blocks(islands: &mut [IslandReport]) -> Vec<Block<'_>> {
    islands
        .chunks_mut(BLOCK)
        .enumerate()
        .map(|(b, islands)| Block {
            first: b * BLOCK,
            islands,
            pending: Vec::new(),
            gpu_first: 0,
            accepted: 0,
            polished: 0,
            max_gpu_error: 0.0,
            repair: 0.0,
            error: None,
        })
        .collect()
}

/// Checked problem `lcp` settled on the CPU into `out` where it can be
/// (n > [`MAX_GPU_N`] by Lemke; with `settings.predict`, what prediction
/// settles), the final check applied; else `Err` with what prediction
/// learnt of M (whether it is positive definite, if it found out).
/// `out.scene` and `out.contacts` are the caller's.
pub(crate) fn settle_on_cpu(
    lcp: &Lcp,
    warm: Option<u32>,
    settings: &GpuSolveSettings,
    out: &mut IslandReport,
) -> Result<(), Option<bool>> {
    settle_or_hint(lcp, warm, settings, false, out).map_err(|(definite, _)| definite)
}

/// [`settle_on_cpu`]; with `hint`, prediction's steps 3 and 4 (warm
/// basis, predicted basis: a linear solve each) are left to the settle
/// kernel: `Err` then carries the island's [`super::layout::hint`] word too (0: none).
fn settle_or_hint(
    lcp: &Lcp,
    warm: Option<u32>,
    settings: &GpuSolveSettings,
    hint: bool,
    out: &mut IslandReport,
) -> Result<(), (Option<bool>, u32)> {
    out.method = Method::Enumeration;
    let e = &settings.enumeration;
    if lcp.n() > MAX_GPU_N {
        (out.method, out.path) = (Method::Lemke, SolvePath::Lemke);
        out.solution = lemke(lcp, &settings.lemke);
    } else if !settings.predict {
        return Err((None, 0));
    } else if hint {
        prediction_hint_into(lcp, warm, e, &mut out.path, &mut out.solution)
            .map_err(|h| (h.definite, hint_word(h.warm, h.predicted)))?;
    } else if settings.method != Method::Enumeration {
        // The Lemke kernel takes no tree route: M's definiteness, which
        // `prediction_into` tests on every island for it, is not needed
        // (the CPU path's prediction, step for step).
        if !predict_into(lcp, warm, e, &mut out.path, &mut out.solution) {
            return Err((None, 0));
        }
    } else {
        prediction_into(lcp, warm, e, &mut out.path, &mut out.solution)
            .map_err(|definite| (definite, 0))?;
    }
    check_solution(&mut out.solution, settings.tolerance);
    Ok(())
}

/// [`solve_lcp_batch_warm`] without warm bases.
pub fn solve_lcp_batch(
    ctx: &GpuContext,
    lcps: &[Lcp],
    settings: &GpuSolveSettings,
) -> Result<Report, Error> {
    solve_lcp_batch_warm(ctx, lcps, &|_| None, settings)
}

/// Solves a batch of LCPs (see the module docs): islands with n ≤ 16 by
/// enumeration on the GPU, each answer checked in f64 on the CPU (polished,
/// or repaired by the CPU enumeration), larger ones by Lemke on the CPU,
/// those that need no enumeration settled first by prediction (with
/// `settings.predict`; `warm(i)`: problem i's basis from the last call, if
/// the caller has one). A problem that fails its checks gets path and
/// status invalid. The report's islands are in the caller's order, each
/// through the door's final check (`settings.tolerance`); its choice is
/// left empty for the caller.
pub fn solve_lcp_batch_warm(
    ctx: &GpuContext,
    lcps: &[Lcp],
    warm: &(dyn Fn(usize) -> Option<u32> + Sync),
    settings: &GpuSolveSettings,
) -> Result<Report, Error> {
    settings.check()?;
    let threads = settings.threads;
    // The reports made (a few hundred bytes each, written for the first
    // time) on every thread too.
    let t = Instant::now();
    let mut islands: Vec<IslandReport> = parallel_map(lcps.len(), threads, |i| IslandReport {
        scene: None,
        contacts: ShortVec::indices(lcps[i].n()),
        method: Method::Enumeration,
        path: SolvePath::Invalid,
        solution: LcpSolution::invalid(0),
    });
    let reports = t.elapsed().as_secs_f64();
    let mut blocks = blocks(&mut islands);
    let t = Instant::now();
    let on_device = settings
        .settle_on_device
        .unwrap_or(!ctx.adapter_info().software);
    parallel_fill_by(&mut blocks, threads, 1, |_, b| {
        for (j, island) in b.islands.iter_mut().enumerate() {
            let i = b.first + j;
            // The problem's name is formatted only by the caller's error.
            if lcps[i].validate("problem").is_err() {
                island.solution = LcpSolution::invalid(lcps[i].q.len());
            } else if let Err((definite, hint)) =
                settle_or_hint(&lcps[i], warm(i), settings, on_device, island)
            {
                b.pending.push((i, definite, hint));
            }
        }
    });
    let prediction = t.elapsed().as_secs_f64();
    let mut on_gpu: Vec<&Lcp> = Vec::new();
    let (mut definite, mut hints) = (Vec::new(), Vec::new());
    for b in &mut blocks {
        b.gpu_first = on_gpu.len();
        for &(i, d, h) in &b.pending {
            on_gpu.push(&lcps[i]);
            definite.push(d);
            hints.push(h);
        }
    }
    if on_gpu.is_empty() {
        // Prediction settled every island: nothing to upload or check.
        drop(blocks);
        let figures = GpuFigures {
            report_seconds: reports,
            ..GpuFigures::default()
        };
        return Ok(batch_report(
            ctx,
            islands,
            [0, 0],
            figures,
            [prediction, 0.0, 0.0],
            threads,
        ));
    }
    // The f64 check of each part's answers, on every thread, while the
    // device runs the next chunk.
    let least = match settings.part_islands {
        Some(least) => least,
        None if ctx.adapter_info().software => usize::MAX,
        None => PART_ISLANDS,
    };
    let parts = parts_of(&blocks, on_gpu.len(), least);
    let gpu_parts: Vec<_> = parts.iter().map(|p| gpu_range(&blocks, p)).collect();
    let exact = settings.exact_twin(ctx.precision());
    let (mut validation, mut repair) = (0.0, 0.0);
    let mut check = |j: usize, answers: &Answers| {
        let t = Instant::now();
        parallel_fill_by(&mut blocks[parts[j].clone()], threads, 1, |_, b| {
            for k in 0..b.pending.len() {
                let (i, _, hint) = b.pending[k];
                let (result, z) = answers.of(b.gpu_first + k, lcps[i].n());
                let answer = (result, z, hint);
                let island = &mut b.islands[i - b.first];
                let twin = (exact, true);
                match settle_from_gpu(&lcps[i], answer, settings, twin, island, &mut b.repair) {
                    Ok((verdict, gpu_error)) => {
                        b.accepted += (verdict == Verdict::Accepted) as usize;
                        b.polished += (verdict == Verdict::Polished) as usize;
                        if gpu_error > b.max_gpu_error {
                            b.max_gpu_error = gpu_error;
                        }
                    }
                    Err(e) => b.error = Some(e),
                }
            }
        });
        validation += t.elapsed().as_secs_f64();
        Ok(())
    };
    let t = Instant::now();
    let (_, mut figures) = enumerate_known(
        ctx,
        &on_gpu,
        (&definite, &hints),
        settings,
        &gpu_parts,
        &mut check,
    )?;
    drop(check);
    let gpu = t.elapsed().as_secs_f64() - validation;
    let mut kept = [0, 0];
    for b in &mut blocks {
        if let Some(e) = b.error.take() {
            return Err(e);
        }
        kept[0] += b.accepted;
        kept[1] += b.polished;
        repair += b.repair;
        figures.max_gpu_error = figures.max_gpu_error.max(b.max_gpu_error);
    }
    drop(blocks);
    figures.repair_seconds = repair / threads.max(1) as f64;
    figures.check_seconds = (validation - figures.repair_seconds).max(0.0);
    figures.report_seconds = reports;
    let seconds = [prediction, gpu, validation];
    Ok(batch_report(ctx, islands, kept, figures, seconds, threads))
}

/// Islands of the GPU's list per part of a batch's pipeline, at the least:
/// below it a part's own costs (a submission and a wait, bind groups)
/// outweigh what the overlap hides.
pub const PART_ISLANDS: usize = 16_384;
/// Parts of a batch's pipeline, at most: 100,000 islands make 6 parts,
/// a million 8 of 125,000 (a hardware GPU wants large dispatches).
pub const MAX_PARTS: usize = 8;

/// The pipeline's parts: consecutive ranges of `blocks`, each with about
/// an equal share of the `on_gpu` islands left to the GPU (at least
/// `least`, at most [`MAX_PARTS`] parts), none empty.
fn parts_of(blocks: &[Block<'_>], on_gpu: usize, least: usize) -> Vec<std::ops::Range<usize>> {
    let count = (on_gpu / least.max(1)).clamp(1, MAX_PARTS);
    let share = on_gpu.div_ceil(count);
    let mut parts = Vec::with_capacity(count);
    let (mut first, mut held) = (0, 0);
    for (k, b) in blocks.iter().enumerate() {
        held += b.pending.len();
        if held >= share || (k + 1 == blocks.len() && held > 0) {
            parts.push(first..k + 1);
            (first, held) = (k + 1, 0);
        }
    }
    parts
}

/// The positions in the GPU's list of the islands of `blocks[part]`.
fn gpu_range(blocks: &[Block<'_>], part: &std::ops::Range<usize>) -> std::ops::Range<usize> {
    let last = &blocks[part.end - 1];
    blocks[part.start].gpu_first..last.gpu_first + last.pending.len()
}

/// The report of an LCP batch: `[accepted, polished]` GPU answers kept
/// (as the GPU gave them, re-solved on their basis), the figures,
/// and the seconds of prediction, the GPU and the f64 check; the islands
/// counted on up to `threads` threads.
fn batch_report(
    ctx: &GpuContext,
    islands: Vec<IslandReport>,
    [accepted, polished]: [usize; 2],
    mut figures: GpuFigures,
    [prediction, gpu, validation]: [f64; 3],
    threads: usize,
) -> Report {
    let t = Instant::now();
    let mut r = Report::new_on(islands, Vec::new(), Device::of(ctx), String::new(), threads);
    figures.report_seconds += t.elapsed().as_secs_f64();
    r.counts.accepted = accepted;
    r.counts.polished = polished;
    r.counts.cpu_fallback = r.counts.lemke;
    r.timings.prediction = prediction;
    r.timings.gpu = gpu;
    r.timings.validation = validation;
    r.gpu = Some(figures);
    r
}
