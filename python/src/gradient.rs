//! Gradients of the LCP solve: the library's vector–Jacobian product
//! ([`lcpbatch::gradient::lcp_vjp_batch`]) on dense NumPy batches, for
//! `lcpbatch.lcp_vjp` and the JAX and PyTorch adapters (`python/lcpbatch/`).
//!
//! M (B, n, n) and q (B, n) are read as the solves read them
//! ([`batch::dense`]: finite entries checked, errors naming the index);
//! z, dz and dw (B, n) are read in place when C-ordered, and the library
//! checks their entries (an error naming the island and the field).

use std::time::Instant;

use lcpbatch::gradient::{
    lcp_vjp_batch, lcp_vjp_dense_into, scene_vjp, BodyGradient, Derivative, LcpGradient,
    SceneGradient,
};
use lcpbatch::report::BodyVelocity;
use lcpbatch::Lcp;
use numpy::ndarray::{Array2, Array3, ArrayView2, CowArray, Ix2};
use numpy::{
    IntoPyArray, PyArray1, PyArray2, PyArray3, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2,
    PyReadonlyArray3,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::{batch, guard, scenes, to_py_err};

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
        // In C order: `to_owned` would keep a Fortran-ordered view's order.
        CowArray::from(v.as_standard_layout().into_owned())
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
) -> PyResult<VjpArrays<'py>> {
    let tolerance = tolerance.unwrap_or_else(default_tolerance);
    if let Some(out) = dense_into(py, &m, &q, &z, &dz, dw.as_ref(), tolerance)? {
        return Ok(out);
    }
    let inputs = Inputs::new(&m, &q, &z, &dz, dw.as_ref())?;
    let grads = inputs.vjp(py, tolerance)?;
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

/// The outputs of [`lcp_vjp`] and their three arrays.
type VjpArrays<'py> = (
    Bound<'py, PyArray3<f64>>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray1<i8>>,
);

/// [`lcp_vjp`]'s common case without building the problems: every array
/// C-ordered, of the shapes of one batch, n > 0. The
/// library's [`lcp_vjp_dense_into`] then reads the NumPy arrays in place
/// and writes the gradients straight into the result arrays (GIL
/// released); None for any other case, and where M or q holds a
/// non-finite entry (which the library refuses), for the general path to
/// read (and report errors of) as before.
fn dense_into<'py>(
    py: Python<'py>,
    m: &PyReadonlyArray3<'py, f64>,
    q: &PyReadonlyArray2<'py, f64>,
    z: &PyReadonlyArray2<'py, f64>,
    dz: &PyReadonlyArray2<'py, f64>,
    dw: Option<&PyReadonlyArray2<'py, f64>>,
    tolerance: f64,
) -> PyResult<Option<VjpArrays<'py>>> {
    let (b, n) = q.as_array().dim();
    let same = |a: &PyReadonlyArray2<'py, f64>| a.as_array().dim() == (b, n);
    if n == 0 || m.as_array().dim() != (b, n, n) || !same(z) || !same(dz) || !dw.is_none_or(same) {
        return Ok(None);
    }
    use batch::c_slice as c;
    let (Some(ms), Some(qs), Some(zs), Some(dzs)) = (c(m), c(q), c(z), c(dz)) else {
        return Ok(None);
    };
    let dws = match dw.map(c) {
        None => None,
        Some(Some(s)) => Some(s),
        Some(None) => return Ok(None),
    };
    let gm = PyArray3::<f64>::zeros(py, [b, n, n], false);
    let gq = PyArray2::<f64>::zeros(py, [b, n], false);
    let codes = {
        let (mut gm_rw, mut gq_rw) = (gm.readwrite(), gq.readwrite());
        let (om, oq) = (gm_rw.as_slice_mut()?, gq_rw.as_slice_mut()?);
        py.detach(|| {
            guard(|| {
                lcp_vjp_dense_into(n, ms, qs, zs, dzs, dws, tolerance, om, oq).map_err(to_py_err)
            })
        })
    };
    // The library checks M and q as it goes; a non-finite entry is then
    // named by the general path, as before.
    let codes = match codes {
        Err(_) if !(batch::all_finite(ms) && batch::all_finite(qs)) => return Ok(None),
        codes => codes?,
    };
    let codes: Vec<i8> = codes.into_iter().map(derivative_code).collect();
    Ok(Some((gm, gq, codes.into_pyarray(py))))
}

