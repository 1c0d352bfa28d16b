//! Worlds resident on the GPU (`shaders/world_step.wgsl`,
//! `src/gpu/resident/`, `src/solver/world_gpu.rs`) against the CPU path:
//! in f64 on lavapipe the trajectories of frictionless stacks and spheres
//! (restitution 0) equal the CPU path's within 1e-9 m, step after step,
//! with the same per-world figures; pyramids (islands above 16 contacts)
//! are flagged and follow the CPU's trajectory; states come back bit for
//! bit; a world that overflows its contact slots is flagged, keeps its
//! state on the device and is stepped on the CPU with the CPU's trajectory.
//! Skipped without an f64 adapter (`super::skip`).

use super::common::gpu_settings_or_skip;
use crate::gpu::resident::layout::flags;
use crate::gpu::resident::ResidentWorlds;
use crate::gpu::{GpuContext, GpuOptions, Precision};
use crate::solver::world_gpu::set_test_slots;
use crate::world::generate::{standard_world, WorldKind};
use crate::world::World;
use crate::{Backend, GpuSettings, Method, Settings, Solver};

/// The GPU settings in f64, or None (skipped) without an f64 adapter.
pub(super) fn f64_gpu() -> Option<GpuSettings> {
    let g = gpu_settings_or_skip()?;
    (g.precision == Precision::F64).then_some(g)
}

/// A context in f64 (the caller has checked that the adapter has it).
fn f64_context() -> GpuContext {
    GpuContext::new(&GpuOptions {
        precision: Precision::F64,
        ..GpuOptions::from_env().unwrap()
    })
    .unwrap()
}

fn solver(backend: Backend, gpu: GpuSettings) -> Solver {
    Solver::new(settings(backend, gpu)).unwrap()
}

/// Settings of both paths' solvers: warm starts, no warning lines.
pub(super) fn settings(backend: Backend, gpu: GpuSettings) -> Settings {
    Settings {
        gpu,
        warm_start: true,
        warn_on_stderr: false,
        ..Settings::new(backend, Method::Auto)
    }
}

/// `kind:size` worlds, frictionless, restitution 0, seeds 0..count.
pub(super) fn frictionless(kind: WorldKind, size: usize, count: usize) -> Vec<World> {
    (0..count as u64)
        .map(|seed| {
            let mut w = standard_world(kind, size, seed);
            for b in &mut w.bodies {
                b.friction = 0.0;
                b.restitution = 0.0;
            }
            w
        })
        .collect()
}

/// Largest distance between the bodies' positions of two batches.
pub(super) fn max_distance(a: &[World], b: &[World]) -> f64 {
    (a.iter().zip(b))
        .flat_map(|(wa, wb)| wa.bodies.iter().zip(&wb.bodies))
        .map(|(x, y)| (x.position() - y.position()).length())
        .fold(0.0, f64::max)
}

/// Steps `worlds` `steps` times on the resident path and on the CPU path:
/// positions within 1e-9 m and the same contacts, islands and awake
/// bodies after every step, energies within 1e-9 relative. Returns the worlds
/// the kernel stepped and those it left to the CPU, over all steps.
fn compare(worlds: Vec<World>, steps: usize, gpu: GpuSettings) -> (usize, usize) {
    compare_with(worlds, steps, settings(Backend::Gpu, gpu))
}

/// [`compare`] with these settings (`s.backend` Gpu; the CPU path's
/// solver takes them with `Backend::Cpu`).
pub(super) fn compare_with(worlds: Vec<World>, steps: usize, s: Settings) -> (usize, usize) {
    let (device, host, _) = compare_within(worlds, steps, s, 1e-9);
    (device, host)
}

