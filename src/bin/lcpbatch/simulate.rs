//! `lcpbatch simulate`: many worlds stepped in time through
//! `Solver::step_worlds`, one contact batch per step. Writes into `--out`:
//! `steps.jsonl` (one line per step, aggregated over the worlds), `final.json`
//! (the worlds' final states, readable by `--world`), and SVG plots of
//! energy, penetration, solver error and time per step. Every file is written
//! atomically after the last step, so a failure leaves none half-written.

use std::path::{Path, PathBuf};
use std::time::Instant;

use lcpbatch::io::write_atomically;
use lcpbatch::world::format::{parse_worlds, worlds_to_json};
use lcpbatch::world::generate::{standard_world, WorldKind};
use lcpbatch::{Error, Settings, Solver, StepReport, World};
use plotters::prelude::*;

use super::{BackendArg, FrictionSolverArg, GpuArgs};

/// `simulate`'s default friction tolerance (see `--friction-tolerance`).
pub const WORLD_FRICTION_TOLERANCE: f64 = 1e-12;

/// Options of `lcpbatch simulate`.
#[derive(clap::Args)]
pub struct SimulateArgs {
    /// Worlds stepped together.
    #[arg(long, default_value_t = 100)]
    worlds: usize,
    /// Steps.
    #[arg(long, default_value_t = 500)]
    steps: usize,
    /// Time step (s).
    #[arg(long, default_value_t = 0.01)]
    dt: f64,
    /// A standard world `KIND[:SIZE]` (spheres, stack, pyramid, slide,
    /// incline, rain; world k uses seed + k) or a world file (.json; its
    /// worlds repeated up to --worlds).
    #[arg(long, default_value = "stack:4")]
    world: String,
    /// Seed of the generated worlds.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Where to solve.
    #[arg(long, value_enum, default_value = "cpu")]
    backend: BackendArg,
    /// Solver of frictional islands (pairs with μ = √(μ_a μ_b) > 0).
    #[arg(long, value_enum, default_value = "auto")]
    friction_solver: FrictionSolverArg,
    /// A frictional island is `solved` when its Coulomb error is at most
    /// this. Finer than `solve`'s 1e-8 by default: the error is relative to
    /// the island's largest impulse, and 1e-8 leaves heavy resting boxes
    /// (1000 kg) with velocities of about 1e-6 m/s; 1e-12 keeps a sliding
    /// box on the ground (|v_n| ≤ 1e-9 m/s) and stacks at rest.
    #[arg(long, default_value_t = WORLD_FRICTION_TOLERANCE)]
    friction_tolerance: f64,
    /// Set every body's friction coefficient μ (0: frictionless worlds, the
    /// LCP path; GPU-capable).
    #[arg(long)]
    friction: Option<f64>,
    /// Put bodies to sleep after this many quiet steps (0: never; overrides
    /// the worlds' own setting when given).
    #[arg(long)]
    sleep: Option<u32>,
    /// Output directory (created).
    #[arg(long, default_value = "simulate-out")]
    out: PathBuf,
    #[command(flatten)]
    gpu: GpuArgs,
}

/// One line of `steps.jsonl`: the step's figures over every world.
#[derive(serde::Serialize)]
struct StepLine {
    step: usize,
    time: f64,
    kinetic: f64,
    potential: f64,
    max_penetration: f64,
    contacts: usize,
    islands: usize,
    max_error: f64,
    awake: usize,
    unsolved: usize,
    /// What the unsolved islands got instead: exact frictionless impulses,
    /// PGS's approximate ones, none.
    repaired_exact: usize,
    repaired_approximate: usize,
    repaired_dropped: usize,
    collision_s: f64,
    solve_s: f64,
    /// Within solve_s (the door's timings): checks, islands and assembly.
    assembly_s: f64,
    /// Within solve_s: prediction, GPU, validation and CPU solves.
    lcp_s: f64,
    /// Within solve_s: velocities after the impulses.
    impulses_s: f64,
    integrate_s: f64,
}

impl StepLine {
    fn of(step: usize, time: f64, r: &StepReport) -> Self {
        let w = &r.worlds;
        StepLine {
            step,
            time,
            kinetic: w.iter().map(|x| x.kinetic).sum(),
            potential: w.iter().map(|x| x.potential).sum(),
            max_penetration: w.iter().map(|x| x.max_penetration).fold(0.0, f64::max),
            contacts: w.iter().map(|x| x.contacts).sum(),
            islands: w.iter().map(|x| x.islands).sum(),
            max_error: w.iter().map(|x| x.max_error).fold(0.0, f64::max),
            awake: w.iter().map(|x| x.awake).sum(),
            unsolved: r.unsolved,
            repaired_exact: r.repairs.exact,
            repaired_approximate: r.repairs.approximate,
            repaired_dropped: r.repairs.dropped,
            collision_s: r.timings.collision,
            solve_s: r.timings.solve,
            assembly_s: r.solve.timings.build,
            lcp_s: r.solve.timings.prediction
                + r.solve.timings.gpu
                + r.solve.timings.validation
                + r.solve.timings.solve,
            impulses_s: r.solve.timings.impulses,
            integrate_s: r.timings.integrate,
        }
    }
}

