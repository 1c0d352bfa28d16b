//! The cone projection iterations on the GPU (`shaders/friction_projected.wgsl`)
//! against their CPU twin (`src/friction/projected.rs`, `apgd.rs`).
//!
//! Stated tolerances:
//! - f64 shaders, iterate by iterate (a fixed number of iterations, no
//!   early stop): every entry of r within 1e-11 of the twin's, relative to
//!   the largest entry, and the same iteration and restart counts. The
//!   arithmetic is the twin's in the same order; what differs is √(a² + b²)
//!   (the shader) against `hypot` (the twin) in the cone projection, a
//!   rounding, which the contraction of the iterations keeps at rounding
//!   size.
//! - f64 shaders, final answers: every island solved (cone error ≤ 1e-8 in
//!   f64) with velocities u = W r + q within 1e-7 of the twin's, relative to
//!   ‖q‖∞ + ‖W‖∞‖r‖∞ (u is unique for the convex problem; r need not be).
//! - f32 shaders: every island solved to the f32 tolerance 1e-5 in f64 (the
//!   GPU's answer kept, or polished by the twin and counted), velocities
//!   within 1e-3 of the f64 twin's.

use super::common::gpu_context;
use crate::friction::projected::solve_checked;
use crate::friction::random::random_problems;
use crate::friction::{
    solve_projected_batch, solve_projected_on_gpu, FrictionOrigin, FrictionProblem,
    ProjectedMethod, ProjectedSettings, MAX_GPU_CONTACTS,
};
use crate::gpu::friction::run_on_gpu;
use crate::gpu::friction_rounds::{AT_CAP, CONVERGED, FIRST_TRIES};
use crate::gpu::kernel::SOFTWARE_ROUND_BUDGET;
use crate::gpu::{GpuContext, Precision};
use crate::{GpuSettings, Status};

/// Random islands of k = 1…16 contacts, `per_k` of each.
fn islands(seed: u64, per_k: usize) -> Vec<FrictionProblem> {
    islands_of(seed, per_k, &(1..=MAX_GPU_CONTACTS).collect::<Vec<_>>())
}

/// Random islands of each size in `sizes`, `per_k` of each (each size is
/// one more kernel for lavapipe to compile, about a second each).
fn islands_of(seed: u64, per_k: usize, sizes: &[usize]) -> Vec<FrictionProblem> {
    sizes
        .iter()
        .flat_map(|&k| random_problems(seed + k as u64, per_k, k))
        .collect()
}

/// The sizes the end-to-end tests use (the iterate test covers all 16).
const SOME_SIZES: [usize; 5] = [1, 2, 3, 7, 16];

fn in_cones(p: &FrictionProblem, r: &[f64]) -> bool {
    crate::friction::projected::tests::in_cones(p, r)
}

/// max |a − b| / max(‖a‖∞, ‖b‖∞).
fn rel_diff(a: &[f64], b: &[f64]) -> f64 {
    let big = a.iter().chain(b).fold(1e-300f64, |m, x| m.max(x.abs()));
    a.iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
        / big
}

