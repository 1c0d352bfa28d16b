//! The seeded mutation run over the five readers (fuzz/README.md):
//!
//! ```text
//! cargo run --release --example fuzz_readers -- [--execs N] [--seed S] [--reader NAME]
//! ```
//!
//! N inputs per reader (default 200,000), made from the seeds of
//! fuzz/corpus/<reader>/ (and, for `.dat`, the small Siconos files of the
//! conformance data); prints per reader the count, the time and the slowest
//! input, writes every fault to fuzz/artifacts/, and exits 1 on any.

#[path = "harness.rs"]
mod harness;
#[path = "../src/tests/skip.rs"]
#[allow(dead_code)]
mod skip;

use std::path::Path;
use std::time::Instant;

use harness::{Reader, Tally};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let arg = |name: &str| {
        args.iter()
            .position(|a| a == name)
            .and_then(|i| args.get(i + 1))
            .cloned()
    };
    let execs: u64 = arg("--execs").map_or(200_000, |v| v.parse().expect("--execs N"));
    let seed: u64 = arg("--seed").map_or(1, |v| v.parse().expect("--seed S"));
    let readers: Vec<Reader> = match arg("--reader") {
        Some(name) => {
            vec![Reader::from_name(&name).expect("--reader lcp|scene|friction|world|dat")]
        }
        None => Reader::ALL.to_vec(),
    };
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dat_dirs: Vec<_> = [skip::siconos_dir(), skip::fc3d_dir()]
        .into_iter()
        .flatten()
        .collect();
    let artifacts = root.join("fuzz/artifacts");
    let (mut total, start) = (Tally::default(), Instant::now());
    for (k, &reader) in readers.iter().enumerate() {
        let seeds = harness::seeds(reader, &root.join("fuzz/corpus"), &dat_dirs);
        let (mut t, began) = (Tally::default(), Instant::now());
        harness::run(reader, &seeds, execs, seed.wrapping_add(k as u64), &mut t);
        let secs = began.elapsed().as_secs_f64();
        println!(
            "{:<8} {:>9} inputs ({} seeds), {:>8} accepted, {} faults, {secs:.1} s ({:.0}/s), slowest {:.2} ms ({} bytes)",
            reader.name(),
            t.execs,
            seeds.len(),
            t.accepted,
            t.faults.len(),
            t.execs as f64 / secs,
            t.slowest.0.as_secs_f64() * 1e3,
            t.slowest.2.len(),
        );
        total.execs += t.execs;
        if t.slowest.0 > total.slowest.0 {
            total.slowest = t.slowest;
        }
        total.faults.extend(t.faults);
    }
    let (slow, who, text) = &total.slowest;
    println!(
        "total    {:>9} inputs, {} faults, {:.1} s; slowest {:.2} ms ({}): {:?}",
        total.execs,
        total.faults.len(),
        start.elapsed().as_secs_f64(),
        slow.as_secs_f64() * 1e3,
        who.map_or("-", Reader::name),
        text.chars().take(200).collect::<String>(),
    );
    if total.faults.is_empty() {
        return;
    }
    std::fs::create_dir_all(&artifacts).expect("create fuzz/artifacts");
    for (i, (reader, why, text)) in total.faults.iter().enumerate() {
        if i < 400 {
            println!("FAULT {}: {why}", reader.name());
        }
        let ext = if *reader == Reader::Dat {
            "dat"
        } else {
            "json"
        };
        let file = artifacts.join(format!("{}-{i}.{ext}", reader.name()));
        std::fs::write(&file, text).expect("write a fault's input");
    }
    println!(
        "{} faults; their inputs are in {}",
        total.faults.len(),
        artifacts.display()
    );
    std::process::exit(1);
}
