//! Device buffers: storage buffers, readback, and the splitting of a batch
//! into chunks whose buffers stay under the device's limits.

use wgpu::util::DeviceExt;

use super::batch::GpuSolveSettings;
use super::kernel::TreeRoute;
use super::layout::{BasisResult, PackedIsland};
use super::{GpuContext, Precision};
use crate::cpu::batch::parallel_fill_by;
use crate::lcp::Lcp;
use crate::Error;

impl GpuContext {
    /// Whether the device maps storage buffers themselves (software
    /// adapters, see `GpuContext::new`): no staging buffer or copy on the
    /// way in ([`Self::storage_filled`]) or out ([`Self::submit_and_map`]).
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

    /// A storage buffer of `size` bytes (rounded up to 16 and to 4) that
    /// `fill` writes in place while it is mapped at creation; what `fill`
    /// leaves alone stays 0. One copy fewer than [`Self::storage`] from a
    /// byte vector, and no vector: for the large frictional batches the
    /// copies cost as much as the iterations on lavapipe (measured).
    pub(crate) fn storage_filled(
        &self,
        label: &str,
        size: u64,
        fill: impl FnOnce(&mut wgpu::BufferViewMut),
    ) -> Result<wgpu::Buffer, Error> {
        let mut usage = self.storage_usage();
        // Where the device allows it, the buffer itself is mapped: no
        // staging buffer.
        if self.maps_storage() {
            usage |= wgpu::BufferUsages::MAP_WRITE;
        }
        let buffer = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size: size.max(16).next_multiple_of(4),
            usage,
            mapped_at_creation: true,
        });
        let all = buffer.size();
        fill_mapped(buffer, all, label, fill)
    }

    /// [`Self::storage_filled`] where `fill` writes every byte the shaders
    /// will read: the others are left as they are, 0 in a new buffer, an
    /// earlier batch's bytes in a kept one. Where the device maps storage
    /// buffers ([`Self::maps_storage`]), a buffer given back by
    /// [`Self::keep_spare`] of at least `size` bytes (and at most twice) is
    /// mapped and written again: a new buffer costs a zeroing by wgpu and
    /// the kernel's first touch of every page (the friction batches' W,
    /// 12.8 MB at 10,000 islands of k = 4: about 1 ms of 25 on lavapipe,
    /// measured).
    pub(crate) fn storage_written(
        &self,
        label: &str,
        size: u64,
        fill: impl FnOnce(&mut wgpu::BufferViewMut),
    ) -> Result<wgpu::Buffer, Error> {
        let size = size.max(16).next_multiple_of(4);
        let kept = self.maps_storage().then(|| self.take_spare(size)).flatten();
        let Some(buffer) = kept else {
            return self.storage_filled(label, size, fill);
        };
        buffer.slice(..size).map_async(wgpu::MapMode::Write, |_| {});
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| Error::Gpu(format!("mapping {label}: {e}")))?;
        fill_mapped(buffer, size, label, fill)
    }

    /// A kept buffer of `size` to twice `size` bytes, the smallest (None
    /// when there is none).
    fn take_spare(&self, size: u64) -> Option<wgpu::Buffer> {
        let mut spare = self.spare.lock().ok()?;
        let fits = |b: &wgpu::Buffer| b.size() >= size && b.size() <= 2 * size;
        let at = (0..spare.len())
            .filter(|&i| fits(&spare[i]))
            .min_by_key(|&i| spare[i].size())?;
        Some(spare.swap_remove(at))
    }

    /// Keeps `buffer` (made by [`Self::storage_written`]; the caller is
    /// done with it, and wgpu waits for any submission still using it
    /// before it is mapped again) for a later batch: the newest
    /// [`SPARE_BUFFERS`], at most [`SPARE_BYTES`] in all (a larger buffer
    /// is let go: host memory a context would hold after one huge batch).
    pub(crate) fn keep_spare(&self, buffer: wgpu::Buffer) {
        if !self.maps_storage() || buffer.size() > SPARE_BYTES {
            return;
        }
        if let Ok(mut spare) = self.spare.lock() {
            spare.push(buffer);
            while spare.len() > SPARE_BUFFERS
                || spare.iter().map(wgpu::Buffer::size).sum::<u64>() > SPARE_BYTES
            {
                spare.remove(0);
            }
        }
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
        mut encoder: wgpu::CommandEncoder,
        reads: &[(&wgpu::Buffer, u64)],
        read: impl FnOnce(&[&[u8]]) -> R,
    ) -> Result<R, Error> {
        let mut staging: Vec<(wgpu::Buffer, u64)> = Vec::with_capacity(reads.len());
        for (at, &(src, size)) in reads.iter().enumerate() {
            let size4 = size.max(4).next_multiple_of(4);
            let twice = reads[..at].iter().any(|(b, _)| *b == src);
            if src.usage().contains(wgpu::BufferUsages::MAP_READ) && !twice {
                staging.push((src.clone(), size));
                continue;
            }
            // Readback: MAP_READ buffers cannot be storage on hardware, so
            // copy here.
            let dst = self.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("readback"),
                size: size4,
                usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            encoder.copy_buffer_to_buffer(src, 0, &dst, 0, size4);
            staging.push((dst, size));
        }
        self.queue.submit([encoder.finish()]);
        for (dst, _) in &staging {
            dst.slice(..).map_async(wgpu::MapMode::Read, |_| {});
        }
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| Error::Gpu(format!("waiting for the GPU: {e}")))?;
        let views = staging
            .iter()
            .map(|(dst, _)| {
                dst.slice(..)
                    .get_mapped_range()
                    .map_err(|e| Error::Gpu(format!("reading back: {e}")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let bytes: Vec<&[u8]> = views
            .iter()
            .zip(&staging)
            .map(|(v, (_, size))| &v[..*size as usize])
            .collect();
        let out = read(&bytes);
        drop(views);
        for (dst, _) in &staging {
            dst.unmap();
        }
        Ok(out)
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

/// Host-written buffers a context keeps between batches (two per
/// friction chunk: its W, q, μ and its vectors).
const SPARE_BUFFERS: usize = 4;

/// Bytes of the buffers a context keeps between batches, in all: 512 MiB
/// (the W of 400,000 islands of k = 4 in f64).
const SPARE_BYTES: u64 = 512 << 20;

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
    /// (islands, values) storage buffers: `values` holds each island's M
    /// (row-major) and q in the shader's precision, packed by up to
    /// `threads` threads and copied once into the mapped buffer.
    pub(crate) fn upload(
        &self,
        ctx: &GpuContext,
        lcps: &[&Lcp],
        precision: Precision,
        threads: usize,
    ) -> Result<(wgpu::Buffer, wgpu::Buffer), Error> {
        // islands: the chunk's island table, sorted by n.
        let islands = ctx.storage("islands", bytemuck::cast_slice(&self.table));
        // values: every island's M (row-major) and q, in the shader's precision.
        let sb = precision.bytes() as usize;
        let mut bytes = vec![0u8; self.values * sb];
        // The bytes cut at island boundaries, PACK_BLOCK islands a piece.
        let mut rest = bytes.as_mut_slice();
        let mut pieces = Vec::with_capacity(self.order.len().div_ceil(PACK_BLOCK));
        for block in self.order.chunks(PACK_BLOCK) {
            let len: usize = block.iter().map(|&i| lcps[i].n() * (lcps[i].n() + 1)).sum();
            let (piece, tail) = std::mem::take(&mut rest).split_at_mut(len * sb);
            pieces.push((block, piece));
            rest = tail;
        }
        parallel_fill_by(&mut pieces, threads, 1, |_, (block, piece)| {
            let scalars = block
                .iter()
                .flat_map(|&i| lcps[i].m.iter().chain(&lcps[i].q));
            match precision {
                Precision::F64 => {
                    for (b, &v) in piece.chunks_exact_mut(8).zip(scalars) {
                        b.copy_from_slice(&v.to_le_bytes());
                    }
                }
                _ => {
                    for (b, &v) in piece.chunks_exact_mut(4).zip(scalars) {
                        b.copy_from_slice(&(v as f32).to_le_bytes());
                    }
                }
            }
        });
        let values = ctx.storage_filled("values", bytes.len() as u64, |view| {
            view.slice(..bytes.len()).copy_from_slice(&bytes);
        })?;
        Ok((islands, values))
    }
}

/// Sorts the islands by n (one dispatch per size: no island waits on a
/// larger one), then by `tree` (the tree kernel's islands together), and
/// plans chunks whose buffers stay under `max_bytes`.
pub(crate) fn pack_chunks(
    lcps: &[&Lcp],
    tree: &[TreeRoute],
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
                contacts: 0,
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
