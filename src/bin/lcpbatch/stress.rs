//! Stress families: contact LCPs that are badly conditioned, degenerate,
//! without a P-matrix, or without any solution, from fixed seeds. Every case
//! carries the parameter that makes it hard (a mass ratio, a scale, an angle)
//! so that a report can plot the error against it.

use glam::{DMat3, DVec3};

use crate::generate::{ball_body, box_body, random_island, Rng};
use crate::lcp::Lcp;
use crate::pipeline::build;
use crate::scene::{Body, Contact, Scene};

/// A family of stress problems.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Family {
    /// Random physical islands with masses spread over a ratio of 1 … 1e8.
    MassRatio,
    /// Random islands with every length multiplied by 1e-3 … 1e3 (inertia follows).
    LengthScale,
    /// Random islands with every velocity multiplied by 1e-3 … 1e3.
    VelocityScale,
    /// A ball on the ground touching it at two points whose normals differ by
    /// an angle down to 1e-8 (and 0: duplicate contacts).
    NearParallelNormals,
    /// Boxes resting on the ground and stacked, 4 coplanar contacts per face:
    /// rank-deficient M.
    RestingStacks,
    /// Chains of bodies as in the seed's figure 7, up to n = 16.
    Chains,
    /// Random non-symmetric matrices that are not P-matrices: several solutions or none.
    NonSymmetric,
    /// LCPs built to have no solution: a row with M_ij ≤ 0 everywhere and q_i < 0.
    Infeasible,
    /// The Siconos problems scaled by 1e±6 (from files: see [`siconos_scaled`];
    /// [`generate`] makes none).
    SiconosScaled,
}

impl Family {
    pub const ALL: [Family; 8] = [
        Family::MassRatio,
        Family::LengthScale,
        Family::VelocityScale,
        Family::NearParallelNormals,
        Family::RestingStacks,
        Family::Chains,
        Family::NonSymmetric,
        Family::Infeasible,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Family::MassRatio => "mass_ratio",
            Family::LengthScale => "length_scale",
            Family::VelocityScale => "velocity_scale",
            Family::NearParallelNormals => "near_parallel_normals",
            Family::RestingStacks => "resting_stacks",
            Family::Chains => "chains",
            Family::NonSymmetric => "non_symmetric",
            Family::Infeasible => "infeasible",
            Family::SiconosScaled => "siconos_scaled",
        }
    }
}

/// One stress problem.
#[derive(Clone, Debug)]
pub struct StressCase {
    pub family: Family,
    /// What makes it hard: the mass ratio, the scale, the angle, n.
    pub parameter: f64,
    pub lcp: Lcp,
}

fn islands_of(scene: &Scene) -> Vec<Lcp> {
    build(scene, "stress scene")
        .expect("generated scenes are valid")
        .2
}

fn scaled_lengths(mut scene: Scene, s: f64) -> Scene {
    for b in &mut scene.bodies {
        b.position = (DVec3::from_array(b.position) * s).to_array();
        for row in &mut b.inv_inertia {
            for v in row {
                *v /= s * s;
            }
        }
        // Keep point velocities comparable: ω scales with 1/s.
        b.angular_velocity = (DVec3::from_array(b.angular_velocity) / s).to_array();
    }
    for c in &mut scene.contacts {
        c.point = (DVec3::from_array(c.point) * s).to_array();
    }
    scene
}

fn scaled_velocities(mut scene: Scene, s: f64) -> Scene {
    for b in &mut scene.bodies {
        b.velocity = (DVec3::from_array(b.velocity) * s).to_array();
        b.angular_velocity = (DVec3::from_array(b.angular_velocity) * s).to_array();
    }
    scene
}

fn contact(a: usize, b: Option<usize>, point: DVec3, normal: DVec3, restitution: f64) -> Contact {
    Contact {
        a,
        b,
        point: point.to_array(),
        normal: normal.to_array(),
        restitution,
        id: None,
    }
}

/// A ball of radius 0.5 falling onto the ground with two contacts at the
/// bottom, the second normal tilted by `angle` about z.
fn near_parallel(angle: f64, rng: &mut Rng) -> Scene {
    let mut ball = ball_body(1.0, 0.5, DVec3::new(0.0, 0.5, 0.0));
    ball.velocity = [
        rng.range(-0.5, 0.5),
        -rng.range(0.5, 2.0),
        rng.range(-0.5, 0.5),
    ];
    let n2 = DVec3::new(-angle.sin(), angle.cos(), 0.0);
    Scene {
        bodies: vec![ball],
        contacts: vec![
            contact(0, None, DVec3::ZERO, DVec3::Y, 0.0),
            contact(0, None, DVec3::new(1e-3 * rng.unit(), 0.0, 0.0), n2, 0.0),
        ],
    }
}

