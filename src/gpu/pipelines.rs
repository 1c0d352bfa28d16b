//! Bind group layouts (declared once, here), compute pipelines built from
//! the committed shaders ([`super::shaders`]), their cache in the
//! [`GpuContext`], and the enumeration kernels' run-time tolerances.

use std::sync::{Arc, OnceLock};

use wgpu::util::DeviceExt;

use super::batch::GpuSolveSettings;
use super::layout::scalars_to_bytes;
use super::shaders::{Shader, FIXED_MAX_N, FRICTION_MAX_K};
use super::{GpuContext, Precision};
use crate::cpu::enumeration_tree::{TreeSettings, TREE_MAX_N};
use crate::Error;

/// How a shader sees one binding.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Access {
    Uniform,
    Read,
    ReadWrite,
}
use Access::{Read, ReadWrite, Uniform};

/// The bindings of one entry point (group 0): (binding, access), in the
/// order [`Stage::bind`] takes its buffers.
pub(crate) type Bindings = &'static [(u32, Access)];

/// Every enumeration kernel (shaders/enumeration_basis.wgsl): params,
/// islands, values, results, z, unfinished, least_infeasibility, tolerances.
pub(crate) const ENUMERATION_BINDINGS: Bindings = &[
    (0, Uniform),
    (1, Read),
    (2, Read),
    (3, ReadWrite),
    (4, ReadWrite),
    (5, ReadWrite),
    (6, ReadWrite),
    (7, Uniform),
];
/// shaders/enumeration_all.wgsl: params, islands, values, tolerances,
/// verdicts (the shared enumeration bindings it uses, and its own).
pub(crate) const ALL_BASES_BINDINGS: Bindings = &[
    (0, Uniform),
    (1, Read),
    (2, Read),
    (7, Uniform),
    (8, ReadWrite),
];
/// `assemble_contacts` (shaders/assembly.wgsl): params, bodies,
/// contact_bodies, contacts, rows.
pub(crate) const ASSEMBLE_CONTACTS_BINDINGS: Bindings = &[
    (0, Uniform),
    (1, Read),
    (2, Read),
    (3, Read),
    (4, ReadWrite),
];
/// `assemble_islands` (shaders/assembly.wgsl): params, contact_bodies, rows,
/// islands, slots, values.
pub(crate) const ASSEMBLE_ISLANDS_BINDINGS: Bindings = &[
    (0, Uniform),
    (2, Read),
    (4, ReadWrite),
    (5, Read),
    (6, Read),
    (7, ReadWrite),
];
/// shaders/impulses.wgsl: params, bodies, rows, body_contacts,
/// contact_sides, z, velocities.
pub(crate) const IMPULSES_BINDINGS: Bindings = &[
    (0, Uniform),
    (1, Read),
    (2, Read),
    (3, Read),
    (4, Read),
    (5, Read),
    (6, ReadWrite),
];

/// shaders/friction_projected.wgsl (sweeps, apgd): params, islands, values,
/// vectors, scalars, states, unfinished, controls.
pub(crate) const FRICTION_PROJECTED_BINDINGS: Bindings = &[
    (0, Uniform),
    (1, Read),
    (2, Read),
    (3, ReadWrite),
    (4, ReadWrite),
    (5, ReadWrite),
    (6, ReadWrite),
    (7, Uniform),
];

/// `collide_pairs` (shaders/collide.wgsl): params, bodies, pairs, margins,
/// points, keys, counts.
pub(crate) const COLLIDE_BINDINGS: Bindings = &[
    (0, Uniform),
    (1, Read),
    (2, Read),
    (3, Read),
    (4, ReadWrite),
    (5, ReadWrite),
    (6, ReadWrite),
];

/// Every entry point of the resident world step (shaders/world_step.wgsl's
/// bindings, [`WorldStages`]): params, worlds, consts, state, scratch,
/// words, records, lists (the pair lists and the deferred worlds).
pub(crate) const WORLD_STEP_BINDINGS: Bindings = &[
    (0, Uniform),
    (1, Read),
    (2, Read),
    (3, ReadWrite),
    (4, ReadWrite),
    (5, ReadWrite),
    (6, ReadWrite),
    (7, ReadWrite),
];

/// Workgroup size of every entry point (`@workgroup_size(64)`).
pub const WORKGROUP: u32 = 64;

/// One entry point: its bind group layout and its pipeline.
pub(crate) struct Stage {
    layout: wgpu::BindGroupLayout,
    pub(crate) pipeline: wgpu::ComputePipeline,
    bindings: Bindings,
    /// The entry point's name (for timings and errors).
    pub(crate) entry: &'static str,
}

