//! `lcpbatch simulate`: the files it writes, what they hold, and bad input
//! refused with a message naming item and field and nothing written.

use crate::common::{lcpbatch, temp_dir};
use crate::write;
use lcpbatch::world::format::parse_worlds;
use serde_json::Value;

/// `lcpbatch simulate --out OUT` with `args`.
fn simulate(out: &std::path::Path, args: &[&str]) -> std::process::Output {
    let mut all = vec!["simulate", "--out", out.to_str().unwrap()];
    all.extend_from_slice(args);
    lcpbatch(&all)
}

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
        "--threads",
        "1",
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
    for needle in [
        "world-steps/s",
        "slowest phase",
        "last step (t = 0.400 s): energy ",
        "over all 40 steps: deepest penetration ",
        "unsolved islands 0 (",
        "device: cpu (1 thread(s), f64)",
    ] {
        assert!(stdout.contains(needle), "`{needle}` missing in:\n{stdout}");
    }
    // The door's three parts indented under assembly+solve, before integrate.
    let at = |name: &str| {
        stdout
            .find(name)
            .unwrap_or_else(|| panic!("{name}: {stdout}"))
    };
    assert!(
        at("    assembly+solve") < at("      checks+assembly"),
        "{stdout}"
    );
    assert!(at("      impulses") < at("    integrate"), "{stdout}");
    assert!(!String::from_utf8_lossy(&run.stderr).contains("friction dropped"));
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
        assert_eq!(l["impacts"], 0, "{l}");
        assert_eq!(l["impacts_deferred"], 0, "{l}");
        assert!(l["kinetic"].as_f64().unwrap() < 1e-12, "{l}");
        assert!(l["max_penetration"].as_f64().unwrap() < 1e-9, "{l}");
        assert!(l["max_error"].as_f64().unwrap() < 1e-9, "{l}");
    }
    // Final states read back as worlds, the top box where it started.
    let final_text = std::fs::read_to_string(out.join("final.json")).unwrap();
    let worlds = parse_worlds("final.json", &final_text).unwrap();
    assert_eq!(worlds.len(), 3);
    assert!((worlds[2].bodies[3].position[1] - 2.5).abs() < 1e-9);
    // Plots and pictures, each titled with what was simulated.
    for plot in [
        "energy.svg",
        "penetration.svg",
        "error.svg",
        "time.svg",
        "worlds.svg",
        "worlds-animated.svg",
    ] {
        let svg = std::fs::read_to_string(out.join(plot)).unwrap();
        assert!(svg.starts_with("<svg"), "{plot}");
        assert!(
            svg.contains("3 × stack:3 (μ = 0.5): 40 steps of 10 ms")
                && svg.contains("solved on cpu"),
            "{plot}"
        );
    }
    // The kinetic energy has its own panel; the error plot the frictional
    // islands' tolerance (the stacks have μ = 0.5) and the floor.
    let energy = std::fs::read_to_string(out.join("energy.svg")).unwrap();
    assert!(energy.contains("kinetic energy (J)"));
    let error = std::fs::read_to_string(out.join("error.svg")).unwrap();
    assert!(error.contains("friction tolerance 1e-12") && error.contains("rounding floor"));
    // The stacks are alike: one row of pictures, three boxes and the ground each.
    let worlds_svg = std::fs::read_to_string(out.join("worlds.svg")).unwrap();
    assert!(worlds_svg.contains("world 0: stack:3") && !worlds_svg.contains("world 1:"));
    let animated = std::fs::read_to_string(out.join("worlds-animated.svg")).unwrap();
    assert_eq!(animated.matches("<animate attributeName=\"d\"").count(), 3);
    // A world file as input: the final states, stepped again.
    let again = dir.join("again");
    let final_json = out.join("final.json");
    let run = simulate(
        &again,
        &[
            "--worlds",
            "2",
            "--steps",
            "5",
            "--world",
            final_json.to_str().unwrap(),
        ],
    );
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(again.join("final.json").is_file());
}

/// Frictional islands the friction solver leaves unsolved (here every one:
/// no Coulomb error is at most 1e-300) are solved without friction, and a
/// warning says how many and where most were.
#[test]
fn friction_dropped_is_warned_with_its_count_and_worst_world() {
    let dir = temp_dir("simulate-dropped");
    let run = simulate(
        &dir.join("out"),
        &[
            "--worlds",
            "2",
            "--steps",
            "5",
            "--world",
            "slide",
            "--friction-tolerance",
            "1e-300",
        ],
    );
    assert!(run.status.success());
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(
        stderr.contains("warning: friction dropped on 10 of 10 frictional islands (100.00%)")
            && stderr.contains("most in world 0 (5)"),
        "{stderr}"
    );
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        stdout.contains("unsolved islands 10 (repaired: 10 exactly without friction"),
        "{stdout}"
    );
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
