//! `lcpbatch generate`: fixed-seed scenes and LCP batches as JSON, in the
//! formats `solve` reads (the golden inputs in tests/data/golden are three
//! of them; tests/cli/golden.rs checks they are reproduced byte for byte).

use clap::ValueEnum;
use serde_json::json;

use lcpbatch::generate::families::{family_batch, BenchFamily};
use lcpbatch::generate::stress::{generate, Family};
use lcpbatch::generate::{demo_world, random_scene, Rng};
use lcpbatch::Lcp;

/// What to generate.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Kind {
    /// `count` demo worlds (balls, boxes, stacks), one scene each.
    DemoWorlds,
    /// `count` scenes of 4 random islands of up to 10 contacts, mass ratio 1e3.
    RandomScenes,
    /// `count` LCPs of every stress family (mass ratios, scales, near-parallel
    /// normals, resting stacks, chains, non-symmetric, infeasible).
    StressLcps,
    /// `count` LCPs of the benchmark family `--family`.
    FamilyLcps,
}

/// A benchmark family on the command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum FamilyArg {
    WellConditioned,
    MassRatio,
    RestingStacks,
    MixedN,
}

fn problems(lcps: impl IntoIterator<Item = Lcp>) -> serde_json::Value {
    let problems: Vec<serde_json::Value> = lcps
        .into_iter()
        .map(|l| {
            let n = l.n();
            let rows: Vec<Vec<f64>> = (0..n).map(|i| l.m[i * n..(i + 1) * n].to_vec()).collect();
            json!({"M": rows, "q": l.q})
        })
        .collect();
    json!({ "problems": problems })
}

/// The JSON text (compact) of `count` items of `kind` from `seed`.
pub fn text(kind: Kind, count: usize, seed: u64, family: FamilyArg) -> String {
    let mut rng = Rng::new(seed);
    let value = match kind {
        Kind::DemoWorlds => {
            let scenes: Vec<_> = (0..count).map(|_| demo_world(&mut rng)).collect();
            json!({ "scenes": scenes })
        }
        Kind::RandomScenes => {
            let scenes: Vec<_> = (0..count)
                .map(|_| random_scene(&mut rng, 4, 10, 1e3))
                .collect();
            json!({ "scenes": scenes })
        }
        Kind::StressLcps => problems(
            Family::ALL
                .iter()
                .flat_map(|&f| generate(f, seed, count))
                .map(|c| c.lcp),
        ),
        Kind::FamilyLcps => {
            let f = match family {
                FamilyArg::WellConditioned => BenchFamily::WellConditioned,
                FamilyArg::MassRatio => BenchFamily::MassRatio,
                FamilyArg::RestingStacks => BenchFamily::RestingStacks,
                FamilyArg::MixedN => BenchFamily::MixedN,
            };
            problems(family_batch(f, seed, count))
        }
    };
    serde_json::to_string(&value).expect("serialisable")
}
