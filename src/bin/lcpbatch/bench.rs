//! `lcpbatch bench`: every solver on the same fixed-seed batches, in one
//! process, timed and measured: islands per second against the error.
//!
//! Speed is only compared within one run on one batch (these machines are
//! noisy); the table, the JSON and the plots say which machine and adapter.

use std::collections::BTreeMap;
use std::path::Path;
use std::time::Instant;

use serde::Serialize;

use crate::cpu::batch::{solve_batch, CpuBatchSettings};
use crate::cpu::enumeration::{enumerate, EnumerationSettings};
use crate::cpu::enumeration_gray::{enumerate_gray, GraySettings};
use crate::generate::{demo_world, random_island, Rng};
use crate::lcp::{Lcp, LcpSolution};
use crate::pipeline::build;
use crate::solvers::lemke::{lemke, LemkeSettings};
use crate::solvers::pgs::{pgs, PgsSettings};
use crate::stress::{self, Family};
use crate::Error;

/// A batch family of the benchmark.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum BenchFamily {
    /// Random physical islands, n = 1…12, masses within a ratio of 10.
    WellConditioned,
    /// Random physical islands, n = 1…12, masses within a ratio of 1e4.
    MassRatio,
    /// Boxes resting on the ground and stacked: degenerate, rank-deficient M.
    RestingStacks,
    /// Islands of the demo worlds: balls, boxes and stacks, mixed n.
    MixedN,
    /// The resting stacks solved again with last frame's bases (warm start).
    WarmResting,
}

impl BenchFamily {
    pub const ALL: [BenchFamily; 5] = [
        BenchFamily::WellConditioned,
        BenchFamily::MassRatio,
        BenchFamily::RestingStacks,
        BenchFamily::MixedN,
        BenchFamily::WarmResting,
    ];

    pub fn name(self) -> &'static str {
        match self {
            BenchFamily::WellConditioned => "well_conditioned",
            BenchFamily::MassRatio => "mass_ratio_1e4",
            BenchFamily::RestingStacks => "resting_stacks",
            BenchFamily::MixedN => "mixed_n",
            BenchFamily::WarmResting => "warm_resting",
        }
    }
}

/// About `count` islands of a family, from `seed`.
pub fn family_batch(family: BenchFamily, seed: u64, count: usize) -> Vec<Lcp> {
    let mut rng = Rng::new(seed);
    let mut out = Vec::with_capacity(count + 16);
    match family {
        BenchFamily::WellConditioned | BenchFamily::MassRatio => {
            let ratio = if family == BenchFamily::MassRatio {
                1e4
            } else {
                10.0
            };
            while out.len() < count {
                let n = rng.int(1, 12);
                out.extend(islands(&random_island(&mut rng, n, ratio)));
            }
        }
        BenchFamily::RestingStacks | BenchFamily::WarmResting => {
            out.extend(
                stress::generate(Family::RestingStacks, seed, count)
                    .into_iter()
                    .map(|c| c.lcp),
            );
        }
        BenchFamily::MixedN => {
            while out.len() < count {
                out.extend(islands(&demo_world(&mut rng)));
            }
        }
    }
    out.truncate(count);
    out
}

fn islands(scene: &crate::Scene) -> Vec<Lcp> {
    build(scene, "bench scene")
        .expect("generated scenes are valid")
        .2
}

/// One line of the table: one solver and setting on one batch.
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
    pub max_error: f64,
    /// Islands per status name.
    pub statuses: BTreeMap<String, usize>,
    /// Free-form detail (paths taken, repaired count).
    pub note: String,
}

impl BenchRow {
    /// A row from solutions and the seconds they took.
    pub fn new(
        family: &str,
        solver: &str,
        backend: &str,
        adapter: &str,
        seconds: f64,
        sols: &[LcpSolution],
    ) -> Self {
        let mut errors: Vec<f64> = sols.iter().map(|s| s.residuals.error).collect();
        errors.sort_by(f64::total_cmp);
        let mut statuses = BTreeMap::new();
        for s in sols {
            *statuses.entry(s.status.name().to_string()).or_insert(0) += 1;
        }
        BenchRow {
            family: family.to_string(),
            solver: solver.to_string(),
            backend: backend.to_string(),
            adapter: adapter.to_string(),
            islands: sols.len(),
            seconds,
            islands_per_second: sols.len() as f64 / seconds.max(1e-12),
            median_error: errors.get(errors.len() / 2).copied().unwrap_or(0.0),
            max_error: errors.last().copied().unwrap_or(0.0),
            statuses,
            note: String::new(),
        }
    }
}

