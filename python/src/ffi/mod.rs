//! XLA FFI handlers of the solve and its VJP, for `lcpbatch.jax`: XLA
//! calls them from inside a compiled JAX program (`jax.ffi.ffi_call`) with
//! pointers to its own buffers, so M, q and the gradients are read and
//! written in place: no host callback, no copy into Python, no GIL.
//!
//! - `lcpbatch_solve`: M (..., n, n), q (..., n), float32 or float64 (one
//!   dtype); results z, w (q's shape and dtype), status (q's shape less its
//!   last axis, int8 codes); attribute `solver` (int64, a [`ffi_register`]
//!   id). The same solve as `NativeSolver.solve_dense_zw` (the adapters'
//!   host path): [`NativeSolver::solve_dense_report`]; the rows of a problem
//!   without a solution are NaN, as `_gradient.forward` makes them.
//! - `lcpbatch_vjp`: M, q, z, dz, dw (as above); results dM, dq; attribute
//!   `tolerance` (float64). The same product as `lcp_vjp` (the library's
//!   [`lcp_vjp_dense_into`]), with `_gradient.backward`'s conventions: dw
//!   all zero counts as none, rows whose z is not finite get NaN.
//!
//! float32 arrays are widened to f64 (exactly) and the results rounded back,
//! as the NumPy path's `astype` does. Every argument's dtype, rank and shape
//! is checked; a bad one, a non-finite entry or a library error comes back
//! as an XLA error whose message names the argument (`JaxRuntimeError` in
//! Python); a panic is caught ([`xla::handle`]) and never crosses into XLA.
//!
//! [`xla`] holds the C API's structs, written by hand from
//! `xla/ffi/api/c_api.h`. XLA asks a handler for its API version through
//! the metadata extension; of the execution stages only `execute` does
//! work (the others return at once).

use std::ffi::{c_int, c_void};
use std::sync::Mutex;

use lcpbatch::gradient::lcp_vjp_dense_into;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::batch;
use crate::solver::NativeSolver;

mod xla;

use xla::{
    buffers, dtype_name, handle, invalid, library, scalar, shape, Buf, CallFrame, Fail, XlaError,
    F32, F64, S64, S8,
};

/// The `lcpbatch_solve` handler (see the module docs).
///
/// # Safety
/// Called by XLA with its call frame.
unsafe extern "C" fn solve_handler(frame: *mut CallFrame) -> *mut XlaError {
    unsafe { handle(frame, solve) }
}

/// The `lcpbatch_vjp` handler (see the module docs).
///
/// # Safety
/// Called by XLA with its call frame.
unsafe extern "C" fn vjp_handler(frame: *mut CallFrame) -> *mut XlaError {
    unsafe { handle(frame, vjp) }
}

/// The handlers as `{name: PyCapsule}`, each capsule holding the bare
/// function pointer (unnamed, as `jax.ffi.pycapsule` makes them), for
/// `jax.ffi.register_ffi_target(name, capsule, platform="cpu")`.
#[pyfunction]
pub(crate) fn ffi_targets(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    type Handler = unsafe extern "C" fn(*mut CallFrame) -> *mut XlaError;
    let d = PyDict::new(py);
    for (name, f) in [
        ("lcpbatch_solve", solve_handler as Handler),
        ("lcpbatch_vjp", vjp_handler as Handler),
    ] {
        // SAFETY: a capsule of a function pointer (never null, lives as long
        // as the extension, which is never unloaded), no destructor.
        let capsule = unsafe {
            Bound::from_owned_ptr_or_err(
                py,
                pyo3::ffi::PyCapsule_New(f as *mut c_void, std::ptr::null(), None),
            )?
        };
        d.set_item(name, capsule)?;
    }
    Ok(d)
}

/// A solver the handlers may use, kept for the process's life: a compiled
/// JAX program holds only its id and may run at any later time.
struct Registered {
    native: Py<NativeSolver>,
    /// The Python `Solver`, for its once-only device-fallback warning.
    solver: Py<PyAny>,
}

static SOLVERS: Mutex<Vec<&'static Registered>> = Mutex::new(Vec::new());

/// Registers a Python `lcpbatch.Solver` for the `lcpbatch_solve` handler and
/// returns its id (the same id for the same object); it is never released.
#[pyfunction]
pub(crate) fn ffi_register(solver: &Bound<'_, PyAny>) -> PyResult<i64> {
    let native = solver.getattr("_native")?.cast_into::<NativeSolver>()?;
    let mut list = SOLVERS.lock().unwrap_or_else(|p| p.into_inner());
    if let Some(k) = list
        .iter()
        .position(|r| r.solver.as_ptr() == solver.as_ptr())
    {
        return Ok(k as i64);
    }
    list.push(Box::leak(Box::new(Registered {
        native: native.unbind(),
        solver: solver.clone().unbind(),
    })));
    Ok(list.len() as i64 - 1)
}

