//! `Backend::Auto`'s cost model on a real device: each batch goes where the
//! model estimates it faster, with the same answers as the CPU's, and a
//! calibration measures both paths by island size; batches of worlds step
//! on the resident path or the CPU's per-world path as the model's world
//! figures say (models given in the settings: nothing depends on timing).

use crate::generate::families::islands_of_size;
use crate::settings::{Backend, GpuSettings, Method, Settings};
use crate::solver::WorldCosts;
use crate::world::generate::WorldKind;
use crate::world::World;
use crate::{CostModel, DeviceKind, GpuContext, Solver, Status, StepReport};

use super::common::gpu_settings_or_skip;
use super::gpu_resident::{f64_gpu, frictionless, max_distance, settings as world_settings};

/// A model where the GPU costs 2 ms a call and 1 µs an island, the CPU
/// 5 µs an island: a few islands go to the CPU, thousands to the GPU.
fn model(device: String) -> CostModel {
    CostModel {
        device,
        threads: 2,
        sizes: vec![1, 16],
        cpu_per_island: vec![5e-6, 5e-6],
        gpu_per_island: vec![1e-6, 1e-6],
        gpu_per_batch: 2e-3,
        worlds: None,
    }
}

/// [`model`] with world figures: the resident path at 1 ns a world-step
/// (`gpu_faster`) or 1 ms, the CPU at the other.
fn world_model(gpu_faster: bool) -> CostModel {
    let (fast, slow) = (1e-9, 1e-3);
    let (cpu, gpu) = if gpu_faster {
        (slow, fast)
    } else {
        (fast, slow)
    };
    CostModel {
        worlds: Some(WorldCosts {
            bodies: 5,
            cpu_per_world_step: cpu,
            gpu_per_world_step: gpu,
            gpu_per_submission: 0.0,
        }),
        ..model("given".into())
    }
}

/// Settings of `Backend::Auto` on the f64 adapter, named (so that Auto
/// opens it even where it is a software one), with `cost_model`.
fn auto_on(gpu: GpuSettings, cost_model: Option<CostModel>) -> Settings {
    let mut s = world_settings(Backend::Auto, gpu);
    s.gpu.adapter = Some(
        GpuContext::open(&s.gpu)
            .unwrap()
            .adapter_info()
            .name
            .clone(),
    );
    s.cost_model = cost_model;
    s
}

/// Stacks of 4 and 2 boxes and spheres, frictionless.
fn worlds() -> Vec<World> {
    let mut w = frictionless(WorldKind::Stack, 4, 2);
    w.extend(frictionless(WorldKind::Stack, 2, 1));
    w.extend(frictionless(WorldKind::Spheres, 3, 2));
    w
}

/// `steps` steps of `worlds` by one `step_worlds` call and then a
/// `step_worlds_for` call of the rest: the worlds after, every report.
fn stepped(s: Settings, mut worlds: Vec<World>, steps: usize) -> (Vec<World>, Vec<StepReport>) {
    let mut solver = Solver::new(s).unwrap();
    let mut reports = vec![solver.step_worlds(&mut worlds, 0.01).unwrap()];
    (solver.step_worlds_for(&mut worlds, 0.01, steps - 1, |_, r| reports.push(r))).unwrap();
    (worlds, reports)
}

#[test]
fn auto_steps_worlds_resident_where_the_model_says_the_gpu_is_faster() {
    let Some(gpu) = f64_gpu() else { return };
    let cpu = world_settings(Backend::Cpu, GpuSettings::default());
    let (want, _) = stepped(cpu, worlds(), 200);
    let (got, reports) = stepped(auto_on(gpu, Some(world_model(true))), worlds(), 200);
    for r in &reports {
        assert!(r.resident.is_some(), "{}", r.solve.choice);
        let c = &r.solve.choice;
        assert!(
            c.contains("worlds: 5 × ") && c.contains("cost model"),
            "{c}"
        );
        assert!(c.ends_with("→ GPU"), "{c}");
    }
    assert!(reports[0].solve.choice.contains("5 × 1 step(s)"));
    let d = max_distance(&got, &want);
    assert!(d < 1e-9, "{d} m from the CPU path");
}

