//! Helpers shared by the command-line tests: where the conformance data
//! lies, temporary folders, running the binary, and whether a GPU adapter is
//! there (the library's own tests have theirs in src/tests/common.rs).
#![allow(dead_code)]

use std::path::PathBuf;

use lcpbatch::{Backend, GpuSettings, Method, Precision, Settings, Solver};

/// The conformance folder: `$LCPBATCH_CONFORMANCE`, else `../shared/conformance`
/// beside the crate. `None` (with a line on stderr) when it is absent, so
/// that a checkout without the shared data skips these tests.
pub fn conformance_dir() -> Option<PathBuf> {
    let dir = std::env::var_os("LCPBATCH_CONFORMANCE")
        .map(PathBuf::from)
        .unwrap_or_else(|| {
            PathBuf::from(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/../shared/conformance"
            ))
        });
    if dir.is_dir() {
        Some(dir)
    } else {
        eprintln!(
            "conformance data not found at {} (set LCPBATCH_CONFORMANCE); skipping",
            dir.display()
        );
        None
    }
}

/// The Siconos folder inside the conformance data, when present.
pub fn siconos_dir() -> Option<PathBuf> {
    let dir = conformance_dir()?.join("siconos");
    if dir.is_dir() {
        Some(dir)
    } else {
        eprintln!("{} not found; skipping", dir.display());
        None
    }
}

/// A directory under the system temp dir, unique to this process and `tag`,
/// created empty.
pub fn temp_dir(tag: &str) -> PathBuf {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static COUNTER: AtomicUsize = AtomicUsize::new(0);
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_nanos())
        .unwrap_or(0);
    let dir = std::env::temp_dir().join(format!(
        "lcpbatch-test-{tag}-{}-{}-{nanos}",
        std::process::id(),
        COUNTER.fetch_add(1, Ordering::Relaxed)
    ));
    std::fs::create_dir_all(&dir).expect("create temp dir");
    dir
}

/// Set (to anything) in CI: a GPU test that finds no adapter fails
/// instead of skipping (`.ci/run` installs lavapipe and sets it).
pub const REQUIRE_GPU: &str = "LCPBATCH_REQUIRE_GPU";

/// Whether the environment's adapter (`LCPBATCH_GPU_*`) opens at
/// `precision`. Without any adapter: false with a line on stderr saying the
/// test skips, or a failure where [`REQUIRE_GPU`] is set. f64 on an
/// adapter without it: false.
pub fn gpu_available(precision: Precision) -> bool {
    let gpu = GpuSettings {
        precision,
        ..GpuSettings::from_env().expect("GPU environment variables")
    };
    let s = Solver::new(Settings {
        gpu,
        ..Settings::new(Backend::Gpu, Method::Enumeration)
    })
    .expect("valid settings");
    match s.fallback() {
        None => true,
        Some(why) if precision == Precision::F64 && why.contains("SHADER_F64") => false,
        Some(why) => {
            if std::env::var_os(REQUIRE_GPU).is_some() {
                panic!("no GPU adapter ({why}); {REQUIRE_GPU} is set: GPU tests must run here");
            }
            eprintln!("skipping a GPU test: {why}; {}", lcpbatch::INSTALL_HINT);
            false
        }
    }
}

/// Runs the `lcpbatch` binary with `args` (lavapipe quietened by
/// XDG_RUNTIME_DIR) and returns what it printed and its exit status.
pub fn lcpbatch(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_lcpbatch"))
        .args(args)
        .env("XDG_RUNTIME_DIR", std::env::temp_dir())
        .output()
        .expect("run lcpbatch")
}