fn registered(id: i64) -> Result<&'static Registered, Fail> {
    let list = SOLVERS.lock().unwrap_or_else(|p| p.into_inner());
    usize::try_from(id)
        .ok()
        .and_then(|k| list.get(k).copied())
        .ok_or_else(|| invalid(format!("solver: no solver registered as {id}")))
}

/// Checks M (..., n, n) and q (..., n) of one float dtype; (n, B, dtype).
fn problem(m: &Buf<'_>, q: &Buf<'_>) -> Result<(usize, usize, c_int), Fail> {
    if m.dtype != F32 && m.dtype != F64 {
        return Err(invalid(format!(
            "M: expected float32 or float64, got {}",
            dtype_name(m.dtype)
        )));
    }
    let r = m.dims.len();
    if r < 2 || m.dims[r - 1] != m.dims[r - 2] {
        return Err(invalid(format!(
            "M: expected shape (..., n, n), got {}",
            shape(m.dims)
        )));
    }
    q.expect(m.dtype, &m.dims[..r - 1], "M (..., n, n) needs q (..., n)")?;
    let n = usize::try_from(m.dims[r - 1])
        .map_err(|_| invalid(format!("M: bad shape {}", shape(m.dims))))?;
    let b = Buf {
        dims: &q.dims[..r - 2],
        ..*q
    }
    .len()?;
    Ok((n, b, m.dtype))
}

/// [`batch::check_finite`] as an XLA error.
fn check_finite(ms: &[f64], qs: &[f64], n: usize) -> Result<(), Fail> {
    batch::check_finite(ms, qs, n).map_err(invalid)
}

/// `lcpbatch_solve`: see the module docs.
fn solve(frame: &CallFrame) -> Result<(), Fail> {
    let [m, q] = buffers(&frame.args, ["M", "q"], "arguments")?;
    let (n, b, dtype) = problem(&m, &q)?;
    let [z, w, status] = buffers(&frame.rets, ["z", "w", "status"], "results")?;
    z.expect(dtype, q.dims, "q")?;
    w.expect(dtype, q.dims, "q")?;
    status.expect(
        S8,
        &q.dims[..q.dims.len() - 1],
        "q less its last axis, int8",
    )?;
    // SAFETY: `scalar` checked the dtype.
    let id = unsafe { *scalar(frame, "solver", S64)?.cast::<i64>() };
    let entry = registered(id)?;
    if b == 0 {
        return Ok(());
    }
    if n == 0 {
        return Err(invalid(
            "M: n = 0: every problem needs at least one row".into(),
        ));
    }
    let (ms, qs) = (m.reals()?, q.reals()?);
    // The library checks every entry as it solves; a non-finite one is
    // then named as the callback path names it.
    let solved = entry.native.get().solve_dense_report(n, &ms, &qs);
    let Some(report) = solved.map_err(|e| {
        check_finite(&ms, &qs, n)
            .err()
            .unwrap_or_else(|| library(e))
    })?
    else {
        return Ok(());
    };
    // SAFETY: `expect` checked the dtypes.
    let codes = unsafe { status.view_mut::<i8>() }?;
    let solved: Vec<bool> = report
        .islands
        .iter()
        .map(|i| i.status().is_solution())
        .collect();
    if dtype == F64 {
        let (zs, ws) = unsafe { (z.view_mut::<f64>()?, w.view_mut::<f64>()?) };
        if !batch::zw_into(&report.islands, zs, ws, codes, |v| v) {
            return Err(short(&report));
        }
        nan_rows(zs, ws, n, &solved, f64::NAN);
    } else {
        let (zs, ws) = unsafe { (z.view_mut::<f32>()?, w.view_mut::<f32>()?) };
        if !batch::zw_into(&report.islands, zs, ws, codes, |v| v as f32) {
            return Err(short(&report));
        }
        nan_rows(zs, ws, n, &solved, f32::NAN);
    }
    match &report.fallback {
        Some(why) => warn_fallback(entry, why),
        None => Ok(()),
    }
}

/// The failure of a report that does not fill the results (a library bug).
fn short(report: &lcpbatch::Report) -> Fail {
    let message = format!(
        "the report's {} islands do not fill z",
        report.islands.len()
    );
    (xla::INTERNAL, message)
}

/// NaN in the rows of z and w of the problems without a solution.
fn nan_rows<T: Copy>(z: &mut [T], w: &mut [T], n: usize, solved: &[bool], nan: T) {
    for ((zr, wr), _) in z
        .chunks_exact_mut(n)
        .zip(w.chunks_exact_mut(n))
        .zip(solved)
        .filter(|(_, &ok)| !ok)
    {
        zr.fill(nan);
        wr.fill(nan);
    }
}

