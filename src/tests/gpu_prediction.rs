//! Prediction before the GPU: islands that need no enumeration are settled
//! on the CPU and never uploaded. Results equal those with prediction off
//! (statuses; z bit for bit where the basis is the same, else to 1e-9 — the
//! predicted basis can differ from enumeration's only on degenerate islands,
//! where M ≻ 0 makes z the same), path counts add up to the islands, and a
//! warm start from the cold bases settles every island that has a basis.

use crate::cpu::enumeration::{enumerate, EnumerationSettings};
use crate::generate::{box_on_ground, demo_world, random_island, seed_chain, Rng};
use crate::gpu::batch::solve_lcp_batch_warm;
use crate::gpu::scenes::{check_and_build, solve_scenes_warm};
use crate::gpu::{solve_lcp_batch, solve_scenes, GpuSolveSettings, Precision};
use crate::{Lcp, Method, Report, Scene, SolvePath};

use super::common::gpu_context as context;

fn scenes(count: usize) -> Vec<Scene> {
    let mut rng = Rng::new(0x9e3d_2026);
    (0..count)
        .map(|k| match k % 7 {
            2 => box_on_ground(rng.range(0.1, 3.0), rng.unit()),
            4 => seed_chain(rng.unit()),
            6 => demo_world(&mut rng),
            _ => random_island(&mut rng, 1 + k % 12, [1.0, 10.0, 1e3][k % 3]),
        })
        .collect()
}

fn lcps(count: usize) -> Vec<Lcp> {
    let mut out: Vec<Lcp> = scenes(count)
        .iter()
        .flat_map(|s| crate::tests::reference::build(s, "scene").unwrap().2)
        .collect();
    // One separating island, one single contact, one invalid problem.
    out.push(Lcp::new(vec![2.0, 1.0, 1.0, 2.0], vec![1.0, 0.5]).unwrap());
    out.push(Lcp::new(vec![3.0], vec![-6.0]).unwrap());
    out.push(Lcp {
        m: vec![1.0, f64::NAN, 0.0, 1.0],
        q: vec![1.0, -1.0],
    });
    out
}

/// Islands settled by prediction.
fn predicted(r: &Report) -> usize {
    r.islands.iter().filter(|i| i.path.is_prediction()).count()
}

fn paths_add_up(r: &Report) {
    let c = &r.counts;
    let named = c.named();
    let count = |name: &str| {
        named
            .iter()
            .find(|(n, _)| *n == name)
            .map_or(0, |(_, k)| *k)
    };
    let sum: usize = SolvePath::ALL.iter().map(|p| count(p.name())).sum();
    assert_eq!(sum, r.islands.len(), "{r}");
    assert!(c.polished <= c.enumerated_gpu + c.lemke_gpu, "{r}");
    for p in SolvePath::ALL {
        let n = r.islands.iter().filter(|o| o.path == p).count();
        assert_eq!(n, count(p.name()), "{}", p.name());
    }
    // The GPU backend settles islands by prediction, on the GPU, by repair,
    // by Lemke (n > 16, or where its Lemke kernel gave up), or finds them
    // invalid; nothing else.
    for o in &r.islands {
        assert!(
            o.path.is_prediction()
                || matches!(
                    o.path,
                    SolvePath::EnumeratedGpu
                        | SolvePath::LemkeGpu
                        | SolvePath::Repaired
                        | SolvePath::Lemke
                        | SolvePath::Invalid
                ),
            "{}",
            o.path
        );
    }
}

fn same_results(a: &Report, b: &Report) {
    let mut bitwise = 0;
    for (i, (x, y)) in a.islands.iter().zip(&b.islands).enumerate() {
        assert_eq!(x.solution.status, y.solution.status, "island {i}");
        if x.solution.basis == y.solution.basis {
            assert_eq!(x.solution.z, y.solution.z, "island {i}");
            bitwise += 1;
        } else {
            let scale = x.solution.z.iter().fold(1.0f64, |m, v| m.max(v.abs()));
            for (p, q) in x.solution.z.iter().zip(&y.solution.z) {
                assert!((p - q).abs() <= 1e-9 * scale, "island {i}: {p} vs {q}");
            }
        }
    }
    println!("{bitwise} of {} islands bit for bit", a.islands.len());
}

