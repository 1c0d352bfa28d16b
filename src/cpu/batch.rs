//! The CPU path's parallelism: a batch of islands spread over the cores in
//! interleaved chunks, in order.

use std::sync::Mutex;

/// Indices per chunk handed to a thread at a time: large enough that taking
/// a chunk (one lock) costs nothing beside solving it, small enough that
/// large and small islands spread evenly over the threads.
const CHUNK: usize = 64;

/// `f(0), …, f(count − 1)` in order, computed on up to `threads` threads
/// (0 or 1: on this one). Work is handed out in interleaved chunks of
/// [`CHUNK`] indices; each result is written once, straight into its slot
/// of the output (no per-chunk buffer, no second lock), and the calling
/// thread works as one of the `threads` (one thread fewer to start).
pub fn parallel_map<T: Send>(
    count: usize,
    threads: usize,
    f: impl Fn(usize) -> T + Sync,
) -> Vec<T> {
    let threads = threads.min(count.div_ceil(CHUNK)).max(1);
    if threads == 1 {
        return (0..count).map(f).collect();
    }
    let mut out: Vec<Option<T>> = (0..count).map(|_| None).collect();
    parallel_fill(&mut out, threads, |i, slot| *slot = Some(f(i)));
    out.into_iter()
        .map(|r| r.expect("every chunk was computed"))
        .collect()
}

/// `f(i, &mut out[i])` for every i, over `threads` threads (0 or 1: on
/// the caller's), chunk by chunk as [`parallel_map`]: each result is
/// written where the caller keeps it, never moved (the default CPU path's
/// island reports are a few hundred bytes each).
pub fn parallel_fill<T: Send>(out: &mut [T], threads: usize, f: impl Fn(usize, &mut T) + Sync) {
    let threads = threads.min(out.len().div_ceil(CHUNK)).max(1);
    if threads == 1 {
        for (i, slot) in out.iter_mut().enumerate() {
            f(i, slot);
        }
        return;
    }
    let chunks = Mutex::new(out.chunks_mut(CHUNK).enumerate());
    let work = || loop {
        let next = chunks.lock().unwrap_or_else(|p| p.into_inner()).next();
        let Some((k, slots)) = next else {
            break;
        };
        for (j, slot) in slots.iter_mut().enumerate() {
            f(k * CHUNK + j, slot);
        }
    };
    std::thread::scope(|scope| {
        for _ in 1..threads {
            scope.spawn(&work);
        }
        work();
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
