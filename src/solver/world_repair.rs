//! What a world step does with an island the solver left unsolved (a status
//! that is not a solution after the final check: Lemke's pivot cap, PGS's
//! sweep cap, a Coulomb solver that did not converge, a numerical failure).
//!
//! Applying such an answer moves bodies by impulses nobody checked: a
//! Newton solve that had not converged once let a resting stack fall 19 m.
//! A simulator must never do that, and must say what it did instead. The
//! island's bodies therefore get, in this order, the first of:
//!
//! 1. **exact normal impulses** ([`Repair::Exact`]): the island's
//!    frictionless LCP (the normal rows of its contacts, same q with the gap
//!    term) re-solved by Auto (prediction, checked Lemke, exhaustive
//!    enumeration for n ≤ 20) with at least the default pivot cap, and
//!    checked against `settings.tolerance`. Non-penetration is then exact;
//!    a frictional island loses its friction for this one step (its bodies
//!    slide without friction for Δt, the smallest change that keeps contact
//!    exact);
//! 2. **PGS's normal impulses** ([`Repair::Approximate`]) when step 1 fails
//!    (n > 20 and Lemke ended on a ray): finite, non-negative impulses with
//!    an error above the tolerance (PGS cannot push bodies apart beyond what
//!    the contacts ask for; the next step's gap term corrects what remains);
//! 3. **no impulse** ([`Repair::Dropped`]) when even PGS's answer is not
//!    finite: the bodies fly freely for Δt and the next step's gap term
//!    φ/Δt pushes them out.
//!
//! Each is counted in [`crate::StepReport::repairs`]; `unsolved` keeps
//! counting the islands the solver left unsolved.

use glam::DVec3;
use serde::Serialize;

use super::cpu_path::solve_on_cpu;
use crate::cpu::assembly::ContactRow;
use crate::cpu::impulses::BodyVelocity;
use crate::cpu::pgs::pgs;
use crate::lcp::{Lcp, LcpSolution, Status};
use crate::scene::Scene;
use crate::settings::{Method, Settings};

/// Unsolved islands of a step, by what their bodies got instead (see the
/// module docs of `world_repair`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[non_exhaustive]
pub struct Repairs {
    /// Re-solved exactly without friction (normal impulses, checked).
    pub exact: usize,
    /// Given PGS's finite, non-negative normal impulses (error above the
    /// tolerance).
    pub approximate: usize,
    /// Given no impulse (bodies in free flight for this step).
    pub dropped: usize,
}

impl Repairs {
    /// Counts one repair.
    pub(super) fn add(&mut self, r: Repair) {
        match r {
            Repair::Exact => self.exact += 1,
            Repair::Approximate => self.approximate += 1,
            Repair::Dropped => self.dropped += 1,
        }
    }

    /// Adds another step part's counts.
    pub(super) fn merge(&mut self, o: Repairs) {
        self.exact += o.exact;
        self.approximate += o.approximate;
        self.dropped += o.dropped;
    }

    /// Every repaired island.
    pub fn total(&self) -> usize {
        self.exact + self.approximate + self.dropped
    }
}

/// What an unsolved island got instead.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Repair {
    Exact,
    Approximate,
    Dropped,
}

/// The settings of a repair: the caller's tolerances, Auto with
/// prediction, and at least the default pivot and sweep caps.
pub(super) fn repair_settings(s: &Settings) -> Settings {
    let d = Settings::default();
    Settings {
        method: Method::Auto,
        predict: true,
        all_solutions: false,
        lemke_max_pivots: s.lemke_max_pivots.max(d.lemke_max_pivots),
        pgs_max_sweeps: s.pgs_max_sweeps.max(d.pgs_max_sweeps),
        ..s.clone()
    }
}

/// A solution the step may apply: a solution status, finite, within the
/// tolerance (the final check).
fn usable(s: &LcpSolution, tolerance: f64) -> bool {
    s.status.is_solution() && s.passes_check(tolerance)
}

/// The normal impulses of an unsolved island with frictionless LCP `lcp`
/// (see the module docs), `settings` from [`repair_settings`].
pub(super) fn repair_island(lcp: &Lcp, settings: &Settings) -> (Repair, Vec<f64>) {
    let (_, _, exact) = solve_on_cpu(lcp, None, settings);
    if usable(&exact, settings.tolerance) {
        return (Repair::Exact, exact.z.into_vec());
    }
    let approx = pgs(lcp, &settings.pgs());
    let swept = matches!(approx.status, Status::Solved | Status::NotConverged);
    if swept && approx.z.iter().all(|z| z.is_finite() && *z >= 0.0) {
        return (Repair::Approximate, approx.z.into_vec());
    }
    (Repair::Dropped, vec![0.0; lcp.n()])
}

/// Gives the bodies of an island (those its `contacts` touch) their
/// velocities before the impulses (the scene's v*) plus the normal impulses
/// `z`, one per contact along its row's M⁻¹Jᵀ; other bodies keep theirs.
pub(super) fn reapply(
    scene: &Scene,
    rows: &[ContactRow],
    contacts: &[usize],
    z: &[f64],
    bodies: &mut [BodyVelocity],
) {
    for &c in contacts {
        let con = &scene.contacts[c];
        for k in std::iter::once(con.a).chain(con.b) {
            bodies[k] = BodyVelocity {
                velocity: scene.bodies[k].velocity,
                angular_velocity: scene.bodies[k].angular_velocity,
            };
        }
    }
    for (&c, &zi) in contacts.iter().zip(z) {
        let con = &scene.contacts[c];
        let r = &rows[c].response;
        let block = |at: usize| DVec3::new(r[at], r[at + 1], r[at + 2]) * zi;
        let mut push = |k: usize, lin: DVec3, ang: DVec3| {
            let b = &mut bodies[k];
            b.velocity = (DVec3::from_array(b.velocity) + lin).to_array();
            b.angular_velocity = (DVec3::from_array(b.angular_velocity) + ang).to_array();
        };
        push(con.a, block(0), block(3));
        if let Some(b) = con.b {
            push(b, block(6), block(9));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_capped_method_is_repaired_exactly_and_a_hopeless_one_is_dropped() {
        // Two coupled contacts, both active: M = [[2, 1], [1, 2]], q = (−5, −6),
        // z = (4/3, 7/3).
        let lcp = Lcp::new(vec![2.0, 1.0, 1.0, 2.0], vec![-5.0, -6.0]).unwrap();
        let capped = Settings {
            method: Method::Lemke,
            lemke_max_pivots: 1,
            ..Settings::default()
        };
        let (r, z) = repair_island(&lcp, &repair_settings(&capped));
        assert_eq!(r, Repair::Exact);
        assert!((z[0] - 4.0 / 3.0).abs() < 1e-12 && (z[1] - 7.0 / 3.0).abs() < 1e-12);
        // A zero diagonal: no exact answer (no solution) and no PGS sweep.
        let none = Lcp::new(vec![0.0], vec![-1.0]).unwrap();
        let (r, z) = repair_island(&none, &repair_settings(&Settings::default()));
        assert_eq!((r, z), (Repair::Dropped, vec![0.0]));
    }
}
