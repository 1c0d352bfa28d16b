//! The GPU's verdicts under scaling, in f64 and f32. (Accuracy per stress
//! family, f32 + polish against f64: `lcpbatch stress`, BENCHMARKS.md.)

use crate::generate::stress::{generate, Family};
use crate::gpu::Precision;

/// The GPU's tolerances are relative too: scaling M and q by 1e±6 changes no
/// status and no basis, in f64 (the exact twin) and in f32 (after validation).
#[test]
fn gpu_verdicts_do_not_depend_on_scale() {
    use crate::generate::stress::scaled;
    use crate::gpu::{solve_lcp_batch, GpuSolveSettings};
    for precision in [Precision::F64, Precision::F32] {
        let Some(ctx) = super::common::gpu_context(precision) else {
            continue;
        };
        let lcps: Vec<_> = Family::ALL
            .iter()
            .flat_map(|&f| generate(f, 31, 40))
            .map(|c| c.lcp)
            .filter(|l| l.n() <= 16)
            .collect();
        let s = GpuSolveSettings::default();
        let base = solve_lcp_batch(&ctx, &lcps, &s).expect("GPU solve");
        for f in [1e-6, 1e6] {
            let big: Vec<_> = lcps.iter().map(|l| scaled(l, f)).collect();
            let r = solve_lcp_batch(&ctx, &big, &s).expect("GPU solve");
            for (i, (a, b)) in base.islands.iter().zip(&r.islands).enumerate() {
                assert_eq!(
                    a.solution.status, b.solution.status,
                    "{precision:?} case {i} scaled by {f:e}"
                );
                assert_eq!(
                    a.solution.basis, b.solution.basis,
                    "{precision:?} case {i} scaled by {f:e}"
                );
            }
        }
    }
}