/// Times `f` over every island of `lcps`.
fn timed<F: Fn(&Lcp) -> LcpSolution>(lcps: &[Lcp], f: F) -> (f64, Vec<LcpSolution>) {
    let t = Instant::now();
    let sols: Vec<LcpSolution> = lcps.iter().map(f).collect();
    (t.elapsed().as_secs_f64(), sols)
}

/// The CPU solvers on one batch. Enumeration, Gray-code enumeration and
/// Lemke run single-threaded; "cpu batch" is the CPU path as the library
/// runs it (prediction, Gray code, all cores). On the warm family the batch
/// is first solved cold, and the warm row re-solves it with those bases.
pub fn cpu_rows(
    family: BenchFamily,
    lcps: &[Lcp],
    progress: &dyn Fn(&str),
) -> Result<Vec<BenchRow>, Error> {
    let fam = family.name();
    let es = EnumerationSettings::default();
    let mut rows = Vec::new();
    let cpu = "cpu";
    let adapter = "-";
    progress("cpu enum");
    let (t, sols) = timed(lcps, |l| {
        enumerate(l, &es).expect("n ≤ 20 in bench batches")
    });
    rows.push(BenchRow::new(
        fam,
        "enum (elimination)",
        cpu,
        adapter,
        t,
        &sols,
    ));
    progress("cpu enum gray");
    let gs = GraySettings::default();
    let (t, gray) = timed(lcps, |l| {
        enumerate_gray(l, &gs).expect("n ≤ 20 in bench batches")
    });
    rows.push(BenchRow::new(
        fam,
        "enum (gray code)",
        cpu,
        adapter,
        t,
        &gray,
    ));
    for (threads, name) in [(1, "cpu batch, 1 thread"), (0, "cpu batch, all cores")] {
        progress(name);
        let s = CpuBatchSettings {
            threads,
            ..Default::default()
        };
        let warm: Option<Vec<Option<u32>>> =
            (family == BenchFamily::WarmResting).then(|| gray.iter().map(|s| s.basis).collect());
        let start = Instant::now();
        let res = solve_batch(lcps, warm.as_deref(), &s)?;
        let t = start.elapsed().as_secs_f64();
        let sols: Vec<LcpSolution> = res.iter().map(|r| r.solution.clone()).collect();
        let mut row = BenchRow::new(fam, name, cpu, adapter, t, &sols);
        let paths: Vec<_> = res.iter().map(|r| r.path).collect();
        row.note = crate::prediction::count_paths(&paths)
            .into_iter()
            .filter(|(_, c)| *c > 0)
            .map(|(p, c)| format!("{}={c}", p.name()))
            .collect::<Vec<_>>()
            .join(" ");
        if family == BenchFamily::WarmResting {
            let identical = sols
                .iter()
                .zip(&gray)
                .all(|(a, b)| a.z == b.z && a.status == b.status);
            row.note.push_str(if identical {
                "; identical to cold"
            } else {
                "; DIFFERS from cold"
            });
        }
        rows.push(row);
    }
    progress("cpu lemke");
    let ls = LemkeSettings::default();
    let (t, sols) = timed(lcps, |l| lemke(l, &ls));
    rows.push(BenchRow::new(fam, "lemke", cpu, adapter, t, &sols));
    for iters in [5u64, 20, 100, 1000] {
        progress(&format!("cpu pgs {iters}"));
        let ps = PgsSettings {
            max_iterations: iters,
            tolerance: 1e-14,
        };
        let (t, sols) = timed(lcps, |l| pgs(l, &ps));
        rows.push(BenchRow::new(
            fam,
            &format!("pgs {iters}"),
            cpu,
            adapter,
            t,
            &sols,
        ));
    }
    Ok(rows)
}