impl Stage {
    fn new(
        ctx: &GpuContext,
        shader: Shader,
        entry: &'static str,
        bindings: Bindings,
    ) -> Result<Self, Error> {
        // In a scope of its own, so that a driver refusing the kernel (a
        // lost device: wgpu-hal reads a failed vkCreateComputePipelines as
        // one) is reported with the kernel's name.
        let what = format!("building the kernel {}::{entry}", shader.name());
        ctx.scoped(&what, || Self::build(ctx, shader, entry, bindings))?
    }

    fn build(
        ctx: &GpuContext,
        shader: Shader,
        entry: &'static str,
        bindings: Bindings,
    ) -> Result<Self, Error> {
        let d = &ctx.device;
        let source = shader.source(ctx.precision())?;
        let module = d.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(&shader.name()),
            source: wgpu::ShaderSource::Wgsl(source.into()),
        });
        let entries: Vec<wgpu::BindGroupLayoutEntry> = bindings
            .iter()
            .map(|&(binding, access)| wgpu::BindGroupLayoutEntry {
                binding,
                visibility: wgpu::ShaderStages::COMPUTE,
                ty: wgpu::BindingType::Buffer {
                    ty: match access {
                        Uniform => wgpu::BufferBindingType::Uniform,
                        Read => wgpu::BufferBindingType::Storage { read_only: true },
                        ReadWrite => wgpu::BufferBindingType::Storage { read_only: false },
                    },
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
                count: None,
            })
            .collect();
        let layout = d.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some(entry),
            entries: &entries,
        });
        let pl = d.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(entry),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = d.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(entry),
            layout: Some(&pl),
            module: &module,
            entry_point: Some(entry),
            compilation_options: Default::default(),
            cache: None,
        });
        Ok(Stage {
            layout,
            pipeline,
            bindings,
            entry,
        })
    }

    /// A bind group with `buffers` bound, in the order of the stage's
    /// bindings (a count that does not match is a wgpu validation error).
    pub(crate) fn bind(&self, ctx: &GpuContext, buffers: &[&wgpu::Buffer]) -> wgpu::BindGroup {
        let whole: Vec<wgpu::BufferBinding> = buffers
            .iter()
            .map(|b| b.as_entire_buffer_binding())
            .collect();
        self.bind_parts(ctx, &whole)
    }

    /// [`Self::bind`] with a part of each buffer (offset and size).
    pub(crate) fn bind_parts(
        &self,
        ctx: &GpuContext,
        parts: &[wgpu::BufferBinding],
    ) -> wgpu::BindGroup {
        let entries: Vec<wgpu::BindGroupEntry> = self
            .bindings
            .iter()
            .zip(parts)
            .map(|(&(binding, _), part)| wgpu::BindGroupEntry {
                binding,
                resource: wgpu::BindingResource::Buffer(part.clone()),
            })
            .collect();
        ctx.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("bind group"),
            layout: &self.layout,
            entries: &entries,
        })
    }
}

/// Every stage's pipeline for the context's precision. The specialised
/// kernels are built on first use (each is one more shader compilation).
pub(crate) struct Pipelines {
    /// `shaders/enumeration.wgsl`, any island size.
    pub(crate) enumeration: Stage,
    /// `shaders/enumeration_workgroup.wgsl`: one workgroup per island, the
    /// bases of each popcount in waves of [`WORKGROUP`] lanes.
    pub(crate) enumeration_workgroup: Stage,
    /// [`Shader::Unrolled`] n at index n − 1 (n = 1…[`FIXED_MAX_N`]).
    unrolled: Vec<OnceLock<Stage>>,
    /// [`Shader::Tree`] n at index n − 1 (n = 1…[`TREE_MAX_N`]).
    tree: Vec<OnceLock<Stage>>,
    /// [`Shader::AllBases`] (`all_solutions` only), built on first use.
    all_bases: OnceLock<Stage>,
    /// [`Shader::Settle`] (LCP batches with warm or predicted bases),
    /// built on first use.
    settle: OnceLock<Stage>,
    /// [`Shader::Lemke`], built on first use.
    lemke: OnceLock<Stage>,
    pub(crate) assemble_contacts: Stage,
    pub(crate) assemble_islands: Stage,
    pub(crate) impulses: Stage,
    /// [`Shader::FrictionProjected`] k at index 2(k − 1) (`sweeps`) and
    /// 2(k − 1) + 1 (`apgd`), built on first use (the LCP path never
    /// builds them).
    friction_projected: Vec<OnceLock<Stage>>,
    /// [`Shader::Collide`] (the narrow phase), built on first use.
    collide: OnceLock<Stage>,
    /// The resident world step's stages, built on first use.
    world_step: OnceLock<WorldStages>,
    /// [`Shader::WorldFriction`]'s `world_friction` (the sweeps) and
    /// [`Shader::WorldFrictionApgd`]'s (APGD), each built on first use.
    world_friction: [OnceLock<Stage>; 2],
}

