//! The linear complementarity problem and what a solve reports about it.
//!
//! Find z with
//!
//! ```text
//! w = M z + q ≥ 0,   z ≥ 0,   zᵀw = 0
//! ```
//!
//! (Cottle, Pang & Stone, *The Linear Complementarity Problem*, 1992, §1.1).
//! [`Lcp`] holds (M, q); [`LcpSolution`] carries the
//! answer, its [`Status`], its [`Residuals`] and the work [`Counters`] of the
//! solver that produced it. The status says what the solve found; an
//! [`crate::Error`] says why a solve could not run at all.

use serde::{Deserialize, Serialize};

use crate::short_vec::ShortVec;

/// One LCP(q, M) of dimension n, M dense and row-major.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Lcp {
    /// Row-major n×n matrix: `m[i * n + j]` is M_ij.
    pub m: Vec<f64>,
    /// Length n.
    pub q: Vec<f64>,
}

impl Lcp {
    /// Builds an LCP from a row-major matrix and q, checking shapes and finiteness.
    ///
    /// # Errors
    /// Those of [`Self::validate`], naming the item "problem".
    pub fn new(m: Vec<f64>, q: Vec<f64>) -> Result<Self, crate::Error> {
        let lcp = Lcp { m, q };
        lcp.validate("problem")?;
        Ok(lcp)
    }

    /// Builds an LCP from rows, as the JSON batch format stores it.
    ///
    /// # Errors
    /// [`crate::Error::Invalid`] when a row or the number of rows is not
    /// `q.len()`, or an entry is not finite.
    pub fn from_rows(rows: &[Vec<f64>], q: Vec<f64>) -> Result<Self, crate::Error> {
        let n = q.len();
        for (i, row) in rows.iter().enumerate() {
            if row.len() != n {
                return Err(crate::Error::invalid(
                    "problem",
                    format!("M[{i}]"),
                    format!("row has {} entries, q has {n}", row.len()),
                ));
            }
        }
        if rows.len() != n {
            return Err(crate::Error::invalid(
                "problem",
                "M",
                format!("{} rows, q has {n} entries", rows.len()),
            ));
        }
        Lcp::new(rows.concat(), q)
    }

    /// Dimension n.
    #[inline]
    pub fn n(&self) -> usize {
        self.q.len()
    }

    /// M_ij.
    #[inline]
    pub fn at(&self, i: usize, j: usize) -> f64 {
        self.m[i * self.n() + j]
    }

    /// Checks that M is n×n and every entry of M and q is finite. `item` names
    /// the problem in the error message (rendered only when a check fails:
    /// pass `format_args!("problem {i}")`, not `&format!(..)`).
    ///
    /// # Errors
    /// [`crate::Error::Invalid`] naming `item` and the field (`q`, `M`,
    /// `M[i][j]`, `q[i]`).
    pub fn validate(&self, item: impl std::fmt::Display) -> Result<(), crate::Error> {
        validate_parts(&self.m, &self.q, item)
    }

    /// w = M z + q (inline up to [`crate::short_vec::SHORT_INLINE`] rows: nothing allocated).
    pub fn w(&self, z: &[f64]) -> ShortVec<f64> {
        let mut w = ShortVec::from_elem(0.0, self.n());
        self.w_into(z, &mut w);
        w
    }

    /// w = M z + q written into `w` (n entries), where the caller holds it.
    pub(crate) fn w_into(&self, z: &[f64], w: &mut [f64]) {
        let n = self.n();
        for (i, wi) in w[..n].iter_mut().enumerate() {
            let row = &self.m[i * n..(i + 1) * n];
            *wi = self.q[i] + row.iter().zip(z).map(|(a, b)| a * b).sum::<f64>();
        }
    }

    /// Residuals of a candidate z (w recomputed here).
    pub fn residuals(&self, z: &[f64]) -> Residuals {
        Residuals::of(z, &self.w(z), &self.q)
    }

    /// Is M symmetric to a relative tolerance of 1e-12 of its largest entry?
    pub fn is_symmetric(&self) -> bool {
        let n = self.n();
        // Exactly symmetric (assembled J M⁻¹ Jᵀ often is): no scale needed,
        // 0 is within any tolerance (a NaN or infinite pair goes on).
        if (0..n).all(|i| (0..i).all(|j| self.at(i, j) - self.at(j, i) == 0.0)) {
            return true;
        }
        let scale = self.m.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        (0..n).all(|i| (0..i).all(|j| (self.at(i, j) - self.at(j, i)).abs() <= 1e-12 * scale))
    }
}

