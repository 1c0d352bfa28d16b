//! The report's counts: islands per path and per status, and the largest
//! error with its index, counted in parts on every thread and added in
//! order (the serial count's figures).

use super::{IslandReport, PathCounts};
use crate::cpu::batch::parallel_fill_by;
use crate::lcp::Status;

/// Islands per status (in the order of [`Status::ALL`]) and the largest
/// error over those whose status is a solution, with its index.
type Tally = ([usize; Status::ALL.len()], Option<(f64, usize)>);

/// The [`Tally`] of (status, error) pairs, indices from 0.
pub(super) fn tally(items: impl Iterator<Item = (Status, f64)>) -> Tally {
    let mut statuses = [0usize; Status::ALL.len()];
    let mut max = None;
    for (i, (s, e)) in items.enumerate() {
        if let Some(k) = Status::ALL.iter().position(|&x| x == s) {
            statuses[k] += 1;
        }
        if s.is_solution() {
            max = larger(max, Some((e, i)));
        }
    }
    (statuses, max)
}

/// Islands counted by one thread at a time in [`count_islands`].
const COUNT_PART: usize = 1024;

/// The path counts and the [`Tally`] of `islands`, parts of
/// [`COUNT_PART`] islands on up to `threads` threads, added in order: the
/// serial count's figures (the largest error's first index on a tie).
/// Where a solution's error is NaN, whose place a serial count keeps by
/// its own rule ([`larger`]), the islands are counted again on this thread.
pub(super) fn count_islands(islands: &[IslandReport], threads: usize) -> (PathCounts, Tally) {
    let count = |part: &[IslandReport]| {
        let mut counts = PathCounts::default();
        part.iter().for_each(|i| counts.add(i.path));
        (counts, tally(part.iter().map(|i| (i.status(), i.error()))))
    };
    let mut parts = vec![Default::default(); islands.len().div_ceil(COUNT_PART)];
    parallel_fill_by(&mut parts, threads, 1, |p, slot| {
        let part = &islands[p * COUNT_PART..islands.len().min((p + 1) * COUNT_PART)];
        let nan = part
            .iter()
            .any(|i| i.status().is_solution() && i.error().is_nan());
        *slot = (count(part), nan);
    });
    if parts.iter().any(|(_, nan)| *nan) {
        return count(islands);
    }
    let mut all = (PathCounts::default(), ([0; Status::ALL.len()], None));
    for (p, ((counts, t), _)) in parts.into_iter().enumerate() {
        all.0 += counts;
        add_tally((&mut all.1 .0, &mut all.1 .1), t, p * COUNT_PART);
    }
    all
}

/// The larger of two (error, index) maxima, `a`'s on a tie. NaN compares
/// false: a NaN in `b` always replaces `a`, so that it is reported, never
/// hidden.
fn larger(a: Option<(f64, usize)>, b: Option<(f64, usize)>) -> Option<(f64, usize)> {
    match b {
        Some((e, _)) if !a.is_some_and(|(m, _)| e <= m) => b,
        _ => a,
    }
}

/// `b`'s [`Tally`] added to `a`'s, `b`'s index shifted by `shift`.
pub(super) fn add_tally(
    a: (&mut [usize; Status::ALL.len()], &mut Option<(f64, usize)>),
    b: Tally,
    shift: usize,
) {
    for (x, y) in a.0.iter_mut().zip(b.0) {
        *x += y;
    }
    *a.1 = larger(*a.1, b.1.map(|(e, i)| (e, i + shift)));
}

/// (status, count) of every status counted, in [`Status::ALL`] order.
pub(super) fn nonzero_statuses(counts: [usize; Status::ALL.len()]) -> Vec<(Status, usize)> {
    let all = Status::ALL.iter().zip(counts);
    all.filter(|(_, c)| *c > 0).map(|(&s, c)| (s, c)).collect()
}
