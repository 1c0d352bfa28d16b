//! The pivoting path of Lemke's algorithm on a contiguous dense tableau held
//! in a [`Workspace`] that is reused from problem to problem: once it has
//! grown to the largest n seen, a solve allocates nothing.
//!
//! The tableau is row-major, n rows of `cols = 2n + 2` entries:
//! B⁻¹[I, −M, −d | q] for the current basis B (d the covering vector), the
//! columns being w_0…w_{n−1}, z_0…z_{n−1}, z0, rhs. The first n columns are
//! B⁻¹ itself, which the lexicographic ratio test reads.

use std::collections::HashSet;

use super::lemke::{LemkeSettings, Noise};
use crate::lcp::{Counters, Lcp, Status};

/// How one run of the pivoting path ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum PathEnd {
    /// z0 left (Solved), a secondary ray, or the pivot cap.
    Done(Status),
    /// A secondary ray with z0 at zero to rounding: the basis is a solution
    /// if its re-solve checks out.
    ArtificialAtZero,
    /// A (basis, entering variable) pair came back: the path cycles. Exact
    /// lexicographic pivoting cannot cycle; floating point can, where
    /// rounding decides a tie (a right-hand side of 0 against 1e-17).
    Cycled,
}

/// Everything one Lemke solve writes, kept between solves (one per thread:
/// see [`super::lemke::lemke`]).
#[derive(Debug, Default)]
pub struct Workspace {
    /// The tableau, n rows × (2n + 2) columns, row-major.
    pub(crate) t: Vec<f64>,
    /// basic[i]: the variable basic in row i (w_i = i, z_i = n + i, z0 = 2n).
    pub(crate) basic: Vec<usize>,
    /// The right-hand side the path runs on (q, perturbed on retries).
    pub(crate) q: Vec<f64>,
    /// The covering vector d.
    pub(crate) cover: Vec<f64>,
    /// Rows whose entry in the entering column counts as a pivot.
    candidates: Vec<usize>,
    /// Rows still tied in the lexicographic ratio test.
    tied: Vec<usize>,
    /// The entering column as the original data hold it (Noise::Data).
    column: Vec<f64>,
    /// (basis as a bit set over the 2n + 1 variables, entering) pairs seen
    /// after [`watch_from`] pivots, n ≤ 63.
    seen: HashSet<(u128, usize)>,
    /// The same for n > 63: the sorted basis with the entering variable last.
    seen_large: HashSet<Vec<usize>>,
    /// Scratch of the final basis' re-solve: M_SS, then its solution.
    pub(crate) solve_a: Vec<f64>,
    /// Right-hand side −q_S, then z_S.
    pub(crate) solve_x: Vec<f64>,
    /// The support S of the final basis (z_i basic), increasing.
    pub(crate) support: Vec<usize>,
    /// z read from the final tableau.
    pub(crate) z_tableau: Vec<f64>,
    /// z of the basis re-solved from the data.
    pub(crate) z_polished: Vec<f64>,
    /// w = M z + q for `z_tableau`.
    pub(crate) w_tableau: Vec<f64>,
    /// w = M z + q for `z_polished`.
    pub(crate) w_polished: Vec<f64>,
}

/// Variable indices in the tableau: w_i = i, z_i = n + i, z0 = 2n.
pub(crate) fn complement(var: usize, n: usize) -> usize {
    if var < n {
        var + n
    } else {
        var - n
    }
}

/// Pivots after which the path starts recording (basis, entering) pairs to
/// detect a cycle. A path without rounding trouble ends in at most a few
/// times n pivots; a cycle repeats forever, so recording late only finds it
/// one turn later, and spares every ordinary solve the bookkeeping.
fn watch_from(n: usize) -> u64 {
    4 * n as u64 + 8
}

impl Workspace {
    /// Fills the tableau [I, −M, −d | q] for `lcp` with the right-hand side
    /// `self.q` and the covering vector `self.cover` (both set by the caller),
    /// and the initial basis w.
    fn load(&mut self, lcp: &Lcp) {
        let n = lcp.n();
        let cols = 2 * n + 2;
        self.t.clear();
        self.t.resize(n * cols, 0.0);
        for (i, row) in self.t.chunks_exact_mut(cols).enumerate() {
            row[i] = 1.0;
            for (x, m) in row[n..2 * n].iter_mut().zip(&lcp.m[i * n..(i + 1) * n]) {
                *x = -m;
            }
            row[2 * n] = -self.cover[i];
            row[2 * n + 1] = self.q[i];
        }
        self.basic.clear();
        self.basic.extend(0..n);
        self.seen.clear();
        self.seen_large.clear();
    }

