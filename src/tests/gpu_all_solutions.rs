//! `all_solutions` on the GPU (`shaders/enumeration_all.wgsl`, every basis
//! of every island screened on the device, the flagged ones decided in f64)
//! against the CPU's enumeration through the same door: the same statuses,
//! solution sets, chosen bases and lists of solution bases, on the Siconos
//! conformance problems, the 3×3 Lemke walk-through, and generated
//! degenerate, resting, non-unique and infeasible families; scenes give the
//! same impulses.

use crate::generate::stress::{generate, Family};
use crate::generate::{box_on_ground, random_scene, seed_chain, Rng};
use crate::gpu::Precision;
use crate::io::{read_input, Input};
use crate::settings::{Backend, GpuSettings, Method, Settings};
use crate::{GpuContext, Lcp, Report, Solver};

use super::common::{gpu_settings_or_skip, seed_002_problems, siconos_dir};

fn all_solutions() -> Settings {
    Settings {
        all_solutions: true,
        ..Settings::new(Backend::Cpu, Method::Enumeration)
    }
}

/// A GPU solver at `precision` (None: skipped, see the common helper).
fn gpu_solver(precision: Precision) -> Option<Solver> {
    let mut g: GpuSettings = gpu_settings_or_skip()?;
    if precision == Precision::F32 {
        g.precision = Precision::F32;
    } else if g.precision != Precision::F64 {
        return None; // the skip is announced by gpu_settings_or_skip
    }
    let device = GpuContext::open(&g).expect("the adapter opened a moment ago");
    let settings = Settings {
        gpu: g,
        ..all_solutions()
    };
    Some(Solver::with_device(settings, device).unwrap())
}

/// The problems: Siconos (n ≤ 16) when the conformance data is there, the
/// 3×3 Lemke walk-through's, and the stress families with several solutions, none, or singular M.
fn problems() -> Vec<(String, Lcp)> {
    let mut out = Vec::new();
    if let Some(dir) = siconos_dir() {
        let paths = super::common::dat_files(&dir);
        for p in paths {
            if let Ok(Input::Lcps(v)) = read_input(&p) {
                let name = p.file_name().unwrap().to_string_lossy().to_string();
                out.extend(
                    v.into_iter()
                        .filter(|l| l.n() <= 16)
                        .map(|l| (name.clone(), l)),
                );
            }
        }
    }
    for (k, l) in seed_002_problems().into_iter().enumerate() {
        out.push((format!("Lemke walk-through #{k}"), l));
    }
    for family in [
        Family::NonSymmetric,
        Family::Infeasible,
        Family::RestingStacks,
        Family::Chains,
        Family::NearParallelNormals,
    ] {
        for (k, c) in generate(family, 7, 12).into_iter().enumerate() {
            if c.lcp.n() <= 16 {
                out.push((format!("{} #{k}", family.name()), c.lcp));
            }
        }
    }
    out
}

/// Same status, solution set, chosen basis, solution bases and z on every
/// problem; returns how many had more than one solution.
fn assert_same(names: &[String], gpu: &Report, cpu: &Report, exact: bool) -> usize {
    let mut several = 0;
    for ((name, g), c) in names.iter().zip(&gpu.islands).zip(&cpu.islands) {
        let (g, c) = (&g.solution, &c.solution);
        assert_eq!(g.status, c.status, "{name}: status");
        assert_eq!(g.solution_set, c.solution_set, "{name}: solution set");
        assert_eq!(g.basis, c.basis, "{name}: chosen basis");
        let bases =
            |s: &crate::LcpSolution| s.all_bases.iter().map(|b| b.basis).collect::<Vec<_>>();
        assert_eq!(bases(g), bases(c), "{name}: solution bases");
        // The same bases re-solved by the same f64 code: the same z.
        assert_eq!(g.z, c.z, "{name}: z");
        assert_eq!(g.counters.bases_visited, c.counters.bases_visited, "{name}");
        if exact {
            assert_eq!(
                g.counters.singular_bases, c.counters.singular_bases,
                "{name}"
            );
        }
        several += usize::from(g.all_bases.len() > 1);
    }
    several
}

