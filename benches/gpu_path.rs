//! The GPU path end to end against the CPU on the same batches, through the
//! library's `Solver`: mixed-n islands of the demo worlds in batches of
//! 1,000, 10,000 and 100,000, solved on the GPU (upload, prediction,
//! dispatch, readback, validation in f64) and on the CPU (the default exact
//! path on every core). Without an adapter only the CPU rows run.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lcpbatch::generate::families::{family_batch, BenchFamily};
use lcpbatch::{Backend, GpuSettings, Method, Settings, Solver};

fn bench_path(c: &mut Criterion) {
    let mut solvers = vec![(
        "cpu_auto_all_cores".to_string(),
        Solver::new(Settings::new(Backend::Cpu, Method::Auto)).expect("valid settings"),
    )];
    let gpu = Solver::new(Settings {
        gpu: GpuSettings::from_env().expect("GPU environment variables"),
        ..Settings::new(Backend::Gpu, Method::Auto)
    })
    .expect("valid settings");
    if gpu.fallback().is_none() {
        let p = gpu.device().precision.name();
        solvers.push((format!("gpu_{p}_validated"), gpu));
    } else {
        eprintln!("no GPU adapter: CPU rows only");
    }
    for (name, mut solver) in solvers {
        let mut g = c.benchmark_group(name);
        g.sample_size(10)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(3));
        for size in [1_000usize, 10_000, 100_000] {
            let lcps = family_batch(BenchFamily::MixedN, 2026, size);
            solver.solve_lcps(&lcps[..256]).expect("warm-up"); // compiles kernels
            g.throughput(Throughput::Elements(size as u64));
            g.bench_with_input(BenchmarkId::from_parameter(size), &lcps, |b, lcps| {
                b.iter(|| black_box(solver.solve_lcps(black_box(lcps)).expect("solvable")))
            });
        }
        g.finish();
    }
}

criterion_group!(benches, bench_path);
criterion_main!(benches);
