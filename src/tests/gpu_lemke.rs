//! The Lemke kernel (`shaders/lemke.wgsl`) against its CPU twin
//! (`lemke_textbook_basis`), and methods Lemke and Auto on the GPU against
//! the CPU path: the bench families and the Siconos problems of n ≤ 16.

use crate::cpu::lemke::{lemke_textbook_basis, LemkeSettings};
use crate::generate::families::{family_batch, BenchFamily};
use crate::gpu::batch::enumerate_on_gpu;
use crate::gpu::layout::{FOUND, GAVE_UP};
use crate::gpu::{GpuSolveSettings, Precision};
use crate::io::{read_input, Input, LcpBatchOutput};
use crate::lcp::LcpSolution;
use crate::report::Report;
use crate::settings::{Backend, Method, Settings};
use crate::solver::textbook_checked;
use crate::{GpuContext, Lcp, Solver, Status};

use super::common;
use super::common::gpu_context as context;

fn lemke_only() -> GpuSolveSettings {
    GpuSolveSettings {
        method: Method::Lemke,
        ..Default::default()
    }
}

/// Islands of n = 1…16: random physical islands (mass ratios 1…1e4),
/// resting boxes, the chain, demo worlds, the 3×3 walk-through.
fn islands() -> Vec<Lcp> {
    common::physical_islands(22, 3000, 16)
}

/// In f64 the kernel ends on `lemke_textbook_basis`' basis after as many
/// pivots, and every basis it names passes the CPU path's f64 check where
/// the CPU's does.
#[test]
fn lemke_kernel_ends_on_the_cpu_textbook_basis() {
    let Some(ctx) = context(Precision::F64) else {
        return;
    };
    let lcps = islands();
    let refs: Vec<&Lcp> = lcps.iter().collect();
    let (out, _) = enumerate_on_gpu(&ctx, &refs, &lemke_only()).unwrap();
    let e = GpuSolveSettings::default().enumeration;
    let (mut same, mut differ, mut gave_up, mut largest) = (0, 0, 0, 0);
    for (i, (lcp, o)) in lcps.iter().zip(&out).enumerate() {
        let (cpu, pivots) = lemke_textbook_basis(lcp, &LemkeSettings::default());
        let r = &o.result;
        assert!(
            r.status == FOUND || r.status == GAVE_UP,
            "island {i}: {r:?}"
        );
        if r.status == GAVE_UP {
            gave_up += 1;
            continue;
        }
        if cpu == Some(r.mask) {
            assert_eq!(r.visited as u64, pivots, "island {i}: pivots");
            same += 1;
            largest = largest.max(lcp.n());
        } else {
            differ += 1;
            println!(
                "island {i} (n = {}): GPU {:#x}, CPU {cpu:?}",
                lcp.n(),
                r.mask
            );
        }
        let mut gpu_answer = LcpSolution::invalid(0);
        let mut cpu_answer = LcpSolution::invalid(0);
        let gpu_ok = textbook_checked(lcp, r.mask, r.visited.into(), &e, &mut gpu_answer);
        let cpu_ok = cpu.is_some_and(|m| textbook_checked(lcp, m, pivots, &e, &mut cpu_answer));
        assert!(
            gpu_ok || !cpu_ok,
            "island {i}: the GPU's basis fails the check"
        );
    }
    println!(
        "f64 Lemke kernel: {} islands, {same} on the CPU's basis, {differ} on another, {gave_up} gave up",
        lcps.len()
    );
    assert_eq!(largest, 16);
    assert!(differ * 200 <= lcps.len(), "{differ} bases differ");
    assert!(gave_up * 100 <= lcps.len(), "{gave_up} gave up");
}

/// A batch through a solver at `backend` and `method` (the environment's
/// GPU settings in `precision`), as the CLI writes it, and the report.
fn solve(lcps: &[Lcp], backend: Backend, method: Method, ctx: Option<GpuContext>) -> Report {
    let settings = Settings::new(backend, method);
    let mut s = match ctx {
        Some(c) => Solver::with_device(settings, c).unwrap(),
        None => Solver::new(settings).unwrap(),
    };
    s.solve_lcps(lcps).unwrap()
}

