//! What moves between the host and a resident batch after its upload
//! (besides the per-step records of [`ResidentWorlds::steps`]): the
//! states, all or some worlds' ([`ResidentWorlds::read_states`],
//! [`ResidentWorlds::read_worlds`]; all of them also in the same
//! submission and map as the records of a call's last steps,
//! [`ResidentWorlds::steps_and_states`], unpacked by
//! [`ResidentWorlds::unpack_states`]), a world stepped on the CPU written
//! back ([`ResidentWorlds::write_world`]), a world's warm-start memory
//! ([`ResidentWorlds::read_memory`], [`ResidentWorlds::write_memory`]).
//! Every byte read is counted in [`ResidentWorlds::bytes_read`].

use super::layout::{pack_body_state, unpack_body_state, BS};
use super::ResidentWorlds;
use crate::gpu::layout::{scalars_from_bytes, scalars_to_bytes};
use crate::gpu::GpuContext;
use crate::world::World;
use crate::Error;

/// One entry of a world's warm-start memory on the device: the contact's
/// id as the shader packs it ([`layout::device_key`]) and its reaction
/// (r_n, r_t₁, r_t₂).
pub type MemoryEntry = (u32, [f64; 3]);

/// States as read back: per body [`BS`] scalars and 2 sleep words, the
/// worlds' bodies one after another.
pub struct States {
    state: Vec<f64>,
    sleep: Vec<u32>,
}

impl States {
    /// From the mapped bytes of the state's and the sleep words' reads
    /// ([`ResidentWorlds::state_reads`]).
    pub(super) fn of(bytes: &[&[u8]], precision: crate::gpu::Precision) -> Self {
        States {
            state: scalars_from_bytes(bytes[0], precision),
            sleep: bytemuck::pod_collect_to_vec(bytes[1]),
        }
    }

    /// Copies the bodies from `first` on into `w`'s.
    fn unpack(&self, first: usize, w: &mut World) {
        for (j, b) in w.bodies.iter_mut().enumerate() {
            let at = first + j;
            unpack_body_state(
                b,
                &self.state[at * BS..(at + 1) * BS],
                &self.sleep[2 * at..2 * at + 2],
            );
        }
    }
}

