//! Prediction: settle an island without enumeration when it does not need
//! it. Runs on the CPU between assembly and enumeration, for the CPU and the
//! GPU path alike, and costs O(n³) at most per island.
//!
//! In order:
//! 1. Separating: every contact separates (q ≥ 0): z = 0, the empty basis.
//! 2. Single contact: z = max(0, −q/M) in closed form.
//! 3. Warm start: the basis the caller carried over from the previous frame,
//!    re-solved; kept when it is feasible to the strict tolerance.
//! 4. Predicted basis {i : q_i < 0} (the approaching contacts), kept when it
//!    is feasible and M is positive definite: then the LCP has exactly one
//!    solution, so any feasible basis gives enumeration's z.
//!
//! Cases 1 and 2 return exactly what enumeration returns (they are its first
//! bases). Case 4 returns enumeration's z and w; its basis can differ from
//! enumeration's only where the solution is degenerate (a basic z_i = 0 or a
//! nonbasic w_i = 0). Case 3 keeps last frame's basis while it stays valid:
//! re-solving the same island gives enumeration's result exactly, and for a
//! changed island a valid solution that may differ from enumeration's choice
//! when the solution is not unique (w is the same whenever M is positive
//! semidefinite).

use crate::cpu::enumeration::{feasible_basis_into, EnumerationSettings, MAX_ENUMERATION_N};
use crate::lcp::{Counters, Lcp, LcpSolution, Status};
use crate::report::SolvePath;

/// Is the symmetric part of M positive definite? Cholesky of (M + Mᵀ)/2 with
/// a pivot threshold of n·ε times the largest diagonal entry: a matrix
/// singular to working precision (a box resting on 4 coplanar contacts)
/// answers false. Only symmetric M are tested (contact islands are); a
/// non-symmetric M answers false.
pub fn is_positive_definite(lcp: &Lcp) -> bool {
    let n = lcp.n();
    if n > MAX_ENUMERATION_N || !lcp.is_symmetric() {
        return false;
    }
    // The factor lives on the stack, no larger than n needs: zeroing 20×20
    // entries for a 4×4 island would cost more than the factorisation.
    // n ≤ 6 is compiled for its size (the same operations in the same
    // order: the same verdict).
    match n {
        2 => cholesky_fixed::<2, 4>(&lcp.m),
        3 => cholesky_fixed::<3, 9>(&lcp.m),
        4 => cholesky_fixed::<4, 16>(&lcp.m),
        5 => cholesky_fixed::<5, 25>(&lcp.m),
        6 => cholesky_fixed::<6, 36>(&lcp.m),
        0..=4 => cholesky_succeeds::<16>(lcp),
        5..=8 => cholesky_succeeds::<64>(lcp),
        9..=12 => cholesky_succeeds::<144>(lcp),
        _ => cholesky_succeeds::<{ MAX_ENUMERATION_N * MAX_ENUMERATION_N }>(lcp),
    }
}

/// [`cholesky_succeeds`] for n = `N` (`L` = N² entries of the factor), on
/// M's entries `m`.
fn cholesky_fixed<const N: usize, const L: usize>(m: &[f64]) -> bool {
    let m = &m[..N * N];
    let mut l = [0.0f64; L];
    let dmax = (0..N).map(|i| m[i * N + i]).fold(0.0f64, f64::max);
    let threshold = N as f64 * f64::EPSILON * 16.0 * dmax;
    for j in 0..N {
        let mut d = m[j * N + j];
        for k in 0..j {
            d -= l[j * N + k] * l[j * N + k];
        }
        if !(d > threshold) {
            return false;
        }
        let d = d.sqrt();
        l[j * N + j] = d;
        for i in j + 1..N {
            let mut s = 0.5 * (m[i * N + j] + m[j * N + i]);
            for k in 0..j {
                s -= l[i * N + k] * l[j * N + k];
            }
            l[i * N + j] = s / d;
        }
    }
    true
}

/// The Cholesky factorisation of [`is_positive_definite`], with an L of
/// `N` ≥ n² entries.
fn cholesky_succeeds<const N: usize>(lcp: &Lcp) -> bool {
    let n = lcp.n();
    let mut l = [0.0f64; N];
    let dmax = (0..n).map(|i| lcp.at(i, i)).fold(0.0f64, f64::max);
    let threshold = n as f64 * f64::EPSILON * 16.0 * dmax;
    for j in 0..n {
        let mut d = lcp.at(j, j);
        for k in 0..j {
            d -= l[j * n + k] * l[j * n + k];
        }
        if !(d > threshold) {
            return false;
        }
        let d = d.sqrt();
        l[j * n + j] = d;
        for i in j + 1..n {
            let mut s = 0.5 * (lcp.at(i, j) + lcp.at(j, i));
            for k in 0..j {
                s -= l[i * n + k] * l[j * n + k];
            }
            l[i * n + j] = s / d;
        }
    }
    true
}

