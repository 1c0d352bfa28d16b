//! Device trouble: no adapter, f64 asked of an adapter without SHADER_F64,
//! a device lost between or before batches. The CPU path takes over with a
//! warning, and the results are the CPU path's, byte for byte (compared as
//! the JSON the CLI writes).

use std::path::PathBuf;
use std::process::{Command, Output};

use lcpbatch::backend::{solve_lcps, solve_scenes, Backend, Session, SolvedWhere};
use lcpbatch::generate::{demo_world, random_island, seed_chain, Rng};
use lcpbatch::gpu::{list_adapters, BackendChoice, GpuContext, GpuOptions, Precision};
use lcpbatch::io::{LcpBatchOutput, LcpOutput, SceneOutput, ScenesOutput};
use lcpbatch::pipeline::build;
use lcpbatch::{Lcp, Scene, SolverSettings};

fn scenes() -> Vec<Scene> {
    let mut rng = Rng::new(11);
    let mut s: Vec<Scene> = (0..12).map(|_| demo_world(&mut rng)).collect();
    s.push(seed_chain(0.4));
    s
}

/// Island LCPs of all sizes 1..=9 plus two hand-made ones (no solution, a
/// cycle of Lemke) and one of n = 22 (Lemke after trouble, as on the GPU).
fn lcps() -> Vec<Lcp> {
    let mut rng = Rng::new(12);
    let mut v: Vec<Lcp> = (1..=9)
        .flat_map(|n| build(&random_island(&mut rng, n, 10.0), "t").unwrap().2)
        .collect();
    v.push(Lcp {
        m: vec![0.0, -1.0, 2.0, 2.0, 0.0, -2.0, -1.0, 1.0, 0.0],
        q: vec![-3.0, 6.0, -1.0],
    });
    v.push(Lcp {
        m: vec![2.0, 1.0, 1.0, 2.0],
        q: vec![-5.0, -6.0],
    });
    v
}

fn lcp_json(r: &lcpbatch::backend::LcpBatch) -> String {
    let problems = r
        .problems
        .iter()
        .map(|p| LcpOutput::new(p.solver.name(), &p.solution))
        .collect();
    serde_json::to_string_pretty(&LcpBatchOutput { problems }).unwrap()
}

fn scene_json(r: &lcpbatch::backend::SceneBatch) -> String {
    let scenes = r.scenes.iter().map(SceneOutput::new).collect();
    serde_json::to_string_pretty(&ScenesOutput { scenes }).unwrap()
}

/// The CPU backend's answers (the reference).
fn cpu_reference(lcps: &[Lcp], scenes: &[Scene]) -> (String, String) {
    let s = SolverSettings::default();
    let l = solve_lcps(&Backend::Cpu, lcps, &s).unwrap();
    let c = solve_scenes(&Backend::Cpu, scenes, &s).unwrap();
    assert_eq!(l.report.solved, SolvedWhere::Cpu);
    assert_eq!(l.report.fallback, None);
    assert_eq!(l.problems.len(), lcps.len());
    assert_eq!(c.scenes.len(), scenes.len());
    (lcp_json(&l), scene_json(&c))
}

fn no_such_adapter() -> GpuOptions {
    GpuOptions {
        adapter_name: Some("no-such-adapter".into()),
        ..GpuOptions::default()
    }
}

#[test]
fn no_adapter_the_cpu_takes_over_with_the_same_results() {
    let (lcps, scenes) = (lcps(), scenes());
    let (cpu_l, cpu_s) = cpu_reference(&lcps, &scenes);
    for backend in [
        Backend::Gpu(no_such_adapter()),
        Backend::Auto(no_such_adapter()),
    ] {
        let mut session = Session::new(&backend).expect("device trouble is not an error");
        assert!(session.context().is_none());
        let why = session
            .fallback()
            .expect("the reason is recorded")
            .to_string();
        assert!(
            why.contains("no adapter whose name contains `no-such-adapter`"),
            "{why}"
        );
        let s = SolverSettings::default();
        let l = session.solve_lcps(&lcps, &s).unwrap();
        assert_eq!(l.report.solved, SolvedWhere::Cpu);
        assert_eq!(l.report.fallback.as_deref(), Some(why.as_str()));
        assert!(l.report.gpu.is_none());
        assert!(l.problems.iter().all(|p| p.solved_on.is_none()));
        assert_eq!(lcp_json(&l), cpu_l);
        let c = session.solve_scenes(&scenes, &s).unwrap();
        assert_eq!(c.report.fallback.as_deref(), Some(why.as_str()));
        assert!(c.solved_on.is_none());
        assert_eq!(scene_json(&c), cpu_s);
        assert!(c.report.to_string().contains("GPU trouble"));
    }
}

