//! The cone projection iterations (APGD and projected Jacobi) on the CPU
//! twin over every core against the GPU (the environment's adapter; on this
//! machine Mesa lavapipe) in f64 and f32, each solving to its tolerance
//! (default 1e-8 in f64, 1e-5 in f32) with every GPU answer validated in
//! f64 on the CPU (polish and repair included in the time). Fixed-seed
//! random islands of k contacts from random contact Jacobians
//! (`lcpbatch::internals::random_problems`), 10,000 islands at
//! k = 1 and 4, fewer at 8 and 16 where a GPU batch of 10,000 takes many
//! seconds on a software adapter (`BATCHES`; `LCPBATCH_FRICTION_BENCH_K=1,4`
//! picks sizes). Jacobi runs at k = 1 only (at k = 4 some islands stop at
//! the 20,000-sweep cap).
//! Before each row it prints the largest cone error reached and the
//! islands polished or repaired. Throughput is in islands per second; groups are small (10
//! samples). Without an adapter only the CPU rows run.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lcpbatch::device::GpuContext;
use lcpbatch::internals::{
    random_problems, solve_projected_batch, solve_projected_on_gpu, ProjectedMethod,
    ProjectedSettings,
};
use lcpbatch::{FrictionProblem, GpuSettings, Precision};

/// (k, islands per batch).
const BATCHES: [(usize, usize); 4] = [(1, 10_000), (4, 10_000), (8, 2_000), (16, 500)];

/// The sizes of `BATCHES` asked for in `LCPBATCH_FRICTION_BENCH_K` (all
/// without it).
fn wanted(k: usize) -> bool {
    std::env::var("LCPBATCH_FRICTION_BENCH_K")
        .map_or(true, |v| v.split(',').any(|x| x.trim().parse() == Ok(k)))
}

fn settings(method: ProjectedMethod, tolerance: f64) -> ProjectedSettings {
    ProjectedSettings {
        method,
        tolerance: Some(tolerance),
        max_iterations: 20_000,
        ..Default::default()
    }
}

/// A GPU context at `precision`, or None (no adapter, no f64).
fn gpu(precision: Precision) -> Option<GpuContext> {
    let s = GpuSettings {
        precision,
        ..GpuSettings::from_env().expect("GPU environment variables")
    };
    GpuContext::open(&s)
        .ok()
        .filter(|c| c.precision() == precision)
}

fn worst(errors: impl Iterator<Item = f64>) -> f64 {
    errors.fold(0.0, f64::max)
}

fn bench_projected(c: &mut Criterion) {
    let contexts: Vec<GpuContext> = [Precision::F64, Precision::F32]
        .into_iter()
        .filter_map(gpu)
        .collect();
    let gpu_settings = GpuSettings::default();
    for (k, count) in BATCHES.into_iter().filter(|&(k, _)| wanted(k)) {
        let problems: Vec<FrictionProblem> = random_problems(0x5EED + k as u64, count, k);
        let mut g = c.benchmark_group(format!("friction_projected/k={k}/n={count}"));
        g.sample_size(10)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(2));
        g.throughput(Throughput::Elements(count as u64));
        for method in [ProjectedMethod::Apgd, ProjectedMethod::Jacobi] {
            if method == ProjectedMethod::Jacobi && k > 1 {
                continue;
            }
            for tol in [1e-8, 1e-5] {
                let s = settings(method, tol);
                let out = solve_projected_batch(&problems, None, &s, 0).expect("valid");
                let err = worst(out.iter().map(|o| o.residuals.cone_error));
                let name = format!("cpu_all_cores/{}/tol={tol:e}", method.name());
                eprintln!("{name}: worst cone error {err:.2e}");
                g.bench_function(BenchmarkId::from_parameter(&name), |b| {
                    b.iter(|| black_box(solve_projected_batch(black_box(&problems), None, &s, 0)))
                });
            }
            for ctx in &contexts {
                let tol = if ctx.precision() == Precision::F64 {
                    1e-8
                } else {
                    1e-5
                };
                let s = settings(method, tol);
                // Compiles the shader (untimed) and reports what validation did.
                let (out, f) = solve_projected_on_gpu(ctx, &problems, None, &s, &gpu_settings)
                    .expect("GPU run");
                let err = worst(out.iter().map(|o| o.residuals.cone_error));
                let name = format!(
                    "gpu_{}/{}/tol={tol:e}",
                    ctx.precision().name(),
                    method.name()
                );
                eprintln!(
                    "{name}: worst cone error {err:.2e}, kept {} polished {} repaired {}, rounds {}",
                    f.gpu, f.polished, f.repaired, f.rounds
                );
                g.bench_function(BenchmarkId::from_parameter(&name), |b| {
                    b.iter(|| {
                        black_box(solve_projected_on_gpu(
                            ctx,
                            black_box(&problems),
                            None,
                            &s,
                            &gpu_settings,
                        ))
                    })
                });
            }
        }
        g.finish();
    }
}

criterion_group!(benches, bench_projected);
criterion_main!(benches);
