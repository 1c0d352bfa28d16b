//! The projected friction methods (jacobi, pgs, apgd) through the one door:
//! on the CPU (the twin) and on the GPU where one is open, every answer
//! solved to the cone complementarity residual, the Coulomb error beside it,
//! the GPU's figures in the report.

use crate::friction::random::random_problems;
use crate::settings::{Backend, Settings};
use crate::{FrictionMethod, GpuContext, Precision, Solver, Status};

use super::common::gpu_settings_or_skip;

/// The cone error the GPU's `solved` islands of `r` meet: the projected
/// settings' tolerance at the precision the solver's shaders ran in
/// (f32 where the adapter has no SHADER_F64).
fn gpu_tolerance(solver: &Solver, r: &crate::Report) -> f64 {
    let projected = solver.settings().friction().projected_settings();
    crate::gpu::friction::tolerance_for(&projected, r.device.precision)
}

fn settings(method: FrictionMethod) -> Settings {
    Settings {
        friction_method: method,
        friction_max_iterations: 5_000,
        ..Settings::new(Backend::Cpu, crate::Method::Auto)
    }
}

#[test]
fn projected_methods_solve_through_the_door_on_cpu_and_gpu() {
    let problems: Vec<_> = [1, 3, 8]
        .iter()
        .flat_map(|&k| random_problems(40 + k as u64, 6, k))
        .collect();
    let gpu = gpu_settings_or_skip();
    for method in [
        FrictionMethod::Jacobi,
        FrictionMethod::Pgs,
        FrictionMethod::Apgd,
    ] {
        let cpu = Solver::new(settings(method))
            .unwrap()
            .solve_friction(&problems)
            .unwrap();
        assert!(!cpu.on_gpu());
        for isl in &cpu.friction {
            assert_eq!(isl.status(), Status::Solved, "{method:?} on the CPU");
            assert!(isl.solution.residuals.cone_error <= 1e-8);
            assert_eq!(isl.method(), method);
        }
        let Some(g) = gpu.clone() else {
            continue;
        };
        let device = GpuContext::open(&g).unwrap();
        let mut s = Solver::with_device(
            Settings {
                gpu: g,
                ..settings(method)
            },
            device,
        )
        .unwrap();
        let r = s.solve_friction(&problems).unwrap();
        assert!(r.on_gpu(), "{method:?}: {:?}", r.fallback);
        assert!(r.gpu.is_some_and(|f| f.dispatches > 0));
        let tol = gpu_tolerance(&s, &r);
        for (a, b) in r.friction.iter().zip(&cpu.friction) {
            assert_eq!(a.status(), Status::Solved, "{method:?} on the GPU");
            let e = a.solution.residuals.cone_error;
            assert!(e <= tol, "{method:?}: cone error {e:e} above {tol:e}");
            // The same convex problem: u is unique where W is definite,
            // here to within 1e3 times the tolerance (1e-5 at f64's 1e-8;
            // f32 measured up to 1.2e-3 on GL llvmpipe, island 17 with
            // ‖r‖∞ = 76).
            let du = a
                .solution
                .u
                .iter()
                .zip(&b.solution.u)
                .map(|(x, y)| (x - y).abs());
            let du = du.fold(0.0, f64::max);
            assert!(du < 1e3 * tol, "{method:?}: u differs by {du:e}");
        }
    }
}

/// A few small scenes with friction (a box sliding on the ground, one on a
/// steep incline, a stack of two, μ = 0.5) and one without.
fn friction_scenes() -> Vec<crate::Scene> {
    use crate::generate::friction::{box_on_ground_moving, box_on_incline, box_stack};
    let mut plain = box_stack(1, 0.0, 0.1, 0.0);
    for c in &mut plain.contacts {
        c.friction = 0.0;
    }
    vec![
        box_on_ground_moving(1.0, 0.5, glam::DVec3::new(2.0, -0.1, 0.5)),
        plain,
        box_on_incline(0.7, 0.5, 0.05),
        box_stack(2, 0.5, 0.1, 0.3),
    ]
}

/// Largest |a − b| / (1 + |b|) over the bodies' velocities after.
fn velocity_deviation(a: &crate::Report, b: &crate::Report) -> f64 {
    let mut worst = 0.0f64;
    for (sa, sb) in a.scenes.iter().zip(&b.scenes) {
        for (va, vb) in sa.bodies.iter().zip(&sb.bodies) {
            let pa = va.velocity.iter().chain(&va.angular_velocity);
            let pb = vb.velocity.iter().chain(&vb.angular_velocity);
            for (x, y) in pa.zip(pb) {
                worst = worst.max((x - y).abs() / (1.0 + y.abs()));
            }
        }
    }
    worst
}