/// Is M symmetric positive semidefinite? Cholesky with diagonal pivoting:
/// the largest remaining diagonal entry is eliminated first, and once it is
/// at most 1e-9 times the largest diagonal entry of M, every remaining entry
/// must be that small too (a PSD matrix with a zero diagonal entry has a
/// zero row). A box resting on 4 coplanar contacts answers true; a matrix
/// with a negative direction, or a non-symmetric one, false. O(n³).
pub fn is_positive_semidefinite(lcp: &Lcp) -> bool {
    let n = lcp.n();
    if n > MAX_ENUMERATION_N || !lcp.is_symmetric() {
        return false;
    }
    // On the stack, no larger than n needs (the GPU path tests every
    // island it sends to the tree kernel: nothing allocated per island).
    match n {
        0..=4 => semidefinite_on_stack::<16>(lcp),
        5..=8 => semidefinite_on_stack::<64>(lcp),
        9..=12 => semidefinite_on_stack::<144>(lcp),
        _ => semidefinite_on_stack::<{ MAX_ENUMERATION_N * MAX_ENUMERATION_N }>(lcp),
    }
}

/// [`is_positive_semidefinite`] on an `N` ≥ n² array: the indices left in
/// an array of their own, removed as `Vec::swap_remove` would (the same
/// order, the same pivots, the same verdict).
fn semidefinite_on_stack<const N: usize>(lcp: &Lcp) -> bool {
    let n = lcp.n();
    let mut a = [0.0f64; N];
    for i in 0..n {
        for j in 0..n {
            a[i * n + j] = 0.5 * (lcp.at(i, j) + lcp.at(j, i));
        }
    }
    let dmax = (0..n).map(|i| a[i * n + i]).fold(0.0f64, f64::max);
    let tol = 1e-9 * dmax;
    let mut all = [0usize; MAX_ENUMERATION_N];
    for (i, v) in all.iter_mut().enumerate().take(n) {
        *v = i;
    }
    let mut len = n;
    while len > 0 {
        let left = &all[..len];
        let (k, &p) = left
            .iter()
            .enumerate()
            .max_by(|x, y| a[x.1 * n + x.1].total_cmp(&a[y.1 * n + y.1]))
            .expect("not empty");
        let d = a[p * n + p];
        if !(d > tol) {
            // The rest must vanish (this includes d < −tol: not PSD).
            return left
                .iter()
                .all(|&i| left.iter().all(|&j| a[i * n + j].abs() <= tol));
        }
        all[k] = all[len - 1];
        len -= 1;
        let left = &all[..len];
        // Schur complement on the remaining indices.
        for &i in left {
            let f = a[i * n + p] / d;
            for &j in left {
                a[i * n + j] -= f * a[p * n + j];
            }
        }
    }
    true
}

/// Tries the cheap paths on one island (the tests' form of
/// [`predict_into`]). `warm_basis` is the caller's basis from the previous
/// frame, if any. None: the island needs enumeration.
///
/// The same answers as [`prediction_into`]; since nothing learnt is
/// returned, step 4 tests M's definiteness only where the predicted basis
/// is feasible (the CPU path's order: the Cholesky test is the dearer of
/// the two at n ≤ 8, and the basis is infeasible on a third of the islands).
#[cfg(test)]
pub fn predict(
    lcp: &Lcp,
    warm_basis: Option<u32>,
    settings: &EnumerationSettings,
) -> Option<(SolvePath, LcpSolution)> {
    let (mut path, mut out) = (SolvePath::Separating, LcpSolution::invalid(0));
    predict_into(lcp, warm_basis, settings, &mut path, &mut out).then_some((path, out))
}

/// One island settled by prediction where it can be: its solution written
/// into `out` (true), where the CPU path's report holds it (see
/// [`feasible_basis_into`]), the step that gave it in `path`; false, `out`
/// untouched (`path` then says nothing), when the island needs more than
/// prediction.
pub(crate) fn predict_into(
    lcp: &Lcp,
    warm_basis: Option<u32>,
    settings: &EnumerationSettings,
    path: &mut SolvePath,
    out: &mut LcpSolution,
) -> bool {
    steps(lcp, warm_basis, settings, path, None, out)
}

/// [`predict_into`], keeping what it learnt of an island it could not
/// settle: `Err` with whether M is positive definite (its step 4, which the
/// GPU's choice of enumeration kernel needs too; None when the step did not
/// run), `out` untouched.
pub(crate) fn prediction_into(
    lcp: &Lcp,
    warm_basis: Option<u32>,
    settings: &EnumerationSettings,
    path: &mut SolvePath,
    out: &mut LcpSolution,
) -> Result<(), Option<bool>> {
    let mut definite = None;
    match steps(lcp, warm_basis, settings, path, Some(&mut definite), out) {
        true => Ok(()),
        false => Err(definite),
    }
}

