//! The enumeration stage: every island of a table through its size's
//! kernel (and first through the tree kernel where routed), in rounds until
//! every island is done; or, with [`KernelPlan::lemke`], through the Lemke
//! kernel, one dispatch per size in one round (it always finishes).

use super::buffers::Role;
use super::dispatch::{split, Ranges, Span};
use super::kernel::{EnumerationKernel, KernelPlan, TreeRoute};
use super::layout::{
    scalars_from_bytes, BasisResult, PackedIsland, Params, TREE_DECIDED, TREE_UNDECIDED,
};
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

/// The stage's output buffers (bindings 3-6), kept from an earlier call
/// where the context has them ([`Role`]), each bound and cleared on its
/// first `size` bytes only, and the Params of every dispatch.
struct Outputs {
    /// Where each island's enumeration stands (cleared: not started).
    results: Part,
    /// Each island's z of the chosen basis (cleared: 0 off the basis).
    z: Part,
    /// Islands per size n still in progress after a round.
    unfinished: Part,
    /// Infeasibility of each island's least infeasible basis so far.
    least: Part,
    /// One Params per dispatch, [`Outputs::params_stride`] bytes apart.
    params: Part,
}

/// A buffer of a role and the bytes of it a call uses: `bytes`, bound
/// and cleared as `size` (rounded up to 16 and to 4: the size of the
/// buffer a call used to make for it).
struct Part {
    role: Role,
    buffer: wgpu::Buffer,
    bytes: u64,
    size: u64,
}

impl Part {
    fn new(ctx: &GpuContext, role: Role, bytes: u64) -> Self {
        let size = bytes.max(16).next_multiple_of(4);
        let buffer = ctx.kept_or_new(role, size);
        Part {
            role,
            buffer,
            bytes,
            size,
        }
    }

    fn binding(&self) -> wgpu::BufferBinding<'_> {
        wgpu::BufferBinding {
            buffer: &self.buffer,
            offset: 0,
            size: wgpu::BufferSize::new(self.size),
        }
    }
}

impl Outputs {
    /// Bytes between two dispatches' Params: the device's uniform offset
    /// alignment.
    fn params_stride(ctx: &GpuContext) -> u64 {
        let align = ctx.limits().min_uniform_buffer_offset_alignment as u64;
        (std::mem::size_of::<Params>() as u64).next_multiple_of(align.max(4))
    }

    /// Gives every buffer back to the context for the next call.
    fn keep(self, ctx: &GpuContext) {
        for p in [
            self.results,
            self.z,
            self.unfinished,
            self.least,
            self.params,
        ] {
            ctx.keep(p.role, p.buffer);
        }
    }
}

/// One island size's dispatches: the tree kernel's (tree buckets, first
/// round only) and the size kernel's.
struct Bucket {
    n: u32,
    tree: Option<Ranges>,
    ranges: Ranges,
}