/// [`compare_with`] with positions within `bound` (m) instead of 1e-9;
/// above 1e-9 the energies and awake bodies are not compared (a
/// displacement of `bound` moves the potential energy by m|g| `bound`).
/// Returns also the largest distance seen.
fn compare_within(
    worlds: Vec<World>,
    steps: usize,
    s: Settings,
    bound: f64,
) -> (usize, usize, f64) {
    let mut on_gpu = worlds.clone();
    let mut on_cpu = worlds;
    let cpu = Settings {
        backend: Backend::Cpu,
        gpu: GpuSettings::default(),
        ..s.clone()
    };
    let mut g = Solver::new(s).unwrap();
    let mut c = Solver::new(cpu).unwrap();
    let (mut device, mut host, mut largest) = (0, 0, 0.0f64);
    let strict = bound <= 1e-9;
    for step in 0..steps {
        let rg = g.step_worlds(&mut on_gpu, 0.01).unwrap();
        let rc = c.step_worlds(&mut on_cpu, 0.01).unwrap();
        let r = rg.resident.expect("the resident path ran");
        device += r.on_device;
        host += r.on_cpu;
        let d = max_distance(&on_gpu, &on_cpu);
        largest = largest.max(d);
        assert!(d < bound, "step {step}: positions differ by {d} m");
        for (k, (a, b)) in rg.worlds.iter().zip(&rc.worlds).enumerate() {
            let same = (a.contacts, a.islands) == (b.contacts, b.islands);
            assert!(same, "step {step}, world {k}: {a:?} vs {b:?}");
            if !strict {
                continue;
            }
            assert_eq!(a.awake, b.awake, "step {step}, world {k}");
            let close = |x: f64, y: f64| (x - y).abs() <= 1e-9 * x.abs().max(1.0);
            let same = close(a.kinetic, b.kinetic) && close(a.potential, b.potential);
            assert!(same, "step {step}, world {k}: energies {a:?} vs {b:?}");
            assert!((a.max_penetration - b.max_penetration).abs() < 1e-9);
        }
        assert_eq!(rg.unsolved, rc.unsolved);
    }
    (device, host, largest)
}

#[test]
fn resident_stacks_follow_the_cpu_path_for_500_steps() {
    let Some(gpu) = f64_gpu() else { return };
    // Stacks of 4, 2 and 3 boxes in one batch.
    let mut worlds = frictionless(WorldKind::Stack, 4, 1);
    worlds.extend(frictionless(WorldKind::Stack, 2, 1));
    worlds.extend(frictionless(WorldKind::Stack, 3, 1));
    let (device, host) = compare(worlds, 500, gpu);
    assert_eq!(host, 0, "every world on the device");
    assert_eq!(device, 1500);
}

#[test]
fn resident_spheres_and_pyramids_follow_the_cpu_path() {
    let Some(gpu) = f64_gpu() else { return };
    let (device, host) = compare(frictionless(WorldKind::Spheres, 8, 4), 300, gpu.clone());
    assert_eq!((device, host), (1200, 0));
    // A pyramid of 3 boxes is one island of 20 contacts (the bottom two
    // touch side by side): flagged, stepped on the CPU.
    let (device, host) = compare(frictionless(WorldKind::Pyramid, 2, 2), 50, gpu);
    assert_eq!((device, host), (0, 100));
}

/// Sleeping bodies woken through a chain of contacts (`world_collide`'s
/// rounds, one body further down per round, and the bodies an awake one can
/// reach): stacks asleep but for their top box, which falls onto the next.
#[test]
fn stacks_woken_from_the_top_follow_the_cpu_path() {
    let Some(gpu) = f64_gpu() else { return };
    let mut worlds = frictionless(WorldKind::Stack, 4, 2);
    for w in &mut worlds {
        let top = w.bodies.len() - 1;
        for b in w.bodies.iter_mut().filter(|b| !b.fixed) {
            b.asleep = true;
        }
        w.bodies[top].asleep = false;
        w.bodies[top].position[1] += 0.05;
    }
    // The CPU path wakes every box of both stacks within the steps compared.
    let mut on_cpu = worlds.clone();
    let mut c = solver(Backend::Cpu, GpuSettings::default());
    let woken = (0..60).any(|_| {
        let r = c.step_worlds(&mut on_cpu, 0.01).unwrap();
        r.worlds.iter().all(|w| w.awake == 4)
    });
    assert!(woken, "the stacks stayed asleep");
    let (device, host) = compare(worlds, 60, gpu);
    assert_eq!((device, host), (120, 0));
}

