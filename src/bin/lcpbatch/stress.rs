//! `lcpbatch stress`: the stress families of `lcpbatch::generate::stress`
//! through every method and precision, against the f64 enumeration: error
//! distributions, status agreement, repaired counts, error against the
//! condition number. Every solve goes through the library's one door.

use std::path::PathBuf;

use lcpbatch::generate::stress::{basis_condition, generate, siconos_scaled, Family, StressCase};
use lcpbatch::io::write_atomically;
use lcpbatch::{Backend, Error, GpuSettings, Lcp, Method, Report, Settings, Solver, Status};

use crate::devices::{gpu_solvers, machine_description};
use crate::plots;

/// One method's result on one stress case, next to the f64 reference.
#[derive(Clone, Debug, serde::Serialize)]
pub struct StressPoint {
    pub family: String,
    pub solver: String,
    pub parameter: f64,
    /// Condition number of the reference basis' principal submatrix.
    pub condition: f64,
    /// The error measure of z on the problem as posed; None (`null`, "n/a"
    /// in the table) where the status claims no z: no solution, a ray, an
    /// input the method cannot take (an error of 1 there measured only z = 0).
    pub error: Option<f64>,
    pub status: String,
    pub status_matches_reference: bool,
    /// Every z and w finite.
    pub finite: bool,
}

/// Summary of one family and one method.
#[derive(Clone, Debug, serde::Serialize)]
pub struct StressRow {
    pub family: String,
    pub solver: String,
    pub cases: usize,
    /// Over the cases with an error (see [`StressPoint::error`]); None
    /// when no case has one.
    pub median_error: Option<f64>,
    pub p99_error: Option<f64>,
    pub max_error: Option<f64>,
    /// Share of cases whose status equals the f64 exhaustive enumeration's.
    pub status_match: f64,
    /// Cases with a NaN or Inf in z or w (must be 0).
    pub non_finite: usize,
    /// Islands the GPU validation had to re-solve on the CPU (GPU rows only).
    pub repaired: Option<usize>,
}

/// What `lcpbatch stress` runs.
#[derive(Clone, Debug)]
pub struct StressOptions {
    /// Cases per family.
    pub cases: usize,
    pub seed: u64,
    /// The Siconos folder for the scaled family; None: skip it.
    pub siconos: Option<PathBuf>,
    pub out_dir: PathBuf,
    /// None: CPU only.
    pub gpu: Option<GpuSettings>,
    /// M + αI on every problem (0: the problem as posed).
    pub regularization: f64,
}

