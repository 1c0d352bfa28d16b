//! Batches of LCPs on the GPU: the enumeration stage for islands of any mix
//! of sizes, then validation of every answer on the CPU in f64.
//!
//! Scheduling: islands are sorted by n and dispatched one size at a time, so
//! that a workgroup never waits on a larger island than its own. A batch is
//! split into chunks whose buffers stay under the device's storage-binding
//! and buffer limits, and each dispatch into ranges of at most 65,535
//! workgroups; the caller sees one result per island, in its order.

use std::time::Instant;

use super::kernels::Pipelines;
use super::layout::{
    scalars_from_bytes, scalars_to_bytes, BasisResult, PackedIsland, TREE_DECIDED, TREE_UNDECIDED,
};
use super::{GpuContext, Precision, MAX_GPU_N};
use crate::cpu::enumeration::EnumerationSettings;
use crate::cpu::enumeration_tree::TREE_MAX_N;
use crate::lcp::{Counters, Lcp, LcpSolution, Residuals, Status};
use crate::prediction::{
    is_positive_definite, is_positive_semidefinite, prediction, SolvePath, Unsettled,
};
use crate::solvers::lemke::{lemke, LemkeSettings};
use crate::solvers::Solver;
use crate::validation::{validate_island, BatchReport, GpuVerdict, Verdict};
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
    /// Settle islands that need no enumeration on the CPU first
    /// ([`crate::prediction::predict`]: separating, single contact, warm
    /// start, predicted basis), so that only the others are uploaded and
    /// dispatched. Default true.
    pub predict: bool,
    /// Which enumeration shader runs (default [`EnumerationKernel::Auto`]).
    pub kernel: EnumerationKernel,
    /// Gray-code kernel: rebuild the tableau every this many pivots (None:
    /// [`DEFAULT_REFACTOR_PERIOD`]; 1…65,535).
    pub refactor_period: Option<u32>,
    /// Gray-code kernel: measure the tableau's drift at every scheduled
    /// rebuild ([`EnumerationOutput::drift`]); for the period study.
    pub measure_drift: bool,
    /// Largest island the tree kernel takes (default [`TREE_MAX_N`]; values
    /// above it act as it; 0 turns the tree off).
    pub tree_max_n: usize,
}

/// The enumeration shader.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum EnumerationKernel {
    /// Per island size, whichever measured faster ([`EnumerationKernel::for_n`]):
    /// Unrolled up to [`UNROLLED_UP_TO_N`], Workgroup from
    /// [`WORKGROUP_FROM_N`], Elimination between.
    #[default]
    Auto,
    /// `shaders/enumeration.wgsl`: bases by size, one elimination each, stop
    /// at the first valid one.
    Elimination,
    /// `shaders/enumeration_gray.wgsl`: every basis in Gray-code order, one
    /// principal pivot each, candidates confirmed by elimination.
    Gray,
    /// `shaders/enumeration.wgsl` specialised per island size (constant
    /// loop bounds and private-array indices) for n ≤
    /// [`super::kernels::FIXED_MAX_N`]; the elimination kernel above.
    /// Same answers as Elimination, bit for bit.
    Unrolled,
    /// `shaders/enumeration_tree.wgsl` first, on every island of n ≤
    /// [`GpuSolveSettings::tree_max_n`]: all bases screened by principal pivots down the tree
    /// of bases, the screened ones confirmed by elimination; the islands it
    /// leaves undecided, and the larger ones, go to Auto's kernel. Auto
    /// sends only positive definite islands to it ([`AUTO_TREE`]).
    Tree,
    /// `shaders/enumeration_workgroup.wgsl`: one workgroup per island, its
    /// 64 invocations solving the bases of one popcount in waves of 64
    /// consecutive masks, stopping at the first wave with a valid basis
    /// (the elimination kernel's order and choice: in f64 the same basis,
    /// z and counters). Parallelism inside an island, for few large ones.
    Workgroup,
}

/// Gray-code refactorisation period of the GPU kernel (see BENCHMARKS.md).
pub const DEFAULT_REFACTOR_PERIOD: u32 = 32;

