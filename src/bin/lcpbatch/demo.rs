//! `lcpbatch demo`: the main job (many instances' islands solved on the chosen path, compared with the other path on the same batch) and worlds stepped in time.

use lcpbatch::device::list_adapters;
use lcpbatch::generate::{demo_world, Rng};
use lcpbatch::report::{Device, DeviceKind};
use lcpbatch::{Backend, Error, Precision, Scene, Settings, Solver};

use super::{simulate, solver_for, BackendArg, GpuArgs};
/// Solves `scenes` twice and times the second run: the first dispatch of
/// each GPU kernel compiles it (per island size and kernel, 0.5–9 s on a
/// software adapter without Mesa's shader cache), and a warm-up on a few
/// worlds does not reach every kernel the whole batch uses. Both paths are
/// timed alike; without warm start the second run solves the batch anew.
fn timed(solver: &mut Solver, scenes: &[Scene]) -> Result<(lcpbatch::Report, f64), Error> {
    solver.solve_scenes(scenes)?;
    let t = std::time::Instant::now();
    let r = solver.solve_scenes(scenes)?;
    Ok((r, t.elapsed().as_secs_f64()))
}

/// The precision `device` solves in and why, e.g. "f32 (the GL adapter has
/// no SHADER_F64; …)"; `asked`: `--precision` or LCPBATCH_GPU_PRECISION.
fn precision_and_why(device: &Device, asked: Precision, gpu: &GpuArgs) -> String {
    let why = match (device.kind, asked) {
        (DeviceKind::Cpu, _) => "the CPU path always solves in f64".to_string(),
        (_, Precision::F32 | Precision::F64) => {
            "asked for by --precision or LCPBATCH_GPU_PRECISION".to_string()
        }
        (_, Precision::Auto) => {
            // The device's name starts with the adapter's name and backend.
            let adapters = gpu.settings().map(|s| list_adapters(s.api));
            let backend = adapters
                .unwrap_or_default()
                .into_iter()
                .find(|a| {
                    device
                        .name
                        .starts_with(&format!("{} ({}", a.name, a.backend))
                })
                .map(|a| a.backend.replace("Gl", "GL") + " ")
                .unwrap_or_default();
            if device.precision == Precision::F64 {
                format!("the {backend}adapter has SHADER_F64")
            } else {
                format!(
                    "the {backend}adapter has no SHADER_F64; every answer is still \
                     checked, and solved again in f64, on the CPU"
                )
            }
        }
    };
    format!("{} ({why})", device.precision.name())
}

pub(super) fn demo(
    worlds: usize,
    seed: u64,
    backend: BackendArg,
    gpu: &GpuArgs,
) -> Result<(), Error> {
    let mut rng = Rng::new(seed);
    let scenes: Vec<Scene> = (0..worlds).map(|_| demo_world(&mut rng)).collect();
    let contacts: usize = scenes.iter().map(|s| s.contacts.len()).sum();
    let bodies: usize = scenes.iter().map(|s| s.bodies.len()).sum();
    let asked = gpu.settings()?.precision;
    let mut solver = solver_for(backend.backend(), gpu, crate::settings())?;
    let (report, secs) = timed(&mut solver, &scenes)?;
    let islands = report.islands.len();
    println!(
        "{worlds} simulation instances, {bodies} bodies, {contacts} contacts, {islands} islands"
    );
    println!("{report}");
    println!(
        "precision: {}",
        precision_and_why(&report.device, asked, gpu)
    );
    println!(
        "throughput: {:.0} islands/s end to end ({secs:.3} s: the second of two solves of \
         the batch, so that GPU kernels compiling at their first dispatch are left out)",
        islands as f64 / secs
    );
    // The other path on the same batch, so that the choice can be judged.
    let other = if report.on_gpu() {
        Some(solver_for(Backend::Cpu, gpu, crate::settings())?)
    } else if report.fallback.is_none() && !list_adapters(gpu.settings()?.api).is_empty() {
        Some(solver_for(Backend::Gpu, gpu, crate::settings())?)
    } else {
        None
    };
    if let Some(mut other) = other.filter(|o| o.fallback().is_none()) {
        let (r, t) = timed(&mut other, &scenes)?;
        let kind = match r.device.kind {
            DeviceKind::Cpu => "CPU path",
            DeviceKind::HardwareGpu => "GPU path (hardware)",
            DeviceKind::SoftwareGpu => "GPU path (software adapter)",
        };
        println!(
            "for comparison, {kind} on the same batch (its second solve too): {:.0} islands/s ({t:.3} s), {:.2}x the chosen path",
            islands as f64 / t,
            secs / t
        );
        println!("  device: {}", r.device.name);
        println!("  precision: {}", precision_and_why(&r.device, asked, gpu));
    }
    Ok(())
}

/// The demo's second part, the main job over time: `count` worlds (half
/// resting 4-box stacks, frictionless; half boxes sliding on the ground with
/// μ = 0.5 until friction stops them) stepped together, one contact batch
/// per step of 10 ms, with the plots of energy, penetration, solver error
/// and time per step written to `out`.
pub(super) fn demo_in_time(
    count: usize,
    steps: usize,
    backend: BackendArg,
    gpu: &GpuArgs,
    out: &std::path::Path,
) -> Result<(), Error> {
    if steps == 0 || count == 0 {
        return Ok(());
    }
    let mut worlds = simulate::load_worlds("stack:4", count.div_ceil(2), 1)?;
    for b in worlds.iter_mut().flat_map(|w| w.bodies.iter_mut()) {
        b.friction = 0.0;
    }
    if count >= 2 {
        worlds.extend(simulate::load_worlds("slide", count / 2, 1)?);
    }
    let mut solver = solver_for(
        backend.backend(),
        gpu,
        Settings {
            warm_start: true,
            friction_tolerance: simulate::WORLD_FRICTION_TOLERANCE,
            ..crate::settings()
        },
    )?;
    println!(
        "\nmany worlds in time: {} resting 4-box stacks and {} boxes sliding at μ = 0.5, {steps} steps of 10 ms, one batch per step",
        count.div_ceil(2),
        count / 2
    );
    println!("device: {} ({})", solver.device().name, solver.choice());
    let groups = [
        ("resting stack:4".to_string(), count.div_ceil(2)),
        ("sliding box".to_string(), count / 2),
    ];
    simulate::step_and_write(&mut solver, &mut worlds, &groups, steps, 0.01, out)
}
