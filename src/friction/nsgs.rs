//! Non-smooth block Gauss–Seidel (NSGS, as Siconos' FC3D_NSGS): sweep over
//! the contacts, each solved exactly ([`solve_contact`]) with the others'
//! reactions frozen at their latest values. A Coulomb iteration: judged by
//! the Coulomb error, not the cone complementarity residual.

use super::local::{solve_contact, Block};
use super::problem::FrictionProblem;
use super::residual::coulomb_error;

/// Contact i's 3×3 diagonal block of W.
pub fn diagonal_block(p: &FrictionProblem, i: usize) -> Block {
    std::array::from_fn(|a| std::array::from_fn(|b| p.at(3 * i + a, 3 * i + b)))
}

/// One sweep over the contacts in order, updating `r` in place.
pub fn nsgs_sweep(p: &FrictionProblem, blocks: &[Block], r: &mut [f64]) {
    let n = p.dim();
    for (i, block) in blocks.iter().enumerate() {
        // The local free velocity: q_i + Σ_{j ≠ i} W_ij r_j, i.e. the row
        // times r minus the own block's part.
        let mut local = [0.0; 3];
        for (a, l) in local.iter_mut().enumerate() {
            let row = &p.w[(3 * i + a) * n..(3 * i + a + 1) * n];
            let full: f64 = row.iter().zip(&*r).map(|(x, y)| x * y).sum();
            let own: f64 = (0..3).map(|b| block[a][b] * r[3 * i + b]).sum();
            *l = p.q[3 * i + a] + full - own;
        }
        let current = [r[3 * i], r[3 * i + 1], r[3 * i + 2]];
        let ri = solve_contact(block, local, p.mu[i], current);
        r[3 * i..3 * i + 3].copy_from_slice(&ri);
    }
}

/// NSGS from `r` (a warm start or zeros) until the Coulomb error is at most
/// `tolerance` or `max_sweeps` sweeps ran: (sweeps, error of the last r).
/// One contact is exact after one sweep.
pub fn nsgs(p: &FrictionProblem, r: &mut [f64], max_sweeps: u64, tolerance: f64) -> (u64, f64) {
    let blocks: Vec<Block> = (0..p.contacts()).map(|i| diagonal_block(p, i)).collect();
    let mut error = coulomb_error(p, r);
    let mut sweeps = 0;
    while sweeps < max_sweeps && !(error <= tolerance) {
        nsgs_sweep(p, &blocks, r);
        sweeps += 1;
        error = coulomb_error(p, r);
        if !error.is_finite() {
            break;
        }
    }
    (sweeps, error)
}
