//! Pass 2 of a world step ([`Solver::step_worlds`](super::Solver::step_worlds))
//! for one world: a frictionless world is solved here on the CPU
//! ([`step_world_on_cpu`]), a world of the batch solved by
//! [`Solver::solve_built_scenes`](super::Solver::solve_built_scenes) gets
//! its repairs ([`finish_batch_world`]); then its velocities, poses and
//! figures. Also the pass's parallel loop over the worlds
//! ([`parallel_map_mut`]). Each world is warm-started from its own memory
//! ([`crate::warm::Warm`], one shard).

use std::time::Instant;

use super::cpu_path::{check, solve_on_cpu, Solved};
use super::ids_of;
use super::world_friction::repair_unsolved;
use super::world_path::{max_error, SceneResults, Stepped, WorldStep, WorldStepReport};
use super::world_repair::{repair_island, Repairs};
use crate::build::Built;
use crate::cpu::batch::parallel_fill_by;
use crate::cpu::enumeration::{solve_basis, BasisOutcome, MAX_ENUMERATION_N};
use crate::cpu::impulses::{apply_impulses, BodyVelocity};
use crate::lcp::{Counters, Lcp, LcpSolution, Status};
use crate::report::{IslandReport, Report, SceneReport, SolvePath};
use crate::scene::Scene;
use crate::settings::{Method, Settings};
use crate::warm::basis_entries;
use crate::world::step::finish;

/// Worlds handed to a thread at a time: few, so that the threads end a
/// pass together (a 4-box stack's step with friction is about 25 µs).
const CHUNK: usize = 4;

/// `f(i, &mut items[i])` for every item on up to `threads` threads (0 or 1:
/// on this one), results in order, [`CHUNK`] items at a time.
pub(super) fn parallel_map_mut<T: Send, R: Send>(
    items: &mut [T],
    threads: usize,
    f: impl Fn(usize, &mut T) -> R + Sync,
) -> Vec<R> {
    let mut slots: Vec<(&mut T, Option<R>)> = items.iter_mut().map(|t| (t, None)).collect();
    parallel_fill_by(&mut slots, threads, CHUNK, |i, (t, r)| *r = Some(f(i, t)));
    slots
        .into_iter()
        .map(|(_, r)| r.expect("every item was stepped"))
        .collect()
}

/// Pass 2 for a frictionless world on the CPU: islands (once), assembly,
/// warm hints from its own memory, `solve_scenes`' per-island solve and
/// check, repairs, impulses, integration. `fix`: the repair settings.
pub(super) fn step_world_on_cpu(
    settings: &Settings,
    index: usize,
    item: &mut WorldStep,
    dt: f64,
    fix: &Settings,
) -> Stepped {
    let t0 = Instant::now();
    let scene = &item.prepared.scene;
    let Built {
        islands,
        rows,
        lcps,
    } = Built::new(scene);
    let warm = settings.warm_start;
    let hints: Vec<Option<u32>> = islands
        .iter()
        .map(|isl| {
            let memory = &item.warm.bases;
            warm.then(|| memory.basis(ids_of(scene, &isl.contacts)))
                .flatten()
        })
        .collect();
    let t1 = Instant::now();
    let mut reports: Vec<IslandReport> = islands
        .into_iter()
        .zip(lcps.iter().zip(&hints))
        .map(|(isl, (lcp, &hint))| {
            let (method, path, solution) = hint
                .and_then(|h| warm_settle(lcp, h, settings))
                .unwrap_or_else(|| solve_on_cpu(lcp, None, settings));
            IslandReport {
                scene: Some(index),
                contacts: isl.contacts.into(),
                method,
                path,
                solution,
            }
        })
        .collect();
    check(&mut reports, settings.tolerance);
    let t2 = Instant::now();
    let mut impulses = vec![0.0; scene.contacts.len()];
    let mut repairs = Repairs::default();
    for (isl, lcp) in reports.iter().zip(&lcps) {
        let repaired;
        let z = if isl.status().is_solution() {
            &isl.solution.z[..]
        } else {
            let (r, z) = repair_island(lcp, fix);
            repairs.add(r);
            repaired = z;
            &repaired[..]
        };
        for (&c, &zi) in isl.contacts.iter().zip(z) {
            impulses[c] = zi;
        }
    }
    let bodies = apply_impulses(scene, &rows, &impulses);
    if warm {
        let solved = reports.iter().filter(|i| i.status().is_solution());
        let with_basis =
            solved.filter_map(|i| Some((ids_of(scene, &i.contacts), i.solution.basis?)));
        let entries = with_basis.flat_map(|(ids, basis)| basis_entries(ids, basis));
        item.warm.bases.record(entries);
    }
    let t3 = Instant::now();
    let error = max_error(reports.iter(), std::iter::empty());
    let world = finish_world(item, &bodies, dt, reports.len(), error, repairs.total());
    let t4 = Instant::now();
    Stepped {
        solved: SceneResults::Own(SceneReport {
            impulses,
            bodies,
            islands: 0..0,
            friction: None,
        }),
        islands: reports,
        friction: Vec::new(),
        world,
        times: [t1 - t0, t2 - t1, t3 - t2, t4 - t3].map(|d| d.as_secs_f64()),
        repairs,
    }
}

