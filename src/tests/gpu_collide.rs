//! The narrow phase on the GPU (`shaders/collide.wgsl`, `src/gpu/collide.rs`)
//! against its CPU twins (`src/world/collide.rs`, `collide_box.rs`): seeded
//! random pairs of each type (sphere–sphere, sphere–plane, sphere–box,
//! box–plane, box–box, either order, a static body on either side) touching,
//! overlapping, separated, near parallel and edge to edge; and every pair of
//! the standard worlds after some CPU steps, whose contacts in pair order
//! must be `world_contacts`' own. In f64 the same contacts, bodies and
//! feature ids, and points, normals and gaps within 1e-12 (lavapipe:
//! bit for bit, measured); in f32 the same within [`F32_TOL`] where the
//! f32 rounding of the inputs does not change a decision (see
//! [`compare`]).

use glam::{DQuat, DVec3};

use super::common::gpu_context;
use super::world::cpu;
use crate::generate::Rng;
use crate::gpu::collide::{collide_pairs_on_gpu, PairContacts};
use crate::gpu::{GpuContext, Precision};
use crate::world::collide::{collide_shapes, ContactPoint, Placed};
use crate::world::generate::{standard_world, WorldKind};
use crate::world::step::world_contacts;
use crate::world::{RigidBody, Shape};
use crate::GpuSettings;

/// Points, normals and gaps in f32: the inputs rounded to f32 (positions
/// to 6e-8 of their size, up to 10 m here) and f32 arithmetic through the
/// rotation and the clipping.
const F32_TOL: f64 = 1e-5;

/// A batch of pairs over one list of bodies, with their margins.
#[derive(Default)]
struct Batch {
    bodies: Vec<RigidBody>,
    pairs: Vec<(usize, usize)>,
    margins: Vec<f64>,
}

impl Batch {
    /// The CPU twin of every pair, as the stage reports it: collide_shapes,
    /// the dynamic body as a (world_contacts' order).
    fn twins(&self) -> Vec<Vec<ContactPoint>> {
        let b = &self.bodies;
        (self.pairs.iter().zip(&self.margins))
            .map(|(&(i, j), &m)| {
                let swap = b[i].fixed;
                let (a, bb, s) = if swap { (j, i, -1.0) } else { (i, j, 1.0) };
                let hits = collide_shapes(&Placed::of(&b[i]), &Placed::of(&b[j]), m);
                let point = |h: &crate::world::collide::Hit| ContactPoint {
                    a,
                    b: bb,
                    point: h.point,
                    normal: h.normal * s,
                    gap: h.gap,
                    feature: h.feature,
                };
                hits.iter().map(point).collect()
            })
            .collect()
    }

    /// The GPU's contacts of every pair under `gpu`'s limits.
    fn on_gpu(&self, ctx: &GpuContext, gpu: &GpuSettings) -> Vec<PairContacts> {
        collide_pairs_on_gpu(ctx, &self.bodies, &self.pairs, &self.margins, gpu).unwrap()
    }
}

fn body(shape: Shape, centre: DVec3, q: DQuat, fixed: bool) -> RigidBody {
    let mut b = if fixed {
        RigidBody::fixed(shape, centre.to_array())
    } else {
        RigidBody::new(shape, centre.to_array(), 1.0)
    };
    b.orientation = q.to_array();
    b
}

fn cube(h: DVec3) -> Shape {
    Shape::Box {
        half_extents: h.to_array(),
    }
}

fn random_quat(rng: &mut Rng) -> DQuat {
    DQuat::from_axis_angle(rng.unit_vector(), rng.range(0.0, std::f64::consts::TAU))
}

/// The configurations of the random pairs.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Config {
    Touching,
    Overlapping,
    Separated,
    NearParallel,
    EdgeEdge,
}