fn on_and_off(precision: Precision) {
    let Some(ctx) = context(precision) else {
        return;
    };
    let lcps = lcps(700);
    let on = solve_lcp_batch(&ctx, &lcps, &GpuSolveSettings::default()).unwrap();
    let off = solve_lcp_batch(
        &ctx,
        &lcps,
        &GpuSolveSettings {
            predict: false,
            ..Default::default()
        },
    )
    .unwrap();
    println!("on:\n{on}\noff:\n{off}");
    paths_add_up(&on);
    paths_add_up(&off);
    assert_eq!(predicted(&off), 0);
    assert!(on.counts.separating > 0);
    assert!(on.counts.single_contact > 0);
    assert!(on.counts.predicted_basis > 0);
    assert!(on.counts.enumerated_gpu > 0);
    assert_eq!(on.counts.warm_start, 0);
    assert_eq!(on.statuses, off.statuses);
    same_results(&on, &off);

    // Warm start from the cold bases: every island with a basis is settled
    // without enumeration, with the same z.
    let warm: Vec<Option<u32>> = on.islands.iter().map(|o| o.solution.basis).collect();
    let hot = solve_lcp_batch_warm(&ctx, &lcps, &|i| warm[i], &Default::default()).unwrap();
    println!("warm:\n{hot}");
    paths_add_up(&hot);
    assert!(hot.counts.warm_start > 0);
    for (i, (c, h)) in on.islands.iter().zip(&hot.islands).enumerate() {
        if c.solution.basis.is_some() {
            assert!(
                !matches!(h.path, SolvePath::EnumeratedGpu | SolvePath::Repaired),
                "island {i}"
            );
        }
    }
    same_results(&on, &hot);
}

#[test]
fn prediction_on_and_off_agree_f64() {
    on_and_off(Precision::F64);
}

#[test]
fn prediction_on_and_off_agree_f32() {
    on_and_off(Precision::F32);
}

/// Scenes: predicted islands are assembled but not enumerated on the GPU;
/// impulses and velocities are the same with prediction on and off.
#[test]
fn scene_prediction_on_and_off_agree() {
    let Some(ctx) = context(Precision::Auto) else {
        return;
    };
    let scenes = scenes(400);
    let on = solve_scenes(&ctx, &scenes, &GpuSolveSettings::default()).unwrap();
    let off = solve_scenes(
        &ctx,
        &scenes,
        &GpuSolveSettings {
            predict: false,
            ..Default::default()
        },
    )
    .unwrap();
    println!("on:\n{on}\noff:\n{off}");
    assert!(predicted(&on) > 0);
    assert_eq!(predicted(&off), 0);
    paths_add_up(&on);
    assert_eq!(on.statuses, off.statuses);
    let mut predicted = 0;
    for (s, (a, b)) in on.scenes.iter().zip(&off.scenes).enumerate() {
        let (a, b) = (
            &on.islands[a.islands.clone()],
            &off.islands[b.islands.clone()],
        );
        for (k, (x, y)) in a.iter().zip(b).enumerate() {
            assert_eq!(x.solution.status, y.solution.status, "scene {s} island {k}");
            let scale = x.solution.z.iter().fold(1.0f64, |m, v| m.max(v.abs()));
            for (p, q) in x.solution.z.iter().zip(&y.solution.z) {
                assert!((p - q).abs() <= 1e-9 * scale, "scene {s} island {k}");
            }
            if x.solution.basis == y.solution.basis {
                assert_eq!(x.solution.z, y.solution.z, "scene {s} island {k}");
            }
            if x.path.is_prediction() {
                predicted += 1;
            }
        }
    }
    assert_eq!(predicted, self::predicted(&on));
    // Warm from the cold bases.
    let warm: Vec<Vec<Option<u32>>> = on
        .scenes
        .iter()
        .map(|s| {
            on.islands[s.islands.clone()]
                .iter()
                .map(|i| i.solution.basis)
                .collect()
        })
        .collect();
    let built = check_and_build(&scenes).unwrap();
    let refs: Vec<&Scene> = scenes.iter().collect();
    let hot = solve_scenes_warm(&ctx, &refs, &built, Some(&warm), &Default::default()).unwrap();
    println!("warm:\n{hot}");
    assert!(hot.counts.warm_start > 0);
    for (a, b) in on.scenes.iter().zip(&hot.scenes) {
        let (a, b) = (
            &on.islands[a.islands.clone()],
            &hot.islands[b.islands.clone()],
        );
        for (x, y) in a.iter().zip(b) {
            if x.solution.basis == y.solution.basis {
                assert_eq!(x.solution.z, y.solution.z);
            }
        }
    }
}

/// The CPU path's answer for a valid island of n ≤ 16 with warm basis
/// `warm` (prediction, else enumeration), as (path, solution).
fn cpu_twin(lcp: &Lcp, warm: Option<u32>) -> (SolvePath, crate::LcpSolution) {
    let e = EnumerationSettings::default();
    crate::prediction::predict(lcp, warm, &e)
        .unwrap_or_else(|| (SolvePath::EnumeratedGpu, enumerate(lcp, &e).unwrap()))
}

