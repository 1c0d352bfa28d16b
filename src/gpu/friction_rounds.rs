//! The cone projection iterations on the GPU: frictional islands packed
//! into chunks under the binding limits, and the rounds of
//! `shaders/friction_projected.wgsl` until every island is done.

use bytemuck::{Pod, Zeroable};

use super::buffers::Role;
use super::dispatch::{Ranges, Span};
use super::layout::{scalar_from_bytes, scalars_from_bytes, scalars_to_bytes};
use super::pipelines::{Pipelines, Stage};
use super::{GpuContext, Precision};
use crate::cpu::batch::parallel_fill;
use crate::friction::{FrictionProblem, ProjectedMethod};
use crate::Error;

/// Largest island the shader takes (3k ≤ 48 entries; `MAX_DIM` there).
pub const MAX_GPU_CONTACTS: usize = 16;

/// WGSL `FrictionIsland`: an island's contacts and where its data lie.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Pod, Zeroable)]
pub(crate) struct PackedFrictionIsland {
    /// k, the island's contacts.
    pub k: u32,
    /// Offset of W in `values` (q follows at + 9k², μ at + 9k² + 3k).
    pub data: u32,
    /// Offset of the island's vectors in `vectors`.
    pub vectors: u32,
    /// The island's place in the chunk: its entry in `states` and
    /// `scalars` (the table the rounds see holds only running islands).
    pub slot: u32,
}

/// WGSL `FrictionState`: where one island's iteration stands.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Pod, Zeroable)]
pub(crate) struct FrictionState {
    /// [`NOT_STARTED`], [`RUNNING`], [`CONVERGED`], [`AT_CAP`], [`FAILED`].
    pub status: u32,
    pub iterations: u32,
    pub restarts: u32,
    /// APGD: doublings of L so far in the current iteration.
    pub doublings: u32,
}

/// [`FrictionState::status`]: not started (zeroed buffers).
#[allow(dead_code, reason = "the shader's value, named for the record")]
pub(crate) const NOT_STARTED: u32 = 0;
/// Still iterating.
pub(crate) const RUNNING: u32 = 1;
/// The shader's stop measure met the tolerance.
#[cfg_attr(not(test), allow(dead_code))]
pub(crate) const CONVERGED: u32 = 2;
/// max_iterations reached.
pub(crate) const AT_CAP: u32 = 3;
/// A non-finite error or step (the CPU twin's numerical failure).
pub(crate) const FAILED: u32 = 4;

/// Scalars per island in `scalars`: θ, L, best error, last error.
const SCALARS: usize = 4;
/// Steps per island in the first round, then 2×, 4×, … up to
/// [`GROWN_TRIES`], each round its own submission with the finished islands
/// dropped; then the full round budget. Why: the lanes of a SIMD group on
/// llvmpipe wait for the slowest island of the group within a round, and
/// the iteration counts are skewed (APGD on random spheres k = 4: median
/// 53, p90 116, max 565), so one long round keeps most lanes idle; each
/// round also reloads every running island (W and its vectors, about as
/// much as 20 steps at k = 4, measured), so the first round is long enough
/// that the quick sets (boxes, stacks: at most 60 steps) finish in it.
/// 2026-11-26 on lavapipe, 10,000 islands: APGD random spheres k = 4 rounds
/// 0.10 → 0.08 s, PGS 0.19 → 0.14 s, Jacobi 0.45 → 0.40 s.
pub(crate) const FIRST_TRIES: u32 = 64;
/// See [`FIRST_TRIES`].
const GROWN_TRIES: u32 = 1024;
/// Bytes of `unfinished`: one counter per k = 0…16.
const UNFINISHED_BYTES: u64 = 17 * 4;

/// Scalars of an island's vectors: sweeps x and the steps (4k); APGD x,
/// u(x), y, u(y), best (15k), padded to a multiple of 4 (the k ≤ 4 kernels
/// read and write them as vec4).
fn vector_len(method: ProjectedMethod, k: usize) -> usize {
    if method == ProjectedMethod::Apgd {
        (15 * k).next_multiple_of(4)
    } else {
        4 * k
    }
}