/// The shader's iterates after `iterations` iterations (or fewer, where the
/// cone error reaches 1e-10 first) equal the twin's, over several rounds (a
/// round budget of a few iterations). (On an adapter that rounds
/// differently, the tolerance stops the iterations before rounding decides
/// their course: APGD's momentum carried a difference of one rounding in
/// the cone projection (hypot against √(a² + b²), before cone.rs used the
/// shader's formula) to 1e-12 of r, and near the rounding floor APGD's
/// restart test ∇f(y)·(x_new − x) > 0 takes rounding's sign.)
fn iterates_match(ctx: &GpuContext, problems: &[FrictionProblem], method: ProjectedMethod) {
    let all: Vec<usize> = (0..problems.len()).collect();
    // lavapipe runs f64 as the CPU does; a hardware adapter may fuse a
    // multiply and an add.
    let bitwise = ctx.adapter_info().software;
    for (iterations, budget) in [(1u32, None), (9, Some(6_000)), (60, None)] {
        let settings = ProjectedSettings {
            method,
            tolerance: Some(1e-10),
            max_iterations: iterations,
            ..Default::default()
        };
        let gpu = GpuSettings {
            round_budget: budget,
            ..GpuSettings::default()
        };
        let (runs, figures) = run_on_gpu(ctx, problems, &all, None, &settings, &gpu).unwrap();
        if budget.is_some() {
            assert!(figures.rounds > 2, "{method:?}: {} rounds", figures.rounds);
        }
        for (i, (p, run)) in problems.iter().zip(&runs).enumerate() {
            let twin = solve_checked(p, None, &settings, 1e-10);
            let what = format!(
                "{method:?} {iterations} iterations, island {i} (k = {})",
                p.contacts()
            );
            assert!(
                [CONVERGED, AT_CAP].contains(&run.state.status),
                "{what}: {:?}",
                run.state
            );
            assert_eq!(
                run.state.iterations, twin.iterations,
                "{what}: {:?}, error {:e}; twin {:?}",
                run.state, run.error, twin.residuals
            );
            assert_eq!(run.state.restarts, twin.restarts, "{what}");
            let d = rel_diff(&run.r, &twin.r);
            assert!(d <= 1e-11, "{what}: r differs by {d:e}");
            if bitwise {
                assert_eq!(run.r, twin.r, "{what}: not bit for bit");
            }
        }
    }
}

#[test]
fn f64_shader_iterates_are_the_twins() {
    let Some(ctx) = gpu_context(Precision::F64) else {
        return;
    };
    let problems = islands(0xA11, 2);
    for method in ProjectedMethod::ALL {
        iterates_match(&ctx, &problems, method);
    }
}

/// The default rounds grow (FIRST_TRIES steps, then twice as many, each
/// round its own submission with the finished islands dropped); islands
/// that run past the first round continue where it stopped. Their
/// iterates equal those of full-budget rounds (a round budget given: no
/// growing) and the twin's iteration counts, on islands that need more
/// than FIRST_TRIES steps (k = 1, 4: the unrolled kernels; 7: the buffer
/// kernel).
#[test]
fn growing_rounds_give_the_iterates_of_full_rounds() {
    let Some(ctx) = gpu_context(Precision::F64) else {
        return;
    };
    let problems = islands_of(0x5C4, 4, &[1, 4, 7]);
    let all: Vec<usize> = (0..problems.len()).collect();
    let bitwise = ctx.adapter_info().software;
    for method in ProjectedMethod::ALL {
        let settings = ProjectedSettings {
            method,
            tolerance: Some(1e-12),
            max_iterations: 400,
            ..Default::default()
        };
        let (grown, figures) = run_on_gpu(
            &ctx,
            &problems,
            &all,
            None,
            &settings,
            &GpuSettings::default(),
        )
        .unwrap();
        let full = GpuSettings {
            round_budget: Some(SOFTWARE_ROUND_BUDGET),
            ..GpuSettings::default()
        };
        let (flat, _) = run_on_gpu(&ctx, &problems, &all, None, &settings, &full).unwrap();
        let longest = grown.iter().map(|r| r.state.iterations).max().unwrap_or(0);
        assert!(
            longest > 2 * FIRST_TRIES && figures.rounds >= 3,
            "{method:?}: longest island {longest} iterations, {} rounds",
            figures.rounds
        );
        for (i, ((p, g), f)) in problems.iter().zip(&grown).zip(&flat).enumerate() {
            let what = format!("{method:?} island {i} (k = {})", p.contacts());
            assert_eq!(g.state, f.state, "{what}");
            let twin = solve_checked(p, None, &settings, 1e-12);
            assert_eq!(g.state.iterations, twin.iterations, "{what}");
            let d = rel_diff(&g.r, &f.r);
            assert!(d <= 1e-11, "{what}: r differs by {d:e}");
            if bitwise {
                assert_eq!(g.r, f.r, "{what}: not bit for bit");
            }
        }
    }
}

