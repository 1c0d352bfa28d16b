//! The enumeration stage: every island of a table through its size's
//! kernel (and first through the tree kernel where routed), in rounds until
//! every island is done; or, with [`KernelPlan::lemke`], through the Lemke
//! kernel, one dispatch per size in one round (it always finishes).

use super::buffers::{Role, Submitted};
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
    /// The island table (binding 1) and every island's M and q (binding 2),
    /// held until the job ends ([`InFlight::finish`]).
    pub islands: wgpu::Buffer,
    pub values: wgpu::Buffer,
    /// The tolerances uniform (binding 7, [`super::pipelines::Tolerances`]).
    pub tolerances: &'a wgpu::Buffer,
    pub table: &'a [PackedIsland],
    pub tree: &'a [TreeRoute],
    /// Run the settle kernel over the table before the first round
    /// (`shaders/enumeration_settle.wgsl`): LCP batches whose table
    /// carries warm or predicted bases ([`PackedIsland::contacts`]).
    pub settle: bool,
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
        self,
        encoder: wgpu::CommandEncoder,
        read_back: bool,
    ) -> Result<EnumerationRun, Error> {
        self.start(encoder)?.finish(read_back)
    }

    /// The first submission of [`Self::run`] (`encoder` and the first
    /// round), not waited for: the host works while the device runs it,
    /// then [`InFlight::finish`] does the rest.
    pub(crate) fn start(self, mut encoder: wgpu::CommandEncoder) -> Result<InFlight<'a>, Error> {
        let t = Instant::now();
        let run = EnumerationRun {
            results: Vec::new(),
            z: Vec::new(),
            figures: GpuFigures::default(),
        };
        let mut flight = InFlight {
            stamps: Stamps::new(self.ctx),
            job: self,
            state: None,
            active: Vec::new(),
            per_submit: 1,
            run,
            submitted: None,
            answers_read: false,
        };
        if flight.job.table.is_empty() {
            // Nothing to enumerate (prediction settled every island): run what
            // the encoder holds (assembly).
            flight.submitted = Some(flight.job.ctx.submit_reads(encoder, &[]));
        } else {
            let job = &flight.job;
            let (plans, mut params) = job.plans()?;
            let everything = Span::items(0, job.table.len() as u32);
            let settle = job
                .settle
                .then(|| split(everything, job.max_groups, &mut params));
            let out = job.outputs(&params, &mut encoder);
            let buckets = job.buckets(plans, &out)?;
            if let Some(dispatches) = settle {
                // After `outputs` cleared the records, before the first round.
                let stage = job.pipelines.settle(job.ctx)?;
                let ranges = job.bind(stage, dispatches, &out);
                job.ctx.record(&mut encoder, stage, &ranges);
                flight.run.figures.dispatches += ranges.len();
            }
            flight.active = (0..buckets.len()).collect();
            flight.state = Some((out, buckets));
            flight.submit(encoder)?;
        }
        flight.run.figures.kernel_seconds += t.elapsed().as_secs_f64();
        Ok(flight)
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
        let bind = |(stage, dispatches)| self.bind(stage, dispatches, out);
        Ok(plans
            .into_iter()
            .map(|p| Bucket {
                n: p.n,
                tree: p.tree.map(bind),
                ranges: bind(p.ranges),
            })
            .collect())
    }

    /// The bind groups of `stage`'s `dispatches` (the index of each one's
    /// Params, its workgroups) over the job's buffers and `out`.
    fn bind(&self, stage: &Stage, dispatches: Vec<(usize, u32)>, out: &Outputs) -> Ranges {
        let stride = Outputs::params_stride(self.ctx);
        let params_size = wgpu::BufferSize::new(std::mem::size_of::<Params>() as u64);
        let bind_one = |(at, groups): (usize, u32)| {
            let params = wgpu::BufferBinding {
                buffer: &out.params.buffer,
                offset: at as u64 * stride,
                size: params_size,
            };
            let parts = [
                params,
                self.islands.as_entire_buffer_binding(),
                self.values.as_entire_buffer_binding(),
                out.results.binding(),
                out.z.binding(),
                out.unfinished.binding(),
                out.least.binding(),
                self.tolerances.as_entire_buffer_binding(),
            ];
            (stage.bind_parts(self.ctx, &parts), groups)
        };
        dispatches.into_iter().map(bind_one).collect()
    }

    /// Counts the tree kernel's decisions in `run.results`.
    fn count_tree(&self, run: &mut EnumerationRun) {
        let tree_count = |v: u32| {
            run.results
                .iter()
                .enumerate()
                .filter(|&(i, r)| self.route(i) != TreeRoute::Off && r._pad1 == v)
                .count()
        };
        run.figures.tree_decided = tree_count(TREE_DECIDED);
        run.figures.tree_undecided = tree_count(TREE_UNDECIDED);
    }
}

