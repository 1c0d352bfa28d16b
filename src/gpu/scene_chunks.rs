//! Scenes built on the CPU ([`Built`]) and packed into chunks under the device's
//! binding limit: what `scenes.rs` uploads.

use super::kernel::TreeRoute;
use super::layout::{
    pack_body, pack_contact, BasisResult, ContactBodies, PackedIsland, Slot, BODY, ROW, VELOCITY,
};
use super::MAX_GPU_N;
use crate::build::Built;
use crate::scene::Scene;

/// The packed buffers of a chunk of scenes.
#[derive(Default)]
pub(super) struct Chunk {
    pub(super) scenes: Vec<usize>,
    pub(super) first_body: Vec<u32>,
    pub(super) first_contact: Vec<u32>,
    pub(super) bodies: Vec<f64>,
    pub(super) ids: Vec<ContactBodies>,
    pub(super) contacts: Vec<f64>,
    /// Islands with n ≤ 16, sorted by n.
    pub(super) table: Vec<PackedIsland>,
    /// (scene, island) of every table entry.
    pub(super) keys: Vec<(usize, usize)>,
    /// The entries of `table` that enumeration runs on (prediction settled
    /// the others on the CPU), and their (scene, island).
    pub(super) enum_table: Vec<PackedIsland>,
    pub(super) enum_keys: Vec<(usize, usize)>,
    /// Per `enum_table` entry: how it goes through the tree kernel.
    pub(super) enum_tree: Vec<TreeRoute>,
    pub(super) slots: Vec<Slot>,
    pub(super) values_len: u32,
    pub(super) z_len: u32,
}

/// Bytes of the largest buffer a scene needs (see [`Chunk`]).
pub(super) fn scene_bytes(scene: &Scene, p: &Built, sb: u64) -> [u64; 5] {
    let nb = scene.bodies.len() as u64;
    let nc = scene.contacts.len() as u64;
    let small = p.islands.iter().filter(|i| i.len() <= MAX_GPU_N);
    let values: u64 = small
        .clone()
        .map(|i| (i.len() * i.len() + i.len()) as u64)
        .sum();
    [
        nb * BODY as u64 * sb,
        nc * ROW as u64 * sb,
        values * sb,
        // slots (8 bytes each), contact bodies (16 bytes each); results
        // (32 bytes per island ≤ contacts).
        nc * std::mem::size_of::<BasisResult>() as u64,
        nb * VELOCITY as u64 * sb,
    ]
}

/// Packs a chunk; `settled(s, k)`: island k of scene s needs no
/// enumeration; `tree(s, k)`: it runs the tree kernel first (the table is
/// sorted by n, then by this).
pub(super) fn pack_chunk(
    scenes: &[&Scene],
    prepared: &[Built],
    members: &[usize],
    settled: &dyn Fn(usize, usize) -> bool,
    tree: &dyn Fn(usize, usize) -> TreeRoute,
) -> Chunk {
    let mut c = Chunk::default();
    let mut entries: Vec<(usize, usize, usize)> = Vec::new(); // (n, position in chunk, island)
    for &s in members {
        let scene = scenes[s];
        let fb = (c.bodies.len() / BODY) as u32;
        let fc = c.ids.len() as u32;
        c.scenes.push(s);
        c.first_body.push(fb);
        c.first_contact.push(fc);
        for b in &scene.bodies {
            pack_body(b, &mut c.bodies);
        }
        for ct in &scene.contacts {
            pack_contact(ct, &scene.bodies, fb, &mut c.ids, &mut c.contacts);
        }
        let pos = c.scenes.len() - 1;
        for (k, isl) in prepared[s].islands.iter().enumerate() {
            if isl.len() <= MAX_GPU_N {
                entries.push((isl.len(), pos, k));
            }
        }
    }
    entries.sort_by_key(|&(n, pos, k)| (n, tree(c.scenes[pos], k)));
    for (n, pos, k) in entries {
        let s = c.scenes[pos];
        let fc = c.first_contact[pos];
        c.table.push(PackedIsland {
            n: n as u32,
            data: c.values_len,
            z: c.z_len,
            contacts: c.slots.len() as u32,
        });
        let island_index = (c.table.len() - 1) as u32;
        for &ct in &prepared[s].islands[k].contacts {
            c.slots.push(Slot {
                island: island_index,
                contact: fc + ct as u32,
            });
        }
        c.keys.push((s, k));
        if !settled(s, k) {
            c.enum_table.push(c.table[island_index as usize]);
            c.enum_keys.push((s, k));
            c.enum_tree.push(tree(s, k));
        }
        c.values_len += (n * n + n) as u32;
        c.z_len += n as u32;
    }
    c
}

/// Splits the scenes into chunks under the binding limit; scenes too large
/// for one chunk on their own are returned apart.
pub(super) fn plan(
    scenes: &[&Scene],
    prepared: &[Built],
    max_bytes: u64,
    sb: u64,
) -> (Vec<Vec<usize>>, Vec<usize>) {
    let mut chunks = Vec::new();
    let mut alone = Vec::new();
    let mut cur: Vec<usize> = Vec::new();
    let mut acc = [0u64; 5];
    for (s, (scene, p)) in scenes.iter().zip(prepared).enumerate() {
        let b = scene_bytes(scene, p, sb);
        if b.iter().any(|&x| x > max_bytes) {
            alone.push(s);
            continue;
        }
        if acc.iter().zip(&b).any(|(a, x)| a + x > max_bytes) && !cur.is_empty() {
            chunks.push(std::mem::take(&mut cur));
            acc = [0; 5];
        }
        for (a, x) in acc.iter_mut().zip(&b) {
            *a += x;
        }
        cur.push(s);
    }
    if !cur.is_empty() {
        chunks.push(cur);
    }
    (chunks, alone)
}
