//! The larger FrictionContact3D problems of
//! ../shared/conformance/siconos-fc3d-large (52, 276 and 570 contacts),
//! solved by `auto` and by `prox` from r = 0 to Siconos' tolerance 1e-8,
//! judged by the Coulomb error (Siconos' fc3d error). Each solve's time is
//! printed beside Siconos' (reference.json).

use std::time::Instant;

use super::skip::conformance_subdir;
use crate::friction::{coulomb_error, solve_friction_problem, FrictionMethod, FrictionSettings};
use crate::io::fc3d::parse_fc3d;
use crate::Status;

/// Siconos' tolerance on these problems, which every answer must reach.
const TARGET: f64 = 1e-8;

#[test]
fn every_large_problem_is_solved_by_auto_and_prox() {
    let Some(dir) = conformance_subdir("siconos-fc3d-large") else {
        return;
    };
    let text = std::fs::read_to_string(dir.join("reference.json")).unwrap();
    let reference: serde_json::Value = serde_json::from_str(&text).unwrap();
    let map = reference["problems"].as_object().unwrap();
    assert_eq!(map.len(), 3, "the README lists three problems");
    for (name, entry) in map {
        let p = parse_fc3d(name, &std::fs::read_to_string(dir.join(name)).unwrap()).unwrap();
        assert_eq!(p.contacts() as u64, entry["contacts"].as_u64().unwrap());
        let fastest = entry["siconos"]
            .as_object()
            .unwrap()
            .iter()
            .filter(|(_, s)| s["info"] == 0)
            .map(|(solver, s)| (s["seconds"].as_f64().unwrap(), solver.clone()))
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .unwrap();
        for method in [FrictionMethod::Auto, FrictionMethod::Prox] {
            let settings = FrictionSettings {
                method,
                tolerance: TARGET,
                ..FrictionSettings::default()
            };
            let start = Instant::now();
            let s = solve_friction_problem(&p, None, &settings);
            let seconds = start.elapsed().as_secs_f64();
            eprintln!(
                "{name}: k = {}, {}: {} error {:.2e} in {} iterations, {seconds:.3} s \
                 (Siconos' fastest: {} {:.3} s)",
                p.contacts(),
                method.name(),
                s.status,
                s.residuals.coulomb_error,
                s.iterations,
                fastest.1,
                fastest.0,
            );
            assert_eq!(
                s.status,
                Status::Solved,
                "{name}, {}: {:?}",
                method.name(),
                s.residuals
            );
            // The reported error is the answer's own, in the problem's order.
            let error = coulomb_error(&p, &s.r);
            assert!(error <= TARGET, "{name}, {}: {error:e}", method.name());
            assert!(
                s.residuals.cone_violation <= 1e-12,
                "{name}: {:?}",
                s.residuals
            );
        }
    }
}
