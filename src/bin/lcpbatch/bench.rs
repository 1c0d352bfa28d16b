//! `lcpbatch bench`: every method on the same fixed-seed batches, in one
//! process, timed and measured: islands per second against the error. Every
//! row goes through the library's one door (`Solver`).
//!
//! Speed is only compared within one run on one batch (these machines are
//! noisy); the table, the JSON and the plots say which machine and adapter.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::time::Instant;

use serde::Serialize;

use lcpbatch::generate::families::{family_batch, islands_of_size, BenchFamily};
use lcpbatch::{Backend, Error, GpuSettings, Lcp, Method, Report, Settings, Solver};

use crate::bench_table::{print_table, row_line, write_json};
use crate::devices::{gpu_solvers, machine_description};
use crate::plots::{self, Curve};

/// What `lcpbatch bench` runs.
#[derive(Clone, Debug)]
pub struct BenchOptions {
    /// Islands per family.
    pub islands: usize,
    pub seed: u64,
    pub out_dir: PathBuf,
    /// None: CPU rows only.
    pub gpu: Option<GpuSettings>,
    /// Islands per n for the time-against-n curves.
    pub per_n: usize,
    /// Batch sizes for the time-against-batch-size curves.
    pub batch_sizes: Vec<usize>,
}

/// One line of the table: one method and setting on one batch.
#[derive(Clone, Debug, Serialize)]
pub struct BenchRow {
    pub family: String,
    pub solver: String,
    pub backend: String,
    pub adapter: String,
    pub islands: usize,
    pub seconds: f64,
    pub islands_per_second: f64,
    pub median_error: f64,
    /// Largest error over islands with a solution.
    pub max_error: f64,
    /// Islands per status name.
    pub statuses: BTreeMap<String, usize>,
    /// Islands per path, and what validation did.
    pub note: String,
    /// GPU rows: microseconds per island in each phase of the call, in
    /// order (host preparation: the checks, warm bases, prediction; the GPU
    /// phase's parts, the kernels as the host waits for them; the f64
    /// check, its repairs, the report; the rest: the door). They add up to
    /// the call's time.
    pub phases_us_per_island: Vec<(String, f64)>,
    /// GPU rows: microseconds per island the device ran the kernels, by
    /// its timestamps (None: no timestamps on this adapter, no kernel run,
    /// or no GPU row).
    pub device_kernels_us_per_island: Option<f64>,
    /// GPU rows: microseconds per island of host work (upload, check) done
    /// while a chunk was on the device.
    pub overlapped_us_per_island: f64,
}

impl BenchRow {
    fn of(family: BenchFamily, solver: &str, report: &Report, seconds: f64) -> Self {
        let mut errors: Vec<f64> = report
            .islands
            .iter()
            .filter(|i| i.status().is_solution())
            .map(|i| i.error())
            .collect();
        errors.sort_by(f64::total_cmp);
        let statuses = report
            .status_counts()
            .into_iter()
            .map(|(s, c)| (s.name().to_string(), c))
            .collect();
        let mut note: Vec<String> = report
            .counts
            .nonzero()
            .iter()
            .map(|(p, c)| format!("{p}={c}"))
            .collect();
        let mut phases = Vec::new();
        let (mut device_kernels, mut overlapped) = (None, 0.0);
        let per = 1e6 / report.islands.len().max(1) as f64;
        if let Some(g) = report.gpu.as_ref().filter(|_| report.on_gpu()) {
            note.push(format!(
                "tree decided={} undecided={}; gpu's own max error {:.1e}",
                g.tree_decided, g.tree_undecided, g.max_gpu_error
            ));
            let t = &report.timings;
            let parts = g.pack_seconds + g.upload_seconds + g.kernel_seconds + g.readback_seconds;
            let rest = seconds - t.prediction - t.gpu - t.validation - g.report_seconds;
            device_kernels = g.kernel_device_seconds.map(|s| s * per);
            overlapped = g.overlapped_seconds * per;
            phases = [
                ("host preparation", t.prediction),
                ("pack", g.pack_seconds),
                ("upload", g.upload_seconds),
                ("kernels", g.kernel_seconds),
                ("readback", g.readback_seconds),
                ("other GPU host work", (t.gpu - parts).max(0.0)),
                ("f64 check", g.check_seconds),
                ("repair", g.repair_seconds),
                ("report", g.report_seconds),
                ("door", rest.max(0.0)),
            ]
            .into_iter()
            .map(|(name, secs)| (name.to_string(), secs * per))
            .collect();
        }
        BenchRow {
            family: family.name().into(),
            solver: solver.into(),
            backend: if report.on_gpu() { "gpu" } else { "cpu" }.into(),
            adapter: if report.on_gpu() {
                report.device.name.clone()
            } else {
                "-".into()
            },
            islands: report.islands.len(),
            seconds,
            islands_per_second: report.islands.len() as f64 / seconds.max(1e-12),
            median_error: errors.get(errors.len() / 2).copied().unwrap_or(0.0),
            max_error: errors.last().copied().unwrap_or(0.0),
            statuses,
            note: note.join(" "),
            phases_us_per_island: phases,
            device_kernels_us_per_island: device_kernels,
            overlapped_us_per_island: overlapped,
        }
    }
}

