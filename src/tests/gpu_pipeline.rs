//! The pipelined LCP batch (issue 22): a batch cut into parts, each part's
//! chunks written while the one before runs and each part checked while
//! the next runs, gives byte for byte what one part gives, with the
//! enumeration kernels and the Lemke kernel, split under tiny limits too;
//! its figures (chunks, the device's kernel seconds where the adapter has
//! timestamps, overlapped host work, check, report) are filled in.

use crate::generate::families::{family_batch, BenchFamily};
use crate::gpu::{solve_lcp_batch, GpuSolveSettings, Precision};
use crate::settings::Method;
use crate::Lcp;

use super::common::gpu_context as context;

/// Every bench family, 600 islands each, after one another.
fn batch() -> Vec<Lcp> {
    BenchFamily::ALL
        .iter()
        .flat_map(|&f| family_batch(f, 7, 600))
        .collect()
}

#[test]
fn parts_give_what_one_part_gives() {
    let Some(ctx) = context(Precision::Auto) else {
        return;
    };
    let lcps = batch();
    for method in [Method::Enumeration, Method::Auto] {
        let one = GpuSolveSettings {
            method,
            ..Default::default()
        };
        let whole = solve_lcp_batch(&ctx, &lcps, &one).unwrap();
        for split in [None, Some(4096)] {
            let parts = GpuSolveSettings {
                part_islands: Some(64),
                max_binding_bytes: split,
                ..one
            };
            let piped = solve_lcp_batch(&ctx, &lcps, &parts).unwrap();
            let (w, p) = (whole.gpu.unwrap(), piped.gpu.unwrap());
            println!("{method:?} {split:?}: one part {w:?}\nparts {p:?}");
            assert_eq!(w.chunks, 1, "{method:?}");
            // Parts of whole blocks of 256 islands (2,200 of the 3,000 left
            // to the GPU: about 6 parts), more chunks under 4 KiB bindings.
            assert!(p.chunks > 4, "{method:?} {split:?}: {} chunks", p.chunks);
            assert!(p.overlapped_seconds > 0.0);
            assert_eq!(whole.counts, piped.counts, "{method:?} {split:?}");
            for (i, (a, b)) in whole.islands.iter().zip(&piped.islands).enumerate() {
                assert_eq!(a.path, b.path, "{method:?} problem {i}");
                assert_eq!(a.method, b.method, "{method:?} problem {i}");
                assert_eq!(a.solution, b.solution, "{method:?} problem {i}");
            }
            for f in [&w, &p] {
                let has = ctx
                    .device
                    .features()
                    .contains(wgpu::Features::TIMESTAMP_QUERY);
                assert_eq!(f.kernel_device_seconds.is_some(), has);
                assert!(f.kernel_device_seconds.unwrap_or(0.0) >= 0.0);
                assert!(f.check_seconds > 0.0 && f.report_seconds > 0.0);
                assert!(f.repair_seconds >= 0.0);
            }
        }
    }
}
