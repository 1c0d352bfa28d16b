//! Lemke's complementary pivoting algorithm (Lemke 1965; Cottle–Pang–Stone
//! 1992, §4.4), with a lexicographic ratio test so that it cannot cycle on
//! degenerate problems.
//!
//! The artificial variable z0 with covering vector e = (1, …, 1) turns the
//! LCP into w − M z − e z0 = q. The tableau holds B⁻¹[I, −M, −e | q] for the
//! current basis B; the first n columns are B⁻¹ itself, which the
//! lexicographic test reads. Each step brings in the complement of the
//! variable that just left, until z0 leaves (a solution) or the entering
//! column has no positive entry (a secondary ray: Lemke gives up).

use std::cell::RefCell;

use super::lemke_tableau::{PathEnd, Workspace};
use crate::lcp::{Counters, Lcp, LcpSolution, Residuals, Status};
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

thread_local! {
    /// Each thread's Lemke workspace: the tableau and scratch of the last
    /// solve, grown to the largest n seen, reused by the next.
    static WORKSPACE: RefCell<Workspace> = RefCell::new(Workspace::default());
}

/// Tableau entries a thread keeps between solves (n = 64: 64 × 130); a
/// larger problem's workspace is dropped after its solve, so that one big
/// LCP does not pin its tableau to the thread for good.
const KEPT_TABLEAU: usize = 64 * 130;

/// `f` with this thread's workspace (a fresh one should the thread's be in
/// use already, which no caller in the crate does).
fn with_workspace<T>(f: impl FnOnce(&mut Workspace) -> T) -> T {
    WORKSPACE.with(|ws| match ws.try_borrow_mut() {
        Ok(mut ws) => {
            let out = f(&mut ws);
            if ws.t.capacity() > KEPT_TABLEAU {
                *ws = Workspace::default();
            }
            out
        }
        Err(_) => f(&mut Workspace::default()),
    })
}

/// Solves `lcp` with Lemke's algorithm. Statuses: `Solved`, `RayTermination`,
/// `NotConverged` (pivot cap). The counters carry the pivot count.
///
/// If the pivoting path cycles (see `PathEnd::Cycled`), the run starts over
/// on q perturbed by 1e-10·‖q‖∞ (then 1e-7·‖q‖∞) with distinct weights per
/// row, which breaks the ties rounding decided; the final basis is then
/// re-solved with the true q, and the error reported is the true problem's.
///
/// The tableau and scratch live in a per-thread workspace: a batch of solves
/// on one thread allocates only the answers (z, w).
pub fn lemke(lcp: &Lcp, settings: &LemkeSettings) -> LcpSolution {
    with_workspace(|ws| lemke_in(ws, lcp, settings))
}

/// [`lemke`] with the caller's workspace.
fn lemke_in(ws: &mut Workspace, lcp: &Lcp, settings: &LemkeSettings) -> LcpSolution {
    // The textbook run first (covering vector e, the pivot tolerance
    // relative to the entering column). Where it does not end on a checked
    // solution, the other runs are tried, and one of their answers is taken
    // only if it is a solution within ACCEPT_TOL on the problem as posed:
    // - D M D (when M's diagonal spreads over 1e6) rescues block-scaled M;
    // - the covering vector |q| keeps small components beside huge ones
    //   (z0 starts at 1 instead of max|q_i|);
    // both with the pivot-noise test that follows the data.
    let first = lemke_as_posed(ws, lcp, settings, Cover::Ones, Noise::Column);
    let good = |s: &LcpSolution| s.status == Status::Solved && s.residuals.error <= RETRY_ABOVE;
    if good(&first) {
        return first;
    }
    let scaling = diagonal_scaling(lcp);
    let mut retries = Vec::new();
    if let Some(d) = &scaling {
        retries.push(lemke_scaled(ws, lcp, d, settings, Cover::Ones));
    }
    retries.push(lemke_as_posed(
        ws,
        lcp,
        settings,
        Cover::MinusQ,
        Noise::Data,
    ));
    if let Some(d) = &scaling {
        retries.push(lemke_scaled(ws, lcp, d, settings, Cover::MinusQ));
    }
    let accepted = |s: &LcpSolution| s.status == Status::Solved && s.residuals.error <= ACCEPT_TOL;
    retries
        .into_iter()
        .filter(accepted)
        .min_by(|a, b| a.residuals.error.total_cmp(&b.residuals.error))
        .filter(|r| !accepted(&first) || r.residuals.error < first.residuals.error)
        .unwrap_or(first)
}

