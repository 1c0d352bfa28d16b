//! The `lcpbatch` command line.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};

use lcpbatch::io::{
    read_input, write_atomically, Input, LcpBatchOutput, LcpOutput, SceneOutput, ScenesOutput,
};
use lcpbatch::pipeline::solve_scene;
use lcpbatch::{solve, Error, Solver, SolverSettings};

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
    },
}

fn run(cli: Cli) -> Result<(), Error> {
    match cli.command {
        Command::Solve {
            file,
            solver,
            all_solutions,
            output,
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
            let text = match read_input(&file)? {
                Input::Lcps(lcps) => {
                    let problems = lcps
                        .iter()
                        .enumerate()
                        .map(|(i, lcp)| {
                            solve(lcp, &settings)
                                .map(|s| LcpOutput::new(settings.solver.name(), &s))
                                .map_err(|e| Error::Unsupported(format!("problem {i}: {e}")))
                        })
                        .collect::<Result<Vec<_>, _>>()?;
                    serde_json::to_string_pretty(&LcpBatchOutput { problems })
                        .expect("serialisable")
                }
                Input::Scenes(scenes) => {
                    let scenes = scenes
                        .iter()
                        .enumerate()
                        .map(|(i, s)| {
                            solve_scene(s, &settings, &format!("scene {i}"))
                                .map(|r| SceneOutput::new(&r))
                        })
                        .collect::<Result<Vec<_>, _>>()?;
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
