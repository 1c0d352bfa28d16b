//! The workgroup enumeration kernel (`shaders/enumeration_workgroup.wgsl`:
//! one workgroup per island, the bases of each popcount in waves of 64)
//! against the CPU twin (`cpu::enumeration::enumerate`) and the per-island
//! elimination kernel: same status, basis, z and counters in f64; same
//! validated answers in f32. Speeds: `cargo bench --bench gpu_path --
//! gpu_workgroup` (BENCHMARKS.md).

use crate::cpu::enumeration::{enumerate, EnumerationSettings};
use crate::generate::families::islands_of_size;
use crate::generate::stress::{generate, Family};
use crate::gpu::batch::{enumerate_on_gpu, EnumerationKernel};
use crate::gpu::layout::{FOUND, NONE, RELAXED};
use crate::gpu::{solve_lcp_batch, GpuContext, GpuSolveSettings, Precision};
use crate::{Lcp, Status};

use super::common;
use super::common::gpu_context as context;

/// Random physical islands of exactly n = 8…16 contacts (`per_n` each),
/// resting stacks and chains (n ≤ 16), and small hand-made problems with
/// no valid basis.
fn islands(per_n: usize, seed: u64) -> Vec<Lcp> {
    let mut lcps = Vec::new();
    for n in 8..=16 {
        lcps.extend(islands_of_size(n, per_n, seed));
    }
    for family in [Family::RestingStacks, Family::Chains] {
        lcps.extend(
            generate(family, seed, 60)
                .into_iter()
                .map(|c| c.lcp)
                .filter(|l| l.n() <= 16),
        );
    }
    lcps.extend(common::seed_002_problems());
    lcps.push(Lcp::new(vec![-1.0, 0.0, 0.0, -1.0], vec![-1.0, -1.0]).unwrap());
    lcps
}

fn kernel(kernel: EnumerationKernel) -> GpuSolveSettings {
    GpuSolveSettings {
        kernel,
        predict: false,
        ..Default::default()
    }
}

/// Compares the workgroup kernel's raw output with the CPU twin and the
/// elimination kernel's raw output, island by island.
fn check_f64(ctx: &GpuContext, lcps: &[Lcp], settings: &GpuSolveSettings) -> usize {
    let refs: Vec<&Lcp> = lcps.iter().collect();
    let (w, ws) = enumerate_on_gpu(ctx, &refs, settings).unwrap();
    let (e, _) = enumerate_on_gpu(ctx, &refs, &kernel(EnumerationKernel::Elimination)).unwrap();
    println!("{} islands, {} rounds", lcps.len(), ws.rounds);
    let es = EnumerationSettings::default();
    let mut found = 0;
    for (i, (l, (o, oe))) in lcps.iter().zip(w.iter().zip(&e)).enumerate() {
        let cpu = enumerate(l, &es).unwrap();
        let r = &o.result;
        // The elimination kernel: the same record and the same z, bit for bit.
        assert_eq!(r.mask, oe.result.mask, "island {i} (n = {})", l.n());
        assert_eq!(r.status, oe.result.status, "island {i}");
        assert_eq!(r.visited, oe.result.visited, "island {i}");
        assert_eq!(r.singular, oe.result.singular, "island {i}");
        assert_eq!(o.z, oe.z, "island {i}");
        // The CPU twin: status, basis, z, counters.
        assert_eq!(r.visited as u64, cpu.counters.bases_visited, "island {i}");
        assert_eq!(r.singular as u64, cpu.counters.singular_bases, "island {i}");
        match cpu.status {
            Status::Solved => {
                assert!(
                    r.status == FOUND || r.status == RELAXED,
                    "island {i}: {r:?}"
                );
                found += (r.status == FOUND) as usize;
                assert_eq!(Some(r.mask), cpu.basis, "island {i}: {l:?}");
                let scale = cpu.z.iter().fold(1.0f64, |m, v| m.max(v.abs()));
                for (a, b) in o.z.iter().zip(&cpu.z) {
                    assert!(
                        (a - b).abs() <= 1e-12 * scale,
                        "island {i}: {:?} vs {:?}",
                        o.z,
                        cpu.z
                    );
                }
            }
            _ => assert_eq!(r.status, NONE, "island {i}: {r:?}"),
        }
    }
    found
}