/// `threads` 0: `--threads` (every core unless it says otherwise).
fn cpu_solver(method: Method, threads: usize, predict: bool) -> Result<Solver, Error> {
    Solver::new(Settings {
        threads: if threads == 0 {
            crate::settings().threads
        } else {
            threads
        },
        predict,
        ..Settings::new(Backend::Cpu, method)
    })
}

/// One id per row of every problem (for warm start by contact ids).
fn ids_of(lcps: &[Lcp]) -> Vec<Vec<u64>> {
    let mut next = 0u64;
    lcps.iter()
        .map(|l| {
            let ids = (next..next + l.n() as u64).collect();
            next += l.n() as u64;
            ids
        })
        .collect()
}

/// Solves `lcps` once and times it; on the warm family the batch is solved
/// cold first (untimed, remembering its bases) and the timed call re-solves
/// it warm. Returns the report, the seconds and, when warm, how it compares
/// with the cold one ([`Cold`]).
fn timed(
    solver: &mut Solver,
    family: BenchFamily,
    lcps: &[Lcp],
) -> Result<(Report, f64, Option<Cold>), Error> {
    if family != BenchFamily::WarmResting {
        let t = Instant::now();
        let r = solver.solve_lcps(lcps)?;
        return Ok((r, t.elapsed().as_secs_f64(), None));
    }
    let ids = ids_of(lcps);
    let cold = solver.solve_lcps_keyed(lcps, &ids)?;
    let t = Instant::now();
    let hot = solver.solve_lcps_keyed(lcps, &ids)?;
    let secs = t.elapsed().as_secs_f64();
    solver.clear_warm_start();
    let same = Cold::of(&cold, &hot);
    Ok((hot, secs, Some(same)))
}

/// How a warm call's answers compare with the cold call's: the same
/// bytes; the same statuses and bases with z within [`Z_CLOSE`] (relative
/// to ‖z‖∞): a GPU's z accepted as it gave it beside the warm basis
/// re-solved on the CPU; or not.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Cold {
    Identical,
    Close,
    Differs,
}

/// Largest |z_cold − z_warm| / max(‖z_cold‖∞, 1e-300) called close.
const Z_CLOSE: f64 = 1e-12;

impl Cold {
    fn of(cold: &Report, hot: &Report) -> Cold {
        let pairs = || cold.islands.iter().zip(&hot.islands);
        if pairs().all(|(a, b)| a.solution.z == b.solution.z && a.status() == b.status()) {
            return Cold::Identical;
        }
        let close = |a: &[f64], b: &[f64]| {
            let scale = a.iter().fold(1e-300f64, |m, v| m.max(v.abs()));
            a.len() == b.len()
                && a.iter()
                    .zip(b)
                    .all(|(x, y)| (x - y).abs() <= Z_CLOSE * scale)
        };
        let same = pairs().all(|(a, b)| {
            a.status() == b.status()
                && a.solution.basis == b.solution.basis
                && close(&a.solution.z, &b.solution.z)
        });
        if same {
            Cold::Close
        } else {
            Cold::Differs
        }
    }

    /// The row's note.
    fn note(self) -> &'static str {
        match self {
            Cold::Identical => "; identical to cold",
            Cold::Close => "; same as cold (statuses, bases; z within 1e-12)",
            Cold::Differs => "; DIFFERS from cold",
        }
    }
}

fn row(
    solver: &mut Solver,
    family: BenchFamily,
    lcps: &[Lcp],
    name: &str,
) -> Result<BenchRow, Error> {
    let (report, secs, same) = timed(solver, family, lcps)?;
    let mut r = BenchRow::of(family, name, &report, secs);
    if let Some(same) = same {
        r.note.push_str(same.note());
    }
    Ok(r)
}

