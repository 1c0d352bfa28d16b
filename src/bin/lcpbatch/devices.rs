//! The GPU solvers `bench` and `stress` compare, and the machine in words.

use lcpbatch::device::list_adapters;
use lcpbatch::{Backend, GpuSettings, Precision, Settings, Solver};

/// A GPU solver in f32 and, where the adapter has SHADER_F64, one in f64
/// (none when `gpu` is None or no adapter opens; a warning says why).
pub fn gpu_solvers(gpu: &Option<GpuSettings>, base: &Settings) -> Vec<Solver> {
    let Some(gpu) = gpu else {
        return Vec::new();
    };
    let open = |precision| {
        Solver::new(Settings {
            backend: Backend::Gpu,
            gpu: GpuSettings {
                precision,
                ..gpu.clone()
            },
            ..base.clone()
        })
    };
    let Ok(f32_solver) = open(Precision::F32) else {
        return Vec::new();
    };
    if f32_solver.fallback().is_some() {
        return Vec::new();
    }
    let name = f32_solver.device().name;
    let has_f64 = list_adapters(gpu.api)
        .iter()
        .any(|a| a.f64 && name.starts_with(&a.name));
    let mut out = vec![f32_solver];
    if has_f64 {
        if let Ok(s) = open(Precision::F64) {
            out.push(s);
        }
    } else {
        eprintln!("warning: the adapter has no f64; GPU rows in f32 only");
    }
    out
}

/// CPU threads and the adapters of `gpus`, for the JSON files.
pub fn machine_description(gpus: &[Solver]) -> String {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut s = format!("{threads} CPU thread(s)");
    for g in gpus {
        s.push_str("; ");
        s.push_str(&g.device().name);
    }
    s
}
