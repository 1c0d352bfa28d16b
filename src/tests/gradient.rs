//! `lcpbatch::gradient` on LCPs: the vector–Jacobian product against
//! central finite differences of re-solved problems, against the gradient
//! of the equivalent QP by its KKT system (an independent derivation), the
//! degenerate and undefined flags, the errors and the batch doors.

use crate::generate::Rng;
use crate::gradient::{lcp_vjp, lcp_vjp_batch, lcp_vjp_dense_into, Derivative, LcpGradient};
use crate::settings::{Backend, Method, Settings};
use crate::tests::common::run;
use crate::{Lcp, Solver};

#[path = "gradient_scene.rs"]
mod scene;

/// Relative tolerance τ of the tests (the default `Settings::tolerance`).
const TOL: f64 = 1e-8;
/// The finite-difference step.
const STEP: f64 = 1e-6;

#[derive(Clone, Copy, Debug)]
enum Kind {
    /// Symmetric positive definite: AᵀA + I/2.
    Pd,
    /// Symmetric positive semidefinite of rank ⌈n/2⌉ plus a skew part.
    Psd,
    /// Non-symmetric, strictly row diagonally dominant with a positive
    /// diagonal: a P-matrix.
    PMatrix,
}

fn random_lcp(rng: &mut Rng, n: usize, kind: Kind) -> Lcp {
    let rank = match kind {
        Kind::Psd => n.div_ceil(2),
        _ => n,
    };
    let a: Vec<f64> = (0..rank * n).map(|_| rng.range(-1.0, 1.0)).collect();
    let gram = |i: usize, j: usize| (0..rank).map(|r| a[r * n + i] * a[r * n + j]).sum::<f64>();
    let mut m = vec![0.0; n * n];
    match kind {
        Kind::Pd | Kind::Psd => {
            let s: Vec<f64> = (0..n * n).map(|_| rng.range(-0.5, 0.5)).collect();
            let skew = matches!(kind, Kind::Psd);
            for i in 0..n {
                for j in 0..n {
                    m[i * n + j] = gram(i, j)
                        + if skew {
                            s[i * n + j] - s[j * n + i]
                        } else {
                            0.0
                        }
                        + if i == j && !skew { 0.5 } else { 0.0 };
                }
            }
        }
        Kind::PMatrix => {
            for i in 0..n {
                let mut off = 0.0;
                for j in (0..n).filter(|&j| j != i) {
                    m[i * n + j] = rng.range(-1.0, 1.0);
                    off += m[i * n + j].abs();
                }
                m[i * n + i] = off + rng.range(0.1, 1.0);
            }
        }
    }
    let q = (0..n).map(|_| rng.range(-1.0, 1.0)).collect();
    Lcp::new(m, q).unwrap()
}

/// A solution by Lemke, or None when it finds none.
fn solve(lcp: &Lcp) -> Option<(Vec<f64>, Vec<f64>)> {
    let s = run(lcp, Method::Lemke);
    s.status.is_solution().then(|| (s.z.to_vec(), s.w.to_vec()))
}

/// The rows with z_i > τ_z (as the module classifies them).
fn active_set(lcp: &Lcp, z: &[f64]) -> Vec<bool> {
    let inf = |v: &[f64]| v.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    let m_max = inf(&lcp.m);
    let tau_z = TOL * inf(&lcp.q).max(m_max * inf(z)) / m_max;
    z.iter().map(|&x| x > tau_z).collect()
}

fn loss(z: &[f64], w: &[f64], g: &[f64], h: &[f64]) -> f64 {
    z.iter().zip(g).map(|(a, b)| a * b).sum::<f64>()
        + w.iter().zip(h).map(|(a, b)| a * b).sum::<f64>()
}

/// Finite differences of every entry of (M, q), then q: the central
/// difference, or None where the active set changed within the step.
fn finite_differences(lcp: &Lcp, g: &[f64], h: &[f64], active: &[bool]) -> Vec<Option<f64>> {
    let n = lcp.n();
    (0..n * n + n)
        .map(|p| {
            let at = |step: f64| {
                let mut l = lcp.clone();
                if p < n * n {
                    l.m[p] += step;
                } else {
                    l.q[p - n * n] += step;
                }
                let (z, w) = solve(&l)?;
                (active_set(&l, &z) == active).then(|| loss(&z, &w, g, h))
            };
            Some((at(STEP)? - at(-STEP)?) / (2.0 * STEP))
        })
        .collect()
}

