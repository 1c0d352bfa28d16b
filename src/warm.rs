//! The warm-start memory: what each contact did in the last calls, by the
//! caller's contact id (stable across calls, e.g. a feature pair from
//! collision detection), for the next call to start from. One type,
//! [`WarmMemory`], serves the LCP bases (per contact: whether it carried
//! impulse, i.e. was in its island's basis) and the frictional reactions
//! (r_n, r_t₁, r_t₂); the solver keeps one pair ([`Warm`]) for its calls, the
//! world step one pair per world.
//!
//! An id not recorded for `keep` calls is forgotten
//! ([`crate::Settings::warm_start_calls`]; default 1: only the last call's
//! ids), so that the memory stays bounded however many contacts come and go.
//! The ids are spread over shards by a hash of the id, so that a batch's
//! records can be written on several threads, one shard each at a time,
//! every shard in the batch's order ([`WarmMemory::record_all`]); the maps
//! hash an id by one seeded multiplication ([`IdHash`]). Lookups take
//! `&self`: many threads look up at once (the CPU path's `parallel_fill`).
//!
//! A caller that splits one batch into several calls (the Python package's
//! chunks) joins them into one call of the memory ([`Warm::join_calls`]):
//! each part's records carry the same call, and the ids of earlier calls
//! are forgotten only when the join ends, after every part has looked up.

use std::collections::HashMap;
use std::hash::{BuildHasher, Hasher, RandomState};

use crate::cpu::batch::parallel_fill_by;

/// Shards of the solver's memory (a world's has one).
pub(crate) const SHARDS: usize = 16;

/// Ids recorded (in one call, over every shard) below which
/// [`WarmMemory::record_all`] stays on the calling thread: waking the
/// other threads costs more.
const PARALLEL_RECORDS: usize = 4096;

/// A value remembered by contact id, with the call that last recorded it.
#[derive(Clone, Copy, Debug)]
struct Entry<V> {
    value: V,
    call: u64,
}

/// One warm-start memory: a value per contact id, ids not recorded for
/// `keep` calls forgotten; see the module docs.
#[derive(Clone, Debug)]
pub(crate) struct WarmMemory<V> {
    shards: Vec<HashMap<u64, Entry<V>, IdHash>>,
    /// Picks an id's shard (independent of the maps' own hash).
    seed: u64,
    /// Calls an id is kept without being recorded again (at least 1).
    keep: u64,
    /// Calls recorded so far.
    calls: u64,
    /// Calls joined into one ([`Warm::join_calls`]): records carry call
    /// `calls + 1` and forget nothing until the join ends.
    joined: bool,
    /// Whether the joined call has recorded anything.
    joined_records: bool,
}

/// The solver's or a world's memory: the LCP bases and the frictional
/// reactions, each with its own calls (a call that records no frictional
/// island leaves the reactions as they are).
#[derive(Clone, Debug)]
pub(crate) struct Warm {
    /// Per contact id: whether it was in its island's basis.
    pub(crate) bases: WarmMemory<bool>,
    /// Per contact id: its reaction (r_n, r_t₁, r_t₂).
    pub(crate) reactions: WarmMemory<[f64; 3]>,
    /// Per contact id: its island was settling in a call it keeps (a world
    /// step's warm start that was off, see
    /// `solver::world_friction::SETTLED`; by default the last step only):
    /// the next call polishes its start even where it is within the
    /// tolerance.
    pub(crate) settling: WarmMemory<bool>,
}

impl Warm {
    /// Both memories, keeping ids `keep` calls, on `shards` shards (1 or
    /// [`SHARDS`]).
    pub(crate) fn new(keep: usize, shards: usize) -> Self {
        Warm {
            bases: WarmMemory::new(keep, shards),
            reactions: WarmMemory::new(keep, shards),
            settling: WarmMemory::new(keep, shards),
        }
    }

    /// `true`: the calls that follow count as one call of both memories
    /// until `join_calls(false)`, which ends it (forgetting, after the
    /// parts' records, the ids that call has put past `keep` calls). A part
    /// looks up the memory of the calls before the join and the records of
    /// the parts before it.
    pub(crate) fn join_calls(&mut self, join: bool) {
        self.bases.join_calls(join);
        self.reactions.join_calls(join);
        self.settling.join_calls(join);
    }
}