/// Shape x and shape y of pair type `t` (0 sphere–sphere, 1 sphere–plane,
/// 2 sphere–box, 3 box–plane, 4 box–box), posed for `config` before the
/// gap is set: (x, y), y the one that may be static.
fn pose(rng: &mut Rng, t: usize, config: Config) -> (RigidBody, RigidBody) {
    let size = |rng: &mut Rng| {
        DVec3::new(
            rng.range(0.2, 1.0),
            rng.range(0.2, 1.0),
            rng.range(0.2, 1.0),
        )
    };
    let centre = rng.vector(5.0);
    let qy = random_quat(rng);
    let dir = rng.unit_vector();
    let fixed = rng.unit() < 0.5;
    let sphere = |r: f64| Shape::Sphere { radius: r };
    match t {
        0 | 2 => {
            let r = rng.range(0.2, 1.0);
            let y = if t == 0 {
                body(sphere(rng.range(0.2, 1.0)), centre, qy, fixed)
            } else {
                body(cube(size(rng)), centre, qy, fixed)
            };
            (
                body(sphere(r), centre + dir * 1.5, random_quat(rng), false),
                y,
            )
        }
        1 | 3 => {
            let n = if rng.unit() < 0.3 {
                DVec3::Y
            } else {
                rng.unit_vector()
            };
            let plane = body(
                Shape::Plane {
                    normal: n.to_array(),
                },
                centre,
                DQuat::IDENTITY,
                true,
            );
            let x = if t == 1 {
                body(
                    sphere(rng.range(0.2, 1.0)),
                    centre + n,
                    random_quat(rng),
                    false,
                )
            } else {
                // Near parallel: a face of the box nearly along the plane.
                let q = if config == Config::NearParallel {
                    let tilt = DQuat::from_axis_angle(rng.unit_vector(), rng.log_range(1e-9, 1e-3));
                    tilt * DQuat::from_rotation_arc(DVec3::Y, n)
                } else {
                    random_quat(rng)
                };
                body(
                    cube(size(rng)),
                    centre + n * 2.0 + rng.vector(0.5),
                    q,
                    false,
                )
            };
            (x, plane)
        }
        _ => {
            let (hx, hy) = (size(rng), size(rng));
            let (qx, qy) = match config {
                // The same frame up to a small turn, face to face along y's axis 1.
                Config::NearParallel => {
                    let turn =
                        DQuat::from_axis_angle(rng.unit_vector(), rng.log_range(1e-12, 1e-3));
                    (turn * qy, qy)
                }
                // x's edge along z turned 45° about z, y's along x turned
                // 45° about x, a little off, the whole turned.
                Config::EdgeEdge => {
                    let g = random_quat(rng);
                    let off = |rng: &mut Rng| {
                        DQuat::from_axis_angle(rng.unit_vector(), rng.range(0.0, 0.2))
                    };
                    let qx = g * off(rng) * DQuat::from_rotation_z(std::f64::consts::FRAC_PI_4);
                    let qy = g * off(rng) * DQuat::from_rotation_x(std::f64::consts::FRAC_PI_4);
                    (qx, qy)
                }
                _ => (random_quat(rng), qy),
            };
            let up = match config {
                Config::NearParallel => qy * DVec3::Y + rng.vector(0.2),
                Config::EdgeEdge => qy * (qx.conjugate() * DVec3::Y).normalize(),
                _ => dir,
            };
            // Two equal boxes exactly stacked, in a third of the near-parallel pairs.
            let hx = if config == Config::NearParallel && rng.unit() < 0.3 {
                hy
            } else {
                hx
            };
            let y = body(cube(hy), centre, qy, fixed);
            (body(cube(hx), centre + up * 2.0, qx, false), y)
        }
    }
}

/// Random pairs: `per` of each type and configuration, x moved along the
/// CPU's normal until its deepest point's gap is the configuration's.
fn random_pairs(seed: u64, per: usize) -> Batch {
    let mut rng = Rng::new(seed);
    let mut batch = Batch::default();
    let configs = [
        Config::Touching,
        Config::Overlapping,
        Config::Separated,
        Config::NearParallel,
        Config::EdgeEdge,
    ];
    for t in 0..5 {
        for config in configs {
            for _ in 0..per {
                let margin = rng.range(0.0, 0.05);
                let target = match config {
                    Config::Touching | Config::NearParallel => rng.range(-1e-9, 1e-9),
                    Config::Overlapping | Config::EdgeEdge => rng.range(-0.2, -1e-4),
                    Config::Separated => margin + rng.range(0.0, 0.3),
                };
                let (mut x, y) = pose(&mut rng, t, config);
                let all = collide_shapes(&Placed::of(&x), &Placed::of(&y), 1e3);
                if let Some(deep) = all.iter().min_by(|a, b| a.gap.total_cmp(&b.gap)) {
                    let p = x.position() + deep.normal * (target - deep.gap);
                    x.position = p.to_array();
                }
                // Either order, so that both flips of the twin run.
                let k = batch.bodies.len();
                let order = if rng.unit() < 0.5 {
                    (k, k + 1)
                } else {
                    (k + 1, k)
                };
                batch.bodies.extend([x, y]);
                batch.pairs.push(order);
                batch.margins.push(margin);
            }
        }
    }
    batch
}