/// f64: ≥ 500 islands n = 8…16 plus stress families; the workgroup kernel's
/// status, basis, z and counters are the CPU twin's (and the elimination
/// kernel's, bit for bit).
#[test]
fn workgroup_kernel_equals_the_cpu_twin_in_f64() {
    let Some(ctx) = context(Precision::F64) else {
        return;
    };
    let lcps = islands(56, 4);
    assert!(lcps.len() >= 500 + 4, "{}", lcps.len());
    let big = lcps.iter().filter(|l| l.n() >= 8).count();
    assert!(big >= 500, "{big} islands with n ≥ 8");
    let found = check_f64(&ctx, &lcps, &kernel(EnumerationKernel::Workgroup));
    // Not only trivial answers: most islands have a valid basis.
    assert!(found >= lcps.len() / 2, "{found} of {}", lcps.len());
}

/// f64 with the smallest round budget: one wave per round, so every wave
/// resumes from the saved (mask, rank) and levels end between rounds; the
/// answers and counters do not change.
#[test]
fn workgroup_kernel_resumes_across_rounds() {
    let Some(ctx) = context(Precision::F64) else {
        return;
    };
    let mut lcps = Vec::new();
    for n in 8..=10 {
        lcps.extend(islands_of_size(n, 12, 9));
    }
    lcps.extend(
        generate(Family::Chains, 9, 10)
            .into_iter()
            .map(|c| c.lcp)
            .filter(|l| l.n() <= 10),
    );
    lcps.push(Lcp::new(vec![-1.0, 0.0, 0.0, -1.0], vec![-1.0, -1.0]).unwrap());
    let settings = GpuSolveSettings {
        round_budget: Some(1),
        ..kernel(EnumerationKernel::Workgroup)
    };
    let refs: Vec<&Lcp> = lcps.iter().collect();
    let (_, stats) = enumerate_on_gpu(&ctx, &refs, &settings).unwrap();
    // n ≥ 8 islands need at least levels 0, 1, 2 (three waves) to be found.
    assert!(stats.rounds >= 3, "{} rounds", stats.rounds);
    check_f64(&ctx, &lcps, &settings);
}

/// f32 (after the f64 validation): whole batches give the elimination
/// kernel's statuses, bases and z.
#[test]
fn workgroup_kernel_batches_equal_elimination_batches_in_f32() {
    let Some(ctx) = context(Precision::F32) else {
        return;
    };
    let lcps = islands(30, 11);
    let e = solve_lcp_batch(&ctx, &lcps, &kernel(EnumerationKernel::Elimination)).unwrap();
    let w = solve_lcp_batch(&ctx, &lcps, &kernel(EnumerationKernel::Workgroup)).unwrap();
    println!("elimination:\n{e}\nworkgroup:\n{w}");
    assert_eq!(e.statuses, w.statuses);
    for (i, (a, b)) in e.islands.iter().zip(&w.islands).enumerate() {
        assert_eq!(a.solution.status, b.solution.status, "island {i}");
        assert_eq!(a.solution.basis, b.solution.basis, "island {i}");
        // The f32 records too (bases visited, singular): same arithmetic, same order.
        assert_eq!(a.solution.counters, b.solution.counters, "island {i}");
        let scale = a.solution.z.iter().fold(1.0f64, |m, v| m.max(v.abs()));
        for (x, y) in a.solution.z.iter().zip(&b.solution.z) {
            assert!((x - y).abs() <= 1e-9 * scale, "island {i}");
        }
    }
}
