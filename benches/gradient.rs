//! The cost of a batch's gradient against the cost of its solve (issue 25,
//! item 5): on the batches of `lcpbatch bench` (20,000 islands of each
//! family, seed 2026), in one run, the CPU solve through the `Solver`
//! (the default exact path, checks and report included) and the
//! vector–Jacobian product of the solved batch (`Report::lcp_vjps`, ∂L/∂z
//! and ∂L/∂w given), on one thread (by the thread's CPU time: the solver's
//! `threads: 1`, and `lcp_vjp` island by island) and on every core (wall
//! clock: the solver's default threads, and `Report::lcp_vjps`). Before
//! the groups it prints, per family, how the islands' derivatives read.
//! Throughput is in islands per second. Groups are small (10 samples, 1 s).

use std::hint::black_box;
use std::time::Duration;

#[path = "common/cpu_time.rs"]
mod cpu_time;
use cpu_time::time_steps;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lcpbatch::generate::families::{family_batch, BenchFamily};
use lcpbatch::generate::Rng;
use lcpbatch::gradient::{lcp_vjp, Derivative};
use lcpbatch::{Backend, Lcp, Method, Settings, Solver};

const ISLANDS: usize = 20_000;
const SEED: u64 = 2026;

fn bench_gradient(c: &mut Criterion) {
    let tolerance = Settings::default().tolerance;
    for family in [
        BenchFamily::WellConditioned,
        BenchFamily::MassRatio,
        BenchFamily::RestingStacks,
        BenchFamily::MixedN,
    ] {
        let lcps: Vec<Lcp> = family_batch(family, SEED, ISLANDS);
        let mut rng = Rng::new(SEED);
        let seeds: Vec<Vec<f64>> = lcps
            .iter()
            .map(|l| (0..l.n()).map(|_| rng.range(-1.0, 1.0)).collect())
            .collect();
        let dz: Vec<&[f64]> = seeds.iter().map(|v| &v[..]).collect();
        let mut one = Solver::new(Settings {
            threads: 1,
            ..Settings::new(Backend::Cpu, Method::Auto)
        })
        .expect("valid settings");
        let mut all =
            Solver::new(Settings::new(Backend::Cpu, Method::Auto)).expect("valid settings");
        let report = all.solve_lcps(&lcps).expect("solvable");
        let grads = report.lcp_vjps(&lcps, &dz, Some(&dz)).expect("valid");
        let count = |d: Derivative| grads.iter().filter(|g| g.derivative == d).count();
        eprintln!(
            "{}: {} islands, derivative exact {}, one_sided {}, undefined {}",
            family.name(),
            lcps.len(),
            count(Derivative::Exact),
            count(Derivative::OneSided),
            count(Derivative::Undefined)
        );
        let mut group = c.benchmark_group(format!("gradient_{}", family.name()));
        group
            .sample_size(10)
            .warm_up_time(Duration::from_millis(300))
            .measurement_time(Duration::from_secs(1))
            .throughput(Throughput::Elements(lcps.len() as u64));
        group.bench_function(BenchmarkId::new("solve", "1_thread"), |b| {
            b.iter_custom(|iters| {
                time_steps(iters, true, || {
                    black_box(one.solve_lcps(black_box(&lcps)).expect("solvable"));
                })
            })
        });
        group.bench_function(BenchmarkId::new("vjp", "1_thread"), |b| {
            b.iter_custom(|iters| {
                time_steps(iters, true, || {
                    for (i, (lcp, isl)) in lcps.iter().zip(&report.islands).enumerate() {
                        let z = &isl.solution.z[..];
                        black_box(lcp_vjp(lcp, z, dz[i], Some(dz[i]), tolerance).expect("valid"));
                    }
                })
            })
        });
        group.bench_function(BenchmarkId::new("solve", "all_cores"), |b| {
            b.iter(|| black_box(all.solve_lcps(black_box(&lcps)).expect("solvable")))
        });
        group.bench_function(BenchmarkId::new("vjp", "all_cores"), |b| {
            b.iter(|| {
                black_box(
                    report
                        .lcp_vjps(black_box(&lcps), &dz, Some(&dz))
                        .expect("valid"),
                )
            })
        });
        group.finish();
    }
}

criterion_group!(benches, bench_gradient);
criterion_main!(benches);
