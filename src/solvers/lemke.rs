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
    /// A secondary ray with z0 at zero to rounding: the basis is a solution
    /// if its re-solve checks out (see [`ACCEPT_TOL`]).
    ArtificialAtZero,
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
    // The textbook run first (covering vector e, the pivot tolerance
    // relative to the entering column). Where it does not end on a checked
    // solution, the other runs are tried, and one of their answers is taken
    // only if it is a solution within ACCEPT_TOL on the problem as posed:
    // - D M D (when M's diagonal spreads over 1e6) rescues block-scaled M;
    // - the covering vector |q| keeps small components beside huge ones
    //   (z0 starts at 1 instead of max|q_i|);
    // both with the pivot-noise test that follows the data.
    let first = lemke_as_posed(lcp, settings, Cover::Ones, Noise::Column);
    let good = |s: &LcpSolution| s.status == Status::Solved && s.residuals.error <= RETRY_ABOVE;
    if good(&first) {
        return first;
    }
    let scaling = diagonal_scaling(lcp);
    let mut retries = Vec::new();
    if let Some(d) = &scaling {
        retries.push(lemke_scaled(lcp, d, settings, Cover::Ones));
    }
    retries.push(lemke_as_posed(lcp, settings, Cover::MinusQ, Noise::Data));
    if let Some(d) = &scaling {
        retries.push(lemke_scaled(lcp, d, settings, Cover::MinusQ));
    }
    let accepted = |s: &LcpSolution| s.status == Status::Solved && s.residuals.error <= ACCEPT_TOL;
    retries
        .into_iter()
        .filter(accepted)
        .min_by(|a, b| a.residuals.error.total_cmp(&b.residuals.error))
        .filter(|r| !accepted(&first) || r.residuals.error < first.residuals.error)
        .unwrap_or(first)
}

/// Which entries of the entering column count as pivots.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Noise {
    /// Above `pivot_tol` times the column's largest magnitude (the textbook
    /// run).
    Column,
    /// Above `pivot_tol` times the rounding the entry can carry,
    /// ε·Σ_j |B⁻¹_ij|·|a_j| with a the column in the original data: an entry
    /// small only because the data are (a row scaled by 1e-200) stays a pivot.
    Data,
}

/// A first answer with a larger error (or no solution) makes Lemke try the
/// covering vector |q| before giving its answer.
const RETRY_ABOVE: f64 = 1e-12;

/// The covering vector d of the artificial variable z0 (w − M z − d z0 = q).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Cover {
    /// d = (1, …, 1): the textbook choice.
    Ones,
    /// d_i = |q_i| (the smallest non-zero |q_j| where q_i = 0): every
    /// approaching row reaches zero at z0 = 1 together, whatever its scale.
    MinusQ,
}

impl Cover {
    fn vector(self, q: &[f64]) -> Vec<f64> {
        match self {
            Cover::Ones => vec![1.0; q.len()],
            Cover::MinusQ => {
                let floor = q
                    .iter()
                    .map(|v| v.abs())
                    .filter(|&v| v > 0.0)
                    .fold(f64::INFINITY, f64::min);
                let floor = if floor.is_finite() { floor } else { 1.0 };
                q.iter()
                    .map(|&v| if v != 0.0 { v.abs() } else { floor })
                    .collect()
            }
        }
    }
}

/// [`lemke`] on LCP(D M D, D q), whose solution is z' = D⁻¹ z, w' = D w
/// (D > 0 keeps every sign and every product z_i w_i = z'_i w'_i); z is
/// mapped back and polished on the problem as posed.
fn lemke_scaled(lcp: &Lcp, d: &[f64], settings: &LemkeSettings, cover: Cover) -> LcpSolution {
    let n = lcp.n();
    let scaled = Lcp {
        m: (0..n * n).map(|k| d[k / n] * lcp.m[k] * d[k % n]).collect(),
        q: lcp.q.iter().zip(d).map(|(q, d)| q * d).collect(),
    };
    let s = lemke_as_posed(&scaled, settings, cover, Noise::Data);
    let z: Vec<f64> = s.z.iter().zip(d).map(|(z, d)| z * d).collect();
    let mut sol = LcpSolution::from_z(lcp, s.status, z, s.counters);
    sol.basis = s.basis;
    if let (Status::Solved, Some(mask)) = (s.status, s.basis) {
        let support: Vec<usize> = (0..n).filter(|&i| mask >> i & 1 == 1).collect();
        if let Some(polished) = polish(lcp, &support) {
            let better = LcpSolution::from_z(lcp, s.status, polished, s.counters);
            if polish_wins(lcp, &better, &sol) {
                sol = LcpSolution {
                    basis: s.basis,
                    ..better
                };
            }
        }
    }
    sol
}

