//! Every basis of every island on the GPU (`all_solutions`): the screen
//! `shaders/enumeration_all.wgsl` solves all 2ⁿ bases of each island in
//! parallel, one invocation per (island, basis), and flags the bases that
//! may be solutions; the CPU then re-solves the flagged ones in f64 and
//! decides the solution set exactly as its enumeration does
//! ([`crate::cpu::enumeration::enumerate_screened`]).
//!
//! Why this is exact: a basis the CPU counts as a solution has an
//! infeasibility ≤ the relaxed tolerance in f64. In f64 the screen runs the
//! twin's arithmetic and tolerances operation for operation, so it flags
//! exactly those bases, and its "singular" is the CPU's. In f32 the screen
//! flags every basis within the f32 screen tolerance (1e-3, above f32's
//! rounding on islands with a condition number up to about 1e4) and every
//! basis f32 finds singular; all of them are re-solved in f64.

use std::time::Instant;

use super::batch::GpuSolveSettings;
use super::buffers::limits_for;
use super::dispatch::Span;
use super::layout::{scalars_to_bytes, PackedIsland};
use super::pipelines::{Tolerances, WORKGROUP};
use super::{GpuContext, Precision, MAX_GPU_N};
use crate::lcp::Lcp;
use crate::Error;

/// Verdict bit: the basis may be a solution (re-solve it in f64).
const CANDIDATE: u32 = 1;
/// Verdict bit: the elimination met a pivot below the pivot tolerance.
const SINGULAR_BASIS: u32 = 2;
/// Bases per verdict word (two bits each).
const BASES_PER_WORD: usize = 16;

/// What the screen left of one island.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Screened {
    /// Bases to re-solve in f64: flagged candidates, and in f32 the bases
    /// f32 found singular too.
    pub candidates: Vec<u32>,
    /// Bases found singular by the twin's own arithmetic (f64), not re-solved.
    pub trusted_singular: u64,
}

/// Work figures of one screen.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct ScreenFigures {
    pub chunks: usize,
    pub dispatches: usize,
    /// Seconds of GPU work (upload, dispatch, readback).
    pub seconds: f64,
}

/// Screens every basis of every island (each n ≤ [`MAX_GPU_N`]), in the
/// caller's order. Device trouble is [`Error::Gpu`].
pub(crate) fn screen_all_bases(
    ctx: &GpuContext,
    lcps: &[&Lcp],
    settings: &GpuSolveSettings,
) -> Result<(Vec<Screened>, ScreenFigures), Error> {
    if let Some((i, l)) = lcps.iter().enumerate().find(|(_, l)| l.n() > MAX_GPU_N) {
        return Err(Error::Unsupported(format!(
            "problem {i}: the GPU screens islands of n ≤ {MAX_GPU_N} (n = {})",
            l.n()
        )));
    }
    let start = Instant::now();
    let (max_bytes, max_groups) = limits_for(ctx, settings);
    let mut out = vec![Screened::default(); lcps.len()];
    let mut figures = ScreenFigures::default();
    // One size at a time: a dispatch maps invocations to (island, basis) by n.
    for n in 1..=MAX_GPU_N {
        let of_size: Vec<usize> = (0..lcps.len()).filter(|&i| lcps[i].n() == n).collect();
        for chunk in size_chunks(&of_size, n, ctx.precision(), max_bytes) {
            let words = screen_chunk(ctx, lcps, chunk, n, settings, max_groups, &mut figures)?;
            for (k, &i) in chunk.iter().enumerate() {
                out[i] = decode(&words[k * words_per_island(n)..], n, ctx.precision());
            }
        }
    }
    figures.seconds = start.elapsed().as_secs_f64();
    Ok((out, figures))
}

/// Verdict words of one island of n contacts.
fn words_per_island(n: usize) -> usize {
    (1usize << n).div_ceil(BASES_PER_WORD)
}

/// Splits islands of one size into chunks whose buffers (values, verdicts,
/// island table) stay under `max_bytes` per binding and whose invocations
/// (islands × 2ⁿ) fit a u32.
fn size_chunks(
    islands: &[usize],
    n: usize,
    precision: Precision,
    max_bytes: u64,
) -> std::slice::Chunks<'_, usize> {
    let scalar = if precision == Precision::F64 { 8 } else { 4 };
    let per_island = [
        ((n * n + n) * scalar) as u64,
        (words_per_island(n) * 4) as u64,
        std::mem::size_of::<PackedIsland>() as u64,
    ];
    let by_bytes = per_island.iter().map(|&b| max_bytes / b).min().unwrap_or(1);
    let by_invocations = u32::MAX as u64 >> n;
    let per_chunk = by_bytes.min(by_invocations).max(1) as usize;
    islands.chunks(per_chunk)
}

