//! Helpers shared by the command-line tests: where the conformance data
//! lies and skips (both from src/tests/skip.rs, which the library's own
//! tests share), temporary folders, running the binary, and whether a GPU
//! adapter is there.
#![allow(dead_code)]

use std::path::PathBuf;

use lcpbatch::{Backend, GpuSettings, Method, Precision, Settings, Solver};

#[path = "../../src/tests/skip.rs"]
mod skip;
pub use skip::{fc3d_dir, siconos_dir, skip, Lack};

/// A directory under the system temp dir, unique to this call, created
/// empty and removed with everything in it when dropped (a failing test's
/// too: unwinding drops it).
pub struct TempDir(PathBuf);

impl std::ops::Deref for TempDir {
    type Target = std::path::Path;
    fn deref(&self) -> &std::path::Path {
        &self.0
    }
}

impl AsRef<std::path::Path> for TempDir {
    fn as_ref(&self) -> &std::path::Path {
        &self.0
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// A [`TempDir`] named after `tag`, this process and a counter.
pub fn temp_dir(tag: &str) -> TempDir {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static COUNTER: AtomicUsize = AtomicUsize::new(0);
    let dir = std::env::temp_dir().join(format!(
        "lcpbatch-test-{tag}-{}-{}",
        std::process::id(),
        COUNTER.fetch_add(1, Ordering::Relaxed)
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("create temp dir");
    TempDir(dir)
}

/// Whether the environment's adapter (`LCPBATCH_GPU_*`) opens at
/// `precision`. Otherwise false after a [`skip`]: [`Lack::F64`] where f64
/// is asked of an adapter without it, [`Lack::Adapter`] without any
/// adapter (a failure where `LCPBATCH_REQUIRE_GPU` is set).
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
        Some(why) if precision == Precision::F64 && why.contains("SHADER_F64") => {
            skip(Lack::F64, &format!("the f64 part: {why}"));
            false
        }
        Some(why) => {
            // The error says how to install an adapter.
            skip(Lack::Adapter, &format!("no GPU adapter ({why})"));
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
