//! The command line on the GPU: `solve --backend gpu` writes what
//! `--backend cpu` writes (f64 shaders: byte for byte), `info` lists the
//! adapter and its features, `demo` prints its summary.

use lcpbatch::generate::{demo_world, seed_chain, Rng};
use lcpbatch::Precision;
use lcpbatch::Scene;

use super::common::{lcpbatch, temp_dir};
use super::write;

fn ok(args: &[&str]) -> String {
    let out = lcpbatch(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "lcpbatch {args:?} failed: {err}\n(no GPU adapter? {})",
        lcpbatch::device::INSTALL_HINT
    );
    String::from_utf8(out.stdout).expect("utf-8")
}

#[test]
fn gpu_and_cpu_backends_write_the_same_output() {
    let mut rng = Rng::new(5);
    let mut scenes: Vec<Scene> = (0..30).map(|_| demo_world(&mut rng)).collect();
    scenes.push(seed_chain(0.4));
    let dir = temp_dir("gpu-cli");
    let scenes_file = write(
        &dir,
        "scenes.json",
        &serde_json::json!({ "scenes": scenes }).to_string(),
    );
    let batch_file = write(
        &dir,
        "batch.json",
        r#"{"problems":[{"M":[[2,1],[1,2]],"q":[-5,-6]},
            {"M":[[0,-1,2],[2,0,-2],[-1,1,0]],"q":[-3,6,-1]},
            {"M":[[0,-1,2],[2,0,-2],[-1,1,0]],"q":[-3,6,1]},
            {"M":[[1,0],[0,1]],"q":[1,2]}]}"#,
    );
    // The adapter the CLI will pick (same environment): does it have f64?
    if !super::common::gpu_available(Precision::Auto) {
        return;
    }
    let f64_adapter = super::common::gpu_available(Precision::F64);
    for file in [&scenes_file, &batch_file] {
        let f = file.to_str().unwrap();
        let cpu = ok(&["solve", f, "--backend", "cpu", "--solver", "enum"]);
        // Method enumeration, as the CPU run, on `backend` at `precision`.
        let enumerate = |backend: &str, precision: &str| {
            let args = ["solve", f, "--backend", backend, "--solver", "enum"];
            ok(&[&args[..], &["--precision", precision]].concat())
        };
        if f64_adapter {
            let gpu = enumerate("gpu", "f64");
            let auto = enumerate("auto", "f64");
            // Both paths settle the same islands by prediction and
            // enumerate the rest in the same order: byte for byte.
            assert_eq!(gpu, cpu, "{f}: GPU output differs from the CPU's");
            assert_eq!(auto, cpu, "{f}: auto");
        }
        // f32 shaders: the same statuses and bases (z polished in f64).
        let g32: serde_json::Value = serde_json::from_str(&enumerate("gpu", "f32")).unwrap();
        let c: serde_json::Value = serde_json::from_str(&cpu).unwrap();
        let key = if c.get("problems").is_some() {
            "problems"
        } else {
            "scenes"
        };
        let (g, c) = (g32[key].as_array().unwrap(), c[key].as_array().unwrap());
        assert_eq!(g.len(), c.len());
        for (a, b) in g.iter().zip(c) {
            if key == "problems" {
                assert_eq!(a["status"], b["status"]);
                assert_eq!(a["basis"], b["basis"]);
            } else {
                let (ia, ib) = (
                    a["islands"].as_array().unwrap(),
                    b["islands"].as_array().unwrap(),
                );
                for (x, y) in ia.iter().zip(ib) {
                    assert_eq!(x["status"], y["status"]);
                    assert_eq!(x["contacts"], y["contacts"]);
                }
            }
        }
    }
    // --backend gpu refuses what only the CPU does.
    let out = lcpbatch(&[
        "solve",
        batch_file.to_str().unwrap(),
        "--backend",
        "gpu",
        "--solver",
        "pgs",
    ]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("enumeration or Lemke only"));
}

#[test]
fn info_lists_adapters_and_features() {
    if !super::common::gpu_available(Precision::Auto) {
        return;
    }
    let text = ok(&["info"]);
    assert!(text.contains("adapters:"), "{text}");
    assert!(text.contains("features: f64"), "{text}");
    assert!(text.contains("limits: storage binding"), "{text}");
    assert!(text.contains("backend auto: "), "{text}");
    assert!(text.contains("backend gpu: "), "{text}");
    let dir = temp_dir("gpu-cli");
    let f = write(
        &dir,
        "one.json",
        r#"{"problems":[{"M":[[2,1],[1,2]],"q":[-5,-6]}]}"#,
    );
    let args = [
        "solve",
        f.to_str().unwrap(),
        "--backend",
        "gpu",
        "--adapter",
        "no such adapter 7",
    ];
    // Device trouble: gpu, like auto, warns and solves on the CPU
    // (tests/cli/trouble.rs checks the output is the CPU's).
    let out = lcpbatch(&args);
    assert!(out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("warning: GPU: no adapter whose name contains `no such adapter 7`"),
        "{err}"
    );
    // auto falls back to the CPU with a message.
    let out = lcpbatch(&[
        "solve",
        f.to_str().unwrap(),
        "--backend",
        "auto",
        "--adapter",
        "no such adapter 7",
    ]);
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("solving on the CPU"));
}