/// The Siconos LCPs of n ≤ 16, if the conformance data are present.
fn siconos_small() -> Vec<Lcp> {
    let Some(dir) = super::common::siconos_dir() else {
        return Vec::new();
    };
    let paths = super::common::dat_files(&dir);
    let mut lcps = Vec::new();
    for p in paths {
        if let Input::Lcps(v) = read_input(&p).unwrap() {
            lcps.extend(v.into_iter().filter(|l| l.n() <= 16));
        }
    }
    lcps
}

/// Method Auto on the GPU (f64) gives the CPU path's output bytes on four
/// bench families and the Siconos problems of n ≤ 16, the GPU's Lemke
/// settling most of what prediction leaves. Method Lemke gives the CPU's
/// statuses and solutions: its GPU answers are the textbook basis
/// re-solved in f64 (Auto's answer), where the CPU's `lemke` may keep its
/// tableau's z, which differs in the last bits (counted, not asserted).
#[test]
fn lemke_and_auto_on_the_gpu_give_the_cpu_answers() {
    if context(Precision::F64).is_none() {
        return;
    }
    let mut batches: Vec<(String, Vec<Lcp>)> = [
        BenchFamily::WellConditioned,
        BenchFamily::MassRatio,
        BenchFamily::RestingStacks,
        BenchFamily::MixedN,
    ]
    .into_iter()
    .map(|f| (format!("{f:?}"), family_batch(f, 7, 400)))
    .collect();
    let siconos = siconos_small();
    if !siconos.is_empty() {
        batches.push(("siconos".into(), siconos));
    }
    for (name, lcps) in &batches {
        for method in [Method::Auto, Method::Lemke] {
            let cpu = solve(lcps, Backend::Cpu, method, None);
            let gpu = solve(lcps, Backend::Gpu, method, context(Precision::F64));
            assert!(gpu.on_gpu(), "{name}");
            let (g, k) = (LcpBatchOutput::of(&gpu), LcpBatchOutput::of(&cpu));
            let mut differ = 0;
            for (i, (a, b)) in g.problems.iter().zip(&k.problems).enumerate() {
                let (ja, jb) = (to_json(a), to_json(b));
                if ja == jb {
                    continue;
                }
                differ += 1;
                assert_eq!(a.status, b.status, "{name} problem {i}");
                if method == Method::Auto {
                    // Auto: the CPU's basis, z within rounding (the GPU's
                    // z accepted by the f64 check, the CPU's re-solved).
                    assert_eq!(a.basis, b.basis, "{name} problem {i}: {ja} ≠ {jb}");
                    let d = common::z_rel_diff(&a.z, &b.z);
                    assert!(d <= 1e-12, "{name} problem {i}: z differs by {d:e}");
                }
                let scale = b.z.iter().fold(1.0f64, |m, v| m.max(v.abs()));
                let dz = common::max_diff(&a.z, &b.z);
                assert!(
                    dz <= 1e-9 * scale,
                    "{name} problem {i}: z differs by {dz:e}"
                );
            }
            let c = &gpu.counts;
            println!(
                "{name} {method:?}: {} islands, lemke_gpu {}, lemke (CPU) {}, repaired {}, {differ} not the CPU's bytes",
                lcps.len(),
                c.lemke_gpu,
                c.lemke,
                c.repaired
            );
            if name != "siconos" {
                assert!(c.lemke_gpu > 0, "{name} {method:?}");
            }
        }
    }
}

fn to_json(o: &crate::io::LcpOutput) -> String {
    serde_json::to_string(o).unwrap()
}

/// The f32 kernel (GL llvmpipe, or lavapipe at f32): every answer checked
/// in f64, solved where the CPU's is.
#[test]
fn f32_lemke_answers_are_checked_solutions() {
    let Some(ctx) = context(Precision::F32) else {
        return;
    };
    let lcps = islands();
    let cpu = solve(&lcps, Backend::Cpu, Method::Auto, None);
    let gpu = solve(&lcps, Backend::Gpu, Method::Auto, Some(ctx));
    println!("f32 Lemke kernel: {gpu}");
    assert!(gpu.counts.lemke_gpu > 0);
    for (i, (g, c)) in gpu.islands.iter().zip(&cpu.islands).enumerate() {
        assert_eq!(g.status(), c.status(), "island {i}");
        if g.status() == Status::Solved {
            assert!(g.error() <= 1e-8, "island {i}: error {:e}", g.error());
        }
    }
}
