//! Gradients of the LCP solve: the library's vector–Jacobian product
//! ([`lcpbatch::gradient::lcp_vjp_batch`]) on dense NumPy batches, for
//! `lcpbatch.lcp_vjp` and the JAX and PyTorch adapters (`python/lcpbatch/`).
//!
//! M (B, n, n) and q (B, n) are read as the solves read them
//! ([`batch::dense`]: finite entries checked, errors naming the index);
//! z, dz and dw (B, n) are read in place when C-ordered, and the library
//! checks their entries (an error naming the island and the field).

use std::time::Instant;

use lcpbatch::gradient::{lcp_vjp_batch, Derivative, LcpGradient};
use lcpbatch::Lcp;
use numpy::ndarray::{Array2, Array3, ArrayView2, CowArray, Ix2};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArray3, PyReadonlyArray2, PyReadonlyArray3};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::{batch, guard, to_py_err};

/// Names of the derivative kinds in the order of their codes.
#[pyfunction]
pub(crate) fn derivative_names() -> Vec<&'static str> {
    Derivative::ALL.iter().map(|d| d.name()).collect()
}

/// The code of a kind: its place in [`Derivative::ALL`].
fn derivative_code(d: Derivative) -> i8 {
    Derivative::ALL
        .iter()
        .position(|&x| x == d)
        .map_or(-1, |k| k as i8)
}

/// A (B, n) argument as C-ordered rows: a view when it already is, a copy
/// otherwise; `ValueError` naming `arg` when its shape is not `shape`.
fn rows_of<'a>(
    a: &'a PyReadonlyArray2<'_, f64>,
    arg: &str,
    shape: &[usize],
) -> PyResult<CowArray<'a, f64, Ix2>> {
    let v: ArrayView2<'a, f64> = a.as_array();
    if v.shape() != shape {
        return Err(PyValueError::new_err(format!(
            "{arg}: expected shape ({}) to match q, got ({})",
            batch::join(shape),
            batch::join(v.shape())
        )));
    }
    Ok(if v.is_standard_layout() {
        CowArray::from(v)
    } else {
        CowArray::from(v.to_owned())
    })
}

/// The rows of a C-ordered (B, n) array as slices (B empty slices for n = 0).
fn slices<'a>(a: &'a CowArray<'_, f64, Ix2>) -> Vec<&'a [f64]> {
    let (b, n) = a.dim();
    match a.as_slice() {
        Some(s) if n > 0 => s.chunks_exact(n).collect(),
        _ => vec![&[][..]; b],
    }
}

/// The problems and the rows of z, dz and dw of one call, checked.
struct Inputs<'a> {
    lcps: Vec<Lcp>,
    z: CowArray<'a, f64, Ix2>,
    dz: CowArray<'a, f64, Ix2>,
    dw: Option<CowArray<'a, f64, Ix2>>,
}

impl<'a> Inputs<'a> {
    fn new(
        m: &PyReadonlyArray3<'_, f64>,
        q: &PyReadonlyArray2<'_, f64>,
        z: &'a PyReadonlyArray2<'_, f64>,
        dz: &'a PyReadonlyArray2<'_, f64>,
        dw: Option<&'a PyReadonlyArray2<'_, f64>>,
    ) -> PyResult<Self> {
        let lcps = batch::dense(m, q)?;
        let shape = q.as_array().shape().to_vec();
        Ok(Inputs {
            lcps,
            z: rows_of(z, "z", &shape)?,
            dz: rows_of(dz, "dz", &shape)?,
            dw: dw.map(|d| rows_of(d, "dw", &shape)).transpose()?,
        })
    }

    /// The library's batched product, GIL released.
    fn vjp(&self, py: Python<'_>, tolerance: f64) -> PyResult<Vec<LcpGradient>> {
        let (z, dz) = (slices(&self.z), slices(&self.dz));
        let dw = self.dw.as_ref().map(slices);
        let lcps = &self.lcps;
        py.detach(|| {
            guard(|| lcp_vjp_batch(lcps, &z, &dz, dw.as_deref(), tolerance).map_err(to_py_err))
        })
    }
}

/// The default relative tolerance of the product's scale τ: the solver's
/// default `tolerance`, which judges the solutions the product starts from.
pub(crate) fn default_tolerance() -> f64 {
    lcpbatch::Settings::default().tolerance
}

/// ∂L/∂M (B, n, n), ∂L/∂q (B, n) and the derivative codes (B,) int8 (see
/// [`derivative_names`]) of a dense batch at its solutions z, given ∂L/∂z
/// and optionally ∂L/∂w (shapes and dtypes checked in Python).
#[pyfunction]
#[pyo3(signature = (m, q, z, dz, dw=None, tolerance=None))]
#[allow(clippy::type_complexity)]
pub(crate) fn lcp_vjp<'py>(
    py: Python<'py>,
    m: PyReadonlyArray3<'py, f64>,
    q: PyReadonlyArray2<'py, f64>,
    z: PyReadonlyArray2<'py, f64>,
    dz: PyReadonlyArray2<'py, f64>,
    dw: Option<PyReadonlyArray2<'py, f64>>,
    tolerance: Option<f64>,
) -> PyResult<(
    Bound<'py, PyArray3<f64>>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray1<i8>>,
)> {
    let inputs = Inputs::new(&m, &q, &z, &dz, dw.as_ref())?;
    let grads = inputs.vjp(py, tolerance.unwrap_or_else(default_tolerance))?;
    let (b, n) = inputs.z.dim();
    let (mut gm, mut gq) = (Vec::with_capacity(b * n * n), Vec::with_capacity(b * n));
    for g in &grads {
        gm.extend_from_slice(&g.m);
        gq.extend_from_slice(&g.q);
    }
    let codes: Vec<i8> = grads
        .iter()
        .map(|g| derivative_code(g.derivative))
        .collect();
    let err = |e: numpy::ndarray::ShapeError| PyValueError::new_err(e.to_string());
    Ok((
        Array3::from_shape_vec((b, n, n), gm)
            .map_err(err)?
            .into_pyarray(py),
        Array2::from_shape_vec((b, n), gq)
            .map_err(err)?
            .into_pyarray(py),
        codes.into_pyarray(py),
    ))
}

/// For `bench_overhead.py`: the seconds of `repeats` calls of the library's
/// `lcp_vjp_batch` on the whole batch, timed in Rust (the problems are
/// built before the clock starts).
#[pyfunction]
pub(crate) fn time_lcp_vjp(
    py: Python<'_>,
    m: PyReadonlyArray3<'_, f64>,
    q: PyReadonlyArray2<'_, f64>,
    z: PyReadonlyArray2<'_, f64>,
    dz: PyReadonlyArray2<'_, f64>,
    repeats: usize,
) -> PyResult<Vec<f64>> {
    let inputs = Inputs::new(&m, &q, &z, &dz, None)?;
    (0..repeats)
        .map(|_| {
            let t = Instant::now();
            inputs.vjp(py, default_tolerance())?;
            Ok(t.elapsed().as_secs_f64())
        })
        .collect()
}
