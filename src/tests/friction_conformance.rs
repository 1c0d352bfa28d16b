//! Every FrictionContact3D problem of ../shared/conformance/siconos-fc3d,
//! read by the fc3d reader and solved by each exact Coulomb solver, judged
//! by the Coulomb error (Siconos' fc3d error) against reference.json.

use super::common::fc3d_dir;
use crate::friction::{solve_friction_problem, FrictionMethod, FrictionSettings};
use crate::io::fc3d::{is_fc3d, parse_fc3d};
use crate::Status;

/// Every problem must reach this Coulomb error with the exact path.
const TARGET: f64 = 1e-10;

fn problems() -> Vec<(String, crate::FrictionProblem, serde_json::Value)> {
    let Some(dir) = fc3d_dir() else {
        return Vec::new();
    };
    let text = std::fs::read_to_string(dir.join("reference.json")).unwrap();
    let reference: serde_json::Value = serde_json::from_str(&text).unwrap();
    let map = reference["problems"].as_object().unwrap();
    assert_eq!(map.len(), 9, "the README lists nine problems");
    map.iter()
        .map(|(name, r)| {
            let text = std::fs::read_to_string(dir.join(name)).unwrap();
            assert!(
                is_fc3d(&text),
                "{name} is not recognised as FrictionContact3D"
            );
            let p = parse_fc3d(name, &text).unwrap();
            assert_eq!(
                p.contacts() as u64,
                r["contacts"].as_u64().unwrap(),
                "{name}"
            );
            (name.clone(), p, r.clone())
        })
        .collect()
}

#[test]
fn the_reader_gives_the_references_own_error() {
    for (name, p, r) in problems() {
        let reference: Vec<f64> = r["r"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        let ours = crate::friction::coulomb_error(&p, &reference);
        let theirs = r["error"].as_f64().unwrap();
        assert!(
            (ours - theirs).abs() <= 1e-14 + 1e-6 * theirs,
            "{name}: error of the reference r {ours:e}, reference.json says {theirs:e}"
        );
    }
}

#[test]
fn every_problem_reaches_the_target_error_with_the_exact_path() {
    let settings = FrictionSettings {
        tolerance: TARGET,
        ..FrictionSettings::default()
    };
    for (name, p, r) in problems() {
        let s = solve_friction_problem(&p, None, &settings);
        eprintln!(
            "{name}: k = {}, auto: {} error {:.2e} in {} iterations",
            p.contacts(),
            s.status,
            s.residuals.coulomb_error,
            s.iterations
        );
        assert_eq!(s.status, Status::Solved, "{name}: {:?}", s.residuals);
        assert!(
            s.residuals.coulomb_error <= TARGET && s.residuals.cone_violation <= 1e-12,
            "{name}"
        );
        if r["unique"] == "yes" {
            // A unique solution: ours is the reference.
            for (a, b) in s.r.iter().zip(r["r"].as_array().unwrap()) {
                let b = b.as_f64().unwrap();
                assert!((a - b).abs() <= 1e-8 * (1.0 + b.abs()), "{name}: {:?}", s.r);
            }
        }
    }
}

#[test]
fn nsgs_and_newton_alone_on_the_conformance_problems() {
    // Recorded, not required: which problems each method reaches alone.
    for method in [FrictionMethod::Nsgs, FrictionMethod::Newton] {
        let settings = FrictionSettings {
            method,
            tolerance: TARGET,
            max_iterations: 10_000,
        };
        for (name, p, _) in problems() {
            let s = solve_friction_problem(&p, None, &settings);
            eprintln!(
                "{name}: {}: {} error {:.2e} in {} iterations",
                method.name(),
                s.status,
                s.residuals.coulomb_error,
                s.iterations
            );
            // Whatever it reached, its status says so.
            assert_eq!(
                s.status == Status::Solved,
                s.residuals.coulomb_error <= TARGET,
                "{name}"
            );
            if s.status == Status::Solved {
                assert!(
                    s.residuals.cone_violation <= 1e-9,
                    "{name}: {:?}",
                    s.residuals
                );
            }
        }
    }
}
