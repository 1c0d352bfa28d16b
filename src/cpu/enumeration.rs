//! Exhaustive enumeration of the 2ⁿ complementary bases (the complementary
//! cones of Murty, *Linear Complementarity, Linear and Nonlinear
//! Programming*, 1988, ch. 1; Cottle–Pang–Stone 1992, ch. 1): the CPU twin
//! of `shaders/enumeration.wgsl`, in f64.
//!
//! A complementary basis is a set S ⊆ {0..n}: z_i is basic for i ∈ S (w_i = 0)
//! and w_i is basic for i ∉ S (z_i = 0). Then
//!
//! ```text
//! M_SS z_S = −q_S,        w_i = q_i + Σ_{j∈S} M_ij z_j   (i ∉ S)
//! ```
//!
//! and S gives a solution when z_S ≥ 0 and w ≥ 0. Bases are encoded as a u32
//! mask, bit i set when z_i is basic.
//!
//! # Which basis is chosen
//! Among all valid bases the chosen one has the fewest basic z (the fewest
//! contacts carrying impulse), ties broken by the smallest mask. Bases are
//! visited in exactly this order, so stopping at the first valid basis and
//! visiting all of them choose the same one. Valid means feasible to a strict
//! relative tolerance (1e-12); only when no basis is, the least infeasible
//! basis within a relaxed tolerance (1e-9) is chosen (then every basis has
//! been visited). A basis that rounding makes look feasible therefore never
//! wins over one that is feasible outright: near-parallel contact normals
//! (angle 1e-8) otherwise gave errors of 1e-9 where 1e-16 is reachable.
//!
//! # Tolerances (all relative, so that scaling M and q changes no verdict)
//! - Singular: a pivot below `pivot_tol` times its column's largest entry in
//!   M_SS (see [`crate::linalg::solve_in_place`]); such a basis is skipped.
//! - Feasible: z_i ≥ −tol·‖z_S‖∞ and w_i ≥ −tol·(|q_i| + Σ_j |M_ij z_j|), the
//!   second scale being the size of the terms whose cancellation gives w_i;
//!   tol is the strict or the relaxed tolerance above. The solutions counted
//!   by `all_solutions` are the bases feasible to the relaxed tolerance.

use crate::lcp::{BasisSolution, Counters, Lcp, LcpSolution, Residuals, SolutionSet, Status};
use crate::linalg::{null_space, solve_in_place, PIVOT_TOL};
use crate::short_vec::ShortVec;

/// Largest n the CPU enumerates (2²⁰ bases).
pub const MAX_ENUMERATION_N: usize = 20;

/// Settings of exhaustive enumeration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EnumerationSettings {
    /// Visit every basis and report every valid one (default false: stop at
    /// the first valid basis in the documented order).
    pub all_solutions: bool,
    /// Relative pivot tolerance for singular principal submatrices
    /// (default [`PIVOT_TOL`] = 1e-13).
    pub pivot_tol: f64,
    /// Relative feasibility tolerance of a valid basis (default 1e-12).
    pub feasibility_tol: f64,
    /// When no basis is feasible to `feasibility_tol`, the least infeasible
    /// basis is accepted if its infeasibility is at most this (default 1e-9).
    /// Such bases arise where rounding decides the sign of a w_i that is
    /// zero in exact arithmetic (degenerate or ill-conditioned islands).
    pub relaxed_feasibility_tol: f64,
}

impl Default for EnumerationSettings {
    fn default() -> Self {
        EnumerationSettings {
            all_solutions: false,
            pivot_tol: PIVOT_TOL,
            feasibility_tol: 1e-12,
            relaxed_feasibility_tol: 1e-9,
        }
    }
}

impl EnumerationSettings {
    /// Checks that the tolerances are finite and in [0, 1).
    pub fn validate(&self) -> Result<(), crate::Error> {
        for (name, v) in [
            ("pivot_tol", self.pivot_tol),
            ("feasibility_tol", self.feasibility_tol),
            ("relaxed_feasibility_tol", self.relaxed_feasibility_tol),
        ] {
            if !(0.0..1.0).contains(&v) {
                return Err(crate::Error::invalid(
                    "enumeration settings",
                    name,
                    format!("{v} is not in [0, 1)"),
                ));
            }
        }
        if self.relaxed_feasibility_tol < self.feasibility_tol {
            return Err(crate::Error::invalid(
                "enumeration settings",
                "relaxed_feasibility_tol",
                "must be at least feasibility_tol",
            ));
        }
        Ok(())
    }
}