#[test]
fn demo_prints_its_summary_and_the_other_path() {
    // Auto: the CPU unless there is a hardware GPU; the other path compared;
    // then 100 worlds stepped in time, their plots written.
    let out = temp_dir("demo");
    let o = out.to_str().unwrap();
    let text = ok(&["demo", "--worlds", "200", "--steps", "20", "--out", o]);
    for needle in [
        "device: ",
        "islands: ",
        "statuses: solved",
        "max error: ",
        "islands/s",
        "many worlds in time: 50 resting 4-box stacks and 50 boxes sliding",
        "100 worlds x 20 steps",
        "world-steps/s",
        "unsolved islands 0",
    ] {
        assert!(text.contains(needle), "`{needle}` missing in:\n{text}");
    }
    for file in ["steps.jsonl", "final.json", "energy.svg", "penetration.svg"] {
        assert!(out.join(file).is_file(), "{file}");
    }
    if !super::common::gpu_available(Precision::Auto) {
        return;
    }
    assert!(text.contains("for comparison, "), "{text}");
    // On the GPU by name: its path counts and figures.
    let text = ok(&[
        "demo",
        "--worlds",
        "200",
        "--backend",
        "gpu",
        "--steps",
        "0",
    ]);
    // Auto on the GPU: prediction, then the Lemke kernel.
    for needle in [
        "lemke_gpu ",
        "polished ",
        "gpu: ",
        "for comparison, CPU path",
    ] {
        assert!(text.contains(needle), "`{needle}` missing in:\n{text}");
    }
    assert!(!text.contains("repaired"), "{text}");
}

#[test]
fn every_solution_on_the_gpu_is_written_as_the_cpu_writes_it() {
    if !super::common::gpu_available(Precision::F64) {
        return;
    }
    let mut rng = Rng::new(9);
    let mut scenes: Vec<Scene> = (0..8).map(|_| demo_world(&mut rng)).collect();
    scenes.push(seed_chain(0.4));
    let dir = temp_dir("gpu-cli");
    let scenes_file = write(
        &dir,
        "all-scenes.json",
        &serde_json::json!({ "scenes": scenes }).to_string(),
    );
    let batch_file = write(
        &dir,
        "all-batch.json",
        r#"{"problems":[{"M":[[1,1],[1,1]],"q":[-1,-1]},
            {"M":[[0,-1,2],[2,0,-2],[-1,1,0]],"q":[-3,6,-1]},
            {"M":[[-1,2],[2,-1]],"q":[1,1]},
            {"M":[[0,0],[0,0]],"q":[-1,1]}]}"#,
    );
    for file in [&scenes_file, &batch_file] {
        let f = file.to_str().unwrap();
        let cpu = ok(&["solve", f, "--backend", "cpu", "--all-solutions"]);
        let gpu = ok(&[
            "solve",
            f,
            "--backend",
            "gpu",
            "--precision",
            "f64",
            "--all-solutions",
        ]);
        assert_eq!(gpu, cpu, "{f}: GPU --all-solutions differs from the CPU's");
    }
    // The LCP output carries the solution sets (a continuum, isolated
    // solutions, none).
    let cpu = ok(&["solve", batch_file.to_str().unwrap(), "--all-solutions"]);
    for set in ["bounded_continuum", "no_solution", "isolated"] {
        assert!(cpu.contains(set), "{set}: {cpu}");
    }
}

#[test]
fn info_measures_and_caches_auto_s_cost_model_for_a_named_adapter() {
    if !super::common::gpu_available(Precision::Auto) {
        return;
    }
    let cache = temp_dir("cost-cli");
    let run = |args: &[&str]| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_lcpbatch"))
            .args(args)
            .env("XDG_RUNTIME_DIR", std::env::temp_dir())
            .env("LCPBATCH_CACHE_DIR", &*cache)
            .output()
            .expect("run lcpbatch");
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8(out.stdout).unwrap()
    };
    // Unnamed software adapters: auto stays on the CPU, no model.
    let plain = run(&["info"]);
    if plain.contains("backend auto: hardware adapter") {
        return; // a hardware GPU: auto measures without a name; covered below too
    }
    assert!(plain.contains("no cost model"), "{plain}");
    // Named, the adapter is measured once; a second run reads the cache.
    let first = run(&["info", "--adapter", "llvmpipe"]);
    assert!(
        first.contains("cost model (") && first.contains("CPU µs/island"),
        "{first}"
    );
    let cached: Vec<_> = std::fs::read_dir(&cache).unwrap().collect();
    assert_eq!(cached.len(), 1);
    let second = run(&["info", "--adapter", "llvmpipe"]);
    let model = |t: &str| t[t.find("cost model (").unwrap()..].to_string();
    assert_eq!(
        model(&first),
        model(&second),
        "the cached model is read back"
    );
}
