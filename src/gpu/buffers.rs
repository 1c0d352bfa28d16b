//! Device buffers: storage buffers, readback, and the splitting of a batch
//! into chunks whose buffers stay under the device's limits.

use wgpu::util::DeviceExt;

use super::batch::GpuSolveSettings;
use super::friction_rounds::write_scalars;
use super::kernel::TreeRoute;
use super::layout::{BasisResult, PackedIsland};
use super::{GpuContext, Precision};
use crate::cpu::batch::parallel_fill_by;
use crate::lcp::Lcp;
use crate::Error;

impl GpuContext {
    /// Whether the device maps storage buffers themselves (software
    /// adapters, see `GpuContext::new`): no staging buffer or copy on the
    /// way in ([`Self::kept_written`]) or out ([`Self::submit_and_map`]).
    fn maps_storage(&self) -> bool {
        self.device
            .features()
            .contains(wgpu::Features::MAPPABLE_PRIMARY_BUFFERS)
    }

    /// The usage of every storage buffer: bound by the shaders, copied to
    /// and from; where [`Self::maps_storage`], also mapped for reading.
    fn storage_usage(&self) -> wgpu::BufferUsages {
        let usage = wgpu::BufferUsages::STORAGE
            | wgpu::BufferUsages::COPY_SRC
            | wgpu::BufferUsages::COPY_DST;
        if self.maps_storage() {
            usage | wgpu::BufferUsages::MAP_READ
        } else {
            usage
        }
    }

