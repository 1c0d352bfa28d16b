//! The CPU path's parallelism: a batch of islands spread over the cores in
//! interleaved chunks, in order.

/// `f(0), …, f(count − 1)` in order, computed on up to `threads` threads
/// (0 or 1: on this one). Work is handed out in interleaved chunks of 64
/// indices, so that large and small islands spread evenly over the threads.
pub fn parallel_map<T: Send>(
    count: usize,
    threads: usize,
    f: impl Fn(usize) -> T + Sync,
) -> Vec<T> {
    let threads = threads.min(count.div_ceil(64)).max(1);
    if threads == 1 {
        return (0..count).map(f).collect();
    }
    let chunk = 64;
    let mut out: Vec<Option<T>> = (0..count).map(|_| None).collect();
    let next = std::sync::atomic::AtomicUsize::new(0);
    let results = std::sync::Mutex::new(&mut out);
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| loop {
                let start = next.fetch_add(chunk, std::sync::atomic::Ordering::Relaxed);
                if start >= count {
                    break;
                }
                let end = (start + chunk).min(count);
                let part: Vec<T> = (start..end).map(&f).collect();
                let mut guard = results.lock().unwrap_or_else(|p| p.into_inner());
                for (k, r) in part.into_iter().enumerate() {
                    guard[start + k] = Some(r);
                }
            });
        }
    });
    out.into_iter()
        .map(|r| r.expect("every chunk was computed"))
        .collect()
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
}