/// The CPU rows on one batch: bare enumeration, enumeration after
/// prediction, the default path (Auto) on one thread and on every core,
/// Lemke and PGS with 5…1000 sweeps (one thread each).
pub fn cpu_rows(
    family: BenchFamily,
    lcps: &[Lcp],
    progress: &dyn Fn(&str),
) -> Result<Vec<BenchRow>, Error> {
    let warm = family == BenchFamily::WarmResting;
    let mut rows = Vec::new();
    let cases: [(&str, Method, usize, bool); 5] = [
        ("enum (elimination)", Method::Enumeration, 1, false),
        ("enum + prediction, 1 thread", Method::Enumeration, 1, true),
        ("auto, 1 thread", Method::Auto, 1, true),
        ("auto, all cores", Method::Auto, 0, true),
        ("lemke", Method::Lemke, 1, true),
    ];
    for (name, method, threads, predict) in cases {
        progress(name);
        let mut s = cpu_solver(method, threads, predict)?;
        if warm {
            s = Solver::new(Settings {
                warm_start: true,
                ..s.settings().clone()
            })?;
        }
        rows.push(row(&mut s, family, lcps, name)?);
    }
    for sweeps in [5u64, 20, 100, 1000] {
        let name = format!("pgs {sweeps}");
        progress(&name);
        let mut s = Solver::new(Settings {
            threads: 1,
            pgs_max_sweeps: sweeps,
            pgs_tolerance: 1e-14,
            ..Settings::new(Backend::Cpu, Method::Pgs)
        })?;
        rows.push(row(&mut s, family, lcps, &name)?);
    }
    Ok(rows)
}

/// The GPU row on one batch: enumeration (method Enumeration) or Lemke's
/// textbook path (Auto) on the device after prediction, every answer
/// validated in f64 (time: the whole call). Up to 16 islands of every size
/// in the batch are solved once untimed first, so that the kernels' builds
/// (one per size, on first use) stay out of the figure.
pub fn gpu_row(solver: &mut Solver, family: BenchFamily, lcps: &[Lcp]) -> Result<BenchRow, Error> {
    let precision = solver.device().precision.name();
    let name = match solver.settings().method {
        Method::Enumeration => format!("gpu enum {precision} + f64 polish"),
        _ => format!("gpu lemke {precision} + f64 check"),
    };
    let mut per_size = BTreeMap::<usize, usize>::new();
    let head: Vec<Lcp> = lcps
        .iter()
        .filter(|l| {
            let seen = per_size.entry(l.n()).or_default();
            *seen += 1;
            *seen <= 16
        })
        .cloned()
        .collect();
    let head = &head[..];
    if family == BenchFamily::WarmResting {
        let mut warm = Solver::new(Settings {
            warm_start: true,
            ..solver.settings().clone()
        })?;
        warm.solve_lcps(head)?;
        return row(&mut warm, family, lcps, &name);
    }
    solver.solve_lcps(head)?;
    row(solver, family, lcps, &name)
}

/// `Backend::Auto` on the bench's adapter, named so that a software adapter
/// is opened too: it chooses per batch by its cost model (cached, or
/// measured now). None without a GPU.
pub fn auto_solver(gpus: &[Solver], gpu: &Option<GpuSettings>) -> Option<Solver> {
    let name = gpus.first()?.shared_device()?.adapter_info().name.clone();
    let gpu = GpuSettings {
        adapter: Some(name),
        ..gpu.clone()?
    };
    Solver::new(Settings {
        gpu,
        ..crate::settings()
    })
    .ok()
    .filter(|s| s.cost_model().is_some())
}

/// The auto row, its note saying where the cost model sent the batch and
/// its speed against the faster of the CPU (default path, every core) and
/// the GPU rows on the same batch.
fn auto_row(
    solver: &mut Solver,
    family: BenchFamily,
    lcps: &[Lcp],
    same_batch: &[BenchRow],
) -> Result<BenchRow, Error> {
    let mut warm;
    let solver = if family == BenchFamily::WarmResting {
        warm = Solver::new(Settings {
            warm_start: true,
            cost_model: solver.cost_model().cloned(),
            ..solver.settings().clone()
        })?;
        &mut warm
    } else {
        solver
    };
    let (report, secs, same) = timed(solver, family, lcps)?;
    let mut r = BenchRow::of(family, "auto (cost model)", &report, secs);
    if same == Some(Cold::Differs) {
        r.note.push_str(Cold::Differs.note());
    }
    let chose = if report.choice.ends_with("GPU") {
        "GPU"
    } else {
        "CPU"
    };
    let faster = same_batch
        .iter()
        .filter(|b| b.solver == "auto, all cores" || b.solver.starts_with("gpu"))
        .map(|b| b.islands_per_second)
        .fold(0.0, f64::max);
    r.backend = format!("auto → {chose}");
    r.note.push_str(&format!(
        "; {:.2}x the faster of CPU (all cores) and GPU",
        r.islands_per_second / faster
    ));
    Ok(r)
}

