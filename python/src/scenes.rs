//! Scenes from arrays: one dict of arrays per scene (built and shape-checked
//! by `lcpbatch/_scenes.py`), [`Scene`]s for the library, and impulses and
//! velocities back as flat arrays.
//!
//! Layout of one scene (N bodies, C contacts):
//! - bodies: `inv_mass` (N,), `inv_inertia` (N, 3, 3) world frame,
//!   `position`, `velocity`, `angular_velocity` (N, 3);
//! - contacts: `a`, `b` (C,) int64 body indices, `b` = −1 for the static
//!   world; `point`, `normal` (C, 3); `restitution` (C,); `mu` (C,)
//!   Coulomb friction coefficients (0: frictionless); `tangent` (C, 3) the
//!   caller's first tangent t₁ or None (the library's basis); `id` (C,)
//!   uint64 or None (contact ids for warm start).
//!
//! The library's own checks (`Scene::validate`) name the scene, the body or
//! contact and the field.

use lcpbatch::{Body, Contact, Report, Scene};
use numpy::ndarray::ArrayView2;
use numpy::{IntoPyArray, PyReadonlyArray1, PyReadonlyArray2, PyReadonlyArray3};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// At most this many contacts per chunk of scenes (a scene is never split).
pub(crate) const CHUNK_CONTACTS: usize = 65_536;

/// One scene's arrays, read from a dict with these keys.
#[derive(FromPyObject)]
#[pyo3(from_item_all)]
pub(crate) struct SceneArrays<'py> {
    inv_mass: PyReadonlyArray1<'py, f64>,
    inv_inertia: PyReadonlyArray3<'py, f64>,
    position: PyReadonlyArray2<'py, f64>,
    velocity: PyReadonlyArray2<'py, f64>,
    angular_velocity: PyReadonlyArray2<'py, f64>,
    a: PyReadonlyArray1<'py, i64>,
    b: PyReadonlyArray1<'py, i64>,
    point: PyReadonlyArray2<'py, f64>,
    normal: PyReadonlyArray2<'py, f64>,
    restitution: PyReadonlyArray1<'py, f64>,
    mu: PyReadonlyArray1<'py, f64>,
    tangent: Option<PyReadonlyArray2<'py, f64>>,
    id: Option<PyReadonlyArray1<'py, u64>>,
}

fn vec3(v: &ArrayView2<f64>, k: usize) -> [f64; 3] {
    [v[[k, 0]], v[[k, 1]], v[[k, 2]]]
}

fn body_index(
    scene: usize,
    field: &str,
    k: usize,
    v: i64,
    world_ok: bool,
) -> PyResult<Option<usize>> {
    match v {
        -1 if world_ok => Ok(None),
        v if v >= 0 => Ok(Some(v as usize)),
        v => Err(PyValueError::new_err(format!(
            "contacts[{scene}]['{field}'][{k}] is {v}: a body index must be ≥ 0{}",
            if world_ok {
                " (or −1 for the static world)"
            } else {
                ""
            }
        ))),
    }
}

