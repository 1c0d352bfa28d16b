//! Exhaustive enumeration in Gray-code order: one principal pivot per basis
//! (O(n²)) instead of one elimination (O(k³) plus O(nk) for w). Same
//! settings, same choice of basis and same result as
//! [`crate::cpu::enumeration::enumerate`], which it calls to confirm every
//! candidate.
//!
//! # Principal pivoting
//! For a basis S write the basic variables through the nonbasic ones:
//!
//! ```text
//! [z_S; w_N] = T [w_S; z_N] + t,     T = M_SS⁻¹-based principal pivot transform of M
//! ```
//!
//! The basic solution is t (nonbasic variables at 0): z_S = t_S, w_N = t_N.
//! Gray code order g(k) = k ⊕ (k >> 1) changes one index r per step; adding
//! or removing r from S is the principal pivot on T_rr:
//!
//! ```text
//! T'_rr = 1/T_rr,  T'_ir = T_ir/T_rr,  T'_rj = −T_rj/T_rr,
//! T'_ij = T_ij − T_ir T_rj / T_rr,   t'_r = −t_r/T_rr,  t'_i = t_i − T_ir t_r/T_rr
//! ```
//!
//! which exists exactly when the new basis is nonsingular
//! (det M_S'S' = ±T_rr det M_SS).
//!
//! # Error control
//! Pivots accumulate rounding. The tableau is rebuilt from M by elimination
//! every `refactor_period` steps, and whenever |T_rr| falls below
//! `pivot_tol` times the largest magnitude in row r (a basis singular to
//! working precision, whose neighbours would inherit its error). While the
//! tableau is invalid (after a singular basis) each basis is rebuilt until
//! one is nonsingular.
//!
//! # Exactness
//! t only screens: a basis whose t is feasible to a loose 1e-6 (relative to
//! ‖q‖∞ + max|M|·‖z_S‖₁, an upper bound of enumeration's own scale for w) is
//! confirmed by enumeration's elimination with the strict and relaxed
//! tolerances. Drift below that screen cannot drop a basis enumeration would
//! accept, and the choice rule (fewest basic z, then smallest mask; the least
//! infeasible within the relaxed tolerance when none is strictly feasible) is
//! applied to the confirmed bases, so the result is enumeration's.

use crate::cpu::enumeration::{
    enumerate, solve_basis, BasisOutcome, EnumerationSettings, MAX_ENUMERATION_N,
};
use crate::lcp::{Counters, Lcp, LcpSolution, Status};

/// Settings of Gray-code enumeration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GraySettings {
    pub enumeration: EnumerationSettings,
    /// Rebuild the tableau from M every this many pivots (default 64).
    pub refactor_period: u32,
    /// Screening tolerance on t (default 1e-6, relative; see the module docs).
    pub screen_tol: f64,
    /// A principal pivot |T_rr| below this times the largest entry of row r
    /// is not taken (default 1e-6): it would multiply the tableau's rounding
    /// error by up to 1/tol. That basis is decided by elimination instead and
    /// the tableau rebuilt at the next step.
    pub pivot_tol: f64,
}

impl Default for GraySettings {
    fn default() -> Self {
        GraySettings {
            enumeration: EnumerationSettings::default(),
            refactor_period: 64,
            screen_tol: 1e-6,
            pivot_tol: 1e-6,
        }
    }
}

/// The principal pivot tableau of one basis, for islands of exactly K
/// contacts: sizes known at compile time let the pivot loops unroll and
/// vectorise (one monomorphisation per K = 1…20).
struct Tableau<const K: usize> {
    t: [[f64; K]; K],
    rhs: [f64; K],
    /// False after a singular basis: rebuild before the next pivot.
    valid: bool,
}

impl<const K: usize> Tableau<K> {
    fn new() -> Self {
        Tableau {
            t: [[0.0; K]; K],
            rhs: [0.0; K],
            valid: false,
        }
    }

