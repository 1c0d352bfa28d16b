//! A frictional rain (`rain:32`: spheres and boxes of mixed sizes and
//! densities falling on the ground, μ = 0.4) through `Solver::step_worlds`
//! on the CPU at the CLI's friction tolerance 1e-12. Some islands end
//! unsolved at the iteration cap (single boxes on four corners and small
//! piles whose W is singular: NSGS stalls at 1e-11–1e-9, Newton stalls,
//! PROX needs 500–15,000 steps); each is repaired exactly, and
//! penetration stays bounded.

use crate::settings::{Backend, Method, Settings};
use crate::world::generate::{standard_world, WorldKind};
use crate::Solver;

/// 4 worlds × 200 steps of 10 ms (the fall, the impacts, the settling):
/// every unsolved island repaired exactly (normal impulses, checked), at
/// most one island in 100 unsolved, and the deepest penetration below
/// 10 cm.
#[test]
fn a_frictional_rain_repairs_exactly_and_stays_bounded() {
    let mut worlds: Vec<_> = (0..4)
        .map(|k| standard_world(WorldKind::Rain, 32, 1 + k))
        .collect();
    let mut solver = Solver::new(Settings {
        warm_start: true,
        friction_tolerance: 1e-12,
        ..Settings::new(Backend::Cpu, Method::Auto)
    })
    .unwrap();
    let (mut unsolved, mut islands, mut deepest) = (0, 0, 0.0f64);
    for step in 0..200 {
        let r = solver.step_worlds(&mut worlds, 0.01).unwrap();
        assert_eq!(r.repairs.exact, r.unsolved, "step {step}: {:?}", r.repairs);
        unsolved += r.unsolved;
        islands += r.solve.friction.len();
        deepest = r
            .worlds
            .iter()
            .fold(deepest, |d, w| d.max(w.max_penetration));
    }
    assert!(
        100 * unsolved <= islands,
        "{unsolved} of {islands} islands unsolved"
    );
    assert!(deepest < 0.1, "deepest penetration {deepest} m");
}