#[test]
fn user_errors_stay_errors_after_device_trouble() {
    // An invalid scene (normal of length 0) is the caller's error on every path.
    let mut bad = seed_chain(0.4);
    bad.contacts[0].normal = [0.0, 0.0, 0.0];
    let s = SolverSettings::default();
    let cpu = solve_scenes(&Backend::Cpu, std::slice::from_ref(&bad), &s).unwrap_err();
    let gpu = solve_scenes(&Backend::Gpu(no_such_adapter()), &[bad], &s).unwrap_err();
    assert!(matches!(gpu, lcpbatch::Error::Invalid { .. }), "{gpu}");
    assert_eq!(gpu.to_string(), cpu.to_string());
    // Lemke is not the GPU's: refused on Gpu, served on Auto.
    let lemke = SolverSettings::with_solver(lcpbatch::Solver::Lemke);
    let e = solve_lcps(&Backend::Gpu(no_such_adapter()), &lcps(), &lemke).unwrap_err();
    assert!(matches!(e, lcpbatch::Error::Unsupported(_)), "{e}");
    let r = solve_lcps(&Backend::Auto(no_such_adapter()), &lcps(), &lemke).unwrap();
    let c = solve_lcps(&Backend::Cpu, &lcps(), &lemke).unwrap();
    assert_eq!(lcp_json(&r), lcp_json(&c));
    // After trouble an island too large to enumerate goes to Lemke (as on
    // the GPU path) instead of failing; the CPU backend refuses it.
    let mut rng = Rng::new(13);
    let big = build(&random_island(&mut rng, 22, 10.0), "t").unwrap().2;
    assert!(big.iter().any(|l| l.n() > 20));
    assert!(solve_lcps(&Backend::Cpu, &big, &s).is_err());
    let r = solve_lcps(&Backend::Gpu(no_such_adapter()), &big, &s).unwrap();
    for (p, l) in r.problems.iter().zip(&big) {
        if l.n() > 20 {
            assert_eq!(p.solver, lcpbatch::Solver::Lemke);
            assert!(p.solution.status.is_solution());
        }
    }
}

/// The GL adapter (llvmpipe), which the CI machine has and which has no
/// SHADER_F64.
fn gl() -> GpuOptions {
    let adapters = list_adapters(BackendChoice::Gl);
    assert!(
        !adapters.is_empty(),
        "no GL adapter: {}",
        lcpbatch::gpu::INSTALL_HINT
    );
    GpuOptions {
        backend: BackendChoice::Gl,
        ..GpuOptions::default()
    }
}

#[test]
fn f64_asked_of_an_adapter_without_it_falls_back_to_the_cpu() {
    let opts = gl();
    let has_f64 = list_adapters(BackendChoice::Gl).iter().all(|a| a.f64);
    let f64_opts = GpuOptions {
        precision: Precision::F64,
        ..opts.clone()
    };
    let (lcps, scenes) = (lcps(), scenes());
    let (cpu_l, cpu_s) = cpu_reference(&lcps, &scenes);
    let mut session = Session::new(&Backend::Gpu(f64_opts)).unwrap();
    if has_f64 {
        println!("the GL adapter has SHADER_F64: nothing to fall back from");
        assert!(session.fallback().is_none());
        return;
    }
    let why = session
        .fallback()
        .expect("f64 without SHADER_F64 is device trouble");
    assert!(why.contains("has no SHADER_F64"), "{why}");
    let s = SolverSettings::default();
    assert_eq!(lcp_json(&session.solve_lcps(&lcps, &s).unwrap()), cpu_l);
    assert_eq!(
        scene_json(&session.solve_scenes(&scenes, &s).unwrap()),
        cpu_s
    );
    // Auto precision on the same adapter is f32 on the GPU, no trouble.
    let mut session = Session::new(&Backend::Gpu(opts)).unwrap();
    assert!(session.fallback().is_none());
    assert_eq!(
        session.context().map(|c| c.precision()),
        Some(Precision::F32)
    );
    let r = session.solve_lcps(&lcps[..4], &s).unwrap();
    assert_eq!(r.report.solved, SolvedWhere::Gpu);
    assert!(r.report.gpu.is_some());
}

/// The environment's adapter, at f64 where it has it.
fn context() -> GpuContext {
    let o = GpuOptions::from_env().unwrap();
    GpuContext::new(&GpuOptions {
        precision: Precision::F64,
        ..o.clone()
    })
    .or_else(|_| GpuContext::new(&o))
    .unwrap_or_else(|e| panic!("no GPU adapter: {e}"))
}