/// Prints the table.
pub fn print_table(rows: &[BenchRow]) {
    println!(
        "{:<17} {:<26} {:<7} {:<28} {:>8} {:>12} {:>10} {:>10}  statuses / notes",
        "family", "solver", "backend", "adapter", "islands", "islands/s", "median err", "max err"
    );
    for r in rows {
        let st: Vec<String> = r.statuses.iter().map(|(k, v)| format!("{k}={v}")).collect();
        println!(
            "{:<17} {:<26} {:<7} {:<28} {:>8} {:>12.0} {:>10.1e} {:>10.1e}  {} {}",
            r.family,
            r.solver,
            r.backend,
            truncate(&r.adapter, 28),
            r.islands,
            r.islands_per_second,
            r.median_error,
            r.max_error,
            st.join(" "),
            r.note
        );
    }
}

fn truncate(s: &str, n: usize) -> String {
    s.chars().take(n).collect()
}

/// Draws run time per island against the maximum error, log–log, one point
/// per solver and setting (errors of exactly 0 are drawn at 1e-17).
pub fn plot_time_vs_error(rows: &[BenchRow], path: &Path, title: &str) -> Result<(), Error> {
    use plotters::prelude::*;
    let floor = 1e-17;
    let pts: Vec<(f64, f64, String)> = rows
        .iter()
        .map(|r| {
            (
                1e6 / r.islands_per_second,
                r.max_error.max(floor),
                format!("{} [{}]", r.solver, r.family),
            )
        })
        .collect();
    let (xmin, xmax) = bounds(pts.iter().map(|p| p.0));
    let (ymin, ymax) = bounds(pts.iter().map(|p| p.1));
    let plot_err = |e: String| Error::Io {
        path: path.to_path_buf(),
        source: std::io::Error::other(e),
    };
    let root = SVGBackend::new(path, (1100, 750)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| plot_err(e.to_string()))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 20))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d((xmin..xmax).log_scale(), (ymin..ymax).log_scale())
        .map_err(|e| plot_err(e.to_string()))?;
    chart
        .configure_mesh()
        .x_desc("microseconds per island")
        .y_desc("maximum error (Siconos measure)")
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()
        .map_err(|e| plot_err(e.to_string()))?;
    let colors = [
        RED,
        BLUE,
        GREEN,
        MAGENTA,
        CYAN,
        BLACK,
        RGBColor(255, 140, 0),
        RGBColor(128, 0, 128),
    ];
    for (i, (x, y, label)) in pts.iter().enumerate() {
        let c = colors[i % colors.len()];
        chart
            .draw_series(std::iter::once(Circle::new((*x, *y), 4, c.filled())))
            .map_err(|e| plot_err(e.to_string()))?;
        chart
            .draw_series(std::iter::once(Text::new(
                label.clone(),
                (*x, *y),
                ("sans-serif", 10).into_font().color(&c),
            )))
            .map_err(|e| plot_err(e.to_string()))?;
    }
    root.present().map_err(|e| plot_err(e.to_string()))
}

/// Log-scale bounds with a margin of a factor 2 on each side.
fn bounds(v: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = v.fold((f64::INFINITY, 0.0f64), |(a, b), x| (a.min(x), b.max(x)));
    if !lo.is_finite() || hi <= 0.0 {
        return (1e-3, 1.0);
    }
    (lo / 2.0, (hi * 2.0).max(lo))
}

/// One curve of a line plot: a label and (x, seconds-per-island) points.
pub type Curve = (String, Vec<(f64, f64)>);

