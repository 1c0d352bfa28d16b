//! `lcpbatch stress`: the stress families of `lcpbatch::generate::stress`
//! through every solver and precision.

use lcpbatch::generate::stress::{basis_condition, generate, siconos_scaled, Family, StressCase};

/// One solver's result on one stress case, next to the f64 reference.
#[derive(Clone, Debug, serde::Serialize)]
pub struct StressPoint {
    pub family: String,
    pub solver: String,
    pub parameter: f64,
    /// Condition number of the reference basis' principal submatrix.
    pub condition: f64,
    pub error: f64,
    pub status: String,
    pub status_matches_reference: bool,
    /// Every z and w finite.
    pub finite: bool,
}

/// Summary of one family and one solver.
#[derive(Clone, Debug, serde::Serialize)]
pub struct StressRow {
    pub family: String,
    pub solver: String,
    pub cases: usize,
    pub median_error: f64,
    pub p99_error: f64,
    pub max_error: f64,
    /// Share of cases whose status equals the f64 exhaustive enumeration's.
    pub status_match: f64,
    /// Cases with a NaN or Inf in z or w (must be 0).
    pub non_finite: usize,
    /// Islands the GPU validation had to re-solve on the CPU (GPU rows only).
    pub repaired: Option<usize>,
}

/// Summarises points per (family, solver), in first-seen order.
pub fn summarise(points: &[StressPoint]) -> Vec<StressRow> {
    let mut keys: Vec<(String, String)> = Vec::new();
    for p in points {
        let k = (p.family.clone(), p.solver.clone());
        if !keys.contains(&k) {
            keys.push(k);
        }
    }
    keys.into_iter()
        .map(|(family, solver)| {
            let ps: Vec<&StressPoint> = points
                .iter()
                .filter(|p| p.family == family && p.solver == solver)
                .collect();
            let mut e: Vec<f64> = ps.iter().map(|p| p.error).collect();
            e.sort_by(f64::total_cmp);
            let q = |f: f64| {
                e.get(((e.len() as f64 - 1.0) * f).round() as usize)
                    .copied()
                    .unwrap_or(0.0)
            };
            StressRow {
                cases: ps.len(),
                median_error: q(0.5),
                p99_error: q(0.99),
                max_error: e.last().copied().unwrap_or(0.0),
                status_match: ps.iter().filter(|p| p.status_matches_reference).count() as f64
                    / ps.len().max(1) as f64,
                non_finite: ps.iter().filter(|p| !p.finite).count(),
                repaired: None,
                family,
                solver,
            }
        })
        .collect()
}

/// Runs the f64 reference (exhaustive enumeration) and the CPU solvers on
/// `cases`: Gray-code enumeration, Lemke, PGS (100 sweeps) and the CPU batch
/// path. Returns one point per case and solver, the reference included.
pub fn run_cpu(label: &str, cases: &[StressCase], regularization: f64) -> Vec<StressPoint> {
    use crate::cpu::enumeration::{enumerate, EnumerationSettings};
    use crate::cpu::enumeration_gray::{enumerate_gray, GraySettings};
    use crate::solvers::lemke::{lemke, LemkeSettings};
    use crate::solvers::pgs::{pgs, PgsSettings};
    let es = EnumerationSettings::default();
    let mut points = Vec::new();
    for c in cases {
        let lcp = if regularization > 0.0 {
            regularized(&c.lcp, regularization)
        } else {
            c.lcp.clone()
        };
        let reference = enumerate(&lcp, &es).expect("stress cases have n ≤ 20");
        let condition = reference
            .basis
            .map_or(f64::NAN, |b| basis_condition(&lcp, b));
        let mut push = |solver: &str, sol: &crate::LcpSolution| {
            // Errors are measured on the problem as posed, before regularisation.
            let res = c.lcp.residuals(&sol.z);
            points.push(StressPoint {
                family: label.to_string(),
                solver: solver.to_string(),
                parameter: c.parameter,
                condition,
                error: res.error,
                status: sol.status.name().to_string(),
                status_matches_reference: sol.status == reference.status,
                finite: sol.z.iter().chain(&sol.w).all(|v| v.is_finite()) && res.error.is_finite(),
            });
        };
        push("enum f64 (reference)", &reference);
        push(
            "enum gray f64",
            &enumerate_gray(&lcp, &GraySettings::default()).expect("n ≤ 20"),
        );
        push("lemke f64", &lemke(&lcp, &LemkeSettings::default()));
        push(
            "pgs 100",
            &pgs(
                &lcp,
                &PgsSettings {
                    max_iterations: 100,
                    tolerance: 1e-12,
                },
            ),
        );
        let batch = crate::cpu::batch::solve_island(&lcp, None, &Default::default());
        push("cpu batch f64", &batch.solution);
    }
    points
}

