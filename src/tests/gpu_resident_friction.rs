//! Worlds with friction resident on the GPU (`shaders/world_friction.wgsl`,
//! `world_apgd.wgsl`) against the CPU path with the same projected method
//! (`pgs`, `jacobi`, `apgd`): in f64 on lavapipe, μ = 0.5 stacks of 2–4
//! boxes, a sliding box and boxes on inclines follow the CPU's trajectory
//! within 1e-9 m over 300–500 steps with the same contacts, islands and
//! awake bodies every step; a world whose island misses the tolerance is
//! flagged (NOT_SOLVED) and follows the CPU's trajectory. Skipped without
//! an f64 adapter.

use super::gpu_resident::{compare_with, f64_gpu, frictionless, max_distance};
use crate::friction::FrictionMethod;
use crate::friction::FrictionMethod::Apgd;
use crate::gpu::resident::layout::flags;
use crate::gpu::resident::{WorldRecord, MAX_ROUNDS};
use crate::solver::world_gpu::next_rounds;
use crate::world::generate::{incline, standard_world, WorldKind};
use crate::world::World;
use crate::{Backend, GpuSettings, Method, Settings, Solver};

/// `kind:size` worlds with μ = 0.5 on every body, restitution 0.
pub(super) fn frictional(kind: WorldKind, size: usize, count: usize) -> Vec<World> {
    let mut worlds = frictionless(kind, size, count);
    for b in worlds.iter_mut().flat_map(|w| w.bodies.iter_mut()) {
        b.friction = 0.5;
    }
    worlds
}

/// Both paths' settings: `method`, warm starts as given.
pub(super) fn settings(gpu: GpuSettings, method: FrictionMethod, warm_start: bool) -> Settings {
    Settings {
        gpu,
        warm_start,
        friction_method: method,
        warn_on_stderr: false,
        ..Settings::new(Backend::Gpu, Method::Auto)
    }
}

/// Stacks of 4, 2 and 3 boxes in one batch within 1e-9 m for 500 steps
/// (until the loops took three entries per iteration, the 4-box stack
/// left the CPU's trajectory by about 3 µm batched so). Tolerance 1e-6:
/// Gauss–Seidel sweeps stall short of 1e-8 on a cold 4-box stack within
/// the 1,000 sweeps (on the CPU too: every step unsolved).
#[test]
fn resident_frictional_stacks_follow_the_cpu_path_for_500_steps() {
    let Some(gpu) = f64_gpu() else { return };
    let mut worlds = frictional(WorldKind::Stack, 4, 1);
    worlds.extend(frictional(WorldKind::Stack, 2, 1));
    worlds.extend(frictional(WorldKind::Stack, 3, 1));
    let s = Settings {
        friction_tolerance: 1e-6,
        ..settings(gpu, FrictionMethod::Pgs, false)
    };
    let (device, host) = compare_with(worlds, 500, s);
    println!("pgs stacks of 4, 2, 3: {device} on the device, {host} on the CPU");
    assert_eq!(device + host, 1500);
    assert!(device >= 1400, "{device} on the device");
}

/// A loop budget far past llvmpipe's loop limit (a quarter of 1e6 loop
/// iterations per invocation and round): where the limit cuts the loops
/// short, `loops_left` flags the worlds and the CPU steps them, so the
/// trajectory stays the CPU's (on lavapipe every world-step went to the
/// CPU; without such a limit, none).
#[test]
fn the_loop_limit_flags_worlds_and_never_gives_wrong_steps() {
    let Some(gpu) = f64_gpu() else { return };
    let mut worlds = frictional(WorldKind::Stack, 4, 1);
    worlds.extend(frictional(WorldKind::Stack, 2, 1));
    worlds.extend(frictional(WorldKind::Stack, 3, 1));
    let gpu = GpuSettings {
        round_budget: Some(1_000_000),
        ..gpu
    };
    let s = Settings {
        friction_tolerance: 1e-6,
        ..settings(gpu, FrictionMethod::Pgs, false)
    };
    let (device, host) = compare_with(worlds, 30, s);
    println!("past the limit: {device} on the device, {host} on the CPU");
    assert_eq!(device + host, 90);
}