/// Diagonal spread above which Lemke runs on the scaled problem.
const SCALING_SPREAD: f64 = 1e6;

/// D = diag(1/√M_ii) (1 where M_ii ≤ 0) when the positive diagonal entries
/// of M spread over more than [`SCALING_SPREAD`]; None otherwise: a
/// well-scaled problem keeps its own rounding. The scaled M has a unit
/// diagonal, so the pivot and ratio tests compare like with like (on
/// M = diag(1e300, 1e-300) the unscaled run stops on a ray).
fn diagonal_scaling(lcp: &Lcp) -> Option<Vec<f64>> {
    let n = lcp.n();
    let diag = (0..n).map(|i| lcp.at(i, i)).filter(|&v| v > 0.0);
    let (lo, hi) = diag.fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    if !(hi > SCALING_SPREAD * lo) {
        return None;
    }
    Some(
        (0..n)
            .map(|i| {
                let v = lcp.at(i, i);
                if v > 0.0 {
                    1.0 / v.sqrt()
                } else {
                    1.0
                }
            })
            .collect(),
    )
}

/// [`lemke`] on the problem as posed, without scaling.
fn lemke_as_posed(lcp: &Lcp, settings: &LemkeSettings, cover: Cover, noise: Noise) -> LcpSolution {
    let n = lcp.n();
    let mut counters = Counters::default();
    if lcp.q.iter().all(|&v| v >= 0.0) {
        let mut sol = LcpSolution::from_z(lcp, Status::Solved, vec![0.0; n], counters);
        sol.basis = Some(0);
        return sol;
    }
    let qmax = lcp.q.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let d = cover.vector(&lcp.q);
    // The first run that did not end on a solution, reported if no later
    // (perturbed) run finds one.
    let mut failed: Option<LcpSolution> = None;
    for eta in [0.0, 1e-10, 1e-7] {
        // Weights in [1, 2), distinct for every row (golden-ratio sequence).
        let q: Vec<f64> = (0..n)
            .map(|i| lcp.q[i] + eta * qmax * (1.0 + (i as f64 * 0.618_033_988_749_895).fract()))
            .collect();
        let (end, basic, t) = pivot_path(lcp, &q, &d, noise, settings, &mut counters);
        let (status, checked) = match end {
            PathEnd::Cycled => continue,
            PathEnd::ArtificialAtZero => (Status::Solved, true),
            // A solution of a perturbed q counts once its basis re-solved
            // with the true q checks out.
            PathEnd::Done(status) => (status, eta > 0.0),
        };
        let sol = basis_solution(lcp, status, &basic, &t, counters, checked);
        if sol.status == Status::Solved {
            return sol;
        }
        // Degenerate ties (a resting stack: equal q_i, rank-deficient M)
        // can send the unperturbed path onto a ray rounding made up; the
        // perturbed runs break the ties.
        failed.get_or_insert(sol);
    }
    failed.unwrap_or_else(|| LcpSolution::from_z(lcp, Status::NotConverged, vec![0.0; n], counters))
}

/// The solution of the final tableau: z from its basic values, then the
/// basis re-solved with the true q ([`polish`]). With `checked`, `Solved`
/// stands only if the error is at most [`ACCEPT_TOL`] (else `RayTermination`).
fn basis_solution(
    lcp: &Lcp,
    status: Status,
    basic: &[usize],
    t: &[f64],
    counters: Counters,
    checked: bool,
) -> LcpSolution {
    let n = lcp.n();
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
            if polish_wins(lcp, &better, &sol) {
                sol = better;
            }
        }
        if n <= 32 {
            sol.basis = Some(support.iter().fold(0u32, |m, &i| m | 1 << i));
        }
        if checked && !(sol.residuals.error <= ACCEPT_TOL) {
            sol.status = Status::RayTermination;
            sol.basis = None;
        }
    }
    sol
}

/// A ray reached with z0 at zero to rounding, or a solution of a perturbed
/// q, ends with `Solved` only when the basis re-solved with the true q has
/// at most this error; otherwise it is a ray.
const ACCEPT_TOL: f64 = 1e-9;

