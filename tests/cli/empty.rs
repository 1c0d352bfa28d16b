//! A scene without contacts is valid and gives an empty result, on every
//! backend (the GPU path has nothing to dispatch and must not trip over it).

use std::path::PathBuf;

use super::common::{lcpbatch, temp_dir};
use super::write;

fn solve(file: &PathBuf, backend: &str) -> (serde_json::Value, String) {
    let out = lcpbatch(&["solve", file.to_str().unwrap(), "--backend", backend]);
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    assert!(out.status.success(), "--backend {backend}: {err}");
    let text = String::from_utf8(out.stdout).unwrap();
    (serde_json::from_str(&text).expect("JSON"), err)
}

#[test]
fn an_empty_scene_gives_an_empty_result_on_every_backend() {
    let dir = temp_dir("empty");
    let f = write(&dir, "empty.json", r#"{"bodies":[],"contacts":[]}"#);
    let expected = serde_json::json!({"scenes": [{"contacts": [], "bodies": [], "islands": []}]});
    let gpu_ok = super::common::gpu_available(lcpbatch::Precision::Auto);
    for backend in ["cpu", "gpu", "auto"] {
        let (v, err) = solve(&f, backend);
        assert_eq!(v, expected, "--backend {backend}");
        if gpu_ok {
            assert!(!err.contains("warning"), "--backend {backend}: {err}");
        }
    }
}

#[test]
fn a_scene_without_contacts_keeps_its_velocities() {
    let dir = temp_dir("empty");
    let f = write(
        &dir,
        "no_contacts.json",
        r#"{"bodies":[{"inv_mass":1.0,"inv_inertia":[[6,0,0],[0,6,0],[0,0,6]],
            "position":[0,0.5,0],"velocity":[0,-1,0],"angular_velocity":[0,0.5,0]}],
            "contacts":[]}"#,
    );
    let (cpu, _) = solve(&f, "cpu");
    let scene = &cpu["scenes"][0];
    assert_eq!(scene["contacts"], serde_json::json!([]));
    assert_eq!(scene["islands"], serde_json::json!([]));
    assert_eq!(
        scene["bodies"][0]["velocity"],
        serde_json::json!([0.0, -1.0, 0.0])
    );
    assert_eq!(
        scene["bodies"][0]["angular_velocity"],
        serde_json::json!([0.0, 0.5, 0.0])
    );
    let (gpu, _) = solve(&f, "gpu");
    assert_eq!(gpu, cpu);
}