impl<V: Copy + Send + Sync> WarmMemory<V> {
    /// An empty memory keeping ids `keep` calls (at least 1), on `shards`
    /// shards (a power of two, at most [`SHARDS`]).
    pub(crate) fn new(keep: usize, shards: usize) -> Self {
        debug_assert!(shards.is_power_of_two() && shards <= SHARDS);
        let hash = IdHash::default();
        WarmMemory {
            shards: (0..shards)
                .map(|_| HashMap::with_hasher(hash.clone()))
                .collect(),
            seed: IdHash::default().seed,
            keep: keep.max(1) as u64,
            calls: 0,
            joined: false,
            joined_records: false,
        }
    }

    /// See [`Warm::join_calls`].
    fn join_calls(&mut self, join: bool) {
        if self.joined && !join && self.joined_records {
            self.calls += 1;
            let (call, keep) = (self.calls, self.keep);
            for map in &mut self.shards {
                map.retain(|_, e| e.call + keep > call);
            }
        }
        if self.joined != join {
            self.joined_records = false;
        }
        self.joined = join;
    }

    /// The call the next records carry, and whether they forget first
    /// (not while calls are joined: the join's end does).
    fn next_call(&mut self) -> (u64, bool) {
        if self.joined {
            self.joined_records = true;
            return (self.calls + 1, false);
        }
        self.calls += 1;
        (self.calls, true)
    }

    fn shard(&self, id: u64) -> usize {
        shard_of(id, self.seed, self.shards.len())
    }

    /// The value remembered for `id`, if any.
    fn get(&self, id: u64) -> Option<V> {
        self.shards[self.shard(id)].get(&id).map(|e| e.value)
    }

    /// How many ids are remembered.
    #[cfg(test)]
    pub(crate) fn len(&self) -> usize {
        self.shards.iter().map(HashMap::len).sum()
    }

    /// One call's records: every (id, value) of `entries`, in order (an id
    /// recorded twice keeps the later value); an id recorded in none of
    /// the last `keep` calls (this one included) is forgotten.
    pub(crate) fn record<I: Iterator<Item = (u64, V)>>(&mut self, entries: I) {
        let ((call, forgets), keep) = (self.next_call(), self.keep);
        for map in self.shards.iter_mut().filter(|_| forgets) {
            forget(map, call, keep);
        }
        for (id, value) in entries {
            let k = self.shard(id);
            self.shards[k].insert(id, Entry { value, call });
        }
    }

    /// [`WarmMemory::record`] of every record's `entries`, in the records'
    /// order, on up to `threads` threads (shards split between them; each
    /// thread reads every record and writes its shards' ids, in the
    /// records' order, so that an id recorded twice keeps the later value,
    /// as one thread would). `ids` counts the entries, for the choice of
    /// threads.
    pub(crate) fn record_all<R: Sync, I: Iterator<Item = (u64, V)>>(
        &mut self,
        records: &[R],
        ids: usize,
        threads: usize,
        entries: impl Fn(&R) -> I + Sync,
    ) {
        let threads = threads.clamp(1, self.shards.len());
        if threads == 1 || ids < PARALLEL_RECORDS {
            self.record(records.iter().flat_map(&entries));
            return;
        }
        let (call, forgets) = self.next_call();
        let (keep, seed, n) = (self.keep, self.seed, self.shards.len());
        let per = n.div_ceil(threads);
        let write = |first: usize, shards: &mut [HashMap<u64, Entry<V>, IdHash>]| {
            for map in shards.iter_mut().filter(|_| forgets) {
                forget(map, call, keep);
            }
            for (id, value) in records.iter().flat_map(&entries) {
                let s = shard_of(id, seed, n);
                if let Some(map) = s.checked_sub(first).and_then(|j| shards.get_mut(j)) {
                    map.insert(id, Entry { value, call });
                }
            }
        };
        // On the kept threads (`parallel_fill_by`): threads started per
        // call cost more than the records of a batch of small islands.
        let mut parts: Vec<_> = self.shards.chunks_mut(per).collect();
        parallel_fill_by(&mut parts, threads, 1, |c, part| write(c * per, part));
    }
}

/// Before call `call`'s records: the ids not recorded in the `keep − 1`
/// calls before it go (with `keep` 1, all of them).
fn forget<V>(map: &mut HashMap<u64, Entry<V>, IdHash>, call: u64, keep: u64) {
    if keep == 1 {
        map.clear();
    } else {
        map.retain(|_, e| e.call + keep > call);
    }
}

impl WarmMemory<bool> {
    /// Whether any of these contact ids was recorded `true` (an island
    /// with a contact that was settling; contacts without id are not).
    pub(crate) fn any(&self, mut ids: impl Iterator<Item = Option<u64>>) -> bool {
        if self.shards.iter().all(HashMap::is_empty) {
            return false; // nothing settling: no lookups
        }
        ids.any(|id| id.and_then(|id| self.get(id)) == Some(true))
    }