/// Whether every entry is finite: no exponent field all ones (±inf, NaN),
/// tested on the bits with an OR that vectorises, without stopping early
/// (the common answer is yes, and the whole slice has to be read for it).
pub(crate) fn all_finite(v: &[f64]) -> bool {
    const EXPONENT: u64 = 0x7ff0_0000_0000_0000;
    v.iter().fold(0u64, |bad, x| {
        bad | u64::from(x.to_bits() & EXPONENT == EXPONENT)
    }) == 0
}

/// Siconos' `lcp_compute_error`: ‖z − max(0, z − w)‖₂ / ‖q‖₂, not divided when
/// ‖q‖₂ ≤ machine epsilon. Zero exactly when (z, w) is complementary and
/// both are non-negative; w must be M z + q for the measure to mean anything.
pub fn lcp_error(z: &[f64], w: &[f64], q: &[f64]) -> f64 {
    let num = norm2(z.iter().zip(w).map(|(&zi, &wi)| zi - (zi - wi).max(0.0)));
    let qn = norm2(q.iter().copied());
    if qn > f64::EPSILON {
        num / qn
    } else {
        num
    }
}

/// Euclidean norm, scaled by the largest magnitude so that it neither
/// overflows for entries near 1e200 nor underflows for entries near 1e-200.
pub fn norm2(v: impl Iterator<Item = f64> + Clone) -> f64 {
    let big = v.clone().fold(0.0f64, |m, x| m.max(x.abs()));
    if big == 0.0 || !big.is_finite() {
        return big;
    }
    big * v.map(|x| (x / big) * (x / big)).sum::<f64>().sqrt()
}

/// How far a (z, w) pair is from solving the LCP, as numbers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Residuals {
    /// Siconos error measure, see [`lcp_error`].
    pub error: f64,
    /// min_i z_i (negative means z is infeasible).
    pub min_z: f64,
    /// min_i w_i (negative means w is infeasible).
    pub min_w: f64,
    /// max_i |z_i w_i|: the worst complementarity violation.
    pub max_complementarity: f64,
}

impl Residuals {
    /// Residuals of z against w (w = M z + q) and q.
    pub fn of(z: &[f64], w: &[f64], q: &[f64]) -> Self {
        Residuals {
            error: lcp_error(z, w, q),
            min_z: z.iter().copied().fold(f64::INFINITY, f64::min),
            min_w: w.iter().copied().fold(f64::INFINITY, f64::min),
            max_complementarity: z
                .iter()
                .zip(w)
                .map(|(a, b)| (a * b).abs())
                .fold(0.0, f64::max),
        }
    }
}

/// What a solve found. Kept apart from [`crate::Error`], which says why a
/// solve could not run.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum Status {
    /// A solution was found (and, when all bases were visited, it is the only one).
    Solved,
    /// Exhaustive enumeration found more than one solution; the solution
    /// carries the chosen one and [`LcpSolution::solution_set`] describes them all.
    MultipleSolutions,
    /// Enumeration visited every complementary basis and none is feasible:
    /// the LCP has no solution reachable by a nonsingular basis.
    NoSolution,
    /// Lemke's algorithm ended on a secondary ray: it could not find a
    /// solution (for copositive-plus M this proves there is none).
    RayTermination,
    /// An iterative solver (PGS) or a pivot cap (Lemke) stopped before the
    /// tolerance was met; z is the last iterate.
    NotConverged,
    /// The problem could not be posed (a contact island or matrix failed a check).
    InvalidInput,
    /// The solver's answer is not usable: z, w or the error measure is not
    /// finite (z_i = 1e10 / 1e-300 overflows), or the error is above
    /// [`crate::Settings::tolerance`]. z is what the solver found.
    NumericalFailure,
}

impl Status {
    /// True when z is a solution the caller can use.
    pub fn is_solution(self) -> bool {
        matches!(self, Status::Solved | Status::MultipleSolutions)
    }

    /// Every status, in a fixed order (for tables and per-status counts).
    pub const ALL: [Status; 7] = [
        Status::Solved,
        Status::MultipleSolutions,
        Status::NoSolution,
        Status::RayTermination,
        Status::NotConverged,
        Status::InvalidInput,
        Status::NumericalFailure,
    ];

