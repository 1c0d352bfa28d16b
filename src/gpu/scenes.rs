//! Whole scenes on the GPU: assembly (per contact, then per island),
//! enumeration and impulse application as shaders, every answer validated
//! on the CPU in f64.
//!
//! One submission per chunk of scenes runs `assemble_contacts` →
//! `assemble_islands` → `enumeration` (one dispatch per island size) on
//! device-resident buffers; the chosen bases come back, the CPU polishes
//! them in f64 (against its own f64 assembly, O(n²) per island) and a
//! second submission applies the validated impulses with `impulses.wgsl`.
//! Its velocities are checked against the f64 twin, whose values are kept.

// `assemble_on_gpu` (the assembly stage alone) serves the stage tests.
#![cfg_attr(not(test), allow(dead_code))]

use std::time::Instant;

use super::batch::{settle_from_gpu, settle_on_cpu, solve_lcp_batch_warm, GpuSolveSettings};
use super::buffers::limits_for;
use super::enumeration::EnumerationJob;
use super::kernel::{KernelPlan, TreeRoute};
use super::layout::{
    scalars_from_bytes, scalars_to_bytes, unpack_row, BasisResult, BodyContacts, ContactSide, BODY,
    NO_BODY, ROW, VELOCITY,
};
use super::pipelines::{Pipelines, Tolerances};
use super::scene_chunks::{pack_chunk, plan, Chunk};
use super::GpuContext;
use crate::build::Built;
use crate::cpu::assembly::ContactRow;
use crate::cpu::batch::parallel_map;
use crate::cpu::impulses::{apply_impulses, BodyVelocity};
use crate::gpu::validation::Verdict;
use crate::lcp::{Lcp, LcpSolution};
use crate::report::{Device, GpuFigures, IslandReport, Report, SceneReport, SolvePath};
use crate::scene::Scene;
use crate::settings::Method;
use crate::short_vec::ShortVec;
use crate::Error;

/// The GPU's assembly stage output, unpacked (for comparison with the twin).
#[derive(Clone, Debug)]
pub struct GpuAssembly {
    /// Per scene, per contact: the row assembled on the GPU.
    pub rows: Vec<Vec<ContactRow>>,
    /// Per scene, per island with n ≤ 16 (in `find_islands` order): (M, q)
    /// assembled on the GPU.
    pub lcps: Vec<Vec<Option<Lcp>>>,
}

/// Device buffers of a chunk that the impulse stage reuses.
struct Resident {
    bodies: wgpu::Buffer,
    rows: wgpu::Buffer,
}

struct StageOutput {
    results: Vec<BasisResult>,
    z: Vec<f64>,
    rows: Option<Vec<f64>>,
    values: Option<Vec<f64>>,
    resident: Resident,
    /// Dispatches, rounds, the tree kernel's decisions, seconds.
    figures: GpuFigures,
}

