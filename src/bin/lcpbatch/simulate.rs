//! `lcpbatch simulate`: many worlds stepped in time through
//! `Solver::step_worlds_framed`, the states of the film's worlds read back
//! only where it takes a frame, every state after the last step. Writes into `--out`:
//! `steps.jsonl` (one line per step, aggregated over the worlds), `final.json`
//! (the worlds' final states, readable by `--world`), SVG plots of energy,
//! penetration, solver error and time per step, and pictures of a few worlds
//! (`worlds.svg`, side views at a few times; `worlds-animated.svg`, in
//! motion). Every file is written atomically after the last step, so a
//! failure leaves none half-written.

use std::path::{Path, PathBuf};
use std::time::Instant;

use super::pictures::Film;
use super::plots::{time_panels, Curve, Panel, COLORS};
use super::{BackendArg, FrictionSolverArg, GpuArgs};
use lcpbatch::io::write_atomically;
use lcpbatch::world::format::{parse_worlds, worlds_to_json};
use lcpbatch::world::generate::{standard_world, WorldKind};
use lcpbatch::world::ResidentStep;
use lcpbatch::{Error, Frames, Settings, Solver, StepReport, World};
use plotters::style::BLACK;

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
    /// Bounces resolved at their time of impact within the step, and those
    /// left to the step when its bound on impacts was reached.
    impacts: usize,
    impacts_deferred: usize,
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
            impacts: w.iter().map(|x| x.impacts).sum(),
            impacts_deferred: w.iter().map(|x| x.impacts_deferred).sum(),
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
        ..crate::settings()
    })?;
    println!("device: {} ({})", solver.device().name, solver.choice());
    let groups = [(args.world.clone(), worlds.len())];
    step_and_write(
        &mut solver,
        &mut worlds,
        &groups,
        args.steps,
        args.dt,
        &args.out,
    )
}

/// Steps `worlds` `steps` times through the solver's door with a progress
/// bar, then writes steps.jsonl, final.json, the plots and the pictures of
/// the worlds to `out` and prints the summary (`simulate` and `demo`).
/// `groups` names the worlds in order: (kind or file, how many).
pub fn step_and_write(
    solver: &mut Solver,
    worlds: &mut [World],
    groups: &[(String, usize)],
    steps: usize,
    dt: f64,
    out: &Path,
) -> Result<(), Error> {
    let bar = indicatif::ProgressBar::new(steps as u64);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{elapsed_precise} [{bar:30}] {pos}/{len} {msg}")
            .expect("valid template"),
    );
    let shown = shown_worlds(worlds, groups);
    let ks: Vec<usize> = shown.iter().map(|s| s.0).collect();
    let mut film = Film::new(worlds, shown, steps, dt);
    let frame_steps: Vec<bool> = (0..=steps).map(|s| film.wants(s, steps)).collect();
    // The film's view of the batch: its shown worlds as the frames hand
    // them over (the others are not drawn).
    let mut view = worlds.to_vec();
    let mut lines = Vec::with_capacity(steps);
    let mut run = Run::new(worlds.len());
    let start = Instant::now();
    // Only the film's worlds' states come back where it takes a frame (on
    // the resident GPU path; every state once, after the last step).
    let frames = Frames {
        worlds: &ks,
        at: &|s| frame_steps[s],
    };
    let observe = |step: usize, r: StepReport| {
        let line = StepLine::of(step, (step + 1) as f64 * dt, &r);
        run.add(step, line.time, &r);
        bar.set_message(format!(
            "{} contacts, {} islands",
            line.contacts, line.islands
        ));
        bar.inc(1);
        lines.push(line);
    };
    let show = |s: usize, states: &[World]| {
        for (&k, w) in ks.iter().zip(states) {
            view[k].clone_from(w);
        }
        film.record(&view, s, steps, s as f64 * dt);
    };
    solver.step_worlds_framed(worlds, dt, steps, frames, observe, show)?;
    let wall = start.elapsed().as_secs_f64();
    bar.finish_and_clear();
    let title = title(solver, worlds, groups, steps, dt);
    write_outputs(out, &lines, worlds, &run, solver.settings(), &title)?;
    film.write(out, &title)?;
    print_summary(&lines, &run, worlds.len(), wall);
    // Where `--backend auto` stepped the worlds, with the estimates.
    if let Some(route) = run.route.as_ref().filter(|r| r.contains("; worlds: ")) {
        println!("  worlds stepped: {route}");
    }
    println!("wrote {}", out.display());
    Ok(())
}