/// M + αI: makes a positive semidefinite M definite (one solution), at the
/// price of an error of order α‖z‖ on the original problem. α = 0 (the
/// default everywhere) leaves the problem untouched.
pub fn regularized(lcp: &Lcp, alpha: f64) -> Lcp {
    let n = lcp.n();
    let mut m = lcp.m.clone();
    for i in 0..n {
        m[i * n + i] += alpha;
    }
    Lcp {
        m,
        q: lcp.q.clone(),
    }
}

/// Draws error against condition number (log–log), one colour per solver.
pub fn plot_error_vs_condition(
    points: &[StressPoint],
    path: &std::path::Path,
) -> Result<(), crate::Error> {
    use plotters::prelude::*;
    let plot_err = |e: String| crate::Error::Io {
        path: path.to_path_buf(),
        source: std::io::Error::other(e),
    };
    let floor = 1e-18;
    let pts: Vec<&StressPoint> = points.iter().filter(|p| p.condition.is_finite()).collect();
    let xmax = pts.iter().map(|p| p.condition).fold(10.0f64, f64::max) * 2.0;
    let ymax = pts.iter().map(|p| p.error).fold(1e-10f64, f64::max) * 2.0;
    let root = SVGBackend::new(path, (1000, 700)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| plot_err(e.to_string()))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "error against the condition number of the chosen basis",
            ("sans-serif", 20),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d((0.5f64..xmax).log_scale(), (floor..ymax).log_scale())
        .map_err(|e| plot_err(e.to_string()))?;
    chart
        .configure_mesh()
        .x_desc("condition number (1-norm) of M_SS")
        .y_desc("error (Siconos measure; 0 drawn at 1e-18)")
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()
        .map_err(|e| plot_err(e.to_string()))?;
    let mut solvers: Vec<&str> = Vec::new();
    for p in &pts {
        if !solvers.contains(&p.solver.as_str()) {
            solvers.push(&p.solver);
        }
    }
    let colors = [
        BLACK,
        RED,
        BLUE,
        GREEN,
        MAGENTA,
        CYAN,
        RGBColor(255, 140, 0),
        RGBColor(128, 0, 128),
    ];
    for (i, s) in solvers.iter().enumerate() {
        let c = colors[i % colors.len()];
        chart
            .draw_series(
                pts.iter().filter(|p| p.solver == *s).map(|p| {
                    Circle::new((p.condition.max(1.0), p.error.max(floor)), 2, c.filled())
                }),
            )
            .map_err(|e| plot_err(e.to_string()))?
            .label(s.to_string())
            .legend(move |(x, y)| Circle::new((x + 8, y), 4, c.filled()));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(|e| plot_err(e.to_string()))?;
    root.present().map_err(|e| plot_err(e.to_string()))
}

/// The GPU on `cases`: its own answer (z in the shader's precision) and the
/// validated one. Returns the points and the repaired count.
pub fn run_gpu(
    ctx: &crate::gpu::GpuContext,
    label: &str,
    cases: &[StressCase],
) -> Result<(Vec<StressPoint>, usize), crate::Error> {
    use crate::cpu::enumeration::{enumerate, EnumerationSettings};
    let lcps: Vec<Lcp> = cases.iter().map(|c| c.lcp.clone()).collect();
    let res = crate::gpu::solve_lcp_batch(ctx, &lcps, &Default::default())?;
    let p = ctx.precision().name();
    let mut points = Vec::new();
    for (c, o) in cases.iter().zip(&res.islands) {
        let reference = enumerate(&c.lcp, &EnumerationSettings::default()).expect("n ≤ 20");
        let condition = reference
            .basis
            .map_or(f64::NAN, |b| basis_condition(&c.lcp, b));
        let raw_z = if o.gpu_z.len() == c.lcp.n() {
            o.gpu_z.clone()
        } else {
            o.solution.z.clone()
        };
        for (solver, z, status) in [
            (
                format!("gpu {p} (no polish)"),
                raw_z,
                crate::bench::gpu_own_status(o),
            ),
            (
                format!("gpu {p} + polish"),
                o.solution.z.clone(),
                o.solution.status,
            ),
        ] {
            let res = c.lcp.residuals(&z);
            let w = c.lcp.w(&z);
            points.push(StressPoint {
                family: label.to_string(),
                solver,
                parameter: c.parameter,
                condition,
                error: res.error,
                status: status.name().to_string(),
                status_matches_reference: status == reference.status,
                finite: z.iter().chain(&w).all(|v| v.is_finite()) && res.error.is_finite(),
            });
        }
    }
    Ok((points, res.report.repaired))
}

/// What `lcpbatch stress` runs.
#[derive(Clone, Debug)]
pub struct StressOptions {
    /// Cases per family (default 500).
    pub cases: usize,
    pub seed: u64,
    /// The Siconos folder for the scaled family; None: skip it.
    pub siconos: Option<std::path::PathBuf>,
    pub out_dir: std::path::PathBuf,
    pub gpu: Option<crate::gpu::GpuOptions>,
    /// M + αI on every problem (default 0).
    pub regularization: f64,
}

impl Default for StressOptions {
    fn default() -> Self {
        StressOptions {
            cases: 500,
            seed: 2026,
            siconos: None,
            out_dir: "stress-out".into(),
            gpu: Some(crate::gpu::GpuOptions::default()),
            regularization: 0.0,
        }
    }
}

/// Runs every family through the CPU solvers and the GPU (f32 and, where
/// the adapter has it, f64), prints the table, writes `stress.json` and
/// `error_vs_condition.svg`.
pub fn run(opts: &StressOptions) -> Result<Vec<StressRow>, crate::Error> {
    std::fs::create_dir_all(&opts.out_dir).map_err(|source| crate::Error::Io {
        path: opts.out_dir.clone(),
        source,
    })?;
    let contexts = crate::bench::gpu_contexts(&opts.gpu);
    let mut sets: Vec<(String, Vec<StressCase>)> = Family::ALL
        .iter()
        .map(|&f| (f.name().to_string(), generate(f, opts.seed, opts.cases)))
        .collect();
    if let Some(dir) = &opts.siconos {
        sets.push((
            "siconos_scaled".into(),
            siconos_scaled(dir)?.into_iter().map(|(_, c)| c).collect(),
        ));
    }
    let bar = indicatif::ProgressBar::new(sets.len() as u64);
    let mut points = Vec::new();
    let mut repaired = std::collections::HashMap::new();
    for (label, cases) in &sets {
        bar.set_message(label.clone());
        points.extend(run_cpu(label, cases, opts.regularization));
        if opts.regularization == 0.0 {
            for ctx in &contexts {
                let (pts, rep) = run_gpu(ctx, label, cases)?;
                repaired.insert(
                    (
                        label.clone(),
                        format!("gpu {} + polish", ctx.precision().name()),
                    ),
                    rep,
                );
                points.extend(pts);
            }
        }
        bar.inc(1);
    }
    bar.finish_and_clear();
    let mut rows = summarise(&points);
    for r in &mut rows {
        r.repaired = repaired.get(&(r.family.clone(), r.solver.clone())).copied();
    }
    println!(
        "{:<22} {:<26} {:>6} {:>9} {:>9} {:>9} {:>8} {:>9} {:>9}",
        "family", "solver", "cases", "median", "p99", "max", "status=", "non-fin.", "repaired"
    );
    for r in &rows {
        println!(
            "{:<22} {:<26} {:>6} {:>9.1e} {:>9.1e} {:>9.1e} {:>7.1}% {:>9} {:>9}",
            r.family,
            r.solver,
            r.cases,
            r.median_error,
            r.p99_error,
            r.max_error,
            100.0 * r.status_match,
            r.non_finite,
            r.repaired.map_or("-".into(), |v| v.to_string())
        );
    }
    #[derive(serde::Serialize)]
    struct File<'a> {
        machine: String,
        regularization: f64,
        rows: &'a [StressRow],
        points: &'a [StressPoint],
    }
    let file = File {
        machine: crate::bench::machine_description(&contexts),
        regularization: opts.regularization,
        rows: &rows,
        points: &points,
    };
    crate::io::write_atomically(
        &opts.out_dir.join("stress.json"),
        &serde_json::to_string(&file).expect("serialisable"),
    )?;
    plot_error_vs_condition(&points, &opts.out_dir.join("error_vs_condition.svg"))?;
    println!(
        "wrote {}/{{stress.json, error_vs_condition.svg}}",
        opts.out_dir.display()
    );
    Ok(rows)
}
