//! `lcpbatch simulate`: the files it writes, what they hold, and bad input
//! refused with a message naming item and field and nothing written.

use crate::common::{lcpbatch, temp_dir};
use crate::write;
use lcpbatch::world::format::parse_worlds;
use serde_json::Value;

#[test]
fn simulate_writes_steps_final_states_and_plots() {
    let dir = temp_dir("simulate");
    let out = dir.join("out");
    let args = [
        "simulate",
        "--worlds",
        "3",
        "--steps",
        "40",
        "--world",
        "stack:3",
        "--backend",
        "cpu",
        "--out",
        out.to_str().unwrap(),
    ];
    let run = lcpbatch(&args);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        stdout.contains("world-steps/s") && stdout.contains("slowest phase"),
        "{stdout}"
    );
    let lines: Vec<Value> = std::fs::read_to_string(out.join("steps.jsonl"))
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(lines.len(), 40);
    for l in &lines {
        // 3 worlds × 3 boxes × 4 corners; one island per world; at rest.
        assert_eq!(l["contacts"], 36, "{l}");
        assert_eq!(l["islands"], 3, "{l}");
        assert_eq!(l["unsolved"], 0, "{l}");
        assert_eq!(l["repaired_exact"], 0, "{l}");
        assert_eq!(l["repaired_dropped"], 0, "{l}");
        assert!(l["kinetic"].as_f64().unwrap() < 1e-12, "{l}");
        assert!(l["max_penetration"].as_f64().unwrap() < 1e-9, "{l}");
        assert!(l["max_error"].as_f64().unwrap() < 1e-9, "{l}");
    }
    // Final states read back as worlds, the top box where it started.
    let final_text = std::fs::read_to_string(out.join("final.json")).unwrap();
    let worlds = parse_worlds("final.json", &final_text).unwrap();
    assert_eq!(worlds.len(), 3);
    assert!((worlds[2].bodies[3].position[1] - 2.5).abs() < 1e-9);
    for plot in ["energy.svg", "penetration.svg", "error.svg", "time.svg"] {
        let svg = std::fs::read_to_string(out.join(plot)).unwrap();
        assert!(svg.starts_with("<svg"), "{plot}");
    }
    // A world file as input: the final states, stepped again.
    let again = dir.join("again");
    let run = lcpbatch(&[
        "simulate",
        "--worlds",
        "2",
        "--steps",
        "5",
        "--world",
        out.join("final.json").to_str().unwrap(),
        "--out",
        again.to_str().unwrap(),
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(again.join("final.json").is_file());
}

#[test]
fn bad_worlds_and_options_are_refused_and_nothing_is_written() {
    let dir = temp_dir("simulate-bad");
    let bad = write(
        &dir,
        "bad.json",
        r#"{"bodies":[{"shape":{"box":{"half_extents":[0.5,-1,0.5]}},"position":[0,1,0],"mass":1}]}"#,
    );
    let cases: [(Vec<&str>, &str); 4] = [
        (
            vec!["--world", bad.to_str().unwrap()],
            "world 0, body 0: field `shape.box.half_extents[1]`",
        ),
        (vec!["--world", "tower"], "--world: field `kind`"),
        (vec!["--dt=-0.01"], "--dt"),
        (vec!["--worlds", "0"], "--worlds"),
    ];
    for (extra, want) in cases {
        let out = dir.join("out");
        let mut args = vec!["simulate", "--steps", "3", "--out", out.to_str().unwrap()];
        args.extend(extra.iter().copied());
        let run = lcpbatch(&args);
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert!(!run.status.success(), "{args:?}");
        assert!(stderr.contains(want), "{args:?}: {stderr}");
        assert!(!out.exists(), "{args:?}: output written");
    }
}
