//! The GPU assembly of frictional islands: W = J M⁻¹ Jᵀ (3k × 3k,
//! interleaved per contact) and q, the twin of
//! [`crate::friction::assembly`] (`assemble_friction_contact`,
//! `assemble_friction_island`).
//!
//! No new shader: the CPU twin defines a contact's three rows as the
//! frictionless row ([`crate::cpu::assembly::assemble_contact`]) along n
//! (with restitution) and along t₁, t₂ (without), and W's entries as
//! `matrix_entry` of those rows. So the stages of `shaders/assembly.wgsl`
//! run as they are on the **direction contacts**: each contact c becomes
//! the three contacts 3c (normal n), 3c + 1 (t₁), 3c + 2 (t₂), with the
//! frame of [`crate::Contact::tangents`] computed here while packing;
//! `assemble_contacts` gives the 3 rows per contact, `assemble_islands`
//! over the island's 3k direction contacts in order gives exactly W
//! (interleaved) and q. A shader of its own would repeat assembly.wgsl
//! line for line. `src/tests/gpu_friction_assembly.rs` compares the result
//! with the CPU twin.

use super::buffers::limits_for;
use super::layout::{pack_body, pack_contact, scalars_from_bytes, scalars_to_bytes};
use super::layout::{ContactBodies, PackedIsland, Slot, ROW};
use super::{GpuContext, GpuSolveSettings};
use crate::friction::assembly::FrictionIsland;
use crate::friction::FrictionProblem;
use crate::islands::{find_islands, Island};
use crate::scene::{Contact, Scene};
use crate::settings::GpuSettings;
use crate::Error;

/// The three direction contacts of `c`: itself (normal n, its restitution),
/// then along t₁ and t₂ with restitution 0 (as the CPU twin assembles them).
pub(crate) fn direction_contacts(c: &Contact) -> [Contact; 3] {
    let (t1, t2) = c.tangents();
    let along = |d: glam::DVec3| {
        let mut dc = c.clone();
        dc.normal = d.to_array();
        dc.restitution = 0.0;
        dc
    };
    [c.clone(), along(t1), along(t2)]
}

/// The packed inputs of the assembly stages for a batch of scenes.
#[derive(Default)]
struct Packed {
    bodies: Vec<f64>,
    ids: Vec<ContactBodies>,
    contacts: Vec<f64>,
    table: Vec<PackedIsland>,
    slots: Vec<Slot>,
    values_len: usize,
    /// (scene, island's contacts, μ) of every table entry.
    keys: Vec<(usize, Vec<usize>, Vec<f64>)>,
}

impl Packed {
    /// Adds scene `s` (validated) and its `islands`: its bodies, its
    /// direction contacts, and one table entry of 3k rows per island.
    fn add(&mut self, s: usize, scene: &Scene, islands: &[Island]) {
        let fb = (self.bodies.len() / super::layout::BODY) as u32;
        let fc = self.ids.len() as u32;
        for b in &scene.bodies {
            pack_body(b, &mut self.bodies);
        }
        for c in &scene.contacts {
            for dc in direction_contacts(c) {
                pack_contact(&dc, &scene.bodies, fb, &mut self.ids, &mut self.contacts);
            }
        }
        for island in islands {
            let n = 3 * island.len();
            let index = self.table.len() as u32;
            self.table.push(PackedIsland {
                n: n as u32,
                data: self.values_len as u32,
                z: 0,
                contacts: self.slots.len() as u32,
            });
            for &c in &island.contacts {
                for d in 0..3 {
                    self.slots.push(Slot {
                        island: index,
                        contact: fc + 3 * c as u32 + d,
                    });
                }
            }
            self.values_len += n * n + n;
            let mu = island.contacts.iter().map(|&c| scene.contacts[c].friction);
            self.keys.push((s, island.contacts.clone(), mu.collect()));
        }
    }

    /// Bytes of the rows, values, bodies and contacts buffers at `sb`
    /// bytes per scalar (the largest ones; each grows by a scene's own).
    fn bytes(&self, sb: u64) -> [u64; 4] {
        [
            (self.ids.len() * ROW) as u64 * sb,
            self.values_len as u64 * sb,
            self.bodies.len() as u64 * sb,
            self.contacts.len() as u64 * sb,
        ]
    }
}