/// Pass 2 for a world of the batch solved in one call (`batch`:
/// its scene, its index in the batch, the batch's report): repairs of
/// its unsolved islands (LCP or frictional), integration.
pub(super) fn finish_batch_world(
    item: &mut WorldStep,
    batch: (&Scene, usize, &Report),
    dt: f64,
    fix: &Settings,
) -> Stepped {
    let (scene, j, report) = batch;
    let t0 = Instant::now();
    let d = &report.scenes[j];
    let lcp = &report.islands[d.islands.clone()];
    let friction = d.friction.as_ref().map_or(&report.friction[0..0], |f| {
        &report.friction[f.islands.clone()]
    });
    let unsolved: Vec<&[usize]> = lcp
        .iter()
        .filter(|i| !i.status().is_solution())
        .map(|i| i.contacts.as_slice())
        .chain(
            friction
                .iter()
                .filter(|i| !i.status().is_solution())
                .map(|i| i.contacts.as_slice()),
        )
        .collect();
    let mut bodies: Option<Vec<BodyVelocity>> = None;
    let mut repairs = Repairs::default();
    if !unsolved.is_empty() {
        let mut after = d.bodies.clone();
        repairs = repair_unsolved(scene, unsolved.into_iter(), &mut after, fix);
        bodies = Some(after);
    }
    let t1 = Instant::now();
    let after = bodies.as_deref().unwrap_or(&d.bodies);
    let error = max_error(lcp.iter(), friction.iter());
    let islands = lcp.len() + friction.len();
    let world = finish_world(item, after, dt, islands, error, repairs.total());
    Stepped {
        islands: Vec::new(),
        friction: Vec::new(),
        solved: SceneResults::InBatch(bodies),
        world,
        times: [
            0.0,
            0.0,
            (t1 - t0).as_secs_f64(),
            t1.elapsed().as_secs_f64(),
        ],
        repairs,
    }
}

/// Block principal pivots tried from a warm basis before giving up on it.
const WARM_PIVOTS: u64 = 3;

/// The world path's warm start: last step's basis `hint`, and when its
/// solution is not feasible (to the strict `feasibility_tol`), up to
/// [`WARM_PIVOTS`] block principal pivots from it (Kostreva 1978; Júdice
/// and Pires 1994): the basic contacts whose impulse came out negative
/// leave the basis, the others that would penetrate (w < 0) enter. A
/// resting stack's basis is degenerate (4 coplanar contacts per face, rank
/// 3: a contact that carries no load sits at z = 0 or w = 0), and rounding
/// moves that zero across from step to step; `solve_scenes`' warm start
/// then sends the island to Lemke, while one pivot finds the neighbouring
/// basis. Every answer is an exact basis solution, feasible to the strict
/// tolerance and within `tolerance` (the final check
/// again). None: the island is solved as usual, without the hint. Only for
/// Auto and Enumeration with `predict`, n ≤ 20.
fn warm_settle(lcp: &Lcp, hint: u32, s: &Settings) -> Option<Solved> {
    let n = lcp.n();
    let enumerates = matches!(s.method, Method::Auto | Method::Enumeration);
    if !enumerates || !s.predict || s.all_solutions || n > MAX_ENUMERATION_N || hint >> n != 0 {
        return None;
    }
    let e = s.enumeration();
    let mut mask = hint;
    for round in 0..=WARM_PIVOTS {
        let BasisOutcome::Solved { z, w, feasible, .. } = solve_basis(lcp, mask, &e) else {
            return None;
        };
        if feasible {
            let counters = Counters {
                bases_visited: round + 1,
                ..Counters::default()
            };
            let mut solution = LcpSolution::from_z(lcp, Status::Solved, z, counters);
            let finite = solution.z.iter().chain(&solution.w).all(|v| v.is_finite());
            if !(finite && solution.residuals.error <= s.tolerance) {
                return None;
            }
            solution.basis = Some(mask);
            return Some((Method::Enumeration, SolvePath::WarmStart, solution));
        }
        // z comes back clamped at 0: a basic contact at 0 had a negative one.
        let basic = |i: usize| mask >> i & 1 == 1;
        let leave = (0..n).filter(|&i| basic(i) && z[i] <= 0.0);
        let enter = (0..n).filter(|&j| !basic(j) && w[j] < 0.0);
        let next = leave.fold(mask, |m, i| m & !(1 << i)) | enter.fold(0, |m, j| m | 1 << j);
        if next == mask {
            return None;
        }
        mask = next;
    }
    None
}

/// Integration (the world's velocities after the impulses, `bodies`; its
/// poses) and its figures after the step.
pub(super) fn finish_world(
    item: &mut WorldStep,
    bodies: &[BodyVelocity],
    dt: f64,
    islands: usize,
    max_error: f64,
    unsolved: usize,
) -> WorldStepReport {
    finish(item.world, &item.prepared, bodies, dt);
    let (w, p) = (&*item.world, &item.prepared);
    WorldStepReport {
        kinetic: w.kinetic_energy(),
        potential: w.potential_energy(),
        max_penetration: p.contacts.iter().map(|c| -c.gap).fold(0.0, f64::max),
        contacts: p.contacts.len(),
        islands,
        max_error,
        awake: w.bodies.iter().filter(|b| !b.fixed && !b.asleep).count(),
        unsolved,
        impacts: p.impacts.count,
        impacts_deferred: p.impacts.deferred,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_parallel_loop_gives_every_result_in_order_and_mutates_each_item_once() {
        for threads in [0, 1, 2, 3] {
            let mut items: Vec<usize> = (0..1000).collect();
            let out = parallel_map_mut(&mut items, threads, |i, x| {
                *x += 1;
                i * 2
            });
            assert_eq!(out, (0..1000).map(|i| i * 2).collect::<Vec<_>>());
            assert_eq!(items, (1..1001).collect::<Vec<_>>());
        }
    }
}