/// What solving one basis gave.
// z and w inline (`ShortVec`) make `Solved` far larger than `Singular`;
// boxing them would allocate per basis, what `ShortVec` is there to avoid.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, PartialEq)]
pub enum BasisOutcome {
    /// M_SS is singular to the pivot tolerance.
    Singular,
    /// The basic solution (z, w with w = M z + q recomputed in full) and
    /// whether it is feasible to the strict tolerance `feasibility_tol`.
    /// `infeasibility` is the relative measure both tolerances are applied
    /// to (0 when feasible outright; any value above the relaxed tolerance
    /// stands for "more than that").
    Solved {
        z: ShortVec<f64>,
        w: ShortVec<f64>,
        feasible: bool,
        infeasibility: f64,
    },
}

thread_local! {
    /// One scratch per thread for [`solve_basis`] and [`feasible_basis_into`]:
    /// zeroing its 3.7 KB per call costs as much as the solve itself for
    /// n ≤ 8.
    static SCRATCH: std::cell::RefCell<Scratch> = std::cell::RefCell::new(Scratch::new());
}

/// Reusable buffers: nothing is allocated per basis.
struct Scratch {
    a: [f64; MAX_ENUMERATION_N * MAX_ENUMERATION_N],
    x: [f64; MAX_ENUMERATION_N],
    idx: [usize; MAX_ENUMERATION_N],
    z: [f64; MAX_ENUMERATION_N],
}

impl Scratch {
    fn new() -> Self {
        Scratch {
            a: [0.0; MAX_ENUMERATION_N * MAX_ENUMERATION_N],
            x: [0.0; MAX_ENUMERATION_N],
            idx: [0; MAX_ENUMERATION_N],
            z: [0.0; MAX_ENUMERATION_N],
        }
    }

    /// Solves basis `mask` into `self.z` (full length n, zeros off S).
    /// Returns None when M_SS is singular, else the basis' relative
    /// infeasibility (see [`infeasibility`]); 0 means feasible.
    fn solve(&mut self, lcp: &Lcp, mask: u32, s: &EnumerationSettings) -> Option<f64> {
        // Islands of n ≤ 8 are compiled for their size (the same
        // operations in the same order: the same bits).
        match lcp.n() {
            2 => self.solve_fixed::<2>(lcp, mask, s),
            3 => self.solve_fixed::<3>(lcp, mask, s),
            4 => self.solve_fixed::<4>(lcp, mask, s),
            5 => self.solve_fixed::<5>(lcp, mask, s),
            6 => self.solve_fixed::<6>(lcp, mask, s),
            7 => self.solve_fixed::<7>(lcp, mask, s),
            8 => self.solve_fixed::<8>(lcp, mask, s),
            n => self.solve_sized(n, &lcp.m, &lcp.q, mask, s),
        }
    }

    /// [`Scratch::solve`] for n = `N`.
    fn solve_fixed<const N: usize>(
        &mut self,
        lcp: &Lcp,
        mask: u32,
        s: &EnumerationSettings,
    ) -> Option<f64> {
        self.solve_sized(N, &lcp.m[..N * N], &lcp.q[..N], mask, s)
    }

    /// [`Scratch::solve`] on M (n×n) and q.
    #[inline(always)]
    fn solve_sized(
        &mut self,
        n: usize,
        m: &[f64],
        q: &[f64],
        mask: u32,
        s: &EnumerationSettings,
    ) -> Option<f64> {
        let mut k = 0;
        for i in 0..n {
            if mask >> i & 1 == 1 {
                self.idx[k] = i;
                k += 1;
            }
        }
        for (r, &i) in self.idx[..k].iter().enumerate() {
            for (c, &j) in self.idx[..k].iter().enumerate() {
                self.a[r * k + c] = m[i * n + j];
            }
            self.x[r] = -q[i];
        }
        if !solve_in_place(&mut self.a[..k * k], &mut self.x[..k], k, s.pivot_tol) {
            return None;
        }
        self.z[..n].iter_mut().for_each(|v| *v = 0.0);
        let mut zmax = 0.0f64;
        for (r, &i) in self.idx[..k].iter().enumerate() {
            self.z[i] = self.x[r];
            zmax = zmax.max(self.x[r].abs());
        }
        // Relative infeasibility: the worst of −z_i/‖z_S‖∞ and
        // −w_i/(|q_i| + Σ_j |M_ij z_j|), the second scale being the size of the
        // terms whose cancellation gives w_i.
        let mut worst = 0.0f64;
        for &v in &self.x[..k] {
            if v < 0.0 {
                worst = worst.max(-v / zmax);
            }
        }
        if worst > s.relaxed_feasibility_tol {
            return Some(worst);
        }
        for i in 0..n {
            if mask >> i & 1 == 1 {
                continue;
            }
            let (mut w, mut scale) = (q[i], q[i].abs());
            for &j in &self.idx[..k] {
                let t = m[i * n + j] * self.z[j];
                w += t;
                scale += t.abs();
            }
            if w < 0.0 {
                worst = worst.max(-w / scale);
                if worst > s.relaxed_feasibility_tol {
                    return Some(worst);
                }
            }
        }
        Some(worst)
    }
}

