//! `lcpbatch bench --friction`: every friction solver on the same
//! fixed-seed frictional islands (boxes resting and sliding, stacks, random
//! spheres and boxes; k contacts each), in one process, timed and measured:
//! islands per second against the Coulomb error. Every row goes through the
//! library's one door (`Solver::solve_friction`, checks and report
//! included).
//!
//! The exact Coulomb methods (`auto`, `nsgs`, `newton`) run on the CPU on
//! every core; the cone projection iterations (`jacobi`, `pgs`, `apgd`) on
//! the CPU and, where an adapter is open, on the GPU in f32 and f64 (every
//! answer judged in f64 on the CPU there). The projected methods solve the
//! convex cone complementarity model, so they are judged by its residual
//! (`cone_error`) and their Coulomb error is the model's distance from
//! Coulomb where contacts slide.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

use serde::Serialize;

use lcpbatch::generate::friction::{friction_batch, FrictionFamily};
use lcpbatch::io::write_atomically;
use lcpbatch::{
    Backend, Error, FrictionMethod, FrictionProblem, GpuSettings, Report, Settings, Solver,
};

use crate::devices::{gpu_solvers, machine_description};
use crate::plots;

/// What `lcpbatch bench --friction` runs.
#[derive(Clone, Debug)]
pub struct FrictionBenchOptions {
    /// Islands per set of k ≤ 4 contacts (a fifth of it above).
    pub islands: usize,
    /// Contacts per island, one set per family that has islands of k.
    pub sizes: Vec<usize>,
    pub seed: u64,
    pub out_dir: PathBuf,
    /// None: CPU rows only.
    pub gpu: Option<GpuSettings>,
    /// Timed runs of each row (≥ 1): its time is their median.
    pub runs: usize,
    /// Some: the Siconos FrictionContact3D `.dat` files of this folder
    /// instead of the generated islands ([`fc3d_rows`]).
    pub fc3d: Option<PathBuf>,
}

/// Every friction method, in the table's order.
const METHODS: [FrictionMethod; 7] = [
    FrictionMethod::Auto,
    FrictionMethod::Nsgs,
    FrictionMethod::Newton,
    FrictionMethod::Prox,
    FrictionMethod::Jacobi,
    FrictionMethod::Pgs,
    FrictionMethod::Apgd,
];

/// One line of the table: one method on one backend on one set of islands.
#[derive(Clone, Debug, Serialize)]
pub struct FrictionRow {
    pub family: String,
    /// Contacts per island.
    pub k: usize,
    pub solver: String,
    pub backend: String,
    /// The device in words (`cpu (N threads)` or the adapter, with its precision).
    pub device: String,
    pub islands: usize,
    /// The median of `run_seconds`.
    pub seconds: f64,
    /// Every timed run of the row, in order (the rows of a set take turns).
    pub run_seconds: Vec<f64>,
    pub islands_per_second: f64,
    /// Largest Coulomb error (Siconos fc3d, De Saxcé) over every island.
    pub max_coulomb_error: f64,
    pub median_coulomb_error: f64,
    /// Largest cone complementarity residual (what the projected methods
    /// are judged by).
    pub max_cone_error: f64,
    /// Mean NSGS sweeps + Newton steps, or projected iterations.
    pub mean_iterations: f64,
    /// Islands per status name.
    pub statuses: BTreeMap<String, usize>,
    /// What the GPU's answers needed on the CPU (kept, polished, repaired).
    pub note: String,
}

impl FrictionRow {
    fn of(set: &Set, solver: &str, report: &Report, run_seconds: Vec<f64>) -> Self {
        let seconds = median(&run_seconds);
        let isl = &report.friction;
        let mut coulomb: Vec<f64> = isl.iter().map(|i| i.error()).collect();
        coulomb.sort_by(f64::total_cmp);
        let cone = isl
            .iter()
            .map(|i| i.solution.residuals.cone_error)
            .fold(0.0, f64::max);
        let iterations = isl
            .iter()
            .map(|i| i.solution.iterations as f64)
            .sum::<f64>();
        let mut statuses = BTreeMap::new();
        for i in isl {
            *statuses.entry(i.status().name().to_string()).or_insert(0) += 1;
        }
        let on_gpu = report.on_gpu();
        let note = if on_gpu {
            let c = &report.counts;
            format!(
                "polished={} repaired={} cpu_fallback={}",
                c.polished, c.repaired, c.cpu_fallback
            )
        } else {
            String::new()
        };
        FrictionRow {
            family: set.family.name().into(),
            k: set.k,
            solver: solver.into(),
            backend: if on_gpu { "gpu" } else { "cpu" }.into(),
            device: report.device.name.clone(),
            islands: isl.len(),
            seconds,
            run_seconds,
            islands_per_second: isl.len() as f64 / seconds.max(1e-12),
            max_coulomb_error: coulomb.last().copied().unwrap_or(0.0),
            median_coulomb_error: coulomb.get(coulomb.len() / 2).copied().unwrap_or(0.0),
            max_cone_error: cone,
            mean_iterations: iterations / isl.len().max(1) as f64,
            statuses,
            note,
        }
    }
}