    /// One run of the complementary pivoting path on (M, `self.q`) with the
    /// covering vector `self.cover`; the final tableau and basis stay in the
    /// workspace.
    pub(crate) fn pivot_path(
        &mut self,
        lcp: &Lcp,
        noise: Noise,
        settings: &LemkeSettings,
        counters: &mut Counters,
    ) -> PathEnd {
        self.load(lcp);
        let n = lcp.n();
        let cols = 2 * n + 2;
        let rhs = 2 * n + 1;
        let z0 = 2 * n;
        let q_scale = self.q.iter().fold(0.0f64, |m, v| m.max(v.abs()));

        // First pivot: z0 enters (see first_row).
        let first = self.first_row(n);
        self.pivot(n, first, z0);
        counters.pivots += 1;
        let mut entering = complement(self.basic[first], n);
        self.basic[first] = z0;
        let watch = watch_from(n);

        loop {
            if counters.pivots >= settings.max_pivots {
                return PathEnd::Done(Status::NotConverged);
            }
            if counters.pivots >= watch && !self.record(n, entering) {
                return PathEnd::Cycled;
            }
            let colmax = self.pivot_candidates(lcp, entering, noise, settings);
            // x_B = rhs − T[:, e] t for the entering variable at value t ≥ 0:
            // rows with a positive entry decrease; the first to reach zero leaves.
            if self.candidates.is_empty() || colmax == 0.0 {
                // z0 at zero to rounding: the current basis is already a
                // solution (a degenerate step let another variable leave in
                // z0's place, by 1e-17); the caller re-solves and checks it.
                let z0_row = self.basic.iter().position(|&v| v == z0);
                let at_zero =
                    z0_row.is_some_and(|r| self.t[r * cols + rhs] <= settings.pivot_tol * q_scale);
                return if at_zero {
                    PathEnd::ArtificialAtZero
                } else {
                    PathEnd::Done(Status::RayTermination)
                };
            }
            let best = self.leaving_row(n, entering);
            self.pivot(n, best, entering);
            counters.pivots += 1;
            let leaving = self.basic[best];
            self.basic[best] = entering;
            if leaving == z0 {
                return PathEnd::Done(Status::Solved);
            }
            entering = complement(leaving, n);
        }
    }

    /// Records (basis, entering); false when the pair was seen before.
    fn record(&mut self, n: usize, entering: usize) -> bool {
        if 2 * n < 128 {
            let set = self.basic.iter().fold(0u128, |s, &v| s | 1u128 << v);
            self.seen.insert((set, entering))
        } else {
            let mut key = self.basic.clone();
            key.sort_unstable();
            key.push(entering);
            self.seen_large.insert(key)
        }
    }

    /// Fills `self.candidates` with the rows whose entry in the entering
    /// column counts as a pivot (see [`Noise`]); returns the column's largest
    /// magnitude.
    fn pivot_candidates(
        &mut self,
        lcp: &Lcp,
        entering: usize,
        noise: Noise,
        settings: &LemkeSettings,
    ) -> f64 {
        let n = lcp.n();
        let cols = 2 * n + 2;
        let t = &self.t;
        // Plain comparisons (a NaN entry is skipped, as f64::max would).
        let mut colmax = 0.0f64;
        for i in 0..n {
            let v = t[i * cols + entering].abs();
            if v > colmax {
                colmax = v;
            }
        }
        self.candidates.clear();
        match noise {
            Noise::Column => {
                let floor = settings.pivot_tol * colmax;
                self.candidates
                    .extend((0..n).filter(|&i| t[i * cols + entering] > floor));
            }
            Noise::Data => {
                // ε·Σ_j |B⁻¹_ij|·|a_j|, a the entering column of [I, −M, −d].
                self.column.clear();
                self.column.extend((0..n).map(|i| match entering {
                    v if v < n => f64::from(u8::from(i == v)),
                    v if v < 2 * n => lcp.at(i, v - n).abs(),
                    _ => self.cover[i].abs(),
                }));
                for i in 0..n {
                    let row = &t[i * cols..i * cols + n];
                    let sum: f64 = row.iter().zip(&self.column).map(|(b, a)| b.abs() * a).sum();
                    if t[i * cols + entering] > settings.pivot_tol * sum {
                        self.candidates.push(i);
                    }
                }
            }
        }
        colmax
    }

