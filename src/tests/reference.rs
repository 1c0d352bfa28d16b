//! The tests' reference: one LCP solved by one algorithm ([`Solver`],
//! [`SolverSettings`], [`solve`]), one scene island by island
//! ([`solve_scene`]), the library's build ([`crate::build::Built`]) and
//! solvers called directly; the batched and GPU solves are compared with
//! it. The library's door is [`crate::Solver`].

use crate::build::Built;
use crate::cpu::assembly::ContactRow;
use crate::cpu::enumeration::MAX_ENUMERATION_N;
use crate::cpu::enumeration::{enumerate, EnumerationSettings};
use crate::cpu::impulses::{apply_impulses, BodyVelocity};
use crate::cpu::lemke::{lemke, LemkeSettings};
use crate::cpu::pgs::{pgs, PgsSettings};
use crate::islands::Island;
use crate::lcp::{Lcp, LcpSolution};
use crate::scene::Scene;
use crate::Error;

/// One island's problem and result.
#[derive(Clone, Debug)]
pub struct IslandResult {
    /// The scene's contact indices, in the order of the LCP's rows.
    pub contacts: Vec<usize>,
    /// The solver that actually ran (enumeration hands islands beyond its
    /// size limit to Lemke).
    pub solver: Solver,
    pub lcp: Lcp,
    pub solution: LcpSolution,
}

/// A scene after the impact.
#[derive(Clone, Debug)]
pub struct SceneSolution {
    /// Normal impulse of every contact, in the scene's order.
    pub impulses: Vec<f64>,
    /// Velocities of every body after the impulses.
    pub bodies: Vec<BodyVelocity>,
    pub islands: Vec<IslandResult>,
    /// Assembly's per-contact rows (K, Jacobian, response, v_rel, q).
    pub rows: Vec<ContactRow>,
}

/// Checks a scene and builds it: islands, contact rows and island LCPs.
pub fn build(scene: &Scene, item: &str) -> Result<(Vec<Island>, Vec<ContactRow>, Vec<Lcp>), Error> {
    scene.validate(item)?;
    let b = Built::new(scene);
    Ok((b.islands, b.rows, b.lcps))
}

/// Solves one scene on the CPU: every island with the chosen solver
/// (enumeration falls back to Lemke above n = 20), then the impulses.
/// `item` names the scene in errors (e.g. "scene 0").
pub fn solve_scene(
    scene: &Scene,
    settings: &SolverSettings,
    item: &str,
) -> Result<SceneSolution, Error> {
    let (islands, rows, lcps) = build(scene, item)?;
    let mut impulses = vec![0.0; scene.contacts.len()];
    let mut results = Vec::with_capacity(islands.len());
    for (island, lcp) in islands.into_iter().zip(lcps) {
        let mut s = *settings;
        if s.solver == Solver::Enum && lcp.n() > MAX_ENUMERATION_N {
            s.solver = Solver::Lemke;
        }
        let solution = solve(&lcp, &s)?;
        for (&c, &zi) in island.contacts.iter().zip(&solution.z) {
            impulses[c] = zi;
        }
        results.push(IslandResult {
            contacts: island.contacts,
            solver: s.solver,
            lcp,
            solution,
        });
    }
    let bodies = apply_impulses(scene, &rows, &impulses);
    Ok(SceneSolution {
        impulses,
        bodies,
        islands: results,
        rows,
    })
}

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
