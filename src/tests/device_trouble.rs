//! Device trouble: no adapter, f64 asked of an adapter without SHADER_F64,
//! a device lost between, before or in the middle of a batch. The CPU path
//! takes over with a warning, and the results are the CPU path's, byte for
//! byte (compared as the JSON the CLI writes). The command line's side is
//! in tests/cli/trouble.rs.

use super::common::{gpu_settings_or_skip, skip, Lack};
use crate::generate::families::island_lcps;
use crate::generate::{demo_world, random_island, seed_chain, Rng};
use crate::gpu::{list_adapters, BackendChoice};
use crate::io::{LcpBatchOutput, ScenesOutput};
use crate::{Backend, GpuSettings, Lcp, Method, Precision, Report, Scene, Settings, Solver};

pub(super) fn scenes() -> Vec<Scene> {
    let mut rng = Rng::new(11);
    let mut s: Vec<Scene> = (0..12).map(|_| demo_world(&mut rng)).collect();
    s.push(seed_chain(0.4));
    s
}

/// Island LCPs of all sizes 1..=9 plus two hand-made ones (a 3×3 with a
/// zero diagonal that Lemke's method solves by hand, and the 2×2
/// M = [[2, 1], [1, 2]], q = (−5, −6)).
pub(super) fn lcps() -> Vec<Lcp> {
    let mut rng = Rng::new(12);
    let mut v: Vec<Lcp> = (1..=9)
        .flat_map(|n| island_lcps(&random_island(&mut rng, n, 10.0)))
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

fn lcp_json(r: &Report) -> String {
    serde_json::to_string_pretty(&LcpBatchOutput::of(r)).unwrap()
}

fn scene_json(r: &Report) -> String {
    serde_json::to_string_pretty(&ScenesOutput::of(r)).unwrap()
}

fn solver(backend: Backend, method: Method, gpu: GpuSettings) -> Solver {
    Solver::new(Settings {
        gpu,
        ..Settings::new(backend, method)
    })
    .expect("device trouble is not an error")
}

/// The CPU backend's answers (the reference), with enumeration as the GPU runs it.
fn cpu_reference(lcps: &[Lcp], scenes: &[Scene]) -> (String, String) {
    let mut s = solver(Backend::Cpu, Method::Enumeration, GpuSettings::default());
    let l = s.solve_lcps(lcps).unwrap();
    let c = s.solve_scenes(scenes).unwrap();
    assert!(!l.on_gpu());
    assert_eq!(l.fallback, None);
    assert_eq!(l.islands.len(), lcps.len());
    assert_eq!(c.scenes.len(), scenes.len());
    (lcp_json(&l), scene_json(&c))
}

fn no_such_adapter() -> GpuSettings {
    GpuSettings {
        adapter: Some("no-such-adapter".into()),
        ..GpuSettings::default()
    }
}

#[test]
fn no_adapter_the_cpu_takes_over_with_the_same_results() {
    let (lcps, scenes) = (lcps(), scenes());
    let (cpu_l, cpu_s) = cpu_reference(&lcps, &scenes);
    for backend in [Backend::Gpu, Backend::Auto] {
        let mut s = solver(backend, Method::Enumeration, no_such_adapter());
        assert!(s.shared_device().is_none());
        let why = s.fallback().expect("the reason is recorded").to_string();
        assert!(
            why.contains("no adapter whose name contains `no-such-adapter`"),
            "{why}"
        );
        let l = s.solve_lcps(&lcps).unwrap();
        assert!(!l.on_gpu());
        assert_eq!(l.fallback.as_deref(), Some(why.as_str()));
        assert!(l.gpu.is_none());
        assert_eq!(lcp_json(&l), cpu_l);
        let c = s.solve_scenes(&scenes).unwrap();
        assert_eq!(c.fallback.as_deref(), Some(why.as_str()));
        assert_eq!(scene_json(&c), cpu_s);
        assert!(c.to_string().contains("GPU trouble"));
    }
}

#[test]
fn user_errors_stay_errors_after_device_trouble() {
    // An invalid scene (normal of length 0) is the caller's error on every path.
    let mut bad = seed_chain(0.4);
    bad.contacts[0].normal = [0.0, 0.0, 0.0];
    let mut cpu = solver(Backend::Cpu, Method::Enumeration, GpuSettings::default());
    let mut gpu = solver(Backend::Gpu, Method::Enumeration, no_such_adapter());
    let e_cpu = cpu.solve_scenes(std::slice::from_ref(&bad)).unwrap_err();
    let e_gpu = gpu.solve_scenes(&[bad]).unwrap_err();
    assert!(matches!(e_gpu, crate::Error::Invalid { .. }), "{e_gpu}");
    assert_eq!(e_gpu.to_string(), e_cpu.to_string());
    // PGS is not the GPU's: refused on Gpu (a settings error); Lemke is
    // served on Auto.
    let e = Solver::new(Settings {
        gpu: no_such_adapter(),
        ..Settings::new(Backend::Gpu, Method::Pgs)
    })
    .unwrap_err();
    assert!(e.to_string().contains("backend"), "{e}");
    let r = solver(Backend::Auto, Method::Lemke, no_such_adapter())
        .solve_lcps(&lcps())
        .unwrap();
    let c = solver(Backend::Cpu, Method::Lemke, GpuSettings::default())
        .solve_lcps(&lcps())
        .unwrap();
    assert_eq!(lcp_json(&r), lcp_json(&c));
    // After trouble an island too large to enumerate goes to Lemke (as on
    // the GPU path) instead of failing; the CPU backend refuses it.
    let mut rng = Rng::new(13);
    let big = island_lcps(&random_island(&mut rng, 22, 10.0));
    assert!(big.iter().any(|l| l.n() > 20));
    assert!(cpu.solve_lcps(&big).is_err());
    let r = gpu.solve_lcps(&big).unwrap();
    for (p, l) in r.islands.iter().zip(&big) {
        if l.n() > 20 {
            assert_eq!(p.method, Method::Lemke);
            assert!(p.status().is_solution());
        }
    }
}

#[test]
fn f64_asked_of_an_adapter_without_it_falls_back_to_the_cpu() {
    let Some(gl) = list_adapters(BackendChoice::Gl).into_iter().next() else {
        skip(Lack::Other, "no GL adapter here (llvmpipe through EGL)");
        return;
    };
    if gl.f64 {
        skip(
            Lack::Other,
            "the GL adapter has SHADER_F64: nothing to fall back from",
        );
        return;
    }
    let gl_settings = |precision| GpuSettings {
        api: BackendChoice::Gl,
        precision,
        ..GpuSettings::default()
    };
    let (lcps, scenes) = (lcps(), scenes());
    let (cpu_l, cpu_s) = cpu_reference(&lcps, &scenes);
    let mut s = solver(
        Backend::Gpu,
        Method::Enumeration,
        gl_settings(Precision::F64),
    );
    let why = s
        .fallback()
        .expect("f64 without SHADER_F64 is device trouble");
    assert!(why.contains("has no SHADER_F64"), "{why}");
    assert_eq!(lcp_json(&s.solve_lcps(&lcps).unwrap()), cpu_l);
    assert_eq!(scene_json(&s.solve_scenes(&scenes).unwrap()), cpu_s);
    // Auto precision on the same adapter is f32 on the GPU, no trouble.
    let mut s = solver(
        Backend::Gpu,
        Method::Enumeration,
        gl_settings(Precision::Auto),
    );
    assert!(s.fallback().is_none());
    assert_eq!(s.device().precision, Precision::F32);
    let r = s.solve_lcps(&lcps[..4]).unwrap();
    assert!(r.on_gpu() && r.gpu.is_some());
}

/// A GPU solver on the environment's adapter (f64 where it has it) whose
/// batches are split into chunks of at most `binding` bytes.
fn chunked(gpu: GpuSettings, binding: u64) -> Solver {
    let mut s = Settings::new(Backend::Gpu, Method::Enumeration);
    s.gpu = GpuSettings {
        max_binding_bytes: Some(binding),
        ..gpu
    };
    Solver::new(s).unwrap()
}

#[test]
fn a_device_lost_between_batches_hands_the_next_to_the_cpu() {
    let Some(gpu) = gpu_settings_or_skip() else {
        return;
    };
    // Five copies, so that the batch needs several chunks of the smallest
    // binding (1 KiB) in f32 as in f64 (one copy fits one chunk in f32).
    let lcps: Vec<Lcp> = (0..5).flat_map(|_| lcps()).collect();
    let scenes = scenes();
    let (cpu_l, cpu_s) = cpu_reference(&lcps, &scenes);
    let mut s = chunked(gpu, 1024);
    let before = s.solve_lcps(&lcps).unwrap();
    assert!(before.on_gpu());
    let chunks = before.gpu.as_ref().unwrap().chunks;
    assert!(chunks > 1, "{chunks} chunk(s)");
    assert!(s.fallback().is_none());
    // The device is lost between two batches (cached pipelines: wgpu
    // panics in `create_buffer_init`, which the solver catches).
    s.shared_device().unwrap().simulate_device_loss();
    let after = s.solve_lcps(&lcps).unwrap();
    assert!(!after.on_gpu());
    let why = after.fallback.clone().expect("the loss is recorded");
    assert!(why.contains("device lost"), "{why}");
    assert!(s.shared_device().is_none(), "the lost device is dropped");
    assert_eq!(lcp_json(&after), cpu_l);
    // Later batches stay on the CPU, with the same reason.
    let c = s.solve_scenes(&scenes).unwrap();
    assert_eq!(c.fallback.as_deref(), Some(why.as_str()));
    assert_eq!(scene_json(&c), cpu_s);
}

#[test]
fn a_device_lost_before_a_scene_batch_hands_it_to_the_cpu() {
    let Some(gpu) = gpu_settings_or_skip() else {
        return;
    };
    let scenes = scenes();
    let (_, cpu_s) = cpu_reference(&[], &scenes);
    let mut s = chunked(gpu, 4096);
    s.shared_device().unwrap().simulate_device_loss();
    let r = s.solve_scenes(&scenes).unwrap();
    assert!(!r.on_gpu());
    assert!(r.fallback.as_deref().unwrap().contains("device lost"));
    assert_eq!(scene_json(&r), cpu_s);
}

/// A second thread destroys the device while the batch runs (half-way
/// through by the time of an undisturbed run; if the batch was done by
/// then, again on a fresh device with half the delay, down to a loss
/// before the batch).
#[test]
fn a_device_lost_in_the_middle_of_a_batch_hands_it_to_the_cpu() {
    let Some(gpu) = gpu_settings_or_skip() else {
        return;
    };
    // Many small chunks (a submission each), so that the batch can be cut.
    let mut rng = Rng::new(14);
    let lcps: Vec<Lcp> = (0..60)
        .flat_map(|k| island_lcps(&random_island(&mut rng, 6 + k % 6, 10.0)))
        .collect();
    let (cpu_l, _) = cpu_reference(&lcps, &[]);
    let mut undisturbed = chunked(gpu.clone(), 1024);
    let t = std::time::Instant::now();
    let whole = undisturbed.solve_lcps(&lcps).unwrap();
    let mut delay = t.elapsed() / 2;
    let chunks = whole.gpu.as_ref().unwrap().chunks;
    assert!(chunks > 10, "{chunks} chunks");
    loop {
        let mut s = chunked(gpu.clone(), 1024);
        let device = s.shared_device().unwrap();
        let r = std::thread::scope(|scope| {
            scope.spawn(|| {
                std::thread::sleep(delay);
                device.simulate_device_loss();
            });
            s.solve_lcps(&lcps).unwrap()
        });
        if r.on_gpu() {
            // Done before the loss: try again, sooner.
            assert!(r.fallback.is_none());
            assert!(!delay.is_zero(), "a loss before the batch went unnoticed");
            delay /= 2;
            continue;
        }
        let why = r.fallback.clone().expect("the loss is recorded");
        println!("lost after {delay:?} of a {chunks}-chunk batch: {why}");
        assert!(why.contains("device lost"), "{why}");
        assert!(s.shared_device().is_none());
        assert_eq!(lcp_json(&r), cpu_l);
        break;
    }
}
