//! The readers' fuzzing harness (fuzz/harness.rs, fuzz/README.md), a short
//! seeded run in every `cargo test`: a few thousand inputs per reader, made
//! from fuzz/corpus/ (and the small Siconos files of the conformance data),
//! each read without a panic, under a second, and either accepted or
//! refused with an error naming the item and the field. The long run is
//! `cargo run --release --example fuzz_readers` (or the libFuzzer targets).

#[path = "common/mod.rs"]
mod common;
#[path = "../fuzz/harness.rs"]
mod harness;

use harness::{named, Reader, Tally};
use lcpbatch::Error;

/// Inputs per reader (the seeds first).
const EXECS: u64 = 3000;

#[test]
fn every_reader_survives_a_seeded_run_and_names_every_refusal() {
    let corpus = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/corpus");
    let dat_dirs: Vec<_> = [common::siconos_dir(), common::fc3d_dir()]
        .into_iter()
        .flatten()
        .collect();
    for (k, reader) in Reader::ALL.into_iter().enumerate() {
        let seeds = harness::seeds(reader, &corpus, &dat_dirs);
        assert!(seeds.len() >= 2, "{}: {} seeds", reader.name(), seeds.len());
        let mut t = Tally::default();
        harness::run(reader, &seeds, EXECS, 24 + k as u64, &mut t);
        assert_eq!(t.execs, EXECS);
        // Both answers are exercised: the seeds are accepted, most
        // mutations refused.
        assert!(
            t.accepted >= seeds.len() as u64 && t.accepted < EXECS,
            "{}: {} of {EXECS} accepted",
            reader.name(),
            t.accepted
        );
        let faults: Vec<String> = t
            .faults
            .iter()
            .take(5)
            .map(|(_, why, text)| {
                format!(
                    "{why}\n  input: {:?}",
                    text.chars().take(300).collect::<String>()
                )
            })
            .collect();
        assert!(
            faults.is_empty(),
            "{}:\n{}",
            reader.name(),
            faults.join("\n")
        );
    }
}

/// A `.dat` reader's error.
fn dat(message: &str) -> Error {
    Error::Dat {
        path: "fuzz.dat".into(),
        message: message.into(),
    }
}

#[test]
fn the_check_refuses_errors_that_name_no_item_or_field() {
    let friction = r#"{"friction_problems":[{"W":[[1]],"q":[1],"q":[1],"mu":[0]}]}"#;
    let bad = [
        // A friction problem named as a scene.
        (
            Reader::Friction,
            friction,
            Error::invalid("scene 0", "q", "appears twice"),
        ),
        // An item the format has no word for.
        (Reader::Lcp, "{}", Error::invalid("problem", "q", "missing")),
        // A stand-in for a field that is not about the item's kind.
        (
            Reader::World,
            "{}",
            Error::invalid("world 0", "(item)", "invalid type"),
        ),
        // Valid JSON refused in serde's words.
        (
            Reader::Scene,
            friction,
            lcpbatch::io::parse_json("f", "{").unwrap_err(),
        ),
        // A .dat message naming no field of the format.
        (Reader::Dat, "1", dat("bad header")),
    ];
    for (reader, text, e) in bad {
        assert!(named(reader, text, &e).is_err(), "{reader:?} {e}");
    }
    let good = [
        (
            Reader::Friction,
            friction,
            Error::invalid("problem 0", "q", "appears twice"),
        ),
        (
            Reader::Scene,
            "{}",
            Error::invalid("scene 2, contact 1", "normal", "zero"),
        ),
        (
            Reader::World,
            "{}",
            Error::invalid("world 1, body 0", "mass", "missing"),
        ),
        (
            Reader::Lcp,
            "{",
            lcpbatch::io::parse_json("fuzz.json", "{").unwrap_err(),
        ),
        (Reader::Dat, "1", dat("line 1: n = 0")),
    ];
    for (reader, text, e) in good {
        assert!(named(reader, text, &e).is_ok(), "{reader:?} {e}");
    }
}