/// The textbook run of [`lemke`] alone (covering vector e, the column's
/// pivot tolerance, q as posed, no perturbation): the final basis (bit i:
/// z_i basic) when the path ended on a solution, None otherwise (a ray, a
/// cycle, the pivot cap, n > 32), and the pivots it took. Nothing is
/// re-solved or checked: that is the caller's (the default CPU path
/// re-solves the basis in f64 and checks it, and calls [`lemke`] only where
/// that fails). This is the first thing [`lemke`] does, so where the check
/// passes the two agree on the basis.
pub fn lemke_textbook_basis(lcp: &Lcp, settings: &LemkeSettings) -> (Option<u32>, u64) {
    let n = lcp.n();
    if lcp.q.iter().all(|&v| v >= 0.0) {
        return (Some(0), 0);
    }
    if n > 32 {
        return (None, 0);
    }
    with_workspace(|ws| {
        let mut counters = Counters::default();
        ws.q.clear();
        ws.q.extend_from_slice(&lcp.q);
        Cover::Ones.fill(&lcp.q, &mut ws.cover);
        let end = ws.pivot_path(lcp, Noise::Column, settings, &mut counters);
        let mask = match end {
            PathEnd::Done(Status::Solved) | PathEnd::ArtificialAtZero => Some(
                ws.basic
                    .iter()
                    .filter(|&&v| (n..2 * n).contains(&v))
                    .fold(0u32, |m, &v| m | 1 << (v - n)),
            ),
            _ => None,
        };
        (mask, counters.pivots)
    })
}

/// Which entries of the entering column count as pivots.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Noise {
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
    /// Writes the covering vector for `q` into `out`.
    fn fill(self, q: &[f64], out: &mut Vec<f64>) {
        out.clear();
        match self {
            Cover::Ones => out.resize(q.len(), 1.0),
            Cover::MinusQ => {
                let floor = q
                    .iter()
                    .map(|v| v.abs())
                    .filter(|&v| v > 0.0)
                    .fold(f64::INFINITY, f64::min);
                let floor = if floor.is_finite() { floor } else { 1.0 };
                out.extend(q.iter().map(|&v| if v != 0.0 { v.abs() } else { floor }));
            }
        }
    }
}