impl EnumerationKernel {
    /// The kernel that runs islands of n contacts.
    /// For [`EnumerationKernel::Tree`]: the kernel after the tree (the tree
    /// itself is chosen per island, [`KernelPlan::tree_for`]).
    pub fn for_n(self, n: usize) -> EnumerationKernel {
        match self {
            EnumerationKernel::Auto | EnumerationKernel::Tree => {
                if GRAY_FROM_N.is_some_and(|g| n >= g) {
                    EnumerationKernel::Gray
                } else if WORKGROUP_FROM_N.is_some_and(|w| n >= w) {
                    EnumerationKernel::Workgroup
                } else if n <= UNROLLED_UP_TO_N {
                    EnumerationKernel::Unrolled
                } else {
                    EnumerationKernel::Elimination
                }
            }
            EnumerationKernel::Unrolled if n > super::kernels::FIXED_MAX_N => {
                EnumerationKernel::Elimination
            }
            k => k,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            EnumerationKernel::Auto => "auto",
            EnumerationKernel::Elimination => "elimination",
            EnumerationKernel::Gray => "gray",
            EnumerationKernel::Unrolled => "unrolled",
            EnumerationKernel::Tree => "tree",
            EnumerationKernel::Workgroup => "workgroup",
        }
    }
}

/// Auto: the Gray-code kernel from this island size on. None (never): on lavapipe
/// it measured 0.27–0.8× the elimination kernel's islands/s at every n from
/// 1 to 12 (BENCHMARKS.md).
pub const GRAY_FROM_N: Option<usize> = None;
/// Auto: the specialised straight-line elimination kernel up to this island
/// size (on lavapipe 1.14–1.97× the looped kernel's islands/s at n = 1…7,
/// 1.07–1.15× at n = 8: not clearly faster there; BENCHMARKS.md).
pub const UNROLLED_UP_TO_N: usize = 7;
/// Auto: the workgroup kernel (one workgroup per island) from this island
/// size on. On lavapipe (2 cores, 128 islands of one size per batch) it
/// measured 0.70–0.75× the per-island elimination kernel's islands/s at
/// n = 8, 0.94× (f64) and 1.39× (f32) at n = 9, and was faster in every
/// run from n = 10 on: 1.02–1.10× at 10, 1.2–1.7× at 11…16 (BENCHMARKS.md).
/// Its 64 lanes solve bases of one size side by side, where the per-island
/// kernel's lanes diverge (each island stops at a different basis).
pub const WORKGROUP_FROM_N: Option<usize> = Some(10);
/// Auto: positive definite and semidefinite islands of n ≤
/// [`GpuSolveSettings::tree_max_n`] go to the tree kernel first (on lavapipe
/// 2–25× the islands/s of Auto's other kernels at n = 6…12 on definite
/// islands, 17–33× end to end on resting stacks; BENCHMARKS.md). Its first dispatch per size
/// compiles for 1.5 s (n = 6) to 9 s (n = 12) on lavapipe without Mesa's
/// shader cache, once per process.
pub const AUTO_TREE: bool = true;

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
            refactor_period: None,
            measure_drift: false,
            tree_max_n: TREE_MAX_N,
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

/// Where an island's answer came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SolvedOn {
    /// The GPU's basis, valid in f64 (polished), or the GPU's "no
    /// solution" confirmed on the CPU.
    Gpu,
    /// The GPU's answer failed the f64 check; the CPU enumeration solved it.
    Repaired,
    /// n > 16: solved on the CPU by Lemke.
    CpuFallback,
    /// Settled on the CPU by prediction before the GPU (see
    /// [`IslandOutcome::path`] for which case).
    Predicted,
    /// The problem failed its checks (status InvalidInput).
    Invalid,
}

impl SolvedOn {
    pub fn name(self) -> &'static str {
        match self {
            SolvedOn::Gpu => "gpu",
            SolvedOn::Repaired => "repaired",
            SolvedOn::CpuFallback => "cpu_fallback",
            SolvedOn::Predicted => "predicted",
            SolvedOn::Invalid => "invalid",
        }
    }
}

/// One island's result.
#[derive(Clone, Debug)]
pub struct IslandOutcome {
    /// The validated solution (z, w and residuals in f64).
    pub solution: LcpSolution,
    pub solved_on: SolvedOn,
    /// How the island was settled: a prediction case, Enumerated (GPU,
    /// validated) or Lemke; None for a problem that failed its checks.
    pub path: Option<SolvePath>,
    /// The algorithm whose answer this is: Enum (GPU or CPU) or Lemke.
    pub solver: Solver,
    /// What the GPU's enumeration stage reported (None when it did not run).
    pub gpu: Option<BasisResult>,
    /// The GPU's own z, before the f64 polish (empty when it did not run).
    pub gpu_z: Vec<f64>,
}

/// Results in the caller's order and the batch's report.
#[derive(Clone, Debug)]
pub struct GpuBatchResult {
    pub islands: Vec<IslandOutcome>,
    pub report: BatchReport,
}