impl SceneArrays<'_> {
    /// The library's scene; `index` is the scene's place in the batch.
    pub(crate) fn scene(&self, index: usize) -> PyResult<Scene> {
        let (inertia, pos, vel, ang) = (
            self.inv_inertia.as_array(),
            self.position.as_array(),
            self.velocity.as_array(),
            self.angular_velocity.as_array(),
        );
        let bodies = self
            .inv_mass
            .as_array()
            .iter()
            .enumerate()
            .map(|(k, &inv_mass)| {
                // Through the constructor, so that fields the library adds
                // later keep their defaults here.
                let mut b = Body::new(inv_mass, [0.0; 3], vec3(&pos, k));
                b.inv_inertia =
                    std::array::from_fn(|i| std::array::from_fn(|j| inertia[[k, i, j]]));
                b.velocity = vec3(&vel, k);
                b.angular_velocity = vec3(&ang, k);
                b
            })
            .collect();
        let (point, normal, rest) = (
            self.point.as_array(),
            self.normal.as_array(),
            self.restitution.as_array(),
        );
        let ids = self.id.as_ref().map(|i| i.as_array());
        let mu = self.mu.as_array();
        let tangent = self.tangent.as_ref().map(|t| t.as_array());
        let (a, b) = (self.a.as_array(), self.b.as_array());
        let mut contacts = Vec::with_capacity(a.len());
        for k in 0..a.len() {
            let mut c = Contact::new(
                body_index(index, "a", k, a[k], false)?.unwrap_or(0),
                body_index(index, "b", k, b[k], true)?,
                vec3(&point, k),
                vec3(&normal, k),
                rest[k],
            );
            c.id = ids.as_ref().map(|i| i[k]);
            // Checked by the library's Contact::validate (finite, ≥ 0; a
            // tangent unit and orthogonal to the normal).
            c.friction = mu[k];
            c.tangent = tangent.as_ref().map(|t| vec3(t, k));
            contacts.push(c);
        }
        Ok(Scene { bodies, contacts })
    }
}

/// Consecutive chunks of scenes with at most [`CHUNK_CONTACTS`] contacts
/// each (a larger scene is a chunk of its own).
pub(crate) fn chunks(scenes: &[Scene]) -> Vec<std::ops::Range<usize>> {
    let mut out = Vec::new();
    let (mut start, mut contacts) = (0, 0);
    for (i, s) in scenes.iter().enumerate() {
        if i > start && contacts + s.contacts.len() > CHUNK_CONTACTS {
            out.push(start..i);
            start = i;
            contacts = 0;
        }
        contacts += s.contacts.len();
    }
    if start < scenes.len() {
        out.push(start..scenes.len());
    }
    out
}

/// (total contacts, 3) rows from a flat vector of triples.
fn rows3(v: Vec<f64>) -> PyResult<numpy::ndarray::Array2<f64>> {
    let rows = v.len() / 3;
    numpy::ndarray::Array2::from_shape_vec((rows, 3), v)
        .map_err(|e| PyValueError::new_err(e.to_string()))
}

/// Per contact of every scene: the impulse vector on body a in the world
/// frame (`impulse`, (C, 3)) and its tangential parts in the contact's frame
/// (`tangential`, (C, 2)). A frictionless scene's impulse is z n (tangential
/// 0); a frictional scene's comes from [`lcpbatch::SceneFriction`].
fn contact_vectors(
    py: Python<'_>,
    d: &Bound<'_, PyDict>,
    scenes: &[Scene],
    r: &Report,
) -> PyResult<()> {
    let (mut vec, mut tangential) = (Vec::new(), Vec::new());
    for (scene, s) in scenes.iter().zip(&r.scenes) {
        match &s.friction {
            Some(f) => {
                for c in &f.contacts {
                    vec.extend_from_slice(&c.impulse);
                    tangential.extend_from_slice(&c.tangential);
                }
            }
            None => {
                for (c, z) in scene.contacts.iter().zip(&s.impulses) {
                    vec.extend(c.normal.iter().map(|n| n * z));
                    tangential.extend_from_slice(&[0.0, 0.0]);
                }
            }
        }
    }
    let rows = tangential.len() / 2;
    d.set_item("impulse", rows3(vec)?.into_pyarray(py))?;
    let tangential = numpy::ndarray::Array2::from_shape_vec((rows, 2), tangential)
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
    d.set_item("tangential", tangential.into_pyarray(py))
}

