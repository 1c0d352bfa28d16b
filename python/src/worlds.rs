//! Worlds in time: `NativeWorld` holds one [`lcpbatch::World`] (from the
//! library's strict JSON world format or a standard generator), hands its
//! state out as NumPy arrays and takes a new state back; the solver's
//! `step_worlds` (in `solver.rs`) advances a batch of them.

use lcpbatch::world::format::{parse_worlds, worlds_to_json};
use lcpbatch::world::generate::{standard_world, WorldKind};
use lcpbatch::world::{World, WorldStepReport};
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray2, PyReadonlyArray2};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::to_py_err;

/// One world of bodies under gravity (see the module docs).
#[pyclass(module = "lcpbatch._native")]
#[derive(Clone)]
pub(crate) struct NativeWorld {
    pub(crate) world: World,
}

/// (N, D) rows from each body's `f`.
fn rows<const D: usize>(
    w: &World,
    f: impl Fn(&lcpbatch::world::RigidBody) -> [f64; D],
) -> Array2<f64> {
    let flat: Vec<f64> = w.bodies.iter().flat_map(f).collect();
    Array2::from_shape_vec((w.bodies.len(), D), flat).expect("N rows of D")
}

/// Row `k` of a state array named `name`, shape (N, D) checked.
fn take<const D: usize>(
    a: &Option<PyReadonlyArray2<f64>>,
    name: &str,
    n: usize,
) -> PyResult<Option<Vec<[f64; D]>>> {
    let Some(a) = a else { return Ok(None) };
    let v = a.as_array();
    if v.shape() != [n, D] {
        return Err(PyValueError::new_err(format!(
            "{name}: expected shape ({n}, {D}), got {:?}",
            v.shape()
        )));
    }
    Ok(Some(
        v.outer_iter()
            .map(|r| std::array::from_fn(|i| r[i]))
            .collect(),
    ))
}

#[pymethods]
impl NativeWorld {
    /// Every world of a world file's text (`{"worlds": [...]}` or one
    /// world object); errors name the world, the body and the field.
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<Vec<NativeWorld>> {
        let worlds = parse_worlds("world text", text).map_err(to_py_err)?;
        Ok(worlds
            .into_iter()
            .map(|world| NativeWorld { world })
            .collect())
    }

    /// A standard world: `kind` one of the library's generator kinds, `size`
    /// (None: the kind's default), `seed`.
    #[staticmethod]
    #[pyo3(signature = (kind, size=None, seed=0))]
    fn generate(kind: &str, size: Option<usize>, seed: u64) -> PyResult<NativeWorld> {
        let text = match size {
            Some(n) => format!("{kind}:{n}"),
            None => kind.to_string(),
        };
        let (kind, size) = WorldKind::parse("World.generate", &text).map_err(to_py_err)?;
        Ok(NativeWorld {
            world: standard_world(kind, size, seed),
        })
    }

