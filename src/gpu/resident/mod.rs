//! Worlds resident on the GPU (issue 23): a batch of worlds (restitution 0)
//! uploaded once and stepped by `shaders/world_step.wgsl` (dispatches
//! the collision phase, the solve, and where a world may have friction
//! rounds of `world_friction`), up to [`MOST_STEPS`] steps per submission,
//! with nothing read back per step but a small record per world.
//!
//! [`ResidentWorlds::new`] packs the worlds ([`layout`]) and uploads them;
//! [`ResidentWorlds::steps`] runs `k` steps in one submission and reads
//! back each step's per-world records; [`ResidentWorlds::restore`] puts
//! back the state as it was before such a submission;
//! [`ResidentWorlds::read_states`] and [`ResidentWorlds::read_worlds`]
//! copy the states (of all worlds, of some) into `World`s;
//! [`ResidentWorlds::write_world`] replaces one world's state (after the
//! host stepped it on the CPU).
//!
//! Bytes read back per step: [`REC`] scalars and 4 words per world (80
//! bytes in f64); the states, 13 scalars and 2 words per body, only when
//! asked.
//!
//! Buffers are sized once from the worlds: [`layout::contact_slots`]
//! contact slots per world (4 per pair that may touch: never reached by
//! the narrow phase, which gives at most 4 points per pair), islands up to
//! [`layout::ISLAND_MAX`] contacts; a world past either is flagged
//! ([`layout::flags`]) and keeps its state on the device. With friction,
//! [`layout::FR`] more scalars per world (one island's rows, W, q and the
//! sweeps' vectors) and 6 per contact slot (this step's reactions and the
//! warm-start memory). The narrow phase keeps each candidate pair's
//! manifold in [`layout::contact_slots`] pair records of [`CP`] scalars
//! per world before it orders the contacts. Several steps per submission
//! keep a copy of the state, the words and the warm-start memory, and
//! [`MOST_STEPS`] steps' records (at most 64 MiB).

mod dispatch;
pub mod layout;
mod transfer;

pub use transfer::{MemoryEntry, States};

use super::kernel::round_budget;
use super::layout::{scalars_from_bytes, scalars_to_bytes};
use super::{GpuContext, GpuSolveSettings, Precision};
use crate::friction::ProjectedMethod;
use crate::world::World;
use crate::Error;
use layout::{
    contact_slots, may_have_friction, pack_body_consts, pack_body_state, pack_world_consts, BC, CP,
    FR, REC, ROW, WC,
};
use std::cell::Cell;

/// The frictional phase's settings: those of its CPU twin, the projected
/// sweeps of `friction/projected.rs` (relaxation 1) or `friction/apgd.rs`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ResidentFriction {
    /// An island is solved when its cone error is at most this.
    pub tolerance: f64,
    /// Sweeps (APGD iterations) before the iteration stops (not solved
    /// unless within the tolerance).
    pub max_iterations: u32,
    /// Gauss–Seidel sweeps (`pgs`), Jacobi sweeps or APGD.
    pub method: ProjectedMethod,
    /// Start from the reactions of the last step (by contact id).
    pub warm_start: bool,
}

/// Most rounds of the frictional phase in one step.
pub const MAX_ROUNDS: u32 = 1024;

/// What one step gave for one world.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct WorldRecord {
    /// [`layout::flags`] bits: 0 when the kernel stepped the world.
    pub flags: u32,
    /// Contacts and islands this step.
    pub contacts: usize,
    pub islands: usize,
    /// Kinetic and potential energy after the step (J).
    pub kinetic: f64,
    pub potential: f64,
    /// Deepest penetration among this step's contacts (m, ≥ 0).
    pub max_penetration: f64,
    /// Largest LCP error measure of the world's islands.
    pub max_error: f64,
    /// Dynamic bodies awake after the step.
    pub awake: usize,
    /// Rounds of `world_friction` the world was active in this step (0:
    /// not handed over).
    pub rounds: u32,
}

/// Offsets of the frictional phase's parts (see `StepParams` in the
/// shader), 0 where no world may have friction.
#[derive(Clone, Copy, Debug, Default)]
struct FrictionAt {
    region: usize,
    reactions: usize,
    memory_r: usize,
    memory: usize,
}