/// Warm bases tried on the device (the settle kernel): right (the cold
/// call's basis), wrong (one contact flipped), out of range, and on a rank
/// one island a valid basis that is not enumeration's choice, beside
/// prediction's own. Every island's status, path, basis and z are the CPU
/// path's (z bit for bit where the host re-solved the basis, within
/// 1e-12 where the GPU's f64 z was kept); warm hits are counted as warm
/// hits, not as GPU answers.
fn warm_islands(precision: Precision, method: Method) {
    let Some(ctx) = context(precision) else {
        return;
    };
    let mut lcps = lcps(300);
    // Rank one: z1 + z2 = 1; enumeration picks {0}, the warm {1} is valid.
    lcps.push(Lcp::new(vec![1.0, 1.0, 1.0, 1.0], vec![-1.0, -1.0]).unwrap());
    // The warm {1} infeasible.
    lcps.push(Lcp::new(vec![1.0, 1.0, 1.0, 1.0], vec![-1.0, 2.0]).unwrap());
    let settings = GpuSolveSettings {
        method,
        settle_on_device: Some(true),
        ..Default::default()
    };
    let cold = solve_lcp_batch(&ctx, &lcps, &settings).unwrap();
    let last = lcps.len() - 1;
    let warm: Vec<Option<u32>> = (0..lcps.len())
        .map(|i| match (i, cold.islands[i].solution.basis) {
            (i, _) if i + 1 >= last => Some(0b10),
            (_, None) => None,
            (i, Some(b)) if i % 4 == 1 => Some(b ^ 1),
            (i, Some(_)) if i % 4 == 2 => Some(1 << 17),
            (_, Some(b)) => Some(b),
        })
        .collect();
    let hot = solve_lcp_batch_warm(&ctx, &lcps, &|i| warm[i], &settings).unwrap();
    println!("{precision:?} {}:\n{hot}", method.name());
    paths_add_up(&hot);
    let c = &hot.counts;
    assert!(
        c.accepted + c.polished <= c.enumerated_gpu + c.lemke_gpu,
        "{hot}"
    );
    let (mut warm_hits, mut predicted) = (0, 0);
    for (i, (lcp, h)) in lcps.iter().zip(&hot.islands).enumerate() {
        if lcp.validate("problem").is_err() {
            continue;
        }
        let (path, cpu) = cpu_twin(lcp, warm[i]);
        warm_hits += (path == SolvePath::WarmStart) as usize;
        predicted += (path == SolvePath::PredictedBasis) as usize;
        let s = &h.solution;
        if !path.is_prediction() {
            assert!(!h.path.is_prediction(), "island {i}: {}", h.path);
            if method == Method::Enumeration {
                assert_eq!(s.status, cpu.status, "island {i}");
            }
            continue;
        }
        if precision == Precision::F32 && h.path != path {
            // f32: a basis the device judged infeasible where f64 finds
            // it valid is enumerated instead (the f64 check polishes it).
            assert_eq!(s.status, cpu.status, "island {i}");
            continue;
        }
        assert_eq!(h.path, path, "island {i}");
        assert_eq!(h.method, Method::Enumeration, "island {i}");
        assert_eq!((s.status, s.basis), (cpu.status, cpu.basis), "island {i}");
        assert_eq!(s.counters, cpu.counters, "island {i}");
        let scale = cpu.z.iter().fold(1e-300f64, |m, v| m.max(v.abs()));
        for (p, q) in s.z.iter().zip(&cpu.z) {
            assert!((p - q).abs() <= 1e-12 * scale, "island {i}: {p} vs {q}");
        }
        if precision == Precision::F32 {
            assert_eq!(s.z, cpu.z, "island {i}: re-solved on the host");
        }
    }
    assert!(warm_hits > 50 && predicted > 0, "{warm_hits} {predicted}");
    assert_eq!(hot.islands[last - 1].path, SolvePath::WarmStart);
    assert_eq!(hot.islands[last - 1].solution.z, vec![0.0, 1.0]);
    assert_ne!(hot.islands[last].path, SolvePath::WarmStart);
    if precision == Precision::F64 {
        assert_eq!((c.warm_start, c.predicted_basis), (warm_hits, predicted));
    }
    // The warm hits alone: on the device they are uploaded and settled by
    // the kernel; on the host nothing is uploaded.
    let hits: Vec<usize> = (0..lcps.len())
        .filter(|&i| hot.islands[i].path == SolvePath::WarmStart)
        .collect();
    let again: Vec<Lcp> = hits.iter().map(|&i| lcps[i].clone()).collect();
    let bases: Vec<Option<u32>> = hits
        .iter()
        .map(|&i| hot.islands[i].solution.basis)
        .collect();
    for device in [true, false] {
        let s = GpuSolveSettings {
            settle_on_device: Some(device),
            ..settings
        };
        let r = solve_lcp_batch_warm(&ctx, &again, &|i| bases[i], &s).unwrap();
        assert_eq!(r.counts.warm_start, again.len(), "{r}");
        assert_eq!(r.gpu.map_or(0, |g| g.chunks) > 0, device, "{r}");
        for (k, &i) in hits.iter().enumerate() {
            assert_eq!(r.islands[k].solution.basis, bases[k], "island {i}");
        }
    }
}

#[test]
fn warm_bases_settled_on_the_device_f64() {
    warm_islands(Precision::F64, Method::Enumeration);
    warm_islands(Precision::F64, Method::Lemke);
}

#[test]
fn warm_bases_settled_on_the_device_f32() {
    warm_islands(Precision::F32, Method::Enumeration);
    warm_islands(Precision::F32, Method::Auto);
}