/// The worlds `--world` names, `count` of them.
pub fn load_worlds(spec: &str, count: usize, seed: u64) -> Result<Vec<World>, Error> {
    if count == 0 {
        return Err(Error::invalid("--worlds", "count", "must be at least 1"));
    }
    let path = Path::new(spec);
    if spec.ends_with(".json") || path.is_file() {
        let text = std::fs::read_to_string(path).map_err(|source| Error::Io {
            path: path.to_path_buf(),
            source,
        })?;
        let from_file = parse_worlds(spec, &text)?;
        return Ok((0..count)
            .map(|k| from_file[k % from_file.len()].clone())
            .collect());
    }
    let (kind, size) = WorldKind::parse("--world", spec)?;
    Ok((0..count)
        .map(|k| standard_world(kind, size, seed.wrapping_add(k as u64)))
        .collect())
}

/// Runs `lcpbatch simulate`.
pub fn simulate_command(args: SimulateArgs) -> Result<(), Error> {
    if !args.dt.is_finite() || args.dt <= 0.0 {
        return Err(Error::invalid(
            "--dt",
            "dt",
            format!("{} is not a positive number", args.dt),
        ));
    }
    if args.steps == 0 {
        return Err(Error::invalid("--steps", "steps", "must be at least 1"));
    }
    let mut worlds = load_worlds(&args.world, args.worlds, args.seed)?;
    if let Some(n) = args.sleep {
        worlds.iter_mut().for_each(|w| w.sleep.steps = n);
    }
    if let Some(mu) = args.friction {
        if !mu.is_finite() || mu < 0.0 {
            return Err(Error::invalid(
                "--friction",
                "friction",
                format!("{mu} is not a number ≥ 0"),
            ));
        }
        for b in worlds.iter_mut().flat_map(|w| w.bodies.iter_mut()) {
            b.friction = mu;
        }
    }
    let mut solver = Solver::new(Settings {
        backend: args.backend.backend(),
        gpu: args.gpu.settings()?,
        warm_start: true,
        friction_method: args.friction_solver.method(),
        friction_tolerance: args.friction_tolerance,
        ..Settings::default()
    })?;
    println!("device: {} ({})", solver.device().name, solver.choice());
    step_and_write(&mut solver, &mut worlds, args.steps, args.dt, &args.out)
}

/// Steps `worlds` `steps` times through the solver's door with a progress
/// bar, then writes steps.jsonl, final.json and the plots to `out` and
/// prints the summary (`simulate` and `demo`).
pub fn step_and_write(
    solver: &mut Solver,
    worlds: &mut [World],
    steps: usize,
    dt: f64,
    out: &Path,
) -> Result<(), Error> {
    let bar = indicatif::ProgressBar::new(steps as u64);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{elapsed_precise} [{bar:30}] {pos}/{len} {msg}")
            .expect("valid template"),
    );
    let mut lines = Vec::with_capacity(steps);
    let start = Instant::now();
    for step in 0..steps {
        let r = solver.step_worlds(worlds, dt)?;
        let line = StepLine::of(step, (step + 1) as f64 * dt, &r);
        bar.set_message(format!(
            "{} contacts, {} islands",
            line.contacts, line.islands
        ));
        bar.inc(1);
        lines.push(line);
    }
    let wall = start.elapsed().as_secs_f64();
    bar.finish_and_clear();
    write_outputs(out, &lines, worlds)?;
    print_summary(&lines, worlds.len(), wall);
    println!("wrote {}", out.display());
    Ok(())
}

/// Totals and the slowest phase, on stdout.
fn print_summary(lines: &[StepLine], worlds: usize, wall: f64) {
    let sum = |f: fn(&StepLine) -> f64| lines.iter().map(f).sum::<f64>();
    let phases = [
        ("collision", sum(|l| l.collision_s)),
        ("assembly+solve", sum(|l| l.solve_s)),
        ("integrate", sum(|l| l.integrate_s)),
    ];
    let door = [
        ("checks+assembly", sum(|l| l.assembly_s)),
        ("LCP solve", sum(|l| l.lcp_s)),
        ("impulses", sum(|l| l.impulses_s)),
    ];
    let rate = (worlds * lines.len()) as f64 / wall;
    println!(
        "{} worlds x {} steps in {wall:.3} s: {rate:.0} world-steps/s",
        worlds,
        lines.len()
    );
    for (name, t) in phases {
        println!("  {name:>15}: {t:.3} s ({:.1}%)", 100.0 * t / wall);
    }
    for (name, t) in door {
        println!("    {name:>15}: {t:.3} s ({:.1}%)", 100.0 * t / wall);
    }
    let slowest = phases
        .iter()
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .expect("3 phases");
    let last = lines.last().expect("at least one step");
    println!(
        "  slowest phase: {}; last step: energy {:.6e} J, max penetration {:.3e} m, max error {:.3e}, unsolved islands {} (repaired: {} exactly without friction, {} by PGS, {} without impulse)",
        slowest.0,
        last.kinetic + last.potential,
        last.max_penetration,
        last.max_error,
        lines.iter().map(|l| l.unsolved).sum::<usize>(),
        lines.iter().map(|l| l.repaired_exact).sum::<usize>(),
        lines.iter().map(|l| l.repaired_approximate).sum::<usize>(),
        lines.iter().map(|l| l.repaired_dropped).sum::<usize>(),
    );
}

