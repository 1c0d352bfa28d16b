//! Lemke in Rust against a plain dense-tableau Lemke in C (benches/c/lemke.c,
//! compiled by build.rs with feature `c-reference`), and the default CPU
//! path (`Method::Auto` through the `Solver`, one and two threads), on the
//! same batches in one run (issue 11, part 4):
//!
//! - SPD n = 4, 8, 12: M = A Aᵀ / n + 0.05 I, A_ij and q_i ~ U[−1, 1];
//! - resting stacks n = 8, 12 (src/generate's stress family: boxes on the
//!   ground and stacked, rank-deficient M).
//!
//! Rows: `c` (pivots; z and w read from the final tableau, nothing checked),
//! `rust_path` (`lcpbatch::internals::lemke_textbook_basis`: the same
//! pivots, the final basis read from the tableau, nothing checked: the like
//! of `c`), `rust` (`lcpbatch::internals::lemke`: the same textbook path,
//! then its basis re-solved from the data, the better z kept, and the
//! residuals), `auto_1t` and
//! `auto_2t` (the default CPU path: prediction, Lemke's basis re-solved and
//! checked in f64, the report). Throughput in problems per second.
//!
//! `cargo bench --features c-reference --bench lemke_c`

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lcpbatch::generate::{stress, Rng};
use lcpbatch::internals::{lemke, lemke_textbook_basis, LemkeSettings};
use lcpbatch::{Backend, Lcp, Method, Settings, Solver, Status};

extern "C" {
    fn lemke_c_work_size(n: i32) -> usize;
    fn lemke_c(
        n: i32,
        m: *const f64,
        q: *const f64,
        z: *mut f64,
        w: *mut f64,
        work: *mut f64,
        max_pivots: i32,
    ) -> i32;
}

/// Problems per batch.
const BATCH: usize = 2000;

/// M = A Aᵀ / n + 0.05 I with A_ij ~ U[−1, 1], q ~ U[−1, 1].
fn spd_batch(n: usize, count: usize, seed: u64) -> Vec<Lcp> {
    let mut rng = Rng::new(seed);
    (0..count)
        .map(|_| {
            let a: Vec<f64> = (0..n * n).map(|_| rng.range(-1.0, 1.0)).collect();
            let mut m = vec![0.0; n * n];
            for i in 0..n {
                for j in 0..n {
                    let dot: f64 = (0..n).map(|k| a[i * n + k] * a[j * n + k]).sum();
                    m[i * n + j] = dot / n as f64 + if i == j { 0.05 } else { 0.0 };
                }
            }
            let q = (0..n).map(|_| rng.range(-1.0, 1.0)).collect();
            Lcp::new(m, q).expect("finite")
        })
        .collect()
}

/// `count` resting-stack problems of exactly n contacts.
fn resting_batch(n: usize, count: usize, seed: u64) -> Vec<Lcp> {
    let mut out = Vec::with_capacity(count);
    let mut seed = seed;
    while out.len() < count {
        out.extend(
            stress::generate(stress::Family::RestingStacks, seed, 4 * count)
                .into_iter()
                .map(|c| c.lcp)
                .filter(|l| l.n() == n),
        );
        seed += 1;
    }
    out.truncate(count);
    out
}

/// Solves every problem with the C Lemke; returns the solved count (so that
/// nothing is optimised away) and fills `z`.
fn c_batch(lcps: &[Lcp], z: &mut [f64], w: &mut [f64], work: &mut [f64]) -> usize {
    let mut solved = 0;
    for l in lcps {
        let n = l.n();
        // SAFETY: m is n×n, q, z, w have n entries, work has
        // lemke_c_work_size(n) ≤ work.len() entries, n ≤ 64.
        let r = unsafe {
            lemke_c(
                n as i32,
                l.m.as_ptr(),
                l.q.as_ptr(),
                z.as_mut_ptr(),
                w.as_mut_ptr(),
                work.as_mut_ptr(),
                10_000,
            )
        };
        solved += usize::from(r >= 0);
    }
    solved
}

/// The largest error of the C answers and how many it solved (printed once,
/// so the comparison is between answers of the same quality).
fn c_quality(lcps: &[Lcp]) -> (f64, usize) {
    let mut work = vec![0.0; 64 * 130];
    let (mut worst, mut solved) = (0.0f64, 0);
    for l in lcps {
        let (mut z, mut w) = (vec![0.0; l.n()], vec![0.0; l.n()]);
        solved += c_batch(std::slice::from_ref(l), &mut z, &mut w, &mut work);
        worst = worst.max(l.residuals(&z).error);
    }
    (worst, solved)
}

