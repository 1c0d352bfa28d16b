//! The build phase, once per scene per call: a checked scene → its islands
//! (contacts coupled through shared dynamic bodies, [`find_islands`]), its
//! contact rows, and each island's problem (an LCP without friction, W, q
//! and μ with it). Every path takes what was built here: the CPU and GPU
//! solves, the friction path, the world step, the warm start (islands'
//! contact ids) and the cost model (islands' sizes). Nothing here checks a
//! scene: `Solver::solve_scenes` checks every scene once, before the build.

use crate::cpu::assembly::{assemble_contacts, assemble_island, ContactRow};
use crate::cpu::batch::parallel_map;
use crate::friction::assembly::{
    assemble_friction_contacts, assemble_friction_island, FrictionContactRows,
};
use crate::friction::FrictionProblem;
use crate::islands::{find_islands, Island};
use crate::lcp::Lcp;
use crate::scene::Scene;

/// A scene built for the LCP path: islands, f64 contact rows, island LCPs
/// (one per island, in the islands' order).
#[derive(Clone, Debug)]
pub(crate) struct Built {
    pub(crate) islands: Vec<Island>,
    pub(crate) rows: Vec<ContactRow>,
    pub(crate) lcps: Vec<Lcp>,
}

impl Built {
    /// Builds a checked scene.
    pub(crate) fn new(scene: &Scene) -> Self {
        let islands = find_islands(scene);
        let rows = assemble_contacts(scene);
        let lcps = islands
            .iter()
            .map(|isl| assemble_island(scene, &rows, isl))
            .collect();
        Built {
            islands,
            rows,
            lcps,
        }
    }

    /// Every checked scene, over `threads` cores.
    pub(crate) fn all(scenes: &[&Scene], threads: usize) -> Vec<Built> {
        parallel_map(scenes.len(), threads, |i| Built::new(scenes[i]))
    }
}

/// A scene built for the friction path: islands and f64 contact rows
/// (normal and two tangent rows per contact); each island's problem is
/// assembled from them, all at once ([`FrictionBuilt::problems`]) or one
/// at a time into a reused buffer (the world step).
#[derive(Clone, Debug)]
pub(crate) struct FrictionBuilt {
    pub(crate) islands: Vec<Island>,
    pub(crate) rows: Vec<FrictionContactRows>,
}

impl FrictionBuilt {
    /// Builds a checked scene.
    pub(crate) fn new(scene: &Scene) -> Self {
        FrictionBuilt {
            islands: find_islands(scene),
            rows: assemble_friction_contacts(scene),
        }
    }

    /// Every island's frictional problem, in the islands' order.
    pub(crate) fn problems(&self, scene: &Scene) -> Vec<FrictionProblem> {
        self.islands
            .iter()
            .map(|isl| assemble_friction_island(scene, &self.rows, isl))
            .collect()
    }
}
