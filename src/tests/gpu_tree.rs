//! The tree kernel (`shaders/enumeration_tree.wgsl`) against its CPU twin
//! (`cpu::enumeration_tree`) and against the elimination kernel: what it
//! decides is the twin's decision (f64: the same basis, z and counters); what
//! it leaves undecided the elimination kernel finishes; whole batches give
//! the elimination kernel's answers. Its speed is measured by
//! `cargo bench --bench gpu_kernels`.

use crate::cpu::enumeration::enumerate;
use crate::cpu::enumeration_tree::{enumerate_tree, TreeOutcome, TreeSettings, TREE_MAX_N};
use crate::gpu::batch::{enumerate_on_gpu, EnumerationKernel};
use crate::gpu::layout::{FOUND, TREE_DECIDED, TREE_UNDECIDED};
use crate::gpu::{solve_lcp_batch, GpuSolveSettings, Precision};
use crate::prediction::{is_positive_definite, is_positive_semidefinite};
use crate::Lcp;

use super::common;
use super::common::gpu_context as context;

/// Physical islands n = 1…8 (most positive definite; resting boxes are
/// semidefinite: small pivots), the non-symmetric problems of the 3×3
/// Lemke walk-through (zero diagonals, [`common::seed_002_problems`]) and a
/// positive definite 2×2.
fn islands(seed: u64, count: usize) -> Vec<Lcp> {
    let mut lcps = common::physical_islands(seed, count, 8);
    lcps.push(Lcp::new(vec![2.0, 1.0, 1.0, 2.0], vec![-3.0, -3.0]).unwrap());
    lcps
}

/// The route [`EnumerationKernel::Tree`] gives an island: semidefinite when
/// M is positive semidefinite but not definite.
fn semidefinite(l: &Lcp) -> bool {
    !is_positive_definite(l) && is_positive_semidefinite(l)
}

fn tree_only() -> GpuSolveSettings {
    GpuSolveSettings {
        kernel: EnumerationKernel::Tree,
        predict: false,
        ..Default::default()
    }
}

/// f64: every island the kernel decides, the twin decides the same way
/// (basis, z to 1e-12, visited, singular); every island it leaves, the twin
/// leaves too and the elimination kernel's answer follows.
#[test]
fn tree_kernel_equals_its_cpu_twin_in_f64() {
    let Some(ctx) = context(Precision::F64) else {
        return;
    };
    let lcps = islands(41, 400);
    let refs: Vec<&Lcp> = lcps.iter().collect();
    let (out, stats) = enumerate_on_gpu(&ctx, &refs, &tree_only()).unwrap();
    let elimination = GpuSolveSettings {
        kernel: EnumerationKernel::Elimination,
        predict: false,
        ..Default::default()
    };
    let (elim, _) = enumerate_on_gpu(&ctx, &refs, &elimination).unwrap();
    println!(
        "{} islands: tree decided {}, left {}",
        lcps.len(),
        stats.tree_decided,
        stats.tree_undecided
    );
    let (mut decided, mut left) = (0, 0);
    for (i, (l, o)) in lcps.iter().zip(&out).enumerate() {
        let r = &o.result;
        match enumerate_tree(l, semidefinite(l), &TreeSettings::default()) {
            TreeOutcome::Decided(cpu) => {
                decided += 1;
                assert_eq!(r._pad1, TREE_DECIDED, "island {i}: {l:?}");
                assert_eq!(r.status, FOUND, "island {i}");
                assert_eq!(Some(r.mask), cpu.basis, "island {i}");
                assert_eq!(r.visited as u64, cpu.counters.bases_visited);
                assert_eq!(r.singular as u64, cpu.counters.singular_bases);
                let scale = cpu.z.iter().fold(1.0f64, |m, v| m.max(v.abs()));
                for (a, b) in o.z.iter().zip(&cpu.z) {
                    assert!((a - b).abs() <= 1e-12 * scale, "island {i}");
                }
            }
            TreeOutcome::Undecided(why) => {
                left += 1;
                assert_eq!(r._pad1, TREE_UNDECIDED, "island {i} ({why:?})");
                // Finished by the elimination kernel: its record and z.
                let mut e = elim[i].result;
                e._pad1 = TREE_UNDECIDED;
                assert_eq!(*r, e, "island {i}");
                assert_eq!(o.z, elim[i].z, "island {i}");
            }
        }
    }
    assert_eq!((decided, left), (stats.tree_decided, stats.tree_undecided));
    assert!(decided > 200 && left > 0, "decided {decided}, left {left}");
}

