//! "Nothing else changes": `lcpbatch solve` output, byte for byte, on the
//! Siconos conformance problems and on fixed batches (tests/data/golden:
//! 40 demo worlds, 12 random multi-island scenes, 96 stress LCPs of every
//! family), with every solver and option, and on the GPU in f64 by
//! enumeration (the same bytes as the CPU's enumeration: the GPU's answers
//! are polished in f64; without an adapter the CPU's fallback gives them
//! too). Each output is compared by its length and FNV-1a hash with
//! `tests/data/golden/expected.txt`, recorded from the code before the "One door" change (commit a2173b0) and passing
//! unchanged through it. Re-recorded since, each for a stated reason:
//! `--solver lemke` (Lemke's retries and polish, "Fastest exact answer"
//! part 2) and the default (now `--solver auto`: Lemke checked in f64 before
//! enumeration, part 1); `--solver enum` gives the old default's bytes.
//! After an intended change of output,
//! `LCPBATCH_BLESS_GOLDEN=1 cargo test --release --test cli golden`
//! rewrites the record (and the commit must say why).

use super::common;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

const RECORD: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/data/golden/expected.txt"
);

/// The option sets every input is solved with.
const OPTIONS: [&[&str]; 6] = [
    &[],
    &["--solver", "enum"],
    &["--backend", "gpu", "--precision", "f64", "--solver", "enum"],
    &["--solver", "lemke"],
    &["--solver", "pgs"],
    &["--all-solutions"],
];

fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &b| {
        (h ^ b as u64).wrapping_mul(0x0100_0000_01b3)
    })
}

/// (label, input path) of every golden input.
fn inputs() -> Vec<(String, PathBuf)> {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/golden");
    let mut v: Vec<(String, PathBuf)> =
        ["demo_worlds.json", "random_scenes.json", "stress_lcps.json"]
            .iter()
            .map(|f| (f.to_string(), data.join(f)))
            .collect();
    if let Some(dir) = common::siconos_dir() {
        let mut dats: Vec<PathBuf> = std::fs::read_dir(&dir)
            .expect("read the Siconos folder")
            .map(|e| e.expect("dir entry").path())
            .filter(|p| p.extension().is_some_and(|e| e == "dat"))
            .collect();
        dats.sort();
        for p in dats {
            v.push((
                format!("siconos/{}", p.file_name().unwrap().to_string_lossy()),
                p,
            ));
        }
    }
    v
}

fn record() -> BTreeMap<String, String> {
    std::fs::read_to_string(RECORD)
        .unwrap_or_default()
        .lines()
        .filter_map(|l| l.split_once(" => "))
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect()
}

#[test]
fn solve_output_is_byte_identical_to_the_record() {
    let bless = std::env::var_os("LCPBATCH_BLESS_GOLDEN").is_some();
    let expected = record();
    let mut seen = BTreeMap::new();
    let mut differ = Vec::new();
    let gpu_f64 = common::gpu_available(lcpbatch::Precision::F64);
    for (label, path) in inputs() {
        for opts in OPTIONS {
            // Enumeration of every basis is exponential: only the small problems.
            if opts == ["--all-solutions"] && label == "siconos/lcp_tobenna.dat" {
                continue;
            }
            // Each GPU run compiles its kernels (seconds on a software
            // adapter): the batches only; src/tests/gpu_conformance.rs covers
            // the Siconos problems on the GPU. Without an f64 adapter the
            // GPU lines are not this machine's to check.
            let key = format!("{label} {}", opts.join(" ")).trim_end().to_string();
            if opts.contains(&"gpu") && (label.starts_with("siconos/") || !gpu_f64) {
                if let Some(v) = expected.get(&key) {
                    seen.insert(key, v.clone()); // kept as recorded
                }
                continue;
            }
            let mut args = vec!["solve", path.to_str().unwrap()];
            args.extend_from_slice(opts);
            let out = common::lcpbatch(&args);
            let value = if out.status.success() {
                format!(
                    "{} bytes, fnv1a {:016x}",
                    out.stdout.len(),
                    fnv1a(&out.stdout)
                )
            } else {
                format!("error: {}", String::from_utf8_lossy(&out.stderr).trim())
            };
            match expected.get(&key) {
                Some(v) if *v == value => {}
                Some(v) => differ.push(format!("{key}: expected {v}, got {value}")),
                None if bless => {}
                None if label.starts_with("siconos/") && expected.is_empty() => {}
                None => differ.push(format!("{key}: not in the record (got {value})")),
            }
            seen.insert(key, value);
        }
    }
    if bless {
        let text: String = seen.iter().map(|(k, v)| format!("{k} => {v}\n")).collect();
        std::fs::write(RECORD, text).expect("write the record");
        return;
    }
    assert!(
        differ.is_empty(),
        "solve output changed ({} of {}); if intended, rerun with LCPBATCH_BLESS_GOLDEN=1:\n{}",
        differ.len(),
        seen.len(),
        differ.join("\n")
    );
}

/// The golden inputs are `lcpbatch generate`'s output, byte for byte:
/// `--kind demo-worlds --count 40 --seed 11`, `--kind random-scenes --count
/// 12 --seed 12`, `--kind stress-lcps --count 12 --seed 13`.
#[test]
fn the_golden_inputs_are_what_generate_writes() {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/golden");
    for (file, args) in [
        ("demo_worlds.json", ["demo-worlds", "40", "11"]),
        ("random_scenes.json", ["random-scenes", "12", "12"]),
        ("stress_lcps.json", ["stress-lcps", "12", "13"]),
    ] {
        let out = common::lcpbatch(&[
            "generate", "--kind", args[0], "--count", args[1], "--seed", args[2],
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let want = std::fs::read(data.join(file)).expect("golden input");
        // stdout ends with the newline println adds.
        assert_eq!(out.stdout[..out.stdout.len() - 1], want[..], "{file}");
    }
    // Bad input: a count of 0 is refused, naming the flag.
    let out = common::lcpbatch(&["generate", "--kind", "demo-worlds", "--count", "0"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("--count"));
}
