//! Stage by stage, the GPU against its CPU twin on the same packed inputs:
//! assembly (K, Jacobian, response, v_rel, q per contact; M and q per
//! island), enumeration (chosen basis and counters), impulses (through the
//! scene pipeline's check).

use crate::cpu::assembly::ContactRow;
use crate::cpu::enumeration::{enumerate, EnumerationSettings};
use crate::generate::{box_on_ground, demo_world, random_island, seed_chain, Rng};
use crate::gpu::batch::{enumerate_on_gpu, EnumerationKernel};
use crate::gpu::layout::{
    assemble_contacts_packed, pack_body, pack_contact, unpack_row, DYNAMIC_A, DYNAMIC_B,
};
use crate::gpu::scenes::assemble_on_gpu;
use crate::gpu::{GpuSolveSettings, Precision};
use crate::islands::find_islands;
use crate::tests::reference::build;
use crate::{Body, Contact, Lcp, Scene};

use super::common::gpu_context as context;

fn scenes() -> Vec<Scene> {
    let mut rng = Rng::new(7);
    let mut v = vec![box_on_ground(1.0, 0.5), seed_chain(0.3)];
    for k in 0..300 {
        v.push(random_island(&mut rng, 1 + k % 12, [1.0, 1e2, 1e4][k % 3]));
    }
    for _ in 0..20 {
        v.push(demo_world(&mut rng));
    }
    v
}

/// |a − b| ≤ tol · scale, elementwise.
fn close(a: &[f64], b: &[f64], scale: f64, tol: f64) -> Result<(), String> {
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        let d = (x - y).abs();
        if d.is_nan() || d > tol * scale {
            return Err(format!("entry {i}: {x} vs {y} (scale {scale})"));
        }
    }
    Ok(())
}

fn row_parts(r: &ContactRow) -> Vec<(&'static str, Vec<f64>)> {
    vec![
        ("K", r.k.transpose().to_cols_array().to_vec()),
        ("jacobian", r.jacobian.to_vec()),
        ("response", r.response.to_vec()),
        ("v_rel q", vec![r.v_rel, r.q]),
    ]
}

fn assembly(precision: Precision, tol: f64) {
    let Some(ctx) = context(precision) else {
        return;
    };
    let scenes = scenes();
    let gpu = assemble_on_gpu(&ctx, &scenes, &GpuSolveSettings::default()).unwrap();
    let mut checked = (0, 0);
    for (s, scene) in scenes.iter().enumerate() {
        let (_, rows, lcps) = build(scene, "scene").unwrap();
        // The twin on the same packed records as the shader's input.
        let (mut bodies, mut ids, mut contacts) = (Vec::new(), Vec::new(), Vec::new());
        scene.bodies.iter().for_each(|b| pack_body(b, &mut bodies));
        scene
            .contacts
            .iter()
            .for_each(|c| pack_contact(c, &scene.bodies, 0, &mut ids, &mut contacts));
        let twin = assemble_contacts_packed(&bodies, &ids, &contacts);
        for (k, (g, c)) in gpu.rows[s].iter().zip(&rows).enumerate() {
            let t = unpack_row(&twin[k * 36..(k + 1) * 36]);
            assert_eq!(
                &t, c,
                "twin on packed input differs from the unpacked CPU assembly"
            );
            // v_rel is a difference of point velocities ω × (p − x): its f32
            // rounding is relative to the size of the terms (positions in
            // world coordinates), not to the (possibly cancelled) result.
            let ct = &scene.contacts[k];
            let point_speed = |b: usize| {
                let body = &scene.bodies[b];
                let r = ct.point().length() + body.position().length();
                body.velocity().length() + body.angular_velocity().length() * r
            };
            let speeds = point_speed(ct.a) + ct.b.map_or(0.0, point_speed);
            for ((name, gv), (_, cv)) in row_parts(g).into_iter().zip(row_parts(c)) {
                let mut scale = cv
                    .iter()
                    .fold(0.0f64, |m, v| m.max(v.abs()))
                    .max(f64::MIN_POSITIVE);
                if name == "v_rel q" {
                    scale = scale.max(2.0 * speeds);
                }
                close(&gv, &cv, scale, tol)
                    .unwrap_or_else(|e| panic!("scene {s} contact {k}: {name}: {e}"));
            }
            checked.0 += 1;
        }
        for (k, (g, c)) in gpu.lcps[s].iter().zip(&lcps).enumerate() {
            let g: &Lcp = g.as_ref().expect("every island here has n ≤ 16");
            let scale = c.m.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            close(&g.m, &c.m, scale, tol)
                .unwrap_or_else(|e| panic!("scene {s} island {k}: M: {e}"));
            let qs =
                c.q.iter()
                    .fold(0.0f64, |m, v| m.max(v.abs()))
                    .max(f64::MIN_POSITIVE);
            close(&g.q, &c.q, qs, tol).unwrap_or_else(|e| panic!("scene {s} island {k}: q: {e}"));
            checked.1 += 1;
        }
    }
    println!(
        "{precision:?}: {} contact rows and {} island LCPs within {tol:e}",
        checked.0, checked.1
    );
    assert!(checked.0 > 1000 && checked.1 > 300);
}

