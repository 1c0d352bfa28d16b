//! The CPU path for a batch of island LCPs: prediction, then enumeration in
//! Gray-code order (or Lemke above n = 20), spread over the cores.
//! Per island it allocates only the result; the enumeration works in fixed
//! arrays on the stack.

use crate::cpu::enumeration::{enumerate, MAX_ENUMERATION_N};
use crate::cpu::enumeration_gray::{enumerate_gray, GraySettings};
use crate::lcp::{Lcp, LcpSolution};
use crate::prediction::{is_positive_definite, prediction, SolvePath};
use crate::solvers::lemke::{lemke, LemkeSettings};

/// Settings of the CPU batch path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CpuBatchSettings {
    /// Enumeration settings and the Gray-code refactorisation period.
    pub gray: GraySettings,
    /// Try the cheap paths of [`crate::prediction`] first (default true).
    pub predict: bool,
    /// Worker threads; 0 (default) uses every core the OS reports.
    pub threads: usize,
    /// For islands above n = 20.
    pub lemke: LemkeSettings,
}

impl Default for CpuBatchSettings {
    fn default() -> Self {
        CpuBatchSettings {
            gray: GraySettings::default(),
            predict: true,
            threads: 0,
            lemke: LemkeSettings::default(),
        }
    }
}

/// One island's result and how it was reached.
#[derive(Clone, Debug)]
pub struct CpuIslandResult {
    pub path: SolvePath,
    pub solution: LcpSolution,
}

/// Solves one island: prediction, else enumeration (by elimination or in
/// Gray-code order, whichever [`prefers_elimination`] expects to be faster),
/// else (n > 20) Lemke.
pub fn solve_island(lcp: &Lcp, warm_basis: Option<u32>, s: &CpuBatchSettings) -> CpuIslandResult {
    if lcp.n() > MAX_ENUMERATION_N {
        return CpuIslandResult {
            path: SolvePath::Lemke,
            solution: lemke(lcp, &s.lemke),
        };
    }
    let mut definite = None;
    if s.predict {
        match prediction(lcp, warm_basis, &s.gray.enumeration) {
            Ok((path, solution)) => return CpuIslandResult { path, solution },
            Err(unsettled) => definite = unsettled.definite,
        }
    }
    let definite = definite.unwrap_or_else(|| is_positive_definite(lcp));
    let solution = if prefers_elimination(lcp, definite) {
        enumerate(lcp, &s.gray.enumeration)
    } else {
        enumerate_gray(lcp, &s.gray)
    }
    .expect("n ≤ 20 and settings validated by the caller");
    CpuIslandResult {
        path: SolvePath::Enumerated,
        solution,
    }
}

/// Which enumeration is cheaper for this island? Both give the same result.
///
/// - M not positive definite (resting contacts: four coplanar contacts of a
///   box give a singular M): elimination. Many principal submatrices are
///   singular, and each costs the Gray code a rebuild of its tableau
///   (`lcpbatch bench`, resting stacks and mixed n: elimination 1.2× faster).
/// - Otherwise by the expected number of bases. Elimination visits bases by
///   size and stops at the first valid one; the active set is usually among
///   the approaching contacts, so it visits about Σ_{j ≤ a} C(n, j) bases
///   (a = #{q_i < 0}) at ~5× the cost per basis of the Gray code, which
///   always visits all 2ⁿ (measured at n = 10 on this machine: 170 against
///   35 ns per basis).
///
/// `definite`: whether M is positive definite
/// ([`crate::prediction::is_positive_definite`], which prediction has
/// usually run already).
pub fn prefers_elimination(lcp: &Lcp, definite: bool) -> bool {
    if !definite {
        return true;
    }
    let n = lcp.n();
    let a = lcp.q.iter().filter(|&&v| v < 0.0).count();
    let mut visited = 0u64;
    let mut c = 1u64; // C(n, j)
    for j in 0..=a {
        visited += c;
        c = c * (n - j) as u64 / (j + 1) as u64;
    }
    5 * visited < (1u64 << n)
}

/// Solves every island of a batch, in order. `warm[i]` is island i's basis
/// from the previous frame, if the caller has one. Errors only on settings
/// out of range.
pub fn solve_batch(
    lcps: &[Lcp],
    warm: Option<&[Option<u32>]>,
    s: &CpuBatchSettings,
) -> Result<Vec<CpuIslandResult>, crate::Error> {
    s.gray.enumeration.validate()?;
    let threads = match s.threads {
        0 => std::thread::available_parallelism().map_or(1, |n| n.get()),
        t => t,
    };
    let warm_of = |i: usize| warm.and_then(|w| w.get(i).copied().flatten());
    Ok(parallel_map(lcps.len(), threads, |i| {
        solve_island(&lcps[i], warm_of(i), s)
    }))
}

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
    use crate::cpu::enumeration::enumerate;
    use crate::generate::{demo_world, Rng};
    use crate::pipeline::build;

    #[test]
    fn batch_equals_enumeration_island_by_island_on_any_thread_count() {
        let mut rng = Rng::new(3);
        let lcps: Vec<Lcp> = (0..40)
            .flat_map(|_| build(&demo_world(&mut rng), "t").unwrap().2)
            .collect();
        for threads in [1, 3] {
            let s = CpuBatchSettings {
                threads,
                ..Default::default()
            };
            let results = solve_batch(&lcps, None, &s).unwrap();
            for (lcp, r) in lcps.iter().zip(&results) {
                let e = enumerate(lcp, &s.gray.enumeration).unwrap();
                assert_eq!(r.solution.status, e.status);
                let scale = e.z.iter().fold(1e-300f64, |m, v| m.max(v.abs()));
                for (a, b) in r.solution.z.iter().zip(&e.z) {
                    assert!(
                        (a - b).abs() <= 1e-12 * scale,
                        "{:?} vs {:?}",
                        r.solution.z,
                        e.z
                    );
                }
            }
        }
    }

    #[test]
    fn warm_start_resolves_the_same_batch_without_enumeration() {
        let mut rng = Rng::new(4);
        let lcps: Vec<Lcp> = (0..20)
            .flat_map(|_| build(&demo_world(&mut rng), "t").unwrap().2)
            .collect();
        let s = CpuBatchSettings {
            threads: 1,
            ..Default::default()
        };
        let cold = solve_batch(&lcps, None, &s).unwrap();
        let warm: Vec<Option<u32>> = cold.iter().map(|r| r.solution.basis).collect();
        let hot = solve_batch(&lcps, Some(&warm), &s).unwrap();
        for (c, h) in cold.iter().zip(&hot) {
            assert_eq!(c.solution.z, h.solution.z);
            assert_ne!(h.path, SolvePath::Enumerated);
        }
    }
}