/// A bucket before its bind groups: its stages, and per dispatch the
/// index of its Params and its workgroups.
struct Plan<'a> {
    n: u32,
    tree: Option<(&'a Stage, Vec<(usize, u32)>)>,
    ranges: (&'a Stage, Vec<(usize, u32)>),
}

const UNFINISHED_BYTES: u64 = 17 * 4;

impl<'a> EnumerationJob<'a> {
    fn route(&self, i: usize) -> TreeRoute {
        self.tree.get(i).copied().unwrap_or_default()
    }

    /// The kernel of islands of n contacts (after the tree).
    fn size_stage(&self, n: u32) -> Result<&'a Stage, Error> {
        let p = self.pipelines;
        if self.plan.lemke {
            return p.lemke(self.ctx);
        }
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
        let mut encoder = encoder;
        let (plans, params) = self.plans()?;
        let out = self.outputs(&params, &mut encoder);
        let buckets = self.buckets(plans, &out)?;
        let encoder = self.rounds(&out, &buckets, encoder, &mut run)?;
        run.figures.kernel_seconds = t.elapsed().as_secs_f64();
        if read_back {
            let t = Instant::now();
            self.read(&out, encoder, &mut run)?;
            run.figures.readback_seconds = t.elapsed().as_secs_f64();
        }
        // Every submission reading them has ended (`rounds` waits for the
        // last): the next call may take them.
        drop(buckets);
        out.keep(self.ctx);
        Ok(run)
    }

    /// The output buffers, kept or new, the ones the shaders expect zeroed
    /// cleared by `encoder`, and `params` written at their offsets (through
    /// the queue: before the encoder's submission).
    fn outputs(&self, params: &[Params], encoder: &mut wgpu::CommandEncoder) -> Outputs {
        let ctx = self.ctx;
        let sb = ctx.precision().bytes();
        let results_size = (self.table.len() * std::mem::size_of::<BasisResult>()) as u64;
        let z_len = self
            .table
            .iter()
            .map(|r| (r.z + r.n) as u64)
            .max()
            .unwrap_or(0);
        let stride = Outputs::params_stride(ctx);
        let out = Outputs {
            results: Part::new(ctx, Role::Results, results_size),
            z: Part::new(ctx, Role::Z, z_len * sb),
            unfinished: Part::new(ctx, Role::Unfinished, UNFINISHED_BYTES),
            least: Part::new(ctx, Role::Least, self.table.len() as u64 * sb),
            params: Part::new(ctx, Role::Params, params.len() as u64 * stride),
        };
        // `rounds` clears `unfinished` before each submission's last round.
        for p in [&out.results, &out.z, &out.least] {
            encoder.clear_buffer(&p.buffer, 0, Some(p.size));
        }
        let mut bytes = vec![0u8; out.params.size as usize];
        for (at, p) in bytes.chunks_mut(stride as usize).zip(params) {
            at[..std::mem::size_of::<Params>()].copy_from_slice(bytemuck::bytes_of(p));
        }
        ctx.queue.write_buffer(&out.params.buffer, 0, &bytes);
        out
    }

    /// One plan per island size and tree route: a workgroup never waits on
    /// a larger island. (One dispatch over all sizes per round was tried:
    /// 12x fewer dispatches but 35% slower at 10k islands on lavapipe, whose
    /// threads then got the small and the large islands in unequal halves.)
    /// Returns the plans and the Params of every dispatch, in order.
    fn plans(&self) -> Result<(Vec<Plan<'a>>, Vec<Params>), Error> {
        let mut plans = Vec::new();
        let mut params = Vec::new();
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
                Some((stage, split(tree_span, self.max_groups, &mut params)))
            };
            if !self.plan.lemke
                && self.plan.kernel.for_n(n as usize) == EnumerationKernel::Workgroup
            {
                span.per_group = 1;
            }
            let stage = self.size_stage(n)?;
            let ranges = (stage, split(span, self.max_groups, &mut params));
            plans.push(Plan { n, tree, ranges });
            first = last;
        }
        Ok((plans, params))
    }

    /// The bind groups of every plan's dispatches.
    fn buckets(&self, plans: Vec<Plan<'a>>, out: &Outputs) -> Result<Vec<Bucket>, Error> {
        let stride = Outputs::params_stride(self.ctx);
        let params_size = wgpu::BufferSize::new(std::mem::size_of::<Params>() as u64);
        let whole = |b: &'a wgpu::Buffer| b.as_entire_buffer_binding();
        let bind = |(stage, dispatches): (&Stage, Vec<(usize, u32)>)| -> Ranges {
            let bind_one = |(at, groups): (usize, u32)| {
                let params = wgpu::BufferBinding {
                    buffer: &out.params.buffer,
                    offset: at as u64 * stride,
                    size: params_size,
                };
                let parts = [
                    params,
                    whole(self.islands),
                    whole(self.values),
                    out.results.binding(),
                    out.z.binding(),
                    out.unfinished.binding(),
                    out.least.binding(),
                    whole(self.tolerances),
                ];
                (stage.bind_parts(self.ctx, &parts), groups)
            };
            dispatches.into_iter().map(bind_one).collect()
        };
        Ok(plans
            .into_iter()
            .map(|p| Bucket {
                n: p.n,
                tree: p.tree.map(bind),
                ranges: bind(p.ranges),
            })
            .collect())
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
                    let u = &out.unfinished;
                    encoder.clear_buffer(&u.buffer, 0, Some(u.size));
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
            let unfinished = [(&out.unfinished.buffer, UNFINISHED_BYTES)];
            let counts = ctx.submit_and_read(encoder, &unfinished)?;
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
        let reads = [
            (&out.results.buffer, out.results.bytes),
            (&out.z.buffer, out.z.bytes),
        ];
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