/// The steps of [`prediction_into`]: whether one settled the island, its
/// solution written into `out` and in `path` the step that gave it (`out`
/// untouched when none did). With `learn`, M's definiteness is tested on
/// every island that reaches step 4 and written there; without, only
/// where the predicted basis is feasible.
fn steps(
    lcp: &Lcp,
    warm_basis: Option<u32>,
    settings: &EnumerationSettings,
    path: &mut SolvePath,
    learn: Option<&mut Option<bool>>,
    out: &mut LcpSolution,
) -> bool {
    if lcp.n() > MAX_ENUMERATION_N {
        return false;
    }
    if closed_form_into(lcp, settings, path, out) {
        return true;
    }
    // 3. Last frame's basis.
    if let Some(mask) = warm_basis.filter(|&m| m >> lcp.n() == 0) {
        if feasible_basis_into(lcp, mask, settings, counters(1), || true, out) {
            *path = SolvePath::WarmStart;
            return true;
        }
    }
    // 4. The approaching contacts, when the solution is unique.
    let approaching = approaching(lcp);
    *path = SolvePath::PredictedBasis;
    let Some(definite) = learn else {
        return feasible_basis_into(
            lcp,
            approaching,
            settings,
            counters(1),
            || is_positive_definite(lcp),
            out,
        );
    };
    *definite = Some(is_positive_definite(lcp));
    *definite == Some(true)
        && feasible_basis_into(lcp, approaching, settings, counters(1), || true, out)
}

/// Counters of an island prediction settles after visiting `bases` bases.
fn counters(bases: u64) -> Counters {
    Counters {
        bases_visited: bases,
        ..Counters::default()
    }
}

/// The predicted basis: the approaching contacts {i : q_i < 0}.
fn approaching(lcp: &Lcp) -> u32 {
    (0..lcp.n())
        .filter(|&i| lcp.q[i] < 0.0)
        .fold(0u32, |m, i| m | 1 << i)
}

/// Steps 1 and 2 of [`prediction_into`] (no linear solve: the empty basis,
/// one contact in closed form): whether one settled the island, as
/// [`steps`] says it.
fn closed_form_into(
    lcp: &Lcp,
    settings: &EnumerationSettings,
    path: &mut SolvePath,
    out: &mut LcpSolution,
) -> bool {
    // 1. Separating: the empty basis, feasible iff q ≥ 0.
    if lcp.q.iter().all(|&v| v >= 0.0) {
        *path = SolvePath::Separating;
        return feasible_basis_into(lcp, 0, settings, counters(1), || true, out);
    }
    // 2. One approaching contact: z = −q/M when M > 0, else no solution.
    if lcp.n() == 1 {
        *path = SolvePath::SingleContact;
        if !feasible_basis_into(lcp, 1, settings, counters(2), || true, out) {
            *out = LcpSolution::from_z(lcp, Status::NoSolution, [0.0], counters(2));
        }
        return true;
    }
    false
}

/// What [`prediction_hint_into`] leaves to the device: the bases its steps
/// 3 and 4 would solve, for the GPU to try in that order.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Hint {
    /// Whether M is positive definite (tested on every island left of
    /// n ≤ 20; None above).
    pub definite: Option<bool>,
    /// The warm basis (0: none; an empty basis settles no island that is
    /// not separating).
    pub warm: u32,
    /// The predicted basis where M is positive definite, else 0.
    pub predicted: u32,
}

/// [`prediction_into`] with steps 3 and 4 (a linear solve each) left to
/// the device: steps 1 and 2 settle the island on the host (`Ok`, as
/// there), else `Err` with the bases the GPU tries in order (the CPU
/// path's answer whenever one is valid there: [`hinted_into`] is the host's
/// twin). M's definiteness is tested on every island left, as
/// [`prediction_into`] tests it on every island reaching step 4, except
/// where the warm basis is the predicted one (step 4 would repeat step 3).
pub(crate) fn prediction_hint_into(
    lcp: &Lcp,
    warm_basis: Option<u32>,
    settings: &EnumerationSettings,
    path: &mut SolvePath,
    out: &mut LcpSolution,
) -> Result<(), Hint> {
    let n = lcp.n();
    if closed_form_into(lcp, settings, path, out) {
        return Ok(());
    }
    let warm = warm_basis.filter(|&m| m >> n == 0).unwrap_or(0);
    let predicted = approaching(lcp);
    if warm == predicted {
        // Step 4 would try the basis step 3 tried, in the same precision:
        // it cannot succeed where that failed, so M's definiteness (a
        // Cholesky) is left to the routes that need it.
        return Err(Hint {
            definite: None,
            warm,
            predicted: 0,
        });
    }
    let definite = is_positive_definite(lcp);
    Err(Hint {
        definite: Some(definite),
        warm,
        predicted: if definite { predicted } else { 0 },
    })
}