/// For `bench_overhead.py`: the seconds of `repeats` calls of the library's
/// `lcp_vjp_batch` on the whole batch, timed in Rust (the problems are
/// built before the clock starts); with `dense`, of `lcp_vjp_dense_into`
/// on the arrays in place (C-ordered; the gradients' buffers allocated
/// before the clock starts).
#[pyfunction]
#[pyo3(signature = (m, q, z, dz, repeats, dense=false))]
pub(crate) fn time_lcp_vjp(
    py: Python<'_>,
    m: PyReadonlyArray3<'_, f64>,
    q: PyReadonlyArray2<'_, f64>,
    z: PyReadonlyArray2<'_, f64>,
    dz: PyReadonlyArray2<'_, f64>,
    repeats: usize,
    dense: bool,
) -> PyResult<Vec<f64>> {
    if !dense {
        let inputs = Inputs::new(&m, &q, &z, &dz, None)?;
        return (0..repeats)
            .map(|_| {
                let t = Instant::now();
                inputs.vjp(py, default_tolerance())?;
                Ok(t.elapsed().as_secs_f64())
            })
            .collect();
    }
    use batch::c_slice as c;
    let n = q.as_array().shape()[1];
    let (Some(ms), Some(qs), Some(zs), Some(dzs)) = (c(&m), c(&q), c(&z), c(&dz)) else {
        return Err(PyValueError::new_err("M, q, z, dz: C-ordered arrays"));
    };
    let (mut om, mut oq) = (vec![0.0; ms.len()], vec![0.0; qs.len()]);
    let tolerance = default_tolerance();
    py.detach(|| {
        guard(|| {
            (0..repeats)
                .map(|_| {
                    let t = Instant::now();
                    lcp_vjp_dense_into(n, ms, qs, zs, dzs, None, tolerance, &mut om, &mut oq)
                        .map_err(to_py_err)?;
                    Ok(t.elapsed().as_secs_f64())
                })
                .collect()
        })
    })
}

/// The library's error for scene `s` of the batch ([`scene_vjp`] names
/// its one scene "scene 0").
fn in_scene(e: lcpbatch::Error, s: usize) -> lcpbatch::Error {
    match e {
        lcpbatch::Error::Invalid {
            item,
            field,
            reason,
        } => lcpbatch::Error::invalid(
            item.replacen("scene 0", &format!("scene {s}"), 1),
            field,
            reason,
        ),
        other => other,
    }
}

/// A scene's ∂L/∂(velocities after), (N, 3) linear and angular, either
/// None (0), as the library's one [`BodyVelocity`] per body (None when
/// both are); `ValueError` naming the argument and the scene for a shape
/// that is not (N, 3).
fn body_velocities(
    s: usize,
    v: Option<&PyReadonlyArray2<'_, f64>>,
    w: Option<&PyReadonlyArray2<'_, f64>>,
    bodies: usize,
) -> PyResult<Option<Vec<BodyVelocity>>> {
    if v.is_none() && w.is_none() {
        return Ok(None);
    }
    let view = |a: Option<&PyReadonlyArray2<'_, f64>>, arg: &str| {
        let a = a.map(|a| a.as_array().to_owned());
        match &a {
            Some(x) if x.shape() != [bodies, 3] => Err(PyValueError::new_err(format!(
                "{arg}[{s}]: expected shape ({bodies}, 3), got ({})",
                batch::join(x.shape())
            ))),
            _ => Ok(a),
        }
    };
    let (v, w) = (view(v, "d_velocity")?, view(w, "d_angular_velocity")?);
    let row = |a: &Option<Array2<f64>>, k: usize| {
        a.as_ref()
            .map_or([0.0; 3], |a| [a[[k, 0]], a[[k, 1]], a[[k, 2]]])
    };
    Ok(Some(
        (0..bodies)
            .map(|k| BodyVelocity {
                velocity: row(&v, k),
                angular_velocity: row(&w, k),
            })
            .collect(),
    ))
}