/// Above n = 8 the kernel loops over the bases of the first n − 8 indices
/// around the straight-line tree of the last 8: the same decisions as the
/// twin (f64: basis, z, counters), n = 9…12.
#[test]
fn tree_kernel_with_a_prefix_loop_equals_its_cpu_twin_in_f64() {
    let Some(ctx) = context(Precision::F64) else {
        return;
    };
    let settings = GpuSolveSettings {
        tree_max_n: TREE_MAX_N,
        ..tree_only()
    };
    for n in 9..=TREE_MAX_N {
        let lcps = crate::generate::families::islands_of_size(n, 48, 7 + n as u64);
        let refs: Vec<&Lcp> = lcps.iter().collect();
        let (out, stats) = enumerate_on_gpu(&ctx, &refs, &settings).unwrap();
        println!(
            "n = {n}: tree decided {}, left {}",
            stats.tree_decided, stats.tree_undecided
        );
        assert!(stats.tree_decided >= 30, "n = {n}: {}", stats.tree_decided);
        for (i, (l, o)) in lcps.iter().zip(&out).enumerate() {
            let r = &o.result;
            match enumerate_tree(l, semidefinite(l), &TreeSettings::default()) {
                TreeOutcome::Decided(cpu) => {
                    assert_eq!(r._pad1, TREE_DECIDED, "n = {n}, island {i}");
                    assert_eq!(Some(r.mask), cpu.basis, "n = {n}, island {i}");
                    assert_eq!(r.visited as u64, cpu.counters.bases_visited);
                    assert_eq!(r.singular as u64, cpu.counters.singular_bases);
                    let scale = cpu.z.iter().fold(1.0f64, |m, v| m.max(v.abs()));
                    for (a, b) in o.z.iter().zip(&cpu.z) {
                        assert!((a - b).abs() <= 1e-12 * scale, "n = {n}, island {i}");
                    }
                }
                TreeOutcome::Undecided(why) => {
                    assert_eq!(r._pad1, TREE_UNDECIDED, "n = {n}, island {i} ({why:?})");
                    assert_eq!(
                        Some(r.mask),
                        enumerate(l, &Default::default()).unwrap().basis
                    );
                }
            }
        }
    }
}

/// What the tree decides is enumeration's choice: on positive definite
/// islands the CPU twin (which the kernel equals in f64) gives the basis and
/// z of the CPU elimination enumeration, and leaves few undecided (a Schur
/// complement below 1e-8 of its diagonal: ill-conditioned, not singular).
#[test]
fn tree_decisions_are_enumerations_on_positive_definite_islands() {
    let lcps = islands(43, 600);
    let (mut pd, mut left) = (0, 0);
    for (i, l) in lcps.iter().enumerate() {
        if !is_positive_definite(l) {
            continue;
        }
        pd += 1;
        let e = enumerate(l, &Default::default()).unwrap();
        match enumerate_tree(l, semidefinite(l), &TreeSettings::default()) {
            TreeOutcome::Decided(t) => {
                assert_eq!(t.basis, e.basis, "island {i}");
                assert_eq!(t.z, e.z, "island {i}");
            }
            TreeOutcome::Undecided(_) => left += 1,
        }
    }
    println!("{pd} positive definite islands, {left} undecided");
    assert!(pd > 300, "{pd}");
    assert!(left * 50 <= pd, "{left} of {pd} undecided");
}

