//! Lemke keeps its promise on copositive-plus M: no ray on a feasible
//! problem (issue "Fastest exact answer", part 2).
use super::*;
use proptest::prelude::*;

/// The LCP with M = B Bᵀ (B n×k, rank k < n possible) scaled by
/// D = diag(10^e_i), and q built around a known solution (z*, w*).
fn known_solution_lcp(n: usize, b: &[f64], k: usize, exps: &[f64], picks: &[f64]) -> Lcp {
    let d: Vec<f64> = exps.iter().map(|e| 10f64.powf(*e)).collect();
    let mut m = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            let v: f64 = (0..k).map(|t| b[i * k + t] * b[j * k + t]).sum();
            m[i * n + j] = d[i] * v * d[j];
        }
    }
    let z: Vec<f64> = (0..n)
        .map(|i| if picks[i] > 0.0 { picks[i] / d[i] } else { 0.0 })
        .collect();
    let q = (0..n)
        .map(|i| {
            let w = if z[i] > 0.0 { 0.0 } else { -picks[i] * d[i] };
            w - (0..n).map(|j| m[i * n + j] * z[j]).sum::<f64>()
        })
        .collect();
    Lcp::new(m, q).unwrap()
}

fn case(max_exp: f64) -> impl Strategy<Value = Lcp> {
    (2usize..=12).prop_flat_map(move |n| {
        (1usize..=n).prop_flat_map(move |k| {
            (
                prop::collection::vec(-1.0f64..1.0, n * k),
                prop::collection::vec(-max_exp..=max_exp, n),
                prop::collection::vec(-1.0f64..1.0, n),
            )
                .prop_map(move |(b, e, p)| known_solution_lcp(n, &b, k, &e, &p))
        })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn no_ray_on_feasible_semidefinite_problems(lcp in case(0.0)) {
        let s = lemke(&lcp, &LemkeSettings::default());
        prop_assert_eq!(s.status, Status::Solved, "{:?}", lcp);
        prop_assert!(s.residuals.error <= 1e-9, "error {:e}: {:?}", s.residuals.error, lcp);
    }

    #[test]
    fn no_ray_on_badly_scaled_semidefinite_problems(lcp in case(100.0)) {
        let s = lemke(&lcp, &LemkeSettings::default());
        prop_assert_eq!(s.status, Status::Solved, "{:?}", lcp);
        prop_assert!(s.residuals.error <= 1e-9, "error {:e}: {:?}", s.residuals.error, lcp);
    }

    #[test]
    fn diagonal_problems_across_the_range_of_f64(
        d in prop::collection::vec(-300.0f64..300.0, 1..8),
        q in prop::collection::vec(-1.0f64..1.0, 8),
    ) {
        // z_i = max(0, −q_i / d_i), finite for |q_i| ≤ 1 and d_i ≥ 1e-300.
        let n = d.len();
        let mut m = vec![0.0; n * n];
        for i in 0..n {
            m[i * n + i] = 10f64.powf(d[i]);
        }
        let lcp = Lcp::new(m, q[..n].to_vec()).unwrap();
        let s = lemke(&lcp, &LemkeSettings::default());
        prop_assert_eq!(s.status, Status::Solved);
        for i in 0..n {
            let want = (-lcp.q[i] / lcp.at(i, i)).max(0.0);
            prop_assert!((s.z[i] - want).abs() <= 1e-9 * want, "{:?} vs {}", s.z, want);
        }
    }
}

#[test]
fn extreme_diagonal_of_the_issue_is_solved() {
    let lcp = Lcp::new(vec![1e300, 0.0, 0.0, 1e-300], vec![-1.0, -1.0]).unwrap();
    let s = lemke(&lcp, &LemkeSettings::default());
    assert_eq!(s.status, Status::Solved);
    assert_eq!(s.z[0], 1e-300);
    assert!((s.z[1] - 1e300).abs() <= 1e-15 * 1e300);
}