#[test]
fn a_device_lost_between_batches_hands_the_next_to_the_cpu() {
    let (lcps, scenes) = (lcps(), scenes());
    let (cpu_l, cpu_s) = cpu_reference(&lcps, &scenes);
    let s = SolverSettings::default();
    let mut session = Session::from_context(context());
    // Tiny bindings: the batch goes to the GPU in several chunks.
    session.gpu_settings.max_binding_bytes = Some(1024);
    let before = session.solve_lcps(&lcps, &s).unwrap();
    assert_eq!(before.report.solved, SolvedWhere::Gpu);
    let chunks = before.report.gpu.as_ref().unwrap().chunks;
    assert!(chunks > 1, "{chunks} chunk(s)");
    assert!(session.fallback().is_none());

    // The device is lost between two batches (cached pipelines: wgpu
    // panics in `create_buffer_init`, which the session catches); for a loss
    // inside a batch see the test below.
    session.context().unwrap().simulate_device_loss();
    let after = session.solve_lcps(&lcps, &s).unwrap();
    assert_eq!(after.report.solved, SolvedWhere::Cpu);
    let why = after.report.fallback.clone().expect("the loss is recorded");
    assert!(why.contains("device lost"), "{why}");
    assert!(session.context().is_none(), "the lost context is dropped");
    assert_eq!(lcp_json(&after), cpu_l);
    // Later batches stay on the CPU, with the same reason.
    let c = session.solve_scenes(&scenes, &s).unwrap();
    assert_eq!(c.report.fallback.as_deref(), Some(why.as_str()));
    assert_eq!(scene_json(&c), cpu_s);
}

#[test]
fn a_device_lost_before_a_scene_batch_hands_it_to_the_cpu() {
    let scenes = scenes();
    let (_, cpu_s) = cpu_reference(&[], &scenes);
    let s = SolverSettings::default();
    let mut session = Session::from_context(context());
    session.gpu_settings.max_binding_bytes = Some(4096);
    session.context().unwrap().simulate_device_loss();
    let r = session.solve_scenes(&scenes, &s).unwrap();
    assert_eq!(r.report.solved, SolvedWhere::Cpu);
    assert!(r
        .report
        .fallback
        .as_deref()
        .unwrap()
        .contains("device lost"));
    assert_eq!(scene_json(&r), cpu_s);
}

// ---- the command line ----

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

fn temp(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lcpbatch-trouble-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn files() -> [PathBuf; 2] {
    let problems: Vec<serde_json::Value> = lcps()
        .iter()
        .map(|l| {
            let n = l.n();
            let rows: Vec<Vec<f64>> = (0..n).map(|i| l.m[i * n..(i + 1) * n].to_vec()).collect();
            serde_json::json!({"M": rows, "q": l.q})
        })
        .collect();
    [
        temp(
            "batch.json",
            &serde_json::json!({ "problems": problems }).to_string(),
        ),
        temp(
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
    for file in files() {
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
    gl();
    if list_adapters(BackendChoice::Gl).iter().all(|a| a.f64) {
        println!("the GL adapter has SHADER_F64: nothing to fall back from");
        return;
    }
    for file in files() {
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
    assert!(text.contains("adapter: none (CPU path"), "{text}");
    assert!(text.contains("statuses: solved"), "{text}");
}

/// A second thread destroys the device while the batch runs (half-way
/// through by the time of an undisturbed run; if the batch was done by
/// then, again on a fresh device with half the delay, down to a loss
/// before the batch).
#[test]
fn a_device_lost_in_the_middle_of_a_batch_hands_it_to_the_cpu() {
    // Many small chunks (a submission each), so that the batch can be cut.
    let mut rng = Rng::new(14);
    let lcps: Vec<Lcp> = (0..60)
        .flat_map(|k| {
            build(&random_island(&mut rng, 6 + k % 6, 10.0), "t")
                .unwrap()
                .2
        })
        .collect();
    let (cpu_l, _) = cpu_reference(&lcps, &[]);
    let s = SolverSettings::default();
    let session = |ctx: GpuContext| {
        let mut session = Session::from_context(ctx);
        session.gpu_settings.max_binding_bytes = Some(1024);
        session
    };
    let mut undisturbed = session(context());
    let t = std::time::Instant::now();
    let whole = undisturbed.solve_lcps(&lcps, &s).unwrap();
    let mut delay = t.elapsed() / 2;
    let chunks = whole.report.gpu.as_ref().unwrap().chunks;
    assert!(chunks > 10, "{chunks} chunks");
    loop {
        let mut session = session(context());
        let ctx = session.shared_context().unwrap();
        let r = std::thread::scope(|scope| {
            scope.spawn(|| {
                std::thread::sleep(delay);
                ctx.simulate_device_loss();
            });
            session.solve_lcps(&lcps, &s).unwrap()
        });
        if r.report.solved == SolvedWhere::Gpu {
            // Done before the loss: try again, sooner.
            assert!(r.report.fallback.is_none());
            assert!(!delay.is_zero(), "a loss before the batch went unnoticed");
            delay /= 2;
            continue;
        }
        let why = r.report.fallback.clone().expect("the loss is recorded");
        println!("lost after {delay:?} of a {chunks}-chunk batch: {why}");
        assert!(why.contains("device lost"), "{why}");
        assert!(session.context().is_none());
        assert_eq!(lcp_json(&r), cpu_l);
        break;
    }
}