/// max |a − b| / max(‖b‖∞, 1e-300) over the entries both have.
fn rel_error(grad: &LcpGradient, fd: &[Option<f64>]) -> f64 {
    let ours: Vec<f64> = grad.m.iter().chain(&grad.q).copied().collect();
    let scale = fd.iter().flatten().fold(1e-300f64, |a, x| a.max(x.abs()));
    ours.iter()
        .zip(fd)
        .filter_map(|(a, b)| b.map(|b| (a - b).abs()))
        .fold(0.0, f64::max)
        / scale
}

/// Seeded PD, PSD and non-symmetric P-matrix LCPs of n = 1…12: with a
/// random loss gᵀz + hᵀw, the VJP equals central differences of re-solved
/// problems (step 1e-6, relative error ≤ 1e-5) at every entry whose
/// perturbation keeps the active set; entries that change it are skipped
/// and counted (at most 5% of them), degenerate islands are counted apart.
#[test]
fn vjp_matches_central_differences() {
    let mut rng = Rng::new(0x6EAD);
    let (mut checked, mut skipped, mut entries, mut flagged, mut worst) = (0, 0, 0, 0, 0.0f64);
    for kind in [Kind::Pd, Kind::Psd, Kind::PMatrix] {
        for n in 1..=12 {
            for _ in 0..3 {
                let lcp = random_lcp(&mut rng, n, kind);
                let Some((z, _)) = solve(&lcp) else {
                    assert!(matches!(kind, Kind::Psd), "{kind:?}: Lemke failed");
                    continue;
                };
                let g: Vec<f64> = (0..n).map(|_| rng.range(-1.0, 1.0)).collect();
                let h: Vec<f64> = (0..n).map(|_| rng.range(-1.0, 1.0)).collect();
                let grad = lcp_vjp(&lcp, &z, &g, Some(&h), TOL).unwrap();
                if grad.derivative != Derivative::Exact {
                    flagged += 1;
                    continue;
                }
                let fd = finite_differences(&lcp, &g, &h, &active_set(&lcp, &z));
                entries += fd.len();
                skipped += fd.iter().filter(|x| x.is_none()).count();
                let e = rel_error(&grad, &fd);
                assert!(e <= 1e-5, "{kind:?} n = {n}: relative error {e:.2e}");
                worst = worst.max(e);
                checked += 1;
            }
        }
    }
    eprintln!(
        "{checked} islands checked, {flagged} not exact; {skipped} of {entries} entries skipped; worst {worst:.2e}"
    );
    assert!(checked >= 90, "{checked}");
    assert!(skipped * 20 <= entries, "{skipped} of {entries} skipped");
}

/// Solves the k×k system A x = b by Gauss–Jordan with full pivoting (the
/// test's own, apart from `crate::linalg`); None when singular.
fn gauss_jordan(mut a: Vec<f64>, mut b: Vec<f64>, k: usize) -> Option<Vec<f64>> {
    let mut col_of: Vec<usize> = (0..k).collect();
    for c in 0..k {
        let (mut pr, mut pc, mut best) = (c, c, 0.0);
        for r in c..k {
            for cc in c..k {
                if a[r * k + cc].abs() > best {
                    (pr, pc, best) = (r, cc, a[r * k + cc].abs());
                }
            }
        }
        if best < 1e-12 {
            return None;
        }
        for j in 0..k {
            a.swap(c * k + j, pr * k + j);
        }
        b.swap(c, pr);
        for r in 0..k {
            a.swap(r * k + c, r * k + pc);
        }
        col_of.swap(c, pc);
        for r in (0..k).filter(|&r| r != c) {
            let f = a[r * k + c] / a[c * k + c];
            for j in 0..k {
                a[r * k + j] -= f * a[c * k + j];
            }
            b[r] -= f * b[c];
        }
    }
    let mut x = vec![0.0; k];
    for c in 0..k {
        x[col_of[c]] = b[c] / a[c * k + c];
    }
    Some(x)
}