/// Loop work per invocation and round of `world_friction`: a quarter of
/// the loop budget. llvmpipe runs 8 invocations in lockstep and counts
/// their loop iterations together; worlds in different phases (assembly,
/// sweeps, judgement) add up, and past about 65,535 the loops end early
/// (seen: a 4-box stack batched with smaller ones left the CPU's
/// trajectory by 3 µm, alone it kept it to 2e-15 m).
fn friction_budget(budget: u32) -> u32 {
    (budget / 4).max(1)
}

/// The state, the words, the records (whose last two scalars are
/// `world_solve_warm`'s warm basis) and the warm-start memory as they were
/// before a submission of several steps.
struct Saved {
    state: wgpu::Buffer,
    words: wgpu::Buffer,
    records: wgpu::Buffer,
    memory: wgpu::Buffer,
}

/// Most steps in one submission ([`ResidentWorlds::steps`]).
pub const MOST_STEPS: usize = 16;

/// The per-world records of one step from its [`REC`] scalars per world
/// (`rec`) and its 4 words per world (`out`: contacts, moving bodies,
/// flags, islands).
fn records_of(rec: &[f64], out: &[u32]) -> Vec<WorldRecord> {
    (rec.chunks(REC).zip(out.chunks(4)))
        .map(|(r, o)| WorldRecord {
            flags: o[2],
            contacts: o[0] as usize,
            islands: o[3] as usize,
            kinetic: r[0],
            potential: r[1],
            max_penetration: r[2],
            max_error: r[3],
            awake: r[4] as usize,
            rounds: r[5] as u32,
        })
        .collect()
}

/// A batch of worlds on the device (see the module docs).
pub struct ResidentWorlds {
    /// First body of each world, and the total at the end.
    first: Vec<usize>,
    slots: usize,
    /// The narrow phase's pair records: where they start in `scratch`, and
    /// how many per world (4 per pair that may touch, whatever `slots`).
    pairs_at: usize,
    pair_slots: usize,
    /// `candidate_pairs`' per-body reaches (in `scratch`) and per-world
    /// candidates (in `words`): where they start.
    reach_at: usize,
    cands_at: usize,
    budget: u32,
    tolerances: [f64; 3],
    friction: Option<ResidentFriction>,
    /// `world_solve_warm` tries last step's bases first (the CPU path's
    /// `warm_settle`: `warm_start` on, a method that predicts).
    warm_bases: bool,
    at: FrictionAt,
    /// Rounds of `world_friction` per step (0: none).
    rounds: Cell<u32>,
    precision: Precision,
    params: wgpu::Buffer,
    state: wgpu::Buffer,
    scratch: wgpu::Buffer,
    words: wgpu::Buffer,
    records: wgpu::Buffer,
    /// The step's work lists (the worlds `world_solve_warm` leaves to
    /// `world_lemke`, two words each, the pairs of each family for the narrow phase): per
    /// list the indirect dispatch's workgroups (x, y, z) and the count,
    /// then the entries ([`dispatch`]); and the headers copied aside for
    /// the dispatches.
    lists: wgpu::Buffer,
    list_groups: wgpu::Buffer,
    bind: wgpu::BindGroup,
    /// Each step's records within a submission ([`Self::steps`]): per step
    /// the records, then the worlds' 4 words; mapped in place.
    history: wgpu::Buffer,
    most_steps: usize,
    /// The copies [`Self::restore`] puts back (None: one step per
    /// submission).
    saved: Option<Saved>,
    bytes_read: Cell<u64>,
    /// Bytes uploaded by [`Self::new`].
    pub bytes_up: u64,
}