/// Submission 1: assembly (contacts, islands) and, given a plan and the
/// tolerances uniform, enumeration.
// About 90 lines: the buffers of one submission are created and bound in
// one place, in binding order, so that they can be read against the shaders.
fn assemble_and_enumerate(
    ctx: &GpuContext,
    p: &Pipelines,
    c: &Chunk,
    max_groups: u32,
    enumerate: Option<(&KernelPlan, &wgpu::Buffer)>,
) -> Result<StageOutput, Error> {
    let precision = ctx.precision();
    let sb = precision.bytes();
    ctx.scoped(
        "assembly and enumeration",
        || -> Result<StageOutput, Error> {
            // bodies: packed bodies of every scene in the chunk (20 scalars each).
            let bodies = ctx.storage("bodies", &scalars_to_bytes(&c.bodies, precision));
            // contact_bodies: each contact's bodies, as chunk-wide body indices.
            let ids = ctx.storage("contact_bodies", bytemuck::cast_slice(&c.ids));
            // contacts: point, normal, restitution, bias of every contact (8 scalars).
            let contacts = ctx.storage("contacts", &scalars_to_bytes(&c.contacts, precision));
            // rows: assembly's per-contact output (K, J, M⁻¹Jᵀ, v_rel, q); the
            // island stage and the impulse stage read it on the device.
            let rows_size = (c.ids.len() * ROW) as u64 * sb;
            let rows = ctx.storage_zeroed("rows", rows_size);
            // islands: the island table, sorted by n.
            let islands = ctx.storage("islands", bytemuck::cast_slice(&c.table));
            // slots: one (island, contact) per island row, for the island stage.
            let slots = ctx.storage("slots", bytemuck::cast_slice(&c.slots));
            // values: every island's M and q as assembled here, read by enumeration.
            let values_size = c.values_len as u64 * sb;
            let values = ctx.storage_zeroed("values", values_size);
            let mut encoder = ctx.encoder("assembly and enumeration");
            let n_contacts = c.ids.len() as u32;
            let contact_buffers = [&bodies, &ids, &contacts, &rows];
            let st = &p.assemble_contacts;
            ctx.dispatch(&mut encoder, st, n_contacts, max_groups, &contact_buffers);
            let island_buffers = [&ids, &rows, &islands, &slots, &values];
            let st = &p.assemble_islands;
            ctx.dispatch(
                &mut encoder,
                st,
                c.slots.len() as u32,
                max_groups,
                &island_buffers,
            );
            let dispatches = 2;
            if let Some((plan, tolerances)) = enumerate {
                // Only the islands prediction left: a table of their own
                // (offsets into the same values) when some were settled.
                let enum_islands = if c.enum_table.len() == c.table.len() {
                    islands
                } else {
                    ctx.storage("enumeration islands", bytemuck::cast_slice(&c.enum_table))
                };
                let job = EnumerationJob {
                    ctx,
                    pipelines: p,
                    islands: enum_islands,
                    values: values.clone(),
                    tolerances,
                    table: &c.enum_table,
                    tree: &c.enum_tree,
                    // Prediction ran on the CPU's assembly; the table's
                    // fourth word is the assembly's.
                    settle: false,
                    max_groups,
                    plan,
                };
                let mut run = job.run(encoder, true)?;
                run.figures.dispatches += dispatches;
                return Ok(StageOutput {
                    results: run.results,
                    z: run.z,
                    rows: None,
                    values: None,
                    resident: Resident { bodies, rows },
                    figures: run.figures,
                });
            }
            let got =
                ctx.submit_and_read(encoder, &[(&rows, rows_size), (&values, values_size)])?;
            let mut got = got.into_iter();
            Ok(StageOutput {
                results: Vec::new(),
                z: Vec::new(),
                rows: got.next().map(|b| scalars_from_bytes(&b, precision)),
                values: got.next().map(|b| scalars_from_bytes(&b, precision)),
                resident: Resident { bodies, rows },
                figures: GpuFigures {
                    dispatches,
                    ..GpuFigures::default()
                },
            })
        },
    )?
}

/// Submission 2: velocities after the impulses `z` (one per chunk contact).
fn apply_on_gpu(
    ctx: &GpuContext,
    p: &Pipelines,
    c: &Chunk,
    resident: &Resident,
    z: &[f64],
    max_groups: u32,
) -> Result<Vec<f64>, Error> {
    let precision = ctx.precision();
    let nb = c.bodies.len() / BODY;
    // CSR of (contact, side) per body, in contact order (the twin's order).
    let mut count = vec![0u32; nb];
    for id in &c.ids {
        count[id.a as usize] += 1;
        if id.b != NO_BODY {
            count[id.b as usize] += 1;
        }
    }
    let mut ranges = Vec::with_capacity(nb);
    let mut start = 0u32;
    for &k in &count {
        ranges.push(BodyContacts { start, count: 0 });
        start += k;
    }
    let mut sides = vec![ContactSide::default(); start as usize];
    for (ci, id) in c.ids.iter().enumerate() {
        for (side, b) in [(0u32, id.a), (1u32, id.b)] {
            if b == NO_BODY {
                continue;
            }
            let r = &mut ranges[b as usize];
            sides[(r.start + r.count) as usize] = ContactSide {
                contact: ci as u32,
                side,
            };
            r.count += 1;
        }
    }
    ctx.scoped("impulses", || -> Result<Vec<f64>, Error> {
        // body_contacts: each body's range in contact_sides.
        let body_contacts = ctx.storage("body_contacts", bytemuck::cast_slice(&ranges));
        // contact_sides: (contact, side) pairs gathered per body.
        let contact_sides = ctx.storage("contact_sides", bytemuck::cast_slice(&sides));
        // z: the validated impulse of every contact.
        let zb = ctx.storage("z", &scalars_to_bytes(z, precision));
        // velocities: the output, 8 scalars per body.
        let vel_size = (nb * VELOCITY) as u64 * precision.bytes();
        let velocities = ctx.storage_zeroed("velocities", vel_size);
        let mut encoder = ctx.encoder("impulses");
        let buffers = [
            &resident.bodies,
            &resident.rows,
            &body_contacts,
            &contact_sides,
            &zb,
            &velocities,
        ];
        ctx.dispatch(&mut encoder, &p.impulses, nb as u32, max_groups, &buffers);
        let got = ctx.submit_and_read(encoder, &[(&velocities, vel_size)])?;
        Ok(scalars_from_bytes(&got[0], precision))
    })?
}