    /// The lexicographic minimum-ratio test: among the candidates (rows
    /// whose entry d_i in the entering column is positive), the row
    /// minimising (rhs_i, B⁻¹_i0, B⁻¹_i1, …) / d_i lexicographically. B⁻¹ is
    /// the tableau's w-columns. Rows of B⁻¹ are linearly independent, so
    /// exactly one row survives, which is what keeps Lemke from cycling on
    /// degenerate problems.
    ///
    /// Comparisons are exact: a tolerance on ties (tried: 1e-14 to 1e-9
    /// relative to the column) merges rows whose keys truly differ, breaks
    /// the strict lexicographic order and made Lemke cycle on Siconos'
    /// lcp_tobenna; exact comparison solves it in 179 pivots. rhs values that
    /// rounding made slightly negative count as 0. When z0 is among the rows
    /// tied on the ratio itself, z0 leaves: that ends the algorithm with a
    /// solution.
    fn leaving_row(&mut self, n: usize, entering: usize) -> usize {
        let cols = 2 * n + 2;
        let rhs = cols - 1;
        let z0 = 2 * n;
        let t = &self.t;
        let key = |i: usize, col: usize| {
            let v = t[i * cols + col];
            let v = if col == rhs { v.max(0.0) } else { v };
            v / t[i * cols + entering]
        };
        // The ratio itself, in one pass: most tests end here with one row.
        let mut min = f64::INFINITY;
        let mut first = usize::MAX;
        let mut ties = 0;
        for &i in &self.candidates {
            let k = key(i, rhs);
            if k < min {
                (min, first, ties) = (k, i, 1);
            } else if k == min {
                ties += 1;
            }
        }
        if first == usize::MAX {
            // Every ratio NaN (entries overflowed): any candidate will do;
            // the caller's check rejects what comes of it.
            return self.candidates[0];
        }
        if ties <= 1 {
            return first;
        }
        self.tied.clear();
        let tied = &mut self.tied;
        tied.extend(self.candidates.iter().filter(|&&i| key(i, rhs) <= min));
        if let Some(&z) = tied.iter().find(|&&i| self.basic[i] == z0) {
            return z;
        }
        for col in 0..n {
            let min = tied
                .iter()
                .map(|&i| key(i, col))
                .fold(f64::INFINITY, f64::min);
            tied.retain(|&i| key(i, col) <= min);
            if tied.len() <= 1 {
                break;
            }
        }
        tied.first().copied().unwrap_or(first)
    }

    /// The first leaving row: z0 enters at the value that makes the most
    /// negative q_i / d_i zero (d the covering vector). Lexicographically
    /// that is the minimum of (q_i, row i of I) / d_i: among exact ties the
    /// largest index, which keeps every row lexicographically positive after
    /// the pivot.
    fn first_row(&self, n: usize) -> usize {
        let ratio = |i: usize| self.q[i] / self.cover[i];
        let min = (0..n).map(ratio).fold(f64::INFINITY, f64::min);
        (0..n).rev().find(|&i| ratio(i) == min).expect("n ≥ 1")
    }

    /// Gauss–Jordan pivot on (row r, column c): row r divided by its pivot,
    /// then every other row minus its entry in column c times row r.
    #[inline(always)]
    fn pivot(&mut self, n: usize, r: usize, c: usize) {
        let cols = 2 * n + 2;
        let (head, rest) = self.t[..n * cols].split_at_mut(r * cols);
        let (prow, tail) = rest.split_at_mut(cols);
        let inv = 1.0 / prow[c];
        prow.iter_mut().for_each(|x| *x *= inv);
        prow[c] = 1.0;
        let prow = &*prow;
        for row in head
            .chunks_exact_mut(cols)
            .chain(tail.chunks_exact_mut(cols))
        {
            let f = row[c];
            if f != 0.0 {
                for (x, p) in row.iter_mut().zip(prow) {
                    *x -= f * p;
                }
                row[c] = 0.0;
            }
        }
    }
}
