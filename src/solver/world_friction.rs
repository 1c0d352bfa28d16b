//! Pass 2 of a world step ([`Solver::step_worlds`](super::Solver::step_worlds))
//! for one world with friction on the CPU ([`step_frictional_world_on_cpu`]): its
//! frictional islands found, assembled and solved inside the pass, world by
//! world on the thread that steps it, warm-started from that world's own
//! memory of the last steps ([`crate::warm::Warm`]). `solve_scenes`' friction path
//! ([`super::friction_path`]) did the same work for the whole batch between
//! the passes, with a serial warm-start lookup and record in one map shared
//! by every world; here nothing of a world's solve waits for another
//! world, and a world's bits do not depend on the batch around it or on the
//! thread count.

use std::cell::RefCell;
use std::time::Instant;

use super::friction_path::contact_impulse;
use super::ids_of;
use super::world_cpu::finish_world;
use super::world_path::{max_error, SceneResults, Stepped, WorldStep};
use super::world_repair::{reapply, repair_island, Repairs};
use crate::build::FrictionBuilt;
use crate::cpu::assembly::{assemble_contacts, assemble_island};
use crate::cpu::impulses::BodyVelocity;
use crate::friction::assembly::FrictionContactRows;
use crate::friction::assembly::{apply_friction_impulses, assemble_friction_island_into};
use crate::friction::solve::usable_start;
use crate::friction::{
    project_on_cone, solve_friction_problem, FrictionMethod, FrictionProblem, FrictionResiduals,
    FrictionSettings, FrictionSolution,
};
use crate::islands::Island;
use crate::lcp::Status;
use crate::report::{FrictionIslandReport, SceneFriction, SceneReport};
use crate::scene::Scene;
use crate::settings::Settings;
use crate::warm::reaction_entries;