/// Runs only the assembly stage on the GPU and unpacks its output, for the
/// stage-by-stage comparison with [`crate::cpu::assembly`].
pub fn assemble_on_gpu(
    ctx: &GpuContext,
    scenes: &[Scene],
    settings: &GpuSolveSettings,
) -> Result<GpuAssembly, Error> {
    let prepared = check_and_build(scenes)?;
    let scenes: Vec<&Scene> = scenes.iter().collect();
    let pipelines = ctx.pipelines()?;
    let (max_bytes, max_groups) = limits_for(ctx, settings);
    let (chunks, alone) = plan(&scenes, &prepared, max_bytes, ctx.precision().bytes());
    if !alone.is_empty() {
        return Err(Error::Unsupported(format!(
            "scene {} is too large for one GPU buffer",
            alone[0]
        )));
    }
    let mut rows: Vec<Vec<ContactRow>> = vec![Vec::new(); scenes.len()];
    let mut lcps: Vec<Vec<Option<Lcp>>> = prepared
        .iter()
        .map(|p| vec![None; p.islands.len()])
        .collect();
    for members in chunks {
        let c = pack_chunk(&scenes, &prepared, &members, &|_, _| false, &|_, _| {
            TreeRoute::Off
        });
        let out = assemble_and_enumerate(ctx, &pipelines, &c, max_groups, None)?;
        let r = out.rows.unwrap_or_default();
        let v = out.values.unwrap_or_default();
        for (pos, &s) in c.scenes.iter().enumerate() {
            let fc = c.first_contact[pos] as usize;
            rows[s] = (0..scenes[s].contacts.len())
                .map(|k| unpack_row(&r[(fc + k) * ROW..(fc + k + 1) * ROW]))
                .collect();
        }
        for (rec, &(s, k)) in c.table.iter().zip(&c.keys) {
            let (n, at) = (rec.n as usize, rec.data as usize);
            lcps[s][k] = Some(Lcp {
                m: v[at..at + n * n].to_vec(),
                q: v[at + n * n..at + n * n + n].to_vec(),
            });
        }
    }
    Ok(GpuAssembly { rows, lcps })
}

/// Solves scenes on the GPU (see the module docs). Scenes are checked as on
/// the CPU path (an invalid scene is an error naming it); islands with
/// n > 16 are solved on the CPU by Lemke; a scene too large for one GPU
/// buffer is assembled on the CPU and its islands solved as an LCP batch.
pub fn solve_scenes(
    ctx: &GpuContext,
    scenes: &[Scene],
    settings: &GpuSolveSettings,
) -> Result<Report, Error> {
    let built = check_and_build(scenes)?;
    let scenes: Vec<&Scene> = scenes.iter().collect();
    solve_scenes_warm(ctx, &scenes, &built, None, settings)
}

/// Checks every scene (an error names it) and builds it.
pub(crate) fn check_and_build(scenes: &[Scene]) -> Result<Vec<Built>, Error> {
    scenes
        .iter()
        .enumerate()
        .map(|(i, s)| {
            s.validate(format_args!("scene {i}"))?;
            Ok(Built::new(s))
        })
        .collect()
}