/// Output of the enumeration stage for one island, before validation.
#[derive(Clone, Debug, PartialEq)]
pub struct EnumerationOutput {
    pub result: BasisResult,
    /// z of the chosen basis in the shader's precision (zeros when none).
    pub z: Vec<f64>,
    /// Gray-code kernel with `measure_drift`: the largest difference between
    /// the pivoted and the rebuilt tableau's t at a scheduled rebuild,
    /// relative to the screen's scale of each entry; else 0.
    pub drift: f64,
}

/// What one GPU run did (for the report and the benches).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RunStats {
    pub chunks: usize,
    pub dispatches: usize,
    /// Enumeration rounds (summed over chunks).
    pub rounds: usize,
    /// Seconds of upload + dispatch + readback.
    pub seconds: f64,
    /// Islands the tree kernel decided, and those it left to elimination.
    pub tree_decided: usize,
    pub tree_undecided: usize,
}

/// Largest bytes per binding and workgroups per dispatch for this batch.
pub(crate) fn limits_for(ctx: &GpuContext, settings: &GpuSolveSettings) -> (u64, u32) {
    let l = ctx.limits();
    let bind = l.max_storage_buffer_binding_size.min(l.max_buffer_size);
    let bind = settings.max_binding_bytes.map_or(bind, |b| b.min(bind));
    let groups = l.max_compute_workgroups_per_dimension;
    let groups = settings.max_workgroups.map_or(groups, |g| g.min(groups));
    (bind.max(1024), groups.max(1))
}

/// Loop work per invocation and round on software adapters: llvmpipe ends
/// every loop of an invocation after about 65,535 iterations in all.
pub const SOFTWARE_ROUND_BUDGET: u32 = 48_000;
/// Loop work per invocation and round on hardware (bounds one dispatch's time).
pub const HARDWARE_ROUND_BUDGET: u32 = 1 << 22;

/// The Gray-code kernel's loop work per round for a round budget: its cost
/// model undercounts what llvmpipe counts (measured on lavapipe: at 48,000
/// units some n = 12 islands lost bases at period 32, at 20,000 none did at
/// periods 1 and 32), so it gets 5/12 of the budget.
pub fn gray_budget(budget: u32) -> u32 {
    (budget as u64 * 5 / 12).max(1) as u32
}

/// Which enumeration shader runs per size, and its per-round parameters.
#[derive(Clone, Copy, Debug)]
pub struct KernelPlan {
    /// Loop work per invocation and round.
    pub budget: u32,
    pub kernel: EnumerationKernel,
    /// Gray-code refactorisation period.
    pub period: u32,
    pub measure: bool,
    /// Largest island for the tree kernel (≤ [`TREE_MAX_N`]).
    pub tree_max_n: usize,
}

impl KernelPlan {
    pub(crate) fn new(ctx: &GpuContext, settings: &GpuSolveSettings) -> Self {
        KernelPlan {
            budget: round_budget(ctx, settings),
            kernel: settings.kernel,
            period: settings.refactor_period.unwrap_or(DEFAULT_REFACTOR_PERIOD),
            measure: settings.measure_drift,
            tree_max_n: settings.tree_max_n.min(TREE_MAX_N),
        }
    }

    /// Does this island go to the tree kernel first, and how? Only when n ≤
    /// `tree_max_n`. Positive definite M (every pivot of the tree exists):
    /// [`TreeRoute::Definite`]; symmetric positive semidefinite M (resting
    /// contacts): [`TreeRoute::Semidefinite`]; both tested on the CPU in
    /// O(n³). Auto ([`AUTO_TREE`]) routes only these;
    /// [`EnumerationKernel::Tree`] sends the others too, as Definite.
    /// `definite`: whether M is positive definite, when the caller knows
    /// (prediction tests it; else it is tested here).
    pub fn tree_for(&self, lcp: &Lcp, definite: Option<bool>) -> TreeRoute {
        if lcp.n() > self.tree_max_n
            || !matches!(
                self.kernel,
                EnumerationKernel::Tree | EnumerationKernel::Auto
            )
            || (self.kernel == EnumerationKernel::Auto && !AUTO_TREE)
        {
            return TreeRoute::Off;
        }
        if definite.unwrap_or_else(|| is_positive_definite(lcp)) {
            TreeRoute::Definite
        } else if is_positive_semidefinite(lcp) {
            TreeRoute::Semidefinite
        } else if self.kernel == EnumerationKernel::Tree {
            TreeRoute::Definite
        } else {
            TreeRoute::Off
        }
    }
}

/// How an island goes through the tree kernel (`shaders/enumeration_tree.wgsl`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum TreeRoute {
    /// Not at all: Auto's kernel for its size.
    #[default]
    Off,
    /// A pivot at most the tree pivot tolerance leaves the island undecided.
    Definite,
    /// M is symmetric positive semidefinite: a pivot singular to working
    /// precision cuts its subtree (no basis below it is nonsingular).
    Semidefinite,
}