/// Pass 2 for a world with friction on the CPU: islands, the frictional
/// assembly, warm starts from its own memory, the Coulomb solves (each
/// island to `settings.friction_tolerance`, as `solve_scenes`' friction path
/// solves it), repairs of unsolved islands, impulses, integration.
/// `index`: the world's place in the batch; `fix`: the repair settings.
pub(super) fn step_frictional_world_on_cpu(
    settings: &Settings,
    index: usize,
    item: &mut WorldStep,
    dt: f64,
    fix: &Settings,
) -> Stepped {
    let t0 = Instant::now();
    let scene = &item.prepared.scene;
    let FrictionBuilt { islands, rows } = FrictionBuilt::new(scene);
    let warm = settings.warm_start;
    let starts: Vec<Option<Vec<f64>>> = islands
        .iter()
        .map(|isl| {
            let ids = ids_of(scene, &isl.contacts);
            warm.then(|| item.warm.reactions.reactions(ids)).flatten()
        })
        .collect();
    let settling: Vec<bool> = islands
        .iter()
        .map(|isl| warm && item.warm.settling.any(ids_of(scene, &isl.contacts)))
        .collect();
    let friction = settings.friction();
    let mut r = vec![[0.0; 3]; scene.contacts.len()];
    let mut u = vec![[0.0; 3]; scene.contacts.len()];
    let mut reports = Vec::with_capacity(islands.len());
    // Each island assembled into this thread's problem just before its
    // solve (W allocated once per thread; its seconds go to the build).
    let mut assembly = std::time::Duration::ZERO;
    let t1 = Instant::now();
    let checked = checked_starts(scene, &rows, &islands, &starts, &friction);
    let mut settled = Vec::with_capacity(islands.len());
    for (((island, start), checked), settling) in
        islands.into_iter().zip(&starts).zip(checked).zip(settling)
    {
        let ta = Instant::now();
        let mut solve = |polish: Option<FrictionSolution>| {
            with_problem(|problem| {
                assemble_friction_island_into(scene, &rows, &island, problem);
                assembly += ta.elapsed();
                match polish {
                    Some(as_is) => polish_start(problem, as_is, &friction),
                    None => solve_friction_problem(problem, start.as_deref(), &friction),
                }
            })
        };
        let near = SETTLED * friction.tolerance;
        let small = island.contacts.len() < POLISH_BELOW;
        let (solution, off, polished) = match checked {
            Checked::Within(s, error) if !(settling && small) || error <= near => (s, error, false),
            Checked::Within(s, error) => (solve(Some(s)), error, true),
            Checked::Other(error) => (solve(None), error, false),
        };
        // A polish that fell short of `near` (Newton creeping, as on the
        // pyramid's edge contacts) is not tried again next step.
        let weak = polished && solution.residuals.coulomb_error > near;
        settled.push(off <= near || weak || !small);
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
        item.warm
            .reactions
            .record(solved_reactions(scene, &reports));
        let unsettled = reports.iter().zip(&settled).filter(|(_, &s)| !s);
        item.warm.settling.record(
            unsettled
                .flat_map(|(isl, _)| ids_of(scene, &isl.contacts).flatten().map(|id| (id, true))),
        );
    }
    let t3 = Instant::now();
    let error = max_error(std::iter::empty(), reports.iter());
    let world = finish_world(item, &bodies, dt, reports.len(), error, repairs.total());
    let t4 = Instant::now();
    Stepped {
        solved: SceneResults::Own(SceneReport {
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

/// Each island's start (its warm start, else zero: as
/// [`solve_friction_problem`] takes it) projected on its cones and judged
/// without W: the starts of every island applied to the bodies at once
/// (islands share no dynamic body), each row's u = J v⁺ + (q − v_rel) (=
/// W r + q), its Coulomb error. Some(the answer, 0 iterations) where that
/// is within the tolerance (a resting island's warm start, a separating
/// island's zero): its W is never assembled (a resting 4-box stack's 48 ×
/// 48 W was a fifth of its step). Every island is None for the projected
/// methods (judged by another residual).
///
/// Each island's start comes back as [`Checked`]: within the tolerance
/// (the answer, its error), or not (its error; infinite where not finite
/// or judged by another residual).
fn checked_starts(
    scene: &Scene,
    rows: &[FrictionContactRows],
    islands: &[Island],
    starts: &[Option<Vec<f64>>],
    s: &FrictionSettings,
) -> Vec<Checked> {
    if s.method.projected().is_some() {
        return (0..islands.len())
            .map(|_| Checked::Other(f64::INFINITY))
            .collect();
    }
    let mut r = vec![[0.0; 3]; scene.contacts.len()];
    for (island, start) in islands.iter().zip(starts) {
        let usable = |w: &&Vec<f64>| usable_start(w, 3 * island.len());
        if let Some(w) = start.as_ref().filter(usable) {
            for (i, &c) in island.contacts.iter().enumerate() {
                let wi = [w[3 * i], w[3 * i + 1], w[3 * i + 2]];
                r[c] = project_on_cone(wi, scene.contacts[c].friction);
            }
        }
    }
    let bodies = apply_friction_impulses(scene, rows, &r);
    let velocity = |k: usize| {
        bodies[k]
            .velocity
            .into_iter()
            .chain(bodies[k].angular_velocity)
    };
    islands
        .iter()
        .map(|island| {
            let contacts = &island.contacts;
            let (mut q, mut u) = (Vec::with_capacity(3 * contacts.len()), Vec::new());
            for &c in contacts {
                let con = &scene.contacts[c];
                for row in &rows[c].rows {
                    let mut jv: f64 = (row.jacobian[..6].iter().zip(velocity(con.a)))
                        .map(|(j, v)| j * v)
                        .sum();
                    if let Some(b) = con.b {
                        jv += (row.jacobian[6..].iter().zip(velocity(b)))
                            .map(|(j, v)| j * v)
                            .sum::<f64>();
                    }
                    u.push(jv + (row.q - row.v_rel));
                    q.push(row.q);
                }
            }
            let mu = contacts
                .iter()
                .map(|&c| scene.contacts[c].friction)
                .collect();
            let p = FrictionProblem {
                w: Vec::new(),
                q,
                mu,
            };
            let ri: Vec<f64> = contacts.iter().flat_map(|&c| r[c]).collect();
            let residuals = FrictionResiduals::of_velocity(&p, &ri, &u);
            let finite = ri.iter().chain(&u).all(|v| v.is_finite());
            let error = match finite {
                true => residuals.coulomb_error,
                false => f64::INFINITY,
            };
            if !(error <= s.tolerance) {
                return Checked::Other(error);
            }
            let solution = FrictionSolution {
                status: Status::Solved,
                r: ri,
                u,
                residuals,
                iterations: 0,
                method: s.method,
            };
            Checked::Within(solution, error)
        })
        .collect()
}

/// An island's start as [`checked_starts`] judged it through the bodies.
enum Checked {
    /// Within the tolerance: the answer as it is (0 iterations), its error.
    Within(FrictionSolution, f64),
    /// Not (its Coulomb error; infinite where not finite or not judged).
    Other(f64),
}

/// A world's island is settled where its warm start's Coulomb error is at
/// most this fraction of the tolerance; else the next step polishes its
/// start ([`polish_start`]) even where that is within the tolerance.
///
/// Why: a resting stack's start is last step's reactions, which also
/// cancelled last step's velocity. A start accepted as it is with an error
/// near the tolerance (a relative 1e-12 of reactions of ~100 N s) leaves the
/// bodies a velocity of ~1e-10 m/s; the next steps' solves remove the
/// penetration it makes (bias φ/Δt) and then cancel the velocity that
/// removed it, and the step after that finds last step's reactions off by
/// as much as the first start again: a cycle of three steps, two of them
/// Newton solves, at any tolerance (measured on `stack:4`: warm errors
/// 9.1e-13, 2.7e-12, 2.7e-12 for 1e-12; 8.9e-15, 2.7e-14, 2.7e-14 for
/// 1e-14). Polishing the step after an unsettled one leaves the bodies at
/// rest, so that the following steps' starts are within rounding.
pub(super) const SETTLED: f64 = 0.1;

/// How far below the tolerance [`polish_start`] aims: Newton from a
/// resting stack's start reaches 1e-17 in a step.
const POLISH_TARGET: f64 = 1e-3;

/// Newton steps [`polish_start`] takes at most.
const POLISH_STEPS: u64 = 2;

/// Islands of at least this many contacts are not polished: on them
/// Newton near a solution creeps (their edge and faint slides are taken as
/// sticking, `friction::newton::classify`): `stack:10`'s 40-contact island
/// went from 6.0e-13 to 5.6e-13 in two steps, `pyramid:4`'s 88 from 1.8e-13
/// to 9.0e-14, and polishing them took more iterations over 100 steps than
/// it saved (stack:10 122 instead of 76 a world, pyramid:4 180 instead of
/// 159); `stack:4`'s 16 contacts went from 2.7e-12 to 1e-17 in a step.
const POLISH_BELOW: usize = crate::friction::sparse::SPARSE_FROM;

/// A start within the tolerance (`as_is`, its answer as it is) polished by
/// Newton ([`FrictionMethod::Newton`] through [`solve_friction_problem`]:
/// large islands reordered) towards [`POLISH_TARGET`] of the tolerance, at
/// most [`POLISH_STEPS`] steps: the polished answer where its error is
/// smaller, else `as_is` (the steps counted either way). Solved either way.
fn polish_start(
    p: &FrictionProblem,
    as_is: FrictionSolution,
    s: &FrictionSettings,
) -> FrictionSolution {
    let newton = FrictionSettings {
        method: FrictionMethod::Newton,
        tolerance: POLISH_TARGET * s.tolerance,
        max_iterations: POLISH_STEPS,
    };
    let polished = solve_friction_problem(p, Some(&as_is.r), &newton);
    let iterations = polished.iterations;
    let better = polished.residuals.coulomb_error < as_is.residuals.coulomb_error;
    let mut out = if better { polished } else { as_is };
    out.status = Status::Solved;
    out.iterations = iterations;
    out.method = s.method;
    out
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
    use crate::friction::assembly::assemble_friction_island;
    use crate::generate::Rng;
    use crate::settings::{Backend, Method};
    use crate::world::generate::{standard_world, WorldKind};
    use crate::world::step::prepare;
    use crate::Solver;

    /// The check through the bodies computes W r + q: on the islands of a
    /// pyramid at rest and of rains in flight and landing (bodies of
    /// 1.7–730 kg, spheres and boxes, restitution), with random reactions
    /// in the cones, its u equals the assembled W r + q to 1e-12 of the
    /// largest entry, and a start is accepted (0 iterations) exactly where
    /// its error is within the tolerance.
    #[test]
    fn the_check_through_the_bodies_is_w_r_plus_q() {
        let mut rng = Rng::new(5);
        let mut solver = Solver::new(Settings {
            friction_tolerance: 1e-12,
            ..Settings::new(Backend::Cpu, Method::Auto)
        })
        .unwrap();
        let mut worlds = vec![standard_world(WorldKind::Pyramid, 4, 0)];
        worlds.extend((0..3).map(|k| standard_world(WorldKind::Rain, 32, k)));
        let mut islands_seen = 0;
        for step in 0..120 {
            for (index, world) in worlds.iter().enumerate() {
                let scene = prepare(world, index, 0.01).scene;
                let FrictionBuilt { islands, rows } = FrictionBuilt::new(&scene);
                let starts: Vec<Option<Vec<f64>>> = (islands.iter())
                    .map(|isl| Some((0..3 * isl.len()).map(|_| rng.range(0.0, 50.0)).collect()))
                    .collect();
                let accept_all = FrictionSettings {
                    tolerance: f64::INFINITY,
                    ..FrictionSettings::default()
                };
                let all = checked_starts(&scene, &rows, &islands, &starts, &accept_all);
                let strict = FrictionSettings::default();
                let some = checked_starts(&scene, &rows, &islands, &starts, &strict);
                for ((isl, solution), kept) in islands.iter().zip(all).zip(some) {
                    let Checked::Within(solution, error) = solution else {
                        panic!("step {step}: not accepted at an infinite tolerance");
                    };
                    assert_eq!(solution.iterations, 0);
                    assert_eq!(error, solution.residuals.coulomb_error);
                    let p = assemble_friction_island(&scene, &rows, isl);
                    let u = p.velocity(&solution.r);
                    let scale = u.iter().chain(&p.q).fold(1.0f64, |m, v| m.max(v.abs()));
                    for (a, b) in u.iter().zip(&solution.u) {
                        assert!((a - b).abs() <= 1e-12 * scale, "step {step}: {a} vs {b}");
                    }
                    let within = solution.residuals.coulomb_error <= strict.tolerance;
                    let accepted = matches!(kept, Checked::Within(..));
                    assert_eq!(accepted, within, "step {step}");
                    islands_seen += 1;
                }
            }
            solver.step_worlds(&mut worlds, 0.01).unwrap();
        }
        assert!(islands_seen > 1000, "{islands_seen} islands");
    }

    /// A resting 4-box stack at the tolerance of `simulate` (1e-12): with
    /// the step after an unsettled one polished ([`SETTLED`]), 90 of 100
    /// steps take its warm start as it is (accepting every start within
    /// the tolerance, 55: the three-step cycle of `SETTLED`'s docs); every
    /// island solved, within the tolerance, and polished islands below
    /// [`SETTLED`] of it or no worse than their start.
    #[test]
    fn a_resting_stack_settles_into_warm_starts() {
        let tolerance = 1e-12;
        let mut solver = Solver::new(Settings {
            friction_tolerance: tolerance,
            warm_start: true,
            threads: 1,
            ..Settings::new(Backend::Cpu, Method::Auto)
        })
        .unwrap();
        let mut worlds = vec![standard_world(WorldKind::Stack, 4, 0)];
        let mut as_is = 0;
        for step in 0..100 {
            let report = solver.step_worlds(&mut worlds, 0.01).unwrap();
            assert_eq!(report.unsolved, 0, "step {step}");
            let [island] = &report.solve.friction[..] else {
                panic!("step {step}: one island");
            };
            assert!(
                island.error() <= tolerance,
                "step {step}: {}",
                island.error()
            );
            as_is += usize::from(island.solution.iterations == 0);
        }
        assert!(
            as_is >= 85,
            "{as_is} of 100 steps took the warm start as it is"
        );
    }
}

/// The warm-start entries of a frictional step: its solved islands'
/// reactions by contact id (unsolved islands record none).
pub(super) fn solved_reactions<'a>(
    scene: &'a Scene,
    reports: &'a [FrictionIslandReport],
) -> impl Iterator<Item = (u64, [f64; 3])> + 'a {
    let solved = reports.iter().filter(|i| i.status().is_solution());
    solved.flat_map(|isl| reaction_entries(ids_of(scene, &isl.contacts), &isl.solution.r))
}
