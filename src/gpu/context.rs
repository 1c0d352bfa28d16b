//! Device and adapter choice: [`GpuOptions`], [`GpuContext`] (adapter,
//! device, queue, the error handling that turns wgpu's errors into
//! [`Error::Gpu`]) and what `lcpbatch info` lists.

use std::sync::{Arc, Mutex};

use super::pipelines::Pipelines;
use crate::Error;

/// How to install a software adapter when there is none.
pub const INSTALL_HINT: &str =
    "install a software adapter: `apt-get install mesa-vulkan-drivers libvulkan1` \
(Debian/Ubuntu; lavapipe through Vulkan) or `apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri` \
(llvmpipe through GL)";

pub use crate::settings::{BackendChoice, Precision};

impl Precision {
    /// Parses "auto", "f32" or "f64" in any case ([`std::str::FromStr`] of
    /// the lowercase text).
    pub fn parse(s: &str) -> Result<Self, Error> {
        s.to_ascii_lowercase().parse()
    }

    /// Bytes of one scalar (Auto must have been resolved).
    pub fn bytes(self) -> u64 {
        match self {
            Precision::F64 => 8,
            _ => 4,
        }
    }
}

impl BackendChoice {
    /// Parses `auto`, `vulkan`, `gl`, `metal` or `dx12` (and common spellings).
    pub fn parse(s: &str) -> Result<Self, Error> {
        match s.to_ascii_lowercase().as_str() {
            "auto" | "all" | "" => Ok(BackendChoice::Auto),
            "vulkan" | "vk" => Ok(BackendChoice::Vulkan),
            "gl" | "gles" | "opengl" => Ok(BackendChoice::Gl),
            "metal" | "mtl" => Ok(BackendChoice::Metal),
            "dx12" | "d3d12" => Ok(BackendChoice::Dx12),
            other => Err(Error::invalid(
                "backend",
                "backend",
                format!("`{other}` is not one of auto, vulkan, gl, metal, dx12"),
            )),
        }
    }

    /// The wgpu backends to look on.
    pub fn backends(self) -> wgpu::Backends {
        match self {
            BackendChoice::Auto => wgpu::Backends::all(),
            BackendChoice::Vulkan => wgpu::Backends::VULKAN,
            BackendChoice::Gl => wgpu::Backends::GL,
            BackendChoice::Metal => wgpu::Backends::METAL,
            BackendChoice::Dx12 => wgpu::Backends::DX12,
        }
    }
}

/// Environment variable that forces a backend (auto, vulkan, gl, metal, dx12).
pub const ENV_BACKEND: &str = "LCPBATCH_GPU_BACKEND";
/// Environment variable that forces an adapter: a case-insensitive part of its name.
pub const ENV_ADAPTER: &str = "LCPBATCH_GPU_ADAPTER";
/// Environment variable that picks the precision (auto, f32, f64).
pub const ENV_PRECISION: &str = "LCPBATCH_GPU_PRECISION";

/// How to pick the adapter and the precision.
#[derive(Clone, Debug, PartialEq)]
pub struct GpuOptions {
    pub backend: BackendChoice,
    /// A case-insensitive part of the adapter's name; None: the best adapter.
    pub adapter_name: Option<String>,
    /// HighPerformance by default: with PowerPreference::None wgpu does not
    /// sort adapters and a software adapter may win over a real GPU.
    pub power: wgpu::PowerPreference,
    pub precision: Precision,
}

impl Default for GpuOptions {
    fn default() -> Self {
        GpuOptions {
            backend: BackendChoice::Auto,
            adapter_name: None,
            power: wgpu::PowerPreference::HighPerformance,
            precision: Precision::Auto,
        }
    }
}

impl GpuOptions {
    /// Defaults overridden by [`ENV_BACKEND`], [`ENV_ADAPTER`] and [`ENV_PRECISION`].
    pub fn from_env() -> Result<Self, Error> {
        let mut o = GpuOptions::default();
        if let Ok(v) = std::env::var(ENV_BACKEND) {
            o.backend = BackendChoice::parse(&v)?;
        }
        if let Ok(v) = std::env::var(ENV_ADAPTER) {
            if !v.is_empty() {
                o.adapter_name = Some(v);
            }
        }
        if let Ok(v) = std::env::var(ENV_PRECISION) {
            o.precision = Precision::parse(&v)?;
        }
        Ok(o)
    }
}

