//! The benchmark's batch families, from fixed seeds: what `lcpbatch bench`,
//! the criterion benches and the tests solve.

use super::{demo_world, random_island, stress, Rng};
use crate::lcp::Lcp;
use crate::scene::Scene;

/// A batch family of the benchmark.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum BenchFamily {
    /// Random physical islands, n = 1…12, masses within a ratio of 10.
    WellConditioned,
    /// Random physical islands, n = 1…12, masses within a ratio of 1e4.
    MassRatio,
    /// Boxes resting on the ground and stacked: degenerate, rank-deficient M.
    RestingStacks,
    /// Islands of the demo worlds: balls, boxes and stacks, mixed n.
    MixedN,
    /// The resting stacks solved again with last frame's bases (warm start).
    WarmResting,
}

impl BenchFamily {
    /// Every family, in the table's order.
    pub const ALL: [BenchFamily; 5] = [
        BenchFamily::WellConditioned,
        BenchFamily::MassRatio,
        BenchFamily::RestingStacks,
        BenchFamily::MixedN,
        BenchFamily::WarmResting,
    ];

    /// The snake_case name used in tables and JSON.
    pub fn name(self) -> &'static str {
        match self {
            BenchFamily::WellConditioned => "well_conditioned",
            BenchFamily::MassRatio => "mass_ratio_1e4",
            BenchFamily::RestingStacks => "resting_stacks",
            BenchFamily::MixedN => "mixed_n",
            BenchFamily::WarmResting => "warm_resting",
        }
    }
}

/// Exactly `count` islands of a family, from `seed`.
pub fn family_batch(family: BenchFamily, seed: u64, count: usize) -> Vec<Lcp> {
    let mut rng = Rng::new(seed);
    let mut out = Vec::with_capacity(count + 16);
    match family {
        BenchFamily::WellConditioned | BenchFamily::MassRatio => {
            let ratio = if family == BenchFamily::MassRatio {
                1e4
            } else {
                10.0
            };
            while out.len() < count {
                let n = rng.int(1, 12);
                out.extend(island_lcps(&random_island(&mut rng, n, ratio)));
            }
        }
        BenchFamily::RestingStacks | BenchFamily::WarmResting => {
            out.extend(
                stress::generate(stress::Family::RestingStacks, seed, count)
                    .into_iter()
                    .map(|c| c.lcp),
            );
        }
        BenchFamily::MixedN => {
            while out.len() < count {
                out.extend(island_lcps(&demo_world(&mut rng)));
            }
        }
    }
    out.truncate(count);
    out
}

/// `count` random physical islands of exactly n contacts (mass ratio 100).
pub fn islands_of_size(n: usize, count: usize, seed: u64) -> Vec<Lcp> {
    let mut rng = Rng::new(seed ^ (n as u64) << 32);
    let mut out = Vec::with_capacity(count);
    while out.len() < count {
        out.extend(
            island_lcps(&random_island(&mut rng, n, 100.0))
                .into_iter()
                .filter(|l| l.n() == n),
        );
    }
    out.truncate(count);
    out
}

/// The LCPs of a generated (valid) scene's islands.
pub fn island_lcps(scene: &Scene) -> Vec<Lcp> {
    scene
        .islands("generated scene")
        .expect("generated scenes are valid")
        .into_iter()
        .map(|p| p.lcp)
        .collect()
}