/// For symmetric positive definite M the LCP is the KKT system of
/// min ½zᵀMz + qᵀz s.t. z ≥ 0, with multipliers λ = w:
/// Mz + q − λ = 0, λ_i z_i = 0. Differentiated (as OptNet does), with
/// K = [[M, −I], [diag λ, diag z]]: K (dz, dλ) = (−(dM z + dq), 0). So for
/// L with (g, h) = (∂L/∂z, ∂L/∂λ), Kᵀ(a, b) = (g, h) gives ∂L/∂q = −a,
/// ∂L/∂M = −a zᵀ: the 2n system over all rows, no active set.
#[test]
fn vjp_equals_the_qp_kkt_gradient_on_positive_definite_problems() {
    let mut rng = Rng::new(0x0971);
    let mut compared = 0;
    for n in 1..=12 {
        for _ in 0..6 {
            let lcp = random_lcp(&mut rng, n, Kind::Pd);
            let (z, w) = solve(&lcp).unwrap();
            let g: Vec<f64> = (0..n).map(|_| rng.range(-1.0, 1.0)).collect();
            let h: Vec<f64> = (0..n).map(|_| rng.range(-1.0, 1.0)).collect();
            let ours = lcp_vjp(&lcp, &z, &g, Some(&h), TOL).unwrap();
            if ours.derivative != Derivative::Exact {
                continue;
            }
            let k = 2 * n;
            // Kᵀ, row-major: Kᵀ[r][c] = K[c][r].
            let mut kt = vec![0.0; k * k];
            for i in 0..n {
                for j in 0..n {
                    kt[j * k + i] = lcp.at(i, j);
                }
                kt[(n + i) * k + i] = -1.0;
                kt[i * k + n + i] = w[i];
                kt[(n + i) * k + n + i] = z[i];
            }
            let rhs: Vec<f64> = g.iter().chain(&h).copied().collect();
            let ab = gauss_jordan(kt, rhs, k).expect("KKT system nonsingular");
            let scale = ours.q.iter().fold(1e-300f64, |a, x| a.max(x.abs()));
            for i in 0..n {
                assert!((ours.q[i] + ab[i]).abs() <= 1e-9 * scale, "n = {n}: q[{i}]");
                for j in 0..n {
                    let want = -ab[i] * z[j];
                    let got = ours.m[i * n + j];
                    assert!(
                        (got - want).abs() <= 1e-9 * scale * (1.0 + z[j].abs()),
                        "n = {n}: M[{i}][{j}]"
                    );
                }
            }
            compared += 1;
        }
    }
    assert!(compared >= 60, "{compared}");
}

#[test]
fn degenerate_singular_and_non_solutions_are_flagged() {
    // M = I, q = (−1, 0): z = (1, 0), w = (0, 0): row 1 is degenerate.
    let lcp = Lcp::new(vec![1.0, 0.0, 0.0, 1.0], vec![-1.0, 0.0]).unwrap();
    let g = lcp_vjp(&lcp, &[1.0, 0.0], &[1.0, 1.0], Some(&[0.0, 2.0]), TOL).unwrap();
    assert_eq!(g.derivative, Derivative::OneSided);
    // Row 1 treated as inactive: ∂L/∂q = (−1, h_1), ∂L/∂M = r zᵀ.
    assert_eq!(g.q, vec![-1.0, 2.0]);
    assert_eq!(g.m, vec![-1.0, 0.0, 2.0, 0.0]);
    // The same with a strictly inactive row 1: exact.
    let lcp2 = Lcp::new(lcp.m.clone(), vec![-1.0, 0.5]).unwrap();
    let g2 = lcp_vjp(&lcp2, &[1.0, 0.0], &[1.0, 1.0], None, TOL).unwrap();
    assert_eq!(g2.derivative, Derivative::Exact);
    assert_eq!(g2.q, vec![-1.0, 0.0]);
    // Rank one: z₁ + z₂ = 1 is a segment of solutions, M_αα singular.
    let seg = Lcp::new(vec![1.0; 4], vec![-1.0, -1.0]).unwrap();
    let g = lcp_vjp(&seg, &[0.5, 0.5], &[1.0, 0.0], None, TOL).unwrap();
    assert_eq!(g.derivative, Derivative::Undefined);
    assert!(g.m.iter().chain(&g.q).all(|&x| x == 0.0));
    // Not a solution (z ⟂ w fails, or z < 0): undefined, zeros.
    for z in [[1.0, 1.0], [-1.0, 0.0]] {
        let g = lcp_vjp(&lcp2, &z, &[1.0, 1.0], None, TOL).unwrap();
        assert_eq!(g.derivative, Derivative::Undefined, "{z:?}");
    }
    // Names and their inverse.
    for d in Derivative::ALL {
        assert_eq!(d.name().parse::<Derivative>().unwrap(), d);
    }
    let e = "both".parse::<Derivative>().unwrap_err().to_string();
    assert!(e.contains("exact, one_sided, undefined"), "{e}");
}