/// The resident world step's entry points (every one with
/// [`WORLD_STEP_BINDINGS`]), in dispatch order: shaders/world_step.wgsl's
/// header.
pub(crate) struct WorldStages {
    /// [`Shader::WorldCollide`]: per world the candidates and the pair
    /// lists; per listed pair the narrow phase by family (box–box,
    /// box–plane, with a sphere: the lists 1, 2, 3 of `lists`, indirect
    /// dispatches); per world the contacts.
    pub(crate) candidate_pairs: Stage,
    pub(crate) narrow: [Stage; 3],
    pub(crate) world_contacts: Stage,
    /// [`Shader::WorldAssemble`]: per world the islands, handed over to
    /// the frictional phase or assembled (M, q, the responses kept per
    /// contact slot); [`Shader::WorldSolve`]: per world the islands whose warm bases
    /// hold, the others listed; [`Shader::WorldLemke`]: per listed world
    /// those islands by Lemke's path (indirect), [`Shader::WorldLemkeCheck`]
    /// their bases re-solved and checked (indirect); [`Shader::WorldFinish`]:
    /// per world `finish` (after the frictional rounds, where any).
    pub(crate) world_assemble: Stage,
    pub(crate) world_solve_warm: Stage,
    pub(crate) world_lemke: Stage,
    pub(crate) world_lemke_check: Stage,
    pub(crate) world_finish: Stage,
}

/// The stage in `cache` (index n − 1), built on first use.
fn lazy<'a>(
    cache: &'a [OnceLock<Stage>],
    ctx: &GpuContext,
    n: usize,
    shader: Shader,
) -> Result<&'a Stage, Error> {
    let slot = n
        .checked_sub(1)
        .and_then(|i| cache.get(i))
        .ok_or_else(|| Error::Gpu(format!("no {shader:?} kernel for n = {n}")))?;
    once(slot, ctx, shader, ENUMERATION_BINDINGS)
}

/// The stage in `slot` (entry point `main` of `shader`), built on first use.
fn once<'a>(
    slot: &'a OnceLock<Stage>,
    ctx: &GpuContext,
    shader: Shader,
    bindings: Bindings,
) -> Result<&'a Stage, Error> {
    if let Some(s) = slot.get() {
        return Ok(s);
    }
    let stage = Stage::new(ctx, shader, "main", bindings)?;
    Ok(slot.get_or_init(|| stage))
}

impl Pipelines {
    fn build(ctx: &GpuContext) -> Result<Self, Error> {
        ctx.scoped("building the pipelines", || -> Result<Self, Error> {
            let enumeration = |s| Stage::new(ctx, s, "main", ENUMERATION_BINDINGS);
            Ok(Pipelines {
                enumeration: enumeration(Shader::Enumeration)?,
                enumeration_workgroup: enumeration(Shader::Workgroup)?,
                unrolled: (0..FIXED_MAX_N).map(|_| OnceLock::new()).collect(),
                tree: (0..TREE_MAX_N).map(|_| OnceLock::new()).collect(),
                all_bases: OnceLock::new(),
                settle: OnceLock::new(),
                lemke: OnceLock::new(),
                assemble_contacts: Stage::new(
                    ctx,
                    Shader::Assembly,
                    "assemble_contacts",
                    ASSEMBLE_CONTACTS_BINDINGS,
                )?,
                assemble_islands: Stage::new(
                    ctx,
                    Shader::Assembly,
                    "assemble_islands",
                    ASSEMBLE_ISLANDS_BINDINGS,
                )?,
                impulses: Stage::new(ctx, Shader::Impulses, "main", IMPULSES_BINDINGS)?,
                friction_projected: (0..2 * FRICTION_MAX_K).map(|_| OnceLock::new()).collect(),
                collide: OnceLock::new(),
                world_step: OnceLock::new(),
                world_friction: [OnceLock::new(), OnceLock::new()],
            })
        })?
    }

    /// The specialised elimination stage for islands of n contacts
    /// (1 ≤ n ≤ [`FIXED_MAX_N`]), built on first use.
    pub(crate) fn unrolled(&self, ctx: &GpuContext, n: usize) -> Result<&Stage, Error> {
        lazy(&self.unrolled, ctx, n, Shader::Unrolled(n))
    }