/// One run of the complementary pivoting path on (M, q).
fn pivot_path(
    lcp: &Lcp,
    q: &[f64],
    cover: &[f64],
    noise_rule: Noise,
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
        t[i * cols + z0] = -cover[i];
        t[i * cols + rhs] = q[i];
    }
    let mut basic: Vec<usize> = (0..n).collect();
    let q_scale = q.iter().fold(0.0f64, |m, v| m.max(v.abs()));

    // First pivot: z0 enters (see first_row).
    let first = first_row(&t, cols, n, cover);
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
        let (colmax, candidates) = pivot_candidates(lcp, &t, cover, entering, noise_rule, settings);
        // x_B = rhs − T[:, e] t for the entering variable at value t ≥ 0:
        // rows with a positive entry decrease; the first to reach zero leaves.
        if candidates.is_empty() || colmax == 0.0 {
            // z0 at zero to rounding: the current basis is already a
            // solution (a degenerate step let another variable leave in
            // z0's place, by 1e-17); the caller re-solves and checks it.
            let z0_row = basic.iter().position(|&v| v == z0);
            let at_zero = z0_row.is_some_and(|r| t[r * cols + rhs] <= settings.pivot_tol * q_scale);
            break if at_zero {
                PathEnd::ArtificialAtZero
            } else {
                PathEnd::Done(Status::RayTermination)
            };
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

/// The rows whose entry in the entering column counts as a pivot (see
/// [`Noise`]), and the column's largest magnitude.
fn pivot_candidates(
    lcp: &Lcp,
    t: &[f64],
    cover: &[f64],
    entering: usize,
    noise_rule: Noise,
    settings: &LemkeSettings,
) -> (f64, Vec<usize>) {
    let n = lcp.n();
    let cols = 2 * n + 2;
    let colmax = (0..n).fold(0.0f64, |m, i| m.max(t[i * cols + entering].abs()));
    let a = (noise_rule == Noise::Data).then(|| original_column(lcp, cover, entering));
    let noise = |i: usize| match &a {
        None => settings.pivot_tol * colmax,
        Some(a) => {
            let mut sum = 0.0;
            for (j, aj) in a.iter().enumerate() {
                sum += t[i * cols + j].abs() * aj.abs();
            }
            settings.pivot_tol * sum
        }
    };
    let candidates = (0..n)
        .filter(|&i| t[i * cols + entering] > noise(i))
        .collect();
    (colmax, candidates)
}

/// Column `var` of [I, −M, −d] (w, z, z0; d the covering vector), the
/// entering column as the original data hold it.
fn original_column(lcp: &Lcp, cover: &[f64], var: usize) -> Vec<f64> {
    let n = lcp.n();
    match var {
        v if v < n => (0..n).map(|i| if i == v { 1.0 } else { 0.0 }).collect(),
        v if v < 2 * n => (0..n).map(|i| -lcp.at(i, v - n)).collect(),
        _ => cover.iter().map(|d| -d).collect(),
    }
}

/// Whether the polished z (the basis re-solved from the data) is kept over
/// the tableau's: by the row-relative residual ([`row_residual`]), not the
/// error measure, which cannot see rounding in a small w_i beside a huge
/// z_i (z_i − max(0, z_i − w_i) rounds to 0): the tableau's z can be wrong in
/// its 8th digit with an error measure of 1e-127.
fn polish_wins(lcp: &Lcp, polished: &LcpSolution, tableau: &LcpSolution) -> bool {
    row_residual(lcp, polished) <= row_residual(lcp, tableau)
}

/// max_i of the violation of row i (|w_i| where z_i > 0, else max(0, −w_i))
/// relative to the row's scale |q_i| + Σ_j |M_ij z_j|: the accuracy of a
/// basic solution that every row sees at its own scale.
fn row_residual(lcp: &Lcp, sol: &LcpSolution) -> f64 {
    let n = lcp.n();
    (0..n)
        .map(|i| {
            let w = sol.w[i];
            let v = if sol.z[i] > 0.0 {
                w.abs()
            } else {
                (-w).max(0.0)
            };
            let scale =
                lcp.q[i].abs() + (0..n).map(|j| (lcp.at(i, j) * sol.z[j]).abs()).sum::<f64>();
            if v == 0.0 {
                0.0
            } else {
                v / scale
            }
        })
        .fold(0.0, f64::max)
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

/// The first leaving row: z0 enters at the value that makes the most
/// negative q_i / d_i zero (d the covering vector). Lexicographically that
/// is the minimum of (q_i, row i of I) / d_i: among exact ties the largest
/// index, which keeps every row lexicographically positive after the pivot.
fn first_row(t: &[f64], cols: usize, n: usize, cover: &[f64]) -> usize {
    let rhs = cols - 1;
    let ratio = |i: usize| t[i * cols + rhs] / cover[i];
    let min = (0..n).map(ratio).fold(f64::INFINITY, f64::min);
    (0..n).rev().find(|&i| ratio(i) == min).expect("n ≥ 1")
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

#[cfg(test)]
mod properties {
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
}
