//! Lemke's complementary pivoting algorithm (seed 002), with a lexicographic
//! ratio test so that it cannot cycle on degenerate problems.
//!
//! The artificial variable z0 with covering vector e = (1, …, 1) turns the
//! LCP into w − M z − e z0 = q. The tableau holds B⁻¹[I, −M, −e | q] for the
//! current basis B; the first n columns are B⁻¹ itself, which the
//! lexicographic test reads. Each step brings in the complement of the
//! variable that just left, until z0 leaves (a solution) or the entering
//! column has no positive entry (a secondary ray: Lemke gives up).

use crate::lcp::{Counters, Lcp, LcpSolution, Status};
use crate::linalg::{solve_in_place, PIVOT_TOL};

/// Settings of Lemke's algorithm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LemkeSettings {
    /// Pivot cap (default 10,000); reaching it gives `NotConverged`.
    pub max_pivots: u64,
    /// An entry of the entering column counts as positive when it exceeds
    /// this times the column's largest magnitude (default 1e-12).
    pub pivot_tol: f64,
}

impl Default for LemkeSettings {
    fn default() -> Self {
        LemkeSettings {
            max_pivots: 10_000,
            pivot_tol: 1e-12,
        }
    }
}

/// Variable indices in the tableau: w_i = i, z_i = n + i, z0 = 2n.
fn complement(var: usize, n: usize) -> usize {
    if var < n {
        var + n
    } else {
        var - n
    }
}

/// How one run of the pivoting path ended.
enum PathEnd {
    /// z0 left (Solved), a secondary ray, or the pivot cap.
    Done(Status),
    /// A (basis, entering variable) pair came back: the path cycles. Exact
    /// lexicographic pivoting cannot cycle; floating point can, where
    /// rounding decides a tie (a right-hand side of 0 against 1e-17).
    Cycled,
}

/// Solves `lcp` with Lemke's algorithm. Statuses: `Solved`, `RayTermination`,
/// `NotConverged` (pivot cap). The counters carry the pivot count.
///
/// If the pivoting path cycles (see [`PathEnd::Cycled`]), the run starts over
/// on q perturbed by 1e-10·‖q‖∞ (then 1e-7·‖q‖∞) with distinct weights per
/// row, which breaks the ties rounding decided; the final basis is then
/// re-solved with the true q, and the error reported is the true problem's.
pub fn lemke(lcp: &Lcp, settings: &LemkeSettings) -> LcpSolution {
    let n = lcp.n();
    let mut counters = Counters::default();
    if lcp.q.iter().all(|&v| v >= 0.0) {
        let mut sol = LcpSolution::from_z(lcp, Status::Solved, vec![0.0; n], counters);
        sol.basis = Some(0);
        return sol;
    }
    let qmax = lcp.q.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let mut result = None;
    for eta in [0.0, 1e-10, 1e-7] {
        // Weights in [1, 2), distinct for every row (golden-ratio sequence).
        let q: Vec<f64> = (0..n)
            .map(|i| lcp.q[i] + eta * qmax * (1.0 + (i as f64 * 0.618_033_988_749_895).fract()))
            .collect();
        let (end, basic, t) = pivot_path(lcp, &q, settings, &mut counters);
        match end {
            PathEnd::Done(status) => {
                result = Some((status, basic, t));
                break;
            }
            PathEnd::Cycled => continue,
        }
    }
    let Some((status, basic, t)) = result else {
        return LcpSolution::from_z(lcp, Status::NotConverged, vec![0.0; n], counters);
    };
    let cols = 2 * n + 2;
    let rhs = 2 * n + 1;
    let mut z = vec![0.0; n];
    let mut support = Vec::new();
    for (i, &v) in basic.iter().enumerate() {
        if (n..2 * n).contains(&v) {
            z[v - n] = t[i * cols + rhs].max(0.0);
            support.push(v - n);
        }
    }
    support.sort_unstable();
    let mut sol = LcpSolution::from_z(lcp, status, z, counters);
    if status == Status::Solved {
        if let Some(polished) = polish(lcp, &support) {
            let better = LcpSolution::from_z(lcp, status, polished, counters);
            if better.residuals.error <= sol.residuals.error {
                sol = better;
            }
        }
        if n <= 32 {
            sol.basis = Some(support.iter().fold(0u32, |m, &i| m | 1 << i));
        }
    }
    sol
}

