//! CPU throughput per method on fixed-seed physical islands, per island size
//! n = 1…12 (1000 islands per n, mass ratio 100), one thread, through the
//! library's `Solver`: bare enumeration, Lemke and PGS (no prediction), and
//! the default exact path (`auto`: prediction, Lemke checked in f64,
//! enumeration where the check fails). Throughput is in islands per second.
//! Groups are small (10 samples, 1 s) so that the bench takes minutes.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lcpbatch::generate::families::islands_of_size;
use lcpbatch::{Backend, Lcp, Method, Settings, Solver};

const ISLANDS_PER_N: usize = 1000;
const MAX_N: usize = 12;

fn bench_solvers(c: &mut Criterion) {
    let sets: Vec<(usize, Vec<Lcp>)> = (1..=MAX_N)
        .map(|n| (n, islands_of_size(n, ISLANDS_PER_N, 0xBE7C)))
        .collect();
    for (method, predict) in [
        (Method::Enumeration, false),
        (Method::Lemke, false),
        (Method::Pgs, false),
        (Method::Auto, true),
    ] {
        let mut solver = Solver::new(Settings {
            threads: 1,
            predict,
            ..Settings::new(Backend::Cpu, method)
        })
        .expect("valid settings");
        let mut group = c.benchmark_group(format!("cpu_{}", method.name()));
        group
            .sample_size(10)
            .warm_up_time(Duration::from_millis(300))
            .measurement_time(Duration::from_secs(1));
        for (n, lcps) in &sets {
            group.throughput(Throughput::Elements(lcps.len() as u64));
            group.bench_with_input(BenchmarkId::from_parameter(n), lcps, |b, lcps| {
                b.iter(|| black_box(solver.solve_lcps(black_box(lcps)).expect("solvable")))
            });
        }
        group.finish();
    }
}

criterion_group!(benches, bench_solvers);
criterion_main!(benches);
