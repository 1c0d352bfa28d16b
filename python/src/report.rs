//! One [`Report`] from the chunks of a call, and a report as a Python dict.
//!
//! A long batch is solved in chunks (so that Ctrl-C is seen between them);
//! the caller sees one report: islands and scenes concatenated, counts,
//! statuses and timings summed, the largest error over all chunks with its
//! index in the whole batch, the device of the last chunk and the first
//! fallback reason.

use lcpbatch::{DeviceKind, GpuFigures, PathCounts, Report, SolvePath, Status, Timings};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Every solve path, in the order of the codes handed to Python.
pub(crate) const PATHS: [SolvePath; 10] = [
    SolvePath::Separating,
    SolvePath::SingleContact,
    SolvePath::WarmStart,
    SolvePath::PredictedBasis,
    SolvePath::EnumeratedGpu,
    SolvePath::Repaired,
    SolvePath::EnumeratedCpu,
    SolvePath::Lemke,
    SolvePath::Pgs,
    SolvePath::Invalid,
];

/// The code of `path` (its index in [`PATHS`]).
pub(crate) fn path_code(path: SolvePath) -> i8 {
    PATHS
        .iter()
        .position(|&p| p == path)
        .unwrap_or(PATHS.len() - 1) as i8
}

/// The code of `status` (its index in [`Status::ALL`]).
pub(crate) fn status_code(status: Status) -> i8 {
    Status::ALL
        .iter()
        .position(|&s| s == status)
        .unwrap_or(Status::ALL.len() - 1) as i8
}

/// Sums every count (a count the library adds to `PathCounts` must be added
/// here too: the struct is listed field by field).
fn add_counts(a: &mut PathCounts, b: &PathCounts) {
    a.separating += b.separating;
    a.single_contact += b.single_contact;
    a.warm_start += b.warm_start;
    a.predicted_basis += b.predicted_basis;
    a.enumerated_gpu += b.enumerated_gpu;
    a.enumerated_cpu += b.enumerated_cpu;
    a.lemke += b.lemke;
    a.pgs += b.pgs;
    a.invalid += b.invalid;
    a.polished += b.polished;
    a.repaired += b.repaired;
    a.cpu_fallback += b.cpu_fallback;
}

fn add_timings(a: &mut Timings, b: &Timings) {
    a.build += b.build;
    a.prediction += b.prediction;
    a.gpu += b.gpu;
    a.validation += b.validation;
    a.solve += b.solve;
    a.impulses += b.impulses;
    a.total += b.total;
}

// `..a` names no field today; it keeps this compiling when the library adds one.
#[allow(clippy::needless_update)]
fn add_gpu(a: Option<GpuFigures>, b: Option<GpuFigures>) -> Option<GpuFigures> {
    match (a, b) {
        (Some(a), Some(b)) => Some(GpuFigures {
            chunks: a.chunks + b.chunks,
            dispatches: a.dispatches + b.dispatches,
            rounds: a.rounds + b.rounds,
            tree_decided: a.tree_decided + b.tree_decided,
            tree_undecided: a.tree_undecided + b.tree_undecided,
            max_gpu_error: a.max_gpu_error.max(b.max_gpu_error),
            max_velocity_deviation: a.max_velocity_deviation.max(b.max_velocity_deviation),
            // A figure the library adds later is the first chunk's until
            // it is merged here.
            ..a
        }),
        (a, b) => a.or(b),
    }
}

/// Appends the frictional parts of `next` to `t`: scene indices shifted by
/// `scenes_before`, the scenes' frictional island ranges past `t`'s islands,
/// statuses summed, the largest Coulomb error (NaN wins, as in the library's
/// `Report::set_friction`) with its index in the whole batch. Runs before
/// the scenes are appended.
fn merge_friction(t: &mut Report, next: &mut Report, scenes_before: usize) {
    let before = t.friction.len();
    for isl in &mut next.friction {
        isl.scene = isl.scene.map(|s| s + scenes_before);
    }
    for s in &mut next.scenes {
        if let Some(f) = &mut s.friction {
            f.islands = f.islands.start + before..f.islands.end + before;
        }
    }
    for (a, b) in t.friction_statuses.iter_mut().zip(next.friction_statuses) {
        *a += b;
    }
    if let Some((e, i)) = next.max_coulomb_error {
        if !t.max_coulomb_error.is_some_and(|(m, _)| e <= m) {
            t.max_coulomb_error = Some((e, i + before));
        }
    }
    t.friction.append(&mut next.friction);
}