/// One scene's gradient as a dict: `inv_mass` (N,), `inv_inertia` (N, 3, 3),
/// `position`, `velocity`, `angular_velocity` (N, 3), `point`, `normal`
/// (C, 3), `restitution` (C,), `islands` (derivative codes, per island of
/// the scene) and `derivative` (the worst code).
fn scene_gradient_dict<'py>(py: Python<'py>, g: &SceneGradient) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let err = |e: numpy::ndarray::ShapeError| PyValueError::new_err(e.to_string());
    let rows = |v: Vec<f64>| Array2::from_shape_vec((v.len() / 3, 3), v).map_err(err);
    let b = &g.bodies;
    let flat = |v: Vec<f64>| v.into_pyarray(py);
    d.set_item("inv_mass", flat(b.iter().map(|b| b.inv_mass).collect()))?;
    let inertia: Vec<f64> = b
        .iter()
        .flat_map(|b| b.inv_inertia.into_iter().flatten())
        .collect();
    d.set_item(
        "inv_inertia",
        Array3::from_shape_vec((b.len(), 3, 3), inertia)
            .map_err(err)?
            .into_pyarray(py),
    )?;
    for (key, f) in [
        (
            "position",
            (|b: &BodyGradient| b.position) as fn(&BodyGradient) -> [f64; 3],
        ),
        ("velocity", |b| b.velocity),
        ("angular_velocity", |b| b.angular_velocity),
    ] {
        d.set_item(key, rows(b.iter().flat_map(f).collect())?.into_pyarray(py))?;
    }
    let c = &g.contacts;
    d.set_item(
        "point",
        rows(c.iter().flat_map(|c| c.point).collect())?.into_pyarray(py),
    )?;
    d.set_item(
        "normal",
        rows(c.iter().flat_map(|c| c.normal).collect())?.into_pyarray(py),
    )?;
    d.set_item(
        "restitution",
        flat(c.iter().map(|c| c.restitution).collect()),
    )?;
    let islands: Vec<i8> = g.islands.iter().map(|&x| derivative_code(x)).collect();
    d.set_item("islands", islands.into_pyarray(py))?;
    d.set_item("derivative", derivative_code(g.derivative))?;
    Ok(d)
}

/// Per frictionless scene (the dicts of `solve_scenes`), at its contacts'
/// impulses, given ∂L/∂impulses and/or ∂L/∂(velocities after): the library's
/// [`scene_vjp`], one scene after the other with the GIL released; a list
/// of [`scene_gradient_dict`]s. Lengths are checked by the library (an
/// error naming the scene and the field).
#[pyfunction]
#[pyo3(signature = (scenes, impulses, d_impulses=None, d_velocity=None, d_angular_velocity=None, tolerance=None))]
pub(crate) fn scene_vjp_batch<'py>(
    py: Python<'py>,
    scenes: Vec<scenes::SceneArrays<'py>>,
    impulses: Vec<PyReadonlyArray1<'py, f64>>,
    d_impulses: Option<Vec<PyReadonlyArray1<'py, f64>>>,
    d_velocity: Option<Vec<PyReadonlyArray2<'py, f64>>>,
    d_angular_velocity: Option<Vec<PyReadonlyArray2<'py, f64>>>,
    tolerance: Option<f64>,
) -> PyResult<Vec<Bound<'py, PyDict>>> {
    let tolerance = tolerance.unwrap_or_else(default_tolerance);
    let count = |arg: &str, got: Option<usize>| match got {
        Some(k) if k != scenes.len() => Err(PyValueError::new_err(format!(
            "{arg}: expected one array per scene ({}), got {k}",
            scenes.len()
        ))),
        _ => Ok(()),
    };
    count("impulses", Some(impulses.len()))?;
    count("d_impulses", d_impulses.as_ref().map(Vec::len))?;
    count("d_velocity", d_velocity.as_ref().map(Vec::len))?;
    count(
        "d_angular_velocity",
        d_angular_velocity.as_ref().map(Vec::len),
    )?;
    let mut out = Vec::with_capacity(scenes.len());
    for (s, arrays) in scenes.iter().enumerate() {
        let scene = arrays.scene(s)?;
        let z = impulses[s].as_array().to_vec();
        let dz = d_impulses.as_ref().map(|d| d[s].as_array().to_vec());
        let dv = body_velocities(
            s,
            d_velocity.as_ref().map(|d| &d[s]),
            d_angular_velocity.as_ref().map(|d| &d[s]),
            scene.bodies.len(),
        )?;
        let g = py.detach(|| {
            guard(|| {
                scene_vjp(&scene, &z, dz.as_deref(), dv.as_deref(), tolerance)
                    .map_err(|e| to_py_err(in_scene(e, s)))
            })
        })?;
        out.push(scene_gradient_dict(py, &g)?);
    }
    Ok(out)
}
