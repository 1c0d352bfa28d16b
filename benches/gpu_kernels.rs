//! The GPU enumeration kernels against each other, through the library's
//! `Solver` (`GpuSettings::kernel`): 512 random physical islands of n = 4,
//! 8, 10 and 12 contacts per batch, f32 and f64, prediction off so that every
//! island is enumerated; then prediction off, on and warm-started on the
//! mixed family. Each solver compiles its kernels in an untimed first call.
//! Without an adapter nothing runs.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lcpbatch::generate::families::{family_batch, islands_of_size, BenchFamily};
use lcpbatch::{Backend, EnumerationKernel, GpuSettings, Method, Precision, Settings, Solver};

const ISLANDS: usize = 512;

/// A GPU solver at `precision` with `kernel`, or None (no adapter, no f64).
fn gpu(
    precision: Precision,
    kernel: EnumerationKernel,
    predict: bool,
    warm: bool,
) -> Option<Solver> {
    let gpu = GpuSettings {
        precision,
        kernel,
        ..GpuSettings::from_env().expect("GPU environment variables")
    };
    let s = Solver::new(Settings {
        gpu,
        predict,
        warm_start: warm,
        ..Settings::new(Backend::Gpu, Method::Enumeration)
    })
    .expect("valid settings");
    s.fallback().is_none().then_some(s)
}

fn configure(g: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>) {
    g.sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(2));
}

fn bench_kernels(c: &mut Criterion) {
    for precision in [Precision::F32, Precision::F64] {
        for n in [4usize, 8, 10, 12] {
            let lcps = islands_of_size(n, ISLANDS, 0x6E7);
            let mut g = c.benchmark_group(format!("gpu_kernel/{}/n={n}", precision.name()));
            configure(&mut g);
            g.throughput(Throughput::Elements(lcps.len() as u64));
            for kernel in [
                EnumerationKernel::Elimination,
                EnumerationKernel::Unrolled,
                EnumerationKernel::Tree,
                EnumerationKernel::Workgroup,
                EnumerationKernel::Auto,
            ] {
                let Some(mut s) = gpu(precision, kernel, false, false) else {
                    continue;
                };
                s.solve_lcps(&lcps).expect("compile, untimed");
                g.bench_function(BenchmarkId::from_parameter(kernel.name()), |b| {
                    b.iter(|| black_box(s.solve_lcps(black_box(&lcps)).expect("solvable")))
                });
            }
            g.finish();
        }
    }
}

fn bench_prediction(c: &mut Criterion) {
    let lcps = family_batch(BenchFamily::MixedN, 7, 4000);
    let ids: Vec<Vec<u64>> = {
        let mut next = 0u64;
        lcps.iter()
            .map(|l| {
                next += l.n() as u64;
                (next - l.n() as u64..next).collect()
            })
            .collect()
    };
    for precision in [Precision::F32, Precision::F64] {
        let mut g = c.benchmark_group(format!("gpu_prediction/{}", precision.name()));
        configure(&mut g);
        g.throughput(Throughput::Elements(lcps.len() as u64));
        for (name, predict, warm) in [
            ("off", false, false),
            ("on", true, false),
            ("warm", true, true),
        ] {
            let Some(mut s) = gpu(precision, EnumerationKernel::Auto, predict, warm) else {
                continue;
            };
            s.solve_lcps_keyed(&lcps, &ids)
                .expect("compile and remember, untimed");
            g.bench_function(name, |b| {
                b.iter(|| {
                    black_box(
                        s.solve_lcps_keyed(black_box(&lcps), &ids)
                            .expect("solvable"),
                    )
                })
            });
        }
        g.finish();
    }
}

criterion_group!(benches, bench_kernels, bench_prediction);
criterion_main!(benches);
