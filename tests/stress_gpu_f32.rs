//! Issue 5's accuracy requirement for f32 on the GPU: after the f64 polish
//! (and repair where the polish fails), every stress family's answer has the
//! status of the f64 enumeration, no NaN or Inf, and an error ≤ 1e-9 wherever
//! the chosen basis' principal submatrix has a condition number ≤ 1e10. The
//! GPU's own f32 answers are only summarised (their error against the
//! condition number is documented in BENCHMARKS.md).

use lcpbatch::gpu::{GpuContext, GpuOptions, Precision, INSTALL_HINT};
use lcpbatch::stress::{generate, run_gpu, summarise, Family};

#[test]
fn f32_plus_polish_is_as_accurate_as_f64_where_the_basis_is_conditioned() {
    let mut o = GpuOptions::from_env().expect("GPU environment variables");
    o.precision = Precision::F32;
    let ctx =
        GpuContext::new(&o).unwrap_or_else(|e| panic!("no GPU adapter ({e}): {INSTALL_HINT}"));
    let mut worst = 0.0f64;
    let mut repaired_total = 0;
    for family in Family::ALL {
        let cases: Vec<_> = generate(family, 23, 120)
            .into_iter()
            .filter(|c| c.lcp.n() <= 16)
            .collect();
        let (points, repaired) = run_gpu(&ctx, family.name(), &cases).expect("GPU solve");
        repaired_total += repaired;
        for p in points.iter().filter(|p| p.solver.ends_with("+ polish")) {
            assert!(p.finite, "{}: NaN or Inf", family.name());
            assert!(
                p.status_matches_reference,
                "{}: status {} differs from f64 enumeration",
                family.name(),
                p.status
            );
            if p.status == "solved" && p.condition <= 1e10 {
                assert!(
                    p.error <= 1e-9,
                    "{} p={}: error {:e} at condition {:e}",
                    family.name(),
                    p.parameter,
                    p.error,
                    p.condition
                );
                worst = worst.max(p.error);
            }
        }
        for row in summarise(&points) {
            eprintln!(
                "{:<22} {:<22} median {:>8.1e} max {:>8.1e} status match {:>5.1}%",
                row.family,
                row.solver,
                row.median_error,
                row.max_error,
                100.0 * row.status_match
            );
        }
    }
    // Observed on lavapipe, 2026-11-22: worst 8.1e-15 after polish, 14 repaired;
    // repairs
    // come mostly from near-parallel normals, which f32 cannot tell apart.
    eprintln!("worst f32 + polish error where cond ≤ 1e10: {worst:e}; repaired {repaired_total}");
}

/// The GPU's tolerances are relative too: scaling M and q by 1e±6 changes no
/// status and no basis, in f64 (the exact twin) and in f32 (after validation).
#[test]
fn gpu_verdicts_do_not_depend_on_scale() {
    use lcpbatch::gpu::{solve_lcp_batch, GpuSolveSettings};
    use lcpbatch::stress::scaled;
    for precision in [Precision::F64, Precision::F32] {
        let mut o = GpuOptions::from_env().expect("GPU environment variables");
        o.precision = precision;
        let ctx = match GpuContext::new(&o) {
            Ok(c) => c,
            Err(e) if precision == Precision::F64 && e.to_string().contains("SHADER_F64") => {
                eprintln!("no f64 on this adapter: {e}");
                continue;
            }
            Err(e) => panic!("no GPU adapter ({e}): {INSTALL_HINT}"),
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