#[test]
fn bad_input_names_the_island_and_the_field() {
    let lcp = Lcp::new(vec![2.0, 0.0, 0.0, 2.0], vec![-1.0, 1.0]).unwrap();
    let err = |r: Result<_, crate::Error>| r.map(|_: Vec<LcpGradient>| ()).unwrap_err().to_string();
    let z: &[f64] = &[0.5, 0.0];
    let one =
        |z: &[f64], dz: &[f64], dw: Option<&[f64]>| lcp_vjp(&lcp, z, dz, dw, TOL).map(|g| vec![g]);
    assert_eq!(
        err(one(&[0.5], &[1.0, 0.0], None)),
        "island 0: field `z`: has 1 entries, expected 2"
    );
    assert_eq!(
        err(one(z, &[1.0, f64::NAN], None)),
        "island 0: field `dz[1]`: not a finite number"
    );
    assert_eq!(
        err(one(z, &[1.0, 0.0], Some(&[1.0, 2.0, 3.0]))),
        "island 0: field `dw`: has 3 entries, expected 2"
    );
    let lcps = vec![lcp.clone(), lcp.clone()];
    let good: &[f64] = &[1.0, 0.0];
    let bad: &[f64] = &[f64::INFINITY, 0.0];
    assert_eq!(
        err(lcp_vjp_batch(
            &lcps,
            &[z, z],
            &[good, good],
            Some(&[good, bad]),
            TOL
        )),
        "island 1: field `dw[0]`: not a finite number"
    );
    assert_eq!(
        err(lcp_vjp_batch(&lcps, &[z], &[good, good], None, TOL)),
        "batch: field `z`: has 1 entries, expected 2"
    );
    assert_eq!(
        err(lcp_vjp_batch(&lcps, &[z, z], &[good, good], None, 1.5)),
        "gradient: field `tolerance`: 1.5 is not in [0, 1)"
    );
    let mut broken = lcps.clone();
    broken[1].m[1] = f64::NAN;
    assert_eq!(
        err(lcp_vjp_batch(&broken, &[z, z], &[good, good], None, TOL)),
        "island 1: field `M[0][1]`: not a finite number"
    );
}

