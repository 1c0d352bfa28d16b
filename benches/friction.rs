//! CPU throughput of the exact Coulomb solvers on fixed-seed frictional
//! islands of k = 1…16 contacts (src/generate/friction.rs: boxes resting
//! and sliding at k = 4, stacks at k = 4, 8, 12, 16, random spheres and
//! boxes at every k), 1000 islands per set for k ≤ 4 and 200 above, through
//! the library's `Solver::solve_friction` (checks and report included):
//! `auto` (NSGS then Alart–Curnier Newton) on one thread and on every core,
//! `nsgs` on one thread for k ≤ 8 (above, its sweeps take seconds per
//! batch). Before each group
//! it prints, per set, the largest Coulomb error reached and the statuses,
//! so that islands/s can be read against the error. Throughput is in
//! islands per second. Groups are small (10 samples, 1 s).

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lcpbatch::generate::friction::{friction_batch, FrictionFamily};
use lcpbatch::{Backend, FrictionMethod, FrictionProblem, Settings, Solver, Status};

const ISLANDS: usize = 1000;
const SIZES: [usize; 7] = [1, 2, 3, 4, 8, 12, 16];

fn sets() -> Vec<(String, Vec<FrictionProblem>)> {
    let mut out = Vec::new();
    for family in FrictionFamily::ALL {
        for k in SIZES {
            let count = if k <= 4 { ISLANDS } else { ISLANDS / 5 };
            if let Some(batch) = friction_batch(family, k, 0xF1C7, count) {
                out.push((format!("{}/k={k}", family.name()), batch));
            }
        }
    }
    out
}

fn bench_friction(c: &mut Criterion) {
    let all = sets();
    for (method, threads, max_k, label) in [
        (FrictionMethod::Auto, 1, 16, "auto"),
        (FrictionMethod::Auto, 0, 4, "auto_all_cores"),
        (FrictionMethod::Nsgs, 1, 8, "nsgs"),
    ] {
        let sets: Vec<&(String, Vec<FrictionProblem>)> = all
            .iter()
            .filter(|(_, b)| b[0].contacts() <= max_k)
            .collect();
        let mut solver = Solver::new(Settings {
            threads,
            friction_method: method,
            ..Settings::new(Backend::Cpu, lcpbatch::Method::Auto)
        })
        .expect("valid settings");
        for (name, batch) in &sets {
            let r = solver.solve_friction(batch).expect("valid problems");
            let solved = r
                .friction
                .iter()
                .filter(|i| i.status() == Status::Solved)
                .count();
            let max_error = r.friction.iter().map(|i| i.error()).fold(0.0f64, f64::max);
            let iterations: u64 = r.friction.iter().map(|i| i.solution.iterations).sum();
            eprintln!(
                "friction_{label} {name}: solved {solved}/{}, max Coulomb error {max_error:.2e}, mean iterations {:.1}",
                batch.len(),
                iterations as f64 / batch.len() as f64
            );
        }
        let mut group = c.benchmark_group(format!("friction_{label}"));
        group
            .sample_size(10)
            .warm_up_time(Duration::from_millis(300))
            .measurement_time(Duration::from_secs(1));
        for (name, batch) in sets {
            group.throughput(Throughput::Elements(batch.len() as u64));
            group.bench_with_input(BenchmarkId::from_parameter(name), batch, |b, batch| {
                b.iter(|| black_box(solver.solve_friction(black_box(batch)).expect("valid")))
            });
        }
        group.finish();
    }
}

criterion_group!(benches, bench_friction);
criterion_main!(benches);