#[test]
fn assembly_matches_cpu_twin_f32() {
    assembly(Precision::F32, 1e-5);
}

#[test]
fn assembly_matches_cpu_twin_f64() {
    assembly(Precision::F64, 1e-12);
}

/// A moving platform (static: inv_mass 0, zero inertia, but a velocity and
/// a spin, like a kinematic body) under two boxes, four contacts each; one
/// contact per box names the platform as body a (normal −y), the others as
/// body b. The platform is static, so it joins no islands (two islands) and
/// its side is flagged static in the packed records; the GPU's M and q (M
/// skips the static sides, q keeps the platform's velocity) equal the CPU's.
#[test]
fn moving_static_platform_matches_cpu_f64() {
    let Some(ctx) = context(Precision::F64) else {
        return;
    };
    let mut platform = Body::fixed([0.0, -0.5, 0.0]);
    platform.velocity = [0.3, 0.8, -0.2];
    platform.angular_velocity = [0.1, 0.4, -0.3];
    assert!(platform.is_static());
    let mut bodies = vec![platform];
    let mut contacts = Vec::new();
    for (k, x) in [-2.0, 2.0].into_iter().enumerate() {
        let mut b = Body::new(
            1.0 / (1.0 + k as f64),
            [6.0, 5.0 + k as f64, 4.0],
            [x, 0.5, 0.1],
        );
        b.velocity = [0.2 * x, -1.0, 0.1];
        b.angular_velocity = [0.5, -0.2, 0.3 * x];
        let body = bodies.len();
        bodies.push(b);
        for (i, (dx, dz)) in [(-0.5, -0.5), (0.5, -0.5), (-0.5, 0.5), (0.5, 0.5)]
            .into_iter()
            .enumerate()
        {
            let point = [x + dx, 0.0, 0.1 + dz];
            contacts.push(if i == 3 {
                Contact {
                    a: 0,
                    b: Some(body),
                    point,
                    normal: [0.0, -1.0, 0.0],
                    restitution: 0.25,
                    id: None,
                    // A gap term (time stepping's φ/Δt) reaches q on both paths.
                    bias: -0.125,
                    friction: 0.0,
                    tangent: None,
                }
            } else {
                Contact {
                    a: body,
                    b: Some(0),
                    point,
                    normal: [0.0, 1.0, 0.0],
                    restitution: 0.5,
                    id: None,
                    bias: 0.0625 * i as f64,
                    friction: 0.0,
                    tangent: None,
                }
            });
        }
    }
    let scene = Scene { bodies, contacts };

    let islands = find_islands(&scene);
    assert_eq!(islands.len(), 2, "the platform joins no islands");
    assert_eq!(islands[0].contacts, vec![0, 1, 2, 3]);
    assert_eq!(islands[1].contacts, vec![4, 5, 6, 7]);

    let (mut packed, mut ids, mut packed_contacts) = (Vec::new(), Vec::new(), Vec::new());
    scene.bodies.iter().for_each(|b| pack_body(b, &mut packed));
    for c in &scene.contacts {
        pack_contact(c, &scene.bodies, 0, &mut ids, &mut packed_contacts);
    }
    for (k, id) in ids.iter().enumerate() {
        let expected = if k % 4 == 3 { DYNAMIC_B } else { DYNAMIC_A };
        assert_eq!(id.flags, expected, "contact {k}: dynamic sides");
    }

    let (_, rows, lcps) = build(&scene, "platform").unwrap();
    assert_eq!(lcps.len(), 2);
    // The platform's motion reaches q: at rest it would give other values.
    let mut at_rest = scene.clone();
    at_rest.bodies[0].velocity = [0.0; 3];
    at_rest.bodies[0].angular_velocity = [0.0; 3];
    let (_, rest_rows, _) = build(&at_rest, "platform at rest").unwrap();
    for (k, (r, r0)) in rows.iter().zip(&rest_rows).enumerate() {
        assert!((r.v_rel - r0.v_rel).abs() > 1e-3, "contact {k}: v_rel");
    }

    let gpu = assemble_on_gpu(
        &ctx,
        std::slice::from_ref(&scene),
        &GpuSolveSettings::default(),
    )
    .unwrap();
    for (k, (g, c)) in gpu.rows[0].iter().zip(&rows).enumerate() {
        for ((name, gv), (_, cv)) in row_parts(g).into_iter().zip(row_parts(c)) {
            let scale = cv.iter().fold(1e-300f64, |m, v| m.max(v.abs()));
            close(&gv, &cv, scale, 1e-12).unwrap_or_else(|e| panic!("contact {k}: {name}: {e}"));
        }
    }
    for (k, (g, c)) in gpu.lcps[0].iter().zip(&lcps).enumerate() {
        let g = g.as_ref().expect("n = 4");
        assert_eq!((g.m.len(), g.q.len()), (16, 4), "island {k}");
        let scale = c.m.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        close(&g.m, &c.m, scale, 1e-12).unwrap_or_else(|e| panic!("island {k}: M: {e}"));
        let qs = c.q.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        close(&g.q, &c.q, qs, 1e-12).unwrap_or_else(|e| panic!("island {k}: q: {e}"));
    }
}

