//! Pass 2 of a world step ([`Solver::step_worlds`]) for one world with
//! friction on the CPU ([`Solver::step_frictional_world_on_cpu`]): its
//! frictional islands found, assembled and solved inside the pass, world by
//! world on the thread that steps it, warm-started from that world's own
//! memory of the last step ([`FrictionMemory`]). The door's friction path
//! ([`super::friction_path`]) did the same work for the whole batch between
//! the passes, with a serial warm-start lookup and record in one map shared
//! by every world; here nothing of a world's solve waits for another
//! world, and a world's bits do not depend on the batch around it or on the
//! thread count.

use std::cell::RefCell;
use std::time::Instant;

use super::friction_path::contact_impulse;
use super::world_cpu::figures;
use super::world_path::Solved as Results;
use super::world_path::{max_error, Item, Stepped};
use super::world_repair::{reapply, repair_island, Repairs};
use super::Solver;
use crate::build::FrictionBuilt;
use crate::cpu::assembly::{assemble_contacts, assemble_island};
use crate::cpu::impulses::BodyVelocity;
use crate::friction::assembly::{apply_friction_impulses, assemble_friction_island_into};
use crate::friction::{solve_friction_problem, FrictionProblem};
use crate::islands::Island;
use crate::report::{FrictionIslandReport, SceneFriction, SceneReport};
use crate::scene::Scene;
use crate::settings::Settings;
use crate::world::step::finish;

/// One world's frictional reactions of its last step, per contact id,
/// sorted by id: replaced every step, so that only the ids seen in the
/// last step are kept (a contact that went away is forgotten).
#[derive(Clone, Debug, Default)]
pub(super) struct FrictionMemory {
    reactions: Vec<(u64, [f64; 3])>,
}

impl FrictionMemory {
    /// The warm start of an island with these contact ids (None for a
    /// contact without id): the remembered reaction, zero for a contact not
    /// remembered; None when none of them is remembered.
    pub(super) fn start(&self, ids: impl Iterator<Item = Option<u64>>) -> Option<Vec<f64>> {
        let mut any = false;
        let mut r = Vec::new();
        for id in ids {
            let found = id.and_then(|id| {
                self.reactions
                    .binary_search_by_key(&id, |e| e.0)
                    .ok()
                    .map(|k| self.reactions[k].1)
            });
            any |= found.is_some();
            r.extend_from_slice(&found.unwrap_or([0.0; 3]));
        }
        any.then_some(r)
    }

    /// Replaces the memory with the reactions of this step's solved
    /// islands (`scene`'s contacts carry the ids).
    pub(super) fn record(&mut self, scene: &Scene, islands: &[FrictionIslandReport]) {
        self.reactions.clear();
        for isl in islands.iter().filter(|i| i.status().is_solution()) {
            let r = &isl.solution.r;
            for (i, &c) in isl.contacts.iter().enumerate() {
                if let Some(id) = scene.contacts[c].id {
                    self.reactions
                        .push((id, [r[3 * i], r[3 * i + 1], r[3 * i + 2]]));
                }
            }
        }
        self.reactions.sort_unstable_by_key(|e| e.0);
    }

    /// How many contacts are remembered.
    #[cfg(test)]
    pub(super) fn len(&self) -> usize {
        self.reactions.len()
    }
}

impl Solver {
    /// Pass 2 for a world with friction on the CPU: islands, the frictional
    /// assembly, warm starts from its own memory, the Coulomb solves (each
    /// island to `settings.friction_tolerance`, as the door's friction path
    /// solves it), repairs of unsolved islands, impulses, integration.
    /// `index`: the world's place in the batch; `fix`: the repair settings.
    pub(super) fn step_frictional_world_on_cpu(
        &self,
        index: usize,
        item: &mut Item,
        dt: f64,
        fix: &Settings,
    ) -> Stepped {
        let t0 = Instant::now();
        let scene = &item.prepared.scene;
        let FrictionBuilt { islands, rows } = FrictionBuilt::new(scene);
        let warm = self.settings.warm_start;
        let starts: Vec<Option<Vec<f64>>> = islands
            .iter()
            .map(|isl| {
                let ids = isl.contacts.iter().map(|&c| scene.contacts[c].id);
                warm.then(|| item.warm.friction.start(ids)).flatten()
            })
            .collect();
        let settings = self.settings.friction();
        let mut r = vec![[0.0; 3]; scene.contacts.len()];
        let mut u = vec![[0.0; 3]; scene.contacts.len()];
        let mut reports = Vec::with_capacity(islands.len());
        // Each island assembled into this thread's problem just before its
        // solve (W allocated once per thread; its seconds go to the build).
        let mut assembly = std::time::Duration::ZERO;
        let t1 = Instant::now();
        for (island, start) in islands.into_iter().zip(&starts) {
            let ta = Instant::now();
            let solution = with_problem(|problem| {
                assemble_friction_island_into(scene, &rows, &island, problem);
                assembly += ta.elapsed();
                solve_friction_problem(problem, start.as_deref(), &settings)
            });
            for (i, &c) in island.contacts.iter().enumerate() {
                r[c].copy_from_slice(&solution.r[3 * i..3 * i + 3]);
                u[c].copy_from_slice(&solution.u[3 * i..3 * i + 3]);
            }
            reports.push(FrictionIslandReport {
                scene: Some(index),
                contacts: island.contacts,
                warm_started: start.is_some(),
                solution,
            });
        }
        let t2 = Instant::now();
        let mut bodies = apply_friction_impulses(scene, &rows, &r);
        let contacts = rows
            .iter()
            .zip(r.iter().zip(&u))
            .map(|(row, (&ri, &ui))| contact_impulse(row, ri, ui))
            .collect();
        let unsolved = reports
            .iter()
            .filter(|i| !i.status().is_solution())
            .map(|i| i.contacts.as_slice());
        let repairs = repair_unsolved(scene, unsolved, &mut bodies, fix);
        if warm {
            item.warm.friction.record(scene, &reports);
        }
        let t3 = Instant::now();
        finish(item.world, &item.prepared, &bodies, dt);
        let error = max_error(std::iter::empty(), reports.iter());
        let world = figures(
            item.world,
            &item.prepared,
            reports.len(),
            error,
            repairs.total(),
        );
        let t4 = Instant::now();
        Stepped {
            solved: Results::Own(SceneReport {
                impulses: r.iter().map(|ri| ri[0]).collect(),
                bodies,
                islands: 0..0,
                friction: Some(SceneFriction {
                    contacts,
                    // Local to this world; the step's report shifts it.
                    islands: 0..reports.len(),
                }),
            }),
            islands: Vec::new(),
            friction: reports,
            world,
            times: [
                t1 - t0 + assembly,
                (t2 - t1).saturating_sub(assembly),
                t3 - t2,
                t4 - t3,
            ]
            .map(|d| d.as_secs_f64()),
            repairs,
        }
    }
}