/// A warm basis that no longer holds: 4-box stacks at rest on the device,
/// then the top box given 0.5 m/s upwards (written as the host writes a
/// world it stepped): its contacts keep their ids, so last step's bases
/// hint that they push. The kernel sets the hint aside (block pivots or
/// Lemke's path), steps every world itself through the flight and the
/// landing, and follows the CPU path from the same states within 1e-9 m.
/// Lemke's path runs only in the steps that need it: both worlds go to
/// `world_lemke` in the first step (no warm basis yet), none while they
/// rest, some again after the kick.
#[test]
fn a_warm_basis_that_no_longer_holds_is_set_aside() {
    if f64_gpu().is_none() {
        return;
    }
    let ctx = f64_context();
    let worlds = frictionless(WorldKind::Stack, 4, 2);
    let settings = Settings::default();
    let r =
        ResidentWorlds::new(&ctx, &worlds, 1e-8, &settings.gpu_solve(), true, None, None).unwrap();
    let mut on_gpu = worlds.clone();
    let mut on_cpu = worlds;
    let mut c = solver(Backend::Cpu, GpuSettings::default());
    let mut kicked = 0;
    for step in 0..40 {
        if step == 20 {
            for (k, w) in on_cpu.iter_mut().enumerate() {
                let top = w.bodies.len() - 1;
                w.bodies[top].velocity[1] = 0.5;
                r.write_world(&ctx, k, w).unwrap();
            }
        }
        let records = r.step(&ctx, 0.01).unwrap();
        c.step_worlds(&mut on_cpu, 0.01).unwrap();
        assert!(
            records.iter().all(|x| x.flags == 0),
            "step {step}: {records:?}"
        );
        let deferred = r.deferred_worlds(&ctx).unwrap();
        match step {
            0 => assert_eq!(deferred, 2),
            2..20 => assert_eq!(deferred, 0, "step {step}"),
            _ => kicked += deferred,
        }
        r.read_states(&ctx, &mut on_gpu).unwrap();
        let d = max_distance(&on_gpu, &on_cpu);
        assert!(d < 1e-9, "step {step}: positions differ by {d} m");
    }
    assert!(kicked > 0);
    // The top boxes flew and landed.
    let top = |w: &World| w.bodies[w.bodies.len() - 1].position[1];
    let rest = frictionless(WorldKind::Stack, 4, 2);
    assert!(on_gpu
        .iter()
        .zip(&rest)
        .all(|(a, b)| (top(a) - top(b)).abs() < 1e-3));
}

#[test]
fn states_come_back_bit_for_bit() {
    if f64_gpu().is_none() {
        return;
    }
    let ctx = f64_context();
    let mut worlds = frictionless(WorldKind::Spheres, 5, 2);
    worlds.extend(frictionless(WorldKind::Stack, 3, 1));
    worlds[0].bodies[1].velocity = [0.1, -0.2, 1e-300];
    worlds[0].bodies[2].asleep = true;
    worlds[0].bodies[2].quiet_steps = 9;
    worlds[2].bodies[1].orientation = [0.1, 0.2, 0.3, 0.9];
    let settings = Settings::default();
    let r =
        ResidentWorlds::new(&ctx, &worlds, 1e-8, &settings.gpu_solve(), true, None, None).unwrap();
    let mut back = worlds.clone();
    for b in back.iter_mut().flat_map(|w| w.bodies.iter_mut()) {
        b.position = [0.0; 3];
        b.orientation = [0.0, 0.0, 0.0, 1.0];
        b.velocity = [1.0; 3];
        b.asleep = false;
        b.quiet_steps = 3;
    }
    r.read_states(&ctx, &mut back).unwrap();
    assert_eq!(back, worlds);
    // Another batch's shape is refused.
    assert!(r.read_states(&ctx, &mut back[..1]).is_err());
}

#[test]
fn a_world_past_its_contact_slots_is_flagged_and_stepped_on_the_cpu() {
    let Some(gpu) = f64_gpu() else { return };
    let ctx = f64_context();
    // Stack of 2 at rest: 8 contacts; 6 slots cannot hold them.
    let worlds = frictionless(WorldKind::Stack, 2, 2);
    let settings = Settings::default();
    let r = ResidentWorlds::new(
        &ctx,
        &worlds,
        1e-8,
        &settings.gpu_solve(),
        true,
        None,
        Some(6),
    )
    .unwrap();
    let records = r.step(&ctx, 0.01).unwrap();
    assert!(records.iter().all(|x| x.flags & flags::CONTACTS_FULL != 0));
    // The device kept the state of a flagged world.
    let mut back = worlds.clone();
    r.read_states(&ctx, &mut back).unwrap();
    assert_eq!(back, worlds);
    // Through the door, with 6 slots: every step on the CPU, the CPU's
    // trajectory bit for bit.
    set_test_slots(Some(6));
    let mut on_gpu = worlds.clone();
    let mut on_cpu = worlds;
    let mut g = solver(Backend::Gpu, gpu);
    let mut c = solver(Backend::Cpu, GpuSettings::default());
    for _ in 0..200 {
        let rg = g.step_worlds(&mut on_gpu, 0.01).unwrap();
        c.step_worlds(&mut on_cpu, 0.01).unwrap();
        let f = rg.resident.unwrap();
        assert_eq!((f.on_device, f.on_cpu, f.contacts_full), (0, 2, 2));
    }
    set_test_slots(None);
    assert_eq!(on_gpu, on_cpu);
}