/// Every island of every scene (validated; errors name the scene) with its
/// frictional problem assembled on the GPU of `ctx`, in
/// [`crate::friction::assembly::friction_islands`]' order. Scenes are
/// batched under the binding limits of `gpu`; a scene too large for one
/// buffer on its own is an [`Error::Unsupported`] (assemble it on the CPU).
pub fn assemble_friction_on_gpu(
    ctx: &GpuContext,
    scenes: &[Scene],
    gpu: &GpuSettings,
) -> Result<Vec<Vec<FrictionIsland>>, Error> {
    for (i, s) in scenes.iter().enumerate() {
        s.validate(format_args!("scene {i}"))?;
    }
    let refs: Vec<&Scene> = scenes.iter().collect();
    let islands: Vec<Vec<Island>> = scenes.iter().map(find_islands).collect();
    let islands: Vec<&[Island]> = islands.iter().map(Vec::as_slice).collect();
    assemble_built_friction_on_gpu(ctx, &refs, &islands, gpu)
}

/// [`assemble_friction_on_gpu`] for checked scenes and their islands
/// (`islands[s]`: scene s's, as built), checked by nobody again.
pub(crate) fn assemble_built_friction_on_gpu(
    ctx: &GpuContext,
    scenes: &[&Scene],
    islands: &[&[Island]],
    gpu: &GpuSettings,
) -> Result<Vec<Vec<FrictionIsland>>, Error> {
    let limits = GpuSolveSettings {
        max_binding_bytes: gpu.max_binding_bytes,
        max_workgroups: gpu.max_workgroups,
        ..GpuSolveSettings::default()
    };
    let (max_bytes, max_groups) = limits_for(ctx, &limits);
    let sb = ctx.precision().bytes();
    let mut out: Vec<Vec<FrictionIsland>> = vec![Vec::new(); scenes.len()];
    let mut chunk = Packed::default();
    for (s, scene) in scenes.iter().enumerate() {
        let mut alone = Packed::default();
        alone.add(s, scene, islands[s]);
        let own = alone.bytes(sb);
        if own.iter().any(|&b| b > max_bytes) {
            return Err(Error::Unsupported(format!(
                "scene {s} is too large for one GPU buffer: assemble it on the CPU"
            )));
        }
        let now = chunk.bytes(sb);
        if now.iter().zip(&own).any(|(a, b)| a + b > max_bytes) {
            run_chunk(ctx, &chunk, max_groups, &mut out)?;
            chunk = Packed::default();
        }
        chunk.add(s, scene, islands[s]);
    }
    if !chunk.table.is_empty() {
        run_chunk(ctx, &chunk, max_groups, &mut out)?;
    }
    Ok(out)
}

/// Runs `assemble_contacts` and `assemble_islands` on one chunk and puts
/// each island's problem into `out`.
fn run_chunk(
    ctx: &GpuContext,
    c: &Packed,
    max_groups: u32,
    out: &mut [Vec<FrictionIsland>],
) -> Result<(), Error> {
    let p = ctx.pipelines()?;
    let precision = ctx.precision();
    let values = ctx.scoped("friction assembly", || -> Result<Vec<f64>, Error> {
        let bodies = ctx.storage("bodies", &scalars_to_bytes(&c.bodies, precision));
        let ids = ctx.storage("contact_bodies", bytemuck::cast_slice(&c.ids));
        let contacts = ctx.storage("contacts", &scalars_to_bytes(&c.contacts, precision));
        let rows = ctx.storage_zeroed("rows", (c.ids.len() * ROW) as u64 * precision.bytes());
        let islands = ctx.storage("islands", bytemuck::cast_slice(&c.table));
        let slots = ctx.storage("slots", bytemuck::cast_slice(&c.slots));
        let values_size = c.values_len as u64 * precision.bytes();
        let values = ctx.storage_zeroed("values", values_size);
        let mut encoder = ctx.encoder("friction assembly");
        let n_contacts = c.ids.len() as u32;
        let st = &p.assemble_contacts;
        ctx.dispatch(
            &mut encoder,
            st,
            n_contacts,
            max_groups,
            &[&bodies, &ids, &contacts, &rows],
        );
        let st = &p.assemble_islands;
        let island_buffers = [&ids, &rows, &islands, &slots, &values];
        ctx.dispatch(
            &mut encoder,
            st,
            c.slots.len() as u32,
            max_groups,
            &island_buffers,
        );
        let read = ctx.submit_and_read(encoder, &[(&values, values_size)])?;
        Ok(scalars_from_bytes(&read[0], precision))
    })??;
    for (rec, (s, contacts, mu)) in c.table.iter().zip(&c.keys) {
        let (n, at) = (rec.n as usize, rec.data as usize);
        let (w, q) = values
            .get(at..at + n * n + n)
            .ok_or_else(|| Error::Gpu("friction assembly: short read".into()))?
            .split_at(n * n);
        out[*s].push(FrictionIsland {
            contacts: contacts.clone(),
            problem: FrictionProblem {
                w: w.to_vec(),
                q: q.to_vec(),
                mu: mu.clone(),
            },
        });
    }
    Ok(())
}