/// Semidefinite islands (resting boxes and stacks, chains): the twin with
/// singular pivots cutting their subtrees decides as the CPU enumeration
/// does (basis and z), and the kernel in f64 as the twin.
#[test]
fn semidefinite_islands_decide_as_enumeration() {
    use crate::generate::stress::{generate, Family};
    let mut lcps: Vec<Lcp> = Vec::new();
    for family in [Family::RestingStacks, Family::Chains] {
        lcps.extend(
            generate(family, 5, 300)
                .into_iter()
                .map(|c| c.lcp)
                .filter(|l| l.n() <= TREE_MAX_N && semidefinite(l)),
        );
    }
    lcps.extend(
        crate::generate::families::family_batch(
            crate::generate::families::BenchFamily::RestingStacks,
            9,
            400,
        )
        .into_iter()
        .filter(|l| l.n() <= TREE_MAX_N && semidefinite(l)),
    );
    let (mut decided, mut left) = (0, 0);
    for (i, l) in lcps.iter().enumerate() {
        let e = enumerate(l, &Default::default()).unwrap();
        match enumerate_tree(l, true, &TreeSettings::default()) {
            TreeOutcome::Decided(t) => {
                decided += 1;
                assert_eq!(t.basis, e.basis, "island {i}: {l:?}");
                assert_eq!(t.z, e.z, "island {i}");
            }
            TreeOutcome::Undecided(_) => left += 1,
        }
    }
    println!(
        "{} semidefinite islands: decided {decided}, left {left}",
        lcps.len()
    );
    assert!(
        lcps.len() > 300 && decided * 10 >= lcps.len() * 9,
        "{decided} of {}",
        lcps.len()
    );
    let Some(ctx) = context(Precision::F64) else {
        return;
    };
    let refs: Vec<&Lcp> = lcps.iter().collect();
    let (out, _) = enumerate_on_gpu(&ctx, &refs, &GpuSolveSettings::default()).unwrap();
    for (i, (l, o)) in lcps.iter().zip(&out).enumerate() {
        if let TreeOutcome::Decided(t) = enumerate_tree(l, true, &TreeSettings::default()) {
            assert_eq!(o.result._pad1, TREE_DECIDED, "island {i}");
            assert_eq!(Some(o.result.mask), t.basis, "island {i}");
        } else {
            assert_eq!(o.result._pad1, TREE_UNDECIDED, "island {i}");
        }
    }
}

/// Whole batches with the default kernel choice (Auto: positive definite
/// islands through the tree) and with every island through it give the
/// elimination kernel's statuses and bases, in both precisions, with
/// prediction off; in f64 nothing is repaired.
#[test]
fn tree_batches_equal_elimination_batches() {
    for precision in [Precision::F64, Precision::F32] {
        let Some(ctx) = context(precision) else {
            continue;
        };
        let lcps = islands(47, 400);
        let with = |kernel| GpuSolveSettings {
            kernel,
            predict: false,
            ..Default::default()
        };
        let e = solve_lcp_batch(&ctx, &lcps, &with(EnumerationKernel::Elimination)).unwrap();
        for kernel in [EnumerationKernel::Auto, EnumerationKernel::Tree] {
            let t = solve_lcp_batch(&ctx, &lcps, &with(kernel)).unwrap();
            println!("{} {kernel:?}:\n{t}", precision.name());
            let tree_decided = t.gpu.unwrap_or_default().tree_decided;
            assert!(tree_decided > 100, "{t}");
            assert_eq!(e.statuses, t.statuses);
            if precision == Precision::F64 {
                assert_eq!(t.counts.repaired, 0);
            }
            for (i, (a, b)) in e.islands.iter().zip(&t.islands).enumerate() {
                assert_eq!(a.solution.status, b.solution.status, "island {i}");
                assert_eq!(a.solution.basis, b.solution.basis, "island {i}");
                let scale = a.solution.z.iter().fold(1.0f64, |m, v| m.max(v.abs()));
                for (x, y) in a.solution.z.iter().zip(&b.solution.z) {
                    assert!((x - y).abs() <= 1e-9 * scale, "island {i}");
                }
            }
        }
    }
}
