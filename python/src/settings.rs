//! The Python keyword arguments of `lcpbatch.Solver(...)` as the library's
//! [`lcpbatch::Settings`]. Each name is checked here (an unknown word is a
//! `ValueError` naming the argument and the words it accepts); the ranges are
//! checked by [`lcpbatch::Settings::validate`] when the solver is built.

use lcpbatch::{Backend, BackendChoice, FrictionMethod, Method, Precision, Settings};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

/// The arguments of `NativeSolver(...)`, as Python passes them (one struct,
/// so that the constructor's signature stays one list).
pub(crate) struct Args<'a> {
    pub backend: &'a str,
    /// "auto", "enum" (or "enumeration"), "lemke" or "pgs": the Python
    /// keyword `method` (its deprecated alias `solver` is resolved in Python).
    pub method: &'a str,
    pub precision: &'a str,
    pub all_solutions: bool,
    pub warm_start: bool,
    /// Python calls (a call's chunks are one, see `run_chunks`) a contact
    /// id is remembered without being seen again; at least 1.
    pub warm_start_calls: usize,
    pub tolerance: Option<f64>,
    pub threads: usize,
    pub adapter: Option<String>,
    pub api: &'a str,
    pub predict: bool,
    pub lemke_max_pivots: Option<u64>,
    pub pgs_max_sweeps: Option<u64>,
    pub pgs_tolerance: Option<f64>,
    /// "auto", "nsgs", "newton", "prox", "jacobi", "pgs" or "apgd" (islands and
    /// problems with friction).
    pub friction_method: &'a str,
    pub friction_tolerance: Option<f64>,
    pub friction_max_iterations: Option<u64>,
}

fn bad(arg: &str, got: &str, allowed: &str) -> PyErr {
    PyValueError::new_err(format!("{arg}: '{got}' is not one of {allowed}"))
}

/// `backend`: "auto", "cpu" or "gpu".
fn backend(s: &str) -> PyResult<Backend> {
    match s.to_ascii_lowercase().as_str() {
        "auto" => Ok(Backend::Auto),
        "cpu" => Ok(Backend::Cpu),
        "gpu" => Ok(Backend::Gpu),
        _ => Err(bad("backend", s, "'auto', 'cpu', 'gpu'")),
    }
}

/// `method`: "auto", "enum" (or "enumeration"), "lemke" or "pgs".
fn method(s: &str) -> PyResult<Method> {
    match s.to_ascii_lowercase().as_str() {
        "auto" => Ok(Method::Auto),
        "enum" | "enumeration" => Ok(Method::Enumeration),
        "lemke" => Ok(Method::Lemke),
        "pgs" => Ok(Method::Pgs),
        _ => Err(bad("method", s, "'auto', 'enum', 'lemke', 'pgs'")),
    }
}

impl Args<'_> {
    /// The library's settings; `ValueError` naming the argument at fault.
    pub fn settings(&self) -> PyResult<Settings> {
        let mut s = Settings::new(backend(self.backend)?, method(self.method)?);
        s.gpu.precision = Precision::parse(self.precision)
            .map_err(|_| bad("precision", self.precision, "'auto', 'f32', 'f64'"))?;
        s.gpu.api = BackendChoice::parse(self.api)
            .map_err(|_| bad("api", self.api, "'auto', 'vulkan', 'gl', 'metal', 'dx12'"))?;
        s.gpu.adapter = self.adapter.clone();
        s.all_solutions = self.all_solutions;
        s.warm_start = self.warm_start;
        s.warm_start_calls = self.warm_start_calls;
        s.threads = self.threads;
        s.predict = self.predict;
        if let Some(t) = self.tolerance {
            s.tolerance = t;
        }
        if let Some(p) = self.lemke_max_pivots {
            s.lemke_max_pivots = p;
        }
        if let Some(p) = self.pgs_max_sweeps {
            s.pgs_max_sweeps = p;
        }
        if let Some(t) = self.pgs_tolerance {
            s.pgs_tolerance = t;
        }
        s.friction_method = self
            .friction_method
            .to_ascii_lowercase()
            .parse::<FrictionMethod>()
            .map_err(|_| {
                bad(
                    "friction_method",
                    self.friction_method,
                    "'auto', 'nsgs', 'newton', 'prox', 'jacobi', 'pgs', 'apgd'",
                )
            })?;
        if let Some(t) = self.friction_tolerance {
            s.friction_tolerance = t;
        }
        if let Some(n) = self.friction_max_iterations {
            s.friction_max_iterations = n;
        }
        // Python reports device trouble as a DeviceWarning (from the
        // report's fallback): the library's stderr line would say it twice.
        s.warn_on_stderr = false;
        // "settings: tolerance: 2 is not in (0, 1)" names the argument too.
        s.validate().map_err(crate::to_py_err)?;
        Ok(s)
    }
}
