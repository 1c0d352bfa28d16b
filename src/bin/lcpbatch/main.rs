//! The `lcpbatch` command line: a client of the library's public API
//! (`Solver`, `Settings`, `Report`, the formats in `lcpbatch::io`).

mod bench;
mod bench_friction;
mod bench_table;
mod demo;
mod devices;
mod generate;
mod pictures;
mod plots;
mod simulate;
mod stress;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};

use lcpbatch::device::list_adapters;
use lcpbatch::io::friction::FrictionBatchOutput;
use lcpbatch::io::{read_input, write_atomically, Input, LcpBatchOutput, ScenesOutput};
use lcpbatch::{
    Backend, BackendChoice, Error, FrictionMethod, GpuSettings, Method, Precision, Settings, Solver,
};

#[derive(Parser)]
#[command(
    name = "lcpbatch",
    version,
    about = "Batched rigid-body contact LCPs, solved exactly"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// CPU threads for the commands that use cores (default: every core
    /// the OS reports; the benches' one-thread rows stay at one).
    #[arg(long, global = true, value_name = "N")]
    threads: Option<usize>,
}

/// `--threads`, set once before the command runs (0: every core).
static THREADS: std::sync::OnceLock<usize> = std::sync::OnceLock::new();

/// The library's defaults with `--threads`: what every command starts from.
pub(crate) fn settings() -> Settings {
    Settings {
        threads: THREADS.get().copied().unwrap_or(0),
        ..Settings::default()
    }
}

#[derive(Clone, Copy, ValueEnum)]
enum SolverArg {
    /// The fastest exact path: prediction, Lemke checked in f64, enumeration
    /// where the check fails (on the GPU: Lemke's path per island, each
    /// basis checked in f64 on the CPU).
    Auto,
    Enum,
    Lemke,
    Pgs,
}

/// How islands and problems with friction (Coulomb) are solved, on the
/// CPU in f64; each is judged by its Coulomb error.
#[derive(Clone, Copy, ValueEnum)]
pub(crate) enum FrictionSolverArg {
    /// NSGS sweeps, then Alart–Curnier Newton polishing to the rounding of f64
    /// (PROX where both stall).
    Auto,
    /// Non-smooth Gauss–Seidel over contacts, each solved exactly.
    Nsgs,
    /// Alart–Curnier semismooth Newton with line search alone.
    Newton,
    /// The proximal-point iteration (Newton on W + αI around the last
    /// iterate, α adapted): large piles where Newton alone stalls.
    Prox,
    /// Projected Jacobi sweeps on the cone complementarity model (GPU with
    /// --backend gpu), judged by that model's residual.
    Jacobi,
    /// Projected Gauss–Seidel sweeps on the cone complementarity model.
    Pgs,
    /// Accelerated projected gradient (APGD) on the cone complementarity model.
    Apgd,
}

impl FrictionSolverArg {
    pub(crate) fn method(self) -> FrictionMethod {
        parsed(&self)
    }
}

