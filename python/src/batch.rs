//! LCP batches: NumPy arrays in, for the library (read in place, or as
//! [`Lcp`]s), and per-problem results out as flat arrays.
//!
//! Input comes dense (M of shape (B, n, n), q of shape (B, n), any strides)
//! or ragged (a list of (nᵢ, nᵢ) and a list of (nᵢ,) arrays). A C-ordered
//! dense batch is read in place by the library
//! ([`lcpbatch::Solver::solve_dense`]), which checks every entry; any
//! other is copied once into [`Lcp`]s, each entry checked as it is copied.
//! A non-finite entry's error names the argument and the index in NumPy's
//! notation.
//!
//! Output is flat: z, w and the basis of every problem one after the other,
//! with `offsets` (B + 1 entries) marking where each starts, so that Python
//! reshapes a dense batch to (B, n) or splits a ragged one without copying.

use std::borrow::Cow;
use std::ops::Range;

use lcpbatch::lcp::SolutionSet;
use lcpbatch::report::IslandReport;
use lcpbatch::Lcp;
use numpy::ndarray::{Array2, ArrayView1, ArrayView2, ArrayView3, Axis, Dimension};
use numpy::{
    IntoPyArray, PyArray1, PyArray2, PyReadonlyArray, PyReadonlyArray1, PyReadonlyArray2,
    PyReadonlyArray3,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

/// At most this many problems per chunk (with [`CHUNK_WORK`]): one call of
/// the library per chunk, a Ctrl-C check between chunks.
pub(crate) const CHUNK_PROBLEMS: usize = 65_536;

/// At most this much work per chunk, counting 2^n per problem of size n (the
/// bases enumeration may visit): 32,768 problems of n = 8 (a 20,000-problem
/// batch is one call), 128 of n = 16, one of n ≥ 23. Enumerating 2^23 bases
/// of n = 12 takes about 1.4 s on two cores, so Ctrl-C is seen within about
/// that on the slowest path (most problems never enumerate).
pub(crate) const CHUNK_WORK: u64 = 1 << 23;

/// Splits problems of sizes `ns` into consecutive chunks under both limits
/// (every chunk holds at least one problem).
pub(crate) fn chunks(ns: impl Iterator<Item = usize>) -> Vec<Range<usize>> {
    chunks_by(ns.map(|n| 1u64 << n.min(24)), CHUNK_WORK)
}

/// Splits problems of work `costs` into consecutive chunks of at most
/// [`CHUNK_PROBLEMS`] problems and `limit` work (every chunk holds at least
/// one problem, however costly).
pub(crate) fn chunks_by(costs: impl Iterator<Item = u64>, limit: u64) -> Vec<Range<usize>> {
    let mut out = Vec::new();
    let (mut start, mut work) = (0usize, 0u64);
    let mut end = 0usize;
    for cost in costs {
        if end > start && (end - start == CHUNK_PROBLEMS || work + cost > limit) {
            out.push(start..end);
            start = end;
            work = 0;
        }
        work += cost;
        end += 1;
    }
    if end > start {
        out.push(start..end);
    }
    out
}

/// The first entry of `values` that is not finite, as (position, value).
pub(crate) fn first_non_finite<'a>(values: impl Iterator<Item = &'a f64>) -> Option<(usize, f64)> {
    values
        .enumerate()
        .find(|(_, v)| !v.is_finite())
        .map(|(k, v)| (k, *v))
}

fn non_finite(arg: &str, index: String, v: f64) -> PyErr {
    PyValueError::new_err(non_finite_message(arg, &index, v))
}

/// The error of a non-finite entry: `arg` and its `index` ("[3, 0, 1]").
pub(crate) fn non_finite_message(arg: &str, index: &str, v: f64) -> String {
    format!("{arg}{index} is {v}: every entry of {arg} must be finite")
}

