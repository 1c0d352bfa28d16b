//! Enumeration down the tree of bases: every complementary basis of an
//! island screened by principal pivots taken depth first, then the screened
//! candidates confirmed by elimination in enumeration's order. CPU twin of
//! `shaders/enumeration_tree.wgsl` (same pivots in the same order, same
//! screen, same confirmation), which is generated per island size up to
//! [`TREE_MAX_N`] and which the GPU path runs on islands whose M is
//! positive definite.
//!
//! # The tree
//! Decide index 0, then 1, …, then n − 1: a node at depth d is a set S of
//! indices below d, and its children are S (index d nonbasic: nothing to do)
//! and S ∪ {d} (index d basic: one principal pivot on T_dd, the notation of
//! the Gray-code enumeration this crate had: `[z_S; w_N] = T [w_S; z_N] + t`). The
//! 2ⁿ leaves are the bases; the pivots, one per "basic" edge, number
//! 2ⁿ − 1, as in Gray-code order, but the tableau of each leaf comes from M
//! by at most n pivots in a fixed order (ascending index), so rounding does
//! not accumulate along the walk and needs no refactorisation. A pivot on d
//! only touches the columns still to be pivoted (> d) and t.
//!
//! T_dd at node S is the Schur complement M_dd − M_dS M_SS⁻¹ M_Sd: positive
//! for every S when M is positive definite, which is why the GPU routes only
//! such islands here (then no pivot order is ever needed). A pivot at most
//! `pivot_tol` · M_dd (a Schur complement that lost that many digits, or a
//! matrix that is not positive definite after all) leaves the island
//! undecided: the caller enumerates it by elimination instead.
//!
//! Semidefinite islands (resting contacts: a box on 4 coplanar contacts has
//! a singular M) take one more rule. When M is symmetric positive
//! semidefinite and M_{S∪d} is singular, so is every principal submatrix
//! that contains S ∪ {d} (a null vector xᵀMx = 0 of the smaller one is a
//! null vector of M, hence of the larger), so no basis below that node has a
//! solution: a pivot at most `singular_tol` · M_dd (singular to working
//! precision) cuts the subtree, and only pivots between the two tolerances
//! leave the island undecided.
//!
//! # Screen and confirmation
//! A leaf passes the screen when z_S ≥ −tol·max|t_S| and, for each i off
//! S, w_i ≥ −tol·(|q_i| + max_j |M_ij|·Σ|t_S|): an upper bound of
//! enumeration's own scale of w_i, |q_i| + Σ_j |M_ij z_j|, that keeps rows
//! of small entries (a heavy body's contacts beside a light one's) from
//! being screened against the large ones. The passing
//! bases are confirmed by [`solve_basis`] in enumeration's order (fewest
//! basic z, then smallest mask), at most `max_confirmations` of them: the
//! first feasible to the strict tolerance is enumeration's choice, since
//! every basis enumeration would accept passes the looser screen. When none
//! of them is, the island is undecided (enumeration's answer may then be a
//! least infeasible basis, which the screen does not rank).

// The CPU twin of `shaders/enumeration_tree.wgsl`: the stage tests compare
// the kernel with it; the CPU path itself does not screen by the tree.
#![cfg_attr(not(test), allow(dead_code))]

use crate::cpu::enumeration::{solve_basis, BasisOutcome, EnumerationSettings};
use crate::lcp::{Counters, Lcp, LcpSolution, Status};

/// Largest island the GPU's tree kernel is generated for (its bitmap of
/// screened bases has 2ⁿ bits and its straight-line part assumes n − 8 ≤ 5;
/// `src/tests/gpu_tree.rs` checks every size up to it). The CPU twin takes any
/// n up to 16.
pub const TREE_MAX_N: usize = 12;
/// Largest n the CPU twin takes (2ⁿ leaves, one bit each).
pub const TREE_TWIN_MAX_N: usize = 16;

