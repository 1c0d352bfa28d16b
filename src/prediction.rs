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

// `WarmStart`'s counters serve the tests.
#![cfg_attr(not(test), allow(dead_code))]

use std::collections::HashMap;
use std::hash::{BuildHasher, Hasher, RandomState};

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
    let mut a = [0.0f64; MAX_ENUMERATION_N * MAX_ENUMERATION_N];
    for i in 0..n {
        for j in 0..n {
            a[i * n + j] = 0.5 * (lcp.at(i, j) + lcp.at(j, i));
        }
    }
    let dmax = (0..n).map(|i| a[i * n + i]).fold(0.0f64, f64::max);
    let tol = 1e-9 * dmax;
    let mut left: Vec<usize> = (0..n).collect();
    while !left.is_empty() {
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
        left.swap_remove(k);
        // Schur complement on the remaining indices.
        for &i in &left {
            let f = a[i * n + p] / d;
            for &j in &left {
                a[i * n + j] -= f * a[p * n + j];
            }
        }
    }
    true
}

/// Tries the cheap paths on one island. `warm_basis` is the caller's basis
/// from the previous frame, if any. None: the island needs enumeration.
///
/// The same answers as [`prediction`]; since nothing learnt is returned,
/// step 4 tests M's definiteness only where the predicted basis is
/// feasible (the CPU path's order: the Cholesky test is the dearer of the
/// two at n ≤ 8, and the basis is infeasible on a third of the islands).
pub fn predict(
    lcp: &Lcp,
    warm_basis: Option<u32>,
    settings: &EnumerationSettings,
) -> Option<(SolvePath, LcpSolution)> {
    let mut path = SolvePath::Separating;
    predict_solution(lcp, warm_basis, settings, &mut path).map(|s| (path, s))
}

/// [`predict`] with the path written to `path` (the CPU path's form: the
/// solution is returned as built, not moved into a pair).
pub fn predict_solution(
    lcp: &Lcp,
    warm_basis: Option<u32>,
    settings: &EnumerationSettings,
    path: &mut SolvePath,
) -> Option<LcpSolution> {
    let mut out = LcpSolution::invalid(0);
    steps(lcp, warm_basis, settings, path, None, &mut out).then_some(out)
}