    /// Principal pivot on index r. Returns false (and invalidates) when
    /// |T_rr| is below the tolerance relative to its row.
    #[inline]
    fn pivot(&mut self, r: usize, pivot_tol: f64) -> bool {
        let p = self.t[r][r];
        let rowmax = self.t[r].iter().fold(0.0f64, |m, v| m.max(v.abs()));
        if !(p.abs() > pivot_tol * rowmax) {
            self.valid = false;
            return false;
        }
        let inv = 1.0 / p;
        // Row r first: T'_rj = −T_rj/T_rr (j ≠ r), t'_r = −t_r/T_rr.
        let mut row = self.t[r];
        for v in &mut row {
            *v *= -inv;
        }
        let tr = -self.rhs[r] * inv;
        for i in 0..K {
            if i == r {
                continue;
            }
            let f = self.t[i][r];
            // T'_ij = T_ij + T_ir·(−T_rj/T_rr); column r set below.
            for (x, y) in self.t[i].iter_mut().zip(&row) {
                *x += f * y;
            }
            self.rhs[i] += f * tr;
            self.t[i][r] = f * inv;
        }
        self.t[r] = row;
        self.t[r][r] = inv;
        self.rhs[r] = tr;
        true
    }

    /// Rebuilds the tableau of basis `mask` from M by successive principal
    /// pivots from the identity basis, choosing at each step the remaining
    /// index of S with the largest |T_rr| (a pivot order that exists for any
    /// nonsingular M_SS that is positive definite; for other M_SS a zero
    /// diagonal can remain, and the basis is then treated as singular).
    fn rebuild(&mut self, lcp: &Lcp, mask: u32, pivot_tol: f64) -> bool {
        for (i, row) in self.t.iter_mut().enumerate() {
            row.copy_from_slice(&lcp.m[i * K..(i + 1) * K]);
        }
        self.rhs.copy_from_slice(&lcp.q);
        self.valid = true;
        let mut left = mask;
        while left != 0 {
            let mut best = None;
            let mut best_v = -1.0;
            let mut rest = left;
            while rest != 0 {
                let r = rest.trailing_zeros() as usize;
                rest &= rest - 1;
                let v = self.t[r][r].abs();
                if v > best_v {
                    best_v = v;
                    best = Some(r);
                }
            }
            let r = best.expect("left is not empty");
            if !self.pivot(r, pivot_tol) {
                return false;
            }
            left &= !(1u32 << r);
        }
        true
    }
}

/// Solves `lcp` by enumerating every basis in Gray-code order. Returns the
/// same solution as [`enumerate`] with the same enumeration settings; the
/// counters count every basis visited and, among the bases checked by
/// elimination, those found singular.
pub fn enumerate_gray(lcp: &Lcp, settings: &GraySettings) -> Result<LcpSolution, crate::Error> {
    let es = &settings.enumeration;
    es.validate()?;
    let n = lcp.n();
    if n > MAX_ENUMERATION_N {
        return enumerate(lcp, es);
    }
    if es.all_solutions {
        // Every basis is confirmed anyway; elimination is as fast.
        return enumerate(lcp, es);
    }
    macro_rules! dispatch {
        ($($k:literal)*) => {
            match n {
                $($k => enumerate_gray_k::<$k>(lcp, settings),)*
                _ => unreachable!("1 ≤ n ≤ {MAX_ENUMERATION_N}"),
            }
        };
    }
    Ok(dispatch!(1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20))
}