/// What `lcpbatch info` prints about one adapter.
#[derive(Clone, Debug, PartialEq)]
pub struct AdapterSummary {
    /// The adapter's name.
    pub name: String,
    /// The wgpu backend (Vulkan, Gl, …).
    pub backend: String,
    /// Discrete, integrated, virtual, CPU (software) or other.
    pub device_type: String,
    /// Driver name and version, where reported.
    pub driver: String,
    /// True for software adapters (lavapipe, llvmpipe, WARP).
    pub software: bool,
    /// Whether it has SHADER_F64.
    pub f64: bool,
    /// Whether it has subgroup operations.
    pub subgroups: bool,
    /// Whether it has timestamp queries.
    pub timestamps: bool,
    /// Largest storage-buffer binding, bytes.
    pub max_storage_buffer_binding_size: u64,
    /// Largest buffer, bytes.
    pub max_buffer_size: u64,
    /// Largest workgroup count per dispatch dimension.
    pub max_compute_workgroups_per_dimension: u32,
    /// Largest invocations per workgroup.
    pub max_compute_invocations_per_workgroup: u32,
    /// Largest workgroup storage, bytes.
    pub max_compute_workgroup_storage_size: u32,
}

impl AdapterSummary {
    fn of(adapter: &wgpu::Adapter) -> Self {
        let info = adapter.get_info();
        let f = adapter.features();
        let l = adapter.limits();
        AdapterSummary {
            name: info.name.clone(),
            backend: format!("{:?}", info.backend),
            device_type: format!("{:?}", info.device_type),
            driver: format!("{} {}", info.driver, info.driver_info)
                .trim()
                .to_string(),
            software: info.device_type == wgpu::DeviceType::Cpu,
            f64: f.contains(wgpu::Features::SHADER_F64),
            subgroups: f.contains(wgpu::Features::SUBGROUP),
            timestamps: f.contains(wgpu::Features::TIMESTAMP_QUERY),
            max_storage_buffer_binding_size: l.max_storage_buffer_binding_size,
            max_buffer_size: l.max_buffer_size,
            max_compute_workgroups_per_dimension: l.max_compute_workgroups_per_dimension,
            max_compute_invocations_per_workgroup: l.max_compute_invocations_per_workgroup,
            max_compute_workgroup_storage_size: l.max_compute_workgroup_storage_size,
        }
    }
}

impl std::fmt::Display for AdapterSummary {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let yes = |b: bool| if b { "yes" } else { "no" };
        writeln!(
            f,
            "{} ({}, {}{})",
            self.name,
            self.backend,
            self.device_type,
            if self.software { ", software" } else { "" }
        )?;
        if !self.driver.is_empty() {
            writeln!(f, "  driver: {}", self.driver)?;
        }
        writeln!(
            f,
            "  features: f64 {}, subgroups {}, timestamps {}",
            yes(self.f64),
            yes(self.subgroups),
            yes(self.timestamps)
        )?;
        write!(
            f,
            "  limits: storage binding {} MiB, buffer {} MiB, workgroups/dim {}, invocations/workgroup {}, workgroup storage {} KiB",
            self.max_storage_buffer_binding_size >> 20,
            self.max_buffer_size >> 20,
            self.max_compute_workgroups_per_dimension,
            self.max_compute_invocations_per_workgroup,
            self.max_compute_workgroup_storage_size >> 10
        )
    }
}

fn instance(backends: wgpu::Backends) -> wgpu::Instance {
    let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
    desc.backends = backends;
    wgpu::Instance::new(desc)
}

/// Every adapter on the chosen backends (for `lcpbatch info`).
pub fn list_adapters(backend: BackendChoice) -> Vec<AdapterSummary> {
    let inst = instance(backend.backends());
    pollster::block_on(inst.enumerate_adapters(backend.backends()))
        .iter()
        .map(AdapterSummary::of)
        .collect()
}

/// Rank for picking among adapters: hardware before software, Vulkan/Metal/DX12 before GL.
fn rank(info: &wgpu::AdapterInfo) -> (u8, u8) {
    let t = match info.device_type {
        wgpu::DeviceType::DiscreteGpu => 0,
        wgpu::DeviceType::IntegratedGpu => 1,
        wgpu::DeviceType::VirtualGpu => 2,
        wgpu::DeviceType::Other => 3,
        wgpu::DeviceType::Cpu => 4,
    };
    let b = if info.backend == wgpu::Backend::Gl {
        1
    } else {
        0
    };
    (t, b)
}

