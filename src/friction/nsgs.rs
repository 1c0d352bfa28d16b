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

use super::local::{solve_contact, Block};
use super::problem::FrictionProblem;
use super::sparse::{Pattern, SPARSE_FROM};
use super::workspace::{block_at, Workspace};

/// One sweep with `ws.u` = W r + q kept current (see the module docs).
/// On islands of at least [`SPARSE_FROM`] contacts the update of u reads
/// the compact copy `ws.columns` of W's nonzero blocks (built by
/// [`gather_columns`] when the sweeps start; the dense W's rows are
/// 3k apart, one cache miss per row); below it, W itself, which is small
/// enough to stay in cache. The same numbers either way, bit for bit.
fn sweep(p: &FrictionProblem, ws: &mut Workspace, r: &mut [f64]) {
    let (blocks, pattern, columns) = (&ws.blocks, &ws.pattern, &ws.columns);
    if columns.is_empty() {
        sweep_with(p, blocks, pattern, &mut ws.u, r, |i, _, j| {
            block_at(p, j, i)
        });
    } else {
        sweep_with(p, blocks, pattern, &mut ws.u, r, |_, t, _| columns[t]);
    }
}

/// The sweep of [`sweep`], W's block (j, i) given by `block(i, t, j)`
/// for contact j at position t of the pattern's list (`pattern.cols[t]`).
#[inline(always)]
fn sweep_with(
    p: &FrictionProblem,
    blocks: &[Block],
    pattern: &Pattern,
    u: &mut [f64],
    r: &mut [f64],
    block: impl Fn(usize, usize, usize) -> Block,
) {
    for (i, diagonal) in blocks.iter().enumerate() {
        let current = [r[3 * i], r[3 * i + 1], r[3 * i + 2]];
        let local: [f64; 3] = std::array::from_fn(|a| {
            u[3 * i + a]
                - (diagonal[a][0] * current[0]
                    + diagonal[a][1] * current[1]
                    + diagonal[a][2] * current[2])
        });
        let ri = solve_contact(diagonal, local, p.mu[i], current);
        let d = [ri[0] - current[0], ri[1] - current[1], ri[2] - current[2]];
        if d != [0.0; 3] {
            // Only the rows of contacts coupled to i (W's zero rows would
            // add ±0).
            for t in pattern.start[i]..pattern.start[i + 1] {
                let j = pattern.cols[t];
                let w = block(i, t, j);
                for (a, w) in w.iter().enumerate() {
                    u[3 * j + a] += w[0] * d[0] + w[1] * d[1] + w[2] * d[2];
                }
            }
        }
        r[3 * i..3 * i + 3].copy_from_slice(&ri);
    }
}

/// W's nonzero blocks by block column, in the order of `pattern.cols`:
/// entry t of contact i's list (`pattern.cols[t]` = j) is W's block
/// (j, i), rows of j, columns of i; the sweep's update of u reads them
/// contiguously. Empty below [`SPARSE_FROM`] contacts (the sweep reads W).
fn gather_columns(p: &FrictionProblem, pattern: &Pattern, columns: &mut Vec<Block>) {
    columns.clear();
    if p.contacts() < SPARSE_FROM {
        return;
    }
    for i in 0..p.contacts() {
        columns.extend(pattern.row(i).iter().map(|&j| block_at(p, j, i)));
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
    if !(error <= tolerance) && max_sweeps > 0 {
        gather_columns(p, &ws.pattern, &mut ws.columns);
    }
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::friction::random::random_problem;
    use crate::generate::Rng;

    #[test]
    fn sweeps_over_the_compact_blocks_give_the_dense_sweeps_bits() {
        let mut rng = Rng::new(24);
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        for _ in 0..4 {
            let p = random_problem(&mut rng, SPARSE_FROM + 8, 100.0);
            let runs = [true, false].map(|compact| {
                let (mut ws, mut r) = (Workspace::default(), vec![0.0; p.dim()]);
                ws.prepare(&p, &r);
                gather_columns(&p, &ws.pattern, &mut ws.columns);
                assert_eq!(ws.columns.len(), ws.pattern.cols.len());
                if !compact {
                    ws.columns.clear();
                }
                for _ in 0..10 {
                    sweep(&p, &mut ws, &mut r);
                }
                (ws, r)
            });
            // W is block-sparse here (so the pattern skips blocks) and the
            // sweeps moved r.
            assert!(runs[0].0.pattern.cols.len() < p.contacts() * p.contacts());
            assert!(runs[0].1.iter().any(|&x| x != 0.0));
            let [compact, dense] = &runs;
            assert_eq!(bits(&compact.1), bits(&dense.1));
            assert_eq!(bits(&compact.0.u), bits(&dense.0.u));
        }
    }
}
