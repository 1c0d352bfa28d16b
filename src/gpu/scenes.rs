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

use super::batch::{solve_lcp_batch_warm, GpuSolveSettings, SolvedOn};
use super::buffers::limits_for;
use super::enumeration::EnumerationJob;
use super::kernel::{KernelPlan, TreeRoute};
use super::layout::{
    scalars_from_bytes, scalars_to_bytes, unpack_row, BasisResult, BodyContacts, ContactSide, BODY,
    NO_BODY, ROW, VELOCITY,
};
use super::pipelines::{Pipelines, Tolerances};
use super::scene_chunks::{pack_chunk, plan, Chunk};
use super::{GpuContext, MAX_GPU_N};
use crate::build::Built;
use crate::cpu::assembly::ContactRow;
use crate::cpu::impulses::{apply_impulses, BodyVelocity};
use crate::cpu::lemke::lemke;
use crate::gpu::validation::{validate_island, BatchReport, GpuVerdict, Verdict};
use crate::lcp::{Lcp, LcpSolution};
use crate::prediction::{prediction, SolvePath};
use crate::report::{IslandReport, SceneReport};
use crate::scene::Scene;
use crate::settings::Method;
use crate::Error;

/// Scenes after the impact, with where each island was solved.
#[derive(Clone, Debug)]
pub struct GpuSceneResult {
    /// Every island of every scene, scene after scene, in `find_islands`
    /// order: the door's reports (method, path, validated solution).
    pub islands: Vec<IslandReport>,
    /// Per scene: impulses, velocities after them (the f64 twin's) and its
    /// islands' range in `islands`.
    pub scenes: Vec<SceneReport>,
    /// Per scene, per island: where it was solved.
    pub solved_on: Vec<Vec<SolvedOn>>,
    pub report: BatchReport,
    /// Largest |GPU velocity − f64 velocity| / (1 + |f64 velocity|) of the
    /// impulse stage over every body.
    pub max_velocity_deviation: f64,
}

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
    dispatches: usize,
    rounds: usize,
    /// Islands the tree kernel decided, and those it left to elimination.
    tree: (usize, usize),
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
                    islands: &enum_islands,
                    values: &values,
                    tolerances,
                    table: &c.enum_table,
                    tree: &c.enum_tree,
                    max_groups,
                    plan,
                };
                let run = job.run(encoder, true)?;
                return Ok(StageOutput {
                    results: run.results,
                    z: run.z,
                    rows: None,
                    values: None,
                    resident: Resident { bodies, rows },
                    dispatches: dispatches + run.dispatches,
                    rounds: run.rounds,
                    tree: (run.tree_decided, run.tree_undecided),
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
                dispatches,
                rounds: 0,
                tree: (0, 0),
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
) -> Result<GpuSceneResult, Error> {
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
/// (the impulse stage reads every row) but does not enumerate them.
pub fn solve_scenes_warm(
    ctx: &GpuContext,
    scenes: &[&Scene],
    built: &[Built],
    warm: Option<&[Vec<Option<u32>>]>,
    settings: &GpuSolveSettings,
) -> Result<GpuSceneResult, Error> {
    settings.enumeration.validate()?;
    if settings.enumeration.all_solutions {
        return Err(Error::Unsupported(
            "all_solutions is not supported on the GPU; use the CPU backend".into(),
        ));
    }
    let prepared = built;
    let (max_bytes, max_groups) = limits_for(ctx, settings);
    let (chunks, alone) = plan(scenes, prepared, max_bytes, ctx.precision().bytes());
    let mut run = SceneRun {
        ctx,
        scenes,
        settings,
        pipelines: ctx.pipelines()?,
        tolerances: ctx.scoped("tolerances", || {
            Tolerances::new(ctx.precision(), settings).upload(ctx)
        })?,
        max_groups,
        kernel_plan: KernelPlan::new(ctx, settings),
        report: BatchReport::new(ctx.adapter_info().name.clone(), ctx.precision()),
        solved: prepared
            .iter()
            .map(|p| vec![None; p.islands.len()])
            .collect(),
        gpu_velocities: vec![None; scenes.len()],
        predicted: Vec::new(),
        definite: Vec::new(),
        prepared,
    };
    run.predict(warm, &alone);
    for members in chunks {
        run.chunk(&members)?;
    }
    // Scenes too large for one buffer: their islands as an LCP batch.
    for &s in &alone {
        let w = warm.and_then(|w| w.get(s)).map(Vec::as_slice);
        let r = solve_lcp_batch_warm(ctx, &run.prepared[s].lcps, w, settings)?;
        run.report.merge(&r.report);
        for (k, o) in r.islands.into_iter().enumerate() {
            let path = o.path.unwrap_or(SolvePath::Enumerated);
            run.solved[s][k] = Some((o.solution, o.solver, o.solved_on, path));
        }
    }
    run.finish()
}

/// Per scene, per island: the solution, its solver and where it came from.
type Solved = Vec<Vec<Option<(LcpSolution, Method, SolvedOn, SolvePath)>>>;

/// What [`solve_scenes_warm`]'s steps share.
struct SceneRun<'a> {
    ctx: &'a GpuContext,
    scenes: &'a [&'a Scene],
    settings: &'a GpuSolveSettings,
    pipelines: std::sync::Arc<Pipelines>,
    tolerances: wgpu::Buffer,
    max_groups: u32,
    kernel_plan: KernelPlan,
    report: BatchReport,
    prepared: &'a [Built],
    solved: Solved,
    /// Per scene: the impulse stage's velocities (8 scalars per body).
    gpu_velocities: Vec<Option<Vec<f64>>>,
    /// Per scene, per island: the solution prediction settled, or whether
    /// M is positive definite where prediction found out (for the tree
    /// kernel's route).
    predicted: Vec<Vec<Option<(SolvePath, LcpSolution)>>>,
    definite: Vec<Vec<Option<bool>>>,
}