impl ResidentWorlds {
    /// Uploads `worlds` (each within [`layout::out_of_scope`]'s limits,
    /// checked by the caller) to `ctx`. `tolerance`: the door's final
    /// check; `gpu`: Lemke's pivot tolerance and cap, the loop budget;
    /// `warm_bases`: frictionless islands start from last step's basis
    /// where their contacts are last step's (else Lemke from the empty
    /// basis every step); `friction`: the frictional phase's settings (None: a world with
    /// friction is flagged NOT_SOLVED); `slots`: contact slots per world
    /// (None: [`contact_slots`]).
    ///
    /// # Errors
    /// [`Error::Unsupported`] where a buffer would pass the device's
    /// binding limit or there are more worlds than one dispatch takes;
    /// [`Error::Gpu`] for device trouble.
    pub fn new(
        ctx: &GpuContext,
        worlds: &[World],
        tolerance: f64,
        gpu: &GpuSolveSettings,
        warm_bases: bool,
        friction: Option<ResidentFriction>,
        slots: Option<usize>,
    ) -> Result<Self, Error> {
        let slots = slots.unwrap_or_else(|| contact_slots(worlds)).max(1);
        let precision = ctx.precision();
        let sb = precision.bytes() as usize;
        let mut first = Vec::with_capacity(worlds.len() + 1);
        let mut info: Vec<[u32; 4]> = Vec::with_capacity(worlds.len());
        let total: usize = worlds.iter().map(|w| w.bodies.len()).sum();
        let mut consts = Vec::with_capacity(worlds.len() * WC + total * BC);
        let (mut state, mut sleep) = (Vec::new(), Vec::new());
        let mut bodies = 0;
        for w in worlds {
            first.push(bodies);
            info.push([bodies as u32, w.bodies.len() as u32, w.sleep.steps, 0]);
            pack_world_consts(w, &mut consts);
            bodies += w.bodies.len();
        }
        first.push(bodies);
        for b in worlds.iter().flat_map(|w| &w.bodies) {
            pack_body_consts(b, &mut consts);
            pack_body_state(b, &mut state, &mut sleep);
        }
        let n = worlds.len();
        let contacts_at = 6 * bodies;
        // The contact slots, then their rows (world_assemble).
        let mut scratch_len = contacts_at + n * slots * (CP + ROW);
        let keys_at = 2 * bodies + 4 * n;
        let fstate_at = keys_at + 4 * n * slots;
        let mut words_len = fstate_at + 4 * n;
        let friction = friction.filter(|_| worlds.iter().any(may_have_friction));
        let mut at = FrictionAt::default();
        if friction.is_some() {
            at.reactions = scratch_len;
            at.memory_r = at.reactions + 3 * n * slots;
            at.region = at.memory_r + 3 * n * slots;
            scratch_len = at.region + n * FR;
            at.memory = words_len;
            words_len += n * (slots + 1);
        }
        let pairs_at = scratch_len;
        let pair_slots = contact_slots(worlds);
        scratch_len += n * pair_slots * CP;
        // candidate_pairs' per-body reaches and per-world candidates
        // (count, bodies, count words: pair_slots / 4 candidates at most).
        let reach_at = scratch_len;
        scratch_len += bodies;
        let cands_at = words_len;
        let candidates = pair_slots / crate::gpu::collide::SLOTS;
        words_len += n * (1 + 2 * candidates);
        // The lists: the headers, the worlds for Lemke's path (a world and
        // its islands each), three pair lists.
        let lists_len = dispatch::LIST_HEADERS as usize / 4 + 2 * n + 3 * n * candidates;
        let largest = [
            scratch_len * sb,
            words_len * 4,
            consts.len() * sb,
            lists_len * 4,
        ];
        let limit = ctx.limits().max_storage_buffer_binding_size;
        let groups = n.div_ceil(super::pipelines::WORKGROUP as usize);
        if largest.iter().any(|&b| b as u64 > limit) || groups > 65_535 {
            return Err(Error::Unsupported(format!(
                "{n} resident worlds of {slots} contact slots do not fit the device's limits"
            )));
        }
        let budget = round_budget(ctx, gpu);
        // The first step's rounds: an island of min(16, slots) contacts
        // assembled, swept up to the cap and judged (the shader's costs);
        // the caller sizes the later steps' ([`Self::set_rounds`]).
        let k = slots.min(16) as u64;
        let sweeps = u64::from(friction.map_or(0, |f| f.max_iterations)) + 1;
        let work = 12 * k * k + k * (slots as u64 + 1) + 64 + sweeps * (2 * k * k + 8 * k + 16);
        let rounds = match friction {
            Some(_) => {
                let per_round = u64::from(friction_budget(budget));
                work.div_ceil(per_round).clamp(1, u64::from(MAX_ROUNDS)) as u32
            }
            None => 0,
        };
        let lemke = &gpu.lemke;
        let stages = ctx.pipelines()?;
        ctx.scoped("uploading resident worlds", || -> Result<Self, Error> {
            let mut words = sleep;
            words.resize(words_len.max(4), 0);
            let info_buffer = ctx.storage("worlds", bytemuck::cast_slice(&info));
            let consts_buffer = ctx.storage("consts", &scalars_to_bytes(&consts, precision));
            let state_buffer = ctx.storage("state", &scalars_to_bytes(&state, precision));
            let scratch = ctx.storage_zeroed("scratch", (scratch_len * sb) as u64);
            let words_buffer = ctx.storage("words", bytemuck::cast_slice(&words));
            let records = ctx.storage_zeroed("records", (n * REC * sb) as u64);
            let params = ctx.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("world step params"),
                size: 128,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            // Every list empty: workgroups 0 × 1 × 1, count 0 (the
            // kernels empty them again each step).
            use wgpu::util::DeviceExt;
            let lists = ctx
                .device
                .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some("world step lists"),
                    contents: bytemuck::cast_slice(&dispatch::empty_lists(lists_len)),
                    usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
                });
            let list_groups = ctx.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("world step list workgroups"),
                size: dispatch::LIST_HEADERS,
                usage: wgpu::BufferUsages::INDIRECT | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let stage = &stages.world_step(ctx)?.candidate_pairs;
            let bind = stage.bind(
                ctx,
                &[
                    &params,
                    &info_buffer,
                    &consts_buffer,
                    &state_buffer,
                    &scratch,
                    &words_buffer,
                    &records,
                    &lists,
                ],
            );
            // Each step's records of a submission: up to MOST_STEPS, within
            // 64 MiB.
            let stride = (n * (REC * sb + 16)) as u64;
            let most_steps = ((64 << 20) / stride).clamp(1, MOST_STEPS as u64);
            let history = ctx.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("world step records"),
                size: most_steps * stride,
                usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let copy = |label, b: &wgpu::Buffer| ctx.storage_zeroed(label, b.size());
            let saved = (most_steps > 1).then(|| Saved {
                state: copy("saved state", &state_buffer),
                words: copy("saved words", &words_buffer),
                records: copy("saved records", &records),
                memory: ctx.storage_zeroed("saved memory", (3 * n * slots * sb) as u64),
            });
            let r = ResidentWorlds {
                bytes_up: ((consts.len() + state.len()) * sb + words.len() * 4 + n * 16) as u64,
                history,
                most_steps: most_steps as usize,
                saved,
                bytes_read: Cell::new(0),
                first,
                slots,
                pairs_at,
                pair_slots,
                reach_at,
                cands_at,
                budget,
                tolerances: [tolerance, lemke.pivot_tol, lemke.max_pivots as f64],
                friction,
                warm_bases,
                at,
                rounds: Cell::new(rounds),
                precision,
                params,
                state: state_buffer,
                scratch: scratch.clone(),
                words: words_buffer,
                records,
                lists,
                list_groups,
                bind,
            };
            r.write_params(ctx, 0.0);
            Ok(r)
        })?
    }

    /// Worlds held.
    fn count(&self) -> usize {
        self.first.len() - 1
    }

    /// The uniform for a step of `dt` (see `StepParams` in the shader).
    fn write_params(&self, ctx: &GpuContext, dt: f64) {
        let n = self.count();
        let bodies = self.first[n];
        let keys_at = 2 * bodies + 4 * n;
        let f = self.friction.unwrap_or(ResidentFriction {
            tolerance: 0.0,
            max_iterations: 0,
            method: ProjectedMethod::Jacobi,
            warm_start: false,
        });
        // The shader's method word (`world_friction.wgsl`'s METHOD_APGD).
        let method = match f.method {
            ProjectedMethod::Jacobi => 0,
            ProjectedMethod::GaussSeidel => 1,
            ProjectedMethod::Apgd => 2,
        };
        let at = self.at;
        let ints: [u32; 21] = [
            n as u32,
            self.slots as u32,
            (n * WC) as u32,
            (2 * bodies) as u32,
            keys_at as u32,
            self.budget,
            (6 * bodies) as u32,
            at.region as u32,
            (keys_at + 4 * n * self.slots) as u32,
            f.max_iterations,
            method,
            u32::from(f.warm_start),
            at.reactions as u32,
            at.memory as u32,
            at.memory_r as u32,
            friction_budget(self.budget),
            self.pairs_at as u32,
            self.pair_slots as u32,
            u32::from(self.warm_bases),
            self.cands_at as u32,
            self.reach_at as u32,
        ];
        let [tol, pivot, pivots] = self.tolerances;
        let mut bytes = bytemuck::cast_slice(&ints).to_vec();
        // The scalars at their alignment (StepParams' `dt`).
        let align = self.precision.bytes() as usize;
        bytes.resize(bytes.len().next_multiple_of(align), 0);
        let scalars = [dt, tol, pivot, pivots, f.tolerance];
        bytes.extend(scalars_to_bytes(&scalars, self.precision));
        bytes.resize(128, 0);
        ctx.queue.write_buffer(&self.params, 0, &bytes);
    }

    /// One step of `dt` for every world held ([`Self::steps`] with `k` 1):
    /// the per-world records.
    ///
    /// # Errors
    /// [`Error::Gpu`] for device trouble.
    pub fn step(&self, ctx: &GpuContext, dt: f64) -> Result<Vec<WorldRecord>, Error> {
        Ok(self.steps(ctx, dt, 1)?.pop().expect("one step"))
    }

    /// [`Self::steps_and_states`] without the states.
    ///
    /// # Errors
    /// [`Error::Gpu`] for device trouble.
    pub fn steps(
        &self,
        ctx: &GpuContext,
        dt: f64,
        k: usize,
    ) -> Result<Vec<Vec<WorldRecord>>, Error> {
        Ok(self.steps_and_states(ctx, dt, k, false)?.0)
    }

    /// `k` steps of `dt` for every world held (1 to [`Self::most_steps`])
    /// in one submission, nothing read back but each step's records, once
    /// (per world [`REC`] scalars and 4 words a step; the states stay on
    /// the device: [`Self::read_states`]). Each step is dispatched as
    /// [`Self::step`] dispatches it and its records copied aside. With `k`
    /// > 1 the state, the words and the warm-start memory are first copied
    /// aside on the device ([`Self::restore`] puts them back): a world
    /// flagged in a step keeps its state, and the steps after it step it on
    /// from there, so such a submission must be redone step by step.
    /// With `states`, every world's state after the last step comes back
    /// in the same map ([`Self::unpack_states`]).
    ///
    /// # Errors
    /// [`Error::Gpu`] for device trouble.
    pub fn steps_and_states(
        &self,
        ctx: &GpuContext,
        dt: f64,
        k: usize,
        states: bool,
    ) -> Result<(Vec<Vec<WorldRecord>>, Option<transfer::States>), Error> {
        let k = k.clamp(1, self.most_steps);
        let n = self.count();
        let stages = ctx.pipelines()?;
        let step_stages = stages.world_step(ctx)?;
        let rounds = self.rounds.get();
        let friction = match rounds {
            0 => None,
            _ => {
                let apgd = self
                    .friction
                    .is_some_and(|f| f.method == ProjectedMethod::Apgd);
                Some(stages.world_friction(ctx, apgd)?)
            }
        };
        let (rec_bytes, stride) = self.record_bytes();
        let out_at = (2 * self.first[n] * 4) as u64;
        let records = ctx.scoped("resident world steps", || {
            self.write_params(ctx, dt);
            let mut encoder = ctx.encoder("resident world steps");
            if k > 1 {
                self.save(&mut encoder);
            }
            for j in 0..k as u64 {
                let friction = friction.map(|s| (s, rounds));
                let mut ops = self.collide_ops(step_stages);
                ops.extend(self.solve_ops(step_stages, friction));
                self.record(&mut encoder, &ops);
                let at = j * stride;
                encoder.copy_buffer_to_buffer(&self.records, 0, &self.history, at, rec_bytes);
                let words = 16 * n as u64;
                let to = at + rec_bytes;
                encoder.copy_buffer_to_buffer(&self.words, out_at, &self.history, to, words);
            }
            let mut reads = vec![(&self.history, k as u64 * stride)];
            reads.extend(self.state_reads().into_iter().filter(|_| states));
            let read = reads.iter().map(|r| r.1).sum::<u64>();
            let records = ctx.submit_and_map(encoder, &reads, |v| {
                let records = (v[0].chunks(stride as usize))
                    .map(|b| {
                        let rec = scalars_from_bytes(&b[..rec_bytes as usize], self.precision);
                        let out: Vec<u32> = bytemuck::pod_collect_to_vec(&b[rec_bytes as usize..]);
                        records_of(&rec, &out)
                    })
                    .collect();
                (
                    records,
                    states.then(|| transfer::States::of(&v[1..], self.precision)),
                )
            });
            records.map(|r| (r, read))
        })??;
        let (out, read) = records;
        self.bytes_read.set(self.bytes_read.get() + read);
        Ok(out)
    }

    /// Bytes of one step's records: the [`REC`] scalars of every world, and
    /// with its 4 words.
    fn record_bytes(&self) -> (u64, u64) {
        let n = self.count() as u64;
        let rec = n * REC as u64 * self.precision.bytes();
        (rec, rec + 16 * n)
    }

    /// Most steps of one submission ([`Self::steps`]): 16, fewer where
    /// their records would pass 64 MiB.
    pub fn most_steps(&self) -> usize {
        self.most_steps
    }

    /// Bytes read back from the device since the batch was uploaded
    /// (records, states, warm-start memories).
    pub fn bytes_read(&self) -> u64 {
        self.bytes_read.get()
    }

    /// Records the copies of the state, the words, the records and the
    /// warm-start memory into `saved` (before a submission of several steps).
    fn save(&self, encoder: &mut wgpu::CommandEncoder) {
        let s = self
            .saved
            .as_ref()
            .expect("kept where several steps go in one submission");
        encoder.copy_buffer_to_buffer(&self.state, 0, &s.state, 0, self.state.size());
        encoder.copy_buffer_to_buffer(&self.words, 0, &s.words, 0, self.words.size());
        encoder.copy_buffer_to_buffer(&self.records, 0, &s.records, 0, self.records.size());
        if let Some((at, len)) = self.memory_range() {
            encoder.copy_buffer_to_buffer(&self.scratch, at, &s.memory, 0, len);
        }
    }

    /// Puts back the state, the words, the records and the warm-start
    /// memory as they were before the last submission of several steps
    /// ([`Self::steps`]).
    ///
    /// # Errors
    /// [`Error::Gpu`] for device trouble.
    pub fn restore(&self, ctx: &GpuContext) -> Result<(), Error> {
        let s = self
            .saved
            .as_ref()
            .expect("kept where several steps go in one submission");
        ctx.scoped("restoring resident worlds", || {
            let mut encoder = ctx.encoder("restore");
            encoder.copy_buffer_to_buffer(&s.state, 0, &self.state, 0, self.state.size());
            encoder.copy_buffer_to_buffer(&s.words, 0, &self.words, 0, self.words.size());
            encoder.copy_buffer_to_buffer(&s.records, 0, &self.records, 0, self.records.size());
            if let Some((at, len)) = self.memory_range() {
                encoder.copy_buffer_to_buffer(&s.memory, 0, &self.scratch, at, len);
            }
            ctx.queue.submit([encoder.finish()]);
        })
    }

    /// Where the warm-start reactions are in `scratch` (bytes), None where
    /// no world may have friction.
    fn memory_range(&self) -> Option<(u64, u64)> {
        let sb = self.precision.bytes();
        let len = (3 * self.count() * self.slots) as u64 * sb;
        (self.at.region != 0).then_some((self.at.memory_r as u64 * sb, len))
    }

    /// Worlds `world_solve_warm` left to `world_lemke` in the last step
    /// (a warm basis that did not hold, or none: without warm bases every
    /// world with contacts).
    ///
    /// # Errors
    /// [`Error::Gpu`] for device trouble.
    #[cfg(test)]
    pub(crate) fn deferred_worlds(&self, ctx: &GpuContext) -> Result<u32, Error> {
        let encoder = ctx.encoder("deferred worlds");
        let v = ctx.submit_and_read(encoder, &[(&self.lists, 16)])?;
        Ok(bytemuck::pod_read_unaligned(&v[0][12..16]))
    }

    /// Rounds of `world_friction` per step (0: no world may have friction).
    pub fn rounds(&self) -> u32 {
        self.rounds.get()
    }

    /// Sets the rounds of the next steps (1 to [`MAX_ROUNDS`]; nothing where
    /// no world may have friction).
    pub fn set_rounds(&self, rounds: u32) {
        if self.rounds.get() > 0 {
            self.rounds.set(rounds.clamp(1, MAX_ROUNDS));
        }
    }

    /// Bodies of world `k`.
    fn bodies_of(&self, k: usize) -> usize {
        self.first[k + 1] - self.first[k]
    }
}