    /// The stage that screens every basis of every island, built on first use.
    pub(crate) fn all_bases(&self, ctx: &GpuContext) -> Result<&Stage, Error> {
        once(&self.all_bases, ctx, Shader::AllBases, ALL_BASES_BINDINGS)
    }

    /// The settle stage (each island's warm, then predicted basis; the
    /// enumeration kernels' bindings), built on first use.
    pub(crate) fn settle(&self, ctx: &GpuContext) -> Result<&Stage, Error> {
        once(&self.settle, ctx, Shader::Settle, ENUMERATION_BINDINGS)
    }

    /// The Lemke stage (islands of any size up to
    /// [`super::MAX_GPU_N`]; the enumeration kernels' bindings), built on
    /// first use.
    pub(crate) fn lemke(&self, ctx: &GpuContext) -> Result<&Stage, Error> {
        once(&self.lemke, ctx, Shader::Lemke, ENUMERATION_BINDINGS)
    }

    /// The narrow phase's stage (`collide_pairs`), built on first use.
    pub(crate) fn collide(&self, ctx: &GpuContext) -> Result<&Stage, Error> {
        if let Some(s) = self.collide.get() {
            return Ok(s);
        }
        let stage = Stage::new(ctx, Shader::Collide, "collide_pairs", COLLIDE_BINDINGS)?;
        Ok(self.collide.get_or_init(|| stage))
    }

    /// The resident world step's stages (one layout, [`WorldStages`]),
    /// built on first use.
    pub(crate) fn world_step(&self, ctx: &GpuContext) -> Result<&WorldStages, Error> {
        if let Some(s) = self.world_step.get() {
            return Ok(s);
        }
        let stage = |shader, entry| Stage::new(ctx, shader, entry, WORLD_STEP_BINDINGS);
        let collide = |entry| stage(Shader::WorldCollide, entry);
        let stages = WorldStages {
            candidate_pairs: collide("candidate_pairs")?,
            narrow: [
                collide("narrow_box_box")?,
                collide("narrow_box_plane")?,
                collide("narrow_sphere")?,
            ],
            world_contacts: collide("world_contacts")?,
            world_assemble: stage(Shader::WorldAssemble, "world_assemble")?,
            world_solve_warm: stage(Shader::WorldSolve, "world_solve_warm")?,
            world_lemke: stage(Shader::WorldLemke, "world_lemke")?,
            world_lemke_check: stage(Shader::WorldLemkeCheck, "world_lemke_check")?,
            world_finish: stage(Shader::WorldFinish, "world_finish")?,
        };
        Ok(self.world_step.get_or_init(|| stages))
    }

    /// The resident world step's frictional stage `world_friction` (the
    /// layout of [`Self::world_step`]'s) of the sweeps or, `apgd`, of
    /// APGD, built on first use.
    pub(crate) fn world_friction(&self, ctx: &GpuContext, apgd: bool) -> Result<&Stage, Error> {
        let cell = &self.world_friction[usize::from(apgd)];
        if let Some(s) = cell.get() {
            return Ok(s);
        }
        let shader = match apgd {
            true => Shader::WorldFrictionApgd,
            false => Shader::WorldFriction,
        };
        let stage = Stage::new(ctx, shader, "world_friction", WORLD_STEP_BINDINGS)?;
        Ok(cell.get_or_init(|| stage))
    }

    /// The tree stage for islands of n contacts (1 ≤ n ≤ [`TREE_MAX_N`]),
    /// built on first use.
    pub(crate) fn tree(&self, ctx: &GpuContext, n: usize) -> Result<&Stage, Error> {
        lazy(&self.tree, ctx, n, Shader::Tree(n))
    }
}

impl Pipelines {
    /// The entry point `sweeps` (`apgd` false) or `apgd` of
    /// shaders/friction_projected.wgsl for islands of k contacts
    /// (1 ≤ k ≤ [`FRICTION_MAX_K`]), built on first use.
    pub(crate) fn friction_projected(
        &self,
        ctx: &GpuContext,
        k: usize,
        apgd: bool,
    ) -> Result<&Stage, Error> {
        let slot = k
            .checked_sub(1)
            .and_then(|i| self.friction_projected.get(2 * i + apgd as usize))
            .ok_or_else(|| Error::Gpu(format!("no friction kernel for k = {k}")))?;
        if let Some(s) = slot.get() {
            return Ok(s);
        }
        let entry = if apgd { "apgd" } else { "sweeps" };
        let stage = ctx.scoped("building the friction pipeline", || {
            Stage::new(
                ctx,
                Shader::FrictionProjected(k),
                entry,
                FRICTION_PROJECTED_BINDINGS,
            )
        })??;
        Ok(slot.get_or_init(|| stage))
    }
}