/// `lcp_vjp_dense_into` (the Python binding's door: flat arrays in, the
/// caller's arrays out) gives bit for bit what `lcp_vjp_batch` gives on
/// the same problems, undefined islands' zeros over whatever the output
/// held, and the same first error.
#[test]
fn dense_into_agrees_with_the_batch_product() {
    let mut rng = Rng::new(0xD3E5);
    let n = 6;
    let mut lcps: Vec<Lcp> = (0..3000)
        .map(|i| random_lcp(&mut rng, n, [Kind::Pd, Kind::PMatrix][i % 2]))
        .collect();
    // M = 0 with q < 0: no solution at z = 0, so undefined.
    lcps.push(Lcp::new(vec![0.0; n * n], vec![-1.0; n]).unwrap());
    let report = Solver::new(Settings::new(Backend::Cpu, Method::Lemke))
        .unwrap()
        .solve_lcps(&lcps)
        .unwrap();
    // The last island at z = 0 (w = q < 0: undefined).
    let mut z: Vec<f64> = report.islands[..lcps.len() - 1]
        .iter()
        .flat_map(|i| i.solution.z.iter().copied())
        .collect();
    z.extend([0.0; 6]);
    let b = lcps.len();
    let dz: Vec<f64> = (0..b * n).map(|_| rng.range(-1.0, 1.0)).collect();
    let dw: Vec<f64> = (0..b * n).map(|_| rng.range(-1.0, 1.0)).collect();
    let m: Vec<f64> = lcps.iter().flat_map(|l| l.m.clone()).collect();
    let q: Vec<f64> = lcps.iter().flat_map(|l| l.q.clone()).collect();
    let rows = |v: &[f64]| v.chunks_exact(n).map(|c| c.to_vec()).collect::<Vec<_>>();
    let (zr, dzr, dwr) = (rows(&z), rows(&dz), rows(&dw));
    fn s(v: &[Vec<f64>]) -> Vec<&[f64]> {
        v.iter().map(|r| &r[..]).collect()
    }
    for with_dw in [false, true] {
        let dwo = with_dw.then_some(&dw[..]);
        let want = lcp_vjp_batch(
            &lcps,
            &s(&zr),
            &s(&dzr),
            with_dw.then(|| s(&dwr)).as_deref(),
            TOL,
        )
        .unwrap();
        let (mut gm, mut gq) = (vec![f64::NAN; b * n * n], vec![f64::NAN; b * n]);
        let got = lcp_vjp_dense_into(n, &m, &q, &z, &dz, dwo, TOL, &mut gm, &mut gq).unwrap();
        assert!(want.iter().any(|g| g.derivative == Derivative::Undefined));
        for (i, g) in want.iter().enumerate() {
            assert_eq!(got[i], g.derivative, "island {i}");
            assert_eq!(&gm[i * n * n..(i + 1) * n * n], &g.m[..], "island {i}");
            assert_eq!(&gq[i * n..(i + 1) * n], &g.q[..], "island {i}");
        }
    }
    let mut bad = dz.clone();
    bad[7 * n + 2] = f64::NAN;
    let (mut gm, mut gq) = (vec![0.0; b * n * n], vec![0.0; b * n]);
    let e = lcp_vjp_dense_into(n, &m, &q, &z, &bad, None, TOL, &mut gm, &mut gq).unwrap_err();
    assert_eq!(
        e.to_string(),
        "island 7: field `dz[2]`: not a finite number"
    );
    let e = lcp_vjp_dense_into(n, &m, &q[1..], &z, &dz, None, TOL, &mut gm, &mut gq).unwrap_err();
    assert!(e.to_string().starts_with("batch: "), "{e}");
}

/// A batch of 3,000 (more than one chunk per thread) through the solver:
/// `Report::lcp_vjps` gives, island by island, what `lcp_vjp` gives at the
/// reported z, and islands without a solution come back undefined.
#[test]
fn report_and_batch_agree_with_the_single_island_product() {
    let mut rng = Rng::new(0xBA7C);
    let mut lcps: Vec<Lcp> = (0..3000)
        .map(|i| random_lcp(&mut rng, 1 + i % 8, [Kind::Pd, Kind::PMatrix][i % 2]))
        .collect();
    // No solution: M = −1, q = −1.
    lcps.push(Lcp::new(vec![-1.0], vec![-1.0]).unwrap());
    let report = Solver::new(Settings::new(Backend::Cpu, Method::Lemke))
        .unwrap()
        .solve_lcps(&lcps)
        .unwrap();
    let dz: Vec<Vec<f64>> = lcps
        .iter()
        .map(|l| (0..l.n()).map(|_| rng.range(-1.0, 1.0)).collect())
        .collect();
    let dz: Vec<&[f64]> = dz.iter().map(|v| &v[..]).collect();
    let z: Vec<&[f64]> = report.islands.iter().map(|i| &i.solution.z[..]).collect();
    let from_report = report.lcp_vjps(&lcps, &dz, Some(&dz)).unwrap();
    let batch = lcp_vjp_batch(&lcps, &z, &dz, Some(&dz), TOL).unwrap();
    for (i, lcp) in lcps.iter().enumerate().take(3000) {
        let single = lcp_vjp(lcp, z[i], dz[i], Some(dz[i]), TOL).unwrap();
        for g in [&from_report[i], &batch[i]] {
            assert_eq!(
                (&g.m, &g.q, g.derivative),
                (&single.m, &single.q, single.derivative),
                "island {i}"
            );
        }
    }
    assert_eq!(from_report[3000].derivative, Derivative::Undefined);
    assert!(from_report[3000].q.iter().all(|&x| x == 0.0));
    let e = report
        .lcp_vjps(&lcps[1..], &dz[1..], None)
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("batch: field `lcps`"), "{e}");
}
