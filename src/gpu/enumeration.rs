//! The enumeration stage: every island of a table through its size's
//! kernel (and first through the tree kernel where routed), in rounds until
//! every island is done.

use super::dispatch::{Ranges, Span};
use super::kernel::{EnumerationKernel, KernelPlan, TreeRoute};
use super::layout::{scalars_from_bytes, BasisResult, PackedIsland, TREE_DECIDED, TREE_UNDECIDED};
use super::pipelines::{Pipelines, Stage};
use super::{GpuContext, MAX_GPU_N};
use crate::report::GpuFigures;
use crate::Error;

use std::time::Instant;

/// What the enumeration stage gave for a table of islands.
pub(crate) struct EnumerationRun {
    pub results: Vec<BasisResult>,
    /// z of every island at its table offset, in the shader's precision.
    pub z: Vec<f64>,
    /// Dispatches, rounds, the tree kernel's decisions, and the seconds of
    /// the kernels (submission to the last round's end) and of the readback.
    pub figures: GpuFigures,
}

/// One enumeration over `table` (sorted by n, then by `tree`; M and q in
/// `values`): the device buffers and the plan every round shares.
/// `tree[i]` (empty: none): entry i runs the tree kernel in the first round,
/// and the size's kernel after it only if left undecided.
pub(crate) struct EnumerationJob<'a> {
    pub ctx: &'a GpuContext,
    pub pipelines: &'a Pipelines,
    /// The island table (binding 1) and every island's M and q (binding 2).
    pub islands: &'a wgpu::Buffer,
    pub values: &'a wgpu::Buffer,
    /// The tolerances uniform (binding 7, [`super::pipelines::Tolerances`]).
    pub tolerances: &'a wgpu::Buffer,
    pub table: &'a [PackedIsland],
    pub tree: &'a [TreeRoute],
    pub max_groups: u32,
    pub plan: &'a KernelPlan,
}

/// The stage's output buffers (bindings 3-6).
struct Outputs {
    /// Where each island's enumeration stands (zeroed: not started).
    results: wgpu::Buffer,
    results_size: u64,
    /// Each island's z of the chosen basis (zeroed: 0 off the basis).
    z: wgpu::Buffer,
    z_size: u64,
    /// Islands per size n still in progress after a round.
    unfinished: wgpu::Buffer,
    /// Infeasibility of each island's least infeasible basis so far.
    least: wgpu::Buffer,
}

/// One island size's dispatches: the tree kernel's (tree buckets, first
/// round only) and the size kernel's.
struct Bucket {
    n: u32,
    tree: Option<Ranges>,
    ranges: Ranges,
}

const UNFINISHED_BYTES: u64 = 17 * 4;

impl<'a> EnumerationJob<'a> {
    fn route(&self, i: usize) -> TreeRoute {
        self.tree.get(i).copied().unwrap_or_default()
    }

