//! Device trouble on the command line: no adapter, f64 asked of an adapter
//! without it. `solve` warns once and writes the CPU's output, byte for
//! byte; `demo` runs on the CPU. (The library's side: src/tests/device_trouble.rs.)

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use lcpbatch::device::list_adapters;
use lcpbatch::generate::families::island_lcps;
use lcpbatch::generate::{demo_world, random_island, seed_chain, Rng};
use lcpbatch::{BackendChoice, Lcp, Scene};

use super::common::{skip, temp_dir, Lack};
use super::write;

fn scenes() -> Vec<Scene> {
    let mut rng = Rng::new(11);
    let mut s: Vec<Scene> = (0..12).map(|_| demo_world(&mut rng)).collect();
    s.push(seed_chain(0.4));
    s
}

fn lcps() -> Vec<Lcp> {
    let mut rng = Rng::new(12);
    let mut v: Vec<Lcp> = (1..=9)
        .flat_map(|n| island_lcps(&random_island(&mut rng, n, 10.0)))
        .collect();
    v.push(Lcp {
        m: vec![0.0, -1.0, 2.0, 2.0, 0.0, -2.0, -1.0, 1.0, 0.0],
        q: vec![-3.0, 6.0, -1.0],
    });
    v
}

fn lcpbatch(args: &[&str], env: &[(&str, &str)]) -> Output {
    let mut c = Command::new(env!("CARGO_BIN_EXE_lcpbatch"));
    c.args(args)
        .env("XDG_RUNTIME_DIR", std::env::temp_dir())
        .env_remove("LCPBATCH_GPU_ADAPTER")
        .env_remove("LCPBATCH_GPU_PRECISION");
    for (k, v) in env {
        c.env(k, v);
    }
    c.output().expect("runs")
}

/// The batch and scenes files, in `dir`.
fn files(dir: &Path) -> [PathBuf; 2] {
    let problems: Vec<serde_json::Value> = lcps()
        .iter()
        .map(|l| {
            let n = l.n();
            let rows: Vec<Vec<f64>> = (0..n).map(|i| l.m[i * n..(i + 1) * n].to_vec()).collect();
            serde_json::json!({"M": rows, "q": l.q})
        })
        .collect();
    [
        write(
            dir,
            "batch.json",
            &serde_json::json!({ "problems": problems }).to_string(),
        ),
        write(
            dir,
            "scenes.json",
            &serde_json::json!({ "scenes": scenes() }).to_string(),
        ),
    ]
}

fn stdout_of(out: &Output, what: &str) -> String {
    assert!(
        out.status.success(),
        "{what}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout.clone()).unwrap()
}

#[test]
fn cli_gpu_without_the_adapter_warns_and_writes_the_cpu_output() {
    let dir = temp_dir("trouble");
    for file in files(&dir) {
        let f = file.to_str().unwrap();
        let cpu = stdout_of(&lcpbatch(&["solve", f, "--backend", "cpu"], &[]), "cpu");
        assert!(cpu.contains("\"status\""));
        for backend in ["gpu", "auto"] {
            let out = lcpbatch(
                &[
                    "solve",
                    f,
                    "--backend",
                    backend,
                    "--adapter",
                    "no-such-adapter",
                ],
                &[],
            );
            let text = stdout_of(&out, backend);
            let err = String::from_utf8_lossy(&out.stderr);
            assert!(
                err.contains("warning: GPU: no adapter whose name contains `no-such-adapter`"),
                "{err}"
            );
            assert!(err.contains("solving on the CPU"), "{err}");
            assert_eq!(
                err.matches("warning:").count(),
                1,
                "warned more than once: {err}"
            );
            assert_eq!(text, cpu, "{f} --backend {backend}");
        }
    }
}

#[test]
fn cli_f64_on_gl_warns_and_writes_the_cpu_output() {
    let gl = list_adapters(BackendChoice::Gl);
    if gl.is_empty() {
        skip(Lack::Other, "no GL adapter here (llvmpipe through EGL)");
        return;
    }
    if gl.iter().all(|a| a.f64) {
        skip(
            Lack::Other,
            "the GL adapter has SHADER_F64: nothing to fall back from",
        );
        return;
    }
    let dir = temp_dir("trouble");
    for file in files(&dir) {
        let f = file.to_str().unwrap();
        let cpu = stdout_of(&lcpbatch(&["solve", f, "--backend", "cpu"], &[]), "cpu");
        // The flag, and the environment variables.
        let flags = lcpbatch(
            &[
                "solve",
                f,
                "--backend",
                "gpu",
                "--gpu-backend",
                "gl",
                "--precision",
                "f64",
            ],
            &[],
        );
        let env = lcpbatch(
            &["solve", f, "--backend", "gpu"],
            &[
                ("LCPBATCH_GPU_BACKEND", "gl"),
                ("LCPBATCH_GPU_PRECISION", "f64"),
            ],
        );
        for out in [flags, env] {
            let text = stdout_of(&out, "gl f64");
            let err = String::from_utf8_lossy(&out.stderr);
            assert!(err.contains("warning: GPU: adapter"), "{err}");
            assert!(err.contains("has no SHADER_F64"), "{err}");
            assert_eq!(text, cpu, "{f}");
        }
    }
}

#[test]
fn cli_demo_without_the_adapter_runs_on_the_cpu() {
    let out = lcpbatch(
        &[
            "demo",
            "--worlds",
            "20",
            "--backend",
            "gpu",
            "--adapter",
            "no-such-adapter",
        ],
        &[],
    );
    let text = stdout_of(&out, "demo");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("warning: GPU: no adapter whose name contains"),
        "{err}"
    );
    assert!(text.contains("device: cpu"), "{text}");
    assert!(text.contains("GPU trouble, solved on the CPU"), "{text}");
    assert!(text.contains("statuses: solved"), "{text}");
}