/// Scalars of an island's block in `values`: W, q, μ (9k² + 4k), padded to
/// a multiple of 4 (read as vec4 by the k ≤ 4 kernels).
fn values_len(p: &FrictionProblem) -> usize {
    (p.w.len() + p.q.len() + p.mu.len()).next_multiple_of(4)
}

/// Where the answer lies among an island's vectors: APGD's best iterate,
/// the sweeps' x.
fn answer_offset(method: ProjectedMethod, k: usize) -> usize {
    if method == ProjectedMethod::Apgd {
        12 * k
    } else {
        0
    }
}

/// A chunk of islands (sorted by k) packed for the shader: where each
/// island's data and vectors lie. The buffers themselves are written at
/// upload, straight from the problems ([`RoundsJob::run`]).
pub(crate) struct FrictionChunk {
    /// The caller's index of each table entry.
    pub order: Vec<usize>,
    table: Vec<PackedFrictionIsland>,
    /// Scalars in `values` (W, q, μ of every island).
    values_len: usize,
    /// Scalars in `vectors` (every island's vectors, its start r0 in the
    /// first 3k).
    vectors_len: usize,
}

/// Packs `problems[i]` for i in `indices` (each valid, k ≤
/// [`MAX_GPU_CONTACTS`]), sorted by k, into chunks whose buffers each stay
/// under `max_bytes` at `sb` bytes per scalar.
pub(crate) fn pack_friction_chunks(
    problems: &[FrictionProblem],
    indices: &[usize],
    method: ProjectedMethod,
    max_bytes: u64,
    sb: u64,
) -> Vec<FrictionChunk> {
    let mut order = indices.to_vec();
    order.sort_by_key(|&i| problems[i].contacts());
    let mut chunks = Vec::new();
    let mut at = 0;
    while at < order.len() {
        let mut chunk = FrictionChunk {
            order: Vec::new(),
            table: Vec::new(),
            values_len: 0,
            vectors_len: 0,
        };
        while at < order.len() {
            let i = order[at];
            let p = &problems[i];
            let k = p.contacts();
            let values = (chunk.values_len + values_len(p)) as u64 * sb;
            let vectors = (chunk.vectors_len + vector_len(method, k)) as u64 * sb;
            let count = chunk.order.len() as u64 + 1;
            let per_island = (SCALARS as u64 * sb).max(16);
            let too_big = values.max(vectors).max(count * per_island) > max_bytes;
            if too_big && !chunk.order.is_empty() {
                break;
            }
            chunk.table.push(PackedFrictionIsland {
                k: k as u32,
                data: chunk.values_len as u32,
                vectors: chunk.vectors_len as u32,
                slot: chunk.table.len() as u32,
            });
            chunk.values_len += values_len(p);
            chunk.vectors_len += vector_len(method, k);
            chunk.order.push(i);
            at += 1;
        }
        chunks.push(chunk);
    }
    chunks
}

/// Writes `src` at scalar `at` of `view` in precision `p` (little-endian,
/// as the shaders read them).
pub(crate) fn write_scalars(
    view: &mut wgpu::WriteOnly<[u8]>,
    at: usize,
    src: &[f64],
    p: Precision,
) {
    if src.is_empty() {
        return;
    }
    if p == Precision::F64 {
        let bytes: &[u8] = bytemuck::cast_slice(src);
        view.slice(8 * at..8 * at + bytes.len())
            .copy_from_slice(bytes);
    } else {
        // A contact's W block rows at a time: small enough for the stack.
        let mut buf = [0u8; 4 * 64];
        for (c, part) in src.chunks(64).enumerate() {
            for (b, &v) in buf.chunks_exact_mut(4).zip(part) {
                b.copy_from_slice(&(v as f32).to_le_bytes());
            }
            let from = 4 * (at + 64 * c);
            view.slice(from..from + 4 * part.len())
                .copy_from_slice(&buf[..4 * part.len()]);
        }
    }
}