/// Where the kernel's time goes: 1,000 frictionless 4-box stacks, each
/// command of a step timed apart over 20 steps (`cargo test --release
/// resident_kernel_times -- --ignored --nocapture`): per command the
/// median over steps 5 to 19 (the warm bases in place) of its wall ms and
/// of the CPU ms of the whole process over it (lavapipe runs the kernels
/// on threads of its own; on a loaded machine the CPU time moves less than
/// the wall time); then the same steps in one submission each.
#[test]
#[ignore = "a measurement, not a check"]
fn resident_kernel_times() {
    if f64_gpu().is_none() {
        return;
    }
    let ctx = f64_context();
    let worlds = frictionless(WorldKind::Stack, 4, 1000);
    let settings = Settings::default();
    let r =
        ResidentWorlds::new(&ctx, &worlds, 1e-8, &settings.gpu_solve(), true, None, None).unwrap();
    r.time_kernels(&ctx, 0.01, process_cpu_ms).unwrap();
    let mut steps = Vec::new();
    for step in 0..20 {
        let times = r.time_kernels(&ctx, 0.01, process_cpu_ms).unwrap();
        if step >= 5 {
            steps.push(times);
        }
    }
    let median = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let mut total = [0.0; 2];
    for (k, (name, _)) in steps[0].iter().enumerate() {
        let wall = median(steps.iter().map(|s| 1e3 * s[k].1[0]).collect());
        let cpu = median(steps.iter().map(|s| s[k].1[1]).collect());
        total = [total[0] + wall, total[1] + cpu];
        println!("{name}: {wall:.2} ms (CPU {cpu:.2} ms)");
    }
    println!(
        "sum of the medians: {:.1} ms (CPU {:.1} ms)",
        total[0], total[1]
    );
    let whole: Vec<f64> = (0..15)
        .map(|_| {
            let start = std::time::Instant::now();
            r.step(&ctx, 0.01).unwrap();
            1e3 * start.elapsed().as_secs_f64()
        })
        .collect();
    println!("one submission a step: median {:.1} ms", median(whole));
}

/// CPU ms of every thread of this process so far (Linux
/// `/proc/self/task/*/schedstat`; 0 elsewhere).
fn process_cpu_ms() -> f64 {
    let Ok(tasks) = std::fs::read_dir("/proc/self/task") else {
        return 0.0;
    };
    let ns: u64 = tasks
        .filter_map(|t| std::fs::read_to_string(t.ok()?.path().join("schedstat")).ok())
        .filter_map(|s| s.split_whitespace().next()?.parse::<u64>().ok())
        .sum();
    ns as f64 * 1e-6
}

/// The device is lost in the middle of a run: the step that finds it is
/// taken by the CPU path from the last good state, and the trajectory is
/// the CPU's (within 1e-9 m: the steps before ran on the device).
#[test]
fn a_device_lost_mid_run_hands_the_worlds_to_the_cpu() {
    let Some(gpu) = f64_gpu() else { return };
    let worlds = frictionless(WorldKind::Spheres, 4, 2);
    let mut on_gpu = worlds.clone();
    let mut on_cpu = worlds;
    let mut g = solver(Backend::Gpu, gpu);
    let mut c = solver(Backend::Cpu, GpuSettings::default());
    for step in 0..60 {
        if step == 30 {
            g.shared_device().unwrap().simulate_device_loss();
        }
        let r = g.step_worlds(&mut on_gpu, 0.01).unwrap();
        c.step_worlds(&mut on_cpu, 0.01).unwrap();
        assert_eq!(r.resident.is_some(), step < 30, "step {step}");
        let d = max_distance(&on_gpu, &on_cpu);
        assert!(d < 1e-9, "step {step}: {d} m");
    }
    assert!(g.fallback().is_some());
}