/// What the enumeration stage gave for a table of islands.
pub(crate) struct EnumerationRun {
    pub results: Vec<BasisResult>,
    /// z of every island at its table offset, in the shader's precision.
    pub z: Vec<f64>,
    /// Per island (table order), the Gray kernel's measured drift (empty
    /// unless measured).
    pub drift: Vec<f64>,
    pub dispatches: usize,
    pub rounds: usize,
    /// Islands the tree kernel decided, and those it left to elimination.
    pub tree_decided: usize,
    pub tree_undecided: usize,
}

/// Runs the enumeration stage over `table` (sorted by n, then by `tree`; M
/// and q in `values`), in rounds until every island is done. `tree[i]`
/// (empty: none): entry i runs the tree kernel in the first round, and the
/// size's kernel after it only if left undecided. `encoder` may hold
/// earlier work (assembly); it is submitted with the first round.
#[allow(clippy::too_many_arguments)]
pub(crate) fn run_enumeration(
    ctx: &GpuContext,
    pipelines: &Pipelines,
    islands: &wgpu::Buffer,
    values: &wgpu::Buffer,
    table: &[PackedIsland],
    tree: &[TreeRoute],
    max_groups: u32,
    plan: &KernelPlan,
    mut encoder: wgpu::CommandEncoder,
    read_back: bool,
) -> Result<EnumerationRun, Error> {
    let route = |i: usize| tree.get(i).copied().unwrap_or_default();
    let in_tree = |i: usize| route(i) != TreeRoute::Off;
    let precision = ctx.precision();
    let sb = precision.bytes();
    if table.is_empty() {
        // Nothing to enumerate (prediction settled every island): run what
        // the encoder holds (assembly) and wait.
        ctx.submit_and_read(encoder, &[])?;
        return Ok(EnumerationRun {
            results: Vec::new(),
            z: Vec::new(),
            drift: Vec::new(),
            dispatches: 0,
            rounds: 0,
            tree_decided: 0,
            tree_undecided: 0,
        });
    }
    // results: where each island's enumeration stands (zeroed: not started).
    let results_size = (table.len() * std::mem::size_of::<BasisResult>()) as u64;
    let results = ctx.storage_zeroed("results", results_size);
    // z: each island's z of the chosen basis (zeroed: 0 off the basis).
    let z_len = table.iter().map(|r| (r.z + r.n) as u64).max().unwrap_or(0);
    let z_size = z_len * sb;
    let z = ctx.storage_zeroed("z", z_size);
    // unfinished: islands per size n still in progress after a round.
    let unfinished = ctx.storage_zeroed("unfinished", 17 * 4);
    // least: infeasibility of each island's least infeasible basis so far.
    let least = ctx.storage_zeroed("least_infeasibility", table.len() as u64 * sb);
    // drift: the Gray kernel's measured tableau drift per island.
    let drift_size = table.len() as u64 * sb;
    let drift = ctx.storage_zeroed("drift", drift_size);
    let stage_of = |n: u32| match plan.kernel.for_n(n as usize) {
        EnumerationKernel::Gray => &pipelines.enumeration_gray,
        EnumerationKernel::Unrolled => pipelines.fixed(ctx, n as usize),
        EnumerationKernel::Workgroup => &pipelines.enumeration_workgroup,
        _ => &pipelines.enumeration,
    };
    let bind = |params: &wgpu::Buffer, stage: &super::kernels::Stage, gray: bool| {
        let mut entries = vec![
            wgpu::BindGroupEntry {
                binding: 0,
                resource: params.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: islands.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 2,
                resource: values.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 3,
                resource: results.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 4,
                resource: z.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 5,
                resource: unfinished.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 6,
                resource: least.as_entire_binding(),
            },
        ];
        if gray {
            entries.push(wgpu::BindGroupEntry {
                binding: 7,
                resource: drift.as_entire_binding(),
            });
        }
        ctx.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("enumeration"),
            layout: &stage.layout,
            entries: &entries,
        })
    };
    // One bucket per island size: a workgroup never waits on a larger island.
    // (One dispatch over all sizes per round was tried: 12x fewer dispatches
    // but 35% slower at 10k islands on lavapipe, whose threads then got the
    // small and the large islands in unequal halves.)
    let flags = plan.period.clamp(1, 0xffff) | (plan.measure as u32) << 16;
    // Per bucket: n, the tree kernel's ranges (tree buckets) and the size
    // kernel's ranges.
    type Ranges = Vec<(wgpu::BindGroup, u32)>;
    let mut buckets: Vec<(u32, Option<Ranges>, Ranges)> = Vec::new();
    let mut first = 0usize;
    while first < table.len() {
        let n = table[first].n;
        let t = route(first);
        let mut last = first;
        while last < table.len() && table[last].n == n && route(last) == t {
            last += 1;
        }
        // params.flags bit 0: semidefinite (singular pivots cut subtrees).
        let tree_ranges = (t != TreeRoute::Off).then(|| {
            ctx.ranges_per_group(
                first as u32,
                (last - first) as u32,
                super::kernels::WORKGROUP,
                max_groups,
                plan.budget,
                (t == TreeRoute::Semidefinite) as u32,
                &|p| bind(p, pipelines.tree(ctx, n as usize), false),
            )
        });
        let kernel = plan.kernel.for_n(n as usize);
        let gray = kernel == EnumerationKernel::Gray;
        let per_group = if kernel == EnumerationKernel::Workgroup {
            1
        } else {
            super::kernels::WORKGROUP
        };
        let r = ctx.ranges_per_group(
            first as u32,
            (last - first) as u32,
            per_group,
            max_groups,
            if gray {
                gray_budget(plan.budget)
            } else {
                plan.budget
            },
            if gray { flags } else { 0 },
            &|p| bind(p, stage_of(n), gray),
        );
        buckets.push((n, tree_ranges, r));
        first = last;
    }
    let mut active: Vec<usize> = (0..buckets.len()).collect();
    let (mut rounds, mut dispatches, mut per_submit) = (0usize, 0usize, 1usize);
    while !active.is_empty() {
        for r in 0..per_submit {
            if r + 1 == per_submit {
                // Count only what the last round of this submission leaves.
                encoder.clear_buffer(&unfinished, 0, None);
            }
            for &b in &active {
                let (n, tree_ranges, ranges) = &buckets[b];
                match tree_ranges {
                    Some(t) if rounds + r == 0 => {
                        ctx.record(&mut encoder, pipelines.tree(ctx, *n as usize), t);
                        dispatches += t.len();
                    }
                    _ => {
                        ctx.record(&mut encoder, stage_of(*n), ranges);
                        dispatches += ranges.len();
                    }
                }
            }
        }
        rounds += per_submit;
        let counts = ctx.submit_and_read(encoder, &[(&unfinished, 17 * 4)])?;
        let counts: &[u32] = bytemuck::try_cast_slice(&counts[0])
            .map_err(|e| Error::Gpu(format!("unfinished counts: {e}")))?;
        active.retain(|&b| counts.get(buckets[b].0 as usize).copied().unwrap_or(0) > 0);
        // Every round visits at least one basis of every unfinished island.
        if rounds > (1 << MAX_GPU_N) + 1 {
            return Err(Error::Gpu(
                "enumeration made no progress (rounds exceed 2^16)".into(),
            ));
        }
        encoder = ctx
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("enumeration readback"),
            });
        per_submit = (per_submit * 2).min(256);
    }
    if !read_back {
        return Ok(EnumerationRun {
            results: Vec::new(),
            z: Vec::new(),
            drift: Vec::new(),
            dispatches,
            rounds,
            tree_decided: 0,
            tree_undecided: 0,
        });
    }
    let mut reads = vec![(&results, results_size), (&z, z_size)];
    if plan.measure {
        reads.push((&drift, drift_size));
    }
    let mut read = ctx.submit_and_read(encoder, &reads)?;
    let drift = if plan.measure {
        scalars_from_bytes(&read.pop().unwrap_or_default(), precision)
    } else {
        Vec::new()
    };
    let z_bytes = read.pop().unwrap_or_default();
    let r_bytes = read.pop().unwrap_or_default();
    let results: Vec<BasisResult> = bytemuck::try_cast_slice(&r_bytes)
        .map_err(|e| Error::Gpu(format!("results: {e}")))?
        .to_vec();
    let tree_count = |v: u32| {
        results
            .iter()
            .enumerate()
            .filter(|&(i, r)| in_tree(i) && r._pad1 == v)
            .count()
    };
    Ok(EnumerationRun {
        tree_decided: tree_count(TREE_DECIDED),
        tree_undecided: tree_count(TREE_UNDECIDED),
        results,
        z: scalars_from_bytes(&z_bytes, precision),
        drift,
        dispatches,
        rounds,
    })
}