    /// The snake_case name used in JSON output.
    pub fn name(self) -> &'static str {
        match self {
            Status::Solved => "solved",
            Status::MultipleSolutions => "multiple_solutions",
            Status::NoSolution => "no_solution",
            Status::RayTermination => "ray_termination",
            Status::NotConverged => "not_converged",
            Status::InvalidInput => "invalid_input",
            Status::NumericalFailure => "numerical_failure",
        }
    }
}

impl std::fmt::Display for Status {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The whole solution set, as far as exhaustive enumeration can tell.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum SolutionSet {
    /// No feasible complementary basis.
    Empty,
    /// Finitely many isolated solutions (1 means unique).
    Isolated {
        /// How many distinct solutions.
        count: usize,
    },
    /// A segment (or polytope) of solutions, bounded.
    BoundedContinuum,
    /// A ray of solutions: z + t d solves the LCP for every t ≥ 0.
    UnboundedContinuum,
}

/// Work a solver did, for comparing solvers and for benchmarks.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[non_exhaustive]
pub struct Counters {
    /// Complementary bases whose principal system was formed (enumeration).
    pub bases_visited: u64,
    /// Bases skipped because their principal submatrix is singular (enumeration).
    pub singular_bases: u64,
    /// Pivots (Lemke).
    pub pivots: u64,
    /// Sweeps (PGS).
    pub iterations: u64,
}

/// One valid complementary basis and the solution it gives.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BasisSolution {
    /// Bit i set: z_i is basic (contact i carries impulse), w_i = 0.
    pub basis: u32,
    /// The basic solution.
    pub z: Vec<f64>,
    /// w = M z + q for it.
    pub w: Vec<f64>,
}

/// The result of one LCP solve.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub struct LcpSolution {
    /// What the solve found.
    pub status: Status,
    /// The impulses (or the last iterate when the status is not a solution;
    /// zeros when nothing was found). Inline up to [`crate::short_vec::SHORT_INLINE`]
    /// entries: a batch of small problems allocates nothing per answer.
    pub z: ShortVec<f64>,
    /// w = M z + q for the z above.
    pub w: ShortVec<f64>,
    /// The error measure and the sign and complementarity residuals of (z, w).
    pub residuals: Residuals,
    /// The work the solver did.
    pub counters: Counters,
    /// The complementary basis that gave z (bit i: z_i basic), when the
    /// solver works with bases and found one.
    pub basis: Option<u32>,
    /// Every valid basis, when enumeration was asked for all solutions.
    #[serde(skip_serializing_if = "Vec::is_empty", default)]
    pub all_bases: Vec<BasisSolution>,
    /// Distinct solutions among `all_bases` (same z to a relative 1e-8).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub solution_set: Option<SolutionSet>,
}

impl LcpSolution {
    /// A result with the given status and z, w and residuals computed from `lcp`.
    pub fn from_z(
        lcp: &Lcp,
        status: Status,
        z: impl Into<ShortVec<f64>>,
        counters: Counters,
    ) -> Self {
        let z = z.into();
        let w = lcp.w(&z);
        let residuals = Residuals::of(&z, &w, &lcp.q);
        LcpSolution {
            status,
            z,
            w,
            residuals,
            counters,
            basis: None,
            all_bases: Vec::new(),
            solution_set: None,
        }
    }

    /// The door's final check of an answer: z, w and the error measure
    /// finite, the error at most `tolerance` (its status aside).
    pub fn passes_check(&self, tolerance: f64) -> bool {
        self.z.iter().chain(&self.w).all(|v| v.is_finite())
            && self.residuals.error.is_finite()
            && self.residuals.error <= tolerance
    }

    /// A result for a problem of `n` rows that failed its checks: status
    /// `InvalidInput`, z = w = 0.
    pub(crate) fn invalid(n: usize) -> Self {
        LcpSolution {
            status: Status::InvalidInput,
            z: ShortVec::from_elem(0.0, n),
            w: ShortVec::from_elem(0.0, n),
            residuals: Residuals::default(),
            counters: Counters::default(),
            basis: None,
            all_bases: Vec::new(),
            solution_set: None,
        }
    }

    /// Number of distinct solutions when known (None for a continuum or when
    /// not all bases were visited).
    pub fn solution_count(&self) -> Option<usize> {
        match self.solution_set {
            Some(SolutionSet::Empty) => Some(0),
            Some(SolutionSet::Isolated { count }) => Some(count),
            _ => None,
        }
    }
}