/// The friction batches' buffers are written in place, a new one at its
/// creation (`kept_written` on a fresh context): a shader's view of them,
/// read back, is what was written, and 0 where nothing was; on a software
/// adapter the device maps storage buffers themselves (no staging copy).
#[test]
fn filled_storage_buffers_hold_what_was_written() {
    let Some(ctx) = gpu_context(Precision::F64) else {
        return;
    };
    if ctx.adapter_info().software {
        assert!(ctx
            .device
            .features()
            .contains(wgpu::Features::MAPPABLE_PRIMARY_BUFFERS));
    }
    let written: Vec<u8> = (1..=24).collect();
    let role = crate::gpu::buffers::Role::FrictionValues;
    let buffer = ctx
        .kept_written(role, 64, |mut view| {
            view.slice(16..40).copy_from_slice(&written);
        })
        .unwrap();
    let back = ctx
        .submit_and_read(ctx.encoder("test"), &[(&buffer, 64)])
        .unwrap();
    let mut expected = vec![0u8; 64];
    expected[16..40].copy_from_slice(&written);
    assert_eq!(back[0], expected);
}

/// A buffer given back is written again in place by the next batch that
/// fits it (software adapters), and a batch after a larger one (its
/// buffers kept, an earlier batch's bytes in them) gives the raw answers,
/// bit for bit, that it gives on a context of its own.
#[test]
fn kept_buffers_are_written_again_and_change_no_answer() {
    let Some(ctx) = gpu_context(Precision::F64) else {
        return;
    };
    let role = crate::gpu::buffers::Role::FrictionValues;
    let first = ctx.kept_written(role, 64, |mut view| view.fill(7)).unwrap();
    let kept = first.clone();
    ctx.keep(role, first);
    let again = ctx
        .kept_written(role, 48, |mut view| view.slice(..8).fill(9))
        .unwrap();
    let back = ctx
        .submit_and_read(ctx.encoder("test"), &[(&again, 64)])
        .unwrap();
    if ctx.adapter_info().software {
        assert!(again == kept, "the kept buffer is written again");
        // Written where asked; the rest keeps the earlier batch's bytes.
        assert_eq!(&back[0][..8], &[9; 8]);
        assert_eq!(&back[0][8..], &[7; 56]);
    } else {
        assert_eq!(&back[0][..8], &[9; 8]);
    }

    // The larger batch warm-started away from 0 (its starts stay in the
    // kept vectors), the smaller one cold: within twice, so it takes them.
    let sizes = [1, 2, 4];
    let large = islands_of(0xB16, 40, &sizes);
    let small = islands_of(0x5A11, 25, &sizes);
    let away: Vec<Vec<f64>> = large.iter().map(|p| vec![1.0; p.dim()]).collect();
    let settings = ProjectedSettings {
        method: ProjectedMethod::Apgd,
        ..Default::default()
    };
    let gpu = GpuSettings::default();
    let all = |p: &[FrictionProblem]| (0..p.len()).collect::<Vec<_>>();
    run_on_gpu(&ctx, &large, &all(&large), Some(&away), &settings, &gpu).unwrap();
    let (after, _) = run_on_gpu(&ctx, &small, &all(&small), None, &settings, &gpu).unwrap();
    let fresh = gpu_context(Precision::F64).unwrap();
    let (alone, _) = run_on_gpu(&fresh, &small, &all(&small), None, &settings, &gpu).unwrap();
    assert_eq!(after, alone);
}