    /// Names of the generator kinds.
    #[staticmethod]
    fn kinds() -> Vec<&'static str> {
        WorldKind::ALL.iter().map(|(_, n)| *n).collect()
    }

    /// An independent copy (the same bits, runtime state included).
    fn copy(&self) -> NativeWorld {
        self.clone()
    }

    /// The world in the library's JSON world format.
    fn to_json(&self) -> String {
        worlds_to_json(std::slice::from_ref(&self.world))
    }

    /// Number of bodies (planes and other static bodies included).
    fn bodies(&self) -> usize {
        self.world.bodies.len()
    }

    /// Per body: "sphere", "box" or "plane".
    fn shapes(&self) -> Vec<&'static str> {
        self.world
            .bodies
            .iter()
            .map(|b| match b.shape {
                lcpbatch::world::Shape::Sphere { .. } => "sphere",
                lcpbatch::world::Shape::Box { .. } => "box",
                lcpbatch::world::Shape::Plane { .. } => "plane",
            })
            .collect()
    }

    /// Per body: static (never moves).
    fn fixed(&self) -> Vec<bool> {
        self.world.bodies.iter().map(|b| b.fixed).collect()
    }

    /// Per body: asleep.
    fn asleep(&self) -> Vec<bool> {
        self.world.bodies.iter().map(|b| b.asleep).collect()
    }

    /// The state as four arrays: positions (N, 3), orientations (N, 4)
    /// quaternions [x, y, z, w], velocities (N, 3), angular velocities (N, 3).
    #[allow(clippy::type_complexity)]
    fn state<'py>(
        &self,
        py: Python<'py>,
    ) -> (
        Bound<'py, PyArray2<f64>>,
        Bound<'py, PyArray2<f64>>,
        Bound<'py, PyArray2<f64>>,
        Bound<'py, PyArray2<f64>>,
    ) {
        let w = &self.world;
        (
            rows(w, |b| b.position).into_pyarray(py),
            rows(w, |b| b.orientation).into_pyarray(py),
            rows(w, |b| b.velocity).into_pyarray(py),
            rows(w, |b| b.angular_velocity).into_pyarray(py),
        )
    }

    /// Replaces the arrays given (None keeps that part); the world is then
    /// checked by the library (a non-unit quaternion, a NaN: `ValueError`
    /// naming the body and the field) and left unchanged when it fails.
    #[pyo3(signature = (positions=None, orientations=None, velocities=None, angular_velocities=None))]
    fn set_state(
        &mut self,
        positions: Option<PyReadonlyArray2<f64>>,
        orientations: Option<PyReadonlyArray2<f64>>,
        velocities: Option<PyReadonlyArray2<f64>>,
        angular_velocities: Option<PyReadonlyArray2<f64>>,
    ) -> PyResult<()> {
        let n = self.world.bodies.len();
        let mut w = self.world.clone();
        let p = take::<3>(&positions, "positions", n)?;
        let o = take::<4>(&orientations, "orientations", n)?;
        let v = take::<3>(&velocities, "velocities", n)?;
        let a = take::<3>(&angular_velocities, "angular_velocities", n)?;
        for (k, b) in w.bodies.iter_mut().enumerate() {
            p.as_ref().inspect(|p| b.position = p[k]);
            o.as_ref().inspect(|o| b.orientation = o[k]);
            v.as_ref().inspect(|v| b.velocity = v[k]);
            a.as_ref().inspect(|a| b.angular_velocity = a[k]);
        }
        w.validate("world").map_err(to_py_err)?;
        self.world = w;
        Ok(())
    }

    /// Kinetic energy (J).
    fn kinetic_energy(&self) -> f64 {
        self.world.kinetic_energy()
    }

    /// Potential energy −Σ m g·x (J).
    fn potential_energy(&self) -> f64 {
        self.world.potential_energy()
    }
}

/// Per-step, per-world summaries as (steps, W) arrays in `d`: `kinetic`,
/// `potential`, `max_penetration`, `max_error` (f64), `contacts`,
/// `islands`, `awake`, `impacts`, `impacts_deferred` (int64).
pub(crate) fn summaries_into(
    py: Python<'_>,
    d: &Bound<'_, PyDict>,
    steps: &[Vec<WorldStepReport>],
    worlds: usize,
) -> PyResult<()> {
    let shape = (steps.len(), worlds);
    let err = |e: numpy::ndarray::ShapeError| PyValueError::new_err(e.to_string());
    let f = |g: &dyn Fn(&WorldStepReport) -> f64| {
        let flat: Vec<f64> = steps.iter().flatten().map(g).collect();
        Array2::from_shape_vec(shape, flat).map_err(err)
    };
    let i = |g: &dyn Fn(&WorldStepReport) -> usize| {
        let flat: Vec<i64> = steps.iter().flatten().map(|r| g(r) as i64).collect();
        Array2::from_shape_vec(shape, flat).map_err(err)
    };
    d.set_item("kinetic", f(&|r| r.kinetic)?.into_pyarray(py))?;
    d.set_item("potential", f(&|r| r.potential)?.into_pyarray(py))?;
    d.set_item(
        "max_penetration",
        f(&|r| r.max_penetration)?.into_pyarray(py),
    )?;
    d.set_item("max_error", f(&|r| r.max_error)?.into_pyarray(py))?;
    d.set_item("contacts", i(&|r| r.contacts)?.into_pyarray(py))?;
    d.set_item("islands", i(&|r| r.islands)?.into_pyarray(py))?;
    d.set_item("awake", i(&|r| r.awake)?.into_pyarray(py))?;
    d.set_item("impacts", i(&|r| r.impacts)?.into_pyarray(py))?;
    d.set_item(
        "impacts_deferred",
        i(&|r| r.impacts_deferred)?.into_pyarray(py),
    )
}
