//! The door for worlds in time: [`Solver::step_worlds`] advances a batch of
//! [`World`]s by one step Δt (seed 001 §四, DVI; the parts per world are in
//! [`crate::world::step`]): collision for every world (over every core),
//! ONE [`Solver::solve_scenes`] call holding every world's islands (CPU or
//! GPU, warm-started by contact id with `Settings::warm_start`), then the
//! velocities after the impulses and the poses.

use std::time::Instant;

use serde::Serialize;

use super::Solver;
use crate::cpu::batch::parallel_map;
use crate::report::Report;
use crate::world::step::{finish, prepare, Prepared};
use crate::world::World;
use crate::Error;

/// One world after a step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct WorldStepReport {
    /// Kinetic energy (J) after the step.
    pub kinetic: f64,
    /// Potential energy −Σ m g·x (J) after the step.
    pub potential: f64,
    /// Deepest penetration (m, ≥ 0) among this step's contacts, before the
    /// step's correction (collision's −φ).
    pub max_penetration: f64,
    /// Contacts this step.
    pub contacts: usize,
    /// Islands this step.
    pub islands: usize,
    /// Largest error measure of this world's islands (0 when none): the
    /// LCP error of frictionless islands, the Coulomb error of frictional ones.
    pub max_error: f64,
    /// Dynamic bodies awake after the step.
    pub awake: usize,
}

/// Seconds per phase of one step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct StepTimings {
    /// Gravity, broad and narrow phase, the scenes (all worlds).
    pub collision: f64,
    /// The door's `solve_scenes`: checks, assembly and solve, impulses.
    pub solve: f64,
    /// Velocities and poses.
    pub integrate: f64,
}

/// What one step of a batch of worlds found.
#[derive(Clone, Debug)]
pub struct StepReport {
    /// One per world, in the caller's order.
    pub worlds: Vec<WorldStepReport>,
    /// The door's report of the step's one batch (statuses, paths, device).
    pub solve: Report,
    /// Seconds per phase.
    pub timings: StepTimings,
    /// Islands whose status is not a solution (their worlds' bodies then
    /// get the velocities the door reports for them, v* where no impulse).
    pub unsolved: usize,
}

impl Solver {
    /// Advances every world by one step of `dt` seconds; see the module
    /// docs. Every world is checked first (an error names the world, the
    /// body and the field) and none moves then; `dt` must be finite and > 0.
    /// The same world gives the same trajectory alone or in a batch (bit for
    /// bit on the CPU: each island is solved on its own, contact ids carry
    /// the world's index).
    pub fn step_worlds(&mut self, worlds: &mut [World], dt: f64) -> Result<StepReport, Error> {
        if !dt.is_finite() || dt <= 0.0 {
            return Err(Error::invalid(
                "step",
                "dt",
                format!("{dt} is not a positive number"),
            ));
        }
        for (i, w) in worlds.iter().enumerate() {
            w.validate(&format!("world {i}"))?;
        }
        let start = Instant::now();
        let shared: &[World] = worlds;
        let prepared: Vec<Prepared> =
            parallel_map(shared.len(), self.threads, |i| prepare(&shared[i], i, dt));
        let (scenes, prepared): (Vec<crate::Scene>, Vec<Prepared>) = prepared
            .into_iter()
            .map(|mut p| (std::mem::take(&mut p.scene), p))
            .unzip();
        let collision = start.elapsed().as_secs_f64();
        let solve = self.solve_scenes(&scenes)?;
        let solved_at = Instant::now();
        let mut reports = Vec::with_capacity(worlds.len());
        for (k, (w, p)) in worlds.iter_mut().zip(&prepared).enumerate() {
            let scene = &solve.scenes[k];
            finish(w, p, &scene.bodies, dt);
            // Frictionless islands (LCP error) and frictional ones (Coulomb error).
            let friction = scene.friction.as_ref().map_or(0..0, |f| f.islands.clone());
            let max_error = solve.islands[scene.islands.clone()]
                .iter()
                .filter(|i| i.status().is_solution())
                .map(|i| i.error())
                .chain(
                    solve.friction[friction.clone()]
                        .iter()
                        .filter(|i| i.status().is_solution())
                        .map(|i| i.error()),
                )
                .fold(0.0, f64::max);
            reports.push(WorldStepReport {
                kinetic: w.kinetic_energy(),
                potential: w.potential_energy(),
                max_penetration: p.contacts.iter().map(|c| -c.gap).fold(0.0, f64::max),
                contacts: p.contacts.len(),
                islands: scene.islands.len() + friction.len(),
                max_error,
                awake: w.bodies.iter().filter(|b| !b.fixed && !b.asleep).count(),
            });
        }
        let unsolved = solve
            .islands
            .iter()
            .map(|i| i.status())
            .chain(solve.friction.iter().map(|i| i.status()))
            .filter(|s| !s.is_solution())
            .count();
        Ok(StepReport {
            worlds: reports,
            timings: StepTimings {
                collision,
                solve: solve.timings.total,
                integrate: solved_at.elapsed().as_secs_f64(),
            },
            solve,
            unsolved,
        })
    }
}