/// The library's value that an argument names: its command-line spelling
/// read by the library's `FromStr` (the inverse of its `name()`), so that
/// the CLI's names and the library's are one table. Every spelling parses
/// (`every_argument_value_is_a_library_name`).
fn parsed<T: std::str::FromStr<Err = Error>>(arg: &impl ValueEnum) -> T {
    let value = arg.to_possible_value().expect("no value is skipped");
    value
        .get_name()
        .parse()
        .unwrap_or_else(|e| unreachable!("{e}"))
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum BackendArg {
    /// Where a hardware adapter exists (or --adapter names one): each batch
    /// where a cost model of this machine (measured once, cached; `info`
    /// shows it) estimates it faster, frictional islands on the CPU; else the
    /// CPU (an unnamed software adapter is never opened: it is slower than
    /// the CPU path on every batch measured).
    Auto,
    /// The GPU for every batch, software adapters included, every answer
    /// checked on the CPU in f64; device trouble solves on the CPU instead.
    Gpu,
    /// The f64 path over every core.
    Cpu,
}

#[derive(Clone, Copy, ValueEnum)]
enum PrecisionArg {
    /// f64 where the adapter has SHADER_F64, else f32.
    Auto,
    F32,
    F64,
}

/// Adapter choice, shared by `solve`, `demo` and `info`.
#[derive(clap::Args, Clone)]
struct GpuArgs {
    /// Only adapters whose name contains this (case-insensitive); also
    /// LCPBATCH_GPU_ADAPTER.
    #[arg(long)]
    adapter: Option<String>,
    /// wgpu backend to look on: auto, vulkan, gl, metal, dx12; also
    /// LCPBATCH_GPU_BACKEND.
    #[arg(long = "gpu-backend")]
    gpu_backend: Option<String>,
    /// Shader precision; also LCPBATCH_GPU_PRECISION.
    #[arg(long, value_enum)]
    precision: Option<PrecisionArg>,
}

impl GpuArgs {
    /// Environment first, flags over it.
    fn settings(&self) -> Result<GpuSettings, Error> {
        let mut o = GpuSettings::from_env()?;
        if let Some(a) = &self.adapter {
            o.adapter = Some(a.clone());
        }
        if let Some(b) = &self.gpu_backend {
            o.api = BackendChoice::parse(b)?;
        }
        if let Some(p) = self.precision {
            o.precision = parsed::<Precision>(&p);
        }
        Ok(o)
    }
}

#[derive(Subcommand)]
enum Command {
    /// Solve a scene file, a many-scene file, an LCP or friction batch (JSON),
    /// or a Siconos .dat file (LCP or FrictionContact3D, told apart by its header).
    Solve(SolveArgs),
    /// The main job: generate thousands of islands from many simulation
    /// instances (balls and boxes on the ground and on each other), solve
    /// them on the path --backend chooses, validate every answer on the CPU
    /// in f64, compare with the other path; then step worlds in time and
    /// write the plots (as `simulate`).
    Demo {
        /// Simulation instances (each a few balls, boxes and stacks).
        #[arg(long, default_value_t = 1000)]
        worlds: usize,
        /// Seed of the generator.
        #[arg(long, default_value_t = 2026)]
        seed: u64,
        /// Where to solve.
        #[arg(long, value_enum, default_value = "auto")]
        backend: BackendArg,
        /// Steps of the worlds stepped in time (second part; 0 skips it).
        #[arg(long, default_value_t = 200)]
        steps: usize,
        /// Where the second part writes steps.jsonl, final.json and its plots.
        #[arg(long, default_value = "demo-out")]
        out: PathBuf,
        #[command(flatten)]
        gpu: GpuArgs,
    },
    /// Write fixed-seed scenes or LCP batches as JSON (what `solve` reads).
    Generate(GenerateArgs),
    /// List GPU adapters, backends, features (f64, subgroups, timestamps) and
    /// limits, say which adapter `solve --backend auto` would pick, and show
    /// the cost model by which auto chooses per batch (measured once and
    /// cached where a hardware adapter is, or one is named).
    Info {
        #[command(flatten)]
        gpu: GpuArgs,
        /// Measure the cost model again (on an idle machine) and cache it.
        #[arg(long)]
        calibrate: bool,
    },
    /// Every solver on the same fixed-seed batches (well conditioned, mass
    /// ratio 1e4, resting stacks, mixed n, warm-started resting): a table of
    /// islands/s against error, bench.json and SVG plots of time against
    /// error, against n and against batch size. With --friction: the
    /// friction solvers on frictional islands, islands/s against the
    /// Coulomb error.
    Bench(BenchArgs),
    /// Stress families (mass ratios to 1e8, length and velocity scales to
    /// 1e±3, near-parallel normals, resting stacks, chains to n = 16,
    /// non-P-matrix and infeasible LCPs, the Siconos problems scaled by 1e±6)
    /// through every solver and precision: error distribution, status agreement
    /// with f64 enumeration, repaired counts, stress.json and a plot of error
    /// against condition number.
    Stress(StressArgs),
    /// Step many rigid-body worlds in time (the velocity-level time stepping
    /// of Stewart–Trinkle and Anitescu–Potra, README "Simulating worlds"; one
    /// contact batch per step): progress, steps.jsonl, final.json and plots
    /// in --out.
    Simulate(simulate::SimulateArgs),
}

impl BackendArg {
    fn backend(self) -> Backend {
        parsed(&self)
    }
}

#[derive(clap::Args)]
struct SolveArgs {
    /// Input file (.json or .dat).
    file: PathBuf,
    /// Method for every problem or island without friction.
    #[arg(
        long = "method",
        visible_alias = "solver",
        value_enum,
        default_value = "auto"
    )]
    solver: SolverArg,
    /// Method for every problem or island with friction (contacts with
    /// μ > 0, friction batches, FrictionContact3D files).
    #[arg(
        long = "friction-method",
        visible_alias = "friction-solver",
        value_enum,
        default_value = "auto"
    )]
    friction_solver: FrictionSolverArg,
    /// A frictional island is `solved` when its Coulomb error is at most this.
    #[arg(long, default_value_t = 1e-8)]
    friction_tolerance: f64,
    /// Enumeration only: visit every basis and report every solution.
    #[arg(long)]
    all_solutions: bool,
    /// Write the result here (atomically) instead of to stdout.
    #[arg(short = 'o', long = "output")]
    output: Option<PathBuf>,
    /// Where to solve.
    #[arg(long, value_enum, default_value = "cpu")]
    backend: BackendArg,
    #[command(flatten)]
    gpu: GpuArgs,
}

