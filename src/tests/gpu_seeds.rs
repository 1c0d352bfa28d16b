//! The LCPs worked by hand (`tests/seeds.rs`: two coupled contacts, the
//! 3×3 Lemke walk-through) through the GPU, in f64 and in f32.

use crate::gpu::batch::enumerate_on_gpu;
use crate::gpu::{solve_lcp_batch, GpuSolveSettings, Precision};
use crate::{Lcp, SolvePath, Status};

/// A fresh context at `precision`; a missing adapter fails the test with the
/// install hint (GPU tests never skip).
use super::common::gpu_context as context;

fn seeds() -> Vec<(Lcp, Vec<f64>, Vec<f64>)> {
    vec![
        // Two coupled contacts, both active: z = (4/3, 7/3), w = 0.
        (
            Lcp::new(vec![2.0, 1.0, 1.0, 2.0], vec![-5.0, -6.0]).unwrap(),
            vec![4.0 / 3.0, 7.0 / 3.0],
            vec![0.0, 0.0],
        ),
        // The 3×3 Lemke walk-through (zero diagonal): z = (0, 1, 3), w = (2, 0, 0).
        (
            Lcp::new(
                vec![0.0, -1.0, 2.0, 2.0, 0.0, -2.0, -1.0, 1.0, 0.0],
                vec![-3.0, 6.0, -1.0],
            )
            .unwrap(),
            vec![0.0, 1.0, 3.0],
            vec![2.0, 0.0, 0.0],
        ),
        // The same M with q = (−3, 6, 1): z = (1, 0, 1.5).
        (
            Lcp::new(
                vec![0.0, -1.0, 2.0, 2.0, 0.0, -2.0, -1.0, 1.0, 0.0],
                vec![-3.0, 6.0, 1.0],
            )
            .unwrap(),
            vec![1.0, 0.0, 1.5],
            vec![0.0, 5.0, 0.0],
        ),
    ]
}

fn check(precision: Precision) {
    let Some(ctx) = context(precision) else {
        return;
    };
    let cases = seeds();
    let lcps: Vec<Lcp> = cases.iter().map(|c| c.0.clone()).collect();
    // Every example on the GPU (prediction would settle the first).
    let gs = GpuSolveSettings {
        predict: false,
        ..Default::default()
    };
    let r = solve_lcp_batch(&ctx, &lcps, &gs).unwrap();
    println!("{r}");
    // The stage's own output: the GPU's z before the f64 polish.
    let refs: Vec<&Lcp> = lcps.iter().collect();
    let (raw, _) = enumerate_on_gpu(&ctx, &refs, &gs).unwrap();
    for (k, ((_, z, w), o)) in cases.iter().zip(&r.islands).enumerate() {
        assert_eq!(o.solution.status, Status::Solved, "seed case {k}");
        assert_eq!(
            o.path,
            SolvePath::EnumeratedGpu,
            "seed case {k} must be answered by the GPU"
        );
        for i in 0..z.len() {
            assert!(
                (o.solution.z[i] - z[i]).abs() < 1e-12,
                "case {k} z {:?} vs {z:?}",
                o.solution.z
            );
            assert!(
                (o.solution.w[i] - w[i]).abs() < 1e-12,
                "case {k} w {:?} vs {w:?}",
                o.solution.w
            );
            // The GPU's own z, before polish, to its precision.
            let tol = if ctx.precision() == Precision::F64 {
                1e-12
            } else {
                1e-5
            };
            assert!(
                (raw[k].z[i] - z[i]).abs() < tol * 4.0,
                "case {k} gpu z {:?}",
                raw[k].z
            );
        }
        assert!(o.solution.residuals.error < 1e-14);
    }
    // f64: the GPU's z passes the check as it is (accepted); f32: every
    // basis re-solved in f64 (polished).
    let kept = match ctx.precision() {
        Precision::F64 => (r.counts.accepted, r.counts.polished),
        _ => (r.counts.polished, r.counts.accepted),
    };
    assert_eq!(kept, (3, 0));
    assert_eq!(r.counts.repaired, 0);
}

#[test]
fn seeds_in_f64() {
    check(Precision::F64);
}

#[test]
fn seeds_in_f32() {
    check(Precision::F32);
}
