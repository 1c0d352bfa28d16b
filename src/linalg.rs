//! Small dense linear algebra in f64: the kernels the solvers share.
//!
//! Matrices are row-major slices of k×k entries. Nothing here allocates
//! except [`null_space`], which only the all-solutions analysis calls.

/// Default relative pivot tolerance: a pivot smaller than this times the
/// largest entry of its column in the original matrix means the matrix is
/// singular (to working precision). Relative to each column, so that scaling
/// the problem, or one contact's row and column, changes no verdict.
pub const PIVOT_TOL: f64 = 1e-13;

/// Solves A x = b by Gaussian elimination with partial pivoting, in place:
/// `a` (k×k, row-major) is destroyed and `x` holds b on entry, the solution on
/// exit.
///
/// Returns false, leaving `x` unspecified, when A is singular: a column that is
/// all zeros, or a pivot |u_cc| ≤ `pivot_tol` · max_r |A_rc| (the column's
/// largest entry before elimination). Never divides by such a pivot.
pub fn solve_in_place(a: &mut [f64], x: &mut [f64], k: usize, pivot_tol: f64) -> bool {
    debug_assert!(a.len() >= k * k && x.len() >= k);
    // The column maxima on the stack, no larger than k needs: zeroing 64
    // entries for a 4×4 basis costs as much as the columns' scan.
    // Contact islands' bases are small: k ≤ 6 is compiled for its size
    // (loops of known length, no bounds checks; the same operations in the
    // same order, so the same bits).
    match k {
        0 => true,
        1 => solve_fixed::<1>(a, x, pivot_tol),
        2 => solve_fixed::<2>(a, x, pivot_tol),
        3 => solve_fixed::<3>(a, x, pivot_tol),
        4 => solve_fixed::<4>(a, x, pivot_tol),
        5 => solve_fixed::<5>(a, x, pivot_tol),
        6 => solve_fixed::<6>(a, x, pivot_tol),
        7..=20 => solve_with::<20>(a, x, k, pivot_tol),
        21..=64 => solve_with::<64>(a, x, k, pivot_tol),
        _ => solve_large(a, x, k, pivot_tol),
    }
}

/// [`solve_in_place`] for k = `K`.
fn solve_fixed<const K: usize>(a: &mut [f64], x: &mut [f64], pivot_tol: f64) -> bool {
    let (a, x) = (&mut a[..K * K], &mut x[..K]);
    let mut colmax = [0.0f64; K];
    for r in 0..K {
        for c in 0..K {
            colmax[c] = colmax[c].max(a[r * K + c].abs());
        }
    }
    eliminate(a, x, K, pivot_tol, &colmax)
}

/// [`solve_in_place`] with the column maxima in `K` ≥ k entries.
fn solve_with<const K: usize>(a: &mut [f64], x: &mut [f64], k: usize, pivot_tol: f64) -> bool {
    let mut colmax = [0.0f64; K];
    let colmax = &mut colmax[..k];
    for r in 0..k {
        for c in 0..k {
            colmax[c] = colmax[c].max(a[r * k + c].abs());
        }
    }
    eliminate(a, x, k, pivot_tol, colmax)
}

fn solve_large(a: &mut [f64], x: &mut [f64], k: usize, pivot_tol: f64) -> bool {
    let mut colmax = vec![0.0f64; k];
    for r in 0..k {
        for c in 0..k {
            colmax[c] = colmax[c].max(a[r * k + c].abs());
        }
    }
    eliminate(a, x, k, pivot_tol, &colmax)
}

#[inline(always)]
fn eliminate(a: &mut [f64], x: &mut [f64], k: usize, pivot_tol: f64, colmax: &[f64]) -> bool {
    for c in 0..k {
        // Partial pivoting: the largest remaining entry of column c.
        let mut p = c;
        let mut best = a[c * k + c].abs();
        for r in c + 1..k {
            let v = a[r * k + c].abs();
            if v > best {
                best = v;
                p = r;
            }
        }
        if !(best > pivot_tol * colmax[c]) || best == 0.0 {
            return false;
        }
        if p != c {
            for j in 0..k {
                a.swap(c * k + j, p * k + j);
            }
            x.swap(c, p);
        }
        let inv = 1.0 / a[c * k + c];
        for r in c + 1..k {
            let f = a[r * k + c] * inv;
            if f != 0.0 {
                for j in c + 1..k {
                    a[r * k + j] -= f * a[c * k + j];
                }
                x[r] -= f * x[c];
            }
        }
    }
    for c in (0..k).rev() {
        let mut s = x[c];
        for j in c + 1..k {
            s -= a[c * k + j] * x[j];
        }
        x[c] = s / a[c * k + c];
    }
    true
}

