//! The CPU path's parallelism: a batch of islands spread over the cores in
//! chunks, in order, on threads that live as long as the process.
//!
//! Why threads that stay: a batch is a few milliseconds (a step of 1,000
//! worlds, a batch of 10,000 small islands), and threads started per batch
//! began each with cold per-thread memory (their allocator caches, the
//! friction solver's thread-local problem) and gave it all back at their
//! end, every batch (BENCHMARKS.md, "Worlds in time"). The pools are
//! rayon's, one per thread count asked for, built on first use.

use std::sync::{Arc, Mutex, OnceLock};

use rayon::prelude::*;
use rayon::ThreadPool;

/// Indices per chunk handed to a thread at a time: large enough that taking
/// a chunk costs nothing beside solving it, small enough that large and
/// small islands spread evenly over the threads.
const CHUNK: usize = 64;

/// The most threads a pool has (a larger `threads` setting gets this many):
/// every pool stays for the process's life.
const MAX_THREADS: usize = 256;

/// The pools built so far: the process that built them and their thread
/// count.
type Pools = Mutex<Vec<(u32, usize, Arc<ThreadPool>)>>;

/// The pool of `threads` threads (≥ 2), built on first use and kept. None
/// where the system refuses threads: the caller then works alone.
///
/// A child made by `fork` (Python's `multiprocessing` on Linux) inherits
/// the pools but not their threads, and would wait for them forever: a
/// process uses only the pools it built itself (the inherited ones are
/// forgotten, not dropped, since their threads are not there to stop).
fn pool(threads: usize) -> Option<Arc<ThreadPool>> {
    let threads = threads.min(MAX_THREADS);
    static POOLS: OnceLock<Pools> = OnceLock::new();
    let me = std::process::id();
    let mut pools = POOLS
        .get_or_init(Default::default)
        .lock()
        .unwrap_or_else(|p| p.into_inner());
    if pools.iter().any(|(pid, _, _)| *pid != me) {
        std::mem::forget(std::mem::take(&mut *pools));
    }
    if let Some((_, _, p)) = pools.iter().find(|(_, n, _)| *n == threads) {
        return Some(p.clone());
    }
    let built = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .thread_name(|i| format!("lcpbatch-{i}"))
        .build()
        .ok()?;
    let built = Arc::new(built);
    pools.push((me, threads, built.clone()));
    Some(built)
}

/// `f(0), …, f(count − 1)` in order, computed on up to `threads` threads
/// (0 or 1: on this one; else a pool's, at least [`CHUNK`] indices a task).
pub fn parallel_map<T: Send>(
    count: usize,
    threads: usize,
    f: impl Fn(usize) -> T + Sync,
) -> Vec<T> {
    let threads = threads.min(count.div_ceil(CHUNK)).max(1);
    let Some(pool) = (threads > 1).then(|| pool(threads)).flatten() else {
        return (0..count).map(f).collect();
    };
    // Each result written in its place by the thread that computes it:
    // nothing moved after, nothing written twice.
    let mut out = Vec::with_capacity(count);
    pool.install(|| {
        (0..count)
            .into_par_iter()
            .with_min_len(CHUNK)
            .map(&f)
            .collect_into_vec(&mut out)
    });
    out
}

/// `f(i, &mut out[i])` for every slot, on up to `threads` threads (0 or 1:
/// on this one; else a pool's), [`CHUNK`] slots at a time; see
/// [`parallel_fill_by`].
pub fn parallel_fill<T: Send>(out: &mut [T], threads: usize, f: impl Fn(usize, &mut T) + Sync) {
    parallel_fill_by(out, threads, CHUNK, f);
}

/// `f(i, &mut out[i])` for every slot, on up to `threads` threads (0 or 1:
/// on this one; else a pool's). Chunks of `chunk` consecutive slots are
/// handed out in order as threads ask (one lock each), so a core busy
/// elsewhere takes fewer; each slot is visited once.
pub(crate) fn parallel_fill_by<T: Send>(
    out: &mut [T],
    threads: usize,
    chunk: usize,
    f: impl Fn(usize, &mut T) + Sync,
) {
    let chunk = chunk.max(1);
    // The pool of the thread count asked for (one pool per count, however
    // small the batch); a batch of one chunk stays on this thread.
    let alone = threads <= 1 || out.len() <= chunk;
    let Some(pool) = (!alone).then(|| pool(threads)).flatten() else {
        for (i, slot) in out.iter_mut().enumerate() {
            f(i, slot);
        }
        return;
    };
    let chunks = Mutex::new(out.chunks_mut(chunk).enumerate());
    pool.broadcast(|_| loop {
        let next = chunks.lock().unwrap_or_else(|p| p.into_inner()).next();
        let Some((k, slots)) = next else {
            break;
        };
        for (j, slot) in slots.iter_mut().enumerate() {
            f(k * chunk + j, slot);
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn results_come_back_in_order_on_any_thread_count() {
        for threads in [0, 1, 2, 3, 8] {
            let out = parallel_map(1000, threads, |i| i * i);
            assert_eq!(out, (0..1000).map(|i| i * i).collect::<Vec<_>>());
        }
        assert!(parallel_map(0, 4, |i| i).is_empty());
    }

    #[test]
    fn every_slot_is_filled_once_on_any_thread_count() {
        for threads in [0, 1, 2, 3, 8] {
            let mut out = vec![(0usize, 0usize); 1000];
            parallel_fill(&mut out, threads, |i, slot| {
                *slot = (slot.0 + 1, i * i);
            });
            assert!(out.iter().enumerate().all(|(i, &s)| s == (1, i * i)));
        }
        parallel_fill(&mut Vec::<usize>::new(), 4, |_, _| unreachable!());
    }
}