/// [`lemke`] on LCP(D M D, D q), whose solution is z' = D⁻¹ z, w' = D w
/// (D > 0 keeps every sign and every product z_i w_i = z'_i w'_i); z is
/// mapped back and polished on the problem as posed.
fn lemke_scaled(
    ws: &mut Workspace,
    lcp: &Lcp,
    d: &[f64],
    settings: &LemkeSettings,
    cover: Cover,
) -> LcpSolution {
    let n = lcp.n();
    let scaled = Lcp {
        m: (0..n * n).map(|k| d[k / n] * lcp.m[k] * d[k % n]).collect(),
        q: lcp.q.iter().zip(d).map(|(q, d)| q * d).collect(),
    };
    let s = lemke_as_posed(ws, &scaled, settings, cover, Noise::Data);
    let z: Vec<f64> = s.z.iter().zip(d).map(|(z, d)| z * d).collect();
    let mut sol = LcpSolution::from_z(lcp, s.status, z, s.counters);
    sol.basis = s.basis;
    if let (Status::Solved, Some(mask)) = (s.status, s.basis) {
        ws.support.clear();
        ws.support.extend((0..n).filter(|&i| mask >> i & 1 == 1));
        if polish(ws, lcp) && polish_wins(lcp, &ws.z_polished, &sol.z) {
            sol = LcpSolution {
                basis: s.basis,
                ..LcpSolution::from_z(lcp, s.status, ws.z_polished.clone(), s.counters)
            };
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
fn lemke_as_posed(
    ws: &mut Workspace,
    lcp: &Lcp,
    settings: &LemkeSettings,
    cover: Cover,
    noise: Noise,
) -> LcpSolution {
    let n = lcp.n();
    let mut counters = Counters::default();
    if lcp.q.iter().all(|&v| v >= 0.0) {
        let mut sol = LcpSolution::from_z(lcp, Status::Solved, vec![0.0; n], counters);
        sol.basis = Some(0);
        return sol;
    }
    let qmax = lcp.q.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    cover.fill(&lcp.q, &mut ws.cover);
    // The first run that did not end on a solution, reported if no later
    // (perturbed) run finds one.
    let mut failed: Option<LcpSolution> = None;
    for eta in [0.0, 1e-10, 1e-7] {
        // Weights in [1, 2), distinct for every row (golden-ratio sequence).
        ws.q.clear();
        ws.q.extend(
            (0..n).map(|i| {
                lcp.q[i] + eta * qmax * (1.0 + (i as f64 * 0.618_033_988_749_895).fract())
            }),
        );
        let end = ws.pivot_path(lcp, noise, settings, &mut counters);
        let (status, checked) = match end {
            PathEnd::Cycled => continue,
            PathEnd::ArtificialAtZero => (Status::Solved, true),
            // A solution of a perturbed q counts once its basis re-solved
            // with the true q checks out.
            PathEnd::Done(status) => (status, eta > 0.0),
        };
        let sol = basis_solution(ws, lcp, status, counters, checked);
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

/// The solution of the workspace's final tableau: z from its basic values,
/// or the basis re-solved with the true q ([`polish`]) where that has the
/// smaller row residual ([`polish_wins`]). With `checked`, `Solved` stands
/// only if the error is at most [`ACCEPT_TOL`] (else `RayTermination`).
fn basis_solution(
    ws: &mut Workspace,
    lcp: &Lcp,
    status: Status,
    counters: Counters,
    checked: bool,
) -> LcpSolution {
    let n = lcp.n();
    let cols = 2 * n + 2;
    let rhs = 2 * n + 1;
    ws.z_tableau.clear();
    ws.z_tableau.resize(n, 0.0);
    ws.support.clear();
    for (i, &v) in ws.basic.iter().enumerate() {
        if (n..2 * n).contains(&v) {
            ws.z_tableau[v - n] = ws.t[i * cols + rhs].max(0.0);
            ws.support.push(v - n);
        }
    }
    if status != Status::Solved {
        return LcpSolution::from_z(lcp, status, ws.z_tableau.as_slice(), counters);
    }
    ws.support.sort_unstable();
    // w of each candidate z comes out of its row residual; the winner's
    // goes into the answer as is.
    let tableau = row_residual(lcp, &ws.z_tableau, &mut ws.w_tableau);
    let polished =
        polish(ws, lcp) && row_residual(lcp, &ws.z_polished, &mut ws.w_polished) <= tableau;
    let (z, w) = if polished {
        (&ws.z_polished, &ws.w_polished)
    } else {
        (&ws.z_tableau, &ws.w_tableau)
    };
    let mut sol = LcpSolution {
        status,
        residuals: Residuals::of(z, w, &lcp.q),
        z: z.as_slice().into(),
        w: w.as_slice().into(),
        counters,
        basis: None,
        all_bases: Vec::new(),
        solution_set: None,
    };
    if n <= 32 {
        sol.basis = Some(ws.support.iter().fold(0u32, |m, &i| m | 1 << i));
    }
    if checked && !(sol.residuals.error <= ACCEPT_TOL) {
        sol.status = Status::RayTermination;
        sol.basis = None;
    }
    sol
}

/// A ray reached with z0 at zero to rounding, or a solution of a perturbed
/// q, ends with `Solved` only when the basis re-solved with the true q has
/// at most this error; otherwise it is a ray.
const ACCEPT_TOL: f64 = 1e-9;

/// Whether the polished z (the basis re-solved from the data) is kept over
/// the tableau's: by the row-relative residual ([`row_residual`]), not the
/// error measure, which cannot see rounding in a small w_i beside a huge
/// z_i (z_i − max(0, z_i − w_i) rounds to 0): the tableau's z can be wrong in
/// its 8th digit with an error measure of 1e-127.
fn polish_wins(lcp: &Lcp, polished: &[f64], tableau: &[f64]) -> bool {
    let mut w = Vec::new();
    row_residual(lcp, polished, &mut w) <= row_residual(lcp, tableau, &mut w)
}

/// max_i of the violation of row i (|w_i| where z_i > 0, else max(0, −w_i))
/// relative to the row's scale |q_i| + Σ_j |M_ij z_j|: the accuracy of a
/// basic solution that every row sees at its own scale. w = M z + q is left
/// in `w`, each w_i = q_i + Σ_j M_ij z_j summed in [`Lcp::w`]'s order (from
/// −0, as `Iterator::sum` starts), in the same pass as the scale.
fn row_residual(lcp: &Lcp, z: &[f64], w: &mut Vec<f64>) -> f64 {
    let n = lcp.n();
    w.clear();
    let mut worst = 0.0f64;
    for (i, row) in lcp.m.chunks_exact(n).enumerate() {
        let (mut sum, mut size) = (-0.0f64, 0.0f64);
        for (a, b) in row.iter().zip(z) {
            let t = a * b;
            sum += t;
            size += t.abs();
        }
        let wi = lcp.q[i] + sum;
        w.push(wi);
        let v = if z[i] > 0.0 { wi.abs() } else { (-wi).max(0.0) };
        if v != 0.0 {
            worst = worst.max(v / (lcp.q[i].abs() + size));
        }
    }
    worst
}

/// Re-solves the basis `ws.support` from the original data into
/// `ws.z_polished`, M_SS z_S = −q_S: the tableau's values carry the rounding
/// of every pivot, this solve only its own. False when M_SS is singular.
/// Negative entries are clamped to 0; the caller keeps whichever z has the
/// smaller row residual.
fn polish(ws: &mut Workspace, lcp: &Lcp) -> bool {
    let k = ws.support.len();
    let support = &ws.support;
    ws.solve_a.clear();
    ws.solve_a.extend(
        support
            .iter()
            .flat_map(|&i| support.iter().map(move |&j| lcp.at(i, j))),
    );
    ws.solve_x.clear();
    ws.solve_x.extend(support.iter().map(|&i| -lcp.q[i]));
    if !solve_in_place(&mut ws.solve_a, &mut ws.solve_x, k, PIVOT_TOL) {
        return false;
    }
    ws.z_polished.clear();
    ws.z_polished.resize(lcp.n(), 0.0);
    for (&i, &v) in support.iter().zip(&ws.solve_x) {
        ws.z_polished[i] = v.max(0.0);
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    /// M = A Aᵀ / n + 0.05 I, A_ij and q_i ~ U[−1, 1].
    fn spd(n: usize, rng: &mut crate::generate::Rng) -> Lcp {
        let a: Vec<f64> = (0..n * n).map(|_| rng.range(-1.0, 1.0)).collect();
        let m = (0..n * n)
            .map(|k| {
                let (i, j) = (k / n, k % n);
                let dot: f64 = (0..n).map(|t| a[i * n + t] * a[j * n + t]).sum();
                dot / n as f64 + if i == j { 0.05 } else { 0.0 }
            })
            .collect();
        Lcp::new(m, (0..n).map(|_| rng.range(-1.0, 1.0)).collect()).unwrap()
    }

    #[test]
    fn a_reused_workspace_gives_the_answers_of_a_fresh_one() {
        // Sizes up and down through this thread's workspace, and one beyond
        // what the thread keeps (n = 70): every answer is the one a fresh
        // workspace gives, bit for bit, and the textbook basis is Lemke's.
        let mut rng = crate::generate::Rng::new(7);
        let settings = LemkeSettings::default();
        for n in [12, 3, 8, 1, 70, 12, 5, 2] {
            let lcp = spd(n, &mut rng);
            let reused = lemke(&lcp, &settings);
            let fresh = lemke_in(&mut Workspace::default(), &lcp, &settings);
            assert_eq!(reused, fresh, "n = {n}");
            assert_eq!(reused.status, Status::Solved, "n = {n}");
            let (mask, pivots) = lemke_textbook_basis(&lcp, &settings);
            if n <= 32 {
                assert_eq!(mask, reused.basis, "n = {n}");
            }
            assert_eq!(pivots, if n <= 32 { reused.counters.pivots } else { 0 });
            WORKSPACE.with(|ws| assert!(ws.borrow().t.capacity() <= KEPT_TABLEAU));
        }
    }

    #[test]
    fn seed_002_walkthrough() {
        // A 3×3 worked by hand through Lemke's pivots, q = (−3, 6, −1):
        // z = (0, 1, 3), w = (2, 0, 0).
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
#[path = "lemke_properties.rs"]
mod properties;