/// `levels` unit boxes stacked on the ground, each face 4 contacts.
fn stack(levels: usize, rng: &mut Rng) -> Scene {
    let mut bodies = vec![Body::fixed([0.0, -0.5, 0.0])];
    let mut contacts = Vec::new();
    let e = if rng.unit() < 0.5 {
        0.0
    } else {
        rng.range(0.0, 0.5)
    };
    for l in 0..levels {
        let mut b = box_body(
            rng.log_range(0.5, 10.0),
            DVec3::splat(0.5),
            DMat3::IDENTITY,
            DVec3::new(0.0, 0.5 + l as f64, 0.0),
        );
        b.velocity = [0.0, -rng.range(0.0, 1.0), 0.0];
        bodies.push(b);
        let (a, below) = (bodies.len() - 1, bodies.len() - 2);
        for (dx, dz) in [(-0.5, -0.5), (0.5, -0.5), (-0.5, 0.5), (0.5, 0.5)] {
            contacts.push(contact(
                a,
                Some(below),
                DVec3::new(dx, l as f64, dz),
                DVec3::Y,
                e,
            ));
        }
    }
    Scene { bodies, contacts }
}

/// A chain of boxes along x with `n` contacts in all: one or two contacts per
/// interface, the first body pushed into the others (seed figure 7 extended).
fn chain(n: usize, rng: &mut Rng) -> Scene {
    let mut bodies = Vec::new();
    let mut contacts = Vec::new();
    let mut i = 0;
    bodies.push({
        let mut b = box_body(
            rng.log_range(1.0, 10.0),
            DVec3::splat(0.5),
            DMat3::IDENTITY,
            DVec3::ZERO,
        );
        b.velocity = [1.0, 0.0, 0.0];
        b
    });
    while contacts.len() < n {
        i += 1;
        let mut b = box_body(
            rng.log_range(1.0, 10.0),
            DVec3::splat(0.5),
            DMat3::IDENTITY,
            DVec3::new(i as f64, 0.0, 0.0),
        );
        b.velocity = [rng.range(-0.5, 0.5), 0.0, 0.0];
        bodies.push(b);
        let per = if contacts.len() + 2 <= n && rng.unit() < 0.5 {
            2
        } else {
            1
        };
        for _ in 0..per {
            let p = DVec3::new(i as f64 - 0.5, rng.range(-0.4, 0.4), rng.range(-0.4, 0.4));
            contacts.push(contact(i, Some(i - 1), p, DVec3::X, rng.range(0.0, 1.0)));
        }
    }
    Scene { bodies, contacts }
}

/// Generates about `count` cases of `family` from `seed` (islands from one
/// scene are kept together, so the count can be exceeded slightly).
pub fn generate(family: Family, seed: u64, count: usize) -> Vec<StressCase> {
    let mut rng = Rng::new(seed ^ (family as u64).wrapping_mul(0x9E37_79B9));
    let mut out = Vec::with_capacity(count);
    if family == Family::SiconosScaled {
        return out;
    }
    let mut k = 0usize;
    while out.len() < count {
        let mut push = |parameter: f64, lcps: Vec<Lcp>| {
            out.extend(lcps.into_iter().map(|lcp| StressCase {
                family,
                parameter,
                lcp,
            }));
        };
        match family {
            Family::MassRatio => {
                let ratio = [1.0, 1e2, 1e4, 1e6, 1e8][k % 5];
                let n = rng.int(1, 8);
                push(ratio, islands_of(&random_island(&mut rng, n, ratio)));
            }
            Family::LengthScale => {
                let s = [1e-3, 1e-1, 1.0, 1e1, 1e3][k % 5];
                let n = rng.int(1, 8);
                push(
                    s,
                    islands_of(&scaled_lengths(random_island(&mut rng, n, 10.0), s)),
                );
            }
            Family::VelocityScale => {
                let s = [1e-3, 1e-1, 1.0, 1e1, 1e3][k % 5];
                let n = rng.int(1, 8);
                push(
                    s,
                    islands_of(&scaled_velocities(random_island(&mut rng, n, 10.0), s)),
                );
            }
            Family::NearParallelNormals => {
                let angle = [1e-2, 1e-4, 1e-6, 1e-8, 0.0][k % 5];
                push(angle, islands_of(&near_parallel(angle, &mut rng)));
            }
            Family::RestingStacks => {
                let levels = 1 + k % 3;
                push(levels as f64, islands_of(&stack(levels, &mut rng)));
            }
            Family::Chains => {
                let n = 1 + k % 16;
                push(n as f64, islands_of(&chain(n, &mut rng)));
            }
            Family::NonSymmetric => {
                let n = rng.int(2, 8);
                let m: Vec<f64> = (0..n * n).map(|_| rng.range(-1.0, 1.0)).collect();
                let q: Vec<f64> = (0..n).map(|_| rng.range(-1.0, 1.0)).collect();
                push(n as f64, vec![Lcp { m, q }]);
            }
            Family::Infeasible => {
                let n = rng.int(1, 8);
                let bad = rng.int(0, n - 1);
                let mut m: Vec<f64> = (0..n * n).map(|_| rng.range(-1.0, 1.0)).collect();
                for j in 0..n {
                    m[bad * n + j] = -rng.range(0.0, 1.0);
                }
                let mut q: Vec<f64> = (0..n).map(|_| rng.range(-1.0, 1.0)).collect();
                q[bad] = -rng.range(0.1, 1.0);
                push(n as f64, vec![Lcp { m, q }]);
            }
            Family::SiconosScaled => unreachable!("returned above"),
        }
        k += 1;
    }
    out
}