/// [`predict_solution`] written into `out` (true), where the CPU path's
/// report holds it (see [`feasible_basis_into`]); false, `out` untouched,
/// when the island needs more than prediction.
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
    let n = lcp.n();
    if n > MAX_ENUMERATION_N {
        return false;
    }
    let counters = |bases: u64| Counters {
        bases_visited: bases,
        ..Counters::default()
    };
    // 1. Separating: the empty basis, feasible iff q ≥ 0.
    if lcp.q.iter().all(|&v| v >= 0.0) {
        *path = SolvePath::Separating;
        return feasible_basis_into(lcp, 0, settings, counters(1), || true, out);
    }
    // 2. One approaching contact: z = −q/M when M > 0, else no solution.
    if n == 1 {
        *path = SolvePath::SingleContact;
        if !feasible_basis_into(lcp, 1, settings, counters(2), || true, out) {
            *out = LcpSolution::from_z(lcp, Status::NoSolution, [0.0], counters(2));
        }
        return true;
    }
    // 3. Last frame's basis.
    if let Some(mask) = warm_basis.filter(|&m| m >> n == 0) {
        if feasible_basis_into(lcp, mask, settings, counters(1), || true, out) {
            *path = SolvePath::WarmStart;
            return true;
        }
    }
    // 4. The approaching contacts, when the solution is unique.
    let approaching = (0..n)
        .filter(|&i| lcp.q[i] < 0.0)
        .fold(0u32, |m, i| m | 1 << i);
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
    fn records_on_several_threads_are_the_records_of_one() {
        // 3,000 islands of 4 ids (above the parallel threshold); every id
        // also appears in a later island, whose basis must win as on one
        // thread, and some ids are never recorded.
        let ids: Vec<Vec<u64>> = (0..3000u64)
            .map(|i| (0..4).map(|k| (i * 4 + k) % 10_000).collect())
            .collect();
        let records: Vec<(&[u64], u32)> = ids
            .iter()
            .enumerate()
            .map(|(i, k)| (k.as_slice(), (i as u32 * 7) % 16))
            .collect();
        let mut one = WarmStart::default();
        for &(k, basis) in &records {
            one.record(k, basis);
        }
        for threads in [2, 3, 16, 64] {
            let mut many = WarmStart::default();
            many.record_all(&records, threads);
            for k in &ids {
                assert_eq!(many.basis(k), one.basis(k), "{threads} threads, ids {k:?}");
            }
            assert_eq!(many.basis(&[10_001, 10_002]), None);
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

/// Last frame's active contacts, keyed by contact ids the caller supplies
/// (stable across frames, e.g. a feature pair from collision detection).
/// An island's warm basis is the set of its contacts that carried impulse
/// last frame; islands none of whose contacts were seen get none.
///
/// The ids are spread over [`SHARDS`] maps by a hash of the id, so that a
/// batch's records can be written on several threads, one shard each at a
/// time, every shard in the batch's order ([`WarmStart::record_all`]);
/// the maps hash an id by one seeded multiplication ([`IdHasher`]).
#[derive(Clone, Debug)]
pub struct WarmStart {
    shards: Vec<HashMap<u64, bool, IdHash>>,
    /// Picks an id's shard (independent of the maps' own hash).
    seed: u64,
}

/// Shards of [`WarmStart`].
const SHARDS: usize = 16;

/// Records (of every shard's ids) below which [`WarmStart::record_all`]
/// stays on the calling thread: starting a thread costs more.
const PARALLEL_RECORDS: usize = 4096;

impl Default for WarmStart {
    fn default() -> Self {
        let hash = IdHash::default();
        WarmStart {
            shards: (0..SHARDS)
                .map(|_| HashMap::with_hasher(hash.clone()))
                .collect(),
            seed: IdHash::default().seed,
        }
    }
}

impl WarmStart {
    fn shard(&self, id: u64) -> usize {
        (fold_multiply(id, self.seed) >> 60) as usize % SHARDS
    }

    /// Records an island's basis: `contact_ids[i]` was active iff bit i of `basis`.
    pub fn record(&mut self, contact_ids: &[u64], basis: u32) {
        for (i, &id) in contact_ids.iter().enumerate() {
            let k = self.shard(id);
            self.shards[k].insert(id, i < 32 && basis >> i & 1 == 1);
        }
    }

    /// [`WarmStart::record`] of every (ids, basis) in order, on up to
    /// `threads` threads (shards split between them; each thread reads every
    /// record and writes its shards' ids, in the records' order, so that an
    /// id recorded twice keeps the later basis, as one thread would).
    pub fn record_all(&mut self, records: &[(&[u64], u32)], threads: usize) {
        let ids: usize = records.iter().map(|(k, _)| k.len()).sum();
        let threads = threads.clamp(1, SHARDS);
        if threads == 1 || ids < PARALLEL_RECORDS {
            for &(k, basis) in records {
                self.record(k, basis);
            }
            return;
        }
        let seed = self.seed;
        let per = SHARDS.div_ceil(threads);
        let write = |first: usize, shards: &mut [HashMap<u64, bool, IdHash>]| {
            for &(k, basis) in records {
                for (i, &id) in k.iter().enumerate() {
                    let s = (fold_multiply(id, seed) >> 60) as usize % SHARDS;
                    if let Some(map) = s.checked_sub(first).and_then(|j| shards.get_mut(j)) {
                        map.insert(id, i < 32 && basis >> i & 1 == 1);
                    }
                }
            }
        };
        std::thread::scope(|scope| {
            let mut parts = self.shards.chunks_mut(per).enumerate();
            let mine = parts.next();
            for (c, part) in parts {
                scope.spawn(move || write(c * per, part));
            }
            if let Some((_, part)) = mine {
                write(0, part);
            }
        });
    }

    /// The warm basis for an island with these contacts, if any was seen.
    pub fn basis(&self, contact_ids: &[u64]) -> Option<u32> {
        let mut seen = false;
        let mut mask = 0u32;
        for (i, &id) in contact_ids.iter().enumerate().take(32) {
            if let Some(&a) = self.shards[self.shard(id)].get(&id) {
                seen = true;
                if a {
                    mask |= 1 << i;
                }
            }
        }
        seen.then_some(mask)
    }
}

/// The 128-bit product of `x ^ seed` and an odd constant, folded to 64 bits:
/// every bit of the id reaches the high bits (the shard) and the low ones.
fn fold_multiply(x: u64, seed: u64) -> u64 {
    let p = u128::from(x ^ seed) * 0x9e37_79b9_7f4a_7c15_u128;
    (p as u64) ^ (p >> 64) as u64
}

/// The maps' hash of a contact id: [`fold_multiply`] with a seed drawn per
/// memory from the standard library's random keys (std's SipHash would
/// cost more than the rest of a warm-started island's bookkeeping).
#[derive(Clone, Debug)]
struct IdHash {
    seed: u64,
}

impl Default for IdHash {
    fn default() -> Self {
        IdHash {
            seed: RandomState::new().hash_one(0x5eed_u64),
        }
    }
}

impl BuildHasher for IdHash {
    type Hasher = IdHasher;
    fn build_hasher(&self) -> IdHasher {
        IdHasher {
            seed: self.seed,
            state: 0,
        }
    }
}

/// See [`IdHash`]; ids are u64 (`write_u64`), other keys are hashed byte by byte.
struct IdHasher {
    seed: u64,
    state: u64,
}

impl Hasher for IdHasher {
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.state = fold_multiply(self.state ^ u64::from(b), self.seed);
        }
    }

    fn write_u64(&mut self, x: u64) {
        self.state = fold_multiply(self.state ^ x, self.seed);
    }

    fn finish(&self) -> u64 {
        self.state
    }
}