/// steps.jsonl, final.json and the plots, each written atomically.
fn write_outputs(out: &Path, lines: &[StepLine], worlds: &[World]) -> Result<(), Error> {
    std::fs::create_dir_all(out).map_err(|source| Error::Io {
        path: out.to_path_buf(),
        source,
    })?;
    let mut jsonl = String::new();
    for l in lines {
        jsonl.push_str(&serde_json::to_string(l).expect("a step line serialises"));
        jsonl.push('\n');
    }
    write_atomically(&out.join("steps.jsonl"), &jsonl)?;
    write_atomically(&out.join("final.json"), &worlds_to_json(worlds))?;
    let t = |f: fn(&StepLine) -> f64| -> Vec<(f64, f64)> {
        lines.iter().map(|l| (l.time, f(l))).collect()
    };
    let plots: [(&str, &str, Vec<Series>); 4] = [
        (
            "energy.svg",
            "energy (J)",
            vec![
                ("kinetic", t(|l| l.kinetic)),
                ("potential", t(|l| l.potential)),
                ("total", t(|l| l.kinetic + l.potential)),
            ],
        ),
        (
            "penetration.svg",
            "max penetration (m)",
            vec![("max penetration", t(|l| l.max_penetration))],
        ),
        (
            "error.svg",
            "max solver error",
            vec![("max error", t(|l| l.max_error))],
        ),
        (
            "time.svg",
            "seconds per step",
            vec![
                ("collision", t(|l| l.collision_s)),
                ("assembly+solve", t(|l| l.solve_s)),
                ("integrate", t(|l| l.integrate_s)),
            ],
        ),
    ];
    for (file, y_desc, series) in plots {
        let tmp = out.join(format!(".{file}.tmp{}", std::process::id()));
        let done = line_plot(&tmp, y_desc, &series).and_then(|()| {
            std::fs::rename(&tmp, out.join(file)).map_err(|source| Error::Io {
                path: out.join(file),
                source,
            })
        });
        if done.is_err() {
            let _ = std::fs::remove_file(&tmp);
        }
        done?;
    }
    Ok(())
}

/// One labelled line: (simulated time, value) points.
type Series<'a> = (&'a str, Vec<(f64, f64)>);

/// Lines of y against simulated time (linear axes).
fn line_plot(path: &Path, y_desc: &str, series: &[Series]) -> Result<(), Error> {
    let err = |e: String| Error::Io {
        path: path.to_path_buf(),
        source: std::io::Error::other(e),
    };
    let pts = || series.iter().flat_map(|s| s.1.iter());
    let (x0, x1) = pts().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
        (a.min(p.0), b.max(p.0))
    });
    let (mut y0, mut y1) = pts()
        .filter(|p| p.1.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.1), b.max(p.1))
        });
    if !(y0.is_finite() && y1.is_finite()) {
        (y0, y1) = (0.0, 1.0);
    }
    let pad = ((y1 - y0) * 0.05).max(1e-12 * y1.abs().max(1.0));
    let root = SVGBackend::new(path, (900, 500)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(e.to_string()))?;
    let mut chart = ChartBuilder::on(&root)
        .margin(15)
        .x_label_area_size(40)
        .y_label_area_size(90)
        .build_cartesian_2d(x0..x1.max(x0 + 1e-9), (y0 - pad)..(y1 + pad))
        .map_err(|e| err(e.to_string()))?;
    chart
        .configure_mesh()
        .x_desc("simulated time (s)")
        .y_desc(y_desc)
        .y_label_formatter(&|v| format!("{v:.3e}"))
        .draw()
        .map_err(|e| err(e.to_string()))?;
    let colors = [RED, BLUE, BLACK];
    for (k, (label, p)) in series.iter().enumerate() {
        let c = colors[k % colors.len()];
        chart
            .draw_series(LineSeries::new(p.iter().copied(), c.stroke_width(2)))
            .map_err(|e| err(e.to_string()))?
            .label(*label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(|e| err(e.to_string()))?;
    root.present().map_err(|e| err(e.to_string()))
}
