//! The projected friction methods (jacobi, pgs, apgd) through the one door:
//! on the CPU (the twin) and on the GPU where one is open, every answer
//! solved to the cone complementarity residual, the Coulomb error beside it,
//! the GPU's figures in the report.

use crate::friction::random::random_problems;
use crate::settings::{Backend, Settings};
use crate::{FrictionMethod, GpuContext, Solver, Status};

use super::common::gpu_settings_or_skip;

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
        for (a, b) in r.friction.iter().zip(&cpu.friction) {
            assert_eq!(a.status(), Status::Solved, "{method:?} on the GPU");
            // The same convex problem: u is unique where W is definite.
            let du = a
                .solution
                .u
                .iter()
                .zip(&b.solution.u)
                .map(|(x, y)| (x - y).abs());
            assert!(du.fold(0.0, f64::max) < 1e-5, "{method:?}");
        }
    }
}
