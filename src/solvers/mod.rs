//! The three LCP solvers behind one entry point. Exhaustive enumeration lives
//! in [`crate::cpu::enumeration`] because it is also a GPU stage's CPU twin;
//! Lemke and PGS run on the CPU only.

pub mod lemke;
mod lemke_tableau;
pub mod pgs;

use crate::cpu::enumeration::{enumerate, EnumerationSettings};
use crate::lcp::{Lcp, LcpSolution};
use lemke::{lemke, LemkeSettings};
use pgs::{pgs, PgsSettings};

/// Which algorithm solves an LCP.
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum Solver {
    /// Exhaustive enumeration of complementary bases (exact, n ≤ 20).
    #[default]
    Enum,
    /// Lemke's complementary pivoting (exact, any n).
    Lemke,
    /// Projected Gauss–Seidel (iterative, approximate).
    Pgs,
}

impl Solver {
    /// The name used in the tests' messages.
    #[cfg(test)]
    pub fn name(self) -> &'static str {
        match self {
            Solver::Enum => "enum",
            Solver::Lemke => "lemke",
            Solver::Pgs => "pgs",
        }
    }
}

/// Settings of every solver; only the chosen solver's part is read.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolverSettings {
    pub solver: Solver,
    pub enumeration: EnumerationSettings,
    pub lemke: LemkeSettings,
    pub pgs: PgsSettings,
    /// Enumeration only: settle what [`crate::prediction`] can before
    /// enumerating (default true), as the GPU path does, so that both report
    /// the same result and counters. Not used with `all_solutions`.
    pub predict: bool,
}

impl Default for SolverSettings {
    fn default() -> Self {
        SolverSettings {
            solver: Solver::default(),
            enumeration: EnumerationSettings::default(),
            lemke: LemkeSettings::default(),
            pgs: PgsSettings::default(),
            predict: true,
        }
    }
}

impl SolverSettings {
    /// Default settings for `solver` (the tests' shorthand).
    #[cfg(test)]
    pub fn with_solver(solver: Solver) -> Self {
        SolverSettings {
            solver,
            ..Default::default()
        }
    }
}

/// Solves one LCP with the chosen solver. Errors only when the solver cannot
/// take the problem at all (enumeration beyond its size limit, settings out
/// of range); everything else is a status on the solution.
pub fn solve(lcp: &Lcp, settings: &SolverSettings) -> Result<LcpSolution, crate::Error> {
    match settings.solver {
        Solver::Enum if settings.predict && !settings.enumeration.all_solutions => {
            settings.enumeration.validate()?;
            match crate::prediction::predict(lcp, None, &settings.enumeration) {
                Some((_, solution)) => Ok(solution),
                None => enumerate(lcp, &settings.enumeration),
            }
        }
        Solver::Enum => enumerate(lcp, &settings.enumeration),
        Solver::Lemke => Ok(lemke(lcp, &settings.lemke)),
        Solver::Pgs => Ok(pgs(lcp, &settings.pgs)),
    }
}