#[derive(clap::Args)]
struct GenerateArgs {
    /// What to write.
    #[arg(long, value_enum)]
    kind: generate::Kind,
    /// Scenes, or LCPs (per family for stress-lcps).
    #[arg(long, default_value_t = 100)]
    count: usize,
    /// Seed of the generator (the same seed gives the same file).
    #[arg(long, default_value_t = 2026)]
    seed: u64,
    /// The benchmark family of family-lcps.
    #[arg(long, value_enum, default_value = "mixed-n")]
    family: generate::FamilyArg,
    /// Write here (atomically) instead of to stdout.
    #[arg(short = 'o', long = "output")]
    output: Option<PathBuf>,
}

#[derive(clap::Args)]
struct BenchArgs {
    /// Islands per family (default 20,000); with --friction, per set of
    /// k ≤ 4 contacts, a fifth of it above (default 2,000).
    #[arg(long)]
    islands: Option<usize>,
    /// The friction solvers instead of the LCP ones: boxes resting and
    /// sliding, stacks and random spheres of --sizes contacts, every method
    /// on the CPU and the projected ones on the GPU too; friction.json and
    /// friction_time_vs_error.svg.
    #[arg(long)]
    friction: bool,
    /// With --friction: contacts per island, one set per family that has them.
    #[arg(long, value_delimiter = ',', default_value = "1,2,4,8,16")]
    sizes: Vec<usize>,
    /// With --friction: timed runs of every row; its time is their median
    /// (the rows of a set take turns, run by run).
    #[arg(long, default_value_t = 5)]
    runs: usize,
    /// With --friction: instead of the generated islands, every Siconos
    /// FrictionContact3D .dat file of this folder (e.g.
    /// ../shared/conformance/siconos-fc3d-large), auto, nsgs and prox on one
    /// thread, wall and CPU seconds of the solve call; friction_fc3d.json.
    #[arg(long, value_name = "DIR")]
    fc3d_dir: Option<PathBuf>,
    /// Islands per n for the time-against-n curves.
    #[arg(long, default_value_t = 500)]
    per_n: usize,
    /// Batch sizes for the time-against-batch-size curves.
    #[arg(long, value_delimiter = ',', default_value = "1000,10000,100000")]
    batch_sizes: Vec<usize>,
    #[arg(long, default_value_t = 2026)]
    seed: u64,
    /// Folder for bench.json and the plots.
    #[arg(long, default_value = "bench-out")]
    out: PathBuf,
    /// CPU only, even where an adapter exists.
    #[arg(long)]
    cpu_only: bool,
    #[command(flatten)]
    gpu: GpuArgs,
}

#[derive(clap::Args)]
struct StressArgs {
    /// Cases per family.
    #[arg(long, default_value_t = 500)]
    cases: usize,
    #[arg(long, default_value_t = 2026)]
    seed: u64,
    /// Folder of Siconos .dat files for the scaled family (default
    /// $LCPBATCH_CONFORMANCE/siconos or ../shared/conformance/siconos, if present).
    #[arg(long)]
    siconos: Option<PathBuf>,
    /// Solve M + αI instead of M (default 0: the problem as posed).
    #[arg(long, default_value_t = 0.0)]
    regularization: f64,
    /// Folder for stress.json and the plot.
    #[arg(long, default_value = "stress-out")]
    out: PathBuf,
    /// CPU only, even where an adapter exists.
    #[arg(long)]
    cpu_only: bool,
    #[command(flatten)]
    gpu: GpuArgs,
}

/// A solver on `backend` with the GPU flags; on device trouble (no
/// adapter, f64 asked of an adapter without it, a device lost in the middle
/// of a batch) it warns on stderr and solves on the CPU.
fn solver_for(backend: Backend, gpu: &GpuArgs, settings: Settings) -> Result<Solver, Error> {
    Solver::new(Settings {
        backend,
        gpu: gpu.settings()?,
        ..settings
    })
}