/// The frictional islands as flat arrays: `friction_scene`, `friction_status`
/// (codes), `friction_error` (Coulomb error), `friction_cone_error`,
/// `friction_iterations`, and `friction_contacts` (the scene's contact
/// indices, flat) with `friction_offsets` (F + 1).
pub(crate) fn friction_islands_into(
    py: Python<'_>,
    d: &Bound<'_, PyDict>,
    r: &Report,
) -> PyResult<()> {
    let f = &r.friction;
    let scene: Vec<i64> = f.iter().map(|i| i.scene.map_or(-1, |s| s as i64)).collect();
    d.set_item("friction_scene", scene.into_pyarray(py))?;
    let status: Vec<i8> = f
        .iter()
        .map(|i| crate::report::status_code(i.status()))
        .collect();
    d.set_item("friction_status", status.into_pyarray(py))?;
    let error: Vec<f64> = f.iter().map(|i| i.error()).collect();
    d.set_item("friction_error", error.into_pyarray(py))?;
    let cone: Vec<f64> = f.iter().map(|i| i.solution.residuals.cone_error).collect();
    d.set_item("friction_cone_error", cone.into_pyarray(py))?;
    let iterations: Vec<u64> = f.iter().map(|i| i.solution.iterations).collect();
    d.set_item("friction_iterations", iterations.into_pyarray(py))?;
    let mut offsets = vec![0i64];
    let mut contacts = Vec::new();
    for i in f {
        contacts.extend(i.contacts.iter().map(|&c| c as i64));
        offsets.push(contacts.len() as i64);
    }
    d.set_item("friction_contacts", contacts.into_pyarray(py))?;
    d.set_item("friction_offsets", offsets.into_pyarray(py))
}

/// Per scene results into `d`: `impulses` (normal parts) flat with
/// `contact_offsets` (S + 1), `impulse` (C, 3) and `tangential` (C, 2) per
/// contact (see [`contact_vectors`]), `velocity` and `angular_velocity`
/// (total bodies, 3) with `body_offsets`; per island `island_scene` and
/// `island_contacts` (flat, laid out like z) besides the island arrays of
/// [`crate::batch::islands_into`], and the frictional islands of
/// [`friction_islands_into`].
pub(crate) fn scenes_into(
    py: Python<'_>,
    d: &Bound<'_, PyDict>,
    scenes: &[Scene],
    r: &Report,
) -> PyResult<()> {
    contact_vectors(py, d, scenes, r)?;
    friction_islands_into(py, d, r)?;
    let mut impulses = Vec::new();
    let (mut vel, mut ang) = (Vec::new(), Vec::new());
    let (mut contact_offsets, mut body_offsets) = (vec![0i64], vec![0i64]);
    for s in &r.scenes {
        impulses.extend_from_slice(&s.impulses);
        for b in &s.bodies {
            vel.extend_from_slice(&b.velocity);
            ang.extend_from_slice(&b.angular_velocity);
        }
        contact_offsets.push(impulses.len() as i64);
        body_offsets.push((vel.len() / 3) as i64);
    }
    let rows = vel.len() / 3;
    let shaped = |v: Vec<f64>| numpy::ndarray::Array2::from_shape_vec((rows, 3), v);
    let err = |e: numpy::ndarray::ShapeError| PyValueError::new_err(e.to_string());
    d.set_item("impulses", impulses.into_pyarray(py))?;
    d.set_item("velocity", shaped(vel).map_err(err)?.into_pyarray(py))?;
    d.set_item(
        "angular_velocity",
        shaped(ang).map_err(err)?.into_pyarray(py),
    )?;
    d.set_item("contact_offsets", contact_offsets.into_pyarray(py))?;
    d.set_item("body_offsets", body_offsets.into_pyarray(py))?;
    let scene: Vec<i64> = r
        .islands
        .iter()
        .map(|i| i.scene.map_or(-1, |s| s as i64))
        .collect();
    d.set_item("island_scene", scene.into_pyarray(py))?;
    let contacts: Vec<i64> = r
        .islands
        .iter()
        .flat_map(|i| i.contacts.iter().map(|&c| c as i64))
        .collect();
    d.set_item("island_contacts", contacts.into_pyarray(py))?;
    crate::batch::islands_into(py, d, &r.islands)
}