#[test]
fn resident_sliding_and_inclined_boxes_follow_the_cpu_path() {
    let Some(gpu) = f64_gpu() else { return };
    let worlds = vec![
        standard_world(WorldKind::Slide, 1, 0),
        standard_world(WorldKind::Incline, 1, 0),
        incline(30f64.to_radians(), 0.3, 0.5),
    ];
    for method in [FrictionMethod::Pgs, FrictionMethod::Jacobi] {
        let s = settings(gpu.clone(), method, false);
        let (device, host) = compare_with(worlds.clone(), 500, s);
        println!("{method:?}: {device} world-steps on the device, {host} on the CPU");
        assert_eq!(device + host, 1500);
        assert!(device >= 1400, "{method:?}: {device} on the device");
    }
}

/// Two sweeps cannot bring a cold 3-box stack within 1e-8: its island is
/// not solved on either path; the resident path flags it, the CPU steps
/// it (and repairs the island as the CPU path does), same trajectory.
#[test]
fn a_frictional_world_that_misses_the_tolerance_is_stepped_on_the_cpu() {
    let Some(gpu) = f64_gpu() else { return };
    let worlds = frictional(WorldKind::Stack, 3, 2);
    let s = Settings {
        friction_max_iterations: 2,
        ..settings(gpu, FrictionMethod::Pgs, false)
    };
    let cpu = Settings {
        backend: Backend::Cpu,
        gpu: GpuSettings::default(),
        ..s.clone()
    };
    let mut on_gpu = worlds.clone();
    let mut on_cpu = worlds;
    let mut g = Solver::new(s).unwrap();
    let mut c = Solver::new(cpu).unwrap();
    let mut not_solved = 0;
    for step in 0..50 {
        let rg = g.step_worlds(&mut on_gpu, 0.01).unwrap();
        let rc = c.step_worlds(&mut on_cpu, 0.01).unwrap();
        let f = rg.resident.expect("the resident path ran");
        not_solved += f.not_solved;
        assert_eq!(f.not_solved, f.on_cpu, "step {step}");
        assert_eq!(rg.unsolved, rc.unsolved, "step {step}");
        let d = max_distance(&on_gpu, &on_cpu);
        assert!(d < 1e-9, "step {step}: {d} m");
    }
    assert!(not_solved >= 90, "{not_solved} world-steps flagged");
}

/// Warm starts on the device: μ = 0.5 stacks of 2 and 3 in one batch
/// (tolerance 1e-6, as above: an island left unsolved records no
/// reactions, so at 1e-8 every step starts cold and stalls, on the CPU
/// alike). The first steps' rounds are too few for the cold stacks: those
/// worlds are stepped on the CPU, whose recorded reactions go to the
/// device's memory, and the device goes on warm from there: the CPU's
/// trajectory within 1e-9 m.
#[test]
fn warm_started_frictional_stacks_follow_the_cpu_path() {
    let Some(gpu) = f64_gpu() else { return };
    let mut worlds = frictional(WorldKind::Stack, 2, 1);
    worlds.extend(frictional(WorldKind::Stack, 3, 1));
    let s = Settings {
        friction_tolerance: 1e-6,
        ..settings(gpu, FrictionMethod::Pgs, true)
    };
    let (device, host) = compare_with(worlds, 500, s);
    println!("warm pgs stacks: {device} on the device, {host} on the CPU");
    assert_eq!(device + host, 1000);
    assert!(
        device >= 950 && host > 0,
        "{device} on the device, {host} on the CPU"
    );
}

/// The hand-over flag is a bit of its own, the shader's, and the rounds
/// follow it alone: doubled where a world was left unfinished (HANDED),
/// down to twice the most a world needed otherwise, a collision's BUDGET
/// ignored.
#[test]
fn the_rounds_double_on_hand_over_only_and_come_back_down() {
    let rec = |flags, rounds| WorldRecord {
        flags,
        rounds,
        ..WorldRecord::default()
    };
    assert_eq!(next_rounds(8, &[rec(0, 3), rec(flags::HANDED, 8)]), 16);
    assert_eq!(next_rounds(8, &[rec(flags::BUDGET, 0), rec(0, 3)]), 6);
    assert_eq!(next_rounds(8, &[rec(0, 2), rec(0, 1)]), 4);
    assert_eq!(next_rounds(8, &[rec(0, 7)]), 8);
    assert_eq!(next_rounds(8, &[rec(flags::BUDGET, 0)]), 8);
    assert_eq!(
        next_rounds(MAX_ROUNDS, &[rec(flags::HANDED, MAX_ROUNDS)]),
        MAX_ROUNDS
    );
}

