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
//! islands per second. Groups are small (10 samples, 1 s). One thread is
//! timed by its CPU time (as `benches/world.rs` does: other processes on a
//! shared machine slow it less), every core by the wall clock.
//!
//! `friction_warm_stack`: the 16-contact islands of 4-box stack worlds
//! (μ = 0.5, Δt = 0.01, boxes offset by up to 2 cm, after 30 steps), solved
//! by `solve_friction_problem` on one thread from the previous step's
//! reactions (by contact id) and from zero; `world_stack4`: 200 such
//! worlds stepped by `Solver::step_worlds` with warm start, one thread
//! (world-steps per second).

use std::hint::black_box;
use std::time::Duration;

#[path = "common/cpu_time.rs"]
mod cpu_time;
use cpu_time::time_steps;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use std::collections::HashMap;

use lcpbatch::friction::{solve_friction_problem, FrictionSettings};
use lcpbatch::generate::friction::{friction_batch, FrictionFamily};
use lcpbatch::generate::Rng;
use lcpbatch::internals::{friction_islands, prepare};
use lcpbatch::world::generate::{standard_world, WorldKind};
use lcpbatch::{Backend, FrictionMethod, FrictionProblem, Settings, Solver, Status, World};

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
                b.iter_custom(|iters| {
                    time_steps(iters, threads == 1, || {
                        black_box(solver.solve_friction(black_box(batch)).expect("valid"));
                    })
                })
            });
        }
        group.finish();
    }
}

const DT: f64 = 0.01;

/// `count` 4-box stack worlds, each box offset in x and z by up to 2 cm
/// (seeded), stepped `settle` times on one thread with warm start.
fn stack_worlds(count: usize, settle: usize) -> (Vec<World>, Solver) {
    let mut rng = Rng::new(0x57AC);
    let mut worlds: Vec<World> = (0..count)
        .map(|_| {
            let mut w = standard_world(WorldKind::Stack, 4, 0);
            for b in w.bodies.iter_mut().filter(|b| !b.fixed) {
                b.position[0] += rng.range(-0.02, 0.02);
                b.position[2] += rng.range(-0.02, 0.02);
            }
            w
        })
        .collect();
    let mut solver = Solver::new(Settings {
        threads: 1,
        warm_start: true,
        ..Settings::new(Backend::Cpu, lcpbatch::Method::Auto)
    })
    .expect("valid settings");
    for _ in 0..settle {
        solver.step_worlds(&mut worlds, DT).expect("valid worlds");
    }
    (worlds, solver)
}

/// Each world's frictional islands this step with the contact ids.
fn islands_of(worlds: &[World]) -> Vec<(FrictionProblem, Vec<u64>)> {
    let mut out = Vec::new();
    for (i, w) in worlds.iter().enumerate() {
        let scene = prepare(w, i, DT).scene;
        for isl in friction_islands(&scene) {
            let ids = isl
                .contacts
                .iter()
                .map(|&c| scene.contacts[c].id.expect("world ids"))
                .collect();
            out.push((isl.problem, ids));
        }
    }
    out
}

/// The islands of the step after `settle` steps, each with its warm start:
/// the previous step's reactions (solved to the default tolerance) by
/// contact id, zero for a new contact.
fn warm_stack_islands(count: usize, settle: usize) -> Vec<(FrictionProblem, Vec<f64>)> {
    let (mut worlds, mut solver) = stack_worlds(count, settle);
    let s = FrictionSettings::default();
    let mut last: HashMap<u64, [f64; 3]> = HashMap::new();
    for (p, ids) in islands_of(&worlds) {
        let r = solve_friction_problem(&p, None, &s).r;
        for (i, id) in ids.iter().enumerate() {
            last.insert(*id, [r[3 * i], r[3 * i + 1], r[3 * i + 2]]);
        }
    }
    solver.step_worlds(&mut worlds, DT).expect("valid worlds");
    islands_of(&worlds)
        .into_iter()
        .map(|(p, ids)| {
            let warm = ids
                .iter()
                .flat_map(|id| last.get(id).copied().unwrap_or([0.0; 3]))
                .collect();
            (p, warm)
        })
        .collect()
}

fn bench_warm_stack(c: &mut Criterion) {
    let islands = warm_stack_islands(200, 30);
    let mut start: Vec<f64> = islands
        .iter()
        .map(|(p, w)| lcpbatch::friction::coulomb_error(p, w))
        .collect();
    start.sort_by(f64::total_cmp);
    eprintln!(
        "friction_warm_stack: Coulomb error of the warm starts: median {:.2e}, 90 % {:.2e}, max {:.2e}",
        start[start.len() / 2],
        start[start.len() * 9 / 10],
        start[start.len() - 1]
    );
    let mut group = c.benchmark_group("friction_warm_stack");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
        .throughput(Throughput::Elements(islands.len() as u64));
    for (label, method, tolerance, warm) in [
        ("auto_warm", FrictionMethod::Auto, 1e-8, true),
        ("auto_cold", FrictionMethod::Auto, 1e-8, false),
        ("auto_warm_tol1e-12", FrictionMethod::Auto, 1e-12, true),
        ("nsgs_warm", FrictionMethod::Nsgs, 1e-8, true),
    ] {
        let s = FrictionSettings {
            method,
            tolerance,
            ..FrictionSettings::default()
        };
        let run = || {
            islands
                .iter()
                .map(|(p, w)| solve_friction_problem(p, warm.then_some(w.as_slice()), &s))
                .collect::<Vec<_>>()
        };
        let out = run();
        let solved = out.iter().filter(|o| o.status == Status::Solved).count();
        let max_error = out
            .iter()
            .map(|o| o.residuals.coulomb_error)
            .fold(0.0, f64::max);
        let none = out.iter().filter(|o| o.iterations == 0).count();
        let iterations: u64 = out.iter().map(|o| o.iterations).sum();
        eprintln!(
            "friction_warm_stack {label}: k = {}, solved {solved}/{}, max Coulomb error {max_error:.2e}, start accepted {none}, mean iterations {:.1}",
            islands[0].0.contacts(),
            out.len(),
            iterations as f64 / out.len() as f64
        );
        group.bench_function(label, |b| b.iter(|| black_box(run())));
    }
    group.finish();
    let (mut worlds, mut solver) = stack_worlds(200, 30);
    let mut group = c.benchmark_group("world_stack4");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
        .throughput(Throughput::Elements(worlds.len() as u64));
    group.bench_function("step_worlds_warm_1_thread", |b| {
        b.iter(|| black_box(solver.step_worlds(&mut worlds, DT).expect("valid")))
    });
    group.finish();
}

criterion_group!(benches, bench_warm_stack, bench_friction);
criterion_main!(benches);