fn default_path(threads: usize) -> Solver {
    Solver::new(Settings {
        threads,
        ..Settings::new(Backend::Cpu, Method::Auto)
    })
    .expect("valid settings")
}

fn bench_lemke_c(c: &mut Criterion) {
    let batches: Vec<(String, Vec<Lcp>)> = vec![
        ("spd_4".into(), spd_batch(4, BATCH, 4)),
        ("spd_8".into(), spd_batch(8, BATCH, 8)),
        ("spd_12".into(), spd_batch(12, BATCH, 12)),
        ("resting_8".into(), resting_batch(8, BATCH, 2026)),
        ("resting_12".into(), resting_batch(12, BATCH, 2026)),
    ];
    let settings = LemkeSettings::default();
    let (mut one, mut two) = (default_path(1), default_path(2));
    let mut work = vec![0.0; 64 * 130];
    let (mut z, mut w) = (vec![0.0; 64], vec![0.0; 64]);
    assert!(unsafe { lemke_c_work_size(64) } <= work.len());
    let mut group = c.benchmark_group("lemke_c");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
    for (name, lcps) in &batches {
        let (c_err, c_solved) = c_quality(lcps);
        let rust: Vec<_> = lcps.iter().map(|l| lemke(l, &settings)).collect();
        let rust_err = rust.iter().map(|s| s.residuals.error).fold(0.0, f64::max);
        let rust_solved = rust.iter().filter(|s| s.status == Status::Solved).count();
        let auto = one.solve_lcps(lcps).expect("solvable");
        let pivots: u64 = lcps
            .iter()
            .map(|l| lemke_textbook_basis(l, &settings).1)
            .sum();
        eprintln!(
            "{name}: C solved {c_solved}/{} max error {c_err:.1e}; Rust lemke {rust_solved} max error {rust_err:.1e}, {:.1} pivots per problem; auto solved {} max error {:.1e}",
            lcps.len(),
            pivots as f64 / lcps.len() as f64,
            auto.islands.iter().filter(|i| i.status().is_solution()).count(),
            auto.islands.iter().map(|i| i.solution.residuals.error).fold(0.0, f64::max),
        );
        group.throughput(Throughput::Elements(lcps.len() as u64));
        group.bench_with_input(BenchmarkId::new("c", name), lcps, |b, l| {
            b.iter(|| black_box(c_batch(black_box(l), &mut z, &mut w, &mut work)))
        });
        group.bench_with_input(BenchmarkId::new("rust", name), lcps, |b, l| {
            b.iter(|| {
                black_box(l)
                    .iter()
                    .map(|p| lemke(p, &settings).residuals.error)
                    .fold(0.0, f64::max)
            })
        });
        group.bench_with_input(BenchmarkId::new("rust_path", name), lcps, |b, l| {
            b.iter(|| {
                black_box(l)
                    .iter()
                    .map(|p| lemke_textbook_basis(p, &settings).1)
                    .sum::<u64>()
            })
        });
        group.bench_with_input(BenchmarkId::new("auto_1t", name), lcps, |b, l| {
            b.iter(|| black_box(one.solve_lcps(black_box(l)).expect("solvable")))
        });
        group.bench_with_input(BenchmarkId::new("auto_2t", name), lcps, |b, l| {
            b.iter(|| black_box(two.solve_lcps(black_box(l)).expect("solvable")))
        });
    }
    group.finish();
}

/// The default path on one and two threads over 10,000 islands (the
/// issue's batch size for its two-thread target).
fn bench_threads(c: &mut Criterion) {
    let batches = [
        ("spd_8", spd_batch(8, 10_000, 80)),
        ("resting_12", resting_batch(12, 10_000, 2027)),
    ];
    let (mut one, mut two) = (default_path(1), default_path(2));
    let mut group = c.benchmark_group("threads");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(2));
    for (name, lcps) in &batches {
        group.throughput(Throughput::Elements(lcps.len() as u64));
        group.bench_with_input(BenchmarkId::new("auto_1t", name), lcps, |b, l| {
            b.iter(|| black_box(one.solve_lcps(black_box(l)).expect("solvable")))
        });
        group.bench_with_input(BenchmarkId::new("auto_2t", name), lcps, |b, l| {
            b.iter(|| black_box(two.solve_lcps(black_box(l)).expect("solvable")))
        });
    }
    group.finish();
}

criterion_group!(benches, bench_lemke_c, bench_threads);
criterion_main!(benches);
