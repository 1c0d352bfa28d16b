//! Worlds in time: world-steps per second of `Solver::step_worlds` on the
//! CPU (f64, warm start on, as `lcpbatch simulate` runs), for N = 1, 100 and
//! 1000 copies of the standard worlds `stack:4` (frictionless and μ = 0.5),
//! `slide` (μ = 0.5) and `spheres:8` (frictionless), on one thread and on
//! every core. Each world is first stepped 50 times (0.5 s: the spheres land,
//! warm start fills), then each iteration is one step of the whole batch;
//! throughput is in world-steps per second (criterion's elem/s).
//!
//! Before each group it prints, per batch, where one step's time goes (from
//! the step report, averaged over 10 steps): collision, the door's checks
//! and assembly, the LCP or Coulomb solves, impulses, integration, and the
//! islands left unsolved. Groups are small (10 samples, 1 s).
//!
//! Frictionless cases also get a row `resident_gpu_wall` at 100 and 1000
//! worlds where a GPU with SHADER_F64 opens (`Backend::Gpu`: the resident
//! path, `src/solver/world_gpu.rs`; states read back every step, as
//! `step_worlds` returns them); skipped, with a line, elsewhere.
//!
//! On one thread the time measured is the thread's CPU time (Linux
//! `/proc/thread-self/schedstat`, ns; wall time elsewhere), so that other
//! processes on a shared machine slow the figure less; on every core it is
//! wall time. Compare ratios within one run.

use std::hint::black_box;
use std::time::Duration;

#[path = "common/cpu_time.rs"]
mod cpu_time;
use cpu_time::time_steps;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use lcpbatch::world::generate::{standard_world, WorldKind};
use lcpbatch::{Backend, Method, Settings, Solver, StepReport, World};

const DT: f64 = 0.01;
const COUNTS: [usize; 3] = [1, 100, 1000];

/// One bench case: a name, the world kind and size, μ for every body
/// (None: the kind's own).
struct Case {
    name: &'static str,
    kind: WorldKind,
    size: usize,
    friction: Option<f64>,
}

const CASES: [Case; 4] = [
    Case {
        name: "stack4_frictionless",
        kind: WorldKind::Stack,
        size: 4,
        friction: Some(0.0),
    },
    Case {
        name: "stack4_mu0.5",
        kind: WorldKind::Stack,
        size: 4,
        friction: Some(0.5),
    },
    Case {
        name: "slide_mu0.5",
        kind: WorldKind::Slide,
        size: 1,
        friction: Some(0.5),
    },
    Case {
        name: "spheres8_frictionless",
        kind: WorldKind::Spheres,
        size: 8,
        friction: Some(0.0),
    },
];

fn worlds(case: &Case, count: usize) -> Vec<World> {
    (0..count)
        .map(|k| {
            let mut w = standard_world(case.kind, case.size, 1 + k as u64);
            if let Some(mu) = case.friction {
                w.bodies.iter_mut().for_each(|b| b.friction = mu);
            }
            w
        })
        .collect()
}

fn solver(threads: usize) -> Solver {
    Solver::new(Settings {
        threads,
        warm_start: true,
        // What `lcpbatch simulate` uses: keeps heavy stacks at rest and a
        // sliding box on the ground (the tests' bounds).
        friction_tolerance: 1e-12,
        ..Settings::new(Backend::Cpu, Method::Auto)
    })
    .expect("valid settings")
}

/// A solver on the GPU (the resident path for frictionless worlds).
fn gpu_solver() -> Solver {
    Solver::new(Settings {
        warm_start: true,
        warn_on_stderr: false,
        ..Settings::new(Backend::Gpu, Method::Auto)
    })
    .expect("valid settings")
}

/// Where a step's time goes, in words, from `reports` (one per step).
fn phases(reports: &[StepReport]) -> String {
    let sum = |f: &dyn Fn(&StepReport) -> f64| reports.iter().map(f).sum::<f64>();
    let total = sum(&|r| r.timings.collision + r.timings.solve + r.timings.integrate);
    let part = |x: f64| 100.0 * x / total;
    let collision = sum(&|r| r.timings.collision);
    let build = sum(&|r| r.solve.timings.build);
    let solves = sum(&|r| {
        r.solve.timings.prediction
            + r.solve.timings.gpu
            + r.solve.timings.validation
            + r.solve.timings.solve
    });
    let impulses = sum(&|r| r.solve.timings.impulses);
    let door = sum(&|r| r.timings.solve);
    let integrate = sum(&|r| r.timings.integrate);
    let unsolved: usize = reports.iter().map(|r| r.unsolved).sum();
    let last = &reports[reports.len() - 1].solve;
    let paths: Vec<String> = last
        .counts
        .nonzero()
        .iter()
        .map(|(p, n)| format!("{p} {n}"))
        .collect();
    format!(
        "{:.1} µs/step: collision {:.0}%, door {:.0}% (checks+islands+assembly {:.0}%, solves {:.0}%, impulses {:.0}%, rest {:.0}%), integrate {:.0}%; unsolved islands {unsolved}; last step's paths: {}, frictional islands {}",
        1e6 * total / reports.len() as f64,
        part(collision),
        part(door),
        part(build),
        part(solves),
        part(impulses),
        part(door - build - solves - impulses),
        part(integrate),
        paths.join(", "),
        last.friction.len(),
    )
}

/// The first argument that is not an option: criterion's filter. Cases it
/// does not name are skipped before their (slow) setup and phase print.
fn filter() -> Option<String> {
    std::env::args().skip(1).find(|a| !a.starts_with('-'))
}

fn bench_worlds(c: &mut Criterion) {
    let wanted = |id: &str| filter().is_none_or(|f| id.contains(f.as_str()));
    for case in &CASES {
        let mut group = c.benchmark_group(case.name);
        group
            .sample_size(10)
            .warm_up_time(Duration::from_millis(300))
            .measurement_time(Duration::from_secs(1));
        for count in COUNTS {
            let rows = [
                (Some(1), "1_thread_cpu_time"),
                (Some(0), "all_cores_wall"),
                (None, "resident_gpu_wall"),
            ];
            for (threads, label) in rows {
                let resident = threads.is_none();
                if !wanted(&format!("{}/{label}/{count}", case.name))
                    || (resident && (case.friction != Some(0.0) || count < 100))
                {
                    continue;
                }
                let mut s = threads.map_or_else(gpu_solver, solver);
                let mut batch = worlds(case, count);
                for _ in 0..50 {
                    s.step_worlds(&mut batch, DT).expect("valid worlds");
                }
                let reports: Vec<StepReport> = (0..10)
                    .map(|_| s.step_worlds(&mut batch, DT).expect("valid worlds"))
                    .collect();
                if resident && reports[0].resident.is_none() {
                    println!(
                        "{}/{label}/{count}: skipped (no GPU with SHADER_F64)",
                        case.name
                    );
                    continue;
                }
                println!("{}/{label}/{count}: {}", case.name, phases(&reports));
                group.throughput(Throughput::Elements(count as u64));
                group.bench_with_input(BenchmarkId::new(label, count), &count, |b, _| {
                    b.iter_custom(|iters| {
                        time_steps(iters, threads == Some(1), || {
                            black_box(s.step_worlds(&mut batch, DT).expect("valid worlds"));
                        })
                    })
                });
            }
        }
        group.finish();
    }
}

criterion_group!(benches, bench_worlds);
criterion_main!(benches);
