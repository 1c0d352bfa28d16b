//! The narrow phase on the GPU (`shaders/collide.wgsl`, entry point
//! `collide_pairs`): the host side of its test and bench door. Packs bodies
//! and candidate pairs, dispatches one invocation per pair, reads the
//! contacts back as [`ContactPoint`]s, those of the CPU twins
//! ([`crate::world::collide`]'s `collide_shapes` with `world_contacts`'
//! ordering of a pair: the dynamic body is a).
//!
//! The shader's functions take values only (no bindings): the resident
//! world step (`shaders/world_step.wgsl`, `src/gpu/resident/`) calls them
//! from its own kernel with its own body state, whose shape record is
//! [`shape_record`]'s.
//!
//! # Layouts (keep in sync with `shaders/collide.wgsl`)
//! - body, [`BODY`] scalars: position (3), orientation quaternion
//!   `[x, y, z, w]` (4, as stored: the shader normalises it as
//!   [`RigidBody::rotation`] does), shape kind (0 sphere, 1 box, 2 plane),
//!   shape parameters (3: radius, 0, 0 | half extents | plane normal),
//!   static flag (1: static);
//! - pair: its two body indices (`vec2<u32>`) and its margin (a scalar);
//! - out, per pair [`SLOTS`] contact slots of [`POINT`] scalars (point,
//!   normal, gap, pad) and keys (`vec4<u32>`: a, b, feature, 0), and one
//!   count word: the manifold's points, bit 31 ([`OVERFLOW`]) set where
//!   they did not fit. Every pair type gives at most 4 points (manifolds
//!   are reduced to four), so the bound is never reached by the CPU twins'
//!   algorithms; a pair that would exceed it is flagged, never cut silently.

// Besides `shape_record`, this door serves the tests (src/tests/gpu_collide.rs)
// only: the resident step runs the WGSL functions from its own kernel.
#![cfg_attr(
    not(test),
    allow(
        dead_code,
        reason = "the narrow phase's test door; the resident step calls the WGSL itself"
    )
)]

use super::buffers::limits_for;
use super::layout::{scalars_from_bytes, scalars_to_bytes};
use super::{GpuContext, GpuSolveSettings};
use crate::settings::GpuSettings;
use crate::world::collide::ContactPoint;
use crate::world::{RigidBody, Shape};
use crate::Error;
use glam::DVec3;

/// Scalars per packed body.
pub const BODY: usize = 12;
/// Contact slots per pair: the most points any pair type gives.
pub const SLOTS: usize = 4;
/// Scalars per contact slot (point, normal, gap, pad).
pub const POINT: usize = 8;
/// Set in a pair's count word where its manifold did not fit its slots.
pub const OVERFLOW: u32 = 1 << 31;

/// A shape as the shaders read it: its kind (0 sphere, 1 box, 2 plane) and
/// parameters (radius, 0, 0 | half extents | plane normal).
pub fn shape_record(shape: &Shape) -> (f64, [f64; 3]) {
    match *shape {
        Shape::Sphere { radius } => (0.0, [radius, 0.0, 0.0]),
        Shape::Box { half_extents } => (1.0, half_extents),
        Shape::Plane { normal } => (2.0, normal),
    }
}

/// Appends body `b`'s record (see the module docs) to `out`.
pub fn pack_collide_body(b: &RigidBody, out: &mut Vec<f64>) {
    let (kind, size) = shape_record(&b.shape);
    out.extend_from_slice(&b.position);
    out.extend_from_slice(&b.orientation);
    out.push(kind);
    out.extend_from_slice(&size);
    out.push(if b.fixed { 1.0 } else { 0.0 });
}

/// The contacts the GPU found for one pair.
#[derive(Clone, Debug, PartialEq)]
pub struct PairContacts {
    /// Its points in the twin's order, at most [`SLOTS`]; body indices are
    /// indices into the bodies given.
    pub contacts: Vec<ContactPoint>,
    /// The manifold did not fit (see [`OVERFLOW`]): `contacts` holds the
    /// first [`SLOTS`] only.
    pub overflow: bool,
}