/// Settings of the tree enumeration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TreeSettings {
    /// Tolerances of the confirming elimination.
    pub enumeration: EnumerationSettings,
    /// Screen tolerance on t, relative (default 1e-6, the Gray-code screen's;
    /// f32 kernels use `F32_SCREEN_TOL` in src/gpu/pipelines.rs).
    pub screen_tol: f64,
    /// A pivot T_dd at most this times M_dd leaves the island undecided
    /// (default 1e-8: in f64 a leaf's t then keeps about 8 digits, far more
    /// than the screen needs).
    pub pivot_tol: f64,
    /// Semidefinite islands: a pivot at most this times M_dd is singular and
    /// its subtree is cut (default 1e-14, a few rounding errors of M_dd:
    /// where elimination also finds M_SS singular).
    pub singular_tol: f64,
    /// Screened bases confirmed by elimination at most (default 8).
    pub max_confirmations: u32,
}

impl Default for TreeSettings {
    fn default() -> Self {
        TreeSettings {
            enumeration: EnumerationSettings::default(),
            screen_tol: 1e-6,
            pivot_tol: 1e-8,
            singular_tol: 1e-14,
            max_confirmations: 8,
        }
    }
}

/// Why the tree left an island to elimination.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Undecided {
    /// A pivot T_dd ≤ pivot_tol · M_dd.
    SmallPivot,
    /// No screened basis among the first `max_confirmations` is feasible to
    /// the strict tolerance.
    NotConfirmed,
    /// n is 0 or above [`TREE_TWIN_MAX_N`].
    Size,
}

/// What the tree gave for one island.
// An `LcpSolution` holds z and w inline (`ShortVec`), so `Decided` is far
// larger than the others; boxing it would allocate per island, what
// `ShortVec` is there to avoid.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, PartialEq)]
pub enum TreeOutcome {
    /// Enumeration's basis and z. Counters: every basis screened
    /// (bases_visited = 2ⁿ), the singular ones among those confirmed.
    Decided(LcpSolution),
    Undecided(Undecided),
}

/// The screen pass: the masks of the bases that pass the screen, in
/// enumeration's order (popcount, then mask), or why the island is
/// undecided. `semidefinite`: M is symmetric positive semidefinite
/// ([`crate::prediction::is_positive_semidefinite`]), so singular pivots cut
/// their subtree (see the module docs).
pub fn screen_tree(lcp: &Lcp, semidefinite: bool, s: &TreeSettings) -> Result<Vec<u32>, Undecided> {
    let n = lcp.n();
    if n == 0 || n > TREE_TWIN_MAX_N {
        return Err(Undecided::Size);
    }
    let mut walk = Walk {
        n,
        s,
        diag: [0.0; TREE_TWIN_MAX_N],
        qabs: [0.0; TREE_TWIN_MAX_N],
        rowmax: [0.0; TREE_TWIN_MAX_N],
        semidefinite,
        tab: [0.0; SLOTS * TREE_TWIN_MAX_N * TREE_TWIN_MAX_N],
        rhs: [0.0; SLOTS * TREE_TWIN_MAX_N],
        passed: Vec::new(),
        small_pivot: false,
    };
    // Scales of the screen, in the kernel's order; slot 0 holds M and q.
    for i in 0..n {
        walk.diag[i] = lcp.m[i * n + i];
        walk.qabs[i] = lcp.q[i].abs();
        walk.rowmax[i] = lcp.m[i * n..(i + 1) * n]
            .iter()
            .fold(0.0f64, |a, v| a.max(v.abs()));
        walk.rhs[i] = lcp.q[i];
    }
    walk.tab[..n * n].copy_from_slice(&lcp.m);
    walk.node(0, 0, 0);
    if walk.small_pivot {
        return Err(Undecided::SmallPivot);
    }
    let mut passed = walk.passed;
    passed.sort_by_key(|&m| (m.count_ones(), m));
    Ok(passed)
}

/// Tableaux the walk keeps at once: one per depth on the current path.
const SLOTS: usize = TREE_TWIN_MAX_N + 1;