/// Draws microseconds per island against `x_desc` (n or batch size), log y
/// and linear or log x.
pub fn plot_curves(
    curves: &[Curve],
    path: &Path,
    title: &str,
    x_desc: &str,
    log_x: bool,
) -> Result<(), Error> {
    use plotters::prelude::*;
    let plot_err = |e: String| Error::Io {
        path: path.to_path_buf(),
        source: std::io::Error::other(e),
    };
    let xs = curves.iter().flat_map(|c| c.1.iter().map(|p| p.0));
    let ys = curves.iter().flat_map(|c| c.1.iter().map(|p| p.1 * 1e6));
    let (xlo, xhi) = xs
        .clone()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(x), b.max(x))
        });
    let (xmin, xmax) = bounds(xs);
    let (ymin, ymax) = bounds(ys);
    let root = SVGBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| plot_err(e.to_string()))?;
    let colors = [RED, BLUE, GREEN, MAGENTA, CYAN, BLACK];
    macro_rules! draw {
        ($xr:expr) => {{
            let mut chart = ChartBuilder::on(&root)
                .caption(title, ("sans-serif", 20))
                .margin(15)
                .x_label_area_size(45)
                .y_label_area_size(70)
                .build_cartesian_2d($xr, (ymin..ymax).log_scale())
                .map_err(|e| plot_err(e.to_string()))?;
            chart
                .configure_mesh()
                .x_desc(x_desc)
                .y_desc("microseconds per island")
                .y_label_formatter(&|v| format!("{v:.0e}"))
                .draw()
                .map_err(|e| plot_err(e.to_string()))?;
            for (i, (label, pts)) in curves.iter().enumerate() {
                let c = colors[i % colors.len()];
                chart
                    .draw_series(LineSeries::new(
                        pts.iter().map(|&(x, y)| (x, y * 1e6)),
                        c.stroke_width(2),
                    ))
                    .map_err(|e| plot_err(e.to_string()))?
                    .label(label.clone())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c));
            }
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .draw()
                .map_err(|e| plot_err(e.to_string()))?;
        }};
    }
    if log_x {
        draw!((xmin..xmax).log_scale());
    } else {
        draw!((xlo - 0.5)..(xhi + 0.5));
    }
    root.present().map_err(|e| plot_err(e.to_string()))
}

/// Seconds per island of the CPU enumerations (bare, and the CPU batch path
/// with prediction on one thread) on random islands of exactly n contacts,
/// n = 1…`max_n`, `count` islands each.
pub fn cpu_time_vs_n(max_n: usize, count: usize, seed: u64) -> Vec<Curve> {
    let es = EnumerationSettings::default();
    let gs = GraySettings::default();
    let bs = CpuBatchSettings {
        threads: 1,
        ..Default::default()
    };
    let mut elim = Vec::new();
    let mut gray = Vec::new();
    let mut batch = Vec::new();
    for n in 1..=max_n {
        let lcps = islands_of_size(n, count, seed);
        let (t, _) = timed(&lcps, |l| enumerate(l, &es).expect("n ≤ 20"));
        elim.push((n as f64, t / lcps.len() as f64));
        let (t, _) = timed(&lcps, |l| enumerate_gray(l, &gs).expect("n ≤ 20"));
        gray.push((n as f64, t / lcps.len() as f64));
        // The CPU path as the library runs it, with prediction, like the GPU path.
        let (t, _) = timed(&lcps, |l| {
            crate::cpu::batch::solve_island(l, None, &bs).solution
        });
        batch.push((n as f64, t / lcps.len() as f64));
    }
    vec![
        ("cpu enum (elimination)".into(), elim),
        ("cpu enum (gray code)".into(), gray),
        (
            "cpu batch, 1 thread (prediction + enumeration)".into(),
            batch,
        ),
    ]
}

/// `count` random physical islands of exactly n contacts (mass ratio 100).
pub fn islands_of_size(n: usize, count: usize, seed: u64) -> Vec<Lcp> {
    let mut rng = Rng::new(seed ^ (n as u64) << 32);
    let mut out = Vec::with_capacity(count);
    while out.len() < count {
        out.extend(
            islands(&random_island(&mut rng, n, 100.0))
                .into_iter()
                .filter(|l| l.n() == n),
        );
    }
    out.truncate(count);
    out
}