/// One set of islands: a family at one k.
struct Set {
    family: FrictionFamily,
    k: usize,
    problems: Vec<FrictionProblem>,
}

fn sets(opts: &FrictionBenchOptions) -> Vec<Set> {
    let mut out = Vec::new();
    for family in FrictionFamily::ALL {
        for &k in &opts.sizes {
            let count = if k <= 4 {
                opts.islands
            } else {
                (opts.islands / 5).max(1)
            };
            if let Some(problems) = friction_batch(family, k, opts.seed, count) {
                out.push(Set {
                    family,
                    k,
                    problems,
                });
            }
        }
    }
    out
}

/// The median of `xs` (not empty): the middle one, or the mean of the
/// two middle ones.
fn median(xs: &[f64]) -> f64 {
    let mut v = xs.to_vec();
    v.sort_by(f64::total_cmp);
    let m = v.len() / 2;
    if v.len() % 2 == 1 {
        v[m]
    } else {
        0.5 * (v[m - 1] + v[m])
    }
}

/// The settings of one method (the default tolerance 1e-8 and cap).
fn method_settings(base: &Settings, method: FrictionMethod) -> Settings {
    Settings {
        friction_method: method,
        ..base.clone()
    }
}

/// The solvers of one set's rows, named as the table names them: every
/// method on the CPU over every core, then on each GPU of `gpus`
/// (`devices::gpu_solvers`) the projected methods, each first run untimed
/// on a few islands so that its kernel compiles stay out of the figure.
fn row_solvers(set: &Set, gpus: &[Solver]) -> Result<Vec<(String, Solver)>, Error> {
    let mut out = Vec::new();
    for m in METHODS {
        let base = Settings {
            backend: Backend::Cpu,
            ..crate::settings()
        };
        out.push((
            m.name().to_string(),
            Solver::new(method_settings(&base, m))?,
        ));
    }
    for gpu in gpus {
        let precision = gpu.device().precision.name();
        for m in METHODS.into_iter().filter(|m| m.projected().is_some()) {
            let mut s = Solver::new(method_settings(gpu.settings(), m))?;
            s.solve_friction(&set.problems[..set.problems.len().min(16)])?;
            out.push((format!("gpu {} {precision}", m.name()), s));
        }
    }
    Ok(out)
}

/// The rows of one set: `runs` rounds in which every solver solves the
/// whole set once, timed (the solvers take turns, so that a noisy
/// machine's drift falls on all of them alike); each row's time is the
/// median of its runs, its figures those of its last report.
fn set_rows(set: &Set, gpus: &[Solver], runs: usize) -> Result<Vec<FrictionRow>, Error> {
    let mut solvers = row_solvers(set, gpus)?;
    let mut times: Vec<Vec<f64>> = vec![Vec::new(); solvers.len()];
    let mut reports: Vec<Option<Report>> = solvers.iter().map(|_| None).collect();
    for _ in 0..runs.max(1) {
        for (j, (_, solver)) in solvers.iter_mut().enumerate() {
            // The last run's report is dropped before the clock starts.
            reports[j] = None;
            let t = Instant::now();
            let report = solver.solve_friction(&set.problems)?;
            times[j].push(t.elapsed().as_secs_f64());
            reports[j] = Some(report);
        }
    }
    Ok(solvers
        .iter()
        .zip(reports)
        .zip(times)
        .filter_map(|(((name, _), report), t)| Some(FrictionRow::of(set, name, &report?, t)))
        .collect())
}

