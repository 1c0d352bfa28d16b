//! A frictional rain (`rain:32`: spheres and boxes of mixed sizes and
//! densities falling on the ground, μ = 0.4) through `Solver::step_worlds`
//! on the CPU at the CLI's friction tolerance 1e-12. Some islands end
//! unsolved at the iteration cap (single boxes on four corners and small
//! piles whose W is singular: NSGS stalls at 1e-11–1e-9, Newton stalls,
//! PROX needs 500–15,000 steps); each is repaired exactly, its best
//! iterate is the next step's warm start, and penetration stays bounded.

use crate::settings::{Backend, Method, Settings};
use crate::world::generate::{standard_world, WorldKind};
use crate::Solver;

/// 4 worlds × 200 steps of 10 ms (the fall, the impacts, the settling):
/// every unsolved island repaired exactly (normal impulses checked), an
/// island unsolved in one step warm-started in the next when the same
/// contacts form it again, and the deepest penetration below 10 cm.
#[test]
fn a_frictional_rain_repairs_exactly_restarts_warm_and_stays_bounded() {
    let mut worlds: Vec<_> = (0..4)
        .map(|k| standard_world(WorldKind::Rain, 32, 1 + k))
        .collect();
    let mut solver = Solver::new(Settings {
        warm_start: true,
        friction_tolerance: 1e-12,
        ..Settings::new(Backend::Cpu, Method::Auto)
    })
    .unwrap();
    let (mut unsolved, mut again, mut deepest) = (0, 0, 0.0f64);
    let mut last: Vec<(usize, Vec<usize>)> = Vec::new();
    for step in 0..200 {
        let r = solver.step_worlds(&mut worlds, 0.01).unwrap();
        assert_eq!(r.repairs.exact, r.unsolved, "step {step}: {:?}", r.repairs);
        unsolved += r.unsolved;
        for isl in &r.solve.friction {
            let key = (isl.scene.unwrap(), isl.contacts.clone());
            if last.contains(&key) {
                again += 1;
                assert!(isl.warm_started, "step {step}: {key:?} started cold");
            }
        }
        last = (r.solve.friction.iter())
            .filter(|i| !i.status().is_solution())
            .map(|i| (i.scene.unwrap(), i.contacts.clone()))
            .collect();
        deepest = r
            .worlds
            .iter()
            .fold(deepest, |d, w| d.max(w.max_penetration));
    }
    // Measured: 12 unsolved, 5 of them met again, 3.6 cm deepest.
    assert!(
        again > 0,
        "no unsolved island met again ({unsolved} unsolved)"
    );
    assert!(deepest < 0.1, "deepest penetration {deepest} m");
}