/// Solves one complementary basis of `lcp` and reports its z, w and
/// feasibility. This is the "polish" step of GPU validation: the GPU picks the
/// basis, f64 recomputes it. Negative z within tolerance are clamped to 0.
///
/// # Panics
/// If n > [`MAX_ENUMERATION_N`] (its scratch is fixed-size); every caller in
/// the crate checks n first (the GPU enumerates n ≤ 16, prediction and the
/// enumerations stop above 20).
pub fn solve_basis(lcp: &Lcp, mask: u32, settings: &EnumerationSettings) -> BasisOutcome {
    let n = lcp.n();
    assert!(
        n <= MAX_ENUMERATION_N,
        "solve_basis: n = {n} > {MAX_ENUMERATION_N}"
    );
    SCRATCH.with(|s| match s.try_borrow_mut() {
        Ok(mut s) => basis_outcome(&mut s, lcp, mask, settings),
        Err(_) => basis_outcome(&mut Scratch::new(), lcp, mask, settings),
    })
}

/// Basis `mask` re-solved as [`solve_basis`] does, and when it is feasible
/// (to the strict tolerance) and `keep()` says so too (asked only of a
/// feasible basis: prediction tests M's definiteness only there), the
/// solution it gives written into `out` (true): status `Solved`, z, w (the
/// same values [`solve_basis`] returns), their residuals, the basis and
/// `counters`. False, `out` untouched, when M_SS is singular, the basis
/// infeasible or not kept. The skips of the default path (prediction,
/// Lemke's checked basis) settle an island through this.
///
/// The answer is written where the caller keeps it (the default CPU path:
/// in the batch's report) and nothing is allocated for n ≤
/// [`crate::SHORT_INLINE`]: returning it by value instead moved a
/// just-written solution (z and w stored entry by entry, then copied with
/// wide loads) at each of the six calls it went up through, and each move
/// stalled on store forwarding, costing more than the arithmetic here.
pub(crate) fn feasible_basis_into(
    lcp: &Lcp,
    mask: u32,
    settings: &EnumerationSettings,
    counters: Counters,
    keep: impl FnOnce() -> bool,
    out: &mut LcpSolution,
) -> bool {
    let n = lcp.n();
    assert!(
        n <= MAX_ENUMERATION_N,
        "feasible_basis: n = {n} > {MAX_ENUMERATION_N}"
    );
    SCRATCH.with(|s| match s.try_borrow_mut() {
        Ok(mut s) => feasible_solution(&mut s, lcp, mask, settings, counters, keep, out),
        Err(_) => feasible_solution(
            &mut Scratch::new(),
            lcp,
            mask,
            settings,
            counters,
            keep,
            out,
        ),
    })
}

/// [`feasible_basis_into`] with the caller's scratch.
fn feasible_solution(
    s: &mut Scratch,
    lcp: &Lcp,
    mask: u32,
    settings: &EnumerationSettings,
    counters: Counters,
    keep: impl FnOnce() -> bool,
    out: &mut LcpSolution,
) -> bool {
    let Some(infeasibility) = s.solve(lcp, mask, settings) else {
        return false;
    };
    if !(infeasibility <= settings.feasibility_tol && keep()) {
        return false;
    }
    let n = lcp.n();
    out.z.reset(0.0, n);
    for (zi, &v) in out.z.iter_mut().zip(&s.z[..n]) {
        *zi = v.max(0.0);
    }
    out.w.reset(0.0, n);
    lcp.w_into(&out.z, &mut out.w);
    out.residuals = Residuals::of(&out.z, &out.w, &lcp.q);
    solved_on_basis(mask, counters, out);
    true
}