fn print_table(rows: &[FrictionRow]) {
    println!(
        "{:<15} {:>3} {:<15} {:>7} {:>11} {:>11} {:>11} {:>9}  statuses / notes",
        "family", "k", "solver", "islands", "islands/s", "max Coulomb", "max cone", "mean it"
    );
    for r in rows {
        let st: Vec<String> = r.statuses.iter().map(|(k, v)| format!("{k}={v}")).collect();
        println!(
            "{:<15} {:>3} {:<15} {:>7} {:>11.0} {:>11.1e} {:>11.1e} {:>9.1}  {} {}",
            r.family,
            r.k,
            r.solver,
            r.islands,
            r.islands_per_second,
            r.max_coulomb_error,
            r.max_cone_error,
            r.mean_iterations,
            st.join(" "),
            r.note
        );
    }
}

/// The plot: microseconds per island against the largest Coulomb error,
/// one colour per solver (and backend), one point per set.
fn plot(rows: &[FrictionRow], machine: &str, path: &Path) -> Result<(), Error> {
    let points: Vec<(f64, f64, String)> = rows
        .iter()
        .map(|r| {
            (
                1e6 / r.islands_per_second,
                r.max_coulomb_error.max(1e-17),
                r.solver.clone(),
            )
        })
        .collect();
    plots::scatter(
        &points,
        path,
        &format!("lcpbatch bench --friction: time against Coulomb error ({machine})"),
        (
            "microseconds per island",
            "largest Coulomb error (Siconos fc3d, De Saxcé)",
        ),
        false,
    )
}

/// Runs every set through every row, prints the table, writes
/// `friction.json` and `friction_time_vs_error.svg` into `opts.out_dir`.
pub fn run(opts: &FrictionBenchOptions) -> Result<(), Error> {
    std::fs::create_dir_all(&opts.out_dir).map_err(|source| Error::Io {
        path: opts.out_dir.clone(),
        source,
    })?;
    if let Some(dir) = &opts.fc3d {
        return run_fc3d(dir, opts.runs, &opts.out_dir);
    }
    let gpus = gpu_solvers(&opts.gpu, &crate::settings());
    let machine = machine_description(&gpus);
    println!("machine: {machine}");
    let sets = sets(opts);
    let bar = indicatif::ProgressBar::new(sets.len() as u64);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{elapsed_precise} [{bar:30}] {pos}/{len} {msg}")
            .expect("valid template"),
    );
    let mut rows = Vec::new();
    for set in &sets {
        bar.set_message(format!("{} k = {}", set.family.name(), set.k));
        rows.extend(set_rows(set, &gpus, opts.runs)?);
        bar.inc(1);
    }
    bar.finish_and_clear();
    print_table(&rows);
    #[derive(Serialize)]
    struct File<'a> {
        machine: &'a str,
        rows: &'a [FrictionRow],
    }
    let dir = &opts.out_dir;
    write_atomically(
        &dir.join("friction.json"),
        &serde_json::to_string_pretty(&File {
            machine: &machine,
            rows: &rows,
        })
        .expect("serialisable"),
    )?;
    plot(&rows, &machine, &dir.join("friction_time_vs_error.svg"))?;
    println!(
        "wrote {}/{{friction.json, friction_time_vs_error.svg}}",
        dir.display()
    );
    Ok(())
}

/// The methods of the `--fc3d-dir` rows: Newton alone is left out (on
/// piles it stalls and runs its cap, seconds a problem).
const FC3D_METHODS: [FrictionMethod; 3] = [
    FrictionMethod::Auto,
    FrictionMethod::Nsgs,
    FrictionMethod::Prox,
];

/// One row of `--fc3d-dir`: one method on one Siconos FrictionContact3D
/// problem from r = 0, on one thread, the default tolerance 1e-8.
#[derive(Clone, Debug, Serialize)]
pub struct Fc3dRow {
    /// The file name.
    pub problem: String,
    pub contacts: usize,
    pub solver: String,
    pub status: String,
    /// Siconos' fc3d error (De Saxcé) of the answer.
    pub coulomb_error: f64,
    /// NSGS sweeps plus Newton steps (PROX: its inner steps).
    pub iterations: u64,
    /// The median of `run_seconds`: wall seconds of the solve call.
    pub seconds: f64,
    pub run_seconds: Vec<f64>,
    /// The median CPU seconds (user + system, the whole process) of the
    /// call: on a loaded machine the figure to compare.
    pub cpu_seconds: f64,
    /// Siconos' fastest converging solver in the folder's
    /// `reference.json` (its name and seconds, on its own machine).
    pub siconos: Option<(String, f64)>,
}