/// A basis of the null space of A (k×k, row-major), computed by reduction to
/// row echelon form with partial pivoting and the same column-relative
/// tolerance as [`solve_in_place`]. Each vector is scaled to unit ∞-norm.
/// Empty when A is nonsingular.
pub fn null_space(a: &[f64], k: usize, pivot_tol: f64) -> Vec<Vec<f64>> {
    let mut m = a[..k * k].to_vec();
    let mut colmax = vec![0.0f64; k];
    for r in 0..k {
        for c in 0..k {
            colmax[c] = colmax[c].max(m[r * k + c].abs());
        }
    }
    let mut pivot_cols = Vec::new();
    let mut row = 0;
    for c in 0..k {
        if row == k {
            break;
        }
        let (p, best) = (row..k)
            .map(|r| (r, m[r * k + c].abs()))
            .fold((row, -1.0), |acc, v| if v.1 > acc.1 { v } else { acc });
        if !(best > pivot_tol * colmax[c]) || best == 0.0 {
            continue;
        }
        for j in 0..k {
            m.swap(row * k + j, p * k + j);
        }
        let inv = 1.0 / m[row * k + c];
        for j in 0..k {
            m[row * k + j] *= inv;
        }
        for r in 0..k {
            if r != row {
                let f = m[r * k + c];
                if f != 0.0 {
                    for j in 0..k {
                        m[r * k + j] -= f * m[row * k + j];
                    }
                }
            }
        }
        pivot_cols.push(c);
        row += 1;
    }
    let free: Vec<usize> = (0..k).filter(|c| !pivot_cols.contains(c)).collect();
    free.iter()
        .map(|&f| {
            // x_f = 1, x_pivot(r) = -R[r][f], other free variables 0.
            let mut v = vec![0.0; k];
            v[f] = 1.0;
            for (r, &pc) in pivot_cols.iter().enumerate() {
                v[pc] = -m[r * k + f];
            }
            let s = v.iter().fold(0.0f64, |a, x| a.max(x.abs()));
            v.iter_mut().for_each(|x| *x /= s);
            v
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_and_detects_singularity_relative_to_scale() {
        let mut a = [2.0, 1.0, 1.0, 2.0];
        let mut x = [5.0, 6.0];
        assert!(solve_in_place(&mut a, &mut x, 2, PIVOT_TOL));
        assert!((x[0] - 4.0 / 3.0).abs() < 1e-15 && (x[1] - 7.0 / 3.0).abs() < 1e-15);
        // Rank one, at every scale.
        for s in [1e-12, 1.0, 1e12] {
            let mut a = [s, s, s, s];
            let mut x = [1.0, 1.0];
            assert!(!solve_in_place(&mut a, &mut x, 2, PIVOT_TOL));
        }
        // Tiny but well-conditioned: not singular.
        let mut a = [1e-30, 0.0, 0.0, 1e-30];
        let mut x = [1e-30, 2e-30];
        assert!(solve_in_place(&mut a, &mut x, 2, PIVOT_TOL));
        assert!((x[1] - 2.0).abs() < 1e-14);
    }

    #[test]
    fn null_space_of_rank_deficient_matrix() {
        // [[1,1],[1,1]]: kernel (1,-1).
        let ns = null_space(&[1.0, 1.0, 1.0, 1.0], 2, PIVOT_TOL);
        assert_eq!(ns.len(), 1);
        assert!((ns[0][0] + ns[0][1]).abs() < 1e-15);
        assert!(null_space(&[2.0, 1.0, 1.0, 2.0], 2, PIVOT_TOL).is_empty());
        assert_eq!(null_space(&[0.0; 9], 3, PIVOT_TOL).len(), 3);
    }
}