/// `out`, whose z, w and residuals are written, marked as the answer of
/// basis `mask`: status `Solved`, the basis, `counters`, no solution set.
/// [`feasible_basis_into`]'s tail, and the GPU check's where it keeps the
/// GPU's z (`crate::gpu::validation::accept_gpu_z`).
pub(crate) fn solved_on_basis(mask: u32, counters: Counters, out: &mut LcpSolution) {
    out.status = Status::Solved;
    out.counters = counters;
    out.basis = Some(mask);
    out.all_bases.clear();
    out.solution_set = None;
}

/// The scratch's z of the last solve, negative entries clamped to 0.
fn clamped_z(s: &Scratch, n: usize) -> ShortVec<f64> {
    s.z[..n].iter().map(|v| v.max(0.0)).collect()
}

/// [`solve_basis`] with the caller's scratch.
fn basis_outcome(
    s: &mut Scratch,
    lcp: &Lcp,
    mask: u32,
    settings: &EnumerationSettings,
) -> BasisOutcome {
    let n = lcp.n();
    match s.solve(lcp, mask, settings) {
        None => BasisOutcome::Singular,
        Some(infeasibility) => {
            let feasible = infeasibility <= settings.feasibility_tol;
            let z = clamped_z(s, n);
            let w = lcp.w(&z);
            BasisOutcome::Solved {
                z,
                w,
                feasible,
                infeasibility,
            }
        }
    }
}

/// Visits subsets of {0..n} by increasing size, each size in increasing
/// numeric order (Gosper's hack), calling `f` until it returns false.
fn for_each_basis_in_order(n: usize, mut f: impl FnMut(u32) -> bool) {
    let full: u64 = 1u64 << n;
    for k in 0..=n {
        if k == 0 {
            if !f(0) {
                return;
            }
            continue;
        }
        let mut s: u64 = (1u64 << k) - 1;
        while s < full {
            if !f(s as u32) {
                return;
            }
            // Next larger integer with the same number of set bits.
            let c = s & s.wrapping_neg();
            let r = s + c;
            s = (((r ^ s) >> 2) / c) | r;
        }
    }
}

/// Solves `lcp` by exhaustive enumeration of its complementary bases.
///
/// Errors only when n exceeds [`MAX_ENUMERATION_N`] or the settings are out
/// of range; every other outcome is a [`Status`]: `Solved` (one valid basis
/// chosen; when `all_solutions`, the solution is also the only one),
/// `MultipleSolutions` (all_solutions only), `NoSolution` (no basis is
/// feasible and nonsingular).
pub fn enumerate(lcp: &Lcp, settings: &EnumerationSettings) -> Result<LcpSolution, crate::Error> {
    settings.validate()?;
    let n = lcp.n();
    if n > MAX_ENUMERATION_N {
        return Err(crate::Error::Unsupported(format!(
            "enumeration visits 2^n bases and is limited to n ≤ {MAX_ENUMERATION_N} (this problem has n = {n}); use Lemke"
        )));
    }
    Ok(decide(lcp, settings, |visit| {
        for_each_basis_in_order(n, visit)
    }))
}

/// [`enumerate`] over the bases a screen left (the GPU's
/// `shaders/enumeration_all.wgsl`, which solved every basis): `candidates`
/// are re-solved in f64 in enumeration's order and decided exactly as
/// [`enumerate`] decides, which gives its answer whenever they include every
/// basis feasible to the relaxed tolerance in f64. `trusted_singular`: bases
/// the screen found singular with the twin's own arithmetic (f64), counted
/// and not re-solved. Counters: every basis visited.
pub fn enumerate_screened(
    lcp: &Lcp,
    settings: &EnumerationSettings,
    candidates: &mut [u32],
    trusted_singular: u64,
) -> Result<LcpSolution, crate::Error> {
    settings.validate()?;
    let n = lcp.n();
    if n > MAX_ENUMERATION_N || candidates.iter().any(|&m| m >> n != 0) {
        return Err(crate::Error::Unsupported(format!(
            "screened enumeration: a basis outside 2^{n} or n > {MAX_ENUMERATION_N}"
        )));
    }
    candidates.sort_unstable_by_key(|&m| (m.count_ones(), m));
    let mut sol = decide(lcp, settings, |visit| {
        for &m in candidates.iter() {
            if !visit(m) {
                return;
            }
        }
    });
    sol.counters.bases_visited = 1u64 << n;
    sol.counters.singular_bases += trusted_singular;
    Ok(sol)
}