    /// The warm basis of an island with these contact ids (None for a
    /// contact without id): bit i set when contact i was in its island's
    /// basis; None when none of them is remembered. Contacts past the 32nd
    /// are not looked up.
    pub(crate) fn basis(&self, ids: impl Iterator<Item = Option<u64>>) -> Option<u32> {
        let mut seen = false;
        let mut mask = 0u32;
        for (i, id) in ids.enumerate().take(32) {
            if let Some(active) = id.and_then(|id| self.get(id)) {
                seen = true;
                mask |= u32::from(active) << i;
            }
        }
        seen.then_some(mask)
    }
}

impl WarmMemory<[f64; 3]> {
    /// The warm start of an island with these contact ids (None for a
    /// contact without id): the remembered reactions, zero for a contact
    /// not remembered; None when none of them is remembered.
    pub(crate) fn reactions(&self, ids: impl Iterator<Item = Option<u64>>) -> Option<Vec<f64>> {
        let mut any = false;
        let mut r = Vec::with_capacity(3 * ids.size_hint().0);
        for id in ids {
            let found = id.and_then(|id| self.get(id));
            any |= found.is_some();
            r.extend_from_slice(&found.unwrap_or([0.0; 3]));
        }
        any.then_some(r)
    }
}

/// The entries of an island's record: contact i (those with an id)
/// was active iff bit i of `basis` (contacts past the 32nd inactive).
pub(crate) fn basis_entries(
    ids: impl Iterator<Item = Option<u64>>,
    basis: u32,
) -> impl Iterator<Item = (u64, bool)> {
    ids.enumerate()
        .filter_map(move |(i, id)| Some((id?, i < 32 && basis >> i & 1 == 1)))
}

/// The entries of an island's record: contact i (those with an id)
/// with its reaction `r[3i..3i + 3]`.
pub(crate) fn reaction_entries<'a>(
    ids: impl Iterator<Item = Option<u64>> + 'a,
    r: &'a [f64],
) -> impl Iterator<Item = (u64, [f64; 3])> + 'a {
    ids.enumerate()
        .filter_map(move |(i, id)| Some((id?, [r[3 * i], r[3 * i + 1], r[3 * i + 2]])))
}