impl SceneRun<'_> {
    /// Prediction, on the f64 assembly, for every island the GPU would enumerate.
    fn predict(&mut self, warm: Option<&[Vec<Option<u32>>]>, alone: &[usize]) {
        let t_predict = Instant::now();
        let settings = self.settings;
        (self.predicted, self.definite) = self
            .prepared
            .iter()
            .enumerate()
            .map(|(s, p)| {
                p.lcps
                    .iter()
                    .enumerate()
                    .map(|(k, lcp)| {
                        if !settings.predict || lcp.n() > MAX_GPU_N || alone.contains(&s) {
                            return (None, None);
                        }
                        let w = warm
                            .and_then(|w| w.get(s))
                            .and_then(|v| v.get(k).copied().flatten());
                        match prediction(lcp, w, &settings.enumeration) {
                            Ok(settled) => (Some(settled), None),
                            Err(unsettled) => (None, unsettled.definite),
                        }
                    })
                    .unzip()
            })
            .unzip();
        self.report.prediction_seconds += t_predict.elapsed().as_secs_f64();
    }

    /// One chunk of scenes: assembly and enumeration on the GPU, validation
    /// on the CPU, impulses on the GPU.
    fn chunk(&mut self, members: &[usize]) -> Result<(), Error> {
        let t0 = Instant::now();
        let (prepared, predicted, definite) = (self.prepared, &self.predicted, &self.definite);
        let c = pack_chunk(
            self.scenes,
            prepared,
            members,
            &|s, k| predicted[s][k].is_some(),
            &|s, k| match predicted[s][k] {
                Some(_) => TreeRoute::Off,
                None => self
                    .kernel_plan
                    .tree_for(&prepared[s].lcps[k], definite[s][k]),
            },
        );
        let enumerate = Some((&self.kernel_plan, &self.tolerances));
        let out =
            assemble_and_enumerate(self.ctx, &self.pipelines, &c, self.max_groups, enumerate)?;
        let report = &mut self.report;
        report.gpu_seconds += t0.elapsed().as_secs_f64();
        report.chunks += 1;
        report.dispatches += out.dispatches;
        report.rounds += out.rounds;
        report.tree_decided += out.tree.0;
        report.tree_undecided += out.tree.1;
        let t1 = Instant::now();
        self.settle(&c, &out)?;
        self.report.validation_seconds += t1.elapsed().as_secs_f64();
        // Impulses of the chunk's contacts, validated, to the impulse stage.
        let t2 = Instant::now();
        let mut z = vec![0.0; c.ids.len()];
        for (pos, &s) in c.scenes.iter().enumerate() {
            let fc = c.first_contact[pos] as usize;
            for (k, isl) in self.prepared[s].islands.iter().enumerate() {
                if let Some((sol, _, _, _)) = &self.solved[s][k] {
                    for (&ct, &zi) in isl.contacts.iter().zip(&sol.z) {
                        z[fc + ct] = zi;
                    }
                }
            }
        }
        let vel = apply_on_gpu(
            self.ctx,
            &self.pipelines,
            &c,
            &out.resident,
            &z,
            self.max_groups,
        )?;
        self.report.gpu_seconds += t2.elapsed().as_secs_f64();
        for (pos, &s) in c.scenes.iter().enumerate() {
            let fb = c.first_body[pos] as usize;
            let nb = self.scenes[s].bodies.len();
            self.gpu_velocities[s] = Some(vel[fb * VELOCITY..(fb + nb) * VELOCITY].to_vec());
        }
        Ok(())
    }

    /// The chunk's islands: predicted, validated GPU answers, Lemke above
    /// [`MAX_GPU_N`].
    fn settle(&mut self, c: &Chunk, out: &StageOutput) -> Result<(), Error> {
        let settings = self.settings;
        for &(s, k) in &c.keys {
            if let Some((path, sol)) = self.predicted[s][k].take() {
                self.report.record_predicted(path, &sol);
                self.solved[s][k] = Some((sol, Method::Enumeration, SolvedOn::Predicted, path));
            }
        }
        for ((rec, &(s, k)), res) in c.enum_table.iter().zip(&c.enum_keys).zip(&out.results) {
            let (z0, n) = (rec.z as usize, rec.n as usize);
            let verdict = GpuVerdict::of(res, out.z.get(z0..z0 + n).unwrap_or(&[]));
            let checked = validate_island(
                &self.prepared[s].lcps[k],
                &verdict,
                &settings.enumeration,
                settings.exact_twin(self.ctx.precision()),
            )?;
            self.report.record_gpu(&checked);
            let on = if checked.verdict == Verdict::Repaired {
                SolvedOn::Repaired
            } else {
                SolvedOn::Gpu
            };
            self.solved[s][k] = Some((
                checked.solution,
                Method::Enumeration,
                on,
                SolvePath::Enumerated,
            ));
        }
        for &s in &c.scenes {
            for (k, isl) in self.prepared[s].islands.iter().enumerate() {
                if isl.len() > MAX_GPU_N {
                    let sol = lemke(&self.prepared[s].lcps[k], &settings.lemke);
                    self.report.record_cpu_fallback(&sol);
                    self.solved[s][k] =
                        Some((sol, Method::Lemke, SolvedOn::CpuFallback, SolvePath::Lemke));
                }
            }
        }
        Ok(())
    }

    /// Every scene's report in the CPU path's shape; the f64 twin's
    /// velocities are kept, the GPU's checked against them.
    fn finish(self) -> Result<GpuSceneResult, Error> {
        let mut solved = self.solved;
        let mut max_velocity_deviation = 0.0f64;
        let mut islands = Vec::new();
        let mut out_scenes = Vec::with_capacity(self.scenes.len());
        let mut solved_on = Vec::with_capacity(self.scenes.len());
        for (s, (scene, p)) in self.scenes.iter().zip(self.prepared).enumerate() {
            let first = islands.len();
            let mut impulses = vec![0.0; scene.contacts.len()];
            let mut on = Vec::with_capacity(p.islands.len());
            for (island, slot) in p.islands.iter().zip(&mut solved[s]) {
                let (solution, method, where_, path) = slot
                    .take()
                    .ok_or_else(|| Error::Gpu(format!("scene {s}: an island got no result")))?;
                for (&c, &zi) in island.contacts.iter().zip(&solution.z) {
                    impulses[c] = zi;
                }
                on.push(where_);
                islands.push(IslandReport {
                    scene: Some(s),
                    contacts: island.contacts.as_slice().into(),
                    method,
                    path: where_.path(Some(path)),
                    solution,
                });
            }
            let bodies: Vec<BodyVelocity> = apply_impulses(scene, &p.rows, &impulses);
            if let Some(v) = &self.gpu_velocities[s] {
                let dev = velocity_deviation(&bodies, v);
                max_velocity_deviation = max_velocity_deviation.max(dev);
            }
            out_scenes.push(SceneReport {
                impulses,
                bodies,
                islands: first..islands.len(),
                friction: None,
            });
            solved_on.push(on);
        }
        Ok(GpuSceneResult {
            islands,
            scenes: out_scenes,
            solved_on,
            report: self.report,
            max_velocity_deviation,
        })
    }
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