    /// A storage buffer holding `bytes` (at least 16 bytes: empty bindings
    /// are invalid), readable by the shaders and copyable to a readback buffer.
    pub(crate) fn storage(&self, label: &str, bytes: &[u8]) -> wgpu::Buffer {
        let usage = self.storage_usage();
        if bytes.len() < 16 {
            let mut padded = bytes.to_vec();
            padded.resize(16, 0);
            return self
                .device
                .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some(label),
                    contents: &padded,
                    usage,
                });
        }
        self.device
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytes,
                usage,
            })
    }

    /// An uninitialised storage buffer of `size` bytes (rounded up to 16).
    pub(crate) fn storage_zeroed(&self, label: &str, size: u64) -> wgpu::Buffer {
        self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size: size.max(16).next_multiple_of(4),
            usage: self.storage_usage(),
            mapped_at_creation: false,
        })
    }

    /// Copies each (buffer, bytes) to a mappable buffer, submits `encoder`,
    /// waits, and returns the bytes.
    pub(crate) fn submit_and_read(
        &self,
        encoder: wgpu::CommandEncoder,
        reads: &[(&wgpu::Buffer, u64)],
    ) -> Result<Vec<Vec<u8>>, Error> {
        self.submit_and_map(encoder, reads, |views| {
            views.iter().map(|v| v.to_vec()).collect()
        })
    }

    /// [`Self::submit_and_read`] that hands `read` the mapped bytes
    /// themselves (each buffer's first `bytes`), so that a caller taking a
    /// part of them copies only that part. A buffer the device maps itself
    /// ([`Self::maps_storage`]) is read in place (no copy: the friction
    /// batches' vectors, 4.8 MB at 10,000 islands of k = 4); the others
    /// through a staging buffer. A buffer given twice is read once.
    pub(crate) fn submit_and_map<R>(
        &self,
        encoder: wgpu::CommandEncoder,
        reads: &[(&wgpu::Buffer, u64)],
        read: impl FnOnce(&[&[u8]]) -> R,
    ) -> Result<R, Error> {
        let submitted = self.submit_reads(encoder, reads);
        self.map_reads(submitted, read)
    }

    /// The first half of [`Self::submit_and_map`]: the copies recorded and
    /// `encoder` submitted, nothing waited for; the host may work while the
    /// device runs it, then read with [`Self::map_reads`].
    pub(crate) fn submit_reads(
        &self,
        mut encoder: wgpu::CommandEncoder,
        reads: &[(&wgpu::Buffer, u64)],
    ) -> Submitted {
        // (buffer mapped, bytes to read, whether it is a kept readback copy)
        let mut staging: Vec<(wgpu::Buffer, u64, bool)> = Vec::with_capacity(reads.len());
        for (at, &(src, size)) in reads.iter().enumerate() {
            let size4 = size.max(4).next_multiple_of(4);
            let twice = reads[..at].iter().any(|(b, _)| *b == src);
            if src.usage().contains(wgpu::BufferUsages::MAP_READ) && !twice {
                staging.push((src.clone(), size, false));
                continue;
            }
            // Readback: MAP_READ buffers cannot be storage on hardware, so
            // copy here, into a copy kept from an earlier call if there is one.
            let dst = self.kept_or_new(Role::Readback, size4);
            encoder.copy_buffer_to_buffer(src, 0, &dst, 0, size4);
            staging.push((dst, size, true));
        }
        let index = self.queue.submit([encoder.finish()]);
        Submitted { staging, index }
    }

    /// The second half of [`Self::submit_and_map`]: waits for that
    /// submission (only: a later one, the next chunk's, may still run) and
    /// hands `read` the bytes.
    pub(crate) fn map_reads<R>(
        &self,
        submitted: Submitted,
        read: impl FnOnce(&[&[u8]]) -> R,
    ) -> Result<R, Error> {
        let Submitted { staging, index } = submitted;
        let range = |size: u64| ..size.max(4).next_multiple_of(4);
        for (dst, size, _) in &staging {
            dst.slice(range(*size))
                .map_async(wgpu::MapMode::Read, |_| {});
        }
        self.device
            .poll(wgpu::PollType::Wait {
                submission_index: Some(index),
                timeout: None,
            })
            .map_err(|e| Error::Gpu(format!("waiting for the GPU: {e}")))?;
        let views = staging
            .iter()
            .map(|(dst, size, _)| {
                dst.slice(range(*size))
                    .get_mapped_range()
                    .map_err(|e| Error::Gpu(format!("reading back: {e}")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let bytes: Vec<&[u8]> = views
            .iter()
            .zip(&staging)
            .map(|(v, (_, size, _))| &v[..*size as usize])
            .collect();
        let out = read(&bytes);
        drop(views);
        for (dst, _, kept) in staging {
            dst.unmap();
            if kept {
                self.keep(Role::Readback, dst);
            }
        }
        Ok(out)
    }
}

/// A submission [`GpuContext::submit_reads`] made: the buffers to map once
/// it has run (each with the bytes to read and whether it is a kept
/// readback copy), and its index.
pub(crate) struct Submitted {
    staging: Vec<(wgpu::Buffer, u64, bool)>,
    index: wgpu::SubmissionIndex,
}

/// What a buffer kept between calls is for ([`GpuContext::take_kept`],
/// [`GpuContext::keep`]): a role has one usage, and a buffer kept for a
/// role is taken only for it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Role {
    /// The enumeration stage's island table and its M and q: host-written
    /// ([`GpuContext::kept_written`]), every byte the shaders read.
    Islands,
    Values,
    /// The enumeration stage's outputs: cleared by the encoder before use.
    Results,
    Z,
    Unfinished,
    Least,
    /// The enumeration stage's Params, one per dispatch at aligned offsets
    /// (`queue.write_buffer`).
    Params,
    /// Mappable copies of storage buffers for reading back (hardware).
    Readback,
    /// Mappable buffers the host writes and copies into storage buffers
    /// ([`GpuContext::kept_written`], hardware).
    Staging,
    /// The friction batches' W, q, μ and their vectors: host-written like
    /// `Values` (a new buffer costs a zeroing by wgpu and the kernel's first
    /// touch of every page: the W of 10,000 islands of k = 4, 12.8 MB, about
    /// 1 ms of 25 on lavapipe, measured).
    FrictionValues,
    FrictionVectors,
}

/// The buffers a context keeps between calls, by role, and the
/// tolerances uniform last asked for (kept while the tolerances are the
/// same: it is never rewritten).
#[derive(Default)]
pub(crate) struct Kept {
    /// (role, buffer, the last submission that used it where known).
    buffers: Vec<(Role, wgpu::Buffer, Option<wgpu::SubmissionIndex>)>,
    pub(crate) tolerances: Option<(super::pipelines::Tolerances, wgpu::Buffer)>,
}

/// Kept buffers of one role, at most (a call reads back two buffers at once).
const KEPT_PER_ROLE: usize = 2;

/// Bytes of the buffers kept by role, in all: 1 GiB (the enumeration
/// buffers of a chunk of a million islands of n = 4 in f64, about 400 MB,
/// twice); a larger buffer is let go.
const KEPT_BYTES: u64 = 1 << 30;

impl GpuContext {
    /// The usage of the buffers of `role`.
    fn role_usage(&self, role: Role) -> wgpu::BufferUsages {
        use wgpu::BufferUsages as U;
        match role {
            Role::Islands | Role::Values | Role::FrictionValues | Role::FrictionVectors
                if self.maps_storage() =>
            {
                self.storage_usage() | U::MAP_WRITE
            }
            Role::Params => U::UNIFORM | U::COPY_DST,
            Role::Readback => U::MAP_READ | U::COPY_DST,
            Role::Staging => U::MAP_WRITE | U::COPY_SRC,
            _ => self.storage_usage(),
        }
    }

    /// A new buffer of `role` for `size` bytes, a little larger (size
    /// rounded up to an eighth of its next power of two, within the
    /// binding limit) so that a slightly larger call takes it again.
    fn new_kept(&self, role: Role, size: u64, mapped: bool) -> wgpu::Buffer {
        let size = size.max(16).next_multiple_of(4);
        let step = (size.next_power_of_two() / 8).max(4);
        let l = self.limits();
        let cap = l.max_storage_buffer_binding_size.min(l.max_buffer_size);
        let grown = size.next_multiple_of(step).min(cap).max(size);
        self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(&format!("{role:?}").to_lowercase()),
            size: grown,
            usage: self.role_usage(role),
            mapped_at_creation: mapped,
        })
    }

    /// The smallest kept buffer of `role` with at least `size` bytes, taken
    /// out of the context (None when there is none): no other call sees it
    /// until [`Self::keep`] gives it back.
    pub(crate) fn take_kept(&self, role: Role, size: u64) -> Option<wgpu::Buffer> {
        self.take_kept_used(role, size).map(|(b, _)| b)
    }

    /// [`Self::take_kept`] with the last submission that used the buffer,
    /// where [`Self::keep_used`] was told.
    fn take_kept_used(
        &self,
        role: Role,
        size: u64,
    ) -> Option<(wgpu::Buffer, Option<wgpu::SubmissionIndex>)> {
        let mut kept = self.kept.lock().ok()?;
        let at = (0..kept.buffers.len())
            .filter(|&i| kept.buffers[i].0 == role && kept.buffers[i].1.size() >= size)
            .min_by_key(|&i| kept.buffers[i].1.size())?;
        let (_, buffer, used) = kept.buffers.swap_remove(at);
        Some((buffer, used))
    }

    /// [`Self::take_kept`], else a new buffer of `role` (not mapped).
    pub(crate) fn kept_or_new(&self, role: Role, size: u64) -> wgpu::Buffer {
        let size = size.max(16).next_multiple_of(4);
        self.take_kept(role, size)
            .unwrap_or_else(|| self.new_kept(role, size, false))
    }

    /// Gives `buffer` (of `role`, made by this module) back for a later
    /// call. The caller is done with it; a submission may still read it:
    /// whoever takes it writes it through the queue or the encoder (ordered
    /// after that submission) or maps it (wgpu waits for the submission).
    /// The newest [`KEPT_PER_ROLE`] of a role are kept, at most
    /// [`KEPT_BYTES`] in all.
    pub(crate) fn keep(&self, role: Role, buffer: wgpu::Buffer) {
        self.keep_used(role, buffer, None);
    }

    /// [`Self::keep`], with the last submission that uses the buffer (a
    /// mapping then waits for that one only: [`Self::kept_mapped`]).
    fn keep_used(&self, role: Role, buffer: wgpu::Buffer, used: Option<wgpu::SubmissionIndex>) {
        if buffer.size() > KEPT_BYTES / 2 || buffer.usage() != self.role_usage(role) {
            return;
        }
        let Ok(mut kept) = self.kept.lock() else {
            return;
        };
        let b = &mut kept.buffers;
        b.push((role, buffer, used));
        while b.iter().filter(|(r, _, _)| *r == role).count() > KEPT_PER_ROLE {
            let oldest = b.iter().position(|(r, _, _)| *r == role).unwrap_or(0);
            b.remove(oldest);
        }
        while b.iter().map(|(_, x, _)| x.size()).sum::<u64>() > KEPT_BYTES {
            b.remove(0);
        }
    }

    /// A buffer of `role` (at least `size` bytes, rounded up to 16 and to
    /// 4) whose first `size` bytes `fill` writes, every one of them (a kept
    /// buffer holds an earlier call's bytes). The view `fill` gets can be
    /// split ([`wgpu::WriteOnly::split_at`]) and its parts written by
    /// several threads. Where the device maps storage buffers, the buffer
    /// itself is mapped and written; else a mappable staging buffer
    /// ([`Role::Staging`], kept between calls like the others) is, and
    /// copied into the buffer by a submission of its own (ordered before
    /// the caller's next one). Why not `queue.write_buffer`: it allocates a
    /// staging buffer per call, and its view is filled from one thread.
    /// Give the buffer back with [`Self::keep`].
    pub(crate) fn kept_written(
        &self,
        role: Role,
        size: u64,
        fill: impl FnOnce(wgpu::WriteOnly<'_, [u8]>),
    ) -> Result<wgpu::Buffer, Error> {
        let size = size.max(16).next_multiple_of(4);
        if self.maps_storage() {
            return self.kept_mapped(role, size, fill);
        }
        let staging = self.kept_mapped(Role::Staging, size, fill)?;
        let buffer = self.kept_or_new(role, size);
        let mut encoder = self.encoder("upload");
        encoder.copy_buffer_to_buffer(&staging, 0, &buffer, 0, size);
        let copy = self.queue.submit([encoder.finish()]);
        // The copy may still read it: whoever takes it next maps it, and
        // wgpu maps it only once the copy is done (waiting for the copy
        // alone, not for a chunk's kernels submitted after it).
        self.keep_used(Role::Staging, staging, Some(copy));
        Ok(buffer)
    }

    /// A buffer of `role` (mappable for writing) with its first `size`
    /// bytes written by `fill`: a kept one mapped again (wgpu waits for any
    /// submission using it), else a new one mapped at its creation.
    fn kept_mapped(
        &self,
        role: Role,
        size: u64,
        fill: impl FnOnce(wgpu::WriteOnly<'_, [u8]>),
    ) -> Result<wgpu::Buffer, Error> {
        let what = format!("writing {role:?}");
        let buffer = match self.take_kept_used(role, size) {
            Some((buffer, used)) => {
                self.map_for_writing(&buffer, size, used)
                    .map_err(|e| Error::Gpu(format!("{what}: {e}")))?;
                buffer
            }
            None => self.new_kept(role, size, true),
        };
        fill_mapped(buffer, size, &what, |view| fill(view.slice(..)))
    }
}

impl GpuContext {
    /// Maps `buffer`'s first `size` bytes for writing. An idle buffer (a
    /// chunk's, once read back) maps at one poll that waits for nothing,
    /// so the next chunk is packed while the last one still runs; else the
    /// wait is for `used`, the last submission using it, where known, and
    /// for every submission where not.
    fn map_for_writing(
        &self,
        buffer: &wgpu::Buffer,
        size: u64,
        used: Option<wgpu::SubmissionIndex>,
    ) -> Result<(), wgpu::PollError> {
        let mapped = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
        let flag = mapped.clone();
        buffer
            .slice(..size)
            .map_async(wgpu::MapMode::Write, move |r| {
                flag.store(r.is_ok(), std::sync::atomic::Ordering::Release)
            });
        self.device.poll(wgpu::PollType::Poll)?;
        if !mapped.load(std::sync::atomic::Ordering::Acquire) {
            self.device.poll(wgpu::PollType::Wait {
                submission_index: used,
                timeout: None,
            })?;
        }
        Ok(())
    }
}

/// `fill` run on the first `size` bytes of `buffer`, mapped for writing
/// (at creation or by `map_async`), then the buffer unmapped and returned.
fn fill_mapped(
    buffer: wgpu::Buffer,
    size: u64,
    label: &str,
    fill: impl FnOnce(&mut wgpu::BufferViewMut),
) -> Result<wgpu::Buffer, Error> {
    {
        let mut view = buffer
            .slice(..size)
            .get_mapped_range_mut()
            .map_err(|e| Error::Gpu(format!("filling {label}: {e}")))?;
        fill(&mut view);
    }
    buffer.unmap();
    Ok(buffer)
}

/// A part of a mapped view ([`wgpu::WriteOnly::split_at`]), to be written
/// by another thread.
struct ViewPart<'a>(wgpu::WriteOnly<'a, [u8]>);

// SAFETY: a `WriteOnly<'a, [u8]>` is exclusive write access to its bytes
// for 'a, as `&'a mut [u8]` is, which is Send. wgpu implements Send for
// `WriteOnly<T>` where `T: Send`, a bound that implies `T: Sized` (the impl
// has no `?Sized`), so slices miss it; nothing in the type is tied to a
// thread. The parts `split_at` makes do not overlap, and the mapped view
// they borrow from outlives them ('a): the buffer is unmapped only after.
unsafe impl Send for ViewPart<'_> {}

/// Largest bytes per binding and workgroups per dispatch for this batch.
pub(crate) fn limits_for(ctx: &GpuContext, settings: &GpuSolveSettings) -> (u64, u32) {
    let l = ctx.limits();
    let bind = l.max_storage_buffer_binding_size.min(l.max_buffer_size);
    let bind = settings.max_binding_bytes.map_or(bind, |b| b.min(bind));
    let groups = l.max_compute_workgroups_per_dimension;
    let groups = settings.max_workgroups.map_or(groups, |g| g.min(groups));
    (bind.max(1024), groups.max(1))
}

/// A chunk of an LCP batch, planned for the enumeration stage.
pub(crate) struct PackedChunk {
    /// The caller's indices of the chunk's islands, sorted by n, then by
    /// `tree`.
    pub(crate) order: Vec<usize>,
    pub(crate) table: Vec<PackedIsland>,
    /// Per table entry: how it goes through the tree kernel.
    pub(crate) tree: Vec<TreeRoute>,
    /// Scalars of M (row-major) then q of every island, in all.
    values: usize,
}

/// Islands packed by one thread at a time.
const PACK_BLOCK: usize = 1024;

impl PackedChunk {
    /// (islands, values) storage buffers ([`Role::Islands`],
    /// [`Role::Values`]: kept from an earlier call where the context has
    /// them; give them back with [`GpuContext::keep`]): `values` holds each
    /// island's M (row-major) and q in the shader's precision, packed by up
    /// to `threads` threads.
    pub(crate) fn upload(
        &self,
        ctx: &GpuContext,
        lcps: &[&Lcp],
        precision: Precision,
        threads: usize,
    ) -> Result<(wgpu::Buffer, wgpu::Buffer), Error> {
        // islands: the chunk's island table, sorted by n.
        let table: &[u8] = bytemuck::cast_slice(&self.table);
        let islands = ctx.kept_written(Role::Islands, table.len() as u64, |mut view| {
            view.slice(..table.len()).copy_from_slice(table);
        })?;
        // values: every island's M (row-major) and q, in the shader's
        // precision, packed by every thread straight into the mapped view,
        // cut at island boundaries, PACK_BLOCK islands a piece.
        let sb = precision.bytes() as usize;
        let values = ctx.kept_written(Role::Values, (self.values * sb) as u64, |view| {
            let mut rest = view;
            let mut pieces = Vec::with_capacity(self.order.len().div_ceil(PACK_BLOCK));
            for block in self.order.chunks(PACK_BLOCK) {
                let len: usize = block.iter().map(|&i| lcps[i].n() * (lcps[i].n() + 1)).sum();
                let (piece, tail) = rest.split_at(len * sb);
                pieces.push((block, ViewPart(piece)));
                rest = tail;
            }
            parallel_fill_by(&mut pieces, threads, 1, |_, (block, ViewPart(piece))| {
                let mut at = 0;
                for &i in block.iter() {
                    let (m, q) = (&lcps[i].m, &lcps[i].q);
                    write_scalars(piece, at, m, precision);
                    write_scalars(piece, at + m.len(), q, precision);
                    at += m.len() + q.len();
                }
            });
        })?;
        Ok((islands, values))
    }
}

/// Sorts the islands by n (one dispatch per size: no island waits on a
/// larger one), then by `tree` (the tree kernel's islands together), and
/// plans chunks whose buffers stay under `max_bytes`; each island's
/// `hints` word (empty: none) goes into its table entry, for the settle
/// kernel.
pub(crate) fn pack_chunks(
    lcps: &[&Lcp],
    (tree, hints): (&[TreeRoute], &[u32]),
    max_bytes: u64,
    sb: u64,
) -> Vec<PackedChunk> {
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
        let (mut data, mut zoff) = (0u32, 0u32);
        for &i in &order[at..end] {
            let n = lcps[i].n() as u32;
            table.push(PackedIsland {
                n,
                data,
                z: zoff,
                contacts: hints.get(i).copied().unwrap_or(0),
            });
            data += n * n + n;
            zoff += n;
        }
        chunks.push(PackedChunk {
            order: order[at..end].to_vec(),
            tree: order[at..end].iter().map(|&i| route(i)).collect(),
            table,
            values: values as usize,
        });
        at = end;
    }
    chunks
}