/// An f64 island stopped at the iteration cap is kept as the twin ends it
/// at the same cap (`not_converged`, about the twin's error), not polished
/// or solved again on the CPU with the budget a second time.
#[test]
fn f64_islands_at_the_cap_end_as_the_twin_ends_them() {
    let Some(ctx) = gpu_context(Precision::F64) else {
        return;
    };
    let problems = islands_of(0xCA9, 20, &[1, 4]);
    for method in ProjectedMethod::ALL {
        let settings = ProjectedSettings {
            method,
            max_iterations: 3,
            ..Default::default()
        };
        let cpu = solve_projected_batch(&problems, None, &settings, 0).unwrap();
        let (out, figures) =
            solve_projected_on_gpu(&ctx, &problems, None, &settings, &GpuSettings::default())
                .unwrap();
        let capped = cpu.iter().filter(|c| c.status == Status::NotConverged);
        assert!(
            capped.count() >= problems.len() / 2,
            "{method:?}: few at the cap"
        );
        assert_eq!((figures.polished, figures.repaired), (0, 0), "{method:?}");
        for (i, (g, c)) in out.iter().zip(&cpu).enumerate() {
            let what = format!("{method:?} island {i}");
            assert_eq!(g.status, c.status, "{what}");
            assert_eq!(g.iterations, c.iterations, "{what}");
            let (eg, ec) = (g.residuals.cone_error, c.residuals.cone_error);
            assert!((eg - ec).abs() <= 1e-9 * (1.0 + ec), "{what}: {eg} vs {ec}");
        }
    }
}

/// Final answers of the GPU path against the twin's, at `precision`.
fn final_answers_match(precision: Precision, u_tol: f64) {
    let Some(ctx) = gpu_context(precision) else {
        return;
    };
    let problems = islands_of(0xB22, 8, &SOME_SIZES);
    let gpu = GpuSettings::default();
    for method in ProjectedMethod::ALL {
        let settings = ProjectedSettings {
            method,
            max_iterations: 20_000,
            ..Default::default()
        };
        let cpu = solve_projected_batch(&problems, None, &settings, 0).unwrap();
        let (out, figures) =
            solve_projected_on_gpu(&ctx, &problems, None, &settings, &gpu).unwrap();
        let tol = if precision == Precision::F64 {
            1e-8
        } else {
            1e-5
        };
        eprintln!(
            "{} {method:?}: gpu {} polished {} repaired {} (rounds {}, dispatches {})",
            precision.name(),
            figures.gpu,
            figures.polished,
            figures.repaired,
            figures.rounds,
            figures.dispatches
        );
        for (i, ((p, g), c)) in problems.iter().zip(&out).zip(&cpu).enumerate() {
            let what = format!(
                "{method:?} island {i} (k = {}, {:?})",
                p.contacts(),
                figures.origins[i]
            );
            if c.status != Status::Solved {
                // The twin's cap: the GPU (or its repair) can be no better.
                continue;
            }
            assert_eq!(g.status, Status::Solved, "{what}: {:?}", g.residuals);
            assert!(g.residuals.cone_error <= tol, "{what}");
            assert!(in_cones(p, &g.r), "{what}: {:?}", g.r);
            let d = crate::friction::projected::tests::velocity_diff(p, g, c);
            assert!(d <= u_tol, "{what}: u differs by {d:e}");
        }
        if precision == Precision::F64 {
            // The f64 shader is the twin: nothing to polish where the twin converged.
            assert_eq!(
                figures.gpu + figures.repaired,
                problems.len(),
                "{figures:?}"
            );
        }
        assert!(figures.gpu > problems.len() / 2, "{figures:?}");
        // Warm start from the answers: at most one iteration, kept as is.
        let starts: Vec<Vec<f64>> = out.iter().map(|s| s.r.clone()).collect();
        let (warm, wf) =
            solve_projected_on_gpu(&ctx, &problems, Some(&starts), &settings, &gpu).unwrap();
        for (i, (w, g)) in warm.iter().zip(&out).enumerate() {
            if g.status == Status::Solved && wf.origins[i] == FrictionOrigin::Gpu {
                assert!(
                    wf.gpu_iterations[i] <= 1,
                    "{method:?} island {i}: {}",
                    wf.gpu_iterations[i]
                );
                assert_eq!(w.status, Status::Solved);
            }
        }
        assert!(wf.gpu >= figures.gpu, "{wf:?}");
    }
}