/// One run of the complementary pivoting path on (M, q).
fn pivot_path(
    lcp: &Lcp,
    q: &[f64],
    settings: &LemkeSettings,
    counters: &mut Counters,
) -> (PathEnd, Vec<usize>, Vec<f64>) {
    let n = lcp.n();
    let cols = 2 * n + 2; // w, z, z0, rhs
    let rhs = 2 * n + 1;
    let z0 = 2 * n;
    let mut t = vec![0.0f64; n * cols];
    for i in 0..n {
        t[i * cols + i] = 1.0;
        for j in 0..n {
            t[i * cols + n + j] = -lcp.at(i, j);
        }
        t[i * cols + z0] = -1.0;
        t[i * cols + rhs] = q[i];
    }
    let mut basic: Vec<usize> = (0..n).collect();

    // First pivot: z0 enters at the value that makes the most negative q_i zero.
    // Lexicographic minimum of (q_i, row i of B⁻¹) over all rows.
    let first = first_row(&t, cols, n);
    pivot(&mut t, cols, n, first, z0);
    counters.pivots += 1;
    let mut entering = complement(basic[first], n);
    basic[first] = z0;
    let mut seen = std::collections::HashSet::new();

    let end = loop {
        if counters.pivots >= settings.max_pivots {
            break PathEnd::Done(Status::NotConverged);
        }
        let mut key: Vec<usize> = basic.clone();
        key.sort_unstable();
        key.push(entering);
        if !seen.insert(key) {
            break PathEnd::Cycled;
        }
        let colmax = (0..n).fold(0.0f64, |m, i| m.max(t[i * cols + entering].abs()));
        let tol = settings.pivot_tol * colmax;
        let candidates: Vec<usize> = (0..n).filter(|&i| t[i * cols + entering] > tol).collect();
        // x_B = rhs − T[:, e] t for the entering variable at value t ≥ 0:
        // rows with a positive entry decrease; the first to reach zero leaves.
        if candidates.is_empty() || colmax == 0.0 {
            break PathEnd::Done(Status::RayTermination);
        }
        let best = leaving_row(&t, cols, n, entering, &candidates, |i| basic[i] == z0);
        pivot(&mut t, cols, n, best, entering);
        counters.pivots += 1;
        let leaving = basic[best];
        basic[best] = entering;
        if leaving == z0 {
            break PathEnd::Done(Status::Solved);
        }
        entering = complement(leaving, n);
    };
    (end, basic, t)
}

/// Re-solves the final basis from the original data, M_SS z_S = −q_S: the
/// tableau's values carry the rounding of every pivot, this solve only its
/// own. None when M_SS is singular. Negative entries are clamped to 0; the
/// caller keeps whichever z has the smaller error.
fn polish(lcp: &Lcp, support: &[usize]) -> Option<Vec<f64>> {
    let k = support.len();
    let mut a: Vec<f64> = support
        .iter()
        .flat_map(|&i| support.iter().map(move |&j| lcp.at(i, j)))
        .collect();
    let mut x: Vec<f64> = support.iter().map(|&i| -lcp.q[i]).collect();
    if !solve_in_place(&mut a, &mut x, k, PIVOT_TOL) {
        return None;
    }
    let mut z = vec![0.0; lcp.n()];
    for (&i, &v) in support.iter().zip(&x) {
        z[i] = v.max(0.0);
    }
    Some(z)
}