fn info(gpu: &GpuArgs, calibrate: bool) -> Result<(), Error> {
    let g = gpu.settings()?;
    let adapters = list_adapters(g.api);
    if adapters.is_empty() {
        println!(
            "no GPU adapter found: {}\nthe CPU path is used.",
            lcpbatch::device::INSTALL_HINT
        );
        return Ok(());
    }
    println!("adapters:");
    for a in &adapters {
        println!("{a}");
    }
    let mut auto = solver_for(Backend::Auto, gpu, settings())?;
    println!("backend auto: {} ({})", auto.device().name, auto.choice());
    if calibrate && auto.shared_device().is_some() {
        let model = auto.calibrate()?;
        let path = model.save()?;
        println!("measured again and cached in {}", path.display());
        print!("{model}");
    } else if let Some(model) = auto.cost_model() {
        print!("{model}");
    } else {
        println!(
            "no cost model: auto solves on the CPU (name an adapter with --adapter to measure one)"
        );
    }
    let named = solver_for(Backend::Gpu, gpu, settings())?;
    match named.fallback() {
        None => println!("backend gpu: {}", named.device().name),
        Some(why) => println!("backend gpu: none ({why}); the CPU path is used"),
    }
    Ok(())
}

fn generate_command(args: GenerateArgs) -> Result<(), Error> {
    let GenerateArgs {
        kind,
        count,
        seed,
        family,
        output,
    } = args;

    if count == 0 {
        return Err(Error::invalid("generate", "--count", "must be positive"));
    }
    let text = generate::text(kind, count, seed, family);
    match output {
        Some(path) => write_atomically(&path, &text),
        None => {
            println!("{text}");
            Ok(())
        }
    }
}

fn bench_command(args: BenchArgs) -> Result<(), Error> {
    let BenchArgs {
        islands,
        friction,
        sizes,
        runs,
        fc3d_dir,
        per_n,
        batch_sizes,
        seed,
        out,
        cpu_only,
        gpu,
    } = args;

    let gpu = if cpu_only {
        None
    } else {
        Some(gpu.settings()?)
    };
    if friction {
        let islands = islands.unwrap_or(2_000);
        if islands == 0 || sizes.is_empty() || sizes.contains(&0) || runs == 0 {
            return Err(Error::invalid(
                "bench --friction",
                "--islands/--sizes/--runs",
                "must be positive",
            ));
        }
        return bench_friction::run(&bench_friction::FrictionBenchOptions {
            islands,
            sizes,
            seed,
            out_dir: out,
            gpu,
            runs,
            fc3d: fc3d_dir,
        });
    }
    let islands = islands.unwrap_or(20_000);
    if islands == 0 || per_n == 0 || batch_sizes.contains(&0) {
        return Err(Error::invalid(
            "bench",
            "--islands/--per-n/--batch-sizes",
            "must be positive",
        ));
    }
    let opts = bench::BenchOptions {
        islands,
        seed,
        out_dir: out,
        gpu,
        per_n,
        batch_sizes,
    };
    bench::run(&opts).map(|_| ())
}

fn stress_command(args: StressArgs) -> Result<(), Error> {
    let StressArgs {
        cases,
        seed,
        siconos,
        regularization,
        out,
        cpu_only,
        gpu,
    } = args;

    if cases == 0 {
        return Err(Error::invalid("stress", "--cases", "must be positive"));
    }
    if !(regularization.is_finite() && regularization >= 0.0) {
        return Err(Error::invalid(
            "stress",
            "--regularization",
            "must be a finite number ≥ 0",
        ));
    }
    let siconos = siconos.or_else(|| {
        let base = std::env::var_os("LCPBATCH_CONFORMANCE")
            .map(PathBuf::from)
            .unwrap_or_else(|| PathBuf::from("../shared/conformance"));
        Some(base.join("siconos")).filter(|d| d.is_dir())
    });
    if siconos.is_none() {
        eprintln!("Siconos problems not found; the siconos_scaled family is skipped");
    }
    let opts = stress::StressOptions {
        cases,
        seed,
        siconos,
        out_dir: out,
        gpu: if cpu_only {
            None
        } else {
            Some(gpu.settings()?)
        },
        regularization,
    };
    stress::run(&opts).map(|_| ())
}