/// The standard worlds after `steps` CPU steps, every pair of bodies not
/// both static with `world_contacts`' margin (the world's plus how far each
/// body moves within Δt), and each world's contacts from `world_contacts`.
fn world_pairs(steps: usize, dt: f64) -> (Batch, Vec<(usize, Vec<ContactPoint>)>) {
    let mut batch = Batch::default();
    let mut expected = Vec::new();
    for (kind, _) in WorldKind::ALL {
        for seed in 1..=2 {
            let mut worlds = vec![standard_world(kind, kind.default_size(), seed)];
            let mut solver = cpu();
            for _ in 0..steps {
                solver.step_worlds(&mut worlds, dt).unwrap();
            }
            let w = &worlds[0];
            assert!(w.bodies.iter().all(|b| !b.asleep), "no sleeping here");
            // prepare's v* (gravity on the awake dynamic bodies).
            let v: Vec<(DVec3, DVec3)> = (w.bodies.iter())
                .map(|b| {
                    let g = if b.fixed {
                        DVec3::ZERO
                    } else {
                        w.gravity() * dt
                    };
                    (b.velocity() + g, b.angular_velocity())
                })
                .collect();
            let reach: Vec<f64> = (w.bodies.iter().zip(&v))
                .map(|(b, (l, a))| {
                    if b.fixed {
                        0.0
                    } else {
                        (l.length() + a.length() * b.bounding_radius()) * dt
                    }
                })
                .collect();
            let first = batch.bodies.len();
            for i in 0..w.bodies.len() {
                for j in i + 1..w.bodies.len() {
                    if !(w.bodies[i].fixed && w.bodies[j].fixed) {
                        batch.pairs.push((first + i, first + j));
                        batch.margins.push(w.contact_margin + reach[i] + reach[j]);
                    }
                }
            }
            batch.bodies.extend(w.bodies.iter().cloned());
            expected.push((first, world_contacts(w, &v, dt).0));
        }
    }
    (batch, expected)
}

/// What a comparison saw: pairs and contacts compared, the largest
/// deviations (point, normal, gap), pairs left out in f32.
#[derive(Debug, Default)]
struct Seen {
    pairs: usize,
    contacts: usize,
    point: f64,
    normal: f64,
    gap: f64,
    decided_otherwise: usize,
}

/// GPU against twin, pair by pair: the same count, bodies and feature ids,
/// then points, normals and gaps within `tol`. In f32 (`strict` false) a
/// pair whose count or ids differ is counted (`decided_otherwise`) rather
/// than failed: f32 rounds the inputs by more than the twins' thresholds
/// near a decision (CLIP_TOL is 1e-7 of a box, below f32's 6e-8 of a
/// position 10 m out; a gap at the margin); the callers bound their number.
fn compare(gpu: &[PairContacts], cpu: &[Vec<ContactPoint>], tol: f64, strict: bool) -> Seen {
    let mut seen = Seen::default();
    assert_eq!(gpu.len(), cpu.len());
    for (k, (g, c)) in gpu.iter().zip(cpu).enumerate() {
        assert!(!g.overflow, "pair {k}: overflow flagged");
        let ids = |v: &[ContactPoint]| v.iter().map(|p| (p.a, p.b, p.feature)).collect::<Vec<_>>();
        if ids(&g.contacts) != ids(c) {
            assert!(!strict, "pair {k}: GPU {:?}\nCPU {:?}", g.contacts, c);
            seen.decided_otherwise += 1;
            continue;
        }
        for (p, q) in g.contacts.iter().zip(c) {
            seen.point = seen.point.max((p.point - q.point).abs().max_element());
            seen.normal = seen.normal.max((p.normal - q.normal).abs().max_element());
            seen.gap = seen.gap.max((p.gap - q.gap).abs());
            seen.contacts += 1;
        }
        assert!(
            seen.point <= tol && seen.normal <= tol && seen.gap <= tol,
            "pair {k}: {seen:?}\nGPU {:?}\nCPU {:?}",
            g.contacts,
            c
        );
        seen.pairs += 1;
    }
    seen
}

