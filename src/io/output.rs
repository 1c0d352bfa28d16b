//! The JSON output of `lcpbatch solve`: per LCP its status, z, w, error and
//! counters; per scene the contacts' impulses, the bodies' velocities and
//! the islands. Field names are fixed (see the README).

use serde::{Deserialize, Serialize};

use super::friction;
use crate::cpu::impulses::BodyVelocity;
use crate::lcp::{LcpSolution, SolutionSet};

/// One LCP result in the output file.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct LcpOutput {
    /// The status's snake_case name.
    pub status: String,
    /// The impulses.
    pub z: Vec<f64>,
    /// w = M z + q.
    pub w: Vec<f64>,
    /// The Siconos error measure ‖z − max(0, z − w)‖ / ‖q‖.
    pub error: f64,
    /// The smallest z_i.
    pub min_z: f64,
    /// The smallest w_i.
    pub min_w: f64,
    /// max |z_i w_i|.
    pub max_complementarity: f64,
    /// Indices i with z_i basic, when the solver works with bases.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub basis: Option<Vec<usize>>,
    /// The method whose answer this is: `enum`, `lemke` or `pgs`.
    pub solver: String,
    /// Bases whose principal system was formed (enumeration).
    pub bases_visited: u64,
    /// Pivots (Lemke).
    pub pivots: u64,
    /// Sweeps (PGS).
    pub iterations: u64,
    /// With --all-solutions: the whole solution set and every distinct solution.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub solution_set: Option<SolutionSet>,
    #[serde(skip_serializing_if = "Vec::is_empty", default)]
    /// With --all-solutions: every distinct solution.
    pub solutions: Vec<Vec<f64>>,
}

/// Basis mask as a list of indices.
pub fn basis_indices(mask: u32, n: usize) -> Vec<usize> {
    (0..n.min(32)).filter(|&i| mask >> i & 1 == 1).collect()
}

impl LcpOutput {
    /// One problem's output from its solution and the method's name.
    pub fn new(solver: &str, sol: &LcpSolution) -> Self {
        let n = sol.z.len();
        LcpOutput {
            status: sol.status.name().to_string(),
            z: sol.z.to_vec(),
            w: sol.w.to_vec(),
            error: sol.residuals.error,
            min_z: sol.residuals.min_z,
            min_w: sol.residuals.min_w,
            max_complementarity: sol.residuals.max_complementarity,
            basis: sol.basis.map(|m| basis_indices(m, n)),
            solver: solver.to_string(),
            bases_visited: sol.counters.bases_visited,
            pivots: sol.counters.pivots,
            iterations: sol.counters.iterations,
            solution_set: sol.solution_set.clone(),
            solutions: crate::cpu::enumeration::distinct_solutions(&sol.all_bases)
                .into_iter()
                .map(|b| b.z.clone())
                .collect(),
        }
    }
}

/// `{"problems": [...]}`.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct LcpBatchOutput {
    /// One entry per problem, in the input's order.
    pub problems: Vec<LcpOutput>,
}

/// One contact's result.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ContactOutput {
    /// The normal impulse z ≥ 0.
    pub impulse: f64,
    /// Scenes with friction only: the impulse vector, its normal and
    /// tangential parts, the frame and the local velocity after.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub friction: Option<friction::ContactFrictionOutput>,
}

/// One island's result.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct IslandOutput {
    /// The scene's contact indices, in the order of the island's LCP rows.
    pub contacts: Vec<usize>,
    /// The status's snake_case name.
    pub status: String,
    /// The Siconos error measure of the island's LCP.
    pub error: f64,
    /// The method whose answer this is.
    pub solver: String,
}

/// One scene's result.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct SceneOutput {
    /// One entry per contact, in the scene's order.
    pub contacts: Vec<ContactOutput>,
    /// One entry per body, in the scene's order: velocities after the impulses.
    pub bodies: Vec<BodyVelocity>,
    /// One entry per island.
    pub islands: Vec<IslandOutput>,
    /// Scenes with friction only: one entry per island (then `islands` is empty).
    #[serde(skip_serializing_if = "Vec::is_empty", default)]
    pub friction_islands: Vec<friction::FrictionOutput>,
}

/// `{"scenes": [...]}`, also for a single scene.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ScenesOutput {
    /// One entry per scene, in the input's order.
    pub scenes: Vec<SceneOutput>,
}

impl LcpBatchOutput {
    /// The output of an LCP batch's report.
    pub fn of(report: &crate::Report) -> Self {
        LcpBatchOutput {
            problems: report
                .islands
                .iter()
                .map(|isl| LcpOutput::new(isl.method.name(), &isl.solution))
                .collect(),
        }
    }
}

impl ScenesOutput {
    /// The output of a scene batch's report.
    pub fn of(report: &crate::Report) -> Self {
        ScenesOutput {
            scenes: report
                .scenes
                .iter()
                .map(|sc| SceneOutput {
                    contacts: sc
                        .impulses
                        .iter()
                        .enumerate()
                        .map(|(c, &impulse)| ContactOutput {
                            impulse,
                            friction: sc.friction.as_ref().map(|f| f.contacts[c]),
                        })
                        .collect(),
                    bodies: sc.bodies.clone(),
                    islands: report.islands[sc.islands.clone()]
                        .iter()
                        .map(|r| IslandOutput {
                            contacts: r.contacts.to_vec(),
                            status: r.solution.status.name().to_string(),
                            error: r.solution.residuals.error,
                            solver: r.method.name().to_string(),
                        })
                        .collect(),
                    friction_islands: sc
                        .friction
                        .as_ref()
                        .map(|f| {
                            report.friction[f.islands.clone()]
                                .iter()
                                .map(friction::FrictionOutput::of)
                                .collect()
                        })
                        .unwrap_or_default(),
                })
                .collect(),
        }
    }
}
