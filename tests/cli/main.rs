//! The `lcpbatch` command line: output shapes for every kind of input, and
//! bad input refused with a non-zero exit, a message naming the item and
//! field, and no output file.

#[path = "../common/mod.rs"]
mod common;

mod empty;
mod friction;
mod golden;
mod gpu;
mod simulate;
mod trouble;

use std::path::{Path, PathBuf};

use common::{lcpbatch, temp_dir};
use lcpbatch::generate::{box_on_ground, random_island, seed_chain, Rng};
use lcpbatch::{Backend, Lcp, Method, Scene, Settings, Solver};
use serde_json::{json, Value};

/// The library's own answer, on the CPU with `method`.
fn cpu(method: Method) -> Solver {
    Solver::new(Settings::new(Backend::Cpu, method)).unwrap()
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// Runs `solve FILE extra…`, expects success, parses stdout.
fn solve_ok(file: &Path, extra: &[&str]) -> Value {
    let mut args = vec!["solve", file.to_str().unwrap()];
    args.extend_from_slice(extra);
    let out = lcpbatch(&args);
    assert!(
        out.status.success(),
        "{args:?}: exit {:?}, stderr {}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "{args:?}: stdout is not JSON ({e}): {}",
            String::from_utf8_lossy(&out.stdout)
        )
    })
}

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap_or_else(|| panic!("not an array: {v}"))
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

fn close(a: &[f64], b: &[f64], tol: f64) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(x, y)| (x - y).abs() <= tol * x.abs().max(1.0))
}

/// Checks one scene's output against the library's own solve.
fn check_scene_output(out: &Value, scene: &Scene, method: Method) {
    let r = cpu(method)
        .solve_scenes(std::slice::from_ref(scene))
        .unwrap();
    let lib = &r.scenes[0];
    let contacts = out["contacts"].as_array().expect("contacts");
    assert_eq!(contacts.len(), scene.contacts.len());
    for (c, z) in contacts.iter().zip(&lib.impulses) {
        assert!((c["impulse"].as_f64().unwrap() - z).abs() <= 1e-12 * z.abs().max(1.0));
    }
    let bodies = out["bodies"].as_array().expect("bodies");
    assert_eq!(bodies.len(), scene.bodies.len());
    for (b, v) in bodies.iter().zip(&lib.bodies) {
        assert!(close(&numbers(&b["velocity"]), &v.velocity, 1e-12), "{b}");
        assert!(
            close(&numbers(&b["angular_velocity"]), &v.angular_velocity, 1e-12),
            "{b}"
        );
    }
    let islands = out["islands"].as_array().expect("islands");
    assert_eq!(islands.len(), lib.islands.len());
    for (i, r) in islands.iter().zip(&r.islands[lib.islands.clone()]) {
        let contacts: Vec<usize> = i["contacts"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| c.as_u64().unwrap() as usize)
            .collect();
        assert_eq!(contacts, r.contacts);
        assert_eq!(i["status"], r.solution.status.name());
        assert!(i["error"].as_f64().unwrap() <= 1e-9);
    }
}

#[test]
fn solves_a_scene_file() {
    let dir = temp_dir("scene");
    let scene = seed_chain(0.5);
    let file = write(&dir, "chain.json", &serde_json::to_string(&scene).unwrap());
    for (solver, name) in [(Method::Enumeration, "enum"), (Method::Lemke, "lemke")] {
        let out = solve_ok(&file, &["--solver", name]);
        let scenes = out["scenes"].as_array().expect("scenes");
        assert_eq!(scenes.len(), 1);
        check_scene_output(&scenes[0], &scene, solver);
    }
}