/// The Python `Solver`'s once-only warning that the GPU fell back to the
/// CPU (the callback path gives it too); the one place a handler takes the
/// GIL, and only when the library reports a fallback.
fn warn_fallback(entry: &Registered, why: &str) -> Result<(), Fail> {
    Python::attach(|py| {
        entry
            .solver
            .bind(py)
            .call_method1("_warn_fallback", (why,))
            .map(drop)
            .map_err(|e| invalid(e.to_string()))
    })
}

/// `lcpbatch_vjp`: see the module docs.
fn vjp(frame: &CallFrame) -> Result<(), Fail> {
    let [m, q, z, dz, dw] = buffers(&frame.args, ["M", "q", "z", "dz", "dw"], "arguments")?;
    let (n, b, dtype) = problem(&m, &q)?;
    for x in [&z, &dz, &dw] {
        x.expect(dtype, q.dims, "q")?;
    }
    let [gm, gq] = buffers(&frame.rets, ["dM", "dq"], "results")?;
    gm.expect(dtype, m.dims, "M")?;
    gq.expect(dtype, q.dims, "q")?;
    // SAFETY: `scalar` checked the dtype.
    let tolerance = unsafe { *scalar(frame, "tolerance", F64)?.cast::<f64>() };
    if n == 0 {
        return match b {
            0 => Ok(()),
            _ => Err(invalid(
                "M: n = 0: every problem needs at least one row".into(),
            )),
        };
    }
    let (ms, qs, zs, dzs, dws) = (m.reals()?, q.reals()?, z.reals()?, dz.reals()?, dw.reals()?);
    // The library checks M and q as it goes; a non-finite entry is then
    // named as the callback path names it.
    let named = |e: Fail| check_finite(&ms, &qs, n).err().unwrap_or(e);
    // A zero ∂L/∂w (JAX passes zeros for an unused w) adds nothing.
    let dw = dws.iter().any(|&v| v != 0.0).then_some(&dws[..]);
    if dtype == F64 {
        // SAFETY: `expect` checked the dtypes.
        let (om, oq) = unsafe { (gm.view_mut::<f64>()?, gq.view_mut::<f64>()?) };
        vjp_rows(n, [&ms, &qs, &zs, &dzs], dw, tolerance, om, oq).map_err(named)
    } else {
        let (mut om, mut oq) = (vec![0.0; ms.len()], vec![0.0; qs.len()]);
        vjp_rows(n, [&ms, &qs, &zs, &dzs], dw, tolerance, &mut om, &mut oq).map_err(named)?;
        gm.put(&om)?;
        gq.put(&oq)
    }
}

/// The product into `om`, `oq` as `_gradient.backward` computes it: on the
/// whole batch when z is finite, else on the rows whose z is (gathered
/// into one batch, so an error's island index counts those rows) with NaN
/// gradients for the others.
fn vjp_rows(
    n: usize,
    [m, q, z, dz]: [&[f64]; 4],
    dw: Option<&[f64]>,
    tolerance: f64,
    om: &mut [f64],
    oq: &mut [f64],
) -> Result<(), Fail> {
    if batch::all_finite(z) {
        return lcp_vjp_dense_into(n, m, q, z, dz, dw, tolerance, om, oq)
            .map(drop)
            .map_err(library);
    }
    let ok: Vec<bool> = z.chunks_exact(n).map(batch::all_finite).collect();
    let pick = |a: &[f64], per: usize| -> Vec<f64> {
        a.chunks_exact(per)
            .zip(&ok)
            .filter(|(_, &k)| k)
            .flat_map(|(r, _)| r.iter().copied())
            .collect()
    };
    let (pm, pq, pz, pdz) = (pick(m, n * n), pick(q, n), pick(z, n), pick(dz, n));
    let pdw = dw.map(|d| pick(d, n));
    let (mut gm, mut gq) = (vec![0.0; pm.len()], vec![0.0; pq.len()]);
    lcp_vjp_dense_into(
        n,
        &pm,
        &pq,
        &pz,
        &pdz,
        pdw.as_deref(),
        tolerance,
        &mut gm,
        &mut gq,
    )
    .map_err(library)?;
    let (mut gm_rows, mut gq_rows) = (gm.chunks_exact(n * n), gq.chunks_exact(n));
    for ((rm, rq), &k) in om
        .chunks_exact_mut(n * n)
        .zip(oq.chunks_exact_mut(n))
        .zip(&ok)
    {
        let rows = if k {
            gm_rows.next().zip(gq_rows.next())
        } else {
            None
        };
        match rows {
            Some((a, b)) => {
                rm.copy_from_slice(a);
                rq.copy_from_slice(b);
            }
            _ => {
                rm.fill(f64::NAN);
                rq.fill(f64::NAN);
            }
        }
    }
    Ok(())
}
