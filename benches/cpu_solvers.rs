//! CPU solver throughput: enumeration, Lemke and PGS on fixed-seed physical
//! islands, per island size n = 1…12 (1000 islands per n from
//! `generate::random_island` with mass ratio 100). Throughput is in islands
//! per second. Each group is kept small (10 samples, 1 s of measurement) so
//! that `cargo bench --bench cpu_solvers` finishes in a few minutes.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lcpbatch::generate::{random_island, Rng};
use lcpbatch::pipeline::build;
use lcpbatch::{solve, Lcp, Solver, SolverSettings};

const ISLANDS_PER_N: usize = 1000;
const MAX_N: usize = 12;
const MASS_RATIO: f64 = 100.0;

/// The island LCPs of size n (assembly is not timed).
fn islands(n: usize) -> Vec<Lcp> {
    let mut rng = Rng::new(0xBE7C_0000 + n as u64);
    (0..ISLANDS_PER_N)
        .map(|_| {
            let scene = random_island(&mut rng, n, MASS_RATIO);
            let (_, _, mut lcps) = build(&scene, "bench island").expect("valid scene");
            lcps.pop().expect("one island")
        })
        .collect()
}

fn bench_solvers(c: &mut Criterion) {
    let sets: Vec<(usize, Vec<Lcp>)> = (1..=MAX_N).map(|n| (n, islands(n))).collect();
    for solver in [Solver::Enum, Solver::Lemke, Solver::Pgs] {
        // Bare solvers: no prediction before enumeration (BENCHMARKS.md's
        // `enum` column is exhaustive enumeration alone).
        let settings = SolverSettings {
            predict: false,
            ..SolverSettings::with_solver(solver)
        };
        let mut group = c.benchmark_group(format!("cpu_{}", solver.name()));
        group
            .sample_size(10)
            .warm_up_time(Duration::from_millis(300))
            .measurement_time(Duration::from_secs(1));
        for (n, lcps) in &sets {
            group.throughput(Throughput::Elements(lcps.len() as u64));
            group.bench_with_input(BenchmarkId::from_parameter(n), lcps, |b, lcps| {
                b.iter(|| {
                    for lcp in lcps {
                        black_box(solve(black_box(lcp), &settings).expect("solvable"));
                    }
                })
            });
        }
        group.finish();
    }
}

criterion_group!(benches, bench_solvers);
criterion_main!(benches);