/// Steps 3 and 4 on the host, from the bases a [`Hint`] names (`warm`,
/// then `predicted`; 0: none): the step that settled the island, its
/// solution in `out`, or None (`out` untouched). The CPU path's answer for
/// an island whose hint [`prediction_hint_into`] gave.
pub(crate) fn hinted_into(
    lcp: &Lcp,
    (warm, predicted): (u32, u32),
    settings: &EnumerationSettings,
    out: &mut LcpSolution,
) -> Option<SolvePath> {
    let n = lcp.n();
    [
        (warm, SolvePath::WarmStart),
        (predicted, SolvePath::PredictedBasis),
    ]
    .into_iter()
    .find(|&(mask, _)| {
        mask != 0
            && mask >> n == 0
            && feasible_basis_into(lcp, mask, settings, counters(1), || true, out)
    })
    .map(|(_, path)| path)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cpu::enumeration::enumerate;

    #[test]
    fn semidefinite_test() {
        let psd = |m: Vec<f64>| is_positive_semidefinite(&Lcp::new(m, vec![0.0; 2]).unwrap());
        assert!(psd(vec![2.0, 1.0, 1.0, 2.0]));
        assert!(psd(vec![1.0, 1.0, 1.0, 1.0])); // rank one
        assert!(psd(vec![0.0, 0.0, 0.0, 1.0]));
        assert!(!psd(vec![1.0, 2.0, 2.0, 1.0])); // eigenvalue −1
        assert!(!psd(vec![0.0, 1.0, 1.0, 1.0])); // zero diagonal, nonzero row
        assert!(!psd(vec![1.0, 0.5, -0.5, 1.0])); // not symmetric
                                                  // A box resting on 4 coplanar contacts: rank 3 of 4.
        let scene = crate::generate::box_on_ground(1.0, 0.5);
        let lcps = crate::tests::reference::build(&scene, "scene").unwrap().2;
        assert!(lcps
            .iter()
            .all(|l| is_positive_semidefinite(l) && !is_positive_definite(l)));
    }

    #[test]
    fn cheap_paths_agree_with_enumeration() {
        let settings = EnumerationSettings::default();
        let cases = [
            (
                vec![2.0, 1.0, 1.0, 2.0],
                vec![-5.0, -6.0],
                Some(SolvePath::PredictedBasis),
            ),
            (
                vec![2.0, 1.0, 1.0, 2.0],
                vec![5.0, 0.0],
                Some(SolvePath::Separating),
            ),
            (
                vec![2.0, 1.0, 1.0, 2.0],
                vec![-1.0, 4.0],
                Some(SolvePath::PredictedBasis),
            ),
            // Rank one: not positive definite, enumeration needed.
            (vec![1.0, 1.0, 1.0, 1.0], vec![-1.0, -1.0], None),
            (vec![3.0], vec![-6.0], Some(SolvePath::SingleContact)),
            (vec![-3.0], vec![-6.0], Some(SolvePath::SingleContact)),
        ];
        for (m, q, path) in cases {
            let lcp = Lcp::new(m, q).unwrap();
            let predicted = predict(&lcp, None, &settings);
            assert_eq!(predicted.as_ref().map(|p| p.0), path, "{lcp:?}");
            if let Some((_, sol)) = predicted {
                let e = enumerate(&lcp, &settings).unwrap();
                assert_eq!(sol.status, e.status);
                assert_eq!(sol.z, e.z);
                assert_eq!(sol.basis, e.basis);
            }
        }
    }

    #[test]
    fn warm_start_is_kept_only_while_valid() {
        let settings = EnumerationSettings::default();
        // Rank one M, solutions z1 + z2 = 1: the warm basis {1} is valid.
        let lcp = Lcp::new(vec![1.0, 1.0, 1.0, 1.0], vec![-1.0, -1.0]).unwrap();
        let (path, sol) = predict(&lcp, Some(0b10), &settings).unwrap();
        assert_eq!(path, SolvePath::WarmStart);
        assert_eq!(sol.z, vec![0.0, 1.0]);
        // An infeasible warm basis falls through to enumeration.
        let lcp = Lcp::new(vec![1.0, 1.0, 1.0, 1.0], vec![-1.0, 2.0]).unwrap();
        assert!(predict(&lcp, Some(0b10), &settings).is_none());
    }
}