/// The adapter `options` ask for among `all`, and how it was chosen: a
/// forced name, else request_adapter (a hardware adapter on another backend
/// preferred over a software one), else the software fallback, else the
/// best ranked adapter.
fn choose_adapter(
    inst: &wgpu::Instance,
    all: Vec<wgpu::Adapter>,
    options: &GpuOptions,
) -> Result<(wgpu::Adapter, String), Error> {
    let backends = options.backend.backends();
    let chosen = if let Some(want) = &options.adapter_name {
        let w = want.to_lowercase();
        let found = all
            .into_iter()
            .find(|a| a.get_info().name.to_lowercase().contains(&w));
        match found {
            Some(a) => (a, format!("forced by name `{want}`")),
            None => {
                let names: Vec<String> = list_adapters(options.backend)
                    .into_iter()
                    .map(|s| format!("{} ({})", s.name, s.backend))
                    .collect();
                return Err(Error::Gpu(format!(
                    "no adapter whose name contains `{want}`; available: {}",
                    if names.is_empty() {
                        "none".to_string()
                    } else {
                        names.join(", ")
                    }
                )));
            }
        }
    } else {
        let requested = pollster::block_on(inst.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: options.power,
            force_fallback_adapter: false,
            compatible_surface: None,
            apply_limit_buckets: false,
        }));
        match requested {
            Ok(a) => {
                // request_adapter may hand back a software adapter while a
                // hardware one exists on another backend: prefer hardware.
                let best = all.into_iter().min_by_key(|x| rank(&x.get_info()));
                match best {
                    Some(b) if rank(&b.get_info()) < rank(&a.get_info()) => {
                        (b, "hardware (best ranked)".to_string())
                    }
                    _ => {
                        let sw = a.get_info().device_type == wgpu::DeviceType::Cpu;
                        let how = if sw {
                            "software fallback (no hardware adapter)"
                        } else {
                            "hardware (high performance)"
                        };
                        (a, how.to_string())
                    }
                }
            }
            Err(_) => {
                let fallback =
                    pollster::block_on(inst.request_adapter(&wgpu::RequestAdapterOptions {
                        power_preference: options.power,
                        force_fallback_adapter: true,
                        compatible_surface: None,
                        apply_limit_buckets: false,
                    }));
                match fallback {
                    Ok(a) => (a, "software fallback (no hardware adapter)".to_string()),
                    Err(_) => match all.into_iter().min_by_key(|x| rank(&x.get_info())) {
                        Some(a) => (a, "only adapter found".to_string()),
                        None => {
                            return Err(Error::Gpu(format!(
                                "no GPU adapter found on backends {:?}: {INSTALL_HINT}",
                                backends
                            )))
                        }
                    },
                }
            }
        }
    };
    Ok(chosen)
}

/// wgpu errors that reached no error scope, collected instead of panicking.
#[derive(Clone, Default)]
pub(crate) struct ErrorSink(Arc<Mutex<Vec<String>>>);

impl ErrorSink {
    pub(crate) fn take(&self) -> Vec<String> {
        match self.0.lock() {
            Ok(mut v) => std::mem::take(&mut *v),
            Err(p) => std::mem::take(&mut *p.into_inner()),
        }
    }
}

/// Adapter, device, queue and pipelines: created once, reused for every batch.
pub struct GpuContext {
    pub(crate) device: wgpu::Device,
    pub(crate) queue: wgpu::Queue,
    summary: AdapterSummary,
    /// How the adapter was chosen, in words (for the demo and `info`).
    selection: String,
    precision: Precision,
    limits: wgpu::Limits,
    pub(crate) errors: ErrorSink,
    /// The pipelines of the context's precision: built on first use, then reused.
    pub(crate) pipelines: Mutex<Option<Arc<Pipelines>>>,
    /// The LCP enumeration stage's and the friction batches' buffers by
    /// role, kept for the next call, and the tolerances uniform ([`super::buffers::Kept`]).
    pub(crate) kept: Mutex<super::buffers::Kept>,
}

impl std::fmt::Debug for GpuContext {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("GpuContext")
            .field("adapter", &self.summary.name)
            .field("precision", &self.precision)
            .finish()
    }
}

impl GpuContext {
    /// Opens the adapter and device `settings` ask for (the seam through
    /// which a caller, a test for one, hands its own device to
    /// [`crate::Solver::with_device`]).
    ///
    /// # Errors
    /// [`Error::Gpu`] when there is no adapter, or the one named or the
    /// precision asked for is unavailable.
    pub fn open(settings: &crate::GpuSettings) -> Result<Self, Error> {
        GpuContext::new(&settings.options())
    }