#[test]
fn auto_keeps_worlds_on_the_cpu_where_the_model_says_the_gpu_is_slower() {
    let Some(gpu) = f64_gpu() else { return };
    let cpu = world_settings(Backend::Cpu, GpuSettings::default());
    let (want, want_reports) = stepped(cpu, worlds(), 100);
    // Slower by the figures, or no world figures at all: the CPU's
    // per-world path, bit for bit (not the GPU's batch route).
    for (model, why) in [
        (world_model(false), "→ CPU"),
        (model("given".into()), "no world figures → CPU"),
    ] {
        let (got, reports) = stepped(auto_on(gpu.clone(), Some(model)), worlds(), 100);
        assert!(got == want, "the CPU path's trajectory");
        for (r, w) in reports.iter().zip(&want_reports) {
            assert!(r.resident.is_none());
            assert_eq!(r.solve.device.kind, DeviceKind::Cpu);
            assert!(r.solve.choice.ends_with(why), "{}", r.solve.choice);
            assert!(r.worlds == w.worlds);
        }
    }
}

#[test]
fn auto_without_a_gpu_steps_worlds_as_before() {
    let mut auto = Solver::new(world_settings(Backend::Auto, GpuSettings::default())).unwrap();
    if auto.device().kind != DeviceKind::Cpu {
        return; // a hardware adapter: Auto opened it.
    }
    let cpu = world_settings(Backend::Cpu, GpuSettings::default());
    let (want, want_reports) = stepped(cpu, worlds(), 30);
    let mut got = worlds();
    let mut reports = vec![auto.step_worlds(&mut got, 0.01).unwrap()];
    (auto.step_worlds_for(&mut got, 0.01, 29, |_, r| reports.push(r))).unwrap();
    assert!(got == want);
    for (r, w) in reports.iter().zip(&want_reports) {
        assert!(r.resident.is_none() && !r.solve.choice.contains("worlds:"));
        assert_eq!(r.solve.choice, auto.choice());
        assert!(r.worlds == w.worlds);
    }
}

#[test]
fn auto_solves_each_batch_where_the_model_estimates_it_faster() {
    let Some(g) = gpu_settings_or_skip() else {
        return;
    };
    let mut settings = Settings {
        gpu: g,
        method: Method::Enumeration,
        ..Settings::new(Backend::Auto, Method::Enumeration)
    };
    // The named adapter makes Auto open it even when it is a software one.
    let name = GpuContext::open(&settings.gpu)
        .unwrap()
        .adapter_info()
        .name
        .clone();
    settings.gpu.adapter = Some(name);
    settings.cost_model = Some(model("given".into()));
    let mut auto = Solver::new(settings).unwrap();
    assert_eq!(auto.cost_model().map(|m| m.device.as_str()), Some("given"));
    let mut cpu = Solver::new(Settings::new(Backend::Cpu, Method::Enumeration)).unwrap();

    let few = islands_of_size(4, 8, 1);
    let r = auto.solve_lcps(&few).unwrap();
    assert_eq!(r.device.kind, DeviceKind::Cpu, "{}", r.choice);
    assert!(
        r.choice.contains("cost model") && r.choice.ends_with("→ CPU"),
        "{}",
        r.choice
    );

    let many = islands_of_size(4, 3000, 2);
    let r = auto.solve_lcps(&many).unwrap();
    assert!(r.on_gpu(), "{}", r.choice);
    assert!(r.choice.ends_with("→ GPU"), "{}", r.choice);
    let c = cpu.solve_lcps(&many).unwrap();
    for (a, b) in r.islands.iter().zip(&c.islands) {
        assert_eq!(a.status(), b.status());
        assert_eq!(a.status(), Status::Solved);
    }
}

#[test]
fn a_calibration_measures_both_paths_by_island_size() {
    let Some(g) = gpu_settings_or_skip() else {
        return;
    };
    let device = GpuContext::open(&g).unwrap();
    let mut solver = Solver::with_device(Settings::default(), device).unwrap();
    let m = solver.calibrate().unwrap();
    println!("{m}");
    m.validate().unwrap();
    assert_eq!(m.sizes, crate::solver::CALIBRATION_SIZES.to_vec());
    // Kept under the adapter and precision, not how the adapter was chosen.
    let info = solver.shared_device().unwrap().adapter_info().clone();
    assert!(m.device.starts_with(&info.name), "{}", m.device);
    assert!(!m.device.contains("forced") && !m.device.contains("fallback"));
    // Every size was timed on both paths (`validate` checks the figures are
    // finite and ≥ 0). Their order by size is not asserted: a test sharing
    // the machine with others cannot time anything reliably.
    assert_eq!(m.cpu_per_island.len(), m.sizes.len());
    assert_eq!(m.gpu_per_island.len(), m.sizes.len());
    // The world figures where the adapter has f64 (the resident path).
    let f64 = solver.shared_device().unwrap().precision() == crate::Precision::F64;
    assert_eq!(m.worlds.is_some(), f64);
}