/// [`Lcp::validate`] of a problem held as slices (M row-major n×n, q).
pub(crate) fn validate_parts(
    m: &[f64],
    q: &[f64],
    item: impl std::fmt::Display,
) -> Result<(), crate::Error> {
    let n = q.len();
    if n == 0 {
        return Err(crate::Error::invalid(item, "q", "empty problem (n = 0)"));
    }
    if m.len() != n * n {
        return Err(crate::Error::invalid(
            item,
            "M",
            format!("has {} entries, expected n² = {}", m.len(), n * n),
        ));
    }
    if all_finite(q) && all_finite(m) {
        return Ok(());
    }
    if let Some(i) = q.iter().position(|v| !v.is_finite()) {
        return Err(crate::Error::invalid(
            item,
            format!("q[{i}]"),
            "not a finite number",
        ));
    }
    if let Some(k) = m.iter().position(|v| !v.is_finite()) {
        return Err(crate::Error::invalid(
            item,
            format!("M[{}][{}]", k / n, k % n),
            "not a finite number",
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn error_measure_is_zero_on_a_solution_and_unscaled_for_tiny_q() {
        // M = [[2, 1], [1, 2]], q = (−5, −6): z = (4/3, 7/3), w = 0.
        let lcp = Lcp::new(vec![2.0, 1.0, 1.0, 2.0], vec![-5.0, -6.0]).unwrap();
        let r = lcp.residuals(&[4.0 / 3.0, 7.0 / 3.0]);
        assert!(r.error < 1e-15, "{r:?}");
        // No overflow for huge entries.
        assert!((lcp_error(&[1e200], &[1e200], &[1.0]) - 1e200).abs() < 1e186);
        // q = 0: the measure is not divided.
        assert_eq!(lcp_error(&[1.0], &[1.0], &[0.0]), 1.0);
        // z = 1, w = -1: z - max(0, 2) = -1, |q| = 1.
        assert_eq!(lcp_error(&[1.0], &[-1.0], &[-1.0]), 1.0);
    }

    #[test]
    fn shapes_and_non_finite_entries_are_named() {
        let e = Lcp::new(vec![1.0, 2.0, 3.0], vec![1.0, 2.0]).unwrap_err();
        assert!(e.to_string().contains("M"), "{e}");
        let e = Lcp::new(vec![1.0, f64::NAN, 0.0, 1.0], vec![1.0, 2.0]).unwrap_err();
        assert!(e.to_string().contains("M[0][1]"), "{e}");
        let e = Lcp::from_rows(&[vec![1.0], vec![1.0, 2.0]], vec![1.0, 2.0]).unwrap_err();
        assert!(e.to_string().contains("M[0]"), "{e}");
    }

    /// The error texts, byte for byte, with the name as a `&str` or as
    /// `format_args!` (rendered only when a check fails).
    #[test]
    fn error_texts_are_exact() {
        let i = 4;
        let cases = [
            (
                Lcp {
                    m: vec![1.0, 0.0, 0.0, 1.0],
                    q: vec![1.0, f64::NAN],
                },
                "problem 4: field `q[1]`: not a finite number",
            ),
            (
                Lcp {
                    m: vec![1.0; 3],
                    q: vec![1.0, 2.0],
                },
                "problem 4: field `M`: has 3 entries, expected n² = 4",
            ),
        ];
        for (lcp, want) in cases {
            assert_eq!(lcp.validate("problem 4").unwrap_err().to_string(), want);
            let e = lcp.validate(format_args!("problem {i}")).unwrap_err();
            assert_eq!(e.to_string(), want);
        }
        let mut p = crate::friction::FrictionProblem {
            w: vec![0.0; 9],
            q: vec![0.0; 3],
            mu: vec![-0.5],
        };
        let want = "problem 4: field `mu[0]`: -0.5 is not a finite number ≥ 0";
        assert_eq!(p.validate("problem 4").unwrap_err().to_string(), want);
        let e = p.validate(format_args!("problem {i}")).unwrap_err();
        assert_eq!(e.to_string(), want);
        p.mu[0] = 0.5;
        p.w[5] = f64::INFINITY;
        let e = p.validate(format_args!("problem {i}")).unwrap_err();
        assert_eq!(
            e.to_string(),
            "problem 4: field `W[1][2]`: not a finite number"
        );
    }
}