/// [`solve_scenes`] for checked scenes and what was built of them
/// (`built[s]`: scene s's islands, rows and LCPs), with warm bases:
/// `warm[s][k]` is the basis of island k of scene s (in `find_islands`
/// order) from the previous frame, if any.
/// With `settings.predict` (default), islands that need no enumeration are
/// settled on the CPU from its f64 assembly; the GPU still assembles them
/// (the impulse stage reads every row) but does not enumerate them. The
/// host's passes (prediction, the f64 check of the answers, the impulses'
/// f64 twin) run on `settings.threads` threads. The report's islands are
/// scene after scene, each through the door's final check; its choice is
/// left empty for the caller.
pub fn solve_scenes_warm(
    ctx: &GpuContext,
    scenes: &[&Scene],
    built: &[Built],
    warm: Option<&[Vec<Option<u32>>]>,
    settings: &GpuSolveSettings,
) -> Result<Report, Error> {
    settings.check()?;
    let threads = settings.threads;
    let (max_bytes, max_groups) = limits_for(ctx, settings);
    let (chunks, alone) = plan(scenes, built, max_bytes, ctx.precision().bytes());
    // Every island of every scene, scene after scene: first[s] is scene s's first.
    let mut first = Vec::with_capacity(scenes.len() + 1);
    let mut index = Vec::new();
    for (s, b) in built.iter().enumerate() {
        first.push(index.len());
        index.extend((0..b.lcps.len()).map(|k| (s, k)));
    }
    first.push(index.len());
    let warm_of = |s: usize, k: usize| warm.and_then(|w| w.get(s)?.get(k).copied().flatten());
    let mut in_alone = vec![false; scenes.len()];
    for &s in &alone {
        in_alone[s] = true;
    }
    let mut figures = GpuFigures::default();
    let (mut accepted, mut polished) = (0, 0);

    // Prediction (and Lemke above n = 16) on the CPU's f64 assembly; each
    // island left to the GPU gets its route through the tree kernel (from
    // what prediction learnt of its M; None: settled, or in a scene solved
    // as an LCP batch below).
    let kernel_plan = KernelPlan::new(ctx, settings);
    let t = Instant::now();
    let settled = parallel_map(index.len(), threads, |j| {
        let (s, k) = index[j];
        let mut island = IslandReport {
            scene: Some(s),
            contacts: built[s].islands[k].contacts.as_slice().into(),
            method: Method::Enumeration,
            path: SolvePath::EnumeratedGpu,
            solution: LcpSolution::invalid(0),
        };
        let lcp = &built[s].lcps[k];
        let left = match in_alone[s] {
            true => None,
            false => settle_on_cpu(lcp, warm_of(s, k), settings, &mut island)
                .err()
                .map(|definite| kernel_plan.tree_for(lcp, definite)),
        };
        (island, left)
    });
    let (mut islands, left): (Vec<IslandReport>, Vec<Option<TreeRoute>>) =
        settled.into_iter().unzip();
    let prediction = t.elapsed().as_secs_f64();

    let pipelines = ctx.pipelines()?;
    let tolerances = ctx.scoped("tolerances", || {
        Tolerances::new(ctx.precision(), settings).upload(ctx)
    })?;
    let exact = settings.exact_twin(ctx.precision());
    let mut gpu_velocities: Vec<Option<Vec<f64>>> = vec![None; scenes.len()];
    let (mut gpu, mut validation) = (0.0, 0.0);
    for members in chunks {
        let t = Instant::now();
        let c = pack_chunk(
            scenes,
            built,
            &members,
            &|s, k| left[first[s] + k].is_none(),
            &|s, k| left[first[s] + k].unwrap_or(TreeRoute::Off),
        );
        let enumerate = Some((&kernel_plan, &tolerances));
        let out = assemble_and_enumerate(ctx, &pipelines, &c, max_groups, enumerate)?;
        figures += out.figures;
        figures.chunks += 1;
        gpu += t.elapsed().as_secs_f64();

        // The chunk's GPU answers checked in f64, in parallel, then put in place.
        let t = Instant::now();
        let checked = parallel_map(c.enum_keys.len(), threads, |j| {
            let ((s, k), rec) = (c.enum_keys[j], &c.enum_table[j]);
            let (z0, n) = (rec.z as usize, rec.n as usize);
            let answer = (&out.results[j], out.z.get(z0..z0 + n).unwrap_or(&[]), 0);
            // Only method, path and solution are written (and taken below).
            let mut island = IslandReport {
                scene: None,
                contacts: ShortVec::new(),
                method: Method::Enumeration,
                path: SolvePath::EnumeratedGpu,
                solution: LcpSolution::invalid(0),
            };
            let mut repair = 0.0;
            settle_from_gpu(
                &built[s].lcps[k],
                answer,
                settings,
                // The GPU solved its own assembly: its basis re-solved on
                // the CPU's (the CPU's bytes), not its z kept.
                (exact, false),
                &mut island,
                &mut repair,
            )
            .map(|(verdict, gpu_error)| (island, verdict, gpu_error, repair))
        });
        let mut repair = 0.0;
        for (j, r) in checked.into_iter().enumerate() {
            let (island, verdict, gpu_error, secs) = r?;
            repair += secs;
            let (s, k) = c.enum_keys[j];
            let mine = &mut islands[first[s] + k];
            (mine.method, mine.path, mine.solution) = (island.method, island.path, island.solution);
            polished += (verdict == Verdict::Polished) as usize;
            if gpu_error > figures.max_gpu_error {
                figures.max_gpu_error = gpu_error;
            }
        }
        let repair = repair / threads.max(1) as f64;
        figures.repair_seconds += repair;
        figures.check_seconds += (t.elapsed().as_secs_f64() - repair).max(0.0);
        validation += t.elapsed().as_secs_f64();

        // Impulses of the chunk's contacts, validated, to the impulse stage.
        let t = Instant::now();
        let mut z = vec![0.0; c.ids.len()];
        for (pos, &s) in c.scenes.iter().enumerate() {
            let fc = c.first_contact[pos] as usize;
            for isl in &islands[first[s]..first[s + 1]] {
                for (&ct, &zi) in isl.contacts.iter().zip(&isl.solution.z) {
                    z[fc + ct] = zi;
                }
            }
        }
        let vel = apply_on_gpu(ctx, &pipelines, &c, &out.resident, &z, max_groups)?;
        gpu += t.elapsed().as_secs_f64();
        for (pos, &s) in c.scenes.iter().enumerate() {
            let fb = c.first_body[pos] as usize;
            let nb = scenes[s].bodies.len();
            gpu_velocities[s] = Some(vel[fb * VELOCITY..(fb + nb) * VELOCITY].to_vec());
        }
    }
    // Scenes too large for one buffer: their islands as an LCP batch.
    for &s in &alone {
        let w = |k: usize| warm_of(s, k);
        let r = solve_lcp_batch_warm(ctx, &built[s].lcps, &w, settings)?;
        for (k, isl) in r.islands.into_iter().enumerate() {
            let mine = &mut islands[first[s] + k];
            (mine.method, mine.path, mine.solution) = (isl.method, isl.path, isl.solution);
        }
        figures += r.gpu.unwrap_or_default();
        accepted += r.counts.accepted;
        polished += r.counts.polished;
        gpu += r.timings.gpu;
        validation += r.timings.validation;
    }

    // Every scene's impulses and velocities: the f64 twin's, the GPU's
    // checked against them.
    let t = Instant::now();
    let finished = parallel_map(scenes.len(), threads, |s| {
        let mut impulses = vec![0.0; scenes[s].contacts.len()];
        for isl in &islands[first[s]..first[s + 1]] {
            for (&c, &zi) in isl.contacts.iter().zip(&isl.solution.z) {
                impulses[c] = zi;
            }
        }
        let bodies: Vec<BodyVelocity> = apply_impulses(scenes[s], &built[s].rows, &impulses);
        let deviation = gpu_velocities[s]
            .as_ref()
            .map_or(0.0, |v| velocity_deviation(&bodies, v));
        let report = SceneReport {
            impulses,
            bodies,
            islands: first[s]..first[s + 1],
            friction: None,
        };
        (report, deviation)
    });
    let (out_scenes, deviations): (Vec<SceneReport>, Vec<f64>) = finished.into_iter().unzip();
    figures.max_velocity_deviation = deviations.into_iter().fold(0.0, f64::max);
    let impulses = t.elapsed().as_secs_f64();
    let mut r = Report::new(islands, out_scenes, Device::of(ctx), String::new());
    r.counts.accepted = accepted;
    r.counts.polished = polished;
    r.counts.cpu_fallback = r.counts.lemke;
    r.timings.prediction = prediction;
    r.timings.gpu = gpu;
    r.timings.validation = validation;
    r.timings.impulses = impulses;
    r.gpu = Some(figures);
    Ok(r)
}

/// Largest |GPU velocity − f64 velocity| / (1 + |f64 velocity|) over `bodies`.
fn velocity_deviation(bodies: &[BodyVelocity], gpu: &[f64]) -> f64 {
    let mut max = 0.0f64;
    for (b, ref_v) in bodies.iter().enumerate() {
        let g = &gpu[b * VELOCITY..(b + 1) * VELOCITY];
        let (v, w) = (
            super::layout::velocity::VELOCITY,
            super::layout::velocity::ANGULAR_VELOCITY,
        );
        for i in 0..3 {
            let dv = (g[v + i] - ref_v.velocity[i]).abs() / (1.0 + ref_v.velocity[i].abs());
            let dw = (g[w + i] - ref_v.angular_velocity[i]).abs()
                / (1.0 + ref_v.angular_velocity[i].abs());
            max = max.max(dv).max(dw);
        }
    }
    max
}