/// What the shader gave for one island.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct GpuIslandRun {
    pub state: FrictionState,
    /// The shader's answer (APGD's best iterate, the sweeps' x), in the
    /// shader's precision.
    pub r: Vec<f64>,
    /// The shader's own stop measure of that answer (NaN before the first).
    pub error: f64,
}

/// What the rounds of one chunk did.
pub(crate) struct ChunkRun {
    /// Per table entry.
    pub islands: Vec<GpuIslandRun>,
    pub dispatches: usize,
    pub rounds: usize,
}

/// The fixed inputs of every chunk's rounds.
pub(crate) struct RoundsJob<'a> {
    pub ctx: &'a GpuContext,
    pub pipelines: &'a Pipelines,
    pub method: ProjectedMethod,
    /// The controls uniform (binding 7).
    pub controls: &'a wgpu::Buffer,
    pub budget: u32,
    /// Steps in the first round of a growing schedule ([`FIRST_TRIES`]);
    /// None: every round at `budget`.
    pub first_tries: Option<u32>,
    pub max_groups: u32,
    pub max_iterations: u32,
}

/// The controls uniform: max_iterations and three pads (u32), then
/// tolerance, relaxation and two pads in the shader's precision.
pub(crate) fn controls_buffer(
    ctx: &GpuContext,
    max_iterations: u32,
    tolerance: f64,
    relaxation: f64,
) -> wgpu::Buffer {
    use wgpu::util::DeviceExt;
    let mut bytes: Vec<u8> = bytemuck::cast_slice(&[max_iterations, 0u32, 0, 0]).to_vec();
    bytes.extend(scalars_to_bytes(
        &[tolerance, relaxation, 0.0, 0.0],
        ctx.precision(),
    ));
    ctx.device
        .create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("friction controls"),
            contents: &bytes,
            usage: wgpu::BufferUsages::UNIFORM,
        })
}

/// The chunk's device buffers (bindings 2-6; the table of binding 1 is
/// made per submission from the islands still running).
struct ChunkBuffers {
    values: wgpu::Buffer,
    vectors: wgpu::Buffer,
    vectors_size: u64,
    scalars: wgpu::Buffer,
    scalars_size: u64,
    states: wgpu::Buffer,
    states_size: u64,
    unfinished: wgpu::Buffer,
}

