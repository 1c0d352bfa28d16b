//! The CPU path for whole scenes, in named phases: build (islands and
//! assembly), solve (one LCP per island), write back (impulses applied to the
//! bodies).

// `solve_scene` (one scene, one island at a time) is the reference the
// tests compare batched and GPU solves with.
#![cfg_attr(not(test), allow(dead_code))]

use crate::cpu::assembly::{assemble_contacts, assemble_island, ContactRow};
use crate::cpu::enumeration::MAX_ENUMERATION_N;
use crate::cpu::impulses::{apply_impulses, BodyVelocity};
use crate::islands::{find_islands, Island};
use crate::lcp::{Lcp, LcpSolution};
use crate::scene::Scene;
use crate::solvers::{solve, Solver, SolverSettings};
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

/// Build phase: validated scene → islands, contact rows and island LCPs.
pub fn build(scene: &Scene, item: &str) -> Result<(Vec<Island>, Vec<ContactRow>, Vec<Lcp>), Error> {
    scene.validate(item)?;
    let islands = find_islands(scene);
    let rows = assemble_contacts(scene);
    let lcps = islands
        .iter()
        .map(|isl| assemble_island(scene, &rows, isl))
        .collect();
    Ok((islands, rows, lcps))
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