/// Runs the enumeration stage alone on every problem (each must be valid
/// with n ≤ 16) and returns its raw output, in order. This is the stage the
/// tests compare with its CPU twin, [`crate::cpu::enumeration::enumerate`].
pub fn enumerate_on_gpu(
    ctx: &GpuContext,
    lcps: &[&Lcp],
    settings: &GpuSolveSettings,
) -> Result<(Vec<EnumerationOutput>, RunStats), Error> {
    enumerate_known(ctx, lcps, &[], settings)
}

/// [`enumerate_on_gpu`] with `definite[i]`: whether island i's M is
/// positive definite, where prediction found out (empty: nothing known).
fn enumerate_known(
    ctx: &GpuContext,
    lcps: &[&Lcp],
    definite: &[Option<bool>],
    settings: &GpuSolveSettings,
) -> Result<(Vec<EnumerationOutput>, RunStats), Error> {
    let start = Instant::now();
    let mut stats = RunStats::default();
    check_gpu_sizes(lcps)?;
    let precision = ctx.precision();
    let pipelines = ctx.pipelines(settings.gpu_tolerances(precision))?;
    let (max_bytes, max_groups) = limits_for(ctx, settings);
    let plan = KernelPlan::new(ctx, settings);

    let mut out = vec![
        EnumerationOutput {
            result: BasisResult::default(),
            z: Vec::new(),
            drift: 0.0,
        };
        lcps.len()
    ];
    let tree: Vec<TreeRoute> = lcps
        .iter()
        .enumerate()
        .map(|(i, l)| plan.tree_for(l, definite.get(i).copied().flatten()))
        .collect();
    for chunk in pack_chunks(lcps, &tree, max_bytes, precision.bytes()) {
        let run = ctx.scoped("enumeration", || -> Result<EnumerationRun, Error> {
            let (islands_buf, values_buf) = chunk.upload(ctx, precision);
            let encoder = ctx
                .device
                .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                    label: Some("enumeration"),
                });
            run_enumeration(
                ctx,
                &pipelines,
                &islands_buf,
                &values_buf,
                &chunk.table,
                &chunk.tree,
                max_groups,
                &plan,
                encoder,
                true,
            )
        })??;
        for (t, ((&i, rec), res)) in chunk
            .order
            .iter()
            .zip(&chunk.table)
            .zip(&run.results)
            .enumerate()
        {
            let (z0, n) = (rec.z as usize, rec.n as usize);
            out[i] = EnumerationOutput {
                result: *res,
                drift: run.drift.get(t).copied().unwrap_or(0.0),
                z: run
                    .z
                    .get(z0..z0 + n)
                    .map(<[f64]>::to_vec)
                    .unwrap_or_default(),
            };
        }
        stats.chunks += 1;
        stats.dispatches += run.dispatches;
        stats.rounds += run.rounds;
        stats.tree_decided += run.tree_decided;
        stats.tree_undecided += run.tree_undecided;
    }
    stats.seconds = start.elapsed().as_secs_f64();
    Ok((out, stats))
}