#[test]
fn solves_a_multi_scene_file_to_an_output_file() {
    let dir = temp_dir("scenes");
    let mut rng = Rng::new(3);
    let scenes = vec![
        box_on_ground(1.0, 0.2),
        random_island(&mut rng, 6, 100.0),
        seed_chain(0.0),
    ];
    let file = write(&dir, "many.json", &json!({ "scenes": scenes }).to_string());
    let out_path = dir.join("out.json");
    let out = lcpbatch(&[
        "solve",
        file.to_str().unwrap(),
        "-o",
        out_path.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.stdout.is_empty(), "with -o nothing goes to stdout");
    let v: Value = serde_json::from_str(&std::fs::read_to_string(&out_path).unwrap()).unwrap();
    let got = v["scenes"].as_array().unwrap();
    assert_eq!(got.len(), 3);
    for (o, s) in got.iter().zip(&scenes) {
        check_scene_output(o, s, Method::Enumeration);
    }
    // No temporary file is left beside the output.
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    assert_eq!(names.len(), 2, "{names:?}");
}

#[test]
fn solves_an_lcp_batch_with_every_solver() {
    let dir = temp_dir("batch");
    let problems = json!({"problems": [
        {"M": [[2, 1], [1, 2]], "q": [-5, -6]},
        {"M": [[0.01]], "q": [-0.001]},
        {"M": [[2, 0], [0, 8]], "q": [-1, -1]}
    ]});
    let file = write(&dir, "batch.json", &problems.to_string());
    let expected = [vec![4.0 / 3.0, 7.0 / 3.0], vec![0.1], vec![0.5, 0.125]];
    for solver in ["enum", "lemke", "pgs"] {
        let out = solve_ok(&file, &["--solver", solver]);
        let got = out["problems"].as_array().expect("problems");
        assert_eq!(got.len(), 3);
        for (p, z) in got.iter().zip(&expected) {
            assert_eq!(p["status"], "solved", "{solver}: {p}");
            assert_eq!(p["solver"], solver);
            let tol = if solver == "pgs" { 1e-8 } else { 1e-12 };
            assert!(close(&numbers(&p["z"]), z, tol), "{solver}: {p}");
            assert!(
                close(&numbers(&p["w"]), &vec![0.0; z.len()], tol),
                "{solver}: {p}"
            );
            assert!(p["error"].as_f64().unwrap() <= 1e-10);
        }
    }
    // --all-solutions reports the solution set.
    let out = solve_ok(&file, &["--all-solutions"]);
    for p in out["problems"].as_array().unwrap() {
        assert_eq!(
            p["solution_set"],
            json!({"kind": "isolated", "count": 1}),
            "{p}"
        );
        assert_eq!(p["solutions"].as_array().unwrap().len(), 1);
    }
    // … and needs enumeration.
    let out = lcpbatch(&[
        "solve",
        file.to_str().unwrap(),
        "--solver",
        "lemke",
        "--all-solutions",
    ]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("--all-solutions"));
}

#[test]
fn solves_a_dat_file() {
    let dir = temp_dir("dat");
    // Column-major: M = [[2, 1], [1, 2]] is symmetric anyway; q = (−5, −6).
    let file = write(
        &dir,
        "p.dat",
        "2\n0\n2\n2\n2 2\n2 1\n1 2\n-5 -6\n# comment\n",
    );
    let out = solve_ok(&file, &[]);
    let p = &out["problems"][0];
    assert_eq!(p["status"], "solved");
    assert!(
        close(&numbers(&p["z"]), &[4.0 / 3.0, 7.0 / 3.0], 1e-12),
        "{p}"
    );
    assert_eq!(p["basis"], json!([0, 1]));
    // The conformance problems, when present, go through the CLI as well.
    if let Some(sic) = common::siconos_dir() {
        for name in ["lcp_deudeu.dat", "lcp_ortiz_block.dat", "lcp_CPS_1.dat"] {
            let path = sic.join(name);
            let text = std::fs::read_to_string(&path).unwrap();
            let lcp: Lcp = lcpbatch::io::siconos::parse_dat(name, &text).unwrap();
            let r = cpu(Method::Lemke)
                .solve_lcps(std::slice::from_ref(&lcp))
                .unwrap();
            let lib = &r.islands[0].solution;
            let out = solve_ok(&path, &["--solver", "lemke"]);
            let p = &out["problems"][0];
            assert_eq!(p["status"], lib.status.name(), "{name}");
            assert!(close(&numbers(&p["z"]), &lib.z, 1e-12), "{name}");
        }
        // A bimatrix game with three isolated solutions, all reported.
        let out = solve_ok(&sic.join("lcp_CPS_3.dat"), &["--all-solutions"]);
        let p = &out["problems"][0];
        assert_eq!(p["status"], "multiple_solutions", "{p}");
        assert_eq!(p["solution_set"], json!({"kind": "isolated", "count": 3}));
        assert_eq!(p["solutions"].as_array().unwrap().len(), 3);
        // And a problem without solution.
        let out = solve_ok(
            &sic.join("lcp_Pang_isolated_sol_perturbed.dat"),
            &["--all-solutions"],
        );
        let p = &out["problems"][0];
        assert_eq!(p["status"], "no_solution", "{p}");
        assert_eq!(p["solution_set"], json!({"kind": "empty"}));
    }
}

/// Bad input: exit non-zero, stderr names every `needles`, and with -o no
/// output file appears.
fn refuse(name: &str, text: &str, needles: &[&str]) {
    let dir = temp_dir("bad");
    let file = write(&dir, name, text);
    let out_path = dir.join("out.json");
    let out = lcpbatch(&[
        "solve",
        file.to_str().unwrap(),
        "-o",
        out_path.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{name}: accepted: {text}");
    for n in needles {
        assert!(stderr.contains(n), "{name}: stderr lacks `{n}`: {stderr}");
    }
    assert!(!out_path.exists(), "{name}: an output file was written");
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        1,
        "{name}: something besides the input was left"
    );
    assert!(
        out.stdout.is_empty(),
        "{name}: {}",
        String::from_utf8_lossy(&out.stdout)
    );
}

fn scene_json_value(edit: impl FnOnce(&mut Value)) -> Value {
    let mut v = serde_json::to_value(box_on_ground(1.0, 0.5)).unwrap();
    edit(&mut v);
    v
}

fn scene_json(edit: impl FnOnce(&mut Value)) -> String {
    scene_json_value(edit).to_string()
}

#[test]
fn bad_input_is_refused_and_named() {
    refuse(
        "broken.json",
        "{\"problems\": [{\"M\": [[1]], \"q\": [1]}",
        &["broken.json", "line"],
    );
    refuse("bad.json", "[1, 2]", &["bad.json", "object"]);
    refuse(
        "lengths.json",
        r#"{"problems": [{"M": [[1, 0], [0, 1]], "q": [1, 1]}, {"M": [[2, 1], [1]], "q": [-1, -1]}]}"#,
        &["problem 1", "M[1]"],
    );
    // A misspelt key is named as unknown, not its spelling as missing.
    refuse(
        "misspelt.json",
        r#"{"problems": [{"M": [[1]], "q": [1]}, {"M": [[1]], "Q": [1]}]}"#,
        &["problem 1: field `Q`: unknown field (expected `M`, `q`)"],
    );
    refuse(
        "rows.json",
        r#"{"problems": [{"M": [[1, 0, 0], [0, 1, 0]], "q": [1, 1]}]}"#,
        &["problem 0", "M[0]"],
    );
    refuse(
        "nan.dat",
        "2\n0\n2\n2\n2 2\n2 1\n1 nan\n-5 -6\n",
        &["nan.dat", "M[1][1]", "finite"],
    );
    refuse(
        "nanq.dat",
        "2\n0\n2\n2\n2 2\n2 1\n1 2\n-5 NaN\n",
        &["nanq.dat", "q[1]"],
    );
    refuse(
        "short.dat",
        "2\n0\n2\n2\n2 2\n2 1\n1 2\n-5\n",
        &["short.dat", "q[1]"],
    );
    refuse(
        "mass.json",
        &scene_json(|v| v["bodies"][1]["inv_mass"] = json!(-1.0)),
        &["scene 0, body 1", "inv_mass"],
    );
    refuse(
        "inertia.json",
        &scene_json(|v| v["bodies"][1]["inv_inertia"][0][2] = json!(0.5)),
        &["scene 0, body 1", "inv_inertia", "symmetric"],
    );
    refuse(
        "normal.json",
        &scene_json(|v| v["contacts"][2]["normal"] = json!([0.0, 0.0, 0.0])),
        &["scene 0, contact 2", "normal"],
    );
    refuse(
        "index.json",
        &scene_json(|v| v["contacts"][3]["b"] = json!(9)),
        &["scene 0, contact 3", "`b`", "out of range"],
    );
    refuse(
        "index_a.json",
        &scene_json(|v| v["contacts"][0]["a"] = json!(2)),
        &["scene 0, contact 0", "`a`", "out of range"],
    );
    // In a many-scene file the failing scene is named.
    let good = serde_json::to_value(seed_chain(0.0)).unwrap();
    let mut bad = serde_json::to_value(seed_chain(0.0)).unwrap();
    bad["bodies"][2]["inv_mass"] = json!(-0.5);
    refuse(
        "many.json",
        &json!({"scenes": [good, bad]}).to_string(),
        &["scene 1, body 2", "inv_mass"],
    );
    // Values of the wrong type or shape name the item and the field, as
    // the checks on values do.
    refuse(
        "type.json",
        &scene_json(|v| v["bodies"][1]["inv_mass"] = json!("x")),
        &["scene 0, body 1", "inv_mass", "string"],
    );
    refuse(
        "inertia_row.json",
        &scene_json(|v| v["bodies"][1]["inv_inertia"][2] = json!([1.0, 0.0])),
        &["scene 0, body 1", "inv_inertia[2]", "3"],
    );
    refuse(
        "negative_index.json",
        &scene_json(|v| v["contacts"][1]["a"] = json!(-1)),
        &["scene 0, contact 1", "`a`", "-1"],
    );
    refuse(
        "short_point.json",
        &scene_json(|v| v["contacts"][2]["point"] = json!([0.0, 0.0])),
        &["scene 0, contact 2", "point", "3"],
    );
    refuse(
        "missing.json",
        &scene_json(|v| {
            v["contacts"][3].as_object_mut().unwrap().remove("normal");
        }),
        &["scene 0, contact 3", "normal", "missing"],
    );
    refuse(
        "null.json",
        &json!({"scenes": [
            serde_json::to_value(seed_chain(0.0)).unwrap(),
            scene_json_value(|v| v["contacts"][0]["restitution"] = json!(null))
        ]})
        .to_string(),
        &["scene 1, contact 0", "restitution", "null"],
    );
    refuse(
        "entry.json",
        r#"{"problems": [{"M": [[1]], "q": [1]}, {"M": [[1, "x"], [0, 1]], "q": [1, 1]}]}"#,
        &["problem 1", "M[0][1]", "string"],
    );
    refuse(
        "q_type.json",
        r#"{"problems": [{"M": [[1, 0], [0, 1]], "q": [1, true]}]}"#,
        &["problem 0", "q[1]", "boolean"],
    );
    refuse(
        "extra.json",
        r#"{"problems": [{"M": [[1]], "q": [1], "extra": 1}]}"#,
        &["problem 0", "extra", "unknown"],
    );
    refuse(
        "not_a_list.json",
        r#"{"problems": {"M": [[1]], "q": [1]}}"#,
        &["problems", "array"],
    );
    // A missing input file names the path.
    let out = lcpbatch(&["solve", "/nonexistent/lcpbatch-input.json"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("lcpbatch-input.json"));
}

/// A reader that stops early (`lcpbatch generate … | head -c 100`) ends the
/// tool quietly: no panic about a broken pipe.
#[cfg(unix)]
#[test]
fn a_closed_pipe_ends_the_tool_quietly() {
    use std::io::Read;
    use std::process::{Command, Stdio};
    let mut child = Command::new(env!("CARGO_BIN_EXE_lcpbatch"))
        .args(["generate", "--kind", "stress-lcps", "--count", "2000"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut head = [0u8; 100];
    child.stdout.take().unwrap().read_exact(&mut head).unwrap();
    // The reader's end is dropped here: the pipe is closed.
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!err.contains("panicked"), "{err}");
}

/// Without XDG_RUNTIME_DIR (a headless machine as root), listing the
/// adapters prints no display-probe errors.
#[test]
fn no_display_probe_errors_without_xdg_runtime_dir() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_lcpbatch"))
        .arg("info")
        .env_remove("XDG_RUNTIME_DIR")
        .output()
        .unwrap();
    assert!(out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!err.contains("XDG_RUNTIME_DIR"), "{err}");
}