impl GpuContext {
    /// The pipelines for the context's precision, built on first use.
    pub(crate) fn pipelines(&self) -> Result<Arc<Pipelines>, Error> {
        let mut cache = self
            .pipelines
            .lock()
            .map_err(|_| Error::Gpu("pipeline cache poisoned".into()))?;
        if let Some(p) = cache.as_ref() {
            return Ok(p.clone());
        }
        let p = Arc::new(Pipelines::build(self)?);
        *cache = Some(p.clone());
        Ok(p)
    }
}

/// Tree kernel in f32: the screen's tolerance (f64 uses
/// [`TreeSettings`]'), looser than the f32 feasibility tolerance (1e-4).
pub const F32_SCREEN_TOL: f64 = 1e-3;
/// Tree kernel in f32: a pivot T_dd at most this times M_dd leaves the
/// island to elimination (f64 uses [`TreeSettings`]'). With f32's 6e-8
/// rounding it bounds a leaf's error near 1e-4, under the screen's 1e-3.
pub const F32_TREE_PIVOT_TOL: f64 = 1e-3;
/// Tree kernel in f32, semidefinite islands: a pivot at most this times
/// M_dd is singular (f32 rounds a singular Schur complement to about 1e-7
/// of M_dd) and cuts its subtree.
pub const F32_TREE_SINGULAR_TOL: f64 = 1e-5;

/// The Lemke kernel in f32: an entry of the entering column is a pivot when
/// it exceeds this times the column's largest magnitude (f64 uses
/// [`crate::cpu::lemke::LemkeSettings`]'). f32 tableaus carry rounding near
/// 1e-7 of their entries; the f64 check decides on the basis.
pub const F32_LEMKE_PIVOT_TOL: f64 = 1e-6;

/// The pivot cap the Lemke kernel reads (an f32 holds integers exactly up to
/// 2^24).
const LEMKE_MAX_PIVOTS: u64 = 1 << 24;

/// The enumeration kernels' tolerances (WGSL `Tolerances`, binding 7):
/// pivot, feasibility, relaxed, screen, tree pivot, tree singular, and two
/// pads, which the Lemke kernel reads as its pivot tolerance and pivot cap,
/// in the shader's precision. Passed at run time so that the
/// committed shaders serve every setting; the f64 values are the CPU twins'
/// exactly, so the f64 arithmetic stays the twins' bit for bit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Tolerances(pub [f64; 8]);

impl Tolerances {
    pub(crate) fn new(precision: Precision, settings: &GpuSolveSettings) -> Self {
        let (pivot, feasibility, relaxed) = settings.gpu_tolerances(precision);
        let tree = TreeSettings::default();
        let (screen, tree_pivot, singular) = if precision == Precision::F64 {
            (tree.screen_tol, tree.pivot_tol, tree.singular_tol)
        } else {
            (F32_SCREEN_TOL, F32_TREE_PIVOT_TOL, F32_TREE_SINGULAR_TOL)
        };
        let lemke = &settings.lemke;
        let lemke_pivot = if precision == Precision::F64 {
            lemke.pivot_tol
        } else {
            lemke.pivot_tol.max(F32_LEMKE_PIVOT_TOL)
        };
        Tolerances([
            pivot,
            feasibility,
            relaxed,
            screen,
            tree_pivot,
            singular,
            lemke_pivot,
            lemke.max_pivots.min(LEMKE_MAX_PIVOTS) as f64,
        ])
    }

    /// A uniform buffer holding the tolerances in `ctx`'s precision: the
    /// context's, kept while the tolerances asked for are the same (a
    /// uniform no call rewrites: others may hold it), else a new one, kept
    /// in its place.
    pub(crate) fn upload(&self, ctx: &GpuContext) -> wgpu::Buffer {
        let mut kept = ctx.kept.lock().ok();
        if let Some((t, buffer)) = kept.as_ref().and_then(|k| k.tolerances.as_ref()) {
            if t == self {
                return buffer.clone();
            }
        }
        let buffer = ctx
            .device
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("tolerances"),
                contents: &scalars_to_bytes(&self.0, ctx.precision()),
                usage: wgpu::BufferUsages::UNIFORM,
            });
        if let Some(k) = kept.as_mut() {
            k.tolerances = Some((*self, buffer.clone()));
        }
        buffer
    }
}