    /// Picks an adapter (a forced one, else hardware with HighPerformance,
    /// else a software adapter), opens a device with the adapter's own
    /// limits, and installs the error handler. Error::Gpu when there is no
    /// adapter (the message says how to install one) or the forced adapter
    /// or precision is unavailable.
    pub fn new(options: &GpuOptions) -> Result<Self, Error> {
        let backends = options.backend.backends();
        let inst = instance(backends);
        let all = pollster::block_on(inst.enumerate_adapters(backends));
        let (adapter, selection) = choose_adapter(&inst, all, options)?;
        let summary = AdapterSummary::of(&adapter);
        let precision = match options.precision {
            Precision::Auto if summary.f64 => Precision::F64,
            Precision::Auto => Precision::F32,
            Precision::F64 if !summary.f64 => {
                return Err(Error::Gpu(format!(
                    "adapter `{}` has no SHADER_F64: use --precision f32",
                    summary.name
                )))
            }
            p => p,
        };
        let mut features = wgpu::Features::empty();
        if precision == Precision::F64 {
            features |= wgpu::Features::SHADER_F64;
        }
        // A software adapter's buffers are host memory: storage buffers the
        // host writes in place save a staging buffer and its copy at the
        // next submission (`kept_written`: the friction batches' W, 12.8
        // MB at 10,000 islands of k = 4, about 3 ms of 45 on lavapipe).
        let mappable = wgpu::Features::MAPPABLE_PRIMARY_BUFFERS;
        if summary.software && adapter.features().contains(mappable) {
            features |= mappable;
        }
        // GPU timestamps, where offered: the kernels' own seconds per
        // chunk (`GpuFigures::kernel_device_seconds`).
        if adapter.features().contains(wgpu::Features::TIMESTAMP_QUERY) {
            features |= wgpu::Features::TIMESTAMP_QUERY;
        }
        let limits = adapter.limits();
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("lcpbatch device"),
            required_features: features,
            required_limits: limits.clone(),
            experimental_features: wgpu::ExperimentalFeatures::disabled(),
            memory_hints: wgpu::MemoryHints::Performance,
            trace: wgpu::Trace::Off,
        }))
        .map_err(|e| Error::Gpu(format!("adapter `{}`: no device: {e}", summary.name)))?;
        let errors = ErrorSink::default();
        let sink = errors.clone();
        device.on_uncaptured_error(Arc::new(move |e: wgpu::Error| {
            if let Ok(mut v) = sink.0.lock() {
                v.push(e.to_string());
            }
        }));
        // A lost device (driver reset, out of memory) is reported the same way.
        let lost = errors.clone();
        device.set_device_lost_callback(move |reason, message| {
            if reason != wgpu::DeviceLostReason::Destroyed {
                if let Ok(mut v) = lost.0.lock() {
                    v.push(format!("device lost ({reason:?}): {message}"));
                }
            }
        });
        Ok(GpuContext {
            device,
            queue,
            summary,
            selection,
            precision,
            limits,
            errors,
            pipelines: Mutex::new(None),
            kept: Mutex::default(),
        })
    }

    /// For tests of device trouble: destroys the device, as a driver reset
    /// would lose it, and reports the loss the way the device-lost callback
    /// reports a real one (the callback ignores a deliberate destroy). Every
    /// later GPU call on this context fails: with [`Error::Gpu`], or with a
    /// panic inside wgpu (`create_buffer_init` on a lost device), which
    /// [`crate::backend`] turns into device trouble as well.
    #[doc(hidden)]
    pub fn simulate_device_loss(&self) {
        self.device.destroy();
        if let Ok(mut v) = self.errors.0.lock() {
            v.push("device lost (simulated): the device was destroyed".into());
        }
    }

    /// The chosen adapter.
    pub fn adapter_info(&self) -> &AdapterSummary {
        &self.summary
    }

    /// How the adapter was chosen, in words.
    pub fn selection(&self) -> &str {
        &self.selection
    }

    /// The shaders' precision (never Auto).
    pub fn precision(&self) -> Precision {
        self.precision
    }

    /// The device's limits (the adapter's own, not WebGPU's minimums).
    pub fn limits(&self) -> &wgpu::Limits {
        &self.limits
    }

    /// Runs `f` inside a validation + out-of-memory + internal error scope
    /// and turns any error (or one caught by the uncaptured handler) into
    /// Error::Gpu naming `what`.
    pub(crate) fn scoped<T>(&self, what: &str, f: impl FnOnce() -> T) -> Result<T, Error> {
        let oom = self.device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let internal = self.device.push_error_scope(wgpu::ErrorFilter::Internal);
        let validation = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let out = f();
        let mut found = Vec::new();
        for guard in [validation, internal, oom] {
            if let Some(e) = pollster::block_on(guard.pop()) {
                found.push(e.to_string());
            }
        }
        found.extend(self.errors.take());
        if found.is_empty() {
            Ok(out)
        } else {
            Err(Error::Gpu(format!("{what}: {}", found.join("; "))))
        }
    }
}