/// One problem from a (n, n) view of M and a (n,) view of q; `at` prefixes
/// the index in errors ("3, " for a dense batch, "[3][" style for ragged).
fn lcp_of(
    m: ArrayView2<f64>,
    q: ArrayView1<f64>,
    index: &dyn Fn(Vec<usize>) -> String,
) -> PyResult<Lcp> {
    let n = q.len();
    if let Some((k, v)) = first_non_finite(m.iter()) {
        return Err(non_finite("M", index(vec![k / n, k % n]), v));
    }
    if let Some((k, v)) = first_non_finite(q.iter()) {
        return Err(non_finite("q", index(vec![k]), v));
    }
    Ok(Lcp {
        m: m.iter().copied().collect(),
        q: q.to_vec(),
    })
}

pub(crate) fn join(ix: &[usize]) -> String {
    ix.iter()
        .map(usize::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}

/// Whether every entry is finite (no early exit, so that it vectorises).
pub(crate) fn all_finite(values: &[f64]) -> bool {
    values.iter().fold(true, |ok, v| ok & v.is_finite())
}

/// The entries of `a` in C order as one slice, where they lie so in memory
/// (None otherwise). Not NumPy's `as_slice`, which also takes an array in
/// Fortran order: its flat order is not the batch's.
pub(crate) fn c_slice<'a, D: Dimension>(a: &'a PyReadonlyArray<'_, f64, D>) -> Option<&'a [f64]> {
    a.as_array().to_slice()
}

/// A dense batch M (B, n, n), q (B, n) (shapes checked in Python) as n and
/// its two flat slices, where both arrays are C-ordered and n > 0: the
/// batches the library reads in place ([`lcpbatch::Solver::solve_dense`]);
/// None for any other (read element by element by [`dense`]).
pub(crate) fn dense_slices<'a>(
    m: &'a PyReadonlyArray3<f64>,
    q: &'a PyReadonlyArray2<f64>,
) -> Option<(usize, &'a [f64], &'a [f64])> {
    let n = q.as_array().shape()[1];
    (n > 0).then_some((n, c_slice(m)?, c_slice(q)?))
}

/// The message of the first non-finite entry of the C-ordered batch `ms`
/// (B·n·n), `qs` (B·n), problem by problem (M[b] before q[b]), as [`dense`]
/// names it: `[b, i, j]` for M, `[b, i]` for q. Ok where every entry is
/// finite.
pub(crate) fn check_finite(ms: &[f64], qs: &[f64], n: usize) -> Result<(), String> {
    if all_finite(ms) && all_finite(qs) {
        return Ok(());
    }
    for (b, (m, q)) in ms.chunks_exact(n * n).zip(qs.chunks_exact(n)).enumerate() {
        if let Some((k, v)) = first_non_finite(m.iter()) {
            let index = format!("[{b}, {}, {}]", k / n, k % n);
            return Err(non_finite_message("M", &index, v));
        }
        if let Some((k, v)) = first_non_finite(q.iter()) {
            return Err(non_finite_message("q", &format!("[{b}, {k}]"), v));
        }
    }
    Ok(())
}

/// A dense batch: M (B, n, n), q (B, n) (shapes checked in Python), read
/// element by element into one [`Lcp`] per problem (any memory order), a
/// non-finite entry named by its index.
pub(crate) fn dense(m: &PyReadonlyArray3<f64>, q: &PyReadonlyArray2<f64>) -> PyResult<Vec<Lcp>> {
    let (m, q): (ArrayView3<f64>, ArrayView2<f64>) = (m.as_array(), q.as_array());
    m.outer_iter()
        .zip(q.outer_iter())
        .enumerate()
        .map(|(b, (mb, qb))| lcp_of(mb, qb, &|ix| format!("[{b}, {}]", join(&ix))))
        .collect()
}

/// A ragged batch: lists of (nᵢ, nᵢ) and (nᵢ,) arrays (shapes checked in Python).
pub(crate) fn ragged(
    m: &[PyReadonlyArray2<f64>],
    q: &[PyReadonlyArray1<f64>],
) -> PyResult<Vec<Lcp>> {
    m.iter()
        .zip(q)
        .enumerate()
        .map(|(b, (mb, qb))| {
            lcp_of(mb.as_array(), qb.as_array(), &|ix| {
                format!("[{b}][{}]", join(&ix))
            })
        })
        .collect()
}