/// Uploads one chunk of islands of size n, dispatches the screen over all
/// their bases, and reads the verdict words back.
fn screen_chunk(
    ctx: &GpuContext,
    lcps: &[&Lcp],
    chunk: &[usize],
    n: usize,
    settings: &GpuSolveSettings,
    max_groups: u32,
    figures: &mut ScreenFigures,
) -> Result<Vec<u32>, Error> {
    let stride = n * n + n;
    let mut values = Vec::with_capacity(chunk.len() * stride);
    let mut table = Vec::with_capacity(chunk.len());
    for (k, &i) in chunk.iter().enumerate() {
        table.push(PackedIsland {
            n: n as u32,
            data: (k * stride) as u32,
            z: (k * words_per_island(n)) as u32,
            contacts: 0,
        });
        values.extend_from_slice(&lcps[i].m);
        values.extend_from_slice(&lcps[i].q);
    }
    let word_count = chunk.len() * words_per_island(n);
    ctx.scoped("screening every basis", || -> Result<Vec<u32>, Error> {
        let pipelines = ctx.pipelines()?;
        let stage = pipelines.all_bases(ctx)?;
        // The island table: size, where M and q start, where the verdicts start.
        let islands = ctx.storage("islands", bytemuck::cast_slice(&table));
        // M (row-major) then q of every island, in the shader's precision.
        let values = ctx.storage("values", &scalars_to_bytes(&values, ctx.precision()));
        // The run-time tolerances (pivot, relaxed, screen).
        let tolerances = Tolerances::new(ctx.precision(), settings).upload(ctx);
        // Two verdict bits per basis, zeroed by wgpu, set by atomicOr.
        let verdicts = ctx.storage_zeroed("verdicts", word_count as u64 * 4);
        let span = Span {
            first: 0,
            count: (chunk.len() << n) as u32,
            per_group: WORKGROUP,
            budget: 0,
            flags: n as u32,
        };
        let ranges = ctx.ranges(span, max_groups, &|params| {
            stage.bind(ctx, &[params, &islands, &values, &tolerances, &verdicts])
        });
        let mut encoder = ctx.encoder("all bases");
        ctx.record(&mut encoder, stage, &ranges);
        figures.chunks += 1;
        figures.dispatches += ranges.len();
        let bytes = ctx.submit_and_read(encoder, &[(&verdicts, word_count as u64 * 4)])?;
        Ok(bytemuck::pod_collect_to_vec(&bytes[0]))
    })?
}

/// The bases of one island to re-solve, from its verdict words.
fn decode(words: &[u32], n: usize, precision: Precision) -> Screened {
    let trust_singular = precision == Precision::F64;
    let mut s = Screened::default();
    for mask in 0..(1u32 << n) {
        let w = words[mask as usize / BASES_PER_WORD];
        let v = (w >> (2 * (mask as usize % BASES_PER_WORD))) & 3;
        if v & CANDIDATE != 0 {
            s.candidates.push(mask);
        } else if v & SINGULAR_BASIS != 0 {
            if trust_singular {
                s.trusted_singular += 1;
            } else {
                s.candidates.push(mask);
            }
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn verdict_words_decode_by_basis() {
        // n = 2: bases 0..4 in the low byte of one word: 0 candidate,
        // 1 singular, 2 nothing, 3 candidate.
        let w = CANDIDATE | (SINGULAR_BASIS << 2) | (CANDIDATE << 6);
        let f64s = decode(&[w], 2, Precision::F64);
        assert_eq!(f64s.candidates, vec![0, 3]);
        assert_eq!(f64s.trusted_singular, 1);
        let f32s = decode(&[w], 2, Precision::F32);
        assert_eq!(f32s.candidates, vec![0, 1, 3]);
        assert_eq!(f32s.trusted_singular, 0);
    }

    #[test]
    fn chunks_respect_the_binding_limit_and_u32_invocations() {
        let islands: Vec<usize> = (0..100_000).collect();
        let n16: Vec<usize> = size_chunks(&islands, 16, Precision::F64, 1 << 30)
            .map(|c| c.len())
            .collect();
        // 4096 verdict words (16 KiB) per island; islands × 2^16 stays a u32.
        assert!(
            n16.iter().all(|&c| ((c as u64) << 16) <= u32::MAX as u64),
            "{n16:?}"
        );
        let small: Vec<usize> = size_chunks(&islands, 4, Precision::F64, 1024)
            .map(|c| c.len())
            .collect();
        // (16 + 4) × 8 = 160 bytes of values per island: 6 per 1 KiB.
        assert_eq!(small[0], 6);
    }
}