/// Writes the rows and the curves (seconds per island) as JSON, atomically.
pub fn write_json(
    rows: &[BenchRow],
    curves: &[(&str, &[Curve])],
    machine: &str,
    path: &Path,
) -> Result<(), Error> {
    #[derive(Serialize)]
    struct CurveOut<'a> {
        plot: &'a str,
        label: &'a str,
        /// (x, seconds per island)
        points: &'a [(f64, f64)],
    }
    #[derive(Serialize)]
    struct File<'a> {
        machine: &'a str,
        rows: &'a [BenchRow],
        curves: Vec<CurveOut<'a>>,
    }
    let curves = curves
        .iter()
        .flat_map(|(plot, cs)| {
            cs.iter().map(move |(label, points)| CurveOut {
                plot,
                label,
                points,
            })
        })
        .collect();
    let text = serde_json::to_string_pretty(&File {
        machine,
        rows,
        curves,
    })
    .expect("serialisable");
    crate::io::write_atomically(path, &text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_family_builds_and_cpu_rows_agree_on_status() {
        for f in BenchFamily::ALL {
            let lcps = family_batch(f, 1, 40);
            assert_eq!(lcps.len(), 40, "{f:?}");
            let rows = cpu_rows(f, &lcps, &|_| {}).unwrap();
            let exact: Vec<&BenchRow> = rows
                .iter()
                .filter(|r| r.solver.starts_with("enum") || r.solver.starts_with("cpu batch"))
                .collect();
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
                assert!(rows.iter().any(|r| r.note.contains("identical to cold")));
            }
        }
    }

    #[test]
    fn plots_are_written() {
        let dir = std::env::temp_dir().join(format!("lcpbatch-bench-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let lcps = family_batch(BenchFamily::MixedN, 2, 30);
        let rows = cpu_rows(BenchFamily::MixedN, &lcps, &|_| {}).unwrap();
        plot_time_vs_error(&rows, &dir.join("e.svg"), "t").unwrap();
        plot_curves(&cpu_time_vs_n(3, 5, 1), &dir.join("n.svg"), "t", "n", false).unwrap();
        let svg = std::fs::read_to_string(dir.join("e.svg")).unwrap();
        assert!(svg.contains("<svg") && svg.contains("pgs 1000"));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

/// The GPU rows on one batch, for one context: the GPU's own answer
/// (upload + dispatch + readback; its z in the shader's precision) and the
/// validated answer (plus the f64 polish and repairs on the CPU).
pub fn gpu_rows(
    ctx: &crate::gpu::GpuContext,
    family: BenchFamily,
    lcps: &[Lcp],
) -> Result<Vec<BenchRow>, Error> {
    let settings = crate::gpu::GpuSolveSettings::default();
    let res = crate::gpu::solve_lcp_batch(ctx, lcps, &settings)?;
    let precision = ctx.precision().name();
    let adapter = ctx.adapter_info().name.clone();
    let r = &res.report;
    // The GPU's own z, error measured in f64 on the problem.
    let raw: Vec<LcpSolution> = lcps
        .iter()
        .zip(&res.islands)
        .map(|(l, o)| {
            let z = if o.gpu_z.len() == l.n() {
                o.gpu_z.clone()
            } else {
                o.solution.z.clone()
            };
            LcpSolution::from_z(l, gpu_own_status(o), z, o.solution.counters)
        })
        .collect();
    let validated: Vec<LcpSolution> = res.islands.iter().map(|o| o.solution.clone()).collect();
    let mut a = BenchRow::new(
        family.name(),
        &format!("gpu enum {precision}"),
        "gpu",
        &adapter,
        r.gpu_seconds,
        &raw,
    );
    a.note =
        "GPU's own z and verdict, before validation; time: upload + dispatch + readback".into();
    let paths_note = |r: &crate::validation::BatchReport| {
        crate::prediction::SolvePath::ALL
            .iter()
            .zip(r.paths)
            .filter(|(_, c)| *c > 0)
            .map(|(p, c)| format!("{}={c}", p.name()))
            .collect::<Vec<_>>()
            .join(" ")
    };
    let mut b = BenchRow::new(
        family.name(),
        &format!("gpu enum {precision} + f64 polish"),
        "gpu",
        &adapter,
        end_to_end_seconds(r),
        &validated,
    );
    b.note = format!(
        "{}; tree decided={} undecided={}; polished={} repaired={} cpu_fallback={}",
        paths_note(r),
        r.tree_decided,
        r.tree_undecided,
        r.polished,
        r.repaired,
        r.cpu_fallback
    );
    let mut rows = vec![a, b];
    if family == BenchFamily::WarmResting {
        // The same batch again, warm-started from the cold bases.
        let warm: Vec<Option<u32>> = res.islands.iter().map(|o| o.solution.basis).collect();
        let hot = crate::gpu::batch::solve_lcp_batch_warm(ctx, lcps, Some(&warm), &settings)?;
        let h = &hot.report;
        let sols: Vec<LcpSolution> = hot.islands.iter().map(|o| o.solution.clone()).collect();
        let mut row = BenchRow::new(
            family.name(),
            &format!("gpu enum {precision} + f64 polish, warm"),
            "gpu",
            &adapter,
            end_to_end_seconds(h),
            &sols,
        );
        let identical = sols
            .iter()
            .zip(&validated)
            .all(|(a, b)| a.z == b.z && a.status == b.status);
        row.note = format!(
            "{}; polished={} repaired={}{}",
            paths_note(h),
            h.polished,
            h.repaired,
            if identical {
                "; identical to cold"
            } else {
                "; DIFFERS from cold"
            }
        );
        rows.push(row);
    }
    Ok(rows)
}

/// The GPU's own verdict on an island, before validation: a basis found
/// (strictly or within the relaxed tolerance) is Solved, none is
/// NoSolution; islands the GPU did not enumerate keep their final status.
pub fn gpu_own_status(o: &crate::gpu::IslandOutcome) -> crate::Status {
    use crate::gpu::layout::{FOUND, NONE, RELAXED};
    match o.gpu.map(|r| r.status) {
        Some(FOUND) | Some(RELAXED) => crate::Status::Solved,
        Some(NONE) => crate::Status::NoSolution,
        _ => o.solution.status,
    }
}

/// What `lcpbatch bench` runs.
#[derive(Clone, Debug)]
pub struct BenchOptions {
    /// Islands per family (default 20,000).
    pub islands: usize,
    pub seed: u64,
    /// Where the JSON and the plots go (created if missing).
    pub out_dir: std::path::PathBuf,
    /// The GPU to use; None: CPU only.
    pub gpu: Option<crate::gpu::GpuOptions>,
    /// Islands per n for the time-against-n curves (default 500).
    pub per_n: usize,
    /// Batch sizes of the time-against-batch-size curves.
    pub batch_sizes: Vec<usize>,
}

impl Default for BenchOptions {
    fn default() -> Self {
        BenchOptions {
            islands: 20_000,
            seed: 2026,
            out_dir: "bench-out".into(),
            gpu: Some(crate::gpu::GpuOptions::default()),
            per_n: 500,
            batch_sizes: vec![1_000, 10_000, 100_000],
        }
    }
}

/// GPU contexts for f32 and, where the adapter has it, f64. A missing
/// adapter is a warning: the caller runs on the CPU only.
pub fn gpu_contexts(opts: &Option<crate::gpu::GpuOptions>) -> Vec<crate::gpu::GpuContext> {
    use crate::gpu::{GpuContext, Precision};
    let Some(base) = opts else { return Vec::new() };
    let mut out = Vec::new();
    for p in [Precision::F32, Precision::F64] {
        let o = crate::gpu::GpuOptions {
            precision: p,
            ..base.clone()
        };
        match GpuContext::new(&o) {
            Ok(ctx) if ctx.precision() == p => out.push(ctx),
            Ok(_) => eprintln!("warning: the adapter has no f64; GPU rows in f32 only"),
            Err(e) => {
                eprintln!("warning: {e}; CPU rows only");
                break;
            }
        }
    }
    out
}

/// Runs the whole benchmark: every family through every solver, the table,
/// `bench.json`, `time_vs_error.svg`, `time_vs_n.svg`, `time_vs_batch_size.svg`.
/// A GPU batch's time end to end: prediction, upload, dispatch, readback
/// and validation (what the CPU batch path's time also covers).
fn end_to_end_seconds(r: &crate::validation::BatchReport) -> f64 {
    r.prediction_seconds + r.gpu_seconds + r.validation_seconds
}

pub fn run(opts: &BenchOptions) -> Result<Vec<BenchRow>, Error> {
    std::fs::create_dir_all(&opts.out_dir).map_err(|source| Error::Io {
        path: opts.out_dir.clone(),
        source,
    })?;
    let contexts = gpu_contexts(&opts.gpu);
    let steps =
        (BenchFamily::ALL.len() * (9 + 2 * contexts.len()) + 12 + opts.batch_sizes.len()) as u64;
    let bar = indicatif::ProgressBar::new(steps);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{elapsed_precise} [{bar:30}] {pos}/{len} {msg}")
            .expect("valid template")
            .progress_chars("=> "),
    );
    let mut rows = Vec::new();
    for family in BenchFamily::ALL {
        bar.set_message(format!("{}: generating", family.name()));
        let lcps = family_batch(family, opts.seed, opts.islands);
        rows.extend(cpu_rows(family, &lcps, &|s| {
            bar.set_message(format!("{}: {s}", family.name()));
            bar.inc(1);
        })?);
        for ctx in &contexts {
            bar.set_message(format!("{}: gpu {}", family.name(), ctx.precision().name()));
            // The first dispatch compiles the shaders: warm up outside the timing.
            crate::gpu::solve_lcp_batch(ctx, &lcps[..lcps.len().min(64)], &Default::default())?;
            rows.extend(gpu_rows(ctx, family, &lcps)?);
            bar.inc(2);
        }
    }
    // Time against n: CPU enumerations and the GPU (validated) on islands of exactly n.
    bar.set_message("time against n");
    let mut by_n = cpu_time_vs_n(12, opts.per_n, opts.seed);
    for ctx in &contexts {
        let mut pts = Vec::new();
        for n in 1..=12 {
            let lcps = islands_of_size(n, opts.per_n, opts.seed);
            // Untimed first: the kernels of this size compile at their first dispatch.
            crate::gpu::solve_lcp_batch(ctx, &lcps[..lcps.len().min(64)], &Default::default())?;
            let r = crate::gpu::solve_lcp_batch(ctx, &lcps, &Default::default())?;
            pts.push((n as f64, end_to_end_seconds(&r.report) / lcps.len() as f64));
            bar.inc(1);
        }
        by_n.push((format!("gpu {} + polish", ctx.precision().name()), pts));
    }
    // Time against batch size (mixed n).
    bar.set_message("time against batch size");
    let mut by_size: Vec<Curve> = vec![("cpu batch (all cores)".into(), Vec::new())];
    for ctx in &contexts {
        by_size.push((
            format!("gpu {} + polish", ctx.precision().name()),
            Vec::new(),
        ));
    }
    for &size in &opts.batch_sizes {
        let lcps = family_batch(BenchFamily::MixedN, opts.seed + 1, size);
        let t = Instant::now();
        solve_batch(&lcps, None, &CpuBatchSettings::default())?;
        by_size[0]
            .1
            .push((size as f64, t.elapsed().as_secs_f64() / size as f64));
        for (k, ctx) in contexts.iter().enumerate() {
            let r = crate::gpu::solve_lcp_batch(ctx, &lcps, &Default::default())?;
            by_size[k + 1]
                .1
                .push((size as f64, end_to_end_seconds(&r.report) / size as f64));
        }
        bar.inc(1);
    }
    bar.finish_and_clear();
    let machine = machine_description(&contexts);
    print_table(&rows);
    write_json(
        &rows,
        &[("time_vs_n", &by_n), ("time_vs_batch_size", &by_size)],
        &machine,
        &opts.out_dir.join("bench.json"),
    )?;
    plot_time_vs_error(
        &rows,
        &opts.out_dir.join("time_vs_error.svg"),
        &format!("time against error — {machine}"),
    )?;
    plot_curves(
        &by_n,
        &opts.out_dir.join("time_vs_n.svg"),
        "time per island against n",
        "n (contacts per island)",
        false,
    )?;
    plot_curves(
        &by_size,
        &opts.out_dir.join("time_vs_batch_size.svg"),
        "time per island against batch size",
        "islands per batch",
        true,
    )?;
    println!("machine: {machine}");
    println!(
        "wrote {}/{{bench.json, time_vs_error.svg, time_vs_n.svg, time_vs_batch_size.svg}}",
        opts.out_dir.display()
    );
    Ok(rows)
}

/// Cores and the adapter, in words.
pub fn machine_description(contexts: &[crate::gpu::GpuContext]) -> String {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let adapter = contexts
        .first()
        .map(|c| format!("{} ({})", c.adapter_info().name, c.adapter_info().backend))
        .unwrap_or_else(|| "no GPU adapter".into());
    format!("{cores} CPU threads; {adapter}")
}