/// Seconds per island against n (random islands of exactly n contacts):
/// bare enumeration and the default path on one thread, and each GPU solver.
fn time_vs_n(opts: &BenchOptions, gpus: &mut [Solver]) -> Result<Vec<Curve>, Error> {
    let mut curves: Vec<Curve> = vec![
        ("cpu enum (elimination), 1 thread".into(), Vec::new()),
        ("cpu auto, 1 thread".into(), Vec::new()),
    ];
    curves.extend(
        gpus.iter()
            .map(|g| (format!("gpu {}", g.device().precision.name()), Vec::new())),
    );
    let mut cpu = [
        cpu_solver(Method::Enumeration, 1, false)?,
        cpu_solver(Method::Auto, 1, true)?,
    ];
    for n in 1..=12 {
        let lcps = islands_of_size(n, opts.per_n, opts.seed);
        let per_island = |s: &mut Solver| -> Result<f64, Error> {
            let t = Instant::now();
            s.solve_lcps(&lcps)?;
            Ok(t.elapsed().as_secs_f64() / lcps.len() as f64)
        };
        for (k, s) in cpu.iter_mut().enumerate() {
            let t = per_island(s)?;
            curves[k].1.push((n as f64, t));
        }
        for (k, g) in gpus.iter_mut().enumerate() {
            g.solve_lcps(&lcps[..lcps.len().min(16)])?; // compile this size, untimed
            let t = per_island(g)?;
            curves[2 + k].1.push((n as f64, t));
        }
    }
    Ok(curves)
}

/// Seconds per island against the batch size (mixed n): the default path
/// on every core and each GPU solver.
fn time_vs_batch(opts: &BenchOptions, gpus: &mut [Solver]) -> Result<Vec<Curve>, Error> {
    let mut cpu = cpu_solver(Method::Auto, 0, true)?;
    let mut curves = vec![("cpu auto, all cores".to_string(), Vec::new())];
    curves.extend(
        gpus.iter()
            .map(|g| (format!("gpu {}", g.device().precision.name()), Vec::new())),
    );
    for &size in &opts.batch_sizes {
        let lcps = family_batch(BenchFamily::MixedN, opts.seed, size);
        let solvers = std::iter::once(&mut cpu).chain(gpus.iter_mut());
        for (k, s) in solvers.enumerate() {
            s.solve_lcps(&lcps[..lcps.len().min(256)])?; // warm-up, untimed
            let t = Instant::now();
            s.solve_lcps(&lcps)?;
            curves[k]
                .1
                .push((size as f64, t.elapsed().as_secs_f64() / size as f64));
        }
    }
    Ok(curves)
}

