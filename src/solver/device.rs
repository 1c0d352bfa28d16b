//! Which device takes a batch: the backend asked for and the adapters
//! found, once per solver ([`choose`]); per batch, `Backend::Auto`'s cost
//! model ([`gpu_for`]); the CPU path as a device ([`cpu_device`]). The
//! frictional islands' choice is [`super::friction_path::friction_on_gpu`].

use super::CostModel;
use crate::gpu::{self, Precision};
use crate::report::{Device, DeviceKind};
use crate::settings::{Backend, Settings};

/// Whether `s` asks for a GPU, and why in words for the report
/// (`Backend::Auto`: a hardware adapter or a named one, never an unnamed
/// software adapter; see the module docs of [`super`]).
pub(super) fn choose(s: &Settings) -> (bool, String) {
    match s.backend {
        Backend::Cpu => (false, "backend cpu".into()),
        Backend::Gpu => (true, "backend gpu".into()),
        Backend::Auto if !s.gpu_capable() => (
            false,
            format!("backend auto: {} runs on the CPU only", s.method.name()),
        ),
        Backend::Auto if s.gpu.adapter.is_some() => (true, "backend auto: adapter named".into()),
        Backend::Auto => {
            let adapters = gpu::list_adapters(s.gpu.api);
            let hardware = adapters.iter().find(|a| !a.software);
            match (hardware, adapters.first()) {
                (Some(a), _) => (true, format!("backend auto: hardware adapter {}", a.name)),
                (None, Some(a)) => (
                    false,
                    format!(
                        "backend auto: the only adapters are software ({}), slower than the CPU path; name one or ask for backend gpu to use it",
                        a.name
                    ),
                ),
                (None, None) => (false, "backend auto: no GPU adapter".into()),
            }
        }
    }
}

/// Whether the next batch of islands of `sizes` goes to the GPU, and
/// why in words for the report (`choice`, the solver's, with the cost
/// model's estimates; without a cost model: wherever a GPU is open).
pub(super) fn gpu_for(
    gpu_open: bool,
    cost: Option<&CostModel>,
    choice: &str,
    sizes: impl Iterator<Item = usize>,
) -> (bool, String) {
    match (gpu_open, cost) {
        (false, _) => (false, choice.to_string()),
        (true, None) => (true, choice.to_string()),
        (true, Some(m)) => {
            let (cpu, gpu) = m.estimate(sizes);
            let on_gpu = gpu < cpu;
            let why = format!(
                "{}; cost model: CPU {:.3} ms, GPU {:.3} ms estimated → {}",
                choice,
                cpu * 1e3,
                gpu * 1e3,
                if on_gpu { "GPU" } else { "CPU" }
            );
            (on_gpu, why)
        }
    }
}

/// The CPU path as a device.
pub(super) fn cpu_device(threads: usize) -> Device {
    Device {
        kind: DeviceKind::Cpu,
        name: format!("cpu ({threads} thread(s), f64)"),
        precision: Precision::F64,
    }
}