#[test]
fn f64_shader_answers_are_the_twins() {
    final_answers_match(Precision::F64, 1e-7);
}

#[test]
fn f32_shader_answers_meet_the_f32_tolerance() {
    final_answers_match(Precision::F32, 1e-3);
}

#[test]
fn splitting_invalid_and_large_islands() {
    let Some(ctx) = gpu_context(Precision::F64) else {
        return;
    };
    let mut problems = islands_of(0xC33, 3, &SOME_SIZES);
    problems.extend(random_problems(5, 2, MAX_GPU_CONTACTS + 2));
    let mut bad = problems[3].clone();
    bad.mu[0] = f64::NAN;
    problems.push(bad);
    let settings = ProjectedSettings::default();
    let (whole, wf) =
        solve_projected_on_gpu(&ctx, &problems, None, &settings, &GpuSettings::default()).unwrap();
    let split = GpuSettings {
        max_binding_bytes: Some(8 * 1024),
        max_workgroups: Some(1),
        ..GpuSettings::default()
    };
    let (parts, pf) = solve_projected_on_gpu(&ctx, &problems, None, &settings, &split).unwrap();
    assert!(
        pf.chunks > 3 && wf.chunks == 1,
        "{} vs {} chunks",
        pf.chunks,
        wf.chunks
    );
    assert_eq!(whole, parts, "the answers do not depend on the splitting");
    let n = problems.len();
    assert_eq!(wf.origins[n - 1], FrictionOrigin::Invalid);
    assert_eq!(whole[n - 1].status, Status::InvalidInput);
    assert_eq!(wf.origins[n - 3..n - 1], [FrictionOrigin::CpuFallback; 2]);
    assert_eq!((wf.invalid, wf.cpu_fallback), (1, 2));
    // A bad warm start is an error naming it.
    let mut warm: Vec<Vec<f64>> = problems.iter().map(|p| vec![0.0; p.dim()]).collect();
    warm[2].pop();
    let e = solve_projected_on_gpu(
        &ctx,
        &problems,
        Some(&warm),
        &settings,
        &GpuSettings::default(),
    )
    .unwrap_err();
    assert!(
        e.to_string().contains("problem 2") && e.to_string().contains("r0"),
        "{e}"
    );
}

#[test]
fn frictionless_islands_on_the_gpu_give_the_lcp_answer() {
    let Some(ctx) = gpu_context(Precision::Auto) else {
        return;
    };
    let mut problems = islands_of(0xD44, 3, &SOME_SIZES);
    for p in &mut problems {
        p.mu.iter_mut().for_each(|m| *m = 0.0);
    }
    let report = crate::friction::projected::tests::lemke_on_the_normal_blocks(&problems);
    let settings = ProjectedSettings {
        max_iterations: 50_000,
        ..Default::default()
    };
    let (out, _) =
        solve_projected_on_gpu(&ctx, &problems, None, &settings, &GpuSettings::default()).unwrap();
    let tol = if ctx.precision() == Precision::F64 {
        1e-8
    } else {
        1e-5
    };
    for (i, (s, l)) in out.iter().zip(&report.islands).enumerate() {
        assert_eq!(s.status, Status::Solved, "island {i}");
        let k = s.r.len() / 3;
        assert!((0..k).all(|c| s.r[3 * c + 1] == 0.0 && s.r[3 * c + 2] == 0.0));
        // w = u_n is unique: compare against the scale of its terms.
        let un: Vec<f64> = (0..k).map(|c| s.u[3 * c]).collect();
        let scale = problems[i]
            .q
            .iter()
            .chain(&s.r)
            .fold(1.0f64, |m, x| m.max(x.abs()));
        let dw = un
            .iter()
            .zip(&l.solution.w)
            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
        assert!(dw <= 100.0 * tol * scale, "island {i}: w differs by {dw:e}");
    }
}
