//! One-thread timing by the thread's CPU time, shared by the benches
//! (`#[path]`-included): on a shared machine other processes slow a
//! figure measured this way less than one measured by the wall clock.

use std::time::{Duration, Instant};

/// This thread's CPU time so far (None where the kernel does not say).
pub fn thread_cpu_time() -> Option<Duration> {
    let text = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let ns: u64 = text.split_whitespace().next()?.parse().ok()?;
    Some(Duration::from_nanos(ns))
}

/// Time of `iters` runs of `step`: CPU time of this thread when `cpu` (and
/// the kernel says it; Linux `/proc/thread-self/schedstat`), else wall.
pub fn time_steps(iters: u64, cpu: bool, mut step: impl FnMut()) -> Duration {
    let wall = Instant::now();
    let start = thread_cpu_time().filter(|_| cpu);
    for _ in 0..iters {
        step();
    }
    match (start, thread_cpu_time()) {
        (Some(a), Some(b)) => b.saturating_sub(a),
        _ => wall.elapsed(),
    }
}