/// The CPU seconds this process has used (user + system).
fn process_cpu_seconds() -> f64 {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `t` is a valid timespec for clock_gettime to write.
    let rc = unsafe { libc::clock_gettime(libc::CLOCK_PROCESS_CPUTIME_ID, &mut t) };
    if rc == 0 {
        t.tv_sec as f64 + t.tv_nsec as f64 * 1e-9
    } else {
        f64::NAN
    }
}

/// Siconos' fastest converging solver per problem in `dir/reference.json`
/// (the layout of `../shared/conformance/siconos-fc3d-large`), where there
/// is one.
fn siconos_fastest(dir: &Path) -> BTreeMap<String, (String, f64)> {
    let Ok(text) = std::fs::read_to_string(dir.join("reference.json")) else {
        return BTreeMap::new();
    };
    let Ok(v) = serde_json::from_str::<serde_json::Value>(&text) else {
        return BTreeMap::new();
    };
    let Some(problems) = v["problems"].as_object() else {
        return BTreeMap::new();
    };
    let fastest = |entry: &serde_json::Value| {
        entry["siconos"]
            .as_object()?
            .iter()
            .filter(|(_, s)| s["info"] == 0)
            .filter_map(|(name, s)| Some((name.clone(), s["seconds"].as_f64()?)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
    };
    problems
        .iter()
        .filter_map(|(name, entry)| Some((name.clone(), fastest(entry)?)))
        .collect()
}

/// The rows of every `.dat` FrictionContact3D file of `dir` (by name):
/// `runs` rounds in which each method solves each problem once on one
/// thread (the methods take turns), timed around the solve call alone.
pub fn fc3d_rows(dir: &Path, runs: usize) -> Result<Vec<Fc3dRow>, Error> {
    let io = |source| Error::Io {
        path: dir.to_path_buf(),
        source,
    };
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(io)?
        .filter_map(|e| Some(e.ok()?.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "dat"))
        .collect();
    files.sort();
    let reference = siconos_fastest(dir);
    let mut rows = Vec::new();
    for file in &files {
        let name = file
            .file_name()
            .map_or(String::new(), |n| n.to_string_lossy().into());
        let text = std::fs::read_to_string(file).map_err(|source| Error::Io {
            path: file.clone(),
            source,
        })?;
        let problem = [lcpbatch::io::fc3d::parse_fc3d(&name, &text)?];
        let mut solvers = FC3D_METHODS
            .iter()
            .map(|&m| {
                let base = Settings {
                    backend: Backend::Cpu,
                    threads: 1,
                    ..crate::settings()
                };
                Solver::new(method_settings(&base, m))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let mut times = vec![(Vec::new(), Vec::new()); solvers.len()];
        let mut reports: Vec<Option<Report>> = solvers.iter().map(|_| None).collect();
        for _ in 0..runs.max(1) {
            for (j, solver) in solvers.iter_mut().enumerate() {
                reports[j] = None;
                let (cpu, wall) = (process_cpu_seconds(), Instant::now());
                let report = solver.solve_friction(&problem)?;
                times[j].0.push(wall.elapsed().as_secs_f64());
                times[j].1.push(process_cpu_seconds() - cpu);
                reports[j] = Some(report);
            }
        }
        for ((method, report), (wall, cpu)) in FC3D_METHODS.iter().zip(reports).zip(times) {
            let Some(island) = report.as_ref().and_then(|r| r.friction.first()) else {
                continue;
            };
            rows.push(Fc3dRow {
                problem: name.clone(),
                contacts: problem[0].contacts(),
                solver: method.name().into(),
                status: island.status().name().into(),
                coulomb_error: island.error(),
                iterations: island.solution.iterations,
                seconds: median(&wall),
                run_seconds: wall,
                cpu_seconds: median(&cpu),
                siconos: reference.get(&name).cloned(),
            });
        }
    }
    Ok(rows)
}

/// `--fc3d-dir`: prints the rows of [`fc3d_rows`] and writes them to
/// `out_dir/friction_fc3d.json`.
fn run_fc3d(dir: &Path, runs: usize, out_dir: &Path) -> Result<(), Error> {
    let rows = fc3d_rows(dir, runs)?;
    println!(
        "{:<34} {:>4} {:<6} {:<14} {:>9} {:>6} {:>9} {:>9}  Siconos' fastest (its machine)",
        "problem", "k", "solver", "status", "Coulomb", "it", "wall s", "CPU s"
    );
    for r in &rows {
        let siconos = r
            .siconos
            .as_ref()
            .map_or(String::new(), |(s, t)| format!("{s} {t:.3} s"));
        println!(
            "{:<34} {:>4} {:<6} {:<14} {:>9.2e} {:>6} {:>9.4} {:>9.4}  {siconos}",
            r.problem,
            r.contacts,
            r.solver,
            r.status,
            r.coulomb_error,
            r.iterations,
            r.seconds,
            r.cpu_seconds
        );
    }
    let path = out_dir.join("friction_fc3d.json");
    write_atomically(
        &path,
        &serde_json::to_string_pretty(&rows).expect("serialisable"),
    )?;
    println!("wrote {}", path.display());
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every set of a small bench has a row per method; the exact methods
    /// reach the default tolerance on the boxes and stacks, every row's
    /// figures are finite, and the plot is written.
    #[test]
    fn every_method_runs_on_every_set_and_the_plot_is_written() {
        let dir = std::env::temp_dir().join(format!("lcpbatch-fbench-{}", std::process::id()));
        let opts = FrictionBenchOptions {
            islands: 20,
            sizes: vec![1, 4, 8],
            seed: 3,
            out_dir: dir.clone(),
            gpu: None,
            runs: 3,
            fc3d: None,
        };
        let sets = sets(&opts);
        // Random spheres at 1, 4, 8; stacks at 4, 8; resting and sliding boxes at 4.
        assert_eq!(sets.len(), 7);
        let mut rows = Vec::new();
        for set in &sets {
            let r = set_rows(set, &[], opts.runs).unwrap();
            assert_eq!(r.len(), METHODS.len());
            for row in &r {
                assert_eq!(row.islands, set.problems.len());
                assert_eq!(row.run_seconds.len(), 3);
                assert_eq!(row.seconds, median(&row.run_seconds));
                assert!(row.islands_per_second.is_finite() && row.islands_per_second > 0.0);
                assert!(row.max_coulomb_error.is_finite(), "{row:?}");
                if row.solver == "auto" && set.family != FrictionFamily::RandomSpheres {
                    assert!(row.max_coulomb_error <= 1e-8, "{row:?}");
                    assert_eq!(row.statuses.get("solved"), Some(&set.problems.len()));
                }
            }
            rows.extend(r);
        }
        std::fs::create_dir_all(&dir).unwrap();
        plot(&rows, "test", &dir.join("f.svg")).unwrap();
        let svg = std::fs::read_to_string(dir.join("f.svg")).unwrap();
        assert!(svg.contains("<svg") && svg.contains("apgd") && svg.contains("newton"));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// The `--fc3d-dir` rows on the small Siconos FC3D set (where the
    /// shared conformance data is present): a row per method and file,
    /// `auto` solved to 1e-8 on each, its times finite.
    #[test]
    fn every_fc3d_file_gets_a_row_per_method() {
        let base = std::env::var_os("LCPBATCH_CONFORMANCE").map_or_else(
            || {
                PathBuf::from(concat!(
                    env!("CARGO_MANIFEST_DIR"),
                    "/../shared/conformance"
                ))
            },
            PathBuf::from,
        );
        let dir = base.join("siconos-fc3d");
        if !dir.is_dir() {
            eprintln!("skipped: no {}", dir.display());
            return;
        }
        let rows = fc3d_rows(&dir, 2).unwrap();
        let files = std::fs::read_dir(&dir)
            .unwrap()
            .filter(|e| {
                e.as_ref()
                    .unwrap()
                    .path()
                    .extension()
                    .is_some_and(|x| x == "dat")
            })
            .count();
        assert!(files > 0);
        assert_eq!(rows.len(), files * FC3D_METHODS.len());
        for r in &rows {
            assert_eq!(r.run_seconds.len(), 2);
            assert_eq!(r.seconds, median(&r.run_seconds));
            assert!(r.cpu_seconds.is_finite() && r.cpu_seconds >= 0.0, "{r:?}");
            if r.solver == "auto" {
                assert_eq!(r.status, "solved", "{r:?}");
                assert!(r.coulomb_error <= 1e-8, "{r:?}");
            }
        }
    }
}