/// Enumeration alone (the elimination kernel: Auto would send positive
/// definite islands to the tree kernel, which `src/tests/gpu_tree.rs` compares
/// with its own twin), on the CPU's f64 LCPs: in f64 the same basis and the
/// same counters as the twin, island by island.
#[test]
fn enumeration_matches_cpu_twin_f64() {
    let Some(ctx) = context(Precision::F64) else {
        return;
    };
    let lcps: Vec<Lcp> = scenes()
        .iter()
        .flat_map(|s| build(s, "scene").unwrap().2)
        .collect();
    let refs: Vec<&Lcp> = lcps.iter().collect();
    let elimination = GpuSolveSettings {
        kernel: EnumerationKernel::Elimination,
        ..Default::default()
    };
    let (out, stats) = enumerate_on_gpu(&ctx, &refs, &elimination).unwrap();
    for (i, (l, o)) in lcps.iter().zip(&out).enumerate() {
        let c = enumerate(l, &EnumerationSettings::default()).unwrap();
        assert_eq!(Some(o.result.mask), c.basis, "island {i}: basis");
        assert_eq!(
            o.result.visited as u64, c.counters.bases_visited,
            "island {i}: visited"
        );
        assert_eq!(
            o.result.singular as u64, c.counters.singular_bases,
            "island {i}: singular"
        );
        for (a, b) in o.z.iter().zip(&c.z) {
            assert!(
                (a - b).abs() <= 1e-12 * (1.0 + b.abs()),
                "island {i}: z {:?} vs {:?}",
                o.z,
                c.z
            );
        }
    }
    println!("{} islands, {} dispatches", lcps.len(), stats.dispatches);
}

/// The enumeration stage's buffers kept between calls (`Role`): a context
/// that ran earlier batches, larger and smaller, other tolerances, split in
/// chunks or not, gives each batch the answers of a context that keeps
/// nothing, record
/// for record and z for z, at each precision. A kept output not cleared, a
/// stale Params, tolerances or island table would change them: each batch
/// is another draw of islands than the one before it.
fn kept_buffers_match_fresh_contexts(precision: Precision) {
    use crate::gpu::buffers::Role;
    let (Some(kept), Some(fresh)) = (context(precision), context(precision)) else {
        return;
    };
    let loose = GpuSolveSettings {
        gpu_feasibility_tol: Some(1e-3),
        ..Default::default()
    };
    let chunked = GpuSolveSettings {
        max_binding_bytes: Some(4096),
        ..Default::default()
    };
    let batches = [
        (
            super::common::physical_islands(31, 120, 10),
            GpuSolveSettings::default(),
        ),
        (
            super::common::physical_islands(32, 12, 5),
            GpuSolveSettings::default(),
        ),
        (super::common::physical_islands(33, 200, 9), loose),
        (super::common::physical_islands(34, 60, 8), chunked),
        (
            super::common::physical_islands(35, 3, 3),
            GpuSolveSettings::default(),
        ),
    ];
    for (b, (lcps, settings)) in batches.iter().enumerate() {
        let refs: Vec<&Lcp> = lcps.iter().collect();
        let again = enumerate_on_gpu(&kept, &refs, settings).unwrap().0;
        // A context that keeps nothing (its pipelines compiled once).
        *fresh.kept.lock().unwrap() = Default::default();
        let want = enumerate_on_gpu(&fresh, &refs, settings).unwrap().0;
        assert_eq!(again.len(), lcps.len(), "batch {b}");
        for (i, (a, f)) in again.iter().zip(&want).enumerate() {
            assert_eq!(a, f, "batch {b} ({} islands), island {i}", lcps.len());
        }
        // The buffers are kept for the next batch (so that it takes them).
        for role in [Role::Values, Role::Results, Role::Z, Role::Params] {
            let buffer = kept.take_kept(role, 16);
            assert!(buffer.is_some(), "batch {b}: no {role:?} buffer kept");
            kept.keep(role, buffer.unwrap());
        }
    }
}

#[test]
fn kept_buffers_match_fresh_contexts_f32() {
    kept_buffers_match_fresh_contexts(Precision::F32);
}

#[test]
fn kept_buffers_match_fresh_contexts_f64() {
    kept_buffers_match_fresh_contexts(Precision::F64);
}