/// What a plot's title says was simulated: the worlds (kind, count, μ),
/// the steps, and the device.
fn title(
    solver: &Solver,
    worlds: &[World],
    groups: &[(String, usize)],
    steps: usize,
    dt: f64,
) -> Vec<String> {
    let mut first = 0;
    let kinds: Vec<String> = groups
        .iter()
        .filter(|g| g.1 > 0)
        .map(|(name, n)| {
            let mu = worlds[first..first + n]
                .iter()
                .flat_map(|w| w.bodies.iter().map(|b| b.friction))
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), m| {
                    (a.min(m), b.max(m))
                });
            first += n;
            let mu = if mu.0 == mu.1 {
                format!("μ = {}", mu.0)
            } else {
                format!("μ {}–{}", mu.0, mu.1)
            };
            format!("{n} × {name} ({mu})")
        })
        .collect();
    vec![
        format!("{}: {steps} steps of {} ms", kinds.join(" + "), dt * 1e3),
        format!("solved on {}", solver.device().name),
    ]
}

/// The worlds the pictures show (with their labels): the first of each
/// group, or of a single group the first, middle and last where they
/// differ at the start; three at most.
fn shown_worlds(worlds: &[World], groups: &[(String, usize)]) -> Vec<(usize, String)> {
    let mut shown: Vec<(usize, String)> = Vec::new();
    let mut first = 0;
    for (name, n) in groups.iter().filter(|g| g.1 > 0) {
        let picks = if groups.len() == 1 {
            vec![first, first + n / 2, first + n - 1]
        } else {
            vec![first]
        };
        for k in picks {
            let same = shown.iter().any(|s| worlds[s.0] == worlds[k]);
            if !same && shown.len() < 3 {
                shown.push((k, format!("world {k}: {name}")));
            }
        }
        first += n;
    }
    shown
}

/// Figures over the whole run that steps.jsonl does not hold per world.
struct Run {
    /// Deepest penetration, its world and step.
    deepest: (f64, usize, usize),
    /// Frictional islands over all steps.
    frictional: usize,
    /// Frictional islands left unsolved (repaired without friction), per
    /// world.
    friction_dropped: Vec<usize>,
    /// (time, largest error) of the frictionless islands, of the
    /// frictional ones (Coulomb error), at the steps that had them.
    errors: [Vec<(f64, f64)>; 2],
    /// The resident GPU path's figures summed over its steps (None when no
    /// step took it).
    resident: Option<ResidentStep>,
    /// The first step's choice (`--backend auto`: where the worlds went
    /// and the cost model's estimates).
    route: Option<String>,
}

impl Run {
    fn new(worlds: usize) -> Self {
        Run {
            deepest: (0.0, 0, 0),
            frictional: 0,
            friction_dropped: vec![0; worlds],
            errors: [Vec::new(), Vec::new()],
            resident: None,
            route: None,
        }
    }

    fn add(&mut self, step: usize, time: f64, r: &StepReport) {
        self.route.get_or_insert_with(|| r.solve.choice.clone());
        if let Some(f) = &r.resident {
            (self.resident.get_or_insert_with(ResidentStep::default)).add(f);
        }
        let errors = [r.solve.max_error, r.solve.max_coulomb_error];
        for (line, e) in self.errors.iter_mut().zip(errors) {
            line.extend(e.map(|(e, _)| (time, e)));
        }
        for (k, w) in r.worlds.iter().enumerate() {
            if w.max_penetration > self.deepest.0 {
                self.deepest = (w.max_penetration, k, step);
            }
        }
        self.frictional += r.solve.friction.len();
        for isl in r
            .solve
            .friction
            .iter()
            .filter(|i| !i.status().is_solution())
        {
            if let Some(k) = isl.scene {
                self.friction_dropped[k] += 1;
            }
        }
    }
}