/// A chunk of an LCP batch, packed for the enumeration stage.
struct PackedChunk {
    /// The caller's indices of the chunk's islands, sorted by n, then by
    /// `tree`.
    order: Vec<usize>,
    table: Vec<PackedIsland>,
    /// Per table entry: how it goes through the tree kernel.
    tree: Vec<TreeRoute>,
    /// M (row-major) then q of every island, in f64.
    data: Vec<f64>,
}

impl PackedChunk {
    /// (islands, values) storage buffers.
    fn upload(&self, ctx: &GpuContext, precision: Precision) -> (wgpu::Buffer, wgpu::Buffer) {
        // islands: the chunk's island table, sorted by n.
        let islands = ctx.storage("islands", bytemuck::cast_slice(&self.table));
        // values: every island's M (row-major) and q, in the shader's precision.
        let values = ctx.storage("values", &scalars_to_bytes(&self.data, precision));
        (islands, values)
    }
}

/// Sorts the islands by n (one dispatch per size: no island waits on a
/// larger one), then by `tree` (the tree kernel's islands together), and
/// packs them into chunks whose buffers stay under `max_bytes`.
fn pack_chunks(lcps: &[&Lcp], tree: &[TreeRoute], max_bytes: u64, sb: u64) -> Vec<PackedChunk> {
    let route = |i: usize| tree.get(i).copied().unwrap_or_default();
    let mut order: Vec<usize> = (0..lcps.len()).collect();
    order.sort_by_key(|&i| (lcps[i].n(), route(i)));
    let mut chunks = Vec::new();
    let mut at = 0;
    while at < order.len() {
        let mut end = at;
        let (mut values, mut zs) = (0u64, 0u64);
        while end < order.len() {
            let n = lcps[order[end]].n() as u64;
            let nv = values + n * n + n;
            let nz = zs + n;
            let count = (end - at + 1) as u64;
            let too_big = nv * sb > max_bytes
                || nz * sb > max_bytes
                || count * std::mem::size_of::<BasisResult>() as u64 > max_bytes;
            if too_big && end > at {
                break;
            }
            values = nv;
            zs = nz;
            end += 1;
        }
        let mut table = Vec::with_capacity(end - at);
        let mut data = Vec::with_capacity(values as usize);
        let mut zoff = 0u32;
        for &i in &order[at..end] {
            let l = lcps[i];
            table.push(PackedIsland {
                n: l.n() as u32,
                data: data.len() as u32,
                z: zoff,
                contacts: 0,
            });
            data.extend_from_slice(&l.m);
            data.extend_from_slice(&l.q);
            zoff += l.n() as u32;
        }
        chunks.push(PackedChunk {
            order: order[at..end].to_vec(),
            tree: order[at..end].iter().map(|&i| route(i)).collect(),
            table,
            data,
        });
        at = end;
    }
    chunks
}

