//! `Backend::Auto`'s cost model on a real device: each batch goes where the
//! model estimates it faster, with the same answers as the CPU's, and a
//! calibration measures both paths by island size.

use crate::generate::families::islands_of_size;
use crate::settings::{Backend, Method, Settings};
use crate::{CostModel, DeviceKind, GpuContext, Solver, Status};

use super::common::gpu_settings_or_skip;

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
}
