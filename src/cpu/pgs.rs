//! Projected Gauss–Seidel (Cottle–Pang–Stone 1992, ch. 5, projected SOR
//! with ω = 1): the LCP as a projection on the orthant. Each sweep
//! projects every z_i onto [0, ∞) after a Gauss–Seidel step on row i,
//!
//! ```text
//! z_i ← max(0, z_i − (q_i + Σ_j M_ij z_j) / M_ii),
//! ```
//!
//! which is exact for one contact and converges for symmetric positive
//! semidefinite M with a positive diagonal (the contact matrices this tool
//! builds). It needs M_ii > 0; it is cheap per sweep and approximate.

use crate::lcp::{Counters, Lcp, LcpSolution, Residuals, Status};

/// Settings of projected Gauss–Seidel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PgsSettings {
    /// Sweep cap (default 1000); reaching it gives `NotConverged`.
    pub max_iterations: u64,
    /// Stop when the Siconos error measure is at most this (default 1e-10).
    pub tolerance: f64,
}

impl Default for PgsSettings {
    fn default() -> Self {
        PgsSettings {
            max_iterations: 1000,
            tolerance: 1e-10,
        }
    }
}

/// Solves `lcp` by projected Gauss–Seidel from z = 0. Statuses: `Solved`
/// (error ≤ tolerance), `NotConverged` (sweep cap; z is the last iterate),
/// `InvalidInput` (a diagonal entry M_ii ≤ 0, which PGS cannot divide by).
/// On a problem where it diverges it stops at the last finite iterate, with
/// `NotConverged`: z and w never hold NaN or Inf.
/// The error is checked after every sweep, so a converged result costs one
/// more matrix–vector product per sweep than PGS alone.
pub fn pgs(lcp: &Lcp, settings: &PgsSettings) -> LcpSolution {
    let n = lcp.n();
    let mut counters = Counters::default();
    if (0..n).any(|i| !(lcp.at(i, i) > 0.0)) {
        return LcpSolution::from_z(lcp, Status::InvalidInput, vec![0.0; n], counters);
    }
    let mut z = vec![0.0; n];
    let mut status = Status::NotConverged;
    // Check z = 0 first: an island that separates needs no sweep.
    if lcp.residuals(&z).error <= settings.tolerance {
        status = Status::Solved;
    }
    let mut last = z.clone();
    while status != Status::Solved && counters.iterations < settings.max_iterations {
        last.copy_from_slice(&z);
        for i in 0..n {
            let row = &lcp.m[i * n..(i + 1) * n];
            let r = lcp.q[i] + row.iter().zip(&z).map(|(a, b)| a * b).sum::<f64>();
            z[i] = (z[i] - r / row[i]).max(0.0);
        }
        counters.iterations += 1;
        let w = lcp.w(&z);
        if !z.iter().chain(&w).all(|v| v.is_finite()) {
            // Diverged (PGS has no convergence guarantee without symmetric
            // positive semidefinite M): report the last finite iterate.
            z.copy_from_slice(&last);
            break;
        }
        if Residuals::of(&z, &w, &lcp.q).error <= settings.tolerance {
            status = Status::Solved;
        }
    }
    LcpSolution::from_z(lcp, status, z, counters)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seed_000_two_by_two_converges() {
        let lcp = Lcp::new(vec![2.0, 1.0, 1.0, 2.0], vec![-5.0, -6.0]).unwrap();
        let sol = pgs(&lcp, &PgsSettings::default());
        assert_eq!(sol.status, Status::Solved);
        assert!((sol.z[0] - 4.0 / 3.0).abs() < 1e-9 && (sol.z[1] - 7.0 / 3.0).abs() < 1e-9);
        assert!(sol.counters.iterations > 1);
    }

    #[test]
    fn zero_diagonal_is_reported_not_divided() {
        let lcp = Lcp::new(vec![0.0, 1.0, 1.0, 1.0], vec![-1.0, -1.0]).unwrap();
        assert_eq!(
            pgs(&lcp, &PgsSettings::default()).status,
            Status::InvalidInput
        );
    }

    #[test]
    fn divergence_stops_at_the_last_finite_iterate() {
        // Non-symmetric with a dominant off-diagonal: the iterates grow
        // without bound until they overflow.
        let lcp = Lcp::new(vec![1.0, -1e200, -1e200, 1.0], vec![-1.0, -1.0]).unwrap();
        let sol = pgs(&lcp, &PgsSettings::default());
        assert_eq!(sol.status, Status::NotConverged);
        assert!(sol.z.iter().all(|v| v.is_finite()), "{:?}", sol.z);
    }

    #[test]
    fn a_sweep_cap_gives_not_converged() {
        let lcp = Lcp::new(vec![1.0, 0.99, 0.99, 1.0], vec![-1.0, -1.5]).unwrap();
        let sol = pgs(
            &lcp,
            &PgsSettings {
                max_iterations: 3,
                tolerance: 1e-14,
            },
        );
        assert_eq!(sol.status, Status::NotConverged);
        assert_eq!(sol.counters.iterations, 3);
    }
}
