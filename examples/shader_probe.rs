//! Bringing up a new GPU: compiles every compute entry point of the given
//! WGSL files (default: every file of `shaders/generated/`) on the first
//! adapter of the chosen backend, each in an error scope of its own, and
//! prints per entry point the milliseconds the pipeline took to build and
//! what the driver said (wgpu's warnings, e.g. an unrecognised Vulkan
//! error, go to stderr). A device lost on one entry point is reported and a
//! new device is opened for the next.
//!
//! `cargo run --release --example shader_probe -- [vulkan|gl] [FILE.wgsl ...]`

use std::sync::{Arc, Mutex};
use std::time::Instant;

struct Stderr;

impl log::Log for Stderr {
    fn enabled(&self, m: &log::Metadata) -> bool {
        m.level() <= log::Level::Warn
    }
    fn log(&self, r: &log::Record) {
        if self.enabled(r.metadata()) {
            eprintln!("  [{} {}] {}", r.level(), r.target(), r.args());
        }
    }
    fn flush(&self) {}
}

/// The compute entry points of a WGSL text: the `fn` after each `@compute`.
fn entry_points(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(at) = rest.find("@compute") {
        rest = &rest[at + 8..];
        if let Some(f) = rest.find("fn ") {
            let name: String = rest[f + 3..]
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            out.push(name);
        }
    }
    out
}

type Lost = Arc<Mutex<Vec<String>>>;

fn fail(why: &str) -> ! {
    eprintln!("shader_probe: {why}");
    std::process::exit(1)
}

fn open(adapter: &wgpu::Adapter, lost: &Lost) -> (wgpu::Device, wgpu::Queue) {
    let features = adapter.features() & wgpu::Features::SHADER_F64;
    let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
        label: Some("shader probe"),
        required_features: features,
        required_limits: adapter.limits(),
        experimental_features: wgpu::ExperimentalFeatures::disabled(),
        memory_hints: wgpu::MemoryHints::Performance,
        trace: wgpu::Trace::Off,
    }))
    .unwrap_or_else(|e| fail(&format!("no device: {e}")));
    let sink = lost.clone();
    device.set_device_lost_callback(move |reason, message| {
        if reason != wgpu::DeviceLostReason::Destroyed {
            if let Ok(mut v) = sink.lock() {
                v.push(format!("device lost ({reason:?}): {message}"));
            }
        }
    });
    (device, queue)
}

fn main() {
    log::set_logger(&Stderr).ok();
    log::set_max_level(log::LevelFilter::Warn);
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let backends = match args.first().map(String::as_str) {
        Some("gl") => {
            args.remove(0);
            wgpu::Backends::GL
        }
        Some("vulkan") => {
            args.remove(0);
            wgpu::Backends::VULKAN
        }
        _ => wgpu::Backends::VULKAN,
    };
    if args.is_empty() {
        let mut files: Vec<String> = std::fs::read_dir("shaders/generated")
            .unwrap_or_else(|e| fail(&format!("shaders/generated: {e}")))
            .filter_map(|e| e.ok().map(|e| e.path().display().to_string()))
            .filter(|p| p.ends_with(".wgsl"))
            .collect();
        files.sort();
        args = files;
    }
    let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
    desc.backends = backends;
    let instance = wgpu::Instance::new(desc);
    let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
        power_preference: wgpu::PowerPreference::HighPerformance,
        force_fallback_adapter: false,
        compatible_surface: None,
        apply_limit_buckets: false,
    }))
    .unwrap_or_else(|e| fail(&format!("no adapter: {e}")));
    let info = adapter.get_info();
    println!(
        "adapter: {} ({:?}, {})",
        info.name, info.backend, info.driver_info
    );
    let f64_ok = adapter.features().contains(wgpu::Features::SHADER_F64);
    let lost: Lost = Arc::default();
    let (mut device, _queue) = open(&adapter, &lost);
    for file in &args {
        if file.contains("_f64") && !f64_ok {
            continue;
        }
        let text = match std::fs::read_to_string(file) {
            Ok(t) => t,
            Err(e) => fail(&format!("{file}: {e}")),
        };
        for entry in entry_points(&text) {
            let t = Instant::now();
            let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
            let internal = device.push_error_scope(wgpu::ErrorFilter::Internal);
            let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some(file),
                source: wgpu::ShaderSource::Wgsl(text.as_str().into()),
            });
            let _pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some(&entry),
                layout: None,
                module: &module,
                entry_point: Some(&entry),
                compilation_options: Default::default(),
                cache: None,
            });
            let _ = device.poll(wgpu::PollType::wait_indefinitely());
            let mut said: Vec<String> = [internal, scope]
                .into_iter()
                .filter_map(|g| pollster::block_on(g.pop()).map(|e| e.to_string()))
                .collect();
            said.extend(
                lost.lock()
                    .map(|mut v| std::mem::take(&mut *v))
                    .unwrap_or_default(),
            );
            let ms = t.elapsed().as_secs_f64() * 1e3;
            let verdict = if said.is_empty() {
                "ok".to_string()
            } else {
                said.join("; ")
            };
            println!("{file} {entry}: {ms:.0} ms: {verdict}");
            if verdict.contains("device lost") {
                (device, _) = open(&adapter, &lost);
            }
        }
    }
}
