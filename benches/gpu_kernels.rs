//! The GPU enumeration kernels against each other, and prediction before
//! the GPU on and off, in islands per second (criterion; replaces the
//! measurement tests that printed the tables in BENCHMARKS.md).
//!
//! - `gpu_kernel/<precision>/n=<n>`: the elimination,
//!   specialised (unrolled) and tree kernels, and Auto's choice, on the same
//!   batch of islands of exactly n contacts, uploaded once, dispatch alone
//!   (every enumeration round; Tree: every island through the tree kernel,
//!   the undecided ones then by elimination; Auto: the positive definite
//!   ones through the tree);
//! - `gpu_prediction/<precision>`: `solve_lcp_batch_warm` on demo-world
//!   islands with prediction off, on, and on with last frame's bases (warm).
//!
//! Device and pipelines are made once, and every batch is dispatched once
//! before timing (lavapipe compiles a shader at its first dispatch). The
//! adapter follows LCPBATCH_GPU_ADAPTER / _BACKEND; both precisions run where
//! the adapter has f64. LCPBATCH_BENCH_ISLANDS sets islands per batch (512).

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lcpbatch::bench::{family_batch, islands_of_size, BenchFamily};
use lcpbatch::cpu::enumeration_tree::TREE_MAX_N;
use lcpbatch::gpu::batch::{solve_lcp_batch_warm, EnumerationKernel, UploadedBatch};
use lcpbatch::gpu::{GpuContext, GpuOptions, GpuSolveSettings, Precision};
use lcpbatch::Lcp;

fn contexts() -> Vec<GpuContext> {
    let base = GpuOptions::from_env().expect("GPU environment variables");
    let mut out = Vec::new();
    for precision in [Precision::F32, Precision::F64] {
        match GpuContext::new(&GpuOptions {
            precision,
            ..base.clone()
        }) {
            Ok(c) => out.push(c),
            Err(e) if precision == Precision::F64 => eprintln!("f64 skipped: {e}"),
            Err(e) => panic!("no GPU adapter: {e}"),
        }
    }
    out
}

fn islands_per_batch() -> usize {
    std::env::var("LCPBATCH_BENCH_ISLANDS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(512)
}

fn configure(g: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>) {
    g.sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(2));
}

fn bench_kernels(c: &mut Criterion) {
    for ctx in contexts() {
        let p = ctx.precision().name();
        for n in [8usize, 10, 12] {
            let lcps = islands_of_size(n, islands_per_batch(), 2026);
            let refs: Vec<&Lcp> = lcps.iter().collect();
            let mut g = c.benchmark_group(format!("gpu_kernel/{p}/n={n}"));
            configure(&mut g);
            g.throughput(Throughput::Elements(lcps.len() as u64));
            for kernel in [
                EnumerationKernel::Elimination,
                EnumerationKernel::Unrolled,
                EnumerationKernel::Tree,
                EnumerationKernel::Auto,
            ] {
                if kernel == EnumerationKernel::Unrolled && n > 8 {
                    continue; // specialised kernels exist for n ≤ 8
                }
                if kernel == EnumerationKernel::Tree && n > TREE_MAX_N {
                    continue;
                }
                let s = GpuSolveSettings {
                    kernel,
                    predict: false,
                    ..Default::default()
                };
                let b = UploadedBatch::new(&ctx, &refs, &s).expect("upload");
                b.dispatch().expect("warm-up dispatch");
                g.bench_function(
                    BenchmarkId::from_parameter(format!("{kernel:?}")),
                    |bench| bench.iter(|| black_box(b.dispatch().expect("dispatch"))),
                );
            }
            g.finish();
        }
    }
}

fn bench_prediction(c: &mut Criterion) {
    for ctx in contexts() {
        let p = ctx.precision().name();
        let lcps = family_batch(BenchFamily::MixedN, 7, 8 * islands_per_batch());
        let on = GpuSolveSettings::default();
        let off = GpuSolveSettings {
            predict: false,
            ..Default::default()
        };
        let cold = solve_lcp_batch_warm(&ctx, &lcps, None, &on).expect("warm-up");
        let warm: Vec<Option<u32>> = cold.islands.iter().map(|o| o.solution.basis).collect();
        let mut g = c.benchmark_group(format!("gpu_prediction/{p}"));
        configure(&mut g);
        g.throughput(Throughput::Elements(lcps.len() as u64));
        g.bench_function("off", |b| {
            b.iter(|| black_box(solve_lcp_batch_warm(&ctx, &lcps, None, &off).unwrap()))
        });
        g.bench_function("on", |b| {
            b.iter(|| black_box(solve_lcp_batch_warm(&ctx, &lcps, None, &on).unwrap()))
        });
        g.bench_function("warm", |b| {
            b.iter(|| black_box(solve_lcp_batch_warm(&ctx, &lcps, Some(&warm), &on).unwrap()))
        });
        g.finish();
    }
}

criterion_group!(benches, bench_kernels, bench_prediction);
criterion_main!(benches);