/// A batch uploaded once, for timing the enumeration dispatches alone (the
/// benches): [`UploadedBatch::dispatch`] runs every round of every chunk and
/// waits, with neither upload nor readback of results.
pub struct UploadedBatch<'a> {
    ctx: &'a GpuContext,
    pipelines: std::sync::Arc<Pipelines>,
    /// Per chunk: table, tree flags, islands and values buffers.
    chunks: Vec<(
        Vec<PackedIsland>,
        Vec<TreeRoute>,
        wgpu::Buffer,
        wgpu::Buffer,
    )>,
    max_groups: u32,
    plan: KernelPlan,
}

impl<'a> UploadedBatch<'a> {
    /// Uploads `lcps` (each valid, 1 ≤ n ≤ 16).
    pub fn new(
        ctx: &'a GpuContext,
        lcps: &[&Lcp],
        settings: &GpuSolveSettings,
    ) -> Result<Self, Error> {
        check_gpu_sizes(lcps)?;
        let precision = ctx.precision();
        let pipelines = ctx.pipelines(settings.gpu_tolerances(precision))?;
        let (max_bytes, max_groups) = limits_for(ctx, settings);
        let plan = KernelPlan::new(ctx, settings);
        let tree: Vec<TreeRoute> = lcps.iter().map(|l| plan.tree_for(l, None)).collect();
        let chunks = ctx.scoped("upload", || {
            pack_chunks(lcps, &tree, max_bytes, precision.bytes())
                .into_iter()
                .map(|c| {
                    let (i, v) = c.upload(ctx, precision);
                    (c.table, c.tree, i, v)
                })
                .collect()
        })?;
        Ok(UploadedBatch {
            ctx,
            pipelines,
            chunks,
            max_groups,
            plan,
        })
    }

    /// Runs the enumeration of every island and waits; returns the rounds.
    pub fn dispatch(&self) -> Result<usize, Error> {
        let mut rounds = 0;
        for (table, tree, islands, values) in &self.chunks {
            let run = self.ctx.scoped("enumeration", || {
                let encoder =
                    self.ctx
                        .device
                        .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                            label: Some("enumeration"),
                        });
                run_enumeration(
                    self.ctx,
                    &self.pipelines,
                    islands,
                    values,
                    table,
                    tree,
                    self.max_groups,
                    &self.plan,
                    encoder,
                    false,
                )
            })??;
            rounds += run.rounds;
        }
        Ok(rounds)
    }
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

/// Loop work per invocation and round for this adapter and these settings.
pub(crate) fn round_budget(ctx: &GpuContext, settings: &GpuSolveSettings) -> u32 {
    let default = if ctx.adapter_info().software {
        SOFTWARE_ROUND_BUDGET
    } else {
        HARDWARE_ROUND_BUDGET
    };
    settings.round_budget.unwrap_or(default).max(1)
}

/// A result for a problem that failed its checks.
fn invalid_solution(lcp: &Lcp) -> LcpSolution {
    let n = lcp.q.len();
    LcpSolution {
        status: Status::InvalidInput,
        z: vec![0.0; n],
        w: vec![0.0; n],
        residuals: Residuals::default(),
        counters: Counters::default(),
        basis: None,
        all_bases: Vec::new(),
        solution_set: None,
    }
}

/// Solves a batch of LCPs: islands with n ≤ 16 by enumeration on the GPU,
/// each answer validated in f64 on the CPU (polished, or repaired by the CPU
/// enumeration), larger ones by Lemke on the CPU. Problems that fail their
/// checks get status InvalidInput. Results come back in the caller's order.
/// With `settings.predict`, islands that need no enumeration are settled on
/// the CPU first and never uploaded (see [`solve_lcp_batch_warm`]).
pub fn solve_lcp_batch(
    ctx: &GpuContext,
    lcps: &[Lcp],
    settings: &GpuSolveSettings,
) -> Result<GpuBatchResult, Error> {
    solve_lcp_batch_warm(ctx, lcps, None, settings)
}