#[test]
fn every_solution_on_the_gpu_is_the_cpus_in_both_precisions() {
    let (names, lcps): (Vec<String>, Vec<Lcp>) = problems().into_iter().unzip();
    assert!(lcps.len() >= 60, "{} problems", lcps.len());
    let cpu = Solver::new(all_solutions())
        .unwrap()
        .solve_lcps(&lcps)
        .unwrap();
    for precision in [Precision::F64, Precision::F32] {
        let Some(mut solver) = gpu_solver(precision) else {
            continue;
        };
        let gpu = solver.solve_lcps(&lcps).unwrap();
        assert!(gpu.on_gpu(), "{precision:?}: {:?}", gpu.fallback);
        assert_eq!(gpu.counts.enumerated_gpu, lcps.len(), "{precision:?}");
        let several = assert_same(&names, &gpu, &cpu, precision == Precision::F64);
        println!(
            "{precision:?}: {} problems, {several} with several solutions; statuses {:?}; {}",
            lcps.len(),
            gpu.status_counts(),
            gpu.timings.gpu
        );
        assert!(
            several >= 5,
            "the families must include non-unique problems"
        );
    }
}

#[test]
fn scenes_with_every_solution_on_the_gpu_give_the_cpus_impulses() {
    let mut rng = Rng::new(31);
    let mut scenes = vec![box_on_ground(1.0, 0.0), seed_chain(0.3)];
    scenes.extend((0..6).map(|_| random_scene(&mut rng, 4, 8, 1e2)));
    let cpu = Solver::new(all_solutions())
        .unwrap()
        .solve_scenes(&scenes)
        .unwrap();
    let Some(mut solver) = gpu_solver(Precision::F64) else {
        return;
    };
    let gpu = solver.solve_scenes(&scenes).unwrap();
    assert!(gpu.on_gpu());
    let names: Vec<String> = (0..gpu.islands.len())
        .map(|i| format!("island {i}"))
        .collect();
    assert_same(&names, &gpu, &cpu, true);
    for (g, c) in gpu.scenes.iter().zip(&cpu.scenes) {
        assert_eq!(g.impulses, c.impulses);
    }
}

#[test]
fn the_screen_flags_exactly_the_bases_its_cpu_twin_flags_in_f64() {
    use crate::cpu::enumeration::{solve_basis, BasisOutcome, EnumerationSettings};
    use crate::cpu::enumeration_tree::TreeSettings;
    use crate::gpu::all_bases::screen_all_bases;
    use crate::gpu::{GpuSolveSettings, MAX_GPU_N};
    let Some(g) = gpu_settings_or_skip() else {
        return;
    };
    if g.precision != Precision::F64 {
        return; // the skip is announced by gpu_settings_or_skip
    }
    let ctx = GpuContext::open(&g).unwrap();
    let lcps: Vec<Lcp> = problems()
        .into_iter()
        .map(|(_, l)| l)
        .filter(|l| l.n() <= 10)
        .collect();
    let refs: Vec<&Lcp> = lcps.iter().collect();
    let (screened, _) = screen_all_bases(&ctx, &refs, &GpuSolveSettings::default()).unwrap();
    let e = EnumerationSettings::default();
    // The f64 screen's tolerance: the relaxed one or the tree's screen.
    let screen = e
        .relaxed_feasibility_tol
        .max(TreeSettings::default().screen_tol);
    let (mut flagged, mut total) = (0, 0);
    for (l, s) in lcps.iter().zip(&screened) {
        assert!(l.n() <= MAX_GPU_N);
        let mut want = Vec::new();
        let mut singular = 0;
        for mask in 0..1u32 << l.n() {
            match solve_basis(l, mask, &e) {
                BasisOutcome::Singular => singular += 1,
                BasisOutcome::Solved { infeasibility, .. } if infeasibility <= screen => {
                    want.push(mask)
                }
                BasisOutcome::Solved { .. } => {}
            }
        }
        assert_eq!(s.candidates, want, "n = {}", l.n());
        assert_eq!(s.trusted_singular, singular, "n = {}", l.n());
        flagged += want.len();
        total += 1usize << l.n();
    }
    // It screens: most bases are not solutions.
    println!("{flagged} of {total} bases flagged");
    assert!(flagged * 4 < total, "{flagged} of {total}");
}