/// Scenes with friction through `Backend::Gpu` with a projected method:
/// assembled and iterated on the GPU, every island solved to the cone
/// error tolerance of the shaders' precision (checked in f64), the
/// velocities after equal to the CPU's (same method, same convex problem:
/// u unique where W is definite, and the bodies' velocities are unique
/// even where it is not) within 100 times that tolerance relative (1e-6
/// in f64); the report says what ran where. The exact methods stay on the
/// CPU with the GPU open.
#[test]
fn scenes_with_friction_run_on_the_gpu_with_the_gpu_backend() {
    let Some(g) = gpu_settings_or_skip() else {
        return;
    };
    let scenes = friction_scenes();
    let method = FrictionMethod::Apgd;
    let cpu = Solver::new(settings(method))
        .unwrap()
        .solve_scenes(&scenes)
        .unwrap();
    assert!(
        cpu.choice.contains("friction: apgd on the CPU"),
        "{}",
        cpu.choice
    );
    let gpu_settings = Settings {
        backend: Backend::Gpu,
        gpu: g,
        ..settings(method)
    };
    let mut solver = Solver::new(gpu_settings.clone()).unwrap();
    let r = solver.solve_scenes(&scenes).unwrap();
    assert!(r.on_gpu(), "{:?}", r.fallback);
    let tol = gpu_tolerance(&solver, &r);
    assert!(
        r.choice
            .contains("friction: apgd on the GPU, assembled on the GPU"),
        "{}",
        r.choice
    );
    assert!(r.gpu.as_ref().is_some_and(|f| f.dispatches > 0));
    assert_eq!(r.friction.len(), cpu.friction.len());
    assert_eq!(r.friction.len(), 3, "one island per frictional scene");
    for isl in &r.friction {
        assert_eq!(isl.status(), Status::Solved);
        let e = isl.solution.residuals.cone_error;
        assert!(e <= tol, "cone error {e:e} above {tol:e}");
        assert_eq!(isl.method(), method);
    }
    assert!(r.scenes[1].friction.is_none(), "the frictionless scene");
    // 1e2 times the tolerance: 1e-6 at f64's 1e-8 (f32 measured 2.3e-5 on
    // GL llvmpipe).
    let dev = velocity_deviation(&r, &cpu);
    assert!(
        dev < 1e2 * tol,
        "GPU and CPU velocities after differ by {dev:e}"
    );

    // Exact Coulomb: on the CPU even with the GPU open, the same answers.
    let exact = Settings {
        friction_method: FrictionMethod::Auto,
        ..gpu_settings
    };
    let r = Solver::new(exact.clone())
        .unwrap()
        .solve_scenes(&scenes)
        .unwrap();
    assert!(
        r.choice.contains("on the CPU (the exact Coulomb methods"),
        "{}",
        r.choice
    );
    let cpu = Solver::new(Settings {
        backend: Backend::Cpu,
        ..exact
    })
    .unwrap()
    .solve_scenes(&scenes)
    .unwrap();
    assert_eq!(velocity_deviation(&r, &cpu), 0.0);
}

/// With too few iterations for the GPU (Jacobi, 3 sweeps, f32 shaders,
/// whose answers are not the twin's: an f64 shader's answer at the cap is
/// kept, see `gpu_friction`) the f64 check sends islands to the CPU: each
/// is polished (the CPU continues from the GPU's answer) or repaired
/// (solved again from its start), counted in the report and named in its
/// choice; no island is called solved above the f32 tolerance.
#[test]
fn gpu_friction_islands_that_miss_the_tolerance_are_polished_and_counted() {
    let Some(mut g) = gpu_settings_or_skip() else {
        return;
    };
    g.precision = Precision::F32;
    // Without the frictionless scene: the LCP path's counts would add in.
    let mut scenes = friction_scenes();
    scenes.remove(1);
    let mut solver = Solver::new(Settings {
        backend: Backend::Gpu,
        gpu: g,
        friction_max_iterations: 3,
        ..settings(FrictionMethod::Jacobi)
    })
    .unwrap();
    let r = solver.solve_scenes(&scenes).unwrap();
    assert!(r.on_gpu(), "{:?}", r.fallback);
    let sent_back = r.counts.polished + r.counts.repaired;
    assert!(sent_back >= 1, "{}", r.choice);
    assert!(
        r.choice
            .contains(&format!("{} polished", r.counts.polished))
            && r.choice
                .contains(&format!("{} repaired", r.counts.repaired)),
        "{}",
        r.choice
    );
    for isl in &r.friction {
        let e = isl.solution.residuals.cone_error;
        assert_eq!(isl.status() == Status::Solved, e <= 1e-5, "error {e:e}");
    }
}