/// The shard of `id` among `n` (a power of two ≤ [`SHARDS`]): the top bits
/// of its [`fold_multiply`].
fn shard_of(id: u64, seed: u64, n: usize) -> usize {
    (fold_multiply(id, seed) >> 60) as usize & (n - 1)
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

#[cfg(test)]
mod tests {
    use super::*;

    fn some(ids: &[u64]) -> impl Iterator<Item = Option<u64>> + '_ {
        ids.iter().map(|&id| Some(id))
    }

    fn entries<'a>(&(k, basis): &(&'a [u64], u32)) -> impl Iterator<Item = (u64, bool)> + 'a {
        basis_entries(some(k), basis)
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
        let mut one = WarmMemory::new(1, SHARDS);
        one.record_all(&records, 12_000, 1, entries);
        for threads in [2, 3, 16, 64] {
            let mut many = WarmMemory::new(1, SHARDS);
            many.record_all(&records, 12_000, threads, entries);
            assert_eq!(many.len(), one.len());
            for k in &ids {
                assert_eq!(
                    many.basis(some(k)),
                    one.basis(some(k)),
                    "{threads} threads, {k:?}"
                );
            }
            assert_eq!(many.basis([Some(10_001), Some(10_002)].into_iter()), None);
        }
    }

    /// Fresh ids every call for 10,000 calls (20 calls of 5,000 ids for the
    /// record on several threads): the memory holds the last `keep` calls'
    /// ids and no more, on one shard or many; an id last seen `keep` calls
    /// ago is still there, one seen `keep + 1` calls ago is gone.
    #[test]
    fn the_memory_stays_bounded_over_10000_calls_with_fresh_ids() {
        for (keep, shards, per_call, threads) in [
            (1, 1, 8, 1),
            (3, 1, 8, 1),
            (1, SHARDS, 8, 4),
            (2, SHARDS, 5000, 4),
        ] {
            let mut memory = WarmMemory::<[f64; 3]>::new(keep, shards);
            let calls = if per_call > 100 { 20 } else { 10_000 };
            for call in 0..calls as u64 {
                let ids: Vec<u64> = (0..per_call).map(|k| call * per_call + k).collect();
                memory.record_all(&ids, ids.len(), threads, |&id| {
                    std::iter::once((id, [call as f64, 0.0, 0.0]))
                });
                assert!(memory.len() <= keep * per_call as usize, "{keep} {shards}");
            }
            let last = calls as u64 - 1;
            assert_eq!(memory.len(), keep * per_call as usize);
            let id = |call: u64| std::iter::once(Some(call * per_call));
            let oldest = last + 1 - keep as u64;
            assert_eq!(
                memory.reactions(id(oldest)),
                Some(vec![oldest as f64, 0.0, 0.0])
            );
            assert_eq!(memory.reactions(id(oldest - 1)), None);
        }
    }

    /// Through `Solver::solve_lcps_keyed`: ids not seen in the last call
    /// are forgotten by default, kept with `warm_start_calls: 2`.
    #[test]
    fn the_solver_forgets_ids_after_warm_start_calls() {
        use crate::report::SolvePath;
        use crate::{Backend, Lcp, Method, Settings, Solver};
        // Rank one M: no predicted basis, only the warm start settles it.
        let lcps = [Lcp::new(vec![1.0, 1.0, 1.0, 1.0], vec![-1.0, -1.0]).unwrap()];
        for (calls, kept) in [(1, false), (2, true)] {
            let mut solver = Solver::new(Settings {
                warm_start: true,
                warm_start_calls: calls,
                ..Settings::new(Backend::Cpu, Method::Enumeration)
            })
            .unwrap();
            for ids in [[1, 2], [3, 4]] {
                solver.solve_lcps_keyed(&lcps, &[ids.to_vec()]).unwrap();
            }
            let again = solver.solve_lcps_keyed(&lcps, &[vec![1, 2]]).unwrap();
            let warm = again.islands[0].path == SolvePath::WarmStart;
            assert_eq!(warm, kept, "warm_start_calls {calls}");
        }
    }

    /// Parts joined into one call (one shard and the record on several
    /// threads): with `keep` 1 every part still finds the ids of the call
    /// before the join, which go when the join ends; the parts' ids stay
    /// for the call after it, as one call's would, and go at the next.
    #[test]
    fn joined_calls_forget_as_one_call() {
        for (shards, per_part, threads) in [(1, 8, 1), (SHARDS, 5000, 4)] {
            let mut warm = Warm::new(1, shards);
            let ids = |part: u64| (0..per_part).map(move |k| part * 10_000 + k);
            let record = |m: &mut WarmMemory<bool>, part: u64| {
                let ids: Vec<u64> = ids(part).collect();
                m.record_all(&ids, ids.len(), threads, |&id| std::iter::once((id, true)));
            };
            let seen =
                |m: &WarmMemory<bool>, part: u64| m.basis(ids(part).take(1).map(Some)).is_some();
            record(&mut warm.bases, 0);
            warm.join_calls(true);
            for part in 1..=3 {
                record(&mut warm.bases, part);
                let kept = seen(&warm.bases, 0);
                assert!(kept, "part {part}: the call before the join is kept");
            }
            warm.join_calls(false);
            let memory = &mut warm.bases;
            assert!(!seen(memory, 0));
            assert!((1..=3).all(|part| seen(memory, part)));
            assert_eq!(memory.len(), 3 * per_part as usize);
            record(memory, 4);
            assert!((1..=3).all(|part| !seen(memory, part)) && seen(memory, 4));
            // A join that records nothing is no call.
            warm.join_calls(true);
            warm.join_calls(false);
            assert!(seen(&warm.bases, 4));
        }
    }

    #[test]
    fn lookups_give_zero_or_nothing_for_contacts_not_remembered() {
        let mut memory = WarmMemory::<[f64; 3]>::new(1, 1);
        let r = [1.0, 0.1, 0.2, 2.0, 0.3, 0.4];
        memory.record(reaction_entries([Some(7), Some(3)].into_iter(), &r));
        assert_eq!(
            memory.reactions([Some(3), None, Some(9)].into_iter()),
            Some(vec![2.0, 0.3, 0.4, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0])
        );
        assert_eq!(memory.reactions([None, Some(9)].into_iter()), None);
        let mut bases = WarmMemory::<bool>::new(1, SHARDS);
        bases.record(basis_entries(some(&[5, 6, 7]), 0b101));
        assert_eq!(
            bases.basis([Some(6), Some(7), None, Some(5)].into_iter()),
            Some(0b1010)
        );
        assert_eq!(bases.basis([Some(8)].into_iter()), None);
    }
}
