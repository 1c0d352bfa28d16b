//! `lcpbatch solve` with friction: FrictionContact3D .dat files, JSON
//! batches of frictional problems, scenes with friction, the
//! `--friction-solver` flag, and bad friction input refused.

use super::common::{fc3d_dir, lcpbatch, temp_dir};
use super::{numbers, solve_ok, write};
use serde_json::Value;

#[test]
fn fc3d_files_are_read_and_solved_to_the_conformance_target() {
    let Some(dir) = fc3d_dir() else {
        return;
    };
    for name in [
        "Rover4396.dat",
        "FC3D_Example1_SBM.dat",
        "OneObject-i1028-138.hdf5.dat",
    ] {
        for solver in ["auto", "nsgs"] {
            let out = solve_ok(
                &dir.join(name),
                &["--friction-solver", solver, "--friction-tolerance", "1e-10"],
            );
            let p = &out["friction_problems"][0];
            let error = p["coulomb_error"].as_f64().unwrap();
            if solver == "auto" || !name.starts_with("OneObject") {
                assert_eq!(p["status"], "solved", "{name} {solver}: {p}");
                assert!(error <= 1e-10, "{name}");
            } else {
                // NSGS needs about 1300 sweeps on this one (23 contacts):
                // the default cap of 1000 stops it, and the status says so.
                assert_eq!(p["status"], "not_converged", "{name} {solver}: {p}");
                assert!(error > 1e-10 && error < 1e-6, "{name}: {error}");
            }
            assert_eq!(p["solver"], solver);
            assert_eq!(numbers(&p["r"]).len(), numbers(&p["u"]).len());
        }
    }
}

#[test]
fn a_json_batch_of_frictional_problems_and_a_scene_with_friction() {
    let dir = temp_dir("friction-cli");
    // W = I, approaching at 10, sliding at (3, −4), μ = 0.5: r = (10, −3, 4).
    let batch = write(
        &dir,
        "batch.json",
        r#"{"friction_problems": [{"W": [[1,0,0],[0,1,0],[0,0,1]], "q": [-10, 3, -4], "mu": [0.5]}]}"#,
    );
    let out = solve_ok(&batch, &[]);
    let p = &out["friction_problems"][0];
    let r = numbers(&p["r"]);
    assert!(
        (r[0] - 10.0).abs() < 1e-12 && (r[1] + 3.0).abs() < 1e-12 && (r[2] - 4.0).abs() < 1e-12,
        "{p}"
    );
    assert_eq!(p["iterations"].as_u64().unwrap() >= 1, true);
    // The same as a scene: a unit point mass on the ground.
    let scene = write(
        &dir,
        "scene.json",
        r#"{"bodies": [{"inv_mass": 1, "inv_inertia": [[0,0,0],[0,0,0],[0,0,0]], "position": [0,0,0],
             "velocity": [3, -10, 4], "angular_velocity": [0,0,0]}],
            "contacts": [{"a": 0, "b": null, "point": [0,0,0], "normal": [0,1,0], "restitution": 0, "friction": 0.5, "id": 3}]}"#,
    );
    let out = solve_ok(&scene, &["--friction-solver", "newton"]);
    let s = &out["scenes"][0];
    let c = &s["contacts"][0];
    assert!((c["impulse"].as_f64().unwrap() - 10.0).abs() < 1e-12, "{c}");
    let f = &c["friction"];
    let world = numbers(&f["impulse"]);
    // t₁ = x, t₂ = −z: (−3, 4) in the frame is (−3, 10, −4) in the world.
    for (a, b) in world.iter().zip([-3.0, 10.0, -4.0]) {
        assert!((a - b).abs() < 1e-12, "{f}");
    }
    assert!((f["normal"].as_f64().unwrap() - 10.0).abs() < 1e-12);
    assert_eq!(numbers(&f["tangential"]).len(), 2);
    let v = numbers(&s["bodies"][0]["velocity"]);
    assert!(v.iter().all(|x| x.abs() < 1e-12), "stops: {v:?}");
    assert_eq!(s["islands"].as_array().unwrap().len(), 0);
    let isl = &s["friction_islands"][0];
    assert_eq!(
        (isl["status"].as_str(), isl["solver"].as_str()),
        (Some("solved"), Some("newton"))
    );
    assert_eq!(isl["contacts"], serde_json::json!([0]));
}

#[test]
fn bad_friction_input_is_refused_naming_the_item_and_field() {
    let dir = temp_dir("friction-cli-bad");
    let cases = [
        (
            r#"{"friction_problems": [{"W": [[1,0,0],[0,1,0],[0,0,1]], "q": [-1, 0, 0], "mu": [-0.5]}]}"#,
            "mu[0]",
        ),
        (
            r#"{"friction_problems": [{"W": [[1,0],[0,1,0],[0,0,1]], "q": [-1, 0, 0], "mu": [0.5]}]}"#,
            "W[0]",
        ),
        // A key twice in a friction problem names the problem (not "scene 0").
        (
            r#"{"friction_problems": [{"W": [[1]], "q": [1], "mu": [0]},
                {"W": [[1,0,0],[0,1,0],[0,0,1]], "q": [-1, 0, 0], "q": [1, 0, 0], "mu": [0.5]}]}"#,
            "error: problem 1: field `q`: appears twice in one object",
        ),
        (
            r#"{"bodies": [{"inv_mass": 1, "inv_inertia": [[0,0,0],[0,0,0],[0,0,0]], "position": [0,0,0],
                 "velocity": [0,0,0], "angular_velocity": [0,0,0]}],
                "contacts": [{"a": 0, "b": null, "point": [0,0,0], "normal": [0,1,0], "restitution": 0, "friction": -1}]}"#,
            "contact 0: field `friction`",
        ),
    ];
    for (i, (text, want)) in cases.iter().enumerate() {
        let f = write(&dir, &format!("bad{i}.json"), text);
        let out = lcpbatch(&["solve", f.to_str().unwrap()]);
        assert!(!out.status.success());
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(want), "{want}: {err}");
    }
    let dat = write(&dir, "bad.dat", "3 1 0 3 3 3 3 1 0 0 0 1 0 0 0 1 -1 0 0 x");
    let out = lcpbatch(&["solve", dat.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        !out.status.success() && err.contains("bad.dat") && err.contains("mu[0]"),
        "{err}"
    );
    let help = lcpbatch(&["solve", "--help"]);
    let text = String::from_utf8_lossy(&help.stdout);
    assert!(
        text.contains("--friction-solver") && text.contains("nsgs"),
        "{text}"
    );
    let _: Value = Value::Null;
}
