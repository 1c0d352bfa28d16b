//! Non-smooth block Gauss–Seidel (NSGS, as Siconos' FC3D_NSGS): sweep over
//! the contacts, each solved exactly ([`solve_contact`]) with the others'
//! reactions frozen at their latest values. A Coulomb iteration: judged by
//! the Coulomb error, not the cone complementarity residual.
//!
//! The sweep keeps u = W r + q current: contact i's local free velocity is
//! u_i − W_ii r_i, and its new reaction moves u by W_{·i} Δr_i (3k × 3
//! multiply-adds), so that the error after each sweep needs no product
//! with W. Before a sweep count is reported as converged, u is recomputed
//! exactly and the error checked again (the updates' rounding drifts).

use super::local::solve_contact;
use super::problem::FrictionProblem;
use super::workspace::Workspace;

/// One sweep with `ws.u` = W r + q kept current (see the module docs).
fn sweep(p: &FrictionProblem, ws: &mut Workspace, r: &mut [f64]) {
    let n = p.dim();
    let u = &mut ws.u;
    for (i, block) in ws.blocks.iter().enumerate() {
        let current = [r[3 * i], r[3 * i + 1], r[3 * i + 2]];
        let local: [f64; 3] = std::array::from_fn(|a| {
            u[3 * i + a]
                - (block[a][0] * current[0] + block[a][1] * current[1] + block[a][2] * current[2])
        });
        let ri = solve_contact(block, local, p.mu[i], current);
        let d = [ri[0] - current[0], ri[1] - current[1], ri[2] - current[2]];
        if d != [0.0; 3] {
            // Only the rows of contacts coupled to i (W's zero rows would
            // add ±0).
            for &j in ws.pattern.row(i) {
                for row in 3 * j..3 * j + 3 {
                    let w = &p.w[row * n + 3 * i..row * n + 3 * i + 3];
                    u[row] += w[0] * d[0] + w[1] * d[1] + w[2] * d[2];
                }
            }
        }
        r[3 * i..3 * i + 3].copy_from_slice(&ri);
    }
}

/// When NSGS gives way to Newton: after two sweeps, once the linear rate
/// e_k / e_{k−1} predicts more than `budget` further sweeps to reach the
/// tolerance (or the error does not decrease).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Patience {
    /// The most further sweeps worth running at the observed rate.
    pub budget: f64,
}

/// NSGS from `r` with `ws` prepared for `p` and `ws.u` = W r + q: sweeps
/// until the Coulomb error is at most `tolerance`, `max_sweeps` ran, or
/// (with `patience`) convergence is too slow. Returns (sweeps, error of the
/// final r); `ws.u` is then exact for r.
pub(crate) fn nsgs_in(
    p: &FrictionProblem,
    ws: &mut Workspace,
    r: &mut [f64],
    max_sweeps: u64,
    tolerance: f64,
    patience: Option<Patience>,
) -> (u64, f64) {
    let mut error = ws.error(p, r);
    let mut sweeps = 0;
    while sweeps < max_sweeps && !(error <= tolerance) {
        sweep(p, ws, r);
        sweeps += 1;
        let before = error;
        error = ws.error(p, r);
        if error <= tolerance {
            ws.refresh(p, r);
            error = ws.error(p, r);
        }
        if !error.is_finite() {
            break;
        }
        if let Some(pat) = patience {
            let rate = error / before;
            let needed = (tolerance / error).ln() / rate.ln();
            if sweeps >= 2 && error > tolerance && !(rate < 1.0 && needed <= pat.budget) {
                break;
            }
        }
    }
    if !(error <= tolerance) {
        ws.refresh(p, r);
        error = ws.error(p, r);
    }
    (sweeps, error)
}
