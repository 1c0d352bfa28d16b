//! Batches of frictional contact problems (Siconos' FrictionContact3D form:
//! W (3k × 3k), q (3k), μ (k), contact i owning entries 3i normal, 3i + 1
//! and 3i + 2 tangents) from NumPy arrays, and their results as flat arrays.
//!
//! Dense input is W (B, 3k, 3k), q (B, 3k), μ (B, k) with any strides;
//! ragged input is three lists. Every entry is checked while it is copied
//! (finite, μ ≥ 0); the error names the argument and the index. The
//! library's own `FrictionProblem::validate` runs again in the solver.

use std::ops::Range;

use lcpbatch::report::FrictionIslandReport;
use lcpbatch::FrictionProblem;
use numpy::ndarray::{ArrayView1, ArrayView2};
use numpy::{IntoPyArray, PyReadonlyArray1, PyReadonlyArray2, PyReadonlyArray3};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::batch::{first_non_finite, join};

/// At most this much work per chunk, counting (3k)² per problem of k
/// contacts (one NSGS sweep or Newton step of it): 65,536 problems of one
/// contact, 4,096 of four. Ctrl-C is checked between chunks.
pub(crate) const CHUNK_FRICTION_WORK: u64 = 1 << 19;

/// Splits problems of `ks` contacts into consecutive chunks under
/// [`CHUNK_FRICTION_WORK`] and [`crate::batch::CHUNK_PROBLEMS`].
pub(crate) fn chunks(ks: impl Iterator<Item = usize>) -> Vec<Range<usize>> {
    crate::batch::chunks_by(ks.map(|k| 9 * (k as u64) * (k as u64)), CHUNK_FRICTION_WORK)
}

/// One problem from views of W (3k, 3k), q (3k) and μ (k); `at` writes the
/// index of an entry in the error ("[b, i, j]" or "[b][i, j]").
fn problem_of(
    w: ArrayView2<f64>,
    q: ArrayView1<f64>,
    mu: ArrayView1<f64>,
    at: &dyn Fn(&[usize]) -> String,
) -> PyResult<FrictionProblem> {
    let n = q.len();
    if let Some((k, v)) = first_non_finite(w.iter()) {
        return Err(PyValueError::new_err(format!(
            "W{} is {v}: every entry of W must be finite",
            at(&[k / n, k % n])
        )));
    }
    if let Some((k, v)) = first_non_finite(q.iter()) {
        return Err(PyValueError::new_err(format!(
            "q{} is {v}: every entry of q must be finite",
            at(&[k])
        )));
    }
    if let Some((k, v)) = mu
        .iter()
        .enumerate()
        .find(|(_, v)| !v.is_finite() || **v < 0.0)
        .map(|(k, v)| (k, *v))
    {
        return Err(PyValueError::new_err(format!(
            "mu{} is {v}: a friction coefficient must be finite and ≥ 0",
            at(&[k])
        )));
    }
    Ok(FrictionProblem {
        w: w.iter().copied().collect(),
        q: q.to_vec(),
        mu: mu.to_vec(),
    })
}

/// A dense batch (shapes checked in Python).
pub(crate) fn dense(
    w: &PyReadonlyArray3<f64>,
    q: &PyReadonlyArray2<f64>,
    mu: &PyReadonlyArray2<f64>,
) -> PyResult<Vec<FrictionProblem>> {
    let (w, q, mu) = (w.as_array(), q.as_array(), mu.as_array());
    w.outer_iter()
        .zip(q.outer_iter())
        .zip(mu.outer_iter())
        .enumerate()
        .map(|(b, ((wb, qb), mb))| problem_of(wb, qb, mb, &|ix| format!("[{b}, {}]", join(ix))))
        .collect()
}

/// A ragged batch: lists of (3kᵢ, 3kᵢ), (3kᵢ,) and (kᵢ,) arrays (shapes
/// checked in Python).
pub(crate) fn ragged(
    w: &[PyReadonlyArray2<f64>],
    q: &[PyReadonlyArray1<f64>],
    mu: &[PyReadonlyArray1<f64>],
) -> PyResult<Vec<FrictionProblem>> {
    w.iter()
        .zip(q)
        .zip(mu)
        .enumerate()
        .map(|(b, ((wb, qb), mb))| {
            problem_of(wb.as_array(), qb.as_array(), mb.as_array(), &|ix| {
                format!("[{b}][{}]", join(ix))
            })
        })
        .collect()
}

/// Per problem results as flat arrays in `d`: `offsets` (B + 1, in entries
/// of r), `r`, `u`, and per problem `status` (codes), `coulomb_error`,
/// `cone_error`, `iterations`, `warm_started`.
pub(crate) fn problems_into(
    py: Python<'_>,
    d: &Bound<'_, PyDict>,
    islands: &[FrictionIslandReport],
) -> PyResult<()> {
    let (mut r, mut u) = (Vec::new(), Vec::new());
    let mut offsets = vec![0i64];
    for isl in islands {
        r.extend_from_slice(&isl.solution.r);
        u.extend_from_slice(&isl.solution.u);
        offsets.push(r.len() as i64);
    }
    d.set_item("offsets", offsets.into_pyarray(py))?;
    d.set_item("r", r.into_pyarray(py))?;
    d.set_item("u", u.into_pyarray(py))?;
    let status: Vec<i8> = islands
        .iter()
        .map(|i| crate::report::status_code(i.status()))
        .collect();
    d.set_item("status", status.into_pyarray(py))?;
    let per = |f: &dyn Fn(&FrictionIslandReport) -> f64| {
        islands.iter().map(f).collect::<Vec<f64>>().into_pyarray(py)
    };
    d.set_item("coulomb_error", per(&|i| i.error()))?;
    d.set_item("cone_error", per(&|i| i.solution.residuals.cone_error))?;
    let iterations: Vec<u64> = islands.iter().map(|i| i.solution.iterations).collect();
    d.set_item("iterations", iterations.into_pyarray(py))?;
    let warm: Vec<bool> = islands.iter().map(|i| i.warm_started).collect();
    d.set_item("warm_started", warm.into_pyarray(py))
}