/// Contact ids of a dense batch, one row per problem.
pub(crate) fn dense_ids(ids: &PyReadonlyArray2<u64>) -> Vec<Vec<u64>> {
    ids.as_array()
        .axis_iter(Axis(0))
        .map(|r| r.to_vec())
        .collect()
}

/// Contact ids of a dense batch, row after row: in place where C-ordered.
pub(crate) fn flat_ids<'a>(ids: &'a PyReadonlyArray2<u64>) -> Cow<'a, [u64]> {
    match ids.as_array().to_slice() {
        Some(s) => Cow::Borrowed(s),
        None => Cow::Owned(ids.as_array().iter().copied().collect()),
    }
}

/// Contact ids of a ragged batch.
pub(crate) fn ragged_ids(ids: &[PyReadonlyArray1<u64>]) -> Vec<Vec<u64>> {
    ids.iter().map(|r| r.as_array().to_vec()).collect()
}

fn solution_set_name(s: &Option<SolutionSet>) -> Option<&'static str> {
    s.as_ref().map(|s| match s {
        SolutionSet::Empty => "empty",
        SolutionSet::Isolated { .. } => "isolated",
        SolutionSet::BoundedContinuum => "bounded_continuum",
        SolutionSet::UnboundedContinuum => "unbounded_continuum",
    })
}

/// The z and w of a dense batch's islands as two (B, n) arrays (`dim`),
/// and their status codes (B,), in one pass over the islands.
pub(crate) fn zw<'py>(
    py: Python<'py>,
    islands: &[IslandReport],
    dim: (usize, usize),
) -> PyResult<ZwArrays<'py>> {
    let (mut z, mut w) = (vec![0.0; dim.0 * dim.1], vec![0.0; dim.0 * dim.1]);
    let mut status = vec![0; islands.len()];
    if !zw_into(islands, &mut z, &mut w, &mut status, |v| v) {
        return Err(PyValueError::new_err(format!(
            "the report's {} islands do not fill a ({}, {}) batch",
            islands.len(),
            dim.0,
            dim.1
        )));
    }
    Ok((
        array2(py, dim, z)?,
        array2(py, dim, w)?,
        status.into_pyarray(py),
    ))
}

/// Writes the islands' z and w one after the other into `z` and `w` (as
/// `to` converts each entry) and their status codes into `status`, in one
/// pass. `false`, with nothing written, where the islands do not fill the
/// slices exactly (one island per status, their z lengths summing to
/// `z.len()`): a report of the wrong size, which only a library bug gives.
#[must_use]
pub(crate) fn zw_into<T>(
    islands: &[IslandReport],
    z: &mut [T],
    w: &mut [T],
    status: &mut [i8],
    to: impl Fn(f64) -> T,
) -> bool {
    let total: usize = islands.iter().map(|i| i.solution.z.len()).sum();
    if islands.len() != status.len() || total != z.len() || total != w.len() {
        return false;
    }
    let mut at = 0;
    for (i, code) in islands.iter().zip(status.iter_mut()) {
        let (sz, sw) = (&i.solution.z, &i.solution.w);
        let end = at + sz.len();
        for (o, &v) in z[at..end].iter_mut().zip(sz) {
            *o = to(v);
        }
        for (o, &v) in w[at..end].iter_mut().zip(sw) {
            *o = to(v);
        }
        *code = crate::report::status_code(i.status());
        at = end;
    }
    true
}

/// `v` as a NumPy array of shape `dim` (`ValueError` if its length is not that).
fn array2<T: numpy::Element>(
    py: Python<'_>,
    dim: (usize, usize),
    v: Vec<T>,
) -> PyResult<Bound<'_, PyArray2<T>>> {
    let err = |e: numpy::ndarray::ShapeError| PyValueError::new_err(e.to_string());
    Ok(Array2::from_shape_vec(dim, v)
        .map_err(err)?
        .into_pyarray(py))
}

/// What [`zw`] returns: z, w and the status codes.
pub(crate) type ZwArrays<'py> = (
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray1<i8>>,
);