impl ResidentWorlds {
    /// The states held, copied into `worlds` (the batch uploaded, in
    /// order): bit for bit what was uploaded when no step ran.
    ///
    /// # Errors
    /// [`Error::Invalid`] where `worlds` is not the batch's shape;
    /// [`Error::Gpu`] for device trouble.
    #[cfg_attr(
        not(test),
        allow(
            dead_code,
            reason = "the solver reads every state with a call's last step (steps_and_states); the tests read them alone"
        )
    )]
    pub fn read_states(&self, ctx: &GpuContext, worlds: &mut [World]) -> Result<(), Error> {
        self.check_shape(worlds)?;
        let encoder = ctx.encoder("read states");
        let states = self.read("reading resident states", ctx, encoder, self.state_reads())?;
        self.unpack_states(&states, worlds)
    }

    /// `states` (every world's, read with [`Self::steps_and_states`])
    /// copied into `worlds` (the batch uploaded, in order).
    ///
    /// # Errors
    /// [`Error::Invalid`] where `worlds` is not the batch's shape.
    pub fn unpack_states(&self, states: &States, worlds: &mut [World]) -> Result<(), Error> {
        self.check_shape(worlds)?;
        for (k, w) in worlds.iter_mut().enumerate() {
            states.unpack(self.first[k], w);
        }
        Ok(())
    }

    /// World `k`'s state in `states` (every world's) copied into `w`
    /// (world `k` of the batch).
    pub fn unpack_world(&self, states: &States, k: usize, w: &mut World) {
        states.unpack(self.first[k], w);
    }

    /// An error where `worlds` is not the batch's shape.
    fn check_shape(&self, worlds: &[World]) -> Result<(), Error> {
        let shape_differs = worlds.len() != self.count()
            || (worlds.iter().enumerate()).any(|(k, w)| w.bodies.len() != self.bodies_of(k));
        match shape_differs {
            true => Err(Error::invalid(
                "read_states",
                "worlds",
                "not the batch the device holds".to_string(),
            )),
            false => Ok(()),
        }
    }

    /// The reads of every world's state: the state's bytes, the sleep
    /// words' bytes (each from its buffer's first byte).
    pub(super) fn state_reads(&self) -> [(&wgpu::Buffer, u64); 2] {
        let bodies = self.first[self.count()] as u64;
        let sb = self.precision.bytes();
        [
            (&self.state, bodies * BS as u64 * sb),
            (&self.words, 8 * bodies),
        ]
    }

    /// The states of worlds `ks` (in the batch) copied into `worlds` (as
    /// many, each of its world's bodies), in one submission of their ranges.
    ///
    /// # Errors
    /// [`Error::Gpu`] for device trouble.
    pub fn read_worlds(
        &self,
        ctx: &GpuContext,
        ks: &[usize],
        worlds: &mut [World],
    ) -> Result<(), Error> {
        let sb = self.precision.bytes();
        let bodies: usize = ks.iter().map(|&k| self.bodies_of(k)).sum();
        let (state_len, words_len) = (bodies as u64 * BS as u64 * sb, 8 * bodies as u64);
        // Copies of the worlds' ranges, one after another: reads start at
        // a buffer's first byte.
        let (state, words) = ctx.scoped("reading resident worlds", || {
            let state = ctx.storage_zeroed("worlds' states", state_len);
            let words = ctx.storage_zeroed("worlds' sleep words", words_len);
            (state, words)
        })?;
        let mut encoder = ctx.encoder("read worlds");
        let (mut s_at, mut w_at) = (0, 0);
        for &k in ks {
            let (first, nb) = (self.first[k] as u64, self.bodies_of(k) as u64);
            let len = nb * BS as u64 * sb;
            encoder.copy_buffer_to_buffer(&self.state, first * BS as u64 * sb, &state, s_at, len);
            encoder.copy_buffer_to_buffer(&self.words, first * 8, &words, w_at, nb * 8);
            (s_at, w_at) = (s_at + len, w_at + nb * 8);
        }
        let states = self.read(
            "reading resident worlds",
            ctx,
            encoder,
            [(&state, state_len), (&words, words_len)],
        )?;
        let mut first = 0;
        for w in worlds.iter_mut() {
            states.unpack(first, w);
            first += w.bodies.len();
        }
        Ok(())
    }

    /// The states (`reads`: the state's bytes, the sleep words' bytes) that
    /// `encoder` and the copies to map give, counted in [`Self::bytes_read`].
    fn read(
        &self,
        what: &str,
        ctx: &GpuContext,
        encoder: wgpu::CommandEncoder,
        reads: [(&wgpu::Buffer, u64); 2],
    ) -> Result<States, Error> {
        let states = ctx.scoped(what, || {
            ctx.submit_and_map(encoder, &reads, |v| States::of(v, self.precision))
        })??;
        self.bytes_read
            .set(self.bytes_read.get() + reads[0].1 + reads[1].1);
        Ok(states)
    }

    /// World `k`'s warm-start memory on the device: per entry the id as
    /// the shader packs it ([`layout::device_key`]) and the reaction
    /// (empty where no world may have friction).
    ///
    /// # Errors
    /// [`Error::Gpu`] for device trouble.
    pub fn read_memory(&self, ctx: &GpuContext, k: usize) -> Result<Vec<MemoryEntry>, Error> {
        if self.at.region == 0 {
            return Ok(Vec::new());
        }
        let sb = self.precision.bytes();
        let ids_at = ((self.at.memory + k * (self.slots + 1)) * 4) as u64;
        let ids_len = ((self.slots + 1) * 4) as u64;
        let r_at = (self.at.memory_r + 3 * k * self.slots) as u64 * sb;
        let r_len = (3 * self.slots) as u64 * sb;
        ctx.scoped("reading a warm-start memory", || {
            // Copies of the two ranges: reads start at a buffer's first byte.
            let ids = ctx.storage_zeroed("memory ids", ids_len);
            let rs = ctx.storage_zeroed("memory reactions", r_len);
            let mut encoder = ctx.encoder("read memory");
            encoder.copy_buffer_to_buffer(&self.words, ids_at, &ids, 0, ids_len);
            encoder.copy_buffer_to_buffer(&self.scratch, r_at, &rs, 0, r_len);
            self.bytes_read.set(self.bytes_read.get() + ids_len + r_len);
            ctx.submit_and_map(encoder, &[(&ids, ids_len), (&rs, r_len)], |v| {
                let words: Vec<u32> = bytemuck::pod_collect_to_vec(v[0]);
                let r = scalars_from_bytes(v[1], self.precision);
                let n = (words[0] as usize).min(self.slots);
                (0..n)
                    .map(|e| (words[1 + e], [r[3 * e], r[3 * e + 1], r[3 * e + 2]]))
                    .collect()
            })
        })?
    }

    /// Replaces world `k`'s warm-start memory on the device with `entries`
    /// (a step on the CPU recorded them; past the world's contact slots
    /// they are cut: such a world overflows its slots and is stepped on the
    /// CPU). Nothing where no world may have friction.
    ///
    /// # Errors
    /// [`Error::Gpu`] for device trouble.
    pub fn write_memory(
        &self,
        ctx: &GpuContext,
        k: usize,
        entries: &[MemoryEntry],
    ) -> Result<(), Error> {
        if self.at.region == 0 {
            return Ok(());
        }
        let kept = &entries[..entries.len().min(self.slots)];
        let mut ids = vec![kept.len() as u32];
        ids.extend(kept.iter().map(|e| e.0));
        let r: Vec<f64> = kept.iter().flat_map(|e| e.1).collect();
        let ids_at = ((self.at.memory + k * (self.slots + 1)) * 4) as u64;
        let r_at = (self.at.memory_r + 3 * k * self.slots) as u64 * self.precision.bytes();
        ctx.scoped("writing a warm-start memory", || {
            ctx.queue
                .write_buffer(&self.words, ids_at, bytemuck::cast_slice(&ids));
            if !r.is_empty() {
                let bytes = scalars_to_bytes(&r, self.precision);
                ctx.queue.write_buffer(&self.scratch, r_at, &bytes);
            }
        })
    }

    /// Replaces world `k`'s state on the device with `w`'s (the same
    /// bodies; stepped on the CPU).
    ///
    /// # Errors
    /// [`Error::Gpu`] for device trouble.
    pub fn write_world(&self, ctx: &GpuContext, k: usize, w: &World) -> Result<(), Error> {
        let (mut state, mut sleep) = (Vec::new(), Vec::new());
        for b in &w.bodies {
            pack_body_state(b, &mut state, &mut sleep);
        }
        let at = self.first[k] as u64;
        let sb = self.precision.bytes();
        ctx.scoped("writing a resident world", || {
            let q = &ctx.queue;
            q.write_buffer(
                &self.state,
                at * BS as u64 * sb,
                &scalars_to_bytes(&state, self.precision),
            );
            q.write_buffer(&self.words, at * 8, bytemuck::cast_slice(&sleep));
        })
    }
}

#[cfg(test)]
impl ResidentWorlds {
    /// The records buffer as it is now: per world [`super::layout::REC`]
    /// scalars (the last two the solve's warm basis), not counted.
    pub fn records_now(&self, ctx: &GpuContext) -> Result<Vec<f64>, Error> {
        let len = self.records.size();
        ctx.scoped("reading the records", || {
            let encoder = ctx.encoder("read records");
            ctx.submit_and_map(encoder, &[(&self.records, len)], |v| {
                scalars_from_bytes(v[0], self.precision)
            })
        })?
    }
}