impl RoundsJob<'_> {
    /// The kernel of islands of k contacts.
    fn stage(&self, k: u32) -> Result<&Stage, Error> {
        let apgd = self.method == ProjectedMethod::Apgd;
        self.pipelines
            .friction_projected(self.ctx, k as usize, apgd)
    }

    /// The loop work (see the shader's top) of an island of k contacts in
    /// a round that makes `tries` steps after its start (APGD: backtracking
    /// tries; the sweeps: sweeps), at most the round budget.
    fn budget_for_tries(&self, k: u32, tries: u32) -> u32 {
        let n = 3 * k;
        let product = n * n + n;
        let (start, per_try) = match self.method {
            ProjectedMethod::Apgd => (n * n + 6 * n + 2 * product + 8 * n, product + 10 * n),
            ProjectedMethod::GaussSeidel => (n * n + 4 * n + product, 2 * product + 6 * n),
            _ => (n * n + 4 * n + product, product + 6 * n),
        };
        start
            .saturating_add(tries.saturating_mul(per_try))
            .min(self.budget)
    }

    /// The chunk's buffers, W, q, μ and the starts written straight into
    /// them from `problems` (`warm[i]`, where given, is island i's r0;
    /// else 0, which the zeroed buffer already holds).
    fn upload(
        &self,
        chunk: &FrictionChunk,
        problems: &[FrictionProblem],
        warm: Option<&[Vec<f64>]>,
    ) -> Result<ChunkBuffers, Error> {
        let (ctx, p) = (self.ctx, self.ctx.precision());
        let sb = p.bytes();
        let count = chunk.table.len() as u64;
        let states_size = count * std::mem::size_of::<FrictionState>() as u64;
        let scalars_size = count * SCALARS as u64 * sb;
        let vectors_size = chunk.vectors_len as u64 * sb;
        // Both written in place, in buffers kept from the last chunk where
        // there are (`kept_written`): every byte a shader reads is written
        // here. The shaders read an island's block padding, and drop it.
        let values_size = chunk.values_len as u64 * sb;
        let values = ctx.kept_written(Role::FrictionValues, values_size, |mut view| {
            for (rec, &i) in chunk.table.iter().zip(&chunk.order) {
                let (pr, at) = (&problems[i], rec.data as usize);
                write_scalars(&mut view, at, &pr.w, p);
                write_scalars(&mut view, at + pr.w.len(), &pr.q, p);
                write_scalars(&mut view, at + pr.w.len() + pr.q.len(), &pr.mu, p);
            }
        })?;
        // The first round reads each island's start r0 (x, 3k: 0 without a
        // warm start) and computes the rest of its vectors (it may read a
        // few entries past x, in its own block, and overwrite them).
        let zeros = [0.0; 3 * MAX_GPU_CONTACTS];
        let vectors = ctx.kept_written(Role::FrictionVectors, vectors_size, |mut view| {
            for (rec, &i) in chunk.table.iter().zip(&chunk.order) {
                let k = rec.k as usize;
                let r0 = warm
                    .and_then(|w| w.get(i))
                    .map_or(&zeros[..3 * k], Vec::as_slice);
                write_scalars(&mut view, rec.vectors as usize, r0, p);
            }
        })?;
        Ok(ChunkBuffers {
            values,
            vectors,
            vectors_size,
            scalars: ctx.storage_zeroed("friction scalars", scalars_size),
            scalars_size,
            states: ctx.storage_zeroed("friction states", states_size),
            states_size,
            unfinished: ctx.storage_zeroed("friction unfinished", UNFINISHED_BYTES),
        })
    }

    /// One dispatch range per island size k over `table` (sorted by k;
    /// uploaded here as binding 1), through its kernel (a lane never waits
    /// on a larger island): (k, ranges).
    fn buckets(
        &self,
        table: &[PackedFrictionIsland],
        b: &ChunkBuffers,
        tries: Option<u32>,
    ) -> Result<Vec<(u32, Ranges)>, Error> {
        let gauss_seidel = (self.method == ProjectedMethod::GaussSeidel) as u32;
        let islands = self
            .ctx
            .storage("friction islands", bytemuck::cast_slice(table));
        let mut out = Vec::new();
        let mut first = 0;
        while first < table.len() {
            let k = table[first].k;
            let stage = self.stage(k)?;
            let last = first + table[first..].iter().take_while(|r| r.k == k).count();
            let budget = tries.map_or(self.budget, |t| self.budget_for_tries(k, t));
            let span = Span {
                budget,
                flags: gauss_seidel,
                ..Span::items(first as u32, (last - first) as u32)
            };
            let bind = |params: &wgpu::Buffer| {
                stage.bind(
                    self.ctx,
                    &[
                        params,
                        &islands,
                        &b.values,
                        &b.vectors,
                        &b.scalars,
                        &b.states,
                        &b.unfinished,
                        self.controls,
                    ],
                )
            };
            out.push((k, self.ctx.ranges(span, self.max_groups, &bind)));
            first = last;
        }
        Ok(out)
    }

    /// Runs the chunk's rounds (doubling the rounds per submission up to
    /// 256) until no island runs, and reads the answers back. After each
    /// submission the islands' states come back and the next one
    /// dispatches only the islands still running (on lavapipe every
    /// invocation of a finished island still cost about 1.5 µs a round,
    /// measured: a batch's few slow islands made its rounds cost as much as
    /// all of it).
    /// `problems` and `warm` are the caller's, indexed by `chunk.order`.
    pub(crate) fn run(
        &self,
        chunk: &FrictionChunk,
        problems: &[FrictionProblem],
        warm: Option<&[Vec<f64>]>,
    ) -> Result<ChunkRun, Error> {
        let ctx = self.ctx;
        let b = self.upload(chunk, problems, warm)?;
        let mut run = ChunkRun {
            islands: Vec::new(),
            dispatches: 0,
            rounds: 0,
        };
        // Every round makes each running island try at least one step; a
        // step is accepted after at most 64 doublings of L.
        let cap = (self.max_iterations as usize + 1) * 65 + 1;
        let mut running = chunk.table.clone();
        let mut per_submit = 1usize;
        // Short rounds first (see FIRST_TRIES), then the full budget.
        let mut tries = self.first_tries;
        while !running.is_empty() {
            let buckets = self.buckets(&running, &b, tries)?;
            let mut encoder = ctx.encoder("friction rounds");
            for _ in 0..per_submit {
                for (k, ranges) in &buckets {
                    ctx.record(&mut encoder, self.stage(*k)?, ranges);
                    run.dispatches += ranges.len();
                }
            }
            run.rounds += per_submit;
            let states = ctx.submit_and_read(encoder, &[(&b.states, b.states_size)])?;
            let states: &[FrictionState] = bytemuck::try_cast_slice(&states[0])
                .map_err(|e| Error::Gpu(format!("friction states: {e}")))?;
            running.retain(|rec| {
                states
                    .get(rec.slot as usize)
                    .is_some_and(|st| st.status <= RUNNING)
            });
            if run.rounds > cap {
                return Err(Error::Gpu(format!(
                    "friction iterations made no progress ({} rounds)",
                    run.rounds
                )));
            }
            tries = match tries {
                Some(t) if t < GROWN_TRIES => Some(2 * t),
                Some(_) => None,
                None => {
                    per_submit = (per_submit * 2).min(256);
                    None
                }
            };
        }
        run.islands = self.read(chunk, &b)?;
        ctx.keep(Role::FrictionValues, b.values);
        ctx.keep(Role::FrictionVectors, b.vectors);
        Ok(run)
    }

    /// The answers of the chunk's islands, each island's answer and
    /// scalars taken straight from the mapped readback (the rest of its
    /// vectors stay there).
    fn read(&self, chunk: &FrictionChunk, b: &ChunkBuffers) -> Result<Vec<GpuIslandRun>, Error> {
        let ctx = self.ctx;
        let reads = [
            (&b.vectors, b.vectors_size),
            (&b.scalars, b.scalars_size),
            (&b.states, b.states_size),
        ];
        let p: Precision = ctx.precision();
        let sb = p.bytes() as usize;
        ctx.submit_and_map(ctx.encoder("friction readback"), &reads, |bytes| {
            let (vectors, scalars, state_bytes) = (bytes[0], bytes[1], bytes[2]);
            let states: &[FrictionState] = bytemuck::try_cast_slice(state_bytes)
                .map_err(|e| Error::Gpu(format!("friction states: {e}")))?;
            // Every table entry's place lies inside the buffers as packed:
            // checked once here, so that the reads below cannot miss.
            let n = chunk.table.len();
            if states.len() < n
                || scalars.len() < sb * SCALARS * n
                || vectors.len() < sb * chunk.vectors_len
            {
                return Err(Error::Gpu("friction results: short read".into()));
            }
            // APGD: the best iterate's error; the sweeps: the last one's.
            let e = if self.method == ProjectedMethod::Apgd {
                2
            } else {
                3
            };
            // Over every core: each island's answer is a cache miss or two
            // in the mapped vectors (1.5 ms of about 25 on one core at
            // 10,000 islands of k = 4 on lavapipe, measured).
            let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
            let mut runs = vec![GpuIslandRun::default(); n];
            parallel_fill(&mut runs, threads, |t, run| {
                let rec = &chunk.table[t];
                let (k, v) = (rec.k as usize, rec.vectors as usize);
                let at = sb * (v + answer_offset(self.method, k));
                let e_at = sb * (SCALARS * t + e);
                run.state = states[t];
                run.r = scalars_from_bytes(&vectors[at..at + sb * 3 * k], p);
                run.error = scalar_from_bytes(&scalars[e_at..e_at + sb], p);
            });
            Ok(runs)
        })?
    }
}