/// Appends the report of the next chunk to `total` (None: the first chunk).
/// Scene indices and island ranges of `next` are shifted past `total`'s
/// (frictional islands too, see [`merge_friction`]).
pub(crate) fn merge(total: Option<Report>, mut next: Report, scenes_before: usize) -> Report {
    let Some(mut t) = total else { return next };
    merge_friction(&mut t, &mut next, scenes_before);
    let islands_before = t.islands.len();
    for isl in &mut next.islands {
        isl.scene = isl.scene.map(|s| s + scenes_before);
    }
    for s in &mut next.scenes {
        s.islands = s.islands.start + islands_before..s.islands.end + islands_before;
    }
    add_counts(&mut t.counts, &next.counts);
    for (a, b) in t.statuses.iter_mut().zip(next.statuses) {
        *a += b;
    }
    if let Some((e, i)) = next.max_error {
        // NaN replaces the maximum, as in Report::new, so that it is seen.
        if !t.max_error.is_some_and(|(m, _)| e <= m) {
            t.max_error = Some((e, i + islands_before));
        }
    }
    add_timings(&mut t.timings, &next.timings);
    t.gpu = add_gpu(t.gpu, next.gpu);
    t.fallback = t.fallback.or(next.fallback);
    t.device = next.device;
    t.choice = next.choice;
    t.islands.append(&mut next.islands);
    t.scenes.append(&mut next.scenes);
    t
}

/// "cpu", "hardware_gpu" or "software_gpu".
pub(crate) fn device_kind_name(kind: DeviceKind) -> &'static str {
    match kind {
        DeviceKind::Cpu => "cpu",
        DeviceKind::HardwareGpu => "hardware_gpu",
        DeviceKind::SoftwareGpu => "software_gpu",
    }
}

/// A dict of (name, value) pairs.
fn dict_of<'py, V: IntoPyObject<'py> + Copy>(
    py: Python<'py>,
    items: &[(&str, V)],
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for (name, v) in items {
        d.set_item(*name, *v)?;
    }
    Ok(d)
}

/// The report's batch figures as a dict (per-island data goes in arrays).
pub(crate) fn to_dict<'py>(
    py: Python<'py>,
    r: &Report,
    chunks: usize,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("text", r.to_string())?;
    d.set_item("device", &r.device.name)?;
    d.set_item("device_kind", device_kind_name(r.device.kind))?;
    d.set_item("precision", r.device.precision.name())?;
    d.set_item("choice", &r.choice)?;
    d.set_item("fallback", r.fallback.as_deref())?;
    let c = &r.counts;
    let counts = [
        ("separating", c.separating),
        ("single_contact", c.single_contact),
        ("warm_start", c.warm_start),
        ("predicted_basis", c.predicted_basis),
        ("enumerated_gpu", c.enumerated_gpu),
        ("polished", c.polished),
        ("repaired", c.repaired),
        ("enumerated_cpu", c.enumerated_cpu),
        ("lemke", c.lemke),
        ("cpu_fallback", c.cpu_fallback),
        ("pgs", c.pgs),
        ("invalid", c.invalid),
    ];
    d.set_item("counts", dict_of(py, &counts)?)?;
    let statuses: Vec<(&str, usize)> = Status::ALL
        .iter()
        .zip(r.statuses)
        .map(|(s, n)| (s.name(), n))
        .collect();
    d.set_item("statuses", dict_of(py, &statuses)?)?;
    d.set_item("max_error", r.max_error.map(|(e, _)| e))?;
    d.set_item("max_error_index", r.max_error.map(|(_, i)| i))?;
    let t = &r.timings;
    let timings = [
        ("build", t.build),
        ("prediction", t.prediction),
        ("gpu", t.gpu),
        ("validation", t.validation),
        ("solve", t.solve),
        ("impulses", t.impulses),
        ("total", t.total),
    ];
    d.set_item("timings", dict_of(py, &timings)?)?;
    d.set_item("gpu", r.gpu.map(|g| gpu_dict(py, &g)).transpose()?)?;
    d.set_item("friction_islands", r.friction.len())?;
    let statuses: Vec<(&str, usize)> = Status::ALL
        .iter()
        .zip(r.friction_statuses)
        .map(|(s, n)| (s.name(), n))
        .collect();
    d.set_item("friction_statuses", dict_of(py, &statuses)?)?;
    d.set_item("max_coulomb_error", r.max_coulomb_error.map(|(e, _)| e))?;
    d.set_item(
        "max_coulomb_error_index",
        r.max_coulomb_error.map(|(_, i)| i),
    )?;
    d.set_item("chunks", chunks)?;
    Ok(d)
}

fn gpu_dict<'py>(py: Python<'py>, g: &GpuFigures) -> PyResult<Bound<'py, PyDict>> {
    let d = dict_of(
        py,
        &[
            ("chunks", g.chunks),
            ("dispatches", g.dispatches),
            ("rounds", g.rounds),
            ("tree_decided", g.tree_decided),
            ("tree_undecided", g.tree_undecided),
        ],
    )?;
    d.set_item("max_gpu_error", g.max_gpu_error)?;
    d.set_item("max_velocity_deviation", g.max_velocity_deviation)?;
    Ok(d)
}
