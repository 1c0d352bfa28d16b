//! The GPU assembly of frictional islands (`shaders/assembly.wgsl` on the
//! direction contacts, `src/gpu/friction_assembly.rs`) against its CPU twin
//! `src/friction/assembly.rs`: μ and the contacts equal, W within 1e-13 of
//! ‖W‖∞ and q within 1e-13 of ‖q‖∞ in f64 (the rows' 3×3 products group
//! their sums otherwise than glam: the last bit differs, measured), within
//! 1e-5 in f32.

use super::common::gpu_context;
use crate::friction::assembly::{friction_islands, FrictionIsland};
use crate::generate::friction::{box_on_ground_moving, box_on_incline, box_stack};
use crate::generate::{random_scene, Rng};
use crate::gpu::friction_assembly::assemble_friction_on_gpu;
use crate::gpu::Precision;
use crate::{GpuSettings, Scene};

/// Random scenes of islands with up to 16 contacts (mass ratios to 1e3),
/// friction on every contact, a caller's tangent on some, and the friction
/// generators' boxes and stacks.
fn scenes() -> Vec<Scene> {
    let mut rng = Rng::new(0xFA);
    let mut out = Vec::new();
    for i in 0..6 {
        let mut s = random_scene(&mut rng, 5, 16, [1.0, 10.0, 1e3][i % 3]);
        for (k, c) in s.contacts.iter_mut().enumerate() {
            c.friction = 0.1 * (k % 9) as f64;
            if k % 5 == 3 {
                // A caller's t₁: the default frame turned by 30°.
                let (t1, t2) = c.tangents();
                let (sn, cs) = (30f64.to_radians().sin(), 30f64.to_radians().cos());
                c.tangent = Some((t1 * cs + t2 * sn).to_array());
            }
        }
        out.push(s);
    }
    out.push(box_on_ground_moving(
        2.0,
        0.4,
        glam::DVec3::new(1.0, -0.5, 0.3),
    ));
    out.push(box_on_incline(0.3, 0.5, 0.2));
    out.push(box_stack(4, 0.6, 0.3, 0.1));
    out
}

fn compare(gpu: &[Vec<FrictionIsland>], scenes: &[Scene], tol: f64) -> usize {
    let mut islands = 0;
    for (s, (g, scene)) in gpu.iter().zip(scenes).enumerate() {
        let cpu = friction_islands(scene);
        assert_eq!(g.len(), cpu.len(), "scene {s}");
        for (k, (a, b)) in g.iter().zip(&cpu).enumerate() {
            assert_eq!(a.contacts, b.contacts, "scene {s} island {k}");
            assert_eq!(a.problem.mu, b.problem.mu, "scene {s} island {k}");
            let p = &b.problem;
            let n = p.dim();
            let w_inf = (0..n)
                .map(|r| p.w[r * n..(r + 1) * n].iter().map(|x| x.abs()).sum::<f64>())
                .fold(0.0, f64::max);
            let q_inf = p.q.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let dw = a
                .problem
                .w
                .iter()
                .zip(&p.w)
                .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
            let dq = a
                .problem
                .q
                .iter()
                .zip(&p.q)
                .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
            assert!(
                dw <= tol * w_inf,
                "scene {s} island {k}: W differs by {dw:e}"
            );
            assert!(
                dq <= tol * q_inf.max(1e-300),
                "scene {s} island {k}: q differs by {dq:e}"
            );
            islands += 1;
        }
    }
    islands
}

#[test]
fn friction_assembly_on_the_gpu_is_the_twins() {
    let scenes = scenes();
    let large = scenes
        .iter()
        .flat_map(friction_islands)
        .filter(|i| i.contacts.len() >= 10)
        .count();
    assert!(large > 0, "islands of 10 or more contacts are covered");
    for precision in [Precision::F64, Precision::F32] {
        let Some(ctx) = gpu_context(precision) else {
            continue;
        };
        let tol = if precision == Precision::F64 {
            1e-13
        } else {
            1e-5
        };
        let whole = assemble_friction_on_gpu(&ctx, &scenes, &GpuSettings::default()).unwrap();
        let n = compare(&whole, &scenes, tol);
        // Split under a small binding limit: the same answers.
        let split = GpuSettings {
            max_binding_bytes: Some(64 * 1024),
            max_workgroups: Some(2),
            ..GpuSettings::default()
        };
        let parts = assemble_friction_on_gpu(&ctx, &scenes, &split).unwrap();
        assert_eq!(parts, whole, "{}", precision.name());
        eprintln!("{}: {n} islands compared", precision.name());
    }
}