/// The decision of enumeration over the bases `bases` hands to its visitor,
/// in enumeration's order (by size, then mask); the visitor returns false
/// to stop (at the first valid basis unless `all_solutions`).
fn decide(
    lcp: &Lcp,
    settings: &EnumerationSettings,
    bases: impl FnOnce(&mut dyn FnMut(u32) -> bool),
) -> LcpSolution {
    let n = lcp.n();
    let mut scratch = Scratch::new();
    let mut counters = Counters::default();
    // The first basis feasible to the strict tolerance, else the least
    // infeasible one within the relaxed tolerance (first in order on a tie).
    let mut chosen: Option<u32> = None;
    let mut least: Option<(f64, u32)> = None;
    let mut all = Vec::new();
    bases(&mut |mask| {
        counters.bases_visited += 1;
        let Some(infeasibility) = scratch.solve(lcp, mask, settings) else {
            counters.singular_bases += 1;
            return true;
        };
        if infeasibility > settings.relaxed_feasibility_tol {
            return true;
        }
        if infeasibility <= settings.feasibility_tol && chosen.is_none() {
            chosen = Some(mask);
            if !settings.all_solutions {
                return false;
            }
        }
        if least.is_none_or(|(v, _)| infeasibility < v) {
            least = Some((infeasibility, mask));
        }
        if settings.all_solutions {
            let z = clamped_z(&scratch, n);
            let w = lcp.w(&z);
            all.push(BasisSolution {
                basis: mask,
                z: z.into_vec(),
                w: w.into_vec(),
            });
        }
        true
    });
    let Some(basis) = chosen.or(least.map(|(_, mask)| mask)) else {
        let mut sol = LcpSolution::from_z(lcp, Status::NoSolution, vec![0.0; n], counters);
        if settings.all_solutions {
            sol.solution_set = Some(SolutionSet::Empty);
        }
        return sol;
    };
    let BasisOutcome::Solved { z, .. } = solve_basis(lcp, basis, settings) else {
        unreachable!("a basis found nonsingular is nonsingular again")
    };
    let mut sol = LcpSolution::from_z(lcp, Status::Solved, z, counters);
    sol.basis = Some(basis);
    if settings.all_solutions {
        let set = classify_solution_set(lcp, &all, settings);
        if set != (SolutionSet::Isolated { count: 1 }) {
            sol.status = Status::MultipleSolutions;
        }
        sol.solution_set = Some(set);
        sol.all_bases = all;
    }
    sol
}

/// Two solutions are the same point when they agree to a relative 1e-8.
fn same_point(a: &[f64], b: &[f64]) -> bool {
    let scale = a.iter().chain(b).fold(0.0f64, |m, v| m.max(v.abs()));
    a.iter()
        .zip(b)
        .all(|(x, y)| (x - y).abs() <= 1e-8 * scale.max(f64::MIN_POSITIVE))
}

/// Distinct solutions among the valid bases.
pub fn distinct_solutions(all: &[BasisSolution]) -> Vec<&BasisSolution> {
    let mut out: Vec<&BasisSolution> = Vec::new();
    for b in all {
        if !out.iter().any(|o| same_point(&o.z, &b.z)) {
            out.push(b);
        }
    }
    out
}

/// Is z a solution of `lcp` to the feasibility tolerance?
fn is_solution(lcp: &Lcp, z: &[f64], tol: f64) -> bool {
    let n = lcp.n();
    let zmax = z.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    (0..n).all(|i| {
        let (mut w, mut scale) = (lcp.q[i], lcp.q[i].abs());
        for j in 0..n {
            let t = lcp.at(i, j) * z[j];
            w += t;
            scale += t.abs();
        }
        z[i] >= -tol * zmax
            && w >= -tol * scale
            && (z[i].abs() <= tol * zmax.max(f64::MIN_POSITIVE)
                || w.abs() <= tol * scale.max(f64::MIN_POSITIVE))
    })
}