/// Totals, phases as a tree and the last step's figures, on stdout; a
/// warning where friction was dropped.
fn print_summary(lines: &[StepLine], run: &Run, worlds: usize, wall: f64) {
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
    println!("  phases (seconds over the run, share of the wall time):");
    for (name, t) in phases {
        println!("    {name}: {t:.3} s ({:.1}%)", 100.0 * t / wall);
        if name == "assembly+solve" {
            for (name, t) in door {
                println!("      {name}: {t:.3} s ({:.1}%)", 100.0 * t / wall);
            }
        }
    }
    let slowest = phases
        .iter()
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .expect("3 phases");
    println!("  slowest phase: {}", slowest.0);
    let last = lines.last().expect("at least one step");
    println!(
        "  last step (t = {:.3} s): energy {:.6e} J (kinetic {:.3e} J), max penetration {:.3e} m, max error {:.3e}",
        last.time,
        last.kinetic + last.potential,
        last.kinetic,
        last.max_penetration,
        last.max_error,
    );
    let total = |f: fn(&StepLine) -> usize| lines.iter().map(f).sum::<usize>();
    let deepest = match run.deepest {
        (d, world, step) if d > 0.0 => format!("{d:.3e} m (world {world}, step {step})"),
        _ => "0 m".to_string(),
    };
    println!(
        "  over all {} steps: deepest penetration {deepest}, max error {:.3e}, unsolved islands {} (repaired: {} exactly without friction, {} by PGS, {} without impulse)",
        lines.len(),
        lines.iter().map(|l| l.max_error).fold(0.0, f64::max),
        total(|l| l.unsolved),
        total(|l| l.repaired_exact),
        total(|l| l.repaired_approximate),
        total(|l| l.repaired_dropped),
    );
    if let Some(f) = &run.resident {
        println!(
            "  resident on the GPU: {} world-steps on the device, {} on the CPU (flagged: contacts full {}, island above 16 contacts {}, not solved {}, non-finite {}, loop budget {}); {} bytes up per batch, {} back per step (mean), up to {} steps a submission",
            f.on_device,
            f.on_cpu,
            f.contacts_full,
            f.island_too_large,
            f.not_solved,
            f.non_finite,
            f.budget,
            f.bytes_up,
            f.bytes_back / lines.len() as u64,
            f.submission_steps,
        );
    }
    let dropped: usize = run.friction_dropped.iter().sum();
    if dropped > 0 {
        let (worst, most) = run
            .friction_dropped
            .iter()
            .enumerate()
            .max_by_key(|&(k, n)| (*n, std::cmp::Reverse(k)))
            .expect("a world");
        eprintln!(
            "warning: friction dropped on {dropped} of {} frictional islands ({:.2}%): the friction solver left them unsolved, and each was solved without friction for that step; most in world {worst} ({most})",
            run.frictional,
            100.0 * dropped as f64 / run.frictional.max(1) as f64
        );
    }
}

/// steps.jsonl, final.json and the plots, each written atomically.
fn write_outputs(
    out: &Path,
    lines: &[StepLine],
    worlds: &[World],
    run: &Run,
    settings: &Settings,
    title: &[String],
) -> Result<(), Error> {
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
    let t = |name: &str, f: fn(&StepLine) -> f64| -> Curve {
        (
            name.to_string(),
            lines.iter().map(|l| (l.time, f(l))).collect(),
        )
    };
    let linear = |y_desc: &str, series: Vec<Curve>| Panel {
        y_desc: y_desc.to_string(),
        series,
        floor: None,
        marks: Vec::new(),
    };
    // The frictionless islands' LCP error and the frictional ones' Coulomb
    // error, each with its tolerance, where the run had such islands.
    let mut errors = Vec::new();
    let mut tolerances = Vec::new();
    let kinds = [
        (
            "frictionless islands (LCP)",
            "LCP tolerance",
            settings.tolerance,
        ),
        (
            "frictional islands (Coulomb)",
            "friction tolerance",
            settings.friction_tolerance,
        ),
    ];
    for ((name, tol_name, tol), pts) in kinds.into_iter().zip(&run.errors) {
        if !pts.is_empty() {
            let color = COLORS[errors.len()];
            errors.push((name.to_string(), pts.clone()));
            tolerances.push((format!("{tol_name} {tol:.0e}"), tol, color));
        }
    }
    let plots: [(&str, Vec<Panel>); 4] = [
        (
            "energy.svg",
            vec![
                linear(
                    "energy (J)",
                    vec![
                        t("total", |l| l.kinetic + l.potential),
                        t("potential", |l| l.potential),
                    ],
                ),
                linear("kinetic energy (J)", vec![t("kinetic", |l| l.kinetic)]),
            ],
        ),
        (
            "penetration.svg",
            vec![Panel {
                floor: Some((
                    1e-12,
                    "rounding floor 1e-12 m (less is drawn on it)".to_string(),
                )),
                marks: vec![("1 mm".to_string(), 1e-3, BLACK)],
                ..linear(
                    "deepest penetration (m)",
                    vec![t("deepest of any world", |l| l.max_penetration)],
                )
            }],
        ),
        (
            "error.svg",
            vec![Panel {
                floor: Some((
                    f64::EPSILON,
                    "rounding floor: f64 ε (less is drawn on it)".to_string(),
                )),
                marks: tolerances,
                ..linear("largest error of an island", errors)
            }],
        ),
        (
            "time.svg",
            vec![linear(
                "milliseconds per step",
                vec![
                    t("collision", |l| 1e3 * l.collision_s),
                    t("assembly+solve", |l| 1e3 * l.solve_s),
                    t("integrate", |l| 1e3 * l.integrate_s),
                ],
            )],
        ),
    ];
    for (file, panels) in plots {
        let tmp = out.join(format!(".{file}.tmp{}", std::process::id()));
        let done = time_panels(&tmp, title, &panels).and_then(|()| {
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
