//! The GPU path against the CPU enumeration on the same batches of
//! fixed-seed physical islands, n = 1…12 mixed (`generate::random_island`,
//! mass ratios up to 1e3), in islands per second:
//!
//! - `gpu_upload_dispatch_readback`: pack + upload M and q, every
//!   enumeration round, readback of the chosen bases and z;
//! - `gpu_dispatch`: the enumeration rounds alone on a batch uploaded once;
//! - `gpu_solve_validated`: `solve_lcp_batch`, i.e. the above plus the f64
//!   validation (polish) of every island on the CPU;
//! - `cpu_enumeration`: `cpu::enumeration::enumerate` island by island, one thread;
//! - `gpu_workgroup/<precision>/n=<n>`, n = 8, 10, 12, 14, 16
//!   (LCPBATCH_WORKGROUP_SIZES, e.g. `9,11`): the same batch
//!   of islands of exactly n contacts (`bench::islands_of_size`, seed 2026,
//!   LCPBATCH_WORKGROUP_ISLANDS per n, default 128) through the per-island
//!   elimination kernel and the workgroup kernel (one workgroup per island),
//!   uploaded once, dispatches alone (every round), and through
//!   `cpu::enumeration::enumerate` on one thread. Both precisions where the
//!   adapter has f64; `cargo bench --bench gpu_path -- gpu_workgroup` runs
//!   these alone.
//!
//! The device and the pipelines are made once, and one batch is solved
//! before any timing: lavapipe compiles a shader at its first dispatch.
//! Batch sizes: 1k, 10k and 100k islands on a hardware adapter; 1k and 10k
//! on a software adapter (100k takes minutes there), unless
//! LCPBATCH_BENCH_SIZES (e.g. `1000,10000,100000`) says otherwise.
//! The adapter and precision follow LCPBATCH_GPU_ADAPTER / _BACKEND / _PRECISION.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lcpbatch::bench::islands_of_size;
use lcpbatch::cpu::enumeration::{enumerate, EnumerationSettings};
use lcpbatch::generate::{random_island, Rng};
use lcpbatch::gpu::batch::{enumerate_on_gpu, EnumerationKernel, UploadedBatch};
use lcpbatch::gpu::{solve_lcp_batch, GpuContext, GpuOptions, GpuSolveSettings, Precision};
use lcpbatch::pipeline::build;
use lcpbatch::Lcp;

/// `count` island LCPs, n = 1…12 in turn (assembly is not timed).
fn batch(count: usize) -> Vec<Lcp> {
    let mut rng = Rng::new(0x6B0_0000 + count as u64);
    (0..count)
        .map(|k| {
            let scene = random_island(&mut rng, 1 + k % 12, [1.0, 10.0, 1e3][k % 3]);
            let (_, _, mut lcps) = build(&scene, "bench island").expect("valid scene");
            lcps.pop().expect("one island")
        })
        .collect()
}

fn sizes(ctx: &GpuContext) -> Vec<usize> {
    if let Ok(v) = std::env::var("LCPBATCH_BENCH_SIZES") {
        let s: Vec<usize> = v.split(',').filter_map(|x| x.trim().parse().ok()).collect();
        if !s.is_empty() {
            return s;
        }
    }
    if ctx.adapter_info().software {
        vec![1_000, 10_000]
    } else {
        vec![1_000, 10_000, 100_000]
    }
}

