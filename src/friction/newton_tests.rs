//! The Levenberg–Marquardt step's products and factorisation against the
//! plain loops they replace: the same bits (the world steps and the
//! Siconos answers of the suite depend on them).

use super::*;
use crate::friction::sparse::SPARSE_FROM;
use crate::friction::workspace::{dot, dots};

/// A chain of `k` contacts between `k + 1` bodies (contact i between
/// bodies a and a + 1, a random), W = J Jᵀ with random 3 × 6 blocks:
/// block-sparse from `SPARSE_FROM` contacts on, semidefinite (more
/// contact directions than degrees of freedom from k = 2 on).
fn chain(seed: u64, k: usize) -> FrictionProblem {
    let mut rng = crate::generate::Rng::new(seed);
    let bodies = k + 1;
    let n = 3 * k;
    let mut jac = vec![0.0; n * 6 * bodies];
    for i in 0..k {
        let a = rng.int(0, bodies - 2);
        for row in 3 * i..3 * i + 3 {
            for col in 6 * a..6 * a + 12 {
                jac[row * 6 * bodies + col] = rng.range(-1.0, 1.0);
            }
        }
    }
    let m = 6 * bodies;
    let w = (0..n * n)
        .map(|e| {
            (0..m)
                .map(|c| jac[e / n * m + c] * jac[e % n * m + c])
                .sum()
        })
        .collect();
    let q = (0..n).map(|_| rng.range(-1.0, 1.0)).collect();
    let mu = (0..k).map(|_| rng.range(0.1, 1.0)).collect();
    FrictionProblem::new(w, q, mu).unwrap()
}

#[test]
fn dots_give_the_bits_of_dot() {
    let mut rng = crate::generate::Rng::new(5);
    for len in 0..23 {
        let v = |rng: &mut crate::generate::Rng| -> Vec<f64> {
            (0..len).map(|_| rng.range(-1.0, 1.0)).collect()
        };
        let (x, a, b, c, d) = (
            v(&mut rng),
            v(&mut rng),
            v(&mut rng),
            v(&mut rng),
            v(&mut rng),
        );
        let want = [dot(&a, &x), dot(&b, &x), dot(&c, &x), dot(&d, &x)].map(f64::to_bits);
        assert_eq!(dots([&a[..], &b, &c, &d], &x).map(f64::to_bits), want);
        assert_eq!(dots([&a[..], &b, &c], &x).map(f64::to_bits), want[..3]);
        assert_eq!(dots([&a[..]], &x).map(f64::to_bits), want[..1]);
    }
}

#[test]
fn block_runs_are_the_runs_of_consecutive_blocks() {
    let runs: Vec<_> = block_runs(&[0, 1, 2, 5, 7, 8]).collect();
    assert_eq!(runs, [(0, 3), (5, 6), (7, 9)]);
    assert_eq!(block_runs(&[]).count(), 0);
}

/// ∂Φᵀ∂Φ and −∂ΦᵀΦ of `normal_system` against one row of ∂Φ at a time
/// over every column (a product with a zero of ∂Φ skipped), bit for bit,
/// on small (dense) and large (reordered, enveloped) islands; and the
/// Cholesky of the damped matrix against the one-row-at-a-time loop.
#[test]
fn the_normal_system_and_its_cholesky_keep_the_plain_loops_bits() {
    for (seed, k) in [(1, 3), (2, 12), (3, 40), (4, 57)] {
        let p0 = chain(seed, k);
        let mut ws = Workspace::default();
        let p = if k >= SPARSE_FROM {
            ws.pattern.build(&p0);
            let order = super::super::sparse::bandwidth_order(&ws.pattern);
            ws.pattern.permute(&order);
            super::super::sparse::permuted(&p0, &order, &ws.pattern)
        } else {
            p0
        };
        let n = p.dim();
        let r: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin().abs()).collect();
        ws.prepare_with(&p, &r, k >= SPARSE_FROM);
        ws.newton_buffers();
        alart_curnier(
            &p,
            &r,
            &ws.u,
            &ws.rho,
            &mut ws.phi,
            Some((&mut ws.jac, &ws.pattern)),
        );
        normal_system(n, &mut ws);
        let (mut normal, mut rhs) = (vec![0.0; n * n], vec![0.0; n]);
        for (row, f) in ws.jac.chunks_exact(n).zip(&ws.phi) {
            for i in (0..n).filter(|&i| row[i] != 0.0) {
                for j in i..n {
                    normal[j * n + i] += row[i] * row[j];
                }
            }
            for c in (0..n).filter(|_| *f != 0.0) {
                rhs[c] -= row[c] * f;
            }
        }
        assert_eq!(rhs.map_bits(), ws.trial.map_bits(), "k = {k}: −∂ΦᵀΦ");
        for j in 0..n {
            let first = ws.first[j];
            assert!(normal[j * n..j * n + first].iter().all(|&v| v == 0.0));
            let (got, want) = (
                &ws.normal[j * n + first..=j * n + j],
                &normal[j * n + first..=j * n + j],
            );
            assert_eq!(
                got.to_vec().map_bits(),
                want.to_vec().map_bits(),
                "k = {k}, row {j}"
            );
        }
        // The damped matrix's Cholesky: against one row at a time.
        for (i, v) in normal.iter_mut().enumerate() {
            *v += if i % (n + 1) == 0 { 1e-6 } else { 0.0 };
        }
        let (mut a, mut x) = (normal.clone(), rhs.clone());
        assert!(cholesky_in(&mut a, &mut x, n, None, &ws.first).is_some());
        let (mut b, mut y) = (normal, rhs);
        cholesky_one_row_at_a_time(&mut b, &mut y, n, &ws.first);
        assert_eq!(x.map_bits(), y.map_bits(), "k = {k}: Cholesky");
    }
}

/// `cholesky_in`'s factorisation (no pivot dropped) one row of L at a
/// time by `dot`, as it was, and its two solves.
fn cholesky_one_row_at_a_time(a: &mut [f64], x: &mut [f64], n: usize, env: &[usize]) {
    let (first, last) = env.split_at(n);
    for j in 0..n {
        let fj = first[j];
        let row_j = &a[j * n + fj..j * n + j];
        let d = (a[j * n + j] - dot(row_j, row_j)).sqrt();
        a[j * n + j] = d;
        for i in j + 1..=last[j] {
            if first[i] > j {
                continue;
            }
            let s = first[i].max(fj);
            let (upper, lower) = a.split_at_mut(i * n);
            let li = &mut lower[..n];
            li[j] = (li[j] - dot(&li[s..j], &upper[j * n + s..j * n + j])) * (1.0 / d);
        }
    }
    for i in 0..n {
        let fi = first[i];
        x[i] = (x[i] - dot(&a[i * n + fi..i * n + i], &x[fi..i])) / a[i * n + i];
    }
    for i in (0..n).rev() {
        let mut v = x[i];
        for k in (i + 1..=last[i]).filter(|&k| first[k] <= i) {
            v -= a[k * n + i] * x[k];
        }
        x[i] = v / a[i * n + i];
    }
}

trait Bits {
    fn map_bits(&self) -> Vec<u64>;
}

impl Bits for Vec<f64> {
    fn map_bits(&self) -> Vec<u64> {
        self.iter().map(|v| v.to_bits()).collect()
    }
}