/// Runs every family through every row, prints the table, writes
/// `bench.json` and the plots into `opts.out_dir`.
pub fn run(opts: &BenchOptions) -> Result<(), Error> {
    std::fs::create_dir_all(&opts.out_dir).map_err(|source| Error::Io {
        path: opts.out_dir.clone(),
        source,
    })?;
    // The enumeration kernels (method Enumeration) and the Lemke kernel
    // (Auto), each in f32 and, where the adapter has it, f64.
    let enumeration = Settings {
        method: Method::Enumeration,
        ..crate::settings()
    };
    let mut gpus = gpu_solvers(&opts.gpu, &enumeration);
    let mut lemke_gpus = gpu_solvers(&opts.gpu, &crate::settings());
    let machine = machine_description(&gpus);
    println!("machine: {machine}");
    let mut auto = auto_solver(&gpus, &opts.gpu);
    if let Some(m) = auto.as_ref().and_then(Solver::cost_model) {
        print!("auto's {m}");
    }
    let steps = (BenchFamily::ALL.len() * (10 + gpus.len() + lemke_gpus.len()) + 2) as u64;
    let bar = indicatif::ProgressBar::new(steps);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{elapsed_precise} [{bar:30}] {pos}/{len} {msg}")
            .expect("valid template"),
    );
    let mut rows = Vec::new();
    for family in BenchFamily::ALL {
        let lcps = family_batch(family, opts.seed, opts.islands);
        let progress = |what: &str| {
            bar.set_message(format!("{} {what}", family.name()));
            bar.inc(1);
        };
        let first = rows.len();
        rows.extend(cpu_rows(family, &lcps, &progress)?);
        for g in gpus.iter_mut().chain(lemke_gpus.iter_mut()) {
            progress("gpu");
            rows.push(gpu_row(g, family, &lcps)?);
        }
        if let Some(a) = auto.as_mut() {
            progress("auto");
            let same_batch = rows[first..].to_vec();
            rows.push(auto_row(a, family, &lcps, &same_batch)?);
        }
        // Without a terminal (a log, a time limit) each family's rows as
        // they end: a run cut short still shows the families it finished.
        if bar.is_hidden() {
            for r in &rows[first..] {
                println!("{}", row_line(r));
            }
        }
    }
    // The table before the curves: a run stopped during the large batches
    // (a time limit) still shows every family's rows.
    bar.suspend(|| print_table(&rows));
    bar.set_message("time against n");
    let by_n = time_vs_n(opts, &mut gpus)?;
    bar.inc(1);
    bar.set_message("time against batch size");
    let by_batch = time_vs_batch(opts, &mut gpus)?;
    bar.finish_and_clear();
    println!("\nµs per island against the batch size (mixed n):");
    for (label, points) in &by_batch {
        let at: Vec<String> = points
            .iter()
            .map(|(size, secs)| format!("{size:.0}: {:.3}", secs * 1e6))
            .collect();
        println!("{label:<28} {}", at.join(", "));
    }
    let dir = &opts.out_dir;
    write_json(
        &rows,
        &[("time_vs_n", &by_n), ("time_vs_batch_size", &by_batch)],
        &machine,
        &dir.join("bench.json"),
    )?;
    let points: Vec<(f64, f64, String)> = rows
        .iter()
        .map(|r| {
            (
                1e6 / r.islands_per_second,
                r.max_error.max(1e-17),
                format!("{} [{}]", r.solver, r.family),
            )
        })
        .collect();
    plots::scatter(
        &points,
        &dir.join("time_vs_error.svg"),
        &format!("lcpbatch bench: time against error ({machine})"),
        ("microseconds per island", "maximum error (Siconos measure)"),
        true,
    )?;
    plots::curves(
        &by_n,
        &dir.join("time_vs_n.svg"),
        "time per island against n",
        "n",
        false,
    )?;
    plots::curves(
        &by_batch,
        &dir.join("time_vs_batch_size.svg"),
        "time per island against batch size (mixed n)",
        "islands per batch",
        true,
    )?;
    println!(
        "wrote {}/{{bench.json, time_vs_error.svg, time_vs_n.svg, time_vs_batch_size.svg}}",
        dir.display()
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_family_runs_and_the_exact_rows_agree() {
        for f in BenchFamily::ALL {
            let lcps = family_batch(f, 1, 40);
            let rows = cpu_rows(f, &lcps, &|_| {}).unwrap();
            let exact: Vec<&BenchRow> = rows
                .iter()
                .filter(|r| r.solver.starts_with("enum") || r.solver.starts_with("auto"))
                .collect();
            assert_eq!(exact.len(), 4);
            for r in &exact {
                assert_eq!(r.statuses, exact[0].statuses, "{} {}", r.family, r.solver);
                assert!(
                    r.max_error < 1e-9,
                    "{} {} {}",
                    r.family,
                    r.solver,
                    r.max_error
                );
            }
            if f == BenchFamily::WarmResting {
                assert!(exact.iter().all(|r| r.note.contains("identical to cold")));
                assert!(exact[1].note.contains("warm_start=40"), "{}", exact[1].note);
            }
        }
    }

    #[test]
    fn plots_are_written() {
        let dir = std::env::temp_dir().join(format!("lcpbatch-bench-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let lcps = family_batch(BenchFamily::MixedN, 2, 30);
        let rows = cpu_rows(BenchFamily::MixedN, &lcps, &|_| {}).unwrap();
        let pts: Vec<(f64, f64, String)> = rows
            .iter()
            .map(|r| {
                (
                    1e6 / r.islands_per_second,
                    r.max_error.max(1e-17),
                    r.solver.clone(),
                )
            })
            .collect();
        plots::scatter(&pts, &dir.join("e.svg"), "t", ("x", "y"), true).unwrap();
        let svg = std::fs::read_to_string(dir.join("e.svg")).unwrap();
        assert!(svg.contains("<svg") && svg.contains("pgs 1000"));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