/// The lexicographic minimum-ratio test: among `candidates` (rows whose
/// entry d_i in the entering column is positive), the row minimising
/// (rhs_i, B⁻¹_i0, B⁻¹_i1, …) / d_i lexicographically. B⁻¹ is the tableau's
/// w-columns. Rows of B⁻¹ are linearly independent, so exactly one row
/// survives, which is what keeps Lemke from cycling on degenerate problems.
///
/// Comparisons are exact: a tolerance on ties (tried: 1e-14 to 1e-9 relative
/// to the column) merges rows whose keys truly differ, breaks the strict
/// lexicographic order and made Lemke cycle on Siconos' lcp_tobenna; exact
/// comparison solves it in 179 pivots. rhs values that rounding made slightly
/// negative count as 0. When z0 is among the rows tied on the ratio itself,
/// z0 leaves: that ends the algorithm with a solution.
fn leaving_row(
    t: &[f64],
    cols: usize,
    n: usize,
    entering: usize,
    candidates: &[usize],
    is_z0: impl Fn(usize) -> bool,
) -> usize {
    let rhs = cols - 1;
    let mut tied: Vec<usize> = candidates.to_vec();
    // Column -1 is rhs, then the n columns of B⁻¹.
    for col in std::iter::once(rhs).chain(0..n) {
        let key = |i: usize| {
            let v = t[i * cols + col];
            let v = if col == rhs { v.max(0.0) } else { v };
            v / t[i * cols + entering]
        };
        let min = tied.iter().map(|&i| key(i)).fold(f64::INFINITY, f64::min);
        tied.retain(|&i| key(i) <= min);
        if col == rhs {
            if let Some(&z) = tied.iter().find(|&&i| is_z0(i)) {
                return z;
            }
        }
        if tied.len() == 1 {
            break;
        }
    }
    tied[0]
}

/// The first leaving row: the lexicographic minimum of (q_i, row i of I), i.e.
/// the most negative q_i, the largest index among exact ties (which keeps
/// every row lexicographically positive after the pivot).
fn first_row(t: &[f64], cols: usize, n: usize) -> usize {
    let rhs = cols - 1;
    let min = (0..n)
        .map(|i| t[i * cols + rhs])
        .fold(f64::INFINITY, f64::min);
    (0..n)
        .rev()
        .find(|&i| t[i * cols + rhs] == min)
        .expect("n ≥ 1")
}

/// Gauss–Jordan pivot on (row r, column c).
fn pivot(t: &mut [f64], cols: usize, n: usize, r: usize, c: usize) {
    let inv = 1.0 / t[r * cols + c];
    for j in 0..cols {
        t[r * cols + j] *= inv;
    }
    t[r * cols + c] = 1.0;
    for i in 0..n {
        if i == r {
            continue;
        }
        let f = t[i * cols + c];
        if f != 0.0 {
            for j in 0..cols {
                t[i * cols + j] -= f * t[r * cols + j];
            }
            t[i * cols + c] = 0.0;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seed_002_walkthrough() {
        // Seed 002's equations use q = (−3, 6, −1): z = (0, 1, 3), w = (2, 0, 0).
        let m = vec![0.0, -1.0, 2.0, 2.0, 0.0, -2.0, -1.0, 1.0, 0.0];
        let lcp = Lcp::new(m.clone(), vec![-3.0, 6.0, -1.0]).unwrap();
        let sol = lemke(&lcp, &LemkeSettings::default());
        assert_eq!(sol.status, Status::Solved);
        for (a, b) in sol.z.iter().zip([0.0, 1.0, 3.0]) {
            assert!((a - b).abs() < 1e-12, "{:?}", sol.z);
        }
        for (a, b) in sol.w.iter().zip([2.0, 0.0, 0.0]) {
            assert!((a - b).abs() < 1e-12, "{:?}", sol.w);
        }
        // The printed q = (−3, 6, 1) has the solution z = (1, 0, 1.5).
        let lcp = Lcp::new(m, vec![-3.0, 6.0, 1.0]).unwrap();
        let sol = lemke(&lcp, &LemkeSettings::default());
        assert_eq!(sol.status, Status::Solved);
        for (a, b) in sol.z.iter().zip([1.0, 0.0, 1.5]) {
            assert!((a - b).abs() < 1e-12, "{:?}", sol.z);
        }
    }
}