/// The narrow phase of `pairs` (indices into `bodies`) with per-pair
/// `margins` on the GPU of `ctx`, in pair order. Pairs go in chunks under
/// the binding limits of `gpu` (`max_binding_bytes`, `max_workgroups`).
///
/// # Errors
/// [`Error::Invalid`] naming the pair for an index out of range, a pair of
/// one body or of two static bodies, or a margin that is not finite;
/// [`Error::Unsupported`] where the bodies do not fit one binding;
/// [`Error::Gpu`] for device trouble.
pub fn collide_pairs_on_gpu(
    ctx: &GpuContext,
    bodies: &[RigidBody],
    pairs: &[(usize, usize)],
    margins: &[f64],
    gpu: &GpuSettings,
) -> Result<Vec<PairContacts>, Error> {
    if margins.len() != pairs.len() {
        return Err(Error::invalid(
            "narrow phase",
            "margins",
            format!("{} margins for {} pairs", margins.len(), pairs.len()),
        ));
    }
    for (k, (&(i, j), &m)) in pairs.iter().zip(margins).enumerate() {
        let item = format!("pair {k}");
        if i >= bodies.len() || j >= bodies.len() || bodies.len() > u32::MAX as usize {
            return Err(Error::invalid(
                item,
                "bodies",
                format!("({i}, {j}) with {} bodies", bodies.len()),
            ));
        }
        if i == j || (bodies[i].fixed && bodies[j].fixed) {
            return Err(Error::invalid(
                item,
                "bodies",
                format!("({i}, {j}) is one body or two static ones"),
            ));
        }
        if !m.is_finite() {
            return Err(Error::invalid(item, "margin", format!("{m} is not finite")));
        }
    }
    let limits = GpuSolveSettings {
        max_binding_bytes: gpu.max_binding_bytes,
        max_workgroups: gpu.max_workgroups,
        ..GpuSolveSettings::default()
    };
    let (max_bytes, max_groups) = limits_for(ctx, &limits);
    let precision = ctx.precision();
    let sb = precision.bytes();
    let mut packed = Vec::with_capacity(bodies.len() * BODY);
    for b in bodies {
        pack_collide_body(b, &mut packed);
    }
    if packed.len() as u64 * sb > max_bytes {
        return Err(Error::Unsupported(format!(
            "{} bodies do not fit one GPU binding: collide them on the CPU",
            bodies.len()
        )));
    }
    let stage = ctx.pipelines()?;
    let stage = stage.collide(ctx)?;
    // The largest of a chunk's buffers is its points: SLOTS × POINT
    // scalars per pair.
    let per_chunk = (max_bytes / ((SLOTS * POINT) as u64 * sb)).max(1) as usize;
    let body_buffer = ctx.storage("bodies", &scalars_to_bytes(&packed, precision));
    let mut out = Vec::with_capacity(pairs.len());
    for (chunk, chunk_margins) in pairs.chunks(per_chunk).zip(margins.chunks(per_chunk)) {
        let n = chunk.len();
        let ij: Vec<[u32; 2]> = chunk.iter().map(|&(i, j)| [i as u32, j as u32]).collect();
        let (points, keys, counts) = ctx.scoped("narrow phase", || -> Result<_, Error> {
            let pair_buffer = ctx.storage("pairs", bytemuck::cast_slice(&ij));
            let margin_buffer = ctx.storage("margins", &scalars_to_bytes(chunk_margins, precision));
            let points_size = (n * SLOTS * POINT) as u64 * sb;
            let keys_size = (n * SLOTS * 16) as u64;
            let counts_size = (n * 4) as u64;
            let points = ctx.storage_zeroed("points", points_size);
            let keys = ctx.storage_zeroed("keys", keys_size);
            let counts = ctx.storage_zeroed("counts", counts_size);
            let mut encoder = ctx.encoder("narrow phase");
            let buffers = [
                &body_buffer,
                &pair_buffer,
                &margin_buffer,
                &points,
                &keys,
                &counts,
            ];
            ctx.dispatch(&mut encoder, stage, n as u32, max_groups, &buffers);
            let reads = [
                (&points, points_size),
                (&keys, keys_size),
                (&counts, counts_size),
            ];
            ctx.submit_and_map(encoder, &reads, |v| {
                (
                    scalars_from_bytes(v[0], precision),
                    bytemuck::pod_collect_to_vec::<u8, u32>(v[1]),
                    bytemuck::pod_collect_to_vec::<u8, u32>(v[2]),
                )
            })
        })??;
        for (p, &count) in counts.iter().enumerate() {
            let len = (count & !OVERFLOW) as usize;
            let contacts = (0..len.min(SLOTS))
                .map(|k| {
                    let slot = p * SLOTS + k;
                    let v = &points[slot * POINT..(slot + 1) * POINT];
                    let key = &keys[slot * 4..slot * 4 + 4];
                    ContactPoint {
                        a: key[0] as usize,
                        b: key[1] as usize,
                        point: DVec3::new(v[0], v[1], v[2]),
                        normal: DVec3::new(v[3], v[4], v[5]),
                        gap: v[6],
                        feature: key[2] as u16,
                    }
                })
                .collect();
            out.push(PairContacts {
                contacts,
                overflow: count & OVERFLOW != 0 || len > SLOTS,
            });
        }
    }
    Ok(out)
}