/// The depth-first walk's state. Tableau slot k (n×n row-major, and t) is
/// the tableau after the k-th pivot on the current path; a node's "index
/// basic" child writes slot k + 1 from slot k, so nothing is copied for the
/// "index nonbasic" child and nothing is allocated per node.
struct Walk<'a> {
    n: usize,
    s: &'a TreeSettings,
    /// M_dd, the scale of the pivot test.
    diag: [f64; TREE_TWIN_MAX_N],
    /// |q_i| and max_j |M_ij|: the screen's scale of w_i.
    qabs: [f64; TREE_TWIN_MAX_N],
    rowmax: [f64; TREE_TWIN_MAX_N],
    semidefinite: bool,
    tab: [f64; SLOTS * TREE_TWIN_MAX_N * TREE_TWIN_MAX_N],
    rhs: [f64; SLOTS * TREE_TWIN_MAX_N],
    passed: Vec<u32>,
    small_pivot: bool,
}

impl Walk<'_> {
    /// Node at depth d with basis `mask` (indices < d) and its tableau in
    /// slot `k` (only columns ≥ d are current).
    fn node(&mut self, d: usize, mask: u32, k: usize) {
        let n = self.n;
        if self.small_pivot {
            return; // undecided whatever the rest gives
        }
        let (nn, t0, r0) = (n * n, k * n * n, k * n);
        if d == n {
            if self.screen(mask, r0) {
                self.passed.push(mask);
            }
            return;
        }
        // Index d nonbasic: the same tableau.
        self.node(d + 1, mask, k);
        // Index d basic: principal pivot on T_dd (columns > d and t only),
        // into slot k + 1.
        let p = self.tab[t0 + d * n + d];
        if self.semidefinite && !(p > self.s.singular_tol * self.diag[d]) {
            return; // M_{S∪d} singular: so is every basis below.
        }
        if !(p > self.s.pivot_tol * self.diag[d]) {
            self.small_pivot = true;
            return;
        }
        let inv = 1.0 / p;
        let ninv = -inv;
        let (t1, r1) = (t0 + nn, r0 + n);
        // Row d: T'_dj = −T_dj/T_dd, t'_d = −t_d/T_dd.
        for j in d + 1..n {
            self.tab[t1 + d * n + j] = self.tab[t0 + d * n + j] * ninv;
        }
        let tr = -self.rhs[r0 + d] * inv;
        self.rhs[r1 + d] = tr;
        // Other rows: T'_ij = T_ij + T_id·T'_dj, t'_i = t_i + T_id·t'_d.
        for i in (0..n).filter(|&i| i != d) {
            let f = self.tab[t0 + i * n + d];
            for j in d + 1..n {
                self.tab[t1 + i * n + j] = self.tab[t0 + i * n + j] + f * self.tab[t1 + d * n + j];
            }
            self.rhs[r1 + i] = self.rhs[r0 + i] + f * tr;
        }
        self.node(d + 1, mask | 1 << d, k + 1);
    }

    /// The Gray-code screen on the basic solution t of `mask` (at `at` in
    /// `rhs`).
    fn screen(&self, mask: u32, at: usize) -> bool {
        let t = &self.rhs[at..at + self.n];
        let tol = self.s.screen_tol;
        let (mut zmax, mut zsum) = (0.0f64, 0.0f64);
        for (i, &v) in t.iter().enumerate() {
            if mask >> i & 1 == 1 {
                let a = v.abs();
                zmax = zmax.max(a);
                zsum += a;
            }
        }
        let mut pass = true;
        for (i, &v) in t.iter().enumerate() {
            let scale = if mask >> i & 1 == 1 {
                zmax
            } else {
                self.qabs[i] + self.rowmax[i] * zsum
            };
            pass &= v >= -tol * scale;
        }
        pass
    }
}