/// [`solve_lcp_batch`] with warm bases: `warm[i]` is island i's basis from
/// the previous frame, if the caller has one (used by prediction only, so
/// ignored when `settings.predict` is false).
pub fn solve_lcp_batch_warm(
    ctx: &GpuContext,
    lcps: &[Lcp],
    warm: Option<&[Option<u32>]>,
    settings: &GpuSolveSettings,
) -> Result<GpuBatchResult, Error> {
    settings.enumeration.validate()?;
    if settings.enumeration.all_solutions {
        return Err(Error::Unsupported(
            "all_solutions is not supported on the GPU; use the CPU backend".into(),
        ));
    }
    let mut report = BatchReport::new(ctx.adapter_info().name.clone(), ctx.precision());
    let mut slots: Vec<Option<IslandOutcome>> = vec![None; lcps.len()];
    let mut on_gpu: Vec<usize> = Vec::new();
    // Per island on the GPU: whether M is positive definite, if prediction found out.
    let mut definite: Vec<Option<bool>> = Vec::new();
    let warm_of = |i: usize| warm.and_then(|w| w.get(i).copied().flatten());
    let t_predict = Instant::now();
    for (i, lcp) in lcps.iter().enumerate() {
        if lcp.validate(&format!("problem {i}")).is_err() {
            slots[i] = Some(IslandOutcome {
                solution: invalid_solution(lcp),
                solved_on: SolvedOn::Invalid,
                path: None,
                solver: Solver::Enum,
                gpu: None,
                gpu_z: Vec::new(),
            });
        } else if lcp.n() > MAX_GPU_N {
            slots[i] = Some(IslandOutcome {
                solution: lemke(lcp, &settings.lemke),
                solved_on: SolvedOn::CpuFallback,
                path: Some(SolvePath::Lemke),
                solver: Solver::Lemke,
                gpu: None,
                gpu_z: Vec::new(),
            });
        } else {
            let predicted = match settings.predict {
                true => prediction(lcp, warm_of(i), &settings.enumeration),
                false => Err(Unsettled { definite: None }),
            };
            match predicted {
                Ok((path, solution)) => {
                    slots[i] = Some(IslandOutcome {
                        solution,
                        solved_on: SolvedOn::Predicted,
                        path: Some(path),
                        solver: Solver::Enum,
                        gpu: None,
                        gpu_z: Vec::new(),
                    })
                }
                Err(unsettled) => {
                    on_gpu.push(i);
                    definite.push(unsettled.definite);
                }
            }
        }
    }
    report.prediction_seconds = t_predict.elapsed().as_secs_f64();
    let refs: Vec<&Lcp> = on_gpu.iter().map(|&i| &lcps[i]).collect();
    let (outputs, stats) = enumerate_known(ctx, &refs, &definite, settings)?;
    report.gpu_seconds = stats.seconds;
    report.chunks = stats.chunks;
    report.dispatches = stats.dispatches;
    report.rounds = stats.rounds;
    report.tree_decided = stats.tree_decided;
    report.tree_undecided = stats.tree_undecided;
    let start = Instant::now();
    for (&i, o) in on_gpu.iter().zip(outputs) {
        let verdict = GpuVerdict::of(&o.result, &o.z);
        let checked = validate_island(
            &lcps[i],
            &verdict,
            &settings.enumeration,
            settings.exact_twin(ctx.precision()),
        )?;
        report.record_gpu(&checked);
        let solved_on = match checked.verdict {
            Verdict::Polished | Verdict::ConfirmedNoSolution => SolvedOn::Gpu,
            Verdict::Repaired => SolvedOn::Repaired,
        };
        slots[i] = Some(IslandOutcome {
            solution: checked.solution,
            solved_on,
            path: Some(SolvePath::Enumerated),
            solver: Solver::Enum,
            gpu: Some(o.result),
            gpu_z: o.z,
        });
    }
    report.validation_seconds = start.elapsed().as_secs_f64();
    let islands: Vec<IslandOutcome> = slots
        .into_iter()
        .map(|s| s.ok_or_else(|| Error::Gpu("an island got no result".into())))
        .collect::<Result<_, _>>()?;
    for o in &islands {
        match (o.solved_on, o.path) {
            (SolvedOn::CpuFallback, _) => report.record_cpu_fallback(&o.solution),
            (SolvedOn::Invalid, _) => report.record_invalid(),
            (SolvedOn::Predicted, Some(p)) => report.record_predicted(p, &o.solution),
            _ => {}
        }
    }
    Ok(GpuBatchResult { islands, report })
}
