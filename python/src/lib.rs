//! `lcpbatch._native`: the Rust side of the Python package, a thin client of
//! the library's one door ([`lcpbatch::Solver`]).
//!
//! It converts NumPy arrays into the library's [`lcpbatch::Lcp`] and
//! [`lcpbatch::Scene`], solves in chunks with the GIL released (checking for
//! Ctrl-C between chunks), and hands back plain dicts of NumPy arrays that
//! the Python package (`python/lcpbatch/`) wraps in result classes. Argument
//! checks that need no solver (shapes, dtypes) live in Python; the checks of
//! the values (finite entries, the library's own `validate`) happen here and
//! become `ValueError`s naming the argument, the index and the fault.
//!
//! Gradients: [`gradient`] binds the library's vector–Jacobian product of
//! the solve (`lcpbatch.lcp_vjp`, and the JAX and PyTorch adapters);
//! [`ffi`] exports the solve and the product as XLA FFI handlers, which
//! `lcpbatch.jax` calls from inside compiled JAX programs.
//!
//! No Rust panic reaches Python: every call into the library runs under
//! [`guard`], which turns a panic into a `RuntimeError`.

use std::panic::{catch_unwind, AssertUnwindSafe};

use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

mod batch;
mod ffi;
mod friction;
mod gradient;
mod report;
mod scenes;
mod settings;
mod solver;
mod worlds;

/// The library's error as the Python exception a NumPy user expects: bad
/// values and unsupported requests are `ValueError`s, the rest `RuntimeError`.
pub(crate) fn to_py_err(e: lcpbatch::Error) -> PyErr {
    match e {
        lcpbatch::Error::Invalid { .. } | lcpbatch::Error::Unsupported(_) => {
            PyValueError::new_err(e.to_string())
        }
        other => PyRuntimeError::new_err(other.to_string()),
    }
}

/// Runs `f`, turning a panic into a `RuntimeError` that carries its message
/// (the library catches wgpu's panics itself; this is the last net).
pub(crate) fn guard<T>(f: impl FnOnce() -> PyResult<T>) -> PyResult<T> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(payload) => Err(PyRuntimeError::new_err(format!(
            "lcpbatch internal error (a bug, please report it): {}",
            panic_message(&payload)
        ))),
    }
}

/// A caught panic's message ("unknown panic" when it carries none).
pub(crate) fn panic_message(payload: &Box<dyn std::any::Any + Send>) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".into())
}

/// Every adapter wgpu finds on `api` ("auto", "vulkan", "gl", "metal",
/// "dx12"), as dicts; empty when there is none.
#[pyfunction]
#[pyo3(signature = (api = "auto"))]
fn adapters<'py>(py: Python<'py>, api: &str) -> PyResult<Vec<Bound<'py, PyDict>>> {
    let api = lcpbatch::BackendChoice::parse(api).map_err(to_py_err)?;
    let found = py.detach(|| guard(|| Ok(lcpbatch::device::list_adapters(api))))?;
    found
        .into_iter()
        .map(|a| {
            let d = PyDict::new(py);
            d.set_item("name", a.name)?;
            d.set_item("backend", a.backend)?;
            d.set_item("device_type", a.device_type)?;
            d.set_item("driver", a.driver)?;
            d.set_item("software", a.software)?;
            d.set_item("f64", a.f64)?;
            Ok(d)
        })
        .collect()
}

/// Names of the statuses in the order of their codes (`lcpbatch::Status::ALL`).
#[pyfunction]
fn status_names() -> Vec<&'static str> {
    lcpbatch::Status::ALL.iter().map(|s| s.name()).collect()
}

/// Names of the solve paths in the order of their codes.
#[pyfunction]
fn path_names() -> Vec<&'static str> {
    report::PATHS.iter().map(|p| p.name()).collect()
}

/// Panics inside the guard: the tests' proof that a panic becomes a
/// `RuntimeError` and never reaches Python as a panic.
#[pyfunction]
fn _panic_for_test() -> PyResult<()> {
    guard(|| -> PyResult<()> { panic!("deliberate panic for the test of the guard") })
}

/// The extension module.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<solver::NativeSolver>()?;
    m.add_class::<worlds::NativeWorld>()?;
    m.add_function(wrap_pyfunction!(adapters, m)?)?;
    m.add_function(wrap_pyfunction!(status_names, m)?)?;
    m.add_function(wrap_pyfunction!(path_names, m)?)?;
    m.add_function(wrap_pyfunction!(_panic_for_test, m)?)?;
    m.add_function(wrap_pyfunction!(gradient::lcp_vjp, m)?)?;
    m.add_function(wrap_pyfunction!(gradient::derivative_names, m)?)?;
    m.add_function(wrap_pyfunction!(gradient::time_lcp_vjp, m)?)?;
    m.add_function(wrap_pyfunction!(gradient::scene_vjp_batch, m)?)?;
    m.add_function(wrap_pyfunction!(ffi::ffi_targets, m)?)?;
    m.add_function(wrap_pyfunction!(ffi::ffi_register, m)?)?;
    m.add("DEFAULT_VJP_TOLERANCE", gradient::default_tolerance())?;
    m.add("CHUNK_PROBLEMS", batch::CHUNK_PROBLEMS)?;
    m.add("CHUNK_WORK", batch::CHUNK_WORK)?;
    m.add("CHUNK_CONTACTS", scenes::CHUNK_CONTACTS)?;
    m.add("CHUNK_FRICTION_WORK", friction::CHUNK_FRICTION_WORK)?;
    Ok(())
}