/// A job on the device ([`EnumerationJob::start`]): its buffers, the
/// buckets still unfinished and the submission in flight.
pub(crate) struct InFlight<'a> {
    job: EnumerationJob<'a>,
    /// The outputs and buckets (None: an empty table).
    state: Option<(Outputs, Vec<Bucket>)>,
    active: Vec<usize>,
    per_submit: usize,
    run: EnumerationRun,
    stamps: Option<Stamps>,
    submitted: Option<Submitted>,
    /// Whether the last submission read results and z too (the Lemke
    /// kernel: one round ends every island).
    answers_read: bool,
}

impl InFlight<'_> {
    /// Records `per_submit` rounds of the active buckets into `encoder`
    /// (between timestamps where the device has them) and submits it with
    /// the copies of the unfinished counts (and, for the Lemke kernel's
    /// first round, of results and z), waiting for nothing.
    fn submit(&mut self, mut encoder: wgpu::CommandEncoder) -> Result<(), Error> {
        let job = &self.job;
        let ctx = job.ctx;
        let Some((out, buckets)) = &self.state else {
            return Ok(());
        };
        if let Some(s) = &self.stamps {
            s.write(&mut encoder, 0);
        }
        let rounds = self.run.figures.rounds;
        for r in 0..self.per_submit {
            if r + 1 == self.per_submit {
                // Count only what the last round of this submission leaves.
                let u = &out.unfinished;
                encoder.clear_buffer(&u.buffer, 0, Some(u.size));
            }
            for &b in &self.active {
                let bucket = &buckets[b];
                match &bucket.tree {
                    Some(t) if rounds + r == 0 => {
                        let stage = job.pipelines.tree(ctx, bucket.n as usize)?;
                        ctx.record(&mut encoder, stage, t);
                        self.run.figures.dispatches += t.len();
                    }
                    _ => {
                        ctx.record(&mut encoder, job.size_stage(bucket.n)?, &bucket.ranges);
                        self.run.figures.dispatches += bucket.ranges.len();
                    }
                }
            }
        }
        self.run.figures.rounds += self.per_submit;
        let mut reads = vec![(&out.unfinished.buffer, UNFINISHED_BYTES)];
        if let Some(s) = &self.stamps {
            s.write(&mut encoder, 1);
            encoder.resolve_query_set(&s.set, 0..2, &s.resolved, 0);
            reads.push((&s.resolved, 16));
        }
        // The Lemke kernel ends every island in its one round: its answers
        // come back with the counts, without a submission of their own.
        self.answers_read = job.plan.lemke && rounds == 0;
        if self.answers_read {
            reads.push((&out.results.buffer, out.results.bytes));
            reads.push((&out.z.buffer, out.z.bytes));
        }
        self.submitted = Some(ctx.submit_reads(encoder, &reads));
        Ok(())
    }

    /// Waits for the submission in flight and submits rounds (doubling the
    /// rounds per submission, up to 256) until no island is unfinished;
    /// then, with `read_back`, reads results and z. The buffers go back to
    /// the context for the next chunk or call.
    pub(crate) fn finish(mut self, read_back: bool) -> Result<EnumerationRun, Error> {
        let ctx = self.job.ctx;
        let t = Instant::now();
        let mut answers = None;
        while let Some(submitted) = self.submitted.take() {
            let (stamps, with_answers) = (self.stamps.is_some(), self.answers_read);
            let (counts, ticks, got) = ctx.map_reads(submitted, |bytes| {
                let counts: Vec<u32> =
                    bytemuck::pod_collect_to_vec(bytes.first().copied().unwrap_or(&[]));
                let ticks: Option<Vec<u64>> = stamps
                    .then(|| bytemuck::pod_collect_to_vec(bytes.get(1).copied().unwrap_or(&[])));
                let at = 1 + stamps as usize;
                let got = with_answers.then(|| {
                    let r: Vec<BasisResult> =
                        bytemuck::pod_collect_to_vec(bytes.get(at).copied().unwrap_or(&[]));
                    let z = bytes.get(at + 1).copied().unwrap_or(&[]);
                    (r, scalars_from_bytes(z, ctx.precision()))
                });
                (counts, ticks, got)
            })?;
            if let (Some(s), Some(&[t0, t1])) = (&self.stamps, ticks.as_deref()) {
                let secs = t1.saturating_sub(t0) as f64 * s.period_ns * 1e-9;
                *self.run.figures.kernel_device_seconds.get_or_insert(0.0) += secs;
            }
            let Some((_, buckets)) = &self.state else {
                break;
            };
            self.active
                .retain(|&b| counts.get(buckets[b].n as usize).copied().unwrap_or(0) > 0);
            if self.active.is_empty() {
                answers = got;
                break;
            }
            // Every round visits at least one basis of every unfinished island.
            if self.run.figures.rounds > (1 << MAX_GPU_N) + 1 {
                return Err(Error::Gpu(
                    "enumeration made no progress (rounds exceed 2^16)".into(),
                ));
            }
            self.per_submit = (self.per_submit * 2).min(256);
            self.submit(ctx.encoder("enumeration rounds"))?;
        }
        self.run.figures.kernel_seconds += t.elapsed().as_secs_f64();
        let Some((out, buckets)) = self.state.take() else {
            return Ok(self.run);
        };
        if read_back {
            let t = Instant::now();
            let (results, z) = match answers {
                Some(got) => got,
                None => {
                    let reads = [
                        (&out.results.buffer, out.results.bytes),
                        (&out.z.buffer, out.z.bytes),
                    ];
                    let mut read = ctx
                        .submit_and_read(ctx.encoder("enumeration readback"), &reads)?
                        .into_iter();
                    let r_bytes = read.next().unwrap_or_default();
                    let z_bytes = read.next().unwrap_or_default();
                    let results = bytemuck::try_cast_slice(&r_bytes)
                        .map_err(|e| Error::Gpu(format!("results: {e}")))?
                        .to_vec();
                    (results, scalars_from_bytes(&z_bytes, ctx.precision()))
                }
            };
            (self.run.results, self.run.z) = (results, z);
            self.job.count_tree(&mut self.run);
            self.run.figures.readback_seconds = t.elapsed().as_secs_f64();
        }
        // Every submission reading them has ended (the loop waited for the
        // last): the next chunk or call may take them.
        drop(buckets);
        out.keep(ctx);
        Ok(self.run)
    }

    /// The job's island table and values buffers, for the caller to keep.
    pub(crate) fn buffers(&self) -> (wgpu::Buffer, wgpu::Buffer) {
        (self.job.islands.clone(), self.job.values.clone())
    }
}