thread_local! {
    /// This thread's island problem, reassembled island after island.
    static PROBLEM: RefCell<FrictionProblem> = const {
        RefCell::new(FrictionProblem {
            w: Vec::new(),
            q: Vec::new(),
            mu: Vec::new(),
        })
    };
}

/// Runs `f` with this thread's island problem (a fresh one where it is in
/// use already).
fn with_problem<T>(f: impl FnOnce(&mut FrictionProblem) -> T) -> T {
    let mut f = Some(f);
    let out = PROBLEM.with(|cell| {
        cell.try_borrow_mut()
            .ok()
            .map(|mut p| (f.take().expect("called once"))(&mut p))
    });
    match out {
        Some(v) => v,
        None => (f.take().expect("not called yet"))(&mut FrictionProblem {
            w: Vec::new(),
            q: Vec::new(),
            mu: Vec::new(),
        }),
    }
}

/// Repairs every unsolved island of `scene` (its contacts), as
/// `world_repair` says: the island's bodies get their velocities before the
/// impulses plus the repair's normal impulses, in `bodies`. Returns what
/// the islands got.
pub(super) fn repair_unsolved<'a>(
    scene: &Scene,
    unsolved: impl Iterator<Item = &'a [usize]>,
    bodies: &mut [BodyVelocity],
    fix: &Settings,
) -> Repairs {
    let mut repairs = Repairs::default();
    let mut rows = None;
    for contacts in unsolved {
        let rows = rows.get_or_insert_with(|| assemble_contacts(scene));
        let island = Island {
            contacts: contacts.to_vec(),
        };
        let (r, z) = repair_island(&assemble_island(scene, rows, &island), fix);
        repairs.add(r);
        reapply(scene, rows, contacts, &z, bodies);
    }
    repairs
}

#[cfg(test)]
mod tests {
    use super::*;

    fn island(contacts: &[usize], r: Vec<f64>) -> FrictionIslandReport {
        use crate::friction::{FrictionMethod, FrictionSolution};
        use crate::lcp::Status;
        FrictionIslandReport {
            scene: Some(0),
            contacts: contacts.to_vec(),
            warm_started: false,
            solution: FrictionSolution {
                status: Status::Solved,
                u: vec![0.0; r.len()],
                r,
                residuals: Default::default(),
                iterations: 0,
                method: FrictionMethod::Auto,
            },
        }
    }

    fn scene_with_ids(ids: &[u64]) -> Scene {
        use crate::scene::{Body, Contact};
        let mut contact = Contact::new(0, None, [0.0; 3], [0.0, 1.0, 0.0], 0.0);
        let contacts = ids
            .iter()
            .map(|&id| {
                contact.id = Some(id);
                contact.clone()
            })
            .collect();
        Scene {
            bodies: vec![Body::new(1.0, [1.0; 3], [0.0; 3])],
            contacts,
        }
    }

    #[test]
    fn the_memory_keeps_only_the_last_steps_contacts() {
        let mut memory = FrictionMemory::default();
        let first = scene_with_ids(&[7, 3]);
        memory.record(
            &first,
            &[island(&[0, 1], vec![1.0, 0.1, 0.2, 2.0, 0.3, 0.4])],
        );
        assert_eq!(memory.len(), 2);
        assert_eq!(
            memory.start([Some(3), None, Some(9)].into_iter()),
            Some(vec![2.0, 0.3, 0.4, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0])
        );
        // Contact 7 went away, 5 is new: 7 is forgotten, the memory does
        // not grow with every id ever seen.
        let second = scene_with_ids(&[3, 5]);
        memory.record(
            &second,
            &[island(&[0, 1], vec![4.0, 0.0, 0.0, 5.0, 0.0, 0.0])],
        );
        assert_eq!(memory.len(), 2);
        assert_eq!(memory.start([Some(7)].into_iter()), None);
        assert_eq!(
            memory.start([Some(5), Some(3)].into_iter()),
            Some(vec![5.0, 0.0, 0.0, 4.0, 0.0, 0.0])
        );
    }
}
