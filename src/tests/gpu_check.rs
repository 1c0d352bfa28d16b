//! The f64 check of the GPU's answers (`src/gpu/validation.rs`), per
//! kernel (enumeration, Lemke): the GPU's own z accepted where it passes,
//! and a z corrupted after the kernel refused: its basis re-solved in f64
//! (polished, the CPU's bytes), or, where the basis named is wrong too, the
//! island solved again on the CPU (repaired).

use crate::cpu::enumeration::{enumerate, EnumerationSettings};
use crate::gpu::batch::{enumerate_on_gpu, settle_from_gpu};
use crate::gpu::layout::FOUND;
use crate::gpu::validation::Verdict;
use crate::gpu::{GpuSolveSettings, Precision};
use crate::lcp::LcpSolution;
use crate::report::{IslandReport, SolvePath};
use crate::settings::Method;
use crate::short_vec::ShortVec;
use crate::solver::textbook_checked;
use crate::Lcp;

use super::common;
use super::common::gpu_context as context;

/// An empty island report for `settle_from_gpu` to fill.
fn blank() -> IslandReport {
    IslandReport {
        scene: None,
        contacts: ShortVec::new(),
        method: Method::Enumeration,
        path: SolvePath::Invalid,
        solution: LcpSolution::invalid(0),
    }
}

/// For each kernel (`method`: Enumeration, Lemke) in f64: every FOUND
/// answer is accepted as the GPU gave it, z within 1e-12 of its basis
/// re-solved in f64, the status and basis the re-solve's; the same answer
/// with one basic z_i scaled by 1 + 1e-6 is refused and re-solved
/// (polished: the re-solve's bytes); with its basis named wrong as well
/// (one index flipped), solved again on the CPU (repaired, the CPU
/// enumeration's answer where the kernel is the enumeration).
fn check_refuses_wrong_answers(method: Method) {
    let Some(ctx) = context(Precision::F64) else {
        return;
    };
    let gs = GpuSolveSettings {
        method,
        predict: false,
        ..Default::default()
    };
    let lcps: Vec<Lcp> = common::physical_islands(41, 300, 12);
    let refs: Vec<&Lcp> = lcps.iter().collect();
    let (out, _) = enumerate_on_gpu(&ctx, &refs, &gs).unwrap();
    let exact = gs.exact_twin(ctx.precision());
    assert!(exact);
    let e: EnumerationSettings = gs.enumeration;
    let (mut accepted, mut refused, mut repaired) = (0, 0, 0);
    for (i, (lcp, o)) in lcps.iter().zip(&out).enumerate() {
        let r = o.result;
        if r.status != FOUND || r.mask == 0 {
            continue;
        }
        // The re-solve of the GPU's basis in f64: what the check falls back on.
        let mut resolved = LcpSolution::invalid(0);
        if !textbook_checked(lcp, r.mask, r.visited.into(), &e, &mut resolved) {
            continue;
        }
        let mut repair = 0.0;
        let mut island = blank();
        let (verdict, _) = settle_from_gpu(
            lcp,
            (&r, &o.z, 0),
            &gs,
            (exact, true),
            &mut island,
            &mut repair,
        )
        .unwrap();
        assert_eq!(verdict, Verdict::Accepted, "island {i}");
        assert_eq!(island.solution.status, resolved.status, "island {i}");
        assert_eq!(island.solution.basis, Some(r.mask), "island {i}");
        assert_eq!(&island.solution.z[..], &o.z[..], "island {i}");
        let d = common::z_rel_diff(&island.solution.z, &resolved.z);
        assert!(d <= 1e-12, "island {i}: z {d:e} from the re-solve");
        accepted += 1;

        // One basic z_k > 0 off by 1e-6 relative: refused, the basis re-solved.
        let Some(k) = (0..lcp.n()).find(|&k| r.mask >> k & 1 == 1 && o.z[k] > 0.0) else {
            continue;
        };
        let mut wrong = o.z.clone();
        wrong[k] *= 1.0 + 1e-6;
        let mut island = blank();
        let (verdict, gpu_error) = settle_from_gpu(
            lcp,
            (&r, &wrong, 0),
            &gs,
            (exact, true),
            &mut island,
            &mut repair,
        )
        .unwrap();
        assert!(
            gpu_error > 0.0,
            "island {i}: the wrong z's error is measured"
        );
        if verdict == Verdict::Polished {
            assert_eq!(island.solution.z, resolved.z, "island {i}");
            assert_eq!(island.solution.basis, resolved.basis, "island {i}");
            refused += 1;
        } else {
            // An error of 1e-6 · z_k below 1e-12 · ‖q‖: still within the check.
            assert_eq!(verdict, Verdict::Accepted, "island {i}");
            assert!(gpu_error <= 1e-12, "island {i}");
        }

        // A wrong basis too (k left out, z_k ≠ 0 outside it): never
        // accepted; the basis fails in f64 or names another answer.
        let mut bad = r;
        bad.mask ^= 1 << k;
        let mut island = blank();
        let (verdict, _) = settle_from_gpu(
            lcp,
            (&bad, &wrong, 0),
            &gs,
            (exact, true),
            &mut island,
            &mut repair,
        )
        .unwrap();
        assert_ne!(verdict, Verdict::Accepted, "island {i}");
        if verdict == Verdict::Repaired {
            repaired += 1;
            if method == Method::Enumeration {
                let cpu = enumerate(lcp, &e).unwrap();
                assert_eq!(island.solution.z, cpu.z, "island {i}");
                assert_eq!(island.path, SolvePath::Repaired, "island {i}");
            }
        }
    }
    println!("{method:?}: accepted {accepted}, refused {refused}, repaired {repaired}");
    assert!(accepted >= 100, "{accepted} answers checked");
    assert!(refused >= accepted / 2, "{refused} of {accepted} refused");
    assert!(repaired > 0, "no wrong basis repaired");
}

#[test]
fn the_check_refuses_a_wrong_enumeration_answer() {
    check_refuses_wrong_answers(Method::Enumeration);
}

#[test]
fn the_check_refuses_a_wrong_lemke_answer() {
    check_refuses_wrong_answers(Method::Lemke);
}