/// Tells isolated solutions from a continuum.
///
/// - Two distinct solutions whose midpoint also solves the LCP span a segment
///   of solutions (a bounded continuum, unless a ray is found too).
/// - For a solution z* and a set S with supp(z*) ⊆ S ⊆ {i : w*_i = 0} whose
///   M_SS is singular, a kernel direction d of M_SS keeps w_S = 0 along
///   z* + t d; if d (or −d) keeps z ≥ 0 and w ≥ 0 for small t > 0 there is a
///   continuum, unbounded when nothing ever stops it (d ≥ 0 and (M d)_i ≥ 0
///   off S).
// Long (about 90 lines) on purpose: the four cases of the solution set
// (empty, isolated, bounded or unbounded continuum) read top to bottom.
fn classify_solution_set(lcp: &Lcp, all: &[BasisSolution], s: &EnumerationSettings) -> SolutionSet {
    let n = lcp.n();
    let distinct = distinct_solutions(all);
    let tol = s.feasibility_tol.max(1e-12);
    let mut bounded = false;
    for (i, a) in distinct.iter().enumerate() {
        for b in &distinct[i + 1..] {
            let mid: Vec<f64> = a.z.iter().zip(&b.z).map(|(x, y)| 0.5 * (x + y)).collect();
            if is_solution(lcp, &mid, tol) {
                bounded = true;
            }
        }
    }
    for sol in &distinct {
        let zmax = sol
            .z
            .iter()
            .fold(0.0f64, |m, v| m.max(v.abs()))
            .max(f64::MIN_POSITIVE);
        let wscale: Vec<f64> = (0..n)
            .map(|i| lcp.q[i].abs() + (0..n).map(|j| (lcp.at(i, j) * sol.z[j]).abs()).sum::<f64>())
            .collect();
        let zero_z = |i: usize| sol.z[i].abs() <= tol * zmax;
        let zero_w = |i: usize| sol.w[i].abs() <= tol * wscale[i].max(f64::MIN_POSITIVE);
        let must: u32 = (0..n).filter(|&i| !zero_z(i)).fold(0, |m, i| m | 1 << i);
        let may: u32 = (0..n).filter(|&i| zero_w(i)).fold(0, |m, i| m | 1 << i);
        if must & !may != 0 {
            continue;
        }
        let free = may & !must;
        // Every S between `must` and `may`: subsets of `free` added to `must`.
        let mut sub = free;
        loop {
            let set = must | sub;
            let idx: Vec<usize> = (0..n).filter(|&i| set >> i & 1 == 1).collect();
            let k = idx.len();
            if k > 0 {
                let a: Vec<f64> = idx
                    .iter()
                    .flat_map(|&i| idx.iter().map(move |&j| lcp.at(i, j)))
                    .collect();
                for d_s in null_space(&a, k, s.pivot_tol) {
                    let mut d = vec![0.0; n];
                    for (r, &i) in idx.iter().enumerate() {
                        d[i] = d_s[r];
                    }
                    let md: Vec<f64> = (0..n)
                        .map(|i| (0..n).map(|j| lcp.at(i, j) * d[j]).sum())
                        .collect();
                    let mscale = lcp.m.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                    for sign in [1.0, -1.0] {
                        let dz = |i: usize| sign * d[i];
                        let dw = |i: usize| sign * md[i];
                        let eps = 1e-10;
                        // Directions allowed at t = 0+.
                        let ok = (0..n).all(|i| {
                            if set >> i & 1 == 1 {
                                !zero_z(i) || dz(i) >= -eps
                            } else {
                                !zero_w(i) || dw(i) >= -eps * mscale
                            }
                        });
                        if ok {
                            let unbounded = (0..n).all(|i| {
                                if set >> i & 1 == 1 {
                                    dz(i) >= -eps
                                } else {
                                    dw(i) >= -eps * mscale
                                }
                            });
                            if unbounded {
                                return SolutionSet::UnboundedContinuum;
                            }
                            bounded = true;
                        }
                    }
                }
            }
            if sub == 0 {
                break;
            }
            sub = (sub - 1) & free;
        }
    }
    if bounded {
        SolutionSet::BoundedContinuum
    } else {
        SolutionSet::Isolated {
            count: distinct.len(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn order_is_by_size_then_mask() {
        let mut v = Vec::new();
        for_each_basis_in_order(3, |m| {
            v.push(m);
            true
        });
        assert_eq!(v, vec![0, 1, 2, 4, 3, 5, 6, 7]);
    }

    #[test]
    fn seed_000_two_by_two() {
        let lcp = Lcp::new(vec![2.0, 1.0, 1.0, 2.0], vec![-5.0, -6.0]).unwrap();
        let sol = enumerate(&lcp, &EnumerationSettings::default()).unwrap();
        assert_eq!(sol.status, Status::Solved);
        assert_eq!(sol.basis, Some(0b11));
        assert!((sol.z[0] - 4.0 / 3.0).abs() < 1e-14 && (sol.z[1] - 7.0 / 3.0).abs() < 1e-14);
    }
}