/// GPU timestamps around each submission's rounds, where the device has
/// `TIMESTAMP_QUERY`: a query set of two and the buffer they resolve into.
struct Stamps {
    set: wgpu::QuerySet,
    resolved: wgpu::Buffer,
    /// Nanoseconds per tick.
    period_ns: f64,
}

impl Stamps {
    fn new(ctx: &GpuContext) -> Option<Self> {
        if !ctx
            .device
            .features()
            .contains(wgpu::Features::TIMESTAMP_QUERY)
        {
            return None;
        }
        let set = ctx.device.create_query_set(&wgpu::QuerySetDescriptor {
            label: Some("enumeration timestamps"),
            ty: wgpu::QueryType::Timestamp,
            count: 2,
        });
        let resolved = ctx.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("enumeration timestamps"),
            size: 16,
            usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let period_ns = ctx.queue.get_timestamp_period() as f64;
        Some(Stamps {
            set,
            resolved,
            period_ns,
        })
    }

    /// An empty pass writing timestamp `at`: 0 at its beginning (before
    /// the rounds), 1 at its end (after them).
    fn write(&self, encoder: &mut wgpu::CommandEncoder, at: u32) {
        let writes = wgpu::ComputePassTimestampWrites {
            query_set: &self.set,
            beginning_of_pass_write_index: (at == 0).then_some(0),
            end_of_pass_write_index: (at == 1).then_some(1),
        };
        encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("timestamp"),
            timestamp_writes: Some(writes),
        });
    }
}