/// The same LCP with M and q both multiplied by `s`: the same z, w scaled by s.
pub fn scaled(lcp: &Lcp, s: f64) -> Lcp {
    Lcp {
        m: lcp.m.iter().map(|v| v * s).collect(),
        q: lcp.q.iter().map(|v| v * s).collect(),
    }
}

/// 1-norm condition number ‖A‖₁‖A⁻¹‖₁ of the principal submatrix M_SS of a
/// basis (1 for the empty basis, ∞ when singular to working precision).
pub fn basis_condition(lcp: &Lcp, mask: u32) -> f64 {
    let n = lcp.n();
    let idx: Vec<usize> = (0..n).filter(|&i| mask >> i & 1 == 1).collect();
    let k = idx.len();
    if k == 0 {
        return 1.0;
    }
    let a: Vec<f64> = idx
        .iter()
        .flat_map(|&i| idx.iter().map(move |&j| lcp.at(i, j)))
        .collect();
    let norm1 = |m: &[f64]| {
        (0..k)
            .map(|c| (0..k).map(|r| m[r * k + c].abs()).sum::<f64>())
            .fold(0.0, f64::max)
    };
    let mut inv = vec![0.0; k * k];
    for c in 0..k {
        let mut work = a.clone();
        let mut x = vec![0.0; k];
        x[c] = 1.0;
        if !crate::linalg::solve_in_place(&mut work, &mut x, k, 0.0) {
            return f64::INFINITY;
        }
        for r in 0..k {
            inv[r * k + c] = x[r];
        }
    }
    norm1(&a) * norm1(&inv)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_family_generates_valid_problems() {
        for f in Family::ALL {
            let cases = generate(f, 7, 20);
            assert!(cases.len() >= 20, "{f:?}");
            for c in &cases {
                c.lcp.validate(f.name()).unwrap();
            }
        }
    }

    #[test]
    fn condition_number_of_diagonal_basis() {
        let lcp = Lcp::new(vec![2.0, 0.0, 0.0, 1e-6], vec![-1.0, -1.0]).unwrap();
        assert!((basis_condition(&lcp, 0b11) - 2e6).abs() < 1e-3);
        assert_eq!(basis_condition(&lcp, 0), 1.0);
    }
}

/// The Siconos problems of `dir` (a folder of `.dat` files) with n ≤ 16,
/// each scaled by 1e-6 and by 1e6 (M and q together: same z, w scaled).
pub fn siconos_scaled(dir: &std::path::Path) -> Result<Vec<(String, StressCase)>, crate::Error> {
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .map_err(|source| crate::Error::Io {
            path: dir.to_path_buf(),
            source,
        })?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "dat"))
        .collect();
    files.sort();
    let mut out = Vec::new();
    for f in files {
        let crate::io::Input::Lcps(lcps) = crate::io::read_input(&f)? else {
            continue;
        };
        for lcp in lcps.into_iter().filter(|l| l.n() <= 16) {
            for s in [1e-6, 1e6] {
                let name = f
                    .file_stem()
                    .map(|s| s.to_string_lossy().into_owned())
                    .unwrap_or_default();
                out.push((
                    name,
                    StressCase {
                        family: Family::SiconosScaled,
                        parameter: s,
                        lcp: scaled(&lcp, s),
                    },
                ));
            }
        }
    }
    Ok(out)
}

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
