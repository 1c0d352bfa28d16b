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

/// Solves `lcp` with Lemke's algorithm. Statuses: `Solved`, `RayTermination`,
/// `NotConverged` (pivot cap). The counters carry the pivot count.
pub fn lemke(lcp: &Lcp, settings: &LemkeSettings) -> LcpSolution {
    let n = lcp.n();
    let mut counters = Counters::default();
    if lcp.q.iter().all(|&v| v >= 0.0) {
        let mut sol = LcpSolution::from_z(lcp, Status::Solved, vec![0.0; n], counters);
        sol.basis = Some(0);
        return sol;
    }
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
        t[i * cols + rhs] = lcp.q[i];
    }
    let mut basic: Vec<usize> = (0..n).collect();

    // First pivot: z0 enters at the value that makes the most negative q_i zero.
    // Lexicographic minimum of (q_i, row i of B⁻¹) over all rows.
    let first = (0..n)
        .min_by(|&a, &b| lex_cmp(&t, cols, n, rhs, a, b, -1.0, -1.0))
        .expect("n ≥ 1");
    pivot(&mut t, cols, n, first, z0);
    counters.pivots += 1;
    let mut entering = complement(basic[first], n);
    basic[first] = z0;

    let status = loop {
        if counters.pivots >= settings.max_pivots {
            break Status::NotConverged;
        }
        let colmax = (0..n).fold(0.0f64, |m, i| m.max(t[i * cols + entering].abs()));
        let tol = settings.pivot_tol * colmax;
        let candidates: Vec<usize> = (0..n).filter(|&i| t[i * cols + entering] > tol).collect();
        // x_B = rhs − T[:, e] t for the entering variable at value t ≥ 0:
        // rows with a positive entry decrease; the first to reach zero leaves.
        if candidates.is_empty() || colmax == 0.0 {
            break Status::RayTermination;
        }
        // Minimum ratio rhs_i / T_ie, lexicographically; z0 leaves on a tie.
        let mut best = candidates[0];
        for &i in &candidates[1..] {
            let ord = lex_cmp(
                &t,
                cols,
                n,
                rhs,
                i,
                best,
                t[i * cols + entering],
                t[best * cols + entering],
            );
            if ord == std::cmp::Ordering::Less
                || (ord == std::cmp::Ordering::Equal && basic[i] == z0)
            {
                best = i;
            }
        }
        if let Some(&zr) = candidates.iter().find(|&&i| basic[i] == z0) {
            // Prefer z0 when its ratio ties the minimum.
            let rz = t[zr * cols + rhs] / t[zr * cols + entering];
            let rb = t[best * cols + rhs] / t[best * cols + entering];
            if rz <= rb * (1.0 + 1e-14) + 1e-300 {
                best = zr;
            }
        }
        pivot(&mut t, cols, n, best, entering);
        counters.pivots += 1;
        let leaving = basic[best];
        basic[best] = entering;
        if leaving == z0 {
            break Status::Solved;
        }
        entering = complement(leaving, n);
    };

    let mut z = vec![0.0; n];
    let mut mask = 0u32;
    for (i, &v) in basic.iter().enumerate() {
        if (n..2 * n).contains(&v) {
            z[v - n] = t[i * cols + rhs].max(0.0);
            if v - n < 32 {
                mask |= 1 << (v - n);
            }
        }
    }
    let mut sol = LcpSolution::from_z(lcp, status, z, counters);
    if status == Status::Solved && n <= 32 {
        sol.basis = Some(mask);
    }
    sol
}

/// Lexicographic comparison of rows a and b of [rhs | B⁻¹], each divided by the
/// magnitude of its entry in the pivot column (da, db ≠ 0). For the first pivot
/// da = db = −1: the order of (q_i, row i of I).
#[allow(clippy::too_many_arguments)]
fn lex_cmp(
    t: &[f64],
    cols: usize,
    n: usize,
    rhs: usize,
    a: usize,
    b: usize,
    da: f64,
    db: f64,
) -> std::cmp::Ordering {
    let (sa, sb) = (da.abs(), db.abs());
    let ra = t[a * cols + rhs] / sa;
    let rb = t[b * cols + rhs] / sb;
    let tie = 1e-12 * ra.abs().max(rb.abs()).max(f64::MIN_POSITIVE);
    if (ra - rb).abs() > tie {
        return ra.partial_cmp(&rb).unwrap_or(std::cmp::Ordering::Equal);
    }
    for j in 0..n {
        let xa = t[a * cols + j] / sa;
        let xb = t[b * cols + j] / sb;
        let tie = 1e-12 * xa.abs().max(xb.abs());
        if (xa - xb).abs() > tie {
            return xa.partial_cmp(&xb).unwrap_or(std::cmp::Ordering::Equal);
        }
    }
    std::cmp::Ordering::Equal
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