/// The resident APGD against the CPU path's (`s` with `Backend::Cpu`) for
/// `steps` steps: [`compare_with`]'s checks (positions within 1e-9 m, the
/// same contacts, islands, awake bodies and energies every step), then
/// again step by step the same unsolved islands and each world's error
/// (the Coulomb error of the device's answer, which the device judged by
/// its f64 cone error) within half of the larger plus the tolerance: near
/// the tolerance the two answers are two iterates of it (measured: 7.4e-13
/// against 8.8e-13, 8.8e-13 against 1.7e-13 at 1e-12), the same measure
/// where another error would differ by orders. Returns the world-steps on the device and on the CPU.
fn compare_apgd(worlds: Vec<World>, steps: usize, s: Settings) -> (usize, usize) {
    let (device, host) = compare_with(worlds.clone(), steps, s.clone());
    let cpu = Settings {
        backend: Backend::Cpu,
        gpu: GpuSettings::default(),
        ..s.clone()
    };
    let tol = s.friction_tolerance;
    let (mut on_gpu, mut on_cpu) = (worlds.clone(), worlds);
    let (mut g, mut c) = (Solver::new(s).unwrap(), Solver::new(cpu).unwrap());
    for step in 0..steps.min(100) {
        let rg = g.step_worlds(&mut on_gpu, 0.01).unwrap();
        let rc = c.step_worlds(&mut on_cpu, 0.01).unwrap();
        assert_eq!(rg.unsolved, rc.unsolved, "step {step}");
        for (k, (a, b)) in rg.worlds.iter().zip(&rc.worlds).enumerate() {
            let close =
                (a.max_error - b.max_error).abs() <= 0.5 * a.max_error.max(b.max_error) + tol;
            assert!(close, "step {step}, world {k}: {a:?} vs {b:?}");
        }
    }
    (device, host)
}

/// APGD resident: stacks of 4, 2 and 3 boxes in one batch, warm-started
/// and cold, against the CPU path's APGD at the CLI's tolerance 1e-12.
/// The two paths' iterates differ by rounding, and APGD's stopping
/// iteration (and its restarts) can flip on it: the paths then part by
/// about the tolerance's share of the impulse (measured over 300 steps:
/// 2.3e-7 m at 1e-8 warm, 2.7e-9 m at 1e-10, 2.5e-11 m at 1e-12).
#[test]
fn resident_apgd_stacks_follow_the_cpu_path() {
    let Some(gpu) = f64_gpu() else { return };
    let mut worlds = frictional(WorldKind::Stack, 4, 1);
    worlds.extend(frictional(WorldKind::Stack, 2, 1));
    worlds.extend(frictional(WorldKind::Stack, 3, 1));
    for warm in [true, false] {
        let s = Settings {
            friction_tolerance: 1e-12,
            ..settings(gpu.clone(), Apgd, warm)
        };
        let (device, host) = compare_apgd(worlds.clone(), 300, s);
        println!("apgd stacks (warm {warm}): {device} on the device, {host} on the CPU");
        assert_eq!(device + host, 900);
        assert!(device >= 800, "{device} on the device");
    }
}

/// APGD resident: a box sliding at 2 m/s, boxes on a 20° (sticking) and a
/// 30° (sliding) incline, at the CLI's tolerance 1e-12 (see above; at
/// 1e-8 they part by 2.4e-8 m in 300 steps), against the CPU path's APGD.
#[test]
fn resident_apgd_sliding_and_inclined_boxes_follow_the_cpu_path() {
    let Some(gpu) = f64_gpu() else { return };
    let worlds = vec![
        standard_world(WorldKind::Slide, 1, 0),
        standard_world(WorldKind::Incline, 1, 0),
        incline(30f64.to_radians(), 0.3, 0.5),
    ];
    let s = Settings {
        friction_tolerance: 1e-12,
        ..settings(gpu, Apgd, true)
    };
    let (device, host) = compare_apgd(worlds, 300, s);
    println!("apgd slide and inclines: {device} on the device, {host} on the CPU");
    assert_eq!(device + host, 900);
    assert!(device >= 800, "{device} on the device");
}