fn enumerate_gray_k<const K: usize>(lcp: &Lcp, settings: &GraySettings) -> LcpSolution {
    let es = &settings.enumeration;
    let n = K;
    let mmax = lcp.m.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let qmax = lcp.q.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let mut tab = Tableau::<K>::new();
    let mut counters = Counters::default();
    // Best strictly feasible basis by (popcount, mask), and least infeasible.
    let mut best: Option<u32> = None;
    let mut least: Option<(f64, u32)> = None;
    let key = |m: u32| (m.count_ones(), m);
    let mut since_rebuild = 0u32;
    let mut mask = 0u32;
    tab.rebuild(lcp, 0, settings.pivot_tol);
    for k in 0u64..(1u64 << n) {
        if k > 0 {
            let r = k.trailing_zeros() as usize;
            mask ^= 1 << r;
            since_rebuild += 1;
            if tab.valid && since_rebuild < settings.refactor_period {
                tab.pivot(r, settings.pivot_tol);
            } else {
                since_rebuild = 0;
                tab.rebuild(lcp, mask, settings.pivot_tol);
            }
        }
        counters.bases_visited += 1;
        // A basis that cannot beat the best one found needs no check.
        if best.is_some_and(|b| key(b) < key(mask)) {
            continue;
        }
        if tab.valid && !screen(&tab, mask, qmax, mmax, settings.screen_tol) {
            continue;
        }
        // Screened in, or no tableau for this basis (singular to the pivot
        // test, or a principal pivot order that does not exist): decide with
        // enumeration's own elimination and tolerances.
        match solve_basis(lcp, mask, es) {
            BasisOutcome::Singular => counters.singular_bases += 1,
            BasisOutcome::Solved { infeasibility, .. } => {
                if infeasibility <= es.feasibility_tol {
                    best = Some(mask);
                } else if infeasibility <= es.relaxed_feasibility_tol
                    && least.is_none_or(|(v, lm)| (infeasibility, key(mask)) < (v, key(lm)))
                {
                    least = Some((infeasibility, mask));
                }
            }
        }
    }
    let Some(basis) = best.or(least.map(|(_, m)| m)) else {
        return LcpSolution::from_z(lcp, Status::NoSolution, vec![0.0; n], counters);
    };
    let BasisOutcome::Solved { z, .. } = solve_basis(lcp, basis, es) else {
        unreachable!("a confirmed basis is nonsingular")
    };
    let mut sol = LcpSolution::from_z(lcp, Status::Solved, z, counters);
    sol.basis = Some(basis);
    sol
}

/// Does the tableau's basic solution pass the loose screen? z_S = t_S ≥
/// −tol·‖z‖∞ and w_N = t_N ≥ −tol·(‖q‖∞ + max|M|·‖z‖₁).
#[inline]
fn screen<const K: usize>(tab: &Tableau<K>, mask: u32, qmax: f64, mmax: f64, tol: f64) -> bool {
    let (mut zmax, mut zsum) = (0.0f64, 0.0f64);
    let mut m = mask;
    while m != 0 {
        let i = m.trailing_zeros() as usize;
        m &= m - 1;
        zmax = zmax.max(tab.rhs[i].abs());
        zsum += tab.rhs[i].abs();
    }
    let wscale = qmax + mmax * zsum;
    (0..K).all(|i| {
        if mask >> i & 1 == 1 {
            tab.rhs[i] >= -tol * zmax
        } else {
            tab.rhs[i] >= -tol * wscale
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generate::{random_island, Rng};
    use crate::pipeline::build;

    #[test]
    fn agrees_with_elimination_on_random_islands_and_seed_examples() {
        let settings = GraySettings::default();
        let mut lcps = vec![
            Lcp::new(vec![2.0, 1.0, 1.0, 2.0], vec![-5.0, -6.0]).unwrap(),
            Lcp::new(
                vec![0.0, -1.0, 2.0, 2.0, 0.0, -2.0, -1.0, 1.0, 0.0],
                vec![-3.0, 6.0, -1.0],
            )
            .unwrap(),
            Lcp::new(vec![1.0, 1.0, 1.0, 1.0], vec![-1.0, -1.0]).unwrap(),
        ];
        let mut rng = Rng::new(11);
        for _ in 0..300 {
            let n = rng.int(1, 10);
            lcps.extend(build(&random_island(&mut rng, n, 100.0), "t").unwrap().2);
        }
        lcps.extend(
            build(&crate::generate::box_on_ground(1.0, 0.0), "t")
                .unwrap()
                .2,
        );
        for lcp in &lcps {
            let a = enumerate(lcp, &settings.enumeration).unwrap();
            let b = enumerate_gray(lcp, &settings).unwrap();
            assert_eq!((a.status, a.basis), (b.status, b.basis), "{lcp:?}");
            assert_eq!(a.z, b.z);
        }
    }
}
