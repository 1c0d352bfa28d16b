//! The `lcpbatch` command line.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};

use lcpbatch::backend::{Backend, Session};
use lcpbatch::generate::{demo_world, Rng};
use lcpbatch::gpu::{list_adapters, BackendChoice, GpuContext, GpuOptions, Precision};
use lcpbatch::io::{
    read_input, write_atomically, Input, LcpBatchOutput, LcpOutput, SceneOutput, ScenesOutput,
};
use lcpbatch::lcp::Status;
use lcpbatch::pipeline::solve_scene;
use lcpbatch::{Error, Scene, Solver, SolverSettings};

#[derive(Parser)]
#[command(
    name = "lcpbatch",
    version,
    about = "Batched rigid-body contact LCPs, solved exactly"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Clone, Copy, ValueEnum)]
enum SolverArg {
    Enum,
    Lemke,
    Pgs,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum BackendArg {
    /// The GPU whenever an adapter exists, else the CPU.
    Auto,
    Gpu,
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
    fn options(&self) -> Result<GpuOptions, Error> {
        let mut o = GpuOptions::from_env()?;
        if let Some(a) = &self.adapter {
            o.adapter_name = Some(a.clone());
        }
        if let Some(b) = &self.gpu_backend {
            o.backend = BackendChoice::parse(b)?;
        }
        if let Some(p) = self.precision {
            o.precision = match p {
                PrecisionArg::Auto => Precision::Auto,
                PrecisionArg::F32 => Precision::F32,
                PrecisionArg::F64 => Precision::F64,
            };
        }
        Ok(o)
    }
}

#[derive(Subcommand)]
enum Command {
    /// Solve a scene file, a many-scene file, an LCP batch (JSON) or a Siconos .dat file.
    Solve {
        /// Input file (.json or .dat).
        file: PathBuf,
        /// Solver for every problem or island.
        #[arg(long, value_enum, default_value = "enum")]
        solver: SolverArg,
        /// Enumeration only: visit every basis and report every solution.
        #[arg(long)]
        all_solutions: bool,
        /// Write the result here (atomically) instead of to stdout.
        #[arg(short = 'o', long = "output")]
        output: Option<PathBuf>,
        /// Where to solve: auto (the GPU whenever an adapter exists), gpu, cpu.
        #[arg(long, value_enum, default_value = "cpu")]
        backend: BackendArg,
        #[command(flatten)]
        gpu: GpuArgs,
    },
    /// Generate thousands of islands from many simulation instances (balls
    /// and boxes on the ground and on each other), solve them on the best
    /// adapter, validate every answer on the CPU in f64, print a summary.
    Demo {
        /// Simulation instances (each a few balls, boxes and stacks).
        #[arg(long, default_value_t = 1000)]
        worlds: usize,
        /// Seed of the generator.
        #[arg(long, default_value_t = 2026)]
        seed: u64,
        /// Where to solve (auto: the GPU whenever an adapter exists).
        #[arg(long, value_enum, default_value = "auto")]
        backend: BackendArg,
        #[command(flatten)]
        gpu: GpuArgs,
    },
    /// List GPU adapters, backends, features (f64, subgroups, timestamps) and
    /// limits, and say which adapter `solve --backend auto` would pick.
    Info {
        #[command(flatten)]
        gpu: GpuArgs,
    },
    /// Every solver on the same fixed-seed batches (well conditioned, mass
    /// ratio 1e4, resting stacks, mixed n, warm-started resting): a table of
    /// islands/s against error, bench.json and SVG plots of time against
    /// error, against n and against batch size.
    Bench {
        /// Islands per family.
        #[arg(long, default_value_t = 20_000)]
        islands: usize,
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
    },
    /// Stress families (mass ratios to 1e8, length and velocity scales to
    /// 1e±3, near-parallel normals, resting stacks, chains to n = 16,
    /// non-P-matrix and infeasible LCPs, the Siconos problems scaled by 1e±6)
    /// through every solver and precision: error distribution, status agreement
    /// with f64 enumeration, repaired counts, stress.json and a plot of error
    /// against condition number.
    Stress {
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
    },
}

/// The backend for `backend`: on device trouble (no adapter, f64 asked of
/// an adapter without it, a device lost in the middle of a batch) the
/// session warns on stderr and solves on the CPU, for gpu and auto alike.
fn backend_for(backend: BackendArg, gpu: &GpuArgs) -> Result<Backend, Error> {
    Ok(match backend {
        BackendArg::Cpu => Backend::Cpu,
        BackendArg::Gpu => Backend::Gpu(gpu.options()?),
        BackendArg::Auto => Backend::Auto(gpu.options()?),
    })
}

fn demo(worlds: usize, seed: u64, backend: BackendArg, gpu: &GpuArgs) -> Result<(), Error> {
    let mut rng = Rng::new(seed);
    let scenes: Vec<Scene> = (0..worlds).map(|_| demo_world(&mut rng)).collect();
    let mut session = Session::new(&backend_for(backend, gpu)?)?;
    let contacts: usize = scenes.iter().map(|s| s.contacts.len()).sum();
    let settings = SolverSettings::default();
    if let Some(ctx) = session.context() {
        println!("adapter: {}", lcpbatch::backend::describe_context(ctx));
        // Warm-up, untimed: the first dispatch of a kernel compiles it (the
        // enumeration kernels are specialised per island size, and a
        // software adapter takes up to seconds each), so one world for each
        // island size of the batch goes first.
        let mut sizes = std::collections::BTreeSet::new();
        let mut warm_up = Vec::new();
        for s in &scenes {
            let (_, _, lcps) = lcpbatch::pipeline::build(s, "scene")?;
            if lcps.iter().any(|l| !sizes.contains(&l.n())) {
                sizes.extend(lcps.iter().map(|l| l.n()));
                warm_up.push(s.clone());
            }
        }
        session.solve_scenes(&warm_up, &settings)?;
    }
    let t = std::time::Instant::now();
    let r = session.solve_scenes(&scenes, &settings)?;
    let secs = t.elapsed().as_secs_f64();
    match &r.report.gpu {
        Some(report) => {
            let islands = report.islands;
            println!(
                "{worlds} simulation instances, {} bodies, {contacts} contacts, {islands} islands",
                scenes.iter().map(|s| s.bodies.len()).sum::<usize>()
            );
            println!("{report}");
            println!(
                "impulse stage: max deviation from f64 {:.2e}",
                r.report.max_velocity_deviation.unwrap_or(0.0)
            );
            println!(
                "throughput: {:.0} islands/s end to end ({:.3} s: assembly, enumeration, validation, impulses)",
                islands as f64 / secs,
                secs
            );
            let t = std::time::Instant::now();
            for (i, s) in scenes.iter().enumerate() {
                solve_scene(s, &settings, &format!("scene {i}"))?;
            }
            let cpu = t.elapsed().as_secs_f64();
            println!(
                "CPU path on the same batch (one thread, f64 enumeration): {:.0} islands/s ({cpu:.3} s)",
                islands as f64 / cpu
            );
        }
        None => {
            match session.fallback() {
                Some(why) => println!("adapter: none (CPU path; GPU trouble: {why})"),
                None => println!("adapter: none (CPU path)"),
            }
            let mut statuses = [0usize; 6];
            let (mut islands, mut max_error) = (0usize, 0.0f64);
            for isl in r.scenes.iter().flat_map(|s| &s.islands) {
                islands += 1;
                let k = Status::ALL
                    .iter()
                    .position(|&x| x == isl.solution.status)
                    .unwrap_or(5);
                statuses[k] += 1;
                if isl.solution.status.is_solution() {
                    max_error = max_error.max(isl.solution.residuals.error);
                }
            }
            let list: Vec<String> = Status::ALL
                .iter()
                .zip(statuses)
                .filter(|(_, c)| *c > 0)
                .map(|(s, c)| format!("{s} {c}"))
                .collect();
            println!("{worlds} simulation instances, {contacts} contacts, {islands} islands");
            println!("statuses: {}", list.join(", "));
            println!("max error: {max_error:.3e}");
            println!(
                "throughput: {:.0} islands/s ({secs:.3} s)",
                islands as f64 / secs
            );
        }
    }
    Ok(())
}

fn info(gpu: &GpuArgs) -> Result<(), Error> {
    let o = gpu.options()?;
    let adapters = list_adapters(o.backend);
    if adapters.is_empty() {
        println!(
            "no GPU adapter found: {}\nthe CPU path is used.",
            lcpbatch::gpu::INSTALL_HINT
        );
        return Ok(());
    }
    println!("adapters:");
    for a in &adapters {
        println!("{a}");
    }
    match GpuContext::new(&o) {
        Ok(ctx) => println!("chosen: {}", lcpbatch::backend::describe_context(&ctx)),
        Err(e) => println!("chosen: none ({e}); the CPU path is used"),
    }
    Ok(())
}

fn run(cli: Cli) -> Result<(), Error> {
    match cli.command {
        Command::Demo {
            worlds,
            seed,
            backend,
            gpu,
        } => demo(worlds, seed, backend, &gpu),
        Command::Info { gpu } => info(&gpu),
        Command::Bench {
            islands,
            per_n,
            batch_sizes,
            seed,
            out,
            cpu_only,
            gpu,
        } => {
            if islands == 0 || per_n == 0 || batch_sizes.contains(&0) {
                return Err(Error::invalid(
                    "bench",
                    "--islands/--per-n/--batch-sizes",
                    "must be positive",
                ));
            }
            let opts = lcpbatch::bench::BenchOptions {
                islands,
                seed,
                out_dir: out,
                gpu: if cpu_only { None } else { Some(gpu.options()?) },
                per_n,
                batch_sizes,
            };
            lcpbatch::bench::run(&opts).map(|_| ())
        }
        Command::Stress {
            cases,
            seed,
            siconos,
            regularization,
            out,
            cpu_only,
            gpu,
        } => {
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
            let opts = lcpbatch::stress::StressOptions {
                cases,
                seed,
                siconos,
                out_dir: out,
                gpu: if cpu_only { None } else { Some(gpu.options()?) },
                regularization,
            };
            lcpbatch::stress::run(&opts).map(|_| ())
        }
        Command::Solve {
            file,
            solver,
            all_solutions,
            output,
            backend,
            gpu,
        } => {
            let mut settings = SolverSettings::with_solver(match solver {
                SolverArg::Enum => Solver::Enum,
                SolverArg::Lemke => Solver::Lemke,
                SolverArg::Pgs => Solver::Pgs,
            });
            if all_solutions {
                if settings.solver != Solver::Enum {
                    return Err(Error::Unsupported(
                        "--all-solutions needs --solver enum".into(),
                    ));
                }
                settings.enumeration.all_solutions = true;
            }
            // The GPU enumerates; Lemke, PGS and --all-solutions run on the CPU.
            let gpu_capable = settings.solver == Solver::Enum && !all_solutions;
            if backend == BackendArg::Gpu && !gpu_capable {
                return Err(Error::Unsupported(
                    "--backend gpu solves by enumeration only (no --solver lemke/pgs, no --all-solutions)"
                        .into(),
                ));
            }
            let input = read_input(&file)?;
            let backend = if gpu_capable {
                backend_for(backend, &gpu)?
            } else {
                Backend::Cpu
            };
            let mut session = Session::new(&backend)?;
            if let Some(ctx) = session.context() {
                eprintln!("adapter: {}", lcpbatch::backend::describe_context(ctx));
            }
            let text = match input {
                Input::Lcps(lcps) => {
                    let r = session.solve_lcps(&lcps, &settings)?;
                    if let Some(report) = &r.report.gpu {
                        eprintln!("{report}");
                    }
                    let problems = r
                        .problems
                        .iter()
                        .map(|p| LcpOutput::new(p.solver.name(), &p.solution))
                        .collect();
                    serde_json::to_string_pretty(&LcpBatchOutput { problems })
                        .expect("serialisable")
                }
                Input::Scenes(scenes) => {
                    let r = session.solve_scenes(&scenes, &settings)?;
                    if let Some(report) = &r.report.gpu {
                        eprintln!("{report}");
                    }
                    let scenes = r.scenes.iter().map(SceneOutput::new).collect();
                    serde_json::to_string_pretty(&ScenesOutput { scenes }).expect("serialisable")
                }
            };
            match output {
                Some(path) => write_atomically(&path, &text)?,
                None => println!("{text}"),
            }
            Ok(())
        }
    }
}

fn main() -> ExitCode {
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
