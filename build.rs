//! Build script. Does nothing unless the feature `c-reference` is on (only
//! the bench `lemke_c` asks for it): then it compiles the plain C Lemke of
//! benches/c/lemke.c with the system's C compiler (`$CC`, else `cc`; -O3,
//! the target's baseline instruction set like the Rust code) and links the
//! object into the benches only. Normal builds, tests and CI compile no C.

use std::env;
use std::path::PathBuf;
use std::process::Command;

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    if env::var_os("CARGO_FEATURE_C_REFERENCE").is_none() {
        return;
    }
    println!("cargo:rerun-if-changed=benches/c/lemke.c");
    println!("cargo:rerun-if-env-changed=CC");
    let out = PathBuf::from(env::var("OUT_DIR").expect("cargo sets OUT_DIR"));
    let object = out.join("lemke_c.o");
    let cc = env::var("CC").unwrap_or_else(|_| "cc".to_string());
    let status = Command::new(&cc)
        .args(["-O3", "-fPIC", "-c", "benches/c/lemke.c", "-o"])
        .arg(&object)
        .status()
        .unwrap_or_else(|e| panic!("feature c-reference: cannot run the C compiler `{cc}`: {e}"));
    assert!(
        status.success(),
        "feature c-reference: `{cc}` failed on benches/c/lemke.c"
    );
    println!("cargo:rustc-link-arg-benches={}", object.display());
}
