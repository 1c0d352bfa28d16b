//! The specialised (unrolled) elimination kernels against the looped
//! elimination kernel: the same raw output bit for bit.

use crate::gpu::batch::{enumerate_on_gpu, EnumerationKernel};
use crate::gpu::{GpuSolveSettings, Precision};
use crate::Lcp;

use super::common;
use super::common::gpu_context as context;

/// Fixed-seed physical islands n = 1…12 (mass ratios 1…1e4), resting boxes
/// (singular bases), the chain of four coupled bodies, demo worlds, and the
/// non-symmetric problems of the 3×3 Lemke walk-through, with zero
/// diagonals (no principal pivot order from the empty basis).
fn islands(seed: u64, count: usize) -> Vec<Lcp> {
    let mut lcps = common::physical_islands(seed, count, 12);
    lcps.push(Lcp::new(vec![1.0, 1.0, 1.0, 1.0], vec![-1.0, -1.0]).unwrap());
    lcps.push(Lcp::new(vec![-1.0, 0.0, 0.0, -1.0], vec![-1.0, -1.0]).unwrap());
    lcps
}

/// The specialised (unrolled) elimination kernel for n ≤ 8 gives the
/// elimination kernel's raw output bit for bit (basis, status, counters, z).
#[test]
fn unrolled_kernel_equals_elimination_kernel() {
    for precision in [Precision::F64, Precision::F32] {
        let Some(ctx) = context(precision) else {
            continue;
        };
        let lcps = islands(5, 300);
        let refs: Vec<&Lcp> = lcps.iter().collect();
        let run = |kernel| {
            let s = GpuSolveSettings {
                kernel,
                ..Default::default()
            };
            enumerate_on_gpu(&ctx, &refs, &s).unwrap().0
        };
        let e = run(EnumerationKernel::Elimination);
        let u = run(EnumerationKernel::Unrolled);
        let mut small = 0;
        for (i, (a, b)) in e.iter().zip(&u).enumerate() {
            assert_eq!(a.result, b.result, "island {i} (n = {})", lcps[i].n());
            assert_eq!(a.z, b.z, "island {i}");
            small += (lcps[i].n() <= 8) as usize;
        }
        assert!(small > 100);
    }
}