/// Per-island results as flat arrays in `d`: `offsets` (I + 1), `z`, `w`,
/// `basis` (flat, bool), and per island `status`, `path` (codes), `error`,
/// `has_basis`, `pivots`, `iterations`, `bases_visited`, `solution_count`
/// (−1 where unknown) and `solution_set` (a list of names or None).
pub(crate) fn islands_into(
    py: Python<'_>,
    d: &Bound<'_, PyDict>,
    islands: &[IslandReport],
) -> PyResult<()> {
    // One pass over the islands (a few hundred bytes each): a pass per
    // array read them all again, at the cost of the memory traffic.
    let (total, count) = (
        islands.iter().map(|i| i.solution.z.len()).sum(),
        islands.len(),
    );
    let (mut z, mut w, mut basis) = (
        Vec::with_capacity(total),
        Vec::with_capacity(total),
        Vec::with_capacity(total),
    );
    let mut offsets = Vec::with_capacity(count + 1);
    offsets.push(0i64);
    let [mut status, mut path] = [(); 2].map(|_| Vec::<i8>::with_capacity(count));
    let (mut error, mut has_basis) = (Vec::with_capacity(count), Vec::with_capacity(count));
    let [mut pivots, mut iterations, mut visited] =
        [(); 3].map(|_| Vec::<u64>::with_capacity(count));
    let (mut solutions, mut sets) = (Vec::with_capacity(count), Vec::with_capacity(count));
    let mut all_found = false;
    for isl in islands {
        let s = &isl.solution;
        z.extend_from_slice(&s.z);
        w.extend_from_slice(&s.w);
        let mask = s.basis.unwrap_or(0);
        basis.extend((0..s.z.len()).map(|i| i < 32 && mask >> i & 1 == 1));
        offsets.push(z.len() as i64);
        status.push(crate::report::status_code(isl.status()));
        path.push(crate::report::path_code(isl.path));
        error.push(isl.error());
        has_basis.push(s.basis.is_some());
        pivots.push(s.counters.pivots);
        iterations.push(s.counters.iterations);
        visited.push(s.counters.bases_visited);
        solutions.push(s.solution_count().map_or(-1, |c| c as i64));
        sets.push(solution_set_name(&s.solution_set));
        all_found |= !s.all_bases.is_empty();
    }
    d.set_item("offsets", offsets.into_pyarray(py))?;
    d.set_item("z", z.into_pyarray(py))?;
    d.set_item("w", w.into_pyarray(py))?;
    d.set_item("basis", basis.into_pyarray(py))?;
    d.set_item("status", status.into_pyarray(py))?;
    d.set_item("path", path.into_pyarray(py))?;
    d.set_item("error", error.into_pyarray(py))?;
    d.set_item("has_basis", has_basis.into_pyarray(py))?;
    d.set_item("pivots", pivots.into_pyarray(py))?;
    d.set_item("iterations", iterations.into_pyarray(py))?;
    d.set_item("bases_visited", visited.into_pyarray(py))?;
    d.set_item("solution_count", solutions.into_pyarray(py))?;
    d.set_item("solution_set", sets)?;
    if all_found {
        d.set_item("all_bases", all_bases(py, islands)?)?;
    }
    Ok(())
}

/// With `all_solutions`: per island, (k, n) arrays of the z and the basis
/// of every valid complementary basis enumeration found.
fn all_bases<'py>(py: Python<'py>, islands: &[IslandReport]) -> PyResult<Vec<Bound<'py, PyTuple>>> {
    islands
        .iter()
        .map(|isl| {
            let n = isl.solution.z.len();
            let found = &isl.solution.all_bases;
            let z: Vec<f64> = found.iter().flat_map(|b| b.z.iter().copied()).collect();
            let basis: Vec<bool> = found
                .iter()
                .flat_map(|b| (0..n).map(move |i| i < 32 && b.basis >> i & 1 == 1))
                .collect();
            let shape = (found.len(), n);
            let (z, basis) = (array2(py, shape, z)?, array2(py, shape, basis)?);
            PyTuple::new(py, [z.into_any(), basis.into_any()])
        })
        .collect()
}