fn solve_command(args: SolveArgs) -> Result<(), Error> {
    let SolveArgs {
        file,
        solver,
        friction_solver,
        friction_tolerance,
        all_solutions,
        output,
        backend,
        gpu,
    } = args;

    let method: Method = parsed(&solver);
    if all_solutions && !matches!(method, Method::Auto | Method::Enumeration) {
        return Err(Error::Unsupported(
            "--all-solutions needs --solver auto or enum".into(),
        ));
    }
    // The GPU enumerates (with --all-solutions every basis) or runs Lemke's
    // path (auto, lemke); PGS runs on the CPU.
    let gpu_capable = matches!(method, Method::Auto | Method::Enumeration | Method::Lemke);
    if backend == BackendArg::Gpu && !gpu_capable {
        return Err(Error::Unsupported(
            "--backend gpu solves by enumeration or Lemke only (no --solver pgs)".into(),
        ));
    }
    let input = read_input(&file)?;
    let settings = Settings {
        method,
        all_solutions,
        friction_method: friction_solver.method(),
        friction_tolerance,
        ..settings()
    };
    let backend = if gpu_capable {
        backend.backend()
    } else {
        Backend::Cpu
    };
    let mut solver = solver_for(backend, &gpu, settings)?;
    let report = match &input {
        Input::Lcps(lcps) => solver.solve_lcps(lcps)?,
        Input::Scenes(scenes) => solver.solve_scenes(scenes)?,
        Input::Friction(problems) => solver.solve_friction(problems)?,
    };
    if report.on_gpu() {
        eprintln!("{report}");
    }
    let text = match input {
        Input::Lcps(_) => serde_json::to_string_pretty(&LcpBatchOutput::of(&report)),
        Input::Scenes(_) => serde_json::to_string_pretty(&ScenesOutput::of(&report)),
        Input::Friction(_) => serde_json::to_string_pretty(&FrictionBatchOutput::of(&report)),
    }
    .expect("serialisable");
    match output {
        Some(path) => write_atomically(&path, &text)?,
        None => println!("{text}"),
    }
    Ok(())
}

fn run(cli: Cli) -> Result<(), Error> {
    match cli.command {
        Command::Demo {
            worlds,
            seed,
            backend,
            steps,
            out,
            gpu,
        } => {
            demo::demo(worlds, seed, backend, &gpu)?;
            demo::demo_in_time(worlds / 2, steps, backend, &gpu, &out)
        }
        Command::Info { gpu, calibrate } => info(&gpu, calibrate),
        Command::Generate(args) => generate_command(args),
        Command::Bench(args) => bench_command(args),
        Command::Stress(args) => stress_command(args),
        Command::Solve(args) => solve_command(args),
        Command::Simulate(args) => simulate::simulate_command(args),
    }
}

/// Output into a pipe whose reader has gone (`lcpbatch solve … | head`)
/// ends the process quietly, as it does other Unix tools: Rust ignores
/// SIGPIPE, so `println!` would panic on the closed pipe instead.
fn exit_quietly_on_a_closed_pipe() {
    #[cfg(unix)]
    // SAFETY: restoring the default disposition of one signal at start-up,
    // before any other thread exists.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
}

/// Where XDG_RUNTIME_DIR is not set (a headless machine, root, a
/// container), Mesa's Wayland probe prints "error: XDG_RUNTIME_DIR is
/// invalid or not set" at every adapter enumeration; the tool then points
/// it at the temporary folder, which only quiets that probe (no Wayland
/// display is found there, as before).
fn quiet_the_headless_display_probe() {
    if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
        std::env::set_var("XDG_RUNTIME_DIR", std::env::temp_dir());
    }
}

fn main() -> ExitCode {
    exit_quietly_on_a_closed_pipe();
    quiet_the_headless_display_probe();
    let cli = Cli::parse();
    if let Some(n) = cli.threads {
        THREADS
            .set(n)
            .expect("--threads is set once, before any command runs");
    }
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every spelling the CLI accepts is the name of a library value.
    #[test]
    fn every_argument_value_is_a_library_name() {
        for a in SolverArg::value_variants() {
            let _: Method = parsed(a);
        }
        for a in FrictionSolverArg::value_variants() {
            let _: FrictionMethod = parsed(a);
        }
        for a in BackendArg::value_variants() {
            let _: Backend = parsed(a);
        }
        for a in PrecisionArg::value_variants() {
            let _: Precision = parsed(a);
        }
        assert_eq!(parsed::<Method>(&SolverArg::Enum), Method::Enumeration);
    }
}