/// Screens every basis of `lcp` down the tree, then confirms the passing
/// ones in enumeration's order. Decided: the same basis, z and status as
/// [`crate::cpu::enumeration::enumerate`] with `s.enumeration`, provided
/// enumeration's basis passes the screen (see the module docs).
/// `semidefinite` as in [`screen_tree`].
pub fn enumerate_tree(lcp: &Lcp, semidefinite: bool, s: &TreeSettings) -> TreeOutcome {
    let passed = match screen_tree(lcp, semidefinite, s) {
        Ok(p) => p,
        Err(why) => return TreeOutcome::Undecided(why),
    };
    let mut counters = Counters {
        bases_visited: 1u64 << lcp.n(),
        ..Counters::default()
    };
    for &mask in passed.iter().take(s.max_confirmations as usize) {
        match solve_basis(lcp, mask, &s.enumeration) {
            BasisOutcome::Singular => counters.singular_bases += 1,
            BasisOutcome::Solved {
                z, feasible: true, ..
            } => {
                let mut sol = LcpSolution::from_z(lcp, Status::Solved, z, counters);
                sol.basis = Some(mask);
                return TreeOutcome::Decided(sol);
            }
            BasisOutcome::Solved { .. } => {}
        }
    }
    TreeOutcome::Undecided(Undecided::NotConfirmed)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cpu::enumeration::enumerate;
    use crate::prediction::is_positive_definite;

    #[test]
    fn decides_enumerations_basis_on_positive_definite_islands() {
        let lcps = crate::generate::families::islands_of_size(6, 400, 11);
        let s = TreeSettings::default();
        let (mut decided, mut pd) = (0, 0);
        for lcp in &lcps {
            if !is_positive_definite(lcp) {
                continue;
            }
            pd += 1;
            let e = enumerate(lcp, &s.enumeration).unwrap();
            match enumerate_tree(lcp, false, &s) {
                TreeOutcome::Decided(t) => {
                    decided += 1;
                    assert_eq!(t.basis, e.basis);
                    assert_eq!(t.z, e.z);
                    assert_eq!(t.status, e.status);
                    assert_eq!(t.counters.bases_visited, 64);
                }
                TreeOutcome::Undecided(why) => panic!("undecided ({why:?}) on a PD island"),
            }
        }
        assert!(pd > 300, "{pd} positive definite islands of 400");
        assert_eq!(decided, pd);
    }

    #[test]
    fn small_pivot_and_a_positive_definite_2x2() {
        // M_00 = 0 (not positive definite).
        let lcp = Lcp::new(
            vec![0.0, -1.0, 2.0, 2.0, 0.0, -2.0, -1.0, 1.0, 0.0],
            vec![-3.0, 6.0, -1.0],
        )
        .unwrap();
        assert_eq!(
            enumerate_tree(&lcp, false, &TreeSettings::default()),
            TreeOutcome::Undecided(Undecided::SmallPivot)
        );
        // Positive definite 2×2: z = M⁻¹(−q) = (1, 1).
        let lcp = Lcp::new(vec![2.0, 1.0, 1.0, 2.0], vec![-3.0, -3.0]).unwrap();
        let TreeOutcome::Decided(sol) = enumerate_tree(&lcp, false, &TreeSettings::default())
        else {
            panic!("undecided");
        };
        assert_eq!(sol.basis, Some(0b11));
        assert!((sol.z[0] - 1.0).abs() < 1e-15 && (sol.z[1] - 1.0).abs() < 1e-15);
        // The screen ranks bases by enumeration's order.
        let passed = screen_tree(&lcp, false, &TreeSettings::default()).unwrap();
        assert_eq!(passed, vec![0b11]);
    }

    #[test]
    fn confirmation_cap_leaves_the_island_undecided() {
        // q = 0: every basis with z_S = 0 passes the screen; the empty basis
        // is feasible and first.
        let lcp = Lcp::new(vec![2.0, 1.0, 1.0, 2.0], vec![0.0, 0.0]).unwrap();
        let passed = screen_tree(&lcp, false, &TreeSettings::default()).unwrap();
        assert_eq!(passed, vec![0b00, 0b01, 0b10, 0b11]);
        // Negative q with a cap of 0 confirmations.
        let s = TreeSettings {
            max_confirmations: 0,
            ..TreeSettings::default()
        };
        assert_eq!(
            enumerate_tree(&lcp, false, &s),
            TreeOutcome::Undecided(Undecided::NotConfirmed)
        );
    }
}
