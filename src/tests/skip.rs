//! Skipping a test, or a part of one, so that whoever runs `cargo test`
//! sees it, and where the conformance data lies. Shared by the library's
//! tests (`src/tests/common.rs`) and the command-line tests
//! (`tests/common/mod.rs` includes this file by `#[path]`): std only.

use std::io::Write;
use std::path::PathBuf;

/// Set (to anything) in CI: a GPU test that finds no adapter fails
/// instead of skipping (`.ci/run` installs lavapipe and sets it).
pub const REQUIRE_GPU: &str = "LCPBATCH_REQUIRE_GPU";

/// Set (to anything) where the adapter must have SHADER_F64 (`.ci/run`'s
/// run on lavapipe, not its GL-only run): a test's f64 part fails instead
/// of skipping.
pub const REQUIRE_F64: &str = "LCPBATCH_REQUIRE_F64";

/// What a skipped test, or part of a test, did not find.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lack {
    /// Any GPU adapter: a failure where [`REQUIRE_GPU`] is set.
    Adapter,
    /// SHADER_F64 on the adapter: a failure where [`REQUIRE_F64`] is set.
    F64,
    /// Anything else (the conformance data, which `.ci/run` checks before
    /// the tests; a GL adapter beside Vulkan): never a failure.
    Other,
}

/// Skips (the caller returns or leaves out the part) with a line
/// `SKIPPED <test>: <why>` on stderr, or panics where the variable of
/// `lack` (see [`Lack`]) is set. The line is written through the stderr
/// handle, not `eprintln!`, whose output libtest captures and drops for a
/// passing test: so every skip shows in `cargo test`'s own output.
pub fn skip(lack: Lack, why: &str) {
    let require = match lack {
        Lack::Adapter => Some(REQUIRE_GPU),
        Lack::F64 => Some(REQUIRE_F64),
        Lack::Other => None,
    };
    if let Some(var) = require.filter(|v| std::env::var_os(v).is_some()) {
        panic!("{why} ({var} is set: this must run here, not skip)");
    }
    // libtest names each test's thread after the test (with one test
    // thread it may run on `main`).
    let test = std::thread::current()
        .name()
        .filter(|n| *n != "main")
        .map(|n| format!(" {n}"))
        .unwrap_or_default();
    let _ = writeln!(std::io::stderr(), "SKIPPED{test}: {why}");
}

/// The folder `name` inside the conformance data (`$LCPBATCH_CONFORMANCE`,
/// else `../shared/conformance` beside the crate).
/// None, after a visible [`skip`], when it is absent, so that a checkout
/// without the shared data skips these tests.
pub fn conformance_subdir(name: &str) -> Option<PathBuf> {
    let base = std::env::var_os("LCPBATCH_CONFORMANCE")
        .map(PathBuf::from)
        .unwrap_or_else(|| {
            PathBuf::from(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/../shared/conformance"
            ))
        });
    let dir = base.join(name);
    if dir.is_dir() {
        Some(dir)
    } else {
        skip(
            Lack::Other,
            &format!(
                "conformance data not found at {} (set LCPBATCH_CONFORMANCE)",
                dir.display()
            ),
        );
        None
    }
}

/// The Siconos LCP folder inside the conformance data, when present.
pub fn siconos_dir() -> Option<PathBuf> {
    conformance_subdir("siconos")
}

/// The Siconos `.dat` files of `dir`, sorted by name.
pub fn dat_files(dir: &std::path::Path) -> Vec<PathBuf> {
    let mut paths: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "dat"))
        .collect();
    paths.sort();
    paths
}

/// The Siconos FrictionContact3D folder inside the conformance data, when
/// present.
pub fn fc3d_dir() -> Option<PathBuf> {
    conformance_subdir("siconos-fc3d")
}