/// Summarises points per (family, method), in first-seen order.
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
            let mut e: Vec<f64> = ps.iter().filter_map(|p| p.error).collect();
            e.sort_by(f64::total_cmp);
            let q = |f: f64| {
                e.get(((e.len() as f64 - 1.0) * f).round() as usize)
                    .copied()
            };
            StressRow {
                cases: ps.len(),
                median_error: q(0.5),
                p99_error: q(0.99),
                max_error: e.last().copied(),
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

/// M + αI: makes a positive semidefinite M definite (one solution), at the
/// price of an error of order α‖z‖ on the original problem.
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

/// Whether a status comes with a z whose error means something: a solution,
/// the last iterate at a cap, or an answer that failed the final check; not
/// `no_solution`, `ray_termination` or `invalid_input`, which claim none.
fn has_z(status: Status) -> bool {
    !matches!(
        status,
        Status::NoSolution | Status::RayTermination | Status::InvalidInput
    )
}

/// The points of one method's report on `cases`, against the reference.
fn points_of(
    label: &str,
    solver: &str,
    cases: &[StressCase],
    reference: &Report,
    conditions: &[f64],
    report: &Report,
) -> Vec<StressPoint> {
    cases
        .iter()
        .zip(&report.islands)
        .zip(reference.islands.iter().zip(conditions))
        .map(|((c, isl), (r, &condition))| {
            // Errors are measured on the problem as posed, before regularisation.
            let res = c.lcp.residuals(&isl.solution.z);
            let s = &isl.solution;
            let error = has_z(isl.status()).then_some(res.error);
            StressPoint {
                family: label.into(),
                solver: solver.into(),
                parameter: c.parameter,
                condition,
                error,
                status: isl.status().name().into(),
                status_matches_reference: isl.status() == r.status(),
                finite: s.z.iter().chain(&s.w).all(|v| v.is_finite())
                    && error.is_none_or(f64::is_finite),
            }
        })
        .collect()
}

fn cpu(method: Method, f: impl FnOnce(&mut Settings)) -> Result<Solver, Error> {
    let mut s = Settings {
        threads: 1,
        ..Settings::new(Backend::Cpu, method)
    };
    f(&mut s);
    Solver::new(s)
}

/// One family through the f64 reference (bare enumeration) and every
/// method; the GPU solvers too when the problem is not regularised.
/// Returns the points and the repaired count per GPU method.
fn run_family(
    label: &str,
    cases: &[StressCase],
    regularization: f64,
    gpus: &mut [Solver],
) -> Result<(Vec<StressPoint>, Vec<(String, usize)>), Error> {
    let lcps: Vec<Lcp> = cases
        .iter()
        .map(|c| match regularization > 0.0 {
            true => regularized(&c.lcp, regularization),
            false => c.lcp.clone(),
        })
        .collect();
    let reference = cpu(Method::Enumeration, |s| s.predict = false)?.solve_lcps(&lcps)?;
    let conditions: Vec<f64> = lcps
        .iter()
        .zip(&reference.islands)
        .map(|(l, r)| r.solution.basis.map_or(f64::NAN, |b| basis_condition(l, b)))
        .collect();
    let mut points = points_of(
        label,
        "enum f64 (reference)",
        cases,
        &reference,
        &conditions,
        &reference,
    );
    let methods: [(&str, Method, fn(&mut Settings)); 3] = [
        ("auto f64", Method::Auto, |_| {}),
        ("lemke f64", Method::Lemke, |_| {}),
        ("pgs 100", Method::Pgs, |s| {
            s.pgs_max_sweeps = 100;
            s.pgs_tolerance = 1e-12;
        }),
    ];
    for (name, method, f) in methods {
        let r = cpu(method, f)?.solve_lcps(&lcps)?;
        points.extend(points_of(label, name, cases, &reference, &conditions, &r));
    }
    let mut repaired = Vec::new();
    if regularization == 0.0 {
        for g in gpus.iter_mut() {
            let r = g.solve_lcps(&lcps)?;
            let name = format!("gpu {} + polish", g.device().precision.name());
            repaired.push((name.clone(), r.counts.repaired));
            points.extend(points_of(label, &name, cases, &reference, &conditions, &r));
        }
    }
    Ok((points, repaired))
}

/// An error in the table: `1.2e-15`, or `n/a` where no case has one.
fn error_cell(e: Option<f64>) -> String {
    e.map_or("n/a".into(), |e| format!("{e:.1e}"))
}

fn print_rows(rows: &[StressRow]) {
    println!(
        "{:<22} {:<26} {:>6} {:>9} {:>9} {:>9} {:>8} {:>9} {:>9}",
        "family", "solver", "cases", "median", "p99", "max", "status=", "non-fin.", "repaired"
    );
    for r in rows {
        println!(
            "{:<22} {:<26} {:>6} {:>9} {:>9} {:>9} {:>7.1}% {:>9} {:>9}",
            r.family,
            r.solver,
            r.cases,
            error_cell(r.median_error),
            error_cell(r.p99_error),
            error_cell(r.max_error),
            100.0 * r.status_match,
            r.non_finite,
            r.repaired.map_or("-".into(), |v| v.to_string())
        );
    }
}

/// Runs every family, prints the table, writes `stress.json` and
/// `error_vs_condition.svg` into `opts.out_dir`.
pub fn run(opts: &StressOptions) -> Result<Vec<StressRow>, Error> {
    std::fs::create_dir_all(&opts.out_dir).map_err(|source| Error::Io {
        path: opts.out_dir.clone(),
        source,
    })?;
    let mut gpus = gpu_solvers(&opts.gpu, &crate::settings());
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
        let (pts, rep) = run_family(label, cases, opts.regularization, &mut gpus)?;
        points.extend(pts);
        for (solver, n) in rep {
            repaired.insert((label.clone(), solver), n);
        }
        bar.inc(1);
    }
    bar.finish_and_clear();
    let mut rows = summarise(&points);
    for r in &mut rows {
        r.repaired = repaired.get(&(r.family.clone(), r.solver.clone())).copied();
    }
    print_rows(&rows);
    #[derive(serde::Serialize)]
    struct File<'a> {
        machine: String,
        regularization: f64,
        rows: &'a [StressRow],
        points: &'a [StressPoint],
    }
    let file = File {
        machine: machine_description(&gpus),
        regularization: opts.regularization,
        rows: &rows,
        points: &points,
    };
    write_atomically(
        &opts.out_dir.join("stress.json"),
        &serde_json::to_string(&file).expect("serialisable"),
    )?;
    let scatter: Vec<(f64, f64, String)> = points
        .iter()
        .filter(|p| p.condition.is_finite())
        .filter_map(|p| Some((p.condition.max(1.0), p.error?.max(1e-18), p.solver.clone())))
        .collect();
    plots::scatter(
        &scatter,
        &opts.out_dir.join("error_vs_condition.svg"),
        "error against the condition number of the chosen basis",
        (
            "condition number (1-norm) of M_SS",
            "error (Siconos measure; 0 drawn at 1e-18)",
        ),
        false,
    )?;
    println!(
        "wrote {}/{{stress.json, error_vs_condition.svg}}",
        opts.out_dir.display()
    );
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_family_agrees_with_the_reference_on_the_cpu() {
        for f in Family::ALL {
            let cases = generate(f, 3, 25);
            let (points, _) = run_family(f.name(), &cases, 0.0, &mut []).unwrap();
            let rows = summarise(&points);
            for r in &rows {
                assert_eq!(r.non_finite, 0, "{} {}", r.family, r.solver);
                if r.solver.starts_with("auto") || r.solver.starts_with("enum") {
                    assert_eq!(r.status_match, 1.0, "{} {}", r.family, r.solver);
                }
            }
        }
    }

    #[test]
    fn problems_without_a_solution_have_no_error_to_report() {
        let cases = generate(Family::Infeasible, 4, 10);
        let (points, _) = run_family("infeasible", &cases, 0.0, &mut []).unwrap();
        let rows = summarise(&points);
        // Enumeration proves there is no solution: no z, so no error (it
        // used to print 1.0, the error of z = 0).
        let reference: Vec<&StressPoint> = points
            .iter()
            .filter(|p| p.solver.starts_with("enum"))
            .collect();
        assert_eq!(reference.len(), 10);
        assert!(reference
            .iter()
            .all(|p| p.status == "no_solution" && p.error.is_none() && p.finite));
        let row = rows.iter().find(|r| r.solver.starts_with("enum")).unwrap();
        assert_eq!((row.median_error, row.max_error), (None, None));
        assert_eq!(error_cell(row.max_error), "n/a");
        assert_eq!(error_cell(Some(1.5e-15)), "1.5e-15");
        // PGS at its cap keeps its last iterate's error.
        let pgs: Vec<&StressPoint> = points.iter().filter(|p| p.solver == "pgs 100").collect();
        assert!(pgs
            .iter()
            .filter(|p| p.status == "not_converged")
            .all(|p| p.error.is_some()));
        let json = serde_json::to_string(&row).unwrap();
        assert!(json.contains(r#""max_error":null"#), "{json}");
    }

    #[test]
    fn regularization_makes_resting_stacks_definite() {
        let cases = generate(Family::RestingStacks, 5, 20);
        let (points, _) = run_family("resting", &cases, 1e-6, &mut []).unwrap();
        let auto: Vec<&StressPoint> = points.iter().filter(|p| p.solver == "auto f64").collect();
        assert!(!auto.is_empty());
        assert!(auto
            .iter()
            .all(|p| p.error.is_some_and(|e| e < 1e-3) && p.finite));
    }
}