fn bench_gpu(c: &mut Criterion) {
    let options = GpuOptions::from_env().expect("GPU environment variables");
    let ctx = GpuContext::new(&options).unwrap_or_else(|e| panic!("no GPU adapter: {e}"));
    eprintln!(
        "adapter: {} ({}, {}), precision {}",
        ctx.adapter_info().name,
        ctx.adapter_info().backend,
        ctx.selection(),
        ctx.precision().name()
    );
    let settings = GpuSolveSettings::default();
    // Warm-up: pipelines built and shaders compiled outside any timing.
    let warm = batch(64);
    solve_lcp_batch(&ctx, &warm, &settings).expect("warm-up");

    let sets: Vec<(usize, Vec<Lcp>)> = sizes(&ctx).into_iter().map(|s| (s, batch(s))).collect();
    let configure = |g: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>| {
        g.sample_size(10)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(2));
    };

    let mut g = c.benchmark_group("gpu_upload_dispatch_readback");
    configure(&mut g);
    for (size, lcps) in &sets {
        let refs: Vec<&Lcp> = lcps.iter().collect();
        g.throughput(Throughput::Elements(*size as u64));
        g.bench_with_input(BenchmarkId::from_parameter(size), &refs, |b, refs| {
            b.iter(|| black_box(enumerate_on_gpu(&ctx, refs, &settings).expect("GPU run")))
        });
    }
    g.finish();

    let mut g = c.benchmark_group("gpu_dispatch");
    configure(&mut g);
    for (size, lcps) in &sets {
        let refs: Vec<&Lcp> = lcps.iter().collect();
        let uploaded = UploadedBatch::new(&ctx, &refs, &settings).expect("upload");
        uploaded.dispatch().expect("first dispatch");
        g.throughput(Throughput::Elements(*size as u64));
        g.bench_function(BenchmarkId::from_parameter(size), |b| {
            b.iter(|| black_box(uploaded.dispatch().expect("dispatch")))
        });
    }
    g.finish();

    let mut g = c.benchmark_group("gpu_solve_validated");
    configure(&mut g);
    for (size, lcps) in &sets {
        g.throughput(Throughput::Elements(*size as u64));
        g.bench_with_input(BenchmarkId::from_parameter(size), lcps, |b, lcps| {
            b.iter(|| black_box(solve_lcp_batch(&ctx, lcps, &settings).expect("GPU solve")))
        });
    }
    g.finish();

    let mut g = c.benchmark_group("cpu_enumeration");
    configure(&mut g);
    let es = EnumerationSettings::default();
    for (size, lcps) in &sets {
        g.throughput(Throughput::Elements(*size as u64));
        g.bench_with_input(BenchmarkId::from_parameter(size), lcps, |b, lcps| {
            b.iter(|| {
                for l in lcps {
                    black_box(enumerate(black_box(l), &es).expect("enumerable"));
                }
            })
        });
    }
    g.finish();
}

/// The workgroup kernel against the per-island elimination kernel and the
/// CPU enumeration (one thread), per island size, on the same batch.
fn bench_workgroup(c: &mut Criterion) {
    let base = GpuOptions::from_env().expect("GPU environment variables");
    let count: usize = std::env::var("LCPBATCH_WORKGROUP_ISLANDS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(128);
    let sizes: Vec<usize> = std::env::var("LCPBATCH_WORKGROUP_SIZES")
        .ok()
        .map(|v| v.split(',').filter_map(|x| x.trim().parse().ok()).collect())
        .filter(|v: &Vec<usize>| !v.is_empty())
        .unwrap_or_else(|| vec![8, 10, 12, 14, 16]);
    for precision in [Precision::F32, Precision::F64] {
        let ctx = match GpuContext::new(&GpuOptions {
            precision,
            ..base.clone()
        }) {
            Ok(c) => c,
            Err(e) if precision == Precision::F64 => {
                eprintln!("f64 skipped: {e}");
                continue;
            }
            Err(e) => panic!("no GPU adapter: {e}"),
        };
        let p = precision.name();
        for &n in &sizes {
            let lcps = islands_of_size(n, count, 2026);
            let refs: Vec<&Lcp> = lcps.iter().collect();
            let mut g = c.benchmark_group(format!("gpu_workgroup/{p}/n={n}"));
            g.sample_size(10)
                .warm_up_time(Duration::from_millis(300))
                .measurement_time(Duration::from_secs(2))
                .throughput(Throughput::Elements(lcps.len() as u64));
            for kernel in [EnumerationKernel::Elimination, EnumerationKernel::Workgroup] {
                let s = GpuSolveSettings {
                    kernel,
                    predict: false,
                    ..Default::default()
                };
                let b = UploadedBatch::new(&ctx, &refs, &s).expect("upload");
                b.dispatch().expect("warm-up dispatch");
                g.bench_function(BenchmarkId::from_parameter(kernel.name()), |bench| {
                    bench.iter(|| black_box(b.dispatch().expect("dispatch")))
                });
            }
            let es = EnumerationSettings::default();
            g.bench_function(BenchmarkId::from_parameter("cpu"), |bench| {
                bench.iter(|| {
                    for l in &lcps {
                        black_box(enumerate(black_box(l), &es).expect("enumerable"));
                    }
                })
            });
            g.finish();
        }
    }
}

criterion_group!(benches, bench_gpu, bench_workgroup);
criterion_main!(benches);