    /// The kernel of islands of n contacts (after the tree).
    fn size_stage(&self, n: u32) -> Result<&'a Stage, Error> {
        let p = self.pipelines;
        Ok(match self.plan.kernel.for_n(n as usize) {
            EnumerationKernel::Unrolled => p.unrolled(self.ctx, n as usize)?,
            EnumerationKernel::Workgroup => &p.enumeration_workgroup,
            _ => &p.enumeration,
        })
    }

    /// Runs every round and, with `read_back`, reads results and z.
    /// `encoder` may hold earlier work (assembly); it is submitted with the
    /// first round.
    pub(crate) fn run(
        &self,
        encoder: wgpu::CommandEncoder,
        read_back: bool,
    ) -> Result<EnumerationRun, Error> {
        let mut run = EnumerationRun {
            results: Vec::new(),
            z: Vec::new(),
            figures: GpuFigures::default(),
        };
        let t = Instant::now();
        if self.table.is_empty() {
            // Nothing to enumerate (prediction settled every island): run what
            // the encoder holds (assembly) and wait.
            self.ctx.submit_and_read(encoder, &[])?;
            run.figures.kernel_seconds = t.elapsed().as_secs_f64();
            return Ok(run);
        }
        let out = self.outputs();
        let buckets = self.buckets(&out)?;
        let encoder = self.rounds(&out, &buckets, encoder, &mut run)?;
        run.figures.kernel_seconds = t.elapsed().as_secs_f64();
        if read_back {
            let t = Instant::now();
            self.read(&out, encoder, &mut run)?;
            run.figures.readback_seconds = t.elapsed().as_secs_f64();
        }
        Ok(run)
    }

    fn outputs(&self) -> Outputs {
        let ctx = self.ctx;
        let sb = ctx.precision().bytes();
        let results_size = (self.table.len() * std::mem::size_of::<BasisResult>()) as u64;
        let z_len = self
            .table
            .iter()
            .map(|r| (r.z + r.n) as u64)
            .max()
            .unwrap_or(0);
        Outputs {
            results: ctx.storage_zeroed("results", results_size),
            results_size,
            z: ctx.storage_zeroed("z", z_len * sb),
            z_size: z_len * sb,
            unfinished: ctx.storage_zeroed("unfinished", UNFINISHED_BYTES),
            least: ctx.storage_zeroed("least_infeasibility", self.table.len() as u64 * sb),
        }
    }

    /// One bucket per island size and tree route: a workgroup never waits
    /// on a larger island. (One dispatch over all sizes per round was tried:
    /// 12x fewer dispatches but 35% slower at 10k islands on lavapipe, whose
    /// threads then got the small and the large islands in unequal halves.)
    fn buckets(&self, out: &Outputs) -> Result<Vec<Bucket>, Error> {
        let bind = |params: &wgpu::Buffer, stage: &Stage| {
            stage.bind(
                self.ctx,
                &[
                    params,
                    self.islands,
                    self.values,
                    &out.results,
                    &out.z,
                    &out.unfinished,
                    &out.least,
                    self.tolerances,
                ],
            )
        };
        let mut buckets = Vec::new();
        let mut first = 0usize;
        while first < self.table.len() {
            let n = self.table[first].n;
            let t = self.route(first);
            let mut last = first;
            while last < self.table.len() && self.table[last].n == n && self.route(last) == t {
                last += 1;
            }
            let mut span = Span {
                budget: self.plan.budget,
                ..Span::items(first as u32, (last - first) as u32)
            };
            let tree = if t == TreeRoute::Off {
                None
            } else {
                let stage = self.pipelines.tree(self.ctx, n as usize)?;
                // params.flags bit 0: semidefinite (singular pivots cut subtrees).
                let flags = (t == TreeRoute::Semidefinite) as u32;
                let tree_span = Span { flags, ..span };
                Some(
                    self.ctx
                        .ranges(tree_span, self.max_groups, &|p| bind(p, stage)),
                )
            };
            if self.plan.kernel.for_n(n as usize) == EnumerationKernel::Workgroup {
                span.per_group = 1;
            }
            let stage = self.size_stage(n)?;
            let ranges = self.ctx.ranges(span, self.max_groups, &|p| bind(p, stage));
            buckets.push(Bucket { n, tree, ranges });
            first = last;
        }
        Ok(buckets)
    }

    /// Submits rounds (doubling the rounds per submission, up to 256) until
    /// no island is unfinished; returns a fresh encoder.
    fn rounds(
        &self,
        out: &Outputs,
        buckets: &[Bucket],
        mut encoder: wgpu::CommandEncoder,
        run: &mut EnumerationRun,
    ) -> Result<wgpu::CommandEncoder, Error> {
        let ctx = self.ctx;
        let mut active: Vec<usize> = (0..buckets.len()).collect();
        let mut per_submit = 1usize;
        while !active.is_empty() {
            for r in 0..per_submit {
                if r + 1 == per_submit {
                    // Count only what the last round of this submission leaves.
                    encoder.clear_buffer(&out.unfinished, 0, None);
                }
                for &b in &active {
                    let bucket = &buckets[b];
                    match &bucket.tree {
                        Some(t) if run.figures.rounds + r == 0 => {
                            let stage = self.pipelines.tree(ctx, bucket.n as usize)?;
                            ctx.record(&mut encoder, stage, t);
                            run.figures.dispatches += t.len();
                        }
                        _ => {
                            ctx.record(&mut encoder, self.size_stage(bucket.n)?, &bucket.ranges);
                            run.figures.dispatches += bucket.ranges.len();
                        }
                    }
                }
            }
            run.figures.rounds += per_submit;
            let counts = ctx.submit_and_read(encoder, &[(&out.unfinished, UNFINISHED_BYTES)])?;
            let counts: &[u32] = bytemuck::try_cast_slice(&counts[0])
                .map_err(|e| Error::Gpu(format!("unfinished counts: {e}")))?;
            active.retain(|&b| counts.get(buckets[b].n as usize).copied().unwrap_or(0) > 0);
            // Every round visits at least one basis of every unfinished island.
            if run.figures.rounds > (1 << MAX_GPU_N) + 1 {
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
        Ok(encoder)
    }

    /// Reads results and z back, and counts the tree kernel's decisions.
    fn read(
        &self,
        out: &Outputs,
        encoder: wgpu::CommandEncoder,
        run: &mut EnumerationRun,
    ) -> Result<(), Error> {
        let reads = [(&out.results, out.results_size), (&out.z, out.z_size)];
        let mut read = self.ctx.submit_and_read(encoder, &reads)?.into_iter();
        let r_bytes = read.next().unwrap_or_default();
        let z_bytes = read.next().unwrap_or_default();
        run.results = bytemuck::try_cast_slice(&r_bytes)
            .map_err(|e| Error::Gpu(format!("results: {e}")))?
            .to_vec();
        run.z = scalars_from_bytes(&z_bytes, self.ctx.precision());
        let tree_count = |v: u32| {
            run.results
                .iter()
                .enumerate()
                .filter(|&(i, r)| self.route(i) != TreeRoute::Off && r._pad1 == v)
                .count()
        };
        run.figures.tree_decided = tree_count(TREE_DECIDED);
        run.figures.tree_undecided = tree_count(TREE_UNDECIDED);
        Ok(())
    }
}