#[test]
fn random_pairs_on_the_gpu_are_the_twins() {
    let batch = random_pairs(0xC011DE, 40);
    let cpu = batch.twins();
    // Coverage: every kind of answer the twins give is among the pairs.
    let all: Vec<&ContactPoint> = cpu.iter().flatten().collect();
    let edge = all.iter().filter(|p| p.feature >> 8 == 7).count();
    let clipped = all
        .iter()
        .filter(|p| p.feature >> 8 != 7 && p.feature & 31 >= 4)
        .count();
    let four = cpu.iter().filter(|c| c.len() == 4).count();
    let none = cpu.iter().filter(|c| c.is_empty()).count();
    assert!(
        edge > 10 && clipped > 10 && four > 10 && none > 50,
        "edge {edge}, clipped {clipped}, four {four}, none {none}"
    );
    for precision in [Precision::F64, Precision::F32] {
        let Some(ctx) = gpu_context(precision) else {
            continue;
        };
        let f64 = precision == Precision::F64;
        let tol = if f64 { 1e-12 } else { F32_TOL };
        let start = std::time::Instant::now();
        let gpu = batch.on_gpu(&ctx, &GpuSettings::default());
        let took = start.elapsed();
        let seen = compare(&gpu, &cpu, tol, f64);
        assert!(seen.decided_otherwise * 20 <= batch.pairs.len(), "{seen:?}");
        let start = std::time::Instant::now();
        assert_eq!(batch.on_gpu(&ctx, &GpuSettings::default()), gpu);
        let warm = start.elapsed();
        // Split under a small binding limit (3 chunks of pairs) and two
        // workgroups per dispatch: the same.
        let split = GpuSettings {
            max_binding_bytes: Some(200_000),
            max_workgroups: Some(2),
            ..GpuSettings::default()
        };
        assert_eq!(batch.on_gpu(&ctx, &split), gpu);
        eprintln!(
            "{}: {} pairs ({edge} edge, {clipped} clipped points, {four} with 4, {none} empty), \
             {seen:?}; first call (shader compiled) {took:?}, again {warm:?} (pack, upload, \
             dispatch, readback)",
            precision.name(),
            batch.pairs.len(),
        );
    }
}

#[test]
fn standard_world_pairs_on_the_gpu_are_world_contacts() {
    let dt = 0.01;
    // One context per precision (a shader compilation each: minutes on GL).
    let contexts: Vec<GpuContext> = [Precision::F64, Precision::F32]
        .into_iter()
        .filter_map(gpu_context)
        .collect();
    for steps in [3, 40] {
        let (batch, expected) = world_pairs(steps, dt);
        let cpu = batch.twins();
        for ctx in &contexts {
            let precision = ctx.precision();
            let f64 = precision == Precision::F64;
            let gpu = batch.on_gpu(ctx, &GpuSettings::default());
            let tol = if f64 { 1e-12 } else { F32_TOL };
            let seen = compare(&gpu, &cpu, tol, f64);
            assert!(seen.decided_otherwise * 20 <= batch.pairs.len(), "{seen:?}");
            if f64 {
                // In pair order, each world's contacts are world_contacts'.
                let mut at = 0;
                for (w, (first, contacts)) in expected.iter().enumerate() {
                    let end = expected.get(w + 1).map_or(batch.bodies.len(), |e| e.0);
                    let mut found = Vec::new();
                    while at < batch.pairs.len() && batch.pairs[at].0 < end {
                        found.extend(gpu[at].contacts.iter().map(|p| ContactPoint {
                            a: p.a - first,
                            b: p.b - first,
                            ..*p
                        }));
                        at += 1;
                    }
                    assert_eq!(&found, contacts, "world {w} after {steps} steps");
                }
            }
            eprintln!(
                "{} after {steps} steps: {} pairs, {seen:?}",
                precision.name(),
                batch.pairs.len()
            );
        }
    }
}

#[test]
fn bad_pairs_are_refused_naming_the_pair() {
    let Some(ctx) = gpu_context(Precision::Auto) else {
        return;
    };
    let ball = body(
        Shape::Sphere { radius: 0.5 },
        DVec3::ZERO,
        DQuat::IDENTITY,
        false,
    );
    let ground = body(
        Shape::Plane {
            normal: [0.0, 1.0, 0.0],
        },
        DVec3::ZERO,
        DQuat::IDENTITY,
        true,
    );
    let bodies = [ball, ground.clone(), ground];
    let g = GpuSettings::default();
    for (pairs, margins, what) in [
        (vec![(0, 1), (0, 3)], vec![0.0, 0.0], "pair 1"),
        (vec![(1, 1)], vec![0.0], "pair 0"),
        (vec![(0, 1), (1, 2)], vec![0.0, 0.0], "pair 1"),
        (vec![(0, 1)], vec![f64::NAN], "pair 0"),
    ] {
        let e = collide_pairs_on_gpu(&ctx, &bodies, &pairs, &margins, &g)
            .unwrap_err()
            .to_string();
        assert!(e.contains(what), "{e}");
    }
    // Refused before any dispatch: no shader compiled (minutes on GL).
    let e = collide_pairs_on_gpu(&ctx, &bodies, &[(0, 1)], &[], &g).unwrap_err();
    assert!(e.to_string().contains("margins"), "{e}");
}
